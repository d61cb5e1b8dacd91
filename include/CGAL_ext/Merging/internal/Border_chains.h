// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The manual merge of merge_borders.h: two chains of border edges, checked
// and walked, glued edge to edge or bridged with new faces.

#ifndef CGAL_EXT_MERGING_INTERNAL_BORDER_CHAINS_H
#define CGAL_EXT_MERGING_INTERNAL_BORDER_CHAINS_H

#include <CGAL_ext/Merging/Merge_types.h>
#include <CGAL_ext/Merging/internal/Border_glue.h>
#include <CGAL_ext/Merging/internal/Merged_mesh.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/exceptions.h>

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
} // namespace CGAL_ext

#endif // CGAL_EXT_MERGING_INTERNAL_BORDER_CHAINS_H
