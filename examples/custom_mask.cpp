// custom_mask [OUT] [--levels N]
//
// A user-defined subdivision mask: Loop subdivision with Warren's vertex
// weights, beta = 3/(8n) (3/16 at valence 3), instead of Loop's cosine
// formula. The weights are rational for every valence, so exact kernels stay
// exact without special cases; at valences 3 and 6 they equal Loop's.
//
// The mask only gives the smooth rules; the refiner supplies the topology,
// the Möbius connections, and OpenSubdiv's border and crease rules. The
// program subdivides a triangulated Boy's surface (a closed one-sided
// surface with vertices of valence 3 to 8) with it and with the
// built-in Loop mask, writes the result (OBJ, OFF or PLY by extension) if OUT
// is given, and prints one JSON line: the result's counts and the largest
// distance between the two results (vertex numbering is the same).

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace S = CGAL_ext::Subdivision;

// A model of the SubdivisionMask concept (see doc/subdivision.md).
struct Warren_loop_mask
{
  static constexpr S::Split split = S::Split::triangle; // one triangle into four
  static constexpr bool creases = true;                  // apply border and crease rules

  // Smooth edge: 3/8 of its ends, 1/8 of the two opposite vertices.
  template <class W>
  void smooth_edge(unsigned, unsigned, S::Edge_weights<W>& w) const
  {
    w.vertex = W(3) / W(8);
    w.face = W(1) / W(8);
  }

  // Smooth vertex of valence n: (1 - n beta) V + beta (sum of neighbours).
  template <class W>
  void smooth_vertex(unsigned n, S::Vertex_weights<W>& w) const
  {
    const W beta = n == 3 ? W(3) / W(16) : W(3) / W(8 * int(n));
    w.edge = beta;
    w.vertex = W(1) - W(int(n)) * beta;
  }
};

namespace {

const examples::Tool_usage usage{
  "custom_mask", "custom_mask [OUT] [--levels N]",
  "Loop subdivision with Warren's vertex weights, a user-defined mask: subdivides a triangulated\n"
  "Boy's surface N times (0 to 7, default 3) with it and with the built-in Loop mask, writes the\n"
  "result to OUT if given (.obj, .off, .ply) and prints one JSON line: the result's counts and\n"
  "the largest distance between the two results.\n"};

int custom_mask(int argc, char** argv)
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  const examples::Arguments args = examples::parse_arguments(argc, argv, {"--levels"});
  if (args.positional.size() > 1)
    throw examples::Usage_error("expected at most one file name, got " + std::to_string(args.positional.size()));
  const std::string out = args.positional.empty() ? "" : args.positional[0];
  // Level 7 has 3 million triangles in each of the two results; level 10
  // would have 200 million, more than a machine holds twice.
  const unsigned levels = unsigned(examples::integer_argument("--levels", args.value("--levels", "3"), 0, 7));
  if (!out.empty())
    CGAL_ext::IO::check_output_file(out); // before the work, not after it

  // Boy's surface of quads, each cut into two triangles.
  CGAL_ext::Mobius_mesh<Point> quads;
  CGAL_ext::make_projective_plane(quads, 4);
  std::vector<std::array<std::size_t, 3>> triangles;
  for (CGAL_ext::Face_index f : quads.faces()) {
    std::vector<std::size_t> vs;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, quads))
      vs.push_back(v.idx());
    for (std::size_t i = 1; i + 1 < vs.size(); ++i)
      triangles.push_back({vs[0], vs[i], vs[i + 1]});
  }
  CGAL_ext::Mobius_mesh<Point> warren;
  CGAL_ext::polygon_soup_to_mobius_mesh(quads.points().data(), triangles, warren);
  CGAL_ext::Mobius_mesh<Point> loop = warren;

  const auto np = CGAL_ext::parameters::number_of_iterations(levels);
  S::subdivide(warren, Warren_loop_mask(), np);
  S::loop(loop, np);

  double largest = 0;
  for (CGAL_ext::Vertex_index v : warren.vertices())
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(warren.point(v), loop.point(v))));
  if (!out.empty())
    CGAL_ext::IO::write_polygon_mesh(out, warren);

  examples::Json_object line;
  line.add("mask", "warren_loop").add("levels", levels).add("distance_to_loop", largest);
  examples::print_json_line(line.append(examples::mesh_summary(warren)));
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return examples::run_tool(usage, argc, argv, [&] { return custom_mask(argc, argv); });
}
