#!/usr/bin/env python3
# Copyright (c) 2026 The DGG-VTP for CGAL authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Pair queries (issue 59): the search toward the target against the disk search and a whole field.

For each mesh: the targets at the 30%, 60% and 90% quantiles of the distance from the source (a
field at epsilon 1e-1 picks them); per epsilon, `dggvtp --source S --target T` (the pair query,
toward T), `dggvtp --source S --max-distance D(1 + epsilon)` (the disk search: every vertex nearer
than the target, D the pair's distance) and the whole field, the three alternating, REPEAT times:
median propagation seconds (`--stats`), windows and pops, the ratios disk / pair and field / pair,
and the pair's value against the exact one. One thread.

usage: pair_queries.py [--dggvtp PATH] [--repeat R] [--epsilons E ...] [--source S] MESH [MESH ...]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def run(dggvtp, args, out=None):
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as f:
        stats = f.name
    cmd = [dggvtp] + args + ["--threads", "1", "--quiet", "--stats", stats]
    if out is None:
        cmd += ["--output", "/dev/null"]
    r = subprocess.run(cmd, check=True, capture_output=True, text=True)
    with open(stats) as f:
        s = json.load(f)
    os.unlink(stats)
    return s, r.stdout


def field(dggvtp, mesh, source, epsilon):
    with tempfile.NamedTemporaryFile(suffix=".txt", delete=False) as f:
        path = f.name
    run(dggvtp, [mesh, "--source", str(source), "--epsilon", str(epsilon), "--output", path], out=path)
    with open(path) as f:
        d = [float(x) for x in f]
    os.unlink(path)
    return d


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("meshes", nargs="+")
    p.add_argument("--dggvtp", default=os.path.join(os.path.dirname(__file__), "../../build/bin/dggvtp"))
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--source", type=int, default=0)
    p.add_argument("--epsilons", nargs="+", default=["0", "1e-1", "1e-2", "1e-3", "1e-4"])
    p.add_argument("--quantiles", nargs="+", type=float, default=[0.3, 0.6, 0.9])
    a = p.parse_args()
    print("| mesh | vertices | quantile | target | epsilon | pair s | disk s | field s | disk / pair | field / pair "
          "| pair windows | disk windows | pair pops | disk pops | pair value / exact - 1 |")
    print("|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for mesh in a.meshes:
        rough = field(a.dggvtp, mesh, a.source, 1e-1)
        order = sorted(range(len(rough)), key=lambda v: rough[v])
        reachable = [v for v in order if rough[v] < float("inf")]
        targets = [reachable[min(len(reachable) - 1, int(q * len(reachable)))] for q in a.quantiles]
        exact_at = {}
        for t in targets:
            s, out = run(a.dggvtp, [mesh, "--source", str(a.source), "--target", str(t), "--exact"])
            exact_at[t] = float(out.split()[0])
        for e in a.epsilons:
            eps = float(e)
            field_s = []
            for q, t in zip(a.quantiles, targets):
                pair, disk = [], []
                value = None
                radius = exact_at[t] * (1 + eps)
                for _ in range(a.repeat):
                    s, out = run(a.dggvtp, [mesh, "--source", str(a.source), "--target", str(t), "--epsilon", e])
                    pair.append(s)
                    value = float(out.split()[0])
                    s, _ = run(a.dggvtp, [mesh, "--source", str(a.source), "--max-distance", repr(radius), "--epsilon", e])
                    disk.append(s)
                    if len(field_s) < a.repeat:
                        s, _ = run(a.dggvtp, [mesh, "--source", str(a.source), "--epsilon", e])
                        field_s.append(s)
                tp = statistics.median(x["seconds_propagate"] for x in pair)
                td = statistics.median(x["seconds_propagate"] for x in disk)
                tf = statistics.median(x["seconds_propagate"] for x in field_s)
                print(f"| {os.path.basename(mesh)} | {pair[0]['vertices']} | {q:.0%} | {t} | {e} | {tp:.3f} | {td:.3f} | "
                      f"{tf:.3f} | {td / tp:.2f} | {tf / tp:.2f} | {pair[0]['windows_created']} | {disk[0]['windows_created']} "
                      f"| {pair[0]['vertices_popped']} | {disk[0]['vertices_popped']} | {value / exact_at[t] - 1:.2e} |",
                      flush=True)


if __name__ == "__main__":
    sys.exit(main())
