#!/usr/bin/env bash
# Builds the benchmarks in Release and runs every benchmark program of bench/,
# then prints, per case, each implementation's median time and memory next to
# ours, with the ratios (peer time / our time: above 1 means we are faster;
# our bytes / peer bytes: below 1 means we use less).
#
# Benchmark names are `group/case.../implementation`, with `/threads:N` after
# the implementations run at several thread counts (one row per count); the
# first implementation whose name starts with `CGAL_ext` is the reference of
# its case. Counters whose name
# contains `bytes` are compared as memory.
#
# Environment: CGAL_EXT_BENCH_BUILD_DIR (build/bench), CGAL_EXT_BENCH_JOBS (2),
# CGAL_EXT_BENCH_REPETITIONS (5), CGAL_EXT_BENCH_OUT (directory of the JSON
# results, the build directory by default). Arguments are passed to every
# program, e.g. `scripts/bench.sh --benchmark_filter=torus`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

build=${CGAL_EXT_BENCH_BUILD_DIR:-build/bench}
jobs=${CGAL_EXT_BENCH_JOBS:-2}
repetitions=${CGAL_EXT_BENCH_REPETITIONS:-5}
out=${CGAL_EXT_BENCH_OUT:-$build/results}
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_EXT_BUILD_BENCHMARKS=ON \
      -DCGAL_EXT_BUILD_TESTS=OFF -DCGAL_EXT_BUILD_EXAMPLES=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$jobs"
mkdir -p "$out"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
status=0
shopt -s nullglob
for program in "$build"/bench/bench_*; do
  [ -x "$program" ] && [ -f "$program" ] || continue
  name=$(basename "$program")
  json="$out/$name.json"
  echo "== $name"
  if ! "$program" --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true \
       --benchmark_out="$json" --benchmark_out_format=json "$@" >/dev/null; then
    echo "$name failed" >&2
    status=1
    continue
  fi
  python3 - "$json" <<'EOF'
import json, sys
from collections import OrderedDict

data = json.load(open(sys.argv[1]))
SUFFIXES = ("real_time", "process_time", "manual_time")
PREFIXES = ("iterations:", "repeats:", "min_time:", "min_warmup_time:")

# A thread count stays with its implementation (`name/threads:N`): each count
# is a row of its own.
def split(run_name):
    parts = [p for p in run_name.split("/") if p not in SUFFIXES and not p.startswith(PREFIXES)]
    while len(parts) > 1 and parts[-1].startswith("threads:"):
        parts[-2:] = [parts[-2] + "/" + parts[-1]]
    return "/".join(parts[:-1]), parts[-1]

# Medians when there are repetitions, single runs otherwise.
rows = OrderedDict()
have_medians = any(b.get("aggregate_name") == "median" for b in data["benchmarks"])
for b in data["benchmarks"]:
    if b.get("error_occurred"):
        case, impl = split(b.get("run_name", b["name"]))
        rows.setdefault(case, OrderedDict())[impl] = {"error": b.get("error_message", "error")}
        continue
    if have_medians and b.get("aggregate_name") != "median":
        continue
    if not have_medians and b.get("run_type") == "aggregate":
        continue
    case, impl = split(b.get("run_name", b["name"]))
    rows.setdefault(case, OrderedDict())[impl] = b

def ms(b, key):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
    return b[key] * scale

def fmt_ms(v):
    # Three significant digits below 10 ms, so that microsecond cases stay readable.
    return "%.1f" % v if v >= 10 else "%.3g" % v

for case, impls in rows.items():
    ref_name = next((i for i in impls if i.startswith("CGAL_ext")), None)
    ref = impls.get(ref_name) if ref_name else None
    if ref is not None and "error" in ref:
        ref = None
    mem_keys = []
    for b in impls.values():
        for k in b:
            if "bytes" in k and k not in mem_keys and isinstance(b[k], (int, float)):
                mem_keys.append(k)
    print()
    print(case + ("" if ref else "   (no CGAL_ext reference)"))
    header = ["implementation", "real ms", "cpu ms", "real ratio", "cpu ratio"]
    for k in mem_keys:
        header += [k, "ours/peer"]
    table = [header]
    for impl, b in impls.items():
        if "error" in b:
            table.append([impl, "error: " + b["error"]])
            continue
        line = [impl, fmt_ms(ms(b, "real_time")), fmt_ms(ms(b, "cpu_time"))]
        for key in ("real_time", "cpu_time"):
            line.append("%.2f" % (b[key] / ref[key]) if ref and impl != ref_name else "1" if ref else "-")
        for k in mem_keys:
            v = b.get(k)
            line.append("-" if v is None else "%.1f" % v)
            r = ref.get(k) if ref else None
            line.append("%.3f" % (r / v) if (r is not None and v) and impl != ref_name else ("1" if impl == ref_name else "-"))
        table.append(line)
    widths = [max(len(r[i]) for r in table if i < len(r)) for i in range(len(header))]
    for r in table:
        print("  " + "  ".join(c.rjust(widths[i]) if i else c.ljust(widths[i]) for i, c in enumerate(r)))
print()
print("real/cpu ratio = peer time / our time (above 1: ours is faster); "
      "ours/peer = our bytes / peer bytes (below 1: ours is smaller); medians of the repetitions")
EOF
done
exit $status
