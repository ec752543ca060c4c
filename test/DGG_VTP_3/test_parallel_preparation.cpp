// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The preparation with the named parameter concurrency_tag: on 1, 2, 4 and 8 threads (more threads
// than cores is the point: the blocks are shared out differently) the prepared mesh and the patch
// partition are those of Sequential_tag bit for bit, and so is every distance; an error names the
// element the sequential preparation names. Nothing here measures time.

#include "test_utilities.h"
#include "without_tbb.h"

#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/unfold_input.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using namespace dggvtp_test;

namespace {

namespace DP = CGAL::DGG_VTP_3::parameters;
using Mesh_data = CGAL::DGG_VTP_3::internal::Unfolded_mesh<double>;
using Partition = CGAL::DGG_VTP_3::internal::Patch_partition<double>;
using Soup_solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Epick>;

template <class T>
bool same_bits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

// The meshes of the checks: bunny (75k faces: several blocks of the faces' radix sort), a border
// (lion_head), and a jittered grid of 80k faces with a second grid pinched to one of its corners
// (a vertex of two fans).
std::vector<std::pair<std::string, Soup>> test_soups()
{
  std::vector<std::pair<std::string, Soup>> soups;
  soups.emplace_back("bunny.ply", read_soup("bunny.ply"));
  soups.emplace_back("lion_head.ply", read_soup("lion_head.ply"));
  Soup grid = flat_patch(200, 200, 1., 1., 0.1, 37, Rigid_motion({1., 2., 3.}, 0.3, {0., 0., 0.}));
  const Soup wing = flat_patch(20, 20, 1., 1., 0.1, 38, Rigid_motion({3., 1., 2.}, 1.1, {-20., 0., 0.}));
  const std::size_t offset = grid.points.size() - 1; // wing's vertex 0 is grid's vertex 0
  grid.points.insert(grid.points.end(), wing.points.begin() + 1, wing.points.end());
  for(std::vector<std::size_t> face : wing.faces)
  {
    for(std::size_t& v : face)
      v = v == 0 ? 0 : v + offset;
    grid.faces.push_back(face);
  }
  soups.emplace_back("pinched grids", grid);
  return soups;
}

// runs `f(threads)` on 1, 2, 4 and 8 threads (without TBB, Parallel_if_available_tag is
// Sequential_tag: the case refuses to compare it with itself)
template <class F>
void on_each_thread_count(const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  for(int threads : {1, 2, 4, 8})
    on_threads(threads, [&] { f(threads); });
#else
  (void)f;
  DGG_VTP_3_REFUSE_WITHOUT_TBB("the preparation with Parallel_if_available_tag against Sequential_tag");
#endif
}

template <class ConcurrencyTag>
std::pair<Mesh_data, Partition> prepared(const Soup& soup)
{
  Mesh_data mesh;
  CGAL::DGG_VTP_3::internal::unfold_triangle_soup<ConcurrencyTag>(
    epick_points(soup), soup.faces, CGAL::Identity_property_map<Epick::Point_3>(), Epick(), mesh);
  Partition partition(mesh, ConcurrencyTag());
  return {std::move(mesh), std::move(partition)};
}

// every number the queries read from the prepared mesh and its partition
std::size_t differences(const std::pair<Mesh_data, Partition>& a, const std::pair<Mesh_data, Partition>& b)
{
  const Mesh_data& m = a.first;
  const Mesh_data& n = b.first;
  if(m.number_of_vertices() != n.number_of_vertices() || m.number_of_faces() != n.number_of_faces() ||
     m.number_of_non_manifold_vertices() != n.number_of_non_manifold_vertices() || a.second.size() != b.second.size() ||
     !same_bits(a.second.band(), b.second.band()))
    return 1;
  std::size_t count = 0;
  for(Mesh_data::Index h = 0; h < m.number_of_halfedges(); ++h)
    count += !(m.source(h) == n.source(h) && m.opposite(h) == n.opposite(h) && same_bits(m.length(h), n.length(h)) &&
               same_bits(m.apex(h).x, n.apex(h).x) && same_bits(m.apex(h).y, n.apex(h).y) &&
               m.corner_rank(h) == n.corner_rank(h));
  for(Mesh_data::Index v = 0; v < m.number_of_vertices(); ++v)
  {
    count += !(m.is_singular(v) == n.is_singular(v) && m.is_exact_pseudo_source(v) == n.is_exact_pseudo_source(v) &&
               a.second.owner(v) == b.second.owner(v) &&
               std::equal(m.corners_begin(v), m.corners_end(v), n.corners_begin(v), n.corners_end(v)));
  }
  for(Mesh_data::Index p = 0; p < a.second.size(); ++p)
    count += !std::equal(a.second.border_begin(p), a.second.border_end(p), b.second.border_begin(p), b.second.border_end(p));
  return count;
}

// the fields from one source, exact and 1e-2, of a soup solver or (with `mesh`) a mesh solver
template <class Solver>
std::vector<std::vector<double>> fields(const Solver& solver, const Sm_d::Mesh* mesh = nullptr)
{
  using Mesh = Sm_d::Mesh;
  const std::size_t n = solver.number_of_vertices();
  std::vector<std::vector<double>> result;
  for(double accuracy : {0., 1e-2})
    for(std::size_t s : {2 * n / 3})
    {
      std::vector<double> field(n);
      if constexpr(std::is_same<Solver, Soup_solver>::value)
        solver.compute_distances(s, CGAL::make_property_map(field), DP::accuracy(accuracy));
      else
      {
        auto d = get(CGAL::dynamic_vertex_property_t<double>(), *mesh);
        solver.compute_distances(Mesh::Vertex_index(Mesh::size_type(s)), d, DP::accuracy(accuracy));
        for(std::size_t i = 0; i < n; ++i)
          field[i] = get(d, Mesh::Vertex_index(Mesh::size_type(i)));
      }
      result.push_back(field);
    }
  return result;
}

std::size_t differences(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b)
{
  std::size_t count = 0;
  for(std::size_t k = 0; k < a.size(); ++k)
    for(std::size_t i = 0; i < a[k].size(); ++i)
      count += !same_bits(a[k][i], b[k][i]);
  return count;
}

} // namespace

BOOST_AUTO_TEST_SUITE(parallel_preparation)

BOOST_AUTO_TEST_CASE(prepared_mesh_is_the_same_for_any_thread_count)
{
  for(const auto& [name, soup] : test_soups())
  {
    const auto sequential = prepared<CGAL::Sequential_tag>(soup);
    BOOST_TEST(sequential.first.number_of_non_manifold_vertices() == (name == "pinched grids" ? 1u : 0u), name);
    on_each_thread_count([&, &name = name, &soup = soup](int threads) {
      BOOST_TEST(differences(prepared<CGAL::Parallel_if_available_tag>(soup), sequential) == 0u,
                 name << ", " << threads << " threads");
    });
  }
}

// the solvers' named parameter: every distance of both solvers, exact and DGG-VTP, bit for bit
// (the pinched grids are no Surface_mesh: the soup solver only)
BOOST_AUTO_TEST_CASE(distances_are_the_same_for_any_thread_count)
{
  using Mesh = Sm_d::Mesh;
  using Mesh_solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
  const auto tag = DP::concurrency_tag(CGAL::Parallel_if_available_tag());
  for(const auto& [name, soup] : test_soups())
  {
    const std::vector<Epick::Point_3> points = epick_points(soup);
    const std::vector<std::vector<double>> reference = fields(Soup_solver(points, soup.faces));
    on_each_thread_count([&, &name = name, &soup = soup](int threads) {
      BOOST_TEST(differences(fields(Soup_solver(points, soup.faces, tag)), reference) == 0u,
                 name << ", soup solver, " << threads << " threads");
    });
    if(name == "pinched grids")
      continue;
    // its own reference: a face's first halfedge need not be the soup's first corner, and the
    // frames of another corner round otherwise
    const Mesh mesh = make_mesh<Mesh>(soup);
    const std::vector<std::vector<double>> mesh_reference = fields(Mesh_solver(mesh), &mesh);
    on_each_thread_count([&, &name = name](int threads) {
      BOOST_TEST(differences(fields(Mesh_solver(mesh, tag), &mesh), mesh_reference) == 0u,
                 name << ", mesh solver, " << threads << " threads");
    });
  }
}

// Two degenerate triangles far apart in the faces' order: the parallel preparation names the one
// the sequential preparation names, whichever block meets its own first.
BOOST_AUTO_TEST_CASE(errors_are_the_same_for_any_thread_count)
{
  Soup soup = test_soups().back().second;
  for(std::size_t at : {std::size_t(10), soup.faces.size() - 10})
  {
    const std::size_t first = soup.points.size();
    const std::array<double, 3> p = soup.points[soup.faces[at][0]];
    soup.points.insert(soup.points.end(), {p, p, {p[0] + 1., p[1], p[2]}});
    soup.faces.push_back({first, first + 1, first + 2});
  }
  const auto message = [&](const auto& np) {
    try
    {
      Soup_solver solver(epick_points(soup), soup.faces, np);
    }
    catch(const std::invalid_argument& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string sequential = message(DP::concurrency_tag(CGAL::Sequential_tag()));
  BOOST_TEST(sequential.find("is degenerate") != std::string::npos, sequential);
  on_each_thread_count([&](int threads) {
    BOOST_TEST(message(DP::concurrency_tag(CGAL::Parallel_if_available_tag())) == sequential, threads << " threads");
  });
}

BOOST_AUTO_TEST_SUITE_END()
