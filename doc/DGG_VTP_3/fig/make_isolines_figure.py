"""Makes the manual's figure bunny_isolines.png: the exact geodesic distance from vertex 0 of the
bundled bunny, as colours and isolines, seen from the front. The distances come from dggvtp.

usage (Debian's interpreter, with NumPy and Matplotlib), from the repository's root:
  cmake --build build --target dggvtp
  /usr/bin/python3 doc/DGG_VTP_3/fig/make_isolines_figure.py build/bin/dggvtp
"""
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
MESH = os.path.join(HERE, "..", "..", "..", "data", "meshes", "bunny.ply")


def read_binary_ply(path):
    """Points (float x, y, z) and triangles (uchar count, int indices) of a binary little-endian PLY."""
    with open(path, "rb") as f:
        header = []
        while not header or header[-1] != "end_header":
            header.append(f.readline().decode("ascii").strip())
        nv = int(next(line.split()[2] for line in header if line.startswith("element vertex")))
        nf = int(next(line.split()[2] for line in header if line.startswith("element face")))
        points = np.frombuffer(f.read(12 * nv), dtype="<f4").reshape(nv, 3).astype(float)
        faces = np.frombuffer(f.read(13 * nf), dtype=np.dtype([("n", "u1"), ("v", "<i4", 3)]))
    assert (faces["n"] == 3).all(), "triangles only"
    return points, faces["v"].astype(int)


def main():
    dggvtp = sys.argv[1]
    points, triangles = read_binary_ply(MESH)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "d.npy")
        subprocess.run([dggvtp, MESH, "--source", "0", "--output", out, "--output-format", "npy", "--quiet"],
                       check=True)
        distance = np.load(out)

    # front view (looking down -z), faces turned towards the viewer only, so that the back of the
    # bunny does not show through
    a, b, c = (points[triangles[:, k]] for k in range(3))
    front = np.cross(b - a, c - a)[:, 2] > 0
    triangulation = Triangulation(points[:, 0], points[:, 1], triangles[front])
    levels = np.linspace(0, distance.max(), 21)

    fig, ax = plt.subplots(figsize=(4.2, 4.2), dpi=100)
    ax.tripcolor(triangulation, distance, shading="gouraud", cmap="viridis")
    ax.tricontour(triangulation, distance, levels=levels, colors="white", linewidths=0.6)
    ax.plot(*points[0, :2], "o", color="red", markersize=5)
    ax.set_aspect("equal")
    ax.axis("off")
    fig.tight_layout(pad=0)
    fig.savefig(os.path.join(HERE, "bunny_isolines.png"))


if __name__ == "__main__":
    main()
