// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Type-erased, named struct-of-arrays storage for the per-element properties
// of Mobius_mesh (the same idea as Surface_mesh's Property_container).

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_PROPERTY_CONTAINER_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_PROPERTY_CONTAINER_H

#include <CGAL_ext/internal/Huge_page_allocator.h>

#include <CGAL/assertions.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// A value type passed as an argument, for walking a list of value types
// (the maps of a mesh are found by name and type at run time).
template <class T>
struct Type_tag
{
  using type = T;
};

// Calls f(Type_tag<T>()) for the arrays of 2 to 4 floats or doubles: the
// fixed-size values (texture coordinates, colours) that the channels,
// conversions and subdivision carry.
template <class F>
void for_each_small_array_type(F&& f)
{
  f(Type_tag<std::array<float, 2>>());
  f(Type_tag<std::array<float, 3>>());
  f(Type_tag<std::array<float, 4>>());
  f(Type_tag<std::array<double, 2>>());
  f(Type_tag<std::array<double, 3>>());
  f(Type_tag<std::array<double, 4>>());
}

// Where a transfer takes its values from: element `first + i` of the target
// takes element `source_of[i]` of the source, unless that is `no_source`.
struct Transfer_sources
{
  static constexpr std::uint32_t no_source = (std::numeric_limits<std::uint32_t>::max)();
  std::size_t first;
  const std::vector<std::uint32_t>& source_of;
  // The entries of `source_of` to copy, [begin, end): all by default, or a
  // block of them, which threads copy side by side.
  std::size_t begin = 0;
  std::size_t end = (std::numeric_limits<std::size_t>::max)();
};

class Base_property_array
{
public:
  explicit Base_property_array(std::string name) : name_(std::move(name)) {}
  virtual ~Base_property_array() = default;

  virtual void resize(std::size_t n) = 0;
  virtual void reserve(std::size_t n) = 0;
  virtual void shrink_to_fit() = 0;
  // Appends `n` elements of `other` (same type), starting at its index `from`.
  virtual void append_from(const Base_property_array& other, std::size_t from, std::size_t n) = 0;
  // Copies values from `source` as `sources` says, if it has the same value
  // type (as CGAL's Base_property_array::transfer): the array knows its own
  // type, so copies between meshes need no list of value types.
  virtual bool transfer(const Base_property_array& source, const Transfer_sources& sources) = 0;
  // Keeps the elements `kept[0], kept[1], ...` (increasing), in that order,
  // as elements 0, 1, ...: garbage collection, in place.
  virtual void compact(const std::vector<std::uint32_t>& kept) = 0;
  // Element `to` takes the value of element `from`: an element moved into
  // another's slot (in-place edits that keep the arrays compact).
  virtual void copy(std::size_t from, std::size_t to) = 0;
  // Element `i` takes the default value again (a recycled slot).
  virtual void reset(std::size_t i) = 0;
  // The face whose halfedges are `hs` (in cycle order) was reversed. A
  // halfedge value stays with its halfedge; a corner channel's moves with
  // the corner (Corner_channel_array.h).
  virtual void reverse_face(const std::uint32_t* hs, std::size_t n) { (void)hs, (void)n; }
  virtual std::unique_ptr<Base_property_array> clone() const = 0;
  virtual std::unique_ptr<Base_property_array> empty_clone() const = 0;
  virtual const std::type_info& value_type() const = 0;

  const std::string& name() const { return name_; }

private:
  std::string name_;
};

// A bool stored in a byte of its own: std::vector<bool> packs bits and has
// no `bool&` to hand out, which a property map must.
struct Bool_cell
{
  bool value = false;
  Bool_cell() = default;
  Bool_cell(bool b) : value(b) {} // implicit, so that a vector of cells fills from a bool
};

// push_back() where the caller knows there is room: without the
// reallocation path, the caller needs no stack frame.
template <class Vector, class Value>
void push_within_capacity(Vector& v, Value&& x)
{
  CGAL_precondition(v.size() < v.capacity());
#if defined(__GNUC__) || defined(__clang__)
  if (v.size() == v.capacity())
    __builtin_unreachable();
#endif
  v.push_back(std::forward<Value>(x));
}

template <class T>
using Stored_value = std::conditional_t<std::is_same_v<T, bool>, Bool_cell, T>;

template <class T>
class Property_array final : public Base_property_array
{
public:
  using Stored = Stored_value<T>;

  Property_array(std::string name, T default_value)
    : Base_property_array(std::move(name)), default_(std::move(default_value))
  {}

  void resize(std::size_t n) override
  {
    if (n == data_.size() + 1)
      push_default();
    else
      resize_slowly(n);
  }
  // One more element, with the default value. Euler operations grow the
  // arrays by one element at a time: a push_back is inline, a filling
  // resize an out-of-line call.
  [[gnu::flatten]] void push_default()
  {
    if (data_.size() < data_.capacity())
      push_within_capacity(data_, Stored(default_));
    else
      resize_slowly(data_.size() + 1);
  }
  void reserve(std::size_t n) override
  {
    if (n > data_.capacity())
      grow_capacity(n);
  }
  void shrink_to_fit() override { data_.shrink_to_fit(); }
  void append_from(const Base_property_array& other, std::size_t from, std::size_t n) override
  {
    const auto& o = static_cast<const Property_array&>(other);
    if (data_.size() + n > data_.capacity())
      grow_capacity((std::max)(data_.size() + n, 2 * data_.size())); // as insert() would grow it
    data_.insert(data_.end(), o.data_.begin() + from, o.data_.begin() + from + n);
  }
  bool transfer(const Base_property_array& source, const Transfer_sources& sources) override
  {
    if (source.value_type() != typeid(T))
      return false;
    const auto& from = static_cast<const Property_array&>(source).data_;
    const std::size_t end = (std::min)(sources.end, sources.source_of.size());
    for (std::size_t i = sources.begin; i < end; ++i)
      if (sources.source_of[i] != Transfer_sources::no_source)
        data_[sources.first + i] = from[sources.source_of[i]];
    return true;
  }
  void compact(const std::vector<std::uint32_t>& kept) override
  {
    // kept[i] >= i, so moving forward never overwrites a value still to move.
    for (std::size_t i = 0; i < kept.size(); ++i)
      if (kept[i] != i)
        data_[i] = std::move(data_[kept[i]]);
    data_.resize(kept.size(), Stored(default_));
  }
  void copy(std::size_t from, std::size_t to) override { data_[to] = data_[from]; }
  void reset(std::size_t i) override { data_[i] = Stored(default_); }
  std::unique_ptr<Base_property_array> clone() const override
  {
    return std::make_unique<Property_array>(*this);
  }
  std::unique_ptr<Base_property_array> empty_clone() const override
  {
    return std::make_unique<Property_array>(name(), default_);
  }
  const std::type_info& value_type() const override { return typeid(T); }

  T& operator[](std::size_t i)
  {
    if constexpr (std::is_same_v<T, bool>)
      return data_[i].value;
    else
      return data_[i];
  }
  std::vector<Stored>& data() { return data_; }
  const std::vector<Stored>& data() const { return data_; }
  const T& default_value() const { return default_; }

private:
  // Moves the values to a buffer of `capacity` elements advised onto huge
  // pages before anything touches it (see Huge_page_allocator.h), the part
  // the values move into included: vector::reserve() would write them before
  // the buffer could be advised, leaving them on 4 KiB pages, one fault per
  // page (half of an array doubled). The array stays a `std::vector<Stored>`, the
  // type `Property_map::data()` gives users, so the advice covers only the
  // whole huge pages inside the buffer, not its unaligned ends.
  void grow_capacity(std::size_t capacity)
  {
    std::vector<Stored> grown;
    grown.reserve(capacity);
    advise_huge_pages(grown.data(), capacity * sizeof(Stored));
    // Moved only if moving cannot throw, as vector::reserve() does: a
    // failure then leaves the values as they were.
    if constexpr (std::is_nothrow_move_constructible_v<Stored>)
      grown.insert(grown.end(), std::make_move_iterator(data_.begin()), std::make_move_iterator(data_.end()));
    else
      grown.insert(grown.end(), data_.begin(), data_.end());
    data_.swap(grown);
  }
  // Out of line, so that growing by one within capacity needs no stack frame.
  [[gnu::noinline]] void resize_slowly(std::size_t n)
  {
    if (n > data_.capacity())
      grow_capacity((std::max)(n, 2 * data_.size())); // as the vector itself grows
    if (n <= data_.size()) {
      data_.resize(n, Stored(default_));
      return;
    }
    // Within the capacity: appended one by one, not by resize(n, value),
    // whose in-place fill (vector::_M_fill_insert) is ~15 % of a warm
    // subdivision's time on the result's points.
    const Stored value(default_);
    for (std::size_t i = data_.size(); i < n; ++i)
      push_within_capacity(data_, value);
  }

  std::vector<Stored> data_;
  T default_;
};

// A lightweight handle on one property array: a model of LvaluePropertyMap.
// It stays valid while the property exists, across element insertions.
template <class Key, class T>
class Property_map
{
public:
  using key_type = Key;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;

  Property_map() = default;
  explicit Property_map(Property_array<T>* array) : array_(array) {}

  reference operator[](Key k) const { return (*array_)[k.idx()]; }
  /// The values in index order (bools as `Bool_cell`s, one byte each).
  std::vector<Stored_value<T>>& data() const { return array_->data(); }
  explicit operator bool() const { return array_ != nullptr; }

  friend reference get(const Property_map& m, Key k) { return m[k]; }
  friend void put(const Property_map& m, Key k, const T& v) { m[k] = v; }

  bool operator==(const Property_map& o) const { return array_ == o.array_; }
  bool operator!=(const Property_map& o) const { return array_ != o.array_; }

  Property_array<T>* array() const { return array_; }

private:
  Property_array<T>* array_ = nullptr;
};

// The named arrays of one element kind; all arrays always have the same size.
class Property_container
{
public:
  Property_container() = default;
  Property_container(const Property_container& o) { *this = o; }
  Property_container(Property_container&&) noexcept = default;
  Property_container& operator=(const Property_container& o)
  {
    if (this == &o)
      return *this;
    arrays_.clear();
    arrays_.reserve(o.arrays_.size());
    for (const auto& a : o.arrays_)
      arrays_.push_back(a->clone());
    size_ = o.size_;
    return *this;
  }
  Property_container& operator=(Property_container&&) noexcept = default;

  std::size_t size() const { return size_; }

  void resize(std::size_t n)
  {
    for (auto& a : arrays_)
      a->resize(n);
    size_ = n;
  }
  // Records that the caller grew every array by one element itself (with
  // `Property_array::push_default()`, knowing their types).
  void grown_by_one() { ++size_; }
  void reserve(std::size_t n)
  {
    for (auto& a : arrays_)
      a->reserve(n);
    reserved_ = n;
  }
  void shrink_to_fit()
  {
    for (auto& a : arrays_)
      a->shrink_to_fit();
    reserved_ = 0;
  }
  void clear()
  {
    arrays_.clear();
    size_ = 0;
  }
  // Appends all elements of `other`; arrays of the same name and type are
  // copied, others get their default values; arrays only in `other` are added.
  void append(const Property_container& other)
  {
    const std::size_t old_size = size_;
    for (const auto& oa : other.arrays_) {
      if (find(oa->name(), oa->value_type()) == nullptr) {
        auto a = oa->empty_clone();
        a->resize(old_size);
        arrays_.push_back(std::move(a));
      }
    }
    for (auto& a : arrays_) {
      if (const Base_property_array* oa = other.find(a->name(), a->value_type()))
        a->append_from(*oa, 0, other.size_);
      else
        a->resize(old_size + other.size_);
    }
    size_ = old_size + other.size_;
  }

  // Keeps the elements listed in `kept` (increasing) of every array.
  void compact(const std::vector<std::uint32_t>& kept)
  {
    for (auto& a : arrays_)
      a->compact(kept);
    size_ = kept.size();
  }

  // Element `i` of every array takes its default value again.
  void reset(std::size_t i)
  {
    for (auto& a : arrays_)
      a->reset(i);
  }

  // Element `to` of every array takes the value of element `from`.
  void copy(std::size_t from, std::size_t to)
  {
    for (auto& a : arrays_)
      a->copy(from, to);
  }

  template <class T>
  std::pair<Property_array<T>*, bool> add(const std::string& name, const T& default_value)
  {
    if (Base_property_array* a = find_by_name(name)) {
      if (a->value_type() == typeid(T))
        return {static_cast<Property_array<T>*>(a), false};
      return {nullptr, false};
    }
    auto array = std::make_unique<Property_array<T>>(name, default_value);
    // Room for what reserve() asked of the others (the removal flags, made
    // at the first removal, would otherwise grow by reallocation).
    array->reserve(reserved_);
    array->resize(size_);
    Property_array<T>* raw = array.get();
    arrays_.push_back(std::move(array));
    return {raw, true};
  }

  // The array of type `A` (a subclass of Base_property_array) named
  // `name`, added if there is none (built from `name`); null and false if
  // the name is taken by an array of another type.
  template <class A>
  std::pair<A*, bool> add_array(const std::string& name)
  {
    if (Base_property_array* a = find_by_name(name))
      return {dynamic_cast<A*>(a), false};
    auto array = std::make_unique<A>(name);
    array->reserve(reserved_);
    array->resize(size_);
    A* raw = array.get();
    arrays_.push_back(std::move(array));
    return {raw, true};
  }
  // Adds `array`, built whole by its caller with one element per slot
  // (spares a large array its fill). Null if its name is taken or its size
  // is not the container's.
  template <class A>
  A* adopt_array(std::unique_ptr<A> array, std::size_t array_size)
  {
    if (array_size != size_ || find_by_name(array->name()))
      return nullptr;
    array->reserve(reserved_);
    A* raw = array.get();
    arrays_.push_back(std::move(array));
    return raw;
  }
  // The array of type `A` named `name`, or null.
  template <class A>
  A* find_array(const std::string& name) const
  {
    return dynamic_cast<A*>(find_by_name(name));
  }
  // Calls f(array) for each array of type `A` (a base class included).
  template <class A, class F>
  void for_each_array(F&& f) const
  {
    for (const auto& a : arrays_)
      if (auto* x = dynamic_cast<A*>(a.get()))
        f(*x);
  }

  template <class T>
  Property_array<T>* get(const std::string& name) const
  {
    return static_cast<Property_array<T>*>(find(name, typeid(T)));
  }

  // The array named as `like` with its value type, added (with `like`'s
  // default value) if there is none; null if the name is taken by another type.
  Base_property_array* add_like(const Base_property_array& like)
  {
    if (Base_property_array* a = find_by_name(like.name()))
      return a->value_type() == like.value_type() ? a : nullptr;
    auto array = like.empty_clone();
    array->reserve(reserved_);
    array->resize(size_);
    arrays_.push_back(std::move(array));
    return arrays_.back().get();
  }

  // The arrays, for walking them all (transfers between meshes).
  const std::vector<std::unique_ptr<Base_property_array>>& arrays() const { return arrays_; }

  bool remove(const Base_property_array* array)
  {
    for (auto it = arrays_.begin(); it != arrays_.end(); ++it) {
      if (it->get() == array) {
        arrays_.erase(it);
        return true;
      }
    }
    return false;
  }

  std::vector<std::string> names() const
  {
    std::vector<std::string> result;
    for (const auto& a : arrays_)
      result.push_back(a->name());
    return result;
  }

private:
  Base_property_array* find(const std::string& name, const std::type_info& type) const
  {
    for (const auto& a : arrays_)
      if (a->name() == name && a->value_type() == type)
        return a.get();
    return nullptr;
  }
  Base_property_array* find_by_name(const std::string& name) const
  {
    for (const auto& a : arrays_)
      if (a->name() == name)
        return a.get();
    return nullptr;
  }

  std::vector<std::unique_ptr<Base_property_array>> arrays_;
  std::size_t size_ = 0;
  std::size_t reserved_ = 0; // the last reserve()
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_PROPERTY_CONTAINER_H
