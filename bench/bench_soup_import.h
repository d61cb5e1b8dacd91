// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the two translation units of bench_soup_import share. The Mobius_mesh
// side is compiled apart from <CGAL/Surface_mesh.h>: with both in one unit,
// CGAL's BGL free functions (`CGAL::halfedges_around_face` ...) are found by
// argument-dependent lookup on `Mobius_mesh<CGAL::Point_3<K>>` from the
// unqualified calls inside the CGAL_ext headers, and fail to compile.

#ifndef CGAL_EXT_BENCH_SOUP_IMPORT_H
#define CGAL_EXT_BENCH_SOUP_IMPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace soup_import {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;

struct Mesh_stats
{
  std::size_t vertices = 0, edges = 0, faces = 0;
};

/// Builds a `CGAL_ext::Mobius_mesh<Point>` from the soup with
/// `polygon_soup_to_mobius_mesh`, calls `while_built` (if any) while the mesh
/// exists, and destroys it.
Mesh_stats import_into_mobius_mesh(const std::vector<Point>& points, const std::vector<Polygon>& polygons,
                                   const std::function<void()>& while_built);

} // namespace soup_import

#endif // CGAL_EXT_BENCH_SOUP_IMPORT_H
