// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of Euler_operations.h: the checks that decide whether an
// operation keeps the mesh a 2-manifold (with the reason when it does not),
// the link condition, and the operations themselves, unchecked.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_EULER_IMPL_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_EULER_IMPL_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Euler_support.h>
#include <CGAL_ext/Mobius_mesh/internal/Plain_links.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/assertions.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Euler {
namespace internal {

using CGAL_ext::internal::Walk;
using CGAL_ext::internal::dart_of;
using CGAL_ext::internal::walk_of;

// The checks below walk faces and vertex rings in place, without collecting
// them: they run on every checked operation, and the rings are short.

// True if the face or border loop of `d` has exactly three sides.
template <class P>
bool is_triangle(Dart d, const Mobius_mesh<P>& m)
{
  const Dart n = m.next(d), nn = m.next(n);
  return n != d && nn != d && m.next(nn) == d;
}

// True if the face or border loop of `d` has fewer than `k` sides, walking at most k - 1 of them.
template <class P>
bool has_fewer_sides_than(Dart d, std::size_t k, const Mobius_mesh<P>& m)
{
  Dart c = d;
  for (std::size_t i = 1; i < k; ++i) {
    c = m.next(c);
    if (c == d)
      return true;
  }
  return false;
}

// True if `target(d)` has fewer than `k` edges, walking at most k - 1 of them.
template <class P>
bool has_fewer_edges_than(Dart d, std::size_t k, const Mobius_mesh<P>& m)
{
  Dart c = d;
  for (std::size_t i = 1; i < k; ++i) {
    c = m.opposite(m.next(c));
    if (c == d)
      return true;
  }
  return false;
}

// True if the face (or border loop) of `d` visits `v`.
template <class P>
bool face_holds(Dart d, Vertex_index v, const Mobius_mesh<P>& m)
{
  Dart c = d;
  do {
    if (m.target(c) == v)
      return true;
    c = m.next(c);
  } while (c != d);
  return false;
}

using Plain = CGAL_ext::internal::Plain_reader;
using Plain_links = CGAL_ext::internal::Plain_links;
namespace encoding = CGAL_ext::internal::dart_encoding;

// Walks the ring of `a` by halfedge index, as long as no link on the way is
// flipped and no edge Möbius: 1 if `b` is a neighbour, 0 if not, -1 if the
// walk met a flip (the walk of darts must decide).
template <class P>
int plain_are_adjacent(std::uint32_t start, Vertex_index b, const Mobius_mesh<P>& m)
{
  const Plain pl(m);
  std::uint32_t c = start;
  do {
    const std::uint32_t out = pl.plain_step(c);
    if (out == encoding::null)
      return -1;
    if (pl.target(out) == b.idx())
      return 1;
    c = Plain::opposite(out);
  } while (c != start);
  return 0;
}

// Walks the ring of `a` by its outgoing darts: the far end of next(c) is
// one load where an unflipped dart's source would need its partner too.
template <class P>
bool are_adjacent(Vertex_index a, Vertex_index b, const Mobius_mesh<P>& m)
{
  const Dart start = m.halfedge(a);
  if (!start.is_valid())
    return false;
  if (!start.is_flipped()) {
    const int plain = plain_are_adjacent(encoding::halfedge_of_dart(start.bits()), b, m);
    if (plain >= 0)
      return plain == 1;
  }
  Dart c = start;
  do {
    const Dart out = m.next(c);
    if (m.target(out) == b)
      return true;
    c = m.opposite(out);
  } while (c != start);
  return false;
}

// The ring of a vertex, for the checks that intersect two rings: no
// allocation for the usual small fans.
using Vertex_list = boost::container::small_vector<Vertex_index, 16>;

template <class P>
Vertex_list neighbours(Dart into, const Mobius_mesh<P>& m)
{
  Vertex_list vs;
  for (Vertex_index v : CGAL_ext::vertices_around_target(into, m))
    vs.push_back(v);
  return vs;
}

inline bool holds(const Vertex_list& vs, Vertex_index v) { return std::find(vs.begin(), vs.end(), v) != vs.end(); }

// True if a face around `target(into)` other than `f1` and `f2` visits `v`.
template <class P>
bool other_face_around_holds(Dart into, Face_index f1, Face_index f2, Vertex_index v, const Mobius_mesh<P>& m)
{
  Dart c = into;
  do {
    const Face_index f = m.face(c);
    if (f.is_valid() && f != f1 && f != f2 && face_holds(c, v, m))
      return true;
    c = m.opposite(m.next(c));
  } while (c != into);
  return false;
}

// Throws an Euler_error naming the operation if `why` (a reason from the
// why_not_*() functions below, null when the operation may be done) is set.
inline void refuse_if(const char* operation, const char* why)
{
  if (why != nullptr)
    throw Euler_error(std::string("Euler::") + operation + ": " + why);
}

template <class P>
const char* why_not_join_face(Dart d, const Mobius_mesh<P>& m)
{
  const Dart o = m.opposite(d);
  if (m.is_border(d) || m.is_border(o))
    return "the edge is on the border";
  if (m.face(d) == m.face(o))
    return "the edge has the same face on both sides";
  if (has_fewer_edges_than(d.flipped(), 3, m) || has_fewer_edges_than(d, 3, m))
    return "an end of the edge would be left with one edge";
  std::size_t shared = 0;
  Dart c = d;
  do {
    shared += face_holds(o, m.target(c), m) ? 1 : 0;
    c = m.next(c);
  } while (c != d);
  if (shared != 2)
    return "the two faces share a vertex besides the edge's ends";
  return nullptr;
}

template <class P>
const char* why_not_split_face(Dart h, Dart g, const Mobius_mesh<P>& m)
{
  if (m.is_border(h) || m.face(h) != m.face(g))
    return "the darts are not in one face";
  if (h.is_flipped() != g.is_flipped())
    return "the darts walk the face in opposite directions";
  if (h == g || m.next(h) == g || m.next(g) == h)
    return "the new edge would join adjacent corners";
  if (m.target(h) == m.target(g))
    return "the corners are one vertex, which the face visits twice";
  if (are_adjacent(m.target(h), m.target(g), m))
    return "the corners are already joined by an edge";
  return nullptr;
}

template <class P>
const char* why_not_join_vertex(Dart d, const Mobius_mesh<P>& m)
{
  if (m.source(d) == m.target(d))
    return "the edge is a loop (a degenerate edge of non-manifold input)";
  const Dart o = m.opposite(d);
  for (Dart side : {d, o})
    if (has_fewer_sides_than(side, 4, m))
      return "a face or border loop of the edge has fewer than four sides";
  const Vertex_index s = m.source(d), t = m.target(d);
  if (m.is_border(s) && m.is_border(t) && !m.is_border(m.edge(d)))
    return "both ends are on the border but the edge is not";
  const Vertex_list ns = neighbours(d.flipped(), m);
  for (Vertex_index w : CGAL_ext::vertices_around_target(d, m))
    if (holds(ns, w))
      return "the ends have a common neighbour";
  if (other_face_around_holds(d.flipped(), m.face(d), m.face(o), t, m))
    return "another face holds both ends";
  return nullptr;
}

template <class P>
const char* why_not_detach_face(Dart d, const Mobius_mesh<P>& m, bool keep_edges)
{
  if (m.is_border(d))
    return "the dart is on the border";
  std::vector<Vertex_index> corners;
  for (Dart c : CGAL_ext::halfedges_around_face(d, m))
    corners.push_back(m.target(c));
  std::sort(corners.begin(), corners.end());
  if (std::adjacent_find(corners.begin(), corners.end()) != corners.end())
    return "the face visits a vertex twice (non-manifold input), which its removal could pinch";
  for (Dart c : CGAL_ext::halfedges_around_face(d, m)) {
    const bool in_border = m.is_border(m.opposite(c)), out_border = m.is_border(m.opposite(m.next(c)));
    if (keep_edges && in_border)
      return "the face has a border edge";
    if (!in_border && !out_border && m.is_border(m.target(c)))
      return "a corner of the face is already on the border (it would be pinched)";
  }
  return nullptr;
}

template <class P>
const char* why_not_add_face_to_border(Dart h1, Dart h2, const Mobius_mesh<P>& m)
{
  if (!m.is_border(h1) || !m.is_border(h2))
    return "the darts are not border darts";
  if (h1 == h2 || m.next(h1) == h2)
    return "the new face would have fewer than three sides";
  bool found = false;
  for (Dart c : CGAL_ext::halfedges_around_face(h1, m))
    if (c == h2)
      found = true;
  if (!found)
    return "the darts are not on one border loop, walked one way";
  if (are_adjacent(m.target(h2), m.target(h1), m))
    return "the new edge already exists";
  return nullptr;
}

// The triangle sides of the edge of `d`: its far corners (`apexes`, at most
// two), or why a collapse would fold something up there.
template <class P>
const char* why_not_collapse_triangles(Dart d, const Mobius_mesh<P>& m, Vertex_list& apexes)
{
  const Dart o = m.opposite(d);
  for (Dart side : {d, o}) {
    if (m.is_border(side)) {
      if (has_fewer_sides_than(side, 4, m))
        return "the edge is on a border loop of three sides";
      continue;
    }
    if (!internal::is_triangle(side, m))
      continue;
    apexes.push_back(m.target(m.next(side)));
    if (m.is_border(m.opposite(m.next(side))) && m.is_border(m.opposite(m.prev(side))))
      return "a triangle of the edge has its two other sides on the border";
    const Dart other = side == d ? o : d;
    if (!m.is_border(other) && face_holds(other, apexes.back(), m))
      return "the faces of the edge meet again at the far corner of a triangle";
  }
  return nullptr;
}

// What the link condition asks of the star of `p = source(d)`, gathered in
// one walk of its faces: the ring of p, whether a face other than those of
// the edge holds `q = target(d)`, and whether a face holds both apexes.
struct Source_star
{
  Vertex_list ring;
  bool other_face_holds_q = false;
  bool a_face_holds_apexes = false;
};

template <class P>
Source_star scan_source_star(Dart d, const Vertex_list& apexes, const Mobius_mesh<P>& m)
{
  const Dart o = m.opposite(d);
  const Face_index f1 = m.face(d), f2 = m.face(o);
  const Vertex_index q = m.target(d);
  // Null apexes (fewer than two triangles) match no vertex.
  const Vertex_index a0 = apexes.size() == 2 ? apexes[0] : Vertex_index();
  const Vertex_index a1 = apexes.size() == 2 ? apexes[1] : Vertex_index();
  Source_star star;
  Dart c = o;
  do {
    const Dart out = m.next(c);
    star.ring.push_back(m.target(out));
    const Face_index f = m.face(c);
    if (f.is_valid()) {
      bool q_in = false, a0_in = false, a1_in = false;
      for (Dart x = out; x != c; x = m.next(x)) { // the face's corners but p
        const Vertex_index v = m.target(x);
        q_in |= v == q;
        a0_in |= v == a0;
        a1_in |= v == a1;
      }
      star.other_face_holds_q = star.other_face_holds_q || (q_in && f != f1 && f != f2);
      star.a_face_holds_apexes = star.a_face_holds_apexes || (a0_in && a1_in);
    }
    c = m.opposite(out);
  } while (c != o);
  return star;
}

// True if a face around `a` holds both `b` and `c`.
template <class P>
bool some_face_holds(Vertex_index a, Vertex_index b, Vertex_index c, const Mobius_mesh<P>& m)
{
  for (Dart x : CGAL_ext::halfedges_around_target(m.halfedge(a), m))
    if (!m.is_border(x) && face_holds(x, b, m) && face_holds(x, c, m))
      return true;
  return false;
}

// The ring of a vertex by halfedge index, in a buffer of fixed size: the
// plain link condition gives up on larger rings.
struct Plain_ring
{
  static constexpr std::size_t capacity = 32;
  std::uint32_t v[capacity];
  std::size_t n = 0;
  bool p_on_border = false; // a border gap comes round
  bool holds(std::uint32_t x) const
  {
    for (std::size_t i = 0; i < n; ++i)
      if (v[i] == x)
        return true;
    return false;
  }
};

// The star of p = source(h) walked by halfedge index for the link condition
// (as `scan_source_star()`), from o = opposite(h): its ring but q and the
// apexes into `ring` (p has no loop, so p is not there either). The ring
// runs a1, ..., a0, q (the triangles of the edge are its first and last
// faces); if q and the apexes come round nowhere else and every face is a
// triangle, no face but those of the edge holds q and, p having four
// neighbours at least, no face holds both apexes. False otherwise, or if the
// walk meets a flip or a Möbius edge, or the ring is too large: the walk of
// darts then decides.
template <class P>
bool plain_scan_source_star(std::uint32_t h, std::uint32_t a0, std::uint32_t a1, const Mobius_mesh<P>& m,
                            Plain_ring& ring)
{
  const Plain pl(m);
  const std::uint32_t o = Plain::opposite(h), q = pl.target(h);
  std::uint32_t c = o, specials = 0, degree = 0;
  do {
    const std::uint32_t out = pl.plain_step(c);
    if (out == encoding::null || ring.n == Plain_ring::capacity)
      return false;
    const std::uint32_t k = pl.target(out);
    const bool special = k == q || k == a0 || k == a1;
    specials += special ? 1 : 0;
    ring.v[ring.n] = k;
    ring.n += special ? 0 : 1;
    if (pl.is_border(c))
      ring.p_on_border = true;
    else if (pl.next(pl.next(out)) != c)
      return false; // not a triangle
    ++degree;
    c = Plain::opposite(out);
  } while (c != o);
  return specials == 3 && degree >= 4;
}

// True if the link condition surely holds for the edge of `d`, found by
// halfedge index where the common case allows: `d` unflipped, two triangles
// on the edge, the stars of both ends without flips, Möbius edges or faces
// other than triangles around the removed end. False means "ask the walk of
// darts", which also says why a collapse is refused.
template <class P>
bool plain_link_condition_holds(Dart d, const Mobius_mesh<P>& m)
{
  if (d.is_flipped())
    return false;
  const Plain pl(m);
  const std::uint32_t h = encoding::halfedge_of_dart(d.bits()), o = Plain::opposite(h);
  if (pl.is_mobius(h) || pl.is_border(h) || pl.is_border(o) ||
      pl.face(h) == pl.face(o))
    return false;
  const std::uint32_t n1 = pl.next(h), n2 = pl.next(n1);
  const std::uint32_t m1 = pl.next(o), m2 = pl.next(m1);
  if (pl.next(n2) != h || pl.next(m2) != o)
    return false; // not two triangles
  const std::uint32_t a0 = pl.target(n1), a1 = pl.target(m1);
  if (a0 == a1 || (pl.is_border(Plain::opposite(n1)) && pl.is_border(Plain::opposite(n2))) ||
      (pl.is_border(Plain::opposite(m1)) && pl.is_border(Plain::opposite(m2))))
    return false;
  // q keeps its edges to a0 and a1 (distinct, as a0 != a1): three at least.
  Plain_ring ring;
  if (!plain_scan_source_star(h, a0, a1, m, ring))
    return false;
  if (ring.p_on_border && pl.is_border_vertex(pl.target(h)))
    return false; // both ends on the border, the edge not
  std::uint32_t c = h; // into q
  do {
    const std::uint32_t out = pl.plain_step(c);
    if (out == encoding::null)
      return false;
    if (ring.holds(pl.target(out)))
      return false;
    c = Plain::opposite(out);
  } while (c != h);
  return true;
}

template <class P>
const char* why_not_collapse_edge(Dart d, const Mobius_mesh<P>& m)
{
  if (m.source(d) == m.target(d))
    return "the edge is a loop (a degenerate edge of non-manifold input)";
  if (plain_link_condition_holds(d, m))
    return nullptr;
  const Vertex_index p = m.source(d), q = m.target(d);
  Vertex_list apexes;
  if (const char* why = why_not_collapse_triangles(d, m, apexes))
    return why;
  if (m.is_border(p) && m.is_border(q) && !m.is_border(m.edge(d)))
    return "both ends are on the border but the edge is not";
  if (has_fewer_edges_than(d, 3, m))
    return "the kept end would vanish with the triangle of the edge";
  const Source_star star = scan_source_star(d, apexes, m);
  Dart c = d;
  do { // the ring of q, by the far ends of its outgoing darts
    const Dart out = m.next(c);
    const Vertex_index k = m.target(out);
    if (k != p && holds(star.ring, k) && !holds(apexes, k))
      return "the link condition fails: the ends have a common neighbour that is not across a triangle of the edge";
    c = m.opposite(out);
  } while (c != d);
  if (star.other_face_holds_q)
    return "another face holds both ends";
  if (star.a_face_holds_apexes && some_face_holds(q, apexes[0], apexes[1], m))
    return "two triangles would become one (the mesh is too small around the edge)";
  return nullptr;
}

template <class P>
bool may_remove_center_vertex(Dart d, const Mobius_mesh<P>& mesh)
{
  const Vertex_index v = mesh.target(d);
  if (mesh.is_border(v))
    return false;
  boost::container::small_vector<Vertex_index, 32> rim;
  boost::container::small_vector<Face_index, 32> beyond;
  for (Dart c : CGAL_ext::halfedges_around_target(d, mesh))
    for (Dart r = mesh.next(mesh.next(c)); r != c; r = mesh.next(r)) {
      rim.push_back(mesh.source(r));
      beyond.push_back(mesh.face(mesh.opposite(r)));
    }
  std::sort(rim.begin(), rim.end());
  std::sort(beyond.begin(), beyond.end());
  return rim.size() >= 3 && std::adjacent_find(rim.begin(), rim.end()) == rim.end() &&
         std::unique(beyond.begin(), beyond.end()) - beyond.begin() >= 2;
}

// Turns the faces at the edge of `d` so that `d` is unflipped and the edge
// is not Möbius; returns the dart that makes the walk of `d`. Nothing to do
// in the usual case, told by two bits.
template <class P>
Dart orient_edge(Dart d, Mobius_mesh<P>& mesh)
{
  if (!d.is_flipped() && !mesh.is_mobius(mesh.edge(d)))
    return d;
  const Walk wd = walk_of(d, mesh);
  CGAL_ext::internal::unflip(d, mesh);
  d = dart_of(wd, mesh);
  CGAL_ext::internal::make_edge_orientable(d, mesh);
  return dart_of(wd, mesh);
}

// The operations without their checks: the public overloads check (or
// assert) first, collapse_edge() checks once for its parts.

// The bodies below run on unflipped darts of faces once the check of their
// first line made them so (turning faces only near a Möbius edge): face
// cycles never mix orientations, so their links are read and written by
// halfedge index.

template <class P>
Dart flip_edge_unchecked(Dart d, Mobius_mesh<P>& mesh)
{
  CGAL_ext::internal::make_edge_orientable(d, mesh);
  const Plain_links pl(mesh);
  // The triangles a0 = (a->b), a1, a2 in fa and b0 = (b->a), b1, b2 in fb.
  // Each value is used soon after it is read (fewer of them live at once).
  const std::uint32_t a0 = encoding::halfedge_of_dart(d.bits()), b0 = Plain::opposite(a0);
  const std::uint32_t a1 = pl.next(a0), a2 = pl.next(a1);
  const std::uint32_t b1 = pl.next(b0), b2 = pl.next(b1);
  // a and b lose the diagonal: keep their stored incoming darts off it.
  const std::uint32_t e = encoding::edge_of_halfedge(a0), va = pl.target(b0), vb = pl.target(a0);
  if (encoding::edge_of_dart(pl.vertex_dart(vb)) == e)
    pl.set_vertex_halfedge(vb, b2);
  if (encoding::edge_of_dart(pl.vertex_dart(va)) == e)
    pl.set_vertex_halfedge(va, a2);
  const std::uint32_t f_a = pl.face(a0), f_b = pl.face(b0);
  pl.set_face(b1, f_a);
  pl.set_face(a1, f_b);
  pl.set_face_halfedge(f_a, a0);
  pl.set_face_halfedge(f_b, b0);
  pl.set_target(a0, pl.target(a1));
  pl.set_target(b0, pl.target(b1));
  pl.set_next(a0, a2);
  pl.set_next(a2, b1);
  pl.set_next(b1, a0);
  pl.set_next(b0, b2);
  pl.set_next(b2, a1);
  pl.set_next(a1, b0);
  // The diagonal's halfedges now end at the far corners c = target(a1) and
  // d = target(b1): they take the values that fa had at c and fb at d (the
  // other corners keep their slots and values).
  mesh.copy_corner(Halfedge_index(a1), Halfedge_index(a0));
  mesh.copy_corner(Halfedge_index(b1), Halfedge_index(b0));
  return Dart::from_bits(encoding::dart(a0, false));
}

// join_face() once the edge of `h` is not Möbius and `h` unflipped.
template <class P>
Dart join_face_oriented(std::uint32_t h, Mobius_mesh<P>& mesh)
{
  const Plain_links pl(mesh);
  const std::uint32_t o = Plain::opposite(h);
  const std::uint32_t f = pl.face(h), g = pl.face(o);
  const std::uint32_t hp = pl.prev(h), hn = pl.next(h);
  const std::uint32_t op = pl.prev(o), on = pl.next(o);
  for (std::uint32_t c = on; c != o; c = pl.next(c))
    pl.set_face(c, f);
  pl.set_next(hp, on);
  pl.set_next(op, hn);
  pl.set_face_halfedge(f, hp);
  const std::uint32_t e = encoding::edge_of_halfedge(h);
  for (std::uint32_t end : {hp, op}) {
    const std::uint32_t v = pl.target(end);
    if (encoding::edge_of_dart(pl.vertex_dart(v)) == e)
      pl.set_vertex_halfedge(v, end);
  }
  mesh.remove_edge(Edge_index(e));
  mesh.remove_face(Face_index(g));
  return Dart::from_bits(encoding::dart(hp, false));
}

template <class P>
Dart join_face_unchecked(Dart d, Mobius_mesh<P>& mesh)
{
  d = orient_edge(d, mesh);
  return join_face_oriented(encoding::halfedge_of_dart(d.bits()), mesh);
}

template <class P>
Dart split_face_unchecked(Dart h, Dart g, Mobius_mesh<P>& mesh)
{
  if (h.is_flipped()) { // then g is too: turn their face
    const Walk wg = walk_of(g, mesh);
    h = CGAL_ext::internal::unflip(h, mesh);
    g = dart_of(wg, mesh);
  }
  const std::uint32_t hh = encoding::halfedge_of_dart(h.bits()), gh = encoding::halfedge_of_dart(g.bits());
  const Plain before(mesh);
  const std::uint32_t f = before.face(hh);
  const std::uint32_t hn = before.next(hh), gn = before.next(gh);
  const Edge_index e = mesh.add_edge(Vertex_index(before.target(gh)), Vertex_index(before.target(hh)));
  const std::uint32_t x = encoding::halfedge_of_edge(e.idx(), 0), y = encoding::halfedge_of_edge(e.idx(), 1);
  const std::uint32_t fn = mesh.add_face_record(Halfedge_index(gh)).idx();
  const Plain_links pl(mesh); // after adding: the arrays may have moved
  pl.set_next(hh, x);
  pl.set_next(x, gn);
  pl.set_next(gh, y);
  pl.set_next(y, hn);
  pl.set_face(x, f);
  for (std::uint32_t c = y; c != gh; c = pl.next(c))
    pl.set_face(c, fn);
  pl.set_face(gh, fn);
  pl.set_face_halfedge(f, hh);
  // The new corners are at corners the face had: x ends at target(g) in f,
  // y at target(h) in the new face; they take the face's values there.
  mesh.copy_corner(Halfedge_index(gh), Halfedge_index(x));
  mesh.copy_corner(Halfedge_index(hh), Halfedge_index(y));
  return Dart::from_bits(encoding::dart(x, false));
}

// join_vertex() once the star of source(d) is oriented with `d` unflipped
// (`orient_star()`): the walk round it is by halfedge index.
template <class P>
Dart join_vertex_oriented(Dart d, Mobius_mesh<P>& mesh)
{
  const Plain_links pl(mesh);
  const std::uint32_t h = encoding::halfedge_of_dart(d.bits()), o = Plain::opposite(h);
  const Dart od = Dart::from_bits(encoding::dart(o, false));
  const std::uint32_t s = pl.target(o), t = pl.target(h);
  const bool on_border = pl.is_border_vertex(s) || pl.is_border_vertex(t);
  // Along a border the links round t may be flipped: darts there. Faces
  // are linked by halfedge index.
  const auto plain_dart = [](std::uint32_t x) { return Dart::from_bits(encoding::dart(x, false)); };
  const Dart dp = on_border ? mesh.prev(d) : plain_dart(pl.prev(h));
  const Dart dn = on_border ? mesh.next(d) : plain_dart(pl.next(h));
  const Dart op = on_border ? mesh.prev(od) : plain_dart(pl.prev(o));
  const Dart on = on_border ? mesh.next(od) : plain_dart(pl.next(o));
  // The darts into s now end at t; the walk round s reads links only, not
  // the targets it changes.
  for (std::uint32_t c = Plain::opposite(pl.next(o)); c != o; c = Plain::opposite(pl.next(c)))
    pl.set_target(c, t);
  if (on_border) {
    mesh.set_next(dp, dn);
    mesh.set_next(op, on);
  } else {
    pl.set_next(encoding::halfedge_of_dart(dp.bits()), encoding::halfedge_of_dart(dn.bits()));
    pl.set_next(encoding::halfedge_of_dart(op.bits()), encoding::halfedge_of_dart(on.bits()));
  }
  for (const std::uint32_t side : {h, o}) {
    const std::uint32_t f = pl.face(side);
    if (f != encoding::null && pl.face_halfedge(f) == side)
      pl.set_face_halfedge(f, encoding::halfedge_of_dart((side == h ? dp : op).bits()));
  }
  mesh.remove_edge(Edge_index(encoding::edge_of_halfedge(h)));
  mesh.remove_vertex(Vertex_index(s));
  if (on_border) // t must store a border dart: look for it
    CGAL_ext::internal::reset_vertex_halfedge(Vertex_index(t), op, mesh);
  else
    pl.set_vertex_halfedge(t, encoding::halfedge_of_dart(op.bits()));
  return op;
}

template <class P>
Dart join_vertex_unchecked(Dart d, Mobius_mesh<P>& mesh)
{
  if (d.is_flipped() ||
      (!Plain::is_plain_everywhere(mesh) && CGAL_ext::internal::star_has_mobius_edge(mesh.opposite(d), mesh))) {
    const Walk wd = walk_of(d, mesh);
    // Orient the star of source(d) so that opposite(d), and with it d, is unflipped.
    CGAL_ext::internal::orient_star(mesh.opposite(d), mesh);
    d = dart_of(wd, mesh);
  }
  CGAL_assertion(!d.is_flipped());
  return join_vertex_oriented(d, mesh);
}

template <class P>
Dart remove_center_vertex_unchecked(Dart d, Mobius_mesh<P>& mesh)
{
  d = CGAL_ext::internal::orient_star(d, mesh);
  const Vertex_index v = mesh.target(d);
  const Face_index kept = mesh.face(d);
  boost::container::small_vector<Dart, 16> into;
  for (Dart c : CGAL_ext::halfedges_around_target(d, mesh))
    into.push_back(c);
  const Dart result = mesh.prev(d);
  // Around v the rim chains run against the circulation: chain i+1 ends where chain i starts.
  const std::size_t k = into.size();
  boost::container::small_vector<Dart, 16> first(k), last(k);
  for (std::size_t i = 0; i < k; ++i) {
    first[i] = mesh.next(mesh.next(into[i]));
    last[i] = mesh.prev(into[i]);
  }
  for (std::size_t i = 0; i < k; ++i) {
    for (Dart r = first[i];; r = mesh.next(r)) {
      mesh.set_face(r.halfedge(), kept);
      if (r == last[i])
        break;
    }
    mesh.set_next(last[(i + 1) % k], first[i]);
  }
  for (std::size_t i = 0; i < k; ++i) {
    const Vertex_index r = mesh.target(last[i]);
    const Halfedge_index stored = mesh.halfedge(r).halfedge();
    if (Mobius_mesh<P>::edge(stored) == mesh.edge(into[i]) ||
        Mobius_mesh<P>::edge(stored) == mesh.edge(mesh.next(into[i])))
      mesh.set_halfedge(r, last[i]);
    mesh.remove_edge(mesh.edge(into[i]));
    if (mesh.face(into[i]) != kept)
      mesh.remove_face(mesh.face(into[i]));
  }
  mesh.set_halfedge(kept, result.halfedge());
  mesh.remove_vertex(v);
  return result;
}

template <class P>
Dart make_hole_unchecked(Dart d, Mobius_mesh<P>& mesh)
{
  const Walk wd = walk_of(d, mesh);
  CGAL_ext::internal::detach_face(mesh.face(d), mesh, false);
  return dart_of(wd, mesh);
}

template <class P>
Dart add_face_to_border_unchecked(Dart h1, Dart h2, Mobius_mesh<P>& mesh)
{
  std::vector<Dart> cycle;
  for (Dart c = mesh.next(h1);; c = mesh.next(c)) {
    cycle.push_back(c);
    if (c == h2)
      break;
  }
  const Dart before = h1, after = mesh.next(h2);
  const Vertex_index a = mesh.target(h1), b = mesh.target(h2);
  const Edge_index e = mesh.add_edge(a, b);
  const Dart inner(Mobius_mesh<P>::halfedge(e, 0), false), outer(Mobius_mesh<P>::halfedge(e, 1), false);
  mesh.set_next(before, outer);
  mesh.set_next(outer, after);
  cycle.push_back(inner);
  CGAL_ext::internal::make_face_of_border_chain(cycle, mesh);
  for (std::size_t i = 0; i + 2 < cycle.size(); ++i)
    mesh.set_halfedge(mesh.target(Dart(cycle[i].halfedge(), false)), Dart(cycle[i].halfedge(), false));
  mesh.set_halfedge(a, before);
  mesh.set_halfedge(b, outer);
  return inner;
}

// True if the ring round the target of `into` (a halfedge into it, walked
// unflipped) meets no flipped link and no Möbius edge: then its star is
// oriented as `orient_star()` leaves it, and nothing there will turn.
template <class P>
bool is_plain_star(std::uint32_t into, const Mobius_mesh<P>& m)
{
  const Plain pl(m);
  if (pl.is_plain_everywhere())
    return true;
  std::uint32_t c = into;
  do {
    const std::uint32_t out = pl.plain_step(c);
    if (out == encoding::null)
      return false;
    c = Plain::opposite(out);
  } while (c != into);
  return true;
}

// collapse_edge() where no face turns: `d` unflipped, its edge and the sides
// that go with the triangles not Möbius, and the star of the removed end
// plain, which the joins and detaches keep so; `d` then names the same walk
// throughout, and join_vertex() needs no orient_star().
template <class P>
Vertex_index collapse_plain_edge(Dart d, Mobius_mesh<P>& mesh)
{
  const Plain pl(mesh); // the joins and detaches add nothing: the arrays stay
  const std::uint32_t h = encoding::halfedge_of_dart(d.bits());
  const Vertex_index p(pl.target(Plain::opposite(h))), q(pl.target(h));
  for (std::uint32_t side : {h, Plain::opposite(h)}) {
    if (pl.is_border(side) || pl.next(pl.next(pl.next(side))) != side)
      continue; // not a triangle (a face has three sides at least)
    const std::uint32_t gone = pl.prev(side);
    if (!pl.is_border(Plain::opposite(gone))) {
      join_face_oriented(gone, mesh);
    } else {
      CGAL_ext::internal::detach_face(Face_index(pl.face(side)), mesh, true);
      if (mesh.is_removed(p))
        return q; // p had no other face
    }
  }
  join_vertex_oriented(d, mesh);
  return q;
}

template <class P>
Vertex_index collapse_edge_unchecked(Dart d, Mobius_mesh<P>& mesh)
{
  if (!d.is_flipped()) {
    // The side that goes on the edge's own side ends at p: in p's star.
    const Plain pl(mesh);
    const std::uint32_t h = encoding::halfedge_of_dart(d.bits()), o = Plain::opposite(h);
    if (pl.is_plain_everywhere() ||
        (!pl.is_mobius(h) && (pl.is_border(o) || !pl.is_mobius(pl.prev(o))) && is_plain_star(o, mesh)))
      return collapse_plain_edge(d, mesh);
  }
  const Walk wd = walk_of(d, mesh);
  const Vertex_index p = mesh.source(d), q = mesh.target(d);
  for (bool first_side : {true, false}) {
    d = dart_of(wd, mesh);
    const Dart side = first_side ? d : mesh.opposite(d);
    if (mesh.is_border(side) || !internal::is_triangle(side, mesh))
      continue;
    // The triangle's side that ends at its first corner (at p on one side, at
    // q on the other) goes: the other side becomes the merged edge.
    const Dart gone = mesh.prev(side);
    if (!mesh.is_border(mesh.opposite(gone))) {
      join_face_unchecked(gone, mesh);
    } else {
      CGAL_ext::internal::detach_face(mesh.face(side), mesh, true);
      if (mesh.is_removed(p))
        return q; // p had no other face
    }
  }
  join_vertex_unchecked(dart_of(wd, mesh), mesh);
  return q;
}

} // namespace internal
} // namespace Euler
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_EULER_IMPL_H
