// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Hole filling on a Mobius_mesh, one-sided surfaces included: CGAL's
// triangulation of a hole (Liepa's weights: the largest dihedral angle, then
// the area), its refinement and its fairing, with the faces added by the
// mesh's own add_face(), which glues them across Möbius connections.

#ifndef CGAL_EXT_HOLE_FILLING_TRIANGULATE_HOLE_H
#define CGAL_EXT_HOLE_FILLING_TRIANGULATE_HOLE_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// CGAL's tracer of a hole's triangulation, which builds the faces by CGAL's
// Euler operations, in the same (post) order, as vertex triples of the loop.
struct Hole_triangle_tracer
{
  std::vector<std::array<int, 3>> triangles;
  template <class LookupTable>
  void operator()(const LookupTable& lambda, int i, int k)
  {
    if (i + 1 == k)
      return;
    const int la = i + 2 == k ? i + 1 : lambda.get(i, k);
    (*this)(lambda, i, la);
    (*this)(lambda, la, k);
    triangles.push_back({i, la, k});
  }
};

} // namespace internal

/// \ingroup PkgMobiusMeshHoleFilling
/// \brief triangulates the hole whose border loop holds `border_dart`, as
/// CGAL's `Polygon_mesh_processing::triangulate_hole()` does, on any mesh,
/// one-sided ones included.
///
/// The loop is walked from `border_dart` with `next()`; a loop that passes a
/// Möbius connection (the border of a Möbius strip) is one loop, and the
/// patch glued into it makes Möbius edges where it meets faces running the
/// other way: capping the border of a Möbius strip gives a projective plane.
/// The triangulation is CGAL's own (the same points, the same third points
/// of the faces along the loop for the dihedral angles, the same edges that
/// must not be created twice); the faces are added by `Mobius_mesh::add_face()`
/// in the order CGAL's Euler operations would add them, each running along the
/// loop. CGAL's own function cannot: it links the loop's darts by
/// `Euler::add_face_to_border()` through the graph traits, and a flipped
/// border dart cannot be made part of a face's cycle that way.
///
/// \param mesh the mesh
/// \param border_dart a dart of the hole's border loop
/// \param out an output iterator of `Face_index`: the new faces
/// \param np CGAL's named parameters `use_delaunay_triangulation` (default
///   `true`) and `do_not_use_cubic_algorithm` (default `false`), as in CGAL;
///   the 2D constrained Delaunay shortcut (`use_2d_constrained_delaunay_triangulation`)
///   is not taken.
/// \returns `out` past the new faces; nothing is added if CGAL finds no
///   triangulation (a loop of fewer than three sides, or none that avoids
///   existing edges).
/// \throws Parameter_error if `border_dart` is not a border dart of `mesh`,
///   or its loop passes a vertex twice; the mesh is then unchanged.
template <class P, class FaceOutputIterator, class NamedParameters = CGAL::parameters::Default_named_parameters>
FaceOutputIterator triangulate_hole(Mobius_mesh<P>& mesh, Dart border_dart, FaceOutputIterator out,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Kernel = typename CGAL::Kernel_traits<P>::Kernel;
  const char* what = "triangulate_hole";
  if (!border_dart.is_valid() || border_dart.halfedge().idx() >= mesh.num_halfedges() ||
      mesh.is_removed(mesh.edge(border_dart.halfedge())) || !mesh.is_border(border_dart))
    throw Parameter_error(std::string(what) + ": the dart is not a border dart of the mesh");

  std::vector<P> points, third_points;
  std::vector<Vertex_index> loop;
  std::map<Vertex_index, int> index_of;
  for (Dart d : CGAL_ext::halfedges_around_face(border_dart, mesh)) {
    const Vertex_index v = mesh.target(d);
    points.push_back(mesh.point(v));
    third_points.push_back(mesh.point(mesh.target(mesh.next(mesh.opposite(mesh.next(d))))));
    if (!index_of.emplace(v, int(loop.size())).second)
      throw Parameter_error(std::string(what) + ": the border loop passes vertex " + std::to_string(v.idx()) +
                            " twice");
    loop.push_back(v);
  }
  const int n = int(loop.size());
  // Edges that join two vertices of the loop that are not neighbours on it:
  // the triangulation must not make them again.
  std::vector<std::pair<int, int>> existing_edges;
  for (const auto& [v, i] : index_of) {
    const int before = i == 0 ? n - 1 : i - 1, after = i == n - 1 ? 0 : i + 1;
    for (Dart d : CGAL_ext::halfedges_around_target(mesh.halfedge(v), mesh)) {
      const auto it = index_of.find(mesh.source(d));
      if (it != index_of.end() && it->second != before && it->second != after && i < it->second)
        existing_edges.push_back({i, it->second});
    }
  }
  using Weight_calculator =
    CGAL::internal::Weight_calculator<CGAL::internal::Weight_min_max_dihedral_and_area,
                                      CGAL::internal::Is_valid_existing_edges_and_degenerate_triangle>;
  CGAL::internal::Is_valid_existing_edges_and_degenerate_triangle is_valid(existing_edges);
  internal::Hole_triangle_tracer tracer;
  CGAL::Polygon_mesh_processing::Hole_filling::Default_visitor visitor;
  const bool use_dt3 = choose_parameter(get_parameter(np, CGAL::internal_np::use_delaunay_triangulation), true);
  const bool skip_cubic = choose_parameter(get_parameter(np, CGAL::internal_np::do_not_use_cubic_algorithm), false);
  CGAL::internal::triangulate_hole_polyline(points, third_points, tracer, Weight_calculator(is_valid), visitor, use_dt3,
                                            skip_cubic, Kernel());
  // CGAL's points start at the target of the border dart, its triangles use
  // the indices of the closed polyline: index n is index 0 again.
  std::string why;
  for (const auto& t : tracer.triangles) {
    const Face_index f = mesh.add_face({loop[t[0] % n], loop[t[1] % n], loop[t[2] % n]}, &why);
    if (f == Mobius_mesh<P>::null_face())
      throw Error(std::string(what) + ": a triangle of the patch could not be added: " + why);
    *out++ = f;
  }
  return out;
}

/// \ingroup PkgMobiusMeshHoleFilling
/// \brief triangulates and refines a hole, as CGAL's
/// `Polygon_mesh_processing::triangulate_and_refine_hole()`: `triangulate_hole()`,
/// then CGAL's `Polygon_mesh_processing::refine()` of the new faces, which
/// works on the mesh through the graph traits (the patch's own edges are not
/// Möbius edges: its faces run alike).
/// \returns the face and vertex output iterators past the new faces and vertices.
template <class P, class FaceOutputIterator, class VertexOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
std::pair<FaceOutputIterator, VertexOutputIterator>
triangulate_and_refine_hole(Mobius_mesh<P>& mesh, Dart border_dart, FaceOutputIterator face_out,
                            VertexOutputIterator vertex_out, const NamedParameters& np = CGAL::parameters::default_values())
{
  std::vector<Face_index> patch;
  triangulate_hole(mesh, border_dart, std::back_inserter(patch), np);
  face_out = std::copy(patch.begin(), patch.end(), face_out);
  return CGAL::Polygon_mesh_processing::refine(mesh, patch, face_out, vertex_out, np);
}

/// \ingroup PkgMobiusMeshHoleFilling
/// \brief triangulates, refines and fairs a hole, as CGAL's
/// `Polygon_mesh_processing::triangulate_refine_and_fair_hole()`:
/// `triangulate_and_refine_hole()`, then CGAL's `Polygon_mesh_processing::fair()`
/// of the new vertices (its Laplacian is orientation-free, so it runs on the
/// mesh through the graph traits). Takes CGAL's named parameters of these
/// functions (`density_control_factor`, `fairing_continuity`, `sparse_linear_solver`).
/// \returns whether fairing succeeded, and the output iterators past the new
///   faces and vertices.
template <class P, class FaceOutputIterator, class VertexOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
std::tuple<bool, FaceOutputIterator, VertexOutputIterator>
triangulate_refine_and_fair_hole(Mobius_mesh<P>& mesh, Dart border_dart, FaceOutputIterator face_out,
                                 VertexOutputIterator vertex_out,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  std::vector<Vertex_index> patch;
  face_out = triangulate_and_refine_hole(mesh, border_dart, face_out, std::back_inserter(patch), np).first;
  const bool faired = CGAL::Polygon_mesh_processing::fair(mesh, patch, np);
  vertex_out = std::copy(patch.begin(), patch.end(), vertex_out);
  return std::make_tuple(faired, face_out, vertex_out);
}

} // namespace CGAL_ext

namespace CGAL {
namespace Polygon_mesh_processing {

/// CGAL's `triangulate_hole()` called on a `Mobius_mesh` after this header is
/// included: `CGAL_ext::triangulate_hole()` when the mesh has Möbius edges
/// (CGAL's own would link a flipped border dart into a face and break the
/// mesh), CGAL's function otherwise.
template <class P, class OutputIterator, class NamedParameters = parameters::Default_named_parameters>
OutputIterator triangulate_hole(CGAL_ext::Mobius_mesh<P>& pmesh, CGAL_ext::Dart border_halfedge, OutputIterator out,
                                const NamedParameters& np = parameters::default_values())
{
  if (CGAL_ext::has_mobius_edges(pmesh))
    return CGAL_ext::triangulate_hole(pmesh, border_halfedge, out, np);
  return CGAL::Polygon_mesh_processing::triangulate_hole<CGAL_ext::Mobius_mesh<P>, OutputIterator, NamedParameters>(
    pmesh, border_halfedge, out, np);
}

/// CGAL's `triangulate_refine_and_fair_hole()` on a `Mobius_mesh`: as
/// `triangulate_hole()` above.
template <class P, class FaceOutputIterator, class VertexOutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
std::tuple<bool, FaceOutputIterator, VertexOutputIterator>
triangulate_refine_and_fair_hole(CGAL_ext::Mobius_mesh<P>& pmesh, CGAL_ext::Dart border_halfedge,
                                 FaceOutputIterator face_out, VertexOutputIterator vertex_out,
                                 const NamedParameters& np = parameters::default_values())
{
  if (CGAL_ext::has_mobius_edges(pmesh))
    return CGAL_ext::triangulate_refine_and_fair_hole(pmesh, border_halfedge, face_out, vertex_out, np);
  return CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole<CGAL_ext::Mobius_mesh<P>, FaceOutputIterator,
                                                                        VertexOutputIterator, NamedParameters>(
    pmesh, border_halfedge, face_out, vertex_out, np);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_EXT_HOLE_FILLING_TRIANGULATE_HOLE_H
