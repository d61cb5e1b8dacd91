# cmake -DMESH_INFO=<mesh_info> -DCONVERT=<convert> -DFILE=<mesh> -DOUT=<file> -P same_mobius_count.cmake
#
# One surface, one Möbius edge count: mesh_info on FILE and convert of FILE
# (whose round trip keeps every face's orientation) must report the same
# "mobius_edges", whatever orientation the faces of FILE have.
execute_process(COMMAND ${MESH_INFO} ${FILE} RESULT_VARIABLE _info_status OUTPUT_VARIABLE _info)
execute_process(COMMAND ${CONVERT} ${FILE} ${OUT} RESULT_VARIABLE _convert_status OUTPUT_VARIABLE _convert)
if(NOT _info_status EQUAL 0 OR NOT _convert_status EQUAL 0)
  message(FATAL_ERROR "mesh_info exited ${_info_status}, convert ${_convert_status}")
endif()
string(REGEX MATCH "\"mobius_edges\":([0-9]+)" _ "${_info}")
set(_from_info ${CMAKE_MATCH_1})
string(REGEX MATCH "\"mobius_edges\":([0-9]+)" _ "${_convert}")
set(_from_convert ${CMAKE_MATCH_1})
if(_from_info STREQUAL "" OR NOT _from_info STREQUAL _from_convert)
  message(FATAL_ERROR "mesh_info counts '${_from_info}' Möbius edges, convert '${_from_convert}'")
endif()
message(STATUS "both count ${_from_info} Möbius edges")
