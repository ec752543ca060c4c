#!/usr/bin/env python3
"""Exact mode of dggvtp against CGAL's Surface_mesh_shortest_path, same meshes, same run.

Each measurement is a process of its own (so peak RSS is per algorithm); times are propagation
only (dggvtp: seconds_propagate; SMSP: sequence tree + distance queries), medians over --repeat
runs; ratios are SMSP / ours. Accuracy: max relative difference over all vertices.
"""
import argparse, json, os, statistics, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))


def run(cmd):
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def read_distances(path):
    with open(path) as f:
        return [float(line) for line in f]


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument('--build', default=os.path.join(REPO, 'build'), help='build directory (bin/dggvtp, bin/smsp_distances)')
    p.add_argument('--meshes', nargs='*', default=[os.path.join(REPO, 'data', 'meshes', m + '.ply')
                   for m in ('spot', 'lion_head', 'blade', 'turbine', 'bunny')])
    p.add_argument('--repeat', type=int, default=3)
    p.add_argument('--sources', default='0,half', help='comma-separated vertex indices; "half" = n/2')
    p.add_argument('--skip-smsp-above', type=int, default=60000, help='vertices (SMSP needs ~10 GiB at 164k)')
    p.add_argument('--out', help='also write the table to this file')
    a = p.parse_args()
    dggvtp = os.path.join(a.build, 'bin', 'dggvtp')
    smsp = os.path.join(a.build, 'bin', 'smsp_distances')
    rows = ['| mesh | vertices | source | ours (s) | SMSP (s) | time ratio | ours peak RSS (MB) | SMSP peak RSS (MB) | memory ratio | max rel. difference |',
            '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|']
    tmp = tempfile.mkdtemp()
    for mesh in a.meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        probe = os.path.join(tmp, 'probe.json')
        run([dggvtp, mesh, '--quiet', '--stats', probe])
        n = json.load(open(probe))['vertices']
        for s in a.sources.split(','):
            src = n // 2 if s == 'half' else int(s)
            ours_t, ours_m, ref_t, ref_m = [], [], [], []
            for _ in range(a.repeat):
                run([dggvtp, mesh, '--quiet', '--source', str(src), '--output', os.path.join(tmp, 'ours.txt'),
                     '--stats', os.path.join(tmp, 'ours.json')])
                st = json.load(open(os.path.join(tmp, 'ours.json')))
                ours_t.append(st['seconds_propagate']); ours_m.append(st['peak_rss_mb'])
                if n <= a.skip_smsp_above:
                    run([smsp, mesh, str(src), os.path.join(tmp, 'ref.txt'), os.path.join(tmp, 'ref.json')])
                    st = json.load(open(os.path.join(tmp, 'ref.json')))
                    ref_t.append(st['seconds_propagate']); ref_m.append(st['peak_rss_mb'])
            ot, om = statistics.median(ours_t), statistics.median(ours_m)
            if ref_t:
                rt, rm = statistics.median(ref_t), statistics.median(ref_m)
                ours = read_distances(os.path.join(tmp, 'ours.txt'))
                ref = read_distances(os.path.join(tmp, 'ref.txt'))
                err = max(abs(x - y) / y for x, y in zip(ours, ref) if y > 0)
                rows.append(f'| {name} | {n} | {src} | {ot:.3f} | {rt:.2f} | {rt / ot:.0f}x | {om:.0f} | {rm:.0f} | {rm / om:.0f}x | {err:.1e} |')
            else:
                rows.append(f'| {name} | {n} | {src} | {ot:.3f} | - | - | {om:.0f} | - | - | - |')
            print(rows[-1], flush=True)
    table = '\n'.join(rows)
    print('\n' + table)
    if a.out:
        with open(a.out, 'w') as f:
            f.write(table + '\n')


if __name__ == '__main__':
    sys.exit(main())
