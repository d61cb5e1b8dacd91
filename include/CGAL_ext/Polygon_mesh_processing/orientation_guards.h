// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// CGAL's functions that need a volume, hence a global orientation, refuse a
// Mobius_mesh with Möbius edges before they touch it: overloads of
// PMP::volume(), PMP::centroid() and PMP::orient_to_bound_a_volume() for the
// mesh, more specialised than CGAL's, found by a call made after this header
// is included. So does PMP::angle_and_area_smoothing() (smooth_mesh()), whose
// moves turn edges about face normals taken in each face's own orientation.

#ifndef CGAL_EXT_POLYGON_MESH_PROCESSING_ORIENTATION_GUARDS_H
#define CGAL_EXT_POLYGON_MESH_PROCESSING_ORIENTATION_GUARDS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>

#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

namespace CGAL {
namespace Polygon_mesh_processing {

/// `PMP::volume()` of a `Mobius_mesh`: a closed one-sided surface bounds no
/// volume, and CGAL's signed sum over faces would follow arbitrary face
/// orientations, so a mesh with Möbius edges is refused with
/// `CGAL_ext::Parameter_error` (`CGAL_ext::require_orientable_model()`);
/// without Möbius edges it is CGAL's `volume()`.
template <class P, typename CGAL_NP_TEMPLATE_PARAMETERS>
typename GetGeomTraits<CGAL_ext::Mobius_mesh<P>, CGAL_NP_CLASS>::type::FT
volume(const CGAL_ext::Mobius_mesh<P>& tmesh, const CGAL_NP_CLASS& np = parameters::default_values())
{
  CGAL_ext::require_orientable_model(tmesh, "PMP::volume()");
  return CGAL::Polygon_mesh_processing::volume<CGAL_ext::Mobius_mesh<P>, NP_T, NP_Tag, NP_Base>(tmesh, np);
}

/// `PMP::centroid()` of a `Mobius_mesh`: the centroid of the enclosed volume,
/// refused as `volume()` on a mesh with Möbius edges.
template <class P, typename CGAL_NP_TEMPLATE_PARAMETERS>
typename GetGeomTraits<CGAL_ext::Mobius_mesh<P>, CGAL_NP_CLASS>::type::Point_3
centroid(const CGAL_ext::Mobius_mesh<P>& tmesh, const CGAL_NP_CLASS& np = parameters::default_values())
{
  CGAL_ext::require_orientable_model(tmesh, "PMP::centroid()");
  return CGAL::Polygon_mesh_processing::centroid<CGAL_ext::Mobius_mesh<P>, NP_T, NP_Tag, NP_Base>(tmesh, np);
}

/// `PMP::orient_to_bound_a_volume()` of a `Mobius_mesh`: refused as
/// `volume()` on a mesh with Möbius edges (`CGAL_ext::orient()` removes them
/// from an orientable mesh).
template <class P, class NamedParameters = parameters::Default_named_parameters>
void orient_to_bound_a_volume(CGAL_ext::Mobius_mesh<P>& tm, const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::require_orientable_model(tm, "PMP::orient_to_bound_a_volume()");
  CGAL::Polygon_mesh_processing::orient_to_bound_a_volume<CGAL_ext::Mobius_mesh<P>, NamedParameters>(tm, np);
}

/// `PMP::angle_and_area_smoothing()` of faces of a `Mobius_mesh`: its angle
/// moves rotate edges about each face's normal in the face's own orientation,
/// which disagree across a Möbius edge (the result differs from the same
/// smoothing on the orientation double cover), so a mesh with Möbius edges
/// is refused; without Möbius edges it is CGAL's function.
template <class P, class FaceRange, class NamedParameters = parameters::Default_named_parameters>
void angle_and_area_smoothing(const FaceRange& faces, CGAL_ext::Mobius_mesh<P>& tmesh,
                              const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::require_orientable_model(tmesh, "PMP::angle_and_area_smoothing()");
  CGAL::Polygon_mesh_processing::angle_and_area_smoothing<CGAL_ext::Mobius_mesh<P>, FaceRange, NamedParameters>(
    faces, tmesh, np);
}

/// `PMP::angle_and_area_smoothing()` of all faces of a `Mobius_mesh`, refused as above.
template <class P, typename CGAL_NP_TEMPLATE_PARAMETERS>
void angle_and_area_smoothing(CGAL_ext::Mobius_mesh<P>& tmesh, const CGAL_NP_CLASS& np = parameters::default_values())
{
  CGAL::Polygon_mesh_processing::angle_and_area_smoothing(faces(tmesh), tmesh, np);
}

/// `PMP::smooth_mesh()` (CGAL 5.5's name of `angle_and_area_smoothing()`) of a
/// `Mobius_mesh`, refused as above.
template <class P, class FaceRange, class NamedParameters = parameters::Default_named_parameters>
void smooth_mesh(const FaceRange& faces, CGAL_ext::Mobius_mesh<P>& tmesh,
                 const NamedParameters& np = parameters::default_values())
{
  CGAL::Polygon_mesh_processing::angle_and_area_smoothing(faces, tmesh, np);
}

/// `PMP::smooth_mesh()` of all faces of a `Mobius_mesh`, refused as above.
template <class P, typename CGAL_NP_TEMPLATE_PARAMETERS>
void smooth_mesh(CGAL_ext::Mobius_mesh<P>& tmesh, const CGAL_NP_CLASS& np = parameters::default_values())
{
  CGAL::Polygon_mesh_processing::angle_and_area_smoothing(faces(tmesh), tmesh, np);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_EXT_POLYGON_MESH_PROCESSING_ORIENTATION_GUARDS_H
