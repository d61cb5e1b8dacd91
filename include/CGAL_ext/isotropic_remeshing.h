// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Isotropic remeshing of a Mobius_mesh (Botsch and Kobbelt), with the
// contract of CGAL's Polygon_mesh_processing::isotropic_remeshing(), on any
// surface: Möbius strips, Klein bottles and other one-sided surfaces included.

#ifndef CGAL_EXT_ISOTROPIC_REMESHING_H
#define CGAL_EXT_ISOTROPIC_REMESHING_H

#include <CGAL_ext/Limit_surface.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Remeshing/internal/Isotropic_remesher.h>
#include <CGAL_ext/Remeshing/internal/Narrow_regions.h>
#include <CGAL_ext/Remeshing/internal/Remeshing_setup.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshEditing
/// What `isotropic_remeshing()` did, for the caller to judge the result by.
struct Isotropic_remeshing_result
{
  /// The iterations run: `number_of_iterations`, or fewer where the loop
  /// settled first (`stopped_early`).
  unsigned iterations = 0;
  /// True if the loop stopped before `number_of_iterations` because two
  /// iterations in a row each raised the share of edges in [4/5 L, 4/3 L] by
  /// less than 0.1 point and changed the number of faces by less than 1 %
  /// (`stop_when_converged`).
  bool stopped_early = false;
  /// The share of the result's edges whose length is in [4/5 L, 4/3 L]
  /// (Botsch and Kobbelt's band, which the loop aims at).
  double share_in_band = 0;
  /// The faces of the input in parts of the surface narrower than any
  /// triangle with sides in the band (see `allow_narrow_regions`): there the
  /// result is a strip of slivers as wide as the input, whose edges across
  /// are out of the band whatever the loop does.
  std::size_t narrow_faces = 0;
  /// The width of the narrowest of them (twice its area over its longest
  /// side); infinity if there is none.
  double narrowest_width = std::numeric_limits<double>::infinity();
  /// The values of the result's corner channels that the loop made (at
  /// split, collapsed and moved vertices), interpolated from the input's.
  std::size_t corner_values_interpolated = 0;
  /// The edges of the corner channels' seams (of the input once
  /// triangulated), which the loop protects and leaves as they were: where
  /// most edges are seams (corner normals of a flat-shaded mesh, a value per
  /// face) the loop can do little.
  std::size_t seam_edges_protected = 0;
};

namespace internal {

// The limit surface that project_to_limit_surface(true) asks for, or none.
// Only a call that names the parameter instantiates Limit_surface.
template <class P, class NP>
std::unique_ptr<Subdivision::Limit_surface<Subdivision::Catmull_clark_mask, P>>
limit_surface_to_project_on(const Mobius_mesh<P>& mesh, const NP& np)
{
  if constexpr (!parameters::is_default_parameter<NP, CGAL_ext::internal_np::project_to_limit_surface_t>::value) {
    if (parameters::get_parameter(np, CGAL_ext::internal_np::project_to_limit_surface))
      return std::make_unique<Subdivision::Limit_surface<Subdivision::Catmull_clark_mask, P>>(mesh, np);
  }
  return nullptr;
}

} // namespace internal

/// \ingroup PkgMobiusMeshEditing
/// \brief remeshes `mesh` into triangles whose edges are close to
/// `target_edge_length` (L), by Botsch and Kobbelt's loop, as
/// `CGAL::Polygon_mesh_processing::isotropic_remeshing()` does: each
/// iteration splits the edges longer than 4/3 L at their midpoints (longest
/// first, and the edges those splits make, until none is longer; an edge
/// made between two needles, triangles narrower than 0.44 L, is flipped
/// across them once their sides are split rather than split itself, so a
/// needle becomes a strip and not 3^k stacked needles), collapses the edges shorter than 4/5 L (shortest first) into
/// their midpoints where no edge would become longer than 4/3 L (an edge
/// from a border or a fixed vertex goes into that vertex, which keeps its
/// point), flips edges to bring valences
/// towards 6 (4 on the border), moves each vertex to the area-weighted
/// centroid of its triangles in its tangent plane, and projects it back onto
/// the input surface (the closest point, through an AABB tree of the input's
/// triangles built once).
///
/// On any surface: every step is written on darts, normals are taken per
/// dart (`vertex_normal(Dart)`), and a collapse, flip or move is refused if
/// it would turn a triangle over as seen from the darts around it, so it
/// works across Möbius edges. What makes the surface what it is stays: the
/// Euler characteristic, the number of border loops, orientability (a Möbius
/// strip stays one non-orientable strip), the number of components.
///
/// Corner channels (texture coordinates, corner normals: see
/// `Mobius_mesh::add_corner_channel()`) are carried. The seams of each
/// channel (edges whose two faces hold different value indices at an end)
/// are protected whatever the parameters say: neither split, collapsed nor
/// flipped, their vertices never move (`relax_constraints` leaves them too),
/// so every seam keeps its vertices and their values on either side. Off the
/// seams the values are interpolated linearly: a split's new vertex takes
/// the value halfway along the edge; a collapse into a midpoint, the value
/// halfway between its ends, and one into a seam vertex, that vertex's value
/// on the side of the edge; a flip keeps each corner's value; a vertex that
/// moves takes the input's value where it lands (in the input triangle
/// closest to its new point, read before the loop began), or, where that
/// triangle could be on a seam's other side (in another region of the input
/// between seams, or with the point on one of its seam edges), the value of
/// the triangle of its star that holds the point. So a channel that is
/// linear on the input's triangles (texture coordinates of a plane's points,
/// say) stays exact up to rounding, and elsewhere each value is the input's
/// piecewise linear channel where its vertex lies, without drifting with the
/// moves. Values are appended, never changed in place; those that no corner
/// names at the end are dropped, and the others keep their order. Channels
/// whose values have no linear combination are refused. With
/// `project_to_limit_surface`, the seams' vertices stay on the input's faces
/// as protected vertices do.
///
/// Faces that are not triangles are first split into triangles by
/// `triangulate_faces()`. The mesh must have no removed elements; the
/// result is garbage-collected. Positions: midpoints are computed in the
/// kernel's `FT`; relaxation and projection in `double`, converted back to
/// the point type (exact kernels work, but moved points are rounded to
/// double).
///
/// \param mesh the mesh, remeshed in place
/// \param target_edge_length L, positive and finite
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{how many times the loop runs, from 0 to 1000
///       (fewer where it settles first: see `stop_when_converged`)}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{protect_borders}
///     \cgalParamDescription{`true`: border edges are neither split nor
///       collapsed nor flipped, and their vertices do not move (but see
///       `relax_constraints`). `false`:
///       border edges are split and collapsed like others, and border
///       vertices slide along the input's border (to the middle of their
///       border neighbours, then onto the border edges of their own loop of
///       the input, even where another loop is closer), so each border loop
///       stays one loop on its own part of the input's border.}
///     \cgalParamDefault{the value of CGAL's `protect_constraints`, itself `false` by default}
///   \cgalParamNEnd
///   \cgalParamNBegin{protect_sharp_edges}
///     \cgalParamDescription{`true`: edges whose sharpness (`edge_sharpness_map()`,
///       the `e:sharpness` property) is above 0 are protected as borders are;
///       their vertices stay fixed (but see `relax_constraints`)}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{relax_constraints}
///     \cgalParamDescription{CGAL's parameter. `true`: the vertices of the
///       protected polylines (protected borders, protected sharp edges) are
///       relaxed too, along their polyline only: each moves to 1/2 of itself
///       and 1/4 of each of its two neighbours on the polyline, measured by
///       arc length along the input's polyline, so it stays on that polyline
///       (a border loop that passes Möbius edges is one polyline). Corners
///       never move: vertices on other than two protected edges, and those
///       where the polyline turns by more than 60 degrees. The protected
///       edges are still neither split, collapsed nor flipped. Without
///       protection it changes nothing: unprotected border vertices always
///       slide along the input's border.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`, as in CGAL}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_memory}
///     \cgalParamDescription{the most bytes the remeshing may take, estimated
///       from the input before it starts: from the triangles the first split
///       pass makes (the diagonals of polygons included) and those that later
///       iterations tend to (the input's area in equilateral triangles of
///       side L/2, and two per 4/5 L of border)}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{the memory available (Linux's `MemAvailable`, else the physical memory)}
///   \cgalParamNEnd
///   \cgalParamNBegin{stop_when_converged}
///     \cgalParamDescription{`true`: the loop stops before
///       `number_of_iterations` after two iterations in a row that each
///       raised the share of edges in [4/5 L, 4/3 L] by less than 0.1 point
///       and changed the number of faces by less than 1 %: the next ones
///       would not change more (a mesh already remeshed to L stops after
///       two). One such iteration is not enough: it may move vertices
///       without a split or collapse, lowering the band, and the next one
///       make up for it. `false`: it runs them all, as CGAL does.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{project_to_limit_surface}
///     \cgalParamDescription{`true`: vertices are projected onto the
///       Catmull–Clark limit surface of the input (`Subdivision::Limit_surface`,
///       the input taken as a subdivision cage, read with the same named
///       parameters: its sharpness maps, `boundary_interpolation`,
///       `crease_method`) instead of onto its faces, by
///       `Limit_surface::closest_point()`; a free border vertex goes to
///       the middle of its border neighbours, onto the input's border loop,
///       then onto the limit surface. So a remeshed cage lies on its smooth
///       surface, but for the vertices that never move: protected ones, and
///       those whose every move would turn a triangle over. The limit surface
///       reads `edge_sharpness_map`, `vertex_sharpness_map`,
///       `boundary_interpolation`, `crease_method` and `vertex_point_map`
///       as `Limit_surface` does, and refuses what it refuses;
///       `maximum_memory` does not count it.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{allow_narrow_regions}
///     \cgalParamDescription{what to do with a surface that is narrower than
///       L in places. A part of it is narrow where faces narrower than any
///       triangle with sides in [4/5 L, 4/3 L] (0.44 L, the altitude of the
///       triangle 4/5 L, 4/5 L, 4/3 L) and longer than 4/3 L lie side by
///       side, with the surface's border on at least 3/4 of their outline
///       and a mean width under 0.44 L: a needle alone, a strip narrower
///       than L, a thin tail. Such a part can only be cut along its length.
///       `true`: it is, into a strip across it of two triangles per 4/3 L of
///       length or fewer (the split pass flips the edges between needles
///       rather than splitting them), and the result counts its faces
///       (`narrow_faces`). `false`: `Parameter_error`, naming its narrowest
///       face, that face's width and length, and 0.44 L. Slivers beside
///       wider faces (a fan of a triangulated polygon, a sliver along a
///       border) are no narrow part: they are always remeshed.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns what the loop did (`Isotropic_remeshing_result`): the
/// iterations run, whether it settled early, the share of edges in the band,
/// and the faces of the input's narrow parts.
/// \throws Parameter_error if L is not positive and finite, the number of
/// iterations is out of range, `maximum_memory` is not positive, `mesh` has
/// removed elements, a corner channel whose values have no linear combination
/// or a corner whose value index is past its values, an edge's sharpness is NaN or negative (with
/// `protect_sharp_edges(true)`), a point has a coordinate beyond +-1e60 (where
/// squared lengths and normals in double overflow), the mesh is less than
/// 1e-60 across (where they underflow), or L is under 1024 times the spacing
/// of doubles at the largest coordinate (too fine for the coordinates), or
/// `allow_narrow_regions(false)` is given and the surface has a part
/// narrower than L allows (the message names its narrowest face, that face's
/// width and length, and the width a triangle of the band needs).
/// \throws Size_error if the estimated result has more elements than the
/// mesh's indices hold or needs more than `maximum_memory`, or if the loop
/// makes more than twice the estimated faces (a surface the estimate does not
/// foresee, such as a closed tube thinner than L).
/// \throws Euler_error if a polygon cannot be triangulated (triangulate_faces()),
/// or if an edit is refused part way (two faces on the same corners, say).
/// \throws Parameter_error as `Subdivision::Limit_surface`'s constructor
/// with `project_to_limit_surface(true)`.
/// In all these cases `mesh` is as it was before the call: the checks run
/// before it is touched, and a failure part way puts it back from a copy
/// (property maps taken before such a failure must then be taken again).
template <class P, class NP = parameters::Default_named_parameters>
Isotropic_remeshing_result isotropic_remeshing(Mobius_mesh<P>& mesh, double target_edge_length,
                                               const NP& np = parameters::default_values())
{
  internal::Remeshing_options options = internal::remeshing_options(target_edge_length, np);
  internal::require_no_garbage(mesh, "isotropic_remeshing");
  internal::refuse_non_manifold_joins(mesh, "isotropic_remeshing");
  internal::require_interpolated_channels<typename CGAL::Kernel_traits<P>::Kernel::FT>(mesh, "isotropic_remeshing");
  internal::require_valid_corner_indices(mesh, "isotropic_remeshing");
  const double largest_coordinate = internal::require_coordinates_in_range(mesh, "isotropic_remeshing");
  internal::require_length_resolved(largest_coordinate, target_edge_length, "isotropic_remeshing");
  if (options.protect_sharp_edges)
    internal::require_valid_edge_sharpness(mesh, parameters::default_values(), "isotropic_remeshing");
  // Narrow parts are found (and refused with allow_narrow_regions(false))
  // before the size check, whose message would not say why.
  const internal::Narrow_regions narrow =
    internal::find_narrow_regions(mesh, options, internal::remeshing_protection(mesh, options));
  internal::require_no_narrow_regions(narrow, options);
  const double estimated_faces = internal::check_remeshing_size(
    mesh, options,
    parameters::choose_parameter(parameters::get_parameter(np, CGAL_ext::internal_np::maximum_memory),
                                 internal::available_memory()));
  // The loop may not hold more than twice the estimate the memory check
  // accepted (nor more than the indices hold).
  options.face_budget = (std::min)(2 * estimated_faces, double(internal::max_faces));
  Isotropic_remeshing_result result;
  result.narrow_faces = narrow.faces;
  result.narrowest_width = narrow.narrowest_width;
  // An operation that fails part way (an Euler operation refused on input
  // the checks above cannot see, such as two faces on the same corners, or
  // the face budget) must leave the caller's mesh as it was: the mesh is
  // edited in place, so that the caller's property maps stay valid, and put
  // back from a copy if anything throws.
  // The limit surface of the input as it is, before its faces are split.
  const auto limit = internal::limit_surface_to_project_on(mesh, np);
  if (limit)
    options.project = [&limit](const internal::Remeshing_point& p) {
      const P on = limit->closest_point(P(p.x(), p.y(), p.z())).point;
      return internal::Remeshing_point(CGAL::to_double(on.x()), CGAL::to_double(on.y()), CGAL::to_double(on.z()));
    };
  const Mobius_mesh<P> before = mesh;
  const std::vector<std::size_t> values_before = internal::corner_value_counts(mesh);
  try {
    triangulate_faces(mesh);
    if (!mesh.corner_channels().empty()) {
      const std::vector<char> seams = internal::corner_seam_edges(mesh);
      result.seam_edges_protected = std::size_t(std::count(seams.begin(), seams.end(), char(1)));
    }
    {
      // The remesher keeps edge indices across splits and collapses: added
      // elements must not take the slots of removed ones while it runs.
      struct Appending
      {
        Mobius_mesh<P>& mesh;
        const bool recycled = mesh.does_recycle_garbage();
        explicit Appending(Mobius_mesh<P>& m) : mesh(m) { mesh.set_recycle_garbage(false); }
        ~Appending() { mesh.set_recycle_garbage(recycled); }
      } appending(mesh);
      const internal::Remeshing_run run = internal::Isotropic_remesher<P>(mesh, options).run();
      result.iterations = run.iterations;
      result.stopped_early = run.stopped_early;
      result.share_in_band = run.share_in_band;
    }
    mesh.collect_garbage();
    result.corner_values_interpolated = internal::added_values_in_use(mesh, values_before);
    internal::remove_unused_corner_values(mesh);
  } catch (...) {
    mesh = before;
    throw;
  }
  return result;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_ISOTROPIC_REMESHING_H
