"""read_mesh gives the file's vertices and faces in the file's order, as dggvtp reads them."""
import numpy as np
import pytest

import dggvtp
from conftest import CLI_DATA, MESHES, mesh, needs_cli, run_cli


def read_simple_ply(path):
    """An independent reader of the bundled meshes' layout: binary little-endian PLY, float x y z,
    faces as a uchar count and int indices"""
    raw = open(path, "rb").read()
    end = raw.index(b"end_header\n") + len(b"end_header\n")
    header = raw[:end].decode().split("\n")
    assert "format binary_little_endian 1.0" in header
    n = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    m = int(next(l for l in header if l.startswith("element face")).split()[2])
    V = np.frombuffer(raw, dtype="<f4", count=3 * n, offset=end).reshape(n, 3)
    faces = np.frombuffer(raw, dtype=np.dtype([("k", "u1"), ("i", "<i4", 3)]), count=m, offset=end + 12 * n)
    assert np.all(faces["k"] == 3)
    return V.astype(np.float64), faces["i"].astype(np.int64)


@pytest.mark.parametrize("name", MESHES)
def test_file_order(name):
    V, F = dggvtp.read_mesh(mesh(name))
    V0, F0 = read_simple_ply(mesh(name))
    assert V.dtype == np.float64 and F.dtype == np.int64
    assert np.array_equal(V, V0) and np.array_equal(F, F0)


def test_text_formats_and_polygons(tmp_path):
    # a permuted vertex order and a quad: the order stays the file's, the quad becomes 2 triangles
    V0 = np.array([[1, 1, 0], [0, 0, 0], [0, 1, 0], [1, 0, 0], [2, 0.5, 0]], dtype=float)
    (tmp_path / "m.off").write_text("OFF\n5 2 0\n" + "".join(f"{x} {y} {z}\n" for x, y, z in V0) +
                                    "4 1 3 0 2\n3 3 4 0\n")
    (tmp_path / "m.obj").write_text("".join(f"v {x} {y} {z}\n" for x, y, z in V0) + "f 2 4 1 3\nf 4 5 1\n")
    for name in ("m.off", "m.obj"):
        V, F = dggvtp.read_mesh(tmp_path / name)
        assert np.array_equal(V, V0)
        assert F.shape == (3, 3) and list(F[2]) == [3, 4, 0]
        assert sorted(map(sorted, F[:2].tolist())) in ([[0, 1, 2], [0, 1, 3]], [[0, 2, 3], [1, 2, 3]])


@needs_cli
@pytest.mark.parametrize("name", ["quad.off", "non_manifold_vertex.off", "inconsistent_orientation.off",
                                  "two_components_and_isolated_vertex.off"])
def test_solver_of_read_mesh_is_dggvtp(tmp_path, name):
    # the CLI's own test files (repairs, polygons, isolated vertices): the same distances per vertex
    path = str(CLI_DATA / name)
    V, F = dggvtp.read_mesh(path)
    solver = dggvtp.GeodesicSolver(V, F)
    for source in range(min(len(V), 3)):
        expected = run_cli(tmp_path, path, "--source", source)
        assert solver.distances(source).tobytes() == expected.tobytes(), (name, source)
