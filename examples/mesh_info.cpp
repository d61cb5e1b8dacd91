// mesh_info FILE
//
// Reads an OBJ, OFF or PLY file into a Mobius_mesh, orients it (fewest
// Möbius edges), and prints its topology as one line of JSON:
//   {"vertices":V,"edges":E,"faces":F,"border_loops":B,"mobius_edges":M,
//    "orientable":true|false,"closed":true|false,"components":C,
//    "euler_characteristic":X,"valid":true|false}
// On bad input or usage it prints one line "mesh_info: <what>" on stderr and
// exits with status 2.

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <exception>
#include <iostream>
#include <string>

namespace {

int fail(std::string what)
{
  // One line, whatever the message holds.
  std::replace(what.begin(), what.end(), '\n', ' ');
  std::cerr << "mesh_info: " << what << std::endl;
  return 2;
}

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
    const std::size_t mobius_edges = CGAL_ext::orient(mesh);
    const char* const boolean[] = {"false", "true"};
    std::cout << "{\"vertices\":" << mesh.number_of_vertices() << ",\"edges\":" << mesh.number_of_edges()
              << ",\"faces\":" << mesh.number_of_faces()
              << ",\"border_loops\":" << CGAL_ext::number_of_border_cycles(mesh)
              << ",\"mobius_edges\":" << mobius_edges
              << ",\"orientable\":" << boolean[CGAL_ext::is_orientable(mesh)]
              << ",\"closed\":" << boolean[CGAL_ext::is_closed(mesh)]
              << ",\"components\":" << CGAL_ext::connected_components(mesh).count
              << ",\"euler_characteristic\":" << CGAL_ext::euler_characteristic(mesh)
              << ",\"valid\":" << boolean[mesh.is_valid()] << "}" << std::endl;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  return 0;
}
