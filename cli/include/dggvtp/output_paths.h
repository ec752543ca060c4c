// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_OUTPUT_PATHS_H
#define DGGVTP_OUTPUT_PATHS_H

// What dggvtp and dggvtp-batch check of their output files before the work, so that a mistake
// costs a moment and not the whole computation: that each can be written (before the mesh is
// loaded), and that the file system of dggvtp-batch's large output has room for it.
// Errors are dggvtp::Input_error (one `error:` line, exit status 2).

#include <dggvtp/load_mesh.h> // Input_error

#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace dggvtp {

// The directory that holds `path` ("." for a bare name).
inline std::string parent_directory(const std::string& path)
{
  const std::string::size_type slash = path.find_last_of('/');
  if(slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Throws unless `path` can be written the way the programs write it: standard output ("-"); an
// existing file that is not a regular file (a device, a pipe) in place, if it is writable; or
// else through a temporary file beside it, renamed over it. That temporary file is made here and
// removed at once, so the check is the write itself and leaves nothing behind. `what` names the
// path as the user gave it, e.g. "--output 'd.txt'".
inline void check_writable(const std::string& what, const std::string& path)
{
  if(path == "-")
    return;
  struct stat existing;
  if(::stat(path.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode))
  {
    if(S_ISDIR(existing.st_mode))
      throw Input_error("cannot write " + what + ": it is a directory");
    if(::access(path.c_str(), W_OK) != 0)
      throw Input_error("cannot write " + what + ": " + std::strerror(errno));
    return;
  }
  std::string probe = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(&probe[0]);
  if(fd < 0)
    throw Input_error("cannot write " + what + ": " + std::strerror(errno));
  ::close(fd);
  std::remove(probe.c_str());
}

// The bytes that an unprivileged writer may still use on the file system of `path` (an
// existing file or directory). For tests only, the environment variable
// DGGVTP_BATCH_TEST_FREE_BYTES=N makes every file system report N bytes free, so that a refusal
// can be tested without filling a disk.
inline std::uint64_t free_bytes(const std::string& path)
{
  if(const char* forced = std::getenv("DGGVTP_BATCH_TEST_FREE_BYTES"))
    return std::strtoull(forced, nullptr, 10);
  struct statvfs fs;
  if(::statvfs(path.c_str(), &fs) != 0)
    throw Input_error("cannot query the free space of '" + path + "': " + std::strerror(errno));
  return std::uint64_t(fs.f_bavail) * std::uint64_t(fs.f_frsize);
}

// "68679328 bytes (65.5 MiB)"
inline std::string bytes_text(std::uint64_t bytes)
{
  const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = double(bytes);
  int unit = -1;
  while(value >= 1024. && unit < 5)
    value /= 1024., ++unit;
  char text[64];
  if(unit < 0)
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  else
    std::snprintf(text, sizeof text, "%llu bytes (%.1f %s)", static_cast<unsigned long long>(bytes), value, units[unit]);
  return text;
}

// Throws unless the file system of `directory` (an existing one) has `needed` bytes free;
// `what` says what needs them.
inline void check_room(const std::string& what, std::uint64_t needed, const std::string& directory)
{
  const std::uint64_t available = free_bytes(directory);
  if(needed > available)
    throw Input_error(what + " needs " + bytes_text(needed) + " on the file system of '" + directory + "', which has " +
                      bytes_text(available) + " free");
}

} // namespace dggvtp

#endif // DGGVTP_OUTPUT_PATHS_H
