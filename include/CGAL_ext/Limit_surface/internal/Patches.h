// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The patches a limit surface is pieced from, with their basis functions and
// first and second derivatives: for Catmull–Clark the bicubic B-spline patch
// of a regular region and the 20-point cubic Gregory patch that OpenSubdiv
// puts where refinement stops near an irregular vertex; for Loop the quartic
// box-spline triangle of a regular region and OpenSubdiv's 18-point quartic
// Gregory triangle.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCHES_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCHES_H

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// A point as three coordinates of the kernel's number type: patches combine
// points linearly, and an exact number type keeps a regular patch exact.
template <class FT>
using Coordinates = std::array<FT, 3>;

template <class FT>
void add_scaled(Coordinates<FT>& sum, const FT& w, const Coordinates<FT>& p)
{
  for (int i = 0; i < 3; ++i)
    sum[i] += w * p[i];
}

// Basis weights of one patch at one parameter: value, d/ds, d/dt, and the
// three second derivatives.
template <class FT, std::size_t N>
struct Basis
{
  std::array<FT, N> w, ds, dt, dss, dst, dtt;
};

// Position and derivatives with respect to the patch's own (s, t).
template <class FT>
struct Patch_value
{
  Coordinates<FT> p, ds, dt, dss, dst, dtt;
};

// The uniform cubic B-spline basis on [0, 1] and its two derivatives.
template <class FT>
void bspline_curve(const FT& t, FT w[4], FT d[4], FT d2[4])
{
  const FT t2 = t * t, t3 = t2 * t, one6 = FT(1) / FT(6);
  w[0] = one6 * (FT(1) - FT(3) * (t - t2) - t3);
  w[1] = one6 * (FT(4) - FT(6) * t2 + FT(3) * t3);
  w[2] = one6 * (FT(1) + FT(3) * (t + t2 - t3));
  w[3] = one6 * t3;
  d[0] = -t2 / FT(2) + t - FT(1) / FT(2);
  d[1] = FT(3) * t2 / FT(2) - FT(2) * t;
  d[2] = -FT(3) * t2 / FT(2) + t + FT(1) / FT(2);
  d[3] = t2 / FT(2);
  d2[0] = FT(1) - t;
  d2[1] = FT(3) * t - FT(2);
  d2[2] = FT(1) - FT(3) * t;
  d2[3] = t;
}

// The cubic Bernstein basis on [0, 1] and its two derivatives.
template <class FT>
void bezier_curve(const FT& t, FT w[4], FT d[4], FT d2[4])
{
  const FT c = FT(1) - t;
  w[0] = c * c * c;
  w[1] = FT(3) * c * c * t;
  w[2] = FT(3) * c * t * t;
  w[3] = t * t * t;
  d[0] = -FT(3) * c * c;
  d[1] = FT(3) * c * c - FT(6) * c * t;
  d[2] = FT(6) * c * t - FT(3) * t * t;
  d[3] = FT(3) * t * t;
  d2[0] = FT(6) * c;
  d2[1] = FT(18) * t - FT(12);
  d2[2] = FT(6) - FT(18) * t;
  d2[3] = FT(6) * t;
}

// A bicubic B-spline patch (point (i, j) at index 4 j + i, i along s) at
// (s, t), as a tensor product: each row of four points combined along s
// (value, first and second derivative), then the rows along t; 216
// products where the 16 weights of each of the six derivatives take 384.
template <class FT>
Patch_value<FT> evaluate_bspline(const std::array<Coordinates<FT>, 20>& points, const FT& s, const FT& t)
{
  FT ws[4], ds[4], d2s[4], wt[4], dt[4], d2t[4];
  bspline_curve(s, ws, ds, d2s);
  bspline_curve(t, wt, dt, d2t);
  Patch_value<FT> r;
  for (auto* c : {&r.p, &r.ds, &r.dt, &r.dss, &r.dst, &r.dtt})
    *c = {FT(0), FT(0), FT(0)};
  for (int j = 0; j < 4; ++j) {
    Coordinates<FT> row{FT(0), FT(0), FT(0)}, row_s = row, row_ss = row;
    for (int i = 0; i < 4; ++i) {
      const Coordinates<FT>& x = points[std::size_t(4 * j + i)];
      add_scaled(row, ws[i], x);
      add_scaled(row_s, ds[i], x);
      add_scaled(row_ss, d2s[i], x);
    }
    add_scaled(r.p, wt[j], row);
    add_scaled(r.dt, dt[j], row);
    add_scaled(r.dtt, d2t[j], row);
    add_scaled(r.ds, wt[j], row_s);
    add_scaled(r.dst, dt[j], row_s);
    add_scaled(r.dss, wt[j], row_ss);
  }
  return r;
}

// The Gregory basis in OpenSubdiv's point order (five points per corner:
// P, Ep, Em, Fp, Fm; corner k at (k == 1 || k == 2, k >= 2)). Each pair of
// face points is blended rationally into the Bezier point it replaces; the
// derivatives are those of the Bezier patch with the blended points, as
// OpenSubdiv computes them (not the derivatives of the rational blend).
template <class FT>
void gregory_basis(const FT& s, const FT& t, Basis<FT, 20>& b)
{
  static const int boundary[12] = {0, 1, 7, 5, 2, 6, 16, 12, 15, 17, 11, 10};
  static const int boundary_col[12] = {0, 1, 2, 3, 0, 3, 0, 3, 0, 1, 2, 3};
  static const int boundary_row[12] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 3, 3};
  static const int interior[8] = {3, 4, 8, 9, 13, 14, 18, 19};
  static const int interior_col[8] = {1, 1, 2, 2, 2, 2, 1, 1};
  static const int interior_row[8] = {1, 1, 1, 1, 2, 2, 2, 2};
  FT ws[4], ds[4], d2s[4], wt[4], dt[4], d2t[4];
  bezier_curve(s, ws, ds, d2s);
  bezier_curve(t, wt, dt, d2t);
  const FT sc = FT(1) - s, tc = FT(1) - t;
  // At a corner both members of a pair have weight 0: any split will do.
  auto inverse = [](const FT& x) { return x > FT(0) ? FT(1) / x : FT(1); };
  const FT d0 = inverse(s + t), d1 = inverse(sc + t), d2 = inverse(sc + tc), d3 = inverse(s + tc);
  const FT g[8] = {s * d0, FT(1) - s * d0, t * d1, FT(1) - t * d1, sc * d2, FT(1) - sc * d2, tc * d3, FT(1) - tc * d3};
  auto set = [&](int k, int i, int j, const FT& factor) {
    b.w[k] = ws[i] * wt[j] * factor;
    b.ds[k] = ds[i] * wt[j] * factor;
    b.dt[k] = ws[i] * dt[j] * factor;
    b.dss[k] = d2s[i] * wt[j] * factor;
    b.dst[k] = ds[i] * dt[j] * factor;
    b.dtt[k] = ws[i] * d2t[j] * factor;
  };
  for (int k = 0; k < 12; ++k)
    set(boundary[k], boundary_col[k], boundary_row[k], FT(1));
  for (int k = 0; k < 8; ++k)
    set(interior[k], interior_col[k], interior_row[k], g[k]);
}

// x^k for a small k >= 0, and 0 for k < 0 (a derivative's vanished term).
template <class FT>
FT power(const FT& x, int k)
{
  if (k < 0)
    return FT(0);
  FT r(1);
  for (int i = 0; i < k; ++i)
    r *= x;
  return r;
}

template <class FT, std::size_t N>
void clear(Basis<FT, N>& b)
{
  for (auto* a : {&b.w, &b.ds, &b.dt, &b.dss, &b.dst, &b.dtt})
    a->fill(FT(0));
}

// The quartic box spline of a regular Loop triangle (Stam's basis, written
// in the monomials of (s, t)), its 12 points laid out as OpenSubdiv lays
// them out, on the triangular lattice:
//
//        10 -- 11
//       7 --  8 --  9
//    3 -- 4 --  5 --  6
//       0 --  1 --  2
//
// the triangle's corners at 4 (s, t) = (0, 0), 5 (1, 0) and 8 (0, 1).
// Monomials 1, s, t, s², st, t², s³, s²t, st², t³, s⁴, s³t, s²t², st³, t⁴, and
// twelve times each point's basis function in them.
struct Box_spline_monomials
{
  static constexpr int count = 15;
  static constexpr int exponent[count][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {3, 0}, {2, 1},
                                             {1, 2}, {0, 3}, {4, 0}, {3, 1}, {2, 2}, {1, 3}, {0, 4}};
  static constexpr int twelve_times[12][count] = {{1, -2, -4, 0, 6, 6, 2, 0, -6, -4, -1, -2, 0, 2, 1},
                                                  {1, 2, -2, 0, -6, 0, -4, 0, 6, 2, 2, 4, 0, -2, -1},
                                                  {0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -1, -2, 0, 0, 0},
                                                  {1, -4, -2, 6, 6, 0, -4, -6, 0, 2, 1, 2, 0, -2, -1},
                                                  {6, 0, 0, -12, -12, -12, 8, 12, 12, 8, -1, -2, 0, -2, -1},
                                                  {1, 4, 2, 6, 6, 0, -4, -6, -12, -4, -1, -2, 0, 4, 2},
                                                  {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0},
                                                  {1, -2, 2, 0, -6, 0, 2, 6, 0, -4, -1, -2, 0, 4, 2},
                                                  {1, 2, 4, 0, 6, 6, -4, -12, -6, -4, 2, 4, 0, -2, -1},
                                                  {0, 0, 0, 0, 0, 0, 2, 6, 6, 2, -1, -2, 0, -2, -1},
                                                  {0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -2, -1},
                                                  {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 1}};
};

// Replaces the 12 points of a box-spline patch by the coefficients of its
// polynomial in the 15 monomials (the integer weights above, over 12): done
// once when the patch is built, it leaves each evaluation the monomials and
// their derivatives to weight, about a tenth of the operations of weighting
// the points by the basis functions and each of their derivatives, which
// was most of a regular Loop patch's cost. Linear, so exact in an exact
// number type.
template <class FT>
void box_spline_to_monomials(std::array<Coordinates<FT>, 20>& points)
{
  using M = Box_spline_monomials;
  std::array<Coordinates<FT>, M::count> coefficient;
  for (auto& c : coefficient)
    c = {FT(0), FT(0), FT(0)};
  const FT twelfth = FT(1) / FT(12);
  for (std::size_t k = 0; k < 12; ++k)
    for (std::size_t m = 0; m < std::size_t(M::count); ++m)
      if (M::twelve_times[k][m] != 0)
        add_scaled(coefficient[m], FT(M::twelve_times[k][m]) * twelfth, points[k]);
  std::copy(coefficient.begin(), coefficient.end(), points.begin());
}

// The box spline at (s, t) with its derivatives, from the coefficients of
// its monomials (box_spline_to_monomials()).
template <class FT>
Patch_value<FT> evaluate_box_spline(const std::array<Coordinates<FT>, 20>& coefficient, const FT& s, const FT& t)
{
  using M = Box_spline_monomials;
  const FT ps[5] = {FT(1), s, s * s, s * s * s, s * s * s * s};
  const FT pt[5] = {FT(1), t, t * t, t * t * t, t * t * t * t};
  Patch_value<FT> r;
  for (auto* c : {&r.p, &r.ds, &r.dt, &r.dss, &r.dst, &r.dtt})
    *c = {FT(0), FT(0), FT(0)};
  // Adds `factor` s^a t^e times the monomial's coefficient to `sum`; nothing
  // where a derivative has taken a power below 0 (its factor is then 0).
  const auto add = [&](Coordinates<FT>& sum, std::size_t m, int factor, int a, int e) {
    if (factor != 0)
      add_scaled(sum, FT(factor) * ps[a] * pt[e], coefficient[m]);
  };
  for (std::size_t m = 0; m < std::size_t(M::count); ++m) {
    const int a = M::exponent[m][0], e = M::exponent[m][1];
    add(r.p, m, 1, a, e);
    add(r.ds, m, a, a > 0 ? a - 1 : 0, e);
    add(r.dt, m, e, a, e > 0 ? e - 1 : 0);
    add(r.dss, m, a * (a - 1), a > 1 ? a - 2 : 0, e);
    add(r.dst, m, a * e, a > 0 ? a - 1 : 0, e > 0 ? e - 1 : 0);
    add(r.dtt, m, e * (e - 1), a, e > 1 ? e - 2 : 0);
  }
  return r;
}

// The quartic Bernstein polynomial 4!/(i! j! k!) u^i v^j w^k, u = s, v = t,
// w = 1 - s - t, and its derivatives in (s, t), added `factor` times into
// entry n (d/ds = d/du - d/dw, d/dt = d/dv - d/dw).
template <class FT, std::size_t N>
void add_bernstein(Basis<FT, N>& b, std::size_t n, int i, int j, const FT& factor, const FT& s, const FT& t)
{
  static const int factorial[5] = {1, 1, 2, 6, 24};
  const int k = 4 - i - j;
  const FT u = s, v = t, w = FT(1) - s - t;
  const FT c = factor * FT(24 / (factorial[i] * factorial[j] * factorial[k]));
  // The derivative of u^i v^j w^k taken a times in u, b in v, e in w (at most twice each).
  auto term = [&](int a, int b2, int e) {
    auto falling = [](int x, int d) { return d == 0 ? 1 : d == 1 ? x : x * (x - 1); };
    return FT(falling(i, a) * falling(j, b2) * falling(k, e)) * power(u, i - a) * power(v, j - b2) * power(w, k - e);
  };
  b.w[n] += c * term(0, 0, 0);
  b.ds[n] += c * (term(1, 0, 0) - term(0, 0, 1));
  b.dt[n] += c * (term(0, 1, 0) - term(0, 0, 1));
  b.dss[n] += c * (term(2, 0, 0) - FT(2) * term(1, 0, 1) + term(0, 0, 2));
  b.dst[n] += c * (term(1, 1, 0) - term(1, 0, 1) - term(0, 1, 1) + term(0, 0, 2));
  b.dtt[n] += c * (term(0, 2, 0) - FT(2) * term(0, 1, 1) + term(0, 0, 2));
}

// OpenSubdiv's 18-point quartic Gregory triangle: five points per corner
// (P, Ep, Em, Fp, Fm, corner k at (k == 1, k == 2)), then the middle points
// of edges 0, 1 and 2. It is the quartic Bezier triangle whose three inner
// points each blend a pair of face points rationally; the derivatives are
// those of the Bezier triangle with the blended points, as OpenSubdiv
// computes them (not those of the rational blend).
template <class FT>
void gregory_triangle_basis(const FT& s, const FT& t, Basis<FT, 18>& b)
{
  const FT u = s, v = t, w = FT(1) - s - t;
  // At a corner both members of a pair have weight 0: any split will do.
  auto share = [](const FT& a, const FT& b2) { return a + b2 > FT(0) ? a / (a + b2) : FT(1); };
  const FT g0 = share(u, v), g1 = share(v, w), g2 = share(w, u);
  // (entry, power of u, power of v, factor)
  const struct
  {
    int entry, i, j;
    FT factor;
  } points[18] = {{0, 0, 0, FT(1)},  {1, 1, 0, FT(1)},  {2, 0, 1, FT(1)},      {3, 1, 1, g0},  {4, 1, 1, FT(1) - g0},
                  {5, 4, 0, FT(1)},  {6, 3, 1, FT(1)},  {7, 3, 0, FT(1)},      {8, 2, 1, g1},  {9, 2, 1, FT(1) - g1},
                  {10, 0, 4, FT(1)}, {11, 0, 3, FT(1)}, {12, 1, 3, FT(1)},     {13, 1, 2, g2}, {14, 1, 2, FT(1) - g2},
                  {15, 2, 0, FT(1)}, {16, 2, 2, FT(1)}, {17, 0, 2, FT(1)}};
  clear(b);
  for (const auto& p : points)
    add_bernstein(b, std::size_t(p.entry), p.i, p.j, p.factor, s, t);
}

// What a patch is.
enum class Patch_type
{
  bspline,          // 16 points
  gregory,          // 20 points
  box_spline,       // 12 points, kept as its 15 monomials' coefficients (box_spline_to_monomials())
  gregory_triangle, // 18 points
};

// A patch over a part of its face's (or sub-face's) parameters: the square
// [u0, u0 + size] x [v0, v0 + size] for a quad patch; for a triangle, the
// half of that square below its diagonal, or, `rotated`, the triangle of
// corners (u0, v0), (u0 - size, v0), (u0, v0 - size), whose own (s, t) run
// against (u, v). A triangle is found by the quadrants `path` (two bits per
// level, the first level lowest) that lead to it from its face, `depth` deep.
template <class FT>
struct Patch
{
  Patch_type type = Patch_type::bspline;
  double u0 = 0, v0 = 0, size = 1;
  bool rotated = false;
  unsigned depth = 0;
  std::uint64_t path = 0;
  std::array<Coordinates<FT>, 20> points;
};

// The patches of a face or sub-face: one, kept inline, wherever the face is
// regular or needs no refinement; more where adaptive refinement splits it.
template <class FT>
using Patch_list = boost::container::small_vector<Patch<FT>, 1>;

template <class FT, std::size_t N>
Patch_value<FT> combine(const Basis<FT, N>& b, const std::array<Coordinates<FT>, 20>& points)
{
  Patch_value<FT> r;
  for (auto* c : {&r.p, &r.ds, &r.dt, &r.dss, &r.dst, &r.dtt})
    *c = {FT(0), FT(0), FT(0)};
  for (std::size_t k = 0; k < N; ++k) {
    add_scaled(r.p, b.w[k], points[k]);
    add_scaled(r.ds, b.ds[k], points[k]);
    add_scaled(r.dt, b.dt[k], points[k]);
    add_scaled(r.dss, b.dss[k], points[k]);
    add_scaled(r.dst, b.dst[k], points[k]);
    add_scaled(r.dtt, b.dtt[k], points[k]);
  }
  return r;
}

template <class FT>
Patch_value<FT> evaluate_patch(const Patch<FT>& patch, const FT& s, const FT& t)
{
  switch (patch.type) {
  case Patch_type::gregory: {
    Basis<FT, 20> b;
    gregory_basis(s, t, b);
    return combine(b, patch.points);
  }
  case Patch_type::box_spline:
    return evaluate_box_spline(patch.points, s, t); // its coefficients
  case Patch_type::gregory_triangle: {
    Basis<FT, 18> b;
    gregory_triangle_basis(s, t, b);
    return combine(b, patch.points);
  }
  default:
    return evaluate_bspline(patch.points, s, t);
  }
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCHES_H
