// pmp_on_mobius [FILE]
//
// Runs CGAL's Polygon Mesh Processing on a non-orientable surface (by default
// a Möbius strip of 20 x 4 quads). The algorithms that need no global
// orientation run on the Mobius_mesh itself, through its graph traits:
// triangulation (face by face), area, bounding box, connected components.
// Those that need one are refused by CGAL_ext::require_orientable_model();
// for them the mesh is cut along its Möbius edges into a CGAL::Surface_mesh,
// which CGAL measures, and glued back along the recorded seam. The result has
// the same topology as the input: the same Euler characteristic, border loops
// and orientability.

#include "arguments.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <exception>
#include <iostream>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

const examples::Tool_usage usage{
  "pmp_on_mobius", "pmp_on_mobius [FILE]",
  "Runs CGAL's Polygon Mesh Processing on a non-orientable surface: the mesh in FILE (.obj,\n"
  ".off, .ply; by default a Möbius strip of 20 x 4 quads) is oriented, triangulated and\n"
  "measured by CGAL directly; cut along its Möbius edges into a CGAL::Surface_mesh for what\n"
  "needs a global orientation, and glued back along the recorded seam. Prints each step;\n"
  "exits 1 if the topology changed.\n"};

int pmp_on_mobius(int argc, char** argv)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
  const examples::Arguments args = examples::parse_arguments(argc, argv, {});
  if (args.positional.size() > 1)
    throw examples::Usage_error("expected at most one file name, got " + std::to_string(args.positional.size()));
  const std::string file = args.positional.empty() ? CGAL_EXT_EXAMPLE_DATA_DIR "/mobius_20x4_quads.obj"
                                                   : args.positional[0];
  Mesh mesh;
  CGAL_ext::IO::read_polygon_mesh(file, mesh);
  // Fewest Möbius edges first: they are where the surface is cut.
  const std::size_t seam = CGAL_ext::orient(mesh);
  std::cout << "input: " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " faces, chi = " << CGAL_ext::euler_characteristic(mesh) << ", "
            << (CGAL_ext::is_orientable(mesh) ? "orientable" : "non-orientable") << ", " << seam
            << " Möbius edges\n";

  // Orientation-free algorithms, directly on the mesh. Triangulation splits
  // each face inside itself, so it needs no global orientation either.
  PMP::triangulate_faces(mesh);
  // CGAL's triangulation removes each polygon it splits (through the graph
  // traits' remove_face()); the removed slots go before the conversion below.
  mesh.collect_garbage();
  const auto components =
    PMP::connected_components(mesh, get(CGAL::dynamic_face_property_t<std::size_t>(), mesh));
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  std::cout << "CGAL on the Mobius_mesh: " << mesh.number_of_faces() << " triangles, area " << PMP::area(mesh)
            << ", " << components << " component(s), box [" << box.xmin() << ", " << box.xmax() << "] x ["
            << box.ymin() << ", " << box.ymax() << "] x [" << box.zmin() << ", " << box.zmax() << "], "
            << (CGAL::is_valid_polygon_mesh(mesh) ? "valid" : "INVALID") << "\n";

  // Normals need a global orientation: refused while Möbius edges remain.
  try {
    CGAL_ext::require_orientable_model(mesh, "PMP::compute_vertex_normals");
    std::cout << "no Möbius edges: CGAL's normals apply directly\n";
  } catch (const CGAL_ext::Parameter_error& e) {
    std::cout << "refused: " << e.what() << "\n";
  }

  // What needs an orientation runs on the cut copy.
  CGAL::Surface_mesh<Kernel::Point_3> sm;
  const auto cut = CGAL_ext::to_surface_mesh(mesh, sm);
  std::cout << "cut into a Surface_mesh: " << sm.number_of_vertices() << " vertices (" << cut.added_vertices
            << " seam copies), " << cut.seam_edges << " edges cut, "
            << (CGAL::is_valid_polygon_mesh(sm) ? "valid" : "INVALID") << ", area " << PMP::area(sm) << "\n";

  Mesh back;
  CGAL_ext::from_surface_mesh(sm, back);
  const bool same_topology = CGAL_ext::euler_characteristic(back) == CGAL_ext::euler_characteristic(mesh) &&
                             CGAL_ext::number_of_border_cycles(back) == CGAL_ext::number_of_border_cycles(mesh) &&
                             CGAL_ext::is_orientable(back) == CGAL_ext::is_orientable(mesh) && back.is_valid();
  std::cout << "glued back: " << back.number_of_vertices() << " vertices, " << back.number_of_edges() << " edges, "
            << back.number_of_faces() << " faces, chi = " << CGAL_ext::euler_characteristic(back) << ", "
            << CGAL_ext::number_of_border_cycles(back) << " border loop(s), "
            << (CGAL_ext::is_orientable(back) ? "orientable" : "non-orientable") << ", "
            << CGAL_ext::number_of_mobius_edges(back) << " Möbius edges: "
            << (same_topology ? "same topology" : "TOPOLOGY CHANGED") << std::endl;
  return same_topology ? 0 : 1;
}

} // namespace

int main(int argc, char* argv[])
{
  return examples::run_tool(usage, argc, argv, [&] { return pmp_on_mobius(argc, argv); });
}
