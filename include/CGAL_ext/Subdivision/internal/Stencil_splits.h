// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The two schemes whose child vertices are not the parent's vertices, edges
// and faces: Doo–Sabin (dual: a point per face corner) and √3 (a point per
// triangle, old edges flipped). Each step lists the child faces by index
// arithmetic on the parent level, oriented like the parent faces they come
// from, and gives every child vertex a stencil (weighted parent vertices).
// The child connectivity, Möbius edges included, is then built from the face
// list by the mesh's linear-time connectivity builder.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_STENCIL_SPLITS_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_STENCIL_SPLITS_H

#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Level.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// Child vertex i is sum over j in [offset[i], offset[i+1]) of weight[j] * parent source[j].
template <class W>
struct Stencils
{
  std::vector<u32> offset, source;
  std::vector<W> weight;

  void clear(std::size_t reserve_vertices)
  {
    offset.assign(1, 0);
    offset.reserve(reserve_vertices + 1);
    source.clear();
    weight.clear();
  }
  void add(u32 s, const W& w)
  {
    source.push_back(s);
    weight.push_back(w);
  }
  void close() { offset.push_back(u32(source.size())); }
  u32 size() const { return u32(offset.size() - 1); }
};

// Child faces as flat lists of child vertices.
using CGAL_ext::internal::Face_list;

// The corner at end `v` of face halfedge `h`.
inline u32 corner_at(const Level& p, u32 h, u32 v)
{
  return p.h_target[h] == v ? p.h_corner[h] : p.h_corner[dart_encoding::halfedge_of_dart(p.h_prev[h])];
}

inline bool is_border_edge(const Level& p, u32 e)
{
  return p.h_face[dart_encoding::halfedge_of_edge(e, 0)] == null_u32 ||
         p.h_face[dart_encoding::halfedge_of_edge(e, 1)] == null_u32;
}

// The halfedge without a face of border edge `e`.
inline u32 border_halfedge(const Level& p, u32 e)
{
  const u32 h0 = dart_encoding::halfedge_of_edge(e, 0);
  return p.h_face[h0] == null_u32 ? h0 : dart_encoding::halfedge_of_edge(e, 1);
}

// Builds level `c` (nv vertices) from a face list, through the mesh's
// connectivity builder, which pairs the faces' sides and sets a Möbius bit
// where two faces run the same way; in parallel for `CGAL::Parallel_tag`.
template <class ConcurrencyTag = CGAL::Sequential_tag>
void level_from_faces(u32 nv, const Face_list& faces, Level& c)
{
  CGAL_ext::internal::Connectivity_builder builder(faces.view(nv), ConcurrencyTag());
  // No sharpness: Doo–Sabin and √3 have no creases.
  c.resize(nv, builder.number_of_edges(), faces.size(), u32(faces.vertex.size()),
           Level::corner_table | Level::halfedge_corners);
  CGAL_ext::internal::Connectivity_arrays arrays;
  arrays.target = c.h_target.data();
  arrays.next_bits = c.h_next.data();
  arrays.prev_bits = c.h_prev.data();
  arrays.face = c.h_face.data();
  arrays.vertex_dart_bits = c.v_dart.data();
  arrays.face_halfedge = c.f_first.data();
  arrays.mobius = c.e_mobius.data();
  builder.build(arrays, false);
  index_corners<ConcurrencyTag>(c);
}

// The Doo–Sabin quad of interior edge e, oriented like its face h0 (the
// corners at e's ends, in that face's order reversed): P, Q, R, S with P, Q
// in face h0 and R, S in face h1, Q and R at the source of h0.
inline std::array<u32, 4> dual_edge_quad(const Level& p, u32 e)
{
  const u32 h0 = dart_encoding::halfedge_of_edge(e, 0), h1 = dart_encoding::halfedge_of_edge(e, 1);
  const u32 a = p.source_of(h0), b = p.h_target[h0];
  return {p.h_corner[h0], corner_at(p, h0, a), corner_at(p, h1, a), corner_at(p, h1, b)};
}

// Whether the quad of edge e runs from corner x to corner y.
inline bool quad_runs_from_to(const Level& p, u32 e, u32 x, u32 y)
{
  const std::array<u32, 4> q = dual_edge_quad(p, e);
  for (u32 i = 0; i < 4; ++i)
    if (q[i] == x && q[(i + 1) % 4] == y)
      return true;
  return false;
}

// The Doo–Sabin face of vertex v: its corners in the order of the walk
// around v (border darts skipped), into `ring`. Returns the number of
// sides it shares with an edge quad and how many of those the quad runs
// along in walk order: a side run the same way by both faces is a Möbius edge.
inline std::pair<u32, u32> dual_vertex_ring(const Level& p, u32 v, std::vector<u32>& ring)
{
  ring.clear();
  u32 shared = 0, along = 0;
  const u32 d0 = p.v_dart[v];
  u32 d = d0;
  do {
    const u32 dn = p.opposite(p.next(d)); // across the edge of next(d)
    if (!p.is_border_dart(d)) {
      const u32 x = corner_at(p, dart_encoding::halfedge_of_dart(d), v);
      ring.push_back(x);
      if (!p.is_border_dart(dn)) {
        ++shared;
        const u32 y = corner_at(p, dart_encoding::halfedge_of_dart(dn), v);
        along += quad_runs_from_to(p, dart_encoding::edge_of_dart(dn), x, y) ? 1u : 0u;
      }
    }
    d = dn;
  } while (d != d0);
  return {shared, along};
}

// Appends to a list of lists (`offset`, whose last entry is where the
// entries end) the lists of elements [0, n): count(i, scratch) gives the
// number of lists and of entries of element i, resize(m) makes room for m
// entries in all, and write(i, list, entry, scratch) writes element i's
// lists from list number `list` and entry `entry` on, setting
// offset[list + j + 1] at the end of its list j. The lists lie in element
// order, as appending them in a loop over the elements lays them: both
// counts are prefix-summed, so that the elements may be written in
// parallel. `Scratch` is made once per block of elements.
template <class ConcurrencyTag, class Scratch, class Offsets, class Count, class Resize, class Write>
void append_lists(u32 n, Offsets& offset, const Count& count, const Resize& resize, const Write& write)
{
  Array<u32> lists(std::size_t(n) + 1), entries(std::size_t(n) + 1);
  lists[0] = entries[0] = 0;
  for_each_block<ConcurrencyTag>(n, [&](u32 begin, u32 end) {
    Scratch scratch;
    for (u32 i = begin; i < end; ++i) {
      const std::pair<u32, u32> c = count(i, scratch);
      lists[i + 1] = c.first;
      entries[i + 1] = c.second;
    }
  });
  prefix_sum<ConcurrencyTag>(lists.data(), n);
  prefix_sum<ConcurrencyTag>(entries.data(), n);
  const u32 list0 = u32(offset.size() - 1), entry0 = offset.back();
  offset.resize(offset.size() + lists[n]);
  resize(std::size_t(entry0) + entries[n]);
  for_each_block<ConcurrencyTag>(n, [&](u32 begin, u32 end) {
    Scratch scratch;
    for (u32 i = begin; i < end; ++i)
      write(i, list0 + lists[i], entry0 + entries[i], scratch);
  });
}

// The same for stencils and faces.
template <class ConcurrencyTag, class Scratch, class W, class Count, class Write>
void append_stencils(u32 n, Stencils<W>& st, const Count& count, const Write& write)
{
  append_lists<ConcurrencyTag, Scratch>(
    n, st.offset, count,
    [&](std::size_t m) {
      st.source.resize(m);
      st.weight.resize(m);
    },
    write);
}
template <class ConcurrencyTag, class Scratch, class Count, class Write>
void append_faces(u32 n, Face_list& faces, const Count& count, const Write& write)
{
  append_lists<ConcurrencyTag, Scratch>(
    n, faces.offset, count, [&](std::size_t m) { faces.vertex.resize(m); }, write);
}

// Doo–Sabin, the stencil of corner i of face f (of n corners from k0):
// writes its parent vertices and weights from `j` on and returns where it
// ends; `w` holds the face's smooth weights, made by the first interior
// corner (`made`).
template <class Mask, class W>
u32 dual_corner_stencil(const Level& p, const Mask& mask, u32 k0, u32 n, u32 i, std::vector<W>& w, bool& made,
                        Stencils<W>& st, u32 j)
{
  const u32 h_in = p.corner_h[k0 + i], h_out = p.corner_h[k0 + (i + 1) % n];
  const u32 v = p.h_target[h_in];
  const bool in_border = p.h_face[dart_encoding::opposite_halfedge(h_in)] == null_u32,
             out_border = p.h_face[dart_encoding::opposite_halfedge(h_out)] == null_u32;
  auto add = [&](u32 s, const W& x) {
    st.source[j] = s;
    st.weight[j] = x;
    ++j;
  };
  if (in_border && out_border) {
    add(v, W(1));
  } else if (in_border || out_border) {
    // Chaikin on the border edge: the border tends to a quadratic B-spline.
    add(v, W(3) / W(4));
    add(in_border ? p.source_of(h_in) : p.h_target[h_out], W(1) / W(4));
  } else {
    if (!made) {
      w.resize(n);
      mask.corner(n, w.data());
      made = true;
    }
    for (u32 t = 0; t < n; ++t)
      add(p.h_target[p.corner_h[k0 + (i + t) % n]], w[t]);
  }
  return j;
}

// The number of entries of the stencil of dual_corner_stencil().
inline u32 dual_corner_size(const Level& p, u32 k0, u32 n, u32 i)
{
  const bool in_border = p.h_face[dart_encoding::opposite_halfedge(p.corner_h[k0 + i])] == null_u32,
             out_border = p.h_face[dart_encoding::opposite_halfedge(p.corner_h[k0 + (i + 1) % n])] == null_u32;
  return in_border && out_border ? 1 : (in_border || out_border ? 2 : n);
}

// Doo–Sabin: child vertex k is parent corner k. Child faces: one per face
// (its corners), one quad per interior edge, one per vertex with three or
// more faces (interior or border). Faces, edges and vertices each give
// their stencils and faces in index order, in parallel for `CGAL::Parallel_tag`.
template <class ConcurrencyTag = CGAL::Sequential_tag, class Mask, class W>
void dual_split(const Level& p, const Mask& mask, Face_list& faces, Stencils<W>& st)
{
  st.clear(p.nc);
  faces.clear();
  append_stencils<ConcurrencyTag, std::vector<W>>(
    p.nf, st,
    [&](u32 f, std::vector<W>&) {
      const u32 k0 = p.f_offset[f], n = p.degree(f);
      u32 entries = 0;
      for (u32 i = 0; i < n; ++i)
        entries += dual_corner_size(p, k0, n, i);
      return std::pair<u32, u32>(n, entries);
    },
    [&](u32 f, u32 list, u32 entry, std::vector<W>& w) {
      const u32 k0 = p.f_offset[f], n = p.degree(f);
      bool made = false;
      for (u32 i = 0; i < n; ++i) {
        entry = dual_corner_stencil(p, mask, k0, n, i, w, made, st, entry);
        st.offset[list + i + 1] = entry;
      }
    });
  using Ring = std::vector<u32>;
  append_faces<ConcurrencyTag, Ring>(
    p.nf, faces, [&](u32 f, Ring&) { return std::pair<u32, u32>(1, p.degree(f)); },
    [&](u32 f, u32 list, u32 entry, Ring&) {
      for (u32 k = p.f_offset[f]; k < p.f_offset[f + 1]; ++k)
        faces.vertex[entry++] = k;
      faces.offset[list + 1] = entry;
    });
  append_faces<ConcurrencyTag, Ring>(
    p.ne, faces,
    [&](u32 e, Ring&) { return is_border_edge(p, e) ? std::pair<u32, u32>(0, 0) : std::pair<u32, u32>(1, 4); },
    [&](u32 e, u32 list, u32 entry, Ring&) {
      if (is_border_edge(p, e))
        return;
      const std::array<u32, 4> q = dual_edge_quad(p, e);
      std::copy(q.begin(), q.end(), faces.vertex.begin() + entry);
      faces.offset[list + 1] = entry + 4;
    });
  // A vertex face: two corners are already joined by the quads of the edges
  // between them, so it needs three. Its sides are shared with edge quads
  // only: it is oriented against most of them, so that as few sides as can
  // be become Möbius edges (none on an orientable mesh, where the quads all
  // run along the walk).
  auto vertex_face = [&](u32 v, Ring& ring) {
    if (p.v_dart[v] == null_u32)
      return false;
    const auto [shared, along] = dual_vertex_ring(p, v, ring);
    if (ring.size() < 3)
      return false;
    if (2 * along > shared)
      std::reverse(ring.begin(), ring.end());
    return true;
  };
  append_faces<ConcurrencyTag, Ring>(
    p.nv, faces,
    [&](u32 v, Ring& ring) {
      return vertex_face(v, ring) ? std::pair<u32, u32>(1, u32(ring.size())) : std::pair<u32, u32>(0, 0);
    },
    [&](u32 v, u32 list, u32 entry, Ring& ring) {
      if (!vertex_face(v, ring))
        return;
      std::copy(ring.begin(), ring.end(), faces.vertex.begin() + entry);
      faces.offset[list + 1] = entry + u32(ring.size());
    });
}

// The child vertices of a √3 step that are not parent vertices: the
// centroid of each face (null for none) and the first of the two points of
// each border edge (refining steps), numbered in face and edge order.
struct Sqrt3_points
{
  std::vector<u32> face_border, centroid, border_point;
  u32 count = 0; // child vertices
};

// The child vertices of a √3 step of `p` (see sqrt3_split()).
template <class ConcurrencyTag>
void number_sqrt3_points(const Level& p, bool refine_border, Sqrt3_points& pts)
{
  const u32 nv = p.nv, ne = p.ne, nf = p.nf;
  // Border face -> its border halfedge (refining steps).
  pts.face_border.assign(refine_border ? nf : 0, null_u32);
  if (refine_border)
    for_each_index<ConcurrencyTag>(ne, [&](u32 e) {
      if (!is_border_edge(p, e))
        return;
      const u32 h = dart_encoding::opposite_halfedge(border_halfedge(p, e)); // the face's side
      CGAL_assertion(pts.face_border[p.h_face[h]] == null_u32); // true after a non-refining step
      pts.face_border[p.h_face[h]] = h;
    });
  // Numbers from flags: first[i + 1] holds element i's count, then its number.
  auto number = [&](u32 n, u32 start, u32 step, const auto& has, std::vector<u32>& out) {
    Array<u32> first(std::size_t(n) + 1);
    first[0] = 0;
    for_each_index<ConcurrencyTag>(n, [&](u32 i) { first[i + 1] = has(i) ? step : 0; });
    prefix_sum<ConcurrencyTag>(first.data(), n);
    out.resize(n);
    for_each_index<ConcurrencyTag>(n, [&](u32 i) { out[i] = has(i) ? start + first[i] : null_u32; });
    return start + first[n];
  };
  pts.count = number(
    nf, nv, 1, [&](u32 f) { return !refine_border || pts.face_border[f] == null_u32; }, pts.centroid);
  pts.border_point.clear();
  if (refine_border)
    pts.count = number(
      ne, pts.count, 2, [&](u32 e) { return is_border_edge(p, e); }, pts.border_point);
}

// The √3 stencil of parent vertex v from entry `j` on; returns where it ends.
template <class Mask, class W>
u32 sqrt3_vertex_stencil(const Level& p, const Mask& mask, bool refine_border, u32 v, Stencils<W>& st, u32 j)
{
  auto add = [&](u32 s, const W& x) {
    st.source[j] = s;
    st.weight[j] = x;
    ++j;
  };
  const u32 d0 = p.v_dart[v];
  if (d0 == null_u32 || (p.is_border_dart(d0) && !refine_border)) {
    add(v, W(1));
  } else if (p.is_border_dart(d0)) {
    add(p.source(d0), W(4) / W(27));
    add(v, W(19) / W(27));
    add(p.target(p.next(d0)), W(4) / W(27));
  } else {
    u32 n = 0, d = d0;
    do {
      ++n;
      d = p.opposite(p.next(d));
    } while (d != d0);
    Vertex_weights<W> vw;
    vw.vertex = vw.edge = W(0);
    mask.smooth_vertex(n, vw);
    add(v, vw.vertex);
    do {
      add(p.source(d), vw.edge);
      d = p.opposite(p.next(d));
    } while (d != d0);
  }
  return j;
}

// The number of entries of sqrt3_vertex_stencil().
inline u32 sqrt3_vertex_stencil_size(const Level& p, bool refine_border, u32 v)
{
  const u32 d0 = p.v_dart[v];
  if (d0 == null_u32 || (p.is_border_dart(d0) && !refine_border))
    return 1;
  if (p.is_border_dart(d0))
    return 3;
  u32 n = 0, d = d0;
  do {
    ++n;
    d = p.opposite(p.next(d));
  } while (d != d0);
  return n + 1;
}

// √3 step `refine_border` (every second step): child vertices are
// [parent vertices | centroids | two points per border edge (refining
// steps only)]. A face with a border edge gets no centroid in a refining
// step: its border edge is trisected instead. Stencils in child vertex
// order, faces in edge order, in parallel for `CGAL::Parallel_tag`.
template <class ConcurrencyTag = CGAL::Sequential_tag, class Mask, class W>
void sqrt3_split(const Level& p, const Mask& mask, bool refine_border, Face_list& faces, Stencils<W>& st)
{
  Sqrt3_points pts;
  number_sqrt3_points<ConcurrencyTag>(p, refine_border, pts);
  const std::vector<u32>&face_border = pts.face_border, &centroid = pts.centroid, &border_point = pts.border_point;
  st.clear(pts.count);
  struct None
  {};
  append_stencils<ConcurrencyTag, None>(
    p.nv, st, [&](u32 v, None&) { return std::pair<u32, u32>(1, sqrt3_vertex_stencil_size(p, refine_border, v)); },
    [&](u32 v, u32 list, u32 entry, None&) {
      st.offset[list + 1] = sqrt3_vertex_stencil(p, mask, refine_border, v, st, entry);
    });
  append_stencils<ConcurrencyTag, None>(
    p.nf, st,
    [&](u32 f, None&) { return centroid[f] == null_u32 ? std::pair<u32, u32>(0, 0) : std::pair<u32, u32>(1, 3); },
    [&](u32 f, u32 list, u32 entry, None&) {
      if (centroid[f] == null_u32)
        return;
      for (u32 k = p.f_offset[f]; k < p.f_offset[f + 1]; ++k, ++entry) {
        st.source[entry] = p.h_target[p.corner_h[k]];
        st.weight[entry] = W(1) / W(3);
      }
      st.offset[list + 1] = entry;
    });
  if (refine_border) {
    append_stencils<ConcurrencyTag, None>(
      p.ne, st,
      [&](u32 e, None&) {
        return border_point[e] == null_u32 ? std::pair<u32, u32>(0, 0) : std::pair<u32, u32>(2, 6);
      },
      [&](u32 e, u32 list, u32 j, None&) {
        if (border_point[e] == null_u32)
          return;
        const u32 d = dart_encoding::dart(border_halfedge(p, e), false);
        const u32 s = p.source(d), t = p.target(d);
        const u32 src[6] = {p.source(p.prev(d)), s, t, s, t, p.target(p.next(d))};
        const int w27[6] = {1, 16, 10, 10, 16, 1};
        for (int i = 0; i < 6; ++i) {
          st.source[j + i] = src[i];
          st.weight[j + i] = W(w27[i]) / W(27);
        }
        st.offset[list + 1] = j + 3;
        st.offset[list + 2] = j + 6;
      });
  }
  CGAL_assertion(st.size() == pts.count);

  // The border point of edge e nearest its end `x`.
  auto point_near = [&](u32 e, u32 x) {
    const u32 d = dart_encoding::dart(border_halfedge(p, e), false);
    return p.source(d) == x ? border_point[e] : border_point[e] + 1;
  };
  // What replaces face f next to its edge with end `x`: the centroid, or in a
  // refining step the border point nearest the end shared with f's border edge.
  auto apex = [&](u32 f, u32 x, u32 y) {
    if (centroid[f] != null_u32)
      return centroid[f];
    const u32 hb = face_border[f], eb = dart_encoding::edge_of_halfedge(hb);
    const u32 shared = (p.h_target[hb] == x || p.source_of(hb) == x) ? x : y;
    return point_near(eb, shared);
  };
  faces.clear();
  append_faces<ConcurrencyTag, None>(
    p.ne, faces,
    [&](u32 e, None&) { return is_border_edge(p, e) ? std::pair<u32, u32>(1, 3) : std::pair<u32, u32>(2, 6); },
    [&](u32 e, u32 list, u32 j, None&) {
      const u32 h0 = dart_encoding::halfedge_of_edge(e, 0), h1 = dart_encoding::halfedge_of_edge(e, 1);
      u32 t[6];
      u32 n = 3;
      if (!is_border_edge(p, e)) {
        const u32 a = p.source_of(h0), b = p.h_target[h0];
        const u32 o0 = apex(p.h_face[h0], a, b), o1 = apex(p.h_face[h1], a, b);
        // The flipped edge o0–o1, oriented like face h0.
        const u32 two[6] = {a, o1, o0, o1, b, o0};
        std::copy(two, two + 6, t);
        n = 6;
      } else {
        const u32 h = p.h_face[h0] == null_u32 ? h1 : h0, f = p.h_face[h];
        const u32 a = p.source_of(h), b = p.h_target[h];
        if (centroid[f] != null_u32) {
          t[0] = a, t[1] = b, t[2] = centroid[f];
        } else {
          t[0] = point_near(e, a), t[1] = point_near(e, b), t[2] = p.h_target[dart_encoding::halfedge_of_dart(p.h_next[h])];
        }
      }
      std::copy(t, t + n, faces.vertex.begin() + j);
      faces.offset[list + 1] = j + 3;
      if (n == 6)
        faces.offset[list + 2] = j + 6;
    });
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_STENCIL_SPLITS_H
