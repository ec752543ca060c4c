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

#ifndef CGAL_DGG_VTP_3_INTERNAL_WINDOW_PROPAGATION_H
#define CGAL_DGG_VTP_3_INTERNAL_WINDOW_PROPAGATION_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>
#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/internal/Distance_bound.h>
#include <CGAL/DGG_VTP_3/internal/Distance_to_go.h>
#include <CGAL/DGG_VTP_3/internal/Index_set.h>
#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/Point_targets.h>
#include <CGAL/DGG_VTP_3/internal/Progress_report.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_patch.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_vertices.h>
#include <CGAL/DGG_VTP_3/internal/Pseudo_source_emission.h>
#include <CGAL/DGG_VTP_3/internal/Round_scheduler.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_copies.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_directions.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/Window_construction.h>
#include <CGAL/DGG_VTP_3/internal/Window_lists.h>
#include <CGAL/DGG_VTP_3/internal/Window_pruning.h>
#include <CGAL/DGG_VTP_3/internal/early_termination.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// One propagation from a set of sources (paper, Algorithm 1) over an Unfolded_mesh: the scratch of
// the solvers' const queries, kept between queries (Propagation_pool). run() first undoes what the
// last run touched (vertices, faces, lists, patches): a query costs what it reaches, not the mesh.
//
// Windows sit in per-halfedge window lists; a vertex-oriented priority queue pops the nearest
// vertex, which may emit windows as a pseudo-source (see Pseudo_source_emission) and brings its
// faces into the propagation region R; then the window lists inside R are propagated in FIFO
// order until every window has left R (into every sheet of an edge of copies: Vertex_copies.h).
// Pruning is by the distance bound, the ICH rule, "one angle, two sides" and pairwise trimming
// (see Window_pruning), all of them on keys (see Window and Tuning::key_ratio). With accuracy 0
// this is the exact VTP algorithm: keys are distances, only saddle and singular vertices are
// pseudo-sources and windows travel without bound. DGG-VTP adds the distance bound, and the
// relay vertices of the windows it stops as pseudo-sources (see Pseudo_source_states).
// It runs on one patch of faces at a time (Patch_partition), in rounds that a Round_scheduler
// drives; what it does to another patch's part of the mesh goes through the scheduler's hand_off().
// `direct_only`: the run is the certified geodesic graph's build rule, which changes who emits and
// when the run ends (see Direct_distances, Geodesic_graph_build.h); ordinary queries never
// instantiate it, and none of it is on their path.
template <class FT, bool direct_only = false>
class Window_propagation
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;
  using Win = Window<FT>;
  using Scheduler = Round_scheduler<FT>;
  using T = Tuning<FT>;
  using Stops = typename Key_ratio<FT>::Stops;
  friend Scheduler;

public:
  Window_propagation(const Mesh& mesh, const Patch_partition<FT>& partition)
    : m_mesh(mesh)
    , m_partition(partition)
    , m_scheduler(partition, mesh.number_of_vertices())
    , m_keys(number<FT>(0), mesh.number_of_vertices())
    , m_emission(mesh, m_keys)
    , m_vertices(mesh, partition)
    , m_in_region(mesh.number_of_faces(), partition.size())
    , m_scheduled(mesh.number_of_halfedges(), 0)
    , m_window_limit(window_limit(mesh))
  {
    for(Index k = 0; k < partition.size(); ++k)
      m_patches.emplace_back(k, partition.first_face(k), partition.end_face(k, mesh.number_of_faces()));
  }

  static FT infinity() { return Number_type_math<FT>::infinity(); }

  // The distance to the nearest of the sources: they all start at 0, with their copies (relax()
  // relays every later distance to a vertex's copies), and emit all around (lines 1-8), as far as
  // the query needs. `accuracy` is the user's epsilon: 0 for the exact algorithm.
  template <class ConcurrencyTag>
  void run(const Propagation_query<FT>& query, FT accuracy)
  {
    reset(query, accuracy);
    m_query = &query;
    const Index nv = Index(m_vertices.distance.size());
    for(std::size_t k = 0; k < query.vertex_sources.size(); ++k)
    {
      const Index s = query.vertex_sources[k];
      m_vertices.set_source(s, query.source_numbers[k]);
      m_scheduler.commit(s, number<FT>(0));
      m_scheduler.wake(m_partition.owner(s));
      m_patches[m_partition.owner(s)].queue.push(Queue_entry(order(s), s));
      Emission_out out{*this, m_patches[m_partition.owner(s)]};
      m_emission.to_copies(s, number<FT>(0), number<FT>(0), out);
    }
    m_targets = Point_targets<FT>(m_mesh, query.point_targets);
    const auto out_in_face = [this](Index f) {
      m_scheduler.wake(m_partition.patch_of_face(f));
      return Emission_out{*this, m_patches[m_partition.patch_of_face(f)]};
    };
    for(std::size_t k = 0; k < query.point_sources.size(); ++k)
      m_emission.from_surface_point(query.point_sources[k], nv + query.source_numbers[query.vertex_sources.size() + k],
                                    out_in_face);
    m_scheduler.template deliver_now<ConcurrencyTag>(*this);
    m_scheduler.template run<ConcurrencyTag>(*this, m_stats.windows_peak);
    for(Index k : m_scheduler.woken())
      m_patches[k].add_statistics(m_stats);
    m_targets.finish(m_mesh, m_vertices.distance, query);
    m_stats.vertices_reached = m_vertices.finish(query.max_distance, m_pending_keys, query.vertex_targets, m_pending_at_targets);
    m_reusable = !query.add_to_field;
  }

  // whether the last run() ended normally from nothing: one that threw (a cancelled query, a refused
  // mesh) may have left messages between patches, and one that added to a field left it behind
  bool reusable() const { return m_reusable; }

  // per vertex, when recorded: the pseudo-source of its path, where its path arrives from
  using Arrival = typename Propagation_vertices<FT>::Arrival;
  const std::vector<Index>& origins() const { return m_vertices.origins(); }
  const std::vector<Arrival>& arrivals() const { return m_vertices.arrivals(); }
  static Index no_origin() { return Propagation_vertices<FT>::no_origin(); }
  const Point_targets<FT>& point_targets() const { return m_targets; } // how their paths arrive

  const std::vector<FT>& distances() const { return m_vertices.distance; }
  // in a direct-only run, per vertex the weight of its edge from the source (see Direct_distances)
  const std::vector<FT>& direct_distances() const { return m_vertices.direct.all(); }
  // per vertex, a lower bound of its exact distance (see Propagation_vertices::finish)
  const std::vector<FT>& lower_bounds() const { return m_vertices.least_key; }
  // the vertices the run gave a distance (+infinity beyond max_distance); the others are as before
  const std::vector<Index>& reached() const { return m_vertices.reached(); }
  const Propagation_statistics& statistics() const { return m_stats; }

private:
  using Patch = Propagation_patch<FT>;
  using Queue_entry = typename Patch::Queue_entry;

  // the state of a new propagation, in the time of what the last one touched
  void reset(const Propagation_query<FT>& query, FT accuracy)
  {
    m_reusable = false;
    m_keys = Key_ratio<FT>(accuracy, m_mesh.number_of_vertices(), // see keep_field() and Direct_distances
                           query.add_to_field ? Stops::never : direct_only ? Stops::always : Stops::where_they_pay);
    m_emission.set_keys(m_keys);
    for(Index k : m_scheduler.woken())
      m_patches[k].clear(m_scheduled);
    m_scheduler.reset(m_vertices.reached());
    m_vertices.start(m_keys, query);
    if(query.add_to_field)
      m_scheduler.commit_borders(m_vertices.distance); // the other patches read the prior field
    m_in_region.clear();
    m_stats = Propagation_statistics();
    m_progress.reset();
    m_targets = Point_targets<FT>();
    m_to_go = !query.toward_targets || (query.vertex_targets.empty() && query.point_targets.empty())
                ? Distance_to_go<FT>()
                : Distance_to_go<FT>(m_mesh, query.vertex_targets, query.point_targets);
  }

  // A vertex's place in the queues: its distance, plus the lower bound of the distance still to go
  // to the targets of a query that searches toward them (see Distance_to_go). A queue
  // entry whose order is above this is superseded.
  FT order(Index v) const
  {
    return m_to_go.active() ? m_vertices.distance[v] + m_to_go.at(m_mesh, v) : m_vertices.distance[v];
  }

  // ---------------------------------------------------------------------------------------------
  // what the scheduler asks of a patch (see Round_scheduler)

  FT nearest_queued(Index k)
  {
    auto& queue = m_patches[k].queue;
    while(!queue.empty() && queue.top().first > order(queue.top().second))
      queue.pop(); // superseded by a later, shorter distance
    return queue.empty() ? infinity() : queue.top().first;
  }

  bool has_lists_to_propagate(Index k) const { return !m_patches[k].fifo.empty(); }

  // whether every distance the query needs is final (see early_termination.h); `nearest`: the
  // first queued vertex of all patches, by order(). Its limit serves the round's pop_limit() too.
  bool query_is_answered(FT nearest)
  {
    m_limit = early_termination_limit(*m_query, m_targets, m_mesh, m_vertices.distance);
    const auto to_go = [this](const Patch& p, Index h, const Win& w) {
      return m_to_go.on_edge(m_mesh, p.first_halfedge + h, w.b0, w.b1);
    };
    const bool answered =
      direct_run_done() || nothing_pending_below(m_limit, nearest, m_keys, m_patches, m_scheduler.woken(), to_go);
    // the work left pending gives the targets keys above the limit's, but only them if the search
    // went toward them
    m_pending_at_targets = answered ? least_key_left(m_limit, m_keys) : infinity();
    m_pending_keys = !answered || !m_to_go.active()
                       ? m_pending_at_targets
                       : (std::min)(m_pending_at_targets,
                                    least_pending_key(m_keys, m_patches, m_scheduler.woken(), m_vertices.distance));
    return answered;
  }

  // how far the rounds need to pop for what the query asks (see pop_limit())
  FT pop_limit() const { return internal::pop_limit(m_limit, m_keys); }

  // lines 9-29 in one patch, for the vertices nearer than `limit`
  void run_round(Index k, FT limit)
  {
    Patch& p = m_patches[k];
    propagate_scheduled_lists(p);
    while(!p.queue.empty() && p.queue.top().first <= limit && !direct_run_done())
    {
      const Queue_entry top = p.queue.top();
      p.queue.pop();
      const Index v = top.second;
      if(top.first > order(v))
        continue; // superseded by a later, shorter distance
      ++p.stats.vertices_popped;
      Emission_out out{*this, p}; // lines 10-13: v as a pseudo-source
      if(is_dgg() ? m_vertices.pseudo_sources.pop(v) || m_vertices.is_source[v] : m_vertices.is_source[v] || m_mesh.is_singular(v))
        m_emission.all_around(v, m_vertices.emission_distance(v), out);
      else if(!is_dgg() && m_mesh.is_exact_pseudo_source(v))
        m_emission.in_shadow(v, m_vertices.distance[v], m_vertices.incoming[v], out);
      enter_propagation_region(p, v);
      propagate_scheduled_lists(p);
    }
    p.lists.release_if_empty();
  }

  std::size_t take_peak(Index k) { return m_patches[k].take_peak(); }

  // after the first round, then at most every 0.1 s (see Progress_report)
  void report_progress()
  {
    m_progress(m_query->progress, [this] {
      std::size_t popped = 0;
      for(Index k : m_scheduler.woken())
        popped += m_patches[k].stats.vertices_popped;
      return popped;
    }, m_vertices.distance.size());
  }

  void receive(Index k, const typename Scheduler::Window_message& m) { add_window(m_patches[k], m.halfedge, m.window); }
  void receive(Index k, const typename Scheduler::Relax_message& m)
  {
    relax(m_patches[k], m.vertex, m.distance, m.key, m.corner, m.direction, m.origin);
  }
  void receive(Index k, const typename Scheduler::Face_message& m) { enter_face(m_patches[k], m.face); }
  void receive(Index k, const typename Scheduler::Relay_message& m) { make_emitter(m_patches[k], m.vertex); }

  // A window list waits outside R only if none of its face's vertices was ever reached (never,
  // on well-formed input); rather than lose its windows, its face enters R when nothing else is left.
  bool schedule_stranded_lists(std::vector<Index>& active)
  {
    for(Index k : m_scheduler.woken())
    {
      Patch& p = m_patches[k];
      for(Index h : p.unscheduled_lists(m_scheduled))
      {
        m_in_region.insert(Mesh::face(h), p.id);
        schedule(p, h);
      }
      if(!p.fifo.empty())
        active.push_back(p.id);
    }
    return !active.empty();
  }

  // ---------------------------------------------------------------------------------------------
  // vertices

  // lines 23-24 (see Propagation_vertices::relax), on the patch that owns `v`, and v's copies at
  // once: windows through a copy are compared with its own key (see for_each_face_across)
  void relax(Patch& p, Index v, FT d, FT key, Index corner, const Point& direction, Index origin)
  {
    if(m_scheduler.template hand_off<typename Scheduler::Relax_message>(p.id, m_partition.owner(v), v, d, key, corner,
                                                                         direction, origin))
      return;
    const bool smaller_key = key < m_vertices.least_key[v];
    const bool queue = m_vertices.relax(v, d, key, corner, direction, origin);
    if(queue)
      p.queue.push(Queue_entry(order(v), v));
    Emission_out out{*this, p};
    if(queue || smaller_key)
      m_emission.to_copies(v, m_vertices.distance[v], m_vertices.least_key[v], out);
  }

  // what the pseudo-sources of patch `patch` send out (see Pseudo_source_emission)
  struct Emission_out
  {
    Window_propagation& propagation;
    Patch& patch;
    void relax(Index v, FT d, FT key, Index corner, const Point& direction, Index origin)
    { propagation.relax(patch, v, d, key, corner, direction, origin); }
    void add_window(Index h, Win w)
    {
      // In DGG-VTP a pseudo-source lights all its corners, and the windows it sends back towards nearer
      // vertices are mostly beaten through their edge's ends already: the ICH rule now spares them the lists.
      if(propagation.is_dgg())
      {
        const End_keys ends = propagation.end_keys(patch, h);
        if(!trim_by_end_vertices(w, propagation.m_mesh.length(h), ends.a, ends.b))
          return;
      }
      propagation.add_window(patch, h, with_bound(w, propagation.m_keys));
    }
    void count_pseudo_source() { ++patch.stats.pseudo_sources; }
  };

  // lines 14-15
  void enter_propagation_region(Patch& p, Index v)
  {
    for(const Index* c = m_mesh.corners_begin(v); c != m_mesh.corners_end(v); ++c)
    {
      const Index f = Mesh::face(*c);
      if(!m_scheduler.template hand_off<typename Scheduler::Face_message>(p.id, m_partition.patch_of_face(f), f))
        enter_face(p, f);
    }
  }

  void enter_face(Patch& p, Index f)
  {
    if(!m_in_region.insert(f, p.id))
      return;
    for(Index h = 3 * f; h < 3 * f + 3; ++h)
      schedule(p, h);
  }

  // ---------------------------------------------------------------------------------------------
  // window lists

  void schedule(Patch& p, Index h)
  {
    if(!m_scheduled[h] && !p.lists.empty(h - p.first_halfedge))
    {
      m_scheduled[h] = 1;
      p.fifo.push_back(h);
    }
  }

  void add_window(Patch& p, Index h, const Win& w)
  {
    if(m_scheduler.template hand_off<typename Scheduler::Window_message>(p.id, m_partition.patch_of_halfedge(h), h, w))
      return;
    p.lists.push(h - p.first_halfedge, w);
    if constexpr(direct_only)
      m_vertices.direct.stored(w);
    if(m_in_region.contains(Mesh::face(h)))
      schedule(p, h);
  }

  // lines 16-28
  void propagate_scheduled_lists(Patch& p)
  {
    while(!p.fifo.empty())
    {
      const Index h = p.fifo.front();
      p.fifo.pop_front();
      m_scheduled[h] = 0;
      if(!p.fifo.empty())
        p.lists.prefetch(p.fifo.front() - p.first_halfedge);
      propagate_window_list(p, h);
    }
  }

  // Lines 17-27 for the window list of halfedge `h`: its windows cross the face of `h`, from
  // edge (a, b) towards the apex c, and leave through edge (c, a) (left) or (b, c) (right).
  void propagate_window_list(Patch& p, Index h)
  {
    refuse_windows_beyond(m_window_limit, p.lists.created());
    p.lists.take(h - p.first_halfedge, p.buffer);
    if constexpr(direct_only)
      m_vertices.direct.taken(p.buffer);
    const Index apex_vertex = m_mesh.source(Mesh::prev(h));
    const Point c = m_mesh.apex(h);

    // line 18: distance bound and ICH rule
    const FT len = m_mesh.length(h);
    const End_keys ends = end_keys(p, h);
    std::size_t kept = 0;
    for(Win& w : p.buffer)
    {
      if(w.beyond_bound(distance_to_interval(w.source, w.b0, w.b1)) && may_stop(w))
        stop_at_bound(p, w);
      else if(trim_by_end_vertices(w, len, ends.a, ends.b))
        p.buffer[kept++] = w;
    }
    p.buffer.resize(kept);
    trim_overlapping_windows(p.buffer, p.starts);
    if(m_targets.in_face(Mesh::face(h)))
      m_targets.cross(m_mesh, h, p.buffer, m_keys);

    // "one angle, two sides": the window that reaches c best, B, splits the face along its path
    // to c, and the other windows' children keep to their side of it (see sides_of_best_path)
    const Best_toward_apex<FT> best = best_toward_apex(p.buffer, c, m_keys, p.toward_apex);
    if(best.value_window != nullptr) // lines 21-24 for the apex
    {
      // arrival direction at c, in the frame of c's corner prev(h), which starts along c -> a
      const Point to_a = Point{number<FT>(0), number<FT>(0)} - c;
      const Point back = best.value_window->source - c;
      relax(p, apex_vertex, best.value, best.distance, Mesh::prev(h), Point{dot(to_a, back), cross(to_a, back)},
            best.value_window->origin);
    }

    // lines 19-26: the children on the edges (c, a) and (b, c); a child whose ray grazes c takes it
    // as its CH-relay vertex on that side (line 22); one whose side was cut loses that relay
    const bool left = m_mesh.has_face_across(Mesh::prev(h)), right = m_mesh.has_face_across(Mesh::next(h));
    const Point b{len, number<FT>(0)};
    const auto into = [this, &p](Index t, const Win& in) { add_window(p, t, in); };
    // whether copy `v` emits all around at a key at most `key` (see for_each_face_across)
    const auto covered = [this, &p](Index v, FT key) { return vertex_key(p, v) <= key; };
    Win child;
    for(std::size_t i = 0; i < p.buffer.size(); ++i)
    {
      const Win& w = p.buffer[i];
      const FT x = p.toward_apex[i].crossing;
      Sides<FT> keep{w.b1, w.b0};
      if(best.window != nullptr && &w != best.window)
        keep = sides_of_best_path(w, p.toward_apex[i], c, best);
      if(left && w.b0 < (std::min)(x, keep.left_end) &&
         left_child(w, c, x, keep.left_end, m_mesh.length(Mesh::prev(h)), child))
      {
        if(x < keep.left_end)
          take_relay(child, child.relay_right, child.relay_right_vertex, length(c - w.source), apex_vertex, m_keys);
        else if(keep.left_end < w.b1)
          child.drop_relay(child.relay_right);
        for_each_face_across(m_mesh, Mesh::prev(h), with_bound(child, m_keys), into, covered);
        if(x < keep.left_end)
          anticipate_stop(p, child, apex_vertex, m_mesh.length(Mesh::prev(h)));
      }
      if(right && (std::max)(x, keep.right_start) < w.b1 &&
         right_child(w, b, c, x, keep.right_start, m_mesh.length(Mesh::next(h)), child))
      {
        if(keep.right_start < x)
          take_relay(child, child.relay_left, child.relay_left_vertex, length(c - w.source), apex_vertex, m_keys);
        else if(w.b0 < keep.right_start)
          child.drop_relay(child.relay_left);
        for_each_face_across(m_mesh, Mesh::next(h), with_bound(child, m_keys), into, covered);
        if(keep.right_start < x)
          anticipate_stop(p, child, apex_vertex, m_mesh.length(Mesh::next(h)));
      }
    }
  }

  // the keys of the ends of the edge of halfedge `h` (its source a, its target b) for the ICH rule,
  // from the distances patch `p` sees (see Propagation_vertices::key)
  struct End_keys { FT a, b; };
  End_keys end_keys(const Patch& p, Index h) const
  {
    return End_keys{vertex_key(p, m_mesh.source(h)), vertex_key(p, m_mesh.target(h))};
  }
  FT vertex_key(const Patch& p, Index v) const
  {
    return m_vertices.key(v, m_scheduler.distance_seen(p.id, v, m_vertices.distance), m_partition.owner(v) == p.id);
  }

  // Line 18, the distance bound: `w` stops, and its beam beyond is left to its relays' windows
  // (see distance_bound), which must then emit.
  void stop_at_bound(Patch& p, const Win& w)
  {
    if(w.relay_left > FT(0))
      make_emitter(p, w.relay_left_vertex);
    if(w.relay_right > FT(0))
      make_emitter(p, w.relay_right_vertex);
  }

  // A window that took vertex `v` as relay and will stop within a few lengths of its edge (of
  // length `edge`) will rely on `v`: it becomes a pseudo-source now, so that it emits when it is
  // popped, in distance order, rather than after the windows that its own would have pruned.
  void anticipate_stop(Patch& p, const Win& w, Index v, FT edge)
  {
    if(w.beyond_bound(distance_to_interval(w.source, w.b0, w.b1) + T::stop_anticipation() * edge))
      make_emitter(p, v);
  }

  // vertex `v` emits all around when popped next (again, if it was); not in a direct-only run (Direct_distances)
  void make_emitter(Patch& p, Index v)
  {
    if constexpr(!direct_only)
      if(!m_scheduler.template hand_off<typename Scheduler::Relay_message>(p.id, m_partition.owner(v), v) &&
         m_vertices.pseudo_sources.make_emitter(v))
        p.queue.push(Queue_entry(order(v), v));
  }

  // the build rule's own ending and stops (see Direct_distances)
  bool direct_run_done() const
  {
    if constexpr(direct_only)
      return m_vertices.direct.done();
    else
      return false;
  }
  bool may_stop(const Win& w) const
  {
    if constexpr(direct_only)
      return m_vertices.direct.may_stop(w);
    else
      return true;
  }

  bool is_dgg() const { return !m_keys.is_exact(); }

  const Mesh& m_mesh;
  const Patch_partition<FT>& m_partition;
  Scheduler m_scheduler;
  Key_ratio<FT> m_keys;               // rho = 1 + epsilon (1: exact) and its constants
  Pseudo_source_emission<FT> m_emission; // what pseudo-sources send out, and where
  Propagation_vertices<FT, direct_only> m_vertices; // per vertex: distance, arrivals, (pseudo-)source
  Index_set m_in_region;              // the faces inside the propagation region R
  std::vector<char> m_scheduled;      // per halfedge: its window list is in its patch's FIFO
  const std::size_t m_window_limit;   // see window_limit()
  std::deque<Patch> m_patches;        // a deque: a patch never moves
  const Propagation_query<FT>* m_query = nullptr;
  Progress_report m_progress;         // of the query's progress callback
  Point_targets<FT> m_targets;        // the query's targets inside faces
  Distance_to_go<FT> m_to_go;         // to the query's targets, if any
  Propagation_statistics m_stats;
  FT m_limit = infinity();            // the largest distance of interest (see early_termination_limit)
  FT m_pending_keys = infinity();     // no key the run left undone is below it (+inf: none left)
  FT m_pending_at_targets = infinity(); // no such key is below it at the targets
  bool m_reusable = true;             // see reusable()
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_WINDOW_PROPAGATION_H
