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
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_checks.h>
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
    const auto& index = c.indices();
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

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_CORNER_DATA_H
