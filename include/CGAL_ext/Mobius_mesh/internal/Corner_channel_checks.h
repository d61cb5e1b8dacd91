// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/Mobius_mesh/corner_data.h>: the seams of a channel,
// the checks of value indices, the removal of unused values, and the one
// refusal of the operations that cannot carry a channel.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_CHECKS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_CHECKS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_array.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Whether the channel whose corners hold the value indices `index` is cut
// along the edge `e` of two faces: their corners at one end (or both) hold
// different indices.
template <class P, class Indices>
bool is_channel_cut(const Mobius_mesh<P>& mesh, const Indices& index, Edge_index e)
{
  // The corners at both ends, on both sides: d's face and opposite(d)'s.
  const Dart d(Mobius_mesh<P>::halfedge(e, 0), false), o = mesh.opposite(d);
  return index[mesh.corner(d).idx()] != index[mesh.corner(mesh.prev(o)).idx()] ||
         index[mesh.corner(mesh.prev(d)).idx()] != index[mesh.corner(o).idx()];
}

// The seams of all the corner channels of `mesh`, by edge index.
template <class P>
std::vector<char> corner_seam_edges(const Mobius_mesh<P>& mesh)
{
  std::vector<char> seam(mesh.num_edges(), 0);
  const auto& hprops = Connectivity_access::properties<Halfedge_index>(mesh);
  hprops.template for_each_array<Base_corner_channel>([&](const Base_corner_channel& c) {
    for (Edge_index e : mesh.edges())
      if (!mesh.is_border(e) && is_channel_cut(mesh, c.indices(), e))
        seam[e.idx()] = 1;
  });
  return seam;
}

// Refuses, before `function` touches `mesh`, a face corner whose value index
// is past its channel's values (no value is allowed), naming the channel,
// the face and the vertex.
template <class P>
void require_valid_corner_indices(const Mobius_mesh<P>& mesh, const std::string& function)
{
  Connectivity_access::properties<Halfedge_index>(mesh).template for_each_array<Base_corner_channel>(
    [&](const Base_corner_channel& c) {
      for (Face_index f : mesh.faces())
        for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
          const std::uint32_t i = c.indices()[mesh.corner(d).idx()];
          if (i != Base_corner_channel::no_value && i >= c.number_of_values())
            throw Parameter_error(function + ": corner channel \"" + c.name() + "\": the corner of face f" +
                                  std::to_string(f.idx()) + " at vertex v" + std::to_string(mesh.target(d).idx()) +
                                  " has value index " + std::to_string(i) + " of " +
                                  std::to_string(c.number_of_values()));
        }
    });
}

// Drops the values of channel `c` of `mesh` that no face corner names,
// keeping the others in their order and the first `kept_prefix` ones
// whether named or not. The slots that hold no face corner are cleared
// first: a removed edge's are already (Mobius_mesh::remove_edge()), but a
// border halfedge may keep the index its face gave it, as CGAL's generic
// Euler::remove_face() knows of no channel.
template <class P>
void remove_unused_values(const Mobius_mesh<P>& mesh, Base_corner_channel& c, std::size_t kept_prefix)
{
  Base_corner_channel::Index_array& index = c.indices();
  for (std::size_t i = 0; i < index.size(); ++i)
    if (mesh.is_removed(Halfedge_index(i)) || mesh.is_border(Halfedge_index(i)))
      index[i] = Base_corner_channel::no_value;
  c.remove_unused_values(kept_prefix);
}

// Drops the values of every channel that no face corner names (those of
// the corners an edit removed), keeping the others in their order.
template <class P>
void remove_unused_corner_values(Mobius_mesh<P>& mesh)
{
  Connectivity_access::properties<Halfedge_index>(mesh).template for_each_array<Base_corner_channel>(
    [&](Base_corner_channel& c) { remove_unused_values(mesh, c, 0); });
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_CHECKS_H
