// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Re-running a double computation in more precision: the same mesh in a Surface_mesh over double
// and one over CGAL::Gmpfr (MPFR, 150 bits), the same source, and the largest relative difference
// between the two results. A double result is trustworthy where the difference is a few units of
// double's rounding (about 1e-15). The type of the points is all that changes.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using Point_double = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Point_mpfr = CGAL::Simple_cartesian<CGAL::Gmpfr>::Point_3;

// exact distances from the first vertex, in the number type of `Point`, as doubles (the vertices
// in the soup's order: polygon_soup_to_polygon_mesh keeps it)
template <class Point>
std::vector<double> distances_from_first_vertex(const std::vector<Point_double>& points,
                                                const std::vector<std::vector<std::size_t>>& faces, double& seconds)
{
  using Mesh = CGAL::Surface_mesh<Point>;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  std::vector<Point> converted;
  for(const Point_double& p : points)
    converted.emplace_back(FT(p.x()), FT(p.y()), FT(p.z()));
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(converted, faces, mesh);
  auto distance = mesh.template add_property_map<typename Mesh::Vertex_index, FT>("v:distance").first;
  const auto start = std::chrono::steady_clock::now();
  CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, distance, *vertices(mesh).begin());
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<double> result;
  for(auto v : vertices(mesh))
    result.push_back(CGAL::to_double(distance[v]));
  return result;
}

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : DGG_VTP_3_DATA_DIR "/spot.ply";
  std::vector<Point_double> points;
  std::vector<std::vector<std::size_t>> faces;
  if(!CGAL::IO::read_polygon_soup(filename, points, faces) || points.empty())
  {
    std::cerr << "Invalid input: cannot read " << filename << std::endl;
    return EXIT_FAILURE;
  }

  CGAL::Gmpfr::set_default_precision(150);
  double seconds_double = 0., seconds_mpfr = 0.;
  const std::vector<double> in_double = distances_from_first_vertex<Point_double>(points, faces, seconds_double);
  const std::vector<double> in_mpfr = distances_from_first_vertex<Point_mpfr>(points, faces, seconds_mpfr);

  double largest = 0.;
  std::size_t where = 0;
  for(std::size_t i = 1; i < in_double.size(); ++i)
  {
    const double difference = std::abs(in_double[i] - in_mpfr[i]) / in_mpfr[i];
    if(difference > largest)
    {
      largest = difference;
      where = i;
    }
  }
  std::cout << in_double.size() << " vertices; double " << seconds_double << " s, Gmpfr (150 bits) " << seconds_mpfr
            << " s; largest relative difference " << largest << " at vertex " << where << std::endl;
  // more than a few hundred units of double's rounding would mean a double result not to trust
  return largest < 1e-13 ? EXIT_SUCCESS : EXIT_FAILURE;
}
