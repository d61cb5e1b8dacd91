// What the example tools print: one JSON line of a mesh's counts.
#ifndef CGAL_EXT_EXAMPLES_MESH_SUMMARY_H
#define CGAL_EXT_EXAMPLES_MESH_SUMMARY_H

#include "arguments.h"
#include "json_line.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <cstddef>
#include <iostream>
#include <string>

namespace examples {

// "mobius_edges" counts the Möbius edges left once a copy of the mesh is
// oriented with CGAL_ext::orient() (as few as it finds). The count of the mesh
// as it stands depends on how its faces happen to be oriented; this one
// depends on the surface only, so every tool gives the same number for it.
template <class P>
Json_object mesh_summary(const CGAL_ext::Mobius_mesh<P>& mesh)
{
  CGAL_ext::Mobius_mesh<P> oriented = mesh;
  const std::size_t mobius_edges = CGAL_ext::orient(oriented);
  Json_object summary;
  summary.add("vertices", mesh.number_of_vertices())
    .add("edges", mesh.number_of_edges())
    .add("faces", mesh.number_of_faces())
    .add("border_loops", CGAL_ext::number_of_border_cycles(mesh))
    .add("mobius_edges", mobius_edges)
    .add("orientable", CGAL_ext::is_orientable(mesh))
    .add("closed", CGAL_ext::is_closed(mesh))
    .add("components", CGAL_ext::connected_components(mesh).count)
    .add("euler_characteristic", CGAL_ext::euler_characteristic(mesh))
    .add("valid", mesh.is_valid());
  return summary;
}

/// Prints mesh_summary() as the tool's line.
template <class P>
void print_mesh_summary(const CGAL_ext::Mobius_mesh<P>& mesh, std::ostream& out = std::cout)
{
  print_json_line(mesh_summary(mesh), out);
}

} // namespace examples

#endif
