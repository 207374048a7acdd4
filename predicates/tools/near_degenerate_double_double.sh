#!/usr/bin/env bash
# Appends to results/predicates/README.md the near_degenerate rows before and after the
# double-double stage: `before` is predicates_bench built at commit 3266a99 (stages B, C, D only),
# run now with the settings of bench/run_predicates_bench.sh into
# results/predicates/near_degenerate_before_double_double.json; `after` is the median over the
# results/predicates/bench.run*.json that bench/run_predicates_bench.sh wrote. Run it right after
# that script, in the same session.
set -euo pipefail

root="$(cd "$(dirname "$0")/../.." && pwd)"
out="$root/results/predicates"
before_commit=3266a99
work="${WORK_DIR:-/tmp/cavity-before-double-double}"

if [[ ! -d "$work/src" ]]; then
    mkdir -p "$work/src"
    git -C "$root" archive "$before_commit" | tar -x -C "$work/src"
fi
cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAVITY_BUILD_TESTS=OFF \
    >/dev/null
cmake --build "$work/build" --target predicates_bench -j2 >/dev/null
"$work/build/bench/predicates_bench" --benchmark_filter=near_degenerate --benchmark_repetitions=5 \
    --benchmark_report_aggregates_only=true --benchmark_min_time=0.2 \
    --benchmark_out="$out/near_degenerate_before_double_double.json" --benchmark_out_format=json \
    >/dev/null

python3 - "$out" "$before_commit" "$0" <<'PY'
import glob, json, statistics, sys

out, commit, command = sys.argv[1], sys.argv[2], sys.argv[3]
def medians(path):
    return {b["run_name"]: b for b in json.load(open(path))["benchmarks"]
            if b.get("aggregate_name") == "median"}
before = medians(f"{out}/near_degenerate_before_double_double.json")
after_runs = [medians(p) for p in sorted(glob.glob(f"{out}/bench.run*.json"))]
lines = [
    "",
    "## near_degenerate before and after the double-double stage",
    "",
    f"Made by `{command}` after `bench/run_predicates_bench.sh`. `before` is",
    f"`near_degenerate_before_double_double.json`, the same benchmark built at commit {commit}",
    "(stages B, C, D after the filter), run in the same session; `after` is the median over the",
    "runs above (the double-double stage first, then B, C, D). CPU ns per call; the `adaptive`",
    "fraction includes the double-double stage. The closing remark of the previous section",
    "(stage B paid on every query) describes the `before` state.",
    "",
    "| predicate | before ns | before adaptive / exact | after ns | after adaptive / exact | speed-up |",
    "|---|---|---|---|---|---|",
]
for pred in ("orient3d", "insphere", "orient4d"):
    name = f"BM_{pred}/cavity/near_degenerate"
    if name not in before or not all(name in r for r in after_runs):
        continue
    b = before[name]
    a = statistics.median(r[name]["cpu_time"] for r in after_runs)
    st = after_runs[-1][name]
    lines.append(f"| {pred} | {b['cpu_time']:.0f} | {b['adaptive']:.3f} / {b['exact']:.3f} | "
                 f"{a:.0f} | {st['adaptive']:.3f} / {st['exact']:.3f} | "
                 f"{b['cpu_time'] / a:.1f}× |")
open(f"{out}/README.md", "a").write("\n".join(lines) + "\n")
PY
echo "appended the double-double comparison to $out/README.md"
