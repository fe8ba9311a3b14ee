# Simulator integration tests: fog-sim reproducibility (same arguments -> same bytes), bad inputs,
# the bundled datasets' checksums, and their bit-for-bit regeneration by scripts/make_datasets.sh.
set(sim_scripts ${FOG_SOURCE_DIR}/tests/sim/integration)
set(sim_work ${CMAKE_CURRENT_BINARY_DIR}/sim)

add_test(NAME sim_datasets_manifest_checksums COMMAND bash ${sim_scripts}/manifest_checksums.sh ${FOG_SOURCE_DIR})
set_tests_properties(sim_datasets_manifest_checksums PROPERTIES LABELS "sim;integration")

if(TARGET fog-sim)
  add_test(NAME sim_short_run_reproducible
    COMMAND bash ${sim_scripts}/short_run_reproducible.sh $<TARGET_FILE:fog-sim> ${sim_work}/repro)
  set_tests_properties(sim_short_run_reproducible PROPERTIES LABELS "sim;integration")
  add_test(NAME sim_bad_inputs COMMAND bash ${sim_scripts}/bad_inputs.sh $<TARGET_FILE:fog-sim> ${sim_work}/bad)
  set_tests_properties(sim_bad_inputs PROPERTIES LABELS "sim;integration")
  add_test(NAME sim_datasets_regenerate
    COMMAND bash ${sim_scripts}/datasets_regenerate.sh $<TARGET_FILE:fog-sim> ${FOG_SOURCE_DIR} ${sim_work}/datasets)
  set_tests_properties(sim_datasets_regenerate PROPERTIES LABELS "sim;integration" TIMEOUT 300)
endif()
