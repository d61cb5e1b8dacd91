// convert IN OUT [--cut] [--no-tags]
//
// Reads a polygon mesh (OBJ, OFF or PLY) into a Mobius_mesh and converts it
// to a CGAL::Surface_mesh: orientable meshes as they are, non-orientable ones
// cut along their Möbius edges with the cut recorded in a seam map. By
// default the Surface_mesh is converted back (gluing the seam) and OUT is the
// round trip, which has the input's topology; with --cut, OUT is the
// Surface_mesh's oriented cut mesh. Prints the counts of what is written as
// one line of JSON (Möbius edges counted once oriented, as every tool does):
//   {"vertices":V,"edges":E,"faces":F,"border_loops":B,"mobius_edges":M,
//    "orientable":true|false,"closed":true|false,"components":C,
//    "euler_characteristic":X,"valid":true|false}
// On bad input or usage it prints one line "convert: <what>" on stderr and
// exits with status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Surface_mesh_conversion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace {

const examples::Tool_usage usage{
  "convert", "convert IN OUT [--cut] [--no-tags]",
  "Reads a polygon mesh (.obj, .off, .ply) and converts it to a CGAL::Surface_mesh: orientable\n"
  "meshes as they are, non-orientable ones cut along their Möbius edges with the cut recorded in\n"
  "a seam map. OUT is the round trip back (the seam glued), with the input's topology, or with\n"
  "  --cut   the Surface_mesh's oriented cut mesh as it is.\n"
  "  --no-tags  an OBJ OUT without OpenSubdiv's tag lines (creases, corners), for readers that\n"
  "           refuse them (CGAL's)\n"
  "Prints the counts of what is written as one line of JSON, as mesh_info does (Möbius edges\n"
  "counted once a copy is oriented).\n"};

int convert(int argc, char** argv)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
  const examples::Arguments args = examples::parse_arguments(argc, argv, {}, {"--cut", examples::no_tags_flag});
  if (args.positional.size() != 2)
    throw examples::Usage_error("expected two file names, got " + std::to_string(args.positional.size()));
  Mesh mesh;
  CGAL_ext::IO::check_output_file(args.positional[1]); // before the work, not after it
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], mesh);
  // The round trip keeps the corner channels and their seams (as halfedge
  // maps of the Surface_mesh): whether OUT holds them is known now.
  CGAL_ext::IO::check_output_file(args.positional[1], mesh);
  CGAL::Surface_mesh<Kernel::Point_3> sm;
  CGAL_ext::to_surface_mesh(mesh, sm);
  if (args.has("--cut")) {
    // The cut mesh as it is: drop the records, so nothing is glued back.
    if (auto seam = sm.property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name);
        seam.second)
      sm.remove_property_map(seam.first);
    if (auto flag = sm.property_map<CGAL::SM_Face_index, bool>(CGAL_ext::reversed_faces_map_name); flag.second)
      sm.remove_property_map(flag.first);
  }
  Mesh out;
  CGAL_ext::from_surface_mesh(sm, out);
  CGAL_ext::IO::write_polygon_mesh(args.positional[1], out, examples::write_parameters(args));
  examples::print_mesh_summary(out);
  return 0;
}

} // namespace

int main(int argc, char* argv[]) { return examples::run_tool(usage, argc, argv, [&] { return convert(argc, argv); }); }
