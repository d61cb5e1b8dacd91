// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reading and writing a Mobius_mesh as OBJ, OFF or PLY, with OpenSubdiv's
// OBJ tags for creases, corners and the mesh-level subdivision options.

#ifndef CGAL_EXT_IO_POLYGON_MESH_IO_H
#define CGAL_EXT_IO_POLYGON_MESH_IO_H

#include <CGAL_ext/IO/internal/Atomic_output_file.h>
#include <CGAL_ext/IO/internal/OFF_reader.h>
#include <CGAL_ext/IO/internal/PLY_reader.h>
#include <CGAL_ext/IO/internal/Text_scanning.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
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

// The vertex index of one face corner (v, v/vt, v//vn or v/vt/vn).
inline bool parse_face_corner(Token t, long long& index)
{
  const char* slash = std::find(t.begin, t.end, '/');
  if (!parse_integer(Token{t.begin, slash}, index))
    return false;
  if (slash == t.end)
    return true;
  const char* slash2 = std::find(slash + 1, t.end, '/');
  const Token texture{slash + 1, slash2};
  long long other = 0;
  if (slash2 == t.end) // v/vt
    return parse_integer(texture, other);
  return (texture.empty() || parse_integer(texture, other)) && parse_integer(Token{slash2 + 1, t.end}, other);
}

// Reads an OBJ text in one pass: points, polygons (0-based; negative indices
// count back from the last vertex read), the line of each, and OpenSubdiv's
// tags. Checks the syntax of `v`, `f` and `t` lines and that every face and
// tag names a vertex of the file.
template <class P>
Obj_scan read_obj_text(const std::string& filename, const std::string& text, std::vector<P>& points,
                       std::vector<std::vector<std::size_t>>& polygons)
{
  Obj_scan scan;
  std::vector<Token> tok;
  std::vector<std::string> tag_tokens;
  long long largest_index = 0; // checked at the end: faces may name vertices defined further down
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
    } else if (s == "f") {
      const long long n_points = static_cast<long long>(points.size());
      std::vector<std::size_t> polygon;
      polygon.reserve(tok.size() - 1);
      for (std::size_t i = 1; i < tok.size(); ++i) {
        long long index = 0;
        if (!parse_face_corner(tok[i], index))
          fail("face corner '" + printable(tok[i]) + "' is not a vertex index (v, v/vt, v//vn or v/vt/vn)");
        if (index == 0)
          fail("face corner '" + printable(tok[i]) + "': OBJ vertex indices start at 1");
        // The token, not -index, in the message: -index overflows for the least long long.
        if (index < 0 && n_points + index < 0)
          fail("face corner '" + printable(tok[i]) + "' counts back past the first vertex: only " +
               std::to_string(n_points) + " vertices precede it");
        largest_index = (std::max)(largest_index, index);
        polygon.push_back(std::size_t(index < 0 ? n_points + index : index - 1));
      }
      polygons.push_back(std::move(polygon));
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
  check_obj_indices(filename, largest_index, points.size(), polygons, scan);
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

// Sets the sharpness the tags give, on the vertices the soup points became.
template <class P, class NP>
void apply_obj_tags(const Obj_scan& scan, const std::string& filename,
                    const std::vector<std::vector<std::size_t>>& polygons, std::size_t n_points,
                    Mobius_mesh<P>& mesh, const NP& np)
{
  if (scan.creases.empty() && scan.corners.empty())
    return;
  // Soup point -> mesh vertices. Without merging the import keeps the point
  // indices and only appends the vertices that splitting creates; those (and
  // every vertex under merging) are found through the faces, which keep the
  // polygons' order and start: the halfedge of face p ends at corner 1 of p.
  std::vector<std::vector<Vertex_index>> images(n_points);
  using Tolerance = std::decay_t<decltype(parameters::get_parameter(np, CGAL_ext::internal_np::tolerance))>;
  constexpr bool merged = !std::is_same_v<Tolerance, CGAL::internal_np::Param_not_found>;
  if constexpr (!merged) {
    for (std::size_t s = 0; s < n_points && s < mesh.number_of_vertices(); ++s)
      images[s].push_back(Vertex_index(s));
  }
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

template <class P, class Map>
void write_crease_tags(std::ostream& out, const Mobius_mesh<P>& mesh, const Map& sharpness)
{
  for (Edge_index e : mesh.edges()) {
    const float s = float(get(sharpness, e));
    if (s != 0)
      out << "t crease 2/1/0 " << mesh.vertex(e, 0).idx() << ' ' << mesh.vertex(e, 1).idx() << ' ' << float_text(s)
          << '\n';
  }
}
// The mesh's own map may be missing; a map given as a parameter is not optional.
template <class P, class Map>
void write_crease_tags(std::ostream& out, const Mobius_mesh<P>& mesh, const std::optional<Map>& sharpness)
{
  if (sharpness)
    write_crease_tags(out, mesh, *sharpness);
}

template <class P, class Map>
void write_corner_tags(std::ostream& out, const Mobius_mesh<P>& mesh, const Map& sharpness)
{
  for (Vertex_index v : mesh.vertices()) {
    const float s = float(get(sharpness, v));
    if (s != 0)
      out << "t corner 1/1/0 " << v.idx() << ' ' << float_text(s) << '\n';
  }
}
template <class P, class Map>
void write_corner_tags(std::ostream& out, const Mobius_mesh<P>& mesh, const std::optional<Map>& sharpness)
{
  if (sharpness)
    write_corner_tags(out, mesh, *sharpness);
}

// read_polygon_mesh() without its translation of foreign exceptions.
template <class P, class NP>
Sharp_feature_options read_polygon_mesh(const std::string& filename, Mesh_format format, Mobius_mesh<P>& mesh,
                                        const NP& np)
{
  const std::string text = read_whole_file(filename);
  std::vector<P> points;
  std::vector<std::vector<std::size_t>> polygons;
  Obj_scan obj;
  if (format == Mesh_format::obj)
    obj = read_obj_text(filename, text, points, polygons);
  else if (format == Mesh_format::off)
    obj.lines = read_off(filename, text, points, polygons);
  else
    obj.lines = read_ply(filename, text, points, polygons);
  if (polygons.empty())
    throw IO_error(filename, 0, "the file has no faces");

  Mobius_mesh<P> result;
  try {
    polygon_soup_to_mobius_mesh(points, polygons, result, np);
  } catch (const Soup_error& e) {
    throw_soup_error_in_file(e, filename, obj.lines);
  }
  if (format == Mesh_format::obj)
    apply_obj_tags(obj, filename, polygons, points.size(), result, np);
  mesh = std::move(result);
  return obj.options;
}

} // namespace internal

/// \ingroup PkgMobiusMeshIO
///
/// Reads a polygon mesh from an OBJ, OFF or PLY file (chosen by the file
/// name's extension, in any letter case) into `mesh`, replacing its content.
/// Each format is read in one pass by the library's own reader: OBJ
/// (vertices, faces as `v`, `v/vt`, `v//vn` or `v/vt/vn` with negative
/// indices counting back, and tags), OFF (text or binary, with Geomview's
/// `[ST][C][N][4][n]OFF` variants; the dimension must be 3) and PLY (ASCII or
/// binary, index lists of any integer type). Lines may end in "\n", "\r\n"
/// or "\r"; a UTF-8 byte order mark is skipped; in OBJ and OFF a `#` starts a
/// comment anywhere on a line. Counts in a header are believed only as far as
/// the rest of the file can hold them. The polygons then go through
/// `polygon_soup_to_mobius_mesh()`, so non-orientable surfaces are read with
/// their Möbius connections; faces keep the file's orientation.
///
/// From OBJ files, OpenSubdiv's tag lines are read as well (vertex indices in
/// tags count from 0):
/// `t crease n/m/0 v0 v1 ... s...` sets the sharpness of the edges (v0, v1),
/// (v2, v3), ... (one sharpness for all pairs, or one per pair) in the edge
/// property map `edge_sharpness_name`; `t corner n/m/0 v... s...` sets vertex
/// sharpness in the map `vertex_sharpness_name`; each map is created only if
/// the file has such tags. `t interpolateboundary 1/0/0 k` (0 none,
/// 1 edge and corner, 2 edge only), `t creasemethod 0/0/1 chaikin|uniform` and
/// `t smoothtriangles 0/0/1 smooth|catmark` are returned. Other tags are
/// ignored.
///
/// \param filename the file to read
/// \param mesh the mesh that receives the file's content; unchanged if reading fails
/// \param np optional named parameters, passed on to `polygon_soup_to_mobius_mesh()`:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{points closer than this are merged before the mesh is built}
///     \cgalParamType{the kernel's `FT`}
///     \cgalParamDefault{no merging}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_non_manifold_vertices}
///     \cgalParamDescription{if `true`, a vertex whose polygons form several fans is split}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the mesh-level options the file's tags set (unset where it has none).
/// \throws IO_error, naming the file and (where there is one) the line, if the
///   file cannot be read, has an unknown extension, has a malformed line or tag
///   (a coordinate that is not a finite number, a count its file cannot hold),
///   a tag names a vertex that does not exist or a crease names two vertices
///   that share no edge, or if its polygons do not form a 2-manifold (then
///   `IO_error::soup_kind()` tells which `Soup_error` it was, and the line is
///   that of the offending polygon in OBJ and ASCII OFF files).
/// \throws Parameter_error for a negative or NaN tolerance.
template <class P, class NP = parameters::Default_named_parameters>
Sharp_feature_options read_polygon_mesh(const std::string& filename, Mobius_mesh<P>& mesh,
                                        const NP& np = parameters::default_values())
{
  const internal::Mesh_format format = internal::format_of(filename);
  // What the standard library or CGAL throw leaves here as an IO_error with
  // the file's name, so that a caller needs to catch one type for bad files.
  try {
    return internal::read_polygon_mesh(filename, format, mesh, np);
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw IO_error(filename, 0, "out of memory while reading the file");
  } catch (const std::length_error& e) {
    throw IO_error(filename, 0, std::string("too large to read (") + e.what() + ")");
  } catch (const CGAL::Failure_exception& e) {
    throw IO_error(filename, 0, std::string("reading failed: ") + e.what());
  }
}

/// \ingroup PkgMobiusMeshIO
///
/// Writes `mesh` to an OBJ, OFF or PLY file, chosen by the file name's
/// extension (in any letter case), through CGAL's polygon soup writers.
/// Each face is written in its own orientation, so reading the file back
/// gives the same Möbius edges. Coordinates are written as doubles with 17
/// significant digits, which read back exactly; exact kernels write
/// `CGAL::to_double()` of each coordinate (which may be one unit in the last
/// place away from the nearest double). PLY is written in binary unless
/// `use_binary_mode(false)`.
///
/// To OBJ files, OpenSubdiv's tags are written too: `t crease 2/1/0 v0 v1 s`
/// for each edge and `t corner 1/1/0 v s` for each vertex whose sharpness is
/// not 0, and the options that are set in `options`. A mesh without sharpness
/// and without options gets no tag line, so that readers which do not know
/// OpenSubdiv's tags (CGAL's OBJ reader refuses any) read the file.
///
/// \param filename the file to write
/// \param mesh the mesh
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{edge_sharpness_map}
///     \cgalParamDescription{the sharpness of each edge}
///     \cgalParamType{a readable property map with key `Edge_index` and a value convertible to `float`}
///     \cgalParamDefault{the edge property map `edge_sharpness_name` if `mesh` has one, else none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_sharpness_map}
///     \cgalParamDescription{the sharpness of each vertex}
///     \cgalParamType{a readable property map with key `Vertex_index` and a value convertible to `float`}
///     \cgalParamDefault{the vertex property map `vertex_sharpness_name` if `mesh` has one, else none}
///   \cgalParamNEnd
///   \cgalParamNBegin{stream_precision}
///     \cgalParamDescription{significant digits of the coordinates in text formats}
///     \cgalParamType{int}
///     \cgalParamDefault{17}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{whether PLY files are written in binary}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param options mesh-level subdivision options, written as OBJ tags
///
/// \throws IO_error if the extension is unknown, a coordinate is not a finite
///   double (NaN, infinite, or beyond the doubles' range in an exact kernel),
///   or the file cannot be written. The data goes to a temporary file beside
///   `filename`, flushed to the disk and renamed over `filename` once
///   complete: whatever fails, an existing `filename` is left as it was.
template <class P, class NP = parameters::Default_named_parameters>
void write_polygon_mesh(const std::string& filename, const Mobius_mesh<P>& mesh,
                        const NP& np = parameters::default_values(), const Sharp_feature_options& options = {})
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Double_point = CGAL::Simple_cartesian<double>::Point_3;
  CGAL_ext::internal::require_no_garbage(mesh, "write_polygon_mesh");
  const internal::Mesh_format format = internal::format_of(filename);

  std::vector<Double_point> points;
  points.reserve(mesh.number_of_vertices());
  for (Vertex_index v : mesh.vertices()) {
    const P& p = mesh.point(v);
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    // Written, a NaN or an infinity makes a file that no reader takes back.
    const Double_point& q = points.back();
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()))
      throw IO_error(filename, 0,
                     "vertex " + std::to_string(v.idx()) + " has a coordinate that is not a finite double; "
                     "nothing was written");
  }
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(mesh.number_of_faces());
  for (Face_index f : mesh.faces()) {
    polygons.emplace_back();
    for (Vertex_index v : CGAL_ext::vertices_around_face(mesh.halfedge(f), mesh))
      polygons.back().push_back(v.idx());
  }

  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 17);
  const bool binary =
    format == internal::Mesh_format::ply && choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), true);
  // A temporary file beside the target, renamed over it once complete: a
  // failed or interrupted write never destroys the old file.
  internal::Atomic_output_file file(filename, binary ? std::ios::out | std::ios::binary : std::ios::out);
  std::ofstream& out = file.stream();
  const auto cgal_np = CGAL::parameters::stream_precision(precision);
  bool written = false;
  if (format == internal::Mesh_format::obj) {
    written = CGAL::IO::write_OBJ(out, points, polygons, cgal_np);
    // OpenSubdiv's tags; vertex indices in tags count from 0.
    internal::write_crease_tags(out, mesh,
                                choose_parameter(get_parameter(np, CGAL_ext::internal_np::edge_sharpness),
                                                 mesh.template property_map<Edge_index, float>(edge_sharpness_name)));
    internal::write_corner_tags(
      out, mesh,
      choose_parameter(get_parameter(np, CGAL_ext::internal_np::vertex_sharpness),
                       mesh.template property_map<Vertex_index, float>(vertex_sharpness_name)));
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
  } else if (format == internal::Mesh_format::off) {
    written = CGAL::IO::write_OFF(out, points, polygons, cgal_np);
  } else {
    CGAL::IO::set_mode(out, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
    written = CGAL::IO::write_PLY(out, points, polygons, cgal_np);
  }
  if (!written)
    throw IO_error(filename, 0, "writing the file failed" + internal::system_reason() + "; the old file is unchanged");
  file.commit();
}

} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_POLYGON_MESH_IO_H
