// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// OpenSubdiv's Bfr::Parameterization of a base face that is not a quad: n
// quad sub-faces of size 1/2 laid out in rows of unit tiles. Evaluation,
// tessellation and projection all place sub-faces by these two functions.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_PARAMETERIZATION_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_PARAMETERIZATION_H

#include <array>
#include <cmath>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// Bfr's row length of the sub-face layout of an n-gon (n != 4).
inline int sub_face_row(int n) { return n < 10 ? (2 + (n > 4 ? 1 : 0)) : (1 + int(std::sqrt(float(n - 1)))); }

// The tile of sub-face k of an n-gon: the corner (u, v) of its unit tile,
// whose lower-left quarter the sub-face covers.
inline std::array<int, 2> sub_face_tile(int n, int k) { return {k % sub_face_row(n), k / sub_face_row(n)}; }

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_PARAMETERIZATION_H
