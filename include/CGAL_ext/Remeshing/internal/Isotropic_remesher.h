// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The loop of isotropic_remeshing(): Botsch and Kobbelt's split / collapse /
// flip / relax / project, on darts, so that it runs across Möbius edges, with
// the corner channels carried (Corner_channel_edits.h: seams are protected).

#ifndef CGAL_EXT_REMESHING_INTERNAL_ISOTROPIC_REMESHER_H
#define CGAL_EXT_REMESHING_INTERNAL_ISOTROPIC_REMESHER_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_edits.h>
#include <CGAL_ext/Mobius_mesh/internal/Triangles_round_collapse.h>
#include <CGAL_ext/Remeshing/internal/Constraint_polylines.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Sharp_feature_options.h>
#include <CGAL_ext/internal/Union_find.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/assertions.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <queue>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Relaxation and projection run in double whatever the kernel (see isotropic_remeshing()).
using Remeshing_kernel = CGAL::Simple_cartesian<double>;
using Remeshing_point = Remeshing_kernel::Point_3;
using Remeshing_vector = Remeshing_kernel::Vector_3;

template <class Point>
Remeshing_point to_remeshing_point(const Point& p)
{
  return Remeshing_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

template <class Vector>
Remeshing_vector to_remeshing_vector(const Vector& v)
{
  return Remeshing_vector(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
}

// Twice the vector area of triangle (p, q, r), in that orientation; null if it is degenerate.
inline Remeshing_vector triangle_normal(const Remeshing_point& p, const Remeshing_point& q, const Remeshing_point& r)
{
  return CGAL::cross_product(q - p, r - p);
}

// Would moving target(into) to `to` turn a face around it over? Each face is
// compared with itself, walked the way the circulation's dart walks it, so
// the test means the same on both sides of a Möbius edge. Faces in `skip`
// (those that a collapse removes) are not looked at.
template <class P>
bool remeshing_move_keeps_sides(Dart into, const Remeshing_point& to, const Mobius_mesh<P>& mesh,
                                Face_index skip_a = Face_index(), Face_index skip_b = Face_index())
{
  const Remeshing_point from = to_remeshing_point(mesh.point(mesh.target(into)));
  for (Dart c : CGAL_ext::halfedges_around_target(into, mesh)) {
    if (mesh.is_border(c) || mesh.face(c) == skip_a || mesh.face(c) == skip_b)
      continue;
    const Remeshing_point u = to_remeshing_point(mesh.point(mesh.source(c)));
    const Remeshing_point w = to_remeshing_point(mesh.point(mesh.target(mesh.next(c))));
    const Remeshing_vector before = triangle_normal(u, from, w);
    if (before.squared_length() > 0 && !(before * triangle_normal(u, to, w) > 0))
      return false;
  }
  return true;
}

// The input surface, copied once as triangles (and border segments) in double,
// with the AABB trees that projection asks for closest points. The border
// segments are stored loop by loop, so that a border vertex can be kept on
// its own loop: where two loops pass close by (a thin strip, two holes side
// by side) the closest border point may be on the other one.
class Remeshing_input_surface
{
  using K = Remeshing_kernel;
  using Triangles = std::vector<K::Triangle_3>;
  using Segments = std::vector<K::Segment_3>;
  using Triangle_tree =
    CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>>;
  using Segment_tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segments::const_iterator>>>;

public:
  static constexpr std::uint32_t no_loop = std::uint32_t(-1);

  // Fills `loop_of_edge` with the input border loop of each input edge
  // (`no_loop` for inner edges), or leaves it empty if the input has no border.
  template <class P>
  Remeshing_input_surface(const Mobius_mesh<P>& mesh, std::vector<std::uint32_t>& loop_of_edge)
  {
    triangles_.reserve(mesh.number_of_faces());
    for (Face_index f : mesh.faces()) {
      const Dart d = mesh.halfedge(f);
      triangles_.emplace_back(to_remeshing_point(mesh.point(mesh.source(d))),
                              to_remeshing_point(mesh.point(mesh.target(d))),
                              to_remeshing_point(mesh.point(mesh.target(mesh.next(d)))));
    }
    const std::vector<Dart> loops = CGAL_ext::border_cycles(mesh);
    loop_of_edge.clear();
    if (!loops.empty()) // a closed surface needs no loop of its edges
      loop_of_edge.assign(mesh.num_edges(), no_loop);
    for (Dart start : loops) {
      loop_begin_.push_back(border_.size());
      for (Dart d : CGAL_ext::halfedges_around_face(start, mesh)) {
        loop_of_edge[mesh.edge(d).idx()] = std::uint32_t(loop_begin_.size() - 1);
        border_.emplace_back(to_remeshing_point(mesh.point(mesh.source(d))),
                             to_remeshing_point(mesh.point(mesh.target(d))));
      }
    }
    loop_begin_.push_back(border_.size());
    loop_trees_.resize(loop_begin_.size() - 1);
    faces_tree_.insert(triangles_.begin(), triangles_.end());
    faces_tree_.accelerate_distance_queries();
    if (!border_.empty()) {
      border_tree_.insert(border_.begin(), border_.end());
      border_tree_.accelerate_distance_queries();
    }
  }
  Remeshing_input_surface(const Remeshing_input_surface&) = delete;
  Remeshing_input_surface& operator=(const Remeshing_input_surface&) = delete;

  Remeshing_point closest_on_faces(const Remeshing_point& p) const { return faces_tree_.closest_point(p); }

  // The point of the input closest to p, the triangle it lies in (its rank
  // among the input's faces) and its barycentric coordinates there.
  struct Location
  {
    Remeshing_point point;
    std::size_t triangle;
    std::array<double, 3> weight;
  };
  Location closest_location(const Remeshing_point& p) const
  {
    const auto [point, triangle] = faces_tree_.closest_point_and_primitive(p);
    const auto d = [](const Remeshing_point& x) { return Point_d{x.x(), x.y(), x.z()}; };
    return {point, std::size_t(triangle - triangles_.begin()),
            barycentric_d(d(triangle->vertex(0)), d(triangle->vertex(1)), d(triangle->vertex(2)), d(point))};
  }

  // A border vertex stays on its own border loop of the input: the closest
  // point there. The tree of all loops answers first; only where its answer
  // is on another loop is a tree of that loop alone built (once) and asked.
  std::optional<Remeshing_point> closest_on_border(const Remeshing_point& p, std::uint32_t loop) const
  {
    if (loop >= loop_trees_.size())
      return std::nullopt;
    const auto [point, segment] = border_tree_.closest_point_and_primitive(p);
    if (loop_of_segment(std::size_t(segment - border_.begin())) == loop)
      return point;
    std::unique_ptr<Segment_tree>& own = loop_trees_[loop];
    if (!own) {
      own = std::make_unique<Segment_tree>(border_.cbegin() + std::ptrdiff_t(loop_begin_[loop]),
                                           border_.cbegin() + std::ptrdiff_t(loop_begin_[loop + 1]));
      own->accelerate_distance_queries();
    }
    return own->closest_point(p);
  }

private:
  std::uint32_t loop_of_segment(std::size_t i) const
  {
    return std::uint32_t(std::upper_bound(loop_begin_.begin(), loop_begin_.end(), i) - loop_begin_.begin() - 1);
  }

  Triangles triangles_;
  Segments border_;                       // loop by loop
  std::vector<std::size_t> loop_begin_;   // where each loop's segments begin in border_, and the end
  Triangle_tree faces_tree_;
  Segment_tree border_tree_;
  mutable std::vector<std::unique_ptr<Segment_tree>> loop_trees_; // built where the first answer was wrong
};

// The smallest altitude, in units of L, of a triangle whose three sides are
// all in [4/5 L, 4/3 L]: that of the triangle of sides 4/5, 4/5 and 4/3 on
// its long side (0.442). Narrower than this, no triangle of the band fits.
inline double narrowest_band_triangle() { return std::sqrt(0.8 * 0.8 - (2.0 / 3.0) * (2.0 / 3.0)); }

// The options of one run, read from the named parameters by isotropic_remeshing().
struct Remeshing_options
{
  double target_edge_length = 1;
  unsigned iterations = 1;
  bool protect_borders = false;
  bool protect_sharp_edges = false;
  bool relax_constraints = false;
  bool stop_when_converged = true;
  bool allow_narrow_regions = true;
  // Where a moved vertex goes instead of the closest point of the input's
  // triangles (project_to_limit_surface: the closest point of the input's
  // limit surface); unset, the triangles.
  std::function<Remeshing_point(const Remeshing_point&)> project;
  // The most faces the loop may hold at any time; isotropic_remeshing() sets
  // it from the size estimate that the memory check accepted.
  double face_budget = std::numeric_limits<double>::infinity();
};

// What the loop did: the iterations it ran, whether it stopped before the
// number asked because an iteration changed nothing that matters, and the
// share of edges in [4/5 L, 4/3 L] at the end.
struct Remeshing_run
{
  unsigned iterations = 0;
  bool stopped_early = false;
  double share_in_band = 0;
};

// An iteration that raises the share of edges in the band by less than
// `settled_band_gain` (0.1 point) and changes the number of faces by less
// than `settled_face_change` (1 %) has changed nothing that matters; two in a
// row have settled the loop: a fixed point of Botsch and Kobbelt's operations
// (a regular lattice, a mesh already at L) stays one. One alone has not: an
// iteration may move vertices without a split or collapse, and the band with
// them, and the next one split and collapse more (a torus of 576 triangles
// at 0.6 times its mean edge: 96.3 % of edges in the band after two
// iterations, 91.2 % after three at the same count, 98.4 % after five).
inline constexpr double settled_band_gain = 1e-3;
inline constexpr double settled_face_change = 1e-2;
inline constexpr unsigned settled_iterations = 2;

template <class P>
class Isotropic_remesher
{
  using Mesh = Mobius_mesh<P>;
  using Sharpness_map = typename Mesh::template Property_map<Edge_index, float>;
  using Location = Remeshing_input_surface::Location;
  // The triangle of a Location that is not on the input (the limit surface's).
  static constexpr std::size_t no_triangle = std::size_t(-1);

public:
  Isotropic_remesher(Mesh& mesh, const Remeshing_options& options)
    : mesh_(mesh), options_(options), input_(mesh, border_loop_),
      // Botsch and Kobbelt's band, as in CGAL: 4/5 L and 4/3 L.
      low2_(square(0.8 * options.target_edge_length)), high2_(square(4.0 / 3.0 * options.target_edge_length)),
      needle2_(square(narrowest_band_triangle() * options.target_edge_length)),
      sharpness_(mesh.template property_map<Edge_index, float>(edge_sharpness_name)), corners_(mesh)
  {
    collapse_options_.is_protected = [this](Edge_index e) { return is_protected(e); };
    if (corners_.has_channels()) {
      keep_input_charts();
      on_seam_.resize(mesh.num_vertices(), 0);
      for (Vertex_index v : mesh.vertices())
        on_seam_[v.idx()] = touches_seam(v);
    }
    if (options.relax_constraints && (options.protect_borders || options.protect_sharp_edges))
      polylines_.emplace(
        mesh, [this](Edge_index e) { return is_protected(e); }, [this](Vertex_index v) { return approximate(v); });
  }
  Isotropic_remesher(const Isotropic_remesher&) = delete;
  Isotropic_remesher& operator=(const Isotropic_remesher&) = delete;

  // Runs the iterations asked for, or fewer with stop_when_converged: after
  // settled_iterations in a row that each raised the share of edges in the
  // band by less than settled_band_gain and changed the face count by less
  // than settled_face_change, the next ones would not do more (CGAL runs a
  // fixed number; a mesh already at L would be relaxed again for nothing).
  Remeshing_run run()
  {
    Remeshing_run done;
    Band_count before = band_count();
    done.share_in_band = before.share();
    unsigned settled = 0;
    project_in_place(); // the input's vertices, before splits crowd them
    for (unsigned i = 0; i < options_.iterations; ++i) {
      split_long_edges();
      collapse_short_edges();
      equalize_valences();
      slide_along_constraints();
      relax_and_project();
      corners_.remove_unused_values(); // the input's stay where input_corners_ finds them
      ++done.iterations;
      const Band_count after = band_count();
      done.share_in_band = after.share();
      settled = has_settled(before, after) ? settled + 1 : 0;
      if (options_.stop_when_converged && settled == settled_iterations && done.iterations < options_.iterations) {
        done.stopped_early = true;
        break;
      }
      before = after;
    }
    project_in_place(); // every free vertex again: those whose relaxed point was refused stay off it otherwise
    return done;
  }

private:
  static double square(double x) { return x * x; }

  struct Band_count
  {
    std::size_t in_band = 0, edges = 0, faces = 0;
    double share() const { return edges == 0 ? 0.0 : double(in_band) / double(edges); }
  };

  Band_count band_count() const
  {
    Band_count count;
    for (Edge_index e : mesh_.edges()) {
      const double l2 = squared_length(e);
      count.in_band += l2 >= low2_ && l2 <= high2_;
      ++count.edges;
    }
    count.faces = mesh_.number_of_faces();
    return count;
  }

  static bool has_settled(const Band_count& before, const Band_count& after)
  {
    const double change = std::abs(double(after.faces) - double(before.faces));
    return after.share() < before.share() + settled_band_gain &&
           change <= settled_face_change * double((std::max)(before.faces, std::size_t(1)));
  }

  // The size check before the loop bounds its result from the input; where
  // that estimate is wrong (a surface it does not foresee), the loop stops
  // here rather than take more memory than the check allowed. The caller
  // then puts the mesh back.
  void check_face_budget() const
  {
    if (double(mesh_.number_of_faces()) <= options_.face_budget)
      return;
    std::ostringstream what;
    what << "isotropic_remeshing to edge length " << options_.target_edge_length << " made more than "
         << static_cast<unsigned long long>(options_.face_budget)
         << " faces, twice the size estimated before it started (see named parameter maximum_memory); the mesh is "
            "as it was";
    throw Size_error(what.str(), "faces", mesh_.number_of_faces(),
                     static_cast<unsigned long long>(options_.face_budget));
  }

  double squared_length(Edge_index e) const
  {
    return CGAL::to_double(CGAL::squared_distance(mesh_.point(mesh_.vertex(e, 0)), mesh_.point(mesh_.vertex(e, 1))));
  }

  // Borders and sharp edges as asked; the seams of corner channels always.
  bool is_protected(Edge_index e) const
  {
    if (options_.protect_borders && mesh_.is_border(e))
      return true;
    if (options_.protect_sharp_edges && sharpness_ && (*sharpness_)[e] > 0)
      return true;
    return is_on_seam(mesh_.vertex(e, 0)) && is_on_seam(mesh_.vertex(e, 1)) && corners_.is_seam(e);
  }

  // Whether v is an end of a seam edge of a corner channel (the tip of a
  // slit too, whose corners may all hold one value: not only the vertices
  // that Corner_channel_edits::is_seam_vertex() names). The ends of the
  // seams are those of the input: a seam is never split, collapsed or
  // flipped and its ends never removed, and no edit makes a seam (a split or
  // a flip gives the new corners the values of the old ones at the same
  // vertex, a collapse off the seams gives the merged corners one value) nor
  // makes a vertex the end of one; the one vertex an edit removes is off the
  // seams, so an index taken again holds no mark. check_star() asserts it in
  // debug builds.
  bool is_on_seam(Vertex_index v) const { return v.idx() < on_seam_.size() && on_seam_[v.idx()]; }
  // The same, from the corners: what is_on_seam() was made from.
  bool touches_seam(Vertex_index v) const
  {
    if (corners_.has_channels())
      for (Edge_index e : CGAL_ext::edges_around_target(v, mesh_))
        if (corners_.is_seam(e))
          return true;
    return false;
  }

  // A vertex on a protected edge is never removed and relax_and_project()
  // leaves it; only slide_along_constraints() moves it, along its polyline:
  // so protected polylines keep their vertices, corners and shape.
  bool is_fixed(Vertex_index v) const
  {
    if (is_on_seam(v))
      return true;
    for (Edge_index e : CGAL_ext::edges_around_target(v, mesh_))
      if (is_protected(e))
        return true;
    return false;
  }

  template <class Queue>
  void push_edges_around(Vertex_index v, Queue& queue, bool long_ones)
  {
    for (Edge_index e : CGAL_ext::edges_around_target(v, mesh_))
      push_if_outside_band(e, queue, long_ones);
  }

  template <class Queue>
  void push_if_outside_band(Edge_index e, Queue& queue, bool long_ones)
  {
    if (is_protected(e))
      return;
    const double l2 = squared_length(e);
    if (long_ones ? l2 > high2_ : l2 < low2_)
      queue.emplace(l2, e);
  }

  // The dart of face f that ends at v.
  Dart dart_into_in_face(Vertex_index v, Face_index f) const
  {
    for (Dart c : CGAL_ext::halfedges_around_target(v, mesh_))
      if (!mesh_.is_border(c) && mesh_.face(c) == f)
        return c;
    CGAL_assertion(false);
    return Dart();
  }

  // Longest first, as CGAL: an edge's entry is stale once its length changed.
  // The halves and the edges that join the new vertex to the far corners go
  // back to the queue, as CGAL puts them back, so that one pass leaves no
  // edge longer than 4/3 L: left for the next iteration, a joining edge is
  // split with its own joining edges left long, and so on, and a coarse input
  // grows to many times its final size before collapses catch up (a unit
  // square of two triangles at L = 0.01 held 2 million triangles in its
  // fourth iteration, for 23 000 at the end). A joining edge goes back only
  // if it is shorter than sqrt(3)/2 of the edge split, the longest a median
  // of a triangle's longest side can be: so each chain of splits shortens
  // geometrically and the pass ends even where the far corner lies beyond a
  // protected edge that cannot be split (CGAL splits, with protected
  // constraints, only the longest edge of its faces).
  //
  // Needles are the exception. Split at midpoints, a triangle much narrower
  // than its length becomes three needles of half its length, two of them
  // side by side across a joining edge as long as they are; splitting that
  // edge too makes 3^k triangles for k halvings where a strip of 2^(k+1)
  // would do (a triangle 1000 x 1e-6 at L = 0.01: 10^8), and collapses then
  // remove most of them. So a joining edge between two needles is not split
  // (is_needle_join()): the sides of the needles are, and as they are, the
  // joining edge is flipped to the shorter diagonal that their new vertices
  // offer (straighten_needles()), which zips the needle into a strip of
  // triangles across it. One that no flip shortens is split in the next
  // iteration, as any edge that was there when the pass began.
  void split_long_edges()
  {
    made_by_split_.assign(mesh_.num_edges(), 0);
    std::priority_queue<std::pair<double, Edge_index>> queue;
    for (Edge_index e : mesh_.edges())
      push_if_outside_band(e, queue, true);
    while (!queue.empty()) {
      const auto [l2, e] = queue.top();
      queue.pop();
      if (squared_length(e) != l2 || is_needle_join(e))
        continue;
      const auto [half, middle] = split_at_midpoint(e);
      made_by_split_.resize(mesh_.num_edges(), 0);
      made_by_split_[half.idx()] = made_by_split_[e.idx()];
      push_if_outside_band(e, queue, true);
      push_if_outside_band(half, queue, true);
      for (Edge_index join : CGAL_ext::edges_around_target(middle, mesh_)) {
        if (join == e || join == half)
          continue;
        made_by_split_[join.idx()] = 1;
        if (squared_length(join) <= 0.75 * l2)
          push_if_outside_band(join, queue, true);
      }
      straighten_needles(middle, queue);
      check_face_budget();
    }
  }

  // Is the face of c narrower than any triangle of the band (its width, twice
  // its area over its longest side, under narrowest_band_triangle() L)?
  bool is_needle(Dart c) const
  {
    const Remeshing_point p = approximate(mesh_.source(c)), q = approximate(mesh_.target(c)),
                          r = approximate(mesh_.target(mesh_.next(c)));
    const double longest2 = (std::max)({(q - p).squared_length(), (r - q).squared_length(), (p - r).squared_length()});
    return triangle_normal(p, q, r).squared_length() < needle2_ * longest2;
  }

  bool is_needle_join(Edge_index e) const
  {
    const Dart d = Mesh::halfedge(e);
    return made_by_split_[e.idx()] && !mesh_.is_border(e) && is_needle(d) && is_needle(mesh_.opposite(d));
  }

  // After a split inside needles: each side of the faces around the new
  // vertex, and in turn each side of a quad whose diagonal turned, is flipped
  // if it is a long edge between two needles and the other diagonal of its
  // quad is shorter. Each flip shortens an edge, so this ends.
  template <class Queue>
  void straighten_needles(Vertex_index w, Queue& queue)
  {
    boost::container::small_vector<Edge_index, 16> work;
    for (Dart c : CGAL_ext::halfedges_around_target(w, mesh_))
      if (!mesh_.is_border(c))
        work.push_back(mesh_.edge(mesh_.prev(c))); // the side across the face from w
    while (!work.empty()) {
      const Edge_index e = work.back();
      work.pop_back();
      if (!flip_needle_edge(e))
        continue;
      push_if_outside_band(e, queue, true);
      const Dart d = Mesh::halfedge(e);
      for (Dart side : {d, mesh_.opposite(d)})
        for (Dart q : {mesh_.next(side), mesh_.prev(side)})
          work.push_back(mesh_.edge(q));
    }
  }

  // Flips e if it is longer than 4/3 L, between two needles that lie nearly
  // in one plane (normals within 25 degrees: a needle's pieces, not two
  // sides of a crease or of a thin tube, which the flip would cut across),
  // and the other diagonal of its quad is shorter, where equalize_valences()
  // would allow the flip (valences of three or more, no triangle turned over).
  bool flip_needle_edge(Edge_index e)
  {
    if (is_protected(e) || mesh_.is_border(e))
      return false;
    const double l2 = squared_length(e);
    const Dart d = Mesh::halfedge(e), o = mesh_.opposite(d);
    if (!(l2 > high2_) || !is_needle(d) || !is_needle(o))
      return false;
    const Vertex_index a = mesh_.source(d), b = mesh_.target(d);
    const Vertex_index c = mesh_.target(mesh_.next(d)), x = mesh_.target(mesh_.next(o));
    if (!(CGAL::to_double(CGAL::squared_distance(mesh_.point(c), mesh_.point(x))) < l2))
      return false;
    const Remeshing_point pa = approximate(a), pb = approximate(b);
    const Remeshing_vector n_d = triangle_normal(pa, pb, approximate(c)), n_o = triangle_normal(pb, pa, approximate(x));
    const double cos_turn = n_d * n_o, flat = std::cos(25.0 * CGAL_PI / 180);
    if (!(cos_turn > 0 && square(cos_turn) >= square(flat) * n_d.squared_length() * n_o.squared_length()))
      return false;
    for (Vertex_index v : {a, b})
      if (mesh_.degree(v) <= (mesh_.is_border(v) ? 2u : 3u))
        return false;
    if (!Euler::can_flip_edge(d, mesh_) || !flip_keeps_side(a, b, c, x))
      return false;
    Euler::flip_edge(d, mesh_, Euler::unchecked); // can_flip_edge() said yes above
    made_by_split_[e.idx()] = 1;
    check_star(a);
    check_star(b);
    return true;
  }

  // Splits e at its midpoint (computed in the kernel's FT) and joins the new
  // vertex to the far corner of each triangle of e; returns the new half of e
  // and the new vertex.
  std::pair<Edge_index, Vertex_index> split_at_midpoint(Edge_index e)
  {
    const Dart d = Mesh::halfedge(e);
    const Face_index sides[2] = {mesh_.face(d), mesh_.face(mesh_.opposite(d))};
    const P middle = CGAL::midpoint(mesh_.point(mesh_.source(d)), mesh_.point(mesh_.target(d)));
    const auto corner_plan = corners_.split_plan(d); // read before the split
    const Dart n = Euler::split_edge(d, mesh_);
    const Vertex_index w = mesh_.target(n);
    mesh_.point(w) = middle;
    corners_.apply_split(corner_plan, w); // before split_face(), which copies them
    if (sharpness_) // both halves keep the edge's sharpness
      (*sharpness_)[mesh_.edge(n)] = (*sharpness_)[e];
    // Both halves of a border edge are on its loop (the inner edges made below are on none).
    if (!border_loop_.empty()) {
      border_loop_.resize(mesh_.num_edges() + 2, Remeshing_input_surface::no_loop);
      border_loop_[mesh_.edge(n).idx()] = border_loop_[e.idx()];
    }
    for (Face_index f : sides) {
      if (!f.is_valid())
        continue;
      const Dart into = dart_into_in_face(w, f);
      Euler::split_face(into, mesh_.next(mesh_.next(into)), mesh_);
    }
    if (!chart_.empty()) { // the faces round w are on the split edge's side of the seams
      const std::uint32_t chart = chart_[(sides[0].is_valid() ? sides[0] : sides[1]).idx()];
      chart_.resize(mesh_.num_faces(), chart);
      for (Dart h : CGAL_ext::halfedges_around_target(mesh_.halfedge(w), mesh_))
        if (!mesh_.is_border(h))
          chart_[mesh_.face(h).idx()] = chart;
    }
    check_star(w);
    return {mesh_.edge(n), w};
  }

  // Shortest first; a collapse changes the lengths around the kept vertex.
  void collapse_short_edges()
  {
    using Entry = std::pair<double, Edge_index>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (Edge_index e : mesh_.edges())
      push_if_outside_band(e, queue, false);
    while (!queue.empty()) {
      const auto [l2, e] = queue.top();
      queue.pop();
      if (mesh_.is_removed(e) || squared_length(e) != l2)
        continue;
      const Vertex_index kept = collapse(e);
      if (kept.is_valid())
        push_edges_around(kept, queue, false);
    }
  }

  // Would moving both ends of the edge of d to `to` make an edge longer than 4/3 L?
  bool collapse_makes_long_edge(Dart d, const P& to) const
  {
    for (Dart side : {d, mesh_.opposite(d)})
      for (Vertex_index k : CGAL_ext::vertices_around_target(side, mesh_))
        if (CGAL::to_double(CGAL::squared_distance(to, mesh_.point(k))) > high2_)
          return true;
    return false;
  }

  // Whether the collapse of d (source into target) puts the kept vertex at
  // the edge's midpoint, as Botsch and Kobbelt do: where both ends may move
  // along the same surface (two inner vertices, or the two ends of a border
  // edge). Otherwise the target keeps its point, so that borders, chords
  // between two border points and fixed vertices keep their places. CGAL
  // always keeps one end: then the edges around the removed end grow by the
  // whole edge, not half of it, and the long-edge rule refuses most
  // collapses next to the border.
  bool meets_at_midpoint(Dart d) const
  {
    const Vertex_index kept = mesh_.target(d);
    return !is_fixed(kept) && (mesh_.is_border(mesh_.edge(d)) || !mesh_.is_border(kept));
  }

  // Of a triangle of a collapsed edge, the side that stays after
  // collapse_edge(d), the side it removes (the one before the edge) and that
  // side's sharpness, read before the collapse.
  struct Merged_sides
  {
    Edge_index survivor, removed;
    float removed_sharpness;
  };
  boost::container::small_vector<Merged_sides, 2> merged_edges(Dart d) const
  {
    boost::container::small_vector<Merged_sides, 2> merged;
    for (Dart side : {d, mesh_.opposite(d)})
      if (!mesh_.is_border(side)) {
        const Edge_index removed = mesh_.edge(mesh_.prev(side));
        merged.push_back({mesh_.edge(mesh_.next(side)), removed, sharpness_ ? (*sharpness_)[removed] : 0.0f});
      }
    return merged;
  }

  // Joins one end of e into the other, at the midpoint or the kept end's
  // point (meets_at_midpoint()), if some direction is allowed; returns the
  // kept vertex, or null if none is.
  Vertex_index collapse(Edge_index e)
  {
    const Dart d = Mesh::halfedge(e);
    for (Dart c : {d, mesh_.opposite(d)}) {
      const Vertex_index gone = mesh_.source(c), kept = mesh_.target(c);
      // A border vertex joined into an inner one would pull the border inwards.
      if (is_fixed(gone) || (mesh_.is_border(gone) && !mesh_.is_border(kept)))
        continue;
      const bool midpoint = meets_at_midpoint(c);
      const P to = midpoint ? CGAL::midpoint(mesh_.point(gone), mesh_.point(kept)) : mesh_.point(kept);
      if (collapse_makes_long_edge(c, to) || check_collapse(c, to, mesh_, collapse_options_) != Collapse_verdict::allowed) {
        if (midpoint)
          break; // the other direction would meet at the same point and be refused the same way
        continue;
      }
      const auto merged = merged_edges(c);
      const auto corner_plan = corners_.plan(c, to); // read before the collapse
      const auto charts = charts_around(c);
      Euler::collapse_edge(c, mesh_, Euler::unchecked); // check_collapse() checked the link condition
      mesh_.point(kept) = to;
      corners_.apply(corner_plan, kept);
      restore_charts(charts, kept);
      corners_.merge_flags(gone, kept);
      // Of two sides of a triangle that become one edge, collapse_edge()
      // keeps one index: it keeps the sharpness of both, and the border loop
      // of either (an inner side merged with a border one is on the border).
      for (const Merged_sides& m : merged) {
        if (sharpness_)
          (*sharpness_)[m.survivor] = std::max((*sharpness_)[m.survivor], m.removed_sharpness);
        if (!border_loop_.empty() && border_loop_[m.survivor.idx()] == Remeshing_input_surface::no_loop)
          border_loop_[m.survivor.idx()] = border_loop_[m.removed.idx()];
      }
      check_star(kept);
      return kept;
    }
    return Vertex_index();
  }

  // The charts of the faces round both ends of c but the two along it, to
  // give them back to the same faces after the collapse.
  using Face_charts = Triangles_round_collapse<std::uint32_t>;
  Face_charts charts_around(Dart c) const
  {
    if (chart_.empty())
      return Face_charts();
    return Face_charts(mesh_, c, [&](const Face_charts::Darts& f) { return chart_[mesh_.face(f.at_end).idx()]; });
  }
  void restore_charts(const Face_charts& charts, Vertex_index kept)
  {
    charts.for_each_after(mesh_, kept,
                          [&](const Face_charts::Darts& f, std::uint32_t chart) { chart_[mesh_.face(f.at_end).idx()] = chart; });
  }

  int valence_deviation(Vertex_index v, int change) const
  {
    const int target = mesh_.is_border(v) ? 4 : 6;
    return std::abs(int(valence_[v.idx()]) + change - target);
  }

  // Flips every edge whose flip brings the valences of its four vertices
  // closer to 6 (4 on the border), if the two new triangles keep the side
  // the old ones face: their normals, taken in the orientation that the
  // edge's darts carry, must agree with the old pair's. The valences are
  // counted once and kept up to date: walking a vertex's fan for each of its
  // edges is quadratic in its valence, which degenerate input makes large.
  void equalize_valences()
  {
    valence_.assign(mesh_.num_vertices(), 0);
    for (Edge_index e : mesh_.edges()) {
      ++valence_[mesh_.vertex(e, 0).idx()];
      ++valence_[mesh_.vertex(e, 1).idx()];
    }
    for (Edge_index e : mesh_.edges()) {
      const Dart d = Mesh::halfedge(e);
      if (is_protected(e) || mesh_.is_border(e))
        continue;
      const Dart o = mesh_.opposite(d);
      const Vertex_index a = mesh_.source(d), b = mesh_.target(d);
      const Vertex_index c = mesh_.target(mesh_.next(d)), x = mesh_.target(mesh_.next(o));
      const int before = valence_deviation(a, 0) + valence_deviation(b, 0) + valence_deviation(c, 0) +
                         valence_deviation(x, 0);
      const int after = valence_deviation(a, -1) + valence_deviation(b, -1) + valence_deviation(c, 1) +
                        valence_deviation(x, 1);
      // The counts first: can_flip_edge() walks the fan of c.
      if (after >= before || !keeps_valence_at_least_three(a) || !keeps_valence_at_least_three(b) ||
          !Euler::can_flip_edge(d, mesh_) || !flip_keeps_side(a, b, c, x))
        continue;
      Euler::flip_edge(d, mesh_, Euler::unchecked); // can_flip_edge() said yes above
      --valence_[a.idx()];
      --valence_[b.idx()];
      ++valence_[c.idx()];
      ++valence_[x.idx()];
      check_star(a);
      check_star(b);
    }
  }

  bool keeps_valence_at_least_three(Vertex_index v) const
  {
    return valence_[v.idx()] > (mesh_.is_border(v) ? 2u : 3u);
  }

  Remeshing_point approximate(Vertex_index v) const { return to_remeshing_point(mesh_.point(v)); }

  // Triangles (a, b, c) and (b, a, x) in one orientation become (a, x, c)
  // and (x, b, c): each must face the old pair's side and keep an area (a
  // rounding error's normal may face either way, as where c, x and a lie on
  // one protected line), by the collapses' measure of degeneracy.
  bool flip_keeps_side(Vertex_index a, Vertex_index b, Vertex_index c, Vertex_index x) const
  {
    const Remeshing_point pa = approximate(a), pb = approximate(b), pc = approximate(c), px = approximate(x);
    const Remeshing_vector old_side = triangle_normal(pa, pb, pc) + triangle_normal(pb, pa, px);
    const auto sound = [&](const Remeshing_point& p, const Remeshing_point& q, const Remeshing_point& r) {
      const Remeshing_vector n = triangle_normal(p, q, r);
      const double longest = (std::max)({(q - p).squared_length(), (r - q).squared_length(), (p - r).squared_length()});
      return old_side * n > 0 && n.squared_length() > square(collapse_options_.min_relative_area * longest);
    };
    return sound(pa, px, pc) && sound(px, pb, pc);
  }

  // Every free vertex moves to the area-weighted centroid of its triangles,
  // taken in its tangent plane, then onto the input surface (a border vertex:
  // to the middle of its border neighbours, then onto the input's border),
  // unless that would turn a triangle around it over.
  void relax_and_project()
  {
    for (Vertex_index v : mesh_.vertices()) {
      if (mesh_.is_isolated(v) || is_fixed(v))
        continue;
      if (mesh_.is_border(v)) {
        const std::optional<Remeshing_point> to = border_position(v);
        if (to && remeshing_move_keeps_sides(mesh_.halfedge(v), *to, mesh_))
          move_vertex(v, *to);
      } else if (const std::optional<Location> to = inner_position(v)) {
        if (remeshing_move_keeps_sides(mesh_.halfedge(v), to->point, mesh_))
          move_vertex(v, to->point, to->triangle == no_triangle ? nullptr : &*to);
      }
    }
  }

  // Moves v (off the seams, or the seams' values would not follow) to `to`,
  // its corners taking the values there; `on_input`, where known, is where
  // `to` lies on the input (its point is `to`), found by the projection.
  void move_vertex(Vertex_index v, const Remeshing_point& to, const Location* on_input = nullptr)
  {
    CGAL_assertion(!is_on_seam(v));
    CGAL_assertion(!on_input || on_input->point == to);
    const P point(to.x(), to.y(), to.z());
    const std::vector<std::uint32_t> corner_plan =
      move_plan(v, on_input ? *on_input : closest_if_channels(to), point); // read before the move
    mesh_.point(v) = point;
    corners_.apply_move(corner_plan, v);
    check_star(v);
  }

  // Moves v to `at(fraction)` for the largest of 1, 1/2, ... 1/16 that turns
  // no triangle around it over (as CGAL gives up a move after four halvings);
  // returns that fraction, or 0 if none.
  template <class PointAt>
  double move_keeping_sides(Vertex_index v, const PointAt& at)
  {
    for (double fraction = 1; fraction > 0.05; fraction /= 2) {
      const Remeshing_point to = at(fraction);
      if (remeshing_move_keeps_sides(mesh_.halfedge(v), to, mesh_)) {
        move_vertex(v, to);
        return fraction;
      }
    }
    return 0;
  }

  // With options_.project (the limit surface), every free vertex goes to
  // the closest point of that surface to where it is: at the start, where the
  // input's vertices are far from it (a cage's) and their edges long enough
  // to take the move, and at the end, for those whose relaxed point was
  // refused.
  void project_in_place()
  {
    if (!options_.project)
      return;
    for (Vertex_index v : mesh_.vertices()) {
      if (mesh_.is_isolated(v) || is_fixed(v))
        continue;
      const Remeshing_point from = approximate(v), to = options_.project(from);
      move_keeping_sides(v, [&](double fraction) { return from + fraction * (to - from); });
    }
  }

  // The corner values of v moved to `to`: the input's there, from the
  // input triangle nearest to it, so that values do not drift with the
  // moves; but interpolated in v's star where that triangle may hold the
  // values of a seam's other side: where it lies in another chart (a region
  // of the input that no seam cuts) than v's faces, or where `to` lies on a
  // seam edge of it (on a closed surface one chart can lie on both sides of
  // a seam; off its edges, v cannot be across it, as a move across a seam
  // edge of v's star would turn a triangle over and is refused).
  std::vector<std::uint32_t> move_plan(Vertex_index v, const Location& to, const P& point) const
  {
    if (!corners_.has_channels())
      return {};
    CGAL_assertion(to.triangle != no_triangle);
    const std::size_t triangle = to.triangle;
    const std::array<double, 3>& weight = to.weight;
    for (Dart h : CGAL_ext::halfedges_around_target(mesh_.halfedge(v), mesh_))
      if (!mesh_.is_border(h)) {
        if (input_chart_[triangle] != chart_[mesh_.face(h).idx()])
          break;
        // Edge k of the triangle runs from corner k to corner k + 1: `to` is
        // on it where the weight of corner k + 2 vanishes.
        for (int k = 0; k < 3; ++k)
          if ((input_seam_sides_[triangle] >> k & 1) && weight[(k + 2) % 3] < 1e-9)
            return corners_.move_plan(v, point);
        return corners_.move_plan(v, input_corners_.data() + triangle * corners_per_triangle_, weight);
      }
    return corners_.move_plan(v, point);
  }

  // The charts of the input (its faces joined across every edge but the
  // seams), by face, and the corner indices of each input triangle, in the
  // order of input_'s triangles; chart_ starts as input_chart_ and follows
  // the faces.
  void keep_input_charts()
  {
    Union_find charts(std::uint32_t(mesh_.num_faces()));
    for (Edge_index e : mesh_.edges())
      if (!mesh_.is_border(e) && !corners_.is_seam(e))
        charts.unite(mesh_.face(Mesh::halfedge(e)).idx(), mesh_.face(mesh_.opposite(Mesh::halfedge(e))).idx());
    chart_.resize(mesh_.num_faces());
    for (Face_index f : mesh_.faces()) {
      chart_[f.idx()] = charts.find(f.idx());
      input_chart_.push_back(chart_[f.idx()]);
      // Its sides from the source of halfedge(f) on, as input_ holds its corners.
      const Dart d = mesh_.halfedge(f);
      std::uint8_t seam_sides = 0;
      for (int k = 0; k < 3; ++k)
        seam_sides |= std::uint8_t(corners_.is_seam(mesh_.edge(k == 0 ? d : k == 1 ? mesh_.next(d) : mesh_.prev(d))) << k);
      input_seam_sides_.push_back(seam_sides);
      const std::vector<std::uint32_t> corners = corners_.triangle_corners(f);
      corners_per_triangle_ = corners.size();
      input_corners_.insert(input_corners_.end(), corners.begin(), corners.end());
    }
  }

  // relax_constraints: each vertex of a protected polyline but its corners
  // slides along the input's polyline (see Constraint_polylines); any part
  // of a move stays on the polyline. The vertices of seams stay: their
  // corners on either side hold the input's values.
  void slide_along_constraints()
  {
    if (!polylines_)
      return;
    for (const Polyline_move& move : polylines_->relaxation_moves()) {
      const Vertex_index v = polylines_->vertex(move);
      CGAL_assertion(!mesh_.is_removed(v) && is_fixed(v));
      if (is_on_seam(v))
        continue;
      const double done = move_keeping_sides(v, [&](double fraction) { return polylines_->point_after(move, fraction); });
      if (done > 0)
        polylines_->commit(move, done);
    }
  }

  // The input's closest location to p, where the moves need it (with corner channels).
  Location closest_if_channels(const Remeshing_point& p) const
  {
    return corners_.has_channels() ? input_.closest_location(p) : Location{p, no_triangle, {}};
  }

  // Where v's relaxation takes it, projected: onto the input with the
  // triangle it lands in (with corner channels), or onto the limit surface
  // (`no_triangle`).
  std::optional<Location> inner_position(Vertex_index v) const
  {
    // The normal's sign depends on the side of the dart; the tangent plane does not.
    Remeshing_vector normal = to_remeshing_vector(CGAL_ext::vertex_normal(mesh_.halfedge(v), mesh_));
    const double normal2 = normal.squared_length();
    if (!(normal2 > 0))
      return std::nullopt;
    normal = normal / std::sqrt(normal2);
    Remeshing_vector sum = CGAL::NULL_VECTOR;
    double area = 0;
    const Remeshing_point p = approximate(v);
    for (Dart c : CGAL_ext::halfedges_around_target(v, mesh_)) {
      if (mesh_.is_border(c))
        continue;
      const Remeshing_point u = approximate(mesh_.source(c)), w = approximate(mesh_.target(mesh_.next(c)));
      const double a = std::sqrt(CGAL::cross_product(u - p, w - p).squared_length());
      sum = sum + a * (CGAL::centroid(u, p, w) - CGAL::ORIGIN);
      area += a;
    }
    if (!(area > 0))
      return std::nullopt;
    const Remeshing_point centroid = CGAL::ORIGIN + sum / area;
    const Remeshing_point tangent = centroid + ((p - centroid) * normal) * normal;
    if (options_.project)
      return Location{options_.project(tangent), no_triangle, {}};
    if (!corners_.has_channels()) // no values to read: no weights to compute
      return Location{input_.closest_on_faces(tangent), no_triangle, {}};
    return input_.closest_location(tangent);
  }

  std::optional<Remeshing_point> border_position(Vertex_index v) const
  {
    std::optional<Remeshing_point> middle;
    std::optional<Dart> border_dart;
    for (Dart c : CGAL_ext::halfedges_around_target(v, mesh_)) {
      if (!mesh_.is_border(c))
        continue;
      if (middle) // two gaps in the fan: no single border line to slide on
        return std::nullopt;
      middle = CGAL::midpoint(approximate(mesh_.source(c)), approximate(mesh_.target(mesh_.next(c))));
      border_dart = c;
    }
    // Its two border edges are on one loop (the walk met one gap).
    if (!middle || border_loop_.empty())
      return std::nullopt;
    const std::optional<Remeshing_point> on_border =
      input_.closest_on_border(*middle, border_loop_[mesh_.edge(*border_dart).idx()]);
    // The limit surface's border runs inside the input's: the point of the
    // input's border loop goes onto the limit surface, where it is nearest.
    if (on_border && options_.project)
      return options_.project(*on_border);
    return on_border;
  }

  // After each operation, in debug builds: the darts around the touched
  // vertex still make a manifold star of triangles (a full is_valid() per
  // operation would make the loop quadratic).
  void check_star([[maybe_unused]] Vertex_index v) const
  {
#ifndef NDEBUG
    CGAL_assertion(!mesh_.is_removed(v) && !mesh_.is_isolated(v));
    for (Dart c : CGAL_ext::halfedges_around_target(v, mesh_)) {
      CGAL_assertion(mesh_.target(c) == v && !mesh_.is_removed(mesh_.edge(c)));
      CGAL_assertion(mesh_.opposite(mesh_.opposite(c)) == c);
      CGAL_assertion(mesh_.next(mesh_.prev(c)) == c && mesh_.prev(mesh_.next(c)) == c);
      CGAL_assertion(mesh_.source(mesh_.next(c)) == v && mesh_.face(mesh_.next(c)) == mesh_.face(c));
      CGAL_assertion(mesh_.is_border(c) || (!mesh_.is_removed(mesh_.face(c)) && mesh_.degree(mesh_.face(c)) == 3));
      CGAL_assertion(is_on_seam(mesh_.source(c)) == touches_seam(mesh_.source(c)));
    }
    CGAL_assertion(is_on_seam(v) == touches_seam(v));
#endif
  }

  Mesh& mesh_;
  Remeshing_options options_;
  // By edge: the input border loop a border edge is on (empty if closed).
  // Declared before input_, which fills it.
  std::vector<std::uint32_t> border_loop_;
  std::vector<std::uint32_t> valence_; // during equalize_valences(), by vertex index
  const Remeshing_input_surface input_;
  const double low2_, high2_;
  const double needle2_; // the square of the width under which a triangle is a needle (is_needle())
  std::vector<char> made_by_split_; // during split_long_edges(), by edge index: made by a split, not there before
  std::optional<Sharpness_map> sharpness_;
  Corner_channel_edits<P> corners_; // the corner channels' rules, none without channels
  // With corner channels (keep_input_charts()): by input triangle, its chart
  // and its corners' value indices (corners_per_triangle_ each); by face, its chart.
  std::vector<std::uint32_t> input_chart_, input_corners_, chart_;
  std::vector<char> on_seam_; // by vertex, with corner channels: is_on_seam()
  std::vector<std::uint8_t> input_seam_sides_; // by input triangle: bit k if its side k is a seam
  std::size_t corners_per_triangle_ = 0;
  Collapse_options collapse_options_;
  std::optional<Constraint_polylines> polylines_; // with relax_constraints only
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_REMESHING_INTERNAL_ISOTROPIC_REMESHER_H
