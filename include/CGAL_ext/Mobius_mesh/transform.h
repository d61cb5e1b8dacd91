// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Copying a Mobius_mesh (also across point types), applying an affine
// transformation to its points and corner normals, and the property-map
// transfer that copying and merging share.

#ifndef CGAL_EXT_MOBIUS_MESH_TRANSFORM_H
#define CGAL_EXT_MOBIUS_MESH_TRANSFORM_H

#include <CGAL_ext/Mobius_mesh/internal/Mesh_copy.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
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

namespace internal {

// Whether a transformation shows its matrix, as CGAL::Aff_transformation_3
// does (`cartesian(i, j)`): only then can normals be transformed.
template <class T, class = void>
struct Has_cartesian_matrix : std::false_type
{};
template <class T>
struct Has_cartesian_matrix<T, std::void_t<decltype(std::declval<const T&>().cartesian(0, 0))>> : std::true_type
{};

// n -> sign(det A) A^-T n = cof(A) n / |det A|, A the linear part of t.
// The cofactor matrix is what cross products of transformed edges give, so
// a normal keeps agreeing with its face's cycle, which transform() keeps
// also where t mirrors the surface (there A^-T n alone would point the other
// way). No division but by |det A|: exact with an exact kernel.
template <class Vector_3>
class Normal_transformation
{
public:
  using FT = typename CGAL::Kernel_traits<Vector_3>::Kernel::FT;

  template <class Transformation>
  explicit Normal_transformation(const Transformation& t)
  {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        cofactor_[i][j] = t.cartesian((i + 1) % 3, (j + 1) % 3) * t.cartesian((i + 2) % 3, (j + 2) % 3) -
                          t.cartesian((i + 1) % 3, (j + 2) % 3) * t.cartesian((i + 2) % 3, (j + 1) % 3);
    det_ = t.cartesian(0, 0) * cofactor_[0][0] + t.cartesian(0, 1) * cofactor_[0][1] +
           t.cartesian(0, 2) * cofactor_[0][2];
    if (det_ < 0)
      det_ = -det_;
  }

  bool is_singular() const { return det_ == 0; }

  Vector_3 operator()(const Vector_3& n) const
  {
    const auto row = [&](int i) {
      return (cofactor_[i][0] * n.x() + cofactor_[i][1] * n.y() + cofactor_[i][2] * n.z()) / det_;
    };
    return Vector_3(row(0), row(1), row(2));
  }

private:
  FT cofactor_[3][3];
  FT det_;
};

// The channel "c:normal" transformed as the normals of the transformed
// surface: each value by Normal_transformation, then given back its length
// where the number type is not exact (a square root would make an exact one
// inexact). Refused (Parameter_error, before the mesh is touched) where the
// normals cannot follow: a transformation without a matrix, a singular one,
// or values of another type than the readers make.
template <class P, class Transformation>
std::optional<Normal_transformation<Corner_normal<P>>> checked_normal_transformation(const Mobius_mesh<P>& mesh,
                                                                                     const Transformation& t)
{
  const std::vector<std::string> names = mesh.corner_channels();
  if (std::find(names.begin(), names.end(), corner_normal_name) == names.end())
    return std::nullopt;
  const std::string why = std::string("transform: the mesh has the corner channel \"") + corner_normal_name + "\", ";
  if (!mesh.template corner_channel<Corner_normal<P>>(corner_normal_name))
    throw Parameter_error(why + "whose values are not the kernel's Vector_3, which transform() knows how to transform");
  if constexpr (!Has_cartesian_matrix<Transformation>::value) {
    throw Parameter_error(why + "whose normals need the transformation's matrix: pass a CGAL::Aff_transformation_3");
  } else {
    Normal_transformation<Corner_normal<P>> normal(t);
    if (normal.is_singular())
      throw Parameter_error(why + "whose normals a singular transformation (determinant 0) does not carry");
    return normal;
  }
}

template <class P>
void transform_corner_normals(Mobius_mesh<P>& mesh, const Normal_transformation<Corner_normal<P>>& normal)
{
  using FT = typename Normal_transformation<Corner_normal<P>>::FT;
  constexpr bool exact = std::is_same_v<typename CGAL::Algebraic_structure_traits<FT>::Is_exact, CGAL::Tag_true>;
  for (Corner_normal<P>& n : mesh.template corner_channel<Corner_normal<P>>(corner_normal_name)->values()) {
    const Corner_normal<P> m = normal(n);
    const FT before = n.squared_length(), after = m.squared_length();
    if (exact || after == 0 || before == after)
      n = m;
    else
      n = m * CGAL::approximate_sqrt(before / after);
  }
}

} // namespace internal

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
