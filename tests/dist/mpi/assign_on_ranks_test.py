#!/usr/bin/python3
"""hexadapt-assign under mpirun on 2 and 3 ranks, on parallel files VTK wrote: the gathered
file is the bytes of the run on one process and the report its figures; the .pvtu and .pvts
of pieces read in VTK as the same cells and materials, and the .pvts is read again on ranks
as on one process; an error in one rank's layers stops every rank with one message and no
output.

usage: assign_on_ranks_test.py TOOLS_DIR WORK_DIR MPIEXEC
"""
import filecmp
import json
import os
import sys

import numpy as np
import vtk
from vtk.util import numpy_support as ns

from tool_runs import ToolRuns, grid, unstructured

RUNS = ToolRuns(*sys.argv[1:4])
check, path, report, write_pieces = RUNS.check, RUNS.path, RUNS.report, RUNS.write_pieces


def run(folder, ranks, *args):
    return RUNS.run("assign", folder, ranks, *args)


def by_centre(data):
    centres = vtk.vtkCellCenters()
    centres.SetInputData(data)
    centres.Update()
    c = ns.vtk_to_numpy(centres.GetOutput().GetPoints().GetData())
    m = ns.vtk_to_numpy(data.GetCellData().GetArray("material"))
    return {tuple(np.round(p, 6)): x for p, x in zip(c, m)}


def read(name, reader):
    r = reader()
    r.SetFileName(path(name))
    r.Update()
    return r.GetOutput()


write_pieces(grid((13, 11, 17)), "hex.pvtr", 4)
write_pieces(grid((13, 11, 17)), "ghost.pvtr", 5, ghost=1)
write_pieces(grid((19, 15, 0), flat=True), "quad.pvtr", 3)

for case in ("hex", "ghost", "quad"):
    code, err = run(case + "_serial", 0, "../%s.pvtr" % case, "-o", "out.vtu", "--gather",
                    "--json", "out.json")
    check(code == 0, "%s: the serial run exits %d: %s" % (case, code, err))
    serial = by_centre(read(case + "_serial/out.vtu", vtk.vtkXMLUnstructuredGridReader))
    mended = report(case + "_serial")["assign"]["node_solves"]
    check(mended > 10, "%s: only %d nodes mended, too few to test the ranks" % (case, mended))
    for ranks in (2, 3):
        folder = "%s_%d" % (case, ranks)
        code, err = run(folder, ranks, "../%s.pvtr" % case, "-o", "out.vtu", "--gather", "--json",
                        "out.json")
        check(code == 0, "%s on %d ranks exits %d: %s" % (case, ranks, code, err))
        check(filecmp.cmp(path(case + "_serial", "out.vtu"), path(folder, "out.vtu"), shallow=False),
              "%s on %d ranks: the gathered file differs from the serial one" % (case, ranks))
        check(report(case + "_serial") == report(folder, ranks),
              "%s on %d ranks: the report differs from the serial one" % (case, ranks))
        code, err = run(folder, ranks, "../%s.pvtr" % case, "-o", "pieces.pvtu")
        check(code == 0, "%s on %d ranks, pieces: exit %d: %s" % (case, ranks, code, err))
        check(sorted(f for f in os.listdir(path(folder)) if f.startswith("pieces")) ==
              ["pieces.pvtu"] + ["pieces_%d.vtu" % r for r in range(ranks)],
              "%s on %d ranks: not one piece per rank" % (case, ranks))
        pieces = by_centre(read(folder + "/pieces.pvtu", vtk.vtkXMLPUnstructuredGridReader))
        check(pieces == serial,
              "%s on %d ranks: VTK reads other cells or materials in the .pvtu (%d cells, %d "
              "serial)" % (case, ranks, len(pieces), len(serial)))
        # Structured pieces, each placed in the whole grid by its extent.
        code, err = run(folder, ranks, "../%s.pvtr" % case, "-o", "slabs.pvts")
        check(code == 0, "%s on %d ranks, .pvts: exit %d: %s" % (case, ranks, code, err))
        check(sorted(f for f in os.listdir(path(folder)) if f.startswith("slabs")) ==
              ["slabs.pvts"] + ["slabs_%d.vts" % r for r in range(ranks)],
              "%s on %d ranks: not one .vts piece per rank" % (case, ranks))
        slabs = read(folder + "/slabs.pvts", vtk.vtkXMLPStructuredGridReader)
        whole = read(case + "_serial/out.vtu", vtk.vtkXMLUnstructuredGridReader)
        check(slabs.GetNumberOfPoints() == whole.GetNumberOfPoints() and by_centre(slabs) == serial,
              "%s on %d ranks: VTK reads other points, cells or materials in the .pvts"
              % (case, ranks))

# The .pvts of 3 ranks is an input a later run on ranks reads slab by slab: on 2 ranks it
# gives the bytes of one process reading it.
for ranks in (0, 2):
    code, err = run("chain_%d" % ranks, ranks, "../hex_3/slabs.pvts", "-o", "out.vtu", "--gather")
    check(code == 0, "the .pvts read again on %d ranks: exit %d: %s" % (ranks, code, err))
check(filecmp.cmp(path("chain_0", "out.vtu"), path("chain_2", "out.vtu"), shallow=False),
      "the .pvts read again on 2 ranks: the gathered file differs from the serial one")

# A material nowhere the majority (the slab, at most 0.3 of a cell), kept: the cells it gets
# are those of the serial run, on 2 and 3 ranks.
thin = grid((13, 11, 17))
slab_vf = ns.vtk_to_numpy(thin.GetCellData().GetArray("vf_slab"))
matrix_vf = ns.vtk_to_numpy(thin.GetCellData().GetArray("vf_matrix"))
matrix_vf += 0.7 * slab_vf
slab_vf *= 0.3
thin.GetCellData().GetArray("vf_slab").Modified()
thin.GetCellData().GetArray("vf_matrix").Modified()
write_pieces(thin, "thin.pvtr", 4)
kept = RUNS.as_serial("assign", "thin", "thin.pvtr", "--keep-materials")["assign"]["kept"]
check(len(kept) == 1 and kept[0]["name"] == "slab" and kept[0]["cells"] > 10,
      "kept material: the serial run keeps %r" % kept)

# Small pieces (--min-island) joined across the ranks' borders: the serial file and report.
islands = RUNS.as_serial("assign", "islands", "hex.pvtr", "--min-island", "8")["assign"]["islands"]
check(islands["reassigned"] > 3, "--min-island: the serial run reassigns %r" % islands)

# A label map: its materials are the values of the whole grid, one of them (42) only in the
# last layers, which one rank alone holds; the gathered file is the serial one. A value that
# is not an integer is named by its cell's id in the whole grid.
labelled = grid((13, 11, 17))
ball = ns.vtk_to_numpy(labelled.GetCellData().GetArray("vf_ball"))
slab = ns.vtk_to_numpy(labelled.GetCellData().GetArray("vf_slab"))
ids = np.where(ball > 0.5, 3.0, np.where(slab > 0.5, 7.0, 1.0))
ids[13 * 11 * 16 + 20] = 42
for name in ("vf_ball", "vf_slab", "vf_matrix"):
    labelled.GetCellData().RemoveArray(name)
ids_array = ns.numpy_to_vtk(ids, deep=1)
ids_array.SetName("ids")
labelled.GetCellData().AddArray(ids_array)
write_pieces(labelled, "labels.pvtr", 4)
code, err = run("labels_serial", 0, "../labels.pvtr", "-o", "out.vtu", "--gather", "--labels",
                "ids")
check(code == 0, "labels: the serial run exits %d: %s" % (code, err))
for ranks in (2, 3):
    folder = "labels_%d" % ranks
    code, err = run(folder, ranks, "../labels.pvtr", "-o", "out.vtu", "--gather", "--labels",
                    "ids")
    check(code == 0, "labels on %d ranks exits %d: %s" % (ranks, code, err))
    check(filecmp.cmp(path("labels_serial", "out.vtu"), path(folder, "out.vtu"), shallow=False),
          "labels on %d ranks: the gathered file differs from the serial one" % ranks)
ids[13 * 11 * 15 + 5] = 2.5
ids_array = ns.numpy_to_vtk(ids, deep=1)
ids_array.SetName("ids")
labelled.GetCellData().AddArray(ids_array)
write_pieces(labelled, "badlabels.pvtr", 4)
code, err = run("badlabels", 3, "../badlabels.pvtr", "-o", "out.pvtu", "--labels", "ids")
check(code == 2 and err.count("error") == 1 and "cell %d" % (13 * 11 * 15 + 5) in err,
      "a label 2.5 on 3 ranks: exit %d, %r" % (code, err))

# A sum far from 1 in a cell of the last layers: every rank stops, one message names the
# cell by its id in the whole grid, nothing is written.
bad = grid((13, 11, 17))
matrix = bad.GetCellData().GetArray("vf_matrix")
cell = 13 * 11 * 15 + 40
matrix.SetValue(cell, matrix.GetValue(cell) + 0.3)
write_pieces(bad, "bad.pvtr", 4)
code, err = run("bad", 3, "../bad.pvtr", "-o", "out.pvtu")
check(code == 2, "a bad sum on 3 ranks exits %d, not 2: %s" % (code, err))
check(err.count("error") == 1 and "cell %d" % cell in err,
      "a bad sum on 3 ranks: not one message naming cell %d: %r" % (cell, err))
check(not os.listdir(path("bad")), "a bad sum on 3 ranks left files: %s" % os.listdir(path("bad")))

# Unstructured meshes (hexahedra, quads) whose cells come in a shuffled order, in pieces VTK
# wrote (their border points repeated): the ranks merge the pieces, cut the cells with
# PT-Scotch and correct across the parts' borders; the gathered file is the serial one's bytes
# and the report its figures; the .pvtu pieces read in VTK as the serial cells and materials.
write_pieces(unstructured(grid((13, 11, 17))), "mesh.pvtu", 4)
write_pieces(unstructured(grid((19, 15, 0), flat=True)), "flat.pvtu", 3)
check(0 < read("mesh_1.vtu", vtk.vtkXMLUnstructuredGridReader).GetNumberOfCells() < 13 * 11 * 17,
      "the pieces of mesh.pvtu are not parts of it")
for case in ("mesh", "flat"):
    mended = RUNS.as_serial("assign", case, case + ".pvtu")["assign"]["node_solves"]
    check(mended > 10, "%s: only %d nodes mended, too few to test the ranks" % (case, mended))
    serial = by_centre(read(case + "_serial/out.vtu", vtk.vtkXMLUnstructuredGridReader))
    code, err = run(case + "_3", 3, "../%s.pvtu" % case, "-o", "pieces.pvtu")
    pieces = by_centre(read(case + "_3/pieces.pvtu", vtk.vtkXMLPUnstructuredGridReader))
    check(code == 0 and pieces == serial,
          "%s on 3 ranks, pieces: exit %d (%s), VTK reads %d cells (%d serial) or other "
          "materials" % (case, code, err, len(pieces), len(serial)))
# The same mesh as one unstructured legacy .vtk: rank 0 reads it and the ranks cut it as they
# cut a .vtu; the gathered file is the serial one's bytes.
legacy = vtk.vtkUnstructuredGridWriter()
legacy.SetFileName(path("mesh.vtk"))
legacy.SetInputData(unstructured(grid((13, 11, 17))))
legacy.SetFileTypeToBinary()
legacy.Write()
RUNS.as_serial("assign", "legacy", "mesh.vtk")
islands = RUNS.as_serial("assign", "mesh_islands", "mesh.pvtu",
                        "--min-island", "8")["assign"]["islands"]
check(islands["reassigned"] > 3, "--min-island, unstructured: the serial run reassigns %r" % islands)
write_pieces(unstructured(thin), "thinmesh.pvtu", 4)
kept = RUNS.as_serial("assign", "thinmesh", "thinmesh.pvtu", "--keep-materials")["assign"]["kept"]
check(len(kept) == 1 and kept[0]["cells"] > 10,
      "kept material, unstructured: the serial run keeps %r" % kept)
with open(path("mesh_3", "out.json")) as f:
    parts = json.load(f)["ranks"]
check(sum(parts["cells"]) == 13 * 11 * 17 and min(parts["ghost_cells"]) > 0,
      "the unstructured mesh on 3 ranks: parts %r" % parts)
code, err = run("usage", 2, "../mesh.pvtu", "-o", "out.pvts")
check(code == 1 and ".pvts" in err and err.count("error") == 1,
      "an unstructured mesh to a .pvts on 2 ranks: exit %d, %r" % (code, err))
bad = unstructured(grid((13, 11, 17)))
matrix = bad.GetCellData().GetArray("vf_matrix")
matrix.SetValue(2000, matrix.GetValue(2000) + 0.3)
write_pieces(bad, "badmesh.pvtu", 4)
code, serial_err = run("badmesh_serial", 0, "../badmesh.pvtu", "-o", "out.vtu")
named = serial_err.split("cell ")[-1].split(":")[0]
code, err = run("badmesh", 3, "../badmesh.pvtu", "-o", "out.pvtu")
check(code == 2 and err.count("error") == 1 and "cell %s:" % named in err
      and not os.listdir(path("badmesh")),
      "a bad sum in an unstructured mesh on 3 ranks: exit %d, %r (one process: %r)"
      % (code, err, serial_err))

code, err = run("usage", 2, "../hex.pvtr", "-o", "out.vtu")
check(code == 1 and ".pvtu" in err and "--gather" in err and err.count("error") == 1,
      "a .vtu without --gather on 2 ranks: exit %d, %r" % (code, err))
os.remove(path("hex_2.vtr") if os.path.exists(path("hex_2.vtr")) else path("hex", "hex_2.vtr"))
code, err = run("usage", 3, "../hex.pvtr", "-o", "out.pvtu")
check(code == 2 and "hex_2.vtr" in err and err.count("error") == 1,
      "a missing piece on 3 ranks: exit %d, %r" % (code, err))
check(not [f for f in os.listdir(path("usage")) if f.startswith("out")], "outputs left behind")

sys.exit(RUNS.finish())
