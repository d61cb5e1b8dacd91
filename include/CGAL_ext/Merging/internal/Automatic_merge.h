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
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

template <class P>
std::vector<std::uint32_t> border_vertices(const Mobius_mesh<P>& m)
{
  std::vector<std::uint32_t> vs;
  for (Vertex_index v : m.vertices())
    if (!m.is_isolated(v) && m.is_border(v))
      vs.push_back(v.idx());
  return vs;
}

// The border halfedges at the border vertices `vs`, in increasing order.
template <class P>
std::vector<std::uint32_t> border_halfedges(const Mobius_mesh<P>& work, const std::vector<std::uint32_t>& vs)
{
  std::vector<std::uint32_t> hs;
  for (std::uint32_t v : vs) {
    const Dart in = work.halfedge(Vertex_index(v));
    hs.push_back(in.halfedge().idx());
    hs.push_back(work.next(in).halfedge().idx());
  }
  std::sort(hs.begin(), hs.end());
  hs.erase(std::unique(hs.begin(), hs.end()), hs.end());
  return hs;
}

// The border as the glue sees it. Two border vertices match if they are
// within the tolerance: any two (`self`), or one of [0, split) and one of
// [split, nv) (the two meshes' "parts"). Coincident vertices are grouped
// into classes first, and matches are decided per pair of classes: a
// soup of duplicated faces puts thousands of vertices at one point, whose
// pairs, quadratic in number, are counted and never listed. Border edges
// are indexed by the classes of their ends, so that the edges a border edge
// may be glued to are looked up rather than searched for: near-linear time
// in the border (and in the pairs of distinct close classes).
class Border_classes
{
public:
  using u32 = std::uint32_t;

  // A border edge seen from its end `x` (its other end `y`), keyed by the
  // classes of x and y and its part: each edge has an entry from both ends.
  struct Entry
  {
    u32 from, part, to, halfedge, x, y;
  };
  using Entries = std::pair<const Entry*, const Entry*>;

  template <class P, class Traits>
  Border_classes(const Mobius_mesh<P>& work, std::size_t split, bool self, const Close_points<Traits>& close)
    : vertex_(border_vertices(work)), halfedge_(border_halfedges(work, vertex_)), split_(split), self_(self)
  {
    auto point_of = [&work](u32 v) -> const P& { return work.point(Vertex_index(v)); };
    const Coincident_groups groups = close.coincident(vertex_, point_of);
    class_ = groups.group;
    n_classes_ = groups.size();
    count_.assign(2 * std::size_t(n_classes_), 0);
    for (u32 i = 0; i < vertex_.size(); ++i)
      ++count_[2 * std::size_t(class_[i]) + part_of(vertex_[i])];
    // One point per class: its first vertex.
    std::vector<std::pair<u32, u32>> close_classes;
    close.self_pairs(groups.first, [&](u32 i) -> const P& { return point_of(vertex_[i]); },
                     [&](u32 i, u32 j) { close_classes.emplace_back(class_[i], class_[j]); });
    index_near(std::move(close_classes));
    index_edges(work);
  }

  const std::vector<u32>& halfedges() const { return halfedge_; }
  u32 class_of(Vertex_index v) const { return class_[local(v.idx())]; }
  u32 part_of(u32 v) const { return self_ || v < split_ ? 0 : 1; }
  // The part whose vertices match those of `part`.
  u32 matching_part(u32 part) const { return self_ ? 0 : 1 - part; }

  // Class c and the classes within the tolerance of it, c first, then in increasing order.
  std::pair<const u32*, const u32*> near(u32 c) const
  {
    return {near_.data() + near_start_[c], near_.data() + near_start_[c + 1]};
  }
  bool is_near(u32 c, u32 d) const
  {
    const auto [begin, end] = near(c);
    return d == c || std::binary_search(begin + 1, end, d);
  }
  // The entries of the border edges of `part` seen from an end in class c, by the other end's class.
  Entries entries(u32 part, u32 c) const
  {
    const std::size_t k = 2 * std::size_t(c) + part;
    return {entry_.data() + entry_start_[k], entry_.data() + entry_start_[k + 1]};
  }

  // The number of matching vertex pairs: k(k - 1)/2 in a class of k
  // vertices (of one part with k' of the other: k k'), and the products of
  // the sizes of two classes within the tolerance of each other.
  std::size_t matching_pairs() const
  {
    std::size_t n = 0;
    for (u32 c = 0; c < n_classes_; ++c) {
      const std::size_t a = count(c, 0), b = count(c, 1);
      n += self_ ? (a > 1 ? a * (a - 1) / 2 : 0) : a * b;
      const auto [begin, end] = near(c);
      for (const u32* d = begin + 1; d != end; ++d)
        if (*d > c)
          n += self_ ? a * count(*d, 0) : a * count(*d, 1) + b * count(*d, 0);
    }
    return n;
  }

private:
  u32 local(u32 v) const { return u32(std::lower_bound(vertex_.begin(), vertex_.end(), v) - vertex_.begin()); }
  std::size_t count(u32 c, u32 part) const { return count_[2 * std::size_t(c) + part]; }

  // The lists of near(), from the pairs of distinct close classes.
  void index_near(std::vector<std::pair<u32, u32>> pairs)
  {
    const std::size_t n = pairs.size();
    for (std::size_t i = 0; i < n; ++i)
      pairs.emplace_back(pairs[i].second, pairs[i].first);
    std::sort(pairs.begin(), pairs.end());
    near_start_.assign(std::size_t(n_classes_) + 1, 0);
    near_.reserve(n_classes_ + pairs.size());
    std::size_t k = 0;
    for (u32 c = 0; c < n_classes_; ++c) {
      near_start_[c] = near_.size();
      near_.push_back(c);
      for (; k < pairs.size() && pairs[k].first == c; ++k)
        near_.push_back(pairs[k].second);
    }
    near_start_[n_classes_] = near_.size();
  }

  // Two entries per border edge, grouped by the class of `x` and the part,
  // then by the class of `y`, then by halfedge: the halfedges are in
  // increasing order, and two stable counting sorts keep that order, in
  // linear time.
  template <class P>
  void index_edges(const Mobius_mesh<P>& work)
  {
    entry_.reserve(2 * halfedge_.size());
    for (u32 h : halfedge_) {
      const u32 s = work.source(Dart(Halfedge_index(h), false)).idx();
      const u32 t = work.target(Dart(Halfedge_index(h), false)).idx();
      const u32 cs = class_[local(s)], ct = class_[local(t)];
      entry_.push_back({cs, part_of(s), ct, h, s, t});
      entry_.push_back({ct, part_of(t), cs, h, t, s});
    }
    std::vector<Entry> scratch(entry_.size());
    std::vector<std::size_t> by_to;
    sort_by(entry_, scratch, n_classes_, [](const Entry& e) { return std::size_t(e.to); }, by_to);
    sort_by(entry_, scratch, 2 * std::size_t(n_classes_),
            [](const Entry& e) { return 2 * std::size_t(e.from) + e.part; }, entry_start_);
  }

  // Sorts `entries` stably by `key` (< n_keys) through `scratch` (of their
  // size); `start[k]` receives the position of the first entry of key k
  // (and start[n_keys] their number).
  template <class Key>
  static void sort_by(std::vector<Entry>& entries, std::vector<Entry>& scratch, std::size_t n_keys, Key key,
                      std::vector<std::size_t>& start)
  {
    start.assign(n_keys + 1, 0);
    for (const Entry& e : entries)
      ++start[key(e) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (const Entry& e : entries)
      scratch[next[key(e)]++] = e;
    entries.swap(scratch);
  }

  std::vector<u32> vertex_, halfedge_;
  std::size_t split_;
  bool self_;
  std::vector<u32> class_; // of each border vertex
  u32 n_classes_ = 0;
  std::vector<std::size_t> count_;                  // vertices of each class and part
  std::vector<std::size_t> near_start_, entry_start_; // offsets into near_ and entry_
  std::vector<u32> near_;
  std::vector<Entry> entry_;
};

// Calls `visit(entry)` for each border edge that border halfedge `b` (s -> t)
// may be glued to, seen from its end x matched with s (y matched with t),
// until `visit` returns true: the edges of the matching part from a vertex
// of s's class or a class near it to one of t's or near it, but b itself and
// another edge from s to t. An edge with both ends near both s and t is
// visited from both ends, the end in the class first met first: s's class,
// then its near classes in increasing order.
template <class P, class Visit>
void visit_glue_candidates(const Mobius_mesh<P>& work, Halfedge_index b, const Border_classes& bc, Visit visit)
{
  using Entry = Border_classes::Entry;
  const Vertex_index s = work.source(Dart(b, false)), t = work.target(Dart(b, false));
  const std::uint32_t ct = bc.class_of(t), part = bc.matching_part(bc.part_of(s.idx()));
  auto candidate = [&](const Entry& e) { return e.halfedge != b.idx() && (e.x != s.idx() || e.y != t.idx()); };
  const auto [near_t, near_t_end] = bc.near(ct);
  const auto [near_s, near_s_end] = bc.near(bc.class_of(s));
  for (const std::uint32_t* cx = near_s; cx != near_s_end; ++cx) {
    const auto [begin, end] = bc.entries(part, *cx);
    // Whichever is shorter: the edges from class *cx, or the classes near t
    // (many edges leave a class of many coincident vertices; a class may be
    // near many classes under a large tolerance).
    if (end - begin <= near_t_end - near_t) {
      for (const Entry* e = begin; e != end; ++e)
        if (bc.is_near(ct, e->to) && candidate(*e) && visit(*e))
          return;
      continue;
    }
    for (const std::uint32_t* cy = near_t; cy != near_t_end; ++cy) {
      const Entry* e = std::lower_bound(begin, end, *cy, [](const Entry& x, std::uint32_t c) { return x.to < c; });
      for (; e != end && e->to == *cy; ++e)
        if (candidate(*e) && visit(*e))
          return;
    }
  }
}

// A border edge that a border halfedge may be glued to, with whether it
// runs the same way (from the vertex matched with the halfedge's source).
using Glue_candidate = std::pair<Halfedge_index, bool>;

// The candidates of border halfedge `b`, but at most two: one is glued to b,
// two already make an error.
template <class P>
std::vector<Glue_candidate> first_glue_candidates(const Mobius_mesh<P>& work, Halfedge_index b,
                                                  const Border_classes& bc)
{
  std::vector<Glue_candidate> found;
  visit_glue_candidates(work, b, bc, [&](const Border_classes::Entry& e) {
    const Halfedge_index h(e.halfedge);
    if (found.empty() || found[0].first != h)
      found.emplace_back(h, work.source(Dart(h, false)).idx() == e.x);
    return found.size() == 2;
  });
  return found;
}

// All the candidates of border halfedge `b` (each once, from the end met
// first), for the message of the error they make.
template <class P>
std::vector<Glue_candidate> all_glue_candidates(const Mobius_mesh<P>& work, Halfedge_index b,
                                                const Border_classes& bc)
{
  std::vector<Glue_candidate> met;
  visit_glue_candidates(work, b, bc, [&](const Border_classes::Entry& e) {
    const Halfedge_index h(e.halfedge);
    met.emplace_back(h, work.source(Dart(h, false)).idx() == e.x);
    return false;
  });
  // Without the second visits of edges met from both ends (in time
  // n log n: a class of many coincident vertices has many candidates).
  std::vector<std::size_t> order(met.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&met](std::size_t i, std::size_t j) { return met[i].first < met[j].first; });
  std::vector<bool> again(met.size(), false);
  for (std::size_t k = 1; k < order.size(); ++k)
    again[order[k]] = met[order[k]].first == met[order[k - 1]].first;
  std::vector<Glue_candidate> found;
  for (std::size_t i = 0; i < met.size(); ++i)
    if (!again[i])
      found.push_back(met[i]);
  return found;
}

template <class P>
[[noreturn]] void throw_ambiguous_glue(const Mobius_mesh<P>& work, Halfedge_index b,
                                       const std::vector<Glue_candidate>& found)
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

// Pairs the border edges to glue (each border edge takes at most one
// partner); records pairs and counts in `result` and returns the pairs as
// darts whose sources (and targets) are glued.
template <class P>
std::vector<Glue_pair> pair_border_edges(const Mobius_mesh<P>& work, const Border_classes& bc, Merge_result& result)
{
  const std::vector<std::uint32_t>& border = bc.halfedges();
  auto local = [&border](Halfedge_index h) {
    return std::size_t(std::lower_bound(border.begin(), border.end(), h.idx()) - border.begin());
  };
  std::vector<bool> paired(border.size(), false);
  std::vector<Glue_pair> glue;
  for (std::uint32_t bi : border) {
    const Halfedge_index b(bi);
    if (paired[local(b)])
      continue;
    const std::vector<Glue_candidate> found = first_glue_candidates(work, b, bc);
    if (found.empty())
      continue;
    if (found.size() > 1)
      throw_ambiguous_glue(work, b, all_glue_candidates(work, b, bc));
    const std::uint32_t s = work.source(Dart(b, false)).idx(), t = work.target(Dart(b, false)).idx();
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

  const Border_classes border(mesh, split, self, close);
  std::vector<Glue_pair> pairs = pair_border_edges(mesh, border, result);
  // Each identified pair matches (its vertices are within the tolerance);
  // the other matching pairs glue no edge.
  result.ignored_vertex_pairs = border.matching_pairs() - result.vertex_pairs.size();
  glue_in_place(mesh, std::move(pairs), result);
  return result;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MERGING_INTERNAL_AUTOMATIC_MERGE_H
