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

#ifndef CGAL_DGG_VTP_3_INTERNAL_GEODESIC_GRAPH_BUILD_H
#define CGAL_DGG_VTP_3_INTERNAL_GEODESIC_GRAPH_BUILD_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_pool.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window_propagation.h>

#include <CGAL/assertions.h>
#include <CGAL/for_each.h>
#include <CGAL/tags.h>

#include <boost/range/irange.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The build runs of the certified geodesic graph (an experiment, not a class of the package: see
// Direct_distances and benchmark/DGG_VTP_3/README.md, Table 14). One direct-only propagation on
// `mesh` (patches `partition`) from each of `vertices`, each on one thread, the runs shared among
// threads as `ConcurrencyTag` says: `out(k, reached, w, statistics)` as the k-th is done, `w` per
// vertex the weight of its edge from vertices[k] (+infinity: no edge; 0 at vertices[k]), finite
// only among `reached`, the numbers of the vertices the run reached. `accuracy` > 0.
template <class ConcurrencyTag, class FT, class Out>
void geodesic_graph_build_runs(const Unfolded_mesh<FT>& mesh, const Patch_partition<FT>& partition,
                               const std::vector<std::uint32_t>& vertices, FT accuracy, const Out& out)
{
  using Propagation = Window_propagation<FT, true>;
  CGAL_precondition(accuracy > FT(0));
  Propagation_pool<Propagation> pool;
  CGAL::for_each<ConcurrencyTag>(boost::irange(std::size_t(0), vertices.size()), [&](std::size_t k) {
    Propagation_query<FT> query;
    query.vertex_sources.assign(1, vertices[k]);
    query.source_numbers.assign(1, 0);
    const auto lease = pool.take([&] { return std::make_unique<Propagation>(mesh, partition); });
    lease->template run<Sequential_tag>(query, accuracy);
    out(k, lease->reached(), lease->direct_distances(), lease->statistics());
    return true;
  });
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_GEODESIC_GRAPH_BUILD_H
