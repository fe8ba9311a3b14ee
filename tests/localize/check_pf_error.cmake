# MRPT's pf-localization on fog-localize's compensated rawlog (-D GT_ERROR=<its GT_error.txt>,
# one weighted particle-to-truth distance per step): it must have compared most of the 4230
# steps with the ground truth and localized: median error < 1 m (more than half the steps).
file(STRINGS ${GT_ERROR} lines)
list(LENGTH lines n)
if(n LESS 4000)
  message(FATAL_ERROR "pf-localization compared only ${n} steps with the ground truth")
endif()
set(below 0)
foreach(v ${lines})
  if(v LESS 1.0)
    math(EXPR below "${below} + 1")
  endif()
endforeach()
math(EXPR half "${n} / 2")
message(STATUS "pf-localization: ${n} steps, ${below} with error < 1 m")
if(NOT below GREATER half)
  message(FATAL_ERROR "pf-localization: median error >= 1 m (${below} of ${n} steps below 1 m)")
endif()
