// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Garland–Heckbert plane quadrics in double: the weighted sum of squared
// distances to a set of planes, and the point that minimises it.

#ifndef CGAL_EXT_DECIMATION_INTERNAL_QUADRIC_H
#define CGAL_EXT_DECIMATION_INTERNAL_QUADRIC_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <limits>

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
    // A sum of squares: below zero is rounding; NaN, an overflow, counts as
    // the largest cost rather than none.
    if (std::isnan(value))
      return std::numeric_limits<double>::infinity();
    return value > 0 ? value : 0;
  }

  /// The point nearest to `centre` among those that minimise the quadric
  /// over the directions it determines well. A is split into its eigen
  /// directions; along those whose eigenvalue is at least
  /// `relative_threshold` times the largest, x moves from `centre` to the
  /// minimum; along the others (a flat or straight neighbourhood, where the
  /// "minimiser" drifts far along a plane or line on a rounding error) it
  /// stays at `centre`. This is Lindstrom's truncated pseudo-inverse
  /// ("Out-of-core simplification of large polygonal models", 2000): on fine
  /// meshes the tangential eigenvalues shrink with the square of the angle
  /// between neighbouring normals, so a test on A's determinant would throw
  /// the whole solution away on them. Returns how many directions were
  /// determined: 3 where planes meet in a point (a corner), 0 if A is zero
  /// (x is then `centre`).
  int minimizer_near(const std::array<double, 3>& centre, std::array<double, 3>& x,
                      double relative_threshold = 1e-3) const
  {
    Eigen::Matrix3d m;
    m << a[0], a[1], a[2], a[1], a[3], a[4], a[2], a[4], a[5];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(m);
    const Eigen::Vector3d& lambda = eigen.eigenvalues(); // increasing
    x = centre;
    if (!(lambda(2) > 0))
      return 0;
    const Eigen::Vector3d x0(centre[0], centre[1], centre[2]);
    const Eigen::Vector3d gradient = m * x0 + Eigen::Vector3d(b[0], b[1], b[2]); // half of it
    Eigen::Vector3d result = x0;
    int rank = 0;
    for (int i = 0; i < 3; ++i)
      if (lambda(i) >= relative_threshold * lambda(2)) {
        const auto direction = eigen.eigenvectors().col(i);
        result -= (direction.dot(gradient) / lambda(i)) * direction;
        ++rank;
      }
    if (!(std::isfinite(result(0)) && std::isfinite(result(1)) && std::isfinite(result(2))))
      return 0;
    x = {result(0), result(1), result(2)};
    return rank;
  }
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_INTERNAL_QUADRIC_H
