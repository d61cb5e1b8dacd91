// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/Mobius_mesh/triangulate_faces.h>: the fan triangulation of faces: corners, apexes and the plan of fans.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_FAN_TRIANGULATION_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_FAN_TRIANGULATION_H

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
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_FAN_TRIANGULATION_H
