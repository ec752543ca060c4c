# Type information of the extension module dggvtp._dggvtp (PEP 561, with py.typed): its
# signatures as help() shows them, and the documentation there.
import os
from typing import Any, List, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt
import scipy.sparse

__version__: str

_Vertices = Union[int, npt.ArrayLike, None]
_SourceVertices = Union[int, npt.ArrayLike]
_Real = Union[float, np.floating[Any], np.integer[Any]]   # NumPy scalars too
_Points = Optional[npt.ArrayLike]
_FacePoints = Optional[Tuple[npt.ArrayLike, npt.ArrayLike]]
_Distances = npt.NDArray[np.float64]
_Labels = npt.NDArray[np.int64]
_Precision = Literal["double", "float"]
_PerVertex = Optional[npt.ArrayLike]

class InputError(ValueError): ...

def read_mesh(path: Union[str, os.PathLike[str]], *,
              repair: bool = False) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...

class GeodesicSolver:
    def __init__(self, V: npt.ArrayLike, F: npt.ArrayLike, *, precision: _Precision = "double",
                 repair: bool = False, threads: int = 0) -> None: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def precision(self) -> _Precision: ...
    @property
    def repairs(self) -> List[str]: ...
    @overload
    def distances(self, sources: _Vertices, *, points: _Points = None, face_points: _FacePoints = None,
                  epsilon: _Real = 0.0, max_distance: _Real = ..., threads: int = 0,
                  return_labels: Literal[False] = False, return_bounds: Literal[False] = False,
                  prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                  prior_bounds: _PerVertex = None) -> _Distances: ...
    @overload
    def distances(self, sources: _Vertices, *, points: _Points = None, face_points: _FacePoints = None,
                  epsilon: _Real = 0.0, max_distance: _Real = ..., threads: int = 0,
                  return_labels: Literal[True], return_bounds: Literal[False] = False,
                  prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                  prior_bounds: _PerVertex = None) -> Tuple[_Distances, _Labels]: ...
    @overload
    def distances(self, sources: _Vertices, *, points: _Points = None, face_points: _FacePoints = None,
                  epsilon: _Real = 0.0, max_distance: _Real = ..., threads: int = 0,
                  return_labels: Literal[False] = False,
                  return_bounds: Literal[True],
                  prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                  prior_bounds: _PerVertex = None) -> Tuple[_Distances, _Distances]: ...
    @overload
    def distances(self, sources: _Vertices, *, points: _Points = None, face_points: _FacePoints = None,
                  epsilon: _Real = 0.0, max_distance: _Real = ..., threads: int = 0,
                  return_labels: Literal[True], return_bounds: Literal[True],
                  prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                  prior_bounds: _PerVertex = None) -> Tuple[_Distances, _Labels, _Distances]: ...
    @overload
    def distances(self, sources: _Vertices, *, points: _Points = None, face_points: _FacePoints = None,
                  epsilon: _Real = 0.0, max_distance: _Real = ..., threads: int = 0, return_labels: bool = False,
                  return_bounds: bool = False,
                  prior_distances: _PerVertex = None, prior_labels: _PerVertex = None,
                  prior_bounds: _PerVertex = None) -> Union[_Distances, Tuple[_Distances, _Labels],
                                                        Tuple[_Distances, _Distances],
                                                        Tuple[_Distances, _Labels, _Distances]]: ...
    @overload
    def distances_from_each(self, sources: _SourceVertices, *, epsilon: _Real = 0.0, max_distance: _Real = ...,
                            threads: int = 0, return_bounds: Literal[False] = False) -> _Distances: ...
    @overload
    def distances_from_each(self, sources: _SourceVertices, *, epsilon: _Real = 0.0, max_distance: _Real = ...,
                            threads: int = 0, return_bounds: Literal[True]) -> Tuple[_Distances, _Distances]: ...
    @overload
    def distances_from_each(self, sources: _SourceVertices, *, epsilon: _Real = 0.0, max_distance: _Real = ...,
                            threads: int = 0,
                            return_bounds: bool = False) -> Union[_Distances, Tuple[_Distances, _Distances]]: ...
    # the values, then bounds and paths, those asked for, in that order
    @overload
    def pair_distances(self, sources: _SourceVertices, targets: _SourceVertices, *, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_bounds: Literal[False] = False,
                       return_paths: Literal[False] = False) -> _Distances: ...
    @overload
    def pair_distances(self, sources: _SourceVertices, targets: _SourceVertices, *, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_bounds: Literal[True],
                       return_paths: Literal[False] = False) -> Tuple[_Distances, _Distances]: ...
    @overload
    def pair_distances(self, sources: _SourceVertices, targets: _SourceVertices, *, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_bounds: Literal[False] = False,
                       return_paths: Literal[True]) -> Tuple[_Distances, List[_Distances]]: ...
    @overload
    def pair_distances(self, sources: _SourceVertices, targets: _SourceVertices, *, epsilon: _Real = 0.0,
                       max_distance: _Real = ..., threads: int = 0, return_bounds: Literal[True],
                       return_paths: Literal[True]) -> Tuple[_Distances, _Distances, List[_Distances]]: ...
    # the samples, then distances, labels and bounds, those asked for, in that order
    @overload
    def farthest_point_sampling(self, k: int, *, first_sample: int = 0, epsilon: _Real = 0.0, threads: int = 0,
                                return_distances: Literal[False] = False, return_labels: Literal[False] = False,
                                return_bounds: Literal[False] = False) -> _Labels: ...
    @overload
    def farthest_point_sampling(self, k: int, *, first_sample: int = 0, epsilon: _Real = 0.0, threads: int = 0,
                                return_distances: Literal[True], return_labels: Literal[False] = False,
                                return_bounds: Literal[False] = False) -> Tuple[_Labels, _Distances]: ...
    @overload
    def farthest_point_sampling(self, k: int, *, first_sample: int = 0, epsilon: _Real = 0.0, threads: int = 0,
                                return_distances: Literal[False] = False, return_labels: Literal[True],
                                return_bounds: Literal[False] = False) -> Tuple[_Labels, _Labels]: ...
    @overload
    def farthest_point_sampling(self, k: int, *, first_sample: int = 0, epsilon: _Real = 0.0, threads: int = 0,
                                return_distances: Literal[True], return_labels: Literal[True],
                                return_bounds: Literal[False] = False) -> Tuple[_Labels, _Distances, _Labels]: ...
    @overload
    def farthest_point_sampling(self, k: int, *, first_sample: int = 0, epsilon: _Real = 0.0, threads: int = 0,
                                return_distances: Literal[True], return_labels: Literal[False] = False,
                                return_bounds: Literal[True]) -> Tuple[_Labels, _Distances, _Distances]: ...
    @overload
    def farthest_point_sampling(self, k: int, *, first_sample: int = 0, epsilon: _Real = 0.0, threads: int = 0,
                                return_distances: Literal[True], return_labels: Literal[True],
                                return_bounds: Literal[True]) -> Tuple[_Labels, _Distances, _Labels, _Distances]: ...
    @overload
    def farthest_point_sampling(self, k: int, *, first_sample: int = 0, epsilon: _Real = 0.0, threads: int = 0,
                                return_distances: bool = False, return_labels: bool = False,
                                return_bounds: bool = False) -> Union[_Labels, Tuple[npt.NDArray[Any], ...]]: ...
    def local_distance_matrix(self, max_distance: _Real, sources: _Vertices = None, *, epsilon: _Real = 0.0,
                              threads: int = 0, symmetric: bool = False,
                              format: str = 'csr') -> scipy.sparse.csr_matrix | scipy.sparse.csc_matrix: ...
    @overload
    def target_distances(self, sources: _Vertices, targets: _Vertices, *, points: _Points = None,
                         face_points: _FacePoints = None, target_points: _Points = None,
                         target_face_points: _FacePoints = None, epsilon: _Real = 0.0, max_distance: _Real = ...,
                         threads: int = 0, return_labels: Literal[False] = False) -> _Distances: ...
    @overload
    def target_distances(self, sources: _Vertices, targets: _Vertices, *, points: _Points = None,
                         face_points: _FacePoints = None, target_points: _Points = None,
                         target_face_points: _FacePoints = None, epsilon: _Real = 0.0, max_distance: _Real = ...,
                         threads: int = 0, return_labels: Literal[True]) -> Tuple[_Distances, _Labels]: ...
    @overload
    def target_distances(self, sources: _Vertices, targets: _Vertices, *, points: _Points = None,
                         face_points: _FacePoints = None, target_points: _Points = None,
                         target_face_points: _FacePoints = None, epsilon: _Real = 0.0, max_distance: _Real = ...,
                         threads: int = 0,
                         return_labels: bool) -> Union[_Distances, Tuple[_Distances, _Labels]]: ...
    def distances_and_paths(self, sources: _Vertices, targets: _Vertices, *, points: _Points = None,
                            face_points: _FacePoints = None, target_points: _Points = None,
                            target_face_points: _FacePoints = None, epsilon: _Real = 0.0,
                            max_distance: _Real = ..., threads: int = 0,
                            source_first: bool = True) -> Tuple[_Distances, List[_Distances]]: ...
    def geodesic_path(self, sources: _Vertices, target: _Vertices, *, points: _Points = None,
                      face_points: _FacePoints = None, target_point: _Points = None,
                      target_face_point: _FacePoints = None, epsilon: _Real = 0.0, max_distance: _Real = ...,
                      threads: int = 0, source_first: bool = True) -> _Distances: ...
    def distance_and_path(self, source: int, target: int, *, epsilon: _Real = 0.0, max_distance: _Real = ...,
                          threads: int = 0, source_first: bool = True) -> Tuple[float, _Distances]: ...
    # deprecated (one more release): geodesic_path(), distances_and_paths() and distance_and_path()
    # replace them; these keep the former order of their tuples and of their paths
    def shortest_path(self, sources: _Vertices = None, target: _Vertices = None, *, points: _Points = None,
                      face_points: _FacePoints = None, target_point: _Points = None,
                      target_face_point: _FacePoints = None, epsilon: _Real = 0.0, max_distance: _Real = ...,
                      threads: int = 0, source_first: bool = False) -> _Distances: ...
    def shortest_paths(self, sources: _Vertices = None, targets: _Vertices = None, *, points: _Points = None,
                       face_points: _FacePoints = None, target_points: _Points = None,
                       target_face_points: _FacePoints = None, epsilon: _Real = 0.0, max_distance: _Real = ...,
                       threads: int = 0, source_first: bool = False) -> Tuple[List[_Distances], _Distances]: ...
    def geodesic_distance(self, source: Any, target: Any, *, epsilon: _Real = 0.0, max_distance: _Real = ...,
                          threads: int = 0, source_first: bool = False) -> Tuple[float, _Distances]: ...
