// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// NumPy's .npy format, version 1.0, for a C-ordered 2D array of float32 or float64
// (https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html): the header, and the
// offset of each row after it. Shared by the command-line programs.

#ifndef DGGVTP_NPY_H
#define DGGVTP_NPY_H

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace dggvtp {

// The element type of an .npy array: 4 or 8 bytes, IEEE 754, in the byte order of this machine.
enum class Npy_dtype { float32, float64 };

inline std::size_t npy_item_size(Npy_dtype dtype) { return dtype == Npy_dtype::float32 ? 4 : 8; }

// NumPy's mark of the byte order of this machine, that of the values written: '<' or '>'
inline char npy_byte_order()
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  return '>';
#else
  return '<';
#endif
}

// NumPy's name of the type: '<f4', '<f8' (or '>' on a big-endian machine)
inline std::string npy_descr(Npy_dtype dtype)
{
  return std::string(1, npy_byte_order()) + (dtype == Npy_dtype::float32 ? "f4" : "f8");
}

// The bytes before the data of a rows x columns array: the magic string, the version (1.0), the
// header's length (2 bytes, little-endian) and the header, a Python dict literal padded with
// spaces and ended by '\n' so that the data starts at a multiple of 64 bytes.
// The header of a .npy file, format version 1.0, of an array of `descr` values (e.g. "<f8") of
// shape `shape` (a Python tuple, e.g. "(3,)"): the magic string, the version, the length of the
// dictionary (little-endian), and the dictionary padded with spaces and ended by a newline so that
// the data starts at a multiple of 64 bytes.
inline std::string npy_header(const std::string& descr, const std::string& shape)
{
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  const std::size_t prefix = 10; // "\x93NUMPY", 2 version bytes, 2 length bytes
  const std::size_t total = (prefix + dict.size() + 1 + 63) / 64 * 64;
  dict.append(total - prefix - dict.size() - 1, ' ');
  dict += '\n';
  if(dict.size() > 0xffff)
    throw std::length_error("npy header longer than version 1.0 allows");
  std::string out("\x93NUMPY\x01\x00", 8);
  out += char(dict.size() & 0xff);
  out += char(dict.size() >> 8);
  return out + dict;
}

inline std::string npy_header(Npy_dtype dtype, std::size_t rows, std::size_t columns)
{
  return npy_header(npy_descr(dtype), "(" + std::to_string(rows) + ", " + std::to_string(columns) + ")");
}

// The size in bytes of the whole file; throws std::overflow_error if it does not fit in 63 bits
// (the offsets of MPI-IO and of pwrite are signed).
inline std::uint64_t npy_file_size(Npy_dtype dtype, std::size_t rows, std::size_t columns)
{
  const std::uint64_t limit = std::uint64_t(std::numeric_limits<std::int64_t>::max());
  const std::uint64_t header = npy_header(dtype, rows, columns).size();
  const std::uint64_t row_bytes = std::uint64_t(columns) * npy_item_size(dtype);
  if(columns != 0 && (row_bytes / npy_item_size(dtype) != columns || (rows != 0 && row_bytes > (limit - header) / rows)))
    throw std::overflow_error("an array of " + std::to_string(rows) + " x " + std::to_string(columns) +
                              " values is too large for one file");
  return header + std::uint64_t(rows) * row_bytes;
}

} // namespace dggvtp

#endif // DGGVTP_NPY_H
