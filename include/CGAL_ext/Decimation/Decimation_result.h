// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What decimate() did.

#ifndef CGAL_EXT_DECIMATION_DECIMATION_RESULT_H
#define CGAL_EXT_DECIMATION_DECIMATION_RESULT_H

#include <cstddef>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshDecimation
/// What `decimate()` did.
struct Decimation_result
{
  std::size_t faces_before = 0; ///< triangles after triangulating the input, before any collapse
  std::size_t faces_after = 0;  ///< triangles of the result
  std::size_t collapses = 0;    ///< edge collapses done
  /// The largest error of a collapse done, in squared length units (see `maximum_error`).
  double largest_error = 0;
  /// Vertices moved after the collapses to lower the largest distance to the
  /// input (see `relocate_vertices`).
  std::size_t relocations = 0;
  /// Values of the corner channels (all channels together) that the result
  /// holds and that collapses made: from the attribute quadrics, or by
  /// interpolating two values along the collapsed edge where there are none
  /// (`corner_value_weight` 0, a channel of one value, faces without a
  /// field); the others are the input's own.
  std::size_t corner_values_interpolated = 0;
};

} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_DECIMATION_RESULT_H
