# The topology a test mesh states on its first line, written when the data was
# made, independently of the library ("chi=0 orientable=False
# boundary_loops=1"): sets _chi, _orientable (true or false) and _border_loops
# in the caller's scope, for the tool tests to expect.
macro(cgal_ext_stated_topology file)
  file(STRINGS ${file} _header LIMIT_COUNT 1)
  string(REGEX MATCH "chi=(-?[0-9]+) orientable=(True|False) boundary_loops=([0-9]+)" _match "${_header}")
  if(NOT _match)
    message(FATAL_ERROR "${file}: no 'chi=N orientable=True|False boundary_loops=N' on its first line")
  endif()
  set(_chi ${CMAKE_MATCH_1})
  string(TOLOWER ${CMAKE_MATCH_2} _orientable)
  set(_border_loops ${CMAKE_MATCH_3})
endmacro()
