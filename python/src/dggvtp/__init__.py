"""Geodesic distances on triangle meshes by window propagation (DGG-VTP for CGAL).

Exact distances (the VTP algorithm) or distances within a relative error epsilon of the exact ones
(DGG-VTP), from vertices or surface points to every vertex, to chosen targets, shortest paths, and
sparse matrices of the distances within a radius. NumPy arrays in, NumPy arrays out.

    V, F = dggvtp.read_mesh("mesh.ply")
    d = dggvtp.geodesic_distances(V, F, 0)        # one call
    solver = dggvtp.GeodesicSolver(V, F)          # or prepared once, for many queries
    d = solver.distances(0)
    distance, path = solver.geodesic_distance(0, 7)   # one pair, as pygeodesic
    import dggvtp.gdist as gdist                       # gdist's functions, as tvb-gdist

help(dggvtp.GeodesicSolver) documents every argument.
"""
from typing import Any

try:
    from ._dggvtp import GeodesicSolver, InputError, __version__, read_mesh
except ModuleNotFoundError as e:  # the sources, python/src/dggvtp, have no compiled module
    raise ModuleNotFoundError(f"dggvtp imported from {__path__[0]}, without its compiled module _dggvtp: build it "
                              "(target dggvtp_python; PYTHONPATH=build/python) or install it (README.md, "
                              "section Python)") from e

from ._short_errors import short_type_errors

__all__ = ["GeodesicSolver", "InputError", "geodesic_distances", "read_mesh", "__version__"]

# pybind11's TypeErrors print every argument (the whole V and F): one line instead
read_mesh = short_type_errors(read_mesh, "read_mesh")
for _name in ("__init__", "distances", "distances_from_each", "local_distance_matrix", "target_distances",
              "shortest_paths", "shortest_path", "geodesic_distance"):
    setattr(GeodesicSolver, _name, short_type_errors(getattr(GeodesicSolver, _name), f"GeodesicSolver.{_name}"))
del _name


def geodesic_distances(V: Any, F: Any, sources: Any = None, *, precision: str = "double", repair: bool = False,
                       **options: Any) -> Any:
    """Geodesic distance of every vertex of the mesh (V, F) to the nearest source, in one call.

    GeodesicSolver(V, F, precision, repair=repair, threads=threads).distances(sources, **options),
    the same values: the options are those of GeodesicSolver.distances (points, face_points,
    epsilon, max_distance, threads, return_labels, return_bounds); threads serves the preparation
    too. For several queries on one mesh, keep a GeodesicSolver: it prepares the mesh once.
    """
    threads = options.get("threads", 1)
    return GeodesicSolver(V, F, precision, repair=repair, threads=threads).distances(sources, **options)
