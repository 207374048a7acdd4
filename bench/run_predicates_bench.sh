#!/usr/bin/env bash
# Builds predicates_bench with the release preset's settings (Ninja, CMAKE_BUILD_TYPE=Release), runs
# it RUNS times (default 3) and writes results/predicates/bench.run<i>.json and
# results/predicates/README.md (ns per call, the ratios cavity/plain over the runs, the goals, and
# the near_degenerate comparison with results/predicates/near_degenerate_before.json), and the
# predicates item of the top README (bench/predicates_report.py). BUILD_DIR overrides the build
# directory; extra arguments go to the benchmark (e.g. --benchmark_filter=orient3d).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build/release}"
out="$root/results/predicates"
mkdir -p "$out"

# Only the build type is set: the other cache options (tests on or off) stay as the directory has
# them, so benchmarking never turns off the tests of a developer's build.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target predicates_bench -j2

# RUNS independent runs (default 3): on the shared machine the ratios move between runs, so the
# README gives the median ratio over the runs and its range.
runs="${RUNS:-3}"
for ((i = 1; i <= runs; i++)); do
    "$build/bench/predicates_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_min_time=0.2 --benchmark_out="$out/bench.run$i.json" --benchmark_out_format=json \
        "$@" >/dev/null
done

python3 "$root/bench/predicates_report.py" "$out" "$runs" "$out/README.md" "$0 $*" \
    --readme "$root/README.md"
echo "wrote $out/bench.run*.json and $out/README.md"
