# I/O integration tests: fog-convert on bad inputs, MRPT's rawlog-edit reading our rawlogs (with
# libmrpt_fog.so as plugin, and the stock form without it), and an out-of-tree find_package
# consumer built against the installed package. Scripts: tests/io/integration/*.cmake.
set(io_scripts ${FOG_SOURCE_DIR}/tests/io/integration)
set(io_data ${FOG_SOURCE_DIR}/tests/data/io)
set(io_work ${CMAKE_CURRENT_BINARY_DIR}/io)

if(TARGET fog-convert)
  add_test(NAME io_convert_bad_inputs COMMAND ${CMAKE_COMMAND} -DFOG_CONVERT=$<TARGET_FILE:fog-convert>
    -DDATA=${io_data} -DWORK=${io_work}/bad_inputs -P ${io_scripts}/convert_bad_inputs.cmake)
  set_tests_properties(io_convert_bad_inputs PROPERTIES LABELS "io;integration")
  add_test(NAME io_convert_roundtrip COMMAND ${CMAKE_COMMAND} -DFOG_CONVERT=$<TARGET_FILE:fog-convert>
    -DDATA=${io_data} -DWORK=${io_work}/roundtrip -P ${io_scripts}/convert_roundtrip.cmake)
  set_tests_properties(io_convert_roundtrip PROPERTIES LABELS "io;integration")

  find_program(FOG_RAWLOG_EDIT rawlog-edit)
  if(FOG_RAWLOG_EDIT)
    foreach(mode plugin-info export-txt stock-info)
      add_test(NAME io_rawlog_edit_${mode} COMMAND ${CMAKE_COMMAND} -DFOG_CONVERT=$<TARGET_FILE:fog-convert>
        -DRAWLOG_EDIT=${FOG_RAWLOG_EDIT} -DPLUGIN=$<TARGET_FILE:mrpt_fog> -DDATA=${io_data}
        -DWORK=${io_work}/rawlog_edit_${mode} -DMODE=${mode} -P ${io_scripts}/rawlog_edit.cmake)
      set_tests_properties(io_rawlog_edit_${mode} PROPERTIES LABELS "io;integration")
    endforeach()
  else()
    # Fail loudly rather than skip: the acceptance test needs MRPT's rawlog-edit (mrpt-apps).
    message(WARNING "rawlog-edit not found: install the Debian package mrpt-apps (scripts/setup.sh)")
    add_test(NAME io_rawlog_edit_missing COMMAND ${CMAKE_COMMAND} -E false)
    set_tests_properties(io_rawlog_edit_missing PROPERTIES LABELS "io;integration")
  endif()
endif()

add_test(NAME io_find_package_consumer COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR}
  -DCONSUMER_SRC=${FOG_SOURCE_DIR}/tests/consumer -DWORK=${io_work}/consumer
  -DCMAKE_GENERATOR=${CMAKE_GENERATOR} -P ${io_scripts}/find_package_consumer.cmake)
set_tests_properties(io_find_package_consumer PROPERTIES LABELS "io;integration" TIMEOUT 600)

# Files are sacred: outputs equal to inputs, FIFOs, symlinks, modes, signals (issue 14).
if(TARGET fog-convert AND TARGET fog-calibrate AND TARGET fog-compensate AND TARGET fog-evaluate)
  add_test(NAME io_files_sacred COMMAND bash ${io_scripts}/files_sacred.sh $<TARGET_FILE_DIR:fog-convert>
    ${FOG_SOURCE_DIR} ${io_work}/files_sacred)
  set_tests_properties(io_files_sacred PROPERTIES LABELS "io;integration" TIMEOUT 300)
endif()

# The same thermistor screening in every program (issue 14).
if(TARGET fog-calibrate AND TARGET fog-evaluate)
  add_test(NAME io_screening_everywhere COMMAND bash ${io_scripts}/screening_everywhere.sh
    $<TARGET_FILE_DIR:fog-calibrate> ${FOG_SOURCE_DIR} ${io_work}/screening_everywhere)
  set_tests_properties(io_screening_everywhere PROPERTIES LABELS "io;integration" TIMEOUT 300)
endif()

# No silent empty model (issue 14).
if(TARGET fog-calibrate)
  add_test(NAME io_calibrate_empty_model COMMAND bash ${io_scripts}/empty_model.sh
    $<TARGET_FILE_DIR:fog-calibrate> ${FOG_SOURCE_DIR} ${io_work}/empty_model)
  set_tests_properties(io_calibrate_empty_model PROPERTIES LABELS "io;integration" TIMEOUT 300)
endif()

# fog-drift streams a single-axis drive; the figures must be those of --in-memory (issue 14).
if(TARGET fog-sim AND TARGET fog-calibrate AND TARGET fog-drift)
  add_test(NAME io_drift_streaming_equals_in_memory COMMAND bash ${io_scripts}/drift_streaming.sh
    $<TARGET_FILE:fog-sim> $<TARGET_FILE:fog-calibrate> $<TARGET_FILE:fog-drift> ${FOG_SOURCE_DIR} ${io_work}/drift_streaming)
  set_tests_properties(io_drift_streaming_equals_in_memory PROPERTIES LABELS "io;integration;nav" TIMEOUT 300)
endif()

# Logger CSVs read through a format file (docs/reference/format-files.md): the same calibration
# and held-out figures as the native CSV of the same samples, to 1e-6 relative (the vendor files
# written by scripts/vendor_layout.py, independent of the C++ readers). Default suite: the first
# 2400 rows of every 10th (1 Hz, 40 min) of chamber A (fit) and B (held out); long: both runs whole.
find_program(FOG_PYTHON3_IO python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(FOG_PYTHON3_IO AND TARGET fog-calibrate AND TARGET fog-evaluate)
  add_test(NAME io.format_equivalence COMMAND sh ${io_scripts}/format_equivalence.sh
    $<TARGET_FILE:fog-calibrate> $<TARGET_FILE:fog-evaluate> ${FOG_SOURCE_DIR} ${io_work}/format_equivalence 10 2400)
  set_tests_properties(io.format_equivalence PROPERTIES LABELS "io;integration"
    PASS_REGULAR_EXPRESSION "format_equivalence: same calibration and figures")
  add_test(NAME io.format_equivalence_full COMMAND sh ${io_scripts}/format_equivalence.sh
    $<TARGET_FILE:fog-calibrate> $<TARGET_FILE:fog-evaluate> ${FOG_SOURCE_DIR} ${io_work}/format_equivalence_full 1 0)
  set_tests_properties(io.format_equivalence_full PROPERTIES LABELS "io;integration;long"
    PASS_REGULAR_EXPRESSION "format_equivalence: same calibration and figures")
endif()

# The quickstart of docs/guide/calibrate-your-gyro.md on examples/your_gyro/, as written.
if(TARGET fog-convert AND TARGET fog-calibrate AND TARGET fog-evaluate AND TARGET fog-compensate)
  add_test(NAME guide.calibrate_your_gyro COMMAND sh ${io_scripts}/guide_quickstart.sh ${FOG_SOURCE_DIR}
    $<TARGET_FILE_DIR:fog-convert> ${io_work}/guide_quickstart)
  set_tests_properties(guide.calibrate_your_gyro PROPERTIES LABELS "io;integration"
    PASS_REGULAR_EXPRESSION "guide_quickstart: the quickstart runs")
endif()
if(TARGET fog-convert AND TARGET fog-calibrate AND TARGET fog-evaluate AND TARGET fog-compensate)
  add_test(NAME io.format_errors COMMAND sh ${io_scripts}/format_errors.sh $<TARGET_FILE_DIR:fog-convert>
    ${FOG_SOURCE_DIR} ${io_work}/format_errors)
  set_tests_properties(io.format_errors PROPERTIES LABELS "io;integration"
    PASS_REGULAR_EXPRESSION "format_errors: every bad format stopped with its key named and no output")
endif()
if(FOG_PYTHON3_IO AND TARGET fog-calibrate AND TARGET fog-evaluate)
  add_test(NAME io.unit_slip_warned COMMAND sh ${io_scripts}/unit_slip.sh $<TARGET_FILE_DIR:fog-calibrate>
    ${FOG_SOURCE_DIR} ${io_work}/unit_slip)
  set_tests_properties(io.unit_slip_warned PROPERTIES LABELS "io;integration" PASS_REGULAR_EXPRESSION "unit_slip: named")
endif()
