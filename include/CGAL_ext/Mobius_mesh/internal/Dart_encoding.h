// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The one owner of how darts, halfedges and edges are packed into 32-bit
// integers. The mesh, the subdivision levels and the conversions all index
// with these functions, so the encoding can change in one place.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_DART_ENCODING_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_DART_ENCODING_H

#include <cstdint>
#include <limits>

namespace CGAL_ext {
namespace internal {
namespace dart_encoding {

using u32 = std::uint32_t;

/// The value of a null handle or dart.
constexpr u32 null = (std::numeric_limits<u32>::max)();

// Halfedges come in pairs per edge: halfedges 2e and 2e+1 are edge e's.
constexpr u32 edge_of_halfedge(u32 h) { return h >> 1; }
constexpr u32 halfedge_of_edge(u32 e, u32 i) { return 2 * e + i; }
constexpr u32 opposite_halfedge(u32 h) { return h ^ 1u; }
/// Which of its edge's two halfedges `h` is: 0 or 1 (`h == halfedge_of_edge(edge_of_halfedge(h), side)`).
constexpr u32 side_of_halfedge(u32 h) { return h & 1u; }

// A dart is a halfedge and an orientation bit: halfedge << 1 | flipped.
constexpr u32 dart(u32 h, bool flipped) { return (h << 1) | u32(flipped); }
constexpr u32 halfedge_of_dart(u32 d) { return d >> 1; }
constexpr bool is_flipped(u32 d) { return (d & 1u) != 0; }
constexpr u32 flip(u32 d) { return d ^ 1u; }
constexpr u32 edge_of_dart(u32 d) { return d >> 2; }
/// The same dart once the edges are renumbered from `edge_offset` on (a
/// mesh appended to another).
constexpr u32 shift_dart(u32 d, u32 edge_offset) { return d + 4 * edge_offset; }

/// The dart of the other halfedge of the edge, running against `d`: the
/// partner halfedge, with the orientation bit toggled across a Möbius edge
/// (where the two halfedges run the same way).
constexpr u32 opposite_dart(u32 d, bool mobius_edge) { return (d ^ 2u) ^ u32(mobius_edge); }

} // namespace dart_encoding
} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_DART_ENCODING_H
