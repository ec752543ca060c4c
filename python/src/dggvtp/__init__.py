"""Geodesic distances on triangle meshes by window propagation (DGG-VTP for CGAL).

Exact distances (the VTP algorithm) or distances within a relative error epsilon of the exact ones
(DGG-VTP), from vertices or surface points to every vertex, to chosen targets, shortest paths, and
sparse matrices of the distances within a radius. NumPy arrays in, NumPy arrays out.

    V, F = dggvtp.read_mesh("mesh.ply")
    d = dggvtp.geodesic_distances(V, F, 0)        # one call
    solver = dggvtp.GeodesicSolver(V, F)          # or prepared once, for many queries
    d = solver.distances(0)
    distance, path = solver.distance_and_path(0, 7)    # one pair, the path from 0 to 7
    import dggvtp.gdist as gdist                       # gdist's functions, as tvb-gdist

Every call runs on all cores (threads=0); in a pool of worker processes pass threads=1.
help(dggvtp.GeodesicSolver) documents every argument.
"""
import functools
from typing import Any

try:
    from ._dggvtp import GeodesicSolver, InputError, __version__, read_mesh
except ModuleNotFoundError as e:  # the sources, python/src/dggvtp, have no compiled module
    raise ModuleNotFoundError(f"dggvtp imported from {__path__[0]}, without its compiled module _dggvtp: build it "
                              "(target dggvtp_python; PYTHONPATH=build/python) or install it (README.md, "
                              "section Python)") from e

from . import _deprecated
from ._short_errors import short_type_errors

__all__ = ["GeodesicSolver", "InputError", "geodesic_distances", "read_mesh", "__version__"]

# pybind11's TypeErrors print every argument (the whole V and F): one line instead
read_mesh = short_type_errors(read_mesh, "read_mesh")
for _name in ("__init__", "distances", "distances_from_each", "local_distance_matrix", "target_distances",
              "distances_and_paths", "geodesic_path", "distance_and_path", "farthest_point_sampling",
              "pair_distances"):
    setattr(GeodesicSolver, _name, short_type_errors(getattr(GeodesicSolver, _name), f"GeodesicSolver.{_name}"))
# the former spellings, for one more release (see _deprecated.py)
GeodesicSolver.__init__ = _deprecated.keyword_precision(GeodesicSolver.__init__)  # type: ignore[method-assign]
_SOURCES = ("sources", ("points", "face_points"))
for _name, _required in (("distances", [_SOURCES]),
                         ("target_distances", [_SOURCES, ("targets", ("target_points", "target_face_points"))]),
                         ("distances_and_paths", [_SOURCES, ("targets", ("target_points", "target_face_points"))]),
                         ("geodesic_path", [_SOURCES, ("target", ("target_point", "target_face_point"))])):
    setattr(GeodesicSolver, _name, _deprecated.requires(getattr(GeodesicSolver, _name), _name, _required))
GeodesicSolver.farthest_point_sampling = _deprecated.first_sample(  # type: ignore[method-assign]
    GeodesicSolver.farthest_point_sampling)
for _name, _former in _deprecated.FORMER_METHODS.items():
    setattr(GeodesicSolver, _name, _former)
del _name, _required, _former, _SOURCES


def _geodesic_distances(V: Any, F: Any, sources: Any, *, precision: str = "double", repair: bool = False,
                        **options: Any) -> Any:
    """Geodesic distance of every vertex of the mesh (V, F) to the nearest source, in one call.

    GeodesicSolver(V, F, precision=precision, repair=repair, threads=threads).distances(sources,
    **options), the same values: the options are those of GeodesicSolver.distances (points,
    face_points, epsilon, max_distance, threads, return_labels, return_bounds, prior_distances,
    prior_labels, prior_bounds); threads (default 0: all cores) serves the preparation too. For
    several queries on one mesh, keep a GeodesicSolver: it prepares the mesh once.
    """
    threads = options.get("threads", 0)
    return GeodesicSolver(V, F, precision=precision, repair=repair, threads=threads).distances(sources, **options)


@functools.wraps(_geodesic_distances)
def geodesic_distances(*args: Any, **kwargs: Any) -> Any:
    if len(args) == 2 and "sources" not in kwargs:  # the former spelling: sources omitted
        if kwargs.get("points") is None and kwargs.get("face_points") is None:
            raise TypeError("geodesic_distances() missing required argument: 'sources' (or None with points or "
                            "face_points)")
        _deprecated.warn("geodesic_distances(V, F) without sources is deprecated: they are required, None (or []) "
                         "where points or face_points give the places")
        kwargs["sources"] = None
    return _geodesic_distances(*args, **kwargs)


geodesic_distances.__name__ = geodesic_distances.__qualname__ = "geodesic_distances"
