#!/usr/bin/env bash
# Builds the test suite with -Wall -Wextra under AddressSanitizer and
# UndefinedBehaviorSanitizer, and runs it (GoogleTest through CTest), after
# building the API reference with warnings as errors.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# The API reference first: it takes seconds and fails on an undocumented
# public class, function or named parameter.
bash scripts/reference.sh

build=${CGAL_EXT_TEST_BUILD_DIR:-build/test}
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# -g1: line tables only, enough for the sanitizers' stack traces; full debug
# information of CGAL's templates costs much of the build's time.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
      -DCGAL_EXT_SANITIZE=ON -DCGAL_EXT_BUILD_TESTS=ON -DCGAL_EXT_BUILD_EXAMPLES=ON "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
cd "$build"
ctest --output-on-failure -j "$(nproc)"
