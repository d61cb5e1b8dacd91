// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The closest point of a limit surface to a query point. A sampling of
// every quad and sub-face (every triangle, for Loop) into triangles, in an
// AABB tree, gives the start and the sub-faces worth trying; in each,
// Newton's method on the surface's own first and second derivatives, kept
// inside the sub-face's parameter box (or triangle), finishes. Where the minimum lies on the line between two sub-faces
// (or faces), both are tried, since the sampling finds both near the query.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_PROJECTION_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_PROJECTION_H

#include <CGAL_ext/Limit_surface/internal/Parameterization.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/AABB_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Intersections_3/Bbox_3_Sphere_3.h>
#include <CGAL/Intersections_3/Sphere_3_Triangle_3.h>
#include <CGAL/Origin.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// A quad face, or one sub-face of another face, as a box of the face's
// parameters; or a triangle of Loop over its domain u, v >= 0, u + v <= 1.
struct Projection_tile
{
  Face_index face;
  double u0, v0, size;
  bool triangle = false;
};

// The parameter domain of a tile as Newton's method keeps to it: the box
// [lo, hi], cut by u + v <= 1 for a triangle; its sides as half-planes
// n · x <= c.
struct Tile_domain
{
  std::array<double, 2> lo, hi;
  bool triangle = false;
  double size = 1;
  std::vector<std::array<double, 3>> sides; // n0, n1, c

  explicit Tile_domain(const Projection_tile& t)
      : lo{t.u0, t.v0}, hi{t.u0 + t.size, t.v0 + t.size}, triangle(t.triangle), size(t.size)
  {
    sides = {{-1, 0, -lo[0]}, {0, -1, -lo[1]}};
    if (triangle)
      sides.push_back({1, 1, 1});
    else
      sides.insert(sides.end(), {{1, 0, hi[0]}, {0, 1, hi[1]}});
  }

  // Whether x is on `side` and a descent along -g would leave by it.
  bool blocks(const std::array<double, 3>& side, const std::array<double, 2>& x, const double g[2]) const
  {
    return side[0] * x[0] + side[1] * x[1] >= side[2] - 1e-12 * size && side[0] * g[0] + side[1] * g[1] < 0;
  }

  // The nearest point of the long side of a triangle, from beyond it.
  static void onto_long_side(std::array<double, 2>& y)
  {
    const double t = std::clamp((y[0] - y[1] + 1) / 2, 0.0, 1.0);
    y = {t, 1 - t};
  }

  void project(std::array<double, 2>& y) const
  {
    for (std::size_t i = 0; i < 2; ++i)
      y[i] = std::clamp(y[i], lo[i], hi[i]);
    if (triangle && y[0] + y[1] > 1)
      onto_long_side(y);
  }

  // A parameter within rounding of a side is on it, so that the side holds
  // it rather than clamp every step to a vanishing move.
  void snap(std::array<double, 2>& y) const
  {
    const double e = 1e-12 * size;
    for (std::size_t i = 0; i < 2; ++i)
      y[i] = y[i] - lo[i] <= e ? lo[i] : hi[i] - y[i] <= e ? hi[i] : y[i];
    if (triangle && 1 - y[0] - y[1] <= e)
      onto_long_side(y);
  }
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
  using FT = typename Surface::FT;

  // The tree's primitives are the sample triangles' numbers; a triangle is
  // made when the tree reads it, from the grid points its tile shares with
  // its neighbours (stored, its corners would take 72 bytes; the points
  // take some 19 a triangle of a quad at projection_rate 4, 27 of a
  // sub-face, 38 of a Loop triangle, whose square grid is half used).
  struct Triangle_map
  {
    using key_type = std::uint32_t;
    using value_type = K::Triangle_3;
    using reference = K::Triangle_3;
    using category = boost::readable_property_map_tag;
    const Limit_projection* projection = nullptr;
    friend K::Triangle_3 get(const Triangle_map& m, std::uint32_t i) { return m.projection->triangle(i); }
  };
  // A point on each primitive, as the tree needs one: its first corner.
  struct Corner_map
  {
    using key_type = std::uint32_t;
    using value_type = K::Point_3;
    using reference = const K::Point_3&;
    using category = boost::readable_property_map_tag;
    const Limit_projection* projection = nullptr;
    friend const K::Point_3& get(const Corner_map& m, std::uint32_t i) { return m.projection->corner(i, 0); }
  };
  using Primitive = CGAL::AABB_primitive<std::uint32_t, Triangle_map, Corner_map, CGAL::Tag_true, CGAL::Tag_false>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

  // The surface at one parameter, as Newton's method reads it.
  struct Local
  {
    K::Vector_3 r, du, dv, duu, duv, dvv; // r: from the query to the point
    double squared_distance;
  };

  // The triangles of cell (i, j) of a tile's grid, by the grid offsets of
  // their corners: the two of a quad's cell (split along its diagonal), and
  // the one pointing up and the one pointing down of a triangle's cell.
  enum Cell_triangle : std::uint8_t { quad_lower, quad_upper, domain_up, domain_down };
  static constexpr std::array<std::array<std::array<int, 2>, 3>, 4> cell_corners{
    {{{{0, 0}, {1, 0}, {1, 1}}}, {{{0, 0}, {1, 1}, {0, 1}}}, {{{0, 0}, {1, 0}, {0, 1}}}, {{{1, 0}, {1, 1}, {0, 1}}}}};

  // A sample triangle: its tile, its cell (i, j) of the tile's n × n grid
  // (16 bits: Limit_surface caps projection_rate at 1024) and which of the
  // cell's triangles it is; 12 bytes rather than its corners' parameters
  // and points.
  struct Triangle_source
  {
    std::uint32_t tile;
    std::uint16_t i, j, n;
    Cell_triangle shape;

    // The local parameters (in [0, 1]²) of the triangle's corners.
    std::array<std::array<double, 2>, 3> corners() const
    {
      std::array<std::array<double, 2>, 3> st;
      for (int k = 0; k < 3; ++k)
        st[k] = {double(i + cell_corners[shape][k][0]) / n, double(j + cell_corners[shape][k][1]) / n};
      return st;
    }
    // Where corner k lies in its tile's grid of (n + 1)² points, row by row.
    std::size_t grid_index(int k) const
    {
      return (std::size_t(j) + std::size_t(cell_corners[shape][k][1])) * (std::size_t(n) + 1) + i +
             std::size_t(cell_corners[shape][k][0]);
    }
  };

public:
  // Samples each quad on a `rate` × `rate` grid, each sub-face of another
  // face on a (`rate` / 2)² one (the sub-face is half as wide); with
  // `triangle_domain` (Loop) each triangle on its own domain, `rate` samples a side.
  template <class P>
  Limit_projection(const Surface& surface, const Mobius_mesh<P>& mesh, int rate, bool triangle_domain = false)
  {
    CGAL_precondition(rate <= 65535); // the cells' 16-bit indices
    reserve(surface, mesh, std::max(1, rate), triangle_domain);
    for (Face_index f : mesh.faces()) {
      if (surface.is_hole(f))
        continue;
      const int n = int(mesh.degree(f));
      if (triangle_domain) {
        add_tile(surface, {f, 0.0, 0.0, 1.0, true}, std::max(1, rate));
        continue;
      }
      if (n == 4) {
        add_tile(surface, {f, 0.0, 0.0, 1.0}, std::max(1, rate));
        continue;
      }
      for (int k = 0; k < n; ++k) {
        const std::array<int, 2> tile = sub_face_tile(n, k);
        add_tile(surface, {f, double(tile[0]), double(tile[1]), 0.5}, std::max(1, rate / 2));
      }
    }
    tree_.insert(boost::counting_iterator<std::uint32_t>(0),
                 boost::counting_iterator<std::uint32_t>(std::uint32_t(sources_.size())), Triangle_map{this},
                 Corner_map{this});
    tree_.build();
    accelerate_distance_queries();
  }
  Limit_projection(const Limit_projection&) = delete;
  Limit_projection& operator=(const Limit_projection&) = delete;

  bool empty() const { return sources_.empty(); }
  const Projection_tile& tile(std::uint32_t i) const { return tiles_[i]; }

  // Corner k of sample triangle i, and the triangle.
  const K::Point_3& corner(std::uint32_t i, int k) const
  {
    const Triangle_source& s = sources_[i];
    return points_[grid_start_[s.tile] + s.grid_index(k)];
  }
  K::Triangle_3 triangle(std::uint32_t i) const { return K::Triangle_3(corner(i, 0), corner(i, 1), corner(i, 2)); }

  // A parameter found in double, as the kernel's numbers: on a triangle's
  // long side u + v may pass 1 by a rounding in double, which an exact
  // kernel would refuse; there v is taken as 1 - u, in the kernel.
  static std::array<FT, 2> kernel_parameters(const Projection_tile& t, double u, double v)
  {
    FT fu(u), fv(v);
    if (t.triangle && fu + fv > FT(1))
      fv = FT(1) - fu;
    return {fu, fv};
  }

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
    for (const std::uint32_t i : hits) {
      const K::Point_3 c = K().construct_projected_point_3_object()(triangle(i), q);
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
  // Room for every tile, grid point and triangle (an upper bound: degenerate
  // triangles are left out), so that the arrays are not copied as they grow.
  template <class P>
  void reserve(const Surface& surface, const Mobius_mesh<P>& mesh, int rate, bool triangle_domain)
  {
    std::size_t tiles = 0, points = 0, triangles = 0;
    for (Face_index f : mesh.faces()) {
      if (surface.is_hole(f))
        continue;
      const std::size_t n = mesh.degree(f), r = std::size_t(rate), half = std::size_t(std::max(1, rate / 2));
      if (triangle_domain) { // r (r + 1) / 2 cells up, r (r - 1) / 2 down
        tiles += 1;
        points += (r + 1) * (r + 1);
        triangles += r * r;
      } else if (n == 4) {
        tiles += 1;
        points += (r + 1) * (r + 1);
        triangles += 2 * r * r;
      } else {
        tiles += n;
        points += n * (half + 1) * (half + 1);
        triangles += 2 * n * half * half;
      }
    }
    if (triangles > std::numeric_limits<std::uint32_t>::max()) // the tree numbers them in 32 bits
      throw Size_error("Limit_surface::closest_point: the search structure would sample " + std::to_string(triangles) +
                         " triangles, more than the " + std::to_string(std::numeric_limits<std::uint32_t>::max()) +
                         " it can number (lower projection_rate)",
                       "triangles", triangles, std::numeric_limits<std::uint32_t>::max());
    tiles_.reserve(tiles);
    grid_start_.reserve(tiles);
    points_.reserve(points);
    sources_.reserve(triangles);
  }

  // The hints of the tree's distance queries: a sample point of each tile
  // (a corner of its first triangle, which lies on that primitive, as CGAL
  // needs) rather than one of each triangle (CGAL's default): a search
  // structure as many times smaller as a tile has triangles (32 a quad at
  // rate 4), whose nearest point starts a query within a tile of its answer.
  // Built now, while one thread holds the structure, not in a query.
  void accelerate_distance_queries()
  {
    if (sources_.empty())
      return; // nothing to search (Limit_surface::closest_point() refuses the query)
    std::vector<typename Tree::Point_and_primitive_id> hints;
    hints.reserve(tiles_.size());
    for (std::uint32_t i = 0; i < std::uint32_t(sources_.size()); ++i)
      if (i == 0 || sources_[i].tile != sources_[i - 1].tile)
        hints.emplace_back(corner(i, 0), i);
    tree_.accelerate_distance_queries(hints.cbegin(), hints.cend());
  }

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
    const std::array<FT, 2> at = kernel_parameters(t, uv[0], uv[1]);
    return to_point(surface.evaluate(t.face, at[0], at[1]).point);
  }

  void add_tile(const Surface& surface, const Projection_tile& t, int n)
  {
    const std::uint32_t id = std::uint32_t(tiles_.size());
    tiles_.push_back(t);
    grid_start_.push_back(points_.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        if (t.triangle && i + j > n) { // outside the triangle: a place holder
          points_.push_back(K::Point_3(CGAL::ORIGIN));
          continue;
        }
        points_.push_back(sample(surface, t, double(i) / n, double(j) / n));
        const K::Point_3& p = points_.back();
        scale_ = std::max({scale_, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
      }
    const Triangle_source cell{id, 0, 0, std::uint16_t(n), quad_lower};
    if (t.triangle) { // the grid's points with i + j <= n, two triangles a cell but on the long side
      for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
          std::size_t before = sources_.size();
          add_triangle(at_cell(cell, i, j, domain_up));
          measure_gap(surface, t, before, (i + 1.0 / 3) / n, (j + 1.0 / 3) / n);
          if (i + j + 1 == n)
            continue;
          before = sources_.size();
          add_triangle(at_cell(cell, i, j, domain_down));
          measure_gap(surface, t, before, (i + 2.0 / 3) / n, (j + 2.0 / 3) / n);
        }
      return;
    }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t before = sources_.size();
        add_triangle(at_cell(cell, i, j, quad_lower));
        add_triangle(at_cell(cell, i, j, quad_upper));
        measure_gap(surface, t, before, (i + 0.5) / n, (j + 0.5) / n);
      }
  }

  static Triangle_source at_cell(Triangle_source s, int i, int j, Cell_triangle shape)
  {
    s.i = std::uint16_t(i);
    s.j = std::uint16_t(j);
    s.shape = shape;
    return s;
  }

  // Adds sample triangle `s` of the last tile, whose grid points are in place.
  void add_triangle(const Triangle_source& s)
  {
    sources_.push_back(s);
    if (triangle(std::uint32_t(sources_.size() - 1)).is_degenerate())
      sources_.pop_back(); // at a corner where the surface pinches; its neighbours hold the point
  }

  // The distance from the surface at a cell's centre to the cell's triangles.
  void measure_gap(const Surface& surface, const Projection_tile& t, std::size_t first, double s, double r)
  {
    if (first == sources_.size())
      return;
    const K::Point_3 centre = sample(surface, t, s, r);
    double d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i < sources_.size(); ++i)
      d2 = std::min(d2, CGAL::squared_distance(centre, triangle(std::uint32_t(i))));
    gap_ = std::max(gap_, std::sqrt(d2));
  }

  // The face's parameters of point c of sample triangle i (barycentric).
  std::array<double, 2> parameters_at(std::uint32_t i, const K::Point_3& c) const
  {
    const K::Triangle_3 t = triangle(i);
    const K::Vector_3 e0 = t[1] - t[0], e1 = t[2] - t[0], e2 = c - t[0];
    const double d00 = e0 * e0, d01 = e0 * e1, d11 = e1 * e1, d20 = e2 * e0, d21 = e2 * e1;
    const double denominator = d00 * d11 - d01 * d01;
    double b = 0, g = 0;
    if (denominator > 0) {
      b = std::clamp((d11 * d20 - d01 * d21) / denominator, 0.0, 1.0);
      g = std::clamp((d00 * d21 - d01 * d20) / denominator, 0.0, 1.0 - b);
    }
    const std::array<std::array<double, 2>, 3> st = sources_[i].corners();
    const double s = (1 - b - g) * st[0][0] + b * st[1][0] + g * st[2][0];
    const double r = (1 - b - g) * st[0][1] + b * st[1][1] + g * st[2][1];
    return face_parameters(tiles_[sources_[i].tile], s, r);
  }

  Local local(const Surface& surface, const Projection_tile& t, double u, double v, const K::Point_3& q) const
  {
    const std::array<FT, 2> at = kernel_parameters(t, u, v);
    const auto e = surface.evaluate(t.face, at[0], at[1]);
    Local l{to_point(e.point) - q, to_vector(e.du), to_vector(e.dv), to_vector(e.duu), to_vector(e.duv),
            to_vector(e.dvv), 0.0};
    l.squared_distance = l.r.squared_length();
    return l;
  }

  // The Newton step for ½|S − q|² at l, held along a side of the domain
  // that x sits on and the step would leave by (a projected Newton step),
  // nothing where two sides hold it. The Hessian is the full one where it
  // is positive definite, Gauss–Newton's JᵀJ elsewhere (away from a
  // minimum, or on a saddle).
  static std::array<double, 2> newton_step(const Local& l, const std::array<double, 2>& x, const Tile_domain& domain)
  {
    const double g[2] = {l.r * l.du, l.r * l.dv};
    const double G[3] = {l.du * l.du, l.du * l.dv, l.dv * l.dv};
    const double H[3] = {G[0] + l.r * l.duu, G[1] + l.r * l.duv, G[2] + l.r * l.dvv};
    std::vector<std::array<double, 3>> held;
    for (const auto& side : domain.sides)
      if (domain.blocks(side, x, g))
        held.push_back(side);
    if (held.empty()) {
      const bool full = H[0] > 0 && H[0] * H[2] - H[1] * H[1] > 0;
      const double* M = full ? H : G;
      const double det = M[0] * M[2] - M[1] * M[1];
      if (det > 0)
        return {-(M[2] * g[0] - M[1] * g[1]) / det, -(M[0] * g[1] - M[1] * g[0]) / det};
      const double trace = G[0] + G[2];
      return trace > 0 ? std::array<double, 2>{-g[0] / trace, -g[1] / trace} : std::array<double, 2>{0.0, 0.0};
    }
    if (held.size() > 1)
      return {0.0, 0.0};
    // Along the side: d its direction, Newton's step in one variable.
    const double d[2] = {-held[0][1], held[0][0]};
    const auto quadratic = [&](const double* M) { return d[0] * d[0] * M[0] + 2 * d[0] * d[1] * M[1] + d[1] * d[1] * M[2]; };
    const double h = quadratic(H) > 0 ? quadratic(H) : quadratic(G);
    const double t = h > 0 ? -(g[0] * d[0] + g[1] * d[1]) / h : 0.0;
    return {t * d[0], t * d[1]};
  }

  // Near the minimum the squared distance changes by less than its
  // rounding (a parameter off by 1e-8 changes it by 1e-16 of itself): a
  // step is then judged by the gradient, which still shrinks quadratically.
  double rounding(const Local& l) const
  {
    return 1e-13 * (l.squared_distance + std::sqrt(l.squared_distance) * scale_);
  }

  // |gradient|² along what the domain's sides leave free.
  static double free_gradient2(const Local& l, const std::array<double, 2>& x, const Tile_domain& domain)
  {
    const double g[2] = {l.r * l.du, l.r * l.dv};
    std::vector<std::array<double, 3>> held;
    for (const auto& side : domain.sides)
      if (domain.blocks(side, x, g))
        held.push_back(side);
    if (held.empty())
      return g[0] * g[0] + g[1] * g[1];
    if (held.size() > 1)
      return 0;
    const double along = -g[0] * held[0][1] + g[1] * held[0][0];
    return along * along / (held[0][0] * held[0][0] + held[0][1] * held[0][1]);
  }

  // Newton's method in one tile from `start`, halving a step that brings
  // the point neither closer nor nearer stationary, until the step vanishes.
  Projection_result newton(const Surface& surface, std::uint32_t tile, const std::array<double, 2>& start,
                           const K::Point_3& q) const
  {
    const Projection_tile& t = tiles_[tile];
    const Tile_domain domain(t);
    std::array<double, 2> x = start;
    domain.snap(x);
    Local l = local(surface, t, x[0], x[1], q);
    for (int iteration = 0; iteration < 100; ++iteration) {
      const std::array<double, 2> step = newton_step(l, x, domain);
      if (std::abs(step[0]) + std::abs(step[1]) <= 1e-14 * t.size)
        break;
      bool closer = false;
      std::array<double, 2> y = x;
      for (double fraction = 1; fraction > 1e-6 && !closer; fraction /= 2) {
        y = {x[0] + fraction * step[0], x[1] + fraction * step[1]};
        domain.project(y);
        domain.snap(y);
        const Local m = local(surface, t, y[0], y[1], q);
        if (m.squared_distance < l.squared_distance || (m.squared_distance <= l.squared_distance + rounding(l) &&
                                                        free_gradient2(m, y, domain) < free_gradient2(l, x, domain))) {
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
  std::vector<std::size_t> grid_start_; // per tile, its first point
  std::vector<K::Point_3> points_;        // each tile's grid, row by row
  std::vector<Triangle_source> sources_;
  Tree tree_;
  double gap_ = 0, scale_ = 0;
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_PROJECTION_H
