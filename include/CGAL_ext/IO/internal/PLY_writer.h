// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Writes a polygon soup as PLY (ASCII or binary little endian) with scalar
// properties per vertex after x, y and z: what CGAL's soup writer writes
// (the same header, the same bytes) when there are none, and the vertex
// properties as CGAL's Surface_mesh writer names and types them otherwise.

#ifndef CGAL_EXT_IO_INTERNAL_PLY_WRITER_H
#define CGAL_EXT_IO_INTERNAL_PLY_WRITER_H

#include <CGAL_ext/IO/internal/PLY_reader.h>
#include <CGAL_ext/Mobius_mesh.h>

#include <cfloat>
#include <climits>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace IO {
namespace internal {

inline const char* ply_type_name(Ply_type t)
{
  static const char* const names[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
  return names[int(t)];
}

// A name a PLY header can hold as one token, and that is not a coordinate.
inline bool is_ply_property_name(const std::string& name)
{
  if (name.empty() || name == "x" || name == "y" || name == "z")
    return false;
  for (const char c : name)
    if (static_cast<unsigned char>(c) <= ' ' || c == 127)
      return false;
  return true;
}

// The map named `map_name` if its values are of type T, as a column of
// values of type Written (CGAL writes 64-bit integers as 32-bit ones; an
// integer conversion wraps where a conversion from double would be undefined).
template <class T, class Written = T, class P>
bool add_ply_column(const Mobius_mesh<P>& mesh, const std::string& map_name, Ply_type type,
                    std::vector<Ply_vertex_column>& columns)
{
  const auto map = mesh.template property_map<Vertex_index, T>(map_name);
  if (!map)
    return false;
  Ply_vertex_column column{map_name.substr(2), type, {}};
  column.values.reserve(mesh.number_of_vertices());
  for (Vertex_index v : mesh.vertices())
    column.values.push_back(double(Written((*map)[v])));
  columns.push_back(std::move(column));
  return true;
}

// The vertex property maps that CGAL's Surface_mesh PLY writer writes: those
// named "v:NAME" (the point map aside) whose value is one of its integer or
// floating-point types, as PLY properties NAME of the matching type (64-bit
// integers as 32-bit ones, as CGAL does), in the order of the maps.
template <class P>
std::vector<Ply_vertex_column> ply_vertex_columns(const Mobius_mesh<P>& mesh)
{
  std::vector<Ply_vertex_column> columns;
  for (const std::string& name : mesh.template properties<Vertex_index>()) {
    if (name.rfind("v:", 0) != 0 || name == "v:point" || !is_ply_property_name(name.substr(2)))
      continue;
    // The first type that fits; a map of another value type is not written.
    (void)(add_ply_column<std::int8_t>(mesh, name, Ply_type::int8, columns) ||
      add_ply_column<std::uint8_t>(mesh, name, Ply_type::uint8, columns) ||
      add_ply_column<std::int16_t>(mesh, name, Ply_type::int16, columns) ||
      add_ply_column<std::uint16_t>(mesh, name, Ply_type::uint16, columns) ||
      add_ply_column<std::int32_t>(mesh, name, Ply_type::int32, columns) ||
      add_ply_column<std::uint32_t>(mesh, name, Ply_type::uint32, columns) ||
      add_ply_column<std::int64_t, std::int32_t>(mesh, name, Ply_type::int32, columns) ||
      add_ply_column<std::uint64_t, std::uint32_t>(mesh, name, Ply_type::uint32, columns) ||
      add_ply_column<float>(mesh, name, Ply_type::float32, columns) ||
      add_ply_column<double>(mesh, name, Ply_type::float64, columns));
  }
  return columns;
}

// Bytes in little-endian order, whatever the machine's.
template <class T>
void write_little_endian(std::ostream& out, T value)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const std::uint16_t one = 1;
  if (*reinterpret_cast<const unsigned char*>(&one) == 0)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
      std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out.write(bytes, sizeof(T));
}

// A value of a column in its type: text as CGAL's writer prints it (small
// integers as numbers, not characters), or its bytes.
inline void write_ply_value(std::ostream& out, bool binary, Ply_type type, double value)
{
  switch (type) {
  case Ply_type::int8: binary ? write_little_endian(out, std::int8_t(value)) : void(out << int(value)); break;
  case Ply_type::uint8: binary ? write_little_endian(out, std::uint8_t(value)) : void(out << int(value)); break;
  case Ply_type::int16: binary ? write_little_endian(out, std::int16_t(value)) : void(out << std::int16_t(value)); break;
  case Ply_type::uint16: binary ? write_little_endian(out, std::uint16_t(value)) : void(out << std::uint16_t(value)); break;
  case Ply_type::int32: binary ? write_little_endian(out, std::int32_t(value)) : void(out << std::int32_t(value)); break;
  case Ply_type::uint32: binary ? write_little_endian(out, std::uint32_t(value)) : void(out << std::uint32_t(value)); break;
  case Ply_type::float32: binary ? write_little_endian(out, float(value)) : void(out << float(value)); break;
  case Ply_type::float64: binary ? write_little_endian(out, value) : void(out << value); break;
  }
}

// Writes the soup. The header is CGAL's (`CGAL::IO::write_PLY()` of a
// soup): double x, y, z, then the columns; faces as a list of int indices
// with a uchar count, or a uint count where a face has more than 255 corners
// (CGAL's writer would cut its count short). Text uses the stream's precision.
template <class Point>
bool write_ply(std::ostream& out, bool binary, const std::vector<Point>& points,
               const std::vector<std::vector<std::size_t>>& polygons, const std::vector<Ply_vertex_column>& columns)
{
  std::size_t largest = 0;
  for (const auto& polygon : polygons)
    largest = std::max(largest, polygon.size());
  const bool wide_count = largest > 255;
  const bool wide_index = points.size() > std::size_t(INT_MAX);
  out << "ply\n"
      << (binary ? "format binary_little_endian 1.0" : "format ascii 1.0") << "\n"
      << "comment Generated by the CGAL library\n"
      << "element vertex " << points.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n";
  for (const Ply_vertex_column& c : columns)
    out << "property " << ply_type_name(c.type) << " " << c.name << "\n";
  out << "element face " << polygons.size() << "\n"
      << "property list " << (wide_count ? "uint " : "uchar ") << (wide_index ? "uint" : "int") << " vertex_indices\n"
      << "end_header\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (binary) {
      write_little_endian(out, double(p.x()));
      write_little_endian(out, double(p.y()));
      write_little_endian(out, double(p.z()));
    } else {
      out << p.x() << ' ' << p.y() << ' ' << p.z();
    }
    for (const Ply_vertex_column& c : columns) {
      if (!binary)
        out << ' ';
      write_ply_value(out, binary, c.type, c.values[i]);
    }
    if (!binary)
      out << '\n';
  }
  for (const auto& polygon : polygons) {
    if (binary) {
      if (wide_count)
        write_little_endian(out, std::uint32_t(polygon.size()));
      else
        write_little_endian(out, std::uint8_t(polygon.size()));
      for (std::size_t v : polygon)
        wide_index ? write_little_endian(out, std::uint32_t(v)) : write_little_endian(out, std::int32_t(v));
    } else {
      out << polygon.size();
      for (std::size_t v : polygon)
        out << ' ' << v;
      out << '\n';
    }
  }
  return out.good();
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_PLY_WRITER_H
