// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Builds a Mobius_mesh from a polygon soup, in time linear in the soup's
// size, finding normal and Möbius connections between polygons.

#ifndef CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H
#define CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H

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

/// \ingroup PkgMobiusMeshSoup
///
/// Builds a 2-manifold `Mobius_mesh` from a polygon soup and appends it to
/// `mesh`. Two polygons that share an edge are connected whichever way they
/// run along it: in opposite directions (a normal connection) or in the same
/// direction (a Möbius connection). Each orientable connected component is
/// oriented, as CGAL's readers orient a soup: its polygons are reversed where
/// needed to agree with its lowest-numbered polygon, so that it has no Möbius
/// edge and every CGAL algorithm that needs an orientation is right on it
/// (`keep_orientation(true)` keeps every polygon as given). Non-orientable
/// components keep their polygons' orientations; `orient()` reduces their
/// Möbius edges.
///
/// The soup is checked before anything is built, and bad input throws a
/// `Soup_error` that names the polygons and points at fault; `mesh` is then
/// left unchanged.
///
/// \param points a range of points
/// \param polygons a range of ranges of indices into `points`
/// \param mesh the mesh the soup's polygons are added to
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map giving the point of an element of `points`}
///     \cgalParamDefault{`CGAL::Identity_property_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel whose `Compare_squared_distance_3` decides merges}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{points whose exact distance is at most the exact value of
///                           this number are merged first (transitively); decided
///                           exactly on every kernel, as in `merge_borders()`;
///                           0 merges exact duplicates only}
///     \cgalParamType{`double` or the kernel's `FT`}
///     \cgalParamDefault{no merging}
///   \cgalParamNEnd
///   \cgalParamNBegin{keep_orientation}
///     \cgalParamDescription{if `true`, every polygon keeps its orientation, so that
///                           an orientable soup whose polygons disagree is built
///                           with Möbius edges}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_non_manifold_vertices}
///     \cgalParamDescription{if `true`, a vertex whose polygons form several fans is
///                           split into one vertex per fan (as CGAL's
///                           `duplicate_non_manifold_vertices()` does) instead of refused}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of vertices added by splitting non-manifold vertices.
/// \throws Soup_error for an index out of range, a polygon with fewer than
///   three vertices or a repeated vertex, an edge shared by three or more
///   polygons, a non-manifold vertex (unless split), a non-finite coordinate.
/// \throws Parameter_error for a negative or NaN tolerance.
/// \throws Size_error (a `Parameter_error`) for more points, polygons or
///   edges than the mesh's 32-bit indices hold, before the mesh is allocated.
template <class PointRange, class PolygonRange, class P, class NamedParameters = parameters::Default_named_parameters>
std::size_t polygon_soup_to_mobius_mesh(const PointRange& points, const PolygonRange& polygons, Mobius_mesh<P>& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto point_map =
    choose_parameter(get_parameter(np, CGAL::internal_np::point_map), CGAL::Identity_property_map<P>());
  using Input_point = std::decay_t<decltype(get(point_map, *std::begin(points)))>;
  using Default_traits = typename CGAL::Kernel_traits<Input_point>::Kernel;
  const auto traits = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  using FT = typename std::decay_t<decltype(traits)>::FT;
  const bool split = choose_parameter(get_parameter(np, CGAL_ext::internal_np::split_non_manifold_vertices), false);

  // 1. Validate.
  const std::size_t n_points = std::size(points);
  internal::check_soup_points(points, point_map);
  internal::Face_list flat = internal::flatten_soup_polygons(polygons, n_points);
  // Random access to the points: directly where the range has it, else
  // through a table of addresses (not built for vectors: on a large soup
  // its pages would cost more than the rest of the import's first touch).
  using Iterator = decltype(std::begin(points));
  constexpr bool random_access = std::is_base_of_v<std::random_access_iterator_tag,
                                                   typename std::iterator_traits<Iterator>::iterator_category>;
  std::vector<const typename std::iterator_traits<Iterator>::value_type*> item;
  if constexpr (!random_access) {
    item.reserve(n_points);
    for (const auto& x : points)
      item.push_back(&x);
  }
  auto point_of = [&](std::uint32_t i) {
    if constexpr (random_access)
      return get(point_map, std::begin(points)[i]);
    else
      return get(point_map, *item[i]);
  };

  // 2. Merge close points, if asked: vertex v of the mesh is soup point
  //    representative[v].
  std::vector<std::uint32_t> representative;
  const auto tolerance = get_parameter(np, CGAL_ext::internal_np::tolerance);
  if constexpr (!std::is_same_v<std::decay_t<decltype(tolerance)>, CGAL::internal_np::Param_not_found>)
    representative = internal::merge_soup_points(std::uint32_t(n_points), point_of, traits,
                                                 internal::checked_tolerance<FT>(tolerance), flat);
  const std::uint32_t n_vertices = std::uint32_t(representative.empty() ? n_points : representative.size());

  // 3. Build.
  Mobius_mesh<P> result;
  const std::size_t added_vertices = internal::build_mesh_from_faces(
    flat.view(n_vertices), [&](std::uint32_t v) { return P(point_of(representative.empty() ? v : representative[v])); },
    split, result);
  if (!choose_parameter(get_parameter(np, CGAL_ext::internal_np::keep_orientation), false))
    orient_orientable_components(result);

  internal::append_mesh(mesh, std::move(result));
  return added_vertices;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H
