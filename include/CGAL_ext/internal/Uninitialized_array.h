// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Arrays that are about to be overwritten whole do not need to be zeroed
// first: for large meshes that first pass costs as much as the writing.
// Their large buffers are on huge pages (see Huge_page_allocator.h).

#ifndef CGAL_EXT_INTERNAL_UNINITIALIZED_ARRAY_H
#define CGAL_EXT_INTERNAL_UNINITIALIZED_ARRAY_H

#include <CGAL_ext/internal/Huge_page_allocator.h>

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// As Huge_page_allocator, except that constructing without a value leaves a
// trivially copyable element unwritten: `resize(n)` then only allocates.
// Constructing from a value (`resize(n, value)`, `push_back`) is unchanged.
template <class T>
struct Overwrite_allocator : Huge_page_allocator<T>
{
  template <class U>
  struct rebind
  {
    using other = Overwrite_allocator<U>;
  };
  Overwrite_allocator() = default;
  template <class U>
  Overwrite_allocator(const Overwrite_allocator<U>&) noexcept
  {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>)
  {
    if constexpr (!std::is_trivially_copyable_v<U>)
      ::new (static_cast<void*>(p)) U();
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using Uninitialized_array = std::vector<T, Overwrite_allocator<T>>;

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_INTERNAL_UNINITIALIZED_ARRAY_H
