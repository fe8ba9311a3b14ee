# Peak memory of fog-odometry and fog-compensate on a long vehicle log (docs/validation/vehicle.md):
# -D GEN=vehicle-rawlog-gen -D ODO=fog-odometry -D COMP=fog-compensate -D TIME=/usr/bin/time
# -D DRIVE=datasets/drive.rawlog -D CAL=<calibration> -D WORK=<scratch> -D REPEAT=<n>
# -D MIN_SAMPLES=<FOG samples the log must hold> -D LIMIT_KB=<peak resident set size allowed [kB]>
# 1. vehicle-rawlog-gen (MRPT's classes only) drives the bundled drive REPEAT times in a row with a
#    181-ray 2-D scan every 0.1 s (observations-only format);
# 2. /usr/bin/time -v runs each program on it; its "Maximum resident set size" must stay at or
#    below LIMIT_KB. The logs (gigabytes) are removed at the end, also on failure.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
  if(NOT rc EQUAL 0)
    file(REMOVE_RECURSE ${WORK})
    message(FATAL_ERROR "${what} failed (${rc}):\n${so}\n${se}")
  endif()
  set(out "${so}" PARENT_SCOPE)
  set(err "${se}" PARENT_SCOPE)
endfunction()

run("vehicle-rawlog-gen" ${GEN} ${DRIVE} ${WORK}/mem --repeat ${REPEAT} --scan-hz 10 --obs-only)
message(STATUS "${out}")
string(REGEX MATCH "([0-9]+) FOG samples, ([0-9]+) scans" m "${out}")
set(n_fog ${CMAKE_MATCH_1})
if(NOT n_fog OR n_fog LESS MIN_SAMPLES)
  file(REMOVE_RECURSE ${WORK})
  message(FATAL_ERROR "the log holds ${n_fog} FOG samples, fewer than ${MIN_SAMPLES}")
endif()

set(failed "")
foreach(prog odometry compensate)
  if(prog STREQUAL "odometry")
    set(cmd ${ODO} -q -i ${WORK}/mem_obs.rawlog --cal ${CAL} -o ${WORK}/out_odometry.rawlog)
  else()
    set(cmd ${COMP} -q -i ${WORK}/mem_obs.rawlog --cal ${CAL} -o ${WORK}/out_compensate.rawlog)
  endif()
  run("fog-${prog}" ${TIME} -v ${cmd})
  string(REGEX MATCH "Maximum resident set size \\(kbytes\\): ([0-9]+)" m "${err}")
  set(rss_kb ${CMAKE_MATCH_1})
  string(REGEX MATCH "Elapsed \\(wall clock\\) time \\(h:mm:ss or m:ss\\): ([0-9:.]+)" m "${err}")
  message(STATUS "fog-${prog}: ${n_fog} FOG samples: peak resident set size ${rss_kb} kB (limit ${LIMIT_KB} kB), wall time ${CMAKE_MATCH_1}")
  if(NOT rss_kb)
    set(failed "${failed}fog-${prog}: no peak memory in /usr/bin/time's output\n")
  elseif(rss_kb GREATER LIMIT_KB)
    set(failed "${failed}fog-${prog}: peak resident set size ${rss_kb} kB > ${LIMIT_KB} kB\n")
  endif()
  file(REMOVE ${WORK}/out_${prog}.rawlog)
endforeach()
file(REMOVE_RECURSE ${WORK})
if(failed)
  message(FATAL_ERROR "${failed}")
endif()
