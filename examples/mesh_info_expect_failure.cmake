# cmake -DMESH_INFO=<program> [-DFILE=<file>] [-DEXPECT=<regex>] -P mesh_info_expect_failure.cmake
#
# Runs mesh_info on FILE (no argument if FILE is unset) and checks that it
# fails the documented way: exit status 2, nothing on stdout, and exactly one
# line on stderr, "mesh_info: <what>", matching EXPECT if given.
if(DEFINED FILE)
  set(_args ${FILE})
endif()
execute_process(COMMAND ${MESH_INFO} ${_args}
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status STREQUAL "2")
  message(FATAL_ERROR "exit status '${_status}', expected 2; stderr: ${_err}")
endif()
if(NOT _out STREQUAL "")
  message(FATAL_ERROR "expected nothing on stdout, got: ${_out}")
endif()
if(NOT _err MATCHES "^mesh_info: [^\n]+\n$")
  message(FATAL_ERROR "expected one line 'mesh_info: <what>' on stderr, got: ${_err}")
endif()
if(DEFINED EXPECT AND NOT _err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match '${EXPECT}': ${_err}")
endif()
message(STATUS "as expected: ${_err}")
