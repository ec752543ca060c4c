"""Targets, shortest paths and one field per source, against dggvtp and distances()."""
import numpy as np
import pytest

import dggvtp
from conftest import mesh, needs_cli, run_cli_lines


@pytest.fixture(scope="module")
def bunny():
    return dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh("bunny.ply")))


@needs_cli
def test_target_distances(bunny):
    t = bunny.target_distances([0], targets=[1000, 20000], target_points=[0.0, 0.1, 0.0], epsilon=1e-4)
    expected = run_cli_lines(mesh("bunny.ply"), "--source", 0, "--target", 1000, "--target", 20000,
                             "--target-point", 0.0, 0.1, 0.0, "--epsilon", 1e-4)
    assert t.tolist() == expected
    full = bunny.distances(0, epsilon=1e-4)
    assert t[0] == full[1000] and t[1] == full[20000]


@needs_cli
def test_shortest_path(tmp_path, bunny):
    for target in (dict(target=1000), dict(target_point=[0.0, 0.1, 0.0])):
        path = bunny.shortest_path(0, **target)
        assert path.ndim == 2 and path.shape[1] == 3 and len(path) >= 2
        option = ["--path-to", 1000] if "target" in target else ["--path-to-point", 0.0, 0.1, 0.0]
        length = run_cli_lines(mesh("bunny.ply"), "--source", 0, *option, "--paths", tmp_path / "p.obj")[0]
        expected = np.array([[float(x) for x in line.split()[1:]]
                             for line in open(tmp_path / "p.obj") if line.startswith("v ")])
        assert np.array_equal(path, expected)
        assert np.linalg.norm(np.diff(path, axis=0), axis=1).sum() == pytest.approx(length, rel=1e-12)
    V, _ = dggvtp.read_mesh(mesh("bunny.ply"))
    assert np.array_equal(bunny.shortest_path(0, target=1000)[-1], V[0])


def test_unreachable_path_is_empty():
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0]]
    solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [3, 4, 5]])
    assert solver.shortest_path(0, target=4).shape == (0, 3)
    assert np.isinf(solver.target_distances(0, targets=[4])[0])


def test_distances_from_each(bunny):
    sources = [0, 17, 99]
    for threads in (1, 2):
        D = bunny.distances_from_each(sources, epsilon=1e-6, threads=threads)
        assert D.shape == (3, bunny.num_vertices) and D.dtype == np.float64
        for k, s in enumerate(sources):
            assert D[k].tobytes() == bunny.distances(s, epsilon=1e-6).tobytes()
    assert bunny.distances_from_each([], epsilon=1e-6).shape == (0, bunny.num_vertices)


def test_help_and_attributes(bunny):
    for f in (dggvtp.read_mesh, dggvtp.GeodesicSolver, dggvtp.GeodesicSolver.distances,
              dggvtp.GeodesicSolver.distances_from_each, dggvtp.GeodesicSolver.target_distances,
              dggvtp.GeodesicSolver.shortest_path, dggvtp.GeodesicSolver.__init__):
        assert f.__doc__ and len(f.__doc__) > 40, f
    assert bunny.num_vertices == 37706 and bunny.num_faces == 75408 and bunny.precision == "double"
    assert bunny.repairs == []
