// subdivide IN OUT [--scheme catmull-clark|loop|linear|doo-sabin|sqrt3] [--levels N]
//   [--vertex-rule standard|edge-points] [--boundary none|edge-only|edge-and-corner]
//   [--crease-method uniform|chaikin] [--triangles catmark|smooth] [--kernel double|epick|epeck]
//   [--fvar-interpolation none|corners-only|corners-plus1|corners-plus2|boundaries|all]
//   [--max-memory BYTES] [--drop-corner-data] [--no-tags]
//
// Reads a mesh (OBJ with OpenSubdiv's tags, OFF, PLY), subdivides it and
// writes the result (format by extension); see the usage text below. Bad
// input or options: one line on stderr, exit status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace {

namespace S = CGAL_ext::Subdivision;

const examples::Tool_usage usage{
  "subdivide",
  "subdivide IN OUT [--scheme catmull-clark|loop|linear|doo-sabin|sqrt3] [--levels N] "
  "[--vertex-rule standard|edge-points] [--boundary none|edge-only|edge-and-corner] "
  "[--crease-method uniform|chaikin] [--triangles catmark|smooth] [--kernel double|epick|epeck] "
  "[--fvar-interpolation none|corners-only|corners-plus1|corners-plus2|boundaries|all] "
  "[--max-memory BYTES] [--drop-corner-data] [--no-tags]",
  "Reads a mesh (.obj with OpenSubdiv's tags, .off, .ply), subdivides it and writes the result to\n"
  "OUT (format by extension; an OBJ keeps the tags).\n"
  "  --scheme          catmull-clark (the default), loop, linear, doo-sabin or sqrt3\n"
  "  --levels N        subdivision steps, 0 to 15 (default 1)\n"
  "  --vertex-rule     standard, or edge-points (the smooth vertex rule averages the new edge\n"
  "                    points instead of the old neighbours)\n"
  "  --boundary        border rule: none (OpenSubdiv's hole faces left out), edge-only, edge-and-corner\n"
  "  --crease-method   uniform or chaikin (semi-sharp creases)\n"
  "  --triangles       catmark, or smooth: OpenSubdiv's smooth-triangle rule, a smoother\n"
  "                    Catmull-Clark edge rule next to triangles (OBJ tag 't smoothtriangles')\n"
  "  --kernel          double (the default), epick or epeck\n"
  "  --fvar-interpolation  which texture coordinates and normals stay linear (OpenSubdiv's\n"
  "                    FVarLinearInterpolation): none, corners-only, corners-plus1 (the default),\n"
  "                    corners-plus2, boundaries or all (bilinear)\n"
  "  --max-memory      refuse before starting if the subdivision would need more bytes (the\n"
  "                    library's estimate of its peak; default: the memory available)\n"
  "  --drop-corner-data  go on without the input's texture coordinates and normals where the\n"
  "                    scheme (doo-sabin, sqrt3) or OUT's format cannot carry them (refused otherwise)\n"
  "  --no-tags         write an OBJ without OpenSubdiv's tag lines (creases, corners, options),\n"
  "                    for readers that refuse them (CGAL's)\n"
  "Texture coordinates and normals (OBJ vt/vn) are subdivided with OpenSubdiv's face-varying rules\n"
  "and written to OUT: OBJ holds them per corner, PLY per vertex where they have no seam.\n"
  "The OBJ tags give the defaults of --boundary (else edge-only), --crease-method (else uniform)\n"
  "and --triangles (else catmark); flags override them. The output carries the tags its input\n"
  "had or its flags set, and no others. Prints one JSON line with the result's counts and the\n"
  "subdivision time (without I/O).\n"};

enum class Scheme { catmull_clark, loop, linear, doo_sabin, sqrt3 };
enum class Kernel_choice { simple_cartesian, epick, epeck };

const examples::Choices<Scheme> schemes = {{"catmull-clark", Scheme::catmull_clark},
                                           {"loop", Scheme::loop},
                                           {"linear", Scheme::linear},
                                           {"doo-sabin", Scheme::doo_sabin},
                                           {"sqrt3", Scheme::sqrt3}};
const examples::Choices<Kernel_choice> kernels = {
  {"double", Kernel_choice::simple_cartesian}, {"epick", Kernel_choice::epick}, {"epeck", Kernel_choice::epeck}};
const examples::Choices<S::Vertex_rule> vertex_rules = {{"standard", S::Vertex_rule::standard},
                                                        {"edge-points", S::Vertex_rule::edge_points}};

struct Settings
{
  std::string in, out;
  Scheme scheme = Scheme::catmull_clark;
  Kernel_choice kernel = Kernel_choice::simple_cartesian;
  unsigned levels = 1;
  S::Vertex_rule vertex_rule = S::Vertex_rule::standard;
  CGAL_ext::Sharp_feature_options rule_flags; // --boundary, --crease-method, --triangles
  CGAL_ext::Face_varying_interpolation fvar = CGAL_ext::Face_varying_interpolation::corners_plus1; // as OpenSubdiv
  double max_memory = S::Refinement_options().maximum_memory; // the library's default
  bool drop_corner_data = false;
  bool write_tags = true;
};

Settings parse(int argc, char** argv)
{
  const examples::Arguments args = examples::parse_arguments(
    argc, argv,
    {"--scheme", "--levels", "--vertex-rule", "--boundary", "--crease-method", "--triangles", "--kernel",
     "--fvar-interpolation", "--max-memory"},
    {examples::drop_corner_data_flag, examples::no_tags_flag});
  if (args.positional.size() != 2)
    throw examples::Usage_error("expected two file names, got " + std::to_string(args.positional.size()));
  Settings s;
  s.in = args.positional[0];
  s.out = args.positional[1];
  s.scheme = examples::choice_argument("--scheme", args.value("--scheme", "catmull-clark"), schemes);
  s.kernel = examples::choice_argument("--kernel", args.value("--kernel", "double"), kernels);
  if (args.has("--levels"))
    s.levels = unsigned(examples::integer_argument("--levels", args.value("--levels", ""), 0, 15));
  s.vertex_rule = examples::choice_argument("--vertex-rule", args.value("--vertex-rule", "standard"), vertex_rules);
  s.rule_flags = examples::subdivision_rule_flags(args);
  s.fvar = examples::face_varying_argument(args);
  s.write_tags = !args.has(examples::no_tags_flag);
  s.drop_corner_data = args.has(examples::drop_corner_data_flag);
  if (args.has("--max-memory")) {
    s.max_memory = examples::real_argument("--max-memory", args.value("--max-memory", ""));
    if (!(s.max_memory > 0))
      throw examples::Usage_error("--max-memory '" + args.value("--max-memory", "") + "' is not positive");
  }
  return s;
}

template <class Mesh>
bool is_triangle_mesh(const Mesh& mesh)
{
  for (auto f : mesh.faces())
    if (mesh.degree(f) != 3)
      return false;
  return true;
}

// Under Boundary_interpolation::none OpenSubdiv leaves out the faces it
// marks as holes ("f:hole"); the library keeps them so that the mesh stays a
// manifold, and the tool leaves them out of the file. A face whose removal
// would pinch a vertex waits for its neighbours; any that cannot go stay.
template <class Mesh>
std::size_t remove_hole_faces(Mesh& mesh)
{
  const auto hole = mesh.template property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  if (!hole)
    return 0;
  std::vector<CGAL_ext::Face_index> left;
  for (auto f : mesh.faces())
    if ((*hole)[f] != 0)
      left.push_back(f);
  std::size_t removed = 0;
  for (bool progress = true; progress;) {
    progress = false;
    std::vector<CGAL_ext::Face_index> kept;
    for (auto f : left) {
      if (CGAL_ext::Euler::can_remove_face(mesh.halfedge(f), mesh)) {
        CGAL_ext::Euler::remove_face(mesh.halfedge(f), mesh);
        ++removed;
        progress = true;
      } else {
        kept.push_back(f);
      }
    }
    left.swap(kept);
  }
  if (removed > 0)
    mesh.collect_garbage();
  return removed;
}

template <class K>
void run(const Settings& s)
{
  CGAL_ext::Mobius_mesh<typename K::Point_3> mesh;
  CGAL_ext::IO::check_output_file(s.out); // before the work, not after it
  // Non-manifold input is subdivided as OpenSubdiv does, through manifold
  // sheets, and written joined again.
  CGAL_ext::Sharp_feature_options tags = CGAL_ext::IO::read_polygon_mesh(
    s.in, mesh, CGAL_ext::parameters::non_manifold_policy(CGAL_ext::Non_manifold_policy::split));
  const CGAL_ext::Non_manifold_counts non_manifold = CGAL_ext::non_manifold_counts(mesh);
  // Corner channels go through Catmull-Clark, Loop and (bi)linear with their
  // seams where they are: whether OUT's format holds them is known now. The
  // library refuses them for Doo-Sabin and sqrt3 before any work.
  const bool carried = s.scheme != Scheme::doo_sabin && s.scheme != Scheme::sqrt3;
  const examples::Json_array dropped = examples::drop_corner_channels_if(
    mesh, carried ? examples::why_output_cannot_hold_corner_data(s.out, mesh) : "doo-sabin and sqrt3 do not carry them",
    s.drop_corner_data);
  // The output carries the options the input or the flags set, and no
  // others: a tag line makes the file unreadable to CGAL's OBJ reader, so one
  // is written only where it tells something.
  const CGAL_ext::Sharp_feature_options rules = examples::with_flags(tags, s.rule_flags);
  // The library refuses, before it allocates anything, a subdivision whose
  // estimated peak of memory is above the limit.
  const auto np = examples::subdivision_rule_parameters(rules)
                    .number_of_iterations(s.levels)
                    .vertex_rule(s.vertex_rule)
                    .face_varying_interpolation(s.fvar)
                    .maximum_memory(s.max_memory);

  const auto start = std::chrono::steady_clock::now();
  switch (s.scheme) {
  case Scheme::loop: S::loop(mesh, np); break;
  case Scheme::linear:
    if (is_triangle_mesh(mesh))
      S::linear(mesh, np); // midpoints, each triangle into four
    else
      S::bilinear(mesh, np); // midpoints and centroids, each n-gon into n quads
    break;
  case Scheme::doo_sabin: S::doo_sabin(mesh, np); break;
  case Scheme::sqrt3: S::sqrt3(mesh, np); break;
  case Scheme::catmull_clark: S::catmull_clark(mesh, np); break;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t hole_faces =
    rules.boundary_interpolation == CGAL_ext::Boundary_interpolation::none ? remove_hole_faces(mesh) : 0;
  CGAL_ext::IO::write_polygon_mesh(s.out, mesh, examples::write_parameters(s.write_tags), rules);
  const CGAL_ext::Non_manifold_counts written = CGAL_ext::non_manifold_counts(mesh);
  examples::Json_object line;
  line.add("scheme", examples::choice_name(schemes, s.scheme))
    .add("kernel", examples::choice_name(kernels, s.kernel))
    .add("levels", s.levels)
    .add("fvar_interpolation", examples::choice_name(examples::face_varying_modes(), s.fvar))
    .add("vertices", written.input_vertices) // as written: non-manifold input joined again
    .add("edges", written.input_edges)
    .add("faces", mesh.number_of_faces())
    .add("hole_faces_removed", hole_faces)
    .add("seconds", seconds)
    .add("corner_channels", examples::corner_channels_json(mesh));
  if (s.drop_corner_data)
    line.add("corner_channels_dropped", dropped);
  line.add("non_manifold_vertices", non_manifold.vertices).add("non_manifold_edges", non_manifold.edges);
  examples::print_json_line(line);
}

int subdivide(int argc, char** argv)
{
  const Settings s = parse(argc, argv);
  switch (s.kernel) {
  case Kernel_choice::epick: run<CGAL::Exact_predicates_inexact_constructions_kernel>(s); break;
  case Kernel_choice::epeck: run<CGAL::Exact_predicates_exact_constructions_kernel>(s); break;
  case Kernel_choice::simple_cartesian: run<CGAL::Simple_cartesian<double>>(s); break;
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return examples::run_tool(usage, argc, argv, [&] { return subdivide(argc, argv); });
}
