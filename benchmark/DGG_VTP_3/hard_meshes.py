#!/usr/bin/env python3
"""Meshes made on purpose for the adversary (issue 35): where DGG-VTP's pruning rules may go wrong.

Deterministic: every mesh comes from its own random stream (--seed, default 35, and the mesh's
name), and the same seed gives the same bytes with the same NumPy and SciPy (binary little-endian
PLY, float x y z as the shared meshes, so that the double and the float computations see the same
surface; int vertex indices). Flat faces are triangulated as CAD exporters do, with few or no inner
points: SciPy's Delaunay of the boundary points, the boundary segments split until each is an edge
(a conforming triangulation), the triangles outside the region dropped. The meshes:

  coupling        a short thick tube on a flange pierced by bolt holes (closed, genus 9): flat faces
                  meeting at sharp edges, long thin triangles on the flat faces and along the walls
  bushing         a short thick tube, finely segmented, one band of long thin triangles per wall
                  (closed, genus 1): paths around it nearly tie all the way
  holey_block     a block pierced by a grid of round holes of jittered sizes (closed, genus 35)
  terrain_ridged  a height field of ridged fractal noise (creases along the ridges), open
  terrain_cliffs  the same relief in terraces: near-vertical cliffs between flat steps, open
  jittered_grid   a grid with jittered x, y and random heights (a saddle or cone at every vertex)
  folded_sheet    a sheet folded sharply 12 times, the folds' height varying along them (not
                  developable), open
  saddle_obtuse   a smooth saddle z = x^2 - y^2 on staggered rows 8 times closer than the points
                  of a row: every triangle obtuse (apex angle about 152 degrees), anisotropic
  cone_spikes     a plate with spikes whose tips have angle sums from 2e-4 to 0.1 radians (the
                  loader refuses tips sharper than 1e-4), open

--small writes a few-hundred-vertex version of coupling, bushing, holey_block, terrain_ridged and
cone_spikes (the CTest of the adversary generates them in the build tree). With --check (the
default when --build holds bin/dggvtp) every file is run through `dggvtp MESH` (exact, source 0),
which must accept it without any warning: manifold, oriented, no degenerate face, no sliver, one
component.

Example (from the repository root):
  /usr/bin/python3 benchmark/DGG_VTP_3/hard_meshes.py /tmp/hard_meshes            # all, checked
  /usr/bin/python3 benchmark/DGG_VTP_3/hard_meshes.py /tmp/hard_small --small
"""
import argparse
import os
import subprocess
import sys
import zlib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))


class Failure(Exception):
    """A mesh that came out wrong, or a check that failed: `error: ...`, exit status 2."""


# ---------------------------------------------------------------------------------------------
# building blocks
# ---------------------------------------------------------------------------------------------

class Mesh:
    """Points and triangles being assembled; rings of points are numbered once per (loop, level)."""

    def __init__(self):
        self.points = []    # (k, 3) arrays
        self.faces = []     # (m, 3) arrays of indices
        self.count = 0      # points so far
        self.rings = {}     # (loop id, z) -> indices of that loop's points at height z

    def add_points(self, points):
        """Appends points (k, 3); their indices."""
        points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        self.points.append(points)
        self.count += len(points)
        return np.arange(self.count - len(points), self.count)

    def add_faces(self, faces):
        self.faces.append(np.asarray(faces, dtype=np.int64).reshape(-1, 3))

    def ring(self, loop_id, loop, z):
        """The indices of a 2-D loop's points lifted to height z (made at the first call)."""
        key = (loop_id, float(z))
        if key not in self.rings:
            self.rings[key] = self.add_points(np.column_stack([loop, np.full(len(loop), z)]))
        return self.rings[key]

    def arrays(self):
        return np.concatenate(self.points), np.concatenate(self.faces)


def circle(center, radius, count, phase=0.):
    """count points on a circle, counterclockwise."""
    t = phase + 2 * np.pi * np.arange(count) / count
    return np.column_stack([center[0] + radius * np.cos(t), center[1] + radius * np.sin(t)])


def rectangle(x0, y0, x1, y1, nx, ny):
    """The boundary of a rectangle, counterclockwise, nx and ny segments along x and y."""
    bottom = np.column_stack([np.linspace(x0, x1, nx + 1)[:-1], np.full(nx, y0)])
    right = np.column_stack([np.full(ny, x1), np.linspace(y0, y1, ny + 1)[:-1]])
    top = np.column_stack([np.linspace(x1, x0, nx + 1)[:-1], np.full(nx, y1)])
    left = np.column_stack([np.full(ny, x0), np.linspace(y1, y0, ny + 1)[:-1]])
    return np.concatenate([bottom, right, top, left])


def inside(points, loops):
    """Whether each 2-D point is inside the region the loops bound (even-odd rule)."""
    x, y = points[:, 0:1], points[:, 1:2]
    odd = np.zeros(len(points), dtype=bool)
    for loop in loops:
        a, b = loop, np.roll(loop, -1, axis=0)
        crosses = (a[:, 1] > y) != (b[:, 1] > y)
        with np.errstate(divide='ignore', invalid='ignore'):
            x_cross = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
        odd ^= (np.count_nonzero(crosses & (x < x_cross), axis=1) % 2).astype(bool)
    return odd


def triangulate_regions(loops, regions, inner=None):
    """Conforming triangulations of planar regions that share boundary loops.

    loops: 2-D closed polylines (k, 2); regions: per region, the ids of its loops; inner: per
    region, points inside it (or None). Segments of the loops are split at their midpoints (in
    every region, as the loops are shared) until every segment is an edge of the Delaunay
    triangulation of each region's points; the triangles whose centroid is outside the region are
    dropped. Returns the refined loops and per region (points, counterclockwise triangles), the
    points being the region's loops in order, then its inner points.
    """
    from scipy.spatial import Delaunay
    loops = [np.asarray(loop, dtype=np.float64) for loop in loops]
    inner = inner or [None] * len(regions)
    for _ in range(60):
        split = [set() for _ in loops]
        results = []
        for ids, extra in zip(regions, inner):
            parts = [loops[i] for i in ids] + ([extra] if extra is not None and len(extra) else [])
            points = np.concatenate(parts)
            simplices = Delaunay(points).simplices
            edges = set(map(tuple, np.sort(np.concatenate([simplices[:, [0, 1]], simplices[:, [1, 2]],
                                                            simplices[:, [2, 0]]]), axis=1).tolist()))
            offset = 0
            for i in ids:
                n = len(loops[i])
                for k in range(n):
                    a, b = offset + k, offset + (k + 1) % n
                    if (min(a, b), max(a, b)) not in edges:
                        split[i].add(k)
                offset += n
            results.append((points, simplices))
        if not any(split):
            break
        for i, ks in enumerate(split):
            if ks:
                loop = loops[i]
                mid = 0.5 * (loop + np.roll(loop, -1, axis=0))
                out = []
                for k in range(len(loop)):
                    out.append(loop[k])
                    if k in ks:
                        out.append(mid[k])
                loops[i] = np.array(out)
    else:
        raise Failure('the boundary segments did not become Delaunay edges in 60 rounds of splitting')
    triangulated = []
    for (points, simplices), ids in zip(results, regions):
        kept = simplices[inside(points[simplices].mean(axis=1), [loops[i] for i in ids])]
        p = points[kept]
        area = (p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1])
        kept[area < 0] = kept[area < 0][:, [0, 2, 1]]
        triangulated.append((points, kept))
    return loops, triangulated


def add_flat_face(mesh, loops, loop_ids, points, triangles, z, up):
    """A triangulated planar region at height z, facing +z (up) or -z; its loops' rings shared."""
    index = [mesh.ring(i, loops[i], z) for i in loop_ids]
    rest = len(points) - sum(len(loops[i]) for i in loop_ids)
    if rest:
        index.append(mesh.add_points(np.column_stack([points[-rest:], np.full(rest, z)])))
    index = np.concatenate(index)
    mesh.add_faces(index[triangles if up else triangles[:, ::-1]])


def add_wall(mesh, lower, upper, material_inside, layers=1):
    """The wall between two rings (same loop, counterclockwise seen from +z) in `layers` bands,
    facing away from the material: outward where the material is inside the loop (an outer wall),
    inward for a hole."""
    p = np.concatenate(mesh.points)
    rings = [lower]
    for k in range(1, layers):
        t = k / layers
        rings.append(mesh.add_points((1 - t) * p[lower] + t * p[upper]))
    rings.append(upper)
    for a, b in zip(rings[:-1], rings[1:]):
        a1, b1 = np.roll(a, -1), np.roll(b, -1)
        quads = np.column_stack([a, a1, b1, b]) if material_inside else np.column_stack([a1, a, b, b1])
        mesh.add_faces(np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]]))


def grid_faces(nx, ny, diagonal=None):
    """Triangles of an nx x ny grid of points (row-major, x fastest), counterclockwise; diagonal:
    per cell True to split along (0,0)-(1,1) (default all)."""
    i, j = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1))
    a = (j * nx + i).ravel()
    b, c, d = a + 1, a + nx + 1, a + nx
    main = np.ones(len(a), dtype=bool) if diagonal is None else np.asarray(diagonal).ravel()
    t1 = np.where(main[:, None], np.column_stack([a, b, c]), np.column_stack([a, b, d]))
    t2 = np.where(main[:, None], np.column_stack([a, c, d]), np.column_stack([b, c, d]))
    return np.concatenate([t1, t2])


def value_noise(rng, x, y, cells):
    """Smooth random values in [0, 1] over the unit square, `cells` lattice cells across."""
    lattice = rng.random((cells + 2, cells + 2))
    fx, fy = x * cells, y * cells
    ix, iy = np.floor(fx).astype(int), np.floor(fy).astype(int)
    tx, ty = fx - ix, fy - iy
    sx, sy = tx ** 3 * (tx * (6 * tx - 15) + 10), ty ** 3 * (ty * (6 * ty - 15) + 10)
    v00, v10 = lattice[iy, ix], lattice[iy, ix + 1]
    v01, v11 = lattice[iy + 1, ix], lattice[iy + 1, ix + 1]
    return (v00 * (1 - sx) + v10 * sx) * (1 - sy) + (v01 * (1 - sx) + v11 * sx) * sy


def ridged_noise(rng, x, y, octaves=5, cells=3):
    """Ridged multifractal noise in [0, ~1]: sharp crests where a noise octave crosses its middle."""
    height, weight, amplitude, total = 0., 1., 1., 0.
    for _ in range(octaves):
        ridge = (1 - np.abs(2 * value_noise(rng, x, y, cells) - 1)) ** 2 * weight
        weight = np.clip(2 * ridge, 0, 1)
        height = height + amplitude * ridge
        total += amplitude
        amplitude *= 0.5
        cells *= 2
    return height / total


# ---------------------------------------------------------------------------------------------
# the meshes
# ---------------------------------------------------------------------------------------------

def coupling(rng, scale):
    """Flange (outer radius 1, thickness 0.25) with 8 bolt holes, a hub (radius 0.55, height 0.6)
    and a bore (radius 0.35) through both."""
    n = lambda k: max(8, int(round(k * scale)))  # noqa: E731
    r_bore, r_hub, r_out, r_bolt, hole = 0.35, 0.55, 1.0, 0.78, 0.09
    thickness, height = 0.25, 0.85
    loops = [circle((0, 0), r_out, n(160)), circle((0, 0), r_hub, n(96), 0.013),
             circle((0, 0), r_bore, n(96), 0.021)]
    bolts = []
    for k in range(8):
        t = 2 * np.pi * (k + 0.5) / 8
        bolts.append(len(loops))
        loops.append(circle((r_bolt * np.cos(t), r_bolt * np.sin(t)), hole * (1 + 0.1 * rng.random()), n(40),
                            rng.random()))
    flange_top, flange_bottom, hub_top = [0, 1] + bolts, [0, 2] + bolts, [1, 2]
    loops, (top, bottom, cap) = triangulate_regions(loops, [flange_top, flange_bottom, hub_top])
    mesh = Mesh()
    add_flat_face(mesh, loops, flange_top, *top, thickness, True)
    add_flat_face(mesh, loops, flange_bottom, *bottom, 0., False)
    add_flat_face(mesh, loops, hub_top, *cap, thickness + height, True)
    add_wall(mesh, mesh.ring(0, loops[0], 0.), mesh.ring(0, loops[0], thickness), True)
    add_wall(mesh, mesh.ring(1, loops[1], thickness), mesh.ring(1, loops[1], thickness + height), True, 3)
    add_wall(mesh, mesh.ring(2, loops[2], 0.), mesh.ring(2, loops[2], thickness + height), False, 4)
    for b in bolts:
        add_wall(mesh, mesh.ring(b, loops[b], 0.), mesh.ring(b, loops[b], thickness), False)
    return mesh.arrays()


def bushing(rng, scale):
    """A short thick tube: radii 1 and 0.6, height 0.3 (0.2 with --small), 400 and 320 segments
    (160 and 128), each wall one band of long thin triangles, the rims' annuli without inner points."""
    n_out, n_in, height = (400, 320, 0.3) if scale >= 1 else (160, 128, 0.2)
    loops, ((points, triangles),) = triangulate_regions([circle((0, 0), 1., n_out),
                                                         circle((0, 0), 0.6, n_in, 0.01)], [[0, 1]])
    mesh = Mesh()
    add_flat_face(mesh, loops, [0, 1], points, triangles, height, True)
    add_flat_face(mesh, loops, [0, 1], points, triangles, 0., False)
    add_wall(mesh, mesh.ring(0, loops[0], 0.), mesh.ring(0, loops[0], height), True)
    add_wall(mesh, mesh.ring(1, loops[1], 0.), mesh.ring(1, loops[1], height), False)
    return mesh.arrays()


def holey_block(rng, scale):
    """A 3 x 2 x 0.3 block pierced by a 7 x 5 grid of round holes of jittered radius and place."""
    nx, ny = (7, 5) if scale >= 1 else (4, 3)
    width, depth, thickness = 3.0, 2.0, 0.3
    per_hole = max(8, int(round(24 * scale)))
    loops = [rectangle(0, 0, width, depth, 3 * nx, 3 * ny)]
    pitch_x, pitch_y = width / nx, depth / ny
    for j in range(ny):
        for i in range(nx):
            c = ((i + 0.5 + 0.12 * (rng.random() - 0.5)) * pitch_x, (j + 0.5 + 0.12 * (rng.random() - 0.5)) * pitch_y)
            loops.append(circle(c, (0.22 + 0.12 * rng.random()) * min(pitch_x, pitch_y), per_hole, rng.random()))
    ids = list(range(len(loops)))
    loops, ((points, triangles),) = triangulate_regions(loops, [ids])
    mesh = Mesh()
    add_flat_face(mesh, loops, ids, points, triangles, thickness, True)
    add_flat_face(mesh, loops, ids, points, triangles, 0., False)
    add_wall(mesh, mesh.ring(0, loops[0], 0.), mesh.ring(0, loops[0], thickness), True)
    for i in ids[1:]:
        add_wall(mesh, mesh.ring(i, loops[i], 0.), mesh.ring(i, loops[i], thickness), False)
    return mesh.arrays()


def terrain(rng, scale, terraces=0):
    """A height field over the unit square, ridged noise 0.35 high; terraces > 0: that many
    steps with steep risers."""
    n = max(12, int(round(56 * scale)))
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    h = ridged_noise(rng, x, y)
    if terraces:
        steps = h * terraces
        base = np.floor(steps)
        h = (base + np.clip((steps - base - 0.75) / 0.25, 0, 1) ** 2) / terraces
    points = np.column_stack([x.ravel(), y.ravel(), 0.35 * h.ravel()])
    return points, grid_faces(n, n)


def jittered_grid(rng, scale):
    """A grid with x, y jittered by up to 0.35 of a cell and random heights (0.4 of a cell)."""
    n = max(12, int(round(45 * scale)))
    step = 1. / (n - 1)
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    jitter = (rng.random((2, n, n)) - 0.5) * 0.7 * step
    jitter[:, :, [0, -1]] = 0   # keep the border straight
    jitter[:, [0, -1], :] = 0
    z = (rng.random((n, n)) - 0.5) * 0.4 * step + 0.1 * np.sin(3 * x) * np.cos(2 * y)
    points = np.column_stack([(x + jitter[0]).ravel(), (y + jitter[1]).ravel(), z.ravel()])
    return points, grid_faces(n, n, rng.random((n - 1, n - 1)) < 0.5)


def folded_sheet(rng, scale):
    """12 sharp folds across a 3 x 1 sheet, fold height varying along each fold (0.4 to 1.6 of the
    slope 4 profile), fold lines slightly bent."""
    folds, per_fold = 12, 8
    nx, ny = folds * per_fold + 1, max(6, int(round(25 * scale)))
    x, y = np.meshgrid(np.linspace(0, 3, nx), np.linspace(0, 1, ny))
    period = 3. / folds
    phase = (x / period) % 1
    profile = np.where(phase < 0.5, phase, 1 - phase) * period * 4
    amplitude = 1 + 0.6 * np.sin(2 * np.pi * y + 0.7 * x + rng.random())
    bend = 0.02 * np.sin(np.pi * y) * np.sin(3 * x)
    points = np.column_stack([(x + bend).ravel(), y.ravel(), (profile * amplitude).ravel()])
    return points, grid_faces(nx, ny)


def saddle_obtuse(rng, scale):
    """z = 0.8 (x^2 - y^2) over [-1, 1] x [-0.5, 0.5]: rows 0.01 apart, points 0.08 apart in a
    row, every other row shifted by half: isosceles triangles with a 152-degree apex."""
    nx, ny = max(6, int(round(26 * scale))), max(11, int(round(101 * scale)))
    dx, dy = 2. / (nx - 1), 1. / (ny - 1)
    points, index = [], np.zeros((ny, nx), dtype=np.int64)
    for j in range(ny):
        xs = -1 + dx * np.arange(nx) + (0.5 * dx if j % 2 else 0)
        xs = np.clip(xs, -1, 1)
        if j % 2:   # a shifted row: the first point at -1, the rest shifted, the last clipped away
            xs = np.concatenate([[-1.], xs[:-1]])
        y = -0.5 + j * dy
        index[j] = np.arange(len(points), len(points) + nx)
        points += [(x, y, 0.8 * (x * x - y * y)) for x in xs]
    faces = []
    for j in range(ny - 1):
        lo, hi = index[j], index[j + 1]
        if j % 2 == 0:   # lower row unshifted: triangles (lo i, lo i+1, hi i+1) and (lo i, hi i+1, hi i)
            for i in range(nx - 1):
                faces.append((lo[i], lo[i + 1], hi[i + 1]))
                faces.append((lo[i], hi[i + 1], hi[i]))
        else:            # lower row shifted
            for i in range(nx - 1):
                faces.append((lo[i], lo[i + 1], hi[i]))
                faces.append((lo[i + 1], hi[i + 1], hi[i]))
    return np.array(points), np.array(faces)


def cone_spikes(rng, scale):
    """A 2 x 2 plate (jittered inner points) with spikes 0.6 high whose tips have angle sums
    2e-4, 5e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1 (fewer with --small)."""
    angles = (2e-4, 5e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1) if scale >= 1 else (2e-4, 1e-3, 1e-2)
    height, ring = 0.6, 8
    loops = [rectangle(-1, -1, 1, 1, max(4, int(round(16 * scale))), max(4, int(round(16 * scale))))]
    centers = []
    for k, angle in enumerate(angles):
        t = 2 * np.pi * k / len(angles) + 0.3 * rng.random()
        c = (0.55 * np.cos(t), 0.55 * np.sin(t))
        centers.append(c)
        # tip angle sum = ring * 2 asin(r sin(pi/ring) / slant) ~ 2 pi r / height
        loops.append(circle(c, height * angle / (2 * np.pi), ring, rng.random()))
    n = max(8, int(round(30 * scale)))
    g = np.linspace(-1, 1, n + 1)[1:-1]
    gx, gy = np.meshgrid(g, g)
    inner = np.column_stack([gx.ravel(), gy.ravel()]) + (rng.random((len(g) ** 2, 2)) - 0.5) * (1.0 / n)
    far = np.all([np.hypot(*(inner - c).T) > 1.5 / n for c in centers], axis=0)
    ids = list(range(len(loops)))
    loops, ((points, triangles),) = triangulate_regions(loops, [ids], [inner[far]])
    mesh = Mesh()
    add_flat_face(mesh, loops, ids, points, triangles, 0., True)
    for k, c in enumerate(centers):
        base = mesh.ring(k + 1, loops[k + 1], 0.)
        apex = mesh.add_points([(c[0], c[1], height)])[0]
        mesh.add_faces(np.column_stack([base, np.roll(base, -1), np.full(len(base), apex)]))
    return mesh.arrays()


MESHES = {   # name: (generator, scale of the full set, scale of --small)
    'coupling': (coupling, 1., 0.25),
    'bushing': (bushing, 1., 0.4),
    'holey_block': (holey_block, 1., 0.42),
    'terrain_ridged': (terrain, 1., 0.36),
    'terrain_cliffs': (lambda rng, scale: terrain(rng, scale, terraces=5), 1., None),
    'jittered_grid': (jittered_grid, 1., None),
    'folded_sheet': (folded_sheet, 1., None),
    'saddle_obtuse': (saddle_obtuse, 1., None),
    'cone_spikes': (cone_spikes, 1., 0.4),
}


# ---------------------------------------------------------------------------------------------
# output and checks
# ---------------------------------------------------------------------------------------------

def write_ply(path, points, faces, comment):
    """Binary little-endian PLY: float x y z, list uchar int vertex_indices."""
    header = (f'ply\nformat binary_little_endian 1.0\ncomment {comment}\nelement vertex {len(points)}\n'
              'property float x\nproperty float y\nproperty float z\n'
              f'element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n')
    records = np.zeros(len(faces), dtype=[('n', 'u1'), ('v', '<i4', (3,))])
    records['n'], records['v'] = 3, faces
    with open(path, 'wb') as f:
        f.write(header.encode('ascii'))
        f.write(np.ascontiguousarray(points, dtype='<f4').tobytes())
        f.write(records.tobytes())


def topology(points, faces):
    """(boundary edges, genus or None if open) after checking the mesh is an oriented manifold
    whose points are all used; raises Failure otherwise."""
    if len(np.unique(faces)) != len(points):
        raise Failure('points no face uses')
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    if len({tuple(e) for e in directed.tolist()}) != len(directed):
        raise Failure('an edge used twice in the same direction (non-manifold or inconsistently oriented)')
    undirected = np.sort(directed, axis=1)
    _, counts = np.unique(undirected, axis=0, return_counts=True)
    if counts.max() > 2:
        raise Failure('an edge with more than two faces')
    p = points[faces]
    area = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    if area.min() <= 0:
        raise Failure('a face of zero area')
    border = int(np.count_nonzero(counts == 1))
    euler = len(points) - len(counts) + len(faces)
    return border, (None if border else (2 - euler) // 2)


def check_with_dggvtp(dggvtp, path):
    """dggvtp must read the file and run from vertex 0 without any warning."""
    r = subprocess.run([dggvtp, path, '--output', os.devnull], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True)
    if r.returncode != 0 or r.stderr.strip():
        raise Failure(f'dggvtp {path}: exit status {r.returncode}: {r.stderr.strip() or "no message"}')


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('folder', help='where the .ply files go (made if missing)')
    p.add_argument('--small', action='store_true', help='the few-hundred-vertex set (for the CTest)')
    p.add_argument('--only', nargs='+', metavar='NAME', help='only these meshes (see the list above)')
    p.add_argument('--seed', type=int, default=35, help='the seed (default 35): the same seed, the same bytes')
    p.add_argument('--build', default=os.path.join(REPO, 'build'),
                   help='build directory holding bin/dggvtp, for --check (default: <repo>/build)')
    p.add_argument('--check', choices=['yes', 'no', 'auto'], default='auto',
                   help='run each file through dggvtp (auto: when BUILD/bin/dggvtp exists; yes: required)')
    p.add_argument('--quiet', action='store_true', help='no line per mesh')
    a = p.parse_args()
    try:
        dggvtp = os.path.join(a.build, 'bin', 'dggvtp')
        check = a.check == 'yes' or (a.check == 'auto' and os.access(dggvtp, os.X_OK))
        if check and not os.access(dggvtp, os.X_OK):
            raise Failure(f'--check yes: {dggvtp} is not an executable (build the target dggvtp, or pass --build)')
        names = [n for n, (_, full, small) in MESHES.items() if (small if a.small else full) is not None]
        if a.only:
            unknown = sorted(set(a.only) - set(names))
            if unknown:
                raise Failure(f"unknown mesh {', '.join(unknown)} (the {'small ' if a.small else ''}set: "
                              f"{', '.join(names)})")
            names = [n for n in names if n in a.only]
        os.makedirs(a.folder, exist_ok=True)
        for name in names:
            make, full, small = MESHES[name]
            scale = small if a.small else full
            # one stream per mesh, from its name: a mesh does not change when another one does
            rng = np.random.default_rng([a.seed, zlib.crc32(name.encode())])
            points, faces = make(rng, scale)
            points = points.astype(np.float32).astype(np.float64)   # what the file holds
            border, genus = topology(points, faces)
            suffix = '_small' if a.small else ''
            path = os.path.join(a.folder, f'{name}{suffix}.ply')
            write_ply(path, points, faces, f'hard_meshes.py {name}{suffix} seed {a.seed}')
            if check:
                check_with_dggvtp(dggvtp, path)
            if not a.quiet:
                shape = f'closed, genus {genus}' if genus is not None else f'open, {border} border edges'
                print(f'{path}: {len(points)} vertices, {len(faces)} faces, {shape}'
                      + (', accepted by dggvtp' if check else ''), flush=True)
    except (Failure, OSError) as e:
        print(f'error: {e}', file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main())
