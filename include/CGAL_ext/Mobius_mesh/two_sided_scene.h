// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What a renderer draws to show the two sides of a surface: the orientation
// double cover of the mesh, each face twice, a hair apart along its normals,
// one colour per side, and the edges that matter (borders, Möbius edges,
// sharp edges) in their own colours. Free of any GUI library, so that a
// program with its own renderer, and the tests, can use it; the Qt viewer of
// draw_mobius_mesh.h draws it.

#ifndef CGAL_EXT_MOBIUS_MESH_TWO_SIDED_SCENE_H
#define CGAL_EXT_MOBIUS_MESH_TWO_SIDED_SCENE_H

#include <CGAL_ext/Mobius_mesh/Two_sided_style.h>
#include <CGAL_ext/Mobius_mesh/internal/Coordinate_checks.h>
#include <CGAL_ext/Mobius_mesh/internal/Two_sided_geometry.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshDrawing
/// \brief builds the orientation double cover of `mesh` for drawing.
///
/// A one-sided surface has no normal field, so no renderer can shade "the
/// front" of it; it can shade the front of each face. Each face is drawn
/// twice, `style.gap / 2` of the bounding box's diagonal to either side of
/// the surface along the unit vertex normals seen from its darts
/// (`vertex_normal(Dart, ...)`): the side its orientation points to in
/// `style.front`, the other in `style.back`. Faces that agree in orientation
/// share their sheets, so an orientable patch shows one colour per side, and
/// the colours swap across each Möbius edge: on a one-sided surface both
/// colours meet on one side. Each edge with a face is drawn on both sheets,
/// coloured by kind (border, Möbius, sharp by its sharpness, or plain; plain
/// edges only if `style.plain_edges`).
///
/// \param mesh a mesh without garbage
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{two_sided_style}
///     \cgalParamDescription{a `Two_sided_style`: colours and gap}
///     \cgalParamDefault{`Two_sided_style()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_color_map}
///     \cgalParamDescription{a readable property map to `CGAL::IO::Color`, instead of the style's
///       front and back colours; edges keep theirs. Keyed by `Face_index`: both sides of each face
///       in its colour (a scalar field that needs no side, as a distance). Keyed by `Dart`: each
///       side in its own, the colour of the side of `face(d)` seen from `d`, asked for with
///       `halfedge(f)` (the front) and `halfedge(f).flipped()` (the back): a field that has a
///       value per side, as a mean curvature, which changes sign from one side to the other}
///     \cgalParamDefault{none: the style's side colours}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_sharpness_map}
///     \cgalParamDescription{a readable property map from `Edge_index` to sharpness}
///     \cgalParamDefault{the mesh's `e:sharpness` map where it has one, else no sharp edges}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`mesh.points()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDefault{the kernel of the point type, through `CGAL::Kernel_traits`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Parameter_error if the mesh has garbage, the gap is negative or not
/// finite, or a point is not in the range of the library's algorithms in
/// double (coordinates within +-1e60, the mesh at least 1e-60 across, unless
/// it is a single point).
template <class P, class NP = parameters::Default_named_parameters>
Two_sided_scene make_two_sided_scene(const Mobius_mesh<P>& mesh, const NP& np = parameters::default_values())
{
  namespace pm = CGAL_ext::parameters;
  internal::require_no_garbage(mesh, "make_two_sided_scene");
  const Two_sided_style style =
    pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::two_sided_style), Two_sided_style());
  if (!(style.gap >= 0) || !std::isfinite(style.gap))
    throw Parameter_error("make_two_sided_scene: the gap " + std::to_string(style.gap) +
                          " is not a finite number >= 0");
  const internal::Two_sided_geometry<P, NP> geometry(mesh, np);
  // Normals and the gap are computed in double from squared lengths.
  internal::require_coordinates_in_range(mesh, "make_two_sided_scene",
                                         [&](Vertex_index v) { return geometry.point(v); });
  Two_sided_scene scene;
  for (Vertex_index v : mesh.vertices())
    scene.bbox += geometry.point(v).bbox();
  const double diagonal = std::sqrt(CGAL::square(scene.bbox.x_span()) + CGAL::square(scene.bbox.y_span()) +
                                    CGAL::square(scene.bbox.z_span()));
  const double half_gap = mesh.number_of_vertices() ? style.gap * diagonal / 2 : 0;
  internal::add_two_sided_faces(mesh, geometry, style, half_gap, internal::face_color_values(mesh, np), scene);
  internal::add_two_sided_segments(mesh, geometry, internal::edge_sharpness_values(mesh, np), style, half_gap,
                                   scene);
  return scene;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TWO_SIDED_SCENE_H
