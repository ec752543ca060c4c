// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// A distance field on its mesh, in files that viewers open: binary PLY (MeshLab colours a mesh
// by the vertex `quality`; ParaView reads the other properties) and legacy VTK polydata (ParaView).

#ifndef DGGVTP_FIELD_FILES_H
#define DGGVTP_FIELD_FILES_H

#include <dggvtp/load_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace dggvtp {

// The format of the --output file: the one --output-format names, or else its extension's.
inline std::string output_format_of(const std::string& path, const std::string& format_option)
{
  if(!format_option.empty())
    return format_option;
  const std::string extension = internal::lower_case_extension(path);
  return extension == "ply" || extension == "vtk" || extension == "npy" ? extension : "text";
}

// The mesh of a file, as the fields are written on it: its points in the file's order, and its
// faces as read (polygons are kept, orientations are the file's; with --repair, without the faces
// that repeat a vertex, as loading leaves them out). Kept while the solver runs, so in flat
// arrays: 12 bytes a triangle.
struct File_mesh
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::uint32_t> corners;  // the faces' vertices, face after face
  std::vector<std::size_t> face_start; // face f: corners [face_start[f], face_start[f + 1]); empty: all triangles

  std::size_t number_of_faces() const { return face_start.empty() ? corners.size() / 3 : face_start.size() - 1; }
  std::size_t face_size(std::size_t f) const { return face_start.empty() ? 3 : face_start[f + 1] - face_start[f]; }
  const std::uint32_t* face(std::size_t f) const { return corners.data() + (face_start.empty() ? 3 * f : face_start[f]); }
};

// The file mesh of a soup as loading gives it, before the repairs and the solver change it.
inline File_mesh file_mesh_of(const Loaded_soup& soup)
{
  File_mesh mesh;
  mesh.points.reserve(soup.file_vertices);
  for(std::size_t i = 0; i < soup.file_vertices; ++i)
    mesh.points.push_back({soup.points[i].x(), soup.points[i].y(), soup.points[i].z()});
  const auto file_vertex = [&](std::size_t v) { return std::uint32_t(soup.file_vertex_of[v]); };
  mesh.corners.reserve(3 * soup.triangles.size());
  for(const auto& t : soup.triangles)
    for(std::uint32_t v : t)
      mesh.corners.push_back(file_vertex(v));
  if(!soup.polygons.empty())
  {
    mesh.face_start.reserve(soup.triangles.size() + soup.polygons.size() + 1);
    for(std::size_t f = 0; f <= soup.triangles.size(); ++f)
      mesh.face_start.push_back(3 * f);
    for(const auto& polygon : soup.polygons)
    {
      for(std::size_t v : polygon)
        mesh.corners.push_back(file_vertex(v));
      mesh.face_start.push_back(mesh.corners.size());
    }
  }
  return mesh;
}

namespace internal {

// Bytes in a chosen order, whatever the machine's, written to a FILE in blocks of 1 MB. Write
// errors show in the FILE's error flag, which the caller checks when closing it.
class Byte_writer
{
public:
  Byte_writer(std::FILE* file, bool big_endian) : m_file(file), m_big_endian(big_endian) {}
  Byte_writer(const Byte_writer&) = delete;
  Byte_writer& operator=(const Byte_writer&) = delete;
  ~Byte_writer() { flush(); }

  void text(const std::string& s)
  {
    for(char c : s)
      put_byte(c);
  }
  template <class T>
  void value(T x)
  {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &x, sizeof(T));
    const bool little_endian_machine = is_little_endian();
    for(std::size_t i = 0; i < sizeof(T); ++i)
      put_byte(char(bytes[m_big_endian == little_endian_machine ? sizeof(T) - 1 - i : i]));
  }
  void flush()
  {
    if(!m_block.empty())
      std::fwrite(m_block.data(), 1, m_block.size(), m_file);
    m_block.clear();
  }

private:
  static bool is_little_endian()
  {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }
  void put_byte(char c)
  {
    m_block.push_back(c);
    if(m_block.size() >= (1u << 20))
      flush();
  }
  std::FILE* m_file;
  bool m_big_endian;
  std::vector<char> m_block;
};

inline void check_field_sizes(const File_mesh& mesh, const std::vector<double>& distances,
                              const std::vector<long long>* labels)
{
  if(distances.size() != mesh.points.size() || (labels && labels->size() != mesh.points.size()))
    throw std::logic_error("a field file needs one distance and label per vertex of the file");
}

inline std::string header_comment(const std::string& mesh_name, const std::string& field)
{
  std::string name = mesh_name;
  std::replace(name.begin(), name.end(), '\n', ' ');
  return "dggvtp geodesic " + std::string(field == "distance" ? "distances" : "distance error bounds") + " on " + name;
}

} // namespace internal

// Binary little-endian PLY: vertex x y z (float), `float quality` (the distance; where it is
// infinite, the largest finite distance, so that a viewer's colour scale spans the reached part),
// `double distance` (inf where unreached; or the property `field` so named), `int label` when
// labels are given; faces as `list uchar int vertex_indices`. Throws Input_error for a face of
// more than 255 vertices.
inline void write_ply_field(std::FILE* file, const std::string& mesh_name, const File_mesh& mesh,
                            const std::vector<double>& distances, const std::vector<long long>* labels,
                            const std::string& field = "distance")
{
  internal::check_field_sizes(mesh, distances, labels);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    if(mesh.face_size(f) > 255)
      throw Input_error("a face of more than 255 vertices does not fit a PLY face list of uchar size");
  float largest = 0.f;
  for(double d : distances)
    if(std::isfinite(d))
      largest = (std::max)(largest, float(d));
  internal::Byte_writer out(file, false);
  out.text("ply\nformat binary_little_endian 1.0\ncomment " + internal::header_comment(mesh_name, field) +
           "\nelement vertex " + std::to_string(mesh.points.size()) +
           "\nproperty float x\nproperty float y\nproperty float z\nproperty float quality\nproperty double " + field + "\n" +
           (labels ? "property int label\n" : "") + "element face " + std::to_string(mesh.number_of_faces()) +
           "\nproperty list uchar int vertex_indices\nend_header\n");
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    for(double c : mesh.points[v])
      out.value(float(c));
    out.value(std::isfinite(distances[v]) ? float(distances[v]) : largest);
    out.value(distances[v]);
    if(labels)
      out.value(std::int32_t((*labels)[v]));
  }
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    out.value(std::uint8_t(mesh.face_size(f)));
    for(std::size_t k = 0; k < mesh.face_size(f); ++k)
      out.value(std::int32_t(mesh.face(f)[k]));
  }
}

// Legacy VTK polydata, binary (big-endian, as the format requires): POINTS (double), POLYGONS,
// POINT_DATA with the scalars `distance` (double, inf where unreached; or named `field`) and
// `label` (int) when labels are given.
inline void write_vtk_field(std::FILE* file, const std::string& mesh_name, const File_mesh& mesh,
                            const std::vector<double>& distances, const std::vector<long long>* labels,
                            const std::string& field = "distance")
{
  internal::check_field_sizes(mesh, distances, labels);
  const std::size_t list_size = mesh.number_of_faces() + mesh.corners.size();
  if(list_size > std::size_t((std::numeric_limits<std::int32_t>::max)()))
    throw Input_error("the mesh has too many faces for a legacy VTK file");
  internal::Byte_writer out(file, true);
  out.text("# vtk DataFile Version 3.0\n" + internal::header_comment(mesh_name, field).substr(0, 200) +
           "\nBINARY\nDATASET POLYDATA\nPOINTS " + std::to_string(mesh.points.size()) + " double\n");
  for(const auto& p : mesh.points)
    for(double c : p)
      out.value(c);
  out.text("\nPOLYGONS " + std::to_string(mesh.number_of_faces()) + " " + std::to_string(list_size) + "\n");
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    out.value(std::int32_t(mesh.face_size(f)));
    for(std::size_t k = 0; k < mesh.face_size(f); ++k)
      out.value(std::int32_t(mesh.face(f)[k]));
  }
  out.text("\nPOINT_DATA " + std::to_string(mesh.points.size()) + "\nSCALARS " + field + " double 1\nLOOKUP_TABLE default\n");
  for(double d : distances)
    out.value(d);
  if(labels)
  {
    out.text("\nSCALARS label int 1\nLOOKUP_TABLE default\n");
    for(long long label : *labels)
      out.value(std::int32_t(label));
  }
  out.text("\n");
}

} // namespace dggvtp

#endif // DGGVTP_FIELD_FILES_H
