// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The Python module dggvtp: NumPy arrays in, NumPy arrays out. Arguments are checked and converted
// here, with the GIL held; every computation runs with the GIL released (Soup_solver.h).

#include "Soup_solver.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using dggvtp::Place;
using dggvtp::python::Query;
using dggvtp::python::Solver_interface;

const double infinity = std::numeric_limits<double>::infinity();

[[noreturn]] void bad(const std::string& message) { throw py::value_error(message); }

// `object` as a NumPy array of `dtype`, refusing other kinds of numbers than `kinds` (a silent
// conversion of floats to indices, or of strings to numbers, would hide a mistake)
py::array as_array(const py::handle& object, const char* name, const char* kinds, const char* dtype)
{
  py::object a;
  try
  {
    a = py::module_::import("numpy").attr("asarray")(object);
  }
  catch(const py::error_already_set& e)
  {
    bad(std::string(name) + " is not an array of numbers: " + e.what());
  }
  std::string kind = py::str(a.attr("dtype").attr("kind"));
  if(py::int_(a.attr("size")).cast<std::size_t>() == 0) // [] is float64 for NumPy
    kind = "i";
  if(kind.empty() || std::string(kinds).find(kind) == std::string::npos)
    bad(std::string(name) + " must hold " + (std::string(kinds) == "iu" ? "integers" : "real numbers") + ", not " +
        std::string(py::str(a.attr("dtype"))));
  return py::array(a.attr("astype")(dtype, "copy"_a = false));
}

// an (m, 3) array, or (3,) for one row when `one_row` is allowed
template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> rows_of_3(const py::handle& object, const char* name,
                                                                    const char* kinds, const char* dtype, bool one_row)
{
  py::array a = as_array(object, name, kinds, dtype);
  if(one_row && a.ndim() == 1 && a.shape(0) == 3)
    a = a.attr("reshape")(1, 3);
  if(a.ndim() != 2 || a.shape(1) != 3)
    bad(std::string(name) + " must have shape (" + (one_row ? "k" : "n") + ", 3), not " +
        std::string(py::str(a.attr("shape"))));
  return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
}

// vertices given as an int, a sequence of ints or None (none), checked against the mesh
std::vector<Place> vertex_places(const py::handle& object, const char* what, std::size_t vertices)
{
  std::vector<Place> places;
  if(object.is_none())
    return places;
  const py::array a = as_array(object, what, "iu", "int64");
  if(a.ndim() > 1)
    bad(std::string(what) + " must be a vertex index or a sequence of them");
  const auto v = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a.attr("reshape")(-1));
  for(py::ssize_t i = 0; i < v.size(); ++i)
  {
    if(v.at(i) < 0 || std::uint64_t(v.at(i)) >= vertices)
      bad(std::string(what) + " " + std::to_string(v.at(i)) + " is out of range (the mesh has " +
          std::to_string(vertices) + " vertices)");
    Place p;
    p.vertex = std::size_t(v.at(i));
    places.push_back(p);
  }
  return places;
}

// 3D points as a (k, 3) or (3,) array-like, or None (none); located on the surface later
std::vector<Place> point_places(const py::handle& object, const char* what)
{
  std::vector<Place> places;
  if(object.is_none())
    return places;
  const auto a = rows_of_3<double>(object, what, "iuf", "float64", true);
  for(py::ssize_t i = 0; i < a.shape(0); ++i)
  {
    Place p;
    p.is_point = true;
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(p.point[c] = a.at(i, c)))
        bad(std::string(what) + " needs finite coordinates (row " + std::to_string(i) + ")");
    places.push_back(p);
  }
  return places;
}

struct Geodesic_solver
{
  std::unique_ptr<Solver_interface> solver;
  std::string precision;

  Query query(const py::object& sources, const py::object& points, double epsilon, double max_distance,
              long threads, bool needs_source = true) const
  {
    if(threads < 0)
      bad("threads must be >= 0 (0: all cores)");
    Query q;
    q.sources = vertex_places(sources, "source", solver->number_of_vertices());
    for(const Place& p : point_places(points, "points"))
      q.sources.push_back(p);
    if(q.sources.empty() && needs_source)
      bad("no source given (sources or points)");
    q.epsilon = epsilon;
    q.max_distance = max_distance;
    q.threads = threads;
    return q;
  }
};

// The soup of arrays V, F: the file's soup of the same vertices and triangles as dggvtp's loader
// makes it (the corners in a Surface_mesh face's order), refusing what its readers refuse.
dggvtp::Loaded_soup soup_of_arrays(const py::object& V, const py::object& F)
{
  const auto v = rows_of_3<double>(V, "V", "iuf", "float64", false);
  const auto f = rows_of_3<std::int64_t>(F, "F", "iu", "int64", false);
  const std::size_t n = std::size_t(v.shape(0));
  if(n == 0)
    bad("V has no vertices");
  if(n >= std::numeric_limits<std::uint32_t>::max())
    bad("V has too many vertices (at most 2^32 - 2)");
  dggvtp::Loaded_soup soup;
  soup.points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!std::isfinite(v.at(i, 0)) || !std::isfinite(v.at(i, 1)) || !std::isfinite(v.at(i, 2)))
      bad("vertex " + std::to_string(i) + " has a coordinate that is not finite");
    soup.points.emplace_back(v.at(i, 0), v.at(i, 1), v.at(i, 2));
  }
  soup.triangles.reserve(std::size_t(f.shape(0)));
  for(py::ssize_t t = 0; t < f.shape(0); ++t)
  {
    std::uint32_t corners[3];
    for(int k = 0; k < 3; ++k)
    {
      const std::int64_t i = f.at(t, k);
      if(i < 0 || std::uint64_t(i) >= n)
        bad("face " + std::to_string(t) + " refers to vertex " + std::to_string(i) + ", but the mesh has " +
            std::to_string(n) + " vertices");
      corners[k] = std::uint32_t(i);
      for(int j = 0; j < k; ++j)
        if(corners[j] == corners[k])
          bad("face " + std::to_string(t) + " uses vertex " + std::to_string(i) + " twice");
    }
    soup.triangles.push_back(dggvtp::as_surface_mesh_face(corners));
  }
  dggvtp::internal::number_file_vertices(soup);
  return soup;
}

py::tuple read_mesh(const py::object& path)
{
  const std::string file = py::str(py::module_::import("os").attr("fspath")(path));
  dggvtp::Loaded_soup soup;
  {
    py::gil_scoped_release unlocked;
    soup = dggvtp::load_soup(file);
    if(soup.polygons.empty())
      dggvtp::triangles_to_polygons(soup); // back to the file's corner order
    else
      dggvtp::internal::triangulate_soup(soup);
  }
  py::array_t<double> V({py::ssize_t(soup.file_vertices), py::ssize_t(3)});
  py::array_t<std::int64_t> F({py::ssize_t(soup.polygons.size()), py::ssize_t(3)});
  auto v = V.mutable_unchecked<2>();
  auto f = F.mutable_unchecked<2>();
  for(std::size_t i = 0; i < soup.file_vertices; ++i)
    for(int c = 0; c < 3; ++c)
      v(i, c) = soup.points[i][c];
  for(std::size_t t = 0; t < soup.polygons.size(); ++t)
    for(int k = 0; k < 3; ++k)
      f(t, k) = std::int64_t(soup.polygons[t][k]);
  return py::make_tuple(V, F);
}

} // namespace

#include "docstrings.h"

PYBIND11_MODULE(dggvtp, m)
{
  m.doc() = doc::module;
  py::register_exception<dggvtp::Input_error>(m, "InputError", PyExc_ValueError);
  m.attr("InputError").attr("__doc__") = doc::input_error;

  m.def("read_mesh", &read_mesh, "path"_a, doc::read_mesh);

  py::class_<Geodesic_solver>(m, "GeodesicSolver", doc::solver)
    .def(py::init([](const py::object& V, const py::object& F, const std::string& precision) {
           if(precision != "double" && precision != "float")
             bad("precision must be 'double' or 'float', not '" + precision + "'");
           dggvtp::Loaded_soup soup = soup_of_arrays(V, F);
           py::gil_scoped_release unlocked;
           return Geodesic_solver{dggvtp::python::make_soup_solver(std::move(soup), precision), precision};
         }),
         "V"_a, "F"_a, "precision"_a = "double", doc::init)
    .def_property_readonly("num_vertices", [](const Geodesic_solver& s) { return s.solver->number_of_vertices(); },
                           doc::num_vertices)
    .def_property_readonly("num_faces", [](const Geodesic_solver& s) { return s.solver->number_of_faces(); },
                           doc::num_faces)
    .def_readonly("precision", &Geodesic_solver::precision, doc::precision)
    .def_property_readonly("repairs", [](const Geodesic_solver& s) { return s.solver->repairs(); }, doc::repairs)
    .def(
      "distances",
      [](const Geodesic_solver& s, const py::object& sources, const py::object& points, double epsilon,
         double max_distance, long threads, bool return_labels) -> py::object {
        const Query q = s.query(sources, points, epsilon, max_distance, threads);
        const py::ssize_t n = py::ssize_t(s.solver->number_of_vertices());
        py::array_t<double> d(n);
        py::array_t<std::int64_t> labels(return_labels ? n : 0);
        double* out = d.mutable_data();
        long long* out_labels = return_labels ? reinterpret_cast<long long*>(labels.mutable_data()) : nullptr;
        {
          py::gil_scoped_release unlocked;
          s.solver->distances(q, out, out_labels);
        }
        if(return_labels)
          return py::make_tuple(d, labels);
        return std::move(d);
      },
      "sources"_a = py::none(), py::kw_only(), "points"_a = py::none(), "epsilon"_a = 0., "max_distance"_a = infinity,
      "threads"_a = 1, "return_labels"_a = false, doc::distances)
    .def(
      "distances_from_each",
      [](const Geodesic_solver& s, const py::object& sources, double epsilon, double max_distance, long threads) {
        Query q = s.query(sources, py::none(), epsilon, max_distance, threads, false);
        const py::ssize_t n = py::ssize_t(s.solver->number_of_vertices());
        py::array_t<double> rows({py::ssize_t(q.sources.size()), n});
        double* out = rows.mutable_data();
        {
          py::gil_scoped_release unlocked;
          s.solver->distances_from_each(q, out);
        }
        return rows;
      },
      "sources"_a, py::kw_only(), "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 1,
      doc::distances_from_each)
    .def(
      "target_distances",
      [](const Geodesic_solver& s, const py::object& sources, const py::object& points, const py::object& targets,
         const py::object& target_points, double epsilon, double max_distance, long threads) {
        Query q = s.query(sources, points, epsilon, max_distance, threads);
        q.targets = vertex_places(targets, "target", s.solver->number_of_vertices());
        for(const Place& p : point_places(target_points, "target_points"))
          q.targets.push_back(p);
        if(q.targets.empty())
          bad("no target given (targets or target_points)");
        std::vector<double> t;
        {
          py::gil_scoped_release unlocked;
          t = s.solver->target_distances(q);
        }
        return py::array_t<double>(py::ssize_t(t.size()), t.data());
      },
      "sources"_a = py::none(), py::kw_only(), "points"_a = py::none(), "targets"_a = py::none(),
      "target_points"_a = py::none(), "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 1,
      doc::target_distances)
    .def(
      "shortest_path",
      [](const Geodesic_solver& s, const py::object& sources, const py::object& points, const py::object& target,
         const py::object& target_point, double epsilon, double max_distance, long threads) {
        Query q = s.query(sources, points, epsilon, max_distance, threads);
        if(target.is_none() == target_point.is_none())
          bad("give one target: target (a vertex) or target_point (3 coordinates)");
        q.path_targets = target.is_none() ? point_places(target_point, "target_point")
                                          : vertex_places(target, "target", s.solver->number_of_vertices());
        if(q.path_targets.size() != 1)
          bad("give one target: target (a vertex) or target_point (3 coordinates)");
        dggvtp::Polyline line;
        {
          py::gil_scoped_release unlocked;
          line = s.solver->shortest_path(q);
        }
        py::array_t<double> path({py::ssize_t(line.size()), py::ssize_t(3)});
        auto p = path.mutable_unchecked<2>();
        for(std::size_t i = 0; i < line.size(); ++i)
          for(int c = 0; c < 3; ++c)
            p(i, c) = line[i][c];
        return path;
      },
      "sources"_a = py::none(), py::kw_only(), "points"_a = py::none(), "target"_a = py::none(),
      "target_point"_a = py::none(), "epsilon"_a = 0., "max_distance"_a = infinity, "threads"_a = 1,
      doc::shortest_path)
    .def("__repr__", [](const Geodesic_solver& s) {
      return "<dggvtp.GeodesicSolver: " + std::to_string(s.solver->number_of_vertices()) + " vertices, " +
             std::to_string(s.solver->number_of_faces()) + " faces, " + s.precision + ">";
    });
}
