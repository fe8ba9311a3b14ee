# Precompiled headers for clean builds (CI): the standard, Eigen, MRPT and GoogleTest headers
# every translation unit parses again take ~40 % of a test file's compile time (4.5 s of
# 7.9-21.5 s in Release; docs/validation/ci-time.md). With MRPT_FOG_PCH=ON each group below
# precompiles them once (in its first target) and the group's other targets reuse that header.
#
# Off by default: ccache does not cache compilations that use a precompiled header unless its
# sloppiness settings allow it, so incremental developer builds with ccache are faster without.
# scripts/run-tests.sh and scripts/run-sanitizers.sh (the CI) switch it on.
#
# A group's headers must be reachable from every member's include path (GCC falls back to the
# plain header when a precompiled one does not match a target's flags, -Winvalid-pch says so).
option(MRPT_FOG_PCH "Precompile the heavy standard/Eigen/MRPT/GoogleTest headers" OFF)

set(FOG_PCH_STD <algorithm> <cmath> <cstdio> <cstring> <filesystem> <fstream> <functional>
  <limits> <map> <memory> <optional> <random> <sstream> <stdexcept> <string> <vector>)
set(FOG_PCH_HEADERS_lib ${FOG_PCH_STD} <Eigen/Dense> <mrpt/serialization/CArchive.h>
  <mrpt/obs/CObservation.h>)
set(FOG_PCH_HEADERS_app ${FOG_PCH_HEADERS_lib} <mrpt/3rdparty/tclap/CmdLine.h>)
set(FOG_PCH_HEADERS_test ${FOG_PCH_HEADERS_lib} <gtest/gtest.h>)

# fog_precompile(<group> <target>...): lib, app or test. The first target of a group (over the
# whole configure) builds the precompiled header, the others reuse it.
function(fog_precompile group)
  if(NOT MRPT_FOG_PCH)
    return()
  endif()
  foreach(target ${ARGN})
    if(NOT TARGET ${target})
      continue()
    endif()
    get_property(owner GLOBAL PROPERTY FOG_PCH_OWNER_${group})
    if(owner)
      target_precompile_headers(${target} REUSE_FROM ${owner})
    else()
      target_precompile_headers(${target} PRIVATE ${FOG_PCH_HEADERS_${group}})
      target_compile_options(${target} PRIVATE -Winvalid-pch)
      set_property(GLOBAL PROPERTY FOG_PCH_OWNER_${group} ${target})
    endif()
  endforeach()
endfunction()
