// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// dggvtp-batch --max-distance's output: a sparse matrix in the .npz file that
// scipy.sparse.save_npz(file, matrix, compressed=False) writes and scipy.sparse.load_npz reads:
// a ZIP archive of uncompressed .npy members indices, indptr, format (b'csr'), shape and data, in
// that order, as numpy.savez writes them (it forces ZIP64 on every member).
//
// Every size and offset goes in ZIP64 fields, in the local and central headers and the end
// records (the 32-bit fields hold 0xFFFFFFFF, as the format allows): one way of writing, the one
// the tests read, whatever the size of the file (beyond 4 GiB too). Times are 1980-01-01 00:00, so
// that the same matrix gives the same bytes.

#ifndef DGGVTP_NPZ_H
#define DGGVTP_NPZ_H

#include <dggvtp/npy.h>

#include <boost/crc.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace dggvtp {

// Writes the archive through `write(bytes, size)`, member by member: add() takes the member's
// bytes as a function that hands them, in pieces, to its argument; it is called twice, once for
// their CRC-32 and size (the local header comes before them) and once to write them.
class Npz_writer
{
public:
  using Sink = std::function<void(const char*, std::size_t)>;
  using Bytes = std::function<void(const Sink&)>;

  explicit Npz_writer(Sink write) : m_write(std::move(write)) {}

  // the member NAME.npy: `header` (npy_header()), then the values that `values` gives
  void add(const std::string& name, const std::string& header, const Bytes& values)
  {
    boost::crc_32_type crc;
    std::uint64_t size = header.size();
    crc.process_bytes(header.data(), header.size());
    values([&](const char* bytes, std::size_t n) {
      crc.process_bytes(bytes, n);
      size += n;
    });
    Member m{name + ".npy", crc.checksum(), size, m_offset};
    std::string local;
    put32(local, 0x04034b50);
    put_common(local, m);
    put16(local, 20); // extra field: ZIP64, the sizes
    local += m.name;
    put16(local, 0x0001);
    put16(local, 16);
    put64(local, m.size);
    put64(local, m.size);
    emit(local);
    emit(header);
    values([&](const char* bytes, std::size_t n) { emit(bytes, n); });
    m_members.push_back(m);
  }

  // the central directory and the end records
  void finish()
  {
    const std::uint64_t directory = m_offset;
    for(const Member& m : m_members)
    {
      std::string central;
      put32(central, 0x02014b50);
      put16(central, (3 << 8) | 45); // made by: Unix, ZIP 4.5
      put_common(central, m);
      put16(central, 28); // extra field: ZIP64, the sizes and the offset
      put16(central, 0);  // comment
      put16(central, 0);  // disk
      put16(central, 0);  // internal attributes
      put32(central, std::uint32_t(0644) << 16); // external: a regular file, rw-r--r--
      put32(central, 0xffffffff);
      central += m.name;
      put16(central, 0x0001);
      put16(central, 24);
      put64(central, m.size);
      put64(central, m.size);
      put64(central, m.offset);
      emit(central);
    }
    const std::uint64_t end_of_directory = m_offset;
    std::string end;
    put32(end, 0x06064b50); // ZIP64 end of central directory record
    put64(end, 44);
    put16(end, 45);
    put16(end, 45);
    put32(end, 0);
    put32(end, 0);
    put64(end, m_members.size());
    put64(end, m_members.size());
    put64(end, end_of_directory - directory);
    put64(end, directory);
    put32(end, 0x07064b50); // its locator
    put32(end, 0);
    put64(end, end_of_directory);
    put32(end, 1);
    put32(end, 0x06054b50); // end of central directory record, its fields in the ZIP64 one
    put16(end, 0);
    put16(end, 0);
    put16(end, 0xffff);
    put16(end, 0xffff);
    put32(end, 0xffffffff);
    put32(end, 0xffffffff);
    put16(end, 0);
    emit(end);
  }

private:
  struct Member
  {
    std::string name;
    std::uint32_t crc;
    std::uint64_t size; // stored: compressed and uncompressed alike
    std::uint64_t offset;
  };

  static void put16(std::string& out, std::uint32_t v)
  {
    for(int i = 0; i < 2; ++i)
      out += char((v >> (8 * i)) & 0xff);
  }
  static void put32(std::string& out, std::uint32_t v)
  {
    for(int i = 0; i < 4; ++i)
      out += char((v >> (8 * i)) & 0xff);
  }
  static void put64(std::string& out, std::uint64_t v)
  {
    for(int i = 0; i < 8; ++i)
      out += char((v >> (8 * i)) & 0xff);
  }
  // from the version needed to the name's length: the same in the local and the central header
  static void put_common(std::string& out, const Member& m)
  {
    put16(out, 45); // version needed: ZIP64
    put16(out, 0);  // flags
    put16(out, 0);  // stored
    put16(out, 0);  // time 00:00
    put16(out, (0 << 9) | (1 << 5) | 1); // date 1980-01-01
    put32(out, m.crc);
    put32(out, 0xffffffff); // sizes: in the ZIP64 field
    put32(out, 0xffffffff);
    put16(out, std::uint32_t(m.name.size()));
  }
  void emit(const std::string& bytes) { emit(bytes.data(), bytes.size()); }
  void emit(const char* bytes, std::size_t n)
  {
    m_write(bytes, n);
    m_offset += n;
  }

  Sink m_write;
  std::uint64_t m_offset = 0;
  std::vector<Member> m_members;
};

// A CSR matrix of `rows` (Sparse_row-like: columns, values) by `columns` through `write`, as
// scipy.sparse.save_npz(compressed=False) writes it: data in `dtype`, indices and indptr in int32
// when the entries and the columns fit in it (as SciPy chooses), int64 otherwise.
template <class Rows>
void write_csr_npz(const Rows& rows, std::size_t columns, Npy_dtype dtype, const Npz_writer::Sink& write)
{
  std::uint64_t nonzeros = 0;
  for(const auto& r : rows)
    nonzeros += r.columns.size();
  const std::uint64_t int32_max = 0x7fffffff;
  const bool wide = nonzeros > int32_max || columns > int32_max;
  const std::string order(1, npy_byte_order());
  const std::string index = order + (wide ? "i8" : "i4");
  const std::string count = "(" + std::to_string(nonzeros) + ",)";
  // each value in the bytes of type T, in blocks
  const auto in_blocks = [](const Npz_writer::Sink& sink, auto each) {
    std::vector<char> block;
    each([&](auto value) {
      const char* bytes = reinterpret_cast<const char*>(&value);
      block.insert(block.end(), bytes, bytes + sizeof value);
      if(block.size() >= (1 << 20))
      {
        sink(block.data(), block.size());
        block.clear();
      }
    });
    sink(block.data(), block.size());
  };
  const auto as_index = [wide](auto& put, std::uint64_t v) {
    if(wide)
      put(std::int64_t(v));
    else
      put(std::int32_t(v));
  };
  Npz_writer npz(write);
  npz.add("indices", npy_header(index, count), [&](const Npz_writer::Sink& sink) {
    in_blocks(sink, [&](auto put) {
      for(const auto& r : rows)
        for(const auto c : r.columns)
          as_index(put, c);
    });
  });
  npz.add("indptr", npy_header(index, "(" + std::to_string(rows.size() + 1) + ",)"), [&](const Npz_writer::Sink& sink) {
    in_blocks(sink, [&](auto put) {
      std::uint64_t at = 0;
      as_index(put, at);
      for(const auto& r : rows)
        as_index(put, at += r.columns.size());
    });
  });
  npz.add("format", npy_header("|S3", "()"), [](const Npz_writer::Sink& sink) { sink("csr", 3); });
  npz.add("shape", npy_header(order + "i8", "(2,)"), [&](const Npz_writer::Sink& sink) {
    in_blocks(sink, [&](auto put) {
      put(std::int64_t(rows.size()));
      put(std::int64_t(columns));
    });
  });
  npz.add("data", npy_header(npy_descr(dtype), count), [&](const Npz_writer::Sink& sink) {
    in_blocks(sink, [&](auto put) {
      for(const auto& r : rows)
        for(const double v : r.values)
          if(dtype == Npy_dtype::float32)
            put(float(v));
          else
            put(v);
    });
  });
  npz.finish();
}

} // namespace dggvtp

#endif // DGGVTP_NPZ_H
