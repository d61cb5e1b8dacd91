// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/polygon_soup_to_mobius_mesh.h>: the soup import: point checks, flattening and merging of the polygons.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_SOUP_IMPORT_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_SOUP_IMPORT_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Close_points.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/property_map.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace internal {

template <class FT>
bool is_finite_number(const FT& x)
{
  if constexpr (std::is_floating_point_v<FT>)
    return std::isfinite(x);
  else
    return true; // exact number types hold no infinities or NaNs
}

template <class PointRange, class PointMap>
void check_soup_points(const PointRange& points, PointMap point_map)
{
  std::size_t i = 0;
  for (auto it = std::begin(points); it != std::end(points); ++it, ++i) {
    const auto& p = get(point_map, *it);
    if (!is_finite_number(p.x()) || !is_finite_number(p.y()) || !is_finite_number(p.z()))
      throw Soup_error(Soup_error::Kind::non_finite_point, "point " + std::to_string(i) + " has a non-finite coordinate",
                       {}, {i});
  }
}

// The soup's polygons as face lists, checked: at least three corners each,
// every index naming a point, counts within the mesh's 32-bit indices.
template <class PolygonRange>
Face_list flatten_soup_polygons(const PolygonRange& polygons, std::size_t n_points)
{
  using Kind = Soup_error::Kind;
  check_mesh_size("the polygon soup", Mesh_size{n_points, 0, std::size(polygons), 0});
  // Each edge has at most two corners: past twice the edge limit, the soup
  // needs too many edges whatever it shares. (The exact edge count is checked
  // when the polygons are paired.)
  constexpr std::size_t max_corners = 2 * max_edges;
  Face_list flat;
  flat.offset.reserve(std::size(polygons) + 1);
  std::size_t p = 0;
  for (const auto& polygon : polygons) {
    const std::size_t size = std::size(polygon);
    if (size < 3)
      throw Soup_error(Kind::degenerate_polygon,
                       "polygon " + std::to_string(p) + " has " + std::to_string(size) +
                         " vertices; a polygon needs at least three",
                       {p}, {});
    for (const auto& index : polygon) {
      bool negative = false;
      if constexpr (std::is_signed_v<std::decay_t<decltype(index)>>)
        negative = index < 0;
      if (negative || std::size_t(index) >= n_points)
        throw Soup_error(Kind::index_out_of_range,
                         "polygon " + std::to_string(p) + " names point " + std::to_string(index) +
                           ", but there are only " + std::to_string(n_points) + " points",
                         {p}, {});
      flat.vertex.push_back(std::uint32_t(index));
    }
    if (flat.vertex.size() > max_corners)
      check_mesh_size("the polygon soup (whose corners give at least)",
                      Mesh_size{0, (flat.vertex.size() + 1) / 2, 0, 0});
    flat.offset.push_back(std::uint32_t(flat.vertex.size()));
    ++p;
  }
  return flat;
}

// Merges the points within the tolerance of each other: renumbers the
// corners by class and returns the soup index of each class's point (its
// lowest member). `point_of(i)` is soup point i.
template <class PointOf, class Traits>
std::vector<std::uint32_t> merge_soup_points(std::uint32_t n_points, PointOf point_of, const Traits& traits,
                                             const typename Traits::FT& tolerance, Face_list& flat)
{
  std::uint32_t n_classes = 0;
  const std::vector<std::uint32_t> cls = Close_points<Traits>(traits, tolerance).classes(n_points, point_of, n_classes);
  for (std::uint32_t& v : flat.vertex)
    v = cls[v];
  std::vector<std::uint32_t> representative(n_classes);
  for (std::uint32_t i = n_points; i-- > 0;)
    representative[cls[i]] = i;
  return representative;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_SOUP_IMPORT_H
