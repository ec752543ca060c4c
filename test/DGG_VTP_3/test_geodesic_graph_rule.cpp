// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The build rule of the certified geodesic graph (issue 54; benchmark/DGG_VTP_3/README.md, Table 14):
// one direct-only propagation from every vertex gives its out-edges, and Dijkstra on them stays
// within [exact, (1 + epsilon) exact] from every source, at every vertex; a smaller epsilon keeps
// more edges.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/internal/Geodesic_graph_build.h>

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

// the graph from the build runs on the prepared `soup` (internal: no class of the package has them)
Built build_graph(const Soup& soup, double epsilon)
{
  namespace I = CGAL::DGG_VTP_3::internal;
  I::Unfolded_mesh<double> mesh;
  const I::Unfolding_order order = I::unfold_triangle_soup<CGAL::Sequential_tag>(
    epick_points(soup), soup.faces, CGAL::Identity_property_map<Epick::Point_3>(), Epick(), mesh);
  const I::Patch_partition<double> partition(mesh, CGAL::Sequential_tag());
  const std::size_t n = mesh.number_of_vertices();
  std::vector<std::uint32_t> all(n);
  for(std::size_t v = 0; v < n; ++v)
    all[v] = std::uint32_t(v);
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<double> weights;
  Built b;
  I::geodesic_graph_build_runs<CGAL::Sequential_tag>(
    mesh, partition, all, epsilon, [&](std::size_t k, const auto& reached, const auto& w, const auto&) {
      for(const auto v : reached) // in the soup's numbering
        if(v != all[k] && w[v] < std::numeric_limits<double>::infinity())
        {
          edges.emplace_back(order.vertices[k], order.vertices[v]);
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

// every `step`-th source of `soup`, against `exact(source)`, at `epsilons` in decreasing order
template <class Exact>
void check_rule(const Soup& soup, const Exact& exact, const std::vector<double>& epsilons, std::size_t step,
                const std::string& name)
{
  std::size_t edges_before = 0; // at the larger epsilon before
  for(double epsilon : epsilons)
  {
    const Built b = build_graph(soup, epsilon);
    BOOST_TEST(b.edges >= edges_before, name << ", epsilon " << epsilon << ": a smaller epsilon keeps no fewer edges");
    edges_before = b.edges;
    double worst = 0., lowest = 0.;
    std::size_t unreached = 0;
    for(std::size_t s = 0; s < soup.points.size(); s += step)
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
  const Soup soup = read_soup("pinion.ply");
  const Sm mesh = make_mesh<Sm>(soup);
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Sm> exact(mesh);
  check_rule(soup, [&](std::size_t s) { return solver_distances(exact, mesh, s); }, {1., 1e-1, 1e-2, 1e-3}, every,
             "pinion");
}

// a flat cylinder with borders, where the windows of the source run far before they stop (the
// design note's model); against the analytic distances
BOOST_AUTO_TEST_CASE(every_source_of_a_prism)
{
  const Prism prism = prism_lateral_surface(7, 6, 9, 1.5, 54);
  check_rule(prism.soup, [&](std::size_t s) { return prism.distances(s); }, {1e-1, 1e-2, 1e-4}, every, "prism");
}

BOOST_AUTO_TEST_SUITE_END()
