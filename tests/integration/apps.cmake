# Every program (every apps/fog-* folder): --help prints the usage, ends with examples and exits
# 0 without doing any work; an unknown option is one error line naming the program and exit
# status 2 (MRPT's TCLAP does not exit by itself).
file(GLOB fog_app_dirs LIST_DIRECTORIES true ${FOG_SOURCE_DIR}/apps/fog-*)
set(fog_apps "")
foreach(dir ${fog_app_dirs})
  get_filename_component(app ${dir} NAME)
  list(APPEND fog_apps ${app})
endforeach()
foreach(app ${fog_apps})
  if(TARGET ${app})
    add_test(NAME apps.${app}.help_and_usage_error COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:${app}> -DNAME=${app}
      -P ${FOG_SOURCE_DIR}/tests/apps/check_help.cmake)
    set_tests_properties(apps.${app}.help_and_usage_error PROPERTIES LABELS "apps;integration" TIMEOUT 60)
  endif()
endforeach()
