#!/usr/bin/env bash
# Issue 13's scale goal: the default engine (BRIO order + sequential triangulation, exact) on N
# uniform points generated in the process, whole-process peak memory against 24 GiB. One run,
# nothing written but the measurement: at 10^8 points a TetGen .ele alone would be ~20 GB of text,
# which measures the disk, not the engine. Writes results/scale/scale.csv, results/scale/README.md
# and the scale item of the top README.
#   bench/run_scale_bench.sh [N]    (default 100000000; needs about 245 bytes per point)
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-100000000}"
build="${BUILD_DIR:-build/release}"
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build "$build" --target peers_bench
out=results/scale
mkdir -p "$out"
csv="$out/scale.csv.tmp"
echo "distribution,n,engine,threads,run,seconds,wall_seconds,tets,peak_rss_bytes,baseline_rss_bytes" > "$csv"
"$build/bench/peers_bench" --dist cube --n "$n" --repeats 1 --only cavity >> "$csv"
mv "$csv" "$out/scale.csv"
# %.0f, not %d: mawk's %d stops at 2^31 - 1, which read a 24 GiB machine as 2 GiB.
mem_total=$(awk '/^MemTotal:/ {printf "%.0f", $2 * 1024}' /proc/meminfo)
/usr/bin/python3 bench/scale_report.py "$out/scale.csv" "$mem_total" \
  "$(uptime | sed 's/.*load average: //')" --readme README.md > "$out/README.md"
cat "$out/README.md"
