// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The closest point of a limit surface to a query point. A sampling of
// every quad and sub-face into triangles, in an AABB tree, gives the start
// and the sub-faces worth trying; in each, Newton's method on the surface's
// own first and second derivatives, kept inside the sub-face's parameter
// box, finishes. Where the minimum lies on the line between two sub-faces
// (or faces), both are tried, since the sampling finds both near the query.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_PROJECTION_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_PROJECTION_H

#include <CGAL_ext/Limit_surface/internal/Parameterization.h>
#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Intersections_3/Bbox_3_Sphere_3.h>
#include <CGAL/Intersections_3/Sphere_3_Triangle_3.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// A quad face, or one sub-face of another face, as a box of the face's parameters.
struct Projection_tile
{
  Face_index face;
  double u0, v0, size;
};

// Where the search ended: a tile, the face's parameters and the squared distance.
struct Projection_result
{
  std::uint32_t tile = 0;
  double u = 0, v = 0;
  double squared_distance = std::numeric_limits<double>::infinity();
};

// `Surface` is Limit_surface; the search runs in double whatever its kernel.
// The surface is passed to each call, not kept: the Limit_surface that owns
// this structure may have been moved since it was built.
template <class Surface>
class Limit_projection
{
  using K = CGAL::Simple_cartesian<double>;
  using Triangles = std::vector<K::Triangle_3>;
  using Tree =
    CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, typename Triangles::const_iterator>>>;
  using FT = typename Surface::FT;

  // The surface at one parameter, as Newton's method reads it.
  struct Local
  {
    K::Vector_3 r, du, dv, duu, duv, dvv; // r: from the query to the point
    double squared_distance;
  };

  // A sample triangle: its tile and the local parameters (in [0, 1]²) of its corners.
  struct Triangle_source
  {
    std::uint32_t tile;
    std::array<std::array<double, 2>, 3> st;
  };

public:
  // Samples each quad on a `rate` × `rate` grid, each sub-face of another
  // face on a (`rate` / 2)² one (the sub-face is half as wide).
  template <class P>
  Limit_projection(const Surface& surface, const Mobius_mesh<P>& mesh, int rate)
  {
    for (Face_index f : mesh.faces()) {
      const int n = int(mesh.degree(f));
      if (n == 4) {
        add_tile(surface, {f, 0.0, 0.0, 1.0}, std::max(1, rate));
        continue;
      }
      for (int k = 0; k < n; ++k) {
        const std::array<int, 2> tile = sub_face_tile(n, k);
        add_tile(surface, {f, double(tile[0]), double(tile[1]), 0.5}, std::max(1, rate / 2));
      }
    }
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.build();
    tree_.accelerate_distance_queries(); // now: lazily, the first query would build it, racing others
  }
  Limit_projection(const Limit_projection&) = delete;
  Limit_projection& operator=(const Limit_projection&) = delete;

  bool empty() const { return triangles_.empty(); }
  const Projection_tile& tile(std::uint32_t i) const { return tiles_[i]; }

  // The closest point of the surface to q, among the local minima that
  // Newton's method reaches in the tiles the sampling puts near q.
  Projection_result closest(const Surface& surface, const K::Point_3& q) const
  {
    const auto nearest = tree_.closest_point_and_primitive(q);
    const double reach = std::sqrt(CGAL::squared_distance(q, nearest.first)) + slack();
    std::vector<typename Tree::Primitive_id> hits{nearest.second};
    tree_.all_intersected_primitives(K::Sphere_3(q, reach * reach), std::back_inserter(hits));
    // The nearest sample point of each tile, nearest tiles first.
    std::unordered_map<std::uint32_t, std::pair<double, std::array<double, 2>>> starts;
    for (const auto& id : hits) {
      const std::size_t i = std::size_t(id - triangles_.cbegin());
      const K::Point_3 c = K().construct_projected_point_3_object()(*id, q);
      const double d2 = CGAL::squared_distance(q, c);
      auto [it, added] = starts.emplace(sources_[i].tile, std::make_pair(d2, std::array<double, 2>{}));
      if (added || d2 < it->second.first)
        it->second = {d2, parameters_at(i, c)};
    }
    std::vector<std::pair<double, std::uint32_t>> order;
    for (const auto& [tile, start] : starts)
      order.emplace_back(start.first, tile);
    std::sort(order.begin(), order.end());
    Projection_result best;
    for (const auto& [d2, tile] : order) {
      if (std::sqrt(d2) > std::sqrt(best.squared_distance) + slack())
        break; // no point of this tile's surface comes closer than the best
      const std::array<double, 2>& st = starts[tile].second;
      const Projection_result r = newton(surface, tile, st, q);
      if (r.squared_distance < best.squared_distance)
        best = r;
    }
    return best;
  }

private:
  // How far the surface may lie from its sample triangles and still hold
  // the closest point: twice the largest gap measured at the cells' centres
  // on each side, and a little more than rounding.
  double slack() const { return 4 * gap_ + 1e-12 * scale_; }

  K::Point_3 to_point(const typename Surface::Kernel::Point_3& p) const
  {
    return K::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  K::Vector_3 to_vector(const typename Surface::Kernel::Vector_3& v) const
  {
    return K::Vector_3(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
  }

  // The face's parameters of local parameter (s, t) of a tile.
  static std::array<double, 2> face_parameters(const Projection_tile& t, double s, double r)
  {
    return {t.u0 + t.size * s, t.v0 + t.size * r};
  }

  K::Point_3 sample(const Surface& surface, const Projection_tile& t, double s, double r) const
  {
    const std::array<double, 2> uv = face_parameters(t, s, r);
    return to_point(surface.evaluate(t.face, FT(uv[0]), FT(uv[1])).point);
  }

  void add_tile(const Surface& surface, const Projection_tile& t, int n)
  {
    const std::uint32_t id = std::uint32_t(tiles_.size());
    tiles_.push_back(t);
    std::vector<K::Point_3> grid;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        grid.push_back(sample(surface, t, double(i) / n, double(j) / n));
        scale_ = std::max({scale_, std::abs(grid.back().x()), std::abs(grid.back().y()), std::abs(grid.back().z())});
      }
    const auto at = [&](int i, int j) { return std::size_t(j * (n + 1) + i); };
    const auto st = [&](int i, int j) { return std::array<double, 2>{double(i) / n, double(j) / n}; };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t before = triangles_.size();
        add_triangle(id, grid, {at(i, j), at(i + 1, j), at(i + 1, j + 1)}, {st(i, j), st(i + 1, j), st(i + 1, j + 1)});
        add_triangle(id, grid, {at(i, j), at(i + 1, j + 1), at(i, j + 1)}, {st(i, j), st(i + 1, j + 1), st(i, j + 1)});
        measure_gap(surface, t, before, (i + 0.5) / n, (j + 0.5) / n);
      }
  }

  void add_triangle(std::uint32_t tile, const std::vector<K::Point_3>& grid, const std::array<std::size_t, 3>& corners,
                    const std::array<std::array<double, 2>, 3>& st)
  {
    const K::Triangle_3 triangle(grid[corners[0]], grid[corners[1]], grid[corners[2]]);
    if (triangle.is_degenerate()) // at a corner where the surface pinches; its neighbours hold the point
      return;
    triangles_.push_back(triangle);
    sources_.push_back({tile, st});
  }

  // The distance from the surface at a cell's centre to the cell's triangles.
  void measure_gap(const Surface& surface, const Projection_tile& t, std::size_t first, double s, double r)
  {
    if (first == triangles_.size())
      return;
    const K::Point_3 centre = sample(surface, t, s, r);
    double d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i < triangles_.size(); ++i)
      d2 = std::min(d2, CGAL::squared_distance(centre, triangles_[i]));
    gap_ = std::max(gap_, std::sqrt(d2));
  }

  // The face's parameters of point c of sample triangle i (barycentric).
  std::array<double, 2> parameters_at(std::size_t i, const K::Point_3& c) const
  {
    const K::Triangle_3& t = triangles_[i];
    const K::Vector_3 e0 = t[1] - t[0], e1 = t[2] - t[0], e2 = c - t[0];
    const double d00 = e0 * e0, d01 = e0 * e1, d11 = e1 * e1, d20 = e2 * e0, d21 = e2 * e1;
    const double denominator = d00 * d11 - d01 * d01;
    double b = 0, g = 0;
    if (denominator > 0) {
      b = std::clamp((d11 * d20 - d01 * d21) / denominator, 0.0, 1.0);
      g = std::clamp((d00 * d21 - d01 * d20) / denominator, 0.0, 1.0 - b);
    }
    const auto& st = sources_[i].st;
    const double s = (1 - b - g) * st[0][0] + b * st[1][0] + g * st[2][0];
    const double r = (1 - b - g) * st[0][1] + b * st[1][1] + g * st[2][1];
    return face_parameters(tiles_[sources_[i].tile], s, r);
  }

  Local local(const Surface& surface, const Projection_tile& t, double u, double v, const K::Point_3& q) const
  {
    const auto e = surface.evaluate(t.face, FT(u), FT(v));
    Local l{to_point(e.point) - q, to_vector(e.du), to_vector(e.dv), to_vector(e.duu), to_vector(e.duv),
            to_vector(e.dvv), 0.0};
    l.squared_distance = l.r.squared_length();
    return l;
  }

  // The Newton step for ½|S − q|² at l, with the coordinates that sit on
  // the box's side and would leave it held (a projected Newton step). The
  // Hessian is the full one where it is positive definite, Gauss–Newton's
  // JᵀJ elsewhere (away from a minimum, or on a saddle).
  static std::array<double, 2> newton_step(const Local& l, const std::array<double, 2>& x,
                                           const std::array<double, 2>& lo, const std::array<double, 2>& hi)
  {
    const double g[2] = {l.r * l.du, l.r * l.dv};
    const double G[3] = {l.du * l.du, l.du * l.dv, l.dv * l.dv};
    const double H[3] = {G[0] + l.r * l.duu, G[1] + l.r * l.duv, G[2] + l.r * l.dvv};
    bool free[2];
    for (int i = 0; i < 2; ++i)
      free[i] = !((x[i] <= lo[i] && g[i] > 0) || (x[i] >= hi[i] && g[i] < 0));
    if (free[0] && free[1]) {
      const bool full = H[0] > 0 && H[0] * H[2] - H[1] * H[1] > 0;
      const double* M = full ? H : G;
      const double det = M[0] * M[2] - M[1] * M[1];
      if (det > 0)
        return {-(M[2] * g[0] - M[1] * g[1]) / det, -(M[0] * g[1] - M[1] * g[0]) / det};
      const double trace = G[0] + G[2];
      return trace > 0 ? std::array<double, 2>{-g[0] / trace, -g[1] / trace} : std::array<double, 2>{0.0, 0.0};
    }
    std::array<double, 2> step{0.0, 0.0};
    for (int i = 0; i < 2; ++i)
      if (free[i]) {
        const double h = H[2 * i] > 0 ? H[2 * i] : G[2 * i];
        step[std::size_t(i)] = h > 0 ? -g[i] / h : 0.0;
      }
    return step;
  }

  // Near the minimum the squared distance changes by less than its
  // rounding (a parameter off by 1e-8 changes it by 1e-16 of itself): a
  // step is then judged by the gradient, which still shrinks quadratically.
  double rounding(const Local& l) const
  {
    return 1e-13 * (l.squared_distance + std::sqrt(l.squared_distance) * scale_);
  }

  // |gradient|² over the coordinates that the box's sides do not hold.
  static double free_gradient2(const Local& l, const std::array<double, 2>& x, const std::array<double, 2>& lo,
                               const std::array<double, 2>& hi)
  {
    const double g[2] = {l.r * l.du, l.r * l.dv};
    double sum = 0;
    for (std::size_t i = 0; i < 2; ++i)
      if (!((x[i] <= lo[i] && g[i] > 0) || (x[i] >= hi[i] && g[i] < 0)))
        sum += g[i] * g[i];
    return sum;
  }

  // Newton's method in one tile from `start`, halving a step that brings
  // the point neither closer nor nearer stationary, until the step vanishes.
  Projection_result newton(const Surface& surface, std::uint32_t tile, const std::array<double, 2>& start,
                           const K::Point_3& q) const
  {
    const Projection_tile& t = tiles_[tile];
    const std::array<double, 2> lo{t.u0, t.v0}, hi{t.u0 + t.size, t.v0 + t.size};
    // A parameter within rounding of the box's side is on it, so that the
    // side holds it rather than clamp every step to a vanishing move.
    const auto snap = [&](std::array<double, 2>& y) {
      for (std::size_t i = 0; i < 2; ++i)
        y[i] = y[i] - lo[i] <= 1e-12 * t.size ? lo[i] : hi[i] - y[i] <= 1e-12 * t.size ? hi[i] : y[i];
    };
    std::array<double, 2> x = start;
    snap(x);
    Local l = local(surface, t, x[0], x[1], q);
    for (int iteration = 0; iteration < 100; ++iteration) {
      const std::array<double, 2> step = newton_step(l, x, lo, hi);
      if (std::abs(step[0]) + std::abs(step[1]) <= 1e-14 * t.size)
        break;
      bool closer = false;
      std::array<double, 2> y = x;
      for (double fraction = 1; fraction > 1e-6 && !closer; fraction /= 2) {
        for (int i = 0; i < 2; ++i)
          y[std::size_t(i)] = std::clamp(x[std::size_t(i)] + fraction * step[std::size_t(i)], lo[std::size_t(i)], hi[std::size_t(i)]);
        snap(y);
        const Local m = local(surface, t, y[0], y[1], q);
        if (m.squared_distance < l.squared_distance || (m.squared_distance <= l.squared_distance + rounding(l) &&
                                                        free_gradient2(m, y, lo, hi) < free_gradient2(l, x, lo, hi))) {
          l = m;
          closer = true;
        }
      }
      if (!closer)
        break;
      x = y;
    }
    return {tile, x[0], x[1], l.squared_distance};
  }

  std::vector<Projection_tile> tiles_;
  Triangles triangles_;
  std::vector<Triangle_source> sources_;
  Tree tree_;
  double gap_ = 0, scale_ = 0;
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_PROJECTION_H
