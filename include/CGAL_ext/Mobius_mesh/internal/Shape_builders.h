// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/Mobius_mesh/generators.h>: the grids and gluings that the shape generators build from.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_SHAPE_BUILDERS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_SHAPE_BUILDERS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL/Kernel_traits.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

constexpr double generator_pi = 3.14159265358979323846;

// Coordinates are computed in double and converted once, so that every kernel
// (exact ones included) receives the same points.
template <class P>
P make_generator_point(double x, double y, double z)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  return P(FT(x), FT(y), FT(z));
}

inline void check_resolution(const char* function, const char* name, std::size_t value, std::size_t minimum)
{
  if (value < minimum)
    throw Parameter_error(std::string(function) + ": " + name + " = " + std::to_string(value) +
                          ", but it must be at least " + std::to_string(minimum));
}

inline void check_length(const char* function, const char* name, double value)
{
  if (!std::isfinite(value) || !(value > 0))
    throw Parameter_error(std::string(function) + ": " + name + " = " + std::to_string(value) +
                          ", but it must be a finite number > 0");
}

// The edges of the new part and of the mesh it joins, checked by the one
// rule of the mesh's size (Size_limits.h), and the memory of the new part
// (a vertex and about `edges_per_cell` - 1 faces per cell) against the
// memory available. `a` and `b` are factors of the edge count, capped (past
// any mesh's size) so that the product cannot wrap.
template <class P>
void check_edge_count(const char* function, std::size_t existing_edges, std::size_t a, std::size_t b,
                      std::size_t edges_per_cell)
{
  using Wide = unsigned long long;
  constexpr Wide cap = Wide(1) << 31;
  const Wide cells = (std::min)(Wide(a), cap) * (std::min)(Wide(b), cap);
  const std::string what = std::string(function) + ": the resolution " + std::to_string(a) + " x " + std::to_string(b);
  check_mesh_size(what, Mesh_size{0, Wide(existing_edges) + cells * edges_per_cell, 0, 0});
  const Mesh_size part{cells, cells * edges_per_cell, cells * (edges_per_cell - 1), 0};
  check_memory(what, mesh_bytes<P>(part), available_memory());
}

// A grid of nu x nvv vertices (i, j). Column i = nu is column 0 again,
// mirrored across (j -> nvv - 1 - j) when `reflect`; row j = nvv is row 0
// again when `wrap_v`.
struct Periodic_grid
{
  std::size_t nu, nvv;
  bool wrap_v, reflect;

  std::size_t operator()(std::size_t i, std::size_t j) const
  {
    if (wrap_v && j == nvv)
      j = 0;
    if (i == nu) {
      i = 0;
      if (reflect)
        j = nvv - 1 - j;
    }
    return i * nvv + j;
  }
};

// Appends the faces, numbered over `points`, to `mesh`.
template <class P>
void append_generated(Mobius_mesh<P>& mesh, const std::vector<P>& points, const Face_list& faces)
{
  Mobius_mesh<P> part;
  build_mesh_from_faces(faces.view(std::uint32_t(points.size())),
                        [&points](std::uint32_t v) -> const P& { return points[v]; }, false, part);
  append_mesh(mesh, std::move(part));
}

// Builds the grid's cells as quads (i, j), (i+1, j), (i+1, j+1), (i, j+1), or
// as two triangles split along (i, j)-(i+1, j+1), welded by index. Returns
// the unflipped dart of the first new face from (0, 0) to (1, 0) if the grid
// is closed across, otherwise a border dart with target (0, 0).
template <class P, class PointFunction>
Dart make_periodic_grid(Mobius_mesh<P>& mesh, const Periodic_grid& grid, bool quads, PointFunction point)
{
  std::vector<P> points;
  points.reserve(grid.nu * grid.nvv);
  for (std::size_t i = 0; i < grid.nu; ++i)
    for (std::size_t j = 0; j < grid.nvv; ++j) {
      const std::array<double, 3> c = point(i, j);
      points.push_back(make_generator_point<P>(c[0], c[1], c[2]));
    }
  const std::size_t rows = grid.wrap_v ? grid.nvv : grid.nvv - 1;
  const Vertex_index first_vertex(mesh.num_vertices());
  const Face_index first_face(mesh.num_faces());
  auto v = [&grid](std::size_t i, std::size_t j) { return std::uint32_t(grid(i, j)); };
  Face_list faces;
  faces.offset.reserve((quads ? 1 : 2) * grid.nu * rows + 1);
  faces.vertex.reserve(4 * grid.nu * rows + 2 * grid.nu * rows * (quads ? 0 : 1));
  for (std::size_t i = 0; i < grid.nu; ++i)
    for (std::size_t j = 0; j < rows; ++j) {
      if (quads) {
        faces.add({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      } else {
        faces.add({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
        faces.add({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  append_generated(mesh, points, faces);
  return grid.wrap_v ? mesh.halfedge(first_face) : mesh.halfedge(first_vertex);
}

// The Bryant-Kusner parametrization of Boy's surface, for `w` in the closed
// unit disk; antipodal points of the unit circle have the same image.
// Written as g * |D|^2 / |g * |D|^2|^2 so that nothing blows up near the
// zeros of D inside the disk (where the surface passes through the origin).
inline std::array<double, 3> boy_surface_point(std::complex<double> w)
{
  const std::complex<double> w3 = w * w * w, w4 = w3 * w, w6 = w3 * w3;
  const std::complex<double> d = w6 + std::sqrt(5.0) * w3 - 1.0;
  const std::complex<double> dc = std::conj(d);
  const double n = std::norm(d);
  const double h1 = -1.5 * (w * (1.0 - w4) * dc).imag();
  const double h2 = -1.5 * (w * (1.0 + w4) * dc).real();
  const double h3 = ((1.0 + w6) * dc).imag() - 0.5 * n;
  const double hh = h1 * h1 + h2 * h2 + h3 * h3;
  if (!(hh > 0))
    return {0.0, 0.0, 0.0};
  return {h1 * n / hh, h2 * n / hh, h3 * n / hh};
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_SHAPE_BUILDERS_H
