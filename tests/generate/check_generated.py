#!/usr/bin/python3
"""Third-party readers (meshio, VTK) accept hexadapt-generate's files: the cells, the
vf_<material> arrays and their exact sums of 1 survive the round trip.

  check_generated.py TOOLS_DIR
"""
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def check(tool, tmp, name, args, n_cells, cell_type, materials):
    for ext in (".vtu", ".vtk"):
        path = os.path.join(tmp, name + ext)
        subprocess.run([tool, name, "-q", "-o", path] + args, check=True)
        mesh = meshio.read(path)
        assert len(mesh.cells) == 1 and mesh.cells[0].type == cell_type, (path, mesh.cells)
        assert len(mesh.cells[0].data) == n_cells, (path, len(mesh.cells[0].data))
        arrays = {k: v[0] for k, v in mesh.cell_data.items() if k.startswith("vf_")}
        assert sorted(arrays) == sorted("vf_" + m for m in materials), (path, sorted(arrays))
        total = sum(arrays.values())
        assert np.all(total == 1.0), (path, np.abs(total - 1).max())
        assert all(a.dtype == np.float64 for a in arrays.values()), path
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(tmp, name + ".vtu"))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfCells() == n_cells
    vf = vtk_to_numpy(grid.GetCellData().GetArray("vf_" + materials[-1]))
    assert 0 < vf.sum() < n_cells


def main():
    tool = os.path.join(sys.argv[1], "hexadapt-generate")
    with tempfile.TemporaryDirectory() as tmp:
        check(tool, tmp, "venn4", ["--dims", "20,16"], 320, "quad",
              ["outside", "a", "b", "c", "d"])
        check(tool, tmp, "asteroid", ["--dims", "8,8,8", "--jitter", "0.2"], 512, "hexahedron",
              ["space", "rock", "core"])
        check(tool, tmp, "stir", ["--dims", "16,8", "--extrude", "3"], 384, "hexahedron",
              ["bottom", "middle", "top"])
    print("ok")


if __name__ == "__main__":
    main()
