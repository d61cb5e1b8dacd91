// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The patches a limit surface is pieced from: the bicubic B-spline patch of
// a regular region and the 20-point cubic Gregory patch that OpenSubdiv puts
// where refinement stops near an irregular vertex, with their basis
// functions and first and second derivatives.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCHES_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCHES_H

#include <array>
#include <cstddef>

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

// The tensor-product B-spline basis, point (i, j) at index 4 j + i (i along s).
template <class FT>
void bspline_basis(const FT& s, const FT& t, Basis<FT, 16>& b)
{
  FT ws[4], ds[4], d2s[4], wt[4], dt[4], d2t[4];
  bspline_curve(s, ws, ds, d2s);
  bspline_curve(t, wt, dt, d2t);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int k = 4 * j + i;
      b.w[k] = ws[i] * wt[j];
      b.ds[k] = ds[i] * wt[j];
      b.dt[k] = ws[i] * dt[j];
      b.dss[k] = d2s[i] * wt[j];
      b.dst[k] = ds[i] * dt[j];
      b.dtt[k] = ws[i] * d2t[j];
    }
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

// A patch over the square [u0, u0 + size] x [v0, v0 + size] of its face's
// (or sub-face's) parameters.
template <class FT>
struct Patch
{
  bool gregory = false;
  double u0 = 0, v0 = 0, size = 1;
  std::array<Coordinates<FT>, 20> points; // 16 used by a B-spline patch
};

// Position and derivatives with respect to the patch's own (s, t).
template <class FT>
struct Patch_value
{
  Coordinates<FT> p, ds, dt, dss, dst, dtt;
};

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
  if (patch.gregory) {
    Basis<FT, 20> b;
    gregory_basis(s, t, b);
    return combine(b, patch.points);
  }
  Basis<FT, 16> b;
  bspline_basis(s, t, b);
  return combine(b, patch.points);
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCHES_H
