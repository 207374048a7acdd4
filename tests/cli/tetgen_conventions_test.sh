#!/usr/bin/env bash
# cavity and Debian's TetGen triangulate the same points; each program's .ele is checked with the
# other's convention: every tetrahedron of both has positive right-hand volume (counted exactly by
# volume_signs.py, independent of cavity), `cavity check` accepts TetGen's mesh, and a mesh in the
# inverted convention (cavity's files before 0.2) is refused by one message naming it. The .neigh
# and .face files are checked against their definitions and TetGen's boundary faces.
set -euo pipefail
cavity="$1"
here="$(cd "$(dirname "$0")" && pwd)"
python=/usr/bin/python3
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# A grid makes the Delaunay triangulation degenerate: TetGen and cavity may break ties apart, but
# both must be valid and positively oriented.
for dist in cube grid; do
  "$cavity" generate "$dist" 1000 -o "$dist.node" >/dev/null
  "$cavity" triangulate "$dist.node" -o "$dist.cavity" --quiet
  tetgen -Q "$dist.node" >/dev/null
  read -r pos neg flat < <("$python" "$here/volume_signs.py" "$dist.node" "$dist.cavity.ele")
  [ "$neg" = 0 ] && [ "$flat" = 0 ] && [ "$pos" -gt 0 ] ||
    fail "$dist: cavity's .ele has $pos positive, $neg negative, $flat flat tetrahedra"
  read -r pos neg flat < <("$python" "$here/volume_signs.py" "$dist.node" "$dist.1.ele")
  [ "$neg" = 0 ] && [ "$flat" = 0 ] ||
    fail "$dist: TetGen's .ele has $neg negative, $flat flat tetrahedra: the test's premise is wrong"
  "$cavity" check "$dist.1.node" "$dist.1.ele" --quiet 2>err.txt ||
    fail "$dist: cavity check rejects TetGen's mesh: $(head -3 err.txt)"
  "$cavity" check "$dist.node" "$dist.cavity.ele" --quiet 2>err.txt ||
    fail "$dist: cavity check rejects cavity's mesh: $(head -3 err.txt)"
done

# TetGen reads cavity's .ele back (-r), header comment included.
tetgen -rQ cube.cavity >/dev/null || fail "tetgen -r cannot read cavity's mesh"

# On points in general position the Delaunay triangulation is unique: the same tetrahedra.
sorted() { awk 'NR > 1 && $1 !~ /^#/ && NF >= 5 { print $2; print $3; print $4; print $5 }' "$1" |
  "$python" -c 'import sys; v = sys.stdin.read().split()
print(sorted(tuple(sorted(map(int, v[i:i + 4]))) for i in range(0, len(v), 4)))'; }
a="$(sorted cube.cavity.ele)"
b="$(sorted cube.1.ele)"
[ "${#a}" -gt 100 ] && [ "$a" = "$b" ] || fail "cube: cavity and TetGen differ"

# TetGen's companions: .neigh (-n) and the hull's .face, against TetGen's boundary faces.
"$cavity" triangulate cube.node -o cube.companions -n -f --quiet
"$python" "$here/tetgen_companions.py" cube.companions cube.1.face >/dev/null ||
  fail "cube: .neigh or .face wrong"
awk 'NR == 1 { print; next } { $1 = $1 + 1; print }' cube.node > one.node  # 1-based numbering
"$cavity" triangulate one.node -o one.companions -n -f --quiet
tetgen -Q one.node >/dev/null
"$python" "$here/tetgen_companions.py" one.companions one.1.face >/dev/null ||
  fail "1-based: .neigh or .face wrong"

# The inverted convention is refused by one message that names it.
awk 'NR == 1 || $1 ~ /^#/ { print; next } { print $1, $3, $2, $4, $5 }' cube.cavity.ele > inverted.ele
"$cavity" check cube.node inverted.ele --quiet 2>err.txt && fail "check accepts an inverted mesh"
grep -q "inverted.ele: all [0-9]* non-flat tetrahedra have negative volume" err.txt ||
  fail "inverted mesh: unexpected message: $(cat err.txt)"
echo "cavity and TetGen agree on the orientation convention"
