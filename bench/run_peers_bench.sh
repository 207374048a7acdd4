#!/usr/bin/env bash
# cavity against CGAL's Delaunay_triangulation_3 (Epick), and cavity's parallel construction
# against its sequential engine: time in the same process, and whole-process peak memory of each
# engine run alone. Writes results/peers/peers.csv and results/peers/README.md.
#   bench/run_peers_bench.sh [N]      N points (default 1000000; the grid is round(cbrt N)^3)
#   THREADS=T (default 2) threads for the parallel construction; REPEATS=R (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-1000000}"
repeats="${REPEATS:-3}"
threads="${THREADS:-2}"
build="${BUILD_DIR:-build/release}"
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build "$build" --target peers_bench
bin="$build/bench/peers_bench"
out=results/peers
mkdir -p "$out"
csv="$out/peers.csv.tmp"
echo "distribution,n,engine,threads,run,seconds,wall_seconds,tets,peak_rss_bytes,baseline_rss_bytes" > "$csv"
for dist in cube grid sphere; do
  "$bin" --dist "$dist" --n "$n" --repeats "$repeats" --threads "$threads" >> "$csv"
  for engine in cavity cgal cavity-threads; do
    "$bin" --dist "$dist" --n "$n" --repeats 1 --threads "$threads" --only "$engine" >> "$csv"
  done
done
mv "$csv" "$out/peers.csv"
/usr/bin/python3 bench/peers_report.py "$out/peers.csv" "$n" "$(uptime | sed 's/.*load average: //')" \
  --readme README.md > "$out/README.md"
cat "$out/README.md"
