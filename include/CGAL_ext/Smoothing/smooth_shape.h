// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shape smoothing (mean curvature flow) on a Mobius_mesh, one-sided surfaces
// included: CGAL's implicit flow, with the rescaling that keeps a closed
// surface from shrinking done by area where no volume exists.

#ifndef CGAL_EXT_SMOOTHING_SMOOTH_SHAPE_H
#define CGAL_EXT_SMOOTHING_SMOOTH_SHAPE_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshSmoothing
/// \brief smooths the shape of the faces `faces` of `mesh` by the implicit
/// mean curvature flow of CGAL's `Polygon_mesh_processing::smooth_shape()`,
/// on any triangle mesh, one-sided ones included.
///
/// On a mesh without Möbius edges this is CGAL's `smooth_shape()`, which
/// rescales a closed mesh after each step so that its enclosed volume is
/// kept (about the only constrained vertex, or the volume's centroid).
/// The flow itself (cotangent stiffness and mass matrices) does not depend
/// on an orientation, and runs on a one-sided mesh through the graph traits.
/// But a one-sided closed surface bounds no volume (CGAL's signed volume of
/// it is a sum whose signs follow arbitrary face orientations), so on a mesh
/// with Möbius edges the step that CGAL would rescale by volume — a closed
/// mesh with at most one constrained vertex — is rescaled by **area**
/// instead: by the square root of the area before the step over the area
/// after it, about the constrained vertex if there is one, else about the
/// area-weighted centroid of the faces, each taken before and after the step
/// as CGAL takes its anchors. Both are orientation-free. Otherwise (a border,
/// or two constrained vertices or more) nothing is rescaled, as in CGAL.
///
/// \param faces the faces to smooth
/// \param mesh a triangle mesh
/// \param time the time step (as in CGAL)
/// \param np CGAL's named parameters of `smooth_shape()`: `number_of_iterations`,
///   `vertex_is_constrained_map`, `vertex_point_map`, `geom_traits`,
///   `sparse_linear_solver`.
/// \throws Parameter_error if `mesh` is not a triangle mesh.
template <class P, class FaceRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
void smooth_shape(const FaceRange& faces, Mobius_mesh<P>& mesh, const double time,
                  const NamedParameters& np = CGAL::parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Mesh = Mobius_mesh<P>;
  if (!CGAL::is_triangle_mesh(mesh))
    throw Parameter_error("smooth_shape: the mesh must be a triangle mesh (PMP::triangulate_faces() makes one)");
  if (!has_mobius_edges(mesh)) {
    PMP::smooth_shape(faces, mesh, time, np);
    return;
  }
  if (std::begin(faces) == std::end(faces))
    return;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using GeomTraits = typename CGAL::GetGeomTraits<Mesh, NamedParameters>::type;
  using VertexPointMap = typename CGAL::GetVertexPointMap<Mesh, NamedParameters>::type;
  using VCMap = typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::vertex_is_constrained_t,
                                                                    NamedParameters,
                                                                    CGAL::Static_boolean_property_map<Vertex_index, false>>::type;
  GeomTraits gt = choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
  VertexPointMap vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                        get_property_map(CGAL::vertex_point, mesh));
  VCMap vcm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                               CGAL::Static_boolean_property_map<Vertex_index, false>());
  const unsigned int iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 1);

  using Sparse_matrix = Eigen::SparseMatrix<double>;
  using Default_solver = CGAL::Eigen_solver_traits<Eigen::BiCGSTAB<Sparse_matrix, Eigen::IncompleteLUT<double>>>;
  using Solver = typename CGAL::GetSolver<NamedParameters, Default_solver>::type;
  using Matrix = typename Solver::Matrix;
  using Vector = typename Solver::Vector;
  Solver solver = choose_parameter<Default_solver>(get_parameter(np, CGAL::internal_np::sparse_linear_solver));

  // The anchor of the area rescaling, and whether there is one (CGAL's rule:
  // a closed mesh with at most one constrained vertex).
  std::size_t constrained = 0;
  Vertex_index anchor_vertex;
  for (Vertex_index v : mesh.vertices())
    if (get(vcm, v)) {
      ++constrained;
      anchor_vertex = v;
    }
  const bool rescale = constrained <= 1 && CGAL::is_closed(mesh);

  using FT = typename GeomTraits::FT;
  using Point = typename GeomTraits::Point_3;
  using Vector_3 = typename GeomTraits::Vector_3;
  // Area and area-weighted centroid of the faces, orientation-free.
  auto area_and_centroid = [&](Point& centroid) {
    double area = 0, cx = 0, cy = 0, cz = 0;
    for (Face_index f : mesh.faces()) {
      const Dart d = mesh.halfedge(f);
      const Point& a = get(vpm, mesh.source(d));
      const Point& b = get(vpm, mesh.target(d));
      const Point& c = get(vpm, mesh.target(mesh.next(d)));
      const double s = CGAL::to_double(CGAL::approximate_sqrt(gt.compute_squared_area_3_object()(a, b, c)));
      area += s;
      cx += s * CGAL::to_double(a.x() + b.x() + c.x()) / 3;
      cy += s * CGAL::to_double(a.y() + b.y() + c.y()) / 3;
      cz += s * CGAL::to_double(a.z() + b.z() + c.z()) / 3;
    }
    centroid = area > 0 ? Point(FT(cx / area), FT(cy / area), FT(cz / area)) : Point(FT(0), FT(0), FT(0));
    return area;
  };

  const std::size_t n = vertices(mesh).size();
  Matrix A(n, n);
  Vector bx(n), by(n), bz(n), Xx(n), Xy(n), Xz(n);
  std::vector<CGAL::Triple<std::size_t, std::size_t, double>> stiffness;
  PMP::internal::Shape_smoother<Mesh, VertexPointMap, VCMap, Solver, GeomTraits> smoother(mesh, vpm, vcm, gt);
  smoother.init_smoothing(faces);
  smoother.calculate_stiffness_matrix_elements(stiffness);
  for (unsigned int i = 0; i < iterations; ++i) {
    smoother.setup_system(A, bx, by, bz, stiffness, time);
    if (!smoother.solve_system(A, Xx, Xy, Xz, bx, by, bz, solver))
      break;
    Point before, after;
    const double old_area = rescale ? area_and_centroid(before) : 0;
    smoother.update_mesh_no_scaling(Xx, Xy, Xz);
    if (!rescale)
      continue;
    const double new_area = area_and_centroid(after);
    if (!(new_area > 0))
      continue;
    if (constrained == 1)
      before = after = get(vpm, anchor_vertex);
    const FT factor = FT(std::sqrt(old_area / new_area));
    for (Vertex_index v : mesh.vertices()) {
      const Vector_3 d = gt.construct_vector_3_object()(after, get(vpm, v));
      put(vpm, v, gt.construct_translated_point_3_object()(before, gt.construct_scaled_vector_3_object()(d, factor)));
    }
  }
}

/// \ingroup PkgMobiusMeshSmoothing
/// \brief `smooth_shape()` of all faces of `mesh`.
template <class P, class NamedParameters = CGAL::parameters::Default_named_parameters>
void smooth_shape(Mobius_mesh<P>& mesh, const double time, const NamedParameters& np = CGAL::parameters::default_values())
{
  smooth_shape(faces(mesh), mesh, time, np);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_SMOOTHING_SMOOTH_SHAPE_H
