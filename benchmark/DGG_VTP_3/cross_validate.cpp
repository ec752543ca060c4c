// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Cross-validation of the double computation against the same computation in CGAL::Gmpfr, or in
// CGAL's exact kernel with square roots (CORE::Expr, for meshes of a few dozen faces):
//
//   cross_validate MESH [--precision P | --exact-kernel] [--epsilon E] [--source N]...
//
// The mesh is loaded as dggvtp loads it (vertex i is the i-th vertex of the file) into a
// Surface_mesh over double and one over CGAL::Simple_cartesian<CGAL::Gmpfr>, the Gmpfr default
// precision being P bits (default 150), or over CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt;
// both run from the same sources (default vertex 0), exact (default) or DGG-VTP with accuracy E.
// Prints a Markdown table row: the mesh, its vertices, the mode, P ("exact" for the exact kernel),
// the largest relative difference |d_double - d_reference| / d_reference over the vertices (the
// difference computed in the reference's type), the vertex where it is, the vertices where one
// run reaches and the other does not, the time of each run, and the precision the Gmpfr distances
// came out with (CGAL's Gmpfr computes at the larger of its operands' precisions; the propagation
// makes its numbers at the default precision).

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace {

template <class Kernel>
struct Run
{
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  std::vector<typename Kernel::FT> distances; // per vertex of the file
  double seconds = 0.;

  Run(dggvtp::Loaded_soup soup, const std::vector<std::size_t>& sources, double epsilon)
  {
    Mesh mesh = dggvtp::make_triangle_mesh<Kernel>(soup);
    std::vector<typename Mesh::Vertex_index> source_vertices;
    for(std::size_t s : sources)
      source_vertices.push_back(typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(s)));
    auto map = mesh.template add_property_map<typename Mesh::Vertex_index, typename Kernel::FT>("v:d").first;
    const auto start = std::chrono::steady_clock::now();
    CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, source_vertices, CGAL::parameters::accuracy(epsilon));
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for(std::size_t i = 0; i < soup.file_vertices; ++i)
      distances.push_back(get(map, typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(i))));
  }
};

// The largest relative difference of `in_double` from `reference` and where it is, and the
// vertices that one of them reaches and the other does not
struct Comparison
{
  double worst = 0.;
  std::size_t worst_vertex = 0;
  std::size_t reach_differs = 0;
};

template <class FT>
Comparison compare(const std::vector<double>& in_double, const std::vector<FT>& reference)
{
  const FT unreached = CGAL::DGG_VTP_3::internal::Number_type_math<FT>::infinity();
  Comparison c;
  for(std::size_t i = 0; i < reference.size(); ++i)
  {
    const FT& exact = reference[i];
    const double d = in_double[i];
    if(exact == unreached || !std::isfinite(d))
    {
      c.reach_differs += (exact == unreached) != std::isinf(d);
      continue;
    }
    if(exact == FT(0)) // a source
      continue;
    const double relative = CGAL::to_double(CGAL::abs(FT(d) - exact) / exact);
    if(!(relative <= c.worst))
    {
      c.worst = relative;
      c.worst_vertex = i;
    }
  }
  return c;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: cross_validate MESH [--precision P | --exact-kernel] [--epsilon E] [--source N]...\n";
    return 1;
  }
  try
  {
    const std::string path = argv[1];
    long precision = 150;
    bool exact_kernel = false;
    double epsilon = 0.;
    std::vector<std::size_t> sources;
    for(int i = 2; i < argc; ++i)
    {
      const std::string option = argv[i];
      if(option == "--exact-kernel")
      {
        exact_kernel = true;
        continue;
      }
      if(i + 1 == argc)
        throw std::invalid_argument("option " + option + " needs a value");
      if(option == "--precision")
        precision = std::stol(argv[++i]);
      else if(option == "--epsilon")
        epsilon = std::stod(argv[++i]);
      else if(option == "--source")
        sources.push_back(std::stoul(argv[++i]));
      else
        throw std::invalid_argument("unknown option " + option);
    }
    if(sources.empty())
      sources.push_back(0);
    CGAL::Gmpfr::set_default_precision(precision);

    const dggvtp::Loaded_soup soup = dggvtp::load_soup(path);
    for(std::size_t s : sources)
      if(s >= soup.file_vertices)
        throw std::invalid_argument("source " + std::to_string(s) + " is not a vertex of the file");
    const Run<CGAL::Exact_predicates_inexact_constructions_kernel> in_double(soup, sources, epsilon);
    Comparison c;
    double reference_seconds = 0.;
    std::string bits = "exact", result_bits = "exact";
    if(exact_kernel)
    {
      const Run<CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt> in_exact(soup, sources, epsilon);
      c = compare(in_double.distances, in_exact.distances);
      reference_seconds = in_exact.seconds;
    }
    else
    {
      const Run<CGAL::Simple_cartesian<CGAL::Gmpfr>> in_mpfr(soup, sources, epsilon);
      c = compare(in_double.distances, in_mpfr.distances);
      reference_seconds = in_mpfr.seconds;
      bits = std::to_string(precision);
      result_bits = std::to_string(long(in_mpfr.distances[c.worst_vertex].get_precision()));
    }
    const std::string name = path.substr(path.find_last_of('/') + 1);
    char mode[32] = "exact";
    if(epsilon > 0.)
      std::snprintf(mode, sizeof mode, "DGG-VTP %g", epsilon);
    std::printf("| %s | %zu | %s | %s | %.3g | %zu | %zu | %.3f | %.3f | %s |\n", name.c_str(), soup.file_vertices,
                mode, bits.c_str(), c.worst, c.worst_vertex, c.reach_differs, in_double.seconds, reference_seconds,
                result_bits.c_str());
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
