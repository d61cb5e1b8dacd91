// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// After a decimation: vertices moved to lower the largest distance between
// the result and its input, measured with an AABB tree of the input.

#ifndef CGAL_EXT_DECIMATION_INTERNAL_DISTANCE_RELOCATION_H
#define CGAL_EXT_DECIMATION_INTERNAL_DISTANCE_RELOCATION_H

#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/assertions.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL_ext {
namespace internal {

// A triangle mesh copied as points and index triples in double, with an
// AABB tree whose primitives are triangle numbers: the tree makes each
// triangle from the points when it needs it, so it holds no copy of them
// (an AABB_triangle_primitive over Triangle_3s would add 72 bytes per triangle).
class Input_triangles
{
public:
  using K = CGAL::Simple_cartesian<double>;
  using Point = K::Point_3;

  // `mesh` must be a triangle mesh without removed elements.
  template <class P>
  explicit Input_triangles(const Mobius_mesh<P>& mesh)
  {
    points_.reserve(mesh.number_of_vertices());
    for (Vertex_index v : mesh.vertices()) {
      const P& p = mesh.point(v);
      points_.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    triangles_.reserve(mesh.number_of_faces());
    for (Face_index f : mesh.faces()) {
      const Dart d = mesh.halfedge(f);
      triangles_.push_back({std::uint32_t(mesh.source(d).idx()), std::uint32_t(mesh.target(d).idx()),
                            std::uint32_t(mesh.target(mesh.next(d)).idx())});
    }
  }
  Input_triangles(const Input_triangles&) = delete;
  Input_triangles& operator=(const Input_triangles&) = delete;

  // Built apart from the copy, so that the caller can build it once what it
  // no longer needs is freed. Queries take a hint, a point of the input near
  // the answer, in place of the k-d tree that accelerate_distance_queries()
  // would build (40 bytes more per triangle).
  void build_tree()
  {
    tree_ = std::make_unique<Tree>(boost::counting_iterator<std::uint32_t>(0),
                                   boost::counting_iterator<std::uint32_t>(std::uint32_t(triangles_.size())), this);
    tree_->build();
  }
  // Input vertex i, a point of the input: a hint for points near it.
  const Point& point(std::size_t i) const { return points_[i]; }
  std::size_t number_of_points() const { return points_.size(); }
  // The closest point to p on the input; `hint` must be a point of the input.
  Point closest_point(const Point& p, const Point& hint) const { return tree_->closest_point(p, hint); }

private:
  // CGAL's AABBPrimitiveWithSharedData: the shared data is the copy itself.
  struct Primitive
  {
    using Id = std::uint32_t;
    using Point = K::Point_3;
    using Datum = K::Triangle_3;
    using Shared_data = const Input_triangles*;

    Primitive() = default;
    Primitive(boost::counting_iterator<std::uint32_t> it, const Input_triangles*) : id_(*it) {}
    Id id() const { return id_; }
    Datum datum(Shared_data s) const
    {
      const auto& t = s->triangles_[id_];
      return Datum(s->points_[t[0]], s->points_[t[1]], s->points_[t[2]]);
    }
    Point reference_point(Shared_data s) const { return s->points_[s->triangles_[id_][0]]; }
    static Shared_data construct_shared_data(const Input_triangles* s) { return s; }

    Id id_ = 0;
  };
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

  std::vector<Point> points_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::unique_ptr<Tree> tree_;
};

// Moves vertices of a decimated triangle mesh to lower the largest distance
// to its input. A decimation's quadrics measure the distance at the
// vertices; the largest distance lies inside the triangles, and where the
// surface bends little along a long edge (the top of a torus' tube, along
// its circle) the quadrics barely see it. The residual of a point of the
// result is the vector to it from its closest point on the input; each
// movable vertex, where its star's residuals are among the largest, moves
// along the residuals' main direction (orientation-free, so one-sided stars
// need no normal) by the step that minimises the largest residual of its
// star in the linear model (a sample at barycentric weight w moves w times as
// far), and the move is kept only if the star's measured largest residual
// went down and no face turned over. Samples: the vertices, the edges'
// midpoints and the faces' centroids.
//
// Vertex v's first hint is input vertex origin[v], a point of the input near
// it (for a decimation: the vertex of the same index before the garbage
// collection).
template <class P>
class Distance_relocation
{
  using Point = Input_triangles::Point;
  using Vector = Input_triangles::K::Vector_3;

public:
  // `movable[v]` says whether vertex v may move; border and isolated vertices never do.
  Distance_relocation(Mobius_mesh<P>& mesh, const Input_triangles& input, std::vector<std::uint32_t> origin,
                      std::vector<char> movable)
    : m_(mesh), input_(input), origin_(std::move(origin)), movable_(std::move(movable))
  {
    CGAL_precondition(origin_.size() == mesh.num_vertices() && movable_.size() == mesh.num_vertices());
    for (Vertex_index v : m_.vertices()) {
      CGAL_precondition(origin_[v.idx()] < input.number_of_points());
      movable_[v.idx()] = movable_[v.idx()] && !m_.is_border(v) && !m_.is_isolated(v);
    }
  }

  // Relocates for at most `passes` passes; returns the number of moves kept.
  std::size_t run(int passes)
  {
    near_vertex_.resize(m_.num_vertices());
    near_edge_.resize(m_.num_edges());
    near_face_.resize(m_.num_faces());
    for (Vertex_index v : m_.vertices())
      near_vertex_[v.idx()] = input_.closest_point(point(v), input_.point(origin_[v.idx()]));
    for (Edge_index e : m_.edges())
      near_edge_[e.idx()] = input_.closest_point(midpoint(e), near_vertex_[m_.vertex(e, 0).idx()]);
    for (Face_index f : m_.faces())
      near_face_[f.idx()] = input_.closest_point(centroid(f), near_vertex_[m_.target(m_.halfedge(f)).idx()]);
    double coordinate = 0;
    for (Vertex_index v : m_.vertices()) {
      const Point p = point(v);
      coordinate = (std::max)({coordinate, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
    }
    std::size_t moves = 0;
    for (int pass = 0; pass < passes; ++pass) {
      std::size_t moved = 0;
      for (Vertex_index v : worst_stars(negligible * coordinate))
        moved += relocate(v);
      moves += moved;
      if (moved == 0)
        break;
    }
    return moves;
  }

private:
  // What counts as a distance: below a 10^12th of the largest coordinate it
  // is the rounding of the closest points, and exact results (a cube's
  // corners) are left as they are.
  static constexpr double negligible = 1e-12;
  // Stars whose largest residual is at least this share of the mesh's largest are moved.
  static constexpr double worst_share = 0.7;

  Point point(Vertex_index v) const
  {
    const P& p = m_.point(v);
    return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  Point midpoint(Edge_index e) const { return CGAL::midpoint(point(m_.vertex(e, 0)), point(m_.vertex(e, 1))); }
  Point centroid(Face_index f) const
  {
    const Dart d = m_.halfedge(f);
    return CGAL::centroid(point(m_.source(d)), point(m_.target(d)), point(m_.target(m_.next(d))));
  }
  Vector vertex_residual(Vertex_index v) const { return point(v) - near_vertex_[v.idx()]; }
  Vector edge_residual(Edge_index e) const { return midpoint(e) - near_edge_[e.idx()]; }
  Vector face_residual(Face_index f) const { return centroid(f) - near_face_[f.idx()]; }

  // The largest residual length in the star of v, over the samples it moves.
  double star_largest(Vertex_index v) const
  {
    double largest = vertex_residual(v).squared_length();
    for (Dart d : CGAL_ext::halfedges_around_target(v, m_)) {
      largest = (std::max)(largest, edge_residual(m_.edge(d)).squared_length());
      if (!m_.is_border(d))
        largest = (std::max)(largest, face_residual(m_.face(d)).squared_length());
    }
    return std::sqrt(largest);
  }

  // The movable vertices whose stars hold the largest residuals, worst
  // first; none once the largest is not above `floor`.
  std::vector<Vertex_index> worst_stars(double floor) const
  {
    std::vector<double> largest(m_.num_vertices(), 0);
    double mesh_largest = 0;
    for (Vertex_index v : m_.vertices())
      if (movable_[v.idx()])
        mesh_largest = (std::max)(mesh_largest, largest[v.idx()] = star_largest(v));
    std::vector<Vertex_index> order;
    if (!(mesh_largest > floor))
      return order;
    for (Vertex_index v : m_.vertices())
      if (movable_[v.idx()] && largest[v.idx()] >= worst_share * mesh_largest)
        order.push_back(v);
    std::sort(order.begin(), order.end(),
              [&](Vertex_index a, Vertex_index b) { return largest[a.idx()] > largest[b.idx()]; });
    return order;
  }

  struct Sample
  {
    Vector residual;
    double weight; // how far it moves when the vertex moves by 1
  };

  // The main direction of the residuals (the top eigenvector of the sum of
  // their outer products, by power iteration from the longest): a residual
  // and its opposite count alike.
  static Vector main_direction(const std::vector<Sample>& samples)
  {
    Vector u(0, 0, 0);
    for (const Sample& s : samples)
      if (s.residual.squared_length() > u.squared_length())
        u = s.residual;
    for (int i = 0; i < 8 && u.squared_length() > 0; ++i) {
      Vector next(0, 0, 0);
      for (const Sample& s : samples)
        next = next + (s.residual * u) * s.residual;
      u = next / std::sqrt(next.squared_length());
    }
    return u;
  }

  // The step along u that minimises the largest |r + w t u| of the samples,
  // a convex function of t: ternary search within three times the largest residual.
  static double best_step(const std::vector<Sample>& samples, const Vector& u, double largest)
  {
    const auto worst = [&](double t) {
      double w = 0;
      for (const Sample& s : samples)
        w = (std::max)(w, (s.residual + (s.weight * t) * u).squared_length());
      return w;
    };
    double low = -3 * largest, high = 3 * largest;
    for (int i = 0; i < 60; ++i) { // (2/3)^60: a 10^-11th of the interval
      const double a = low + (high - low) / 3, b = high - (high - low) / 3;
      if (worst(a) < worst(b))
        high = b;
      else
        low = a;
    }
    const double t = (low + high) / 2;
    return worst(t) < worst(0) ? t : 0;
  }

  // Tries one move of v; keeps it if its star's largest residual went down
  // and none of its faces turned over. The closest points before the move
  // are the hints of those after it.
  bool relocate(Vertex_index v)
  {
    std::vector<Sample> samples{{vertex_residual(v), 1.0}};
    edges_.clear();
    faces_.clear();
    for (Dart d : CGAL_ext::halfedges_around_target(v, m_)) {
      edges_.push_back(m_.edge(d));
      samples.push_back({edge_residual(edges_.back()), 0.5});
      if (!m_.is_border(d)) {
        faces_.push_back(m_.face(d));
        samples.push_back({face_residual(faces_.back()), 1.0 / 3});
      }
    }
    const double before = star_largest(v);
    const Vector u = main_direction(samples);
    const double t = u.squared_length() > 0 ? best_step(samples, u, before) : 0;
    if (t == 0)
      return false;
    normals_.clear();
    for (Face_index f : faces_)
      normals_.push_back(face_vector(f));
    const P old = m_.point(v);
    const Point old_near_vertex = near_vertex_[v.idx()];
    was_edge_.clear();
    was_face_.clear();
    const Point moved = point(v) + t * u;
    m_.point(v) = P(moved.x(), moved.y(), moved.z());
    near_vertex_[v.idx()] = input_.closest_point(moved, old_near_vertex);
    for (Edge_index e : edges_) {
      was_edge_.push_back(near_edge_[e.idx()]);
      near_edge_[e.idx()] = input_.closest_point(midpoint(e), was_edge_.back());
    }
    for (Face_index f : faces_) {
      was_face_.push_back(near_face_[f.idx()]);
      near_face_[f.idx()] = input_.closest_point(centroid(f), was_face_.back());
    }
    bool kept = star_largest(v) < before;
    for (std::size_t i = 0; kept && i < faces_.size(); ++i)
      kept = face_vector(faces_[i]) * normals_[i] > 0;
    if (kept)
      return true;
    m_.point(v) = old;
    near_vertex_[v.idx()] = old_near_vertex;
    for (std::size_t i = 0; i < edges_.size(); ++i)
      near_edge_[edges_[i].idx()] = was_edge_[i];
    for (std::size_t i = 0; i < faces_.size(); ++i)
      near_face_[faces_[i].idx()] = was_face_[i];
    return false;
  }

  // The normal of triangle f in its own orientation (its length twice its area).
  Vector face_vector(Face_index f) const
  {
    const Dart d = m_.halfedge(f);
    const Point a = point(m_.source(d)), b = point(m_.target(d)), c = point(m_.target(m_.next(d)));
    return CGAL::cross_product(b - a, c - a);
  }

  Mobius_mesh<P>& m_;
  const Input_triangles& input_;
  std::vector<std::uint32_t> origin_;
  std::vector<char> movable_;
  std::vector<Point> near_vertex_, near_edge_, near_face_; // closest input points of the samples, by index
  // Scratch of relocate(), kept to spare allocations.
  std::vector<Edge_index> edges_;
  std::vector<Face_index> faces_;
  std::vector<Vector> normals_;
  std::vector<Point> was_edge_, was_face_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_INTERNAL_DISTANCE_RELOCATION_H
