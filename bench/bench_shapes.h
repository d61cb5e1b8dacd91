// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Inputs that several benchmarks share, as triangle soups, so that each peer
// is given the same points and faces.

#ifndef CGAL_EXT_BENCH_SHAPES_H
#define CGAL_EXT_BENCH_SHAPES_H

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace bench_shapes {

template <class Point>
struct Triangle_soup
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

/// The torus of radii 2 and 1 at angles a (round its axis) and b (round its tube).
template <class Point>
Point torus_point(double a, double b)
{
  return Point((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b));
}

/// An n x n torus (radii 2 and 1) of quads, each split along one diagonal:
/// n² points, 2 n² triangles.
template <class Point>
Triangle_soup<Point> torus_triangle_soup(std::size_t n)
{
  Triangle_soup<Point> s;
  const double pi = std::acos(-1.0);
  s.points.reserve(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      s.points.push_back(torus_point<Point>(2 * pi * double(i) / double(n), 2 * pi * double(j) / double(n)));
    }
  const auto at = [n](std::size_t i, std::size_t j) { return (i % n) * n + (j % n); };
  s.triangles.reserve(2 * n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return s;
}

} // namespace bench_shapes

#endif // CGAL_EXT_BENCH_SHAPES_H
