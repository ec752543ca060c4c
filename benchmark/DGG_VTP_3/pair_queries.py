#!/usr/bin/env python3
# Copyright (c) 2026 The DGG-VTP for CGAL authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Pair queries (issue 59): the search toward the target against the disk search and a whole field.

For each mesh: the targets at the 30%, 60% and 90% quantiles of the distance from the source (a
field at epsilon 1e-1 picks them); per epsilon, on one thread, `pair_distances([s], [t])` (the
search toward t), `target_distances(s, [t])` (the disk search: every vertex nearer than t) and the
whole field `distances(s)`, the three alternating, REPEAT times: median seconds, the ratios
disk / pair and field / pair, and the pair's value against the exact one (and the disk's).

usage: PYTHONPATH=build/python pair_queries.py [--repeat R] [--epsilons E ...] [--source S] MESH [MESH ...]
"""
import argparse
import os
import statistics
import sys
import time

import numpy as np

import dggvtp


def timed(f):
    start = time.perf_counter()
    value = f()
    return time.perf_counter() - start, value


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("meshes", nargs="+")
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--source", type=int, default=0)
    p.add_argument("--epsilons", nargs="+", type=float, default=[0.0, 1e-1, 1e-2, 1e-3, 1e-4])
    p.add_argument("--quantiles", nargs="+", type=float, default=[0.3, 0.6, 0.9])
    a = p.parse_args()
    print("| mesh | vertices | quantile | target | epsilon | pair s | disk s | field s | disk / pair | field / pair "
          "| pair / exact - 1 |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for mesh in a.meshes:
        solver = dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh), threads=1)
        rough = solver.distances(a.source, epsilon=1e-1, threads=1)
        reachable = np.argsort(rough)[: int(np.isfinite(rough).sum())]
        targets = [int(reachable[min(len(reachable) - 1, int(q * len(reachable)))]) for q in a.quantiles]
        for eps in a.epsilons:
            field = []
            for q, t in zip(a.quantiles, targets):
                exact = solver.pair_distances([a.source], [t], threads=1)[0]
                pair, disk = [], []
                for _ in range(a.repeat):
                    s, value = timed(lambda: solver.pair_distances([a.source], [t], epsilon=eps, threads=1)[0])
                    pair.append(s)
                    s, at_disk = timed(lambda: solver.target_distances(a.source, [t], epsilon=eps, threads=1)[0])
                    disk.append(s)
                    if len(field) < a.repeat:
                        field.append(timed(lambda: solver.distances(a.source, epsilon=eps, threads=1))[0])
                    assert exact * (1 - 1e-12) <= value <= exact * (1 + eps) * (1 + 1e-12), (value, exact)
                    assert exact * (1 - 1e-12) <= at_disk <= exact * (1 + eps) * (1 + 1e-12), (at_disk, exact)
                tp, td, tf = statistics.median(pair), statistics.median(disk), statistics.median(field)
                print(f"| {os.path.basename(mesh)} | {solver.num_vertices} | {q:.0%} | {t} | {eps:g} | {tp:.3f} | "
                      f"{td:.3f} | {tf:.3f} | {td / tp:.2f} | {tf / tp:.2f} | {value / exact - 1:.2e} |", flush=True)


if __name__ == "__main__":
    sys.exit(main())
