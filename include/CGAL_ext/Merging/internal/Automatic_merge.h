// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The automatic merge of merge_borders.h: border vertices within the
// tolerance of each other (decided exactly), the border edges whose ends match
// paired, and the pairs glued in place.

#ifndef CGAL_EXT_MERGING_INTERNAL_AUTOMATIC_MERGE_H
#define CGAL_EXT_MERGING_INTERNAL_AUTOMATIC_MERGE_H

#include <CGAL_ext/Merging/Merge_types.h>
#include <CGAL_ext/Merging/internal/Border_glue.h>
#include <CGAL_ext/Merging/internal/Merged_mesh.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Close_points.h>

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
namespace internal {

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

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MERGING_INTERNAL_AUTOMATIC_MERGE_H
