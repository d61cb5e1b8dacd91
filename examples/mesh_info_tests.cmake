# CTest tests of the mesh_info tool (included from examples/CMakeLists.txt).
#
# * Every file in test/data/nonorientable/ states on its first line what a
#   correct import finds (V, E, F, chi, orientability, border loops); the
#   test's pass expression is built from that line.
# * Failures: a missing file, no argument, and every file in test/data/bad/
#   but the non-manifold ones (described, not refused) must make mesh_info exit with status 2 and
#   one line on stderr; files in test/data/bad/ say on their first line at
#   which line the error is ("error at line N [or M ...]" or "no line").
if(NOT CGAL_EXT_BUILD_TESTS)
  return()
endif()

set(_mesh_info_data ${PROJECT_SOURCE_DIR}/test/data)

file(GLOB _mesh_info_good ${_mesh_info_data}/nonorientable/*.obj)
foreach(_file ${_mesh_info_good})
  get_filename_component(_name ${_file} NAME_WE)
  file(STRINGS ${_file} _header LIMIT_COUNT 1)
  if(NOT _header MATCHES
     "V=([0-9]+) E=([0-9]+) F=([0-9]+) chi=(-?[0-9]+) orientable=(True|False) boundary_loops=([0-9]+)")
    message(FATAL_ERROR "${_file}: the first line does not state V, E, F, chi, orientable and boundary_loops")
  endif()
  set(_v ${CMAKE_MATCH_1})
  set(_e ${CMAKE_MATCH_2})
  set(_f ${CMAKE_MATCH_3})
  set(_chi ${CMAKE_MATCH_4})
  string(TOLOWER ${CMAKE_MATCH_5} _orientable)
  set(_b ${CMAKE_MATCH_6})
  # orient() leaves no Möbius edge on an orientable surface and at least one otherwise.
  if(_orientable STREQUAL "true")
    set(_mobius "0")
  else()
    set(_mobius "[1-9][0-9]*")
  endif()
  if(_b EQUAL 0)
    set(_closed "true")
  else()
    set(_closed "false")
  endif()
  add_test(NAME mesh_info.${_name} COMMAND mesh_info ${_file})
  set_tests_properties(mesh_info.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "^{\"vertices\":${_v},\"edges\":${_e},\"faces\":${_f},\"border_loops\":${_b},\"mobius_edges\":${_mobius},\"orientable\":${_orientable},\"closed\":${_closed},\"components\":[1-9][0-9]*,\"euler_characteristic\":${_chi},\"valid\":true}\n$")
endforeach()

# Texture coordinates and normals: the cube's uv net cuts 7 of its 12 edges
# (a net of a cube keeps 5 folds); each face has normals of its own.
add_test(NAME mesh_info.corner_channels COMMAND mesh_info ${_mesh_info_data}/opensubdiv/catmark_cube.obj)
set_tests_properties(mesh_info.corner_channels PROPERTIES PASS_REGULAR_EXPRESSION
  "\"valid\":true,\"corner_channels\":\\[\\{\"name\":\"c:uv\",\"values\":14,\"seam_edges\":7,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\},\\{\"name\":\"c:normal\",\"values\":24,\"seam_edges\":12,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\}\\]\\}\n$")

# A Möbius strip of three quads (columns t_k b_k at 0, 120 and 240 degrees,
# each a half turn further from the last; quad 2 joins column 2 to column 0
# turned over) has one Möbius edge however it is oriented. With a texture
# coordinate per vertex (f v/v) the channel is continuous across it; with
# four of its own per quad every inner edge (3, the Möbius one included) is a seam.
set(_strip_v "v 2.5 0 0\nv -1.125 1.9485 0.433\nv -0.875 -1.5155 0.433\nv 1.5 0 0\nv -0.875 1.5155 -0.433\nv -1.125 -1.9485 -0.433\n")
set(_strip_continuous ${CMAKE_CURRENT_BINARY_DIR}/mobius3_uv_continuous.obj)
file(WRITE ${_strip_continuous} "${_strip_v}vt 0 1\nvt 0.333 1\nvt 0.667 1\nvt 0 0\nvt 0.333 0\nvt 0.667 0\n"
  "f 1/1 4/4 5/5 2/2\nf 2/2 5/5 6/6 3/3\nf 3/3 6/6 1/1 4/4\n")
set(_strip_seamed ${CMAKE_CURRENT_BINARY_DIR}/mobius3_uv_per_quad.obj)
file(WRITE ${_strip_seamed} "${_strip_v}vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 4/2 5/3 2/4\nf 2/5 5/6 6/7 3/8\nf 3/9 6/10 1/11 4/12\n")
set(_strip_line "\"border_loops\":1,\"mobius_edges\":1,\"orientable\":false,\"closed\":false,\"components\":1,\"euler_characteristic\":0,\"valid\":true")
add_test(NAME mesh_info.corner_channels_continuous_across_mobius COMMAND mesh_info ${_strip_continuous})
set_tests_properties(mesh_info.corner_channels_continuous_across_mobius PROPERTIES PASS_REGULAR_EXPRESSION
  "${_strip_line},\"corner_channels\":\\[\\{\"name\":\"c:uv\",\"values\":6,\"seam_edges\":0,\"corners_without_value\":0,\"mobius_edges_continuous\":1,\"mobius_edges_seamed\":0\\}\\]\\}\n$")
add_test(NAME mesh_info.corner_channels_seamed_across_mobius COMMAND mesh_info ${_strip_seamed})
set_tests_properties(mesh_info.corner_channels_seamed_across_mobius PROPERTIES PASS_REGULAR_EXPRESSION
  "${_strip_line},\"corner_channels\":\\[\\{\"name\":\"c:uv\",\"values\":12,\"seam_edges\":3,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":1\\}\\]\\}\n$")

set(_mesh_info_check ${CMAKE_CURRENT_SOURCE_DIR}/mesh_info_expect_failure.cmake)
add_test(NAME mesh_info.fails.no_argument
  COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:mesh_info> -DEXPECT=usage -P ${_mesh_info_check})
add_test(NAME mesh_info.fails.missing_file
  COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:mesh_info> -DFILE=${_mesh_info_data}/no_such_file.obj
          "-DEXPECT=no_such_file.obj: cannot open" -P ${_mesh_info_check})
add_test(NAME mesh_info.fails.unknown_extension
  COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:mesh_info> -DFILE=${_mesh_info_data}/README.md
          "-DEXPECT=unknown file extension" -P ${_mesh_info_check})
# Non-manifold input is described as the manifold sheets it is read into,
# with the input's counts: catmark_fan has four edges of three faces and five
# non-manifold vertices (as OpenSubdiv's Vtr tags them: test_non_manifold.cpp
# compares the counts); the readers' bad files have an edge (1, 2) of three
# triangles on five points (seven edges), and two triangles that share
# vertex 1 only.
add_test(NAME mesh_info.non_manifold.catmark_fan COMMAND mesh_info ${_mesh_info_data}/opensubdiv/catmark_fan.obj)
set_tests_properties(mesh_info.non_manifold.catmark_fan PROPERTIES PASS_REGULAR_EXPRESSION
  "\"non_manifold_vertices\":5,\"non_manifold_edges\":4,")
foreach(_file obj_nonmanifold_edge.obj off_nonmanifold_edge.off)
  add_test(NAME mesh_info.non_manifold.${_file} COMMAND mesh_info ${_mesh_info_data}/bad/${_file})
  set_tests_properties(mesh_info.non_manifold.${_file} PROPERTIES PASS_REGULAR_EXPRESSION
    "^{\"vertices\":9,\"edges\":9,\"faces\":3,\"border_loops\":3,.*\"non_manifold_vertices\":2,\"non_manifold_edges\":1,\"input_vertices\":5,\"input_edges\":7}\n$")
endforeach()
add_test(NAME mesh_info.non_manifold.obj_nonmanifold_vertex.obj
  COMMAND mesh_info ${_mesh_info_data}/bad/obj_nonmanifold_vertex.obj)
set_tests_properties(mesh_info.non_manifold.obj_nonmanifold_vertex.obj PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":6,\"edges\":6,\"faces\":2,\"border_loops\":2,.*\"non_manifold_vertices\":1,\"non_manifold_edges\":0,\"input_vertices\":5,\"input_edges\":6}\n$")
# A polygon that visits vertex 1 twice, (0, 1, 2, 1), beside the quad
# (0, 1, 2, 3): four non-manifold edges and three vertices, as OpenSubdiv's
# Vtr tags them (the pairs (0, 1) and (1, 2) are run along three times each).
add_test(NAME mesh_info.non_manifold.obj_repeated_vertex.obj
  COMMAND mesh_info ${_mesh_info_data}/bad/obj_repeated_vertex.obj)
set_tests_properties(mesh_info.non_manifold.obj_repeated_vertex.obj PROPERTIES PASS_REGULAR_EXPRESSION
  "\"non_manifold_vertices\":3,\"non_manifold_edges\":4,\"input_vertices\":4,\"input_edges\":6}\n$")
# A degenerate edge (5, 5) inside the fan of an interior vertex: a loop of
# the sheet, one non-manifold edge and vertex (OpenSubdiv's tags, compared in
# test_non_manifold.cpp), no vertex split; its texture seam there.
add_test(NAME mesh_info.non_manifold.grid_degenerate_edge_uv.obj
  COMMAND mesh_info ${_mesh_info_data}/nonmanifold/grid_degenerate_edge_uv.obj)
set_tests_properties(mesh_info.non_manifold.grid_degenerate_edge_uv.obj PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":16,\"edges\":25,\"faces\":9,\"border_loops\":2,.*\"valid\":true,.*\"values\":17,\"seam_edges\":1,.*\"non_manifold_vertices\":1,\"non_manifold_edges\":1,\"input_vertices\":16,\"input_edges\":25}\n$")

file(GLOB _mesh_info_bad ${_mesh_info_data}/bad/*)
foreach(_file ${_mesh_info_bad})
  get_filename_component(_name ${_file} NAME)
  if(_name MATCHES "nonmanifold_(edge|vertex)|repeated_vertex")
    continue() # bad for the library's default policy only: described above
  endif()
  file(STRINGS ${_file} _header LIMIT_COUNT 1)
  if(_header MATCHES "error at line ([0-9]+( or [0-9]+)*)")
    string(REPLACE " or " "|" _lines "${CMAKE_MATCH_1}")
    set(_expect "${_name}:(${_lines}): ")
  elseif(_header MATCHES "error with no line")
    set(_expect "${_name}: ")
  else()
    message(FATAL_ERROR "${_file}: the first line does not say where the error is")
  endif()
  add_test(NAME mesh_info.fails.${_name}
    COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:mesh_info> -DFILE=${_file} "-DEXPECT=${_expect}"
            -P ${_mesh_info_check})
endforeach()
