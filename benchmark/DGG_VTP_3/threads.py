#!/usr/bin/env python3
"""Parallel_tag of one propagation: dggvtp --threads T against --threads 1, on one mesh.

For each mode (the exact mode, then each epsilon), runs dggvtp with every thread count in turn,
--repeat rounds alternating the thread counts (the machine's noise then falls on all of them
alike), and reports per mode and thread count: the median `seconds_propagate`, its speed-up over
1 thread (ratio of the medians), windows created, peak live windows (and its ratio to 1 thread),
the largest relative error against the exact mode's distances, and whether the distances are the
same bytes as with 1 thread (they must be: the rounds do not depend on the thread count).

Example (from the repository root, after building dggvtp in build/; the mesh from
benchmark/DGG_VTP_3/large_mesh.sh or benchmark/DGG_VTP_3/make_large.sh):
  python3 benchmark/DGG_VTP_3/threads.py --mesh /tmp/large_meshes/bunny_1M.ply --out threads.md
"""
import argparse
import filecmp
import json
import math
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exact_vs_smsp import REPO, machine, read_distances, revision, run  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--mesh', required=True)
    parser.add_argument('--dggvtp', default=os.path.join(REPO, 'build', 'bin', 'dggvtp'))
    parser.add_argument('--source', type=int, default=0)
    parser.add_argument('--modes', default='exact,1e-6,1e-7', help='comma-separated: exact or an epsilon')
    parser.add_argument('--threads', default='1,2', help='comma-separated thread counts, 1 first')
    parser.add_argument('--repeat', type=int, default=3)
    parser.add_argument('--timeout', type=float, default=3600.)
    parser.add_argument('--out', help='Markdown table (also printed)')
    args = parser.parse_args()
    threads = [int(t) for t in args.threads.split(',')]
    if threads[0] != 1 or args.repeat < 1:
        sys.exit('error: --threads must start with 1 and --repeat be at least 1')

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        exact = None
        for mode in args.modes.split(','):
            flags = ['--exact'] if mode == 'exact' else ['--epsilon', mode]
            times = {t: [] for t in threads}
            stats = {}
            for r in range(args.repeat):
                for t in threads:
                    out, st = os.path.join(tmp, 'd%d_%d.txt' % (t, r)), os.path.join(tmp, 's.json')
                    err = run([args.dggvtp, args.mesh, '--quiet', '--source', str(args.source), '--threads', str(t),
                               '--output', out, '--stats', st] + flags, args.timeout)
                    if err:
                        sys.exit('error: dggvtp failed: %s' % err)
                    with open(st) as f:
                        stats[t] = json.load(f)
                    times[t].append(stats[t]['seconds_propagate'])
                    print('%s, %d threads, run %d: %.2f s' % (mode, t, r + 1, times[t][-1]), file=sys.stderr, flush=True)
            if mode == 'exact':
                exact = read_distances(os.path.join(tmp, 'd1_0.txt'))
            for t in threads:
                identical = all(filecmp.cmp(os.path.join(tmp, 'd1_0.txt'), os.path.join(tmp, 'd%d_%d.txt' % (t, r)),
                                            shallow=False) for r in range(args.repeat))
                error = float('nan')
                if exact is not None:
                    d = read_distances(os.path.join(tmp, 'd%d_0.txt' % t))
                    error = max(((b - a) / a for a, b in zip(exact, d) if a > 0 and math.isfinite(a)), default=0.)
                rows.append((mode, t, statistics.median(times[t]), statistics.median(times[1]) / statistics.median(times[t]),
                             stats[t]['windows_created'], stats[t]['windows_peak'],
                             stats[t]['windows_peak'] / stats[1]['windows_peak'], error, identical,
                             ' '.join('%.2f' % x for x in times[t])))
            for r in range(args.repeat):
                for t in threads:
                    os.remove(os.path.join(tmp, 'd%d_%d.txt' % (t, r)))

    lines = ['%s, source %d, %s; revision %s; median of %d runs, thread counts alternating' %
             (os.path.basename(args.mesh), args.source, machine(), revision(), args.repeat), '',
             '| mode | threads | seconds (median) | speed-up | windows created | peak windows | peak / 1 thread | max rel. error | same bytes as 1 thread | runs (s) |',
             '|---|---:|---:|---:|---:|---:|---:|---:|:---:|---|']
    for mode, t, sec, speedup, created, peak, peak_ratio, error, identical, runs in rows:
        lines.append('| %s | %d | %.2f | %.2fx | %d | %d | %.3f | %.2e | %s | %s |' %
                     (mode, t, sec, speedup, created, peak, peak_ratio, error, 'yes' if identical else 'NO', runs))
    text = '\n'.join(lines) + '\n'
    print(text)
    if args.out:
        with open(args.out, 'w') as f:
            f.write(text)
    if not all(row[8] for row in rows):
        sys.exit('error: the distances differ between thread counts')


if __name__ == '__main__':
    main()
