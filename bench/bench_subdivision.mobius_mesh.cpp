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
#include <tbb/global_control.h>
#endif

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
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  if (parallel) {
    if (scheme == Scheme::catmull_clark)
      S::catmull_clark<CGAL::Parallel_tag>(mesh, np);
    else
      S::loop<CGAL::Parallel_tag>(mesh, np);
    return;
  }
#else
  (void)parallel; // registered only when parallel_available()
#endif
  if (scheme == Scheme::catmull_clark)
    S::catmull_clark(mesh, np);
  else
    S::loop(mesh, np);
}

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

void limit_threads([[maybe_unused]] int threads)
{
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  // Lives to the end of the program: the cap holds while the object exists.
  static tbb::global_control control(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
}

Soup torus_soup(std::size_t nu, std::size_t nv)
{
  CGAL_ext::Mobius_mesh<Point> mesh;
  CGAL_ext::make_torus(mesh, nu, nv);
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

} // namespace subdivision_bench
