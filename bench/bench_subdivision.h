// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the two translation units of bench_subdivision share. Our side
// (bench_subdivision.mobius_mesh.cpp) is compiled apart from
// <CGAL/Surface_mesh.h> for the reason given in bench_soup_import.h: with both
// in one unit, CGAL's BGL free functions are found by argument-dependent
// lookup from the CGAL_ext headers and fail to compile. So the Mobius_mesh is
// kept behind a pointer here.

#ifndef CGAL_EXT_BENCH_SUBDIVISION_H
#define CGAL_EXT_BENCH_SUBDIVISION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace subdivision_bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;

struct Soup
{
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

enum class Scheme { catmull_clark, loop };

/// A `CGAL_ext::Mobius_mesh<Point>`.
class Our_mesh
{
public:
  Our_mesh();
  ~Our_mesh();
  Our_mesh(const Our_mesh&) = delete;
  Our_mesh& operator=(const Our_mesh&) = delete;

  /// Builds the mesh with `polygon_soup_to_mobius_mesh`.
  void assign(const Soup& soup);
  /// Copy assignment of the mesh.
  void assign(const Our_mesh& other);
  void clear();

  /// `Subdivision::catmull_clark` / `loop` with `number_of_iterations(levels)`;
  /// with `parallel`, their `CGAL::Parallel_tag` form (see `parallel_available`).
  void subdivide(Scheme scheme, unsigned levels, bool parallel);

  std::size_t number_of_vertices() const;
  std::size_t number_of_faces() const;
  std::vector<Point> points() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Whether the library has the parallel subdivision (`CGAL_EXT_SUBDIVISION_PARALLEL`).
bool parallel_available();

/// Caps TBB at `threads` for the rest of the program (no-op without the parallel path).
void limit_threads(int threads);

/// The soup of `CGAL_ext::make_torus(mesh, nu, nv)`: its points and its faces' vertex cycles.
Soup torus_soup(std::size_t nu, std::size_t nv);

} // namespace subdivision_bench

#endif // CGAL_EXT_BENCH_SUBDIVISION_H
