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

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Which faces of `m` an orientation of it reversed: records each face's
// first two corners before, and finds them in the other order after. A
// reversed face keeps its corners' values at their vertices, corner normals
// included, so those point to the face's back once it is reversed.
template <class P>
class Reversed_faces
{
public:
  // Records nothing where `needed` is false (no channel to turn).
  Reversed_faces(const Mobius_mesh<P>& m, bool needed) : first_(needed ? m.num_faces() : 0)
  {
    if (!needed)
      return;
    for (Face_index f : m.faces()) {
      const Dart d = m.halfedge(f);
      first_[f.idx()] = {m.target(d), m.target(m.next(d))};
    }
  }
  // After the orientation: whether face f runs the other way round now.
  bool reversed(const Mobius_mesh<P>& m, Face_index f) const
  {
    if (first_.empty())
      return false;
    const auto& [a, b] = first_[f.idx()];
    for (Dart d : halfedges_around_face(m.halfedge(f), m))
      if (m.target(d) == a)
        return m.target(m.next(d)) != b;
    return false;
  }

private:
  std::vector<std::pair<Vertex_index, Vertex_index>> first_;
};

// Where each corner of the offset's polygons comes from: for polygon p, the
// input corner slot of each of its corners in the polygon's order (none for
// a rim corner), and whether the corner normals of the input point to the
// other side of p than p's own (p is the copy of its face on the face's back
// side, or the face was reversed before the copies were made, not both).
// Kept only where the input has channels.
class Offset_corner_sources
{
public:
  static constexpr std::uint32_t none = Base_corner_channel::no_value;

  explicit Offset_corner_sources(bool kept) : kept_(kept) {}

  void add_polygon(const std::vector<std::uint32_t>& slots, bool normals_turned)
  {
    if (!kept_)
      return;
    slots_.push_back(slots);
    back_.push_back(normals_turned ? 1 : 0);
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
        const std::size_t h = built.corner(d).idx();
        if (h >= on_back.size())
          continue; // never (a face's corner is a halfedge): GCC 12 at -O3 warns of a write past the end
        source_of[h] = slot == none ? Transfer_sources::no_source : slot;
        on_back[h] = back_[p];
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
  // those no corner names any longer are dropped. (offset_mesh() refuses a
  // "c:normal" channel of a type not turned here, before any work.)
  template <class P>
  static void turn_back_normals(Mobius_mesh<P>& built, const std::vector<std::uint8_t>& on_back)
  {
    turn_back<Corner_normal<P>>(built, on_back, [](const auto& n) { return -n; });
    const auto negate = [](auto a) {
      for (auto& x : a)
        x = -x;
      return a;
    };
    turn_back<std::array<double, 3>>(built, on_back, negate);
    turn_back<std::array<float, 3>>(built, on_back, negate);
  }

  template <class T, class P, class Negate>
  static void turn_back(Mobius_mesh<P>& built, const std::vector<std::uint8_t>& on_back, const Negate& negate)
  {
    auto normals = built.template corner_channel<T>(corner_normal_name);
    if (!normals)
      return;
    const std::size_t n = normals->number_of_values();
    if (n > (none - 1) / 2)
      throw Size_error("offset_mesh: the corner normals turned to the back side would be " + std::to_string(2 * n) +
                         " values, more than the mesh's 32-bit indices hold",
                       "corner normal values", 2 * n, none - 1);
    for (std::size_t i = 0; i < n; ++i)
      normals->values().push_back(negate(normals->values()[i]));
    for (Halfedge_index h : built.halfedges())
      if (on_back[h.idx()] && normals->has_value(h))
        normals->set_index(h, normals->index(h) + std::uint32_t(n));
    normals->array()->remove_unused_values(0);
  }

public:
  // Refuses a "c:normal" channel whose values the offset could not turn.
  template <class P>
  static void require_turnable_normals(const Mobius_mesh<P>& mesh)
  {
    const auto& names = mesh.corner_channels();
    if (std::find(names.begin(), names.end(), corner_normal_name) == names.end() ||
        mesh.template corner_channel<Corner_normal<P>>(corner_normal_name) ||
        mesh.template corner_channel<std::array<double, 3>>(corner_normal_name) ||
        mesh.template corner_channel<std::array<float, 3>>(corner_normal_name))
      return;
    throw Parameter_error(std::string("offset_mesh: the corner channel \"") + corner_normal_name +
                          "\" has values of a type the offset cannot turn to the back side (the kernel's Vector_3 "
                          "or std::array of 3 doubles or floats)");
  }

private:
  bool kept_;
  std::vector<std::vector<std::uint32_t>> slots_;
  std::vector<std::uint8_t> back_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_OFFSET_INTERNAL_OFFSET_CORNER_CHANNELS_H
