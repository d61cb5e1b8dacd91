// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Copying a Mobius_mesh (also across point types), applying an affine
// transformation to its points and corner normals, and the property-map
// transfer that copying and merging share.

#ifndef CGAL_EXT_MOBIUS_MESH_TRANSFORM_H
#define CGAL_EXT_MOBIUS_MESH_TRANSFORM_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/internal/Mesh_copy.h>
#include <CGAL_ext/Mobius_mesh/internal/Normal_transformation.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Parallel_loops.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshOperations
///
/// Appends a copy of `src` to `dst` (a disjoint union if `dst` is not empty),
/// converting points with `CGAL::Cartesian_converter` when the point types
/// differ (exact when converting to an exact kernel). Connectivity, Möbius
/// bits and face orientations are copied as they are; the indices of the copy
/// are those of `src` shifted by the returned offsets (halfedges by twice the
/// edge offset).
///
/// Every property map of `src` is copied by name, whatever its value type
/// (as `Mobius_mesh::join()` does).
///
/// \param src the mesh to copy
/// \param dst the mesh the copy is appended to
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_to_vertex_output_iterator}
///     \cgalParamDescription{receives `std::pair<Vertex_index, Vertex_index>` (source, copy) per vertex}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_to_halfedge_output_iterator}
///     \cgalParamDescription{receives `std::pair<Halfedge_index, Halfedge_index>` per halfedge}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_to_face_output_iterator}
///     \cgalParamDescription{receives `std::pair<Face_index, Face_index>` per face}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the offsets of the copy's vertex, edge and face indices in `dst`.
template <class P1, class P2, class NamedParameters = parameters::Default_named_parameters>
typename Mobius_mesh<P2>::Join_offsets copy_mesh(const Mobius_mesh<P1>& src, Mobius_mesh<P2>& dst,
                                                 const NamedParameters& np = parameters::default_values())
{
  // Built apart and appended at the end: `dst` is untouched if anything throws.
  Mobius_mesh<P2> part;
  if constexpr (std::is_same_v<P1, P2>) {
    part = src;
  } else {
    internal::copy_connectivity(src, part);
    const internal::Point_converter<P1, P2> convert;
    for (Vertex_index v : src.vertices())
      part.point(v) = convert(src.point(v));
    auto same = [](auto i) { return i; };
    internal::transfer_properties<Vertex_index>(src, part, 0, src.num_vertices(), same);
    internal::transfer_properties<Halfedge_index>(src, part, 0, src.num_halfedges(), same);
    internal::transfer_properties<Edge_index>(src, part, 0, src.num_edges(), same);
    internal::transfer_properties<Face_index>(src, part, 0, src.num_faces(), same);
  }
  const auto off = internal::append_mesh(dst, std::move(part));
  internal::write_pairs(np, CGAL::internal_np::vertex_to_vertex_output_iterator, [&](auto out) {
    for (Vertex_index v : src.vertices())
      out(std::make_pair(v, Vertex_index(v.idx() + off.vertices)));
  });
  internal::write_pairs(np, CGAL::internal_np::halfedge_to_halfedge_output_iterator, [&](auto out) {
    for (Halfedge_index h : src.halfedges())
      out(std::make_pair(h, Halfedge_index(h.idx() + 2 * off.edges)));
  });
  internal::write_pairs(np, CGAL::internal_np::face_to_face_output_iterator, [&](auto out) {
    for (Face_index f : src.faces())
      out(std::make_pair(f, Face_index(f.idx() + off.faces)));
  });
  return off;
}

/// \ingroup PkgMobiusMeshOperations
///
/// Appends a disjoint copy of `src` to `dst` (any point types); the same as
/// `copy_mesh(src, dst, np)`, under the name the operation has in the source
/// design. Source first, as in `CGAL::copy_face_graph(source, target)`.
template <class P1, class P2, class NamedParameters = parameters::Default_named_parameters>
typename Mobius_mesh<P2>::Join_offsets disjoint_union(const Mobius_mesh<P1>& src, Mobius_mesh<P2>& dst,
                                                      const NamedParameters& np = parameters::default_values())
{
  return copy_mesh(src, dst, np);
}

/// \ingroup PkgMobiusMeshOperations
///
/// Applies `t` to every point of `mesh`; the connectivity is unchanged (an
/// orientation-reversing `t` mirrors the surface but keeps its face cycles).
/// With an exact kernel the new points are exact.
///
/// The corner channel of normals (`corner_normal_name`, `"c:normal"`, values
/// `Corner_normal<P>`) follows the surface: each normal *n* becomes
/// sign(det *A*) *A*⁻ᵀ *n*, *A* the linear part of `t` (the inverse transpose,
/// turned over where `t` mirrors, so that the normals still agree with the
/// face cycles that are kept), and is then given back its length (a unit
/// normal stays unit). With an exact kernel (`FT` exact) the inverse transpose
/// is exact and the length is left as it comes, since rescaling would take a
/// square root: under a rotation or a reflection it is unchanged, under other
/// maps normalise with `CGAL::approximate_sqrt()` if unit normals are needed.
/// Texture coordinates (`"c:uv"`) and other channels are left as they are.
///
/// \tparam Transformation `CGAL::Aff_transformation_3<K>` of the point's
///   kernel, or any type with `P transform(const P&) const` (then the mesh
///   must not have the channel `"c:normal"`).
/// \throws Parameter_error, before the mesh is touched, if the mesh has the
///   channel `"c:normal"` and `t` has no matrix (`cartesian(i, j)`), is
///   singular, or the channel's values are not the kernel's `Vector_3`.
template <class P, class Transformation>
void transform(Mobius_mesh<P>& mesh, const Transformation& t)
{
  const auto normal = internal::checked_normal_transformation(mesh, t);
  for (Vertex_index v : mesh.vertices())
    mesh.point(v) = t.transform(mesh.point(v));
  if (normal)
    internal::transform_corner_normals(mesh, *normal);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TRANSFORM_H
