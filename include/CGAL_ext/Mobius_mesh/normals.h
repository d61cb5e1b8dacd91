// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Face and vertex normals on a Mobius_mesh. A one-sided surface has no
// global normal field, so every normal here is seen from the side of a dart:
// the unflipped darts of a face see its normal, the flipped darts its negation.

#ifndef CGAL_EXT_MOBIUS_MESH_NORMALS_H
#define CGAL_EXT_MOBIUS_MESH_NORMALS_H

#include <CGAL_ext/Mobius_mesh/Vertex_normal_weighting.h>
#include <CGAL_ext/Mobius_mesh/internal/Normal_sums.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshNormals
/// \brief the normal of face `f` in the face's own orientation, by Newell's method.
///
/// Unnormalised (the default), it is the sum over the face's edges of the
/// cross-product terms of Newell's method: twice the face's vector area, whose
/// length is twice the area for a planar face. It needs no square root, so it
/// is exact on exact kernels (EPECK, `Simple_cartesian<CGAL::Exact_rational>`).
/// For a non-planar face it is the normal of the plane that Newell's method
/// fits, the same as CGAL's `Polygon_mesh_processing::compute_face_normal()`.
///
/// \param f a face of `mesh`
/// \param mesh the mesh
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{normalize}
///     \cgalParamDescription{`true` to return a unit vector (through `CGAL::approximate_sqrt()`,
///                           so not exact); the zero vector of a degenerate face stays zero}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a readable property map from `Vertex_index` to points}
///     \cgalParamDefault{`mesh.points()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{a CGAL kernel}
///     \cgalParamDefault{the kernel of the point type, through `CGAL::Kernel_traits`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns a `Vector_3` of the traits
/// \throws Parameter_error if `f` is not a face of `mesh`.
template <class P, class NP = parameters::Default_named_parameters>
typename internal::Normal_types<P, NP>::Vector face_normal(Face_index f, const Mobius_mesh<P>& mesh,
                                                           const NP& np = parameters::default_values())
{
  internal::check_face("face_normal", f, mesh);
  const internal::Normal_settings<P, NP> s(mesh, np);
  const auto n = internal::newell_vector(f, mesh, s);
  return s.normalize ? internal::unit_vector(n, s.traits) : n;
}

/// \ingroup PkgMobiusMeshNormals
/// \brief the normal of `face(d)` seen from the side of dart `d`: the face
/// normal if `d` is unflipped, its negation if `d` is flipped.
///
/// So `face_normal(d.flipped(), m) == -face_normal(d, m)`, and two darts that
/// are opposite across an edge, Möbius or not, see their faces from the same side.
/// Named parameters as for `face_normal(Face_index, ...)`.
/// \throws Parameter_error if `d` is not a dart of `mesh` or is a border dart (it has no face).
template <class P, class NP = parameters::Default_named_parameters>
typename internal::Normal_types<P, NP>::Vector face_normal(Dart d, const Mobius_mesh<P>& mesh,
                                                           const NP& np = parameters::default_values())
{
  internal::check_dart("face_normal", d, mesh);
  if (mesh.is_border(d))
    throw Parameter_error("face_normal: dart " + internal::describe(d) + " is a border dart and has no face");
  const internal::Normal_settings<P, NP> s(mesh, np);
  auto n = internal::newell_vector(mesh.face(d), mesh, s);
  if (d.is_flipped())
    n = s.traits.construct_opposite_vector_3_object()(n);
  return s.normalize ? internal::unit_vector(n, s.traits) : n;
}

/// \ingroup PkgMobiusMeshNormals
/// \brief the normal at `target(d)` seen from the side of `d`.
///
/// The weighted sum of the normals of the faces around `target(d)`, gathered
/// by circulating from `d` (`halfedges_around_target(d, mesh)`): each face is
/// taken as the circulation's dart in it sees it, so the sum uses one
/// orientation of the vertex's fan even where the fan crosses Möbius edges.
/// For a dart of a face that is the side of `face(d)`: the result has the
/// sign of `face_normal(d)` wherever the surface is smooth. For a border dart
/// it is the side of the face of `opposite(d)` as seen by `opposite(d)` —
/// the orientation in which the border loop runs against its faces, as in
/// `Surface_mesh` — which is also the side of the next face dart around the
/// vertex. The two darts of a face that end at one vertex, `d` and
/// `next(d).flipped()`, give opposite normals.
///
/// \param d a dart of `mesh`
/// \param mesh the mesh
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_normal_weighting}
///     \cgalParamDescription{a `Vertex_normal_weighting`: `uniform`, `area` or `angle`}
///     \cgalParamDefault{`Vertex_normal_weighting::area`, the only exact one}
///   \cgalParamNEnd
///   \cgalParamNBegin{normalize}
///     \cgalParamDescription{`true` to return a unit vector (a zero sum stays zero)}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`mesh.points()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDefault{the kernel of the point type, through `CGAL::Kernel_traits`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Parameter_error if `d` is not a dart of `mesh`.
template <class P, class NP = parameters::Default_named_parameters>
typename internal::Normal_types<P, NP>::Vector vertex_normal(Dart d, const Mobius_mesh<P>& mesh,
                                                             const NP& np = parameters::default_values())
{
  internal::check_dart("vertex_normal", d, mesh);
  const internal::Normal_settings<P, NP> s(mesh, np);
  const auto face_vector = [&](Face_index f) { return internal::weighted_face_vector(f, mesh, s); };
  return internal::fan_normal(d, mesh, s, face_vector);
}

/// \ingroup PkgMobiusMeshNormals
/// \brief the normal at `v` seen from the side of the orientation of one of
/// its faces: that of `halfedge(v)`, or the first face around `v` from
/// `halfedge(v)` when that is a border dart.
///
/// That is `vertex_normal(d, mesh, np)` for the unflipped dart `d` of that
/// face that ends at `v`. On a mesh without Möbius edges (an orientable mesh
/// after `orient()`) it agrees with the normals of all faces around `v`. On a
/// one-sided surface the sign is only as meaningful as that face's
/// orientation; use `vertex_normal(d, ...)` to choose the side. The zero
/// vector for an isolated vertex.
/// \throws Parameter_error if `v` is not a vertex of `mesh`.
template <class P, class NP = parameters::Default_named_parameters>
typename internal::Normal_types<P, NP>::Vector vertex_normal(Vertex_index v, const Mobius_mesh<P>& mesh,
                                                             const NP& np = parameters::default_values())
{
  if (!mesh.is_valid(v))
    throw Parameter_error("vertex_normal: vertex " + std::to_string(v.idx()) + " is not a vertex of the mesh (" +
                          std::to_string(mesh.number_of_vertices()) + " vertices)");
  if (mesh.is_isolated(v))
    return typename internal::Normal_types<P, NP>::Vector(CGAL::NULL_VECTOR);
  return CGAL_ext::vertex_normal(internal::vertex_side_dart(v, mesh), mesh, np);
}

/// \ingroup PkgMobiusMeshNormals
/// \brief writes `face_normal(f, mesh, np)` for every face `f` into
/// `face_normals`: each face's normal in its own orientation.
///
/// \tparam FaceNormalMap a writable property map from `Face_index` to the traits' `Vector_3`
template <class P, class FaceNormalMap, class NP = parameters::Default_named_parameters>
void compute_face_normals(const Mobius_mesh<P>& mesh, FaceNormalMap face_normals,
                          const NP& np = parameters::default_values())
{
  const internal::Normal_settings<P, NP> s(mesh, np);
  for (Face_index f : mesh.faces()) {
    const auto n = internal::newell_vector(f, mesh, s);
    put(face_normals, f, s.normalize ? internal::unit_vector(n, s.traits) : n);
  }
}

/// \ingroup PkgMobiusMeshNormals
/// \brief writes `vertex_normal(v, mesh, np)` for every vertex `v` into
/// `vertex_normals`: each seen from the side of the orientation of one of its faces.
///
/// Computes each face normal once. On a mesh without Möbius edges the
/// normals agree with the faces; on a one-sided surface they cannot all
/// agree: use `compute_corner_normals()` for normals that agree with each face.
/// \tparam VertexNormalMap a writable property map from `Vertex_index` to the traits' `Vector_3`
template <class P, class VertexNormalMap, class NP = parameters::Default_named_parameters>
void compute_vertex_normals(const Mobius_mesh<P>& mesh, VertexNormalMap vertex_normals,
                            const NP& np = parameters::default_values())
{
  const internal::Normal_settings<P, NP> s(mesh, np);
  const auto faces = internal::weighted_face_vectors(mesh, s);
  const auto face_vector = [&](Face_index f) { return faces[f.idx()]; };
  for (Vertex_index v : mesh.vertices())
    put(vertex_normals, v,
        mesh.is_isolated(v) ? typename internal::Normal_types<P, NP>::Vector(CGAL::NULL_VECTOR)
                            : internal::fan_normal(internal::vertex_side_dart(v, mesh), mesh, s, face_vector));
}

/// \ingroup PkgMobiusMeshNormals
/// \brief writes, for every halfedge `h` of a face, the vertex normal at
/// `target(h)` seen from the side of `face(h)`'s orientation: `vertex_normal(Dart(h), mesh, np)`.
///
/// These are the per-corner normals a renderer wants on a one-sided surface:
/// each agrees in sign with its face's normal where the surface is smooth,
/// while one vertex may get opposite normals in faces on the two sides of a
/// Möbius edge. Each vertex's fan is summed once. The values of border
/// halfedges are not written.
/// \tparam HalfedgeNormalMap a writable property map from `Halfedge_index` to the traits' `Vector_3`
template <class P, class HalfedgeNormalMap, class NP = parameters::Default_named_parameters>
void compute_corner_normals(const Mobius_mesh<P>& mesh, HalfedgeNormalMap corner_normals,
                            const NP& np = parameters::default_values())
{
  const internal::Normal_settings<P, NP> s(mesh, np);
  const auto faces = internal::weighted_face_vectors(mesh, s);
  const auto face_vector = [&](Face_index f) { return faces[f.idx()]; };
  const auto negate = s.traits.construct_opposite_vector_3_object();
  for (Vertex_index v : mesh.vertices()) {
    if (mesh.is_isolated(v))
      continue;
    const auto normal = internal::fan_normal(mesh.halfedge(v), mesh, s, face_vector);
    // Every dart of the fan carries the orientation of the first. An
    // unflipped dart is its face's corner at v; a flipped one runs against
    // its face, whose corner at v is then the halfedge of the next dart,
    // seen from the other side.
    for (Dart c : CGAL_ext::halfedges_around_target(mesh.halfedge(v), mesh)) {
      if (mesh.is_border(c))
        continue;
      if (c.is_flipped())
        put(corner_normals, mesh.next(c).halfedge(), negate(normal));
      else
        put(corner_normals, c.halfedge(), normal);
    }
  }
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_NORMALS_H
