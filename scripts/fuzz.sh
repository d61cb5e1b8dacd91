#!/usr/bin/env bash
# Builds the libFuzzer targets (test/fuzz/, clang with ASan and UBSan) and, for
# each reader (OBJ, OFF, PLY) and each algorithm family of the tools
# (subdivide, decimate, remesh, merge, offset; FUZZ_FAMILIES chooses), replays
# the seed corpus (test/fuzz/corpus/<format>/, test/fuzz/corpus/tools/) and
# then fuzzes for FUZZ_SECONDS (default 20) seconds. New inputs go to
# <build>/corpus/<name>/, crashes to <build>/findings/. Exits non-zero on a
# finding.
#
#   FUZZ_SECONDS=3600 FUZZ_JOBS=2 bash scripts/fuzz.sh   # an hour per reader
#   FUZZ_SEED=1 bash scripts/fuzz.sh                     # the same random choices from the same corpus
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CGAL_EXT_FUZZ_BUILD_DIR:-build/fuzz}
seconds=${FUZZ_SECONDS:-20}
jobs=${FUZZ_JOBS:-1}
seed=()
if [ -n "${FUZZ_SEED:-}" ]; then seed=(-seed="$FUZZ_SEED"); fi
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="${CLANGXX:-clang++}" -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS_DEBUG="" -DCGAL_EXT_BUILD_TESTS=OFF -DCGAL_EXT_BUILD_EXAMPLES=OFF \
      -DCGAL_EXT_BUILD_FUZZERS=ON "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)"
# Absolute paths from here on: the fuzzers run inside the findings directory.
root=$PWD
build=$(cd -- "$build" >/dev/null && pwd)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0:malloc_limit_mb=2048}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
mkdir -p "$build/findings"
# The targets write each input to a file for the readers to open: there, not
# in the system's temporary directory, and removed at the end.
export TMPDIR="$build/scratch"
mkdir -p "$TMPDIR"
trap 'rm -rf "$TMPDIR"' EXIT
# fuzz_one TARGET SEEDS CORPUS NAME [libFuzzer options...]: replays the seeds,
# then fuzzes for $seconds seconds from the corpus and the seeds.
fuzz_one() {
  local target=$1 seeds=$2 corpus=$3 name=$4
  shift 4
  mkdir -p "$corpus"
  echo "== $name: replaying $(ls "$seeds" | wc -l) seeds"
  "$target" "$seeds"/* >"$build/findings/replay_$name.log" 2>&1 ||
    { tail -40 "$build/findings/replay_$name.log"; exit 1; }
  echo "== $name: fuzzing for ${seconds}s"
  # -rss_limit_mb: a reader that believes a header's counts, or an algorithm
  # that allocates without bound, shows up as an out-of-memory finding.
  local parallel=()
  # Several jobs log to fuzz-<n>.log in the working directory.
  if [ "$jobs" -gt 1 ]; then parallel=(-jobs="$jobs" -workers="$jobs"); fi
  (cd "$build/findings" && "$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
      -artifact_prefix="$name-" "${parallel[@]}" -print_final_stats=1 "${seed[@]}" "$@" "$corpus" "$root/$seeds") \
      >"$build/findings/fuzz_$name.log" 2>&1 ||
    { tail -60 "$build/findings/fuzz_$name.log"; exit 1; }
  grep -h "stat::number_of_executed_units\|cov:" "$build/findings/fuzz_$name.log" | tail -2 || true
}
for format in obj off ply; do
  fuzz_one "$build/test/fuzz/fuzz_$format" "test/fuzz/corpus/$format" "$build/corpus/$format" "$format" \
    -max_len=8192 -dict="$root/test/fuzz/$format.dict"
done
# The tools' paths: four option bytes and an OBJ file, one algorithm family
# each (test/fuzz/fuzz_tools.cpp); the OBJ dictionary helps them too.
for family in ${FUZZ_FAMILIES:-subdivide decimate remesh merge offset}; do
  fuzz_one "$build/test/fuzz/fuzz_$family" test/fuzz/corpus/tools "$build/corpus/$family" "$family" \
    -max_len=4096 -dict="$root/test/fuzz/obj.dict"
done
echo "fuzzing: no findings"
