#!/usr/bin/env bash
# Renders the pictures of the manual (doc/pictures/*.png) from the library's
# own tools: the release example tools (built as scripts/demo.sh builds them)
# make the meshes, and the view tool draws each with one colour per side (blue
# where the faces' orientation points, orange on the other side) on a virtual
# screen (xvfb-run). Needs the Debian packages libcgal-qt5-dev and xvfb; not
# part of the test script.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v xvfb-run >/dev/null 2>&1 || { echo "pictures: xvfb-run is not installed (apt-get install xvfb)" >&2; exit 2; }

build=${CGAL_EXT_DEMO_BUILD_DIR:-build/release}
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_EXT_BUILD_TESTS=OFF -DCGAL_EXT_BUILD_EXAMPLES=ON \
      "${launcher[@]}" >/dev/null
cmake --build "$build" --target subdivide merge offset decimate remesh geodesics curvature tessellate -j "${CGAL_EXT_JOBS:-$(nproc)}"
cmake --build "$build" --target view -j "${CGAL_EXT_JOBS:-$(nproc)}" ||
  { echo "pictures: the view tool was not built (apt-get install libcgal-qt5-dev)" >&2; exit 2; }
tools=$build/examples

data=test/data/nonorientable
work=build/pictures
out=doc/pictures
mkdir -p "$work" "$out"

# render MESH PNG [WIDTH HEIGHT]: the mesh seen from above at an angle (40°
# up, 25° round), z up, on white; with all its edges if $edges is set (cages
# and coarse levels), else only its borders, Möbius edges and sharp edges;
# coloured by the PLY vertex property $scalar if it is set, by the checker of
# its texture coordinates if $checker is.
edges=
scalar=
checker=
render() {
  local width=${3:-480} height=${4:-360} options=()
  [ -n "$edges" ] || options+=(--features-only)
  [ -z "$scalar" ] || options+=(--scalar "$scalar")
  [ -z "$checker" ] || options+=(--uv-checker)
  xvfb-run -a -s "-screen 0 1280x1024x24" "$tools/view" "$1" --screenshot "$2" --size "${width}x$height" \
    --direction -0.32,0.69,-0.64 "${options[@]}" >/dev/null 2>"$work/view.log" || { cat "$work/view.log" >&2; exit 2; }
  echo "pictures: $2 ($(stat -c %s "$2") bytes)"
}
subdivide() { "$tools/subdivide" "$@" >/dev/null; }

# The Möbius strip, and three Catmull–Clark steps across its seam.
edges=1 render "$data/mobius_20x4_quads.obj" "$out/mobius.png"
subdivide "$data/mobius_20x4_quads.obj" "$work/mobius_cc3.obj" --levels 3
render "$work/mobius_cc3.obj" "$out/mobius_catmull_clark.png"

# A texture across the Möbius strip: the checker of its texture coordinates,
# cut open by one seam across the strip, on the cage and after three
# Catmull–Clark steps, which carry them by OpenSubdiv's face-varying rules.
checker=1 render test/data/uv/mobius_12x2_uv.obj "$out/mobius_uv_cage.png"
subdivide test/data/uv/mobius_12x2_uv.obj "$work/mobius_uv_cc3.obj" --levels 3
checker=1 render "$work/mobius_uv_cc3.obj" "$out/mobius_uv_catmull_clark.png"

# The figure-8 Klein bottle, smoothed by two Catmull–Clark steps.
subdivide "$data/klein_fig8_24x12_quads.obj" "$work/klein_cc2.obj" --levels 2
render "$work/klein_cc2.obj" "$out/klein_bottle.png"

# One step of Doo–Sabin on the quad strip and of √3 on the triangle strip,
# with their edges: the faces show each scheme's pattern.
subdivide "$data/mobius_20x4_quads.obj" "$work/mobius_doo_sabin1.obj" --scheme doo-sabin --levels 1
edges=1 render "$work/mobius_doo_sabin1.obj" "$out/mobius_doo_sabin.png"
subdivide "$data/mobius_20x4_tris.obj" "$work/mobius_sqrt3_1.obj" --scheme sqrt3 --levels 1
edges=1 render "$work/mobius_sqrt3_1.obj" "$out/mobius_sqrt3.png"

# A crease sequence: a cube whose twelve edges have sharpness 0, 1, 2 and
# infinity (OpenSubdiv's OBJ tags, vertex indices from 0), after four
# Catmull–Clark steps.
for s in 0 1 2 10; do
  cage=$work/cube_crease_$s.obj
  {
    printf 'v %s\n' "-1 -1 -1" "1 -1 -1" "1 1 -1" "-1 1 -1" "-1 -1 1" "1 -1 1" "1 1 1" "-1 1 1"
    printf 'f %s\n' "1 4 3 2" "5 6 7 8" "1 2 6 5" "2 3 7 6" "3 4 8 7" "4 1 5 8"
    if [ "$s" != 0 ]; then
      for edge in "0 1" "1 2" "2 3" "3 0" "4 5" "5 6" "6 7" "7 4" "0 4" "1 5" "2 6" "3 7"; do echo "t crease 2/1/0 $edge $s"; done
    fi
  } >"$cage"
  name=$s; [ "$s" = 10 ] && name=inf
  subdivide "$cage" "$work/cube_crease_${name}_cc4.obj" --levels 4
  render "$work/cube_crease_${name}_cc4.obj" "$out/crease_$name.png" 240 200
done

# A strip glued from two halves: the Möbius strip's faces 1-40 and 41-80
# (rings 0-10 and 10-20 of its 5-vertex rings), each its own file. Their ends
# coincide; `merge` glues both, one end straight and one with the twist.
awk '/^v /{ if (++n <= 55) print } /^f /{ if (++m <= 40) print }' "$data/mobius_20x4_quads.obj" >"$work/half_a.obj"
awk '/^v /{ v[++n] = $0 } /^f /{ if (++m > 40) f[m] = $0 }
     END {
       for (i = 51; i <= 100; ++i) print v[i]
       for (i = 1; i <= 5; ++i) print v[i]
       for (k = 41; k <= 80; ++k) {
         split(f[k], w, " "); line = "f"
         for (j = 2; j <= 5; ++j) line = line " " (w[j] > 50 ? w[j] - 50 : w[j] + 50)
         print line
       }
     }' "$data/mobius_20x4_quads.obj" >"$work/half_b.obj"
# Pulled apart along z for the picture of the halves.
awk '/^v /{ printf "v %s %s %s\n", $2, $3, $4 + 0.35; next } { print }' "$work/half_b.obj" >"$work/half_b_lifted.obj"
awk '/^v /{ print } /^f /{ f[++m] = $0 } END { for (k = 1; k <= m; ++k) print f[k] }' "$work/half_a.obj" >"$work/halves.obj"
awk '/^v /{ print }' "$work/half_b_lifted.obj" >>"$work/halves.obj"
awk '/^f /{ printf "f %d %d %d %d\n", $2 + 55, $3 + 55, $4 + 55, $5 + 55 }' "$work/half_b_lifted.obj" >>"$work/halves.obj"
edges=1 render "$work/halves.obj" "$out/merge_halves.png"
"$tools/merge" "$work/half_a.obj" "$work/half_b.obj" "$work/glued.obj"
edges=1 render "$work/glued.obj" "$out/merge_glued.png"

# The thickened strip: both offsets of the Möbius strip are one closed surface.
"$tools/offset" "$data/mobius_20x4_quads.obj" "$work/mobius_offset.obj" --distance 0.1 >/dev/null
edges=1 render "$work/mobius_offset.obj" "$out/mobius_offset.png"

# Decimation and remeshing keep a one-sided surface one-sided: the Klein
# bottle after two Catmull–Clark steps (4608 quads, 9216 triangles), decimated
# to 10 %; Boy's surface remeshed to edges of about 0.12.
subdivide "$data/klein_fig8_24x12_quads.obj" "$work/klein_cc2_for_decimation.obj" --levels 2
"$tools/decimate" "$work/klein_cc2_for_decimation.obj" "$work/klein_decimated.obj" --ratio 0.1 >/dev/null
edges=1 render "$work/klein_decimated.obj" "$out/klein_decimated.png"
"$tools/remesh" "$data/boys_surface_quads.obj" "$work/boys_remeshed.obj" --edge-length 0.12 --iterations 5 >/dev/null
edges=1 render "$work/boys_remeshed.obj" "$out/boys_remeshed.png"

# The geodesic distance on the Klein bottle (two Catmull–Clark steps,
# triangulated) from vertex 0, by the heat method: violet near, yellow far.
"$tools/geodesics" "$work/klein_cc2.obj" "$work/klein_distance.ply" --source 0 --triangulate >/dev/null
scalar=distance render "$work/klein_distance.ply" "$out/klein_geodesic_distance.png"

# Its mean curvature, each side of each face coloured by the values seen from
# it (the curvature tool writes the side each vertex's value is seen from):
# violet -M, yellow M, M the largest over both sides.
"$tools/curvature" "$work/klein_cc2.obj" "$work/klein_curvature.ply" --triangulate >/dev/null
scalar=mean_curvature render "$work/klein_curvature.ply" "$out/klein_mean_curvature.png"

# The Catmull–Clark limit surface of the Klein bottle's cage (288 quads),
# tessellated at rate 8 (every quad 8 x 8, shared samples computed once):
# the cage with its edges, the tessellation beside it.
"$tools/tessellate" "$data/klein_fig8_24x12_quads.obj" "$work/klein_tessellated.obj" --rate 8 >/dev/null
edges=1 render "$data/klein_fig8_24x12_quads.obj" "$out/klein_cage.png" 360 300
render "$work/klein_tessellated.obj" "$out/klein_tessellated.png" 360 300
