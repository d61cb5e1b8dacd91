// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reads an OFF file, text or binary, in one pass into a polygon soup. The
// header keyword is Geomview's [ST][C][N][4][n]OFF [BINARY]: what each vertex
// carries besides its coordinates (texture, colour, normal), homogeneous
// coordinates (4) and an explicit dimension (n), which must be 3. Texture
// coordinates and normals are kept for corner channels (a value per point).
// Counts are believed only as far as the bytes after the header can hold them.

#ifndef CGAL_EXT_IO_INTERNAL_OFF_READER_H
#define CGAL_EXT_IO_INTERNAL_OFF_READER_H

#include <CGAL_ext/IO/internal/Corner_data.h>
#include <CGAL_ext/IO/internal/Text_scanning.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace IO {
namespace internal {

// What the header keyword says each vertex carries.
struct Off_layout
{
  bool texture = false, colour = false, normal = false, homogeneous = false, n_dimensional = false;
  long long dimension = 3;

  // The numbers a vertex starts with: its coordinates (and w).
  std::size_t coordinates() const { return std::size_t(dimension) + (homogeneous ? 1 : 0); }
  // The floats of a binary vertex: coordinates, normal, colour (RGBA), texture (s t).
  std::size_t binary_floats() const
  {
    return coordinates() + (normal ? 3 : 0) + (colour ? 4 : 0) + (texture ? 2 : 0);
  }
};

inline bool parse_off_keyword(Token keyword, Off_layout& layout)
{
  const char* p = keyword.begin;
  auto take = [&](const char* s) {
    const std::size_t n = std::strlen(s);
    if (std::size_t(keyword.end - p) < n || std::memcmp(p, s, n) != 0)
      return false;
    p += n;
    return true;
  };
  layout.texture = take("ST");
  layout.colour = take("C");
  layout.normal = take("N");
  layout.homogeneous = take("4");
  layout.n_dimensional = take("n");
  return take("OFF") && p == keyword.end;
}

inline void check_off_dimension(const std::string& filename, std::size_t line, const Off_layout& layout)
{
  if (layout.dimension != 3)
    throw IO_error(filename, line,
                   "only 3-dimensional OFF files can be read; this one has dimension " +
                     std::to_string(layout.dimension));
}

// The point (x/w, y/w, z/w); its coordinates must be finite as doubles.
template <class P>
bool homogeneous_point(const P& p, double w, P& result)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  if (w == 0 || !std::isfinite(w))
    return false;
  result = w == 1 ? p : P(p.x() / FT(w), p.y() / FT(w), p.z() / FT(w));
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(CGAL::to_double(result[i])))
      return false;
  return true;
}

// Appends a vertex's normal (3 numbers from `normal`) and texture
// coordinates (2 from `texture`) to the channels, as the layout has them;
// false if one is not finite.
template <class T>
bool add_off_values(const Off_layout& layout, const T* normal, const T* texture, Read_corner_data& corners)
{
  if (layout.normal)
    corners.normal.values.push_back({double(normal[0]), double(normal[1]), double(normal[2])});
  if (layout.texture)
    corners.uv.values.push_back({double(texture[0]), double(texture[1])});
  bool finite = true;
  for (int i = 0; i < 3; ++i)
    finite = finite && (!layout.normal || std::isfinite(double(normal[i])));
  for (int i = 0; i < 2; ++i)
    finite = finite && (!layout.texture || std::isfinite(double(texture[i])));
  return finite;
}

// Binary OFF after its keyword line: big-endian 32-bit counts and indices and
// 32-bit floats, each face followed by its colour (a count and that many floats).
template <class P>
void read_off_binary(const std::string& filename, Off_layout layout, const char* begin, const char* end,
                     std::vector<P>& points, std::vector<std::vector<std::size_t>>& polygons,
                     Read_corner_data& corners)
{
  Byte_reader in(begin, end, true);
  auto fail = [&](const std::string& what) { throw IO_error(filename, 0, "binary OFF: " + what); };
  auto read_count = [&](const char* what) {
    if (!in.has(4))
      fail(std::string("the file ends before the ") + what);
    const std::int32_t n = in.read<std::int32_t>();
    if (n < 0)
      fail(std::string("negative ") + what + " " + std::to_string(n));
    return n;
  };
  if (layout.n_dimensional)
    layout.dimension = read_count("dimension");
  check_off_dimension(filename, 0, layout);
  const std::int32_t n_vertices = read_count("vertex count");
  const std::int32_t n_faces = read_count("face count");
  read_count("edge count");
  const std::size_t vertex_bytes = 4 * layout.binary_floats();
  check_count_fits(filename, 0, "vertices", std::uint64_t(n_vertices), vertex_bytes, in.remaining());
  // A face is at least its corner count and its colour count.
  check_count_fits(filename, 0, "faces", std::uint64_t(n_faces), 8,
                   in.remaining() - std::size_t(n_vertices) * vertex_bytes);
  points.reserve(std::size_t(n_vertices));
  std::vector<float> values(layout.binary_floats());
  for (std::int32_t v = 0; v < n_vertices; ++v) {
    for (float& value : values)
      value = in.read<float>();
    using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
    const P p{FT(double(values[0])), FT(double(values[1])), FT(double(values[2]))};
    P q;
    if (!std::isfinite(values[0]) || !std::isfinite(values[1]) || !std::isfinite(values[2]) ||
        !homogeneous_point(p, layout.homogeneous ? double(values[3]) : 1.0, q))
      fail("vertex " + std::to_string(v) + " has a coordinate that is not a finite number");
    points.push_back(q);
    // After the coordinates: the normal, the colour (RGBA), the texture (s t).
    const std::size_t at = layout.coordinates();
    if (!add_off_values(layout, &values[at], values.data() + values.size() - 2, corners))
      fail("vertex " + std::to_string(v) + " has a normal or texture coordinate that is not a finite number");
  }
  polygons.reserve(std::size_t(n_faces));
  for (std::int32_t f = 0; f < n_faces; ++f) {
    const std::string face = "face " + std::to_string(f);
    const std::int32_t size = read_count((face + "'s corner count").c_str());
    check_count_fits(filename, 0, "corners in " + face, std::uint64_t(size), 4, in.remaining());
    std::vector<std::size_t> polygon(static_cast<std::size_t>(size));
    for (std::size_t& corner : polygon) {
      const std::int32_t index = in.read<std::int32_t>();
      if (index < 0 || index >= n_vertices)
        fail(face + " names vertex " + std::to_string(index) + ", but vertex indices run from 0 to " +
             std::to_string(n_vertices - 1));
      corner = std::size_t(index);
    }
    const std::int32_t n_colour = read_count((face + "'s colour count").c_str());
    if (n_colour > 4 || !in.has(4 * std::size_t(n_colour)))
      fail(face + " announces " + std::to_string(n_colour) + " colour components (0 to 4 that the file holds)");
    for (std::int32_t c = 0; c < n_colour; ++c)
      in.read<float>();
    polygons.push_back(std::move(polygon));
  }
}

// The numbers after the keyword: [dimension] vertices faces [edges], on the
// keyword's line or the next ones; nothing may follow them on their line.
// The dimension goes into `layout`.
inline std::vector<long long> read_off_counts(const std::string& filename, Text_lines& lines,
                                              std::vector<Token>& tok, std::size_t first, Off_layout& layout)
{
  auto fail = [&](const std::string& what) { throw IO_error(filename, lines.number(), what); };
  const std::size_t needed = layout.n_dimensional ? 3 : 2;
  std::vector<long long> counts;
  std::size_t i = first;
  while (counts.size() < needed) {
    while (i == tok.size()) {
      if (!lines.next())
        fail("the file ends before the vertex and face counts");
      split_tokens(lines.line().begin, lines.line().end, tok);
      i = 0;
    }
    long long value = 0;
    if (!parse_integer(tok[i], value) || value < 0)
      fail("expected the counts 'vertices faces edges', not '" + printable(tok[i]) + "'");
    counts.push_back(value);
    ++i;
    if (layout.n_dimensional && counts.size() == 1) {
      layout.dimension = value;
      check_off_dimension(filename, lines.number(), layout);
    }
  }
  long long edges = 0;
  if (i < tok.size() && !parse_integer(tok[i++], edges))
    fail("the edge count '" + printable(tok[i - 1]) + "' is not an integer");
  if (i < tok.size())
    fail("unexpected '" + printable(tok[i]) + "' after the counts 'vertices faces edges'");
  return counts;
}

// Tokens after what a line must hold (a vertex's normal, colour and texture,
// a face's colour) must be numbers.
inline void check_trailing_numbers(const std::string& filename, std::size_t line, const std::vector<Token>& tok,
                                   std::size_t first, const char* what)
{
  double value = 0;
  for (std::size_t i = first; i < tok.size(); ++i)
    if (!parse_real(tok[i], value))
      throw IO_error(filename, line, std::string("'") + printable(tok[i]) + "' after the " + what +
                                       " is not a number");
}

// Text OFF: one vertex or face per line.
template <class P>
Soup_lines read_off_text(const std::string& filename, Text_lines& lines, std::vector<Token>& tok,
                         const Off_layout& layout, long long n_vertices, long long n_faces,
                         std::vector<P>& points, std::vector<std::vector<std::size_t>>& polygons,
                         Read_corner_data& corners)
{
  auto fail = [&](const std::string& what) { throw IO_error(filename, lines.number(), what); };
  auto next_record = [&] {
    while (lines.next()) {
      split_tokens(lines.line().begin, lines.line().end, tok);
      if (!tok.empty())
        return true;
    }
    return false;
  };
  Soup_lines soup_lines;
  const std::size_t dimension = layout.coordinates();
  points.reserve(std::size_t(n_vertices));
  for (long long i = 0; i < n_vertices; ++i) {
    if (!next_record())
      fail("the file ends after " + std::to_string(i) + " of " + std::to_string(n_vertices) + " vertices");
    if (tok.size() < dimension)
      fail("a vertex needs " + std::to_string(dimension) + " coordinates, this line has " +
           std::to_string(tok.size()));
    double xyzw[4] = {0, 0, 0, 1};
    for (std::size_t c = 0; c < dimension; ++c)
      if (!parse_real(tok[c], xyzw[c]))
        fail("vertex coordinate '" + printable(tok[c]) + "' is not a finite number");
    check_trailing_numbers(filename, lines.number(), tok, dimension, "vertex coordinates");
    // After the coordinates: the normal, a colour of 1 to 4 numbers, the
    // texture (s t) last.
    const std::size_t extra = (layout.normal ? 3 : 0) + (layout.texture ? 2 : 0);
    if (tok.size() < dimension + extra)
      fail(std::string("the vertex lacks its ") + (layout.normal ? "normal" : "") +
           (layout.normal && layout.texture ? " and " : "") + (layout.texture ? "texture coordinates" : "") +
           " (the header is " + (layout.texture ? "ST" : "") + (layout.colour ? "C" : "") +
           (layout.normal ? "N" : "") + "OFF)");
    if (extra > 0) {
      double numbers[5] = {0, 0, 0, 0, 0};
      const std::size_t texture_at = tok.size() - 2;
      for (std::size_t i = 0; i < 3 && layout.normal; ++i)
        parse_real(tok[dimension + i], numbers[i]);
      for (std::size_t i = 0; i < 2 && layout.texture; ++i)
        parse_real(tok[texture_at + i], numbers[3 + i]);
      add_off_values(layout, numbers, numbers + 3, corners);
    }
    P p;
    if (!homogeneous_point(point_from_tokens<P>(&tok[0], xyzw), xyzw[3], p))
      fail("the homogeneous vertex (" + printable(tok[0].begin, tok[dimension - 1].end) + ") has no finite position");
    points.push_back(p);
    soup_lines.point_lines.push_back(lines.number());
  }
  polygons.reserve(std::size_t(n_faces));
  for (long long i = 0; i < n_faces; ++i) {
    if (!next_record())
      fail("the file ends after " + std::to_string(i) + " of " + std::to_string(n_faces) + " faces");
    long long size = 0;
    if (!parse_integer(tok[0], size) || size < 0)
      fail("a face starts with its number of vertices, not '" + printable(tok[0]) + "'");
    if (tok.size() - 1 < std::size_t(size))
      fail("the face announces " + std::to_string(size) + " vertices but lists " + std::to_string(tok.size() - 1));
    std::vector<std::size_t> polygon(static_cast<std::size_t>(size));
    for (std::size_t c = 0; c < polygon.size(); ++c) {
      long long index = 0;
      if (!parse_integer(tok[c + 1], index))
        fail("face vertex '" + printable(tok[c + 1]) + "' is not an index");
      if (index < 0 || index >= n_vertices)
        fail("face names vertex " + std::to_string(index) + ", but vertex indices run from 0 to " +
             std::to_string(n_vertices - 1));
      polygon[c] = std::size_t(index);
    }
    check_trailing_numbers(filename, lines.number(), tok, polygon.size() + 1, "face's vertex indices");
    polygons.push_back(std::move(polygon));
    soup_lines.polygon_lines.push_back(lines.number());
  }
  // More lines than the counts announce: the counts are wrong, and what the
  // file means is not known.
  if (next_record())
    fail("the file goes on after the " + std::to_string(n_faces) + " faces that its counts announce");
  return soup_lines;
}

// Reads an OFF file (its whole text) into a polygon soup, and the vertices'
// texture coordinates and normals into `corners` (a value per point);
// returns the line of each point and polygon (none for binary OFF).
template <class P>
Soup_lines read_off(const std::string& filename, const std::string& text, std::vector<P>& points,
                    std::vector<std::vector<std::size_t>>& polygons, Read_corner_data& corners)
{
  const char* const text_end = text.data() + text.size();
  Text_lines lines(text.data(), text_end);
  std::vector<Token> tok;
  do {
    if (!lines.next())
      throw IO_error(filename, 0, "the file is empty: no OFF header");
    split_tokens(lines.line().begin, lines.line().end, tok);
  } while (tok.empty());
  Off_layout layout;
  if (!parse_off_keyword(tok[0], layout))
    throw IO_error(filename, lines.number(),
                   "missing OFF header: the file starts with '" + printable(tok[0]) + "'");
  if (tok.size() > 1 && tok[1] == "BINARY") {
    if (tok.size() > 2)
      throw IO_error(filename, lines.number(), "unexpected '" + printable(tok[2]) + "' after 'BINARY'");
    read_off_binary(filename, layout, lines.rest(), text_end, points, polygons, corners);
    corners.uv.per_vertex = corners.normal.per_vertex = true;
    return Soup_lines();
  }
  const std::vector<long long> counts = read_off_counts(filename, lines, tok, 1, layout);
  const long long n_vertices = counts[counts.size() - 2], n_faces = counts.back();
  // The shortest vertex line is "0 0 0\n", the shortest face line "0\n".
  const std::size_t remaining = std::size_t(text_end - lines.rest());
  const std::size_t vertex_bytes = 2 * layout.coordinates();
  check_count_fits(filename, lines.number(), "vertices", std::uint64_t(n_vertices), vertex_bytes, remaining);
  check_count_fits(filename, lines.number(), "faces", std::uint64_t(n_faces), 2,
                   remaining - std::size_t(n_vertices) * vertex_bytes);
  Soup_lines soup_lines = read_off_text(filename, lines, tok, layout, n_vertices, n_faces, points, polygons, corners);
  corners.uv.per_vertex = corners.normal.per_vertex = true;
  return soup_lines;
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_OFF_READER_H
