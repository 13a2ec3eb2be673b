#!/usr/bin/python3
"""Our scaled Jacobian and shape against VTK's own vtkMeshQuality (Verdict), cell by cell.

Usage: vtk_quality_compare.py HEXADAPT_MEASURE WORKDIR

Builds randomly perturbed (seeded) hex and quad grids with VTK, writes them as .vtu, runs
hexadapt-measure --quality-field on them, and compares the per-cell `scaled_jacobian` and
`shape` arrays it wrote with vtkMeshQuality's HexScaledJacobian / HexShape and
QuadScaledJacobian / QuadShape on the same cells: equal to 1e-9. The perturbation is large
enough to invert some corners, so the sign conventions are compared too. Quads stay
counter-clockwise as a whole (positive area): VTK orients each quad by its own normal,
hexadapt by +z, and the two agree only there.
"""
import json
import os
import subprocess
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

TOLERANCE = 1e-9


def perturbed_grid(n, dim, amplitude, seed):
    """Unstructured grid of n^dim unit cells, every node moved by up to `amplitude`."""
    rng = np.random.default_rng(seed)
    axes = [np.arange(n + 1, dtype=float)] * dim
    if dim == 2:
        axes.append(np.zeros(1))
    zs, ys, xs = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    pts = np.stack([xs.ravel(), ys.ravel(), zs.ravel()], axis=1)
    pts[:, :dim] += rng.uniform(-amplitude, amplitude, (len(pts), dim))
    points = vtk.vtkPoints()
    for p in pts:
        points.InsertNextPoint(*p)
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(points)
    nx = n + 1
    if dim == 2:
        for j in range(n):
            for i in range(n):
                q = vtk.vtkQuad()
                for k, node in enumerate([j * nx + i, j * nx + i + 1, (j + 1) * nx + i + 1, (j + 1) * nx + i]):
                    q.GetPointIds().SetId(k, node)
                grid.InsertNextCell(q.GetCellType(), q.GetPointIds())
    else:
        def node(i, j, k):
            return (k * nx + j) * nx + i
        for k in range(n):
            for j in range(n):
                for i in range(n):
                    h = vtk.vtkHexahedron()
                    corners = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                               node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                               node(i, j + 1, k + 1)]
                    for c, v in enumerate(corners):
                        h.GetPointIds().SetId(c, v)
                    grid.InsertNextCell(h.GetCellType(), h.GetPointIds())
    return grid


def vtk_quality(grid, dim, measure):
    f = vtk.vtkMeshQuality()
    f.SetInputData(grid)
    if dim == 3:
        getattr(f, "SetHexQualityMeasureTo" + measure)()
    else:
        getattr(f, "SetQuadQualityMeasureTo" + measure)()
    f.Update()
    return vtk_to_numpy(f.GetOutput().GetCellData().GetArray("Quality")).astype(float)


def write_vtu(grid, path):
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetInputData(grid)
    w.SetFileName(path)
    if not w.Write():
        raise RuntimeError("cannot write " + path)


def read_cell_array(path, name):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    a = r.GetOutput().GetCellData().GetArray(name)
    if a is None:
        raise RuntimeError(f"{path} has no cell array {name}")
    return vtk_to_numpy(a).astype(float)


def signed_areas(grid):
    out = []
    for c in range(grid.GetNumberOfCells()):
        p = [grid.GetPoint(grid.GetCell(c).GetPointId(k)) for k in range(4)]
        out.append(0.5 * ((p[2][0] - p[0][0]) * (p[3][1] - p[1][1]) - (p[3][0] - p[1][0]) * (p[2][1] - p[0][1])))
    return np.array(out)


def compare(tool, workdir, name, dim, n, amplitude, seed):
    grid = perturbed_grid(n, dim, amplitude, seed)
    if dim == 2 and signed_areas(grid).min() <= 0:
        raise RuntimeError(f"{name}: a quad turned clockwise; lower the amplitude")
    src = os.path.join(workdir, name + ".vtu")
    out = os.path.join(workdir, name + ".quality.vtu")
    report = os.path.join(workdir, name + ".json")
    write_vtu(grid, src)
    run = subprocess.run([tool, src, "-q", "--threshold", "-1", "--quality-field", out, "--json", report])
    # Inverted corners fail the mesh check (exit 3); anything else is an error.
    if run.returncode not in (0, 3):
        raise RuntimeError(f"{name}: hexadapt-measure exited with {run.returncode}")
    failures = 0
    for ours_name, measure in (("scaled_jacobian", "ScaledJacobian"), ("shape", "Shape")):
        ours = read_cell_array(out, ours_name)
        theirs = vtk_quality(grid, dim, measure)
        diff = np.abs(ours - theirs)
        worst = int(np.argmax(diff))
        print(f"{name} {ours_name}: {len(ours)} cells, ours in [{ours.min():.4f}, {ours.max():.4f}], "
              f"max |ours - VTK| = {diff.max():.3e} (cell {worst})")
        if diff.max() > TOLERANCE:
            print(f"  MISMATCH cell {worst}: ours {ours[worst]!r} VTK {theirs[worst]!r}")
            failures += 1
        if ours_name == "scaled_jacobian":
            if ours.min() >= 0:
                print(f"  {name}: no inverted corner: the sign convention is not exercised")
                failures += 1
            with open(report) as f:
                j = json.load(f)
            if abs(j["quality"]["scaled_jacobian"]["min"] - theirs.min()) > TOLERANCE:
                print(f"  report min {j['quality']['scaled_jacobian']['min']} != VTK min {theirs.min()}")
                failures += 1
    return failures


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 1
    tool, workdir = sys.argv[1], sys.argv[2]
    os.makedirs(workdir, exist_ok=True)
    print("VTK", vtk.vtkVersion.GetVTKVersion())
    failures = 0
    failures += compare(tool, workdir, "hexes", 3, 8, 0.42, seed=20261122)
    failures += compare(tool, workdir, "quads", 2, 24, 0.42, seed=7)
    print("FAILED" if failures else "all cells agree with vtkMeshQuality to 1e-9")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
