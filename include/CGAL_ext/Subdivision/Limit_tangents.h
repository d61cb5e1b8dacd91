// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The limit tangents at a vertex, the type that `limit.h` returns.

#ifndef CGAL_EXT_SUBDIVISION_LIMIT_TANGENTS_H
#define CGAL_EXT_SUBDIVISION_LIMIT_TANGENTS_H

namespace CGAL_ext {
namespace Subdivision {
/// \ingroup PkgSubdivision
/// The two limit tangents at a vertex, as OpenSubdiv's
/// `Far::PrimvarRefiner::Limit()` gives them: `tangent1` along the first
/// edge of the vertex's ring (a smooth vertex) or along the first crease
/// edge (a crease or border vertex), `tangent2` across; `tangent1 ×
/// tangent2` is the limit normal, on the side the ring was walked from.
template <class Vector>
struct Limit_tangents
{
  Vector tangent1; ///< the first tangent
  Vector tangent2; ///< the second tangent
};

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_LIMIT_TANGENTS_H
