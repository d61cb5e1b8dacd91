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
#include <cstdint>
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

enum class Scheme { catmull_clark, loop, bilinear, doo_sabin, sqrt3 };

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

  /// `Subdivision::catmull_clark` / `loop` / `bilinear` / `doo_sabin` / `sqrt3`
  /// with `number_of_iterations(levels)`;
  /// with `parallel`, their `CGAL::Parallel_tag` form (see `parallel_available`).
  void subdivide(Scheme scheme, unsigned levels, bool parallel);
  /// One Catmull–Clark step through `Subdivision::Refiner::refine_and_interpolate`
  /// (the path of `catmull_clark()` for points alone), with
  /// `Refinement_options::parallel_min_vertices` = `parallel_min_vertices`,
  /// under `CGAL::Parallel_tag` if `parallel`.
  void refine_once(bool parallel, std::uint32_t parallel_min_vertices);
  /// `Subdivision::Refinement_options::automatic`.
  static std::uint32_t automatic_threshold();

  std::size_t number_of_vertices() const;
  std::size_t number_of_faces() const;
  std::vector<Point> points() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Whether the library has the parallel subdivision (`CGAL_EXT_SUBDIVISION_PARALLEL`).
bool parallel_available();

/// Caps TBB at `threads` while it exists (a `tbb::global_control`; nothing
/// without the parallel path). Controls of one parameter that exist at once
/// do not nest: TBB applies the smallest cap of them all, so no other cap may
/// be alive, such as one for the whole program.
class Thread_limit
{
public:
  explicit Thread_limit(int threads);
  ~Thread_limit();
  /// The number of threads TBB allows now, with every cap alive applied
  /// (without the parallel path, 1).
  static std::size_t allowed();
  Thread_limit(const Thread_limit&) = delete;
  Thread_limit& operator=(const Thread_limit&) = delete;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// What it costs the machine when one core reads what another wrote, the
/// hand-over between the loops of a parallel pass: a loop rewrites `data`,
/// then another adds to each element of `sums` the element of `data` at the
/// same index (`other` false) or half the array further on (`other` true),
/// each loop on `parts` threads by TBB's static partition, which gives each
/// thread the same slice in both loops: with `other`, with two threads or
/// more, each reads what another thread wrote. One thread for `parts` 1, or
/// without the parallel path. Returns `data.size()`.
std::size_t write_then_read(std::vector<double>& data, std::vector<double>& sums, unsigned parts, bool other);

/// A block of bytes to write.
struct Block
{
  unsigned char* data;
  std::size_t size;
};

/// Writes every byte of `blocks` once (`memset`), each block cut into
/// `parts` contiguous slices of equal size; with `parts` > 1, one TBB task
/// per slice index writes that slice of every block (without the parallel
/// path, one after the other).
void write_blocks(const std::vector<Block>& blocks, unsigned parts);

/// The bytes of each array of a `CGAL_ext::Mobius_mesh<Point>` with these
/// counts and only its point map: vertex points and halfedges, halfedge
/// targets, next, previous and faces, the edges' Möbius flags, the faces'
/// halfedges.
std::vector<std::size_t> mesh_array_bytes(std::size_t vertices, std::size_t edges, std::size_t faces);

/// The soup of `CGAL_ext::make_torus(mesh, nu, nv)`: its points and its faces' vertex cycles.
Soup torus_soup(std::size_t nu, std::size_t nv);
/// The soup of `CGAL_ext::make_mobius_strip(mesh, n_around, n_across)` (one half twist, quads).
Soup mobius_strip_soup(std::size_t n_around, std::size_t n_across);
/// The soup of `CGAL_ext::make_klein_bottle(mesh, nu, nv)`.
Soup klein_bottle_soup(std::size_t nu, std::size_t nv);

} // namespace subdivision_bench

#endif // CGAL_EXT_BENCH_SUBDIVISION_H
