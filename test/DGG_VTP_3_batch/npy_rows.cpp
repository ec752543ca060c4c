// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Test helper of dggvtp-batch: checks that a file is a 2D float32/float64 .npy as NumPy writes
// it (version 1.0, header padded to a multiple of 64 bytes and ended by '\n', C order, the size
// the shape says) and prints it for the tests to compare with dggvtp, without NumPy.
// usage: npy_rows FILE          prints "ROWS COLUMNS DTYPE"
//        npy_rows FILE ROW      prints row ROW as dggvtp --output does: one %.17g value per line
//                               (float32 values widened to double), "inf" when unreachable
// Exit status 1 if the file is not such an .npy file (with a message on stderr).

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <regex>
#include <string>

int main(int argc, char** argv)
{
  if(argc != 2 && argc != 3)
  {
    std::cerr << "usage: npy_rows FILE [ROW]\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto bad = [&](const std::string& why) {
    std::cerr << "npy_rows: " << argv[1] << ": " << why << "\n";
    return 1;
  };
  if(bytes.size() < 10 || bytes.compare(0, 8, std::string("\x93NUMPY\x01\x00", 8)) != 0)
    return bad("not an .npy file of version 1.0");
  const std::size_t header_length = std::size_t(static_cast<unsigned char>(bytes[8])) |
                                    std::size_t(static_cast<unsigned char>(bytes[9])) << 8;
  const std::size_t data = 10 + header_length;
  if(data % 64 != 0 || bytes.size() < data || bytes[data - 1] != '\n')
    return bad("header not padded to 64 bytes or not ended by a newline");
  const std::string header = bytes.substr(10, header_length);
  std::smatch match;
  if(!std::regex_match(header, match,
                       std::regex(R"(\{'descr': '<(f4|f8)', 'fortran_order': False, 'shape': \((\d+), (\d+)\), \} *\n)")))
    return bad("unexpected header: " + header);
  const std::string dtype = match[1] == "f4" ? "float32" : "float64";
  const std::size_t item = match[1] == "f4" ? 4 : 8;
  const std::size_t rows = std::stoull(match[2]), columns = std::stoull(match[3]);
  if(bytes.size() != data + rows * columns * item)
    return bad("the file has " + std::to_string(bytes.size()) + " bytes, the shape says " +
               std::to_string(data + rows * columns * item));
  if(argc == 2)
  {
    std::cout << rows << " " << columns << " " << dtype << "\n";
    return 0;
  }
  const std::size_t row = std::stoull(argv[2]);
  if(row >= rows)
    return bad("no row " + std::to_string(row));
  std::string out;
  char text[40];
  for(std::size_t c = 0; c < columns; ++c)
  {
    double value;
    const char* p = bytes.data() + data + (row * columns + c) * item;
    if(item == 4)
    {
      float f;
      std::memcpy(&f, p, 4);
      value = f;
    }
    else
      std::memcpy(&value, p, 8);
    char* end = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 17).ptr;
    out.append(text, end);
    out += '\n';
  }
  std::cout << out;
  return 0;
}
