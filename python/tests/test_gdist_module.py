"""dggvtp.gdist against gdist's published expectations (issue 44): the assertions of tvb-gdist's
own tests on its fixtures (data/gdist, see its README), exact and at epsilon 1e-4 (within the
contract: [exact, exact (1 + 1e-4)]), with gdist's argument order, defaults and output types."""
import pathlib
import warnings

import numpy as np
import pytest
import scipy.sparse

import dggvtp.gdist as gdist

DATA = pathlib.Path(__file__).resolve().parent / "data" / "gdist"


def load(name, nv):
    data = np.loadtxt(DATA / name, skiprows=1)
    return data[:nv].astype(np.float64), data[nv:].astype(np.int32)


@pytest.fixture(scope="module")
def flat():
    return load("flat_triangular_mesh.txt", 121)


@pytest.fixture(scope="module")
def hedgehog():
    return load("hedgehog_mesh.txt", 300)


def within(d, exact, epsilon):
    """the contract: exact to rounding at 0, else in [exact, exact (1 + epsilon)]"""
    d, exact = np.asarray(d), np.asarray(exact)
    return np.all(d >= exact * (1 - 1e-12) - 1e-12) and np.all(d <= exact * (1 + epsilon) + 1e-12)


@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
def test_compute_gdist_flat(flat, epsilon):
    V, F = flat
    d = gdist.compute_gdist(V, F, source_indices=np.array([1], np.int32), target_indices=np.array([2], np.int32),
                            epsilon=epsilon)
    assert d.dtype == np.float64 and d.shape == (1,)
    np.testing.assert_array_almost_equal(d, [0.2])
    assert within(d, [0.2], epsilon)


@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
def test_compute_gdist_one_indexed(epsilon):
    V, F = load("flat_triangular_mesh_1_indexed.txt", 121)
    d = gdist.compute_gdist(V, F, np.array([2], np.int32), np.array([3], np.int32), is_one_indexed=True,
                            epsilon=epsilon)
    np.testing.assert_array_almost_equal(d, [0.2])


@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
def test_compute_gdist_every_vertex_from_vertex_0(flat, epsilon):
    V, F = flat
    expected = np.loadtxt(DATA / "flat_triangular_mesh_no_target.txt")
    d = gdist.compute_gdist(V, F, None, None, epsilon=epsilon)
    assert d.shape == (121,)
    np.testing.assert_array_almost_equal(d, expected)
    assert within(d, expected, epsilon)
    # the flat mesh: Euclidean distances, to rounding
    assert np.allclose(gdist.compute_gdist(V, F), np.linalg.norm(V - V[0], axis=1), rtol=1e-14, atol=1e-15)


@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
def test_compute_gdist_hedgehog(hedgehog, epsilon):
    V, F = hedgehog
    d = gdist.compute_gdist(V, F, source_indices=np.array([0], np.int32), target_indices=np.array([1], np.int32),
                            epsilon=epsilon)
    np.testing.assert_array_almost_equal(d, [1.40522])


@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
@pytest.mark.parametrize("mesh, nv, expected, radius", [("flat_triangular_mesh.txt", 121, 0.2, 0.3),
                                                         ("hedgehog_mesh.txt", 300, 1.40522, 1.45)])
def test_local_gdist_matrix(mesh, nv, expected, radius, epsilon):
    V, F = load(mesh, nv)
    distances = gdist.local_gdist_matrix(V, F, epsilon=epsilon)
    assert type(distances) is scipy.sparse.csc_matrix and distances.shape == (nv, nv)
    assert (abs(distances - distances.T) > 1e-6).nnz == 0
    np.testing.assert_array_almost_equal(distances.toarray()[1][0], expected)
    assert distances.diagonal().max() == 0 and np.all(distances.data > 0)   # no stored zeros, as gdist
    near = gdist.local_gdist_matrix(V, F, radius, epsilon=epsilon)
    assert (abs(near - near.T) > 1e-6).nnz == 0
    assert np.max(near) <= radius
    if epsilon:
        exact = gdist.local_gdist_matrix(V, F)
        assert within(distances[distances.nonzero()], exact[distances.nonzero()], epsilon)


def test_local_gdist_matrix_one_indexed():
    V, F = load("flat_triangular_mesh_1_indexed.txt", 121)
    distances = gdist.local_gdist_matrix(V, F, is_one_indexed=True)
    np.testing.assert_array_almost_equal(distances.toarray()[1][0], 0.2)
    near = gdist.local_gdist_matrix(V, F, 0.3, True)
    assert (abs(near - near.T) > 1e-6).nnz == 0 and np.max(near) <= 0.3


@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
def test_distance_matrix_of_selected_points(flat, epsilon):
    V, F = flat
    points = np.array([2, 5, 10, 12, 14, 16], dtype=np.int32)
    distances = gdist.distance_matrix_of_selected_points(V, F, points, epsilon=epsilon)
    expected = np.loadtxt(DATA / "flat_triangular_mesh_pairwise_matrix.txt")
    np.testing.assert_array_almost_equal(distances.toarray(), expected)
    assert (abs(distances - distances.T) > 1e-6).nnz == 0
    assert distances.nnz == len(points) * len(points) - len(points)
    assert type(distances) is scipy.sparse.csc_matrix
    nonzero = expected != 0
    assert within(distances.toarray()[nonzero], expected[nonzero], epsilon)


def test_max_distance_and_none(flat):
    V, F = flat
    every = gdist.compute_gdist(V, F, max_distance=None)
    near = gdist.compute_gdist(V, F, max_distance=0.5)
    assert np.all(np.isfinite(every))
    assert np.array_equal(near[every <= 0.5], every[every <= 0.5]) and np.all(np.isinf(near[every > 0.5 + 1e-9]))
    pairs = gdist.distance_matrix_of_selected_points(V, F, [0, 1, 120], max_distance=0.5)
    assert pairs.nnz == 2 and pairs[0, 1] == pytest.approx(0.2)   # 0-120 is 2.8 apart: no entry
    with pytest.raises(ValueError, match="max_distance"):
        gdist.compute_gdist(V, F, max_distance=-1.0)


def test_no_warning_and_bad_input(flat):
    V, F = flat
    with warnings.catch_warnings():
        warnings.simplefilter("error")   # gdist's flat mesh had its faces turned: no warning for that
        gdist.compute_gdist(V, F, [1], [2])
    with pytest.raises(ValueError):
        gdist.compute_gdist(V, F, [500], [2])
    with pytest.raises(ValueError, match="is_one_indexed"):
        gdist.compute_gdist(V, F, is_one_indexed=True)
