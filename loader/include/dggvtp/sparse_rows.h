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

// The row of the field `d` (per solver vertex of `soup`, +infinity where unreached) from the
// solver vertices `reached`, which hold every finite distance of `d` (the propagation's reached
// vertices: see compute_distances_from_each_source_set), so that a row costs what its field
// reaches, not the size of the mesh: per file vertex the smallest distance of its copies, as
// file_vertex_distances() gives it, the same bits; a file vertex of `merged` (file vertex -> the
// lost vertices merged into it by a repair, see Repair_record::merged_into(); may be null) gives
// its distance to those too.
template <class FT, class Index>
void sparse_row(const Loaded_soup& soup, const std::vector<FT>& d, const std::vector<Index>& reached,
                const std::map<std::size_t, std::vector<std::size_t>>* merged, Sparse_row& row)
{
  std::vector<std::pair<std::uint32_t, double>> entries;
  for(const Index i : reached)
    if(!std::isinf(d[i]))
    {
      const std::size_t v = soup.file_vertex_of.empty() ? std::size_t(i) : soup.file_vertex_of[i];
      entries.emplace_back(std::uint32_t(v), double(d[i]));
      if(merged && !merged->empty())
        if(const auto m = merged->find(v); m != merged->end())
          for(std::size_t lost : m->second)
            entries.emplace_back(std::uint32_t(lost), double(d[i]));
    }
  std::sort(entries.begin(), entries.end()); // by vertex, then distance: the smallest first
  // the exact size: rows are kept by the thousand, so their slack would add up to their size
  std::size_t size = 0;
  for(std::size_t k = 0; k < entries.size(); ++k)
    size += k == 0 || entries[k].first != entries[k - 1].first;
  row.columns.clear();
  row.values.clear();
  row.columns.reserve(size);
  row.values.reserve(size);
  for(const auto& [v, value] : entries)
    if(row.columns.empty() || row.columns.back() != v)
    {
      row.columns.push_back(v);
      row.values.push_back(value);
    }
}

// The transpose of the matrix of `rows` (rows.size() x `columns`), as rows: row j holds the
// entries of column j, in increasing row.
inline std::vector<Sparse_row> transposed(const std::vector<Sparse_row>& rows, std::size_t columns)
{
  std::vector<std::size_t> count(columns, 0);
  for(const Sparse_row& r : rows)
    for(std::uint32_t c : r.columns)
      ++count[c];
  std::vector<Sparse_row> t(columns);
  for(std::size_t j = 0; j < columns; ++j)
  {
    t[j].columns.reserve(count[j]);
    t[j].values.reserve(count[j]);
  }
  for(std::size_t k = 0; k < rows.size(); ++k)
    for(std::size_t e = 0; e < rows[k].columns.size(); ++e)
    {
      t[rows[k].columns[e]].columns.push_back(std::uint32_t(k));
      t[rows[k].columns[e]].values.push_back(rows[k].values[e]);
    }
  return t;
}

// The square matrix of `rows` made symmetric: each entry the smaller of (i, j) and (j, i), an
// entry present in one direction only (the other beyond the radius) taking that one's distance.
// Holds the transpose while merging: up to three copies of the matrix at the peak.
inline void make_symmetric(std::vector<Sparse_row>& rows)
{
  std::vector<Sparse_row> t = transposed(rows, rows.size());
  for(std::size_t i = 0; i < rows.size(); ++i)
  {
    const Sparse_row& a = rows[i];
    const Sparse_row& b = t[i];
    Sparse_row m;
    std::size_t x = 0, y = 0;
    while(x < a.columns.size() || y < b.columns.size())
    {
      if(y == b.columns.size() || (x < a.columns.size() && a.columns[x] < b.columns[y]))
      {
        m.columns.push_back(a.columns[x]);
        m.values.push_back(a.values[x++]);
      }
      else if(x == a.columns.size() || b.columns[y] < a.columns[x])
      {
        m.columns.push_back(b.columns[y]);
        m.values.push_back(b.values[y++]);
      }
      else
      {
        m.columns.push_back(a.columns[x]);
        m.values.push_back((std::min)(a.values[x++], b.values[y++]));
      }
    }
    m.columns.shrink_to_fit();
    m.values.shrink_to_fit();
    rows[i] = std::move(m);
    t[i] = Sparse_row();
  }
}

} // namespace dggvtp

#endif // DGGVTP_SPARSE_ROWS_H
