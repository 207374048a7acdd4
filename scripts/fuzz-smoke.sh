#!/usr/bin/env bash
# A short libFuzzer run of every file reader (and the predicates), for CI: builds the fuzz preset
# (clang, ASan + UBSan incl. float-cast-overflow, coverage-guided) and runs each target for
# SECONDS (default 20), two at a time, from the seed files in fuzz/seeds/. A crash, sanitizer
# report, non-cavity exception, leak or an allocation above 2 GB fails the run and leaves the
# reproducer in build/fuzz/findings/.
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
fuzz_one() {
  local target=$1 corpus
  corpus="$(mktemp -d)"
  if [ -d "fuzz/seeds/${target%_fuzz}" ]; then
    cp "fuzz/seeds/${target%_fuzz}"/* "$corpus"/
  fi
  echo "fuzz-smoke: $target for ${seconds} s" >&2
  if ! "build/fuzz/fuzz/$target" -max_total_time="$seconds" -rss_limit_mb=2048 \
    -timeout=10 -artifact_prefix="$findings/$target-" -print_final_stats=1 "$corpus" \
    2>"$findings/$target.log"; then
    tail -40 "$findings/$target.log" >&2
    rm -rf "$corpus"
    return 1
  fi
  grep -E "^stat::number_of_executed_units" "$findings/$target.log" |
    sed "s/^/$target /" >&2 || true
  rm -rf "$corpus"
}
# Two targets at a time (libFuzzer runs on one core; CI has two), each for the full SECONDS.
for ((i = 0; i < ${#targets[@]}; i += 2)); do
  pids=()
  for target in "${targets[@]:i:2}"; do
    fuzz_one "$target" &
    pids+=($!)
  done
  failed=0
  for pid in "${pids[@]}"; do
    wait "$pid" || failed=1
  done
  [ "$failed" = 0 ] || exit 1
done
echo "fuzz-smoke: every target ran ${seconds} s without a finding" >&2
