#!/usr/bin/python3
"""Parallel, multi-block, time-series and LZ4/LZMA-compressed VTK files written by VTK itself,
through the tools: the same assignment as from the single file, and exit 2 with a clear
message for the broken ones. Then a label map through assign and adapt.

usage: parallel_vtk_test.py TOOLS_DIR WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np
import vtk
from vtk.util import numpy_support as ns

TOOLS, WORK = sys.argv[1], sys.argv[2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def path(name):
    return os.path.join(WORK, name)


def tool(name, *args):
    r = subprocess.run([os.path.join(TOOLS, "hexadapt-" + name), *args],
                       capture_output=True, text=True)
    return r.returncode, r.stderr


# ---- a 3D rectilinear grid with three materials (a ball and a slab in a matrix) -------------

def fractions_grid(n=(12, 10, 6), shift=0.0):
    axes = [np.linspace(0, 1, k + 1) ** 1.15 * k for k in n]
    g = vtk.vtkRectilinearGrid()
    g.SetDimensions(*[k + 1 for k in n])
    for setter, a in zip((g.SetXCoordinates, g.SetYCoordinates, g.SetZCoordinates), axes):
        setter(ns.numpy_to_vtk(a, deep=1))
    s = 5  # samples per axis and cell
    ball, slab = [], []
    for k in range(n[2]):
        for j in range(n[1]):
            for i in range(n[0]):
                t = (np.arange(s) + 0.5) / s
                x = axes[0][i] + t * (axes[0][i + 1] - axes[0][i])
                y = axes[1][j] + t * (axes[1][j + 1] - axes[1][j])
                z = axes[2][k] + t * (axes[2][k + 1] - axes[2][k])
                X, Y, Z = np.meshgrid(x, y, z, indexing="ij")
                inb = (X - 5.5 - shift) ** 2 + (Y - 4.5) ** 2 + (Z - 3) ** 2 < 3.2 ** 2
                ins = (Y < 2.2) & ~inb
                ball.append(inb.mean())
                slab.append(ins.mean())
    ball, slab = np.array(ball), np.array(slab)
    for name, v in (("vf_ball", ball), ("vf_slab", slab), ("vf_matrix", 1 - ball - slab)):
        arr = ns.numpy_to_vtk(np.clip(v, 0, 1), deep=1)
        arr.SetName(name)
        g.GetCellData().AddArray(arr)
    return g


def write(writer, name, data=None, port=None, pieces=None, ghost=0, compressor=None):
    w = writer()
    w.SetFileName(path(name))
    if data is not None:
        w.SetInputData(data)
    else:
        w.SetInputConnection(port)
    if pieces:
        w.SetNumberOfPieces(pieces)
        w.SetStartPiece(0)
        w.SetEndPiece(pieces - 1)
        w.SetGhostLevel(ghost)
    if compressor:
        getattr(w, "SetCompressorTypeTo" + compressor)()
    w.Write()


def read_vtu(name):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path(name))
    r.Update()
    return r.GetOutput()


def by_centre(name, array="material"):
    """{rounded cell centre: value} of an output file."""
    d = read_vtu(name)
    centres = vtk.vtkCellCenters()
    centres.SetInputData(d)
    centres.Update()
    c = ns.vtk_to_numpy(centres.GetOutput().GetPoints().GetData())
    v = ns.vtk_to_numpy(d.GetCellData().GetArray(array))
    return {tuple(np.round(p, 5)): x for p, x in zip(c, v)}


grid = fractions_grid()
write(vtk.vtkXMLRectilinearGridWriter, "single.vtr", data=grid)
reader = vtk.vtkXMLRectilinearGridReader()
reader.SetFileName(path("single.vtr"))
# vtkAppendFilter asks its source for one piece at a time, so the parallel writer gets real
# pieces (a reader of an unstructured file would give each piece the whole mesh).
to_unstructured = vtk.vtkAppendFilter()
to_unstructured.SetInputConnection(reader.GetOutputPort())
to_points = vtk.vtkRectilinearGridToPointSet()
to_points.SetInputConnection(reader.GetOutputPort())
write(vtk.vtkXMLUnstructuredGridWriter, "single.vtu", port=to_unstructured.GetOutputPort())
write(vtk.vtkXMLPUnstructuredGridWriter, "four.pvtu", port=to_unstructured.GetOutputPort(), pieces=4)
write(vtk.vtkXMLPUnstructuredGridWriter, "ghost.pvtu", port=to_unstructured.GetOutputPort(),
      pieces=4, ghost=1)
write(vtk.vtkXMLPRectilinearGridWriter, "four.pvtr", port=reader.GetOutputPort(), pieces=4)
write(vtk.vtkXMLPRectilinearGridWriter, "ghost.pvtr", port=reader.GetOutputPort(), pieces=4,
      ghost=1)
write(vtk.vtkXMLStructuredGridWriter, "single.vts", port=to_points.GetOutputPort())
write(vtk.vtkXMLPStructuredGridWriter, "four.pvts", port=to_points.GetOutputPort(), pieces=4)
for c in ("LZ4", "LZMA"):
    write(vtk.vtkXMLUnstructuredGridWriter, "single_%s.vtu" % c.lower(),
          port=to_unstructured.GetOutputPort(), compressor=c)

with open(path("four.pvtu")) as f:
    text = f.read()
check(text.count("<Piece") == 4, "VTK wrote 4 pieces")
for k in range(4):
    with open(path("four_%d.vtu" % k)) as f:
        check('NumberOfCells="720"' not in f.read(), "piece %d is not the whole mesh" % k)


def assign(src, out, *extra):
    rc, err = tool("assign", path(src), "-o", path(out), "--json", path(out + ".json"), *extra)
    check(rc == 0, "assign %s: exit %d: %s" % (src, rc, err))
    return rc


# ---- parallel files give the single file's assignment --------------------------------------
assign("single.vtu", "single.assign.vtu")
reference = by_centre("single.assign.vtu")
check(len(reference) == 720, "720 cells in the single file")
for src in ("four.pvtu", "ghost.pvtu"):
    if assign(src, src + ".assign.vtu") == 0:
        got = by_centre(src + ".assign.vtu")
        check(got == reference, "%s: same material per cell as the single file" % src)
        check(read_vtu(src + ".assign.vtu").GetNumberOfPoints() ==
              read_vtu("single.assign.vtu").GetNumberOfPoints(), "%s: border points welded" % src)
# Structured pieces become the one grid: the same cells in the same order.
assign("single.vtr", "single_vtr.assign.vtu")
for src in ("four.pvtr", "ghost.pvtr", "four.pvts"):
    if assign(src, src + ".assign.vtu") == 0:
        a = read_vtu("single_vtr.assign.vtu")
        b = read_vtu(src + ".assign.vtu")
        check(b.GetCellData().GetArray("vtkGhostType") is None, "%s: no ghost flags" % src)
        for name in ("material", "vf_ball"):
            x = ns.vtk_to_numpy(a.GetCellData().GetArray(name))
            y = ns.vtk_to_numpy(b.GetCellData().GetArray(name))
            check(np.array_equal(x, y), "%s: %s as from the single .vtr" % (src, name))
        check(np.allclose(ns.vtk_to_numpy(a.GetPoints().GetData()),
                          ns.vtk_to_numpy(b.GetPoints().GetData()), rtol=0, atol=1e-6),
              "%s: points as from the single .vtr" % src)

# ---- LZ4 and LZMA ---------------------------------------------------------------------------
for c in ("lz4", "lzma"):
    with open(path("single_%s.vtu" % c), "rb") as f:
        check(("vtk%sDataCompressor" % c.upper()).encode() in f.read(), "VTK wrote %s" % c)
    if assign("single_%s.vtu" % c, "%s.assign.vtu" % c) == 0:
        check(by_centre("%s.assign.vtu" % c) == reference, "%s: same assignment" % c)
    # A corrupt block: flip bytes in the middle of the appended data.
    with open(path("single_%s.vtu" % c), "rb") as f:
        data = bytearray(f.read())
    start = data.index(b"<AppendedData")
    start = data.index(b"_", start) + 1 + 40
    for k in range(start, start + 12):
        data[k] ^= 0x5A
    with open(path("corrupt_%s.vtu" % c), "wb") as f:
        f.write(data)
    rc, err = tool("assign", path("corrupt_%s.vtu" % c), "-o", path("x.vtu"))
    check(rc == 2 and "corrupt" in err and "block" in err,
          "corrupt %s: exit %d: %s" % (c, rc, err))

# ---- time series ----------------------------------------------------------------------------
steps = [(0.0, 0.0), (0.5, 1.0), (1.25, 2.0)]
pvd = ['<?xml version="1.0"?>', '<VTKFile type="Collection" version="0.1">', "<Collection>"]
os.makedirs(path("series"))
for k, (t, shift) in enumerate(steps):
    write(vtk.vtkXMLRectilinearGridWriter, "series/s_%d.vtr" % k, data=fractions_grid(shift=shift))
    pvd.append('<DataSet timestep="%g" group="" part="0" file="series/s_%d.vtr"/>' % (t, k))
pvd += ["</Collection>", "</VTKFile>"]
with open(path("series.pvd"), "w") as f:
    f.write("\n".join(pvd) + "\n")
assign("series/s_1.vtr", "s1.assign.vtu")
for args in (["--step", "1"], ["--time", "0.5"]):
    if assign("series.pvd", "pvd.assign.vtu", *args) == 0:
        check(by_centre("pvd.assign.vtu") == by_centre("s1.assign.vtu"), "pvd %s" % args)
for args in (["--step", "3"], ["--time", "0.7"], []):
    rc, err = tool("assign", path("series.pvd"), "-o", path("x.vtu"), *args)
    check(rc == 2 and "0: t = 0, 1: t = 0.5, 2: t = 1.25" in err,
          "pvd %s: exit %d: %s" % (args, rc, err))

# ---- multi-block ----------------------------------------------------------------------------
mb = vtk.vtkMultiBlockDataSet()
mb.SetNumberOfBlocks(2)
left = vtk.vtkExtractRectilinearGrid()
left.SetInputData(grid)
left.SetVOI(0, 6, 0, 10, 0, 6)
left.Update()
right = vtk.vtkExtractRectilinearGrid()
right.SetInputData(grid)
right.SetVOI(6, 12, 0, 10, 0, 6)
right.Update()
mb.SetBlock(0, left.GetOutput())
mb.SetBlock(1, right.GetOutput())
write(vtk.vtkXMLMultiBlockDataWriter, "blocks.vtm", data=mb)
if assign("blocks.vtm", "vtm.assign.vtu") == 0:
    check(by_centre("vtm.assign.vtu") == by_centre("single_vtr.assign.vtu"), "vtm blocks")

# ---- broken collections: exit 2 and a message naming the problem ------------------------------
os.makedirs(path("broken"))


def broken(name, text, expected, pieces=()):
    for p in pieces:
        shutil.copy(path(p), path("broken/" + os.path.basename(p)))
    with open(path("broken/" + name), "w") as f:
        f.write(text)
    rc, err = tool("assign", path("broken/" + name), "-o", path("x.vtu"))
    check(rc == 2 and expected in err, "%s: exit %d, expected %r in: %s" % (name, rc, expected, err))


broken("missing.pvtu", text.replace("four_3.vtu", "gone_3.vtu"), "gone_3.vtu",
       ["four_0.vtu", "four_1.vtu", "four_2.vtu"])
broken("kind.pvtu", text.replace("four_3.vtu", "four_3.vtr"), "expected an UnstructuredGrid",
       ["four_3.vtr"])
with open(path("four.pvtr")) as f:
    ptext = f.read()
broken("lying.pvtr", ptext.replace('WholeExtent="0 12', 'WholeExtent="0 1200'),
       "the pieces hold only", ["four_%d.vtr" % k for k in range(4)])
broken("escape.pvtu", text.replace("four_0.vtu", "../four_0.vtu"), "without '..'")

# ---- a label map: assign, then adapt ----------------------------------------------------------
img = vtk.vtkImageData()
img.SetDimensions(21, 17, 1)
img.SetSpacing(0.5, 0.5, 1)
labels = np.zeros(20 * 16, dtype=np.int32)
for j in range(16):
    for i in range(20):
        x, y = (i + 0.5) * 0.5, (j + 0.5) * 0.5
        labels[i + 20 * j] = 5 if (x - 5) ** 2 + (y - 4) ** 2 < 2.6 ** 2 else (2 if y < 1.6 else 0)
arr = ns.numpy_to_vtk(labels, deep=1)
arr.SetName("phase")
img.GetCellData().AddArray(arr)
write(vtk.vtkXMLImageDataWriter, "labels.vti", data=img)
if assign("labels.vti", "labels.assign.vtu", "--labels", "phase", "--label-names", "5=core") == 0:
    with open(path("labels.assign.vtu.json")) as f:
        report = json.load(f)
    check(report["materials"] == ["label_0", "label_2", "core"], "label names: %s" % report["materials"])
    rc, err = tool("adapt", path("labels.assign.vtu"), "-o", path("labels.mesh.vtu"))
    check(rc == 0, "adapt of the label map: exit %d: %s" % (rc, err))
    if rc == 0:
        mat = ns.vtk_to_numpy(read_vtu("labels.mesh.vtu").GetCellData().GetArray("material"))
        check(sorted(set(mat.tolist())) == [0, 1, 2], "three materials meshed")
flt = ns.numpy_to_vtk(labels.astype(np.float64) + 0.5, deep=1)
flt.SetName("phase")
img.GetCellData().AddArray(flt)
write(vtk.vtkXMLImageDataWriter, "bad_labels.vti", data=img)
rc, err = tool("assign", path("bad_labels.vti"), "-o", path("x.vtu"), "--labels", "phase")
check(rc == 2 and "bad_labels.vti" in err and "'phase'" in err and "not an integer" in err,
      "non-integer labels: exit %d: %s" % (rc, err))
rc, err = tool("assign", path("labels.vti"), "-o", path("x.vtu"), "--labels", "phases")
check(rc == 2 and "labels.vti" in err and "'phases'" in err, "missing label array: %s" % err)

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
