// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What a conversion between Mobius_mesh and CGAL::Surface_mesh did.

#ifndef CGAL_EXT_CONVERSION_CONVERSION_RESULT_H
#define CGAL_EXT_CONVERSION_CONVERSION_RESULT_H

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshConversion
/// What a conversion did.
struct Conversion_result
{
  std::size_t seam_edges = 0;     ///< edges cut (to) or glued (from) along the seam
  std::size_t reversed_faces = 0; ///< faces whose orientation was reversed (to) or restored (from)
  std::size_t added_vertices = 0; ///< vertex copies made along the seam (to) or removed by gluing (from)
  /// Corner channels not carried to the `Surface_mesh` (to): those of a value type that it cannot be
  /// given (see `to_surface_mesh()`); empty when every channel was carried.
  std::vector<std::string> corner_channels_not_carried;
  /// Face corners without a value in a carried channel (to): their halfedges hold the value type's
  /// default (the origin) in the `Surface_mesh`, which has no mark for "no value".
  std::size_t corners_without_value = 0;
};

} // namespace CGAL_ext

#endif // CGAL_EXT_CONVERSION_CONVERSION_RESULT_H
