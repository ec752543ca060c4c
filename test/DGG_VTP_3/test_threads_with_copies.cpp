// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Parallel rounds on a mesh whose vertex copies lie in different patches: a scan with loose flaps,
// made of a real mesh with fins glued on its edges (a third triangle on an edge, its ends split
// into copies as a loader's repair splits them). A distance that reaches a copy is relayed to the
// others, from patch to patch, while the patches receive their messages on several threads: the
// same bits as Sequential_tag on 2, 4 and 8 threads, run after run, with and without targets and
// a maximum distance; and a query that stops early leaves nothing for the next one.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/Triangle_soup_geodesic_distance_solver.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace dggvtp_test;
namespace DP = CGAL::DGG_VTP_3::parameters;

namespace {

using Point = Epick::Point_3;
using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Epick>;
using Triangle = std::array<std::size_t, 3>;

// `mesh` with `count` fins on edges spread over it: the fin on edge (a, b) is the triangle (a',
// b', apex) on copies a' and b' of its ends, its apex above the edge's midpoint, half the edge's
// length away along the normal of a face of the edge
struct Finned_mesh
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<std::size_t> copy_of;

  Finned_mesh(const Soup& mesh, std::size_t count)
  {
    for(const auto& p : mesh.points)
      points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::pair<std::array<std::size_t, 2>, std::size_t>> edges; // (sorted ends, a face)
    for(std::size_t f = 0; f < mesh.faces.size(); ++f)
    {
      const auto& t = mesh.faces[f];
      triangles.push_back({t[0], t[1], t[2]});
      for(int k = 0; k < 3; ++k)
        edges.push_back({{(std::min)(t[k], t[(k + 1) % 3]), (std::max)(t[k], t[(k + 1) % 3])}, f});
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
                edges.end());
    copy_of.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      copy_of[i] = i;
    for(std::size_t k = 0; k < count; ++k)
    {
      const auto& e = edges[k * edges.size() / count];
      const Triangle& t = triangles[e.second];
      const Point a = points[e.first[0]], b = points[e.first[1]];
      const auto n = CGAL::cross_product(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
      const double scale = std::sqrt(CGAL::squared_distance(a, b) / n.squared_length()) / 2;
      const std::size_t first = points.size();
      points.insert(points.end(), {a, b, CGAL::midpoint(a, b) + n * scale});
      copy_of.insert(copy_of.end(), {e.first[0], e.first[1], first + 2});
      triangles.push_back({first, first + 1, first + 2});
    }
  }
};

const Finned_mesh& finned_lion_head()
{
  static const Finned_mesh mesh(read_soup("lion_head.ply"), 1500);
  return mesh;
}

// what a query gives: its field, its targets' distances and its counts
struct Answer
{
  std::vector<double> field;
  std::vector<double> targets;
  CGAL::DGG_VTP_3::Propagation_statistics statistics;
};

bool same_bits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

bool same(const Answer& a, const Answer& b)
{
  return same_bits(a.field, b.field) && same_bits(a.targets, b.targets) &&
         a.statistics.windows_created == b.statistics.windows_created &&
         a.statistics.vertices_popped == b.statistics.vertices_popped &&
         a.statistics.pseudo_sources == b.statistics.pseudo_sources &&
         a.statistics.vertices_reached == b.statistics.vertices_reached &&
         a.statistics.windows_peak == b.statistics.windows_peak;
}

// the kinds of query: a whole field, with targets (early termination), within a maximum distance
enum class Kind { whole, targets, max_distance };

template <class Tag>
Answer answer(const Solver& solver, std::size_t source, double accuracy, Kind kind)
{
  Answer a;
  a.field.assign(solver.number_of_vertices(), -1.);
  const auto map = CGAL::make_property_map(a.field);
  if(kind == Kind::targets)
  {
    const std::size_t n = solver.number_of_vertices();
    const std::vector<std::size_t> targets{(source + n / 7) % n, (source + n / 3) % n, n - 1};
    a.statistics = solver.template compute_distances<Tag>(
      source, map, DP::target_distances(std::back_inserter(a.targets), DP::targets(targets)).accuracy(accuracy));
  }
  else if(kind == Kind::max_distance)
    a.statistics = solver.template compute_distances<Tag>(source, map, DP::max_distance(0.05).accuracy(accuracy));
  else
    a.statistics = solver.template compute_distances<Tag>(source, map, CGAL::parameters::accuracy(accuracy));
  return a;
}

// 20 runs for each thread count; DGG_VTP_3_TEST_RUNS says fewer under ThreadSanitizer, which
// reports a race whether or not it changes a result, 10 to 50 times slower
int runs_per_thread_count()
{
  const char* runs = std::getenv("DGG_VTP_3_TEST_RUNS");
  return runs != nullptr ? std::max(1, std::atoi(runs)) : 20;
}

std::string name(Kind kind)
{
  return kind == Kind::whole ? "whole field" : kind == Kind::targets ? "targets" : "max_distance";
}

} // namespace

BOOST_AUTO_TEST_SUITE(threads_with_copies)

// the fins make copies in other patches than the vertices they copy
BOOST_AUTO_TEST_CASE(the_mesh_has_copies_across_patches)
{
  const Finned_mesh& m = finned_lion_head();
  const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
  BOOST_TEST(solver.number_of_vertices() == m.points.size());
  // a query from a fin's apex reaches the whole mesh through the copies of its edge's ends
  std::vector<double> d(m.points.size());
  solver.compute_distances(m.points.size() - 1, CGAL::make_property_map(d));
  BOOST_TEST(std::count(d.begin(), d.end(), std::numeric_limits<double>::infinity()) == 0);
}

#ifdef CGAL_LINKED_WITH_TBB
// 20 runs on each of 2, 4 and 8 threads (5 with targets or a maximum distance), each the bits
// and counts of Sequential_tag
BOOST_AUTO_TEST_CASE(parallel_rounds_give_the_sequential_bits)
{
  const Finned_mesh& m = finned_lion_head();
  const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
  const std::size_t source = 1234;
  for(Kind kind : {Kind::whole, Kind::targets, Kind::max_distance})
    for(double accuracy : {0., 1e-3, 1e-1})
    {
      const Answer expected = answer<CGAL::Sequential_tag>(solver, source, accuracy, kind);
      const int runs = kind == Kind::whole ? runs_per_thread_count() : (runs_per_thread_count() + 3) / 4;
      for(int threads : {2, 4, 8})
        on_threads(threads, [&] {
          int differ = 0;
          for(int run = 0; run < runs; ++run)
            differ += !same(answer<CGAL::Parallel_tag>(solver, source, accuracy, kind), expected);
          BOOST_TEST(differ == 0, name(kind) << ", accuracy " << accuracy << ", " << threads << " threads: "
                                  << differ << " of " << runs << " runs differ from Sequential_tag");
        });
    }
}

// farthest-point sampling adds each sample to the field of those before, a prior field read
// across the patches' borders and the copies: the samples, the field and the labels of
// Sequential_tag on 2, 4 and 8 threads
BOOST_AUTO_TEST_CASE(farthest_point_sampling_gives_the_sequential_bits)
{
  const Finned_mesh& m = finned_lion_head();
  const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
  const std::size_t n = m.points.size();
  for(double accuracy : {0., 1e-2})
  {
    const auto sample = [&](auto tag, std::vector<double>& d, std::vector<std::size_t>& labels) {
      std::vector<std::size_t> samples;
      d.assign(n, -1.), labels.assign(n, 0);
      solver.farthest_point_sampling<decltype(tag)>(
        60, std::back_inserter(samples),
        DP::distance_map(CGAL::make_property_map(d),
                         DP::nearest_source_map(CGAL::make_property_map(labels), CGAL::parameters::accuracy(accuracy))));
      return samples;
    };
    std::vector<double> d0, d;
    std::vector<std::size_t> l0, l;
    const std::vector<std::size_t> expected = sample(CGAL::Sequential_tag(), d0, l0);
    for(int threads : {2, 4, 8})
      on_threads(threads, [&] {
        int differ = 0;
        for(int run = 0; run < (runs_per_thread_count() + 3) / 4; ++run)
          differ += !(sample(CGAL::Parallel_tag(), d, l) == expected && same_bits(d, d0) && l == l0);
        BOOST_TEST(differ == 0, "accuracy " << accuracy << ", " << threads << " threads: " << differ
                                            << " samplings differ from Sequential_tag");
      });
  }
}
#endif

// A query with targets stops early, with windows left in the lists; the whole field after it, on
// the same solver, is the one of a fresh solver: sequentially and on 2 threads, for sources
// spread over the mesh and over the fins
BOOST_AUTO_TEST_CASE(a_query_that_stops_early_leaves_nothing_behind)
{
  const Finned_mesh& m = finned_lion_head();
  const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
  const std::size_t n = m.points.size();
  for(double accuracy : {0., 1e-3})
    for(std::size_t source : {std::size_t(17), n / 2, n - 2, n - 301})
    {
      const Answer fresh = answer<CGAL::Sequential_tag>(Solver(m.points, m.triangles, DP::copy_of(m.copy_of)), source,
                                                        accuracy, Kind::whole);
      answer<CGAL::Sequential_tag>(solver, source, accuracy, Kind::targets);
      BOOST_TEST(same(answer<CGAL::Sequential_tag>(solver, source, accuracy, Kind::whole), fresh),
                 "source " << source << ", accuracy " << accuracy << ", sequential");
#ifdef CGAL_LINKED_WITH_TBB
      for(int threads : {2, 8})
        on_threads(threads, [&] {
          answer<CGAL::Parallel_tag>(solver, source, accuracy, Kind::targets);
          BOOST_TEST(same(answer<CGAL::Parallel_tag>(solver, source, accuracy, Kind::whole), fresh),
                     "source " << source << ", accuracy " << accuracy << ", " << threads << " threads");
        });
#endif
    }
}

BOOST_AUTO_TEST_SUITE_END()
