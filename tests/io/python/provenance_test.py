#!/usr/bin/python3
"""The command that made a file, read by VTK's own readers (Debian's python3-vtk9) and meshio:
hexadapt-generate then hexadapt-assign with options ("--zero-below", "--void"), a folder with
a space and a file name with a quote. The .vtu holds the assign command exactly in a String
field-data array `hexadapt_command` (its comment escapes "--"); the legacy .vtk holds it as a
char array in the data set's field data, its title line keeps whole pairs within 255
characters. Split as a shell would, the command gives back the arguments typed. meshio reads
the .vtk as it is and the .vtu written with --no-string-fields.

  provenance_test.py TOOLS_DIR WORK_DIR
"""
import os
import shlex
import shutil
import subprocess
import sys

import meshio
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def field_array(reader, path):
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetFieldData().GetAbstractArray("hexadapt_command")


def check_vtu(path, argv):
    a = field_array(vtk.vtkXMLUnstructuredGridReader(), path)
    assert a is not None and a.GetNumberOfTuples() == 1, path
    command = a.GetValue(0)
    assert shlex.split(command) == argv, (command, argv)
    with open(path, "rb") as f:
        head = f.read(4096).decode("utf-8", "replace")
    assert "-\\x2Dzero-below" in head, "the comment escapes '--'"


def check_vtk(path, argv):
    a = field_array(vtk.vtkUnstructuredGridReader(), path)
    assert isinstance(a, vtk.vtkCharArray), type(a)
    command = vtk_to_numpy(a).tobytes().decode()
    assert shlex.split(command) == argv, (command, argv)
    with open(path, "rb") as f:
        title = f.read().split(b"\n")[1].decode()
    assert len(title) <= 255 and title.startswith("hexadapt: hexadapt_tool=hexadapt-assign; "), title
    mesh = meshio.read(path)
    assert mesh.field_data["hexadapt_command"].tobytes().decode() == command


def main():
    tools, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    folder = os.path.join(work, "run 1")
    os.makedirs(folder)
    tool = lambda name: os.path.join(tools, "hexadapt-" + name)
    vf = os.path.join(folder, "vf.vtu")
    subprocess.run([tool("generate"), "venn", "--dims", "12,10", "-q", "-o", vf], check=True)
    for ext in ("vtu", "vtk"):
        out = os.path.join(folder, "it's assigned." + ext)
        args = [vf, "--zero-below", "1e-3", "--void", "gap", "-q", "-o", out]
        subprocess.run([tool("assign")] + args, check=True)
        (check_vtu if ext == "vtu" else check_vtk)(out, ["hexadapt-assign"] + args)
    plain = os.path.join(folder, "plain.vtu")
    subprocess.run([tool("assign"), vf, "--no-string-fields", "-q", "-o", plain], check=True)
    assert field_array(vtk.vtkXMLUnstructuredGridReader(), plain) is None
    mesh = meshio.read(plain)
    assert np.asarray(mesh.cell_data["material"][0]).size == 120
    print("ok")


if __name__ == "__main__":
    main()
