#!/usr/bin/env python3
"""Writes an n^3 unit-cube hex grid as a .pvtu of P .vtu pieces cut across z, each piece with
its own copies of the points it shares with the next (what a solver writing one piece per
rank gives): the input of bench/partition_bench.cpp.

    /usr/bin/python3 bench/pieces_case.py N P OUT_FOLDER   (writes OUT_FOLDER/grid.pvtu)
"""
import os
import sys

import meshio
import numpy as np


def piece(n, z0, z1):
    i, j, k = np.meshgrid(np.arange(n + 1), np.arange(n + 1), np.arange(z0, z1 + 1), indexing="ij")
    points = np.stack([a.ravel(order="F") for a in (i, j, k)], 1).astype(float) / n

    def node(a, b, c):
        return a + (n + 1) * (b + (n + 1) * (c - z0))

    a, b, c = (x.ravel(order="F") for x in np.meshgrid(np.arange(n), np.arange(n),
                                                       np.arange(z0, z1), indexing="ij"))
    hexes = np.stack([node(a, b, c), node(a + 1, b, c), node(a + 1, b + 1, c), node(a, b + 1, c),
                      node(a, b, c + 1), node(a + 1, b, c + 1), node(a + 1, b + 1, c + 1),
                      node(a, b + 1, c + 1)], 1)
    return meshio.Mesh(points, [("hexahedron", hexes)],
                       cell_data={"material": [np.zeros(len(hexes), dtype=np.int32)]})


def main():
    n, pieces, folder = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    os.makedirs(folder, exist_ok=True)
    names = []
    for p in range(pieces):
        names.append(f"grid_{p}.vtu")
        meshio.write(os.path.join(folder, names[-1]), piece(n, n * p // pieces, n * (p + 1) // pieces))
    with open(os.path.join(folder, "grid.pvtu"), "w") as f:
        f.write('<VTKFile type="PUnstructuredGrid" version="1.0"><PUnstructuredGrid GhostLevel="0">'
                '<PCellData><PDataArray type="Int32" Name="material"/></PCellData><PPoints>'
                '<PDataArray type="Float64" NumberOfComponents="3"/></PPoints>')
        f.writelines(f'<Piece Source="{name}"/>' for name in names)
        f.write("</PUnstructuredGrid></VTKFile>\n")


if __name__ == "__main__":
    main()
