// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Per-face data of the triangles round an edge collapse, read before the
// collapse and found again after it.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_TRIANGLES_ROUND_COLLAPSE_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_TRIANGLES_ROUND_COLLAPSE_H

#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Euler::collapse_edge() chooses which neighbour of a removed triangle keeps
// its face index and which of two corners survives, so data kept per face or
// per corner cannot be carried by index through it. A triangle round either
// end of the edge, but the two along it, keeps its two vertices other than
// the ends: they name it after the collapse as before (the collapse's link
// condition makes the name unique). This is the one place that names them so.
template <class Data>
class Triangles_round_collapse
{
public:
  // The darts of one triangle: `at_end` ends at its corner at an end of the
  // edge (the kept vertex, after the collapse), `at_x` and `at_y` at its two
  // other corners, the vertex of `at_x` the lower.
  struct Darts
  {
    Dart at_end, at_x, at_y;
  };

  Triangles_round_collapse() = default;

  // Keeps read(darts) of each triangle round either end of c but the two
  // along c; target(darts.at_end) tells which end.
  template <class P, class Read>
  Triangles_round_collapse(const Mobius_mesh<P>& m, Dart c, Read read)
  {
    const Face_index along[2] = {m.face(c), m.face(m.opposite(c))};
    for (Dart side : {c, m.opposite(c)})
      for (Dart h : CGAL_ext::halfedges_around_target(side, m))
        if (!m.is_border(h) && m.face(h) != along[0] && m.face(h) != along[1]) {
          const Darts darts = darts_of(m, h);
          entries_.push_back({m.target(darts.at_x), m.target(darts.at_y), read(darts)});
        }
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return key(a) < key(b); });
  }

  bool empty() const { return entries_.empty(); }

  // Calls write(darts, data) for each triangle round `kept` after the
  // collapse, with the data read of the triangle of the same name.
  template <class P, class Write>
  void for_each_after(const Mobius_mesh<P>& m, Vertex_index kept, Write write) const
  {
    if (entries_.empty())
      return;
    for (Dart h : CGAL_ext::halfedges_around_target(m.halfedge(kept), m)) {
      if (m.is_border(h))
        continue;
      const Darts darts = darts_of(m, h);
      const auto name = std::make_tuple(m.target(darts.at_x), m.target(darts.at_y));
      const auto at = std::lower_bound(entries_.begin(), entries_.end(), name,
                                       [](const Entry& e, const auto& n) { return key(e) < n; });
      CGAL_assertion(at != entries_.end() && key(*at) == name);
      if (at != entries_.end() && key(*at) == name)
        write(darts, at->data);
    }
  }

private:
  struct Entry
  {
    Vertex_index x, y;
    Data data;
  };
  static std::tuple<Vertex_index, Vertex_index> key(const Entry& e) { return std::make_tuple(e.x, e.y); }

  template <class P>
  static Darts darts_of(const Mobius_mesh<P>& m, Dart at_end)
  {
    Dart at_x = m.next(at_end), at_y = m.next(at_x);
    if (m.target(at_y) < m.target(at_x))
      std::swap(at_x, at_y);
    return {at_end, at_x, at_y};
  }

  std::vector<Entry> entries_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_TRIANGLES_ROUND_COLLAPSE_H
