// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Discrete curvatures of a Mobius_mesh, one-sided surfaces included: the
// Gaussian curvature as an angle defect (intrinsic, no orientation needed),
// the mean curvature vector by the cotangent formula (orientation-free), and
// the scalar mean curvature seen from the side of a dart, as normals are.

#ifndef CGAL_EXT_CURVATURE_DISCRETE_CURVATURES_H
#define CGAL_EXT_CURVATURE_DISCRETE_CURVATURES_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <string>

namespace CGAL_ext {
namespace internal {

inline std::array<double, 3> curvature_vector(double x, double y, double z) { return {x, y, z}; }

template <class P>
std::array<double, 3> curvature_point(const Mobius_mesh<P>& mesh, Vertex_index v)
{
  const P& p = mesh.point(v);
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline std::array<double, 3> curvature_minus(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline double curvature_dot(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double curvature_cross_norm(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  const double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
  return std::sqrt(x * x + y * y + z * z);
}

template <class P>
void require_curvature_vertex(const Mobius_mesh<P>& mesh, Vertex_index v, const char* what)
{
  if (!mesh.is_valid(v) || mesh.is_removed(v))
    throw Parameter_error(std::string(what) + ": vertex " + std::to_string(v.idx()) + " is not in the mesh");
}

} // namespace internal

/// \ingroup PkgMobiusMeshCurvature
/// \brief the discrete Gaussian curvature of `mesh` at `v`, integrated over
/// the vertex's share of the surface: its angle defect, 2π minus the sum of
/// the corner angles of the faces at `v` (π minus that sum on the border).
///
/// It is intrinsic — it needs no orientation and is the same on a one-sided
/// surface as on its orientation double cover — and the discrete Gauss–Bonnet
/// theorem holds exactly: the sum over all vertices is 2π times the Euler
/// characteristic (0 for a torus or a Klein bottle, 2π for a projective plane).
/// Faces may be any polygons; the angle at a corner is the angle between its
/// two sides, computed in `double`. An isolated vertex has 0.
/// \throws Parameter_error if `v` is not a vertex of `mesh`.
template <class P>
double angle_defect(Vertex_index v, const Mobius_mesh<P>& mesh)
{
  internal::require_curvature_vertex(mesh, v, "angle_defect");
  const Dart h = mesh.halfedge(v);
  if (!h.is_valid())
    return 0;
  const double pi = 3.14159265358979323846;
  double sum = 0;
  bool border = false;
  const auto pv = internal::curvature_point(mesh, v);
  for (Dart d : CGAL_ext::halfedges_around_target(h, mesh)) {
    if (mesh.is_border(d)) {
      border = true;
      continue;
    }
    const auto a = internal::curvature_minus(internal::curvature_point(mesh, mesh.source(d)), pv);
    const auto b = internal::curvature_minus(internal::curvature_point(mesh, mesh.target(mesh.next(d))), pv);
    sum += std::atan2(internal::curvature_cross_norm(a, b), internal::curvature_dot(a, b));
  }
  return (border ? pi : 2 * pi) - sum;
}

/// \ingroup PkgMobiusMeshCurvature
/// \brief writes `angle_defect(v, mesh)` of every vertex into `curvatures`, a
/// writable property map from `Vertex_index` to a floating-point type.
template <class P, class VertexCurvatureMap>
void compute_angle_defects(const Mobius_mesh<P>& mesh, VertexCurvatureMap curvatures)
{
  for (Vertex_index v : mesh.vertices())
    put(curvatures, v, angle_defect(v, mesh));
}

/// \ingroup PkgMobiusMeshCurvature
/// \brief the mean curvature vector of a triangle mesh at `v`: H n, the mean
/// curvature times a unit normal, which does not depend on the choice of the
/// normal and so needs no orientation.
///
/// The cotangent formula (Meyer, Desbrun, Schröder and Barr, 2003):
/// H n = 1 / (4 A) Σ (cot α + cot β) (p_v − p_j) over the edges from `v` to
/// its neighbours p_j, α and β the angles facing the edge, with A the
/// mixed area of `v` (the Voronoi area of its triangles, half or a quarter
/// of an obtuse one, as in that paper). On a
/// sphere it points out, H being 1 / radius for the outward normal. Computed
/// in `double`; only the vertex's own triangles count on the border. An
/// isolated vertex has the zero vector.
/// \throws Parameter_error if `v` is not a vertex of `mesh` or one of its
///   faces is not a triangle.
template <class P>
std::array<double, 3> mean_curvature_vector(Vertex_index v, const Mobius_mesh<P>& mesh)
{
  const char* what = "mean_curvature_vector";
  internal::require_curvature_vertex(mesh, v, what);
  std::array<double, 3> sum{0, 0, 0};
  const Dart h = mesh.halfedge(v);
  if (!h.is_valid())
    return sum;
  const auto pv = internal::curvature_point(mesh, v);
  double area = 0;
  for (Dart d : CGAL_ext::halfedges_around_target(h, mesh)) {
    if (mesh.is_border(d))
      continue;
    if (mesh.next(mesh.next(mesh.next(d))) != d)
      throw Parameter_error(std::string(what) + ": face " + std::to_string(mesh.face(d).idx()) +
                            " is not a triangle (PMP::triangulate_faces() makes triangles)");
    const auto pa = internal::curvature_point(mesh, mesh.source(d));
    const auto pb = internal::curvature_point(mesh, mesh.target(mesh.next(d)));
    // Angle at b faces the edge (v, a); angle at a faces the edge (v, b).
    const auto ba = internal::curvature_minus(pa, pb), bv = internal::curvature_minus(pv, pb);
    const auto ab = internal::curvature_minus(pb, pa), av = internal::curvature_minus(pv, pa);
    const double twice_area = internal::curvature_cross_norm(ba, bv);
    if (!(twice_area > 0))
      continue; // a degenerate triangle adds nothing
    const double cot_b = internal::curvature_dot(ba, bv) / twice_area;
    const double cot_a = internal::curvature_dot(ab, av) / twice_area;
    const auto ea = internal::curvature_minus(pv, pa), eb = internal::curvature_minus(pv, pb);
    for (int i = 0; i < 3; ++i)
      sum[i] += cot_b * ea[i] + cot_a * eb[i];
    // Meyer et al.'s mixed area: the Voronoi part of the triangle at v if no
    // angle is obtuse, else half (obtuse at v) or a quarter of the triangle.
    const auto va = internal::curvature_minus(pa, pv), vb = internal::curvature_minus(pb, pv);
    if (internal::curvature_dot(va, vb) < 0)
      area += twice_area / 4;
    else if (cot_a < 0 || cot_b < 0)
      area += twice_area / 8;
    else
      area += (internal::curvature_dot(ea, ea) * cot_b + internal::curvature_dot(eb, eb) * cot_a) / 8;
  }
  if (!(area > 0))
    return {0, 0, 0};
  for (double& x : sum)
    x /= 4 * area;
  return sum;
}

/// \ingroup PkgMobiusMeshCurvature
/// \brief the mean curvature of a triangle mesh at `target(d)`, seen from the
/// side of `d`: the mean curvature vector dotted with the unit vertex normal
/// of `d` (`vertex_normal(d, mesh)`, area weighted). A one-sided surface has
/// no mean curvature per vertex, only per side, as it has no normal per
/// vertex: `mean_curvature(d)` and the value for the other side (for
/// instance `next(d).flipped()` of a face dart) are opposite. On a sphere
/// whose faces face out it is 1 / radius.
/// \throws Parameter_error as `mean_curvature_vector()`.
template <class P>
double mean_curvature(Dart d, const Mobius_mesh<P>& mesh)
{
  const std::array<double, 3> hn = mean_curvature_vector(mesh.target(d), mesh);
  const auto n = vertex_normal(d, mesh);
  const std::array<double, 3> nd{CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())};
  const double len = std::sqrt(internal::curvature_dot(nd, nd));
  return len > 0 ? internal::curvature_dot(hn, nd) / len : 0.0;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_CURVATURE_DISCRETE_CURVATURES_H
