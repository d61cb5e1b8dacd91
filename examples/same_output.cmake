# cmake -DPROGRAM=<tool> -DFIRST=a;b;... -DFIRST_OUT=<file> -DSECOND=a;b;... -DSECOND_OUT=<file>
#       [-DDIFFERENT=a;b;... -DDIFFERENT_OUT=<file>] -P same_output.cmake
#
# Runs PROGRAM with the FIRST and the SECOND arguments, which must write the
# same file; with DIFFERENT, a third run must write a different one (so that
# the two could have differed).
foreach(_run FIRST SECOND DIFFERENT)
  if(NOT DEFINED ${_run})
    continue()
  endif()
  execute_process(COMMAND ${PROGRAM} ${${_run}} RESULT_VARIABLE _status ERROR_VARIABLE _err OUTPUT_QUIET)
  if(NOT _status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} ${${_run}}: exit status ${_status}: ${_err}")
  endif()
  file(READ ${${_run}_OUT} _written_${_run})
endforeach()
if(NOT _written_FIRST STREQUAL _written_SECOND)
  message(FATAL_ERROR "${FIRST_OUT} and ${SECOND_OUT} differ")
endif()
if(DEFINED DIFFERENT AND _written_DIFFERENT STREQUAL _written_FIRST)
  message(FATAL_ERROR "${DIFFERENT_OUT} is the same as ${FIRST_OUT}")
endif()
message(STATUS "as expected")
