// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Principal curvatures and directions of a Mobius_mesh at a vertex, seen
// from the side of a dart, by CGAL's jet fitting: the fit reads points only,
// so it needs no orientation; the side only decides the normal, hence the
// signs of the curvatures and which direction is the larger one.

#ifndef CGAL_EXT_CURVATURE_PRINCIPAL_CURVATURES_H
#define CGAL_EXT_CURVATURE_PRINCIPAL_CURVATURES_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#ifndef CGAL_EIGEN3_ENABLED
#error "CGAL_ext/Curvature/principal_curvatures.h needs Eigen: define CGAL_EIGEN3_ENABLED (CGAL::Eigen3_support)"
#endif

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshCurvature
/// The principal curvatures and directions at a vertex, seen from one side
/// (see `principal_curvatures()`).
struct Principal_curvatures
{
  double max_curvature = 0;                  ///< k1, the larger principal curvature
  double min_curvature = 0;                  ///< k2 <= k1
  std::array<double, 3> max_direction{};     ///< unit tangent along which the curvature is k1
  std::array<double, 3> min_direction{};     ///< unit tangent along which the curvature is k2
  std::array<double, 3> normal{};            ///< the unit normal of the side they are seen from
};

namespace internal {

// The vertices within `rings` edges of v, v first, each once. A few dozen:
// looked up in the list itself, so that a call costs the rings, not the mesh.
template <class P>
std::vector<Vertex_index> vertex_rings(const Mobius_mesh<P>& mesh, Vertex_index v, unsigned rings)
{
  std::vector<Vertex_index> found{v};
  std::size_t begin = 0;
  for (unsigned ring = 0; ring < rings; ++ring) {
    const std::size_t end = found.size();
    for (std::size_t i = begin; i < end; ++i)
      for (Dart d : CGAL_ext::halfedges_around_target(found[i], mesh))
        if (std::find(found.begin(), found.end(), mesh.source(d)) == found.end())
          found.push_back(mesh.source(d));
    begin = end;
  }
  return found;
}

} // namespace internal

/// \ingroup PkgMobiusMeshCurvature
/// \brief the principal curvatures and directions of the surface at
/// `target(d)`, seen from the side of `d`.
///
/// CGAL's `Monge_via_jet_fitting` (Cazals and Pouget's osculating jet) fits
/// a jet of degree 3 (2 where the rings hold fewer than 10 points) to the
/// points of the vertices within `rings` edges of the vertex (itself
/// included) and reads its Monge form of degree 2; the fit needs no
/// orientation. The Monge form is then turned to the side of `d`
/// (`comply_wrt_given_normal()` with `vertex_normal(d, mesh)`), and the
/// curvatures are given with the sign convention of `mean_curvature()`:
/// positive where the surface bends away from the normal, so that on a
/// sphere whose faces face out both are 1 / radius and
/// (k1 + k2) / 2 approximates `mean_curvature(d, mesh)`. From the other
/// side of a one-sided surface (or of any surface) k1 and k2 become −k2 and
/// −k1, the directions trade places and the normal turns over: a one-sided
/// surface has principal curvatures per side, as it has normals per side;
/// the product k1 k2 (Gaussian) and the directions as lines are the same
/// from either side. Faces of any degree; computed in `double`.
///
/// Needs Eigen (`CGAL_EIGEN3_ENABLED`, as CGAL's jet fitting).
/// \throws Parameter_error if `d` is not a dart of `mesh`, `rings` is 0, the
/// rings hold fewer than 6 points (a jet of degree 2 has 6 coefficients), or
/// the vertex has no normal from that side.
template <class P>
Principal_curvatures principal_curvatures(Dart d, const Mobius_mesh<P>& mesh, unsigned rings = 2)
{
  using K = CGAL::Simple_cartesian<double>;
  const std::string what = "principal_curvatures";
  internal::check_dart("principal_curvatures", d, mesh);
  const Vertex_index v = mesh.target(d);
  if (rings == 0)
    throw Parameter_error(what + ": rings must be at least 1");
  std::vector<K::Point_3> points;
  for (Vertex_index w : internal::vertex_rings(mesh, v, rings)) {
    const P& p = mesh.point(w);
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  if (points.size() < 6)
    throw Parameter_error(what + ": vertex " + std::to_string(v.idx()) + " has " + std::to_string(points.size()) +
                          " points within " + std::to_string(rings) + " rings; a jet of degree 2 needs 6");
  const auto n = vertex_normal(d, mesh);
  const K::Vector_3 side(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
  if (!(side.squared_length() > 0))
    throw Parameter_error(what + ": vertex " + std::to_string(v.idx()) + " has no normal from that side");
  using Fitting = CGAL::Monge_via_jet_fitting<K>;
  // A cubic jet where the points allow it (10 coefficients): its curvatures
  // converge as h² on a regular mesh, the quadric's only as h (a torus of
  // 128 × 64 triangulated quads, two rings: 0.017 against 0.068 of 1 / r).
  const std::size_t degree = points.size() >= 10 ? 3 : 2;
  typename Fitting::Monge_form monge = Fitting()(points.begin(), points.end(), degree, 2);
  monge.comply_wrt_given_normal(side);
  // CGAL's Monge form z = (k1 x² + k2 y²) / 2 along the normal: a sphere
  // seen from outside bends away from it, negative there; the library's
  // convention (mean_curvature()) is the opposite.
  const auto unit = [](const K::Vector_3& x) {
    const double length = std::sqrt(x.squared_length());
    return std::array<double, 3>{x.x() / length, x.y() / length, x.z() / length};
  };
  Principal_curvatures c;
  c.max_curvature = -monge.principal_curvatures(1);
  c.min_curvature = -monge.principal_curvatures(0);
  c.max_direction = unit(monge.minimal_principal_direction());
  c.min_direction = unit(monge.maximal_principal_direction());
  c.normal = unit(monge.normal_direction());
  return c;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_CURVATURE_PRINCIPAL_CURVATURES_H
