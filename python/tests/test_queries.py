"""Targets, shortest paths and one field per source: against dggvtp, and against distances()."""
import numpy as np
import pytest

import dggvtp
from conftest import grid, mesh, needs_cli, run_cli_lines, same_bits

pytestmark = pytest.mark.filterwarnings("ignore:target_points")  # (0, 0.1, 0) is 9e-4 off the bunny's surface


@pytest.fixture(scope="module")
def bunny():
    return dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh("bunny.ply")))


@needs_cli
def test_target_distances_as_dggvtp(bunny):
    t = bunny.target_distances([0], targets=[1000, 20000], target_points=[0.0, 0.1, 0.0], epsilon=1e-4)
    expected = run_cli_lines(mesh("bunny.ply"), "--source", 0, "--target", 1000, "--target", 20000,
                             "--target-point", 0.0, 0.1, 0.0, "--epsilon", 1e-4)
    assert t.tolist() == expected


@needs_cli
def test_geodesic_path_as_dggvtp(tmp_path, bunny):
    for target in (dict(target=1000), dict(target=None, target_point=[0.0, 0.1, 0.0])):
        path = bunny.geodesic_path(0, **target, source_first=False)  # dggvtp --paths: from the target
        option = ["--path-to", 1000] if target["target"] else ["--path-to-point", 0.0, 0.1, 0.0]
        length = run_cli_lines(mesh("bunny.ply"), "--source", 0, *option, "--paths", tmp_path / "p.obj")[0]
        expected = np.array([[float(x) for x in line.split()[1:]]
                             for line in open(tmp_path / "p.obj") if line.startswith("v ")])
        assert np.array_equal(path, expected)
        assert np.array_equal(bunny.geodesic_path(0, **target), expected[::-1])  # by default from the source
        assert np.linalg.norm(np.diff(path, axis=0), axis=1).sum() == pytest.approx(length, rel=1e-12)


def test_targets_are_the_field(bunny):
    t = bunny.target_distances([0], targets=[1000, 20000], epsilon=1e-4)
    full = bunny.distances(0, epsilon=1e-4)
    assert t[0] == full[1000] and t[1] == full[20000]


def test_geodesic_path(bunny):
    V, F = dggvtp.read_mesh(mesh("bunny.ply"))
    path = bunny.geodesic_path(0, target=1000)
    assert path.ndim == 2 and path.shape[1] == 3 and len(path) >= 2 and path.dtype == np.float64
    assert np.array_equal(path[0], V[0]) and np.array_equal(path[-1], V[1000])  # from the source to the target
    length = np.linalg.norm(np.diff(path, axis=0), axis=1).sum()
    assert length == pytest.approx(bunny.distances(0)[1000], rel=1e-12)


def test_distances_and_paths_of_one_propagation(bunny):
    targets, points = [1000, 20000, 0], [[0.0, 0.1, 0.0]]
    lengths, paths = bunny.distances_and_paths(0, targets=targets, target_points=points)
    assert len(paths) == 4 and lengths.shape == (4,) and lengths.dtype == np.float64
    one_by_one = [bunny.geodesic_path(0, target=t) for t in targets] + [bunny.geodesic_path(0, None, target_point=points[0])]
    for path, length, alone in zip(paths, lengths, one_by_one):
        assert np.array_equal(path, alone)
        assert np.linalg.norm(np.diff(path, axis=0), axis=1).sum() == pytest.approx(length, rel=1e-12, abs=0)
    assert lengths[2] == 0 and len(paths[2]) == 1  # the source itself
    # the length of the polyline, which is the distance up to rounding
    assert np.allclose(lengths[:2], bunny.target_distances(0, targets=targets[:2]), rtol=1e-12, atol=0)


def test_straight_path_on_a_flat_grid():
    V, F = grid(8)
    lengths, paths = dggvtp.GeodesicSolver(V, F).distances_and_paths(0, targets=[80, 44])
    for path, length, target in zip(paths, lengths, [80, 44]):
        assert length == pytest.approx(np.linalg.norm(V[target]), rel=1e-13)
        # every point on the segment from the target to the source
        direction = V[target] / np.linalg.norm(V[target])
        assert np.allclose(np.cross(path, direction), 0, atol=1e-13)


def test_unreachable_path_is_empty():
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0]]
    with pytest.warns(RuntimeWarning, match="3 of 6 vertices are unreachable"):
        solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [3, 4, 5]])
        solver.distances(0)
    with pytest.warns(RuntimeWarning, match="1 of 1 paths are unreachable"):
        assert solver.geodesic_path(0, target=4).shape == (0, 3)
    with pytest.warns(RuntimeWarning, match="1 of 2 targets are unreachable"):
        assert np.isinf(solver.target_distances(0, targets=[4, 1])[0])
    with pytest.warns(RuntimeWarning, match="1 of 2 paths are unreachable"):
        lengths, paths = solver.distances_and_paths(0, targets=[4, 1])
    assert paths[0].shape == (0, 3) and np.isinf(lengths[0]) and lengths[1] == 1


def test_distances_from_each(bunny):
    sources = [0, 17, 99]
    for threads in (1, 2):
        D = bunny.distances_from_each(sources, epsilon=1e-6, threads=threads)
        assert D.shape == (3, bunny.num_vertices) and D.dtype == np.float64
        for k, s in enumerate(sources):
            assert same_bits(D[k], bunny.distances(s, epsilon=1e-6))
    assert bunny.distances_from_each([], epsilon=1e-6).shape == (0, bunny.num_vertices)


def test_distances_from_each_warns_for_unreachable_rows():
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0], [9, 9, 9]]
    solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [3, 4, 5]])
    with pytest.warns(RuntimeWarning, match="2 of the 2 rows computed leave vertices unreachable .inf., up to 4 of 7"):
        solver.distances_from_each([0, 4])


def test_help_and_attributes(bunny):
    for f in (dggvtp.read_mesh, dggvtp.GeodesicSolver, dggvtp.GeodesicSolver.distances,
              dggvtp.GeodesicSolver.distances_from_each, dggvtp.GeodesicSolver.target_distances,
              dggvtp.GeodesicSolver.geodesic_path, dggvtp.GeodesicSolver.distances_and_paths,
              dggvtp.GeodesicSolver.distance_and_path, dggvtp.GeodesicSolver.farthest_point_sampling,
              dggvtp.GeodesicSolver.local_distance_matrix, dggvtp.GeodesicSolver.__init__, dggvtp.geodesic_distances):
        assert f.__doc__ and len(f.__doc__) > 40, f
    assert bunny.num_vertices == 37706 and bunny.num_faces == 75408 and bunny.precision == "double"
    assert bunny.repairs == []
    assert repr(bunny) == "<dggvtp.GeodesicSolver: 37706 vertices, 75408 faces, double>"
