#!/usr/bin/env bash
# Installs the Debian packages the project needs; does nothing when they are there.
set -euo pipefail

required=(cmake g++ make ccache libcgal-dev libboost-dev libeigen3-dev libgmp-dev libmpfr-dev
          libgtest-dev libbenchmark-dev libtbb-dev doxygen python3)
# Peers used only for reference tests and benchmarks, the viewer (CGAL's Qt5
# component, with a virtual screen and software OpenGL for its tests) and the
# readers' fuzz targets (clang's libFuzzer):
# installed where the package archive has them, skipped cleanly when absent.
optional=(libosd-dev libopenmesh-dev libcgal-qt5-dev xvfb xauth libgl1-mesa-dri clang libclang-rt-dev)

missing() { for p in "$@"; do dpkg -s "$p" >/dev/null 2>&1 || echo "$p"; done; }

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

mapfile -t need < <(missing "${required[@]}")
mapfile -t want < <(missing "${optional[@]}")
if [ ${#need[@]} -gt 0 ] || [ ${#want[@]} -gt 0 ]; then
  "${sudo_cmd[@]}" apt-get update -qq
fi
if [ ${#need[@]} -gt 0 ]; then
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}"
fi
for p in "${want[@]}"; do
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "$p" \
    || echo "note: optional package $p is not available; its comparisons will be skipped" >&2
done
