// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The links of a Mobius_mesh read and written as plain halfedge indices, as
// Surface_mesh does: next(h) is the stored link, opposite(h) is h ^ 1, and no
// orientation bit is looked at. That is exact wherever the darts involved are
// unflipped and no edge crossed is Möbius, which holds for every face cycle
// (a face cycle never mixes orientations) and for the whole star of a vertex
// whose edges are none of them Möbius. Euler operations check that once (or,
// walking a ring, at each step, with `plain_step()`), then edit the arrays as
// an orientable mesh would: a flip bit tested at every step costs them more
// than the edit itself.
//
// A view holds the arrays' addresses, so that a sequence of edits reloads
// none of them: it is valid until an element is added to the mesh (which may
// move the arrays); make it after adding.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_PLAIN_LINKS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_PLAIN_LINKS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>

#include <cstdint>

namespace CGAL_ext {
namespace internal {

// Reading. The arrays hold 32-bit values (indices, dart bits) and the
// Möbius bytes, as Connectivity_access lays them out.
class Plain_reader
{
public:
  using u32 = std::uint32_t;

  template <class P>
  explicit Plain_reader(const Mobius_mesh<P>& m)
    : next_(raw(m.h_next_)), prev_(raw(m.h_prev_)), target_(raw(m.h_target_)), face_(raw(m.h_face_)),
      vertex_(raw(m.v_halfedge_)), face_halfedge_(raw(m.f_halfedge_)), mobius_(m.e_mobius_.data()),
      everywhere_(is_plain_everywhere(m))
  {}

  // True if the mesh has no Möbius edge (it counts them): then, the mesh
  // being valid (one fan per vertex), no link is flipped either (faces agree
  // across every edge, so the border darts at a vertex run the way its faces
  // do), and every walk is plain.
  template <class P>
  static bool is_plain_everywhere(const Mobius_mesh<P>& m)
  {
    return m.mobius_edges_ == 0;
  }
  bool is_plain_everywhere() const { return everywhere_; }

  static constexpr u32 opposite(u32 h) { return dart_encoding::opposite_halfedge(h); }

  // The halfedge after (before) `h` in its cycle. Exact for a face halfedge,
  // and for a border halfedge whose stored link is unflipped.
  u32 next(u32 h) const { return dart_encoding::halfedge_of_dart(next_[h]); }
  u32 prev(u32 h) const { return dart_encoding::halfedge_of_dart(prev_[h]); }

  // For a ring walk round the target of `into`: the halfedge after `into`,
  // out of that vertex, whose opposite is the next halfedge into it; or
  // `dart_encoding::null` where the stored link is flipped or the edge out is
  // Möbius, where the plain walk stops being the walk of darts.
  u32 plain_step(u32 into) const
  {
    const u32 n = next_[into];
    if (!everywhere_ && (dart_encoding::is_flipped(n) || mobius_[dart_encoding::edge_of_dart(n)] != 0))
      return dart_encoding::null;
    return dart_encoding::halfedge_of_dart(n);
  }

  u32 target(u32 h) const { return target_[h]; }
  u32 face(u32 h) const { return face_[h]; }
  bool is_border(u32 h) const { return face_[h] == dart_encoding::null; }
  bool is_mobius(u32 h) const { return mobius_[dart_encoding::edge_of_halfedge(h)] != 0; }
  // The bits of the stored dart of vertex `v`.
  u32 vertex_dart(u32 v) const { return vertex_[v]; }
  bool is_border_vertex(u32 v) const
  {
    const u32 d = vertex_[v];
    return d == dart_encoding::null || is_border(dart_encoding::halfedge_of_dart(d));
  }
  u32 face_halfedge(u32 f) const { return face_halfedge_[f]; }

protected:
  template <class Array>
  static u32* raw(const Array& a)
  {
    static_assert(sizeof(typename Array::value_type) == sizeof(u32), "handles are plain 32-bit values");
    return reinterpret_cast<u32*>(const_cast<typename Array::value_type*>(a.data()));
  }

  // Written only through a Plain_links, which is made from a mutable mesh.
  u32 *next_, *prev_, *target_, *face_, *vertex_, *face_halfedge_;
  const std::uint8_t* mobius_;
  bool everywhere_;
};

// Reading and writing.
class Plain_links : public Plain_reader
{
public:
  template <class P>
  explicit Plain_links(Mobius_mesh<P>& m) : Plain_reader(m)
  {}

  // Links `h` to `g` within a face (or a border cycle that runs unflipped).
  void set_next(u32 h, u32 g) const
  {
    next_[h] = dart_encoding::dart(g, false);
    prev_[g] = dart_encoding::dart(h, false);
  }
  void set_target(u32 h, u32 v) const { target_[h] = v; }
  void set_face(u32 h, u32 f) const { face_[h] = f; }
  // The stored dart of `v`: the unflipped dart of `h`.
  void set_vertex_halfedge(u32 v, u32 h) const { vertex_[v] = dart_encoding::dart(h, false); }
  void set_face_halfedge(u32 f, u32 h) const { face_halfedge_[f] = h; }
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_PLAIN_LINKS_H
