#!/usr/bin/env python3
"""DGG-VTP epsilon sweep against the exact mode of dggvtp: accuracy, time, windows, memory.

For every mesh, several sources (mesh_baseline picks vertex 0, a border vertex, the vertices of
largest and smallest angle sum, vertex n/2, then evenly spaced ones), the exact mode (--exact) and
each epsilon of the sweep; every run is a process of its own. Per mesh and epsilon, over all sources:
  - accuracy against the exact mode: max and mean of the relative error / epsilon, the fraction of
    vertices within epsilon, and the lowest relative error (below 0 means shorter than exact: DGG-VTP
    distances are lengths of real paths, so only rounding may go there), and whether the contract holds:
    every vertex within epsilon and none below the exact distance by more than 1e-12 relative;
  - time: `seconds_propagate`, median over --repeat runs for the first source (the other sources are
    run once, for accuracy), the ratio exact / DGG-VTP of the same run;
  - windows created, peak live windows, peak RSS of the whole process.
Also the time of Boost.Graph's Dijkstra over the mesh edges on the same mesh (the floor), median of
--repeat runs. Writes a Markdown table (--out), raw figures (--json) and an accuracy-against-time
figure like the paper's Fig. 8 (--plot, needs python3-matplotlib).

Example (from the repository root, after building dggvtp and mesh_baseline in build/):
  python3 benchmark/DGG_VTP_3/dgg_sweep.py --meshes data/meshes/*.ply --out sweep.md --plot sweep.png
(terrain_jacksboro.ply, not stored: python3 benchmark/DGG_VTP_3/make_terrain_jacksboro.py, then add
/tmp/terrain_jacksboro.ply to --meshes)
"""
import argparse
import datetime
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exact_vs_smsp import REPO, machine, read_distances, revision, run  # noqa: E402

EPSILONS = (1e-4, 1e-5, 1e-6, 1e-7)


def dggvtp_run(dggvtp, mesh, source, mode, tmp, timeout):
    """(distances, stats) of one dggvtp process; mode is None for --exact, else epsilon."""
    out, st = os.path.join(tmp, 'd.txt'), os.path.join(tmp, 's.json')
    flags = ['--exact'] if mode is None else ['--epsilon', repr(mode)]
    err = run([dggvtp, mesh, '--quiet', '--threads', '1', '--source', str(source), '--output', out, '--stats', st] + flags,
              timeout)
    if err:
        raise RuntimeError(f'dggvtp {os.path.basename(mesh)} source {source} {flags}: {err}')
    with open(st) as f:
        return read_distances(out), json.load(f)


def errors(d, exact, source):
    """Relative errors per vertex (source and vertices unreachable in both excluded)."""
    out = []
    for i, (x, y) in enumerate(zip(d, exact)):
        if i == source or (math.isinf(x) and math.isinf(y)):
            continue
        out.append(math.inf if math.isinf(x) or y <= 0 else (x - y) / y)
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--build', default=os.path.join(REPO, 'build'),
                   help='build directory holding bin/dggvtp and bin/mesh_baseline (default: <repo>/build)')
    p.add_argument('--meshes', nargs='+', help='mesh files')
    p.add_argument('--epsilons', nargs='+', type=float, default=list(EPSILONS))
    p.add_argument('--sources', type=int, default=5, help='sources per mesh (default 5)')
    p.add_argument('--repeat', type=int, default=3, help='timed runs of the first source (default 3)')
    p.add_argument('--timeout', type=float, default=3600, help='seconds per process (default 3600)')
    p.add_argument('--out', help='write the table (Markdown) to this file')
    p.add_argument('--json', help='write the raw figures to this file')
    p.add_argument('--plot', help='write the accuracy-against-time figure (PNG) to this file')
    p.add_argument('--replot', metavar='JSON', help='only draw --plot from the --json file of an earlier run')
    a = p.parse_args()
    if a.replot:
        if not a.plot:
            sys.exit('error: --replot needs --plot')
        with open(a.replot) as f:
            saved = json.load(f)
        plot(a.plot, [r for r in saved['runs'] if r.get('summary')], saved['when'])
        return 0
    if not a.meshes:
        sys.exit('error: --meshes is required')

    dggvtp = os.path.join(a.build, 'bin', 'dggvtp')
    baseline = os.path.join(a.build, 'bin', 'mesh_baseline')
    for exe in (dggvtp, baseline):
        if not os.access(exe, os.X_OK):
            sys.exit(f'error: {exe} is not an executable (build the targets dggvtp and mesh_baseline)')
    tmp = tempfile.mkdtemp(prefix='dgg_sweep.')
    header = ['| mesh | vertices | epsilon | sources | max err/eps | mean err/eps | within eps | lowest rel. err '
              '| contract | time (s) | exact (s) | exact/DGG | Dijkstra (s) | DGG/Dijkstra | windows created '
              '| peak windows | peak RSS (MB) |',
              '|---|---:|---:|---:|---:|---:|---:|---:|:---:|---:|---:|---:|---:|---:|---:|---:|---:|']
    print('\n'.join(header), flush=True)
    rows, raw = [], []
    for mesh in a.meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        r = subprocess.run([baseline, mesh, 'sources', str(a.sources)], capture_output=True, text=True,
                           timeout=a.timeout)
        if r.returncode != 0:
            sys.exit(f'error: mesh_baseline {mesh}: {r.stderr.strip()}')
        sources = [int(s) for s in r.stdout.split()]
        r = subprocess.run([baseline, mesh, 'dijkstra', str(sources[0]), str(a.repeat)], capture_output=True,
                           text=True, timeout=a.timeout)
        dijkstra = json.loads(r.stdout)['seconds_dijkstra']
        per_eps = {e: {'errors_max': 0., 'sum': 0., 'count': 0, 'within': 0, 'lowest': 0., 'times': [],
                       'exact_times': [], 'stats': None} for e in a.epsilons}
        n = None
        for k, src in enumerate(sources):
            repeat = a.repeat if k == 0 else 1
            exact_times = []
            for _ in range(repeat):
                exact, est = dggvtp_run(dggvtp, mesh, src, None, tmp, a.timeout)
                exact_times.append(est['seconds_propagate'])
            n = est['vertices']
            for e in a.epsilons:
                acc = per_eps[e]
                times = []
                for _ in range(repeat):
                    d, st = dggvtp_run(dggvtp, mesh, src, e, tmp, a.timeout)
                    times.append(st['seconds_propagate'])
                rel = errors(d, exact, src)
                acc['errors_max'] = max([acc['errors_max']] + rel)
                acc['sum'] += sum(x for x in rel if x > 0 and not math.isinf(x))
                acc['count'] += len(rel)
                acc['within'] += sum(1 for x in rel if x <= e)
                acc['lowest'] = min([acc['lowest']] + rel)
                if k == 0:
                    acc['times'], acc['exact_times'], acc['stats'], acc['exact_stats'] = times, exact_times, st, est
                raw.append({'mesh': mesh, 'vertices': n, 'source': src, 'epsilon': e, 'seconds': times,
                            'exact_seconds': exact_times, 'max_rel_error': max(rel, default=0.),
                            'stats': st, 'exact_stats': est})
        for e in a.epsilons:
            acc = per_eps[e]
            t, te = statistics.median(acc['times']), statistics.median(acc['exact_times'])
            st = acc['stats']
            contract = acc['errors_max'] <= e and acc['lowest'] >= -1e-12
            row = (f"| {name} | {n} | {e:g} | {len(sources)} | {acc['errors_max'] / e:.3f} "
                   f"| {acc['sum'] / max(1, acc['count']) / e:.3f} | {acc['within'] / max(1, acc['count']):.4f} "
                   f"| {acc['lowest']:.1e} | {'yes' if contract else 'NO'} | {t:.3f} | {te:.3f} | {te / t:.2f} "
                   f"| {dijkstra:.4f} | {t / dijkstra:.1f} "
                   f"| {st['windows_created']} | {st['windows_peak']} | {st['peak_rss_mb']:.0f} |")
            rows.append(row)
            print(row, flush=True)
            raw.append({'mesh': mesh, 'vertices': n, 'epsilon': e, 'summary': True,
                        'max_over_eps': acc['errors_max'] / e, 'mean_over_eps': acc['sum'] / max(1, acc['count']) / e,
                        'within': acc['within'] / max(1, acc['count']), 'contract': contract,
                        'seconds': t, 'exact_seconds': te,
                        'exact_peak_rss_mb': acc['exact_stats']['peak_rss_mb'],
                        'exact_windows_peak': acc['exact_stats']['windows_peak'],
                        'dijkstra_seconds': dijkstra, 'stats': st})
        te = statistics.median(per_eps[a.epsilons[0]]['exact_times'])
        est = per_eps[a.epsilons[0]]['exact_stats']
        row = (f"| {name} | {n} | exact | {len(sources)} | 0 | 0 | 1 | 0 | yes | {te:.3f} | {te:.3f} | 1.00 "
               f"| {dijkstra:.4f} "
               f"| {te / dijkstra:.1f} | {est['windows_created']} | {est['windows_peak']} | {est['peak_rss_mb']:.0f} |")
        rows.append(row)
        print(row, flush=True)

    stamp = f'{datetime.date.today()}, {revision()}, {machine()}'
    if a.out:
        with open(a.out, 'w') as f:
            f.write(f'{stamp}\n\n' + '\n'.join(header + rows) + '\n')
    if a.json:
        with open(a.json, 'w') as f:
            json.dump({'when': stamp, 'runs': raw}, f, indent=1)
    if a.plot:
        plot(a.plot, [r for r in raw if r.get('summary')], stamp)
    return 0


def plot(path, summaries, stamp):
    """Max and mean relative error against propagation time, one panel per mesh (paper, Fig. 8)."""
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit('error: --plot needs matplotlib: apt-get install python3-matplotlib, and run this script with '
                 "Debian's /usr/bin/python3 (or draw later: --replot JSON --plot PNG)")
    meshes = list(dict.fromkeys(s['mesh'] for s in summaries))
    cols = min(3, len(meshes))
    rows = (len(meshes) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
    for ax, mesh in zip(axes.flat, meshes):
        s = sorted((x for x in summaries if x['mesh'] == mesh), key=lambda x: x['epsilon'])
        t = [x['seconds'] for x in s]
        ax.semilogy(t, [x['max_over_eps'] * x['epsilon'] for x in s], 'o-', label='DGG-VTP max error')
        ax.semilogy(t, [x['mean_over_eps'] * x['epsilon'] for x in s], 's--', label='DGG-VTP mean error')
        ax.semilogy(t, [x['epsilon'] for x in s], ':', color='grey', label='epsilon')
        for x in s:
            ax.annotate(f"{x['epsilon']:g}", (x['seconds'], x['epsilon']), fontsize=7, color='grey')
        ax.axvline(s[0]['exact_seconds'], color='black', lw=1, label='exact mode (error 0)')
        # a linear time axis from 0: the distance to the exact mode's line reads as the speed-up
        ax.set_xlim(0, 1.1 * max(t + [s[0]['exact_seconds']]))
        ax.set_title(f"{os.path.splitext(os.path.basename(mesh))[0]} ({s[0]['vertices']} vertices)", fontsize=9)
        ax.set_xlabel('propagation time (s)')
        ax.set_ylabel('relative error')
    for ax in list(axes.flat)[len(meshes):]:
        ax.axis('off')
    axes.flat[0].legend(fontsize=7)
    fig.suptitle(stamp, fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == '__main__':
    sys.exit(main())
