// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// The triangle-soup solver: points and triangles as plain arrays, as a file reader or another
// language hands them over, without building a CGAL mesh. Vertices are indices into the array of
// points, and the distances go into a std::vector through a property map. Here the soup is a flat
// grid, where the geodesic distance is the straight-line one: the answer is known. The grid is
// regular, so that lines from the source run exactly through vertices, a case the exact mode
// must get right (it keeps windows that tie there; test: regular_grid).

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

int main()
{
  // a 21 x 21 grid of points in the plane z = 0, two triangles per square, as flat arrays
  const int n = 21;
  const double h = 1. / (n - 1);
  std::vector<std::array<double, 3>> coordinates;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      coordinates.push_back({i * h, j * h, 0.});
  std::vector<std::array<int, 3>> triangles;
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
    {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }

  // the coordinates are read through a point map: no copy into CGAL points
  const auto as_point = [](const std::array<double, 3>& p) { return Kernel::Point_3(p[0], p[1], p[2]); };
  const CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel> solver(
    coordinates, triangles, CGAL::parameters::point_map(boost::make_function_property_map<std::array<double, 3>>(as_point)));

  std::vector<double> distances(coordinates.size());
  const std::size_t source = (n / 2) * n + n / 2; // near the centre
  solver.compute_distances(source, CGAL::make_property_map(distances));

  double largest = 0.;
  for(std::size_t v = 0; v < coordinates.size(); ++v)
  {
    const double straight = std::hypot(coordinates[v][0] - coordinates[source][0], coordinates[v][1] - coordinates[source][1]);
    largest = (std::max)(largest, std::abs(distances[v] - straight));
  }
  std::cout << coordinates.size() << " points, " << triangles.size() << " triangles; distance to the corner (0, 0) "
            << distances[0] << "; largest difference from the straight-line distance " << largest << std::endl;
  return largest <= 1e-12 ? EXIT_SUCCESS : EXIT_FAILURE;
}
