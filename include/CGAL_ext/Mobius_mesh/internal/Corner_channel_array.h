// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The storage of a corner channel of Mobius_mesh (per-corner data, as OBJ's
// `vt`/`vn` and OpenSubdiv's face-varying channels model it): an array of
// value indices, one per halfedge, kept among the mesh's halfedge properties,
// and the channel's own array of values.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_ARRAY_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_ARRAY_H

#include <CGAL_ext/Mobius_mesh/internal/Property_container.h>
#include <CGAL_ext/internal/Uninitialized_array.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// What every corner channel has, whatever its value type: the value index of
// each halfedge's corner. Being one more halfedge property array, it is
// resized, compacted, copied and appended with the others; only the values
// need care (appending offsets the indices; reversing a face moves them).
class Base_corner_channel : public Base_property_array
{
public:
  static constexpr std::uint32_t no_value = (std::numeric_limits<std::uint32_t>::max)();
  // A value index per halfedge slot: large arrays on huge pages, and the
  // array a subdivision builds for its last level is taken as it is.
  using Index_array = Uninitialized_array<std::uint32_t>;

  using Base_property_array::Base_property_array;

  void resize(std::size_t n) override { index_.resize(n, no_value); }
  void reserve(std::size_t n) override { index_.reserve(n); }
  void shrink_to_fit() override { index_.shrink_to_fit(); }
  void compact(const std::vector<std::uint32_t>& kept) override
  {
    for (std::size_t i = 0; i < kept.size(); ++i)
      index_[i] = index_[kept[i]]; // kept[i] >= i
    index_.resize(kept.size());
  }
  void copy(std::size_t from, std::size_t to) override { index_[to] = index_[from]; }
  void reset(std::size_t i) override { index_[i] = no_value; }
  // The slot of a corner is the halfedge of its face that ends at it, along
  // the face's orientation: after the face is reversed, halfedge hs[i] ends
  // where hs[i-1] ended (hs is the face's cycle before the reversal).
  void reverse_face(const std::uint32_t* hs, std::size_t n) override
  {
    if (n == 0)
      return;
    const std::uint32_t last = index_[hs[n - 1]];
    for (std::size_t i = n - 1; i > 0; --i)
      index_[hs[i]] = index_[hs[i - 1]];
    index_[hs[0]] = last;
  }

  Index_array& indices() { return index_; }
  const Index_array& indices() const { return index_; }
  virtual std::size_t number_of_values() const = 0;
  // Drops the values that no slot names, keeping the others in their order
  // and the first `kept_prefix` ones whether named or not (where a caller
  // holds their indices).
  virtual void remove_unused_values(std::size_t kept_prefix) = 0;

protected:
  // Appends the indices [from, from + n) of `o`, shifted by `offset` (null stays null).
  void append_indices(const Base_corner_channel& o, std::size_t from, std::size_t n, std::uint32_t offset)
  {
    index_.reserve(index_.size() + n);
    for (std::size_t i = from; i < from + n; ++i)
      index_.push_back(o.index_[i] == no_value ? no_value : o.index_[i] + offset);
  }

  Index_array index_;
};

template <class T>
class Corner_channel_array final : public Base_corner_channel
{
public:
  explicit Corner_channel_array(std::string name) : Base_corner_channel(std::move(name)) {}

  // A join: the other mesh's values follow this one's, its indices shifted.
  void append_from(const Base_property_array& other, std::size_t from, std::size_t n) override
  {
    const auto& o = static_cast<const Corner_channel_array&>(other);
    append_indices(o, from, n, std::uint32_t(values_.size()));
    values_.insert(values_.end(), o.values_.begin(), o.values_.end());
  }
  // A copy between meshes, element by element: the indices keep naming the
  // source's values, which this channel takes. The copy runs in blocks, on
  // several threads under CGAL::Parallel_tag: only the first block copies
  // the values, and no block reads them.
  bool transfer(const Base_property_array& source, const Transfer_sources& sources) override
  {
    if (source.value_type() != value_type())
      return false;
    const auto& from = static_cast<const Corner_channel_array&>(source);
    if (&from != this && sources.begin == 0)
      values_ = from.values_;
    const std::size_t end = (std::min)(sources.end, sources.source_of.size());
    for (std::size_t i = sources.begin; i < end; ++i)
      if (sources.source_of[i] != Transfer_sources::no_source)
        index_[sources.first + i] = from.index_[sources.source_of[i]];
    return true;
  }
  std::unique_ptr<Base_property_array> clone() const override { return std::make_unique<Corner_channel_array>(*this); }
  std::unique_ptr<Base_property_array> empty_clone() const override
  {
    return std::make_unique<Corner_channel_array>(name());
  }
  // Not T itself: a channel is found only as a channel, never as a halfedge map.
  const std::type_info& value_type() const override { return typeid(Corner_channel_array); }
  std::size_t number_of_values() const override { return values_.size(); }
  void remove_unused_values(std::size_t kept_prefix) override
  {
    const std::size_t n = values_.size();
    std::vector<std::uint32_t> renamed(n, no_value);
    std::fill_n(renamed.begin(), (std::min)(kept_prefix, n), 0u);
    for (std::uint32_t i : index_)
      if (i < n) // (an index past the values names none)
        renamed[i] = 0;
    std::uint32_t kept = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (renamed[i] != no_value) {
        if (kept != i) // (a self-move would leave some types empty)
          values_[kept] = std::move(values_[i]);
        renamed[i] = kept++;
      }
    values_.erase(values_.begin() + kept, values_.end());
    for (std::uint32_t& i : index_)
      if (i < n)
        i = renamed[i];
  }

  std::vector<T>& values() { return values_; }

private:
  std::vector<T> values_;
};

/// \ingroup PkgMobiusMesh
///
/// A handle on one corner channel of a `Mobius_mesh` (see
/// `Mobius_mesh::add_corner_channel()`): the channel's values, and for each
/// face corner the index of its value. A corner is named by its *slot*, the
/// halfedge of its face that ends at it along the face's orientation
/// (`Mobius_mesh::corner(d)` gives the slot of the corner of `face(d)` at
/// `target(d)` for any face dart `d`, flipped or not). Two corners at one
/// vertex that hold the same index are continuous there; different indices
/// make a seam. A corner that was never given an index holds `no_value()`.
/// The handle stays valid while the channel exists, across insertions.
///
/// \tparam H the halfedge index type of the mesh
/// \tparam T the value type
template <class H, class T>
class Corner_channel
{
public:
  /// The value type.
  using value_type = T;
  /// The index of no value.
  static constexpr std::uint32_t no_value() { return Base_corner_channel::no_value; }

  /// A null handle.
  Corner_channel() = default;
  /// The handle of `array` (internal).
  explicit Corner_channel(Corner_channel_array<T>* array) : array_(array) {}

  /// The channel's values: an index `i` names `values()[i]`.
  std::vector<T>& values() const { return array_->values(); }
  /// The number of values.
  std::size_t number_of_values() const { return array_->values().size(); }
  /// Appends `t` to the values and returns its index.
  std::uint32_t add_value(const T& t) const
  {
    array_->values().push_back(t);
    return std::uint32_t(array_->values().size() - 1);
  }

  /// The value index of the corner in slot `h` (`no_value()` if none).
  std::uint32_t index(H h) const { return array_->indices()[h.idx()]; }
  /// Gives the corner in slot `h` the value index `i`.
  void set_index(H h, std::uint32_t i) const { array_->indices()[h.idx()] = i; }
  /// The value of the corner in slot `h`, which must have one. It is shared
  /// by all the corners that hold the same index.
  T& operator[](H h) const { return array_->values()[index(h)]; }
  /// True if the corner in slot `h` has a value.
  bool has_value(H h) const { return index(h) != no_value(); }

  /// The channel's name.
  const std::string& name() const { return array_->name(); }
  /// False for a null handle.
  explicit operator bool() const { return array_ != nullptr; }
  ///@{
  /// Two handles are equal if they name the same channel.
  bool operator==(const Corner_channel& o) const { return array_ == o.array_; }
  bool operator!=(const Corner_channel& o) const { return array_ != o.array_; }
  ///@}
  /// The storage (internal).
  Corner_channel_array<T>* array() const { return array_; }

private:
  Corner_channel_array<T>* array_ = nullptr;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_ARRAY_H
