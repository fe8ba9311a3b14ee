# Three-axis FOG end to end (issue 12 part 3): fog-sim --triad makes a short chamber run and a
# short drive, fog-calibrate fits one model per axis into one file, fog-compensate writes all
# three compensated axes into CObservationIMU, fog-drift runs the 3-D strapdown. Short runs at
# 1-2 Hz (a few seconds); the figures with full runs: docs/nav.md, "Three-axis FOG".
if(NOT TARGET fog-sim OR NOT TARGET fog-calibrate OR NOT TARGET fog-compensate OR NOT TARGET fog-drift)
  return()
endif()
set(_t3 ${CMAKE_CURRENT_BINARY_DIR}/triad)
file(MAKE_DIRECTORY ${_t3})
add_test(NAME triad.sim_calibrate
  COMMAND sh -c "\"$0\" --triad --profile seed --rate-hz 1 --duration-s 9000 -o '${_t3}/chamber3.rawlog' >/dev/null && \"$1\" -i '${_t3}/chamber3.rawlog' --model multipoint -o '${_t3}/cal3.yaml' --json '${_t3}/cal3.json'"
          $<TARGET_FILE:fog-sim> $<TARGET_FILE:fog-calibrate>)
set_tests_properties(triad.sim_calibrate PROPERTIES LABELS "integration;model;triad" FIXTURES_SETUP triad_cal
  PASS_REGULAR_EXPRESSION "axis x \\(the runs' stated Earth rate removed from the bias\\):.*axis y .*axis z .*wrote")
# one file, three axes, Earth rate not in the bias
add_test(NAME triad.calibration_file
  COMMAND sh -c "[ $(grep -c '^  - axis: ' '${_t3}/cal3.yaml') -eq 3 ] && grep -q 'handling: \"in_table_rate\"' '${_t3}/cal3.yaml' && grep -q '\"axes\"' '${_t3}/cal3.json'")
set_tests_properties(triad.calibration_file PROPERTIES LABELS "integration;model;triad" FIXTURES_REQUIRED triad_cal)
add_test(NAME triad.compensate_all_axes
  COMMAND fog-compensate -i ${_t3}/chamber3.rawlog --cal ${_t3}/cal3.yaml -o ${_t3}/comp3.rawlog)
set_tests_properties(triad.compensate_all_axes PROPERTIES LABELS "integration;model;triad" FIXTURES_REQUIRED triad_cal
  PASS_REGULAR_EXPRESSION "axis xyz \\(one model each\\)")
find_program(FOG_RAWLOG_EDIT_T3 rawlog-edit)
if(FOG_RAWLOG_EDIT_T3)
  # MRPT reads the stock CObservationIMU rawlog (9001 samples: IMU + thermistor DAQ each)
  add_test(NAME triad.compensated_rawlog_read_by_mrpt COMMAND ${FOG_RAWLOG_EDIT_T3} --info -i ${_t3}/comp3.rawlog)
  set_tests_properties(triad.compensated_rawlog_read_by_mrpt PROPERTIES LABELS "integration;model;triad"
    DEPENDS triad.compensate_all_axes FIXTURES_REQUIRED triad_cal PASS_REGULAR_EXPRESSION "Overall number of objects +: 18002")
endif()
add_test(NAME triad.drift_3d
  COMMAND sh -c "\"$0\" --triad --profile drive --rate-hz 2 --duration-s 900 -o '${_t3}/drive3.rawlog' >/dev/null && \"$1\" -i '${_t3}/drive3.rawlog' --cal '${_t3}/cal3.yaml' --json '${_t3}/drift3.json' && grep -q '\"three_axis\"' '${_t3}/drift3.json'"
          $<TARGET_FILE:fog-sim> $<TARGET_FILE:fog-drift>)
set_tests_properties(triad.drift_3d PROPERTIES LABELS "integration;nav;triad" FIXTURES_REQUIRED triad_cal
  PASS_REGULAR_EXPRESSION "3-D strapdown \\(triad x, y, z")
# a triad calibration whose bias holds the Earth rate (runs without earth_rate_dph) is refused
# by fog-drift in 3-D with the reason, and no output is left
add_test(NAME triad.drift_refuses_in_bias
  COMMAND sh -c "sed 's/in_table_rate/in_bias/' '${_t3}/cal3.yaml' > '${_t3}/cal3_inbias.yaml'; out=$(\"$0\" -i '${_t3}/drive3.rawlog' --cal '${_t3}/cal3_inbias.yaml' --json '${_t3}/bad.json' 2>&1); rc=$?; echo \"$out\"; [ $rc -ne 0 ] && echo \"$out\" | grep -q 'unknown for the horizontal axes' && [ ! -e '${_t3}/bad.json' ]"
          $<TARGET_FILE:fog-drift>)
set_tests_properties(triad.drift_refuses_in_bias PROPERTIES LABELS "integration;nav;triad" DEPENDS triad.drift_3d FIXTURES_REQUIRED triad_cal)
# every axis through every program: per-axis evaluation, fog-compensate's CSV read back
add_test(NAME triad.evaluate_every_axis COMMAND sh ${FOG_SOURCE_DIR}/tests/io/integration/triad_axes.sh
  $<TARGET_FILE:fog-evaluate> $<TARGET_FILE:fog-compensate> $<TARGET_FILE:fog-convert>
  ${_t3}/chamber3.rawlog ${_t3}/cal3.yaml ${_t3}/axes)
set_tests_properties(triad.evaluate_every_axis PROPERTIES LABELS "integration;io;triad" FIXTURES_REQUIRED triad_cal
  PASS_REGULAR_EXPRESSION "triad_axes: every axis evaluated and read back")
