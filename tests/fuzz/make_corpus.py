#!/usr/bin/python3
"""Writes the binary and XML seed files of the fuzz corpus with VTK and meshio themselves,
so the seeds are what those libraries really write (the ASCII legacy and text seeds are
hand-written). Run with Debian's python3 (python3-vtk9, python3-meshio):
    tests/fuzz/make_corpus.py tests/fuzz/corpus
"""
import os
import sys

import meshio
import numpy as np
import vtk
from vtk.util import numpy_support


def cell_array(name, values, vtk_type=vtk.VTK_DOUBLE):
    a = numpy_support.numpy_to_vtk(np.asarray(values), deep=1, array_type=vtk_type)
    a.SetName(name)
    return a


def hex_grid():
    """Two hexes (VTK_HEXAHEDRON) with two fraction arrays and an int point array."""
    pts = vtk.vtkPoints()
    for z in (0, 1):
        for y in (0, 1):
            for x in (0, 1, 2):
                pts.InsertNextPoint(x, y, z)
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(pts)
    for c in ((0, 1, 4, 3, 6, 7, 10, 9), (1, 2, 5, 4, 7, 8, 11, 10)):
        ids = vtk.vtkIdList()
        for i in c:
            ids.InsertNextId(i)
        grid.InsertNextCell(vtk.VTK_HEXAHEDRON, ids)
    grid.GetCellData().AddArray(cell_array("vf_a", [1.0, 0.25]))
    grid.GetCellData().AddArray(cell_array("vf_b", [0.0, 0.75], vtk.VTK_FLOAT))
    grid.GetPointData().AddArray(cell_array("id", np.arange(12, dtype=np.int32), vtk.VTK_INT))
    return grid


def image():
    img = vtk.vtkImageData()
    img.SetDimensions(4, 3, 2)
    img.SetSpacing(0.5, 0.5, 1.0)
    img.GetCellData().AddArray(cell_array("vf_a", np.linspace(0, 1, 6)))
    return img


def rectilinear():
    g = vtk.vtkRectilinearGrid()
    g.SetDimensions(3, 3, 1)
    g.SetXCoordinates(cell_array("x", [0.0, 0.5, 2.0]))
    g.SetYCoordinates(cell_array("y", [0.0, 1.0, 1.5]))
    g.SetZCoordinates(cell_array("z", [0.0]))
    g.GetCellData().AddArray(cell_array("vf_a", [0.0, 0.5, 1.0, 0.25]))
    return g


def structured():
    g = vtk.vtkStructuredGrid()
    g.SetDimensions(3, 2, 2)
    pts = vtk.vtkPoints()
    for z in (0, 1):
        for y in (0, 1):
            for x in (0, 1, 2):
                pts.InsertNextPoint(x + 0.1 * y, y, z)
    g.SetPoints(pts)
    g.GetCellData().AddArray(cell_array("vf_a", [0.3, 0.7]))
    return g


def write_xml(writer_class, data, path, mode, compress=False, header64=False, encode=False):
    w = writer_class()
    w.SetInputData(data)
    w.SetFileName(path)
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary,
     "appended": w.SetDataModeToAppended}[mode]()
    w.SetEncodeAppendedData(1 if encode else 0)
    if compress:
        w.SetCompressorTypeToZLib()
    else:
        w.SetCompressorTypeToNone()
    if header64:
        w.SetHeaderTypeToUInt64()
    w.Write()


def main(root):
    xml = os.path.join(root, "vtk_xml")
    legacy = os.path.join(root, "vtk_legacy")
    grid = hex_grid()
    vtu = vtk.vtkXMLUnstructuredGridWriter
    write_xml(vtu, grid, os.path.join(xml, "hex_ascii.vtu"), "ascii")
    write_xml(vtu, grid, os.path.join(xml, "hex_base64.vtu"), "binary")
    write_xml(vtu, grid, os.path.join(xml, "hex_appended_raw.vtu"), "appended")
    write_xml(vtu, grid, os.path.join(xml, "hex_appended_base64_zlib.vtu"), "appended",
              compress=True, encode=True)
    write_xml(vtu, grid, os.path.join(xml, "hex_zlib_uint64.vtu"), "binary", compress=True,
              header64=True)
    write_xml(vtk.vtkXMLImageDataWriter, image(), os.path.join(xml, "image_raw.vti"),
              "appended")
    write_xml(vtk.vtkXMLRectilinearGridWriter, rectilinear(),
              os.path.join(xml, "rectilinear_ascii.vtr"), "ascii")
    write_xml(vtk.vtkXMLStructuredGridWriter, structured(),
              os.path.join(xml, "structured_zlib.vts"), "binary", compress=True)
    quads = meshio.Mesh(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0],
                                  [2, 1, 0]], dtype=float),
                        [("quad", np.array([[0, 1, 2, 3], [1, 4, 5, 2]]))],
                        cell_data={"vf_a": [np.array([0.5, 1.0])]})
    meshio.write(os.path.join(xml, "quads_meshio.vtu"), quads)

    w = vtk.vtkUnstructuredGridWriter()
    w.SetInputData(grid)
    w.SetFileName(os.path.join(legacy, "hex_binary.vtk"))
    w.SetFileTypeToBinary()
    w.Write()
    w = vtk.vtkUnstructuredGridWriter()
    w.SetInputData(grid)
    w.SetFileName(os.path.join(legacy, "hex_binary_v42.vtk"))
    w.SetFileTypeToBinary()
    w.SetFileVersion(42)  # classic CELLS / CELL_TYPES layout
    w.Write()
    w = vtk.vtkStructuredPointsWriter()
    w.SetInputData(image())
    w.SetFileName(os.path.join(legacy, "image_binary.vtk"))
    w.SetFileTypeToBinary()
    w.Write()


if __name__ == "__main__":
    main(sys.argv[1])
