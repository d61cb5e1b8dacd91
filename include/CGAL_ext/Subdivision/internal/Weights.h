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
#include <CGAL_ext/Sharp_feature_options.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Incidence.h>
#include <CGAL_ext/Subdivision/internal/Level.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// How the interpolation passes add up the terms of a vertex point
// (Interpolation.h). Each kind of term (the neighbours, the face points,
// the new edge points) is summed unweighted and its sum weighted once per
// vertex: a product per vertex, where weighting every term costs one per
// term and a look-up of both ends' weights per edge. Kinds weighted alike
// at every vertex share a sum (the standard masks need only one); the
// others get one of their own.
struct Vertex_sums
{
  enum Term : int { neighbours, face_points, edge_points };
  static constexpr int none = -1;

  int sum_of[3] = {none, none, none}; // the sum each kind of term is added to
  Term weight_of[3] = {};             // for each sum, the kind whose weight it takes
  int count = 0;                      // the sums, at most 3

  template <class W>
  static const W& weight(const Vertex_weights<W>& w, Term t)
  {
    return t == neighbours ? w.edge : t == face_points ? w.face : w.edge_point;
  }
  template <class W>
  static bool has(const Vertex_weights<W>& w, Term t)
  {
    return t == neighbours ? w.has_edge : t == face_points ? w.has_face : w.has_edge_point;
  }
  // Groups the kinds of terms of the weights in `table`.
  template <class W>
  void group(const std::vector<Vertex_weights<W>>& table)
  {
    *this = Vertex_sums();
    for (Term t : {neighbours, face_points, edge_points}) {
      if (std::none_of(table.begin(), table.end(), [&](const auto& w) { return has(w, t); }))
        continue;
      for (int s = 0; s < count && sum_of[t] == none; ++s)
        if (std::all_of(table.begin(), table.end(),
                        [&](const auto& w) { return weight(w, t) == weight(w, weight_of[s]); }))
          sum_of[t] = s;
      if (sum_of[t] == none) {
        weight_of[count] = t;
        sum_of[t] = count++;
      }
    }
  }
};

// The weights of one step, each distinct set stored once: every parent edge
// and vertex holds the index of its weights in a small table, 4 bytes where
// a copy would take 24 (edge) or 56 (vertex). Smooth weights depend only on
// face degrees or valence and are shared; crease, corner and semi-sharp
// weights, rarer, get entries of their own or share the constant ones.
// The shared entries come first, in the order of their keys, then the
// entries of single elements in element order: a numbering that does not
// depend on the order in which the elements are visited, so that the
// threads of a parallel build make the serial table.
template <class W>
struct Step_weights
{
  static constexpr u32 max_shared_degree = 16; // smooth edges between faces of fewer sides are shared

  std::vector<Edge_weights<W>> edges;
  std::vector<Vertex_weights<W>> vertices;
  Array<u32> edge_class, vertex_class;
  Vertex_sums sums; // made from `vertices` once they are all in

  void reset(u32 ne, u32 nv)
  {
    edges.clear();
    vertices.clear();
    edge_class.clear(); // not copied when growing
    edge_class.resize(ne);
    vertex_class.clear();
    vertex_class.resize(nv);
  }
  // Notes which terms of `w` are non-zero: the interpolation passes skip the others.
  static Edge_weights<W> finish(Edge_weights<W> w)
  {
    w.has_face = !CGAL::is_zero(w.face);
    return w;
  }
  static Vertex_weights<W> finish(Vertex_weights<W> w)
  {
    w.has_edge = !CGAL::is_zero(w.edge);
    w.has_face = !CGAL::is_zero(w.face);
    w.has_edge_point = !CGAL::is_zero(w.edge_point);
    w.has_crease = !CGAL::is_zero(w.crease);
    return w;
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
// per-vertex scratch arrays between steps. Edges and vertices are each
// weighted in two passes over their elements, which may run in parallel:
// the first finds the child sharpness and a key (a shared entry of the
// table, or `own_entry`), then the shared entries are made, and the second
// pass numbers the elements' own entries by a prefix sum and fills them.
// The mask's functions are called from several threads: they are const.
template <class Mask, class W>
class Weight_builder
{
public:
  // The weights of parent level `p` into `sw`, and the sharpness of its
  // child (of `child_nv` vertices) into `child`. `incidence`, the tables of
  // `p`, gives the edges at each vertex; needed for `CGAL::Parallel_tag`.
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  void build(const Mask& mask, Crease_method method, const Level& p, u32 child_nv, Step_weights<W>& sw,
             Child_sharpness& child, const Incidence* incidence = nullptr)
  {
    mask_ = &mask;
    method_ = method;
    p_ = &p;
    incidence_ = incidence;
    sw_ = &sw;
    sw.reset(p.ne, p.nv);
    child.edges.clear();
    child.vertices.clear();
    if (p.sharp) {
      child.edges.resize(2 * p.ne + p.nc);
      child.vertices.resize(child_nv);
    }
    count_edges_at_vertices<ConcurrencyTag>();
    bool any = add_edge_weights<ConcurrencyTag>(child.edges.data());
    if (p.sharp)
      for_each_index<ConcurrencyTag>(p.nc, [&](u32 c) { child.edges[2 * p.ne + c] = 0.0f; });
    any = add_vertex_weights<ConcurrencyTag>(child.vertices.data()) || any;
    sw.sums.group(sw.vertices);
    child.any = any;
    if (any)
      for_each_index<ConcurrencyTag>(child_nv - p.nv, [&](u32 i) { child.vertices[p.nv + i] = 0.0f; });
    else
      child.release();
  }

  // Frees the scratch arrays.
  void clear()
  {
    decltype(valence_)().swap(valence_);
    decltype(sharp_count_)().swap(sharp_count_);
    decltype(semi_sharp_)().swap(semi_sharp_);
    decltype(own_before_)().swap(own_before_);
  }

private:
  static constexpr u32 D = Step_weights<W>::max_shared_degree;
  // The key of an element whose weights are its own entry of the table.
  static constexpr u32 own_entry = null_u32;

  // The neighbours of a vertex and the sharpness of the edges to them, now
  // and in the child level, in the order of the walk around it.
  struct Ring
  {
    std::vector<u32> vertex;
    std::vector<float> sharpness, child_sharpness;
  };

  // Valence of every vertex and, with sharpness, its sharp and semi-sharp
  // edges, summed in edge order. Serially, a pass over the edges; in
  // parallel, a vertex at a time (no two threads write one count), from the
  // level's incidence tables, which the refiner makes before the weights of
  // every level it weights in parallel.
  template <class ConcurrencyTag>
  void count_edges_at_vertices()
  {
    const Level& p = *p_;
    valence_.clear();
    valence_.resize(p.nv);
    if (p.sharp) {
      sharp_count_.clear();
      sharp_count_.resize(p.nv);
      semi_sharp_.clear();
      semi_sharp_.resize(p.nv);
    }
    if constexpr (!is_parallel_tag<ConcurrencyTag>) {
      std::fill(valence_.begin(), valence_.end(), 0u);
      for (u32 e = 0; e < p.ne; ++e) {
        ++valence_[p.source(edge_dart(e))];
        ++valence_[p.h_target[edge_halfedge(e)]];
      }
      if (!p.sharp)
        return;
      std::fill(sharp_count_.begin(), sharp_count_.end(), 0u);
      std::fill(semi_sharp_.begin(), semi_sharp_.end(), Crease::Semi_sharp_edges());
      for (u32 e = 0; e < p.ne; ++e) {
        const float s = p.e_sharp[e];
        if (!Crease::is_sharp(s))
          continue;
        for (u32 v : {p.source(edge_dart(e)), p.h_target[edge_halfedge(e)]}) {
          ++sharp_count_[v];
          semi_sharp_[v].add(s);
        }
      }
    } else {
      // The incidence tables list the edge ends at each vertex in edge
      // order: no walk, no sort.
      CGAL_precondition(incidence_ != nullptr);
      const Incidence& inc = *incidence_;
      for_each_index<ConcurrencyTag>(p.nv, [&](u32 v) {
        const u32 i0 = inc.edge_offset[v], i1 = inc.edge_offset[v + 1];
        valence_[v] = i1 - i0;
        if (!p.sharp)
          return;
        u32 sharp = 0;
        Crease::Semi_sharp_edges semi_sharp;
        for (u32 i = i0; i < i1; ++i) {
          const float s = p.e_sharp[dart_encoding::edge_of_halfedge(inc.edge_ends[i])];
          if (Crease::is_sharp(s)) {
            ++sharp;
            semi_sharp.add(s);
          }
        }
        sharp_count_[v] = sharp;
        semi_sharp_[v] = semi_sharp;
      });
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

  // The degrees of the faces of edge e (0 for none).
  std::pair<u32, u32> face_degrees(u32 e) const
  {
    const Level& p = *p_;
    const u32 f0 = p.h_face[edge_halfedge(e)], f1 = p.h_face[dart_encoding::halfedge_of_edge(e, 1)];
    return {f0 == null_u32 ? 0u : p.degree(f0), f1 == null_u32 ? 0u : p.degree(f1)};
  }

  // Edge keys: 0 the crease mask, 1 + d0 * D + d1 the smooth mask between
  // faces of degrees d0 and d1 (both below D); a semi-sharp blend is an
  // entry of its own. `s` is the edge's sharpness, `sa` and `sb` its children's.
  u32 edge_key(u32 e, float s, float sa, float sb) const
  {
    if (Mask::creases && Crease::edge_point_is_crease(method_, s, sa, sb))
      return 0;
    if (Mask::creases && Crease::is_sharp(s))
      return own_entry;
    const auto [d0, d1] = face_degrees(e);
    return d0 < D && d1 < D ? smooth_edge_key(d0, d1) : own_entry;
  }
  static u32 smooth_edge_key(u32 d0, u32 d1) { return 1 + d0 * D + d1; }
  // The shared table entry of an edge key other than `own_entry`.
  Edge_weights<W> shared_edge_entry(u32 key) const
  {
    return Step_weights<W>::finish(key == 0 ? Edge_weights<W>{W(0.5), W(0), false}
                                            : smooth_edge_weights((key - 1) / D, (key - 1) % D, 0.0f));
  }

  // The smooth mask of edge e; if it is semi-sharp (`s > 0`), OpenSubdiv's
  // blend with the crease mask, weighted by `s` (not clamped).
  Edge_weights<W> smooth_edge_weights(u32 d0, u32 d1, float s) const
  {
    Edge_weights<W> w{};
    mask_->smooth_edge(d0, d1, w);
    if (Crease::is_sharp(s)) {
      const W pw = W(double(s)), cw = W(1) - pw;
      w.vertex = pw * W(0.5) + cw * w.vertex;
      w.face = cw * w.face;
    }
    return w;
  }

  // Edge weights, each edge on its own; the child edges' sharpness into
  // `child` (2e at the source, 2e+1 at the target) if the parent is sharp.
  // Returns whether a child edge keeps some sharpness.
  template <class ConcurrencyTag>
  bool add_edge_weights(float* child)
  {
    const Level& p = *p_;
    Step_weights<W>& sw = *sw_;
    if (!p.sharp && p.face_degree != 0 && p.face_degree < D && p.ne != 0) {
      // No crease and no border, and faces of one degree: every edge has the
      // same smooth mask, which needs no look at its faces.
      const u32 cls = u32(sw.edges.size());
      sw.edges.push_back(shared_edge_entry(smooth_edge_key(p.face_degree, p.face_degree)));
      for_each_index<ConcurrencyTag>(p.ne, [&](u32 e) { sw.edge_class[e] = cls; });
      return false;
    }
    std::vector<std::uint8_t> used(1 + D * D, 0);
    u32 any = 0, own = 0;
    classify<ConcurrencyTag>(p.ne, sw.edge_class, used, any, own, [&](u32 e, Ring&, u32& block_any) {
      const float s = p.sharp ? p.e_sharp[e] : 0.0f;
      float sa = 0.0f, sb = 0.0f;
      if (Crease::is_sharp(s)) {
        sa = child_edge_sharpness(s, p.source(edge_dart(e)));
        sb = child_edge_sharpness(s, p.h_target[edge_halfedge(e)]);
        block_any |= Crease::is_sharp(sa) || Crease::is_sharp(sb) ? 1u : 0u;
      }
      if (p.sharp) {
        child[2 * e] = sa;
        child[2 * e + 1] = sb;
      }
      return edge_key(e, s, sa, sb);
    });
    std::vector<u32> class_of(used.size(), null_u32);
    for (u32 key = 0; key < used.size(); ++key) {
      if (!used[key])
        continue;
      class_of[key] = u32(sw.edges.size());
      sw.edges.push_back(shared_edge_entry(key));
    }
    assign_classes<ConcurrencyTag>(p.ne, sw.edge_class, class_of, own, sw.edges,
                                   [&](u32 e, Ring&, Edge_weights<W>& w) {
                                     const auto [d0, d1] = face_degrees(e);
                                     w = smooth_edge_weights(d0, d1, Mask::creases && p.sharp ? p.e_sharp[e] : 0.0f);
                                   });
    return any != 0;
  }

  // Gives each element of [0, n) its class key, key_of(i, ring, any) (which
  // sets `any` if a child keeps some sharpness), into `cls`; marks the keys
  // of shared entries in `used` and counts in `own` the elements of key
  // `own_entry`. Blocks of elements may run in parallel.
  template <class ConcurrencyTag, class KeyOf>
  void classify(u32 n, Array<u32>& cls, std::vector<std::uint8_t>& used, u32& any, u32& own, const KeyOf& key_of)
  {
    for_each_block<ConcurrencyTag>(n, [&](u32 begin, u32 end) {
      Ring ring;
      u32 block_any = 0, block_own = 0;
      for (u32 i = begin; i < end; ++i) {
        const u32 key = key_of(i, ring, block_any);
        cls[i] = key;
        if (key == own_entry)
          ++block_own;
        else
          mark<ConcurrencyTag>(used[key]);
      }
      atomic_add<ConcurrencyTag>(any, block_any);
      atomic_add<ConcurrencyTag>(own, block_own);
    });
  }

  // Replaces each key in `cls` by its class: `class_of[key]` for the shared
  // entries, which `table` holds, and for the elements of key `own_entry`
  // (`own` of them) new entries appended to `table` in element order, each
  // made by entry(i, ring, weights).
  template <class ConcurrencyTag, class Table, class Entry>
  void assign_classes(u32 n, Array<u32>& cls, const std::vector<u32>& class_of, u32 own, Table& table,
                      const Entry& entry)
  {
    if (own == 0) {
      for_each_index<ConcurrencyTag>(n, [&](u32 i) { cls[i] = class_of[cls[i]]; });
      return;
    }
    const u32 base = u32(table.size());
    table.resize(std::size_t(base) + own);
    own_before_.clear();
    own_before_.resize(std::size_t(n) + 1);
    own_before_[0] = 0;
    for_each_index<ConcurrencyTag>(n, [&](u32 i) { own_before_[i + 1] = cls[i] == own_entry ? 1 : 0; });
    prefix_sum<ConcurrencyTag>(own_before_.data(), n);
    for_each_block<ConcurrencyTag>(n, [&](u32 begin, u32 end) {
      Ring ring;
      for (u32 i = begin; i < end; ++i) {
        if (cls[i] != own_entry) {
          cls[i] = class_of[cls[i]];
          continue;
        }
        cls[i] = base + own_before_[i];
        typename Table::value_type w{};
        entry(i, ring, w);
        table[cls[i]] = Step_weights<W>::finish(w);
      }
    });
  }

  // Vertex weights; the child vertices' sharpness into `child` if the parent
  // is sharp. Returns whether a child vertex keeps some sharpness. Keys: 0
  // the corner mask, 1 + n the smooth mask of valence n.
  template <class ConcurrencyTag>
  bool add_vertex_weights(float* child)
  {
    const Level& p = *p_;
    Step_weights<W>& sw = *sw_;
    const u32 max_valence =
      reduce<ConcurrencyTag>(p.nv, u32(0), [&](u32 v) { return valence_[v]; }, [](u32 a, u32 b) {
        return (std::max)(a, b);
      });
    std::vector<std::uint8_t> used(std::size_t(max_valence) + 2, 0);
    u32 any = 0, own = 0;
    classify<ConcurrencyTag>(p.nv, sw.vertex_class, used, any, own, [&](u32 v, Ring& ring, u32& block_any) {
      const u32 n = valence_[v];
      u32 key = n == 0 ? 0 : 1 + n;
      if (p.sharp) {
        const float vs = p.v_sharp[v];
        child[v] = Crease::subdivide_vertex_sharpness(vs);
        block_any |= Crease::is_sharp(child[v]) ? 1u : 0u;
        if (n != 0 && Mask::creases && !(Crease::is_smooth(vs) && sharp_count_[v] == 0))
          key = sharp_vertex_key(v, vs, child[v], ring, nullptr);
      }
      return key;
    });
    std::vector<u32> class_of(used.size(), null_u32);
    for (u32 key = 0; key < used.size(); ++key) {
      if (!used[key])
        continue;
      Vertex_weights<W> w{};
      if (key == 0)
        corner_weights(w);
      else
        smooth_weights(*mask_, key - 1, w);
      class_of[key] = u32(sw.vertices.size());
      sw.vertices.push_back(Step_weights<W>::finish(w));
    }
    assign_classes<ConcurrencyTag>(p.nv, sw.vertex_class, class_of, own, sw.vertices,
                                   [&](u32 v, Ring& ring, Vertex_weights<W>& w) {
                                     sharp_vertex_key(v, p.v_sharp[v], child[v], ring, &w);
                                   });
    return any != 0;
  }

  // A vertex with sharpness or sharp edges: the key of the mask of its
  // rule, or `own_entry` if it is blended with the mask of its child's rule
  // where they differ; that blend is then written into `*w` if `w` is given.
  u32 sharp_vertex_key(u32 v, float vs, float child_vs, Ring& ring, Vertex_weights<W>* w) const
  {
    const Crease::Rule rule = Crease::vertex_rule(vs, sharp_count_[v]);
    if (rule == Crease::Rule::smooth || rule == Crease::Rule::dart)
      return 1 + valence_[v];
    walk_ring(v, ring);
    const u32 m = u32(ring.vertex.size());
    const Crease::Rule child_rule = Crease::vertex_rule(child_vs, m, ring.child_sharpness.data());
    if (rule == Crease::Rule::corner && child_rule == Crease::Rule::corner)
      return 0;
    if (!w)
      return own_entry;
    rule_weights(rule, ring, ring.sharpness, valence_[v], *w);
    if (child_rule != rule) {
      const float fraction = Crease::fractional_weight_at_vertex(vs, child_vs, m, ring.sharpness.data(),
                                                                 ring.child_sharpness.data());
      Vertex_weights<W> c{};
      rule_weights(child_rule, ring, ring.child_sharpness, valence_[v], c);
      blend(*w, c, fraction);
    }
    return own_entry;
  }

  // The ring of `v` into `ring`.
  void walk_ring(u32 v, Ring& ring) const
  {
    const Level& p = *p_;
    ring.vertex.clear();
    ring.sharpness.clear();
    ring.child_sharpness.clear();
    const u32 d0 = p.v_dart[v];
    u32 d = d0;
    do {
      const float s = p.e_sharp[dart_encoding::edge_of_dart(d)];
      ring.vertex.push_back(p.source(d));
      ring.sharpness.push_back(s);
      ring.child_sharpness.push_back(Crease::is_sharp(s) ? child_edge_sharpness(s, v) : 0.0f);
      d = p.opposite(p.next(d));
    } while (d != d0);
  }

  // The mask of `rule`, its crease ends taken from the edge sharpness
  // `sharpness` of the walk `ring`.
  void rule_weights(Crease::Rule rule, const Ring& ring, const std::vector<float>& sharpness, u32 valence,
                    Vertex_weights<W>& w) const
  {
    if (rule == Crease::Rule::corner) {
      corner_weights(w);
    } else if (rule == Crease::Rule::crease) {
      u32 ends[2] = {null_u32, null_u32};
      for (std::size_t i = 0, j = 0; i < sharpness.size() && j < 2; ++i)
        if (Crease::is_sharp(sharpness[i]))
          ends[j++] = ring.vertex[i];
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
  const Incidence* incidence_ = nullptr;
  Step_weights<W>* sw_ = nullptr;
  // per vertex (own_before_: per element of the pass being numbered)
  Array<u32> valence_, sharp_count_, own_before_;
  Array<Crease::Semi_sharp_edges> semi_sharp_;
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_WEIGHTS_H
