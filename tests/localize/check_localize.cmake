# Checks fog-localize's JSON (-D JSON=) and output folder (-D DIR=) on the bundled drive:
# - every gyro has an open-stretch position RMS (the --json contract);
# - the map localizes: urban RMS < 1 m for every gyro, and no run diverged;
# - the open fields are observation-poor: their RMS exceeds the urban one for every gyro;
# - the tunnel fixes heading and lateral position: its RMS is below the open fields' RMS;
# - the files pf-localization needs exist;
# - the calibration is named: with the bundled rate-table run (-D RATETABLE=) present, the
#   default fit models the scale factor; without it, the JSON says bias only.
file(READ ${JSON} j)
string(JSON cal_source GET "${j}" calibration source)
string(JSON cal_sf TYPE "${j}" calibration scale_factor)
message(STATUS "calibration: ${cal_source}, scale_factor ${cal_sf}")
if(EXISTS "${RATETABLE}")
  if(NOT cal_source STREQUAL "fitted_bias_and_scale_factor" OR NOT cal_sf STREQUAL "OBJECT")
    message(FATAL_ERROR "with ${RATETABLE} present the default calibration must fit the scale factor (got ${cal_source}, ${cal_sf})")
  endif()
elseif(NOT cal_source STREQUAL "fitted_bias_only" OR NOT cal_sf STREQUAL "NULL")
  message(FATAL_ERROR "without a rate-table run the calibration must say bias only (got ${cal_source}, ${cal_sf})")
endif()
foreach(g raw compensated ideal)
  string(JSON open GET "${j}" position_rms_m ${g})
  string(JSON urban GET "${j}" position_rms_m_by_kind ${g} urban)
  string(JSON tunnel GET "${j}" position_rms_m_by_kind ${g} tunnel)
  string(JSON div GET "${j}" diverged_runs ${g})
  message(STATUS "${g}: open ${open} m, tunnel ${tunnel} m, urban ${urban} m, diverged ${div}")
  if(NOT urban LESS 1.0)
    message(FATAL_ERROR "${g}: urban position RMS ${urban} m (the map should localize to < 1 m)")
  endif()
  if(NOT div EQUAL 0)
    message(FATAL_ERROR "${g}: ${div} run(s) diverged")
  endif()
  if(NOT open GREATER urban)
    message(FATAL_ERROR "${g}: open-field RMS ${open} m not above the urban ${urban} m")
  endif()
  if(NOT tunnel LESS open)
    message(FATAL_ERROR "${g}: tunnel RMS ${tunnel} m not below the open-field ${open} m")
  endif()
endforeach()
# Heading budget of the open stretches: an entry per open stretch and gyro; the ideal gyro (no
# thermal error, only noise: its whole-drive heading error is ~0.001 deg in fog-drift) drifts
# < 0.005 deg over each field.
foreach(g raw compensated ideal)
  string(JSON n LENGTH "${j}" heading_budget ${g})
  if(NOT n EQUAL 3)
    message(FATAL_ERROR "${g}: ${n} heading_budget entries, expected one per open stretch (3)")
  endif()
endforeach()
foreach(i 0 1 2)
  string(JSON d GET "${j}" heading_budget ideal ${i} gyro_drift_deg)
  string(REGEX REPLACE "^-" "" d "${d}")
  if(NOT d LESS 0.005)
    message(FATAL_ERROR "ideal gyro drifts ${d} deg over open stretch ${i} (expected < 0.005)")
  endif()
endforeach()
foreach(f map.gridmap.gz map.png errors.png ground_truth.txt localize_compensated.rawlog pf-localization_compensated.ini localize.json)
  if(NOT EXISTS ${DIR}/${f})
    message(FATAL_ERROR "fog-localize did not write ${DIR}/${f}")
  endif()
endforeach()
