// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Nearest-point queries on a fixed set of points (CGAL's kd-tree), in double
// precision: the manual merge uses them to choose which border parts face
// each other, a choice of what to glue and not a geometric decision, so
// coordinates rounded to doubles are good enough on every kernel.

#ifndef CGAL_EXT_INTERNAL_NEAREST_POINTS_H
#define CGAL_EXT_INTERNAL_NEAREST_POINTS_H

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

class Nearest_points
{
public:
  using Kernel = CGAL::Simple_cartesian<double>;
  using Point = Kernel::Point_3;

  template <class P>
  static Point rounded(const P& p)
  {
    return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  explicit Nearest_points(std::vector<Point> points)
    : points_(std::move(points)),
      tree_(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(points_.size()),
            Splitter(), Traits(CGAL::make_property_map(std::as_const(points_))))
  {}
  // The tree refers to `points_`: neither may move.
  Nearest_points(const Nearest_points&) = delete;
  Nearest_points& operator=(const Nearest_points&) = delete;

  /// The index of a point nearest to `q` (the set must not be empty) and its squared distance.
  std::pair<std::size_t, double> nearest(const Point& q) const
  {
    const Search search(tree_, q, 1, 0, true, Distance(CGAL::make_property_map(points_)));
    const auto& found = *search.begin();
    return {found.first, found.second};
  }

  const Point& point(std::size_t i) const { return points_[i]; }
  std::size_t size() const { return points_.size(); }

private:
  using Map = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Map, CGAL::Search_traits_3<Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = Search::Tree;
  using Splitter = Tree::Splitter;
  using Distance = Search::Distance;

  std::vector<Point> points_;
  Tree tree_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_INTERNAL_NEAREST_POINTS_H
