// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The module's arguments checked and converted, with the GIL held: NumPy's conventions (any
// array-like in), a ValueError that says what to do for anything else.

#ifndef DGGVTP_PYTHON_ARGUMENTS_H
#define DGGVTP_PYTHON_ARGUMENTS_H

#include "typed_object.h"

#include <dggvtp/load_mesh.h>
#include <dggvtp/query_places.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace dggvtp {
namespace python {

using namespace pybind11::literals;

[[noreturn]] inline void bad(const std::string& message) { throw py::value_error(message); }

// `object` as a NumPy array of `dtype`, refusing other kinds of numbers than `kinds` (a silent
// conversion of floats to indices, or of strings to numbers, would hide a mistake)
inline py::array as_array(const py::handle& object, const std::string& name, const char* kinds, const char* dtype)
{
  py::object a;
  try
  {
    a = py::module_::import("numpy").attr("asarray")(object);
  }
  catch(const py::error_already_set& e)
  {
    bad(name + " is not an array of numbers: " + e.what());
  }
  std::string kind = py::str(a.attr("dtype").attr("kind"));
  if(py::int_(a.attr("size")).cast<std::size_t>() == 0) // [] is float64 for NumPy
    kind = "i";
  if(kind.empty() || std::string(kinds).find(kind) == std::string::npos)
    bad(name + " must hold " + (std::string(kinds) == "iu" ? "integers" : "real numbers") + ", not " +
        std::string(py::str(a.attr("dtype"))));
  return py::array(a.attr("astype")(dtype, "copy"_a = false));
}

template <class T>
using C_array = py::array_t<T, py::array::c_style | py::array::forcecast>;

// an (m, 3) array, or (3,) for one row when `one_row` is allowed
template <class T>
C_array<T> rows_of_3(const py::handle& object, const std::string& name, const char* kinds, const char* dtype,
                     bool one_row)
{
  py::array a = as_array(object, name, kinds, dtype);
  if(one_row && a.ndim() == 1 && a.shape(0) == 3)
    a = a.attr("reshape")(1, 3);
  if(a.ndim() != 2 || a.shape(1) != 3)
    bad(name + " must have shape (" + (one_row ? "k" : "n") + ", 3), not " + std::string(py::str(a.attr("shape"))));
  return C_array<T>::ensure(a);
}

// indices of vertices (of V) or faces (of F): an int or a sequence of them, each in [0, count)
inline C_array<std::int64_t> indices(const py::handle& object, const std::string& name, std::size_t count,
                                     bool of_faces)
{
  const py::array a = as_array(object, name, "iu", "int64");
  if(a.ndim() > 1)
    bad(name + " must be a " + (of_faces ? "face" : "vertex") + " index or a sequence of them, not an array of shape " +
        std::string(py::str(a.attr("shape"))));
  const auto v = C_array<std::int64_t>::ensure(a.attr("reshape")(-1));
  for(py::ssize_t i = 0; i < v.size(); ++i)
    if(v.at(i) < 0 || std::uint64_t(v.at(i)) >= count)
      bad(name + " " + std::to_string(v.at(i)) + " is out of range (" +
          (of_faces ? "F has " + std::to_string(count) + " faces" : "the mesh has " + std::to_string(count) + " vertices") +
          ")");
  return v;
}

// vertices given as an int, a sequence of ints or None (none), checked against the mesh
inline std::vector<Place> vertex_places(const Vertices& vertices, const std::string& name, std::size_t count)
{
  std::vector<Place> places;
  if(vertices.object.is_none())
    return places;
  const auto v = indices(vertices.object, name, count, false);
  places.resize(std::size_t(v.size()));
  for(std::size_t i = 0; i < places.size(); ++i)
    places[i].vertex = std::size_t(v.at(py::ssize_t(i)));
  return places;
}

// one value per vertex, an array-like of shape (count,) converted to `dtype`; None: none
template <class T>
std::optional<C_array<T>> per_vertex(const Optional_array& values, const std::string& name, std::size_t count,
                                     const char* kinds, const char* dtype)
{
  if(values.object.is_none())
    return std::nullopt;
  const py::array a = as_array(values.object, name, kinds, dtype);
  if(a.ndim() != 1 || std::size_t(a.shape(0)) != count)
    bad(name + " must have shape (num_vertices,) = (" + std::to_string(count) + ",), not " +
        std::string(py::str(a.attr("shape"))));
  return C_array<T>::ensure(a);
}

// the precision argument: "double" or "float"
inline std::string precision_of(const Precision& precision)
{
  if(!py::isinstance<py::str>(precision.object))
    throw py::type_error("precision must be a str, 'double' or 'float', not " +
                         std::string(py::str(py::type::of(precision.object).attr("__name__"))));
  const std::string p = py::str(precision.object);
  if(p != "double" && p != "float")
    bad("precision must be 'double' or 'float', not '" + p + "'");
  return p;
}

// 3D points as a (k, 3) or (3,) array-like, or None (none); located on the surface later
inline std::vector<Place> point_places(const Points& points, const std::string& name)
{
  std::vector<Place> places;
  if(points.object.is_none())
    return places;
  const auto a = rows_of_3<double>(points.object, name, "iuf", "float64", true);
  for(py::ssize_t i = 0; i < a.shape(0); ++i)
  {
    Place p;
    p.is_point = true;
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(p.point[c] = a.at(i, c)))
        bad(name + " needs finite coordinates (row " + std::to_string(i) + ")");
    places.push_back(p);
  }
  return places;
}

// Points on faces as (faces, barycentric): an int or an array (k,) of faces of F, and (3,) or
// (k, 3) barycentric coordinates of their corners in F's order; or None (none). The places hold
// F's face in `triangle` until the solver puts its own there.
inline std::vector<Place> face_point_places(const Face_points& face_points, const std::string& name,
                                            std::size_t faces)
{
  std::vector<Place> places;
  if(face_points.object.is_none())
    return places;
  if(!py::isinstance<py::sequence>(face_points.object) || py::isinstance<py::str>(face_points.object) ||
     py::len(face_points.object) != 2)
    bad(name + " must be a pair (faces, barycentric): face indices (k,) and their barycentric coordinates (k, 3)");
  const py::sequence pair = face_points.object;
  const auto f = indices(pair[0], name + " face", faces, true);
  const auto b = rows_of_3<double>(pair[1], name + " barycentric coordinates", "iuf", "float64", true);
  if(b.shape(0) != f.size())
    bad(name + " gives " + std::to_string(f.size()) + " faces and " + std::to_string(b.shape(0)) +
        " rows of barycentric coordinates: give one row per face");
  // the library's tolerance (rounding, as PMP::locate() leaves it), said here with the row
  const double tolerance = 1e-12;
  for(py::ssize_t i = 0; i < f.size(); ++i)
  {
    Place p;
    p.is_face_point = true;
    p.triangle = std::size_t(f.at(i));
    double sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      p.barycentric[k] = b.at(i, k);
      if(!std::isfinite(p.barycentric[k]) || p.barycentric[k] < -tolerance)
        bad(name + " barycentric coordinates must be finite and not negative (row " + std::to_string(i) + ")");
      sum += p.barycentric[k];
    }
    if(!(std::abs(sum - 1.) <= tolerance))
      bad(name + " barycentric coordinates must add up to 1 (row " + std::to_string(i) + " adds up to " +
          std::to_string(sum) + ")");
    places.push_back(p);
  }
  return places;
}

// The soup of the arrays V, F: the soup of the same vertices and triangles as dggvtp's loader
// makes of a file (the corners in a Surface_mesh face's order), refusing what its readers refuse.
// V may be (n, 2): z = 0. With `repair` on, the faces that repeat a vertex are left out (as
// --repair does). F goes to `faces` as it is (points on faces are given on F's faces).
inline Loaded_soup soup_of_arrays(const Array_like& V_, const Array_like& F_, const Repair_option& repair,
                                  std::vector<std::array<std::uint32_t, 3>>& faces)
{
  py::array V = as_array(V_.object, "V", "iuf", "float64");
  if(V.ndim() == 2 && V.shape(1) == 2) // in the plane z = 0, as libigl takes it
    V = py::module_::import("numpy").attr("pad")(V, py::make_tuple(py::make_tuple(0, 0), py::make_tuple(0, 1)));
  if(V.ndim() != 2 || (V.shape(1) != 3))
    bad("V must have shape (n, 3), or (n, 2) for points of the plane z = 0, not " +
        std::string(py::str(V.attr("shape"))));
  const auto v = C_array<double>::ensure(V);
  const auto f = rows_of_3<std::int64_t>(F_.object, "F", "iu", "int64", false);
  const std::size_t n = std::size_t(v.shape(0));
  if(n == 0)
    bad("V has no vertices");
  if(n >= std::numeric_limits<std::uint32_t>::max())
    bad("V has too many vertices (at most 2^32 - 2)");
  Loaded_soup soup;
  soup.points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!std::isfinite(v.at(i, 0)) || !std::isfinite(v.at(i, 1)) || !std::isfinite(v.at(i, 2)))
      bad("vertex " + std::to_string(i) + " has a coordinate that is not finite");
    soup.points.emplace_back(v.at(i, 0), v.at(i, 1), v.at(i, 2));
  }
  faces.resize(std::size_t(f.shape(0)));
  std::vector<char> repeats(faces.size(), 0);
  for(std::size_t t = 0; t < faces.size(); ++t)
    for(int k = 0; k < 3; ++k)
    {
      const std::int64_t i = f.at(t, k);
      if(i < 0 || std::uint64_t(i) >= n)
        bad("face " + std::to_string(t) + " refers to vertex " + std::to_string(i) + ", but the mesh has " +
            std::to_string(n) + " vertices");
      faces[t][k] = std::uint32_t(i);
      for(int j = 0; j < k; ++j)
        if(faces[t][j] == faces[t][k] && !repair.on)
          bad("face " + std::to_string(t) + " uses vertex " + std::to_string(i) + " twice; " + repair.name +
              " drops such faces");
        else if(faces[t][j] == faces[t][k])
          repeats[t] = 1;
    }
  std::vector<std::array<std::uint32_t, 3>> kept = faces;
  internal::drop_faces(kept, repeats, repair, soup.repairs);
  soup.triangles.reserve(kept.size());
  for(const auto& corners : kept)
    soup.triangles.push_back(as_surface_mesh_face(corners));
  internal::number_file_vertices(soup);
  return soup;
}

} // namespace python
} // namespace dggvtp

#endif // DGGVTP_PYTHON_ARGUMENTS_H
