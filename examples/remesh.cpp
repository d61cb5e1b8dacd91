// remesh IN OUT --edge-length L [--iterations K] [--protect-borders] [--protect-sharp]
//        [--relax-constraints] [--max-memory BYTES] [--all-iterations] [--refuse-narrow]
//        [--project-to-limit] [--drop-corner-data] [--no-tags]
//
// Remeshes a polygon mesh (.obj, .off, .ply) into triangles whose edges are
// close to L (Botsch and Kobbelt's isotropic remeshing), on any surface: a
// Möbius strip stays one non-orientable strip. Prints one line of JSON:
//   {"vertices":V,"edges":E,"faces":F,"border_loops":B,"orientable":true|false,
//    "closed":true|false,"components":C,"euler_characteristic":X,"valid":true|false,
//    "in_band":S,"iterations":I,"stopped_early":true|false,"narrow_faces":N,
//    "narrowest_width":W,"seconds":T[,"limit_distance":D][,"corner_values_interpolated":N,
//    "seam_edges_protected":M][,"corner_channels_dropped":[...]]}
// where S is the share of edges between 4/5 L and 4/3 L, I the iterations
// run (fewer than K where the loop settled first), N the input's faces in
// parts of the surface narrower than any triangle with sides in the band
// (0.44 L), W the width of the narrowest (null if none), D (with
// --project-to-limit) the largest distance from the result's vertices and
// face centroids to the input's Catmull–Clark limit surface, N (where the
// output has texture coordinates or normals) the values of the output that
// the loop interpolated (seams are protected and keep their values, and the
// other corners take the input's values where their vertices land), M the
// seam edges it left as they were.
// A bad file or option, a result larger than --max-memory, a narrow surface
// with --refuse-narrow: one line on stderr, exit status 2.

#include "arguments.h"
#include "json_line.h"
#include "limit_distance.h"
#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/isotropic_remeshing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <string>

namespace {

const examples::Tool_usage usage{
  "remesh",
  "remesh IN OUT --edge-length L [--iterations K] [--protect-borders] [--protect-sharp] [--relax-constraints] "
  "[--max-memory BYTES] [--all-iterations] [--refuse-narrow] [--project-to-limit] [--drop-corner-data] [--no-tags]",
  "Reads a polygon mesh (.obj, .off, .ply), splits its faces into triangles and remeshes it so\n"
  "that its edges come close to L (Botsch and Kobbelt's loop of splits, collapses, flips,\n"
  "tangential relaxation and projection onto the input), on any surface, one-sided ones included.\n"
  "  --iterations K       at most how many times the loop runs (1 to 1000, default 1); it stops\n"
  "                       after two iterations in a row that each raised the share of edges in\n"
  "                       the band by less than 0.1 point and changed the face count by less\n"
  "                       than 1 %\n"
  "  --all-iterations     run all K iterations even so\n"
  "  --protect-borders    border edges and their vertices stay as they are (but see below)\n"
  "  --protect-sharp      so do the edges the file tags as sharp (OBJ crease tags)\n"
  "  --relax-constraints  the vertices of protected borders and sharp edges slide along them\n"
  "                       to even out their edges; corners stay\n"
  "  --max-memory BYTES   refuse before starting if the remeshing would need more (estimated\n"
  "                       from the input and L; default: the memory available)\n"
  "  --refuse-narrow      refuse a surface narrower than 0.44 L in places (a needle, a strip\n"
  "                       thinner than L), which can only be cut into a strip of slivers\n"
  "  --project-to-limit   take IN as a subdivision cage: vertices go onto its Catmull-Clark\n"
  "                       limit surface (OBJ crease tags read) instead of onto its faces, and\n"
  "                       the JSON line says how far the result lies from it (limit_distance)\n"
  "  --drop-corner-data   go on without the input's texture coordinates and normals\n"
  "  --no-tags            an OBJ OUT without OpenSubdiv's tag lines (the sharp edges), which\n"
  "                       CGAL's reader refuses\n"
  "Writes OUT and prints its counts, topology, the share of edges between 4/5 L and 4/3 L, the\n"
  "iterations run, whether the loop settled early, the input's faces in narrow parts and the\n"
  "narrowest's width, and the time taken as one line of JSON. Texture coordinates and normals\n"
  "are carried: their seams are protected (neither split, collapsed, flipped nor moved) and keep\n"
  "their values; elsewhere each corner takes the input's value where its vertex lands.\n"};

template <class Mesh>
double share_in_band(const Mesh& mesh, double L)
{
  std::size_t inside = 0;
  for (auto e : mesh.edges()) {
    const double l2 = CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1)));
    inside += l2 >= 0.64 * L * L && l2 <= 16.0 / 9.0 * L * L;
  }
  return mesh.number_of_edges() == 0 ? 0 : double(inside) / double(mesh.number_of_edges());
}

int remesh(int argc, char** argv)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
  const examples::Arguments args =
    examples::parse_arguments(argc, argv, {"--edge-length", "--iterations", "--max-memory"},
                              {"--protect-borders", "--protect-sharp", "--relax-constraints", "--all-iterations",
                               "--refuse-narrow", "--project-to-limit", examples::drop_corner_data_flag,
                               examples::no_tags_flag});
  if (args.positional.size() != 2)
    throw examples::Usage_error("expected two file names, got " + std::to_string(args.positional.size()));
  if (!args.has("--edge-length"))
    throw examples::Usage_error("--edge-length is required");
  const double L = examples::real_argument("--edge-length", args.value("--edge-length", ""));
  if (!(L > 0))
    throw examples::Usage_error("--edge-length '" + args.value("--edge-length", "") + "' is not positive");
  const long iterations = examples::integer_argument("--iterations", args.value("--iterations", "1"), 1, 1000);
  const double max_memory =
    args.has("--max-memory") ? examples::real_argument("--max-memory", args.value("--max-memory", "")) : 1.0;
  if (!(max_memory > 0))
    throw examples::Usage_error("--max-memory '" + args.value("--max-memory", "") + "' is not positive");

  Mesh mesh;
  CGAL_ext::IO::check_output_file(args.positional[1]); // before the work, not after it
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], mesh);
  const bool drop = args.has(examples::drop_corner_data_flag);
  const examples::Json_array dropped = examples::drop_corner_channels_if(mesh, drop ? "asked" : "", drop);
  const auto start = std::chrono::steady_clock::now();
  const auto np = CGAL_ext::parameters::number_of_iterations(unsigned(iterations))
                    .protect_borders(args.has("--protect-borders"))
                    .protect_sharp_edges(args.has("--protect-sharp"))
                    .relax_constraints(args.has("--relax-constraints"))
                    .stop_when_converged(!args.has("--all-iterations"))
                    .allow_narrow_regions(!args.has("--refuse-narrow"))
                    .project_to_limit_surface(args.has("--project-to-limit"));
  const auto cage = args.has("--project-to-limit") ? examples::cage_surface(mesh) : nullptr;
  // Without --max-memory, the library's default: the memory available.
  const CGAL_ext::Isotropic_remeshing_result result =
    args.has("--max-memory") ? CGAL_ext::isotropic_remeshing(mesh, L, np.maximum_memory(max_memory))
                             : CGAL_ext::isotropic_remeshing(mesh, L, np);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], mesh, examples::write_parameters(args));
  examples::Json_object line;
  line.add("vertices", mesh.number_of_vertices())
    .add("edges", mesh.number_of_edges())
    .add("faces", mesh.number_of_faces())
    .add("border_loops", CGAL_ext::number_of_border_cycles(mesh))
    .add("orientable", CGAL_ext::is_orientable(mesh))
    .add("closed", CGAL_ext::is_closed(mesh))
    .add("components", CGAL_ext::connected_components(mesh).count)
    .add("euler_characteristic", CGAL_ext::euler_characteristic(mesh))
    .add("valid", mesh.is_valid())
    .add("in_band", share_in_band(mesh, L))
    .add("iterations", result.iterations)
    .add("stopped_early", result.stopped_early)
    .add("narrow_faces", result.narrow_faces)
    .add("narrowest_width", result.narrowest_width)
    .add("seconds", seconds);
  if (args.has("--project-to-limit"))
    line.add("limit_distance", examples::limit_distance(mesh, *cage));
  if (!mesh.corner_channels().empty())
    line.add("corner_values_interpolated", result.corner_values_interpolated)
      .add("seam_edges_protected", result.seam_edges_protected);
  if (drop)
    line.add("corner_channels_dropped", dropped);
  examples::print_json_line(line);
  return 0;
}

} // namespace

int main(int argc, char* argv[]) { return examples::run_tool(usage, argc, argv, [&] { return remesh(argc, argv); }); }
