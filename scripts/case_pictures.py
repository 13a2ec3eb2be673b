#!/usr/bin/python3
"""Pictures of the generated cases for testdata/README.md.

Runs hexadapt-generate for every case (or the ones named), reads the .vtu with VTK and draws
each cell in the mix of its materials' colours (a mid-height slice of the cells for 3D
cases). Needs Debian's python3-vtk9, python3-numpy and python3-matplotlib.

  scripts/case_pictures.py [--tools build/tools] [--out docs/images] [case ...]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
import vtk  # noqa: E402

# One colour per material index: background first.
COLOURS = np.array([[0.93, 0.93, 0.93], [0.84, 0.30, 0.20], [0.20, 0.45, 0.80],
                    [0.95, 0.75, 0.20], [0.30, 0.70, 0.40]])

# Per case: extra generate options for the picture (small grids keep the files small).
OPTIONS = {
    "sphere": ["--dims", "48,48,48"],
    "asteroid": ["--dims", "64,64,64"],
    "venn": ["--dims", "80,80"],
    "venn4": ["--dims", "80,80"],
    "vortex": ["--dims", "128,128"],
}


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def cells_and_colours(grid):
    points = vtk_to_numpy(grid.GetPoints().GetData())
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    n_cells = grid.GetNumberOfCells()
    cells = conn.reshape(n_cells, -1)
    cd = grid.GetCellData()
    names = [cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays())]
    vf = [vtk_to_numpy(cd.GetArray(n)) for n in names if n.startswith("vf_")]
    colour = sum(f[:, None] * COLOURS[m] for m, f in enumerate(vf))
    if cells.shape[1] == 8:  # hexes: the layer of cells around mid-height, bottom faces
        zc = points[cells].mean(axis=1)[:, 2]
        levels = np.unique(np.round(zc, 9))
        mid = levels[len(levels) // 2]
        keep = np.abs(zc - mid) < 1e-8
        cells, colour = cells[keep], colour[keep]
        first = cells[:, :4]
        ordered = grid.GetCellType(0) == vtk.VTK_HEXAHEDRON
        cells = first if ordered else first[:, [0, 1, 3, 2]]
    return points[:, :2][cells], colour


def draw(path, png, title):
    polys, colour = cells_and_colours(read(path))
    lo, hi = polys.reshape(-1, 2).min(axis=0), polys.reshape(-1, 2).max(axis=0)
    aspect = (hi[1] - lo[1]) / (hi[0] - lo[0])
    fig, ax = plt.subplots(figsize=(4.0, max(1.6, 4.0 * aspect) + 0.4))
    ax.add_collection(PolyCollection(polys, facecolors=colour, edgecolors="none"))
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)
    ax.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=72)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--tools", default="build/tools")
    ap.add_argument("--out", default="docs/images")
    ap.add_argument("cases", nargs="*")
    args = ap.parse_args()
    tool = os.path.join(args.tools, "hexadapt-generate")
    listing = subprocess.run([tool, "--list"], check=True, capture_output=True, text=True).stdout
    names = args.cases or [line.split()[0] for line in listing.splitlines()[1:] if line.strip()]
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            vtu = os.path.join(tmp, name + ".vtu")
            cmd = [tool, name, "-o", vtu, "-q"] + OPTIONS.get(name, [])
            subprocess.run(cmd, check=True)
            png = os.path.join(args.out, "generate_" + name + ".png")
            draw(vtu, png, name + " (" + " ".join(OPTIONS.get(name, ["defaults"])) + ")")
            print(png, os.path.getsize(png), "bytes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
