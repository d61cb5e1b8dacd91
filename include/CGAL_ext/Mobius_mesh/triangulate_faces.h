// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Triangulating the faces of a Mobius_mesh, as CGAL's
// Polygon_mesh_processing::triangulate_faces() does for a Surface_mesh.

#ifndef CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H
#define CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H

#include <CGAL_ext/Mobius_mesh/internal/Fan_triangulation.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshEuler
/// \brief Splits every face of `mesh` with more than three sides into
/// triangles, with `Euler::split_face()`: a quad along its shorter diagonal, a
/// larger face by a fan from the corner whose smallest triangle is largest
/// (so a planar convex face gives no degenerate or flipped triangle). Where
/// that would join two corners that an edge already joins (a quad whose
/// shorter diagonal is an edge of the mesh, or the diagonal another face
/// takes), the next best diagonal or fan is taken. The new faces take the
/// values of every face property map of the face they come from; vertices
/// and edges keep theirs (new edges get the maps' defaults). Corner channels
/// are kept: each triangle's corners hold the values the face had there. Möbius edges and
/// the surface's topology are unchanged.
/// \returns the number of faces added (a face of `n` sides adds `n - 3`).
/// \throws Parameter_error if `mesh` has removed elements.
/// \throws Euler_error, naming the face and its vertices, if every fan of a
/// face would duplicate an edge. Both are thrown before `mesh` is touched.
template <class P>
std::size_t triangulate_faces(Mobius_mesh<P>& mesh)
{
  CGAL_ext::internal::require_no_garbage(mesh, "triangulate_faces");
  const std::size_t n_old = mesh.number_of_faces();
  std::vector<std::uint32_t> parent;
  for (const auto& [f, apex] : internal::plan_fans(mesh)) {
    // Cut the triangle (apex, next corner, the one after) off, while more than three sides remain.
    for (std::size_t sides = mesh.degree(f); sides > 3; --sides) {
      Euler::split_face(apex, mesh.next(mesh.next(apex)), mesh, Euler::unchecked);
      parent.push_back(std::uint32_t(f.idx()));
    }
  }
  if (!parent.empty())
    internal::transfer_properties<Face_index>(mesh, mesh, n_old, mesh.number_of_faces(),
                                              [&](Face_index g) { return Face_index(parent[g.idx() - n_old]); });
  return parent.size();
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H
