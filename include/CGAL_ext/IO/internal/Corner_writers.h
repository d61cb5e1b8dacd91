// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The writers of meshes with texture coordinates or normals: OBJ with
// `vt`/`vn` and `f v/vt/vn` corners (a value per face corner), OFF and PLY
// with a value per vertex. Meshes without them go through CGAL's soup
// writers; these write the same points and faces, and the values beside.

#ifndef CGAL_EXT_IO_INTERNAL_CORNER_WRITERS_H
#define CGAL_EXT_IO_INTERNAL_CORNER_WRITERS_H

#include <CGAL_ext/IO/internal/Corner_data.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace IO {
namespace internal {

using Written_point = CGAL::Simple_cartesian<double>::Point_3;
using Written_polygons = std::vector<std::vector<std::size_t>>;

// The channels a writer takes beside the points and faces: each present or not.
struct Written_corner_data
{
  Written_channel<2> uv;
  Written_channel<3> normal;

  bool empty() const { return !uv.is_present() && !normal.is_present(); }
};

template <std::size_t N>
void write_values(std::ostream& out, const char* keyword, const std::vector<std::array<double, N>>& values)
{
  for (const std::array<double, N>& v : values) {
    out << keyword;
    for (double x : v)
      out << ' ' << x;
    out << '\n';
  }
}

// OBJ: each face corner as `v`, `v/vt`, `v//vn` or `v/vt/vn`, as it has
// values (a face may have corners with values and corners without, as the
// reader takes them).
inline void write_obj_with_corners(std::ostream& out, const std::vector<Written_point>& points,
                                   const Written_polygons& polygons, const Written_corner_data& data, int precision)
{
  out.precision(precision);
  out << "# " << points.size() << " vertices, " << polygons.size() << " faces\n";
  for (const Written_point& p : points)
    out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  write_values(out, "vt", data.uv.values);
  write_values(out, "vn", data.normal.values);
  std::size_t c = 0;
  for (const std::vector<std::size_t>& polygon : polygons) {
    out << 'f';
    for (std::size_t v : polygon) {
      const bool vt = data.uv.is_present() && data.uv.has_value(c);
      const bool vn = data.normal.is_present() && data.normal.has_value(c);
      out << ' ' << v + 1;
      if (vt || vn)
        out << '/';
      if (vt)
        out << data.uv.corner[c] + 1;
      if (vn)
        out << '/' << data.normal.corner[c] + 1;
      ++c;
    }
    out << '\n';
  }
}

// The values per vertex for OFF and PLY (a seam refused), each present or not.
struct Vertex_values
{
  std::vector<std::array<double, 2>> uv;
  std::vector<std::array<double, 3>> normal;
};

template <class P>
Vertex_values vertex_values(const Written_corner_data& data, const Mobius_mesh<P>& mesh, const std::string& filename,
                            const char* format)
{
  Vertex_values values;
  if (data.uv.is_present())
    values.uv = per_vertex_values(data.uv, mesh, filename, format);
  if (data.normal.is_present())
    values.normal = per_vertex_values(data.normal, mesh, filename, format);
  return values;
}

// OFF with Geomview's prefixes: `[ST][N]OFF`, each vertex `x y z [nx ny nz] [s t]`.
inline void write_off_with_values(std::ostream& out, const std::vector<Written_point>& points,
                                  const Written_polygons& polygons, const Vertex_values& values, int precision)
{
  const bool uv = !values.uv.empty(), normal = !values.normal.empty();
  out.precision(precision);
  out << (uv ? "ST" : "") << (normal ? "N" : "") << "OFF\n" << points.size() << ' ' << polygons.size() << " 0\n";
  for (std::size_t v = 0; v < points.size(); ++v) {
    out << points[v].x() << ' ' << points[v].y() << ' ' << points[v].z();
    if (normal)
      out << ' ' << values.normal[v][0] << ' ' << values.normal[v][1] << ' ' << values.normal[v][2];
    if (uv)
      out << ' ' << values.uv[v][0] << ' ' << values.uv[v][1];
    out << '\n';
  }
  for (const std::vector<std::size_t>& polygon : polygons) {
    out << polygon.size();
    for (std::size_t v : polygon)
      out << ' ' << v;
    out << '\n';
  }
}

// Little-endian bytes, whatever the machine's order.
template <class T, class Bits>
void put_little_endian(std::ostream& out, T value)
{
  Bits bits;
  static_assert(sizeof(Bits) == sizeof(T), "a value and its bits");
  std::memcpy(&bits, &value, sizeof bits);
  char bytes[sizeof(T)];
  for (std::size_t i = 0; i < sizeof(T); ++i)
    bytes[i] = char((bits >> (8 * i)) & 0xFF);
  out.write(bytes, sizeof bytes);
}

// PLY: the vertices' x y z, nx ny nz and s t as doubles, the faces' index lists.
inline void write_ply_with_values(std::ostream& out, const std::vector<Written_point>& points,
                                  const Written_polygons& polygons, const Vertex_values& values, bool binary,
                                  int precision)
{
  std::size_t largest_face = 0;
  for (const std::vector<std::size_t>& polygon : polygons)
    largest_face = (std::max)(largest_face, polygon.size());
  const bool byte_counts = largest_face <= 255;
  std::vector<const char*> names = {"x", "y", "z"};
  if (!values.normal.empty())
    names.insert(names.end(), {"nx", "ny", "nz"});
  if (!values.uv.empty())
    names.insert(names.end(), {"s", "t"});
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\ncomment written by CGAL_ext\n"
      << "element vertex " << points.size() << '\n';
  for (const char* name : names)
    out << "property double " << name << '\n';
  out << "element face " << polygons.size() << "\nproperty list " << (byte_counts ? "uchar" : "int")
      << " int vertex_indices\nend_header\n";
  out.precision(precision);
  for (std::size_t v = 0; v < points.size(); ++v) {
    std::vector<double> row = {points[v].x(), points[v].y(), points[v].z()};
    if (!values.normal.empty())
      row.insert(row.end(), values.normal[v].begin(), values.normal[v].end());
    if (!values.uv.empty())
      row.insert(row.end(), values.uv[v].begin(), values.uv[v].end());
    for (std::size_t k = 0; k < row.size(); ++k) {
      if (binary)
        put_little_endian<double, std::uint64_t>(out, row[k]);
      else
        out << (k ? " " : "") << row[k];
    }
    if (!binary)
      out << '\n';
  }
  for (const std::vector<std::size_t>& polygon : polygons) {
    if (!binary) {
      out << polygon.size();
      for (std::size_t v : polygon)
        out << ' ' << v;
      out << '\n';
      continue;
    }
    if (byte_counts)
      out.put(char(polygon.size()));
    else
      put_little_endian<std::int32_t, std::uint32_t>(out, std::int32_t(polygon.size()));
    for (std::size_t v : polygon)
      put_little_endian<std::int32_t, std::uint32_t>(out, std::int32_t(v));
  }
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_CORNER_WRITERS_H
