// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The points an algorithm accepts, checked before it touches anything: finite
// ones for those that compare distances, and within the range where
// computations in double neither overflow nor underflow for those that
// measure areas and angles in double.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_COORDINATE_CHECKS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_COORDINATE_CHECKS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace CGAL_ext {
namespace internal {

// Decimation, remeshing and offsets measure in double: squared lengths,
// areas, dot products of face normals (fourth powers of the coordinates) and
// quadrics (an area times a squared distance, summed over every face). Past
// some size they overflow to infinity or NaN; below some size they underflow
// to zero, and every face looks degenerate. Within +-1e60 the largest of
// them, summed over 2^32 faces, stays below 1e260; over a mesh at least
// 1e-60 across, the fourth power of its size stays above 1e-240, far from
// the least double (1e-308), even for features a millionth of its size.
constexpr double max_abs_coordinate = 1e60;
constexpr double min_extent = 1e-60;

template <class Point>
std::string describe_vertex(Vertex_index v, const Point& p)
{
  std::ostringstream what;
  what << "vertex " << v.idx() << " at (" << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y()) << ", "
       << CGAL::to_double(p.z()) << ")";
  return what.str();
}

// Refuses a mesh with a point that is not finite (as a double), naming the
// first such vertex: a NaN makes every comparison of distances false.
template <class P>
void require_finite_points(const Mobius_mesh<P>& mesh, const char* function)
{
  for (Vertex_index v : mesh.vertices()) {
    const P& p = mesh.point(v);
    if (std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
        std::isfinite(CGAL::to_double(p.z())))
      continue;
    throw Parameter_error(std::string(function) + ": " + describe_vertex(v, p) +
                          " has a coordinate that is not finite");
  }
}

// Refuses a mesh with a point beyond max_abs_coordinate (or not finite),
// naming the first such vertex, or one whose bounding box is less than
// min_extent across (but not a single point), before anything is touched.
// Returns the largest absolute coordinate, for require_length_resolved().
// `point_of(v)` gives the point of vertex v (a vertex point map's, say).
template <class P, class Point_of>
double require_coordinates_in_range(const Mobius_mesh<P>& mesh, const char* function, const Point_of& point_of)
{
  std::array<double, 3> low{}, high{};
  bool first = true;
  for (Vertex_index v : mesh.vertices()) {
    const auto& p = point_of(v);
    const std::array<double, 3> x{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    const double b = max_abs_coordinate;
    if (!(std::abs(x[0]) <= b && std::abs(x[1]) <= b && std::abs(x[2]) <= b)) { // true for NaN too
      std::ostringstream what;
      what << function << ": " << describe_vertex(v, p) << " has a coordinate beyond +-" << max_abs_coordinate
           << ", where its computations in double overflow";
      throw Parameter_error(what.str());
    }
    for (int i = 0; i < 3; ++i) {
      low[i] = first ? x[i] : (std::min)(low[i], x[i]);
      high[i] = first ? x[i] : (std::max)(high[i], x[i]);
    }
    first = false;
  }
  const double extent = (std::max)({high[0] - low[0], high[1] - low[1], high[2] - low[2]});
  if (extent > 0 && extent < min_extent) {
    std::ostringstream what;
    what << function << ": the mesh is only " << extent << " across (the longest side of its bounding box), under "
         << min_extent << ", where its areas in double underflow; scale it up first";
    throw Parameter_error(what.str());
  }
  double largest = 0;
  for (int i = 0; i < 3; ++i)
    largest = (std::max)({largest, std::abs(low[i]), std::abs(high[i])});
  return largest;
}

// The same for the mesh's own points.
template <class P>
double require_coordinates_in_range(const Mobius_mesh<P>& mesh, const char* function)
{
  return require_coordinates_in_range(mesh, function, [&](Vertex_index v) -> const P& { return mesh.point(v); });
}

// Refuses a length that coordinates up to `largest` in absolute value
// cannot resolve: under 1024 times the spacing of doubles there. Finer than
// that, the midpoint of an edge rounds onto one of its ends (a split leaves
// a half as long as the edge), and the lengths compared are rounding errors.
inline void require_length_resolved(double largest, double length, const char* function)
{
  const double spacing = std::nextafter(largest, HUGE_VAL) - largest;
  if (length >= 1024 * spacing)
    return;
  std::ostringstream what;
  what << function << ": the edge length " << length << " is under 1024 times the spacing of the coordinates ("
       << spacing << " between doubles at " << largest << ", the largest), too fine for them to resolve";
  throw Parameter_error(what.str());
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_COORDINATE_CHECKS_H
