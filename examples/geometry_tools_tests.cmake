# CTest tests of the geometry tools, geodesics, curvature, fill_holes and
# smooth (included from examples/CMakeLists.txt). Each figure is checked
# against a reference the tool does not compute: a closed form, the topology a
# test mesh states on its first line (Gauss-Bonnet, the Euler characteristic
# of a capped surface), or the same figure on the orientation double cover
# that the offset tool builds. close_numbers compares real numbers, which
# CMake's scripts cannot.
if(NOT CGAL_EXT_BUILD_TESTS)
  return()
endif()

add_executable(close_numbers ${PROJECT_SOURCE_DIR}/test/close_numbers.cpp)
target_link_libraries(close_numbers PRIVATE cgal_ext_warnings)

set(_data ${PROJECT_SOURCE_DIR}/test/data/nonorientable)
set(_tools ${PROJECT_SOURCE_DIR}/test/data/tools)
set(_out ${CMAKE_CURRENT_BINARY_DIR}/tool_output)
file(MAKE_DIRECTORY ${_out})

# cgal_ext_compare_figures(NAME RUN tool args... FIELD f [PATTERN regex] [STDOUT regex] TOLERANCE t
#                          (EXPECTED x | OTHER_FIELD g | [BETWEEN tool args...] REFERENCE tool args...))
# A test that runs compare_figures.cmake: RUN's figure FIELD (or PATTERN's
# first group) within the relative TOLERANCE of EXPECTED, of the field g of
# its own line, or of the same field of REFERENCE's line (BETWEEN runs first).
function(cgal_ext_compare_figures name)
  cmake_parse_arguments(ARG "" "FIELD;PATTERN;REFERENCE_PATTERN;STDOUT;TOLERANCE;EXPECTED;OTHER_FIELD" "RUN;BETWEEN;REFERENCE" ${ARGN})
  set(defines -DFIELD=${ARG_FIELD} -DTOLERANCE=${ARG_TOLERANCE} -DCLOSE=$<TARGET_FILE:close_numbers>)
  foreach(key RUN BETWEEN REFERENCE PATTERN REFERENCE_PATTERN STDOUT EXPECTED OTHER_FIELD)
    if(DEFINED ARG_${key})
      string(REPLACE ";" "\\;" value "${ARG_${key}}") # a command stays one argument
      list(APPEND defines "-D${key}=${value}")
    endif()
  endforeach()
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} ${defines} -P ${PROJECT_SOURCE_DIR}/examples/compare_figures.cmake)
endfunction()

set(_geodesics $<TARGET_FILE:geodesics>)

# ------------------------------------------------------------------ geodesics

# The hemi-icosahedron (a projective plane, one-sided) joins each vertex to
# the five others by a straight edge, so the exact distance to each is that
# edge's length: an icosahedron's edge, or the chord between two of its
# vertices that are neighbours' antipodes, 2 sin(θ/2) with cos θ = -1/√5:
# √(2 + 2/√5) = 1.7013016167, the largest from vertex 0. The heat method
# approximates it on this coarsest mesh within 2 %. (The tools print six
# significant digits: 1e-5 is as close as a figure can be checked.)
cgal_ext_compare_figures(geodesics.rp2_exact_closed_form
  RUN ${_geodesics} ${_data}/rp2_hemi_icosahedron.obj ${_out}/geodesics_rp2_exact.ply --source 0 --method exact
  STDOUT "\"closed\":true,.*\"distance_at_sources\":0,"
  FIELD max_distance EXPECTED 1.7013016167 TOLERANCE 1e-5)
cgal_ext_compare_figures(geodesics.rp2_heat_closed_form
  RUN ${_geodesics} ${_data}/rp2_hemi_icosahedron.obj ${_out}/geodesics_rp2_heat.ply --source 0
  FIELD max_distance EXPECTED 1.7013016167 TOLERANCE 0.02)
cgal_ext_compare_figures(geodesics.rp2_heat_intrinsic_closed_form
  RUN ${_geodesics} ${_data}/rp2_hemi_icosahedron.obj ${_out}/geodesics_rp2_heat_intrinsic.ply --source 0
      --method heat-intrinsic
  STDOUT "\"method\":\"heat-intrinsic\","
  FIELD max_distance EXPECTED 1.7013016167 TOLERANCE 0.02)

# A flat convex rectangle, 2 x 1: the geodesic from a corner is the segment,
# and the farthest vertex the opposite corner, at √5. The heat method within 3 %.
cgal_ext_compare_figures(geodesics.flat_rectangle_exact_closed_form
  RUN ${_geodesics} ${_tools}/flat_rectangle_16x8_tris.obj ${_out}/geodesics_rectangle_exact.ply --source 0
      --method exact
  STDOUT "\"distance_at_sources\":0,.*\"farthest_vertex\":152,"
  FIELD max_distance EXPECTED 2.2360679775 TOLERANCE 1e-5)
cgal_ext_compare_figures(geodesics.flat_rectangle_heat_closed_form
  RUN ${_geodesics} ${_tools}/flat_rectangle_16x8_tris.obj ${_out}/geodesics_rectangle_heat.ply --source 0
  STDOUT "\"farthest_vertex\":152,"
  FIELD max_distance EXPECTED 2.2360679775 TOLERANCE 0.03)

# The Klein bottle against its orientation double cover: `offset --solid`
# by 1e-5 makes the cover of the triangulated bottle (written by the first
# run), an orientable mesh on which CGAL runs directly, and the distance
# from both lifts of the source is the bottle's, up to the offset. The lifts
# of vertex 0 are the cover's vertices 0 and 5 (offset numbers the cover's
# vertices in the order its faces first use them); were they not, the cover's
# largest distance would be some 70 % larger.
foreach(_method exact heat heat-intrinsic)
  cgal_ext_compare_figures(geodesics.klein_${_method}_equals_double_cover
    RUN ${_geodesics} ${_data}/klein_fig8_24x12_quads.obj ${_out}/geodesics_klein_${_method}.ply --source 0
        --method ${_method} --triangulate
    STDOUT "\"orientable\":false,\"closed\":true,.*\"triangulated_faces\":288,.*\"distance_at_sources\":0,"
    BETWEEN $<TARGET_FILE:offset> ${_out}/geodesics_klein_${_method}.ply ${_out}/geodesics_klein_cover_${_method}.ply
            --distance 1e-5 --solid
    REFERENCE ${_geodesics} ${_out}/geodesics_klein_cover_${_method}.ply ${_out}/geodesics_klein_cover_${_method}_d.ply
              --source 0,5 --method ${_method}
    FIELD max_distance TOLERANCE 1e-4)
endforeach()

cgal_ext_tool_fails(geodesics.fails.source_out_of_range geodesics
  "${_data}/mobius_20x4_tris.obj;${_out}/x.ply;--source;3,100"
  "^geodesics: --source '100' is not an integer from 0 to 99; usage: [^\n]+\n$")
cgal_ext_tool_fails(geodesics.fails.not_triangles geodesics
  "${_data}/klein_fig8_24x12_quads.obj;${_out}/x.ply;--source;0"
  "^geodesics: [^\n]*klein_fig8_24x12_quads.obj: 288 of its 288 faces are not triangles, and the geodesic distance needs a triangle mesh \\(give --triangulate\\)\n$")
cgal_ext_tool_fails(geodesics.fails.heat_vertex_on_no_face geodesics
  "${_tools}/triangle_two_stray_vertices.obj;${_out}/x.ply;--source;0"
  "^geodesics: [^\n]*triangle_two_stray_vertices.obj: vertex 3 is on no face, and the heat method needs every vertex on one \\(--method exact takes it\\)\n$")
cgal_ext_tool_fails(geodesics.fails.method geodesics
  "${_data}/mobius_20x4_tris.obj;${_out}/x.ply;--source;0;--method;dijkstra"
  "^geodesics: --method 'dijkstra' is not heat, heat-intrinsic or exact; usage: [^\n]+\n$")
cgal_ext_tool_fails(geodesics.fails.not_ply geodesics
  "${_data}/mobius_20x4_tris.obj;${_out}/x.obj;--source;0"
  "^geodesics: OUT '[^']*x.obj' is not a .ply file[^\n]*; usage: [^\n]+\n$")

# ------------------------------------------------------------------ curvature

# Gauss-Bonnet: the angle defects sum to 2π times the Euler characteristic the
# file states, one-sided surfaces and surfaces with a border included. The
# signed mean and principal curvatures are seen from a side chosen per
# vertex, which is a choice only at vertices on a Möbius edge: none on an
# orientable surface (files are read oriented), some on a one-sided one.
file(GLOB _files ${_data}/*.obj)
foreach(_file ${_files})
  get_filename_component(_name ${_file} NAME_WE)
  cgal_ext_stated_topology(${_file})
  if(_chi EQUAL 0)
    set(_total "-?(0|[0-9.]+e-1[0-9])") # below 1e-10
  elseif(_chi EQUAL 1)
    set(_total "6\\.28319")
  elseif(_chi EQUAL 2)
    set(_total "12\\.5664")
  else()
    message(FATAL_ERROR "${_file}: no expected total for chi ${_chi}")
  endif()
  if(_orientable)
    set(_on_mobius_edges "0")
  else()
    set(_on_mobius_edges "[1-9][0-9]*")
  endif()
  set(_range "\\[[^]]+\\]")
  add_test(NAME curvature.gauss_bonnet.${_name}
    COMMAND curvature ${_file} ${_out}/curvature_${_name}.ply --triangulate)
  set_tests_properties(curvature.gauss_bonnet.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "\"orientable\":${_orientable},.*\"euler_characteristic\":${_chi},\"valid\":true,.*\"total_angle_defect\":${_total},.*\"vertices_on_mobius_edges\":${_on_mobius_edges},\"max_curvature\":${_range},\"min_curvature\":${_range},\"mean_curvature\":${_range}}")
endforeach()

# The torus (R = 2, r = 0.7, 24 x 12 quads, triangulated): its mean curvature
# for the outward normal, (R + 2 r cos θ) / (2 r (R + r cos θ)), is 0.8994709
# on the outer equator and 0.3296703 on the inner one, within 2 % on this mesh.
cgal_ext_compare_figures(curvature.torus_mean_curvature_outer
  RUN $<TARGET_FILE:curvature> ${_data}/torus_24x12_quads.obj ${_out}/curvature_torus_outer.ply --triangulate
  FIELD mean_curvature PATTERN "\"mean_curvature\":.[^,]+,([-0-9.e]+)" EXPECTED 0.8994709 TOLERANCE 0.02)
cgal_ext_compare_figures(curvature.torus_mean_curvature_inner
  RUN $<TARGET_FILE:curvature> ${_data}/torus_24x12_quads.obj ${_out}/curvature_torus_inner.ply --triangulate
  FIELD mean_curvature PATTERN "\"mean_curvature\":.([-0-9.e]+)," EXPECTED 0.3296703 TOLERANCE 0.02)
# Its principal curvatures, on a finer torus of the same shape (64 x 32 quads,
# triangulated: a jet fitted over two rings of the coarse one spans a third of
# the tube and overshoots k1 by 45 %): k1 = 1 / r = 1.4285714 everywhere (its
# smallest and largest values checked, within 6 %), k2 = cos θ / (R + r cos θ),
# from -0.7692308 on the inner equator to 0.3703704 on the outer one (3 %).
set(_fine_torus ${PROJECT_SOURCE_DIR}/test/data/tools/torus_64x32_quads.obj)
cgal_ext_compare_figures(curvature.torus_max_curvature_low
  RUN $<TARGET_FILE:curvature> ${_fine_torus} ${_out}/curvature_torus_k1_low.ply --triangulate
  FIELD max_curvature PATTERN "\"max_curvature\":.([-0-9.e]+)," EXPECTED 1.4285714 TOLERANCE 0.06)
cgal_ext_compare_figures(curvature.torus_max_curvature_high
  RUN $<TARGET_FILE:curvature> ${_fine_torus} ${_out}/curvature_torus_k1_high.ply --triangulate
  FIELD max_curvature PATTERN "\"max_curvature\":.[^,]+,([-0-9.e]+)" EXPECTED 1.4285714 TOLERANCE 0.06)
cgal_ext_compare_figures(curvature.torus_min_curvature_inner
  RUN $<TARGET_FILE:curvature> ${_fine_torus} ${_out}/curvature_torus_k2_inner.ply --triangulate
  FIELD min_curvature PATTERN "\"min_curvature\":.([-0-9.e]+)," EXPECTED -0.7692308 TOLERANCE 0.03)
cgal_ext_compare_figures(curvature.torus_min_curvature_outer
  RUN $<TARGET_FILE:curvature> ${_fine_torus} ${_out}/curvature_torus_k2_outer.ply --triangulate
  FIELD min_curvature PATTERN "\"min_curvature\":.[^,]+,([-0-9.e]+)" EXPECTED 0.3703704 TOLERANCE 0.03)

cgal_ext_tool_fails(curvature.fails.not_triangles curvature
  "${_data}/torus_24x12_quads.obj;${_out}/x.ply"
  "^curvature: [^\n]*torus_24x12_quads.obj: 288 of its 288 faces are not triangles, and the mean curvature needs a triangle mesh \\(give --triangulate\\)\n$")
cgal_ext_tool_fails(curvature.fails.missing_file curvature
  "${_out}/no_such.obj;${_out}/x.ply"
  "^curvature: [^\n]*no_such.obj[^\n]*\n$")

# ----------------------------------------------------------------- fill_holes

# Each filled hole adds a disk: the Euler characteristic grows by the number
# of border loops the file states, and the result is closed. A Möbius strip
# capped is a projective plane (χ = 1, one-sided); the flat rectangle and the
# pentagon, discs, become spheres (χ = 2).
foreach(_case "${_data}/mobius_20x4_tris.obj;fair" "${_data}/mobius_20x4_quads.obj;fair;--triangulate"
              "${_data}/mobius_20x4_quads.obj;refine;--triangulate" "${_data}/mobius_20x4_quads.obj;triangulate"
              "${_tools}/flat_rectangle_16x8_tris.obj;fair" "${_tools}/pentagon.obj;fair;--triangulate")
  list(GET _case 0 _file)
  list(GET _case 1 _fill)
  set(_flags)
  list(LENGTH _case _length)
  if(_length GREATER 2)
    list(GET _case 2 _flags)
  endif()
  get_filename_component(_name ${_file} NAME_WE)
  if(_name STREQUAL "pentagon")
    set(_chi 1)
    set(_orientable true)
    set(_border_loops 1)
  else()
    cgal_ext_stated_topology(${_file})
  endif()
  math(EXPR _chi "${_chi} + ${_border_loops}")
  add_test(NAME fill_holes.${_name}.${_fill} COMMAND fill_holes ${_file} ${_out}/fill_holes_${_name}_${_fill}.obj
                                                     --fill ${_fill} ${_flags})
  set_tests_properties(fill_holes.${_name}.${_fill} PROPERTIES PASS_REGULAR_EXPRESSION
    "\"border_loops\":0,[^}]*\"orientable\":${_orientable},\"closed\":true,\"components\":1,\"euler_characteristic\":${_chi},\"valid\":true,[^}]*\"holes\":${_border_loops},\"filled\":${_border_loops},")
endforeach()

# The smallest Möbius strip joins each of its five vertices to the four
# others: every diagonal of its border loop is an edge already, so no
# triangulation of the hole exists and it stays open. A closed surface has
# no hole, whatever its faces.
add_test(NAME fill_holes.mobius_min_5tris.no_triangulation
  COMMAND fill_holes ${_data}/mobius_min_5tris.obj ${_out}/fill_holes_mobius_min.obj)
set_tests_properties(fill_holes.mobius_min_5tris.no_triangulation PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":5,\"edges\":10,\"faces\":5,\"border_loops\":1,.*\"holes\":1,\"filled\":0,")
add_test(NAME fill_holes.klein.closed COMMAND fill_holes ${_data}/klein_fig8_24x12_quads.obj ${_out}/fill_holes_klein.obj)
set_tests_properties(fill_holes.klein.closed PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":288,\"edges\":576,\"faces\":288,.*\"holes\":0,\"filled\":0,")
cgal_ext_tool_fails(fill_holes.fails.not_triangles fill_holes
  "${_data}/mobius_20x4_quads.obj;${_out}/x.obj"
  "^fill_holes: [^\n]*mobius_20x4_quads.obj: 80 of its 80 faces are not triangles, and refining and fairing a hole needs a triangle mesh \\(give --triangulate\\)\n$")

# --------------------------------------------------------------------- smooth

# The flow moves vertices only: the counts the file states (quads split in
# two by --triangulate: one more edge and face each), χ and orientability stay.
foreach(_file ${_files})
  get_filename_component(_name ${_file} NAME_WE)
  cgal_ext_stated_topology(${_file})
  file(STRINGS ${_file} _header LIMIT_COUNT 1)
  string(REGEX MATCH "V=([0-9]+) E=([0-9]+) F=([0-9]+)" _counts "${_header}")
  set(_v ${CMAKE_MATCH_1})
  set(_e ${CMAKE_MATCH_2})
  set(_f ${CMAKE_MATCH_3})
  if(_name MATCHES "quads")
    math(EXPR _e "${_e} + ${_f}")
    math(EXPR _f "2 * ${_f}")
  endif()
  add_test(NAME smooth.keeps_counts.${_name}
    COMMAND smooth ${_file} ${_out}/smooth_${_name}.obj --iterations 3 --triangulate)
  set_tests_properties(smooth.keeps_counts.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "^{\"vertices\":${_v},\"edges\":${_e},\"faces\":${_f},\"border_loops\":${_border_loops},[^}]*\"orientable\":${_orientable},[^}]*\"euler_characteristic\":${_chi},\"valid\":true,")
endforeach()

# A closed one-sided surface bounds no volume: it is rescaled to keep its area.
foreach(_name klein_fig8_24x12_quads boys_surface_quads)
  cgal_ext_compare_figures(smooth.keeps_area.${_name}
    RUN $<TARGET_FILE:smooth> ${_data}/${_name}.obj ${_out}/smooth_area_${_name}.obj --iterations 5 --time 1e-3
        --triangulate
    STDOUT "\"orientable\":false,\"closed\":true,"
    FIELD area_after OTHER_FIELD area_before TOLERANCE 1e-5)
endforeach()

cgal_ext_tool_fails(smooth.fails.not_triangles smooth
  "${_data}/boys_surface_quads.obj;${_out}/x.obj"
  "^smooth: [^\n]*boys_surface_quads.obj: 108 of its 108 faces are not triangles, and smoothing needs a triangle mesh \\(give --triangulate\\)\n$")
cgal_ext_tool_fails(smooth.fails.iterations smooth
  "${_data}/mobius_20x4_tris.obj;${_out}/x.obj;--iterations;-1"
  "^smooth: --iterations '-1' is not an integer from 0 to 1000000; usage: [^\n]+\n$")
