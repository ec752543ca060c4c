// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// What dggvtp-batch needs from MPI and from the file system, with or without MPI:
//   Communicator   the processes of the run (MPI's world, or this process alone)
//   Row_file       writes rows at their offsets in the output file and makes them durable
//                  (MPI-IO under MPI, pwrite + fdatasync otherwise)
//   Record_file    the done-rows record of one process: one line per row, appended only after
//                  the row's bytes are durable; a torn last line is ignored when read back
// Errors are dggvtp::Input_error (one `error:` line, exit status 2).

#ifndef DGGVTP_BATCH_IO_H
#define DGGVTP_BATCH_IO_H

#include <dggvtp/load_mesh.h> // Input_error

#ifdef DGGVTP_WITH_MPI
#include <mpi.h>
#endif

#include <dirent.h>
#include <fcntl.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace dggvtp {

inline std::string system_error_text(int error) { return std::strerror(error); }

// ---------------------------------------------------------------------------------------------
// Communicator
// ---------------------------------------------------------------------------------------------

// True when this process was started by an MPI launcher (mpirun/mpiexec of Open MPI or MPICH,
// srun with PMI or PMIx): only then is MPI initialised, so that a plain run of the program needs
// no MPI runtime at all.
inline bool started_by_mpi_launcher()
{
  for(const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK", "PMIX_RANK"})
    if(std::getenv(name) != nullptr)
      return true;
  return false;
}

// The processes of the run. Without MPI (not built with it, or not started by a launcher): one
// process, rank 0. Under MPI: MPI_COMM_WORLD, initialised with MPI_THREAD_SERIALIZED (the
// threads of a process write rows one at a time, under a mutex) and finalised by the destructor.
class Communicator
{
public:
  Communicator(int& argc, char**& argv)
  {
#ifdef DGGVTP_WITH_MPI
    if(started_by_mpi_launcher())
    {
      MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &m_thread_level);
      m_mpi = true;
      MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
      MPI_Comm_size(MPI_COMM_WORLD, &m_size);
      MPI_Comm node; // the processes of the run on this machine
      MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, m_rank, MPI_INFO_NULL, &node);
      MPI_Comm_size(node, &m_size_on_node);
      MPI_Comm_free(&node);
    }
#else
    (void)argc;
    (void)argv;
#endif
  }
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;
  ~Communicator()
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
      MPI_Finalize();
#endif
  }

  int rank() const { return m_rank; }
  int size() const { return m_size; }
  // the number of processes of the run on this machine, this one included
  int size_on_this_node() const { return m_size_on_node; }
  bool uses_mpi() const { return m_mpi; }
  // whether several threads of this process may call MPI, one at a time
  bool allows_threads() const
  {
#ifdef DGGVTP_WITH_MPI
    return !m_mpi || m_thread_level >= MPI_THREAD_SERIALIZED;
#else
    return true;
#endif
  }

  int max(int value) const { return reduce(value, true); }
  int min(int value) const { return reduce(value, false); }
  void barrier() const
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
      MPI_Barrier(MPI_COMM_WORLD);
#endif
  }
  // a barrier that sleeps while it waits (MPI's blocking calls spin, and would take the cores
  // from the ranks still computing on the same machine)
  void idle_barrier() const
  {
#ifdef DGGVTP_WITH_MPI
    if(!m_mpi)
      return;
    MPI_Request request;
    MPI_Ibarrier(MPI_COMM_WORLD, &request);
    for(int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
#endif
  }
  // rank 0's bytes to every rank
  void broadcast(std::string& bytes) const
  {
#ifdef DGGVTP_WITH_MPI
    if(!m_mpi)
      return;
    unsigned long long size = bytes.size();
    MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    bytes.resize(size);
    for(unsigned long long done = 0; done < size;)
    {
      const int chunk = int(std::min<unsigned long long>(size - done, 1u << 30));
      MPI_Bcast(&bytes[done], chunk, MPI_CHAR, 0, MPI_COMM_WORLD);
      done += chunk;
    }
#else
    (void)bytes;
#endif
  }
  // every rank's value, in the order of the ranks, on rank 0 (empty elsewhere)
  std::vector<double> gather(double value) const
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
    {
      std::vector<double> out(m_rank == 0 ? m_size : 0);
      MPI_Gather(&value, 1, MPI_DOUBLE, out.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
      return out;
    }
#endif
    return {value};
  }
  // ends every process of the run (after an error seen by this one only)
  [[noreturn]] void abort(int status) const
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
      MPI_Abort(MPI_COMM_WORLD, status);
#endif
    std::exit(status);
  }

private:
  int reduce(int value, bool maximum) const
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
    {
      int out = value;
      MPI_Allreduce(&value, &out, 1, MPI_INT, maximum ? MPI_MAX : MPI_MIN, MPI_COMM_WORLD);
      return out;
    }
#else
    (void)maximum;
#endif
    return value;
  }

  bool m_mpi = false;        // MPI initialised by this object
  int m_rank = 0, m_size = 1;
  int m_size_on_node = 1;    // processes of the run on this machine
  int m_thread_level = 0;    // what MPI_Init_thread provided
};

// The threads of a process for --threads `asked`: `asked` itself, but for 0 (all cores) under
// mpirun with several processes on this machine, where each takes its share of the cores (or, if
// the launcher bound it to fewer cores, those), so that the processes of a node do not run more
// threads than it has cores. The rows are the same bytes for any number.
inline long threads_of_process(long asked, const Communicator& comm)
{
  const int here = comm.size_on_this_node();
  if(asked != 0 || here <= 1)
    return asked;
  const long cores = long((std::max)(1u, std::thread::hardware_concurrency()));
  long mine = cores;
  cpu_set_t set;
  if(sched_getaffinity(0, sizeof set, &set) == 0)
    mine = CPU_COUNT(&set);
  if(mine < cores) // bound by the launcher
    return (std::max)(1L, mine);
  return (std::max)(1L, cores / here);
}

// ---------------------------------------------------------------------------------------------
// Row_file
// ---------------------------------------------------------------------------------------------

// An existing file, opened for writing at offsets by this process alone (MPI_COMM_SELF under
// MPI: every process writes its own rows, so no collective call is needed per row).
class Row_file
{
public:
  Row_file(const std::string& path, bool use_mpi) : m_path(path), m_mpi(use_mpi)
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
    {
      const int error = MPI_File_open(MPI_COMM_SELF, path.c_str(), MPI_MODE_WRONLY, MPI_INFO_NULL, &m_file);
      if(error != MPI_SUCCESS)
        throw Input_error("cannot open '" + path + "' with MPI-IO: " + mpi_error_text(error));
      return;
    }
#endif
    m_fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if(m_fd < 0)
      throw Input_error("cannot open '" + path + "': " + system_error_text(errno));
  }
  Row_file(const Row_file&) = delete;
  Row_file& operator=(const Row_file&) = delete;
  ~Row_file()
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
    {
      MPI_File_close(&m_file);
      return;
    }
#endif
    if(m_fd >= 0)
      ::close(m_fd);
  }

  void write_at(std::uint64_t offset, const char* bytes, std::size_t size)
  {
    while(size > 0)
    {
      const std::size_t chunk = std::min<std::size_t>(size, std::size_t(1) << 30);
#ifdef DGGVTP_WITH_MPI
      if(m_mpi)
      {
        MPI_Status status;
        const int error = MPI_File_write_at(m_file, MPI_Offset(offset), bytes, int(chunk), MPI_BYTE, &status);
        int written = 0;
        MPI_Get_count(&status, MPI_BYTE, &written);
        if(error != MPI_SUCCESS || std::size_t(written) != chunk)
          throw Input_error("cannot write '" + m_path + "' with MPI-IO: " +
                            (error != MPI_SUCCESS ? mpi_error_text(error) : std::string("short write")));
        offset += chunk, bytes += chunk, size -= chunk;
        continue;
      }
#endif
      const ssize_t written = ::pwrite(m_fd, bytes, chunk, off_t(offset));
      if(written < 0 && errno == EINTR)
        continue;
      if(written <= 0)
        throw Input_error("cannot write '" + m_path + "': " + system_error_text(written < 0 ? errno : ENOSPC));
      offset += std::size_t(written), bytes += written, size -= std::size_t(written);
    }
  }

  // what was written is on the storage device when this returns
  void sync()
  {
#ifdef DGGVTP_WITH_MPI
    if(m_mpi)
    {
      const int error = MPI_File_sync(m_file);
      if(error != MPI_SUCCESS)
        throw Input_error("cannot write '" + m_path + "' with MPI-IO: " + mpi_error_text(error));
      return;
    }
#endif
    if(::fdatasync(m_fd) != 0)
      throw Input_error("cannot write '" + m_path + "': " + system_error_text(errno));
  }

private:
#ifdef DGGVTP_WITH_MPI
  static std::string mpi_error_text(int error)
  {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(error, text, &length);
    return std::string(text, std::size_t(length));
  }
  MPI_File m_file = MPI_FILE_NULL;
#endif
  std::string m_path;
  bool m_mpi = false;
  int m_fd = -1;
};

// ---------------------------------------------------------------------------------------------
// Record_file
// ---------------------------------------------------------------------------------------------

// The done-rows record of one process: `DIR/done.<rank>`, one decimal row number per line.
class Record_file
{
public:
  explicit Record_file(const std::string& path) : m_path(path)
  {
    m_fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0666);
    if(m_fd < 0)
      throw Input_error("cannot write '" + path + "': " + system_error_text(errno));
    // a torn last line (a kill while appending) would run into the next record: cut it off
    const off_t size = ::lseek(m_fd, 0, SEEK_END);
    off_t keep = size;
    char c = '\n';
    while(keep > 0 && ::pread(m_fd, &c, 1, keep - 1) == 1 && c != '\n')
      --keep;
    if(keep != size && ::ftruncate(m_fd, keep) != 0)
      throw Input_error("cannot write '" + path + "': " + system_error_text(errno));
  }
  Record_file(const Record_file&) = delete;
  Record_file& operator=(const Record_file&) = delete;
  ~Record_file() { ::close(m_fd); }

  // appends the rows and makes them durable; a process killed meanwhile leaves at most a torn
  // last line, which read_records() ignores
  void append(const std::vector<std::size_t>& rows)
  {
    if(rows.empty())
      return;
    std::string text;
    for(std::size_t row : rows)
      text += std::to_string(row) + '\n';
    const char* bytes = text.data();
    std::size_t size = text.size();
    while(size > 0)
    {
      const ssize_t written = ::write(m_fd, bytes, size);
      if(written < 0 && errno == EINTR)
        continue;
      if(written <= 0)
        throw Input_error("cannot write '" + m_path + "': " + system_error_text(written < 0 ? errno : ENOSPC));
      bytes += written, size -= std::size_t(written);
    }
    if(::fdatasync(m_fd) != 0)
      throw Input_error("cannot write '" + m_path + "': " + system_error_text(errno));
  }

private:
  std::string m_path;
  int m_fd = -1;
};

// An exclusive lock (flock) on a directory, held until destruction: a second run on the same
// checkpoint fails at once instead of writing into it too. (flock is advisory and, on some
// network file systems, local to a node.)
class Directory_lock
{
public:
  Directory_lock() = default;
  explicit Directory_lock(const std::string& directory)
  {
    m_fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if(m_fd < 0)
      throw Input_error("cannot open '" + directory + "': " + system_error_text(errno));
    if(::flock(m_fd, LOCK_EX | LOCK_NB) != 0)
    {
      const int error = errno;
      ::close(m_fd);
      m_fd = -1;
      if(error == EWOULDBLOCK)
        throw Input_error("another dggvtp-batch is running on the checkpoint '" + directory + "'");
      throw Input_error("cannot lock '" + directory + "': " + system_error_text(error));
    }
  }
  Directory_lock(Directory_lock&& other) noexcept : m_fd(other.m_fd) { other.m_fd = -1; }
  Directory_lock& operator=(Directory_lock&& other) noexcept
  {
    std::swap(m_fd, other.m_fd);
    return *this;
  }
  ~Directory_lock()
  {
    if(m_fd >= 0)
      ::close(m_fd);
  }

private:
  int m_fd = -1;
};

// The names in `directory` (without . and ..); throws if it cannot be read.
inline std::vector<std::string> directory_entries(const std::string& directory)
{
  DIR* dir = ::opendir(directory.c_str());
  if(dir == nullptr)
    throw Input_error("cannot read '" + directory + "': " + system_error_text(errno));
  std::vector<std::string> out;
  while(const dirent* entry = ::readdir(dir))
  {
    const std::string name = entry->d_name;
    if(name != "." && name != "..")
      out.push_back(name);
  }
  ::closedir(dir);
  std::sort(out.begin(), out.end());
  return out;
}

// Marks in `done` (one flag per row) the rows recorded in the `done.*` files of `directory`.
// A line without its newline (the process was killed while appending it) and a line that is not
// a row number below done.size() are ignored: those rows are computed again.
inline void read_records(const std::string& directory, std::vector<unsigned char>& done)
{
  for(const std::string& name : directory_entries(directory))
  {
    if(name.compare(0, 5, "done.") != 0)
      continue;
    const std::string path = directory + "/" + name;
    std::ifstream in(path, std::ios::binary);
    if(!in)
      throw Input_error("cannot read '" + path + "'");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t begin = 0;
    for(std::size_t end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
    {
      const std::string line = text.substr(begin, end - begin);
      if(line.empty() || line.size() > 19 || line.find_first_not_of("0123456789") != std::string::npos)
        continue;
      const unsigned long long row = std::stoull(line);
      if(row < done.size())
        done[row] = 1;
    }
  }
}

// Writes into `path` atomically the bytes that `produce` hands, in pieces, to the function it is
// given: a temporary file beside it, flushed to the device, then renamed over it (and the
// directory flushed, so that the rename survives a crash).
inline void write_file_atomically(const std::string& path,
                                  const std::function<void(const std::function<void(const char*, std::size_t)>&)>& produce)
{
  std::string temporary = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(&temporary[0]);
  if(fd < 0)
    throw Input_error("cannot write '" + path + "': " + system_error_text(errno));
  bool ok = true;
  produce([&](const char* bytes, std::size_t size) {
    for(std::size_t done = 0; ok && done < size;)
    {
      const ssize_t written = ::write(fd, bytes + done, size - done);
      if(written < 0 && errno == EINTR)
        continue;
      ok = written > 0;
      done += ok ? std::size_t(written) : 0;
    }
  });
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ok = ok && ::fchmod(fd, 0666 & ~mask) == 0 && ::fsync(fd) == 0;
  const int error = errno;
  ok = (::close(fd) == 0) && ok;
  if(!ok || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const int rename_error = ok ? errno : error;
    std::remove(temporary.c_str());
    throw Input_error("cannot write '" + path + "': " + system_error_text(rename_error));
  }
  const std::string::size_type slash = path.rfind('/');
  const std::string directory = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const int dir_fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if(dir_fd >= 0)
  {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

inline void write_file_atomically(const std::string& path, const std::string& bytes)
{
  write_file_atomically(path, [&](const std::function<void(const char*, std::size_t)>& write) {
    write(bytes.data(), bytes.size());
  });
}

} // namespace dggvtp

#endif // DGGVTP_BATCH_IO_H
