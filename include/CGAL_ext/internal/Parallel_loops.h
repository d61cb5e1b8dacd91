// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Loops over index ranges that run with TBB for `CGAL::Parallel_tag` and as
// plain loops for `CGAL::Sequential_tag`, giving the same result either way:
// what the subdivision steps and the connectivity builder run on.

#ifndef CGAL_EXT_INTERNAL_PARALLEL_LOOPS_H
#define CGAL_EXT_INTERNAL_PARALLEL_LOOPS_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_scan.h>
#endif

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace CGAL_ext {
namespace internal {

// Whether `ConcurrencyTag` asks for TBB.
template <class ConcurrencyTag>
constexpr bool is_parallel_tag = std::is_convertible_v<ConcurrencyTag, CGAL::Parallel_tag>;

// The elements a TBB task takes at least: enough that scheduling costs
// little next to the loop bodies, which are a few memory accesses each.
constexpr std::uint32_t parallel_grain = 4096;

// Calls body(begin, end) on blocks that cover [0, n), in parallel with TBB
// for `CGAL::Parallel_tag` (one block, [0, n), otherwise): a body that needs
// scratch space makes it once per block.
template <class ConcurrencyTag, class Body>
void for_each_block(std::uint32_t n, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (is_parallel_tag<ConcurrencyTag>) {
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, n, parallel_grain),
                      [&](const tbb::blocked_range<std::uint32_t>& r) { body(r.begin(), r.end()); });
    return;
  }
#else
  static_assert(!is_parallel_tag<ConcurrencyTag>, "CGAL::Parallel_tag needs TBB (CGAL_LINKED_WITH_TBB)");
#endif
  body(std::uint32_t(0), n);
}

// Calls body(i) for i in [0, n): in parallel with TBB for `CGAL::Parallel_tag`.
template <class ConcurrencyTag, class Body>
void for_each_index(std::uint32_t n, const Body& body)
{
  for_each_block<ConcurrencyTag>(n, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i != end; ++i)
      body(i);
  });
}

// Offsets from counts, in place: `offset[i + 1]` holds the count of element
// i on entry, `offset[0]` the first offset (0 for offsets from the start);
// on return `offset[i]` is the first offset plus the counts before i.
// Integer sums, so the blocks of the parallel scan give the serial
// numbering exactly.
template <class ConcurrencyTag, class T>
void prefix_sum(T* offset, std::uint32_t n)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (is_parallel_tag<ConcurrencyTag>) {
    const T first = offset[0];
    tbb::parallel_scan(
      tbb::blocked_range<std::uint32_t>(1, n + 1, parallel_grain), T(0),
      [&](const tbb::blocked_range<std::uint32_t>& r, T sum, bool is_final) {
        for (std::uint32_t i = r.begin(); i != r.end(); ++i) {
          sum += offset[i];
          if (is_final)
            offset[i] = first + sum;
        }
        return sum;
      },
      [](T a, T b) { return a + b; });
    return;
  }
#endif
  for (std::uint32_t i = 1; i <= n; ++i)
    offset[i] += offset[i - 1];
}

// op(... op(op(init, f(0)), f(1)) ..., f(n - 1)) for an associative and
// commutative `op` on integers (a sum, a maximum): the same whatever the
// blocks of the parallel reduction.
template <class ConcurrencyTag, class T, class F, class Op>
T reduce(std::uint32_t n, T init, const F& f, const Op& op)
{
  auto run = [&](std::uint32_t begin, std::uint32_t end, T x) {
    for (std::uint32_t i = begin; i != end; ++i)
      x = op(x, f(i));
    return x;
  };
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (is_parallel_tag<ConcurrencyTag>)
    return tbb::parallel_reduce(
      tbb::blocked_range<std::uint32_t>(0, n, parallel_grain), init,
      [&](const tbb::blocked_range<std::uint32_t>& r, T x) { return run(r.begin(), r.end(), x); }, op);
#endif
  return run(0, n, init);
}

// The number of i in [0, n) for which pred(i) holds.
template <class ConcurrencyTag, class Pred>
std::uint32_t count_if(std::uint32_t n, const Pred& pred)
{
  return reduce<ConcurrencyTag>(
    n, std::uint32_t(0), [&](std::uint32_t i) { return pred(i) ? 1u : 0u; },
    [](std::uint32_t a, std::uint32_t b) { return a + b; });
}

// x += y, atomically for `CGAL::Parallel_tag`; returns the old x. Counts
// made by several threads are integers, the same whatever the order of the
// additions.
template <class ConcurrencyTag>
std::uint32_t atomic_add(std::uint32_t& x, std::uint32_t y)
{
  if constexpr (is_parallel_tag<ConcurrencyTag>) {
    return __atomic_fetch_add(&x, y, __ATOMIC_RELAXED);
  } else {
    const std::uint32_t old = x;
    x += y;
    return old;
  }
}

// x = max(x, y), atomically for `CGAL::Parallel_tag`: the largest of the
// values several threads offer, whatever their order.
template <class ConcurrencyTag>
void atomic_max(std::uint32_t& x, std::uint32_t y)
{
  if constexpr (is_parallel_tag<ConcurrencyTag>) {
    std::uint32_t old = __atomic_load_n(&x, __ATOMIC_RELAXED);
    while (old < y && !__atomic_compare_exchange_n(&x, &old, y, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
    }
  } else {
    x = (std::max)(x, y);
  }
}

// x |= y, atomically for `CGAL::Parallel_tag` (bits of one word that
// several threads set).
template <class ConcurrencyTag>
void atomic_or(std::uint64_t& x, std::uint64_t y)
{
  if constexpr (is_parallel_tag<ConcurrencyTag>)
    __atomic_fetch_or(&x, y, __ATOMIC_RELAXED);
  else
    x |= y;
}

// Calls body(ConcurrencyTag()) if `parallel` and ConcurrencyTag asks for
// threads, body(CGAL::Sequential_tag()) otherwise: every loop of the body
// then runs in one mode, chosen at run time, with a tag that is a constant
// in it.
template <class ConcurrencyTag, class Body>
void with_concurrency(bool parallel, const Body& body)
{
  if constexpr (is_parallel_tag<ConcurrencyTag>) {
    if (parallel) {
      body(ConcurrencyTag());
      return;
    }
  }
  body(CGAL::Sequential_tag());
}

// x = 1, atomically for `CGAL::Parallel_tag` (a flag that several threads
// may raise). A flag already raised is only read: the threads then share
// its cache line instead of taking it from each other.
template <class ConcurrencyTag>
void mark(std::uint8_t& x)
{
  if constexpr (is_parallel_tag<ConcurrencyTag>) {
    if (!__atomic_load_n(&x, __ATOMIC_RELAXED))
      __atomic_store_n(&x, std::uint8_t(1), __ATOMIC_RELAXED);
  } else {
    x = 1;
  }
}

// Sorts the short lists that the per-element passes sort (the edges or
// faces at a vertex, the sides in a vertex's bucket): insertion sort,
// without std::sort's set-up, but std::sort for a long one (a vertex of
// high degree).
template <class T>
void sort_short(T* begin, T* end)
{
  if (end - begin > 32) {
    std::sort(begin, end);
    return;
  }
  for (T* i = begin + (begin != end ? 1 : 0); i < end; ++i) {
    const T x = *i;
    T* j = i;
    for (; j != begin && *(j - 1) > x; --j)
      *j = *(j - 1);
    *j = x;
  }
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_INTERNAL_PARALLEL_LOOPS_H
