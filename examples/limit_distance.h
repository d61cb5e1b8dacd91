// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// How far a decimated or remeshed result lies from the smooth surface its
// input stands for, when the input is a subdivision cage: the tools'
// "limit_distance".

#ifndef CGAL_EXT_EXAMPLES_LIMIT_DISTANCE_H
#define CGAL_EXT_EXAMPLES_LIMIT_DISTANCE_H

#include <CGAL_ext/Limit_surface.h>
#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/centroid.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace examples {

template <class P>
using Cage_surface = CGAL_ext::Subdivision::Limit_surface<CGAL_ext::Subdivision::Catmull_clark_mask, P>;

// The Catmull–Clark limit surface of `cage` (its own sharpness maps), made
// before the tool's work, so that a cage it refuses stops the tool before
// anything is written.
template <class P>
std::unique_ptr<Cage_surface<P>> cage_surface(const CGAL_ext::Mobius_mesh<P>& cage)
{
  return std::make_unique<Cage_surface<P>>(cage);
}

// The largest distance from the vertices and face centroids of `result` to `surface`.
template <class P>
double limit_distance(const CGAL_ext::Mobius_mesh<P>& result, const Cage_surface<P>& surface)
{
  double farthest = 0;
  const auto measure = [&](const P& p) {
    farthest = (std::max)(farthest, std::sqrt(CGAL::to_double(surface.closest_point(p).squared_distance)));
  };
  for (CGAL_ext::Vertex_index v : result.vertices())
    if (!result.is_isolated(v))
      measure(result.point(v));
  for (CGAL_ext::Face_index f : result.faces()) {
    std::vector<P> corners;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(result.halfedge(f), result))
      corners.push_back(result.point(v));
    measure(CGAL::centroid(corners.begin(), corners.end(), CGAL::Dimension_tag<0>()));
  }
  return farthest;
}

} // namespace examples

#endif // CGAL_EXT_EXAMPLES_LIMIT_DISTANCE_H
