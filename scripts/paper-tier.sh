#!/usr/bin/env bash
# Runs, or continues, the paper tier of a suite (default: theorem, Theorem 5.4 at 10^3..10^7) in
# N shards at once, and merges what is measured into results/experiments/paper/: the whole table
# when every run is done, else a partial one whose .meta.json says how many runs it holds (so the
# script can be stopped at any time, with Ctrl-C or a job scheduler's TERM, and started again
# later: nothing already measured is redone). Then it rewrites the plots and the report from the
# quick tier's tables and this one.
# Usage: scripts/paper-tier.sh [SHARDS [SUITE]]   (SHARDS defaults to the number of cores)
set -euo pipefail
cd "$(dirname "$0")/.."
shards="${1:-$(nproc)}"
suite="${2:-theorem}"
build=build/release
out=results/experiments/paper
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j2 --target cavity
cavity="$build/cli/cavity"
mkdir -p "$out"

pids=()
stop() {
  # Stopped from outside: end the shards, keep their finished runs.
  trap - INT TERM
  kill "${pids[@]}" 2>/dev/null || true
  wait || true
  merge
  exit 130
}
merge() {
  # The last shard to finish merges a complete tier itself and removes the parts; parts left
  # over mean a stopped tier. A run cut short leaves nothing in them: parts hold finished runs.
  if compgen -G "$out/$(basename "$suite" .suite).part-*-of-$shards.csv" > /dev/null; then
    "$cavity" experiment "$suite" --tier paper --shard "1/$shards" --merge --partial --out "$out" --quiet
  fi
  local meta
  meta="$out/$(basename "$suite" .suite).meta.json"
  echo "paper tier: $(grep -o '"runs_measured": [0-9]*' "$meta") of $(grep -o '"runs": [0-9]*' "$meta")"
  /usr/bin/python3 results/plot.py results/experiments/quick results/experiments/plots "$out"
  /usr/bin/python3 results/report.py results/experiments/quick results/README.md "$out"
}
trap stop INT TERM
for ((i = 1; i <= shards; ++i)); do
  "$cavity" experiment "$suite" --tier paper --resume --shard "$i/$shards" --out "$out" --quiet &
  pids+=($!)
done
wait "${pids[@]}"
trap - INT TERM
merge
