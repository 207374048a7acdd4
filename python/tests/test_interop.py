"""cavity.Delaunay handed to other tools (meshio, VTK/PyVista arrays), and used from threads."""

import importlib.util
import threading
import time

import numpy as np
import pytest

import cavity


def right_hand_volumes(points, cells):
    p = points[cells]
    return np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])


def test_to_meshio_has_positive_tetrahedra(tmp_path):
    meshio = pytest.importorskip("meshio")
    points = np.random.default_rng(1).random((300, 3))
    d = cavity.Delaunay(points)
    mesh = d.to_meshio()
    assert isinstance(mesh, meshio.Mesh)
    tets = mesh.cells_dict["tetra"]
    assert np.array_equal(tets, d.simplices) and np.array_equal(mesh.points, points)
    assert (right_hand_volumes(mesh.points, tets) > 0).all()
    # And it survives a VTK file round trip with the same cells.
    path = tmp_path / "tets.vtu"
    mesh.write(path)
    back = meshio.read(path)
    assert np.array_equal(back.cells_dict["tetra"], d.simplices)


def test_vtk_cells_are_what_pyvista_takes():
    points = np.random.default_rng(2).random((200, 3))
    d = cavity.Delaunay(points)
    cells, celltypes, pts = d.vtk_cells()
    assert cells.dtype == np.int64 and celltypes.dtype == np.uint8
    assert cells.shape == (5 * d.nsimplex,)
    rows = cells.reshape(-1, 5)
    assert (rows[:, 0] == 4).all() and np.array_equal(rows[:, 1:], d.simplices)
    assert (celltypes == cavity._delaunay.VTK_TETRA).all() and cavity._delaunay.VTK_TETRA == 10
    assert (right_hand_volumes(pts, rows[:, 1:]) > 0).all()


def test_to_pyvista_or_what_to_use_without_it():
    d = cavity.Delaunay(np.random.default_rng(3).random((20, 3)))
    if importlib.util.find_spec("pyvista") is None:
        with pytest.raises(ImportError, match="vtk_cells"):
            d.to_pyvista()
    else:
        assert d.to_pyvista().n_cells == d.nsimplex


def test_construction_releases_the_gil():
    """While one thread triangulates, another runs Python code: it could not if the engine held
    the GIL (the interpreter hands the GIL over only between bytecodes)."""
    points = np.random.default_rng(4).random((300_000, 3))
    ticks = []
    span = {}
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())

    def build():
        span["start"] = time.perf_counter()
        cavity.Delaunay(points)
        span["end"] = time.perf_counter()
        done.set()

    counter = threading.Thread(target=count)
    counter.start()
    build()
    counter.join()
    start, end = span["start"], span["end"]
    # The middle half of the construction: conversions at either end hold the GIL.
    middle = [t for t in ticks if start + (end - start) / 4 < t < end - (end - start) / 4]
    assert len(middle) > 100


def test_two_threads_triangulate_two_point_sets_correctly():
    rng = np.random.default_rng(5)
    sets = [rng.random((20_000, 3)) for _ in range(2)]
    out = [None, None]

    def run(i):
        out[i] = cavity.Delaunay(sets[i])

    threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for i in range(2):
        assert np.array_equal(out[i].simplices, cavity.Delaunay(sets[i]).simplices)


def vtk_volumes(cells, celltypes, points):
    """Each cell's signed volume as VTK's own mesh-quality filter (Verdict) computes it."""
    data_model = pytest.importorskip("vtkmodules.vtkCommonDataModel")
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
    from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR, vtkPoints
    from vtkmodules.vtkFiltersVerdict import vtkMeshQuality

    grid = data_model.vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    grid.SetPoints(vtk_points)
    cell_array = data_model.vtkCellArray()
    cell_array.SetCells(len(celltypes), numpy_to_vtkIdTypeArray(cells, deep=True))
    grid.SetCells(numpy_to_vtk(celltypes, deep=True, array_type=VTK_UNSIGNED_CHAR), cell_array)
    quality = vtkMeshQuality()
    quality.SetInputData(grid)
    quality.SetTetQualityMeasureToVolume()
    quality.Update()
    return vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Quality"))


def test_vtk_itself_finds_every_cell_positive():
    d = cavity.Delaunay(np.random.default_rng(6).random((300, 3)))
    cells, celltypes, points = d.vtk_cells()
    volumes = vtk_volumes(cells, celltypes, points)
    assert len(volumes) == d.nsimplex and (volumes > 0).all()
    assert volumes.sum() == pytest.approx(np.abs(right_hand_volumes(points, d.simplices)).sum() / 6)
    # The filter's volume is signed: the same cells with two vertices swapped are all negative.
    swapped = cells.reshape(-1, 5)[:, [0, 2, 1, 3, 4]].ravel()
    assert (vtk_volumes(swapped, celltypes, points) < 0).all()


def test_one_object_shared_by_threads_stays_consistent():
    """add_points from two threads at once, and queries meanwhile: the insertions are serialised,
    the arrays a query reads stay alive while newer ones are published, and the end state is the
    triangulation of every point, as one construction of the final points would give."""
    rng = np.random.default_rng(7)
    d = cavity.Delaunay(rng.random((2000, 3)), incremental=True)
    batches = [rng.random((3000, 3)) for _ in range(6)]
    queries = rng.random((5000, 3))
    errors = []

    def insert(mine):
        try:
            for b in mine:
                d.add_points(b)
        except Exception as e:  # reported below: a thread's exception is otherwise lost
            errors.append(e)

    def query():
        try:
            for _ in range(20):
                found = d.find_simplex(queries)
                assert (found >= -1).all() and (found >= 0).mean() > 0.9  # the hull grows
                d.vertex_neighbor_vertices
        except Exception as e:
            errors.append(e)

    threads = [threading.Thread(target=insert, args=(batches[0::2],)),
               threading.Thread(target=insert, args=(batches[1::2],)),
               threading.Thread(target=query)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert d.npoints == 2000 + 6 * 3000
    whole = cavity.Delaunay(np.asarray(d.points))
    assert np.array_equal(np.sort(np.sort(d.simplices, axis=1), axis=0),
                          np.sort(np.sort(whole.simplices, axis=1), axis=0))
    assert d.check()
