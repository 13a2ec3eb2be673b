#!/usr/bin/python3
"""Cross-checks of the legacy .vtk reader and writer against VTK and meshio.

Usage: legacy_vtk_test.py PATH/TO/hexadapt_legacy_probe

1. VTK (python3-vtk9) writes every data set type (ASCII and binary, 2D and 3D, the 5.1
   layout and the classic one via SetFileVersion(42)); meshio writes quads and hexes. Our
   reader (through the probe) must give the same points, cells and arrays.
2. Our writer's output is read back by VTK and by meshio and compared with what we wrote.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import vtk
from vtk.util import numpy_support as ns

PROBE = sys.argv[1]
TMP = tempfile.mkdtemp(prefix="hexadapt_legacy_")
FAILURES = []
VTK_TYPES = {
    vtk.VTK_SIGNED_CHAR: "int8", vtk.VTK_CHAR: "int8", vtk.VTK_UNSIGNED_CHAR: "uint8",
    vtk.VTK_SHORT: "int16", vtk.VTK_UNSIGNED_SHORT: "uint16", vtk.VTK_INT: "int32",
    vtk.VTK_UNSIGNED_INT: "uint32", vtk.VTK_LONG: "int64", vtk.VTK_LONG_LONG: "int64",
    vtk.VTK_UNSIGNED_LONG_LONG: "uint64", vtk.VTK_ID_TYPE: "int32", vtk.VTK_FLOAT: "float32",
    vtk.VTK_DOUBLE: "float64",
}
# MeshData hex node b is VTK_HEXAHEDRON node VTK_OF_BINARY[b].
VTK_OF_BINARY = [0, 1, 3, 2, 4, 5, 7, 6]


def check(ok, what):
    if not ok:
        FAILURES.append(what)
        print("FAIL:", what)


def probe(*args):
    r = subprocess.run([PROBE, *args], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"probe {args} failed: {r.stderr}")
    return json.loads(r.stdout) if args[0] == "read" else None


def add_arrays(ds, n_points, n_cells, rng):
    """Arrays of several types and component counts on the cells and points."""
    def make(cls, name, n, comps, lo, hi):
        a = cls()
        a.SetName(name)
        a.SetNumberOfComponents(comps)
        vals = rng.integers(lo, hi, size=n * comps) if lo is not None else rng.random(n * comps)
        for v in vals:
            a.InsertNextValue(v.item())
        return a
    cd, pd = ds.GetCellData(), ds.GetPointData()
    cd.AddArray(make(vtk.vtkDoubleArray, "vf_water", n_cells, 1, None, None))
    cd.AddArray(make(vtk.vtkFloatArray, "vf air", n_cells, 1, None, None))
    cd.AddArray(make(vtk.vtkIntArray, "material", n_cells, 1, -3, 9))
    cd.AddArray(make(vtk.vtkUnsignedCharArray, "flags", n_cells, 1, 0, 255))
    cd.AddArray(make(vtk.vtkLongLongArray, "big", n_cells, 1, -2**40, 2**40))
    pair = make(vtk.vtkDoubleArray, "pair", n_cells, 2, None, None)
    pair.SetComponentName(0, "first")  # makes VTK write a METADATA block
    pair.SetComponentName(1, "second")
    cd.AddArray(pair)
    vec = make(vtk.vtkFloatArray, "velocity", n_points, 3, None, None)
    pd.AddArray(vec)
    pd.SetVectors(vec)
    pd.AddArray(make(vtk.vtkShortArray, "tag", n_points, 1, -100, 100))


def expected_arrays(attr):
    out = {}
    for k in range(attr.GetNumberOfArrays()):
        a = attr.GetArray(k)
        out[a.GetName()] = (a.GetNumberOfComponents(), VTK_TYPES[a.GetDataType()],
                            ns.vtk_to_numpy(a).astype(np.float64).ravel())
    return out


def close(a, b, exact):
    """Binary files carry exact values; VTK's ASCII ones print floats with 6 digits."""
    return np.array_equal(a, b) if exact else np.allclose(a, b, rtol=1e-5, atol=1e-7)


def compare_arrays(label, ours, theirs, exact=True):
    names = {a["name"] for a in ours}
    check(names == set(theirs), f"{label}: array names {sorted(names)} != {sorted(theirs)}")
    for a in ours:
        if a["name"] not in theirs:
            continue
        comps, typ, vals = theirs[a["name"]]
        check(a["components"] == comps, f"{label}: {a['name']} components")
        check(a["type"] == typ, f"{label}: {a['name']} type {a['type']} != {typ}")
        check(close(np.array(a["values"], dtype=np.float64), vals, exact),
              f"{label}: {a['name']} values")


def cell_centres(points, cells, k):
    p = np.array(points, dtype=np.float64)
    c = np.array(cells, dtype=np.int64).reshape(-1, k)
    return p[c].mean(axis=1)


def vtk_cell_centres(ds):
    out = []
    for c in range(ds.GetNumberOfCells()):
        ids = ds.GetCell(c).GetPointIds()
        out.append(np.mean([ds.GetPoint(ids.GetId(i)) for i in range(ids.GetNumberOfIds())], axis=0))
    return np.array(out)


def compare_dataset(label, path, ds, dim, exact):
    got = probe("read", path)
    k = 4 if dim == 2 else 8
    check(got["dim"] == dim, f"{label}: dim {got['dim']}")
    check(got["n_cells"] == ds.GetNumberOfCells(), f"{label}: cells {got['n_cells']}")
    check(got["n_points"] == ds.GetNumberOfPoints(), f"{label}: points {got['n_points']}")
    theirs = np.array([ds.GetPoint(p) for p in range(ds.GetNumberOfPoints())])
    ours = np.array(got["points"])
    check(close(ours, theirs, exact), f"{label}: point coordinates")
    # Same cells in the same order: compare cell centres.
    check(np.allclose(cell_centres(ours, got["cells"], k), vtk_cell_centres(ds), atol=1e-6),
          f"{label}: cell order / connectivity")
    if isinstance(ds, vtk.vtkUnstructuredGrid) and dim == 3:
        cells = np.array(got["cells"]).reshape(-1, 8)
        for c in range(ds.GetNumberOfCells()):
            ids = ds.GetCell(c).GetPointIds()
            want = [ids.GetId(VTK_OF_BINARY[b]) for b in range(8)]
            check(list(cells[c]) == want, f"{label}: hex {c} node order")
    compare_arrays(label + " cell", got["cell_data"], expected_arrays(ds.GetCellData()), exact)
    compare_arrays(label + " point", got["point_data"], expected_arrays(ds.GetPointData()), exact)


def image(dims):
    ds = vtk.vtkImageData()
    ds.SetDimensions(*dims)
    ds.SetOrigin(0.5, -1, 0)
    ds.SetSpacing(0.25, 0.5, 2)
    return ds


def rectilinear(dims, rng):
    ds = vtk.vtkRectilinearGrid()
    ds.SetDimensions(*dims)
    for axis, setter in enumerate([ds.SetXCoordinates, ds.SetYCoordinates, ds.SetZCoordinates]):
        setter(ns.numpy_to_vtk(np.cumsum(rng.random(dims[axis]) + 0.1), deep=1))
    return ds


def curvilinear(dims, rng):
    ds = vtk.vtkStructuredGrid()
    ds.SetDimensions(*dims)
    pts = vtk.vtkPoints()
    for k in range(dims[2]):
        for j in range(dims[1]):
            for i in range(dims[0]):
                pts.InsertNextPoint(i + 0.2 * rng.random(), j + 0.2 * rng.random(),
                                    0.0 if dims[2] == 1 else k + 0.2 * rng.random())
    ds.SetPoints(pts)
    return ds


def unstructured(dim, rng):
    """A 3 x 2 (x 2) grid as quads / hexahedra with jittered interior nodes."""
    n = (4, 3, 3 if dim == 3 else 1)
    ds = vtk.vtkUnstructuredGrid()
    pts = vtk.vtkPoints()
    for k in range(n[2]):
        for j in range(n[1]):
            for i in range(n[0]):
                pts.InsertNextPoint(i + 0.1 * rng.random(), j + 0.1 * rng.random(), float(k))
    ds.SetPoints(pts)
    pid = lambda i, j, k: i + n[0] * (j + n[1] * k)
    for k in range(max(n[2] - 1, 1)):
        for j in range(n[1] - 1):
            for i in range(n[0] - 1):
                quad = [pid(i, j, k), pid(i + 1, j, k), pid(i + 1, j + 1, k), pid(i, j + 1, k)]
                if dim == 2:
                    ds.InsertNextCell(vtk.VTK_QUAD, 4, quad)
                else:
                    top = [pid(a % n[0], (a // n[0]) % n[1], k + 1) for a in quad]
                    ds.InsertNextCell(vtk.VTK_HEXAHEDRON, 8, quad + top)
    return ds


def write_vtk(ds, path, binary, version42=False):
    w = vtk.vtkDataSetWriter()
    w.SetInputData(ds)
    w.SetFileName(path)
    if binary:
        w.SetFileTypeToBinary()
    else:
        w.SetFileTypeToASCII()
    if version42:
        w.SetFileVersion(42)
    w.Write()


def vtk_written_files(rng):
    cases = [("image2d", image((4, 3, 1)), 2), ("image3d", image((3, 4, 3)), 3),
             ("rect2d", rectilinear((5, 3, 1), rng), 2), ("rect3d", rectilinear((3, 3, 4), rng), 3),
             ("sgrid2d", curvilinear((4, 5, 1), rng), 2), ("sgrid3d", curvilinear((3, 4, 3), rng), 3),
             ("ugrid2d", unstructured(2, rng), 2), ("ugrid3d", unstructured(3, rng), 3)]
    for name, ds, dim in cases:
        add_arrays(ds, ds.GetNumberOfPoints(), ds.GetNumberOfCells(), rng)
        variants = [("ascii", False, False), ("binary", True, False)]
        if name.startswith("ugrid"):
            variants += [("ascii42", False, True), ("binary42", True, True)]
        for tag, binary, v42 in variants:
            path = os.path.join(TMP, f"{name}_{tag}.vtk")
            write_vtk(ds, path, binary, v42)
            compare_dataset(f"vtk {name} {tag}", path, ds, dim, exact=binary)


def meshio_written_files(rng):
    import meshio
    for dim in (2, 3):
        ds = unstructured(dim, rng)
        pts = np.array([ds.GetPoint(p) for p in range(ds.GetNumberOfPoints())])
        k = 4 if dim == 2 else 8
        conn = np.array([[ds.GetCell(c).GetPointId(i) for i in range(k)]
                         for c in range(ds.GetNumberOfCells())])
        n = len(conn)
        cell_data = {"vf_a": [rng.random(n)], "mat": [rng.integers(0, 5, n).astype(np.int32)],
                     "v2": [rng.random((n, 2))]}
        point_data = {"phi": rng.random(len(pts)).astype(np.float32)}
        mesh = meshio.Mesh(pts, [("quad" if dim == 2 else "hexahedron", conn)],
                           cell_data=cell_data, point_data=point_data)
        for binary in (True, False):
            path = os.path.join(TMP, f"meshio_{dim}d_{'bin' if binary else 'ascii'}.vtk")
            meshio.write(path, mesh, file_format="vtk", binary=binary)
            got = probe("read", path)
            label = f"meshio {dim}d {'binary' if binary else 'ascii'}"
            check(got["n_cells"] == n and got["dim"] == dim, f"{label}: counts")
            check(np.allclose(np.array(got["points"]), pts), f"{label}: points")
            cells = np.array(got["cells"]).reshape(-1, k)
            want = conn if dim == 2 else conn[:, VTK_OF_BINARY]
            check(np.array_equal(cells, want), f"{label}: connectivity")
            arrays = {a["name"]: a for a in got["cell_data"]}
            for name, (vals,) in cell_data.items():
                check(name in arrays and np.allclose(np.array(arrays[name]["values"]), vals.ravel()),
                      f"{label}: cell array {name}")
            check(arrays.get("mat", {}).get("type") == "int32", f"{label}: mat type")
            phi = {a["name"]: a for a in got["point_data"]}.get("phi")
            check(phi is not None and phi["type"] == "float32" and
                  np.array_equal(np.array(phi["values"]), point_data["phi"].astype(np.float64)),
                  f"{label}: point array phi")


def our_files_read_back(rng):
    import meshio
    for name in ("ugrid2d", "ugrid3d", "rect2d", "image3d"):
        src = os.path.join(TMP, f"{name}_binary.vtk")
        out = os.path.join(TMP, f"{name}_ours.vtk")
        probe("rewrite", src, out)
        ours = probe("read", src)
        with open(out, "rb") as f:
            lines = f.read().split(b"\n")
        check(lines[0] == b"# vtk DataFile Version 4.2", f"ours {name}: version line")
        check(lines[1].startswith(b"hexadapt: tool=hexadapt_legacy_probe") and len(lines[1]) <= 255,
              f"ours {name}: title line {lines[1][:60]}")
        r = vtk.vtkUnstructuredGridReader()
        r.SetFileName(out)
        r.ReadAllScalarsOn()
        r.ReadAllVectorsOn()
        r.ReadAllFieldsOn()
        r.Update()
        ug = r.GetOutput()
        dim, k = ours["dim"], 4 if ours["dim"] == 2 else 8
        label = f"vtk reads ours {name}"
        check(ug.GetNumberOfCells() == ours["n_cells"], f"{label}: cells")
        check(np.allclose(ns.vtk_to_numpy(ug.GetPoints().GetData()), np.array(ours["points"])),
              f"{label}: points")
        want_type = vtk.VTK_QUAD if dim == 2 else vtk.VTK_HEXAHEDRON
        check(all(ug.GetCellType(c) == want_type for c in range(ug.GetNumberOfCells())),
              f"{label}: cell types")
        cells = np.array(ours["cells"]).reshape(-1, k)
        for c in range(ug.GetNumberOfCells()):
            ids = [ug.GetCell(c).GetPointId(i) for i in range(k)]
            want = list(cells[c]) if dim == 2 else [cells[c][VTK_OF_BINARY[i]] for i in range(8)]
            check(ids == want, f"{label}: cell {c} nodes {ids} != {want}")
        if dim == 3:
            q = vtk.vtkMeshQuality()
            q.SetInputData(ug)
            q.SetHexQualityMeasureToScaledJacobian()
            q.Update()
            sj = ns.vtk_to_numpy(q.GetOutput().GetCellData().GetArray("Quality"))
            check(sj.min() > 0, f"{label}: hexes not inverted (min scaled Jacobian {sj.min()})")
        for attr, key in ((ug.GetCellData(), "cell_data"), (ug.GetPointData(), "point_data")):
            theirs = expected_arrays(attr)
            compare_arrays(label + " " + key, ours[key], theirs)
        m = meshio.read(out)
        label = f"meshio reads ours {name}"
        check(np.allclose(m.points, np.array(ours["points"])), f"{label}: points")
        block = m.cells[0]
        check(block.type == ("quad" if dim == 2 else "hexahedron"), f"{label}: cell type")
        want = cells if dim == 2 else cells[:, VTK_OF_BINARY]
        check(np.array_equal(block.data, want), f"{label}: connectivity")
        for a in ours["cell_data"]:
            got = m.cell_data.get(a["name"].replace(" ", "%20")) or m.cell_data.get(a["name"])
            check(got is not None and np.allclose(np.asarray(got[0], dtype=float).ravel(), a["values"]),
                  f"{label}: cell array {a['name']}")


def main():
    rng = np.random.default_rng(7)
    vtk_written_files(rng)
    meshio_written_files(rng)
    our_files_read_back(rng)
    print(f"{len(FAILURES)} failures; files in {TMP}")
    if not FAILURES and not os.environ.get("KEEP"):
        import shutil
        shutil.rmtree(TMP)
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
