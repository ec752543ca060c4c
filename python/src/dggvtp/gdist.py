"""gdist's functions, answered by dggvtp: ``import dggvtp.gdist as gdist`` is the whole change.

compute_gdist, local_gdist_matrix and distance_matrix_of_selected_points take the arguments of
tvb-gdist 2.x (``gdist``) in its order, with its defaults, and return what it returns: NumPy
arrays, scipy.sparse.csc_matrix. The distances are exact by default, as gdist's are (the same to
about 1e-15 relative); the keyword ``epsilon``, this module's own, asks for DGG-VTP instead: every
distance within a relative error epsilon of the exact one, never below it.

Where dggvtp differs from gdist, on purpose:
  - any array-like is taken (gdist wants float64 vertices and int32 indices);
  - ``max_distance=None`` (the default) means no limit (gdist's default is 1e100);
  - a vertex beyond ``max_distance``, or on another component, is ``inf`` in compute_gdist and
    has no entry in the matrices (gdist may give 1e100 or store inf there); "beyond" is said of
    the distance computed: with ``epsilon`` > 0 every vertex within max_distance / (1 + epsilon)
    of the exact distance is there, and some within max_distance may not be (to have all of
    them, pass max_distance (1 + epsilon) and keep the entries whose certified lower bound d - b
    is within it, d and b from GeodesicSolver.distances(..., return_bounds=True));
  - bad input raises ValueError with a message (gdist may crash or hang).
As in gdist, ``is_one_indexed`` applies to ``triangles`` only: source, target and point indices
are 0-based either way.
"""
from typing import Any, Optional

import numpy as np
import scipy.sparse

from . import _dggvtp

__all__ = ["compute_gdist", "local_gdist_matrix", "distance_matrix_of_selected_points"]


def _solver(vertices: Any, triangles: Any, is_one_indexed: bool) -> _dggvtp.GeodesicSolver:
    triangles = np.asarray(triangles)
    if is_one_indexed:
        if triangles.size and triangles.min() < 1:
            raise ValueError("is_one_indexed=True, but triangles has an index below 1")
        triangles = triangles - 1
    return _dggvtp.GeodesicSolver(vertices, triangles)


def _limit(max_distance: Optional[float]) -> float:
    if max_distance is None:
        return np.inf
    limit = float(max_distance)
    if not limit >= 0:
        raise ValueError(f"max_distance must be a number >= 0 or None (no limit), not {max_distance!r}")
    return limit


def compute_gdist(vertices: Any, triangles: Any, source_indices: Any = None, target_indices: Any = None,
                  max_distance: Optional[float] = None, is_one_indexed: bool = False, *,
                  epsilon: float = 0.0) -> np.ndarray:
    """Geodesic distance of each target to the nearest source, as gdist.compute_gdist.

    vertices: (n, 3) coordinates; triangles: (m, 3) vertex indices (1-based if is_one_indexed).
    source_indices: vertex indices (default: vertex 0); target_indices: vertex indices (default:
    every vertex). Returns a float64 array, one distance per target, inf beyond max_distance or
    where no path reaches. epsilon: 0 (exact, the default) or in (0, 1], every distance within a
    relative error epsilon of the exact one. The propagation stops once the targets are final.
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    sources = [0] if source_indices is None else source_indices
    limit = _limit(max_distance)
    if target_indices is None:
        return solver.distances(sources, epsilon=epsilon, max_distance=limit)
    return solver.target_distances(sources, target_indices, epsilon=epsilon, max_distance=limit)


def local_gdist_matrix(vertices: Any, triangles: Any, max_distance: Optional[float] = None,
                       is_one_indexed: bool = False, *, epsilon: float = 0.0) -> scipy.sparse.csc_matrix:
    """The distances from every vertex to those within max_distance of it, as
    gdist.local_gdist_matrix: a scipy.sparse.csc_matrix (n, n), entry (i, j) the distance from i to
    j where it is positive and at most max_distance (no entry on the diagonal, as gdist). With
    max_distance=None every pair: n^2 entries (memory!). epsilon as in compute_gdist; the matrix
    is then the smaller of (i, j) and (j, i), symmetric as gdist's exact one.
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    limit = _limit(max_distance)
    # no limit: every pair within the largest radius the matrix can take
    radius = float(np.finfo(np.float64).max) if np.isinf(limit) else limit
    # gdist's matrix is symmetric (exact both ways, to rounding); with epsilon, the two ways
    # differ within it: the smaller of each pair keeps it symmetric
    matrix = solver.local_distance_matrix(radius, epsilon=epsilon, format="csc", symmetric=epsilon > 0)
    matrix.eliminate_zeros()
    return matrix


def distance_matrix_of_selected_points(vertices: Any, triangles: Any, points: Any,
                                       max_distance: Optional[float] = None, is_one_indexed: bool = False, *,
                                       epsilon: float = 0.0) -> scipy.sparse.csc_matrix:
    """The distances between pairs of the given vertices, as gdist.distance_matrix_of_selected_points:
    a scipy.sparse.csc_matrix (n, n) whose entries (p, q) and (q, p), for p before q in `points`,
    both hold the distance from p to q (computed from p; the same as from q to about 1e-15 in the
    exact mode); a pair beyond max_distance, or not connected, has no entry. epsilon as in
    compute_gdist.
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    limit = _limit(max_distance)
    points = np.asarray(points).reshape(-1)
    rows, columns, values = [], [], []
    for k in range(len(points) - 1):
        targets = points[k + 1:]
        d = solver.target_distances(int(points[k]), targets, epsilon=epsilon, max_distance=limit)
        kept = np.isfinite(d)
        for first, second in ((np.full(len(targets), points[k]), targets), (targets, np.full(len(targets), points[k]))):
            rows.append(first[kept])
            columns.append(second[kept])
            values.append(d[kept])
    n = solver.num_vertices
    if not rows:
        return scipy.sparse.csc_matrix((n, n))
    return scipy.sparse.csc_matrix((np.concatenate(values), (np.concatenate(rows), np.concatenate(columns))),
                                   shape=(n, n))
