# fog-discrepancy --write-cal end to end on the lumped-coil second generator (tests/support):
# two runs with a hidden 5th-order temperature term (effect/noise 3), base M2:Ca@3/1; the
# calibration written must carry the added terms, fog-compensate must run it, the JSON must show
# the gap through the compensator shrinking on the confirmation run, and --plots creates a
# directory that did not exist.
# -D GEN=<lumped-coil-gen> -D DISC=<fog-discrepancy> -D COMP=<fog-compensate> -D WORK=<dir>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(s 1 2)
  execute_process(COMMAND ${GEN} -o ${WORK}/run${s}.csv --seed ${s} --effect temp_poly_order=3 RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "lumped-coil-gen failed")
  endif()
endforeach()
execute_process(COMMAND ${DISC} --measured ${WORK}/run1.csv --measured ${WORK}/run2.csv --model M2:Ca@3/1
  --write-cal ${WORK}/aug.yaml --json ${WORK}/gap.json --plots ${WORK}/new/plots
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-discrepancy failed (${rc}): ${err}")
endif()
if(NOT EXISTS ${WORK}/new/plots/discrepancy_residual.png)
  message(FATAL_ERROR "--plots did not create the directory / plot")
endif()
file(READ ${WORK}/gap.json j)
string(JSON nadded LENGTH "${j}" write_cal added_terms)
string(JSON before GET "${j}" write_cal confirm_through_compensator before rms_dph)
string(JSON after GET "${j}" write_cal confirm_through_compensator after rms_dph)
if(nadded LESS 1)
  message(FATAL_ERROR "--write-cal added no term although temp_poly_order was hidden")
endif()
if(NOT after LESS before)
  message(FATAL_ERROR "gap through the compensator did not shrink: ${before} -> ${after}")
endif()
execute_process(COMMAND ${COMP} -i ${WORK}/run2.csv --cal ${WORK}/aug.yaml -o ${WORK}/comp.csv RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-compensate refused the written calibration: ${err}")
endif()
message(STATUS "write-cal: ${nadded} terms added; confirmation run through the compensator ${before} -> ${after} deg/h")
