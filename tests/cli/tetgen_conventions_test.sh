#!/usr/bin/env bash
# cavity and Debian's TetGen triangulate the same points; each program's .ele is checked with the
# other's convention: every tetrahedron of both has positive right-hand volume (counted exactly by
# volume_signs.py, independent of cavity), `cavity check` accepts TetGen's mesh, and a mesh in the
# inverted convention (cavity's files before 0.2) is refused by one message naming it. The .neigh
# and .face files are checked against their definitions and TetGen's boundary faces, and both
# programs carve the same domain out of a PLC (exact volumes).
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

# TetGen -p carves the same domain as cavity cdt: an L-shaped prism (volume 3/4 of its hull's
# 7/8) and a cube [0,4]^3 around [1,3]^3 whose shell is a volume hole (8 kept, region 9), the
# volumes summed exactly over the rationals from both programs' files.
exact_volume() {  # exact_volume NODE ELE: the sum of right-hand volumes, as a fraction
  "$python" - "$1" "$2" <<'PY'
import sys
from fractions import Fraction
def rows(path):
    for line in open(path):
        line = line.split("#", 1)[0].split()
        if line:
            yield line
node = rows(sys.argv[1])
n = int(next(node)[0])
p = {}
for f in node:
    if len(p) == n:
        break
    p[int(f[0])] = [Fraction(float(x)) for x in f[1:4]]
ele = rows(sys.argv[2])
m = int(next(ele)[0])
total = Fraction(0)
for _, f in zip(range(m), ele):
    a, b, c, d = (p[int(v)] for v in f[1:5])
    u, v, w = ([q[i] - a[i] for i in range(3)] for q in (b, c, d))
    total += (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
              + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6
print(total)
PY
}
{
  echo "12 3 0 0"
  i=0
  for z in 0 1; do
    for xy in "0 0" "1 0" "1 0.5" "0.5 0.5" "0.5 1" "0 1"; do echo "$i $xy $z"; i=$((i + 1)); done
  done
  echo "8 0"; echo 1; echo "6 0 1 2 3 4 5"; echo 1; echo "6 6 7 8 9 10 11"
  for i in 0 1 2 3 4 5; do j=$(((i + 1) % 6)); echo 1; echo "4 $i $j $((j + 6)) $((i + 6))"; done
  echo 0
} > lprism.poly
{
  echo "16 3 0 0"
  for i in $(seq 0 15); do
    s=$((i < 8 ? 4 : 2)); o=$((i < 8 ? 0 : 1)); k=$((i % 8))
    echo "$i $((o + (k & 1) * s)) $((o + ((k >> 1) & 1) * s)) $((o + ((k >> 2) & 1) * s))"
  done
  echo "12 0"
  for o in 0 8; do
    for q in "0 1 3 2" "4 5 7 6" "0 1 5 4" "2 3 7 6" "0 2 6 4" "1 3 7 5"; do
      echo 1; echo "4 $(for v in $q; do printf '%d ' $((v + o)); done)"
    done
  done
  echo 1; echo "0 0.5 0.5 0.5"; echo 2; echo "0 0.5 3.5 0.5 5"; echo "1 2 2 2 9"
} > shell.poly
for case in "lprism 3/4" "shell 8"; do
  read -r name expected <<< "$case"
  "$cavity" cdt "$name.poly" -o "$name.cavity" --quiet
  tetgen -pAQ "$name.poly" >/dev/null
  mine="$(exact_volume "$name.cavity.node" "$name.cavity.ele")"
  theirs="$(exact_volume "$name.1.node" "$name.1.ele")"
  [ "$mine" = "$expected" ] && [ "$theirs" = "$expected" ] ||
    fail "$name: cavity's domain has volume $mine, TetGen's $theirs, expected $expected"
done
awk 'NR > 1 && $1 !~ /^#/ && NF >= 6 && $6 != 9 { bad = 1 } END { exit bad }' shell.1.ele ||
  fail "shell: TetGen's kept tetrahedra are not all in region 9: the test's premise is wrong"

# The inverted convention is refused by one message that names it.
awk 'NR == 1 || $1 ~ /^#/ { print; next } { print $1, $3, $2, $4, $5 }' cube.cavity.ele > inverted.ele
"$cavity" check cube.node inverted.ele --quiet 2>err.txt && fail "check accepts an inverted mesh"
grep -q "inverted.ele: all [0-9]* non-flat tetrahedra have negative volume" err.txt ||
  fail "inverted mesh: unexpected message: $(cat err.txt)"
echo "cavity and TetGen agree on the orientation convention"
