#!/usr/bin/python3
"""Exodus II output read by meshio and netCDF4 (Debian's python3-meshio, python3-netcdf4):
the triple point (2D) and the asteroid (3D) through generate, assign and adapt -o X.exo.
Checks one block per named material, the coordinates against the .vtu of the same run, the
domain-side and interface side sets and node sets (every side on its face of the domain,
both sides of every interface), the id maps, the QA and info records; hexadapt-measure and
hexadapt-assign read .exo files; bad files exit 2. The .vtu names its materials in a String
field-data array that VTK reads.

  exodus_test.py TOOLS_DIR WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

import meshio
import netCDF4
import numpy as np
import vtk

# Exodus side numbers -> local nodes (0-based), as the Exodus II manual defines them.
SIDES = {"HEX8": {1: [0, 1, 5, 4], 2: [1, 2, 6, 5], 3: [2, 3, 7, 6], 4: [0, 4, 7, 3],
                  5: [0, 3, 2, 1], 6: [4, 5, 6, 7]},
         "QUAD4": {1: [0, 1], 2: [1, 2], 3: [2, 3], 4: [3, 0]}}


def run(args, ok=(0,)):
    r = subprocess.run(args, capture_output=True, text=True)
    assert r.returncode in ok, (args, r.returncode, r.stderr)
    return r


def names(nc, var):
    return [b"".join(row).decode().rstrip("\0") for row in nc.variables[var][:].data] \
        if var in nc.variables else []


def side_faces(nc, blocks, set_index):
    """Node ids (0-based) of each face of side set set_index (1-based)."""
    elems = nc.variables[f"elem_ss{set_index}"][:] - 1
    sides = nc.variables[f"side_ss{set_index}"][:]
    faces = []
    for e, s in zip(elems, sides):
        block, local = blocks.element(e)
        faces.append(block.conn[local][SIDES[block.type][s]])
    return faces, elems


class Blocks:
    def __init__(self, nc):
        self.list = []
        for k, name in enumerate(names(nc, "eb_names")):
            conn = nc.variables[f"connect{k + 1}"]
            self.list.append(type("Block", (), {"name": name, "type": conn.elem_type,
                                                 "conn": conn[:] - 1}))
        self.starts = np.cumsum([0] + [len(b.conn) for b in self.list])

    def element(self, e):
        k = np.searchsorted(self.starts, e, side="right") - 1
        return self.list[k], e - self.starts[k]

    def block_of(self, e):
        return self.list[np.searchsorted(self.starts, e, side="right") - 1].name


def check_exodus(path, vtu, materials, dim):
    label = os.path.basename(path)
    # meshio: one cell block per material with cells, coordinates as in the .vtu.
    mesh = meshio.read(path)
    ref = meshio.read(vtu)
    assert np.array_equal(mesh.points[:, :dim], ref.points[:, :dim]), label
    cell_type = "hexahedron" if dim == 3 else "quad"
    assert all(c.type == cell_type for c in mesh.cells), (label, [c.type for c in mesh.cells])
    assert sum(len(c.data) for c in mesh.cells) == len(ref.cells[0].data), label
    for c, m in zip(mesh.cells, mesh.cell_data["material"]):
        assert len(set(m)) == 1, (label, "a block mixes materials")
    with netCDF4.Dataset(path) as nc:
        blocks = Blocks(nc)
        used = sorted({int(m[0]) for m in mesh.cell_data["material"]})
        assert [b.name for b in blocks.list] == [materials[m] for m in used], \
            (label, [b.name for b in blocks.list], materials)
        assert list(nc.variables["eb_prop1"][:]) == [m + 1 for m in used], label
        x = np.stack([nc.variables[f"coord{a}"][:] for a in "xyz"[:dim]], axis=1)
        lo, hi = x.min(axis=0), x.max(axis=0)
        tol = 1e-9 * np.abs(hi - lo).max()
        ss = names(nc, "ss_names")
        ns = names(nc, "ns_names")
        sides = ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"][:2 * dim]
        assert ss[:2 * dim] == sides and ns[:2 * dim] == sides, (label, ss, ns)
        n_boundary = 0
        for k, side in enumerate(sides):
            axis, value = k // 2, (hi if k % 2 else lo)[k // 2]
            faces, _ = side_faces(nc, blocks, k + 1)
            n_boundary += len(faces)
            assert faces, (label, side, "empty")
            for f in faces:
                assert np.all(np.abs(x[f, axis] - value) <= tol), (label, side, x[f])
            nodes = nc.variables[f"node_ns{k + 1}"][:] - 1
            assert np.all(np.abs(x[nodes, axis] - value) <= tol), (label, side)
        pairs = ss[2 * dim:]
        assert pairs, (label, "no interface side sets")
        # Set `a_b`: faces of a's cells against b (names may hold '_' themselves).
        split = {f"{a}_{b}": (a, b) for a in materials for b in materials if a != b}
        assert all(name in split for name in pairs), (label, pairs)
        faces_of = {}
        for k, name in enumerate(pairs, start=2 * dim + 1):
            faces, elems = side_faces(nc, blocks, k)
            assert all(blocks.block_of(e) == split[name][0] for e in elems), (label, name)
            faces_of[name] = sorted(tuple(sorted(f)) for f in faces)
        for name, faces in faces_of.items():
            a, b = split[name]
            assert faces_of[f"{b}_{a}"] == faces, (label, name, "the two sides differ")
        assert set(ns[2 * dim:]) <= set(pairs), (label, ns)
        emap = nc.variables["elem_num_map"][:]
        assert sorted(emap) == list(range(1, len(emap) + 1)), label
        assert list(nc.variables["node_num_map"][:]) == list(range(1, len(x) + 1)), label
        qa = [b"".join(c).decode().rstrip("\0") for c in nc.variables["qa_records"][0]]
        assert qa[0] == "hexadapt-adapt", (label, qa)
        info = names(nc, "info_records")
        assert any(line.startswith("hexadapt_command: hexadapt-adapt") for line in info), info
        print(f"{label}: {len(blocks.list)} blocks {[b.name for b in blocks.list]}, "
              f"{n_boundary} boundary faces, interface sets {pairs}")


def vtu_material_names(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    a = r.GetOutput().GetFieldData().GetAbstractArray("material_names")
    return [a.GetValue(i) for i in range(a.GetNumberOfTuples())]


def pipeline(tools, work, case, dims, dim):
    tool = lambda name: os.path.join(tools, "hexadapt-" + name)
    p = os.path.join(work, case)
    run([tool("generate"), case, "--dims", dims, "-q", "-o", p + ".vf.vtu"])
    run([tool("assign"), p + ".vf.vtu", "-q", "-o", p + ".assign.vtu"])
    run([tool("adapt"), p + ".assign.vtu", "-q", "-o", p + ".exo", "--json", p + ".json"],
        ok=(0, 3))
    run([tool("adapt"), p + ".assign.vtu", "-q", "-o", p + ".plain.vtu", "--no-string-fields"],
        ok=(0, 3))
    run([tool("adapt"), p + ".assign.vtu", "-q", "-o", p + ".vtu"], ok=(0, 3))
    with open(p + ".json") as f:
        materials = json.load(f)["materials"]
    check_exodus(p + ".exo", p + ".plain.vtu", materials, dim)
    assert vtu_material_names(p + ".vtu") == materials, vtu_material_names(p + ".vtu")
    # measure reads the .exo: same cells and quality as the .vtu, and the discrepancy
    # against the fractions works through the material variable.
    got = {}
    for ext in (".exo", ".vtu"):
        run([tool("measure"), p + ext, "--reference", p + ".vf.vtu", "-q", "--json",
             p + ext + ".measure.json"], ok=(0, 3))
        with open(p + ext + ".measure.json") as f:
            got[ext] = json.load(f)
    for key in ("mesh", "quality", "mesh_check", "distances", "size"):
        assert got[".exo"][key] == got[".vtu"][key], (key, got[".exo"][key], got[".vtu"][key])
    assert got[".exo"]["discrepancy"]["total"] == got[".vtu"]["discrepancy"]["total"], case
    # The fractions as element variables: assign reads them from an .exo.
    run([tool("generate"), case, "--dims", dims, "-q", "-o", p + ".vf.exo"])
    run([tool("assign"), p + ".vf.exo", "-q", "-o", p + ".assign2.vtu"])
    r = run([tool("assign"), p + ".vf.exo", "--step", "2", "-q", "-o", p + ".x.vtu"], ok=(2,))
    assert "1 step: 0: t = 0" in r.stderr, r.stderr
    for sets in ("none", "boundary", "interfaces"):
        run([tool("adapt"), p + ".assign.vtu", "-q", "-o", p + f".{sets}.exo",
             "--exodus-sets", sets], ok=(0, 3))
        with netCDF4.Dataset(p + f".{sets}.exo") as nc:
            ss = names(nc, "ss_names")
            assert (sets == "none") == (not ss), (sets, ss)
            assert (sets in ("none", "interfaces")) == ("xmin" not in ss), (sets, ss)


def bad_inputs(tools, work):
    measure = os.path.join(tools, "hexadapt-measure")
    good = os.path.join(work, "triple-point.exo")
    data = open(good, "rb").read()
    for name, content in (("empty.exo", b""), ("text.exo", b"not an exodus file\n"),
                          ("half.exo", data[:len(data) // 2]), ("head.exo", data[:300])):
        path = os.path.join(work, name)
        open(path, "wb").write(content)
        r = run([measure, path, "-q"], ok=(2,))
        assert name in r.stderr, r.stderr
    # An output mesh as a fractions input: no vf_ element variables.
    r = run([os.path.join(tools, "hexadapt-assign"), good, "-q", "-o",
             os.path.join(work, "x.vtu")], ok=(2,))
    assert "triple-point.exo" in r.stderr, r.stderr


def main():
    tools, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    pipeline(tools, work, "triple-point", "42,18", 2)
    pipeline(tools, work, "asteroid", "10,10,10", 3)
    bad_inputs(tools, work)
    print("ok")


if __name__ == "__main__":
    main()
