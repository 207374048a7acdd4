#!/usr/bin/env bash
# The command line's conventions: --version everywhere, the documented exit statuses, counts in
# the forms the field writes them, range messages, out-of-memory messages naming the operation,
# jtets' warning before a long run.
set -euo pipefail
cavity="$1"
version="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
status() { set +e; "$@" >out.txt 2>err.txt; local s=$?; set -e; echo "$s"; }

[ "$("$cavity" --version)" = "cavity $version" ] || fail "cavity --version"
for command in sign generate triangulate check cdt jtets experiment; do
  [ "$("$cavity" "$command" --version)" = "cavity $version" ] || fail "$command --version"
  "$cavity" "$command" --help | grep -q "Exit status: 0 success; 1 bad input" ||
    fail "$command --help does not list the exit statuses"
done

# 2: usage.
[ "$(status "$cavity" no-such-command)" = 2 ] || fail "unknown command: not 2"
[ "$(status "$cavity" triangulate)" = 2 ] || fail "missing argument: not 2"
[ "$(status "$cavity" triangulate x.node -o y --order spiral)" = 2 ] || fail "bad choice: not 2"
[ "$(status "$cavity" generate cube 3 -o p.node)" = 2 ] || fail "n = 3: not 2"
grep -q "^cavity: n must be between 4 and 4294967295" err.txt || fail "range message: $(cat err.txt)"
[ "$(status "$cavity" generate cube 2.5 -o p.node)" = 2 ] || fail "n = 2.5: not 2"
[ "$(status "$cavity" generate cube 1e10 -o p.node)" = 2 ] || fail "n = 1e10: not 2"
[ "$(status "$cavity" generate cube 100 --seed -1 -o p.node)" = 2 ] || fail "--seed -1: not 2"
grep -q "seed must be between 0 and 18446744073709551615" err.txt || fail "seed: $(cat err.txt)"

# Counts in the forms the field writes them.
for n in 2000 2_000 2e3 2.0e3; do
  [ "$(status "$cavity" generate cube "$n" -o "p$n.xyz")" = 0 ] || fail "n = $n refused: $(cat err.txt)"
  [ "$(wc -l < "p$n.xyz")" = 2000 ] || fail "n = $n: not 2000 points"
done

# 1: bad input, or a refused request.
printf '3 3 0 0\n0 0 0 0\n1 1 0 0\n' > short.node
[ "$(status "$cavity" triangulate short.node -o t)" = 1 ] || fail "truncated file: not 1"
grep -q "short.node:3: file ends after 2 of 3 points" err.txt || fail "message: $(cat err.txt)"
mkdir folder.node
[ "$(status "$cavity" triangulate folder.node -o t)" = 1 ] || fail "directory: not 1"
grep -q "folder.node: is a directory" err.txt || fail "directory message: $(cat err.txt)"

# 3: out of memory, named. A sanitizer build reserves terabytes of address space and cannot run
# under a memory limit at all; there the check is skipped, and says so.
"$cavity" generate cube 400000 -o big.node >/dev/null
if (ulimit -v 600000; "$cavity" --version >/dev/null 2>&1); then
  [ "$(status bash -c "ulimit -v 60000; exec \"$cavity\" triangulate big.node -o big")" = 3 ] ||
    fail "out of memory: not 3: $(cat err.txt)"
  grep -Eq "^cavity: out of memory (reading|ordering|triangulating) big.node" err.txt ||
    fail "out-of-memory message: $(cat err.txt)"
  [ ! -e big.ele ] || fail "out of memory: a mesh was written"
  [ "$(status bash -c "ulimit -v 200000; exec \"$cavity\" generate cube 2e8 -o huge.node")" = 3 ] ||
    fail "generate out of memory: not 3"
  grep -q "^cavity: out of memory generating 200000000 cube points (about 4.5 GiB)" err.txt ||
    fail "generate message: $(cat err.txt)"
else
  echo "conventions: this build cannot run under ulimit -v (sanitizers); out-of-memory checks skipped"
fi

# jtets warns before a run that will take minutes (and the run is stopped here).
"$cavity" generate cube 600 -o j.node >/dev/null
set +e
timeout 8 "$cavity" jtets j.node -o j.csv 2>err.txt
set -e
grep -q "cavity jtets: 600 points will take about .* minutes (the cost grows like n^4" err.txt ||
  fail "jtets: no cost warning: $(cat err.txt)"
[ ! -e j.csv ] || fail "jtets: a stopped run left its CSV"

# --stats names the version.
"$cavity" triangulate p2000.xyz -o t --stats t.json --quiet
grep -q "\"version\": \"$version\"" t.json || fail "--stats has no version"
echo "command-line conventions hold"
