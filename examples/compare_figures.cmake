# cmake -DRUN=<tool;args> -DFIELD=<name> [-DPATTERN=<regex>] [-DSTDOUT=<regex>]
#       (-DEXPECTED=<number> | -DOTHER_FIELD=<name>
#        | [-DBETWEEN=<tool;args>] -DREFERENCE=<tool;args> [-DREFERENCE_FIELD=<name>]
#          [-DREFERENCE_PATTERN=<regex>])
#       -DTOLERANCE=<relative> -DCLOSE=<close_numbers> -P compare_figures.cmake
#
# Runs RUN, which must exit 0 and print one JSON line (matching STDOUT if
# given), and takes the number of its field FIELD (or the first group of
# PATTERN; REFERENCE_PATTERN for the reference's line). Compares it (close_numbers) with EXPECTED, a closed form, with
# the field OTHER_FIELD of the same line, or with the field of the line that REFERENCE prints, after BETWEEN has run: the same
# figure computed another way (BETWEEN makes REFERENCE's input, such as the
# orientation double cover of RUN's output).
function(run_tool what command stdout_var)
  execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} exited with '${status}': ${command}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(${stdout_var} "${out}" PARENT_SCOPE)
endfunction()

function(figure what line field pattern result_var)
  if(NOT pattern)
    set(pattern "\"${field}\":([-+0-9.eE]+)")
  endif()
  if(NOT line MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: no '${pattern}' in ${line}")
  endif()
  set(${result_var} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

run_tool("the tool" "${RUN}" _line)
if(DEFINED STDOUT AND NOT _line MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}': ${_line}")
endif()
figure("the tool" "${_line}" "${FIELD}" "${PATTERN}" _value)
if(DEFINED EXPECTED)
  set(_reference ${EXPECTED})
elseif(DEFINED OTHER_FIELD)
  figure("the tool" "${_line}" "${OTHER_FIELD}" "" _reference)
else()
  if(DEFINED BETWEEN)
    run_tool("the step between" "${BETWEEN}" _ignored)
  endif()
  if(NOT DEFINED REFERENCE_FIELD)
    set(REFERENCE_FIELD ${FIELD})
  endif()
  run_tool("the reference" "${REFERENCE}" _reference_line)
  figure("the reference" "${_reference_line}" "${REFERENCE_FIELD}" "${REFERENCE_PATTERN}" _reference)
endif()
execute_process(COMMAND ${CLOSE} ${_value} ${_reference} ${TOLERANCE} RESULT_VARIABLE _status OUTPUT_VARIABLE _out
                ERROR_VARIABLE _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "${FIELD} ${_value} is not within ${TOLERANCE} of ${_reference}: ${_out}${_err}\n${_line}")
endif()
message(STATUS "${FIELD}: ${_out}")
