// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Triangulating the faces of a Mobius_mesh, as CGAL's
// Polygon_mesh_processing::triangulate_faces() does for a Surface_mesh.

#ifndef CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H
#define CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// The darts of face `f` walking the face its own way, one into each corner.
template <class P>
std::vector<Dart> face_corners(Face_index f, const Mobius_mesh<P>& m)
{
  std::vector<Dart> into;
  for (Dart c : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
    into.push_back(c);
  return into;
}

// The corners of a face from which to fan it into triangles, best first, by
// their positions in `into` (face_corners()). A quad takes its shorter
// diagonal first (corners 0 and 1 stand for the two diagonals). A larger
// face ranks its corners by the smallest triangle of their fan, largest
// first: a fan from any corner of a planar convex face has no flipped
// triangle, and this order keeps it from degenerate ones where three corners
// are in line. Each triangle's area is measured along the face's Newell
// normal, so a triangle turned against the face counts as negative.
template <class P>
std::vector<std::size_t> fan_apexes_best_first(const std::vector<Dart>& into, const Mobius_mesh<P>& m)
{
  std::vector<Point_d> ps;
  for (Dart c : into)
    ps.push_back(to_point_d(m.point(m.target(c))));
  const std::size_t n = ps.size();
  if (n == 4) {
    const Point_d d02 = minus_d(ps[0], ps[2]), d13 = minus_d(ps[1], ps[3]);
    return dot_d(d02, d02) <= dot_d(d13, d13) ? std::vector<std::size_t>{0, 1} : std::vector<std::size_t>{1, 0};
  }
  const Point_d normal = newell_d(ps).first;
  std::vector<double> smallest(n, std::numeric_limits<double>::infinity());
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t k = 1; k + 1 < n; ++k) {
      const Point_d& o = ps[a];
      const double area = dot_d(normal, cross_d(minus_d(ps[(a + k) % n], o), minus_d(ps[(a + k + 1) % n], o)));
      smallest[a] = (std::min)(smallest[a], area);
    }
  std::vector<std::size_t> order(n);
  for (std::size_t a = 0; a < n; ++a)
    order[a] = a;
  // NaN areas (points at infinity are refused elsewhere) rank last.
  auto key = [&](std::size_t a) { return std::isnan(smallest[a]) ? -std::numeric_limits<double>::infinity() : smallest[a]; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) > key(b); });
  return order;
}

// The fan of each face to split, chosen for the whole mesh before anything
// is split: a diagonal must not join two corners that an edge already
// joins, in the mesh, in the same fan or among the diagonals chosen for
// faces before. A face whose every fan is refused throws, and the mesh is
// still untouched.
template <class P>
std::vector<std::pair<Face_index, Dart>> plan_fans(const Mobius_mesh<P>& mesh)
{
  std::vector<std::pair<Face_index, Dart>> plan;
  std::unordered_set<std::uint64_t> chosen; // the diagonals chosen, by their ends
  auto key = [](Vertex_index a, Vertex_index b) {
    const std::uint64_t lo = (std::min)(a.idx(), b.idx()), hi = (std::max)(a.idx(), b.idx());
    return lo << 32 | hi;
  };
  auto can_join = [&](Vertex_index a, Vertex_index b) {
    return a != b && chosen.count(key(a, b)) == 0 && !Euler::internal::are_adjacent(a, b, mesh);
  };
  for (Face_index f : mesh.faces()) {
    if (mesh.degree(f) <= 3)
      continue;
    const std::vector<Dart> into = face_corners(f, mesh);
    const std::size_t n = into.size();
    bool planned = false;
    std::vector<std::uint64_t> fan;
    for (std::size_t a : fan_apexes_best_first(into, mesh)) {
      const Vertex_index apex = mesh.target(into[a]);
      bool fan_fits = true;
      fan.clear();
      for (std::size_t k = 2; k + 1 < n && fan_fits; ++k) {
        fan_fits = can_join(apex, mesh.target(into[(a + k) % n]));
        fan.push_back(key(apex, mesh.target(into[(a + k) % n])));
      }
      // A face that passes a corner twice would join the apex to it twice.
      std::sort(fan.begin(), fan.end());
      if (!fan_fits || std::adjacent_find(fan.begin(), fan.end()) != fan.end())
        continue;
      chosen.insert(fan.begin(), fan.end());
      plan.emplace_back(f, into[a]);
      planned = true;
      break;
    }
    if (!planned) {
      std::string corners;
      for (Dart c : into)
        corners += (corners.empty() ? "" : ", ") + std::to_string(mesh.target(c).idx());
      throw Euler_error("triangulate_faces: face " + std::to_string(f.idx()) + " (vertices " + corners +
                        ") has no fan of triangles whose diagonals are not already edges; the mesh is unchanged");
    }
  }
  return plan;
}

} // namespace internal

/// \ingroup PkgMobiusMeshEuler
/// \brief Splits every face of `mesh` with more than three sides into
/// triangles, with `Euler::split_face()`: a quad along its shorter diagonal, a
/// larger face by a fan from the corner whose smallest triangle is largest
/// (so a planar convex face gives no degenerate or flipped triangle). Where
/// that would join two corners that an edge already joins (a quad whose
/// shorter diagonal is an edge of the mesh, or the diagonal another face
/// takes), the next best diagonal or fan is taken. The new faces take the
/// values of every face property map of the face they come from; vertices
/// and edges keep theirs (new edges get the maps' defaults). Möbius edges and
/// the surface's topology are unchanged.
/// \returns the number of faces added (a face of `n` sides adds `n - 3`).
/// \throws Parameter_error if `mesh` has removed elements.
/// \throws Euler_error, naming the face and its vertices, if every fan of a
/// face would duplicate an edge. Both are thrown before `mesh` is touched.
template <class P>
std::size_t triangulate_faces(Mobius_mesh<P>& mesh)
{
  CGAL_ext::internal::require_no_garbage(mesh, "triangulate_faces");
  const std::size_t n_old = mesh.number_of_faces();
  std::vector<std::uint32_t> parent;
  for (const auto& [f, apex] : internal::plan_fans(mesh)) {
    // Cut the triangle (apex, next corner, the one after) off, while more than three sides remain.
    for (std::size_t sides = mesh.degree(f); sides > 3; --sides) {
      Euler::split_face(apex, mesh.next(mesh.next(apex)), mesh, Euler::unchecked);
      parent.push_back(std::uint32_t(f.idx()));
    }
  }
  if (!parent.empty())
    internal::transfer_properties<Face_index>(mesh, mesh, n_old, mesh.number_of_faces(),
                                              [&](Face_index g) { return Face_index(parent[g.idx() - n_old]); });
  return parent.size();
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TRIANGULATE_FACES_H
