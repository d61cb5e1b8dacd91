// mesh_info FILE
//
// Reads an OBJ, OFF or PLY file into a Mobius_mesh, orients it (fewest
// Möbius edges), and prints its topology as one line of JSON:
//   {"vertices":V,"edges":E,"faces":F,"border_loops":B,"mobius_edges":M,
//    "orientable":true|false,"closed":true|false,"components":C,
//    "euler_characteristic":X,"valid":true|false}
// On bad input or usage it prints one line "mesh_info: <what>" on stderr and
// exits with status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <exception>
#include <iostream>
#include <string>

namespace {

int fail(const std::string& what) { return examples::fail("mesh_info", what); }

} // namespace

int main(int argc, char* argv[])
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL_ext::Mobius_mesh<Kernel::Point_3>;
  if (argc != 2)
    return fail("usage: mesh_info FILE (an .obj, .off or .ply polygon mesh)");
  try {
    Mesh mesh;
    CGAL_ext::IO::read_polygon_mesh(argv[1], mesh);
    CGAL_ext::orient(mesh);
    examples::print_mesh_summary(mesh);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  return 0;
}
