"""Every distance with its certified error (issue 45): return_bounds=True gives, per vertex, a
bound b such that the exact distance lies in [d - b, d], with 0 <= b <= epsilon d, 0 at the sources
and everywhere in the exact mode, inf where unreachable and NaN where a repair removed the vertex;
the rows of distances_from_each the same bits as distances; dggvtp --error-bounds the same bits."""
import math

import numpy as np
import pytest

import dggvtp
from conftest import CLI, CLI_DATA, mesh, needs_cli, same_bits

EPSILONS = (1.0, 1e-1, 1e-2, 1e-4, 1e-7)


def check_interval(d, b, exact, epsilon):
    reached = np.isfinite(exact)
    assert np.array_equal(np.isinf(b), np.isinf(d))
    assert (b[reached] >= 0).all()
    assert (d[reached] - b[reached] <= exact[reached] * (1 + 1e-12)).all(), "a lower bound above the exact distance"
    assert (b[reached] <= epsilon * d[reached] * (1 + 1e-12)).all(), "a bound wider than epsilon"


@pytest.mark.parametrize("name", ["pinion.ply", "spot.ply"])
def test_interval_holds(name):
    V, F = dggvtp.read_mesh(mesh(name))
    solver = dggvtp.GeodesicSolver(V, F)
    sources = [0, 5, len(V) // 2]
    exact = solver.distances_from_each(sources)
    d0, b0 = solver.distances_from_each(sources, return_bounds=True)
    assert same_bits(d0, exact) and not b0.any(), "the exact mode: every distance certified exact"
    for epsilon in EPSILONS:
        rows, bounds = solver.distances_from_each(sources, epsilon=epsilon, return_bounds=True)
        assert same_bits(rows, solver.distances_from_each(sources, epsilon=epsilon))
        for k, s in enumerate(sources):
            check_interval(rows[k], bounds[k], exact[k], epsilon)
            assert bounds[k, s] == 0
            d, b = solver.distances(s, epsilon=epsilon, return_bounds=True)
            assert same_bits(d, rows[k]) and same_bits(b, bounds[k])
        # some vertices are certified exact, and not every one (the interval is not a formality)
        assert 0 < np.count_nonzero(bounds == 0) < bounds.size


def test_labels_and_bounds_together():
    V, F = dggvtp.read_mesh(mesh("pinion.ply"))
    solver = dggvtp.GeodesicSolver(V, F)
    d, labels, b = solver.distances([3, 300], epsilon=1e-2, return_labels=True, return_bounds=True)
    d1, labels1 = solver.distances([3, 300], epsilon=1e-2, return_labels=True)
    d2, b2 = solver.distances([3, 300], epsilon=1e-2, return_bounds=True)
    assert same_bits(d, d1) and same_bits(labels, labels1) and same_bits(d, d2) and same_bits(b, b2)
    assert b[3] == 0 and b[300] == 0
    d3, b3 = dggvtp.geodesic_distances(V, F, [3, 300], epsilon=1e-2, return_bounds=True)
    assert same_bits(d3, d) and same_bits(b3, b)


def test_float_bounds_stay_below_the_exact_distance():
    V, F = dggvtp.read_mesh(mesh("pinion.ply"))
    V = V.astype(np.float32).astype(np.float64)   # the surface the float solver sees
    exact = dggvtp.GeodesicSolver(V, F).distances(7)
    single = dggvtp.GeodesicSolver(V, F, precision="float")
    for epsilon in (0.0, 1e-5, 1e-2):
        d, b = single.distances(7, epsilon=epsilon, return_bounds=True)
        # d is rounded to float (half an ulp either way), the lower bound rounded down
        assert (d - b <= exact * (1 + 2.0 ** -24) * (1 + 1e-12)).all()
        assert (b >= 0).all()


def test_unreachable_and_beyond_max_distance():
    V, F = dggvtp.read_mesh(str(CLI_DATA / "two_components_and_isolated_vertex.off"))
    solver = dggvtp.GeodesicSolver(V, F)
    with pytest.warns(RuntimeWarning, match="unreachable"):
        d, b = solver.distances(0, epsilon=0.1, return_bounds=True)
    assert np.array_equal(np.isinf(b), np.isinf(d)) and np.isinf(d).any()
    V, F = dggvtp.read_mesh(mesh("spot.ply"))
    d, b = dggvtp.GeodesicSolver(V, F).distances(0, epsilon=0.1, max_distance=0.2, return_bounds=True)
    assert np.array_equal(np.isinf(b), d > 0.2) and np.isfinite(d).any() and np.isinf(d).any()
    assert not np.isnan(b).any()


def test_removed_vertex_is_nan():
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [5, 5, 5]], float)
    F = np.array([[0, 1, 2], [0, 2, 3]])
    with pytest.warns(RuntimeWarning):
        solver = dggvtp.GeodesicSolver(V, F, repair=True)
    d, b = solver.distances(0, epsilon=0.5, return_bounds=True)
    assert math.isnan(d[4]) and math.isnan(b[4]) and (b[:4] == 0).all()  # a flat square: straight paths


@needs_cli
def test_cli_error_bounds_are_the_same_bits(tmp_path):
    import subprocess
    path = mesh("lion_head.ply")
    V, F = dggvtp.read_mesh(path)
    d, b = dggvtp.GeodesicSolver(V, F).distances(12, epsilon=1e-3, return_bounds=True)
    subprocess.run([CLI, path, "--source", "12", "--epsilon", "1e-3", "--error-bounds", tmp_path / "b.npy",
                    "--output-format", "npy", "--quiet"], check=True)
    assert same_bits(np.load(tmp_path / "b.npy"), b)
    subprocess.run([CLI, path, "--source", "12", "--epsilon", "1e-3", "--error-bounds", tmp_path / "b.txt",
                    "--quiet"], check=True)
    assert same_bits(np.loadtxt(tmp_path / "b.txt"), b)
