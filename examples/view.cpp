// view FILE [--scalar NAME | --uv-checker] [--screenshot OUT.png] [--size WxH] [--direction X,Y,Z]
//      [--up X,Y,Z] [--gap G] [--features-only]
//
// Shows a polygon mesh (.obj, .off, .ply) in CGAL's Basic_viewer_qt with one
// colour per side: blue where each face's orientation points, orange on the
// other side; the colours swap across Möbius edges (green), so a one-sided
// surface shows both colours on one side. Borders are red, sharp edges purple.
// With --scalar NAME the faces are coloured by the PLY vertex property NAME
// instead (a colour ramp from its smallest value to its largest), both sides
// alike; a curvature the curvature tool wrote with the side each vertex's
// value is seen from (side_nx, side_ny, side_nz) colours each side by the
// values seen from it. With
// --uv-checker the texture coordinates (OBJ vt) are drawn as a checker of
// 8 x 8 squares per unit, so that seams show where the squares do not meet.
// With --screenshot it draws the mesh once, writes the PNG and prints one
// line of JSON:
//   {"screenshot":"OUT.png","width":W,"height":H,"faces":F,"mobius_edges":M,"border_edges":B
//    [,"scalar":NAME,"min":LOW,"max":HIGH[,"fronts":[A,B]]][,"uv_checker_levels":L,"faces_drawn":D]}
// ("fronts": the range of the faces' fronts' means, where each side is
// coloured by the values seen from it)
// A bad file or option, or no display: one line on stderr, exit status 2.

#include "arguments.h"
#include "json_line.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/draw_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

const examples::Tool_usage usage{
  "view",
  "view FILE [--scalar NAME | --uv-checker] [--screenshot OUT.png] [--size WxH] [--direction X,Y,Z] [--up X,Y,Z] "
  "[--gap G] [--features-only]",
  "Shows a polygon mesh (.obj, .off, .ply) with one colour per side: blue on the side each face's\n"
  "orientation points to, orange on the other. The colours swap across Möbius edges (green), so a\n"
  "one-sided surface shows both on one side. Borders are red, sharp edges purple by sharpness.\n"
  "  --scalar NAME         colour the faces by the vertex property NAME of a PLY file instead (as\n"
  "                        the geodesics and curvature tools write them): each face by the mean of\n"
  "                        its corners, on a ramp from dark violet (the smallest value) through\n"
  "                        blue and green to yellow (the largest), both sides alike. The signed\n"
  "                        curvatures that curvature writes with the side they are seen from\n"
  "                        (mean_curvature, max_curvature, min_curvature with side_nx, side_ny,\n"
  "                        side_nz) colour each side of a face by the values seen from it (from\n"
  "                        the other side H is -H, k1 is -k2), on a ramp over both sides\n"
  "  --uv-checker          draw the texture coordinates (OBJ vt) as a checker of 8 x 8 squares\n"
  "                        per unit, both sides alike: a seam shows where the squares do not meet\n"
  "                        (the faces are split finely enough for the squares, as far as 4 M faces;\n"
  "                        only border, Möbius and sharp edges are drawn)\n"
  "  --screenshot OUT.png  draw once, write the picture and exit (needs a display: xvfb-run)\n"
  "  --size WxH            the picture's size in pixels (default 800x600)\n"
  "  --direction X,Y,Z     the direction the camera looks in (default -1,-0.6,-1.2)\n"
  "  --up X,Y,Z            the direction that is up in the picture (default 0,0,1)\n"
  "                        (these three with --screenshot; the window opens in CGAL's view)\n"
  "  --gap G               the gap between the two sides, a fraction of the bounding box's\n"
  "                        diagonal (default 0.002)\n"
  "  --features-only       draw only border, Möbius and sharp edges, not the others\n"
  "With --screenshot, prints the picture's name and size and the mesh's counts as one line of JSON.\n"};

std::array<double, 3> direction_argument(const std::string& option, const std::string& text)
{
  std::array<double, 3> d{};
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  in >> d[0] >> comma1 >> d[1] >> comma2 >> d[2];
  if (!in || comma1 != ',' || comma2 != ',' || in.peek() != std::char_traits<char>::eof() ||
      (d[0] == 0 && d[1] == 0 && d[2] == 0))
    throw examples::Usage_error(option + " '" + text + "' is not three numbers X,Y,Z, not all 0");
  return d;
}

// The value of each vertex in its vertex property map "v:NAME", of any
// arithmetic type the PLY reader makes; none if there is no such map.
template <class Mesh>
std::vector<double> vertex_values(const Mesh& mesh, const std::string& name)
{
  std::vector<double> values;
  const auto take = [&](auto zero) {
    const auto map = mesh.template property_map<CGAL_ext::Vertex_index, decltype(zero)>("v:" + name);
    if (map && values.empty())
      for (CGAL_ext::Vertex_index v : mesh.vertices())
        values.push_back(double((*map)[v]));
  };
  take(double()), take(float()), take(std::int8_t()), take(std::uint8_t()), take(std::int16_t());
  take(std::uint16_t()), take(std::int32_t()), take(std::uint32_t());
  return values;
}

// vertex_values(), refused where the file has no property NAME.
template <class Mesh>
std::vector<double> vertex_scalars(const Mesh& mesh, const std::string& file, const std::string& name)
{
  std::vector<double> values = vertex_values(mesh, name);
  if (values.empty() && mesh.number_of_vertices() != 0) {
    std::string names;
    for (const std::string& p : mesh.template properties<CGAL_ext::Vertex_index>())
      if (p.rfind("v:", 0) == 0 && p != "v:point")
        names += (names.empty() ? "" : ", ") + p.substr(2);
    throw std::runtime_error(file + " has no vertex property '" + name + "' of numbers (" +
                             (names.empty() ? std::string("it has none") : "it has: " + names) + ")");
  }
  return values;
}

// A colour ramp of increasing lightness, from dark violet through blue and
// green to yellow (close to matplotlib's viridis), at t in [0, 1].
CGAL::IO::Color ramp(double t)
{
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 4;
  const int i = std::min(int(t), 3);
  const double u = t - i;
  unsigned char rgb[3];
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(std::lround(stops[i][c] + u * (stops[i + 1][c] - stops[i][c])));
  return CGAL::IO::Color(rgb[0], rgb[1], rgb[2]);
}

// The smallest and largest finite values.
void finite_range(const std::vector<double>& values, double& low, double& high)
{
  low = std::numeric_limits<double>::infinity();
  high = -low;
  for (double x : values)
    if (std::isfinite(x)) {
      low = std::min(low, x);
      high = std::max(high, x);
    }
}

// The colour of a value on the ramp from `low` to `high`; grey where it is
// not finite.
CGAL::IO::Color ramp_colour(double x, double low, double high)
{
  return !std::isfinite(x) ? CGAL::IO::Color(128, 128, 128) : ramp(high > low ? (x - low) / (high - low) : 0.0);
}

// Each face's colour, in the face property map "f:ramp": the mean of its
// corners' values on the ramp from the smallest finite value to the largest.
template <class Mesh>
typename Mesh::template Property_map<CGAL_ext::Face_index, CGAL::IO::Color>
face_colours(Mesh& mesh, const std::vector<double>& values, double& low, double& high)
{
  finite_range(values, low, high);
  auto colours = mesh.template add_property_map<CGAL_ext::Face_index, CGAL::IO::Color>("f:ramp").first;
  for (CGAL_ext::Face_index f : mesh.faces()) {
    double sum = 0, n = 0;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(mesh.halfedge(f), mesh)) {
      sum += values[v.idx()];
      ++n;
    }
    colours[f] = ramp_colour(sum / n, low, high);
  }
  return colours;
}

// The fields that the curvature tool writes as seen from the side whose
// unit normal is (side_nx, side_ny, side_nz), and for each the field whose
// opposite is its value from the other side: H becomes -H, and k1 and k2
// become -k2 and -k1.
const std::map<std::string, std::string> other_side_of = {
  {"mean_curvature", "mean_curvature"}, {"max_curvature", "min_curvature"}, {"min_curvature", "max_curvature"}};

// Each side's colour, by face: front then back. `values` are seen from the
// side whose normal is `sides` at each vertex, `other` (negated) from the
// other side; a face's corner sees the side of its dart d into the vertex
// where that normal agrees with vertex_normal(d). Each side shows the mean
// over its corners, on a ramp over the values from both sides; `fronts`
// receives the smallest and largest of the fronts' means.
template <class Mesh>
std::vector<std::array<CGAL::IO::Color, 2>> side_colours(const Mesh& mesh, const std::vector<double>& values,
                                                         const std::vector<double>& other,
                                                         const std::array<std::vector<double>, 3>& sides,
                                                         double& low, double& high, std::array<double, 2>& fronts)
{
  std::vector<double> both = values;
  for (double x : other)
    both.push_back(-x);
  finite_range(both, low, high);
  std::vector<std::array<CGAL::IO::Color, 2>> colours(mesh.num_faces());
  fronts = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (CGAL_ext::Face_index f : mesh.faces()) {
    double front = 0, back = 0, n = 0;
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const std::size_t v = mesh.target(d).idx();
      const auto normal = CGAL_ext::vertex_normal(d, mesh);
      const double dot = CGAL::to_double(normal.x()) * sides[0][v] + CGAL::to_double(normal.y()) * sides[1][v] +
                         CGAL::to_double(normal.z()) * sides[2][v];
      front += dot < 0 ? -other[v] : values[v];
      back += dot < 0 ? values[v] : -other[v];
      ++n;
    }
    colours[f.idx()] = {ramp_colour(front / n, low, high), ramp_colour(back / n, low, high)};
    fronts = {std::min(fronts[0], front / n), std::max(fronts[1], front / n)};
  }
  return colours;
}

// --uv-checker: each face split by bilinear subdivision, which carries the
// texture coordinates linearly (Face_varying_interpolation::all), until the
// largest face spans at most about a quarter of a square (each level halves
// the span of a quad; a triangle's first split, into quads, two thirds), or
// the mesh would pass 4 M faces; each piece coloured by the square its mean
// coordinates fall in.
// Returns the levels of splitting.
constexpr double checker_squares = 8; // per unit of texture coordinate

template <class Mesh>
int split_for_checker(Mesh& mesh, const std::string& file)
{
  using Uv = CGAL_ext::Corner_uv<typename Mesh::Point>;
  const auto uv = mesh.template corner_channel<Uv>(CGAL_ext::corner_uv_name);
  if (!uv)
    throw std::runtime_error(file + " has no texture coordinates (vt) for --uv-checker");
  double span = 0;
  for (CGAL_ext::Face_index f : mesh.faces())
    for (CGAL_ext::Dart a : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
      if (!uv->has_value(mesh.corner(a)))
        throw std::runtime_error(file + ": face " + std::to_string(f.idx()) +
                                 " has a corner without texture coordinates, which --uv-checker needs at every corner");
      for (CGAL_ext::Dart b : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh))
        if (uv->has_value(mesh.corner(b)))
          span = std::max({span, std::abs((*uv)[mesh.corner(a)].x() - (*uv)[mesh.corner(b)].x()),
                           std::abs((*uv)[mesh.corner(a)].y() - (*uv)[mesh.corner(b)].y())});
    }
  int levels = 0;
  for (double faces = double(mesh.number_of_faces()) * 4; span * checker_squares > 0.25 && faces <= 4e6;
       faces *= 4, span /= 2)
    ++levels;
  // Other channels (normals) are not drawn: left out rather than split.
  for (const std::string& name : mesh.corner_channels())
    if (name != CGAL_ext::corner_uv_name)
      mesh.remove_corner_channel(name);
  CGAL_ext::Subdivision::bilinear(mesh, CGAL_ext::parameters::number_of_iterations(levels).face_varying_interpolation(
                                          CGAL_ext::Face_varying_interpolation::all));
  return levels;
}

template <class Mesh>
typename Mesh::template Property_map<CGAL_ext::Face_index, CGAL::IO::Color> checker_colours(Mesh& mesh)
{
  using Uv = CGAL_ext::Corner_uv<typename Mesh::Point>;
  const auto uv = *mesh.template corner_channel<Uv>(CGAL_ext::corner_uv_name);
  auto colours = mesh.template add_property_map<CGAL_ext::Face_index, CGAL::IO::Color>(
                       "f:checker", CGAL::IO::Color(128, 128, 128)).first;
  for (CGAL_ext::Face_index f : mesh.faces()) {
    double u = 0, v = 0, n = 0;
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
      u += uv[mesh.corner(d)].x();
      v += uv[mesh.corner(d)].y();
      ++n;
    }
    const long square = std::lround(std::floor(u / n * checker_squares) + std::floor(v / n * checker_squares));
    colours[f] = square % 2 == 0 ? CGAL::IO::Color(235, 225, 200) : CGAL::IO::Color(70, 90, 150);
  }
  return colours;
}

void size_argument(const std::string& text, CGAL_ext::Screenshot_settings& settings)
{
  const auto x = text.find('x');
  if (x == std::string::npos)
    throw examples::Usage_error("--size '" + text + "' is not WxH");
  settings.width = int(examples::integer_argument("--size", text.substr(0, x), 16, 8192));
  settings.height = int(examples::integer_argument("--size", text.substr(x + 1), 16, 8192));
}

int view(int argc, char** argv)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
  const examples::Arguments args =
    examples::parse_arguments(argc, argv, {"--scalar", "--screenshot", "--size", "--direction", "--up", "--gap"},
                              {"--features-only", "--uv-checker"});
  if (args.has("--scalar") && args.has("--uv-checker"))
    throw examples::Usage_error("--scalar and --uv-checker colour the faces both: give one");
  if (args.positional.size() != 1)
    throw examples::Usage_error("expected one file name, got " + std::to_string(args.positional.size()));
  CGAL_ext::Screenshot_settings settings;
  if (args.has("--size"))
    size_argument(args.value("--size", ""), settings);
  if (args.has("--direction"))
    settings.view_direction = direction_argument("--direction", args.value("--direction", ""));
  if (args.has("--up"))
    settings.up_vector = direction_argument("--up", args.value("--up", ""));
  CGAL_ext::Two_sided_style style;
  if (args.has("--gap"))
    style.gap = examples::real_argument("--gap", args.value("--gap", ""));
  if (!(style.gap >= 0 && style.gap < 1))
    throw examples::Usage_error("--gap '" + args.value("--gap", "") + "' is not from 0 to 1");
  style.plain_edges = !args.has("--features-only") && !args.has("--uv-checker");

  Mesh mesh;
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], mesh);
  const auto show = [&](const auto& np) {
    if (!args.has("--screenshot"))
      CGAL_ext::draw(mesh, np, args.positional[0].c_str());
    else
      CGAL_ext::save_screenshot(mesh, args.value("--screenshot", ""), settings, np);
  };
  // Without --scalar every face keeps the style's two side colours.
  const auto np = CGAL_ext::parameters::two_sided_style(style);
  double low = 0, high = 0;
  std::array<double, 2> fronts{};
  bool sided = false;
  int checker_levels = 0;
  // The file's counts, before --uv-checker splits the faces.
  const std::size_t faces = mesh.number_of_faces();
  std::size_t mobius = 0, border = 0;
  for (auto e : mesh.edges()) {
    mobius += mesh.is_mobius(e);
    border += mesh.is_border(e);
  }
  if (args.has("--uv-checker")) {
    checker_levels = split_for_checker(mesh, args.positional[0]);
    show(np.face_color_map(checker_colours(mesh)));
  } else if (args.has("--scalar")) {
    const std::string name = args.value("--scalar", "");
    const std::vector<double> values = vertex_scalars(mesh, args.positional[0], name);
    const std::array<std::vector<double>, 3> sides{vertex_values(mesh, "side_nx"), vertex_values(mesh, "side_ny"),
                                                   vertex_values(mesh, "side_nz")};
    const auto other = other_side_of.find(name);
    const std::vector<double> other_values =
      other == other_side_of.end() ? std::vector<double>() : vertex_values(mesh, other->second);
    if (sides[0].empty() || sides[1].empty() || sides[2].empty() || other_values.empty()) {
      show(np.face_color_map(face_colours(mesh, values, low, high)));
    } else {
      const auto colours = side_colours(mesh, values, other_values, sides, low, high, fronts);
      sided = true;
      show(np.face_color_map(boost::make_function_property_map<CGAL_ext::Dart>(
        [&](CGAL_ext::Dart d) { return colours[mesh.face(d).idx()][d.is_flipped() ? 1 : 0]; })));
    }
  } else
    show(np);
  if (!args.has("--screenshot"))
    return 0;
  const std::string out = args.value("--screenshot", "");
  examples::Json_object line;
  line.add("screenshot", out)
    .add("width", settings.width)
    .add("height", settings.height)
    .add("faces", faces)
    .add("mobius_edges", mobius)
    .add("border_edges", border);
  if (args.has("--scalar"))
    line.add("scalar", args.value("--scalar", "")).add("min", low).add("max", high);
  if (sided)
    line.add("fronts", examples::Json_array().add(fronts[0]).add(fronts[1]));
  if (args.has("--uv-checker"))
    line.add("uv_checker_levels", checker_levels).add("faces_drawn", mesh.number_of_faces());
  examples::print_json_line(line);
  return 0;
}

} // namespace

int main(int argc, char* argv[]) { return examples::run_tool(usage, argc, argv, [&] { return view(argc, argv); }); }
