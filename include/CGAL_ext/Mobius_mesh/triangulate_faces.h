// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Triangulating the faces of a Mobius_mesh, as CGAL's
// Polygon_mesh_processing::triangulate_faces() does for a Surface_mesh.

#ifndef CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H
#define CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/transform.h>

#include <cstdint>
#include <vector>

namespace CGAL_ext {
namespace internal {

// The corner of face `f` (a dart walking the face's own way, into the corner)
// from which a fan of triangles has the largest smallest triangle: a fan from
// any corner of a planar convex face has no flipped triangle, and this choice
// keeps it from degenerate ones where three corners are in line. The area of
// each triangle is measured along the face's Newell normal, so a triangle
// turned against the face counts as negative. A quad takes its shorter
// diagonal instead.
template <class P>
Dart fan_apex(Face_index f, const Mobius_mesh<P>& m)
{
  std::vector<Dart> into;
  std::vector<Point_d> ps;
  for (Dart c : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
    into.push_back(c);
    ps.push_back(to_point_d(m.point(m.target(c))));
  }
  const std::size_t n = ps.size();
  auto squared_distance = [&](std::size_t i, std::size_t j) {
    const Point_d v = minus_d(ps[i], ps[j]);
    return dot_d(v, v);
  };
  if (n == 4)
    return squared_distance(0, 2) <= squared_distance(1, 3) ? into[0] : into[1];
  const Point_d normal = newell_d(ps).first;
  std::size_t best = 0;
  double best_smallest = -std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < n; ++a) {
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k + 1 < n; ++k) {
      const Point_d& o = ps[a];
      const double area = dot_d(normal, cross_d(minus_d(ps[(a + k) % n], o), minus_d(ps[(a + k + 1) % n], o)));
      smallest = (std::min)(smallest, area);
    }
    if (smallest > best_smallest) {
      best_smallest = smallest;
      best = a;
    }
  }
  return into[best];
}

} // namespace internal

/// \ingroup PkgMobiusMeshEuler
/// \brief Splits every face of `mesh` with more than three sides into
/// triangles, with `Euler::split_face()`: a quad along its shorter diagonal, a
/// larger face by a fan from the corner whose smallest triangle is largest
/// (so a planar convex face gives no degenerate or flipped triangle). The new
/// faces take the values of every face property map of the face they come
/// from; vertices and edges keep theirs (new edges get the maps' defaults).
/// Möbius edges and the surface's topology are unchanged.
/// \returns the number of faces added (a face of `n` sides adds `n - 3`).
/// \throws Parameter_error if `mesh` has removed elements.
template <class P>
std::size_t triangulate_faces(Mobius_mesh<P>& mesh)
{
  CGAL_ext::internal::require_no_garbage(mesh, "triangulate_faces");
  const std::size_t n_old = mesh.number_of_faces();
  std::vector<std::uint32_t> parent;
  for (std::size_t i = 0; i < n_old; ++i) {
    const Face_index f(static_cast<Face_index::size_type>(i));
    if (mesh.degree(f) <= 3)
      continue;
    // Cut the triangle (apex, next corner, the one after) off, while more than three sides remain.
    const Dart apex = internal::fan_apex(f, mesh);
    for (std::size_t sides = mesh.degree(f); sides > 3; --sides) {
      Euler::split_face(apex, mesh.next(mesh.next(apex)), mesh);
      parent.push_back(std::uint32_t(i));
    }
  }
  if (!parent.empty())
    internal::transfer_properties<Face_index>(mesh, mesh, n_old, mesh.number_of_faces(),
                                              [&](Face_index g) { return Face_index(parent[g.idx() - n_old]); });
  return parent.size();
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H
