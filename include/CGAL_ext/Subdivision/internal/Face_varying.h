// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Face-varying (corner) data through the levels of a refiner: the topology of
// a channel at each level (which corners share a value, where the seams are,
// which values are corners or creases of the channel), and the interpolation
// of its values, with OpenSubdiv's face-varying rules (Vtr::FVarLevel,
// FVarRefinement, Far::PrimvarRefiner::InterpolateFaceVarying).

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_FACE_VARYING_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_FACE_VARYING_H

#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Incidence.h>
#include <CGAL_ext/Subdivision/internal/Interpolation.h>
#include <CGAL_ext/Subdivision/internal/Level.h>
#include <CGAL_ext/Subdivision/internal/Stencil_splits.h>
#include <CGAL_ext/Subdivision/internal/Weights.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// One channel at one level. A value is one of the distinct values at one
// vertex (OpenSubdiv's "sibling"): the values of vertex v are
// [v_offset[v], v_offset[v + 1]), and corner[h], the value of the corner of
// face halfedge h (at its target), is one of its target's. At the base level
// the values are the user's, and a vertex's values name them through
// `value_of`; at the levels after it the values are numbered vertex by vertex.
struct Fvar_level
{
  enum Edge_tag : std::uint8_t { mismatch = 1, linear = 2 };
  enum Value_tag : std::uint8_t { differs = 1, crease = 2, semi_sharp = 4, dependent = 8 };
  // The level's arrays (Level.h's Array: large ones on huge pages, whose
  // first touches cost most of a channel's time at fine levels).
  Array<u32> corner;             // per halfedge (null on the border)
  Array<std::uint8_t> edge_tag;  // per edge
  Array<u32> v_offset;           // per vertex, and one past the last
  Array<u32> value_of;           // per vertex value: its index in the values (base level only)
  Array<std::uint8_t> value_tag; // per vertex value; 0: matches the vertex topology

  u32 value(u32 vertex_value) const { return value_of.empty() ? vertex_value : value_of[vertex_value]; }
};

// What the linear-interpolation mode decides (FVarLevel's option flags).
struct Fvar_rules
{
  bool linear_all, linear_boundaries, dependent_sharpness, sharpen_both_if_one_corner, sharpen_darts,
    make_smooth_corners_sharp, corners_are_sharp;

  Fvar_rules(Face_varying_interpolation mode, Boundary_interpolation boundary)
  {
    using F = Face_varying_interpolation;
    linear_all = mode == F::all;
    linear_boundaries = linear_all || mode == F::boundaries;
    dependent_sharpness = mode == F::corners_plus1 || mode == F::corners_plus2;
    sharpen_both_if_one_corner = mode == F::corners_plus2;
    sharpen_darts = sharpen_both_if_one_corner || linear_boundaries;
    corners_are_sharp = mode != F::none;
    make_smooth_corners_sharp = boundary != Boundary_interpolation::edge_and_corner && corners_are_sharp;
  }
};

// The faces and edges around a vertex in the order of a walk (OpenSubdiv's
// vertex-face and vertex-edge lists): dart[i] is the face dart of face i
// that ends at the vertex, edge i is shared by faces i − 1 and i, and a
// border vertex starts at its border and has one edge more than faces.
struct Fvar_ring
{
  // Inline room for the rings of all but rare vertices: a ring is walked
  // per vertex of every level, where a heap allocation would cost more than
  // the walk.
  using Darts = boost::container::small_vector<u32, 16>;
  Darts dart, edge;
  bool border = false;
  Darts all;

  void walk(const Level& L, u32 v)
  {
    dart.clear();
    edge.clear();
    border = false;
    all.clear();
    L.for_each_dart_at(v, [&](u32 d) { all.push_back(d); });
    std::size_t first = 0;
    for (std::size_t i = 0; i < all.size(); ++i)
      if (L.is_border_dart(all[i])) {
        border = true;
        first = i;
      }
    const std::size_t n = all.size();
    for (std::size_t i = border ? 1 : 0; i < n; ++i) {
      const u32 d = all[(first + i) % n];
      dart.push_back(d);
      edge.push_back(dart_encoding::edge_of_dart(d));
    }
    if (border)
      edge.push_back(dart_encoding::edge_of_dart(all[first]));
  }
  u32 faces() const { return u32(dart.size()); }
};

// The slot of the corner of the face of dart d at target(d): the face
// halfedge that ends there along the face's orientation.
inline u32 corner_slot(const Level& L, u32 d)
{
  return dart_encoding::is_flipped(d) ? dart_encoding::halfedge_of_dart(L.next(d)) : dart_encoding::halfedge_of_dart(d);
}

inline float sharpness_of_edge(const Level& L, u32 e) { return L.e_sharp.empty() ? 0.0f : L.e_sharp[e]; }
inline float sharpness_of_vertex(const Level& L, u32 v) { return L.v_sharp.empty() ? 0.0f : L.v_sharp[v]; }

// What a step of a channel reads of the child level: its counts and its
// sharpness (null: all of it 0). A one-pass refinement has no child level
// in its last step, only the sharpness its weights gave the child.
struct Child_level_view
{
  u32 nv = 0, ne = 0;
  const float* e_sharp = nullptr;
  const float* v_sharp = nullptr;

  static Child_level_view of(const Level& L)
  {
    return {L.nv, L.ne, L.e_sharp.empty() ? nullptr : L.e_sharp.data(), L.v_sharp.empty() ? nullptr : L.v_sharp.data()};
  }
};
inline float sharpness_of_edge(const Child_level_view& C, u32 e) { return C.e_sharp ? C.e_sharp[e] : 0.0f; }
inline float sharpness_of_vertex(const Child_level_view& C, u32 v) { return C.v_sharp ? C.v_sharp[v] : 0.0f; }
// Border edges are infinitely sharp, as in OpenSubdiv.
inline bool is_inf_sharp_edge(const Level& L, u32 e)
{
  return is_border_edge(L, e) || Crease::is_infinite(sharpness_of_edge(L, e));
}

// The vertex value (index into F's values) of each face of a ring.
inline void ring_values(const Level& L, const Fvar_level& F, const Fvar_ring& r, std::vector<u32>& out)
{
  out.resize(r.faces());
  for (u32 i = 0; i < r.faces(); ++i)
    out[i] = F.corner[corner_slot(L, r.dart[i])];
}

// The span of faces of one value around a vertex (FVarLevel::ValueSpan):
// its first face and number of faces, whether it is broken (by a seam or an
// infinitely sharp edge, or met twice) and how many semi-sharp edges it has inside.
struct Fvar_span
{
  u32 size = 0, start = 0;
  int disjoint = 0, semi_sharp = 0;
};

// An edge inside a span (between two faces of one value): a seam breaks the
// span (counted, as a span that wraps round is counted once too often), an
// infinitely sharp edge breaks it, a semi-sharp one is counted.
inline void classify_inner_edge(const Level& L, const Fvar_level& F, u32 e, Fvar_span& s)
{
  if (F.edge_tag[e] & Fvar_level::mismatch)
    ++s.disjoint;
  else if (is_inf_sharp_edge(L, e))
    s.disjoint = std::max(s.disjoint, 1);
  else if (Crease::is_semi_sharp(sharpness_of_edge(L, e)))
    ++s.semi_sharp;
}

// Which faces of a ring each value spans (FVarLevel::gatherValueSpans());
// `sibling[i]` is the value of face i, numbered 0, 1, ... in order of first
// appearance, `values` how many there are.
inline void gather_spans(const Level& L, const Fvar_level& F, const Fvar_ring& r, const std::vector<u32>& sibling,
                         u32 values, std::vector<Fvar_span>& spans)
{
  spans.assign(values, Fvar_span());
  const u32 m = r.faces();
  if (values == 1) {
    // One value: a dart of the channel if one edge is a seam, broken if more.
    Fvar_span& s = spans[0];
    for (u32 i = 0; i < u32(r.edge.size()); ++i) {
      const u32 e = r.edge[i];
      if (F.edge_tag[e] & Fvar_level::mismatch) {
        if (s.size != 0) {
          s.disjoint = 1;
          break;
        }
        s.size = m;
        s.start = i;
      } else if (is_inf_sharp_edge(L, e)) {
        s.disjoint = 1;
        break;
      } else if (Crease::is_semi_sharp(sharpness_of_edge(L, e))) {
        ++s.semi_sharp;
      }
    }
    return;
  }
  spans[0].size = 1;
  const bool wraps = !r.border && sibling[m - 1] == 0;
  if (wraps) { // the run of value 0 goes on from the last face to the first
    Fvar_span& s = spans[0];
    if ((F.edge_tag[r.edge[0]] & Fvar_level::mismatch) || is_inf_sharp_edge(L, r.edge[0]))
      s.disjoint = 1;
    else if (Crease::is_semi_sharp(sharpness_of_edge(L, r.edge[0])))
      ++s.semi_sharp;
  }
  for (u32 i = 1; i < m; ++i) {
    Fvar_span& s = spans[sibling[i]];
    if (sibling[i] == sibling[i - 1]) {
      classify_inner_edge(L, F, r.edge[i], s);
    } else {
      if (s.size > 0)
        ++s.disjoint;
      s.start = i;
    }
    ++s.size;
  }
  if (wraps)
    --spans[0].disjoint; // its second run was counted as a break
}

// The two ends of the span of vertex value `x` in a ring whose faces hold
// the vertex values `vv` (the first and last face, in walk order).
template <class Vertex_values>
std::pair<u32, u32> span_ends(const Fvar_level& F, const Fvar_ring& r, const Vertex_values& vv, u32 x, u32 values)
{
  const u32 m = r.faces();
  if (values == 1) { // a dart of the channel: the span starts and ends at its seam
    for (u32 i = 0; i < m; ++i)
      if (F.edge_tag[r.edge[i]] & Fvar_level::mismatch)
        return {i, (i + m - 1) % m};
    return {0, m - 1};
  }
  for (u32 i = 0; i < m; ++i) {
    const bool starts = r.border ? (i == 0 || vv[i - 1] != x) : vv[(i + m - 1) % m] != x;
    if (vv[i] != x || !starts)
      continue;
    u32 end = i;
    while ((r.border ? end + 1 < m : true) && vv[(end + 1) % m] == x && (end + 1) % m != i)
      end = (end + 1) % m;
    return {i, end};
  }
  return {0, m - 1};
}

// The edges strictly inside a span, as positions in the ring (edge i lies
// between faces i − 1 and i).
template <class F>
void for_each_inner_edge(const Fvar_ring& r, std::pair<u32, u32> span, const F& f)
{
  const u32 m = r.faces();
  for (u32 i = span.first; i != span.second; i = (i + 1) % m)
    f((i + 1) % m);
}

// The tags of the values of a vertex whose channel topology differs from
// the vertex's (the second pass of FVarLevel::completeTopologyFromFaceValues()):
// corners (kept as they are), creases of the channel (smoothed along its
// seam), or semi-sharp corners that become creases as the sharpness decays.
inline void tag_values(const Level& L, Fvar_level& F, const Fvar_ring& r, const std::vector<u32>& sibling, u32 v,
                       const Fvar_rules& rules, std::vector<Fvar_span>& spans)
{
  using T = Fvar_level;
  const u32 first = F.v_offset[v], values = F.v_offset[v + 1] - first;
  auto tag_all = [&](std::uint8_t t) { std::fill_n(F.value_tag.begin() + first, values, t); };
  const float vs = sharpness_of_vertex(L, v);
  if (rules.linear_boundaries || Crease::is_infinite(vs) || (rules.dependent_sharpness && values > 2) ||
      (rules.sharpen_darts && values == 1 && !r.border))
    return tag_all(T::differs);
  gather_spans(L, F, r, sibling, values, spans);
  bool all_sharp = false, dependent = false;
  if (rules.dependent_sharpness && values == 2) {
    all_sharp = spans[0].disjoint > 0 || spans[1].disjoint > 0;
    if (rules.sharpen_both_if_one_corner)
      all_sharp = all_sharp || spans[0].size == 1 || spans[1].size == 1;
    dependent = spans[0].semi_sharp != spans[1].semi_sharp;
  }
  if (all_sharp)
    return tag_all(T::differs);
  for (u32 j = 0; j < values; ++j) {
    const Fvar_span& s = spans[j];
    std::uint8_t& t = F.value_tag[first + j];
    if (s.disjoint > 0 || (s.size == 1 && rules.corners_are_sharp))
      t = T::differs;
    else if (s.semi_sharp > 0 || Crease::is_semi_sharp(vs))
      t = T::differs | T::semi_sharp;
    else if (dependent)
      t = T::differs | T::semi_sharp | T::dependent;
    else
      t = T::differs | T::crease;
  }
}

// The base level of a channel from the user's value index of each corner
// (`user`, per halfedge): its vertex values, seams and tags
// (FVarLevel::completeTopologyFromFaceValues()). Serial: as OpenSubdiv's, a
// vertex's boundary test sees the seams found at the vertices before it.
template <class Corners>
void analyse_base(const Level& L, const Corners& user, const Fvar_rules& rules, Fvar_level& F)
{
  F.edge_tag.assign(L.ne, 0);
  F.v_offset.assign(std::size_t(L.nv) + 1, 0);
  F.value_of.clear();
  std::vector<std::uint8_t> differs(L.nv, 0);
  Fvar_ring r;
  std::vector<u32> vv, sibling;
  auto mark_edge = [&](u32 e) {
    const u32 d = dart_encoding::dart(dart_encoding::halfedge_of_edge(e, 0), false);
    differs[L.target(d)] = differs[L.source(d)] = 1;
    F.edge_tag[e] = Fvar_level::mismatch | (rules.linear_boundaries ? Fvar_level::linear : 0);
  };
  for (u32 v = 0; v < L.nv; ++v) {
    r.walk(L, v);
    const u32 m = r.faces();
    vv.resize(m);
    for (u32 i = 0; i < m; ++i)
      vv[i] = user[corner_slot(L, r.dart[i])];
    for (u32 i = r.border ? 1 : 0; i < m; ++i)
      if (vv[i] != vv[(i + m - 1) % m])
        mark_edge(r.edge[i]);
    if (r.border && !differs[v]) {
      if (rules.linear_boundaries && m > 0) {
        differs[v] = 1;
        F.edge_tag[r.edge.front()] |= Fvar_level::linear;
        F.edge_tag[r.edge.back()] |= Fvar_level::linear;
      } else if (m == 1 && rules.make_smooth_corners_sharp) {
        differs[v] = 1;
      }
    }
    u32 count = 0;
    for (u32 i = 0; i < m; ++i)
      if (std::find(vv.begin(), vv.begin() + i, vv[i]) == vv.begin() + i) {
        F.value_of.push_back(vv[i]);
        ++count;
      }
    F.v_offset[v + 1] = F.v_offset[v] + count;
  }
  F.value_tag.assign(F.value_of.size(), 0);
  F.corner.assign(2 * std::size_t(L.ne), null_u32);
  std::vector<Fvar_span> spans;
  for (u32 v = 0; v < L.nv; ++v) {
    r.walk(L, v);
    const u32 m = r.faces(), first = F.v_offset[v], values = F.v_offset[v + 1] - first;
    sibling.resize(m);
    for (u32 i = 0; i < m; ++i) {
      const u32 x = user[corner_slot(L, r.dart[i])];
      sibling[i] = u32(std::find(F.value_of.begin() + first, F.value_of.begin() + first + values, x) -
                       (F.value_of.begin() + first));
      F.corner[corner_slot(L, r.dart[i])] = first + sibling[i];
    }
    if (differs[v])
      tag_values(L, F, r, sibling, v, rules, spans);
  }
}

// One step of a channel from level k to level k + 1 of a refiner
// (FVarRefinement and PrimvarRefiner::interpFVarFrom{Faces,Edges,Verts}()):
// the child's vertex values, tags and corners, then the child values. Each
// child value is computed on its own, but for the sums of the smooth vertex
// rule, which the serial pass scatters and the parallel one gathers in the
// same order; so the loops may run on threads with the serial result, bit
// for bit.
template <class Refiner, class Value>
class Fvar_step
{
public:
  using W = typename Refiner::Weight;
  using Mask = std::decay_t<decltype(std::declval<const Refiner&>().mask())>;
  static constexpr bool quad = Mask::split == Split::quad;

  // Step k of `r` (a slot of a one-pass refinement), into a child seen as `child`.
  Fvar_step(const Refiner& r, unsigned k, const Child_level_view& child, const Fvar_rules& rules, bool linear)
    : r_(r), k_(k), P_(level_of(r, k)), C_(child), rules_(rules), linear_(linear)
  {}

  template <class Tag, class Values>
  void run(const Fvar_level& pf, const Values& pv, Fvar_level& cf, Values& cv)
  {
    pf_ = &pf;
    cf_ = &cf;
    pv_ = pv.data();
    const u32 nv = P_.nv, ne = P_.ne;
    cf.value_of.clear();
    number_child_values<Tag>();
    const u32 n = cf.v_offset[C_.nv];
    // The vertex points' tags are their parents' (reclassified below where
    // semi-sharp); the edge points' are written below where not 0.
    cf.value_tag.resize(n);
    const u32 vertex_values = pf.v_offset[nv];
    std::copy_n(pf.value_tag.begin(), vertex_values, cf.value_tag.begin());
    std::fill(cf.value_tag.begin() + vertex_values, cf.value_tag.end(), std::uint8_t(0));
    cv.clear();
    cv.resize(n); // each written below: vertex, edge and face points
    cv_ = cv.data();
    // The halves of the parent's edges take its tags, the edges inside its
    // faces none; each corner is written once (the largest array of a
    // channel: filling it first would be one more pass over it).
    cf.edge_tag.resize(C_.ne);
    cf.corner.resize(2 * std::size_t(C_.ne));
    for_each_index<Tag>(ne, [&](u32 e) {
      cf.edge_tag[2 * e] = cf.edge_tag[2 * e + 1] = pf.edge_tag[e];
      split_edge_corners(e);
    });
    std::fill(cf.edge_tag.begin() + 2 * std::size_t(ne), cf.edge_tag.end(), std::uint8_t(0));
    for_each_index<Tag>(P_.nf, [&](u32 f) { split_face_corners(f); });
    for_each_index<Tag>(ne, [&](u32 e) { tag_edge_point(e); });
    if (!rules_.linear_boundaries && (!P_.e_sharp.empty() || !P_.v_sharp.empty()))
      for_each_index<Tag>(nv, [&](u32 v) { reclassify_semi_sharp(v); });
    if constexpr (quad)
      for_each_index<Tag>(P_.nf, [&](u32 f) { face_point(f); });
    for_each_index<Tag>(ne, [&](u32 e) { edge_point(e); });
    if (!linear_)
      prepare_smooth_sums<Tag>();
    for_each_index<Tag>(nv, [&](u32 v) { vertex_point(v); });
  }

private:
  using T = Fvar_level;

  // The first child value of each child vertex (cf_->v_offset): the vertex
  // points first, each with its parent's count of values (so with its
  // parent's numbers), then the edge points (two values on a seam, one
  // elsewhere), then the face points (one each).
  template <class Tag>
  void number_child_values()
  {
    const u32 nv = P_.nv, ne = P_.ne;
    Array<u32>& o = cf_->v_offset;
    o.clear(); // cleared first: growing, it then copies nothing
    o.resize(std::size_t(C_.nv) + 1); // each written below
    std::copy_n(pf_->v_offset.begin(), std::size_t(nv) + 1, o.begin());
    for_each_index<Tag>(ne, [&](u32 e) { o[nv + e + 1] = (pf_->edge_tag[e] & T::mismatch) ? 2u : 1u; });
    prefix_sum<Tag>(o.data() + nv, ne);
    face_values_ = o[nv + ne];
    for_each_index<Tag>(C_.nv - nv - ne, [&](u32 f) { o[nv + ne + f + 1] = face_values_ + f + 1; });
  }

  const Value& parent_value(u32 vertex_value) const { return pv_[pf_->value(vertex_value)]; }
  // A face point has one value, and the face points' values come last.
  u32 face_value(u32 f) const { return face_values_ + f; }
  const Value& face_point_of(u32 f) const { return cv_[face_value(f)]; }
  const Value& parent_corner(u32 h) const { return parent_value(pf_->corner[h]); }
  u32 edge_point_value(u32 h) const // the child value of the edge of h on h's side
  {
    const u32 e = dart_encoding::edge_of_halfedge(h);
    return cf_->v_offset[P_.nv + e] + ((pf_->edge_tag[e] & T::mismatch) ? (h & 1u) : 0u);
  }
  // The child value of the corner of h at its target: the parent's own
  // number, as the vertex points come first and keep their values' count.
  u32 vertex_point_value(u32 h) const { return pf_->corner[h]; }

  // The child corners along parent edge e, by the layout of the split
  // (Level.h: the four child halfedges of e are adjacent there). On a side
  // with a face, the child halfedge that ends at the edge point takes the
  // edge point's value on that side, the one that ends at the parent's end
  // the parent corner's; on the border, none.
  void split_edge_corners(u32 e)
  {
    Array<u32>& c = cf_->corner;
    for (u32 side : {0u, 1u}) {
      const u32 h = dart_encoding::halfedge_of_edge(e, side);
      const bool face = P_.h_face[h] != null_u32;
      c[P_.first_child(h)] = face ? edge_point_value(h) : null_u32;
      c[P_.second_child(h)] = face ? vertex_point_value(h) : null_u32;
    }
  }

  // The child corners along the edges inside face f (one per corner k of f:
  // quads, from corner k's edge point to the face point; triangles, between
  // the edge points of corners k and k + 1).
  void split_face_corners(u32 f)
  {
    namespace de = dart_encoding;
    Array<u32>& c = cf_->corner;
    const u32 k0 = P_.f_offset[f], k1 = P_.f_offset[f + 1], ne = P_.ne;
    for (u32 k = k0; k < k1; ++k) {
      const u32 h = P_.corner_h[k];
      if constexpr (quad) {
        c[de::halfedge_of_edge(2 * ne + k, 0)] = face_value(f);
        c[de::halfedge_of_edge(2 * ne + k, 1)] = edge_point_value(h);
      } else {
        c[de::halfedge_of_edge(2 * ne + k, 0)] = edge_point_value(h);
        c[de::halfedge_of_edge(2 * ne + k, 1)] = edge_point_value(P_.corner_h[k + 1 == k1 ? k0 : k + 1]);
      }
    }
  }

  // A seam's edge points are creases of the channel (corners with linear
  // boundaries); the others match the vertex.
  void tag_edge_point(u32 e)
  {
    if ((pf_->edge_tag[e] & (T::mismatch | T::linear)) == 0)
      return;
    const std::uint8_t t = rules_.linear_boundaries ? T::differs : T::differs | T::crease;
    for (u32 i = cf_->v_offset[P_.nv + e]; i < cf_->v_offset[P_.nv + e + 1]; ++i)
      cf_->value_tag[i] = t;
  }

  // A vertex point has its parent's tags (copied in run()), but a
  // semi-sharp value whose sharpness is spent becomes a crease
  // (FVarRefinement::reclassifySemisharpValues()).
  void reclassify_semi_sharp(u32 v)
  {
    const u32 pfirst = pf_->v_offset[v], values = pf_->v_offset[v + 1] - pfirst, cfirst = pfirst;
    if (values == 0 || !(pf_->value_tag[pfirst] & T::differs))
      return;
    if (P_.e_sharp.empty() && !Crease::is_semi_sharp(sharpness_of_vertex(P_, v)))
      return; // no semi-sharp edge: nothing to reclassify (and no walk)
    Fvar_ring r;
    r.walk(P_, v);
    bool parent_semi_edges = false, child_semi_edges = false;
    for (u32 i = 0; i < r.faces(); ++i) {
      parent_semi_edges |= Crease::is_semi_sharp(sharpness_of_edge(P_, r.edge[i]));
      child_semi_edges |= Crease::is_semi_sharp(sharpness_of_edge(C_, child_edge(r, i)));
    }
    if (!Crease::is_semi_sharp(sharpness_of_vertex(P_, v)) && !parent_semi_edges)
      return;
    const float cvs = sharpness_of_vertex(C_, v);
    if (Crease::is_semi_sharp(cvs) || Crease::is_infinite(cvs))
      return;
    std::uint8_t* tags = &cf_->value_tag[cfirst];
    for (u32 j = 0; j < values; ++j) {
      if (!(tags[j] & T::semi_sharp))
        continue;
      bool still = false;
      if (child_semi_edges && !(tags[j] & T::dependent))
        for_each_inner_edge(r, span(r, j, values), [&](u32 i) {
          still |= Crease::is_semi_sharp(sharpness_of_edge(C_, child_edge(r, i)));
        });
      else if (child_semi_edges)
        still = true; // a dependent value waits for its vertex's last semi-sharp edge
      if (!still)
        tags[j] = T::differs | T::crease;
    }
    if (values == 2 && rules_.dependent_sharpness && child_semi_edges) {
      if ((tags[0] & T::dependent) && !(tags[1] & T::semi_sharp))
        tags[0] &= std::uint8_t(~T::dependent);
      else if ((tags[1] & T::dependent) && !(tags[0] & T::semi_sharp))
        tags[1] &= std::uint8_t(~T::dependent);
    }
  }

  // The child edge at the vertex of ring position i (the half of edge i there).
  u32 child_edge(const Fvar_ring& r, u32 i) const
  {
    const u32 d = i < r.faces() ? r.dart[i] : P_.opposite(P_.next(r.dart[r.faces() - 1]));
    return dart_encoding::edge_of_dart(P_.child_dart_to_target(d));
  }
  // The span of value j of the vertex of ring r.
  std::pair<u32, u32> span(const Fvar_ring& r, u32 j, u32 values) const
  {
    Fvar_ring::Darts vv(r.faces()); // inline: a heap allocation would cost more than the span
    for (u32 i = 0; i < r.faces(); ++i)
      vv[i] = pf_->corner[corner_slot(P_, r.dart[i])];
    const u32 v = P_.target(r.dart[0]);
    return span_ends(*pf_, r, vv, pf_->v_offset[v] + j, values);
  }

  void face_point(u32 f)
  {
    const u32 k0 = P_.f_offset[f], k1 = P_.f_offset[f + 1];
    Value sum = parent_corner(P_.corner_h[k0]);
    for (u32 k = k0 + 1; k < k1; ++k)
      sum = sum + parent_corner(P_.corner_h[k]);
    cv_[face_value(f)] = (W(1) / W(double(k1 - k0))) * sum;
  }

  // The values at the source and target of face halfedge h, in its face.
  const Value& at_source(u32 h) const { return parent_corner(dart_encoding::halfedge_of_dart(P_.h_prev[h])); }

  void edge_point(u32 e)
  {
    namespace de = dart_encoding;
    const u32 h0 = de::halfedge_of_edge(e, 0), h1 = de::halfedge_of_edge(e, 1);
    const bool face0 = P_.h_face[h0] != null_u32;
    const u32 first = cf_->v_offset[P_.nv + e], count = cf_->v_offset[P_.nv + e + 1] - first;
    if (linear_ || (cf_->value_tag[first] & T::differs)) { // the midpoint of each side
      for (u32 s = 0; s < count; ++s) {
        const u32 h = count == 2 ? (s == 0 ? h0 : h1) : (face0 ? h0 : h1);
        cv_[first + s] = W(0.5) * parent_corner(h) + W(0.5) * at_source(h);
      }
      return;
    }
    // The edge's own mask, on the values of one side (the sides agree).
    const Edge_weights<W>& w = r_.edge_weights(k_, e);
    const u32 h = face0 ? h0 : h1;
    Value x = w.vertex * parent_corner(h) + w.vertex * at_source(h);
    if (w.has_face)
      for (u32 g : {h0, h1}) {
        const u32 f = P_.h_face[g];
        if (f == null_u32)
          continue;
        if constexpr (quad)
          x = x + w.face * face_point_of(f);
        else // the corner of the triangle across from the edge
          x = x + w.face * parent_corner(de::halfedge_of_dart(P_.h_next[g]));
      }
    cv_[first] = x;
  }

  void vertex_point(u32 v)
  {
    const u32 pfirst = pf_->v_offset[v], values = pf_->v_offset[v + 1] - pfirst, cfirst = cf_->v_offset[v];
    if (values == 0)
      return;
    if (!(cf_->value_tag[cfirst] & T::differs)) {
      if (linear_)
        cv_[cfirst] = parent_value(pfirst);
      else
        cv_[cfirst] = smooth_vertex_point(v);
      return;
    }
    Fvar_ring r;
    for (u32 j = 0; j < values; ++j) {
      const std::uint8_t ct = cf_->value_tag[cfirst + j], pt = pf_->value_tag[pfirst + j];
      const Value& x = parent_value(pfirst + j);
      if (linear_ || !(ct & T::crease)) {
        cv_[cfirst + j] = x;
        continue;
      }
      if (r.dart.empty())
        r.walk(P_, v);
      const std::pair<u32, u32> s = span(r, j, values);
      const Value& a = parent_corner(corner_slot(P_, P_.prev(r.dart[s.first])));
      const Value& b = parent_corner(corner_slot(P_, P_.next(r.dart[s.second])));
      W wv = W(0.75), we = W(0.125);
      if (pt & T::semi_sharp) { // a corner becoming a crease: blended
        const u32 from = (pt & T::dependent) ? 1 - j : j;
        const W corner = W(double(fraction(r, from, values, v))), crease = W(1) - corner;
        wv = crease * W(0.75) + corner;
        we = crease * W(0.125);
      }
      cv_[cfirst + j] = we * a + we * b + wv * x;
    }
  }

  // The part of the corner rule in the child of a semi-sharp value
  // (FVarRefinement::getFractionalWeight()): from the vertex's sharpness and
  // that of the edges inside the value's span.
  float fraction(const Fvar_ring& r, u32 j, u32 values, u32 v) const
  {
    std::vector<float> ps, cs;
    for_each_inner_edge(r, span(r, j, values), [&](u32 i) {
      ps.push_back(sharpness_of_edge(P_, r.edge[i]));
      cs.push_back(sharpness_of_edge(C_, child_edge(r, i)));
    });
    return Crease::fractional_weight_at_vertex(sharpness_of_vertex(P_, v), sharpness_of_vertex(C_, v),
                                               unsigned(ps.size()), ps.data(), cs.data());
  }

  // The smooth rule's sums at the vertices whose value matches their
  // topology (one value, no seam), made as the points' passes make theirs
  // (Interpolation.h): serially, each edge that is no seam and each face
  // corner adds its terms to its vertices' sums, in edge then face order;
  // in parallel, each vertex gathers them from the level's incidence tables
  // in that order. Both give the same bits, and a vertex's terms cost a pass
  // over the edges instead of a walk around it.
  template <class Tag>
  void prepare_smooth_sums()
  {
    vs_ = &Refiner_access::vertex_sums(r_, k_);
    if constexpr (is_parallel_tag<Tag>) {
      inc_ = Refiner_access::incidence(r_, k_);
      if (!inc_) {
        build_incidence<Tag>(P_, quad, own_incidence_);
        inc_ = &own_incidence_;
      }
    } else {
      scatter_smooth_sums();
    }
  }

  // The values at the two ends of edge e, which is no seam (its faces
  // agree at each end): at its halfedge 0's source, then at its target,
  // read in the face of halfedge 0, or of halfedge 1 on the border, which
  // runs the other way but on a Möbius edge.
  std::pair<const Value*, const Value*> end_values(u32 e) const
  {
    namespace de = dart_encoding;
    const u32 h0 = de::halfedge_of_edge(e, 0);
    const bool face0 = P_.h_face[h0] != null_u32;
    const u32 h = face0 ? h0 : de::halfedge_of_edge(e, 1);
    const Value *at_target = &parent_corner(h), *at_start = &at_source(h);
    if (face0 || P_.e_mobius[e])
      return {at_start, at_target};
    return {at_target, at_start};
  }
  const Value& edge_point_of(u32 e) const { return cv_[cf_->v_offset[P_.nv + e]]; }

  void scatter_smooth_sums()
  {
    namespace de = dart_encoding;
    const Vertex_sums& vs = *vs_;
    Value* to[3] = {nullptr, nullptr, nullptr};
    for (int s = 0; s < vs.count; ++s) {
      sums_[s].resize(P_.nv);
      for (u32 v = 0; v < P_.nv; ++v)
        if (pf_->v_offset[v + 1] != pf_->v_offset[v]) // a vertex of no face has no value, and no term
          sums_[s][v] = W(0) * parent_value(pf_->v_offset[v]);
    }
    for (Vertex_sums::Term t : {Vertex_sums::neighbours, Vertex_sums::edge_points, Vertex_sums::face_points})
      if (vs.sum_of[t] != Vertex_sums::none)
        to[t] = sums_[vs.sum_of[t]].data();
    Value *neighbours = to[Vertex_sums::neighbours], *edge_points = to[Vertex_sums::edge_points];
    for (u32 e = 0; e < P_.ne; ++e) {
      if (pf_->edge_tag[e] & T::mismatch)
        continue; // its ends have values of their own rules
      const u32 h0 = de::halfedge_of_edge(e, 0), a = P_.source(de::dart(h0, false)), b = P_.h_target[h0];
      const std::pair<const Value*, const Value*> y = end_values(e);
      if (neighbours)
        neighbours[a] = neighbours[a] + *y.second;
      if (edge_points)
        edge_points[a] = edge_points[a] + edge_point_of(e);
      if (neighbours)
        neighbours[b] = neighbours[b] + *y.first;
      if (edge_points)
        edge_points[b] = edge_points[b] + edge_point_of(e);
    }
    if constexpr (quad)
      if (Value* face_points = to[Vertex_sums::face_points])
        for (u32 f = 0; f < P_.nf; ++f)
          for (u32 k = P_.f_offset[f]; k < P_.f_offset[f + 1]; ++k) {
            const u32 v = P_.h_target[P_.corner_h[k]];
            face_points[v] = face_points[v] + face_point_of(f);
          }
  }

  // The sums of vertex v from the incidence tables, in the serial order.
  void gather_smooth_sums(u32 v, Value* sums) const
  {
    namespace de = dart_encoding;
    const Incidence& inc = *inc_;
    const int neighbours = vs_->sum_of[Vertex_sums::neighbours], edge_points = vs_->sum_of[Vertex_sums::edge_points],
              face_points = vs_->sum_of[Vertex_sums::face_points];
    for (u32 i = inc.edge_offset[v]; i < inc.edge_offset[v + 1]; ++i) {
      const u32 end = inc.edge_ends[i], e = de::edge_of_halfedge(end);
      if (pf_->edge_tag[e] & T::mismatch)
        continue;
      if (neighbours != Vertex_sums::none) { // the value at the other end
        const std::pair<const Value*, const Value*> y = end_values(e);
        sums[neighbours] = sums[neighbours] + (de::side_of_halfedge(end) ? *y.first : *y.second);
      }
      if (edge_points != Vertex_sums::none)
        sums[edge_points] = sums[edge_points] + edge_point_of(e);
    }
    if constexpr (quad)
      if (face_points != Vertex_sums::none)
        for (u32 i = inc.corner_offset[v]; i < inc.corner_offset[v + 1]; ++i)
          sums[face_points] = sums[face_points] + face_point_of(inc.face_of_corner(inc.corners[i]));
  }

  // The vertex's own mask on its sums (Interpolation.h's vertex_point(),
  // without a crease).
  Value point_from_sums(const Vertex_weights<W>& w, u32 v) const
  {
    const Value& own = parent_value(pf_->v_offset[v]);
    const Vertex_sums& vs = *vs_;
    Value x = w.vertex * own;
    if (!takes_sums(w))
      return x;
    auto weigh = [&](auto sum) {
      for (int s = 0; s < vs.count; ++s)
        if (Vertex_sums::has(w, vs.weight_of[s]))
          x = x + Vertex_sums::weight(w, vs.weight_of[s]) * sum(s);
      return x;
    };
    if (!inc_)
      return weigh([&](int s) -> const Value& { return sums_[s][v]; });
    const Value zero = W(0) * own;
    Value gathered[3] = {zero, zero, zero};
    gather_smooth_sums(v, gathered);
    return weigh([&](int s) -> const Value& { return gathered[s]; });
  }

  // The vertex's own mask on the values around it (all one side of no
  // seam): from the sums, but where a crease's ends take a weight of their
  // own, which needs the walk round the vertex to find their values.
  Value smooth_vertex_point(u32 v) const
  {
    const Vertex_weights<W>& w = r_.vertex_weights(k_, v);
    if (!w.has_crease)
      return point_from_sums(w, v);
    const Value x = w.vertex * parent_value(pf_->v_offset[v]);
    // An inner vertex's ring in the walk's order without building the walk,
    // which costs more than the sums.
    Value inner = x;
    bool border = false;
    P_.for_each_dart_at(v, [&](u32 d) {
      border = border || P_.is_border_dart(d);
      if (!border)
        add_ring_terms(inner, w, corner_slot(P_, P_.prev(d)), P_.source(d), dart_encoding::edge_of_dart(d), d);
    });
    if (!border)
      return inner;
    Fvar_ring r;
    r.walk(P_, v);
    const u32 m = r.faces();
    Value sum = x;
    for (u32 i = 0; i < m; ++i)
      add_ring_terms(sum, w, corner_slot(P_, P_.prev(r.dart[i])), P_.source(r.dart[i]), r.edge[i], r.dart[i]);
    // The trailing border edge, seen from the last face.
    const u32 d = P_.next(r.dart[m - 1]);
    add_ring_terms(sum, w, corner_slot(P_, d), P_.target(d), r.edge[m], null_u32);
    return sum;
  }

  // The terms of a vertex point from the edge of a ring to the value of the
  // corner at its far end `far` (in corner slot `slot`) and from the face of
  // `face_dart` (none for the trailing border edge).
  void add_ring_terms(Value& x, const Vertex_weights<W>& w, u32 slot, u32 far, u32 edge, u32 face_dart) const
  {
    const Value& y = parent_corner(slot);
    if (w.has_edge)
      x = x + w.edge * y;
    if (w.has_edge_point)
      x = x + w.edge_point * cv_[cf_->v_offset[P_.nv + edge]];
    if (w.has_crease && (far == w.crease_ends[0] || far == w.crease_ends[1]))
      x = x + w.crease * y;
    if constexpr (quad)
      if (w.has_face && face_dart != null_u32)
        x = x + w.face * face_point_of(P_.h_face[dart_encoding::halfedge_of_dart(face_dart)]);
  }

  const Refiner& r_;
  unsigned k_;
  const Level& P_;
  Child_level_view C_;
  Fvar_rules rules_;
  bool linear_;
  const Fvar_level* pf_ = nullptr;
  Fvar_level* cf_ = nullptr;
  const Value* pv_ = nullptr;
  Value* cv_ = nullptr;
  u32 face_values_ = 0; // the child value of the first face point
  const Vertex_sums* vs_ = nullptr;
  const Incidence* inc_ = nullptr; // parallel: the tables the sums are gathered from
  Incidence own_incidence_;        // made where the refiner has none
  Array<Value> sums_[3];           // serial: the sums, by parent vertex
};

// A channel carried step by step: its topology on the current level (vertex
// values, tags, the value of each corner) and its values there. start() reads
// the base level of a refiner, each step() goes one level down from level k,
// whose weights the refiner holds, into a child seen as `child`: level k + 1
// of a refiner that keeps its levels, or the child of slot 0 of a one-pass
// refinement (Refiner::refine_and_interpolate_carrying()).
template <class Refiner, class Values>
class Fvar_pass
{
public:
  using Value = typename Values::value_type;

  Fvar_pass(const Refiner& r, Face_varying_interpolation mode)
    : rules_(mode, r.options().boundary_interpolation),
      linear_(rules_.linear_all || !std::decay_t<decltype(r.mask())>::creases)
  {}

  // `corners`: the value index of each halfedge's corner of the base level
  // (null on the border), into `values`.
  template <class Corners>
  void start(const Refiner& r, const Corners& corners, Values values)
  {
    analyse_base(level_of(r, 0), corners, rules_, level_);
    values_ = std::move(values);
  }

  template <class Tag>
  void step(const Refiner& r, unsigned k, const Child_level_view& child)
  {
    Fvar_level next; // fresh: the parent's buffers, smaller, are not reused
    Values next_values;
    Fvar_step<Refiner, Value>(r, k, child, rules_, linear_).template run<Tag>(level_, values_, next, next_values);
    level_ = std::move(next);
    values_ = std::move(next_values);
  }

  Fvar_level& level() { return level_; }
  Values& values() { return values_; }

private:
  Fvar_rules rules_;
  bool linear_;
  Fvar_level level_;
  Values values_;
};

// A channel through every level of `r`: `corners` (the value index of each
// halfedge's corner of the base level, null on the border) and `values` in,
// the same of the last level out; or, if `last` is given, the channel's
// topology there in `last` instead of `corners` (which is left as it was),
// with the tags the levels carried down (the limit reads them). Under
// CGAL::Parallel_tag the steps of the levels that `parallel(nv)` allows run
// on threads, with the serial result. `Corners` and `Values` are vectors
// (std::vector, or Array to spare the zero-fill and first touches of large
// levels).
template <class Tag, class Refiner, class Corners, class Values, class Parallel>
void interpolate_face_varying(const Refiner& r, Face_varying_interpolation mode, Corners& corners, Values& values,
                              const Parallel& parallel, Fvar_level* last = nullptr)
{
  Fvar_pass<Refiner, Values> pass(r, mode);
  pass.start(r, corners, std::move(values));
  for (unsigned k = 0; k < r.number_of_levels(); ++k)
    with_concurrency<Tag>(parallel(level_of(r, k).nv), [&](auto tag) {
      pass.template step<decltype(tag)>(r, k, Child_level_view::of(level_of(r, k + 1)));
    });
  values.swap(pass.values());
  Fvar_level& parent = pass.level();
  if (last) {
    *last = std::move(parent);
    return;
  }
  // The last level's vertex values are its values.
  if constexpr (std::is_same_v<Corners, Array<u32>>)
    corners.swap(parent.corner);
  else
    corners.assign(parent.corner.begin(), parent.corner.end());
  if (r.number_of_levels() == 0) {
    for (u32& c : corners)
      if (c != null_u32)
        c = parent.value(c);
  }
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_FACE_VARYING_H
