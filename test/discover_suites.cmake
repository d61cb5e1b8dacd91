# Registers one CTest test per GoogleTest suite of TEST_EXECUTABLE, written
# to CTEST_FILE (which the test directory includes): run after each build of
# the executable, as gtest_discover_tests() does per test.
#
# One process per suite rather than per test: the sanitized suite takes
# 0.2 s to start, which over some 600 tests was a third of the suite's time.
# A suite's COST is its number of tests, so that CTest starts the long ones
# first on a first run, which has no measured times. A skipped test (such as
# one that needs OpenSubdiv where it is not installed) passes with its suite;
# the suite's output says SKIPPED.
execute_process(COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE status TIMEOUT 120)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${status}):\n${listing}")
endif()
string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(suites)
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ #][^ ]*)\\.")
    set(suite "${CMAKE_MATCH_1}")
    list(APPEND suites "${suite}")
    set(count_${suite} 0)
  elseif(line MATCHES "^  [^ ]" AND DEFINED suite)
    math(EXPR count_${suite} "${count_${suite}} + 1")
  endif()
endforeach()
set(script "")
foreach(suite IN LISTS suites)
  string(APPEND script
    "add_test([==[${suite}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${suite}.*]==])\n"
    "set_tests_properties([==[${suite}]==] PROPERTIES COST ${count_${suite}})\n")
endforeach()
file(WRITE "${CTEST_FILE}" "${script}")
