// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// compute_isolines(): every point where the interpolated field equals the value, every crossed
// edge in exactly one piece, consecutive points in one face, pieces closed or ending on the border;
// circles on a flat patch at the right radius.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/isolines.h>

#include <algorithm>
#include <iomanip>
#include <map>

using namespace dggvtp_test;

namespace {

using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Piece = CGAL::DGG_VTP_3::Isoline_piece<Mesh, Epick::Point_3>;
using halfedge_descriptor = boost::graph_traits<Mesh>::halfedge_descriptor;

struct Field_check
{
  std::size_t closed = 0, open = 0;
};

bool share_a_face(halfedge_descriptor a, halfedge_descriptor b, const Mesh& mesh)
{
  for(auto fa : {face(a, mesh), face(opposite(a, mesh), mesh)})
    for(auto fb : {face(b, mesh), face(opposite(b, mesh), mesh)})
      if(fa != Mesh::null_face() && fa == fb)
        return true;
  return false;
}

// whether a face of the edge of `h` has a corner of infinite distance (where pieces may end)
bool next_to_infinity(halfedge_descriptor h, const Mesh& mesh, const Mesh::Property_map<Mesh::Vertex_index, double>& d)
{
  for(auto g : {h, opposite(h, mesh)})
    if(!is_border(g, mesh))
      for(auto v : vertices_around_face(g, mesh))
        if(std::isinf(d[v]))
          return true;
  return false;
}

// the checks that hold for any mesh and field
Field_check check_isolines(const Mesh& mesh, const Mesh::Property_map<Mesh::Vertex_index, double>& d,
                           const std::vector<double>& values, const std::vector<Piece>& pieces)
{
  Field_check result;
  std::map<std::pair<std::size_t, std::size_t>, int> seen; // (value, edge) -> times in the output
  for(const Piece& piece : pieces)
  {
    BOOST_REQUIRE(piece.value_index < values.size());
    BOOST_REQUIRE_EQUAL(piece.points.size(), piece.halfedges.size());
    BOOST_TEST(piece.points.size() >= 2u);
    const double value = values[piece.value_index];
    for(std::size_t i = 0; i < piece.points.size(); ++i)
    {
      const halfedge_descriptor h = piece.halfedges[i];
      const double a = d[source(h, mesh)], b = d[target(h, mesh)];
      BOOST_TEST_REQUIRE((a < value && value <= b));
      const auto& p = mesh.point(source(h, mesh));
      const auto& q = mesh.point(target(h, mesh));
      const auto edge_vector = q - p;
      const double t = CGAL::to_double((piece.points[i] - p) * edge_vector / edge_vector.squared_length());
      BOOST_TEST((t > 0. && t <= 1. + 1e-12));
      // on the segment, not only at the right fraction of it
      const double off = std::sqrt(CGAL::squared_distance(piece.points[i], p + t * edge_vector));
      BOOST_TEST(off <= 1e-12 * std::sqrt(edge_vector.squared_length()));
      const double interpolated = a + t * (b - a);
      BOOST_TEST(std::abs(interpolated - value) <= 1e-12 * value,
                 "point " << i << " at " << std::setprecision(17) << interpolated << ", value " << value);
      ++seen[{piece.value_index, std::size_t(edge(h, mesh))}];
      if(i > 0)
        BOOST_TEST(share_a_face(piece.halfedges[i - 1], h, mesh));
    }
    if(piece.closed)
    {
      ++result.closed;
      BOOST_TEST(share_a_face(piece.halfedges.front(), piece.halfedges.back(), mesh));
    }
    else
    {
      ++result.open;
      for(auto end : {piece.halfedges.front(), piece.halfedges.back()})
        BOOST_TEST((is_border_edge(end, mesh) || next_to_infinity(end, mesh, d)));
    }
  }
  // every crossed edge once
  for(std::size_t k = 0; k < values.size(); ++k)
    for(auto e : edges(mesh))
    {
      const auto h = halfedge(e, mesh);
      const double a = d[source(h, mesh)], b = d[target(h, mesh)];
      const bool crossed = std::isfinite(a) && std::isfinite(b) && (a < values[k]) != (b < values[k]);
      const auto it = seen.find({k, std::size_t(e)});
      const int times = it == seen.end() ? 0 : it->second;
      // a crossing whose faces both have an infinite corner may be a piece of one point: dropped
      BOOST_TEST((times == (crossed ? 1 : 0) || (crossed && times == 0 && next_to_infinity(h, mesh, d))));
    }
  return result;
}

// the checks on the isolines of the geodesic distances from vertex 0 of a mesh file, at `count`
// values evenly spaced strictly inside (0, farthest)
Field_check check_isolines_of_file(const std::string& name, std::size_t count)
{
  Mesh mesh = make_mesh<Mesh>(read_soup(name));
  auto d = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", 0.).first;
  CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, d, *vertices(mesh).begin());
  double farthest = 0.;
  for(auto v : vertices(mesh))
    farthest = (std::max)(farthest, d[v]);
  std::vector<double> values;
  for(std::size_t k = 1; k <= count; ++k)
    values.push_back(farthest * double(k) / double(count + 1));
  std::vector<Piece> pieces;
  CGAL::DGG_VTP_3::compute_isolines(mesh, d, values, std::back_inserter(pieces));
  const Field_check check = check_isolines(mesh, d, values, pieces);
  BOOST_TEST(check.closed + check.open >= values.size());
  return check;
}

} // namespace

BOOST_AUTO_TEST_SUITE(isolines)

BOOST_AUTO_TEST_CASE(bunny_closed_pieces)
{
  const Field_check check = check_isolines_of_file("bunny.ply", 10);
  BOOST_TEST(check.open == 0u);
  BOOST_TEST(check.closed >= 10u);
}

BOOST_AUTO_TEST_CASE(lion_head_open_pieces_end_on_the_border)
{
  BOOST_TEST(check_isolines_of_file("lion_head.ply", 12).open >= 1u);
}

// Vertices exactly at the value count as above it: the curve passes through them, and no point
// is NaN. The field is the grid's column number, so whole columns of vertices sit on the values.
BOOST_AUTO_TEST_CASE(vertices_at_the_value)
{
  const Soup soup = flat_patch(6, 6, 1., 1., 0., 20260301, Rigid_motion({0., 0., 1.}, 0., {0., 0., 0.}));
  Mesh mesh = make_mesh<Mesh>(soup);
  auto d = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", 0.).first;
  for(auto v : vertices(mesh))
    d[v] = mesh.point(v).x();
  const std::vector<double> values = {1., 2.5, 6.};
  std::vector<Piece> pieces;
  CGAL::DGG_VTP_3::compute_isolines(mesh, d, values, std::back_inserter(pieces));
  check_isolines(mesh, d, values, pieces);
  std::size_t at_one = 0;
  for(const Piece& piece : pieces)
    for(const auto& p : piece.points)
    {
      BOOST_TEST(std::isfinite(p.x()));
      if(piece.value_index == 0)
      {
        BOOST_TEST(p.x() == 1.); // the vertex itself, bit for bit
        ++at_one;
      }
    }
  BOOST_TEST(at_one >= 7u);
}

// An unreachable vertex: no edge to it is crossed, so the curve breaks around it into open pieces,
// without NaN; a value beyond every finite distance gives nothing; a NaN value is refused.
BOOST_AUTO_TEST_CASE(infinite_distances)
{
  const Soup soup = flat_patch(6, 6, 1., 1., 0., 20260302, Rigid_motion({0., 0., 1.}, 0., {0., 0., 0.}));
  Mesh mesh = make_mesh<Mesh>(soup);
  auto d = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", 0.).first;
  for(auto v : vertices(mesh))
    d[v] = mesh.point(v) == Epick::Point_3(3., 3., 0.) ? std::numeric_limits<double>::infinity() : mesh.point(v).x();
  const std::vector<double> values = {2.5, 10.};
  std::vector<Piece> pieces;
  CGAL::DGG_VTP_3::compute_isolines(mesh, d, values, std::back_inserter(pieces));
  const Field_check check = check_isolines(mesh, d, values, pieces);
  BOOST_TEST(check.open >= 2u);
  BOOST_TEST(check.closed == 0u);
  for(const Piece& piece : pieces)
  {
    BOOST_TEST(piece.value_index == 0u);
    for(const auto& p : piece.points)
      BOOST_TEST(p.x() == 2.5);
  }
  BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_isolines(mesh, d, std::vector<double>{std::nan("")},
                                                      std::back_inserter(pieces)),
                    std::invalid_argument);
}

// Circles around the centre of a flat square, with the exact (Euclidean) distance as the field:
// the linear interpolation of a convex function is above it, so every point is at most at the
// radius, and short of it by at most h^2 / (8 (r - h)) for edges of length <= h.
BOOST_AUTO_TEST_CASE(circles_on_a_flat_patch)
{
  const Soup soup = flat_patch(20, 20, 0.05, 0.05, 0.15, 20260303, Rigid_motion({0., 0., 1.}, 0., {0., 0., 0.}));
  Mesh mesh = make_mesh<Mesh>(soup);
  const std::size_t centre = 10 * 21 + 10;
  const auto exact = euclidean_distances(mesh, centre);
  auto d = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", 0.).first;
  std::size_t i = 0;
  for(auto v : vertices(mesh))
    d[v] = exact[i++];
  double h = 0.;
  for(auto e : edges(mesh))
    h = (std::max)(h, std::sqrt(CGAL::to_double(CGAL::squared_distance(mesh.point(source(e, mesh)),
                                                                        mesh.point(target(e, mesh))))));
  const Epick::Point_3 c = mesh.point(Mesh::Vertex_index(Mesh::size_type(centre)));
  const std::vector<double> values = {0.15, 0.3, 0.45, 0.6};
  std::vector<Piece> pieces;
  CGAL::DGG_VTP_3::compute_isolines(mesh, d, values, std::back_inserter(pieces));
  const Field_check check = check_isolines(mesh, d, values, pieces);
  std::vector<std::size_t> closed(values.size(), 0), open(values.size(), 0);
  for(const Piece& piece : pieces)
  {
    const double r = values[piece.value_index];
    ++(piece.closed ? closed : open)[piece.value_index];
    for(const auto& p : piece.points)
    {
      const double at = std::sqrt(CGAL::squared_distance(p, c));
      BOOST_TEST(at <= r * (1. + 1e-12));
      BOOST_TEST(r - at <= h * h / (8. * (r - h)), "point at " << at << ", radius " << r);
    }
  }
  // inside the square: one closed circle each; r = 0.6 leaves it: four open arcs
  BOOST_TEST(closed == (std::vector<std::size_t>{1, 1, 1, 0}), boost::test_tools::per_element());
  BOOST_TEST(open == (std::vector<std::size_t>{0, 0, 0, 4}), boost::test_tools::per_element());
  BOOST_TEST(check.closed == 3u);
}

BOOST_AUTO_TEST_SUITE_END()
