"""Geodesic distances on the bunny from one vertex, drawn with matplotlib: the mesh seen from the
front (an orthographic projection onto the x-y plane, the triangles that face the viewer), coloured
by the distance, with isolines. Writes a PNG.

usage: python3 distance_field.py [MESH] [OUTPUT.png]   (default: data/meshes/bunny.ply, distance_field.png)
Needs the package (PYTHONPATH=build/python, or installed as the README says) and python3-matplotlib."""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np

import dggvtp

root = pathlib.Path(__file__).resolve().parents[2]
mesh = sys.argv[1] if len(sys.argv) > 1 else root / "data" / "meshes" / "bunny.ply"
output = sys.argv[2] if len(sys.argv) > 2 else "distance_field.png"

V, F = dggvtp.read_mesh(mesh)
solver = dggvtp.GeodesicSolver(V, F)
source = int(np.argmax(V[:, 1]))                  # the top of the mesh (the bunny's ear tip)
d = solver.distances(source, epsilon=1e-4)
assert np.all(np.isfinite(d)), "the mesh is in one piece"

# only the triangles facing the viewer (looking down -z), in painter's order: the farthest (smallest
# mean z) first, so that nearer ones cover them
normal_z = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])[:, 2]
front = F[normal_z > 0]
triangulation = mtri.Triangulation(V[:, 0], V[:, 1], front[np.argsort(V[front].mean(axis=1)[:, 2])])
figure, axes = plt.subplots(figsize=(7, 6.5))
field = axes.tripcolor(triangulation, d, shading="gouraud", cmap="viridis")
levels = np.linspace(0, d.max(), 12)[1:-1]
axes.tricontour(triangulation, d, levels=levels, colors="white", linewidths=0.6)
axes.plot(V[source, 0], V[source, 1], "r*", markersize=14, label=f"source (vertex {source})")
axes.set_aspect("equal")
axes.margins(0.04)
axes.set_axis_off()
axes.legend(loc="lower right")
figure.colorbar(field, ax=axes, shrink=0.8, label="geodesic distance")
axes.set_title(f"{pathlib.Path(mesh).name}: geodesic distance (DGG-VTP, epsilon 1e-4)")
figure.savefig(output, dpi=120, bbox_inches="tight")
print(f"{output}: {len(V)} vertices, farthest at {d.max():.4g}")
