// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// All rights reserved.
//
// This file is part of DGG_VTP_3, a package written for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_DISTANCE_TO_GO_H
#define CGAL_DGG_VTP_3_INTERNAL_DISTANCE_TO_GO_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Surface_point.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A lower bound of the distance on the surface from a point to the nearest of a query's targets:
// the straight distance in space, which no path on the surface beats. A query with targets orders
// its vertices by distance plus this bound (a search toward the targets, as A* does), and stops
// once nothing pending can reach a target at less than its distance (see early_termination.h).
// The bound grows by at most the length travelled (it is 1-Lipschitz), which is what makes the
// order and the stop sound: along any path, distance + bound never decreases.
//
// The mesh keeps its positions in float; the bound allows for their rounding (half a unit in the
// last place of each coordinate, at both ends) and for the rounding of the edge lengths (relative
// rounding_margin): it is a lower bound of the distances the propagation computes from the
// positions in double. With more targets than max_exact_targets(), the distance to the targets'
// bounding box is taken instead (a weaker bound, at a constant cost per vertex). Without
// targets, the bound is 0 everywhere and the order is the distance's.
template <class FT>
class Distance_to_go
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;

public:
  Distance_to_go() = default;

  Distance_to_go(const Mesh& mesh, const std::vector<Index>& vertex_targets,
                 const std::vector<Surface_point<FT>>& point_targets)
  {
    for(Index v : vertex_targets)
      add(mesh.position(v));
    for(const Surface_point<FT>& q : point_targets)
    {
      double p[3] = {0., 0., 0.};
      for(int k = 0; k < 3; ++k)
      {
        const float* corner = mesh.position(mesh.source(3 * q.face + Index(k)));
        const double b = CGAL::to_double(q.barycentric[k]);
        for(int c = 0; c < 3; ++c)
          p[c] += b * double(corner[c]);
      }
      // a point of the face: the float corners' rounding, and that of the combination
      add(p, 3 * std::numeric_limits<double>::epsilon());
    }
    m_active = !m_targets.empty();
  }

  bool active() const { return m_active; }

  // at vertex `v` of `mesh`
  FT at(const Mesh& mesh, Index v) const
  {
    if(!m_active)
      return number<FT>(0);
    const float* x = mesh.position(v);
    const double d2 = m_targets.size() <= max_exact_targets() ? nearest_squared_distance(x) : squared_box_distance(x);
    // far more than the rounding of the distances, in the propagation as here
    const double d = std::sqrt(d2) * (1. - 1e-10) - half_ulp_sum(x) - m_rounding;
    return d > 0. ? number<FT>(d) : number<FT>(0);
  }

  // at the points of the edge of halfedge `h`, between b0 and b1 from its source, the bound
  // being 1-Lipschitz: at least at(source) - b1 and at(target) - (length - b0)
  FT on_edge(const Mesh& mesh, Index h, FT b0, FT b1) const
  {
    if(!m_active)
      return number<FT>(0);
    const FT a = at(mesh, mesh.source(h)) - b1;
    const FT b = at(mesh, mesh.target(h)) - (mesh.length(h) - b0);
    const FT best = (std::max)(a, b);
    return best > FT(0) ? best : number<FT>(0);
  }

  static constexpr std::size_t max_exact_targets() { return 16; }

private:
  struct Target
  {
    std::array<double, 3> p;
  };

  void add(const float* x) { add(std::array<double, 3>{double(x[0]), double(x[1]), double(x[2])}.data(), 0.); }
  void add(const double* x, double relative = 0.)
  {
    Target t{{x[0], x[1], x[2]}};
    m_targets.push_back(t);
    // the target's own rounding: half a float ulp per coordinate, plus `relative` of its size
    const float f[3] = {float(x[0]), float(x[1]), float(x[2])};
    m_rounding = (std::max)(m_rounding, half_ulp_sum(f) + relative * (std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2])));
    for(int c = 0; c < 3; ++c)
    {
      m_low[c] = (std::min)(m_low[c], x[c]);
      m_high[c] = (std::max)(m_high[c], x[c]);
    }
  }

  // a bound of the distance between a float position and the double one it rounds
  static double half_ulp_sum(const float* x)
  {
    double s = 0.;
    for(int c = 0; c < 3; ++c)
      s += double(std::numeric_limits<float>::epsilon()) * std::abs(double(x[c]));
    return s;
  }
  double nearest_squared_distance(const float* x) const
  {
    double best = std::numeric_limits<double>::infinity();
    for(const Target& t : m_targets)
    {
      double s = 0.;
      for(int c = 0; c < 3; ++c)
        s += (double(x[c]) - t.p[c]) * (double(x[c]) - t.p[c]);
      best = (std::min)(best, s);
    }
    return best;
  }
  double squared_box_distance(const float* x) const
  {
    double s = 0.;
    for(int c = 0; c < 3; ++c)
    {
      const double y = double(x[c]);
      const double e = y < m_low[c] ? m_low[c] - y : y > m_high[c] ? y - m_high[c] : 0.;
      s += e * e;
    }
    return s;
  }

  bool m_active = false;
  std::vector<Target> m_targets;
  double m_rounding = 0.; // the largest rounding of a target's position
  double m_low[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity()};
  double m_high[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                      -std::numeric_limits<double>::infinity()};
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_DISTANCE_TO_GO_H
