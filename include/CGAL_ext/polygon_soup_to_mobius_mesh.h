// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Builds a Mobius_mesh from a polygon soup, in time linear in the soup's
// size, finding normal and Möbius connections between polygons.

#ifndef CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H
#define CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H

#include <CGAL_ext/Mobius_mesh/internal/Soup_import.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
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
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {

namespace internal {

// The join map of a soup split into sheets: each copy made by splitting
// holds the vertex it was split off.
template <class P>
void record_joins(Mobius_mesh<P>& mesh, std::uint32_t n_vertices, const std::vector<Split_vertex>& copies)
{
  auto join =
    mesh.template add_property_map<Vertex_index, std::uint32_t>(non_manifold_join_name, no_non_manifold_join).first;
  for (std::size_t k = 0; k < copies.size(); ++k)
    join[Vertex_index(n_vertices + std::uint32_t(k))] = copies[k].original;
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

  // 3. Build.
  Mobius_mesh<P> result;
  const std::vector<internal::Split_vertex> copies = internal::build_mesh_from_faces(
    flat.view(n_vertices), [&](std::uint32_t v) { return P(point_of(representative.empty() ? v : representative[v])); },
    split, result, split_edges);
  if (split_edges && !copies.empty())
    internal::record_joins(result, n_vertices, copies);
  // Face p is polygon p, its halfedge ending at the polygon's corner 1: what
  // the caller hangs on the corners is set now, before orientation moves them.
  before_orient(result);
  if (!choose_parameter(get_parameter(np, CGAL_ext::internal_np::keep_orientation), false))
    orient_orientable_components(result);

  if (!copies.empty() && split_edges && !internal::is_pristine(mesh))
    internal::prepare_join_append(mesh, result);
  internal::append_mesh(mesh, std::move(result));
  return copies.size();
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
///     \cgalParamDescription{the kernel whose `Compare_squared_distance_3` decides merges (and
///                           whose `Compare_xyz_3` groups coincident points)}
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
///   \cgalParamNBegin{non_manifold_policy}
///     \cgalParamDescription{`Non_manifold_policy::split` takes a soup that is not a
///                           2-manifold (an edge of three or more polygons, fans that meet
///                           at a vertex) as manifold sheets joined by the vertex map
///                           `non_manifold_join_name` (made only where something was split);
///                           `refuse` throws}
///     \cgalParamType{`Non_manifold_policy`}
///     \cgalParamDefault{`Non_manifold_policy::refuse`}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_non_manifold_vertices}
///     \cgalParamDescription{if `true`, a vertex whose polygons form several fans is
///                           split into one vertex per fan (as CGAL's
///                           `duplicate_non_manifold_vertices()` does) instead of refused}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of vertices added by splitting non-manifold vertices
///   (and edges).
/// \throws Soup_error for an index out of range, a polygon with fewer than
///   three vertices or a repeated vertex, an edge shared by three or more
///   polygons (unless split), a non-manifold vertex (unless split), a
///   non-finite coordinate.
/// \throws Parameter_error for a negative or NaN tolerance.
/// \throws Size_error (a `Parameter_error`) for more points, polygons or
///   edges than the mesh's 32-bit indices hold, before the mesh is allocated.
template <class PointRange, class PolygonRange, class P, class NamedParameters = parameters::Default_named_parameters>
std::size_t polygon_soup_to_mobius_mesh(const PointRange& points, const PolygonRange& polygons, Mobius_mesh<P>& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  return internal::soup_to_mobius_mesh(points, polygons, mesh, np, [](Mobius_mesh<P>&) {});
}

} // namespace CGAL_ext

#endif // CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H
