"""`cavity cdt` on surface meshes end to end: the L-shaped prism (a non-convex solid of volume 3) as
OFF, OBJ, ASCII and binary STL, ASCII and binary PLY and TetGen .smesh meshes and carves to exactly that volume,
and `cavity check --poly` validates the result; surfaces that bound no solid and malformed files
are refused with exit status 1, their facets or lines named, and nothing written. A polygon face off
its plane is cut into triangles; exactly coplanar neighbouring faces are merged unless --keep-faces;
--max-protection-points bounds edge protection; an OFF file is read as far as its counts declare."""

import os
import struct
import subprocess
import sys
import tempfile
from fractions import Fraction

cavity = sys.argv[1]

L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
POINTS = [(x, y, z) for z in (0, 1) for x, y in L]
FACES = [(0, 2, 1), (0, 3, 2), (0, 4, 3), (0, 5, 4), (6, 7, 8), (6, 8, 9), (6, 9, 10), (6, 10, 11)]
for i in range(6):
    j = (i + 1) % 6
    FACES += [(i, j, 6 + j), (i, 6 + j, 6 + i)]


def off(points, faces):
    lines = ["OFF", f"{len(points)} {len(faces)} 0"]
    lines += [" ".join(repr(float(c)) for c in p) for p in points]
    lines += ["3 " + " ".join(map(str, f)) for f in faces]
    return "\n".join(lines) + "\n"


def obj(points, faces):
    lines = ["# the L prism", "o L"] + ["v " + " ".join(map(str, p)) for p in points]
    lines += ["f " + " ".join(f"{v + 1}//1" for v in f) for f in faces]
    return "\n".join(lines) + "\n"


def stl_ascii(points, faces):
    out = ["solid L"]
    for f in faces:
        out += ["facet normal 0 0 0", "outer loop"]
        out += ["vertex " + " ".join(map(str, points[v])) for v in f]
        out += ["endloop", "endfacet"]
    return "\n".join(out + ["endsolid L"]) + "\n"


def stl_binary(points, faces):
    data = b"solid but binary".ljust(80) + struct.pack("<I", len(faces))
    for f in faces:
        data += struct.pack("<3f", 0, 0, 0)
        for v in f:
            data += struct.pack("<3f", *points[v])
        data += b"\0\0"
    return data


def ply(points, faces, fmt):
    head = (f"ply\nformat {fmt} 1.0\nelement vertex {len(points)}\nproperty double x\n"
            f"property double y\nproperty double z\nelement face {len(faces)}\n"
            "property list uchar uint vertex_indices\nend_header\n").encode()
    if fmt == "ascii":
        body = "".join(" ".join(map(str, p)) + "\n" for p in points)
        body += "".join("3 " + " ".join(map(str, f)) + "\n" for f in faces)
        return head + body.encode()
    order = "<" if fmt == "binary_little_endian" else ">"
    body = b"".join(struct.pack(order + "3d", *p) for p in points)
    body += b"".join(struct.pack(order + "B3I", 3, *f) for f in faces)
    return head + body


def smesh(points, faces):
    lines = [f"{len(points)} 3 0 0"] + [f"{i} {x} {y} {z}" for i, (x, y, z) in enumerate(points)]
    lines += [f"{len(faces)} 1"] + [f"3 {a} {b} {c} {k + 1}" for k, (a, b, c) in enumerate(faces)]
    return "\n".join(lines + ["0", "0"]) + "\n"


def exact_volume(prefix):
    """The sum of the kept tetrahedra's volumes in rationals; each must be positive."""
    with open(prefix + ".node") as f:
        rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    pts = {int(r[0]): [Fraction(float(c)) for c in r[1:4]] for r in rows[1:]}
    with open(prefix + ".ele") as f:
        rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    total = Fraction(0)
    for r in rows[1:]:
        a, b, c, d = (pts[int(v)] for v in r[1:5])
        u, v, w = ([q[k] - a[k] for k in range(3)] for q in (b, c, d))
        det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
               u[2] * (v[0] * w[1] - v[1] * w[0]))
        assert det > 0, (prefix, r)
        total += det / 6
    return total


def cdt(name, content, *options):
    mode = "wb" if isinstance(content, bytes) else "w"
    with open(name, mode) as f:
        f.write(content)
    prefix = "out_" + name.replace(".", "_")
    r = subprocess.run([cavity, "cdt", name, "--protect", "-o", prefix, *options],
                       capture_output=True, text=True)
    return r, prefix


def expect_refused(name, content, *fragments, options=()):
    r, prefix = cdt(name, content, *options)
    assert r.returncode == 1, (name, r.returncode, r.stderr)
    for fragment in fragments:
        assert fragment in r.stderr, (name, fragment, r.stderr)
    assert not [f for f in os.listdir(".") if f.startswith(prefix)], (name, "partial output")


with tempfile.TemporaryDirectory() as work:
    os.chdir(work)
    meshes = {
        "l.off": off(POINTS, FACES),
        "l.obj": obj(POINTS, FACES),
        "l_ascii.stl": stl_ascii(POINTS, FACES),
        "l_binary.STL": stl_binary(POINTS, FACES),
        "l_ascii.ply": ply(POINTS, FACES, "ascii"),
        "l_le.ply": ply(POINTS, FACES, "binary_little_endian"),
        "l_be.ply": ply(POINTS, FACES, "binary_big_endian"),
        "l.smesh": smesh(POINTS, FACES),
    }
    for name, content in meshes.items():
        r, prefix = cdt(name, content)
        assert r.returncode == 0, (name, r.stderr)
        assert exact_volume(prefix) == 3, (name, exact_volume(prefix))
        check = subprocess.run(
            [cavity, "check", prefix + ".node", prefix + ".ele", "--poly", prefix + ".poly"],
            capture_output=True, text=True)
        assert check.returncode == 0, (name, check.stdout, check.stderr)

    # Facets named as each file numbers them: OFF from 0 with lines, OBJ from 1.
    expect_refused("open.off", off(POINTS, FACES[:-1]), "open.off: ", "3 open edges",
                   "edge 5-6: only facet 18 (line 33)")
    expect_refused("open.obj", obj(POINTS, FACES[:-1]), "3 open edges",
                   "edge 6-7: only facet 19 (line 33)")
    # Two copies of the prism, the second shifted by half: every crossing pair is named.
    shifted = [(x + 0.5, y + 0.5, z + 0.5) for x, y, z in POINTS]
    twice = FACES + [tuple(v + 12 for v in f) for f in FACES]
    expect_refused("twice.stl", stl_binary(POINTS + shifted, twice), "pairs of intersecting facets",
                   "and ")
    # Two prisms sharing the edge 0-1 and nothing else: non-manifold.
    flipped = [(x, -y, -z) for x, y, z in POINTS]
    pair = FACES + [tuple(v if v in (0, 1) else v + 12 for v in reversed(f)) for f in FACES]
    expect_refused("pair.ply", ply(POINTS + flipped, pair, "binary_little_endian"),
                   "non-manifold edges", "edge 0-1: 4 facets")
    # Malformed files: file and line, or byte offset.
    expect_refused("bad.off", off(POINTS, FACES).replace("3 0 2 1", "3 0 2 12"), "bad.off:15: ",
                   "vertex index 12 is not a point")
    expect_refused("short.stl", stl_binary(POINTS, FACES)[:-1], "short.stl: ",
                   "20 triangles has 1084 bytes, this one has 1083")

    # The L's top as one hexagon with corner 8 lifted 2^-30 off its plane, as rounded CAD polygons
    # are: cut into triangles with a note, meshed, and valid.
    lifted = [(x, y, z + 2.0**-30) if i == 8 else (x, y, z) for i, (x, y, z) in enumerate(POINTS)]
    hexagon = off(lifted, FACES[:4] + FACES[8:]).replace("12 16 0", "12 17 0")
    hexagon += "6 6 7 8 9 10 11\n"
    r, prefix = cdt("warped.off", hexagon)
    assert r.returncode == 0, r.stderr
    assert "1 polygon faces whose corners are not coplanar were cut into triangles" in r.stderr, \
        r.stderr
    assert 3 < exact_volume(prefix) < 3 + 2.0**-28, exact_volume(prefix)
    check = subprocess.run([cavity, "check", prefix + ".node", prefix + ".ele", "--poly",
                            prefix + ".poly"], capture_output=True, text=True)
    assert check.returncode == 0, (check.stdout, check.stderr)

    # The L prism's flat faces are 20 triangles: merged into its 8 polygons (the two L-shaped ends,
    # the six rectangles) by default, with a note; --keep-faces keeps the 20.
    for options, note, facets in (((), True, 8), (("--keep-faces",), False, 20)):
        r, prefix = cdt("L.off", off(POINTS, FACES), *options)
        assert r.returncode == 0, r.stderr
        merged = "20 exactly coplanar neighbouring faces were merged into 8 polygons"
        assert (merged in r.stderr) == note, r.stderr
        with open(prefix + ".poly") as f:
            rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
        assert int(rows[1 + int(rows[0][0])][0]) == facets, rows[1 + int(rows[0][0])]
        assert exact_volume(prefix) == 3, exact_volume(prefix)

    # A face more than the counts declare (CGAL's prim.off has one): read as the counts say, as
    # CGAL and TetGen read it, with a note naming the line where the unread data begins.
    r, prefix = cdt("stray.off", off(POINTS, FACES) + "3 0 1 7\n")
    assert r.returncode == 0, r.stderr
    assert f"stray.off:{3 + len(POINTS) + len(FACES)}: data after the faces the counts declare " \
        "was not read" in r.stderr, r.stderr
    assert exact_volume(prefix) == 3, exact_volume(prefix)

    # --max-protection-points: a triangle whose side 8-9 needs one split, in a box; refused when
    # no split is allowed, meshed by default.
    box = ["12 3 0 0"] + [f"{i} {4 * (i % 4 in (1, 2))} {4 * (i % 4 in (2, 3))} {4 * (i >= 4)}"
                          for i in range(8)]
    box += ["8 0.5 0.5 1", "9 3.5 1 2", "10 1 3.5 3", "11 2 0.8125 1.4375",
            "1 0", "1 0", "3 8 9 10", "0", "0"]
    poly = "\n".join(box) + "\n"
    expect_refused("split.poly", poly, "still not edge-protected after inserting 0 points (edge 8-9)",
                   options=("--convex-hull", "--max-protection-points", "0"))
    r, prefix = cdt("split.poly", poly, "--convex-hull")
    assert r.returncode == 0 and "(1 inserted for protection)" in r.stdout, (r.stdout, r.stderr)
print("cdt surface inputs: ok")
