"""The spellings of the first release that a clearer API replaced, kept working for one more
release with a DeprecationWarning (CHANGELOG.md lists each and what replaces it):

- GeodesicSolver(V, F, "float"): precision is keyword-only, GeodesicSolver(V, F, precision="float");
- a query without its sources (distances(points=P)): sources is required, [] or None where only
  points give them (distances(None, points=P)); the same for targets;
- shortest_path(), shortest_paths(), geodesic_distance(): geodesic_path(), distances_and_paths()
  and distance_and_path(), whose paths run from the source to the target and whose tuples give the
  values first: (distances, paths), as (distance, path);
- farthest_point_sampling(k, first=N): first_sample=N, the name of C++ and of the programs.
"""
import functools
import math
import os
import sys
import warnings
import typing
from typing import Any, Callable, Tuple

_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def _stack_level() -> int:
    """the stack level of warnings.warn() called here that points at the caller's line: past the
    frames of this package's own code"""
    level, frame = 1, sys._getframe(1)
    while frame is not None and os.path.dirname(os.path.abspath(frame.f_code.co_filename)) == _PACKAGE:
        level += 1
        frame = frame.f_back  # type: ignore[assignment]
    return level


def warn(message: str) -> None:
    """a DeprecationWarning that points at the caller's line"""
    warnings.warn(message, DeprecationWarning, stacklevel=_stack_level())


def requires(method: Callable[..., Any], name: str, required: typing.Sequence[Tuple[str, typing.Sequence[str]]]) -> Callable[..., Any]:
    """`method` (self, required..., *, ...) for which the former spelling without a required
    argument still works where the keyword arguments that may stand in for it are given (each of
    `required`: its name and those), with a DeprecationWarning; without them, a TypeError says
    that it is missing, as Python says it"""
    @functools.wraps(method)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        for k, (argument, alternatives) in enumerate(required):
            if len(args) > 1 + k or argument in kwargs:
                continue
            if not any(kwargs.get(a) is not None for a in alternatives):
                raise TypeError(f"{name}() missing required argument: '{argument}' (or None with "
                                f"{' or '.join(alternatives)})")
            warn(f"{name}() without {argument} is deprecated: it is required, None (or []) where "
                 f"{' or '.join(alternatives)} give the places; write {name}({argument}=None, ...)")
            kwargs[argument] = None
        return method(*args, **kwargs)
    return wrapper


def keyword_precision(init: Callable[..., Any]) -> Callable[..., Any]:
    """GeodesicSolver.__init__ for which GeodesicSolver(V, F, precision) still works, with a
    DeprecationWarning"""
    @functools.wraps(init)
    def wrapper(self: Any, *args: Any, **kwargs: Any) -> Any:
        if len(args) == 3 and "precision" not in kwargs:
            warn("GeodesicSolver(V, F, precision): precision is keyword-only, write "
                 f"GeodesicSolver(V, F, precision={args[2]!r})")
            kwargs["precision"] = args[2]
            args = args[:2]
        return init(self, *args, **kwargs)
    return wrapper


def first_sample(method: Callable[..., Any]) -> Callable[..., Any]:
    """farthest_point_sampling for which first= still works, with a DeprecationWarning"""
    @functools.wraps(method)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        if "first" in kwargs:
            if "first_sample" in kwargs:
                raise TypeError("farthest_point_sampling(): give first_sample alone (first is its former name)")
            warn("farthest_point_sampling(first=...) is deprecated: write first_sample=..., as C++ and dggvtp "
                 "--first-sample name it")
            kwargs["first_sample"] = kwargs.pop("first")
        return method(*args, **kwargs)
    return wrapper


def shortest_path(self: Any, sources: Any = None, target: Any = None, *, points: Any = None, face_points: Any = None,
                  target_point: Any = None, target_face_point: Any = None, epsilon: float = 0.0,
                  max_distance: float = math.inf, threads: int = 0, source_first: bool = False) -> Any:
    """Deprecated: geodesic_path(sources, target, source_first=False) gives this path.

    The shortest path from the target back to its nearest source (source_first=True: from the
    source to the target), a float64 array (m, 3). geodesic_path() runs from the source to the
    target by default.
    """
    warn("GeodesicSolver.shortest_path() is deprecated: geodesic_path() gives the path from the source to the "
         "target (source_first=False: this function's order, from the target to the source)")
    return self.geodesic_path(sources, target, points=points, face_points=face_points, target_point=target_point,
                              target_face_point=target_face_point, epsilon=epsilon, max_distance=max_distance,
                              threads=threads, source_first=source_first)


def shortest_paths(self: Any, sources: Any = None, targets: Any = None, *, points: Any = None,
                   face_points: Any = None, target_points: Any = None, target_face_points: Any = None,
                   epsilon: float = 0.0, max_distance: float = math.inf, threads: int = 0,
                   source_first: bool = False) -> Tuple[Any, Any]:
    """Deprecated: distances_and_paths(sources, targets, source_first=False) gives these, as
    (lengths, paths).

    Returns (paths, lengths): the paths from each target back to its nearest source
    (source_first=True: from the source), and their lengths.
    """
    warn("GeodesicSolver.shortest_paths() is deprecated: distances_and_paths() returns (distances, paths), the "
         "paths from the source to the target (source_first=False: this function's order)")
    lengths, paths = self.distances_and_paths(sources, targets, points=points, face_points=face_points,
                                              target_points=target_points, target_face_points=target_face_points,
                                              epsilon=epsilon, max_distance=max_distance, threads=threads,
                                              source_first=source_first)
    return paths, lengths


def geodesic_distance(self: Any, source: Any, target: Any, *, epsilon: float = 0.0, max_distance: float = math.inf,
                      threads: int = 0, source_first: bool = False) -> Tuple[float, Any]:
    """Deprecated: distance_and_path(source, target, source_first=False) gives these.

    Returns (distance, path), the path from the target to the source (source_first=True: from the
    source), as pygeodesic's geodesicDistance(source, target).
    """
    warn("GeodesicSolver.geodesic_distance() is deprecated: distance_and_path() returns (distance, path), the path "
         "from the source to the target (source_first=False: this function's order, pygeodesic's)")
    return self.distance_and_path(source, target, epsilon=epsilon, max_distance=max_distance, threads=threads,
                                  source_first=source_first)


FORMER_METHODS = {"shortest_path": shortest_path, "shortest_paths": shortest_paths,
                  "geodesic_distance": geodesic_distance}
