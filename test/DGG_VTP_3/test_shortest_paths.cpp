// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Shortest paths traced back from the Shortest_path_tree: straight on flat patches and on the
// unfolded prism, bending at a saddle, as long as the distance reported, every point on the face
// or edge it names, against Surface_mesh_shortest_path's path lengths; DGG-VTP's within epsilon.

#include "test_utilities.h"

#include <CGAL/Surface_mesh_shortest_path.h>

#include <cmath>
#include <iterator>
#include <limits>

using namespace dggvtp_test;
namespace DP = CGAL::DGG_VTP_3::parameters;

namespace {

template <class Mesh>
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
template <class Mesh>
using Tree = CGAL::DGG_VTP_3::Shortest_path_tree<Solver<Mesh>>;
template <class Mesh>
using Path = std::vector<typename Tree<Mesh>::Path_point>;
template <class Mesh>
using Location = typename Solver<Mesh>::Face_location;
using P3 = std::array<double, 3>;

template <class Mesh>
P3 position(const Mesh& mesh, const Location<Mesh>& l)
{
  P3 p{0., 0., 0.};
  const auto h = halfedge(l.first, mesh);
  const typename boost::graph_traits<Mesh>::vertex_descriptor c[3] = {source(h, mesh), target(h, mesh),
                                                                        target(next(h, mesh), mesh)};
  for(int k = 0; k < 3; ++k)
  {
    const auto& q = get(CGAL::vertex_point, mesh, c[k]);
    p[0] += double(l.second[k]) * double(q.x());
    p[1] += double(l.second[k]) * double(q.y());
    p[2] += double(l.second[k]) * double(q.z());
  }
  return p;
}

double distance(const P3& a, const P3& b)
{
  return std::sqrt(std::pow(a[0] - b[0], 2) + std::pow(a[1] - b[1], 2) + std::pow(a[2] - b[2], 2));
}

template <class Mesh>
double path_length(const Mesh& mesh, const Path<Mesh>& path)
{
  double length = 0.;
  for(std::size_t i = 1; i < path.size(); ++i)
    length += distance(position(mesh, path[i - 1].location), position(mesh, path[i].location));
  return length;
}

// Every point names its simplex right (zero coordinates) and lies on the face named by the next
// point (the face crossed between them); vertex points are their vertices.
template <class Mesh>
void check_structure(const Mesh& mesh, const Path<Mesh>& path, const std::string& what, double tolerance = 1e-9)
{
  using Point = typename Tree<Mesh>::Path_point;
  for(std::size_t i = 0; i < path.size(); ++i)
  {
    const Point& p = path[i];
    int zeros = 0;
    double sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      zeros += double(p.location.second[k]) == 0.;
      sum += double(p.location.second[k]);
      BOOST_TEST(double(p.location.second[k]) >= -tolerance, what << ", point " << i);
    }
    BOOST_TEST(std::abs(sum - 1.) <= tolerance, what << ", point " << i);
    const int expected = p.simplex == Point::VERTEX ? 2 : p.simplex == Point::EDGE ? 1 : 0;
    BOOST_TEST(zeros == expected, what << ", point " << i << ": " << zeros << " zero coordinates");
    if(p.simplex == Point::VERTEX)
    {
      const auto& q = get(CGAL::vertex_point, mesh, p.vertex);
      BOOST_TEST(distance(position(mesh, p.location), {double(q.x()), double(q.y()), double(q.z())}) <= tolerance,
                 what << ", point " << i);
    }
    if(i > 0)
    {
      // the previous point lies on the face this one names
      const auto f = p.location.first;
      const P3 x = position(mesh, path[i - 1].location);
      const auto h = halfedge(f, mesh);
      const typename boost::graph_traits<Mesh>::vertex_descriptor c[3] = {source(h, mesh), target(h, mesh),
                                                                            target(next(h, mesh), mesh)};
      P3 corner[3];
      for(int k = 0; k < 3; ++k)
      {
        const auto& q = get(CGAL::vertex_point, mesh, c[k]);
        corner[k] = {double(q.x()), double(q.y()), double(q.z())};
      }
      // distance from x to the triangle's plane and inside test through areas
      const auto sub = [](const P3& a, const P3& b) { return P3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
      const auto crossp = [](const P3& a, const P3& b) {
        return P3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      };
      const auto dotp = [](const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
      const P3 n = crossp(sub(corner[1], corner[0]), sub(corner[2], corner[0]));
      const double area2 = std::sqrt(dotp(n, n));
      double inside = 0.;
      for(int k = 0; k < 3; ++k)
        inside += std::sqrt(dotp(crossp(sub(corner[(k + 1) % 3], corner[k]), sub(x, corner[k])),
                                 crossp(sub(corner[(k + 1) % 3], corner[k]), sub(x, corner[k]))));
      BOOST_TEST(std::abs(inside - area2) <= tolerance * area2, what << ", point " << i - 1 << " is not on the face of point " << i);
    }
  }
}

// float meshes: their locations are rounded to float
template <class FT>
double structure_tolerance() { return std::is_same<FT, float>::value ? 1e-5 : 1e-9; }

template <class Mesh>
Path<Mesh> path_to(const Tree<Mesh>& tree, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  Path<Mesh> path;
  tree.shortest_path(v, std::back_inserter(path));
  return path;
}

template <class Mesh>
Path<Mesh> path_to_target(const Tree<Mesh>& tree, std::size_t k)
{
  Path<Mesh> path;
  tree.shortest_path_to_target(k, std::back_inserter(path));
  return path;
}

// the largest distance of the path's points from the segment [a, b]
template <class Mesh>
double off_segment(const Mesh& mesh, const Path<Mesh>& path, const P3& a, const P3& b)
{
  double worst = 0.;
  const P3 ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  for(const auto& p : path)
  {
    const P3 x = position(mesh, p.location);
    double t = ((x[0] - a[0]) * ab[0] + (x[1] - a[1]) * ab[1] + (x[2] - a[2]) * ab[2]) / len2;
    t = (std::max)(0., (std::min)(1., t));
    worst = (std::max)(worst, distance(x, {a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]}));
  }
  return worst;
}

// how far from the segment [s, t] a path from s to t of length at most (1 + accuracy) |st| may go
double ellipse_half_width(double st, double accuracy)
{
  return 0.5 * st * std::sqrt((1. + accuracy) * (1. + accuracy) - 1.);
}

} // namespace

BOOST_AUTO_TEST_SUITE(shortest_paths)

// On a flat patch a shortest path is the straight segment, from a vertex or a point to a vertex
// or a point, as long as the distance reported; with accuracy epsilon, a path at most (1 + epsilon)
// times as long, which stays inside the ellipse of foci its ends: within |st| sqrt((1 + epsilon)^2
// - 1) / 2 of the segment.
BOOST_AUTO_TEST_CASE_TEMPLATE(flat_patch_straight, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(flat_patch(12, 9, 1., 1.1, 0.15, 8, Rigid_motion({0.2, 0.4, -0.9}, 0.5, {0., 1., 2.})));
  const Solver<Mesh> solver(mesh);
  const auto vs = vertex_list(mesh);
  const std::vector<typename boost::graph_traits<Mesh>::face_descriptor> fs(faces(mesh).begin(), faces(mesh).end());
  using FT = typename Distance_map<Mesh>::FT;
  const Location<Mesh> from(fs[17], {FT(0.2), FT(0.3), FT(0.5)});
  const std::vector<Location<Mesh>> targets = {Location<Mesh>(fs[190], {FT(0.6), FT(0.1), FT(0.3)})};
  const double tolerance = std::is_same<FT, float>::value ? 1e-5 : 1e-12;
  for(double accuracy : {0., 1e-5})
  {
    const Tree<Mesh> tree = solver.compute_shortest_path_tree(std::vector<Location<Mesh>>{from},
                                                              DP::targets(targets).accuracy(accuracy));
    const P3 s = position(mesh, from);
    for(std::size_t i : {std::size_t(0), std::size_t(57), vs.size() - 1})
    {
      const Path<Mesh> path = path_to<Mesh>(tree, vs[i]);
      const std::string what = config_name<Config>() + ", vertex " + std::to_string(i) + ", accuracy " + std::to_string(accuracy);
      BOOST_REQUIRE(path.size() >= 2);
      check_structure(mesh, path, what, structure_tolerance<FT>());
      const auto& q = get(CGAL::vertex_point, mesh, vs[i]);
      const P3 t{double(q.x()), double(q.y()), double(q.z())};
      BOOST_TEST(off_segment(mesh, path, s, t) <= tolerance * 20. + ellipse_half_width(distance(s, t), accuracy), what);
      BOOST_TEST(path_length(mesh, path) == double(tree.distance(vs[i])), boost::test_tools::tolerance(tolerance));
      BOOST_TEST(double(tree.distance(vs[i])) == distance(s, t), boost::test_tools::tolerance(tolerance + accuracy));
    }
    const Path<Mesh> path = path_to_target<Mesh>(tree, 0);
    BOOST_REQUIRE(path.size() >= 2);
    check_structure(mesh, path, config_name<Config>() + ", target point", structure_tolerance<FT>());
    BOOST_TEST(off_segment(mesh, path, s, position(mesh, targets[0])) <=
               tolerance * 20. + ellipse_half_width(distance(s, position(mesh, targets[0])), accuracy));
    BOOST_TEST(path_length(mesh, path) == double(tree.target_distance(0)), boost::test_tools::tolerance(tolerance));
  }
}

// on the prism, the path is straight in the unfolding and wraps the shorter way around
BOOST_AUTO_TEST_CASE_TEMPLATE(prism_unfolded_straight, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using FT = typename Distance_map<Mesh>::FT;
  const Prism prism = prism_lateral_surface(5, 3, 6, 2., 99);
  const Mesh mesh = make_mesh<Mesh>(prism.soup);
  const Solver<Mesh> solver(mesh);
  const auto vs = vertex_list(mesh);
  const std::size_t from = 2;
  const Tree<Mesh> tree = solver.compute_shortest_path_tree(std::vector<Vertex<Mesh>>{vs[from]});
  const std::vector<double> truth = prism.distances(from);
  const double tolerance = std::is_same<FT, float>::value ? 1e-5 : 1e-12;
  std::size_t wrapped = 0;
  for(std::size_t i = 0; i < vs.size(); i += 3)
  {
    if(i == from)
      continue;
    const Path<Mesh> path = path_to<Mesh>(tree, vs[i]);
    check_structure(mesh, path, config_name<Config>() + ", vertex " + std::to_string(i), structure_tolerance<FT>());
    BOOST_TEST(path_length(mesh, path) == truth[i], boost::test_tools::tolerance(tolerance));
    // straight: as long as the straight line in the unfolding, and it passes no vertex but border
    // vertices (between two points of one border, it runs along the border)
    for(std::size_t k = 1; k + 1 < path.size(); ++k)
      if(path[k].simplex == Tree<Mesh>::Path_point::VERTEX)
        BOOST_TEST(bool(CGAL::is_border(path[k].vertex, mesh)), "vertex " << i << ": bends at point " << k);
    wrapped += std::abs(prism.arc[i] - prism.arc[from]) > prism.perimeter / 2;
  }
  BOOST_TEST(wrapped > 0u); // some paths cross the seam the short way
}

// Eight triangles around a vertex whose angles add up to more than 2 pi (a saddle): between two
// points on opposite sides, the shortest path bends exactly there.
BOOST_AUTO_TEST_CASE_TEMPLATE(bends_at_the_saddle, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using FT = typename Distance_map<Mesh>::FT;
  Soup soup;
  soup.points.push_back({0., 0., 0.});
  const double pi = 3.14159265358979323846;
  for(int k = 0; k < 8; ++k)
  {
    const double a = 2 * pi * k / 8, h = (k % 2 == 0 ? 0.5 : -0.5);
    soup.points.push_back({std::sqrt(1. - h * h) * std::cos(a), std::sqrt(1. - h * h) * std::sin(a), h});
  }
  for(std::size_t k = 0; k < 8; ++k)
    soup.faces.push_back({0, 1 + k, 1 + (k + 1) % 8});
  const Mesh mesh = make_mesh<Mesh>(soup);
  const Solver<Mesh> solver(mesh);
  const std::vector<typename boost::graph_traits<Mesh>::face_descriptor> fs(faces(mesh).begin(), faces(mesh).end());
  const auto vs = vertex_list(mesh);
  const Location<Mesh> s(fs[0], {FT(0.3), FT(0.35), FT(0.35)});
  const std::vector<Location<Mesh>> targets = {Location<Mesh>(fs[4], {FT(0.3), FT(0.35), FT(0.35)})};
  const double tolerance = std::is_same<FT, float>::value ? 1e-5 : 1e-12;
  for(double accuracy : {0., 1e-5})
  {
    const Tree<Mesh> tree = solver.compute_shortest_path_tree(std::vector<Location<Mesh>>{s}, DP::targets(targets).accuracy(accuracy));
    const Path<Mesh> path = path_to_target<Mesh>(tree, 0);
    check_structure(mesh, path, config_name<Config>() + ", across the saddle", structure_tolerance<FT>());
    std::size_t at_centre = 0;
    for(const auto& p : path)
      at_centre += p.simplex == Tree<Mesh>::Path_point::VERTEX && p.vertex == vs[0];
    BOOST_TEST(at_centre == 1u);
    const P3 centre{0., 0., 0.};
    const double expected = distance(position(mesh, s), centre) + distance(centre, position(mesh, targets[0]));
    BOOST_TEST(double(tree.target_distance(0)) == expected, boost::test_tools::tolerance(tolerance + accuracy));
    BOOST_TEST(path_length(mesh, path) == double(tree.target_distance(0)), boost::test_tools::tolerance(tolerance));
  }
}

// Against Surface_mesh_shortest_path: our paths are as long as our distances, which are SMSP's;
// exact paths bend only at saddle or border vertices; DGG-VTP's paths are within epsilon of the
// exact distances, from 5 sources to 100 targets each.
BOOST_AUTO_TEST_CASE(against_smsp_and_dgg_within_epsilon)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Epick, Mesh>;
  for(const char* name : {"spot.ply", "lion_head.ply"})
  {
    const Mesh mesh = make_mesh<Mesh>(read_soup(name));
    const Solver<Mesh> solver(mesh);
    const auto vs = vertex_list(mesh);
    for(std::size_t k = 0; k < 5; ++k)
    {
      const auto from = vs[(k * 7919) % vs.size()];
      CGAL::Surface_mesh_shortest_path<Traits> smsp(mesh);
      smsp.add_source_point(from);
      smsp.build_sequence_tree();
      const Tree<Mesh> exact = solver.compute_shortest_path_tree(std::vector<Mesh::Vertex_index>{from});
      const Tree<Mesh> dgg = solver.compute_shortest_path_tree(std::vector<Mesh::Vertex_index>{from},
                                                              CGAL::parameters::accuracy(1e-5));
      std::size_t bad_bends = 0;
      for(std::size_t t = 0; t < 100; ++t)
      {
        const auto v = vs[(t * 104729 + k * 31) % vs.size()];
        if(v == from)
          continue;
        const std::string what = std::string(name) + ", source " + std::to_string(k) + ", target " + std::to_string(t);
        std::vector<Epick::Point_3> reference;
        smsp.shortest_path_points_to_source_points(v, std::back_inserter(reference));
        double reference_length = 0.;
        for(std::size_t i = 1; i < reference.size(); ++i)
          reference_length += std::sqrt(CGAL::squared_distance(reference[i - 1], reference[i]));
        const Path<Mesh> path = path_to<Mesh>(exact, vs[std::size_t(v)]);
        check_structure(mesh, path, what);
        const double length = path_length(mesh, path);
        BOOST_TEST(length == double(exact.distance(v)), boost::test_tools::tolerance(1e-12));
        BOOST_TEST(length == reference_length, boost::test_tools::tolerance(1e-12));
        for(std::size_t i = 1; i + 1 < path.size(); ++i)
          if(path[i].simplex == Tree<Mesh>::Path_point::VERTEX)
          {
            double angle = 0.;
            for(auto h : CGAL::halfedges_around_target(path[i].vertex, mesh))
              if(!CGAL::is_border(h, mesh))
              {
                const auto a = get(CGAL::vertex_point, mesh, source(h, mesh)) - get(CGAL::vertex_point, mesh, target(h, mesh));
                const auto b = get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh)) -
                               get(CGAL::vertex_point, mesh, target(h, mesh));
                angle += std::acos(a * b / std::sqrt(a.squared_length() * b.squared_length()));
              }
            bad_bends += !(angle > 2 * 3.14159265358979323846 * (1. - 1e-6) || CGAL::is_border(path[i].vertex, mesh));
          }
        const Path<Mesh> approximate = path_to<Mesh>(dgg, v);
        check_structure(mesh, approximate, what + " (DGG-VTP)");
        const double approximate_length = path_length(mesh, approximate);
        BOOST_TEST(approximate_length == double(dgg.distance(v)), boost::test_tools::tolerance(1e-12));
        BOOST_TEST(approximate_length <= reference_length * (1. + 1e-5 + 1e-12), what);
        BOOST_TEST(approximate_length >= reference_length * (1. - 1e-12), what);
      }
      BOOST_TEST(bad_bends == 0u, name << ": exact paths bend at " << bad_bends << " vertices that are not saddles");
    }
  }
}

// targets numbered in the query's order whether they are points or vertices (a location at a
// corner is that vertex), as compute_distances() numbers its target distances; the statistics are
// those of that query
BOOST_AUTO_TEST_CASE(targets_mixing_vertices_and_points)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const Solver<Mesh> solver(mesh);
  const std::vector<Mesh::Face_index> fs(faces(mesh).begin(), faces(mesh).end());
  const std::vector<Location<Mesh>> sources = {Location<Mesh>(fs[5], {0.2, 0.3, 0.5})};
  const std::vector<Location<Mesh>> targets = {Location<Mesh>(fs[300], {0.6, 0.1, 0.3}),
                                               Location<Mesh>(fs[700], {0., 1., 0.}),
                                               Location<Mesh>(fs[900], {0.25, 0.25, 0.5})};
  const Tree<Mesh> tree = solver.compute_shortest_path_tree(sources, DP::targets(targets));
  auto d = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  std::vector<double> expected;
  const CGAL::DGG_VTP_3::Propagation_statistics statistics = solver.compute_distances_to_nearest_source(
    sources, d, DP::target_distances(std::back_inserter(expected), DP::targets(targets)));
  BOOST_TEST(tree.statistics().windows_created == statistics.windows_created);
  BOOST_TEST(tree.statistics().vertices_reached == statistics.vertices_reached);
  const Mesh::Vertex_index corner = target(halfedge(fs[700], mesh), mesh);
  BOOST_TEST(tree.target_distance(1) == tree.distance(corner));
  for(std::size_t k = 0; k < targets.size(); ++k)
  {
    BOOST_TEST(tree.target_distance(k) == expected[k]);
    const Path<Mesh> path = path_to_target<Mesh>(tree, k);
    BOOST_REQUIRE(path.size() >= 2);
    BOOST_TEST(path_length(mesh, path) == expected[k], boost::test_tools::tolerance(1e-12));
  }
  BOOST_TEST(path_to_target<Mesh>(tree, 1).size() == path_to<Mesh>(tree, corner).size());
  BOOST_CHECK_THROW(tree.target_distance(3), std::invalid_argument);
}

// nearest sources, distances and bad queries
BOOST_AUTO_TEST_CASE(tree_queries)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const Solver<Mesh> solver(mesh);
  const auto vs = vertex_list(mesh);
  const std::vector<Mesh::Vertex_index> sources = {vs[3], vs[400]};
  const Tree<Mesh> tree = solver.compute_shortest_path_tree(sources);
  auto d = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  auto labels = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  solver.compute_distances_to_nearest_source(sources, d, DP::nearest_source_map(labels));
  for(auto v : vs)
  {
    BOOST_TEST(tree.distance(v) == get(d, v));
    BOOST_TEST(tree.nearest_source(v) == get(labels, v));
  }
  BOOST_TEST(tree.nearest_source(vs[3]) == 0u);
  BOOST_TEST(tree.nearest_source(vs[400]) == 1u);
  BOOST_CHECK_THROW(tree.target_distance(0), std::invalid_argument);
  BOOST_CHECK_THROW(tree.distance(Mesh::null_vertex()), std::invalid_argument);
  // the path of a source is the source alone
  const Path<Mesh> at_source = path_to<Mesh>(tree, vs[3]);
  BOOST_TEST(at_source.size() == 1u);
}

BOOST_AUTO_TEST_SUITE_END()
