// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The build rule of the certified geodesic graph (issue 54; manual, "A certified geodesic graph"):
// one direct-only propagation from every vertex gives its out-edges, and Dijkstra on them stays
// within [exact, (1 + epsilon) exact] from every source, at every vertex; a smaller epsilon keeps
// more edges.

#include "test_utilities.h"

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

using namespace dggvtp_test;

namespace {

using Sm = CGAL::Surface_mesh<Epick::Point_3>;
using Graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property,
                                                 boost::property<boost::edge_weight_t, double>>;

struct Built
{
  Graph graph;
  std::size_t edges = 0;
};

Built build_graph(const CGAL::DGG_VTP_3::Geodesic_distance_solver<Sm>& solver, double epsilon)
{
  const std::size_t n = solver.number_of_vertices();
  std::vector<std::uint32_t> all(n);
  for(std::size_t v = 0; v < n; ++v)
    all[v] = std::uint32_t(v);
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<double> weights;
  Built b;
  CGAL::DGG_VTP_3::internal::Core_of_solver::core(solver).template direct_runs<CGAL::Sequential_tag>(
    all, epsilon, [&](std::size_t k, const auto& reached, const auto& w, const auto&) {
      for(const auto v : reached)
        if(v != all[k] && w[v] < std::numeric_limits<double>::infinity())
        {
          edges.emplace_back(k, v);
          weights.push_back(w[v]);
        }
    });
  b.graph = Graph(boost::edges_are_unsorted_multi_pass, edges.begin(), edges.end(), weights.begin(), n);
  b.edges = edges.size();
  return b;
}

std::vector<double> graph_distances(const Graph& g, std::size_t source)
{
  std::vector<double> d(boost::num_vertices(g));
  boost::dijkstra_shortest_paths(
    g, boost::vertex(source, g),
    boost::distance_map(boost::make_iterator_property_map(d.begin(), boost::get(boost::vertex_index, g))));
  for(double& x : d)
    if(x == std::numeric_limits<double>::max())
      x = std::numeric_limits<double>::infinity();
  return d;
}

// every `step`-th source of `mesh`, against `exact(source)`, at `epsilons` in decreasing order
template <class Exact>
void check_rule(const Sm& mesh, const Exact& exact, const std::vector<double>& epsilons, std::size_t step,
                const std::string& name)
{
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Sm> solver(mesh);
  std::size_t edges_before = 0; // at the larger epsilon before
  for(double epsilon : epsilons)
  {
    const Built b = build_graph(solver, epsilon);
    BOOST_TEST(b.edges >= edges_before, name << ", epsilon " << epsilon << ": a smaller epsilon keeps no fewer edges");
    edges_before = b.edges;
    double worst = 0., lowest = 0.;
    std::size_t unreached = 0;
    for(std::size_t s = 0; s < num_vertices(mesh); s += step)
    {
      const std::vector<double> truth = exact(s), d = graph_distances(b.graph, s);
      for(std::size_t v = 0; v < d.size(); ++v)
      {
        if(!std::isfinite(d[v]))
        {
          ++unreached;
          continue;
        }
        if(truth[v] > 0.)
        {
          worst = (std::max)(worst, (d[v] - truth[v]) / truth[v]);
          lowest = (std::min)(lowest, (d[v] - truth[v]) / truth[v]);
        }
      }
    }
    BOOST_TEST_MESSAGE(name << ", epsilon " << epsilon << ": " << b.edges << " edges, largest error / epsilon "
                            << worst / epsilon);
    BOOST_TEST(unreached == 0u, name << ", epsilon " << epsilon);
    BOOST_TEST(worst <= epsilon, name << ", epsilon " << epsilon);
    BOOST_TEST(lowest >= -1e-12, name << ", epsilon " << epsilon);
  }
}

#ifdef DGG_VTP_3_TEST_FEWER_CONFIGURATIONS
constexpr std::size_t every = 5;
#else
constexpr std::size_t every = 1;
#endif

} // namespace

BOOST_AUTO_TEST_SUITE(geodesic_graph_rule)

// CAD: flat faces, sharp edges, thin triangles; against the exact mode
BOOST_AUTO_TEST_CASE(every_source_of_pinion)
{
  const Sm mesh = make_mesh<Sm>(read_soup("pinion.ply"));
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Sm> exact(mesh);
  check_rule(mesh, [&](std::size_t s) { return solver_distances(exact, mesh, s); }, {1., 1e-1, 1e-2, 1e-3}, every,
             "pinion");
}

// a flat cylinder with borders, where the windows of the source run far before they stop (the
// design note's model); against the analytic distances
BOOST_AUTO_TEST_CASE(every_source_of_a_prism)
{
  const Prism prism = prism_lateral_surface(7, 6, 9, 1.5, 54);
  const Sm mesh = make_mesh<Sm>(prism.soup);
  check_rule(mesh, [&](std::size_t s) { return prism.distances(s); }, {1e-1, 1e-2, 1e-4}, every, "prism");
}

BOOST_AUTO_TEST_SUITE_END()
