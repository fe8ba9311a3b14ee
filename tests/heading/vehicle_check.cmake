# A vehicle's own rawlog through the programs (docs/guide/your-vehicle.md):
# -D GEN=vehicle-rawlog-gen -D ODO=fog-odometry -D COMP=fog-compensate -D DRIFT=fog-drift
# -D DRIVE=datasets/drive.rawlog -D CAL=<calibration> -D WORK=<scratch> -D DURATION=<s>
# [-D TARGETS=ON: the heading figures against the held-back truth]
# 1. vehicle-rawlog-gen (MRPT's classes only) writes the drive's first DURATION s with a lidar,
#    GPS, camera and MEMS IMU at 1 Hz and no truth, in both formats, and the truth apart;
# 2. per format: fog-compensate exits 0, keeps the format and the count of every label but the
#    FOG's (which becomes the stock IMU 'FOG' + RawDAQ 'FOG_THERMISTORS' pair, one per sample; its
#    metadata comment is not written);
#    fog-odometry keeps the format and every count; fog-drift runs without truth;
# 3. TARGETS: the FOG odometry's heading RMS against the truth <= 0.1 deg and <= 0.05 x the wheels'.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${so}\n${se}")
  endif()
  set(out "${so}" PARENT_SCOPE)
endfunction()
# counts(<file> <var>): "FORMAT ..." and "COUNT <class> '<label>' <n>" lines, as a list
function(counts file var)
  run("count ${file}" ${GEN} --count ${file})
  string(REPLACE "\n" ";" lines "${out}")
  set(${var} "${lines}" PARENT_SCOPE)
endfunction()

run("vehicle-rawlog-gen" ${GEN} ${DRIVE} ${WORK}/vehicle --duration-s ${DURATION})
foreach(fmt obs act)
  set(in ${WORK}/vehicle_${fmt}.rawlog)
  counts(${in} c_in)
  foreach(label LIDAR GPS CAMERA IMU_MEMS)
    if(NOT c_in MATCHES "'${label}' [1-9]")
      message(FATAL_ERROR "${in}: no '${label}' objects: ${c_in}")
    endif()
  endforeach()
  if(c_in MATCHES "GROUND_TRUTH")
    message(FATAL_ERROR "${in} holds a truth")
  endif()
  # fog-compensate
  run("fog-compensate ${fmt}" ${COMP} -q -i ${in} --cal ${CAL} -o ${WORK}/comp_${fmt}.rawlog)
  counts(${WORK}/comp_${fmt}.rawlog c_comp)
  string(REGEX MATCH "CObservationFOG 'FOG' ([0-9]+)" m "${c_in}")
  set(n_fog ${CMAKE_MATCH_1})
  set(expected "")
  # the FOG's own metadata comment (the generator's only comment) goes with the FOG: the stock form has none
  foreach(l ${c_in})
    if(NOT l MATCHES "CObservationFOG 'FOG'" AND NOT l MATCHES "CObservationComment ''")
      list(APPEND expected "${l}")
    endif()
  endforeach()
  list(APPEND expected "COUNT mrpt::obs::CObservationIMU 'FOG' ${n_fog}" "COUNT mrpt::obs::CObservationRawDAQ 'FOG_THERMISTORS' ${n_fog}")
  list(SORT expected)
  set(got ${c_comp})
  list(SORT got)
  if(NOT "${expected}" STREQUAL "${got}")
    message(FATAL_ERROR "fog-compensate ${fmt}: the format or a count changed:\nexpected ${expected}\ngot      ${got}")
  endif()
  # fog-odometry
  run("fog-odometry ${fmt}" ${ODO} -q -i ${in} --cal ${CAL} -o ${WORK}/odo_${fmt}.rawlog --truth ${WORK}/vehicle_truth.rawlog
    --compare-s 600 --json ${WORK}/odo_${fmt}.json)
  counts(${WORK}/odo_${fmt}.rawlog c_odo)
  if(NOT "${c_in}" STREQUAL "${c_odo}")
    message(FATAL_ERROR "fog-odometry ${fmt}: the format or a count changed:\nin  ${c_in}\nout ${c_odo}")
  endif()
  file(READ ${WORK}/odo_${fmt}.json j)
  string(JSON n_rewritten GET "${j}" odometry_rewritten)
  if(n_rewritten LESS 10)
    message(FATAL_ERROR "fog-odometry ${fmt}: only ${n_rewritten} odometry samples rewritten")
  endif()
  if(TARGETS)
    string(JSON fog_rms GET "${j}" fog_vs_truth heading_rms_deg)
    string(JSON wheel_rms GET "${j}" wheels_vs_truth heading_rms_deg)
    string(JSON span GET "${j}" fog_vs_truth span_s)
    if(NOT fog_rms LESS_EQUAL 0.1)
      message(FATAL_ERROR "fog-odometry ${fmt}: FOG heading RMS ${fog_rms} deg > 0.1 deg")
    endif()
    execute_process(COMMAND awk "BEGIN{exit !(${fog_rms} <= 0.05 * ${wheel_rms})}" RESULT_VARIABLE ratio_bad)
    if(ratio_bad)
      message(FATAL_ERROR "fog-odometry ${fmt}: FOG heading RMS ${fog_rms} deg > 0.05 x the wheels' ${wheel_rms} deg")
    endif()
    message(STATUS "fog-odometry ${fmt}: heading RMS over ${span} s: FOG ${fog_rms} deg, wheels ${wheel_rms} deg")
  endif()
  # fog-drift without truth
  run("fog-drift ${fmt}" ${DRIFT} -q -i ${in} --cal ${CAL} --json ${WORK}/drift_${fmt}.json)
  file(READ ${WORK}/drift_${fmt}.json d)
  string(JSON truth GET "${d}" truth)
  if(truth)
    message(FATAL_ERROR "fog-drift ${fmt}: expected the no-truth report:\n${d}")
  endif()
  if(TARGETS)  # the drive stands still for its first 120 s: GPS courses only in the longer run
    string(JSON fixes GET "${d}" gps_course fixes)
    if(fixes LESS 10)
      message(FATAL_ERROR "fog-drift ${fmt}: expected GPS courses:\n${d}")
    endif()
  endif()
endforeach()
