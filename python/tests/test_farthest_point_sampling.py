"""farthest_point_sampling(): against a loop over distances() (the greedy sequence, exact), the
certified choice with epsilon, the same samples for any number of threads, bad input, and
components not sampled yet."""
import numpy as np
import pytest

import dggvtp
from conftest import grid, mesh, same_bits


@pytest.fixture(scope="module")
def spot():
    return dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh("spot.ply")))


def greedy(solver, k, epsilon, first=0):
    """what a Python user writes: k whole fields and their minimum"""
    samples, nearest = [first], np.full(solver.num_vertices, np.inf)
    for _ in range(k - 1):
        nearest = np.minimum(nearest, solver.distances(samples[-1]))
        nearest[samples] = -1.0
        samples.append(int(np.argmax(nearest)))
    return samples, np.minimum(nearest, solver.distances(samples[-1]))


def test_exact_is_the_greedy_sequence(spot):
    samples, d, labels = spot.farthest_point_sampling(30, return_distances=True, return_labels=True)
    expected, field = greedy(spot, 30, 0.0)
    assert samples.dtype == np.int64 and samples.shape == (30,)
    assert samples.tolist() == expected
    assert np.allclose(d, np.maximum(field, 0.0), rtol=1e-13, atol=0.0)
    assert labels.dtype == np.int64 and labels.shape == (spot.num_vertices,)
    assert np.all(labels[samples] == np.arange(30))


@pytest.mark.parametrize("epsilon", [1e-1, 1e-3])
def test_with_epsilon_each_sample_is_certified(spot, epsilon):
    samples, d, labels = spot.farthest_point_sampling(25, epsilon=epsilon, first_sample=7, return_distances=True,
                                                      return_labels=True)
    assert samples[0] == 7
    rows = spot.distances_from_each(samples)  # exact
    for i in range(1, 25):
        nearest = rows[:i].min(axis=0)
        assert nearest[samples[i]] * (1 + epsilon) * (1 + 1e-12) >= nearest.max()
    exact = rows.min(axis=0)
    assert np.all(d >= exact * (1 - 1e-12)) and np.all(d <= exact * (1 + epsilon) * (1 + 1e-12))
    assert np.all(rows[labels, np.arange(spot.num_vertices)] <= exact * (1 + epsilon) * (1 + 1e-12))


def test_one_flag_each_and_threads(spot):
    samples = spot.farthest_point_sampling(20, epsilon=1e-2)
    s2, d2 = spot.farthest_point_sampling(20, epsilon=1e-2, threads=2, return_distances=True)
    s3, labels = spot.farthest_point_sampling(20, epsilon=1e-2, threads=0, return_labels=True)
    assert same_bits(samples, s2) and same_bits(samples, s3)
    assert d2.shape == (spot.num_vertices,) and labels.dtype == np.int64


def test_bad_input_is_refused(spot):
    n = spot.num_vertices
    for k in (0, -1, n + 1):
        with pytest.raises(ValueError, match="k must be in"):
            spot.farthest_point_sampling(k)
    for first in (-1, n):
        with pytest.raises(ValueError, match="first"):
            spot.farthest_point_sampling(2, first_sample=first)
    with pytest.raises(ValueError, match="epsilon"):
        spot.farthest_point_sampling(2, epsilon=2.0)
    with pytest.raises(ValueError, match="threads"):
        spot.farthest_point_sampling(2, threads=-1)


def test_unsampled_components_come_first():
    V, F = grid(6)
    solver = dggvtp.GeodesicSolver(np.vstack([V, V + [10.0, 0.0, 0.0]]), np.vstack([F, F + len(V)]))
    samples, d = solver.farthest_point_sampling(3, return_distances=True)
    assert samples[:2].tolist() == [0, len(V)]
    assert np.all(np.isfinite(d))
    one, d1, labels = solver.farthest_point_sampling(1, return_distances=True, return_labels=True)
    assert np.isinf(d1[len(V):]).all() and (labels[len(V):] == -1).all()


@pytest.mark.parametrize("epsilon", [0.0, 1e-2])
def test_bounds_of_the_samples_field(spot, epsilon):
    samples, d, labels, b = spot.farthest_point_sampling(12, epsilon=epsilon, first_sample=4, return_distances=True,
                                                         return_labels=True, return_bounds=True)
    exact = spot.distances(samples)
    assert b.dtype == np.float64 and b.shape == (spot.num_vertices,)
    assert np.all(b >= 0) and np.all(d - b <= exact * (1 + 1e-12)) and np.all(b <= epsilon * d * (1 + 1e-12))
    if epsilon == 0:
        assert np.all(b == 0)
    # one flag at a time: the samples and then what was asked, in the order of distances()
    s2, b2 = spot.farthest_point_sampling(12, epsilon=epsilon, first_sample=4, return_bounds=True)
    assert same_bits(s2, samples) and same_bits(b2, b)
    s3, d3, b3 = spot.farthest_point_sampling(12, epsilon=epsilon, first_sample=4, return_distances=True,
                                              return_bounds=True)
    assert same_bits(d3, d) and same_bits(b3, b)
