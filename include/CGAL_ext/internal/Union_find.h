// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Disjoint sets of the indices [0, n), on Boost's array-based disjoint sets,
// with the one numbering of classes the library uses: by lowest member.

#ifndef CGAL_EXT_INTERNAL_UNION_FIND_H
#define CGAL_EXT_INTERNAL_UNION_FIND_H

#include <boost/pending/disjoint_sets.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL_ext {
namespace internal {

class Union_find
{
public:
  using u32 = std::uint32_t;

  explicit Union_find(u32 n) : sets_(n) {}

  void unite(u32 a, u32 b) { sets_.union_set(a, b); }
  u32 find(u32 a) { return u32(sets_.find_set(a)); }
  bool same(u32 a, u32 b) { return find(a) == find(b); }

  /// The class of each index, classes numbered in order of their lowest
  /// member (so the first member met of each class is its representative);
  /// `n_classes` receives their number.
  std::vector<u32> classes(u32& n_classes)
  {
    constexpr u32 none = (std::numeric_limits<u32>::max)();
    const u32 n = u32(sets_.parents().size());
    std::vector<u32> cls(n, none), class_of_root(n, none);
    n_classes = 0;
    for (u32 v = 0; v < n; ++v) {
      u32& c = class_of_root[find(v)];
      if (c == none)
        c = n_classes++;
      cls[v] = c;
    }
    return cls;
  }

private:
  boost::disjoint_sets_with_storage<> sets_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_INTERNAL_UNION_FIND_H
