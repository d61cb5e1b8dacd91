// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The steps Euler operations on a Mobius_mesh share: naming a walk so that it
// survives the reversal of faces, orienting the faces of a small patch
// consistently (so that the orientable operation applies with unflipped
// darts), re-linking a border after faces were detached, and making a face of
// a closed chain of border darts.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_EULER_SUPPORT_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_EULER_SUPPORT_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Plain_links.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <vector>

namespace CGAL_ext {
namespace internal {

// A dart named by its halfedge and target: reversing a face changes which bit
// makes a given walk, but not the halfedge or where the walk ends.
struct Walk
{
  Halfedge_index halfedge;
  Vertex_index target;
};

template <class P>
Walk walk_of(Dart d, const Mobius_mesh<P>& m)
{
  return {d.halfedge(), m.target(d)};
}

template <class P>
Dart dart_of(Walk w, const Mobius_mesh<P>& m)
{
  const Dart d(w.halfedge, false);
  return m.target(d) == w.target ? d : d.flipped();
}

// The face whose reversal turns the halfedge of `d`: its own, or across a border.
template <class P>
Face_index face_carrying(Dart d, const Mobius_mesh<P>& m)
{
  return m.is_border(d) ? m.face(m.opposite(d)) : m.face(d);
}

// Reverses the face carrying `d` if `d` is flipped; returns the unflipped dart
// that makes the same walk.
template <class P>
Dart unflip(Dart d, Mobius_mesh<P>& m)
{
  if (!d.is_flipped())
    return d;
  const Walk w = walk_of(d, m);
  m.reverse_face_orientation(face_carrying(d, m));
  return dart_of(w, m);
}

// Reverses the face across the edge of `d` (not the face of `d`) if the edge
// is Möbius, so that the two faces run against each other along it.
template <class P>
void make_edge_orientable(Dart d, Mobius_mesh<P>& m)
{
  if (m.is_mobius(m.edge(d)))
    m.reverse_face_orientation(m.face(m.opposite(d)));
}

// The faces around `target(d)` in circulation order, from the face of `d`
// (border gaps skipped).
template <class P>
std::vector<Face_index> star_faces(Dart d, const Mobius_mesh<P>& m)
{
  std::vector<Face_index> faces;
  for (Dart c : CGAL_ext::halfedges_around_target(d, m))
    if (!m.is_border(c))
      faces.push_back(m.face(c));
  return faces;
}

// True if an edge at `target(d)` is Möbius: only then can the faces around
// it disagree. One circulation, without the checks of the general walk.
template <class P>
bool star_has_mobius_edge(Dart d, const Mobius_mesh<P>& m)
{
  Dart c = d;
  do {
    const Dart out = m.next(c);
    if (m.is_mobius(m.edge(out)))
      return true;
    c = m.opposite(out);
  } while (c != d);
  return false;
}

// Orients the faces around `target(d)` consistently, with `d` unflipped: the
// star of a vertex of a 2-manifold is a disk, so this is always possible, and
// afterwards every dart into or out of the vertex (border darts included) is
// unflipped. Returns the unflipped dart that makes the walk of `d`.
template <class P>
Dart orient_star(Dart d, Mobius_mesh<P>& m)
{
  if (!d.is_flipped() && (Plain_reader::is_plain_everywhere(m) || !star_has_mobius_edge(d, m)))
    return d; // the usual case: nothing to turn, and d already runs the right way
  const Walk w = walk_of(d, m);
  CGAL_assertion_code(const Vertex_index v = m.target(d);)
  // Walk the fan from a face dart, turning each next face to agree with the last.
  Dart c = m.is_border(d) ? m.opposite(m.next(d)) : d; // a face dart into v
  Dart start = c;
  std::size_t n = 0; // faces around v
  for (Dart x : CGAL_ext::halfedges_around_target(d, m))
    n += m.is_border(x) ? 0 : 1;
  for (std::size_t k = 1; k < n; ++k) {
    const Dart out = m.next(c);
    const Dart across = m.opposite(out);
    if (m.is_border(across))
      break;
    if (m.is_mobius(m.edge(out))) {
      const Walk wc = walk_of(across, m);
      m.reverse_face_orientation(m.face(across));
      c = dart_of(wc, m);
    } else {
      c = across;
    }
  }
  // A border vertex's fan may have started mid-way: orient the other side.
  c = start;
  for (std::size_t k = 1; k < n; ++k) {
    const Dart back = m.opposite(c);
    if (m.is_border(back))
      break;
    const Dart prev = m.prev(back);
    if (m.is_mobius(m.edge(c))) {
      const Walk wp = walk_of(prev, m);
      m.reverse_face_orientation(m.face(prev));
      c = dart_of(wp, m);
    } else {
      c = prev;
    }
    if (m.face(c) == m.face(start))
      break;
  }
  Dart r = dart_of(w, m);
  if (r.is_flipped()) {
    for (Face_index f : star_faces(r, m))
      m.reverse_face_orientation(f);
    r = dart_of(w, m);
  }
  CGAL_assertion(m.target(r) == v && !r.is_flipped());
  return r;
}

// The stored dart of `v` after an edit: a border dart into `v` if there is
// one, otherwise `into` (a dart into `v`).
template <class P>
void reset_vertex_halfedge(Vertex_index v, Dart into, Mobius_mesh<P>& m)
{
  CGAL_assertion(m.target(into) == v);
  for (Dart c : CGAL_ext::halfedges_around_target(into, m))
    if (m.is_border(c)) {
      m.set_halfedge(v, c);
      return;
    }
  m.set_halfedge(v, into);
}

// Re-links the border at `v` from its faces, after faces next to `v` were
// detached: walks the fan from the face dart `c` (into `v`) both ways to the
// border edges on either side of the one gap, and joins them. Orientation-free:
// darts carry their own bits.
template <class P>
void relink_border_at(Vertex_index v, Dart c, Mobius_mesh<P>& m)
{
  Dart in = c;
  for (;;) {
    const Dart across = m.opposite(m.next(in));
    in = across;
    if (m.is_border(across))
      break;
  }
  Dart out = c;
  for (;;) {
    const Dart back = m.opposite(out);
    if (m.is_border(back)) {
      out = back;
      break;
    }
    out = m.prev(back);
  }
  m.set_next(in, out);
  m.set_halfedge(v, in);
}

// Makes a face of the closed chain `cycle` of border darts (next(cycle[i]) is
// cycle[i+1], cyclically, or will be once linked): each halfedge gets the new
// face and is stored along it; a dart that walked against its halfedge's
// direction turns the halfedge round, and its edge becomes Möbius (the new
// face runs along it the same way as the face across).
template <class P>
Face_index make_face_of_border_chain(const std::vector<Dart>& cycle, Mobius_mesh<P>& m)
{
  const std::size_t k = cycle.size();
  std::vector<Vertex_index> targets(k);
  for (std::size_t i = 0; i < k; ++i)
    targets[i] = m.target(cycle[i]);
  const Face_index f = m.add_face_record(cycle[0].halfedge());
  for (std::size_t i = 0; i < k; ++i) {
    const Halfedge_index h = cycle[i].halfedge();
    m.set_face(h, f);
    m.set_next(Dart(h, false), Dart(cycle[(i + 1) % k].halfedge(), false));
  }
  for (std::size_t i = 0; i < k; ++i) {
    const Halfedge_index h = cycle[i].halfedge();
    m.set_target(h, targets[i]);
    const bool has_other_face = !m.is_border(Mobius_mesh<P>::opposite_halfedge(h));
    m.set_mobius(m.edge(h), has_other_face && cycle[i].is_flipped());
  }
  return f;
}

// Detaches face `f`: its halfedges become border halfedges (those whose edge
// then has no face are removed with it), the border is re-linked at each
// corner, and corners left without any face are removed if `remove_isolated`,
// or kept as isolated vertices. The face record is removed.
template <class P>
void detach_face(Face_index f, Mobius_mesh<P>& m, bool remove_isolated)
{
  struct Side { Dart d; Vertex_index source, target; bool other_border; };
  std::vector<Side> sides;
  for (Dart d : CGAL_ext::halfedges_around_face(f, m))
    sides.push_back({d, m.source(d), m.target(d), m.is_border(m.opposite(d))});
  for (const Side& s : sides) {
    const Halfedge_index h = s.d.halfedge();
    m.set_face(h, Face_index());
    m.clear_corner(h); // a border halfedge holds no corner
    if (s.other_border) {
      m.remove_edge(m.edge(h));
    } else if (m.is_mobius(m.edge(h))) {
      // A border halfedge runs against the face across: turn this one round.
      m.set_mobius(m.edge(h), false);
      m.set_target(h, s.source);
    }
  }
  const std::size_t k = sides.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Side& in = sides[i];
    const Side& out = sides[(i + 1) % k];
    const Vertex_index v = in.target;
    if (!out.other_border) {
      // The face across the outgoing side has a dart into v.
      relink_border_at(v, dart_of(Walk{Mobius_mesh<P>::opposite_halfedge(out.d.halfedge()), v}, m), m);
    } else if (!in.other_border) {
      const Dart away = dart_of(Walk{Mobius_mesh<P>::opposite_halfedge(in.d.halfedge()), in.source}, m);
      relink_border_at(v, m.prev(away), m);
    } else {
      m.set_halfedge(v, Dart());
      if (remove_isolated)
        m.remove_vertex(v);
    }
  }
  m.remove_face(f);
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_EULER_SUPPORT_H
