# fog-compensate screens thermistor readings before compensating (ThermistorHealth): a
# thermistor frozen at one value from sample 1000 of the synthetic coil run B (0.1 Hz) is
# detected as stuck and its readings go to the fallback model; the clean run has no rejected
# reading (no false alarm on a slow, quantised log); --no-screening switches it off.
if(NOT TARGET fog-calibrate OR NOT TARGET fog-compensate)
  return()
endif()
set(_sd ${FOG_TEST_DATA_DIR}/model)
set(_so ${CMAKE_CURRENT_BINARY_DIR}/screening)
file(MAKE_DIRECTORY ${_so})

add_test(NAME screening.setup
  COMMAND sh -c "\"$0\" -i '${_sd}/coil_A.csv' --model multipoint -o '${_so}/cal.yaml' >/dev/null && awk -F, 'BEGIN{OFS=\",\"} /^#/||/^time/{print;next} {n++; if(n==1000) v=$3; if(n>=1000) $3=v; print}' '${_sd}/coil_B.csv' > '${_so}/coil_B_stuck_Ti1.csv'"
          $<TARGET_FILE:fog-calibrate>)
set_tests_properties(screening.setup PROPERTIES LABELS "integration;model" FIXTURES_SETUP screening_data)

add_test(NAME screening.stuck_detected
  COMMAND fog-compensate -i ${_so}/coil_B_stuck_Ti1.csv --cal ${_so}/cal.yaml -o ${_so}/stuck_comp.csv
          --json ${_so}/stuck_comp.json)
set_tests_properties(screening.stuck_detected PROPERTIES LABELS "integration;model" FIXTURES_REQUIRED screening_data
  PASS_REGULAR_EXPRESSION "fallback model used: 1[0-9][0-9][0-9] samples.*thermistor Ti1: stuck 1[0-9][0-9][0-9] samples \\(1 events\\)")
add_test(NAME screening.stuck_json
  COMMAND sh -c "grep -q '\"screening\"' '${_so}/stuck_comp.json' && grep -q '\"rejected_readings\": 1[0-9][0-9][0-9]' '${_so}/stuck_comp.json'")
set_tests_properties(screening.stuck_json PROPERTIES LABELS "integration;model" DEPENDS screening.stuck_detected
  FIXTURES_REQUIRED screening_data)
add_test(NAME screening.clean_run_no_false_alarm
  COMMAND fog-compensate -i ${_sd}/coil_B.csv --cal ${_so}/cal.yaml -o ${_so}/clean_comp.csv)
set_tests_properties(screening.clean_run_no_false_alarm PROPERTIES LABELS "integration;model"
  FIXTURES_REQUIRED screening_data
  PASS_REGULAR_EXPRESSION "fallback model used: 0 samples.*thermistor screening: all readings accepted")
add_test(NAME screening.off
  COMMAND fog-compensate -i ${_so}/coil_B_stuck_Ti1.csv --cal ${_so}/cal.yaml -o ${_so}/noscr_comp.csv
          --no-screening)
set_tests_properties(screening.off PROPERTIES LABELS "integration;model" FIXTURES_REQUIRED screening_data
  PASS_REGULAR_EXPRESSION "fallback model used: 0 samples.*thermistor screening: off")
