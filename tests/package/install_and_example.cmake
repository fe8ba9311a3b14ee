# -D BUILD_DIR=<project build dir> -D EXAMPLE_SRC=<examples/fog_heading_odometry> -D WORK=<scratch>
# -D DRIVE=<synthetic drive rawlog> -D CAL=<its calibration> -D CMAKE_GENERATOR=<generator>
# -D READER_SRC=<tests/package/reader_only> -D CHAMBER=<a rawlog with CObservationFOG>
# 1. install to WORK/prefix, then move it to WORK/moved (a relocated package); libmrpt_fog and
#    its CMake package do not depend on OpenCV;
# 2. the installed programs carry RUNPATH $ORIGIN/... and run with no LD_LIBRARY_PATH:
#    bin/fog-demo --help, bin/fog-drift on the synthetic circle drive (compensated heading
#    error must be ~0: the drive's thermal bias law is inside the model class);
# 3. a program that reads a rawlog with MRPT's archive API only (tests/package/reader_only: no
#    mrpt_fog symbol, no registerAllClasses call) reads every CObservationFOG of a chamber run;
# 4. examples/fog_heading_odometry built with find_package(mrpt_fog) against the moved prefix,
#    linked to its libraries, run on the same drive: its compensated heading must come back to
#    the closed-form circle (< 1e-3 deg, < 0.01 m) and it must write the odometry rawlog.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(ENV{LD_LIBRARY_PATH} "")

include(${CMAKE_CURRENT_LIST_DIR}/PackageSteps.cmake)

step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK}/prefix)
file(RENAME ${WORK}/prefix ${WORK}/moved)
set(prefix ${WORK}/moved)

# Plotting lives in the programs' static report/ libraries: neither the installed library nor
# its CMake package may depend on OpenCV.
file(GLOB_RECURSE fog_so ${prefix}/*/libmrpt_fog.so)
file(GLOB_RECURSE fog_targets ${prefix}/*/mrpt_fog-targets*.cmake ${prefix}/*/mrpt_fog-config.cmake)
step("readelf libmrpt_fog" readelf -d ${fog_so})
foreach(f ${fog_targets})
  file(READ ${f} txt)
  string(APPEND out "${txt}")
endforeach()
string(TOLOWER "${out}" out)
if(NOT fog_so OR NOT fog_targets OR out MATCHES "opencv")
  message(FATAL_ERROR "libmrpt_fog (${fog_so}) or its package (${fog_targets}) depends on OpenCV")
endif()

step("readelf fog-drift" readelf -d ${prefix}/bin/fog-drift)
if(NOT out MATCHES "(RUNPATH|RPATH)[^\n]*\\$ORIGIN/")
  message(FATAL_ERROR "installed fog-drift has no $ORIGIN RUNPATH:\n${out}")
endif()
step("fog-demo --help" ${prefix}/bin/fog-demo --help)
if(NOT out MATCHES "fog-demo")
  message(FATAL_ERROR "fog-demo --help printed no usage:\n${out}")
endif()
expect_libraries_from(${prefix}/bin/fog-drift ${prefix} libmrpt_fog)
step("installed fog-drift" ${prefix}/bin/fog-drift -i ${DRIVE} --cal ${CAL} --json ${WORK}/drift.json)
file(READ ${WORK}/drift.json drift)
string(JSON comp_deg GET "${drift}" heading_error_final_deg compensated)
if(NOT comp_deg LESS 1e-3)
  message(FATAL_ERROR "installed fog-drift: compensated final heading error ${comp_deg} deg (expected < 1e-3)")
endif()

step("configure example" ${CMAKE_COMMAND} -S ${EXAMPLE_SRC} -B ${WORK}/example -G ${CMAKE_GENERATOR}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
step("build example" ${CMAKE_COMMAND} --build ${WORK}/example)
expect_libraries_from(${WORK}/example/fog_heading_odometry ${prefix} libmrpt_fog libmrpt_fog_nav)
step("run example" ${WORK}/example/fog_heading_odometry ${DRIVE} ${CAL} ${WORK}/odometry.rawlog)
message(STATUS "${out}")
if(NOT out MATCHES "heading error ([-+0-9.eE]+) deg, position error ([-+0-9.eE]+) m")
  message(FATAL_ERROR "example printed no error line:\n${out}")
endif()
set(h "${CMAKE_MATCH_1}")
set(p "${CMAKE_MATCH_2}")
string(REGEX REPLACE "^-" "" h_abs "${h}")
if(NOT h_abs LESS 1e-3 OR NOT p LESS 0.01)
  message(FATAL_ERROR "example: heading error ${h} deg, position error ${p} m (expected < 1e-3 deg, < 0.01 m)")
endif()
if(NOT EXISTS ${WORK}/odometry.rawlog)
  message(FATAL_ERROR "example wrote no odometry rawlog")
endif()

# fog-rawlog-edit (installed script): rawlog-edit with the moved prefix's plugin reads every
# FOG object of the drive (12001 FOG + 12001 FOG_IDEAL samples).
# In a sanitizer build (scripts/run-sanitizers.sh exports FOG_ASAN_PRELOAD) MRPT's uninstrumented
# rawlog-edit loads our instrumented plugin: without the ASan runtime preloaded it stops with "ASan
# runtime does not come first in initial library list" (exit 1). Preloaded for this step only (the
# compilers and ldd above must not run under it).
set(preload "")
if(DEFINED ENV{FOG_ASAN_PRELOAD} AND NOT "$ENV{FOG_ASAN_PRELOAD}" STREQUAL "")
  set(preload ${CMAKE_COMMAND} -E env "LD_PRELOAD=$ENV{FOG_ASAN_PRELOAD}")
endif()
find_program(RAWLOG_EDIT_FOUND rawlog-edit)
if(RAWLOG_EDIT_FOUND)
  step("fog-rawlog-edit --info" ${preload} ${prefix}/bin/fog-rawlog-edit --info -i ${DRIVE})
  if(NOT out MATCHES "FOG_IDEAL / +12001 ")
    message(FATAL_ERROR "fog-rawlog-edit --info did not read the FOG_IDEAL objects:\n${out}")
  endif()
endif()
step("configure reader-only" ${CMAKE_COMMAND} -S ${READER_SRC} -B ${WORK}/reader -G ${CMAKE_GENERATOR}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
step("build reader-only" ${CMAKE_COMMAND} --build ${WORK}/reader)
step("run reader-only" ${WORK}/reader/fog_reader_only ${CHAMBER})
message(STATUS "${out}")
if(NOT out MATCHES "^([0-9]+) objects, ([0-9]+) of class" OR NOT CMAKE_MATCH_2 GREATER 1000)
  message(FATAL_ERROR "reader-only program did not read the FOG objects:\n${out}")
endif()

# The example takes the Earth rate the calibration absorbed from the latitude the file records:
# the same calibration stating latitude 0 instead of the drive's 40 deg must leave exactly the
# vertical Earth rate at 40 deg in the heading: 15.041067 deg/h * sin(40 deg) * 1200 s = 3.2227 deg.
file(READ ${CAL} cal_text)
string(REGEX REPLACE "latitude_deg:[^\n#]*" "latitude_deg: 0 " cal_lat0 "${cal_text}")
if(cal_lat0 STREQUAL cal_text)
  message(FATAL_ERROR "the calibration file has no latitude_deg key")
endif()
file(WRITE ${WORK}/cal_lat0.yaml "${cal_lat0}")
step("run example, calibration at latitude 0" ${WORK}/example/fog_heading_odometry ${DRIVE} ${WORK}/cal_lat0.yaml ${WORK}/odometry_lat0.rawlog)
message(STATUS "${out}")
if(NOT out MATCHES "heading error ([-+0-9.eE]+) deg")
  message(FATAL_ERROR "example printed no error line:\n${out}")
endif()
set(h0 "${CMAKE_MATCH_1}")
string(REGEX REPLACE "^-" "" h0_abs "${h0}")
if(h0_abs LESS 3.2217 OR h0_abs GREATER 3.2237)
  message(FATAL_ERROR "example with the calibration at latitude 0: heading error ${h0} deg, expected 3.2227 +- 0.001 deg")
endif()
