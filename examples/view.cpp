// view FILE [--screenshot OUT.png] [--size WxH] [--direction X,Y,Z] [--up X,Y,Z] [--gap G] [--features-only]
//
// Shows a polygon mesh (.obj, .off, .ply) in CGAL's Basic_viewer_qt with one
// colour per side: blue where each face's orientation points, orange on the
// other side; the colours swap across Möbius edges (green), so a one-sided
// surface shows both colours on one side. Borders are red, sharp edges purple.
// With --screenshot it draws the mesh once, writes the PNG and prints one
// line of JSON:
//   {"screenshot":"OUT.png","width":W,"height":H,"faces":F,"mobius_edges":M,"border_edges":B}
// A bad file or option, or no display: one line on stderr, exit status 2.

#include "arguments.h"
#include "json_line.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/draw_mobius_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <sstream>
#include <string>

namespace {

const examples::Tool_usage usage{
  "view", "view FILE [--screenshot OUT.png] [--size WxH] [--direction X,Y,Z] [--up X,Y,Z] [--gap G] [--features-only]",
  "Shows a polygon mesh (.obj, .off, .ply) with one colour per side: blue on the side each face's\n"
  "orientation points to, orange on the other. The colours swap across Möbius edges (green), so a\n"
  "one-sided surface shows both on one side. Borders are red, sharp edges purple by sharpness.\n"
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
    examples::parse_arguments(argc, argv, {"--screenshot", "--size", "--direction", "--up", "--gap"},
                              {"--features-only"});
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
  style.plain_edges = !args.has("--features-only");

  Mesh mesh;
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], mesh);
  const auto np = CGAL_ext::parameters::two_sided_style(style);
  if (!args.has("--screenshot")) {
    CGAL_ext::draw(mesh, np, args.positional[0].c_str());
    return 0;
  }
  const std::string out = args.value("--screenshot", "");
  CGAL_ext::save_screenshot(mesh, out, settings, np);
  std::size_t mobius = 0, border = 0;
  for (auto e : mesh.edges()) {
    mobius += mesh.is_mobius(e);
    border += mesh.is_border(e);
  }
  examples::Json_object line;
  line.add("screenshot", out)
    .add("width", settings.width)
    .add("height", settings.height)
    .add("faces", mesh.number_of_faces())
    .add("mobius_edges", mobius)
    .add("border_edges", border);
  examples::print_json_line(line);
  return 0;
}

} // namespace

int main(int argc, char* argv[]) { return examples::run_tool(usage, argc, argv, [&] { return view(argc, argv); }); }
