#!/usr/bin/env bash
# Runs the tests of the parallel paths (subdivision and re-interpolation under
# CGAL::Parallel_tag, the soup builder's parallel import) under
# ThreadSanitizer: a build of the test suite of its own (build/tsan), since
# ThreadSanitizer excludes AddressSanitizer. Exits non-zero on a report.
#
#   bash scripts/tsan.sh                      # the parallel tests
#   TSAN_FILTER='*' bash scripts/tsan.sh      # every test (slow)
#
# ThreadSanitizer sees the order that TBB's task spawns and joins make only if
# TBB itself is instrumented (oneTBB's TBB_SANITIZE=thread): with Debian's
# libtbb it reports TBB's own task objects and every write the main thread
# made before a loop. So the script builds the installed oneTBB's Debian
# source (`apt-get source`, through a deb-src list of its own: the system's
# apt configuration is left alone) with TBB_SANITIZE=thread once, into
# <build>/onetbb, and builds the tests against it. Needs the network to the
# Debian archive the first time, and dpkg-dev.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CGAL_EXT_TSAN_BUILD_DIR:-build/tsan}
mkdir -p "$build"
build=$(cd -- "$build" >/dev/null && pwd)
tbb=$build/onetbb

# instrumented_tbb: <build>/onetbb from the source of the installed libtbb-dev.
instrumented_tbb() {
  local package version src=$build/tbb-source
  package=$(dpkg-query -W -f='${source:Package}' libtbb-dev)
  version=$(dpkg-query -W -f='${source:Version}' libtbb-dev)
  rm -rf "$src" && mkdir -p "$src/lists/partial"
  # The deb-src lines of the system's own archives: each enabled stanza of
  # type deb of its deb822 sources (URIs x Suites, its Components, its
  # keyring), and its one-line list.
  awk 'function flush() { if (uris != "" && types ~ /(^| )deb( |$)/ && enabled != "no") {
                            n = split(uris, u, " "); m = split(suites, s, " ");
                            for (i = 1; i <= n; ++i) for (j = 1; j <= m; ++j)
                              print "deb-src", (key != "" ? "[signed-by=" key "] " : "") u[i], s[j], comps }
                          uris = suites = comps = types = key = enabled = "" }
       FNR == 1 { flush() }
       /^[ \t]*$/ { flush(); next }
       /^Types:/ { sub(/^Types:[ \t]*/, ""); types = $0 }
       /^URIs:/ { sub(/^URIs:[ \t]*/, ""); uris = $0 }
       /^Suites:/ { sub(/^Suites:[ \t]*/, ""); suites = $0 }
       /^Components:/ { sub(/^Components:[ \t]*/, ""); comps = $0 }
       /^Signed-By:[ \t]*[^ \t]/ { sub(/^Signed-By:[ \t]*/, ""); key = $0 }
       /^Enabled:/ { sub(/^Enabled:[ \t]*/, ""); enabled = $0 }
       END { flush() }' /etc/apt/sources.list.d/*.sources /dev/null >"$src/sources.list"
  grep -h '^deb ' /etc/apt/sources.list 2>/dev/null | sed 's/^deb /deb-src /' >>"$src/sources.list" || true
  local apt=(-o Dir::Etc::SourceList="$src/sources.list" -o Dir::Etc::SourceParts=/nonexistent
             -o Dir::State::Lists="$src/lists" -o APT::Sandbox::User=root)
  apt-get "${apt[@]}" update >/dev/null
  (cd "$src" && apt-get "${apt[@]}" source "$package=$version" >/dev/null)
  local tree
  tree=$(find "$src" -mindepth 1 -maxdepth 1 -type d -name "$package-*" | head -1)
  [ -n "$tree" ] || { echo "tsan: apt-get source $package=$version gave no source tree" >&2; exit 2; }
  # Its compiler warnings (ThreadSanitizer does not model atomic_thread_fence)
  # go to the log, which is kept only on a failure.
  { cmake -S "$tree" -B "$src/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF \
          -DTBB_STRICT=OFF -DTBB_SANITIZE=thread -DCMAKE_INSTALL_PREFIX="$tbb" &&
    cmake --build "$src/build" -j "$(nproc)" && cmake --install "$src/build"; } >"$build/onetbb.log" 2>&1 ||
    { tail -30 "$build/onetbb.log" >&2; echo "tsan: building the instrumented oneTBB failed" >&2; exit 2; }
  rm -rf "$src" "$build/onetbb.log"
}
# (Called in an if's body, not after ||, so that set -e stops at a failing step.)
if [ ! -f "$tbb/lib/cmake/TBB/TBBConfig.cmake" ]; then
  instrumented_tbb
fi

launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
      -DCGAL_EXT_SANITIZE_THREAD=ON -DCGAL_EXT_BUILD_TESTS=ON -DCGAL_EXT_BUILD_EXAMPLES=OFF \
      -DTBB_DIR="$tbb/lib/cmake/TBB" "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" --target cgal_ext_tests
# The tests must run on the instrumented library, not the system's.
if ! ldd "$build/test/cgal_ext_tests" | grep -q "$tbb/lib/libtbb"; then
  echo "tsan: the tests are not linked to $tbb/lib/libtbb.so" >&2
  exit 2
fi
# The detector must see a race in a loop body through this TBB: a planted one.
probe=$build/tsan_probe
"${CXX:-c++}" -std=c++17 -O1 -g -fsanitize=thread -I"$tbb/include" scripts/tsan_probe.cpp -L"$tbb/lib" -ltbb \
  -Wl,-rpath,"$tbb/lib" -o "$probe"
status=0
TSAN_OPTIONS=exitcode=66 "$probe" >"$probe.log" 2>&1 || status=$?
if [ "$status" -ne 66 ] || ! grep -q "WARNING: ThreadSanitizer: data race" "$probe.log"; then
  echo "tsan: the race planted in scripts/tsan_probe.cpp was not reported (exit $status): a clean run would prove nothing" >&2
  exit 2
fi
# halt_on_error: the first race fails the run; second_deadlock_stack for
# readable lock reports.
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}
filter=${TSAN_FILTER:-'*Parallel*:*parallel*:*Threads*:*threads*'}
"$build/test/cgal_ext_tests" --gtest_filter="$filter" --gtest_brief=1
echo "ThreadSanitizer: no reports ($filter)"
