#!/usr/bin/python3
"""Checks the VTK XML reader and writers of libhexadapt against VTK and meshio.

Writes quad and hex meshes (unstructured .vtu; structured .vti, .vtr, .vts) with cell and
point arrays of several types, with VTK in every encoding (ascii, inline base64, appended
raw and base64, zlib on and off, UInt32 and UInt64 headers, big-endian) and with meshio,
then checks that hexadapt_io_roundtrip reads exactly what was written. Then reads the
.vtu / .vts files our writers produce back with VTK and meshio and compares the values.

usage: vtk_xml_roundtrip.py HEXADAPT_IO_ROUNDTRIP WORK_DIR
"""
import json
import os
import subprocess
import sys

import meshio
import numpy as np
import vtk
from vtk.util import numpy_support as ns

EXE, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
VTK_OF_BINARY = [0, 1, 3, 2, 4, 5, 7, 6]  # binary lattice node b is VTK_HEXAHEDRON node [b]
RNG = np.random.default_rng(7)
TYPE_NAMES = {np.dtype(np.int8): "Int8", np.dtype(np.uint8): "UInt8", np.dtype(np.int32): "Int32",
              np.dtype(np.int64): "Int64", np.dtype(np.float32): "Float32",
              np.dtype(np.float64): "Float64", np.dtype(np.uint16): "UInt16"}
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


# ---- meshes: points, kernel-order cells, arrays -------------------------------------------

def structured_block(n):
    """Points (i fastest) and kernel-order cells of a block with n = (nx, ny, nz) cells."""
    nx, ny, nz = n
    dims = (nx + 1, ny + 1, nz + 1)
    node = lambda i, j, k: i + dims[0] * (j + dims[1] * k)
    cells = []
    if nz == 0:
        for j in range(ny):
            for i in range(nx):
                cells.append([node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0)])
    else:
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    cells.append([node(i + (b & 1), j + (b >> 1 & 1), k + (b >> 2 & 1)) for b in range(8)])
    return dims, np.array(cells, dtype=np.int64)


def arrays_for(n_points, n_cells):
    point = {"dist": RNG.normal(size=n_points),
             "node_id": np.arange(n_points, dtype=np.int64) * 3 - 5,
             "vec": RNG.normal(size=(n_points, 3))}
    cell = {"material": RNG.integers(-3, 100, n_cells).astype(np.int32),
            "vf_a": RNG.random(n_cells).astype(np.float32),
            "vf_b": RNG.random(n_cells),
            "flag": RNG.integers(0, 255, n_cells).astype(np.uint8)}
    return point, cell


def vtk_cells(kernel_cells):
    """Kernel-order cells to VTK connectivity rows (hexes: VTK_HEXAHEDRON order)."""
    if kernel_cells.shape[1] == 8:
        return kernel_cells[:, VTK_OF_BINARY]
    return kernel_cells


def make_meshes():
    meshes = []
    for name, n in [("hex", (3, 2, 2)), ("quad", (4, 3, 0))]:
        dims, cells = structured_block(n)
        g = np.stack(np.meshgrid(*[np.linspace(0, 1, d) for d in dims], indexing="ij"), -1)
        pts = g.transpose(2, 1, 0, 3).reshape(-1, 3) + RNG.normal(scale=0.02, size=(np.prod(dims), 3))
        if n[2] == 0:
            pts[:, 2] = 0.0
        order = RNG.permutation(len(cells))  # unstructured: cells in another order
        pd, cd = arrays_for(len(pts), len(cells))
        meshes.append(dict(name="u" + name, kind="vtu", points=pts, cells=cells[order], n=n,
                           dims=dims, point_data=pd, cell_data=cd))
        for kind in ["vti", "vtr", "vts"]:
            spacing = np.array([0.5, 0.25, 2.0])
            origin = np.array([1.0, -2.0, 0.5])
            axes = [origin[a] + spacing[a] * np.arange(dims[a]) for a in range(3)]
            if kind == "vtr":
                axes = [np.cumsum(RNG.random(dims[a])) for a in range(3)]
            grid = np.stack(np.meshgrid(*axes, indexing="ij"), -1).transpose(2, 1, 0, 3).reshape(-1, 3)
            if kind == "vts":
                grid = grid + RNG.normal(scale=0.01, size=grid.shape)
                if n[2] == 0:
                    grid[:, 2] = origin[2]
            pd, cd = arrays_for(len(grid), len(cells))
            meshes.append(dict(name=kind + name, kind=kind, points=grid, cells=cells, n=n, dims=dims,
                               axes=axes, origin=origin, spacing=spacing, point_data=pd, cell_data=cd))
    return meshes


# ---- writing with VTK and meshio ------------------------------------------------------------

def vtk_array(name, values):
    a = ns.numpy_to_vtk(np.ascontiguousarray(values), deep=True)
    a.SetName(name)
    return a


def vtk_dataset(m):
    kind = m["kind"]
    if kind == "vtu":
        ds = vtk.vtkUnstructuredGrid()
        cells = vtk_cells(m["cells"])
        ctype = vtk.VTK_HEXAHEDRON if cells.shape[1] == 8 else vtk.VTK_QUAD
        ca = vtk.vtkCellArray()
        ca.SetData(vtk_array("offsets", np.arange(len(cells) + 1, dtype=np.int64) * cells.shape[1]),
                   vtk_array("connectivity", cells.reshape(-1).astype(np.int64)))
        ds.SetCells(ctype, ca)
    elif kind == "vti":
        ds = vtk.vtkImageData()
        ds.SetDimensions(*m["dims"])
        ds.SetOrigin(*m["origin"])
        ds.SetSpacing(*m["spacing"])
    elif kind == "vtr":
        ds = vtk.vtkRectilinearGrid()
        ds.SetDimensions(*m["dims"])
        ds.SetXCoordinates(vtk_array("x", m["axes"][0]))
        ds.SetYCoordinates(vtk_array("y", m["axes"][1]))
        ds.SetZCoordinates(vtk_array("z", m["axes"][2]))
    else:
        ds = vtk.vtkStructuredGrid()
        ds.SetDimensions(*m["dims"])
    if kind in ("vtu", "vts"):
        p = vtk.vtkPoints()
        p.SetData(vtk_array("Points", m["points"]))
        ds.SetPoints(p)
    for name, v in m["point_data"].items():
        ds.GetPointData().AddArray(vtk_array(name, v))
    for name, v in m["cell_data"].items():
        ds.GetCellData().AddArray(vtk_array(name, v))
    return ds


WRITERS = {"vtu": vtk.vtkXMLUnstructuredGridWriter, "vti": vtk.vtkXMLImageDataWriter,
           "vtr": vtk.vtkXMLRectilinearGridWriter, "vts": vtk.vtkXMLStructuredGridWriter}


def vtk_modes():
    yield "ascii", dict(mode="ascii", zlib=False, h64=False, big=False)
    for mode in ["binary", "raw", "base64"]:
        for zlib in [False, True]:
            for h64 in [False, True]:
                yield f"{mode}{'-zlib' if zlib else ''}{'-u64' if h64 else ''}", \
                    dict(mode=mode, zlib=zlib, h64=h64, big=False)
    yield "raw-zlib-bigendian", dict(mode="raw", zlib=True, h64=False, big=True)
    yield "binary-bigendian", dict(mode="binary", zlib=False, h64=True, big=True)


def write_vtk(m, mode, path):
    w = WRITERS[m["kind"]]()
    w.SetInputData(vtk_dataset(m))
    w.SetFileName(path)
    if mode["mode"] == "ascii":
        w.SetDataModeToAscii()
    elif mode["mode"] == "binary":
        w.SetDataModeToBinary()
    else:
        w.SetDataModeToAppended()
        w.SetEncodeAppendedData(mode["mode"] == "base64")
    if mode["zlib"]:
        w.SetCompressorTypeToZLib()
        w.SetBlockSize(64)  # several blocks even for these small arrays
    else:
        w.SetCompressorTypeToNone()
    if mode["h64"]:
        w.SetHeaderTypeToUInt64()
    else:
        w.SetHeaderTypeToUInt32()
    if mode["big"]:
        w.SetByteOrderToBigEndian()
    assert w.Write() == 1, path


def write_meshio(m, path, **kw):
    cells = vtk_cells(m["cells"])
    ctype = "hexahedron" if cells.shape[1] == 8 else "quad"
    mesh = meshio.Mesh(m["points"], [(ctype, cells)], point_data=m["point_data"],
                       cell_data={k: [v] for k, v in m["cell_data"].items()})
    meshio.write(path, mesh, file_format="vtu", **kw)


# ---- checks ---------------------------------------------------------------------------------

def run(path, *args):
    r = subprocess.run([EXE, path, *args], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"{path}: exit {r.returncode}: {r.stderr.strip()}")
        print("FAIL:", failures[-1])
        return None
    return json.loads(r.stdout)


def same(a, b, flat=False):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if flat:  # meshio gives single-component arrays as (n, 1)
        a, b = a.reshape(-1), b.reshape(-1)
    return a.shape == b.shape and np.array_equal(a, b)


def check_read(m, got, label):
    if got is None:
        return
    dim = 3 if m["cells"].shape[1] == 8 else 2
    check(got["dim"] == dim, f"{label}: dim {got['dim']}")
    check(same(got["points"], m["points"]), f"{label}: points differ")
    check(same(np.array(got["cells"]).reshape(-1, m["cells"].shape[1]), m["cells"]),
          f"{label}: cells differ")
    for key, source in [("point_data", m["point_data"]), ("cell_data", m["cell_data"])]:
        got_arrays = {a["name"]: a for a in got[key]}
        check(set(got_arrays) == set(source), f"{label}: {key} names {sorted(got_arrays)}")
        for name, v in source.items():
            a = got_arrays.get(name)
            if a is None:
                continue
            check(a["type"] == TYPE_NAMES[v.dtype], f"{label}: {name} type {a['type']}")
            ncomp = 1 if v.ndim == 1 else v.shape[1]
            check(a["n_components"] == ncomp, f"{label}: {name} components")
            check(same(a["values"], v.reshape(-1)), f"{label}: {name} values differ")


def check_vtk_reads_ours(m, path):
    reader = (vtk.vtkXMLUnstructuredGridReader if path.endswith(".vtu")
              else vtk.vtkXMLStructuredGridReader)()
    reader.SetFileName(path)
    reader.Update()
    ds = reader.GetOutput()
    label = f"VTK reading {os.path.basename(path)}"
    check(same(ns.vtk_to_numpy(ds.GetPoints().GetData()), m["points"]), f"{label}: points")
    if path.endswith(".vtu"):
        conn = ns.vtk_to_numpy(ds.GetCells().GetConnectivityArray()).reshape(len(m["cells"]), -1)
        check(same(conn, vtk_cells(m["cells"])), f"{label}: connectivity")
        want = vtk.VTK_HEXAHEDRON if m["cells"].shape[1] == 8 else vtk.VTK_QUAD
        check(all(ds.GetCellType(c) == want for c in range(ds.GetNumberOfCells())), f"{label}: types")
    else:
        check(list(ds.GetDimensions()) == list(m["dims"]), f"{label}: dimensions {ds.GetDimensions()}")
    for data, source in [(ds.GetPointData(), m["point_data"]), (ds.GetCellData(), m["cell_data"])]:
        for name, v in source.items():
            a = data.GetArray(name)
            check(a is not None, f"{label}: no array {name}")
            if a is not None:
                got = ns.vtk_to_numpy(a)
                check(got.dtype == v.dtype and same(got, v), f"{label}: array {name}")
    # The metadata is a comment now: VTK sees no field data, a person sees the lines.
    check(ds.GetFieldData().GetNumberOfArrays() == 0, f"{label}: unexpected field data")
    with open(path, "rb") as f:
        head = f.read(4096)
    check(b"<!-- hexadapt metadata\n" in head and b"\ntool: hexadapt-test\n" in head,
          f"{label}: no readable metadata comment at the start of the file")


def check_metadata(got, metadata, label):
    if got is not None:
        check(got["metadata"] == metadata, f"{label}: metadata {got['metadata']!r}")


def check_meshio_reads_ours(m, path):
    label = f"meshio reading {os.path.basename(path)}"
    mesh = meshio.read(path)
    check(same(mesh.points, m["points"]), f"{label}: points")
    check(len(mesh.cells) == 1 and same(mesh.cells[0].data, vtk_cells(m["cells"])), f"{label}: cells")
    for name, v in m["point_data"].items():
        check(mesh.point_data[name].dtype == v.dtype and same(mesh.point_data[name], v, True),
              f"{label}: point array {name}")
    for name, v in m["cell_data"].items():
        got = mesh.cell_data[name][0]
        check(got.dtype == v.dtype and same(got, v, True), f"{label}: cell array {name}")


def as_meshio_reads(m, path):
    mesh = meshio.read(path)
    cells = mesh.cells[0].data
    squeeze = lambda v: v.reshape(-1) if v.ndim == 2 and v.shape[1] == 1 else v
    return dict(m, points=mesh.points, cells=vtk_cells(cells),
                point_data={k: squeeze(v) for k, v in mesh.point_data.items()},
                cell_data={k: squeeze(v[0]) for k, v in mesh.cell_data.items()})


def main():
    meshes = make_meshes()
    n_files = 0
    # Characters an XML comment cannot hold as they are, and text meshio searches for.
    metadata = {"tool": "hexadapt-test", "options": "a<b & \"c\"\nsecond line",
                "command": "hexadapt-overlay --threads 2 -- x-", "trap": "<AppendedData x=\"1\">",
                "unicode": "\u00e9\u2192"}
    meta_args = [x for k, v in metadata.items() for x in ("--meta", f"{k}={v}")]
    for m in meshes:
        for label, mode in vtk_modes():
            path = os.path.join(WORK, f"{m['name']}-{label}.{m['kind']}")
            write_vtk(m, mode, path)
            check_read(m, run(path), os.path.basename(path))
            n_files += 1
        if m["kind"] == "vtu":
            for label, kw in [("default", {}), ("ascii", dict(binary=False)),
                              ("nozlib", dict(compression=None)),
                              ("u64", dict(header_type="UInt64"))]:
                path = os.path.join(WORK, f"{m['name']}-meshio-{label}.vtu")
                write_meshio(m, path, **kw)
                # meshio's ascii keeps fewer digits: what meshio reads back is the reference.
                check_read(as_meshio_reads(m, path), run(path), os.path.basename(path))
                n_files += 1
        # Our writers, read back by us (with metadata), VTK and meshio (.vtu only: meshio 5
        # reads no .vts).
        source = os.path.join(WORK, f"{m['name']}-raw.{m['kind']}")
        for compress in [[], ["--raw"]]:
            tag = "raw" if compress else "zlib"
            ours = os.path.join(WORK, f"ours-{m['name']}-{tag}.vtu")
            args = ["--vtu", ours, *compress, *meta_args]
            if m["kind"] != "vtu":
                args += ["--vts", ours[:-4] + ".vts"]
            check_read(m, run(source, *args), f"{source} -> {ours}")
            check_vtk_reads_ours(m, ours)
            check_meshio_reads_ours(m, ours)
            if m["kind"] != "vtu":
                vts = ours[:-4] + ".vts"
                check_vtk_reads_ours(m, vts)
                got = run(vts)
                check_read(m, got, vts)
                check_metadata(got, metadata, vts)
            got = run(ours)
            check_read(m, got, ours)
            check_metadata(got, metadata, ours)
    print(f"{n_files} files written by VTK and meshio, {len(meshes)} meshes; "
          f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
