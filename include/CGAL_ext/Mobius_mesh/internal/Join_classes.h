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
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

inline constexpr const char* non_manifold_join_map_name = "v:non_manifold_join";
// The value of a vertex that was not split off another (the map's default,
// so that a vertex added later is joined to none).
inline constexpr std::uint32_t no_join = 0xffffffffu;

// The vertices that a face of `mesh` visits twice, with the first such
// face, by vertex: non-manifold input whose corners there lie in one fan
// (see Repeated_vertex_split.h; a loop's face visits its vertex twice).
template <class P>
std::vector<std::pair<Vertex_index, Face_index>> folded_vertices(const Mobius_mesh<P>& mesh)
{
  std::vector<std::pair<Vertex_index, Face_index>> folded;
  std::vector<std::uint32_t> seen_in(mesh.number_of_vertices(), no_join);
  for (Face_index f : mesh.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const Vertex_index v = mesh.target(d);
      if (seen_in[v.idx()] == f.idx())
        folded.emplace_back(v, f);
      seen_in[v.idx()] = f.idx();
    }
  std::sort(folded.begin(), folded.end());
  folded.erase(std::unique(folded.begin(), folded.end(),
                           [](const auto& a, const auto& b) { return a.first == b.first; }),
               folded.end());
  return folded;
}

// Two vertices are one in the input if the join map gives them the same
// representative; two edges are one if their ends are (an edge of the input
// is the pair of its ends), but for the edges OpenSubdiv makes apart (see
// classify_edges()). Without a join map every class has one member.
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
  // which must hold its own index; edges between the same two input
  // vertices are one only if `edge_group` (empty: all 0) gives them the
  // same value (a subdivided mesh's halves of two input edges stay two).
  template <class P>
  Join_classes(const Mobius_mesh<P>& mesh, std::vector<u32> representative, std::vector<std::uint64_t> edge_group = {})
      : rep_(std::move(representative)), edge_group_(std::move(edge_group))
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
    non_manifold_vertices_ = joined_vertices_;
    // Without joins or faces that visit a vertex twice every edge is its
    // own class: nothing to classify (the writers build these classes for
    // every mesh they write). Such faces come only from the import, which
    // then makes a join map; OpenSubdiv makes their vertex non-manifold.
    const bool has_map = bool(mesh.template property_map<Vertex_index, std::uint32_t>(non_manifold_join_map_name));
    const auto folded = has_map ? folded_vertices(mesh) : std::vector<std::pair<Vertex_index, Face_index>>();
    if (joined_vertices_ != 0 || !folded.empty()) {
      marked_non_manifold_.assign(nv, false);
      for (const auto& f : folded)
        mark_non_manifold_vertex(f.first.idx());
      classify_edges(mesh);
    }
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
  // The copies of edge e's input edge in the mesh.
  u32 edge_members(u32 e) const { return edge_members_.empty() ? 1 : edge_members_[edge_rep_[e]]; }
  // Whether edge e is (a copy of) a non-manifold edge of the input: one of
  // three or more polygons, one a polygon runs along twice, or degenerate.
  bool is_non_manifold_edge(u32 e) const { return !non_manifold_edge_.empty() && non_manifold_edge_[e]; }
  // Whether vertex v is (a copy of) a non-manifold vertex of the input: one
  // of several copies, an end of a non-manifold edge (a loop's too), or one
  // that a face visits twice.
  bool is_non_manifold_vertex(u32 v) const
  {
    return is_joined(v) || (!marked_non_manifold_.empty() && marked_non_manifold_[v]);
  }
  // Whether an edge from vertex a to vertex b is degenerate in the input
  // (both ends one vertex).
  bool is_degenerate_edge(u32 a, u32 b) const { return rep_[a] == rep_[b]; }
  // The vertices of the input that are several of the mesh.
  std::size_t joined_vertices() const { return joined_vertices_; }
  // The non-manifold vertices and edges of the input (OpenSubdiv's).
  std::size_t non_manifold_vertices() const { return non_manifold_vertices_; }
  std::size_t non_manifold_edges() const { return non_manifold_edges_; }
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
  // The edges of the input as OpenSubdiv's Vtr makes them from the joined
  // polygons: the edges of the sheets whose ends are the same two input
  // vertices are one edge, but for a polygon that runs along the pair again
  // (its further sides each an edge of their own) and for a degenerate edge
  // (both ends one vertex: never shared). Where the sheets hold several
  // edges of one pair, every one of them is a non-manifold edge.
  template <class P>
  void classify_edges(const Mobius_mesh<P>& mesh)
  {
    const u32 ne = u32(mesh.number_of_edges());
    edge_rep_.resize(ne);
    edge_members_.assign(ne, 1);
    non_manifold_edge_.assign(ne, false);
    // (the ends' representatives, the edge's group, the edge), sorted: the
    // edges of one pair and group are a run, in index order.
    std::vector<std::tuple<std::uint64_t, std::uint64_t, u32>> by_ends;
    for (u32 e = 0; e < ne; ++e) {
      edge_rep_[e] = e;
      const u32 a = mesh.vertex(Edge_index(e), 0).idx(), b = mesh.vertex(Edge_index(e), 1).idx();
      if (a != b && !is_joined(a) && !is_joined(b))
        continue; // two vertices of the input joined to none: the only edge between them
      if (rep_[a] == rep_[b])
        mark_non_manifold(mesh, e);
      else
        by_ends.emplace_back(std::uint64_t((std::min)(rep_[a], rep_[b])) << 32 | (std::max)(rep_[a], rep_[b]),
                             edge_group_.empty() ? 0 : edge_group_[e], e);
    }
    std::sort(by_ends.begin(), by_ends.end());
    std::vector<u32> group;
    for (std::size_t i = 0, j = 0; i < by_ends.size(); i = j) {
      group.clear();
      for (j = i; j < by_ends.size() && std::get<0>(by_ends[j]) == std::get<0>(by_ends[i]) &&
                  std::get<1>(by_ends[j]) == std::get<1>(by_ends[i]);
           ++j)
        group.push_back(std::get<2>(by_ends[j]));
      if (group.size() > 1)
        join_group(mesh, group);
    }
    for (u32 e = 0; e < ne; ++e)
      if (edge_rep_[e] != e)
        --input_edges_;
    if (non_manifold_edges_ == 0)
      std::vector<bool>().swap(non_manifold_edge_);
  }

  // The edges of the sheets between one pair of input vertices (in index
  // order, each a border with one face): each polygon's first side along the
  // pair joins the first such edge, as in OpenSubdiv's Level; the further
  // sides of a polygon are edges of their own. "First" counts from the
  // face's halfedge, which is OpenSubdiv's first corner only while the face
  // keeps the polygon's orientation: which of a polygon's sides is joined
  // can differ, never a point (all of them are infinitely sharp).
  template <class P>
  void join_group(const Mobius_mesh<P>& mesh, const std::vector<u32>& group)
  {
    std::vector<std::pair<u32, u32>> by_face; // (face, edge)
    for (u32 e : group) {
      auto h = mesh.halfedge(Edge_index(e));
      by_face.emplace_back(mesh.face(mesh.is_border(h) ? mesh.opposite(h) : h).idx(), e);
    }
    std::sort(by_face.begin(), by_face.end());
    std::vector<u32> first; // per face
    for (std::size_t i = 0, j = 0; i < by_face.size(); i = j) {
      for (j = i; j < by_face.size() && by_face[j].first == by_face[i].first; ++j) {
      }
      first.push_back(j - i == 1 ? by_face[i].second : first_side(mesh, Face_index(by_face[i].first), group));
    }
    const u32 shared = *std::min_element(first.begin(), first.end());
    for (u32 e : first) {
      edge_rep_[e] = shared;
      edge_members_[shared] += e == shared ? 0 : 1;
    }
    for (u32 e : group)
      mark_non_manifold(mesh, e);
  }

  // The first edge of `group` (sorted) met walking face f from its halfedge.
  template <class P>
  static u32 first_side(const Mobius_mesh<P>& mesh, Face_index f, const std::vector<u32>& group)
  {
    auto d = mesh.halfedge(f);
    while (!std::binary_search(group.begin(), group.end(), u32(mesh.edge(d).idx())))
      d = mesh.next(d);
    return mesh.edge(d).idx();
  }

  // Edge e is (a copy of) a non-manifold edge, and so are its ends; each
  // class is counted at its representative.
  template <class P>
  void mark_non_manifold(const Mobius_mesh<P>& mesh, u32 e)
  {
    non_manifold_edge_[e] = true;
    if (edge_rep_[e] == e)
      ++non_manifold_edges_;
    for (int i = 0; i < 2; ++i)
      mark_non_manifold_vertex(mesh.vertex(Edge_index(e), i).idx());
  }
  // Vertex v is non-manifold (counted once; a joined one is counted already).
  void mark_non_manifold_vertex(u32 v)
  {
    if (!is_joined(v) && !marked_non_manifold_[v]) {
      marked_non_manifold_[v] = true;
      ++non_manifold_vertices_;
    }
  }

  std::vector<u32> rep_, members_, edge_rep_, edge_members_;
  std::vector<std::uint64_t> edge_group_;
  std::vector<bool> non_manifold_edge_, marked_non_manifold_; // per edge, per vertex
  std::size_t joined_vertices_ = 0, non_manifold_edges_ = 0, input_vertices_ = 0, input_edges_ = 0;
  std::size_t non_manifold_vertices_ = 0;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_JOIN_CLASSES_H
