"""The former spellings of the API (its first release) still work for one more release, each with
a DeprecationWarning that points at the caller's line and names what replaces it, and give what
they gave: paths from the target to the source, (paths, lengths) in that order, precision by
position, a query without its sources, farthest_point_sampling(first=)."""
import pathlib
import warnings

import numpy as np
import pytest

import dggvtp
from conftest import grid, mesh, same_bits


@pytest.fixture(scope="module")
def spot():
    V, F = dggvtp.read_mesh(mesh("spot.ply"))
    return V, F, dggvtp.GeodesicSolver(V, F)


def former(call, replacement):
    """call() under the former spelling: exactly one DeprecationWarning, naming `replacement`,
    at this file's line"""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = call()
    deprecations = [w for w in caught if issubclass(w.category, DeprecationWarning)]
    assert len(deprecations) == 1, [str(w.message) for w in caught]
    assert replacement in str(deprecations[0].message), str(deprecations[0].message)
    assert pathlib.Path(deprecations[0].filename).name == "test_deprecations.py", deprecations[0].filename
    return result


def test_shortest_path_runs_from_the_target(spot):
    V, F, s = spot
    path = former(lambda: s.shortest_path(14, 2200), "geodesic_path()")
    assert np.array_equal(path[0], V[2200]) and np.array_equal(path[-1], V[14])
    assert same_bits(path, s.geodesic_path(14, 2200, source_first=False))
    forth = former(lambda: s.shortest_path(14, target=2200, source_first=True), "geodesic_path()")
    assert same_bits(forth, s.geodesic_path(14, 2200))


def test_shortest_paths_gives_paths_then_lengths(spot):
    V, F, s = spot
    paths, lengths = former(lambda: s.shortest_paths(0, [5, 9], epsilon=1e-3), "distances_and_paths()")
    new_lengths, new_paths = s.distances_and_paths(0, [5, 9], epsilon=1e-3, source_first=False)
    assert same_bits(lengths, new_lengths) and all(same_bits(a, b) for a, b in zip(paths, new_paths))
    assert np.array_equal(paths[0][0], V[5])


def test_geodesic_distance_is_distance_and_path_from_the_target(spot):
    V, F, s = spot
    distance, path = former(lambda: s.geodesic_distance(0, 1234), "distance_and_path()")
    new_distance, new_path = s.distance_and_path(0, 1234)
    assert distance == new_distance and same_bits(path, new_path[::-1])


def test_precision_by_position():
    V, F = grid(4)
    s = former(lambda: dggvtp.GeodesicSolver(V, F, "float"), "precision='float'")
    assert s.precision == "float"
    assert same_bits(s.distances(0), dggvtp.GeodesicSolver(V, F, precision="float").distances(0))


def test_a_query_without_its_sources(spot):
    V, F, s = spot
    d = former(lambda: s.distances(points=V[42]), "distances(sources=None")
    assert same_bits(d, s.distances(42))
    t = former(lambda: s.target_distances(0, target_points=[V[5]]), "target_distances(targets=None")
    assert same_bits(t, s.target_distances(0, [5]))
    p = former(lambda: s.geodesic_path(0, target_point=V[5]), "geodesic_path(target=None")
    assert same_bits(p, s.geodesic_path(0, 5))
    e = former(lambda: dggvtp.geodesic_distances(V, F, points=V[42]), "without sources is deprecated")
    assert same_bits(e, s.distances(42))
    # what never worked still fails, now as Python says a missing argument
    with pytest.raises(TypeError, match="missing required argument: 'sources'"):
        s.distances()
    with pytest.raises(TypeError, match="missing required argument: 'targets'"):
        s.target_distances(0)


def test_farthest_point_sampling_first(spot):
    V, F, s = spot
    samples = former(lambda: s.farthest_point_sampling(5, first=3), "first_sample=")
    assert same_bits(samples, s.farthest_point_sampling(5, first_sample=3))
    with pytest.raises(TypeError, match="first_sample alone"):
        s.farthest_point_sampling(5, first=3, first_sample=3)


def test_the_current_spellings_do_not_warn(spot):
    V, F, s = spot
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s.geodesic_path(14, 2200)
        s.distances_and_paths(0, [5, 9])
        s.distance_and_path(0, 1234)
        s.distances(None, points=V[42])
        s.farthest_point_sampling(3, first_sample=3)
        dggvtp.GeodesicSolver(V, F, precision="float")
        dggvtp.geodesic_distances(V, F, 0)
