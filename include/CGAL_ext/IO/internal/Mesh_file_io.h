// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/IO/polygon_mesh_io.h>: the format a file name names,
// the OpenSubdiv tags and PLY vertex columns read and written, and the reading
// of a file without the translation of foreign exceptions.

#ifndef CGAL_EXT_IO_INTERNAL_MESH_FILE_IO_H
#define CGAL_EXT_IO_INTERNAL_MESH_FILE_IO_H

#include <CGAL_ext/IO/internal/Atomic_output_file.h>
#include <CGAL_ext/IO/internal/Corner_data.h>
#include <CGAL_ext/IO/internal/Corner_writers.h>
#include <CGAL_ext/IO/internal/OBJ_reader.h>
#include <CGAL_ext/IO/internal/OFF_reader.h>
#include <CGAL_ext/IO/internal/PLY_reader.h>
#include <CGAL_ext/IO/internal/PLY_writer.h>
#include <CGAL_ext/IO/internal/Text_scanning.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Join_classes.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/exceptions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace IO {
namespace internal {

enum class Mesh_format { obj, off, ply };

inline std::string lower_extension(const std::string& filename)
{
  const std::string name = std::filesystem::path(filename).filename().string();
  const std::string::size_type dot = name.rfind('.');
  if (dot == std::string::npos)
    return std::string();
  std::string ext = name.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

inline Mesh_format format_of(const std::string& filename)
{
  const std::string ext = lower_extension(filename);
  if (ext == "obj")
    return Mesh_format::obj;
  if (ext == "off")
    return Mesh_format::off;
  if (ext == "ply")
    return Mesh_format::ply;
  throw IO_error(filename, 0,
                 (ext.empty() ? std::string("the file name has no extension")
                              : "unknown file extension '." + ext + "'") +
                   "; expected .obj, .off or .ply");
}

// The shortest decimal text that reads back as the same float, without an
// exponent for everyday magnitudes (10, not 1e+01).
inline std::string float_text(float s)
{
  const bool plain = s == 0 || (std::abs(s) >= 1e-4f && std::abs(s) < 1e6f);
  char buffer[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, double(s));
    if (std::strtof(buffer, nullptr) == s && (!plain || std::strchr(buffer, 'e') == nullptr))
      break;
  }
  return buffer;
}

// Tags name the vertices as written (`joins`: the copies of a joined
// vertex are one, and an edge or vertex of several copies is tagged once).
template <class P, class Sharpness>
void write_crease_tags(std::ostream& out, const Mobius_mesh<P>& mesh, const Sharpness& sharpness,
                       const CGAL_ext::internal::Join_classes& joins, const std::vector<std::uint32_t>& index)
{
  for (Edge_index e : mesh.edges()) {
    const float s = sharpness(e);
    if (s != 0 && joins.edge_representative(e.idx()) == e.idx())
      out << "t crease 2/1/0 " << index[mesh.vertex(e, 0).idx()] << ' ' << index[mesh.vertex(e, 1).idx()] << ' '
          << float_text(s) << '\n';
  }
}

template <class P, class Sharpness>
void write_corner_tags(std::ostream& out, const Mobius_mesh<P>& mesh, const Sharpness& sharpness,
                       const CGAL_ext::internal::Join_classes& joins, const std::vector<std::uint32_t>& index)
{
  for (Vertex_index v : mesh.vertices()) {
    const float s = sharpness(v);
    if (s != 0 && joins.representative(v.idx()) == v.idx())
      out << "t corner 1/1/0 " << index[v.idx()] << ' ' << float_text(s) << '\n';
  }
}

// The rows of the vertices that hold their own index in the join map: a
// joined vertex is written once. Its copies must agree (`what` names the
// data where they do not: a value no file of one vertex holds).
template <class T>
void keep_joined_rows(std::vector<T>& rows, const CGAL_ext::internal::Join_classes& joins, const std::string& filename,
                      const std::string& what)
{
  if (rows.empty())
    return;
  std::vector<T> kept;
  for (std::uint32_t v = 0; v < std::uint32_t(rows.size()); ++v) {
    const std::uint32_t r = joins.representative(v);
    if (!(rows[v] == rows[r]))
      throw IO_error(filename, 0, "vertices " + std::to_string(r) + " and " + std::to_string(v) +
                                    " are one vertex of the input (non-manifold joins) but have different " + what +
                                    "; nothing was written");
    if (r == v)
      kept.push_back(rows[v]);
  }
  rows = std::move(kept);
}

// The points as the files hold them: doubles, each finite (written, a NaN
// or an infinity makes a file that no reader takes back).
template <class P>
std::vector<Written_point> written_points(const Mobius_mesh<P>& mesh, const std::string& filename)
{
  std::vector<Written_point> points;
  points.reserve(mesh.number_of_vertices());
  for (Vertex_index v : mesh.vertices()) {
    const P& p = mesh.point(v);
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    const Written_point& q = points.back();
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()))
      throw IO_error(filename, 0,
                     "vertex " + std::to_string(v.idx()) + " has a coordinate that is not a finite double; "
                     "nothing was written");
  }
  return points;
}

// The corner channels as the file will hold them, checked before the file
// is created: OBJ holds "c:uv" and "c:normal" per face corner; PLY holds
// them per vertex and OFF the normals per vertex, where a channel has no
// seam. Anything else is refused (IO_error), so that nothing is dropped.
template <class P>
Written_corner_data checked_corner_data(const Mobius_mesh<P>& mesh, const std::string& filename, Mesh_format format,
                                        Vertex_values& vertex_values)
{
  const char* format_name = format == Mesh_format::obj ? "OBJ" : format == Mesh_format::off ? "OFF" : "PLY";
  refuse_unwritten_channels(mesh, filename, format_name);
  Written_corner_data corners;
  corners.uv = written_channel<2>(mesh, corner_uv_name, filename);
  corners.normal = written_channel<3>(mesh, corner_normal_name, filename);
  if (format == Mesh_format::obj || corners.empty())
    return corners;
  // CGAL's OFF reader (5.5) reads past the line of a vertex with texture
  // coordinates unless the header also announces colours: OFF files get no
  // texture coordinates, so that every reader takes them.
  if (format == Mesh_format::off && corners.uv.is_present())
    throw IO_error(filename, 0,
                   "the mesh has texture coordinates (\"" + std::string(corner_uv_name) +
                     "\"), which OFF files are not written with (readers differ on STOFF): write OBJ (a value per "
                     "face corner) or PLY (a value per vertex); nothing was written");
  vertex_values = internal::vertex_values(corners, mesh, filename, format_name);
  return corners;
}

// The PLY vertex properties after x, y and z: the corner channels' values
// per vertex (nx ny nz, s t) where the mesh has them, then the vertex maps
// "v:NAME" (see ply_vertex_columns()). A map of the name of a written corner
// property is refused (IO_error) rather than written twice or dropped.
template <class P>
std::vector<Ply_vertex_column> ply_columns(const Mobius_mesh<P>& mesh, const Vertex_values& values,
                                           const std::string& filename)
{
  std::vector<Ply_vertex_column> columns;
  const std::vector<std::string> maps = mesh.template properties<Vertex_index>();
  const auto add = [&](const char* name, const std::string& channel, const auto& per_vertex, std::size_t k) {
    if (std::find(maps.begin(), maps.end(), "v:" + std::string(name)) != maps.end())
      throw IO_error(filename, 0,
                     "the mesh has both the corner channel \"" + channel + "\" and the vertex map \"v:" + name +
                       "\", which PLY files would both hold as the vertex property '" + name +
                       "': remove or rename one; nothing was written");
    Ply_vertex_column column{name, Ply_type::float64, {}};
    column.values.reserve(per_vertex.size());
    for (const auto& v : per_vertex)
      column.values.push_back(v[k]);
    columns.push_back(std::move(column));
  };
  if (!values.normal.empty())
    for (std::size_t k = 0; k < 3; ++k)
      add(k == 0 ? "nx" : k == 1 ? "ny" : "nz", corner_normal_name, values.normal, k);
  if (!values.uv.empty())
    for (std::size_t k = 0; k < 2; ++k)
      add(k == 0 ? "s" : "t", corner_uv_name, values.uv, k);
  std::vector<Ply_vertex_column> vertex_maps = ply_vertex_columns(mesh);
  columns.insert(columns.end(), std::make_move_iterator(vertex_maps.begin()), std::make_move_iterator(vertex_maps.end()));
  return columns;
}

// OpenSubdiv's tags (vertex indices in tags count from 0): sharpness where it
// is not 0, and the options that are set.
template <class P, class NP>
void write_obj_tags(std::ostream& out, const Mobius_mesh<P>& mesh, const NP& np, const Sharp_feature_options& options,
                    const CGAL_ext::internal::Join_classes& joins, const std::vector<std::uint32_t>& index)
{
  write_crease_tags(out, mesh, CGAL_ext::internal::edge_sharpness_of(mesh, np), joins, index);
  write_corner_tags(out, mesh, CGAL_ext::internal::vertex_sharpness_of(mesh, np), joins, index);
  if (options.boundary_interpolation) {
    const int k = *options.boundary_interpolation == Boundary_interpolation::none              ? 0
                  : *options.boundary_interpolation == Boundary_interpolation::edge_and_corner ? 1
                                                                                                : 2;
    out << "t interpolateboundary 1/0/0 " << k << '\n';
  }
  if (options.crease_method)
    out << "t creasemethod 0/0/1 " << (*options.crease_method == Crease_method::chaikin ? "chaikin" : "uniform")
        << '\n';
  if (options.triangle_subdivision)
    out << "t smoothtriangles 0/0/1 "
        << (*options.triangle_subdivision == Triangle_subdivision::smooth ? "smooth" : "catmark") << '\n';
}

template <class T, class P>
void add_vertex_column(Mobius_mesh<P>& mesh, const Ply_vertex_column& column)
{
  auto [map, created] = mesh.template add_property_map<Vertex_index, T>("v:" + column.name);
  if (!created)
    return; // a map of the mesh's own (the points) or of the same name
  for (Vertex_index v : mesh.vertices())
    map[v] = T(column.values[v.idx()]);
}

// The PLY file's other vertex properties as vertex property maps "v:NAME" of
// the file's types, as CGAL's Surface_mesh reader makes them. Only where
// vertex i of the mesh is point i of the file: nothing was merged or split.
template <class P>
void add_vertex_columns(Mobius_mesh<P>& mesh, const std::vector<Ply_vertex_column>& columns)
{
  for (const Ply_vertex_column& c : columns) {
    if (c.values.size() != mesh.number_of_vertices())
      continue;
    switch (c.type) {
    case Ply_type::int8: add_vertex_column<std::int8_t>(mesh, c); break;
    case Ply_type::uint8: add_vertex_column<std::uint8_t>(mesh, c); break;
    case Ply_type::int16: add_vertex_column<std::int16_t>(mesh, c); break;
    case Ply_type::uint16: add_vertex_column<std::uint16_t>(mesh, c); break;
    case Ply_type::int32: add_vertex_column<std::int32_t>(mesh, c); break;
    case Ply_type::uint32: add_vertex_column<std::uint32_t>(mesh, c); break;
    case Ply_type::float32: {
      // An ASCII value beyond a float's range (1e300 for a float property)
      // becomes an infinity, as a conversion from text to float makes it.
      Ply_vertex_column clamped = c;
      for (double& x : clamped.values)
        if (std::isfinite(x) && std::abs(x) > double(std::numeric_limits<float>::max()))
          x = x > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
      add_vertex_column<float>(mesh, clamped);
      break;
    }
    case Ply_type::float64: add_vertex_column<double>(mesh, c); break;
    }
  }
}

// read_polygon_mesh() without its translation of foreign exceptions.
template <class P, class NP>
Sharp_feature_options read_polygon_mesh(const std::string& filename, Mesh_format format, Mobius_mesh<P>& mesh,
                                        const NP& np)
{
  const std::string text = read_whole_file(filename);
  std::vector<P> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<Ply_vertex_column> columns;
  Obj_scan obj;
  if (format == Mesh_format::obj)
    obj = read_obj_text(filename, text, points, polygons);
  else if (format == Mesh_format::off)
    obj.lines = read_off(filename, text, points, polygons, obj.corner_data);
  else
    obj.lines = read_ply(filename, text, points, polygons, obj.corner_data, &columns);
  if (polygons.empty())
    throw IO_error(filename, 0, "the file has no faces");

  // The corners' values and the tags' vertices are read off the mesh as
  // built, face p on polygon p; orientation then moves the values with
  // their vertices.
  using Tolerance = std::decay_t<decltype(parameters::get_parameter(np, CGAL_ext::internal_np::tolerance))>;
  constexpr bool merged = !std::is_same_v<Tolerance, CGAL::internal_np::Param_not_found>;
  std::vector<std::vector<Vertex_index>> images;
  Mobius_mesh<P> result;
  std::size_t split = 0;
  try {
    split = CGAL_ext::internal::soup_to_mobius_mesh(points, polygons, result, np, [&](Mobius_mesh<P>& built) {
      add_read_channels(obj.corner_data, polygons, built);
      if (!obj.creases.empty() || !obj.corners.empty())
        images = soup_point_images(polygons, points.size(), merged, built);
    });
  } catch (const Soup_error& e) {
    throw_soup_error_in_file(e, filename, obj.lines);
  }
  if (!merged && split == 0 && result.number_of_vertices() == points.size())
    add_vertex_columns(result, columns);
  if (!images.empty())
    apply_obj_tags(obj, filename, images, result);
  mesh = std::move(result);
  return obj.options;
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_MESH_FILE_IO_H
