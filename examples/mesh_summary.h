// What the example tools print: one JSON line of a mesh's counts.
#ifndef CGAL_EXT_EXAMPLES_MESH_SUMMARY_H
#define CGAL_EXT_EXAMPLES_MESH_SUMMARY_H

#include "arguments.h"
#include "json_line.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <cstddef>
#include <iostream>
#include <string>
#include <vector>

namespace examples {

// The corner channels of a mesh (texture coordinates "c:uv", normals
// "c:normal"): per channel its name, values, seam edges, the corners
// without a value, and its Möbius edges without and with a seam (those of
// the mesh as it stands).
template <class P>
Json_array corner_channels_json(const CGAL_ext::Mobius_mesh<P>& mesh)
{
  Json_array channels;
  for (const CGAL_ext::Corner_channel_summary& s : CGAL_ext::corner_channel_summaries(mesh))
    channels.add(Json_object()
                   .add("name", s.name)
                   .add("values", s.values)
                   .add("seam_edges", s.seam_edges)
                   .add("corners_without_value", s.corners_without_value)
                   .add("mobius_edges_continuous", s.mobius_edges_continuous)
                   .add("mobius_edges_seamed", s.mobius_edges_seamed));
  return channels;
}

// --drop-corner-data: a tool whose operation or output format cannot carry
// the input's corner channels refuses the input, before the work, unless
// asked to go on without them; what is dropped is named in the JSON line.
inline const char* const drop_corner_data_flag = "--drop-corner-data";

// --fvar-interpolation: how a tool that follows the limit surface carries
// corner channels (OpenSubdiv's FVarLinearInterpolation), corners-plus1 by
// default, as OpenSubdiv's.
inline const Choices<CGAL_ext::Face_varying_interpolation>& face_varying_modes()
{
  static const Choices<CGAL_ext::Face_varying_interpolation> modes = {
    {"none", CGAL_ext::Face_varying_interpolation::none},
    {"corners-only", CGAL_ext::Face_varying_interpolation::corners_only},
    {"corners-plus1", CGAL_ext::Face_varying_interpolation::corners_plus1},
    {"corners-plus2", CGAL_ext::Face_varying_interpolation::corners_plus2},
    {"boundaries", CGAL_ext::Face_varying_interpolation::boundaries},
    {"all", CGAL_ext::Face_varying_interpolation::all}};
  return modes;
}
inline CGAL_ext::Face_varying_interpolation face_varying_argument(const Arguments& args)
{
  return choice_argument("--fvar-interpolation", args.value("--fvar-interpolation", "corners-plus1"),
                         face_varying_modes());
}

// --boundary, --crease-method, --triangles: the subdivision rules of a tool
// that follows a subdivision surface, as the OBJ tags hold them (unset where
// a flag is not given).
inline CGAL_ext::Sharp_feature_options subdivision_rule_flags(const Arguments& args)
{
  static const Choices<CGAL_ext::Boundary_interpolation> boundaries = {
    {"none", CGAL_ext::Boundary_interpolation::none},
    {"edge-only", CGAL_ext::Boundary_interpolation::edge_only},
    {"edge-and-corner", CGAL_ext::Boundary_interpolation::edge_and_corner}};
  static const Choices<CGAL_ext::Crease_method> crease_methods = {{"uniform", CGAL_ext::Crease_method::uniform},
                                                                   {"chaikin", CGAL_ext::Crease_method::chaikin}};
  static const Choices<CGAL_ext::Triangle_subdivision> triangle_rules = {
    {"catmark", CGAL_ext::Triangle_subdivision::catmark}, {"smooth", CGAL_ext::Triangle_subdivision::smooth}};
  CGAL_ext::Sharp_feature_options flags;
  flags.boundary_interpolation = choice_option(args, "--boundary", boundaries);
  flags.crease_method = choice_option(args, "--crease-method", crease_methods);
  flags.triangle_subdivision = choice_option(args, "--triangles", triangle_rules);
  return flags;
}

// The rules the file's tags give, each replaced where its flag is given.
inline CGAL_ext::Sharp_feature_options with_flags(CGAL_ext::Sharp_feature_options tags,
                                                  const CGAL_ext::Sharp_feature_options& flags)
{
  if (flags.boundary_interpolation)
    tags.boundary_interpolation = flags.boundary_interpolation;
  if (flags.crease_method)
    tags.crease_method = flags.crease_method;
  if (flags.triangle_subdivision)
    tags.triangle_subdivision = flags.triangle_subdivision;
  return tags;
}

// The named parameters of those rules, OpenSubdiv's defaults where unset.
inline auto subdivision_rule_parameters(const CGAL_ext::Sharp_feature_options& rules)
{
  return CGAL_ext::parameters::boundary_interpolation(
           rules.boundary_interpolation.value_or(CGAL_ext::Boundary_interpolation::edge_only))
    .crease_method(rules.crease_method.value_or(CGAL_ext::Crease_method::uniform))
    .triangle_subdivision(rules.triangle_subdivision.value_or(CGAL_ext::Triangle_subdivision::catmark));
}

// --no-tags: a tool that writes a mesh leaves OpenSubdiv's tag lines out of
// an OBJ output, which CGAL's OBJ reader then takes (it refuses a 't' line);
// the sharpness and the subdivision options are lost.
inline const char* const no_tags_flag = "--no-tags";

// The named parameters with which a tool writes its output, as `--no-tags`
// asks (`write_tags`: the flag was not given).
inline auto write_parameters(bool write_tags)
{
  return CGAL_ext::parameters::write_subdivision_tags(write_tags);
}

// The same, for a tool that accepts `--no-tags` among its flags.
inline auto write_parameters(const Arguments& args)
{
  return write_parameters(!args.has(no_tags_flag));
}

// Why the format of `out` (a path checked already) cannot hold the corner
// channels of `mesh` (CGAL_ext::IO::check_output_file()); empty if it can.
template <class P>
std::string why_output_cannot_hold_corner_data(const std::string& out, const CGAL_ext::Mobius_mesh<P>& mesh)
{
  try {
    CGAL_ext::IO::check_output_file(out, mesh);
    return std::string();
  } catch (const CGAL_ext::IO_error& e) {
    return e.what();
  }
}

// Drops the corner channels of `mesh` if `why` says they cannot be carried
// (empty: they can) and `drop` allows it, and returns their names; refuses
// them (Parameter_error) if `drop` does not.
template <class P>
Json_array drop_corner_channels_if(CGAL_ext::Mobius_mesh<P>& mesh, const std::string& why, bool drop)
{
  Json_array dropped;
  const std::vector<std::string> names = mesh.corner_channels();
  if (why.empty() || names.empty())
    return dropped;
  std::string list;
  for (const std::string& name : names)
    list += (list.empty() ? "" : ", ") + name;
  if (!drop)
    throw CGAL_ext::Parameter_error("the input's corner channels (" + list + ") cannot be carried: " + why + "; " +
                                    drop_corner_data_flag + " goes on without them");
  for (const std::string& name : names) {
    mesh.remove_corner_channel(name);
    dropped.add(name);
  }
  return dropped;
}

// "mobius_edges" counts the Möbius edges left once a copy of the mesh is
// oriented with CGAL_ext::orient() (as few as it finds). The count of the mesh
// as it stands depends on how its faces happen to be oriented; this one
// depends on the surface only, so every tool gives the same number for it.
template <class P>
Json_object mesh_summary(const CGAL_ext::Mobius_mesh<P>& mesh)
{
  CGAL_ext::Mobius_mesh<P> oriented = mesh;
  const std::size_t mobius_edges = CGAL_ext::orient(oriented);
  Json_object summary;
  summary.add("vertices", mesh.number_of_vertices())
    .add("edges", mesh.number_of_edges())
    .add("faces", mesh.number_of_faces())
    .add("border_loops", CGAL_ext::number_of_border_cycles(mesh))
    .add("mobius_edges", mobius_edges)
    .add("orientable", CGAL_ext::is_orientable(mesh))
    .add("closed", CGAL_ext::is_closed(mesh))
    .add("components", CGAL_ext::connected_components(mesh).count)
    .add("euler_characteristic", CGAL_ext::euler_characteristic(mesh))
    .add("valid", mesh.is_valid());
  // Only where there are some: the line of a mesh without them stays as it was.
  // On the oriented copy (orient() keeps each corner's value at its vertex):
  // its Möbius edges are the ones counted in "mobius_edges".
  if (!mesh.corner_channels().empty())
    summary.add("corner_channels", corner_channels_json(oriented));
  // Non-manifold input, held as manifold sheets: the counts above are the
  // sheets', these the input's.
  if (CGAL_ext::non_manifold_join_map(mesh)) {
    const CGAL_ext::Non_manifold_counts c = CGAL_ext::non_manifold_counts(mesh);
    summary.add("non_manifold_vertices", c.vertices)
      .add("non_manifold_edges", c.edges)
      .add("input_vertices", c.input_vertices)
      .add("input_edges", c.input_edges);
  }
  return summary;
}

/// Prints mesh_summary() as the tool's line.
template <class P>
void print_mesh_summary(const CGAL_ext::Mobius_mesh<P>& mesh, std::ostream& out = std::cout)
{
  print_json_line(mesh_summary(mesh), out);
}

} // namespace examples

#endif
