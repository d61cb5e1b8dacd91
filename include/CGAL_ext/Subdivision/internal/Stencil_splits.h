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
  return p.h_target[h] == v ? p.h_corner[h] : p.h_corner[p.h_prev[h] >> 1];
}

inline bool is_border_edge(const Level& p, u32 e)
{
  return p.h_face[2 * e] == null_u32 || p.h_face[2 * e + 1] == null_u32;
}

// Builds level `c` (nv vertices) from a face list, through the mesh's
// connectivity builder, which pairs the faces' sides and sets a Möbius bit
// where two faces run the same way.
// (The builder is serial; the corner numbering runs as ConcurrencyTag says.)
template <class ConcurrencyTag = CGAL::Sequential_tag>
void level_from_faces(u32 nv, const Face_list& faces, Level& c)
{
  CGAL_ext::internal::Connectivity_builder builder(faces.view(nv));
  c.resize(nv, builder.number_of_edges(), faces.size(), u32(faces.vertex.size()),
           Level::corner_table | Level::sharpness | Level::halfedge_corners);
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

// Doo–Sabin: child vertex k is parent corner k. Child faces: one per face
// (its corners), one quad per interior edge, one per vertex with three or
// more faces (interior or border).
template <class Mask, class W>
void dual_split(const Level& p, const Mask& mask, Face_list& faces, Stencils<W>& st)
{
  st.clear(p.nc);
  faces.clear();
  std::vector<W> w;
  std::vector<u32> ring;
  const W three_quarters = W(3) / W(4), quarter = W(1) / W(4);
  for (u32 f = 0; f < p.nf; ++f) {
    const u32 k0 = p.f_offset[f], n = p.degree(f);
    w.resize(n);
    bool smooth_weights = false;
    for (u32 i = 0; i < n; ++i) {
      const u32 h_in = p.corner_h[k0 + i], h_out = p.corner_h[k0 + (i + 1) % n];
      const u32 v = p.h_target[h_in];
      const bool in_border = p.h_face[h_in ^ 1u] == null_u32, out_border = p.h_face[h_out ^ 1u] == null_u32;
      if (in_border && out_border) {
        st.add(v, W(1));
      } else if (in_border || out_border) {
        // Chaikin on the border edge: the border tends to a quadratic B-spline.
        st.add(v, three_quarters);
        st.add(in_border ? p.source_of(h_in) : p.h_target[h_out], quarter);
      } else {
        if (!smooth_weights) {
          mask.corner(n, w.data());
          smooth_weights = true;
        }
        for (u32 j = 0; j < n; ++j)
          st.add(p.h_target[p.corner_h[k0 + (i + j) % n]], w[j]);
      }
      st.close();
    }
    ring.clear();
    for (u32 i = 0; i < n; ++i)
      ring.push_back(k0 + i);
    faces.add(ring.begin(), ring.end());
  }
  for (u32 e = 0; e < p.ne; ++e) {
    if (is_border_edge(p, e))
      continue;
    const std::array<u32, 4> q = dual_edge_quad(p, e);
    faces.add(q.begin(), q.end());
  }
  for (u32 v = 0; v < p.nv; ++v) {
    if (p.v_dart[v] == null_u32)
      continue;
    const auto [shared, along] = dual_vertex_ring(p, v, ring);
    // Two corners are already joined by the quads of the edges between them.
    if (ring.size() < 3)
      continue;
    // The polygon's sides are shared with edge quads only: orient it against
    // most of them, so that as few sides as can be become Möbius edges (none
    // on an orientable mesh, where the quads all run along the walk).
    if (2 * along > shared)
      faces.add(ring.rbegin(), ring.rend());
    else
      faces.add(ring.begin(), ring.end());
  }
}

// √3 step `refine_border` (every second step): child vertices are
// [parent vertices | centroids | two points per border edge (refining
// steps only)]. A face with a border edge gets no centroid in a refining
// step: its border edge is trisected instead.
template <class Mask, class W>
void sqrt3_split(const Level& p, const Mask& mask, bool refine_border, Face_list& faces, Stencils<W>& st)
{
  const u32 nv = p.nv, ne = p.ne, nf = p.nf;
  // Border face -> its border halfedge (refining steps), and the centroids.
  std::vector<u32> face_border(refine_border ? nf : 0, null_u32);
  if (refine_border) {
    for (u32 e = 0; e < ne; ++e) {
      if (!is_border_edge(p, e))
        continue;
      const u32 h = p.h_face[2 * e] == null_u32 ? 2 * e + 1 : 2 * e;
      CGAL_assertion(face_border[p.h_face[h]] == null_u32); // true after a non-refining step
      face_border[p.h_face[h]] = h;
    }
  }
  std::vector<u32> centroid(nf, null_u32);
  u32 next_vertex = nv;
  for (u32 f = 0; f < nf; ++f)
    if (!refine_border || face_border[f] == null_u32)
      centroid[f] = next_vertex++;
  std::vector<u32> border_point(refine_border ? ne : 0, null_u32); // first of the two points
  if (refine_border)
    for (u32 e = 0; e < ne; ++e)
      if (is_border_edge(p, e)) {
        border_point[e] = next_vertex;
        next_vertex += 2;
      }

  // Stencils, in child vertex order.
  st.clear(next_vertex);
  Vertex_weights<W> vw;
  for (u32 v = 0; v < nv; ++v) {
    const u32 d0 = p.v_dart[v];
    if (d0 == null_u32 || (p.is_border_dart(d0) && !refine_border)) {
      st.add(v, W(1));
    } else if (p.is_border_dart(d0)) {
      st.add(p.source(d0), W(4) / W(27));
      st.add(v, W(19) / W(27));
      st.add(p.target(p.next(d0)), W(4) / W(27));
    } else {
      u32 n = 0, d = d0;
      do {
        ++n;
        d = p.opposite(p.next(d));
      } while (d != d0);
      vw.vertex = vw.edge = W(0);
      mask.smooth_vertex(n, vw);
      st.add(v, vw.vertex);
      do {
        st.add(p.source(d), vw.edge);
        d = p.opposite(p.next(d));
      } while (d != d0);
    }
    st.close();
  }
  const W third = W(1) / W(3);
  for (u32 f = 0; f < nf; ++f) {
    if (centroid[f] == null_u32)
      continue;
    for (u32 k = p.f_offset[f]; k < p.f_offset[f + 1]; ++k)
      st.add(p.h_target[p.corner_h[k]], third);
    st.close();
  }
  if (refine_border) {
    for (u32 e = 0; e < ne; ++e) {
      if (border_point[e] == null_u32)
        continue;
      const u32 d = (p.h_face[2 * e] == null_u32 ? 2 * e : 2 * e + 1) << 1; // the border dart
      const u32 s = p.source(d), t = p.target(d);
      st.add(p.source(p.prev(d)), W(1) / W(27));
      st.add(s, W(16) / W(27));
      st.add(t, W(10) / W(27));
      st.close();
      st.add(s, W(10) / W(27));
      st.add(t, W(16) / W(27));
      st.add(p.target(p.next(d)), W(1) / W(27));
      st.close();
    }
  }
  CGAL_assertion(st.size() == next_vertex);

  // The border point of edge e nearest its end `x`.
  auto point_near = [&](u32 e, u32 x) {
    const u32 d = (p.h_face[2 * e] == null_u32 ? 2 * e : 2 * e + 1) << 1;
    return p.source(d) == x ? border_point[e] : border_point[e] + 1;
  };
  // What replaces face f next to its edge with end `x`: the centroid, or in a
  // refining step the border point nearest the end shared with f's border edge.
  auto apex = [&](u32 f, u32 x, u32 y) {
    if (centroid[f] != null_u32)
      return centroid[f];
    const u32 hb = face_border[f], eb = hb >> 1;
    const u32 shared = (p.h_target[hb] == x || p.source_of(hb) == x) ? x : y;
    return point_near(eb, shared);
  };
  faces.clear();
  for (u32 e = 0; e < ne; ++e) {
    const u32 h0 = 2 * e, h1 = 2 * e + 1;
    if (!is_border_edge(p, e)) {
      const u32 a = p.source_of(h0), b = p.h_target[h0];
      const u32 o0 = apex(p.h_face[h0], a, b), o1 = apex(p.h_face[h1], a, b);
      // The flipped edge o0–o1, oriented like face h0.
      faces.add({a, o1, o0});
      faces.add({o1, b, o0});
      continue;
    }
    const u32 h = p.h_face[h0] == null_u32 ? h1 : h0, f = p.h_face[h];
    const u32 a = p.source_of(h), b = p.h_target[h];
    if (centroid[f] != null_u32) {
      faces.add({a, b, centroid[f]});
    } else {
      const u32 x = p.h_target[p.h_next[h] >> 1];
      faces.add({point_near(e, a), point_near(e, b), x});
    }
  }
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_STENCIL_SPLITS_H
