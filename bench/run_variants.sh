#!/usr/bin/env bash
# The algorithm variants at scale, with the CLI's own --stats: walking vs conflict graph, array
# vs face-hash storage, on 10^6 uniform points, and the default engine on 10^7 points. Writes
# results/variants/*.json, results/variants/README.md and the variants item of the top README.
#   bench/run_variants.sh [N] [BIG_N]    (defaults 1000000 and 10000000)
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-1000000}"
big="${2:-10000000}"
build="${BUILD_DIR:-build/release}"
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build "$build" --target cavity
cavity="$build/cli/cavity"
out=results/variants
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$cavity" generate cube "$n" --seed 1 -o "$work/cube.node" >/dev/null
for variant in "walk array" "conflict-graph array" "walk hash" "conflict-graph hash"; do
  set -- $variant
  "$cavity" triangulate "$work/cube.node" -o "$work/mesh" --locate "$1" --storage "$2" --quiet \
    --stats "$out/cube-$n-$1-$2.json"
done
"$cavity" generate cube "$big" --seed 1 -o "$work/big.node" >/dev/null
"$cavity" triangulate "$work/big.node" -o "$work/big" --quiet --stats "$out/cube-$big-walk-array.json"
/usr/bin/python3 bench/variants_report.py "$out" "$(uptime | sed 's/.*load average: //')" \
  --readme README.md > "$out/README.md"
cat "$out/README.md"
