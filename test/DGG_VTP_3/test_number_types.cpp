// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Number types other than float and double (issue 19): what the propagation asks of them, and
// DGG-VTP against the exact mode in CGAL::Gmpfr. The analytic suite and other_component_is_infinite
// also run Sm_ld and Sm_mpfr.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

using namespace dggvtp_test;

namespace {

// The default precision of CGAL::Gmpfr is per thread and global: set once for the module, so that
// Sm_mpfr means the same in every test case.
struct Gmpfr_default_precision
{
  Gmpfr_default_precision() { CGAL::Gmpfr::set_default_precision(Sm_mpfr::precision); }
};

} // namespace

BOOST_TEST_GLOBAL_FIXTURE(Gmpfr_default_precision);

BOOST_AUTO_TEST_SUITE(number_types)

// std::numeric_limits is not specialised for CGAL::Gmpfr: its infinity() and epsilon() are a
// default-constructed Gmpfr (NaN), which is what the propagation used before issue 19.
BOOST_AUTO_TEST_CASE(gmpfr_infinity_and_machine_epsilon)
{
  using Math = CGAL::DGG_VTP_3::internal::Number_type_math<CGAL::Gmpfr>;
  const CGAL::Gmpfr inf = Math::infinity();
  BOOST_TEST(inf.is_inf());
  BOOST_TEST(inf > CGAL::Gmpfr(0));
  BOOST_TEST(CGAL::to_double(inf) == std::numeric_limits<double>::infinity());
  // 2^(1 - 150)
  BOOST_TEST(Math::machine_epsilon() == CGAL::Gmpfr(std::ldexp(1., 1 - int(Sm_mpfr::precision))));
  BOOST_TEST(CGAL::Gmpfr(1) + Math::machine_epsilon() > CGAL::Gmpfr(1));
}

BOOST_AUTO_TEST_CASE(gmpfr_functions_match_double)
{
  using Math = CGAL::DGG_VTP_3::internal::Number_type_math<CGAL::Gmpfr>;
  const CGAL::Gmpfr x(-0.75), y(2.5);
  BOOST_TEST(CGAL::to_double(Math::abs(x)) == 0.75);
  BOOST_TEST(CGAL::to_double(Math::sqrt(y)) == std::sqrt(2.5));
}

// DGG-VTP keeps its accuracy promise when computed in CGAL::Gmpfr, against the exact mode in
// CGAL::Gmpfr; and the exact mode in CGAL::Gmpfr agrees with the exact mode in double.
BOOST_AUTO_TEST_CASE(gmpfr_dgg_vtp_within_epsilon_of_exact)
{
  const Soup soup = read_soup("pinion.ply");
  const auto mesh = make_mesh<Sm_mpfr::Mesh>(soup);
  const double epsilon = 1e-4;
  const std::vector<double> exact = geodesic_distances(mesh, 0);
  const std::vector<double> dgg = geodesic_distances(mesh, 0, nullptr, CGAL::parameters::accuracy(epsilon));
  check_distances(dgg, exact, 0, epsilon, "pinion Sm_mpfr, DGG-VTP 1e-4 against exact");
  const std::vector<double> in_double = geodesic_distances(make_mesh<Sm_d::Mesh>(soup), 0);
  check_distances(in_double, exact, 0, Sm_d::tolerance, "pinion, exact in Sm_d against exact in Sm_mpfr");
}

// The propagation computes at the default precision the user set, not at the 256 or 512 bits
// of CGAL::Gmpfr's constructors from int and double (the input points are made from doubles):
// every distance comes out at that precision, within its rounding of the 150-bit run.
BOOST_AUTO_TEST_CASE(gmpfr_computes_at_the_default_precision)
{
  const Soup soup = read_soup("spot.ply");
  const std::vector<double> reference = geodesic_distances(make_mesh<Sm_mpfr::Mesh>(soup), 0);
  for(long bits : {64L, 100L})
  {
    CGAL::Gmpfr::set_default_precision(bits);
    const auto mesh = make_mesh<Sm_mpfr::Mesh>(soup);
    auto map = get(CGAL::dynamic_vertex_property_t<CGAL::Gmpfr>(), mesh);
    CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, *vertices(mesh).begin());
    std::size_t other_precision = 0;
    std::vector<double> d;
    for(auto v : vertices(mesh))
    {
      other_precision += (get(map, v).get_precision() != bits);
      d.push_back(CGAL::to_double(get(map, v)));
    }
    CGAL::Gmpfr::set_default_precision(Sm_mpfr::precision);
    BOOST_TEST(other_precision == 0u, other_precision << " distances not at " << bits << " bits");
    check_distances(d, reference, 0, 1e-15, "spot at " + std::to_string(bits) + " bits against 150 bits");
  }
}

BOOST_AUTO_TEST_SUITE_END()
