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

# fog-refine never overwrites: an existing -o is refused (exit non-zero) and left as it was.
if(TARGET fog-refine)
  set(REFINE_DIR ${CMAKE_CURRENT_BINARY_DIR}/refine_keep)
  file(MAKE_DIRECTORY ${REFINE_DIR})
  add_test(NAME apps.fog-refine.keeps_existing_output
    COMMAND sh -c "cp '${FOG_SOURCE_DIR}/tests/data/model/cal_v2_full_A.yaml' '${REFINE_DIR}/old.yaml' && ! \"$0\" --cal '${FOG_SOURCE_DIR}/tests/data/model/cal_v2_full_A.yaml' -i '${FOG_SOURCE_DIR}/datasets/drive.rawlog' -o '${REFINE_DIR}/old.yaml' 2>'${REFINE_DIR}/err.txt' && grep -q 'exists' '${REFINE_DIR}/err.txt' && cmp '${FOG_SOURCE_DIR}/tests/data/model/cal_v2_full_A.yaml' '${REFINE_DIR}/old.yaml'"
      $<TARGET_FILE:fog-refine>)
  set_tests_properties(apps.fog-refine.keeps_existing_output PROPERTIES LABELS "apps;integration" TIMEOUT 60)
endif()
