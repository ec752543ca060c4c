"""local_distance_matrix(): a scipy.sparse.csr_matrix whose row k, as an array with inf where it
has no entry, is distances(sources[k], max_distance=D) bit for bit; and dggvtp-batch --max-distance
writes the same matrix as a .npz that scipy.sparse.load_npz reads."""
import math
import subprocess
import warnings
import zipfile

import numpy as np
import pytest
import scipy.sparse

import dggvtp
from conftest import BATCH, mesh, needs_batch, same_bits


@pytest.fixture(scope="module")
def lion():  # open, with a border: rows near it are cut by it
    V, F = dggvtp.read_mesh(mesh("lion_head.ply"))
    return V, F, dggvtp.GeodesicSolver(V, F)


def dense_row(M, k):
    row = np.full(M.shape[1], np.inf)
    start, end = M.indptr[k], M.indptr[k + 1]
    row[M.indices[start:end]] = M.data[start:end]
    return row


def radius(V, F, neighbours):
    """a radius of about `neighbours` vertices around each vertex: the disc of that many vertices'
    share of the area"""
    area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()
    return math.sqrt(neighbours * area / len(V) / math.pi)


@pytest.mark.parametrize("name, every", [("spot.ply", 1), ("lion_head.ply", 8)])
def test_every_row_is_the_field_within_the_radius(name, every):
    V, F = dggvtp.read_mesh(mesh(name))
    solver = dggvtp.GeodesicSolver(V, F)
    D = radius(V, F, 30)
    M = solver.local_distance_matrix(D, threads=2)
    assert isinstance(M, scipy.sparse.csr_matrix) and M.shape == (len(V), len(V))
    assert M.data.dtype == np.float64 and M.indices.dtype == np.int32 and M.indptr.dtype == np.int32
    assert M.has_sorted_indices and 10 < M.nnz / len(V) < 100
    for k in range(0, len(V), every):
        assert same_bits(dense_row(M, k), solver.distances(k, max_distance=D)), k
    assert np.all(M.diagonal() == 0) and np.all(M.data <= D)
    assert abs(M - M.T).max() < 1e-12 * D  # exact distances are symmetric, up to rounding


def test_sources_epsilon_threads(lion):
    V, F, solver = lion
    D = radius(V, F, 50)
    sources = [5000, 17, 17, 8000]
    M = solver.local_distance_matrix(D, sources, epsilon=1e-3)
    assert M.shape == (4, len(V))
    for k, s in enumerate(sources):
        assert same_bits(dense_row(M, k), solver.distances(s, max_distance=D, epsilon=1e-3))
    for threads in (0, 2):
        other = solver.local_distance_matrix(D, sources, epsilon=1e-3, threads=threads)
        assert all(same_bits(getattr(M, a), getattr(other, a)) for a in ("data", "indices", "indptr"))
    one = solver.local_distance_matrix(D, 17)
    assert one.shape == (1, len(V)) and same_bits(dense_row(one, 0), dense_row(M, 1))
    zero = solver.local_distance_matrix(0.0, [3, 4])
    assert zero.nnz == 2 and list(zero.indices) == [3, 4] and np.all(zero.data == 0)


def test_copies_and_repairs():
    # the seam of test_repair, stitched: vertex 4 merged into 0, 5 into 2; and a stray vertex removed
    V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 0], [1, 1, 0], [5, 5, 5]]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [4, 5, 3]], repair=True)
        d = solver.distances(1)
    M = solver.local_distance_matrix(1.2)
    assert M.shape == (7, 7) and M.indptr[7] - M.indptr[6] == 0  # the removed vertex: no row, no entry
    assert 6 not in M.indices
    for k in range(6):
        expected = solver.distances(k, max_distance=1.2)
        expected[np.isnan(expected)] = np.inf
        assert same_bits(dense_row(M, k), expected), k
    assert dense_row(M, 1)[4] == d[4] == d[0] and same_bits(dense_row(M, 4), dense_row(M, 0))
    with pytest.raises(ValueError, match="source 6 was removed by repair=True"):
        solver.local_distance_matrix(1.0, [6])
    # split vertices: the file vertex's smallest distance
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
    with pytest.warns(RuntimeWarning, match="split"):
        solver = dggvtp.GeodesicSolver(V, [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    M = solver.local_distance_matrix(10.0)
    for k in range(5):
        assert same_bits(dense_row(M, k), solver.distances(k, max_distance=10.0))


@needs_batch
def test_dggvtp_batch_writes_the_same_npz(tmp_path):
    V, F = dggvtp.read_mesh(mesh("spot.ply"))
    solver = dggvtp.GeodesicSolver(V, F)
    D = radius(V, F, 30)
    out = tmp_path / "local.npz"
    sources = tmp_path / "sources.txt"
    sources.write_text("9 3 2000 100\n")
    for spec, rows in (("all", None), (str(sources), [9, 3, 2000, 100])):
        subprocess.run([BATCH, mesh("spot.ply"), "--sources", spec, "--max-distance", repr(D), "--output", out,
                        "--threads", "2", "--quiet"], check=True)
        with zipfile.ZipFile(out) as z:
            assert z.testzip() is None
            assert sorted(z.namelist()) == ["data.npy", "format.npy", "indices.npy", "indptr.npy", "shape.npy"]
        M = scipy.sparse.load_npz(out)
        expected = solver.local_distance_matrix(D, rows)
        assert isinstance(M, scipy.sparse.csr_matrix) and M.shape == expected.shape
        for a in ("data", "indices", "indptr"):
            assert same_bits(getattr(M, a), getattr(expected, a)), a


def test_csc_and_symmetric_against_dense_rows(lion):
    # format='csc' is the same matrix by columns (gdist's format); symmetric=True keeps of each pair
    # the smaller of the two directions, an entry in one direction only (the other beyond the
    # radius) as it is; both checked against the dense rows, at 0 and at an accuracy
    V, F, solver = lion
    D = radius(V, F, 20)
    for epsilon in (0.0, 1e-2):
        M = solver.local_distance_matrix(D, epsilon=epsilon)
        C = solver.local_distance_matrix(D, epsilon=epsilon, format="csc")
        assert isinstance(C, scipy.sparse.csc_matrix) and C.shape == M.shape and C.has_sorted_indices
        assert (C != M).nnz == 0 and same_bits(C.tocsr().data, M.data)
        sources = [5000, 17, 8000]
        Cs = solver.local_distance_matrix(D, sources, epsilon=epsilon, format="csc")
        assert isinstance(Cs, scipy.sparse.csc_matrix) and Cs.shape == (3, len(V))
        for k, s in enumerate(sources):
            assert same_bits(Cs.getrow(k).toarray().ravel()[Cs.getrow(k).indices],
                             M.getrow(s).data), s
        S = solver.local_distance_matrix(D, epsilon=epsilon, symmetric=True)
        assert isinstance(S, scipy.sparse.csr_matrix) and (S != S.T).nnz == 0
        rows = range(0, len(V), 97)
        for k in rows:
            row = solver.distances(k, max_distance=D, epsilon=epsilon)
            column = np.array([solver.distances(j, max_distance=D, epsilon=epsilon)[k] for j in S.getrow(k).indices])
            expected = np.minimum(row[S.getrow(k).indices], column)
            assert same_bits(S.getrow(k).data, expected), k
            assert set(S.getrow(k).indices) >= set(np.flatnonzero(np.isfinite(row))), k
        SC = solver.local_distance_matrix(D, epsilon=epsilon, symmetric=True, format="csc")
        assert isinstance(SC, scipy.sparse.csc_matrix) and (SC != S).nnz == 0


def test_format_and_symmetric_are_checked(lion):
    V, F, solver = lion
    with pytest.raises(ValueError, match="format must be 'csr' or 'csc'"):
        solver.local_distance_matrix(0.1, format="coo")
    with pytest.raises(ValueError, match="symmetric=True needs the square matrix"):
        solver.local_distance_matrix(0.1, [1, 2], symmetric=True)
