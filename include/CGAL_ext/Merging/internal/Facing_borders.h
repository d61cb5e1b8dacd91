// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Border loops walked with their points, and the nearest pair of points of
// two sets of loops: how facing_borders() and aligned_border_loops() choose
// the chains to glue.

#ifndef CGAL_EXT_MERGING_INTERNAL_FACING_BORDERS_H
#define CGAL_EXT_MERGING_INTERNAL_FACING_BORDERS_H

#include <CGAL_ext/Merging/Merge_types.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/internal/Nearest_points.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// A border loop walked with next() from one of its darts: darts[i] runs
// into the i-th vertex, whose point (rounded to doubles) is points[i].
struct Border_walk
{
  std::vector<Dart> darts;
  std::vector<Nearest_points::Point> points;
  std::size_t size() const { return darts.size(); }
  // The dart leaving the i-th vertex, walking on (next) or back (flipped).
  Dart leaving(std::size_t i, bool back) const { return back ? darts[i].flipped() : darts[(i + 1) % size()]; }
};

template <class P>
Border_walk border_walk(const Mobius_mesh<P>& m, Dart d)
{
  Border_walk w;
  for (Dart c : CGAL_ext::halfedges_around_face(d, m)) {
    w.darts.push_back(c);
    w.points.push_back(Nearest_points::rounded(m.point(m.target(c))));
  }
  return w;
}

// Squared distances compared with a relative slack: vertices placed
// symmetrically tie only up to rounding.
inline bool no_farther(double d2, double nearest_d2) { return d2 <= nearest_d2 * (1 + 1e-9); }

// The sum of squared distances of the pairing of two whole loops from their
// vertices i0 and j0, b walked on or back: the k-th vertex of a (of n) with
// the floor(k m / n)-th of b (of m).
inline double pairing_cost(const Border_walk& a, std::size_t i0, const Border_walk& b, std::size_t j0, bool back)
{
  const std::size_t n = a.size(), m = b.size();
  double cost = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t step = k * m / n;
    cost += CGAL::squared_distance(a.points[(i0 + k) % n], b.points[back ? (j0 + m - step) % m : (j0 + step) % m]);
  }
  return cost;
}

// Whole loops from the vertices i0 of a and j0 of b, b walked the way that
// keeps the two walks nearer: the pairing twists only where the loops do.
inline Border_pairing whole_loops(const Border_walk& a, std::size_t i0, const Border_walk& b, std::size_t j0)
{
  const bool back = pairing_cost(a, i0, b, j0, true) < pairing_cost(a, i0, b, j0, false);
  return {a.leaving(i0, false), b.leaving(j0, back), a.size(), b.size()};
}

// For each vertex of `from`: whether it is (up to ties) the vertex of `from`
// nearest to its own nearest vertex of `to`.
inline std::vector<bool> mutually_nearest(const Border_walk& from, const Border_walk& to)
{
  const Nearest_points near_from(from.points), near_to(to.points);
  std::vector<bool> mutual(from.size());
  for (std::size_t i = 0; i < from.size(); ++i) {
    const auto [j, d2] = near_to.nearest(from.points[i]);
    mutual[i] = no_farther(d2, near_from.nearest(to.points[j]).second);
  }
  return mutual;
}

// The run of consecutive `true`s around position s of a cyclic sequence:
// its first position and its length (the whole loop: every position).
inline std::pair<std::size_t, std::size_t> run_around(const std::vector<bool>& in_run, std::size_t s)
{
  const std::size_t n = in_run.size();
  std::size_t before = 0, after = 0;
  while (after + 1 < n && in_run[(s + after + 1) % n])
    ++after;
  while (before + after + 1 < n && in_run[(s + n - before - 1) % n])
    ++before;
  return {(s + n - before) % n, before + after + 1};
}

// A run of one vertex has no edge to glue or bridge (two loops may face
// each other at one vertex only, as a square beside a Möbius strip's twisted
// border): it grows by the neighbour nearer to `q`, the other loop's vertex.
inline std::pair<std::size_t, std::size_t> at_least_one_edge(const Border_walk& w,
                                                             std::pair<std::size_t, std::size_t> run,
                                                             const Nearest_points::Point& q)
{
  if (run.second >= 2 || w.size() < 2)
    return run;
  const std::size_t n = w.size(), previous = (run.first + n - 1) % n, next = (run.first + 1) % n;
  if (CGAL::squared_distance(w.points[previous], q) < CGAL::squared_distance(w.points[next], q))
    return {previous, 2};
  return {run.first, 2};
}

// The parts of two border loops that face each other, from a nearest pair
// of their vertices (i0 of a, j0 of b): the runs of mutually nearest
// vertices around them (at least one edge each), or the whole loops if
// either run is a whole loop.
inline Border_pairing facing_parts(const Border_walk& a, std::size_t i0, const Border_walk& b, std::size_t j0)
{
  const auto [first_a, length_a] = at_least_one_edge(a, run_around(mutually_nearest(a, b), i0), b.points[j0]);
  const auto [first_b, length_b] = at_least_one_edge(b, run_around(mutually_nearest(b, a), j0), a.points[i0]);
  if (length_a == a.size() || length_b == b.size())
    return whole_loops(a, i0, b, j0);
  const std::size_t last_a = (first_a + length_a - 1) % a.size(), last_b = (first_b + length_b - 1) % b.size();
  // b's chain starts at the end nearer to the start of a's.
  const auto d2 = [](const Nearest_points::Point& p, const Nearest_points::Point& q) {
    return CGAL::squared_distance(p, q);
  };
  const bool back = d2(a.points[first_a], b.points[last_b]) + d2(a.points[last_a], b.points[first_b]) <
                    d2(a.points[first_a], b.points[first_b]) + d2(a.points[last_a], b.points[last_b]);
  return {a.leaving(first_a, false), b.leaving(back ? last_b : first_b, back), length_a - 1, length_b - 1};
}

// The vertex of `walks_a` nearest to a vertex of `walks_b` (a loop and a
// position in each); the first such pair on ties.
struct Nearest_pair
{
  std::size_t loop_a = 0, i = 0, loop_b = 0, j = 0;
};

inline Nearest_pair nearest_pair(const std::vector<Border_walk>& walks_a, const std::vector<Border_walk>& walks_b)
{
  std::vector<Nearest_points::Point> points;
  std::vector<std::pair<std::size_t, std::size_t>> where;
  for (std::size_t k = 0; k < walks_b.size(); ++k)
    for (std::size_t j = 0; j < walks_b[k].size(); ++j) {
      points.push_back(walks_b[k].points[j]);
      where.emplace_back(k, j);
    }
  const Nearest_points near_b(std::move(points));
  Nearest_pair best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < walks_a.size(); ++k)
    for (std::size_t i = 0; i < walks_a[k].size(); ++i) {
      const auto [at, d2] = near_b.nearest(walks_a[k].points[i]);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = {k, i, where[at].first, where[at].second};
      }
    }
  return best;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MERGING_INTERNAL_FACING_BORDERS_H
