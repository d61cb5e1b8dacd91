// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Face and vertex normals on a Mobius_mesh. A one-sided surface has no
// global normal field, so every normal here is seen from the side of a dart:
// the unflipped darts of a face see its normal, the flipped darts its negation.

#ifndef CGAL_EXT_MOBIUS_MESH_NORMALS_H
#define CGAL_EXT_MOBIUS_MESH_NORMALS_H

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
/// How `vertex_normal()` weighs the normals of the faces around a vertex.
enum class Vertex_normal_weighting {
  /// Unit face normals, summed: every face counts the same. Needs a square
  /// root per face, so it is not exact on exact kernels.
  uniform,
  /// Newell vectors as they are (twice the vector area of each face): larger
  /// faces count more. No square root: exact on exact kernels.
  area,
  /// The angle of each face at the vertex times its unit normal (Thürmer and
  /// Wüthrich): independent of how the faces around the vertex are split.
  /// The angle is computed in `double` (`atan2`), so it is not exact.
  angle
};

namespace internal {

// The point map, traits and vector type that a call with named parameters `NP` uses.
template <class P, class NP>
struct Normal_types
{
  using Default_point_map = typename Mobius_mesh<P>::template Property_map<Vertex_index, P>;
  using Point_map =
    typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::vertex_point_t, NP, Default_point_map>::type;
  using Point = typename boost::property_traits<Point_map>::value_type;
  using Traits = typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NP,
                                                                    typename CGAL::Kernel_traits<Point>::Kernel>::type;
  using Vector = typename Traits::Vector_3;
};

// What every normal function reads from its named parameters.
template <class P, class NP>
struct Normal_settings
{
  using Types = Normal_types<P, NP>;
  typename Types::Point_map points;
  typename Types::Traits traits;
  bool normalize;
  Vertex_normal_weighting weighting;

  Normal_settings(const Mobius_mesh<P>& mesh, const NP& np)
    : points(parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                          mesh.points())),
      traits(parameters::choose_parameter<typename Types::Traits>(
        parameters::get_parameter(np, CGAL::internal_np::geom_traits))),
      normalize(parameters::choose_parameter(parameters::get_parameter(np, CGAL_ext::internal_np::normalize), false)),
      weighting(parameters::choose_parameter(
        parameters::get_parameter(np, CGAL_ext::internal_np::vertex_normal_weighting), Vertex_normal_weighting::area))
  {}
};

// `v` divided by its largest coordinate (unchanged if zero): a vector of
// length 1 to 2 in the same direction, whose square in double neither
// underflows nor overflows.
template <class Traits>
typename Traits::Vector_3 scaled_to_unit_box(const typename Traits::Vector_3& v, const Traits& traits)
{
  const auto largest = (std::max)({CGAL::abs(v.x()), CGAL::abs(v.y()), CGAL::abs(v.z())});
  return largest == 0 ? v : traits.construct_divided_vector_3_object()(v, largest);
}

template <class Traits>
typename Traits::Vector_3 unit_vector(const typename Traits::Vector_3& v, const Traits& traits)
{
  const auto divide = traits.construct_divided_vector_3_object();
  const auto squared_length = traits.compute_squared_length_3_object();
  const auto squared = squared_length(v);
  if (std::isnormal(CGAL::to_double(squared)))
    return divide(v, CGAL::approximate_sqrt(squared));
  // The square underflowed or overflowed (a face of side 1e-160 has a normal
  // of length 1e-320, whose square is 0 in double).
  const auto w = scaled_to_unit_box(v, traits);
  const auto w_squared = squared_length(w);
  if (w_squared == 0)
    return v; // a degenerate face has no direction: its zero vector stays zero
  return divide(w, CGAL::approximate_sqrt(w_squared));
}

// Newell's vector of face `f` in its own orientation: the sum over its edges
// of (p_i - p_0) x (p_{i+1} - p_0). Translating every point by p_0 does not
// change Newell's sum over a closed polygon (the translation terms cancel) and
// keeps the products small where the face is far from the origin.
template <class P, class Settings>
auto newell_vector(Face_index f, const Mobius_mesh<P>& mesh, const Settings& s)
{
  const auto vector = s.traits.construct_vector_3_object();
  const auto cross = s.traits.construct_cross_product_vector_3_object();
  const auto sum = s.traits.construct_sum_of_vectors_3_object();
  const Dart first = mesh.halfedge(f);
  const auto p0 = get(s.points, mesh.source(first));
  auto normal = vector(CGAL::NULL_VECTOR);
  auto previous = vector(p0, get(s.points, mesh.target(first)));
  for (Dart d = mesh.next(first); mesh.target(d) != mesh.source(first); d = mesh.next(d)) {
    const auto current = vector(p0, get(s.points, mesh.target(d)));
    normal = sum(normal, cross(previous, current));
    previous = current;
  }
  return normal;
}

inline std::string describe(Dart d)
{
  std::ostringstream out;
  out << d;
  return out.str();
}

template <class P>
void check_face(const char* function, Face_index f, const Mobius_mesh<P>& mesh)
{
  if (!mesh.is_valid(f))
    throw Parameter_error(std::string(function) + ": face " + std::to_string(f.idx()) + " is not a face of the mesh (" +
                          std::to_string(mesh.number_of_faces()) + " faces)");
}

template <class P>
void check_dart(const char* function, Dart d, const Mobius_mesh<P>& mesh)
{
  if (!mesh.is_valid(d))
    throw Parameter_error(std::string(function) + ": dart " + describe(d) + " is not a dart of the mesh (" +
                          std::to_string(mesh.number_of_halfedges()) + " halfedges)");
}

// The angle at target(d) between the two sides of face(d) that meet there.
template <class P, class Settings>
double corner_angle(Dart d, const Mobius_mesh<P>& mesh, const Settings& s)
{
  const auto vector = s.traits.construct_vector_3_object();
  const auto apex = get(s.points, mesh.target(d));
  auto a = vector(apex, get(s.points, mesh.source(d)));
  auto b = vector(apex, get(s.points, mesh.target(mesh.next(d))));
  // Where the products of the sides' squares would underflow or overflow in
  // double, each side is first divided by its largest coordinate: the angle
  // stays the same.
  const auto squared_length = s.traits.compute_squared_length_3_object();
  if (!std::isnormal(CGAL::to_double(squared_length(a)) * CGAL::to_double(squared_length(b)))) {
    a = scaled_to_unit_box(a, s.traits);
    b = scaled_to_unit_box(b, s.traits);
  }
  const auto cross = s.traits.construct_cross_product_vector_3_object()(a, b);
  const auto sine_part = squared_length(cross);
  const auto cosine_part = s.traits.compute_scalar_product_3_object()(a, b);
  // atan2 keeps its precision at angles near 0 and pi, where acos does not.
  return std::atan2(std::sqrt(CGAL::to_double(sine_part)), CGAL::to_double(cosine_part));
}

// The weighted sum of the face normals around target(d), each seen from the
// side that circulating from `d` carries. `face_vector(f)` is the normal of
// face f in its own orientation, already weighted per face (unit for uniform
// and angle weighting, Newell's vector for area weighting).
template <class P, class Settings, class FaceVector>
auto fan_normal(Dart d, const Mobius_mesh<P>& mesh, const Settings& s, const FaceVector& face_vector)
{
  const auto sum = s.traits.construct_sum_of_vectors_3_object();
  const auto scale = s.traits.construct_scaled_vector_3_object();
  const auto negate = s.traits.construct_opposite_vector_3_object();
  using FT = typename Settings::Types::Traits::FT;
  auto normal = s.traits.construct_vector_3_object()(CGAL::NULL_VECTOR);
  // The fan of a manifold vertex is a disk (or a half-disk at the border), so
  // the orientation that the darts carry around it is one orientation, even
  // where the walk crosses a Möbius edge: a dart that runs against its face
  // sees that face's normal negated.
  for (Dart c : CGAL_ext::halfedges_around_target(d, mesh)) {
    if (mesh.is_border(c))
      continue;
    auto n = face_vector(mesh.face(c));
    if (c.is_flipped())
      n = negate(n);
    if (s.weighting == Vertex_normal_weighting::angle)
      n = scale(n, FT(corner_angle(c, mesh, s)));
    normal = sum(normal, n);
  }
  return s.normalize ? unit_vector(normal, s.traits) : normal;
}

// The dart that vertex_normal(v) is seen from: the unflipped dart ending at
// v of the face of halfedge(v), or of the first face around v from it when
// halfedge(v) is a border dart. Unflipped, so that the normal follows the
// face's own orientation: on a mesh without Möbius edges, as after orient(),
// vertex and face normals then agree. (The stored dart itself may be flipped:
// reversing a face flips the darts stored on it.)
template <class P>
Dart vertex_side_dart(Vertex_index v, const Mobius_mesh<P>& mesh)
{
  for (Dart c : CGAL_ext::halfedges_around_target(mesh.halfedge(v), mesh))
    if (!mesh.is_border(c))
      return c.is_flipped() ? mesh.next(c).flipped() : c;
  return mesh.halfedge(v); // a vertex of no face: none to follow
}

// What face f adds to a vertex normal before the angle, if any: its unit
// normal, or Newell's vector as it is for area weighting.
template <class P, class Settings>
auto weighted_face_vector(Face_index f, const Mobius_mesh<P>& mesh, const Settings& s)
{
  const auto n = newell_vector(f, mesh, s);
  return s.weighting == Vertex_normal_weighting::area ? n : unit_vector(n, s.traits);
}

// The same for every face at once, for the functions that fill property maps.
template <class P, class Settings>
auto weighted_face_vectors(const Mobius_mesh<P>& mesh, const Settings& s)
{
  std::vector<typename Settings::Types::Vector> vectors;
  vectors.reserve(mesh.number_of_faces());
  for (Face_index f : mesh.faces())
    vectors.push_back(weighted_face_vector(f, mesh, s));
  return vectors;
}

} // namespace internal

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
