// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_WINDOW_PROPAGATION_H
#define CGAL_DGG_VTP_3_INTERNAL_WINDOW_PROPAGATION_H

#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/internal/Distance_bound.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/Window_lists.h>
#include <CGAL/DGG_VTP_3/internal/for_each_index.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <boost/heap/d_ary_heap.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// One single-source propagation (paper, Algorithm 1) over an Unfolded_mesh: the per-query
// scratch of the const queries of Geodesic_distance_solver. It runs patch by patch, in rounds
// (see run()), so that a Parallel_tag shares it among threads with the same results.
//
// Windows sit in per-halfedge window lists; a vertex-oriented priority queue pops the nearest
// vertex, which may emit windows as a pseudo-source and brings its faces into the propagation
// region R; then the window lists inside R are propagated in FIFO order until every window has
// left R. Pruning is by the ICH rule (as interval trimming against the edge's end vertices) and
// by "one angle, two sides". With accuracy 0 this is the exact VTP algorithm: only saddle,
// border and non-manifold vertices are pseudo-sources and windows travel without bound.
template <class FT>
class Window_propagation
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;
  using Win = Window<FT>;

public:
  // `accuracy` is the user's epsilon: 0 for the exact algorithm
  Window_propagation(const Mesh& mesh, FT accuracy)
    : m_mesh(mesh)
    , m_bound_epsilon(bound_epsilon(accuracy))
    , m_fan_half_width(fan_half_width(accuracy))
    , m_distance(mesh.number_of_vertices(), infinity())
    , m_committed(mesh.number_of_vertices(), infinity())
    , m_incoming(mesh.number_of_vertices())
    , m_in_region(mesh.number_of_faces(), 0)
    , m_scheduled(mesh.number_of_halfedges(), 0)
  {
    // patches of consecutive faces (the mesh orders them along a space-filling curve); their
    // number depends on the mesh only, never on the number of threads
    const std::size_t nf = mesh.number_of_faces();
    const std::size_t count = (std::min)(max_patches(), (std::max)(std::size_t(1), nf / min_patch_faces()));
    m_faces_per_patch = Index((nf + count - 1) / count);
    const std::size_t patches = m_faces_per_patch == 0 ? 1 : (nf + m_faces_per_patch - 1) / m_faces_per_patch;
    for(std::size_t k = 0; k < patches; ++k)
    {
      const Index first = Index(k * m_faces_per_patch);
      const Index end = Index((std::min)(nf, (k + 1) * m_faces_per_patch));
      m_patches.emplace_back(Index(k), first, end, patches);
    }
    m_senders.resize(m_patches.size());
    m_receiving.assign(m_patches.size(), 0);
    // a vertex belongs to the patch of its first corner; it is on a border if a face of another
    // patch has it too
    m_owner.assign(mesh.number_of_vertices(), 0);
    m_on_border.assign(mesh.number_of_vertices(), 0);
    for(Index v = 0; v < mesh.number_of_vertices(); ++v)
    {
      if(mesh.corners_begin(v) == mesh.corners_end(v))
        continue;
      m_owner[v] = patch_of_face(Mesh::face(*mesh.corners_begin(v)));
      for(const Index* c = mesh.corners_begin(v); c != mesh.corners_end(v); ++c)
        if(patch_of_face(Mesh::face(*c)) != m_owner[v])
          m_on_border[v] = 1;
    }
    FT total(0);
    for(Index h = 0; h < mesh.number_of_halfedges(); ++h)
      total += mesh.length(h);
    m_band = mesh.number_of_halfedges() == 0 ? FT(0) : band_in_edges() * total / FT(mesh.number_of_halfedges());
  }

  static FT infinity() { return std::numeric_limits<FT>::infinity(); }

  // The distance to the nearest of the sources: they all start at 0 and emit all around.
  //
  // Algorithm 1 runs in every patch of the mesh on its own, in rounds: in a round, each patch
  // pops its vertices nearer than the round's limit (the nearest vertex of all, plus a band) and
  // propagates its window lists, as the sequential algorithm does; what it does to the rest of
  // the mesh (windows into another patch's lists, distances of its vertices, faces entering R)
  // waits in its outbox until the round ends, and the distances of other patches' vertices it
  // reads are those of the round's start. So each patch's round depends on the round's start
  // only, the patches of a round may run on any threads in any order, and the distances are the
  // same bit for bit for any number of threads (and for Sequential_tag).
  template <class ConcurrencyTag>
  void run(const std::vector<Index>& sources)
  {
    m_is_source.assign(m_distance.size(), 0);
    for(Index s : sources)
    {
      m_is_source[s] = 1;
      m_distance[s] = m_committed[s] = FT(0);
      m_patches[m_owner[s]].queue.push(Queue_entry(FT(0), s));
    }
    std::vector<Index> active;
    for(;;)
    {
      FT nearest = infinity();
      active.clear();
      for(Patch& p : m_patches)
      {
        while(!p.queue.empty() && p.queue.top().first > m_distance[p.queue.top().second])
          p.queue.pop(); // superseded by a later, shorter distance
        if(!p.queue.empty())
          nearest = (std::min)(nearest, p.queue.top().first);
        if(!p.queue.empty() || !p.fifo.empty())
          active.push_back(p.id);
      }
      if(active.empty())
      {
        // A window list can only be waiting outside R if none of its face's vertices was ever
        // reached, which well-formed input does not produce; rather than lose its windows, bring
        // such faces into R and go on.
        if(!schedule_stranded_lists(active))
          break;
      }
      const FT limit = nearest + m_band;
      for_each_index<ConcurrencyTag>(active.size(), [&](std::size_t k) { run_round(m_patches[active[k]], limit); });
      // an upper bound of the windows alive at once during the round
      std::size_t peak = 0;
      for(Patch& p : m_patches)
      {
        peak += p.lists.peak();
        p.lists.reset_peak();
      }
      m_stats.windows_peak = (std::max)(m_stats.windows_peak, peak);
      deliver_outboxes<ConcurrencyTag>(active);
    }
    for(Patch& p : m_patches)
    {
      m_stats.windows_created += p.lists.created();
      m_stats.pseudo_sources += p.stats.pseudo_sources;
      m_stats.vertices_popped += p.stats.vertices_popped;
    }
    for(const FT& d : m_distance)
      if(d < infinity())
        ++m_stats.vertices_reached;
  }

  const std::vector<FT>& distances() const { return m_distance; }
  const Propagation_statistics& statistics() const { return m_stats; }

private:
  using Queue_entry = std::pair<FT, Index>;
  using Queue = boost::heap::d_ary_heap<Queue_entry, boost::heap::arity<4>,
                                        boost::heap::compare<std::greater<Queue_entry>>>;

  // A window of the list being propagated seen from the apex: where its ray to the apex crosses the
  // edge, and its distance to the apex along that ray if the crossing lies in its interval (+inf:
  // it does not light the apex)
  struct Toward_apex
  {
    FT crossing;
    FT distance;
  };

  // what a patch does to another one during a round, applied when the round ends
  struct Window_message
  {
    Index halfedge;
    Win window;
  };
  struct Relax_message
  {
    Index vertex;
    FT distance;
    FT back;
  };
  struct Outbox
  {
    std::vector<Window_message> windows;
    std::vector<Relax_message> relaxations;
    std::vector<Index> faces; // entering R
    bool empty() const { return windows.empty() && relaxations.empty() && faces.empty(); }
  };

  // one patch of faces: its window lists (those of its faces' halfedges), its vertices' queue, and
  // the scratch of propagating them
  struct Patch
  {
    Patch(Index id, Index first_face, Index end_face, std::size_t patches)
      : id(id), first_face(first_face), end_face(end_face), first_halfedge(3 * first_face)
      , lists(3 * std::size_t(end_face - first_face)), outbox(patches)
    {}
    Index id, first_face, end_face, first_halfedge;
    Window_lists<FT> lists;          // per halfedge of the patch: windows entering its face
    Queue queue;                     // vertex-oriented priority queue Q (lazy deletion)
    std::deque<Index> fifo;          // FIFO F of window lists to propagate
    std::vector<Win> buffer;         // the window list being propagated
    std::vector<FT> starts;          // its windows' starts, sorted, before pairwise trimming
    std::vector<Toward_apex> toward_apex; // per window of that list, see Toward_apex
    std::vector<Index> changed;      // border vertices whose distance changed in this round
    std::vector<Outbox> outbox;      // per patch: what this round does to it
    std::vector<Index> recipients;   // patches whose outbox is not empty
    Propagation_statistics stats;
  };

  static std::size_t max_patches() { return 256; }
  static std::size_t min_patch_faces() { return 2048; }
  // Rounds pop vertices up to 4 mean edge lengths beyond the nearest: on bunny_1M (1e-6, 730
  // rounds) 1 to 8 edges change the time by less than the noise; wider bands pop vertices before
  // the windows from other patches can shorten them (windows: +0.1% at 1, +2% at 8).
  static FT band_in_edges() { return FT(4); }

  Index patch_of_face(Index f) const { return m_faces_per_patch == 0 ? 0 : f / m_faces_per_patch; }
  Index patch_of_halfedge(Index h) const { return patch_of_face(Mesh::face(h)); }

  // the distance of `v` as patch `p` may read it during a round
  FT distance_seen(const Patch& p, Index v) const { return m_owner[v] == p.id ? m_distance[v] : m_committed[v]; }

  Outbox& outbox_to(Patch& p, Index q)
  {
    Outbox& box = p.outbox[q];
    if(box.empty())
      p.recipients.push_back(q);
    return box;
  }

  // lines 9-29 in one patch, for the vertices nearer than `limit`
  void run_round(Patch& p, FT limit)
  {
    propagate_scheduled_lists(p);
    while(!p.queue.empty() && p.queue.top().first <= limit)
    {
      const Queue_entry top = p.queue.top();
      p.queue.pop();
      const Index v = top.second;
      if(top.first > m_distance[v])
        continue; // superseded by a later, shorter distance
      ++p.stats.vertices_popped;
      if(m_is_source[v] || m_mesh.is_singular(v))
        emit_pseudo_source_windows(p, v, m_mesh.corners_begin(v), m_mesh.corners_end(v));
      else if(is_dgg())
        emit_pseudo_source_windows_in_fan(p, v);
      else if(m_mesh.is_exact_pseudo_source(v))
        emit_pseudo_source_windows_in_shadow(p, v);
      enter_propagation_region(p, v);
      propagate_scheduled_lists(p);
    }
    p.lists.release_if_empty();
  }

  // The outboxes of the round, each patch receiving from the others in the order of their ids,
  // then the distances of border vertices that other patches read
  template <class ConcurrencyTag>
  void deliver_outboxes(const std::vector<Index>& active)
  {
    std::vector<Index> receivers;
    const auto receive = [&](Index q) {
      if(!m_receiving[q])
      {
        m_receiving[q] = 1;
        receivers.push_back(q);
      }
    };
    for(Index p : active)
      receive(p);
    for(Patch& p : m_patches)
    {
      for(Index q : p.recipients)
      {
        receive(q);
        m_senders[q].push_back(p.id);
      }
      p.recipients.clear();
    }
    for_each_index<ConcurrencyTag>(receivers.size(), [&](std::size_t k) {
      Patch& q = m_patches[receivers[k]];
      for(Index sender : m_senders[q.id])
      {
        Outbox& box = m_patches[sender].outbox[q.id];
        for(const Window_message& m : box.windows)
          add_window(q, m.halfedge, m.window);
        for(const Relax_message& m : box.relaxations)
          relax(q, m.vertex, m.distance, m.back);
        for(Index f : box.faces)
          enter_face(q, f);
        box = Outbox(); // its memory back: some pair of patches talks in a few rounds only
      }
      m_senders[q.id].clear();
      m_receiving[q.id] = 0;
      for(Index v : q.changed)
        m_committed[v] = m_distance[v];
      q.changed.clear();
    });
  }

  // ---------------------------------------------------------------------------------------------
  // vertices

  // Lines 23-24: a path of length `d` reaches `v`, arriving from the polar angle `back` at `v`
  // (the direction pointing back along the path). Paths that tie with the best one widen the
  // recorded range of arrival directions: the shadow of a saddle is the union of their shadows.
  void relax(Patch& p, Index v, FT d, FT back)
  {
    if(m_owner[v] != p.id)
    {
      outbox_to(p, m_owner[v]).relaxations.push_back(Relax_message{v, d, back});
      return;
    }
    const FT dv = m_distance[v];
    Incoming& in = m_incoming[v];
    if(d < dv - margin(dv) || dv == infinity())
    {
      m_distance[v] = d;
      in.low = in.high = back;
      p.queue.push(Queue_entry(d, v));
    }
    else if(d <= dv + margin(dv) && !(in.low <= back && back <= in.high))
    {
      in.low = (std::min)(in.low, back);
      in.high = (std::max)(in.high, back);
      if(d < dv)
        m_distance[v] = d;
      p.queue.push(Queue_entry(m_distance[v], v)); // emit the wider shadow if already popped
    }
    else
      return;
    if(m_on_border[v])
      p.changed.push_back(v);
  }

  // Lines 11-13 of the exact algorithm: a shortest path bends at a saddle only if it turns by at
  // least pi on both sides, so a saddle emits windows only into the faces that meet the cone
  // [back + pi, back + angle_sum - pi] of the directions it arrived from, widened by a small
  // angle for rounding (emitting more is always safe: windows are real paths, pruned later).
  void emit_pseudo_source_windows_in_shadow(Patch& p, Index v)
  {
    const FT theta = m_mesh.angle_sum(v);
    const FT widen = FT(8) * std::sqrt(margin(FT(1)));
    emit_pseudo_source_windows_in_cone(p, v, pi() - widen, theta - pi() + widen);
  }

  // Lines 11-12 of DGG-VTP: every vertex is a pseudo-source, but only inside its fan, the
  // directions nearly straight ahead of the geodesic that reached it (paper, Fig. 5): the
  // straight continuations on the two sides, back + pi and back + angle_sum - pi, widened by the
  // fan half-width on both sides (for a convex vertex they swap places).
  void emit_pseudo_source_windows_in_fan(Patch& p, Index v)
  {
    const FT theta = m_mesh.angle_sum(v);
    const FT left = pi(), right = theta - pi();
    emit_pseudo_source_windows_in_cone(p, v, (std::min)(left, right) - m_fan_half_width,
                                       (std::max)(left, right) + m_fan_half_width);
  }

  // windows into the faces that meet [back + from, back + to] for some recorded arrival
  // direction back (a union of cones sliding with back)
  void emit_pseudo_source_windows_in_cone(Patch& p, Index v, FT from_back, FT to_back)
  {
    const FT theta = m_mesh.angle_sum(v);
    const Incoming& in = m_incoming[v];
    FT from = in.low + from_back;
    const FT width = (in.high + to_back) - from;
    if(!(width < theta))
    {
      emit_pseudo_source_windows(p, v, m_mesh.corners_begin(v), m_mesh.corners_end(v));
      return;
    }
    if(width < FT(0))
      return;
    from = std::fmod(from, theta);
    if(from < FT(0))
      from += theta;
    // the cone is [from, from + width] on the circle of length theta; corners in turning order
    ++p.stats.pseudo_sources;
    for(const Index* c = m_mesh.corners_begin(v); c != m_mesh.corners_end(v); ++c)
    {
      const FT start = m_mesh.corner_start_angle(*c);
      const FT end = start + m_mesh.corner_angle(*c);
      const bool meets = (end >= from && start <= from + width) ||
                         (end + theta >= from && start + theta <= from + width);
      if(meets)
        emit_window_across_corner(p, v, *c);
    }
  }

  void emit_pseudo_source_windows(Patch& p, Index v, const Index* first, const Index* last)
  {
    ++p.stats.pseudo_sources;
    for(const Index* c = first; c != last; ++c)
      emit_window_across_corner(p, v, *c);
  }

  // a full-edge window on the edge opposite `v` in the face of corner `h`, and the distances of
  // the corner's two other vertices along its edges
  void emit_window_across_corner(Patch& p, Index v, Index h)
  {
    const FT dv = m_distance[v];
    const Index across = Mesh::next(h); // the edge opposite v; its apex is v
    const Index prev = Mesh::prev(h);
    relax(p, m_mesh.target(h), dv + m_mesh.length(h),
          m_mesh.corner_start_angle(across) + m_mesh.corner_angle(across));
    relax(p, m_mesh.source(prev), dv + m_mesh.length(prev), m_mesh.corner_start_angle(prev));
    const Index t = m_mesh.opposite(across);
    if(t == Mesh::no_halfedge)
      return;
    const FT len = m_mesh.length(across);
    const Point apex = m_mesh.apex(across);
    Win w;
    w.b0 = FT(0);
    w.b1 = len;
    w.source = Point{len - apex.x, -apex.y}; // the same triangle seen from the other side
    w.sigma = dv;
    // line 3 (and 12): the CH-relay vertices of a new window are the ends of its edge
    w.relay_left = m_mesh.length(prev);
    w.relay_right = m_mesh.length(h);
    w.d_max = is_dgg() ? distance_bound(w.source, w.b0, w.b1, w.relay_left, w.relay_right, m_bound_epsilon)
                       : infinity();
    add_window(p, t, w);
  }

  // lines 14-15
  void enter_propagation_region(Patch& p, Index v)
  {
    for(const Index* c = m_mesh.corners_begin(v); c != m_mesh.corners_end(v); ++c)
    {
      const Index f = Mesh::face(*c);
      const Index q = patch_of_face(f);
      if(q == p.id)
        enter_face(p, f);
      else
        outbox_to(p, q).faces.push_back(f);
    }
  }

  void enter_face(Patch& p, Index f)
  {
    if(m_in_region[f])
      return;
    m_in_region[f] = 1;
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
    const Index q = patch_of_halfedge(h);
    if(q != p.id)
    {
      outbox_to(p, q).windows.push_back(Window_message{h, w});
      return;
    }
    p.lists.push(h - p.first_halfedge, w);
    if(m_in_region[Mesh::face(h)])
      schedule(p, h);
  }

  bool schedule_stranded_lists(std::vector<Index>& active)
  {
    for(Patch& p : m_patches)
    {
      for(Index h = p.first_halfedge; h < 3 * p.end_face; ++h)
        if(!p.lists.empty(h - p.first_halfedge) && !m_scheduled[h])
        {
          m_in_region[Mesh::face(h)] = 1;
          schedule(p, h);
        }
      if(!p.fifo.empty())
        active.push_back(p.id);
    }
    return !active.empty();
  }

  // lines 16-28
  void propagate_scheduled_lists(Patch& p)
  {
    while(!p.fifo.empty())
    {
      const Index h = p.fifo.front();
      p.fifo.pop_front();
      m_scheduled[h] = 0;
      propagate_window_list(p, h);
    }
  }

  // Lines 17-27 for the window list of halfedge `h`: its windows cross the face of `h`, from
  // edge (a, b) towards the apex c, and leave through edge (c, a) (left) or (b, c) (right).
  void propagate_window_list(Patch& p, Index h)
  {
    p.lists.take(h - p.first_halfedge, p.buffer);
    const Index apex_vertex = m_mesh.source(Mesh::prev(h));
    const Point c = m_mesh.apex(h);

    // line 18: distance bound and ICH rule
    std::size_t kept = 0;
    for(Win& w : p.buffer)
      if(!(distance_to_interval(w.source, w.b0, w.b1) > w.d_max) && trim_by_end_vertices(p, h, w))
        p.buffer[kept++] = w;
    p.buffer.resize(kept);
    if(!is_dgg())
      trim_overlapping_windows(p);

    // "one angle, two sides": the window that reaches c best, B, splits the face along its path
    // to c, and the other windows' children keep to their side of it (see `sides`)
    FT best_distance = infinity();
    FT best_crossing = FT(0);
    const Win* best = nullptr;
    p.toward_apex.resize(p.buffer.size());
    for(std::size_t i = 0; i < p.buffer.size(); ++i)
    {
      const Win& w = p.buffer[i];
      Toward_apex& t = p.toward_apex[i];
      const FT x = t.crossing = x_axis_crossing(w.source, c);
      t.distance = infinity();
      if(w.b0 <= x && x <= w.b1)
      {
        const FT d = t.distance = w.distance_to(c);
        if(d < best_distance)
        {
          best_distance = d;
          best_crossing = x;
          best = &w;
        }
      }
    }
    if(best != nullptr) // lines 21-24 for the apex
    {
      // arrival direction at c, measured in c's corner, which starts along c -> a
      const Point to_a = Point{FT(0), FT(0)} - c;
      const Point back = best->source - c;
      using std::atan2;
      relax(p, apex_vertex, best_distance,
            m_mesh.corner_start_angle(Mesh::prev(h)) + atan2(cross(to_a, back), dot(to_a, back)));
    }

    const Index left = m_mesh.opposite(Mesh::prev(h));
    const Index right = m_mesh.opposite(Mesh::next(h));
    for(std::size_t i = 0; i < p.buffer.size(); ++i)
    {
      const Win& w = p.buffer[i];
      const FT x = p.toward_apex[i].crossing;
      Sides keep{w.b1, w.b0};
      if(best != nullptr && &w != best)
        keep = sides(w, p.toward_apex[i], c, *best, best_crossing, best_distance);
      if(left != Mesh::no_halfedge && w.b0 < (std::min)(x, keep.left_end))
        add_left_child(p, h, c, w, x, keep.left_end, left);
      if(right != Mesh::no_halfedge && (std::max)(x, keep.right_start) < w.b1)
        add_right_child(p, h, c, w, x, keep.right_start, right);
    }
  }


  // The part of w's interval whose rays may still go left of the apex c (those up to `left_end`)
  // and right of it (from `right_start` on), given the best window B to c.
  struct Sides
  {
    FT left_end;
    FT right_start;
  };

  // A shortest path does not cross B's path to c where B is there first. If w's own way to c
  // (straight when it lights c, else through its nearer end) is no shorter than B's, then B is
  // first at every point of its path that a ray of w reaches (else that ray, then B's path, would
  // reach c sooner), so w keeps only the rays that stay on their side of B's path: above the edge,
  // those that pass c on B's side of B's crossing; below it, those that did not cut B's segment
  // from its pseudo-source. Below the edge, the two windows' unfoldings are known to be the same
  // surface only inside w's lit triangle, so that test applies only when w's interval contains
  // B's crossing. In DGG-VTP B's path is itself approximate, and cutting w behind it loses
  // accuracy unless w is clearly worse: by more than the bound's relative tolerance; otherwise
  // only the classic rule applies, a window lighting c wholly on one side of B's crossing keeps
  // only its child on that side.
  Sides sides(const Win& w, const Toward_apex& t, const Point& c, const Win& best, FT best_crossing,
              FT best_distance) const
  {
    const bool lights_apex = t.distance < infinity();
    FT to_c = t.distance;
    if(!lights_apex)
    {
      const FT end = t.crossing < w.b0 ? w.b0 : w.b1;
      to_c = w.distance_to_base_point(end) + length(c - Point{end, FT(0)});
    }
    Sides keep{w.b1, w.b0};
    if(to_c >= best_distance * (FT(1) + m_bound_epsilon))
    {
      keep.left_end = (std::min)(best_crossing, w.b1);
      keep.right_start = (std::max)(best_crossing, w.b0);
      if(w.b0 < best_crossing && best_crossing < w.b1)
      {
        // a ray of w that meets the edge on the other side of B's line than w's source crossed
        // that line below the edge; on B's segment [s_B, (best_crossing, 0)] (not beyond s_B) up
        // to the ray through s_B, which meets the edge at beyond_sB (all of them if s_B is not
        // nearer the edge than w's source)
        const Point& sB = best.source;
        const FT side = cross(Point{best_crossing - sB.x, -sB.y}, w.source - sB);
        const bool sB_nearer = sB.y > w.source.y;
        const FT beyond_sB = sB_nearer ? x_axis_crossing(w.source, sB) : FT(0);
        if(side < FT(0))
          keep.left_end = sB_nearer ? (std::min)(best_crossing, beyond_sB) : -infinity();
        else if(side > FT(0))
          keep.right_start = sB_nearer ? (std::max)(best_crossing, beyond_sB) : infinity();
      }
    }
    else if(lights_apex)
    {
      if(w.b0 >= best_crossing)
        keep.left_end = w.b0;
      if(w.b1 <= best_crossing)
        keep.right_start = w.b1;
    }
    return keep;
  }

  // The ICH rule (Xin and Wang), applied as trimming: the part of the interval where reaching the
  // edge through its end vertex a (or b) is strictly shorter carries no shortest path, here or
  // beyond. Along the edge `sigma + |p - s| - |p - a|` only decreases, so that part is a prefix
  // (a suffix for b) found in closed form. Returns false when nothing of the window is left.
  bool trim_by_end_vertices(const Patch& p, Index h, Win& w) const
  {
    const FT len = m_mesh.length(h);
    const FT sx = w.source.x;
    const FT ss = sx * sx + w.source.y * w.source.y;
    const FT da = distance_seen(p, m_mesh.source(h));
    if(da < infinity())
    {
      // reaching p = (t, 0) through a costs da + t (a margin keeps rounding from trimming ties)
      const FT k = da + margin(da + len) - w.sigma;
      if(w.distance_to_base_point(w.b1) > k + w.sigma + w.b1)
        return false;
      if(w.distance_to_base_point(w.b0) > k + w.sigma + w.b0)
        shrink_to(w, (ss - k * k) / (FT(2) * (k + sx)), w.b0);
    }
    const FT db = distance_seen(p, m_mesh.target(h));
    if(db < infinity())
    {
      // through b it costs db + len - t
      const FT k = db + margin(db + len) + len - w.sigma;
      if(w.distance_to_base_point(w.b0) > k + w.sigma - w.b0)
        return false;
      if(w.distance_to_base_point(w.b1) > k + w.sigma - w.b1)
        shrink_to(w, (k * k - ss) / (FT(2) * (k - sx)), w.b1);
    }
    return w.b0 < w.b1;
  }

  // a window that meets a vertex takes it as CH-relay vertex on that side; its bound is
  // recomputed and only ever tightens
  void update_relay(Win& w, FT& relay, FT distance) const
  {
    if(!is_dgg())
      return;
    relay = distance;
    w.d_max = (std::min)(w.d_max, distance_bound(w.source, w.b0, w.b1, w.relay_left, w.relay_right,
                                                 m_bound_epsilon));
  }

  // ---------------------------------------------------------------------------------------------
  // accuracy control: how the user's epsilon becomes the bound's epsilon and the fan's width
  // (calibrated so that every vertex stays within epsilon, see doc/)

  static FT bound_epsilon(FT accuracy) { return FT(0.25) * accuracy; }
  static FT fan_half_width(FT accuracy) { using std::sqrt; return FT(3) * sqrt(bound_epsilon(accuracy)); }
  bool is_dgg() const { return m_bound_epsilon > FT(0); }
  static FT pi() { return FT(3.14159265358979323846); }

  // ---------------------------------------------------------------------------------------------
  // pairwise trimming (as in MMP and VTP): where two windows of one list overlap, the part of one
  // that is everywhere farther than the other carries no shortest path and is cut off

  void trim_overlapping_windows(Patch& p)
  {
    if(p.buffer.size() < 2)
      return;
    std::sort(p.buffer.begin(), p.buffer.end(), [](const Win& a, const Win& b) { return a.b0 < b.b0; });
    p.starts.resize(p.buffer.size());
    for(std::size_t i = 0; i < p.buffer.size(); ++i)
      p.starts[i] = p.buffer[i].b0;
    for(std::size_t i = 0; i < p.buffer.size(); ++i)
      for(std::size_t j = i + 1; j < p.buffer.size() && p.starts[j] < p.buffer[i].b1; ++j)
        if(p.buffer[i].b0 < p.buffer[i].b1)
          trim_pair(p.buffer[i], p.buffer[j]);
    std::size_t kept = 0;
    for(const Win& w : p.buffer)
      if(w.b0 < w.b1)
        p.buffer[kept++] = w;
    p.buffer.resize(kept);
  }

  // `u` starts no later than `w`. Their overlap is cut where D_u - D_w = 0 (a hyperbola meets the
  // edge at most twice); on each piece in between the difference has one sign, which the
  // piece's middle tells: its ends are roots or near-ties, so only a clear contradiction there
  // leaves the piece alone. A piece where the two tie within rounding goes to `u`.
  void trim_pair(Win& u, Win& w) const
  {
    const FT lo = (std::max)(u.b0, w.b0);
    const FT hi = (std::min)(u.b1, w.b1);
    if(!(lo < hi))
      return;
    const FT du_lo = u.distance_to_base_point(lo);
    const FT du_hi = u.distance_to_base_point(hi);
    const FT m = margin((std::max)(du_lo, du_hi));
    const auto difference = [&](FT x) { return u.distance_to_base_point(x) - w.distance_to_base_point(x); };
    const FT f_lo = du_lo - w.distance_to_base_point(lo);
    const FT f_hi = du_hi - w.distance_to_base_point(hi);

    // per piece, the sign of D_u - D_w: +1 u is farther, -1 w is farther or they tie, 0 unknown
    FT cuts[4] = {lo, hi, hi, hi};
    int sign[3];
    int pieces = 1;
    // The slope of D_u - D_w is cos_u - cos_w, the cosines of the rays with the edge, each
    // increasing along it: slopes in [a, b] bound the difference on the overlap from both sides
    // by lines through its ends, and when those bounds keep one sign, no root search is needed.
    // (the cosines come from distances minus sigma, so they are widened by sqrt(eps) for the
    // cancellation that this may cost)
    using std::sqrt;
    const FT slack = sqrt(std::numeric_limits<FT>::epsilon());
    const FT a = (lo - u.source.x) / (du_lo - u.sigma) - (hi - w.source.x) / (du_hi - f_hi - w.sigma) - slack;
    const FT b = (hi - u.source.x) / (du_hi - u.sigma) - (lo - w.source.x) / (du_lo - f_lo - w.sigma) + slack;
    const FT len = hi - lo;
    const FT lowest = (a >= FT(0)) ? f_lo : (b <= FT(0)) ? f_hi
                    : f_lo + a * (f_hi - f_lo - b * len) / (a - b);
    const FT highest = (a >= FT(0)) ? f_hi : (b <= FT(0)) ? f_lo
                     : f_lo + b * (f_hi - f_lo - a * len) / (b - a);
    if(lowest > m)
      sign[0] = 1;
    else if(highest < -m)
      sign[0] = -1;
    else
    {
      int n = 1;
      n += equal_distance_points(u, w, lo, hi, cuts + n);
      cuts[n++] = hi;
      if(n == 4 && cuts[2] < cuts[1])
        std::swap(cuts[1], cuts[2]);
      FT at_cut[4];
      at_cut[0] = f_lo;
      at_cut[n - 1] = f_hi;
      for(int k = 1; k + 1 < n; ++k)
        at_cut[k] = difference(cuts[k]);
      pieces = n - 1;
      for(int k = 0; k < pieces; ++k)
      {
        const FT at_middle = difference((cuts[k] + cuts[k + 1]) / FT(2));
        const FT fmin = (std::min)(at_cut[k], at_cut[k + 1]);
        const FT fmax = (std::max)(at_cut[k], at_cut[k + 1]);
        if(at_middle > m)
          sign[k] = fmin > -m ? 1 : 0;
        else if(at_middle < -m)
          sign[k] = fmax < m ? -1 : 0;
        else
          sign[k] = fmin > -m && fmax < m ? -1 : 0;
      }
    }
    int opposite_sign[3];
    for(int k = 0; k < pieces; ++k)
      opposite_sign[k] = -sign[k];
    cut_where_farther(w, cuts, sign, pieces);
    cut_where_farther(u, cuts, opposite_sign, pieces);
  }

  // `x` is farther on the pieces [cuts[k], cuts[k+1]] with farther[k] == -1: cut off the run of
  // such pieces at either end of the overlap, where that end is also an end of `x`
  static void cut_where_farther(Win& x, const FT* cuts, const int* farther, int pieces)
  {
    int first = 0;
    while(first < pieces && farther[first] == -1)
      ++first;
    int last = pieces;
    while(last > first && farther[last - 1] == -1)
      --last;
    const bool starts_x = cuts[0] == x.b0;
    const bool ends_x = cuts[pieces] == x.b1;
    if(first == pieces) // farther on the whole overlap
    {
      if(starts_x && ends_x)
        x.b1 = x.b0;
      else if(starts_x)
        x.b0 = cuts[pieces];
      else if(ends_x)
        x.b1 = cuts[0];
      return;
    }
    if(starts_x && first > 0)
      x.b0 = cuts[first];
    if(ends_x && last < pieces)
      x.b1 = cuts[last];
  }

  // The points of (lo, hi) where the two windows give equal distances: sigma_u + r_u = sigma_w + r_w.
  // Squaring twice gives a quadratic; its spurious roots only add harmless piece boundaries.
  static int equal_distance_points(const Win& u, const Win& w, FT lo, FT hi, FT* out)
  {
    const FT xu = u.source.x, yu = u.source.y, xw = w.source.x, yw = w.source.y;
    const FT delta = w.sigma - u.sigma;
    // r_u^2 - r_w^2 = A t + B, so A t + B - delta^2 = 2 delta r_w
    const FT A = FT(2) * (xw - xu);
    const FT C = (xu * xu + yu * yu - xw * xw - yw * yw) - delta * delta;
    const FT d2 = FT(4) * delta * delta;
    const FT a = A * A - d2;
    const FT b = FT(2) * A * C + d2 * FT(2) * xw;
    const FT c = C * C - d2 * (xw * xw + yw * yw);
    int n = 0;
    auto keep = [&](FT t) { if(lo < t && t < hi) out[n++] = t; };
    const FT scale = (std::max)((std::abs)(a), (std::max)((std::abs)(b), (std::abs)(c)));
    if(!(scale > FT(0)))
      return 0;
    if((std::abs)(a) <= margin(scale))
    {
      if(b != FT(0))
        keep(-c / b);
      return n;
    }
    const FT disc = b * b - FT(4) * a * c;
    if(disc < FT(0))
      return 0;
    using std::sqrt;
    const FT q = -(b + (b < FT(0) ? -sqrt(disc) : sqrt(disc))) / FT(2);
    keep(q / a);
    if(q != FT(0))
      keep(c / q);
    return n;
  }

  static FT margin(FT scale) { return FT(64) * std::numeric_limits<FT>::epsilon() * scale; }
  // moves one end of the interval to `t` if `t` lies strictly inside it; a crossing that
  // rounding puts outside (or a NaN) leaves the window whole, which is always safe
  static void shrink_to(const Win& w, FT t, FT& end)
  {
    if(w.b0 < t && t < w.b1)
      end = t;
  }

  // child on edge (a, c), in the frame of the neighbouring halfedge a -> c, from the rays of `w`
  // through [b0, min(end, x)]; `c` is the apex of `h`, `x` where the window's ray to c crosses
  // the base
  void add_left_child(Patch& p, Index h, const Point& c, const Win& w, FT x, FT end, Index left)
  {
    const FT len = m_mesh.length(Mesh::prev(h));
    const Point a{FT(0), FT(0)};
    const bool grazes_c = x < end;
    const FT u0 = ray_segment_parameter(w.source, Point{w.b0, FT(0)}, a, c);
    const FT u1 = grazes_c ? FT(1) : ray_segment_parameter(w.source, Point{end, FT(0)}, a, c);
    if(!(u0 < u1))
      return;
    Win child = w;
    child.b0 = u0 * len;
    child.b1 = u1 * len;
    child.source = to_neighbour_frame(w.source, a, c, len);
    if(grazes_c) // line 22: the child's b1 ray grazes c, its new CH-relay vertex
      update_relay(child, child.relay_right, length(c - w.source));
    add_window(p, left, child);
  }

  // child on edge (b, c), in the frame of the neighbouring halfedge c -> b, from the rays of `w`
  // through [max(start, x), b1]
  void add_right_child(Patch& p, Index h, const Point& c, const Win& w, FT x, FT start, Index right)
  {
    const FT len = m_mesh.length(Mesh::next(h));
    const Point b{m_mesh.length(h), FT(0)};
    const bool grazes_c = start < x;
    const FT v0 = grazes_c ? FT(0) : ray_segment_parameter(w.source, Point{start, FT(0)}, c, b);
    const FT v1 = ray_segment_parameter(w.source, Point{w.b1, FT(0)}, c, b);
    if(!(v0 < v1))
      return;
    Win child = w;
    child.b0 = v0 * len;
    child.b1 = v1 * len;
    child.source = to_neighbour_frame(w.source, c, b - c, len);
    if(grazes_c) // line 22: the child's b0 ray grazes c
      update_relay(child, child.relay_left, length(c - w.source));
    add_window(p, right, child);
  }

  // ---------------------------------------------------------------------------------------------

  const Mesh& m_mesh;
  const FT m_bound_epsilon;           // epsilon of the distance bound (0: exact, no bound)
  const FT m_fan_half_width;          // radians added on both sides of a pseudo-source's fan
  // polar angles at a vertex (see Unfolded_mesh::corner_start_angle) of the directions back along
  // the shortest paths found so far; a range when several paths tie
  struct Incoming
  {
    FT low = FT(0);
    FT high = FT(0);
  };

  std::vector<FT> m_distance;         // per vertex: best distance found so far (+inf: not reached)
  std::vector<FT> m_committed;        // per border vertex: m_distance at the round's start
  std::vector<Incoming> m_incoming;   // per vertex: arrival directions of its best paths
  std::vector<char> m_in_region;      // per face: inside the propagation region R
  std::vector<char> m_scheduled;      // per halfedge: its window list is in its patch's FIFO
  std::vector<Index> m_owner;         // per vertex: the patch that pops it
  std::vector<char> m_on_border;      // per vertex: a face of another patch than its owner has it
  std::deque<Patch> m_patches;        // a deque: a patch never moves
  Index m_faces_per_patch = 0;
  FT m_band;                          // a round pops the vertices up to this beyond the nearest
  std::vector<char> m_is_source;      // per vertex: one of the sources (they emit all around)
  std::vector<std::vector<Index>> m_senders; // per patch: the patches whose outbox to it is not empty
  std::vector<char> m_receiving;      // per patch: in this round's delivery
  Propagation_statistics m_stats;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_WINDOW_PROPAGATION_H
