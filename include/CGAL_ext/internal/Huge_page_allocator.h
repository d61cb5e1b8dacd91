// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Large arrays on transparent huge pages. A large mesh's arrays are written
// into fresh memory, and touching a fresh 4 KiB page costs a page fault of
// ~10-17 us: for a mesh of a million faces that is most of the import's time.
// Linux can back an anonymous range with 2 MiB pages instead (one fault per
// 512 small pages), but where THP is in `madvise` mode (the common default)
// only for ranges that ask for it with `madvise(MADV_HUGEPAGE)` before they
// are first touched, and only for whole 2 MiB-aligned pages of the range.

#ifndef CGAL_EXT_INTERNAL_HUGE_PAGE_ALLOCATOR_H
#define CGAL_EXT_INTERNAL_HUGE_PAGE_ALLOCATOR_H

#if defined(__linux__) && defined(__has_include)
#  if __has_include(<sys/mman.h>)
#    include <sys/mman.h>
#  endif
#endif

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace internal {

/// The size of a transparent huge page on x86-64 and on most AArch64
/// kernels; blocks from this size up are allocated on its boundaries.
constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;

/// Whether `advise_huge_pages()` does anything on this system.
#ifdef MADV_HUGEPAGE
constexpr bool can_advise_huge_pages = true;
#else
constexpr bool can_advise_huge_pages = false;
#endif

/// Asks the kernel to back the whole huge pages inside `[p, p + bytes)` with
/// huge pages when they are first touched. Only advice: pages already
/// touched stay as they are, and where the kernel refuses (THP off, no
/// `madvise`) nothing changes but the speed, so the result is not checked.
inline void advise_huge_pages(void* p, std::size_t bytes) noexcept
{
#ifdef MADV_HUGEPAGE
  const std::uintptr_t mask = huge_page_bytes - 1;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + mask) & ~mask;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~mask;
  if (begin < end)
    (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

/// A standard allocator (stateless, all instances equal) for large arrays:
/// a block of `huge_page_bytes` or more is advised to be backed by huge
/// pages, so that all of it but the partial huge pages at its two ends
/// faults in 2 MiB at a time. Blocks are allocated as by `std::allocator`,
/// not on huge-page boundaries: arrays that all start at the same offset
/// modulo 4 KiB make the loops that write several of them at one index
/// (the splits, the builder) 15-25 % slower once their pages are in (the
/// processor takes their loads and stores for dependent: 4K aliasing),
/// which costs more to a program that builds meshes repeatedly than the
/// faults of the ends cost a single build.
template <class T>
struct Huge_page_allocator
{
  using value_type = T;
  using is_always_equal = std::true_type;
  using propagate_on_container_move_assignment = std::true_type;

  Huge_page_allocator() = default;
  template <class U>
  Huge_page_allocator(const Huge_page_allocator<U>&) noexcept
  {}

  T* allocate(std::size_t n)
  {
    if (n > (std::numeric_limits<std::size_t>::max)() / sizeof(T))
      throw std::bad_array_new_length();
    T* p = std::allocator<T>().allocate(n);
    if (is_large(n))
      advise_huge_pages(p, n * sizeof(T));
    return p;
  }

  void deallocate(T* p, std::size_t n) noexcept { std::allocator<T>().deallocate(p, n); }

  /// Whether a block of `n` elements is advised to be on huge pages.
  static constexpr bool is_large(std::size_t n) noexcept
  {
    return can_advise_huge_pages && n >= (huge_page_bytes + sizeof(T) - 1) / sizeof(T);
  }
};

template <class T, class U>
constexpr bool operator==(const Huge_page_allocator<T>&, const Huge_page_allocator<U>&) noexcept
{
  return true;
}
template <class T, class U>
constexpr bool operator!=(const Huge_page_allocator<T>&, const Huge_page_allocator<U>&) noexcept
{
  return false;
}

/// A `std::vector` whose large buffers are on huge pages (see
/// `Huge_page_allocator`); otherwise the same, value-initialising included.
template <class T>
using Huge_page_vector = std::vector<T, Huge_page_allocator<T>>;

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_INTERNAL_HUGE_PAGE_ALLOCATOR_H
