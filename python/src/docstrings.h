// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The docstrings of the Python module dggvtp (help(dggvtp.GeodesicSolver) shows them).

#ifndef DGGVTP_PYTHON_DOCSTRINGS_H
#define DGGVTP_PYTHON_DOCSTRINGS_H

namespace doc {

const char* const module = R"(Geodesic distances on triangle meshes by window propagation (DGG-VTP for CGAL).

Exact distances (the VTP algorithm, epsilon = 0) or distances within a relative error epsilon of
the exact ones (DGG-VTP), from vertices or surface points to every vertex, to chosen targets, and
shortest paths. NumPy arrays in, NumPy arrays out; unreachable vertices get inf.

    V, F = dggvtp.read_mesh("mesh.ply")
    solver = dggvtp.GeodesicSolver(V, F)
    d = solver.distances(0)                       # exact, (n,) float64

Bad input raises ValueError (dggvtp.InputError, a subclass, for the input policy of the mesh
loader). Every computation releases the GIL: several Python threads may query one solver at once.
)";

const char* const input_error = R"(Input refused by the mesh loader's input policy (a ValueError).)";

const char* const read_mesh = R"(Reads a mesh file (OFF, OBJ, PLY, STL) with the dggvtp command-line program's readers: the same
fast readers, the same checks, the same vertex order.

Returns V, a float64 array (n, 3) of the file's vertices in the file's order, and F, an int64
array (m, 3) of its triangles, each with its corners in the file's order; faces with more than 3
vertices are triangulated (ear clipping, as dggvtp does). GeodesicSolver(V, F) then gives the
distances dggvtp gives for the file, bit for bit (for a file of triangles).

Raises ValueError (InputError) for an unreadable, empty or truncated file, a coordinate that is
not finite, a face with fewer than 3 or repeated vertices, an index out of range, or a polygon
that cannot be triangulated.
)";

const char* const solver = R"(GeodesicSolver(V, F, precision="double")

A triangle mesh prepared once for any number of geodesic distance queries.

V: (n, 3) vertex coordinates, any array-like of real numbers (converted to float64).
F: (m, 3) triangles, any array-like of integers: 0-based indices into V.
precision: "double" (default) or "float", the number type of the computation (as dggvtp
    --precision); results are float64 either way.

The mesh goes through dggvtp's input policy: inconsistent orientations are fixed and vertices
where several sheets meet are split (see `repairs`); results are still per vertex of V (the
nearest copy). Degenerate faces, slivers, too short edges and too sharp cone tips raise
ValueError with the library's message.

Queries are const and release the GIL: Python threads may call them on one solver at once.
Common keyword arguments of the queries:
  epsilon: 0 (default) for exact distances, or > 0 (finite) for DGG-VTP, every distance within a
      relative error epsilon of the exact one.
  max_distance: the propagation stops there; farther vertices get inf (default inf).
  threads: threads of one propagation (TBB), 0 = all cores, default 1 (sequential); the result
      is the same bit for bit for any number. TBB's limit is process-wide: concurrent calls
      share the smallest.
Sources: `sources` are vertex indices (an int or a sequence), `points` are 3D points (a (k, 3)
or (3,) array-like) taken at the nearest point of the surface (CGAL's locate_with_AABB_tree, as
dggvtp --source-point); both may be given. A point at a vertex's coordinates is that vertex.
)";

const char* const init = R"(Prepares the mesh (V, F) for queries; see the class's documentation.

Raises ValueError for arrays of the wrong shape or kind of numbers, an index out of range, a
face using a vertex twice, a coordinate that is not finite, or a mesh the input policy refuses.
)";

const char* const num_vertices = "Number of vertices of V (the length of a distance array).";
const char* const num_faces = "Number of triangles the solver uses (after the input policy's repairs).";
const char* const precision = "The number type of the computation: 'double' or 'float'.";
const char* const repairs = "What the input policy changed in the mesh (orientations, split vertices), one line each.";

const char* const distances = R"(Geodesic distance of every vertex to the nearest source.

sources: a vertex index or a sequence of them; points: (k, 3) surface points (see the class).
Returns a float64 array (num_vertices,), inf where unreachable (another component, a vertex no
face uses, beyond max_distance). With return_labels=True, returns (distances, labels): labels
int64 (num_vertices,), the index of each vertex's nearest source in the list of the sources
followed by the points, -1 where unreachable.

The same values as dggvtp --source ... --source-point ... --output, bit for bit.
Raises ValueError for an index out of range, no source, points that are not finite, a negative
or non-finite epsilon, a negative or NaN max_distance, threads < 0.
)";

const char* const distances_from_each = R"(One distance field per source vertex: a float64 array (len(sources), num_vertices) whose row k
is distances(sources[k]) (as dggvtp-batch's rows, bit for bit). With threads != 1 the rows are
shared among the threads, each row one sequential propagation.
)";

const char* const target_distances = R"(Distances of chosen targets to the nearest source; the propagation stops once they are final
(cheaper than a full field for near targets).

targets: vertex indices; target_points: (k, 3) surface points (exact distance at the point,
not an interpolation). Returns a float64 array: the targets' distances, then the points', inf
where unreachable. The same values as dggvtp --target / --target-point.
)";

const char* const shortest_path = R"(The shortest path on the surface from one target (a vertex `target`, or a surface point
`target_point`) back to its nearest source: a float64 array (m, 3) of points, from the target to
the source; empty (0, 3) if the target is unreachable. Its length is the target's distance. The
same points as dggvtp --path-to / --path-to-point --paths.
)";

} // namespace doc

#endif // DGGVTP_PYTHON_DOCSTRINGS_H
