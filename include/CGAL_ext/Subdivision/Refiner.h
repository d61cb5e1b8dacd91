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
    edge_weights_.resize(uses_stencils ? 0 : levels);
    vertex_weights_.resize(uses_stencils ? 0 : levels);
    stencils_.resize(uses_stencils ? levels : 0);
    build_base(mesh, edge_sharpness, vertex_sharpness);
    for (unsigned k = 0; k < levels; ++k)
      step(k, k);
  }

  /// Refines `mesh` `levels` times and interpolates `values` (one per vertex
  /// of `mesh`, replaced by one per vertex of the result) on the way, keeping
  /// only two levels at a time: less memory and faster than `refine()` then
  /// `interpolate()`, for when nothing else is to be interpolated.
  /// Afterwards `build_mesh()` gives the result's connectivity and
  /// `number_of_levels()` is 0.
  /// `Values` is a `std::vector` of any value type and allocator.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class P, class Values>
  void refine_and_interpolate(const Mobius_mesh<P>& mesh, unsigned levels, Values& values,
                              const std::vector<float>& edge_sharpness = {},
                              const std::vector<float>& vertex_sharpness = {})
  {
    using Value = typename Values::value_type;
    levels_.resize(levels == 0 ? 1 : 2);
    build_base(mesh, edge_sharpness, vertex_sharpness);
    Values next;
    for (unsigned k = 0; k < levels; ++k) {
      step<ConcurrencyTag>(0, k);
      next.clear(); // the previous level's values are not needed: nothing to copy on growth
      next.resize(levels_[1].nv);
      interpolate_level<ConcurrencyTag>(0, values.data(), next.data());
      Value* dst = next.data();
      internal::for_each_index<ConcurrencyTag>(levels_[1].nv, [&](u32 v) { internal::normalize_value(dst[v], 0); });
      values.swap(next);
      std::swap(levels_[0], levels_[1]);
    }
    levels_.resize(1);
    edge_weights_.clear();
    vertex_weights_.clear();
    stencils_.clear();
    incidence_.clear();
  }

  /// The number of refinement steps done by the last `refine()`.
  unsigned number_of_levels() const { return levels_.empty() ? 0u : unsigned(levels_.size() - 1); }
  /// The topology of level `k` (0 is the base mesh).
  const Level& level(unsigned k) const { return levels_[k]; }
  /// The weights of step `k` (primal schemes: quad and triangle splits).
  const std::vector<Edge_weights<W>>& edge_weights(unsigned k) const { return edge_weights_[k]; }
  const std::vector<Vertex_weights<W>>& vertex_weights(unsigned k) const { return vertex_weights_[k]; }
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

  /// As `build_mesh()`, but hands the last level's arrays over one by one,
  /// freeing each as soon as it is copied: the refiner is empty afterwards.
  template <class P>
  void release_mesh(Mobius_mesh<P>& out, bool write_sharpness);

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
      if (edge_weights_.size() < slot + 1) {
        edge_weights_.resize(slot + 1);
        vertex_weights_.resize(slot + 1);
      }
      if constexpr (Mask::split == Split::quad)
        internal::quad_split<ConcurrencyTag>(levels_[slot], levels_[slot + 1]);
      else
        internal::triangle_split<ConcurrencyTag>(levels_[slot], levels_[slot + 1]);
      compute_weights<ConcurrencyTag>(slot);
    }
  }

  template <class P>
  void build_base(const Mobius_mesh<P>& mesh, const std::vector<float>& es, const std::vector<float>& vs);
  template <class ConcurrencyTag>
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
  std::vector<std::vector<Edge_weights<W>>> edge_weights_;
  std::vector<std::vector<Vertex_weights<W>>> vertex_weights_;
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
}

template <class Mask, class W>
template <class ConcurrencyTag>
void Refiner<Mask, W>::compute_weights(unsigned k)
{
  using internal::null_u32;
  const Level& p = levels_[k];
  Level& c = levels_[k + 1];
  const u32 nv = p.nv, ne = p.ne;
  const bool chaikin = options_.crease_method == Crease_method::chaikin;

  valence_.assign(nv, 0);
  sharp_count_.assign(nv, 0);
  semi_count_.assign(nv, 0);
  semi_sum_.assign(nv, 0.0f);
  for (u32 e = 0; e < ne; ++e) {
    const u32 a = p.source(4 * e), b = p.h_target[2 * e];
    ++valence_[a];
    ++valence_[b];
    const float s = p.e_sharp[e];
    if (s > 0.0f) {
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

  // Edges, each on its own.
  auto& ew = edge_weights_[k];
  ew.resize(ne);
  internal::for_each_index<ConcurrencyTag>(ne, [&](u32 e) {
    const float s = p.e_sharp[e];
    Edge_weights<W>& w = ew[e];
    float sa = 0.0f, sb = 0.0f;
    if (s > 0.0f) {
      sa = child_sharpness(s, p.source(4 * e));
      sb = child_sharpness(s, p.h_target[2 * e]);
    }
    const bool crease = Mask::creases && s > 0.0f && (s >= 1.0f || (chaikin && sa > 0.0f && sb > 0.0f));
    if (crease) {
      w.vertex = W(0.5);
      w.face = W(0);
    } else {
      const u32 f0 = p.h_face[2 * e], f1 = p.h_face[2 * e + 1];
      mask_.smooth_edge(f0 == null_u32 ? 0u : p.degree(f0), f1 == null_u32 ? 0u : p.degree(f1), w);
      if (Mask::creases && s > 0.0f) {
        // Semi-sharp edge decaying to smooth: OpenSubdiv's blend, with the
        // parent sharpness as weight (not clamped).
        const W pw = W(double(s)), cw = W(1) - pw;
        w.vertex = pw * W(0.5) + cw * w.vertex;
        w.face = cw * w.face;
      }
    }
    w.has_face = !CGAL::is_zero(w.face);
    c.e_sharp[2 * e] = sa;
    c.e_sharp[2 * e + 1] = sb;
  });
  for (u32 e = 2 * ne; e < c.ne; ++e)
    c.e_sharp[e] = 0.0f;

  // Vertices.
  auto& vw = vertex_weights_[k];
  vw.resize(nv);
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
  for (u32 v = 0; v < nv; ++v) {
    Vertex_weights<W>& w = vw[v];
    const float vs = p.v_sharp[v];
    c.v_sharp[v] = internal::decrement_sharpness(vs);
    const u32 n = valence_[v];
    if (n == 0) {
      corner_mask(w);
    } else if (!Mask::creases || (vs <= 0.0f && sharp_count_[v] == 0)) {
      smooth_mask(w, n);
    } else {
      const unsigned prule = internal::vertex_rule(vs, sharp_count_[v]);
      if (prule == internal::rule_smooth || prule == internal::rule_dart) {
        smooth_mask(w, n);
      } else {
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
        u32 child_sharp = 0;
        for (std::size_t i = 0; i < m; ++i)
          child_sharp += ring_cs_[i] > 0.0f ? 1u : 0u;
        const float cvs = c.v_sharp[v];
        const unsigned crule = internal::vertex_rule(cvs, child_sharp);
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
        assign(w, prule, ring_s_);
        if (crule != prule) {
          // OpenSubdiv's fractional weight: the mean sharpness of what
          // becomes smooth in the child level, clamped to 1 (float).
          unsigned count = 0;
          float sum = 0.0f;
          if (vs > 0.0f && cvs <= 0.0f) {
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
          Vertex_weights<W> child;
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
      }
    }
    w.terms = std::uint8_t((CGAL::is_zero(w.edge) ? 0 : 1) | (CGAL::is_zero(w.face) ? 0 : 2) |
                           (CGAL::is_zero(w.edge_point) ? 0 : 4) | (CGAL::is_zero(w.crease) ? 0 : 8));
  }
  for (u32 v = nv; v < c.nv; ++v)
    c.v_sharp[v] = 0.0f;
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
  const auto& ew = edge_weights_[k];
  const auto& vw = vertex_weights_[k];
  const u32 nv = p.nv, ne = p.ne, nf = p.nf;
  const u32 fp = nv + ne;

  if constexpr (Mask::split == Split::quad) {
    for (u32 f = 0; f < nf; ++f)
      dst[fp + f] = face_point(p, f, src);
  }
  for (u32 v = 0; v < nv; ++v) {
    const Vertex_weights<W>& w = vw[v];
    dst[v] = w.vertex * src[v];
    if (w.terms & 8)
      dst[v] = dst[v] + w.crease * (src[w.crease_ends[0]] + src[w.crease_ends[1]]);
  }
  for (u32 e = 0; e < ne; ++e) {
    const u32 a = p.source(4 * e), b = p.h_target[2 * e];
    const Value x = edge_point(p, ew[e], e, src, dst + fp);
    dst[nv + e] = x;
    const Vertex_weights<W>&wa = vw[a], &wb = vw[b];
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
        if (vw[v].terms & 2)
          dst[v] = dst[v] + vw[v].face * dst[fp + f];
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
  } else if constexpr (uses_stencils) {
    const internal::Stencils<W>& st = stencils_[k];
    internal::for_each_index<ConcurrencyTag>(st.size(), [&](u32 i) { dst[i] = stencil_point(st, i, src); });
  } else {
    const Level& p = levels_[k];
    const auto& ew = edge_weights_[k];
    const auto& vw = vertex_weights_[k];
    const u32 nv = p.nv, ne = p.ne, nf = p.nf;
    const u32 fp = nv + ne;
    if (incidence_.size() != edge_weights_.size())
      incidence_.assign(edge_weights_.size(), internal::Incidence());
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
      ne, [&](u32 e) { dst[nv + e] = edge_point(p, ew[e], e, src, dst + fp); });
    internal::for_each_index<ConcurrencyTag>(nv, [&](u32 v) {
      const Vertex_weights<W>& w = vw[v];
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
void Refiner<Mask, W>::release_mesh(Mobius_mesh<P>& out, bool write_sharpness)
{
  using internal::null_u32;
  Level& L = levels_.back();
  // What the mesh does not need goes first.
  decltype(L.h_corner)().swap(L.h_corner);
  decltype(L.corner_h)().swap(L.corner_h);
  decltype(L.f_offset)().swap(L.f_offset);
  out.clear();
  std::vector<float> edge_sharpness, vertex_sharpness;
  if (write_sharpness) {
    edge_sharpness.resize(L.ne);
    for (u32 e = 0; e < L.ne; ++e)
      edge_sharpness[e] = (L.h_face[2 * e] == null_u32 || L.h_face[2 * e + 1] == null_u32) ? 0.0f : L.e_sharp[e];
    vertex_sharpness.assign(L.v_sharp.begin(), L.v_sharp.end());
  }
  decltype(L.e_sharp)().swap(L.e_sharp);
  decltype(L.v_sharp)().swap(L.v_sharp);
  internal::Array<std::uint8_t> holes;
  holes.swap(L.f_hole);
  const u32 nv = L.nv, ne = L.ne, nf = L.nf;
  out.assign_connectivity_releasing(nv, ne, nf, L.h_target, L.h_next, L.h_prev, L.h_face, L.e_mobius, L.v_dart,
                                    L.f_first);
  if (write_sharpness) {
    out.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first.data().swap(edge_sharpness);
    out.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first.data().swap(
      vertex_sharpness);
  }
  if (!holes.empty()) {
    auto map = out.template add_property_map<Face_index, std::uint8_t>("f:hole", 0).first;
    for (u32 f = 0; f < nf; ++f)
      map[Face_index(f)] = holes[f];
  }
  levels_.clear();
  edge_weights_.clear();
  vertex_weights_.clear();
  stencils_.clear();
  incidence_.clear();
}

template <class Mask, class W>
template <class P>
void Refiner<Mask, W>::build_mesh(Mobius_mesh<P>& out, bool write_sharpness) const
{
  using internal::null_u32;
  const Level& L = levels_.back();
  // The level already holds the mesh's arrays, index for index.
  out.clear();
  out.assign_connectivity(L.nv, L.ne, L.nf, L.h_target.data(), L.h_next.data(), L.h_prev.data(), L.h_face.data(),
                          L.e_mobius.data(), L.v_dart.data(), L.f_first.data());
  if (write_sharpness) {
    auto es = out.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first;
    auto vs = out.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first;
    for (u32 e = 0; e < L.ne; ++e)
      es[Edge_index(e)] =
        (L.h_face[2 * e] == null_u32 || L.h_face[2 * e + 1] == null_u32) ? 0.0f : L.e_sharp[e];
    for (u32 v = 0; v < L.nv; ++v)
      vs[Vertex_index(v)] = L.v_sharp[v];
  }
  if (!L.f_hole.empty()) {
    auto holes = out.template add_property_map<Face_index, std::uint8_t>("f:hole", 0).first;
    for (u32 f = 0; f < L.nf; ++f)
      holes[Face_index(f)] = L.f_hole[f];
  }
}

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_REFINER_H
