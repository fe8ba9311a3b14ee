# fog-discrepancy end to end on simulator runs (fog-sim "rich" profile at 0.1 Hz, all effects on):
# the multipoint model is tested against run A and confirmed on run B; the JSON keys of the
# contract are checked; bad input gives a one-line error and a non-zero exit.
if(TARGET fog-discrepancy AND TARGET fog-sim)
  set(_disc_dir ${CMAKE_CURRENT_BINARY_DIR}/discrepancy)
  set(_disc_check ${FOG_SOURCE_DIR}/tests/discrepancy/check_discrepancy.cmake)
  add_test(NAME discrepancy.setup COMMAND ${CMAKE_COMMAND} -E make_directory ${_disc_dir})
  add_test(NAME discrepancy.sim_run_a
    COMMAND fog-sim -p rich --rate-hz 0.1 --seed 1 -o ${_disc_dir}/rich_a.csv)
  add_test(NAME discrepancy.sim_run_b
    COMMAND fog-sim -p rich --rate-hz 0.1 --seed 2 -o ${_disc_dir}/rich_b.csv)
  set_tests_properties(discrepancy.setup PROPERTIES FIXTURES_SETUP disc_dir LABELS "integration;discrepancy")
  set_tests_properties(discrepancy.sim_run_a discrepancy.sim_run_b PROPERTIES
    FIXTURES_REQUIRED disc_dir FIXTURES_SETUP disc_runs LABELS "integration;discrepancy")

  add_test(NAME discrepancy.multipoint_named_and_confirmed
    COMMAND ${CMAKE_COMMAND} -DMODE=run -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=--measured;${_disc_dir}/rich_a.csv;--measured;${_disc_dir}/rich_b.csv;--model;multipoint;--json;${_disc_dir}/mp.json;--plots;${_disc_dir}"
      -DJSON=${_disc_dir}/mp.json -DPNG=${_disc_dir}/discrepancy_residual.png -P ${_disc_check})
  add_test(NAME discrepancy.bad_model_one_line_error
    COMMAND ${CMAKE_COMMAND} -DMODE=error -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=--measured;${_disc_dir}/rich_a.csv;--model;quadratic;--json;${_disc_dir}/bad.json"
      -DEXPECT=quadratic -DNOFILE=${_disc_dir}/bad.json -P ${_disc_check})
  add_test(NAME discrepancy.sim_missing_config_one_line_error
    COMMAND ${CMAKE_COMMAND} -DMODE=error -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=--measured;${_disc_dir}/rich_a.csv;--sim;whatever.yaml"
      -DEXPECT=whatever.yaml -P ${_disc_check})
  add_test(NAME discrepancy.missing_file_one_line_error
    COMMAND ${CMAKE_COMMAND} -DMODE=error -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=--measured;${_disc_dir}/does_not_exist.csv;--model;M1"
      -DEXPECT=does_not_exist -P ${_disc_check})
  # the same file as both runs is no confirmation; a block longer than the model's slope window
  # serves is refused with the limit (static model: 120 s derivative window / 4 = 30 s)
  add_test(NAME discrepancy.same_file_twice_refused
    COMMAND ${CMAKE_COMMAND} -DMODE=error -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=--measured;${_disc_dir}/rich_a.csv;--measured;${_disc_dir}/./rich_a.csv;--model;static:3"
      -DEXPECT=same file -P ${_disc_check})
  add_test(NAME discrepancy.block_longer_than_the_model_serves_refused
    COMMAND ${CMAKE_COMMAND} -DMODE=error -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=--measured;${_disc_dir}/rich_a.csv;--model;static:3;--block-s;100"
      -DEXPECT=longest block 30 s -P ${_disc_check})
  set_tests_properties(discrepancy.multipoint_named_and_confirmed discrepancy.bad_model_one_line_error
    discrepancy.same_file_twice_refused discrepancy.block_longer_than_the_model_serves_refused
    discrepancy.sim_missing_config_one_line_error discrepancy.missing_file_one_line_error PROPERTIES
    FIXTURES_REQUIRED disc_runs LABELS "integration;discrepancy")
endif()

# --write-cal and --plots on the lumped-coil second generator (tests/discrepancy/check_write_cal.cmake).
if(TARGET fog-discrepancy AND TARGET fog-compensate AND TARGET fog-calibrate AND TARGET lumped-coil-gen)
  add_test(NAME discrepancy.write_cal_closes_the_loop COMMAND ${CMAKE_COMMAND}
    -DGEN=$<TARGET_FILE:lumped-coil-gen> -DDISC=$<TARGET_FILE:fog-discrepancy> -DCOMP=$<TARGET_FILE:fog-compensate>
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/discrepancy/write_cal -P ${FOG_SOURCE_DIR}/tests/discrepancy/check_write_cal.cmake)
  set_tests_properties(discrepancy.write_cal_closes_the_loop PROPERTIES LABELS "integration;discrepancy" TIMEOUT 600)
  add_test(NAME discrepancy.write_cal_magnetic COMMAND ${CMAKE_COMMAND}
    -DGEN=$<TARGET_FILE:lumped-coil-gen> -DDISC=$<TARGET_FILE:fog-discrepancy> -DCOMP=$<TARGET_FILE:fog-compensate>
    -DCAL=$<TARGET_FILE:fog-calibrate>
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/discrepancy/write_cal_magnetic -P ${FOG_SOURCE_DIR}/tests/discrepancy/check_write_cal_magnetic.cmake)
  set_tests_properties(discrepancy.write_cal_magnetic PROPERTIES LABELS "integration;discrepancy" TIMEOUT 600)
endif()
