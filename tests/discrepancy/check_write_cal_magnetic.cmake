# fog-discrepancy --write-cal with a named magnetic effect, end to end on the lumped-coil second
# generator (tests/support): two 5 s runs with a hidden field sensitivity (effect/noise 3), base
# M2:Ca@3/1. The calibration written must be version 3 with a magnetic section, the JSON must
# show the gap through the compensator shrinking on the confirmation run, fog-compensate must run
# it with the field (no warning, field_unknown_samples 0) and, on a log without a field column,
# warn on stderr and say so in --json. fog-calibrate --magnetic auto (the default) on the same
# first run, with the same samples in the bias fit (--turn-on-exclusion 0), writes the same
# coefficient (the same calibration, the same fit); --magnetic off writes a version-2 file
# without the section.
# -D GEN=<lumped-coil-gen> -D DISC=<fog-discrepancy> -D COMP=<fog-compensate> -D CAL=<fog-calibrate> -D WORK=<dir>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(s 1 2)
  execute_process(COMMAND ${GEN} -o ${WORK}/run${s}.csv --seed ${s} --dt 5 --effect magnetic=3 RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "lumped-coil-gen failed")
  endif()
endforeach()
execute_process(COMMAND ${GEN} -o ${WORK}/nofield.csv --seed 3 --dt 5 --profile cooling RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "lumped-coil-gen failed (cooling)")
endif()
execute_process(COMMAND ${DISC} --measured ${WORK}/run1.csv --measured ${WORK}/run2.csv --model M2:Ca@3/1
  --write-cal ${WORK}/aug.yaml --json ${WORK}/gap.json
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-discrepancy failed (${rc}): ${err}")
endif()
file(READ ${WORK}/aug.yaml cal)
if(NOT cal MATCHES "\nversion: 3\n" OR NOT cal MATCHES "\n    magnetic:")
  message(FATAL_ERROR "the calibration written is not version 3 with a magnetic section")
endif()
file(READ ${WORK}/gap.json j)
string(JSON k GET "${j}" write_cal magnetic dph_per_uT)
string(JSON before GET "${j}" write_cal confirm_through_compensator before rms_dph)
string(JSON after GET "${j}" write_cal confirm_through_compensator after rms_dph)
if(NOT after LESS before)
  message(FATAL_ERROR "gap through the compensator did not shrink: ${before} -> ${after}")
endif()
# with the field: no warning, every sample had it
execute_process(COMMAND ${COMP} -i ${WORK}/run2.csv --cal ${WORK}/aug.yaml -o ${WORK}/comp.csv --json ${WORK}/comp.json
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-compensate refused the written calibration: ${err}")
endif()
if(err MATCHES "warning")
  message(FATAL_ERROR "fog-compensate warned although the log has the field: ${err}")
endif()
file(READ ${WORK}/comp.json cj)
string(JSON unknown GET "${cj}" magnetic field_unknown_samples)
if(NOT unknown EQUAL 0)
  message(FATAL_ERROR "field unknown on ${unknown} samples of a log with a field column")
endif()
# without a field column: compensated without the term, said on stderr and in --json
execute_process(COMMAND ${COMP} -i ${WORK}/nofield.csv --cal ${WORK}/aug.yaml -o ${WORK}/comp2.csv --json ${WORK}/comp2.json
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-compensate failed on a log without field: ${err}")
endif()
if(NOT err MATCHES "magnetic term .* but the log has no field column")
  message(FATAL_ERROR "no stderr warning for a log without field column: '${err}'")
endif()
file(READ ${WORK}/comp2.json cj2)
string(JSON has_col GET "${cj2}" magnetic field_column)
string(JSON warning GET "${cj2}" magnetic warning)
if(has_col OR warning STREQUAL "")
  message(FATAL_ERROR "--json does not say the field was missing: ${cj2}")
endif()
# fog-calibrate fits the section itself when the runs have field segments
# (the same data as fog-discrepancy's fit: its runs have power cycles, whose first hour
# fog-calibrate keeps out of the bias fit by default and fog-discrepancy does not)
execute_process(COMMAND ${CAL} -i ${WORK}/run1.csv --model M2:Ca@3/1 --turn-on-exclusion 0 -o ${WORK}/cal.yaml --json ${WORK}/cal.json -q
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-calibrate failed (${rc}): ${err}")
endif()
if(NOT out MATCHES "magnetic: [0-9.e+-]+ \\+- ")
  message(FATAL_ERROR "fog-calibrate printed no magnetic sensitivity: ${out}")
endif()
file(READ ${WORK}/cal.json fj)
string(JSON k_cal GET "${fj}" magnetic dph_per_uT)
if(NOT k_cal STREQUAL k)
  message(FATAL_ERROR "fog-calibrate's coefficient ${k_cal} differs from --write-cal's ${k}")
endif()
execute_process(COMMAND ${CAL} -i ${WORK}/run1.csv --model M2:Ca@3/1 -o ${WORK}/cal_off.yaml --magnetic off -q
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
file(READ ${WORK}/cal_off.yaml cal_off)
if(NOT rc EQUAL 0 OR NOT cal_off MATCHES "\nversion: 2\n" OR cal_off MATCHES "magnetic:")
  message(FATAL_ERROR "fog-calibrate --magnetic off: not a version-2 file without the section (${rc}: ${err})")
endif()
message(STATUS "write-cal magnetic: ${k} deg/h per uT; confirmation run through the compensator ${before} -> ${after} deg/h")
