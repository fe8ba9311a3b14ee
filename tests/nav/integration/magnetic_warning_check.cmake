# fog-drift with a calibration that has a magnetic section (the test drive's calibration plus a
# magnetic term, file version 3) on a drive whose log has no field column: compensated without
# the term, said on stderr once and in --json ("magnetic_field_warning"), streamed and --in-memory
# alike; the same drive with the calibration without the section has no such key.
# -D DRIFT=<fog-drift> -D DIR=<the nav_drive directory: drive.rawlog, cal.yaml>
file(READ ${DIR}/cal.yaml cal)
string(REPLACE "\nversion: 2\n" "\nversion: 3\n" cal "${cal}")
string(REPLACE "    statistics:  # of the bias compensation"
  "    magnetic:\n      dph_per_uT: 0.0003\n      dph_per_uT_std: 0.00001\n      field_range_uT: [-100, 100]\n      samples: 1000\n    statistics:  # of the bias compensation"
  cal "${cal}")
file(WRITE ${DIR}/cal_magnetic.yaml "${cal}")
foreach(mode "" "--in-memory")
  execute_process(COMMAND ${DRIFT} -q ${mode} -i ${DIR}/drive.rawlog --cal ${DIR}/cal_magnetic.yaml
    --json ${DIR}/drift_magnetic.json RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fog-drift ${mode} failed (${rc}): ${err}")
  endif()
  string(REGEX MATCHALL "warning: axis z: the calibration has a magnetic term" hits "${err}")
  list(LENGTH hits n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "fog-drift ${mode}: expected one stderr warning about the missing field, got ${n}: ${err}")
  endif()
  file(READ ${DIR}/drift_magnetic.json j)
  string(JSON w GET "${j}" magnetic_field_warning)
  if(NOT w MATCHES "^axis z: .*no field column")
    message(FATAL_ERROR "fog-drift ${mode}: --json magnetic_field_warning is '${w}'")
  endif()
endforeach()
file(READ ${DIR}/drift.json plain)
string(JSON t ERROR_VARIABLE missing GET "${plain}" magnetic_field_warning)
if(NOT missing)
  message(FATAL_ERROR "a calibration without magnetic section gave magnetic_field_warning in --json")
endif()
