// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// An edge of three triangles, split into sheets with copies of its ends (as orient_polygon_soup
// splits it) and given as copies (copy_of): a closed octahedron with a triangle hinged on one of
// its edges. Distances against the exact ones by unfolding the hinged triangle onto a face of
// the edge: paths cross the edge's interior into the other sheet, or bend at its ends; in both
// directions, with the hinged triangle's orientation either way; DGG-VTP within [exact, exact (1 +
// epsilon)]; a sphere and a real mesh cut into sheets, one of them turned, against the uncut
// ones; point sources on a split edge; paths as long as the distance, through the copies;
// copy_of's checks, and sheets of one triangle refused.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/Triangle_soup_geodesic_distance_solver.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace DP = CGAL::DGG_VTP_3::parameters;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;
using Triangle = std::array<std::size_t, 3>;

constexpr std::size_t top = 4, bottom = 5, a_copy = 6, b_copy = 7, apex = 8;

// The octahedron of the unit axes (0: +x, 1: -x, 2: +y, 3: -y, 4: +z, 5: -z), the edge AB from
// A = +x to B = +y of faces (A, B, +z) and (B, A, -z), and the triangle (A', B', apex) on copies
// of its ends; the apex at `along` times AB from A, then `out` away from the octahedron in its
// plane z = 0. `flip`: the hinged triangle goes along AB the way of (B, A, -z).
struct Hinged_octahedron
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<std::size_t> copy_of{0, 1, 2, 3, 4, 5, 0, 2, 8};

  Hinged_octahedron(double along, double out, bool flip)
  {
    const double s = std::sqrt(0.5);
    points = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),        Point(0, -1, 0), Point(0, 0, 1),
              Point(0, 0, -1), Point(1, 0, 0), Point(0, 1, 0), Point(1 - along + out * s, along + out * s, 0)};
    triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    triangles.push_back(flip ? Triangle{b_copy, a_copy, apex} : Triangle{a_copy, b_copy, apex});
  }

  // The exact distance between the apex and `s`, a vertex of a face of AB (+z or -z): every path
  // goes through AB, and the shortest from s to a point of AB is the segment in their face; so
  // the path is straight in the unfolding of the hinged triangle onto that face if it crosses
  // AB there, else it bends at A or B.
  double apex_distance(std::size_t s) const
  {
    const auto d = [](const Point& p, const Point& q) { return std::sqrt(CGAL::squared_distance(p, q)); };
    const Point &a = points[0], &b = points[2], &p = points[s], &q = points[apex];
    const double l = d(a, b);
    // in the plane of the face: A at the origin, B at (l, 0), s above the axis, the apex below
    const auto along_ab = [&](const Point& x) { return ((x - a) * (b - a)) / l; };
    const auto off_ab = [&](const Point& x) { return std::sqrt(CGAL::squared_distance(x, a) - CGAL::square(along_ab(x))); };
    const double sx = along_ab(p), sy = off_ab(p), qx = along_ab(q), qy = -off_ab(q);
    const double crossing = sx + (qx - sx) * sy / (sy - qy);
    if(crossing > 0. && crossing < l)
      return std::hypot(sx - qx, sy - qy);
    return (std::min)(d(p, a) + d(a, q), d(p, b) + d(b, q));
  }
};

std::vector<double> distances(const Solver& solver, std::size_t n, std::size_t source, double accuracy)
{
  std::vector<double> d(n);
  solver.compute_distances(source, CGAL::make_property_map(d), CGAL::parameters::accuracy(accuracy));
  return d;
}

// A closed UV sphere (`rings` - 1 rings of `m` vertices between the poles 0 and the last one),
// and the same cut along its equator into two sheets, the southern one on copies of the
// equator's vertices (appended, in its order), turned the other way round if `flip`.
struct Cut_sphere
{
  static constexpr std::size_t rings = 8, m = 12;
  std::vector<Point> points;
  std::vector<Triangle> whole, cut;
  std::vector<std::size_t> copy_of;

  explicit Cut_sphere(bool flip)
  {
    const double pi = std::acos(-1.);
    points.emplace_back(0, 0, 1);
    for(std::size_t i = 1; i < rings; ++i)
      for(std::size_t j = 0; j < m; ++j)
        points.emplace_back(std::sin(pi * i / rings) * std::cos(2 * pi * j / m),
                            std::sin(pi * i / rings) * std::sin(2 * pi * j / m), std::cos(pi * i / rings));
    points.emplace_back(0, 0, -1);
    const std::size_t last = points.size() - 1, equator = 1 + (rings / 2 - 1) * m;
    const auto ring = [](std::size_t i, std::size_t j) { return 1 + (i - 1) * m + j % m; };
    std::vector<Triangle> north, south;
    for(std::size_t j = 0; j < m; ++j)
    {
      north.push_back({0, ring(1, j), ring(1, j + 1)});
      south.push_back({last, ring(rings - 1, j + 1), ring(rings - 1, j)});
      for(std::size_t i = 1; i + 1 < rings; ++i)
      {
        auto& half = i < rings / 2 ? north : south;
        half.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
        half.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
      }
    }
    whole = north;
    whole.insert(whole.end(), south.begin(), south.end());
    copy_of.resize(points.size());
    std::iota(copy_of.begin(), copy_of.end(), std::size_t(0));
    for(std::size_t j = 0; j < m; ++j)
    {
      points.push_back(points[equator + j]);
      copy_of.push_back(equator + j);
    }
    cut = north;
    for(Triangle t : south)
    {
      for(std::size_t& v : t)
        if(v >= equator && v < equator + m)
          v = last + 1 + (v - equator);
      cut.push_back(flip ? Triangle{t[1], t[0], t[2]} : t);
    }
  }
};

// (along, out) of the apex: paths across AB's interior from both faces, from one only, or
// through B alone (the apex beyond B)
const double shapes[][2] = {{0.5, 1.}, {0.2, 0.3}, {0.9, 2.}, {1.6, 0.2}};

} // namespace

BOOST_AUTO_TEST_SUITE(vertex_copies)

BOOST_AUTO_TEST_CASE(hinged_triangle_against_unfolding)
{
  for(const auto& shape : shapes)
    for(const bool flip : {false, true})
      BOOST_TEST_CONTEXT("apex at " << shape[0] << ", " << shape[1] << (flip ? ", flipped" : ""))
      {
        const Hinged_octahedron m(shape[0], shape[1], flip);
        const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
        for(const std::size_t s : {top, bottom})
        {
          const double truth = m.apex_distance(s);
          const std::vector<double> from_s = distances(solver, m.points.size(), s, 0.);
          const std::vector<double> from_apex = distances(solver, m.points.size(), apex, 0.);
          BOOST_TEST(from_s[apex] == truth, boost::test_tools::tolerance(1e-12));
          BOOST_TEST(from_apex[s] == truth, boost::test_tools::tolerance(1e-12));
          // a copy has the distance of its point
          BOOST_TEST(from_s[a_copy] == from_s[0]);
          BOOST_TEST(from_s[b_copy] == from_s[2]);
          BOOST_TEST(from_apex[a_copy] == from_apex[0]);
          BOOST_TEST(from_apex[b_copy] == from_apex[2]);
        }
      }
}

BOOST_AUTO_TEST_CASE(dgg_vtp_within_epsilon)
{
  for(const auto& shape : shapes)
    for(const bool flip : {false, true})
    {
      const Hinged_octahedron m(shape[0], shape[1], flip);
      const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
      for(std::size_t s = 0; s < m.points.size(); ++s)
      {
        const std::vector<double> exact = distances(solver, m.points.size(), s, 0.);
        for(const double epsilon : {1., 1e-1, 1e-3})
        {
          const std::vector<double> d = distances(solver, m.points.size(), s, epsilon);
          for(std::size_t v = 0; v < d.size(); ++v)
            BOOST_TEST_CONTEXT("apex at " << shape[0] << ", " << shape[1] << (flip ? ", flipped" : "") << ", source "
                                          << s << ", vertex " << v << ", epsilon " << epsilon)
            {
              BOOST_TEST(std::isfinite(exact[v]));
              BOOST_TEST(d[v] >= exact[v] * (1 - 1e-12));
              BOOST_TEST(d[v] <= exact[v] * (1 + epsilon));
            }
        }
      }
    }
}

// a source on the split edge is on every sheet: straight to the apex, and to the octahedron's
// vertices of the edge's faces, whichever face it is given in
BOOST_AUTO_TEST_CASE(point_source_on_the_split_edge)
{
  const double t = 0.3;
  for(const bool flip : {false, true})
  {
    const Hinged_octahedron m(0.5, 1., flip);
    const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
    const Point x = m.points[0] + t * (m.points[2] - m.points[0]);
    const std::array<double, 3> in_hinged = flip ? std::array<double, 3>{t, 1 - t, 0.} : std::array<double, 3>{1 - t, t, 0.};
    for(const Solver::Face_location& source :
        {Solver::Face_location{0, {1 - t, t, 0.}}, Solver::Face_location{4, {t, 1 - t, 0.}}, Solver::Face_location{8, in_hinged}})
      BOOST_TEST_CONTEXT("flipped " << flip << ", the source given in face " << source.first)
      {
        std::vector<double> d(m.points.size());
        solver.compute_distances(source, CGAL::make_property_map(d));
        for(const std::size_t v : {top, bottom, apex})
          BOOST_TEST(d[v] == std::sqrt(CGAL::squared_distance(x, m.points[v])), boost::test_tools::tolerance(1e-12));
      }
  }
}

// cut into sheets along the equator and given the copies, the sphere is the same surface: the
// same distances, the copies' those of their points; within epsilon of them with DGG-VTP
BOOST_AUTO_TEST_CASE(sphere_cut_along_its_equator)
{
  for(const bool flip : {false, true})
  {
    const Cut_sphere sphere(flip);
    const std::size_t n = sphere.copy_of.size(), original = n - Cut_sphere::m;
    const std::vector<Point> whole_points(sphere.points.begin(), sphere.points.begin() + original);
    const Solver whole(whole_points, sphere.whole);
    const Solver cut(sphere.points, sphere.cut, DP::copy_of(sphere.copy_of));
    for(const std::size_t s : {std::size_t(0), std::size_t(14), std::size_t(40), std::size_t(70), original - 1, n - 1})
    {
      const std::size_t s_whole = sphere.copy_of[s];
      const std::vector<double> exact = distances(whole, original, s_whole, 0.);
      for(const double epsilon : {0., 1e-1, 1e-3})
      {
        const std::vector<double> d = distances(cut, n, s, epsilon);
        for(std::size_t v = 0; v < n; ++v)
          BOOST_TEST_CONTEXT((flip ? "flipped, " : "") << "source " << s << ", vertex " << v << ", epsilon " << epsilon)
          {
            const double truth = exact[sphere.copy_of[v]];
            BOOST_TEST(d[v] >= truth * (1 - 1e-12));
            BOOST_TEST(d[v] <= truth * (1 + (std::max)(epsilon, 1e-12)));
          }
      }
    }
  }
}

// The same on a real mesh cut along a wavy line into two sheets, one turned the other way: the
// distances of the uncut mesh, within epsilon with DGG-VTP
BOOST_AUTO_TEST_CASE(pinion_cut_into_two_sheets)
{
  const dggvtp_test::Soup soup = dggvtp_test::read_soup("pinion.ply");
  std::vector<Point> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  std::vector<Triangle> whole, cut;
  std::vector<char> second;
  for(const auto& f : soup.faces)
  {
    whole.push_back({f[0], f[1], f[2]});
    const Point c = CGAL::centroid(points[f[0]], points[f[1]], points[f[2]]);
    second.push_back(c.y() + 0.05 * std::sin(20 * c.z()) > 0);
  }
  const std::size_t original = points.size();
  std::vector<char> in_first(original, 0);
  for(std::size_t f = 0; f < whole.size(); ++f)
    for(const std::size_t v : whole[f])
      in_first[v] |= !second[f];
  std::vector<std::size_t> copy_of(original), copy(original, 0);
  std::iota(copy_of.begin(), copy_of.end(), std::size_t(0));
  for(std::size_t f = 0; f < whole.size(); ++f)
  {
    Triangle t = whole[f];
    if(second[f])
    {
      for(std::size_t& v : t)
        if(in_first[v])
        {
          if(copy[v] == 0)
          {
            copy[v] = points.size();
            points.push_back(points[v]);
            copy_of.push_back(v);
          }
          v = copy[v];
        }
      std::swap(t[0], t[1]);
    }
    cut.push_back(t);
  }
  BOOST_TEST_REQUIRE(points.size() > original + 10);
  const Solver uncut(std::vector<Point>(points.begin(), points.begin() + original), whole);
  const Solver sheets(points, cut, DP::copy_of(copy_of));
  for(std::size_t s = 0; s < points.size(); s += points.size() / 12)
  {
    const std::vector<double> exact = distances(uncut, original, copy_of[s], 0.);
    for(const double epsilon : {0., 1e-1, 1e-3})
    {
      const std::vector<double> d = distances(sheets, points.size(), s, epsilon);
      for(std::size_t v = 0; v < d.size(); ++v)
        BOOST_TEST_CONTEXT("source " << s << ", vertex " << v << ", epsilon " << epsilon)
        {
          const double truth = exact[copy_of[v]];
          BOOST_TEST(d[v] >= truth * (1 - 1e-12));
          BOOST_TEST(d[v] <= truth * (1 + (std::max)(epsilon, 1e-12)));
        }
    }
  }
}

// the sheets unlinked, the hinged triangle cannot be reached: what copy_of changes
BOOST_AUTO_TEST_CASE(without_copies_the_sheets_are_apart)
{
  const Hinged_octahedron m(0.5, 1., false);
  const Solver solver(m.points, m.triangles);
  const std::vector<double> d = distances(solver, m.points.size(), top, 0.);
  BOOST_TEST(d[apex] == std::numeric_limits<double>::infinity());
}

BOOST_AUTO_TEST_CASE(paths_go_through_the_copies)
{
  for(const auto& shape : shapes)
    for(const double epsilon : {0., 1e-2})
      BOOST_TEST_CONTEXT("apex at " << shape[0] << ", " << shape[1] << ", epsilon " << epsilon)
      {
        const Hinged_octahedron m(shape[0], shape[1], true);
        const Solver solver(m.points, m.triangles, DP::copy_of(m.copy_of));
        for(const auto& [from, to] : {std::array<std::size_t, 2>{top, apex}, std::array<std::size_t, 2>{apex, bottom},
                                      std::array<std::size_t, 2>{apex, 1}})
        {
          const auto tree = solver.compute_shortest_path_tree(std::vector<std::size_t>{from},
                                                              CGAL::parameters::accuracy(epsilon));
          std::vector<CGAL::DGG_VTP_3::Shortest_path_tree<Solver>::Path_point> path;
          tree.shortest_path(to, std::back_inserter(path));
          BOOST_TEST_REQUIRE(path.size() >= 2u);
          std::vector<Point> at;
          for(const auto& p : path)
          {
            const Triangle& t = m.triangles[p.location.first];
            double xyz[3] = {0., 0., 0.};
            for(int k = 0; k < 3; ++k)
              for(int c = 0; c < 3; ++c)
                xyz[c] += p.location.second[k] * m.points[t[k]][c];
            at.emplace_back(xyz[0], xyz[1], xyz[2]);
          }
          double length = 0.;
          for(std::size_t i = 1; i < at.size(); ++i)
            length += std::sqrt(CGAL::squared_distance(at[i - 1], at[i]));
          BOOST_TEST(length == tree.distance(to), boost::test_tools::tolerance(1e-9));
          BOOST_TEST(CGAL::squared_distance(at.front(), m.points[to]) < 1e-24);
          BOOST_TEST(CGAL::squared_distance(at.back(), m.points[from]) < 1e-24);
        }
      }
}

BOOST_AUTO_TEST_CASE(copy_of_is_checked)
{
  const Hinged_octahedron m(0.5, 1., false);
  BOOST_CHECK_THROW(Solver(m.points, m.triangles, DP::copy_of(std::vector<std::size_t>(3, 0))), std::invalid_argument);
  std::vector<std::size_t> beyond = m.copy_of;
  beyond[a_copy] = 9;
  BOOST_CHECK_THROW(Solver(m.points, m.triangles, DP::copy_of(beyond)), std::invalid_argument);
  std::vector<std::size_t> elsewhere = m.copy_of;
  elsewhere[a_copy] = 1;
  BOOST_CHECK_THROW(Solver(m.points, m.triangles, DP::copy_of(elsewhere)), std::invalid_argument);
}

// Three sheets of one needle triangle (a fuzz input, 0.24 degrees there): the windows between
// them would multiply without end, so the solver refuses them, naming the points; one sheet, or
// two on the same points without copies (a closed pillow), give the distances in the plane.
BOOST_AUTO_TEST_CASE(sheets_of_one_triangle)
{
  const double needle = std::tan(0.24 * std::acos(-1.) / 180.);
  std::vector<Point> points;
  for(int sheet = 0; sheet < 3; ++sheet)
    points.insert(points.end(), {Point(0, 0, 0), Point(1, 0, 0), Point(0, needle, 0)});
  const std::vector<Triangle> three{{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  const std::vector<std::size_t> copy_of{0, 1, 2, 0, 1, 2, 0, 1, 2};
  try
  {
    Solver(points, three, DP::copy_of(copy_of));
    BOOST_ERROR("three sheets of one triangle were taken");
  }
  catch(const std::invalid_argument& e)
  {
    BOOST_CHECK_EQUAL(std::string(e.what()), "two triangles are on the same points 0, 1 and 2 (copy_of making them "
                                             "copies): leave all but one of them out");
  }
  const std::vector<double> expected{0., 1., needle};
  for(const std::vector<Triangle>& faces : {std::vector<Triangle>{{0, 1, 2}}, std::vector<Triangle>{{0, 1, 2}, {0, 2, 1}}})
    for(double accuracy : {0., 1e-3})
    {
      const std::vector<double> d = distances(Solver(points, faces), points.size(), 0, accuracy);
      for(std::size_t v = 0; v < 3; ++v) // relative: the needle's tip is 4e-3 away
        BOOST_TEST((d[v] >= expected[v] * (1. - 1e-15) && d[v] <= expected[v] * (1. + accuracy) * (1. + 1e-15)),
                   "vertex " << v << ": " << d[v] << ", exact " << expected[v] << ", accuracy " << accuracy);
    }
}

BOOST_AUTO_TEST_SUITE_END()
