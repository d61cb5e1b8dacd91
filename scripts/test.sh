#!/usr/bin/env bash
# Builds the test suite with -Wall -Wextra under AddressSanitizer and
# UndefinedBehaviorSanitizer, and runs it (GoogleTest through CTest), after
# building the API reference with warnings as errors.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# The include arrows first: no header includes one of a higher layer, and a
# family's internal/ serves that family only (scripts/check_include_layers.py).
python3 scripts/check_include_layers.py
# Then the API reference: it takes seconds and fails on an undocumented
# public class, function or named parameter.
bash scripts/reference.sh

# The readers' fuzz targets (clang's libFuzzer, ASan + UBSan) build beside
# the test suite; each replays its seed corpus and fuzzes for 20 s with a
# fixed seed. Left out, with a note, where clang has no libFuzzer.
mkdir -p build
fuzz_log=$PWD/build/fuzz.log
fuzz_pid=
if command -v clang++ >/dev/null 2>&1 &&
   echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' |
     clang++ -x c++ -fsanitize=fuzzer - -o build/fuzz_probe >/dev/null 2>&1; then
  # In a process group of its own, so that all of it stops if the build or
  # a test fails first.
  FUZZ_SECONDS=${FUZZ_SECONDS:-20} FUZZ_SEED=${FUZZ_SEED:-1} setsid bash scripts/fuzz.sh >"$fuzz_log" 2>&1 &
  fuzz_pid=$!
  trap 'kill -- -"$fuzz_pid" 2>/dev/null || true' EXIT
else
  echo "note: clang++ with libFuzzer not found: the readers' fuzz targets are not run" >&2
fi

build=${CGAL_EXT_TEST_BUILD_DIR:-build/test}
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# The compiler of the test build: clang++ where it is installed (the fuzz
# targets need it too), which compiles CGAL's templates at -O0 with the
# sanitizers about 2.4 times faster than GCC (examples/convert.cpp: 26 s of
# CPU against 63 s), most of this script's time; else the default, GCC.
# CGAL_EXT_TEST_CXX chooses another; the demo builds with the default.
# clang++ is taken only if it links a program with the sanitizers (its
# runtime is a package of its own).
compiler=()
test_cxx=${CGAL_EXT_TEST_CXX:-$(command -v clang++ || true)}
if [ -z "${CGAL_EXT_TEST_CXX:-}" ] && [ -n "$test_cxx" ] &&
   ! echo 'int main() { return 0; }' |
     "$test_cxx" -x c++ -fsanitize=address,undefined - -o build/sanitizer_probe >/dev/null 2>&1; then
  test_cxx=
fi
if [ -n "$test_cxx" ]; then compiler=(-DCMAKE_CXX_COMPILER="$test_cxx"); fi
# -g1: line tables only, enough for the sanitizers' stack traces; full debug
# information of CGAL's templates costs much of the build's time. -O0: GCC
# compiles CGAL's templates 2-2.5 times faster than at -O1, which is most of
# this script's time; the one suite that computes for long keeps -O1 (see
# test/CMakeLists.txt).
# UBSan's checks at each pointer and reference use (null and alignment, one
# type check, and vptr's dynamic type check at the same places) are left out
# of this build, unless CGAL_EXT_SANITIZE_SKIP says otherwise: at -O0 they
# make much of the code clang generates (subdivide.cpp: 80 s of CPU with
# them, 50 s without; the subdivision suites 189 s and 115 s; the whole
# build 2 100 s and 1 737 s; leaving out any one of the three saves
# nothing). AddressSanitizer still stops on a
# null dereference, and the fuzz targets (the readers and the tools' paths,
# run where clang has libFuzzer) keep every UBSan check.
skip=${CGAL_EXT_SANITIZE_SKIP-null,alignment,vptr}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O0 -g1" \
      -DCGAL_EXT_SANITIZE=ON -DCGAL_EXT_SANITIZE_SKIP="$skip" -DCGAL_EXT_BUILD_TESTS=ON -DCGAL_EXT_BUILD_EXAMPLES=ON "${launcher[@]}" "${compiler[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
(cd "$build" && ctest --output-on-failure -j "$(nproc)")
if [ -n "$fuzz_pid" ]; then
  wait "$fuzz_pid" || { tail -60 "$fuzz_log"; echo "fuzzing the readers failed (log: $fuzz_log)" >&2; exit 1; }
  grep -h "^== \|no findings" "$fuzz_log"
fi
