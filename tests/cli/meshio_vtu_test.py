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
print("meshio reads cavity's .vtu files with positive volumes")
