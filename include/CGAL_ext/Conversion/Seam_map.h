// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The seam map of a cut CGAL::Surface_mesh: which border halfedge each border
// halfedge is glued to, and how, and the names of the maps that
// to_surface_mesh() writes and from_surface_mesh() reads.

#ifndef CGAL_EXT_CONVERSION_SEAM_MAP_H
#define CGAL_EXT_CONVERSION_SEAM_MAP_H

#include <CGAL/Surface_mesh.h>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshConversion
/// One entry of the seam map of a cut `Surface_mesh` (see `to_surface_mesh()`):
/// the border halfedge this border halfedge is glued to, and how. With
/// `twisted == true` the two halfedges are glued running the *same* way
/// (source to source, target to target): the glued edge is a Möbius edge.
/// With `twisted == false` they are glued running opposite ways (source to
/// target), as the two halfedges of an ordinary edge. Halfedges that are not
/// glued hold a null `partner`.
struct Seam_link
{
  /// The border halfedge glued to this one; null if none.
  CGAL::SM_Halfedge_index partner;
  /// True if the two halfedges are glued running the same way (a Möbius edge).
  bool twisted = false;
};

/// Name of the `Surface_mesh` halfedge property map of `Seam_link`s.
inline constexpr const char* seam_map_name = "h:mobius_seam";
/// Name of the `Surface_mesh` face property map (`bool`) that marks the faces
/// whose orientation `to_surface_mesh()` reversed.
inline constexpr const char* reversed_faces_map_name = "f:mobius_reversed";

} // namespace CGAL_ext

#endif // CGAL_EXT_CONVERSION_SEAM_MAP_H
