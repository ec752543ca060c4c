// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// dggvtp-batch: the geodesic distances from many source vertices of a mesh file to all its
// vertices, one row per source, into one NumPy .npy file; over TBB's threads on one machine and
// over the ranks of an MPI job, resumable after a kill. The contract is in README.md and in
// `dggvtp-batch --help`.
//
// How a run goes (every rank, unless said otherwise):
//  1. parse the options, check that the outputs can be written, load the mesh, read the sources,
//     build the solver (as dggvtp does);
//  2. rank 0 checks the free space for the output, opens the checkpoint directory (creating it,
//     or checking that it was made by the same command and reading which rows are done) and
//     tells the other ranks the done rows;
//  3. each rank computes its share of the missing rows (row i of the missing ones goes to rank
//     i mod R), spread over its threads; each row is written at its offset in the checkpoint's
//     copy of the output (MPI-IO under MPI), made durable, and only then recorded as done;
//     fps:K's sources are chosen first, by every rank (the same bits), as the library samples
//     them (each added to the field of those before: a few whole fields in all), then computed as
//     a list;
//  4. rank 0 checks that every row is recorded, renames the file to the output and removes the
//     checkpoint.
// The bytes of a row do not depend on who computes it: each is the same sequential propagation
// (or the parallel one, which gives the same bits) as `dggvtp --source N`.

#include <dggvtp/batch_io.h>
#include <dggvtp/command_line.h>
#include <dggvtp/load_mesh.h>
#include <dggvtp/npy.h>
#include <dggvtp/npz.h>
#include <dggvtp/output_paths.h>
#include <dggvtp/query_places.h>
#include <dggvtp/sparse_rows.h>
#include <dggvtp/threads.h>
#include <dggvtp/arguments.h>
#include <dggvtp/single_value_options.h>
#include <dggvtp/version.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Simple_cartesian.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using dggvtp::Input_error;
using dggvtp::Npy_dtype;

const char* const usage_text = R"(usage: dggvtp-batch MESH --sources FILE|all|fps:K --output OUT.npy [options]

Geodesic distances on the surface of a triangle mesh from many source vertices: one row per
source, one column per vertex of the file, the values `dggvtp --source N` prints, in a NumPy
.npy file. Under `mpirun -np R` the sources are shared among the R processes.

  MESH                   a mesh file CGAL reads: OFF, OBJ, PLY, STL (as dggvtp reads it)
  --sources S            FILE: 0-based vertex indices in the file's order, separated by white
                         space, one row each in that order (no duplicates, at least one;
                         a file named all: ./all);
                         all: every vertex, in order; fps:K: K vertices by farthest-point
                         sampling (the --first-sample vertex first, then each time the vertex
                         farthest from those chosen, the smallest index on ties; unreachable
                         vertices are the farthest; with --epsilon E, one within (1 + E) of the
                         farthest), chosen first at the cost of a few whole fields, then
                         computed as a list
  --first-sample N       the first sample of fps:K: vertex N (default 0), as dggvtp --fps K
                         --first-sample N
  --output OUT.npy       the .npy file (C order, shape (sources, vertices)); it appears only
                         when every row is in it
  --error-bounds B.npy   a second .npy of the same shape and dtype: per row and vertex a certified
                         bound b on the error of the distance d (the exact distance is in
                         [d - b, d], b <= epsilon d; 0 at the source and in the exact mode; inf
                         where unreachable): the values of `dggvtp --source N --error-bounds`;
                         checkpointed and resumed with the rows, renamed into place with them;
                         in float32 rounded as the distances are (not with --max-distance)
  --dtype D              float64 (default) or float32: the element type of the .npy
  --max-distance D       a local distance matrix: only the distances up to D >= 0 (finite), into
                         --output OUT.npz, a sparse matrix (CSR) as scipy.sparse.save_npz writes
                         it (scipy.sparse.load_npz reads it): row k holds the vertices within D of
                         source k and their distances, the source itself as an explicit 0, the
                         values `dggvtp --source N --max-distance D` prints (not inf); the memory
                         is in proportion to them. The rows are held in memory and written at the
                         end, by one process: no --checkpoint (a killed run starts over), no
                         mpirun with more than one process
  --exact                exact distances (VTP algorithm); the default
  --epsilon E            DGG-VTP with accuracy E in [0, 1] (E = 0 is --exact)
  --precision P          double (default) or float: the number type of the computation
  --threads T            threads per process, 0 = all cores (the default; under mpirun, the cores
                         of a node shared among its processes): the preparation runs on them,
                         and the sources are shared among them (fps:K's sampling runs on them);
                         same bytes for any T
  --checkpoint DIR       where the rows written so far and the record of the done rows live
                         (default OUT.npy.checkpoint); the same command run again after a kill
                         computes only the missing rows; a different command (mesh, epsilon,
                         precision, dtype, sources) is refused; removed at the end
  --sources-output FILE  the source vertex of each row, one per line (useful with fps:K)
  --stats FILE           one JSON object: sizes, rows computed and resumed, the time of each stage
                         (load, repair, prepare, compute, write, total) and the threads it used,
                         and per process its peak memory, CPU time and time on its own rows
  --progress             rows done / total, rate and time left on stderr (the default when
                         stderr is a terminal; under mpirun, whose output is a pipe, ask for it)
  --quiet                no summary, no progress, no warnings but the one about unreachable
                         vertices
  --help                 this text
  --version              the version of dggvtp-batch and of CGAL

Short names: -s is --sources, -o is --output, -h is --help. A value may also follow its option
after '=' (--sources=fps:10). An unknown option is refused with the nearest known one ("did you
mean --sources?"). Rows that leave vertices unreachable (inf: other connected components than
the row's source, vertices no face uses) are counted in a 'warning:' line on stderr, even with
--quiet.

Before the mesh is loaded, every output (--output, --checkpoint, --sources-output, --stats) is
checked to be writable; before the first row, the file's size (rows x vertices x 4 or 8 bytes,
and a header) is checked against the free space of the file systems of the checkpoint and of
the output.

Exit status, by the kind of mistake (as for dggvtp): 0 success; 1 bad usage, a command line
wrong whatever the mesh: an unknown option, a missing value, a value that is not a number, a
value out of its range (an --epsilon outside [0, 1], fps:0), options that contradict each other; 2 bad input, a command line
that this mesh or these files make wrong: fps:K beyond the vertices, a mesh or source list that
cannot be read or is refused, an output or checkpoint that cannot be written, a checkpoint of
another command, an output larger than the free space. Either way one line on stderr starting
with 'error:'.
)";

using dggvtp::json_string;
using dggvtp::parse_number;
using dggvtp::peak_rss_mb;
using dggvtp::Usage_error;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// =============================================================================================
// Options
// =============================================================================================

struct Options : dggvtp::Propagation_options
{
  std::string mesh;
  std::string sources;          // FILE, all or fps:K
  std::string output;           // the .npy file
  std::string error_bounds;     // optional: the .npy of the certified error bounds, row by row
  std::string checkpoint;       // default output + ".checkpoint"
  bool checkpoint_given = false;
  std::string sources_output;   // optional
  std::string stats;            // optional
  Npy_dtype dtype = Npy_dtype::float64;
  double max_distance = std::numeric_limits<double>::infinity(); // finite: a local distance matrix
  long threads = 0;             // per process, 0 = all cores (shared among the processes of a node)
  std::size_t first_sample = 0; // fps:K's first sample
  bool first_sample_given = false;
  bool progress = false;        // forced on by --progress
  bool quiet = false;
  bool help = false;
  bool version = false; // with help: print the version instead of the usage

  // --max-distance: the rows are sparse, in memory, and no checkpoint is made
  bool local_matrix() const { return std::isfinite(max_distance); }

  // Messages name the checkpoint as the user knows it: the path given, or the output it is made
  // from (errors about the files inside it end with this)
  std::string checkpoint_origin() const
  {
    return checkpoint_given ? std::string() : " (the default --checkpoint of --output '" + output + "')";
  }
};


Options parse_options(int argc, char** argv)
{
  Options options;
  dggvtp::Single_value_options single_value{"--sources", "--output", "--checkpoint", "--sources-output", "--stats", "--error-bounds",
                                            "--dtype", "--epsilon", "--precision", "--threads", "--max-distance",
                                            "--first-sample"};
  dggvtp::Argument_reader words(argc, argv, {{"-h", "--help"}, {"-o", "--output"}, {"-s", "--sources"}}, usage_text);
  while(words.next())
  {
    const std::string arg = words.word();
    single_value.check(arg);
    const auto value = [&] { return words.value(); };
    const auto name = [&]() -> std::string {
      std::string v = value();
      if(v.empty())
        throw Usage_error(arg + " needs a file name");
      return v;
    };
    if(arg == "--help" || arg == "--version")
    {
      options.help = true;
      options.version = arg == "--version";
      return options;
    }
    else if(arg == "--sources")
    {
      options.sources = value();
      if(options.sources.empty())
        throw Usage_error("--sources needs FILE, all or fps:K");
    }
    else if(arg == "--output")
      options.output = name();
    else if(arg == "--checkpoint")
      options.checkpoint = name();
    else if(arg == "--error-bounds")
      options.error_bounds = name();
    else if(arg == "--sources-output")
      options.sources_output = name();
    else if(arg == "--stats")
      options.stats = name();
    else if(arg == "--dtype")
    {
      const std::string d = value();
      if(d == "float64" || d == "f8")
        options.dtype = Npy_dtype::float64;
      else if(d == "float32" || d == "f4")
        options.dtype = Npy_dtype::float32;
      else
        throw Usage_error("--dtype must be float64 or float32");
    }
    else if(arg == "--max-distance")
    {
      options.max_distance = parse_number<double>(arg, value());
      if(!(options.max_distance >= 0.) || std::isinf(options.max_distance))
        throw Usage_error("--max-distance must be a finite number >= 0 (the local distance matrix keeps the distances "
                          "up to it); without it, the rows hold every distance");
    }
    else if(options.parse(arg, value))
      continue;
    else if(arg == "--threads")
    {
      const std::size_t t = parse_number<std::size_t>(arg, value());
      if(t > 4096)
        throw Usage_error("--threads must be at most 4096");
      options.threads = long(t);
    }
    else if(arg == "--first-sample")
    {
      options.first_sample = parse_number<std::size_t>(arg, value());
      options.first_sample_given = true;
    }
    else if(arg == "--progress")
      options.progress = true;
    else if(arg == "--quiet")
      options.quiet = true;
    else
      dggvtp::parse_mesh_argument(arg, options.mesh);
  }
  words.finish();
  if(options.mesh.empty())
    throw Usage_error("no MESH given");
  if(options.sources.empty())
    throw Usage_error("no --sources given (FILE, all or fps:K)");
  if(options.output.empty())
    throw Usage_error("no --output given");
  if(options.output == "-")
    throw Usage_error("--output must be a file (rows are written at their offsets)");
  options.check();
  if(options.sources.compare(0, 4, "fps:") == 0 && parse_number<std::size_t>("--sources fps:K", options.sources.substr(4)) == 0)
    throw Usage_error("fps:0 selects no source");
  if(options.first_sample_given && options.sources.compare(0, 4, "fps:") != 0)
    throw Usage_error("--first-sample is the first sample of --sources fps:K");
  options.checkpoint_given = !options.checkpoint.empty();
  if(options.local_matrix())
  {
    const std::string& o = options.output;
    if(o.size() < 4 || o.compare(o.size() - 4, 4, ".npz") != 0)
      throw Usage_error("--max-distance writes a sparse matrix as .npz: give --output FILE.npz");
    if(options.checkpoint_given)
      throw Usage_error("--checkpoint does not combine with --max-distance: the rows, of sizes known only once "
                        "computed, are held in memory and written at the end (a killed run starts over)");
    if(!options.error_bounds.empty())
      throw Usage_error("--error-bounds writes dense rows: it does not combine with --max-distance");
  }
  if(options.error_bounds == "-" || options.error_bounds == options.output)
    throw Usage_error("--error-bounds must be a file other than --output (rows are written at their offsets)");
  if(!options.checkpoint_given)
    options.checkpoint = options.output + ".checkpoint";
  return options;
}

// Before the mesh is loaded: every file the run writes can be written (a mistake in a name costs
// a moment, not the rows).
void check_outputs(const Options& options)
{
  struct stat info;
  if(::stat(options.output.c_str(), &info) == 0 && !S_ISREG(info.st_mode))
    throw Input_error("cannot write --output '" + options.output + "': it exists and is not a regular file (the " +
                      "output is renamed into place)");
  dggvtp::check_writable("--output '" + options.output + "'", options.output);
  if(!options.error_bounds.empty())
    dggvtp::check_writable("--error-bounds '" + options.error_bounds + "'", options.error_bounds);
  if(!options.sources_output.empty())
    dggvtp::check_writable("--sources-output '" + options.sources_output + "'", options.sources_output);
  if(!options.stats.empty())
    dggvtp::check_writable("--stats '" + options.stats + "'", options.stats);
  if(options.local_matrix())
    return;
  const std::string checkpoint =
    (options.checkpoint_given ? "--checkpoint '" : "'") + options.checkpoint + "'" + options.checkpoint_origin();
  if(::stat(options.checkpoint.c_str(), &info) != 0)
    dggvtp::check_writable(checkpoint, options.checkpoint); // it can be made
  else if(!S_ISDIR(info.st_mode))
    throw Input_error("cannot write " + checkpoint + ": it is not a directory");
  else
    dggvtp::check_writable(checkpoint, options.checkpoint + "/rows.npy");
}

// Runs `f`; an error about the files of the default checkpoint also names the --output it is made from.
template <class F>
void in_checkpoint(const Options& options, F f)
{
  try
  {
    f();
  }
  catch(const Input_error& e)
  {
    throw Input_error(e.what() + options.checkpoint_origin());
  }
}

// =============================================================================================
// Sources
// =============================================================================================

// FNV-1a, 64 bits: the identity of the mesh file and of a source list in the fingerprint
struct Fnv1a
{
  std::uint64_t value = 0xcbf29ce484222325ull;
  void add(const char* bytes, std::size_t size)
  {
    for(std::size_t i = 0; i < size; ++i)
      value = (value ^ static_cast<unsigned char>(bytes[i])) * 0x100000001b3ull;
  }
  std::string hex() const
  {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
  }
};

struct Sources
{
  bool farthest_point = false;       // fps:K: chosen once the solver is prepared
  std::size_t rows = 0;              // number of sources, rows of the output
  std::vector<std::size_t> vertices; // file vertex of each row (fps:K: empty until chosen)
  std::string identity;              // what the fingerprint records of them
  std::size_t first_sample = 0;      // fps:K's first sample (a file vertex)
};

// the sources of `spec` (FILE, all or fps:K; fps:K's start at `first_sample`)
Sources read_sources(const std::string& spec, std::size_t file_vertices, std::size_t first_sample)
{
  Sources sources;
  if(spec == "all")
  {
    sources.rows = file_vertices;
    sources.vertices.resize(file_vertices);
    for(std::size_t v = 0; v < file_vertices; ++v)
      sources.vertices[v] = v;
    sources.identity = "all";
    return sources;
  }
  if(spec.compare(0, 4, "fps:") == 0)
  {
    sources.farthest_point = true;
    sources.rows = parse_number<std::size_t>("--sources fps:K", spec.substr(4));
    if(sources.rows > file_vertices)
      throw Input_error("fps:" + std::to_string(sources.rows) + " asks for more sources than the mesh has vertices (" +
                        std::to_string(file_vertices) + ")");
    if(first_sample >= file_vertices)
      throw Input_error("--first-sample " + std::to_string(first_sample) + " is out of range (the mesh has " +
                        std::to_string(file_vertices) + " vertices)");
    sources.first_sample = first_sample;
    // vertex 0, the default, as the checkpoints of the versions without --first-sample recorded it
    sources.identity = "fps:" + std::to_string(sources.rows) +
                       (first_sample == 0 ? std::string() : " from vertex " + std::to_string(first_sample));
    return sources;
  }
  std::ifstream in(spec, std::ios::binary);
  if(!in)
    throw Input_error("cannot read the source list '" + spec + "': " + std::strerror(errno));
  std::vector<std::size_t> first_entry(file_vertices, 0); // 1-based entry that listed the vertex
  std::string token;
  while(in >> token)
  {
    const std::size_t entry = sources.vertices.size() + 1;
    if(token.size() > 19 || token.find_first_not_of("0123456789") != std::string::npos)
      throw Input_error("source list '" + spec + "', entry " + std::to_string(entry) + ": '" + token.substr(0, 40) +
                        "' is not a vertex index (0-based integers separated by white space)");
    const unsigned long long v = std::stoull(token);
    if(v >= file_vertices)
      throw Input_error("source list '" + spec + "', entry " + std::to_string(entry) + ": source " + token +
                        " is out of range (the mesh has " + std::to_string(file_vertices) + " vertices)");
    if(first_entry[v] != 0)
      throw Input_error("source list '" + spec + "': vertex " + token + " is listed twice (entries " +
                        std::to_string(first_entry[v]) + " and " + std::to_string(entry) + ")");
    first_entry[v] = entry;
    sources.vertices.push_back(std::size_t(v));
  }
  if(in.bad())
    throw Input_error("cannot read the source list '" + spec + "'");
  if(sources.vertices.empty())
    throw Input_error("source list '" + spec + "' is empty");
  sources.rows = sources.vertices.size();
  Fnv1a hash;
  for(std::size_t v : sources.vertices)
  {
    const std::string text = std::to_string(v) + "\n";
    hash.add(text.data(), text.size());
  }
  sources.identity = "list of " + std::to_string(sources.rows) + " vertices, fnv1a64 " + hash.hex();
  return sources;
}

// =============================================================================================
// Checkpoint
// =============================================================================================

// What the run's rows depend on, one "key value" per line; a checkpoint resumes only for the same.
std::string fingerprint_of(const Options& options, const Sources& sources, std::size_t file_vertices)
{
  std::ifstream in(options.mesh, std::ios::binary);
  if(!in)
    throw Input_error("cannot read '" + options.mesh + "'");
  Fnv1a hash;
  std::uint64_t size = 0;
  std::vector<char> block(1 << 20);
  while(in)
  {
    in.read(block.data(), std::streamsize(block.size()));
    hash.add(block.data(), std::size_t(in.gcount()));
    size += std::uint64_t(in.gcount());
  }
  char epsilon[40]; // the shortest text that reads back as the same double
  *std::to_chars(epsilon, epsilon + sizeof epsilon - 1, options.epsilon).ptr = '\0';
  return "dggvtp-batch checkpoint 1\n"
         "mesh " + std::to_string(size) + " bytes, fnv1a64 " + hash.hex() + "\n"
         "vertices " + std::to_string(file_vertices) + "\n"
         "epsilon " + epsilon + "\n"
         "precision " + options.precision + "\n"
         "dtype " + (options.dtype == Npy_dtype::float32 ? "float32" : "float64") + "\n"
         "sources " + sources.identity + "\n" + (options.error_bounds.empty() ? "" : "error_bounds yes\n");
}

std::map<std::string, std::string> fingerprint_fields(const std::string& text)
{
  std::map<std::string, std::string> fields;
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line))
  {
    const std::string::size_type space = line.find(' ');
    fields[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  return fields;
}

// the differences between the checkpoint's fingerprint and this command's, for the error message
std::string fingerprint_differences(const std::string& recorded, const std::string& current)
{
  const auto a = fingerprint_fields(recorded), b = fingerprint_fields(current);
  std::string out;
  for(const auto& [key, value] : b)
  {
    const auto it = a.find(key);
    const std::string old = it == a.end() ? "(none)" : it->second;
    if(old != value)
      out += (out.empty() ? "" : "; ") + key + " '" + old + "' there, '" + value + "' now";
  }
  for(const auto& [key, value] : a)
    if(b.find(key) == b.end())
      out += (out.empty() ? "" : "; ") + key + " '" + value + "' there, none now";
  return out;
}

bool read_whole_file(const std::string& path, std::string& out)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return false;
  out.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return !in.bad();
}

struct Checkpoint
{
  std::string directory;
  std::string data() const { return directory + "/rows.npy"; }  // the output being filled
  std::string bounds() const { return directory + "/bounds.npy"; } // and --error-bounds'
  // the files filled row by row: the output's, and the bounds' with --error-bounds
  std::vector<std::string> row_files(bool bounds) const
  {
    return bounds ? std::vector<std::string>{data(), this->bounds()} : std::vector<std::string>{data()};
  }
  std::string fingerprint() const { return directory + "/fingerprint"; }
  std::string record(int rank) const { return directory + "/done." + std::to_string(rank); }
  // the names a checkpoint directory holds (and temporary files of them)
  static bool is_own_name(const std::string& name)
  {
    for(const char* prefix : {"rows.npy", "bounds.npy", "fingerprint", "done."})
      if(name.compare(0, std::strlen(prefix), prefix) == 0)
        return true;
    return false;
  }
};

struct Resume
{
  std::vector<unsigned char> done; // per row
  std::vector<std::string> notes;  // warnings for the user
  dggvtp::Directory_lock lock;     // held by rank 0 for the whole run
};

// Rank 0, before the checkpoint is made: the file systems of the checkpoint and of the output have
// room for the rows still to write. The checkpoint's copy is a sparse file, which takes its space
// only as the rows come: without this check a disk would fill up hours into the run.
void check_room_for_output(const Options& options, const Checkpoint& checkpoint, std::size_t rows, std::size_t columns,
                std::uint64_t file_size)
{
  struct stat info;
  const bool exists = ::stat(checkpoint.directory.c_str(), &info) == 0;
  // an existing copy's blocks are reused when resuming, or freed when starting over
  std::uint64_t written = 0;
  if(exists && ::stat(checkpoint.data().c_str(), &info) == 0)
    written = (std::min)(file_size, std::uint64_t(info.st_blocks) * 512);
  if(!options.error_bounds.empty()) // and as much for the bounds, beside it
    file_size *= 2;
  const std::string output = "--output '" + options.output + "' (" + std::to_string(rows) + " rows x " +
                             std::to_string(columns) + " columns x " + std::to_string(dggvtp::npy_item_size(options.dtype)) +
                             " bytes, and its header)";
  const std::string where = exists ? checkpoint.directory : dggvtp::parent_directory(checkpoint.directory);
  dggvtp::check_room(written > 0 ? "the rows still to write of " + output : output, file_size - written, where);
  // the output is renamed from the checkpoint's copy, or copied beside it from another file system
  const std::string output_directory = dggvtp::parent_directory(options.output);
  struct stat output_info;
  if(::stat(where.c_str(), &info) == 0 && ::stat(output_directory.c_str(), &output_info) == 0 &&
     info.st_dev != output_info.st_dev)
    dggvtp::check_room(output, file_size, output_directory);
}

// Rank 0: opens the checkpoint, or creates it. Returns the done rows.
Resume open_checkpoint(const Checkpoint& checkpoint, const std::string& fingerprint, const std::string& header,
                       std::uint64_t file_size, const Sources& sources, std::size_t file_vertices, bool bounds)
{
  Resume resume;
  resume.done.assign(sources.rows, 0);
  struct stat info;
  bool fresh = true;
  if(::stat(checkpoint.directory.c_str(), &info) == 0)
  {
    if(!S_ISDIR(info.st_mode))
      throw Input_error("the checkpoint '" + checkpoint.directory + "' is not a directory");
    resume.lock = dggvtp::Directory_lock(checkpoint.directory);
    std::string recorded;
    if(read_whole_file(checkpoint.fingerprint(), recorded))
    {
      if(recorded != fingerprint)
        throw Input_error("the checkpoint '" + checkpoint.directory + "' belongs to another command (" +
                          fingerprint_differences(recorded, fingerprint) +
                          "): run that command again to finish it, or delete the directory to start over");
      bool intact = true;
      for(const std::string& path : checkpoint.row_files(bounds))
      {
        struct stat data;
        std::string start;
        std::ifstream in(path, std::ios::binary);
        start.resize(header.size());
        intact = intact && ::stat(path.c_str(), &data) == 0 && std::uint64_t(data.st_size) == file_size &&
                 in.read(&start[0], std::streamsize(start.size())) && start == header;
      }
      if(!intact)
        resume.notes.push_back("the checkpoint's copy of the output is missing or damaged: starting over");
      else
      {
        fresh = false;
        dggvtp::read_records(checkpoint.directory, resume.done);
      }
    }
    else
    {
      // a directory without fingerprint: an empty one given by the user, or a checkpoint killed
      // while being created; anything else is not ours to delete
      for(const std::string& name : dggvtp::directory_entries(checkpoint.directory))
        if(!Checkpoint::is_own_name(name))
          throw Input_error("'" + checkpoint.directory + "' is not a dggvtp-batch checkpoint (it holds '" + name +
                            "' and no fingerprint): give another --checkpoint DIR");
    }
  }
  else if(::mkdir(checkpoint.directory.c_str(), 0777) != 0)
    throw Input_error("cannot create the checkpoint directory '" + checkpoint.directory + "': " + std::strerror(errno));
  else
    resume.lock = dggvtp::Directory_lock(checkpoint.directory);

  if(fresh)
  {
    for(const std::string& name : dggvtp::directory_entries(checkpoint.directory))
      if(Checkpoint::is_own_name(name))
        std::remove((checkpoint.directory + "/" + name).c_str());
    resume.done.assign(sources.rows, 0);
    // the data files: the header, then zeros (a sparse file) where the rows will go
    for(const std::string& path : checkpoint.row_files(bounds))
    {
      dggvtp::write_file_atomically(path, header);
      if(::truncate(path.c_str(), off_t(file_size)) != 0)
        throw Input_error("cannot make '" + path + "' " + std::to_string(file_size) + " bytes long: " + std::strerror(errno));
    }
    dggvtp::write_file_atomically(checkpoint.fingerprint(), fingerprint);
  }
  return resume;
}

// Rank 0, every row done: the checkpoint's data files become the outputs (`bounds`: the
// --error-bounds file, or empty), the checkpoint goes.
void finish_checkpoint(const Checkpoint& checkpoint, const std::string& output, const std::string& bounds)
{
  const std::vector<std::string> from = checkpoint.row_files(!bounds.empty());
  for(std::size_t k = 0; k < from.size(); ++k)
  {
    const std::string& to = k == 0 ? output : bounds;
    if(std::rename(from[k].c_str(), to.c_str()) == 0)
      continue;
    if(errno != EXDEV)
      throw Input_error("cannot write '" + to + "': " + std::strerror(errno));
    // another file system: copied beside the output, then renamed
    std::string bytes;
    if(!read_whole_file(from[k], bytes))
      throw Input_error("cannot read '" + from[k] + "'");
    dggvtp::write_file_atomically(to, bytes);
  }
  std::remove(checkpoint.fingerprint().c_str());
  for(const std::string& name : dggvtp::directory_entries(checkpoint.directory))
    if(Checkpoint::is_own_name(name))
      std::remove((checkpoint.directory + "/" + name).c_str());
  ::rmdir(checkpoint.directory.c_str()); // left if the user put other files there
}

// =============================================================================================
// Rows
// =============================================================================================

// a row: the file vertices' distances, as dggvtp prints them, and with --error-bounds their
// certified error bounds, as dggvtp --error-bounds prints them (else empty)
struct Row_values
{
  std::vector<double> distances, bounds;
};

// the file vertices of fps:K (`k`) from the file vertex `first`, sampled on `threads` threads (0 =
// all cores; the same bits for any number)
using Sample_function = std::function<std::vector<std::size_t>(std::size_t k, std::size_t first, long threads)>;
// computes the rows of several sources, each one sequential propagation, on `threads` threads (0 =
// all cores), and hands each to `done` (from any thread) with its number in `file_vertices`
template <class Row>
using Rows_function =
  std::function<void(const std::vector<std::size_t>& file_vertices, long threads, const std::function<void(std::size_t, Row&&)>& done)>;

struct Prepared
{
  Sample_function sample;
  Rows_function<Row_values> rows;
  Rows_function<dggvtp::Sparse_row> local_rows; // --max-distance: the vertices within it, in the time of those
  std::size_t faces = 0;
  double seconds_make_mesh = 0., seconds_prepare = 0.; // the input policy's repairs, the rest
  std::size_t threads = 1; // that prepare the solver, and that --threads gives the rows
};

// the solver prepared on `threads` threads (0 = all cores), the same bits for any number; rows with
// their error bounds if `bounds`
template <class Kernel>
Prepared prepare(std::shared_ptr<dggvtp::Loaded_soup> soup, double epsilon, double max_distance, long threads,
                 bool bounds)
{
  using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;
  Prepared prepared;
  auto solver = std::make_shared<std::optional<Solver>>();
  const Clock::time_point t0 = Clock::now();
  try
  {
    dggvtp::with_threads(threads, [&](auto tag) {
      prepared.seconds_make_mesh = dggvtp::make_solver<decltype(tag)>(*soup, *solver);
      prepared.threads = dggvtp::threads_of(tag);
    });
  }
  catch(const std::invalid_argument& e)
  {
    throw Input_error(e.what());
  }
  prepared.seconds_prepare = seconds_since(t0) - prepared.seconds_make_mesh;
  prepared.faces = soup->triangles.size();
  dggvtp::release_soup(*soup); // keeps file_vertex_of
  const auto np = CGAL::DGG_VTP_3::parameters::max_distance(max_distance).accuracy(epsilon);
  using FT = typename Solver::FT;
  // per file vertex: the distances `d` and, given the lower bounds `lower` (per solver vertex), the bounds
  const auto values = [soup](const std::vector<FT>& d, const std::vector<FT>* lower) {
    Row_values r{dggvtp::file_vertex_distances(*soup, d), {}};
    if(lower)
      r.bounds = dggvtp::certified_errors(r.distances, dggvtp::file_vertex_distances(*soup, *lower));
    return r;
  };
  prepared.sample = [soup, solver, epsilon](std::size_t k, std::size_t first_vertex, long threads) {
    const std::vector<std::size_t> first = dggvtp::solver_vertices_of(*soup, first_vertex);
    if(first.empty())
      throw Input_error("fps:K starts at vertex " + std::to_string(first_vertex) +
                        ", which no face uses: give another --first-sample, or the sources as a FILE");
    std::vector<std::size_t> samples;
    try
    {
      dggvtp::with_threads(threads, [&](auto tag) {
        (*solver)->template farthest_point_sampling<decltype(tag)>(
          k, std::back_inserter(samples),
          CGAL::DGG_VTP_3::parameters::first_sample(first[0], CGAL::parameters::accuracy(epsilon)));
      });
    }
    catch(const std::invalid_argument& e) // more samples than the faces' vertices
    {
      throw Input_error("fps:" + std::to_string(k) + ": " + e.what());
    }
    for(std::size_t& v : samples)
      v = soup->file_vertex_of[v];
    return samples;
  };
  // the rows of `file_vertices`, each handed to `row` as the library gives it
  const auto each_row = [soup, solver, np](const std::vector<std::size_t>& file_vertices, long threads, const auto& row) {
    const std::vector<std::vector<std::size_t>> sets = dggvtp::solver_vertex_sets(*soup, file_vertices);
    dggvtp::with_threads(file_vertices.size() > 1 ? threads : 1, [&](auto tag) {
      (*solver)->template compute_distances_from_each_source_set<decltype(tag)>(sets, row, np);
    });
  };
  prepared.rows = [each_row, bounds, values](const std::vector<std::size_t>& file_vertices, long threads,
                                             const std::function<void(std::size_t, Row_values&&)>& done) {
    if(bounds)
      each_row(file_vertices, threads, [&](std::size_t k, const std::vector<FT>& d,
                                           const CGAL::DGG_VTP_3::Propagation_statistics&, const auto&,
                                           const std::vector<FT>& lower) { done(k, values(d, &lower)); });
    else
      each_row(file_vertices, threads, [&](std::size_t k, const std::vector<FT>& d,
                                           const CGAL::DGG_VTP_3::Propagation_statistics&) {
        done(k, values(d, nullptr));
      });
  };
  prepared.local_rows = [soup, each_row](const std::vector<std::size_t>& file_vertices, long threads,
                                         const std::function<void(std::size_t, dggvtp::Sparse_row&&)>& done) {
    each_row(file_vertices, threads, [&](std::size_t k, const std::vector<FT>& d,
                                         const CGAL::DGG_VTP_3::Propagation_statistics&, const auto& reached) {
      dggvtp::Sparse_row row;
      dggvtp::sparse_row(*soup, d, reached, nullptr, row);
      done(k, std::move(row));
    });
  };
  return prepared;
}

void encode_row(const std::vector<double>& row, Npy_dtype dtype, std::vector<char>& bytes)
{
  bytes.resize(row.size() * dggvtp::npy_item_size(dtype));
  if(row.empty()) // no --error-bounds: memcpy from an empty vector's null data is undefined
    return;
  if(dtype == Npy_dtype::float64)
    std::memcpy(bytes.data(), row.data(), bytes.size());
  else
    for(std::size_t i = 0; i < row.size(); ++i)
    {
      const float f = static_cast<float>(row[i]);
      std::memcpy(bytes.data() + 4 * i, &f, 4);
    }
}

// For tests only: the number of rows after which this process kills itself (SIGKILL, as `kill -9`
// would), right after they are durable and recorded, so that a test of resuming knows what a kill
// left instead of racing the interval of the durable writes. DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=K,
// on rank DGGVTP_BATCH_TEST_KILL_RANK=R only if set. 0: never.
std::size_t rows_before_test_kill(int rank)
{
  const char* rows = std::getenv("DGGVTP_BATCH_TEST_KILL_AFTER_ROWS");
  const char* only = std::getenv("DGGVTP_BATCH_TEST_KILL_RANK");
  if(rows == nullptr || (only != nullptr && parse_number<std::size_t>("DGGVTP_BATCH_TEST_KILL_RANK", only) != std::size_t(rank)))
    return 0;
  return parse_number<std::size_t>("DGGVTP_BATCH_TEST_KILL_AFTER_ROWS", rows);
}

// For tests only: the signal of that kill, SIGKILL, or SIGSTOP with DGGVTP_BATCH_TEST_KILL_SIGNAL=STOP:
// the process then stops there, its checkpoint locked, until a test has run what it wants beside it
int test_kill_signal()
{
  const char* name = std::getenv("DGGVTP_BATCH_TEST_KILL_SIGNAL");
  return name != nullptr && std::string(name) == "STOP" ? SIGSTOP : SIGKILL;
}

// Writes rows at their offsets, into each of the files at `paths` (the rows, and their bounds with
// --error-bounds); every `interval` at most (and at the end) makes what was written durable in
// all of them and only then reports those rows as done (`on_durable`: the record). A kill loses at
// most the rows of the last interval. Safe to call from several threads. With `kill_after` = K > 0
// (tests only), the process kills itself once its first K rows are durable and reported.
class Row_sink
{
public:
  Row_sink(const std::vector<std::string>& paths, bool use_mpi, std::uint64_t header_size, std::uint64_t row_size,
           double interval, std::function<void(const std::vector<std::size_t>&)> on_durable, std::size_t kill_after)
    : m_header_size(header_size), m_row_size(row_size), m_interval(interval),
      m_on_durable(std::move(on_durable)), m_kill_after(kill_after), m_last_sync(Clock::now())
  {
    for(const std::string& path : paths)
      m_files.emplace_back(path, use_mpi);
  }
  // `bytes`: the row's bytes for each file, in the order of the paths
  void write(std::size_t row, const std::vector<std::vector<char>>& bytes)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    for(std::size_t k = 0; k < m_files.size(); ++k)
      m_files[k].write_at(m_header_size + std::uint64_t(row) * m_row_size, bytes[k].data(), bytes[k].size());
    m_pending.push_back(row);
    if(++m_written == m_kill_after)
    {
      flush_locked();
      std::raise(test_kill_signal());
    }
    if(seconds_since(m_last_sync) >= m_interval)
      flush_locked();
  }
  void flush()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    flush_locked();
  }

private:
  void flush_locked()
  {
    if(!m_pending.empty())
    {
      for(dggvtp::Row_file& file : m_files)
        file.sync();
      m_on_durable(m_pending);
      m_pending.clear();
    }
    m_last_sync = Clock::now();
  }

  std::mutex m_mutex;
  std::deque<dggvtp::Row_file> m_files;    // a deque: a file never moves
  std::uint64_t m_header_size, m_row_size; // bytes
  double m_interval;                       // seconds between two syncs at most
  std::function<void(const std::vector<std::size_t>&)> m_on_durable;
  std::vector<std::size_t> m_pending;      // written, not yet durable
  std::size_t m_kill_after;                // tests only: rows written before the kill, 0 = never
  std::size_t m_written = 0;               // rows written by this process
  Clock::time_point m_last_sync;
};

// =============================================================================================
// Progress
// =============================================================================================

// A thread of rank 0 printing the rows done (durable, from all ranks) every second: a line
// rewritten in place on a terminal, a line every 10 s otherwise.
class Progress
{
public:
  Progress(std::function<std::size_t()> count, std::size_t total, std::size_t already_done)
    : m_count(std::move(count)), m_total(total), m_start_count(already_done), m_terminal(::isatty(2) != 0),
      m_start(Clock::now()), m_thread([this] { loop(); })
  {
  }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress()
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_stop = true;
    }
    m_wake.notify_all();
    m_thread.join();
  }

private:
  void loop()
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    Clock::time_point last_line = Clock::now();
    for(;;)
    {
      const bool stop = m_wake.wait_for(lock, std::chrono::seconds(1), [this] { return m_stop; });
      std::size_t done = m_start_count;
      try
      {
        done = m_count();
      }
      catch(const std::exception&)
      {
      }
      if(m_terminal || stop || seconds_since(last_line) >= 10.)
      {
        print(done, stop);
        last_line = Clock::now();
      }
      if(stop)
        return;
    }
  }
  static std::string duration(double s)
  {
    if(!std::isfinite(s))
      return "?";
    const long t = long(s + 0.5);
    char text[32];
    if(t >= 3600)
      std::snprintf(text, sizeof text, "%ldh%02ldm", t / 3600, t / 60 % 60);
    else if(t >= 60)
      std::snprintf(text, sizeof text, "%ldm%02lds", t / 60, t % 60);
    else
      std::snprintf(text, sizeof text, "%lds", t);
    return text;
  }
  void print(std::size_t done, bool last)
  {
    const double elapsed = seconds_since(m_start);
    const double rate = elapsed > 0. ? double(done - std::min(done, m_start_count)) / elapsed : 0.;
    const double left = rate > 0. ? double(m_total - std::min(done, m_total)) / rate
                                  : std::numeric_limits<double>::infinity();
    char line[200];
    std::snprintf(line, sizeof line, "dggvtp-batch: %zu/%zu rows (%.1f%%), %.3g rows/s, %s %s", done, m_total,
                  m_total > 0 ? 100. * double(done) / double(m_total) : 100., rate,
                  last ? "elapsed" : "ETA", (last ? duration(elapsed) : duration(left)).c_str());
    if(m_terminal)
      std::fprintf(stderr, "\r%-79s%s", line, last ? "\n" : "");
    else
      std::fprintf(stderr, "%s\n", line);
    std::fflush(stderr);
  }

  std::function<std::size_t()> m_count; // rows done so far, all ranks
  std::size_t m_total, m_start_count;
  bool m_terminal;
  Clock::time_point m_start;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  bool m_stop = false;
  std::thread m_thread; // last: starts once the rest is ready
};

// CPU time of this process so far (all its threads, user + system), in seconds
double cpu_seconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}



// =============================================================================================
// The run
// =============================================================================================

// Runs `body` on every rank; if it throws on any, the first rank that failed prints its error
// and every rank gets the largest exit status (1 bad usage, 2 bad input), 0 otherwise.
int collectively(const dggvtp::Communicator& comm, const std::function<void()>& body)
{
  int status = 0;
  std::string message;
  try
  {
    body();
  }
  catch(const Usage_error& e)
  {
    status = 1;
    message = std::string("error: ") + e.what() + " (see dggvtp-batch --help)";
  }
  catch(const std::bad_alloc&)
  {
    status = 2;
    message = "error: out of memory";
  }
  catch(const std::exception& e)
  {
    status = 2;
    message = std::string("error: ") + e.what();
  }
  const int first = comm.min(status != 0 ? comm.rank() : comm.size());
  if(first == comm.rank())
    std::cerr << message << std::endl;
  return comm.max(status);
}

struct Phase_one
{
  Options options;
  std::shared_ptr<dggvtp::Loaded_soup> soup;
  std::size_t file_vertices = 0;
  std::vector<std::string> repairs;
  Sources sources;
  Prepared prepared;
  double seconds_load = 0.;   // reading the file
  double seconds_repair = 0.; // the input policy's repairs, if the soup needs them
  double seconds_sample = 0.; // choosing the sources of fps:K
};

int run_main(dggvtp::Communicator& comm, int argc, char** argv)
{
  const Clock::time_point t_start = Clock::now();
  const bool root = comm.rank() == 0;
  Phase_one one;
  Options& options = one.options;

  // 1. every rank: options, mesh, sources, solver
  int status = collectively(comm, [&] {
    options = parse_options(argc, argv);
    if(options.help)
      return;
    if(options.local_matrix() && comm.size() > 1)
      throw Usage_error("--max-distance runs in one process (its rows are gathered in memory): run it without mpirun, "
                        "with --threads");
    check_outputs(options);
    const Clock::time_point t0 = Clock::now();
    one.soup = std::make_shared<dggvtp::Loaded_soup>(dggvtp::load_soup(options.mesh));
    one.file_vertices = one.soup->file_vertices;
    one.sources = read_sources(options.sources, one.file_vertices, options.first_sample);
    dggvtp::npy_file_size(options.dtype, one.sources.rows, one.file_vertices); // too large: error now
    one.seconds_load = seconds_since(t0);
    // one thread per process where MPI allows no threads, as for the rows
    const long threads = comm.allows_threads() ? dggvtp::threads_of_process(options.threads, comm) : 1;
    one.prepared = options.precision == "float"
                     ? prepare<CGAL::Simple_cartesian<float>>(one.soup, options.epsilon, options.max_distance, threads,
                                                              !options.error_bounds.empty())
                     : prepare<CGAL::Exact_predicates_inexact_constructions_kernel>(
                         one.soup, options.epsilon, options.max_distance, threads, !options.error_bounds.empty());
    one.repairs = one.soup->repairs;
    one.seconds_repair = one.prepared.seconds_make_mesh;
    const Clock::time_point t_sample = Clock::now();
    if(one.sources.farthest_point)
      one.sources.vertices = one.prepared.sample(one.sources.rows, one.sources.first_sample, threads);
    one.seconds_sample = seconds_since(t_sample);
  });
  if(status != 0)
    return status;
  if(options.help)
  {
    if(root)
      std::cout << (options.version ? dggvtp::version_text("dggvtp-batch") : std::string(usage_text));
    return 0;
  }
  long threads = dggvtp::threads_of_process(options.threads, comm);
  if(!comm.allows_threads() && threads != 1)
  {
    if(root && !options.quiet && threads > 1) // 0, all cores, is one core then: nothing to say
      std::cerr << "warning: the MPI library does not allow several threads to call it: one thread per process\n";
    threads = 1;
  }
  if(root && !options.quiet)
  {
    for(const std::string& repair : one.repairs)
      std::cerr << "warning: " << options.mesh << ": " << repair << "\n";
#ifndef CGAL_LINKED_WITH_TBB
    if(options.threads > 1) // 0, all cores, is one core without TBB: nothing to say
      std::cerr << "warning: dggvtp-batch was built without TBB: one thread per process\n";
#endif
  }

  Sources& sources = one.sources;
  const std::string header = dggvtp::npy_header(options.dtype, sources.rows, one.file_vertices);
  const std::uint64_t row_size = std::uint64_t(one.file_vertices) * dggvtp::npy_item_size(options.dtype);
  const std::uint64_t file_size = dggvtp::npy_file_size(options.dtype, sources.rows, one.file_vertices);
  const Checkpoint checkpoint{options.checkpoint};

  // 2. rank 0 opens the checkpoint; the others learn the done rows
  Resume resume;
  resume.done.assign(sources.rows, 0);
  status = collectively(comm, [&] {
    if(!root || options.local_matrix())
      return;
    const std::string fingerprint = fingerprint_of(options, sources, one.file_vertices);
    check_room_for_output(options, checkpoint, sources.rows, one.file_vertices, file_size);
    in_checkpoint(options, [&] {
      resume = open_checkpoint(checkpoint, fingerprint, header, file_size, sources, one.file_vertices,
                               !options.error_bounds.empty());
    });
  });
  if(status != 0)
    return status;
  if(root && !options.quiet)
    for(const std::string& note : resume.notes)
      std::cerr << "warning: " << note << "\n";
  if(!options.local_matrix())
  {
    std::string done(resume.done.begin(), resume.done.end());
    comm.broadcast(done);
    resume.done.assign(done.begin(), done.end());
  }
  std::size_t already_done = 0;
  for(unsigned char d : resume.done)
    already_done += d;

  // 3. the missing rows
  const bool show_progress = root && !options.quiet && (options.progress || ::isatty(2));
  std::size_t kill_after = 0;
  status = collectively(comm, [&] { kill_after = rows_before_test_kill(comm.rank()); });
  if(status != 0)
    return status;
  const Clock::time_point t_compute = Clock::now();
  std::size_t computed = 0; // by this rank
  dggvtp::Unreachable_rows unreachable; // of this rank's rows
  std::vector<dggvtp::Sparse_row> local_rows; // --max-distance
  double seconds_own = 0.;  // this rank's rows, without waiting for the others
  try
  {
    std::atomic<std::size_t> durable(already_done); // --max-distance: rows done, for the progress line
    if(options.local_matrix()) // one process (checked above), no checkpoint
    {
      local_rows.resize(sources.rows);
      std::optional<Progress> progress;
      if(show_progress)
        progress.emplace([&] { return durable.load(); }, sources.rows, 0);
      one.prepared.local_rows(sources.vertices, threads, [&](std::size_t i, dggvtp::Sparse_row&& row) {
        local_rows[i] = std::move(row);
        ++durable;
      });
      computed = sources.rows;
      seconds_own = seconds_since(t_compute);
    }
    else
    {
      std::vector<std::size_t> mine; // the missing rows: the i-th to rank i mod R
      for(std::size_t r = 0, i = 0; r < sources.rows; ++r)
        if(!resume.done[r] && i++ % std::size_t(comm.size()) == std::size_t(comm.rank()))
          mine.push_back(r);
      dggvtp::Record_file record(checkpoint.record(comm.rank()));
      Row_sink sink(checkpoint.row_files(!options.error_bounds.empty()), comm.uses_mpi(), header.size(), row_size, 1.0,
                    [&](const std::vector<std::size_t>& rows) { record.append(rows); }, kill_after);
      std::optional<Progress> progress;
      if(show_progress)
        progress.emplace(
          [&] {
            std::vector<unsigned char> done(sources.rows, 0);
            dggvtp::read_records(checkpoint.directory, done);
            std::size_t n = 0;
            for(unsigned char d : done)
              n += d;
            return n;
          },
          sources.rows, already_done);
      std::vector<std::size_t> file_vertices;
      for(std::size_t r : mine)
        file_vertices.push_back(sources.vertices[r]);
      one.prepared.rows(file_vertices, threads, [&](std::size_t i, Row_values&& values) {
        thread_local std::vector<std::vector<char>> bytes(2);
        unreachable.add(values.distances.begin(), values.distances.end());
        encode_row(values.distances, options.dtype, bytes[0]);
        encode_row(values.bounds, options.dtype, bytes[1]);
        sink.write(mine[i], bytes);
      });
      sink.flush();
      computed = mine.size();
      seconds_own = seconds_since(t_compute);
      comm.idle_barrier();
    }
  }
  catch(const std::exception& e)
  {
    // the errors of the rows' files: of the checkpoint
    const std::string what = dynamic_cast<const std::bad_alloc*>(&e) ? std::string("out of memory")
                             : dynamic_cast<const Input_error*>(&e) ? e.what() + options.checkpoint_origin()
                                                                    : std::string(e.what());
    std::cerr << "error: " << (comm.size() > 1 ? "rank " + std::to_string(comm.rank()) + ": " : std::string()) << what
              << std::endl;
    if(comm.size() > 1)
      comm.abort(2); // the other ranks would wait for this one for ever
    return 2;
  }
  const double seconds_compute = seconds_since(t_compute);

  // 4. rank 0: every row recorded? then the output
  const std::vector<double> rss = comm.gather(peak_rss_mb());
  const std::vector<double> cpu = comm.gather(cpu_seconds());
  const std::vector<double> compute_seconds = comm.gather(seconds_own);
  const std::vector<double> computed_per_rank = comm.gather(double(computed));
  const std::vector<double> unreachable_rows = comm.gather(double(unreachable.rows.load()));
  const std::vector<double> unreachable_most = comm.gather(double(unreachable.most.load()));
  const Clock::time_point t_write = Clock::now();
  status = collectively(comm, [&] {
    if(!root)
      return;
    if(options.local_matrix())
      dggvtp::write_file_atomically(options.output, [&](const dggvtp::Npz_writer::Sink& write) {
        dggvtp::write_csr_npz(local_rows, one.file_vertices, options.dtype, write);
      });
    else
      in_checkpoint(options, [&] {
        std::vector<unsigned char> done(sources.rows, 0);
        dggvtp::read_records(checkpoint.directory, done);
        for(std::size_t r = 0; r < sources.rows; ++r)
          if(!done[r])
            throw Input_error("row " + std::to_string(r) + " is not recorded as done after the run (the checkpoint '" +
                              checkpoint.directory + "' was changed meanwhile?)");
      });
    if(!options.local_matrix())
      finish_checkpoint(checkpoint, options.output, options.error_bounds);
    if(!options.sources_output.empty())
    {
      std::string text;
      for(std::size_t v : sources.vertices)
        text += std::to_string(v) + "\n";
      dggvtp::write_file_atomically(options.sources_output, text);
    }
  });
  if(status != 0 || !root)
    return status;
  const double seconds_write = seconds_since(t_write);

  std::size_t computed_total = 0;
  for(double c : computed_per_rank)
    computed_total += std::size_t(c);
  // even with --quiet: a scan in pieces or a stray vertex is worth knowing before using the rows
  const double rows_unreachable = std::accumulate(unreachable_rows.begin(), unreachable_rows.end(), 0.);
  if(rows_unreachable > 0.)
    std::cerr << "warning: "
              << dggvtp::unreachable_rows_warning(std::size_t(rows_unreachable), computed_total,
                                                  std::size_t(*std::max_element(unreachable_most.begin(), unreachable_most.end())),
                                                  one.file_vertices)
              << "\n";
  const double seconds_total = seconds_since(t_start);
  const auto json_list = [](const std::vector<double>& values, const char* format) {
    std::string out;
    for(double v : values)
    {
      char text[32];
      std::snprintf(text, sizeof text, format, v);
      out += (out.empty() ? "" : ", ") + std::string(text);
    }
    return out;
  };
  std::string rss_list;
  double rss_max = 0.;
  for(double r : rss)
  {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", r);
    rss_list += (rss_list.empty() ? "" : ", ") + std::string(text);
    rss_max = (std::max)(rss_max, r);
  }
  const char* dtype = options.dtype == Npy_dtype::float32 ? "float32" : "float64";
  if(!options.stats.empty())
  {
    const auto format = [&](char* text, std::size_t size) {
      return std::snprintf(text, size,
                  "{\"mesh\": %s, \"vertices\": %zu, \"faces\": %zu, \"rows\": %zu, \"rows_computed\": %zu, "
                  "\"rows_resumed\": %zu, \"ranks\": %d, \"threads\": %ld, \"epsilon\": %.17g, \"precision\": \"%s\", "
                  "\"dtype\": \"%s\", \"seconds_load\": %.6f, \"seconds_repair\": %.6f, \"seconds_prepare\": %.6f, "
                  "\"seconds_sample\": %.6f, \"seconds_compute\": %.6f, \"seconds_write\": %.6f, \"seconds_total\": %.6f, "
                  "\"threads_per_stage\": {\"load\": 1, \"repair\": 1, \"prepare\": %zu, \"compute\": %zu, \"write\": 1}, "
                  "\"peak_rss_mb\": [%s], \"cpu_seconds\": [%s], "
                  "\"seconds_compute_per_rank\": [%s]}\n",
                  json_string(options.mesh).c_str(), one.file_vertices, one.prepared.faces, sources.rows,
                  computed_total, already_done, comm.size(), options.threads, options.epsilon,
                  options.precision.c_str(), dtype, one.seconds_load, one.seconds_repair, one.prepared.seconds_prepare,
                  one.seconds_sample, seconds_compute, seconds_write, seconds_total, one.prepared.threads, one.prepared.threads,
                  rss_list.c_str(), json_list(cpu, "%.3f").c_str(),
                  json_list(compute_seconds, "%.3f").c_str());
    };
    std::vector<char> text(std::size_t(format(nullptr, 0)) + 1);
    format(text.data(), text.size());
    dggvtp::write_file_atomically(options.stats, text.data()); // only rank 0 is left: no collective call
  }
  if(!options.quiet)
    std::cout << "dggvtp-batch: " << options.mesh << ": " << one.file_vertices << " vertices, " << one.prepared.faces
              << " faces\n"
              << "  " << sources.rows << " sources (" << sources.identity << "), "
              << (options.epsilon > 0. ? "DGG-VTP epsilon " + std::to_string(options.epsilon) : std::string("exact (VTP)"))
              << ", " << options.precision << ", " << dtype << "\n"
              << "  " << comm.size() << (comm.size() == 1 ? " process" : " processes") << " x "
              << (options.threads == 0 ? std::string("all cores'") : std::to_string(options.threads))
              << (options.threads == 1 ? " thread" : " threads") << ": computed " << computed_total << " rows"
              << (already_done > 0 ? " (" + std::to_string(already_done) + " were done before)" : std::string()) << "\n"
              << "  load " << one.seconds_load << " s, "
              << (one.seconds_repair > 0. ? "repair " + std::to_string(one.seconds_repair) + " s, " : std::string())
              << "prepare " << one.prepared.seconds_prepare << " s, "
              << (sources.farthest_point ? "sample " + std::to_string(one.seconds_sample) + " s, " : std::string())
              << "rows " << seconds_compute << " s, write "
              << seconds_write << " s, total " << seconds_total << " s\n"
              << "  peak memory per process " << rss_list << " MB\n"
              << "  wrote " << options.output << "\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
#ifndef DGGVTP_WITH_MPI
  if(dggvtp::started_by_mpi_launcher())
  {
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    if(size == nullptr)
      size = std::getenv("PMI_SIZE");
    if(size != nullptr && std::string(size) != "1")
    {
      std::cerr << "error: dggvtp-batch was built without MPI: it cannot share the work among " << size
                << " processes (rebuild it with MPI, or run one process)\n";
      return 1;
    }
  }
#endif
  try
  {
    dggvtp::Communicator comm(argc, argv);
    return run_main(comm, argc, argv);
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "error: out of memory\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
  }
  return 2;
}
