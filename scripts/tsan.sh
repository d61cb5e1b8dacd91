#!/usr/bin/env bash
# Runs the tests of the parallel paths (subdivision and re-interpolation under
# CGAL::Parallel_tag, the soup builder's parallel import) under
# ThreadSanitizer: a build of the test suite of its own (build/tsan), since
# ThreadSanitizer excludes AddressSanitizer. Exits non-zero on a report.
#
#   bash scripts/tsan.sh                      # the parallel tests
#   TSAN_FILTER='*' bash scripts/tsan.sh      # every test (slow)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CGAL_EXT_TSAN_BUILD_DIR:-build/tsan}
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
      -DCGAL_EXT_SANITIZE_THREAD=ON -DCGAL_EXT_BUILD_TESTS=ON -DCGAL_EXT_BUILD_EXAMPLES=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" --target cgal_ext_tests
# halt_on_error: the first race fails the run; second_deadlock_stack for
# readable lock reports.
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}
filter=${TSAN_FILTER:-'*Parallel*:*parallel*:*Threads*:*threads*'}
"$build/test/cgal_ext_tests" --gtest_filter="$filter" --gtest_brief=1
echo "ThreadSanitizer: no reports ($filter)"
