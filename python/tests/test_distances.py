"""distances() gives dggvtp's values bit for bit: exact and DGG-VTP, double and float, several
sources and points, labels, max_distance, any number of threads."""
import numpy as np
import pytest

import dggvtp
from conftest import MESHES, mesh, needs_cli, run_cli

pytestmark = needs_cli


@pytest.fixture(scope="module")
def solvers():
    made = {}

    def get(name, precision="double"):
        if (name, precision) not in made:
            made[name, precision] = dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh(name)), precision=precision)
        return made[name, precision]
    return get


def same_bits(a, b):
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("name", MESHES)
@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
def test_as_dggvtp(tmp_path, solvers, name, epsilon):
    solver = solvers(name)
    source = solver.num_vertices // 3
    d = solver.distances(source, epsilon=epsilon)
    assert d.dtype == np.float64 and d.shape == (solver.num_vertices,)
    assert same_bits(d, run_cli(tmp_path, mesh(name), "--source", source, "--epsilon", epsilon))


@pytest.mark.parametrize("epsilon", [0.0, 1e-3])
def test_float_precision(tmp_path, solvers, epsilon):
    d = solvers("spot.ply", "float").distances(7, epsilon=epsilon)
    assert same_bits(d, run_cli(tmp_path, mesh("spot.ply"), "--source", 7, "--epsilon", epsilon, "--precision", "float"))


def test_sources_points_labels(tmp_path, solvers):
    solver = solvers("bunny.ply")
    point = [0.0, 0.1, 0.0]
    d, labels = solver.distances([0, 5000], points=[point], epsilon=1e-4, return_labels=True)
    expected_d, expected_labels = run_cli(tmp_path, mesh("bunny.ply"), "--source", 0, "--source", 5000,
                                          "--source-point", *point, "--epsilon", 1e-4, labels=True)
    assert same_bits(d, expected_d) and same_bits(labels, expected_labels)
    assert set(np.unique(labels)) == {0, 1, 2}


def test_point_at_a_vertex_is_the_vertex(solvers):
    solver = solvers("pinion.ply")
    V, _ = dggvtp.read_mesh(mesh("pinion.ply"))
    assert same_bits(solver.distances(points=V[42]), solver.distances(42))


def test_max_distance(tmp_path, solvers):
    solver = solvers("lion_head.ply")
    d = solver.distances(3, max_distance=0.05)
    assert np.isinf(d).any() and np.isfinite(d).any()
    assert same_bits(d, run_cli(tmp_path, mesh("lion_head.ply"), "--source", 3, "--max-distance", 0.05))


def test_threads_same_bits(solvers):
    solver = solvers("bunny.ply")
    one = solver.distances(0, epsilon=1e-4)
    for threads in (0, 2):
        assert same_bits(solver.distances(0, epsilon=1e-4, threads=threads), one)


def test_array_likes_and_new_buffers(solvers):
    V, F = dggvtp.read_mesh(mesh("pinion.ply"))
    solver = dggvtp.GeodesicSolver(V.tolist(), F.astype(np.int32))
    d = solver.distances(np.int64(5))
    assert same_bits(d, solvers("pinion.ply").distances([5]))
    # the array is NumPy's own: the library wrote into it, nothing refers to another buffer
    assert d.flags.owndata and d.flags.writeable and d.base is None
