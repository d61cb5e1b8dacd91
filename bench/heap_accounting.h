// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Heap accounting for the benchmark programs: counting replacements of the
// global operator new / delete.
//
// This header DEFINES the replaceable global operators (which cannot be
// inline), so it must be included by exactly one translation unit of each
// program: the program's main `bench_<name>.cpp`, never a further part
// `bench_<name>.<part>.cpp` (such as bench_soup_import.mobius_mesh.cpp), or
// the program fails to link with duplicate definitions.
//
// Every allocation of the program goes through these; they count only while
// `heap::counting` is set, so timed loops run at the speed of plain
// malloc/free. A block is counted at malloc_usable_size, the space the heap
// really gives it. Blocks counted must be freed while counting or not at all,
// and blocks allocated before counting must not be freed while counting:
// the measuring code of each program ensures both.

#ifndef CGAL_EXT_BENCH_HEAP_ACCOUNTING_H
#define CGAL_EXT_BENCH_HEAP_ACCOUNTING_H

#include <malloc.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace heap {
inline bool counting = false;
inline std::int64_t live = 0;
inline std::int64_t peak = 0;

inline void on_alloc(void* p)
{
  if (counting) {
    live += std::int64_t(malloc_usable_size(p));
    peak = (std::max)(peak, live);
  }
}
inline void on_free(void* p)
{
  if (counting && p)
    live -= std::int64_t(malloc_usable_size(p));
}
inline void* allocate(std::size_t n)
{
  void* p = std::malloc(n ? n : 1);
  if (!p)
    throw std::bad_alloc();
  on_alloc(p);
  return p;
}
inline void* allocate_aligned(std::size_t n, std::align_val_t al)
{
  const std::size_t a = (std::max)(std::size_t(al), sizeof(void*));
  void* p = nullptr;
  if (posix_memalign(&p, a, n ? n : 1) != 0)
    throw std::bad_alloc();
  on_alloc(p);
  return p;
}
inline void release(void* p) noexcept
{
  on_free(p);
  std::free(p);
}
} // namespace heap

void* operator new(std::size_t n) { return heap::allocate(n); }
void* operator new[](std::size_t n) { return heap::allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
  try { return heap::allocate(n); } catch (...) { return nullptr; }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept
{
  try { return heap::allocate(n); } catch (...) { return nullptr; }
}
void* operator new(std::size_t n, std::align_val_t al) { return heap::allocate_aligned(n, al); }
void* operator new[](std::size_t n, std::align_val_t al) { return heap::allocate_aligned(n, al); }
void operator delete(void* p) noexcept { heap::release(p); }
void operator delete[](void* p) noexcept { heap::release(p); }
void operator delete(void* p, std::size_t) noexcept { heap::release(p); }
void operator delete[](void* p, std::size_t) noexcept { heap::release(p); }
void operator delete(void* p, std::align_val_t) noexcept { heap::release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { heap::release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { heap::release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { heap::release(p); }

#endif // CGAL_EXT_BENCH_HEAP_ACCOUNTING_H
