// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The extension module dggvtp._dggvtp (the package dggvtp re-exports it): NumPy arrays in, NumPy
// arrays out. Arguments are checked and converted here, with the GIL held (arguments.h); every
// computation runs with the GIL released (Soup_solver.h); what dggvtp says on stderr as a
// warning: line becomes a RuntimeWarning.

#include "Soup_solver.h"
#include "arguments.h"
#include "interrupt.h"
#include "typed_object.h"

#include <CGAL/DGG_VTP_3/version.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using namespace dggvtp::python;
using dggvtp::Place;

const double infinity = std::numeric_limits<double>::infinity();

// The stack level of a warning that points at the caller's line: past the frames of this
// package's own Python code (geodesic_distances, dggvtp.gdist, the argument checks), which
// would be named instead.
int caller_stack_level()
{
  static const std::string package = py::str(py::module_::import("os.path").attr("dirname")(
    py::module_::import("dggvtp._dggvtp").attr("__file__")));
  int level = 1;
  for(py::object frame = py::module_::import("sys").attr("_getframe")(0); !frame.is_none();
      frame = frame.attr("f_back"), ++level)
  {
    const std::string file = py::str(frame.attr("f_code").attr("co_filename"));
    if(file.compare(0, package.size(), package) != 0 || file.size() <= package.size() || file[package.size()] != '/')
      break;
  }
  return level;
}

void warn(const std::string& message)
{
  if(PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), caller_stack_level()) != 0) // the filter made it an error
    throw py::error_already_set();
}

// number_text: a number as dggvtp writes it (%.17g)
std::string number_text(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// The places of one range of a query (sources, targets or path targets) with the names of the
// arguments they came from, for warnings that point at one ("points[2]")
struct Named_places
{
  std::vector<Place> places;
  std::vector<std::pair<std::size_t, std::string>> arguments; // (its first place, its name)

  void add(std::vector<Place>&& more, const std::string& argument)
  {
    arguments.emplace_back(places.size(), argument);
    places.insert(places.end(), more.begin(), more.end());
  }
  std::string name_of(std::size_t place) const
  {
    auto a = arguments.begin();
    while(a + 1 != arguments.end() && (a + 1)->first <= place)
      ++a;
    return a->second + "[" + std::to_string(place - a->first) + "]";
  }
};

// the 3D points that a query took at the surface far from where they were given
void warn_moved(const std::vector<dggvtp::Moved_point>& moved, const Named_places* ranges[3])
{
  for(const auto& m : moved)
    warn(ranges[int(m.range)]->name_of(m.place) + " (" + number_text(m.point[0]) + ", " + number_text(m.point[1]) + ", " +
         number_text(m.point[2]) + ") is " + number_text(m.distance) +
         " away from the surface: taken at the nearest point of the surface");
}

// Runs `f` with the GIL released, Ctrl-C cancelling query `q` (see interrupt.h)
template <class F>
void run_interruptible(Query& q, F&& f)
{
  Interrupt_check interrupt;
  q.interrupted = std::ref(interrupt);
  interrupt.run_released(std::forward<F>(f));
  q.interrupted = nullptr; // `interrupt` ends here
}

void warn_unreachable(std::size_t unreachable, std::size_t total, const char* what, double max_distance)
{
  if(std::isinf(max_distance)) // beyond max_distance, they are unreached by request
    if(const std::string w = dggvtp::unreachable_warning(unreachable, total, what); !w.empty())
      warn(w);
}

// a path as an (m, 3) float64 array
py::array_t<double> polyline_array(const dggvtp::Polyline& line)
{
  py::array_t<double> path({py::ssize_t(line.size()), py::ssize_t(3)});
  if(!line.empty())
    std::memcpy(path.mutable_data(), line.data(), line.size() * sizeof line[0]);
  return path;
}

struct Geodesic_solver
{
  std::unique_ptr<Solver_interface> solver;
  std::string precision;
  bool repair = false;
  long threads = 0; // of the preparation (0: all cores)

  std::size_t vertices() const { return solver->number_of_vertices(); }

  Query query(double epsilon, double max_distance, long threads) const
  {
    if(threads < 0)
      bad("threads must be >= 0 (0: all cores)");
    // the library would refuse them too, but in its own words (accuracy); here, the caller's
    if(!(epsilon >= 0. && epsilon <= CGAL::DGG_VTP_3::maximal_accuracy))
      bad("epsilon must be a number in [0, 1] (0: exact); got " + std::string(py::repr(py::float_(epsilon))));
    if(!(max_distance >= 0.))
      bad("max_distance must be a number >= 0 (inf: no limit); got " + std::string(py::repr(py::float_(max_distance))));
    Query q;
    q.epsilon = epsilon;
    q.max_distance = max_distance;
    q.threads = threads;
    return q;
  }

  // The places of three arguments: vertices, 3D points and points on faces; `names`: theirs, and
  // what a vertex of the first is called in messages
  Named_places places(const Vertices& vertices, const Points& points, const Face_points& face_points,
                      const std::array<const char*, 4>& names) const
  {
    Named_places out;
    out.add(vertex_places(vertices, names[3], this->vertices()), names[0]);
    out.add(point_places(points, names[1]), names[1]);
    out.add(face_point_places(face_points, names[2], solver->number_of_faces()), names[2]);
    return out;
  }

  Named_places sources(const Vertices& vertices, const Points& points, const Face_points& face_points) const
  {
    Named_places s = places(vertices, points, face_points, {"sources", "points", "face_points", "source"});
    if(s.places.empty())
      bad("no source given (sources, points or face_points)");
    return s;
  }

  Named_places targets(const Vertices& vertices, const Points& points, const Face_points& face_points) const
  {
    Named_places t = places(vertices, points, face_points, {"targets", "target_points", "target_face_points", "target"});
    if(t.places.empty())
      bad("no target given (targets, target_points or target_face_points)");
    return t;
  }

  // the paths of one propagation as (m, 3) arrays, and their lengths
  // (from the source to the target with `source_first`, else from the target to the source)
  std::pair<std::vector<py::array_t<double>>, py::array_t<double>> paths(Query& q, const Named_places& sources,
                                                                         const Named_places& targets,
                                                                         bool source_first) const
  {
    q.sources = sources.places;
    q.path_targets = targets.places;
    std::vector<dggvtp::Moved_point> moved;
    Paths paths;
    run_interruptible(q, [&] {
      paths = solver->shortest_paths(q, moved);
      if(source_first)
        for(auto& path : paths)
          std::reverse(path.first.begin(), path.first.end());
    });
    const Named_places* ranges[3] = {&sources, &targets, &targets};
    warn_moved(moved, ranges);
    std::vector<py::array_t<double>> lines;
    std::vector<double> lengths;
    for(const auto& [line, length] : paths)
    {
      lines.push_back(polyline_array(line));
      lengths.push_back(length);
    }
    warn_unreachable(dggvtp::count_infinite(lengths), lengths.size(), "paths", q.max_distance);
    return {lines, py::array_t<double>(py::ssize_t(lengths.size()), lengths.data())};
  }
};

dggvtp::Repair_option repair_option(bool repair) { return {"repair=True", repair}; }

Geodesic_solver make_geodesic_solver(const Array_like& V, const Array_like& F, const std::string& precision,
                                     bool repair, long threads)
{
  if(precision != "double" && precision != "float")
    bad("precision must be 'double' or 'float', not '" + precision + "'");
  if(threads < 0)
    bad("threads must be >= 0 (0: all cores)");
  std::vector<std::array<std::uint32_t, 3>> faces;
  dggvtp::Loaded_soup soup = soup_of_arrays(V, F, repair_option(repair), faces);
  Geodesic_solver s;
  s.precision = precision;
  s.repair = repair;
  s.threads = threads;
  {
    py::gil_scoped_release unlocked;
    s.solver = make_soup_solver(std::move(soup), std::move(faces), precision, repair_option(repair), threads);
  }
  // Faces turned to agree with their neighbours change no distance: `repairs` says so, no warning
  // (gdist's flat test mesh had one on every solver).
  for(const std::string& line : s.solver->repairs())
    if(line.rfind("reoriented ", 0) != 0)
      warn("GeodesicSolver(V, F): " + line);
  return s;
}

// The method `name` of `c` that takes the arguments of the queries to several targets and answers
// f(solver, query, sources, targets, flag), `flag` the last keyword argument (`flag_name`, default
// `flag_default`)
template <class Class, class F>
void def_targets_query(Class& c, const char* name, F f, const char* flag_name, bool flag_default, const char* doc)
{
  c.def(
    name,
    [f](const Geodesic_solver& s, const Vertices& sources, const Vertices& targets, const Points& points,
        const Face_points& face_points, const Points& target_points, const Face_points& target_face_points,
        double epsilon, double max_distance, long threads, bool flag) {
      Query q = s.query(epsilon, max_distance, threads);
      return f(s, q, s.sources(sources, points, face_points), s.targets(targets, target_points, target_face_points),
               flag);
    },
    "sources"_a, "targets"_a, py::kw_only(), "points"_a = py::none(),
    "face_points"_a = py::none(), "target_points"_a = py::none(), "target_face_points"_a = py::none(),
    "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 0, py::arg(flag_name) = flag_default, doc);
}

std::pair<py::array_t<double>, py::array_t<std::int64_t>> read_mesh(const Path& path, bool repair)
{
  const std::string file = py::str(py::module_::import("os").attr("fspath")(path.object));
  dggvtp::Loaded_soup soup;
  {
    py::gil_scoped_release unlocked;
    soup = dggvtp::load_soup(file, repair_option(repair));
    if(repair)
      dggvtp::repair_soup(soup, repair_option(repair)); // its triangles, over the file's vertices
    if(!soup.polygons.empty())
      dggvtp::internal::triangulate_soup(soup);
    else
      dggvtp::triangles_to_polygons(soup); // back to the file's corner order
  }
  for(const std::string& line : soup.repairs)
    warn(file + ": " + line);
  py::array_t<double> V({py::ssize_t(soup.file_vertices), py::ssize_t(3)});
  py::array_t<std::int64_t> F({py::ssize_t(soup.polygons.size()), py::ssize_t(3)});
  auto v = V.mutable_unchecked<2>();
  auto f = F.mutable_unchecked<2>();
  for(std::size_t i = 0; i < soup.file_vertices; ++i)
    for(int c = 0; c < 3; ++c)
      v(i, c) = soup.points[i][c];
  for(std::size_t t = 0; t < soup.polygons.size(); ++t)
    for(int k = 0; k < 3; ++k)
      f(t, k) = std::int64_t(soup.file_vertex_of[soup.polygons[t][k]]);
  return {V, F};
}

// The rows as scipy.sparse.csr_matrix((data, indices, indptr), shape), or, `by_column`, as
// scipy.sparse.csc_matrix of shape (columns, rows.size()) (the rows are then its columns): int32
// indices, as SciPy makes them, unless the matrix is too large for them
template <class Index>
py::object compressed_matrix(std::vector<dggvtp::Sparse_row>& rows, std::size_t columns, bool by_column)
{
  std::size_t nonzeros = 0;
  for(const auto& r : rows)
    nonzeros += r.columns.size();
  py::array_t<double> data{py::ssize_t(nonzeros)};
  py::array_t<Index> indices{py::ssize_t(nonzeros)}, indptr{py::ssize_t(rows.size() + 1)};
  {
    py::gil_scoped_release unlocked;
    double* d = data.mutable_data();
    Index* i = indices.mutable_data();
    Index* p = indptr.mutable_data();
    std::size_t at = 0, freed = 0;
    p[0] = 0;
    for(std::size_t k = 0; k < rows.size(); ++k)
    {
      std::copy(rows[k].values.begin(), rows[k].values.end(), d + at);
      std::copy(rows[k].columns.begin(), rows[k].columns.end(), i + at);
      at += rows[k].columns.size();
      p[k + 1] = Index(at);
      freed += rows[k].columns.size() * (sizeof(std::uint32_t) + sizeof(double));
      dggvtp::Sparse_row().columns.swap(rows[k].columns); // its memory back, row by row
      std::vector<double>().swap(rows[k].values);
#ifdef __GLIBC__
      // The rows are small blocks that malloc keeps for reuse; handed back to the system as they
      // are copied, the peak is about one copy of the matrix, not two: the arrays' pages (mapped,
      // not yet touched) become resident only as they are written.
      if(freed > (std::size_t(32) << 20))
      {
        malloc_trim(0);
        freed = 0;
      }
#endif
    }
  }
  if(by_column)
    return py::module_::import("scipy.sparse")
      .attr("csc_matrix")(py::make_tuple(data, indices, indptr), "shape"_a = py::make_tuple(columns, rows.size()));
  return py::module_::import("scipy.sparse")
    .attr("csr_matrix")(py::make_tuple(data, indices, indptr), "shape"_a = py::make_tuple(rows.size(), columns));
}

} // namespace

#include "docstrings.h"

PYBIND11_MODULE(_dggvtp, m)
{
  m.doc() = doc::module;
  m.attr("__version__") = DGG_VTP_3_VERSION_STR;
#ifdef DGGVTP_PYTHON_TEST_HOOKS // a module of the test build (interrupt.h): never the one pip installs
  m.attr("_test_hooks") = true;
#else
  m.attr("_test_hooks") = false;
#endif
  py::register_exception<dggvtp::Input_error>(m, "InputError", PyExc_ValueError);
  m.attr("InputError").attr("__doc__") = doc::input_error;

  m.def("read_mesh", &read_mesh, "path"_a, py::kw_only(), "repair"_a = false, doc::read_mesh);

  py::class_<Geodesic_solver> solver(m, "GeodesicSolver", doc::solver);
  solver
    .def(py::init([](const Array_like& V, const Array_like& F, const Precision& precision, bool repair, long threads) {
           return make_geodesic_solver(V, F, precision_of(precision), repair, threads);
         }),
         "V"_a, "F"_a, py::kw_only(), "precision"_a = py::str("double"), "repair"_a = false, "threads"_a = 0, doc::init)
    // pickle and copy: V and F as given, and the options; rebuilt, not copied
    .def(py::pickle(
      [](const Geodesic_solver& s) {
        const auto [points, faces] = s.solver->given_mesh();
        py::array_t<double> V({py::ssize_t(points.size()), py::ssize_t(3)});
        py::array_t<std::int64_t> F({py::ssize_t(faces.size()), py::ssize_t(3)});
        for(std::size_t i = 0; i < points.size(); ++i)
          for(int c = 0; c < 3; ++c)
            V.mutable_at(i, c) = points[i][c];
        for(std::size_t t = 0; t < faces.size(); ++t)
          for(int k = 0; k < 3; ++k)
            F.mutable_at(t, k) = std::int64_t(faces[t][k]);
        return py::make_tuple(V, F, s.precision, s.repair, s.threads);
      },
      [](const py::tuple& t) {
        if(t.size() != 5)
          bad("not the pickled state of a GeodesicSolver");
        return make_geodesic_solver(Array_like{t[0]}, Array_like{t[1]}, t[2].cast<std::string>(), t[3].cast<bool>(),
                                    t[4].cast<long>());
      }))
    .def_property_readonly("num_vertices", &Geodesic_solver::vertices, doc::num_vertices)
    .def_property_readonly("num_faces", [](const Geodesic_solver& s) { return s.solver->number_of_triangles(); },
                           doc::num_faces)
    .def_readonly("precision", &Geodesic_solver::precision, doc::precision)
    .def_property_readonly("repairs", [](const Geodesic_solver& s) { return s.solver->repairs(); }, doc::repairs)
    .def(
      "distances",
      [](const Geodesic_solver& s, const Vertices& sources, const Points& points, const Face_points& face_points,
         double epsilon, double max_distance, long threads, bool return_labels, bool return_bounds,
         const Optional_array& prior_distances, const Optional_array& prior_labels,
         const Optional_array& prior_bounds) -> Field {
        Query q = s.query(epsilon, max_distance, threads);
        const Named_places named = s.sources(sources, points, face_points);
        q.sources = named.places;
        const py::ssize_t n = py::ssize_t(s.vertices());
        // a field of earlier sources, which these are added to
        const auto prior = per_vertex<double>(prior_distances, "prior_distances", s.vertices(), "iuf", "float64");
        const auto prior_l = per_vertex<std::int64_t>(prior_labels, "prior_labels", s.vertices(), "iu", "int64");
        const auto prior_b = per_vertex<double>(prior_bounds, "prior_bounds", s.vertices(), "iuf", "float64");
        if(!prior && (prior_l || prior_b))
          bad("prior_labels and prior_bounds go with prior_distances (the field they belong to)");
        if(prior && std::isfinite(max_distance))
          bad("prior_distances does not combine with max_distance: the field of every source is computed");
        if(prior && return_labels && !prior_l)
          bad("return_labels=True with prior_distances needs prior_labels (the labels of the prior field)");
        if(prior)
          q.prior_distances = prior->data();
        if(prior_l)
          q.prior_labels = reinterpret_cast<const long long*>(prior_l->data());
        if(prior_b)
          q.prior_bounds = prior_b->data();
        py::array_t<double> d(n);
        py::array_t<std::int64_t> labels(return_labels ? n : 0);
        py::array_t<double> bounds(return_bounds ? n : 0);
        double* out = d.mutable_data();
        long long* out_labels = return_labels ? reinterpret_cast<long long*>(labels.mutable_data()) : nullptr;
        double* out_bounds = return_bounds ? bounds.mutable_data() : nullptr;
        std::vector<dggvtp::Moved_point> moved;
        std::size_t unreachable = 0;
        run_interruptible(q, [&] {
          s.solver->distances(q, out, out_labels, out_bounds, moved);
          unreachable = dggvtp::count_infinite(out, out + n);
        });
        const Named_places* ranges[3] = {&named, nullptr, nullptr};
        warn_moved(moved, ranges);
        warn_unreachable(unreachable, std::size_t(n), "vertices", max_distance);
        if(return_labels && return_bounds)
          return {py::make_tuple(d, labels, bounds)};
        if(return_labels || return_bounds)
          return {py::make_tuple(d, return_labels ? py::object(labels) : py::object(bounds))};
        return {std::move(d)};
      },
      "sources"_a, py::kw_only(), "points"_a = py::none(), "face_points"_a = py::none(),
      "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 0, "return_labels"_a = false,
      "return_bounds"_a = false, "prior_distances"_a = py::none(), "prior_labels"_a = py::none(),
      "prior_bounds"_a = py::none(), doc::distances)
    .def(
      "farthest_point_sampling",
      [](const Geodesic_solver& s, long long k, long long first, double epsilon, long threads, bool return_distances,
         bool return_labels, bool return_bounds) -> Field {
        const std::size_t n = s.vertices();
        if(k < 1 || static_cast<unsigned long long>(k) > n)
          bad("k must be in [1, num_vertices] = [1, " + std::to_string(n) + "]; got " + std::to_string(k));
        if(first < 0 || static_cast<unsigned long long>(first) >= n)
          bad("first_sample " + std::to_string(first) + " is out of range (the mesh has " + std::to_string(n) +
              " vertices)");
        Query q = s.query(epsilon, infinity, threads);
        q.sources.resize(1);
        q.sources[0].vertex = std::size_t(first);
        py::array_t<double> d(static_cast<py::ssize_t>(n));
        py::array_t<std::int64_t> labels(return_labels ? py::ssize_t(n) : 0);
        py::array_t<double> bounds(return_bounds ? py::ssize_t(n) : 0);
        long long* out_labels = return_labels ? reinterpret_cast<long long*>(labels.mutable_data()) : nullptr;
        double* out_bounds = return_bounds ? bounds.mutable_data() : nullptr;
        std::vector<long long> samples;
        run_interruptible(q, [&] {
          samples = s.solver->farthest_point_sampling(q, std::size_t(k), d.mutable_data(), out_labels, out_bounds);
        });
        py::array_t<std::int64_t> out(py::ssize_t(samples.size()));
        std::copy(samples.begin(), samples.end(), out.mutable_data());
        // the samples, then what was asked of the field, in the order of distances()
        py::list result;
        result.append(out);
        if(return_distances)
          result.append(d);
        if(return_labels)
          result.append(labels);
        if(return_bounds)
          result.append(bounds);
        if(result.size() == 1)
          return {std::move(out)};
        return {py::tuple(result)};
      },
      "k"_a, py::kw_only(), "first_sample"_a = 0, "epsilon"_a = 0., "threads"_a = 0, "return_distances"_a = false,
      "return_labels"_a = false, "return_bounds"_a = false, doc::farthest_point_sampling)
    .def(
      "distances_from_each",
      [](const Geodesic_solver& s, const Vertices& sources, double epsilon, double max_distance, long threads,
         bool return_bounds) -> Field {
        if(sources.object.is_none())
          bad("distances_from_each() needs its sources: None would be num_vertices rows of num_vertices "
              "numbers (pass range(solver.num_vertices) for that; local_distance_matrix() keeps those "
              "within a radius)");
        Query q = s.query(epsilon, max_distance, threads);
        q.sources = vertex_places(sources, "source", s.vertices());
        const std::size_t n = s.vertices();
        py::array_t<double> rows({py::ssize_t(q.sources.size()), py::ssize_t(n)});
        py::array_t<double> bounds({py::ssize_t(return_bounds ? q.sources.size() : 0), py::ssize_t(n)});
        double* out = rows.mutable_data();
        dggvtp::Unreachable_rows unreachable;
        run_interruptible(q, [&] {
          s.solver->distances_from_each(q, out, return_bounds ? bounds.mutable_data() : nullptr);
          for(std::size_t k = 0; k < q.sources.size(); ++k)
            unreachable.add(out + k * n, out + (k + 1) * n);
        });
        if(std::isinf(max_distance) && unreachable.rows > 0)
          warn(dggvtp::unreachable_rows_warning(unreachable.rows, q.sources.size(), unreachable.most, n));
        if(return_bounds)
          return {py::make_tuple(rows, bounds)};
        return {std::move(rows)};
      },
      "sources"_a, py::kw_only(), "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 0,
      "return_bounds"_a = false, doc::distances_from_each)
    .def(
      "pair_distances",
      [](const Geodesic_solver& s, const Vertices& sources, const Vertices& targets, double epsilon,
         double max_distance, long threads, bool return_bounds, bool return_paths) -> Field {
        Query q = s.query(epsilon, max_distance, threads);
        q.sources = vertex_places(sources, "source", s.vertices());
        q.targets = vertex_places(targets, "target", s.vertices());
        if(sources.object.is_none() || targets.object.is_none())
          bad("pair_distances() takes two arrays of vertex indices, sources and targets");
        if(q.sources.size() != q.targets.size())
          bad("sources and targets pair up: they must have the same length; got " + std::to_string(q.sources.size()) +
              " sources and " + std::to_string(q.targets.size()) + " targets");
        const py::ssize_t n = py::ssize_t(q.sources.size());
        py::array_t<double> d(n);
        py::array_t<double> bounds(return_bounds ? n : 0);
        Paths paths;
        run_interruptible(q, [&] {
          s.solver->pair_distances(q, d.mutable_data(), return_bounds ? bounds.mutable_data() : nullptr,
                                   return_paths ? &paths : nullptr);
        });
        if(return_bounds) // certified errors, as distances(return_bounds=True) gives them
          for(py::ssize_t k = 0; k < n; ++k)
            bounds.mutable_data()[k] = std::isinf(d.data()[k]) ? d.data()[k] : d.data()[k] - bounds.data()[k];
        warn_unreachable(dggvtp::count_infinite(d.data(), d.data() + n), std::size_t(n), "pairs", max_distance);
        py::list result;
        result.append(d);
        if(return_bounds)
          result.append(bounds);
        if(return_paths)
        {
          py::list lines;
          for(const auto& path : paths)
            lines.append(polyline_array(path.first));
          result.append(lines);
        }
        if(result.size() == 1)
          return {std::move(d)};
        return {py::tuple(result)};
      },
      "sources"_a, "targets"_a, py::kw_only(), "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 0,
      "return_bounds"_a = false, "return_paths"_a = false, doc::pair_distances)
    .def(
      "local_distance_matrix",
      [](const Geodesic_solver& s, double max_distance, const Vertices& sources, double epsilon,
         long threads, bool symmetric, const std::string& format) -> Sparse_matrix {
        if(!(max_distance >= 0.) || std::isinf(max_distance))
          bad("max_distance must be a finite number >= 0 (the matrix holds the distances up to it), not " +
              number_text(max_distance) + ": distances_from_each() gives every distance");
        if(format != "csr" && format != "csc")
          bad("format must be 'csr' or 'csc' (scipy.sparse's names), not '" + format + "'");
        if(symmetric && !sources.object.is_none())
          bad("symmetric=True needs the square matrix of every vertex: leave sources=None");
        Query q = s.query(epsilon, max_distance, threads);
        q.sources = vertex_places(sources, "source", s.vertices());
        if(!sources.object.is_none() && q.sources.empty())
          bad("no source given: sources=None (the default) is every vertex");
        std::vector<dggvtp::Sparse_row> rows(sources.object.is_none() ? s.vertices() : q.sources.size());
        run_interruptible(q, [&] {
          s.solver->local_distance_matrix(q, [&rows](std::size_t k, dggvtp::Sparse_row&& row) { rows[k] = std::move(row); });
          if(symmetric)
            dggvtp::make_symmetric(rows);
        });
        // a symmetric matrix's rows are its columns; otherwise CSC is the CSR of the transpose
        const bool by_column = format == "csc";
        const std::size_t sources_count = rows.size();
        if(by_column && !symmetric)
        {
          py::gil_scoped_release unlocked;
          rows = dggvtp::transposed(rows, s.vertices());
#ifdef __GLIBC__
          malloc_trim(0); // the rows' memory, freed by the assignment
#endif
        }
        const std::size_t columns = by_column && !symmetric ? sources_count : s.vertices();
        const std::size_t rows_out = rows.size();
        const std::uint64_t int32_max = std::uint64_t(std::numeric_limits<std::int32_t>::max());
        std::uint64_t nonzeros = 0;
        for(const auto& r : rows)
          nonzeros += r.columns.size();
        if(nonzeros <= int32_max && (std::max)(columns, rows_out) <= int32_max)
          return {compressed_matrix<std::int32_t>(rows, columns, by_column)};
        return {compressed_matrix<std::int64_t>(rows, columns, by_column)};
      },
      "max_distance"_a, "sources"_a = py::none(), py::kw_only(), "epsilon"_a = 0., "threads"_a = 0,
      "symmetric"_a = false, "format"_a = "csr", doc::local_distance_matrix);
  def_targets_query(
    solver, "target_distances",
    [](const Geodesic_solver& s, Query& q, const Named_places& named_sources, const Named_places& named_targets,
       bool return_labels) -> Field {
      q.sources = named_sources.places;
      q.targets = named_targets.places;
      std::vector<double> t;
      std::vector<long long> labels;
      std::vector<dggvtp::Moved_point> moved;
      run_interruptible(q, [&] { t = s.solver->target_distances(q, moved, return_labels ? &labels : nullptr); });
      const Named_places* ranges[3] = {&named_sources, &named_targets, nullptr};
      warn_moved(moved, ranges);
      warn_unreachable(dggvtp::count_infinite(t), t.size(), "targets", q.max_distance);
      py::array_t<double> d(py::ssize_t(t.size()), t.data());
      if(return_labels)
        return {py::make_tuple(d, py::array_t<std::int64_t>(py::ssize_t(labels.size()),
                                                            reinterpret_cast<const std::int64_t*>(labels.data())))};
      return {std::move(d)};
    },
    "return_labels", false, doc::target_distances);
  def_targets_query(
    solver, "distances_and_paths",
    [](const Geodesic_solver& s, Query& q, const Named_places& sources, const Named_places& targets,
       bool source_first) {
      auto [paths, lengths] = s.paths(q, sources, targets, source_first);
      return py::make_tuple(lengths, paths); // values first, as distance_and_path() and distances(return_*)
    },
    "source_first", true, doc::distances_and_paths);
  solver.def(
    "geodesic_path",
    [](const Geodesic_solver& s, const Vertices& sources, const Vertices& target, const Points& points,
       const Face_points& face_points, const Points& target_point, const Face_points& target_face_point,
       double epsilon, double max_distance, long threads, bool source_first) {
      Query q = s.query(epsilon, max_distance, threads);
      const Named_places t =
        s.places(target, target_point, target_face_point, {"target", "target_point", "target_face_point", "target"});
      if(t.places.size() != 1)
        bad("give one target: target (a vertex), target_point (3 coordinates) or target_face_point ((face, "
            "barycentric))");
      return s.paths(q, s.sources(sources, points, face_points), t, source_first).first.front();
    },
    "sources"_a, "target"_a, py::kw_only(), "points"_a = py::none(),
    "face_points"_a = py::none(), "target_point"_a = py::none(), "target_face_point"_a = py::none(),
    "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 0, "source_first"_a = true, doc::geodesic_path)
    .def(
      "distance_and_path",
      [](const Geodesic_solver& s, const Vertices& source, const Vertices& target, double epsilon,
         double max_distance, long threads, bool source_first) {
        Query q = s.query(epsilon, max_distance, threads);
        const Named_places from = s.places(source, Points{py::none()}, Face_points{py::none()},
                                           {"source", "points", "face_points", "source"});
        const Named_places to = s.places(target, Points{py::none()}, Face_points{py::none()},
                                         {"target", "target_point", "target_face_point", "target"});
        if(from.places.size() != 1 || to.places.size() != 1)
          bad("distance_and_path takes one source vertex and one target vertex (distances_and_paths() takes several)");
        auto [paths, lengths] = s.paths(q, from, to, source_first);
        return py::make_tuple(py::float_(lengths.at(0)), paths.front());
      },
      "source"_a, "target"_a, py::kw_only(), "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 0,
      "source_first"_a = true, doc::distance_and_path)
    .def("__repr__", [](const Geodesic_solver& s) {
      return "<dggvtp.GeodesicSolver: " + std::to_string(s.vertices()) + " vertices, " +
             std::to_string(s.solver->number_of_triangles()) + " faces, " + s.precision + ">";
    });
}
