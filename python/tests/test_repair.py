"""repair=True: the repairs of dggvtp --repair (the same per-vertex results: removed vertices nan
and -1, merged ones their stand-in's values), faces with a repeated corner dropped, and what
dggvtp says as warning: lines as RuntimeWarnings."""
import math
import warnings

import numpy as np
import pytest

import dggvtp
from conftest import CLI_DATA, needs_cli, run_cli, same_bits

SQUARE = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
R2 = math.sqrt(2)

# the corpus of the CLI's cli.repair_* cases: defects of real scans
SEAM = (SQUARE + [[0, 0, 0], [1, 1, 0]], [[0, 1, 2], [4, 5, 3]])                  # coincident vertices
STRAY = (SQUARE + [[5, 5, 5]], [[0, 1, 2], [0, 2, 3]])                             # a vertex no face uses
GRID = ([[i, j, 0] for j in range(3) for i in range(3)] + [[1, 1, 0]],             # marching cubes: a doubled
        [[9, 0, 1], [9, 1, 2], [9, 2, 5], [9, 5, 8], [4, 8, 7], [4, 7, 6],         # centre, two zero-area faces
         [4, 6, 3], [4, 3, 0], [0, 9, 4], [9, 8, 4]])
REPEATED = (SQUARE, [[0, 1, 2], [0, 2, 2], [0, 2, 3]])                             # a face 0 2 2


def repaired(V, F, **kwargs):
    with pytest.warns(RuntimeWarning, match="repair=True"):
        return dggvtp.GeodesicSolver(V, F, repair=True, **kwargs)


def test_stitched_seam():
    solver = dggvtp.GeodesicSolver(*SEAM)
    with pytest.warns(RuntimeWarning, match="3 of 6 vertices are unreachable"):
        assert np.isinf(solver.distances(0)[3:]).all()
    with pytest.warns(RuntimeWarning) as record:
        solver = dggvtp.GeodesicSolver(*SEAM, repair=True)
    messages = [str(w.message) for w in record]
    assert "GeodesicSolver(V, F): repair=True: stitch_borders stitched 1 pairs of coincident border edges" in messages
    assert any("0 vertices of the file removed (nan, label -1), 2 merged" in m for m in messages)
    d, labels = solver.distances(0, return_labels=True)
    assert np.allclose(d, [0, 1, R2, 1, 0, R2], rtol=1e-15) and np.array_equal(labels, [0] * 6)
    assert same_bits(solver.distances(4), d)  # a source on a merged vertex is one on its stand-in


def test_removed_vertex_is_nan():
    solver = repaired(*STRAY)
    d, labels = solver.distances(0, return_labels=True)
    assert np.allclose(d[:4], [0, 1, R2, 1], rtol=1e-15) and math.isnan(d[4])
    assert np.array_equal(labels, [0, 0, 0, 0, -1])
    with pytest.raises(ValueError, match="source 4 was removed by repair=True"):
        solver.distances(4)
    with pytest.raises(ValueError, match="target 4 was removed by repair=True"):
        solver.target_distances(0, targets=[4])
    D = solver.distances_from_each([0, 2])
    assert math.isnan(D[0, 4]) and same_bits(D[0], d)


def test_marching_cubes_and_what_repair_says():
    with pytest.raises(ValueError, match="is degenerate.*; repair=True removes such faces"):
        dggvtp.GeodesicSolver(*GRID)
    with pytest.warns(RuntimeWarning) as record:
        solver = dggvtp.GeodesicSolver(*GRID, repair=True)
    assert "GeodesicSolver(V, F): repair=True: remove_degenerate_faces removed 2 faces and 1 vertex" in [
        str(w.message) for w in record]
    expected = [0, 1, 2, 1, R2, math.sqrt(5), 2, math.sqrt(5), 2 * R2, R2]
    assert np.allclose(solver.distances(0), expected, rtol=1e-15)


def test_faces_with_a_repeated_corner():
    with pytest.raises(ValueError, match="face 1 uses vertex 2 twice; repair=True drops such faces"):
        dggvtp.GeodesicSolver(*REPEATED)
    solver = repaired(*REPEATED)
    assert solver.num_faces == 2 and np.allclose(solver.distances(0), [0, 1, R2, 1], rtol=1e-15)


def test_read_mesh_with_repair(tmp_path):
    path = tmp_path / "r.off"
    path.write_text("OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n5 5 5\n3 0 1 2\n3 0 2 2\n3 0 2 3\n")
    with pytest.raises(ValueError, match="face 1 uses vertex 2 twice; repair=True drops such faces"):
        dggvtp.read_mesh(path)
    with pytest.warns(RuntimeWarning, match="dropped 1 faces with a repeated corner"):
        V, F = dggvtp.read_mesh(path, repair=True)
    assert V.shape == (5, 3) and F.shape == (2, 3) and 4 not in F
    assert sorted(map(sorted, F.tolist())) == [[0, 1, 2], [0, 2, 3]]
    # the arrays of the file, repaired by the solver: the per-vertex results of dggvtp --repair
    with pytest.warns(RuntimeWarning):
        d = dggvtp.GeodesicSolver(V, F, repair=True).distances(0)
    assert np.allclose(d[:4], [0, 1, R2, 1], rtol=1e-15) and math.isnan(d[4])


@needs_cli
@pytest.mark.parametrize("name, mesh", [("seam", SEAM), ("stray", STRAY), ("grid", GRID), ("repeated", REPEATED)])
def test_as_dggvtp_repair(tmp_path, name, mesh):
    V, F = mesh
    path = tmp_path / f"{name}.off"
    path.write_text(f"OFF\n{len(V)} {len(F)} 0\n" + "".join(f"{x} {y} {z}\n" for x, y, z in V) +
                    "".join(f"3 {a} {b} {c}\n" for a, b, c in F))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        solver = dggvtp.GeodesicSolver(V, F, repair=True)
    for source in (0, 2):
        d, labels = solver.distances([source, 3], return_labels=True)
        expected_d, expected_labels = run_cli(tmp_path, str(path), "--repair", "--source", source, "--source", 3,
                                              labels=True)
        assert same_bits(d, expected_d) and same_bits(labels, expected_labels), (name, source)


def test_non_manifold_vertices_warn():
    # two squares that meet at vertex 0 only: kept as it is
    V = SQUARE + [[-1, 0, 0], [-1, -1, 0], [0, -1, 0]]
    with pytest.warns(RuntimeWarning, match=r"GeodesicSolver\(V, F\): kept 1 non-manifold vertices"):
        dggvtp.GeodesicSolver(V, [[0, 1, 2], [0, 2, 3], [0, 4, 5], [0, 5, 6]])
    # three triangles on one edge: split into sheets
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
    with pytest.warns(RuntimeWarning, match=r"GeodesicSolver\(V, F\): split 4 non-manifold vertices"):
        solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    assert solver.repairs == ["split 4 non-manifold vertices"]
    # the copies are one point: the other sheets are reached through the edge's ends
    assert np.allclose(solver.distances(2), [1, np.sqrt(2), 0, 2, 2], rtol=1e-15)

    # a needle three times (a fuzz input that hung): sheets of one triangle; one face is kept
    V = [[0, 0, 0], [1, 0, 0], [0, 0.0041887902047863905, 0]]
    with pytest.warns(RuntimeWarning, match=r"dropped 2 faces on the same three vertices as another face"):
        solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [0, 1, 2], [0, 2, 1]])
    assert np.allclose(solver.distances(1), [1, 0, np.hypot(1, V[2][1])], rtol=1e-15)


def test_point_far_from_the_surface_warns():
    solver = dggvtp.GeodesicSolver(SQUARE, [[0, 1, 2], [0, 2, 3]])
    with pytest.warns(RuntimeWarning, match=r"points\[1\] \(0.5, 0.5, 1\) is 1 away from the surface"):
        solver.distances(0, points=[[0.5, 0.5, 0], [0.5, 0.5, 1]])
    with pytest.warns(RuntimeWarning, match=r"target_points\[0\] \(2, 0, 0\) is 1 away"):
        solver.target_distances(0, target_points=[2, 0, 0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a point on the surface says nothing
        solver.distances(None, points=[0.25, 0.5, 0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # and a warning made an error by the filter is raised
        with pytest.raises(RuntimeWarning):
            solver.distances(None, points=[0.25, 0.5, 3])
