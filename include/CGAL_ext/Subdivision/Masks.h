// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Subdivision masks: policy classes that give the smooth rules of a scheme.
// The refiner owns the topology, the crease and border rules and the blend
// between them, as OpenSubdiv's Sdc::Scheme does; a mask only says how a
// smooth edge point and a smooth vertex point are made.

#ifndef CGAL_EXT_SUBDIVISION_MASKS_H
#define CGAL_EXT_SUBDIVISION_MASKS_H

#include <CGAL_ext/Sharp_feature_options.h>

#include <cmath>
#include <cstdint>

namespace CGAL_ext {
namespace Subdivision {

/// How a scheme changes the topology.
enum class Split {
  quad,     ///< a face of n sides into n quads around a face point (Catmull–Clark, bilinear)
  triangle, ///< a triangle into four (Loop); triangle meshes only
  dual,     ///< a new vertex per face corner; a face per face, edge and vertex (Doo–Sabin)
  sqrt3     ///< a new vertex per triangle, old edges flipped (Kobbelt's √3); triangle meshes only
};

namespace internal {

// 2 cos(2πk/n) as an integer when it is one (n | 12k and the angle a
// multiple of π/3 or π/2), so that exact kernels get exact weights for the
// common valences 3, 4 and 6.
inline bool integer_two_cos(unsigned k, unsigned n, int& value)
{
  if ((12 * k) % n != 0)
    return false;
  static const int table[12] = {2, 0, 1, 0, -1, 0, -2, 0, -1, 0, 1, 0};
  const unsigned m = (12 * k / n) % 12;
  if (m % 2 == 1 && m != 3 && m != 9)
    return false; // ±√3
  value = table[m];
  return true;
}

template <class W>
W two_cos(unsigned k, unsigned n)
{
  int v;
  if (integer_two_cos(k, n, v))
    return W(v);
  return W(2.0 * std::cos(2.0 * M_PI * double(k) / double(n)));
}

} // namespace internal

// The option enums live in namespace CGAL_ext (Sharp_features.h), all in one
// place; they are also reachable by their subdivision names.
using CGAL_ext::Boundary_interpolation;
using CGAL_ext::Crease_method;
using CGAL_ext::Triangle_subdivision;
using CGAL_ext::Vertex_rule;
using CGAL_ext::Face_varying_interpolation;

/// The weights that make the child of a parent edge with ends `a`, `b`:
/// `vertex * (a + b) + face * (F0 + F1)`, where `F0`, `F1` are the face
/// points of the two faces (quad split) or the vertices opposite the edge
/// (triangle split).
template <class W>
struct Edge_weights
{
  W vertex, face;
  bool has_face; ///< false if `face` is zero (set by the refiner)
};

/// \var Edge_weights::vertex
/// The weight of each end of the edge.

/// \var Edge_weights::face
/// The weight of each face point (quad split) or opposite vertex (triangle split).

/// The weights that make the child of a parent vertex `V`:
/// `vertex * V + edge * Σ neighbours + face * Σ face points`
/// `+ edge_point * Σ new edge points + crease * (A + B)`,
/// where `A`, `B` are the far ends of the two crease edges (`crease_ends`).
template <class W>
struct Vertex_weights
{
  W vertex, edge, face, edge_point, crease;
  std::uint32_t crease_ends[2];
  // Which sums are non-zero, so that the interpolation skips the others (set by the refiner).
  bool has_edge;       ///< `edge` is not zero
  bool has_face;       ///< `face` is not zero
  bool has_edge_point; ///< `edge_point` is not zero
  bool has_crease;     ///< `crease` is not zero
};

/// \var Vertex_weights::vertex
/// The weight of the parent vertex `V`.

/// \var Vertex_weights::edge
/// The weight of each neighbour of `V` (the far end of each incident edge).

/// \var Vertex_weights::face
/// The weight of each face point of the faces around `V`.

/// \var Vertex_weights::edge_point
/// The weight of each new edge point of the edges around `V`.

/// \var Vertex_weights::crease
/// The weight of each of the two crease neighbours `A`, `B`.

/// \var Vertex_weights::crease_ends
/// The vertices `A`, `B` at the far ends of the two crease edges of `V`.

/*!
\ingroup PkgSubdivisionConcepts
\cgalConcept

A `SubdivisionMask` gives the smooth rules of a subdivision scheme, in
weights of a number type `W` (`double`, or the exact field type of an exact
kernel). Crease, corner and border rules, and the fractional blend of
semi-sharp features, are the same for every scheme and applied by
`Refiner`; a mask whose smooth rules are the crease rules (bilinear) makes
every edge and vertex behave as sharp.

\code
struct SubdivisionMask {
  static constexpr Split split;             // how faces are split
  static constexpr bool creases;            // false: crease, corner and border rules are not applied
  // Smooth edge with two faces of `d0` and `d1` sides.
  template <class W> void smooth_edge(unsigned d0, unsigned d1, Edge_weights<W>& w) const;
  // Smooth interior vertex of valence `n` (n edges, n faces); zero all weights first.
  template <class W> void smooth_vertex(unsigned n, Vertex_weights<W>& w) const;
};
\endcode

\cgalHasModel `Catmull_clark_mask`, `Loop_mask`, `Bilinear_mask`, `Linear_mask`, `Sqrt3_mask`

A `Sqrt3_mask` (`split == Split::sqrt3`) uses only `smooth_vertex()`, with
`vertex` and `edge` weights; its face points are centroids and its border
rules are Kobbelt's.

A mask with `split == Split::dual` (Doo–Sabin) instead provides

\code
  // Weights of the n vertices of a face, starting at the corner's vertex
  // and following the face, for the new point of that corner.
  template <class W> void corner(unsigned n, W* weights) const;
\endcode
*/

/// \ingroup PkgSubdivision
/// Catmull–Clark, with OpenSubdiv's rules; the vertex rule and the
/// "smooth triangle" option are settings.
struct Catmull_clark_mask
{
  /// How faces are split (see `SubdivisionMask`).
  static constexpr Split split = Split::quad;
  /// True: crease, corner and border rules apply.
  static constexpr bool creases = true;
  /// The smooth vertex rule (named parameter `vertex_rule`).
  Vertex_rule vertex_rule = Vertex_rule::standard;
  /// The edge rule next to triangles (named parameter `triangle_subdivision`).
  Triangle_subdivision triangle_subdivision = Triangle_subdivision::catmark;

  /// The smooth edge rule: ¼ of each end and of each face point, or
  /// OpenSubdiv's smooth-triangle weights next to a triangle.
  template <class W>
  void smooth_edge(unsigned d0, unsigned d1, Edge_weights<W>& w) const
  {
    if (triangle_subdivision == Triangle_subdivision::smooth && (d0 == 3 || d1 == 3)) {
      // OpenSubdiv's TRI_SUB_SMOOTH, with its order of operations.
      const W f0 = d0 == 3 ? W(0.470) : W(0.25), f1 = d1 == 3 ? W(0.470) : W(0.25);
      const W f = W(0.5) * (f0 + f1);
      w.vertex = W(0.5) * (W(1) - W(2) * f);
      w.face = f;
      return;
    }
    w.vertex = W(0.25);
    w.face = W(0.25);
  }

  /// The smooth vertex rule: (n−2)/n of `V` and 1/n² of each neighbour (or
  /// new edge point) and face point.
  template <class W>
  void smooth_vertex(unsigned n, Vertex_weights<W>& w) const
  {
    w.vertex = W(int(n) - 2) / W(int(n));
    w.face = W(1) / W(int(n * n));
    if (vertex_rule == Vertex_rule::standard)
      w.edge = w.face;
    else
      w.edge_point = w.face;
  }
};

/// \ingroup PkgSubdivision
/// Loop subdivision of triangle meshes, with OpenSubdiv's rules.
struct Loop_mask
{
  /// How faces are split (see `SubdivisionMask`).
  static constexpr Split split = Split::triangle;
  /// True: crease, corner and border rules apply.
  static constexpr bool creases = true;

  /// The smooth edge rule: ⅜ of each end, ⅛ of each opposite vertex.
  template <class W>
  void smooth_edge(unsigned, unsigned, Edge_weights<W>& w) const
  {
    w.vertex = W(0.375);
    w.face = W(0.125);
  }

  /// The smooth vertex rule: Loop's β(n) for each neighbour, exact for
  /// valences 3 and 6.
  template <class W>
  void smooth_vertex(unsigned n, Vertex_weights<W>& w) const
  {
    if (n == 6) {
      w.vertex = W(0.625);
      w.edge = W(0.0625);
      return;
    }
    if (n == 3) {
      // cos(2π/3) = −1/2 exactly: β = 1/4, e = 3/16 (Loop's own valence-3 weights)
      w.edge = W(3) / W(16);
      w.vertex = W(1) - W(3) * w.edge;
      return;
    }
    // OpenSubdiv's double arithmetic for the irregular case.
    const double dn = double(n), inv = 1.0 / dn;
    const double beta = 0.25 * std::cos(M_PI * 2.0 * inv) + 0.375;
    const double e = (0.625 - beta * beta) * inv;
    w.edge = W(e);
    w.vertex = W(1.0 - e * dn);
  }
};

/// \ingroup PkgSubdivision
/// Bilinear subdivision (quad split, new points at edge midpoints and face
/// centroids, old points kept), as OpenSubdiv's bilinear scheme: sharpness
/// and borders change nothing.
struct Bilinear_mask
{
  /// How faces are split (see `SubdivisionMask`).
  static constexpr Split split = Split::quad;
  /// False: sharpness and borders change nothing.
  static constexpr bool creases = false;

  /// The edge midpoint.
  template <class W>
  void smooth_edge(unsigned, unsigned, Edge_weights<W>& w) const
  {
    w.vertex = W(0.5);
    w.face = W(0);
  }
  /// The old point, kept.
  template <class W>
  void smooth_vertex(unsigned, Vertex_weights<W>& w) const
  {
    w.vertex = W(1);
  }
};

/// \ingroup PkgSubdivision
/// Linear (midpoint) subdivision of triangle meshes: each triangle into four,
/// new points at edge midpoints, old points kept (CGAL's `Linear_mask_3`
/// with `PTQ`). As with `Bilinear_mask`, sharpness and borders change nothing.
struct Linear_mask
{
  /// How faces are split (see `SubdivisionMask`).
  static constexpr Split split = Split::triangle;
  /// False: sharpness and borders change nothing.
  static constexpr bool creases = false;

  /// The edge midpoint.
  template <class W>
  void smooth_edge(unsigned d0, unsigned d1, Edge_weights<W>& w) const
  {
    Bilinear_mask().smooth_edge(d0, d1, w);
  }
  /// The old point, kept.
  template <class W>
  void smooth_vertex(unsigned n, Vertex_weights<W>& w) const
  {
    Bilinear_mask().smooth_vertex(n, w);
  }
};

/// \ingroup PkgSubdivision
/// Doo–Sabin subdivision of polygon meshes: a new point per face corner,
/// with Doo and Sabin's weights (CGAL's `DooSabin_mask_3`). At a border,
/// a corner on one border edge gets the Chaikin point ¾ v + ¼ w of that
/// edge and a corner between two border edges keeps its vertex, so that a
/// border converges to the quadratic B-spline of the border polygon.
struct Doo_sabin_mask
{
  /// How faces are split (see `SubdivisionMask`).
  static constexpr Split split = Split::dual;
  /// False: sharpness and borders change nothing.
  static constexpr bool creases = false;

  /// Writes the weights of the `n` vertices of a face, starting at the
  /// corner's vertex and following the face, for the new point of that
  /// corner: (n+5)/4n for the corner, (3 + 2 cos(2πk/n))/4n for vertex `k`.
  template <class W>
  void corner(unsigned n, W* weights) const
  {
    if (n == 4) { // the bilinear tensor product of (3/4, 1/4), exactly
      weights[0] = W(9) / W(16);
      weights[1] = weights[3] = W(3) / W(16);
      weights[2] = W(1) / W(16);
      return;
    }
    const W four_n = W(4 * int(n));
    weights[0] = W(int(n) + 5) / four_n;
    for (unsigned k = 1; k < n; ++k)
      weights[k] = (W(3) + internal::two_cos<W>(k, n)) / four_n;
  }
};

/// \ingroup PkgSubdivision
/// Kobbelt's √3 subdivision of triangle meshes: a centroid per triangle,
/// old vertices smoothed with α(n) = (4 − 2 cos(2π/n)) / 9, old edges
/// flipped; two steps triple the resolution. Borders follow Kobbelt (and
/// CGAL's `Sqrt3_mask_3`): in odd steps border triangles are not flipped and
/// border vertices stay; in even steps each border edge is trisected with
/// the 1/27 rules and border vertices smoothed with (4, 19, 4) / 27.
struct Sqrt3_mask
{
  /// How faces are split (see `SubdivisionMask`).
  static constexpr Split split = Split::sqrt3;
  /// False: sharpness and borders change nothing.
  static constexpr bool creases = false;

  /// The smooth vertex rule: 1 − α(n) of `V` and α(n)/n of each neighbour.
  template <class W>
  void smooth_vertex(unsigned n, Vertex_weights<W>& w) const
  {
    const W alpha = (W(4) - internal::two_cos<W>(1, n)) / W(9);
    w.vertex = W(1) - alpha;
    w.edge = alpha / W(int(n));
  }
};

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_MASKS_H
