"""Points on faces, face_points=(faces, barycentric): the same result as the 3D point they make,
wherever 3D points are taken (sources, targets, path targets), whatever the input policy did to the
faces (turned, reoriented, dropped by repair=True)."""
import numpy as np
import pytest

import dggvtp
from conftest import grid, mesh, same_bits

B = np.array([[0.2, 0.3, 0.5], [0.6, 0.1, 0.3], [1 / 3, 1 / 3, 1 / 3]])


@pytest.fixture(scope="module")
def spot():
    V, F = dggvtp.read_mesh(mesh("spot.ply"))
    return V, F, dggvtp.GeodesicSolver(V, F)


def points_of(V, F, faces, barycentric):
    return np.einsum("kj,kjc->kc", barycentric, V[F[faces]])


def close(a, b):
    return np.allclose(a, b, rtol=1e-12, atol=1e-14)


def test_sources_are_the_3d_points(spot):
    V, F, solver = spot
    faces = [10, 2000, 5000]
    for k in range(3):
        by_face = solver.distances(None, face_points=([faces[k]], B[k:k + 1]))
        by_point = solver.distances(None, points=points_of(V, F, [faces[k]], B[k:k + 1]))
        assert close(by_face, by_point)
    d, labels = solver.distances([7], face_points=(faces, B), return_labels=True)
    d_points, labels_points = solver.distances([7], points=points_of(V, F, faces, B), return_labels=True)
    assert close(d, d_points) and np.array_equal(labels, labels_points)
    assert set(np.unique(labels)) == {0, 1, 2, 3}


def test_a_corner_is_its_vertex(spot):
    V, F, solver = spot
    for k in range(3):
        corner = np.eye(3)[k]
        assert same_bits(solver.distances(None, face_points=(123, corner)), solver.distances(int(F[123, k])))


def test_targets_and_paths(spot):
    V, F, solver = spot
    faces = [100, 4000]
    points = points_of(V, F, faces, B[:2])
    t = solver.target_distances(7, None, target_face_points=(faces, B[:2]))
    assert close(t, solver.target_distances(7, None, target_points=points))
    lengths, paths = solver.distances_and_paths(7, targets=[3], target_face_points=(faces, B[:2]))
    point_lengths, _ = solver.distances_and_paths(7, targets=[3], target_points=points)
    assert close(lengths, point_lengths) and len(paths) == 3
    assert np.allclose(paths[1][-1], points[0], atol=1e-15) and np.allclose(paths[2][-1], points[1], atol=1e-15)
    one = solver.geodesic_path(7, None, target_face_point=(faces[0], B[0]))
    assert np.array_equal(one, paths[1])
    assert close(solver.target_distances(None, face_points=(faces, B[:2]), targets=[3]),
                 solver.target_distances(None, points=points, targets=[3]))


def test_on_a_flat_grid_the_distance_is_euclidean():
    V, F = grid(6)
    solver = dggvtp.GeodesicSolver(V, F)
    x = B[0] @ V[F[17]]
    assert np.allclose(solver.distances(None, face_points=(17, B[0])), np.linalg.norm(V - x, axis=1), rtol=1e-13, atol=1e-15)


def test_faces_the_input_policy_turned():
    # the second face of the square goes the other way: the solver reverses it, and its corners
    # are no longer in F's order; a face point still means F's corners
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [0, 3, 2]])
    solver = dggvtp.GeodesicSolver(V, F)  # no warning: orientation changes no distance
    assert solver.repairs == ["reoriented 1 faces"]
    b = np.array([0.1, 0.7, 0.2])
    x = b @ V[F[1]]
    assert np.allclose(solver.distances(None, face_points=(1, b)), np.linalg.norm(V - x, axis=1), rtol=1e-13)


def test_faces_a_repair_dropped():
    # face 1 repeats a vertex (dropped with repair=True): its points are on an edge, located as 3D points
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [0, 2, 2], [0, 2, 3]])
    with pytest.warns(RuntimeWarning, match="repair=True: dropped 1 faces with a repeated corner"):
        solver = dggvtp.GeodesicSolver(V, F, repair=True)
    b = np.array([0.25, 0.5, 0.25])
    x = b @ V[F[1]]
    assert np.allclose(solver.distances(None, face_points=(1, b)), np.linalg.norm(V - x, axis=1), rtol=1e-13)
    # and face 2 is the solver's triangle 1
    b = np.array([0.2, 0.2, 0.6])
    x = b @ V[F[2]]
    assert np.allclose(solver.distances(None, face_points=(2, b)), np.linalg.norm(V - x, axis=1), rtol=1e-13)
