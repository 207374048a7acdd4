"""cavity.cdt: the constrained Delaunay tetrahedralization of a PLC given as arrays."""

import os
import pathlib
import shutil
import subprocess
import sys
import threading

import numpy as np
import pytest

import cavity
from conftest import sorted_rows

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]

# The unit cube's corners (vertex 4x + 2y + z) and its faces as quads, counter-clockwise seen from
# outside.
CUBE = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
CUBE_QUADS = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
CUBE_TRIANGLES = [t for q in CUBE_QUADS for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])]


def volumes(c):
    """Right-hand signed volume of each tetrahedron (floating point)."""
    p = c.points[c.simplices]
    edges = p[:, 1:] - p[:, :1]
    return np.einsum("ij,ij->i", edges[:, 0], np.cross(edges[:, 1], edges[:, 2])) / 6


def assert_positive(c):
    """Every tetrahedron has positive right-hand volume, exactly: orient3d == -1 (Shewchuk's
    sign)."""
    p, s = c.points, c.simplices
    assert np.all(cavity.orient3d(p[s[:, 0]], p[s[:, 1]], p[s[:, 2]], p[s[:, 3]]) == -1)


def loop_area(points, loop):
    """Area of a planar loop (the length of its vector area)."""
    p = points[loop]
    return np.linalg.norm(np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0)) / 2


def assert_polygon_is_union_of_faces(c, marker, loop, area):
    """The faces marked `marker` lie in the plane of `loop` (exactly) and cover `area`; their
    triangles have disjoint interiors, so equal areas of faces inside the polygon mean the union."""
    faces = c.faces[c.face_markers == marker]
    assert len(faces) > 0
    p = c.points
    a, b, d = (p[loop[0]], p[loop[1]], p[loop[2]])
    corners = p[faces.ravel()]
    assert np.all(cavity.orient3d(a, b, d, corners) == 0)
    tri = p[faces]
    face_area = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1) / 2
    assert np.all(face_area > 0)
    assert face_area.sum() == pytest.approx(area, rel=1e-12)


@pytest.mark.parametrize("polygons", [CUBE_QUADS, CUBE_TRIANGLES], ids=["quads", "triangles"])
def test_cube_surface(polygons):
    markers = 10 + np.arange(len(polygons))
    c = cavity.cdt(CUBE, np.array(polygons), markers=markers)
    assert c.points.shape == (8, 3) and c.points.dtype == np.float64
    assert np.array_equal(c.points, CUBE)
    assert c.simplices.dtype == np.int32 and c.simplices.shape[1] == 4
    assert c.faces.dtype == np.int32 and c.faces.shape == (12, 3)
    assert c.face_markers.dtype == np.int32 and c.face_markers.shape == (12,)
    assert c.steiner.dtype == np.int32 and c.steiner.shape == (0,)
    assert c.region_markers is None
    assert c.npoints == 8 and c.nsimplex == len(c.simplices)
    assert_positive(c)
    assert volumes(c).sum() == pytest.approx(1.0, rel=1e-15)
    for marker, loop in zip(markers, polygons):
        assert_polygon_is_union_of_faces(c, marker, loop, loop_area(CUBE, loop))
    if len(polygons) == 12:
        # Triangles are kept as they are.
        assert sorted_rows(c.faces) == sorted_rows(polygons)
        assert sorted(c.face_markers) == sorted(markers)
    st = c.stats
    assert st["tets"] == c.nsimplex and st["faces"] == 12 and st["polygons"] == len(polygons)
    assert st["points"] == st["input_points"] == 8 and st["protection_points"] == 0
    assert st["rotary_steps"] + st["search_visited"] > 0
    assert repr(c) == (f"<cavity.CDT: 8 points (0 protecting), {c.nsimplex} tetrahedra, "
                       "12 polygon triangles>")


def test_arrays_are_read_only():
    c = cavity.cdt(CUBE, CUBE_QUADS)
    for name in ("points", "simplices", "faces", "face_markers", "steiner"):
        with pytest.raises(ValueError):
            getattr(c, name)[...] = 0


def test_every_polygon_form_gives_the_same_mesh():
    reference = cavity.cdt(CUBE, np.array(CUBE_QUADS))
    forms = [
        CUBE_QUADS,
        [tuple(q) for q in CUBE_QUADS],
        [np.array(q, dtype=np.uint16) for q in CUBE_QUADS],
        [[q] for q in CUBE_QUADS],
        [{"loops": [q]} for q in CUBE_QUADS],
        [{"loops": [q], "holes": []} for q in CUBE_QUADS],
        np.array(CUBE_QUADS, dtype=np.int8),
        np.array([np.array(q) for q in CUBE_QUADS] + [None], dtype=object)[:-1],
    ]
    for form in forms:
        c = cavity.cdt(CUBE, form)
        assert np.array_equal(c.simplices, reference.simplices)
        assert np.array_equal(c.faces, reference.faces)


def test_no_polygons_is_the_delaunay_triangulation():
    points = np.random.default_rng(3).random((60, 3))
    c = cavity.cdt(points, np.zeros((0, 3), dtype=int), convex_hull=True)
    assert sorted_rows(c.simplices) == sorted_rows(cavity.Delaunay(points).simplices)
    assert c.faces.shape == (0, 3)
    # No polygon encloses anything: the whole hull is exterior, and carved away.
    carved = cavity.cdt(points, np.zeros((0, 3), dtype=int))
    assert carved.nsimplex == 0 and carved.stats["removed_tets"] == c.nsimplex


def schoenhardt(twisted):
    """A triangular prism whose top is turned by 20 degrees, each side split by a diagonal. With
    the diagonals across the twist (Schönhardt's polyhedron) they are not Delaunay edges."""
    bottom = [(10, 0, 0), (-5, 9, 0), (-5, -9, 0)]
    top = [(9, 3, 10), (-8, 7, 10), (-2, -10, 10)]
    polygons = [[0, 2, 1], [3, 4, 5]]
    diagonals = []
    for i in range(3):
        j = (i + 1) % 3
        if twisted:
            polygons += [[i, j, 3 + j], [i, 3 + j, 3 + i]]
            diagonals.append((i, 3 + j))
        else:
            polygons += [[i, j, 3 + i], [j, 3 + j, 3 + i]]
            diagonals.append((j, 3 + i))
    return np.array(bottom + top, dtype=float), polygons, diagonals


def test_untwisted_prism_needs_no_protection():
    points, polygons, _ = schoenhardt(twisted=False)
    c = cavity.cdt(points, polygons)
    assert c.steiner.shape == (0,) and c.npoints == 6
    assert_positive(c)


def test_schoenhardt_polyhedron_needs_protection():
    points, polygons, diagonals = schoenhardt(twisted=True)
    with pytest.raises(ValueError, match=r"not edge-protected: 1 edge\(s\) .*: 0-4 .*protect=True"):
        cavity.cdt(points, polygons)
    markers = np.arange(len(polygons))
    c = cavity.cdt(points, polygons, markers=markers, protect=True, convex_hull=True)
    assert c.npoints > 6
    assert np.array_equal(c.steiner, np.arange(6, c.npoints))
    assert np.array_equal(c.points[:6], points)
    assert c.stats["protection_points"] == len(c.steiner)
    assert c.stats["input_points"] == 6 and c.stats["points"] == c.npoints
    assert f"({len(c.steiner)} protecting)" in repr(c)
    assert_positive(c)
    hull = cavity.Delaunay(points)
    assert volumes(c).sum() == pytest.approx(volumes(hull).sum(), rel=1e-12)
    # Each protecting point lies exactly on a diagonal, strictly between its ends, and is a vertex
    # of the polygon triangles that replace the split diagonal.
    for s in c.steiner:
        # Small dyadic coordinates: the cross product is exact in floating point.
        on = [(a, b) for a, b in diagonals
              if np.all(np.cross(points[b] - points[a], c.points[s] - points[a]) == 0)
              and np.all(np.minimum(points[a], points[b]) <= c.points[s])
              and np.all(c.points[s] <= np.maximum(points[a], points[b]))
              and not any(np.array_equal(c.points[s], points[v]) for v in (a, b))]
        assert len(on) == 1
        assert s in c.faces
    for marker, loop in zip(markers, polygons):
        assert_polygon_is_union_of_faces(c, marker, loop, loop_area(points, loop))


def test_polygon_in_a_point_cloud_is_inserted_by_flips():
    square = [[0.125, 0.125, 0.5], [0.875, 0.125, 0.5], [0.875, 0.875, 0.5], [0.125, 0.875, 0.5]]
    points = np.vstack([square, np.random.default_rng(5).random((200, 3))])
    c = cavity.cdt(points, [[0, 1, 2, 3]], markers=[4], protect=True, convex_hull=True)
    st = c.stats
    assert st["flips_23"] + st["flips_32"] > 0 and st["events_queued"] > 0
    assert st["region_tets"] > 0 and st["certify_calls"] > 0
    assert st["protection_points"] == len(c.steiner) > 0 and st["protection_rounds"] > 0
    assert_positive(c)
    assert_polygon_is_union_of_faces(c, 4, [0, 1, 2, 3], 0.75**2)
    # The square's sides were split where a random point spoiled them: at z = 1/2, on a side.
    steiner = c.points[c.steiner]
    assert np.all(steiner[:, 2] == 0.5)
    assert np.all(np.isin(steiner[:, :2], [0.125, 0.875]).any(axis=1))


def test_threads_get_the_same_mesh():
    points, polygons, _ = schoenhardt(twisted=True)
    results = [None] * 4

    def work(i):
        c = cavity.cdt(points, polygons, protect=True)
        results[i] = (c.simplices.tobytes(), c.points.tobytes())

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results[0] is not None and all(r == results[0] for r in results)


def box_with_window(top):
    """The surface of [0, 4]^3 whose top (z = 4) is `top`, given the outer and inner loop indices;
    the inner loop is the square [1, 3]^2."""
    corners = [[x, y, z] for x in (0, 4) for y in (0, 4) for z in (0, 4)]
    window = [[1, 1, 4], [3, 1, 4], [3, 3, 4], [1, 3, 4]]
    points = np.array(corners + window, dtype=float)
    sides = [[0, 2, 6, 4], [0, 4, 5, 1], [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5]]
    return points, sides + [top([1, 5, 7, 3], [8, 9, 10, 11])]


def top_faces(c):
    return c.faces[c.face_markers == 1]


def face_areas(c, faces):
    t = c.points[faces]
    return np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1) / 2


def test_polygon_with_a_hole():
    points, polygons = box_with_window(
        lambda outer, inner: {"loops": [outer, inner], "holes": [[2, 2, 4]]})
    markers = [0] * 5 + [1]
    c = cavity.cdt(points, polygons, markers=markers)
    assert_positive(c)
    faces = top_faces(c)
    assert face_areas(c, faces).sum() == pytest.approx(16 - 4)
    centroids = c.points[faces].mean(axis=1)
    inside = np.all((centroids[:, :2] > 1) & (centroids[:, :2] < 3), axis=1)
    assert not np.any(inside)
    # The window's sides are edges of the mesh all the same.
    for a, b in zip([8, 9, 10, 11], [9, 10, 11, 8]):
        assert any({a, b} <= set(f) for f in faces.tolist())


def test_nested_loop_without_a_hole_point_subdivides():
    points, polygons = box_with_window(lambda outer, inner: [outer, inner])
    c = cavity.cdt(points, polygons, markers=[0] * 5 + [1])
    faces = top_faces(c)
    assert face_areas(c, faces).sum() == pytest.approx(16)
    centroids = c.points[faces].mean(axis=1)
    assert np.any(np.all((centroids[:, :2] > 1) & (centroids[:, :2] < 3), axis=1))


def test_hole_point_off_the_plane_is_refused():
    points, polygons = box_with_window(
        lambda outer, inner: {"loops": [outer, inner], "holes": [[2, 2, 4.5]]})
    with pytest.raises(ValueError, match="polygon 5: hole point 0 is not in the plane"):
        cavity.cdt(points, polygons)


def test_hole_point_on_a_loop_side_is_refused():
    points, polygons = box_with_window(
        lambda outer, inner: {"loops": [outer, inner], "holes": [[1, 2, 4]]})
    with pytest.raises(ValueError, match="facet 5: hole point 0 lies on a side"):
        cavity.cdt(points, polygons)


@pytest.mark.parametrize("polygons, message", [
    ([[0, 1, 3, 2], [4, 6, 8]], "polygon 1: corner 8 is out of range for 8 points"),
    ([[0, 1, 3, -2]], "polygon 0: corner -2 is negative"),
    ([[0, 1, 3], [0, 1, 2, 1]], "polygon 1 lists corner 1 twice"),
    ([[0, 1, 3], [4, 6]], r"polygon 1 has 2 corner\(s\); a polygon needs at least 3"),
    ([[0, 1, 2.0]], "polygon 0: corner 2.0 is not an integer"),
    ([[[0, 1, 3, 2], [0, 1, 9]]], "polygon 0, loop 1: corner 9 is out of range"),
    ([[[0, 1, 3, 2], 5]], "polygon 0, loop 1 must be a sequence of point indices, got 5"),
    ([[0, 1, 3], []], "polygon 1 is empty"),
    ([[0, 1, 3], "abc"], "polygon 1 must be a sequence"),
    ([{"loop": [[0, 1, 3]]}], "polygon 0: unknown key 'loop'"),
    ([{"loops": [0, 1, 3]}], r"polygon 0: \"loops\" must be a sequence of loops"),
    (np.array([[0, 1, 3]], dtype=float), "polygons must be integers, got dtype float64"),
    (np.array([[0, 1], [2, 3]]), r"shape \(f, k\) with k >= 3, got \(2, 2\)"),
    (np.array([[0, 1, 8]]), "polygon 0: corner 8 is out of range for 8 points"),
    (np.array([[0, 1, 1]], dtype=np.uint32), "polygon 0 lists corner 1 twice"),
    ([[0, 1, 3, 2], [0, 1, 3, 7]], "polygon 1: corner 7 is not in the plane of the polygon"),
    ("abc", "polygons must be an"),
])
def test_bad_polygons_are_named(polygons, message):
    with pytest.raises(ValueError, match=message):
        cavity.cdt(CUBE, polygons)


def test_collinear_polygon_is_refused():
    points = np.vstack([CUBE, [[2, 2, 2], [3, 3, 3]]])
    with pytest.raises(ValueError, match="polygon 1: its corners are collinear"):
        cavity.cdt(points, [[0, 1, 3], [0, 8, 9]])


def test_non_finite_point_names_the_row():
    points = CUBE.copy()
    points[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"points row 3 has a non-finite value \(nan\) in col"):
        cavity.cdt(points, CUBE_QUADS)


@pytest.mark.parametrize("kwargs, message", [
    ({"segments": [[0, 7], [2, 2]]}, "segment 1 joins point 2 to itself"),
    ({"segments": [[0, 8]]}, "segment 0: point 8 is out of range for 8 points"),
    ({"segments": [[0, 1, 2]]}, r"segments must have shape \(s, 2\)"),
    ({"markers": [1, 2]}, r"markers must have one integer per polygon, shape \(6,\)"),
    ({"markers": [0.5] * 6}, "markers must be integers"),
    ({"markers": [0, 0, 2**40, 0, 0, 0]}, r"markers\[2\] = 1099511627776 does not fit in int32"),
    ({"regions": [[0.5, 0.5, 0.5]]}, r"regions must have shape \(n, 4\)"),
    ({"regions": [[0.5, 0.5, 0.5, 1], [0.5, 0.5, 0.5, 1.5]]},
     "regions row 1: marker 1.5 is not an integer"),
    ({"regions": [[0.5, 0.5, 0.5, 1], [0.5, 2, 0.5, 1]]},
     "regions row 1: the point lies outside the tetrahedralization"),
])
def test_bad_keyword_arguments_are_named(kwargs, message):
    with pytest.raises(ValueError, match=message):
        cavity.cdt(CUBE, CUBE_QUADS, **kwargs)


def test_segment_inside_the_cube_is_an_edge():
    points = np.vstack([CUBE, [[0.25, 0.5, 0.5], [0.75, 0.5, 0.5]]])
    c = cavity.cdt(points, CUBE_QUADS, segments=np.array([[8, 9]]))
    assert any({8, 9} <= set(t) for t in c.simplices.tolist())


# A square in z = 0 inside the convex hull of two apexes above and below it.
SQUARE = np.array([[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0], [0, 0, -1], [0, 0, 1],
                   [0.5, 0.5, -1], [0.25, 0.25, 1]], dtype=float)


@pytest.mark.parametrize("kwargs, message", [
    ({"segments": [[4, 5]]},
     r"(?s)not a piecewise linear complex .*facet 0: edge 4-5 \(a segment\) crosses it"),
    ({"segments": [[6, 7]], "protect": True}, "facet 0: edge 6-7 .* crosses it"),
])
def test_edge_through_a_polygon_is_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        cavity.cdt(SQUARE, [[0, 1, 2, 3]], **kwargs)


def test_crossing_loops_are_refused():
    points = np.array([[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0], [2, -1, 0], [5, 2, 0],
                       [2, 5, 0], [-1, 2, 0], [2, 2, 3], [2, 2, -3]], dtype=float)
    with pytest.raises(ValueError, match="edges 4-5 and 0-1 cross"):
        cavity.cdt(points, [[[0, 1, 2, 3], [4, 5, 6, 7]]], protect=True)


def test_duplicate_points_are_refused():
    with pytest.raises(ValueError, match="points 8 and 5 coincide"):
        cavity.cdt(np.vstack([CUBE, CUBE[5]]), CUBE_QUADS)


def split_box():
    """[0, 1]^3 cut in two at z = 1/2 by a square: two closed boxes sharing it."""
    points = np.array([[x, y, z] for z in (0, 0.5, 1) for y in (0, 1) for x in (0, 1)])
    level = [[4 * k + 0, 4 * k + 1, 4 * k + 3, 4 * k + 2] for k in range(3)]  # z = 0, 0.5, 1
    sides = []
    for k in range(2):
        a, b = 4 * k, 4 * (k + 1)
        sides += [[a, a + 1, b + 1, b], [a + 2, a + 3, b + 3, b + 2],
                  [a, a + 2, b + 2, b], [a + 1, a + 3, b + 3, b + 1]]
    return points, level + sides


def test_regions_mark_the_tetrahedra_between_polygons():
    points, polygons = split_box()
    c = cavity.cdt(points, polygons, regions=[[0.5, 0.5, 0.25, 7], [0.3, 0.6, 0.75, -2]])
    assert c.region_markers.dtype == np.int32 and c.region_markers.shape == (c.nsimplex,)
    z = c.points[c.simplices].mean(axis=1)[:, 2]
    assert np.array_equal(c.region_markers, np.where(z < 0.5, 7, -2))
    # Without a seed in the upper box its tetrahedra are in no region (0).
    c = cavity.cdt(points, polygons, regions=[[0.5, 0.5, 0.25, 7]])
    assert np.array_equal(c.region_markers, np.where(z < 0.5, 7, 0))


def prism(loop):
    """The prism over a polygon `loop` of (x, y) corners, from z = 0 to z = 1: its two caps and its
    sides as polygons."""
    k = len(loop)
    points = np.array([[x, y, z] for z in (0, 1) for x, y in loop], dtype=float)
    polygons = [list(range(k)), list(range(k, 2 * k))]
    polygons += [[i, (i + 1) % k, k + (i + 1) % k, k + i] for i in range(k)]
    return points, polygons


L_SHAPE = [(0, 0), (1, 0), (1, 0.5), (0.5, 0.5), (0.5, 1), (0, 1)]


def test_l_shaped_prism_keeps_its_domain():
    points, polygons = prism(L_SHAPE)
    c = cavity.cdt(points, polygons, protect=True)
    hull = cavity.cdt(points, polygons, protect=True, convex_hull=True)
    assert_positive(c)
    assert volumes(c).sum() == pytest.approx(0.75, abs=1e-15)
    assert volumes(hull).sum() == pytest.approx(0.875, abs=1e-15)
    assert c.nsimplex + c.stats["removed_tets"] == hull.nsimplex and c.stats["removed_tets"] > 0
    # Every kept tetrahedron is inside the L: its centroid is not in the notch [0.5, 1]^2.
    centroids = c.points[c.simplices].mean(axis=1)
    assert not np.any((centroids[:, 0] > 0.5) & (centroids[:, 1] > 0.5))


def cube_with_cavity():
    """[0, 1]^3 holding the cube [1/4, 3/4]^3: both surfaces as quads."""
    inner = 0.25 + 0.5 * CUBE
    points = np.vstack([CUBE, inner])
    return points, CUBE_QUADS + [[v + 8 for v in q] for q in CUBE_QUADS]


def test_hole_point_carves_the_inner_cube():
    points, polygons = cube_with_cavity()
    c = cavity.cdt(points, polygons, holes=[[0.5, 0.5, 0.5]])
    assert_positive(c)
    assert volumes(c).sum() == pytest.approx(1 - 1 / 8, abs=1e-15)
    centroids = c.points[c.simplices].mean(axis=1)
    assert not np.any(np.all((centroids > 0.25) & (centroids < 0.75), axis=1))
    # Without the hole point the inner cube stays, and so it does in the whole hull.
    whole = cavity.cdt(points, polygons)
    assert volumes(whole).sum() == pytest.approx(1, abs=1e-15)
    hull = cavity.cdt(points, polygons, holes=[[0.5, 0.5, 0.5]], convex_hull=True)
    assert np.array_equal(hull.simplices, whole.simplices)
    assert hull.nsimplex == c.nsimplex + c.stats["removed_tets"]
    # A hole point in the shell leaves the inner cube; at a vertex in no polygon (a PLC point
    # of the shell), it is in several tetrahedra, all in the shell, and carves the same.
    shell = np.vstack([points, [[0.125, 0.5, 0.5]]])
    for hole in ([0.1, 0.1, 0.1], [0.125, 0.5, 0.5]):
        inner = cavity.cdt(shell, polygons, holes=[hole])
        assert volumes(inner).sum() == pytest.approx(1 / 8, abs=1e-15)
        centroids = inner.points[inner.simplices].mean(axis=1)
        assert np.all(np.all((centroids > 0.25) & (centroids < 0.75), axis=1))


@pytest.mark.parametrize("holes, message", [
    ([[0.5, 0.5, 0.5], [2, 0.5, 0.5]], "holes row 1: volume hole point lies outside"),
    ([[0.5, 0.5, 0.75]], "holes row 0: volume hole point lies on a polygon"),
    ([[0.25, 0.25, 0.25]], "holes row 0: volume hole point lies on a polygon"),
    ([[0.5, 0.5]], r"holes must have shape \(n, 3\)"),
])
def test_bad_hole_points_are_named(holes, message):
    points, polygons = cube_with_cavity()
    for convex_hull in (False, True):
        with pytest.raises(ValueError, match=message):
            cavity.cdt(points, polygons, holes=holes, convex_hull=convex_hull)


def test_to_meshio():
    meshio = pytest.importorskip("meshio")
    points, polygons = split_box()
    c = cavity.cdt(points, polygons, regions=[[0.5, 0.5, 0.25, 7], [0.5, 0.5, 0.75, 8]])
    mesh = c.to_meshio()
    assert isinstance(mesh, meshio.Mesh)
    assert np.array_equal(mesh.points, c.points)
    assert len(mesh.cells) == 1 and mesh.cells[0].type == "tetra"
    assert np.array_equal(mesh.cells[0].data, c.simplices)
    assert np.array_equal(mesh.cell_data["region"][0], c.region_markers)
    assert cavity.cdt(CUBE, CUBE_QUADS).to_meshio().cell_data == {}


def test_to_meshio_without_meshio(monkeypatch):
    monkeypatch.setitem(sys.modules, "meshio", None)  # makes `import meshio` fail
    with pytest.raises(ImportError, match=r"to_meshio\(\) needs the meshio package"):
        cavity.cdt(CUBE, CUBE_QUADS).to_meshio()


def read_poly(path):
    """The points, polygons, markers and segments of a TetGen .poly file with its points inline
    and facet markers (enough for the repository's fixtures), 0-based."""
    lines = [line.split("#")[0].split() for line in pathlib.Path(path).read_text().splitlines()]
    rows = iter([line for line in lines if line])
    n = int(next(rows)[0])
    table = [next(rows) for _ in range(n)]
    base = int(table[0][0])
    points = np.array([[float(v) for v in row[1:4]] for row in table])
    polygons, markers, segments = [], [], []
    for _ in range(int(next(rows)[0])):
        header = [int(v) for v in next(rows)]
        loops = [[int(v) - base for v in next(rows)[1:]] for _ in range(header[0])]
        assert len(header) < 2 or header[1] == 0, "facet holes are not read here"
        segments += [loop for loop in loops if len(loop) == 2]
        loops = [loop for loop in loops if len(loop) > 2]
        if loops:
            polygons.append(loops)
            markers.append(header[2] if len(header) > 2 else 0)
    return points, polygons, markers, segments


POLY = REPOSITORY / "tests" / "cli" / "data" / "cdt_insert.poly"


def cavity_executable():
    """The command-line program: $CAVITY_EXECUTABLE, else `cavity` on PATH."""
    return os.environ.get("CAVITY_EXECUTABLE") or shutil.which("cavity")


@pytest.fixture
def poly_cdt():
    if not POLY.exists():
        pytest.skip(f"{POLY} is not here (tests run outside the repository)")
    points, polygons, markers, segments = read_poly(POLY)
    with pytest.raises(ValueError, match=r"not edge-protected: 1 edge\(s\) .*: 8-9 "):
        cavity.cdt(points, polygons, markers=markers, segments=segments)
    # A triangle and a segment in a box without walls: no domain, so the whole hull.
    return cavity.cdt(points, polygons, markers=markers, segments=segments, protect=True,
                      convex_hull=True)


def test_poly_fixture_as_the_cli_reports_it(poly_cdt):
    # `cavity cdt tests/cli/data/cdt_insert.poly --protect` prints "protecting vertex 12: 2 0.75
    # 1.5" (the vertex that encroaches is an input vertex, so the split halves the edge) and "13
    # points (1 inserted for protection), 1 polygons: 32 tetrahedra, 2 polygon triangles".
    c = poly_cdt
    assert c.npoints == 13 and c.nsimplex == 32 and len(c.faces) == 2
    assert np.array_equal(c.steiner, [12])
    assert np.array_equal(c.points[12], [2, 0.75, 1.5])
    assert np.array_equal(c.face_markers, [7, 7])
    assert_positive(c)


def test_poly_fixture_same_mesh_as_the_cli(poly_cdt, tmp_path):
    executable = cavity_executable()
    if executable is None:
        pytest.skip("no `cavity` program (set CAVITY_EXECUTABLE)")
    prefix = tmp_path / "out"
    subprocess.run([executable, "cdt", str(POLY), "-o", str(prefix), "--protect", "--convex-hull",
                    "--quiet"], check=True)
    ele = np.loadtxt(f"{prefix}.ele", skiprows=1, dtype=np.int64, comments="#")
    face = np.loadtxt(f"{prefix}.face", skiprows=1, dtype=np.int64, comments="#", ndmin=2)
    node = np.loadtxt(f"{prefix}.node", skiprows=1, comments="#")
    c = poly_cdt
    assert np.array_equal(node[:, 1:4], c.points)
    # The file numbers from 0, as the .poly does; same tetrahedra, same orientation.
    assert np.array_equal(ele[:, 1:5], c.simplices)
    assert np.array_equal(face[:, 1:4], c.faces) and np.array_equal(face[:, 4], c.face_markers)


INSERT = REPOSITORY / "tests" / "cli" / "data" / "cdt_insert.xyz"


def insert_fixture(**kwargs):
    """cdt_insert.poly protected, in its convex hull, with the rows of cdt_insert.xyz inserted."""
    if not POLY.exists() or not INSERT.exists():
        pytest.skip("the fixture files are not here (tests run outside the repository)")
    points, polygons, markers, segments = read_poly(POLY)
    return cavity.cdt(points, polygons, markers=markers, segments=segments, protect=True,
                      convex_hull=True, insert=np.loadtxt(INSERT, comments="#"), **kwargs)


def test_insert_as_the_cli_inserts(tmp_path):
    # Rows 2 and 3 would leave polygon triangle 8 10 12 inside the cavity, row 4 repeats row 0.
    with pytest.warns(RuntimeWarning, match=r"3 of 7 insert points left out, the first: row 2: "
                                            r"the vertex cannot be inserted: polygon triangle "
                                            r"8 10 12 runs through the cavity"):
        c = insert_fixture()
    assert np.array_equal(c.inserted, [13, 14, -1, -1, -1, 15, 16])
    assert [row for row, _ in c.left_out] == [2, 3, 4]
    assert c.left_out[2][1] == "the point coincides with vertex 13"
    assert np.array_equal(c.points[c.inserted[c.inserted >= 0]],
                          np.loadtxt(INSERT, comments="#")[[0, 1, 5, 6]])
    s = c.stats
    assert (s["insert_attempts"], s["inserted"], s["insert_duplicates"]) == (7, 4, 1)
    assert (s["insert_through_cavity"], s["insert_not_star_shaped"],
            s["insert_not_delaunay"]) == (2, 0, 0)
    assert c.npoints == 17 and np.array_equal(c.steiner, [12])
    assert_positive(c)
    executable = cavity_executable()
    if executable is None:
        pytest.skip("no `cavity` program (set CAVITY_EXECUTABLE)")
    prefix = tmp_path / "out"
    subprocess.run([executable, "cdt", str(POLY), "-o", str(prefix), "--protect", "--convex-hull",
                    "--insert", str(INSERT), "--quiet"], check=True, stderr=subprocess.DEVNULL)
    ele = np.loadtxt(f"{prefix}.ele", skiprows=1, dtype=np.int64, comments="#")
    face = np.loadtxt(f"{prefix}.face", skiprows=1, dtype=np.int64, comments="#", ndmin=2)
    node = np.loadtxt(f"{prefix}.node", skiprows=1, comments="#")
    assert np.array_equal(node[:, 1:4], c.points)
    assert np.array_equal(ele[:, 1:5], c.simplices)
    assert np.array_equal(face[:, 1:4], c.faces) and np.array_equal(face[:, 4], c.face_markers)


def test_insert_all_or_nothing_names_the_row():
    with pytest.raises(ValueError, match=r"^insert row 2: the vertex cannot be inserted: .*"
                                         r"\(all_or_nothing=True: nothing returned\)$"):
        insert_fixture(all_or_nothing=True)


def test_insert_on_a_polygon_splits_it():
    # The cube's bottom face (z = 0) gets a vertex at its middle, the edge x = y = 0 one at its
    # middle; both stay on the boundary, which keeps its area, and the volume stays 1.
    c = cavity.cdt(CUBE, CUBE_QUADS, insert=[[0.5, 0.5, 0], [0, 0, 0.5], [0.25, 0.5, 0.75]])
    assert np.array_equal(c.inserted, [8, 9, 10]) and c.left_out == []
    assert (c.stats["insert_on_polygon"], c.stats["insert_on_plc_edge"]) == (2, 1)
    assert_positive(c)
    assert volumes(c).sum() == pytest.approx(1, abs=1e-15)
    bottom = c.faces[np.all(c.points[c.faces][:, :, 2] == 0, axis=1)]
    assert 8 in bottom and len(bottom) == 4


def test_without_insert_nothing_is_reported():
    c = cavity.cdt(CUBE, CUBE_QUADS)
    assert c.inserted is None and c.left_out is None and c.stats["insert_attempts"] == 0
    empty = cavity.cdt(CUBE, CUBE_QUADS, insert=np.empty((0, 3)))
    assert empty.inserted.shape == (0,) and empty.left_out == []
    assert np.array_equal(empty.simplices, c.simplices)


@pytest.mark.parametrize("kwargs, message", [
    ({"all_or_nothing": True}, "all_or_nothing=True applies to insert only"),
    ({"insert": [[0.5, 0.5]]}, r"insert must have shape \(n, 3\), got \(1, 2\)"),
    ({"insert": [[0.5, 0.5, 0.5], [0.5, np.nan, 0.5]]}, "insert row 1 has a non-finite value"),
])
def test_insert_keyword_errors(kwargs, message):
    with pytest.raises(ValueError, match=message):
        cavity.cdt(CUBE, CUBE_QUADS, **kwargs)


def l_prism_triangles():
    """The L prism of L_SHAPE as a triangle surface mesh: each cap a fan of 4 triangles from corner
    0, each side 2 triangles; outward."""
    points, polygons = prism(L_SHAPE)
    bottom = [[0, i + 1, i] for i in range(1, 5)]
    top = [[6, 6 + i, 6 + i + 1] for i in range(1, 5)]
    sides = [t for q in polygons[2:] for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])]
    return points, bottom + top + sides


def write_off(path, points, faces):
    rows = [f"{x!r} {y!r} {z!r}" for x, y, z in points] + [
        f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    path.write_text(f"OFF\n{len(points)} {len(faces)} 0\n" + "\n".join(rows) + "\n")


@pytest.mark.parametrize("keep_faces", [False, True], ids=["merged", "kept"])
def test_surface_mesh_is_read_as_the_cli_reads_it(keep_faces, tmp_path):
    points, triangles = l_prism_triangles()
    c = cavity.cdt(points, triangles, surface=True, keep_faces=keep_faces, protect=True)
    assert_positive(c)
    assert volumes(c).sum() == pytest.approx(0.75, abs=1e-15)
    # 20 faces on 8 flat sides (TetGen without -M); with keep_faces each face stays a polygon.
    assert c.stats["warped_faces"] == 0
    assert c.stats["merged_faces"] == (0 if keep_faces else 20)
    assert c.stats["merged_polygons"] == (0 if keep_faces else 8)
    executable = cavity_executable()
    if executable is None:
        pytest.skip("no `cavity` program (set CAVITY_EXECUTABLE)")
    off = tmp_path / "l.off"
    write_off(off, points, triangles)
    prefix = tmp_path / "out"
    subprocess.run([executable, "cdt", str(off), "-o", str(prefix), "--protect", "--quiet"]
                   + (["--keep-faces"] if keep_faces else []), check=True)
    ele = np.loadtxt(f"{prefix}.ele", skiprows=1, dtype=np.int64, comments="#")
    node = np.loadtxt(f"{prefix}.node", skiprows=1, comments="#")
    assert np.array_equal(node[:, 1:4], c.points)
    assert np.array_equal(ele[:, 1:5], c.simplices)


def test_surface_mesh_warped_face_is_cut():
    # Corner 7 (1, 1, 1) lifted 2^-40: of its faces only the top z = 1 is no longer flat.
    points = CUBE.copy()
    points[7, 2] += 2.0**-40
    c = cavity.cdt(points, CUBE_QUADS, surface=True, protect=True)
    assert c.stats["warped_faces"] == 1
    assert_positive(c)
    assert volumes(c).sum() == pytest.approx(1, abs=1e-12)


def test_surface_mesh_defects_are_named():
    # One triangle missing: its three sides are open, each a side of one face only.
    named = r"3 open edges .*\n +edge 1-3: only facet 0\n +edge 1-7: only facet 10"
    with pytest.raises(ValueError, match=named):
        cavity.cdt(CUBE, CUBE_TRIANGLES[:-1], surface=True)


@pytest.mark.parametrize("kwargs, message", [
    ({"keep_faces": True}, "keep_faces=True applies to surface=True only"),
    ({"surface": True, "segments": [[0, 7]]}, "surface=True takes no segments"),
])
def test_surface_keyword_errors(kwargs, message):
    with pytest.raises(ValueError, match=message):
        cavity.cdt(CUBE, CUBE_QUADS, **kwargs)


def test_surface_mesh_polygon_with_two_loops_is_refused():
    points, polygons = box_with_window(lambda outer, inner: [outer, inner])
    with pytest.raises(ValueError, match="polygon 5: with surface=True each polygon is one loop"):
        cavity.cdt(points, polygons, surface=True)
