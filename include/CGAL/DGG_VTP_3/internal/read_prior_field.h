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

#ifndef CGAL_DGG_VTP_3_INTERNAL_READ_PRIOR_FIELD_H
#define CGAL_DGG_VTP_3_INTERNAL_READ_PRIOR_FIELD_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/parameters.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/as_given.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The prior field of the named parameters prior_distance_map, prior_nearest_source_map and
// prior_lower_bound_map, per vertex of `numbering` (an Unfolded_numbering; errors name the user's
// numbers), checked: a distance >= 0 or +infinity, a
// label where it is finite, a lower bound in [0, distance] (without one: distance / (1 +
// accuracy), which the contract of the prior field makes a lower bound). Returns the number the
// first new source takes: one beyond the largest label.
template <class FT, class Numbering, class NamedParameters>
std::uint32_t read_prior_field(const Numbering& numbering, FT accuracy, const NamedParameters& np,
                               Prior_field<FT>& field)
{
  using Index = std::uint32_t;
  const auto distances = parameters::get_parameter(np, internal_np::prior_distance_map_t());
  const std::size_t nv = numbering.number_of_vertices();
  const FT infinity = Number_type_math<FT>::infinity();
  field.distance.assign(nv, infinity);
  field.lower_bound.assign(nv, infinity);
  field.origin.assign(nv, Index(-1));
  const std::size_t most_labels = std::size_t(Index(-1)) - nv - 1; // origins are labels + nv
  std::size_t next = 0;
  for(std::size_t i = 0; i < nv; ++i)
  {
    const auto v = numbering.vertex(i);
    const double d = CGAL::to_double(get(distances, v));
    if(!(d >= 0.))
      throw std::invalid_argument("the prior distance of vertex " + std::to_string(numbering.user_number(i)) +
                                  " must be >= 0 or +infinity; got " + as_given(d));
    if(d == std::numeric_limits<double>::infinity())
      continue;
    field.distance[i] = FT(get(distances, v));
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::prior_nearest_source_map_t>::value)
    {
      const std::size_t label = get(parameters::get_parameter(np, internal_np::prior_nearest_source_map_t()), v);
      if(label >= most_labels)
        throw std::invalid_argument("the prior nearest source of vertex " + std::to_string(numbering.user_number(i)) +
                                    " must be a source's number where its distance is finite; got " +
                                    std::to_string(label));
      field.origin[i] = Index(nv + label);
      next = (std::max)(next, label + 1);
    }
    field.lower_bound[i] = field.distance[i] / (FT(1) + accuracy);
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::prior_lower_bound_map_t>::value)
    {
      const auto lower = get(parameters::get_parameter(np, internal_np::prior_lower_bound_map_t()), v);
      if(!(CGAL::to_double(lower) >= 0. && FT(lower) <= field.distance[i]))
        throw std::invalid_argument("the prior lower bound of vertex " + std::to_string(numbering.user_number(i)) +
                                    " must be in [0, its prior distance]; got " + as_given(CGAL::to_double(lower)));
      field.lower_bound[i] = FT(lower);
    }
  }
  return Index(next);
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_READ_PRIOR_FIELD_H
