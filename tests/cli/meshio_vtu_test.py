"""cavity's .vtu files as the field's readers see them: meshio and VTK's own reader (python3-vtk9) read the binary and the ASCII encodings to the same points, cells and
cell data as the TetGen files of the same run, and every cell has positive volume (exactly)."""

import os
import subprocess
import sys
import tempfile
from fractions import Fraction

import meshio
import numpy as np
import vtk  # python3-vtk9

cavity = sys.argv[1]


def run(*args):
    subprocess.run([cavity, *args], check=True, stdout=subprocess.DEVNULL)


def exact_volume_signs(points, cells):
    signs = set()
    for cell in cells:
        a, b, c, d = ([Fraction(x) for x in points[v]] for v in cell)
        u, v, w = ([q[k] - a[k] for k in range(3)] for q in (b, c, d))
        det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
               u[2] * (v[0] * w[1] - v[1] * w[0]))
        signs.add((det > 0) - (det < 0))
    return signs


def read_ele(path):
    rows = np.loadtxt(path, skiprows=1, dtype=np.int64, comments="#")
    return rows[:, 1:5]


with tempfile.TemporaryDirectory() as work:
    os.chdir(work)
    run("generate", "ball", "3000", "-o", "p.node", "--weights", "uniform:0:0.001")
    for weighted in (False, True):
        extra = ["--weighted"] if weighted else []
        run("triangulate", "p.node", "-o", "t", *extra)
        ele = read_ele("t.ele")
        for encoding in ([], ["--ascii"]):
            run("triangulate", "p.node", "-o", "v", "--format", "vtu", *encoding, *extra)
            mesh = meshio.read("v.vtu")
            cells = mesh.cells_dict["tetra"]
            assert np.array_equal(cells, ele), (weighted, encoding)
            assert np.array_equal(mesh.cell_data["tet_id"][0], np.arange(len(ele))), encoding
            assert ("weight" in mesh.point_data) == weighted
            assert exact_volume_signs(mesh.points, cells) == {1}, (weighted, encoding)
            reader = vtk.vtkXMLUnstructuredGridReader()
            reader.SetFileName("v.vtu")
            reader.Update()
            grid = reader.GetOutput()
            assert grid.GetNumberOfCells() == len(ele) and grid.GetNumberOfPoints() == 3000
            quality = vtk.vtkCellQuality()
            quality.SetQualityMeasureToVolume()
            quality.SetInputData(grid)
            quality.Update()
            volumes = quality.GetOutput().GetCellData().GetArray("CellQuality")
            assert min(volumes.GetValue(i) for i in range(grid.GetNumberOfCells())) > 0
    # A CDT with TetGen's region list: the .vtu carries each tetrahedron's region marker.
    poly = ["16 3 0 0"]
    for i in range(8):
        poly.append(f"{i} {(i & 1) * 4} {((i >> 1) & 1) * 4} {((i >> 2) & 1) * 4}")
    for i in range(8):
        poly.append(f"{i + 8} {1 + (i & 1) * 2} {1 + ((i >> 1) & 1) * 2} {1 + ((i >> 2) & 1) * 2}")
    squares = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5)]
    poly.append("12 1")
    for offset in (0, 8):
        for s in squares:
            poly += ["1 0 1", "4 " + " ".join(str(v + offset) for v in s)]
    poly += ["0", "2", "0 2 2 2 7", "1 0.5 0.5 0.5 3"]
    with open("boxes.poly", "w") as f:
        f.write("\n".join(poly) + "\n")
    run("cdt", "boxes.poly", "-o", "boxes", "--protect")
    mesh = meshio.read("boxes.vtu")
    cells = mesh.cells_dict["tetra"]
    regions = mesh.cell_data["region"][0]
    centroids = mesh.points[cells].mean(axis=1)
    inside = np.all((centroids > 1) & (centroids < 3), axis=1)
    assert np.array_equal(regions, np.where(inside, 7, 3)), "region markers"
    assert exact_volume_signs(mesh.points, cells) == {1}
print("meshio reads cavity's .vtu files with positive volumes and CDT region markers")
