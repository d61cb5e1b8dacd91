// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reads an OBJ text in one pass into a polygon soup, with its texture
// coordinates and normals (`vt`, `vn` and the corners' indices into them)
// and OpenSubdiv's tags (creases, corners, the mesh-level subdivision
// options), and sets the sharpness the tags give on the mesh the soup became.

#ifndef CGAL_EXT_IO_INTERNAL_OBJ_READER_H
#define CGAL_EXT_IO_INTERNAL_OBJ_READER_H

#include <CGAL_ext/IO/internal/Corner_data.h>
#include <CGAL_ext/IO/internal/Text_scanning.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/exceptions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

struct Crease_tag
{
  std::size_t line;
  long long v0, v1;
  float sharpness;
};

struct Corner_tag
{
  std::size_t line;
  long long v;
  float sharpness;
};

struct Obj_scan
{
  Soup_lines lines;
  std::vector<Crease_tag> creases;
  std::vector<Corner_tag> corners;
  Sharp_feature_options options;
  Read_corner_data corner_data; // vt and vn, and the corners' indices into them
};

template <class Name>
bool is_statement_cgal_skips(const Name& s)
{
  // The statements CGAL's OBJ reader accepts and ignores (CGAL/IO/OBJ.h);
  // the OBJ files read here were read by CGAL's reader before, so they keep
  // passing where it did.
  static const char* const names[] = {"vt",  "vn",      "vp",       "bevel",   "lod",     "ctech",   "c_interp",
                                      "usemap", "usemtl", "stech",   "d_interp", "mtllib", "shadow_obj",
                                      "trace_obj", "o",    "g",        "s",       "p",       "cstype",  "deg",
                                      "step",  "bmat",     "con",      "curv",    "curv2",   "surf",    "parm",
                                      "trim",  "hole",     "scrv",     "sp",      "end",     "surf_1",  "q0_1",
                                      "q1_1",  "curv2d_1", "surf_2",   "q0_2",    "q1_2",    "curv2d_2", "bsp",
                                      "bzp",   "cdc",      "cdp",      "res"};
  for (const char* n : names)
    if (s == n)
      return true;
  return false;
}

// Reads one OpenSubdiv tag line: `t name nint/nfloat/nstring ints floats strings`.
inline void scan_obj_tag(const std::string& filename, std::size_t line, const std::vector<std::string>& tok,
                         Obj_scan& scan)
{
  auto fail = [&](const std::string& what) { throw IO_error(filename, line, what); };
  if (tok.size() < 2)
    fail("a tag line needs a name: 't name nint/nfloat/nstring arguments'");
  const std::string& name = tok[1];
  const bool known = name == "crease" || name == "corner" || name == "interpolateboundary" ||
                     name == "creasemethod" || name == "smoothtriangles";
  if (!known)
    return; // other tags (holes, face-varying options, ...) do not concern the mesh
  if (tok.size() < 3)
    fail("tag '" + name + "' lacks its argument counts 'nint/nfloat/nstring'");
  long long counts[3] = {0, 0, 0};
  {
    std::string c = tok[2];
    std::size_t k = 0, start = 0;
    for (; k < 3; ++k) {
      const std::size_t slash = k < 2 ? c.find('/', start) : std::string::npos;
      if (k < 2 && slash == std::string::npos)
        break;
      const std::string part = c.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
      if (!parse_integer(part, counts[k]) || counts[k] < 0 || counts[k] > 1000000)
        break;
      start = slash + 1;
    }
    if (k != 3)
      fail("tag '" + name + "': '" + printable(c) + "' is not an argument count 'nint/nfloat/nstring'");
  }
  const std::size_t n_int = std::size_t(counts[0]), n_float = std::size_t(counts[1]),
                    n_string = std::size_t(counts[2]);
  if (tok.size() != 3 + n_int + n_float + n_string)
    fail("tag '" + name + "' announces " + std::to_string(n_int) + " integer(s), " + std::to_string(n_float) +
         " float(s) and " + std::to_string(n_string) + " string(s), but has " + std::to_string(tok.size() - 3) +
         " argument(s)");
  std::vector<long long> ints(n_int);
  for (std::size_t i = 0; i < n_int; ++i)
    if (!parse_integer(tok[3 + i], ints[i]))
      fail("tag '" + name + "': '" + printable(tok[3 + i]) + "' is not an integer");
  std::vector<float> floats(n_float);
  for (std::size_t i = 0; i < n_float; ++i) {
    if (!parse_float(tok[3 + n_int + i], floats[i]))
      fail("tag '" + name + "': '" + printable(tok[3 + n_int + i]) + "' is not a finite number");
    if (floats[i] < 0)
      fail("tag '" + name + "': sharpness " + tok[3 + n_int + i] + " is negative");
  }
  const std::string* strings = n_string ? &tok[3 + n_int + n_float] : nullptr;

  if (name == "crease") {
    // Indices are read as pairs (v0 v1, v2 v3, ...), with one sharpness for
    // all pairs or one per pair.
    if (n_int < 2 || n_int % 2 != 0)
      fail("tag 'crease' needs an even number (at least 2) of vertex indices, read as pairs");
    if (n_float != 1 && n_float != n_int / 2)
      fail("tag 'crease' needs one sharpness, or one per vertex pair (" + std::to_string(n_int / 2) + ")");
    for (std::size_t i = 0; i < n_int; i += 2)
      scan.creases.push_back({line, ints[i], ints[i + 1], floats[n_float == 1 ? 0 : i / 2]});
  } else if (name == "corner") {
    if (n_int < 1)
      fail("tag 'corner' needs at least one vertex index");
    if (n_float != 1 && n_float != n_int)
      fail("tag 'corner' needs one sharpness, or one per vertex (" + std::to_string(n_int) + ")");
    for (std::size_t i = 0; i < n_int; ++i)
      scan.corners.push_back({line, ints[i], floats[n_float == 1 ? 0 : i]});
  } else if (name == "interpolateboundary") {
    if (n_int != 1 || ints[0] < 0 || ints[0] > 2)
      fail("tag 'interpolateboundary' needs one integer: 0 (none), 1 (edge and corner) or 2 (edge only)");
    static const Boundary_interpolation modes[] = {Boundary_interpolation::none,
                                                   Boundary_interpolation::edge_and_corner,
                                                   Boundary_interpolation::edge_only};
    scan.options.boundary_interpolation = modes[ints[0]];
  } else if (name == "creasemethod") {
    // OpenSubdiv's regression shapes call the uniform method "normal".
    if (n_string >= 1 && strings[0] == "chaikin")
      scan.options.crease_method = Crease_method::chaikin;
    else if (n_string >= 1 && (strings[0] == "uniform" || strings[0] == "normal"))
      scan.options.crease_method = Crease_method::uniform;
    else
      fail("tag 'creasemethod' needs one string: 'chaikin' or 'uniform'");
  } else { // smoothtriangles
    if (n_string >= 1 && strings[0] == "smooth")
      scan.options.triangle_subdivision = Triangle_subdivision::smooth;
    else if (n_string >= 1 && strings[0] == "catmark")
      scan.options.triangle_subdivision = Triangle_subdivision::catmark;
    else
      fail("tag 'smoothtriangles' needs one string: 'smooth' or 'catmark'");
  }
}

// The checks that need the whole file: faces naming vertices beyond the last
// one (a face may name a vertex defined further down), tags naming vertices
// that do not exist.
inline void check_obj_indices(const std::string& filename, long long largest_index, std::size_t n_points,
                              const std::vector<std::vector<std::size_t>>& polygons, const Obj_scan& scan)
{
  const long long n = static_cast<long long>(n_points);
  if (largest_index > n) {
    for (std::size_t p = 0; p < polygons.size(); ++p)
      for (std::size_t v : polygons[p])
        if (v >= n_points)
          throw IO_error(filename, scan.lines.polygon_lines[p],
                         "face names vertex " + std::to_string(v + 1) + ", but the file has only " +
                           std::to_string(n) + " vertices");
  }
  for (const Crease_tag& c : scan.creases)
    for (long long v : {c.v0, c.v1})
      if (v < 0 || v >= n)
        throw IO_error(filename, c.line,
                       "crease names vertex " + std::to_string(v) + ", but tag indices run from 0 to " +
                         std::to_string(n - 1));
  for (const Corner_tag& c : scan.corners)
    if (c.v < 0 || c.v >= n)
      throw IO_error(filename, c.line,
                     "corner names vertex " + std::to_string(c.v) + ", but tag indices run from 0 to " +
                       std::to_string(n - 1));
}

// One face corner: v, v/vt, v//vn or v/vt/vn (indices as written: from 1,
// or negative counting back).
struct Obj_corner
{
  long long v = 0, vt = 0, vn = 0;
  bool has_vt = false, has_vn = false;
};

inline bool parse_face_corner(Token t, Obj_corner& c)
{
  const char* slash = std::find(t.begin, t.end, '/');
  if (!parse_integer(Token{t.begin, slash}, c.v))
    return false;
  if (slash == t.end)
    return true;
  const char* slash2 = std::find(slash + 1, t.end, '/');
  const Token texture{slash + 1, slash2};
  c.has_vt = !texture.empty();
  if (slash2 == t.end) // v/vt
    return c.has_vt && parse_integer(texture, c.vt);
  c.has_vn = true;
  return (!c.has_vt || parse_integer(texture, c.vt)) && parse_integer(Token{slash2 + 1, t.end}, c.vn);
}

// A `vt u [v [w]]` or `vn x y z` line, appended to the channel's values.
// Texture coordinates in 3D (a w other than 0) are refused, not cut to 2D.
template <std::size_t N, class Fail>
void scan_obj_value(const std::vector<Token>& tok, bool texture, Read_channel<N>& channel, const Fail& fail)
{
  const std::size_t given = tok.size() - 1;
  if (texture ? (given < 1 || given > 3) : given != 3)
    fail(texture ? "a texture coordinate is 'vt u [v [w]]'" : "a normal has three coordinates: 'vn x y z'");
  std::array<double, 3> xyz{0, 0, 0};
  for (std::size_t i = 0; i < given; ++i)
    if (!parse_real(tok[i + 1], xyz[i]))
      fail(std::string(texture ? "texture coordinate" : "normal coordinate") + " '" + printable(tok[i + 1]) +
           "' is not a finite number");
  if (texture && xyz[2] != 0)
    fail("3D texture coordinates are not read (w = " + printable(tok[3]) + " is not 0); only u and v are");
  if (channel.values.size() >= no_corner_value)
    fail("more values than the mesh's 32-bit indices hold");
  std::array<double, N> v;
  for (std::size_t i = 0; i < N; ++i)
    v[i] = xyz[i];
  channel.values.push_back(v);
}

// The value index of one corner: `index` as written (from 1, or negative
// counting back from the last value read so far). An index beyond the last
// value is checked once the whole file is read (it may be defined further down).
template <class Fail>
std::uint32_t obj_value_index(long long index, std::size_t n_values, const char* what, Token corner,
                              long long& largest, const Fail& fail)
{
  if (index == 0)
    fail("face corner '" + printable(corner) + "': OBJ " + what + " indices start at 1");
  if (index < 0 && static_cast<long long>(n_values) + index < 0)
    fail("face corner '" + printable(corner) + "' counts back past the first " + what + ": only " +
         std::to_string(n_values) + " precede it");
  if (index > static_cast<long long>(no_corner_value) - 1)
    fail("face corner '" + printable(corner) + "' names " + what + " " + std::to_string(index) +
         ", more than the mesh's 32-bit indices hold");
  largest = (std::max)(largest, index);
  return std::uint32_t(index < 0 ? static_cast<long long>(n_values) + index : index - 1);
}

// Appends the value indices of one face's `n` corners to a channel: `face`,
// or none (`no_corner_value`) where `face` is empty. Nothing is stored until
// a corner has a value; the corners before it are then filled in without one.
inline void add_face_values(std::vector<std::uint32_t>& index, const std::vector<std::uint32_t>& face,
                            std::size_t corners_before, std::size_t n)
{
  if (face.empty() && index.empty())
    return;
  index.resize(corners_before, no_corner_value);
  if (face.empty())
    index.resize(corners_before + n, no_corner_value);
  else
    index.insert(index.end(), face.begin(), face.end());
}

// Faces that name values beyond the last one of the file.
template <std::size_t N>
void check_obj_value_indices(const std::string& filename, const Read_channel<N>& channel, long long largest,
                             const std::vector<std::vector<std::size_t>>& polygons, const Soup_lines& lines,
                             const char* what)
{
  if (largest <= static_cast<long long>(channel.values.size()))
    return;
  std::size_t first = 0;
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    for (std::size_t c = first; c < first + polygons[p].size() && c < channel.corner_index.size(); ++c)
      if (channel.corner_index[c] != no_corner_value && channel.corner_index[c] >= channel.values.size())
        throw IO_error(filename, lines.polygon_lines[p],
                       "face names " + std::string(what) + " " + std::to_string(channel.corner_index[c] + 1) +
                         ", but the file has only " + std::to_string(channel.values.size()));
    first += polygons[p].size();
  }
}

// The largest indices that faces name (from 1), checked at the end: a face
// may name vertices and values defined further down.
struct Obj_largest_indices
{
  long long v = 0, vt = 0, vn = 0;
};

// One `f` line: its polygon, and its corners' value indices. A corner
// without `vt` (or `vn`) has no value, in a face that has none or beside
// corners that have one (as CGAL's reader, which reads every form, takes it).
// `vt` and `vn` are the caller's buffers, kept across faces.
template <class Fail>
void scan_obj_face(const std::vector<Token>& tok, std::size_t n_points, Obj_scan& scan,
                   std::vector<std::vector<std::size_t>>& polygons, std::size_t& n_corners,
                   Obj_largest_indices& largest, std::vector<std::uint32_t>& vt, std::vector<std::uint32_t>& vn,
                   const Fail& fail)
{
  std::vector<std::size_t> polygon;
  vt.clear();
  vn.clear();
  polygon.reserve(tok.size() - 1);
  for (std::size_t i = 1; i < tok.size(); ++i) {
    Obj_corner c;
    if (!parse_face_corner(tok[i], c))
      fail("face corner '" + printable(tok[i]) + "' is not a vertex index (v, v/vt, v//vn or v/vt/vn)");
    const long long index = c.v, n = static_cast<long long>(n_points);
    if (index == 0)
      fail("face corner '" + printable(tok[i]) + "': OBJ vertex indices start at 1");
    // The token, not -index, in the message: -index overflows for the least long long.
    if (index < 0 && n + index < 0)
      fail("face corner '" + printable(tok[i]) + "' counts back past the first vertex: only " +
           std::to_string(n) + " vertices precede it");
    largest.v = (std::max)(largest.v, index);
    polygon.push_back(std::size_t(index < 0 ? n + index : index - 1));
    // Value indices are kept from the first corner that has one on (the
    // corners before it have none); a face without values keeps none.
    const Read_corner_data& values = scan.corner_data;
    if (c.has_vt) {
      vt.resize(polygon.size() - 1, no_corner_value);
      vt.push_back(obj_value_index(c.vt, values.uv.values.size(), "texture coordinate", tok[i], largest.vt, fail));
    }
    if (c.has_vn) {
      vn.resize(polygon.size() - 1, no_corner_value);
      vn.push_back(obj_value_index(c.vn, values.normal.values.size(), "normal", tok[i], largest.vn, fail));
    }
  }
  for (std::vector<std::uint32_t>* face : {&vt, &vn})
    if (!face->empty())
      face->resize(polygon.size(), no_corner_value);
  add_face_values(scan.corner_data.uv.corner_index, vt, n_corners, polygon.size());
  add_face_values(scan.corner_data.normal.corner_index, vn, n_corners, polygon.size());
  n_corners += polygon.size();
  polygons.push_back(std::move(polygon));
}

// Reads an OBJ text in one pass: points, polygons (0-based; negative indices
// count back from the last vertex read), the line of each, texture
// coordinates and normals with the corners' indices into them, and
// OpenSubdiv's tags. Checks the syntax of `v`, `vt`, `vn`, `f` and `t` lines
// and that every face and tag names a vertex (and value) of the file.
template <class P>
Obj_scan read_obj_text(const std::string& filename, const std::string& text, std::vector<P>& points,
                       std::vector<std::vector<std::size_t>>& polygons)
{
  Obj_scan scan;
  std::vector<Token> tok;
  std::vector<std::string> tag_tokens;
  Obj_largest_indices largest;
  std::size_t n_corners = 0;
  std::vector<std::uint32_t> vt, vn; // a face's value indices
  Text_lines lines(text.data(), text.data() + text.size());
  while (lines.next()) {
    const std::size_t line = lines.number();
    split_tokens(lines.line().begin, lines.line().end, tok);
    auto fail = [&](const std::string& what) { throw IO_error(filename, line, what); };
    if (tok.empty())
      continue;
    const Token s = tok[0];
    if (s == "v") {
      if (tok.size() < 4)
        fail("a vertex needs three coordinates: 'v x y z'");
      double xyz[3];
      for (std::size_t i = 1; i < 4; ++i)
        if (!parse_real(tok[i], xyz[i - 1]))
          fail("vertex coordinate '" + printable(tok[i]) + "' is not a finite number");
      // Numbers may follow x y z (a weight w, a colour r g b), nothing else.
      double extra = 0;
      for (std::size_t i = 4; i < tok.size(); ++i)
        if (!parse_real(tok[i], extra))
          fail("unexpected '" + printable(tok[i]) + "' after the vertex coordinates");
      points.push_back(point_from_tokens<P>(&tok[1], xyz));
      scan.lines.point_lines.push_back(line);
    } else if (s == "vt" || s == "vn") {
      if (s == "vt")
        scan_obj_value(tok, true, scan.corner_data.uv, fail);
      else
        scan_obj_value(tok, false, scan.corner_data.normal, fail);
    } else if (s == "f") {
      scan_obj_face(tok, points.size(), scan, polygons, n_corners, largest, vt, vn, fail);
      scan.lines.polygon_lines.push_back(line);
    } else if (s == "t") {
      tag_tokens.clear();
      for (const Token& t : tok)
        tag_tokens.push_back(t.str());
      scan_obj_tag(filename, line, tag_tokens, scan);
    } else if (!is_statement_cgal_skips(s)) {
      fail("unknown OBJ statement '" + printable(s) + "'");
    }
  }
  check_obj_indices(filename, largest.v, points.size(), polygons, scan);
  // The faces after the last one with values have none.
  for (std::vector<std::uint32_t>* index : {&scan.corner_data.uv.corner_index, &scan.corner_data.normal.corner_index})
    if (!index->empty())
      index->resize(n_corners, no_corner_value);
  check_obj_value_indices(filename, scan.corner_data.uv, largest.vt, polygons, scan.lines, "texture coordinate");
  check_obj_value_indices(filename, scan.corner_data.normal, largest.vn, polygons, scan.lines, "normal");
  return scan;
}

[[noreturn]] inline void throw_soup_error_in_file(const Soup_error& e, const std::string& filename,
                                                  const Soup_lines& lines)
{
  std::size_t line = 0;
  if (!e.polygons().empty() && e.polygons().front() < lines.polygon_lines.size())
    line = lines.polygon_lines[e.polygons().front()];
  else if (!e.vertices().empty() && e.vertices().front() < lines.point_lines.size())
    line = lines.point_lines[e.vertices().front()];
  throw IO_error(filename, line, std::string(e.what()) + " (polygons and points numbered from 0)", e.kind());
}

// The mesh vertices each soup point became, read on the mesh just built by
// the soup import (before orientation reverses faces, so that face p walks
// polygon p from its corner 1). Without merging the import keeps the point
// indices and only appends the vertices that splitting creates; those (and
// every vertex under merging) are found through the faces.
template <class P>
std::vector<std::vector<Vertex_index>> soup_point_images(const std::vector<std::vector<std::size_t>>& polygons,
                                                         std::size_t n_points, bool merged, const Mobius_mesh<P>& mesh)
{
  std::vector<std::vector<Vertex_index>> images(n_points);
  if (!merged)
    for (std::size_t s = 0; s < n_points && s < mesh.number_of_vertices(); ++s)
      images[s].push_back(Vertex_index(s));
  if (merged || mesh.number_of_vertices() != n_points) {
    for (std::size_t p = 0; p < polygons.size(); ++p) {
      const std::vector<std::size_t>& polygon = polygons[p];
      std::size_t c = 1;
      for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(Face_index(p)), mesh)) {
        std::vector<Vertex_index>& image = images[polygon[c % polygon.size()]];
        const Vertex_index v = mesh.target(d);
        if (std::find(image.begin(), image.end(), v) == image.end())
          image.push_back(v);
        ++c;
      }
    }
  }
  return images;
}

// Sets the sharpness the tags give, on the vertices the soup points became
// (`images`, from soup_point_images()).
template <class P>
void apply_obj_tags(const Obj_scan& scan, const std::string& filename,
                    const std::vector<std::vector<Vertex_index>>& images, Mobius_mesh<P>& mesh)
{
  if (!scan.creases.empty()) {
    auto sharpness = edge_sharpness_map(mesh);
    for (const Crease_tag& c : scan.creases) {
      Edge_index edge;
      for (Vertex_index a : images[std::size_t(c.v0)]) {
        if (mesh.is_isolated(a))
          continue;
        for (Dart d : CGAL_ext::halfedges_around_target(a, mesh)) {
          const std::vector<Vertex_index>& b = images[std::size_t(c.v1)];
          if (std::find(b.begin(), b.end(), mesh.source(d)) != b.end())
            edge = mesh.edge(d);
        }
      }
      if (!edge.is_valid())
        throw IO_error(filename, c.line,
                       "crease names vertices " + std::to_string(c.v0) + " and " + std::to_string(c.v1) +
                         " (numbered from 0), which are not joined by an edge");
      sharpness[edge] = c.sharpness;
    }
  }
  if (!scan.corners.empty()) {
    auto sharpness = vertex_sharpness_map(mesh);
    // A corner on a point that merging folded away and no face uses names no vertex.
    for (const Corner_tag& c : scan.corners)
      for (Vertex_index v : images[std::size_t(c.v)])
        sharpness[v] = c.sharpness;
  }
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_OBJ_READER_H
