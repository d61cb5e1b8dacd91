// tessellate IN OUT (--rate N | --tolerance T) [--scheme catmull-clark|loop] [--boundary none|edge-only|edge-and-corner]
//   [--crease-method uniform|chaikin] [--triangles catmark|smooth] [--fvar-interpolation none|corners-only|corners-plus1|corners-plus2|boundaries|all] [--drop-corner-data]
//
// Samples the Catmull–Clark (or Loop) limit surface of a polygon (or
// triangle) mesh (.obj, .off, .ply) uniformly, N segments along every base
// edge, or with each edge's rate chosen from a tolerance T, with
// OpenSubdiv's Bfr::Tessellation samples, and writes the result: watertight (faces share
// the samples of their common edges), borders kept, a one-sided surface
// one-sided. Texture coordinates and corner normals are carried, each on its
// own limit surface at the same samples, seams kept. Prints one line of
// JSON, the counts of mesh_info, the channels and the time:
//   {"vertices":V,"edges":E,"faces":F,"border_loops":B,"mobius_edges":M,
//    "orientable":...,"closed":...,"components":C,"euler_characteristic":X,
//    "valid":true,"corner_channels":[...],"seconds":S}
// A bad file or option: one line on stderr, exit status 2.

#include "arguments.h"
#include "json_line.h"
#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Limit_surface.h>
#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cmath>
#include <string>

namespace {

const examples::Tool_usage usage{
  "tessellate",
  "tessellate IN OUT (--rate N | --tolerance T) [--scheme catmull-clark|loop] [--boundary none|edge-only|edge-and-corner] "
  "[--crease-method uniform|chaikin] [--triangles catmark|smooth] [--fvar-interpolation none|corners-only|corners-plus1|corners-plus2|boundaries|all] [--drop-corner-data]",
  "Reads a polygon mesh (.obj, .off, .ply) and writes a mesh of its limit surface, each face\n"
  "sampled as OpenSubdiv's Bfr::Tessellation samples it:\n"
  "  --rate      segments along every base edge, 1 to 64 (a quad becomes N x N quads, a\n"
  "              triangle of a Loop surface N x N triangles).\n"
  "  --tolerance instead of --rate: a distance in the mesh's units; each base edge gets the\n"
  "              fewest segments (at most 64) whose midpoints lie within it of the surface,\n"
  "              each face inner rates at least those Bfr infers from its edges' and enough\n"
  "              for its inner lines' segments to lie within it too (facets' centres can lie\n"
  "              off by a few tolerances: their two directions add up).\n"
  "  --scheme    catmull-clark (default) or loop (every face a triangle).\n"
  "  --boundary  border rule: edge-only (default), edge-and-corner, or none (the faces with a\n"
  "              vertex on a border are holes, left out, as OpenSubdiv leaves them).\n"
  "  --crease-method  uniform (default) or chaikin: how semi-sharp creases decay.\n"
  "  --triangles catmark (default) or smooth: OpenSubdiv's Catmull-Clark rule at triangles.\n"
  "              The OBJ tags give the defaults of --boundary, --crease-method and\n"
  "              --triangles, as for subdivide; flags override them.\n"
  "  --fvar-interpolation  which texture coordinates and normals stay linear (OpenSubdiv's\n"
  "              FVarLinearInterpolation): none, corners-only, corners-plus1 (the default),\n"
  "              corners-plus2, boundaries or all (bilinear in each face).\n"
  "  --drop-corner-data  go on without the input's texture coordinates and normals where\n"
  "              OUT's format cannot hold them (named in the JSON line).\n"
  "Shared vertex and edge samples are computed once, so the result is watertight, with the\n"
  "input's borders, Euler characteristic and orientability (but for the holes of --boundary\n"
  "none). Prints its counts and the time taken as one line of JSON.\n"};

enum class Scheme { catmull_clark, loop };

const examples::Choices<Scheme> schemes = {{"catmull-clark", Scheme::catmull_clark}, {"loop", Scheme::loop}};

int tessellate(int argc, char** argv)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
  namespace S = CGAL_ext::Subdivision;
  const examples::Arguments args =
    examples::parse_arguments(argc, argv, {"--rate", "--tolerance", "--scheme", "--boundary", "--crease-method", "--triangles",
                               "--fvar-interpolation"},
                              {examples::drop_corner_data_flag});
  if (args.positional.size() != 2)
    throw examples::Usage_error("expected two file names, got " + std::to_string(args.positional.size()));
  if (args.has("--rate") == args.has("--tolerance"))
    throw examples::Usage_error("one of --rate and --tolerance is required");
  const int rate = args.has("--rate") ? int(examples::integer_argument("--rate", args.value("--rate", ""), 1, 64)) : 0;
  const double tolerance = args.has("--tolerance") ? examples::real_argument("--tolerance", args.value("--tolerance", "")) : 0;
  if (args.has("--tolerance") && !(tolerance > 0 && std::isfinite(tolerance)))
    throw examples::Usage_error("--tolerance must be positive and finite");
  const CGAL_ext::Sharp_feature_options flags = examples::subdivision_rule_flags(args);
  const Scheme scheme = examples::choice_argument("--scheme", args.value("--scheme", "catmull-clark"), schemes);
  const CGAL_ext::Face_varying_interpolation fvar = examples::face_varying_argument(args);

  Mesh mesh;
  CGAL_ext::IO::check_output_file(args.positional[1]); // before the work, not after it
  const CGAL_ext::Sharp_feature_options rules =
    examples::with_flags(CGAL_ext::IO::read_polygon_mesh(args.positional[0], mesh), flags);
  // Whether OUT's format holds the corner channels is known now.
  const examples::Json_array dropped = examples::drop_corner_channels_if(
    mesh, examples::why_output_cannot_hold_corner_data(args.positional[1], mesh), args.has(examples::drop_corner_data_flag));
  const auto start = std::chrono::steady_clock::now();
  const auto np = examples::subdivision_rule_parameters(rules).face_varying_interpolation(fvar);
  const auto run = [&](auto mask) {
    using Mask = decltype(mask);
    return rate > 0 ? S::tessellate<Mask>(mesh, rate, np) : S::tessellate_to_tolerance<Mask>(mesh, tolerance, np);
  };
  const Mesh out = scheme == Scheme::loop ? run(S::Loop_mask()) : run(S::Catmull_clark_mask());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], out);
  examples::Json_object line = examples::mesh_summary(out);
  line.add("corner_channels", examples::corner_channels_json(out));
  if (args.has(examples::drop_corner_data_flag))
    line.add("corner_channels_dropped", dropped);
  line.add("seconds", seconds);
  examples::print_json_line(line);
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  return examples::run_tool(usage, argc, argv, [&] { return tessellate(argc, argv); });
}
