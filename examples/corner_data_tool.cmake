# cmake -DPROGRAM=<tool> -DARGS=<a;b;...> -DOUT=<file.obj> [-DEXPECT=<regex>] -DMESH_INFO=<program>
#       -DEXPECT_INFO=<regex> [-DVT=<count>] -P corner_data_tool.cmake
#
# Runs PROGRAM ARGS (a tool that writes OUT), checks its JSON line against
# EXPECT, then reads OUT back with mesh_info and checks its line against
# EXPECT_INFO: the texture coordinates and normals went through the tool and
# into the file. With VT, OUT must have that many `vt` lines.
execute_process(COMMAND ${PROGRAM} ${ARGS} RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status STREQUAL "0")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: exit status ${_status}: ${_err}")
endif()
if(DEFINED EXPECT AND NOT _out MATCHES "${EXPECT}")
  message(FATAL_ERROR "the tool's line does not match '${EXPECT}': ${_out}")
endif()
execute_process(COMMAND ${MESH_INFO} ${OUT} RESULT_VARIABLE _status OUTPUT_VARIABLE _info ERROR_VARIABLE _err)
if(NOT _status STREQUAL "0")
  message(FATAL_ERROR "mesh_info ${OUT}: exit status ${_status}: ${_err}")
endif()
if(NOT _info MATCHES "${EXPECT_INFO}")
  message(FATAL_ERROR "mesh_info's line of ${OUT} does not match '${EXPECT_INFO}': ${_info}")
endif()
if(DEFINED VT)
  file(STRINGS ${OUT} _vt REGEX "^vt ")
  list(LENGTH _vt _n)
  if(NOT _n EQUAL VT)
    message(FATAL_ERROR "${OUT} has ${_n} vt lines, expected ${VT}")
  endif()
endif()
message(STATUS "as expected: ${_info}")
