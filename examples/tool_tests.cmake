# cgal_ext_tool_fails(NAME TOOL ARGS STDERR): a CTest test that runs TOOL
# with ARGS (a ;-list) and passes if it exits with status 2, prints nothing
# on stdout and one line matching the regex STDERR on stderr, as every tool
# does for a bad file or argument (check_tool.cmake checks the streams apart).
function(cgal_ext_tool_fails name tool args stderr)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${tool}> "-DARGS=${args}" -DSTATUS=2 "-DSTDERR=${stderr}"
            -P ${PROJECT_SOURCE_DIR}/examples/check_tool.cmake)
endfunction()

# Every tool that writes a mesh, through data_loss.cmake: a failed write, an
# output that is the input, and a tool killed part way lose no file.
if(CGAL_EXT_BUILD_TESTS)
  set(_torus ${PROJECT_SOURCE_DIR}/test/data/nonorientable/torus_24x12_quads.obj)
  set(_data_loss_convert "@IN@;@OUT@")
  set(_data_loss_subdivide "@IN@;@OUT@;--levels;2")
  set(_data_loss_merge "@IN@;${_torus};@OUT@")
  set(_data_loss_offset "@IN@;@OUT@;--distance;0.05")
  set(_data_loss_remesh "@IN@;@OUT@;--edge-length;0.4")
  set(_data_loss_decimate "@IN@;@OUT@;--ratio;0.5;--no-hausdorff")
  set(_data_loss_custom_mask "@OUT@;--levels;2")
  file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/data_loss)
  foreach(_tool convert subdivide merge offset remesh decimate custom_mask)
    add_test(NAME data_loss.${_tool}
      COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${_tool}> "-DARGS=${_data_loss_${_tool}}" -DINPUT=${_torus}
              -DOUT=${CMAKE_CURRENT_BINARY_DIR}/data_loss/${_tool}.obj -P ${PROJECT_SOURCE_DIR}/examples/data_loss.cmake)
  endforeach()
endif()

# Decimate, remesh and offset go on without texture coordinates and normals
# with --drop-corner-data, which they report; remesh carries them otherwise,
# every face of a UV-mapped Möbius strip written with its corners' values.
if(CGAL_EXT_BUILD_TESTS)
  set(_cube ${PROJECT_SOURCE_DIR}/test/data/opensubdiv/catmark_cube.obj)
  set(_corner_out ${CMAKE_CURRENT_BINARY_DIR}/tool_output)
  file(MAKE_DIRECTORY ${_corner_out})
  set(_corner_decimate "--ratio;0.5;--no-hausdorff")
  set(_corner_remesh "--edge-length;0.5")
  set(_corner_offset "--distance;0.1")
  foreach(_tool decimate remesh offset)
    add_test(NAME ${_tool}.corner_channels_dropped
      COMMAND ${_tool} ${_cube} ${_corner_out}/corner_${_tool}.obj ${_corner_${_tool}} --drop-corner-data)
    set_tests_properties(${_tool}.corner_channels_dropped PROPERTIES PASS_REGULAR_EXPRESSION
      "\"corner_channels_dropped\":\\[\"c:uv\",\"c:normal\"\\]}\n$")
  endforeach()
  set(_strip_uv ${PROJECT_SOURCE_DIR}/test/data/uv/mobius_12x2_uv.obj)
  add_test(NAME remesh.corner_channels_carried
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:remesh>
            "-DARGS=${_strip_uv};${_corner_out}/remesh_uv.obj;--edge-length;0.2;--iterations;3"
            -DOUT=${_corner_out}/remesh_uv.obj "-DCOUNT_REGEX=^f [0-9]+/[0-9]+ [0-9]+/[0-9]+ [0-9]+/[0-9]+$" -DMIN_COUNT=100
            -P ${PROJECT_SOURCE_DIR}/examples/expect_output_lines.cmake)
  add_test(NAME remesh.corner_values_interpolated
    COMMAND remesh ${_strip_uv} ${_corner_out}/remesh_uv_json.obj --edge-length 0.2 --iterations 3)
  set_tests_properties(remesh.corner_values_interpolated PROPERTIES PASS_REGULAR_EXPRESSION
    "\"orientable\":false,.*\"corner_values_interpolated\":[1-9][0-9]*,\"seam_edges_protected\":2}\n$")

  # --no-tags: the tools whose output keeps the input's creases (OpenSubdiv's
  # cube with 12 creased edges) write them as 't crease' lines by default, and
  # no 't' line with the flag. (offset and tessellate write no sharpness.)
  set(_creased ${PROJECT_SOURCE_DIR}/test/data/opensubdiv/catmark_cube_creases1.obj)
  set(_tags_merge "${_creased};${_torus};@OUT@")
  set(_tags_remesh "${_creased};@OUT@;${_corner_remesh};--drop-corner-data")
  set(_tags_decimate "${_creased};@OUT@;${_corner_decimate};--drop-corner-data")
  foreach(_tool merge remesh decimate)
    foreach(_case tagged no_tags)
      set(_written ${_corner_out}/tags_${_tool}_${_case}.obj)
      string(REPLACE "@OUT@" "${_written}" _args "${_tags_${_tool}}")
      if(_case STREQUAL "tagged")
        set(_expect "-DCOUNT_REGEX=^t crease 2/1/0 " -DMIN_COUNT=1)
      else()
        list(APPEND _args --no-tags)
        set(_expect "-DCOUNT_REGEX=^t " -DCOUNT=0)
      endif()
      add_test(NAME ${_tool}.${_case}
        COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${_tool}> "-DARGS=${_args}" -DOUT=${_written} ${_expect}
                -P ${PROJECT_SOURCE_DIR}/examples/expect_output_lines.cmake)
    endforeach()
  endforeach()
endif()

# Examples whose size options once ended in bad_alloc: refused with one line.
if(CGAL_EXT_BUILD_TESTS)
  cgal_ext_tool_fails(example.mobius_walk.too_large mobius_walk "8000;8000"
    "^mobius_walk: 8000 x 8000 quads is more than the 1000000 this example builds; usage: [^\n]+\n$")
  cgal_ext_tool_fails(example.custom_mask.too_many_levels custom_mask "--levels;10"
    "^custom_mask: --levels '10' is not an integer from 0 to 7; usage: [^\n]+\n$")
endif()
