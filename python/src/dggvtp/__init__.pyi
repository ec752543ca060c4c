# Type information of the package dggvtp (PEP 561, with py.typed): what __init__.py exports.
from typing import Literal, Tuple, Union, overload

import numpy.typing as npt

from ._dggvtp import _FacePoints, _Points, _Real, _Vertices, _Distances, _Labels
from ._dggvtp import GeodesicSolver as GeodesicSolver
from ._dggvtp import InputError as InputError
from ._dggvtp import __version__ as __version__
from ._dggvtp import read_mesh as read_mesh

__all__ = ["GeodesicSolver", "InputError", "geodesic_distances", "read_mesh", "__version__"]

@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices = None, *,
                       precision: str = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 1, return_labels: Literal[False] = False,
                       return_bounds: Literal[False] = False) -> _Distances: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices = None, *,
                       precision: str = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 1, return_labels: Literal[True],
                       return_bounds: Literal[False] = False) -> Tuple[_Distances, _Labels]: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices = None, *,
                       precision: str = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 1, return_labels: Literal[False] = False,
                       return_bounds: Literal[True]) -> Tuple[_Distances, _Distances]: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices = None, *,
                       precision: str = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 1, return_labels: Literal[True],
                       return_bounds: Literal[True]) -> Tuple[_Distances, _Labels, _Distances]: ...
@overload
def geodesic_distances(V: npt.ArrayLike, F: npt.ArrayLike, sources: _Vertices = None, *,
                       precision: str = "double", repair: bool = False,
                       points: _Points = None, face_points: _FacePoints = None, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 1, return_labels: bool = False,
                       return_bounds: bool = False) -> Union[_Distances, Tuple[_Distances, _Labels],
                                                             Tuple[_Distances, _Distances],
                                                             Tuple[_Distances, _Labels, _Distances]]: ...
