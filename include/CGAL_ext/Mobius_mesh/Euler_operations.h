// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Euler operations on a Mobius_mesh, named and specified as CGAL::Euler's.

#ifndef CGAL_EXT_MOBIUS_MESH_EULER_OPERATIONS_H
#define CGAL_EXT_MOBIUS_MESH_EULER_OPERATIONS_H

#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/assertions.h>
#include <CGAL_ext/Mobius_mesh/internal/Euler_impl.h>
#include <CGAL_ext/Mobius_mesh/internal/Euler_support.h>
#include <CGAL_ext/Mobius_mesh/internal/Plain_links.h>
#include <CGAL_ext/exceptions.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <string>
#include <vector>

/// \defgroup PkgMobiusMeshEuler Euler operations
/// The operations of `CGAL::Euler`, on darts. Their contracts are CGAL's (the
/// orientable case), with these additions, which hold for every operation:
///
/// - They work on any `Mobius_mesh`: across Möbius edges, at vertices on the
///   Möbius seam, on borders whose loops pass a Möbius connection. To do so an
///   operation may first reverse faces around the place it edits, so that
///   they agree with the darts it was given (the surface is the same; only
///   which edges are Möbius moves). The result is the same mesh, up to the
///   orientation of faces, whichever way the input's faces were oriented; the
///   darts returned walk the way the darts given did.
/// - Each one that could break the 2-manifold has a `can_*()` check (for
///   `collapse_edge()`, `does_satisfy_link_condition()`), and refuses with an
///   `Euler_error` when it says no, leaving the mesh unchanged. Each of them
///   also has an overload that takes `Euler::unchecked` last and skips the
///   check, for callers that checked already (the check is then a
///   precondition, as in `CGAL::Euler`).
/// - Elements are removed as `Mobius_mesh::remove_*()` does: marked, skipped
///   by the ranges, gone for good at `collect_garbage()`. New elements get
///   the default values of every property map (new vertices the origin).
/// - Corner channels: a new corner at a vertex that its face already had a
///   corner at takes the face's value there (`split_face()`,
///   `add_center_vertex()`, the diagonal of `flip_edge()`); the new corners
///   whose value is not known (at a new vertex, those of `split_edge()`,
///   `split_vertex()`, `add_face_to_border()`, `fill_hole()`) have none. A corner that stays keeps its value: after
///   `join_face()` each corner of the merged face has the value one of the
///   two faces had there; after `join_vertex()` and `collapse_edge()` the
///   faces that were around the removed vertex keep its values at the kept
///   vertex (a seam there unless the values agree). The slots of a removed
///   edge hold no value index (`Mobius_mesh::remove_edge()` clears them), so
///   that no value stays in use for them alone. Decimation and
///   remeshing set the corners round their edits by rules of their own
///   (`decimate()`, `isotropic_remeshing()`).

namespace CGAL_ext {
namespace Euler {

/// \ingroup PkgMobiusMeshEuler
/// The type of `unchecked`: passed last to an operation that has a check, it
/// selects the overload that skips the check.
struct Unchecked_t
{
  /// Not implicitly constructible from `{}`, so that it never matches by accident.
  explicit constexpr Unchecked_t() = default;
};

/// \ingroup PkgMobiusMeshEuler
/// Passed last to an Euler operation that has a check (`flip_edge(d, mesh,
/// Euler::unchecked)`), skips it, as `CGAL::Euler` does: for callers that
/// checked already. The check must hold (it is a precondition, asserted in
/// builds with CGAL's preconditions on); if it does not, the mesh is left
/// invalid instead of an `Euler_error` being thrown.
inline constexpr Unchecked_t unchecked{};

/// \ingroup PkgMobiusMeshEuler
/// @{

/// Tells whether `flip_edge(d, mesh)` can be done: the edge of `d` has two
/// triangles, and their far vertices are distinct and not yet adjacent.
template <class P>
bool can_flip_edge(Dart d, const Mobius_mesh<P>& mesh)
{
  using Plain = internal::Plain;
  const Plain pl(mesh);
  if (!d.is_flipped() && !pl.is_mobius(internal::encoding::halfedge_of_dart(d.bits()))) {
    // By halfedge index: the two faces run against each other along the edge.
    const std::uint32_t h = internal::encoding::halfedge_of_dart(d.bits()), o = Plain::opposite(h);
    const std::uint32_t f = pl.face(h), g = pl.face(o);
    if (f == internal::encoding::null || g == internal::encoding::null || f == g)
      return false;
    const std::uint32_t hn = pl.next(h), on = pl.next(o);
    if (pl.next(pl.next(hn)) != h || pl.next(pl.next(on)) != o ||
        hn == h || on == o)
      return false;
    const Vertex_index c(pl.target(hn)), e(pl.target(on));
    return c != e && !internal::are_adjacent(c, e, mesh);
  }
  if (mesh.is_border(mesh.edge(d)))
    return false;
  const Dart o = mesh.opposite(d);
  if (!internal::is_triangle(d, mesh) || !internal::is_triangle(o, mesh) || mesh.face(d) == mesh.face(o))
    return false;
  const Vertex_index c = mesh.target(mesh.next(d)), e = mesh.target(mesh.next(o));
  return c != e && !internal::are_adjacent(c, e, mesh);
}

/// Replaces the diagonal of the two triangles on the edge of `d` by the other
/// diagonal, keeping the edge's index.
/// \returns the dart of the new diagonal in the face of `d`, unflipped.
/// \throws Euler_error if `can_flip_edge(d, mesh)` is false; the mesh is unchanged.
template <class P>
Dart flip_edge(Dart d, Mobius_mesh<P>& mesh)
{
  if (!can_flip_edge(d, mesh))
    throw Euler_error("Euler::flip_edge: the edge is not the diagonal of two triangles that can turn");
  return internal::flip_edge_unchecked(d, mesh);
}

/// `flip_edge(d, mesh)` without its check.
/// \pre `can_flip_edge(d, mesh)`
template <class P>
Dart flip_edge(Dart d, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_flip_edge(d, mesh), "Euler::flip_edge: the edge cannot turn");
  return internal::flip_edge_unchecked(d, mesh);
}

/// Splits the edge of `d` in two with a new vertex (at the origin: set its
/// point): afterwards `d` runs from the new vertex to `target(d)`. It has no
/// check: every edge can be split.
/// \returns the new dart `n` from `source(d)` to the new vertex, with `next(n) == d`.
template <class P>
Dart split_edge(Dart d, Mobius_mesh<P>& mesh)
{
  using Plain = internal::Plain;
  namespace encoding = internal::encoding;
  d = internal::orient_edge(d, mesh);
  const std::uint32_t h = encoding::halfedge_of_dart(d.bits()), o = Plain::opposite(h);
  const Dart od = Dart::from_bits(encoding::dart(o, false));
  // The edge is not Möbius now: source(d) is the target of o. Faces are
  // linked by halfedge index; a border side may be linked to flipped darts,
  // and goes by darts.
  const Plain plain(mesh);
  const std::uint32_t a = plain.target(o);
  const bool h_border = plain.is_border(h), o_border = plain.is_border(o);
  const Dart before = h_border ? mesh.prev(d) : Dart::from_bits(encoding::dart(plain.prev(h), false));
  const Dart after = o_border ? mesh.next(od) : Dart::from_bits(encoding::dart(plain.next(o), false));

  const std::uint32_t w = mesh.add_vertex().idx();
  const std::uint32_t e = mesh.add_edge(Vertex_index(w), Vertex_index(a)).idx();
  const internal::Plain_links pl(mesh); // after adding: the arrays may have moved
  const std::uint32_t h1 = encoding::halfedge_of_edge(e, 0), o1 = encoding::halfedge_of_edge(e, 1);
  pl.set_target(o, w);
  pl.set_face(h1, pl.face(h));
  pl.set_face(o1, pl.face(o));
  if (h_border)
    mesh.set_next(before, Dart::from_bits(encoding::dart(h1, false)));
  else
    pl.set_next(encoding::halfedge_of_dart(before.bits()), h1);
  pl.set_next(h1, h);
  pl.set_next(o, o1);
  if (o_border)
    mesh.set_next(Dart::from_bits(encoding::dart(o1, false)), after);
  else
    pl.set_next(o1, encoding::halfedge_of_dart(after.bits()));
  pl.set_vertex_halfedge(w, o_border ? o : h1);
  // o now ends at w: the corner of its face at a is o1's, and the corners at
  // w (h1's and o's) have no value.
  if (!o_border) {
    mesh.copy_corner(Halfedge_index(o), Halfedge_index(o1));
    mesh.clear_corner(Halfedge_index(o));
  }
  // a's stored dart, if on the split edge, moves to the new edge on the same side.
  const std::uint32_t stored = encoding::halfedge_of_dart(pl.vertex_dart(a));
  if (stored == h)
    mesh.set_halfedge(Vertex_index(a), Dart::from_bits(encoding::dart(h1, true)));
  else if (stored == o)
    pl.set_vertex_halfedge(a, o1);
  return Dart::from_bits(encoding::dart(h1, false));
}

/// Tells whether `join_face(d, mesh)` can be done: the edge of `d` has two
/// distinct faces, which share no vertex but its ends, and both ends keep at
/// least two edges.
template <class P>
bool can_join_face(Dart d, const Mobius_mesh<P>& mesh)
{
  return internal::why_not_join_face(d, mesh) == nullptr;
}

/// Removes the edge of `d`, merging its two faces into the face of `d`.
/// \returns `prev(d)`, now in the merged face.
/// \throws Euler_error if `can_join_face(d, mesh)` is false; the mesh is unchanged.
template <class P>
Dart join_face(Dart d, Mobius_mesh<P>& mesh)
{
  internal::refuse_if("join_face", internal::why_not_join_face(d, mesh));
  return internal::join_face_unchecked(d, mesh);
}

/// `join_face(d, mesh)` without its check.
/// \pre `can_join_face(d, mesh)`
template <class P>
Dart join_face(Dart d, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_join_face(d, mesh), "Euler::join_face: the faces cannot merge");
  return internal::join_face_unchecked(d, mesh);
}

/// Tells whether `split_face(h, g, mesh)` can be done: `h` and `g` walk one
/// face the same way, and their targets are neither adjacent corners nor
/// joined by an edge already.
template <class P>
bool can_split_face(Dart h, Dart g, const Mobius_mesh<P>& mesh)
{
  return internal::why_not_split_face(h, g, mesh) == nullptr;
}

/// Splits the face of `h` and `g` with a new edge from `target(h)` to
/// `target(g)`; `g` goes to the new face.
/// \returns the new dart `n` with `next(h) == n` and `target(n) == target(g)`.
/// \throws Euler_error if `can_split_face(h, g, mesh)` is false; the mesh is unchanged.
template <class P>
Dart split_face(Dart h, Dart g, Mobius_mesh<P>& mesh)
{
  internal::refuse_if("split_face", internal::why_not_split_face(h, g, mesh));
  return internal::split_face_unchecked(h, g, mesh);
}

/// `split_face(h, g, mesh)` without its check.
/// \pre `can_split_face(h, g, mesh)`
template <class P>
Dart split_face(Dart h, Dart g, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_split_face(h, g, mesh), "Euler::split_face: the face cannot be split there");
  return internal::split_face_unchecked(h, g, mesh);
}

/// Tells whether `join_vertex(d, mesh)` can be done: the faces (or border
/// loops) on both sides of the edge of `d` keep at least three sides, its
/// ends have no common neighbour and no other common face, and they are not
/// both on the border unless the edge is.
template <class P>
bool can_join_vertex(Dart d, const Mobius_mesh<P>& mesh)
{
  return internal::why_not_join_vertex(d, mesh) == nullptr;
}

/// Joins `source(d)` into `target(d)`, removing the edge of `d` and
/// `source(d)`.
/// \returns `prev(opposite(d))`, a dart into the kept vertex.
/// \throws Euler_error if `can_join_vertex(d, mesh)` is false; the mesh is unchanged.
template <class P>
Dart join_vertex(Dart d, Mobius_mesh<P>& mesh)
{
  internal::refuse_if("join_vertex", internal::why_not_join_vertex(d, mesh));
  return internal::join_vertex_unchecked(d, mesh);
}

/// `join_vertex(d, mesh)` without its check.
/// \pre `can_join_vertex(d, mesh)`
template <class P>
Dart join_vertex(Dart d, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_join_vertex(d, mesh), "Euler::join_vertex: the ends cannot be joined");
  return internal::join_vertex_unchecked(d, mesh);
}

/// Splits `target(h1)` (which is `target(h2)`) in two joined by a new edge:
/// the darts into it from `opposite(next(h1))` round to `h2` go to the new
/// vertex (at the origin: set its point), those from `opposite(next(h2))`
/// round to `h1` stay. The faces of `h1` and `h2` gain a side each.
/// \returns the new dart into the old vertex, in the face of `h2`.
template <class P>
Dart split_vertex(Dart h1, Dart h2, Mobius_mesh<P>& mesh)
{
  if (h1 == h2 || mesh.target(h1) != mesh.target(h2))
    throw Euler_error("Euler::split_vertex: the darts are not two distinct darts into one vertex");
  const internal::Walk w2 = internal::walk_of(h2, mesh);
  h1 = CGAL_ext::internal::orient_star(h1, mesh);
  h2 = internal::dart_of(w2, mesh);
  const Vertex_index v = mesh.target(h1);
  std::vector<Dart> moving; // opposite(next(h1)) .. h2
  for (Dart c = mesh.opposite(mesh.next(h1));; c = mesh.opposite(mesh.next(c))) {
    moving.push_back(c);
    if (c == h2)
      break;
  }
  const Dart n1 = mesh.next(h1), n2 = mesh.next(h2);
  const Vertex_index w = mesh.add_vertex();
  const Edge_index e = mesh.add_edge(v, w);
  const Dart x(Mobius_mesh<P>::halfedge(e, 0), false), y(Mobius_mesh<P>::halfedge(e, 1), false);
  for (Dart c : moving)
    mesh.set_target(c.halfedge(), w);
  mesh.set_face(x.halfedge(), mesh.face(h2));
  mesh.set_face(y.halfedge(), mesh.face(h1));
  mesh.set_next(h2, x);
  mesh.set_next(x, n2);
  mesh.set_next(h1, y);
  mesh.set_next(y, n1);
  CGAL_ext::internal::reset_vertex_halfedge(v, x, mesh);
  CGAL_ext::internal::reset_vertex_halfedge(w, y, mesh);
  return x;
}

/// Adds a vertex (at the origin: set its point) inside the face of `d`,
/// joined to each of its corners: the face becomes a fan of triangles, the
/// one on `d` keeping the face's index.
/// \returns `next(d)` afterwards, a dart into the new vertex.
template <class P>
Dart add_center_vertex(Dart d, Mobius_mesh<P>& mesh)
{
  if (mesh.is_border(d))
    throw Euler_error("Euler::add_center_vertex: the dart is on the border");
  d = CGAL_ext::internal::unflip(d, mesh);
  std::vector<Dart> sides;
  for (Dart c : CGAL_ext::halfedges_around_face(d, mesh))
    sides.push_back(c);
  const std::size_t k = sides.size();
  const Vertex_index center = mesh.add_vertex();
  std::vector<Dart> in(k), out(k); // in[i]: target(sides[i]) -> center; out[i]: back
  for (std::size_t i = 0; i < k; ++i) {
    const Edge_index e = mesh.add_edge(center, mesh.target(sides[i]));
    in[i] = Dart(Mobius_mesh<P>::halfedge(e, 0), false);
    out[i] = Dart(Mobius_mesh<P>::halfedge(e, 1), false);
  }
  for (std::size_t i = 0; i < k; ++i) {
    const Dart back = out[(i + k - 1) % k]; // center -> source(sides[i])
    const Face_index f = i == 0 ? mesh.face(d) : mesh.add_face_record(sides[i].halfedge());
    mesh.set_next(sides[i], in[i]);
    mesh.set_next(in[i], back);
    mesh.set_next(back, sides[i]);
    for (const Dart& c : {sides[i], in[i], back})
      mesh.set_face(c.halfedge(), f);
    // `back` ends at a corner of the face: it takes the face's value there
    // (`in[i]`, at the new vertex, has none).
    mesh.copy_corner(sides[(i + k - 1) % k].halfedge(), back.halfedge());
  }
  mesh.set_halfedge(mesh.face(d), d.halfedge());
  mesh.set_halfedge(center, in[0]);
  return in[0];
}

/// Tells whether `remove_center_vertex(d, mesh)` can be done: `target(d)` is
/// not on the border, the merged face would visit no vertex twice, and it
/// would not lie on a single face (as at a corner of a tetrahedron, where the
/// volume would fold into two faces glued together).
template <class P>
bool can_remove_center_vertex(Dart d, const Mobius_mesh<P>& mesh)
{
  return internal::may_remove_center_vertex(d, mesh);
}

/// Removes `target(d)` and its edges, merging its faces into the face of `d`.
/// \returns `prev(d)` (before the operation), now a dart of the merged face.
/// \throws Euler_error if `can_remove_center_vertex(d, mesh)` is false; the mesh is unchanged.
template <class P>
Dart remove_center_vertex(Dart d, Mobius_mesh<P>& mesh)
{
  if (!can_remove_center_vertex(d, mesh))
    throw Euler_error("Euler::remove_center_vertex: the vertex is on the border, or its faces would merge "
                      "into a face that visits a vertex twice");
  return internal::remove_center_vertex_unchecked(d, mesh);
}

/// `remove_center_vertex(d, mesh)` without its check.
/// \pre `can_remove_center_vertex(d, mesh)`
template <class P>
Dart remove_center_vertex(Dart d, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_remove_center_vertex(d, mesh), "Euler::remove_center_vertex: the faces cannot merge");
  return internal::remove_center_vertex_unchecked(d, mesh);
}

/// Tells whether `remove_face(d, mesh)` can be done: `d` is in a face, and no
/// corner of it on the border already would be pinched (get a second gap).
template <class P>
bool can_remove_face(Dart d, const Mobius_mesh<P>& mesh)
{
  return internal::why_not_detach_face(d, mesh, false) == nullptr;
}

/// Removes the face of `d`: its sides become border, edges and vertices left
/// without a face are removed.
/// \throws Euler_error if `can_remove_face(d, mesh)` is false; the mesh is unchanged.
template <class P>
void remove_face(Dart d, Mobius_mesh<P>& mesh)
{
  internal::refuse_if("remove_face", internal::why_not_detach_face(d, mesh, false));
  CGAL_ext::internal::detach_face(mesh.face(d), mesh, true);
}

/// `remove_face(d, mesh)` without its check.
/// \pre `can_remove_face(d, mesh)`
template <class P>
void remove_face(Dart d, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_remove_face(d, mesh), "Euler::remove_face: a corner would be pinched");
  CGAL_ext::internal::detach_face(mesh.face(d), mesh, true);
}

/// Tells whether `make_hole(d, mesh)` can be done: as `can_remove_face()`, and
/// no side of the face is on the border.
template <class P>
bool can_make_hole(Dart d, const Mobius_mesh<P>& mesh)
{
  return internal::why_not_detach_face(d, mesh, true) == nullptr;
}

/// Removes the face of `d`, leaving a hole whose border is its sides.
/// \returns the dart of the border that makes the walk of `d`.
/// \throws Euler_error if `can_make_hole(d, mesh)` is false; the mesh is unchanged.
template <class P>
Dart make_hole(Dart d, Mobius_mesh<P>& mesh)
{
  internal::refuse_if("make_hole", internal::why_not_detach_face(d, mesh, true));
  return internal::make_hole_unchecked(d, mesh);
}

/// `make_hole(d, mesh)` without its check.
/// \pre `can_make_hole(d, mesh)`
template <class P>
Dart make_hole(Dart d, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_make_hole(d, mesh), "Euler::make_hole: the face cannot become a hole");
  return internal::make_hole_unchecked(d, mesh);
}

/// Fills the border loop of `d` with one face. A loop that passes a Möbius
/// connection (a loop of a Möbius strip) gives a face with Möbius edges:
/// filling the border of a Möbius strip makes a projective plane.
/// \returns the new face.
/// \throws Euler_error if `d` is not a border dart or its loop has fewer than three sides.
template <class P>
Face_index fill_hole(Dart d, Mobius_mesh<P>& mesh)
{
  if (!mesh.is_border(d))
    throw Euler_error("Euler::fill_hole: the dart is not on the border");
  std::vector<Dart> cycle;
  for (Dart c : CGAL_ext::halfedges_around_face(d, mesh))
    cycle.push_back(c);
  if (cycle.size() < 3)
    throw Euler_error("Euler::fill_hole: the border loop has fewer than three sides");
  const Face_index f = CGAL_ext::internal::make_face_of_border_chain(cycle, mesh);
  for (const Dart& c : cycle)
    mesh.set_halfedge(mesh.target(Dart(c.halfedge(), false)), Dart(c.halfedge(), false));
  return f;
}

/// Tells whether `add_face_to_border(h1, h2, mesh)` can be done: `h2` follows
/// `h1` on one border loop, not next to it, and `target(h1)` and `target(h2)`
/// are not adjacent yet.
template <class P>
bool can_add_face_to_border(Dart h1, Dart h2, const Mobius_mesh<P>& mesh)
{
  return internal::why_not_add_face_to_border(h1, h2, mesh) == nullptr;
}

/// Adds a face whose sides are the border darts after `h1` up to `h2` and a
/// new edge from `target(h2)` to `target(h1)`; `h1` stays on the border.
/// \returns the dart of the new edge in the new face.
/// \throws Euler_error if `can_add_face_to_border(h1, h2, mesh)` is false; the mesh is unchanged.
template <class P>
Dart add_face_to_border(Dart h1, Dart h2, Mobius_mesh<P>& mesh)
{
  internal::refuse_if("add_face_to_border", internal::why_not_add_face_to_border(h1, h2, mesh));
  return internal::add_face_to_border_unchecked(h1, h2, mesh);
}

/// `add_face_to_border(h1, h2, mesh)` without its check.
/// \pre `can_add_face_to_border(h1, h2, mesh)`
template <class P>
Dart add_face_to_border(Dart h1, Dart h2, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(can_add_face_to_border(h1, h2, mesh), "Euler::add_face_to_border: no face fits there");
  return internal::add_face_to_border_unchecked(h1, h2, mesh);
}

/// Tells whether `collapse_edge(d, mesh)` keeps the mesh a 2-manifold without
/// degenerate faces: the link condition (every common neighbour of the ends
/// is the far corner of a triangle of the edge), no other face holds both
/// ends, the ends are not both on the border unless the edge is, and nothing
/// around the edge is so small that it would fold up (a border loop of three
/// sides, a triangle with two border sides, two triangles that would become one).
template <class P>
bool does_satisfy_link_condition(Dart d, const Mobius_mesh<P>& mesh)
{
  return internal::why_not_collapse_edge(d, mesh) == nullptr;
}

/// Collapses the edge of `d`: `source(d)` is joined into `target(d)`, and a
/// triangle on either side of the edge goes with it: as in CGAL, the side of
/// the triangle before the edge (walking with `d` on one side, with
/// `opposite(d)` on the other) is removed by joining the triangle with the
/// face across it, or the triangle is removed if that side is on the border.
/// \returns the kept vertex, `target(d)`.
/// \throws Euler_error if `does_satisfy_link_condition(d, mesh)` is false; the mesh is unchanged.
template <class P>
Vertex_index collapse_edge(Dart d, Mobius_mesh<P>& mesh)
{
  internal::refuse_if("collapse_edge", internal::why_not_collapse_edge(d, mesh));
  return internal::collapse_edge_unchecked(d, mesh);
}

/// `collapse_edge(d, mesh)` without its check, as `CGAL::Euler::collapse_edge()`.
/// \pre `does_satisfy_link_condition(d, mesh)`
template <class P>
Vertex_index collapse_edge(Dart d, Mobius_mesh<P>& mesh, Unchecked_t)
{
  CGAL_precondition_msg(does_satisfy_link_condition(d, mesh), "Euler::collapse_edge: the link condition fails");
  return internal::collapse_edge_unchecked(d, mesh);
}

/// @}

} // namespace Euler
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_EULER_OPERATIONS_H
