# cmake -DPROGRAM=<tool> [-DARGS=a;b;...] [-DSTATUS=<n>] [-DSTDOUT=<regex>] [-DSTDERR=<regex>]
#       [-DOUTPUT=<file> -DAXIS=x|y|z -DLEVELS=<v;w;...>] -P check_tool.cmake
#
# Runs PROGRAM with ARGS and checks what CTest's pass expressions cannot:
# the exit status (STATUS, default 0), stdout and stderr apart (each must
# match its regex; an unset one must be empty), and, with OUTPUT, that the
# distinct AXIS coordinates of the vertices of the OBJ file written are
# exactly LEVELS (as the file prints them, in CMake's NATURAL order).
if(NOT DEFINED STATUS)
  set(STATUS 0)
endif()
execute_process(COMMAND ${PROGRAM} ${ARGS} RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status STREQUAL "${STATUS}")
  message(FATAL_ERROR "exit status '${_status}', expected ${STATUS}; stdout: ${_out}; stderr: ${_err}")
endif()
foreach(_stream out err)
  string(TOUPPER "STD${_stream}" _expected)
  if(DEFINED ${_expected})
    if(NOT _${_stream} MATCHES "${${_expected}}")
      message(FATAL_ERROR "std${_stream} does not match '${${_expected}}': ${_${_stream}}")
    endif()
  elseif(NOT _${_stream} STREQUAL "")
    message(FATAL_ERROR "expected nothing on std${_stream}, got: ${_${_stream}}")
  endif()
endforeach()
if(DEFINED OUTPUT)
  set(_column_x 1)
  set(_column_y 2)
  set(_column_z 3)
  file(STRINGS ${OUTPUT} _vertices REGEX "^v ")
  set(_levels)
  foreach(_line ${_vertices})
    string(REGEX REPLACE " +" ";" _fields "${_line}")
    list(GET _fields ${_column_${AXIS}} _value)
    list(APPEND _levels ${_value})
  endforeach()
  list(REMOVE_DUPLICATES _levels)
  list(SORT _levels COMPARE NATURAL)
  if(NOT _levels STREQUAL "${LEVELS}")
    message(FATAL_ERROR "${AXIS} levels of ${OUTPUT}: '${_levels}', expected '${LEVELS}'")
  endif()
endif()
message(STATUS "as expected: ${_out}${_err}")
