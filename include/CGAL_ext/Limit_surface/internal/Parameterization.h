// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// OpenSubdiv's Bfr::Parameterization of a base face that is not a quad: n
// quad sub-faces of size 1/2 laid out in rows of unit tiles. Evaluation,
// tessellation and projection all place sub-faces by these functions; the
// the tessellation and its rates place the points of a face's boundary by
// corner_parameter() and edge_parameter().

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_PARAMETERIZATION_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_PARAMETERIZATION_H

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// Bfr's row length of the sub-face layout of an n-gon (n != 4).
inline int sub_face_row(int n) { return n < 10 ? (2 + (n > 4 ? 1 : 0)) : (1 + int(std::sqrt(float(n - 1)))); }

// The tile of sub-face k of an n-gon: the corner (u, v) of its unit tile,
// whose lower-left quarter the sub-face covers.
inline std::array<int, 2> sub_face_tile(int n, int k) { return {k % sub_face_row(n), k / sub_face_row(n)}; }

// The sub-face of an n-gon (n != 4) that parameter (u, v) lies in, and the
// parameter (su, sv) there: the nearest tile (a parameter on the line
// between two sub-faces belongs to the upper one, as Bfr's quadtree
// descends), held inside the layout; (su, sv) lies in [0, 1]² for a (u, v)
// of the face's domain.
template <class FT>
struct Sub_face_point
{
  int k;
  FT su, sv;
};
template <class FT>
Sub_face_point<FT> locate_sub_face(int n, const FT& u, const FT& v)
{
  const int row = sub_face_row(n);
  int ut = int(CGAL::to_double(u) + 0.25), vt = int(CGAL::to_double(v) + 0.25);
  ut = std::max(0, std::min(ut, row - 1));
  vt = std::max(0, vt);
  if (vt * row + ut >= n)
    vt = n / row - 1 + (ut < n % row ? 1 : 0);
  return {vt * row + ut, FT(2) * (u - FT(ut)), FT(2) * (v - FT(vt))};
}

// Whether a face of `sides` sides is parameterised over a triangle, (0, 0),
// (1, 0), (0, 1) (a triangle under Loop: `triangle_domain`).
inline bool is_triangle_domain(int sides, bool triangle_domain) { return triangle_domain && sides == 3; }

// Whether a face has one parameter domain of its own (a quad, a Loop
// triangle) rather than n quad sub-faces.
inline bool has_own_domain(int sides, bool triangle_domain)
{
  return sides == 4 || is_triangle_domain(sides, triangle_domain);
}

// (u, v) of local parameter (su, sv) of sub-face k of a face of `sides`
// sides, or of a quad's own parameter (k unused).
template <class FT>
std::array<FT, 2> sub_face_parameter(int sides, int k, const FT& su, const FT& sv)
{
  if (sides == 4)
    return {su, sv};
  const std::array<int, 2> tile = sub_face_tile(sides, k);
  return {FT(tile[0]) + su / FT(2), FT(tile[1]) + sv / FT(2)};
}

// The parameter of corner k of a face of `sides` sides; `triangle_domain`
// (Loop) parameterises a triangle over (0, 0), (1, 0), (0, 1).
template <class FT>
std::array<FT, 2> corner_parameter(int sides, bool triangle_domain, int k)
{
  if (is_triangle_domain(sides, triangle_domain)) {
    const int uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    return {FT(uv[k][0]), FT(uv[k][1])};
  }
  if (sides == 4) {
    const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    return {FT(uv[k][0]), FT(uv[k][1])};
  }
  return sub_face_parameter(sides, k, FT(0), FT(0));
}

// The parameter at fraction i / n along edge k (from corner k) of a face of
// `sides` sides, as Bfr gives it: of an n-gon, in sub-face k for the first
// half of the edge and in sub-face k + 1 after.
template <class FT>
std::array<FT, 2> edge_parameter(int sides, bool triangle_domain, int k, int i, int n)
{
  const FT t = FT(i) / FT(n);
  if (is_triangle_domain(sides, triangle_domain)) {
    switch (k) {
      case 0: return {t, FT(0)};
      case 1: return {FT(1) - t, t};
      default: return {FT(0), FT(1) - t};
    }
  }
  if (sides == 4) {
    switch (k) {
      case 0: return {t, FT(0)};
      case 1: return {FT(1), t};
      case 2: return {FT(1) - t, FT(1)};
      default: return {FT(0), FT(1) - t};
    }
  }
  if (2 * i < n)
    return sub_face_parameter(sides, k, FT(2) * t, FT(0));
  return sub_face_parameter(sides, (k + 1) % sides, FT(0), FT(2) * (FT(1) - t));
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_PARAMETERIZATION_H
