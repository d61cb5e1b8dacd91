// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The parts of a surface too narrow for a target edge length, found before
// the mesh is touched, and the shape of a face that tells them (its area,
// longest side and width).

#ifndef CGAL_EXT_REMESHING_INTERNAL_NARROW_REGIONS_H
#define CGAL_EXT_REMESHING_INTERNAL_NARROW_REGIONS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Remeshing/internal/Isotropic_remesher.h>
#include <CGAL_ext/exceptions.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

struct Face_shape
{
  std::size_t corners = 0;
  double area = 0;
  double longest = 0;                                    // the longest side
  // 2 area / longest side for a triangle, area / longest side otherwise
  double width = std::numeric_limits<double>::infinity();
  Edge_index longest_edge;
};

template <class P>
Face_shape face_shape(const Mobius_mesh<P>& mesh, Face_index f)
{
  boost::container::small_vector<Point_d, 8> corners;
  Face_shape shape;
  for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
    const Point_d a = to_point_d(mesh.point(mesh.source(d))), b = to_point_d(mesh.point(mesh.target(d)));
    const double side = std::sqrt(dot_d(minus_d(b, a), minus_d(b, a)));
    if (side >= shape.longest) {
      shape.longest = side;
      shape.longest_edge = mesh.edge(d);
    }
    corners.push_back(a);
  }
  const Point_d n = newell_d(corners).first;
  shape.corners = corners.size();
  shape.area = std::sqrt(dot_d(n, n)) / 2;
  if (shape.longest > 0) // a strip of quads l x w has area l w: its width is area / l, a triangle's twice that
    shape.width = (shape.corners == 3 ? 2 : 1) * shape.area / shape.longest;
  return shape;
}

// The faces of the parts of a surface narrower than a target length allows
// (see find_narrow_regions()), and the narrowest of them.
struct Narrow_regions
{
  std::size_t faces = 0;
  Face_index narrowest;
  double narrowest_width = std::numeric_limits<double>::infinity();
  double narrowest_length = 0;
};

// A narrow face is narrower than any triangle of the band (its width under
// narrowest_band_triangle() L) and longer than 4/3 L along an edge that the
// split pass may cut: no triangle with sides from 4/5 L to 4/3 L fits in it,
// and the loop can only cut it along its length into a strip as wide as it.
// Where a wider face lies beside it, collapses and flips join its pieces to
// that face's; where none does, nothing can: a region of narrow faces joined
// by their edges is a narrow part of the surface if at least 3/4 of its
// outline is the surface's border (not mostly faces beside it) and its area
// over half that border (its mean width) is also under
// narrowest_band_triangle() L. A needle alone, a strip narrower than L and a
// thin tail on a wide part are narrow parts; a sliver amid wide faces, a
// sliver along a border and a fan of slivers that together span a wide cap
// are not. A closed tube thinner than L has no border and is not found.
template <class P, class Is_protected>
Narrow_regions find_narrow_regions(const Mobius_mesh<P>& mesh, const Remeshing_options& options,
                                   const Is_protected& is_protected)
{
  const double L = options.target_edge_length, narrow = narrowest_band_triangle() * L;
  std::vector<Face_shape> shapes(mesh.num_faces());
  std::vector<char> is_narrow(mesh.num_faces(), 0);
  for (Face_index f : mesh.faces()) {
    shapes[f.idx()] = face_shape(mesh, f);
    const Face_shape& s = shapes[f.idx()];
    is_narrow[f.idx()] = s.width < narrow && s.longest > 4.0 / 3.0 * L && !is_protected(s.longest_edge);
  }
  Narrow_regions found;
  std::vector<char> seen(mesh.num_faces(), 0);
  std::vector<Face_index> region, stack;
  for (Face_index start : mesh.faces()) {
    if (!is_narrow[start.idx()] || seen[start.idx()])
      continue;
    region.clear();
    stack.assign(1, start);
    seen[start.idx()] = 1;
    double area = 0, border = 0, beside = 0;
    while (!stack.empty()) {
      const Face_index f = stack.back();
      stack.pop_back();
      region.push_back(f);
      area += shapes[f.idx()].area;
      for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
        const Point_d a = to_point_d(mesh.point(mesh.source(d))), b = to_point_d(mesh.point(mesh.target(d)));
        const double side = std::sqrt(dot_d(minus_d(b, a), minus_d(b, a)));
        if (mesh.is_border(mesh.edge(d))) {
          border += side;
          continue;
        }
        const Face_index g = mesh.face(mesh.opposite(d));
        if (!is_narrow[g.idx()])
          beside += side;
        else if (!seen[g.idx()]) {
          seen[g.idx()] = 1;
          stack.push_back(g);
        }
      }
    }
    if (!(border > 0 && border >= 3 * beside && 2 * area / border < narrow))
      continue;
    found.faces += region.size();
    for (Face_index f : region)
      if (shapes[f.idx()].width < found.narrowest_width) {
        found.narrowest = f;
        found.narrowest_width = shapes[f.idx()].width;
        found.narrowest_length = shapes[f.idx()].longest;
      }
  }
  return found;
}

// Refuses, with Parameter_error naming its narrowest face, a surface with
// narrow parts (find_narrow_regions()) if allow_narrow_regions is false.
inline void require_no_narrow_regions(const Narrow_regions& found, const Remeshing_options& options)
{
  if (found.faces == 0 || options.allow_narrow_regions)
    return;
  const double L = options.target_edge_length;
  std::ostringstream what;
  what << "isotropic_remeshing: face f" << found.narrowest.idx() << " is " << found.narrowest_width << " wide and "
       << found.narrowest_length << " long, in a part of the surface narrower than any triangle with sides from 4/5 L "
       << "to 4/3 L (" << narrowest_band_triangle() * L << " for L = " << L << ")";
  if (found.faces > 1)
    what << " with " << found.faces - 1 << " other such faces";
  what << ": remeshing could only cut it along its length into slivers, and allow_narrow_regions is false";
  throw Parameter_error(what.str());
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_REMESHING_INTERNAL_NARROW_REGIONS_H
