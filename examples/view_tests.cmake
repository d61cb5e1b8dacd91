# CTest tests of the view tool (included from examples/CMakeLists.txt when
# CGAL's Qt5 component is there). The pictures are taken under Xvfb and
# checked by side_colours, which counts the pixels of each side's colour: a
# one-sided surface shows both colours, the closed torus (its faces pointing
# outwards in the file) the front's only. (An open two-sided band would show
# both too: that the colours swap across Möbius edges is tested on the scene
# itself, in test_two_sided_scene.cpp.) One virtual screen at a time: xvfb-run -a
# races for display numbers when several start together.
if(NOT CGAL_EXT_BUILD_TESTS)
  return()
endif()
find_program(CGAL_EXT_XVFB_RUN xvfb-run)
if(NOT CGAL_EXT_XVFB_RUN)
  message(STATUS "xvfb-run not found: the view tool's screenshot tests are left out")
  return()
endif()
find_package(Qt5 REQUIRED COMPONENTS Gui)
add_executable(side_colours ${PROJECT_SOURCE_DIR}/test/side_colours.cpp)
target_link_libraries(side_colours PRIVATE Qt5::Gui cgal_ext_warnings)

set(_data ${PROJECT_SOURCE_DIR}/test/data/nonorientable)
set(_out ${CMAKE_CURRENT_BINARY_DIR}/tool_output)
file(MAKE_DIRECTORY ${_out})

# Qt's legacy OpenGL buffers, D-Bus and the OpenGL driver keep allocations
# to the end of the process, which the leak checker would report: leaks are
# checked by view.leaks alone.
set(_environment "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")
foreach(_case "mobius_20x4_quads;both" "klein_fig8_24x12_quads;both" "boys_surface_quads;both"
              "torus_24x12_quads;front")
  list(GET _case 0 _name)
  list(GET _case 1 _sides)
  add_test(NAME view.${_name}
    COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${CGAL_EXT_XVFB_RUN} -DVIEW=$<TARGET_FILE:view>
            -DCHECK=$<TARGET_FILE:side_colours> -DINPUT=${_data}/${_name}.obj -DPICTURE=${_out}/view_${_name}.png
            -DSIDES=${_sides} -P ${CMAKE_CURRENT_SOURCE_DIR}/view_screenshot.cmake)
  set_tests_properties(view.${_name} PROPERTIES ENVIRONMENT "${_environment}" TIMEOUT 120 RESOURCE_LOCK xvfb)
endforeach()

# The viewer frees what it and CGAL's viewer make (CGAL 5.5's shaders and
# clipping frame included): a leak whose allocation passes through either
# fails; those of Qt, D-Bus and the OpenGL driver alone are reported only.
add_test(NAME view.leaks
  COMMAND ${CGAL_EXT_XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:view> ${_data}/mobius_20x4_quads.obj
          --screenshot ${_out}/view_leaks.png --size 64x48)
set_tests_properties(view.leaks PROPERTIES
  ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1:abort_on_error=0;LSAN_OPTIONS=exitcode=0"
  PASS_REGULAR_EXPRESSION "\"screenshot\":"
  FAIL_REGULAR_EXPRESSION "CGAL_ext::|CGAL::Basic_viewer_qt|CGAL::QGLViewer|CGAL::qglviewer"
  TIMEOUT 120 RESOURCE_LOCK xvfb)

# What float alone would lose: a view direction of 1e200 (normalised by the
# library, not by OpenGL), a cube at 1e50 (drawn in a box of size 1), and a
# face of ten collinear corners beside a square (no area, no normal: its
# edges are drawn, the face is not). Each must show the front.
set(_tools ${PROJECT_SOURCE_DIR}/test/data/tools)
set(_far_direction_input ${_data}/torus_24x12_quads.obj)
set(_far_direction_args "--direction;1e200,0,0")
set(_cube_1e50_input ${_tools}/cube_1e50.obj)
set(_collinear_face_input ${_tools}/collinear_decagon_and_square.obj)
foreach(_name far_direction cube_1e50 collinear_face)
  add_test(NAME view.${_name}
    COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${CGAL_EXT_XVFB_RUN} -DVIEW=$<TARGET_FILE:view>
            -DCHECK=$<TARGET_FILE:side_colours> -DINPUT=${_${_name}_input} -DPICTURE=${_out}/view_${_name}.png
            -DSIDES=front "-DOPTIONS=${_${_name}_args}" -P ${CMAKE_CURRENT_SOURCE_DIR}/view_screenshot.cmake)
  set_tests_properties(view.${_name} PROPERTIES ENVIRONMENT "${_environment}" TIMEOUT 120 RESOURCE_LOCK xvfb)
endforeach()
# Past the range of the library's algorithms in double: one line, exit 2.
cgal_ext_tool_fails(view.fails.coordinates_beyond_range view
  "${_tools}/cube_1e155.obj;--screenshot;${_out}/x.png"
  "^view: make_two_sided_scene: vertex 1 at \\(1e\\+155, 0, 0\\) has a coordinate beyond \\+-1e\\+60[^\n]*\n$")
set_tests_properties(view.fails.coordinates_beyond_range PROPERTIES ENVIRONMENT "${_environment}")

# A scalar field on a one-sided surface: the geodesic distance on the Klein
# bottle from vertex 0, coloured from the ramp's violet (near) to its yellow
# (far), both sides alike.
add_test(NAME view.scalar.setup
  COMMAND geodesics ${_data}/klein_fig8_24x12_quads.obj ${_out}/view_klein_distance.ply --source 0 --triangulate)
set_tests_properties(view.scalar.setup PROPERTIES FIXTURES_SETUP view_scalar ENVIRONMENT "${_environment}")
add_test(NAME view.scalar.klein_distance
  COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${CGAL_EXT_XVFB_RUN} -DVIEW=$<TARGET_FILE:view>
          -DCHECK=$<TARGET_FILE:side_colours> -DINPUT=${_out}/view_klein_distance.ply
          "-DOPTIONS=--scalar;distance;--features-only" -DPICTURE=${_out}/view_klein_distance.png -DSIDES=ramp
          -P ${CMAKE_CURRENT_SOURCE_DIR}/view_screenshot.cmake)
set_tests_properties(view.scalar.klein_distance PROPERTIES FIXTURES_REQUIRED view_scalar
  ENVIRONMENT "${_environment}" TIMEOUT 120 RESOURCE_LOCK xvfb)
# A field seen from a side: the curvature tool's mean curvature, each side of
# each face coloured by the values seen from it. On the Möbius strip, seen
# from below, the picture shows both ends of the ramp, and the faces' fronts
# see both signs (the side of the faces' orientation turns over once round
# the strip). On the Klein bottle the ramp runs from -M to M, M the
# largest mean curvature over both sides of every vertex: the largest over
# the vertices of the bottle's orientation double cover (offset by 1e-5 to
# either side, as for the geodesics), to the cover's offset (within 1e-4).
add_test(NAME view.scalar.sides_setup_mobius
  COMMAND curvature ${_data}/mobius_20x4_quads.obj ${_out}/view_mobius_curvature.ply --triangulate)
add_test(NAME view.scalar.sides_setup_klein
  COMMAND curvature ${_data}/klein_fig8_24x12_quads.obj ${_out}/view_klein_curvature.ply --triangulate)
set_tests_properties(view.scalar.sides_setup_mobius view.scalar.sides_setup_klein PROPERTIES
  FIXTURES_SETUP view_sides ENVIRONMENT "${_environment}")
add_test(NAME view.scalar.mobius_mean_curvature_sides
  COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${CGAL_EXT_XVFB_RUN} -DVIEW=$<TARGET_FILE:view>
          -DCHECK=$<TARGET_FILE:side_colours> -DINPUT=${_out}/view_mobius_curvature.ply
          "-DOPTIONS=--scalar;mean_curvature;--features-only;--direction;0,0,-1"
          -DPICTURE=${_out}/view_mobius_curvature.png -DSIDES=ramp
          "-DEXPECT=\"scalar\":\"mean_curvature\",.*\"fronts\":\\[-[0-9.e]+,[0-9.e]+\\]}"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/view_screenshot.cmake)
# On the torus, oriented outwards, the front of every face sees the mean
# curvature of the outward normal, (R + 2 r cos θ) / (2 r (R + r cos θ)),
# from 0.33 (inner equator) to 0.90 (outer): the faces' fronts' means lie
# within, and the picture of the torus from outside shows the ramp's upper
# end only (the signs of the side logic).
add_test(NAME view.scalar.sides_setup_torus
  COMMAND curvature ${_data}/torus_24x12_quads.obj ${_out}/view_torus_curvature.ply --triangulate)
set_tests_properties(view.scalar.sides_setup_torus PROPERTIES FIXTURES_SETUP view_sides ENVIRONMENT "${_environment}")
add_test(NAME view.scalar.torus_mean_curvature_fronts
  COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${CGAL_EXT_XVFB_RUN} -DVIEW=$<TARGET_FILE:view>
          -DCHECK=$<TARGET_FILE:side_colours> -DINPUT=${_out}/view_torus_curvature.ply
          "-DOPTIONS=--scalar;mean_curvature" -DPICTURE=${_out}/view_torus_curvature.png -DSIDES=high
          "-DEXPECT=\"min\":-0\\.9[0-9]*,\"max\":0\\.9[0-9]*,\"fronts\":\\[0\\.3[3-9][0-9]*,0\\.(8[5-9]|9)[0-9]*\\]}"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/view_screenshot.cmake)
set_tests_properties(view.scalar.torus_mean_curvature_fronts PROPERTIES FIXTURES_REQUIRED view_sides
  ENVIRONMENT "${_environment}" TIMEOUT 120 RESOURCE_LOCK xvfb)
cgal_ext_compare_figures(view.scalar.klein_mean_curvature_equals_double_cover
  RUN ${CGAL_EXT_XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:view> ${_out}/view_klein_curvature.ply
      --scalar mean_curvature --screenshot ${_out}/view_klein_curvature.png
  FIELD max
  BETWEEN $<TARGET_FILE:offset> ${_out}/view_klein_curvature.ply ${_out}/view_klein_cover.ply --distance 1e-5 --solid
  REFERENCE $<TARGET_FILE:curvature> ${_out}/view_klein_cover.ply ${_out}/view_klein_cover_curvature.ply
  REFERENCE_PATTERN "\"mean_curvature\":\\[[^,]+,([-0-9.e]+)\\]"
  TOLERANCE 1e-4)
set_tests_properties(view.scalar.mobius_mean_curvature_sides view.scalar.klein_mean_curvature_equals_double_cover
  PROPERTIES FIXTURES_REQUIRED view_sides ENVIRONMENT "${_environment}" TIMEOUT 120 RESOURCE_LOCK xvfb)
cgal_ext_tool_fails(view.fails.scalar view
  "${_data}/mobius_20x4_quads.obj;--scalar;distance;--screenshot;${_out}/x.png"
  "^view: [^\n]*mobius_20x4_quads.obj has no vertex property 'distance' of numbers \\(it has none\\)\n$")
set_tests_properties(view.fails.scalar PROPERTIES ENVIRONMENT "${_environment}")

# Texture coordinates as a checker: a Möbius strip whose texture is cut open
# across it (test/data/uv), its faces split until each spans a quarter of a
# square. A file without vt: one line, exit 2.
add_test(NAME view.uv_checker
  COMMAND ${CMAKE_COMMAND} -DXVFB_RUN=${CGAL_EXT_XVFB_RUN} -DVIEW=$<TARGET_FILE:view>
          -DCHECK=$<TARGET_FILE:side_colours> -DINPUT=${PROJECT_SOURCE_DIR}/test/data/uv/mobius_12x2_uv.obj
          "-DOPTIONS=--uv-checker" -DPICTURE=${_out}/view_uv_checker.png -DSIDES=checker
          "-DEXPECT=\"faces\":24,\"mobius_edges\":[0-9]+,\"border_edges\":24,\"uv_checker_levels\":4,\"faces_drawn\":6144}"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/view_screenshot.cmake)
set_tests_properties(view.uv_checker PROPERTIES ENVIRONMENT "${_environment}" TIMEOUT 120 RESOURCE_LOCK xvfb)
cgal_ext_tool_fails(view.fails.uv_checker_without_vt view
  "${_data}/mobius_20x4_quads.obj;--uv-checker;--screenshot;${_out}/x.png"
  "^view: [^\n]*mobius_20x4_quads.obj has no texture coordinates \\(vt\\) for --uv-checker\n$")
set_tests_properties(view.fails.uv_checker_without_vt PROPERTIES ENVIRONMENT "${_environment}")

# No display: one line naming what is missing, exit 2, no picture.
add_test(NAME view.fails.no_display
  COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY --unset=QT_QPA_PLATFORM
          ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:view>
          "-DARGS=${_data}/mobius_20x4_quads.obj;--screenshot;${_out}/view_no_display.png" -DSTATUS=2
          "-DSTDERR=^view: save_screenshot: no display to draw on[^\n]*\n$" -P ${CMAKE_CURRENT_SOURCE_DIR}/check_tool.cmake)
cgal_ext_tool_fails(view.fails.missing_file view
  "${_out}/no_such.obj;--screenshot;${_out}/x.png"
  "^view: [^\n]*no_such.obj[^\n]*\n$")
cgal_ext_tool_fails(view.fails.size view
  "${_data}/mobius_20x4_quads.obj;--size;8x600"
  "^view: --size '8' is not an integer from 16 to 8192; usage: [^\n]+\n$")
set_tests_properties(view.fails.no_display view.fails.missing_file view.fails.size PROPERTIES
  ENVIRONMENT "${_environment}")
