// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Float against double, exact mode, on every bundled mesh. SMSP is too slow to be the reference
// on the larger ones, and the double exact mode agrees with it to 1e-14 where it runs. Float is
// where rounding decisions in the pruning matter: a pair of windows judged "tied" within float
// rounding once lost the cone behind the trimmed one, leaving unreachable vertices on bunny.

#include "test_utilities.h"

using namespace dggvtp_test;

namespace {

template <class Config>
void check_against_double(const std::string& file)
{
  const Soup soup = read_soup(file);
  const typename Sm_d::Mesh reference = make_mesh<typename Sm_d::Mesh>(soup);
  const typename Config::Mesh mesh = make_mesh<typename Config::Mesh>(soup);
  const std::size_t n = num_vertices(mesh);
  for(std::size_t s : {std::size_t(0), n / 3, 2 * n / 3})
  {
    const std::vector<double> truth = geodesic_distances(reference, s);
    CGAL::DGG_VTP_3::Propagation_statistics statistics;
    const std::vector<double> d = geodesic_distances(mesh, s, &statistics);
    check_distances(d, truth, s, Config::tolerance, file + " " + config_name<Config>() + ", source " + std::to_string(s));
    BOOST_TEST(statistics.vertices_reached == num_vertices(mesh));
  }
}

} // namespace

BOOST_AUTO_TEST_SUITE(float_against_double)

BOOST_AUTO_TEST_CASE_TEMPLATE(bunny, Config, Float_configurations)
{
  check_against_double<Config>("bunny.ply");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(blade, Config, Float_configurations)
{
  check_against_double<Config>("blade.ply");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(turbine, Config, Float_configurations)
{
  check_against_double<Config>("turbine.ply");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(lion_head, Config, Float_configurations)
{
  check_against_double<Config>("lion_head.ply");
}

BOOST_AUTO_TEST_SUITE_END()
