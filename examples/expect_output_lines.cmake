# cmake -DPROGRAM=<tool> -DARGS=<a;b;...> -DOUT=<file> [-DPRESENT=<line;line;...>]
#       [-DABSENT=<line;line;...>] [-DCOUNT_REGEX=<regex> (-DCOUNT=<n> | -DMIN_COUNT=<n>)]
#       -P expect_output_lines.cmake
#
# Runs PROGRAM ARGS (a tool that writes OUT) and checks lines of OUT: each
# line of PRESENT is one of them, none of ABSENT is, and COUNT of them (or
# MIN_COUNT at least) match COUNT_REGEX. Values that the test computes by hand (a midpoint, a face
# centre) are compared as the writer prints them (the shortest exact text).
execute_process(COMMAND ${PROGRAM} ${ARGS} RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status STREQUAL "0")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: exit status ${_status}: ${_err}")
endif()
file(STRINGS ${OUT} _lines)
foreach(_line IN LISTS PRESENT)
  list(FIND _lines "${_line}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "${OUT} has no line '${_line}'")
  endif()
endforeach()
foreach(_line IN LISTS ABSENT)
  list(FIND _lines "${_line}" _at)
  if(NOT _at EQUAL -1)
    message(FATAL_ERROR "${OUT} has the line '${_line}'")
  endif()
endforeach()
if(DEFINED COUNT_REGEX)
  set(_matching ${_lines})
  list(FILTER _matching INCLUDE REGEX "${COUNT_REGEX}")
  list(LENGTH _matching _n)
  if(DEFINED COUNT AND NOT _n EQUAL COUNT)
    message(FATAL_ERROR "${OUT} has ${_n} lines matching '${COUNT_REGEX}', expected ${COUNT}")
  endif()
  if(DEFINED MIN_COUNT AND _n LESS MIN_COUNT)
    message(FATAL_ERROR "${OUT} has ${_n} lines matching '${COUNT_REGEX}', expected ${MIN_COUNT} at least")
  endif()
endif()
message(STATUS "as expected: ${_out}")
