#!/usr/bin/env python3
"""Exact mode of dggvtp against CGAL's exact Surface_mesh_shortest_path (SMSP), same meshes, same sources.

Every measurement is a process of its own, so each peak RSS belongs to one algorithm (whole process:
mesh, preprocessing, propagation, output). Times are propagation only: `seconds_propagate` of
`dggvtp --stats` and, for SMSP, build_sequence_tree() + one distance query per vertex
(`smsp_distances`). Medians over --repeat runs; ratios are SMSP / ours (> 1: we are faster / smaller).
Accuracy: max over the vertices of |ours - SMSP| / SMSP (the source vertex, where SMSP is 0, is
reported separately as an absolute difference); vertices unreachable in one and not the other count
as an infinite error.

Example (from the repository root, after building dggvtp and smsp_distances):
  python3 benchmark/DGG_VTP_3/exact_vs_smsp.py --build build --out /tmp/exact_vs_smsp.md
"""
import argparse
import datetime
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))
BUNDLED = ('spot', 'lion_head', 'blade', 'turbine', 'bunny')


def count_vertices(path):
    """Vertex count from a PLY or OFF header, None if it cannot be read cheaply."""
    try:
        with open(path, 'rb') as f:
            first = f.readline().strip()
            if first == b'ply':
                for _ in range(200):
                    line = f.readline().strip()
                    parts = line.split()
                    if parts[:2] == [b'element', b'vertex']:
                        return int(parts[2])
                    if line == b'end_header' or not line and f.tell() > 1 << 16:
                        return None
            elif first.endswith(b'OFF'):
                rest = first[first.index(b'OFF') + 3:].split()
                while not rest:
                    line = f.readline()
                    if not line:
                        return None
                    rest = line.split(b'#')[0].split()
                return int(rest[0])
    except (OSError, ValueError, IndexError):
        pass
    return None


def run(cmd, timeout):
    """Runs cmd; returns None on success, else a short reason."""
    try:
        r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return f'timeout after {timeout} s'
    except OSError as e:
        return str(e)
    if r.returncode != 0:
        msg = r.stderr.decode(errors='replace').strip().splitlines()
        return f'exit {r.returncode}' + (f': {msg[-1]}' if msg else '')
    return None


def read_distances(path):
    with open(path) as f:
        return [float(line) for line in f]


def compare(ours, ref, source):
    """(max relative difference off the source, the vertex where it is reached, absolute difference at
    the source)."""
    if len(ours) != len(ref):
        return math.inf, None, math.inf
    rel, worst = 0., None
    for i, (x, y) in enumerate(zip(ours, ref)):
        if i == source:
            continue
        if math.isinf(x) or math.isinf(y):
            e = 0. if x == y else math.inf
        elif y > 0:
            e = abs(x - y) / y
        else:
            e = 0. if x == y else math.inf
        if e > rel:
            rel, worst = e, i
    return rel, worst, abs(ours[source] - ref[source])


def symmetry_note(dggvtp, smsp, mesh, name, src, worst, ours, ref, tmp, timeout):
    """Both programs again, from the worst vertex back to the source: an exact method gives
    d(s, w) = d(w, s), so an asymmetric pair points at the program that is off."""
    o, oj = os.path.join(tmp, 'back_ours.txt'), os.path.join(tmp, 'back_ours.json')
    r, rj = os.path.join(tmp, 'back_ref.txt'), os.path.join(tmp, 'back_ref.json')
    if run([dggvtp, mesh, '--exact', '--threads', '1', '--quiet', '--source', str(worst), '--output', o, '--stats', oj], timeout) \
            or run([smsp, mesh, str(worst), r, rj], timeout):
        return f'{name}, source {src}: worst vertex {worst}; the symmetry check failed to run'
    ob, rb = read_distances(o)[src], read_distances(r)[src]
    return (f'{name}, source {src}, worst vertex {worst}: dggvtp d(s,w) = {ours[worst]:.17g}, '
            f'd(w,s) = {ob:.17g} (asymmetry {abs(ours[worst] - ob) / ob:.1e}); '
            f'SMSP d(s,w) = {ref[worst]:.17g}, d(w,s) = {rb:.17g} (asymmetry {abs(ref[worst] - rb) / rb:.1e})')


def fmt(seconds):
    return f'{seconds:.4f}' if seconds < 0.1 else f'{seconds:.3f}'


def revision():
    """The repository's commit, and whether the library, the loader or the CLI had uncommitted changes."""
    try:
        head = subprocess.run(['git', '-C', REPO, 'rev-parse', '--short', 'HEAD'], capture_output=True,
                              text=True, timeout=30).stdout.strip()
        dirty = subprocess.run(['git', '-C', REPO, 'status', '--porcelain', '--', 'include', 'loader', 'cli'],
                               capture_output=True, text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return 'unknown commit'
    return f'commit {head or "?"}' + (' + uncommitted changes in include/, loader/ or cli/' if dirty else '')


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        with open('/proc/cpuinfo') as f:
            for line in f:
                if line.startswith('model name'):
                    cpu = line.split(':', 1)[1].strip()
                    break
    except OSError:
        pass
    return f'{cpu}, {os.cpu_count()} logical cores, {platform.system()} {platform.release()}'


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--build', default=os.path.join(REPO, 'build'),
                   help='build directory holding bin/dggvtp and bin/smsp_distances (default: <repo>/build)')
    p.add_argument('--dggvtp', help='path of dggvtp (default: BUILD/bin/dggvtp)')
    p.add_argument('--smsp', help='path of smsp_distances (default: BUILD/bin/smsp_distances)')
    p.add_argument('--meshes', nargs='*', default=[],
                   help='mesh files, e.g. data/meshes/*.ply (default: the bundled '
                        + ', '.join(BUNDLED) + ' from <repo>/data/meshes)')
    p.add_argument('--repeat', type=int, default=3, help='runs per algorithm, mesh and source (default 3)')
    p.add_argument('--sources', default='0,half',
                   help='comma-separated source vertex indices; "half" = n/2 (default: 0,half)')
    p.add_argument('--skip-smsp-above', type=int, default=60000, metavar='N',
                   help='do not run SMSP on meshes with more than N vertices (SMSP needs ~10 GiB at 164k '
                        'vertices; default 60000)')
    p.add_argument('--timeout', type=float, default=1800, help='seconds per process (default 1800)')
    p.add_argument('--check-symmetry-above', type=float, default=1e-9, metavar='E',
                   help='when the max rel. error exceeds E, run both programs from the worst vertex back to '
                        'the source and print both distances each way (default 1e-9)')
    p.add_argument('--out', help='also write the table (Markdown, with date and machine) to this file')
    p.add_argument('--json', help='also write every raw measurement to this JSON file')
    a = p.parse_args()

    dggvtp = a.dggvtp or os.path.join(a.build, 'bin', 'dggvtp')
    smsp = a.smsp or os.path.join(a.build, 'bin', 'smsp_distances')
    meshes = a.meshes or [os.path.join(REPO, 'data', 'meshes', m + '.ply') for m in BUNDLED]
    for exe in (dggvtp, smsp):
        if not os.access(exe, os.X_OK):
            sys.exit(f'error: {exe} is not an executable (build it, or pass --build/--dggvtp/--smsp)')

    header = ['| mesh | vertices | source | ours (s) | SMSP (s) | time ratio SMSP/ours | ours peak RSS (MB) '
              '| SMSP peak RSS (MB) | memory ratio SMSP/ours | max rel. error | source abs. error |',
              '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|']
    rows, raw, notes, failures = [], [], [], 0
    print('\n'.join(header), flush=True)
    tmp = tempfile.mkdtemp(prefix='exact_vs_smsp.')
    ours_out, ours_json = os.path.join(tmp, 'ours.txt'), os.path.join(tmp, 'ours.json')
    ref_out, ref_json = os.path.join(tmp, 'ref.txt'), os.path.join(tmp, 'ref.json')

    for mesh in meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        n = count_vertices(mesh)
        if n is None:  # not PLY/OFF: ask dggvtp (one extra run)
            err = run([dggvtp, mesh, '--exact', '--threads', '1', '--quiet', '--stats', ours_json], a.timeout)
            n = None if err else json.load(open(ours_json))['vertices']
        if n is None:
            rows.append(f'| {name} | ? | - | FAILED: cannot count the vertices | | | | | | | |')
            print(rows[-1], flush=True)
            failures += 1
            continue
        sources = []
        for s in a.sources.split(','):
            s = s.strip()
            src = n // 2 if s == 'half' else int(s)
            if src not in sources:
                sources.append(src)
        with_smsp = n <= a.skip_smsp_above
        for src in sources:
            rec = {'mesh': mesh, 'vertices': n, 'source': src, 'ours': [], 'smsp': []}
            error = None
            for _ in range(a.repeat):
                for f in (ours_out, ours_json, ref_out, ref_json):
                    if os.path.exists(f):
                        os.remove(f)
                error = run([dggvtp, mesh, '--exact', '--threads', '1', '--quiet', '--source', str(src),
                             '--output', ours_out, '--stats', ours_json], a.timeout)
                if error:
                    error = 'dggvtp ' + error
                    break
                rec['ours'].append(json.load(open(ours_json)))
                if with_smsp:
                    error = run([smsp, mesh, str(src), ref_out, ref_json], a.timeout)
                    if error:
                        error = 'smsp_distances ' + error
                        break
                    rec['smsp'].append(json.load(open(ref_json)))
            raw.append(rec)
            if error:
                failures += 1
                rows.append(f'| {name} | {n} | {src} | FAILED: {error} | | | | | | | |')
                print(rows[-1], flush=True)
                continue
            ot = statistics.median(s['seconds_propagate'] for s in rec['ours'])
            om = statistics.median(s['peak_rss_mb'] for s in rec['ours'])
            rec['ours_median'] = {'seconds_propagate': ot, 'peak_rss_mb': om}
            if with_smsp:
                rt = statistics.median(s['seconds_propagate'] for s in rec['smsp'])
                rm = statistics.median(s['peak_rss_mb'] for s in rec['smsp'])
                ours, ref = read_distances(ours_out), read_distances(ref_out)
                rel, worst, src_abs = compare(ours, ref, src)
                if rel > a.check_symmetry_above and worst is not None:
                    notes.append(symmetry_note(dggvtp, smsp, mesh, name, src, worst, ours, ref, tmp, a.timeout))
                    print('  note: ' + notes[-1], flush=True)
                rec.update(smsp_median={'seconds_propagate': rt, 'peak_rss_mb': rm},
                           max_rel_error=rel, worst_vertex=worst, source_abs_error=src_abs)
                ratio = f'{rt / ot:.1f}x' if ot > 0 else '-'
                rows.append(f'| {name} | {n} | {src} | {fmt(ot)} | {fmt(rt)} | {ratio} | {om:.0f} | {rm:.0f} '
                            f'| {rm / om:.1f}x | {rel:.1e} | {src_abs:.1e} |')
            else:
                rows.append(f'| {name} | {n} | {src} | {fmt(ot)} | skipped (> {a.skip_smsp_above} vertices) '
                            f'| - | {om:.0f} | - | - | - | - |')
            print(rows[-1], flush=True)

    stamp = (f'{datetime.datetime.now().strftime("%Y-%m-%d %H:%M")}, {machine()}; '
             f'{revision()}; median of {a.repeat} runs; dggvtp --exact vs CGAL Surface_mesh_shortest_path (Epick)')
    table = '\n'.join(header + rows)
    if notes:
        table += ('\n\nSymmetry checks (max rel. error > %g; w = vertex of the largest difference):\n'
                  % a.check_symmetry_above) + '\n'.join('- ' + n for n in notes)
    print('\n' + stamp + '\n\n' + table)
    if a.out:
        with open(a.out, 'w') as f:
            f.write(stamp + '\n\n' + table + '\n')
    if a.json:
        with open(a.json, 'w') as f:
            json.dump({'date': stamp, 'runs': raw}, f, indent=1, default=str)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
