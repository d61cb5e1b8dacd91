// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The options of isotropic_remeshing() read from its named parameters, and
// the size of its result estimated and checked before the mesh is touched.

#ifndef CGAL_EXT_REMESHING_INTERNAL_REMESHING_SETUP_H
#define CGAL_EXT_REMESHING_INTERNAL_REMESHING_SETUP_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_checks.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Remeshing/internal/Isotropic_remesher.h>
#include <CGAL_ext/Remeshing/internal/Narrow_regions.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

template <class NP>
Remeshing_options remeshing_options(double target_edge_length, const NP& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if (!(std::isfinite(target_edge_length) && target_edge_length > 0)) {
    std::ostringstream what;
    what << "isotropic_remeshing: the target edge length " << target_edge_length
         << " is not a positive finite number";
    throw Parameter_error(what.str());
  }
  const auto iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 1u);
  const long long count = static_cast<long long>(iterations);
  if (count < 0 || count > 1000)
    throw Parameter_error("isotropic_remeshing: number_of_iterations " + std::to_string(count) +
                          " is not from 0 to 1000");
  Remeshing_options options;
  options.target_edge_length = target_edge_length;
  options.iterations = static_cast<unsigned>(count);
  // protect_constraints is CGAL's name; its default constraints are the border.
  const bool constraints = choose_parameter(get_parameter(np, CGAL::internal_np::protect_constraints), false);
  options.protect_borders =
    choose_parameter(get_parameter(np, CGAL_ext::internal_np::protect_borders), constraints);
  options.protect_sharp_edges =
    choose_parameter(get_parameter(np, CGAL_ext::internal_np::protect_sharp_edges), false);
  options.relax_constraints = choose_parameter(get_parameter(np, CGAL::internal_np::relax_constraints), false);
  options.stop_when_converged =
    choose_parameter(get_parameter(np, CGAL_ext::internal_np::stop_when_converged), true);
  options.allow_narrow_regions =
    choose_parameter(get_parameter(np, CGAL_ext::internal_np::allow_narrow_regions), true);
  return options;
}

// The triangles of a remeshing's input and the most its result may hold.
struct Remeshing_estimate
{
  double input_triangles = 0;
  double faces = 0;
};

// Whether the loop will leave edge e alone (Isotropic_remesher::is_protected(),
// read before the remesher exists): the seams of corner channels too.
template <class P>
auto remeshing_protection(const Mobius_mesh<P>& mesh, const Remeshing_options& options)
{
  const auto sharpness = mesh.template property_map<Edge_index, float>(edge_sharpness_name);
  auto seam = std::make_shared<const std::vector<char>>(
    mesh.corner_channels().empty() ? std::vector<char>() : corner_seam_edges(mesh));
  return [&mesh, options, sharpness, seam](Edge_index e) {
    return (options.protect_borders && mesh.is_border(e)) ||
           (options.protect_sharp_edges && sharpness && (*sharpness)[e] > 0) || (!seam->empty() && (*seam)[e.idx()]);
  };
}

// Estimated from the input before anything is touched, the most triangles
// are the larger of what the first split pass makes (it cuts each
// unprotected edge longer than 4/3 L into 2^k pieces of at most 4/3 L, each
// cut adding a triangle on each side of the edge: exact, but for the
// diagonals that triangulate polygons, bounded by half the perimeter, and
// for the edges that join the cuts to the far corners, which the same pass
// splits where the faces are wide, as the area term below counts, and flips
// across needles, which adds none) and what the later
// iterations tend to: the input's area in equilateral triangles of side
// L / 2, and two triangles per 4/5 L of border. The first pass leaves edges
// shorter than L that no collapse may remove without making one longer
// than 4/3 L: a unit square of two triangles remeshed to L = 0.04 holds 2.6
// times its area in triangles of side L after 3 iterations, a strip
// narrower than L two triangles per L of its length whatever its area.
template <class P>
Remeshing_estimate remeshing_face_estimate(const Mobius_mesh<P>& mesh, const Remeshing_options& options)
{
  const double L = options.target_edge_length, high = 4.0 / 3.0 * L, low = 0.8 * L;
  const auto is_protected = remeshing_protection(mesh, options);
  // How many triangles the first pass adds on each side of an edge of this length.
  const auto added_per_side = [high](double length) {
    return length > high ? std::exp2(std::ceil(std::log2(length / high))) - 1 : 0.0;
  };
  double input = 0, area = 0, border = 0, split = 0;
  std::vector<Point_d> corners;
  for (Face_index f : mesh.faces()) {
    corners.clear();
    for (Vertex_index v : CGAL_ext::vertices_around_face(f, mesh))
      corners.push_back(to_point_d(mesh.point(v)));
    const Point_d n = newell_d(corners).first;
    input += double(corners.size()) - 2;
    area += std::sqrt(dot_d(n, n)) / 2;
    if (corners.size() > 3) { // the diagonals triangulate_faces() adds, each at most half the perimeter
      double perimeter = 0;
      for (std::size_t i = 0; i < corners.size(); ++i) {
        const Point_d side = minus_d(corners[(i + 1) % corners.size()], corners[i]);
        perimeter += std::sqrt(dot_d(side, side));
      }
      split += (double(corners.size()) - 3) * 2 * added_per_side(perimeter / 2);
    }
  }
  split += input;
  for (Edge_index e : mesh.edges()) {
    const Point_d d = minus_d(to_point_d(mesh.point(mesh.vertex(e, 0))), to_point_d(mesh.point(mesh.vertex(e, 1))));
    const double length = std::sqrt(dot_d(d, d));
    if (mesh.is_border(e))
      border += length;
    if (!is_protected(e))
      split += added_per_side(length) * (mesh.is_border(e) ? 1 : 2);
  }
  const double later = area / (std::sqrt(3.0) / 4 * (L / 2) * (L / 2)) + 2 * border / low;
  return {input, (std::max)(split, later)};
}

// Refuses, with Size_error, a remeshing whose estimated result the mesh's
// indices cannot hold or whose estimated peak is above `maximum_memory`,
// and returns the estimated faces otherwise:
// 1.5 times the mesh's arrays at the estimated size (the mesh, its grown
// arrays and the queues) and ~200 bytes per input triangle (their copy and
// AABB tree). For the remeshing benchmark (125 000 triangles of a torus to
// their mean edge length: a peak of 45 MB, 100 000 triangles left) that is
// about 70 MB, from an estimate of about 450 000 triangles.
template <class P>
double check_remeshing_size(const Mobius_mesh<P>& mesh, const Remeshing_options& options, double maximum_memory)
{
  if (!(maximum_memory > 0))
    throw Parameter_error("isotropic_remeshing: maximum_memory " + std::to_string(maximum_memory) +
                          " is not a positive number");
  const auto [input_triangles, faces] = remeshing_face_estimate(mesh, options);
  auto count = [](double x) { return static_cast<unsigned long long>(x < 1.8e19 ? std::ceil(x) : 1.8e19); };
  const Mesh_size size{count(faces / 2 + 2), count(faces * 1.5 + 1), count(faces), 0};
  std::ostringstream what;
  what << "isotropic_remeshing to edge length " << options.target_edge_length;
  check_mesh_size(what.str(), size);
  check_memory(what.str(), 1.5 * mesh_bytes<P>(size) + 200 * input_triangles, maximum_memory);
  return faces;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_REMESHING_INTERNAL_REMESHING_SETUP_H
