// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Which points lie within a tolerance of each other, decided exactly: the
// one rule that the soup import and the merging of borders share.
//
// The rule: two points are close iff their exact Euclidean distance is at
// most the tolerance, the tolerance being the exact value of the number
// given (a double is the dyadic rational it holds). It holds on every kernel:
// with a floating-point number type neither the squared distance nor
// tolerance² is rounded (an interval filter decides, exact rationals where
// it cannot); with an exact number type the kernel's own
// `Compare_squared_distance_3` is exact already.

#ifndef CGAL_EXT_INTERNAL_CLOSE_POINTS_H
#define CGAL_EXT_INTERNAL_CLOSE_POINTS_H

#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Union_find.h>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace internal {

/// The tolerance as the kernel's number type, after checking that it is a
/// finite number >= 0.
template <class FT, class T>
FT checked_tolerance(const T& t)
{
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(t))
      throw Parameter_error("the merge tolerance must be a finite number >= 0 (it is " + std::to_string(t) + ")");
  const FT tolerance(t);
  if (CGAL::is_negative(tolerance))
    throw Parameter_error("the merge tolerance must be a finite number >= 0 (it is " +
                          std::to_string(CGAL::to_double(tolerance)) + ")");
  return tolerance;
}

/// The exact test "distance(p, q) <= tolerance".
template <class Traits>
class Within_tolerance
{
public:
  using FT = typename Traits::FT;
  using Point = typename Traits::Point_3;

  Within_tolerance(const Traits& traits, const FT& tolerance)
    : traits_(traits), tolerance_(tolerance), squared_(tolerance * tolerance)
  {}

  const FT& tolerance() const { return tolerance_; }

  bool operator()(const Point& p, const Point& q) const
  {
    if constexpr (std::is_floating_point_v<FT>)
      return within_floating(p, q);
    else
      return traits_.compare_squared_distance_3_object()(p, q, squared_) != CGAL::LARGER;
  }

private:
  // Both sides in interval arithmetic; where the intervals overlap (the
  // distance is the tolerance, or within rounding of it), exact rationals.
  bool within_floating(const Point& p, const Point& q) const
  {
    {
      using I = CGAL::Interval_nt<false>;
      typename I::Protector protect_rounding;
      const I dx = I(p.x()) - I(q.x()), dy = I(p.y()) - I(q.y()), dz = I(p.z()) - I(q.z());
      const I t(tolerance_);
      const CGAL::Uncertain<bool> within = CGAL::square(dx) + CGAL::square(dy) + CGAL::square(dz) <= CGAL::square(t);
      if (CGAL::is_certain(within))
        return CGAL::get_certain(within);
    }
    using Q = CGAL::Exact_rational;
    const Q dx = Q(p.x()) - Q(q.x()), dy = Q(p.y()) - Q(q.y()), dz = Q(p.z()) - Q(q.z());
    const Q t(tolerance_);
    return dx * dx + dy * dy + dz * dz <= t * t;
  }

  Traits traits_;
  FT tolerance_, squared_;
};

/// Points grouped by exact coincidence: `group[i]` is the group of the i-th
/// point, groups numbered in order of their first member; `first[g]` is the
/// position of group g's first member.
struct Coincident_groups
{
  std::vector<std::uint32_t> group, first;
  std::uint32_t size() const { return std::uint32_t(first.size()); }
};

/// Candidate pairs by box intersection (closed double boxes padded by the
/// tolerance and one unit in the last place, so that no close pair is
/// missed), each decided by `Within_tolerance`.
///
/// Coincident points are close to each other under any tolerance and close
/// to the same other points, while k of them make k(k - 1)/2 pairs: a soup
/// of duplicated faces has thousands at one point. So callers group them
/// first (`coincident()`, with the traits' `Compare_xyz_3`) and search pairs
/// among one point per group, in time near-linear in the number of points.
template <class Traits>
class Close_points
{
public:
  using FT = typename Traits::FT;
  using Point = typename Traits::Point_3;
  using u32 = std::uint32_t;

  Close_points(const Traits& traits, const FT& tolerance)
    : traits_(traits), within_(traits, tolerance), pad_(CGAL::to_interval(tolerance).second)
  {}

  const Within_tolerance<Traits>& within() const { return within_; }

  /// Calls `report(i, j)` once for every close pair of the points `ids`
  /// (`point_of(id)` gives a point).
  template <class PointOf, class Report>
  void self_pairs(const std::vector<u32>& ids, PointOf point_of, Report report) const
  {
    std::vector<Box> boxes = padded_boxes(ids, point_of);
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), decide(point_of, report));
  }

  /// Calls `report(i, j)` once for every close pair with `i` in `a`, `j` in `b`.
  template <class PointOf, class Report>
  void cross_pairs(const std::vector<u32>& a, const std::vector<u32>& b, PointOf point_of, Report report) const
  {
    std::vector<Box> boxes_a = padded_boxes(a, point_of), boxes_b = padded_boxes(b, point_of);
    CGAL::box_intersection_d(boxes_a.begin(), boxes_a.end(), boxes_b.begin(), boxes_b.end(),
                             decide(point_of, report));
  }

  /// The points `ids` grouped by exact coincidence (`point_of(id)` gives a
  /// point), in O(n log n) comparisons.
  template <class PointOf>
  Coincident_groups coincident(const std::vector<u32>& ids, PointOf point_of) const
  {
    const u32 n = u32(ids.size());
    const auto compare = traits_.compare_xyz_3_object();
    auto coincide = [&](u32 i, u32 j) { return compare(point_of(ids[i]), point_of(ids[j])) == CGAL::EQUAL; };
    // Sorted by point, coincident points by position: each run starts with its first member.
    std::vector<u32> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](u32 i, u32 j) {
      const CGAL::Comparison_result c = compare(point_of(ids[i]), point_of(ids[j]));
      return c != CGAL::EQUAL ? c == CGAL::SMALLER : i < j;
    });
    std::vector<u32> run_start(n);
    for (u32 k = 0; k < n; ++k)
      run_start[order[k]] = k > 0 && coincide(order[k - 1], order[k]) ? run_start[order[k - 1]] : order[k];
    Coincident_groups groups;
    groups.group.resize(n);
    for (u32 i = 0; i < n; ++i) {
      if (run_start[i] == i) {
        groups.group[i] = groups.size();
        groups.first.push_back(i);
      } else {
        groups.group[i] = groups.group[run_start[i]];
      }
    }
    return groups;
  }

  /// Classes of the points [0, n) under "close", closed transitively,
  /// numbered by their lowest member; `n_classes` receives their number.
  template <class PointOf>
  std::vector<u32> classes(u32 n, PointOf point_of, u32& n_classes) const
  {
    std::vector<u32> ids(n);
    std::iota(ids.begin(), ids.end(), 0u);
    const Coincident_groups groups = coincident(ids, point_of);
    Union_find sets(n);
    for (u32 i = 0; i < n; ++i)
      sets.unite(i, groups.first[groups.group[i]]);
    // One point per group: its first member (the ids are the positions).
    self_pairs(groups.first, point_of, [&](u32 i, u32 j) { sets.unite(i, j); });
    return sets.classes(n_classes);
  }

private:
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, u32>;

  template <class PointOf>
  std::vector<Box> padded_boxes(const std::vector<u32>& ids, PointOf point_of) const
  {
    std::vector<Box> boxes;
    boxes.reserve(ids.size());
    for (u32 id : ids) {
      const CGAL::Bbox_3 b = point_of(id).bbox();
      double lo[3] = {below(b.xmin()), below(b.ymin()), below(b.zmin())};
      double hi[3] = {above(b.xmax()), above(b.ymax()), above(b.zmax())};
      boxes.emplace_back(lo, hi, id);
    }
    return boxes;
  }
  double below(double x) const { return std::nextafter(x - pad_, -HUGE_VAL); }
  double above(double x) const { return std::nextafter(x + pad_, HUGE_VAL); }

  template <class PointOf, class Report>
  auto decide(PointOf& point_of, Report& report) const
  {
    return [this, &point_of, &report](const Box& a, const Box& b) {
      if (within_(point_of(a.info()), point_of(b.info())))
        report(a.info(), b.info());
    };
  }

  Traits traits_;
  Within_tolerance<Traits> within_;
  double pad_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_INTERNAL_CLOSE_POINTS_H
