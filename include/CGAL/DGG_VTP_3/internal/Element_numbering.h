// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// All rights reserved.
//
// This file is part of DGG_VTP_3, a package written for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_ELEMENT_NUMBERING_H
#define CGAL_DGG_VTP_3_INTERNAL_ELEMENT_NUMBERING_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/for_each_block.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// How a solver's user names its vertices and faces, and their numbers in Unfolded_mesh's input
// (vertex i is the i-th vertex, face i the i-th face before the unfolding's reordering). What the
// two solvers differ by: Solver_core does everything else with these numbers, in the prepared
// mesh's order (Unfolded_numbering).
//
//   vertex_index(v) the number of v, or number_of_vertices() if v is not a vertex of the input
//   vertex(i)       the vertex of number i
//   face_index(f), face(i), number_of_faces(): the same for faces

// A graph's descriptors, numbered by its index maps.
template <class TriangleMesh, class VertexIndexMap, class FaceIndexMap>
class Mesh_numbering
{
public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  // `vim` and `fim` must be bijections onto [0, n) (unfold_triangle_mesh() checks it)
  Mesh_numbering(const TriangleMesh& tm, const VertexIndexMap& vim, const FaceIndexMap& fim)
    : m_vim(vim), m_fim(fim)
  {
    m_vertices.resize(static_cast<std::size_t>(num_vertices(tm)));
    for(vertex_descriptor v : vertices(tm))
      m_vertices[static_cast<std::size_t>(get(m_vim, v))] = v;
    m_faces.resize(static_cast<std::size_t>(num_faces(tm)));
    for(face_descriptor f : faces(tm))
      m_faces[static_cast<std::size_t>(get(m_fim, f))] = f;
  }

  std::size_t number_of_vertices() const { return m_vertices.size(); }
  std::size_t number_of_faces() const { return m_faces.size(); }
  std::size_t vertex_index(vertex_descriptor v) const { return checked(static_cast<std::size_t>(get(m_vim, v)), v, m_vertices); }
  std::size_t face_index(face_descriptor f) const { return checked(static_cast<std::size_t>(get(m_fim, f)), f, m_faces); }
  vertex_descriptor vertex(std::size_t i) const { return m_vertices[i]; }
  face_descriptor face(std::size_t i) const { return m_faces[i]; }

private:
  // an element of another mesh may have an index in range: it must be the element of that index
  template <class Descriptor>
  static std::size_t checked(std::size_t i, const Descriptor& d, const std::vector<Descriptor>& all)
  {
    return i < all.size() && all[i] == d ? i : all.size();
  }

  VertexIndexMap m_vim;                      // user's vertex -> number
  FaceIndexMap m_fim;                        // user's face -> number
  std::vector<vertex_descriptor> m_vertices; // number -> user's vertex
  std::vector<face_descriptor> m_faces;      // number -> user's face
};

// The points and triangles of a soup, named by their indices.
class Index_numbering
{
public:
  using vertex_descriptor = std::size_t;
  using face_descriptor = std::size_t;

  Index_numbering(std::size_t number_of_vertices, std::size_t number_of_faces)
    : m_number_of_vertices(number_of_vertices), m_number_of_faces(number_of_faces)
  {}

  std::size_t number_of_vertices() const { return m_number_of_vertices; }
  std::size_t number_of_faces() const { return m_number_of_faces; }
  std::size_t vertex_index(std::size_t v) const { return v < m_number_of_vertices ? v : m_number_of_vertices; }
  std::size_t face_index(std::size_t f) const { return f < m_number_of_faces ? f : m_number_of_faces; }
  static std::size_t vertex(std::size_t i) { return i; }
  static std::size_t face(std::size_t i) { return i; }

private:
  std::size_t m_number_of_vertices, m_number_of_faces;
};

// A user's numbering (`Numbering`) in the order of the prepared mesh: element i here is the user's
// element of number order.vertices[i] (order.faces[i]; see Unfolding_order). Solver_core works in
// this numbering; the user's numbers remain for messages and for what goes back in them.
template <class Numbering>
class Unfolded_numbering
{
public:
  using vertex_descriptor = typename Numbering::vertex_descriptor;
  using face_descriptor = typename Numbering::face_descriptor;

  template <class ConcurrencyTag>
  Unfolded_numbering(Numbering user, Unfolding_order order, ConcurrencyTag)
    : m_user(std::move(user)), m_order(std::move(order))
    , m_vertex(m_order.vertices.size()), m_face(m_order.faces.size())
  {
    for_each_block<ConcurrencyTag>(m_vertex.size(), [&](std::size_t i0, std::size_t i1) {
      for(std::size_t i = i0; i < i1; ++i)
        m_vertex[m_order.vertices[i]] = std::uint32_t(i);
    });
    for_each_block<ConcurrencyTag>(m_face.size(), [&](std::size_t i0, std::size_t i1) {
      for(std::size_t i = i0; i < i1; ++i)
        m_face[m_order.faces[i]] = std::uint32_t(i);
    });
  }

  std::size_t number_of_vertices() const { return m_vertex.size(); }
  std::size_t number_of_faces() const { return m_face.size(); }
  std::size_t vertex_index(vertex_descriptor v) const { return renumbered(m_user.vertex_index(v), m_vertex); }
  std::size_t face_index(face_descriptor f) const { return renumbered(m_user.face_index(f), m_face); }
  vertex_descriptor vertex(std::size_t i) const { return m_user.vertex(m_order.vertices[i]); }
  face_descriptor face(std::size_t i) const { return m_user.face(m_order.faces[i]); }

  // the user's number of vertex i, and the vertex of the user's number j
  std::size_t user_number(std::size_t i) const { return m_order.vertices[i]; }
  // the same, as arrays: per vertex its user's number, and per user's number its vertex
  const std::vector<std::uint32_t>& user_numbers() const { return m_order.vertices; }
  const std::vector<std::uint32_t>& vertices_of_user_numbers() const { return m_vertex; }
  vertex_descriptor user_vertex(std::size_t j) const { return m_user.vertex(j); }

private:
  static std::size_t renumbered(std::size_t j, const std::vector<std::uint32_t>& to)
  {
    return j < to.size() ? std::size_t(to[j]) : to.size();
  }

  Numbering m_user;
  Unfolding_order m_order;             // element of this numbering -> the user's number
  std::vector<std::uint32_t> m_vertex; // the user's number -> vertex of this numbering
  std::vector<std::uint32_t> m_face;   // likewise for faces
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_ELEMENT_NUMBERING_H
