#!/usr/bin/python3
# Copyright (c) 2026 The DGG-VTP for CGAL authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Rebuild terrain_jacksboro.ply (138,632 vertices, 275,772 faces) from matplotlib's sample DEM.

The input is `mpl-data/sample_data/jacksboro_fault_dem.npz` of the Debian package
`python-matplotlib-data` (/usr/share/matplotlib/mpl-data/sample_data/, or the same file in a pip
install of matplotlib: matplotlib/mpl-data/sample_data/): a DEM of 344 x 403 samples (int16
elevation in metres, 3 arc-second spacing dx = dy = 1/1200 degree). Licence of the data: the
matplotlib licence (PSF-based, BSD-compatible), per Debian's copyright file.

Construction (the team's terrain_jacksboro.ply, byte for byte):
  - every grid sample (row i, column j) is a vertex, rows first (vertex i * 403 + j);
  - x = j dx, y = -i dy, in metres: degrees times pi/180 times a spherical Earth of radius
    R = 6,371,008.8 m (the IUGG mean radius), x also times cos of the middle latitude
    (ymin + ymax) / 2 of the npz; row 0 (the npz's ymin) at y = 0, the rows going south;
    x and y rounded to the millimetre (y = +0.0 on row 0, not -0.0), then stored as float;
  - z = the elevation in metres;
  - each cell (a = i * 403 + j, b = a + 1, c = a + 403, d = a + 404) split along the diagonal a-d
    into (a, d, b) and (a, c, d), normals up (+z): first (a, d, b) for every cell (rows first),
    then (a, c, d) for every cell;
  - binary little-endian PLY, `float x y z`, `list uchar int vertex_indices`.

usage: make_terrain_jacksboro.py [OUT.ply] [--npz FILE]
  OUT.ply  default: ${TMPDIR:-/tmp}/terrain_jacksboro.ply (generated; keep it out of git)
"""
import argparse
import math
import os
import sys

import numpy as np

EARTH_RADIUS_M = 6371008.8   # IUGG mean Earth radius
NPZ_PLACES = (
    '/usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz',   # Debian python-matplotlib-data
)


def find_npz():
    for p in NPZ_PLACES:
        if os.path.isfile(p):
            return p
    try:  # a pip install of matplotlib ships the same file
        import matplotlib
        p = os.path.join(matplotlib.get_data_path(), 'sample_data', 'jacksboro_fault_dem.npz')
        if os.path.isfile(p):
            return p
    except ImportError:
        pass
    return None


def build(npz):
    d = np.load(npz)
    elev = d['elevation']
    ny, nx = elev.shape
    dx, dy = float(d['dx']), float(d['dy'])
    lat0 = 0.5 * (float(d['ymin']) + float(d['ymax']))
    c = math.cos(math.radians(lat0))
    x = np.round(np.arange(nx, dtype=np.float64) * dx * math.pi / 180.0 * EARTH_RADIUS_M * c, 3)
    y = 0.0 - np.round(np.arange(ny, dtype=np.float64) * dy * math.pi / 180.0 * EARTH_RADIUS_M, 3)  # +0.0 on row 0
    v = np.empty((ny, nx, 3), dtype='<f4')
    v[:, :, 0] = x[None, :]
    v[:, :, 1] = y[:, None]
    v[:, :, 2] = elev.astype(np.float64)
    a = (np.arange(ny - 1)[:, None] * nx + np.arange(nx - 1)[None, :]).ravel()
    b, cc, dd = a + 1, a + nx, a + nx + 1
    tris = np.concatenate([np.stack([a, dd, b], axis=1), np.stack([a, cc, dd], axis=1)])
    f = np.empty(len(tris), dtype=[('n', 'u1'), ('i', '<i4', (3,))])
    f['n'] = 3
    f['i'] = tris
    return v.reshape(-1, 3), f


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('out', nargs='?',
                    default=os.path.join(os.environ.get('TMPDIR', '/tmp'), 'terrain_jacksboro.ply'),
                    help='output PLY (default: ${TMPDIR:-/tmp}/terrain_jacksboro.ply)')
    ap.add_argument('--npz', help='jacksboro_fault_dem.npz (default: found in python-matplotlib-data '
                                  'or matplotlib\'s data path)')
    args = ap.parse_args()
    npz = args.npz or find_npz()
    if not npz or not os.path.isfile(npz):
        sys.exit('error: jacksboro_fault_dem.npz not found: install python-matplotlib-data '
                 '(Debian) or matplotlib (pip), or pass --npz FILE')
    v, f = build(npz)
    header = ('ply\nformat binary_little_endian 1.0\n'
              'element vertex %d\nproperty float x\nproperty float y\nproperty float z\n'
              'element face %d\nproperty list uchar int vertex_indices\nend_header\n' % (len(v), len(f)))
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    tmp = args.out + '.tmp'
    with open(tmp, 'wb') as fh:
        fh.write(header.encode('ascii'))
        fh.write(v.tobytes())
        fh.write(f.tobytes())
    os.replace(tmp, args.out)
    print('%s: %d vertices, %d faces (from %s)' % (args.out, len(v), len(f), npz))


if __name__ == '__main__':
    main()
