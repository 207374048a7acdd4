"""Checks the .neigh and .face files cavity writes next to its .ele (TetGen's -n and boundary
faces) against their definitions and against TetGen's own .face of the same points:
  tetgen_companions.py PREFIX TETGEN_FACE
Each neighbour shares the facet opposite the listed vertex and lists the tetrahedron back; -1 marks
exactly the hull facets; the hull triangles are TetGen's, each in an orientation that is a
rotation of TetGen's (counter-clockwise seen from outside)."""

import sys


def rows(path):
    with open(path) as f:
        lines = [l.split("#", 1)[0].split() for l in f]
    lines = [l for l in lines if l]
    return lines[0], lines[1:]


def canonical(triangle):
    """The rotation of a triangle starting at its smallest vertex (keeps the orientation)."""
    k = triangle.index(min(triangle))
    return tuple(triangle[k:] + triangle[:k])


prefix, tetgen_face = sys.argv[1], sys.argv[2]
_, ele = rows(prefix + ".ele")
header, neigh = rows(prefix + ".neigh")
assert int(header[0]) == len(ele) == len(neigh) and header[1] == "4", header
base = int(ele[0][0])
tets = {int(r[0]): [int(v) for v in r[1:5]] for r in ele}
hull_facets = set()
for r in neigh:
    t, across = int(r[0]), [int(v) for v in r[1:5]]
    for i, u in enumerate(across):
        facet = set(tets[t]) - {tets[t][i]}
        if u == -1:
            hull_facets.add(frozenset(facet))
            continue
        assert facet <= set(tets[u]), (t, i, u)
        assert t in [int(v) for v in neigh[u - base][1:5]], (t, u)

_, faces = rows(prefix + ".face")
ours = {canonical([int(v) for v in r[1:4]]) for r in faces}
_, theirs_rows = rows(tetgen_face)
theirs = {canonical([int(v) for v in r[1:4]]) for r in theirs_rows}
assert {frozenset(f) for f in ours} == hull_facets, "the .face is not the -1 facets of .neigh"
assert ours == theirs, f"{len(ours ^ theirs)} hull triangles differ from TetGen's"
print(len(neigh), "tetrahedra,", len(ours), "hull triangles as TetGen's")
