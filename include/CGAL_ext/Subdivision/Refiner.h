// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The subdivision engine: refines the topology of a Mobius_mesh level by
// level, keeps each level's weights, and interpolates any vertex data
// through the levels without refining again.

#ifndef CGAL_EXT_SUBDIVISION_REFINER_H
#define CGAL_EXT_SUBDIVISION_REFINER_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Level.h>
#include <CGAL_ext/Subdivision/internal/Stencil_splits.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/number_utils.h>
#include <CGAL/tags.h>


#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {

/// The rules of a refinement that do not depend on the scheme.
struct Refinement_options
{
  Boundary_interpolation boundary_interpolation = Boundary_interpolation::edge_only;
  Crease_method crease_method = Crease_method::uniform;
  /// With `CGAL::Parallel_tag`, levels of fewer vertices are interpolated
  /// serially (with the same result): on small levels the incidence tables
  /// of the parallel pass cost more than the threads save.
  std::uint32_t parallel_min_vertices = 1u << 17;
};

namespace internal {

enum Rule : unsigned { rule_smooth = 1, rule_dart = 2, rule_crease = 4, rule_corner = 8 };

inline float decrement_sharpness(float s)
{
  if (s <= 0.0f)
    return 0.0f;
  if (s >= infinitely_sharp)
    return infinitely_sharp;
  return s > 1.0f ? s - 1.0f : 0.0f;
}

// OpenSubdiv's Chaikin rule for the child of an edge of sharpness `s` at an
// end vertex of `valence` edges, `semi_count` of which are semi-sharp with
// sharpnesses summing to `semi_sum` (float arithmetic, as OpenSubdiv).
inline float chaikin_sharpness(float s, unsigned valence, float semi_sum, unsigned semi_count)
{
  if (valence < 2)
    return decrement_sharpness(s);
  if (s <= 0.0f)
    return 0.0f;
  if (s >= infinitely_sharp)
    return infinitely_sharp;
  if (semi_count > 1) {
    const float average = (semi_sum - s) / float(semi_count - 1);
    s = 0.75f * s + 0.25f * average;
  }
  s -= 1.0f;
  return s > 0.0f ? s : 0.0f;
}

inline unsigned vertex_rule(float vertex_sharpness, unsigned sharp_edges)
{
  if (vertex_sharpness > 0.0f || sharp_edges > 2)
    return rule_corner;
  return 1u << sharp_edges;
}

template <class V>
auto normalize_value(V& v, int) -> decltype(v.exact(), void())
{
  v.exact(); // evaluates a lazy exact value and drops its construction history
}
template <class V>
void normalize_value(V&, long)
{}

// Vertex -> incident edges and faces, each in increasing order: the order in
// which the serial pass adds their terms, so a gather gives the same bits.
struct Incidence
{
  std::vector<u32> edge_offset, edges, face_offset, faces;
};

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
  u32 add(Edge_weights<W> w)
  {
    w.has_face = !CGAL::is_zero(w.face);
    edges.push_back(w);
    return u32(edges.size() - 1);
  }
  u32 add(Vertex_weights<W> w)
  {
    w.terms = std::uint8_t((CGAL::is_zero(w.edge) ? 0 : 1) | (CGAL::is_zero(w.face) ? 0 : 2) |
                           (CGAL::is_zero(w.edge_point) ? 0 : 4) | (CGAL::is_zero(w.crease) ? 0 : 8));
    vertices.push_back(w);
    return u32(vertices.size() - 1);
  }
  const Edge_weights<W>& edge(u32 e) const { return edges[edge_class[e]]; }
  const Vertex_weights<W>& vertex(u32 v) const { return vertices[vertex_class[v]]; }
};

} // namespace internal

/// \ingroup PkgSubdivision
///
/// Refines a `Mobius_mesh` with a subdivision mask and keeps what it needs to
/// interpolate vertex data through the levels: each level's topology
/// (`internal::Level`) and each level's edge and vertex weights. Refining is
/// done once; `interpolate()` then maps any vertex data (points in any kernel,
/// normals, colours) from the base mesh to the last level, as often as needed.
/// Buffers are kept and reused when the same refiner refines again.
///
/// \tparam Mask a model of `SubdivisionMask`
/// \tparam W the weight type: `double`, or the field type of an exact kernel
template <class Mask, class W = double>
class Refiner
{
public:
  using Weight = W;
  using Level = internal::Level;
  using u32 = internal::u32;

  explicit Refiner(const Mask& mask = Mask(), const Refinement_options& options = Refinement_options())
    : mask_(mask), options_(options)
  {}

  const Mask& mask() const { return mask_; }
  const Refinement_options& options() const { return options_; }

  /// Refines `mesh` `levels` times. `edge_sharpness` and `vertex_sharpness`
  /// hold one value per edge / vertex (an empty vector means all 0).
  /// \throws Parameter_error if a sharpness is NaN, or if the mask splits
  /// triangles and `mesh` has a face that is not a triangle.
  template <class P>
  void refine(const Mobius_mesh<P>& mesh, unsigned levels, const std::vector<float>& edge_sharpness = {},
              const std::vector<float>& vertex_sharpness = {})
  {
    levels_.resize(levels + 1);
    weights_.resize(uses_stencils ? 0 : levels);
    stencils_.resize(uses_stencils ? levels : 0);
    build_base(mesh, edge_sharpness, vertex_sharpness);
    for (unsigned k = 0; k < levels; ++k)
      step(k, k);
  }

  /// Refines `mesh` `levels` times into `out`, interpolating `values` (one
  /// per vertex of `mesh`, replaced by one per vertex of `out`) on the way.
  /// Only two levels are alive at a time, and the last one is written
  /// straight into `out`'s arrays: less memory and faster than `refine()`,
  /// `interpolate()` and `build_mesh()`, for when nothing else is to be
  /// interpolated. `out` gets the sharpness maps and the holes as with
  /// `build_mesh()`. The refiner keeps no level afterwards
  /// (`number_of_levels()` is 0).
  /// `Values` is a `std::vector` of any value type and allocator.
  /// \throws Parameter_error as `refine()`, before `out` is touched.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class P, class Values, class Q>
  void refine_and_interpolate(const Mobius_mesh<P>& mesh, unsigned levels, Values& values, Mobius_mesh<Q>& out,
                              const std::vector<float>& edge_sharpness = {},
                              const std::vector<float>& vertex_sharpness = {}, bool write_sharpness = false)
  {
    levels_.resize(levels == 0 ? 1 : 2);
    build_base(mesh, edge_sharpness, vertex_sharpness);
    Values next;
    // Interpolates level 0 into level 1 and keeps only the new values: what
    // a step needs of its parent level is its topology and its weights.
    auto advance_values = [&]() {
      next.clear(); // nothing to copy on growth
      next.resize(child_vertex_count(0));
      interpolate_level<ConcurrencyTag>(0, values.data(), next.data());
      auto* dst = next.data();
      internal::for_each_index<ConcurrencyTag>(u32(next.size()),
                                               [&](u32 v) { internal::normalize_value(dst[v], 0); });
      values.swap(next);
      Values().swap(next);
    };
    for (unsigned k = 0; k < levels; ++k) {
      const bool last = k + 1 == levels;
      if constexpr (uses_stencils) {
        step(0, k);
        advance_values();
      } else {
        if (weights_.empty())
          weights_.resize(1);
        compute_weights(0);
        advance_values();
        weights_[0] = internal::Step_weights<W>(); // the split does not need them
        incidence_.clear();
        if (last) {
          split_into_mesh<ConcurrencyTag>(out, write_sharpness);
          levels_.clear();
          clear_scratch();
          return;
        }
        split<ConcurrencyTag>(0, true);
      }
      std::swap(levels_[0], levels_[1]);
      levels_[1] = Level(); // the parent: too small to hold the next level
    }
    levels_.resize(1);
    build_mesh(out, write_sharpness);
    levels_.clear();
    clear_scratch();
  }

  /// The number of refinement steps done by the last `refine()`.
  unsigned number_of_levels() const { return levels_.empty() ? 0u : unsigned(levels_.size() - 1); }
  /// The topology of level `k` (0 is the base mesh).
  const Level& level(unsigned k) const { return levels_[k]; }
  /// The weights of edge `e` and vertex `v` of level `k` in step `k`
  /// (primal schemes: quad and triangle splits).
  const Edge_weights<W>& edge_weights(unsigned k, u32 e) const { return weights_[k].edge(e); }
  const Vertex_weights<W>& vertex_weights(unsigned k, u32 v) const { return weights_[k].vertex(v); }
  /// The stencils of step `k` (Doo–Sabin and √3): child vertex `i` is the sum
  /// of `weight[j]` times parent vertex `source[j]` over `j` in
  /// `[offset[i], offset[i+1])`.
  const internal::Stencils<W>& stencils(unsigned k) const { return stencils_[k]; }

  /// Interpolates one level: `src` holds a value per vertex of level `k`,
  /// `dst` receives one per vertex of level `k+1`. `Value` needs `Value + Value`
  /// and `W * Value`.
  template <class Value>
  void interpolate_level(unsigned k, const Value* src, Value* dst) const;

  /// As `interpolate_level()`, in parallel with TBB for `CGAL::Parallel_tag`;
  /// the result is bit for bit the serial one (each value is summed in the
  /// same order). The first parallel call builds vertex-to-edge and
  /// vertex-to-face tables, so concurrent calls on one refiner are not allowed.
  template <class ConcurrencyTag, class Value>
  void interpolate_level(unsigned k, const Value* src, Value* dst) const;

  /// Interpolates `base` (one value per vertex of the base mesh) through all
  /// levels into `result` (resized to the vertices of the last level).
  /// `scratch` holds intermediate levels; pass the same vectors again to
  /// avoid allocating.
  ///
  /// With `ConcurrencyTag` = `CGAL::Parallel_tag` (TBB needed), each level is
  /// interpolated in parallel, bit for bit as the serial result.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class Value>
  void interpolate(const std::vector<Value>& base, std::vector<Value>& result, std::vector<Value>& scratch) const
  {
    const unsigned n = number_of_levels();
    if (n == 0) {
      result = base;
      return;
    }
    result.resize(levels_[n].nv);
    if (n > 1)
      scratch.resize(levels_[n - 1].nv);
    const Value* src = base.data();
    for (unsigned k = 0; k < n; ++k) {
      Value* dst = ((n - 1 - k) % 2 == 0) ? result.data() : scratch.data();
      interpolate_level<ConcurrencyTag>(k, src, dst);
      internal::for_each_index<ConcurrencyTag>(levels_[k + 1].nv,
                                               [&](u32 v) { internal::normalize_value(dst[v], 0); });
      src = dst;
    }
  }
  template <class ConcurrencyTag = CGAL::Sequential_tag, class Value>
  void interpolate(const std::vector<Value>& base, std::vector<Value>& result) const
  {
    std::vector<Value> scratch;
    interpolate<ConcurrencyTag>(base, result, scratch);
  }

  /// Replaces the connectivity of `out` with that of the last level. If
  /// `write_sharpness`, the property maps "e:sharpness" and "v:sharpness" get
  /// the sharpness of the last level (border edges: 0, as they are sharp by
  /// rule). If the base had holes (boundary interpolation `none`), the face
  /// property "f:hole" marks the faces that descend from them.
  template <class P>
  void build_mesh(Mobius_mesh<P>& out, bool write_sharpness) const;

private:
  // Refines levels_[slot] into levels_[slot + 1] with the weights or
  // stencils of slot `slot`; `k` is the step's number (√3 alternates).
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  void step(unsigned slot, unsigned k)
  {
    if (levels_.size() < slot + 2)
      levels_.resize(slot + 2);
    incidence_.clear();
    if constexpr (uses_stencils) {
      if (stencils_.size() < slot + 1)
        stencils_.resize(slot + 1);
      internal::Face_list faces;
      if constexpr (Mask::split == Split::dual)
        internal::dual_split(levels_[slot], mask_, faces, stencils_[slot]);
      else
        internal::sqrt3_split(levels_[slot], mask_, k % 2 == 1, faces, stencils_[slot]);
      internal::level_from_faces(stencils_[slot].size(), faces, levels_[slot + 1]);
    } else {
      CGAL_USE(k);
      if (weights_.size() < slot + 1)
        weights_.resize(slot + 1);
      compute_weights(slot);
      split<ConcurrencyTag>(slot, true);
    }
  }

  // The topological split of levels_[slot] into levels_[slot + 1] (primal
  // schemes), after compute_weights(slot), whose child sharpness it takes.
  template <class ConcurrencyTag>
  void split(unsigned slot, bool corner_table)
  {
    Level& c = levels_[slot + 1];
    split_level<ConcurrencyTag>(levels_[slot], c, corner_table);
    if (child_sharp_) {
      c.sharp = true;
      c.e_sharp.swap(child_e_sharp_);
      c.v_sharp.swap(child_v_sharp_);
    }
  }

  // The mask's split of `p` into `c`, a Level or a Mesh_writer.
  template <class ConcurrencyTag, class Child>
  static void split_level(const Level& p, Child& c, bool corner_table)
  {
    if constexpr (Mask::split == Split::quad)
      internal::quad_split<ConcurrencyTag>(p, c, corner_table);
    else
      internal::triangle_split<ConcurrencyTag>(p, c, corner_table);
  }

  // The last split of a one-pass refinement: levels_[0] into `out`.
  template <class ConcurrencyTag, class Q>
  void split_into_mesh(Mobius_mesh<Q>& out, bool write_sharpness)
  {
    out.clear();
    internal::Mesh_writer<Mobius_mesh<Q>> c(out);
    split_level<ConcurrencyTag>(levels_[0], c, false);
    levels_[0] = Level(); // freed before the maps are made
    CGAL_ext::internal::Connectivity_access::reset_property_maps(out);
    if (write_sharpness)
      add_sharpness_maps(out, child_sharp_ ? child_e_sharp_.data() : nullptr,
                         child_sharp_ ? child_v_sharp_.data() : nullptr);
    add_hole_map(out, c.f_hole);
  }

  // The number of vertices of the child of level `k` (primal schemes).
  u32 child_vertex_count(unsigned k) const
  {
    if constexpr (uses_stencils) {
      return stencils_[k].size();
    } else {
      const Level& p = levels_[k];
      return p.nv + p.ne + (Mask::split == Split::quad ? p.nf : 0u);
    }
  }

  void clear_scratch()
  {
    weights_.clear();
    stencils_.clear();
    incidence_.clear();
    decltype(child_e_sharp_)().swap(child_e_sharp_);
    decltype(child_v_sharp_)().swap(child_v_sharp_);
  }

  // The maps build_mesh() documents; null sharpness means all 0.
  template <class Q>
  static void add_sharpness_maps(Mobius_mesh<Q>& out, const float* edge_sharpness, const float* vertex_sharpness)
  {
    auto es = out.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first;
    auto vs = out.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first;
    if (edge_sharpness)
      for (Edge_index e : out.edges())
        if (!out.is_border(e))
          es[e] = edge_sharpness[e.idx()]; // border edges are sharp by rule
    if (vertex_sharpness)
      for (Vertex_index v : out.vertices())
        vs[v] = vertex_sharpness[v.idx()];
  }
  template <class Q, class Holes>
  static void add_hole_map(Mobius_mesh<Q>& out, const Holes& holes)
  {
    if (holes.empty())
      return;
    auto map = out.template add_property_map<Face_index, std::uint8_t>("f:hole", 0).first;
    for (Face_index f : out.faces())
      map[f] = holes[f.idx()];
  }

  template <class P>
  void build_base(const Mobius_mesh<P>& mesh, const std::vector<float>& es, const std::vector<float>& vs);
  void compute_weights(unsigned k);

  // The points both interpolation passes share, formed by the same
  // expressions so that the passes agree bit for bit.
  template <class Value>
  static Value stencil_point(const internal::Stencils<W>& st, u32 i, const Value* src)
  {
    u32 j = st.offset[i];
    const u32 j1 = st.offset[i + 1];
    Value x = st.weight[j] * src[st.source[j]];
    for (++j; j < j1; ++j)
      x = x + st.weight[j] * src[st.source[j]];
    return x;
  }
  template <class Value>
  static Value face_point(const Level& p, u32 f, const Value* src)
  {
    const u32 k0 = p.f_offset[f], k1 = p.f_offset[f + 1];
    Value sum = src[p.h_target[p.corner_h[k0]]];
    for (u32 i = k0 + 1; i < k1; ++i)
      sum = sum + src[p.h_target[p.corner_h[i]]];
    return (k1 - k0 == 4 ? W(1) / W(4) : W(1) / W(int(k1 - k0))) * sum;
  }
  // `face_points`: the level's face points (quad split), indexed by face.
  template <class Value>
  static Value edge_point(const Level& p, const Edge_weights<W>& w, u32 e, const Value* src, const Value* face_points)
  {
    Value x = w.vertex * (src[p.source(4 * e)] + src[p.h_target[2 * e]]);
    if (w.has_face) {
      for (u32 i = 0; i < 2; ++i) {
        const u32 h = 2 * e + i, f = p.h_face[h];
        if (f == internal::null_u32)
          continue;
        if constexpr (Mask::split == Split::quad)
          x = x + w.face * face_points[f];
        else
          x = x + w.face * src[p.h_target[p.h_next[h] >> 1]];
      }
    }
    return x;
  }

  static constexpr bool uses_stencils = Mask::split == Split::dual || Mask::split == Split::sqrt3;

  Mask mask_;
  Refinement_options options_;
  std::vector<Level> levels_;
  std::vector<internal::Stencils<W>> stencils_;
  mutable std::vector<internal::Incidence> incidence_; // built by the first parallel interpolation
  std::vector<internal::Step_weights<W>> weights_;
  // The sharpness of the next level, made by compute_weights() before the
  // split; unused if `child_sharp_` is false (it is all 0).
  internal::Array<float> child_e_sharp_, child_v_sharp_;
  bool child_sharp_ = false;
  // per-vertex scratch of compute_weights()
  std::vector<u32> valence_, sharp_count_, semi_count_;
  std::vector<float> semi_sum_;
  std::vector<u32> ring_u_;
  std::vector<float> ring_s_, ring_cs_;
};

// ---------------------------------------------------------------------------

template <class Mask, class W>
template <class P>
void Refiner<Mask, W>::build_base(const Mobius_mesh<P>& m, const std::vector<float>& es,
                                  const std::vector<float>& vs)
{
  using internal::null_u32;
  Level& L = levels_[0];
  internal::fill_level(m, L);
  const u32 nv = L.nv, ne = L.ne, nf = L.nf;
  for (u32 e = 0; e < ne; ++e) {
    float s = es.empty() ? 0.0f : es[e];
    if (std::isnan(s))
      throw Parameter_error("subdivision: the sharpness of edge e" + std::to_string(e) + " is NaN");
    if (L.h_face[2 * e] == null_u32 || L.h_face[2 * e + 1] == null_u32)
      s = infinitely_sharp; // border edges are infinitely sharp, as in OpenSubdiv
    L.e_sharp[e] = s;
  }
  for (u32 v = 0; v < nv; ++v) {
    const float s = vs.empty() ? 0.0f : vs[v];
    if (std::isnan(s))
      throw Parameter_error("subdivision: the sharpness of vertex v" + std::to_string(v) + " is NaN");
    L.v_sharp[v] = s;
  }
  if constexpr (Mask::split == Split::triangle || Mask::split == Split::sqrt3) {
    for (u32 f = 0; f < nf; ++f)
      if (L.degree(f) != 3)
        throw Parameter_error("subdivision: the scheme needs a triangle mesh, but face f" + std::to_string(f) +
                              " has " + std::to_string(L.degree(f)) + " sides");
  }

  if constexpr (uses_stencils)
    return; // Doo–Sabin and √3 have border rules of their own

  // Border vertices: corners (edge and corner), or their faces become holes (none).
  L.f_hole.clear();
  if (options_.boundary_interpolation == Boundary_interpolation::none)
    L.f_hole.assign(nf, 0);
  for (u32 v = 0; v < nv; ++v) {
    const u32 d0 = L.v_dart[v];
    if (d0 == null_u32 || !L.is_border_dart(d0))
      continue;
    u32 edges = 0, d = d0;
    do {
      ++edges;
      const u32 f = L.h_face[d >> 1];
      if (f != null_u32 && !L.f_hole.empty())
        L.f_hole[f] = 1;
      d = L.opposite(L.next(d));
    } while (d != d0);
    if (options_.boundary_interpolation == Boundary_interpolation::edge_and_corner && edges == 2)
      L.v_sharp[v] = infinitely_sharp;
  }
  // A level without sharpness skips its bookkeeping, and so do its children.
  auto positive = [](float s) { return s > 0.0f; };
  if (std::none_of(L.e_sharp.begin(), L.e_sharp.end(), positive) &&
      std::none_of(L.v_sharp.begin(), L.v_sharp.end(), positive))
    L.drop_sharpness();
}

template <class Mask, class W>
void Refiner<Mask, W>::compute_weights(unsigned k)
{
  using internal::null_u32;
  const Level& p = levels_[k];
  internal::Step_weights<W>& sw = weights_[k];
  const u32 nv = p.nv, ne = p.ne;
  const bool chaikin = options_.crease_method == Crease_method::chaikin;
  sw.reset(ne, nv);
  // The child's sharpness, if the parent has any.
  const u32 child_ne = 2 * ne + p.nc, child_nv = child_vertex_count(k);
  child_e_sharp_.clear();
  child_v_sharp_.clear();
  if (p.sharp) {
    child_e_sharp_.resize(child_ne);
    child_v_sharp_.resize(child_nv);
  }
  float* const ces = child_e_sharp_.data();
  float* const cvs = child_v_sharp_.data();

  valence_.assign(nv, 0);
  for (u32 e = 0; e < ne; ++e) {
    ++valence_[p.source(4 * e)];
    ++valence_[p.h_target[2 * e]];
  }
  if (p.sharp) {
    sharp_count_.assign(nv, 0);
    semi_count_.assign(nv, 0);
    semi_sum_.assign(nv, 0.0f);
    for (u32 e = 0; e < ne; ++e) {
      const float s = p.e_sharp[e];
      if (s <= 0.0f)
        continue;
      const u32 a = p.source(4 * e), b = p.h_target[2 * e];
      ++sharp_count_[a];
      ++sharp_count_[b];
      if (s < infinitely_sharp) {
        ++semi_count_[a];
        ++semi_count_[b];
        semi_sum_[a] += s;
        semi_sum_[b] += s;
      }
    }
  }
  auto child_sharpness = [&](float s, u32 v) {
    return chaikin ? internal::chaikin_sharpness(s, valence_[v], semi_sum_[v], semi_count_[v])
                   : internal::decrement_sharpness(s);
  };
  bool child_sharp = false; // does any child edge or vertex keep some sharpness?

  // Edges, each on its own.
  for (u32 e = 0; e < ne; ++e) {
    const float s = p.sharp ? p.e_sharp[e] : 0.0f;
    float sa = 0.0f, sb = 0.0f;
    if (s > 0.0f) {
      sa = child_sharpness(s, p.source(4 * e));
      sb = child_sharpness(s, p.h_target[2 * e]);
      ces[2 * e] = sa;
      ces[2 * e + 1] = sb;
      child_sharp = child_sharp || sa > 0.0f || sb > 0.0f;
    } else if (p.sharp) {
      ces[2 * e] = ces[2 * e + 1] = 0.0f;
    }
    const bool crease = Mask::creases && s > 0.0f && (s >= 1.0f || (chaikin && sa > 0.0f && sb > 0.0f));
    u32& cls = sw.edge_class[e];
    if (crease) {
      if (sw.crease_edge == null_u32)
        sw.crease_edge = sw.add(Edge_weights<W>{W(0.5), W(0), false});
      cls = sw.crease_edge;
      continue;
    }
    const u32 f0 = p.h_face[2 * e], f1 = p.h_face[2 * e + 1];
    const u32 d0 = f0 == null_u32 ? 0u : p.degree(f0), d1 = f1 == null_u32 ? 0u : p.degree(f1);
    const bool blended = Mask::creases && s > 0.0f;
    constexpr u32 D = internal::Step_weights<W>::max_shared_degree;
    if (!blended && d0 < D && d1 < D && sw.smooth_edge[d0 * D + d1] != null_u32) {
      cls = sw.smooth_edge[d0 * D + d1];
      continue;
    }
    Edge_weights<W> w{};
    mask_.smooth_edge(d0, d1, w);
    if (blended) {
      // Semi-sharp edge decaying to smooth: OpenSubdiv's blend, with the
      // parent sharpness as weight (not clamped).
      const W pw = W(double(s)), cw = W(1) - pw;
      w.vertex = pw * W(0.5) + cw * w.vertex;
      w.face = cw * w.face;
    }
    cls = sw.add(w);
    if (!blended && d0 < D && d1 < D)
      sw.smooth_edge[d0 * D + d1] = cls;
  }
  if (p.sharp)
    std::fill(ces + 2 * ne, ces + child_ne, 0.0f);

  // Vertices.
  auto zero = [](Vertex_weights<W>& w) {
    w.vertex = w.edge = w.face = w.edge_point = w.crease = W(0);
    w.crease_ends[0] = w.crease_ends[1] = null_u32;
  };
  auto corner_mask = [&](Vertex_weights<W>& w) {
    zero(w);
    w.vertex = W(1);
  };
  auto crease_mask = [&](Vertex_weights<W>& w, u32 a, u32 b) {
    zero(w);
    w.vertex = W(0.75);
    w.crease = W(0.125);
    w.crease_ends[0] = a;
    w.crease_ends[1] = b;
  };
  auto smooth_mask = [&](Vertex_weights<W>& w, u32 n) {
    zero(w);
    mask_.smooth_vertex(n, w);
  };
  auto smooth_class = [&](u32 n) {
    if (sw.smooth_vertex.size() <= n)
      sw.smooth_vertex.resize(n + 1, null_u32);
    if (sw.smooth_vertex[n] == null_u32) {
      Vertex_weights<W> w{};
      smooth_mask(w, n);
      sw.smooth_vertex[n] = sw.add(w);
    }
    return sw.smooth_vertex[n];
  };
  auto corner_class = [&]() {
    if (sw.corner_vertex == null_u32) {
      Vertex_weights<W> w{};
      corner_mask(w);
      sw.corner_vertex = sw.add(w);
    }
    return sw.corner_vertex;
  };
  for (u32 v = 0; v < nv; ++v) {
    u32& cls = sw.vertex_class[v];
    const u32 n = valence_[v];
    if (!p.sharp) {
      cls = n == 0 ? corner_class() : smooth_class(n);
      continue;
    }
    const float vs = p.v_sharp[v];
    cvs[v] = internal::decrement_sharpness(vs);
    child_sharp = child_sharp || cvs[v] > 0.0f;
    if (n == 0) {
      cls = corner_class();
      continue;
    }
    if (!Mask::creases || (vs <= 0.0f && sharp_count_[v] == 0)) {
      cls = smooth_class(n);
      continue;
    }
    const unsigned prule = internal::vertex_rule(vs, sharp_count_[v]);
    if (prule == internal::rule_smooth || prule == internal::rule_dart) {
      cls = smooth_class(n);
      continue;
    }
    // Walk the ring: sharpness of each edge now and in the child level.
    ring_u_.clear();
    ring_s_.clear();
    ring_cs_.clear();
    const u32 d0 = p.v_dart[v];
    u32 d = d0;
    do {
      const float s = p.e_sharp[d >> 2];
      ring_u_.push_back(p.source(d));
      ring_s_.push_back(s);
      ring_cs_.push_back(s > 0.0f ? child_sharpness(s, v) : 0.0f);
      d = p.opposite(p.next(d));
    } while (d != d0);
    const std::size_t m = ring_u_.size();
    u32 sharp_children = 0;
    for (std::size_t i = 0; i < m; ++i)
      sharp_children += ring_cs_[i] > 0.0f ? 1u : 0u;
    const unsigned crule = internal::vertex_rule(cvs[v], sharp_children);
    if (crule == prule && prule == internal::rule_corner) {
      cls = corner_class();
      continue;
    }
    // The mask of a rule, its crease ends taken from sharpness `sv`.
    auto assign = [&](Vertex_weights<W>& x, unsigned rule, const std::vector<float>& sv) {
      if (rule == internal::rule_corner) {
        corner_mask(x);
      } else if (rule == internal::rule_crease) {
        u32 ends[2] = {null_u32, null_u32};
        for (std::size_t i = 0, j = 0; i < m && j < 2; ++i)
          if (sv[i] > 0.0f)
            ends[j++] = ring_u_[i];
        crease_mask(x, ends[0], ends[1]);
      } else {
        smooth_mask(x, n);
      }
    };
    Vertex_weights<W> w{};
    assign(w, prule, ring_s_);
    if (crule != prule) {
      // OpenSubdiv's fractional weight: the mean sharpness of what
      // becomes smooth in the child level, clamped to 1 (float).
      unsigned count = 0;
      float sum = 0.0f;
      if (vs > 0.0f && cvs[v] <= 0.0f) {
        count = 1;
        sum = vs;
      }
      for (std::size_t i = 0; i < m; ++i) {
        if (ring_s_[i] > 0.0f && ring_cs_[i] <= 0.0f) {
          sum += ring_s_[i];
          ++count;
        }
      }
      float frac = count ? sum / float(count) : 0.0f;
      if (frac > 1.0f)
        frac = 1.0f;
      Vertex_weights<W> child{};
      assign(child, crule, ring_cs_);
      const W pw = W(double(frac)), cw = W(1) - pw;
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
    cls = sw.add(w);
  }
  child_sharp_ = child_sharp;
  if (child_sharp) {
    std::fill(cvs + nv, cvs + child_nv, 0.0f);
  } else {
    decltype(child_e_sharp_)().swap(child_e_sharp_);
    decltype(child_v_sharp_)().swap(child_v_sharp_);
  }
}

template <class Mask, class W>
template <class Value>
void Refiner<Mask, W>::interpolate_level(unsigned k, const Value* src, Value* dst) const
{
  using internal::null_u32;
  if constexpr (uses_stencils) {
    const internal::Stencils<W>& st = stencils_[k];
    for (u32 i = 0, n = st.size(); i < n; ++i)
      dst[i] = stencil_point(st, i, src);
    return;
  }
  const Level& p = levels_[k];
  const internal::Step_weights<W>& sw = weights_[k];
  const u32 nv = p.nv, ne = p.ne, nf = p.nf;
  const u32 fp = nv + ne;

  if constexpr (Mask::split == Split::quad) {
    for (u32 f = 0; f < nf; ++f)
      dst[fp + f] = face_point(p, f, src);
  }
  for (u32 v = 0; v < nv; ++v) {
    const Vertex_weights<W>& w = sw.vertex(v);
    dst[v] = w.vertex * src[v];
    if (w.terms & 8)
      dst[v] = dst[v] + w.crease * (src[w.crease_ends[0]] + src[w.crease_ends[1]]);
  }
  for (u32 e = 0; e < ne; ++e) {
    const u32 a = p.source(4 * e), b = p.h_target[2 * e];
    const Value x = edge_point(p, sw.edge(e), e, src, dst + fp);
    dst[nv + e] = x;
    const Vertex_weights<W>&wa = sw.vertex(a), &wb = sw.vertex(b);
    if (wa.terms & 1)
      dst[a] = dst[a] + wa.edge * src[b];
    if (wb.terms & 1)
      dst[b] = dst[b] + wb.edge * src[a];
    if (wa.terms & 4)
      dst[a] = dst[a] + wa.edge_point * x;
    if (wb.terms & 4)
      dst[b] = dst[b] + wb.edge_point * x;
  }
  if constexpr (Mask::split == Split::quad) {
    for (u32 f = 0; f < nf; ++f) {
      for (u32 i = p.f_offset[f], i1 = p.f_offset[f + 1]; i < i1; ++i) {
        const u32 v = p.h_target[p.corner_h[i]];
        const Vertex_weights<W>& w = sw.vertex(v);
        if (w.terms & 2)
          dst[v] = dst[v] + w.face * dst[fp + f];
      }
    }
  }
}

template <class Mask, class W>
template <class ConcurrencyTag, class Value>
void Refiner<Mask, W>::interpolate_level(unsigned k, const Value* src, Value* dst) const
{
  using internal::null_u32;
  if constexpr (!std::is_convertible_v<ConcurrencyTag, CGAL::Parallel_tag>) {
    interpolate_level(k, src, dst);
  } else if (!uses_stencils && levels_[k].nv < options_.parallel_min_vertices) {
    interpolate_level(k, src, dst);
  } else if constexpr (uses_stencils) {
    const internal::Stencils<W>& st = stencils_[k];
    internal::for_each_index<ConcurrencyTag>(st.size(), [&](u32 i) { dst[i] = stencil_point(st, i, src); });
  } else {
    const Level& p = levels_[k];
    const internal::Step_weights<W>& sw = weights_[k];
    const u32 nv = p.nv, ne = p.ne, nf = p.nf;
    const u32 fp = nv + ne;
    if (incidence_.size() != weights_.size())
      incidence_.assign(weights_.size(), internal::Incidence());
    internal::Incidence& inc = incidence_[k];
    if (inc.edge_offset.empty()) {
      inc.edge_offset.assign(nv + 1, 0);
      for (u32 e = 0; e < ne; ++e) {
        ++inc.edge_offset[p.source(4 * e) + 1];
        ++inc.edge_offset[p.h_target[2 * e] + 1];
      }
      for (u32 v = 0; v < nv; ++v)
        inc.edge_offset[v + 1] += inc.edge_offset[v];
      inc.edges.resize(2 * std::size_t(ne));
      std::vector<u32> fill(inc.edge_offset.begin(), inc.edge_offset.end() - 1);
      for (u32 e = 0; e < ne; ++e) {
        inc.edges[fill[p.source(4 * e)]++] = e;
        inc.edges[fill[p.h_target[2 * e]]++] = e;
      }
      inc.face_offset.assign(nv + 1, 0);
      for (u32 c = 0; c < p.nc; ++c)
        ++inc.face_offset[p.h_target[p.corner_h[c]] + 1];
      for (u32 v = 0; v < nv; ++v)
        inc.face_offset[v + 1] += inc.face_offset[v];
      inc.faces.resize(p.nc);
      fill.assign(inc.face_offset.begin(), inc.face_offset.end() - 1);
      for (u32 f = 0; f < nf; ++f)
        for (u32 c = p.f_offset[f]; c < p.f_offset[f + 1]; ++c)
          inc.faces[fill[p.h_target[p.corner_h[c]]]++] = f;
    }

    // The serial pass's three loops as gathers, in the same order of terms.
    if constexpr (Mask::split == Split::quad)
      internal::for_each_index<ConcurrencyTag>(nf, [&](u32 f) { dst[fp + f] = face_point(p, f, src); });
    internal::for_each_index<ConcurrencyTag>(
      ne, [&](u32 e) { dst[nv + e] = edge_point(p, sw.edge(e), e, src, dst + fp); });
    internal::for_each_index<ConcurrencyTag>(nv, [&](u32 v) {
      const Vertex_weights<W>& w = sw.vertex(v);
      Value x = w.vertex * src[v];
      if (w.terms & 8)
        x = x + w.crease * (src[w.crease_ends[0]] + src[w.crease_ends[1]]);
      for (u32 i = inc.edge_offset[v]; i < inc.edge_offset[v + 1]; ++i) {
        const u32 e = inc.edges[i];
        const u32 a = p.source(4 * e);
        if (w.terms & 1)
          x = x + w.edge * src[a == v ? p.h_target[2 * e] : a];
        if (w.terms & 4)
          x = x + w.edge_point * dst[nv + e];
      }
      if (w.terms & 2)
        for (u32 i = inc.face_offset[v]; i < inc.face_offset[v + 1]; ++i)
          x = x + w.face * dst[fp + inc.faces[i]];
      dst[v] = x;
    });
  }
}

template <class Mask, class W>
template <class P>
void Refiner<Mask, W>::build_mesh(Mobius_mesh<P>& out, bool write_sharpness) const
{
  const Level& L = levels_.back();
  // The level already holds the mesh's arrays, index for index.
  out.clear();
  CGAL_ext::internal::Connectivity_access::assign(out, L.nv, L.ne, L.nf, L.h_target.data(), L.h_next.data(),
                                                  L.h_prev.data(), L.h_face.data(), L.e_mobius.data(), L.v_dart.data(),
                                                  L.f_first.data());
  if (write_sharpness)
    add_sharpness_maps(out, L.sharp ? L.e_sharp.data() : nullptr, L.sharp ? L.v_sharp.data() : nullptr);
  add_hole_map(out, L.f_hole);
}

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_REFINER_H
