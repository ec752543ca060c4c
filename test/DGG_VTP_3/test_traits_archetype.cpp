// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The concept DGGVTPTraits_3 (doc/DGG_VTP_3/Concepts/DGGVTPTraits_3.h) as an archetype: a traits
// class with exactly the documented members, whose functors cannot be made any other way than
// through the traits object and whose point type offers nothing but what the functors read.
// If the solver needed more, this file would stop compiling.

#include "test_utilities.h"

#include <CGAL/Surface_mesh.h>

using namespace dggvtp_test;

namespace archetype {

// a point that is neither a CGAL point nor has a kernel (no nested R)
struct Point
{
  double coordinates[3] = {0., 0., 0.};
};

class Traits
{
  struct Key {};  // only the traits can make its functors

public:
  using FT = double;
  using Point_3 = archetype::Point;

  struct Compute_x_3
  {
    explicit Compute_x_3(Key) {}
    FT operator()(const Point_3& p) const { return p.coordinates[0]; }
  };
  struct Compute_y_3
  {
    explicit Compute_y_3(Key) {}
    FT operator()(const Point_3& p) const { return p.coordinates[1]; }
  };
  struct Compute_z_3
  {
    explicit Compute_z_3(Key) {}
    FT operator()(const Point_3& p) const { return p.coordinates[2]; }
  };

  Compute_x_3 compute_x_3_object() const { return Compute_x_3(Key()); }
  Compute_y_3 compute_y_3_object() const { return Compute_y_3(Key()); }
  Compute_z_3 compute_z_3_object() const { return Compute_z_3(Key()); }
};

// reads a kernel point of a mesh as an archetype point
template <class Mesh>
struct Point_map
{
  using key_type = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using value_type = Point;
  using reference = Point;
  using category = boost::readable_property_map_tag;
  const Mesh* mesh;
  friend Point get(const Point_map& m, key_type v)
  {
    const auto& p = get(CGAL::vertex_point, *m.mesh, v);
    return Point{{double(p.x()), double(p.y()), double(p.z())}};
  }
};

} // namespace archetype

BOOST_AUTO_TEST_SUITE(traits_concept)

// a Surface_mesh of archetype points, the archetype traits given as named parameter
BOOST_AUTO_TEST_CASE(archetype_surface_mesh_of_archetype_points)
{
  using Reference_mesh = Sm_d::Mesh;
  using Mesh = CGAL::Surface_mesh<archetype::Point>;
  const Soup soup = dggvtp_test::prism_lateral_surface(7, 3, 7, 2., 3).soup;
  const Reference_mesh reference = make_mesh<Reference_mesh>(soup);
  Mesh mesh;
  for(const auto& p : soup.points)
    mesh.add_vertex(archetype::Point{{p[0], p[1], p[2]}});
  for(const auto& f : soup.faces)
    BOOST_REQUIRE(mesh.add_face(Mesh::Vertex_index(std::uint32_t(f[0])), Mesh::Vertex_index(std::uint32_t(f[1])),
                                Mesh::Vertex_index(std::uint32_t(f[2]))) != Mesh::null_face());

  const std::vector<double> expected = geodesic_distances(reference, 10);

  auto map = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", 0.).first;
  const auto np = CGAL::parameters::geom_traits(archetype::Traits()).vertex_point_map(get(CGAL::vertex_point, mesh));
  CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, Mesh::Vertex_index(10), np);
  BOOST_TEST(to_vector(mesh, map) == expected, boost::test_tools::per_element());

  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh, archetype::Traits> solver(mesh, np);
  solver.compute_distances(Mesh::Vertex_index(10), map);
  BOOST_TEST(to_vector(mesh, map) == expected, boost::test_tools::per_element());

  // the traits as the only named parameter (internal point map)
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh, archetype::Traits> solver2(
    mesh, CGAL::parameters::geom_traits(archetype::Traits()));
  solver2.compute_distances(Mesh::Vertex_index(10), map);
  BOOST_TEST(to_vector(mesh, map) == expected, boost::test_tools::per_element());
}

// a kernel mesh read through a vertex point map whose value type is the archetype point
BOOST_AUTO_TEST_CASE(archetype_through_vertex_point_map)
{
  using Mesh = Ph_d::Mesh;
  const Mesh mesh = make_mesh<Mesh>(dggvtp_test::prism_lateral_surface(6, 2, 5, 1.5, 4).soup);
  const std::vector<double> expected = geodesic_distances(mesh, 7);
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  CGAL::DGG_VTP_3::compute_geodesic_distances(
    mesh, map, vertex_list(mesh)[7],
    CGAL::parameters::vertex_point_map(archetype::Point_map<Mesh>{&mesh}).geom_traits(archetype::Traits()));
  BOOST_TEST(to_vector(mesh, map) == expected, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()
