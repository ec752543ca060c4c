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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PATCH_PARTITION_H
#define CGAL_DGG_VTP_3_INTERNAL_PATCH_PARTITION_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/for_each_block.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The faces cut into patches of consecutive faces (the mesh orders them along a space-filling
// curve, so a patch is a compact piece of surface), which the propagation runs in rounds (see
// Round_scheduler). Their number depends on the mesh only, never on the number of threads.
// Computed once per mesh: every query of a solver shares it.
template <class FT>
class Patch_partition
{
public:
  using Index = std::uint32_t;

  Patch_partition() = default;
  // the vertices' owners computed as `ConcurrencyTag` says (for_each_block()), the same whatever it is
  template <class ConcurrencyTag>
  Patch_partition(const Unfolded_mesh<FT>& mesh, ConcurrencyTag)
  {
    using T = Tuning<FT>;
    const std::size_t nf = mesh.number_of_faces();
    const std::size_t count = (std::min)(T::max_patches(), (std::max)(std::size_t(1), nf / T::min_patch_faces()));
    m_faces_per_patch = Index((nf + count - 1) / count);
    m_patches = m_faces_per_patch == 0 ? 1 : (nf + m_faces_per_patch - 1) / m_faces_per_patch;
    // a vertex belongs to the patch of its first corner; it is on a border if a face of another
    // patch has it too
    const std::size_t nv = mesh.number_of_vertices();
    m_owner.assign(nv, 0);
    m_border_begin.assign(m_patches + 1, 0);
    std::vector<char> on_border(nv, 0);
    for_each_block<ConcurrencyTag>(nv, [&](std::size_t v0, std::size_t v1) {
      for(Index v = Index(v0); v < v1; ++v)
      {
        if(mesh.corners_begin(v) == mesh.corners_end(v))
          continue;
        m_owner[v] = patch_of_face(Unfolded_mesh<FT>::face(*mesh.corners_begin(v)));
        for(const Index* c = mesh.corners_begin(v); c != mesh.corners_end(v); ++c)
          if(patch_of_face(Unfolded_mesh<FT>::face(*c)) != m_owner[v])
            on_border[v] = 1;
      }
    });
    for(Index v = 0; v < nv; ++v)
      if(on_border[v])
        ++m_border_begin[m_owner[v] + 1];
    for(std::size_t p = 0; p < m_patches; ++p)
      m_border_begin[p + 1] += m_border_begin[p];
    m_border.resize(m_border_begin[m_patches]);
    std::vector<Index> fill(m_border_begin.begin(), m_border_begin.end() - 1);
    for(Index v = 0; v < nv; ++v)
      if(on_border[v])
        m_border[fill[m_owner[v]]++] = v;

    FT total(0); // in one order, whatever the tag: a sum in floating point depends on it
    for(Index h = 0; h < mesh.number_of_halfedges(); ++h)
      total += mesh.length(h);
    m_band = mesh.number_of_halfedges() == 0 ? number<FT>(0) : T::band_in_edges() * total / number<FT>(mesh.number_of_halfedges());
  }

  std::size_t size() const { return m_patches; }
  Index first_face(Index p) const { return p * m_faces_per_patch; }
  Index end_face(Index p, std::size_t nf) const { return Index((std::min)(nf, std::size_t(p + 1) * m_faces_per_patch)); }
  Index patch_of_face(Index f) const { return m_faces_per_patch == 0 ? 0 : f / m_faces_per_patch; }
  Index patch_of_halfedge(Index h) const { return patch_of_face(Unfolded_mesh<FT>::face(h)); }
  // the patch that pops `v` and keeps its distance
  Index owner(Index v) const { return m_owner[v]; }
  // the vertices patch `p` owns that faces of other patches have too
  const Index* border_begin(Index p) const { return m_border.data() + m_border_begin[p]; }
  const Index* border_end(Index p) const { return m_border.data() + m_border_begin[p + 1]; }
  // how far beyond the nearest vertex a round pops: Tuning::band_in_edges() mean edge lengths
  FT band() const { return m_band; }

private:
  Index m_faces_per_patch = 0;
  std::size_t m_patches = 1;
  std::vector<Index> m_owner;        // per vertex: the patch that owns it
  std::vector<Index> m_border_begin; // per patch + 1: CSR offsets into m_border
  std::vector<Index> m_border;       // border vertices grouped by owner
  FT m_band = number<FT>(0);
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PATCH_PARTITION_H
