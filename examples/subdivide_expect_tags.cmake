# cmake -DSUBDIVIDE=<program> -DIN=<file> -DOUT=<file.obj> [-DARGS=<a;b;...>] [-DTAGS=<line;line;...>]
#       -P subdivide_expect_tags.cmake
#
# Runs subdivide IN OUT ARGS and checks that the tag lines ("t ...") of OUT
# are exactly TAGS, in order (none if TAGS is unset): a tag line is written
# only where it tells something, since CGAL's OBJ reader refuses any.
execute_process(COMMAND ${SUBDIVIDE} ${IN} ${OUT} ${ARGS} RESULT_VARIABLE _status ERROR_VARIABLE _err OUTPUT_QUIET)
if(NOT _status STREQUAL "0")
  message(FATAL_ERROR "subdivide failed (${_status}): ${_err}")
endif()
file(STRINGS ${OUT} _tags REGEX "^t ")
if(NOT "${_tags}" STREQUAL "${TAGS}")
  message(FATAL_ERROR "tag lines of ${OUT}: '${_tags}', expected '${TAGS}'")
endif()
message(STATUS "tag lines as expected: '${_tags}'")
