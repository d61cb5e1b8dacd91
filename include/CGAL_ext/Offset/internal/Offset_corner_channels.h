// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The corner channels of <CGAL_ext/offset_mesh.h>: each corner of a copy of
// an input face takes the value of the input corner it copies, whatever the
// channel's value type; a rim corner takes none. Corner normals turn with the
// side they are on.

#ifndef CGAL_EXT_OFFSET_INTERNAL_OFFSET_CORNER_CHANNELS_H
#define CGAL_EXT_OFFSET_INTERNAL_OFFSET_CORNER_CHANNELS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/exceptions.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Where each corner of the offset's polygons comes from: for polygon p, the
// input corner slot of each of its corners in the polygon's order (none for
// a rim corner), and whether p is the copy of its face on the face's back
// side (the reversed copy). Kept only where the input has channels.
class Offset_corner_sources
{
public:
  static constexpr std::uint32_t none = Base_corner_channel::no_value;

  explicit Offset_corner_sources(bool kept) : kept_(kept) {}

  void add_polygon(const std::vector<std::uint32_t>& slots, bool back)
  {
    if (!kept_)
      return;
    slots_.push_back(slots);
    back_.push_back(back ? 1 : 0);
  }
  void add_rim(std::size_t corners) { add_polygon(std::vector<std::uint32_t>(corners, none), false); }

  // Puts the channels of `input` on `built`, the mesh of the polygons as
  // polygon_soup_to_mobius_mesh() builds it before orienting it (face p is
  // polygon p, its halfedge ending at the polygon's corner 1). Returns the
  // number of corners left without a value (rim corners), per channel.
  template <class P>
  std::size_t carry(const Mobius_mesh<P>& input, Mobius_mesh<P>& built) const
  {
    if (!kept_ || input.corner_channels().empty())
      return 0;
    std::vector<std::uint32_t> source_of(built.num_halfedges(), Transfer_sources::no_source);
    std::vector<std::uint8_t> on_back(built.num_halfedges(), 0);
    std::size_t without = 0;
    for (std::size_t p = 0; p < slots_.size(); ++p) {
      const std::vector<std::uint32_t>& slots = slots_[p];
      std::size_t k = 1;
      for (Dart d : halfedges_around_face(built.halfedge(Face_index(std::uint32_t(p))), built)) {
        const std::uint32_t slot = slots[k++ % slots.size()];
        source_of[built.corner(d).idx()] = slot == none ? Transfer_sources::no_source : slot;
        on_back[built.corner(d).idx()] = back_[p];
        without += slot == none ? 1 : 0;
      }
    }
    const Property_container& from = Connectivity_access::properties<Halfedge_index>(input);
    Property_container& to = Connectivity_access::properties<Halfedge_index>(built);
    for (const auto& array : from.arrays())
      if (dynamic_cast<const Base_corner_channel*>(array.get()) != nullptr)
        if (Base_property_array* channel = to.add_like(*array)) // (a new mesh: no name is taken)
          channel->transfer(*array, Transfer_sources{0, source_of});
    turn_back_normals(built, on_back);
    return without;
  }

private:
  // A corner normal is seen from its face's front: on the copy of a face on
  // its back side it points the other way. The turned values are appended;
  // those no corner names any longer are dropped.
  template <class P>
  static void turn_back_normals(Mobius_mesh<P>& built, const std::vector<std::uint8_t>& on_back)
  {
    auto normals = built.template corner_channel<Corner_normal<P>>(corner_normal_name);
    if (!normals)
      return;
    const std::size_t n = normals->number_of_values();
    if (n > (none - 1) / 2)
      throw Size_error("offset_mesh: the corner normals turned to the back side would be " + std::to_string(2 * n) +
                         " values, more than the mesh's 32-bit indices hold",
                       "corner normal values", 2 * n, none - 1);
    for (std::size_t i = 0; i < n; ++i)
      normals->values().push_back(-normals->values()[i]);
    for (Halfedge_index h : built.halfedges())
      if (on_back[h.idx()] && normals->has_value(h))
        normals->set_index(h, normals->index(h) + std::uint32_t(n));
    normals->array()->remove_unused_values();
  }

  bool kept_;
  std::vector<std::vector<std::uint32_t>> slots_;
  std::vector<std::uint8_t> back_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_OFFSET_INTERNAL_OFFSET_CORNER_CHANNELS_H
