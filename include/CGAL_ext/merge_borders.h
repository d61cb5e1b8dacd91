// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Merging mesh borders: automatically, where border vertices lie within a
// tolerance of each other (compared exactly), or manually, along two chosen
// border loops with one of four strategies. Gluing two border edges that run
// the same way makes a Möbius edge.

#ifndef CGAL_EXT_MERGE_BORDERS_H
#define CGAL_EXT_MERGE_BORDERS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/box_intersection_d.h>

#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshMerge
/// What a merge did. Input vertices and halfedges are numbered as in the
/// input for `merge_borders(mesh, np)`; for two meshes, those of the second
/// mesh come after those of the first (vertex `v` of `mesh_b` is
/// `mesh_a.number_of_vertices() + v`, halfedge `h` is
/// `mesh_a.number_of_halfedges() + h`).
struct Merge_result
{
  std::size_t glued_edges = 0;     ///< pairs of border edges glued into one edge
  std::size_t mobius_edges = 0;    ///< glued edges that are Möbius edges (their two sides ran the same way)
  std::size_t merged_vertices = 0; ///< vertices that disappeared into others
  std::size_t new_faces = 0;       ///< faces added (bridging only)
  std::size_t ignored_vertex_pairs = 0; ///< vertex pairs within the tolerance without an edge to glue
  /// Identified vertex pairs (input numbering), lower index first.
  std::vector<std::pair<std::size_t, std::size_t>> vertex_pairs;
  /// Glued border halfedge pairs (input numbering).
  std::vector<std::pair<std::size_t, std::size_t>> halfedge_pairs;
  /// For each input vertex, the vertex of the result it became.
  std::vector<Vertex_index> vertex_map;
};

/// \ingroup PkgMobiusMeshMerge
/// How `merge_borders()` places the vertices of two glued border chains.
enum class Merge_strategy {
  keep_first,  ///< glued vertices keep the first mesh's positions
  keep_second, ///< glued vertices take the second mesh's positions
  average,     ///< glued vertices move to the midpoint
  bridge       ///< nothing moves: new faces fill the gap (quads, triangles where the chains differ)
};

namespace internal {

// Exact "distance at most tolerance" test: the kernel's
// Compare_squared_distance_3 against tolerance². With a floating-point FT,
// tolerance² may not be representable; then the decision is made on the
// exact rational values of the coordinates instead, so that a point at
// exactly the tolerance is within it and one a unit in the last place
// beyond is not.
template <class Traits>
class Within_tolerance
{
public:
  using FT = typename Traits::FT;
  using Point = typename Traits::Point_3;

  Within_tolerance(const Traits& traits, const FT& tolerance) : traits_(traits), tolerance_(tolerance)
  {
    squared_ = tolerance * tolerance;
    if constexpr (std::is_floating_point_v<FT>) {
      // tol² is exact iff the fused residual is 0 and it is far from underflow.
      exact_square_ = std::fma(tolerance, tolerance, -squared_) == 0 &&
                      (tolerance == 0 || squared_ > std::ldexp(1.0, -960));
    }
  }

  bool operator()(const Point& p, const Point& q) const
  {
    if constexpr (std::is_floating_point_v<FT>) {
      if (!exact_square_) {
        using Q = CGAL::Exact_rational;
        const Q dx = Q(p.x()) - Q(q.x()), dy = Q(p.y()) - Q(q.y()), dz = Q(p.z()) - Q(q.z());
        const Q t(tolerance_);
        return dx * dx + dy * dy + dz * dz <= t * t;
      }
    }
    return traits_.compare_squared_distance_3_object()(p, q, squared_) != CGAL::LARGER;
  }

private:
  Traits traits_;
  FT tolerance_, squared_;
  bool exact_square_ = true;
};

template <class FT, class T>
FT checked_tolerance(const T& t)
{
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(t))
      throw Parameter_error("the merge tolerance must be a finite number >= 0 (it is " + std::to_string(t) + ")");
  const FT tolerance(t);
  if (CGAL::is_negative(tolerance))
    throw Parameter_error("the merge tolerance must be a finite number >= 0 (it is " +
                          std::to_string(CGAL::to_double(tolerance)) + ")");
  return tolerance;
}

inline std::string vertex_list(const std::vector<std::size_t>& vs)
{
  std::string s;
  for (std::size_t i = 0; i < vs.size() && i < 8; ++i)
    s += (i ? ", v" : "v") + std::to_string(vs[i]);
  if (vs.size() > 8)
    s += ", ... (" + std::to_string(vs.size()) + " in all)";
  return s;
}

// Rebuilds `work` with the vertices of each class of `cls` identified (and
// `extra` polygons added, by class), through a soup: linear time, and the
// soup import finds every normal and Möbius connection and refuses what is
// not a 2-manifold. `position[c]` is the point of class c. Properties are
// carried over: faces one to one, a vertex from the lowest member of its
// class, an edge from the first of the edges glued into it.
template <class P>
Mobius_mesh<P> rebuild_glued(const Mobius_mesh<P>& work, const std::vector<std::uint32_t>& cls,
                             const std::vector<P>& position, const std::vector<std::vector<std::uint32_t>>& extra,
                             Merge_result& result)
{
  // The soup in one flat array of corners with a view per polygon: a vector
  // per face would cost one allocation per face, a third of the whole merge.
  const std::size_t nf = work.number_of_faces();
  std::vector<std::uint32_t> corners;
  std::vector<std::size_t> start;
  corners.reserve(work.number_of_halfedges());
  start.reserve(nf + extra.size() + 1);
  start.push_back(0);
  for (Face_index f : work.faces()) {
    for (Dart d : CGAL_ext::halfedges_around_face(work.halfedge(f), work))
      corners.push_back(cls[work.source(d).idx()]);
    start.push_back(corners.size());
  }
  for (const std::vector<std::uint32_t>& polygon : extra) {
    corners.insert(corners.end(), polygon.begin(), polygon.end());
    start.push_back(corners.size());
  }
  std::vector<boost::iterator_range<const std::uint32_t*>> polygons;
  polygons.reserve(start.size() - 1);
  for (std::size_t i = 0; i + 1 < start.size(); ++i)
    polygons.emplace_back(corners.data() + start[i], corners.data() + start[i + 1]);

  Mobius_mesh<P> out;
  try {
    polygon_soup_to_mobius_mesh(position, polygons, out);
  } catch (const Soup_error& e) {
    std::vector<std::size_t> vs;
    for (std::size_t c : e.vertices())
      for (std::size_t v = 0; v < cls.size(); ++v)
        if (cls[v] == c)
          vs.push_back(v);
    using K = Merge_error::Kind;
    switch (e.kind()) {
    case Soup_error::Kind::repeated_vertex:
      throw Merge_error(K::collapsed_face,
                        "the merge would identify two vertices of one face (" + vertex_list(vs) +
                          "): is the tolerance larger than the mesh's edges?",
                        vs);
    case Soup_error::Kind::non_manifold_edge:
      throw Merge_error(K::non_manifold_edge,
                        "the merge would give the edge between " + vertex_list(vs) + " three or more faces", vs);
    default:
      throw Merge_error(K::non_manifold_vertex,
                        "the merge would make a non-manifold vertex of " + vertex_list(vs) +
                          " (its faces would form separate fans)",
                        vs);
    }
  }

  // Correspondences, read off the face cycles in step.
  std::vector<Vertex_index> vertex_src(out.number_of_vertices());
  for (std::size_t v = cls.size(); v-- > 0;)
    vertex_src[cls[v]] = Vertex_index(v);
  // Halfedges and edges are walked only if they have property maps to carry.
  const bool walk = !work.template properties<Halfedge_index>().empty() ||
                    !work.template properties<Edge_index>().empty();
  std::vector<Halfedge_index> halfedge_src(walk ? out.number_of_halfedges() : 0);
  std::vector<Edge_index> edge_src(walk ? out.number_of_edges() : 0);
  if (walk) {
    for (Face_index f : work.faces()) {
      Dart d = out.halfedge(f);
      for (Dart w : CGAL_ext::halfedges_around_face(work.halfedge(f), work)) {
        halfedge_src[d.halfedge().idx()] = w.halfedge();
        const Halfedge_index wo = Mobius_mesh<P>::opposite_halfedge(w.halfedge());
        const Halfedge_index o = Mobius_mesh<P>::opposite_halfedge(d.halfedge());
        if (work.is_border(wo) && out.is_border(o))
          halfedge_src[o.idx()] = wo;
        if (!edge_src[out.edge(d).idx()].is_valid())
          edge_src[out.edge(d).idx()] = work.edge(w);
        d = out.next(d);
      }
    }
  }
  std::vector<Face_index> face_src(out.number_of_faces());
  for (std::size_t f = 0; f < nf; ++f)
    face_src[f] = Face_index(f);
  transfer_properties<Vertex_index>(work, out, 0, out.number_of_vertices(),
                                    [&](Vertex_index v) { return vertex_src[v.idx()]; });
  transfer_properties<Halfedge_index>(work, out, 0, out.number_of_halfedges(),
                                      [&](Halfedge_index h) { return halfedge_src[h.idx()]; });
  transfer_properties<Edge_index>(work, out, 0, out.number_of_edges(),
                                  [&](Edge_index e) { return edge_src[e.idx()]; });
  transfer_properties<Face_index>(work, out, 0, out.number_of_faces(),
                                  [&](Face_index f) { return face_src[f.idx()]; });

  result.vertex_map.resize(cls.size());
  for (std::size_t v = 0; v < cls.size(); ++v)
    result.vertex_map[v] = Vertex_index(cls[v]);
  result.merged_vertices = cls.size() - out.number_of_vertices();
  result.new_faces = extra.size();
  return out;
}

// Numbers the classes of a union-find by their lowest member.
inline std::vector<std::uint32_t> number_classes(std::vector<std::uint32_t>& parent, std::size_t& n_classes)
{
  const std::uint32_t none = Vertex_index::null_value;
  std::vector<std::uint32_t> cls(parent.size(), none);
  n_classes = 0;
  for (std::uint32_t v = 0; v < parent.size(); ++v) {
    std::uint32_t r = v;
    while (parent[r] != r)
      r = parent[r];
    if (cls[r] == none)
      cls[r] = std::uint32_t(n_classes++);
    cls[v] = cls[r];
  }
  return cls;
}

// The automatic merge on `work`: border vertices of `first` are matched with
// those of `second` (both halves of the index range [0, nv) if `self`).
template <class P, class NP>
Merge_result merge_borders_impl(Mobius_mesh<P>& target, const Mobius_mesh<P>& work, std::size_t split, bool self,
                                const NP& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Default_traits = typename CGAL::Kernel_traits<P>::Kernel;
  const auto traits = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  using Traits = std::decay_t<decltype(traits)>;
  using FT = typename Traits::FT;
  const auto tol_param = choose_parameter(get_parameter(np, CGAL_ext::internal_np::tolerance), 0.0);
  const FT tolerance = checked_tolerance<FT>(tol_param);
  const Within_tolerance<Traits> within(traits, tolerance);
  const std::size_t nv = work.number_of_vertices();
  Merge_result result;

  // 1. Candidate vertex pairs: closed, padded double boxes around border
  //    vertices, then the exact test.
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;
  const double pad = CGAL::to_interval(tolerance).second;
  std::vector<Box> boxes_a, boxes_b;
  for (Vertex_index v : work.vertices()) {
    if (work.is_isolated(v) || !work.is_border(v))
      continue;
    const CGAL::Bbox_3 b = work.point(v).bbox();
    double lo[3] = {std::nextafter(b.xmin() - pad, -HUGE_VAL), std::nextafter(b.ymin() - pad, -HUGE_VAL),
                          std::nextafter(b.zmin() - pad, -HUGE_VAL)};
    double hi[3] = {std::nextafter(b.xmax() + pad, HUGE_VAL), std::nextafter(b.ymax() + pad, HUGE_VAL),
                          std::nextafter(b.zmax() + pad, HUGE_VAL)};
    (self || v.idx() < split ? boxes_a : boxes_b).emplace_back(lo, hi, v.idx());
  }
  std::vector<std::vector<std::uint32_t>> match(nv);
  std::size_t close_pairs = 0;
  auto test = [&](const Box& a, const Box& b) {
    const std::uint32_t u = a.info(), w = b.info();
    if (within(work.point(Vertex_index(u)), work.point(Vertex_index(w)))) {
      match[u].push_back(w);
      match[w].push_back(u);
      ++close_pairs;
    }
  };
  if (self)
    CGAL::box_self_intersection_d(boxes_a.begin(), boxes_a.end(), test);
  else
    CGAL::box_intersection_d(boxes_a.begin(), boxes_a.end(), boxes_b.begin(), boxes_b.end(), test);

  // 2. Border edges to glue: (s, t) with (s', t') where s' matches s (or is
  //    s) and t' matches t (or is t). Each border edge may have one partner.
  auto is_close = [&](std::uint32_t a, std::uint32_t b) {
    return a == b || std::find(match[a].begin(), match[a].end(), b) != match[a].end();
  };
  const std::uint32_t none = Vertex_index::null_value;
  std::vector<std::uint32_t> partner(work.number_of_halfedges(), none);
  std::vector<std::uint8_t> same_way(work.number_of_halfedges(), 0);
  std::vector<std::uint32_t> parent(nv);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&parent](std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<bool> used_vertex(nv, false);
  for (Halfedge_index b : work.halfedges()) {
    if (!work.is_border(b) || partner[b.idx()] != none)
      continue;
    const Dart db(b, false);
    const std::uint32_t s = work.source(db).idx(), t = work.target(db).idx();
    if (match[s].empty() && match[t].empty())
      continue;
    std::vector<std::pair<Halfedge_index, bool>> found; // partner, runs the same way
    std::vector<std::uint32_t> around = match[s];
    around.push_back(s);
    for (std::uint32_t s2 : around) {
      const Dart in = work.halfedge(Vertex_index(s2)); // border dart into s2
      for (Dart c : {in, work.next(in)}) {
        if (c.halfedge() == b)
          continue;
        const std::uint32_t cs = work.source(c).idx(), ct = work.target(c).idx();
        const std::uint32_t other = cs == s2 ? ct : cs;
        if ((other == t && s2 == s) || !is_close(t, other))
          continue;
        if (other == t && s2 != s && !is_close(s, s2))
          continue;
        // Runs the same way as b if it leaves the vertex matched with s.
        const bool same = work.source(Dart(c.halfedge(), false)).idx() == s2;
        if (std::find_if(found.begin(), found.end(), [&](const auto& p) { return p.first == c.halfedge(); }) ==
            found.end())
          found.emplace_back(c.halfedge(), same);
      }
    }
    if (found.empty())
      continue;
    if (found.size() > 1) {
      std::vector<std::size_t> vs = {s, t};
      for (const auto& [h, same] : found) {
        vs.push_back(work.source(Dart(h, false)).idx());
        vs.push_back(work.target(Dart(h, false)).idx());
      }
      throw Merge_error(Merge_error::Kind::non_manifold_edge,
                        "border edge (v" + std::to_string(s) + ", v" + std::to_string(t) + ") could be glued to " +
                          std::to_string(found.size()) + " border edges (" + vertex_list(vs) +
                          "): an edge takes at most two faces",
                        vs);
    }
    const Halfedge_index g = found[0].first;
    if (partner[g.idx()] != none) {
      const std::vector<std::size_t> vs = {s, t, work.source(Dart(g, false)).idx(), work.target(Dart(g, false)).idx()};
      throw Merge_error(Merge_error::Kind::non_manifold_edge,
                        "border edge (" + vertex_list({vs[2], vs[3]}) + ") could be glued to two border edges",
                        vs);
    }
    partner[b.idx()] = g.idx();
    partner[g.idx()] = b.idx();
    same_way[b.idx()] = same_way[g.idx()] = found[0].second ? 1 : 0;
    const std::uint32_t gs = work.source(Dart(g, false)).idx(), gt = work.target(Dart(g, false)).idx();
    const std::uint32_t s2 = found[0].second ? gs : gt, t2 = found[0].second ? gt : gs;
    for (auto [x, y] : {std::make_pair(s, s2), std::make_pair(t, t2)}) {
      if (x == y)
        continue;
      const std::uint32_t rx = find(x), ry = find(y);
      if (rx != ry)
        parent[(std::max)(rx, ry)] = (std::min)(rx, ry);
      result.vertex_pairs.emplace_back((std::min)(x, y), (std::max)(x, y));
      used_vertex[x] = used_vertex[y] = true;
    }
    result.halfedge_pairs.emplace_back(b.idx(), g.idx());
    ++result.glued_edges;
    result.mobius_edges += found[0].second ? 1 : 0;
  }
  std::sort(result.vertex_pairs.begin(), result.vertex_pairs.end());
  result.vertex_pairs.erase(std::unique(result.vertex_pairs.begin(), result.vertex_pairs.end()),
                            result.vertex_pairs.end());
  {
    std::size_t used_pairs = 0;
    for (std::uint32_t u = 0; u < nv; ++u)
      for (std::uint32_t w : match[u])
        if (u < w && std::binary_search(result.vertex_pairs.begin(), result.vertex_pairs.end(),
                                        std::make_pair(std::size_t(u), std::size_t(w))))
          ++used_pairs;
    result.ignored_vertex_pairs = close_pairs - used_pairs;
  }
  if (result.glued_edges == 0) {
    result.vertex_map.resize(nv);
    for (std::size_t v = 0; v < nv; ++v)
      result.vertex_map[v] = Vertex_index(v);
    if (&target != &work)
      target = work;
    return result;
  }

  // 3. Rebuild with the glued vertices identified; each keeps the position
  //    of its class's lowest vertex (the first mesh's, in a two-mesh merge).
  std::size_t n_classes = 0;
  for (std::uint32_t v = 0; v < nv; ++v)
    parent[v] = find(v);
  const std::vector<std::uint32_t> cls = number_classes(parent, n_classes);
  std::vector<P> position(n_classes);
  for (std::size_t v = nv; v-- > 0;)
    position[cls[v]] = work.point(Vertex_index(v));
  target = rebuild_glued(work, cls, position, {}, result);
  return result;
}

// The border loop of dart `d` as a vertex chain (targets, walking next from d).
template <class P>
std::vector<std::uint32_t> border_chain(const Mobius_mesh<P>& m, Dart d, const char* which)
{
  if (!m.is_valid(d) || !m.is_border(d))
    throw Merge_error(Merge_error::Kind::not_a_border,
                      std::string("the dart given for the ") + which + " mesh is not a border dart", {});
  std::vector<std::uint32_t> chain;
  for (Dart c : CGAL_ext::halfedges_around_face(d, m))
    chain.push_back(m.target(c).idx());
  return chain;
}

} // namespace internal

/// \ingroup PkgMobiusMeshMerge
///
/// Merges the borders of `mesh_b` into `mesh_a` where they meet: border
/// vertices of `mesh_a` and `mesh_b` within the tolerance of each other are
/// candidates (found with `CGAL::box_intersection_d()` on padded boxes, then
/// decided exactly, see below), and each border edge whose two ends are
/// candidates of the two ends of a border edge of the other mesh is glued to
/// it. Gluing follows the borders from matched vertex to matched vertex as
/// far as both run together; vertex pairs that glue no edge are left apart
/// (counted in `ignored_vertex_pairs`). Two border edges that run the same way
/// become a Möbius edge: a strip glued to itself after a half-twist is a
/// Möbius strip.
///
/// `mesh_a` receives the union of both meshes with the glue; glued vertices
/// keep `mesh_a`'s positions. Faces keep their orientation, `mesh_a`'s faces
/// first. Property maps of every value type are kept (a glued vertex or edge
/// takes `mesh_a`'s value).
///
/// The tolerance test is `Compare_squared_distance_3(p, q, tolerance²)` of the
/// kernel, never a square root: with EPICK or EPECK a point at exactly the
/// tolerance merges and one a unit in the last place further does not (with a
/// `double` tolerance whose square is not a `double`, the comparison is done
/// on exact rationals). A tolerance of 0 glues exact coincidences only.
///
/// \param mesh_a the first mesh, which receives the result
/// \param mesh_b the second mesh
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{the largest distance between two border vertices that may be glued}
///     \cgalParamType{`double` or the kernel's `FT`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel whose `Compare_squared_distance_3` decides}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns what was glued; if nothing is, `mesh_a` becomes the disjoint union.
/// \throws Parameter_error for a negative, infinite or NaN tolerance.
/// \throws Merge_error if the glue would make a non-manifold edge (a border
///   edge with two candidate partners, or three faces at an edge) or vertex, or
///   collapse a face; both meshes are then left unchanged.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b,
                           const NamedParameters& np = parameters::default_values())
{
  Mobius_mesh<P> work = mesh_a;
  const std::size_t split = work.number_of_vertices();
  work.join(mesh_b);
  Mobius_mesh<P> out;
  Merge_result r = internal::merge_borders_impl(out, work, split, false, np);
  mesh_a = std::move(out);
  return r;
}

/// \ingroup PkgMobiusMeshMerge
///
/// Merges the borders of `mesh` with themselves, as the two-mesh
/// `merge_borders()` does, matching any two border vertices within the
/// tolerance. `mesh` is left unchanged if an exception is thrown.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh, const NamedParameters& np = parameters::default_values())
{
  Mobius_mesh<P> out;
  Merge_result r = internal::merge_borders_impl(out, mesh, mesh.number_of_vertices(), true, np);
  mesh = std::move(out);
  return r;
}

/// \ingroup PkgMobiusMeshMerge
///
/// Glues the border loop of `border_b` in `mesh_b` to the border loop of
/// `border_a` in `mesh_a`, whatever the distance between them, and puts the
/// result in `mesh_a`. The loops are walked with `next()` from the two darts,
/// in step: the i-th vertex of one corresponds to the i-th vertex of the
/// other, starting with the targets of `border_a` and `border_b`. Pass a
/// flipped dart to walk a loop the other way. If the two loops are walked
/// against the orientation of their faces in opposite senses (one dart
/// flipped, one not), the glue is orientable; otherwise the glued edges are
/// Möbius edges.
///
/// - `Merge_strategy::keep_first`, `keep_second`, `average`: corresponding
///   vertices are identified at `mesh_a`'s position, `mesh_b`'s, or their
///   midpoint (exact with an exact kernel). The loops must have the same length.
/// - `Merge_strategy::bridge`: nothing moves; new faces join the loops, quads
///   where both advance together, triangles where one loop is longer.
///
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel whose `Construct_midpoint_3` places the vertices under
///       `Merge_strategy::average` (no other strategy computes a point)}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns what was glued (vertex pairs in the numbering of `Merge_result`).
/// \throws Merge_error `not_a_border` if a dart is not a border dart,
///   `mismatched_chains` if the loops differ in length (not with `bridge`),
///   or the kinds of the automatic merge if the result is not a 2-manifold;
///   both meshes are then left unchanged.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, Dart border_a, const Mobius_mesh<P>& mesh_b, Dart border_b,
                           Merge_strategy strategy, const NamedParameters& np = parameters::default_values())
{
  using Default_traits = typename CGAL::Kernel_traits<P>::Kernel;
  const auto traits =
    parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  const auto midpoint = traits.construct_midpoint_3_object();
  const std::vector<std::uint32_t> chain_a = internal::border_chain(mesh_a, border_a, "first");
  std::vector<std::uint32_t> chain_b = internal::border_chain(mesh_b, border_b, "second");
  const std::uint32_t na = mesh_a.number_of_vertices();
  for (std::uint32_t& v : chain_b)
    v += na;
  Mobius_mesh<P> work = mesh_a;
  work.join(mesh_b);
  const std::size_t nv = work.number_of_vertices();
  Merge_result result;

  std::vector<std::uint32_t> parent(nv);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<std::vector<std::uint32_t>> extra;
  if (strategy != Merge_strategy::bridge) {
    if (chain_a.size() != chain_b.size()) {
      std::vector<std::size_t> vs = {chain_a.front(), chain_b.front()};
      throw Merge_error(Merge_error::Kind::mismatched_chains,
                        "the border loops have " + std::to_string(chain_a.size()) + " and " +
                          std::to_string(chain_b.size()) +
                          " edges; only Merge_strategy::bridge joins loops of different lengths",
                        vs);
    }
    for (std::size_t i = 0; i < chain_a.size(); ++i) {
      parent[chain_b[i]] = chain_a[i];
      result.vertex_pairs.emplace_back(chain_a[i], chain_b[i]);
    }
    // The i-th edges of the two walks are glued: the border halfedges under
    // the darts from chain[i-1] to chain[i].
    Dart da = border_a, db = border_b;
    for (std::size_t i = 0; i < chain_a.size(); ++i) {
      result.halfedge_pairs.emplace_back(da.halfedge().idx(), db.halfedge().idx() + mesh_a.number_of_halfedges());
      // Darts that both run with (or both against) their halfedges: the two
      // faces then run the same way along the glued edge.
      result.mobius_edges += da.is_flipped() == db.is_flipped() ? 1 : 0;
      da = mesh_a.next(da);
      db = mesh_b.next(db);
    }
    result.glued_edges = chain_a.size();
  } else {
    const std::size_t n = chain_a.size(), m = chain_b.size();
    // Walk both loops from their starts; at each step advance the one that
    // is behind in proportion (i/n against j/m), or both at once: a quad.
    std::size_t i = 0, j = 0;
    while (i < n || j < m) {
      const std::uint32_t a0 = chain_a[i % n], a1 = chain_a[(i + 1) % n];
      const std::uint32_t b0 = chain_b[j % m], b1 = chain_b[(j + 1) % m];
      const std::size_t lhs = (i + 1) * m, rhs = (j + 1) * n; // compare (i+1)/n with (j+1)/m
      if (i < n && j < m && lhs == rhs) {
        extra.push_back({a0, a1, b1, b0});
        ++i;
        ++j;
      } else if (j >= m || (i < n && lhs < rhs)) {
        extra.push_back({a0, a1, b0});
        ++i;
      } else {
        extra.push_back({a0, b1, b0});
        ++j;
      }
    }
  }
  std::size_t n_classes = 0;
  const std::vector<std::uint32_t> cls = internal::number_classes(parent, n_classes);
  std::vector<P> position(n_classes);
  for (std::size_t v = nv; v-- > 0;) // the lowest member (the first mesh's) wins
    position[cls[v]] = work.point(Vertex_index(v));
  if (strategy == Merge_strategy::keep_second || strategy == Merge_strategy::average)
    for (std::size_t i = 0; i < chain_a.size(); ++i) {
      const P& pa = work.point(Vertex_index(chain_a[i]));
      const P& pb = work.point(Vertex_index(chain_b[i]));
      position[cls[chain_a[i]]] = strategy == Merge_strategy::keep_second ? pb : midpoint(pa, pb);
    }
  Mobius_mesh<P> out = internal::rebuild_glued(work, cls, position, extra, result);
  if (strategy == Merge_strategy::bridge)
    result.mobius_edges = number_of_mobius_edges(out) - number_of_mobius_edges(work);
  mesh_a = std::move(out);
  return result;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MERGE_BORDERS_H
