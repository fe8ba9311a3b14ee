# fog-paper end to end: runs the seed experiment on the simulated gyro and checks the JSON keys
# the issue fixes (paper, ours.in_sample, ours.held_out; each entry with stability_dph and
# range_dph) and that the PNGs are written; and the in-sample reproduction keeps the paper's
# qualitative result: multi-point (3 points) beats the uncompensated output by > 10x in stability.
if(TARGET fog-paper)
  add_test(NAME paper_tables_json COMMAND bash ${FOG_SOURCE_DIR}/tests/sim/integration/fog_paper_json.sh
    $<TARGET_FILE:fog-paper> ${CMAKE_CURRENT_BINARY_DIR}/paper)
  set_tests_properties(paper_tables_json PROPERTIES LABELS "paper;integration" TIMEOUT 300)
endif()
