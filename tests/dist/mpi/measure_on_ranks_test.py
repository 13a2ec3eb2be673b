#!/usr/bin/python3
"""hexadapt-measure under mpirun on 2 and 3 ranks, on .pvtu files VTK wrote: a jittered hex
mesh with every defect the mesh check finds (an inverted cell, a node near another, hanging
nodes, a bow-tie), bad materials, small edges and node targets, and a clean grid far from
unit size. The report on the ranks is the report of one process, figure for figure, with the
same exit code; what runs on one process only, and a missing piece, stop every rank with one
message.

usage: measure_on_ranks_test.py TOOLS_DIR WORK_DIR MPIEXEC
"""
import json
import os
import sys

import numpy as np
import vtk
from vtk.util import numpy_support as ns

from tool_runs import ToolRuns

RUNS = ToolRuns(*sys.argv[1:4])
check, path, run, report = RUNS.check, RUNS.path, RUNS.run, RUNS.report

VTK_ORDER = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def defective(n=(7, 6, 5), scale=1.0, offset=(0.0, 0.0, 0.0)):
    """A vtkUnstructuredGrid of n hexes per axis, inner nodes jittered, with the defects."""
    rng = np.random.default_rng(11)
    nx, ny, nz = n
    k, j, i = np.meshgrid(np.arange(nz + 1), np.arange(ny + 1), np.arange(nx + 1), indexing="ij")
    points = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1).astype(float)
    inner = ((i > 0) & (i < nx) & (j > 0) & (j < ny) & (k > 0) & (k < nz)).ravel()
    points[inner] += rng.uniform(-0.2, 0.2, (inner.sum(), 3))
    points = list(points)

    def node(a, b, c):
        return a + (nx + 1) * (b + (ny + 1) * c)

    cells = [[node(a + d[0], b + d[1], c + d[2]) for d in VTK_ORDER]
             for c in range(nz) for b in range(ny) for a in range(nx)]
    cells[23] = cells[23][4:] + cells[23][:4]  # inverted: bottom and top swapped
    points.append(points[cells[57][0]] + [0.004, 0, 0])  # a node near another (not welded)
    cells[57][0] = len(points) - 1
    # Four half cubes on the top face of cell (3, 2, nz - 1): five nodes hang on it.
    corner = {(0, 0): node(3, 2, nz), (2, 0): node(4, 2, nz), (2, 2): node(4, 3, nz),
              (0, 2): node(3, 3, nz)}
    q = [points[corner[c]] for c in ((0, 0), (2, 0), (2, 2), (0, 2))]
    low, high = {}, {}
    for a in range(3):
        for b in range(3):
            u, v = a / 2, b / 2
            p = (1 - u) * (1 - v) * q[0] + u * (1 - v) * q[1] + u * v * q[2] + (1 - u) * v * q[3]
            if (a, b) in corner:
                low[a, b] = corner[a, b]
            else:
                points.append(p)
                low[a, b] = len(points) - 1
            points.append(p + [0, 0, 0.5])
            high[a, b] = len(points) - 1
    for a in range(2):
        for b in range(2):
            ring = [(a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)]
            cells.append([low[r] for r in ring] + [high[r] for r in ring])
    # A bow-tie: a cube touching the mesh at its far corner only.
    far = node(nx, ny, nz)
    cube = [far]
    for d in VTK_ORDER[1:]:
        points.append(points[far] + d)
        cube.append(len(points) - 1)
    cells.append(cube)

    g = vtk.vtkUnstructuredGrid()
    pts = vtk.vtkPoints()
    pts.SetData(ns.numpy_to_vtk(np.array(points) * scale + offset, deep=1))
    g.SetPoints(pts)
    for c in cells:
        g.InsertNextCell(vtk.VTK_HEXAHEDRON, 8, c)
    m = len(cells)
    for name, values in (
            ("material", np.where(np.arange(m) % 19 == 4, 2.5, np.arange(m) % 2)),
            ("local_size", scale * np.where(np.arange(m) % 13 == 6, 3.0, 1.0))):
        a = ns.numpy_to_vtk(values.astype(float), deep=1)
        a.SetName(name)
        g.GetCellData().AddArray(a)
    targets = np.array(points) * scale + offset + 0.01 * scale * np.sin(np.arange(len(points)))[:, None]
    targets[1::3] = np.nan
    t = ns.numpy_to_vtk(targets, deep=1)
    t.SetName("target")
    g.GetPointData().AddArray(t)
    return g


def write_pieces(g, name, pieces):
    """`g` in WORK/name as `pieces` .vtu pieces and the .pvtu naming them: cell c in piece
    (c // 7) mod pieces, each piece with its own copies of the points it uses (coordinates
    kept in double precision, which VTK's own piece extraction rounds to float)."""
    stem = name[:-len(".pvtu")]
    arrays = {"PPointData": g.GetPointData(), "PCellData": g.GetCellData()}
    lines = ['<?xml version="1.0"?>',
             '<VTKFile type="PUnstructuredGrid" version="1.0" byte_order="LittleEndian" '
             'header_type="UInt64">', '<PUnstructuredGrid GhostLevel="0">']
    for tag, data in arrays.items():
        lines.append("<%s>" % tag)
        for i in range(data.GetNumberOfArrays()):
            a = data.GetArray(i)
            lines.append('<PDataArray type="Float64" Name="%s" NumberOfComponents="%d"/>'
                         % (a.GetName(), a.GetNumberOfComponents()))
        lines.append("</%s>" % tag)
    lines.append('<PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>')
    for p in range(pieces):
        ids = vtk.vtkIdList()
        for c in range(g.GetNumberOfCells()):
            if (c // 7) % pieces == p:
                ids.InsertNextId(c)
        extract = vtk.vtkExtractCells()
        extract.SetInputData(g)
        extract.SetCellList(ids)
        w = vtk.vtkXMLUnstructuredGridWriter()
        w.SetFileName(path("%s_%d.vtu" % (stem, p)))
        w.SetInputConnection(extract.GetOutputPort())
        w.Write()
        lines.append('<Piece Source="%s_%d.vtu"/>' % (os.path.basename(stem), p))
    lines += ["</PUnstructuredGrid>", "</VTKFile>"]
    with open(path(name), "w") as f:
        f.write("\n".join(lines) + "\n")


write_pieces(defective(), "defects.pvtu", 5)
write_pieces(defective(scale=1e-30, offset=(3e-30, 0, -1e-29)), "far.pvtu", 4)
write_pieces(defective(), "two.pvtu", 2)  # 3 ranks: one reads no piece

MEASURE = ("--json", "out.json", "--threshold", "0.8", "--min-edge", "0.5", "--list", "4",
           "--duplicate-tolerance", "1e-3")
for case, wanted in (("defects", 3), ("far", 3), ("two", 3)):
    code, err = run("measure", case + "_serial", 0, "../%s.pvtu" % case, *MEASURE)
    check(code == wanted, "%s: the serial run exits %d: %s" % (case, code, err))
    serial = report(case + "_serial")
    c = serial["mesh_check"]
    check(c["inverted_cells"] == 1 and c["hanging_nodes"] == 5 and c["duplicate_nodes"] == 1
          and c["nonmanifold_nodes"] >= 1,
          "%s: the serial check does not see the defects: %r" % (case, c))
    for ranks in (2, 3):
        folder = "%s_%d" % (case, ranks)
        code, err = run("measure", folder, ranks, "../%s.pvtu" % case, *MEASURE)
        check(code == wanted, "%s on %d ranks exits %d: %s" % (case, ranks, code, err))
        with open(path(folder, "out.json")) as f:
            on = json.load(f)["ranks"]
        check(report(folder) == serial, "%s on %d ranks: the report differs from the serial one"
              % (case, ranks))
        check(on["count"] == ranks and sum(on["cells"]) == serial["mesh"]["cells"]
              and len(on["ghost_cells"]) == ranks and len(on["bytes_sent"]) == ranks
              and all(2 ** 20 < m < 2 ** 32 for m in on["peak_memory"]),
              "%s on %d ranks: the report's ranks are %r" % (case, ranks, on))

# A single .vtu: rank 0 reads it, the ranks cut it as they cut pieces; the serial report.
single = vtk.vtkXMLUnstructuredGridWriter()
single.SetFileName(path("defects.vtu"))
single.SetInputData(defective())
single.Write()
code, err = run("measure", "single_serial", 0, "../defects.vtu", *MEASURE)
code_ranks, err_ranks = run("measure", "single_3", 3, "../defects.vtu", *MEASURE)
check(code == 3 and code_ranks == 3 and report("single_3") == report("single_serial"),
      "a single .vtu on 3 ranks: exit %d (%s), serial %d (%s), or another report"
      % (code_ranks, err_ranks, code, err))

# Refused on several ranks before any work, with one message.
for args, code_wanted, words in (
        (("../defects.pvtu", "--reference", "../defects.pvtu"), 1, ["--reference", "one process"]),
        (("../defects.pvtu", "--quality-field", "q.vtu"), 1, ["--quality-field", "one process"]),
        (("../defects_serial/out.json",), 1, [".pvtu"])):
    code, err = run("measure", "usage", 2, *args)
    check(code == code_wanted and err.count("error") == 1 and all(w in err for w in words),
          "%r on 2 ranks: exit %d, %r" % (args, code, err))
# Beyond --max-memory on a rank: every rank stops (exit 5) with one message.
code, err = run("measure", "usage", 3, "../defects.pvtu", "--max-memory", "10000")
check(code == 5 and err.count("error") == 1 and "rank" in err,
      "--max-memory on 3 ranks: exit %d, %r" % (code, err))
# A piece missing: every rank stops with the message naming it.
os.makedirs(path("broken"))
for name in os.listdir(path()):
    if name.startswith("defects") and name.endswith("u") and name != "defects_3.vtu":
        os.link(path(name), path("broken", name))
code, err = run("measure", "usage", 3, "../broken/defects.pvtu")
check(code == 2 and err.count("error") == 1 and "defects_3.vtu" in err,
      "a missing piece on 3 ranks: exit %d, %r" % (code, err))
check(not os.listdir(path("usage")), "outputs left behind: %s" % os.listdir(path("usage")))

sys.exit(RUNS.finish())
