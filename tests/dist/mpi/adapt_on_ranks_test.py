#!/usr/bin/python3
"""hexadapt-adapt under mpirun on 2 and 3 ranks, on the asteroid (a true 3D case) as a grid and
as a jittered mesh cut by PT-Scotch, and on the .pvts of hexadapt-assign on ranks: every rank's
part adapted with its cuts frozen and the layers across them pillowed makes one mesh, checked
with VTK on its own: its pieces fit (once
their coincident points are merged, every face of one or two cells and the faces of one cell
all on the domain's box), every cell keeps the scaled Jacobian threshold (vtkMeshQuality), the
pieces beside a cut hold its nodes and their copies at the same places, the mesh has one
process's cell count, every interface node aims at the target it has on one process and as
many reach their interface; --gather writes that mesh as one file, the same bytes at every
run; what runs on one process only, bad input cells and a missing piece stop every rank with one
message.

usage: adapt_on_ranks_test.py TOOLS_DIR WORK_DIR MPIEXEC
"""
import filecmp
import json
import os
import sys
from collections import Counter

import numpy as np
import vtk
from vtk.util import numpy_support as ns

from tool_runs import ToolRuns

RUNS = ToolRuns(*sys.argv[1:4])
check, path, run = RUNS.check, RUNS.path, RUNS.run

N = (14, 14, 16)  # cells per axis; the cuts run across z


def read(name):
    reader = (vtk.vtkXMLPUnstructuredGridReader() if name.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path(name))
    reader.Update()
    return reader.GetOutput()


def merged(mesh):
    """The points and hexes of the mesh with its coincident points merged (the pieces' shared
    nodes)."""
    p = ns.vtk_to_numpy(mesh.GetPoints().GetData())
    conn = ns.vtk_to_numpy(mesh.GetCells().GetConnectivityArray()).reshape(-1, 8)
    points, inverse = np.unique(p, axis=0, return_inverse=True)
    return points, inverse.reshape(-1)[conn]


def faces_of_one_cell(conn):
    """Fails on a face of more than two cells; returns the faces of one cell (point ids)."""
    local = ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))
    count = Counter(tuple(sorted(c[list(f)])) for c in conn for f in local)
    check(max(count.values()) <= 2, "a face of more than two cells")
    return [f for f, n in count.items() if n == 1]


def check_one_mesh(name, label, threshold=0.3):
    """The pieces (or the one file) in `name` make one conformal mesh over the box of N
    whose every cell keeps the threshold. Returns its merged points and hexes."""
    mesh = read(name)
    p, conn = merged(mesh)
    lo, hi = p.min(axis=0), p.max(axis=0)
    on_box = np.isclose(p, lo).any(axis=1) | np.isclose(p, hi).any(axis=1)
    open_faces = [f for f in faces_of_one_cell(conn) if not all(on_box[list(f)])]
    check(not open_faces, "%s: %d faces of one cell inside the domain (the pieces do not fit)"
          % (label, len(open_faces)))
    quality = vtk.vtkMeshQuality()
    quality.SetInputData(mesh)
    quality.SetHexQualityMeasureToScaledJacobian()
    quality.Update()
    q = ns.vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Quality"))
    check(q.min() >= threshold - 1e-9, "%s: a cell at scaled Jacobian %g" % (label, q.min()))
    return p, conn


def report(folder, name="out.json"):
    with open(path(folder, name)) as f:
        return json.load(f)


def assigned_grid():
    r = vtk.vtkXMLStructuredGridReader()
    r.SetFileName(path("assigned.vts"))
    r.Update()
    return r.GetOutput()


def input_points():
    return ns.vtk_to_numpy(assigned_grid().GetPoints().GetData()).reshape(N[2] + 1, -1, 3)


def interface_nodes():
    """Per node layer, whether each node of the input grid has cells of two materials."""
    material = ns.vtk_to_numpy(assigned_grid().GetCellData().GetArray("material"))
    cells = np.full((N[2] + 2, N[1] + 2, N[0] + 2), -1)
    cells[1:-1, 1:-1, 1:-1] = material.reshape(N[2], N[1], N[0])
    around = np.stack([cells[a:a + N[2] + 1, b:b + N[1] + 1, c:c + N[0] + 1]
                       for a in (0, 1) for b in (0, 1) for c in (0, 1)])
    low = np.where(around >= 0, around, 99).min(axis=0)
    high = np.where(around >= 0, around, -99).max(axis=0)
    return (low != high).reshape(N[2] + 1, -1)


def targets(mesh):
    return ns.vtk_to_numpy(mesh.GetPointData().GetArray("target"))


code, err = run("generate", ".", 0, "asteroid", "--dims", ",".join(map(str, N)), "-o", "vf.vts")
check(code == 0, "generate exits %d: %s" % (code, err))
code, err = run("assign", ".", 0, "vf.vts", "-o", "assigned.vts")
check(code == 0, "assign exits %d: %s" % (code, err))
code, err = run("adapt", "serial", 0, "../assigned.vts", "-o", "out.vtu", "--json", "out.json")
check(code == 0, "adapt on one process exits %d: %s" % (code, err))
serial = report("serial")["result"]
grid_points = input_points()
on_interface = interface_nodes()
serial_targets = targets(read("serial/out.vtu"))[:on_interface.size].reshape(N[2] + 1, -1, 3)

for ranks in (2, 3):
    folder = "pieces_%d" % ranks
    code, err = run("adapt", folder, ranks, "../assigned.vts", "-o", "out.pvtu", "--json",
                    "out.json")
    check(code == 0, "adapt on %d ranks exits %d: %s" % (ranks, code, err))
    check(sorted(f for f in os.listdir(path(folder)) if f.startswith("out_")) ==
          ["out_%d.vtu" % r for r in range(ranks)], "%d ranks: not one piece per rank" % ranks)
    points, hexes = check_one_mesh(folder + "/out.pvtu", "%d ranks" % ranks)
    r = report(folder)
    res, on = r["result"], r["ranks"]
    check(res["cells"] == len(hexes) and res["nodes"] == len(points),
          "%d ranks: the report's %d cells, %d nodes; the pieces' %d, %d" % (
              ranks, res["cells"], res["nodes"], len(hexes), len(points)))
    check(res["cells_below_threshold"] == 0 and res["min_quality"] >= 0.3
          and res["cells_in"] == N[0] * N[1] * N[2],
          "%d ranks: the report's figures %r" % (ranks, res))
    check(on["count"] == ranks and len(on["cells"]) == ranks and sum(on["cells"]) == res["cells"]
          and sum(on["interface_nodes"]) == res["interface_nodes"],
          "%d ranks: the ranks block %r" % (ranks, on))
    # Every interface node counted as on one process, as many near their interface, and as many
    # cells: the ranks lay one process's layers across the cuts (both 422 near, 3,972 cells on
    # 2 and 3 ranks; with the cells beside a cut unpillowed it was 403 and 387 near).
    check(res["interface_nodes"] == serial["interface_nodes"]
          and res["near_interface"] >= 0.98 * serial["near_interface"]
          and res["cells"] == serial["cells"] and res["frozen_blocked_nodes"] == 0,
          "%d ranks: %r near of %r, %r cells, %r frozen (serial %r of %r, %r cells)" % (
              ranks, res["near_interface"], res["interface_nodes"], res["cells"],
              res["frozen_blocked_nodes"], serial["near_interface"], serial["interface_nodes"],
              serial["cells"]))
    # Every interface node aims where it aims on one process: each rank computed the targets
    # of its nodes with the cells around them and the volume offset of the whole grid. A piece
    # opens with its slab's input nodes, layer by layer.
    plane = (N[0] + 1) * (N[1] + 1)
    for rank, (first, end) in enumerate(on["layers"]):
        mine = targets(read("%s/out_%d.vtu" % (folder, rank)))
        mine = mine[:(end - first + 1) * plane].reshape(end - first + 1, plane, 3)
        off = np.abs(mine - serial_targets[first:end + 1])[on_interface[first:end + 1]].max()
        check(off < 1e-12, "%d ranks, rank %d: an interface node's target %g from one "
              "process's" % (ranks, rank, off))
    # The pieces beside a cut hold its nodes and the copies of the layers across it at the same
    # places, and the second pass moved some of the cut's nodes.
    check(on["cut_layers"] == "pillowed", "%d ranks: the cuts' cells %s" % (
        ranks, on["cut_layers"]))
    for rank, (first, _) in enumerate(on["layers"]):
        if rank == 0:
            continue
        below, above = ({tuple(x) for x in ns.vtk_to_numpy(
            read("%s/out_%d.vtu" % (folder, side)).GetPoints().GetData())}
                        for side in (rank - 1, rank))
        unmoved = sum(tuple(x) in below for x in grid_points[first])
        check(len(below & above) > plane and unmoved < plane,
              "%d ranks, cut at layer %d: %d nodes shared by the pieces (%d), %d unmoved"
              % (ranks, first, len(below & above), plane, unmoved))
    # --gather: the same mesh as one file, its nodes shared, the same bytes at every run.
    for attempt in ("gather", "again"):
        code, err = run("adapt", folder + "_" + attempt, ranks, "../assigned.vts", "-o",
                        "out.vtu", "--gather")
        check(code == 0, "adapt --gather on %d ranks exits %d: %s" % (ranks, code, err))
    one = read(folder + "_gather/out.vtu")
    check(one.GetNumberOfPoints() == res["nodes"] and one.GetNumberOfCells() == res["cells"],
          "%d ranks: the gathered file has %d nodes and %d cells" % (
              ranks, one.GetNumberOfPoints(), one.GetNumberOfCells()))
    check(len(merged(one)[0]) == one.GetNumberOfPoints(),
          "%d ranks: the gathered file repeats nodes" % ranks)
    check_one_mesh(folder + "_gather/out.vtu", "%d ranks, gathered" % ranks)
    check(filecmp.cmp(path(folder + "_gather", "out.vtu"), path(folder + "_again", "out.vtu"),
                      shallow=False), "%d ranks: two runs gather different bytes" % ranks)
    code, err = run("measure", folder, 0, "out.pvtu", "--reference", "../vf.vts")
    check(code == 0, "measure of the %d ranks' pieces exits %d: %s" % (ranks, code, err))

# The mending decided by the ranks together (a cell left out by every rank holding it when
# one's run left it failing; 4 runs on every rank, 3 on one process): the vortex at 20^3 on 2
# ranks lays the same layers across its cut (before, each rank left out its own failing
# cells, the layers differed at the cut, and every rank adapted again unpillowed); the pieces
# fit, every cell keeps the threshold, and nearly as many interface nodes end near their
# interface as on one process (249 of its 252).
for tool, args in (("generate", ("vortex", "--dims", "20,20,20", "--time", "1.5", "-o", "vf.vts")),
                   ("assign", ("vf.vts", "-o", "assigned.vts")),
                   ("adapt", ("assigned.vts", "-o", "serial.vtu", "--json", "serial.json"))):
    code, err = run(tool, "vortex", 0, *args)
    check(code == 0, "%s of the vortex exits %d: %s" % (tool, code, err))
code, err = run("adapt", "vortex", 2, "assigned.vts", "-o", "out.pvtu", "--json", "out.json")
check(code == 0, "adapt of the vortex on 2 ranks exits %d: %s" % (code, err))
vortex, vortex_serial = report("vortex")["result"], report("vortex", "serial.json")["result"]
check(report("vortex")["ranks"]["cut_layers"] == "pillowed"
      and vortex["near_interface"] >= 0.98 * vortex_serial["near_interface"],
      "the vortex on 2 ranks: the cuts' cells %s, %d near (one process: %d)" % (
          report("vortex")["ranks"]["cut_layers"], vortex["near_interface"],
          vortex_serial["near_interface"]))
check_one_mesh("vortex/out.pvtu", "the vortex on 2 ranks")

# 2D (three disks, cut across y): nothing laid across the cuts (the layers are cavities);
# the gathered mesh keeps the threshold, passes measure's checks against the input, and its
# interface nodes are all near their interface, as on one process.
for tool, args in (("generate", ("venn", "--dims", "40,24", "-o", "vf.vts")),
                   ("assign", ("vf.vts", "-o", "assigned.vts")),
                   ("adapt", ("assigned.vts", "-o", "serial.vtu", "--json", "serial.json"))):
    code, err = run(tool, "flat", 0, *args)
    check(code == 0, "%s of the 2D case exits %d: %s" % (tool, code, err))
code, err = run("adapt", "flat", 2, "assigned.vts", "-o", "out.vtu", "--gather", "--json",
                "out.json")
check(code == 0, "adapt of the 2D case on 2 ranks exits %d: %s" % (code, err))
flat, flat_serial = report("flat"), report("flat", "serial.json")
check(flat["ranks"]["cut_layers"] == "none" and flat["threshold_met"]
      and flat["result"]["near_interface"] == flat_serial["result"]["near_interface"] > 100,
      "the 2D case on 2 ranks: cut layers %s, threshold met %s, near %d (one process: %d)"
      % (flat["ranks"]["cut_layers"], flat["threshold_met"], flat["result"]["near_interface"],
         flat_serial["result"]["near_interface"]))
code, err = run("measure", "flat", 0, "out.vtu", "--reference", "vf.vts")
check(code == 0, "measure of the 2D case's gathered mesh exits %d: %s" % (code, err))

# An unstructured mesh (the asteroid with its nodes jittered, as a .vtu): PT-Scotch cuts it,
# each rank adapts its cells and three ghost layers with the nodes it shares frozen, the nodes
# held by several ranks take one point, and the bands of every group of ranks move them on.
# The pieces make one mesh keeping the threshold, with one process's interface nodes, nearly
# as many near their interface (one process: 432; 2, 3 and 4 ranks: 430, 429 and 429, the
# cuts' cells pillowed; on 4 ranks two ranks' copies where the parts meet are too far apart
# for either to take the other's points as they are, and one takes them with its own nodes
# around smoothed), and the gathered file passes measure against the input (and is the same
# at every run on 3 ranks). The asteroid's grid as a mesh on 4 ranks: no such smoothing mends a cut where
# the parts meet, and every rank adapts again with the cells around the cuts unpillowed (401
# of one process's 422 near).
for tool, args in (("generate", ("asteroid", "--dims", ",".join(map(str, N)), "--jitter", "0.2",
                                 "-o", "vf.vtu")),
                   ("assign", ("vf.vtu", "-o", "assigned.vtu")),
                   ("adapt", ("assigned.vtu", "-o", "serial.vtu", "--json", "serial.json"))):
    code, err = run(tool, "mesh", 0, *args)
    check(code == 0, "%s of the jittered asteroid exits %d: %s" % (tool, code, err))
for tool, args in (("assign", ("../vf.vts", "-o", "assigned.vtu")),
                   ("adapt", ("assigned.vtu", "-o", "serial.vtu", "--json", "serial.json"))):
    code, err = run(tool, "plain", 0, *args)
    check(code == 0, "%s of the asteroid as a mesh exits %d: %s" % (tool, code, err))
for case, reference, ranks, layers, share in (("mesh", "vf.vtu", 2, "pillowed", 0.98),
                                              ("mesh", "vf.vtu", 3, "pillowed", 0.98),
                                              ("mesh", "vf.vtu", 4, "pillowed", 0.98),
                                              ("plain", "../vf.vts", 4, "unpillowed", 0.94)):
    label = "the %s on %d ranks" % (case, ranks)
    serial_result = report(case, "serial.json")["result"]
    folder = "%s/ranks_%d" % (case, ranks)
    code, err = run("adapt", folder, ranks, "../assigned.vtu", "-o", "out.pvtu", "--json",
                    "out.json")
    check(code == 0, "adapt of %s exits %d: %s" % (label, code, err))
    points, hexes = check_one_mesh(folder + "/out.pvtu", label)
    r = report(folder)
    res, on = r["result"], r["ranks"]
    check(res["cells"] == len(hexes) and res["nodes"] == len(points)
          and sum(on["cells"]) == res["cells"] and len(on["ghost_cells"]) == ranks,
          "%s: the report's %d cells, %d nodes, ranks %r; the pieces' %d, %d"
          % (label, res["cells"], res["nodes"], on, len(hexes), len(points)))
    check(r["threshold_met"] and on["cut_layers"] == layers
          and res["interface_nodes"] == serial_result["interface_nodes"]
          and res["near_interface"] >= share * serial_result["near_interface"]
          and res["frozen_blocked_nodes"] == 0,
          "%s: cut layers %s, %r near of %r, %r frozen (one process: %r of %r)"
          % (label, on["cut_layers"], res["near_interface"], res["interface_nodes"],
             res["frozen_blocked_nodes"], serial_result["near_interface"],
             serial_result["interface_nodes"]))
    twice = case == "mesh" and ranks == 3  # the same bytes at every run: once is enough
    for attempt in ("gather", "again") if twice else ("gather",):
        code, err = run("adapt", "%s_%s" % (folder, attempt), ranks, "../assigned.vtu", "-o",
                        "out.vtu", "--gather")
        check(code == 0, "adapt --gather of %s exits %d: %s" % (label, code, err))
    one = read(folder + "_gather/out.vtu")
    check(one.GetNumberOfPoints() == res["nodes"] == len(merged(one)[0])
          and one.GetNumberOfCells() == res["cells"],
          "%s: the gathered file has %d nodes (%d distinct), %d cells"
          % (label, one.GetNumberOfPoints(), len(merged(one)[0]), one.GetNumberOfCells()))
    check(not twice or filecmp.cmp(path(folder + "_gather", "out.vtu"),
                                   path(folder + "_again", "out.vtu"), shallow=False),
          "%s: two runs gather different bytes" % label)
    code, err = run("measure", folder + "_gather", 0, "out.vtu", "--reference",
                    "../" + reference)
    check(code == 0, "measure of %s, gathered, exits %d: %s" % (label, code, err))

# The jittered asteroid as one unstructured legacy .vtk (assign writes it): read by rank 0 and
# cut by PT-Scotch as the .vtu is, the gathered mesh keeps the threshold (VTK's own filter)
# and the report has the .vtu's figures. The geometric model of reconstruct, which the
# Makefile passes, is taken on ranks (checked, unused without --correction): the same figures.
code, err = run("assign", "mesh", 0, "vf.vtu", "-o", "assigned.vtk")
check(code == 0, "assign of the jittered asteroid to a .vtk exits %d: %s" % (code, err))
code, err = run("reconstruct", "mesh", 0, "assigned.vtu", "-o", "pixels.vtu", "--model",
                "model.vtk")
check(code == 0, "reconstruct --model of the jittered asteroid exits %d: %s" % (code, err))
for name, args in (("legacy", ("../assigned.vtk",)),
                   ("model", ("../assigned.vtu", "--model", "../model.vtk"))):
    folder = "mesh/%s_3" % name
    code, err = run("adapt", folder, 3, *args, "-o", "out.vtu", "--gather", "--json", "out.json")
    check(code == 0, "adapt of the jittered asteroid's %s on 3 ranks exits %d: %s"
          % (name, code, err))
    check_one_mesh(folder + "/out.vtu", "the jittered asteroid's %s on 3 ranks" % name)
    check(report(folder)["result"] == report("mesh/ranks_3")["result"],
          "the jittered asteroid's %s on 3 ranks: figures %r, the .vtu's %r"
          % (name, report(folder)["result"], report("mesh/ranks_3")["result"]))

# The chain on ranks: assign writes .vts pieces, adapt reads its slabs of them.
code, err = run("assign", "chain", 3, "../vf.vts", "-o", "assigned.pvts")
check(code == 0, "assign on 3 ranks exits %d: %s" % (code, err))
code, err = run("adapt", "chain", 3, "assigned.pvts", "-o", "out.pvtu", "--json", "out.json")
check(code == 0, "adapt on 3 ranks of assign's pieces exits %d: %s" % (code, err))
check_one_mesh("chain/out.pvtu", "the chain")

# What runs on one process, or cannot be written as pieces: exit 1, one message.
for args, what in ((("--method", "base"), "--method base"), (("--correction",), "--correction"),
                   (("-o", "out.vtu"), ".vtu without --gather")):
    options = ("-o", "out.pvtu") + args if args[0] != "-o" else args
    code, err = run("adapt", "refused", 2, "../assigned.vts", *options)
    check(code == 1 and err.count("error:") == 1,
          "%s on 2 ranks: exit %d, %r" % (what, code, err))
check(not os.path.exists(path("refused", "out.pvtu")), "a refused run wrote its output")

# Input cells below the threshold: every rank stops, naming them and the worst of them as one
# process does.
g = vtk.vtkXMLStructuredGridReader()
g.SetFileName(path("assigned.vts"))
g.Update()
bad = g.GetOutput()
p = ns.vtk_to_numpy(bad.GetPoints().GetData())
nx, ny = N[0] + 1, N[1] + 1
for k in (3, 12):  # a node pushed through its neighbour in two slabs
    p[2 + nx * (2 + ny * k)] += 1.6 * (p[3] - p[2])
w = vtk.vtkXMLStructuredGridWriter()
w.SetFileName(path("bad.vts"))
w.SetInputData(bad)
w.Write()
code, err = run("adapt", "bad_serial", 0, "../bad.vts", "-o", "out.vtu", "--json", "out.json")
want = report("bad_serial").get("bad_input_cells")
worst = [f["cell"] for f in report("bad_serial")["result"]["failures"]]
check(code == 3 and want, "bad input on one process: exit %d, %r" % (code, want))
for ranks in (2, 3):
    folder = "bad_%d" % ranks
    code, err = run("adapt", folder, ranks, "../bad.vts", "-o", "out.pvtu", "--json", "out.json")
    got = report(folder).get("bad_input_cells")
    got_worst = [f["cell"] for f in report(folder)["result"]["failures"]]
    check(got_worst == worst, "bad input on %d ranks: the worst cells %r, one process's %r"
          % (ranks, got_worst, worst))
    check(code == 3 and got == want and err.count("warning:") == 1
          and not os.path.exists(path(folder, "out.pvtu")),
          "bad input on %d ranks: exit %d, cells %r (one process: %r), %r" % (
              ranks, code, got, want, err))

# --allow-bad-input runs on every rank as on one process.
code, err = run("adapt", "bad_allowed", 0, "../bad.vts", "-o", "out.vtu", "--json", "out.json",
                "--allow-bad-input")
want = (code, report("bad_allowed")["result"]["input_cells_below_threshold"])
code, err = run("adapt", "bad_allowed_2", 2, "../bad.vts", "-o", "out.pvtu", "--json", "out.json",
                "--allow-bad-input")
got = (code, report("bad_allowed_2")["result"]["input_cells_below_threshold"])
check(got == want and os.path.exists(path("bad_allowed_2", "out.pvtu")),
      "--allow-bad-input on 2 ranks: exit and bad input cells %r, one process %r" % (got, want))

# A missing piece: exit 2 naming it, on every rank count.
os.remove(path("chain", "assigned_1.vts"))
code, err = run("adapt", "chain_missing", 3, "../chain/assigned.pvts", "-o", "out.pvtu")
check(code == 2 and "assigned_1.vts" in err and err.count("error:") == 1,
      "a missing piece on 3 ranks: exit %d, %r" % (code, err))

sys.exit(RUNS.finish())
