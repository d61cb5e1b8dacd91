// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Merging mesh borders: automatically, where border vertices lie within a
// tolerance of each other (compared exactly), or manually, along two chosen
// border loops with one of four strategies. Gluing two border edges that run
// the same way makes a Möbius edge.

#ifndef CGAL_EXT_MERGE_BORDERS_H
#define CGAL_EXT_MERGE_BORDERS_H

#include <CGAL_ext/Merging/Merge_types.h>
#include <CGAL_ext/Merging/internal/Automatic_merge.h>
#include <CGAL_ext/Merging/internal/Border_chains.h>
#include <CGAL_ext/Merging/internal/Facing_borders.h>
#include <CGAL_ext/Merging/internal/Merged_mesh.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/internal/Coordinate_checks.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshMerge
///
/// Merges the borders of `mesh_b` into `mesh_a` where they meet: border
/// vertices of `mesh_a` and `mesh_b` within the tolerance of each other are
/// candidates (coincident vertices grouped first, then the groups paired with
/// `CGAL::box_intersection_d()` on padded boxes and decided exactly, see
/// below: time near-linear in the number of border vertices, however many
/// coincide), and each border edge whose two ends are
/// candidates of the two ends of a border edge of the other mesh is glued to
/// it. Gluing follows the borders from matched vertex to matched vertex as
/// far as both run together; vertex pairs that glue no edge are left apart
/// (counted in `ignored_vertex_pairs`). Two border edges that run the same way
/// become a Möbius edge: a strip glued to itself after a half-twist is a
/// Möbius strip.
///
/// `mesh_a` receives the union of both meshes with the glue; glued vertices
/// keep `mesh_a`'s positions. Faces keep their orientation, `mesh_a`'s faces
/// first. Property maps of every value type are kept (a glued vertex or edge
/// takes `mesh_a`'s value).
///
/// The glue is made in place, in time proportional to the glued border and
/// the fans around it (plus appending `mesh_b`, and finding the border):
/// each glued pair of edges becomes one edge, and the merged vertices and
/// the second edge of each pair are replaced by the last vertex or edge, so
/// the result has no removed elements. Faces keep their indices; a vertex or
/// edge moved into a freed slot changes its index (`Merge_result::vertex_map`
/// says where each vertex went).
///
/// Two vertices are within the tolerance iff their exact distance is at most
/// the exact value of the tolerance, on every kernel, as in the soup import:
/// no square root and no rounded square (floating-point coordinates are
/// decided by an interval filter, then exact rationals; exact kernels by
/// their own `Compare_squared_distance_3`). A point at exactly the tolerance
/// merges and one a unit in the last place further does not. A tolerance of
/// 0 glues exact coincidences only.
///
/// \param mesh_a the first mesh, which receives the result
/// \param mesh_b the second mesh
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{the largest distance between two border vertices that may be glued}
///     \cgalParamType{`double` or the kernel's `FT`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel whose `Compare_squared_distance_3` decides (and whose
///       `Compare_xyz_3` groups coincident vertices)}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns what was glued; if nothing is, `mesh_a` becomes the disjoint union.
/// \throws Parameter_error for a negative, infinite or NaN tolerance, or a
///   point with a coordinate that is not finite.
/// \throws Merge_error if the glue would make a non-manifold edge (a border
///   edge with two candidate partners, or three faces at an edge) or vertex, or
///   collapse a face; both meshes are then left unchanged.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b,
                           const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh_a, "merge_borders");
  CGAL_ext::internal::refuse_folded_faces(mesh_a, "merge_borders");
  CGAL_ext::internal::require_no_garbage(mesh_b, "merge_borders");
  CGAL_ext::internal::refuse_folded_faces(mesh_b, "merge_borders");
  CGAL_ext::internal::require_finite_points(mesh_a, "merge_borders");
  CGAL_ext::internal::require_finite_points(mesh_b, "merge_borders");
  if (&mesh_a == &mesh_b) {
    const Mobius_mesh<P> copy = mesh_b;
    return merge_borders(mesh_a, copy, np);
  }
  internal::Joined<P> joined(mesh_a, mesh_b);
  Merge_result r = internal::merge_borders_impl(mesh_a, joined.offsets().vertices, false, np);
  joined.keep();
  return r;
}

/// \ingroup PkgMobiusMeshMerge
///
/// Merges the borders of `mesh` with themselves, as the two-mesh
/// `merge_borders()` does, matching any two border vertices within the
/// tolerance. `mesh` is left unchanged if an exception is thrown.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh, "merge_borders");
  CGAL_ext::internal::refuse_folded_faces(mesh, "merge_borders");
  CGAL_ext::internal::require_finite_points(mesh, "merge_borders");
  return internal::merge_borders_impl(mesh, mesh.number_of_vertices(), true, np);
}

/// \ingroup PkgMobiusMeshMerge
///
/// The border parts of `mesh_a` and `mesh_b` that face each other, for the
/// manual `merge_borders()`:
/// 1. the two border loops that hold the nearest two border vertices (one of
///    each mesh);
/// 2. on them, the runs of *mutually nearest* vertices around that pair (a
///    vertex is in the run if it is the vertex of its loop nearest to its own
///    nearest vertex of the other loop, ties allowed): the ends of two strip
///    halves facing each other, or, if either run is its whole loop, the
///    whole loops (the facing ends of two tubes);
/// 3. the correspondence: whole loops start at the nearest pair and the
///    second loop is walked the way that keeps the pairing nearer (the sum of
///    squared distances of corresponding vertices), so that the glue twists
///    only where the geometry does; open chains start at the nearer pairing of
///    their ends.
///
/// Distances are measured on the points rounded to doubles (a choice of what
/// to glue, not a geometric decision). The chains may differ in length:
/// only `Merge_strategy::bridge` joins those.
/// \throws Merge_error `not_a_border` if a mesh has no border.
/// \throws Parameter_error if a point has a coordinate that is not finite.
template <class P>
Border_pairing facing_borders(const Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b)
{
  CGAL_ext::internal::require_finite_points(mesh_a, "facing_borders");
  CGAL_ext::internal::require_finite_points(mesh_b, "facing_borders");
  const std::vector<Dart> loops_a = CGAL_ext::border_cycles(mesh_a), loops_b = CGAL_ext::border_cycles(mesh_b);
  if (loops_a.empty() || loops_b.empty())
    throw Merge_error(Merge_error::Kind::not_a_border,
                      std::string("the ") + (loops_a.empty() ? "first" : "second") + " mesh has no border", {});
  std::vector<internal::Border_walk> walks_a, walks_b;
  for (Dart d : loops_a)
    walks_a.push_back(internal::border_walk(mesh_a, d));
  for (Dart d : loops_b)
    walks_b.push_back(internal::border_walk(mesh_b, d));
  const internal::Nearest_pair p = internal::nearest_pair(walks_a, walks_b);
  return internal::facing_parts(walks_a[p.loop_a], p.i, walks_b[p.loop_b], p.j);
}

/// \ingroup PkgMobiusMeshMerge
///
/// The whole border loops of `loop_a` in `mesh_a` and `loop_b` in `mesh_b`
/// (any of their border darts), paired as `facing_borders()` pairs whole
/// loops: from their nearest two vertices, the second loop walked the way
/// that keeps the pairing nearer.
/// \throws Merge_error `not_a_border` if a dart is not a border dart.
/// \throws Parameter_error if a point has a coordinate that is not finite.
template <class P>
Border_pairing aligned_border_loops(const Mobius_mesh<P>& mesh_a, Dart loop_a, const Mobius_mesh<P>& mesh_b,
                                    Dart loop_b)
{
  internal::check_border_dart(mesh_a, loop_a, "first");
  internal::check_border_dart(mesh_b, loop_b, "second");
  CGAL_ext::internal::require_finite_points(mesh_a, "aligned_border_loops");
  CGAL_ext::internal::require_finite_points(mesh_b, "aligned_border_loops");
  const std::vector<internal::Border_walk> walk_a{internal::border_walk(mesh_a, loop_a)},
    walk_b{internal::border_walk(mesh_b, loop_b)};
  const internal::Nearest_pair p = internal::nearest_pair(walk_a, walk_b);
  return internal::whole_loops(walk_a[0], p.i, walk_b[0], p.j);
}

/// \ingroup PkgMobiusMeshMerge
///
/// Glues the border chain `pairing.second` of `mesh_b` to the chain
/// `pairing.first` of `mesh_a`, whatever the distance between them, and puts
/// the result in `mesh_a`. The chains are walked with `next()` from their
/// darts, in step: the k-th edges correspond, and so do the k-th vertices
/// (the darts' sources first). If the two chains are walked against the
/// orientation of their faces in opposite senses (one dart flipped, one
/// not), the glue is orientable; otherwise the glued edges are Möbius edges.
///
/// - `Merge_strategy::keep_first`, `keep_second`, `average`: corresponding
///   vertices are identified at `mesh_a`'s position, `mesh_b`'s, or their
///   midpoint (exact with an exact kernel). The chains must have the same
///   number of edges and be both whole loops or both open.
/// - `Merge_strategy::bridge`: nothing moves; chains of n and m edges are
///   joined by max(n, m) new faces, each advancing the longer chain by one
///   edge: min(n, m) quads, where the shorter chain advances too, spread
///   evenly (the k-th face advances it iff floor((k+1) min / max) >
///   floor(k min / max)), and |n - m| triangles.
///
/// \param mesh_a the first mesh; it receives the result
/// \param mesh_b the second mesh
/// \param pairing the two border chains to glue, of `mesh_a` and `mesh_b`
/// \param strategy where the glued vertices go, or `Merge_strategy::bridge`
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel whose `Construct_midpoint_3` places the vertices under
///       `Merge_strategy::average` (no other strategy computes a point)}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns what was glued (vertex pairs in the numbering of `Merge_result`).
/// \throws Merge_error `not_a_border` if a dart is not a border dart,
///   `mismatched_chains` if a chain has no edge or more than its loop, or
///   (not with `bridge`) the chains differ in length or in being whole loops,
///   or the kinds of the automatic merge if the result is not a 2-manifold;
///   both meshes are then left unchanged.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b, const Border_pairing& pairing,
                           Merge_strategy strategy, const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh_a, "merge_borders");
  CGAL_ext::internal::refuse_folded_faces(mesh_a, "merge_borders");
  CGAL_ext::internal::require_no_garbage(mesh_b, "merge_borders");
  CGAL_ext::internal::refuse_folded_faces(mesh_b, "merge_borders");
  if (&mesh_a == &mesh_b) {
    const Mobius_mesh<P> copy = mesh_b;
    return merge_borders(mesh_a, copy, pairing, strategy, np);
  }
  using Default_traits = typename CGAL::Kernel_traits<P>::Kernel;
  const auto traits =
    parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  const auto midpoint = traits.construct_midpoint_3_object();
  const std::uint32_t na = mesh_a.number_of_vertices();
  const internal::Border_chain chain_a = internal::border_chain(mesh_a, pairing.first, pairing.first_edges, 0, "first");
  const internal::Border_chain chain_b =
    internal::border_chain(mesh_b, pairing.second, pairing.second_edges, na, "second");
  switch (strategy) {
  case Merge_strategy::bridge:
    return internal::bridge_chains(mesh_a, mesh_b, chain_a, chain_b);
  case Merge_strategy::keep_second:
    return internal::glue_chains(mesh_a, mesh_b, chain_a, chain_b, [](const P&, const P& pb) { return pb; });
  case Merge_strategy::average:
    return internal::glue_chains(mesh_a, mesh_b, chain_a, chain_b,
                                 [&midpoint](const P& pa, const P& pb) { return P(midpoint(pa, pb)); });
  default:
    return internal::glue_chains(mesh_a, mesh_b, chain_a, chain_b, [](const P& pa, const P&) { return pa; });
  }
}

/// \ingroup PkgMobiusMeshMerge
///
/// Glues the whole border loop of `border_b` in `mesh_b` to the whole border
/// loop of `border_a` in `mesh_a`: the pairing overload with chains that are
/// the two loops walked from the two darts (the i-th vertices correspond,
/// starting with the darts' sources). Pass a flipped dart to walk a loop the
/// other way; `aligned_border_loops()` chooses the start and the way from
/// the geometry.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, Dart border_a, const Mobius_mesh<P>& mesh_b, Dart border_b,
                           Merge_strategy strategy, const NamedParameters& np = parameters::default_values())
{
  internal::check_border_dart(mesh_a, border_a, "first");
  internal::check_border_dart(mesh_b, border_b, "second");
  const Border_pairing whole{border_a, border_b, internal::loop_length(mesh_a, border_a),
                             internal::loop_length(mesh_b, border_b)};
  return merge_borders(mesh_a, mesh_b, whole, strategy, np);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MERGE_BORDERS_H
