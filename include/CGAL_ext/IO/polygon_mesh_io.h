// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reading and writing a Mobius_mesh as OBJ, OFF or PLY, with OpenSubdiv's
// OBJ tags for creases, corners and the mesh-level subdivision options.

#ifndef CGAL_EXT_IO_POLYGON_MESH_IO_H
#define CGAL_EXT_IO_POLYGON_MESH_IO_H

#include <CGAL_ext/IO/internal/Atomic_output_file.h>
#include <CGAL_ext/IO/internal/Corner_data.h>
#include <CGAL_ext/IO/internal/Corner_writers.h>
#include <CGAL_ext/IO/internal/Mesh_file_io.h>
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
/// their Möbius connections; orientable components are oriented (unless
/// `keep_orientation(true)`), one-sided ones keep the file's orientations.
///
/// Texture coordinates and normals become the corner channels
/// `corner_uv_name` ("c:uv", values `Corner_uv<P>`, the kernel's `Point_2`)
/// and `corner_normal_name` ("c:normal", `Corner_normal<P>`, its `Vector_3`):
/// OBJ's `vt u [v [w]]` and `vn` with each face corner's indices, PLY's
/// per-vertex `s t` (or `u v`, `texture_u texture_v`) and `nx ny nz`, OFF's
/// `ST` and `N` (a corner takes its vertex's value), and PLY's per-face
/// `texcoord` lists (u v per corner). Each corner keeps the
/// value the file gives it at its vertex, also where faces are reversed or
/// points merged. A face without `vt` (or `vn`) has corners without a value.
/// A channel is made only if the file has such values.
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
/// From PLY files, every scalar property of the `vertex` element other than
/// `x`, `y` and `z` becomes a vertex property map named `"v:NAME"` whose value
/// type is the property's (`float`, `double`, `std::int8_t` ... `std::uint32_t`),
/// as CGAL's `Surface_mesh` PLY reader makes them (which turns `nx`, `ny`, `nz`
/// and colours into `"v:normal"` and `"v:color"`; here they are three maps
/// each). `write_polygon_mesh()` writes such maps back. A property whose map
/// cannot be made (`point`, or a name the mesh already holds with another
/// type) is left out, and so are all of them where vertex i of the mesh is not
/// point i of the file: when a `tolerance` merges points, or non-manifold
/// vertices are split.
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
///   \cgalParamNBegin{non_manifold_policy}
///     \cgalParamDescription{`Non_manifold_policy::split` reads polygons that do not form a
///       2-manifold as manifold sheets with a join map (see `polygon_soup_to_mobius_mesh()`)}
///     \cgalParamType{`Non_manifold_policy`}
///     \cgalParamDefault{`Non_manifold_policy::refuse`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the mesh-level options the file's tags set (unset where it has none).
/// \throws IO_error, naming the file and (where there is one) the line, if the
///   file cannot be read, has an unknown extension, has a malformed line or tag
///   (a coordinate, texture coordinate or normal that is not a finite number,
///   a `vt` with a w other than 0, a `vt` or `vn` index out of range, a count
///   its file cannot hold),
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
/// \brief checks, before any work, that `write_polygon_mesh()` could write
/// `filename`: a known extension (`.obj`, `.off`, `.ply`, any letter case),
/// not a directory, in a directory that exists and is writable.
///
/// A program that computes for long calls it first, so that a typo in the
/// output name costs nothing. The write itself checks again.
/// \throws IO_error naming `filename` and what is wrong.
inline void check_output_file(const std::string& filename)
{
  internal::format_of(filename);
  internal::check_output_path(filename);
}

/// \ingroup PkgMobiusMeshIO
/// \brief checks, as `check_output_file(filename)` does, and also that the
/// file's format holds the corner channels of `mesh` as
/// `write_polygon_mesh()` requires: OBJ holds `"c:uv"` and `"c:normal"` per
/// face corner; PLY holds them, OFF the normals, per vertex, where the
/// channel has no seam; no format holds other channels.
///
/// Catmull–Clark, Loop, bilinear and linear subdivision keep a channel's
/// seams where they are and make none, so a program that subdivides may
/// check its input's channels before the work.
/// \throws IO_error naming `filename` and what is wrong.
template <class P>
void check_output_file(const std::string& filename, const Mobius_mesh<P>& mesh)
{
  check_output_file(filename);
  internal::Vertex_values values;
  const internal::Mesh_format format = internal::format_of(filename);
  internal::checked_corner_data(mesh, filename, format, values);
  if (format == internal::Mesh_format::ply)
    internal::ply_columns(mesh, values, filename);
}

/// \ingroup PkgMobiusMeshIO
///
/// Writes `mesh` to an OBJ, OFF or PLY file, chosen by the file name's
/// extension (in any letter case), through CGAL's polygon soup writers (the
/// library's own where corner channels are written).
/// Each face is written in its own orientation, so reading the file back
/// gives the same Möbius edges. Coordinates are written as doubles with 17
/// significant digits, which read back exactly; exact kernels write
/// `CGAL::to_double()` of each coordinate (which may be one unit in the last
/// place away from the nearest double). PLY is written in binary unless
/// `use_binary_mode(false)`. Sheets of non-manifold input (a mesh with the
/// join map `non_manifold_join_name`) are written joined: one point per
/// input vertex, the polygons and tags on them.
///
/// The corner channels "c:uv" and "c:normal" (see `read_polygon_mesh()`; their
/// values may also be `std::array`s of 2 or 3 floats or doubles, or the
/// kernel's `Vector_2` / `Point_3`) are written with 17 significant digits:
/// to OBJ per face corner (`vt`, `vn`, and `v/vt/vn` corners; each value a
/// corner uses once, unused ones left out), to PLY per vertex (`nx ny nz`,
/// `s t`) and to OFF as normals per vertex (`NOFF`), where the channel has no
/// seam. Whatever the format cannot hold is refused before the file is
/// created rather than dropped: a seam or a corner without a value beside
/// valued ones in PLY or OFF, texture coordinates in OFF, any other channel,
/// values of another type (see `check_output_file(filename, mesh)`).
///
/// To PLY files, vertex data is written too, as CGAL's `Surface_mesh` PLY
/// writer writes it: each vertex property map named `"v:NAME"` (the point
/// map aside) whose value type is an integer of 8 to 64 bits, `float` or
/// `double` becomes the PLY vertex property `NAME` of the matching type
/// (64-bit integers as 32-bit ones, as CGAL does), in the order the maps were
/// added. A viewer can colour the mesh by it, and `read_polygon_mesh()` reads
/// it back into a map of the same name and type. Maps of other types, and
/// names that are not one word or are `x`, `y` or `z`, are not written. They
/// come after x, y, z and the corner channels' `nx ny nz` and `s t`; a map
/// `"v:nx"` (and so on) beside the channel written under its name is refused.
/// Without such maps and without corner channels the file is the one CGAL's
/// `write_PLY()` of the polygon soup writes, byte for byte.
///
/// To OBJ files, OpenSubdiv's tags are written too: `t crease 2/1/0 v0 v1 s`
/// for each edge and `t corner 1/1/0 v s` for each vertex whose sharpness is
/// not 0, and the options that are set in `options`. A mesh without sharpness
/// and without options gets no tag line, so that readers which do not know
/// OpenSubdiv's tags (CGAL's OBJ reader refuses any) read the file;
/// `write_subdivision_tags(false)` leaves them out whatever the mesh holds.
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
///   \cgalParamNBegin{write_subdivision_tags}
///     \cgalParamDescription{whether OBJ files get OpenSubdiv's tag lines (sharpness and `options`);
///       `false` writes the dialect that CGAL's `read_OBJ()` and `read_polygon_soup()` read (they refuse
///       a `t` line), losing the sharpness and the options}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param options mesh-level subdivision options, written as OBJ tags (unless
///   `write_subdivision_tags(false)`)
///
/// \throws IO_error if the extension is unknown, a coordinate (or a corner
///   value) is not a finite double (NaN, infinite, or beyond the doubles'
///   range in an exact kernel), a corner channel cannot be held by the format,
///   or the file cannot be written. The data goes to a temporary file beside
///   `filename`, flushed to the disk and renamed over `filename` once
///   complete: whatever fails, an existing `filename` is left as it was.
template <class P, class NP = parameters::Default_named_parameters>
void write_polygon_mesh(const std::string& filename, const Mobius_mesh<P>& mesh,
                        const NP& np = parameters::default_values(), const Sharp_feature_options& options = {})
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  CGAL_ext::internal::require_no_garbage(mesh, "write_polygon_mesh");
  const internal::Mesh_format format = internal::format_of(filename);

  // Everything is checked before the file is created: points, faces, the
  // corner channels and whether the format holds them.
  // Sheets of non-manifold input are written joined again (one vertex for
  // the copies of each input vertex).
  const CGAL_ext::internal::Join_classes joins(mesh);
  const std::vector<std::uint32_t> index = joins.joined_indices();
  std::vector<internal::Written_point> points = internal::written_points(mesh, filename);
  internal::Written_polygons polygons;
  polygons.reserve(mesh.number_of_faces());
  for (Face_index f : mesh.faces()) {
    polygons.emplace_back();
    for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh))
      polygons.back().push_back(index[mesh.target(d).idx()]);
  }
  internal::Vertex_values vertex_values;
  const internal::Written_corner_data corners = internal::checked_corner_data(mesh, filename, format, vertex_values);
  std::vector<internal::Ply_vertex_column> ply_columns;
  if (format == internal::Mesh_format::ply)
    ply_columns = internal::ply_columns(mesh, vertex_values, filename);
  // The join map itself is not data of the input: the joined file has none
  // (nor has a file of a mesh whose map joins nothing, a fold's).
  const auto is_join_map = [](const internal::Ply_vertex_column& c) {
    return "v:" + c.name == CGAL_ext::non_manifold_join_name;
  };
  ply_columns.erase(std::remove_if(ply_columns.begin(), ply_columns.end(), is_join_map), ply_columns.end());
  if (joins.has_joins()) {
    internal::keep_joined_rows(points, joins, filename, "points");
    internal::keep_joined_rows(vertex_values.uv, joins, filename, "texture coordinates");
    internal::keep_joined_rows(vertex_values.normal, joins, filename, "normals");
    for (internal::Ply_vertex_column& c : ply_columns)
      internal::keep_joined_rows(c.values, joins, filename, "values of \"" + c.name + "\"");
  }

  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 17);
  const bool binary =
    format == internal::Mesh_format::ply && choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), true);
  // A temporary file beside the target, renamed over it once complete: a
  // failed or interrupted write never destroys the old file.
  internal::Atomic_output_file file(filename, binary ? std::ios::out | std::ios::binary : std::ios::out);
  std::ofstream& out = file.stream();
  const auto cgal_np = CGAL::parameters::stream_precision(precision);
  bool written = true;
  if (format == internal::Mesh_format::obj) {
    if (corners.empty())
      written = CGAL::IO::write_OBJ(out, points, polygons, cgal_np);
    else
      internal::write_obj_with_corners(out, points, polygons, corners, precision);
    if (choose_parameter(get_parameter(np, CGAL_ext::internal_np::write_subdivision_tags), true))
      internal::write_obj_tags(out, mesh, np, options, joins, index);
  } else if (format == internal::Mesh_format::off) {
    if (corners.empty())
      written = CGAL::IO::write_OFF(out, points, polygons, cgal_np);
    else
      internal::write_off_with_values(out, points, polygons, vertex_values, precision);
  } else {
    out.precision(precision);
    written = internal::write_ply(out, binary, points, polygons, ply_columns);
  }
  if (!written || !out)
    throw IO_error(filename, 0, "writing the file failed" + internal::system_reason() + "; the old file is unchanged");
  file.commit();
}

} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_POLYGON_MESH_IO_H
