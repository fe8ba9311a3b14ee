# Navigation integration: MRPT's own pf-localization reads the dead-reckoned odometry rawlog
# written by mrpt_fog_nav, and its odometry estimate (odo_est.txt) must equal our trajectory.
# Three ctest tests chained by a fixture: write -> pf-localization -> compare.
# The heading error budget's truth split (drive-truth + scripts/heading_budget_truth.py) reproduces
# fog-drift's compensated/ideal heading RMS on the same short drive (docs/validation/navigation.md, "Error budget").
find_program(NAV_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(TARGET fog-drift AND TARGET fog-sim AND TARGET drive-truth AND NAV_PYTHON3)
  add_test(NAME nav.truth_split.matches_fog_drift
    COMMAND bash ${FOG_SOURCE_DIR}/tests/nav/integration/truth_split_check.sh $<TARGET_FILE:fog-sim>
      $<TARGET_FILE:fog-drift> $<TARGET_FILE:drive-truth> ${FOG_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/nav_truth_split)
  set_tests_properties(nav.truth_split.matches_fog_drift PROPERTIES LABELS "nav;integration" TIMEOUT 300)
endif()

find_program(NAV_PF_LOCALIZATION pf-localization)
if(NOT NAV_PF_LOCALIZATION)
  message(STATUS "nav integration: pf-localization not found (package mrpt-apps); test skipped")
  return()
endif()

add_executable(nav_pf_check ${FOG_SOURCE_DIR}/tests/nav/pf/PfLocalizationCheck.cpp)
target_link_libraries(nav_pf_check PRIVATE mrpt_fog_nav mrpt::io mrpt::serialization)

set(NAV_PF_DIR ${CMAKE_CURRENT_BINARY_DIR}/nav_pf)
set(NAV_PF_RAWLOG ${NAV_PF_DIR}/nav_odometry.rawlog)
set(NAV_PF_LOGDIR ${NAV_PF_DIR}/LOG_LOCALIZATION)
configure_file(${FOG_TEST_DATA_DIR}/nav/pf_localization_odometry.ini.in ${NAV_PF_DIR}/pf.ini @ONLY)

add_test(NAME nav.pf_localization.write COMMAND nav_pf_check write ${NAV_PF_DIR})
set_tests_properties(nav.pf_localization.write PROPERTIES FIXTURES_SETUP nav_pf_rawlog LABELS "nav;integration")

# pf-localization's usage is "pf-localization <config.ini>"; with no display and no 3D window
# it runs to the end of the rawlog and exits. stdin from /dev/null (it polls for ESC).
add_test(NAME nav.pf_localization.run
  COMMAND sh -c "'${NAV_PF_LOCALIZATION}' '${NAV_PF_DIR}/pf.ini' < /dev/null"
  WORKING_DIRECTORY ${NAV_PF_DIR})
set_tests_properties(nav.pf_localization.run PROPERTIES FIXTURES_REQUIRED nav_pf_rawlog
  FIXTURES_SETUP nav_pf_output TIMEOUT 300 ENVIRONMENT "DISPLAY=" LABELS "nav;integration")

# Output directory: <logOutput_dir>_<repetition %03u>_<particles %07i>.
add_test(NAME nav.pf_localization.compare
  COMMAND nav_pf_check compare ${NAV_PF_DIR} ${NAV_PF_LOGDIR}_000_0000100/odo_est.txt)
set_tests_properties(nav.pf_localization.compare PROPERTIES FIXTURES_REQUIRED nav_pf_output
  LABELS "nav;integration")

# fog-drift end to end on a synthetic drive with closed-form truth (tests/nav/drive/TestDrive.cpp):
# the ideal gyro must reproduce the truth, the raw gyro's final heading error must equal the
# integral of its known thermal bias, and the compensated one (calibration fitted on a static
# chamber run of the same law) must come back to the truth.
if(TARGET fog-drift)
  add_executable(nav_test_drive ${FOG_SOURCE_DIR}/tests/nav/drive/TestDrive.cpp)
  target_link_libraries(nav_test_drive PRIVATE mrpt_fog)
  set(NAV_DRIVE_DIR ${CMAKE_CURRENT_BINARY_DIR}/nav_drive)
  file(MAKE_DIRECTORY ${NAV_DRIVE_DIR})
  add_test(NAME nav.fog_drift.write_drive COMMAND nav_test_drive write ${NAV_DRIVE_DIR}/drive.rawlog ${NAV_DRIVE_DIR}/cal.yaml)
  set_tests_properties(nav.fog_drift.write_drive PROPERTIES FIXTURES_SETUP nav_drive LABELS "nav;integration")
  add_test(NAME nav.fog_drift.run COMMAND fog-drift -i ${NAV_DRIVE_DIR}/drive.rawlog --cal ${NAV_DRIVE_DIR}/cal.yaml --json ${NAV_DRIVE_DIR}/drift.json
    --plots ${NAV_DRIVE_DIR}/plots --odometry-out ${NAV_DRIVE_DIR}/odometry.rawlog)
  set_tests_properties(nav.fog_drift.run PROPERTIES FIXTURES_REQUIRED nav_drive FIXTURES_SETUP nav_drift_json
    LABELS "nav;integration")
  # fog-drift keeps a variant's trajectory only when --plots or --odometry-out needs it (memory,
  #): the figures and the odometry rawlog must not depend on which outputs were asked for.
  add_test(NAME nav.fog_drift.figures_do_not_depend_on_outputs
    COMMAND sh -c "d='${NAV_DRIVE_DIR}'; \"$0\" -q -i $d/drive.rawlog --cal $d/cal.yaml --json $d/drift_lean.json >/dev/null && \"$0\" -q -i $d/drive.rawlog --cal $d/cal.yaml --json $d/drift_odo.json --odometry-out $d/odometry_alone.rawlog >/dev/null && cmp $d/drift.json $d/drift_lean.json && cmp $d/drift.json $d/drift_odo.json && cmp $d/odometry.rawlog $d/odometry_alone.rawlog"
      $<TARGET_FILE:fog-drift>)
  set_tests_properties(nav.fog_drift.figures_do_not_depend_on_outputs PROPERTIES FIXTURES_REQUIRED nav_drift_json
    LABELS "nav;integration")
  # a calibration's magnetic term on a log without field: warned on stderr and in --json
  add_test(NAME nav.fog_drift.magnetic_warning COMMAND ${CMAKE_COMMAND} -DDRIFT=$<TARGET_FILE:fog-drift>
    -DDIR=${NAV_DRIVE_DIR} -P ${FOG_SOURCE_DIR}/tests/nav/integration/magnetic_warning_check.cmake)
  set_tests_properties(nav.fog_drift.magnetic_warning PROPERTIES FIXTURES_REQUIRED nav_drift_json
    LABELS "nav;integration")
  # an option overriding a different latitude in the metadata: a note and --json option_conflicts
  add_test(NAME nav.fog_drift.latitude_conflict_noted COMMAND ${CMAKE_COMMAND} -DDRIFT=$<TARGET_FILE:fog-drift>
    -DDIR=${NAV_DRIVE_DIR} -P ${FOG_SOURCE_DIR}/tests/nav/integration/latitude_conflict_check.cmake)
  set_tests_properties(nav.fog_drift.latitude_conflict_noted PROPERTIES FIXTURES_REQUIRED nav_drift_json
    LABELS "nav;integration")
  add_test(NAME nav.fog_drift.check COMMAND nav_test_drive check ${NAV_DRIVE_DIR}/drift.json)
  set_tests_properties(nav.fog_drift.check PROPERTIES FIXTURES_REQUIRED nav_drift_json LABELS "nav;integration")
  # The same drive with the gyro off for 250 s (power 0 rows), and a fog-sim drive with a
  # power-off cabin: the stretch reported, each powered span re-aligned from the truth, the
  # figures in closed form, streamed == --in-memory (tests/nav/integration/gyro_off_check.sh).
  if(TARGET fog-sim)
    add_test(NAME nav.fog_drift.gyro_off
      COMMAND bash ${FOG_SOURCE_DIR}/tests/nav/integration/gyro_off_check.sh $<TARGET_FILE:nav_test_drive>
        $<TARGET_FILE:fog-drift> $<TARGET_FILE:fog-sim> ${CMAKE_CURRENT_BINARY_DIR}/nav_gyro_off)
    set_tests_properties(nav.fog_drift.gyro_off PROPERTIES LABELS "nav;integration" TIMEOUT 300)
  endif()
  # fog-drift's --odometry-out (the compensated trajectory) read by pf-localization: the circle.
  set(NAV_PF_RAWLOG ${NAV_DRIVE_DIR}/odometry.rawlog)
  set(NAV_PF_LOGDIR ${NAV_DRIVE_DIR}/LOG_LOCALIZATION)
  configure_file(${FOG_TEST_DATA_DIR}/nav/pf_localization_odometry.ini.in ${NAV_DRIVE_DIR}/pf.ini @ONLY)
  file(READ ${NAV_DRIVE_DIR}/pf.ini nav_pf_ini)
  string(REGEX REPLACE "initial_odo_x=[^\n]*\ninitial_odo_y=[^\n]*\ninitial_odo_phi=[^\n]*\n"
    "initial_odo_x=0\ninitial_odo_y=0\ninitial_odo_phi=0\n" nav_pf_ini "${nav_pf_ini}")
  string(REPLACE "particles_count=100" "particles_count=20" nav_pf_ini "${nav_pf_ini}")
  file(WRITE ${NAV_DRIVE_DIR}/pf.ini "${nav_pf_ini}")
  add_test(NAME nav.fog_drift.pf_localization
    COMMAND sh -c "'${NAV_PF_LOCALIZATION}' '${NAV_DRIVE_DIR}/pf.ini' < /dev/null > pf.log"
    WORKING_DIRECTORY ${NAV_DRIVE_DIR})
  set_tests_properties(nav.fog_drift.pf_localization PROPERTIES FIXTURES_REQUIRED nav_drift_json
    FIXTURES_SETUP nav_drift_pf TIMEOUT 300 ENVIRONMENT "DISPLAY=" LABELS "nav;integration")
  add_test(NAME nav.fog_drift.pf_check
    COMMAND nav_pf_check circle ${NAV_DRIVE_DIR}/LOG_LOCALIZATION_000_0000020/odo_est.txt 12001 477.4648292756860)
  set_tests_properties(nav.fog_drift.pf_check PROPERTIES FIXTURES_REQUIRED nav_drift_pf LABELS "nav;integration")
  # Bad input: a missing file and a drive without truth give one line and a non-zero exit.
  add_test(NAME nav.fog_drift.missing_input COMMAND fog-drift -i ${NAV_DRIVE_DIR}/no_such.rawlog)
  set_tests_properties(nav.fog_drift.missing_input PROPERTIES WILL_FAIL TRUE LABELS "nav;integration")
endif()

# The turn-on offset learned in the field (docs/validation/turn-on-refinement.md): the bundled
# drive with and without +0.3 deg/h, nine drives with drawn offsets, a piece without a
# standstill, months of aging through fog-refine; the script's targets checked. About 15 min.
if(TARGET fog-drift AND TARGET fog-sim AND TARGET fog-calibrate AND TARGET fog-refine AND TARGET gyro-shift AND NAV_PYTHON3)
  add_test(NAME nav.turn_on_refinement
    COMMAND sh -c "cd '${FOG_SOURCE_DIR}' && BUILD='${PROJECT_BINARY_DIR}' NOSTILL_FROM=2760 NOSTILL_TO=4045 scripts/turn_on_refinement.sh '${CMAKE_CURRENT_BINARY_DIR}/turn_on_refinement' >/dev/null && python3 scripts/turn_on_refinement_summary.py '${CMAKE_CURRENT_BINARY_DIR}/turn_on_refinement' --check")
  set_tests_properties(nav.turn_on_refinement PROPERTIES LABELS "long;nav;integration" TIMEOUT 3600)
endif()
