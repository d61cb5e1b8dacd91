// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Offsets of one- and two-sided surfaces: the vertices moved along their
// normals to both sides. On a one-sided surface the two sides are one, and
// the offset is the orientation double cover, displaced.

#ifndef CGAL_EXT_OFFSET_MESH_H
#define CGAL_EXT_OFFSET_MESH_H

#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/internal/Coordinate_checks.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Offset/internal/Offset_corner_channels.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshOperations
/// What `offset_mesh()` made.
struct Offset_result
{
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t rim_faces = 0;       ///< faces joining the two sides along the input's border
  /// corners of the rim faces, which have no value in the input's corner
  /// channels (0 without channels): each channel leaves them without one
  std::size_t corners_without_values = 0;
  std::size_t components = 0;      ///< connected components of the output
  long long euler_characteristic = 0;
  bool closed = false, orientable = false;
};

/// \var Offset_result::vertices
/// The number of vertices of the output.

/// \var Offset_result::edges
/// The number of edges of the output.

/// \var Offset_result::faces
/// The number of faces of the output.

/// \var Offset_result::euler_characteristic
/// V − E + F of the output.

/// \var Offset_result::closed
/// True if the output has no border.

/// \var Offset_result::orientable
/// True if every component of the output is orientable.

namespace internal {

// Which side of each face each corner's lift takes: the input's sides are
// chosen per vertex (the side of the walk of a face dart into it, on which
// vertex_normal() of that dart lies), and a corner takes the vertex's side
// if its face's own orientation agrees with that walk, the other if not. Indexed by halfedge: the corner at
// target(h) of face(h).
template <class P>
std::vector<std::uint8_t> corner_agrees(const Mobius_mesh<P>& m, std::vector<Dart>& side_dart)
{
  std::vector<std::uint8_t> agrees(m.num_halfedges(), 0);
  side_dart.assign(m.num_vertices(), Dart());
  for (Vertex_index v : m.vertices()) {
    if (m.is_isolated(v))
      continue;
    const Dart r = vertex_side_dart(v, m); // the side vertex_normal(v) is seen from
    side_dart[v.idx()] = r;
    // Circulation carries the walk of r across every edge, Möbius or not (the
    // fan is a disk): a dart reached unflipped runs its face the way the
    // walk goes, so that face's own normal is on the walk's side.
    for (Dart c : CGAL_ext::halfedges_around_target(r, m)) {
      if (m.is_border(c))
        continue;
      const Dart along = c.is_flipped() ? m.next(c).flipped() : c; // the face's own dart into v
      agrees[along.halfedge().idx()] = !c.is_flipped();
    }
  }
  return agrees;
}

// Unit normal times `distance`, in the kernel's number type. The square root
// is the only rounded step: on an exact kernel the rest is exact.
template <class Vector>
Vector scaled_unit(const Vector& n, double distance)
{
  const double length = std::sqrt(CGAL::to_double(n.squared_length()));
  if (!(length > 0))
    return n; // the zero vector: a vertex whose faces cancel out stays put
  return n * (typename CGAL::Kernel_traits<Vector>::Kernel::FT(distance) /
              typename CGAL::Kernel_traits<Vector>::Kernel::FT(length));
}

// Builds `out` from the polygons, with only the points they use, and the
// corner channels of `input` carried as `corners` says (see
// Offset_corner_sources); returns the corners left without values.
template <class P>
std::size_t build_from_used_points(const std::vector<P>& points, std::vector<std::vector<std::size_t>>& polygons,
                                   const Mobius_mesh<P>& input, const Offset_corner_sources& corners,
                                   Mobius_mesh<P>& out)
{
  constexpr std::size_t unused = std::size_t(-1);
  std::vector<std::size_t> renumbered(points.size(), unused);
  std::vector<P> used;
  for (auto& polygon : polygons)
    for (std::size_t& i : polygon) {
      if (renumbered[i] == unused) {
        renumbered[i] = used.size();
        used.push_back(points[i]);
      }
      i = renumbered[i];
    }
  std::size_t without = 0;
  soup_to_mobius_mesh(used, polygons, out, parameters::default_values(),
                      [&](Mobius_mesh<P>& built) { without = corners.carry(input, built); });
  return without;
}

// The offset of vertex v to the side of the walk of its side dart `r`: the
// unit vertex normal times `distance`, or the caller's displacement times
// `distance`, turned to that side (its sign against the vertex normal, an
// exact test; a displacement tangent to the surface has no side).
template <class P, class NP, class Vector>
Vector vertex_offset(Vertex_index v, Dart r, const Mobius_mesh<P>& m, double distance, const NP& np,
                     Vertex_normal_weighting weighting)
{
  const Vector n = CGAL_ext::vertex_normal(r, m, parameters::vertex_normal_weighting(weighting));
  const auto given = parameters::get_parameter(np, internal_np::vertex_displacement);
  if constexpr (parameters::is_default_parameter<NP, internal_np::vertex_displacement_t>::value) {
    return scaled_unit(n, distance);
  } else {
    using FT = typename CGAL::Kernel_traits<Vector>::Kernel::FT;
    const Vector delta = Vector(get(given, v)) * FT(distance);
    const CGAL::Sign side = CGAL::sign(delta * n);
    if (side == CGAL::ZERO)
      throw Parameter_error("offset_mesh: the displacement of vertex v" + std::to_string(v.idx()) +
                            " has no side: it is zero or tangent to the surface");
    return side == CGAL::POSITIVE ? delta : -delta;
  }
}

} // namespace internal

/// \ingroup PkgMobiusMeshOperations
///
/// Offsets `mesh` by `distance` to both sides and writes the result into `out`
/// (replacing its content): every vertex moves along its unit vertex normal
/// by `+distance` and by `-distance`.
///
/// - On a **one-sided** (non-orientable) component the two offsets are one
///   surface: the orientation double cover of the component, displaced, and,
///   if the component has a border, closed along it by rim quads. A Möbius
///   strip gives one closed orientable surface of genus 1 (the skin of the
///   thickened strip), a Klein bottle a torus, a projective plane a sphere.
/// - On an **orientable** component, with `solid(true)` both shells, joined
///   along the border by rim quads (a closed surface bounding the thickened
///   component); otherwise the one shell on the side its faces' normals point
///   to (after `orient()`), with no rim.
///
/// The output is oriented outward: the copy of a face on the side its normal
/// points to keeps its orientation, the copy on the other side is reversed,
/// and the rims follow; so a closed output bounds a positive volume. Corner
/// channels are carried: each corner of a copy of a face keeps the value of
/// the corner it copies (corner normals, `corner_normal_name`, turned on the
/// copy on the face's back side, as they are seen from its front); the rim
/// faces' corners have none (`Offset_result::corners_without_values`).
/// Normals are those of
/// `vertex_normal()` with the weighting given (area by default), each taken on
/// the side of a face dart into its vertex; the corners of the double cover
/// follow that side across Möbius edges. The offset points are those
/// positions exactly, up to the rounding of the one square root that makes a
/// normal a unit vector.
///
/// \param mesh the mesh to offset; it must have no removed elements
/// \param distance the offset distance, positive and finite; at most 1e60
///   without `vertex_displacement_map`
/// \param out receives the offset surface (its content is replaced)
/// \param np optional named parameters: `solid` (bool, default `false`),
///   `vertex_normal_weighting` (default `Vertex_normal_weighting::area`),
///   `vertex_displacement_map` (a readable vertex map of vectors δ: each
///   vertex then moves to `p ± distance · δ(v)` instead of along its unit
///   normal; δ's sign does not matter, its side is read against the vertex
///   normal. No square root is taken, so on an exact kernel the offset is
///   exact, e.g. with δ the area-weighted normals of `compute_vertex_normals()`).
/// \throws Parameter_error if `distance` is not positive and finite (and,
///   without `vertex_displacement_map`, at most 1e60), the
///   mesh has removed elements or a corner channel `corner_normal_name` of a
///   type it cannot turn (other than the kernel's `Vector_3` and `std::array`
///   of 3 doubles or floats), a point is not finite, a displacement is zero
///   or tangent to the surface, or (without `vertex_displacement_map`) a point
///   has a coordinate beyond +-1e60 or the mesh is less than 1e-60 across,
///   where unit normals in double overflow or underflow; `out` is then unchanged.
template <class P, class NP = parameters::Default_named_parameters>
Offset_result offset_mesh(const Mobius_mesh<P>& mesh, double distance, Mobius_mesh<P>& out,
                          const NP& np = parameters::default_values())
{
  // Unit normals are made with a square root in double: the points and the
  // distance stay within the range where that neither overflows nor
  // underflows. Displacements given by the caller are used as they are,
  // exactly on an exact kernel.
  constexpr bool unit_normals = parameters::is_default_parameter<NP, internal_np::vertex_displacement_t>::value;
  const double largest_distance = unit_normals ? CGAL_ext::internal::max_abs_coordinate : HUGE_VAL;
  if (!(distance > 0 && distance < HUGE_VAL && distance <= largest_distance)) {
    std::ostringstream what;
    what << "offset_mesh: the distance must be positive and "
         << (unit_normals ? "at most 1e60 (as the coordinates)" : "finite") << ", not " << distance;
    throw Parameter_error(what.str());
  }
  CGAL_ext::internal::require_no_garbage(mesh, "offset_mesh");
  CGAL_ext::internal::refuse_non_manifold_joins(mesh, "offset_mesh");
  internal::Offset_corner_sources::require_turnable_normals(mesh);
  if constexpr (unit_normals)
    CGAL_ext::internal::require_coordinates_in_range(mesh, "offset_mesh");
  else
    CGAL_ext::internal::require_finite_points(mesh, "offset_mesh");
  const bool solid = parameters::choose_parameter(parameters::get_parameter(np, internal_np::solid), false);
  const auto weighting = parameters::choose_parameter(
    parameters::get_parameter(np, internal_np::vertex_normal_weighting), Vertex_normal_weighting::area);

  // Orientable components get consistent orientations, so that one shell is one side.
  Mobius_mesh<P> m = mesh;
  // Where the corners of the input carry values (and only there), the
  // offset's corners are traced back to them.
  const bool carries_channels = !m.corner_channels().empty();
  const internal::Reversed_faces<P> before(m, carries_channels);
  CGAL_ext::orient(m);
  std::vector<std::uint32_t> face_component;
  std::vector<bool> orientable;
  {
    std::vector<std::uint8_t> flip;
    internal::orientation_parities(m, flip, face_component, orientable);
  }

  std::vector<Dart> side_dart;
  const std::vector<std::uint8_t> agrees = internal::corner_agrees(m, side_dart);
  // Lift 2v is v on the side of its side dart, 2v + 1 on the other side.
  std::vector<P> lifts(2 * std::size_t(m.num_vertices()));
  for (Vertex_index v : m.vertices()) {
    const P& p = m.point(v);
    if (!side_dart[v.idx()].is_valid()) {
      lifts[2 * v.idx()] = lifts[2 * v.idx() + 1] = p;
      continue;
    }
    using Vector = typename CGAL::Kernel_traits<P>::Kernel::Vector_3;
    const Vector offset = internal::vertex_offset<P, NP, Vector>(v, side_dart[v.idx()], m, distance, np, weighting);
    lifts[2 * v.idx()] = p + offset;
    lifts[2 * v.idx() + 1] = p - offset;
  }

  // Each face twice (once reversed), or once on an orientable component
  // without `solid`; a rim quad along each border edge where both sides are kept.
  std::vector<std::vector<std::size_t>> polygons;
  internal::Offset_corner_sources corners(carries_channels);
  auto lift = [&](Halfedge_index corner, bool upper) {
    const Vertex_index v = m.target(Dart(corner, false));
    return 2 * std::size_t(v.idx()) + ((agrees[corner.idx()] != 0) == upper ? 0 : 1);
  };
  auto both_sides = [&](Face_index f) { return solid || !orientable[face_component[f.idx()]]; };
  for (Face_index f : m.faces()) {
    std::vector<std::size_t> upper, lower;
    std::vector<std::uint32_t> slots;
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      upper.push_back(lift(d.halfedge(), true));
      lower.push_back(lift(d.halfedge(), false));
      if (carries_channels)
        slots.push_back(d.halfedge().idx());
    }
    const bool reversed = before.reversed(m, f);
    polygons.push_back(upper);
    corners.add_polygon(slots, reversed);
    if (both_sides(f)) {
      std::reverse(lower.begin(), lower.end());
      polygons.push_back(lower);
      std::reverse(slots.begin(), slots.end());
      corners.add_polygon(slots, !reversed);
    }
  }
  std::size_t rim_faces = 0;
  for (Halfedge_index b : m.halfedges()) {
    if (!m.is_border(b))
      continue;
    const Dart inner = m.opposite(Dart(b, false)); // the face's dart along this border edge
    const Face_index f = m.face(inner);
    if (!both_sides(f))
      continue;
    const Dart in_face = inner.is_flipped() ? inner.flipped() : inner;
    const Halfedge_index at_target = in_face.halfedge(), at_source = m.prev(in_face).halfedge();
    // The upper copy runs source -> target along the edge: the rim runs back.
    polygons.push_back({lift(at_target, true), lift(at_source, true), lift(at_source, false),
                        lift(at_target, false)});
    corners.add_rim(4);
    ++rim_faces;
  }

  Mobius_mesh<P> result;
  const std::size_t without_values = internal::build_from_used_points(lifts, polygons, m, corners, result);

  Offset_result r;
  r.vertices = result.number_of_vertices();
  r.edges = result.number_of_edges();
  r.faces = result.number_of_faces();
  r.rim_faces = rim_faces;
  r.corners_without_values = without_values;
  r.components = CGAL_ext::connected_components(result).count;
  r.euler_characteristic = CGAL_ext::euler_characteristic(result);
  r.closed = CGAL_ext::is_closed(result);
  r.orientable = CGAL_ext::is_orientable(result);
  out = std::move(result);
  return r;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_OFFSET_MESH_H
