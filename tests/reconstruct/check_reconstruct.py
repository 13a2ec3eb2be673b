"""ParaView-side check of hexadapt-reconstruct's outputs, with Debian's VTK and meshio.

Writes a 2D two-material case with meshio, runs the tool, then reads the pixel mesh and the
model with VTK's own readers: the pixel `material` array must match the model's interfaces
(every model segment separates two pixels or cells of its two materials) and the model's
arrays must be there.
  check_reconstruct.py TOOL WORKDIR
"""
import os
import subprocess
import sys

import meshio
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def make_case(path):
    n = 8
    pts = np.array([[i, j, 0.0] for j in range(n + 1) for i in range(n + 1)])
    quads = np.array([[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1,
                       (j + 1) * (n + 1) + i] for j in range(n) for i in range(n)])
    s = 20
    frac = []
    for j in range(n):
        for i in range(n):
            u = (np.arange(s) + 0.5) / s
            x, y = np.meshgrid(i + u, j + u)
            frac.append(np.mean(np.hypot(x - 4.1, y - 3.9) < 2.3))
    vf_in = np.array(frac)
    material = (vf_in > 0.5).astype(np.int32)
    meshio.write(path, meshio.Mesh(pts, [("quad", quads)],
                                   cell_data={"vf_out": [1 - vf_in], "vf_in": [vf_in],
                                              "material": [material]}))


def main():
    tool, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    case = os.path.join(work, "disk.assign.vtu")
    make_case(case)
    pixels = os.path.join(work, "disk.pixels.vtu")
    model = os.path.join(work, "disk.model")
    subprocess.run([tool, case, "-o", pixels, "--model", model, "-q"], check=True)

    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(pixels)
    r.Update()
    grid = r.GetOutput()
    mat = vtk_to_numpy(grid.GetCellData().GetArray("material"))
    parent = vtk_to_numpy(grid.GetCellData().GetArray("parent"))
    assert grid.GetNumberOfCells() > 0 and len(mat) == grid.GetNumberOfCells()
    assert set(np.unique(mat)) <= {0, 1}, np.unique(mat)
    assert parent.min() >= 0 and parent.max() < 64

    pr = vtk.vtkPolyDataReader()
    pr.SetFileName(model + ".vtk")
    pr.Update()
    poly = pr.GetOutput()
    lo = vtk_to_numpy(poly.GetCellData().GetArray("material_lo"))
    hi = vtk_to_numpy(poly.GetCellData().GetArray("material_hi"))
    kind = vtk_to_numpy(poly.GetCellData().GetArray("kind"))
    assert poly.GetNumberOfLines() > 0
    assert np.all(lo[kind == 0] == 0) and np.all(hi[kind == 0] == 1)
    # The disk is inside the domain: its interface is closed, so it has no corners.
    assert not np.any(kind == 2)
    # Closed polyline, material 0 on the left of every segment: minus the enclosed signed
    # area is the area of material 1 (pixels plus the cells without pixels).
    area = 0.0
    for c in range(poly.GetNumberOfCells()):
        if kind[c] != 0:
            continue
        ids = poly.GetCell(c).GetPointIds()
        p0 = poly.GetPoint(ids.GetId(0))
        p1 = poly.GetPoint(ids.GetId(1))
        area -= 0.5 * (p0[0] * p1[1] - p1[0] * p0[1])
    cq = vtk.vtkCellSizeFilter()
    cq.SetInputData(grid)
    cq.Update()
    sizes = vtk_to_numpy(cq.GetOutput().GetCellData().GetArray("Area"))
    pix_area = sizes[mat == 1].sum()
    pixelated = set(parent.tolist())
    ra = meshio.read(case)
    inner = [c for c in range(64) if c not in pixelated and ra.cell_data["material"][0][c] == 1]
    want = pix_area + len(inner)
    assert abs(area - want) < 1e-9 * want, (area, want)
    print("ok: %d pixels, %d model segments, disk area %.6f" % (len(mat), int((kind == 0).sum()), area))


if __name__ == "__main__":
    main()
