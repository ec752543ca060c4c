// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The named parameter callback (issue 30): progress that changes nothing in the results, and a
// cancellation that leaves the solver as it was. Nothing here depends on the clock: the first
// call comes after the first round, whatever the machine's speed.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>

#include <chrono>
#include <functional>
#include <thread>
#include <vector>

using namespace dggvtp_test;

namespace {

using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;

Mesh bunny() { return make_mesh<Mesh>(read_soup("bunny.ply")); }

// the distances from vertex `source` with the named parameters `np`
template <class ConcurrencyTag = CGAL::Sequential_tag, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<double> distances(const Solver& solver, const Mesh& mesh, std::size_t source,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  solver.compute_distances<ConcurrencyTag>(vertex_list(mesh).at(source), map, np);
  return to_vector(mesh, map);
}

} // namespace

BOOST_AUTO_TEST_SUITE(progress)

BOOST_AUTO_TEST_CASE(callback_sees_growing_fractions_and_changes_nothing)
{
  const Mesh mesh = bunny();
  const Solver solver(mesh);
  for(double accuracy : {0., 1e-4})
  {
    const auto np = CGAL::parameters::accuracy(accuracy);
    const std::vector<double> reference = distances(solver, mesh, 7, np);
    std::vector<double> fractions;
    const std::function<bool(double)> record = [&](double f) {
      fractions.push_back(f);
      return true;
    };
    BOOST_CHECK(distances(solver, mesh, 7, CGAL::parameters::callback(record).accuracy(accuracy)) == reference);
    BOOST_REQUIRE(!fractions.empty());
    for(std::size_t k = 0; k < fractions.size(); ++k)
    {
      BOOST_CHECK(fractions[k] >= 0. && fractions[k] <= 1.);
      if(k > 0)
        BOOST_CHECK(fractions[k] >= fractions[k - 1]);
    }
  }
}

BOOST_AUTO_TEST_CASE(cancel_throws_and_the_solver_stays_usable)
{
  const Mesh mesh = bunny();
  const Solver solver(mesh);
  const std::vector<double> reference = distances(solver, mesh, 11);
  std::size_t calls = 0;
  const std::function<bool(double)> cancel = [&](double) {
    ++calls;
    return false;
  };
  BOOST_CHECK_THROW(distances(solver, mesh, 11, CGAL::parameters::callback(cancel)), CGAL::DGG_VTP_3::Propagation_cancelled);
  BOOST_CHECK_EQUAL(calls, 1u);
  BOOST_CHECK_THROW(distances<CGAL::Parallel_if_available_tag>(solver, mesh, 11, CGAL::parameters::callback(cancel)),
                    CGAL::DGG_VTP_3::Propagation_cancelled);
  BOOST_CHECK_THROW(solver.compute_shortest_path_tree(std::vector<Mesh::Vertex_index>(1, vertex_list(mesh).at(11)),
                                                      CGAL::parameters::callback(cancel)),
                    CGAL::DGG_VTP_3::Propagation_cancelled);
  // the next queries on the same solver: the same bytes as before the cancellations
  BOOST_CHECK(distances(solver, mesh, 11) == reference);
  BOOST_CHECK(distances<CGAL::Parallel_if_available_tag>(solver, mesh, 11) == reference);
  // cancelling later, at the third call: each call outlasts the 0.1 s between calls, so that the
  // round after it calls again, on any machine (bunny's field takes hundreds of rounds)
  calls = 0;
  const std::function<bool(double)> cancel_third = [&](double) {
    std::this_thread::sleep_for(std::chrono::milliseconds(110));
    return ++calls < 3;
  };
  BOOST_CHECK_THROW(distances(solver, mesh, 11, CGAL::parameters::callback(cancel_third)),
                    CGAL::DGG_VTP_3::Propagation_cancelled);
  BOOST_CHECK_EQUAL(calls, 3u);
  BOOST_CHECK(distances(solver, mesh, 11) == reference);
}

BOOST_AUTO_TEST_SUITE_END()
