// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Local distance matrices: of each field, only the file vertices within its maximum distance, as
// the rows of a CSR matrix (the Python module's local_distance_matrix, dggvtp-batch
// --max-distance), so that the memory is in proportion to the distances kept.

#ifndef DGGVTP_SPARSE_ROWS_H
#define DGGVTP_SPARSE_ROWS_H

#include <dggvtp/loaded_soup.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace dggvtp {

// One row: the file vertices that a field reaches, in increasing order, and their distances
struct Sparse_row
{
  std::vector<std::uint32_t> columns;
  std::vector<double> values;
};

// The row of the field `d` whose vertices are the file's (one per file vertex, +infinity where
// unreached)
template <class FT>
void sparse_row(const std::vector<FT>& d, Sparse_row& row)
{
  // the exact size: rows are kept by the thousand, so their slack would add up to their size
  const std::size_t size =
    std::size_t(std::count_if(d.begin(), d.end(), [](const FT& x) { return !std::isinf(x); }));
  row.columns.clear();
  row.values.clear();
  row.columns.reserve(size);
  row.values.reserve(size);
  for(std::size_t i = 0; i < d.size(); ++i)
    if(!std::isinf(d[i]))
    {
      row.columns.push_back(std::uint32_t(i));
      row.values.push_back(double(d[i]));
    }
}

// The row of the field `d` (per solver vertex of `soup`, +infinity where unreached): per file
// vertex the smallest distance of its copies, as file_vertex_distances() gives it, the same bits;
// a file vertex of `merged` (file vertex -> the lost vertices merged into it by a repair, see
// Repair_record::merged_into(); may be null) gives its distance to those too.
template <class FT>
void sparse_row(const Loaded_soup& soup, const std::vector<FT>& d,
                const std::map<std::size_t, std::vector<std::size_t>>* merged, Sparse_row& row)
{
  if(soup.file_vertex_of.size() == soup.file_vertices && (!merged || merged->empty()))
    return sparse_row(d, row); // the solver's vertices are the file's
  row.columns.clear();
  row.values.clear();
  std::vector<std::pair<std::uint32_t, double>> entries;
  for(std::size_t i = 0; i < d.size(); ++i)
    if(!std::isinf(d[i]))
    {
      const std::size_t v = soup.file_vertex_of[i];
      entries.emplace_back(std::uint32_t(v), double(d[i]));
      if(merged)
        if(const auto m = merged->find(v); m != merged->end())
          for(std::size_t lost : m->second)
            entries.emplace_back(std::uint32_t(lost), double(d[i]));
    }
  std::sort(entries.begin(), entries.end()); // by vertex, then distance: the smallest first
  row.columns.reserve(entries.size());
  row.values.reserve(entries.size());
  for(const auto& [v, value] : entries)
    if(row.columns.empty() || row.columns.back() != v)
    {
      row.columns.push_back(v);
      row.values.push_back(value);
    }
}

} // namespace dggvtp

#endif // DGGVTP_SPARSE_ROWS_H
