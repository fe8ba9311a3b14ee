# Shared by the scripts that install the package and build against it (tests/package/
# install_and_example.cmake, tests/io/integration/find_package_consumer.cmake).

# step(<what> <command...>): runs the command, fails the test with its output when it fails;
# its standard output is left in `out`.
function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${so}\n${se}")
  endif()
  message(STATUS "${what}: ok")
  set(out "${so}" PARENT_SCOPE)
endfunction()

# expect_libraries_from(<program> <prefix> <lib...>): `ldd program` resolves each lib (e.g.
# libmrpt_fog) to a file under prefix, not to the build tree or the system.
function(expect_libraries_from program prefix)
  step("ldd ${program}" ldd ${program})
  foreach(lib ${ARGN})
    string(REGEX MATCH "${lib}\\.so[^\n]*" libline "${out}")
    string(FIND "${libline}" "${prefix}/" in_prefix)
    if(in_prefix EQUAL -1)
      message(FATAL_ERROR "${program} resolves ${lib} from '${libline}', not from ${prefix}")
    endif()
  endforeach()
endfunction()
