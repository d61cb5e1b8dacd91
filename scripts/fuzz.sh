#!/usr/bin/env bash
# Builds the readers' libFuzzer targets (test/fuzz/, clang with ASan and UBSan)
# and, for each of OBJ, OFF and PLY, replays the seed corpus
# (test/fuzz/corpus/<format>/) and then fuzzes for FUZZ_SECONDS (default 20)
# seconds. New inputs go to <build>/corpus/<format>/, crashes to
# <build>/findings/. Exits non-zero on a finding.
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
for format in obj off ply; do
  target="$build/test/fuzz/fuzz_$format"
  seeds=test/fuzz/corpus/$format
  corpus="$build/corpus/$format"
  mkdir -p "$corpus"
  echo "== $format: replaying $(ls "$seeds" | wc -l) seeds"
  "$target" "$seeds"/* >"$build/findings/replay_$format.log" 2>&1 ||
    { tail -40 "$build/findings/replay_$format.log"; exit 1; }
  echo "== $format: fuzzing for ${seconds}s"
  # -rss_limit_mb: a reader that believes a header's counts shows up as an out-of-memory finding.
  parallel=()
  # Several jobs log to fuzz-<n>.log in the working directory.
  if [ "$jobs" -gt 1 ]; then parallel=(-jobs="$jobs" -workers="$jobs"); fi
  (cd "$build/findings" && "$target" -max_total_time="$seconds" -max_len=8192 -rss_limit_mb=2048 \
      -timeout=10 -dict="$root/test/fuzz/$format.dict" -artifact_prefix="$format-" "${parallel[@]}" \
      -print_final_stats=1 "${seed[@]}" "$corpus" "$root/$seeds") >"$build/findings/fuzz_$format.log" 2>&1 ||
    { tail -60 "$build/findings/fuzz_$format.log"; exit 1; }
  grep -h "stat::number_of_executed_units\|cov:" "$build/findings/fuzz_$format.log" | tail -2 || true
done
echo "fuzzing: no findings"
