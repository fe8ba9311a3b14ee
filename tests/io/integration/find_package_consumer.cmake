# Installs the build tree to a scratch prefix, then configures, builds and runs tests/consumer
# (find_package(mrpt_fog), links mrpt_fog::mrpt_fog) against that prefix only.
# -D BUILD_DIR=<project build dir> -D CONSUMER_SRC=<tests/consumer> -D WORK=<scratch dir> -D CMAKE_GENERATOR=<gen>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(prefix ${WORK}/prefix)

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${so}\n${se}")
  endif()
  message(STATUS "${what}: ok")
  set(out "${so}" PARENT_SCOPE)
endfunction()

step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
if(NOT EXISTS ${prefix}/lib/cmake/mrpt_fog/mrpt_fog-config.cmake AND NOT EXISTS ${prefix}/lib64/cmake/mrpt_fog/mrpt_fog-config.cmake)
  file(GLOB_RECURSE cfg ${prefix}/*config.cmake)
  message(FATAL_ERROR "no mrpt_fog-config.cmake installed (found: ${cfg})")
endif()
step("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SRC} -B ${WORK}/build -G ${CMAKE_GENERATOR}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
step("build consumer" ${CMAKE_COMMAND} --build ${WORK}/build)
# The consumer must have linked the installed library, not the build tree's.
step("ldd consumer" ldd ${WORK}/build/fog_consumer)
string(REGEX MATCH "libmrpt_fog\\.so[^\n]*" libline "${out}")
string(FIND "${libline}" "${prefix}" in_prefix)
if(in_prefix EQUAL -1)
  message(FATAL_ERROR "consumer resolves libmrpt_fog from '${libline}', not from ${prefix}")
endif()
step("run consumer" ${WORK}/build/fog_consumer ${WORK}/consumer.rawlog)
string(FIND "${out}" "read back 1 sample(s): OK" ok)
if(ok EQUAL -1)
  message(FATAL_ERROR "consumer output unexpected:\n${out}")
endif()
message(STATUS "${out}")
