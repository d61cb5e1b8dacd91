// decimate IN OUT (--faces N | --ratio R | --max-error E) [--max-angle DEG] [--protect-borders]
//          [--no-relocation] [--no-hausdorff] [--limit-distance] [--corner-value-weight W]
//          [--drop-corner-data] [--no-tags]
//
// Simplifies a polygon mesh (.obj, .off, .ply), orientable or not, by
// Garland–Heckbert edge collapses and writes the result. Prints one line of
// JSON: the output's counts and topology (as mesh_info), then
//   "seconds":S (the decimation alone),"hausdorff":H (the symmetric
//   Hausdorff distance between the input's and the result's surfaces,
//   sampled by CGAL on their faces, edges and face corners (isolated vertices
//   are no surface and are not sampled); null where the input or the result
//   has no area, or with --no-hausdorff)[,"limit_distance":D (with
//   --limit-distance: the largest distance from the result's vertices and face
//   centroids to the input's Catmull–Clark limit surface, the shape a
//   subdivision cage stands for)][,"corner_values_interpolated":N (the
//   output has texture coordinates or normals: kept along their seams, where
//   edges are not collapsed, and elsewhere merged by attribute quadrics,
//   which weigh the values in the cost and the point of each collapse, or
//   with --corner-value-weight 0 interpolated along the collapsed edge; N
//   values of the output were so made)][,"corner_channels_dropped":[...]]}
// A bad file or option: one line on stderr, exit status 2.

#include "arguments.h"
#include "limit_distance.h"
#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/decimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;

const examples::Tool_usage usage{
  "decimate",
  "decimate IN OUT (--faces N | --ratio R | --max-error E) [--max-angle DEG] [--protect-borders] [--no-relocation] "
  "[--no-hausdorff] [--limit-distance] [--corner-value-weight W] [--drop-corner-data] [--no-tags]",
  "Reads a polygon mesh (.obj, .off, .ply), orientable or not, triangulates it and collapses\n"
  "edges, cheapest first by Garland-Heckbert quadric error, until a stop condition holds (give\n"
  "one or more; the first reached stops):\n"
  "  --faces N          at most N faces;\n"
  "  --ratio R          at most R times the triangles of the input, R in [0, 1];\n"
  "  --max-error E      the cheapest collapse's error is above E (squared length units).\n"
  "  --max-angle DEG    no face normal turns by more in one collapse (default 90).\n"
  "  --protect-borders  keep border edges as they are.\n"
  "  --no-relocation    leave the vertices where the collapses put them (by default they then\n"
  "                     move to lower the largest distance to the input).\n"
  "  --no-hausdorff     leave out the Hausdorff distance (null in the JSON line): on large\n"
  "                     meshes its sampling can take longer than the decimation.\n"
  "  --limit-distance   take IN as a subdivision cage and say how far the result lies from\n"
  "                     its Catmull-Clark limit surface (limit_distance in the JSON line).\n"
  "  --corner-value-weight W  how much texture coordinates and normals weigh against the points\n"
  "                     in each collapse, W >= 0 (default 1; 0: the points alone decide).\n"
  "  --drop-corner-data  go on without the input's texture coordinates and normals.\n"
  "  --no-tags          an OBJ OUT without OpenSubdiv's tag lines (the kept creases), which\n"
  "                     CGAL's reader refuses.\n"
  "Edges with sharpness tags (OBJ 't crease') are kept. Texture coordinates and normals are\n"
  "carried: their seams are kept with their values, and elsewhere the values weigh in the cost\n"
  "and the point of each collapse (attribute quadrics), which gives the merged corners their\n"
  "values (with --corner-value-weight 0, interpolated along the collapsed edge). Writes OUT and\n"
  "prints its counts, topology, the time taken and the Hausdorff distance to the input as one\n"
  "line of JSON.\n"};

// The symmetric Hausdorff distance between the surfaces of two meshes, by
// CGAL on their Surface_mesh copies (cut along the seams, same geometry);
// none where a surface has no area, which CGAL's sampling cannot sample.
std::optional<double> hausdorff_distance(const Mesh& a, const Mesh& b)
{
  CGAL::Surface_mesh<Kernel::Point_3> sa, sb;
  CGAL_ext::to_surface_mesh(a, sa);
  CGAL_ext::to_surface_mesh(b, sb);
  // The distance between surfaces: a vertex on no face is not on either.
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(sa);
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(sb);
  if (!(CGAL::Polygon_mesh_processing::area(sa) > 0 && CGAL::Polygon_mesh_processing::area(sb) > 0))
    return std::nullopt;
  const std::size_t faces = (std::max)(std::size_t(a.number_of_faces()), std::size_t(b.number_of_faces()));
  const std::size_t samples = (std::max)(std::size_t(20000), 4 * faces);
  const auto np = CGAL::parameters::number_of_points_on_faces(samples).random_seed(1);
  return CGAL::Polygon_mesh_processing::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(sa, sb, np,
                                                                                                          np);
}

int decimate(int argc, char** argv)
{
  const examples::Arguments args = examples::parse_arguments(
    argc, argv, {"--faces", "--ratio", "--max-error", "--max-angle", "--corner-value-weight"},
    {"--protect-borders", "--no-relocation", "--no-hausdorff", "--limit-distance", examples::drop_corner_data_flag,
     examples::no_tags_flag});
  if (args.positional.size() != 2)
    throw examples::Usage_error("expected two file names, got " + std::to_string(args.positional.size()));
  if (!args.has("--faces") && !args.has("--ratio") && !args.has("--max-error"))
    throw examples::Usage_error("give --faces, --ratio or --max-error");
  const long max_int = long((std::numeric_limits<std::uint32_t>::max)());
  const std::size_t faces = std::size_t(
    args.has("--faces") ? examples::integer_argument("--faces", args.value("--faces", ""), 0, max_int) : 0);
  const double ratio = args.has("--ratio") ? examples::real_argument("--ratio", args.value("--ratio", "")) : 0.0;
  if (!(ratio >= 0 && ratio <= 1))
    throw examples::Usage_error("--ratio '" + args.value("--ratio", "") + "' is not in [0, 1]");
  const double error = args.has("--max-error")
                         ? examples::real_argument("--max-error", args.value("--max-error", ""))
                         : std::numeric_limits<double>::infinity();
  if (!(error >= 0))
    throw examples::Usage_error("--max-error '" + args.value("--max-error", "") + "' is negative");
  const double angle = examples::real_argument("--max-angle", args.value("--max-angle", "90"));
  if (!(angle > 0 && angle <= 180))
    throw examples::Usage_error("--max-angle '" + args.value("--max-angle", "") + "' is not in (0, 180]");
  const double value_weight =
    examples::real_argument("--corner-value-weight", args.value("--corner-value-weight", "1"));
  if (!(value_weight >= 0) || !std::isfinite(value_weight))
    throw examples::Usage_error("--corner-value-weight '" + args.value("--corner-value-weight", "") +
                                "' is not a finite number >= 0");

  Mesh input;
  CGAL_ext::IO::check_output_file(args.positional[1]); // before the work, not after it
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], input);
  const bool drop = args.has(examples::drop_corner_data_flag);
  const examples::Json_array dropped = examples::drop_corner_channels_if(input, drop ? "asked" : "", drop);
  Mesh mesh = input;
  // Of the input as read: the cage, before its faces are split.
  const auto cage = args.has("--limit-distance") ? examples::cage_surface(input) : nullptr;
  const auto start = std::chrono::steady_clock::now();
  const CGAL_ext::Decimation_result done =
    CGAL_ext::decimate(mesh, CGAL_ext::parameters::number_of_faces(faces)
                               .face_ratio(ratio)
                               .maximum_error(error)
                               .maximum_normal_deviation(angle)
                               .protect_borders(args.has("--protect-borders"))
                               .relocate_vertices(!args.has("--no-relocation"))
                               .corner_value_weight(value_weight));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], mesh, examples::write_parameters(args));
  std::optional<double> to_limit;
  if (cage)
    to_limit = examples::limit_distance(mesh, *cage);
  std::optional<double> hausdorff;
  if (!args.has("--no-hausdorff")) {
    CGAL_ext::triangulate_faces(input); // CGAL's sampling wants triangles; the surface is the same
    hausdorff = hausdorff_distance(mesh, input);
  }

  examples::Json_object line = examples::mesh_summary(mesh).add("seconds", seconds).add("hausdorff", hausdorff);
  if (to_limit)
    line.add("limit_distance", *to_limit);
  if (!mesh.corner_channels().empty())
    line.add("corner_values_interpolated", done.corner_values_interpolated);
  if (drop)
    line.add("corner_channels_dropped", dropped);
  examples::print_json_line(line);
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  return examples::run_tool(usage, argc, argv, [&] { return decimate(argc, argv); });
}
