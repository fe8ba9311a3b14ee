# fog-localize on a drive with the gyro off for 5 min (tests/localize/cabin_off.yaml: off from
# 1830 to 2130 s by the profile's own times; fog-sim at 2 Hz, 1 filter seed, 100 particles).
# Before: refused ("gyro rate is not finite ... while the gyro is off"). Now (docs/guide/localization.md,
# "Gyro off"): one stretch of 300-301 s reported; every step that touches it moves the particles
# on the wheel odometry alone: scans every 1 s at t0 + 0.5 s, so the steps into the scans
# 1830.5 .. 2130.5 s, 301 of them; with the default recovery (a re-fix at the turn-on) no gyro's
# filter diverges and the urban and tunnel errors against the truth stay below 1 m (with
# --gyro-off-recovery none the stretch's open-field part loses the filter: docs/guide/localization.md).
# -D SIM=fog-sim -D LOC=fog-localize -D CABIN=cabin_off.yaml -D WORK=<scratch dir>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${SIM} -p drive --cabin ${CABIN} --rate-hz 2 -o ${WORK}/off.rawlog
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE se)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-sim failed: ${se}")
endif()
execute_process(COMMAND ${LOC} --drive ${WORK}/off.rawlog --seeds 1 --particles 100 --out ${WORK}/loc
  --json ${WORK}/loc.json RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fog-localize refused the gyro-off drive (${rc}): ${se}")
endif()
string(FIND "${so}" "gyro off 300.5 s in 1 stretch(es): heading not observable from the gyro there" at)
if(at EQUAL -1)
  message(FATAL_ERROR "no gyro-off line in the text:\n${so}")
endif()
file(READ ${WORK}/loc.json j)
string(JSON n LENGTH "${j}" gyro_off stretches)
string(JSON d GET "${j}" gyro_off stretches 0 duration_s)
if(NOT n EQUAL 1 OR d LESS 300 OR d GREATER 301)
  message(FATAL_ERROR "gyro_off: ${n} stretches, the first ${d} s; expected 1 of 300-301 s")
endif()
foreach(g raw compensated ideal)
  string(JSON steps GET "${j}" gyro_off wheel_only ${g} steps)
  string(JSON fixes GET "${j}" gyro_off wheel_only ${g} refixes)
  string(JSON div GET "${j}" diverged_runs ${g})
  string(JSON urban GET "${j}" position_rms_m_by_kind ${g} urban)
  string(JSON tunnel GET "${j}" position_rms_m_by_kind ${g} tunnel)
  if(NOT steps EQUAL 301 OR NOT fixes EQUAL 1 OR NOT div EQUAL 0)
    message(FATAL_ERROR "${g}: ${steps} wheel-only steps (expected 301), ${fixes} re-fixes (1), diverged ${div} (0)")
  endif()
  if(urban GREATER_EQUAL 1 OR tunnel GREATER_EQUAL 1)
    message(FATAL_ERROR "${g}: urban ${urban} m, tunnel ${tunnel} m RMS against the truth (expected < 1 m)")
  endif()
endforeach()
message(STATUS "fog-localize navigated the gyro-off drive: wheel-only steps across the stretch, re-fixed at the turn-on")
