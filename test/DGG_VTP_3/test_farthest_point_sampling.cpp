// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Adding sources to a field (prior_distance_map) and farthest-point sampling, which adds each
// sample to the field of those before: against whole fields of the exact mode from every sample.
// In the exact mode the samples are the greedy sequence; with an accuracy epsilon each sample's
// exact distance to those before is at least the largest one over 1 + epsilon, and the field, its
// labels and its lower bounds keep the contract of the field of all the samples.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>
#include <CGAL/DGG_VTP_3/Triangle_soup_geodesic_distance_solver.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace dggvtp_test;
namespace DP = CGAL::DGG_VTP_3::parameters;

namespace {

using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Epick>;
const double infinity = std::numeric_limits<double>::infinity();
// what an output holds before the call: a value the call does not write fails the checks (a
// distance or bound of 0, or the label 0 or the library's "none", -1, would pass some)
const double not_written = std::numeric_limits<double>::quiet_NaN();
const std::size_t label_not_written = std::size_t(-2);

Solver make_solver(const Soup& soup)
{
  std::vector<Epick::Point_3> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  return Solver(points, soup.faces);
}

std::vector<double> exact_field(const Solver& solver, std::size_t source)
{
  std::vector<double> d(solver.number_of_vertices());
  solver.compute_distances(source, CGAL::make_property_map(d));
  return d;
}

// what a sampling gives
struct Sampling
{
  std::vector<std::size_t> samples, labels;
  std::vector<double> distances, lower_bounds;
};

Sampling sample(const Solver& solver, std::size_t k, double epsilon, std::size_t first = 0)
{
  Sampling s;
  const std::size_t nv = solver.number_of_vertices();
  s.distances.assign(nv, not_written);
  s.lower_bounds.assign(nv, not_written);
  s.labels.assign(nv, label_not_written);
  solver.farthest_point_sampling(k, std::back_inserter(s.samples),
                                 DP::first_sample(first,
                                 DP::distance_map(CGAL::make_property_map(s.distances),
                                 DP::nearest_source_map(CGAL::make_property_map(s.labels),
                                 DP::lower_bound_map(CGAL::make_property_map(s.lower_bounds),
                                 CGAL::parameters::accuracy(epsilon))))));
  return s;
}

// the exact field of the samples so far (`fields[j]`: the exact field of sample j), and labels
struct Union
{
  std::vector<double> distance;
  std::vector<std::size_t> label;
};

Union exact_union(const std::vector<std::vector<double>>& fields, std::size_t count)
{
  Union u{std::vector<double>(fields[0].size(), infinity), std::vector<std::size_t>(fields[0].size(), 0)};
  for(std::size_t j = 0; j < count; ++j)
    for(std::size_t v = 0; v < u.distance.size(); ++v)
      if(fields[j][v] < u.distance[v])
        u.distance[v] = fields[j][v], u.label[v] = j;
  return u;
}

// the field, labels and lower bounds `s` gives for `count` samples keep the contract against the
// exact union
void check_field(const Sampling& s, const std::vector<std::vector<double>>& fields, double epsilon,
                 const std::string& what)
{
  const Union u = exact_union(fields, s.samples.size());
  const double slack = 1e-12;
  std::size_t wrong = 0, wrong_labels = 0, wrong_bounds = 0;
  for(std::size_t v = 0; v < u.distance.size(); ++v)
  {
    const double e = u.distance[v], d = s.distances[v];
    if(!(d >= e * (1 - slack) - 1e-300 && d <= e * (1 + epsilon) * (1 + slack) + 1e-300))
      ++wrong;
    if(!(s.labels[v] < s.samples.size() && fields[s.labels[v]][v] <= e * (1 + epsilon) * (1 + slack) + 1e-300))
      ++wrong_labels;
    if(!(s.lower_bounds[v] <= e * (1 + slack) && s.lower_bounds[v] >= 0.)) // NaN: never written
      ++wrong_bounds;
  }
  BOOST_TEST(wrong == 0u, what << ": " << wrong << " distances out of [exact, (1 + epsilon) exact] or not written");
  BOOST_TEST(wrong_labels == 0u, what << ": " << wrong_labels << " labels name no sample or one beyond (1 + epsilon) exact");
  BOOST_TEST(wrong_bounds == 0u, what << ": " << wrong_bounds << " lower bounds above the exact distance, negative or not written");
}

// every sample is the farthest (exactly: the greedy sequence; else within 1 + epsilon), and the
// field keeps the contract
void check_sampling(const std::string& name, std::size_t k, double epsilon)
{
  const Solver solver = make_solver(read_soup(name));
  const Sampling s = sample(solver, k, epsilon);
  BOOST_REQUIRE_EQUAL(s.samples.size(), k);
  BOOST_TEST(s.samples[0] == 0u);
  std::vector<std::vector<double>> fields;
  for(std::size_t i = 0; i < k; ++i)
  {
    fields.push_back(exact_field(solver, s.samples[i]));
    if(i + 1 == k)
      break;
    const Union u = exact_union(fields, i + 1);
    const std::size_t greedy = std::size_t(std::max_element(u.distance.begin(), u.distance.end()) - u.distance.begin());
    const std::string what = name + ", epsilon " + std::to_string(epsilon) + ", sample " + std::to_string(i + 1);
    if(epsilon == 0.)
      BOOST_TEST(s.samples[i + 1] == greedy, what << ": " << s.samples[i + 1] << ", the greedy sequence has " << greedy);
    else
      BOOST_TEST(u.distance[s.samples[i + 1]] * (1 + epsilon) * (1 + 1e-12) >= u.distance[greedy],
                 what << ": at " << u.distance[s.samples[i + 1]] << ", the farthest at " << u.distance[greedy]);
  }
  std::vector<std::size_t> sorted = s.samples;
  std::sort(sorted.begin(), sorted.end());
  BOOST_TEST((std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()), "a sample is taken twice");
  check_field(s, fields, epsilon, name + ", epsilon " + std::to_string(epsilon));
}

} // namespace

BOOST_AUTO_TEST_SUITE(farthest_point_sampling)

// pinion and spot have several patches: the samples' cells cross them
BOOST_AUTO_TEST_CASE(exact_samples_are_the_greedy_sequence)
{
  check_sampling("pinion.ply", 40, 0.);
  check_sampling("spot.ply", 40, 0.);
}

BOOST_AUTO_TEST_CASE(samples_with_an_accuracy_are_certified)
{
  for(double epsilon : {1., 1e-1, 1e-2})
    check_sampling("pinion.ply", 40, epsilon);
  for(double epsilon : {1., 1e-2})
  {
    check_sampling("lion_head.ply", 25, epsilon); // a border
    check_sampling("blade.ply", 25, epsilon);     // anisotropic
  }
}

// sources added to the field of others (prior_distance_map, its labels and lower bounds): the
// field of all of them, within the contract; in the exact mode the field of all the sources
BOOST_AUTO_TEST_CASE(sources_added_to_a_field)
{
  const Solver solver = make_solver(read_soup("spot.ply"));
  const std::size_t nv = solver.number_of_vertices();
  const std::vector<std::size_t> earlier{0, nv / 3}, later{nv / 2, nv - 1};
  std::vector<std::vector<double>> fields;
  for(std::size_t v : {earlier[0], earlier[1], later[0], later[1]})
    fields.push_back(exact_field(solver, v));
  for(double epsilon : {0., 1e-2, 5e-1})
  {
    Sampling prior;
    prior.distances.assign(nv, not_written), prior.lower_bounds.assign(nv, not_written);
    prior.labels.assign(nv, label_not_written);
    solver.compute_distances_to_nearest_source(earlier, CGAL::make_property_map(prior.distances),
                                               DP::nearest_source_map(CGAL::make_property_map(prior.labels),
                                               DP::lower_bound_map(CGAL::make_property_map(prior.lower_bounds),
                                               CGAL::parameters::accuracy(epsilon))));
    Sampling s;
    s.samples = {earlier[0], earlier[1], later[0], later[1]};
    s.distances.assign(nv, not_written), s.lower_bounds.assign(nv, not_written), s.labels.assign(nv, label_not_written);
    const auto stats = solver.compute_distances_to_nearest_source(
      later, CGAL::make_property_map(s.distances),
      DP::prior_distance_map(CGAL::make_property_map(prior.distances),
      DP::prior_nearest_source_map(CGAL::make_property_map(prior.labels),
      DP::prior_lower_bound_map(CGAL::make_property_map(prior.lower_bounds),
      DP::nearest_source_map(CGAL::make_property_map(s.labels),
      DP::lower_bound_map(CGAL::make_property_map(s.lower_bounds),
      CGAL::parameters::accuracy(epsilon)))))));
    check_field(s, fields, epsilon, "spot, two sources added to two, epsilon " + std::to_string(epsilon));
    BOOST_TEST(stats.vertices_reached < nv, "the propagation reached every vertex");
    // without the prior's labels and lower bounds: the same distances
    std::vector<double> d(nv);
    solver.compute_distances_to_nearest_source(later, CGAL::make_property_map(d),
                                               DP::prior_distance_map(CGAL::make_property_map(prior.distances),
                                               CGAL::parameters::accuracy(epsilon)));
    BOOST_TEST((d == s.distances));
  }
}

// unreachable vertices are the farthest: the next sample is the first vertex of a component not
// sampled yet
BOOST_AUTO_TEST_CASE(components_not_sampled_come_first)
{
  Soup soup = read_soup("pinion.ply");
  const std::size_t n = soup.points.size(), m = soup.faces.size();
  for(std::size_t i = 0; i < n; ++i)
    soup.points.push_back({soup.points[i][0] + 100., soup.points[i][1], soup.points[i][2]});
  for(std::size_t f = 0; f < m; ++f)
    soup.faces.push_back({soup.faces[f][0] + n, soup.faces[f][1] + n, soup.faces[f][2] + n});
  const Solver solver = make_solver(soup);
  const Sampling s = sample(solver, 5, 1e-2);
  BOOST_TEST(s.samples[0] == 0u);
  BOOST_TEST(s.samples[1] == n, "the second sample is " << s.samples[1] << ", not the first vertex of the other copy");
  BOOST_TEST((std::find_if(s.distances.begin(), s.distances.end(), [](double d) { return !std::isfinite(d); }) ==
              s.distances.end()));
  const Sampling one = sample(solver, 1, 0.);
  BOOST_TEST(one.distances[n] == infinity);
  BOOST_TEST(one.labels[n] == std::size_t(-1));
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused)
{
  const Solver solver = make_solver(read_soup("pinion.ply"));
  const std::size_t nv = solver.number_of_vertices();
  std::vector<std::size_t> out;
  const auto refused = [&](auto&& call, const std::string& part) {
    try
    {
      call();
      BOOST_ERROR("accepted; expected an error with '" << part << "'");
    }
    catch(const std::invalid_argument& e)
    {
      BOOST_TEST(std::string(e.what()).find(part) != std::string::npos, e.what());
    }
  };
  refused([&] { solver.farthest_point_sampling(0, std::back_inserter(out)); }, "number of samples");
  refused([&] { solver.farthest_point_sampling(nv + 1, std::back_inserter(out)); }, "number of samples");
  refused([&] { solver.farthest_point_sampling(2, std::back_inserter(out), DP::first_sample(nv)); }, "first sample");
  refused([&] { solver.farthest_point_sampling(2, std::back_inserter(out), CGAL::parameters::accuracy(-1.)); }, "accuracy");
  std::vector<double> d(nv, 1.), prior(nv, 1.), lower(nv, 0.5);
  std::vector<std::size_t> labels(nv, 0);
  const auto add = [&] {
    solver.compute_distances(std::size_t(0), CGAL::make_property_map(d),
                             DP::prior_distance_map(CGAL::make_property_map(prior),
                             DP::prior_nearest_source_map(CGAL::make_property_map(labels),
                             DP::prior_lower_bound_map(CGAL::make_property_map(lower)))));
  };
  prior[3] = std::nan("");
  refused(add, "prior distance of vertex 3");
  prior[3] = -1.;
  refused(add, "prior distance of vertex 3");
  prior[3] = 1.;
  lower[4] = 2.;
  refused(add, "prior lower bound of vertex 4");
  lower[4] = 0.5;
  labels[5] = std::size_t(-1);
  refused(add, "prior nearest source of vertex 5");
  BOOST_TEST(out.empty());
}

// the whole sampling at once (k = every vertex), then a cancelled one: the solver answers as before
BOOST_AUTO_TEST_CASE(every_vertex_and_cancel)
{
  const Solver solver = make_solver(read_soup("pinion.ply"));
  const std::size_t nv = solver.number_of_vertices();
  const Sampling all = sample(solver, nv, 1e-1, nv - 1);
  std::vector<std::size_t> sorted = all.samples;
  std::sort(sorted.begin(), sorted.end());
  for(std::size_t i = 0; i < nv; ++i)
    BOOST_REQUIRE_EQUAL(sorted[i], i);
  BOOST_TEST(all.samples[0] == nv - 1);
  BOOST_TEST(*std::max_element(all.distances.begin(), all.distances.end()) == 0.);
  const std::vector<double> before = exact_field(solver, 7);
  std::size_t calls = 0;
  std::vector<std::size_t> out;
  BOOST_CHECK_THROW(solver.farthest_point_sampling(50, std::back_inserter(out),
                                                   CGAL::parameters::callback([&](double) { return ++calls < 3; })),
                    CGAL::DGG_VTP_3::Propagation_cancelled);
  BOOST_TEST(calls == 3u);
  BOOST_TEST((exact_field(solver, 7) == before));
  BOOST_TEST((sample(solver, 20, 0.).samples == sample(make_solver(read_soup("pinion.ply")), 20, 0.).samples));
}

BOOST_AUTO_TEST_SUITE_END()
