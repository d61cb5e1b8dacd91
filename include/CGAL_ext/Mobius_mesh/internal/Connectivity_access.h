// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Whole-array access to the storage of a Mobius_mesh, for the library's own
// algorithms: subdivision writes the connectivity by index arithmetic, and
// copies, merges and conversions carry property arrays of any value type.
// Users build and edit meshes through the public members instead; nothing
// here checks consistency (`Mobius_mesh::is_valid()` does).

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_CONNECTIVITY_ACCESS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_CONNECTIVITY_ACCESS_H

#include <CGAL_ext/Mobius_mesh/internal/Property_container.h>
#include <CGAL_ext/internal/Uninitialized_array.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

template <class P>
class Mobius_mesh;

namespace internal {

// Where `Connectivity_access::overwrite()` lets an algorithm write the arrays:
// per halfedge the target, the `Dart::bits()` of `next` and `prev` and the
// face (`Face_index::null_value` on the border); per edge the Möbius byte;
// per vertex the bits of `halfedge(v)`; per face its halfedge.
struct Connectivity_arrays
{
  std::uint32_t *target, *next_bits, *prev_bits, *face, *vertex_dart_bits, *face_halfedge;
  std::uint8_t* mobius;
};

struct Connectivity_access
{
  // Replaces the connectivity of `m` by copies of whole arrays (laid out as
  // in `Connectivity_arrays`); property maps are resized, their values reset
  // to the defaults.
  template <class P>
  static void assign(Mobius_mesh<P>& m, std::uint32_t nv, std::uint32_t ne, std::uint32_t nf,
                     const std::uint32_t* target, const std::uint32_t* next_bits, const std::uint32_t* prev_bits,
                     const std::uint32_t* face, const std::uint8_t* mobius, const std::uint32_t* vertex_dart_bits,
                     const std::uint32_t* face_halfedge)
  {
    const std::size_t nh = 2 * std::size_t(ne);
    assign_values(m.h_target_, target, nh);
    assign_values(m.h_next_, next_bits, nh);
    assign_values(m.h_prev_, prev_bits, nh);
    assign_values(m.h_face_, face, nh);
    assign_values(m.e_mobius_, mobius, ne);
    assign_values(m.v_halfedge_, vertex_dart_bits, nv);
    assign_values(m.f_halfedge_, face_halfedge, nf);
    m.recount_mobius_edges();
    resize_property_maps(m, nv, nh, ne, nf);
  }

  // As `assign()`, for an algorithm that writes the arrays in place instead
  // of copying them in (so a large result is never held twice): resizes them
  // *without initialising them* and returns where to write. Property maps are
  // emptied until `reset_property_maps()`, to be called once every value is
  // written.
  template <class P>
  static Connectivity_arrays overwrite(Mobius_mesh<P>& m, std::uint32_t nv, std::uint32_t ne, std::uint32_t nf)
  {
    const std::size_t nh = 2 * std::size_t(ne);
    Connectivity_arrays a;
    a.target = resize_for_overwrite(m.h_target_, nh);
    a.next_bits = resize_for_overwrite(m.h_next_, nh);
    a.prev_bits = resize_for_overwrite(m.h_prev_, nh);
    a.face = resize_for_overwrite(m.h_face_, nh);
    a.vertex_dart_bits = resize_for_overwrite(m.v_halfedge_, nv);
    a.face_halfedge = resize_for_overwrite(m.f_halfedge_, nf);
    a.mobius = resize_for_overwrite(m.e_mobius_, ne);
    m.mobius_edges_ = Mobius_mesh<P>::unknown_count; // counted once written
    resize_property_maps(m, 0, 0, 0, 0);
    return a;
  }

  // Sizes every property map of `m` to the number of its elements, with all
  // values reset to the map's default.
  template <class P>
  static void reset_property_maps(Mobius_mesh<P>& m)
  {
    m.recount_mobius_edges();
    resize_property_maps(m, m.num_vertices(), m.num_halfedges(), m.num_edges(), m.num_faces());
  }
  // As reset_property_maps(), but the points are `points` (one per vertex),
  // swapped in without a copy, in place of the default point: for an
  // algorithm that writes the points as it goes.
  template <class P>
  static void reset_property_maps(Mobius_mesh<P>& m, std::vector<Stored_value<P>>& points)
  {
    CGAL_precondition(points.size() == m.num_vertices());
    m.recount_mobius_edges();
    resize_property_maps(m, m.num_vertices(), m.num_halfedges(), m.num_edges(), m.num_faces(), &points);
  }

  // The property arrays of element kind `I` (an index type) of `m`.
  template <class I, class P>
  static const Property_container& properties(const Mobius_mesh<P>& m)
  {
    return m.template container<I>();
  }
  template <class I, class P>
  static Property_container& properties(Mobius_mesh<P>& m)
  {
    return m.template container<I>();
  }

private:
  // Resizes `array` to `n` elements left unwritten (nothing is copied if it
  // grows) and returns where to write their values: 32-bit handle values, or
  // bytes for the Möbius flags.
  template <class T>
  static auto resize_for_overwrite(Uninitialized_array<T>& array, std::size_t n)
  {
    static_assert(std::is_trivially_copyable_v<T> && (sizeof(T) == 4 || sizeof(T) == 1),
                  "handles are plain 32-bit values");
    array.clear();
    array.resize(n);
    using Raw = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint8_t>;
    return reinterpret_cast<Raw*>(array.data());
  }
  // Replaces `array` by `n` values copied from `source`, in one pass.
  template <class T>
  static void assign_values(Uninitialized_array<T>& array, const void* source, std::size_t n)
  {
    auto* target = resize_for_overwrite(array, n);
    if (n)
      std::memcpy(target, source, sizeof(T) * n);
  }
  // Every property array back to its default values, at the given sizes;
  // the arrays are new, so nothing in them is removed. The points are
  // `points` instead, if not null (`nv` of them).
  template <class P>
  static void resize_property_maps(Mobius_mesh<P>& m, std::size_t nv, std::size_t nh, std::size_t ne,
                                   std::size_t nf, std::vector<Stored_value<P>>* points = nullptr)
  {
    m.drop_removal_marks();
    for (auto* props : {&m.vprops_, &m.hprops_, &m.eprops_, &m.fprops_})
      props->resize(0);
    if (points)
      m.points_.data().swap(*points); // already of the size the resize below gives
    m.vprops_.resize(nv);
    m.hprops_.resize(nh);
    m.eprops_.resize(ne);
    m.fprops_.resize(nf);
  }
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_CONNECTIVITY_ACCESS_H
