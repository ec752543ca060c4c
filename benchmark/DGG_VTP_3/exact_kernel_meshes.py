#!/usr/bin/env python3
# Small meshes for `cross_validate --exact-kernel` (benchmark README, "Exact kernel"): what CGAL's
# exact kernel with square roots costs as the faces and the distinct edge lengths grow.
#   python3 exact_kernel_meshes.py DIR     writes DIR/<name>.off, one per mesh below
import os
import random
import sys


def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        for p in points:
            f.write(" ".join(repr(float(c)) for c in p) + "\n")
        for t in faces:
            f.write("3 " + " ".join(str(i) for i in t) + "\n")


def grid(n, jitter, seed):
    """(n+1) x (n+1) points of the unit-spaced grid in z = 0, interior points jittered by up to
    `jitter`, random diagonals"""
    rng = random.Random(seed)
    points = []
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = float(i), float(j)
            if 0 < i < n:
                x += rng.uniform(-jitter, jitter)
            if 0 < j < n:
                y += rng.uniform(-jitter, jitter)
            points.append((x, y, 0.0))
    faces = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            faces += [(a, b, c), (a, c, d)] if rng.random() < 0.5 else [(a, b, d), (b, c, d)]
    return points, faces


def tetrahedron(levels):
    """the regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1), each face cut in 4 `levels` times"""
    points = [(1.0, 1.0, 1.0), (1.0, -1.0, -1.0), (-1.0, 1.0, -1.0), (-1.0, -1.0, 1.0)]
    faces = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
    for _ in range(levels):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(points)
                points.append(tuple((p + q) / 2 for p, q in zip(points[a], points[b])))
            return middle[key]

        cut = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            cut += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = cut
    return points, faces


def square_prism(per_side, rings, seed):
    """the lateral surface of the unit square prism, `per_side` segments per side, `rings` rings"""
    rng = random.Random(seed)
    corners = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)]
    ring = []
    for s in range(4):
        for k in range(per_side):
            t = k / per_side
            ring.append((corners[s][0] + t * (corners[s + 1][0] - corners[s][0]),
                         corners[s][1] + t * (corners[s + 1][1] - corners[s][1])))
    m = len(ring)
    points = [(x, y, float(h)) for h in range(rings) for x, y in ring]
    faces = []
    for h in range(rings - 1):
        for k in range(m):
            a, b = h * m + k, h * m + (k + 1) % m
            c, d = b + m, a + m
            faces += [(a, b, c), (a, c, d)] if rng.random() < 0.5 else [(a, b, d), (b, c, d)]
    return points, faces


MESHES = {
    "grid_3x3": grid(3, 0.0, 1),
    "grid_4x4": grid(4, 0.0, 1),
    "grid_6x6": grid(6, 0.0, 1),
    "grid_3x3_jittered": grid(3, 0.1, 1),
    "grid_4x4_jittered": grid(4, 0.1, 1),
    "tetrahedron": tetrahedron(0),
    "tetrahedron_16": tetrahedron(1),
    "tetrahedron_64": tetrahedron(2),
    "right_tetrahedron": ([(0.0, 0.0, 0.0), (3.0, 0.0, 0.0), (0.0, 4.0, 0.0), (0.0, 0.0, 12.0)],
                          [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]),
    "square_prism_32": square_prism(2, 3, 1),
    "square_prism_64": square_prism(4, 3, 1),
}

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    for name, (points, faces) in MESHES.items():
        write_off(os.path.join(out, name + ".off"), points, faces)
        print(f"{name}: {len(points)} vertices, {len(faces)} faces")
