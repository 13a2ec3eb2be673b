"""What the tool tests under mpirun share: a clean work folder, the failures found, a tool run
on some ranks, the report of a run without what depends on the ranks, and grids of three
materials."""
import filecmp
import json
import os
import shutil
import subprocess

import numpy as np
import vtk
from vtk.util import numpy_support as ns


class ToolRuns:
    def __init__(self, tools, work, mpiexec):
        self.tools, self.work, self.mpiexec = tools, work, mpiexec
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        self.failures = []

    def check(self, ok, message):
        if not ok:
            self.failures.append(message)
            print("FAIL:", message)

    def path(self, *names):
        return os.path.join(self.work, *names)

    def run(self, tool, folder, ranks, *args):
        """hexadapt-TOOL ARGS in WORK/folder, on `ranks` MPI ranks (0: without mpirun)."""
        os.makedirs(self.path(folder), exist_ok=True)
        command = [os.path.join(self.tools, "hexadapt-" + tool), *args]
        if ranks:
            command = [self.mpiexec, "-np", str(ranks), "--oversubscribe", *command]
        r = subprocess.run(command, cwd=self.path(folder), capture_output=True, text=True)
        return r.returncode, r.stderr

    def report(self, folder, ranks=None):
        """WORK/folder/out.json without its times and ranks (checked when ranks is given: the
        count, and the layers owned (of an unstructured mesh: the cells), bytes sent and peak
        memory of each)."""
        with open(self.path(folder, "out.json")) as f:
            r = json.load(f)
        r.pop("times")
        on = r.pop("ranks", None)
        if ranks:
            self.check(on["count"] == ranks and len(on["bytes_sent"]) == ranks
                       and len(on["layers"] if "layers" in on else on["cells"]) == ranks
                       and len(on["peak_memory"]) == ranks
                       and all(2 ** 20 < m < 2 ** 32 for m in on["peak_memory"]),
                       "%s: the report's ranks are %r" % (folder, on))
        return r

    def as_serial(self, tool, case, source, *options):
        """Runs hexadapt-TOOL on `source` (in WORK) with `options` on one process, then on 2
        and 3 ranks with --gather: each gathered file must have the serial bytes, each report
        the serial figures. Returns the serial report."""
        args = ("../" + source, "-o", "out.vtu", "--gather", "--json", "out.json") + options
        code, err = self.run(tool, case + "_serial", 0, *args)
        self.check(code == 0, "%s: the serial run exits %d: %s" % (case, code, err))
        for ranks in (2, 3):
            folder = "%s_%d" % (case, ranks)
            code, err = self.run(tool, folder, ranks, *args)
            self.check(code == 0, "%s on %d ranks exits %d: %s" % (case, ranks, code, err))
            self.check(filecmp.cmp(self.path(case + "_serial", "out.vtu"),
                                   self.path(folder, "out.vtu"), shallow=False),
                       "%s on %d ranks: the gathered file differs from the serial one"
                       % (case, ranks))
            self.check(self.report(case + "_serial") == self.report(folder, ranks),
                       "%s on %d ranks: the report differs from the serial one" % (case, ranks))
        return self.report(case + "_serial")

    def write_pieces(self, g, name, pieces, ghost=0):
        """`g` in WORK/name as `pieces` pieces, by VTK's parallel writer for its kind."""
        kind = g.GetClassName().replace("vtk", "")
        w = getattr(vtk, "vtkXMLP" + kind + "Writer")()
        w.SetFileName(self.path(name))
        if kind == "UnstructuredGrid":  # each piece its share of the cells, not the whole
            extract = vtk.vtkExtractUnstructuredGridPiece()
            extract.SetInputData(g)
            w.SetInputConnection(extract.GetOutputPort())
        else:
            w.SetInputData(g)
        w.SetNumberOfPieces(pieces)
        w.SetStartPiece(0)
        w.SetEndPiece(pieces - 1)
        w.SetGhostLevel(ghost)
        w.Write()

    def finish(self):
        print("%d failure(s)" % len(self.failures))
        return 1 if self.failures else 0


def add_materials(g, n, flat=False, origin=(0.0, 0.0, 0.0)):
    """Three materials in `g`, a grid of n cells per axis from `origin`: a rough ball (its
    majority cells pinch at nodes, which assign's correction must mend, across the ranks'
    borders too), a slab below it, the matrix around."""
    centres = vtk.vtkCellCenters()
    centres.SetInputData(g)
    centres.Update()
    c = ns.vtk_to_numpy(centres.GetOutput().GetPoints().GetData()) - origin
    r = np.linalg.norm(c - [n[0] / 2, n[1] / 2, 0 if flat else n[2] / 2], axis=1)
    r += np.random.default_rng(7).uniform(-1.5, 1.5, len(r)) * (2.5 if flat else 1)
    ball = np.clip(4.3 - r, 0, 1)
    slab = np.clip(2.6 - c[:, 1], 0, 1) * (1 - ball)
    for name, v in (("vf_ball", ball), ("vf_slab", slab), ("vf_matrix", 1 - ball - slab)):
        a = ns.numpy_to_vtk(v, deep=1)
        a.SetName(name)
        g.GetCellData().AddArray(a)
    return g


def unstructured(g, seed=3):
    """`g` (a rectilinear grid's voxels or pixels) as an unstructured grid of hexahedra or
    quads, its cells in a shuffled order: pieces of it are scattered over the domain."""
    flat = g.GetCell(0).GetCellType() == vtk.VTK_PIXEL
    order = (0, 1, 3, 2) if flat else (0, 1, 3, 2, 4, 5, 7, 6)
    cells = np.random.default_rng(seed).permutation(g.GetNumberOfCells())
    u = vtk.vtkUnstructuredGrid()
    points = vtk.vtkPoints()
    points.SetData(ns.numpy_to_vtk(np.array([g.GetPoint(i) for i in
                                             range(g.GetNumberOfPoints())]), deep=1))
    u.SetPoints(points)
    u.Allocate(len(cells))
    for c in cells:
        ids = g.GetCell(int(c)).GetPointIds()
        u.InsertNextCell(vtk.VTK_QUAD if flat else vtk.VTK_HEXAHEDRON, len(order),
                         [ids.GetId(k) for k in order])
    data = g.GetCellData()
    for i in range(data.GetNumberOfArrays()):
        a = ns.numpy_to_vtk(ns.vtk_to_numpy(data.GetArray(i))[cells], deep=1)
        a.SetName(data.GetArrayName(i))
        u.GetCellData().AddArray(a)
    return u


def grid(n, flat=False):
    """A rectilinear grid of n cells per axis (nz = 0: 2D) with add_materials' three."""
    axes = [np.linspace(0, 1, k + 1) ** 1.1 * k for k in n[:2]]
    axes.append(np.array([0.0]) if flat else np.linspace(0, n[2], n[2] + 1))
    g = vtk.vtkRectilinearGrid()
    g.SetDimensions(*[len(a) for a in axes])
    for setter, a in zip((g.SetXCoordinates, g.SetYCoordinates, g.SetZCoordinates), axes):
        setter(ns.numpy_to_vtk(a, deep=1))
    return add_materials(g, n, flat)
