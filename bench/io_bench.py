#!/usr/bin/python3
"""Writes a 200^3-cell ImageData with three Float64 cell arrays (volume fractions of a
sphere, a slab and the rest) with VTK, appended raw and zlib-compressed, times VTK's own
reader on them for reference, then runs hexadapt_io_bench on both files.

usage: bench/io_bench.py BUILD_DIR [WORK_DIR] [N]    (run with Debian's /usr/bin/python3)
"""
import os
import subprocess
import sys
import time

import numpy as np
import vtk
from vtk.util import numpy_support as ns

build = sys.argv[1]
work = sys.argv[2] if len(sys.argv) > 2 else "/tmp"
n = int(sys.argv[3]) if len(sys.argv) > 3 else 200

c = (np.arange(n) + 0.5) / n
x, y, z = np.meshgrid(c, c, c, indexing="ij")
r = np.sqrt((x - 0.5) ** 2 + (y - 0.5) ** 2 + (z - 0.5) ** 2)
sphere = np.clip((0.3 - r) * n + 0.5, 0.0, 1.0)
slab = np.clip((0.2 - np.abs(x + 0.3 * y - 0.6)) * n + 0.5, 0.0, 1.0) * (1 - sphere)
rest = 1.0 - sphere - slab
image = vtk.vtkImageData()
image.SetDimensions(n + 1, n + 1, n + 1)
image.SetSpacing(1.0 / n, 1.0 / n, 1.0 / n)
for name, v in [("vf_sphere", sphere), ("vf_slab", slab), ("vf_rest", rest)]:
    a = ns.numpy_to_vtk(np.ascontiguousarray(v.transpose(2, 1, 0).reshape(-1)), deep=True)
    a.SetName(name)
    image.GetCellData().AddArray(a)

files = []
for mode in ["raw", "zlib"]:
    path = os.path.join(work, f"io_bench_{n}_{mode}.vti")
    w = vtk.vtkXMLImageDataWriter()
    w.SetInputData(image)
    w.SetFileName(path)
    w.SetDataModeToAppended()
    w.EncodeAppendedDataOff()
    w.SetHeaderTypeToUInt64()
    if mode == "zlib":
        w.SetCompressorTypeToZLib()
    else:
        w.SetCompressorTypeToNone()
    t = time.perf_counter()
    w.Write()
    t_write = time.perf_counter() - t
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(path)
    t = time.perf_counter()
    reader.Update()
    t_read = time.perf_counter() - t
    size = os.path.getsize(path) / 1e6
    print(f"VTK {vtk.vtkVersion.GetVTKVersion()} reference, {path}: {size:.1f} MB; "
          f"write {t_write:.3f} s, read {t_read:.3f} s ({size / t_read:.0f} MB/s)")
    files.append(path)
del image, sphere, slab, rest, x, y, z, r

subprocess.run([os.path.join(build, "bench", "hexadapt_io_bench"), *files], check=True)
if os.environ.get("KEEP"):
    print("kept", *files)
else:
    for f in files:
        os.remove(f)
