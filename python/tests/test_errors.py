"""Bad input raises ValueError with a message saying what is wrong; it never crashes."""
import math

import numpy as np
import pytest

import dggvtp
from conftest import CLI_DATA

TETRA_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TETRA_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


@pytest.fixture(scope="module")
def solver():
    return dggvtp.GeodesicSolver(TETRA_V, TETRA_F)


@pytest.mark.parametrize("V, F, message", [
    (np.zeros((4, 4)), TETRA_F, r"V must have shape \(n, 3\), or \(n, 2\) for points of the plane z = 0"),
    (np.zeros(12), TETRA_F, r"V must have shape \(n, 3\)"),
    (TETRA_V, np.array(TETRA_F).T[:2], r"F must have shape \(n, 3\)"),
    ([["a", "b", "c"]], TETRA_F, "V must hold real numbers"),
    (TETRA_V, np.array(TETRA_F, dtype=float), "F must hold integers"),
    (TETRA_V, [[0, 1], [2, 3, 1]], "F is not an array of numbers"),
    (np.zeros((0, 3)), np.zeros((0, 3), dtype=int), "V has no vertices"),
    (TETRA_V, [[0, 1, 4]], "face 0 refers to vertex 4, but the mesh has 4 vertices"),
    (TETRA_V, [[0, 1, -1]], "face 0 refers to vertex -1"),
    (TETRA_V, [[0, 1, 1]], "face 0 uses vertex 1 twice; repair=True drops such faces"),
    ([[0, 0, 0], [1, math.nan, 0], [0, 1, 0]], [[0, 1, 2]], "vertex 1 has a coordinate that is not finite"),
    ([[0, 0, 0], [1, math.inf, 0], [0, 1, 0]], [[0, 1, 2]], "vertex 1 has a coordinate that is not finite"),
    # the library's input policy: a degenerate (flat) triangle
    ([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 2]], "degenerate"),
])
def test_bad_mesh(V, F, message):
    with pytest.raises(ValueError, match=message):
        dggvtp.GeodesicSolver(V, F)


def test_bad_precision():
    with pytest.raises(ValueError, match="precision must be 'double' or 'float'"):
        dggvtp.GeodesicSolver(TETRA_V, TETRA_F, precision="half")


@pytest.mark.parametrize("kwargs, message", [
    (dict(sources=4), "source 4 is out of range"),
    (dict(sources=-1), "source -1 is out of range"),
    (dict(sources=[0, 17]), "source 17 is out of range"),
    (dict(sources=[[0]]), "source must be a vertex index"),
    (dict(sources=0.5), "source must hold integers"),
    (dict(), "no source given"),
    (dict(sources=[]), "no source given"),
    (dict(points=[[0, math.nan, 0]]), "points needs finite coordinates"),
    (dict(points=[[0, 0]]), r"points must have shape \(k, 3\)"),
    (dict(face_points=[0, 1, 2]), r"face_points must be a pair \(faces, barycentric\)"),
    (dict(face_points="ab"), r"face_points must be a pair \(faces, barycentric\)"),
    (dict(face_points=(4, [1, 0, 0])), r"face_points face 4 is out of range \(F has 4 faces\)"),
    (dict(face_points=(-1, [1, 0, 0])), r"face_points face -1 is out of range"),
    (dict(face_points=(0.5, [1, 0, 0])), "face_points face must hold integers"),
    (dict(face_points=([0, 1], [1, 0, 0])), "face_points gives 2 faces and 1 rows of barycentric coordinates"),
    (dict(face_points=(0, [1, 0])), r"face_points barycentric coordinates must have shape \(k, 3\)"),
    (dict(face_points=(0, [1.5, -0.5, 0])), r"face_points barycentric coordinates must be finite and not negative \(row 0\)"),
    (dict(face_points=(0, [0.5, 0.5, 0.5])), r"face_points barycentric coordinates must add up to 1 \(row 0 adds up to 1.5"),
    (dict(face_points=(0, [math.nan, 0.5, 0.5])), "face_points barycentric coordinates must be finite"),
    (dict(sources=0, epsilon=-1e-3), r"epsilon must be a number in \[0, 1\] \(0: exact\); got -0.001$"),
    (dict(sources=0, epsilon=math.nan), r"epsilon must be a number in \[0, 1\]"),
    (dict(sources=0, epsilon=math.inf), r"epsilon must be a number in \[0, 1\]"),
    (dict(sources=0, epsilon=1.5), r"epsilon must be a number in \[0, 1\] \(0: exact\); got 1.5$"),
    (dict(sources=0, max_distance=-1.0), r"max_distance must be a number >= 0 \(inf: no limit\); got -1.0$"),
    (dict(sources=0, max_distance=math.nan), "max_distance must be a number >= 0"),
    (dict(sources=0, threads=-2), "threads must be >= 0"),
])
def test_bad_query(solver, kwargs, message):
    kwargs.setdefault("sources", None)
    with pytest.raises(ValueError, match=message):
        solver.distances(**kwargs)


def test_bad_targets(solver):
    with pytest.raises(ValueError, match="target 9 is out of range"):
        solver.target_distances(0, targets=[9])
    with pytest.raises(ValueError, match="no target given"):
        solver.target_distances(0, None)
    with pytest.raises(ValueError, match="target_points needs finite coordinates"):
        solver.target_distances(0, None, target_points=[math.inf, 0, 0])
    with pytest.raises(ValueError, match="give one target"):
        solver.geodesic_path(0, None)
    with pytest.raises(ValueError, match="give one target"):
        solver.geodesic_path(0, target=1, target_point=[0, 0, 0])
    with pytest.raises(ValueError, match="give one target"):
        solver.geodesic_path(0, target=[1, 2])
    with pytest.raises(ValueError, match=r"epsilon must be a number in \[0, 1\]"):
        solver.distances_from_each([0, 1], epsilon=-1.0)


def test_bad_local_distance_matrix(solver):
    for bad in (-1.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="max_distance must be a finite number >= 0"):
            solver.local_distance_matrix(bad)
    with pytest.raises(ValueError, match="source 4 is out of range"):
        solver.local_distance_matrix(1.0, [0, 4])
    with pytest.raises(ValueError, match="no source given: sources=None .the default. is every vertex"):
        solver.local_distance_matrix(1.0, [])
    with pytest.raises(ValueError, match=r"epsilon must be a number in \[0, 1\]"):
        solver.local_distance_matrix(1.0, epsilon=2.0)
    with pytest.raises(ValueError, match="threads must be >= 0"):
        solver.local_distance_matrix(1.0, threads=-1)


def test_bad_path_targets(solver):
    with pytest.raises(ValueError, match="no target given .targets, target_points or target_face_points."):
        solver.distances_and_paths(0, None)
    with pytest.raises(ValueError, match="give one target"):
        solver.geodesic_path(0, None, target_face_point=([0, 1], [[1, 0, 0], [0, 1, 0]]))
    with pytest.raises(ValueError, match="target_face_point barycentric coordinates must add up to 1"):
        solver.geodesic_path(0, None, target_face_point=(0, [1, 1, 0]))


def test_point_on_mesh_without_faces():
    solver = dggvtp.GeodesicSolver([[0, 0, 0], [1, 0, 0]], np.zeros((0, 3), dtype=int))
    with pytest.raises(ValueError, match="the mesh has no face to place a point on"):
        solver.distances(None, points=[0, 0, 0])


def test_isolated_sources():
    # vertex 4 is used by no face: it is a source at distance 0 that reaches nothing; where points
    # are located, no propagation can start from it (dggvtp's message)
    solver = dggvtp.GeodesicSolver(TETRA_V + [[5, 5, 5]], TETRA_F)
    d = solver.distances(4)
    assert d[4] == 0 and np.all(np.isinf(d[:4]))
    with pytest.raises(ValueError, match="every source is a vertex that no face uses"):
        solver.target_distances(4, None, target_points=[0, 0, 0])
    d, labels = solver.distances([0, 4], points=[1, 0, 0], return_labels=True)
    assert d[4] == 0 and labels[4] == 1 and labels[1] == 2
    assert np.all(np.isfinite(d[:4])) and np.all(labels[[0, 2, 3]] == 0)


@pytest.mark.filterwarnings("ignore:.*non-manifold")  # point 4 is split into its 7 sheets
def test_windows_between_sheets_are_refused():
    # A fuzz input (cli.needles_of_seven_sheets_are_refused): needles 20,000 long at point 4, of 7
    # sheets, whose windows circle the point for ever from vertex 3; the query is refused past
    # the window limit, with the message of dggvtp, rather than left to run.
    solver = dggvtp.GeodesicSolver(*dggvtp.read_mesh(str(CLI_DATA / "needles_of_seven_sheets.off")))
    for epsilon in (0, 1e-3):
        with pytest.raises(ValueError, match="windows crossing between their sheets"):
            solver.distances(3, epsilon=epsilon)
    assert np.all(np.isfinite(solver.distances(4)))


@pytest.mark.parametrize("content, message", [
    ("", "cannot read|no vertices|empty"),
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n", "cannot read|truncated"),
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n", "not finite|cannot read"),
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "vertex 5|cannot read"),
])
def test_bad_files(tmp_path, content, message):
    path = tmp_path / "bad.off"
    path.write_text(content)
    with pytest.raises(ValueError, match=message):
        dggvtp.read_mesh(path)


def test_missing_file(tmp_path):
    with pytest.raises(dggvtp.InputError, match="cannot read"):
        dggvtp.read_mesh(tmp_path / "none.ply")
    assert issubclass(dggvtp.InputError, ValueError)
