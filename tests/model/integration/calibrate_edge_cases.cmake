# fog-calibrate's reports on runs that give a part of the fit nothing (tests/data/model/
# make_calibrate_edge_cases.py makes the logs, with known parameters):
# - a held-out figure without held-out samples (one of two -i runs is gyro-off throughout)
#   prints "n/a" and the reason, never a column of zeros, and says why in --json;
# - a run that is never powered holds no turn-on, whatever its metadata power_on_time_s says;
# - the same run as -i and --warmup-run: the warm-up term is fitted and nothing says it was not
#   (default exclusion, and --turn-on-exclusion 0);
# - a magnetic term from a single non-zero field sample (its 95 % interval spans zero) is not
#   written, and the reason is printed and in --json.
# -D BIN=<dir of the programs> -D DATA=<tests/data/model> -D WORK=<scratch dir>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run name)
  execute_process(COMMAND ${BIN}/${name} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE se OUTPUT_VARIABLE so)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} ${ARGN} failed (${rc}): ${se}\n${so}")
  endif()
  set(last_stdout "${so}" PARENT_SCOPE)
endfunction()
function(expect_in text what)
  string(FIND "${text}" "${what}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "expected '${what}' in:\n${text}")
  endif()
endfunction()
function(expect_not_in text what)
  string(FIND "${text}" "${what}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "did not expect '${what}' in:\n${text}")
  endif()
endfunction()
set(model --model M2:Ti1@1/1 -q)

# 1. a gyro-off run as second -i run: no held-out sample
run(fog-calibrate -i ${DATA}/warmup_small.csv -i ${DATA}/all_off.csv ${model} -o ${WORK}/off.yaml --json ${WORK}/off.json)
string(REGEX MATCH "compensated stability +[^\n]*" row "${last_stdout}")
if(NOT row MATCHES "n/a")
  message(FATAL_ERROR "held-out stability without held-out samples is not n/a: '${row}'\n${last_stdout}")
endif()
expect_in("${last_stdout}" "n/a (held-out")
expect_in("${last_stdout}" "all_off.csv is gyro-off throughout")
file(READ ${WORK}/off.json j)
string(JSON why GET "${j}" held_out not_available)
if(NOT why MATCHES "gyro-off throughout")
  message(FATAL_ERROR "off.json: held_out.not_available = '${why}'")
endif()
# 2. ... and that run holds no turn-on (never powered), although its metadata names one
expect_not_in("${last_stdout}" "-i ${DATA}/all_off.csv holds a turn-on")
expect_not_in("${last_stdout}" "turn-on in -i ${DATA}/all_off.csv")

# 3. the same run as -i and --warmup-run
foreach(excl default 0)
  set(extra "")
  if(NOT excl STREQUAL "default")
    set(extra --turn-on-exclusion ${excl})
  endif()
  run(fog-calibrate -i ${DATA}/warmup_small.csv --warmup-run ${DATA}/warmup_small.csv ${model} ${extra}
      -o ${WORK}/same_${excl}.yaml --json ${WORK}/same_${excl}.json)
  expect_in("${last_stdout}" "  warm-up: ")
  expect_not_in("${last_stdout}" "no warm-up term was fitted")
  expect_in("${last_stdout}" "is both an -i run and a --warmup-run")
  file(READ ${WORK}/same_${excl}.json j)
  string(JSON tau GET "${j}" warmup tau_s)
  # the generator's warm-up: 2.0 deg/h, 600 s
  if(NOT tau GREATER 300 OR NOT tau LESS 1200)
    message(FATAL_ERROR "same run as -i and --warmup-run (exclusion ${excl}): warm-up tau ${tau} s, generated 600 s")
  endif()
endforeach()

# 4. a magnetic term from one non-zero field sample is not written
run(fog-calibrate -i ${DATA}/field_one_sample.csv ${model} -o ${WORK}/field.yaml --json ${WORK}/field.json)
file(READ ${WORK}/field.yaml y)
if(y MATCHES "magnetic:")
  message(FATAL_ERROR "a magnetic section was written from one non-zero field sample:\n${y}")
endif()
expect_in("${last_stdout}" "magnetic: not fitted: ")
file(READ ${WORK}/field.json j)
string(JSON why GET "${j}" magnetic not_fitted)
if(why STREQUAL "")
  message(FATAL_ERROR "field.json: no reason for the magnetic term left out")
endif()
message(STATUS "fog-calibrate edge cases: n/a held out, no turn-on when never powered, one warm-up story, no unresolved magnetic term")
