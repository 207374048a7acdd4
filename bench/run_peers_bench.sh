#!/usr/bin/env bash
# cavity against CGAL's Delaunay_triangulation_3 (Epick): time in the same process, and
# whole-process peak memory of each engine run alone. Writes results/peers/peers.csv and
# results/peers/README.md.
#   bench/run_peers_bench.sh [N]      N points (default 1000000; the grid is round(cbrt N)^3)
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-1000000}"
repeats="${REPEATS:-3}"
build="${BUILD_DIR:-build/release}"
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build "$build" --target peers_bench
bin="$build/bench/peers_bench"
out=results/peers
mkdir -p "$out"
csv="$out/peers.csv.tmp"
echo "distribution,n,engine,run,seconds,tets,peak_rss_bytes,baseline_rss_bytes" > "$csv"
for dist in cube grid sphere; do
  "$bin" --dist "$dist" --n "$n" --repeats "$repeats" >> "$csv"
  for engine in cavity cgal; do
    "$bin" --dist "$dist" --n "$n" --repeats 1 --only "$engine" >> "$csv"
  done
done
mv "$csv" "$out/peers.csv"
/usr/bin/python3 bench/peers_report.py "$out/peers.csv" "$n" "$(uptime | sed 's/.*load average: //')" > "$out/README.md"
cat "$out/README.md"
