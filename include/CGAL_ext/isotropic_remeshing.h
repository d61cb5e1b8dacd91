// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Isotropic remeshing of a Mobius_mesh (Botsch and Kobbelt), with the
// contract of CGAL's Polygon_mesh_processing::isotropic_remeshing(), on any
// surface: Möbius strips, Klein bottles and other one-sided surfaces included.

#ifndef CGAL_EXT_ISOTROPIC_REMESHING_H
#define CGAL_EXT_ISOTROPIC_REMESHING_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Remeshing/internal/Isotropic_remesher.h>
#include <CGAL_ext/Remeshing/internal/Remeshing_setup.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshEditing
/// \brief remeshes `mesh` into triangles whose edges are close to
/// `target_edge_length` (L), by Botsch and Kobbelt's loop, as
/// `CGAL::Polygon_mesh_processing::isotropic_remeshing()` does: each
/// iteration splits the edges longer than 4/3 L at their midpoints (longest
/// first), collapses the edges shorter than 4/5 L (shortest first) into
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
///     \cgalParamDescription{how many times the loop runs, from 0 to 1000}
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
/// \cgalNamedParamsEnd
/// \throws Parameter_error if L is not positive and finite, the number of
/// iterations is out of range, `maximum_memory` is not positive, `mesh` has
/// removed elements or a corner channel (the remeshed faces have no rule for
/// the corners: remove the channels, or remesh a copy without them), an edge's sharpness is NaN or negative (with
/// `protect_sharp_edges(true)`), a point has a coordinate beyond +-1e60 (where
/// squared lengths and normals in double overflow), the mesh is less than
/// 1e-60 across (where they underflow), or L is under 1024 times the spacing
/// of doubles at the largest coordinate (too fine for the coordinates).
/// \throws Size_error if the estimated result has more elements than the
/// mesh's indices hold or needs more than `maximum_memory`.
/// \throws Euler_error if a polygon cannot be triangulated (triangulate_faces()),
/// or if an edit is refused part way (two faces on the same corners, say).
/// In all these cases `mesh` is as it was before the call: the checks run
/// before it is touched, and a failure part way puts it back from a copy
/// (property maps taken before such a failure must then be taken again).
template <class P, class NP = parameters::Default_named_parameters>
void isotropic_remeshing(Mobius_mesh<P>& mesh, double target_edge_length, const NP& np = parameters::default_values())
{
  const internal::Remeshing_options options = internal::remeshing_options(target_edge_length, np);
  internal::require_no_garbage(mesh, "isotropic_remeshing");
  internal::refuse_corner_channels(mesh, "isotropic_remeshing",
                                   "splits, collapses, flips and relaxation move corners off the faces they belong to");
  const double largest_coordinate = internal::require_coordinates_in_range(mesh, "isotropic_remeshing");
  internal::require_length_resolved(largest_coordinate, target_edge_length, "isotropic_remeshing");
  if (options.protect_sharp_edges)
    internal::require_valid_edge_sharpness(mesh, parameters::default_values(), "isotropic_remeshing");
  internal::check_remeshing_size(mesh, options,
                                 parameters::choose_parameter(
                                   parameters::get_parameter(np, CGAL_ext::internal_np::maximum_memory),
                                   internal::available_memory()));
  // An operation that fails part way (an Euler operation refused on input
  // the checks above cannot see, such as two faces on the same corners)
  // must leave the caller's mesh as it was: the mesh is edited in place, so
  // that the caller's property maps stay valid, and put back from a copy if
  // anything throws.
  const Mobius_mesh<P> before = mesh;
  try {
    triangulate_faces(mesh);
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
      internal::Isotropic_remesher<P>(mesh, options).run();
    }
    mesh.collect_garbage();
  } catch (...) {
    mesh = before;
    throw;
  }
}

} // namespace CGAL_ext

#endif // CGAL_EXT_ISOTROPIC_REMESHING_H
