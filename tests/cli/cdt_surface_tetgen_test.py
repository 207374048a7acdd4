"""The surface check of `cavity cdt` against TetGen's -d (Debian's tetgen, installed by
scripts/install-deps.sh; the test fails without it): on a torus and an L-shaped prism crossing
each other at seeded random offsets, cavity refuses with as many intersecting facet pairs as
TetGen finds (TetGen lists a pair once per crossing it meets, so its list is made distinct), and
every pair cavity names is one of TetGen's; apart, both accept the surface."""

import math
import os
import random
import re
import subprocess
import sys
import tempfile

cavity = sys.argv[1]

L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
L_POINTS = [(x, y, z) for z in (0, 1) for x, y in L]
L_FACES = [(0, 2, 1), (0, 3, 2), (0, 4, 3), (0, 5, 4), (6, 7, 8), (6, 8, 9), (6, 9, 10),
           (6, 10, 11)]
for i in range(6):
    j = (i + 1) % 6
    L_FACES += [(i, j, 6 + j), (i, 6 + j, 6 + i)]


def torus(n, m, big, small):
    points = []
    for i in range(n):
        for j in range(m):
            u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
            points.append(((big + small * math.cos(v)) * math.cos(u),
                           (big + small * math.cos(v)) * math.sin(u), small * math.sin(v)))
    faces = []
    for i in range(n):
        for j in range(m):
            a, b = i * m + j, ((i + 1) % n) * m + j
            c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            faces += [(a, b, c), (a, c, d)]
    return points, faces


def write_off(name, points, faces):
    with open(name, "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in points)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)


def tetgen_pairs(name):
    out = subprocess.run(["tetgen", "-d", name], capture_output=True, text=True).stdout
    # "Facet #5 intersects facet #29": numbered from 1.
    return {(int(a) - 1, int(b) - 1)
            for a, b in re.findall(r"Facet #(\d+) intersects facet #(\d+)", out)}


def cavity_report(name):
    r = subprocess.run([cavity, "cdt", name, "--protect", "-o", "out"], capture_output=True,
                       text=True)
    count = re.search(r"(\d+) pairs of intersecting facets", r.stderr)
    shown = {(int(a), int(b)) for a, b in re.findall(r"facet (\d+) \(line \d+\) and facet (\d+)",
                                                     r.stderr)}
    return r.returncode, (int(count.group(1)) if count else 0), shown, r.stderr


rng = random.Random(15)
crossing = 0
with tempfile.TemporaryDirectory() as work:
    os.chdir(work)
    t_points, t_faces = torus(24, 12, 2.0, 0.6)
    for trial in range(12):
        # The L prism somewhere around the torus's tube (or far away in the last trials).
        far = 10.0 if trial >= 10 else 0.0
        dx, dy, dz = (rng.uniform(-3, 1.5) + far, rng.uniform(-3, 1.5), rng.uniform(-1.2, 0.4))
        points = t_points + [(x + dx, y + dy, z + dz) for x, y, z in L_POINTS]
        faces = t_faces + [tuple(v + len(t_points) for v in f) for f in L_FACES]
        write_off("m.off", points, faces)
        expected = tetgen_pairs("m.off")
        status, count, shown, stderr = cavity_report("m.off")
        assert count == len(expected), (trial, count, len(expected), stderr)
        assert shown <= expected, (trial, shown - expected)
        if expected:
            crossing += 1
            assert status == 1, (trial, stderr)
        else:
            assert "does not bound a solid" not in stderr, (trial, stderr)
assert crossing >= 4, crossing
print(f"surface check agrees with tetgen -d on 12 configurations ({crossing} crossing)")
