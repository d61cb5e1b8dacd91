// merge A B OUT [--tolerance T] [--strategy auto|keep-first|keep-second|average|bridge] [--loops I,J]
//       [--no-tags]
//
// Reads two polygon meshes (OBJ, OFF or PLY), merges B's borders into A's,
// writes the result to OUT and prints its counts as one line of JSON (see
// the description below). On bad input or usage it prints one line
// "merge: <what>" on stderr and exits with status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/merge_borders.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <optional>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;

const examples::Tool_usage usage{
  "merge",
  "merge A B OUT [--tolerance T] [--strategy auto|keep-first|keep-second|average|bridge] [--loops I,J] [--no-tags]",
  "Reads two polygon meshes (.obj, .off, .ply), merges the borders of B into those of A and\n"
  "writes the result to OUT (format by extension).\n"
  "  --strategy auto         (the default) glue border vertices within the tolerance of each\n"
  "                          other, following the borders as far as they run together\n"
  "  --tolerance T           the largest distance glued by auto (default 0: coincident only)\n"
  "  --strategy keep-first, keep-second, average, bridge\n"
  "                          glue the borders that face each other, wherever they are: the two\n"
  "                          loops with the nearest two border vertices, their mutually\n"
  "                          nearest parts (the whole loops of two tubes end to end, the facing\n"
  "                          ends of two strip halves), paired from their nearest vertices the\n"
  "                          way that does not twist; vertices keep A's positions, take B's,\n"
  "                          move to the midpoints, or stay put with quads and triangles\n"
  "                          bridging the gap\n"
  "  --loops I,J             with those strategies: glue the whole border loops I of A and J of\n"
  "                          B instead (numbered from 0, as CGAL_ext::border_cycles lists them)\n"
  "  --no-tags               an OBJ OUT without OpenSubdiv's tag lines (A's creases), which\n"
  "                          CGAL's reader refuses\n"
  "Prints the counts of the result as one line of JSON: vertices, edges, faces, border_loops,\n"
  "mobius_edges (left once oriented), orientable, closed, components, euler_characteristic,\n"
  "valid.\n"};

// The strategies by name: auto (none of the library's manual strategies)
// glues what lies within the tolerance.
const examples::Choices<std::optional<CGAL_ext::Merge_strategy>> strategies = {
  {"auto", std::nullopt},
  {"keep-first", CGAL_ext::Merge_strategy::keep_first},
  {"keep-second", CGAL_ext::Merge_strategy::keep_second},
  {"average", CGAL_ext::Merge_strategy::average},
  {"bridge", CGAL_ext::Merge_strategy::bridge}};

// The border loop numbered `text` of `mesh` ("A" or "B").
CGAL_ext::Dart loop_numbered(const Mesh& mesh, const std::string& text, const char* which)
{
  const std::vector<CGAL_ext::Dart> loops = CGAL_ext::border_cycles(mesh);
  if (loops.empty())
    throw examples::Usage_error(std::string("--loops: ") + which + " has no border loop");
  const long max = long(loops.size()) - 1;
  return loops[std::size_t(examples::integer_argument(std::string("--loops: the loop of ") + which, text, 0, max))];
}

int merge(int argc, char** argv)
{
  const examples::Arguments args = examples::parse_arguments(argc, argv, {"--tolerance", "--strategy", "--loops"},
                                                             {examples::no_tags_flag});
  if (args.positional.size() != 3)
    throw examples::Usage_error("expected three file names, got " + std::to_string(args.positional.size()));
  const double tolerance = examples::real_argument("the tolerance", args.value("--tolerance", "0"));
  const std::optional<CGAL_ext::Merge_strategy> manual =
    examples::choice_argument("--strategy", args.value("--strategy", "auto"), strategies);
  if (!manual && args.has("--loops"))
    throw examples::Usage_error("--loops needs a manual strategy");
  std::string loops = args.value("--loops", "");
  const std::size_t comma = loops.find(',');
  if (args.has("--loops") && comma == std::string::npos)
    throw examples::Usage_error("--loops takes two numbers I,J, not '" + loops + "'");

  Mesh a, b;
  CGAL_ext::IO::check_output_file(args.positional[2]); // before the work, not after it
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], a);
  CGAL_ext::IO::read_polygon_mesh(args.positional[1], b);
  if (!manual) {
    CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(tolerance));
  } else {
    const CGAL_ext::Border_pairing pairing =
      args.has("--loops") ? CGAL_ext::aligned_border_loops(a, loop_numbered(a, loops.substr(0, comma), "A"), b,
                                                           loop_numbered(b, loops.substr(comma + 1), "B"))
                          : CGAL_ext::facing_borders(a, b);
    CGAL_ext::merge_borders(a, b, pairing, *manual);
  }
  CGAL_ext::IO::write_polygon_mesh(args.positional[2], a, examples::write_parameters(args));
  examples::print_mesh_summary(a);
  return 0;
}

} // namespace

int main(int argc, char* argv[]) { return examples::run_tool(usage, argc, argv, [&] { return merge(argc, argv); }); }
