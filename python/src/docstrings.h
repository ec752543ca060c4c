// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The docstrings of the Python module dggvtp (help(dggvtp.GeodesicSolver) shows them, after the
// signature pybind11 writes from the arguments' types).

#ifndef DGGVTP_PYTHON_DOCSTRINGS_H
#define DGGVTP_PYTHON_DOCSTRINGS_H

namespace doc {

const char* const module = R"(Geodesic distances on triangle meshes by window propagation (DGG-VTP for CGAL).

Exact distances (the VTP algorithm, epsilon = 0) or distances within a relative error epsilon of
the exact ones (DGG-VTP), from vertices or surface points to every vertex, to chosen targets,
shortest paths, and sparse matrices of the distances within a radius. NumPy arrays in, NumPy
arrays out; unreachable vertices get inf.

    V, F = dggvtp.read_mesh("mesh.ply")
    solver = dggvtp.GeodesicSolver(V, F)
    d = solver.distances(0)                       # exact, (n,) float64
    d = dggvtp.geodesic_distances(V, F, 0)        # the same, in one call

Bad input raises ValueError (dggvtp.InputError, a subclass, for the input policy of the mesh
loader); what the dggvtp program reports as a warning (repairs, unreachable vertices, points far
from the surface) is a RuntimeWarning. Every computation releases the GIL: several Python threads
may query one solver at once. Ctrl-C (SIGINT) stops a call within a fraction of a second with
KeyboardInterrupt, the solver ready for the next call. A solver pickles (for multiprocessing)
and copies: it is rebuilt from V, F and its options.

Threads: every call runs on all cores by default (threads=0); the result is the same bit for bit
on any number of threads. In a pool of processes (multiprocessing, concurrent.futures, joblib),
where each worker already takes a core, pass threads=1 to each call (and to GeodesicSolver), or
the workers' threads oversubscribe the cores.
)";

const char* const input_error = R"(Input refused by the mesh loader's input policy (a ValueError).)";

const char* const read_mesh = R"(Reads a mesh file (OFF, OBJ, PLY, STL) with the dggvtp command-line program's readers: the same
fast readers, the same checks, the same vertex order.

Returns V, a float64 array (n, 3) of the file's vertices in the file's order, and F, an int64
array (m, 3) of its triangles, each with its corners in the file's order; faces with more than 3
vertices are triangulated (ear clipping, as dggvtp does; a RuntimeWarning says so).
GeodesicSolver(V, F) then gives the distances dggvtp gives for the file, bit for bit (for a file
of triangles).

repair: False (default) refuses a face that repeats a vertex. True drops such faces and makes
the repairs of dggvtp --repair (CGAL's stitch_borders, remove_degenerate_faces,
remove_almost_degenerate_faces, remove_isolated_vertices), one RuntimeWarning per kind of repair:
V keeps every vertex of the file, in its order (at its repaired place), and F holds the repaired
triangles; a vertex the repairs removed or merged with another is in no face of F (distances:
inf). For the per-vertex results of dggvtp --repair (such vertices nan, or the distance of the
vertex they were merged with), give the file's arrays to GeodesicSolver(V, F, repair=True).

Raises ValueError (InputError) for an unreadable, empty or truncated file, a coordinate that is
not finite, a face with fewer than 3 vertices, an index out of range, or a polygon that cannot be
triangulated.
)";

const char* const solver = R"(GeodesicSolver(V, F, *, precision="double", repair=False, threads=0)

A triangle mesh prepared once for any number of geodesic distance queries.

V: (n, 3) vertex coordinates, any array-like of real numbers (converted to float64); (n, 2) for
    a mesh of the plane z = 0.
F: (m, 3) triangles, any array-like of integers: 0-based indices into V.
precision: "double" (default) or "float", the number type of the computation (as dggvtp
    --precision); results are float64 either way.
repair: the repairs of dggvtp --repair (see read_mesh), the results still per vertex of V: a
    vertex the repairs removed gets nan (label -1), one merged with another at its place gets
    that one's distance; a source or target there is that one, or a ValueError if removed. Faces
    that repeat a vertex are dropped.

The mesh goes through dggvtp's input policy: inconsistent orientations are fixed (`repairs`
says so; no warning: orientation changes no distance) and vertices where several sheets meet are
split (a RuntimeWarning and `repairs` say so), the copies still one point (paths cross from each sheet into the others there); results are still per vertex of V
(the nearest copy). A face on the same three vertices as another is dropped first (a
RuntimeWarning). Degenerate faces, slivers, too short edges and too sharp cone
tips raise ValueError with the library's message.

Queries are const and release the GIL: Python threads may call them on one solver at once.
Common keyword arguments of the queries:
  epsilon: 0 (default) for exact distances, or in (0, 1] for DGG-VTP, every distance within a
      relative error epsilon of the exact one.
  max_distance: the propagation stops there; farther vertices get inf (default inf).
  threads: threads of one propagation (TBB), 0 = all cores (the default), 1 = sequential; the
      result is the same bit for bit for any number. In a pool of worker processes, pass
      threads=1. TBB's limit is process-wide: concurrent calls with threads > 1 share the
      smallest.
Sources (and targets likewise): `sources` are vertex indices (an int or a sequence; required,
[] or None where only points or face points are the sources), `points`
are 3D points (a (k, 3) or (3,) array-like) taken at the nearest point of the surface (CGAL's
locate_with_AABB_tree, as dggvtp --source-point; one farther than 1e-6 times the bounding box's
diagonal gives a RuntimeWarning), `face_points` are points on faces of F as a pair (faces,
barycentric): face indices (k,) and the barycentric coordinates (k, 3) of their corners in F's
order, each at least 0 and adding up to 1 (within 1e-12): the same result as the 3D point they
make, without locating it. Any of them may be given together. A point at a vertex's coordinates,
or at a corner of a face, is that vertex.
Unreachable vertices, targets or paths (without max_distance) give a RuntimeWarning, as dggvtp
prints a warning for them.
)";

const char* const init = R"(Prepares the mesh (V, F) for queries; see the class's documentation.

precision (keyword only): 'double' (default) or 'float'.
threads: threads of the preparation (TBB), 0 = all cores (the default), 1 = sequential; the
prepared solver, and so every result, is the same bit for bit for any number.

Raises ValueError for arrays of the wrong shape or kind of numbers, an index out of range, a
face using a vertex twice (without repair), a coordinate that is not finite, or a mesh the input
policy refuses.
)";

const char* const num_vertices = "Number of vertices of V (the length of a distance array).";
const char* const num_faces = "Number of triangles the solver uses (after the input policy's repairs).";
const char* const precision = "The number type of the computation: 'double' or 'float'.";
const char* const repairs = "What the input policy and repair=True changed in the mesh, one line each.";

const char* const distances = R"(Geodesic distance of every vertex to the nearest source.

sources, points, face_points: the sources (see the class). Returns a float64 array
(num_vertices,), inf where unreachable (another component, a vertex no face uses, beyond
max_distance). With return_labels=True, returns (distances, labels): labels int64
(num_vertices,), the index of each vertex's nearest source in the list of the sources followed
by the points and the face points, -1 where unreachable.

With return_bounds=True, the certified error of each distance comes last ((distances, bounds),
or (distances, labels, bounds)): a float64 array (num_vertices,) such that the exact distance
lies in [distances - bounds, distances]; at most epsilon x distances, 0 where the distance is
certified exact (the sources, every vertex in the exact mode), inf where unreachable. The
distance less the least key that reached the vertex (see the manual, "Certified error"); the
values of dggvtp --error-bounds.

prior_distances (with prior_labels and prior_bounds): adds the sources to the field of earlier
ones, per vertex as distances() of this solver returned it (at this epsilon or a smaller one):
the result is the field of all the sources, within the contract, and the propagation goes only
where the new sources are nearer (the C++ prior_distance_map; farthest-point sampling uses it).
prior_labels (needed for return_labels=True) are that field's labels; the new sources' labels
follow the largest of them (max(prior_labels) + 1 + the index in the list of the new sources).
prior_bounds are its certified errors (return_bounds=True); without them its lower bounds are
prior_distances / (1 + epsilon). Not with max_distance.

>>> d1, l1 = solver.distances([0, 17], return_labels=True)
>>> d, labels = solver.distances(99, prior_distances=d1, prior_labels=l1, return_labels=True)

The same values as dggvtp --source ... --source-point ... --output, bit for bit.
Raises ValueError for an index out of range, no source, points that are not finite, barycentric
coordinates that are negative or do not add up to 1, an epsilon outside [0, 1], a negative or NaN
max_distance, threads < 0, a prior field of the wrong shape or with a negative or NaN distance.
)";

const char* const distances_from_each = R"(One distance field per source vertex: a float64 array (len(sources), num_vertices) whose row k
is distances(sources[k]) (as dggvtp-batch's rows, bit for bit). sources: vertex indices (None is
refused: it would be num_vertices rows of num_vertices numbers; pass range(solver.num_vertices)
to mean it). With threads != 1 (0, the default: all cores) the rows are
shared among the threads, each row one sequential propagation. It holds len(sources) x
num_vertices numbers: for the distances within a radius from many sources, see
local_distance_matrix(). With return_bounds=True, returns (rows, bounds): bounds[k] is the
certified error of row k, as distances(sources[k], return_bounds=True) gives it.
)";

const char* const farthest_point_sampling = R"(Farthest-point sampling: k vertices, first_sample (default 0; C++'s first_sample, dggvtp's
--first-sample) then each time the vertex farthest from those before it (ties to the lowest
index). Returns the samples, int64 (k,); with return_distances, return_labels and return_bounds,
a tuple of the samples then what was asked, in that order (samples, distances, labels, bounds):
distances float64 (num_vertices,), each vertex's distance to the nearest sample; labels int64
(num_vertices,), the index in samples of that sample; bounds float64 (num_vertices,), the
certified error of each distance, as distances(return_bounds=True) gives it.

In the exact mode (epsilon=0) the samples are the greedy sequence; with epsilon > 0 each
sample's exact distance to those before it is at least the largest one divided by 1 + epsilon,
and the distances and labels keep the contract. Each sample is added to the field of those
before, so that it costs its Voronoi cell, not a whole field: 1000 samples cost a few whole
fields, not 1000. Vertices no sample reaches (another component) are at inf, the farthest: the
next sample is the first of them. threads: the rounds of each propagation (as distances());
the same samples for any number. Ctrl-C stops it (KeyboardInterrupt).
Raises ValueError for k outside [1, num_vertices], first_sample out of range, an epsilon outside
[0, 1], threads < 0.

>>> samples, d, labels = solver.farthest_point_sampling(100, return_distances=True, return_labels=True)
>>> samples, d, b = solver.farthest_point_sampling(10, epsilon=1e-2, return_distances=True, return_bounds=True)
)";

const char* const pair_distances = R"(The geodesic distance of each pair (sources[k], targets[k]): two arrays of vertex indices of
the same length; returns float64 (len(sources),). Each pair is one propagation from its source
that searches toward its target (ordered by distance plus a lower bound of what is left to go,
see the manual, "Searching toward a target") and stops once the target's distance is final: a
fraction of a field for most pairs. The pairs run in parallel on `threads` (0: all cores), the
same bits for any number. Each value keeps the contract: within [exact, (1 + epsilon) x exact],
exact in the exact mode (epsilon=0); inf where max_distance or the mesh leaves the target
unreached.

With return_bounds=True, the certified error of each value follows it (float64 (len(sources),),
the exact distance lies in [values - bounds, values], as distances(return_bounds=True) gives
them); with return_paths=True, a list of one float64 (m, 3) polyline per pair, from the source to
the target, whose length is the value (empty where unreached). Both: (values, bounds, paths).

>>> d = solver.pair_distances([0, 0, 7], [100, 2500, 31], epsilon=1e-3)
>>> d, errors, paths = solver.pair_distances([0], [2500], return_bounds=True, return_paths=True)
)";

const char* const local_distance_matrix = R"(The distances within max_distance from each source vertex, as a scipy.sparse.csr_matrix of
shape (len(sources), num_vertices) (default sources=None: every vertex, in order, a square
matrix): row k holds every vertex whose computed distance from sources[k] is <= max_distance,
with that distance, and no other; as an array, with inf where there is no entry, it is
distances(sources[k], max_distance=max_distance, epsilon=epsilon), bit for bit (and the rows of
dggvtp-batch --max-distance). With epsilon > 0 the computed distance may exceed the exact one:
every vertex within max_distance / (1 + epsilon) of the exact distance is there, and some within
max_distance may not be (to have all of them: max_distance (1 + epsilon), then keep the entries
whose certified lower bound d - b is <= max_distance, d and b from distances(...,
return_bounds=True)). The source itself is an explicit 0 (eliminate_zeros() would drop
it). The memory is in proportion to the entries (about 12 bytes each), never num_vertices
squared; indices are int32 unless there are more than 2^31 entries.

The rows are shared among `threads` threads (0, the default: all cores), each one sequential propagation,
with the GIL released. A row costs what it reaches, not the size of the mesh: the solver keeps
its working arrays from query to query and each row pops vertices only up to (1 + epsilon) x
max_distance (about 0.1 ms a row of 100 neighbours, on 10,242 as on 163,842 vertices).

symmetric=True (only with sources=None): each entry the smaller of (i, j) and (j, i), an entry
present in one direction only (the other beyond max_distance) as it is; within the contract at
every epsilon, and what gdist's users test for. format='csc' gives a scipy.sparse.csc_matrix
(gdist's format), 'csr' (the default) a csr_matrix. Both build the transpose: about 3 (symmetric)
and 2 (csc) copies of the matrix at the peak, 1.4 for csr. With repair=True, a vertex the repairs removed has an empty row and no
entry. Raises ValueError for a max_distance that is negative, NaN or inf, a format other than
'csr' and 'csc', symmetric=True with sources.
)";

const char* const target_distances = R"(Distances of chosen targets to the nearest source; the propagation stops once they are final
(cheaper than a full field for near targets). solver.target_distances(0, [5, 9]): from vertex 0
to vertices 5 and 9.

targets: vertex indices; target_points: (k, 3) surface points; target_face_points: (faces,
barycentric) points on faces of F (exact distance at the point, not an interpolation). Returns a
float64 array: the targets' distances, then the points', then the face points', inf where
unreachable. The same values as dggvtp --target / --target-point. With return_labels=True,
returns (distances, labels): labels int64, each target's nearest source (its index in the list of
the sources followed by the points and the face points), -1 where unreachable.
)";

const char* const distances_and_paths = R"(The distances of several targets (targets: vertices, target_points: 3D points,
target_face_points: (faces, barycentric)) to their nearest sources and the shortest paths on the
surface between them, from one propagation that stops once they are final. Returns (distances,
paths): a float64 array of the distances (inf where unreachable), the summed lengths of the
segments of the paths, which are the targets' distances to rounding (a few 1e-16 relative), and
a list of float64 arrays (m, 3) of points, in the order targets, target_points,
target_face_points (an unreachable target's path is empty, (0, 3)).

The points run from the source to the target, as potpourri3d's find_geodesic_path(v_start, v_end)
(v_start the source); with source_first=False from the target to the source, as pygeodesic's
paths and dggvtp --paths. The same points as dggvtp --path-to / --path-to-point --paths.

>>> distances, paths = solver.distances_and_paths(0, [5, 9])
)";

const char* const geodesic_path = R"(The shortest path on the surface between the nearest source and one target (a vertex `target`, a
surface point `target_point`, or a point on a face `target_face_point` = (face, barycentric)): a
float64 array (m, 3) of points, from the source to the target (source_first=False: from the target
to the source); empty (0, 3) if the target is unreachable. solver.geodesic_path(14, 22): from
vertex 14 to vertex 22. Its length is the target's distance to rounding. distances_and_paths()
traces several from one propagation.

>>> path = solver.geodesic_path(14, 22)
)";

const char* const distance_and_path = R"(The geodesic distance between two vertices and the shortest path between them: returns
(distance, path), distance a float (inf if the target is unreachable) and path a float64 array
(m, 3) of points from the source to the target ((0, 3) if unreachable; source_first=False: from
the target to the source, the order of pygeodesic's geodesicDistance(source, target)). The
distance is the path's length (the target's distance to rounding, a few 1e-16 relative). One
propagation, which stops once the target's distance is final.

>>> distance, path = solver.distance_and_path(0, 1234)
)";

} // namespace doc

#endif // DGGVTP_PYTHON_DOCSTRINGS_H
