// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The corner channels that files hold (texture coordinates and corner
// normals): their names and value types, a summary of each channel (values,
// seams, corners without a value), and the one refusal of the operations
// that cannot carry a channel.

#ifndef CGAL_EXT_MOBIUS_MESH_CORNER_DATA_H
#define CGAL_EXT_MOBIUS_MESH_CORNER_DATA_H

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

/// \ingroup PkgMobiusMesh
/// The corner channel of texture coordinates: `read_polygon_mesh()` fills it
/// from OBJ's `vt` (and PLY's and OFF's per-vertex texture coordinates) and
/// `write_polygon_mesh()` writes it back, with values of type `Corner_uv<P>`.
inline constexpr const char* corner_uv_name = "c:uv";
/// \ingroup PkgMobiusMesh
/// The corner channel of normals: filled from OBJ's `vn` (and PLY's and
/// OFF's per-vertex normals), with values of type `Corner_normal<P>`.
inline constexpr const char* corner_normal_name = "c:normal";

/// \ingroup PkgMobiusMesh
/// The value type of the texture coordinates that the readers make: the
/// kernel's `Point_2`, as CGAL's parameterization writes into its `uv` maps.
template <class P>
using Corner_uv = typename CGAL::Kernel_traits<P>::Kernel::Point_2;
/// \ingroup PkgMobiusMesh
/// The value type of the corner normals that the readers make: the kernel's
/// `Vector_3`, as CGAL's `compute_vertex_normals()` writes.
template <class P>
using Corner_normal = typename CGAL::Kernel_traits<P>::Kernel::Vector_3;

/// \ingroup PkgMobiusMesh
/// What `corner_channel_summaries()` tells of one channel.
struct Corner_channel_summary
{
  /// The channel's name.
  std::string name;
  /// The number of values the channel holds (used or not).
  std::size_t values = 0;
  /// The edges along which the channel is cut: edges with two faces whose
  /// corners at one end (or both) hold different value indices. Zero for a
  /// channel that is continuous everywhere.
  std::size_t seam_edges = 0;
  /// The face corners that hold no value (subdivision refuses them).
  std::size_t corners_without_value = 0;
  /// The Möbius edges of the mesh as it stands (`Mobius_mesh::is_mobius()`)
  /// across which the channel is continuous: the two faces hold the same
  /// value index at both ends.
  std::size_t mobius_edges_continuous = 0;
  /// The Möbius edges along which the channel is cut (seam edges, so also
  /// counted in `seam_edges`). With `mobius_edges_continuous`, the mesh's
  /// Möbius edges, each counted once.
  std::size_t mobius_edges_seamed = 0;
};

namespace internal {

// Whether the channel whose corners hold the value indices `index` is cut
// along the edge `e` of two faces: their corners at one end (or both) hold
// different indices.
template <class P>
bool is_channel_cut(const Mobius_mesh<P>& mesh, const std::vector<std::uint32_t>& index, Edge_index e)
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

// Drops the values of every channel that no corner names (those of the
// corners an edit removed), keeping the others in their order.
template <class P>
void remove_unused_corner_values(Mobius_mesh<P>& mesh)
{
  Connectivity_access::properties<Halfedge_index>(mesh).template for_each_array<Base_corner_channel>(
    [](Base_corner_channel& c) { c.remove_unused_values(); });
}

} // namespace internal

/// \ingroup PkgMobiusMesh
/// A summary of each corner channel of `mesh` (in order of creation): its
/// values, seam edges, the corners without a value, and whether it is
/// continuous across each Möbius edge. Linear in the mesh's size.
/// A seam is told by value indices, not by values: two indices of equal
/// values make a seam, as the OBJ writer keeps them apart.
template <class P>
std::vector<Corner_channel_summary> corner_channel_summaries(const Mobius_mesh<P>& mesh)
{
  std::vector<Corner_channel_summary> result;
  const auto& hprops = internal::Connectivity_access::properties<Halfedge_index>(mesh);
  hprops.template for_each_array<internal::Base_corner_channel>([&](const internal::Base_corner_channel& c) {
    Corner_channel_summary s;
    s.name = c.name();
    s.values = c.number_of_values();
    const std::vector<std::uint32_t>& index = c.indices();
    for (Face_index f : mesh.faces())
      for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh))
        s.corners_without_value += index[mesh.corner(d).idx()] == internal::Base_corner_channel::no_value ? 1 : 0;
    for (Edge_index e : mesh.edges()) {
      if (mesh.is_border(e))
        continue;
      const bool seam = internal::is_channel_cut(mesh, index, e);
      s.seam_edges += seam ? 1 : 0;
      // A Möbius edge is no different here (corners do not depend on the way
      // a face is walked), but a texture of a one-sided surface needs a seam
      // somewhere along its loop: whether it lies on the Möbius edges is told apart.
      if (mesh.is_mobius(e))
        ++(seam ? s.mobius_edges_seamed : s.mobius_edges_continuous);
    }
    result.push_back(std::move(s));
  });
  return result;
}

namespace internal {

// The one refusal of the operations that cannot carry corner channels
// (`why` says what they do to corners): before they touch the mesh, naming
// the channel, so that no channel is dropped or garbled silently.
template <class P>
void refuse_corner_channels(const Mobius_mesh<P>& mesh, const std::string& function, const std::string& why)
{
  const std::vector<std::string> names = mesh.corner_channels();
  if (!names.empty())
    throw Parameter_error(function + ": the mesh has the corner channel \"" + names.front() + "\", which " +
                          function + " does not carry (" + why +
                          "); remove it first (Mobius_mesh::remove_corner_channel())");
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_CORNER_DATA_H
