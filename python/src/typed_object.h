// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Arguments and results that the module takes or gives as any Python object (array-likes, None,
// a path), named in the signatures of help() by the types they stand for: pybind11 names a
// py::object "object", which says nothing to a user or a type checker.

#ifndef DGGVTP_PYTHON_TYPED_OBJECT_H
#define DGGVTP_PYTHON_TYPED_OBJECT_H

#include <pybind11/pybind11.h>

namespace dggvtp {
namespace python {

namespace py = pybind11;

// A Python object, converted by the module's own code; `Name::name` is its type in signatures.
template <class Name>
struct Typed_object
{
  py::object object;
};

#define DGGVTP_PYTHON_TYPE_NAME(Type, text)                                                                      \
  struct Type                                                                                                    \
  {                                                                                                              \
    static constexpr auto name = py::detail::const_name(text);                                                  \
  }

DGGVTP_PYTHON_TYPE_NAME(Array_name, "numpy.typing.ArrayLike");
DGGVTP_PYTHON_TYPE_NAME(Vertices_name, "Union[int, numpy.typing.ArrayLike, None]");
DGGVTP_PYTHON_TYPE_NAME(Points_name, "Optional[numpy.typing.ArrayLike]");
DGGVTP_PYTHON_TYPE_NAME(Face_points_name, "Optional[Tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]]");
DGGVTP_PYTHON_TYPE_NAME(Path_name, "Union[str, os.PathLike]");
DGGVTP_PYTHON_TYPE_NAME(Field_name, "Union[numpy.ndarray[numpy.float64], "
                                    "Tuple[numpy.ndarray[numpy.float64], numpy.ndarray[numpy.int64]]]");
DGGVTP_PYTHON_TYPE_NAME(Sparse_name, "scipy.sparse.csr_matrix");
DGGVTP_PYTHON_TYPE_NAME(Optional_array_name, "Optional[numpy.typing.ArrayLike]");
DGGVTP_PYTHON_TYPE_NAME(Precision_name, "Literal['double', 'float']");

#undef DGGVTP_PYTHON_TYPE_NAME

using Array_like = Typed_object<Array_name>;         // V, F
using Vertices = Typed_object<Vertices_name>;        // an index, a sequence of them, or None
using Points = Typed_object<Points_name>;            // (k, 3) or (3,) 3D points, or None
using Face_points = Typed_object<Face_points_name>;  // (faces (k,), barycentric (k, 3)), or None
using Path = Typed_object<Path_name>;                // a file name
using Field = Typed_object<Field_name>;              // distances, or (distances, labels)
using Sparse_matrix = Typed_object<Sparse_name>;
using Optional_array = Typed_object<Optional_array_name>; // one value per vertex, or None
using Precision = Typed_object<Precision_name>;           // 'double' or 'float'


} // namespace python
} // namespace dggvtp

namespace pybind11 {
namespace detail {

template <class Name>
struct type_caster<dggvtp::python::Typed_object<Name>>
{
  PYBIND11_TYPE_CASTER(dggvtp::python::Typed_object<Name>, Name::name);

  bool load(handle source, bool)
  {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const dggvtp::python::Typed_object<Name>& typed, return_value_policy, handle)
  {
    return typed.object.inc_ref();
  }
};

} // namespace detail
} // namespace pybind11

#endif // DGGVTP_PYTHON_TYPED_OBJECT_H
