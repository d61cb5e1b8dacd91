// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The vertex-to-edge and vertex-to-corner tables that let the parallel
// interpolation gather each vertex point's terms in the serial pass's
// order: built by walking around the vertices of a level, or, for a level
// made by a quad or triangle split, written from its parent's tables by
// the split's numbering, with no walk.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_INCIDENCE_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_INCIDENCE_H

#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Level.h>

#include <cstddef>
#include <utility>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// Per vertex, in increasing order (the order in which the serial pass adds
// their terms, so that a gather gives the same bits):
// - the ends of edges at it, each as 2e + end, end 0 being the source of
//   the edge's halfedge 0 and end 1 its target (an edge from a vertex to
//   itself is listed twice, 2e then 2e + 1);
// - the face corners at it (so its faces in increasing order), where the
//   split has face points (quad split); none for the triangle split.
struct Incidence
{
  Array<u32> edge_offset, edge_ends, corner_offset, corners;
  // The face of each corner, where the level does not give all its faces
  // one degree (`Level::face_degree` is 0: a base level).
  Array<u32> corner_face;
  u32 face_degree = 0; // the level's `face_degree`

  bool empty() const { return edge_offset.empty(); }
  void clear() { *this = Incidence(); }
  u32 face_of_corner(u32 k) const
  {
    return face_degree == 4 ? k >> 2 : (face_degree != 0 ? k / face_degree : corner_face[k]);
  }
};

// The edge end at which dart `d` ends, as 2e + end. A dart runs along its
// edge's halfedge 0 (and so ends at end 1) if it is halfedge 0 unflipped,
// or halfedge 1 flipped, except on a Möbius edge, whose two halfedges run
// the same way.
inline u32 edge_end_of_dart(const Level& p, u32 d)
{
  namespace de = dart_encoding;
  const u32 h = de::halfedge_of_dart(d), e = de::edge_of_halfedge(h);
  const bool along = (is_first_halfedge(h) || p.e_mobius[e] != 0) != de::is_flipped(d);
  return de::halfedge_of_edge(e, along ? 1u : 0u);
}

// The face of every corner of `p` into `inc`, unless the level gives all its
// faces one degree.
template <class ConcurrencyTag>
void index_corner_faces(const Level& p, Incidence& inc)
{
  inc.face_degree = p.face_degree;
  if (p.face_degree != 0)
    return;
  inc.corner_face.resize(p.nc);
  for_each_index<ConcurrencyTag>(p.nf, [&](u32 f) {
    for (u32 k = p.f_offset[f]; k < p.f_offset[f + 1]; ++k)
      inc.corner_face[k] = f;
  });
}

// The incidence tables of level `p`, serially: a counting sort of the edge
// ends and the face corners by vertex.
inline void build_incidence_serially(const Level& p, bool with_corners, Incidence& inc)
{
  namespace de = dart_encoding;
  auto ends = [&](u32 e) {
    const u32 h = de::halfedge_of_edge(e, 0);
    return std::pair<u32, u32>(p.source(de::dart(h, false)), p.h_target[h]);
  };
  inc.edge_offset.assign(std::size_t(p.nv) + 1, 0);
  for (u32 e = 0; e < p.ne; ++e) {
    ++inc.edge_offset[ends(e).first + 1];
    ++inc.edge_offset[ends(e).second + 1];
  }
  prefix_sum<CGAL::Sequential_tag>(inc.edge_offset.data(), p.nv);
  inc.edge_ends.resize(2 * std::size_t(p.ne));
  Array<u32> fill(inc.edge_offset.begin(), inc.edge_offset.end() - 1);
  for (u32 e = 0; e < p.ne; ++e) {
    inc.edge_ends[fill[ends(e).first]++] = dart_encoding::halfedge_of_edge(e, 0);
    inc.edge_ends[fill[ends(e).second]++] = dart_encoding::halfedge_of_edge(e, 1);
  }
  if (!with_corners)
    return;
  inc.corner_offset.assign(std::size_t(p.nv) + 1, 0);
  for (u32 k = 0; k < p.nc; ++k)
    ++inc.corner_offset[p.h_target[p.corner_h[k]] + 1];
  prefix_sum<CGAL::Sequential_tag>(inc.corner_offset.data(), p.nv);
  inc.corners.resize(p.nc);
  fill.assign(inc.corner_offset.begin(), inc.corner_offset.end() - 1);
  for (u32 k = 0; k < p.nc; ++k)
    inc.corners[fill[p.h_target[p.corner_h[k]]]++] = k;
  index_corner_faces<CGAL::Sequential_tag>(p, inc);
}

// The incidence tables of level `p`, a vertex at a time (in parallel for
// `CGAL::Parallel_tag`): the walk around a vertex meets each end of an edge
// at it once, and each face corner at it once, as a dart that is not on
// the border; its lists, sorted, are those of the counting sort. Counts
// first, then offsets by a prefix sum, then the lists.
template <class ConcurrencyTag = CGAL::Sequential_tag>
void build_incidence(const Level& p, bool with_corners, Incidence& inc)
{
  if constexpr (!is_parallel_tag<ConcurrencyTag>) {
    build_incidence_serially(p, with_corners, inc);
  } else {
    namespace de = dart_encoding;
    // The corner of each face halfedge (a base level has them). A dart at v
    // on a face ends its corner at v if it runs along the face cycle; a
    // flipped one starts there, and the corner at v is that of the halfedge
    // before it.
    Array<u32> own_corners;
    const u32* h_corner = p.h_corner.data();
    if (with_corners && p.h_corner.size() != 2 * std::size_t(p.ne)) {
      own_corners.resize(2 * std::size_t(p.ne));
      for_each_index<ConcurrencyTag>(p.nc, [&](u32 k) { own_corners[p.corner_h[k]] = k; });
      h_corner = own_corners.data();
    }
    auto corner_at = [&](u32 d) {
      const u32 h = de::halfedge_of_dart(d);
      return h_corner[de::is_flipped(d) ? de::halfedge_of_dart(p.h_prev[h]) : h];
    };
    inc.edge_offset.resize(std::size_t(p.nv) + 1);
    inc.edge_offset[0] = 0;
    if (with_corners) {
      inc.corner_offset.resize(std::size_t(p.nv) + 1);
      inc.corner_offset[0] = 0;
    }
    for_each_index<ConcurrencyTag>(p.nv, [&](u32 v) {
      u32 ends = 0, corners = 0;
      p.for_each_dart_at(v, [&](u32 d) {
        ++ends;
        corners += p.is_border_dart(d) ? 0 : 1;
      });
      inc.edge_offset[v + 1] = ends;
      if (with_corners)
        inc.corner_offset[v + 1] = corners;
    });
    prefix_sum<ConcurrencyTag>(inc.edge_offset.data(), p.nv);
    inc.edge_ends.resize(inc.edge_offset[p.nv]);
    if (with_corners) {
      prefix_sum<ConcurrencyTag>(inc.corner_offset.data(), p.nv);
      inc.corners.resize(inc.corner_offset[p.nv]);
    }
    for_each_index<ConcurrencyTag>(p.nv, [&](u32 v) {
      u32* ends = inc.edge_ends.data() + inc.edge_offset[v];
      u32 n_ends = 0, n_corners = 0;
      p.for_each_dart_at(v, [&](u32 d) {
        ends[n_ends++] = edge_end_of_dart(p, d);
        if (with_corners && !p.is_border_dart(d))
          inc.corners[inc.corner_offset[v] + n_corners++] = corner_at(d);
      });
      sort_short(ends, ends + n_ends);
      if (with_corners)
        sort_short(inc.corners.data() + inc.corner_offset[v], inc.corners.data() + inc.corner_offset[v] + n_corners);
    });
    if (with_corners)
      index_corner_faces<ConcurrencyTag>(p, inc);
  }
}

// Sorts the n ≤ 4 entries an edge point gets from the faces along its edge
// (n is 0, 1, 2 or 4) with compare-exchanges, which do not branch: their
// order depends on where the corners fall in their faces, which a branch
// would mispredict half the time.
inline void sort_face_entries(u32* x, u32 n)
{
  auto exchange = [x](int i, int j) {
    const u32 a = x[i], b = x[j];
    x[i] = a < b ? a : b;
    x[j] = a < b ? b : a;
  };
  if (n == 2) {
    exchange(0, 1);
  } else if (n == 4) {
    exchange(0, 1);
    exchange(2, 3);
    exchange(0, 2);
    exchange(1, 3);
    exchange(1, 2);
  } else if (n > 2) {
    sort_short(x, x + n);
  }
}

// The incidence tables of the child of `p` by `split` (numbered as in
// Level.h), written from the tables `pinc` of `p` (corners included for
// the quad split) rather than by walking the child, whose lists they
// equal:
// - a vertex point keeps its parent's lists, each edge end 2e + i becoming
//   the end i of the child edge 2e + i (its half at that end), each corner
//   k the corner of the child face at it;
// - an edge point has the ends of the parent edge's two halves, then, for
//   each face along the edge, the inner edges of the corners at either end
//   of the edge's halfedge in that face (one of them for the quad split),
//   and the corners of the child faces there;
// - a face point (quad split) has an inner edge and a child corner for each
//   corner of its face.
template <class ConcurrencyTag, Split split>
void derive_incidence(const Level& p, const Incidence& pinc, Incidence& inc)
{
  namespace de = dart_encoding;
  constexpr bool quad = split == Split::quad;
  const u32 nv = p.nv, ne = p.ne, nf = p.nf, nc = p.nc;
  const u32 child_nv = nv + ne + (quad ? nf : 0u);
  inc.clear();
  // faces_before[e]: the faces along the edges before e (a face on each
  // side of an edge that is not on the border).
  Array<u32> faces_before(std::size_t(ne) + 1);
  faces_before[0] = 0;
  for_each_index<ConcurrencyTag>(ne, [&](u32 e) {
    faces_before[e + 1] = u32(p.h_face[de::halfedge_of_edge(e, 0)] != null_u32) +
                          u32(p.h_face[de::halfedge_of_edge(e, 1)] != null_u32);
  });
  prefix_sum<ConcurrencyTag>(faces_before.data(), ne);
  // Where each kind of child vertex starts in the lists.
  constexpr u32 inner_per_side = quad ? 1 : 2;
  const u32 edge_point_ends = 2 * ne, face_point_ends = 4 * ne + inner_per_side * nc;
  const u32 edge_point_corners = nc, face_point_corners = 3 * nc;
  auto edge_point_end = [&](u32 e) { return edge_point_ends + 2 * e + inner_per_side * faces_before[e]; };
  auto edge_point_corner = [&](u32 e) { return edge_point_corners + 2 * faces_before[e]; };

  inc.face_degree = quad ? 4 : 3;
  inc.edge_offset.resize(std::size_t(child_nv) + 1);
  inc.edge_ends.resize(face_point_ends + (quad ? nc : 0u));
  for_each_index<ConcurrencyTag>(nv + 1, [&](u32 v) { inc.edge_offset[v] = pinc.edge_offset[v]; });
  for_each_index<ConcurrencyTag>(ne, [&](u32 e) { inc.edge_offset[nv + e + 1] = edge_point_end(e + 1); });
  for_each_index<ConcurrencyTag>(2 * ne, [&](u32 i) {
    // The child edge 2e + s of parent edge e keeps end s of its parent.
    const u32 end = pinc.edge_ends[i], s = de::side_of_halfedge(end);
    inc.edge_ends[i] = de::halfedge_of_edge(2 * de::edge_of_halfedge(end) + s, s);
  });
  if constexpr (quad) {
    inc.corner_offset.resize(std::size_t(child_nv) + 1);
    inc.corners.resize(4 * std::size_t(nc));
    for_each_index<ConcurrencyTag>(nv + 1, [&](u32 v) { inc.corner_offset[v] = pinc.corner_offset[v]; });
    for_each_index<ConcurrencyTag>(ne, [&](u32 e) { inc.corner_offset[nv + e + 1] = edge_point_corner(e + 1); });
    for_each_index<ConcurrencyTag>(nf, [&](u32 f) {
      inc.edge_offset[nv + ne + f + 1] = face_point_ends + p.f_offset[f + 1];
      inc.corner_offset[nv + ne + f + 1] = face_point_corners + p.f_offset[f + 1];
    });
    for_each_index<ConcurrencyTag>(nc, [&](u32 k) { inc.corners[k] = 4 * pinc.corners[k] + 3; });
  }
  // Each corner k of a face, at the end of its halfedge h, gives the edge
  // point of h its entries for that side (rank 0 or 1 among the faces
  // along the edge), and the face point its own.
  for_each_index<ConcurrencyTag>(nf, [&](u32 f) {
    const u32 k0 = p.f_offset[f], k1 = p.f_offset[f + 1];
    for (u32 k = k0; k < k1; ++k) {
      const u32 h = p.corner_h[k], e = de::edge_of_halfedge(h);
      const u32 before = k == k0 ? k1 - 1 : k - 1; // its halfedge ends where h starts
      const u32 rank = is_first_halfedge(h) ? 0u : u32(p.h_face[de::halfedge_of_edge(e, 0)] != null_u32);
      const u32 inner = 2 * ne + k, inner_before = 2 * ne + before;
      u32* ends = inc.edge_ends.data() + edge_point_end(e) + 2 + inner_per_side * rank;
      if constexpr (quad) {
        ends[0] = 2 * inner; // the inner edge runs from the edge point to the face point
        u32* corners = inc.corners.data() + edge_point_corner(e) + 2 * rank;
        corners[0] = 4 * k + 2;
        corners[1] = 4 * before + 0;
        inc.edge_ends[face_point_ends + k] = 2 * inner + 1;
        inc.corners[face_point_corners + k] = 4 * k + 1;
      } else {
        ends[0] = 2 * inner + 1;   // from the edge point of the next halfedge to h's
        ends[1] = 2 * inner_before; // from h's edge point to that of the one before
      }
    }
  });
  // The halves first (their ends, 4e + 1 and 4e + 2, come before any inner
  // edge's), then the faces' entries in order.
  for_each_index<ConcurrencyTag>(ne, [&](u32 e) {
    u32* ends = inc.edge_ends.data() + edge_point_end(e);
    ends[0] = de::halfedge_of_edge(2 * e, 1);
    ends[1] = de::halfedge_of_edge(2 * e + 1, 0);
    sort_face_entries(ends + 2, edge_point_end(e + 1) - edge_point_end(e) - 2);
    if constexpr (quad)
      sort_face_entries(inc.corners.data() + edge_point_corner(e), edge_point_corner(e + 1) - edge_point_corner(e));
  });
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_INCIDENCE_H
