// What the example tools print: one JSON line of a mesh's counts, and one
// stderr line with exit status 2 on failure.
#ifndef CGAL_EXT_EXAMPLES_MESH_SUMMARY_H
#define CGAL_EXT_EXAMPLES_MESH_SUMMARY_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <algorithm>
#include <iostream>
#include <string>

namespace examples {

template <class P>
void print_mesh_summary(const CGAL_ext::Mobius_mesh<P>& mesh, std::ostream& out = std::cout)
{
  const char* const boolean[] = {"false", "true"};
  out << "{\"vertices\":" << mesh.number_of_vertices() << ",\"edges\":" << mesh.number_of_edges()
      << ",\"faces\":" << mesh.number_of_faces() << ",\"border_loops\":" << CGAL_ext::number_of_border_cycles(mesh)
      << ",\"mobius_edges\":" << CGAL_ext::number_of_mobius_edges(mesh)
      << ",\"orientable\":" << boolean[CGAL_ext::is_orientable(mesh)]
      << ",\"closed\":" << boolean[CGAL_ext::is_closed(mesh)]
      << ",\"components\":" << CGAL_ext::connected_components(mesh).count
      << ",\"euler_characteristic\":" << CGAL_ext::euler_characteristic(mesh)
      << ",\"valid\":" << boolean[mesh.is_valid()] << "}" << std::endl;
}

// One line on stderr, whatever the message holds; returns the exit status 2.
inline int fail(const std::string& tool, std::string what)
{
  std::replace(what.begin(), what.end(), '\n', ' ');
  std::cerr << tool << ": " << what << std::endl;
  return 2;
}

} // namespace examples

#endif
