// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Shared by the translation units of test_DGG_VTP_3: the named configurations (mesh type x number
// type, each with its tolerance), mesh construction from polygon soups, synthetic meshes with
// analytic distances, and the error measure every test reports.

#ifndef CGAL_DGG_VTP_3_TEST_UTILITIES_H
#define CGAL_DGG_VTP_3_TEST_UTILITIES_H

#include <CGAL/DGG_VTP_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <boost/test/unit_test.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#ifndef DGG_VTP_3_DATA_DIR
#error "DGG_VTP_3_DATA_DIR must be defined to the directory of the bundled meshes"
#endif

#ifdef CGAL_LINKED_WITH_TBB
// Runs `f()` on `threads` real threads: in a TBB arena of that many, with TBB's process-wide limit
// on workers raised to it (an arena alone gets no more threads than the cores: 8 would run on 2 on
// the CI machine, and their interleavings would never be tried). Checks that the arena has them.
template <class F>
void on_threads(int threads, const F& f)
{
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  tbb::task_arena arena(threads);
  arena.execute([&] {
    BOOST_REQUIRE_EQUAL(tbb::this_task_arena::max_concurrency(), threads);
    BOOST_REQUIRE_EQUAL(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
                        std::size_t(threads));
    f();
  });
}
#endif

// ---------------------------------------------------------------------------------------------
// Named configurations: mesh type x number type, each with the tolerance its results must meet
// (maximum relative error over all vertices).
// ---------------------------------------------------------------------------------------------

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Sc_float = CGAL::Simple_cartesian<float>;

struct Sm_d // Surface_mesh, double
{
  using Kernel = Epick;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  static constexpr double tolerance = 1e-12;
};
struct Sm_f // Surface_mesh, float
{
  using Kernel = Sc_float;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  static constexpr double tolerance = 1e-5;
};
struct Ph_d // Polyhedron_3 without ids, double
{
  using Kernel = Epick;
  using Mesh = CGAL::Polyhedron_3<Kernel>;
  static constexpr double tolerance = 1e-12;
};
struct Ph_f // Polyhedron_3 without ids, float
{
  using Kernel = Sc_float;
  using Mesh = CGAL::Polyhedron_3<Kernel>;
  static constexpr double tolerance = 1e-5;
};

// The sanitizer builds (scripts/run_sanitizers.sh, run_thread_sanitizer.sh) test fewer
// configurations: Surface_mesh only (a Polyhedron_3 reaches the same library code through its
// property maps, and its instances doubled the time of those builds and their runs), and no MPFR
// (whose cost is its precision, over the code that double runs). The Release run has them all.
#ifdef DGG_VTP_3_TEST_FEWER_CONFIGURATIONS
using All_configurations = std::tuple<Sm_d, Sm_f>;
using Float_configurations = std::tuple<Sm_f>;
#else
using All_configurations = std::tuple<Sm_d, Sm_f, Ph_d, Ph_f>;
using Float_configurations = std::tuple<Sm_f, Ph_f>;
#endif

// Number types beyond float and double, run where an analytic truth is known: their tolerance is
// that of the truth, computed in double.
struct Sm_ld // Surface_mesh, long double
{
  using Kernel = CGAL::Simple_cartesian<long double>;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  static constexpr double tolerance = 1e-14;
};
struct Sm_mpfr // Surface_mesh, CGAL::Gmpfr (default precision set by the module's global fixture)
{
  using Kernel = CGAL::Simple_cartesian<CGAL::Gmpfr>;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  static constexpr double tolerance = 1e-14;
  static constexpr long precision = 150; // bits
};
#ifdef DGG_VTP_3_TEST_FEWER_CONFIGURATIONS
using Analytic_configurations = std::tuple<Sm_d, Sm_f, Sm_ld>;
#else
using Analytic_configurations = std::tuple<Sm_d, Sm_f, Ph_d, Ph_f, Sm_ld, Sm_mpfr>;
#endif

// absolute bound on the distance reported at the source itself
constexpr double source_tolerance = 1e-12;

namespace dggvtp_test {

// ---------------------------------------------------------------------------------------------
// Polygon soups and meshes
// ---------------------------------------------------------------------------------------------

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
};

// the points of `soup` as Epick's
inline std::vector<Epick::Point_3> epick_points(const Soup& soup)
{
  std::vector<Epick::Point_3> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  return points;
}

// deterministic on every platform (std distributions are not)
class Random
{
public:
  explicit Random(std::uint64_t seed) : m_state(seed) {}
  // uniform in [0, 1)
  double uniform()
  {
    m_state ^= m_state << 13; m_state ^= m_state >> 7; m_state ^= m_state << 17;
    return double(m_state >> 11) * (1.0 / 9007199254740992.0);
  }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  bool coin() { return uniform() < 0.5; }
private:
  std::uint64_t m_state;
};

template <class Mesh>
using Vertex = typename boost::graph_traits<Mesh>::vertex_descriptor;

template <class Mesh>
std::vector<Vertex<Mesh>> vertex_list(const Mesh& mesh)
{
  std::vector<Vertex<Mesh>> result;
  for(auto v : vertices(mesh))
    result.push_back(v);
  return result;
}

// builds `Mesh` from the soup, with vertex i (in iteration order) at soup point i
template <class Mesh>
Mesh make_mesh(const Soup& soup)
{
  using Point = typename boost::property_traits<
                  typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  std::vector<Point> points;
  for(const auto& p : soup.points)
    points.emplace_back(FT(p[0]), FT(p[1]), FT(p[2]));
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.faces, mesh);
  BOOST_REQUIRE_EQUAL(num_vertices(mesh), points.size());
  BOOST_REQUIRE_EQUAL(num_faces(mesh), soup.faces.size());
  std::size_t i = 0;
  for(auto v : vertices(mesh))
    BOOST_REQUIRE(get(CGAL::vertex_point, mesh, v) == points[i++]);
  return mesh;
}

inline Soup read_soup(const std::string& name)
{
  const std::string file = std::string(DGG_VTP_3_DATA_DIR) + "/" + name;
  std::vector<Epick::Point_3> points;
  Soup soup;
  BOOST_REQUIRE_MESSAGE(CGAL::IO::read_polygon_soup(file, points, soup.faces), "cannot read " << file);
  for(const auto& p : points)
    soup.points.push_back({p.x(), p.y(), p.z()});
  return soup;
}

// ---------------------------------------------------------------------------------------------
// Distances
// ---------------------------------------------------------------------------------------------

template <class Mesh>
struct Distance_map
{
  using Point = typename boost::property_traits<
                  typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  using type = typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<FT>>::type;
};

// distances in vertex iteration order, converted to double
template <class Mesh, class Map>
std::vector<double> to_vector(const Mesh& mesh, const Map& map)
{
  std::vector<double> result;
  for(auto v : vertices(mesh))
    result.push_back(CGAL::to_double(get(map, v)));
  return result;
}

// distances from the i-th vertex, by the one-shot function
template <class Mesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<double> geodesic_distances(const Mesh& mesh, std::size_t source_index,
                                       CGAL::DGG_VTP_3::Propagation_statistics* statistics = nullptr,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  auto map = get(CGAL::dynamic_vertex_property_t<typename Distance_map<Mesh>::FT>(), mesh);
  const auto s = CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, vertex_list(mesh).at(source_index), np);
  if(statistics)
    *statistics = s;
  return to_vector(mesh, map);
}

// the same through a solver
template <class Solver, class Mesh>
std::vector<double> solver_distances(const Solver& solver, const Mesh& mesh, std::size_t source_index,
                                     CGAL::DGG_VTP_3::Propagation_statistics* statistics = nullptr)
{
  auto map = get(CGAL::dynamic_vertex_property_t<typename Solver::FT>(), mesh);
  const auto s = solver.compute_distances(vertex_list(mesh).at(source_index), map);
  if(statistics)
    *statistics = s;
  return to_vector(mesh, map);
}

struct Error_report
{
  double max_relative = 0.;  // max over vertices other than the source of |d - truth| / truth
  std::size_t worst = 0;     // the vertex where it is reached
  double at_source = 0.;     // distance reported at the source
  std::size_t non_finite = 0;// vertices with a non-finite distance where the truth is finite
};

inline Error_report relative_error(const std::vector<double>& computed, const std::vector<double>& truth,
                                   std::size_t source_index)
{
  Error_report r;
  BOOST_REQUIRE_EQUAL(computed.size(), truth.size());
  r.at_source = source_index < computed.size() ? computed[source_index] : 0.; // none: a source inside a face
  for(std::size_t i = 0; i < computed.size(); ++i)
  {
    if(i == source_index)
      continue;
    if(!std::isfinite(computed[i]))
    {
      ++r.non_finite;
      continue;
    }
    const double e = std::abs(computed[i] - truth[i]) / truth[i];
    if(!(e <= r.max_relative))
    {
      r.max_relative = e;
      r.worst = i;
    }
  }
  return r;
}

// asserts that `computed` matches `truth` within `tolerance` (relative) and prints the figures;
// `source_index` is the source vertex (out of range: the source is not a vertex)
inline void check_distances(const std::vector<double>& computed, const std::vector<double>& truth,
                            std::size_t source_index, double tolerance, const std::string& label)
{
  const Error_report r = relative_error(computed, truth, source_index);
  BOOST_TEST_MESSAGE(label << ": " << computed.size() << " vertices, max relative error "
                     << r.max_relative << " at vertex " << r.worst << " (truth " << truth[r.worst]
                     << "), distance at the source " << r.at_source << ", tolerance " << tolerance);
  BOOST_TEST(r.non_finite == 0u, label);
  BOOST_TEST(r.max_relative <= tolerance, label << ": max relative error " << r.max_relative
                                           << " at vertex " << r.worst);
  BOOST_TEST(r.at_source >= 0., label);
  BOOST_TEST(r.at_source <= source_tolerance, label);
}

template <class Config>
std::string config_name();
template <> inline std::string config_name<Sm_d>() { return "Sm_d"; }
template <> inline std::string config_name<Sm_f>() { return "Sm_f"; }
template <> inline std::string config_name<Ph_d>() { return "Ph_d"; }
template <> inline std::string config_name<Ph_f>() { return "Ph_f"; }
template <> inline std::string config_name<Sm_ld>() { return "Sm_ld"; }
template <> inline std::string config_name<Sm_mpfr>() { return "Sm_mpfr"; }

// ---------------------------------------------------------------------------------------------
// Synthetic meshes
// ---------------------------------------------------------------------------------------------

// a rigid motion of R^3 (rotation about a skew axis, then a translation)
struct Rigid_motion
{
  double r[3][3];
  double t[3];
  Rigid_motion(std::array<double, 3> axis, double angle, std::array<double, 3> translation)
  {
    const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n;
    const double c = std::cos(angle), s = std::sin(angle), C = 1 - c;
    const double m[3][3] = {{c + x * x * C, x * y * C - z * s, x * z * C + y * s},
                            {y * x * C + z * s, c + y * y * C, y * z * C - x * s},
                            {z * x * C - y * s, z * y * C + x * s, c + z * z * C}};
    for(int i = 0; i < 3; ++i)
    {
      for(int j = 0; j < 3; ++j)
        r[i][j] = m[i][j];
      t[i] = translation[i];
    }
  }
  std::array<double, 3> operator()(double x, double y, double z) const
  {
    std::array<double, 3> p;
    for(int i = 0; i < 3; ++i)
      p[i] = r[i][0] * x + r[i][1] * y + r[i][2] * z + t[i];
    return p;
  }
};

// The triangles of a grid of (nx+1) x (ny+1) points, point (i, j) being soup point j * (nx + 1) + i:
// each quad split along a random diagonal.
inline void add_grid_triangles(std::size_t nx, std::size_t ny, Random& random, Soup& soup)
{
  const auto id = [nx](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i)
    {
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if(random.coin())
      {
        soup.faces.push_back({a, b, c});
        soup.faces.push_back({a, c, d});
      }
      else
      {
        soup.faces.push_back({a, b, d});
        soup.faces.push_back({b, c, d});
      }
    }
}

// A flat, convex rectangle [0, nx*dx] x [0, ny*dy] triangulated from a grid of (nx+1) x (ny+1)
// points: interior points jittered by up to `jitter` times the cell size in each direction,
// border points only along the border (so the patch stays a rectangle and every quad stays
// convex for jitter <= 0.15), each quad split along a random diagonal; then moved into 3D by
// a rigid motion. Vertex (i, j) has index j * (nx + 1) + i.
inline Soup flat_patch(std::size_t nx, std::size_t ny, double dx, double dy, double jitter, std::uint64_t seed,
                       const Rigid_motion& motion)
{
  Random random(seed);
  Soup soup;
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i)
    {
      double x = double(i) * dx, y = double(j) * dy;
      const bool x_border = (i == 0 || i == nx), y_border = (j == 0 || j == ny);
      const double jx = random.uniform(-jitter, jitter), jy = random.uniform(-jitter, jitter);
      if(!x_border)
        x += jx * dx;
      if(!y_border)
        y += jy * dy;
      soup.points.push_back(motion(x, y, 0.));
    }
  add_grid_triangles(nx, ny, random, soup);
  return soup;
}

// Euclidean distances from the i-th vertex, computed from the mesh's own coordinates (so float
// meshes are compared with the truth of their rounded points)
template <class Mesh>
std::vector<double> euclidean_distances(const Mesh& mesh, std::size_t source_index)
{
  std::vector<std::array<double, 3>> p;
  for(auto v : vertices(mesh))
  {
    const auto& q = get(CGAL::vertex_point, mesh, v);
    p.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
  }
  std::vector<double> d;
  for(const auto& q : p)
  {
    const double x = q[0] - p[source_index][0], y = q[1] - p[source_index][1], z = q[2] - p[source_index][2];
    d.push_back(std::sqrt(x * x + y * y + z * z));
  }
  return d;
}

// The open lateral surface of a prism over an irregular convex polygon with `sides` corners,
// each side cut into `subdivisions` segments at jittered positions, `rings` rings at irregular
// heights, each quad split along a random diagonal. Intrinsically a flat cylinder of
// circumference `perimeter` and straight borders, so the geodesic distance between (s1, h1) and
// (s2, h2) (arc length along the cross-section, height) is
// min over k in {-1, 0, 1} of sqrt((s2 - s1 + k * perimeter)^2 + (h2 - h1)^2).
struct Prism
{
  Soup soup;
  std::vector<double> arc;    // arc length of each vertex along the cross-section
  std::vector<double> height; // height of each vertex
  double perimeter = 0.;
  std::size_t per_ring = 0;   // vertices per ring; vertex (k, j) has index j * per_ring + k

  // number of vertices whose shortest path from the source crosses the seam of the strip
  std::size_t wrapped(std::size_t source_index) const
  {
    std::size_t n = 0;
    for(std::size_t i = 0; i < arc.size(); ++i)
      n += std::abs(arc[i] - arc[source_index]) > perimeter / 2;
    return n;
  }

  std::vector<double> distances(std::size_t source_index) const
  {
    std::vector<double> d;
    for(std::size_t i = 0; i < arc.size(); ++i)
    {
      const double ds = arc[i] - arc[source_index], dh = height[i] - height[source_index];
      double best = std::numeric_limits<double>::infinity();
      for(int k = -1; k <= 1; ++k)
        best = (std::min)(best, std::hypot(ds + k * perimeter, dh));
      d.push_back(best);
    }
    return d;
  }
};

inline Prism prism_lateral_surface(std::size_t sides, std::size_t subdivisions, std::size_t rings,
                                   double total_height, std::uint64_t seed)
{
  Random random(seed);
  Prism prism;
  const double pi = 3.14159265358979323846;
  // irregular convex polygon: corners on an ellipse at jittered angles
  std::vector<std::array<double, 2>> corners;
  for(std::size_t i = 0; i < sides; ++i)
  {
    const double a = 2 * pi * (double(i) + random.uniform(-0.3, 0.3)) / double(sides);
    corners.push_back({1.3 * std::cos(a), 0.8 * std::sin(a)});
  }
  // points of one ring: corners and jittered points on each side, with their arc length
  std::vector<std::array<double, 2>> ring;
  for(std::size_t i = 0; i < sides; ++i)
  {
    const auto& p = corners[i];
    const auto& q = corners[(i + 1) % sides];
    const double side_length = std::hypot(q[0] - p[0], q[1] - p[1]);
    for(std::size_t k = 0; k < subdivisions; ++k)
    {
      const double t = (k == 0) ? 0. : (double(k) + random.uniform(-0.25, 0.25)) / double(subdivisions);
      ring.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      prism.arc.push_back(prism.perimeter + t * side_length);
    }
    prism.perimeter += side_length;
  }
  prism.per_ring = ring.size();
  const std::vector<double> ring_arc = prism.arc;
  prism.arc.clear();
  std::vector<double> heights;
  for(std::size_t j = 0; j < rings; ++j)
    heights.push_back(total_height * (j == 0 || j + 1 == rings ? double(j)
                                      : double(j) + random.uniform(-0.3, 0.3)) / double(rings - 1));
  const Rigid_motion motion({-0.4, 0.9, 0.2}, 1.1, {2., 0.5, -1.});
  for(std::size_t j = 0; j < rings; ++j)
    for(std::size_t k = 0; k < prism.per_ring; ++k)
    {
      prism.soup.points.push_back(motion(ring[k][0], ring[k][1], heights[j]));
      prism.arc.push_back(ring_arc[k]);
      prism.height.push_back(heights[j]);
    }
  const std::size_t n = prism.per_ring;
  for(std::size_t j = 0; j + 1 < rings; ++j)
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t a = j * n + k, b = j * n + (k + 1) % n, c = (j + 1) * n + (k + 1) % n, d = (j + 1) * n + k;
      if(random.coin())
      {
        prism.soup.faces.push_back({a, b, c});
        prism.soup.faces.push_back({a, c, d});
      }
      else
      {
        prism.soup.faces.push_back({a, b, d});
        prism.soup.faces.push_back({b, c, d});
      }
    }
  return prism;
}

} // namespace dggvtp_test

#endif // CGAL_DGG_VTP_3_TEST_UTILITIES_H
