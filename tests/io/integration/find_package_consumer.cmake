# Installs the build tree to a scratch prefix, then configures, builds and runs tests/consumer
# (find_package(mrpt_fog), links mrpt_fog::mrpt_fog) against that prefix only.
# -D BUILD_DIR=<project build dir> -D CONSUMER_SRC=<tests/consumer> -D WORK=<scratch dir> -D CMAKE_GENERATOR=<gen>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(prefix ${WORK}/prefix)

include(${CMAKE_CURRENT_LIST_DIR}/../../package/PackageSteps.cmake)

step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
if(NOT EXISTS ${prefix}/lib/cmake/mrpt_fog/mrpt_fog-config.cmake AND NOT EXISTS ${prefix}/lib64/cmake/mrpt_fog/mrpt_fog-config.cmake)
  file(GLOB_RECURSE cfg ${prefix}/*config.cmake)
  message(FATAL_ERROR "no mrpt_fog-config.cmake installed (found: ${cfg})")
endif()
step("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SRC} -B ${WORK}/build -G ${CMAKE_GENERATOR}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
step("build consumer" ${CMAKE_COMMAND} --build ${WORK}/build)
# The consumer must have linked the installed library, not the build tree's.
expect_libraries_from(${WORK}/build/fog_consumer ${prefix} libmrpt_fog)
step("run consumer" ${WORK}/build/fog_consumer ${WORK}/consumer.rawlog)
string(FIND "${out}" "read back 1 sample(s): OK" ok)
if(ok EQUAL -1)
  message(FATAL_ERROR "consumer output unexpected:\n${out}")
endif()
message(STATUS "${out}")
