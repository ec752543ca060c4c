#!/usr/bin/env python3
"""The contract of DGG-VTP against an adversary (issue 35): every source, every vertex, within epsilon.

For each mesh, every vertex as a source (--sources all, the default) or a seeded sample of K
distinct vertices (--sample K --seed S), through dggvtp-batch: once in the exact mode and once per
epsilon of --epsilons. Each epsilon's rows are compared with the exact rows, row block by row
block from memory-mapped .npy files (the two matrices are never both in memory), and deleted as
soon as they are compared; the exact matrix is kept until the mesh's epsilons are done.

The contract (README, "DGG-VTP"): every vertex's distance D satisfies
    exact * (1 - 1e-12) <= D <= exact * (1 + epsilon)
and a vertex unreachable in one is unreachable in the other (inf in both); anything else, a NaN
included, is a violation. --budget F checks D <= exact * (1 + F * epsilon) instead (F < 1: how
much margin the rule keeps; the tests use it to show that a violation fails the run).

With every vertex a source, the exact rows are also checked against themselves: a geodesic
distance is symmetric, so |d(s, v) - d(v, s)| / d above 1e-9 (the exact mode agrees with CGAL's
Surface_mesh_shortest_path to about 1e-15) means that the exact mode missed the shorter path from
one of the two sides; such pairs count as violations (a second table, per mesh).

--precision float: the reference stays the exact mode in double; the float exact mode and every
float epsilon are checked as
    exact * (1 - t) <= D <= exact * (1 + epsilon) * (1 + t),   t = FLOAT_ROUNDING = 2^-23,
the float exact mode being the row "exact" of the table (epsilon 0). Why 2^-23 (1.19e-7): the
float exact mode against the double exact mode on the nine shared meshes (every source of pinion
and spot, 200 seeded sources of blade, cat, fandisk, lion_head and turbine, 50 of bunny and
terrain_jacksboro) is off by at most 5.958e-8 relative either way, below 2^-24 = 5.960e-8: the
float result is the double one rounded once to float (the propagation runs in double at least;
the manual says so), "up to its final rounding". t is twice that rounding: the rounding itself,
and as much again for the double reference's own error and the double contract's 1e-12 below.
This holds for meshes whose coordinates are floats (the shared and the generated meshes): on
double coordinates the float run moves the points too, by more than that.

Per mesh and epsilon one table row: the largest error / epsilon with its (source, vertex), the
lowest relative error (D - exact) / exact, the number of violations, and the time ratio
epsilon / exact mode of the rows (`seconds_compute_per_rank` of dggvtp-batch --stats, summed over
the ranks: wall seconds of the rows alone; and the CPU seconds of the processes, `cpu_seconds`,
steadier on a shared machine). Exit status: 0 no violation, 1 a violation (or an asymmetric pair),
2 bad input (no dggvtp-batch, a mesh that cannot be read or that the input policy refuses, a
failed run), with an `error:` line.

--bounds (issue 45) also checks the certified error of every distance: the same rows through the
Python module (build/python: distances_from_each(return_bounds=True)), the same bits as the batch's,
with bounds b such that
    d - b <= exact * (1 + 1e-12)   and   0 <= b <= epsilon * d * (1 + 1e-12)
(float: t added as above); a vertex outside is a violation, and the table gains the largest and
the mean b / (epsilon d).

Example (from the repository root, after building dggvtp-batch in build/):
  /usr/bin/python3 benchmark/DGG_VTP_3/adversary.py data/meshes/pinion.ply --epsilons 1e-1 1e-3 1e-5
  /usr/bin/python3 benchmark/DGG_VTP_3/adversary.py --mesh data/meshes/blade.ply --sample 200 --seed 1 \\
          --markdown blade.md --json blade.json
"""
import argparse
import datetime
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exact_vs_smsp import REPO, machine, revision  # noqa: E402

EPSILONS = (1, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-7)
BELOW_EXACT = 1e-12         # the contract's lower end in double: exact * (1 - 1e-12)
FLOAT_ROUNDING = 2. ** -23  # t of the float check (see the module's docstring)
BLOCK_BYTES = 64 << 20      # rows compared at a time: about this many bytes of each matrix
EXAMPLES = 20               # violations kept per mesh and epsilon for the JSON (the first ones)
ASYMMETRY = 1e-9            # |d(s, v) - d(v, s)| / d above which the exact mode missed a path


class Failure(Exception):
    """Bad input or a failed run: reported as `error: ...`, exit status 2."""


def contract_interval(epsilon, budget=1., rounding=0.):
    """(lowest, highest) allowed relative error (D - exact) / exact at epsilon (0 = exact mode).

    Double: D in [exact (1 - 1e-12), exact (1 + budget epsilon)]; with rounding t (float):
    D in [exact (1 - t), exact (1 + budget epsilon) (1 + t)].
    """
    low = rounding if rounding > 0 else BELOW_EXACT
    return -low, (1 + budget * epsilon) * (1 + rounding) - 1


def relative_errors(exact, d):
    """(D - exact) / exact per element, with the contract's special cases folded in.

    Both inf (unreachable in both): 0. Reachable in one only, or D NaN: +inf when D is the larger
    (or NaN), -inf when D is finite and exact is inf. exact 0 (the source): 0 if D is 0, else
    +inf or -inf by D's sign.
    """
    exact = np.asarray(exact, dtype=np.float64)
    d = np.asarray(d, dtype=np.float64)
    rel = np.zeros(np.broadcast(exact, d).shape)
    finite_e, finite_d = np.isfinite(exact), np.isfinite(d)
    both = finite_e & finite_d
    positive = both & (exact > 0)
    rel[positive] = (d[positive] - exact[positive]) / exact[positive]
    at_zero = both & (exact == 0)
    rel[at_zero & (d > 0)] = np.inf
    rel[at_zero & (d < 0)] = -np.inf
    rel[finite_e & ~finite_d] = np.inf             # D inf or NaN where exact is finite
    rel[~finite_e & finite_d] = -np.inf            # D finite where exact is unreachable
    rel[np.isnan(d) | np.isnan(exact)] = np.inf    # NaN anywhere is a violation
    return rel


class Tally:
    """The comparison of one epsilon's rows with the exact rows, accumulated block by block."""

    def __init__(self, epsilon, budget=1., rounding=0.):
        self.epsilon = epsilon
        self.low, self.high = contract_interval(epsilon, budget, rounding)
        self.max_rel, self.max_at = -np.inf, None   # largest relative error, (row, vertex)
        self.min_rel, self.min_at = np.inf, None    # lowest relative error, (row, vertex)
        self.violations = 0                         # vertices outside the interval, all rows
        self.below = 0                              # of which below it: the exact row too long, or D no path's length
        self.examples = []                          # (row, vertex, exact, D) of the first violations

    def add(self, exact, d, first_row=0):
        """Compares a block of rows (2-D arrays, row `first_row` of the matrix first)."""
        exact = np.asarray(exact, dtype=np.float64)
        d = np.asarray(d, dtype=np.float64)
        if exact.shape != d.shape:
            raise Failure(f'rows of shape {d.shape} compared with exact rows of shape {exact.shape}')
        if exact.size == 0:
            return
        rel = relative_errors(exact, d)
        r, v = np.unravel_index(int(np.argmax(rel)), rel.shape)
        if rel[r, v] > self.max_rel:
            self.max_rel, self.max_at = float(rel[r, v]), (first_row + int(r), int(v))
        r, v = np.unravel_index(int(np.argmin(rel)), rel.shape)
        if rel[r, v] < self.min_rel:
            self.min_rel, self.min_at = float(rel[r, v]), (first_row + int(r), int(v))
        bad = ~((rel >= self.low) & (rel <= self.high))
        count = int(np.count_nonzero(bad))
        self.below += int(np.count_nonzero(rel < self.low))
        if count and len(self.examples) < EXAMPLES:
            for r, v in zip(*np.nonzero(bad)):
                if len(self.examples) == EXAMPLES:
                    break
                self.examples.append((first_row + int(r), int(v), float(exact[r, v]), float(d[r, v])))
        self.violations += count


def compare_files(exact_path, rows_path, epsilon, budget=1., rounding=0.):
    """A Tally of the .npy rows at rows_path against the exact .npy rows, a block of rows at a time.

    Both files are memory-mapped; a block holds about BLOCK_BYTES of each.
    """
    exact = np.load(exact_path, mmap_mode='r')
    rows = np.load(rows_path, mmap_mode='r')
    if exact.ndim != 2 or exact.shape != rows.shape:
        raise Failure(f'{rows_path} has shape {rows.shape}, the exact rows {exact_path} {exact.shape}')
    tally = Tally(epsilon, budget, rounding)
    step = max(1, BLOCK_BYTES // max(1, exact.shape[1] * 8))
    for first in range(0, exact.shape[0], step):
        tally.add(exact[first:first + step], rows[first:first + step], first)
    return tally


class Symmetry:
    """The exact mode against itself: with every vertex a source, d(s, v) = d(v, s)."""

    def __init__(self):
        self.max_rel, self.max_at = 0., None   # largest |d(s, v) - d(v, s)| / max of both, (s, v)
        self.pairs = 0                         # pairs (s < v) above ASYMMETRY, or reachable one way only

    def add(self, block, mirrored, first_row, first_column):
        """Compares block = d[rows, columns] with mirrored = d[columns, rows].T, pairs s < v only."""
        a = np.asarray(block, dtype=np.float64)
        b = np.asarray(mirrored, dtype=np.float64)
        rows = first_row + np.arange(a.shape[0])[:, None]
        columns = first_column + np.arange(a.shape[1])[None, :]
        larger = np.maximum(a, b)
        with np.errstate(invalid='ignore'):
            rel = np.where(a == b, 0., np.abs(a - b) / larger)   # inf both ways: equal; one way only: nan
        rel[np.isnan(rel)] = np.inf
        rel[rows >= columns] = 0.
        r, c = np.unravel_index(int(np.argmax(rel)), rel.shape)
        if rel[r, c] > self.max_rel:
            self.max_rel, self.max_at = float(rel[r, c]), (first_row + int(r), first_column + int(c))
        self.pairs += int(np.count_nonzero(rel > ASYMMETRY))


def check_symmetry(exact_path):
    """A Symmetry of the square exact matrix, square tiles of about BLOCK_BYTES against their mirror."""
    d = np.load(exact_path, mmap_mode='r')
    side = max(1, int((BLOCK_BYTES // 8) ** 0.5))
    symmetry = Symmetry()
    for i in range(0, d.shape[0], side):
        for j in range(i, d.shape[1], side):
            symmetry.add(d[i:i + side, j:j + side], d[j:j + side, i:i + side].T, i, j)
    return symmetry


class Batch:
    """dggvtp-batch on one mesh and one source list, its files in a work folder."""

    def __init__(self, exe, mesh, sources, threads, workdir, quiet):
        self.exe, self.mesh, self.sources, self.threads = exe, mesh, sources, threads
        self.workdir, self.quiet = workdir, quiet

    def run(self, name, epsilon, precision):
        """Runs the rows at epsilon (0: --exact) in precision; (path of the .npy, stats dict)."""
        out = os.path.join(self.workdir, name + '.npy')
        stats = os.path.join(self.workdir, name + '.json')
        command = [self.exe, self.mesh, '--sources', self.sources, '--output', out, '--stats', stats, '--quiet',
                   '--precision', precision, '--dtype', 'float32' if precision == 'float' else 'float64',
                   '--threads', str(self.threads)]
        command += ['--exact'] if epsilon == 0 else ['--epsilon', repr(float(epsilon))]
        try:
            r = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        except OSError as e:
            raise Failure(f'cannot run {self.exe}: {e}') from None
        if r.returncode != 0:
            lines = [line for line in r.stderr.splitlines() if line.strip()]
            said = lines[-1].removeprefix('error: ') if lines else 'no message'
            raise Failure(f"dggvtp-batch {' '.join(command[1:])}: exit status {r.returncode}: {said}")
        if r.stderr.strip() and not self.quiet:
            sys.stderr.write(r.stderr)
        with open(stats) as f:
            return out, json.load(f)


def vertex_count(exe, mesh, workdir):
    """The vertices of the mesh as dggvtp-batch reads it (one row from vertex 0; checks the mesh)."""
    probe = os.path.join(workdir, 'probe.txt')
    with open(probe, 'w') as f:
        f.write('0\n')
    _, stats = Batch(exe, mesh, probe, 1, workdir, True).run('probe', 0, 'double')
    os.remove(os.path.join(workdir, 'probe.npy'))
    return stats['vertices']


def sample_sources(vertices, count, seed):
    """count distinct vertices of 0..vertices-1, increasing, the same for the same seed."""
    rng = np.random.default_rng(seed)
    return np.sort(rng.choice(vertices, size=count, replace=False))


def seconds(stats):
    """(wall seconds of the rows, CPU seconds) of a dggvtp-batch --stats object."""
    return sum(stats['seconds_compute_per_rank']), sum(stats['cpu_seconds'])


def built_at(path):
    """When the binary at path was written (UTC), to tell the library it holds."""
    return datetime.datetime.fromtimestamp(os.path.getmtime(path), datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')


def table_header(bounds=False):
    return ['| mesh | vertices | sources | precision | epsilon | max err/eps | at (source, vertex) | max rel. err '
            '| lowest rel. err | violations | of which below | time eps/exact (wall) | (CPU) | exact rows (s) |'
            + (' bound/eps: max | mean | bound violations |' if bounds else ''),
            '|---|---:|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|' + ('---:|---:|---:|' if bounds else '')]


def table_row(r):
    """One Markdown row of a result record."""
    eps = 'exact' if r['epsilon'] == 0 else f"{r['epsilon']:g}"
    over = '-' if r['epsilon'] == 0 else f"{r['max_over_eps']:.3f}"
    at = '-' if r['max_at'] is None else f"({r['max_at'][0]}, {r['max_at'][1]})"
    return (f"| {r['mesh']} | {r['vertices']} | {r['sources']} | {r['precision']} | {eps} | {over} | {at} "
            f"| {r['max_rel']:.2e} | {r['min_rel']:.1e} | {r['violations']} | {r['below']} | {r['time_ratio']:.2f} "
            f"| {r['cpu_ratio']:.2f} | {r['exact_seconds']:.2f} |"
            + ('' if r.get('bound_violations') is None else
               f" {r['bound_max_over_eps']:.3f} | {r['bound_mean_over_eps']:.3f} | {r['bound_violations']} |"))


def symmetry_header():
    return ['| mesh | vertices | exact mode: max abs(d(s, v) - d(v, s)) / d | at (s, v) | pairs above 1e-9 |',
            '|---|---:|---:|---|---:|']


def symmetry_row(r):
    at = '-' if r['max_at'] is None else f"({r['max_at'][0]}, {r['max_at'][1]})"
    return f"| {r['mesh']} | {r['vertices']} | {r['max_rel']:.1e} | {at} | {r['pairs']} |"


def check_bounds(solver, rows_path, exact_path, sources, epsilon, rounding):
    """--bounds: the rows and certified errors of the module against the batch's rows and the exact
    rows, a block of sources at a time: (violations, largest b / (epsilon d), mean, first violations)"""
    exact = np.load(exact_path, mmap_mode='r')
    batch_rows = np.load(rows_path, mmap_mode='r')
    step = max(1, BLOCK_BYTES // max(1, exact.shape[1] * 8))
    violations, largest, total, count, examples = 0, 0., 0., 0, []
    for first in range(0, len(sources), step):
        block = sources[first:first + step]
        d, b = solver.distances_from_each(block, epsilon=epsilon, return_bounds=True)
        e = np.asarray(exact[first:first + len(block)], dtype=np.float64)
        bad = np.asarray(batch_rows[first:first + len(block)], dtype=np.float64) != d
        bad &= ~(np.isnan(d) & np.isnan(np.asarray(batch_rows[first:first + len(block)], dtype=np.float64)))
        at = np.isfinite(e) & (e > 0)
        with np.errstate(invalid='ignore'):
            bad |= ~(np.isinf(b) == np.isinf(d))
            bad[at] |= ~((d[at] - b[at] <= e[at] * (1 + 1e-12) * (1 + rounding)) & (b[at] >= 0)
                         & (b[at] <= epsilon * d[at] * (1 + 1e-12) * (1 + rounding)))
            ratio = b[at] / (epsilon * d[at])
        violations += int(np.count_nonzero(bad))
        for r, v in zip(*np.nonzero(bad)):
            if len(examples) == EXAMPLES:
                break
            examples.append((first + int(r), int(v), float(e[r, v]), float(d[r, v]), float(b[r, v])))
        if ratio.size:
            largest = max(largest, float(np.nanmax(ratio)))
            total += float(np.nansum(ratio))
            count += ratio.size
    return violations, largest, total / count if count else 0., examples


def module_solver(a, mesh, precision):
    """--bounds: a GeodesicSolver of the Python module built beside dggvtp-batch"""
    sys.path.insert(0, os.path.join(a.build, 'python'))
    try:
        import dggvtp
    except ImportError as e:
        raise Failure(f'--bounds needs the Python module in {a.build}/python (build the target dggvtp_python): {e}')
    return dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh), precision=precision)


def check_mesh(a, exe, mesh, workdir, say):
    """Every epsilon of one mesh against its exact rows: (result records, the exact mode's symmetry
    record, None unless every vertex is a source)."""
    name = os.path.splitext(os.path.basename(mesh))[0]
    vertices = vertex_count(exe, mesh, workdir)
    if a.sample is not None and a.sample < vertices:
        chosen = sample_sources(vertices, a.sample, a.seed)
        sources = os.path.join(workdir, 'sources.txt')
        np.savetxt(sources, chosen, fmt='%d')
        chosen = chosen.tolist()
    else:
        sources, chosen = 'all', None
    rows = len(chosen) if chosen is not None else vertices
    batch = Batch(exe, mesh, sources, a.threads, workdir, a.quiet)
    say(f'{name}: {vertices} vertices, {rows} sources, exact mode (double)')
    exact, exact_stats = batch.run('exact', 0, 'double')
    symmetry = None
    if chosen is None:
        found = check_symmetry(exact)
        symmetry = {'mesh': name, 'vertices': vertices, 'max_rel': found.max_rel, 'max_at': found.max_at,
                    'pairs': found.pairs}
    runs = [(e, a.precision) for e in a.epsilons]
    base_stats = exact_stats
    if a.precision == 'float':
        runs.insert(0, (0, 'float'))   # the float exact mode: the time base, and checked within t
    records = []
    for epsilon, precision in runs:
        say(f'{name}: epsilon {epsilon:g} ({precision})')
        start = time.monotonic()
        path, stats = batch.run(f'eps{epsilon:g}', epsilon, precision)
        ran = time.monotonic() - start
        tally = compare_files(exact, path, epsilon, a.budget, FLOAT_ROUNDING if precision == 'float' else 0.)
        bounds = None
        if a.bounds and epsilon > 0:
            bounds = check_bounds(module_solver(a, mesh, precision), path, exact,
                                  chosen if chosen is not None else list(range(vertices)), epsilon,
                                  FLOAT_ROUNDING if precision == 'float' else 0.)
        os.remove(path)
        (wall, cpu), (base_wall, base_cpu) = seconds(stats), seconds(base_stats)
        if epsilon == 0:
            base_stats = stats   # the float exact mode's row: its time against double's; the next ones against it
        source_of = (lambda row: chosen[row]) if chosen is not None else (lambda row: row)
        at = lambda p: None if p is None else [source_of(p[0]), p[1]]  # noqa: E731
        records.append({
            'mesh': name, 'file': mesh, 'vertices': vertices, 'sources': rows, 'precision': precision,
            'epsilon': epsilon, 'budget': a.budget,
            'max_rel': tally.max_rel, 'max_over_eps': tally.max_rel / epsilon if epsilon else None,
            'max_at': at(tally.max_at), 'min_rel': tally.min_rel, 'min_at': at(tally.min_at),
            'violations': tally.violations, 'below': tally.below, 'interval': [tally.low, tally.high],
            'examples': [[source_of(r), v, e, d] for r, v, e, d in tally.examples],
            'seconds': wall, 'exact_seconds': base_wall, 'time_ratio': wall / base_wall if base_wall else float('nan'),
            'cpu_seconds': cpu, 'exact_cpu_seconds': base_cpu,
            'cpu_ratio': cpu / base_cpu if base_cpu else float('nan'),
            'seconds_run': ran, 'stats': stats, 'exact_stats': base_stats,
            'source_list': chosen, 'seed': a.seed if chosen is not None else None,
            'bound_violations': bounds[0] if bounds else None, 'bound_max_over_eps': bounds[1] if bounds else None,
            'bound_mean_over_eps': bounds[2] if bounds else None,
            'bound_examples': [[source_of(r), v, e, d, b] for r, v, e, d, b in bounds[3]] if bounds else None})
        print(table_row(records[-1]), flush=True)
    os.remove(exact)
    return records, symmetry


def epsilon_list(values):
    """The --epsilons values (separated by spaces or commas), each in (0, 1]."""
    out = []
    for value in values:
        for item in value.replace(',', ' ').split():
            try:
                e = float(item)
            except ValueError:
                raise Failure(f'--epsilons: {item!r} is not a number') from None
            if not 0 < e <= 1:
                raise Failure(f'--epsilons: {item} is outside (0, 1]')
            out.append(e)
    if not out:
        raise Failure('--epsilons: no value')
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('meshes', nargs='*', metavar='MESH', help='mesh files (OFF, OBJ, PLY, STL)')
    p.add_argument('--mesh', action='append', default=[], help='a mesh file (repeatable; added to MESH)')
    p.add_argument('--build', default=os.path.join(REPO, 'build'),
                   help='build directory holding bin/dggvtp-batch (default: <repo>/build)')
    p.add_argument('--sources', choices=['all'], default='all', help='every vertex as a source (the default)')
    p.add_argument('--sample', type=int, metavar='K',
                   help='K distinct vertices chosen with --seed instead (every vertex if K >= the vertices)')
    p.add_argument('--seed', type=int, default=0, help='seed of --sample (default 0)')
    p.add_argument('--epsilons', nargs='+', default=[' '.join(map(str, EPSILONS))], metavar='E',
                   help='epsilons in (0, 1], separated by spaces or commas (default: 1 1e-1 1e-2 1e-3 1e-4 1e-5 '
                        '1e-7)')
    p.add_argument('--precision', choices=['double', 'float'], default='double',
                   help='the computation of the epsilon rows (the exact reference is always double)')
    p.add_argument('--budget', type=float, default=1., metavar='F',
                   help='check D <= exact (1 + F epsilon) (default 1: the contract)')
    p.add_argument('--threads', type=int, default=1, metavar='T', help='threads of dggvtp-batch (default 1)')
    p.add_argument('--workdir', help='folder for the temporary .npy files (default: a new one in $TMPDIR)')
    p.add_argument('--markdown', metavar='FILE', help='write the table (Markdown, with date and machine) here')
    p.add_argument('--json', metavar='FILE', help='write every record (and the first violations) here')
    p.add_argument('--bounds', action='store_true',
                   help='check the certified error bounds too, through the Python module (see above)')
    p.add_argument('--quiet', action='store_true', help='no progress lines on stderr')
    a = p.parse_args()
    say = (lambda _: None) if a.quiet else (lambda text: print(f'adversary: {text}', file=sys.stderr, flush=True))
    try:
        a.epsilons = epsilon_list(a.epsilons)
        meshes = a.meshes + a.mesh
        if not meshes:
            raise Failure('no mesh given (positional MESH or --mesh FILE)')
        if a.sample is not None and a.sample < 1:
            raise Failure(f'--sample {a.sample}: at least 1 source')
        if a.budget <= 0:
            raise Failure(f'--budget {a.budget}: must be positive')
        if a.threads < 0:
            raise Failure(f'--threads {a.threads}: must be 0 (all cores) or more')
        exe = os.path.join(a.build, 'bin', 'dggvtp-batch')
        if not os.access(exe, os.X_OK):
            raise Failure(f'{exe} is not an executable (build the target dggvtp-batch, or pass --build DIR)')
        for mesh in meshes:
            if not os.path.isfile(mesh) or not os.access(mesh, os.R_OK):
                raise Failure(f'{mesh}: not a readable file')
        for out in (a.markdown, a.json):
            if out and not os.access(os.path.dirname(os.path.abspath(out)), os.W_OK):
                raise Failure(f'{out}: its folder is not writable')
        if a.workdir:
            os.makedirs(a.workdir, exist_ok=True)
        workdir = tempfile.mkdtemp(prefix='adversary.', dir=a.workdir)
    except (Failure, OSError) as e:
        print(f'error: {e}', file=sys.stderr)
        return 2

    started = datetime.datetime.now().strftime('%Y-%m-%d %H:%M')
    load_before = os.getloadavg()
    print('\n'.join(table_header(a.bounds)), flush=True)
    records, symmetries = [], []
    try:
        for mesh in meshes:
            found, symmetry = check_mesh(a, exe, os.path.abspath(mesh), workdir, say)
            records += found
            symmetries += [symmetry] if symmetry else []
    except (Failure, OSError) as e:
        print(f'error: {e}', file=sys.stderr)
        return 2
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    load_after = os.getloadavg()
    # the binaries may be older than the checkout: say which were run
    stamp = (f"{started} to {datetime.datetime.now().strftime('%H:%M')}, {revision()} checked out, binaries of "
             f"{os.path.abspath(a.build)} (built {built_at(exe)}), {machine()}, "
             f"load average {load_before[0]:.1f} before, {load_after[0]:.1f} after")
    symmetry_table = symmetry_header() + [symmetry_row(r) for r in symmetries] if symmetries else []
    if symmetry_table:
        print('\n' + '\n'.join(symmetry_table), flush=True)
    if a.markdown:
        with open(a.markdown, 'w') as f:
            f.write(f'{stamp}\n\n' + '\n'.join(table_header(a.bounds) + [table_row(r) for r in records]) + '\n'
                    + ('\n' + '\n'.join(symmetry_table) + '\n' if symmetry_table else ''))
    if a.json:
        with open(a.json, 'w') as f:
            json.dump({'when': stamp, 'command': sys.argv, 'float_rounding': FLOAT_ROUNDING,
                       'asymmetry': ASYMMETRY, 'records': records, 'symmetry': symmetries}, f, indent=1)
    for r in records:
        if r['violations']:
            eps = 'exact' if r['epsilon'] == 0 else f"{r['epsilon']:g}"
            print(f"violation: {r['mesh']} ({r['precision']}) epsilon {eps}: {r['violations']} vertices outside "
                  f"[{r['interval'][0]:.3g}, {r['interval'][1]:.3g}] relative; largest {r['max_rel']:.3g} at "
                  f"(source, vertex) {tuple(r['max_at'])}, lowest {r['min_rel']:.3g} at {tuple(r['min_at'])}",
                  file=sys.stderr)
    for r in symmetries:
        if r['pairs']:
            print(f"violation: {r['mesh']}: the exact mode is not symmetric: {r['pairs']} pairs with "
                  f"|d(s, v) - d(v, s)| above {ASYMMETRY:g} relative, at most {r['max_rel']:.3g} at (s, v) "
                  f"{tuple(r['max_at'])}", file=sys.stderr)
    for r in records:
        if r['bound_violations']:
            print(f"violation: {r['mesh']} ({r['precision']}) epsilon {r['epsilon']:g}: {r['bound_violations']} "
                  f"vertices whose certified bound fails (source, vertex, exact, d, bound): "
                  f"{r['bound_examples'][:3]}", file=sys.stderr)
    violations = (sum(r['violations'] for r in records) + sum(r['pairs'] for r in symmetries)
                  + sum(r['bound_violations'] or 0 for r in records))
    say(f'{len(records)} rows, {violations} violations ({stamp})')
    return 1 if violations else 0


if __name__ == '__main__':
    sys.exit(main())
