# fog-localize end to end on the bundled drive (1 filter seed, 100 particles: ~10 s), checks of
# what the world must give (tests/localize/check_localize.cmake), MRPT's own pf-localization run
# on the written map / rawlog / .ini, and bad input.
if(TARGET fog-localize)
  set(LOC_DIR ${CMAKE_CURRENT_BINARY_DIR}/localize)
  add_test(NAME localize.fog_localize.run COMMAND ${CMAKE_COMMAND} -E env
    $<TARGET_FILE:fog-localize> --drive ${FOG_SOURCE_DIR}/datasets/drive.rawlog --out ${LOC_DIR} --json ${LOC_DIR}.json
    --seeds 1 --particles 100)
  set_tests_properties(localize.fog_localize.run PROPERTIES FIXTURES_SETUP loc_run LABELS "localize;integration" TIMEOUT 600)
  add_test(NAME localize.fog_localize.check COMMAND ${CMAKE_COMMAND} -DJSON=${LOC_DIR}.json -DDIR=${LOC_DIR}
    -DRATETABLE=${FOG_SOURCE_DIR}/datasets/ratetable_A.rawlog
    -P ${FOG_SOURCE_DIR}/tests/localize/check_localize.cmake)
  set_tests_properties(localize.fog_localize.check PROPERTIES FIXTURES_REQUIRED loc_run LABELS "localize;integration")
  # The calibration fog-localize fits by default is the file fog-calibrate writes for the same runs.
  if(TARGET fog-calibrate AND EXISTS ${FOG_SOURCE_DIR}/datasets/ratetable_A.rawlog)
    add_test(NAME localize.fog_localize.calibration_as_fog_calibrate COMMAND sh -c
      "'$<TARGET_FILE:fog-calibrate>' -i '${FOG_SOURCE_DIR}/datasets/chamber_A.rawlog' -i '${FOG_SOURCE_DIR}/datasets/ratetable_A.rawlog' --model multipoint -o '${LOC_DIR}_fog_calibrate.yaml' > /dev/null && cmp '${LOC_DIR}_fog_calibrate.yaml' '${LOC_DIR}/calibration.yaml'")
    set_tests_properties(localize.fog_localize.calibration_as_fog_calibrate PROPERTIES FIXTURES_REQUIRED loc_run
      LABELS "localize;integration")
  endif()
  find_program(LOC_PF_LOCALIZATION pf-localization)
  if(LOC_PF_LOCALIZATION)
    add_test(NAME localize.pf_localization.run
      COMMAND sh -c "'${LOC_PF_LOCALIZATION}' pf-localization_compensated.ini < /dev/null > pf.log 2>&1"
      WORKING_DIRECTORY ${LOC_DIR})
    set_tests_properties(localize.pf_localization.run PROPERTIES FIXTURES_REQUIRED loc_run FIXTURES_SETUP loc_pf
      ENVIRONMENT "DISPLAY=" LABELS "localize;integration" TIMEOUT 300)
    add_test(NAME localize.pf_localization.check COMMAND ${CMAKE_COMMAND}
      -DGT_ERROR=${LOC_DIR}/LOG_compensated_000_0000100/GT_error.txt -P ${FOG_SOURCE_DIR}/tests/localize/check_pf_error.cmake)
    set_tests_properties(localize.pf_localization.check PROPERTIES FIXTURES_REQUIRED loc_pf LABELS "localize;integration")
  endif()
  # A drive with the gyro off for 5 min (tests/localize/gyro_off_check.cmake; ~8 s).
  if(TARGET fog-sim)
    add_test(NAME localize.fog_localize.gyro_off COMMAND ${CMAKE_COMMAND} -DSIM=$<TARGET_FILE:fog-sim>
      -DLOC=$<TARGET_FILE:fog-localize> -DCABIN=${FOG_SOURCE_DIR}/tests/localize/cabin_off.yaml
      -DWORK=${CMAKE_CURRENT_BINARY_DIR}/localize_gyro_off -P ${FOG_SOURCE_DIR}/tests/localize/gyro_off_check.cmake)
    set_tests_properties(localize.fog_localize.gyro_off PROPERTIES LABELS "localize;integration" TIMEOUT 600)
  endif()
  # The odometry of the filter steps across a gyro-off stretch, in closed form.
  add_executable(test_localize_odometry ${FOG_SOURCE_DIR}/tests/localize/test_GyroOffOdometry.cpp
    ${FOG_SOURCE_DIR}/apps/fog-localize/GyroOffOdometry.cpp)
  target_include_directories(test_localize_odometry PRIVATE ${FOG_SOURCE_DIR}/apps/fog-localize)
  target_link_libraries(test_localize_odometry PRIVATE mrpt_fog_heading GTest::gtest GTest::gtest_main)
  fog_add_gtests(test_localize_odometry localize)
  add_test(NAME localize.fog_localize.bad_seeds COMMAND fog-localize --seeds 0 --out ${LOC_DIR}_bad)
  add_test(NAME localize.fog_localize.missing_drive COMMAND fog-localize --drive ${LOC_DIR}/no_such.rawlog --cal x.yaml --out ${LOC_DIR}_bad)
  add_test(NAME localize.fog_localize.bad_fields COMMAND fog-localize --fields curvy --out ${LOC_DIR}_bad)
  # --ratetable chooses a run of the fit: refused beside --cal; a run without table rates is no rate-table run.
  add_test(NAME localize.fog_localize.cal_and_ratetable COMMAND fog-localize --cal x.yaml --ratetable none --out ${LOC_DIR}_bad)
  set_tests_properties(localize.fog_localize.bad_seeds localize.fog_localize.missing_drive localize.fog_localize.bad_fields
    localize.fog_localize.cal_and_ratetable PROPERTIES WILL_FAIL TRUE LABELS "localize;integration")
  add_test(NAME localize.fog_localize.bad_recovery COMMAND fog-localize --gyro-off-recovery maybe --out ${LOC_DIR}_bad)
  set_tests_properties(localize.fog_localize.bad_recovery PROPERTIES
    PASS_REGULAR_EXPRESSION "gyro-off recovery 'maybe' is not refix\\|none" LABELS "localize;integration")
  add_test(NAME localize.fog_localize.bad_wheel_model COMMAND fog-localize --wheel-heading-deg-per-m -1 --out ${LOC_DIR}_bad)
  set_tests_properties(localize.fog_localize.bad_wheel_model PROPERTIES
    PASS_REGULAR_EXPRESSION "--wheel-heading-deg-per-m '-1': out of range" LABELS "localize;integration")
  add_test(NAME localize.fog_localize.bad_roughening COMMAND fog-localize --roughening-k -1 --out ${LOC_DIR}_bad)
  set_tests_properties(localize.fog_localize.bad_roughening PROPERTIES
    PASS_REGULAR_EXPRESSION "--roughening-k '-1': out of range" LABELS "localize;integration")
  add_test(NAME localize.fog_localize.not_a_ratetable COMMAND fog-localize --ratetable ${FOG_SOURCE_DIR}/datasets/warmup.rawlog
    --out ${LOC_DIR}_bad)
  set_tests_properties(localize.fog_localize.not_a_ratetable PROPERTIES
    PASS_REGULAR_EXPRESSION "warmup.rawlog: no table rates" LABELS "localize;integration")
endif()
