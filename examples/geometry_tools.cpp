// The geometry tools, on any surface, one-sided ones included:
//
//   geodesics IN OUT.ply --source V[,W...] [--method heat|heat-intrinsic|exact] [--triangulate]
//   fill_holes IN OUT [--fill triangulate|refine|fair] [--triangulate]
//   smooth IN OUT [--iterations K] [--time T] [--triangulate]
//   curvature IN OUT.ply [--triangulate]
//
// Each reads a polygon mesh (.obj, .off, .ply), writes OUT and prints one line
// of JSON: the counts of the result (mesh_summary.h) and the tool's figures.
// geodesics and curvature write their values as PLY vertex properties, which
// viewers colour by (`view OUT.ply --scalar distance`). A bad file or option:
// one line on stderr, exit status 2.
//
// One translation unit for the four (see geometry_tools.h): CGAL's heat
// method, shortest paths, hole filling and fairing compile for minutes.

#include "geometry_tools.h"

#include "arguments.h"
#include "json_line.h"
#include "mesh_summary.h"

#include <CGAL_ext/Curvature/discrete_curvatures.h>
#include <CGAL_ext/Curvature/principal_curvatures.h>
#include <CGAL_ext/Geodesics/geodesic_distances.h>
#include <CGAL_ext/Hole_filling/triangulate_hole.h>
#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Smoothing/smooth_shape.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace examples {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
using CGAL_ext::Dart;
using CGAL_ext::Face_index;
using CGAL_ext::Vertex_index;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void require_file_names(const Arguments& args)
{
  if (args.positional.size() != 2)
    throw Usage_error("expected two file names, got " + std::to_string(args.positional.size()));
}

// The values of geodesics and curvature are vertex properties, which only
// PLY carries.
void require_ply_output(const std::string& out)
{
  const std::size_t dot = out.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : out.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".ply")
    throw Usage_error("OUT '" + out + "' is not a .ply file: PLY carries the values per vertex");
}

// Refuses a mesh with faces other than triangles, with one line that names
// what needs triangles (`needs`) and says how to go on.
void require_triangles(const Mesh& mesh, const std::string& file, const char* needs)
{
  std::size_t others = 0;
  for (Face_index f : mesh.faces())
    others += mesh.degree(f) != 3 ? 1 : 0;
  if (others != 0)
    throw std::runtime_error(file + ": " + std::to_string(others) + " of its " +
                             std::to_string(mesh.number_of_faces()) + " faces are not triangles, and " + needs +
                             " needs a triangle mesh (give --triangulate)");
}

// The mesh of `file`; with `triangulate`, its polygons split into triangles
// (`added`: the faces that adds). Where `needs` names what needs triangles,
// a mesh with other faces is refused.
Mesh read_mesh(const std::string& file, bool triangulate, const char* needs, std::size_t& added)
{
  Mesh mesh;
  CGAL_ext::IO::read_polygon_mesh(file, mesh);
  added = triangulate ? CGAL_ext::triangulate_faces(mesh) : 0;
  if (needs != nullptr)
    require_triangles(mesh, file, needs);
  return mesh;
}

// A vertex property map "v:NAME" for the output: the input's own if it has
// one of that name and type (read from an earlier output), a new one else.
template <class T>
Mesh::Property_map<Vertex_index, T> output_map(Mesh& mesh, const std::string& name)
{
  const auto [map, created] = mesh.add_property_map<Vertex_index, T>("v:" + name, T());
  (void)created;
  if (!map)
    throw std::runtime_error("the input has a vertex property '" + name + "' of another type");
  return map;
}

// ------------------------------------------------------------------ geodesics

const Tool_usage geodesics_usage{
  "geodesics", "geodesics IN OUT.ply --source V[,W...] [--method heat|heat-intrinsic|exact] [--triangulate]",
  "Reads a triangle mesh (.obj, .off, .ply), one-sided or not, and computes the geodesic distance\n"
  "along the surface from the source vertices (numbered from 0 in the order of the file) to every\n"
  "vertex. Distance needs no orientation: on a one-sided surface it is computed where CGAL can walk\n"
  "the mesh, and on its orientation double cover from both lifts of each source where it cannot.\n"
  "  --method heat   CGAL's heat method (Heat_method_3, Direct), an approximation (default)\n"
  "  --method heat-intrinsic  the heat method on the intrinsic Delaunay triangulation\n"
  "                  (Heat_method_3, Intrinsic_Delaunay): better on meshes with obtuse triangles\n"
  "  --method exact  CGAL's exact shortest paths on the piecewise flat surface (Surface_mesh_shortest_path)\n"
  "  --triangulate   split polygons into triangles first (else they are an error)\n"
  "Writes OUT.ply with the distance as the vertex property 'distance' (double), and prints the\n"
  "counts, the distance at the sources, the largest distance and its vertex as one line of JSON.\n"};

enum class Geodesic_method { heat, heat_intrinsic, exact };

const Choices<Geodesic_method> geodesic_methods = {{"heat", Geodesic_method::heat},
                                                   {"heat-intrinsic", Geodesic_method::heat_intrinsic},
                                                   {"exact", Geodesic_method::exact}};

// "V[,W...]": vertices of `mesh`, by their index in the file.
std::vector<Vertex_index> source_vertices(const std::string& text, const Mesh& mesh)
{
  std::vector<Vertex_index> sources;
  const long last = long(mesh.number_of_vertices()) - 1;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = text.find(',', begin);
    const std::string item = text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    sources.push_back(Vertex_index(std::uint32_t(integer_argument("--source", item, 0, last))));
    if (comma == std::string::npos)
      return sources;
    begin = comma + 1;
  }
}

int geodesics(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv, {"--source", "--method"}, {"--triangulate"});
  require_file_names(args);
  if (!args.has("--source"))
    throw Usage_error("--source is required");
  const Geodesic_method method = choice_argument("--method", args.value("--method", "heat"), geodesic_methods);
  require_ply_output(args.positional[1]);

  std::size_t triangulated = 0;
  Mesh mesh = read_mesh(args.positional[0], args.has("--triangulate"), "the geodesic distance", triangulated);
  const std::vector<Vertex_index> sources = source_vertices(args.value("--source", ""), mesh);
  // CGAL's heat method factors a matrix that a vertex on no face makes
  // singular, and stops with an assertion: say why instead.
  for (Vertex_index v : mesh.vertices())
    if (method != Geodesic_method::exact && !mesh.halfedge(v).is_valid())
      throw std::runtime_error(args.positional[0] + ": vertex " + std::to_string(v.idx()) +
                               " is on no face, and the heat method needs every vertex on one (--method exact "
                               "takes it)");
  auto distance = output_map<double>(mesh, "distance");
  const Clock::time_point start = Clock::now();
  if (method == Geodesic_method::heat)
    CGAL_ext::estimate_geodesic_distances(mesh, distance, sources);
  else if (method == Geodesic_method::heat_intrinsic)
    CGAL_ext::estimate_geodesic_distances<CGAL::Heat_method_3::Intrinsic_Delaunay>(mesh, distance, sources);
  else
    CGAL_ext::exact_geodesic_distances(mesh, distance, sources);
  const double seconds = seconds_since(start);

  double at_sources = 0, largest = 0;
  Vertex_index farthest = sources.front();
  for (Vertex_index s : sources)
    at_sources = std::max(at_sources, std::abs(distance[s]));
  for (Vertex_index v : mesh.vertices())
    if (std::isfinite(distance[v]) && distance[v] > largest) {
      largest = distance[v];
      farthest = v;
    }
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], mesh);
  print_json_line(mesh_summary(mesh)
                    .add("triangulated_faces", triangulated)
                    .add("method", choice_name(geodesic_methods, method))
                    .add("sources", sources.size())
                    .add("distance_at_sources", at_sources)
                    .add("max_distance", largest)
                    .add("farthest_vertex", std::size_t(farthest.idx()))
                    .add("seconds", seconds));
  return 0;
}

// ----------------------------------------------------------------- fill_holes

const Tool_usage fill_holes_usage{
  "fill_holes", "fill_holes IN OUT [--fill triangulate|refine|fair] [--triangulate]",
  "Reads a polygon mesh (.obj, .off, .ply), one-sided or not, and fills every hole: each border\n"
  "loop is triangulated as CGAL's triangulate_hole() does it (Liepa's weights), then refined and\n"
  "faired as by triangulate_refine_and_fair_hole(). A loop that passes a Möbius connection is one\n"
  "hole, and its patch is glued across it: capping a Möbius strip gives a projective plane.\n"
  "  --fill triangulate  triangulate each hole only (any faces around it)\n"
  "  --fill refine       triangulate and refine, so that the patch's triangles match the mesh's\n"
  "  --fill fair         triangulate, refine and fair: the patch bends as the surface (default)\n"
  "  --triangulate       split polygons into triangles first (refining and fairing need them)\n"
  "Writes OUT and prints its counts, the holes found and filled, and the faces and vertices added\n"
  "as one line of JSON.\n"};

enum class Fill { triangulate, refine, fair };

const Choices<Fill> fills = {{"triangulate", Fill::triangulate}, {"refine", Fill::refine}, {"fair", Fill::fair}};

int fill_holes(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv, {"--fill"}, {"--triangulate"});
  require_file_names(args);
  const Fill fill = choice_argument("--fill", args.value("--fill", "fair"), fills);

  std::size_t triangulated = 0;
  Mesh mesh = read_mesh(args.positional[0], args.has("--triangulate"), nullptr, triangulated);
  const std::vector<Dart> holes = CGAL_ext::border_cycles(mesh);
  if (!holes.empty() && fill != Fill::triangulate)
    require_triangles(mesh, args.positional[0], "refining and fairing a hole");
  const Clock::time_point start = Clock::now();
  std::size_t filled = 0, faired = 0, new_faces = 0, new_vertices = 0;
  // Each loop's dart stays a border dart while the others are filled: a
  // patch only adds faces in its own loop, and refining and fairing move
  // and split inside the patch.
  for (Dart hole : holes) {
    std::vector<Face_index> faces;
    std::vector<Vertex_index> vertices;
    if (fill == Fill::triangulate) {
      CGAL_ext::triangulate_hole(mesh, hole, std::back_inserter(faces));
    } else if (fill == Fill::refine) {
      CGAL_ext::triangulate_and_refine_hole(mesh, hole, std::back_inserter(faces), std::back_inserter(vertices));
    } else {
      const auto result = CGAL_ext::triangulate_refine_and_fair_hole(mesh, hole, std::back_inserter(faces),
                                                                     std::back_inserter(vertices));
      faired += std::get<0>(result) && !faces.empty() ? 1 : 0;
    }
    filled += faces.empty() ? 0 : 1;
    new_faces += faces.size();
    new_vertices += vertices.size();
  }
  const double seconds = seconds_since(start);
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], mesh);
  Json_object line = mesh_summary(mesh);
  line.add("triangulated_faces", triangulated)
    .add("fill", choice_name(fills, fill))
    .add("holes", holes.size())
    .add("filled", filled);
  if (fill == Fill::fair)
    line.add("faired", faired);
  else
    line.add("faired", nullptr);
  print_json_line(line.add("new_faces", new_faces).add("new_vertices", new_vertices).add("seconds", seconds));
  return 0;
}

// --------------------------------------------------------------------- smooth

const Tool_usage smooth_usage{
  "smooth", "smooth IN OUT [--iterations K] [--time T] [--triangulate]",
  "Reads a triangle mesh (.obj, .off, .ply), one-sided or not, and smooths its shape by CGAL's\n"
  "implicit mean curvature flow (Polygon_mesh_processing::smooth_shape()); the connectivity stays.\n"
  "A closed surface is rescaled after each step, by its enclosed volume where it is orientable (as\n"
  "in CGAL) and by its area where it is one-sided (it encloses no volume); one with a border is\n"
  "not rescaled (as in CGAL).\n"
  "  --iterations K  the number of steps (default 1)\n"
  "  --time T        the time step, in squared units of length (default 1e-4, as in CGAL's example)\n"
  "  --triangulate   split polygons into triangles first (else they are an error)\n"
  "Writes OUT and prints its counts, its area before and after, and the time taken as one line of\n"
  "JSON.\n"};

int smooth(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv, {"--iterations", "--time"}, {"--triangulate"});
  require_file_names(args);
  const long iterations = integer_argument("--iterations", args.value("--iterations", "1"), 0, 1000000);
  const double time = real_argument("--time", args.value("--time", "1e-4"));
  if (!(time > 0))
    throw Usage_error("--time '" + args.value("--time", "") + "' is not positive");

  std::size_t triangulated = 0;
  Mesh mesh = read_mesh(args.positional[0], args.has("--triangulate"), "smoothing", triangulated);
  const double area_before = CGAL::to_double(CGAL::Polygon_mesh_processing::area(mesh));
  const Clock::time_point start = Clock::now();
  CGAL_ext::smooth_shape(mesh, time, CGAL::parameters::number_of_iterations(unsigned(iterations)));
  const double seconds = seconds_since(start);
  const double area_after = CGAL::to_double(CGAL::Polygon_mesh_processing::area(mesh));
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], mesh);
  print_json_line(mesh_summary(mesh)
                    .add("triangulated_faces", triangulated)
                    .add("iterations", iterations)
                    .add("time_step", time)
                    .add("area_before", area_before)
                    .add("area_after", area_after)
                    .add("seconds", seconds));
  return 0;
}

// ------------------------------------------------------------------ curvature

const Tool_usage curvature_usage{
  "curvature", "curvature IN OUT.ply [--triangulate]",
  "Reads a triangle mesh (.obj, .off, .ply), one-sided or not, and writes OUT.ply with discrete\n"
  "curvatures as vertex properties (doubles), for a viewer to colour by:\n"
  "  angle_defect         the Gaussian curvature integrated over the vertex's share of the surface:\n"
  "                       2 pi minus its corner angles (pi minus them on the border); they sum to\n"
  "                       2 pi times the Euler characteristic (Gauss-Bonnet)\n"
  "  gaussian_curvature   the angle defect per unit area (a third of the vertex's triangles)\n"
  "  mean_curvature_norm  |H|, the length of the mean curvature vector (cotangent formula), which\n"
  "                       needs no orientation: the same on both sides of a one-sided surface\n"
  "  side_nx, side_ny, side_nz  the unit normal of the side the next three are seen from: the side\n"
  "                       the faces' orientation points to where the vertex's faces agree (files\n"
  "                       are read oriented: everywhere on an orientable surface), one of the two\n"
  "                       at a vertex on a Moebius edge. A one-sided surface has these curvatures\n"
  "                       per side, not per vertex: seen from the side whose normal is n they are\n"
  "                       multiplied by the sign of n . side_n (k1 and k2 trading places where it\n"
  "                       is -1); `view OUT.ply --scalar mean_curvature` (or max_curvature,\n"
  "                       min_curvature) colours each side so.\n"
  "  mean_curvature       H, signed, seen from that side (CGAL_ext::mean_curvature(dart, mesh))\n"
  "  max_curvature, min_curvature  the principal curvatures k1 >= k2 from that side (a cubic jet\n"
  "                       fitted to two rings, CGAL_ext::principal_curvatures()); NaN at a vertex\n"
  "                       where no jet can be fitted (fewer than 6 points within two rings, no\n"
  "                       normal), counted in the JSON line (without_principal_curvatures).\n"
  "  --triangulate        split polygons into triangles first (else they are an error)\n"
  "Prints the counts, the total angle defect, the ranges of the curvatures and the number of\n"
  "vertices on a Moebius edge (whose side is a choice) as one line of JSON.\n"};

// The side the signed curvatures of `v` are seen from: the front of its
// first face, as a dart into `v` (none for a vertex on no face). Where the
// faces at `v` agree (no Möbius edge there: everywhere on an oriented
// surface) that is the front of all of them.
Dart vertex_side(const Mesh& mesh, Vertex_index v)
{
  if (!mesh.halfedge(v).is_valid())
    return Dart(); // a vertex on no face
  for (Dart d : CGAL_ext::halfedges_around_target(mesh.halfedge(v), mesh))
    if (!mesh.is_border(d))
      return d.is_flipped() ? mesh.next(d).flipped() : d; // the face's own dart into v
  return Dart();
}

// True if the faces at `v` do not all see one side of it from the front.
bool on_mobius_edge(const Mesh& mesh, Vertex_index v)
{
  bool front = false, back = false;
  if (mesh.halfedge(v).is_valid())
    for (Dart d : CGAL_ext::halfedges_around_target(mesh.halfedge(v), mesh))
      if (!mesh.is_border(d))
        (d.is_flipped() ? back : front) = true;
  return front && back;
}

// A third of the area of the triangles at `v`: its share of the surface.
double vertex_area(const Mesh& mesh, Vertex_index v)
{
  double area = 0;
  if (!mesh.halfedge(v).is_valid())
    return area; // a vertex on no face
  for (Dart d : CGAL_ext::halfedges_around_target(mesh.halfedge(v), mesh))
    if (!mesh.is_border(d))
      area += std::sqrt(CGAL::to_double(CGAL::squared_area(mesh.point(mesh.source(d)), mesh.point(v),
                                                           mesh.point(mesh.target(mesh.next(d)))))) / 3;
  return area;
}

// k1 >= k2 seen from the side of `d`. None (NaN, counted by the caller)
// where the jet cannot be fitted: a vertex on no face, fewer than 6 points
// within two rings (a small component), no normal (degenerate faces).
std::optional<std::array<double, 2>> principal_curvatures_from(const Mesh& mesh, Dart d)
{
  if (!d.is_valid())
    return std::nullopt;
  try {
    const CGAL_ext::Principal_curvatures c = CGAL_ext::principal_curvatures(d, mesh);
    return std::array<double, 2>{c.max_curvature, c.min_curvature};
  } catch (const CGAL_ext::Parameter_error&) {
    return std::nullopt;
  }
}

// The unit normal of the side of `d` (zero where there is none).
std::array<double, 3> side_normal(const Mesh& mesh, Dart d)
{
  if (!d.is_valid())
    return {0, 0, 0};
  const Kernel::Vector_3 n = CGAL_ext::vertex_normal(d, mesh);
  const double length = std::sqrt(CGAL::to_double(n.squared_length()));
  if (!(length > 0))
    return {0, 0, 0};
  return {CGAL::to_double(n.x()) / length, CGAL::to_double(n.y()) / length, CGAL::to_double(n.z()) / length};
}

struct Range
{
  double low = std::numeric_limits<double>::infinity(), high = -std::numeric_limits<double>::infinity();
  void add(double x)
  {
    low = std::min(low, x);
    high = std::max(high, x);
  }
  Json_array json() const { return Json_array().add(low).add(high); }
};

// The output maps of the curvatures seen from a side, and their ranges.
struct Side_curvatures
{
  explicit Side_curvatures(Mesh& mesh)
    : side{output_map<double>(mesh, "side_nx"), output_map<double>(mesh, "side_ny"), output_map<double>(mesh, "side_nz")},
      mean(output_map<double>(mesh, "mean_curvature")), k1(output_map<double>(mesh, "max_curvature")),
      k2(output_map<double>(mesh, "min_curvature"))
  {}

  void compute(const Mesh& mesh, Vertex_index v)
  {
    const Dart d = vertex_side(mesh, v);
    const std::array<double, 3> n = side_normal(mesh, d);
    for (int i = 0; i < 3; ++i)
      side[i][v] = n[std::size_t(i)];
    mean[v] = d.is_valid() ? CGAL_ext::mean_curvature(d, mesh) : 0.0;
    mean_range.add(mean[v]);
    const std::optional<std::array<double, 2>> k = principal_curvatures_from(mesh, d);
    k1[v] = k ? (*k)[0] : std::numeric_limits<double>::quiet_NaN();
    k2[v] = k ? (*k)[1] : std::numeric_limits<double>::quiet_NaN();
    if (k) {
      k1_range.add((*k)[0]);
      k2_range.add((*k)[1]);
    } else {
      ++without_principal;
    }
    on_mobius_edges += on_mobius_edge(mesh, v) ? 1 : 0;
  }

  Mesh::Property_map<Vertex_index, double> side[3], mean, k1, k2;
  Range mean_range, k1_range, k2_range;
  std::size_t without_principal = 0, on_mobius_edges = 0;
};

int curvature(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv, {}, {"--triangulate"});
  require_file_names(args);
  require_ply_output(args.positional[1]);

  std::size_t triangulated = 0;
  Mesh mesh = read_mesh(args.positional[0], args.has("--triangulate"), "the mean curvature", triangulated);
  auto defect = output_map<double>(mesh, "angle_defect");
  auto gaussian = output_map<double>(mesh, "gaussian_curvature");
  auto norm = output_map<double>(mesh, "mean_curvature_norm");
  Side_curvatures sided(mesh);
  double total = 0;
  Range gaussian_range, norm_range;
  for (Vertex_index v : mesh.vertices()) {
    defect[v] = CGAL_ext::angle_defect(v, mesh);
    total += defect[v];
    const double area = vertex_area(mesh, v);
    gaussian[v] = area > 0 ? defect[v] / area : 0.0;
    gaussian_range.add(gaussian[v]);
    const std::array<double, 3> h = CGAL_ext::mean_curvature_vector(v, mesh);
    norm[v] = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    norm_range.add(norm[v]);
    sided.compute(mesh, v);
  }
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], mesh);
  print_json_line(mesh_summary(mesh)
                    .add("triangulated_faces", triangulated)
                    .add("total_angle_defect", total)
                    .add("gaussian_curvature", gaussian_range.json())
                    .add("mean_curvature_norm", norm_range.json())
                    .add("without_principal_curvatures", sided.without_principal)
                    .add("vertices_on_mobius_edges", sided.on_mobius_edges)
                    .add("max_curvature", sided.k1_range.json())
                    .add("min_curvature", sided.k2_range.json())
                    .add("mean_curvature", sided.mean_range.json()));
  return 0;
}

} // namespace

int geodesics_tool(int argc, char** argv)
{
  return run_tool(geodesics_usage, argc, argv, [&] { return geodesics(argc, argv); });
}

int fill_holes_tool(int argc, char** argv)
{
  return run_tool(fill_holes_usage, argc, argv, [&] { return fill_holes(argc, argv); });
}

int smooth_tool(int argc, char** argv) { return run_tool(smooth_usage, argc, argv, [&] { return smooth(argc, argv); }); }

int curvature_tool(int argc, char** argv)
{
  return run_tool(curvature_usage, argc, argv, [&] { return curvature(argc, argv); });
}

} // namespace examples
