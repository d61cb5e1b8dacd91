// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The writers of meshes with texture coordinates or normals: OBJ with
// `vt`/`vn` and `f v/vt/vn` corners (a value per face corner), OFF and PLY
// with a value per vertex (PLY through PLY_writer.h). Meshes without them go
// through CGAL's soup writers; these write the same points and faces, and the
// values beside.

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

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_CORNER_WRITERS_H
