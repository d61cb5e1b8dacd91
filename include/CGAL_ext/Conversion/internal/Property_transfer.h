// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The property maps that the conversions carry between Mobius_mesh and
// CGAL::Surface_mesh: which value types, which maps (Surface_mesh's own
// aside), and the copy of each map through the element correspondences.

#ifndef CGAL_EXT_CONVERSION_INTERNAL_PROPERTY_TRANSFER_H
#define CGAL_EXT_CONVERSION_INTERNAL_PROPERTY_TRANSFER_H

#include <CGAL_ext/Conversion/Seam_map.h>
#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

template <class Q>
bool is_surface_mesh_internal_property(const std::string& name)
{
  return name == "v:connectivity" || name == "h:connectivity" || name == "f:connectivity" || name == "v:point" ||
         name == "v:removed" || name == "e:removed" || name == "f:removed" || name == seam_map_name ||
         name == reversed_faces_map_name;
}

// The halfedge maps of a Surface_mesh that hold corner channels
// (Channel_transfer.h), not copied as halfedge maps.
inline bool is_corner_channel_name(const std::string& name) { return name.compare(0, 2, "c:") == 0; }

// The value types whose property maps the conversions carry. Surface_mesh
// makes a property array only through `add_property_map<I, T>()`, with `T`
// named at compile time, so a list is needed here (copies between
// Mobius_meshes carry any type): bool, the arithmetic types, strings, and,
// when both sides use the same point type, points and vectors of its kernel.
template <class P1, class P2, class F>
void for_each_transferable_type(F&& f)
{
  f(Type_tag<bool>());
  f(Type_tag<char>());
  f(Type_tag<signed char>());
  f(Type_tag<unsigned char>());
  f(Type_tag<short>());
  f(Type_tag<unsigned short>());
  f(Type_tag<int>());
  f(Type_tag<unsigned int>());
  f(Type_tag<long>());
  f(Type_tag<unsigned long>());
  f(Type_tag<long long>());
  f(Type_tag<unsigned long long>());
  f(Type_tag<float>());
  f(Type_tag<double>());
  f(Type_tag<std::string>());
  if constexpr (std::is_same_v<P1, P2>) {
    using K = typename CGAL::Kernel_traits<P1>::Kernel;
    f(Type_tag<typename K::Point_3>());
    f(Type_tag<typename K::Vector_3>());
  }
}

// True if there are property maps of kind `I` to carry over (points and
// Surface_mesh's own maps aside): the element correspondences, a pair per
// element, are built only then (or for an output iterator).
template <class I, class P>
bool has_user_properties(const Mobius_mesh<P>& mesh)
{
  for (const std::string& name : mesh.template properties<I>())
    if (name != "v:point")
      return true;
  return false;
}
template <class SI, class Q>
bool has_user_properties(const CGAL::Surface_mesh<Q>& sm)
{
  for (const std::string& name : sm.template properties<SI>())
    if (!is_surface_mesh_internal_property<Q>(name))
      return true;
  return false;
}

// Mobius_mesh -> Surface_mesh properties of kind `I` (Mobius index type) / `SI`
// (Surface_mesh index type): `pairs` lists (Mobius element, Surface_mesh element).
template <class I, class SI, class P, class Q>
void properties_to_surface_mesh(const Mobius_mesh<P>& src, CGAL::Surface_mesh<Q>& dst,
                                const std::vector<std::pair<I, SI>>& pairs)
{
  for (const std::string& name : src.template properties<I>()) {
    if (name == "v:point" || is_surface_mesh_internal_property<Q>(name))
      continue;
    for_each_transferable_type<P, Q>([&](auto tag) {
      using T = typename decltype(tag)::type;
      const auto from = src.template property_map<I, T>(name);
      if (!from)
        return;
      auto to = dst.template add_property_map<SI, T>(name, from->array()->default_value()).first;
      for (const auto& [i, si] : pairs)
        to[si] = (*from)[i];
    });
  }
}

// A defined default value: CGAL's default points and vectors of a
// floating-point kernel hold uninitialized coordinates.
template <class T>
T initialized_value()
{
  if constexpr (std::is_constructible_v<T, CGAL::Origin>)
    return T(CGAL::ORIGIN);
  else if constexpr (std::is_constructible_v<T, CGAL::Null_vector>)
    return T(CGAL::NULL_VECTOR);
  else
    return T();
}

// Surface_mesh -> Mobius_mesh properties; `pairs` lists (Surface_mesh element, Mobius element).
template <class SI, class I, class Q, class P>
void properties_from_surface_mesh(const CGAL::Surface_mesh<Q>& src, Mobius_mesh<P>& dst,
                                  const std::vector<std::pair<SI, I>>& pairs)
{
  for (const std::string& name : src.template properties<SI>()) {
    if (is_surface_mesh_internal_property<Q>(name) ||
        (std::is_same_v<SI, typename CGAL::Surface_mesh<Q>::Halfedge_index> && is_corner_channel_name(name)))
      continue;
    for_each_transferable_type<Q, P>([&](auto tag) {
      using T = typename decltype(tag)::type;
      const auto [from, found] = src.template property_map<SI, T>(name);
      if (!found)
        return;
      auto to = dst.template add_property_map<I, T>(name, initialized_value<T>()).first;
      if (!to)
        return;
      for (const auto& [si, i] : pairs)
        to[i] = from[si];
    });
  }
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_CONVERSION_INTERNAL_PROPERTY_TRANSFER_H
