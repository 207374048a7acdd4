#!/usr/bin/env bash
# Regenerates the quick tier of every experiment suite, the plots and the summary tables:
#   results/experiments/quick/*.csv, *.j.csv, *.meta.json   (cavity experiment)
#   results/experiments/plots/*.png, *.svg, summary.md       (results/plot.py)
#   the generated sections of results/README.md              (results/report.py)
# The report, results/README.md, embeds those plots. Measured on the 2-core project machine:
# see results/README.md for the time this takes. Usage: scripts/experiments-quick.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
# Always brought up to date: tables written by a stale program would name the wrong commit.
cmake --build "$build" -j2 --target cavity
out=results/experiments/quick
paper=results/experiments/paper  # the paper tier's tables, when committed (see results/README.md)
start=$(date +%s)
cost="suite,wall_s,load_average"
for suite in jtets creation brio scaling theorem theorem-prefix locality quadratic walk adversarial extend degenerate peers giftwrap deletion cdt cdtvalid; do
  t0=$(date +%s)
  "$build/cli/cavity" experiment "$suite" --tier quick --out "$out" --quiet
  cost+=$'\n'"$suite,$(( $(date +%s) - t0 )),$(cut -d' ' -f1 /proc/loadavg)"
  echo "$suite: $(( $(date +%s) - t0 )) s"
done
# The report's cost section is written from this table: wall time per suite and the load average
# when the suite ended (other jobs on the machine slow the wall clock).
printf '%s\n' "$cost" > "$out/cost.csv.tmp" && mv "$out/cost.csv.tmp" "$out/cost.csv"
# Debian's matplotlib: /usr/bin/python3, not whichever python3 comes first on PATH.
/usr/bin/python3 results/plot.py "$out" results/experiments/plots "$paper"
/usr/bin/python3 results/report.py "$out" results/README.md "$paper"
echo "quick tier: $(( $(date +%s) - start )) s in all; report: results/README.md"
