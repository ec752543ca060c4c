"""pair_distances(): each pair's value against the exact field of its source, bounds, paths, threads."""
import warnings

import numpy as np
import pytest

import dggvtp
from conftest import mesh, same_bits


@pytest.fixture(scope="module")
def pinion():
    return dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh("pinion.ply")))


def pairs_of(solver, count=40, seed=3):
    rng = np.random.default_rng(seed)
    n = solver.num_vertices
    return rng.integers(0, n, count), rng.integers(0, n, count)


@pytest.mark.parametrize("epsilon", [0.0, 1e-1, 1e-3])
def test_values_keep_the_contract(pinion, epsilon):
    s, t = pairs_of(pinion)
    d = pinion.pair_distances(s, t, epsilon=epsilon)
    assert d.dtype == np.float64 and d.shape == s.shape
    for k in range(len(s)):
        exact = pinion.distances(int(s[k]))[t[k]]
        tolerance = 1e-12 * exact  # the exact mode's rounding
        assert exact - tolerance <= d[k] <= (1 + epsilon) * exact + tolerance, (k, d[k], exact)


def test_bounds_and_paths(pinion):
    s, t = pairs_of(pinion, 12)
    d, errors, paths = pinion.pair_distances(s, t, epsilon=1e-2, return_bounds=True, return_paths=True)
    V = dggvtp.read_mesh(mesh("pinion.ply"))[0]
    for k in range(len(s)):
        exact = pinion.distances(int(s[k]))[t[k]]
        assert 0 <= errors[k] <= 1e-2 * d[k] + 1e-15
        assert d[k] - errors[k] <= exact * (1 + 1e-12)
        assert paths[k].shape[1] == 3
        assert np.allclose(paths[k][0], V[s[k]]) and np.allclose(paths[k][-1], V[t[k]])
        length = np.linalg.norm(np.diff(paths[k], axis=0), axis=1).sum()
        assert length == pytest.approx(d[k], rel=1e-9, abs=1e-12)
    assert same_bits(pinion.pair_distances(s, t, epsilon=1e-2, return_paths=True)[0], d)


def test_same_bits_on_any_number_of_threads(pinion):
    s, t = pairs_of(pinion, 30)
    one = pinion.pair_distances(s, t, epsilon=1e-3, threads=1, return_bounds=True)
    for threads in (2, 4, 8):
        many = pinion.pair_distances(s, t, epsilon=1e-3, threads=threads, return_bounds=True)
        assert same_bits(one[0], many[0]) and same_bits(one[1], many[1])


def test_max_distance_leaves_far_pairs_unreached(pinion):
    s, t = pairs_of(pinion, 20)
    d = pinion.pair_distances(s, t)
    limit = float(np.median(d))
    near = pinion.pair_distances(s, t, max_distance=limit)
    assert np.array_equal(near[d <= limit], d[d <= limit])
    assert np.all(np.isinf(near[d > limit]))


def test_a_source_is_its_own_target(pinion):
    assert pinion.pair_distances([5], [5]).tolist() == [0.0]


def test_bad_pairs_are_refused(pinion):
    with pytest.raises(ValueError, match="same length"):
        pinion.pair_distances([0, 1], [2])
    with pytest.raises(ValueError, match="out of range|range"):
        pinion.pair_distances([0], [pinion.num_vertices])
    with pytest.raises(ValueError, match="epsilon"):
        pinion.pair_distances([0], [1], epsilon=-1)


def test_copies_and_repairs():
    # split vertices (0 and 1, an edge of three faces): the file vertex's smallest distance
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
    with pytest.warns(RuntimeWarning, match="split"):
        solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    s, t = [0, 2, 3, 4, 1], [2, 3, 4, 1, 1]
    d, errors, paths = solver.pair_distances(s, t, return_bounds=True, return_paths=True)
    for k in range(len(s)):
        assert d[k] == solver.target_distances(s[k], [t[k]])[0]
        assert errors[k] >= 0
        assert np.allclose(paths[k][0], V[s[k]]) and np.allclose(paths[k][-1], V[t[k]])
    assert same_bits(solver.pair_distances(s, t, threads=4), d)
    # merged vertices stand at their stand-in's place; a removed one is refused
    V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 0], [1, 1, 0], [5, 5, 5]]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [4, 5, 3]], repair=True)
    assert solver.pair_distances([1, 1], [4, 0]).tolist() == [1.0, 1.0]
    with pytest.raises(ValueError, match="target 6 was removed by repair=True"):
        solver.pair_distances([0], [6])
