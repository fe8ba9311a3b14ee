# fog_even_unity_batches(<target>): in a unity build (scripts/build-env.sh), splits the target's
# sources into batches of equal size no larger than CMAKE_UNITY_BUILD_BATCH_SIZE: 17 sources at
# 16 per batch would make one unit of 16 heavy files, alone on the critical path, and one of 1.
function(fog_even_unity_batches target)
  if(NOT CMAKE_UNITY_BUILD OR NOT CMAKE_UNITY_BUILD_BATCH_SIZE GREATER 0)
    return()
  endif()
  get_target_property(srcs ${target} SOURCES)
  list(FILTER srcs INCLUDE REGEX "\\.cpp$")
  list(LENGTH srcs n)
  if(n GREATER CMAKE_UNITY_BUILD_BATCH_SIZE)
    math(EXPR nbatch "(${n} + ${CMAKE_UNITY_BUILD_BATCH_SIZE} - 1) / ${CMAKE_UNITY_BUILD_BATCH_SIZE}")
    math(EXPR per "(${n} + ${nbatch} - 1) / ${nbatch}")
    set_target_properties(${target} PROPERTIES UNITY_BUILD_BATCH_SIZE ${per})
  endif()
endfunction()
