# A vehicle's own rawlog (lidar, GPS, camera, MEMS IMU; both formats; no truth) through
# fog-compensate, fog-odometry and fog-drift (tests/heading/vehicle_check.cmake). Both under "long": ten
# program runs each (7-15 s in Release); the default suite has the readers' and the pipeline's unit tests.
if(TARGET fog-odometry AND TARGET vehicle-rawlog-gen)
  add_test(NAME heading.vehicle_rawlog COMMAND ${CMAKE_COMMAND} -DGEN=$<TARGET_FILE:vehicle-rawlog-gen>
    -DODO=$<TARGET_FILE:fog-odometry> -DCOMP=$<TARGET_FILE:fog-compensate> -DDRIFT=$<TARGET_FILE:fog-drift>
    -DDRIVE=${FOG_SOURCE_DIR}/datasets/drive.rawlog -DCAL=${FOG_SOURCE_DIR}/tests/data/heading/cal_full.yaml
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/vehicle_20 -DDURATION=20 -P ${FOG_SOURCE_DIR}/tests/heading/vehicle_check.cmake)
  set_tests_properties(heading.vehicle_rawlog PROPERTIES LABELS "heading;integration;long" TIMEOUT 300)
  # The targets over 600 s against the held-back truth (docs/validation/vehicle.md).
  add_test(NAME heading.vehicle_rawlog_600s COMMAND ${CMAKE_COMMAND} -DGEN=$<TARGET_FILE:vehicle-rawlog-gen>
    -DODO=$<TARGET_FILE:fog-odometry> -DCOMP=$<TARGET_FILE:fog-compensate> -DDRIFT=$<TARGET_FILE:fog-drift>
    -DDRIVE=${FOG_SOURCE_DIR}/datasets/drive.rawlog -DCAL=${FOG_SOURCE_DIR}/tests/data/heading/cal_full.yaml
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/vehicle_600 -DDURATION=600 -DTARGETS=ON -P ${FOG_SOURCE_DIR}/tests/heading/vehicle_check.cmake)
  set_tests_properties(heading.vehicle_rawlog_600s PROPERTIES LABELS "heading;integration;long" TIMEOUT 900)
endif()
