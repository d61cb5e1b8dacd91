// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The crease rules of subdivision as pure functions of a few numbers, as
// OpenSubdiv's Sdc::Crease: how sharpness decays from one level to the next,
// which rule a vertex follows, and the weight that blends two rules where a
// semi-sharp feature decays to smooth. They know nothing of meshes or masks,
// so each can be checked on its own against OpenSubdiv.

#ifndef CGAL_EXT_SUBDIVISION_CREASE_H
#define CGAL_EXT_SUBDIVISION_CREASE_H

#include <CGAL_ext/Sharp_feature_options.h>

namespace CGAL_ext {
namespace Subdivision {

/// \ingroup PkgSubdivision
///
/// Crease rules shared by every scheme with creases (OpenSubdiv's
/// `Sdc::Crease`). Sharpness is a `float`, and so is the arithmetic, as in
/// OpenSubdiv: values `<= 0` are smooth, values `>= infinitely_sharp` (10)
/// are infinitely sharp, the ones between are semi-sharp.
namespace Crease {

/// The subdivision rule of a vertex, from its sharpness and its sharp edges.
enum class Rule {
  smooth, ///< no sharp edge: the smooth mask
  dart,   ///< one sharp edge: the smooth mask too
  crease, ///< two sharp edges: ¾ V + ⅛ (A + B), A and B the far ends of the two edges
  corner  ///< a sharp vertex, or more than two sharp edges: V stays
};

/// Whether sharpness `s` is smooth (`s <= 0`).
constexpr bool is_smooth(float s) { return s <= 0.0f; }
/// Whether sharpness `s` is sharp (`s > 0`), semi-sharp or infinite.
constexpr bool is_sharp(float s) { return s > 0.0f; }
/// Whether sharpness `s` is infinite (`s >= infinitely_sharp`).
constexpr bool is_infinite(float s) { return s >= infinitely_sharp; }
/// Whether sharpness `s` is semi-sharp: sharp, and not infinitely.
constexpr bool is_semi_sharp(float s) { return is_sharp(s) && !is_infinite(s); }

/// The uniform decay of an edge or vertex sharpness to the next level
/// (OpenSubdiv's `SubdivideUniformSharpness`): smooth stays 0, infinite stays
/// `infinitely_sharp`, and a semi-sharp `s` becomes `s - 1`, clamped at 0.
constexpr float subdivide_uniform_sharpness(float s)
{
  if (is_smooth(s))
    return 0.0f;
  if (is_infinite(s))
    return infinitely_sharp;
  return s > 1.0f ? s - 1.0f : 0.0f;
}

/// The sharpness of a vertex at the next level (OpenSubdiv's
/// `SubdivideVertexSharpness`): the uniform decay, whatever the crease method.
constexpr float subdivide_vertex_sharpness(float s) { return subdivide_uniform_sharpness(s); }

/// The semi-sharp edges around a vertex, as the Chaikin rule needs them:
/// their number and the sum of their sharpnesses. The sum is formed in the
/// order of the calls to `add()` (float arithmetic, so order matters).
struct Semi_sharp_edges
{
  /// The sum of the semi-sharp sharpnesses added.
  float sum = 0.0f;
  /// The number of semi-sharp edges added.
  unsigned count = 0;

  /// Counts edge sharpness `s` if it is semi-sharp.
  void add(float s)
  {
    if (is_semi_sharp(s)) {
      sum += s;
      ++count;
    }
  }
};

/// The sharpness of the child of an edge of sharpness `s`, the child that
/// lies at the edge's end vertex `v` (OpenSubdiv's
/// `SubdivideEdgeSharpnessAtVertex`). `valence` is the number of edges at
/// `v` and `around` the semi-sharp ones among them (`s` included, if
/// semi-sharp).
///
/// Uniform: the uniform decay. Chaikin: if `v` has fewer than two edges, the
/// uniform decay; smooth and infinite values stay; otherwise, if `v` has
/// other semi-sharp edges, `s` is first replaced by ¾ s + ¼ (the mean of
/// the other semi-sharp edges), then decremented by 1 and clamped at 0.
inline float subdivide_edge_sharpness_at_vertex(Crease_method method, float s, unsigned valence,
                                                const Semi_sharp_edges& around)
{
  if (method == Crease_method::uniform || valence < 2)
    return subdivide_uniform_sharpness(s);
  if (is_smooth(s))
    return 0.0f;
  if (is_infinite(s))
    return infinitely_sharp;
  if (around.count > 1) {
    const float average = (around.sum - s) / float(around.count - 1);
    s = 0.75f * s + 0.25f * average;
  }
  s -= 1.0f;
  return is_sharp(s) ? s : 0.0f;
}

/// As above, with the sharpnesses of the `valence` edges at the end vertex
/// given one by one (OpenSubdiv's signature); their semi-sharp sum is formed
/// in the order of `incident`.
inline float subdivide_edge_sharpness_at_vertex(Crease_method method, float s, unsigned valence,
                                                const float* incident)
{
  Semi_sharp_edges around;
  if (method == Crease_method::chaikin)
    for (unsigned i = 0; i < valence; ++i)
      around.add(incident[i]);
  return subdivide_edge_sharpness_at_vertex(method, s, valence, around);
}

/// The rule of a vertex of sharpness `vertex_sharpness` with `sharp_edges`
/// sharp incident edges (OpenSubdiv's `DetermineVertexVertexRule`): a corner
/// if the vertex is sharp or has more than two sharp edges, else smooth,
/// dart or crease for 0, 1 or 2 sharp edges.
constexpr Rule vertex_rule(float vertex_sharpness, unsigned sharp_edges)
{
  if (is_sharp(vertex_sharpness) || sharp_edges > 2)
    return Rule::corner;
  return sharp_edges == 0 ? Rule::smooth : (sharp_edges == 1 ? Rule::dart : Rule::crease);
}

/// As above, from the sharpnesses of the `valence` incident edges.
inline Rule vertex_rule(float vertex_sharpness, unsigned valence, const float* incident)
{
  unsigned sharp_edges = 0;
  for (unsigned i = 0; i < valence; ++i)
    sharp_edges += is_sharp(incident[i]) ? 1u : 0u;
  return vertex_rule(vertex_sharpness, sharp_edges);
}

/// The weight of the parent rule where a vertex's rule changes from one
/// level to the next (OpenSubdiv's `ComputeFractionalWeightAtVertex`): the
/// mean sharpness of what becomes smooth, the vertex itself (if `parent_vertex`
/// is sharp and `child_vertex` smooth) and each incident edge `i` with
/// `parent_edges[i]` sharp and `child_edges[i]` smooth, clamped to 1; 0 if
/// nothing becomes smooth. The child point is then
/// `w · M_parent + (1 − w) · M_child`. The mean is formed in float, in this order.
inline float fractional_weight_at_vertex(float parent_vertex, float child_vertex, unsigned valence,
                                         const float* parent_edges, const float* child_edges)
{
  unsigned count = 0;
  float sum = 0.0f;
  if (is_sharp(parent_vertex) && is_smooth(child_vertex)) {
    count = 1;
    sum = parent_vertex;
  }
  for (unsigned i = 0; i < valence; ++i) {
    if (is_sharp(parent_edges[i]) && is_smooth(child_edges[i])) {
      sum += parent_edges[i];
      ++count;
    }
  }
  if (count == 0)
    return 0.0f;
  const float weight = sum / float(count);
  return weight > 1.0f ? 1.0f : weight;
}

/// Whether the child point of an edge of sharpness `s` takes the crease mask
/// ½ (a + b), given the sharpness of its two children `child_a` and `child_b`
/// (at either end); otherwise it takes the smooth mask, blended with the
/// crease mask by `s` (unclamped) if `s > 0`. As OpenSubdiv's refiner decides
/// it: the crease mask where the child point is a crease vertex, both
/// children sharp. Sharpness 1 blends to exactly the crease mask; with
/// uniform decay both children of a sharper edge are sharp. With Chaikin's
/// decay an edge sharper than 1 can lose one child (a weaker semi-sharp edge
/// at that end): its point is then the blend, which extrapolates past the
/// crease mask, as in OpenSubdiv.
inline bool edge_point_is_crease(Crease_method method, float s, float child_a, float child_b)
{
  if (!is_sharp(s))
    return false;
  if (s == 1.0f || (method == Crease_method::uniform && s > 1.0f))
    return true;
  return method == Crease_method::chaikin && is_sharp(child_a) && is_sharp(child_b);
}

} // namespace Crease
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_CREASE_H
