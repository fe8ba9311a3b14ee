# MRPT's stock pf-localization on fog-odometry's output (docs/validation/vehicle.md):
# -D GEN=vehicle-rawlog-gen -D ODO=fog-odometry -D PF=pf-localization -D PLUGIN=libmrpt_fog.so
# -D DRIVE=datasets/drive.rawlog -D CAL=<calibration> -D MAP=<fog-localize's map.gridmap.gz>
# -D WORK=<scratch> -D PARTICLES=<n> [-D DURATION=<s>]
# 1. vehicle-rawlog-gen (MRPT's classes only) writes the drive as a vehicle rawlog in the
#    actions-observations format, its lidar simulated by MRPT on fog-localize's map at the true
#    poses (1 Hz, 360 deg, 60 m), and the truth held back (a rawlog and pf-localization's text);
# 2. fog-odometry rewrites the actions with the compensated FOG's heading and the FOG motion model;
# 3. pf-localization runs once on fog-odometry's output (compensated FOG) and once on the
#    generator's log (wheel odometry, MRPT's default motion model), with the same .ini, map,
#    initial spread and particles (the .ini's likelihood options are fog-localize's). The plugin
#    is preloaded so that MRPT's reader knows CObservationFOG (without it pf-localization stops at
#    the first one);
# 4. position RMS of pf-localization's own GT_error.txt (per step: the particles' weighted mean
#    distance to the truth): the compensated run must be lower than the wheels'.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se WORKING_DIRECTORY ${WORK})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${so}\n${se}")
  endif()
  set(out "${so}" PARENT_SCOPE)
endfunction()

set(dur "")
if(DURATION)
  set(dur --duration-s ${DURATION})
endif()
run("vehicle-rawlog-gen" ${GEN} ${DRIVE} ${WORK}/vehicle --map ${MAP} ${dur})
message(STATUS "${out}")
run("fog-odometry" ${ODO} -q -i ${WORK}/vehicle_act.rawlog --cal ${CAL} -o ${WORK}/fog_act.rawlog
  --truth ${WORK}/vehicle_truth.rawlog --json ${WORK}/fog_odometry.json)
file(READ ${WORK}/fog_odometry.json j)
string(JSON n_rewritten GET "${j}" odometry_rewritten)
if(n_rewritten LESS 100)
  message(FATAL_ERROR "fog-odometry: only ${n_rewritten} actions rewritten")
endif()

# The filter starts around the true pose at the truth's first time, as after a GNSS fix.
file(STRINGS ${WORK}/vehicle_truth.txt first LIMIT_COUNT 1)
separate_arguments(first UNIX_COMMAND "${first}")
list(GET first 1 x0)
list(GET first 2 y0)
list(GET first 3 yaw0)
foreach(run_name compensated wheels)
  if(run_name STREQUAL "compensated")
    set(rawlog fog_act.rawlog)
  else()
    set(rawlog vehicle_act.rawlog)
  endif()
  execute_process(COMMAND awk "BEGIN{printf \"init_PDF_min_x=%.6f\\ninit_PDF_max_x=%.6f\\ninit_PDF_min_y=%.6f\\ninit_PDF_max_y=%.6f\\ninit_PDF_min_yaw_deg=%.6f\\ninit_PDF_max_yaw_deg=%.6f\\n\", ${x0}-2, ${x0}+2, ${y0}-2, ${y0}+2, ${yaw0}*180/3.14159265358979-0.5, ${yaw0}*180/3.14159265358979+0.5}"
    OUTPUT_VARIABLE init)
  file(WRITE ${WORK}/pf_${run_name}.ini "# pf-localization on the vehicle rawlog (${run_name} odometry)
[LocalizationExperiment]
map_file=${MAP}
rawlog_file=${rawlog}
ground_truth_path_file=vehicle_truth.txt
logOutput_dir=LOG_${run_name}
particles_count=${PARTICLES}
experimentRepetitions=1
SAVE_STATS_ONLY=true
SHOW_PROGRESS_3D_REAL_TIME=false
3DSceneFrequency=-1
init_PDF_mode=1
${init}
[PF_options]
PF_algorithm=pfStandardProposal
resamplingMethod=prSystematic
adaptiveSampleSize=0
BETA=0.5
powFactor=1
sampleSize=1

[MetricMap]
occupancyGrid_count=1

[MetricMap_occupancyGrid_00_creationOpts]
resolution=2

[MetricMap_occupancyGrid_00_likelihoodOpts]
likelihoodMethod=lmLikelihoodField_Thrun
LF_stdHit=1
LF_zHit=0.95
LF_zRandom=0.05
LF_maxRange=60
LF_decimation=1
LF_maxCorrsDistance=3
enableLikelihoodCache=true
")
  run("pf-localization ${run_name}" ${CMAKE_COMMAND} -E env DISPLAY= LD_PRELOAD=${PLUGIN} ${PF} pf_${run_name}.ini)
  file(GLOB gt_error ${WORK}/LOG_${run_name}_*/GT_error.txt)
  if(NOT gt_error)
    message(FATAL_ERROR "pf-localization ${run_name}: no GT_error.txt")
  endif()
  execute_process(COMMAND awk "{s += $1 * $1; n++; if ($1 > m) m = $1} END {printf \"%d %.3f %.3f\", n, sqrt(s / n), m}" ${gt_error}
    OUTPUT_VARIABLE stats)
  separate_arguments(stats UNIX_COMMAND "${stats}")
  list(GET stats 0 n_${run_name})
  list(GET stats 1 rms_${run_name})
  list(GET stats 2 max_${run_name})
  message(STATUS "pf-localization ${run_name}: ${n_${run_name}} steps compared with the truth, position RMS ${rms_${run_name}} m, max ${max_${run_name}} m")
endforeach()

# Both runs must have compared most of their steps (the odometry steps of the log).
string(JSON n_steps GET "${j}" odometry_rewritten)
foreach(run_name compensated wheels)
  math(EXPR need "${n_steps} * 9 / 10")
  if(n_${run_name} LESS need)
    message(FATAL_ERROR "pf-localization ${run_name}: only ${n_${run_name}} of ${n_steps} steps compared with the truth")
  endif()
endforeach()
execute_process(COMMAND awk "BEGIN{exit !(${rms_compensated} < ${rms_wheels})}" RESULT_VARIABLE worse)
if(worse)
  message(FATAL_ERROR "pf-localization: the compensated FOG's position RMS ${rms_compensated} m is not below the wheels' ${rms_wheels} m")
endif()
file(WRITE ${WORK}/summary.txt "compensated ${n_compensated} ${rms_compensated} ${max_compensated}\nwheels ${n_wheels} ${rms_wheels} ${max_wheels}\n")
