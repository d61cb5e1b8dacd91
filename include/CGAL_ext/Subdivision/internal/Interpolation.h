// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Applying one step's weights or stencils to vertex data: a serial pass that
// scatters each edge's and face's terms into the vertex points, and a
// parallel pass that gathers them per vertex from incidence tables, in the
// same order, so that both give the same bits.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_INTERPOLATION_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_INTERPOLATION_H

#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Incidence.h>
#include <CGAL_ext/Subdivision/internal/Level.h>
#include <CGAL_ext/Subdivision/internal/Stencil_splits.h>
#include <CGAL_ext/Subdivision/internal/Weights.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// Where a pass writes the child's values, and reads back those it has
// written (face points, edge points): an array of values, or the points of
// the result mesh themselves (Point_output), so that the last level of a
// one-pass refinement needs no array of values and no copy.
template <class Value>
inline void store(Value* out, u32 i, const Value& x)
{
  out[i] = x;
}
template <class Value>
inline const Value& load(const Value* out, u32 i)
{
  return out[i];
}

// The points of a mesh as the output of a pass: each value converted by
// `Convert::to()` as it is written, and back by `Convert::from()` where it is
// read. For conversions that give back each value bit for bit (points of
// doubles), so that a pass into points computes what a pass into values does.
template <class Convert, class Point>
struct Point_output
{
  Point* points;

  Point_output operator+(u32 k) const { return {points + k}; }
};
template <class Convert, class Point>
inline void store(const Point_output<Convert, Point>& out, u32 i, const typename Convert::Value& x)
{
  out.points[i] = Convert::to(x);
}
template <class Convert, class Point>
inline typename Convert::Value load(const Point_output<Convert, Point>& out, u32 i)
{
  return Convert::from(out.points[i]);
}

// The points both passes share, formed by the same expressions so that the
// passes agree bit for bit. Declared inline: they run once per child vertex,
// and a call each costs the interpolation passes about a sixth of their time.
template <class W, class Value>
inline Value stencil_point(const Stencils<W>& st, u32 i, const Value* src)
{
  u32 j = st.offset[i];
  const u32 j1 = st.offset[i + 1];
  Value x = st.weight[j] * src[st.source[j]];
  for (++j; j < j1; ++j)
    x = x + st.weight[j] * src[st.source[j]];
  return x;
}

template <class W, class Value>
inline Value face_point(const Level& p, u32 f, const Value* src)
{
  const u32 k0 = p.f_offset[f], k1 = p.f_offset[f + 1];
  Value sum = src[p.h_target[p.corner_h[k0]]];
  for (u32 i = k0 + 1; i < k1; ++i)
    sum = sum + src[p.h_target[p.corner_h[i]]];
  return (k1 - k0 == 4 ? W(1) / W(4) : W(1) / W(int(k1 - k0))) * sum;
}

// `face_points`: the level's face points (quad split), indexed by face; the
// triangle split takes the vertices opposite the edge instead.
template <Split split, class W, class Value, class Out>
inline Value edge_point(const Level& p, const Edge_weights<W>& w, u32 e, const Value* src, const Out& face_points)
{
  namespace de = dart_encoding;
  const u32 h0 = de::halfedge_of_edge(e, 0);
  Value x = w.vertex * (src[p.source(de::dart(h0, false))] + src[p.h_target[h0]]);
  if (w.has_face) {
    for (u32 i = 0; i < 2; ++i) {
      const u32 h = de::halfedge_of_edge(e, i), f = p.h_face[h];
      if (f == null_u32)
        continue;
      if constexpr (split == Split::quad)
        x = x + w.face * internal::load(face_points, f);
      else
        x = x + w.face * src[p.h_target[de::halfedge_of_dart(p.h_next[h])]];
    }
  }
  return x;
}

// Child vertex i of a stencil step, for every i.
template <class ConcurrencyTag, class W, class Value, class Out>
void interpolate_stencils(const Stencils<W>& st, const Value* src, const Out& dst)
{
  for_each_index<ConcurrencyTag>(st.size(), [&](u32 i) { internal::store(dst, i, stencil_point(st, i, src)); });
}

// The point of parent vertex v, its sums of terms made (Vertex_sums):
// `sum(s)` gives sum s. Both passes form it with this expression.
template <class W, class Value, class Sum>
inline Value vertex_point(const Vertex_weights<W>& w, const Vertex_sums& vs, u32 v, const Value* src, const Sum& sum)
{
  Value x = w.vertex * src[v];
  if (w.has_crease)
    x = x + w.crease * (src[w.crease_ends[0]] + src[w.crease_ends[1]]);
  for (int s = 0; s < vs.count; ++s)
    if (Vertex_sums::has(w, vs.weight_of[s]))
      x = x + Vertex_sums::weight(w, vs.weight_of[s]) * sum(s);
  return x;
}

// Whether the point of a vertex with weights `w` takes any sum.
template <class W>
inline bool takes_sums(const Vertex_weights<W>& w)
{
  return w.has_edge || w.has_face || w.has_edge_point;
}

// The serial pass of a primal step: each edge and each face corner adds
// its terms, unweighted, to the sums of the vertices it touches, in edge
// and then face order; then each vertex point weights its sums. Sum 0 is
// kept in the vertex points themselves if they are values, the others (and
// sum 0 written into points) in scratch arrays.
template <Split split, class W, class Value, class Out>
void interpolate_primal(const Level& p, const Step_weights<W>& sw, const Value* src, const Out& dst)
{
  namespace de = dart_encoding;
  const u32 nv = p.nv, ne = p.ne, nf = p.nf;
  const u32 fp = nv + ne;
  if (nv == 0)
    return; // no edges, no faces
  const Vertex_sums& vs = sw.sums;
  constexpr bool sum_in_output = std::is_same_v<Out, Value*>;
  Array<Value> scratch[3]; // each element is set below
  Value* sums[3] = {nullptr, nullptr, nullptr};
  for (int s = 0; s < vs.count; ++s) {
    if constexpr (sum_in_output) {
      if (s == 0) {
        sums[0] = dst;
        continue;
      }
    }
    scratch[s].resize(nv);
    sums[s] = scratch[s].data();
  }
  auto sum_of = [&](Vertex_sums::Term t) { return vs.sum_of[t] == Vertex_sums::none ? nullptr : sums[vs.sum_of[t]]; };
  Value *neighbours = sum_of(Vertex_sums::neighbours), *edge_points = sum_of(Vertex_sums::edge_points),
        *face_points = sum_of(Vertex_sums::face_points);
  if constexpr (split == Split::quad) {
    for (u32 f = 0; f < nf; ++f)
      internal::store(dst, fp + f, face_point<W>(p, f, src));
  }
  // Each sum starts from 0 · the vertex's own point, as in the gather (a
  // zero made from one point would spread that point's infinities and NaNs
  // to every vertex, where now they stay at the vertex, as its own term does).
  for (int s = 0; s < vs.count; ++s)
    for (u32 v = 0; v < nv; ++v)
      sums[s][v] = W(0) * src[v];
  // Which sums the edges add to, as constants in the loop.
  with_flag(neighbours != nullptr, [&](auto to_neighbours) {
    with_flag(edge_points != nullptr, [&](auto to_edge_points) {
      for (u32 e = 0; e < ne; ++e) {
        const u32 h0 = de::halfedge_of_edge(e, 0);
        const u32 a = p.source(de::dart(h0, false)), b = p.h_target[h0];
        const Value x = edge_point<split>(p, sw.edge(e), e, src, dst + fp);
        internal::store(dst, nv + e, x);
        // All of a's terms, then b's: the gather's order where a = b.
        if constexpr (decltype(to_neighbours)::value)
          neighbours[a] = neighbours[a] + src[b];
        if constexpr (decltype(to_edge_points)::value)
          edge_points[a] = edge_points[a] + x;
        if constexpr (decltype(to_neighbours)::value)
          neighbours[b] = neighbours[b] + src[a];
        if constexpr (decltype(to_edge_points)::value)
          edge_points[b] = edge_points[b] + x;
      }
    });
  });
  if constexpr (split == Split::quad) {
    if (face_points)
      for (u32 f = 0; f < nf; ++f)
        for (u32 i = p.f_offset[f], i1 = p.f_offset[f + 1]; i < i1; ++i) {
          const u32 v = p.h_target[p.corner_h[i]];
          face_points[v] = face_points[v] + internal::load(dst, fp + f);
        }
  }
  for (u32 v = 0; v < nv; ++v)
    internal::store(dst, v, vertex_point(sw.vertex(v), vs, v, src, [&](int s) -> const Value& { return sums[s][v]; }));
}

// The serial pass as gathers over `inc` (the incidence tables of `p`), in
// the same order of terms; each loop may run in parallel.
template <class ConcurrencyTag, Split split, class W, class Value, class Out>
void interpolate_primal(const Level& p, const Step_weights<W>& sw, const Incidence& inc, const Value* src,
                        const Out& dst)
{
  namespace de = dart_encoding;
  const u32 nv = p.nv, ne = p.ne, nf = p.nf;
  const u32 fp = nv + ne;
  if (nv == 0)
    return;
  if constexpr (split == Split::quad)
    for_each_index<ConcurrencyTag>(nf, [&](u32 f) { internal::store(dst, fp + f, face_point<W>(p, f, src)); });
  for_each_index<ConcurrencyTag>(
    ne, [&](u32 e) { internal::store(dst, nv + e, edge_point<split>(p, sw.edge(e), e, src, dst + fp)); });
  const Vertex_sums& vs = sw.sums;
  const int neighbours = vs.sum_of[Vertex_sums::neighbours], edge_points = vs.sum_of[Vertex_sums::edge_points],
            face_points = vs.sum_of[Vertex_sums::face_points];
  // One sum (the standard masks) in one variable, which stays in registers.
  with_flag(vs.count == 1, [&](auto one_sum) {
    auto index = [](int s) { return decltype(one_sum)::value ? 0 : s; };
    for_each_index<ConcurrencyTag>(nv, [&](u32 v) {
      const Vertex_weights<W>& w = sw.vertex(v);
      const Value zero = W(0) * src[v];
      Value sums[3] = {zero, zero, zero};
      if (takes_sums(w)) {
        for (u32 i = inc.edge_offset[v]; i < inc.edge_offset[v + 1]; ++i) {
          const u32 end = inc.edge_ends[i], e = de::edge_of_halfedge(end);
          const u32 h0 = de::halfedge_of_edge(e, 0);
          if (neighbours != Vertex_sums::none) // the vertex at the other end
            sums[index(neighbours)] =
              sums[index(neighbours)] + src[de::side_of_halfedge(end) ? p.source(de::dart(h0, false)) : p.h_target[h0]];
          if (edge_points != Vertex_sums::none)
            sums[index(edge_points)] = sums[index(edge_points)] + internal::load(dst, nv + e);
        }
        if (split == Split::quad && face_points != Vertex_sums::none) // the triangle split has no face points
          for (u32 i = inc.corner_offset[v]; i < inc.corner_offset[v + 1]; ++i)
            sums[index(face_points)] =
              sums[index(face_points)] + internal::load(dst, fp + inc.face_of_corner(inc.corners[i]));
      }
      internal::store(dst, v, vertex_point(w, vs, v, src, [&](int s) -> const Value& { return sums[index(s)]; }));
    });
  });
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_INTERPOLATION_H
