// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/polygon_soup_to_mobius_mesh.h>: the soup import: point checks, flattening and merging of the polygons.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_SOUP_IMPORT_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_SOUP_IMPORT_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/internal/Repeated_vertex_split.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
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
#include <optional>
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

// The join map of a soup split into sheets: each copy made by splitting
// holds the vertex it was split off: first the copies given to the corner
// fans of repeated vertices (`fan_copies`, numbered from `n_vertices`), then
// the builder's (`copies`), whose originals may be the former.
template <class P>
void record_joins(Mobius_mesh<P>& mesh, std::uint32_t n_vertices, const std::vector<std::uint32_t>& fan_copies,
                  const std::vector<Split_vertex>& copies)
{
  auto join =
    mesh.template add_property_map<Vertex_index, std::uint32_t>(non_manifold_join_name, no_non_manifold_join).first;
  for (std::size_t k = 0; k < fan_copies.size(); ++k)
    join[Vertex_index(n_vertices + std::uint32_t(k))] = fan_copies[k];
  const std::uint32_t n_named = n_vertices + std::uint32_t(fan_copies.size());
  for (std::size_t k = 0; k < copies.size(); ++k) {
    const std::uint32_t original = copies[k].original;
    join[Vertex_index(n_named + std::uint32_t(k))] =
      original < n_vertices ? original : fan_copies[original - n_vertices];
  }
}

// Before `part` (with joins) is joined to `mesh`: `mesh` gets a join map if
// it has none (joined to none), and part's joins name the vertices they
// will be once appended (join() copies a map of the same name).
template <class P>
void prepare_join_append(Mobius_mesh<P>& mesh, Mobius_mesh<P>& part)
{
  const std::uint32_t offset = std::uint32_t(mesh.number_of_vertices());
  mesh.template add_property_map<Vertex_index, std::uint32_t>(non_manifold_join_name, no_non_manifold_join);
  auto join = *non_manifold_join_map(part);
  for (Vertex_index v : part.vertices())
    if (join[v] != no_non_manifold_join)
      join[v] += offset;
}

// polygon_soup_to_mobius_mesh(), with `before_orient(result)` called on the
// mesh just built, before its components are oriented and it is appended:
// face p is then polygon p, and `result.halfedge(Face_index(p))` ends at
// corner 1 of the polygon, its `next` at corner 2, and so on. Corner data
// set there (the OBJ reader's texture coordinates) follows each corner's
// vertex when orientation reverses faces.
template <class PointRange, class PolygonRange, class P, class NamedParameters, class BeforeOrient>
std::size_t soup_to_mobius_mesh(const PointRange& points, const PolygonRange& polygons, Mobius_mesh<P>& mesh,
                                const NamedParameters& np, BeforeOrient&& before_orient)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto point_map =
    choose_parameter(get_parameter(np, CGAL::internal_np::point_map), CGAL::Identity_property_map<P>());
  using Input_point = std::decay_t<decltype(get(point_map, *std::begin(points)))>;
  using Default_traits = typename CGAL::Kernel_traits<Input_point>::Kernel;
  const auto traits = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  using FT = typename std::decay_t<decltype(traits)>::FT;
  const bool split_edges =
    choose_parameter(get_parameter(np, CGAL_ext::internal_np::non_manifold_policy), Non_manifold_policy::refuse) ==
    Non_manifold_policy::split;
  const bool split =
    split_edges || choose_parameter(get_parameter(np, CGAL_ext::internal_np::split_non_manifold_vertices), false);

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

  // 3. Build: under the split policy, a vertex that a polygon visits twice
  //    first gets a vertex per corner fan (see Repeated_vertex_split.h).
  std::optional<internal::Repeated_vertex_split> fans;
  if (split_edges)
    fans.emplace(flat, n_vertices);
  const std::vector<std::uint32_t> fan_copies = fans ? fans->original() : std::vector<std::uint32_t>();
  const auto input_vertex = [&](std::uint32_t v) { return v < n_vertices ? v : fan_copies[v - n_vertices]; };
  Mobius_mesh<P> result;
  std::vector<internal::Split_vertex> copies = internal::build_mesh_from_faces(
    fans ? fans->view() : flat.view(n_vertices),
    [&](std::uint32_t v) {
      const std::uint32_t u = input_vertex(v);
      return P(point_of(representative.empty() ? u : representative[u]));
    },
    split, result, split_edges);
  // A folded face (a loop's among them) makes its vertex non-manifold
  // without a copy: the join map (possibly none joined) says so, and makes
  // the functions that cannot keep non-manifold input refuse the mesh.
  const bool joined =
    split_edges && (!copies.empty() || !fan_copies.empty() || fans->number_of_folded_corners() != 0);
  if (joined)
    internal::record_joins(result, n_vertices, fan_copies, copies);
  // Face p is polygon p, its halfedge ending at the polygon's corner 1: what
  // the caller hangs on the corners is set now, before orientation moves them.
  before_orient(result);
  if (!choose_parameter(get_parameter(np, CGAL_ext::internal_np::keep_orientation), false))
    orient_orientable_components(result);

  const std::size_t n_copies = fan_copies.size() + copies.size();
  if (joined && !internal::is_pristine(mesh))
    internal::prepare_join_append(mesh, result);
  internal::append_mesh(mesh, std::move(result));
  return n_copies;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_SOUP_IMPORT_H
