#!/usr/bin/python3
"""cavity.Delaunay next to scipy.spatial.Delaunay (Qhull) on the same points.

1. Speed: n uniform random points in the unit cube, triangulated by both in this process; prints
   each one's wall time, the ratio, and whether the tetrahedra are the same (they must be: random
   points are in general position, so the Delaunay triangulation is unique).
2. Validity on a degenerate input, a k x k x k grid (every cube's 8 corners are cospherical):
   counts, with cavity's exact predicates, the flat simplices (orient3d == 0) and the facets that
   are not locally Delaunay (the apex across the facet strictly inside the circumsphere).

Run from the repository root after building (the package is in BUILD/python):
    PYTHONPATH=build/release/python /usr/bin/python3 examples/compare_scipy.py --n 100000
"""

import argparse
import sys
import time

import numpy as np

import cavity


def timed(make):
    """(result, wall seconds, CPU seconds of this thread): both run on the calling thread, so its
    CPU time is the fair measure when the machine is shared."""
    wall, cpu = time.perf_counter(), time.thread_time()
    result = make()
    return result, time.perf_counter() - wall, time.thread_time() - cpu


def sorted_tets(simplices):
    s = np.sort(np.asarray(simplices, dtype=np.int64), axis=1)
    return s[np.lexsort(s.T[::-1])]


def audit(points, simplices, neighbors):
    """(flat simplices, facets not locally Delaunay), decided exactly by cavity's predicates."""
    p = np.asarray(points, dtype=np.float64)
    t = np.asarray(simplices, dtype=np.int64).copy()
    orientation = cavity.orient3d(p[t[:, 0]], p[t[:, 1]], p[t[:, 2]], p[t[:, 3]])
    flat = int(np.count_nonzero(orientation == 0))
    # Put every simplex in positive orientation (swapping two vertices swaps their neighbors).
    negative = orientation < 0
    t[negative, 0], t[negative, 1] = t[negative, 1].copy(), t[negative, 0].copy()
    nb = np.asarray(neighbors, dtype=np.int64).copy()
    nb[negative, 0], nb[negative, 1] = nb[negative, 1].copy(), nb[negative, 0].copy()
    solid = orientation != 0
    bad = 0
    for i in range(4):
        across = nb[:, i]
        use = solid & (across >= 0)
        u = across[use]
        # The apex of the neighbor: its vertex that is not in this simplex.
        other = np.asarray(simplices, dtype=np.int64)[u]
        mine = t[use]
        in_mine = (other[:, :, None] == mine[:, None, :]).any(axis=2)
        apex = other[np.arange(len(u)), np.argmin(in_mine, axis=1)]
        m = mine
        s = cavity.insphere(p[m[:, 0]], p[m[:, 1]], p[m[:, 2]], p[m[:, 3]], p[apex])
        bad += int(np.count_nonzero(s > 0))
    return flat, bad


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=100_000, help="uniform points (default 100000)")
    parser.add_argument("--grid", type=int, default=10, help="grid side k (default 10: 1000 points)")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    try:
        from scipy.spatial import Delaunay as QhullDelaunay
    except ImportError:
        print("scipy is not installed (Debian: python3-scipy)", file=sys.stderr)
        sys.exit(77)  # ctest's "skipped"

    points = np.random.default_rng(args.seed).random((args.n, 3))
    ours, t_cavity, c_cavity = timed(lambda: cavity.Delaunay(points))
    theirs, t_scipy, c_scipy = timed(lambda: QhullDelaunay(points))
    same = np.array_equal(sorted_tets(ours.simplices), sorted_tets(theirs.simplices))
    print(f"uniform cube, n = {args.n}, seed = {args.seed}")
    for name, wall, cpu, d in (("cavity.Delaunay", t_cavity, c_cavity, ours),
                               ("scipy  Delaunay", t_scipy, c_scipy, theirs)):
        print(f"  {name}: {wall:8.3f} s wall ({1e6 * wall / args.n:.2f} us/point), "
              f"{cpu:8.3f} s CPU, {d.nsimplex} tetrahedra")
    print(f"  speed ratio scipy / cavity: {t_scipy / t_cavity:.1f}x wall, "
          f"{c_scipy / c_cavity:.1f}x CPU")
    t = ours.stats["timings"]
    print(f"  cavity CPU by phase: order {t['order_cpu_s']:.3f} s, triangulate "
          f"{t['triangulate_cpu_s']:.3f} s, neighbors {t['adjacency_cpu_s']:.3f} s")
    print(f"  same tetrahedra: {'yes' if same else 'NO'}")

    k = args.grid
    axis = np.arange(k, dtype=np.float64)
    grid = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)
    print(f"degenerate input: {k}x{k}x{k} grid ({len(grid)} points, cospherical cube corners)")
    ours = cavity.Delaunay(grid)
    flat, bad = audit(grid, ours.simplices, ours.neighbors)
    print(f"  cavity: {ours.nsimplex} tetrahedra, {flat} flat, {bad} facets not locally Delaunay, "
          f"exact check(): {'valid' if ours.check() else 'INVALID'}")
    try:
        theirs = QhullDelaunay(grid)
        flat, bad = audit(grid, theirs.simplices, theirs.neighbors)
        print(f"  scipy:  {theirs.nsimplex} simplices, {flat} flat, {bad} facets not locally "
              f"Delaunay, {len(theirs.coplanar)} points left out (coplanar)")
    except Exception as error:  # Qhull raises QhullError on some degenerate inputs
        print(f"  scipy:  failed: {type(error).__name__}: {str(error).splitlines()[0]}")


if __name__ == "__main__":
    main()
