# Type information of the package dggvtp (PEP 561, with py.typed): what __init__.py exports.
from typing import Literal, Tuple, Union, overload

import numpy.typing as npt

from ._dggvtp import _FacePoints, _Points, _Precision, _PerVertex, _Real, _Vertices, _Distances, _Labels
from ._dggvtp import GeodesicSolver as GeodesicSolver
from ._dggvtp import InputError as InputError
from ._dggvtp import __version__ as __version__
from ._dggvtp import read_mesh as read_mesh

__all__ = ["GeodesicSolver", "InputError", "geodesic_distances", "read_mesh", "__version__"]

@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices, *,
                       precision: _Precision = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_labels: Literal[False] = False,
                       return_bounds: Literal[False] = False,
                       prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                       prior_bounds: _PerVertex = None) -> _Distances: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices, *,
                       precision: _Precision = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_labels: Literal[True],
                       return_bounds: Literal[False] = False,
                       prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                       prior_bounds: _PerVertex = None) -> Tuple[_Distances, _Labels]: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices, *,
                       precision: _Precision = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_labels: Literal[False] = False,
                       return_bounds: Literal[True],
                       prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                       prior_bounds: _PerVertex = None) -> Tuple[_Distances, _Distances]: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices, *,
                       precision: _Precision = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_labels: Literal[True],
                       return_bounds: Literal[True],
                       prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                       prior_bounds: _PerVertex = None) -> Tuple[_Distances, _Labels, _Distances]: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices, *,
                       precision: _Precision = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_labels: bool = False,
                       return_bounds: bool = False,
                       prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                       prior_bounds: _PerVertex = None) -> Union[_Distances, Tuple[_Distances, _Labels],
                                                             Tuple[_Distances, _Distances],
                                                             Tuple[_Distances, _Labels, _Distances]]: ...
