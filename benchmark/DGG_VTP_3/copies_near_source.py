#!/usr/bin/env python3
"""Copies of a split edge near a source (issue 43, item 1), on the adversary's hard meshes.

For each mesh of hard_meshes.py and a few of its faces ABW (picked at random, deterministically):
a source vertex S is put into the face at t |AB| / 2 from A, and a vertex C at t |AB| from A
nearer AB, so that the windows from S reach AB through the short edge AC only, lighting a sliver
of AB at A (the shape of copies_near_source.off); three fins (A, B, F) are hinged on AB, their apexes F at
`t` times 1/2, 1 and 2 |AB| from A, turned 70, 160 and 250 degrees out of the face around AB,
one of them along AB the other way. AB is then an edge of five triangles: dggvtp splits it into
sheets with copies of A and B. Every path from S to an apex crosses AB, straight from S within
triangle ABS and straight to F within its fin, so the exact distance is the least of |S q| + |q F|
over the points q of AB (S and q are in the plane face ABW): the unfolding of the fin onto ABS, or a bend at A or B. It is computed
from the file's coordinates (differences taken exactly, with fractions).

Every apex, and A and B (straight from S within ABS: the control, no copy on the way), from S at
every epsilon: the exact mode within 1e-12 of that distance, DGG-VTP within [exact (1 - 1e-12),
exact (1 + epsilon)], both to the rounding of the input besides: the propagation unfolds faces in
the frames of their edges, whose coordinates are as large as the edges, so a distance d much
shorter than AB carries up to a few machine epsilons times |AB| / d relative (64 machine epsilons
|AB| are allowed; the largest seen is printed as a multiple of machine epsilon |AB|). Before the sliver near a copy was made relative to the
distance (issue 43), a source 3e-8 from the copy got +4.8% in the exact mode
(`copies_near_source.off`); relative to the edge's length alone, such slivers cost first-order
errors once the source is closer than about 1e-5 edge lengths.

Exit status 0 when every check holds, 1 when one fails (each failure printed), 2 on an error.

Example (from the repository root, after building bin/dggvtp):
  /usr/bin/python3 benchmark/DGG_VTP_3/copies_near_source.py --small
  /usr/bin/python3 benchmark/DGG_VTP_3/copies_near_source.py --distances 1e-2,1e-6,1e-10 --edges 5
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile
import zlib
from fractions import Fraction

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))
sys.path.insert(0, HERE)
import hard_meshes  # noqa: E402  (the adversary's meshes, made the same way)


class Failure(Exception):
    """An error that stops the run: `error: ...`, exit status 2."""


FINS = ((0.5, 70.), (1., 160.), (2., 250.))   # (distance from A in t |AB|, turn out of ABW in degrees)


def with_copies_near_a_source(points, faces, face, t):
    """The mesh with a source near A and three fins on AB, where `face` is (A, B, W): a vertex C at
    t |AB| from A, an eighth of the corner from AB, and the source S at t |AB| / 2, seven eighths of
    the corner, the face split into (A, B, C), (C, B, W) and (A, C, W) split around S. Windows
    from S reach AB through the short edge AC, lighting a sliver of it at A.
    (points, faces, index of S, indices of the apexes)."""
    a, b, w = (points[i] for i in faces[face])
    ab, aw = b - a, w - a
    length = np.linalg.norm(ab)
    x = ab / length
    normal = np.cross(ab, aw)
    normal /= np.linalg.norm(normal)
    y = np.cross(normal, x)                      # in the face, towards W
    corner = math.atan2(float(aw @ y), float(aw @ x))
    at = lambda r, angle: a + r * t * length * (math.cos(angle) * x + math.sin(angle) * y)  # noqa: E731
    c, s = at(1., corner / 8), at(0.5, 7 * corner / 8)
    apexes = []
    for r, turn in FINS:
        angle = math.radians(turn)
        out = -y * math.cos(angle) + normal * math.sin(angle)   # 0 degrees: in the face's plane, away from W
        apexes.append(a + r * t * length * (0.5 * x + out))
    p = np.vstack([points, c, s, np.array(apexes)])
    ci, si = len(points), len(points) + 1
    fi = list(range(len(points) + 2, len(points) + 2 + len(FINS)))
    ia, ib, iw = faces[face]
    kept = np.delete(faces, face, axis=0)
    split = [[ia, ib, ci], [ci, ib, iw], [ia, ci, si], [ci, iw, si], [iw, ia, si]]
    fins = [[ia, ib, f] if k % 2 == 0 else [ib, ia, f] for k, f in enumerate(fi)]
    return p, np.vstack([kept, split, fins]), si, fi


def exact_apex_distance(p, ia, ib, si, fi):
    """min over q of AB of |S q| + |q F|, from the coordinates taken exactly relative to A."""
    rel = lambda i: np.array([float(Fraction(c) - Fraction(a)) for c, a in zip(p[i], p[ia])])  # noqa: E731
    b, s, f = rel(ib), rel(si), rel(fi)
    length = np.linalg.norm(b)
    x = b / length
    sx, fx = float(s @ x), float(f @ x)
    sy, fy = np.linalg.norm(s - sx * x), np.linalg.norm(f - fx * x)
    crossing = sx + (fx - sx) * sy / (sy + fy)
    if 0. < crossing < length:
        return math.hypot(fx - sx, fy + sy)
    return min(np.linalg.norm(s) + np.linalg.norm(f), np.linalg.norm(s - b) + np.linalg.norm(f - b))


def write_off(path, points, faces):
    with open(path, 'w') as out:
        out.write(f'OFF\n{len(points)} {len(faces)} 0\n')
        out.writelines(f'{x!r} {y!r} {z!r}\n' for x, y, z in points.tolist())
        out.writelines(f'3 {a} {b} {c}\n' for a, b, c in faces.tolist())


def dggvtp_targets(dggvtp, path, source, targets, epsilon):
    cmd = [dggvtp, path, '--source', str(source), '--epsilon', repr(epsilon)]
    for v in targets:
        cmd += ['--target', str(v)]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode == 2 and 'is a sliver' in r.stderr:
        return None   # the input policy: a narrow corner at A makes the split face too thin
    if r.returncode != 0:
        raise Failure(f"{' '.join(cmd)}: exit status {r.returncode}: {r.stderr.strip()}")
    return [float(line) for line in r.stdout.split()]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--small', action='store_true', help="hard_meshes.py's small set (as the adversary's CTest)")
    p.add_argument('--only', nargs='+', metavar='NAME', help='only these meshes')
    p.add_argument('--edges', type=int, default=3, help='edges per mesh (default 3)')
    p.add_argument('--distances', default='1e-2,1e-4,1e-6,1e-7,1e-8,3e-9',
                   help='t: the source at t |AB| from A (default 1e-2,1e-4,1e-6,1e-7,1e-8,3e-9; the rule before issue 43 failed below about 1e-7;\n below about 1e-9 the split face is a sliver dggvtp refuses)')
    p.add_argument('--epsilons', default='0,1e-7,1e-4,1e-2,1',
                   help='accuracies (default 0,1e-7,1e-4,1e-2,1; 0 is the exact mode)')
    p.add_argument('--seed', type=int, default=43, help='picks the edges (default 43)')
    p.add_argument('--build', default=os.path.join(REPO, 'build'), help='build directory holding bin/dggvtp')
    a = p.parse_args()
    try:
        dggvtp = os.path.join(a.build, 'bin', 'dggvtp')
        if not os.access(dggvtp, os.X_OK):
            raise Failure(f'{dggvtp} is not an executable (build the target dggvtp, or pass --build)')
        try:
            distances = [float(x) for x in a.distances.split(',')]
            epsilons = [float(x) for x in a.epsilons.split(',')]
        except ValueError as e:
            raise Failure(f'--distances and --epsilons take comma-separated numbers: {e}')
        if not all(0. < t <= 0.2 for t in distances):
            raise Failure('--distances: each in (0, 0.2] (the source must stay inside its face)')
        if not all(0. <= e <= 1. for e in epsilons):
            raise Failure('--epsilons: each in [0, 1]')
        names = [n for n, (_, full, small) in hard_meshes.MESHES.items() if (small if a.small else full) is not None]
        if a.only:
            unknown = sorted(set(a.only) - set(names))
            if unknown:
                raise Failure(f"unknown mesh {', '.join(unknown)} (the set: {', '.join(names)})")
            names = [n for n in names if n in a.only]
        failures = checks = skipped = 0
        worst_exact = worst_ratio = worst_rounding = 0.
        with tempfile.TemporaryDirectory() as folder:
            for name in names:
                make, full, small = hard_meshes.MESHES[name]
                points, faces = make(np.random.default_rng([35, zlib.crc32(name.encode())]), small if a.small else full)
                points = points.astype(np.float32).astype(np.float64)
                picks = np.random.default_rng([a.seed, zlib.crc32(name.encode())]).choice(len(faces), a.edges,
                                                                                            replace=False)
                for face in picks.tolist():
                    for t in distances:
                        q, f, si, fi = with_copies_near_a_source(points, faces, face, t)
                        path = os.path.join(folder, f'{name}_{face}_{t:g}.off')
                        write_off(path, q, f)
                        ia, ib = faces[face][0], faces[face][1]
                        ends = [int(ia), int(ib)]
                        truth = [exact_apex_distance(q, ia, ib, si, v) for v in fi]
                        truth += [float(np.linalg.norm([float(Fraction(x) - Fraction(y)) for x, y in zip(q[v], q[si])]))
                                  for v in ends]
                        rounding = 64 * np.finfo(float).eps * float(np.linalg.norm(q[ib] - q[ia]))
                        for epsilon in epsilons:
                            got = dggvtp_targets(dggvtp, path, si, fi + ends, epsilon)
                            if got is None:
                                skipped += 1
                                break
                            for v, d, e in zip(fi + ends, got, truth):
                                checks += 1
                                rel = (d - e) / e
                                if epsilon == 0:
                                    worst_exact = max(worst_exact, abs(rel))
                                    worst_rounding = max(worst_rounding, 64 * abs(d - e) / rounding)
                                else:
                                    worst_ratio = max(worst_ratio, (d - e - rounding) / (epsilon * e))
                                allowed = 1e-12 * e + rounding
                                ok = d - e >= -allowed and d - e <= (epsilon * e if epsilon else 0.) + allowed
                                if not ok:
                                    failures += 1
                                    print(f'FAIL {name}, face {face}, t {t:g}, epsilon {epsilon:g}, apex {v}: '
                                          f'{d!r} against {e!r} (relative {rel:+.3e}, allowed {allowed / e:.1e})', flush=True)
                print(f'{name}: {a.edges} edges x {len(distances)} distances x {len(epsilons)} epsilons', flush=True)
        print(f'{checks} checks, {failures} failures, {skipped} meshes refused as slivers (skipped); exact mode: largest relative error {worst_exact:.2e}; '
              f'largest error / epsilon {worst_ratio:.3f} (beyond the rounding); the largest exact-mode '
              f'error, in machine epsilons |AB|: {worst_rounding:.2f}')
        return 1 if failures else 0
    except (Failure, OSError, hard_meshes.Failure) as e:
        print(f'error: {e}', file=sys.stderr)
        return 2


if __name__ == '__main__':
    sys.exit(main())
