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
#include <CGAL_ext/Mobius_mesh/internal/Border_glue.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/internal/Close_points.h>
#include <CGAL_ext/internal/Coordinate_checks.h>
#include <CGAL_ext/internal/Nearest_points.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
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

/// \ingroup PkgMobiusMeshMerge
/// Two border chains for the manual `merge_borders()`: each starts with its
/// dart and is walked with `next()` (a flipped dart walks its loop the other
/// way), the k-th edges of the two walks corresponding. A chain of as many
/// edges as its border loop is the whole loop. `facing_borders()` and
/// `aligned_border_loops()` find one.
struct Border_pairing
{
  Dart first;                   ///< a border dart of the first mesh, the first edge of its chain
  Dart second;                  ///< a border dart of the second mesh, the first edge of its chain
  std::size_t first_edges = 0;  ///< the number of edges of the first chain
  std::size_t second_edges = 0; ///< the number of edges of the second chain
};

namespace internal {

// Bridging only (the in-place glue adds no faces): rebuilds `work` with the
// vertices of each class of `cls` identified (and `extra` polygons added, by
// class), through a soup: linear time, and the
// soup import finds every normal and Möbius connection and refuses what is
// not a 2-manifold. `position[c]` is the point of class c. Properties are
// carried over: faces one to one, a vertex from the lowest member of its
// class, an edge from the first of the edges glued into it.
template <class P>
Mobius_mesh<P> rebuild_glued(const Mobius_mesh<P>& work, const std::vector<std::uint32_t>& cls,
                             const std::vector<P>& position, const std::vector<std::vector<std::uint32_t>>& extra,
                             Merge_result& result)
{
  // The faces in one flat array of corners: a vector per face would cost
  // one allocation per face, a third of the whole merge.
  const std::size_t nf = work.number_of_faces();
  Face_list faces;
  faces.vertex.reserve(work.number_of_halfedges());
  faces.offset.reserve(nf + extra.size() + 1);
  for (Face_index f : work.faces()) {
    for (Dart d : CGAL_ext::halfedges_around_face(work.halfedge(f), work))
      faces.vertex.push_back(cls[work.source(d).idx()]);
    faces.offset.push_back(std::uint32_t(faces.vertex.size()));
  }
  for (const std::vector<std::uint32_t>& polygon : extra)
    faces.add(polygon.begin(), polygon.end());

  Mobius_mesh<P> out;
  try {
    build_mesh_from_faces(faces.view(std::uint32_t(position.size())), [&position](std::uint32_t v) { return position[v]; }, false, out);
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
                        "the merge would identify two vertices of one face (" + join_ids(vs, "v") +
                          "): is the tolerance larger than the mesh's edges?",
                        vs);
    case Soup_error::Kind::non_manifold_edge:
      throw Merge_error(K::non_manifold_edge,
                        "the merge would give the edge between " + join_ids(vs, "v") + " three or more faces", vs);
    default:
      throw Merge_error(K::non_manifold_vertex,
                        "the merge would make a non-manifold vertex of " + join_ids(vs, "v") +
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

// The border vertices, each with the border vertices within the tolerance
// of it: tables over the border only, not over every vertex of the mesh.
class Border_matches
{
public:
  using u32 = std::uint32_t;

  explicit Border_matches(std::vector<u32> border_vertices)
    : vertex_(std::move(border_vertices)), match_(vertex_.size())
  {}
  const std::vector<u32>& vertices() const { return vertex_; }
  /// The vertices matched with `v` (none if `v` is not on the border).
  const std::vector<u32>& operator[](u32 v) const
  {
    static const std::vector<u32> no_match;
    const u32 i = local(v);
    return i == none ? no_match : match_[i];
  }
  void add(u32 u, u32 w)
  {
    match_[local(u)].push_back(w);
    match_[local(w)].push_back(u);
  }

private:
  static constexpr u32 none = (std::numeric_limits<u32>::max)();
  u32 local(u32 v) const
  {
    const auto it = std::lower_bound(vertex_.begin(), vertex_.end(), v);
    return it != vertex_.end() && *it == v ? u32(it - vertex_.begin()) : none;
  }

  std::vector<u32> vertex_;
  std::vector<std::vector<u32>> match_;
};

// Border vertices within the tolerance of each other: those of [0, split)
// with those of [split, nv), or any two if `self`. Returns the number of
// close pairs.
template <class P, class Traits>
std::size_t close_border_vertices(const Mobius_mesh<P>& work, std::size_t split, bool self,
                                  const Close_points<Traits>& close, Border_matches& match)
{
  std::vector<std::uint32_t> first, second;
  for (std::uint32_t v : match.vertices())
    (self || v < split ? first : second).push_back(v);
  std::size_t n_pairs = 0;
  auto report = [&](std::uint32_t u, std::uint32_t w) {
    match.add(u, w);
    ++n_pairs;
  };
  auto point_of = [&work](std::uint32_t v) -> const P& { return work.point(Vertex_index(v)); };
  if (self)
    close.self_pairs(first, point_of, report);
  else
    close.cross_pairs(first, second, point_of, report);
  return n_pairs;
}

template <class P>
std::vector<std::uint32_t> border_vertices(const Mobius_mesh<P>& m)
{
  std::vector<std::uint32_t> vs;
  for (Vertex_index v : m.vertices())
    if (!m.is_isolated(v) && m.is_border(v))
      vs.push_back(v.idx());
  return vs;
}

// The border edges that border halfedge `b` (s -> t) may be glued to: those
// from a vertex matched with s (or s) to one matched with t (or t), with
// whether each runs the same way as b.
template <class P>
std::vector<std::pair<Halfedge_index, bool>> glue_candidates(const Mobius_mesh<P>& work, Halfedge_index b,
                                                             const Border_matches& match)
{
  const std::uint32_t s = work.source(Dart(b, false)).idx(), t = work.target(Dart(b, false)).idx();
  auto is_close = [&](std::uint32_t x, std::uint32_t y) {
    return x == y || std::find(match[x].begin(), match[x].end(), y) != match[x].end();
  };
  std::vector<std::pair<Halfedge_index, bool>> found;
  std::vector<std::uint32_t> around = match[s];
  around.push_back(s);
  for (std::uint32_t s2 : around) {
    const Dart in = work.halfedge(Vertex_index(s2)); // border dart into s2
    for (Dart c : {in, work.next(in)}) {
      if (c.halfedge() == b)
        continue;
      const std::uint32_t cs = work.source(c).idx(), ct = work.target(c).idx();
      const std::uint32_t other = cs == s2 ? ct : cs;
      if ((other == t && s2 == s) || !is_close(t, other) || (other == t && s2 != s && !is_close(s, s2)))
        continue;
      // Runs the same way as b if it leaves the vertex matched with s.
      const bool same = work.source(Dart(c.halfedge(), false)).idx() == s2;
      if (std::find_if(found.begin(), found.end(), [&](const auto& p) { return p.first == c.halfedge(); }) ==
          found.end())
        found.emplace_back(c.halfedge(), same);
    }
  }
  return found;
}

template <class P>
[[noreturn]] void throw_ambiguous_glue(const Mobius_mesh<P>& work, Halfedge_index b,
                                       const std::vector<std::pair<Halfedge_index, bool>>& found)
{
  const std::size_t s = work.source(Dart(b, false)).idx(), t = work.target(Dart(b, false)).idx();
  std::vector<std::size_t> vs = {s, t};
  for (const auto& candidate : found) {
    vs.push_back(work.source(Dart(candidate.first, false)).idx());
    vs.push_back(work.target(Dart(candidate.first, false)).idx());
  }
  throw Merge_error(Merge_error::Kind::non_manifold_edge,
                    "border edge (v" + std::to_string(s) + ", v" + std::to_string(t) + ") could be glued to " +
                      std::to_string(found.size()) + " border edges (" + join_ids(vs, "v") +
                      "): an edge takes at most two faces",
                    vs);
}

// The border halfedges at the border vertices, in increasing order.
template <class P>
std::vector<std::uint32_t> border_halfedges(const Mobius_mesh<P>& work, const Border_matches& match)
{
  std::vector<std::uint32_t> hs;
  for (std::uint32_t v : match.vertices()) {
    const Dart in = work.halfedge(Vertex_index(v));
    hs.push_back(in.halfedge().idx());
    hs.push_back(work.next(in).halfedge().idx());
  }
  std::sort(hs.begin(), hs.end());
  hs.erase(std::unique(hs.begin(), hs.end()), hs.end());
  return hs;
}

// Pairs the border edges to glue (each border edge takes at most one
// partner); records pairs and counts in `result` and returns the pairs as
// darts whose sources (and targets) are glued.
template <class P>
std::vector<Glue_pair> pair_border_edges(const Mobius_mesh<P>& work, const Border_matches& match,
                                         Merge_result& result)
{
  const std::vector<std::uint32_t> border = border_halfedges(work, match);
  auto local = [&border](Halfedge_index h) {
    return std::size_t(std::lower_bound(border.begin(), border.end(), h.idx()) - border.begin());
  };
  std::vector<bool> paired(border.size(), false);
  std::vector<Glue_pair> glue;
  for (std::uint32_t bi : border) {
    const Halfedge_index b(bi);
    if (paired[local(b)])
      continue;
    const std::uint32_t s = work.source(Dart(b, false)).idx(), t = work.target(Dart(b, false)).idx();
    if (match[s].empty() && match[t].empty())
      continue;
    const std::vector<std::pair<Halfedge_index, bool>> found = glue_candidates(work, b, match);
    if (found.empty())
      continue;
    if (found.size() > 1)
      throw_ambiguous_glue(work, b, found);
    const auto [g, same] = found[0];
    const std::uint32_t gs = work.source(Dart(g, false)).idx(), gt = work.target(Dart(g, false)).idx();
    if (paired[local(g)])
      throw Merge_error(Merge_error::Kind::non_manifold_edge,
                        "border edge (" + join_ids({gs, gt}, "v") + ") could be glued to two border edges",
                        {s, t, gs, gt});
    paired[local(b)] = paired[local(g)] = true;
    const std::uint32_t s2 = same ? gs : gt, t2 = same ? gt : gs;
    for (auto [x, y] : {std::make_pair(s, s2), std::make_pair(t, t2)})
      if (x != y)
        result.vertex_pairs.emplace_back((std::min)(x, y), (std::max)(x, y));
    glue.push_back({Dart(b, false), Dart(g, !same)});
    result.halfedge_pairs.emplace_back(b.idx(), g.idx());
    ++result.glued_edges;
    result.mobius_edges += same ? 1 : 0;
  }
  std::sort(result.vertex_pairs.begin(), result.vertex_pairs.end());
  result.vertex_pairs.erase(std::unique(result.vertex_pairs.begin(), result.vertex_pairs.end()),
                            result.vertex_pairs.end());
  return glue;
}

// Close pairs that glue no edge.
inline std::size_t count_ignored_pairs(const Border_matches& match, std::size_t close_pairs,
                                       const Merge_result& result)
{
  std::size_t used_pairs = 0;
  for (std::uint32_t u : match.vertices())
    for (std::uint32_t w : match[u])
      if (u < w && std::binary_search(result.vertex_pairs.begin(), result.vertex_pairs.end(),
                                      std::make_pair(std::size_t(u), std::size_t(w))))
        ++used_pairs;
  return close_pairs - used_pairs;
}

inline std::vector<Vertex_index> identity_vertex_map(std::size_t nv)
{
  std::vector<Vertex_index> map(nv);
  for (std::size_t v = 0; v < nv; ++v)
    map[v] = Vertex_index(v);
  return map;
}

// Glues `pairs` of border darts of `mesh` in place (see Border_glue);
// throws Merge_error, `mesh` unchanged, if the result is not a 2-manifold.
template <class P>
void glue_in_place(Mobius_mesh<P>& mesh, std::vector<Glue_pair> pairs, Merge_result& result)
{
  if (pairs.empty()) {
    result.vertex_map = identity_vertex_map(mesh.number_of_vertices());
    return;
  }
  const std::size_t given = pairs.size();
  Border_glue<P> glue(mesh, std::move(pairs));
  glue.check();
  // Border edges that end up between the same two vertices are glued too:
  // they count as the given pairs do (a Möbius edge where the faces agree).
  for (std::size_t i = given; i < glue.pairs().size(); ++i) {
    const Glue_pair& p = glue.pairs()[i];
    result.halfedge_pairs.emplace_back(p.first.halfedge().idx(), p.second.halfedge().idx());
    ++result.glued_edges;
    result.mobius_edges += p.second.is_flipped() ? 0 : 1;
  }
  result.merged_vertices = glue.apply(result.vertex_map);
}

// The automatic merge, in place on `mesh`: border vertices of [0, split)
// are matched with those of [split, nv) (any two if `self`).
template <class P, class NP>
Merge_result merge_borders_impl(Mobius_mesh<P>& mesh, std::size_t split, bool self, const NP& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Default_traits = typename CGAL::Kernel_traits<P>::Kernel;
  const auto traits = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  using Traits = std::decay_t<decltype(traits)>;
  const auto tolerance = choose_parameter(get_parameter(np, CGAL_ext::internal_np::tolerance), 0.0);
  const Close_points<Traits> close(traits, checked_tolerance<typename Traits::FT>(tolerance));
  Merge_result result;

  Border_matches match(border_vertices(mesh));
  const std::size_t close_pairs = close_border_vertices(mesh, split, self, close, match);
  std::vector<Glue_pair> pairs = pair_border_edges(mesh, match, result);
  result.ignored_vertex_pairs = count_ignored_pairs(match, close_pairs, result);
  glue_in_place(mesh, std::move(pairs), result);
  return result;
}

// Appends `b` to `a` for a merge, and takes it out again (`a` as it was)
// unless `keep()` is called: a failed merge leaves its first mesh unchanged.
template <class P>
class Joined
{
public:
  Joined(Mobius_mesh<P>& a, const Mobius_mesh<P>& b)
    : a_(a), nv_(a.num_vertices()), ne_(a.num_edges()), nf_(a.num_faces())
  {
    record<Vertex_index>(0);
    record<Halfedge_index>(1);
    record<Edge_index>(2);
    record<Face_index>(3);
    offsets_ = a.join(b);
  }
  Joined(const Joined&) = delete;
  Joined& operator=(const Joined&) = delete;
  ~Joined()
  {
    if (kept_)
      return;
    a_.resize(nv_, ne_, nf_);
    drop_added<Vertex_index>(0);
    drop_added<Halfedge_index>(1);
    drop_added<Edge_index>(2);
    drop_added<Face_index>(3);
  }
  void keep() { kept_ = true; }
  const typename Mobius_mesh<P>::Join_offsets& offsets() const { return offsets_; }

private:
  template <class I>
  void record(int k)
  {
    for (const auto& array : Connectivity_access::properties<I>(a_).arrays())
      arrays_[k].push_back(array.get());
  }
  // Property maps that only the second mesh had.
  template <class I>
  void drop_added(int k)
  {
    Property_container& props = Connectivity_access::properties<I>(a_);
    std::vector<const Base_property_array*> added;
    for (const auto& array : props.arrays())
      if (std::find(arrays_[k].begin(), arrays_[k].end(), array.get()) == arrays_[k].end())
        added.push_back(array.get());
    for (const Base_property_array* array : added)
      props.remove(array);
  }

  Mobius_mesh<P>& a_;
  typename Mobius_mesh<P>::size_type nv_, ne_, nf_;
  std::vector<const Base_property_array*> arrays_[4];
  typename Mobius_mesh<P>::Join_offsets offsets_{};
  bool kept_ = false;
};

template <class P>
void check_border_dart(const Mobius_mesh<P>& m, Dart d, const char* which)
{
  if (!m.is_valid(d) || !m.is_border(d))
    throw Merge_error(Merge_error::Kind::not_a_border,
                      std::string("the dart given for the ") + which + " mesh is not a border dart", {});
}

// The number of edges of the border loop of `d`.
template <class P>
std::size_t loop_length(const Mobius_mesh<P>& m, Dart d)
{
  std::size_t n = 0;
  for (Dart c : CGAL_ext::halfedges_around_face(d, m)) {
    (void)c;
    ++n;
  }
  return n;
}

// A chain of border edges to glue: its vertices (one more than its darts; on
// a whole loop the last is the first again) and its darts.
struct Border_chain
{
  std::vector<std::uint32_t> vertices;
  std::vector<Dart> darts;
  bool whole_loop = false;
  std::size_t edges() const { return darts.size(); }
};

// The chain of `edges` edges walked with next() from `d`, vertex indices shifted by `offset`.
template <class P>
Border_chain border_chain(const Mobius_mesh<P>& m, Dart d, std::size_t edges, std::uint32_t offset, const char* which)
{
  check_border_dart(m, d, which);
  const std::size_t loop_length = internal::loop_length(m, d);
  if (edges == 0 || edges > loop_length)
    throw Merge_error(Merge_error::Kind::mismatched_chains,
                      std::string("the ") + which + " chain has " + std::to_string(edges) +
                        " edges; its border loop has " + std::to_string(loop_length) + " (at least 1 needed)",
                      {m.source(d).idx() + std::size_t(offset)});
  Border_chain chain;
  chain.whole_loop = edges == loop_length;
  chain.vertices.push_back(m.source(d).idx() + offset);
  for (Dart c = d; chain.darts.size() < edges; c = m.next(c)) {
    chain.darts.push_back(c);
    chain.vertices.push_back(m.target(c).idx() + offset);
  }
  return chain;
}

// The faces bridging chains of n and m edges (vertex lists of n + 1 and
// m + 1): max(n, m) faces. Each face advances the longer chain by one edge;
// the shorter chain advances on min(n, m) of them, spread evenly (the k-th
// face advances it iff floor((k + 1) min / max) > floor(k min / max)). So
// min(n, m) quads, where both advance, and |n - m| triangles.
inline std::vector<std::vector<std::uint32_t>> bridge_faces(const std::vector<std::uint32_t>& a,
                                                            const std::vector<std::uint32_t>& b)
{
  const std::size_t n = a.size() - 1, m = b.size() - 1;
  const std::size_t longest = (std::max)(n, m), shortest = (std::min)(n, m);
  std::vector<std::vector<std::uint32_t>> faces;
  std::size_t i = 0, j = 0;
  for (std::size_t k = 0; k < longest; ++k) {
    const bool shorter_advances = (k + 1) * shortest / longest > k * shortest / longest;
    const bool a_advances = n >= m || shorter_advances, b_advances = m >= n || shorter_advances;
    if (a_advances && b_advances)
      faces.push_back({a[i], a[i + 1], b[j + 1], b[j]});
    else if (a_advances)
      faces.push_back({a[i], a[i + 1], b[j]});
    else
      faces.push_back({a[i], b[j + 1], b[j]});
    i += a_advances ? 1 : 0;
    j += b_advances ? 1 : 0;
  }
  return faces;
}

// A border loop walked with next() from one of its darts: darts[i] runs
// into the i-th vertex, whose point (rounded to doubles) is points[i].
struct Border_walk
{
  std::vector<Dart> darts;
  std::vector<Nearest_points::Point> points;
  std::size_t size() const { return darts.size(); }
  // The dart leaving the i-th vertex, walking on (next) or back (flipped).
  Dart leaving(std::size_t i, bool back) const { return back ? darts[i].flipped() : darts[(i + 1) % size()]; }
};

template <class P>
Border_walk border_walk(const Mobius_mesh<P>& m, Dart d)
{
  Border_walk w;
  for (Dart c : CGAL_ext::halfedges_around_face(d, m)) {
    w.darts.push_back(c);
    w.points.push_back(Nearest_points::rounded(m.point(m.target(c))));
  }
  return w;
}

// Squared distances compared with a relative slack: vertices placed
// symmetrically tie only up to rounding.
inline bool no_farther(double d2, double nearest_d2) { return d2 <= nearest_d2 * (1 + 1e-9); }

// The sum of squared distances of the pairing of two whole loops from their
// vertices i0 and j0, b walked on or back: the k-th vertex of a (of n) with
// the floor(k m / n)-th of b (of m).
inline double pairing_cost(const Border_walk& a, std::size_t i0, const Border_walk& b, std::size_t j0, bool back)
{
  const std::size_t n = a.size(), m = b.size();
  double cost = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t step = k * m / n;
    cost += CGAL::squared_distance(a.points[(i0 + k) % n], b.points[back ? (j0 + m - step) % m : (j0 + step) % m]);
  }
  return cost;
}

// Whole loops from the vertices i0 of a and j0 of b, b walked the way that
// keeps the two walks nearer: the pairing twists only where the loops do.
inline Border_pairing whole_loops(const Border_walk& a, std::size_t i0, const Border_walk& b, std::size_t j0)
{
  const bool back = pairing_cost(a, i0, b, j0, true) < pairing_cost(a, i0, b, j0, false);
  return {a.leaving(i0, false), b.leaving(j0, back), a.size(), b.size()};
}

// For each vertex of `from`: whether it is (up to ties) the vertex of `from`
// nearest to its own nearest vertex of `to`.
inline std::vector<bool> mutually_nearest(const Border_walk& from, const Border_walk& to)
{
  const Nearest_points near_from(from.points), near_to(to.points);
  std::vector<bool> mutual(from.size());
  for (std::size_t i = 0; i < from.size(); ++i) {
    const auto [j, d2] = near_to.nearest(from.points[i]);
    mutual[i] = no_farther(d2, near_from.nearest(to.points[j]).second);
  }
  return mutual;
}

// The run of consecutive `true`s around position s of a cyclic sequence:
// its first position and its length (the whole loop: every position).
inline std::pair<std::size_t, std::size_t> run_around(const std::vector<bool>& in_run, std::size_t s)
{
  const std::size_t n = in_run.size();
  std::size_t before = 0, after = 0;
  while (after + 1 < n && in_run[(s + after + 1) % n])
    ++after;
  while (before + after + 1 < n && in_run[(s + n - before - 1) % n])
    ++before;
  return {(s + n - before) % n, before + after + 1};
}

// The parts of two border loops that face each other, from a nearest pair
// of their vertices (i0 of a, j0 of b): the runs of mutually nearest
// vertices around them, or the whole loops if either run is a whole loop.
inline Border_pairing facing_parts(const Border_walk& a, std::size_t i0, const Border_walk& b, std::size_t j0)
{
  const auto [first_a, length_a] = run_around(mutually_nearest(a, b), i0);
  const auto [first_b, length_b] = run_around(mutually_nearest(b, a), j0);
  if (length_a == a.size() || length_b == b.size())
    return whole_loops(a, i0, b, j0);
  const std::size_t last_a = (first_a + length_a - 1) % a.size(), last_b = (first_b + length_b - 1) % b.size();
  // b's chain starts at the end nearer to the start of a's.
  const auto d2 = [](const Nearest_points::Point& p, const Nearest_points::Point& q) {
    return CGAL::squared_distance(p, q);
  };
  const bool back = d2(a.points[first_a], b.points[last_b]) + d2(a.points[last_a], b.points[first_b]) <
                    d2(a.points[first_a], b.points[first_b]) + d2(a.points[last_a], b.points[last_b]);
  return {a.leaving(first_a, false), b.leaving(back ? last_b : first_b, back), length_a - 1, length_b - 1};
}

// The vertex of `walks_a` nearest to a vertex of `walks_b` (a loop and a
// position in each); the first such pair on ties.
struct Nearest_pair
{
  std::size_t loop_a = 0, i = 0, loop_b = 0, j = 0;
};

inline Nearest_pair nearest_pair(const std::vector<Border_walk>& walks_a, const std::vector<Border_walk>& walks_b)
{
  std::vector<Nearest_points::Point> points;
  std::vector<std::pair<std::size_t, std::size_t>> where;
  for (std::size_t k = 0; k < walks_b.size(); ++k)
    for (std::size_t j = 0; j < walks_b[k].size(); ++j) {
      points.push_back(walks_b[k].points[j]);
      where.emplace_back(k, j);
    }
  const Nearest_points near_b(std::move(points));
  Nearest_pair best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < walks_a.size(); ++k)
    for (std::size_t i = 0; i < walks_a[k].size(); ++i) {
      const auto [at, d2] = near_b.nearest(walks_a[k].points[i]);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = {k, i, where[at].first, where[at].second};
      }
    }
  return best;
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
/// The glue is made in place, in time proportional to the glued border and
/// the fans around it (plus appending `mesh_b`, and finding the border):
/// each glued pair of edges becomes one edge, and the merged vertices and
/// the second edge of each pair are replaced by the last vertex or edge, so
/// the result has no removed elements. Faces keep their indices; a vertex or
/// edge moved into a freed slot changes its index (`Merge_result::vertex_map`
/// says where each vertex went).
///
/// Two vertices are within the tolerance iff their exact distance is at most
/// the exact value of the tolerance, on every kernel, as in the soup import:
/// no square root and no rounded square (floating-point coordinates are
/// decided by an interval filter, then exact rationals; exact kernels by
/// their own `Compare_squared_distance_3`). A point at exactly the tolerance
/// merges and one a unit in the last place further does not. A tolerance of
/// 0 glues exact coincidences only.
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
/// \throws Parameter_error for a negative, infinite or NaN tolerance, or a
///   point with a coordinate that is not finite.
/// \throws Merge_error if the glue would make a non-manifold edge (a border
///   edge with two candidate partners, or three faces at an edge) or vertex, or
///   collapse a face; both meshes are then left unchanged.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b,
                           const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh_a, "merge_borders");
  CGAL_ext::internal::require_no_garbage(mesh_b, "merge_borders");
  CGAL_ext::internal::require_finite_points(mesh_a, "merge_borders");
  CGAL_ext::internal::require_finite_points(mesh_b, "merge_borders");
  if (&mesh_a == &mesh_b) {
    const Mobius_mesh<P> copy = mesh_b;
    return merge_borders(mesh_a, copy, np);
  }
  internal::Joined<P> joined(mesh_a, mesh_b);
  Merge_result r = internal::merge_borders_impl(mesh_a, joined.offsets().vertices, false, np);
  joined.keep();
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
  CGAL_ext::internal::require_no_garbage(mesh, "merge_borders");
  CGAL_ext::internal::require_finite_points(mesh, "merge_borders");
  return internal::merge_borders_impl(mesh, mesh.number_of_vertices(), true, np);
}

/// \ingroup PkgMobiusMeshMerge
///
/// The border parts of `mesh_a` and `mesh_b` that face each other, for the
/// manual `merge_borders()`:
/// 1. the two border loops that hold the nearest two border vertices (one of
///    each mesh);
/// 2. on them, the runs of *mutually nearest* vertices around that pair (a
///    vertex is in the run if it is the vertex of its loop nearest to its own
///    nearest vertex of the other loop, ties allowed): the ends of two strip
///    halves facing each other, or, if either run is its whole loop, the
///    whole loops (the facing ends of two tubes);
/// 3. the correspondence: whole loops start at the nearest pair and the
///    second loop is walked the way that keeps the pairing nearer (the sum of
///    squared distances of corresponding vertices), so that the glue twists
///    only where the geometry does; open chains start at the nearer pairing of
///    their ends.
///
/// Distances are measured on the points rounded to doubles (a choice of what
/// to glue, not a geometric decision). The chains may differ in length:
/// only `Merge_strategy::bridge` joins those.
/// \throws Merge_error `not_a_border` if a mesh has no border.
/// \throws Parameter_error if a point has a coordinate that is not finite.
template <class P>
Border_pairing facing_borders(const Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b)
{
  CGAL_ext::internal::require_finite_points(mesh_a, "facing_borders");
  CGAL_ext::internal::require_finite_points(mesh_b, "facing_borders");
  const std::vector<Dart> loops_a = CGAL_ext::border_cycles(mesh_a), loops_b = CGAL_ext::border_cycles(mesh_b);
  if (loops_a.empty() || loops_b.empty())
    throw Merge_error(Merge_error::Kind::not_a_border,
                      std::string("the ") + (loops_a.empty() ? "first" : "second") + " mesh has no border", {});
  std::vector<internal::Border_walk> walks_a, walks_b;
  for (Dart d : loops_a)
    walks_a.push_back(internal::border_walk(mesh_a, d));
  for (Dart d : loops_b)
    walks_b.push_back(internal::border_walk(mesh_b, d));
  const internal::Nearest_pair p = internal::nearest_pair(walks_a, walks_b);
  return internal::facing_parts(walks_a[p.loop_a], p.i, walks_b[p.loop_b], p.j);
}

/// \ingroup PkgMobiusMeshMerge
///
/// The whole border loops of `loop_a` in `mesh_a` and `loop_b` in `mesh_b`
/// (any of their border darts), paired as `facing_borders()` pairs whole
/// loops: from their nearest two vertices, the second loop walked the way
/// that keeps the pairing nearer.
/// \throws Merge_error `not_a_border` if a dart is not a border dart.
/// \throws Parameter_error if a point has a coordinate that is not finite.
template <class P>
Border_pairing aligned_border_loops(const Mobius_mesh<P>& mesh_a, Dart loop_a, const Mobius_mesh<P>& mesh_b,
                                    Dart loop_b)
{
  internal::check_border_dart(mesh_a, loop_a, "first");
  internal::check_border_dart(mesh_b, loop_b, "second");
  CGAL_ext::internal::require_finite_points(mesh_a, "aligned_border_loops");
  CGAL_ext::internal::require_finite_points(mesh_b, "aligned_border_loops");
  const std::vector<internal::Border_walk> walk_a{internal::border_walk(mesh_a, loop_a)},
    walk_b{internal::border_walk(mesh_b, loop_b)};
  const internal::Nearest_pair p = internal::nearest_pair(walk_a, walk_b);
  return internal::whole_loops(walk_a[0], p.i, walk_b[0], p.j);
}

namespace internal {

// Bridging: the union of both meshes rebuilt through a soup with the new
// faces (new faces are the one thing the in-place glue does not make).
template <class P>
Merge_result bridge_chains(Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b, const Border_chain& chain_a,
                           const Border_chain& chain_b)
{
  Mobius_mesh<P> work = mesh_a;
  work.join(mesh_b);
  const std::size_t nv = work.number_of_vertices();
  Merge_result result;
  const std::vector<std::vector<std::uint32_t>> extra = bridge_faces(chain_a.vertices, chain_b.vertices);
  std::vector<std::uint32_t> cls(nv);
  std::vector<P> position(nv);
  for (std::uint32_t v = 0; v < nv; ++v) {
    cls[v] = v;
    position[v] = work.point(Vertex_index(v));
  }
  Mobius_mesh<P> out = rebuild_glued(work, cls, position, extra, result);
  result.mobius_edges = number_of_mobius_edges(out) - number_of_mobius_edges(work);
  mesh_a = std::move(out);
  return result;
}

// Identifies the k-th vertices and glues the k-th edges of two chains of
// equal length, in place in `mesh_a` (after `mesh_b` is appended), the
// glued vertices placed by `place(pa, pb)` (a null function keeps `pa`).
template <class P, class Place>
Merge_result glue_chains(Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b, const Border_chain& chain_a,
                         const Border_chain& chain_b, Place place)
{
  if (chain_a.edges() != chain_b.edges() || chain_a.whole_loop != chain_b.whole_loop) {
    auto describe = [](const Border_chain& c) {
      return std::to_string(c.edges()) + (c.whole_loop ? " (a whole loop)" : " (an open chain)");
    };
    throw Merge_error(Merge_error::Kind::mismatched_chains,
                      "the border chains have " + describe(chain_a) + " and " + describe(chain_b) +
                        " edges; only Merge_strategy::bridge joins chains that differ",
                      {chain_a.vertices.front(), chain_b.vertices.front()});
  }
  const std::uint32_t na = mesh_a.number_of_vertices(), ha = mesh_a.number_of_halfedges();
  Merge_result result;
  // A whole loop's last vertex is its first again.
  const std::size_t n_pairs = chain_a.vertices.size() - (chain_a.whole_loop ? 1 : 0);
  std::vector<P> placed;
  for (std::size_t i = 0; i < n_pairs; ++i) {
    const std::uint32_t va = chain_a.vertices[i], vb = chain_b.vertices[i];
    result.vertex_pairs.emplace_back(va, vb);
    placed.push_back(place(mesh_a.point(Vertex_index(va)), mesh_b.point(Vertex_index(vb - na))));
  }
  std::vector<Glue_pair> pairs;
  for (std::size_t k = 0; k < chain_a.edges(); ++k) {
    const Dart da = chain_a.darts[k], db = chain_b.darts[k];
    const Dart shifted(Halfedge_index(db.halfedge().idx() + ha), db.is_flipped());
    pairs.push_back({da, shifted});
    result.halfedge_pairs.emplace_back(da.halfedge().idx(), shifted.halfedge().idx());
    // Darts that both run with (or both against) their halfedges: the two
    // faces then run the same way along the glued edge.
    result.mobius_edges += da.is_flipped() == db.is_flipped() ? 1 : 0;
  }
  result.glued_edges = chain_a.edges();
  Joined<P> joined(mesh_a, mesh_b);
  glue_in_place(mesh_a, std::move(pairs), result);
  joined.keep();
  for (std::size_t i = 0; i < n_pairs; ++i)
    mesh_a.point(result.vertex_map[chain_a.vertices[i]]) = placed[i];
  return result;
}

} // namespace internal

/// \ingroup PkgMobiusMeshMerge
///
/// Glues the border chain `pairing.second` of `mesh_b` to the chain
/// `pairing.first` of `mesh_a`, whatever the distance between them, and puts
/// the result in `mesh_a`. The chains are walked with `next()` from their
/// darts, in step: the k-th edges correspond, and so do the k-th vertices
/// (the darts' sources first). If the two chains are walked against the
/// orientation of their faces in opposite senses (one dart flipped, one
/// not), the glue is orientable; otherwise the glued edges are Möbius edges.
///
/// - `Merge_strategy::keep_first`, `keep_second`, `average`: corresponding
///   vertices are identified at `mesh_a`'s position, `mesh_b`'s, or their
///   midpoint (exact with an exact kernel). The chains must have the same
///   number of edges and be both whole loops or both open.
/// - `Merge_strategy::bridge`: nothing moves; chains of n and m edges are
///   joined by max(n, m) new faces, each advancing the longer chain by one
///   edge: min(n, m) quads, where the shorter chain advances too, spread
///   evenly (the k-th face advances it iff floor((k+1) min / max) >
///   floor(k min / max)), and |n - m| triangles.
///
/// \param mesh_a the first mesh; it receives the result
/// \param mesh_b the second mesh
/// \param pairing the two border chains to glue, of `mesh_a` and `mesh_b`
/// \param strategy where the glued vertices go, or `Merge_strategy::bridge`
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
///   `mismatched_chains` if a chain has no edge or more than its loop, or
///   (not with `bridge`) the chains differ in length or in being whole loops,
///   or the kinds of the automatic merge if the result is not a 2-manifold;
///   both meshes are then left unchanged.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, const Mobius_mesh<P>& mesh_b, const Border_pairing& pairing,
                           Merge_strategy strategy, const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh_a, "merge_borders");
  CGAL_ext::internal::require_no_garbage(mesh_b, "merge_borders");
  if (&mesh_a == &mesh_b) {
    const Mobius_mesh<P> copy = mesh_b;
    return merge_borders(mesh_a, copy, pairing, strategy, np);
  }
  using Default_traits = typename CGAL::Kernel_traits<P>::Kernel;
  const auto traits =
    parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  const auto midpoint = traits.construct_midpoint_3_object();
  const std::uint32_t na = mesh_a.number_of_vertices();
  const internal::Border_chain chain_a = internal::border_chain(mesh_a, pairing.first, pairing.first_edges, 0, "first");
  const internal::Border_chain chain_b =
    internal::border_chain(mesh_b, pairing.second, pairing.second_edges, na, "second");
  switch (strategy) {
  case Merge_strategy::bridge:
    return internal::bridge_chains(mesh_a, mesh_b, chain_a, chain_b);
  case Merge_strategy::keep_second:
    return internal::glue_chains(mesh_a, mesh_b, chain_a, chain_b, [](const P&, const P& pb) { return pb; });
  case Merge_strategy::average:
    return internal::glue_chains(mesh_a, mesh_b, chain_a, chain_b,
                                 [&midpoint](const P& pa, const P& pb) { return P(midpoint(pa, pb)); });
  default:
    return internal::glue_chains(mesh_a, mesh_b, chain_a, chain_b, [](const P& pa, const P&) { return pa; });
  }
}

/// \ingroup PkgMobiusMeshMerge
///
/// Glues the whole border loop of `border_b` in `mesh_b` to the whole border
/// loop of `border_a` in `mesh_a`: the pairing overload with chains that are
/// the two loops walked from the two darts (the i-th vertices correspond,
/// starting with the darts' sources). Pass a flipped dart to walk a loop the
/// other way; `aligned_border_loops()` chooses the start and the way from
/// the geometry.
template <class P, class NamedParameters = parameters::Default_named_parameters>
Merge_result merge_borders(Mobius_mesh<P>& mesh_a, Dart border_a, const Mobius_mesh<P>& mesh_b, Dart border_b,
                           Merge_strategy strategy, const NamedParameters& np = parameters::default_values())
{
  internal::check_border_dart(mesh_a, border_a, "first");
  internal::check_border_dart(mesh_b, border_b, "second");
  const Border_pairing whole{border_a, border_b, internal::loop_length(mesh_a, border_a),
                             internal::loop_length(mesh_b, border_b)};
  return merge_borders(mesh_a, mesh_b, whole, strategy, np);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MERGE_BORDERS_H
