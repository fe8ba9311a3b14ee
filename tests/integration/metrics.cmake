# Metrics integration: fog-evaluate end to end on small CSV runs with closed-form figures, with a
# calibration made by fog-calibrate, and on bad inputs. Script: tests/metrics/integration/.
if(TARGET fog-evaluate)
  set(metrics_script ${FOG_SOURCE_DIR}/tests/metrics/integration/evaluate_checks.cmake)
  set(metrics_work ${CMAKE_CURRENT_BINARY_DIR}/metrics)
  set(metrics_convert "")
  if(TARGET fog-convert)
    set(metrics_convert -DCONVERT=$<TARGET_FILE:fog-convert>)
  endif()
  foreach(mode step bad)
    add_test(NAME metrics.fog_evaluate.${mode} COMMAND ${CMAKE_COMMAND} -DEVALUATE=$<TARGET_FILE:fog-evaluate>
      ${metrics_convert} -DDATA=${FOG_TEST_DATA_DIR}/metrics -DWORK=${metrics_work}/${mode} -DMODE=${mode} -P ${metrics_script})
    set_tests_properties(metrics.fog_evaluate.${mode} PROPERTIES LABELS "metrics;integration" TIMEOUT 120)
  endforeach()
  if(TARGET fog-calibrate)
    add_test(NAME metrics.fog_evaluate.cal COMMAND ${CMAKE_COMMAND} -DEVALUATE=$<TARGET_FILE:fog-evaluate>
      -DCALIBRATE=$<TARGET_FILE:fog-calibrate> -DDATA=${FOG_TEST_DATA_DIR}/metrics -DWORK=${metrics_work}/cal
      -DMODE=cal -P ${metrics_script})
    set_tests_properties(metrics.fog_evaluate.cal PROPERTIES LABELS "metrics;integration" TIMEOUT 300)
  endif()
endif()
