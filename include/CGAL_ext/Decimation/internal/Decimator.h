// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The decimation loop of decimate(): edge collapses, cheapest first by
// Garland–Heckbert quadric error, each checked before it is made.

#ifndef CGAL_EXT_DECIMATION_INTERNAL_DECIMATOR_H
#define CGAL_EXT_DECIMATION_INTERNAL_DECIMATOR_H

#include <CGAL_ext/Decimation/Decimation_result.h>
#include <CGAL_ext/Decimation/internal/Attribute_quadrics.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_edits.h>
#include <CGAL_ext/Decimation/internal/Decimation_settings.h>
#include <CGAL_ext/Decimation/internal/Quadric.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Sharp_feature_options.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Modifiable_priority_queue.h>
#include <CGAL/assertions.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Where an edge would collapse to, and at what cost.
struct Collapse_candidate
{
  double cost = 0;                 // the quadric's value at the point: the priority
  Point_d point{};                 // in double, unless at an end
  Vertex_index at_end;             // the end whose exact point is the placement, if any
};

// The Garland–Heckbert state of a decimation: per-vertex quadrics and plane
// areas, feature flags and costs per edge, CGAL's modifiable priority queue
// of the edges by cost (one entry per edge, updated in place), the corner
// channels' seams and merges (Corner_channel_edits.h) and their values'
// quadrics (Attribute_quadrics.h).
template <class P>
class Decimator
{
public:
  Decimator(Mobius_mesh<P>& mesh, const Decimation_settings& settings, std::vector<char> feature)
    : m_(mesh), s_(settings), feature_(std::move(feature)), cost_(mesh.num_edges(), 0.0),
      refused_(mesh.num_edges(), 0), quadric_(mesh.num_vertices()), area_(mesh.num_vertices(), 0.0),
      queue_(mesh.num_edges(), Cheaper{&cost_}), corners_(mesh, feature_),
      values_(mesh, corners_, settings.corner_value_weight)
  {
    options_.min_cos_normal_turn = settings.min_cos_normal_turn;
    options_.is_protected = [this](Edge_index e) { return feature_[e.idx()] != 0; };
    if (auto own = mesh.template property_map<Edge_index, float>(edge_sharpness_name))
      sharpness_ = *own;
    init_quadrics();
  }
  // The queue's order reads cost_ through a pointer: not to be copied or moved.
  Decimator(const Decimator&) = delete;
  Decimator& operator=(const Decimator&) = delete;

  Decimation_result run()
  {
    Decimation_result result;
    result.faces_before = m_.number_of_faces();
    for (Edge_index e : m_.edges())
      push(e);
    while (m_.number_of_faces() > s_.target_faces && !queue_.empty()) {
      const Edge_index top = queue_.top_and_pop();
      CGAL_assertion(!m_.is_removed(top));
      const Collapse_candidate c = candidate(top);
      const double error = error_of(top, c);
      if (error > s_.maximum_error)
        break;
      if (collapse(top, c)) {
        ++result.collapses;
        result.largest_error = (std::max)(result.largest_error, error);
      }
    }
    result.faces_after = m_.number_of_faces();
    return result;
  }

  // The feature flags by edge index, as the collapses left them (a merged
  // edge keeps the flag of either side); the decimator is done with them.
  std::vector<char> take_features() { return std::move(feature_); }

private:
  // The queue's order: the cheapest edge on top.
  struct Cheaper
  {
    const std::vector<double>* cost;
    bool operator()(Edge_index a, Edge_index b) const { return (*cost)[a.idx()] < (*cost)[b.idx()]; }
  };
  // The queue's index of an edge.
  struct Edge_id
  {
    using key_type = Edge_index;
    using value_type = std::size_t;
    using reference = std::size_t;
    using category = boost::readable_property_map_tag;
    friend std::size_t get(Edge_id, Edge_index e) { return e.idx(); }
  };

  void init_quadrics()
  {
    for (Face_index f : m_.faces()) {
      const Dart d = m_.halfedge(f);
      const Point_d a = pt(m_.source(d)), b = pt(m_.target(d)), c = pt(m_.target(m_.next(d)));
      const Point_d n = cross_d(minus_d(b, a), minus_d(c, a));
      const double area = 0.5 * std::sqrt(dot_d(n, n));
      const Quadric q = Quadric::of_plane(n, a, area);
      for (Vertex_index v : CGAL_ext::vertices_around_face(d, m_)) {
        quadric_[v.idx()] += q;
        area_[v.idx()] += area;
      }
      // A border edge: the plane through it perpendicular to its face holds
      // the border in place, weighted heavily as Garland and Heckbert do.
      for (Dart s : CGAL_ext::halfedges_around_face(d, m_)) {
        if (!m_.is_border(m_.opposite(s)))
          continue;
        const Point_d p = pt(m_.source(s)), t = pt(m_.target(s));
        const Point_d along = minus_d(t, p);
        const Quadric border = Quadric::of_plane(cross_d(along, n), p, border_weight * dot_d(along, along));
        quadric_[m_.source(s).idx()] += border;
        quadric_[m_.target(s).idx()] += border;
      }
    }
  }

  Point_d pt(Vertex_index v) const { return to_point_d(m_.point(v)); }

  // What the corner values add to the cost of collapsing d: the attribute
  // quadrics of its ends off the seams (a seam vertex keeps its values, and
  // its faces hold several), at the values the collapse keeps or makes:
  // `kept`'s where it keeps that end's (it is on a seam, or the point is its
  // own), else those that agree at both ends, else the best.
  Quadric values_residual(Dart d, Vertex_index kept = Vertex_index()) const
  {
    if (values_.empty())
      return Quadric();
    const Vertex_index p = m_.source(d), q = m_.target(d);
    const bool seam_p = corners_.is_seam_vertex(p), seam_q = corners_.is_seam_vertex(q);
    if (seam_p && seam_q)
      return Quadric();
    const Dart a = corners_.dart_along(d, kept.is_valid() ? kept : p);
    const Dart b = corners_.dart_along(d, kept.is_valid() ? kept : q);
    if (seam_p || seam_q)
      return values_.residual({seam_p ? q : p}, a, b);
    return values_.residual({p, q}, a, b);
  }

  bool fixed(Vertex_index v) const
  {
    for (Edge_index e : CGAL_ext::edges_around_target(m_.halfedge(v), m_))
      if (feature_[e.idx()])
        return true;
    return false;
  }

  // The placement of the edge's collapse: at a fixed end if there is one,
  // else the quadric's minimiser nearest the edge's midpoint.
  Collapse_candidate candidate(Edge_index e) const
  {
    const Dart d = m_.halfedge(e);
    const Vertex_index p = m_.source(d), q = m_.target(d);
    const Quadric points = quadric_[p.idx()] + quadric_[q.idx()];
    Collapse_candidate c;
    const bool fp = fixed(p), fq = fixed(q);
    if (fp || fq) {
      // A seam vertex keeps its place, so that its corners keep their values.
      const Vertex_index seam = corners_.seam_end(d);
      c.at_end = seam.is_valid() ? seam : fp ? p : q;
      c.point = pt(c.at_end);
      c.cost = (points + values_residual(d, c.at_end))(c.point);
      return c;
    }
    const Quadric sum = points + values_residual(d);
    const Point_d a = pt(p), b = pt(q);
    const Point_d mid{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
    const int determined = sum.minimizer_near(mid, c.point);
    c.cost = sum(c.point);
    if (determined < 3)
      return c;
    // Where the planes meet in a point, an end as good as the minimiser up
    // to rounding is taken instead, so that corners stay exactly in place.
    const Point_d ab = minus_d(b, a);
    const double rounding = 1e-12 * (sum.a[0] + sum.a[3] + sum.a[5]) * dot_d(ab, ab);
    for (Vertex_index end : {p, q}) {
      const double cost = (points + values_residual(d, end))(pt(end)); // the end's values kept
      if (cost <= c.cost + rounding) {
        c.cost = cost;
        c.at_end = end;
        c.point = pt(end);
        break;
      }
    }
    return c;
  }

  // The error of collapsing `e` to `c`: the quadric's value at the
  // placement divided by the area of the faces whose planes it sums, an
  // area-weighted mean squared distance. The queue is ordered by it, not by
  // the quadric's value itself: that grows with the area a vertex stands for,
  // so it would favour collapses where the input's faces are small rather
  // than where the surface is flat (on a torus of unequal faces, the inside
  // of the ring first, where it is most curved).
  double error_of(Edge_index e, const Collapse_candidate& c) const
  {
    const Dart d = m_.halfedge(e);
    return c.cost / (std::max)(area_[m_.source(d).idx()] + area_[m_.target(d).idx()],
                               std::numeric_limits<double>::min());
  }

  // Queues `e` at its current cost, or moves it there if it is queued.
  void push(Edge_index e)
  {
    if (feature_[e.idx()])
      return; // a feature edge is never collapsed
    if (!corners_.can_collapse(m_.halfedge(e))) {
      // Nor is an edge between two seam vertices, perhaps queued before a
      // collapse made one end a seam vertex.
      if (queue_.contains(e))
        queue_.erase(e);
      return;
    }
    cost_[e.idx()] = error_of(e, candidate(e));
    if (queue_.contains(e))
      queue_.update(e);
    else
      queue_.push(e);
  }

  P placement(const Collapse_candidate& c) const
  {
    return c.at_end.is_valid() ? m_.point(c.at_end) : P(c.point[0], c.point[1], c.point[2]);
  }

  // The dart from `a` into `b`, or the null dart if they are not adjacent.
  Dart dart_from_to(Vertex_index a, Vertex_index b) const
  {
    for (Dart c : CGAL_ext::halfedges_around_target(m_.halfedge(b), m_))
      if (m_.source(c) == a)
        return c;
    return Dart();
  }

  bool collapse(Edge_index e, const Collapse_candidate& c);
  void check_star(Vertex_index v) const;

  static constexpr double border_weight = 100; // CGAL's default discontinuity multiplier

  Mobius_mesh<P>& m_;
  Decimation_settings s_;
  std::vector<char> feature_;
  std::vector<double> cost_; // error_of() each queued edge's candidate
  std::vector<char> refused_; // edges whose last try was refused: tried again when their neighbourhood changes
  std::vector<Quadric> quadric_;
  std::vector<double> area_;
  std::optional<typename Mobius_mesh<P>::template Property_map<Edge_index, float>> sharpness_;
  Collapse_options options_;
  CGAL::Modifiable_priority_queue<Edge_index, Cheaper, Edge_id> queue_;
  Corner_channel_edits<P> corners_; // after feature_, to which it adds the seams
  Attribute_quadrics<P> values_;    // after corners_, which reads the values
};

// Collapses the edge `e` to `c` if check_collapse() allows it one way or the
// other, then updates the kept vertex's quadric and requeues its edges and
// its neighbours' (whose fold-over verdicts may have changed).
template <class P>
bool Decimator<P>::collapse(Edge_index e, const Collapse_candidate& c)
{
  const P point = placement(c);
  Dart d = m_.halfedge(e);
  if (check_collapse(d, point, m_, options_) != Collapse_verdict::allowed) {
    d = m_.opposite(d);
    if (check_collapse(d, point, m_, options_) != Collapse_verdict::allowed) {
      refused_[e.idx()] = 1;
      return false;
    }
  }
  const Vertex_index p = m_.source(d), q = m_.target(d);
  std::vector<Vertex_index> apexes;
  std::vector<Edge_index> sides; // per apex: its edges to p and to q
  for (Dart side : {d, m_.opposite(d)})
    if (!m_.is_border(side) && m_.degree(m_.face(side)) == 3) {
      apexes.push_back(m_.target(m_.next(side)));
      sides.push_back(m_.edge(dart_from_to(p, apexes.back())));
      sides.push_back(m_.edge(dart_from_to(q, apexes.back())));
    }
  std::vector<std::pair<char, float>> side_values; // read before the collapse removes one of each pair
  for (Edge_index s : sides)
    side_values.emplace_back(feature_[s.idx()], sharpness_ ? (*sharpness_)[s] : 0.f);
  std::vector<std::vector<double>> fitted; // the merged values, where neither end is on a seam
  if (!corners_.is_seam_vertex(p) && !corners_.is_seam_vertex(q))
    fitted = values_.fitted({p, q}, to_point_d(point));
  const typename Corner_channel_edits<P>::Plan corner_plan = corners_.plan(d, point, &fitted); // read before the collapse
  Euler::collapse_edge(d, m_, Euler::unchecked); // check_collapse() checked the link condition
  corners_.apply(corner_plan, q);
  corners_.merge_flags(p, q);
  for (Edge_index s : sides) // one side of each collapsed triangle is gone
    if (m_.is_removed(s) && queue_.contains(s))
      queue_.erase(s);
  m_.points()[q] = point;
  quadric_[q.idx()] += quadric_[p.idx()];
  values_.merge(p, q);
  area_[q.idx()] += area_[p.idx()];
  // The two sides of a collapsed triangle become one edge: a feature if either was.
  for (std::size_t i = 0; i < apexes.size(); ++i) {
    const Dart s = dart_from_to(q, apexes[i]);
    if (!s.is_valid())
      continue;
    const Edge_index kept = m_.edge(s);
    feature_[kept.idx()] = side_values[2 * i].first || side_values[2 * i + 1].first;
    if (sharpness_)
      (*sharpness_)[kept] = (std::max)(side_values[2 * i].second, side_values[2 * i + 1].second);
  }
  CGAL_assertion_code(check_star(q);)
  for (Dart c : CGAL_ext::halfedges_around_target(m_.halfedge(q), m_)) {
    refused_[m_.edge(c).idx()] = 0;
    push(m_.edge(c));
  }
  for (Vertex_index w : CGAL_ext::vertices_around_target(m_.halfedge(q), m_))
    for (Edge_index f : CGAL_ext::edges_around_target(m_.halfedge(w), m_))
      if (refused_[f.idx()]) {
        refused_[f.idx()] = 0;
        push(f);
      }
  return true;
}

// The local validity of the star of `v` after a collapse, in debug builds (a
// full is_valid() per step would make decimation quadratic): every dart into
// v comes back to v round its face, its faces are triangles, and no
// neighbour appears twice.
template <class P>
void Decimator<P>::check_star(Vertex_index v) const
{
  std::vector<Vertex_index> ring;
  for (Dart c : CGAL_ext::halfedges_around_target(m_.halfedge(v), m_)) {
    CGAL_assertion(m_.target(c) == v);
    CGAL_assertion(!m_.is_removed(m_.edge(c)));
    if (!m_.is_border(c)) {
      CGAL_assertion(m_.degree(m_.face(c)) == 3);
      CGAL_assertion(m_.target(m_.next(m_.next(m_.next(c)))) == v);
    }
    ring.push_back(m_.source(c));
  }
  std::sort(ring.begin(), ring.end());
  CGAL_assertion(std::adjacent_find(ring.begin(), ring.end()) == ring.end());
  CGAL_assertion(ring.size() >= 2);
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_INTERNAL_DECIMATOR_H
