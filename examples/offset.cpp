// offset IN OUT --distance D [--solid] [--weighting uniform|area|angle] [--drop-corner-data]
//
// Offsets a polygon mesh (.obj, .off, .ply) by D to both sides along its
// vertex normals and writes the result. A one-sided surface gives one
// surface, its orientation double cover displaced and closed along the
// border by a rim: a Möbius strip becomes one closed printable surface. An
// orientable surface gives the shell on the side its normals point to, or
// with --solid both shells joined by the rim. Prints one line of JSON:
//   {"vertices":V,"edges":E,"faces":F,"rim_faces":R,"closed":true|false,
//    "orientable":true|false,"components":C,"euler_characteristic":X,"seconds":S}
// A bad file or option: one line on stderr, exit status 2.

#include "arguments.h"
#include "json_line.h"
#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/offset_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <string>

namespace {

const examples::Tool_usage usage{
  "offset", "offset IN OUT --distance D [--solid] [--weighting uniform|area|angle] [--drop-corner-data]",
  "Reads a polygon mesh (.obj, .off, .ply) and moves every vertex along its vertex normal by +D\n"
  "and by -D. On a one-sided surface the two offsets are one surface: the orientation double\n"
  "cover, displaced, closed along the border by a rim (a Möbius strip gives one closed surface of\n"
  "genus 1). On an orientable surface: the shell on the side its normals point to, or with\n"
  "  --solid      both shells, joined along the border by a rim.\n"
  "  --weighting  how face normals make a vertex normal: area (default), uniform or angle.\n"
  "  --drop-corner-data  go on without the input's texture coordinates and normals.\n"
  "Texture coordinates and normals per face corner are carried: each copy of a face keeps its\n"
  "corners' values (normals turned on the copy on the face's back side); the rim faces' corners\n"
  "have none, counted in the JSON line.\n"
  "Writes OUT and prints its counts and the time taken as one line of JSON.\n"};

const examples::Choices<CGAL_ext::Vertex_normal_weighting> weightings = {
  {"uniform", CGAL_ext::Vertex_normal_weighting::uniform},
  {"area", CGAL_ext::Vertex_normal_weighting::area},
  {"angle", CGAL_ext::Vertex_normal_weighting::angle}};

int offset(int argc, char** argv)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
  const examples::Arguments args = examples::parse_arguments(argc, argv, {"--distance", "--weighting"},
                                                             {"--solid", examples::drop_corner_data_flag});
  if (args.positional.size() != 2)
    throw examples::Usage_error("expected two file names, got " + std::to_string(args.positional.size()));
  if (!args.has("--distance"))
    throw examples::Usage_error("--distance is required");
  const double distance = examples::real_argument("--distance", args.value("--distance", ""));
  if (!(distance > 0))
    throw examples::Usage_error("--distance '" + args.value("--distance", "") + "' is not positive");
  const auto weighting = examples::choice_argument("--weighting", args.value("--weighting", "area"), weightings);

  Mesh mesh, out;
  CGAL_ext::IO::check_output_file(args.positional[1]); // before the work, not after it
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], mesh);
  const bool drop = args.has(examples::drop_corner_data_flag);
  const examples::Json_array dropped = examples::drop_corner_channels_if(mesh, drop ? "asked" : "", drop);
  const auto start = std::chrono::steady_clock::now();
  const CGAL_ext::Offset_result r = CGAL_ext::offset_mesh(
    mesh, distance, out, CGAL_ext::parameters::solid(args.has("--solid")).vertex_normal_weighting(weighting));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], out);
  examples::Json_object line;
  line.add("vertices", r.vertices)
    .add("edges", r.edges)
    .add("faces", r.faces)
    .add("rim_faces", r.rim_faces)
    .add("closed", r.closed)
    .add("orientable", r.orientable)
    .add("components", r.components)
    .add("euler_characteristic", r.euler_characteristic)
    .add("seconds", seconds);
  if (!out.corner_channels().empty())
    line.add("corners_without_values", r.corners_without_values);
  if (drop)
    line.add("corner_channels_dropped", dropped);
  examples::print_json_line(line);
  return 0;
}

} // namespace

int main(int argc, char* argv[]) { return examples::run_tool(usage, argc, argv, [&] { return offset(argc, argv); }); }
