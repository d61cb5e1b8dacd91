// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Builds a Mobius_mesh from a polygon soup, in time linear in the soup's
// size, finding normal and Möbius connections between polygons.

#ifndef CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H
#define CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/internal/Soup_import.h>
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
///                           at a vertex, a polygon that visits a vertex twice) as manifold
///                           sheets joined by the vertex map `non_manifold_join_name` (made
///                           only where something was split or a degenerate edge became a
///                           loop), as OpenSubdiv takes such input;
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
///   three vertices, a repeated vertex (under `non_manifold_policy` `split`
///   only where a polygon visits a vertex twice within one fan that
///   OpenSubdiv orders round the vertex, whose two visits it then gives one
///   corner, or where two polygons run along a side at the vertex the same
///   way; see doc/subdivision.md, "Non-manifold input"), an
///   edge shared by three or more polygons (unless split), a non-manifold
///   vertex (unless split), a non-finite coordinate.
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
