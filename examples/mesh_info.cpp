// mesh_info FILE
//
// Reads an OBJ, OFF or PLY file into a Mobius_mesh and prints its topology
// as one line of JSON (Möbius edges counted once oriented, as every tool does):
//   {"vertices":V,"edges":E,"faces":F,"border_loops":B,"mobius_edges":M,
//    "orientable":true|false,"closed":true|false,"components":C,
//    "euler_characteristic":X,"valid":true|false[,"corner_channels":[...]]}
// with, for a file with texture coordinates or normals, each corner channel:
//   {"name":"c:uv","values":N,"seam_edges":S,"corners_without_value":W,
//    "mobius_edges_continuous":C,"mobius_edges_seamed":M}
// (C + M is mobius_edges: the Möbius edges of the oriented copy across
// which the channel is continuous, and those along which it has a seam).
// On bad input or usage it prints one line "mesh_info: <what>" on stderr and
// exits with status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <string>

namespace {

const examples::Tool_usage usage{
  "mesh_info", "mesh_info FILE",
  "Reads a polygon mesh (.obj with OpenSubdiv's tags, .off, .ply) and prints its topology as one\n"
  "line of JSON: vertices, edges, faces, border_loops, mobius_edges, orientable, closed,\n"
  "components, euler_characteristic, valid. mobius_edges counts the Möbius edges left once a\n"
  "copy is oriented with CGAL_ext::orient() (as few as it finds), as every tool counts them.\n"
  "A file with texture coordinates or normals (OBJ vt/vn, PLY and OFF per vertex) adds\n"
  "corner_channels: per channel (c:uv, c:normal) its name, values, seam_edges (edges along\n"
  "which its values are cut), corners_without_value, and mobius_edges_continuous and\n"
  "mobius_edges_seamed (the Möbius edges counted in mobius_edges across which the channel is\n"
  "continuous, and those along which it has a seam).\n"};

int mesh_info(int argc, char** argv)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  const examples::Arguments args = examples::parse_arguments(argc, argv, {});
  if (args.positional.size() != 1)
    throw examples::Usage_error("expected one file name, got " + std::to_string(args.positional.size()));
  CGAL_ext::Mobius_mesh<Kernel::Point_3> mesh;
  // Non-manifold input is described, not refused: read as sheets.
  CGAL_ext::IO::read_polygon_mesh(args.positional[0], mesh,
                                  CGAL_ext::parameters::non_manifold_policy(CGAL_ext::Non_manifold_policy::split));
  examples::print_mesh_summary(mesh);
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  return examples::run_tool(usage, argc, argv, [&] { return mesh_info(argc, argv); });
}
