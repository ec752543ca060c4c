// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// A solver keeps the working state of its queries (per vertex, face and halfedge) from one query
// to the next and resets only what the previous query touched (issue 42). Every query must then
// give the bits, and the counts, of the same query on a fresh solver, whatever came before it: a
// larger query, an early-terminated one (windows left in the lists), a cancelled one, another
// accuracy, point sources, labels; and from many threads sharing one solver. A solver assigned
// another answers as that one, and a shortest path tree outlives its solver.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>
#include <CGAL/tags.h>

#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

using namespace dggvtp_test;
namespace DP = CGAL::DGG_VTP_3::parameters;

namespace {

using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
using V = Mesh::Vertex_index;

// what a query gives: its field (bits), its labels, its targets' distances, its counts
struct Answer
{
  std::vector<double> field;
  std::vector<std::size_t> labels;
  std::vector<double> targets;
  CGAL::DGG_VTP_3::Propagation_statistics statistics;
};

// the same bits, not merely the same values (memcmp is not given the null data of an empty vector)
bool same_bits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

bool same(const Answer& a, const Answer& b)
{
  return same_bits(a.field, b.field) && a.labels == b.labels && same_bits(a.targets, b.targets) &&
         a.statistics.windows_created == b.statistics.windows_created &&
         a.statistics.vertices_popped == b.statistics.vertices_popped &&
         a.statistics.pseudo_sources == b.statistics.pseudo_sources &&
         a.statistics.vertices_reached == b.statistics.vertices_reached &&
         a.statistics.windows_peak == b.statistics.windows_peak;
}

// one query of each kind the solver answers, on `solver`
using Query = std::function<Answer(const Solver&)>;

std::vector<std::pair<std::string, Query>> queries(const Mesh& mesh)
{
  const std::vector<V> all = vertex_list(mesh);
  const V a = all[0], b = all[all.size() / 3], c = all[2 * all.size() / 3];
  const auto field_of = [&mesh](const Solver& solver, const std::vector<V>& sources, const auto& np, bool labels) {
    Answer r;
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto label = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
    if(labels)
      r.statistics = solver.compute_distances_to_nearest_source(sources, map, DP::nearest_source_map(label, np));
    else
      r.statistics = solver.compute_distances_to_nearest_source(sources, map, np);
    r.field = to_vector(mesh, map);
    if(labels)
      for(V v : vertices(mesh))
        r.labels.push_back(get(label, v));
    return r;
  };
  const double diagonal = 1.; // the meshes below are about that size; the radii only need to vary
  std::vector<std::pair<std::string, Query>> q;
  q.emplace_back("exact, whole field", [=](const Solver& s) { return field_of(s, {a}, DP::accuracy(0.), false); });
  q.emplace_back("1e-1, within a small radius",
                 [=](const Solver& s) { return field_of(s, {b}, DP::max_distance(0.02 * diagonal, DP::accuracy(0.1)), false); });
  q.emplace_back("1e-3, two sources, labels",
                 [=](const Solver& s) { return field_of(s, {b, c}, DP::accuracy(1e-3), true); });
  q.emplace_back("exact, within a radius", [=](const Solver& s) { return field_of(s, {c}, DP::max_distance(0.1 * diagonal), false); });
  q.emplace_back("1e-2, a target (early termination)", [=, &mesh](const Solver& s) {
    Answer r;
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    const std::vector<V> targets{b};
    r.statistics = s.compute_distances(
      a, map, DP::target_distances(std::back_inserter(r.targets), DP::targets(targets, DP::accuracy(1e-2))));
    return r;
  });
  q.emplace_back("exact, a point source", [=, &mesh](const Solver& s) {
    Answer r;
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    const Mesh::Face_index f = *faces(mesh).begin();
    r.statistics = s.compute_distances_to_nearest_source(
      std::vector<Solver::Face_location>{{f, {{0.2, 0.3, 0.5}}}}, map, CGAL::parameters::default_values());
    r.field = to_vector(mesh, map);
    return r;
  });
  q.emplace_back("1e-5, whole field", [=](const Solver& s) { return field_of(s, {c}, DP::accuracy(1e-5), false); });
  // one propagation on TBB's threads (where linked with TBB): its patches record what they touch
  // from several threads at once
  q.emplace_back("1e-4, whole field, Parallel_if_available_tag", [=, &mesh](const Solver& s) {
    Answer r;
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    r.statistics = s.compute_distances<CGAL::Parallel_if_available_tag>(a, map, DP::accuracy(1e-4));
    r.field = to_vector(mesh, map);
    return r;
  });
  q.emplace_back("exact, within a radius, Parallel_if_available_tag", [=, &mesh](const Solver& s) {
    Answer r;
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    r.statistics = s.compute_distances<CGAL::Parallel_if_available_tag>(b, map, DP::max_distance(0.3 * diagonal));
    r.field = to_vector(mesh, map);
    return r;
  });
  return q;
}

// the answers of fresh solvers (a copy of a solver shares its kept state: not fresh)
std::vector<Answer> fresh_answers(const Mesh& mesh, const std::vector<std::pair<std::string, Query>>& q)
{
  std::vector<Answer> answers;
  for(const auto& query : q)
    answers.push_back(query.second(Solver(mesh)));
  return answers;
}

// every query on `solver` gives the answer of a fresh solver of `mesh`
void check_fresh(const Solver& solver, const Mesh& mesh, const std::vector<Answer>& fresh, const std::string& what)
{
  const auto q = queries(mesh);
  for(std::size_t j = 0; j < q.size(); ++j)
    BOOST_TEST(same(q[j].second(solver), fresh[j]), what << ": '" << q[j].first << "'");
}

// `count` threads share `solver`, each running every query in its own order 3 times, and
// `before(t, i)` before its i-th query: every answer is the fresh one
void check_on_threads(const Solver& solver, const std::vector<std::pair<std::string, Query>>& q,
                      const std::vector<Answer>& fresh, std::size_t count,
                      const std::function<void(std::size_t, std::size_t)>& before)
{
  std::vector<std::size_t> wrong(count, 0);
  std::vector<std::thread> threads;
  for(std::size_t t = 0; t < count; ++t)
    threads.emplace_back([&, t] {
      for(std::size_t i = 0; i < 3 * q.size(); ++i)
      {
        before(t, i);
        const std::size_t j = (i % q.size() * (t + 1) + i / q.size()) % q.size();
        if(!same(q[j].second(solver), fresh[j]))
          ++wrong[t];
      }
    });
  for(std::thread& t : threads)
    t.join();
  for(std::size_t t = 0; t < count; ++t)
    BOOST_TEST(wrong[t] == 0u, "thread " << t << ": " << wrong[t] << " answers differ from a fresh solver's");
}

} // namespace

BOOST_AUTO_TEST_SUITE(query_reuse)

// every query after every other one (a 9 x 9 sequence on one solver, then backwards) gives the
// fresh solver's answer; pinion and spot have several patches (rounds across them)
BOOST_AUTO_TEST_CASE(a_query_after_another_gives_the_fresh_answer)
{
  for(const char* name : {"pinion.ply", "spot.ply"})
  {
    const Mesh mesh = make_mesh<Mesh>(read_soup(name));
    const Solver solver(mesh);
    const auto q = queries(mesh);
    const std::vector<Answer> fresh = fresh_answers(mesh, q);
    for(std::size_t i = 0; i < q.size(); ++i)
      for(std::size_t j = 0; j < q.size(); ++j)
      {
        q[i].second(solver);
        BOOST_TEST(same(q[j].second(solver), fresh[j]), name << ": '" << q[j].first << "' after '" << q[i].first << "'");
      }
    for(std::size_t j = q.size(); j-- > 0;)
      BOOST_TEST(same(q[j].second(solver), fresh[j]), name << ": '" << q[j].first << "' backwards");
  }
}

// a query cancelled by its callback (at its first call, after the first round: later calls
// depend on the clock) leaves the solver as it was, at every accuracy
BOOST_AUTO_TEST_CASE(a_cancelled_query_leaves_no_state)
{
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const Solver solver(mesh);
  const auto q = queries(mesh);
  const std::vector<Answer> fresh = fresh_answers(mesh, q);
  for(double accuracy : {0., 1e-1})
  {
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    BOOST_CHECK_THROW(solver.compute_distances(*vertices(mesh).begin(), map,
                                               DP::callback([](double) { return false; }).accuracy(accuracy)),
                      CGAL::DGG_VTP_3::Propagation_cancelled);
    for(std::size_t j = 0; j < q.size(); ++j)
      BOOST_TEST(same(q[j].second(solver), fresh[j]), "'" << q[j].first << "' after a cancelled query at " << accuracy);
  }
}

// four threads (more than the cores: they interleave) share one solver, each running every query
// in its own order, many times
BOOST_AUTO_TEST_CASE(threads_sharing_one_solver)
{
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const Solver solver(mesh);
  const auto q = queries(mesh);
  const std::vector<Answer> fresh = fresh_answers(mesh, q);
  check_on_threads(solver, q, fresh, 4, [](std::size_t, std::size_t) {});
}

// A solver assigned another (a larger mesh, then a smaller one), by copy or by move, answers as a
// fresh solver of that mesh: the propagations it kept were made for its former mesh. A copy and
// a solver moved from answer too.
BOOST_AUTO_TEST_CASE(assigned_and_moved_solvers_answer_as_fresh_ones)
{
  const Mesh pinion = make_mesh<Mesh>(read_soup("pinion.ply")), spot = make_mesh<Mesh>(read_soup("spot.ply"));
  const std::vector<Answer> fresh_pinion = fresh_answers(pinion, queries(pinion)),
                            fresh_spot = fresh_answers(spot, queries(spot));
  Solver solver(pinion);
  check_fresh(solver, pinion, fresh_pinion, "pinion");
  solver = Solver(spot); // move assignment
  check_fresh(solver, spot, fresh_spot, "pinion assigned a moved spot solver");
  Solver other(pinion);
  check_fresh(other, pinion, fresh_pinion, "another pinion solver");
  solver = other; // copy assignment, to a smaller mesh
  check_fresh(solver, pinion, fresh_pinion, "spot assigned a pinion solver");
  other = Solver(spot);
  check_fresh(solver, pinion, fresh_pinion, "the copy, once the original is assigned spot");
  const Solver moved(std::move(other));
  check_fresh(moved, spot, fresh_spot, "a solver moved from another");
  check_fresh(other, spot, fresh_spot, "the solver moved from"); // NOLINT(bugprone-use-after-move): it stays usable
  const Solver copy(moved);
  check_fresh(copy, spot, fresh_spot, "a copy");
}

// a shortest path tree keeps what it needs of its solver: it outlives it, and it stays the same
// when the solver is assigned another
BOOST_AUTO_TEST_CASE(a_shortest_path_tree_outlives_its_solver)
{
  const Mesh spot = make_mesh<Mesh>(read_soup("spot.ply")), pinion = make_mesh<Mesh>(read_soup("pinion.ply"));
  const std::vector<V> all = vertex_list(spot);
  const auto path_of = [&](const auto& tree) {
    std::vector<double> path;
    using Point = typename std::decay_t<decltype(tree)>::Path_point;
    std::vector<Point> points;
    tree.shortest_path(all[2000], std::back_inserter(points));
    for(const Point& p : points)
      path.insert(path.end(), p.location.second.begin(), p.location.second.end());
    path.push_back(tree.distance(all[2000]));
    return path;
  };
  const std::vector<double> expected = path_of(Solver(spot).compute_shortest_path_tree(std::vector<V>{all[5]}));
  BOOST_TEST(expected.size() > 4u);
  Solver solver(spot);
  const auto tree = solver.compute_shortest_path_tree(std::vector<V>{all[5]});
  solver = Solver(pinion);
  BOOST_TEST(same_bits(path_of(tree), expected), "the solver assigned another mesh");
  const auto orphan = [&] { return Solver(spot).compute_shortest_path_tree(std::vector<V>{all[5]}); }();
  BOOST_TEST(same_bits(path_of(orphan), expected), "the solver destroyed");
}

// release_query_memory() while threads query the solver: they go on, with the fresh answers
BOOST_AUTO_TEST_CASE(releasing_the_memory_while_threads_query)
{
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const Solver solver(mesh);
  const auto q = queries(mesh);
  const std::vector<Answer> fresh = fresh_answers(mesh, q);
  check_on_threads(solver, q, fresh, 3, [&solver](std::size_t t, std::size_t i) {
    if(t == 0 && i % 3 == 0)
      solver.release_query_memory();
  });
  solver.release_query_memory();
  check_fresh(solver, mesh, fresh, "after the memory is released");
}

BOOST_AUTO_TEST_SUITE_END()
