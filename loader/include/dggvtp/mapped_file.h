// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_MAPPED_FILE_H
#define DGGVTP_MAPPED_FILE_H

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <string>

namespace dggvtp {

// A regular file's bytes, mapped read-only for one pass of a reader: no copy into a buffer, and
// the pages go back to the page cache when the object dies (they do not stay in the process's
// peak memory beyond loading). Anything but a non-empty regular file that maps is `!valid()`:
// the caller then takes the path that reports why.
class Mapped_file
{
public:
  explicit Mapped_file(const std::string& path)
  {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if(fd < 0)
      return;
    struct stat status;
    if(::fstat(fd, &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0)
    {
      void* bytes = ::mmap(nullptr, std::size_t(status.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
      if(bytes != MAP_FAILED)
      {
        m_data = static_cast<const char*>(bytes);
        m_size = std::size_t(status.st_size);
        ::madvise(bytes, m_size, MADV_SEQUENTIAL);
      }
    }
    ::close(fd);
  }
  Mapped_file(const Mapped_file&) = delete;
  Mapped_file& operator=(const Mapped_file&) = delete;
  ~Mapped_file()
  {
    if(m_data != nullptr)
      ::munmap(const_cast<char*>(m_data), m_size);
  }

  bool valid() const { return m_data != nullptr; }
  const char* begin() const { return m_data; }
  const char* end() const { return m_data + m_size; }
  std::size_t size() const { return m_size; }

private:
  const char* m_data = nullptr; // the file's first byte; null when not mapped
  std::size_t m_size = 0;       // bytes
};

} // namespace dggvtp

#endif // DGGVTP_MAPPED_FILE_H
