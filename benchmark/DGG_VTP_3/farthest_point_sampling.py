"""Farthest-point sampling (issue 52): GeodesicSolver.farthest_point_sampling(k) against one whole
field of the same epsilon (distances(0)), against a Python loop over distances() (k whole fields
and their minimum, what a user wrote before), and against the same loop over gdist's
compute_gdist (tvb-gdist, Kirsanov's exact MMP, a benchmark peer built outside the repository: see
the benchmark README). One thread, in one process, the variants alternating --repeat times
(medians). Prints a Markdown table row per (k, epsilon).

usage: PYTHONPATH=build/python /usr/bin/python3 benchmark/DGG_VTP_3/farthest_point_sampling.py MESH
           [--k 100,1000] [--epsilon 0,1e-2] [--repeat 3] [--loop-fields 20] [--gdist] [--check]
A loop over k fields takes k times one field and its minimum: it is timed over --loop-fields fields
(all of them when k is smaller) and scaled to k ("loop" columns; "measured" when the whole loop
ran). With --gdist and `import gdist` working, gdist's loop likewise (exact only: gdist has no
accuracy parameter), from the same sources as the sampling chose.
--check: instead of times, the contract of each sampling against the exact rows of its samples
(distances_from_each, exact): the largest (d - exact) / (epsilon exact) of the field, the
violations (d below exact or above (1 + epsilon) exact, labels naming a sample beyond that, a
sample nearer to those before it than the farthest over 1 + epsilon);
exit status 1 if there is one."""
import argparse
import statistics
import sys
import time

import numpy as np

import dggvtp


def seconds(f):
    t0 = time.perf_counter()
    f()
    return time.perf_counter() - t0


def loop_seconds(field, sources, fields):
    """the time of a loop over distances from `sources` and their minimum, timed over `fields` of
    them and scaled to all; returns (seconds, measured: whether every field ran)"""
    count = min(fields, len(sources))
    nearest = None

    def run():
        nonlocal nearest
        for s in sources[:count]:
            d = field(int(s))
            nearest = d if nearest is None else np.minimum(nearest, d)

    return seconds(run) * len(sources) / count, count == len(sources)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mesh")
    parser.add_argument("--k", default="100,1000")
    parser.add_argument("--epsilon", default="0,1e-2")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--loop-fields", type=int, default=20)
    parser.add_argument("--gdist", action="store_true")
    parser.add_argument("--check", action="store_true")
    a = parser.parse_args()
    V, F = dggvtp.read_mesh(a.mesh)
    solver = dggvtp.GeodesicSolver(V, F)
    if a.check:
        return check(a, solver, len(V))
    gdist = None
    if a.gdist:
        import gdist  # noqa: F811 (a benchmark peer, never a dependency)
    print("| mesh | vertices | epsilon | k | whole field (s) | sampling (s) | sampling in whole fields "
          "| loop over distances() (s) | loop / sampling | gdist loop (s) | gdist loop / sampling |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for epsilon in (float(e) for e in a.epsilon.split(",")):
        for k in (int(x) for x in a.k.split(",")):
            whole, sampling = [], []
            for _ in range(a.repeat):
                whole.append(seconds(lambda: solver.distances(0, epsilon=epsilon, threads=1)))
                samples = None

                def sample():
                    nonlocal samples
                    samples = solver.farthest_point_sampling(k, epsilon=epsilon, threads=1)

                sampling.append(seconds(sample))
            w, s = statistics.median(whole), statistics.median(sampling)
            loop, measured = loop_seconds(lambda v: solver.distances(v, epsilon=epsilon, threads=1), samples,
                                          a.loop_fields)
            gdist_cell = "n/a"
            if gdist is not None and epsilon == 0.0:
                Vd, Fi = np.ascontiguousarray(V, dtype=np.float64), np.ascontiguousarray(F, dtype=np.int32)
                g, g_measured = loop_seconds(lambda v: gdist.compute_gdist(Vd, Fi, np.array([v], dtype=np.int32)),
                                             samples, a.loop_fields)
                gdist_cell = f"{g:.1f}{'' if g_measured else ' (scaled)'} | {g / s:.0f}"
            else:
                gdist_cell += " | n/a"
            print(f"| {a.mesh.split('/')[-1]} | {len(V)} | {epsilon:g} | {k} | {w:.3f} | {s:.3f} | {s / w:.1f} "
                  f"| {loop:.1f}{'' if measured else ' (scaled)'} | {loop / s:.0f} | {gdist_cell} |", flush=True)


def check(a, solver, n):
    print("| mesh | vertices | epsilon | k | max error / epsilon | violations |")
    print("|---|---|---|---|---|---|")
    bad = 0
    slack = 1e-12
    for epsilon in (float(e) for e in a.epsilon.split(",")):
        for k in (int(x) for x in a.k.split(",")):
            samples, d, labels = solver.farthest_point_sampling(k, epsilon=epsilon, return_distances=True,
                                                                return_labels=True)
            rows = solver.distances_from_each(samples)
            exact = rows.min(axis=0)
            violations = int(np.sum(d < exact * (1 - slack)) + np.sum(d > exact * (1 + epsilon) * (1 + slack)))
            violations += int(np.sum(rows[labels, np.arange(n)] > exact * (1 + epsilon) * (1 + slack)))
            nearest = rows[0].copy()
            for i in range(1, k):
                violations += int(nearest[samples[i]] * (1 + epsilon) * (1 + slack) < nearest.max())
                nearest = np.minimum(nearest, rows[i])
            positive = exact > 0
            worst = float(np.max((d[positive] - exact[positive]) / (exact[positive] * max(epsilon, 1e-300))))
            print(f"| {a.mesh.split('/')[-1]} | {n} | {epsilon:g} | {k} | {worst if epsilon > 0 else 0.0:.3f} "
                  f"| {violations} |", flush=True)
            bad += violations
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
