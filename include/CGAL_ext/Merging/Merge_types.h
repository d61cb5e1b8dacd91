// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The public types of merge_borders.h: what a merge did, how the manual merge
// places glued vertices, and the two border chains it glues.

#ifndef CGAL_EXT_MERGING_MERGE_TYPES_H
#define CGAL_EXT_MERGING_MERGE_TYPES_H

#include <CGAL_ext/Mobius_mesh.h>

#include <cstddef>
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

} // namespace CGAL_ext

#endif // CGAL_EXT_MERGING_MERGE_TYPES_H
