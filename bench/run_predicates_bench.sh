#!/usr/bin/env bash
# Builds predicates_bench with the release preset's settings (Ninja, CMAKE_BUILD_TYPE=Release), runs
# it and writes results/predicates/bench.json and results/predicates/README.md (ns per call and the
# ratios cavity/plain, with the goals). BUILD_DIR overrides the build directory; extra arguments go
# to the benchmark (e.g. --benchmark_filter=orient3d).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build/release}"
out="$root/results/predicates"
mkdir -p "$out"

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAVITY_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target predicates_bench -j2

"$build/bench/predicates_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_min_time=0.2 --benchmark_out="$out/bench.json" --benchmark_out_format=json "$@"

python3 - "$out/bench.json" "$out/README.md" "$0 $*" <<'PY'
import json, sys

data = json.load(open(sys.argv[1]))
median = {}
counters = {}
for b in data["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    name = b["run_name"]  # BM_<predicate>/<impl>/<class>
    median[name] = b["cpu_time"]
    counters[name] = {k: b[k] for k in ("filter", "adaptive", "exact") if k in b}

goals = {"random": {"orient3d": 1.3, "insphere": 1.3, "orient4d": 1.5},
         "near_degenerate": {}, "degenerate": {"orient3d": 10, "insphere": 10, "orient4d": 10}}
lines = [
    "# Predicate benchmark",
    "",
    "CPU ns per call (median of 5 repetitions, 4096 queries cycled), made by",
    f"`{sys.argv[3].strip()}` on the shared 2-core machine ({data['context'].get('date', '')},",
    f"load average {data['context'].get('load_avg', '?')}): absolute figures move with the load;",
    "the ratios are steadier. Stage columns: fraction of the queries decided by each stage.",
    "",
    "| predicate | inputs | cavity ns | plain ns | oracle ns | cavity/plain | goal | filter | adaptive | exact |",
    "|---|---|---|---|---|---|---|---|---|---|",
]
for pred in ("orient3d", "insphere", "orient4d"):
    for cls in ("random", "near_degenerate", "degenerate"):
        key = lambda impl: f"BM_{pred}/{impl}/{cls}"
        if key("cavity") not in median:
            continue
        c, p, o = median[key("cavity")], median[key("plain")], median.get(key("oracle"), float("nan"))
        ratio = c / p
        goal = goals[cls].get(pred)
        verdict = "—" if goal is None else (f"≤{goal}×: {'met' if ratio <= goal else 'NOT met'}")
        st = counters[key("cavity")]
        lines.append(f"| {pred} | {cls} | {c:.1f} | {p:.1f} | {o:.0f} | {ratio:.2f}× | {verdict} | "
                     f"{st.get('filter', 0):.3f} | {st.get('adaptive', 0):.3f} | {st.get('exact', 0):.3f} |")
lines += [
    "",
    "Inputs: `random` uniform in [-1, 1) (weights too); `degenerate` exactly degenerate integer sets",
    "(coplanar points; points on x²+y²+z² = 45², translated; weights putting the lifted points on one",
    "hyperplane); `near_degenerate` the same sets with 1-4 coordinates moved 1-4 ulps. `plain` is the",
    "same determinant in doubles without any error bound (not robust); `oracle` is cavity::oracle.",
    "",
    "Caveat: on the shared, loaded machine the few-ns rows vary by up to 2x between runs (orient3d",
    "random has measured anywhere from 1.2x to 2.4x); a goal marked met here is met in this run only.",
    "The near-degenerate rows have no goal: their non-integer inputs need expansions or GMP.",
]
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
PY
echo "wrote $out/bench.json and $out/README.md"
