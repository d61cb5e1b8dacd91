# CTest tests of the offset tool (included from examples/CMakeLists.txt).
# With --solid the output is the displaced orientation double cover of the
# input closed along its border by a rim, whatever the input: a closed
# orientable surface with twice the input's Euler characteristic (the rim
# annuli add nothing), one component for a one-sided input, two (the two
# skins) for a two-sided one. Expected values come from each file's first line.
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
  math(EXPR _chi "2 * ${_chi}")
  if(_orientable)
    set(_components 2)
  else()
    set(_components 1)
  endif()
  add_test(NAME offset.${_name} COMMAND offset ${_file} ${_out}/offset_${_name}.obj --distance 0.002 --solid)
  set_tests_properties(offset.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
    "\"closed\":true,\"orientable\":true,\"components\":${_components},\"euler_characteristic\":${_chi},\"seconds\":")
endforeach()

# The hemi-icosahedron (6 vertices, 10 triangles) is covered twice by the icosahedron.
add_test(NAME offset.hemi_icosahedron_counts COMMAND offset ${_data}/rp2_hemi_icosahedron.obj
         ${_out}/offset_icosahedron.obj --distance 0.01)
set_tests_properties(offset.hemi_icosahedron_counts PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":12,\"edges\":30,\"faces\":20,\"rim_faces\":0,")

# A file that is not there, a distance that is not a number, a weighting that is none of the
# accepted ones: one line, exit 2.
cgal_ext_tool_fails(offset.fails.missing_file offset
  "${_out}/no_such.obj;${_out}/x.obj;--distance;1"
  "^offset: [^\n]+\n$")
cgal_ext_tool_fails(offset.fails.distance offset
  "${_data}/mobius_min_5tris.obj;${_out}/x.obj;--distance;-1"
  "^offset: --distance '-1' is not positive; usage: [^\n]+\n$")
cgal_ext_tool_fails(offset.fails.weighting offset
  "${_data}/mobius_min_5tris.obj;${_out}/x.obj;--distance;1;--weighting;median"
  "^offset: --weighting 'median' is not uniform, area or angle; usage: [^\n]+\n$")

# Texture coordinates are carried: the Möbius strip of 12 x 2 quads cut open
# across by one seam (test/data/uv) has a border of 24 edges, so its offset
# has 24 rim quads, whose 96 corners have none; the faces' copies keep theirs
# (the corner-by-corner check is CornerChannels.OffsetsCarryThemOnBothSides).
add_test(NAME offset.texture_coordinates COMMAND offset ${PROJECT_SOURCE_DIR}/test/data/uv/mobius_12x2_uv.obj
         ${_out}/offset_mobius_uv.obj --distance 0.01)
set_tests_properties(offset.texture_coordinates PROPERTIES PASS_REGULAR_EXPRESSION
  "^{\"vertices\":[0-9]+,\"edges\":[0-9]+,\"faces\":72,\"rim_faces\":24,.*\"corners_without_values\":96}")
