# Run by ctest before the tests (a TEST_INCLUDE_FILES script written by fog_add_gtests in
# tests/CMakeLists.txt when MRPT_FOG_TESTS_PER_SUITE is ON): registers one ctest test per
# GoogleTest test suite of a test program, running that suite's cases in one process
# (--gtest_filter=<Suite>.*). Every case still runs; a failing case fails its suite's test and
# its output names the case. Input variables: FOG_GTEST_EXE, FOG_GTEST_LABELS, FOG_GTEST_TARGET.
if(NOT EXISTS "${FOG_GTEST_EXE}")
  add_test("${FOG_GTEST_TARGET}_NOT_BUILT" "${FOG_GTEST_EXE}")
  return()
endif()
execute_process(COMMAND "${FOG_GTEST_EXE}" --gtest_list_tests
  OUTPUT_VARIABLE listing RESULT_VARIABLE rc TIMEOUT 60)
if(NOT rc EQUAL 0)
  add_test("${FOG_GTEST_TARGET}_LISTING_FAILED" "${FOG_GTEST_EXE}" --gtest_list_tests)
  return()
endif()
# A suite line is "<Suite>." or "<Suite>.  # TypeParam = ..." at column 0; case lines are indented.
string(REPLACE ";" "," listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    set(suite "${CMAKE_MATCH_1}")
    if(NOT suite MATCHES "^DISABLED_")
      add_test("${suite}" "${FOG_GTEST_EXE}" "--gtest_filter=${suite}.*")
      set_tests_properties("${suite}" PROPERTIES LABELS "${FOG_GTEST_LABELS}")
    endif()
  endif()
endforeach()
