"""Fins glued on a mesh: a scan with loose flaps. On every k-th edge (a, b) a third triangle (a, b,
apex), its apex above the edge's midpoint, half the edge's length away along the normal of a face
of the edge. The result is a soup with non-manifold edges, which loaders split into sheets with
copies of the edges' ends; on a mesh of several patches, copies land in other patches than the
vertices they copy (the case of threads on meshes with copies).

usage: glue_fins.py MESH.ply COUNT OUT.off   (a binary PLY of float x, y, z and triangles, as the
bundled meshes are)"""
import sys

import numpy as np


def read_ply(path):
    """V (n x 3 float64) and F (m x 3 int) of a binary little-endian PLY of float x, y, z and
    uchar-counted int triangles"""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    counts = {}
    for line in data[:end].decode("ascii").splitlines():
        words = line.split()
        if words[:1] == ["element"]:
            counts[words[1]] = int(words[2])
    nv, nf = counts["vertex"], counts["face"]
    V = np.frombuffer(data, "<f4", 3 * nv, end).reshape(nv, 3).astype(np.float64)
    F = np.frombuffer(data, np.dtype([("n", "u1"), ("v", "<i4", 3)]), nf, end + 12 * nv)["v"].astype(np.int64)
    return V, F


def glue_fins(V, F, count):
    """V and F with `count` fins on edges spread over the mesh (their apexes appended to V)"""
    V, F = np.asarray(V, np.float64), np.asarray(F, np.int64)
    ends = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    face = np.tile(np.arange(len(F)), 3)
    edges, first = np.unique(ends, axis=0, return_index=True)
    chosen = np.linspace(0, len(edges) - 1, count).astype(np.int64)
    a, b = V[edges[chosen, 0]], V[edges[chosen, 1]]
    t = F[face[first[chosen]]]
    n = np.cross(V[t[:, 1]] - V[t[:, 0]], V[t[:, 2]] - V[t[:, 0]])
    apex = (a + b) / 2 + n * (np.linalg.norm(b - a, axis=1) / np.linalg.norm(n, axis=1) / 2)[:, None]
    fins = np.column_stack([edges[chosen], len(V) + np.arange(count)])
    return np.vstack([V, apex]), np.vstack([F, fins])


def write_off(path, V, F):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(V)} {len(F)} 0\n")
        np.savetxt(out, V, "%.17g")
        np.savetxt(out, np.column_stack([np.full(len(F), 3), F]), "%d")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    write_off(sys.argv[3], *glue_fins(*read_ply(sys.argv[1]), int(sys.argv[2])))
