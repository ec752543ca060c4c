#!/usr/bin/env python3
"""How wide the certified interval is (issue 45): per mesh and epsilon, over seeded sources and
every vertex they reach (not the sources), the certified error bound b = d - K (return_bounds=True)
over epsilon x d, its mean and largest value, the share of the vertices certified exact (b = 0),
and the true error (d - exact) / (epsilon exact) against the exact mode, its mean and largest, for
comparison; and that the interval holds (exact in [d - b, d], rounding aside: a violation exits 1).

Example (from the repository root, the module built in build/python):
  PYTHONPATH=build/python /usr/bin/python3 benchmark/DGG_VTP_3/certified_error.py \\
      data/meshes/pinion.ply data/meshes/bunny.ply --sources 10 --markdown bounds.md
"""
import argparse
import os
import sys
import time

import numpy as np

import dggvtp

EPSILONS = (1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-7)


def measure(path, sources, seed, epsilons):
    V, F = dggvtp.read_mesh(path)
    solver = dggvtp.GeodesicSolver(V, F)
    rng = np.random.default_rng(seed)
    chosen = sorted(rng.choice(len(V), size=min(sources, len(V)), replace=False).tolist())
    exact = [solver.distances(s) for s in chosen]
    rows, violations = [], 0
    for epsilon in epsilons:
        width, error, certified, reached = [], [], 0, 0
        for s, ex in zip(chosen, exact):
            d, b = solver.distances(s, epsilon=epsilon, return_bounds=True)
            at = np.isfinite(ex) & (ex > 0)
            violations += int(np.count_nonzero(d[at] - b[at] > ex[at] * (1 + 1e-12)))
            violations += int(np.count_nonzero(b[at] > epsilon * d[at] * (1 + 1e-12)))
            width.append(b[at] / (epsilon * d[at]))
            error.append((d[at] - ex[at]) / (epsilon * ex[at]))
            certified += int(np.count_nonzero(b[at] == 0))
            reached += int(np.count_nonzero(at))
        width, error = np.concatenate(width), np.concatenate(error)
        rows.append((os.path.basename(path), len(V), len(chosen), epsilon, width.mean(), width.max(),
                     certified / reached, error.mean(), error.max()))
    return rows, violations


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('meshes', nargs='+', metavar='MESH')
    p.add_argument('--sources', type=int, default=10, help='seeded sources per mesh (default 10)')
    p.add_argument('--seed', type=int, default=1)
    p.add_argument('--epsilons', type=float, nargs='+', default=list(EPSILONS))
    p.add_argument('--markdown', metavar='FILE', help='write the table here too')
    a = p.parse_args()
    lines = ["| mesh | vertices | sources | epsilon | bound / (eps d), mean | largest | certified exact "
             "| true error / (eps exact), mean | largest |", "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    print("\n".join(lines), flush=True)
    violations = 0
    for path in a.meshes:
        t0 = time.time()
        rows, v = measure(path, a.sources, a.seed, a.epsilons)
        violations += v
        for r in rows:
            lines.append("| %s | %d | %d | %g | %.3f | %.3f | %.1f%% | %.3f | %.3f |" %
                         (r[0], r[1], r[2], r[3], r[4], r[5], 100 * r[6], r[7], r[8]))
            print(lines[-1], flush=True)
        print("# %s: %.0f s, %d violations" % (path, time.time() - t0, v), file=sys.stderr, flush=True)
    if a.markdown:
        with open(a.markdown, 'w') as f:
            f.write("\n".join(lines) + "\n\n%d violations of exact in [d - b, d] or b <= epsilon d\n" % violations)
    print("%d violations" % violations)
    return 1 if violations else 0


if __name__ == '__main__':
    sys.exit(main())
