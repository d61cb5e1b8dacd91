// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// How a vertex normal weighs the normals of the faces around it.

#ifndef CGAL_EXT_MOBIUS_MESH_VERTEX_NORMAL_WEIGHTING_H
#define CGAL_EXT_MOBIUS_MESH_VERTEX_NORMAL_WEIGHTING_H

namespace CGAL_ext {
/// \ingroup PkgMobiusMeshNormals
/// How `vertex_normal()` weighs the normals of the faces around a vertex.
enum class Vertex_normal_weighting {
  /// Unit face normals, summed: every face counts the same. Needs a square
  /// root per face, so it is not exact on exact kernels.
  uniform,
  /// Newell vectors as they are (twice the vector area of each face): larger
  /// faces count more. No square root: exact on exact kernels.
  area,
  /// The angle of each face at the vertex times its unit normal (Thürmer and
  /// Wüthrich): independent of how the faces around the vertex are split.
  /// The angle is computed in `double` (`atan2`), so it is not exact.
  angle
};

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_VERTEX_NORMAL_WEIGHTING_H
