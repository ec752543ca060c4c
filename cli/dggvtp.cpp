// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// dggvtp: geodesic distances from vertices or points of a mesh file's surface to all its vertices
// or to chosen targets, and shortest paths, exact (VTP) or accuracy-controlled (DGG-VTP). The
// command-line contract is documented in README.md and in `dggvtp --help`; scripts depend on it.

#include <dggvtp/arguments.h>
#include <dggvtp/command_line.h>
#include <dggvtp/field_files.h>
#include <dggvtp/isoline_file.h>
#include <dggvtp/single_value_options.h>
#include <dggvtp/version.h>
#include <dggvtp/load_mesh.h>
#include <dggvtp/npy.h>
#include <dggvtp/output_paths.h>
#include <dggvtp/progress_line.h>
#include <dggvtp/query_places.h>
#include <dggvtp/repair.h>
#include <dggvtp/threads.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Simple_cartesian.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <iostream>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

const char* const usage_text = R"(usage: dggvtp MESH [options]

Geodesic distances on the surface of a triangle mesh, from the nearest of one or several sources
(vertices or points of the surface) to every vertex or to chosen targets, and shortest paths.

  MESH                   a mesh file CGAL reads: OFF, OBJ, PLY, STL
  --source N             a source at vertex N (0-based, in the file's order); repeatable: the
                         distance to the nearest source (default: vertex 0, if no source is given)
  --source-point X Y Z   a source at the point of the surface nearest to (X, Y, Z); repeatable,
                         and mixes with --source
  --target N             print the distance of vertex N, or of the surface point nearest to
  --target-point X Y Z   (X, Y, Z), on standard output, one line per target in the order given;
                         repeatable; the propagation stops once the targets' distances are final
  --path-to N            trace the shortest path from vertex N, or from the surface point nearest
  --path-to-point X Y Z  to (X, Y, Z), back to its nearest source and print its length on standard
                         output (one line per path in the order given, after the targets' lines);
                         repeatable; the propagation stops as for --target
  --paths FILE           write the paths of --path-to into an OBJ file: per path a comment, its
                         points as v lines from the target to the source, and one l line; with
                         --pairs, one path per pair, from its source to its target
  --pairs FILE           the distance of each pair of FILE, a source vertex and a target vertex
                         per line (0-based, as --source N; '#' lines and blank lines skipped),
                         on standard output one line per pair in the order given, printed as
                         --target prints; each pair its own propagation, stopped once its target
                         is final, the pairs in parallel (--threads), the same bits as
                         --source S --target T; not with --source, --target, --path-to (put
                         those pairs in FILE), --fps or the per-vertex outputs
  --fps K                farthest-point sampling of K vertices: the --first-sample vertex,
                         then each time the vertex farthest from those chosen (the smallest
                         index on ties; unreachable vertices first; with --epsilon E, one within
                         (1 + E) of the farthest), printed on standard output one a line; the
                         field (--output, --error-bounds) is the distance to the nearest sample
                         and --labels the number of that sample, in every output format (a PLY
                         or VTK file colours the samples' cells). Each sample costs its cell,
                         not a whole field. Not with --source-point, --target, --path-to,
                         --max-distance
  --first-sample N       the first sample of --fps: vertex N (default 0); the library's
                         first_sample (--source N, its former spelling, still works with a
                         warning)
  --max-distance D       stop the propagation at distance D >= 0 (inf allowed): vertices, targets
                         and paths farther away are unreached (inf)
  --exact                exact distances (VTP algorithm); the default
  --epsilon E            DGG-VTP with accuracy E in [0, 1]: every distance within a relative error E
                         of the exact one (E = 0 is --exact)
  --precision P          double (default) or float
  --threads T            number of threads of the preparation and the propagation, 0 = all cores
                         (the default); the distances are the same bit for bit for any T
                         (without TBB at build time: one thread); --threads 1 beside other jobs,
                         e.g. one dggvtp per core in a pool of processes
  --output FILE          one line per vertex of the file, in the file's order: the distance
                         printed with %.17g, or inf if no path on the surface reaches it;
                         '-' writes to standard output
  --error-bounds FILE    one line per vertex of the file, in the file's order: a certified bound
                         on the error of its distance (distance - exact distance is in [0, this]:
                         the distance less the least key that reached the vertex, a lower bound
                         of the exact distance; at most epsilon x the distance, 0 where the
                         distance is certified exact, as at the sources and everywhere in the
                         exact mode), printed with %.17g, inf where unreached; in the format of
                         --output-format (ply, vtk: the field error_bound)
  --labels FILE          one line per vertex of the file, in the file's order: its nearest source,
                         the 0-based number of its --source or --source-point option in the order
                         given, or -1 if no source reaches it; '-' writes to standard output
  --output-format F      text, npy, ply or vtk; by default each file's extension chooses (.npy,
                         .ply, .vtk, anything else text). npy: --output and --labels as NumPy
                         .npy files (format version 1.0, shape (vertices of the file,)): the
                         distances as little-endian float64 '<f8' (inf if unreached), the labels
                         as '<i8'. ply, vtk (--output only): the mesh with the field, in the
                         file's vertex order, for MeshLab and ParaView: binary little-endian PLY
                         with vertex x y z, float quality (the distance; unreached: the largest
                         finite distance), double distance (inf if unreached) and, with
                         --labels, int label; or legacy binary VTK polydata with the point
                         scalars distance (double) and label (int)
  --isolines K           the isolines at K distances evenly spaced between 0 and the largest
  --isolines-at D1,D2,.. finite distance (excluded), or at the distances given, into the OBJ file
  --isolines-output FILE of --isolines-output: per distance a comment, per connected piece of the
                         curve its points as v lines and one l line, which ends with its first
                         vertex again where the piece is closed; the curves are where the linear
                         interpolation of the vertex distances over the triangles equals the
                         distance, through the mesh's edges; edges to unreached vertices are not
                         crossed
  --stats FILE           one JSON object: sizes, the time of each stage (load, repair, prepare,
                         locate, propagate, write) and the threads it used, window counts, peak
                         memory; with --error-bounds, the largest and the mean certified bound
                         over epsilon x distance and the share of the vertices certified exact
  --repair               repair the mesh with CGAL's Polygon_mesh_processing before the input
                         checks, once the faces that repeat a vertex are dropped (refused
                         without --repair): stitch_borders (coincident border edges),
                         remove_degenerate_faces (zero length edges, zero area),
                         remove_almost_degenerate_faces (angles within 0.1 degree of flat,
                         edges 1e4 times shorter than their face's longest and under 1e-4 of
                         the bounding box's diagonal) and
                         remove_isolated_vertices; one 'warning:' line per kind of repair with
                         its counts. Results stay per vertex of the file: a vertex merged with
                         another at its place takes its distance and label, a removed one is nan
                         (label -1); a source or target there is one on the vertex it merged with,
                         and an error where it was removed
  --progress             the progress line on stderr (percentage of the vertices final, time
                         elapsed and left) from the start of the propagation, also when stderr is
                         not a terminal (then one line a second); on a terminal it shows anyway
                         once the propagation has taken a second
  --quiet                no summary, no progress, no warnings but the one about unreachable
                         vertices
  --help                 this text
  --version              the version of dggvtp and of CGAL

Short names: -s is --source, -o is --output, -h is --help. A value may also follow its option
after '=' (--output=d.ply, --source-point=1 2 3). An unknown option is refused with the nearest
known one ("did you mean --source?").

Vertices that no path on the surface reaches (other connected components than the sources',
vertices no face uses) are inf, and a 'warning:' line on stderr counts them, even with --quiet
(targets and paths likewise; not with --max-distance, which leaves vertices unreached on purpose).

Targets and paths stop the propagation before the other vertices are final, so --target and
--path-to do not combine with --output and --labels (ask for those in another run). Distances
and paths are printed with %.17g, or inf for unreached ones. A point is taken at the nearest
point of the surface (CGAL::Polygon_mesh_processing::locate), so it may lie off the surface; one
farther from it than 1e-6 times the diagonal of the mesh's bounding box gets a 'warning:' line
on stderr giving the distance it was moved. Only one output may go to standard output; the
summary then goes to standard error.

Input policy: polygons are triangulated and inconsistent orientations are fixed, splitting
vertices where needed (an edge of more than two faces); a vertex where separate fans of faces
meet is kept, and paths may pass through it (a warning on stderr reports each of these). The
copies of a split vertex are one point: paths go on from each and across a split edge into every
sheet of it; distances are still reported per vertex of the file, the smallest over the copies
of a split vertex (a source or target vertex is one on all its copies). A face on the same
three vertices as another is dropped before splitting. Vertices no face uses, and vertices of other
connected components than the sources', are unreachable: inf. An unreadable or empty file, a
non-finite coordinate, a mesh too large for a double (its bounding box, or a face's squared
edge lengths or area, overflow: scale it down), a face with fewer than 3 or repeated vertices
(--repair drops the latter),
a degenerate face (zero length edge or zero area), a sliver (an edge more than 1e10 times
longer than the height on it),
an edge shorter than 1e-3 machine epsilons times the mesh's size (2.2e-19 of it in double),
the tip of a cone sharper than 1e-4 radians (windows would wrap around those for hours), a polygon that cannot be triangulated (it touches or crosses itself)
or an out-of-range vertex is an error: one line on stderr starting with 'error:', exit status 2,
and no output file; so are OFF files with texture coordinates (STOFF), binary OFF with colours,
and skeletons (SKEL), which CGAL's reader cannot read safely.

Exit status, by the kind of mistake: 0 success; 1 bad usage, a command line wrong whatever the
mesh: an unknown option, a missing value, a value that is not a number, a value out of its
range (a negative or NaN --max-distance, an --epsilon outside [0, 1]), a coordinate that is not
finite, a negative index, options that contradict each other; 2 bad input, a command line that this mesh or these files make wrong: an
index out of range, a mesh that cannot be read or that the input policy refuses, an output that
cannot be written (checked before the mesh is loaded). Either way one line on stderr starting
with 'error:'.
)";

using dggvtp::json_string;
using dggvtp::parse_number;
using dggvtp::peak_rss_mb;
using dggvtp::Place;
using dggvtp::Point_3;
using dggvtp::Polyline;
using dggvtp::Triangle;
using dggvtp::Usage_error;

struct Options : dggvtp::Propagation_options
{
  std::string mesh;
  std::vector<Place> sources;   // in the order given: a label is a number in it
  std::vector<Place> targets;
  std::vector<Place> path_targets;
  double max_distance = std::numeric_limits<double>::infinity();
  long threads = 0;   // 0: all cores
  std::string output;
  std::string error_bounds;
  std::string labels;
  std::string output_format; // empty: by each file's extension
  std::string paths;
  std::string stats;
  std::string pairs_file;   // --pairs FILE
  std::vector<std::pair<std::size_t, std::size_t>> pairs;       // its pairs (source, target), as read
  std::vector<std::size_t> pair_lines;                          // per pair: its line in the file (1-based)
  std::vector<std::pair<std::size_t, std::size_t>> pair_places; // the pairs on the vertices --repair kept
  std::size_t fps = 0; // --fps K: the number of samples (0: none)
  std::optional<std::size_t> first_sample; // --first-sample N
  bool source_as_first_sample = false;      // --fps with --source N: the former spelling of --first-sample
  std::size_t isolines = 0;
  std::vector<double> isolines_at;
  std::string isolines_output;
  bool quiet = false;
  bool repair = false;
  bool progress = false; // the progress line from the start, on any stderr

  bool has_pairs() const { return !pairs_file.empty(); }
  // targets, paths and pairs end the propagation early
  bool stops_early() const { return !targets.empty() || !path_targets.empty() || has_pairs(); }
  bool has_points() const { return dggvtp::has_points({&sources, &targets, &path_targets}); }
  dggvtp::Repair_option repair_option() const { return {"--repair", repair}; }
};


Options parse_options(int argc, char** argv)
{
  Options options;
  const auto places_of = [&](const std::string& option) -> std::vector<Place>& {
    return option == "--source" ? options.sources : option == "--target" ? options.targets : options.path_targets;
  };
  dggvtp::Single_value_options single_value{"--fps", "--first-sample", "--max-distance", "--epsilon", "--precision", "--threads", "--output", "--error-bounds",
                                            "--labels", "--output-format", "--paths", "--pairs", "--stats", "--isolines",
                                            "--isolines-at", "--isolines-output"};
  dggvtp::Argument_reader words(argc, argv, {{"-h", "--help"}, {"-o", "--output"}, {"-s", "--source"}}, usage_text);
  while(words.next())
  {
    const std::string arg = words.word();
    const auto value = [&] { return words.value(); };
    single_value.check(arg);
    if(arg == "--help")
    {
      std::cout << usage_text;
      std::exit(0);
    }
    else if(arg == "--version")
    {
      std::cout << dggvtp::version_text("dggvtp");
      std::exit(0);
    }
    else if(arg == "--source" || arg == "--target" || arg == "--path-to")
    {
      Place place;
      place.vertex = parse_number<std::size_t>(arg, value());
      places_of(arg).push_back(place);
    }
    else if(arg == "--source-point" || arg == "--target-point" || arg == "--path-to-point")
    {
      Place place;
      place.is_point = true;
      for(double& c : place.point)
      {
        c = parse_number<double>(arg, value());
        if(!std::isfinite(c))
          throw Usage_error(arg + " needs finite coordinates");
      }
      places_of(arg.substr(0, arg.size() - std::strlen("-point"))).push_back(place);
    }
    else if(arg == "--max-distance")
    {
      options.max_distance = parse_number<double>(arg, value());
      if(!(options.max_distance >= 0.))
        throw Usage_error("--max-distance must be a number >= 0 (inf allowed)");
    }
    else if(arg == "--output-format")
    {
      options.output_format = value();
      if(options.output_format != "text" && options.output_format != "npy" && options.output_format != "ply" &&
         options.output_format != "vtk")
        throw Usage_error("--output-format must be text, npy, ply or vtk");
    }
    else if(options.parse(arg, value))
      continue;
    else if(arg == "--threads")
      options.threads = long(parse_number<std::size_t>(arg, value()));
    else if(arg == "--output" || arg == "--stats" || arg == "--labels" || arg == "--paths" || arg == "--error-bounds")
    {
      std::string& file = arg == "--output" ? options.output
                        : arg == "--error-bounds" ? options.error_bounds
                        : arg == "--stats"  ? options.stats
                        : arg == "--labels" ? options.labels : options.paths;
      file = value();
      if(file.empty())
        throw Usage_error(arg + " needs a file name ('-' for standard output)");
    }
    else if(arg == "--pairs")
    {
      options.pairs_file = value();
      if(options.pairs_file.empty())
        throw Usage_error("--pairs needs a file name");
    }
    else if(arg == "--fps")
    {
      options.fps = parse_number<std::size_t>(arg, value());
      if(options.fps == 0)
        throw Usage_error("--fps needs a count >= 1");
    }
    else if(arg == "--first-sample")
      options.first_sample = parse_number<std::size_t>(arg, value());
    else if(arg == "--isolines")
    {
      options.isolines = parse_number<std::size_t>(arg, value());
      if(options.isolines == 0)
        throw Usage_error("--isolines needs a count >= 1");
    }
    else if(arg == "--isolines-at")
    {
      const std::string list = value();
      for(std::size_t start = 0, end; start <= list.size(); start = end + 1)
      {
        end = (std::min)(list.find(',', start), list.size());
        options.isolines_at.push_back(parse_number<double>(arg, list.substr(start, end - start)));
        if(!std::isfinite(options.isolines_at.back()))
          throw Usage_error("--isolines-at needs finite distances");
      }
    }
    else if(arg == "--isolines-output")
    {
      options.isolines_output = value();
      if(options.isolines_output.empty())
        throw Usage_error(arg + " needs a file name ('-' for standard output)");
    }
    else if(arg == "--quiet")
      options.quiet = true;
    else if(arg == "--repair")
      options.repair = true;
    else if(arg == "--progress")
      options.progress = true;
    else
      dggvtp::parse_mesh_argument(arg, options.mesh);
  }
  words.finish();
  if(options.mesh.empty())
    throw Usage_error("no MESH given");
  options.check();
  if(options.has_pairs())
  {
    if(!options.sources.empty() || !options.targets.empty() || !options.path_targets.empty())
      throw Usage_error("--pairs gives each query its source and target: not with --source, --target or --path-to "
                        "(or their -point forms); put those pairs in the --pairs file, or run them without --pairs");
    if(options.fps > 0 || options.first_sample)
      throw Usage_error("--pairs and --fps are separate runs");
    if(!(options.output.empty() && options.labels.empty() && options.error_bounds.empty() &&
         options.isolines_output.empty()))
      throw Usage_error("--pairs stops each propagation once its target is final: --output, --labels, "
                        "--error-bounds and isolines need another run (with --source)");
  }
  if(options.first_sample && options.fps == 0)
    throw Usage_error("--first-sample is the first sample of --fps: give --fps K");
  if(options.fps > 0 && (options.sources.size() > 1 || options.has_points() || options.stops_early() ||
                         std::isfinite(options.max_distance)))
    throw Usage_error("--fps samples from one vertex (--first-sample N) over the whole field: not with several sources, "
                      "--source-point, --target, --path-to or --max-distance");
  if(options.fps > 0 && !options.sources.empty())
  {
    if(options.first_sample)
      throw Usage_error("--first-sample and --source both give the first sample of --fps: give --first-sample alone");
    options.source_as_first_sample = true; // the former spelling: a warning once the options are read
  }
  if(options.first_sample)
  {
    Place first;
    first.vertex = *options.first_sample;
    options.sources.assign(1, first);
  }
  if(options.fps > 0 && (options.output == "-" || options.labels == "-" || options.error_bounds == "-" ||
                         options.isolines_output == "-"))
    throw Usage_error("--fps prints the samples on standard output: give the other outputs a file");
  if(options.sources.empty() && !options.has_pairs())
    options.sources.push_back(Place());
  if(options.stops_early() && !(options.output.empty() && options.labels.empty() && options.error_bounds.empty()))
    throw Usage_error("--target and --path-to stop the propagation before every vertex is final: "
                      "--output, --labels and --error-bounds need another run");
  if((options.isolines > 0 || !options.isolines_at.empty()) == options.isolines_output.empty())
    throw Usage_error("--isolines-output goes with --isolines or --isolines-at");
  if(options.isolines > 0 && !options.isolines_at.empty())
    throw Usage_error("--isolines and --isolines-at do not combine");
  if(options.stops_early() && !options.isolines_output.empty())
    throw Usage_error("--target and --path-to stop the propagation before every vertex is final: "
                      "isolines need another run");
  if(!options.paths.empty() && options.path_targets.empty() && !options.has_pairs())
    throw Usage_error("--paths needs --path-to, --path-to-point or --pairs");
  if(int(options.output == "-") + int(options.labels == "-") + int(options.paths == "-") + int(options.isolines_output == "-") +
       int(options.error_bounds == "-") + int(options.stops_early()) > 1)
    throw Usage_error("only one output may go to standard output (the targets', paths' and pairs' lines are one)");
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
  double seconds_make_mesh = 0.; // the input policy's repairs (soup to mesh), if the soup needs them
  double seconds_prepare = 0., seconds_locate = 0., seconds_propagate = 0.;
  std::size_t threads = 1;        // that prepared the solver and propagated
  CGAL::DGG_VTP_3::Propagation_statistics statistics;
  std::vector<double> distances;        // per file vertex, unless the propagation stopped early
  std::vector<double> error_bounds;     // per file vertex, with --error-bounds: distance - lower bound
  std::vector<long long> labels;        // per file vertex, with --labels: its nearest source's option, or -1
  std::vector<double> target_distances; // per --target
  std::vector<double> path_lengths;     // per --path-to
  std::vector<Polyline> paths;          // per --path-to: from the target to the source; empty if unreached;
                                        // with --pairs, per pair, from the source to the target
  std::vector<double> pair_distances;   // per pair of --pairs
  std::vector<double> pair_lengths;     // per pair, with --paths: the length of its path
  std::vector<std::size_t> samples;     // with --fps: the file vertices chosen, in order
  std::vector<std::string> warnings;    // for standard error, unless --quiet
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// "%.17g\n" as printf writes it (and "inf\n"), with std::to_chars: printf per line took most of
// the writing time. At most 25 characters ("-1.2345678901234567e-308\n").
char* put_distance_line(double d, char* out)
{
  out = std::to_chars(out, out + 24, d, std::chars_format::general, 17).ptr;
  *out++ = '\n';
  return out;
}

// a number as the distances are written (%.17g, inf)
std::string number_text(double d)
{
  char line[32];
  return std::string(line, put_distance_line(d, line) - 1);
}

// The query of the options, on the places' range type. The solver keeps what it needs, so the
// soup is gone before the propagation: the peak memory is the larger of input + solver and
// solver + propagation, not their sum (paths keep the soup's points and triangles, to draw them).
template <class Element, class Tag, class Solver>
void run_query(dggvtp::Loaded_soup& soup, const Solver& solver, const Options& options, Run& run)
{
  using FT = typename Solver::FT;
  namespace DP = CGAL::DGG_VTP_3::parameters;
  const Clock::time_point t0 = Clock::now();
  // the locator (its mesh and AABB tree) is gone before the propagation
  const auto q = [&] {
    std::optional<dggvtp::Point_locator> locator;
    if(options.has_points())
      locator.emplace(soup.points, soup.triangles);
    return dggvtp::query_places<Solver, Element>(soup, locator ? &*locator : nullptr, options.sources,
                                                 options.targets, options.path_targets);
  }();
  run.seconds_locate = seconds_since(t0);
  for(const auto& m : q.moved_points)
    run.warnings.push_back(std::string(m.range == dggvtp::Place_range::source   ? "--source-point"
                                       : m.range == dggvtp::Place_range::target ? "--target-point"
                                                                                : "--path-to-point") +
                           " " + number_text(m.point[0]) + " " + number_text(m.point[1]) + " " +
                           number_text(m.point[2]) + " is " + number_text(m.distance) +
                           " away from the surface: taken at the nearest point of the surface");
  if(q.sources.empty()) // the library refuses a query without sources, rightly: nothing to propagate
    throw dggvtp::Input_error("every source is a vertex that no face uses: no point of the surface can be reached");
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
  if(!options.path_targets.empty())
  {
    points.swap(soup.points);
    triangles.swap(soup.triangles);
  }
  // the soup's memory goes back before the propagation, but where the isolines are drawn on its
  // triangles afterwards (they need a full run: never with paths)
  if(options.isolines_output.empty())
    dggvtp::release_soup(soup);

  std::vector<FT> d(solver.number_of_vertices());
  std::vector<FT> lower(options.error_bounds.empty() ? 0 : d.size());
  std::vector<std::size_t> nearest(options.labels.empty() && options.fps == 0 ? 0 : d.size());
  std::vector<FT> at_targets;
  using Tree = decltype(solver.compute_shortest_path_tree(q.sources));
  std::optional<Tree> tree;
  std::optional<dggvtp::Progress_line> line;
  std::function<bool(double)> progress; // empty: no callback
  if(!options.quiet && (options.progress || ::isatty(2)))
    progress = std::ref(line.emplace(options.progress));
  const auto np = DP::max_distance(options.max_distance).accuracy(options.epsilon).callback(progress);
  const Clock::time_point t1 = Clock::now();
  if(!options.path_targets.empty())
  {
    tree.emplace(solver.template compute_shortest_path_tree<Tag>(q.sources, DP::targets(q.targets, np)));
    run.statistics = tree->statistics();
    for(std::size_t v = 0; v < d.size(); ++v)
      d[v] = tree->distance(v);
    for(std::size_t k = 0; k < q.targets.size(); ++k)
      at_targets.push_back(tree->target_distance(k));
  }
  else if(options.fps > 0)
  {
    if constexpr(std::is_same<Element, std::size_t>::value) // no points with --fps
    {
      const auto sample = [&](const auto& np) {
        solver.template farthest_point_sampling<Tag>(options.fps, std::back_inserter(run.samples),
                                                     DP::first_sample(q.sources[0], DP::distance_map(CGAL::make_property_map(d), np)));
      };
      const auto np_fps = CGAL::parameters::accuracy(options.epsilon).callback(progress);
      if(lower.empty())
        sample(DP::nearest_source_map(CGAL::make_property_map(nearest), np_fps));
      else
        sample(DP::nearest_source_map(CGAL::make_property_map(nearest),
                                      DP::lower_bound_map(CGAL::make_property_map(lower), np_fps)));
      for(std::size_t& v : run.samples)
        v = soup.file_vertex_of[v];
    }
  }
  else if(!options.targets.empty())
    run.statistics = solver.template compute_distances_to_nearest_source<Tag>(
      q.sources, CGAL::make_property_map(d), DP::target_distances(std::back_inserter(at_targets), DP::targets(q.targets, np)));
  else
  {
    const auto field = [&](const auto& np) {
      if(lower.empty())
        return solver.template compute_distances_to_nearest_source<Tag>(q.sources, CGAL::make_property_map(d), np);
      return solver.template compute_distances_to_nearest_source<Tag>(
        q.sources, CGAL::make_property_map(d), DP::lower_bound_map(CGAL::make_property_map(lower), np));
    };
    run.statistics = options.labels.empty() ? field(np) : field(DP::nearest_source_map(CGAL::make_property_map(nearest), np));
  }
  run.seconds_propagate = seconds_since(t1);
  if(line)
  {
    line->finish();
    line.reset(); // its last line ends before anything else is printed
  }

  // per solver vertex: the number of the source option, or of the sample (not a source option)
  const std::vector<long long> label =
    options.fps > 0 ? dggvtp::sample_labels(nearest) : dggvtp::finish_sources(q, nearest, d.data());

  const auto target_distance = [&](const auto& t) {
    return double(t.vertices.empty() ? at_targets[t.point] : d[dggvtp::nearest_copy(t.vertices, d)]);
  };
  for(const auto& t : q.target_places)
    run.target_distances.push_back(target_distance(t));
  if(tree)
    for(auto& [line, length] : dggvtp::trace_paths(*tree, q, d, points, triangles))
    {
      run.path_lengths.push_back(length);
      run.paths.push_back(std::move(line));
    }

  if(!options.stops_early())
  {
    run.distances = dggvtp::file_vertex_distances(soup, d);
    if(!lower.empty())
      run.error_bounds = dggvtp::certified_errors(run.distances, dggvtp::file_vertex_distances(soup, lower));
    if(!label.empty())
      run.labels = dggvtp::file_vertex_labels(soup, d, label);
  }
}

// "--pairs 'FILE' line N", for messages about a pair
std::string pair_line_text(const Options& options, std::size_t k)
{
  return "--pairs '" + options.pairs_file + "' line " + std::to_string(options.pair_lines[k]);
}

// --pairs: per pair, the distance from its source to its target (and, with --paths, the path),
// each pair a propagation of its own that stops once its target is final, the pairs in parallel
// under `Tag` (the library's compute_pair_distances(): the same bits on any number of threads)
template <class Tag, class Solver>
void run_pairs(dggvtp::Loaded_soup& soup, const Solver& solver, const Options& options, Run& run)
{
  using FT = typename Solver::FT;
  using Path_point = typename CGAL::DGG_VTP_3::Shortest_path_tree<Solver>::Path_point;
  namespace DP = CGAL::DGG_VTP_3::parameters;
  // per file vertex: its solver vertex, and how many copies the input policy made of it
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> solver_vertex(soup.file_vertices, none), copies(soup.file_vertices, 0);
  for(std::size_t v = 0; v < soup.file_vertex_of.size(); ++v)
    if(copies[soup.file_vertex_of[v]]++ == 0)
      solver_vertex[soup.file_vertex_of[v]] = v;
  // a pair is one source and one target: a vertex split into copies (several sheets at one point)
  // is several sources, which --source takes and a pair does not
  const auto at = [&](std::size_t v, std::size_t k) {
    if(copies[v] == 1)
      return solver_vertex[v];
    if(copies[v] == 0)
      throw dggvtp::Input_error(pair_line_text(options, k) + ": vertex " + std::to_string(v) + " is in no face");
    throw dggvtp::Input_error(pair_line_text(options, k) + ": vertex " + std::to_string(v) + " was split into " +
                              std::to_string(copies[v]) + " copies by the input policy (non-manifold edges or "
                              "orientation): a pair takes one vertex; use --source " + std::to_string(v) +
                              " or --target " + std::to_string(v) + " for it");
  };
  std::vector<bool> in_a_face(soup.file_vertex_of.size(), false);
  for(const Triangle& t : soup.triangles)
    for(std::uint32_t v : t)
      in_a_face[v] = true;

  // paths are drawn on the soup's points and triangles; the rest of the soup goes before the propagation
  const bool with_paths = !options.paths.empty();
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
  if(with_paths)
  {
    points.swap(soup.points);
    triangles.swap(soup.triangles);
  }
  dggvtp::release_soup(soup);

  const std::size_t n = options.pair_places.size();
  run.pair_distances.assign(n, std::numeric_limits<double>::infinity());
  if(with_paths)
  {
    run.paths.assign(n, Polyline());
    run.pair_lengths.assign(n, std::numeric_limits<double>::infinity());
  }
  // The pairs for the library, and their numbers among all. A pair at a vertex no face uses is
  // answered here, as --source and --target answer it: 0 from the vertex to itself (its path that
  // one point), unreached otherwise; the library's path would start on a face of the vertex.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::size_t> asked;
  pairs.reserve(n);
  asked.reserve(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t s = at(options.pair_places[k].first, k), t = at(options.pair_places[k].second, k);
    if(in_a_face[s] && in_a_face[t])
    {
      pairs.emplace_back(s, t);
      asked.push_back(k);
    }
    else if(s == t)
    {
      run.pair_distances[k] = 0.;
      if(with_paths)
      {
        run.paths[k].push_back({double(points[s][0]), double(points[s][1]), double(points[s][2])});
        run.pair_lengths[k] = 0.;
      }
    }
  }
  // each pair writes its own entries: no two threads write the same
  const auto np = DP::max_distance(options.max_distance).accuracy(options.epsilon);
  const Clock::time_point t1 = Clock::now();
  try
  {
    if(with_paths)
      solver.template compute_pair_distances<Tag>(
        pairs,
        [&](std::size_t i, FT d, FT, const std::vector<Path_point>& path) {
          const std::size_t k = asked[i];
          run.pair_distances[k] = double(d);
          if(std::isinf(run.pair_distances[k])) // unreached, or beyond --max-distance: no points
            return;
          auto [line, length] = dggvtp::polyline_of(path, points, triangles);
          run.paths[k] = std::move(line);
          run.pair_lengths[k] = length;
        },
        np);
    else
      solver.template compute_pair_distances<Tag>(
        pairs, [&](std::size_t i, FT d, FT) { run.pair_distances[asked[i]] = double(d); }, np);
  }
  catch(const std::invalid_argument& e) // "pair K: ...": the pair's line
  {
    std::size_t i = 0;
    const std::string what = e.what();
    const auto [end, error] = std::from_chars(what.data() + (std::min)(std::size_t(5), what.size()), what.data() + what.size(), i);
    if(what.compare(0, 5, "pair ") == 0 && error == std::errc() && i < asked.size() && *end == ':')
      throw std::invalid_argument(pair_line_text(options, asked[i]) + std::string(end));
    throw;
  }
  run.seconds_propagate = seconds_since(t1);
}

// The solver is built from the soup; vertices are sources and targets as vertices unless a point
// is given. The preparation and the propagation run as `Tag` says (with_threads()); the solver and
// the distances are the same bit for bit on any number of threads (and without TBB).
template <class Kernel, class Tag>
Run compute(dggvtp::Loaded_soup& soup, const Options& options, Tag tag)
{
  using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;
  Run run;
  run.threads = dggvtp::threads_of(tag);
  std::optional<Solver> solver;
  const Clock::time_point t0 = Clock::now();
  run.seconds_make_mesh = dggvtp::make_solver<Tag>(soup, solver);
  run.seconds_prepare = seconds_since(t0) - run.seconds_make_mesh;
  run.faces = soup.triangles.size();
  if(options.has_pairs())
    run_pairs<Tag>(soup, *solver, options, run);
  else if(options.has_points())
    run_query<typename Solver::Face_location, Tag>(soup, *solver, options, run);
  else
    run_query<std::size_t, Tag>(soup, *solver, options, run);
  return run;
}


char* put_label_line(long long label, char* out)
{
  out = std::to_chars(out, out + 20, label).ptr;
  *out++ = '\n';
  return out;
}

// 8 bytes, little-endian whatever the machine's order
template <class T>
char* put_little_endian(T value, char* out)
{
  static_assert(sizeof(T) == 8, "8-byte values");
  std::uint64_t bits;
  std::memcpy(&bits, &value, 8);
  for(int i = 0; i < 8; ++i)
    *out++ = char((bits >> (8 * i)) & 0xff);
  return out;
}


// Writes `header`, then each value formatted by `put` (at most 32 bytes), through an Output_file
// in blocks of 1 MB.
template <class T, class Put>
void write_values(const std::string& path, const std::string& header, const std::vector<T>& values, Put put)
{
  Output_file file(path);
  std::vector<char> block(1 << 20);
  const std::size_t longest = 32;
  std::size_t used = 0;
  const auto flush = [&] {
    if(std::fwrite(block.data(), 1, used, file.get()) != used)
      throw dggvtp::Input_error("cannot write '" + path + "'");
    used = 0;
  };
  if(std::fwrite(header.data(), 1, header.size(), file.get()) != header.size())
    throw dggvtp::Input_error("cannot write '" + path + "'");
  for(const T& value : values)
  {
    if(block.size() - used < longest)
      flush();
    used = std::size_t(put(value, block.data() + used) - block.data());
  }
  flush();
  file.commit();
}

void write_distances(const std::vector<double>& distances, const std::string& path, const std::string& format)
{
  if(format == "npy")
    write_values(path, dggvtp::npy_header("<f8", "(" + std::to_string(distances.size()) + ",)"), distances, put_little_endian<double>);
  else
    write_values(path, std::string(), distances, put_distance_line);
}

void write_labels(const std::vector<long long>& labels, const std::string& path, const std::string& format)
{
  if(format == "npy")
    write_values(path, dggvtp::npy_header("<i8", "(" + std::to_string(labels.size()) + ",)"), labels, put_little_endian<long long>);
  else
    write_values(path, std::string(), labels, put_label_line);
}

bool is_mesh_format(const std::string& path, const Options& options)
{
  const std::string format = dggvtp::output_format_of(path, options.output_format);
  return !path.empty() && (format == "ply" || format == "vtk");
}

// --output and --error-bounds in the format their option or extension gives; PLY and VTK files
// on `mesh`, the file's mesh as loaded
void write_fields(const Run& run, const Options& options, const std::optional<dggvtp::File_mesh>& mesh)
{
  for(const auto& [path, values, field] : {std::make_tuple(&options.output, &run.distances, "distance"),
                                           std::make_tuple(&options.error_bounds, &run.error_bounds, "error_bound")})
  {
    if(path->empty())
      continue;
    const std::string format = dggvtp::output_format_of(*path, options.output_format);
    if(!is_mesh_format(*path, options))
    {
      write_distances(*values, *path, format);
      continue;
    }
    Output_file file(*path);
    (format == "ply" ? dggvtp::write_ply_field : dggvtp::write_vtk_field)(
      file.get(), options.mesh, *mesh, *values, options.labels.empty() ? nullptr : &run.labels, field);
    file.commit();
  }
}

std::string place_text(const Place& p)
{
  if(!p.is_point)
    return "vertex " + std::to_string(p.vertex);
  return "point (" + number_text(p.point[0]) + " " + number_text(p.point[1]) + " " + number_text(p.point[2]) + ")";
}

// per path: a comment with its number, target and length, its points as v lines, and an l line
// through them (a path of one point, at a source, has none: an l line needs two)
void write_paths(const Run& run, const Options& options)
{
  Output_file file(options.paths);
  if(options.has_pairs())
    std::fprintf(file.get(), "# dggvtp: shortest paths on %s, from the source to the target of each pair of %s\n",
                 options.mesh.c_str(), options.pairs_file.c_str());
  else
    std::fprintf(file.get(), "# dggvtp: shortest paths on %s, from each target back to its nearest source\n",
                 options.mesh.c_str());
  std::size_t written = 0;
  for(std::size_t k = 0; k < run.paths.size(); ++k)
  {
    if(options.has_pairs())
      std::fprintf(file.get(), "# path %zu: vertex %zu to vertex %zu (line %zu), distance %s, length %s%s\n", k,
                   options.pairs[k].first, options.pairs[k].second, options.pair_lines[k],
                   number_text(run.pair_distances[k]).c_str(), number_text(run.pair_lengths[k]).c_str(),
                   run.paths[k].empty() ? " (unreached)" : "");
    else
      std::fprintf(file.get(), "# path %zu: %s, length %s%s\n", k, place_text(options.path_targets[k]).c_str(),
                   number_text(run.path_lengths[k]).c_str(), run.paths[k].empty() ? " (unreached)" : "");
    for(const auto& x : run.paths[k])
    {
      char line[96];
      char* end = line;
      *end++ = 'v';
      for(double c : x)
      {
        *end++ = ' ';
        end = std::to_chars(end, line + sizeof line, c, std::chars_format::general, 17).ptr;
      }
      *end++ = '\n';
      std::fwrite(line, 1, std::size_t(end - line), file.get());
    }
    if(run.paths[k].size() >= 2)
    {
      std::fputc('l', file.get());
      for(std::size_t i = 1; i <= run.paths[k].size(); ++i)
        std::fprintf(file.get(), " %zu", written + i);
      std::fputc('\n', file.get());
    }
    written += run.paths[k].size();
  }
  file.commit();
}

// --error-bounds in --stats: the bounds over epsilon x distance, at the vertices reached (not at
// the sources, where both are 0), and the share of those certified exact (a bound of 0)
struct Bound_summary
{
  bool given = false;
  double largest = 0., mean = 0., certified_exact = 1.;
  std::string json() const
  {
    if(!given)
      return "null";
    char text[160];
    std::snprintf(text, sizeof text, "{\"max_over_epsilon_distance\": %.6g, \"mean_over_epsilon_distance\": %.6g, "
                                     "\"certified_exact\": %.6g}", largest, mean, certified_exact);
    return text;
  }
};

Bound_summary summarize_bounds(const Run& run, double epsilon)
{
  Bound_summary b;
  b.given = !run.error_bounds.empty();
  std::size_t reached = 0, exact = 0;
  double sum = 0.;
  for(std::size_t v = 0; v < run.error_bounds.size(); ++v)
    if(std::isfinite(run.distances[v]) && run.distances[v] > 0.)
    {
      ++reached;
      exact += run.error_bounds[v] == 0.;
      const double r = epsilon > 0. ? run.error_bounds[v] / (epsilon * run.distances[v]) : 0.;
      b.largest = (std::max)(b.largest, r);
      sum += r;
    }
  if(reached > 0)
  {
    b.mean = sum / double(reached);
    b.certified_exact = double(exact) / double(reached);
  }
  return b;
}

// What no path on the surface reaches from the sources: vertices, or targets and paths ("" when
// all are reached). Beyond --max-distance they are unreached by request: no warning then.
std::string unreachable_warning(const Run& run, const Options& options, std::size_t file_vertices)
{
  if(std::isfinite(options.max_distance))
    return std::string();
  if(options.has_pairs())
    return dggvtp::unreachable_warning(dggvtp::count_infinite(run.pair_distances), run.pair_distances.size(),
                                       "pairs' targets");
  if(options.stops_early())
    return dggvtp::unreachable_warning(dggvtp::count_infinite(run.target_distances) + dggvtp::count_infinite(run.path_lengths),
                                       run.target_distances.size() + run.path_lengths.size(), "targets and paths");
  return dggvtp::unreachable_warning(dggvtp::count_infinite(run.distances), file_vertices, "vertices");
}

// A line of a --pairs file as a message shows it: at most 40 characters, '?' for what does not print
std::string shown_line(const std::string& line)
{
  std::string out;
  for(char c : line.substr(0, 40))
    out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return line.size() > 40 ? out + "..." : out;
}

// Reads the pairs of --pairs into `options` (pairs, pair_lines): per line two vertex indices,
// digits only, separated by whitespace; lines that start with '#' (after any whitespace) and blank
// lines skipped. An unreadable file or a line that is not two indices is an Input_error naming
// the file and the line.
void read_pairs(Options& options)
{
  const std::string& path = options.pairs_file;
  const std::string name = "--pairs '" + path + "'";
  struct stat info;
  if(::stat(path.c_str(), &info) != 0)
    throw dggvtp::Input_error("cannot read " + name + ": " + std::strerror(errno));
  if(S_ISDIR(info.st_mode))
    throw dggvtp::Input_error("cannot read " + name + ": it is a directory");
  FILE* file = std::fopen(path.c_str(), "rb");
  if(!file)
    throw dggvtp::Input_error("cannot read " + name + ": " + std::strerror(errno));
  std::string text;
  char block[1 << 16];
  for(std::size_t n; (n = std::fread(block, 1, sizeof block, file)) > 0;)
    text.append(block, n);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if(failed)
    throw dggvtp::Input_error("cannot read " + name);
  std::size_t number = 0;
  for(std::size_t start = 0; start < text.size();)
  {
    const std::size_t end = (std::min)(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    std::vector<std::string> words;
    for(std::size_t i = 0; i < line.size();)
    {
      if(std::isspace(static_cast<unsigned char>(line[i])))
      {
        ++i;
        continue;
      }
      std::size_t j = i;
      while(j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])))
        ++j;
      words.push_back(line.substr(i, j - i));
      i = j;
    }
    if(words.empty() || words[0][0] == '#')
      continue;
    const std::string where = name + " line " + std::to_string(number) + ": ";
    if(words.size() != 2)
      throw dggvtp::Input_error(where + "expected two vertex indices (source target), got '" + shown_line(line) + "'");
    std::size_t v[2];
    for(int i = 0; i < 2; ++i)
    {
      const std::string& w = words[std::size_t(i)];
      const auto [end_of_number, error] = std::from_chars(w.data(), w.data() + w.size(), v[i]);
      if(!std::isdigit(static_cast<unsigned char>(w[0])) || error != std::errc() || end_of_number != w.data() + w.size())
        throw dggvtp::Input_error(where + "'" + shown_line(w) + "' is not a vertex index (a non-negative integer)");
    }
    options.pairs.emplace_back(v[0], v[1]);
    options.pair_lines.push_back(number);
  }
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
  if(options.source_as_first_sample && !options.quiet)
    std::cerr << "warning: --source N with --fps is deprecated: write --first-sample N (the same sample)\n";

  // a mistake in an output's name costs a moment, not the whole computation
  for(const auto& [option, path] : {std::make_pair("--output", &options.output), std::make_pair("--labels", &options.labels),
                                    std::make_pair("--error-bounds", &options.error_bounds),
                                    std::make_pair("--paths", &options.paths), std::make_pair("--stats", &options.stats)})
    if(!path->empty())
      dggvtp::check_writable(std::string(option) + " '" + *path + "'", *path);
  if(options.has_pairs())
    read_pairs(options);

  const Clock::time_point t0 = Clock::now();
  const dggvtp::Repair_option repair = options.repair_option();
  dggvtp::Loaded_soup soup = dggvtp::load_soup(options.mesh, repair);
  // PLY and VTK fields are written on the faces as read, which the repairs and the solver change
  std::optional<dggvtp::File_mesh> file_mesh;
  if(is_mesh_format(options.output, options) || is_mesh_format(options.error_bounds, options))
    file_mesh = dggvtp::file_mesh_of(soup);
  for(const auto& [places, what] : {std::make_pair(&options.sources, "source"), std::make_pair(&options.targets, "target"),
                                    std::make_pair(&options.path_targets, "path target")})
    for(const Place& p : *places)
      if(!p.is_point && p.vertex >= soup.file_vertices)
        throw dggvtp::Input_error(std::string(what) + " " + std::to_string(p.vertex) + " is out of range (the mesh has " +
                                  std::to_string(soup.file_vertices) + " vertices)");
  for(std::size_t k = 0; k < options.pairs.size(); ++k)
    for(std::size_t v : {options.pairs[k].first, options.pairs[k].second})
      if(v >= soup.file_vertices)
        throw dggvtp::Input_error(pair_line_text(options, k) + ": vertex " + std::to_string(v) +
                                  " is out of range (the mesh has " + std::to_string(soup.file_vertices) + " vertices)");
  options.pair_places = options.pairs;
  const double seconds_read = seconds_since(t0);
  const Clock::time_point t_repair = Clock::now();
  dggvtp::Repair_record repaired;
  if(options.repair)
  {
    repaired = dggvtp::repair_soup(soup, repair);
    for(auto [places, what] : {std::make_pair(&options.sources, "source"), std::make_pair(&options.targets, "target"),
                               std::make_pair(&options.path_targets, "path target")})
      for(Place& p : *places)
        if(!p.is_point)
          p.vertex = repaired.file_vertex(p.vertex, what);
    for(std::size_t k = 0; k < options.pair_places.size(); ++k)
    {
      const std::string what = pair_line_text(options, k) + ": vertex";
      options.pair_places[k] = {repaired.file_vertex(options.pair_places[k].first, what),
                                repaired.file_vertex(options.pair_places[k].second, what)};
    }
  }
  const double seconds_repair_soup = seconds_since(t_repair);

  Run run;
  try
  {
    dggvtp::with_threads(options.threads, [&](auto tag) {
      run = options.precision == "float" ? compute<CGAL::Simple_cartesian<float>>(soup, options, tag)
                                         : compute<CGAL::Exact_predicates_inexact_constructions_kernel>(soup, options, tag);
    });
  }
  catch(const std::invalid_argument& e) // the library's documented preconditions
  {
    throw dggvtp::Input_error(dggvtp::with_repair_hint(e.what(), repair));
  }
  repaired.apply(run.distances.empty() ? nullptr : run.distances.data(), run.labels.empty() ? nullptr : run.labels.data());
  repaired.apply(run.error_bounds.empty() ? nullptr : run.error_bounds.data(), nullptr);
  const double seconds_repair = seconds_repair_soup + run.seconds_make_mesh;
  if(!options.quiet)
    for(const std::string& line : soup.repairs)
      std::cerr << "warning: " << options.mesh << ": " << line << "\n";
  if(!options.quiet)
    for(const std::string& warning : run.warnings)
      std::cerr << "warning: " << warning << "\n";
  // even with --quiet: a scan in pieces or a stray vertex is worth knowing before using the numbers
  const std::string unreachable = unreachable_warning(run, options, soup.file_vertices);
  if(!unreachable.empty())
    std::cerr << "warning: " << unreachable << "\n";
#ifndef CGAL_LINKED_WITH_TBB
  if(!options.quiet && options.threads > 1) // 0, all cores, is one core without TBB: nothing to say
    std::cerr << "warning: dggvtp was built without TBB: the propagation ran on one thread\n";
#endif

  const Clock::time_point t_write = Clock::now();
  write_fields(run, options, file_mesh);
  if(!options.labels.empty())
    write_labels(run.labels, options.labels,
                 dggvtp::output_format_of(options.labels, options.output_format) == "npy" ? "npy" : "text");
  if(!options.paths.empty())
    write_paths(run, options);
  if(!options.isolines_output.empty())
  {
    Output_file file(options.isolines_output);
    // the soup's faces go to the isolines' mesh; only its sizes are read after this
    dggvtp::write_isolines_obj(file.get(), options.mesh, std::move(soup), run.distances,
                               options.isolines > 0 ? dggvtp::evenly_spaced_values(run.distances, options.isolines)
                                                    : options.isolines_at);
    file.commit();
  }
  std::string lines; // the samples, or the targets' distances, then the paths' lengths
  for(std::size_t v : run.samples)
    lines += std::to_string(v) + "\n";
  for(const auto* values : {&run.target_distances, &run.path_lengths, &run.pair_distances})
    for(double d : *values)
      lines += number_text(d) + "\n";
  if(!lines.empty())
  {
    std::fwrite(lines.data(), 1, lines.size(), stdout);
    if(std::fflush(stdout) != 0)
      throw dggvtp::Input_error("cannot write to standard output");
  }
  const double seconds_write = seconds_since(t_write);

  // of what is reported: the vertices, or the targets and paths
  double farthest = 0.;
  for(const auto* values : {&run.distances, &run.target_distances, &run.path_lengths, &run.pair_distances})
    for(double d : *values)
      if(std::isfinite(d))
        farthest = (std::max)(farthest, d);
  const double rss = peak_rss_mb();
  const auto& s = run.statistics;
  const Bound_summary bounds = summarize_bounds(run, options.epsilon);
  if(!options.stats.empty())
  {
    Output_file file(options.stats);
    const Place* first = options.sources.empty() ? nullptr : &options.sources.front(); // none with --pairs
    std::fprintf(file.get(),
                 "{\"mesh\": %s, \"vertices\": %zu, \"faces\": %zu, \"source\": %s, \"sources\": %zu, "
                 "\"targets\": %zu, \"paths\": %zu, \"pairs\": %zu, \"distance_limit\": %s, \"epsilon\": %.17g, "
                 "\"precision\": \"%s\", \"threads\": %ld, \"seconds_load\": %.6f, \"seconds_repair\": %.6f, "
                 "\"seconds_prepare\": %.6f, \"seconds_locate\": %.6f, \"seconds_propagate\": %.6f, \"seconds_write\": %.6f, "
                 "\"threads_per_stage\": {\"load\": 1, \"repair\": 1, \"prepare\": %zu, \"locate\": 1, "
                 "\"propagate\": %zu, \"write\": 1}, "
                 "\"windows_created\": %zu, \"windows_peak\": %zu, "
                 "\"pseudo_sources\": %zu, \"vertices_popped\": %zu, \"vertices_reached\": %zu, "
                 "\"max_distance\": %.17g, \"peak_rss_mb\": %.1f, \"error_bounds\": %s}\n",
                 json_string(options.mesh).c_str(), soup.file_vertices, run.faces,
                 !first || first->is_point ? "null" : std::to_string(first->vertex).c_str(), options.sources.size(),
                 options.targets.size(), options.path_targets.size(), options.pairs.size(),
                 std::isfinite(options.max_distance) ? number_text(options.max_distance).c_str() : "null",
                 options.epsilon, options.precision.c_str(), options.threads, seconds_read, seconds_repair,
                 run.seconds_prepare, run.seconds_locate, run.seconds_propagate, seconds_write, run.threads, run.threads,
                 s.windows_created, s.windows_peak,
                 s.pseudo_sources, s.vertices_popped, s.vertices_reached, farthest, rss, bounds.json().c_str());
    file.commit();
  }
  if(!options.quiet)
  {
    const bool stdout_taken = options.output == "-" || options.labels == "-" || options.isolines_output == "-" ||
                              options.stops_early() || options.fps > 0;
    std::ostream& out = stdout_taken ? std::cerr : std::cout;
    std::string sources = options.sources.size() == 1 && !options.sources[0].is_point
                            ? "source " + std::to_string(options.sources[0].vertex) : "sources";
    if(sources == "sources")
      for(std::size_t k = 0; k < options.sources.size(); ++k)
        sources += (k == 0 ? " " : ", ") + place_text(options.sources[k]);
    if(options.fps > 0)
      sources = std::to_string(options.fps) + " samples from vertex " + std::to_string(options.sources[0].vertex);
    if(options.has_pairs())
      sources = std::to_string(options.pairs.size()) + " pairs of " + options.pairs_file;
    out << "dggvtp: " << options.mesh << ": " << soup.file_vertices << " vertices, " << run.faces << " faces\n"
        << "  " << sources << ", "
        << (options.epsilon > 0. ? "DGG-VTP epsilon " + std::to_string(options.epsilon) : std::string("exact (VTP)"))
        << ", " << options.precision << "\n"
        << "  load " << seconds_read << " s, "
        << (options.repair || run.seconds_make_mesh > 0. ? "repair " + std::to_string(seconds_repair) + " s, " : std::string())
        << "prepare " << run.seconds_prepare << " s, "
        << (options.has_points() ? "locate " + std::to_string(run.seconds_locate) + " s, " : std::string())
        << "propagate " << run.seconds_propagate << " s, write " << seconds_write << " s\n"
        << "  prepared and propagated on " << run.threads << (run.threads == 1 ? " thread\n" : " threads\n");
    if(!options.has_pairs()) // the pairs' propagations are not counted
      out << "  windows created " << s.windows_created << ", peak " << s.windows_peak << ", pseudo-sources "
          << s.pseudo_sources << "\n";
    if(options.has_pairs())
      out << "  each pair stopped once its target was final, "
          << run.pair_distances.size() - dggvtp::count_infinite(run.pair_distances) << " of " << run.pair_distances.size()
          << " targets reached, farthest at " << farthest << "\n";
    else if(options.stops_early())
      out << "  stopped once the targets were final, " << s.vertices_reached << " vertices reached, farthest target at "
          << farthest << "\n";
    else
    {
      std::size_t reached = 0;
      for(double d : run.distances)
        reached += std::isfinite(d) ? 1 : 0;
      out << "  reached " << reached << " of " << soup.file_vertices << " vertices, farthest at " << farthest << "\n";
    }
    if(!run.error_bounds.empty())
      out << "  certified exact: " << 100. * bounds.certified_exact << "% of the vertices reached"
          << (options.epsilon > 0. ? ", error bound at most " + std::to_string(bounds.largest) + " epsilon x distance, " +
                                       std::to_string(bounds.mean) + " on average"
                                   : std::string())
          << "\n";
    out << "  peak memory " << rss << " MB\n";
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
