# The installed package as an MRPT user gets it: `cmake --install` to a fresh prefix, the prefix
# moved elsewhere (RUNPATH $ORIGIN/../lib must still find libmrpt_fog), the installed programs
# run (`bin/fog-demo --help`, `bin/fog-drift` on the synthetic drive), and examples/
# fog_heading_odometry configured with find_package(mrpt_fog), built and run against it.
# Script: tests/package/install_and_example.cmake.
if(TARGET fog-drift AND TARGET fog-demo AND TARGET nav_test_drive)
  add_test(NAME package.install_and_example COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR}
    -DEXAMPLE_SRC=${FOG_SOURCE_DIR}/examples/fog_heading_odometry -DWORK=${CMAKE_CURRENT_BINARY_DIR}/package
    -DDRIVE=${CMAKE_CURRENT_BINARY_DIR}/nav_drive/drive.rawlog -DCAL=${CMAKE_CURRENT_BINARY_DIR}/nav_drive/cal.yaml
    -DREADER_SRC=${FOG_SOURCE_DIR}/tests/package/reader_only -DCHAMBER=${CMAKE_CURRENT_BINARY_DIR}/nav_drive/drive.rawlog
    -DCMAKE_GENERATOR=${CMAKE_GENERATOR} -P ${FOG_SOURCE_DIR}/tests/package/install_and_example.cmake)
  set_tests_properties(package.install_and_example PROPERTIES FIXTURES_REQUIRED nav_drive
    LABELS "package;integration" TIMEOUT 600)
endif()
