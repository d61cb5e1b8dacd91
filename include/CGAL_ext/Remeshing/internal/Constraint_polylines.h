// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The protected polylines of a mesh (borders, sharp edges) cut at their
// corners and measured by arc length, so that isotropic_remeshing() can
// slide their vertices along them (CGAL's relax_constraints).

#ifndef CGAL_EXT_REMESHING_INTERNAL_CONSTRAINT_POLYLINES_H
#define CGAL_EXT_REMESHING_INTERNAL_CONSTRAINT_POLYLINES_H

#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Where one vertex of a polyline is asked to go: `offset` along its chain.
struct Polyline_move
{
  std::size_t chain;
  std::size_t position;
  double offset;
};

// The polylines that protected edges form, each chain running from corner to
// corner (or round a loop that has none) over the points it had when it was
// built. Its vertices stay the same mesh vertices for as long as the edges
// stay protected (never split, collapsed or flipped), so a vertex slides by
// changing its arc length on the chain: it stays on the input's polyline
// exactly, between its two neighbours, and never passes a corner. A nearest
// point query on the input's segments would not promise that: next to a
// corner or where two parts of a curve come close, it may jump.
class Constraint_polylines
{
public:
  using Point = CGAL::Simple_cartesian<double>::Point_3;

  // A vertex on other than two protected edges is a corner, and so is one
  // where its polyline turns by more than 60 degrees: CGAL's
  // tangential_relaxation() leaves those (its cosine test, 0.25 < cos²).
  static constexpr double smooth_turn_cosine = 0.5;

  // `is_constrained(e)` tells the protected edges, `point_of(v)` a vertex's
  // point in double. The chains are walked dart by dart, so a border loop
  // that passes a Möbius edge is one chain, as it is one curve.
  template <class P, class IsConstrained, class PointOf>
  Constraint_polylines(const Mobius_mesh<P>& mesh, const IsConstrained& is_constrained, const PointOf& point_of)
  {
    std::vector<char> corner(mesh.num_vertices(), 0), visited(mesh.num_edges(), 0);
    for (Vertex_index v : mesh.vertices())
      corner[v.idx()] = is_corner(v, mesh, is_constrained, point_of);
    for (Vertex_index v : mesh.vertices())
      if (corner[v.idx()])
        for (Dart d : constrained_darts_into(v, mesh, is_constrained))
          if (!visited[mesh.edge(d).idx()])
            add_chain(v, d, mesh, is_constrained, point_of, corner, visited);
    // What is left are loops without a corner.
    for (Edge_index e : mesh.edges())
      if (is_constrained(e) && !visited[e.idx()]) {
        const Dart d = Mobius_mesh<P>::halfedge(e);
        add_chain(mesh.target(d), d, mesh, is_constrained, point_of, corner, visited);
      }
  }

  // CGAL's 1D weights, 1/2 for the vertex and 1/4 for each neighbour on its
  // polyline, taken along the curve: all computed from the same positions,
  // as CGAL does, which keeps the order of the vertices along each chain.
  std::vector<Polyline_move> relaxation_moves() const
  {
    std::vector<Polyline_move> moves;
    for (std::size_t k = 0; k < chains_.size(); ++k) {
      const Chain& c = chains_[k];
      const std::size_t n = c.vertices.size();
      const std::size_t first = c.periodic ? 0 : 1, end = c.periodic ? n : n - 1;
      for (std::size_t i = first; i < end; ++i) {
        const double before = i > 0 ? c.at[i - 1] : c.at[n - 1] - c.length();
        const double after = i + 1 < n ? c.at[i + 1] : c.at[0] + c.length();
        const double offset = 0.25 * (before + after) - 0.5 * c.at[i];
        if (offset != 0)
          moves.push_back({k, i, offset});
      }
    }
    return moves;
  }

  Vertex_index vertex(const Polyline_move& m) const { return chains_[m.chain].vertices[m.position]; }

  // The point `fraction` of the move would take its vertex to.
  Point point_after(const Polyline_move& m, double fraction) const
  {
    const Chain& c = chains_[m.chain];
    return c.point_at(c.at[m.position] + fraction * m.offset);
  }

  void commit(const Polyline_move& m, double fraction) { chains_[m.chain].at[m.position] += fraction * m.offset; }

private:
  struct Chain
  {
    std::vector<Point> points;         // of the input, the first repeated at the end of a loop
    std::vector<double> arc;           // the arc length at each point
    std::vector<Vertex_index> vertices; // a loop's first is not repeated
    std::vector<double> at;            // each vertex's arc length now; a loop's may leave [0, length)
    bool periodic = false;

    double length() const { return arc.back(); }

    Point point_at(double s) const
    {
      const double total = length();
      if (periodic && total > 0)
        s -= std::floor(s / total) * total;
      s = std::clamp(s, 0.0, total);
      const std::size_t i =
        std::min<std::size_t>(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin(), arc.size() - 1);
      if (i == 0)
        return points.front();
      const double span = arc[i] - arc[i - 1];
      const double t = span > 0 ? (s - arc[i - 1]) / span : 0;
      return points[i - 1] + t * (points[i] - points[i - 1]);
    }
  };

  template <class P, class IsConstrained>
  static std::vector<Dart> constrained_darts_into(Vertex_index v, const Mobius_mesh<P>& mesh,
                                                  const IsConstrained& is_constrained)
  {
    std::vector<Dart> darts;
    if (!mesh.is_isolated(v))
      for (Dart d : CGAL_ext::halfedges_around_target(v, mesh))
        if (is_constrained(mesh.edge(d)))
          darts.push_back(d);
    return darts;
  }

  template <class P, class IsConstrained, class PointOf>
  static bool is_corner(Vertex_index v, const Mobius_mesh<P>& mesh, const IsConstrained& is_constrained,
                        const PointOf& point_of)
  {
    const std::vector<Dart> darts = constrained_darts_into(v, mesh, is_constrained);
    if (darts.empty())
      return false;
    if (darts.size() != 2)
      return true;
    const Point p = point_of(v);
    const auto in = p - point_of(mesh.source(darts[0])), out = point_of(mesh.source(darts[1])) - p;
    const double dot = in * out;
    return !(dot > 0 && dot * dot > smooth_turn_cosine * smooth_turn_cosine * in.squared_length() * out.squared_length());
  }

  // Walks from `start` along the protected edge of `into` (a dart that ends
  // at `start`) to the next corner, or back to `start` round a loop.
  template <class P, class IsConstrained, class PointOf>
  void add_chain(Vertex_index start, Dart into, const Mobius_mesh<P>& mesh, const IsConstrained& is_constrained,
                 const PointOf& point_of, const std::vector<char>& corner, std::vector<char>& visited)
  {
    Chain c;
    c.points.push_back(point_of(start));
    c.arc.push_back(0);
    c.vertices.push_back(start);
    Vertex_index v = mesh.source(into);
    Edge_index via = mesh.edge(into);
    for (;;) {
      visited[via.idx()] = 1;
      c.points.push_back(point_of(v));
      c.arc.push_back(c.arc.back() + std::sqrt(CGAL::squared_distance(c.points[c.points.size() - 2], c.points.back())));
      if (v == start || corner[v.idx()])
        break;
      c.vertices.push_back(v);
      const Dart next = other_constrained_dart(v, via, mesh, is_constrained);
      via = mesh.edge(next);
      v = mesh.source(next);
    }
    c.periodic = !corner[start.idx()];
    if (!c.periodic) // the end corner, which may be the start again
      c.vertices.push_back(v);
    c.at = c.arc;
    c.at.resize(c.vertices.size());
    chains_.push_back(std::move(c));
  }

  // The dart into v along its other protected edge (v has two, not being a corner).
  template <class P, class IsConstrained>
  static Dart other_constrained_dart(Vertex_index v, Edge_index via, const Mobius_mesh<P>& mesh,
                                     const IsConstrained& is_constrained)
  {
    for (Dart d : constrained_darts_into(v, mesh, is_constrained))
      if (mesh.edge(d) != via)
        return d;
    CGAL_assertion(false);
    return Dart();
  }

  std::vector<Chain> chains_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_REMESHING_INTERNAL_CONSTRAINT_POLYLINES_H
