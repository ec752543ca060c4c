"""distances(prior_distances=, prior_labels=, prior_bounds=): sources added to the field of earlier
ones (the C++ prior_distance_map, prior_nearest_source_map, prior_lower_bound_map): the field of all
the sources, exact or within the contract, the new sources labelled after the prior ones, from a
field of distances() or of farthest_point_sampling(), and bad prior fields refused."""
import numpy as np
import pytest

import dggvtp
from conftest import mesh


@pytest.fixture(scope="module")
def spot():
    V, F = dggvtp.read_mesh(mesh("spot.ply"))
    return dggvtp.GeodesicSolver(V, F)


def labels_are_nearest(solver, sources, d, labels, rtol):
    """each vertex's label names a source at its distance"""
    rows = solver.distances_from_each(sources)
    at_label = rows[labels, np.arange(solver.num_vertices)]
    return np.allclose(at_label, rows.min(axis=0), rtol=rtol, atol=0)


def test_exact_is_the_field_of_all_the_sources(spot):
    d1, l1 = spot.distances([0, 17], return_labels=True)
    d2, l2 = spot.distances([99, 1500], prior_distances=d1, prior_labels=l1, return_labels=True)
    d, labels = spot.distances([0, 17, 99, 1500], return_labels=True)
    assert np.allclose(d2, d, rtol=1e-13, atol=0)
    assert set(np.unique(l2)) == {0, 1, 2, 3}  # the new sources follow the prior labels
    assert labels_are_nearest(spot, [0, 17, 99, 1500], d2, l2, 1e-13)
    # without labels: the same distances
    assert np.array_equal(spot.distances([99, 1500], prior_distances=d1), d2)


@pytest.mark.parametrize("epsilon", [1e-1, 1e-3])
def test_with_epsilon_within_the_contract_with_bounds(spot, epsilon):
    d1, l1, b1 = spot.distances([0, 17], epsilon=epsilon, return_labels=True, return_bounds=True)
    d2, l2, b2 = spot.distances(99, epsilon=epsilon, prior_distances=d1, prior_labels=l1, prior_bounds=b1,
                                return_labels=True, return_bounds=True)
    exact = spot.distances([0, 17, 99])
    assert np.all(d2 >= exact * (1 - 1e-12)) and np.all(d2 <= exact * (1 + epsilon) * (1 + 1e-12))
    assert np.all(b2 >= 0) and np.all(d2 - b2 <= exact * (1 + 1e-12)) and np.all(b2 <= epsilon * d2 * (1 + 1e-12))
    # without the prior bounds, the prior field's lower bounds are d / (1 + epsilon): still certified
    d3, b3 = spot.distances(99, epsilon=epsilon, prior_distances=d1, return_bounds=True)
    assert np.array_equal(d3, d2) and np.all(d3 - b3 <= exact * (1 + 1e-12))


def test_after_farthest_point_sampling(spot):
    samples, d, labels = spot.farthest_point_sampling(5, return_distances=True, return_labels=True)
    d2, l2 = spot.distances(2000, prior_distances=d, prior_labels=labels, return_labels=True)
    assert np.allclose(d2, spot.distances(list(samples) + [2000]), rtol=1e-13, atol=0)
    assert l2[2000] == 5 and set(np.unique(l2)) <= set(range(6))


def test_float_solver():
    V, F = dggvtp.read_mesh(mesh("spot.ply"))
    s = dggvtp.GeodesicSolver(V, F, precision="float")
    d1 = s.distances(0)
    d2 = s.distances(17, prior_distances=d1)
    assert np.allclose(d2, s.distances([0, 17]), rtol=1e-6, atol=0)


def test_bad_prior_fields_are_refused(spot):
    n = spot.num_vertices
    d, labels = spot.distances(0, return_labels=True)
    with pytest.raises(ValueError, match=r"prior_distances must have shape \(num_vertices,\)"):
        spot.distances(5, prior_distances=d[:-1])
    with pytest.raises(ValueError, match="prior_labels and prior_bounds go with prior_distances"):
        spot.distances(5, prior_labels=labels)
    with pytest.raises(ValueError, match="needs prior_labels"):
        spot.distances(5, prior_distances=d, return_labels=True)
    with pytest.raises(ValueError, match="does not combine with max_distance"):
        spot.distances(5, prior_distances=d, max_distance=0.5)
    with pytest.raises(ValueError, match="prior distance of vertex 3 must be >= 0"):
        spot.distances(5, prior_distances=np.where(np.arange(n) == 3, -1.0, d))
    with pytest.raises(ValueError, match="prior lower bound"):
        spot.distances(5, epsilon=1e-2, prior_distances=d, prior_bounds=-np.ones(n))
    with pytest.raises(ValueError, match="prior_labels must hold integers"):
        spot.distances(5, prior_distances=d, prior_labels=d)
