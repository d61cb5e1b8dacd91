// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The one predicate that decides whether an edge may be collapsed to a given
// point: topology (the link condition and CGAL's guards), protected features,
// and the fold-over check, measured per dart so that it means something
// across Möbius edges. Decimation and remeshing both ask it.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_COLLAPSE_CHECKS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_COLLAPSE_CHECKS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/internal/Coordinate_checks.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <array>
#include <cmath>
#include <functional>

namespace CGAL_ext {
namespace internal {

/// What `check_collapse()` says of a collapse.
enum class Collapse_verdict {
  allowed,
  breaks_topology,     ///< the link condition or one of CGAL's guards fails
  protected_edge,      ///< the edge itself is protected
  moves_protected_end, ///< an end on a protected edge would move, or both ends are on protected edges
  folds_over,          ///< a surviving face's normal would turn by more than the bound
  degenerates          ///< a surviving face would lose its area
};

/// What `check_collapse()` protects and how far a face may turn.
struct Collapse_options
{
  /// Edges never collapsed; an end on one of them may not move. Empty: none.
  std::function<bool(Edge_index)> is_protected;
  /// The cosine of the largest turn allowed of a surviving face's normal:
  /// 0 allows up to 90 degrees, -1 any turn short of degenerating.
  double min_cos_normal_turn = 0.0;
  /// A face whose area after the move is at most this fraction of the
  /// squared longest side is degenerate.
  double min_relative_area = 1e-12;
};

using Point_d = std::array<double, 3>;

template <class Point>
Point_d to_point_d(const Point& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline Point_d cross_d(const Point_d& a, const Point_d& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Point_d minus_d(const Point_d& a, const Point_d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot_d(const Point_d& a, const Point_d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Twice the vector area of the polygon `ps` (Newell), and its longest squared side.
template <class Points>
std::pair<Point_d, double> newell_d(const Points& ps)
{
  Point_d n{0, 0, 0};
  double longest = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const Point_d& a = ps[i];
    const Point_d& b = ps[(i + 1) % ps.size()];
    const Point_d c = cross_d(minus_d(a, ps[0]), minus_d(b, ps[0]));
    n = {n[0] + c[0], n[1] + c[1], n[2] + c[2]};
    longest = (std::max)(longest, dot_d(minus_d(b, a), minus_d(b, a)));
  }
  return {n, longest};
}

template <class P>
bool touches_protected_edge(Vertex_index v, const Mobius_mesh<P>& m, const Collapse_options& o)
{
  for (Edge_index e : CGAL_ext::edges_around_target(m.halfedge(v), m))
    if (o.is_protected(e))
      return true;
  return false;
}

// The fold-over and degeneracy check of one face around an end of the edge of
// `d`: the face seen from its dart `c`, before and after both ends move to
// `moved`. The same dart walks the face before and after, so the comparison
// is of one side of the face, wherever the Möbius edges are.
template <class P>
Collapse_verdict check_face_after_move(Dart c, Vertex_index p, Vertex_index q, const Point_d& moved,
                                       const Mobius_mesh<P>& m, const Collapse_options& o)
{
  boost::container::small_vector<Point_d, 8> before, after;
  for (Vertex_index v : CGAL_ext::vertices_around_face(c, m)) {
    const Point_d x = to_point_d(m.point(v));
    before.push_back(x);
    const Point_d y = (v == p || v == q) ? moved : x;
    if (after.empty() || after.back() != y)
      after.push_back(y);
  }
  if (after.size() > 1 && after.front() == after.back())
    after.pop_back();
  if (after.size() < 3)
    return Collapse_verdict::degenerates;
  const auto [n0, longest0] = newell_d(before);
  const auto [n1, longest1] = newell_d(after);
  const double a1 = std::sqrt(dot_d(n1, n1));
  if (!(a1 > o.min_relative_area * longest1))
    return Collapse_verdict::degenerates;
  const double a0 = std::sqrt(dot_d(n0, n0));
  if (a0 > o.min_relative_area * longest0 && dot_d(n0, n1) < o.min_cos_normal_turn * a0 * a1)
    return Collapse_verdict::folds_over;
  return Collapse_verdict::allowed;
}

/// Whether collapsing the edge of `d` (`source(d)` joined into `target(d)`,
/// as `Euler::collapse_edge(d)` does) with the kept vertex moved to
/// `new_point` is allowed:
///
/// - topology: `Euler::does_satisfy_link_condition(d)`, which holds CGAL's
///   guards too (no border loop of three sides closes, no closed component
///   shrinks below a tetrahedron, no two triangles become one);
/// - features: a protected edge is never collapsed; an end on a protected
///   edge may not move, so `new_point` must be that end's point; both ends
///   on protected edges, the edge itself not, is refused;
/// - geometry (in double): every face that survives around either end keeps
///   a normal that turns by at most the bound of `options`, seen from one
///   fixed dart before and after, and does not degenerate.
///
/// Refusals are cheap to ask for: the mesh is not changed.
template <class P>
Collapse_verdict check_collapse(Dart d, const P& new_point, const Mobius_mesh<P>& m, const Collapse_options& options)
{
  if (options.is_protected && options.is_protected(m.edge(d)))
    return Collapse_verdict::protected_edge;
  if (!Euler::does_satisfy_link_condition(d, m))
    return Collapse_verdict::breaks_topology;
  const Vertex_index p = m.source(d), q = m.target(d);
  if (options.is_protected) {
    const bool fixed_p = touches_protected_edge(p, m, options), fixed_q = touches_protected_edge(q, m, options);
    if ((fixed_p && fixed_q) || (fixed_p && new_point != m.point(p)) || (fixed_q && new_point != m.point(q)))
      return Collapse_verdict::moves_protected_end;
  }
  const Point_d moved = to_point_d(new_point);
  for (Vertex_index end : {p, q}) {
    for (Dart c : CGAL_ext::halfedges_around_target(end == q ? d : m.opposite(d), m)) {
      if (m.is_border(c))
        continue;
      const Face_index f = m.face(c);
      // A triangle of the edge goes with it; a larger face of the edge loses a corner.
      bool has_both = false;
      for (Vertex_index v : CGAL_ext::vertices_around_face(c, m))
        has_both = has_both || (v == (end == p ? q : p));
      if (has_both && m.degree(f) == 3)
        continue;
      if (has_both && end == q)
        continue; // already checked from p's side
      const Collapse_verdict verdict = check_face_after_move(c, p, q, moved, m, options);
      if (verdict != Collapse_verdict::allowed)
        return verdict;
    }
  }
  return Collapse_verdict::allowed;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_COLLAPSE_CHECKS_H
