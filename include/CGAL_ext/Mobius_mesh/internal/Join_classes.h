// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The classes of vertices and edges of a mesh of manifold sheets that were
// one vertex or one edge of the input, read off its join map: the engine of
// <CGAL_ext/Mobius_mesh/non_manifold_joins.h> and of the subdivision of
// non-manifold input.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_JOIN_CLASSES_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_JOIN_CLASSES_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

inline constexpr const char* non_manifold_join_map_name = "v:non_manifold_join";
// The value of a vertex that was not split off another (the map's default,
// so that a vertex added later is joined to none).
inline constexpr std::uint32_t no_join = 0xffffffffu;

// Two vertices are one in the input if the join map gives them the same
// representative; two edges are one if their ends are (an edge of the input
// is the pair of its ends). Without a join map every class has one member.
class Join_classes
{
public:
  using u32 = std::uint32_t;

  // The classes of the join map of `mesh` (each vertex its own without one).
  template <class P>
  explicit Join_classes(const Mobius_mesh<P>& mesh) : Join_classes(mesh, join_map_values(mesh))
  {
  }

  // The classes of `representative`, a representative per vertex of `mesh`,
  // which must hold its own index.
  template <class P>
  Join_classes(const Mobius_mesh<P>& mesh, std::vector<u32> representative) : rep_(std::move(representative))
  {
    const u32 nv = u32(mesh.number_of_vertices());
    members_.assign(nv, 0);
    for (u32 v = 0; v < nv; ++v) {
      if (rep_[v] >= nv || rep_[rep_[v]] != rep_[v])
        throw Parameter_error(std::string("the vertex map \"") + non_manifold_join_map_name + "\" joins vertex " +
                              std::to_string(v) + " to " + std::to_string(rep_[v]) +
                              ", which is not a vertex joined to none");
      ++members_[rep_[v]];
    }
    for (u32 v = 0; v < nv; ++v) {
      input_vertices_ += rep_[v] == v ? 1 : 0;
      joined_vertices_ += rep_[v] == v && members_[v] > 1 ? 1 : 0;
    }
    input_edges_ = mesh.number_of_edges();
    // Without joins every edge is its own class: nothing to classify (the
    // writers build these classes for every mesh they write).
    if (joined_vertices_ != 0)
      classify_edges(mesh);
  }

  template <class P>
  static std::vector<u32> join_map_values(const Mobius_mesh<P>& mesh)
  {
    std::vector<u32> rep(mesh.number_of_vertices());
    const auto map = mesh.template property_map<Vertex_index, std::uint32_t>(non_manifold_join_map_name);
    for (u32 v = 0; v < u32(rep.size()); ++v)
      rep[v] = map && (*map)[Vertex_index(v)] != no_join ? (*map)[Vertex_index(v)] : v;
    return rep;
  }

  bool has_joins() const { return joined_vertices_ != 0; }
  u32 representative(u32 v) const { return rep_[v]; }
  const std::vector<u32>& representatives() const { return rep_; }

  // The classes as the values of a join map: no_join for a representative.
  template <class P>
  void write_map(Mobius_mesh<P>& mesh) const
  {
    auto map = mesh.template add_property_map<Vertex_index, std::uint32_t>(non_manifold_join_map_name, no_join).first;
    for (u32 v = 0; v < u32(rep_.size()); ++v)
      map[Vertex_index(v)] = rep_[v] == v ? no_join : rep_[v];
  }
  // Whether vertex v is one of several vertices of one input vertex.
  bool is_joined(u32 v) const { return members_[rep_[v]] > 1; }
  u32 edge_representative(u32 e) const { return edge_rep_.empty() ? e : edge_rep_[e]; }
  // The copies of edge e's input edge (1 unless it was a non-manifold edge).
  u32 edge_members(u32 e) const { return edge_members_.empty() ? 1 : edge_members_[edge_rep_[e]]; }
  // The vertices and edges of the input that are several of the mesh.
  std::size_t joined_vertices() const { return joined_vertices_; }
  std::size_t joined_edges() const { return joined_edges_; }
  // The vertices and edges of the input: the mesh's, each class once.
  std::size_t input_vertices() const { return input_vertices_; }
  std::size_t input_edges() const { return input_edges_; }

  // The index of each vertex among the representatives, in order: where a
  // writer puts it once the joins are made again.
  std::vector<u32> joined_indices() const
  {
    std::vector<u32> index(rep_.size());
    u32 next = 0;
    for (u32 v = 0; v < u32(rep_.size()); ++v)
      if (rep_[v] == v)
        index[v] = next++;
    for (u32 v = 0; v < u32(rep_.size()); ++v)
      index[v] = index[rep_[v]];
    return index;
  }

private:
  template <class P>
  void classify_edges(const Mobius_mesh<P>& mesh)
  {
    const u32 ne = u32(mesh.number_of_edges());
    edge_rep_.resize(ne);
    std::unordered_map<std::uint64_t, std::pair<u32, u32>> first; // (first edge, members)
    for (u32 e = 0; e < ne; ++e) {
      edge_rep_[e] = e;
      const u32 a = mesh.vertex(Edge_index(e), 0).idx(), b = mesh.vertex(Edge_index(e), 1).idx();
      if (!is_joined(a) || !is_joined(b))
        continue; // only an edge between two joined vertices can have copies
      const auto [lo, hi] = std::minmax(rep_[a], rep_[b]);
      auto [it, added] = first.emplace(std::uint64_t(lo) << 32 | hi, std::make_pair(e, 0u));
      edge_rep_[e] = it->second.first;
      input_edges_ -= added ? 0 : 1;
      if (++it->second.second == 2)
        ++joined_edges_;
    }
    if (joined_edges_ != 0) {
      edge_members_.assign(ne, 1);
      for (const auto& entry : first)
        edge_members_[entry.second.first] = entry.second.second;
    }
  }

  std::vector<u32> rep_, members_, edge_rep_, edge_members_;
  std::size_t joined_vertices_ = 0, joined_edges_ = 0, input_vertices_ = 0, input_edges_ = 0;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_JOIN_CLASSES_H
