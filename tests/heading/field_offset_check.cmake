# fog-odometry applies a calibration's field offset (fog-refine's field_offset section) to the
# compensated gyro: the same drive with CAL and with CAL plus a 0.5 deg/h offset (no aging, no
# standstill updates) must end with headings that differ by -0.5 deg/h x the compared span, in
# closed form (a constant rate offset through the vertical strapdown), to 1e-6 deg.
# -D ODO=fog-odometry -D DRIVE=datasets/drive.rawlog -D CAL=<calibration without field_offset> -D WORK=<scratch dir>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${CAL} cal_text)
if(cal_text MATCHES "\nfield_offset:")
  message(FATAL_ERROR "${CAL} already has a field_offset section")
endif()
file(WRITE ${WORK}/cal_off.yaml "${cal_text}\nfield_offset:\n  offset_dph: 0.5\n  sigma_dph: 0.01\n  aging_dph_per_day: 0\n  aging_sigma_dph_per_day: 0\n  reference_unix_s: 1700000000\n  revision: 1\n")
foreach(c base off)
  if(c STREQUAL "base")
    set(cal ${CAL})
  else()
    set(cal ${WORK}/cal_off.yaml)
  endif()
  execute_process(COMMAND ${ODO} -q -i ${DRIVE} --cal ${cal} --no-field-refinement -o ${WORK}/${c}.rawlog
    --json ${WORK}/${c}.json RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE se)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fog-odometry (${c}) failed (${rc}): ${se}")
  endif()
  file(READ ${WORK}/${c}.json j)
  string(JSON final_${c} GET "${j}" fog_vs_truth heading_final_deg)
  string(JSON span_${c} GET "${j}" fog_vs_truth span_s)
endforeach()
execute_process(COMMAND awk "BEGIN{d = ${final_off} - (${final_base}); e = -0.5 * ${span_base} / 3600; printf \"%.9f %.9f\", d, e; exit !(d - e < 1e-6 && e - d < 1e-6)}"
  RESULT_VARIABLE bad OUTPUT_VARIABLE de)
if(bad)
  message(FATAL_ERROR "final heading difference / expected [deg]: ${de} (span ${span_base} s)")
endif()
message(STATUS "field offset 0.5 deg/h over ${span_base} s: final heading difference / expected [deg]: ${de}")
file(REMOVE_RECURSE ${WORK})
