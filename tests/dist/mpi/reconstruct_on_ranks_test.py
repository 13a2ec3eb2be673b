#!/usr/bin/python3
"""hexadapt-reconstruct under mpirun on 2 and 3 ranks, on parallel files VTK wrote and on the
.pvts of hexadapt-assign on ranks: the gathered pixel mesh is the bytes of the run on one
process and the report its figures (default nsub and 1); the .pvtu of pieces reads in VTK
as the same pixels; what runs on one process only, and a bad input, stop every rank with one
message and no output.

usage: reconstruct_on_ranks_test.py TOOLS_DIR WORK_DIR MPIEXEC
"""
import json
import os
import sys

import numpy as np
import vtk
from vtk.util import numpy_support as ns

from tool_runs import ToolRuns, add_materials, grid, unstructured

RUNS = ToolRuns(*sys.argv[1:4])
check, path, run, report = RUNS.check, RUNS.path, RUNS.run, RUNS.report
write_pieces = RUNS.write_pieces


def jittered(n, offset):
    """A structured grid of n cells per axis, its nodes moved at random (cells of many
    volumes), the whole moved by `offset`."""
    rng = np.random.default_rng(3)
    k, j, i = np.meshgrid(*[np.arange(m + 1, dtype=float) for m in n[::-1]], indexing="ij")
    p = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1)
    p += rng.uniform(-0.2, 0.2, p.shape)
    g = vtk.vtkStructuredGrid()
    g.SetDimensions(*[m + 1 for m in n])
    points = vtk.vtkPoints()
    points.SetData(ns.numpy_to_vtk(p + offset, deep=1))
    g.SetPoints(points)
    return add_materials(g, n, origin=offset)


def pixels(name, reader):
    """(centre, parent) -> (material, free) of every pixel VTK reads in `name`."""
    r = reader()
    r.SetFileName(path(name))
    r.Update()
    data = r.GetOutput()
    centres = vtk.vtkCellCenters()
    centres.SetInputData(data)
    centres.Update()
    c = ns.vtk_to_numpy(centres.GetOutput().GetPoints().GetData())
    arrays = [ns.vtk_to_numpy(data.GetCellData().GetArray(a)) for a in ("parent", "material", "free")]
    return {(tuple(np.round(p, 6)), int(par)): (int(m), int(f))
            for p, par, m, f in zip(c, *arrays)}


write_pieces(grid((13, 11, 17)), "hex.pvtr", 4)
write_pieces(grid((19, 15, 0), flat=True), "quad.pvtr", 3)
write_pieces(jittered((9, 8, 14), np.array([1e6, -2e5, 3e5])), "far.pvts", 3)

# nsub 1 needs 4 ghost layers, the default 2 (the C++ tests cover more nsub and sweeps).
for case, source, options in (("hex", "hex.pvtr", ()), ("hex_nsub1", "hex.pvtr", ("--nsub", "1")),
                              ("quad", "quad.pvtr", ()), ("far", "far.pvts", ("--nsub", "3"))):
    r = RUNS.as_serial("reconstruct", case, source, "--majority", *options)
    check(r.get("mixed_cells", 0) > 30 and r["method_stats"]["rounds"] > 3,
          "%s: %r mixed cells, too few to test the ranks" % (case, r.get("mixed_cells")))

# The chain on ranks: assign writes .vts pieces, reconstruct reads them on other ranks.
code, err = run("assign", "chain", 3, "../hex.pvtr", "-o", "assigned.pvts")
check(code == 0, "assign on 3 ranks exits %d: %s" % (code, err))
RUNS.as_serial("reconstruct", "chain", "chain/assigned.pvts")

# Pieces: one .vtu per rank, read by VTK as the pixels of one process.
serial = pixels("hex_serial/out.vtu", vtk.vtkXMLUnstructuredGridReader)
for ranks in (2, 3):
    folder = "hex_%d" % ranks
    code, err = run("reconstruct", folder, ranks, "../hex.pvtr", "--majority", "-o", "pieces.pvtu")
    check(code == 0, "hex on %d ranks, pieces: exit %d: %s" % (ranks, code, err))
    check(sorted(f for f in os.listdir(path(folder)) if f.startswith("pieces")) ==
          ["pieces.pvtu"] + ["pieces_%d.vtu" % r for r in range(ranks)],
          "hex on %d ranks: not one piece per rank" % ranks)
    got = pixels(folder + "/pieces.pvtu", vtk.vtkXMLPUnstructuredGridReader)
    check(got == serial, "hex on %d ranks: VTK reads other pixels in the .pvtu (%d, serial %d)"
          % (ranks, len(got), len(serial)))

# Unstructured meshes (hexahedra, quads; cells in a shuffled order, in pieces): the ranks
# merge the pieces and cut the cells with PT-Scotch; the gathered pixels come in the order
# of their input cells, the bytes of one process, and the report has its figures.
write_pieces(unstructured(grid((13, 11, 17))), "mesh.pvtu", 4)
write_pieces(unstructured(grid((19, 15, 0), flat=True)), "flat.pvtu", 3)
for case, source, options in (("mesh", "mesh.pvtu", ()), ("mesh_nsub1", "mesh.pvtu", ("--nsub", "1")),
                              ("flat", "flat.pvtu", ())):
    r = RUNS.as_serial("reconstruct", case, source, "--majority", *options)
    check(r.get("mixed_cells", 0) > 30 and r["method_stats"]["rounds"] > 3,
          "%s: %r mixed cells, too few to test the ranks" % (case, r.get("mixed_cells")))
code, err = run("reconstruct", "mesh_3", 3, "../mesh.pvtu", "--majority", "-o", "pieces.pvtu")
got = pixels("mesh_3/pieces.pvtu", vtk.vtkXMLPUnstructuredGridReader)
want = pixels("mesh_serial/out.vtu", vtk.vtkXMLUnstructuredGridReader)
check(code == 0 and got == want, "mesh on 3 ranks, pieces: exit %d (%s), %d pixels (serial %d)"
      % (code, err, len(got), len(want)))

# Mixed cells only in the top layers: the grid is cut by the pixels' memory (the default --cut),
# so the first rank owns most layers, the others a layer of pixels each; a rank without
# pixels writes no piece.
top = vtk.vtkRectilinearGrid()
top.SetDimensions(9, 8, 13)
for setter, n in zip((top.SetXCoordinates, top.SetYCoordinates, top.SetZCoordinates), (9, 8, 13)):
    setter(ns.numpy_to_vtk(np.arange(float(n)), deep=1))
centres = vtk.vtkCellCenters()
centres.SetInputData(top)
centres.Update()
ball = np.linalg.norm(ns.vtk_to_numpy(centres.GetOutput().GetPoints().GetData()) - [4, 3.5, 12],
                      axis=1)
for name, v in (("vf_ball", np.clip(2.5 - ball, 0, 1)), ("vf_rest", 1 - np.clip(2.5 - ball, 0, 1))):
    a = ns.numpy_to_vtk(v, deep=1)
    a.SetName(name)
    top.GetCellData().AddArray(a)
write_pieces(top, "top.pvtr", 3)
for ranks in (0, 4):
    code, err = run("reconstruct", "top_%d" % ranks, ranks, "../top.pvtr", "--majority", "-o",
                    "p.pvtu", "--json", "out.json")
    check(code == 0, "top on %d ranks: exit %d: %s" % (ranks, code, err))
got, want = (pixels("top_%d/p.pvtu" % r, vtk.vtkXMLPUnstructuredGridReader) for r in (4, 0))
check(len(want) > 1000 and got == want, "top on 4 ranks: other pixels (%d, serial %d)"
      % (len(got), len(want)))
with open(path("top_4", "out.json")) as f:
    layers = json.load(f)["ranks"]["layers"]
pixel_layers = {parent // (8 * 7) for _, parent in want}
with_pixels = [r for r, (first, end) in enumerate(layers) if pixel_layers & set(range(first, end))]
check([first for first, _ in layers] == [0] + [end for _, end in layers[:-1]] and
      layers[-1][1] == 12 and layers[0][1] > 6 and with_pixels == [1, 2, 3],
      "top on 4 ranks: owned layers %r, not cut by the pixels (pixels in layers %r)"
      % (layers, sorted(pixel_layers)))
check(sorted(os.listdir(path("top_4"))) == ["out.json", "p.pvtu"] +
      ["p_%d.vtu" % r for r in with_pixels],
      "top on 4 ranks: pieces %r, not those of the ranks with pixels" % os.listdir(path("top_4")))
# --cut layers: equal layer counts, the grid read once; the same pixels.
code, err = run("reconstruct", "top_layers", 4, "../top.pvtr", "--majority", "-o", "p.pvtu",
                "--json", "out.json", "--cut", "layers")
check(code == 0, "top on 4 ranks, --cut layers: exit %d: %s" % (code, err))
with open(path("top_layers", "out.json")) as f:
    layers = json.load(f)["ranks"]["layers"]
check(layers == [[0, 3], [3, 6], [6, 9], [9, 12]], "--cut layers: owned layers %r" % layers)
got = pixels("top_layers/p.pvtu", vtk.vtkXMLPUnstructuredGridReader)
check(got == want, "top on 4 ranks, --cut layers: other pixels (%d, serial %d)"
      % (len(got), len(want)))

# The same cells as an unstructured mesh: PT-Scotch balances the cells' bytes (--cut memory,
# the default), so the ranks holding the mixed cells own fewer cells; --cut layers balances
# their counts. The pixels are one process's either way.
write_pieces(unstructured(top), "topmesh.pvtu", 3)
code, err = run("reconstruct", "topmesh_serial", 0, "../topmesh.pvtu", "--majority", "-o", "p.vtu")
want = pixels("topmesh_serial/p.vtu", vtk.vtkXMLUnstructuredGridReader)
spread = {}
for cut in ("memory", "layers"):
    folder = "topmesh_" + cut
    code, err = run("reconstruct", folder, 4, "../topmesh.pvtu", "--majority", "-o", "p.pvtu",
                    "--json", "out.json", "--cut", cut)
    got = pixels(folder + "/p.pvtu", vtk.vtkXMLPUnstructuredGridReader)
    check(code == 0 and got == want, "the unstructured top on 4 ranks, --cut %s: exit %d (%s), "
          "%d pixels (one process: %d)" % (cut, code, err, len(got), len(want)))
    with open(path(folder, "out.json")) as f:
        cells = json.load(f)["ranks"]["cells"] if code == 0 else [1]
    spread[cut] = max(cells) / min(cells)
check(spread["memory"] > 1.5 and spread["layers"] < 1.1,
      "the unstructured top on 4 ranks: the most cells a rank owns over the fewest, %r" % spread)

# Refused on several ranks before any work, with one message and no output.
for args, code_wanted, words in (
        (("--model", "m.vtk"), 1, ["--model", "one process"]),
        (("--method", "annealing"), 1, ["--method annealing", "greedy"]),
        (("-o", "x.pvts"), 1, [".pvtu"]),
        (("-o", "out.vtu"), 1, [".pvtu", "--gather"])):
    full = ("../hex.pvtr", "--majority") + (args if "-o" in args else args + ("-o", "out.pvtu"))
    code, err = run("reconstruct", "usage", 2, *full)
    check(code == code_wanted and err.count("error") == 1 and all(w in err for w in words),
          "%r on 2 ranks: exit %d, %r" % (args, code, err))
code, err = run("reconstruct", "usage", 2, "../hex.pvtr", "-o", "out.pvtu")
check(code == 2 and "material" in err and "--majority" in err and err.count("error") == 1,
      "no material array on 2 ranks: exit %d, %r" % (code, err))
# --gather holds the whole pixel mesh twice on rank 0: at a --max-memory of the one-process
# estimate every rank's part passes, the gather does not (exit 5 before anything travels).
limit = "%d" % report("hex_serial")["memory_estimate_bytes"]
code, err = run("reconstruct", "usage", 2, "../hex.pvtr", "--majority", "-o", "out.vtu",
                "--gather", "--max-memory", limit)
check(code == 5 and err.count("error") == 1 and "gathering" in err,
      "--gather beyond --max-memory on 2 ranks: exit %d, %r" % (code, err))
code, err = run("reconstruct", "limit", 2, "../hex.pvtr", "--majority", "-o", "out.pvtu",
                "--max-memory", limit)
check(code == 0, "pieces within --max-memory on 2 ranks: exit %d, %r" % (code, err))
check(not os.listdir(path("usage")), "outputs left behind: %s" % os.listdir(path("usage")))

sys.exit(RUNS.finish())
