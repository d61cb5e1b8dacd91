# CTest tests of the tessellate tool (included from examples/CMakeLists.txt).
# The tessellation of a limit surface is watertight: its border loops,
# orientability and Euler characteristic are those each file states on its
# first line, and it is a valid mesh; rate 3 puts two samples inside every
# base edge, so any sample a face failed to share would break the counts.
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
  add_test(NAME tessellate.${_name} COMMAND tessellate ${_file} ${_out}/tessellate_${_name}.obj --rate 3)
  set_tests_properties(tessellate.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "\"border_loops\":${_border_loops},.*\"orientable\":${_orientable},.*\"euler_characteristic\":${_chi},\"valid\":true,\"corner_channels\":\\[\\],\"seconds\":")
endforeach()

# The Möbius strip of 100 vertices, 180 edges and 80 quads at rate 3:
# 100 + 180 x 2 + 80 x 4 vertices, 80 x 9 quads.
add_test(NAME tessellate.mobius_counts COMMAND tessellate ${_data}/mobius_20x4_quads.obj
         ${_out}/tessellate_mobius_counts.obj --rate 3)
set_tests_properties(tessellate.mobius_counts PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":780,\"edges\":1500,\"faces\":720,\"border_loops\":1,")

# Loop: the Möbius strip of 160 triangles (100 vertices, 260 edges) at rate 3:
# 100 + 260 x 2 + 160 x 1 vertices (one inside each triangle), 160 x 9
# triangles, still one non-orientable strip. A face that is not a triangle is refused.
add_test(NAME tessellate.loop_mobius COMMAND tessellate ${_data}/mobius_20x4_tris.obj
         ${_out}/tessellate_loop_mobius.obj --rate 3 --scheme loop)
set_tests_properties(tessellate.loop_mobius PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":780,\"edges\":2220,\"faces\":1440,\"border_loops\":1,\"mobius_edges\":[0-9]+,\"orientable\":false,.*\"euler_characteristic\":0,\"valid\":true,")
cgal_ext_tool_fails(tessellate.fails.loop_on_quads tessellate
  "${_data}/mobius_20x4_quads.obj;${_out}/x.obj;--rate;2;--scheme;loop"
  "^tessellate: [^\n]*not a triangle[^\n]*\n$")

# A file that is not there, a rate out of range, a border rule that is none of the
# accepted ones: one line, exit 2.
cgal_ext_tool_fails(tessellate.fails.missing_file tessellate
  "${_out}/no_such.obj;${_out}/x.obj;--rate;2"
  "^tessellate: [^\n]+\n$")
cgal_ext_tool_fails(tessellate.fails.rate tessellate
  "${_data}/mobius_20x4_quads.obj;${_out}/x.obj;--rate;65"
  "^tessellate: --rate '65' is not an integer from 1 to 64; usage: [^\n]+\n$")
cgal_ext_tool_fails(tessellate.fails.boundary tessellate
  "${_data}/mobius_20x4_quads.obj;${_out}/x.obj;--rate;2;--boundary;corners"
  "^tessellate: --boundary 'corners' is not none, edge-only or edge-and-corner; usage: [^\n]+\n$")

# --boundary none: the 40 quads that touch the border are holes (OpenSubdiv's
# rule); the 20 x 2 quads between them (60 vertices, 100 edges) are still a
# Möbius strip, at rate 3 60 + 100 x 2 + 40 x 4 vertices and 40 x 9 quads.
add_test(NAME tessellate.boundary_none COMMAND tessellate ${_data}/mobius_20x4_quads.obj
         ${_out}/tessellate_boundary_none.obj --rate 3 --boundary none)
set_tests_properties(tessellate.boundary_none PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":420,\"edges\":780,\"faces\":360,\"border_loops\":1,.*\"orientable\":false,.*\"euler_characteristic\":0,\"valid\":true,")

# To a tolerance: the Möbius strip stays one watertight one-sided strip (its
# Euler characteristic 0, one border loop). Both --rate and --tolerance, or
# a tolerance that is not positive: refused (neither: example.tessellate.bad_argument).
add_test(NAME tessellate.tolerance_mobius COMMAND tessellate ${_data}/mobius_20x4_quads.obj
         ${_out}/tessellate_tolerance_mobius.obj --tolerance 0.001)
set_tests_properties(tessellate.tolerance_mobius PROPERTIES PASS_REGULAR_EXPRESSION
  "\"border_loops\":1,.*\"orientable\":false,.*\"euler_characteristic\":0,\"valid\":true,")
cgal_ext_tool_fails(tessellate.fails.rate_and_tolerance tessellate
  "${_data}/mobius_20x4_quads.obj;${_out}/x.obj;--rate;2;--tolerance;0.1"
  "^tessellate: one of --rate and --tolerance is required; usage: [^\n]+\n$")
cgal_ext_tool_fails(tessellate.fails.tolerance tessellate
  "${_data}/mobius_20x4_quads.obj;${_out}/x.obj;--tolerance;0"
  "^tessellate: --tolerance must be positive and finite; usage: [^\n]+\n$")

# Texture coordinates and normals (OBJ vt/vn) are carried, each on its own
# limit surface: the cube's uv net is a disc of 14 values, 6 quads and 19
# edges (7 seams cut open); at rate 2 every edge gains a sample and every
# quad one inside, 14 + 19 + 6 = 39 values, each seam two seam edges (14).
# Its normals are 6 quads apart: 6 x (4 + 4 + 1) = 54 values, the 12 edges'
# halves seams (24). mesh_info reads them back from the file.
set(_cube_data ${PROJECT_SOURCE_DIR}/test/data/opensubdiv/catmark_cube.obj)
set(_tessellated_channels "\"corner_channels\":\\[\\{\"name\":\"c:uv\",\"values\":39,\"seam_edges\":14,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\},\\{\"name\":\"c:normal\",\"values\":54,\"seam_edges\":24,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\}\\]")
add_test(NAME tessellate.corner_data_obj_to_obj
         COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:tessellate> -DMESH_INFO=$<TARGET_FILE:mesh_info>
                 "-DARGS=${_cube_data};${_out}/tessellate_cube_uv.obj;--rate;2;--fvar-interpolation;corners-plus2"
                 -DOUT=${_out}/tessellate_cube_uv.obj "-DEXPECT=${_tessellated_channels}"
                 "-DEXPECT_INFO=\"faces\":24,.*${_tessellated_channels}" -DVT=39
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/corner_data_tool.cmake)
# PLY holds a value per vertex: the cube's seams are refused before the
# work, or left out with --drop-corner-data, which the line reports; a mode
# that is none of OpenSubdiv's is refused.
cgal_ext_tool_fails(tessellate.fails.corner_data_seams_not_in_ply tessellate
  "${_cube_data};${_out}/tessellate_cube_uv.ply;--rate;2"
  "^tessellate: the input's corner channels \\(c:uv, c:normal\\) cannot be carried: [^\n]*--drop-corner-data goes on without them\n$")
add_test(NAME tessellate.corner_data_dropped COMMAND tessellate ${_cube_data} ${_out}/tessellate_cube_uv.ply --rate 2
         --drop-corner-data)
set_tests_properties(tessellate.corner_data_dropped PROPERTIES PASS_REGULAR_EXPRESSION
  "\"corner_channels\":\\[\\],\"corner_channels_dropped\":\\[\"c:uv\",\"c:normal\"\\],")
cgal_ext_tool_fails(tessellate.fails.fvar_mode tessellate
  "${_cube_data};${_out}/x.obj;--rate;2;--fvar-interpolation;smooth"
  "^tessellate: --fvar-interpolation 'smooth' is not [^\n]+\n$")

# OpenSubdiv's smooth rule at triangles is taken (its values: unit tests).
add_test(NAME tessellate.smooth_triangles COMMAND tessellate
         ${PROJECT_SOURCE_DIR}/test/data/opensubdiv/catmark_smoothtris1.obj ${_out}/tessellate_smooth_triangles.obj
         --rate 2 --triangles smooth)
set_tests_properties(tessellate.smooth_triangles PROPERTIES PASS_REGULAR_EXPRESSION "\"valid\":true,")

# The OBJ tags give the defaults: "t interpolateboundary 1/0/0 0" is none,
# leaving the 2 of the 4 x 3 quads without a border vertex (3 x 2 vertices,
# 7 edges): at rate 2, 6 + 7 + 2 vertices and 8 quads; --boundary overrides
# the tag (48 quads).
set(_tools_data ${PROJECT_SOURCE_DIR}/test/data/tools)
add_test(NAME tessellate.boundary_from_tags COMMAND tessellate ${_tools_data}/grid_4x3_boundary_none.obj
         ${_out}/tessellate_boundary_from_tags.obj --rate 2)
set_tests_properties(tessellate.boundary_from_tags PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":15,\"edges\":22,\"faces\":8,\"border_loops\":1,")
add_test(NAME tessellate.boundary_flag_over_tags COMMAND tessellate ${_tools_data}/grid_4x3_boundary_none.obj
         ${_out}/tessellate_boundary_flag_over_tags.obj --rate 2 --boundary edge-only)
set_tests_properties(tessellate.boundary_flag_over_tags PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":63,\"edges\":110,\"faces\":48,\"border_loops\":1,")
