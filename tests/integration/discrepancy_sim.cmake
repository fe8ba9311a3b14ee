# fog-discrepancy --sim end to end: fog-sim makes two "measured" runs (rich profile, 0.05 Hz)
# with shupe_rate, radial_gradient, heat_source, magnetic, earth_rate and thermistor_lag on; the
# simulator configurations under test leave one effect out (heat_source: named from the
# thermistor residual; magnetic: named from the bias residual) or none (null case). The JSON
# contract keys and the gap before/after are checked; bad input gives a one-line error.
# The checker and the SIM.yaml files are written into the build tree (no helper *.cmake here).
if(TARGET fog-discrepancy AND TARGET fog-sim)
  set(_ds_dir ${CMAKE_CURRENT_BINARY_DIR}/discrepancy_sim)
  set(_ds_check ${CMAKE_CURRENT_BINARY_DIR}/discrepancy_sim_check.txt)
  file(MAKE_DIRECTORY ${_ds_dir})
  file(WRITE ${_ds_dir}/noheat.yaml "effects: [shupe_rate, radial_gradient, magnetic, earth_rate, thermistor_lag]\n")
  file(WRITE ${_ds_dir}/nomag.yaml
    "effects: [shupe_rate, radial_gradient, heat_source, earth_rate, thermistor_lag]\n"
    "device:\n  errors: {radial_gradient_dph_per_C: 0.05}\n")
  file(WRITE ${_ds_dir}/null.yaml
    "effects: [shupe_rate, radial_gradient, heat_source, magnetic, earth_rate, thermistor_lag]\n"
    "free: [constant_bias_dph, radial_gradient_dph_per_C, winding_asymmetry_m, thermal_time_scale, thermistor_offsets_C]\n")
  file(WRITE ${_ds_check} [=[
# cmake -P checker: runs EXE ARGS; MODE=named expects named_effects[0].id == EXPECT_ID and the
# gap (bias, or temperature when TEMP=1) to shrink on both runs; MODE=none expects no named
# effect; MODE=error expects a one-line "fog-discrepancy: error:" containing EXPECT.
execute_process(COMMAND ${EXE} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(MODE STREQUAL "error")
  string(STRIP "${err}" e)
  string(FIND "${e}" "\n" nl)
  string(FIND "${e}" "fog-discrepancy: error:" p0)
  string(FIND "${e}" "${EXPECT}" p1)
  if(rc EQUAL 0 OR NOT nl EQUAL -1 OR p0 EQUAL -1 OR p1 EQUAL -1)
    message(FATAL_ERROR "want a one-line error containing '${EXPECT}', got exit ${rc}:\n${err}")
  endif()
  return()
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit ${rc}\n${out}\n${err}")
endif()
message("${out}")
file(READ ${JSON} j)
string(JSON kind GET "${j}" model_kind)
string(JSON n LENGTH "${j}" named_effects)
string(JSON b GET "${j}" gap before rms_dph)
string(JSON a GET "${j}" gap after rms_dph)
string(JSON cb GET "${j}" gap_confirm before rms_dph)
string(JSON ca GET "${j}" gap_confirm after rms_dph)
string(JSON tb GET "${j}" temperature_gap before rms_C)
string(JSON ta GET "${j}" temperature_gap after rms_C)
string(JSON ctb GET "${j}" temperature_gap_confirm before rms_C)
string(JSON cta GET "${j}" temperature_gap_confirm after rms_C)
string(JSON nseg LENGTH "${j}" segments)
string(JSON drive GET "${j}" simulator driving_input)
message("named ${n}; bias gap ${b} -> ${a}, confirm ${cb} -> ${ca}; temperature ${tb} -> ${ta}, confirm ${ctb} -> ${cta}; ${nseg} segments; ${drive}")
if(NOT kind STREQUAL "simulator" OR nseg LESS 3)
  message(FATAL_ERROR "model_kind '${kind}', ${nseg} segments")
endif()
if(MODE STREQUAL "none")
  string(JSON verdict GET "${j}" verdict)
  if(NOT n EQUAL 0 OR NOT verdict STREQUAL "no missing effect found")
    message(FATAL_ERROR "null case: ${n} named, verdict '${verdict}'")
  endif()
  return()
endif()
if(n LESS 1)
  message(FATAL_ERROR "nothing named, expected ${EXPECT_ID}")
endif()
string(JSON first GET "${j}" named_effects 0 id)
string(JSON conf GET "${j}" named_effects 0 confidence)
string(JSON confirmed GET "${j}" named_effects 0 confirmed)
if(NOT first STREQUAL EXPECT_ID OR NOT confirmed)
  message(FATAL_ERROR "first named '${first}' (want ${EXPECT_ID}), confirmed ${confirmed}")
endif()
if(TEMP)
  if(NOT ta LESS tb OR NOT cta LESS ctb)
    message(FATAL_ERROR "temperature gap did not shrink: ${tb} -> ${ta}, confirm ${ctb} -> ${cta}")
  endif()
else()
  if(NOT a LESS b OR NOT ca LESS cb)
    message(FATAL_ERROR "bias gap did not shrink: ${b} -> ${a}, confirm ${cb} -> ${ca}")
  endif()
endif()
]=])
  set(_ds_fx shupe_rate radial_gradient heat_source magnetic earth_rate thermistor_lag)
  set(_ds_eff "")
  foreach(e ${_ds_fx})
    list(APPEND _ds_eff --effect ${e})
  endforeach()
  add_test(NAME discrepancy_sim.run_a COMMAND fog-sim -p rich --rate-hz 0.05 --seed 1 ${_ds_eff} -o ${_ds_dir}/a.csv)
  add_test(NAME discrepancy_sim.run_b COMMAND fog-sim -p rich --rate-hz 0.05 --seed 2 ${_ds_eff} -o ${_ds_dir}/b.csv)
  set_tests_properties(discrepancy_sim.run_a discrepancy_sim.run_b PROPERTIES
    FIXTURES_SETUP disc_sim_runs LABELS "integration;discrepancy")

  set(_ds_runs "--measured;${_ds_dir}/a.csv;--measured;${_ds_dir}/b.csv")
  add_test(NAME discrepancy_sim.heat_source_named_from_temperatures
    COMMAND ${CMAKE_COMMAND} -DMODE=named -DEXPECT_ID=heat_source -DTEMP=1 -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=${_ds_runs};--sim;${_ds_dir}/noheat.yaml;--json;${_ds_dir}/noheat.json"
      -DJSON=${_ds_dir}/noheat.json -P ${_ds_check})
  add_test(NAME discrepancy_sim.magnetic_named_from_bias
    COMMAND ${CMAKE_COMMAND} -DMODE=named -DEXPECT_ID=magnetic -DTEMP=0 -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=${_ds_runs};--sim;${_ds_dir}/nomag.yaml;--json;${_ds_dir}/nomag.json"
      -DJSON=${_ds_dir}/nomag.json -P ${_ds_check})
  add_test(NAME discrepancy_sim.null_no_missing_effect
    COMMAND ${CMAKE_COMMAND} -DMODE=none -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=${_ds_runs};--sim;${_ds_dir}/null.yaml;--json;${_ds_dir}/null.json"
      -DJSON=${_ds_dir}/null.json -P ${_ds_check})
  add_test(NAME discrepancy_sim.missing_config_one_line_error
    COMMAND ${CMAKE_COMMAND} -DMODE=error -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=${_ds_runs};--sim;${_ds_dir}/no_such_sim.yaml" -DEXPECT=no_such_sim.yaml -P ${_ds_check})
  add_test(NAME discrepancy_sim.bad_free_parameter_one_line_error
    COMMAND ${CMAKE_COMMAND} -DMODE=error -DEXE=$<TARGET_FILE:fog-discrepancy>
      "-DARGS=${_ds_runs};--sim;${_ds_dir}/badfree.yaml" "-DEXPECT=unknown parameter 'gain'" -P ${_ds_check})
  file(WRITE ${_ds_dir}/badfree.yaml "free: [gain]\n")
  set_tests_properties(discrepancy_sim.heat_source_named_from_temperatures discrepancy_sim.magnetic_named_from_bias
    discrepancy_sim.null_no_missing_effect discrepancy_sim.missing_config_one_line_error
    discrepancy_sim.bad_free_parameter_one_line_error PROPERTIES
    FIXTURES_REQUIRED disc_sim_runs LABELS "integration;discrepancy")
endif()
