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
# fog-odometry applies a calibration's field offset, in closed form (tests/heading/field_offset_check.cmake;
# two runs on the bundled drive, ~5 s: "long").
if(TARGET fog-odometry)
  add_test(NAME heading.fog_odometry_field_offset COMMAND ${CMAKE_COMMAND} -DODO=$<TARGET_FILE:fog-odometry>
    -DDRIVE=${FOG_SOURCE_DIR}/datasets/drive.rawlog -DCAL=${FOG_SOURCE_DIR}/tests/data/heading/cal_full.yaml
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/odometry_field_offset -P ${FOG_SOURCE_DIR}/tests/heading/field_offset_check.cmake)
  set_tests_properties(heading.fog_odometry_field_offset PROPERTIES LABELS "heading;integration;long" TIMEOUT 300)
endif()
# MRPT's stock pf-localization on fog-odometry's output, on fog-localize's map (the localize
# fixture writes it), against the held-back truth: the compensated FOG's position RMS below the
# wheels' (tests/heading/pf_localization_check.cmake). Whole drive, two filter runs: about a
# minute in Release, under "long".
find_program(VEH_PF_LOCALIZATION pf-localization)
if(TARGET fog-odometry AND TARGET vehicle-rawlog-gen AND TARGET fog-localize AND VEH_PF_LOCALIZATION)
  add_test(NAME heading.pf_localization_vehicle COMMAND ${CMAKE_COMMAND} -DGEN=$<TARGET_FILE:vehicle-rawlog-gen>
    -DODO=$<TARGET_FILE:fog-odometry> -DPF=${VEH_PF_LOCALIZATION} -DPLUGIN=$<TARGET_FILE:mrpt_fog>
    -DDRIVE=${FOG_SOURCE_DIR}/datasets/drive.rawlog -DCAL=${FOG_SOURCE_DIR}/tests/data/heading/cal_full.yaml
    -DMAP=${CMAKE_CURRENT_BINARY_DIR}/localize/map.gridmap.gz -DPARTICLES=100
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/vehicle_pf -P ${FOG_SOURCE_DIR}/tests/heading/pf_localization_check.cmake)
  set_tests_properties(heading.pf_localization_vehicle PROPERTIES FIXTURES_REQUIRED loc_run
    LABELS "heading;integration;long" TIMEOUT 1200)
endif()
# Peak memory of fog-odometry and fog-compensate on 2.8 M FOG samples with a 2-D scan every 0.1 s
# (the bundled drive 67 times, about 79 h of log; tests/heading/memory_check.cmake): at most
# 300 MB (300e6 bytes = 292968 kB) each. Tens of minutes and several GB of scratch: "long".
find_program(VEH_TIME time PATHS /usr/bin NO_DEFAULT_PATH)
if(TARGET fog-odometry AND TARGET fog-compensate AND TARGET vehicle-rawlog-gen AND VEH_TIME)
  add_test(NAME heading.vehicle_memory_2_8M COMMAND ${CMAKE_COMMAND} -DGEN=$<TARGET_FILE:vehicle-rawlog-gen>
    -DODO=$<TARGET_FILE:fog-odometry> -DCOMP=$<TARGET_FILE:fog-compensate> -DTIME=${VEH_TIME}
    -DDRIVE=${FOG_SOURCE_DIR}/datasets/drive.rawlog -DCAL=${FOG_SOURCE_DIR}/tests/data/heading/cal_full.yaml
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/vehicle_memory -DREPEAT=67 -DMIN_SAMPLES=2800000 -DLIMIT_KB=292968
    -P ${FOG_SOURCE_DIR}/tests/heading/memory_check.cmake)
  set_tests_properties(heading.vehicle_memory_2_8M PROPERTIES LABELS "heading;integration;long" TIMEOUT 10800)
endif()
