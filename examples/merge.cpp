// merge A B OUT [--tolerance T] [--strategy auto|keep-first|keep-second|average|bridge]
//
// Reads two polygon meshes (OBJ, OFF or PLY) and merges B's borders into A's:
// * auto (the default): border vertices within T (default 0: exact
//   coincidence) are glued, following the borders as far as they run
//   together; border edges that run the same way become Möbius edges;
// * keep-first, keep-second, average, bridge: the first border loop of A is
//   glued to the border loop of B that comes nearest to it, starting at the
//   B vertex nearest to the loop's first vertex and walking B's loop the way
//   that keeps the two walks together. Vertices keep A's positions, take B's,
//   move to the midpoints, or stay put with new faces bridging the gap.
// Writes the result to OUT and prints its counts as one line of JSON:
//   {"vertices":V,"edges":E,"faces":F,"border_loops":B,"mobius_edges":M,
//    "orientable":true|false,"closed":true|false,"components":C,
//    "euler_characteristic":X,"valid":true|false}
// On bad input or usage it prints one line "merge: <what>" on stderr and
// exits with status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/merge_borders.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;

int fail(const std::string& what) { return examples::fail("merge", what); }

// The border darts of B's loops that pair with A's first loop: the dart into
// the B vertex nearest to the loop's first vertex, walking either way round,
// whichever puts the next vertex nearer to A's next vertex.
std::pair<CGAL_ext::Dart, CGAL_ext::Dart> choose_loops(const Mesh& a, const Mesh& b)
{
  const std::vector<CGAL_ext::Dart> loops_a = CGAL_ext::border_cycles(a), loops_b = CGAL_ext::border_cycles(b);
  if (loops_a.empty() || loops_b.empty())
    throw CGAL_ext::Merge_error(CGAL_ext::Merge_error::Kind::not_a_border,
                                std::string(loops_a.empty() ? "A" : "B") + " has no border to merge", {});
  const CGAL_ext::Dart da = loops_a.front();
  const auto& p = a.point(a.target(da));
  const auto& p_next = a.point(a.target(a.next(da)));
  CGAL_ext::Dart best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (CGAL_ext::Dart loop : loops_b)
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(loop, b)) {
      const double dist = CGAL::to_double(CGAL::squared_distance(p, b.point(b.target(d))));
      if (dist < best_distance) {
        best_distance = dist;
        best = d;
      }
    }
  // The other way round: the dart into the same vertex from its other neighbour.
  const CGAL_ext::Dart other = b.next(best).flipped();
  const double forward = CGAL::to_double(CGAL::squared_distance(p_next, b.point(b.target(b.next(best)))));
  const double backward = CGAL::to_double(CGAL::squared_distance(p_next, b.point(b.target(b.next(other)))));
  return {da, backward < forward ? other : best};
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string usage =
    "usage: merge A B OUT [--tolerance T] [--strategy auto|keep-first|keep-second|average|bridge]";
  if (argc < 4)
    return fail(usage);
  double tolerance = 0;
  std::string strategy = "auto";
  for (int i = 4; i < argc; ++i) {
    const std::string option = argv[i];
    if (i + 1 >= argc)
      return fail("option " + option + " needs a value; " + usage);
    const std::string value = argv[++i];
    if (option == "--tolerance") {
      char* end = nullptr;
      tolerance = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0')
        return fail("the tolerance '" + value + "' is not a number");
    } else if (option == "--strategy") {
      strategy = value;
    } else {
      return fail("unknown option " + option + "; " + usage);
    }
  }
  try {
    Mesh a, b;
    CGAL_ext::IO::read_polygon_mesh(argv[1], a);
    CGAL_ext::IO::read_polygon_mesh(argv[2], b);
    if (strategy == "auto") {
      CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(tolerance));
    } else {
      CGAL_ext::Merge_strategy s;
      if (strategy == "keep-first")
        s = CGAL_ext::Merge_strategy::keep_first;
      else if (strategy == "keep-second")
        s = CGAL_ext::Merge_strategy::keep_second;
      else if (strategy == "average")
        s = CGAL_ext::Merge_strategy::average;
      else if (strategy == "bridge")
        s = CGAL_ext::Merge_strategy::bridge;
      else
        return fail("unknown strategy '" + strategy + "'; " + usage);
      const auto [da, db] = choose_loops(a, b);
      CGAL_ext::merge_borders(a, da, b, db, s);
    }
    CGAL_ext::IO::write_polygon_mesh(argv[3], a);
    examples::print_mesh_summary(a);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  return 0;
}
