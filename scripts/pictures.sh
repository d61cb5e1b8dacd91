#!/usr/bin/env bash
# Renders the pictures of the manual (doc/pictures/*.png) from the library's
# own tools: the release example tools (built as scripts/demo.sh builds them)
# make the meshes, f3d renders them off screen under xvfb-run.
# Needs the Debian packages f3d and xvfb; not part of the test script.
set -euo pipefail
cd "$(dirname "$0")/.."
for tool in f3d xvfb-run; do
  command -v "$tool" >/dev/null 2>&1 || { echo "pictures: $tool is not installed (apt-get install f3d xvfb)" >&2; exit 2; }
done

build=${CGAL_EXT_DEMO_BUILD_DIR:-build/release}
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_EXT_BUILD_TESTS=OFF -DCGAL_EXT_BUILD_EXAMPLES=ON \
      "${launcher[@]}" >/dev/null
cmake --build "$build" --target subdivide merge offset -j "${CGAL_EXT_JOBS:-$(nproc)}"
tools=$build/examples

data=test/data/nonorientable
work=build/pictures
out=doc/pictures
mkdir -p "$work" "$out"

# render MESH PNG [WIDTH HEIGHT]: the mesh seen from above at an angle, on
# white, with its edges drawn if $edges is set (cages and coarse levels), in
# a view angle of $view degrees (narrower: larger).
edges= view=24
render() {
  local width=${3:-480} height=${4:-360} options=()
  [ -n "$edges" ] && options+=(--edges)
  xvfb-run -a f3d "$1" --output="$2" --resolution="$width,$height" --geometry-only --up=+Z \
    --camera-elevation-angle=40 --camera-azimuth-angle=25 --camera-view-angle="$view" --fxaa \
    --bg-color=1,1,1 --quiet "${options[@]}"
  echo "pictures: $2 ($(stat -c %s "$2") bytes)"
}
subdivide() { "$tools/subdivide" "$@" >/dev/null; }

# The Möbius strip, and three Catmull–Clark steps across its seam.
edges=1 render "$data/mobius_20x4_quads.obj" "$out/mobius.png"
subdivide "$data/mobius_20x4_quads.obj" "$work/mobius_cc3.obj" --levels 3
render "$work/mobius_cc3.obj" "$out/mobius_catmull_clark.png"

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
  view=32 render "$work/cube_crease_${name}_cc4.obj" "$out/crease_$name.png" 240 200
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
