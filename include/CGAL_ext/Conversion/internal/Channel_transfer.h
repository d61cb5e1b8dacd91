// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Corner channels between Mobius_mesh and CGAL::Surface_mesh. A channel is a
// Surface_mesh halfedge map of the same name ("c:uv"): each face halfedge
// holds the value of the corner at its target in its face, as CGAL's
// parameterization keeps texture coordinates in halfedge maps. Converted
// back, the halfedge maps named "c:..." become channels again, corners at a
// vertex with equal values sharing one value.

#ifndef CGAL_EXT_CONVERSION_INTERNAL_CHANNEL_TRANSFER_H
#define CGAL_EXT_CONVERSION_INTERNAL_CHANNEL_TRANSFER_H

#include <CGAL_ext/Conversion/internal/Property_transfer.h>
#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// The value types of the channels that the conversions carry: those of the
// property maps (but bool, which a channel's std::vector cannot hand out by
// reference), and 2 to 4 floats or doubles in an std::array and, with one
// point type on both sides, the kernel's 2D points and vectors.
template <class P1, class P2, class F>
void for_each_channel_type(F&& f)
{
  for_each_transferable_type<P1, P2>([&](auto tag) {
    if constexpr (!std::is_same_v<typename decltype(tag)::type, bool>)
      f(tag);
  });
  for_each_small_array_type(f);
  if constexpr (std::is_same_v<P1, P2>) {
    using K = typename CGAL::Kernel_traits<P1>::Kernel;
    f(Type_tag<typename K::Point_2>());
    f(Type_tag<typename K::Vector_2>());
  }
}

// What became of the channels in a conversion to a Surface_mesh.
struct Channel_transfer_report
{
  std::vector<std::string> not_carried; // channels of a value type not in the list above
  std::size_t corners_without_value = 0; // given the type's default value (the origin)
};

// Mobius_mesh -> Surface_mesh: `corners` lists (our corner slot, the
// Surface_mesh face halfedge that ends at that corner), for every face corner.
template <class P, class Q>
Channel_transfer_report channels_to_surface_mesh(const Mobius_mesh<P>& src, CGAL::Surface_mesh<Q>& dst,
                                                 const std::vector<std::pair<Halfedge_index,
                                                                             typename CGAL::Surface_mesh<Q>::Halfedge_index>>& corners)
{
  using SH = typename CGAL::Surface_mesh<Q>::Halfedge_index;
  Channel_transfer_report report;
  for (const std::string& name : src.corner_channels()) {
    bool carried = false;
    for_each_channel_type<P, Q>([&](auto tag) {
      using T = typename decltype(tag)::type;
      const auto channel = src.template corner_channel<T>(name);
      if (carried || !channel)
        return;
      carried = true;
      auto to = dst.template add_property_map<SH, T>(name, initialized_value<T>()).first;
      for (const auto& [slot, s] : corners) {
        if (channel->has_value(slot) && channel->index(slot) < channel->number_of_values())
          to[s] = (*channel)[slot];
        else
          ++report.corners_without_value;
      }
    });
    if (!carried)
      report.not_carried.push_back(name);
  }
  return report;
}

// Surface_mesh -> Mobius_mesh: `corners` lists (the Surface_mesh face
// halfedge, our corner slot in `dst` that ends where it does), for every
// face corner. Corners at one vertex with equal values share a value (where
// they differ, the channel has a seam).
template <class Q, class P>
void channels_from_surface_mesh(const CGAL::Surface_mesh<Q>& src, Mobius_mesh<P>& dst,
                                const std::vector<std::pair<typename CGAL::Surface_mesh<Q>::Halfedge_index,
                                                            Halfedge_index>>& corners)
{
  using SH = typename CGAL::Surface_mesh<Q>::Halfedge_index;
  for (const std::string& name : src.template properties<SH>()) {
    if (!is_corner_channel_name(name))
      continue;
    for_each_channel_type<Q, P>([&](auto tag) {
      using T = typename decltype(tag)::type;
      const auto [from, found] = src.template property_map<SH, T>(name);
      if (!found)
        return;
      auto [channel, created] = dst.template add_corner_channel<T>(name);
      if (!created)
        return; // taken by another type, or met already
      std::vector<std::vector<std::uint32_t>> at_vertex(dst.number_of_vertices()); // value indices
      for (const auto& [s, slot] : corners) {
        const T& value = from[s];
        std::vector<std::uint32_t>& known = at_vertex[dst.target(Dart(slot, false)).idx()];
        std::uint32_t index = Mobius_mesh<P>::template Corner_channel<T>::no_value();
        for (std::uint32_t i : known)
          if (channel.values()[i] == value)
            index = i;
        if (index == Mobius_mesh<P>::template Corner_channel<T>::no_value()) {
          index = channel.add_value(value);
          known.push_back(index);
        }
        channel.set_index(slot, index);
      }
    });
  }
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_CONVERSION_INTERNAL_CHANNEL_TRANSFER_H
