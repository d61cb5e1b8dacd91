// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The weights of one refinement step of a primal scheme (quad and triangle
// splits): for every parent edge and vertex, the weights of its child point,
// from the mask's smooth rules and the crease rules of Crease.h, and the
// sharpness of the child level.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_WEIGHTS_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_WEIGHTS_H

#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Level.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// The weights of one step, each distinct set stored once: every parent edge
// and vertex holds the index of its weights in a small table, 4 bytes where
// a copy would take 24 (edge) or 56 (vertex). Smooth weights depend only on
// face degrees or valence and are shared; crease, corner and semi-sharp
// weights, rarer, get entries of their own or share the constant ones.
template <class W>
struct Step_weights
{
  static constexpr u32 max_shared_degree = 16; // smooth edges between faces of fewer sides are shared

  std::vector<Edge_weights<W>> edges;
  std::vector<Vertex_weights<W>> vertices;
  Array<u32> edge_class, vertex_class;
  std::vector<u32> smooth_edge, smooth_vertex; // by degree pair / valence; null_u32 if not yet made
  u32 crease_edge = null_u32, corner_vertex = null_u32;

  void reset(u32 ne, u32 nv)
  {
    edges.clear();
    vertices.clear();
    edge_class.clear(); // not copied when growing
    edge_class.resize(ne);
    vertex_class.clear();
    vertex_class.resize(nv);
    smooth_edge.assign(max_shared_degree * max_shared_degree, null_u32);
    smooth_vertex.clear();
    crease_edge = corner_vertex = null_u32;
  }
  // Adds `w`, noting which of its terms are non-zero: the interpolation
  // passes skip the others.
  u32 add(Edge_weights<W> w)
  {
    w.has_face = !CGAL::is_zero(w.face);
    edges.push_back(w);
    return u32(edges.size() - 1);
  }
  u32 add(Vertex_weights<W> w)
  {
    w.has_edge = !CGAL::is_zero(w.edge);
    w.has_face = !CGAL::is_zero(w.face);
    w.has_edge_point = !CGAL::is_zero(w.edge_point);
    w.has_crease = !CGAL::is_zero(w.crease);
    vertices.push_back(w);
    return u32(vertices.size() - 1);
  }
  const Edge_weights<W>& edge(u32 e) const { return edges[edge_class[e]]; }
  const Vertex_weights<W>& vertex(u32 v) const { return vertices[vertex_class[v]]; }
};

// The sharpness of a child level, made with the weights of its parent; all
// 0 (and the arrays empty) if `any` is false.
struct Child_sharpness
{
  Array<float> edges, vertices;
  bool any = false;

  void release()
  {
    any = false;
    decltype(edges)().swap(edges);
    decltype(vertices)().swap(vertices);
  }
};

// The vertex masks of the crease rules, and the mask's smooth one.
template <class W>
void zero_weights(Vertex_weights<W>& w)
{
  w.vertex = w.edge = w.face = w.edge_point = w.crease = W(0);
  w.crease_ends[0] = w.crease_ends[1] = null_u32;
}
template <class W>
void corner_weights(Vertex_weights<W>& w)
{
  zero_weights(w);
  w.vertex = W(1);
}
template <class W>
void crease_weights(Vertex_weights<W>& w, u32 a, u32 b)
{
  zero_weights(w);
  w.vertex = W(0.75);
  w.crease = W(0.125);
  w.crease_ends[0] = a;
  w.crease_ends[1] = b;
}
template <class Mask, class W>
void smooth_weights(const Mask& mask, unsigned valence, Vertex_weights<W>& w)
{
  zero_weights(w);
  mask.smooth_vertex(valence, w);
}

// Builds the weights of a step, one parent level at a time; keeps its
// per-vertex scratch arrays between steps.
template <class Mask, class W>
class Weight_builder
{
public:
  // The weights of parent level `p` into `sw`, and the sharpness of its
  // child (of `child_nv` vertices) into `child`.
  void build(const Mask& mask, Crease_method method, const Level& p, u32 child_nv, Step_weights<W>& sw,
             Child_sharpness& child)
  {
    mask_ = &mask;
    method_ = method;
    p_ = &p;
    sw_ = &sw;
    sw.reset(p.ne, p.nv);
    const u32 child_ne = 2 * p.ne + p.nc;
    child.edges.clear();
    child.vertices.clear();
    if (p.sharp) {
      child.edges.resize(child_ne);
      child.vertices.resize(child_nv);
    }
    count_edges_at_vertices();
    bool any = add_edge_weights(child.edges.data());
    if (p.sharp)
      std::fill(child.edges.data() + 2 * p.ne, child.edges.data() + child_ne, 0.0f);
    any = add_vertex_weights(child.vertices.data()) || any;
    child.any = any;
    if (any)
      std::fill(child.vertices.data() + p.nv, child.vertices.data() + child_nv, 0.0f);
    else
      child.release();
  }

  // Frees the scratch arrays.
  void clear()
  {
    decltype(valence_)().swap(valence_);
    decltype(sharp_count_)().swap(sharp_count_);
    decltype(semi_sharp_)().swap(semi_sharp_);
  }

private:
  // Valence of every vertex and, with sharpness, its sharp and semi-sharp
  // edges, summed in edge order.
  void count_edges_at_vertices()
  {
    const Level& p = *p_;
    valence_.assign(p.nv, 0);
    for (u32 e = 0; e < p.ne; ++e) {
      ++valence_[p.source(edge_dart(e))];
      ++valence_[p.h_target[edge_halfedge(e)]];
    }
    if (!p.sharp)
      return;
    sharp_count_.assign(p.nv, 0);
    semi_sharp_.assign(p.nv, Crease::Semi_sharp_edges());
    for (u32 e = 0; e < p.ne; ++e) {
      const float s = p.e_sharp[e];
      if (!Crease::is_sharp(s))
        continue;
      for (u32 v : {p.source(edge_dart(e)), p.h_target[edge_halfedge(e)]}) {
        ++sharp_count_[v];
        semi_sharp_[v].add(s);
      }
    }
  }

  // The first halfedge of edge e, and its unflipped dart.
  static u32 edge_halfedge(u32 e) { return dart_encoding::halfedge_of_edge(e, 0); }
  static u32 edge_dart(u32 e) { return dart_encoding::dart(edge_halfedge(e), false); }

  // The sharpness of the child of an edge of sharpness `s > 0` at its end `v`.
  float child_edge_sharpness(float s, u32 v) const
  {
    return Crease::subdivide_edge_sharpness_at_vertex(method_, s, valence_[v], semi_sharp_[v]);
  }

  // Edge weights, each edge on its own; the child edges' sharpness into
  // `child` (2e at the source, 2e+1 at the target) if the parent is sharp.
  // Returns whether a child edge keeps some sharpness.
  bool add_edge_weights(float* child)
  {
    const Level& p = *p_;
    bool any = false;
    for (u32 e = 0; e < p.ne; ++e) {
      const float s = p.sharp ? p.e_sharp[e] : 0.0f;
      float sa = 0.0f, sb = 0.0f;
      if (Crease::is_sharp(s)) {
        sa = child_edge_sharpness(s, p.source(edge_dart(e)));
        sb = child_edge_sharpness(s, p.h_target[edge_halfedge(e)]);
        any = any || Crease::is_sharp(sa) || Crease::is_sharp(sb);
      }
      if (p.sharp) {
        child[2 * e] = sa;
        child[2 * e + 1] = sb;
      }
      sw_->edge_class[e] = Mask::creases && Crease::edge_point_is_crease(method_, s, sa, sb)
                             ? crease_edge_class()
                             : smooth_edge_class(e, Mask::creases ? s : 0.0f);
    }
    return any;
  }

  u32 crease_edge_class()
  {
    if (sw_->crease_edge == null_u32)
      sw_->crease_edge = sw_->add(Edge_weights<W>{W(0.5), W(0), false});
    return sw_->crease_edge;
  }

  // The smooth mask of edge e; if it is semi-sharp (`s > 0`), OpenSubdiv's
  // blend with the crease mask, weighted by `s` (not clamped).
  u32 smooth_edge_class(u32 e, float s)
  {
    const Level& p = *p_;
    Step_weights<W>& sw = *sw_;
    const u32 f0 = p.h_face[edge_halfedge(e)], f1 = p.h_face[dart_encoding::halfedge_of_edge(e, 1)];
    const u32 d0 = f0 == null_u32 ? 0u : p.degree(f0), d1 = f1 == null_u32 ? 0u : p.degree(f1);
    const bool blended = Crease::is_sharp(s);
    constexpr u32 D = Step_weights<W>::max_shared_degree;
    const bool shared = !blended && d0 < D && d1 < D;
    if (shared && sw.smooth_edge[d0 * D + d1] != null_u32)
      return sw.smooth_edge[d0 * D + d1];
    Edge_weights<W> w{};
    mask_->smooth_edge(d0, d1, w);
    if (blended) {
      const W pw = W(double(s)), cw = W(1) - pw;
      w.vertex = pw * W(0.5) + cw * w.vertex;
      w.face = cw * w.face;
    }
    const u32 cls = sw.add(w);
    if (shared)
      sw.smooth_edge[d0 * D + d1] = cls;
    return cls;
  }

  u32 smooth_vertex_class(u32 n)
  {
    Step_weights<W>& sw = *sw_;
    if (sw.smooth_vertex.size() <= n)
      sw.smooth_vertex.resize(n + 1, null_u32);
    if (sw.smooth_vertex[n] == null_u32) {
      Vertex_weights<W> w{};
      smooth_weights(*mask_, n, w);
      sw.smooth_vertex[n] = sw.add(w);
    }
    return sw.smooth_vertex[n];
  }

  u32 corner_vertex_class()
  {
    if (sw_->corner_vertex == null_u32) {
      Vertex_weights<W> w{};
      corner_weights(w);
      sw_->corner_vertex = sw_->add(w);
    }
    return sw_->corner_vertex;
  }

  // Vertex weights; the child vertices' sharpness into `child` if the parent
  // is sharp. Returns whether a child vertex keeps some sharpness.
  bool add_vertex_weights(float* child)
  {
    const Level& p = *p_;
    bool any = false;
    for (u32 v = 0; v < p.nv; ++v) {
      u32& cls = sw_->vertex_class[v];
      const u32 n = valence_[v];
      if (!p.sharp) {
        cls = n == 0 ? corner_vertex_class() : smooth_vertex_class(n);
        continue;
      }
      const float vs = p.v_sharp[v];
      child[v] = Crease::subdivide_vertex_sharpness(vs);
      any = any || Crease::is_sharp(child[v]);
      if (n == 0)
        cls = corner_vertex_class();
      else if (!Mask::creases || (Crease::is_smooth(vs) && sharp_count_[v] == 0))
        cls = smooth_vertex_class(n);
      else
        cls = sharp_vertex_class(v, vs, child[v]);
    }
    return any;
  }

  // A vertex with sharpness or sharp edges: the mask of its rule, blended
  // with the mask of its child's rule where they differ.
  u32 sharp_vertex_class(u32 v, float vs, float child_vs)
  {
    const Crease::Rule rule = Crease::vertex_rule(vs, sharp_count_[v]);
    if (rule == Crease::Rule::smooth || rule == Crease::Rule::dart)
      return smooth_vertex_class(valence_[v]);
    walk_ring(v);
    const u32 m = u32(ring_vertex_.size());
    const Crease::Rule child_rule = Crease::vertex_rule(child_vs, m, ring_child_sharpness_.data());
    if (rule == Crease::Rule::corner && child_rule == Crease::Rule::corner)
      return corner_vertex_class();
    Vertex_weights<W> w{};
    rule_weights(rule, ring_sharpness_, valence_[v], w);
    if (child_rule != rule) {
      const float fraction = Crease::fractional_weight_at_vertex(vs, child_vs, m, ring_sharpness_.data(),
                                                                 ring_child_sharpness_.data());
      Vertex_weights<W> c{};
      rule_weights(child_rule, ring_child_sharpness_, valence_[v], c);
      blend(w, c, fraction);
    }
    return sw_->add(w);
  }

  // The neighbours of `v` and the sharpness of the edges to them, now and in
  // the child level, in the order of the walk around `v`.
  void walk_ring(u32 v)
  {
    const Level& p = *p_;
    ring_vertex_.clear();
    ring_sharpness_.clear();
    ring_child_sharpness_.clear();
    const u32 d0 = p.v_dart[v];
    u32 d = d0;
    do {
      const float s = p.e_sharp[dart_encoding::edge_of_dart(d)];
      ring_vertex_.push_back(p.source(d));
      ring_sharpness_.push_back(s);
      ring_child_sharpness_.push_back(Crease::is_sharp(s) ? child_edge_sharpness(s, v) : 0.0f);
      d = p.opposite(p.next(d));
    } while (d != d0);
  }

  // The mask of `rule`, its crease ends taken from the edge sharpness
  // `ring` of the walk.
  void rule_weights(Crease::Rule rule, const std::vector<float>& ring, u32 valence, Vertex_weights<W>& w) const
  {
    if (rule == Crease::Rule::corner) {
      corner_weights(w);
    } else if (rule == Crease::Rule::crease) {
      u32 ends[2] = {null_u32, null_u32};
      for (std::size_t i = 0, j = 0; i < ring.size() && j < 2; ++i)
        if (Crease::is_sharp(ring[i]))
          ends[j++] = ring_vertex_[i];
      crease_weights(w, ends[0], ends[1]);
    } else {
      smooth_weights(*mask_, valence, w);
    }
  }

  // w <- fraction · w + (1 − fraction) · child; a crease mask keeps the
  // crease ends of the child rule if it has some, else of the parent's.
  static void blend(Vertex_weights<W>& w, const Vertex_weights<W>& child, float fraction)
  {
    const W pw = W(double(fraction)), cw = W(1) - pw;
    w.vertex = pw * w.vertex + cw * child.vertex;
    w.edge = pw * w.edge + cw * child.edge;
    w.face = pw * w.face + cw * child.face;
    w.edge_point = pw * w.edge_point + cw * child.edge_point;
    if (child.crease_ends[0] != null_u32) {
      w.crease = cw * child.crease;
      w.crease_ends[0] = child.crease_ends[0];
      w.crease_ends[1] = child.crease_ends[1];
    } else {
      w.crease = pw * w.crease;
    }
  }

  const Mask* mask_ = nullptr;
  Crease_method method_ = Crease_method::uniform;
  const Level* p_ = nullptr;
  Step_weights<W>* sw_ = nullptr;
  // per vertex
  std::vector<u32> valence_, sharp_count_;
  std::vector<Crease::Semi_sharp_edges> semi_sharp_;
  // around the vertex being weighted
  std::vector<u32> ring_vertex_;
  std::vector<float> ring_sharpness_, ring_child_sharpness_;
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_WEIGHTS_H
