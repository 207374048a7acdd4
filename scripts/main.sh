#!/usr/bin/env bash
# The README's main command: installs what is missing, builds cavity (Release, build/release),
# and regenerates the quick tier of the experiments — CSVs in results/experiments/quick/, plots in
# results/experiments/plots/, the report in results/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
scripts/experiments-quick.sh build/release
echo
echo "cavity: build/release/cli/cavity"
echo "report: results/README.md (plots in results/experiments/plots/, tables in results/experiments/quick/)"
