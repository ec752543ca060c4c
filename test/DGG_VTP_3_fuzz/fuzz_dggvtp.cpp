// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// libFuzzer target: bytes as a mesh file, read by the loader of dggvtp, then the exact
// propagation and one DGG-VTP run (accuracy 1e-4), as the command-line program does them, and
// both again on 2 threads (Parallel_tag, where linked with TBB), which must give the same bits:
// patches here have 4 faces or more (CGAL_DGG_VTP_3_MIN_PATCH_FACES, 2048 in a release), so that
// the small inputs run rounds across patches, with the copies a repair makes among them. Then a
// farthest-point sampling of 4 vertices from the source (check_sampling: each sample added to the
// field of those before), against its samples' whole fields and on 2 threads.
//
// The first byte chooses how the rest is read:
//   bits 0-1  the file's extension: .off, .ply, .obj, .stl
//   bit  2    the number type: double (Epick) or float (Simple_cartesian<float>)
//   bits 3-7  the source: that file vertex, modulo the number of vertices
// The remaining bytes are the file.
//
// A file that one of the fast readers takes is read by CGAL's guarded path too, and both soups
// must be the same to the bit (check_fast_reader).
//
// Allowed outcomes are those of dggvtp's input policy: dggvtp::Input_error (exit status 2) or the
// library's std::invalid_argument (its documented preconditions), from the loader or from making
// the solver only, but for a propagation's window limit on edges of more than two triangles
// (is_window_limit), or distances. Everything else (an exception from a later check included)
// aborts, so that libFuzzer keeps the input: another exception (it would reach the user as an
// unexplained `error:`), a NaN or negative distance, a source not at 0, a vertex reached by one
// mode and not by the other. With DGG_VTP_3_FUZZ_CONTRACT=1 in the environment, a DGG-VTP
// distance outside [exact, (1 + 1e-4) exact] aborts too (off by default: this tests accuracy,
// not robustness).

#define CGAL_DGG_VTP_3_MIN_PATCH_FACES 4

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

[[noreturn]] void fail(const std::string& what)
{
  std::fprintf(stderr, "fuzz_dggvtp: %s\n", what.c_str());
  std::abort();
}

// The one refusal a propagation may make of a mesh the solver took: too many windows between the
// sheets of edges of more than two triangles (internal/Vertex_copies.h, refuse_windows_beyond).
bool is_window_limit(const std::invalid_argument& e)
{
  return std::string(e.what()).rfind("the propagation made more than ", 0) == 0;
}

template <class Kernel>
using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;

// distances per solver vertex
template <class Kernel, class ConcurrencyTag = CGAL::Sequential_tag>
std::vector<typename Kernel::FT> solver_distances(const dggvtp::Loaded_soup& soup, const Solver<Kernel>& solver,
                                                  std::size_t source, double accuracy)
{
  std::vector<typename Kernel::FT> d(solver.number_of_vertices());
  solver.template compute_distances_to_nearest_source<ConcurrencyTag>(
    dggvtp::solver_vertices_of(soup, source), CGAL::make_property_map(d), CGAL::parameters::accuracy(accuracy));
  return d;
}

// distances per file vertex, the smallest over the copies that loading made (as dggvtp does)
template <class Kernel>
std::vector<double> file_distances(const dggvtp::Loaded_soup& soup, const Solver<Kernel>& solver,
                                   std::size_t source, double accuracy)
{
  const std::vector<typename Kernel::FT> d = solver_distances<Kernel>(soup, solver, source, accuracy);
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    if(std::isnan(double(d[i])))
      fail("NaN distance at solver vertex " + std::to_string(i) + " (accuracy " + std::to_string(accuracy) + ")");
    if(d[i] < 0)
      fail("negative distance at solver vertex " + std::to_string(i));
  }
#ifdef CGAL_LINKED_WITH_TBB
  {
    const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    const std::vector<typename Kernel::FT> threaded = solver_distances<Kernel, CGAL::Parallel_tag>(soup, solver, source, accuracy);
    if(std::memcmp(threaded.data(), d.data(), d.size() * sizeof(d[0])) != 0)
      fail("2 threads give other distances than one (accuracy " + std::to_string(accuracy) + ")");
  }
#endif
  const std::vector<double> out = dggvtp::file_vertex_distances(soup, d);
  if(out[source] != 0.)
    fail("the source is at " + std::to_string(out[source]) + ", not 0");
  return out;
}

// Farthest-point sampling of 4 vertices (each added to the field of those before, see the
// manual), exact: its field is the minimum of its samples' whole fields, within the rounding of
// the ties a vertex keeps (64 ulps of the propagation's double, a few of a float result), and the
// same on 2 threads
template <class Kernel>
void check_sampling(const Solver<Kernel>& solver, std::size_t first)
{
  using FT = typename Kernel::FT;
  const std::size_t n = solver.number_of_vertices(), k = (std::min)(n, std::size_t(4));
  std::vector<FT> d(n);
  std::vector<std::size_t> samples;
  solver.farthest_point_sampling(k, std::back_inserter(samples),
                                 CGAL::DGG_VTP_3::parameters::first_sample(first, CGAL::DGG_VTP_3::parameters::distance_map(
                                                                                    CGAL::make_property_map(d))));
  std::vector<FT> nearest(n, std::numeric_limits<FT>::infinity()), row(n);
  for(std::size_t s : samples)
  {
    solver.compute_distances(s, CGAL::make_property_map(row));
    for(std::size_t i = 0; i < n; ++i)
      nearest[i] = (std::min)(nearest[i], row[i]);
  }
  // (both finite for the tolerance: |finite - inf| <= tolerance * inf would let a finite value
  // pass where the samples' fields do not reach)
  for(std::size_t i = 0; i < n; ++i)
    if(!(d[i] == nearest[i] ||
         (std::isfinite(double(d[i])) && std::isfinite(double(nearest[i])) &&
          std::abs(double(d[i] - nearest[i])) <= (1e-13 + 4. * double(std::numeric_limits<FT>::epsilon())) * double(nearest[i]))))
      fail("farthest-point sampling: vertex " + std::to_string(i) + " at " + std::to_string(double(d[i])) +
           ", its samples' fields give " + std::to_string(double(nearest[i])));
#ifdef CGAL_LINKED_WITH_TBB
  const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  std::vector<FT> threaded(n);
  std::vector<std::size_t> threaded_samples;
  solver.template farthest_point_sampling<CGAL::Parallel_tag>(
    k, std::back_inserter(threaded_samples),
    CGAL::DGG_VTP_3::parameters::first_sample(first, CGAL::DGG_VTP_3::parameters::distance_map(CGAL::make_property_map(threaded))));
  if(threaded_samples != samples || std::memcmp(threaded.data(), d.data(), n * sizeof(FT)) != 0)
    fail("farthest-point sampling on 2 threads differs from one");
#endif
}

// The checks of one input. Making the solver may refuse it (dggvtp::Input_error, or the
// library's std::invalid_argument for its documented preconditions); after that, an exception
// from a check reaches the caller, which aborts unless it is a propagation's window limit.
template <class Kernel>
void run(dggvtp::Loaded_soup& soup, std::size_t source)
{
  std::optional<Solver<Kernel>> solver;
  try
  {
    dggvtp::make_solver(soup, solver);
  }
  catch(const dggvtp::Input_error&)
  {
    return;
  }
  catch(const std::invalid_argument&)
  {
    return;
  }
  if(const std::vector<std::size_t> first = dggvtp::solver_vertices_of(soup, source); !first.empty())
    check_sampling<Kernel>(*solver, first[0]);
  const std::vector<double> exact = file_distances<Kernel>(soup, *solver, source, 0.);
  const std::vector<double> approx = file_distances<Kernel>(soup, *solver, source, 1e-4);
  static const bool check_contract = [] {
    const char* e = std::getenv("DGG_VTP_3_FUZZ_CONTRACT");
    return e != nullptr && std::string(e) == "1";
  }();
  for(std::size_t i = 0; i < exact.size(); ++i)
  {
    if(std::isinf(exact[i]) != std::isinf(approx[i]))
      fail("vertex " + std::to_string(i) + ": exact " + std::to_string(exact[i]) + ", DGG-VTP " +
           std::to_string(approx[i]));
    const double slack = 1e-5 * exact[i] + 1e-12;  // float results are rounded to 6e-8
    if(check_contract && std::isfinite(exact[i]) &&
       (approx[i] < exact[i] - slack || approx[i] > exact[i] * (1. + 1e-4) + slack))
      fail("vertex " + std::to_string(i) + ": DGG-VTP " + std::to_string(approx[i]) +
           " is not within 1e-4 of exact " + std::to_string(exact[i]));
  }
}

// The fast readers against CGAL's guarded path on the same file: what a fast reader takes, that
// path must take too, into the same soup to the bit (points, faces and their corners' order).
void check_fast_reader(const std::string& path)
{
  std::optional<dggvtp::internal::Fast_soup> fast =
    dggvtp::internal::read_fast(path, dggvtp::internal::lower_case_extension(path));
  if(!fast)
    return;
  const std::optional<dggvtp::Loaded_soup> soup = dggvtp::internal::soup_of(*fast);
  if(!soup)
    return;
  dggvtp::Loaded_soup reference;
  try
  {
    reference = dggvtp::load_soup_with_cgal(path);
  }
  catch(const dggvtp::Input_error& e)
  {
    fail(std::string("a fast reader takes a file CGAL's path refuses: ") + e.what());
  }
  if(soup->points.size() != reference.points.size() || soup->file_vertices != reference.file_vertices)
    fail("a fast reader reads " + std::to_string(soup->points.size()) + " points, CGAL's path " +
         std::to_string(reference.points.size()));
  for(std::size_t i = 0; i < soup->points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(std::memcmp(&soup->points[i][c], &reference.points[i][c], sizeof(double)) != 0)
        fail("a fast reader reads point " + std::to_string(i) + " differently from CGAL's path");
  if(soup->triangles != reference.triangles || soup->polygons != reference.polygons)
    fail("a fast reader reads the faces differently from CGAL's path");
}

std::string input_path(const char* extension)
{
  const char* tmp = std::getenv("TMPDIR");
  return std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/fuzz_dggvtp_" +
         std::to_string(::getpid()) + extension;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return 0;
  static const char* const extensions[] = {".off", ".ply", ".obj", ".stl"};
  const unsigned selector = data[0];
  const std::string path = input_path(extensions[selector & 3u]);
  {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if(file == nullptr)
      fail("cannot write " + path);
    if(size > 1 && std::fwrite(data + 1, 1, size - 1, file) != size - 1)
      fail("cannot write " + path);
    std::fclose(file);
  }
  check_fast_reader(path);
  // the loader may refuse the file; after it, only making the solver may refuse it (see run)
  std::optional<dggvtp::Loaded_soup> soup;
  try
  {
    soup = dggvtp::load_soup(path);
  }
  catch(const dggvtp::Input_error&)
  {
  }
  catch(const std::invalid_argument&)
  {
  }
  catch(const std::exception& e)
  {
    fail(std::string("unexpected exception from the loader: ") + e.what());
  }
  std::remove(path.c_str());
  if(!soup)
    return 0;
  try
  {
    const std::size_t source = (selector >> 3) % soup->file_vertices;
    if(selector & 4u)
      run<CGAL::Simple_cartesian<float>>(*soup, source);
    else
      run<CGAL::Exact_predicates_inexact_constructions_kernel>(*soup, source);
  }
  catch(const std::invalid_argument& e)
  {
    if(!is_window_limit(e))
      fail(std::string("std::invalid_argument after the solver accepted the input: ") + e.what());
  }
  catch(const std::exception& e)
  {
    fail(std::string("unexpected exception after the solver accepted the input: ") + e.what());
  }
  return 0;
}
