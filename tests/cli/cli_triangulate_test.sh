#!/usr/bin/env bash
# `cavity triangulate` and `cavity check` end to end: outputs, reports, and every bad input
# (message naming the file and line or the reason, non-zero exit, no mesh file written).
set -u
cavity="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_error NAME FILE PATTERN: triangulating FILE fails, the message matches PATTERN, and no
# output appears.
expect_error() {
  local name="$1" file="$2" pattern="$3"
  if "$cavity" triangulate "$file" -o "out_$name" --quiet 2>err.txt; then
    fail "$name: exit status 0"
  fi
  grep -q -- "$pattern" err.txt || fail "$name: message '$(cat err.txt)' lacks '$pattern'"
  ls "out_$name".* >/dev/null 2>&1 && fail "$name: output written"
  ls .out_"$name"* >/dev/null 2>&1 && fail "$name: temporary left behind"
}

printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 nan\n4 1 1 1\n' > nan.node
expect_error nan nan.node "nan.node:5"
printf '5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 inf\n4 1 1 1\n' > inf.node
expect_error inf inf.node "nan.node:5\|inf.node:5"
printf '0 0 0\n1 0 0\n0 1 1e400\n0 0 1\n' > big.xyz
expect_error out_of_range big.xyz "big.xyz:3"
printf '6 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n' > truncated.node
expect_error truncated truncated.node "truncated.node"
: > empty.xyz
expect_error empty empty.xyz "empty.xyz"
printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 3 0\n' > flat.xyz
expect_error coplanar flat.xyz "affine dimension 2"
printf '0 0 0\n1 2 3\n2 4 6\n3 6 9\n' > line.xyz
expect_error collinear line.xyz "affine dimension 1"
printf '0 0 0\n1 0 0\n0 1 0\n1 0 0\n0 1 0\n' > three.xyz
expect_error three_distinct three.xyz "fewer than 4 distinct"
printf '0 0 0\n1 0 zero\n' > word.xyz
expect_error unparsable word.xyz "word.xyz:2"

# A 1-based .node with a duplicate: the output keeps the numbering, the duplicate is reported.
printf '6 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n6 1 0 0\n' > dup.node
"$cavity" triangulate dup.node -o dup --check --stats dup.json 2>err.txt >out.txt || fail "dup: failed"
grep -q "6->2" err.txt || fail "dup: duplicate not reported: $(cat err.txt)"
# The five points are cospherical: 2 or 3 tetrahedra are Delaunay; the perturbation keyed on the
# input index picks 3 (a golden value: it changes only if the perturbation does).
head -1 dup.ele | grep -q "^3 " || fail "dup: expected 3 tetrahedra, got '$(head -1 dup.ele)'"
awk 'NR>1 && !/^#/ {for (i=2;i<=5;i++) if ($i<1 || $i>5) bad=1} END {exit bad}' dup.ele || fail "dup: indices not 1-based"
grep -q '"duplicates": 1' dup.json || fail "dup: stats lack the duplicate count"
grep -q '"triangulate_s"' dup.json || fail "dup: stats lack timings"
grep -q '"engine": "counting"' dup.json || fail "dup: stats do not name the engine"
# Every predicate's calls by deciding stage, the static filter's among them.
[ "$(grep -c '"static": ' dup.json)" = 4 ] || fail "dup: predicate_stages lack the static stage"
"$cavity" check dup.node dup.ele --quiet || fail "check rejects a valid mesh"

# cavity check catches a flipped tetrahedron and a missing one.
"$cavity" generate cube 200 -o cube.node >/dev/null
"$cavity" triangulate cube.node -o cube --quiet --order random --locate conflict-graph --storage hash || fail "cube: failed"
"$cavity" check cube.node cube.ele --quiet || fail "cube: check rejects a valid mesh"
awk 'NR==2 {t=$3; $3=$4; $4=t} {print}' cube.ele > flipped.ele
"$cavity" check cube.node flipped.ele --quiet 2>err.txt && fail "check accepts a flipped tetrahedron"
grep -q "volume not positive" err.txt || fail "flipped: message '$(cat err.txt)'"
awk 'NR==1 {$1=$1-1} NR!=2 {print}' cube.ele | awk 'NR==1 {print; next} {$1=NR-2; print}' > missing.ele
"$cavity" check cube.node missing.ele --quiet 2>err.txt && fail "check accepts a mesh with a hole"

# Weighted input: a heavy point submerges its neighbours, which are reported.
printf '9 3 1 0\n0 0 0 0 0\n1 4 0 0 0\n2 0 4 0 0\n3 0 0 4 0\n4 4 4 4 0\n5 1 1 1 0\n6 1.2 1 1 0\n7 1 1.2 1 0\n8 1.1 1.1 1.1 5\n' > w.node
"$cavity" triangulate w.node -o w --weighted --check 2>err.txt >/dev/null || fail "weighted: failed: $(cat err.txt)"
grep -q "redundant" err.txt || fail "weighted: redundant points not reported"
"$cavity" check w.node w.ele --weighted --quiet || fail "weighted: check rejects"

# --delete: the result is the (exactly checked) triangulation of the other points; the deleted
# ones are gone. (That it equals triangulating without them is tested in tests/core/edit.)
"$cavity" generate grid 125 -o grid.node >/dev/null
"$cavity" triangulate grid.node -o deleted --delete 0,7,62,124 --check --quiet || fail "delete: failed"
awk 'NR>1 && !/^#/ {for (i=2;i<=5;i++) if ($i==0 || $i==7 || $i==62 || $i==124) bad=1} END {exit bad}' deleted.ele \
  || fail "delete: a deleted point is still a vertex"
"$cavity" triangulate grid.node -o bad_delete --delete 125 --quiet 2>err.txt && fail "delete: out-of-range id accepted"
grep -q "not in" err.txt || fail "delete: message '$(cat err.txt)'"
# The mesh after --delete is checkable: with the same list it is valid, without it the deleted
# points are reported missing, and a wrong list is refused.
"$cavity" check deleted.node deleted.ele --deleted 0,7,62,124 --quiet ||
  fail "delete: check --deleted rejects the mesh"
"$cavity" check deleted.node deleted.ele --quiet 2>/dev/null &&
  fail "delete: check accepts a mesh missing four points"
"$cavity" check deleted.node deleted.ele --deleted 0,7,62 --quiet 2>/dev/null &&
  fail "delete: check accepts a wrong --deleted list"

# cavity cdt and cavity check --poly: a box split by a square through its middle.
cat > box.poly <<'POLY'
12 3 0 0
1 0 0 0
2 2 0 0
3 2 2 0
4 0 2 0
5 0 0 2
6 2 0 2
7 2 2 2
8 0 2 2
9 0 0 1
10 2 0 1
11 2 2 1
12 0 2 1
7 0
1
4 1 2 3 4
1
4 5 6 7 8
1
6 1 2 10 6 5 9
1
6 2 3 11 7 6 10
1
6 3 4 12 8 7 11
1
6 4 1 9 5 8 12
1
4 9 10 11 12
0
POLY
"$cavity" cdt box.poly -o box --quiet || fail "cdt: failed"
"$cavity" check box.node box.ele --poly box.poly --quiet || fail "check --poly rejects a valid CDT"
awk 'NR==2 {t=$3; $3=$4; $4=t} {print}' box.ele > box_flipped.ele
"$cavity" check box.node box_flipped.ele --poly box.poly --quiet 2>/dev/null && fail "check --poly accepts a flipped tetrahedron"

# Carving: the prism over an L (the unit square minus [1/2, 1]^2, z in [0, 1]) keeps its volume
# 3/4 and nothing in the notch; --convex-hull keeps the hull (7/8), and check --poly validates
# each as what it is.
lprism() {  # lprism HOLES: the .poly with the given hole list (count line, then points)
  printf '12 3 0 0\n'
  local i=0
  for z in 0 1; do
    for xy in "0 0" "1 0" "1 0.5" "0.5 0.5" "0.5 1" "0 1"; do
      echo "$i $xy $z"; i=$((i + 1))
    done
  done
  printf '8 0\n1\n6 0 1 2 3 4 5\n1\n6 6 7 8 9 10 11\n'
  for i in 0 1 2 3 4 5; do
    j=$(((i + 1) % 6))
    printf '1\n4 %d %d %d %d\n' "$i" "$j" $((j + 6)) $((i + 6))
  done
  printf '%b' "$1"
}
lprism '0\n' > lprism.poly
"$cavity" cdt lprism.poly -o lprism --protect > lprism.txt || fail "carve: cdt failed"
volume=$(sed -n 's/.*exterior and holes removed): [0-9]* tetrahedra kept, [1-9][0-9]* removed, volume \([0-9.e+-]*\)$/\1/p' lprism.txt)
awk -v v="${volume:-nan}" 'BEGIN {exit !(v - 0.75 <= 1e-15 && 0.75 - v <= 1e-15)}' ||
  fail "carve: volume '$volume' is not 0.75 in '$(grep domain lprism.txt)'"
"$cavity" check lprism.node lprism.ele --poly lprism.poly --quiet || fail "carve: check --poly rejects it"
"$cavity" check lprism.node lprism.ele --poly lprism.poly --convex-hull --quiet 2>/dev/null &&
  fail "carve: check --poly --convex-hull accepts the carved L"
"$cavity" cdt lprism.poly -o lhull --protect --convex-hull > lhull.txt || fail "carve: --convex-hull failed"
grep -q "domain (convex hull): [0-9]* tetrahedra kept, 0 removed, volume 0.87" lhull.txt ||
  fail "carve: --convex-hull: '$(grep domain lhull.txt)'"
"$cavity" check lhull.node lhull.ele --poly lprism.poly --convex-hull --quiet ||
  fail "carve: check --poly --convex-hull rejects the hull"
"$cavity" check lhull.node lhull.ele --poly lprism.poly --quiet 2>/dev/null &&
  fail "carve: check --poly accepts the hull of the L as its domain"
# Each tetrahedron of an .ele (the header and comments skipped) as the even permutation of its
# vertices that puts the least first and the least of the others second: the same oriented
# tetrahedra give the same sorted lines, whatever the storage's slot order or each record's
# rotation.
oriented_tets() {
  awk '{ sub(/#.*/, "") } NF >= 5 { v[0] = $2; v[1] = $3; v[2] = $4; v[3] = $5
    m = 0; for (i = 1; i < 4; i++) if (v[i] + 0 < v[m] + 0) m = i
    if (m == 0) { a = v[0]; x = v[1]; y = v[2]; z = v[3] }
    if (m == 1) { a = v[1]; x = v[0]; y = v[3]; z = v[2] }
    if (m == 2) { a = v[2]; x = v[0]; y = v[1]; z = v[3] }
    if (m == 3) { a = v[3]; x = v[0]; y = v[2]; z = v[1] }
    if (y + 0 < x + 0 && y + 0 < z + 0) { t = x; x = y; y = z; z = t }
    else if (z + 0 < x + 0) { t = z; z = y; y = x; x = t }
    print a, x, y, z }' "$1" | sort
}
# --convex-hull writes the tetrahedra, with their orientation, that `cavity cdt` wrote before
# carving existed (commit b17c6bf), and the carved .ele lists some of those tetrahedra.
cat > lhull_expected.ele <<'ELE'
0 2 10 3 9
1 3 10 2 4
2 4 3 10 11
3 10 3 9 11
4 9 0 6 11
5 8 10 2 9
6 5 3 4 11
7 3 0 9 11
8 2 1 8 9
9 3 1 2 9
10 8 1 7 9
11 7 0 6 9
12 1 0 7 9
13 3 0 1 9
14 5 0 3 11
ELE
[ "$(oriented_tets lhull.ele)" = "$(oriented_tets lhull_expected.ele)" ] ||
  fail "carve: --convex-hull output changed"
oriented_tets lhull_expected.ele > lhull_tets.txt
oriented_tets lprism.ele | grep -qvxFf lhull_tets.txt &&
  fail "carve: a kept tetrahedron is not one of the hull's"
kept=$(head -1 lprism.ele | cut -d' ' -f1)
removed=$(sed -n 's/.* kept, \([0-9]*\) removed.*/\1/p' lprism.txt)
[ "$((kept + removed))" = "$(head -1 lhull.ele | cut -d' ' -f1)" ] ||
  fail "carve: $kept kept + $removed removed is not the hull's $(head -1 lhull.ele)"
# A convex PLC (the box) is its own hull: the same files either way.
"$cavity" cdt box.poly -o boxhull --convex-hull --quiet || fail "carve: box --convex-hull failed"
cmp -s box.ele boxhull.ele || fail "carve: the box's domain differs from its hull"
# A hole point outside the hull, or on a polygon, is refused by its line; nothing is written.
lprism '2\n0 0.25 0.25 0.5\n1 0.75 0.75 0.5\n' > lnotch.poly
lprism '1\n0 0.25 0.25 2\n' > lout.poly
lprism '1\n0 0.25 0.25 1\n' > lon.poly
"$cavity" cdt lout.poly -o lout --protect 2>err.txt && fail "carve: hole outside accepted"
grep -q "lout.poly:32: volume hole point lies outside" err.txt || fail "carve: '$(cat err.txt)'"
ls lout.* 2>/dev/null | grep -qv 'lout.poly' && fail "carve: hole outside wrote output"
"$cavity" cdt lon.poly -o lon --protect 2>err.txt && fail "carve: hole on a polygon accepted"
grep -q "lon.poly:32: volume hole point lies on a polygon" err.txt || fail "carve: '$(cat err.txt)'"
# A hole point in the notch (the exterior) removes nothing more; one in the L removes it all.
"$cavity" cdt lnotch.poly -o lnotch --protect > lnotch.txt 2>err.txt || fail "carve: notch holes failed"
grep -q "0 tetrahedra kept" lnotch.txt || fail "carve: the L's hole left '$(grep domain lnotch.txt)'"
grep -q "lnotch.poly: the polygons enclose no volume" err.txt || fail "carve: no warning: '$(cat err.txt)'"
# A hole in the box's lower half: the upper half (volume 4 of 8) stays, with the lower half of
# each side polygon and the bottom gone with the hole, and check --poly accepts it.
sed '$ s/^0$/1\n1 1 1 0.5/' box.poly > boxhole.poly
"$cavity" cdt boxhole.poly -o boxhole > boxhole.txt || fail "carve: box with a hole failed"
volume=$(sed -n 's/.* removed, volume \([0-9.e+-]*\)$/\1/p' boxhole.txt)
awk -v v="${volume:-nan}" 'BEGIN {exit !(v - 4 <= 4e-15 && 4 - v <= 4e-15)}' ||
  fail "carve: box with a hole: '$(grep domain boxhole.txt)'"
"$cavity" check box.node boxhole.ele --poly boxhole.poly --quiet || fail "carve: check rejects the upper half"
"$cavity" check box.node box.ele --poly boxhole.poly --quiet 2>err.txt && fail "carve: check accepts the hole kept"
grep -q "volume hole point 1 (line 31) lies in tetrahedron" err.txt || fail "carve: '$(cat err.txt)'"

# VTU output.
"$cavity" triangulate cube.node -o cube --format vtu --quiet || fail "vtu: failed"
grep -q "UnstructuredGrid" cube.vtu || fail "vtu: not a VTK XML file"

# The input's point attributes and boundary markers survive into the output .node, exactly; with
# --weighted the weight is the first of them.
printf '%s\n' '# cube corners, two attributes and a marker' '8 3 2 1' \
  '1 0 0 0 0.5 -7 3' '2 1 0 0 0.25 1e-300 0' '3 0 1 0 0.125 2 -1' '4 1 1 0 0 3 3' \
  '5 0 0 1 0 4 3' '6 1 0 1 0 5 3' '7 0 1 1 0 6 0' '8 1 1 1 0.75 7.5 2' > attr.node
for w in "" --weighted; do
  "$cavity" triangulate attr.node -o attr_out $w --quiet || fail "attributes$w: failed"
  tail -n +2 attr_out.node | awk '{ printf "%s %s %s %s %s %s %s\n", $1, $2, $3, $4, $5, $6, $7 }' > got.txt
  tail -n +3 attr.node > want.txt
  cmp -s got.txt want.txt || fail "attributes$w: output .node differs: $(diff want.txt got.txt | head -3)"
  [ "$(head -1 attr_out.node)" = "8 3 2 1" ] || fail "attributes$w: header '$(head -1 attr_out.node)'"
done

# A prefix ending in the format's extension is not doubled; --stats over the input or an output
# file is refused before anything runs; --stats writes JSON booleans.
"$cavity" triangulate cube.node -o named.vtu --format vtu --quiet || fail "named.vtu: failed"
[ -f named.vtu ] && [ ! -e named.vtu.vtu ] || fail "-o named.vtu wrote named.vtu.vtu"
"$cavity" triangulate cube.node -o named.node --quiet || fail "named.node: failed"
[ -f named.ele ] && [ ! -e named.node.ele ] || fail "-o named.node wrote named.node.ele"
for target in named.ele cube.node ./named.node; do
  "$cavity" triangulate cube.node -o named --stats "$target" --quiet 2>err.txt &&
    fail "--stats $target accepted"
  grep -q "would overwrite" err.txt || fail "--stats $target: message '$(cat err.txt)'"
done
"$cavity" triangulate cube.node -o named --stats named.json --quiet || fail "stats: failed"
grep -q '"weighted": false' named.json || fail "stats: weighted is not a JSON boolean"

# A .node and a .ele of two different runs (two runs on one prefix, or one killed between its
# renames) are told apart by the points fingerprint in the .ele's header comment.
"$cavity" generate cube 50 --seed 1 -o run1.node >/dev/null
"$cavity" generate cube 50 --seed 2 -o run2.node >/dev/null
"$cavity" triangulate run1.node -o run1 --quiet || fail "run1: failed"
"$cavity" triangulate run2.node -o run2 --quiet || fail "run2: failed"
"$cavity" check run2.node run1.ele --quiet 2>err.txt && fail "check accepts a .ele of other points"
grep -q "run1.ele: was written for other points than those of run2.node" err.txt ||
  fail "mixed runs: message '$(cat err.txt)'"
"$cavity" check run1.node run1.ele --quiet || fail "check rejects its own run"

# An interrupted run leaves no half-set: a --stats path that cannot be written stops the run
# before any mesh file is committed, and an earlier mesh stays as it was.
cp run1.ele before.ele
"$cavity" triangulate run2.node -o run1 --stats no_such_dir/s.json --quiet 2>err.txt &&
  fail "an unwritable --stats path is accepted"
cmp -s run1.ele before.ele || fail "a failed run replaced the .ele"
"$cavity" check run1.node run1.ele --quiet || fail "a failed run broke the earlier mesh"

# --count-conflicts: Theorem 5.4's counters appear in --stats (and only when asked), the same for
# both locators, and every conflict created is deleted by the end.
"$cavity" generate cube 500 --seed 3 -o conf.node >/dev/null
"$cavity" triangulate conf.node -o conf --count-conflicts --stats conf.json >out.txt || fail "conflicts: failed"
grep -q "conflicts: .* created by solid tetrahedra" out.txt || fail "conflicts: no summary line"
for key in conflicts_created ghost_conflicts_created conflicts_deleted live_conflicts_max; do
  grep -q "\"$key\": [1-9]" conf.json || fail "conflicts: stats lack $key"
done
grep -q '"conflicts_counted": true' conf.json || fail "conflicts: not marked as counted"
grep -q '"engine": "counting+conflict-counter"' conf.json || fail "conflicts: engine not named"
"$cavity" triangulate conf.node -o conf --count-conflicts --locate conflict-graph --stats conf_cg.json --quiet ||
  fail "conflicts: conflict graph failed"
[ "$(grep '"conflicts_created"' conf.json)" = "$(grep '"conflicts_created"' conf_cg.json)" ] ||
  fail "conflicts: the locators disagree"
# The full conflict graph counts them itself, always, and the same.
"$cavity" triangulate conf.node -o conf --locate conflict-graph-all --stats conf_all.json --quiet ||
  fail "conflicts: the full conflict graph failed"
[ "$(grep '"conflicts_created"' conf.json)" = "$(grep '"conflicts_created"' conf_all.json)" ] ||
  fail "conflicts: the full conflict graph disagrees with the counter"
created=$(sed -n 's/.*"conflicts_created": \([0-9]*\).*/\1/p' conf.json)
deleted=$(sed -n 's/.*"conflicts_deleted": \([0-9]*\).*/\1/p' conf.json)
[ "$created" = "$deleted" ] || fail "conflicts: $created created but $deleted deleted"
"$cavity" triangulate conf.node -o conf --stats plain.json --quiet
grep -q '"conflicts_created"' plain.json && fail "conflicts: counted without being asked"

# --bootstrap first keeps the order's own first four; a rule name outside the list is a usage error.
"$cavity" triangulate conf.node -o boot --bootstrap first --order random --check --stats boot.json --quiet ||
  fail "bootstrap first: failed"
grep -q '"bootstrap": "first"' boot.json || fail "bootstrap: not in the stats"
"$cavity" triangulate conf.node -o boot --bootstrap best --quiet 2>/dev/null
[ $? -eq 2 ] || fail "bootstrap: an unknown rule is not a usage error"

# --threads N: the same files, byte for byte, for every N (the canonical order), the same
# tetrahedra as the sequential engine, valid; options it cannot honour are usage errors.
"$cavity" generate cube 30000 -o par.node --seed 4 >/dev/null
"$cavity" triangulate par.node -o par_seq --quiet || fail "threads: the sequential run failed"
for n in 1 2 4; do
  "$cavity" triangulate par.node -o "par_$n" --threads "$n" --neigh --check --quiet \
    --stats "par_$n.json" || fail "threads $n: failed"
done
for n in 2 4; do
  cmp -s par_1.ele "par_$n.ele" || fail "threads $n: .ele differs from --threads 1"
  cmp -s par_1.neigh "par_$n.neigh" || fail "threads $n: .neigh differs from --threads 1"
done
# Each tetrahedron's vertices in increasing order (a 4-element sorting network), then the lines.
sorted_tets() {
  awk 'NR > 1 && !/^#/ { a = $2; b = $3; c = $4; d = $5
    if (a > b) { t = a; a = b; b = t }; if (c > d) { t = c; c = d; d = t }
    if (a > c) { t = a; a = c; c = t }; if (b > d) { t = b; b = d; d = t }
    if (b > c) { t = b; b = c; c = t }; print a, b, c, d }' "$1" | sort
}
[ "$(sorted_tets par_seq.ele | md5sum)" = "$(sorted_tets par_2.ele | md5sum)" ] ||
  fail "threads: tetrahedra differ from the sequential engine's"
grep -q '"engine": "parallel, 2 threads"' par_2.json || fail "threads: --stats does not name the engine"
grep -q '"walk_steps"' par_2.json && fail "threads: --stats has counters the parallel engine lacks"
"$cavity" triangulate par.node -o par_bad --threads 2 --locate conflict-graph --quiet 2>/dev/null
[ $? -eq 2 ] || fail "threads: --locate conflict-graph is not a usage error"
"$cavity" triangulate par.node -o par_bad --threads 0 --quiet 2>/dev/null
[ $? -eq 2 ] || fail "threads: 0 threads is not a usage error"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all triangulate/check CLI cases passed"
