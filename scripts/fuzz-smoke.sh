#!/usr/bin/env bash
# A short libFuzzer run of every file reader (and the predicates), for CI: builds the fuzz preset
# (clang, ASan + UBSan incl. float-cast-overflow, coverage-guided) and runs each target for
# SECONDS (default 20) from the seed files in fuzz/seeds/. A crash, sanitizer report, non-cavity
# exception, leak or an allocation above 2 GB fails the run and leaves the reproducer in
# build/fuzz/findings/.
#   scripts/fuzz-smoke.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
scripts/install-deps.sh
cmake --preset fuzz >/dev/null
targets=(node_fuzz ele_fuzz poly_fuzz ply_fuzz xyz_fuzz off_fuzz stl_fuzz obj_fuzz predicates_fuzz)
cmake --build --preset fuzz --target "${targets[@]}"
findings=build/fuzz/findings
mkdir -p "$findings"
for target in "${targets[@]}"; do
  format="${target%_fuzz}"
  corpus="$(mktemp -d)"
  if [ -d "fuzz/seeds/$format" ]; then
    cp "fuzz/seeds/$format"/* "$corpus"/
  fi
  echo "fuzz-smoke: $target for ${seconds} s" >&2
  "build/fuzz/fuzz/$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
    -artifact_prefix="$findings/$target-" -print_final_stats=1 "$corpus" 2>"$findings/$target.log" ||
    { tail -40 "$findings/$target.log" >&2; rm -rf "$corpus"; exit 1; }
  grep -E "^stat::number_of_executed_units" "$findings/$target.log" >&2 || true
  rm -rf "$corpus"
done
echo "fuzz-smoke: every target ran ${seconds} s without a finding" >&2
