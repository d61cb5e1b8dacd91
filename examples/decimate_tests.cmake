# CTest tests of the decimate tool (included from examples/CMakeLists.txt).
# A decimation keeps the Euler characteristic, the border loops and
# orientability of every input; expected values come from each file's first
# line (written when the data was made, independently of the library). The
# Hausdorff distance, CGAL's sampling of 20 000 points each way (most of a run
# in the sanitized test build), is asked for where a test checks it.
if(NOT CGAL_EXT_BUILD_TESTS)
  return()
endif()

set(_data ${PROJECT_SOURCE_DIR}/test/data/nonorientable)
set(_out ${CMAKE_CURRENT_BINARY_DIR}/tool_output)
file(MAKE_DIRECTORY ${_out})

file(GLOB _files ${_data}/*.obj)
foreach(_file ${_files})
  get_filename_component(_name ${_file} NAME_WE)
  cgal_ext_stated_topology(${_file})
  add_test(NAME decimate.${_name} COMMAND decimate ${_file} ${_out}/decimate_${_name}.obj --ratio 0.5 --no-hausdorff)
  set_tests_properties(decimate.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "\"border_loops\":${_border_loops},[^}]*\"orientable\":${_orientable},[^}]*\"euler_characteristic\":${_chi},\"valid\":true,\"seconds\":[0-9.e+-]+,\"hausdorff\":null}")
endforeach()

# The torus of 24 x 12 quads (576 triangles) down to 100 faces exactly (each
# collapse on a closed surface takes two), then a bound no collapse exceeds
# leaves a flat file alone: the hemi-icosahedron has no collapse of error 0.
add_test(NAME decimate.torus_to_100 COMMAND decimate ${_data}/torus_24x12_quads.obj ${_out}/decimate_torus.obj
         --faces 100 --no-hausdorff)
set_tests_properties(decimate.torus_to_100 PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":50,\"edges\":150,\"faces\":100,\"border_loops\":0,")
add_test(NAME decimate.error_bound_zero COMMAND decimate ${_data}/rp2_hemi_icosahedron.obj ${_out}/decimate_rp2.obj
         --max-error 0)
set_tests_properties(decimate.error_bound_zero PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":6,\"edges\":15,\"faces\":10,.*\"hausdorff\":(0|[0-9.]+e-[0-9]+)}")

# --limit-distance: the distance of the result to the cage's limit surface, after the Hausdorff distance.
add_test(NAME decimate.limit_distance COMMAND decimate ${_data}/torus_24x12_quads.obj ${_out}/decimate_torus_limit.obj
         --faces 100 --limit-distance)
set_tests_properties(decimate.limit_distance PROPERTIES PASS_REGULAR_EXPRESSION
  "\"faces\":100,.*\"hausdorff\":0\\.[0-9]+,\"limit_distance\":0\\.[0-9]+}")

# Without the relocation, the same count and topology.
add_test(NAME decimate.torus_to_100_no_relocation COMMAND decimate ${_data}/torus_24x12_quads.obj
         ${_out}/decimate_torus_unmoved.obj --faces 100 --no-relocation --no-hausdorff)
set_tests_properties(decimate.torus_to_100_no_relocation PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":50,\"edges\":150,\"faces\":100,\"border_loops\":0,")

# A file that is not there, and a ratio out of range: one line, exit 2.
cgal_ext_tool_fails(decimate.fails.missing_file decimate
  "${_out}/no_such.obj;${_out}/x.obj;--faces;10"
  "^decimate: [^\n]+\n$")
cgal_ext_tool_fails(decimate.fails.ratio decimate
  "${_data}/mobius_min_5tris.obj;${_out}/x.obj;--ratio;2"
  "^decimate: --ratio '2' is not in \\[0, 1\\]; usage: [^\n]+\n$")
cgal_ext_tool_fails(decimate.fails.corner_value_weight decimate
  "${_data}/mobius_min_5tris.obj;${_out}/x.obj;--ratio;0.5;--corner-value-weight;-1"
  "^decimate: --corner-value-weight '-1' is not a finite number >= 0; usage: [^\n]+\n$")

# A surface without area (three points in line): nothing to sample for the
# Hausdorff distance, which is null; a point beyond +-1e60: one line, exit 2.
file(WRITE ${_out}/collinear_triangle.obj "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")
add_test(NAME decimate.no_area COMMAND decimate ${_out}/collinear_triangle.obj ${_out}/decimate_collinear.obj --ratio 0)
set_tests_properties(decimate.no_area PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":3,\"edges\":3,\"faces\":1,.*\"valid\":true,\"seconds\":[0-9.e+-]+,\"hausdorff\":null}")
file(WRITE ${_out}/far_triangle.obj "v 0 0 0\nv 1e70 0 0\nv 0 1 0\nf 1 2 3\n")
cgal_ext_tool_fails(decimate.fails.far_point decimate
  "${_out}/far_triangle.obj;${_out}/x.obj;--ratio;0"
  "^decimate: decimate: vertex 1 at [^\n]+ beyond [^\n]+\n$")

# The Hausdorff distance is between surfaces: stray vertices on no face are
# not sampled, so a decimation that leaves a triangle as it was is at 0
# (it used to report the stray vertices' distance, 9.8).
add_test(NAME decimate.hausdorff_ignores_isolated_vertices COMMAND decimate
         ${PROJECT_SOURCE_DIR}/test/data/tools/triangle_two_stray_vertices.obj ${_out}/decimate_stray.obj --ratio 1)
set_tests_properties(decimate.hausdorff_ignores_isolated_vertices PROPERTIES PASS_REGULAR_EXPRESSION
  "\"faces\":1,.*\"hausdorff\":(0|[0-9.]+e-(1[0-9]|[2-9][0-9]))}")
# --no-hausdorff: the distance is left out (null), the rest as usual (the
# tests above), and given with the limit distance (decimate.limit_distance).

# Texture coordinates and normals go through: OpenSubdiv's cube with its uv
# net and its per-face normals, subdivided 3 levels (768 triangles; the uv
# net's 7 seam edges split into 56, the normals' 12 cube edges into 96), then
# decimated by half. Seam edges are never collapsed, so mesh_info reads the
# same number of seam edges back from the file, and every corner has a value
# (that the seams keep their values is tested in test_decimation.cpp).
set(_cube_uv ${_out}/decimate_cube_uv_level3.obj)
add_test(NAME decimate.corner_channels.setup
         COMMAND subdivide ${PROJECT_SOURCE_DIR}/test/data/opensubdiv/catmark_cube.obj ${_cube_uv} --levels 3)
set_tests_properties(decimate.corner_channels.setup PROPERTIES FIXTURES_SETUP decimate_cube_uv)
set(_seams "\"corner_channels\":\\[\\{\"name\":\"c:uv\",\"values\":[0-9]+,\"seam_edges\":56,\"corners_without_value\":0,[^}]*\\},\\{\"name\":\"c:normal\",\"values\":[0-9]+,\"seam_edges\":96,\"corners_without_value\":0,")
# Carried alike when weighed 0 (the points alone choose the collapses).
foreach(_weight default 0)
  set(_name decimate.corner_channels_carried)
  set(_option "")
  if(_weight STREQUAL "0")
    set(_name ${_name}_weight_0)
    set(_option ";--corner-value-weight;0")
  endif()
  add_test(NAME ${_name}
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:decimate> -DMESH_INFO=$<TARGET_FILE:mesh_info>
                   "-DARGS=${_cube_uv};${_out}/${_name}.obj;--ratio;0.5;--no-hausdorff${_option}"
                   -DOUT=${_out}/${_name}.obj "-DEXPECT=\"faces\":3[0-8][0-9],.*\"corner_values_interpolated\":[1-9][0-9]*}"
                   "-DEXPECT_INFO=\"euler_characteristic\":2,\"valid\":true,${_seams}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/corner_data_tool.cmake)
  set_tests_properties(${_name} PROPERTIES FIXTURES_REQUIRED decimate_cube_uv)
endforeach()
