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


def bundle(main_file, folder, names):
    """A collection file and the files it names as one seed of fuzz_vtk_collection."""
    parts = [open(main_file).read()]
    for name in names:
        with open(os.path.join(folder, name)) as f:
            parts.append("--8<-- %s\n%s" % (name, f.read()))
    return "\n".join(parts)


def parallel_writer(writer_class, data_or_port, path, pieces, ghost=0):
    w = writer_class()
    w.SetInputConnection(data_or_port)
    w.SetFileName(path)
    w.SetDataModeToAscii()
    w.SetNumberOfPieces(pieces)
    w.SetStartPiece(0)
    w.SetEndPiece(pieces - 1)
    w.SetGhostLevel(ghost)
    w.Write()


def collection_seeds(root):
    """Seeds of fuzz_vtk_collection: .pvtu (with ghosts), .pvtr, .pvts, .vtm, .pvd, written by
    VTK in ascii (small and readable), then bundled with their pieces."""
    import tempfile
    out = os.path.join(root, "vtk_collection")
    os.makedirs(out, exist_ok=True)
    tmp = tempfile.mkdtemp()
    g = vtk.vtkRectilinearGrid()
    g.SetDimensions(4, 3, 2)
    g.SetXCoordinates(cell_array("x", [0.0, 0.5, 2.0, 3.0]))
    g.SetYCoordinates(cell_array("y", [0.0, 1.0, 1.5]))
    g.SetZCoordinates(cell_array("z", [0.0, 1.0]))
    g.GetCellData().AddArray(cell_array("vf_a", np.linspace(0, 1, 6)))
    # A reader, not the data itself, so that each piece asks for (and gets) its own extent.
    whole = vtk.vtkXMLRectilinearGridWriter()
    whole.SetInputData(g)
    whole.SetFileName(os.path.join(tmp, "whole.vtr"))
    whole.Write()
    source = vtk.vtkXMLRectilinearGridReader()
    source.SetFileName(os.path.join(tmp, "whole.vtr"))
    to_ug = vtk.vtkAppendFilter()
    to_ug.SetInputConnection(source.GetOutputPort())
    to_sg = vtk.vtkRectilinearGridToPointSet()
    to_sg.SetInputConnection(source.GetOutputPort())
    jobs = [(vtk.vtkXMLPUnstructuredGridWriter, to_ug, "hexes.pvtu", 2, 0, "vtu"),
            (vtk.vtkXMLPUnstructuredGridWriter, to_ug, "ghosts.pvtu", 2, 1, "vtu"),
            (vtk.vtkXMLPRectilinearGridWriter, source, "grid.pvtr", 2, 0, "vtr"),
            (vtk.vtkXMLPStructuredGridWriter, to_sg, "grid.pvts", 2, 0, "vts")]
    for writer, port, name, pieces, ghost, ext in jobs:
        parallel_writer(writer, port.GetOutputPort(), os.path.join(tmp, name), pieces, ghost)
        stem = name.rsplit(".", 1)[0]
        names = ["%s/%s_%d.%s" % (stem, stem, k, ext) if os.path.isdir(os.path.join(tmp, stem))
                 else "%s_%d.%s" % (stem, k, ext) for k in range(pieces)]
        with open(os.path.join(out, name), "w") as f:
            f.write(bundle(os.path.join(tmp, name), tmp, names))
    piece = os.path.join(tmp, "hexes_0.vtu") if os.path.exists(os.path.join(tmp, "hexes_0.vtu")) \
        else os.path.join(tmp, "hexes", "hexes_0.vtu")
    piece_text = open(piece).read()
    with open(os.path.join(out, "blocks.vtm"), "w") as f:
        f.write('<VTKFile type="vtkMultiBlockDataSet" version="1.0"><vtkMultiBlockDataSet>'
                '<Block index="0"><DataSet index="0" file="a.vtu"/></Block>'
                '<DataSet index="1" file="b.vtu"/></vtkMultiBlockDataSet></VTKFile>'
                "\n--8<-- a.vtu\n" + piece_text + "\n--8<-- b.vtu\n" + piece_text)
    with open(os.path.join(out, "series.pvd"), "w") as f:
        f.write('<VTKFile type="Collection" version="0.1"><Collection>'
                '<DataSet timestep="0.5" part="0" file="t1.vtu"/>'
                '<DataSet timestep="0" part="0" file="t0.vtu"/>'
                '<DataSet timestep="0" part="1" file="t0b.vtu"/></Collection></VTKFile>'
                "\n--8<-- t0.vtu\n" + piece_text + "\n--8<-- t0b.vtu\n" + piece_text +
                "\n--8<-- t1.vtu\n" + piece_text)


def compressed_seeds(root):
    """LZ4 and LZMA blocks, as VTK writes them."""
    xml = os.path.join(root, "vtk_xml")
    for compressor, header64 in (("LZ4", False), ("LZMA", True)):
        w = vtk.vtkXMLUnstructuredGridWriter()
        w.SetInputData(hex_grid())
        w.SetFileName(os.path.join(xml, "hex_%s.vtu" % compressor.lower()))
        w.SetDataModeToAppended()
        w.SetEncodeAppendedData(0)
        getattr(w, "SetCompressorTypeTo" + compressor)()
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
    compressed_seeds(root)
    collection_seeds(root)


if __name__ == "__main__":
    main(sys.argv[1])
