# fog-convert on bad inputs: non-zero exit, one-line error naming the file, and no file left
# under the requested output name (a previous output there is left intact).
# -D FOG_CONVERT=<exe> -D DATA=<tests/data/io> -D WORK=<scratch dir>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(cases
  "bad_missing_time.csv|missing required column 'time_s'"
  "bad_missing_rate.csv|missing required rate column"
  "bad_number.csv|bad_number.csv:4: column 2 (rate_z_dph): cannot parse '0.x3'"
  "bad_time_backwards.csv|goes backwards"
  "bad_time_duplicate.csv|duplicates the previous sample's time"
  "bad_cell_count.csv|2 cells, but the header"
  "bad_empty_rate.csv|empty cell"
  "empty.csv|empty file"
  "bad_no_header.csv|no header row"
  "bad_header_is_data.csv|header row missing"
  "truncated.csv.gz|truncated or corrupt gzip"
  "unknown_class.rawlog|unknown class 'mrpt_fog::CObservationFOX'"
  "cut_mid_object.rawlog|ends in the middle of this object"
  "truncated.rawlog|truncated or corrupt gzip"
  "does_not_exist.csv|does_not_exist.csv")
set(failures "")
foreach(c ${cases})
  string(REPLACE "|" ";" parts "${c}")
  list(GET parts 0 input)
  list(GET parts 1 expect)
  foreach(out out.rawlog out.csv)
    execute_process(COMMAND ${FOG_CONVERT} -i ${DATA}/${input} -o ${WORK}/${out}
      RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
    string(STRIP "${se}" se)
    string(FIND "${se}" "\n" nl)
    string(FIND "${se}" "${expect}" found)
    string(FIND "${se}" "fog-convert: error: " prefix)
    if(rc EQUAL 0)
      list(APPEND failures "${input} -> ${out}: exit status 0")
    elseif(NOT nl EQUAL -1)
      list(APPEND failures "${input} -> ${out}: error is not one line: ${se}")
    elseif(found EQUAL -1 OR NOT prefix EQUAL 0)
      list(APPEND failures "${input} -> ${out}: message lacks '${expect}': ${se}")
    endif()
    if(EXISTS ${WORK}/${out})
      list(APPEND failures "${input} -> ${out}: output file left behind")
    endif()
    message(STATUS "${input} -> ${out}: rc=${rc}: ${se}")
  endforeach()
endforeach()

# A failed conversion keeps a previous output intact, and leaves no temporary file.
file(WRITE ${WORK}/keep.csv "previous content\n")
execute_process(COMMAND ${FOG_CONVERT} -i ${DATA}/bad_number.csv -o ${WORK}/keep.csv RESULT_VARIABLE rc)
file(READ ${WORK}/keep.csv kept)
if(rc EQUAL 0 OR NOT kept STREQUAL "previous content\n")
  list(APPEND failures "previous output not kept intact (rc=${rc})")
endif()
# Usage errors: exit status 2.
execute_process(COMMAND ${FOG_CONVERT} -i ${DATA}/sample.csv RESULT_VARIABLE rc ERROR_VARIABLE se)
if(NOT rc EQUAL 2)
  list(APPEND failures "missing -o: exit status ${rc}, expected 2")
endif()
execute_process(COMMAND ${FOG_CONVERT} -i ${DATA}/sample.csv -o ${WORK}/x.txt RESULT_VARIABLE rc ERROR_VARIABLE se)
if(rc EQUAL 0 OR EXISTS ${WORK}/x.txt)
  list(APPEND failures "unknown output extension accepted")
endif()
execute_process(COMMAND ${FOG_CONVERT} -i ${DATA}/sample.csv -o ${WORK}/x.csv --to-stock RESULT_VARIABLE rc ERROR_VARIABLE se)
if(rc EQUAL 0 OR EXISTS ${WORK}/x.csv)
  list(APPEND failures "--to-stock to a CSV accepted")
endif()
execute_process(COMMAND ${FOG_CONVERT} -i ${DATA}/sample.csv -o ${WORK}/j.csv --json ${WORK}/no/such/dir/s.json
  RESULT_VARIABLE rc ERROR_VARIABLE se)
if(rc EQUAL 0 OR EXISTS ${WORK}/j.csv)
  list(APPEND failures "unwritable --json path: rc=${rc}, output left: ${se}")
endif()
file(GLOB leftovers ${WORK}/*.tmp-*)
if(leftovers)
  list(APPEND failures "temporary files left: ${leftovers}")
endif()
if(failures)
  string(REPLACE ";" "\n  " failures "${failures}")
  message(FATAL_ERROR "fog-convert bad-input checks failed:\n  ${failures}")
endif()
