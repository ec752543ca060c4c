#!/usr/bin/python3
"""A picture of a mesh's geodesic distance field and its isolines, as dggvtp writes them.

Runs dggvtp once for the field as PLY (--output FIELD.ply) and the isolines as OBJ
(--isolines K --isolines-output), then draws the mesh shaded and coloured by the distance (the
PLY's `quality`, clamped where unreached), the isolines over it in black, and the source in red.
Needs matplotlib and NumPy (Debian's /usr/bin/python3).

Example (from the repository root, after building dggvtp in build/):
  /usr/bin/python3 benchmark/DGG_VTP_3/isolines_figure.py data/meshes/bunny.ply --out bunny_isolines.png
"""
import argparse
import os
import struct
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def read_field_ply(path):
    """dggvtp's field PLY: points (n, 3), quality (n,), triangles (m, 3)."""
    data = open(path, 'rb').read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    header = data[:end].decode('ascii').split('\n')
    n = int(next(line for line in header if line.startswith('element vertex')).split()[2])
    m = int(next(line for line in header if line.startswith('element face')).split()[2])
    labels = 'property int label' in header
    vertex = np.dtype([('x', '<f4'), ('y', '<f4'), ('z', '<f4'), ('quality', '<f4'), ('distance', '<f8')] +
                      ([('label', '<i4')] if labels else []))
    v = np.frombuffer(data, dtype=vertex, count=n, offset=end)
    offset = end + n * vertex.itemsize
    faces = []
    for _ in range(m):
        k = data[offset]
        faces.append(struct.unpack_from('<%di' % k, data, offset + 1))
        offset += 1 + 4 * k
    triangles = [(f[0], f[i], f[i + 1]) for f in faces for i in range(1, len(f) - 1)]
    return np.stack([v['x'], v['y'], v['z']], axis=1).astype(float), v['quality'].astype(float), np.array(triangles)


def read_isolines_obj(path):
    """the polylines of dggvtp's isolines OBJ, each an (k, 3) array."""
    points, lines = [], []
    for line in open(path):
        words = line.split()
        if words and words[0] == 'v':
            points.append([float(x) for x in words[1:4]])
        elif words and words[0] == 'l':
            lines.append([int(i) - 1 for i in words[1:]])
    points = np.array(points)
    return [points[indices] for indices in lines]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('mesh')
    parser.add_argument('--dggvtp', default=os.path.join('build', 'bin', 'dggvtp'))
    parser.add_argument('--source', type=int, default=0)
    parser.add_argument('--isolines', type=int, default=20)
    parser.add_argument('--elevation', type=float, default=15.)
    parser.add_argument('--azimuth', type=float, default=-80.)
    parser.add_argument('--out', default='isolines.png')
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as work:
        field, isolines = os.path.join(work, 'field.ply'), os.path.join(work, 'isolines.obj')
        subprocess.run([args.dggvtp, args.mesh, '--quiet', '--source', str(args.source), '--output', field,
                        '--isolines', str(args.isolines), '--isolines-output', isolines], check=True)
        points, quality, triangles = read_field_ply(field)
        polylines = read_isolines_obj(isolines)

    # y up in most scanned models (bunny): the view's up is the file's y. An orthographic view drawn
    # by the painter's algorithm in 2D: the triangles and the isolines' segments (thin quads, a
    # little in front of the surface they lie on) in one collection, from the farthest to the nearest,
    # so that the surface hides the isolines behind it.
    e, a = np.radians(args.elevation), np.radians(args.azimuth)
    toward = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    right = np.array([-np.sin(a), np.cos(a), 0.])
    up = np.cross(toward, right)
    def project(p):
        q = p[..., [0, 2, 1]]
        return np.stack([q @ right, q @ up], axis=-1), q @ toward

    screen, depth = project(points)
    size = np.ptp(screen, axis=0).max()
    corners = screen[triangles]
    normals = np.cross(points[triangles[:, 1]] - points[triangles[:, 0]], points[triangles[:, 2]] - points[triangles[:, 0]])
    normals = normals[:, [0, 2, 1]] / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    shade = 0.3 + 0.7 * np.abs(normals @ toward)
    colours = plt.get_cmap('viridis')(quality[triangles].mean(axis=1) / max(quality.max(), 1e-300))
    colours[:, :3] *= shade[:, None]
    polygons = list(corners)
    depths = list(depth[triangles].mean(axis=1))
    colour_list = list(colours)
    width, lift = 0.0025 * size, 0.004 * size
    for polyline in polylines:
        s, d = project(polyline)
        for k in range(len(s) - 1):
            step = s[k + 1] - s[k]
            normal = np.array([-step[1], step[0]]) / max(np.linalg.norm(step), 1e-300) * width / 2
            polygons.append(np.array([s[k] - normal, s[k + 1] - normal, s[k + 1] + normal, s[k] + normal]))
            depths.append(max(d[k], d[k + 1]) + lift)
            colour_list.append((0., 0., 0., 1.))
    source = screen[args.source]
    r = 0.012 * size
    polygons.append(source + r * np.array([[1, 0], [0, 1], [-1, 0], [0, -1]]))
    depths.append(depth[args.source] + lift)
    colour_list.append((1., 0., 0., 1.))
    order = np.argsort(depths)

    figure, axes = plt.subplots(figsize=(8, 8))
    axes.add_collection(PolyCollection([polygons[i] for i in order], facecolors=[colour_list[i] for i in order],
                                       edgecolors='none'))
    axes.set_xlim(screen[:, 0].min(), screen[:, 0].max())
    axes.set_ylim(screen[:, 1].min(), screen[:, 1].max())
    axes.set_aspect('equal')
    axes.set_axis_off()
    axes.set_title('%s: %d isolines of the geodesic distance from vertex %d (red), %d pieces'
                   % (os.path.basename(args.mesh), args.isolines, args.source, len(polylines)))
    figure.savefig(args.out, dpi=120, bbox_inches='tight')
    print('wrote', args.out)


if __name__ == '__main__':
    sys.exit(main())
