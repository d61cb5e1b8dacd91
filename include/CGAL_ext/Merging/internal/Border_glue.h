// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Gluing pairs of border edges of a Mobius_mesh in place, in time
// proportional to the glued border (the fans around the glued vertices),
// not to the mesh: the merges of merge_borders.h glue through it.

#ifndef CGAL_EXT_MERGING_INTERNAL_BORDER_GLUE_H
#define CGAL_EXT_MERGING_INTERNAL_BORDER_GLUE_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/exceptions.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

/// Two border darts to glue into one edge: their sources become one vertex,
/// and so do their targets. Darts that both run with their halfedges (or
/// both against) make a Möbius edge: their faces run the same way.
struct Glue_pair
{
  Dart first, second;
};

/// Glues border edges of `mesh` in place, in two phases:
/// - `check()` changes nothing and throws `Merge_error` (naming the input
///   vertices) if the result would not be a 2-manifold: a face with two
///   vertices of one glued class, an edge with three or more faces, or a
///   glued vertex whose fans do not join into one disc or one border fan.
///   These are the checks the soup import made on the whole rebuilt mesh;
///   only the glued vertices can fail them.
/// - `apply()` relinks each pair's two face halfedges into one edge, fixes
///   the border links and the stored darts around the glued vertices, and
///   removes the merged vertices and the second edge of each pair by moving
///   the last element into their slots. That keeps the mesh compact without
///   `collect_garbage()`, which would touch every element of every array.
///
/// What the rebuild through a soup made, up to element numbering: in a
/// glued class the lowest vertex stays (with its point and properties), a
/// glued edge keeps the edge (and properties) of the face met first in face
/// order, each face halfedge keeps its properties. Two border edges that end
/// up between the same two vertices without being paired are glued too, as
/// the soup import did.
template <class P>
class Border_glue
{
public:
  using u32 = std::uint32_t;
  using Mesh = Mobius_mesh<P>;

  Border_glue(Mesh& mesh, std::vector<Glue_pair> pairs) : m_(mesh), pairs_(std::move(pairs)) { index(); }

  /// Throws `Merge_error` if the glue is not a 2-manifold; the mesh is not changed.
  void check()
  {
    check_collapsed_faces();
    while (check_edges()) { // pairs were added: their ends may be new members
      index();
      check_collapsed_faces();
    }
    check_fans();
    // What apply() records, allocated now: apply() must not run out of
    // memory halfway through the relinking.
    moved_.reserve(pairs_.size());
    removed_edges_.reserve(pairs_.size());
    removed_vertices_.reserve(ends_.size());
    vertex_moves_.reserve(ends_.size());
  }

  /// The pairs to glue: those given, then those `check()` added.
  const std::vector<Glue_pair>& pairs() const { return pairs_; }

  /// Glues (after `check()`); `vertex_map[v]` receives the vertex that input
  /// vertex `v` became. Returns the number of vertices merged into others.
  std::size_t apply(std::vector<Vertex_index>& vertex_map)
  {
    vertex_map.resize(m_.num_vertices()); // before the first change, as every allocation
    retarget_members();
    for (const Glue_pair& p : pairs_)
      relink(p);
    std::sort(moved_.begin(), moved_.end());
    for (std::size_t c = 0; c + 1 < class_start_.size(); ++c)
      link_border_fan(c);
    return compact(vertex_map);
  }

private:
  static constexpr u32 none = (std::numeric_limits<u32>::max)();

  // ------------------------------------------------------------ indexing

  void index()
  {
    index_ends();
    collect_fans();
  }

  // The glued vertices ("members"), numbered locally in increasing order,
  // their classes (members identified transitively) and each class's
  // representative, its lowest member.
  void index_ends()
  {
    ends_.clear();
    class_start_.clear();
    for (const Glue_pair& p : pairs_)
      for (Dart d : {p.first, p.second}) {
        ends_.push_back(m_.source(d).idx());
        ends_.push_back(m_.target(d).idx());
      }
    std::sort(ends_.begin(), ends_.end());
    ends_.erase(std::unique(ends_.begin(), ends_.end()), ends_.end());
    const std::size_t n = ends_.size();
    std::vector<u32> rank(n), parent(n);
    boost::disjoint_sets<u32*, u32*> sets(rank.data(), parent.data());
    for (u32 i = 0; i < n; ++i)
      sets.make_set(i);
    for (const Glue_pair& p : pairs_) {
      sets.union_set(local(m_.source(p.first)), local(m_.source(p.second)));
      sets.union_set(local(m_.target(p.first)), local(m_.target(p.second)));
    }
    // Members in increasing order: the first met of each class is its representative.
    rep_.assign(n, none);
    std::vector<u32> rep_of_root(n, none);
    for (u32 i = 0; i < n; ++i) {
      u32& r = rep_of_root[sets.find_set(i)];
      if (r == none)
        r = ends_[i];
      rep_[i] = r;
    }
    // Members grouped by class.
    by_class_.resize(n);
    std::iota(by_class_.begin(), by_class_.end(), 0u);
    std::stable_sort(by_class_.begin(), by_class_.end(), [&](u32 a, u32 b) { return rep_[a] < rep_[b]; });
    for (u32 k = 0; k < n; ++k)
      if (k == 0 || rep_[by_class_[k]] != rep_[by_class_[k - 1]])
        class_start_.push_back(k);
    class_start_.push_back(u32(n));
  }

  u32 local(Vertex_index v) const
  {
    const auto it = std::lower_bound(ends_.begin(), ends_.end(), v.idx());
    return it != ends_.end() && *it == v.idx() ? u32(it - ends_.begin()) : none;
  }
  // The vertex `v` becomes (its representative if glued, else itself).
  u32 class_of(Vertex_index v) const
  {
    const u32 i = local(v);
    return i == none ? v.idx() : rep_[i];
  }
  std::vector<std::size_t> members_of(u32 rep) const
  {
    std::vector<std::size_t> vs;
    for (u32 i = 0; i < ends_.size(); ++i)
      if (rep_[i] == rep)
        vs.push_back(ends_[i]);
    return vs;
  }

  // The incoming darts of each member, read before anything changes.
  // (Each member is on the border: it has a face dart and a border dart.)
  void collect_fans()
  {
    fan_.clear();
    fan_start_.assign(1, 0);
    face_dart_.clear();
    partner_.clear();
    for (u32 w : ends_) {
      for (Dart d : CGAL_ext::halfedges_around_target(m_.halfedge(Vertex_index(w)), m_)) {
        fan_.push_back(d);
        if (face_dart_.size() < fan_start_.size() && !m_.is_border(d))
          face_dart_.push_back(d);
      }
      fan_start_.push_back(u32(fan_.size()));
    }
    for (const Glue_pair& p : pairs_) {
      partner_.emplace_back(p.first.halfedge().idx(), p.second.halfedge().idx());
      partner_.emplace_back(p.second.halfedge().idx(), p.first.halfedge().idx());
    }
    std::sort(partner_.begin(), partner_.end());
  }

  u32 partner(Halfedge_index h) const
  {
    const auto it = std::lower_bound(partner_.begin(), partner_.end(), std::make_pair(h.idx(), u32(0)));
    return it != partner_.end() && it->first == h.idx() ? it->second : none;
  }

  // ------------------------------------------------------------ checks

  void check_collapsed_faces() const
  {
    std::vector<u32> faces;
    for (std::size_t c = 0; c + 1 < class_start_.size(); ++c) {
      faces.clear();
      for (u32 k = class_start_[c]; k < class_start_[c + 1]; ++k) {
        const u32 i = by_class_[k];
        for (u32 t = fan_start_[i]; t < fan_start_[i + 1]; ++t)
          if (!m_.is_border(fan_[t]))
            faces.push_back(m_.face(fan_[t]).idx());
      }
      std::sort(faces.begin(), faces.end());
      if (std::adjacent_find(faces.begin(), faces.end()) != faces.end()) {
        const std::vector<std::size_t> vs = members_of(rep_[by_class_[class_start_[c]]]);
        throw Merge_error(Merge_error::Kind::collapsed_face,
                          "the merge would identify two vertices of one face (" + join_ids(vs, "v") +
                            "): is the tolerance larger than the mesh's edges?",
                          vs);
      }
    }
  }

  // The edges at the glued vertices, by the two vertices they will join:
  // one edge is fine, a glued pair is fine, two unpaired border edges are
  // glued too (the soup import did), anything more has three faces.
  // Returns whether pairs were added.
  bool check_edges()
  {
    const std::size_t n_pairs = pairs_.size();
    struct Entry
    {
      u32 lo, hi, edge;
      bool operator<(const Entry& o) const
      {
        return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : edge < o.edge;
      }
      bool same_ends(const Entry& o) const { return lo == o.lo && hi == o.hi; }
    };
    std::vector<Entry> entries;
    for (u32 i = 0; i < ends_.size(); ++i)
      for (u32 t = fan_start_[i]; t < fan_start_[i + 1]; ++t) {
        const u32 a = rep_[i], b = class_of(m_.source(fan_[t]));
        entries.push_back({(std::min)(a, b), (std::max)(a, b), m_.edge(fan_[t]).idx()});
      }
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end(),
                              [](const Entry& x, const Entry& y) { return x.same_ends(y) && x.edge == y.edge; }),
                  entries.end());
    for (std::size_t k = 0; k < entries.size();) {
      std::size_t end = k + 1;
      while (end < entries.size() && entries[end].same_ends(entries[k]))
        ++end;
      if (end - k >= 2)
        check_shared_ends(Edge_index(entries[k].edge), end - k == 2 ? Edge_index(entries[k + 1].edge) : Edge_index(),
                          entries[k].lo, entries[k].hi);
      k = end;
    }
    return pairs_.size() != n_pairs;
  }

  // Edges `e` and `f` (null if more than two) will join the same two vertices.
  void check_shared_ends(Edge_index e, Edge_index f, u32 lo, u32 hi)
  {
    auto border_halfedge = [this](Edge_index x) {
      for (unsigned i : {0u, 1u})
        if (m_.is_border(Mesh::halfedge(x, i)))
          return Mesh::halfedge(x, i);
      return Halfedge_index();
    };
    const Halfedge_index he = f.is_valid() ? border_halfedge(e) : Halfedge_index();
    const Halfedge_index hf = f.is_valid() ? border_halfedge(f) : Halfedge_index();
    if (!he.is_valid() || !hf.is_valid()) {
      std::vector<std::size_t> vs = members_of(lo);
      if (vs.empty())
        vs.push_back(lo);
      std::vector<std::size_t> more = members_of(hi);
      if (more.empty())
        more.push_back(hi);
      vs.insert(vs.end(), more.begin(), more.end());
      throw Merge_error(Merge_error::Kind::non_manifold_edge,
                        "the merge would give the edge between " + join_ids(vs, "v") + " three or more faces", vs);
    }
    if (partner(he) == hf.idx())
      return;
    // Unpaired: glue them, the sources of the two darts in one class.
    const Dart d(he, false);
    const bool same = class_of(m_.source(Dart(hf, false))) == class_of(m_.source(d));
    pairs_.push_back({d, Dart(hf, !same)});
    partner_.emplace_back(he.idx(), hf.idx());
    partner_.emplace_back(hf.idx(), he.idx());
    std::sort(partner_.begin(), partner_.end());
  }

  // The two border halfedges at member i: into it and out of it.
  std::pair<u32, u32> border_sides(u32 i) const
  {
    const Dart in = m_.halfedge(Vertex_index(ends_[i]));
    return {in.halfedge().idx(), m_.next(in).halfedge().idx()};
  }

  // Each member is one fan with two border sides; a glued pair joins a side
  // of one fan to a side of another (or of the same). The class is a
  // 2-manifold vertex iff the walk from fan to fan meets all its members.
  void check_fans() const
  {
    for (std::size_t c = 0; c + 1 < class_start_.size(); ++c) {
      const u32 first = by_class_[class_start_[c]];
      const u32 size = class_start_[c + 1] - class_start_[c];
      const auto [in0, out0] = border_sides(first);
      u32 met = 1;
      bool closed = false;
      for (u32 from : {out0, in0}) {
        u32 i = first, side = from;
        for (;;) {
          const u32 p = partner(Halfedge_index(side));
          if (p == none)
            break;
          i = member_at(Halfedge_index(p), rep_[first]);
          if (i == first) {
            closed = true;
            break;
          }
          if (++met > size)
            break;
          const auto [in, out] = border_sides(i);
          side = in == p ? out : in;
        }
        if (closed || met > size)
          break;
      }
      if (met != size) {
        const std::vector<std::size_t> vs = members_of(rep_[first]);
        throw Merge_error(Merge_error::Kind::non_manifold_vertex,
                          "the merge would make a non-manifold vertex of " + join_ids(vs, "v") +
                            " (its faces would form separate fans)",
                          vs);
      }
    }
  }

  // The member of class `rep` at an end of border halfedge `h`.
  u32 member_at(Halfedge_index h, u32 rep) const
  {
    const u32 s = local(m_.source(h));
    return s != none && rep_[s] == rep ? s : local(m_.target(h));
  }

  // ------------------------------------------------------------ changes

  // Every halfedge into a merged vertex now points to its representative.
  void retarget_members()
  {
    for (u32 i = 0; i < ends_.size(); ++i) {
      if (rep_[i] == ends_[i])
        continue;
      const Vertex_index w(ends_[i]), r(rep_[i]);
      for (u32 t = fan_start_[i]; t < fan_start_[i + 1]; ++t)
        for (unsigned k : {0u, 1u}) {
          const Halfedge_index x = Mesh::halfedge(m_.edge(fan_[t]), k);
          if (m_.target(x) == w)
            m_.set_target(x, r);
        }
    }
  }

  // Whether face halfedge `a` is met before `b` walking the faces in order,
  // each from its stored halfedge: whose edge the soup import kept.
  bool met_first(Halfedge_index a, Halfedge_index b) const
  {
    const Face_index fa = m_.face(a), fb = m_.face(b);
    if (fa != fb)
      return fa < fb;
    for (Dart d : CGAL_ext::halfedges_around_face(m_.halfedge(fa), m_))
      if (d.halfedge() == a || d.halfedge() == b)
        return d.halfedge() == a;
    return true;
  }

  // The pair's two face halfedges become the two halfedges of the edge of
  // the one met first: the other takes the slot of its border partner.
  void relink(const Glue_pair& p)
  {
    const Halfedge_index fa = Mesh::opposite_halfedge(p.first.halfedge());
    const Halfedge_index fb = Mesh::opposite_halfedge(p.second.halfedge());
    const bool a_stays = met_first(fa, fb);
    const Halfedge_index kept = a_stays ? fa : fb, moved = a_stays ? fb : fa;
    const Halfedge_index slot = Mesh::opposite_halfedge(kept);
    const Dart next = m_.next(Dart(moved)), prev = m_.prev(Dart(moved));
    const Face_index f = m_.face(moved);
    m_.set_target(slot, m_.target(moved));
    m_.set_face(slot, f);
    m_.set_mobius(Mesh::edge(slot), p.first.is_flipped() == p.second.is_flipped());
    m_.set_next(prev, Dart(slot));
    m_.set_next(Dart(slot), next);
    if (m_.halfedge(f).halfedge() == moved)
      m_.set_halfedge(f, slot);
    Connectivity_access::properties<Halfedge_index>(m_).copy(moved.idx(), slot.idx());
    moved_.emplace_back(moved.idx(), slot.idx());
    removed_edges_.push_back(Mesh::edge(moved).idx());
  }

  // Where a face dart read before the relinking is now.
  Dart where_now(Dart d) const
  {
    const auto it = std::lower_bound(moved_.begin(), moved_.end(), std::make_pair(d.halfedge().idx(), u32(0)));
    return it != moved_.end() && it->first == d.halfedge().idx() ? Dart(Halfedge_index(it->second), d.is_flipped())
                                                                 : d;
  }

  // Walks the fan of the class's representative through its faces and links
  // its two border darts, if it has any, as the soup import's builder does.
  void link_border_fan(std::size_t c)
  {
    const u32 i = by_class_[class_start_[c]];
    const Vertex_index rep(rep_[i]);
    // A dart that was a face dart before: a border slot may now hold another halfedge.
    const Dart start = where_now(face_dart_[i]);
    Dart in = start;
    for (;;) {
      const Dart o = m_.opposite(m_.next(in));
      if (o == start) {
        m_.set_halfedge(rep, start);
        return;
      }
      in = o;
      if (m_.is_border(in))
        break;
    }
    Dart out = m_.opposite(start);
    while (!m_.is_border(out))
      out = m_.opposite(m_.prev(out));
    m_.set_next(in, out);
    m_.set_halfedge(rep, in);
  }

  // Removes the merged vertices and the second edges of the pairs, the last
  // element moving into each freed slot; fills `vertex_map`.
  std::size_t compact(std::vector<Vertex_index>& vertex_map)
  {
    std::vector<u32>& removed_vertices = removed_vertices_;
    for (u32 i = 0; i < ends_.size(); ++i)
      if (rep_[i] != ends_[i])
        removed_vertices.push_back(ends_[i]);
    std::sort(removed_edges_.begin(), removed_edges_.end(), std::greater<u32>());
    u32 ne = m_.num_edges();
    for (u32 e : removed_edges_)
      if (e != --ne)
        move_edge(ne, e);
    const u32 nv_in = m_.num_vertices();
    u32 nv = nv_in;
    std::vector<std::pair<u32, u32>>& vertex_moves = vertex_moves_; // (from, to)
    for (auto it = removed_vertices.rbegin(); it != removed_vertices.rend(); ++it)
      if (*it != --nv) {
        move_vertex(nv, *it);
        vertex_moves.emplace_back(nv, *it);
      }
    m_.resize(nv, ne, m_.num_faces());

    for (u32 v = 0; v < nv_in; ++v)
      vertex_map[v] = Vertex_index(v);
    std::sort(vertex_moves.begin(), vertex_moves.end());
    auto now = [&](u32 v) {
      const auto it = std::lower_bound(vertex_moves.begin(), vertex_moves.end(), std::make_pair(v, u32(0)));
      return it != vertex_moves.end() && it->first == v ? it->second : v;
    };
    for (const auto& [from, to] : vertex_moves)
      vertex_map[from] = Vertex_index(to);
    for (u32 i = 0; i < ends_.size(); ++i)
      vertex_map[ends_[i]] = Vertex_index(now(rep_[i]));
    return removed_vertices.size();
  }

  // Edge `from` (with its halfedges) takes the slot of edge `to`, and every
  // link to it follows.
  void move_edge(u32 from, u32 to)
  {
    auto& hprops = Connectivity_access::properties<Halfedge_index>(m_);
    for (unsigned k : {0u, 1u}) {
      const Halfedge_index h = Mesh::halfedge(Edge_index(from), k), g = Mesh::halfedge(Edge_index(to), k);
      const Dart next = m_.next(Dart(h)), prev = m_.prev(Dart(h));
      m_.set_target(g, m_.target(h));
      m_.set_face(g, m_.face(h));
      m_.set_next(prev, Dart(g));
      m_.set_next(Dart(g), next);
      hprops.copy(h.idx(), g.idx());
      if (m_.face(g).is_valid() && m_.halfedge(m_.face(g)).halfedge() == h)
        m_.set_halfedge(m_.face(g), g);
    }
    m_.set_mobius(Edge_index(to), m_.is_mobius(Edge_index(from)));
    Connectivity_access::properties<Edge_index>(m_).copy(from, to);
    // The stored darts of its ends (a vertex's dart runs into it).
    for (unsigned k : {0u, 1u}) {
      const Halfedge_index h = Mesh::halfedge(Edge_index(from), k), g = Mesh::halfedge(Edge_index(to), k);
      for (Vertex_index v : {m_.source(g), m_.target(g)}) {
        const Dart d = m_.halfedge(v);
        if (d.halfedge() == h)
          m_.set_halfedge(v, Dart(g, d.is_flipped()));
      }
    }
  }

  // Vertex `from` takes the slot of vertex `to`; the halfedges into it follow.
  void move_vertex(u32 from, u32 to)
  {
    const Vertex_index v(from), w(to);
    m_.set_halfedge(w, m_.halfedge(v));
    Connectivity_access::properties<Vertex_index>(m_).copy(from, to);
    if (m_.is_isolated(w))
      return;
    for (Dart d : CGAL_ext::halfedges_around_target(m_.halfedge(w), m_))
      for (unsigned k : {0u, 1u}) {
        const Halfedge_index x = Mesh::halfedge(m_.edge(d), k);
        if (m_.target(x) == v)
          m_.set_target(x, w);
      }
  }

  Mesh& m_;
  std::vector<Glue_pair> pairs_;
  std::vector<u32> ends_, rep_, by_class_, class_start_;
  std::vector<Dart> fan_, face_dart_;
  std::vector<u32> fan_start_;
  std::vector<std::pair<u32, u32>> partner_, moved_, vertex_moves_;
  std::vector<u32> removed_edges_, removed_vertices_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MERGING_INTERNAL_BORDER_GLUE_H
