#!/usr/bin/env python3
"""The deciding experiment of the certified geodesic graph (issue 54; design note, section 7).

For each mesh and epsilon, `geodesic_graph_experiment` (built in --build) runs the graph's build
rule from every vertex: one direct-only propagation, its source the only pseudo-source, every
window stopped at its distance bound, every vertex it reaches an out-edge weighted with the
distance found. The theorem (manual, "A certified geodesic graph") says that Dijkstra on those
edges gives d <= D <= (1 + epsilon) d for every source and vertex. This script checks it: the
directed graph's Dijkstra rows (scipy.sparse.csgraph.dijkstra) against the exact rows of
dggvtp-batch --exact, with the adversary's comparison (adversary.py: D in [exact (1 - 1e-12),
exact (1 + epsilon)], unreachable in both or in neither); since the bound is a theorem, any
violation is a bug. The sources: every vertex (the default) or --sample K seeded ones.

One table row per mesh and epsilon: out-degree (mean, 99th percentile, largest), entries per
vertex of the graph stored symmetrised (the union of both directions), windows per run,
microseconds per vertex on the threads given (a query's set-up subtracted: as many runs within
distance 0), peak RSS of the build, the largest error / epsilon and the violations, and the
median time of a Dijkstra row against an exact row of dggvtp-batch (both one thread).

Example (from the repository root, after building the targets dggvtp-batch and
geodesic_graph_experiment in build/):
  /usr/bin/python3 benchmark/DGG_VTP_3/geodesic_graph_experiment.py data/meshes/pinion.ply \\
          --epsilons 1e-2 1e-3 1e-4 --markdown graph.md --json graph.json
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import scipy.sparse
from scipy.sparse.csgraph import dijkstra

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from adversary import (REPO, Batch, Failure, Tally, epsilon_list, machine, revision,  # noqa: E402
                       sample_sources, seconds, vertex_count)

HEADER = ['| mesh | vertices | epsilon | out-degree mean / p99 / max | mean x sqrt(eps) | symmetrised entries '
          '/ vertex | windows / run | us / vertex | build RSS (MB) | sources | max err / eps | violations '
          '| lowest rel. err | Dijkstra row / exact row |',
          '|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|']


def row(r):
    return (f"| {r['mesh']} | {r['vertices']:,} | {r['epsilon']:g} | {r['mean_degree']:.1f} / {r['p99_degree']} / "
            f"{r['max_degree']} | {r['mean_degree'] * r['epsilon'] ** 0.5:.2f} | {r['symmetrised_per_vertex']:.1f} | "
            f"{r['windows_per_vertex']:.0f} | {r['us_per_vertex']:.0f} | {r['peak_rss_mb']:.0f} | {r['sources']} | "
            f"{r['max_over_eps']:.3f} | {r['violations']} | {r['min_rel']:.1e} | {r['query_ratio']:.3f} |")


def build_graph(exe, mesh, epsilon, threads, path):
    """Runs geodesic_graph_experiment: (its JSON record, the CSR matrix of the directed graph)."""
    r = subprocess.run([exe, mesh, repr(float(epsilon)), path, str(threads)], capture_output=True, text=True)
    if r.returncode != 0:
        raise Failure(f'{exe} {mesh} {epsilon}: exit status {r.returncode}: {r.stderr.strip()}')
    record = json.loads(r.stdout)
    graph = scipy.sparse.load_npz(path).tocsr()
    os.remove(path)
    return record, graph


def check(a, mesh, workdir, say):
    name = os.path.splitext(os.path.basename(mesh))[0]
    batch_exe = os.path.join(a.build, 'bin', 'dggvtp-batch')
    graph_exe = os.path.join(a.build, 'bin', 'geodesic_graph_experiment')
    vertices = vertex_count(batch_exe, mesh, workdir)
    chosen = sample_sources(vertices, a.sample, a.seed) if a.sample and a.sample < vertices else np.arange(vertices)
    sources = os.path.join(workdir, 'sources.txt')
    np.savetxt(sources, chosen, fmt='%d')
    say(f'{name}: {vertices} vertices, {len(chosen)} sources, exact rows')
    exact_path, stats = Batch(batch_exe, mesh, sources, 1, workdir, True).run('exact', 0, 'double')
    exact_row_seconds = seconds(stats)[0] / len(chosen)
    exact = np.load(exact_path, mmap_mode='r')
    records = []
    for epsilon in a.epsilons:
        say(f'{name}: epsilon {epsilon:g}, the graph')
        record, graph = build_graph(graph_exe, mesh, epsilon, a.threads, os.path.join(workdir, 'graph.npz'))
        pattern = graph.copy()
        pattern.data[:] = 1.
        record['symmetrised_per_vertex'] = (pattern + pattern.T).nnz / vertices
        tally = Tally(epsilon)
        step = max(1, (64 << 20) // (8 * vertices))
        query_seconds = []
        for first in range(0, len(chosen), step):
            block = chosen[first:first + step]
            start = time.perf_counter()
            d = dijkstra(graph, directed=True, indices=block)
            query_seconds.append((time.perf_counter() - start) / len(block))
            tally.add(exact[first:first + len(block)], d, first)
        at = lambda p: None if p is None else [int(chosen[p[0]]), p[1]]  # noqa: E731
        record.update({
            'mesh': name, 'file': mesh, 'sources': len(chosen), 'max_rel': tally.max_rel,
            'max_over_eps': tally.max_rel / epsilon, 'max_at': at(tally.max_at), 'min_rel': tally.min_rel,
            'min_at': at(tally.min_at), 'violations': tally.violations, 'below': tally.below,
            'examples': [[int(chosen[r]), v, e, dv] for r, v, e, dv in tally.examples],
            'dijkstra_row_seconds': float(np.median(query_seconds)), 'exact_row_seconds': exact_row_seconds,
            'query_ratio': float(np.median(query_seconds)) / exact_row_seconds})
        records.append(record)
        print(row(record), flush=True)
    del exact
    os.remove(exact_path)
    return records


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('meshes', nargs='+', metavar='MESH', help='mesh files (clean: no repair, no copies)')
    p.add_argument('--build', default=os.path.join(REPO, 'build'),
                   help='build directory holding bin/dggvtp-batch and bin/geodesic_graph_experiment')
    p.add_argument('--epsilons', nargs='+', default=['1e-2 1e-3 1e-4'], metavar='E',
                   help='epsilons in (0, 1] (default: 1e-2 1e-3 1e-4)')
    p.add_argument('--sample', type=int, metavar='K', help='K seeded sources instead of every vertex')
    p.add_argument('--seed', type=int, default=1, help='seed of --sample (default 1)')
    p.add_argument('--threads', type=int, default=1, help='threads of the build (default 1)')
    p.add_argument('--json', help='write every record here')
    p.add_argument('--markdown', help='write the table here')
    a = p.parse_args()
    try:
        a.epsilons = epsilon_list(a.epsilons)
        say = lambda m: print(m, file=sys.stderr, flush=True)  # noqa: E731
        records = []
        print('\n'.join(HEADER), flush=True)
        with tempfile.TemporaryDirectory() as workdir:
            for mesh in a.meshes:
                records += check(a, mesh, workdir, say)
        table = '\n'.join(HEADER + [row(r) for r in records]) + '\n'
        if a.markdown:
            with open(a.markdown, 'w') as f:
                f.write(table)
        if a.json:
            with open(a.json, 'w') as f:
                json.dump({'machine': machine(), 'revision': revision(), 'records': records}, f, indent=1)
        return 1 if any(r['violations'] for r in records) else 0
    except Failure as e:
        print(f'error: {e}', file=sys.stderr)
        return 2


if __name__ == '__main__':
    sys.exit(main())
