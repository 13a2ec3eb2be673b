#!/usr/bin/python3
"""Third-party readers accept hexadapt-generate's files: VTK reads the .vtu and .vtk files,
meshio the .vtk files (meshio 1.x cannot parse the String field data of our .vtu
provenance); the cells, the vf_<material> arrays and their exact sums of 1 survive.

  generated_files_test.py TOOLS_DIR
"""
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def check_arrays(path, arrays, materials):
    assert sorted(arrays) == sorted("vf_" + m for m in materials), (path, sorted(arrays))
    total = sum(arrays.values())
    assert np.all(total == 1.0), (path, np.abs(total - 1).max())
    assert all(a.dtype.kind == "f" and a.dtype.itemsize == 8 for a in arrays.values()), path
    assert all(0 < a.sum() for a in arrays.values()), path


def check(tool, tmp, name, args, n_cells, cell_type, materials):
    paths = {}
    for ext in (".vtu", ".vtk"):
        paths[ext] = os.path.join(tmp, name + ext)
        subprocess.run([tool, name, "-q", "-o", paths[ext]] + args, check=True)
    mesh = meshio.read(paths[".vtk"])
    assert len(mesh.cells) == 1 and mesh.cells[0].type == cell_type, mesh.cells
    assert len(mesh.cells[0].data) == n_cells, len(mesh.cells[0].data)
    check_arrays(paths[".vtk"],
                 {k: v[0] for k, v in mesh.cell_data.items() if k.startswith("vf_")}, materials)
    legacy = vtk.vtkUnstructuredGridReader()
    legacy.ReadAllScalarsOn()  # every SCALARS block, not only the first
    for path, reader in ((paths[".vtu"], vtk.vtkXMLUnstructuredGridReader()),
                         (paths[".vtk"], legacy)):
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        assert grid.GetNumberOfCells() == n_cells, path
        cd = grid.GetCellData()
        names = [cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays())]
        check_arrays(path, {n: vtk_to_numpy(cd.GetArray(n)) for n in names if n.startswith("vf_")},
                     materials)


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
