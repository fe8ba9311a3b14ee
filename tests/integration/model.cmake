# Integration tests of the thermal-bias model programs (fog-calibrate, fog-compensate) on the
# synthetic coil runs in tests/data/model (see its README.md).
if(NOT TARGET fog-calibrate OR NOT TARGET fog-compensate)
  return()
endif()
set(_md ${FOG_TEST_DATA_DIR}/model)
set(_mo ${CMAKE_CURRENT_BINARY_DIR}/model)
file(MAKE_DIRECTORY ${_mo})

# Fit on run A, validate on run B: prints in-sample and held-out figures side by side.
add_test(NAME model.calibrate
  COMMAND fog-calibrate -i ${_md}/coil_A.csv --model multipoint -o ${_mo}/cal.yaml
          --validate ${_md}/coil_B.csv --json ${_mo}/fit.json)
set_tests_properties(model.calibrate PROPERTIES LABELS "integration;model" FIXTURES_SETUP model_cal
  PASS_REGULAR_EXPRESSION "in-sample +held-out \\(leave-regime-out, [0-9]+ regimes in [0-9]+ folds\\) +validation run")

# The JSON has the stable keys.
add_test(NAME model.calibrate_json
  COMMAND sh -c "grep -q '\"in_sample\"' '${_mo}/fit.json' && grep -q '\"held_out\"' '${_mo}/fit.json' && grep -q '\"validation\"' '${_mo}/fit.json' && grep -q '\"stability_dph\"' '${_mo}/fit.json'")
set_tests_properties(model.calibrate_json PROPERTIES LABELS "integration;model" FIXTURES_REQUIRED model_cal)

# Compensation to CSV and to a stock-MRPT rawlog; the dropout run uses fallback models.
add_test(NAME model.compensate_csv
  COMMAND fog-compensate -i ${_md}/coil_B_dropout.csv --cal ${_mo}/cal.yaml -o ${_mo}/comp.csv --json ${_mo}/comp.json)
set_tests_properties(model.compensate_csv PROPERTIES LABELS "integration;model" FIXTURES_REQUIRED model_cal
  PASS_REGULAR_EXPRESSION "fallback model used: [1-9][0-9]* samples")
add_test(NAME model.compensate_rawlog
  COMMAND fog-compensate -i ${_md}/coil_B.csv --cal ${_mo}/cal.yaml -o ${_mo}/comp.rawlog)
set_tests_properties(model.compensate_rawlog PROPERTIES LABELS "integration;model" FIXTURES_REQUIRED model_cal
  PASS_REGULAR_EXPRESSION "2520 samples")

# Bad input: one clear line, exit status 1, and no output file left behind.
add_test(NAME model.compensate_other_layout
  COMMAND sh -c "out=$(\"$0\" -i '${_md}/coil_B_other_layout.csv' --cal '${_mo}/cal.yaml' -o '${_mo}/bad.csv' 2>&1); rc=$?; echo \"$out\"; [ $rc -eq 1 ] && echo \"$out\" | grep -q 'another sensor layout' && [ ! -e '${_mo}/bad.csv' ]"
          $<TARGET_FILE:fog-compensate>)
set_tests_properties(model.compensate_other_layout PROPERTIES LABELS "integration;model" FIXTURES_REQUIRED model_cal)
add_test(NAME model.calibrate_bad_preset
  COMMAND sh -c "out=$(\"$0\" -i '${_md}/coil_A.csv' --model M9 -o '${_mo}/bad.yaml' 2>&1); rc=$?; echo \"$out\"; [ $rc -eq 1 ] && echo \"$out\" | grep -q \"unknown preset 'M9'\" && [ ! -e '${_mo}/bad.yaml' ]"
          $<TARGET_FILE:fog-calibrate>)
set_tests_properties(model.calibrate_bad_preset PROPERTIES LABELS "integration;model")
add_test(NAME model.compensate_bad_calibration
  COMMAND sh -c "printf 'format: \"other\"\\n' > '${_mo}/broken.yaml'; out=$(\"$0\" -i '${_md}/coil_B.csv' --cal '${_mo}/broken.yaml' -o '${_mo}/bad2.csv' 2>&1); rc=$?; echo \"$out\"; [ $rc -eq 1 ] && echo \"$out\" | grep -q 'broken.yaml: format' && [ ! -e '${_mo}/bad2.csv' ]"
          $<TARGET_FILE:fog-compensate>)
set_tests_properties(model.compensate_bad_calibration PROPERTIES LABELS "integration;model")
add_test(NAME model.calibrate_help COMMAND fog-calibrate --help)
set_tests_properties(model.calibrate_help PROPERTIES LABELS "integration;model"
  PASS_REGULAR_EXPRESSION "MODEL PRESETS.*points:K.*HOW THE FIT GUARDS")
add_test(NAME model.compensate_help COMMAND fog-compensate --help)
set_tests_properties(model.compensate_help PROPERTIES LABELS "integration;model"
  PASS_REGULAR_EXPRESSION "fallback model")

# MRPT's own rawlog-edit reads the compensated stock-MRPT rawlog (2520 samples of coil_B:
# one CObservationIMU and one CObservationRawDAQ each).
find_program(FOG_RAWLOG_EDIT rawlog-edit)
if(FOG_RAWLOG_EDIT)
  add_test(NAME model.compensated_rawlog_read_by_mrpt
    COMMAND ${FOG_RAWLOG_EDIT} --info -i ${_mo}/comp.rawlog)
  set_tests_properties(model.compensated_rawlog_read_by_mrpt PROPERTIES LABELS "integration;model"
    DEPENDS model.compensate_rawlog FIXTURES_REQUIRED model_cal
    PASS_REGULAR_EXPRESSION "Overall number of objects +: 5040.*FOG_THERMISTORS")
endif()

# Calibration from a rawlog (made by fog-convert) gives the same model as from the CSV.
if(TARGET fog-convert)
  add_test(NAME model.calibrate_from_rawlog
    COMMAND sh -c "\"$0\" -i '${_md}/coil_A.csv' -o '${_mo}/coil_A.rawlog' >/dev/null && \"$1\" -i '${_mo}/coil_A.rawlog' --model M2:Ti1 -o '${_mo}/cal_rawlog.yaml' | grep 'model:' > '${_mo}/m_rawlog.txt' && \"$1\" -i '${_md}/coil_A.csv' --model M2:Ti1 -o '${_mo}/cal_csv.yaml' | grep 'model:' > '${_mo}/m_csv.txt' && cmp '${_mo}/m_rawlog.txt' '${_mo}/m_csv.txt' && grep -q 'terms' '${_mo}/m_csv.txt'"
            $<TARGET_FILE:fog-convert> $<TARGET_FILE:fog-calibrate>)
  set_tests_properties(model.calibrate_from_rawlog PROPERTIES LABELS "integration;model")
endif()

# Scale-factor interval on held-out simulator runs (18 rate-table runs, a few minutes: long).
if(TARGET fog-sim)
  add_test(NAME model.scale_factor_interval_trial
    COMMAND bash ${FOG_SOURCE_DIR}/tests/model/scale_factor/interval_trial.sh $<TARGET_FILE:fog-sim>
            $<TARGET_FILE:fog-calibrate> ${FOG_SOURCE_DIR} ${_mo}/sf_trial)
  set_tests_properties(model.scale_factor_interval_trial PROPERTIES LABELS "long;integration;model" TIMEOUT 1800)
endif()

# fog-calibrate on runs that give a part of the fit nothing: n/a held out, no turn-on in a run never
# powered, one warm-up story when a run is both -i and --warmup-run, no unresolved magnetic term.
add_test(NAME model.calibrate_edge_cases COMMAND ${CMAKE_COMMAND} -DBIN=$<TARGET_FILE_DIR:fog-calibrate>
  -DDATA=${FOG_SOURCE_DIR}/tests/data/model -DWORK=${CMAKE_CURRENT_BINARY_DIR}/model/edge_cases
  -P ${FOG_SOURCE_DIR}/tests/model/integration/calibrate_edge_cases.cmake)
set_tests_properties(model.calibrate_edge_cases PROPERTIES LABELS "integration;model")

# One chamber run that starts with a turn-on calibrates bias and warm-up (--turn-on-exclusion).
if(TARGET fog-sim)
  add_test(NAME model.one_run_calibration COMMAND ${CMAKE_COMMAND} -DBIN=$<TARGET_FILE_DIR:fog-calibrate>
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/model/one_run -P ${FOG_SOURCE_DIR}/tests/model/integration/one_run_calibration.cmake)
  set_tests_properties(model.one_run_calibration PROPERTIES LABELS "integration;model")
endif()
