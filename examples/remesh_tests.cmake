# CTest tests of the remesh tool (included from examples/CMakeLists.txt).
# Remeshing keeps what makes a surface what it is: the Euler characteristic,
# the number of border loops and orientability, taken from each file's first
# line; the output is valid and most of its edges are in the band
# [4/5 L, 4/3 L] (at least 90 %).
if(NOT CGAL_EXT_BUILD_TESTS)
  return()
endif()

set(_data ${PROJECT_SOURCE_DIR}/test/data/nonorientable)
set(_out ${CMAKE_CURRENT_BINARY_DIR}/tool_output)
file(MAKE_DIRECTORY ${_out})

# File and target edge length (half the file's mean edge length or more).
foreach(_case "mobius_20x4_tris;0.18" "klein_fig8_24x12_quads;0.45" "torus_24x12_quads;0.3"
              "boys_surface_quads;0.3")
  list(GET _case 0 _name)
  list(GET _case 1 _length)
  cgal_ext_stated_topology(${_data}/${_name}.obj)
  add_test(NAME remesh.${_name}
           COMMAND remesh ${_data}/${_name}.obj ${_out}/remesh_${_name}.obj --edge-length ${_length} --iterations 5)
  set_tests_properties(remesh.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "\"border_loops\":${_border_loops},\"orientable\":${_orientable},\"closed\":[a-z]+,\"components\":1,\"euler_characteristic\":${_chi},\"valid\":true,\"in_band\":(0\\.9|1[,.])")
endforeach()

# With --project-to-limit the strip, taken as a cage, is remeshed onto its Catmull-Clark limit
# surface: still one non-orientable strip, vertices and face centroids within 0.01 of it (on
# the cage's faces they would be up to 0.1 away; test_remeshing.cpp measures both).
add_test(NAME remesh.project_to_limit
         COMMAND remesh ${_data}/mobius_20x4_tris.obj ${_out}/remesh_limit.obj --edge-length 0.1 --iterations 3
                 --project-to-limit)
set_tests_properties(remesh.project_to_limit PROPERTIES PASS_REGULAR_EXPRESSION
  "\"border_loops\":1,\"orientable\":false,\"closed\":false,\"components\":1,\"euler_characteristic\":0,\"valid\":true.*\"limit_distance\":(0\\.00[0-9]+|[0-9.]+e-0[3-9])}")

# With --protect-borders the Möbius strip's border keeps its 40 vertices and edges.
add_test(NAME remesh.protected_border
         COMMAND remesh ${_data}/mobius_20x4_tris.obj ${_out}/remesh_protected.obj --edge-length 0.15 --protect-borders)
set_tests_properties(remesh.protected_border PROPERTIES PASS_REGULAR_EXPRESSION
  "\"border_loops\":1,\"orientable\":false,\"closed\":false,\"components\":1,\"euler_characteristic\":0,\"valid\":true")

# With --relax-constraints as well, the border slides along itself and stays one loop of a
# non-orientable strip.
add_test(NAME remesh.relaxed_protected_border
         COMMAND remesh ${_data}/mobius_20x4_tris.obj ${_out}/remesh_relaxed.obj --edge-length 0.15 --protect-borders
                 --relax-constraints --iterations 3)
set_tests_properties(remesh.relaxed_protected_border PROPERTIES PASS_REGULAR_EXPRESSION
  "\"border_loops\":1,\"orientable\":false,\"closed\":false,\"components\":1,\"euler_characteristic\":0,\"valid\":true")

# A missing file, a length that is not positive, iterations out of range: one line, exit 2.
cgal_ext_tool_fails(remesh.fails.missing_file remesh
  "${_out}/no_such.obj;${_out}/x.obj;--edge-length;1"
  "^remesh: [^\n]+\n$")
cgal_ext_tool_fails(remesh.fails.negative_length remesh
  "${_data}/mobius_20x4_tris.obj;${_out}/x.obj;--edge-length;-1"
  "^remesh: --edge-length '-1' is not positive; usage: [^\n]+\n$")
cgal_ext_tool_fails(remesh.fails.iterations remesh
  "${_data}/mobius_20x4_tris.obj;${_out}/x.obj;--edge-length;1;--iterations;0"
  "^remesh: --iterations '0' is not an integer from 1 to 1000; usage: [^\n]+\n$")

# A length whose result would not fit the mesh's indices, and one whose
# estimated peak is above --max-memory: refused up front, one line, exit 2.
cgal_ext_tool_fails(remesh.fails.too_fine remesh
  "${_data}/mobius_20x4_tris.obj;${_out}/x.obj;--edge-length;1e-6"
  "^remesh: isotropic_remeshing to edge length 1e-06 would make [0-9]+ edges, [^\n]+\n$")
cgal_ext_tool_fails(remesh.fails.max_memory remesh
  "${_data}/mobius_20x4_tris.obj;${_out}/x.obj;--edge-length;0.01;--max-memory;1e6"
  "^remesh: isotropic_remeshing to edge length 0.01 would need about [0-9.e+-]+ GB of memory, [^\n]+\n$")

# A needle, one triangle 1000 long and 1e-6 wide, at L = 0.08: narrower than
# any triangle of the band, it ends as a strip across it in bounded work (at
# least one triangle per 4/3 L of its length, 9 375, and at most two per
# piece of its longest side cut in 2^14: 32 768), in fewer iterations than
# asked, with the needle reported. With --refuse-narrow: one line naming the
# face and its width, exit 2.
set(_needle ${PROJECT_SOURCE_DIR}/test/data/tools/needle_1000x1e-6.obj)
add_test(NAME remesh.needle
         COMMAND remesh ${_needle} ${_out}/remesh_needle.obj --edge-length 0.08 --iterations 5 --max-memory 1e8)
set_tests_properties(remesh.needle PROPERTIES PASS_REGULAR_EXPRESSION
  "\"faces\":(937[5-9]|93[89][0-9]|9[4-9][0-9][0-9]|[12][0-9][0-9][0-9][0-9]|3[01][0-9][0-9][0-9]|32[0-6][0-9][0-9]|327[0-5][0-9]|3276[0-8]),\"border_loops\":1,.*\"valid\":true,.*\"iterations\":[1-4],\"stopped_early\":true,\"narrow_faces\":1,\"narrowest_width\":1e-06,")
cgal_ext_tool_fails(remesh.fails.narrow remesh
  "${_needle};${_out}/x.obj;--edge-length;0.01;--refuse-narrow"
  "^remesh: isotropic_remeshing: face f0 is 1e-06 wide and 1000 long, [^\n]+\n$")
