// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Polygons that visit a vertex twice, held as manifold sheets: the step of
// the soup import (non_manifold_policy split) that runs before the
// connectivity builder.
//
// OpenSubdiv's Vtr takes such polygons: a degenerate edge (v, v) is an edge
// of its own, never shared; a vertex pair that a polygon runs along twice
// gets a second edge (both non-manifold); a vertex whose corners do not form
// one fan is non-manifold. The sheets hold this once each corner fan of a
// repeated vertex has a vertex of its own: the corners of vertex v are
// joined across the edges OpenSubdiv makes two-sided (a pair of distinct
// vertices run along by exactly two polygons, once each) and every further
// fan gets a copy of v. A polygon may still visit a vertex twice within one
// fan: the builder is told of the further corners there (folded corners),
// which it lets the polygon visit again, and pairs the sides as OpenSubdiv
// pairs them (a degenerate side between two such visits becomes a loop).

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_REPEATED_VERTEX_SPLIT_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_REPEATED_VERTEX_SPLIT_H

#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Union_find.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

class Repeated_vertex_split
{
public:
  using u32 = std::uint32_t;

  // Gives each further corner fan of a vertex that a polygon of `flat`
  // visits twice a new vertex (numbered from `n_vertices` on) and renames
  // its corners; `original()` then names the vertex each new one copies.
  // Throws Soup_error where the sheets cannot hold the polygons as
  // OpenSubdiv does (see rename_fans()).
  Repeated_vertex_split(Face_list& flat, u32 n_vertices) : flat_(flat), n_vertices_(n_vertices)
  {
    find_repeated_corners();
    if (corners_.empty())
      return;
    count_sides();
    std::vector<u32> fan = corner_fans();
    rename_fans(fan);
    check_mesh_size("the polygon soup with a vertex per corner fan",
                    Mesh_size{std::size_t(n_vertices_) + original_.size(), 0, 0, 0});
    find_lone_sides();
  }

  // How many corners of polygons are at a vertex the polygon visited
  // before, in the same fan (see rename_fans()).
  std::size_t number_of_folded_corners() const { return folded_corners_.size(); }

  // The vertex that new vertex `n_vertices + k` copies, for each k.
  const std::vector<u32>& original() const { return original_; }

  // `flat` for the builder, with the sides that must stay borders.
  Face_lists view() const
  {
    Face_lists faces = flat_.view(n_vertices_ + u32(original_.size()));
    faces.lone_side = lone_sides_.data();
    faces.n_lone_sides = lone_sides_.size();
    faces.folded_corner = folded_corners_.data();
    faces.n_folded_corners = folded_corners_.size();
    return faces;
  }

private:
  struct Side_count
  {
    u32 count = 0;
    u32 face = 0;           // the face of the first side
    u32 first_from = 0;     // the vertex the first side starts at
    bool same_face = false; // a face runs along the pair twice
    bool same_way = false;  // two sides run from the same end
  };

  static std::uint64_t key(u32 a, u32 b) { return std::uint64_t((std::min)(a, b)) << 32 | (std::max)(a, b); }
  u32 face_size(u32 f) const { return flat_.offset[f + 1] - flat_.offset[f]; }
  // The corner after corner i of face f (i in [0, size)), as a flat index.
  u32 next_in_face(u32 f, u32 i) const { return flat_.offset[f] + (i + 1) % face_size(f); }
  // The corner before corner i of face f, as a flat index.
  u32 prev_in_face(u32 f, u32 i) const { return flat_.offset[f] + (i + face_size(f) - 1) % face_size(f); }

  // The corners of the vertices some polygon visits twice, as flat indices.
  void find_repeated_corners()
  {
    std::vector<bool> repeated(n_vertices_, false);
    std::vector<u32> seen_in(n_vertices_, ~u32(0));
    for (u32 f = 0; f + 1 < u32(flat_.offset.size()); ++f)
      for (u32 t = flat_.offset[f]; t < flat_.offset[f + 1]; ++t) {
        const u32 v = flat_.vertex[t];
        repeated[v] = repeated[v] || seen_in[v] == f;
        seen_in[v] = f;
      }
    for (u32 f = 0; f + 1 < u32(flat_.offset.size()); ++f)
      for (u32 t = flat_.offset[f]; t < flat_.offset[f + 1]; ++t)
        if (repeated[flat_.vertex[t]]) {
          by_vertex_.emplace_back(flat_.vertex[t], u32(corners_.size()));
          corners_.push_back(t);
          face_.push_back(f);
        }
    std::sort(by_vertex_.begin(), by_vertex_.end());
  }

  // Calls fn(face, from, to) once for each side of a polygon (from corner
  // `from` to corner `to`, flat indices) with a repeated vertex at an end.
  template <class Fn>
  void for_each_side_at_repeated(Fn fn) const
  {
    for (std::size_t k = 0; k < corners_.size(); ++k) {
      const u32 f = face_[k], t = corners_[k], i = t - flat_.offset[f];
      const u32 prev = prev_in_face(f, i);
      fn(f, t, next_in_face(f, i));
      if (!is_repeated_corner(prev)) // else met as that corner's next side
        fn(f, prev, t);
    }
  }
  bool is_repeated_corner(u32 t) const { return std::binary_search(corners_.begin(), corners_.end(), t); }

  // How many polygon sides run along each pair of vertices at a repeated
  // vertex, whether one polygon runs along it twice, and whether two run
  // along it the same way.
  void count_sides()
  {
    for_each_side_at_repeated([&](u32 f, u32 from, u32 to) {
      const u32 a = flat_.vertex[from], b = flat_.vertex[to];
      auto [it, added] = sides_.emplace(key(a, b), Side_count{0, f, a, false, false});
      Side_count& c = it->second;
      c.same_face = c.same_face || (!added && c.face == f);
      c.same_way = c.same_way || (!added && c.first_from == a);
      ++c.count;
    });
  }

  // Two-sided in OpenSubdiv's terms: distinct ends, two sides, two faces.
  bool is_two_sided(u32 a, u32 b) const
  {
    const Side_count& c = sides_.at(key(a, b));
    return a != b && c.count == 2 && !c.same_face;
  }

  // The fan of each repeated corner (an index in corners_ standing for its
  // class): the corners at one vertex joined across two-sided sides.
  std::vector<u32> corner_fans()
  {
    Union_find fans(u32(corners_.size()));
    // For each two-sided pair, the first corner met at each of its ends.
    std::unordered_map<std::uint64_t, std::array<u32, 2>> first_corner;
    for (std::size_t k = 0; k < corners_.size(); ++k) {
      const u32 f = face_[k], i = corners_[k] - flat_.offset[f], v = flat_.vertex[corners_[k]];
      const u32 prev = flat_.vertex[prev_in_face(f, i)];
      const u32 next = flat_.vertex[next_in_face(f, i)];
      for (const u32 w : {prev, next}) {
        if (!is_two_sided(v, w))
          continue;
        u32& first = first_corner.emplace(key(v, w), std::array<u32, 2>{no_corner, no_corner})
                       .first->second[v < w ? 0 : 1];
        if (first == no_corner)
          first = u32(k);
        else
          fans.unite(first, u32(k));
      }
    }
    std::vector<u32> fan(corners_.size());
    for (std::size_t k = 0; k < corners_.size(); ++k)
      fan[k] = fans.find(u32(k));
    return fan;
  }
  static constexpr u32 no_corner = ~u32(0);

  // The first fan of each vertex keeps it; each further fan gets a copy. A
  // fan that holds two corners of one polygon stays one vertex, which the
  // polygon visits again at its further corners there (folded corners): the
  // two ends of a degenerate side (v, v), which becomes a loop, a border edge
  // from the vertex to itself and a border loop of its own (what OpenSubdiv
  // makes of it, a non-manifold edge of its own), or any two corners of a
  // vertex that OpenSubdiv makes non-manifold (see why_not_held()).
  void rename_fans(const std::vector<u32>& fan)
  {
    std::unordered_map<u32, u32> vertex_of_fan;
    std::unordered_map<u32, u32> first_fan_of_vertex;
    std::unordered_map<std::uint64_t, u32> first_corner_of_face_in_fan;
    for (std::size_t k = 0; k < corners_.size(); ++k) {
      const u32 v = flat_.vertex[corners_[k]];
      const auto [first, added] =
        first_corner_of_face_in_fan.emplace(std::uint64_t(face_[k]) << 32 | fan[k], corners_[k]);
      if (!added) {
        const char* why =
          are_ends_of_one_side(face_[k], first->second, corners_[k]) ? nullptr : why_not_held(v, fan);
        if (why)
          throw Soup_error(Soup_error::Kind::repeated_vertex,
                           "polygon " + std::to_string(face_[k]) + " visits vertex " + std::to_string(v) +
                             " twice within one fan of polygons around it, " + why + ", which no sheet holds",
                           {face_[k]}, {v});
        folded_corners_.push_back(corners_[k]); // corners_ is in flat order
      }
      first_fan_of_vertex.emplace(v, fan[k]);
      auto [it, added_fan] = vertex_of_fan.emplace(fan[k], v);
      if (added_fan && first_fan_of_vertex.at(v) != fan[k]) {
        it->second = n_vertices_ + u32(original_.size());
        original_.push_back(v);
      }
    }
    for (std::size_t k = 0; k < corners_.size(); ++k)
      flat_.vertex[corners_[k]] = vertex_of_fan.at(fan[k]);
  }

  // Why the sheets cannot hold, as OpenSubdiv does, a polygon's two visits
  // of vertex v within one fan (null where they can), on the polygons as
  // given. They hold them where OpenSubdiv makes v non-manifold (infinitely
  // sharp), as the sheets make a vertex a polygon visits twice. Where Vtr
  // orders the polygons round v instead (Level::orderVertexFacesAndEdges()
  // succeeds), it gives both visits the polygon's first corner at v
  // (populateLocalIndices() runs after the ordering), so that its next level
  // misses the polygon's face at the other visit round v and counts another
  // twice. The ordering fails where v is on a non-manifold edge of Vtr's
  // (three or more sides, a polygon's twice, a degenerate side), where v
  // has several fans, or where its one fan is open and the polygon it starts
  // at (whose side leaving v is a border) visits v there for the second
  // time: Vtr starts at the polygon's first corner at v. Not held either:
  // two polygons along a side at v the same way, which Vtr makes a
  // non-manifold edge and the sheets a Möbius edge. Computed once per vertex.
  const char* why_not_held(u32 v, const std::vector<u32>& fan)
  {
    const auto known = why_not_held_.find(v);
    if (known != why_not_held_.end())
      return known->second;
    bool non_manifold_edge = false, same_way = false, several_fans = false;
    u32 fan_of_v = no_corner, start = no_corner;
    const auto first = std::lower_bound(by_vertex_.begin(), by_vertex_.end(), std::make_pair(v, u32(0)));
    auto last = first;
    for (; last != by_vertex_.end() && last->first == v; ++last) {
      const u32 k = last->second, f = face_[k], t = corners_[k];
      several_fans = several_fans || (fan_of_v != no_corner && fan[k] != fan_of_v);
      fan_of_v = fan[k];
      for (const u32 side_from : {t, prev_in_face(f, t - flat_.offset[f])}) {
        const u32 a = flat_.vertex[side_from], b = flat_.vertex[next_in_face(f, side_from - flat_.offset[f])];
        const Side_count& c = sides_.at(key(a, b));
        non_manifold_edge = non_manifold_edge || a == b || c.count > 2 || c.same_face;
        same_way = same_way || (is_two_sided(a, b) && c.same_way);
        if (c.count == 1 && side_from == t)
          start = k; // the side leaving v is a border: Vtr's walk starts here
      }
    }
    // The corners of v are in flat order: the face's first visit is its first among them.
    const bool starts_at_second_visit =
      start != no_corner && std::find_if(first, last, [&](const auto& e) { return face_[e.second] == face_[start]; })
                                ->second != start;
    const char* why = nullptr;
    if (same_way)
      why = "where two polygons run along a side the same way (OpenSubdiv: a non-manifold edge; here: a Möbius edge)";
    else if (!non_manifold_edge && !several_fans && !starts_at_second_visit)
      why = "where OpenSubdiv orders the fan and gives both visits one corner";
    return why_not_held_[v] = why;
  }
  // Whether corners a and b (flat indices) of face f follow each other.
  bool are_ends_of_one_side(u32 f, u32 a, u32 b) const
  {
    return next_in_face(f, a - flat_.offset[f]) == b || next_in_face(f, b - flat_.offset[f]) == a;
  }

  // The builder pairs two sides with the same two ends: after renaming, two
  // sides of a pair that OpenSubdiv does not make two-sided (three or more
  // sides, one polygon's twice, or a degenerate edge) could be the only two
  // of their renamed pair. Such sides stay borders of their own.
  void find_lone_sides()
  {
    for_each_side_at_repeated([&](u32, u32 from, u32 to) {
      if (!is_two_sided(original_vertex(flat_.vertex[from]), original_vertex(flat_.vertex[to])))
        lone_sides_.push_back(from);
    });
    std::sort(lone_sides_.begin(), lone_sides_.end());
  }
  u32 original_vertex(u32 v) const { return v < n_vertices_ ? v : original_[v - n_vertices_]; }

  Face_list& flat_;
  u32 n_vertices_;
  std::vector<u32> corners_, face_, original_, lone_sides_, folded_corners_;
  std::vector<std::pair<u32, u32>> by_vertex_; // (vertex, index in corners_) of each repeated corner
  std::unordered_map<u32, const char*> why_not_held_; // why_not_held(), by vertex
  std::unordered_map<std::uint64_t, Side_count> sides_;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_REPEATED_VERTEX_SPLIT_H
