// Builds a Möbius strip and walks around vertices on its seam, printing each
// step in the words of the source design: sibling and Möbius sibling links,
// successor and predecessor links, boundary and Möbius boundary links.
//
// Usage: mobius_walk [n_around n_across]

#include "arguments.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <iostream>
#include <limits>
#include <string>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
using CGAL_ext::Dart;
using CGAL_ext::Vertex_index;

namespace {

std::string name(const Mesh& m, Dart d)
{
  return std::string(m.is_border(d) ? "border " : "") + "e" + std::to_string(d.halfedge().idx());
}

// The source design walks outgoing halfedges: from each one to its sibling
// across the edge, then on to the next outgoing one in the sibling's face
// (its successor, or its predecessor where the sibling runs the other way).
void walk_around(const Mesh& m, Vertex_index v)
{
  std::cout << "Walk around v" << v.idx() << (m.is_border(v) ? " (on the border" : " (interior")
            << (m.is_on_mobius_connection(v) ? ", on a Möbius connection):\n" : "):\n");
  const Dart start = m.opposite(m.halfedge(v)); // outgoing
  Dart d = start;
  std::size_t faces = 0;
  std::cout << "  " << name(m, d);
  do {
    const Dart sibling = m.opposite(d);
    std::cout << (m.is_mobius(m.edge(d)) ? " (mobius sibling link to) " : " (sibling link to) ")
              << name(m, sibling);
    const Dart following = m.next(sibling);
    if (m.is_border(sibling)) {
      // Two border halfedges that both end (or both start) at v: a Möbius boundary link.
      const bool same_direction = sibling.is_flipped() != following.is_flipped();
      std::cout << (same_direction ? " (mobius boundary link to) " : " (boundary link to) ");
    } else {
      ++faces;
      std::cout << (sibling.is_flipped() ? " (predecessor link to) " : " (successor link to) ");
    }
    d = following;
    std::cout << name(m, d);
  } while (d != start);
  std::cout << "\n  back at the start: " << faces << " faces, " << m.degree(v) << " edges.\n";
}

constexpr std::size_t max_quads = 1000000;

const examples::Tool_usage usage{
  "mobius_walk", "mobius_walk [N_AROUND N_ACROSS]",
  "Builds a Möbius strip of N_AROUND x N_ACROSS quads (default 12 x 2; N_AROUND at least 3,\n"
  "N_ACROSS at least 1, a million quads at most) and walks around vertices on its seam, printing each step in the words\n"
  "of the source design (Y. Wang, 2015): sibling and Möbius sibling links, successor and\n"
  "predecessor links, boundary and Möbius boundary links; then the one border loop.\n"};

int walk(int argc, char** argv)
{
  const examples::Arguments args = examples::parse_arguments(argc, argv, {});
  std::size_t n_around = 12, n_across = 2;
  if (args.positional.size() == 2) {
    n_around = std::size_t(examples::integer_argument("N_AROUND", args.positional[0], 3, std::numeric_limits<int>::max()));
    n_across = std::size_t(examples::integer_argument("N_ACROSS", args.positional[1], 1, std::numeric_limits<int>::max()));
    // The walks print two vertices' neighbourhoods: a larger strip shows
    // nothing more and only costs memory (8000 x 8000 quads: 6 GB).
    if (double(n_around) * double(n_across) > max_quads)
      throw examples::Usage_error(std::to_string(n_around) + " x " + std::to_string(n_across) +
                                  " quads is more than the " + std::to_string(max_quads) + " this example builds");
  } else if (!args.positional.empty()) {
    throw examples::Usage_error("expected no number or two, got " + std::to_string(args.positional.size()));
  }
  Mesh m;
  CGAL_ext::make_mobius_strip(m, n_around, n_across);
  CGAL_ext::orient(m);
  std::cout << "Möbius strip of " << n_around << " x " << n_across << " quads with one half-twist: "
            << m.number_of_vertices() << " vertices, " << m.number_of_edges() << " edges, "
            << m.number_of_faces() << " faces, Euler characteristic " << CGAL_ext::euler_characteristic(m) << ", "
            << CGAL_ext::number_of_border_cycles(m) << " border loop, "
            << (CGAL_ext::is_orientable(m) ? "orientable" : "non-orientable") << ", "
            << CGAL_ext::number_of_mobius_edges(m) << " Möbius edges on its seam.\n\n";

  // One walk around a seam vertex on the border and one inside the strip.
  bool shown_border = false, shown_interior = false;
  for (Vertex_index v : m.vertices()) {
    if (!m.is_on_mobius_connection(v))
      continue;
    bool& shown = m.is_border(v) ? shown_border : shown_interior;
    if (shown)
      continue;
    walk_around(m, v);
    std::cout << "\n";
    shown = true;
  }

  // The border loop: one loop, twice as long as the strip, through Möbius boundary links.
  const Dart loop = CGAL_ext::border_cycles(m).front();
  std::size_t length = 0, mobius_links = 0;
  for (Dart d : CGAL_ext::halfedges_around_face(loop, m)) {
    ++length;
    mobius_links += (m.next(d).is_flipped() != d.is_flipped()) ? 1 : 0;
  }
  std::cout << "The border is one loop of " << length << " edges with " << mobius_links
            << " Möbius boundary links.\n";
  return 0;
}

} // namespace

int main(int argc, char** argv) { return examples::run_tool(usage, argc, argv, [&] { return walk(argc, argv); }); }
