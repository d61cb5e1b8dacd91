// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Garland–Heckbert decimation of a Mobius_mesh: edge collapses ordered by
// quadric error, on any surface, one-sided ones included.

#ifndef CGAL_EXT_DECIMATION_H
#define CGAL_EXT_DECIMATION_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/internal/Distance_relocation.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Quadric.h>

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

/// \ingroup PkgMobiusMeshDecimation
/// What `decimate()` did.
struct Decimation_result
{
  std::size_t faces_before = 0; ///< triangles after triangulating the input, before any collapse
  std::size_t faces_after = 0;  ///< triangles of the result
  std::size_t collapses = 0;    ///< edge collapses done
  /// The largest error of a collapse done, in squared length units (see `maximum_error`).
  double largest_error = 0;
  /// Vertices moved after the collapses to lower the largest distance to the
  /// input (see `relocate_vertices`).
  std::size_t relocations = 0;
};

namespace internal {

// The options of decimate(), read and checked before the mesh is touched.
struct Decimation_settings
{
  std::size_t target_faces = 0;                                   // stop at or below this many faces
  double maximum_error = std::numeric_limits<double>::infinity(); // stop when the cheapest collapse costs more
  double min_cos_normal_turn = 0;
  bool protect_borders = false;
  bool relocate_vertices = true;
};

template <class NP>
Decimation_settings decimation_settings(std::size_t faces, const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  const char* fn = "decimate: ";
  Decimation_settings s;
  const bool has_count = !pm::is_default_parameter<NP, CGAL_ext::internal_np::number_of_faces_t>::value;
  const bool has_ratio = !pm::is_default_parameter<NP, CGAL_ext::internal_np::face_ratio_t>::value;
  const bool has_error = !pm::is_default_parameter<NP, CGAL_ext::internal_np::maximum_error_t>::value;
  if (!has_count && !has_ratio && !has_error)
    throw Parameter_error(std::string(fn) + "no stop condition: give number_of_faces, face_ratio or maximum_error");
  s.target_faces = 0;
  if (has_count) {
    const double n = double(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::number_of_faces), 0));
    if (!(n >= 0) || !std::isfinite(n))
      throw Parameter_error(std::string(fn) + "number_of_faces must be a finite number >= 0, not " + std::to_string(n));
    // A count past what a size_t holds saturates (and is reached at once)
    // rather than being cast, which would be undefined.
    const double most = double((std::numeric_limits<std::size_t>::max)()); // rounds up to 2^64 (or 2^32)
    s.target_faces = n < most ? std::size_t(n) : (std::numeric_limits<std::size_t>::max)();
  }
  if (has_ratio) {
    const double r = double(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::face_ratio), 1.0));
    if (!(r >= 0 && r <= 1))
      throw Parameter_error(std::string(fn) + "face_ratio must be in [0, 1], not " + std::to_string(r));
    s.target_faces = (std::max)(s.target_faces, std::size_t(std::floor(r * double(faces))));
  }
  if (has_error) {
    s.maximum_error = double(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::maximum_error), 0.0));
    if (!(s.maximum_error >= 0) || std::isnan(s.maximum_error))
      throw Parameter_error(std::string(fn) + "maximum_error must be >= 0, not " + std::to_string(s.maximum_error));
  }
  const double degrees =
    double(pm::choose_parameter(pm::get_parameter(np, CGAL::internal_np::maximum_normal_deviation), 90.0));
  if (!(degrees > 0 && degrees <= 180))
    throw Parameter_error(std::string(fn) + "maximum_normal_deviation must be in (0, 180] degrees, not " +
                          std::to_string(degrees));
  s.min_cos_normal_turn = degrees == 180 ? -1.0 : std::cos(degrees * 3.14159265358979323846 / 180);
  s.protect_borders = pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::protect_borders), false);
  s.relocate_vertices =
    pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::relocate_vertices), true);
  return s;
}

// Refuses a NaN or negative sharpness in the map given or the mesh's
// "e:sharpness", the one that feature_edges() reads.
template <class P, class NP>
void require_valid_sharpness(const Mobius_mesh<P>& mesh, const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  if constexpr (!pm::is_default_parameter<NP, CGAL_ext::internal_np::edge_sharpness_t>::value) {
    const auto sharpness = pm::get_parameter(np, CGAL_ext::internal_np::edge_sharpness);
    CGAL_ext::internal::require_valid_edge_sharpness(mesh, [&](Edge_index e) { return double(get(sharpness, e)); },
                                                     "decimate");
  } else {
    CGAL_ext::internal::require_valid_edge_sharpness(mesh, "decimate");
  }
}

// Which edges are features, by edge index: sharpness > 0 (the map given or
// the mesh's "e:sharpness"), constrained edges, and borders if asked.
template <class P, class NP>
std::vector<char> feature_edges(const Mobius_mesh<P>& mesh, const NP& np, bool protect_borders)
{
  namespace pm = CGAL_ext::parameters;
  std::vector<char> feature(mesh.num_edges(), 0);
  const auto sharpness = pm::get_parameter(np, CGAL_ext::internal_np::edge_sharpness);
  const auto constrained = pm::get_parameter(np, CGAL::internal_np::edge_is_constrained);
  const auto own = mesh.template property_map<Edge_index, float>(edge_sharpness_name);
  for (Edge_index e : mesh.edges()) {
    bool f = protect_borders && mesh.is_border(e);
    if constexpr (!pm::is_default_parameter<NP, CGAL_ext::internal_np::edge_sharpness_t>::value)
      f = f || get(sharpness, e) > 0;
    else if (own)
      f = f || (*own)[e] > 0;
    if constexpr (!pm::is_default_parameter<NP, CGAL::internal_np::edge_is_constrained_t>::value)
      f = f || get(constrained, e);
    feature[e.idx()] = f;
  }
  return feature;
}

// Where an edge would collapse to, and at what cost.
struct Collapse_candidate
{
  double cost = 0;                 // the quadric's value at the point: the priority
  Point_d point{};                 // in double, unless at an end
  Vertex_index at_end;             // the end whose exact point is the placement, if any
};

// The Garland–Heckbert state of a decimation: per-vertex quadrics and plane
// areas, feature flags and costs per edge, and CGAL's modifiable priority
// queue of the edges by cost (one entry per edge, updated in place).
template <class P>
class Decimator
{
public:
  Decimator(Mobius_mesh<P>& mesh, const Decimation_settings& settings, std::vector<char> feature)
    : m_(mesh), s_(settings), feature_(std::move(feature)), cost_(mesh.num_edges(), 0.0),
      refused_(mesh.num_edges(), 0), quadric_(mesh.num_vertices()), area_(mesh.num_vertices(), 0.0),
      queue_(mesh.num_edges(), Cheaper{&cost_})
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
    const Quadric sum = quadric_[p.idx()] + quadric_[q.idx()];
    Collapse_candidate c;
    const bool fp = fixed(p), fq = fixed(q);
    if (fp || fq) {
      c.at_end = fp ? p : q;
      c.point = pt(c.at_end);
      c.cost = sum(c.point);
      return c;
    }
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
      const double cost = sum(pt(end));
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
  Euler::collapse_edge(d, m_, Euler::unchecked); // check_collapse() checked the link condition
  for (Edge_index s : sides) // one side of each collapsed triangle is gone
    if (m_.is_removed(s) && queue_.contains(s))
      queue_.erase(s);
  m_.points()[q] = point;
  quadric_[q.idx()] += quadric_[p.idx()];
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

/// \ingroup PkgMobiusMeshDecimation
/// \brief Simplifies `mesh` by edge collapses, cheapest first by
/// Garland–Heckbert quadric error, until a stop condition holds.
///
/// Works on any `Mobius_mesh`, one-sided surfaces included: quadrics are
/// orientation-free, and the fold-over check compares each face with itself,
/// seen from one dart, so it means the same across Möbius edges. Faces with
/// more than three sides are triangulated first (`triangulate_faces()`); the
/// result has triangles only. Every collapse keeps the Euler characteristic,
/// the number of border loops and orientability.
///
/// After the collapses, vertices are moved to lower the largest distance
/// between the result and the input (`relocate_vertices`): the quadrics
/// measure the distance at the vertices, and the largest one lies inside the
/// triangles, where the surface bends little along a long edge. Each vertex
/// whose star holds the largest distances (from its vertex, edge midpoints
/// and face centroids to their closest points on the input, found in an AABB
/// tree of a copy of the input) moves along their main direction by the step
/// that minimises the largest of them; a move is kept only if the largest
/// distance of its star went down and no face turned over. Border vertices
/// and the ends of feature edges do not move.
///
/// \param mesh a mesh without removed elements; it is garbage-collected at the end and its
///   unused capacity released
/// \param np named parameters, at least one stop condition:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_faces}
///     \cgalParamDescription{stop when the mesh has at most this many faces}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_ratio}
///     \cgalParamDescription{in [0, 1]: stop at most at this fraction of the (triangulated) faces}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_error}
///     \cgalParamDescription{stop when the cheapest collapse's error is larger: its quadric's value at the
///                           placement divided by the area of the faces whose planes it sums (an area-weighted
///                           mean squared distance, in squared length units)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_normal_deviation}
///     \cgalParamDescription{in degrees, (0, 180]: no face's normal may turn by more in one collapse}
///     \cgalParamDefault{90, as OpenMesh's normal-flipping module}
///   \cgalParamNEnd
///   \cgalParamNBegin{protect_borders}
///     \cgalParamDescription{`true` to keep border edges as they are; otherwise they may collapse along the
///                           border, held by their quadrics}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{relocate_vertices}
///     \cgalParamDescription{`false` to leave the vertices where the collapses put them, without the
///                           copy of the input and its AABB tree that the relocation needs}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_sharpness_map}
///     \cgalParamDescription{edges of sharpness > 0 are features: never collapsed, their ends never moved}
///     \cgalParamDefault{the mesh's `"e:sharpness"` map if it has one}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{a readable map from `Edge_index` to `bool`: `true` edges are features too}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Parameter_error if a parameter is out of range, no stop condition
///   is given, an edge's sharpness is NaN or negative, `mesh` has removed
///   elements, a point has a coordinate
///   beyond +-1e60 (where quadrics in double overflow), or the mesh is less
///   than 1e-60 across (where its areas underflow).
/// \throws Euler_error if a polygon cannot be triangulated (triangulate_faces()).
/// All are thrown before `mesh` is touched.
template <class P, class NP = parameters::Default_named_parameters>
Decimation_result decimate(Mobius_mesh<P>& mesh, const NP& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh, "decimate");
  std::size_t triangles = 0;
  for (Face_index f : mesh.faces())
    triangles += mesh.degree(f) - 2;
  const internal::Decimation_settings settings = internal::decimation_settings(triangles, np);
  internal::require_coordinates_in_range(mesh, "decimate");
  internal::require_valid_sharpness(mesh, np);
  triangulate_faces(mesh);
  // The input, for the distances of the relocation: a copy of its points
  // and triangles now, its tree once the decimator and the removed elements
  // are gone, so that the tree is never held beside them.
  std::optional<internal::Input_triangles> input;
  if (settings.relocate_vertices)
    input.emplace(mesh);
  Decimation_result result;
  std::vector<char> on_feature; // by vertex index, for the relocation only
  {
    internal::Decimator<P> decimator(mesh, settings, internal::feature_edges(mesh, np, settings.protect_borders));
    result = decimator.run();
    if (input) {
      // Feature edges keep their ends where they are, as during the collapses.
      const std::vector<char> feature = decimator.take_features();
      on_feature.assign(mesh.num_vertices(), 0);
      for (Edge_index e : mesh.edges())
        if (feature[e.idx()])
          on_feature[mesh.vertex(e, 0).idx()] = on_feature[mesh.vertex(e, 1).idx()] = 1;
    }
  }
  typename Mobius_mesh<P>::Garbage_collection_maps moved;
  mesh.collect_garbage(moved);
  mesh.shrink_to_fit();
  if (input && result.collapses > 0) {
    // Each vertex's input vertex of the same old index: a point of the input near it.
    std::vector<std::uint32_t> origin(mesh.num_vertices());
    std::vector<char> movable(mesh.num_vertices());
    for (std::size_t old = 0; old < moved.vertices.size(); ++old)
      if (const Vertex_index v = moved.vertices[old]; v.is_valid()) {
        origin[v.idx()] = std::uint32_t(old);
        movable[v.idx()] = !on_feature[old];
      }
    std::vector<char>().swap(on_feature);
    moved = {};
    input->build_tree();
    internal::Distance_relocation<P> relocation(mesh, *input, std::move(origin), std::move(movable));
    result.relocations = relocation.run(3);
  }
  return result;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_H
