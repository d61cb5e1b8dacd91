# cmake -DMESH_INFO=<program> [-DFILE=<file> | -DARGS=<a;b;...>] [-DNAME=<tool>] [-DEXPECT=<regex>]
#       -P mesh_info_expect_failure.cmake
#
# Runs mesh_info (or another tool, NAME) on FILE or ARGS (no argument if both
# are unset) and checks that it fails the documented way: exit status 2,
# nothing on stdout, and exactly one line on stderr, "<NAME>: <what>",
# matching EXPECT if given.
if(DEFINED FILE)
  set(_args ${FILE})
elseif(DEFINED ARGS)
  set(_args ${ARGS})
endif()
if(NOT DEFINED NAME)
  set(NAME mesh_info)
endif()
execute_process(COMMAND ${MESH_INFO} ${_args}
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status STREQUAL "2")
  message(FATAL_ERROR "exit status '${_status}', expected 2; stderr: ${_err}")
endif()
if(NOT _out STREQUAL "")
  message(FATAL_ERROR "expected nothing on stdout, got: ${_out}")
endif()
if(NOT _err MATCHES "^${NAME}: [^\n]+\n$")
  message(FATAL_ERROR "expected one line '${NAME}: <what>' on stderr, got: ${_err}")
endif()
if(DEFINED EXPECT AND NOT _err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match '${EXPECT}': ${_err}")
endif()
message(STATUS "as expected: ${_err}")
