# CTest tests of the convert, merge and pmp_on_mobius tools (included from
# examples/CMakeLists.txt). Expected counts come from the first line of each
# test file (V, E, F, chi, orientability, border loops) or from topology:
# two Möbius strips glued along their borders make a Klein bottle.
if(NOT CGAL_EXT_BUILD_TESTS)
  return()
endif()

set(_data ${PROJECT_SOURCE_DIR}/test/data/nonorientable)
set(_out ${CMAKE_CURRENT_BINARY_DIR}/tool_output)
file(MAKE_DIRECTORY ${_out})
set(_fails "^[a-z_]+: [^\n]+\n$")

# convert: the round trip through Surface_mesh keeps every count of the input.
file(GLOB _files ${_data}/*.obj)
foreach(_file ${_files})
  get_filename_component(_name ${_file} NAME_WE)
  file(STRINGS ${_file} _header LIMIT_COUNT 1)
  string(REGEX MATCH "V=([0-9]+) E=([0-9]+) F=([0-9]+) chi=(-?[0-9]+) orientable=(True|False) boundary_loops=([0-9]+)"
         _match "${_header}")
  string(TOLOWER ${CMAKE_MATCH_5} _orientable)
  if(CMAKE_MATCH_6 EQUAL 0)
    set(_closed true)
  else()
    set(_closed false)
  endif()
  add_test(NAME convert.${_name} COMMAND convert ${_file} ${_out}/convert_${_name}.obj)
  set_tests_properties(convert.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "^{\"vertices\":${CMAKE_MATCH_1},\"edges\":${CMAKE_MATCH_2},\"faces\":${CMAKE_MATCH_3},\"border_loops\":${CMAKE_MATCH_6},\"mobius_edges\":[0-9]+,\"orientable\":${_orientable},\"closed\":${_closed},\"components\":1,\"euler_characteristic\":${CMAKE_MATCH_4},\"valid\":true}\n$")
  # --cut: an oriented cut mesh with the same faces.
  add_test(NAME convert.cut.${_name} COMMAND convert ${_file} ${_out}/cut_${_name}.obj --cut)
  set_tests_properties(convert.cut.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "^{\"vertices\":[0-9]+,\"edges\":[0-9]+,\"faces\":${CMAKE_MATCH_3},\"border_loops\":[0-9]+,\"mobius_edges\":0,\"orientable\":true,.*\"valid\":true}\n$")
  # One rule for the Möbius edge count: convert and mesh_info agree.
  add_test(NAME convert.same_mobius_count.${_name}
    COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:mesh_info> -DCONVERT=$<TARGET_FILE:convert> -DFILE=${_file}
            -DOUT=${_out}/count_${_name}.obj -P ${CMAKE_CURRENT_SOURCE_DIR}/same_mobius_count.cmake)
endforeach()
# A Möbius strip cut along a transversal arc is a disc (chi 1, one border loop).
add_test(NAME convert.cut.mobius_is_a_disc COMMAND convert ${_data}/mobius_20x4_quads.obj ${_out}/cut_disc.obj --cut)
set_tests_properties(convert.cut.mobius_is_a_disc PROPERTIES PASS_REGULAR_EXPRESSION
  "\"faces\":80,\"border_loops\":1,\"mobius_edges\":0,\"orientable\":true,\"closed\":false,\"components\":1,\"euler_characteristic\":1,\"valid\":true}")
# Texture coordinates and normals go through the Surface_mesh as halfedge
# maps and come back with the same values and seams (the cube's uv net cuts
# 7 of its 12 edges; each face has normals of its own), written to OBJ.
add_test(NAME convert.corner_channels
  COMMAND convert ${PROJECT_SOURCE_DIR}/test/data/opensubdiv/catmark_cube.obj ${_out}/convert_cube.obj)
set_tests_properties(convert.corner_channels PROPERTIES PASS_REGULAR_EXPRESSION
  "\"corner_channels\":\\[\\{\"name\":\"c:uv\",\"values\":14,\"seam_edges\":7,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\},\\{\"name\":\"c:normal\",\"values\":24,\"seam_edges\":12,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\}\\]")
add_test(NAME convert.fails.missing_file COMMAND convert ${_data}/no_such_file.obj ${_out}/x.obj)
set_tests_properties(convert.fails.missing_file PROPERTIES PASS_REGULAR_EXPRESSION "${_fails}")
add_test(NAME convert.fails.usage COMMAND convert)
set_tests_properties(convert.fails.usage PROPERTIES PASS_REGULAR_EXPRESSION
  "^convert: expected two file names, got 0; usage: convert IN OUT \\[--cut\\] \\[--no-tags\\]\n$")
# OpenSubdiv's tags: the cube with 12 creased edges (its file's 12 't crease'
# lines) keeps them through the round trip; --no-tags writes no 't' line, the
# OBJ that CGAL's reader takes.
set(_creased ${PROJECT_SOURCE_DIR}/test/data/opensubdiv/catmark_cube_creases1.obj)
add_test(NAME convert.crease_tags
  COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:convert> "-DARGS=${_creased};${_out}/convert_creased.obj"
          -DOUT=${_out}/convert_creased.obj "-DCOUNT_REGEX=^t crease 2/1/0 " -DCOUNT=12
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_output_lines.cmake)
add_test(NAME convert.no_tags
  COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:convert> "-DARGS=${_creased};${_out}/convert_no_tags.obj;--no-tags"
          -DOUT=${_out}/convert_no_tags.obj "-DCOUNT_REGEX=^t " -DCOUNT=0
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_output_lines.cmake)

# merge: two copies of a Möbius strip (100 V, 180 E, 80 F, a 40-edge border)
# glued along their borders are a Klein bottle: 160 V, 320 E, 160 F, closed, chi 0.
set(_klein "^{\"vertices\":160,\"edges\":320,\"faces\":160,\"border_loops\":0,\"mobius_edges\":[0-9]+,\"orientable\":false,\"closed\":true,\"components\":1,\"euler_characteristic\":0,\"valid\":true}\n$")
foreach(_strategy auto keep-first keep-second average)
  add_test(NAME merge.klein.${_strategy} COMMAND merge ${_data}/mobius_20x4_quads.obj ${_data}/mobius_20x4_quads.obj
           ${_out}/klein_${_strategy}.obj --strategy ${_strategy})
  set_tests_properties(merge.klein.${_strategy} PROPERTIES PASS_REGULAR_EXPRESSION "${_klein}")
endforeach()
# Bridging the two borders with 40 quads instead: 200 V, 400 E, 200 F.
add_test(NAME merge.klein.bridge COMMAND merge ${_data}/mobius_20x4_quads.obj ${_data}/mobius_20x4_quads.obj
         ${_out}/klein_bridge.obj --strategy bridge)
set_tests_properties(merge.klein.bridge PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":200,\"edges\":400,\"faces\":200,\"border_loops\":0,\"mobius_edges\":[0-9]+,\"orientable\":false,\"closed\":true,\"components\":1,\"euler_characteristic\":0,\"valid\":true}\n$")
# Closed meshes have nothing to glue: the disjoint union.
add_test(NAME merge.closed_union COMMAND merge ${_data}/torus_24x12_quads.obj ${_data}/torus_24x12_quads.obj
         ${_out}/tori.obj --tolerance 0.5)
set_tests_properties(merge.closed_union PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":576,\"edges\":1152,\"faces\":576,\"border_loops\":0,\"mobius_edges\":0,\"orientable\":true,\"closed\":true,\"components\":2,\"euler_characteristic\":0,\"valid\":true}\n$")
add_test(NAME merge.fails.negative_tolerance COMMAND merge ${_data}/mobius_20x4_quads.obj
         ${_data}/mobius_20x4_quads.obj ${_out}/x.obj --tolerance -1)
set_tests_properties(merge.fails.negative_tolerance PROPERTIES PASS_REGULAR_EXPRESSION "^merge: [^\n]*tolerance[^\n]*\n$")
add_test(NAME merge.fails.unequal_loops COMMAND merge ${_data}/mobius_20x4_quads.obj
         ${_data}/mobius_min_5tris.obj ${_out}/x.obj --strategy average --loops 0,0)
set_tests_properties(merge.fails.unequal_loops PROPERTIES PASS_REGULAR_EXPRESSION
  "^merge: [^\n]*40 \\(a whole loop\\) and 5 \\(a whole loop\\) edges[^\n]*\n$")

# The manual strategies glue the borders that face each other. Two tubes of
# 8 quads end to end (z 0..1 and 1.5..2.5): A's upper loop meets B's lower
# one, the tube grows to 24 V, 16 F, chi 0, 2 loops, and the glued ring lies
# at z 1, 1.5 or their midpoint 1.25; bridging adds 8 quads (32 V, 24 F).
# Two halves of a square strip (x 0..1 and 1.5..2.5, 2x2 quads each): their
# facing sides (3 vertices) are glued, not whole loops: a disc of
# 9 + 9 - 3 = 15 V, 8 F, chi 1, one loop; bridging adds 2 quads (18 V, 10 F).
set(_merge_data ${PROJECT_SOURCE_DIR}/test/data/merge)
set(_check ${CMAKE_CURRENT_SOURCE_DIR}/check_tool.cmake)
foreach(_case "tube;z;0\\;1.25\\;2.5;average" "tube;z;0\\;1\\;2.5;keep-first" "tube;z;0\\;1.5\\;2.5;keep-second"
              "tube;z;0\\;1\\;1.5\\;2.5;bridge"
              "strip;x;0\\;0.5\\;1.25\\;2\\;2.5;average" "strip;x;0\\;0.5\\;1\\;2\\;2.5;keep-first"
              "strip;x;0\\;0.5\\;1.5\\;2\\;2.5;keep-second" "strip;x;0\\;0.5\\;1\\;1.5\\;2\\;2.5;bridge")
  list(GET _case 0 _shape)
  list(GET _case 1 _axis)
  list(GET _case -1 _strategy)
  list(SUBLIST _case 2 -1 _levels)
  list(REMOVE_AT _levels -1)
  if(_shape STREQUAL "tube")
    set(_a ${_merge_data}/tube_z0_z1.obj)
    set(_b ${_merge_data}/tube_z1.5_z2.5.obj)
    set(_counts "\"vertices\":24,\"edges\":40,\"faces\":16,\"border_loops\":2,\"mobius_edges\":0,\"orientable\":true,\"closed\":false,\"components\":1,\"euler_characteristic\":0")
    if(_strategy STREQUAL "bridge")
      set(_counts "\"vertices\":32,\"edges\":56,\"faces\":24,\"border_loops\":2,\"mobius_edges\":0,\"orientable\":true,\"closed\":false,\"components\":1,\"euler_characteristic\":0")
    endif()
  else()
    set(_a ${_merge_data}/strip_x0_x1.obj)
    set(_b ${_merge_data}/strip_x1.5_x2.5.obj)
    set(_counts "\"vertices\":15,\"edges\":22,\"faces\":8,\"border_loops\":1,\"mobius_edges\":0,\"orientable\":true,\"closed\":false,\"components\":1,\"euler_characteristic\":1")
    if(_strategy STREQUAL "bridge")
      set(_counts "\"vertices\":18,\"edges\":27,\"faces\":10,\"border_loops\":1,\"mobius_edges\":0,\"orientable\":true,\"closed\":false,\"components\":1,\"euler_characteristic\":1")
    endif()
  endif()
  add_test(NAME merge.facing.${_shape}.${_strategy}
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:merge>
            "-DARGS=${_a};${_b};${_out}/facing_${_shape}_${_strategy}.obj;--strategy;${_strategy}"
            "-DSTDOUT=^{${_counts},\"valid\":true}\n$" -DOUTPUT=${_out}/facing_${_shape}_${_strategy}.obj
            -DAXIS=${_axis} "-DLEVELS=${_levels}" -P ${_check})
endforeach()
# --loops chooses whole loops: the two strip halves' loops glued whole close into a sphere (10 V, 8 F).
add_test(NAME merge.loops.strip_sphere COMMAND merge ${_merge_data}/strip_x0_x1.obj ${_merge_data}/strip_x1.5_x2.5.obj
         ${_out}/strip_sphere.obj --strategy average --loops 0,0)
set_tests_properties(merge.loops.strip_sphere PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":10,\"edges\":16,\"faces\":8,\"border_loops\":0,\"mobius_edges\":0,\"orientable\":true,\"closed\":true,\"components\":1,\"euler_characteristic\":2,\"valid\":true}\n$")
add_test(NAME merge.fails.loop_out_of_range COMMAND merge ${_merge_data}/tube_z0_z1.obj
         ${_merge_data}/tube_z1.5_z2.5.obj ${_out}/x.obj --strategy average --loops 0,2)
set_tests_properties(merge.fails.loop_out_of_range PROPERTIES PASS_REGULAR_EXPRESSION
  "^merge: --loops: the loop of B '2' is not an integer from 0 to 1; usage: merge [^\n]*\n$")
add_test(NAME merge.fails.missing_file COMMAND merge ${_data}/no_such_file.obj ${_data}/mobius_20x4_quads.obj ${_out}/x.obj)
set_tests_properties(merge.fails.missing_file PROPERTIES PASS_REGULAR_EXPRESSION "${_fails}")

add_test(NAME example.pmp_on_mobius COMMAND pmp_on_mobius)
set_tests_properties(example.pmp_on_mobius PROPERTIES PASS_REGULAR_EXPRESSION "non-orientable, [0-9]+ Möbius edges: same topology")
# A polygon that CGAL's triangulation splits: the removed polygon is collected
# before the conversion (it used to stop with "the mesh has removed elements").
add_test(NAME example.pmp_on_mobius_pentagon COMMAND pmp_on_mobius ${PROJECT_SOURCE_DIR}/test/data/tools/pentagon.obj)
set_tests_properties(example.pmp_on_mobius_pentagon PROPERTIES PASS_REGULAR_EXPRESSION
  "1 border loop\\(s\\), orientable, 0 Möbius edges: same topology")
