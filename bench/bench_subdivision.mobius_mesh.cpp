// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Our side of bench_subdivision (see bench_subdivision.h for why it is a
// translation unit of its own). It must not include heap_accounting.h: the
// program's main unit defines the counting operators.

#include "bench_subdivision.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
#include <CGAL/tags.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace subdivision_bench {

struct Our_mesh::Impl
{
  CGAL_ext::Mobius_mesh<Point> mesh;
};

Our_mesh::Our_mesh() : impl_(std::make_unique<Impl>()) {}
Our_mesh::~Our_mesh() = default;

void Our_mesh::assign(const Soup& soup)
{
  impl_->mesh.clear();
  CGAL_ext::polygon_soup_to_mobius_mesh(soup.points, soup.polygons, impl_->mesh);
}

void Our_mesh::assign(const Our_mesh& other) { impl_->mesh = other.impl_->mesh; }

void Our_mesh::clear() { impl_->mesh = CGAL_ext::Mobius_mesh<Point>(); }

void Our_mesh::subdivide(Scheme scheme, unsigned levels, bool parallel)
{
  namespace S = CGAL_ext::Subdivision;
  const auto np = CGAL_ext::parameters::number_of_iterations(levels);
  auto& mesh = impl_->mesh;
  auto run = [&](auto tag) {
    using Tag = decltype(tag);
    switch (scheme) {
    case Scheme::catmull_clark: S::catmull_clark<Tag>(mesh, np); return;
    case Scheme::loop: S::loop<Tag>(mesh, np); return;
    case Scheme::bilinear: S::bilinear<Tag>(mesh, np); return;
    case Scheme::doo_sabin: S::doo_sabin<Tag>(mesh, np); return;
    case Scheme::sqrt3: S::sqrt3<Tag>(mesh, np); return;
    }
  };
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  if (parallel) {
    run(CGAL::Parallel_tag());
    return;
  }
#else
  (void)parallel; // registered only when parallel_available()
#endif
  run(CGAL::Sequential_tag());
}

void Our_mesh::refine_once(bool parallel, std::uint32_t parallel_min_vertices)
{
  namespace S = CGAL_ext::Subdivision;
  using Mesh = CGAL_ext::Mobius_mesh<Point>;
  Mesh& mesh = impl_->mesh;
  S::Refinement_options options;
  options.parallel_min_vertices = parallel_min_vertices;
  S::Refiner<S::Catmull_clark_mask> refiner(S::Catmull_clark_mask(), options);
  S::internal::Array<S::internal::Vec3> values(mesh.number_of_vertices());
  for (auto v : mesh.vertices())
    values[v.idx()] = {mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()};
  Mesh out;
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  if (parallel)
    refiner.refine_and_interpolate<CGAL::Parallel_tag>(mesh, 1, values, out);
  else
#endif
    refiner.refine_and_interpolate(mesh, 1, values, out);
  (void)parallel;
  for (auto v : out.vertices())
    out.point(v) = Point(values[v.idx()].x, values[v.idx()].y, values[v.idx()].z);
  mesh = std::move(out);
}

std::uint32_t Our_mesh::automatic_threshold() { return CGAL_ext::Subdivision::Refinement_options::automatic; }

std::size_t Our_mesh::number_of_vertices() const { return impl_->mesh.number_of_vertices(); }
std::size_t Our_mesh::number_of_faces() const { return impl_->mesh.number_of_faces(); }

std::vector<Point> Our_mesh::points() const
{
  std::vector<Point> p;
  p.reserve(impl_->mesh.number_of_vertices());
  for (auto v : impl_->mesh.vertices())
    p.push_back(impl_->mesh.point(v));
  return p;
}

bool parallel_available()
{
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  return true;
#else
  return false;
#endif
}

#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
struct Thread_limit::Impl
{
  tbb::global_control control;
};
Thread_limit::Thread_limit(int threads)
  : impl_(new Impl{tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(threads))})
{}
#else
struct Thread_limit::Impl
{};
Thread_limit::Thread_limit(int) {}
#endif
Thread_limit::~Thread_limit() = default;

std::size_t Thread_limit::allowed()
{
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
#else
  return 1;
#endif
}

void write_blocks(const std::vector<Block>& blocks, unsigned parts)
{
  // Slices start on page boundaries, so that no page is shared by two
  // writers: each faults in its own pages on a cold run.
  constexpr std::size_t page = 4096;
  auto write_slice = [&](std::size_t i) {
    for (const Block& b : blocks) {
      const std::size_t slice = (b.size / parts + page - 1) / page * page;
      const std::size_t begin = (std::min)(b.size, i * slice), end = (std::min)(b.size, begin + slice);
      std::memset(b.data + begin, 0x5a, end - begin);
    }
  };
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  if (parts > 1) {
    tbb::parallel_for(std::size_t(0), std::size_t(parts), write_slice, tbb::static_partitioner());
    return;
  }
#endif
  for (std::size_t i = 0; i < parts; ++i)
    write_slice(i);
}

std::size_t write_then_read(std::vector<double>& data, std::vector<double>& sums, unsigned parts, bool other)
{
  const std::size_t n = data.size(), shift = other ? n / 2 : 0;
  double* d = data.data();
  double* s = sums.data();
  auto write = [d](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      d[k] = d[k] * 0.5 + 1.0;
  };
  auto read = [d, s, n, shift](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      s[k] += d[k < n - shift ? k + shift : k + shift - n];
  };
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  if (parts > 1) {
    // The static partition gives each thread the same slice in both loops.
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, n), [&](const Range& r) { write(r.begin(), r.end()); }, tbb::static_partitioner());
    tbb::parallel_for(Range(0, n), [&](const Range& r) { read(r.begin(), r.end()); }, tbb::static_partitioner());
    return n;
  }
#endif
  write(0, n);
  read(0, n);
  return n;
}

std::vector<std::size_t> mesh_array_bytes(std::size_t vertices, std::size_t edges, std::size_t faces)
{
  using namespace CGAL_ext;
  const std::size_t halfedges = 2 * edges;
  return {vertices * sizeof(Point),          vertices * sizeof(Dart),
          halfedges * sizeof(Vertex_index),  halfedges * sizeof(Dart),
          halfedges * sizeof(Dart),          halfedges * sizeof(Face_index),
          edges * sizeof(std::uint8_t),      faces * sizeof(Halfedge_index)};
}

namespace {

Soup soup_of(const CGAL_ext::Mobius_mesh<Point>& mesh)
{
  Soup s;
  s.points.reserve(mesh.number_of_vertices());
  for (auto v : mesh.vertices())
    s.points.push_back(mesh.point(v));
  s.polygons.reserve(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    Polygon& polygon = s.polygons.emplace_back();
    for (auto v : CGAL_ext::vertices_around_face(f, mesh))
      polygon.push_back(v.idx());
  }
  return s;
}

} // namespace

Soup torus_soup(std::size_t nu, std::size_t nv)
{
  CGAL_ext::Mobius_mesh<Point> mesh;
  CGAL_ext::make_torus(mesh, nu, nv);
  return soup_of(mesh);
}

Soup mobius_strip_soup(std::size_t n_around, std::size_t n_across)
{
  CGAL_ext::Mobius_mesh<Point> mesh;
  CGAL_ext::make_mobius_strip(mesh, n_around, n_across);
  return soup_of(mesh);
}

Soup klein_bottle_soup(std::size_t nu, std::size_t nv)
{
  CGAL_ext::Mobius_mesh<Point> mesh;
  CGAL_ext::make_klein_bottle(mesh, nu, nv);
  return soup_of(mesh);
}

} // namespace subdivision_bench
