// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Subdivision of Mobius_mesh: Catmull–Clark, Loop and bilinear, with
// OpenSubdiv's border, crease and corner rules, and Doo–Sabin and √3, all
// across Möbius connections.

#ifndef CGAL_EXT_SUBDIVISION_H
#define CGAL_EXT_SUBDIVISION_H

#include <CGAL_ext/Subdivision/internal/Joined_subdivision.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/Refiner.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
/// Defined when the subdivision functions accept `CGAL::Parallel_tag`.
#define CGAL_EXT_SUBDIVISION_PARALLEL 1
#endif

namespace CGAL_ext {
namespace Subdivision {

/// \ingroup PkgSubdivision
///
/// Subdivides `mesh` with a `SubdivisionMask`: the general form of
/// `catmull_clark()`, `loop()`, `bilinear()` and `linear()`, which document
/// the named parameters.
///
/// Property maps are carried to the result as follows (doc/subdivision.md):
/// vertex maps of `float`, `double`, the kernel's `Point_3` and `Vector_3`,
/// and `std::array`s of 2 to 4 `float`s or `double`s are interpolated with
/// the points' weights; face maps of any type go to the child faces, each
/// taking its parent face's value (quad and triangle splits: Catmull–Clark,
/// Loop, bilinear, linear). Other maps are dropped: edge and halfedge maps
/// (but the sharpness), vertex maps of types without a linear combination
/// (integers, `bool`, strings, colours of bytes), and face maps of Doo–Sabin
/// and √3, whose faces lie across several parent faces.
///
/// \throws Parameter_error as the scheme's own function does (a NaN or
/// negative sharpness, a face the mask does not split, a point in double
/// that is not finite or beyond +-1e300); `mesh` is then unchanged.
template <class ConcurrencyTag = CGAL::Sequential_tag, class Mask, class P,
          class NamedParameters = parameters::Default_named_parameters>
void subdivide(Mobius_mesh<P>& mesh, const Mask& mask,
               const NamedParameters& np = parameters::default_values())
{
  internal::subdivide<ConcurrencyTag>(mesh, mask, np);
}

/// \ingroup PkgSubdivision
///
/// Catmull–Clark subdivision of a mesh of any polygons, orientable or not,
/// with OpenSubdiv's rules for borders, creases and corners. Each step
/// replaces a face of n sides by n quads. Möbius edges are subdivided with
/// the smooth rules, and the result does not depend on the faces'
/// orientations.
///
/// The vertices of the result are laid out as `[vertex points | edge points |
/// face points]`: vertex `v` of the input becomes vertex `v`, edge `e` gives
/// vertex `nv + e`, face `f` gives vertex `nv + ne + f` (per step).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, or `CGAL::Parallel_tag` to
///   refine and interpolate with TBB (if `CGAL_EXT_SUBDIVISION_PARALLEL` is
///   defined), bit for bit as the serial result, each step whose level is
///   large enough for the threads available (`Subdivision::runs_in_parallel()`)
///   and, for Catmull–Clark, Loop and bilinear, where this process's timings
///   favour threads (see `Subdivision::Refiner`). Exact kernels are refined
///   and interpolated serially.
/// \param mesh the mesh, replaced by the result
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the number of subdivision steps}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map giving the input points; the result's points are in `mesh.points()`}
///     \cgalParamDefault{`mesh.points()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_interpolation}
///     \cgalParamDescription{`Boundary_interpolation::edge_only` (border edges are creases),
///       `edge_and_corner` (also border vertices with one face are corners), or `none`
///       (the same points as `edge_only`; faces with a border vertex, and what they
///       become, are marked in the face property `"f:hole"` of type `std::uint8_t`,
///       as OpenSubdiv marks them as holes)}
///     \cgalParamDefault{`Boundary_interpolation::edge_only`}
///   \cgalParamNEnd
///   \cgalParamNBegin{crease_method}
///     \cgalParamDescription{how semi-sharp creases decay: `Crease_method::uniform` or `chaikin`}
///     \cgalParamDefault{`Crease_method::uniform`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_rule}
///     \cgalParamDescription{`Vertex_rule::standard`, or `edge_points` (the smooth vertex rule
///       averages the new edge points instead of the old neighbours)}
///     \cgalParamDefault{`Vertex_rule::standard`}
///   \cgalParamNEnd
///   \cgalParamNBegin{triangle_subdivision}
///     \cgalParamDescription{`Triangle_subdivision::catmark`, or `smooth` (OpenSubdiv's smoother
///       edge rule next to triangles)}
///     \cgalParamDefault{`Triangle_subdivision::catmark`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_sharpness_map}
///     \cgalParamDescription{a readable property map from `Edge_index` to `float`:
///       0 smooth, 10 or more infinitely sharp, in between semi-sharp}
///     \cgalParamDefault{the map `"e:sharpness"` of `mesh` if it has one, else all 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_sharpness_map}
///     \cgalParamDescription{a readable property map from `Vertex_index` to `float` (corners)}
///     \cgalParamDefault{the map `"v:sharpness"` of `mesh` if it has one, else all 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_memory}
///     \cgalParamDescription{the most memory, in bytes, the subdivision may take: a larger
///       estimated peak is refused with `Size_error` before anything is allocated}
///     \cgalParamDefault{the memory available (Linux's `MemAvailable`, else the physical memory)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// If sharpness was given, the result has maps `"e:sharpness"` and
/// `"v:sharpness"` with the decayed sharpness, so that subdividing it again
/// continues the same surface.
///
/// \throws Parameter_error if a sharpness is NaN or negative, or (points in
/// double) a point is not finite or has a coordinate beyond +-1e300, where
/// the sums of a ring's points overflow; `mesh` is then unchanged.
/// \throws Size_error, before anything is allocated, if the result would have
/// more elements than a `Mobius_mesh` indexes, or its estimated peak of memory
/// is more than `maximum_memory` (all the schemes); `mesh` is then unchanged.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NamedParameters = parameters::Default_named_parameters>
void catmull_clark(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  namespace pm = CGAL_ext::parameters;
  Catmull_clark_mask mask;
  mask.vertex_rule =
    pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::vertex_rule), Vertex_rule::standard);
  mask.triangle_subdivision = CGAL_ext::internal::triangle_subdivision_of(np);
  internal::subdivide<ConcurrencyTag>(mesh, mask, np);
}

/// \ingroup PkgSubdivision
///
/// Loop subdivision of a triangle mesh, orientable or not, with OpenSubdiv's
/// rules. Each step splits a triangle in four. Child vertices are laid out as
/// `[vertex points | edge points]`. Named parameters as `catmull_clark()`,
/// without `vertex_rule` and `triangle_subdivision`.
///
/// \throws Parameter_error if a face is not a triangle, a sharpness is NaN or
/// negative, or a point in double is not finite or beyond +-1e300; `mesh` is
/// then unchanged.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NamedParameters = parameters::Default_named_parameters>
void loop(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  internal::subdivide<ConcurrencyTag>(mesh, Loop_mask(), np);
}

/// \ingroup PkgSubdivision
///
/// Bilinear subdivision: the Catmull–Clark split with new points at edge
/// midpoints and face centroids and old points kept (OpenSubdiv's bilinear
/// scheme). Named parameters `number_of_iterations`, `vertex_point_map` and
/// `maximum_memory` (as `catmull_clark()`).
///
/// \throws Parameter_error if a point in double is not finite or beyond
/// +-1e300; `mesh` is then unchanged.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NamedParameters = parameters::Default_named_parameters>
void bilinear(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  internal::subdivide<ConcurrencyTag>(mesh, Bilinear_mask(), np);
}

/// \ingroup PkgSubdivision
///
/// Linear (midpoint) subdivision of a triangle mesh: the Loop split, each
/// triangle into four, with new points at edge midpoints and old points kept
/// (CGAL's `PTQ` with `Linear_mask_3`). Child vertices are laid out as
/// `[vertex points | edge points]`. Named parameters `number_of_iterations`,
/// `vertex_point_map` and `maximum_memory`. For other polygons, `bilinear()`.
///
/// \throws Parameter_error if a face is not a triangle, or a point in double
/// is not finite or beyond +-1e300; `mesh` is then unchanged.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NamedParameters = parameters::Default_named_parameters>
void linear(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  internal::subdivide<ConcurrencyTag>(mesh, Linear_mask(), np);
}

/// \ingroup PkgSubdivision
///
/// Doo–Sabin subdivision of a mesh of any polygons, orientable or not (see
/// `Doo_sabin_mask` for the border rules). Each step makes a vertex per face
/// corner, and a face per face, per interior edge (a quad) and per vertex
/// with three or more faces; the child vertex of a corner is numbered as the
/// corner (faces in order, each face's corners from its first halfedge).
/// Named parameters `number_of_iterations`, `vertex_point_map` and
/// `maximum_memory`; sharpness and boundary options do not apply.
///
/// \throws Parameter_error if a point in double is not finite or beyond
/// +-1e300; `mesh` is then unchanged.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NamedParameters = parameters::Default_named_parameters>
void doo_sabin(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  internal::subdivide<ConcurrencyTag>(mesh, Doo_sabin_mask(), np);
}

/// \ingroup PkgSubdivision
///
/// Kobbelt's √3 subdivision of a triangle mesh, orientable or not, with his
/// border rules (see `Sqrt3_mask`): step `i` of a call (from 0) refines
/// the border when `i` is odd, as CGAL's `Sqrt3_subdivision` does, so border
/// refinement needs two steps in one call. Child vertices are laid out as
/// `[vertices | centroids | border points]`. Named parameters
/// `number_of_iterations`, `vertex_point_map` and `maximum_memory`.
///
/// \throws Parameter_error if a face is not a triangle, or a point in double
/// is not finite or beyond +-1e300; `mesh` is then unchanged.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NamedParameters = parameters::Default_named_parameters>
void sqrt3(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  internal::subdivide<ConcurrencyTag>(mesh, Sqrt3_mask(), np);
}

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_H
