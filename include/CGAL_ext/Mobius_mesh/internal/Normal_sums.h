// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/Mobius_mesh/normals.h>: Newell vectors and the weighted sums of face normals around a vertex, per dart.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_NORMAL_SUMS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_NORMAL_SUMS_H

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
#include <CGAL_ext/Mobius_mesh/Vertex_normal_weighting.h>

namespace CGAL_ext {
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
  // Up to the last corner by darts, not by vertex: a face may visit a vertex
  // twice (non-manifold input held as a folded face).
  for (Dart d = mesh.next(first); mesh.next(d) != first; d = mesh.next(d)) {
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
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_NORMAL_SUMS_H
