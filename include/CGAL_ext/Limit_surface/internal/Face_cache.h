// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What a limit surface builds once per face and keeps, within a budget: one
// slot per face, filled by whichever thread asks first.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_FACE_CACHE_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_FACE_CACHE_H

#include <atomic>
#include <cstddef>
#include <memory>
#include <utility>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// A value of type T per index, made on first use by `make()` and kept while
// the kept values' sizes (`size_of()`) stay within a budget of bytes; past
// it a value is made for its caller alone (into `spill`), each time: the
// memory stays bounded, at the cost of building again. Threads may ask for
// any index at once: the first to store its value (a compare-and-swap)
// wins, and a thread that loses drops its own copy, so `make()` must give
// the same value to every thread; the bytes are reserved before the store,
// so threads together never pass the budget. No lock is taken: a
// std::call_once per face cost a sixth of the time of building the faces
// of a Loop surface evaluated at ten points each.
template <class T>
class Face_cache
{
public:
  Face_cache() = default;
  Face_cache(std::size_t n, std::size_t budget) : slots_(new std::atomic<T*>[n]), size_(n), budget_(budget)
  {
    for (std::size_t i = 0; i < n; ++i)
      slots_[i].store(nullptr, std::memory_order_relaxed);
  }
  Face_cache(Face_cache&& o) noexcept { take(o); }
  Face_cache& operator=(Face_cache&& o) noexcept
  {
    if (this != &o) {
      clear();
      take(o);
    }
    return *this;
  }
  Face_cache(const Face_cache&) = delete;
  Face_cache& operator=(const Face_cache&) = delete;
  ~Face_cache() { clear(); }

  std::size_t size() const { return size_; }
  std::size_t budget() const { return budget_; }
  // The bytes of the values kept (and of those being stored), as `size_of()` counted them.
  std::size_t bytes() const { return used_.load(std::memory_order_relaxed); }

  template <class Make, class SizeOf>
  const T& get(std::size_t i, Make&& make, const SizeOf& size_of, std::unique_ptr<T>& spill) const
  {
    if (const T* known = slots_[i].load(std::memory_order_acquire))
      return *known;
    std::unique_ptr<T> made = make();
    const std::size_t bytes = size_of(*made);
    if (used_.fetch_add(bytes, std::memory_order_relaxed) + bytes > budget_) {
      used_.fetch_sub(bytes, std::memory_order_relaxed);
      if (const T* known = slots_[i].load(std::memory_order_acquire)) // stored meanwhile
        return *known;
      spill = std::move(made);
      return *spill;
    }
    T* expected = nullptr;
    if (slots_[i].compare_exchange_strong(expected, made.get(), std::memory_order_acq_rel, std::memory_order_acquire))
      return *made.release();
    used_.fetch_sub(bytes, std::memory_order_relaxed);
    return *expected; // another thread's, equal to ours
  }

private:
  void take(Face_cache& o) noexcept
  {
    slots_ = std::move(o.slots_);
    size_ = std::exchange(o.size_, 0);
    budget_ = o.budget_;
    used_.store(o.used_.exchange(0, std::memory_order_relaxed), std::memory_order_relaxed);
  }
  void clear()
  {
    for (std::size_t i = 0; i < size_; ++i)
      delete slots_[i].load(std::memory_order_relaxed);
    slots_.reset();
    size_ = 0;
    used_.store(0, std::memory_order_relaxed);
  }

  std::unique_ptr<std::atomic<T*>[]> slots_;
  std::size_t size_ = 0;
  std::size_t budget_ = 0;
  mutable std::atomic<std::size_t> used_{0};
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_FACE_CACHE_H
