// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// dggvtp: geodesic distances from one vertex of a mesh file to all its vertices, exact (VTP) or
// accuracy-controlled (DGG-VTP). The command-line contract is documented in README.md and in
// `dggvtp --help`; scripts depend on it.

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Simple_cartesian.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <charconv>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace {

const char* const usage_text = R"(usage: dggvtp MESH [options]

Geodesic distances on the surface of a triangle mesh, from one vertex to every vertex.

  MESH                   a mesh file CGAL reads: OFF, OBJ, PLY, STL
  --source N             0-based index of the source vertex in the file's order (default 0)
  --exact                exact distances (VTP algorithm); the default
  --epsilon E            DGG-VTP with accuracy E >= 0: every distance within a relative error E
                         of the exact one (E = 0 is --exact)
  --precision P          double (default) or float
  --threads T            number of threads, 0 = all cores (default 1); the distances are the
                         same bit for bit for any T (without TBB at build time: one thread)
  --output FILE          one line per vertex of the file, in the file's order: the distance
                         printed with %.17g, or inf if no path on the surface reaches it;
                         '-' writes to standard output
  --stats FILE           one JSON object: sizes, times, window counts, peak memory
  --quiet                no summary, no warnings
  --help                 this text

Input policy: polygons are triangulated and inconsistent orientations are fixed, splitting
vertices where needed; a vertex where separate fans of faces meet is kept, and paths may pass
through it (a warning on stderr reports each of these); distances are still reported per vertex
of the file, the smallest over the copies of a split vertex. Vertices no face uses, and vertices of other
connected components than the source's, are unreachable: inf. An unreadable or empty file, a
non-finite coordinate, a face with fewer than 3 or repeated vertices, a degenerate face (zero
length edge or zero area), a sliver (an edge more than 1e10 times longer than the height on it),
the tip of a cone sharper than 1e-4 radians (windows would wrap around those for hours), a polygon that cannot be triangulated (it touches or crosses itself)
or an out-of-range source is an error: one line on stderr starting with 'error:', exit status 2,
and no output file; so are OFF files with texture coordinates (STOFF), binary OFF with colours,
and skeletons (SKEL), which CGAL's reader cannot read safely. Bad usage: exit status 1.
)";

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string mesh;
  std::size_t source = 0;
  double epsilon = 0.;
  std::string precision = "double";
  long threads = 1;
  std::string output;
  std::string stats;
  bool quiet = false;
};

template <class T>
T parse_number(const std::string& option, const std::string& text)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  T value{};
  if(std::is_floating_point<T>::value)
    value = T(std::strtod(begin, &end));
  else if(!text.empty() && text[0] != '-')
    value = T(std::strtoull(begin, &end, 10));
  if(end == begin || end == nullptr || *end != '\0' || errno == ERANGE)
    throw Usage_error("invalid value '" + text + "' for " + option);
  return value;
}

Options parse_options(int argc, char** argv)
{
  Options options;
  bool exact = false, epsilon = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Usage_error(arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage_text;
      std::exit(0);
    }
    else if(arg == "--source")
      options.source = parse_number<std::size_t>(arg, value());
    else if(arg == "--exact")
      exact = true;
    else if(arg == "--epsilon")
    {
      options.epsilon = parse_number<double>(arg, value());
      if(!(options.epsilon >= 0.) || !std::isfinite(options.epsilon))
        throw Usage_error("--epsilon must be a finite number >= 0");
      epsilon = true;
    }
    else if(arg == "--precision")
    {
      options.precision = value();
      if(options.precision != "double" && options.precision != "float")
        throw Usage_error("--precision must be double or float");
    }
    else if(arg == "--threads")
      options.threads = long(parse_number<std::size_t>(arg, value()));
    else if(arg == "--output" || arg == "--stats")
    {
      (arg == "--output" ? options.output : options.stats) = value();
      if((arg == "--output" ? options.output : options.stats).empty())
        throw Usage_error(arg + " needs a file name ('-' for standard output)");
    }
    else if(arg == "--quiet")
      options.quiet = true;
    else if(arg.size() > 1 && arg[0] == '-')
      throw Usage_error("unknown option " + arg);
    else if(options.mesh.empty())
      options.mesh = arg;
    else
      throw Usage_error("more than one MESH given ('" + options.mesh + "' and '" + arg + "')");
  }
  if(options.mesh.empty())
    throw Usage_error("no MESH given");
  if(exact && epsilon && options.epsilon > 0.)
    throw Usage_error("--exact and --epsilon E > 0 contradict each other");
  return options;
}

// Writes a regular file through a temporary file next to `path`, renamed over it only once
// complete, so that an error never leaves a partial file. A path that exists and is not a regular
// file (/dev/null, a pipe, a terminal) is written in place: renaming over it would replace the
// device or pipe with a file. "-" is standard output.
class Output_file
{
public:
  explicit Output_file(const std::string& path) : m_path(path)
  {
    if(path == "-")
    {
      m_file = stdout;
      return;
    }
    struct stat existing;
    const bool exists = ::stat(path.c_str(), &existing) == 0;
    if(exists && !S_ISREG(existing.st_mode))
    {
      if(S_ISDIR(existing.st_mode))
        throw dggvtp::Input_error("cannot write '" + path + "': it is a directory");
      if(!(m_file = std::fopen(path.c_str(), "w")))
        throw dggvtp::Input_error("cannot write '" + path + "': " + std::strerror(errno));
      return;
    }
    m_temporary = path + ".tmp-XXXXXX";
    const int fd = mkstemp(&m_temporary[0]);
    if(fd < 0)
      throw dggvtp::Input_error("cannot write '" + path + "': " + std::strerror(errno));
    // mkstemp creates the file private (0600); give it the mode the file it replaces had, or the
    // mode a plain new file would get
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, exists ? (existing.st_mode & 07777) : (0666 & ~mask));
    if(!(m_file = fdopen(fd, "w")))
    {
      const int error = errno;
      ::close(fd);
      std::remove(m_temporary.c_str());
      throw dggvtp::Input_error("cannot write '" + path + "': " + std::strerror(error));
    }
  }
  Output_file(const Output_file&) = delete;
  Output_file& operator=(const Output_file&) = delete;
  ~Output_file()
  {
    if(m_file && m_file != stdout)
    {
      std::fclose(m_file);
      if(!m_temporary.empty())
        std::remove(m_temporary.c_str());
    }
  }
  FILE* get() const { return m_file; }
  void commit()
  {
    if(m_file == stdout)
    {
      if(std::fflush(stdout) != 0)
        throw dggvtp::Input_error("cannot write to standard output");
      return;
    }
    const bool written = std::fflush(m_file) == 0 && !std::ferror(m_file);
    const bool closed = std::fclose(m_file) == 0;
    m_file = nullptr;
    if(m_temporary.empty())
    {
      if(!written || !closed)
        throw dggvtp::Input_error("cannot write '" + m_path + "'");
      return;
    }
    if(!written || !closed || std::rename(m_temporary.c_str(), m_path.c_str()) != 0)
    {
      std::remove(m_temporary.c_str());
      throw dggvtp::Input_error("cannot write '" + m_path + "'");
    }
  }

private:
  std::string m_path;
  std::string m_temporary; // empty when writing in place
  FILE* m_file = nullptr;
};

struct Run
{
  std::size_t faces = 0;
  double seconds_make_mesh = 0.; // soup to mesh, with repairs: part of loading
  double seconds_prepare = 0., seconds_propagate = 0.;
  CGAL::DGG_VTP_3::Propagation_statistics statistics;
  std::vector<double> distances; // per file vertex
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The solver keeps what it needs, so the soup is gone before the propagation: the peak memory is
// the larger of input + solver and solver + propagation, not their sum.
template <class Kernel>
Run compute(dggvtp::Loaded_soup& soup, const Options& options)
{
  using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;
  Run run;
  std::optional<Solver> solver;
  const Clock::time_point t0 = Clock::now();
  run.seconds_make_mesh = dggvtp::make_solver(soup, solver);
  run.seconds_prepare = seconds_since(t0) - run.seconds_make_mesh;
  run.faces = soup.triangles.size();
  dggvtp::release_soup(soup);

  std::vector<typename Solver::FT> d(solver->number_of_vertices());
  const Clock::time_point t1 = Clock::now();
  // the distances are the same bit for bit on any number of threads (and without TBB)
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> limit;
  if(options.threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
#endif
  run.statistics = solver->template compute_distances_to_nearest_source<CGAL::Parallel_if_available_tag>(
    dggvtp::solver_vertices_of(soup, options.source), CGAL::make_property_map(d),
    CGAL::parameters::accuracy(options.epsilon));
  run.seconds_propagate = seconds_since(t1);
  run.distances = dggvtp::file_vertex_distances(soup, d);
  return run;
}

double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

// The text of printf's "%.17g\n" (and "inf\n"), formatted with std::to_chars into large blocks:
// printf per line took most of the writing time.
void write_distances(const std::vector<double>& distances, const std::string& path)
{
  Output_file file(path);
  std::vector<char> block(1 << 20);
  const std::size_t longest_line = 32; // "-1.2345678901234567e-308\n" is 25
  std::size_t used = 0;
  const auto flush = [&] {
    if(std::fwrite(block.data(), 1, used, file.get()) != used)
      throw dggvtp::Input_error("cannot write '" + path + "'");
    used = 0;
  };
  for(double d : distances)
  {
    if(block.size() - used < longest_line)
      flush();
    char* end = std::to_chars(block.data() + used, block.data() + block.size(), d, std::chars_format::general, 17).ptr;
    *end++ = '\n';
    used = std::size_t(end - block.data());
  }
  flush();
  file.commit();
}

std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for(char c : s)
  {
    if(c == '"' || c == '\\')
      out += '\\';
    if(static_cast<unsigned char>(c) < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    }
    else
      out += c;
  }
  return out + "\"";
}

int run_main(int argc, char** argv)
{
  Options options;
  try
  {
    options = parse_options(argc, argv);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "error: " << e.what() << " (see dggvtp --help)\n";
    return 1;
  }

  const Clock::time_point t0 = Clock::now();
  dggvtp::Loaded_soup soup = dggvtp::load_soup(options.mesh);
  if(options.source >= soup.file_vertices)
    throw dggvtp::Input_error("source " + std::to_string(options.source) + " is out of range (the mesh has " +
                              std::to_string(soup.file_vertices) + " vertices)");
  const double seconds_read = seconds_since(t0);

  Run run;
  try
  {
    run = options.precision == "float" ? compute<CGAL::Simple_cartesian<float>>(soup, options)
                                       : compute<CGAL::Exact_predicates_inexact_constructions_kernel>(soup, options);
  }
  catch(const std::invalid_argument& e) // the library's documented preconditions
  {
    throw dggvtp::Input_error(e.what());
  }
  const double seconds_load = seconds_read + run.seconds_make_mesh;
  if(!options.quiet)
    for(const std::string& repair : soup.repairs)
      std::cerr << "warning: " << options.mesh << ": " << repair << "\n";
#ifndef CGAL_LINKED_WITH_TBB
  if(!options.quiet && options.threads != 1)
    std::cerr << "warning: dggvtp was built without TBB: the propagation ran on one thread\n";
#endif

  const Clock::time_point t_write = Clock::now();
  if(!options.output.empty())
    write_distances(run.distances, options.output);
  const double seconds_write = seconds_since(t_write);

  double farthest = 0.;
  for(double d : run.distances)
    if(std::isfinite(d))
      farthest = (std::max)(farthest, d);
  const double rss = peak_rss_mb();
  const auto& s = run.statistics;
  if(!options.stats.empty())
  {
    Output_file file(options.stats);
    std::fprintf(file.get(),
                 "{\"mesh\": %s, \"vertices\": %zu, \"faces\": %zu, \"source\": %zu, \"epsilon\": %.17g, "
                 "\"precision\": \"%s\", \"threads\": %ld, \"seconds_load\": %.6f, \"seconds_prepare\": %.6f, "
                 "\"seconds_propagate\": %.6f, \"seconds_write\": %.6f, \"windows_created\": %zu, \"windows_peak\": %zu, "
                 "\"pseudo_sources\": %zu, \"vertices_popped\": %zu, \"vertices_reached\": %zu, "
                 "\"max_distance\": %.17g, \"peak_rss_mb\": %.1f}\n",
                 json_string(options.mesh).c_str(), soup.file_vertices, run.faces, options.source, options.epsilon,
                 options.precision.c_str(), options.threads, seconds_load, run.seconds_prepare,
                 run.seconds_propagate, seconds_write, s.windows_created, s.windows_peak, s.pseudo_sources, s.vertices_popped,
                 s.vertices_reached, farthest, rss);
    file.commit();
  }
  if(!options.quiet)
  {
    std::ostream& out = options.output == "-" ? std::cerr : std::cout;
    std::size_t reached = 0;
    for(double d : run.distances)
      reached += std::isfinite(d) ? 1 : 0;
    out << "dggvtp: " << options.mesh << ": " << soup.file_vertices << " vertices, " << run.faces << " faces\n"
        << "  source " << options.source << ", "
        << (options.epsilon > 0. ? "DGG-VTP epsilon " + std::to_string(options.epsilon) : std::string("exact (VTP)"))
        << ", " << options.precision << "\n"
        << "  load " << seconds_load << " s, prepare " << run.seconds_prepare << " s, propagate "
        << run.seconds_propagate << " s, write " << seconds_write << " s\n"
        << "  windows created " << s.windows_created << ", peak " << s.windows_peak << ", pseudo-sources "
        << s.pseudo_sources << "\n"
        << "  reached " << reached << " of " << soup.file_vertices << " vertices, farthest at " << farthest << "\n"
        << "  peak memory " << rss << " MB\n";
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run_main(argc, argv);
  }
  catch(const dggvtp::Input_error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
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
