// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Garland–Heckbert plane quadrics in double: the weighted sum of squared
// distances to a set of planes, and the point that minimises it.

#ifndef CGAL_EXT_INTERNAL_QUADRIC_H
#define CGAL_EXT_INTERNAL_QUADRIC_H

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL_ext {
namespace internal {

/// The quadric x -> x^T A x + 2 b.x + c of Garland and Heckbert, A symmetric.
/// A plane's quadric does not change when its normal is turned round, so
/// quadrics need no orientation: they carry over to one-sided surfaces.
struct Quadric
{
  // A's upper triangle: xx xy xz yy yz zz; then b and c.
  std::array<double, 6> a{};
  std::array<double, 3> b{};
  double c = 0;

  /// `weight` times the squared distance to the plane through `point` with
  /// normal `normal` (any length: it is normalised here; zero gives nothing).
  static Quadric of_plane(const std::array<double, 3>& normal, const std::array<double, 3>& point, double weight)
  {
    Quadric q;
    const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (!(length > 0) || !(weight > 0))
      return q;
    const double n[3] = {normal[0] / length, normal[1] / length, normal[2] / length};
    const double d = -(n[0] * point[0] + n[1] * point[1] + n[2] * point[2]);
    q.a = {weight * n[0] * n[0], weight * n[0] * n[1], weight * n[0] * n[2],
           weight * n[1] * n[1], weight * n[1] * n[2], weight * n[2] * n[2]};
    q.b = {weight * n[0] * d, weight * n[1] * d, weight * n[2] * d};
    q.c = weight * d * d;
    return q;
  }

  Quadric& operator+=(const Quadric& o)
  {
    for (int i = 0; i < 6; ++i)
      a[i] += o.a[i];
    for (int i = 0; i < 3; ++i)
      b[i] += o.b[i];
    c += o.c;
    return *this;
  }
  friend Quadric operator+(Quadric x, const Quadric& y) { return x += y; }

  double operator()(const std::array<double, 3>& x) const
  {
    const double ax0 = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
    const double ax1 = a[1] * x[0] + a[3] * x[1] + a[4] * x[2];
    const double ax2 = a[2] * x[0] + a[4] * x[1] + a[5] * x[2];
    const double value = x[0] * ax0 + x[1] * ax1 + x[2] * ax2 + 2 * (b[0] * x[0] + b[1] * x[1] + b[2] * x[2]) + c;
    return value > 0 ? value : 0; // a sum of squares: below zero is rounding
  }

  /// The minimiser of the quadric, A x = -b, by the adjugate, when A is well
  /// conditioned: its determinant is not small against the cube of its
  /// largest entry (a flat or straight neighbourhood has a singular A, whose
  /// "minimiser" is anywhere along a plane or line). Returns false otherwise.
  bool minimizer(std::array<double, 3>& x) const
  {
    const double c00 = a[3] * a[5] - a[4] * a[4], c01 = a[2] * a[4] - a[1] * a[5], c02 = a[1] * a[4] - a[2] * a[3];
    const double c11 = a[0] * a[5] - a[2] * a[2], c12 = a[1] * a[2] - a[0] * a[4], c22 = a[0] * a[3] - a[1] * a[1];
    const double det = a[0] * c00 + a[1] * c01 + a[2] * c02;
    double largest = 0;
    for (double v : a)
      largest = (std::max)(largest, std::abs(v));
    if (!(std::abs(det) > 1e-8 * largest * largest * largest))
      return false;
    x = {-(c00 * b[0] + c01 * b[1] + c02 * b[2]) / det, -(c01 * b[0] + c11 * b[1] + c12 * b[2]) / det,
         -(c02 * b[0] + c12 * b[1] + c22 * b[2]) / det};
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
  }
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_INTERNAL_QUADRIC_H
