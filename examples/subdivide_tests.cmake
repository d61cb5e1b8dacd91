# CTest runs of the subdivide tool: counts of the result follow from the
# split (cube, Catmull-Clark, 2 steps: 98 vertices, 192 edges, 96 faces;
# Möbius strip of 160 triangles, Loop, 2 steps: 2560 faces; Doo-Sabin of
# the cube: a vertex per corner, a face per face, edge and vertex, 24/48/26;
# sqrt3 of the 160-triangle strip, 1 step: 3 triangles per face, border
# edges kept; linear: each triangle into four, each quad into four: 26/48/24
# on the cube), --triangles does what the OBJ tag does, and bad options or
# input exit with status 2.
if(CGAL_EXT_BUILD_TESTS)
  set(_data ${PROJECT_SOURCE_DIR}/test/data)
  add_test(NAME example.subdivide.cube
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/cube2.obj --levels 2)
  set_tests_properties(example.subdivide.cube PROPERTIES
    PASS_REGULAR_EXPRESSION "\"vertices\":98,\"edges\":192,\"faces\":96,\"hole_faces_removed\":0,\"seconds\":")
  # Non-manifold input, as OpenSubdiv subdivides it (78 vertices and 55
  # faces after one Catmull-Clark step: OpenSubdiv's level 1 of the shape;
  # 7 non-manifold vertices and 2 edges, as its Vtr tags them), written joined.
  add_test(NAME example.subdivide.non_manifold
           COMMAND subdivide ${_data}/opensubdiv/catmark_val2_nonman.obj ${CMAKE_CURRENT_BINARY_DIR}/val2_nonman.obj)
  set_tests_properties(example.subdivide.non_manifold PROPERTIES PASS_REGULAR_EXPRESSION
    "\"vertices\":78,\"edges\":[0-9]+,\"faces\":55,.*\"non_manifold_vertices\":7,\"non_manifold_edges\":2}\n$")
  # Polygons that visit a vertex twice (14 of them, 18 degenerate edges among
  # them), as OpenSubdiv 3.5 takes them: its level 1 has 464 vertices and
  # 339 faces; its base level, given the faces as the import orients them
  # (OpenSubdiv makes an edge of two faces that run the same way along it
  # non-manifold), 16 non-manifold vertices and 31 edges.
  add_test(NAME example.subdivide.non_manifold_repeated_vertices
           COMMAND subdivide ${_data}/opensubdiv/catmark_nonman_edges.obj ${CMAKE_CURRENT_BINARY_DIR}/nonman_edges.obj)
  set_tests_properties(example.subdivide.non_manifold_repeated_vertices PROPERTIES PASS_REGULAR_EXPRESSION
    "\"vertices\":464,\"edges\":[0-9]+,\"faces\":339,.*\"non_manifold_vertices\":16,\"non_manifold_edges\":31}\n$")
  add_test(NAME example.subdivide.mobius_loop_epeck
           COMMAND subdivide ${_data}/nonorientable/mobius_20x4_tris.obj ${CMAKE_CURRENT_BINARY_DIR}/mobius2.off
                   --scheme loop --levels 2 --kernel epeck)
  set_tests_properties(example.subdivide.mobius_loop_epeck PROPERTIES
    PASS_REGULAR_EXPRESSION "\"faces\":2560")
  add_test(NAME example.subdivide.cube_doo_sabin
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/cube_ds.ply
                   --scheme doo-sabin --kernel epick --drop-corner-data)
  set_tests_properties(example.subdivide.cube_doo_sabin PROPERTIES
    PASS_REGULAR_EXPRESSION "\"vertices\":24,\"edges\":48,\"faces\":26,\"hole_faces_removed\":0,\"seconds\":.*\"corner_channels_dropped\":\\[\"c:uv\",\"c:normal\"\\]")
  add_test(NAME example.subdivide.mobius_sqrt3
           COMMAND subdivide ${_data}/nonorientable/mobius_20x4_tris.obj ${CMAKE_CURRENT_BINARY_DIR}/mobius_s3.obj
                   --scheme sqrt3)
  set_tests_properties(example.subdivide.mobius_sqrt3 PROPERTIES PASS_REGULAR_EXPRESSION "\"faces\":480,")
  add_test(NAME example.subdivide.mobius_linear
           COMMAND subdivide ${_data}/nonorientable/mobius_20x4_tris.obj ${CMAKE_CURRENT_BINARY_DIR}/mobius_lin.obj
                   --scheme linear)
  set_tests_properties(example.subdivide.mobius_linear PROPERTIES PASS_REGULAR_EXPRESSION "\"faces\":640,")
  add_test(NAME example.subdivide.cube_linear
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/cube_lin.obj
                   --scheme linear --kernel epeck)
  set_tests_properties(example.subdivide.cube_linear PROPERTIES
    PASS_REGULAR_EXPRESSION "\"vertices\":26,\"edges\":48,\"faces\":24,\"hole_faces_removed\":0,\"seconds\":")
  # --boundary none: the faces OpenSubdiv marks as holes (those with a border
  # vertex in the input, and their children) are left out of the file. On the
  # 20x4 Moebius strip that is the two outer rows of 20 quads; Catmull-Clark,
  # 2 levels: 80 * 16 = 1280 faces, of which 640 are holes.
  add_test(NAME example.subdivide.boundary_none_drops_holes
           COMMAND subdivide ${_data}/nonorientable/mobius_20x4_quads.obj ${CMAKE_CURRENT_BINARY_DIR}/mobius_none.obj
                   --levels 2 --boundary none)
  set_tests_properties(example.subdivide.boundary_none_drops_holes PROPERTIES
    PASS_REGULAR_EXPRESSION "\"faces\":640,\"hole_faces_removed\":640,")
  add_test(NAME example.subdivide.sqrt3_on_quads
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/x.obj --scheme sqrt3
                   --drop-corner-data)
  add_test(NAME example.subdivide.bad_option
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/x.obj --levels x)
  add_test(NAME example.subdivide.loop_on_quads
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/x.obj --scheme loop)
  # --triangles smooth does what the OBJ tag 't smoothtriangles 0/0/1 smooth' does: OpenSubdiv's
  # shape with the tag, and the same shape without it but with the flag, give the same file
  # (points and tags); without either, Catmull-Clark's own triangle rule gives another.
  file(STRINGS ${_data}/opensubdiv/catmark_smoothtris1.obj _lines)
  list(FILTER _lines EXCLUDE REGEX "^t smoothtriangles")
  list(JOIN _lines "\n" _untagged)
  set(_plain ${CMAKE_CURRENT_BINARY_DIR}/smoothtris_untagged.obj)
  file(WRITE ${_plain} "${_untagged}\n")
  set(_o ${CMAKE_CURRENT_BINARY_DIR}/smoothtris)
  add_test(NAME example.subdivide.triangles_flag_as_tag
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:subdivide>
                   "-DFIRST=${_data}/opensubdiv/catmark_smoothtris1.obj;${_o}_tag.obj;--levels;2" -DFIRST_OUT=${_o}_tag.obj
                   "-DSECOND=${_plain};${_o}_flag.obj;--levels;2;--triangles;smooth" -DSECOND_OUT=${_o}_flag.obj
                   "-DDIFFERENT=${_plain};${_o}_catmark.obj;--levels;2" -DDIFFERENT_OUT=${_o}_catmark.obj
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/same_output.cmake)
  # Tag lines in the output: none from a file without tags, the options a
  # flag or the input set otherwise (catmark_edgecorner: interpolateboundary 1).
  set(_tags_script ${CMAKE_CURRENT_SOURCE_DIR}/subdivide_expect_tags.cmake)
  add_test(NAME example.subdivide.no_needless_tags
           COMMAND ${CMAKE_COMMAND} -DSUBDIVIDE=$<TARGET_FILE:subdivide> -DIN=${_data}/opensubdiv/catmark_cube.obj
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cube_no_tags.obj -P ${_tags_script})
  add_test(NAME example.subdivide.tags_of_flags_and_input
           COMMAND ${CMAKE_COMMAND} -DSUBDIVIDE=$<TARGET_FILE:subdivide>
                   -DIN=${_data}/opensubdiv/catmark_edgecorner.obj -DOUT=${CMAKE_CURRENT_BINARY_DIR}/edgecorner.obj
                   "-DARGS=--crease-method;chaikin"
                   "-DTAGS=t interpolateboundary 1/0/0 1;t creasemethod 0/0/1 chaikin" -P ${_tags_script})
  # Refused up front by the library, under the limit --max-memory passes to it:
  # the cube's 6 quads at level 12 are 6 * 4^12 = 100663296 faces (about 11 GB);
  # level 2 (96 faces) under a limit of 1000 bytes; Doo-Sabin, whose faces also
  # grow fourfold, at level 10 (about 6 M faces) under 0.2 GB.
  add_test(NAME example.subdivide.too_large_for_memory
           COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:subdivide>
                   "-DARGS=${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/x.obj;--levels;12;--max-memory;1e9"
                   -DNAME=subdivide
                   "-DEXPECT=subdividing 12 levels would need about [0-9.]+ GB of memory, more than the limit of 1 GB"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/mesh_info_expect_failure.cmake)
  add_test(NAME example.subdivide.over_a_given_limit
           COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:subdivide>
                   "-DARGS=${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/x.obj;--levels;2;--max-memory;1000"
                   -DNAME=subdivide "-DEXPECT=subdividing 2 levels would need about" -P ${CMAKE_CURRENT_SOURCE_DIR}/mesh_info_expect_failure.cmake)
  add_test(NAME example.subdivide.doo_sabin_over_a_given_limit
           COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:subdivide>
                   "-DARGS=${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/x.obj;--scheme;doo-sabin;--levels;10;--max-memory;2e8;--drop-corner-data"
                   -DNAME=subdivide "-DEXPECT=subdividing 10 levels would need about [0-9.]+ GB of memory, more than the limit of 0.2 GB"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/mesh_info_expect_failure.cmake)
  # Texture coordinates and normals (OBJ vt/vn) go through: the cube's uv net
  # is a disc of 14 values, 6 quads and 19 edges (its 7 seam edges cut open,
  # the other 5 folds); two quad splits (V' = V + E + F, E' = 2E + 4F) give
  # 125 values and 4 * 7 = 28 seam edges. Its normals are 6 quads apart: 150
  # values, all 48 edges seams. mesh_info reads them back from the file.
  set(_cube_channels "\"corner_channels\":\\[\\{\"name\":\"c:uv\",\"values\":125,\"seam_edges\":28,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\},\\{\"name\":\"c:normal\",\"values\":150,\"seam_edges\":48,\"corners_without_value\":0,\"mobius_edges_continuous\":0,\"mobius_edges_seamed\":0\\}\\]")
  add_test(NAME example.subdivide.corner_data_obj_to_obj
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:subdivide> -DMESH_INFO=$<TARGET_FILE:mesh_info>
                   "-DARGS=${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/cube_uv.obj;--levels;2"
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cube_uv.obj "-DEXPECT=${_cube_channels}"
                   "-DEXPECT_INFO=\"faces\":96,.*${_cube_channels}" -DVT=125
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/corner_data_tool.cmake)
  # PLY holds a value per vertex: the cube's seams are refused before the
  # work, or left out with --drop-corner-data, which the line reports.
  add_test(NAME example.subdivide.corner_data_seams_not_in_ply
           COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:subdivide>
                   "-DARGS=${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/cube_uv.ply;--levels;2"
                   -DNAME=subdivide
                   "-DEXPECT=corner channels \\(c:uv, c:normal\\) cannot be carried: .*has a seam at vertex.*--drop-corner-data goes on without them"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/mesh_info_expect_failure.cmake)
  add_test(NAME example.subdivide.corner_data_dropped_for_ply
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/cube_dropped.ply
                   --levels 2 --drop-corner-data)
  set_tests_properties(example.subdivide.corner_data_dropped_for_ply PROPERTIES PASS_REGULAR_EXPRESSION
    "\"faces\":96,.*\"corner_channels\":\\[\\],\"corner_channels_dropped\":\\[\"c:uv\",\"c:normal\"\\]")
  add_test(NAME example.subdivide.corner_data_not_through_doo_sabin
           COMMAND ${CMAKE_COMMAND} -DMESH_INFO=$<TARGET_FILE:subdivide>
                   "-DARGS=${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/x.obj;--scheme;doo-sabin"
                   -DNAME=subdivide "-DEXPECT=doo-sabin and sqrt3 do not carry them"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/mesh_info_expect_failure.cmake)
  # A bad value of an enumerated option names the accepted ones.
  cgal_ext_tool_fails(example.subdivide.bad_scheme subdivide
    "${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/x.obj;--scheme;butterfly"
    "^subdivide: --scheme 'butterfly' is not catmull-clark, loop, linear, doo-sabin or sqrt3; usage: subdivide [^\n]+\n$")
  # --fvar-interpolation: the cube's uv net (14 values: a column of four
  # squares 1/4 wide from (0.375, 0) to (0.625, 1), a square on each side of
  # the lowest) has 6 faces and 19 edges, so one step makes 14 + 19 + 6 = 39
  # values in every mode. With 'all' they are bilinear: the input's values
  # kept (vt 3, (0.375, 0.25)), face centres (face 1: the mean of (0.375, 0),
  # (0.625, 0), (0.625, 0.25), (0.375, 0.25) is (0.5, 0.125)) and edge
  # midpoints (vt 2 (0.625, 0) and vt 11 (0.875, 0): (0.75, 0)). With the
  # default, corners-plus1, (0.375, 0.25), where the net's border turns
  # between (0.125, 0.25) and (0.375, 0.5), follows OpenSubdiv's smooth
  # border rule: 3/4 (0.375, 0.25) + 1/8 (0.125, 0.25) + 1/8 (0.375, 0.5)
  # = (0.34375, 0.28125).
  # One step of the cube with FLAGS (after IN OUT): 39 vt lines, among them
  # each of PRESENT and none of ABSENT (lists of lines).
  function(cgal_ext_subdivide_vt name flags present absent)
    set(_written ${CMAKE_CURRENT_BINARY_DIR}/cube_${name}.obj)
    add_test(NAME example.subdivide.${name}
             COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:subdivide>
                     "-DARGS=${_data}/opensubdiv/catmark_cube.obj;${_written};${flags}" -DOUT=${_written}
                     "-DPRESENT=${present}" "-DABSENT=${absent}" "-DCOUNT_REGEX=^vt " -DCOUNT=39
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_output_lines.cmake)
  endfunction()
  cgal_ext_subdivide_vt(fvar_all_is_bilinear "--fvar-interpolation;all"
                        "vt 0.375 0.25;vt 0.5 0.125;vt 0.75 0" "vt 0.34375 0.28125")
  cgal_ext_subdivide_vt(fvar_default_smooths_borders "--levels;1"
                        "vt 0.34375 0.28125;vt 0.5 0.125;vt 0.75 0" "vt 0.375 0.25")
  # The default is corners-plus1, as OpenSubdiv's; 'boundaries' keeps the
  # net's border linear, so it differs from it there.
  set(_o ${CMAKE_CURRENT_BINARY_DIR}/cube_fvar)
  add_test(NAME example.subdivide.fvar_default_is_corners_plus1
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:subdivide>
                   "-DFIRST=${_data}/opensubdiv/catmark_cube.obj;${_o}_implicit.obj" -DFIRST_OUT=${_o}_implicit.obj
                   "-DSECOND=${_data}/opensubdiv/catmark_cube.obj;${_o}_plus1.obj;--fvar-interpolation;corners-plus1"
                   -DSECOND_OUT=${_o}_plus1.obj
                   "-DDIFFERENT=${_data}/opensubdiv/catmark_cube.obj;${_o}_boundaries.obj;--fvar-interpolation;boundaries"
                   -DDIFFERENT_OUT=${_o}_boundaries.obj -P ${CMAKE_CURRENT_SOURCE_DIR}/same_output.cmake)
  add_test(NAME example.subdivide.fvar_in_json_line
           COMMAND subdivide ${_data}/opensubdiv/catmark_cube.obj ${CMAKE_CURRENT_BINARY_DIR}/x.obj --fvar-interpolation corners-plus2)
  set_tests_properties(example.subdivide.fvar_in_json_line PROPERTIES
    PASS_REGULAR_EXPRESSION "\"levels\":1,\"fvar_interpolation\":\"corners-plus2\",")
  cgal_ext_tool_fails(example.subdivide.bad_fvar_interpolation subdivide
    "${_data}/opensubdiv/catmark_cube.obj;${CMAKE_CURRENT_BINARY_DIR}/x.obj;--fvar-interpolation;corners_plus1"
    "^subdivide: --fvar-interpolation 'corners_plus1' is not none, corners-only, corners-plus1, corners-plus2, boundaries or all; usage: subdivide [^\n]+\n$")
  # --no-tags: the input's tag and the flag's option are not written.
  add_test(NAME example.subdivide.no_tags
           COMMAND ${CMAKE_COMMAND} -DSUBDIVIDE=$<TARGET_FILE:subdivide>
                   -DIN=${_data}/opensubdiv/catmark_edgecorner.obj -DOUT=${CMAKE_CURRENT_BINARY_DIR}/edgecorner_no_tags.obj
                   "-DARGS=--crease-method;chaikin;--no-tags" -P ${_tags_script})
  set_tests_properties(example.subdivide.sqrt3_on_quads example.subdivide.bad_option
                       example.subdivide.loop_on_quads PROPERTIES WILL_FAIL TRUE)
endif()
