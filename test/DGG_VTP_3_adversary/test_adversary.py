#!/usr/bin/env python3
"""Unit tests of benchmark/DGG_VTP_3/adversary.py's comparison, and of hard_meshes.py's determinism.

The comparison is what decides that a run violates the contract, so it is tested on fabricated rows
with known violations (just outside the interval, just inside, unreachable in one, NaN, below the
exact distance), on .npy files compared in several blocks, and on float32 files. With the
environment variable DGGVTP_BUILD (a build folder with bin/dggvtp-batch; CTest sets it), also the
script's exit status on bad input.

  /usr/bin/python3 test/DGG_VTP_3_adversary/test_adversary.py [-v]
"""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
BENCHMARK = os.path.normpath(os.path.join(HERE, '..', '..', 'benchmark', 'DGG_VTP_3'))
sys.path.insert(0, BENCHMARK)
import adversary  # noqa: E402

SCRIPT = os.path.join(BENCHMARK, 'adversary.py')
GENERATOR = os.path.join(BENCHMARK, 'hard_meshes.py')
MESH = os.path.normpath(os.path.join(HERE, '..', '..', 'data', 'meshes', 'pinion.ply'))


def exact_rows(rows=6, vertices=9, seed=1):
    """Rows like the exact mode's: 0 at the row's source (vertex row % vertices), positive elsewhere."""
    d = np.random.default_rng(seed).uniform(0.5, 2.0, (rows, vertices))
    d[np.arange(rows), np.arange(rows) % vertices] = 0
    return d


class Relative_errors(unittest.TestCase):
    def test_special_cases(self):
        inf, nan = np.inf, np.nan
        exact = np.array([2., 2., inf, inf, 2., 0., 0., 0., nan])
        d = np.array([3., inf, inf, 5., nan, 0., 1e-300, -1e-300, 1.])
        self.assertEqual(adversary.relative_errors(exact, d).tolist(),
                         [0.5, inf, 0., -inf, inf, 0., inf, -inf, inf])


class Contract(unittest.TestCase):
    def check(self, exact, d, epsilon, **kw):
        t = adversary.Tally(epsilon, **kw)
        t.add(exact, d)
        return t

    def test_equal_rows_pass(self):
        e = exact_rows()
        t = self.check(e, e.copy(), 1e-3)
        self.assertEqual(t.violations, 0)
        self.assertEqual(t.max_rel, 0.)

    def test_just_above_epsilon_fails_just_below_passes(self):
        for eps in (1., 1e-1, 1e-4, 1e-7):
            e = exact_rows()
            d = e.copy()
            d[2, 5] = e[2, 5] * (1 + 1.001 * eps)
            t = self.check(e, d, eps)
            self.assertEqual((t.violations, t.max_at), (1, (2, 5)), eps)
            self.assertAlmostEqual(t.max_rel / eps, 1.001, places=6)
            self.assertEqual(t.examples[0][:2], (2, 5))
            d[2, 5] = e[2, 5] * (1 + 0.999 * eps)
            self.assertEqual(self.check(e, d, eps).violations, 0, eps)

    def test_below_exact(self):
        e = exact_rows()
        d = e.copy()
        d[1, 7] = e[1, 7] * (1 - 2e-12)
        d[2, 4] = e[2, 4] * (1 + 2e-2)
        t = self.check(e, d, 1e-2)
        self.assertEqual((t.violations, t.below, t.min_at), (2, 1, (1, 7)))
        d[1, 7] = e[1, 7] * (1 - 1e-13)
        self.assertEqual((self.check(e, d, 1e-2).violations, self.check(e, d, 1e-2).below), (1, 0))

    def test_unreachable_must_agree(self):
        e = exact_rows()
        e[:, 8] = np.inf                      # an isolated vertex: unreachable from every source
        d = e.copy()
        self.assertEqual(self.check(e, d, 1e-2).violations, 0)
        d[3, 8] = 1.                          # reached although unreachable
        d[4, 6] = np.inf                      # lost
        d[5, 2] = np.nan
        t = self.check(e, d, 1e-2)
        self.assertEqual(t.violations, 3)
        self.assertEqual(sorted(x[:2] for x in t.examples), [(3, 8), (4, 6), (5, 2)])

    def test_source_must_be_zero(self):
        e = exact_rows()
        d = e.copy()
        d[0, 0] = 1e-300
        self.assertEqual(self.check(e, d, 1.).violations, 1)

    def test_budget(self):
        e = exact_rows()
        d = e * (1 + 0.5e-3)
        self.assertEqual(self.check(e, d, 1e-3).violations, 0)
        self.assertEqual(self.check(e, d, 1e-3, budget=0.4).violations, np.count_nonzero(e))

    def test_float_rounding(self):
        t = 2 ** -23
        e = exact_rows()
        d = e * (1 + 1e-2) * (1 + 0.9 * t)
        self.assertEqual(self.check(e, d, 1e-2).violations, np.count_nonzero(e))
        self.assertEqual(self.check(e, d, 1e-2, rounding=t).violations, 0)
        self.assertEqual(self.check(e, e * (1 + 1.1 * t), 0, rounding=t).violations, np.count_nonzero(e))
        self.assertEqual(self.check(e, e * (1 - 0.9 * t), 0, rounding=t).violations, 0)
        self.assertEqual(self.check(e, e * (1 - 1.1 * t), 0, rounding=t).violations, np.count_nonzero(e))

    def test_the_float_exact_mode_passes(self):
        """float results rounded from double ones are within FLOAT_ROUNDING of them."""
        e = exact_rows(40, 500)
        d = e.astype(np.float32).astype(np.float64)
        self.assertEqual(self.check(e, d, 0, rounding=adversary.FLOAT_ROUNDING).violations, 0)


class Files(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)
        self.block = adversary.BLOCK_BYTES
        self.addCleanup(setattr, adversary, 'BLOCK_BYTES', self.block)

    def save(self, name, array):
        path = os.path.join(self.folder.name, name)
        np.save(path, array)
        return path

    def test_violation_in_the_last_block(self):
        e = exact_rows(50, 30)
        d = e.copy()
        d[49, 3] *= 1 + 2e-4
        d[10, 4] *= 1 + 0.5e-4
        adversary.BLOCK_BYTES = 7 * 30 * 8    # 7 rows a block: 8 blocks
        t = adversary.compare_files(self.save('e.npy', e), self.save('d.npy', d), 1e-4)
        self.assertEqual((t.violations, t.max_at), (1, (49, 3)))
        self.assertAlmostEqual(t.max_rel, 2e-4)

    def test_float32_rows(self):
        e = exact_rows(8, 20)
        d = (e * (1 + 1e-2)).astype(np.float32)
        path = self.save('d.npy', d)
        self.assertEqual(np.load(path).dtype, np.float32)
        exact = self.save('e.npy', e)
        self.assertEqual(adversary.compare_files(exact, path, 1e-2).violations, np.count_nonzero(d > e * 1.01))
        self.assertEqual(adversary.compare_files(exact, path, 1e-2, rounding=adversary.FLOAT_ROUNDING).violations, 0)

    def test_shapes_must_agree(self):
        with self.assertRaises(adversary.Failure):
            adversary.compare_files(self.save('e.npy', exact_rows(4, 9)), self.save('d.npy', exact_rows(4, 8)), 1.)


class Exact_symmetry(unittest.TestCase):
    """With every vertex a source, the exact matrix must be symmetric: a missed path shows."""

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)
        self.addCleanup(setattr, adversary, 'BLOCK_BYTES', adversary.BLOCK_BYTES)
        e = exact_rows(23, 23)
        self.exact = np.minimum(e, e.T)
        self.exact[22, :] = self.exact[:, 22] = np.inf   # an isolated vertex
        self.exact[22, 22] = 0

    def check(self, d):
        path = os.path.join(self.folder.name, 'e.npy')
        np.save(path, d)
        adversary.BLOCK_BYTES = 8 * 5 * 5   # tiles of 5 x 5: diagonal and off-diagonal ones
        return adversary.check_symmetry(path)

    def test_symmetric(self):
        found = self.check(self.exact)
        self.assertEqual((found.pairs, found.max_rel), (0, 0.))

    def test_a_missed_path(self):
        d = self.exact.copy()
        d[17, 3] *= 1 + 1e-3
        d[4, 9] *= 1 + 1e-12          # rounding: not counted
        found = self.check(d)
        self.assertEqual((found.pairs, found.max_at), (1, (3, 17)))
        self.assertAlmostEqual(found.max_rel, 1e-3 / (1 + 1e-3))

    def test_reachable_one_way(self):
        d = self.exact.copy()
        d[22, 5] = 1.
        found = self.check(d)
        self.assertEqual((found.pairs, found.max_at, found.max_rel), (1, (5, 22), np.inf))


class Certified_bounds(unittest.TestCase):
    """--bounds: check_bounds on fabricated rows and bounds, from a stand-in for the module's solver"""

    class Solver:
        def __init__(self, rows, bounds):
            self.rows, self.bounds = rows, bounds

        def distances_from_each(self, sources, epsilon, return_bounds):
            return self.rows[sources], self.bounds[sources]

    def check(self, rows, bounds, exact, epsilon=0.1, batch_rows=None):
        with tempfile.TemporaryDirectory() as folder:
            exact_path, rows_path = os.path.join(folder, 'e.npy'), os.path.join(folder, 'r.npy')
            np.save(exact_path, exact)
            np.save(rows_path, rows if batch_rows is None else batch_rows)
            return adversary.check_bounds(self.Solver(rows, bounds), rows_path, exact_path,
                                          list(range(len(rows))), epsilon, 0.)

    def test_holding_and_failing_bounds(self):
        exact = exact_rows()
        rows = exact * 1.05
        good = rows - exact                      # the lower bound is the exact distance
        violations, largest, mean, _ = self.check(rows, good, exact)
        self.assertEqual(violations, 0)
        self.assertAlmostEqual(largest, 0.05 / 1.05 / 0.1)
        above = good * 0.5                       # a lower bound above the exact distance
        above[0, 1] = good[0, 1]
        self.assertEqual(self.check(rows, above, exact)[0], rows.size - len(rows) - 1)
        wide = good.copy()
        wide[2, 3] = 0.2 * rows[2, 3]            # wider than epsilon d
        self.assertEqual(self.check(rows, wide, exact)[0], 1)
        negative = good.copy()
        negative[1, 4] = -1e-9
        self.assertEqual(self.check(rows, negative, exact)[0], 1)
        finite = good.copy()
        rows_inf = rows.copy()
        rows_inf[3, 5] = np.inf                  # unreached: the bound must be inf too
        self.assertEqual(self.check(rows_inf, finite, exact, batch_rows=rows_inf)[0], 1)
        other = rows.copy()
        other[4, 6] *= 1 + 1e-15                 # the module's rows differ from the batch's
        self.assertEqual(self.check(other, good, exact, batch_rows=rows)[0], 1)


class Command_line(unittest.TestCase):
    def run_script(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)

    def assert_error(self, r, text):
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn('error: ', r.stderr)
        self.assertIn(text, r.stderr)

    def test_missing_binary(self):
        with tempfile.TemporaryDirectory() as folder:
            self.assert_error(self.run_script(MESH, '--build', folder), 'dggvtp-batch')

    def test_bad_epsilons(self):
        self.assert_error(self.run_script(MESH, '--epsilons', '0'), 'outside (0, 1]')
        self.assert_error(self.run_script(MESH, '--epsilons', '1e-2,x'), 'not a number')

    @unittest.skipUnless(os.environ.get('DGGVTP_BUILD'), 'DGGVTP_BUILD (a build folder) not set')
    def test_mesh_that_cannot_be_read(self):
        with tempfile.TemporaryDirectory() as folder:
            garbage = os.path.join(folder, 'garbage.off')
            with open(garbage, 'w') as f:
                f.write('OFF\n3 1 0\n0 0 0\n')
            build = os.environ['DGGVTP_BUILD']
            self.assert_error(self.run_script(garbage, '--build', build), 'garbage.off')
            self.assert_error(self.run_script(os.path.join(folder, 'missing.ply'), '--build', build),
                              'not a readable file')


class Generator(unittest.TestCase):
    def test_same_bytes_every_run(self):
        with tempfile.TemporaryDirectory() as folder:
            for run in ('a', 'b'):
                r = subprocess.run([sys.executable, GENERATOR, os.path.join(folder, run), '--small', '--check', 'no',
                                    '--quiet'], capture_output=True, text=True)
                self.assertEqual(r.returncode, 0, r.stderr)
            names = sorted(os.listdir(os.path.join(folder, 'a')))
            self.assertGreaterEqual(len(names), 3)
            for name in names:
                with open(os.path.join(folder, 'a', name), 'rb') as a, open(os.path.join(folder, 'b', name), 'rb') as b:
                    self.assertEqual(a.read(), b.read(), name)


if __name__ == '__main__':
    unittest.main()
