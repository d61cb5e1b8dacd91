// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Mobius_mesh side of bench_soup_import (see bench_soup_import.h for why
// it is a translation unit of its own).

#include "bench_soup_import.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

namespace soup_import {

Mesh_stats import_into_mobius_mesh(const std::vector<Point>& points, const std::vector<Polygon>& polygons,
                                   const std::function<void()>& while_built)
{
  CGAL_ext::Mobius_mesh<Point> mesh;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, mesh);
  if (while_built)
    while_built();
  return {mesh.number_of_vertices(), mesh.number_of_edges(), mesh.number_of_faces()};
}

} // namespace soup_import
