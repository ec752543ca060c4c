// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// dggvtp's loader on one mesh in five formats, against CGAL's plain reader:
//
//   loader MESH [DIR]
//
// writes MESH (any format CGAL reads) into DIR (default: a new directory under $TMPDIR, removed at
// the end; given, it is kept) as binary PLY (float coordinates, as MESH's if they are float),
// ASCII PLY, OBJ and OFF (shortest round-trip text of each double) and binary STL, then measures
// each file in a process of its own, so that each peak RSS is that reader's:
//   load      dggvtp::load_soup (the fast readers, or CGAL's guarded path when they give up)
//   guarded   dggvtp::load_soup_with_cgal (the path every file took before the fast readers)
//   CGAL      CGAL::IO::read_polygon_mesh into a Surface_mesh, nothing else
//   prepare   dggvtp::make_solver on what `load` gave (repairs if any, unfolding, checks)
// and prints a Markdown table (peak RSS: of `load` alone, then of load + prepare, of `guarded`, of
// `CGAL`). Run it alone: the times are wall-clock.

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// user + system CPU seconds of this process so far: on a shared machine, less noisy than wall-clock
double cpu_seconds()
{
  struct rusage usage;
  ::getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// the shortest text that reads back as the same double
std::string text(double x)
{
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
}

// --- the five files ---------------------------------------------------------------------------

void write_files(const std::string& mesh, const std::filesystem::path& dir, const std::vector<std::string>& names)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  if(!CGAL::IO::read_polygon_soup(mesh, points, faces))
  {
    std::cerr << "error: cannot read " << mesh << "\n";
    std::exit(1);
  }
  bool float_coordinates = true;
  for(const Point& p : points)
    for(int c = 0; c < 3; ++c)
      float_coordinates = float_coordinates && double(float(p[c])) == p[c];
  for(const std::string& name : names)
  {
    const std::filesystem::path path = dir / name;
    std::ofstream out(path, std::ios::binary);
    const auto put = [&out](const auto& value) { out.write(reinterpret_cast<const char*>(&value), sizeof value); };
    if(name == "binary.ply")
    {
      const char* type = float_coordinates ? "float" : "double";
      out << "ply\nformat binary_little_endian 1.0\nelement vertex " << points.size() << "\nproperty " << type
          << " x\nproperty " << type << " y\nproperty " << type << " z\nelement face " << faces.size()
          << "\nproperty list uchar int vertex_indices\nend_header\n";
      for(const Point& p : points)
        for(int c = 0; c < 3; ++c)
          float_coordinates ? put(float(p[c])) : put(p[c]);
      for(const auto& f : faces)
      {
        put(static_cast<unsigned char>(f.size()));
        for(std::size_t v : f)
          put(static_cast<std::int32_t>(v));
      }
    }
    else if(name == "binary.stl")
    {
      char header[80] = "binary STL of the loader benchmark";
      out.write(header, 80);
      put(static_cast<std::uint32_t>(faces.size()));
      for(const auto& f : faces) // triangles only (STL has nothing else)
      {
        const float normal[3] = {0.f, 0.f, 0.f};
        put(normal);
        for(int k = 0; k < 3; ++k)
          for(int c = 0; c < 3; ++c)
            put(float(points[f[k]][c]));
        put(std::uint16_t(0));
      }
    }
    else
    {
      std::string body;
      const bool ply = name == "ascii.ply", obj = name == "mesh.obj";
      if(ply)
        body = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(points.size()) +
               "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
               std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
      else if(!obj)
        body = "OFF\n" + std::to_string(points.size()) + " " + std::to_string(faces.size()) + " 0\n";
      for(const Point& p : points)
        body += (obj ? "v " : "") + text(p.x()) + " " + text(p.y()) + " " + text(p.z()) + "\n";
      for(const auto& f : faces)
      {
        body += obj ? "f" : std::to_string(f.size());
        for(std::size_t v : f)
          body += " " + std::to_string(obj ? v + 1 : v);
        body += "\n";
      }
      out << body;
    }
    if(!out)
    {
      std::cerr << "error: cannot write " << path << "\n";
      std::exit(1);
    }
  }
}

// --- one measurement, in a child process --------------------------------------------------------

// prints the seconds of the phases it runs, on one line
int measure(const std::string& what, const std::string& path)
{
  try
  {
    auto t0 = std::chrono::steady_clock::now();
    double cpu0 = cpu_seconds();
    if(what == "cgal")
    {
      CGAL::Surface_mesh<Point> mesh;
      const bool read = CGAL::IO::read_polygon_mesh(path, mesh);
      std::printf("%.4f %.4f %d\n", seconds_since(t0), cpu_seconds() - cpu0, read ? int(num_vertices(mesh)) : -1);
      return 0;
    }
    dggvtp::Loaded_soup soup = what == "guarded" ? dggvtp::load_soup_with_cgal(path) : dggvtp::load_soup(path);
    const double load = seconds_since(t0), load_cpu = cpu_seconds() - cpu0;
    if(what == "guarded")
    {
      std::printf("%.4f %.4f %zu\n", load, load_cpu, soup.file_vertices);
      return 0;
    }
    struct rusage usage;
    ::getrusage(RUSAGE_SELF, &usage);
    const double load_rss_mb = double(usage.ru_maxrss) / 1024.;
    t0 = std::chrono::steady_clock::now();
    cpu0 = cpu_seconds();
    std::optional<Solver> solver;
    const double repairs = dggvtp::make_solver(soup, solver);
    const double prepare = seconds_since(t0) - repairs, prepare_cpu = cpu_seconds() - cpu0;
    // repairs (none on a valid mesh) count as loading, as dggvtp counts them
    std::printf("%.4f %.4f %.4f %.4f %.1f\n", load + repairs, load_cpu, prepare, prepare_cpu, load_rss_mb);
  }
  catch(const std::exception& e)
  {
    std::printf("error %s\n", e.what());
  }
  return 0;
}

struct Result
{
  std::vector<double> values; // as the child printed them
  double peak_rss_mb = 0.;
};

Result run_child(const char* self, const std::string& what, const std::string& path)
{
  int fds[2];
  if(::pipe(fds) != 0)
    std::exit(1);
  const pid_t pid = ::fork();
  if(pid == 0)
  {
    ::dup2(fds[1], 1);
    ::close(fds[0]);
    ::execl(self, self, "--measure", what.c_str(), path.c_str(), static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  ::close(fds[1]);
  std::string output;
  char buffer[256];
  for(ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
    output.append(buffer, std::size_t(n));
  ::close(fds[0]);
  int status = 0;
  struct rusage usage;
  ::wait4(pid, &status, 0, &usage);
  Result r;
  r.peak_rss_mb = double(usage.ru_maxrss) / 1024.;
  char* p = output.data();
  for(char* end; (void)(end = nullptr), true; p = end)
  {
    const double v = std::strtod(p, &end);
    if(end == p)
      break;
    r.values.push_back(v);
  }
  if(r.values.empty())
    std::cerr << what << " " << path << ": " << output;
  return r;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc == 4 && std::string(argv[1]) == "--measure")
    return measure(argv[2], argv[3]);
  if(argc < 2 || argc > 3)
  {
    std::cerr << "usage: loader MESH [DIR]\n";
    return 1;
  }
  const bool keep = argc == 3;
  std::filesystem::path dir;
  if(keep)
    dir = argv[2];
  else
  {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/dggvtp_loader_XXXXXX";
    if(::mkdtemp(pattern.data()) == nullptr)
      return 1;
    dir = pattern;
  }
  std::filesystem::create_directories(dir);
  const std::vector<std::string> names = {"binary.ply", "ascii.ply", "mesh.obj", "mesh.off", "binary.stl"};
  write_files(argv[1], dir, names);

  const char* self = "/proc/self/exe";
  std::printf("| file | MB | load s (CPU s) | MB/s | guarded (before) s | CGAL read_polygon_mesh s | prepare s (CPU s) | "
              "peak RSS load MB | load+prepare MB | guarded MB | CGAL MB |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for(const std::string& name : names)
  {
    const std::string path = (dir / name).string();
    const double mb = double(std::filesystem::file_size(path)) / 1e6;
    const Result ours = run_child(self, "load", path);
    const Result guarded = run_child(self, "guarded", path);
    const Result cgal = run_child(self, "cgal", path);
    if(ours.values.size() < 5 || guarded.values.empty() || cgal.values.empty())
      return 1;
    std::printf("| %s | %.1f | %.3f (%.3f) | %.0f | %.2f | %.2f | %.3f (%.3f) | %.0f | %.0f | %.0f | %.0f |\n", name.c_str(),
                mb, ours.values[0], ours.values[1], mb / ours.values[0], guarded.values[0], cgal.values[0],
                ours.values[2], ours.values[3], ours.values[4], ours.peak_rss_mb, guarded.peak_rss_mb, cgal.peak_rss_mb);
    std::fflush(stdout);
  }
  if(!keep)
    std::filesystem::remove_all(dir);
  return 0;
}
