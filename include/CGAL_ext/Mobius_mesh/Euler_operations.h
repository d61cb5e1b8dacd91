// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Euler operations on a Mobius_mesh.

#ifndef CGAL_EXT_MOBIUS_MESH_EULER_OPERATIONS_H
#define CGAL_EXT_MOBIUS_MESH_EULER_OPERATIONS_H

#include <CGAL_ext/Mobius_mesh.h>

namespace CGAL_ext {
namespace Euler {

/// Tells whether `flip_edge(d, mesh)` can be done: the edge of `d` has two
/// triangles, and their far vertices are distinct and not yet adjacent.
template <class P>
bool can_flip_edge(Dart d, const Mobius_mesh<P>& mesh)
{
  if (mesh.is_border(mesh.edge(d)))
    return false;
  const Dart o = mesh.opposite(d);
  if (mesh.degree(mesh.face(d)) != 3 || mesh.degree(mesh.face(o)) != 3 || mesh.face(d) == mesh.face(o))
    return false;
  const Vertex_index c = mesh.target(mesh.next(d)), e = mesh.target(mesh.next(o));
  if (c == e)
    return false;
  for (Vertex_index w : CGAL_ext::vertices_around_target(mesh.halfedge(c), mesh))
    if (w == e)
      return false;
  return true;
}

/// Replaces the diagonal of the two triangles on the edge of `d` by the other
/// diagonal, keeping the edge's index. Across a Möbius edge the second
/// triangle is first reversed (the surface is the same; its Möbius edges
/// move), so that the flip is the orientable one.
/// \pre `can_flip_edge(d, mesh)`
/// \returns the unflipped dart of the new diagonal in the face of `d`.
template <class P>
Dart flip_edge(Dart d, Mobius_mesh<P>& mesh)
{
  CGAL_precondition(can_flip_edge(d, mesh));
  if (mesh.is_mobius(mesh.edge(d)))
    mesh.reverse_face_orientation(mesh.face(mesh.opposite(d)));

  // Work on the unflipped darts of both triangles: a0 = (a->b) in fa, b0 = (b->a) in fb.
  const Dart a0(d.halfedge(), false);
  const Dart b0(Mobius_mesh<P>::opposite_halfedge(d.halfedge()), false);
  const Dart a1 = mesh.next(a0), a2 = mesh.next(a1);
  const Dart b1 = mesh.next(b0), b2 = mesh.next(b1);
  const Face_index f_a = mesh.face(a0), f_b = mesh.face(b0);
  const Vertex_index va = mesh.target(b0), vb = mesh.target(a0);
  const Vertex_index vc = mesh.target(a1), vd = mesh.target(b1);

  mesh.set_target(a0.halfedge(), vc);
  mesh.set_target(b0.halfedge(), vd);
  mesh.set_next(a0, a2);
  mesh.set_next(a2, b1);
  mesh.set_next(b1, a0);
  mesh.set_next(b0, b2);
  mesh.set_next(b2, a1);
  mesh.set_next(a1, b0);
  mesh.set_face(b1.halfedge(), f_a);
  mesh.set_face(a1.halfedge(), f_b);
  mesh.set_halfedge(f_a, a0.halfedge());
  mesh.set_halfedge(f_b, b0.halfedge());
  // a and b lose the diagonal: keep their stored incoming darts off it.
  if (mesh.halfedge(vb).halfedge() == a0.halfedge() || mesh.halfedge(vb).halfedge() == b0.halfedge())
    mesh.set_halfedge(vb, b2);
  if (mesh.halfedge(va).halfedge() == a0.halfedge() || mesh.halfedge(va).halfedge() == b0.halfedge())
    mesh.set_halfedge(va, a2);
  return a0;
}

} // namespace Euler
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_EULER_OPERATIONS_H
