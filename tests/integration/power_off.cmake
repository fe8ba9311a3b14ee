# Power-off rows (gyro off, thermistors logging) through every program that reads a chamber log:
# tests/io/integration/power_off_programs.cmake.
if(TARGET fog-convert AND TARGET fog-calibrate AND TARGET fog-compensate AND TARGET fog-evaluate
   AND TARGET fog-discrepancy)
  add_test(NAME io_power_off_programs COMMAND ${CMAKE_COMMAND} -DBIN=$<TARGET_FILE_DIR:fog-convert>
    -DDATA=${FOG_SOURCE_DIR}/tests/data/io -DWORK=${CMAKE_CURRENT_BINARY_DIR}/io/power_off
    -P ${FOG_SOURCE_DIR}/tests/io/integration/power_off_programs.cmake)
  set_tests_properties(io_power_off_programs PROPERTIES LABELS "io;integration")
endif()
