// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Must NOT compile: an exact kernel without square roots (Epeck, FT = Lazy_exact_nt<Gmpq>) is
// refused with a static_assert that names the kernel to use instead, not with an error from inside
// CGAL::sqrt (test exact_kernel_needs_sqrt).

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

using Mesh = CGAL::Surface_mesh<CGAL::Epeck::Point_3>;

int main()
{
  const Mesh mesh;
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  std::vector<CGAL::Epeck::FT> distances(num_vertices(mesh));
  solver.compute_distances(Mesh::Vertex_index(0), CGAL::make_property_map(distances));
}
