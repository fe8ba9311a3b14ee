# Every program: --help prints the usage and exits 0 without doing any work; an unknown option
# is one error line naming the program and exit status 2 (MRPT's TCLAP does not exit by itself).
foreach(app fog-convert fog-sim fog-calibrate fog-compensate fog-evaluate fog-drift fog-discrepancy fog-paper fog-demo)
  if(TARGET ${app})
    add_test(NAME apps.${app}.help_and_usage_error COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:${app}> -DNAME=${app}
      -P ${FOG_SOURCE_DIR}/tests/apps/check_help.cmake)
    set_tests_properties(apps.${app}.help_and_usage_error PROPERTIES LABELS "apps;integration" TIMEOUT 60)
  endif()
endforeach()
