# The option layer and the output rule (apps/common/Options.h), for every program:
#  - options.sources: no numeric or file option is declared outside the layer;
#  - options.<program>.table (label long): every numeric option --help lists gets each of -1, 0,
#    nan, 1e308, 1e-308, checked against the range --help prints; each run stops at the parser;
#  - outputs.<program>.collisions (label long): every output collided with every input and
#    every other output;
#  - options.<program>.quick (default suite): --help read, one option value and one collision
#    (three program starts: a start costs ~0.3 s in Release, ~20x that under ASan);
#  - hostile.*: the command lines and columns that once destroyed inputs, ran away or were silent.
set(_opt_programs fog-calibrate fog-compensate fog-convert fog-demo fog-discrepancy fog-drift fog-evaluate
  fog-localize fog-paper fog-sim)
# numeric options each program has at least (so a program whose --help lost them fails)
set(_opt_min_fog-calibrate 9)
set(_opt_min_fog-demo 1)
set(_opt_min_fog-discrepancy 3)
set(_opt_min_fog-drift 2)
set(_opt_min_fog-evaluate 1)
set(_opt_min_fog-localize 12)
set(_opt_min_fog-paper 2)
set(_opt_min_fog-sim 3)
add_test(NAME options.sources COMMAND ${CMAKE_COMMAND} -DSRC=${FOG_SOURCE_DIR}
  -P ${FOG_SOURCE_DIR}/tests/apps/check_option_sources.cmake)
set_tests_properties(options.sources PROPERTIES LABELS "apps;integration")
foreach(app IN LISTS _opt_programs)
  if(NOT TARGET ${app})
    continue()
  endif()
  set(_min 0)
  if(DEFINED _opt_min_${app})
    set(_min ${_opt_min_${app}})
  endif()
  add_test(NAME options.${app}.quick COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:${app}> -DNAME=${app}
    -DMIN_OPTIONS=${_min} -DMIN_OUTPUTS=1 -DWORK=${CMAKE_CURRENT_BINARY_DIR}/options_quick_${app}
    -P ${FOG_SOURCE_DIR}/tests/apps/check_program_options.cmake)
  add_test(NAME options.${app}.table COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:${app}> -DNAME=${app}
    -DSUBSET=OFF -DMIN_OPTIONS=${_min} -P ${FOG_SOURCE_DIR}/tests/apps/check_options.cmake)
  add_test(NAME outputs.${app}.collisions COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:${app}> -DNAME=${app}
    -DMIN_OUTPUTS=1 -DWORK=${CMAKE_CURRENT_BINARY_DIR}/outputs_${app} -P ${FOG_SOURCE_DIR}/tests/apps/check_outputs.cmake)
  set_tests_properties(options.${app}.quick PROPERTIES LABELS "apps;integration" TIMEOUT 120)
  set_tests_properties(options.${app}.table outputs.${app}.collisions PROPERTIES LABELS "apps;integration;long"
    TIMEOUT 900)
endforeach()

if(TARGET fog-discrepancy AND TARGET fog-localize AND TARGET fog-calibrate AND TARGET fog-compensate)
  foreach(_case write_cal_onto_inputs negative_counts field_range)
    add_test(NAME hostile.${_case} COMMAND ${CMAKE_COMMAND} -DCASE=${_case} -DBIN=$<TARGET_FILE_DIR:fog-compensate>
      -DDATA=${FOG_TEST_DATA_DIR} -DWORK=${CMAKE_CURRENT_BINARY_DIR}/hostile_${_case}
      -P ${FOG_SOURCE_DIR}/tests/apps/check_hostile_cases.cmake)
    set_tests_properties(hostile.${_case} PROPERTIES LABELS "apps;integration" TIMEOUT 300)
  endforeach()
endif()
