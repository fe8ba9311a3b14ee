# fog-demo end to end on the bundled datasets: the report exists, holds the headline figures,
# and fog-demo refuses to write into a non-empty folder it did not make.
if(TARGET fog-demo)
  add_test(NAME demo.fog_demo.end_to_end COMMAND ${CMAKE_COMMAND} -DDEMO=$<TARGET_FILE:fog-demo>
    -DDATASETS=${FOG_SOURCE_DIR}/datasets -DWORK=${CMAKE_CURRENT_BINARY_DIR}/demo -P ${FOG_SOURCE_DIR}/tests/demo/demo_checks.cmake)
  set_tests_properties(demo.fog_demo.end_to_end PROPERTIES LABELS "demo;integration" TIMEOUT 600)
endif()
