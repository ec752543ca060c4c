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

#ifndef CGAL_DGG_VTP_3_INTERNAL_ROUND_SCHEDULER_H
#define CGAL_DGG_VTP_3_INTERNAL_ROUND_SCHEDULER_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <CGAL/assertions.h>
#include <CGAL/for_each.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Runs a propagation split into the patches of a Patch_partition, in rounds, so that the
// patches of a round may run on any threads in any order with the same results bit for bit.
//
// In a round, every patch with work pops its vertices nearer than the round's limit (the nearest
// vertex of all, plus the partition's band) and propagates its window lists, as the sequential
// algorithm does; what it does to the rest of the mesh (a window into another patch's list, a
// distance of another patch's vertex, a face entering the region R there) is handed off to the
// scheduler and waits in an outbox until the round ends, and the distances of other patches'
// vertices it reads are those of the round's start. So each patch's round depends on the
// round's start only. Outboxes are delivered, receiver by receiver, in the order of the senders.
// A round visits only the patches the propagation has woken (its sources', and those that were
// sent something): a query that reaches a few patches costs no time in the others.
//
// `Propagation` runs Algorithm 1 on one patch at a time; what the scheduler asks of it:
//   FT nearest_queued(p)            drops superseded queue entries, the nearest left (+inf: none)
//   bool has_lists_to_propagate(p)  window lists scheduled in p's FIFO
//   void run_round(p, limit)
//   std::size_t take_peak(p)        windows alive at once in p since the last call
//   void receive(p, message)        for each kind of message below
//   bool schedule_stranded_lists(active)
//   const std::vector<FT>& distances()
//   bool query_is_answered(nearest) every distance the query needs is final, `nearest` being
//                                   the nearest queued vertex of all patches
//   FT pop_limit()                  no vertex beyond it matters to the query (+inf: every one),
//                                   as of the last query_is_answered()
template <class FT>
class Round_scheduler
{
public:
  using Index = std::uint32_t;

  // the four things a patch may do to another one
  struct Window_message
  {
    Index halfedge;
    Window<FT> window;
  };
  struct Relax_message
  {
    Index vertex;
    FT distance;
    FT key;
    Index corner;
    Vec2<FT> direction;
    Index origin;
  };
  struct Face_message
  {
    Index face;
  };
  struct Relay_message // a window stopped, relying on this vertex
  {
    Index vertex;
  };

  Round_scheduler(const Patch_partition<FT>& partition, std::size_t number_of_vertices)
    : m_partition(partition)
    , m_committed(number_of_vertices, Number_type_math<FT>::infinity())
    , m_outbox(partition.size(), std::vector<Outbox>(partition.size()))
    , m_recipients(partition.size())
    , m_inbox(partition.size())
    , m_receiving(partition.size(), 0)
    , m_awake(partition.size(), 0)
  {}

  // for the next propagation: no patch awake, no message waiting (a propagation that threw may
  // have left some), every distance committed +infinity but those of the vertices `reached`,
  // which the last one set
  void reset(const std::vector<Index>& reached)
  {
    for(Index v : reached)
      m_committed[v] = Number_type_math<FT>::infinity();
    for(Index p : m_woken) // only a woken patch has sent or received anything
    {
      for(Index q : m_recipients[p])
        m_outbox[p][q] = Outbox();
      m_recipients[p].clear();
      m_inbox[p].clear();
      m_receiving[p] = 0;
      m_awake[p] = 0;
    }
    m_woken.clear();
  }

  // patch `p` has work (a source, a window put there from outside the rounds)
  void wake(Index p)
  {
    if(m_awake[p])
      return;
    m_awake[p] = 1;
    m_woken.insert(std::lower_bound(m_woken.begin(), m_woken.end(), p), p);
  }

  // the patches woken since reset(), in increasing order: the others have done nothing
  const std::vector<Index>& woken() const { return m_woken; }

  // ---- what a patch sees of the others during a round ----------------------------------------

  // The hand-off point: a `Message` made of `args` from patch `from` concerns patch `to`. If that
  // is another patch, the message waits in the outbox until the round ends (returns true); if
  // not, the caller applies it itself (returns false, and no message is made).
  template <class Message, class... Args>
  bool hand_off(Index from, Index to, const Args&... args)
  {
    if(to == from)
      return false;
    Outbox& box = m_outbox[from][to];
    if(box.empty())
      m_recipients[from].push_back(to);
    box.push(Message{args...});
    return true;
  }

  // the distance of vertex `v` as patch `p` may read it during a round
  FT distance_seen(Index p, Index v, const std::vector<FT>& distance) const
  {
    return m_partition.owner(v) == p ? distance[v] : m_committed[v];
  }

  // a distance set outside the rounds (the sources')
  void commit(Index v, FT d) { m_committed[v] = d; }
  // those of every border vertex (a prior field's, see Propagation_vertices::keep_field)
  void commit_borders(const std::vector<FT>& distance)
  {
    for(Index p = 0; p < Index(m_partition.size()); ++p)
      for(const Index* v = m_partition.border_begin(p); v != m_partition.border_end(p); ++v)
        m_committed[*v] = distance[*v];
  }

  // ---- the rounds ----------------------------------------------------------------------------

  template <class ConcurrencyTag, class Propagation>
  void run(Propagation& propagation, std::size_t& windows_peak)
  {
    std::vector<Index> active;
    for(;;)
    {
      FT nearest = Number_type_math<FT>::infinity();
      active.clear();
      for(Index p : m_woken)
      {
        const FT queued = propagation.nearest_queued(p);
        nearest = (std::min)(nearest, queued);
        if(propagation.has_lists_to_propagate(p) || queued < Number_type_math<FT>::infinity())
          active.push_back(p);
      }
      // early termination ends the rounds of the full propagation, it does not change them
      if(propagation.query_is_answered(nearest) || (active.empty() && !propagation.schedule_stranded_lists(active)))
        break;
      // the band, or less where the query needs no more (but at least the nearest vertex: see
      // pop_limit())
      const FT limit = (std::min)(nearest + m_partition.band(), (std::max)(propagation.pop_limit(), nearest));
      CGAL::for_each<ConcurrencyTag>(active, [&](Index p) { propagation.run_round(p, limit); return true; });
      // an upper bound of the windows alive at once during the round
      std::size_t peak = 0;
      for(Index p : m_woken)
        peak += propagation.take_peak(p);
      windows_peak = (std::max)(windows_peak, peak);
      deliver<ConcurrencyTag>(propagation, active);
      propagation.report_progress(); // between rounds: on the caller's thread, never in a patch's
    }
    CGAL_assertion(all_delivered());
  }

  // whether no message waits: true after deliver_now() and run()
  bool all_delivered() const
  {
    for(Index p : m_woken)
      if(!m_recipients[p].empty())
        return false;
    return true;
  }

  // delivers what was handed off outside the rounds (the sources' first windows and distances)
  template <class ConcurrencyTag, class Propagation>
  void deliver_now(Propagation& propagation)
  {
    deliver<ConcurrencyTag>(propagation, std::vector<Index>());
  }

private:
  struct Outbox
  {
    std::vector<Window_message> windows;
    std::vector<Relax_message> relaxations;
    std::vector<Face_message> faces; // entering R
    std::vector<Relay_message> relays;
    bool empty() const { return windows.empty() && relaxations.empty() && faces.empty() && relays.empty(); }
    void push(const Window_message& m) { windows.push_back(m); }
    void push(const Relax_message& m) { relaxations.push_back(m); }
    void push(const Face_message& m) { faces.push_back(m); }
    void push(const Relay_message& m) { relays.push_back(m); }
  };

  // The outboxes of the round, each patch receiving from the others in the order of their ids,
  // then the distances of the border vertices that other patches read. What a patch receives may
  // make it send more (a distance relayed to a vertex's copies in other patches): those messages
  // are delivered in the same way, wave after wave, until none is left, so that the round ends
  // with every outbox empty, whatever early termination does next. A wave's messages are taken
  // out of the outboxes before it starts: the receivers fill outboxes of their own meanwhile,
  // which no other thread reads, and each receiver's order depends on the data only.
  template <class ConcurrencyTag, class Propagation>
  void deliver(Propagation& propagation, const std::vector<Index>& ran)
  {
    std::vector<Index> receivers;
    const auto receive = [&](Index q) {
      if(!m_receiving[q])
      {
        m_receiving[q] = 1;
        receivers.push_back(q);
      }
    };
    for(Index p : ran) // their border vertices may have changed, even with nothing to receive
      receive(p);
    const std::vector<FT>& distance = propagation.distances();
    for(;;)
    {
      for(Index p : m_woken) // only a woken patch has sent anything
      {
        for(Index q : m_recipients[p])
        {
          receive(q);
          m_inbox[q].push_back(std::move(m_outbox[p][q]));
          m_outbox[p][q] = Outbox(); // its memory goes with the messages: some pairs talk in a few rounds only
        }
        m_recipients[p].clear();
      }
      if(receivers.empty())
        break;
      for(Index q : receivers)
        wake(q);
      CGAL::for_each<ConcurrencyTag>(receivers, [&](Index q) {
        for(const Outbox& box : m_inbox[q]) // in the order of the senders
        {
          for(const Window_message& m : box.windows)
            propagation.receive(q, m);
          for(const Relax_message& m : box.relaxations)
            propagation.receive(q, m);
          for(const Face_message& m : box.faces)
            propagation.receive(q, m);
          for(const Relay_message& m : box.relays) // after the distances the windows gave them
            propagation.receive(q, m);
        }
        m_inbox[q].clear();
        m_receiving[q] = 0;
        // only the patches that ran or received changed their vertices' distances
        for(const Index* v = m_partition.border_begin(q); v != m_partition.border_end(q); ++v)
          m_committed[*v] = distance[*v];
        return true;
      });
      receivers.clear();
    }
  }

  const Patch_partition<FT>& m_partition;
  std::vector<FT> m_committed;                 // per border vertex: its distance at the round's start
  std::vector<std::vector<Outbox>> m_outbox;   // per sender, per receiver
  std::vector<std::vector<Index>> m_recipients; // per sender: the patches whose outbox is not empty
  std::vector<std::vector<Outbox>> m_inbox;    // per receiver: its senders' outboxes in this wave
  std::vector<char> m_receiving;               // per patch: in this round's delivery
  std::vector<char> m_awake;                   // per patch: in m_woken
  std::vector<Index> m_woken;                  // see woken()
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_ROUND_SCHEDULER_H
