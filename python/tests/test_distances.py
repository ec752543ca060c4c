"""distances(): dggvtp's values bit for bit (exact and DGG-VTP, double and float, several sources
and points, labels, max_distance, any number of threads), and, without dggvtp, the oracles that
hold whatever computes them: Euclidean distances on a flat mesh, the accuracy contract of
DGG-VTP, the nearest source of several, the field cut at max_distance."""
import math
import warnings

import numpy as np
import pytest

import dggvtp
from conftest import MESHES, grid, mesh, needs_cli, run_cli, same_bits


@pytest.fixture(scope="module")
def solvers():
    made = {}

    def get(name, precision="double"):
        if (name, precision) not in made:
            made[name, precision] = dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh(name)), precision=precision)
        return made[name, precision]
    return get


# --- against dggvtp --------------------------------------------------------------------------------

@needs_cli
@pytest.mark.parametrize("name", MESHES)
@pytest.mark.parametrize("epsilon", [0.0, 1e-4])
def test_as_dggvtp(tmp_path, solvers, name, epsilon):
    solver = solvers(name)
    source = solver.num_vertices // 3
    d = solver.distances(source, epsilon=epsilon)
    assert d.dtype == np.float64 and d.shape == (solver.num_vertices,)
    assert same_bits(d, run_cli(tmp_path, mesh(name), "--source", source, "--epsilon", epsilon))


@needs_cli
@pytest.mark.parametrize("epsilon", [0.0, 1e-3])
def test_float_precision_as_dggvtp(tmp_path, solvers, epsilon):
    d = solvers("spot.ply", "float").distances(7, epsilon=epsilon)
    assert same_bits(d, run_cli(tmp_path, mesh("spot.ply"), "--source", 7, "--epsilon", epsilon, "--precision", "float"))


@needs_cli
@pytest.mark.filterwarnings("ignore:points")  # the point is 9e-4 off the bunny's surface
def test_sources_points_labels_as_dggvtp(tmp_path, solvers):
    solver = solvers("bunny.ply")
    point = [0.0, 0.1, 0.0]
    d, labels = solver.distances([0, 5000], points=[point], epsilon=1e-4, return_labels=True)
    expected_d, expected_labels = run_cli(tmp_path, mesh("bunny.ply"), "--source", 0, "--source", 5000,
                                          "--source-point", *point, "--epsilon", 1e-4, labels=True)
    assert same_bits(d, expected_d) and same_bits(labels, expected_labels)
    assert set(np.unique(labels)) == {0, 1, 2}


@needs_cli
def test_max_distance_as_dggvtp(tmp_path, solvers):
    d = solvers("lion_head.ply").distances(3, max_distance=0.05)
    assert np.isinf(d).any() and np.isfinite(d).any()
    assert same_bits(d, run_cli(tmp_path, mesh("lion_head.ply"), "--source", 3, "--max-distance", 0.05))


# --- self-contained ---------------------------------------------------------------------------------

@pytest.mark.parametrize("precision, tolerance", [("double", 1e-13), ("float", 1e-6)])
def test_flat_grid_is_euclidean(precision, tolerance):
    V, F = grid(12)
    d = dggvtp.GeodesicSolver(V, F, precision=precision).distances(0)
    assert np.allclose(d, np.linalg.norm(V - V[0], axis=1), rtol=tolerance, atol=tolerance)


def test_plane_mesh_of_two_coordinates():
    V, F = grid(6)
    assert same_bits(dggvtp.GeodesicSolver(V[:, :2], F).distances(5), dggvtp.GeodesicSolver(V, F).distances(5))


@pytest.mark.parametrize("name", ["bunny.ply", "blade.ply", "lion_head.ply"])
@pytest.mark.parametrize("epsilon", [1e-2, 1e-4])
def test_epsilon_within_the_contract(solvers, name, epsilon):
    solver = solvers(name)
    exact = solver.distances(11)
    d = solver.distances(11, epsilon=epsilon)
    reached = np.isfinite(exact)
    assert np.array_equal(reached, np.isfinite(d))
    assert np.all(d[reached] >= exact[reached] * (1 - 1e-12)) and np.all(d[reached] <= exact[reached] * (1 + epsilon))


def test_float_precision_near_double(solvers):
    double = solvers("spot.ply").distances(7)
    assert np.allclose(solvers("spot.ply", "float").distances(7), double, rtol=1e-5, atol=1e-6)


def test_nearest_source_and_labels(solvers):
    solver = solvers("turbine.ply")
    sources = [0, 1000, 4000]
    fields = np.array([solver.distances(s) for s in sources])
    d, labels = solver.distances(sources, return_labels=True)
    # exact either way, up to rounding (the windows of several sources are pruned differently)
    assert np.allclose(d, fields.min(axis=0), rtol=1e-12, atol=0)
    # the label is the source whose field gives the distance (ties: any of them)
    assert np.allclose(fields[labels, np.arange(len(d))], d, rtol=1e-12, atol=0)


def test_point_at_a_vertex_is_the_vertex(solvers):
    solver = solvers("pinion.ply")
    V, _ = dggvtp.read_mesh(mesh("pinion.ply"))
    assert same_bits(solver.distances(None, points=V[42]), solver.distances(42))


def test_max_distance_cuts_the_field(solvers):
    solver = solvers("lion_head.ply")
    full = solver.distances(3)
    d = solver.distances(3, max_distance=0.05)
    inside = full <= 0.05
    assert inside.any() and (~inside).any()
    assert same_bits(d[inside], full[inside]) and np.all(np.isinf(d[~inside]))


def test_threads_same_bits(solvers):
    solver = solvers("bunny.ply")
    one = solver.distances(0, epsilon=1e-4)
    for threads in (0, 2):
        assert same_bits(solver.distances(0, epsilon=1e-4, threads=threads), one)


def test_preparation_threads_same_bits(solvers):
    # the solver prepared on several threads is the sequential one: the same distances, bit for bit
    V, F = dggvtp.read_mesh(mesh("bunny.ply"))
    one = solvers("bunny.ply")
    for threads in (0, 2):
        solver = dggvtp.GeodesicSolver(V, F, threads=threads)
        assert solver.num_faces == one.num_faces
        for s, epsilon in ((0, 0.0), (20000, 1e-4)):
            assert same_bits(solver.distances(s, epsilon=epsilon), one.distances(s, epsilon=epsilon))
    assert same_bits(dggvtp.geodesic_distances(V, F, 7, threads=2), one.distances(7))
    with pytest.raises(ValueError, match="threads"):
        dggvtp.GeodesicSolver(V, F, threads=-1)


def test_array_likes_and_new_buffers(solvers):
    V, F = dggvtp.read_mesh(mesh("pinion.ply"))
    solver = dggvtp.GeodesicSolver(V.tolist(), F.astype(np.int32))
    d = solver.distances(np.int64(5))
    assert same_bits(d, solvers("pinion.ply").distances([5]))
    # the array is NumPy's own: the library wrote into it, nothing refers to another buffer
    assert d.flags.owndata and d.flags.writeable and d.base is None


def test_one_call_is_the_solver(solvers):
    V, F = dggvtp.read_mesh(mesh("spot.ply"))
    solver = solvers("spot.ply")
    assert same_bits(dggvtp.geodesic_distances(V, F, 7), solver.distances(7))
    options = dict(face_points=([3], [[0.2, 0.3, 0.5]]), epsilon=1e-3, max_distance=0.4, return_labels=True)
    for got, expected in zip(dggvtp.geodesic_distances(V, F, [7, 9], **options), solver.distances([7, 9], **options)):
        assert same_bits(got, expected)
    assert same_bits(dggvtp.geodesic_distances(V, F, 7, precision="float"), solvers("spot.ply", "float").distances(7))
    with pytest.raises(TypeError):
        dggvtp.geodesic_distances(V, F, 7, epsilom=1e-3)
    with pytest.raises(ValueError, match="no source given"):
        dggvtp.geodesic_distances(V, F, None)
    with pytest.raises(TypeError, match="missing required argument: 'sources'"):
        dggvtp.geodesic_distances(V, F)


def test_unreachable_vertices_warn():
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0], [9, 9, 9]]
    solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [3, 4, 5]])
    with pytest.warns(RuntimeWarning, match="4 of 7 vertices are unreachable from the sources"):
        d = solver.distances(0)
    assert np.isinf(d[3:]).all() and math.isclose(d[1], 1)
    # beyond max_distance they are unreached by request: no warning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        solver.distances(0, max_distance=10.0)
