// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Limit positions, tangents and normals of Catmull–Clark and Loop surfaces,
// and limit values of corner channels, from the limit masks of OpenSubdiv's
// Sdc schemes, on a mesh of any level.

#ifndef CGAL_EXT_SUBDIVISION_LIMIT_H
#define CGAL_EXT_SUBDIVISION_LIMIT_H

#include <CGAL_ext/Subdivision/Limit_tangents.h>
#include <CGAL_ext/Subdivision/internal/Limit_face_varying.h>
#include <CGAL_ext/Subdivision/internal/Limit_stencils.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/exceptions.h>

#include <cmath>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {

/// \ingroup PkgSubdivision
/// \brief the limit position of vertex `v` on the surface that `Mask`
/// (`Catmull_clark_mask` or `Loop_mask`) converges to from `mesh`, by
/// OpenSubdiv's limit masks (its `Far::PrimvarRefiner::Limit()` on the last
/// level): smooth, crease (¹⁄₆, ⅔, ¹⁄₆) and corner rules; a vertex that still
/// has semi-sharp edges or sharpness follows the crease or corner rule, as
/// there.
///
/// Exact on exact kernels for Catmull–Clark, and for Loop at valences 3, 4
/// and 6 and on creases and corners; other Loop weights involve a cosine.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{edge_sharpness_map, vertex_sharpness_map}
///     \cgalParamDefault{the maps `"e:sharpness"` / `"v:sharpness"` of `mesh` if it has them, else all 0;
///       a subdivided mesh carries those of its level}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_interpolation}
///     \cgalParamDescription{border edges are infinitely sharp; with
///       `Boundary_interpolation::edge_and_corner` a border vertex of one face is a corner}
///     \cgalParamDefault{`Boundary_interpolation::edge_only`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, geom_traits}
///     \cgalParamDefault{`mesh.points()`, the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Parameter_error if `v` is not a vertex of `mesh`, a face
/// around it is not a quad (Catmull–Clark) or a triangle (Loop), or a
/// sharpness of its ring is NaN or negative.
template <class Mask, class P, class NP = parameters::Default_named_parameters>
typename internal::Normal_types<P, NP>::Point limit_point(Vertex_index v, const Mobius_mesh<P>& mesh,
                                                          const NP& np = parameters::default_values())
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  if (!mesh.is_valid(v))
    throw Parameter_error("limit_point: vertex " + std::to_string(v.idx()) + " is not a vertex of the mesh");
  const internal::Limit_settings<P, NP> s(mesh, np);
  if (mesh.is_isolated(v))
    return get(s.points, v);
  internal::Limit_ring<P> ring;
  internal::gather_ring<Mask>("limit_point", internal::vertex_side_dart(v, mesh), mesh, s, ring);
  return internal::limit_point_of_ring<Mask>(ring, s);
}

/// \ingroup PkgSubdivision
/// \brief writes `limit_point<Mask>(v, mesh, np)` for every vertex `v` into
/// `limit_points` (which may be `mesh.points()`: all are computed first).
/// \throws Parameter_error if a face is not a quad (Catmull–Clark) or a
/// triangle (Loop), a sharpness is NaN or negative, or `mesh` has removed
/// elements; nothing is written then.
template <class Mask, class P, class VertexPointMap, class NP = parameters::Default_named_parameters>
void limit_points(const Mobius_mesh<P>& mesh, VertexPointMap limit_points, const NP& np = parameters::default_values())
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  const internal::Limit_settings<P, NP> s(mesh, np);
  using Point = typename internal::Normal_types<P, NP>::Point;
  internal::write_per_vertex<Mask>(
    "limit_points", mesh, s, limit_points, [&](Vertex_index v) { return Point(get(s.points, v)); },
    [&](const internal::Limit_ring<P>& ring) { return internal::limit_point_of_ring<Mask>(ring, s); });
}

/// \ingroup PkgSubdivision
/// \brief the limit tangents at `target(d)`, seen from the side of `d`'s
/// face: the ring is walked from `next(d)` the way the darts go around the
/// vertex, so `tangent1` follows the edge of `next(d)` at a smooth vertex;
/// at a border vertex the walk starts at the border, as OpenSubdiv's does.
/// At a crease vertex `tangent1` runs along the crease and `tangent2` across
/// the faces between the first two sharp edges the walk meets: the surface
/// has a tangent plane on each side of an interior crease.
/// On a one-sided surface the darts carry one orientation around the
/// vertex, across Möbius edges too; the other side's darts give `tangent2`
/// mirrored, hence the opposite normal.
///
/// The tangent weights involve cosines and square roots: computed in
/// `double`, then applied in the kernel. Named parameters as `limit_point()`.
/// \throws Parameter_error if `d` is not a dart of a face of `mesh`, a face
/// around its target is not a quad (Catmull–Clark) or a triangle (Loop), or
/// a sharpness of its ring is NaN or negative.
template <class Mask, class P, class NP = parameters::Default_named_parameters>
Limit_tangents<typename internal::Normal_types<P, NP>::Vector>
limit_tangents(Dart d, const Mobius_mesh<P>& mesh, const NP& np = parameters::default_values())
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  const internal::Limit_settings<P, NP> s(mesh, np);
  return internal::limit_tangents_at<Mask>("limit_tangents", d, mesh, s);
}

/// \ingroup PkgSubdivision
/// \brief the limit normal at `target(d)` seen from the side of `d`'s face:
/// `tangent1 × tangent2` of `limit_tangents()`, a unit vector with
/// `parameters::normalize(true)`. On a mesh without Möbius edges (after
/// `orient()`) it points the way the faces' own normals do.
/// \throws Parameter_error as `limit_tangents()`.
template <class Mask, class P, class NP = parameters::Default_named_parameters>
typename internal::Normal_types<P, NP>::Vector limit_normal(Dart d, const Mobius_mesh<P>& mesh,
                                                             const NP& np = parameters::default_values())
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  const internal::Limit_settings<P, NP> s(mesh, np);
  const auto t = internal::limit_tangents_at<Mask>("limit_normal", d, mesh, s);
  const auto n = s.traits.construct_cross_product_vector_3_object()(t.tangent1, t.tangent2);
  return s.normalize ? internal::unit_vector(n, s.traits) : n;
}

/// \ingroup PkgSubdivision
/// \brief writes the limit normal of every vertex `v` into `limit_normals`,
/// seen from the side that `vertex_normal(v, mesh)` takes (a face of `v`):
/// consistent on a mesh without Möbius edges; on a one-sided surface only
/// as meaningful as that face's orientation (see `limit_normal()`). The
/// zero vector for an isolated vertex. Named parameters as `limit_normal()`.
/// \throws Parameter_error as `limit_points()`; nothing is written then.
template <class Mask, class P, class VertexNormalMap, class NP = parameters::Default_named_parameters>
void limit_normals(const Mobius_mesh<P>& mesh, VertexNormalMap limit_normals,
                   const NP& np = parameters::default_values())
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  const internal::Limit_settings<P, NP> s(mesh, np);
  const auto cross = s.traits.construct_cross_product_vector_3_object();
  using Vector = typename internal::Normal_types<P, NP>::Vector;
  internal::write_per_vertex<Mask>(
    "limit_normals", mesh, s, limit_normals, [](Vertex_index) { return Vector(CGAL::NULL_VECTOR); },
    [&](const internal::Limit_ring<P>& ring) {
      const auto t = internal::limit_tangents_of_ring<Mask>(ring, s);
      const Vector n = cross(t.tangent1, t.tangent2);
      return s.normalize ? internal::unit_vector(n, s.traits) : n;
    });
}

/// \ingroup PkgSubdivision
/// \brief writes into `limits` the limit of every value of the corner
/// channel `channel` (texture coordinates, corner normals...) on the surface
/// that `Mask` (`Catmull_clark_mask` or `Loop_mask`) converges to from
/// `mesh`: OpenSubdiv's `Far::PrimvarRefiner::LimitFaceVarying()` on the
/// last level. As subdivision carries a channel, the channel's own topology
/// decides per value: a value whose corners around its vertex are all one
/// (no seam there, nor a border the mode sharpens) takes the vertex's limit
/// mask (`limit_point()`'s) on the values of its ring; along a seam a value
/// is a crease of the channel (¹⁄₆, ⅔, ¹⁄₆ towards the far ends of the two
/// seam or border edges that bound its faces) or a corner (kept), as the
/// `face_varying_interpolation` mode, the mesh's creases and its borders
/// make it; with `Face_varying_interpolation::all` every value is kept.
/// The tags are read from `mesh` as it stands; OpenSubdiv's come down the
/// levels of a refinement and can remember a vertex's spent sharpness under
/// `corners_plus1` and `corners_plus2` (doc/corner_data.md, "Limit values"),
/// which `limit_face_varying()` on a `Refiner` follows.
///
/// `limits` may be `channel` itself (all values are computed first). Each
/// corner of `limits` gets the limit of its value at its vertex: a value
/// index used at one vertex only (every value of a subdivided mesh) keeps
/// its index, so `limits` has `channel`'s indices and seams and can be
/// written with the mesh; an index used at several vertices gets a value
/// more for each further vertex; unused values are copied.
///
/// Exact where `limit_point()` is, with an exact kernel's number type (the
/// channel's values are combined in the kernel's field). In floating point
/// a crease of the channel is weighted with OpenSubdiv's single-precision
/// constants (1/6 and 2/3 rounded to `float`, which sum to 1 + 3·10⁻⁸), so
/// that the two agree to rounding; exact number types use 1/6 and 2/3.
///
/// \tparam T a value type that subdivision carries (`double`, `std::array`
///   of 2 to 4 `double`s or `float`s, the kernel's `Point_2`, `Vector_2`,
///   `Point_3`, `Vector_3`)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_varying_interpolation}
///     \cgalParamDescription{which values stay linear, as OpenSubdiv's `FVarLinearInterpolation`;
///       give the one the mesh was subdivided with}
///     \cgalParamDefault{`Face_varying_interpolation::corners_plus1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_sharpness_map, vertex_sharpness_map, boundary_interpolation}
///     \cgalParamDefault{as `limit_point()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Parameter_error if a channel is not one of `mesh`, a face corner
/// has no value (or an index beyond the values), a face is not a quad
/// (Catmull–Clark) or a triangle (Loop), a sharpness is NaN or negative, or
/// `mesh` has removed elements or non-manifold joins; nothing is written then.
template <class Mask, class P, class T, class NP = parameters::Default_named_parameters>
void limit_corner_values(const Mobius_mesh<P>& mesh, const CGAL_ext::internal::Corner_channel<Halfedge_index, T>& channel,
                         const CGAL_ext::internal::Corner_channel<Halfedge_index, T>& limits,
                         const NP& np = parameters::default_values())
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  internal::write_corner_limits<Mask>("limit_corner_values", mesh, channel, limits, np);
}

/// \ingroup PkgSubdivision
/// \brief replaces the values of the corner channel named `name` (`"c:uv"`,
/// `"c:normal"`, whatever its value type among those subdivision carries)
/// by their limits: `limit_corner_values<Mask>(mesh, c, c, np)` for that
/// channel `c`.
///
/// \code
/// CGAL_ext::Subdivision::catmull_clark(mesh, parameters::number_of_iterations(2));
/// CGAL_ext::Subdivision::limit_points<Catmull_clark_mask>(mesh, mesh.points());
/// CGAL_ext::Subdivision::limit_corner_values<Catmull_clark_mask>(mesh, "c:uv");
/// CGAL_ext::IO::write_polygon_mesh("limit.obj", mesh);
/// \endcode
/// \throws Parameter_error if `mesh` has no corner channel `name`, its
/// values have no linear combination, or as the function above.
template <class Mask, class P, class NP = parameters::Default_named_parameters>
void limit_corner_values(Mobius_mesh<P>& mesh, const std::string& name, const NP& np = parameters::default_values())
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  internal::write_corner_limits<Mask>("limit_corner_values", mesh, name, np);
}

/// \ingroup PkgSubdivision
/// \brief a corner channel through the levels of `refiner` and to the limit:
/// `Refiner::interpolate_face_varying(mode, corners, values)`, after which
/// each value of the last level is replaced by its limit. This is
/// OpenSubdiv's `InterpolateFaceVarying()` at each level followed by
/// `LimitFaceVarying()`, to the letter: the rule of each value (vertex mask,
/// crease or corner) comes from the tags the refinement carried down the
/// levels, which remember sharpness since spent (see
/// `limit_corner_values()`, which reads them from a mesh as it stands).
/// `corners` holds on return the value index of each halfedge's corner of
/// the last level (null on the border), `values` their limits; the numbers
/// and the weights are as `limit_corner_values()`'s.
/// \tparam Mask `Catmull_clark_mask` or `Loop_mask`
/// \throws Parameter_error if a face of the last level is not a quad
/// (Catmull–Clark) or a triangle (Loop), checked before anything is
/// written, or as `Refiner::interpolate_face_varying()`.
template <class Mask, class W, class Value>
void limit_face_varying(const Refiner<Mask, W>& refiner, Face_varying_interpolation mode,
                        std::vector<std::uint32_t>& corners, std::vector<Value>& values)
{
  static_assert(internal::has_limit_masks<Mask>, "limit masks exist for Catmull_clark_mask and Loop_mask");
  internal::limit_face_varying(refiner, mode, corners, values);
}

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_LIMIT_H
