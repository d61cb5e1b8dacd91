// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The limit surface at points spread over a mesh, side by side:
// CGAL_ext::Subdivision::Limit_surface against OpenSubdiv's Bfr
// (Far::TopologyRefiner, Bfr::RefinerSurfaceFactory, a Bfr::Surface per
// face, its patch points, Evaluate) on the same points and faces:
//   limit_surface/evaluate/torus320x320  make_torus(mesh, 320, 320): 102 400 quads, all regular
//   limit_surface/evaluate/cube_level7   a cube refined seven times by catmull_clark(): 98 304 quads
//                                        round 8 vertices of valence 3 (Gregory patches there)
//   limit_surface/evaluate/octahedron_level7  Loop: an octahedron refined seven times by loop():
//                                        131 072 triangles round 6 vertices of valence 4
// 10 parameters per face (about a million points), the same for both, each
// evaluated with its first and second derivatives (what Limit_surface
// always computes). Timed: from the mesh (ours) or the points and face
// lists (Bfr) to every point evaluated, the surface's construction
// included; the factory's cache is Bfr's default. Implementations:
// CGAL_ext_Limit_surface (serial), CGAL_ext_Limit_surface_parallel/threads:N
// (faces split among N TBB threads, one surface), OpenSubdiv_Bfr and
// OpenSubdiv_Bfr_parallel/threads:N (one factory whose cache threads may
// share, Bfr::SurfaceFactoryCacheThreaded; a Surface per thread), and
// CGAL_ext_uniform_2_levels: uniform refinement (catmull_clark() or
// loop()) to about the same number of points (16 or 10 per face; points of
// the level, not of the limit).
//
//   limit_surface/tessellate/...         each face tessellated at rate 4
//                                        (16 quads a quad, 16 triangles a
//                                        triangle): ours, Limit_surface::
//                                        tessellate(4), a connected mesh with a
//                                        normal per corner; Bfr, per face a
//                                        Bfr::Tessellation at rate 4 (triangles)
//                                        whose coordinates are evaluated with
//                                        first derivatives, the points and
//                                        facets kept per face (a soup: Bfr does
//                                        not join them); the surface's
//                                        construction included in both. The same
//                                        density as CGAL_ext_uniform_2_levels.
//                                        ..._parallel/threads:N on N TBB threads:
//                                        ours tessellate<CGAL::Parallel_tag>(4)
//                                        (the serial mesh, bit for bit); Bfr's
//                                        faces in blocks of 256, each block a
//                                        soup of its own, joined in face order.
//   limit_surface/tessellate_rate8/...   the same at rate 8 (64 facets a face:
//                                        6.6 M quads of the torus, 8.4 M
//                                        triangles of the octahedron; Bfr 13.1 M
//                                        and 8.4 M triangles), beside uniform
//                                        refinement by three levels (the same
//                                        number of faces).
//   limit_surface/closest_point/...      ours alone: 10 000 queries near the
//                                        surface (the search structure built
//                                        in the first, and counted).
//
// At start the program checks that both give the same points (to 1e-9 of
// the size) on every face: a comparison of different outputs is worthless.

#include <CGAL_ext/Limit_surface.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>

#include <benchmark/benchmark.h>

#if CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surfaceFactoryCache.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
namespace S = CGAL_ext::Subdivision;
template <class Mask>
using Surface = S::Limit_surface<Mask, Point>;

constexpr int points_per_face = 10;

struct Input
{
  Mesh mesh;
  std::vector<std::array<double, 2>> parameters; // points_per_face per face, face by face
};

Input make_input(const std::string& name)
{
  Input in;
  if (name == "torus320x320") {
    CGAL_ext::make_torus(in.mesh, 320, 320);
  } else if (name == "octahedron_level7") {
    const std::vector<Point> corners{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const std::vector<std::vector<std::size_t>> triangles{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                          {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    CGAL_ext::polygon_soup_to_mobius_mesh(corners, triangles, in.mesh);
    S::loop(in.mesh, CGAL_ext::parameters::number_of_iterations(7));
  } else {
    const std::vector<Point> corners{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const std::vector<std::vector<std::size_t>> quads{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    CGAL_ext::polygon_soup_to_mobius_mesh(corners, quads, in.mesh);
    S::catmull_clark(in.mesh, CGAL_ext::parameters::number_of_iterations(7));
  }
  CGAL::Random random(1);
  in.parameters.resize(in.mesh.number_of_faces() * points_per_face);
  for (auto& uv : in.parameters) {
    uv = {random.get_double(0, 1), random.get_double(0, 1)};
    if (name == "octahedron_level7" && uv[0] + uv[1] > 1) // into the triangle, evenly
      uv = {1 - uv[0], 1 - uv[1]};
  }
  return in;
}

const Input& input(const std::string& name)
{
  static std::map<std::string, Input> inputs;
  auto it = inputs.find(name);
  if (it == inputs.end())
    it = inputs.emplace(name, make_input(name)).first;
  return it->second;
}

// Evaluates the points of faces [begin, end) on `surface`; returns a sum that
// keeps the compiler from dropping the work.
template <class Mask>
double evaluate_ours(const Surface<Mask>& surface, const Input& in, std::size_t begin, std::size_t end)
{
  double sum = 0;
  for (std::size_t f = begin; f < end; ++f)
    for (int k = 0; k < points_per_face; ++k) {
      const auto& uv = in.parameters[f * points_per_face + std::size_t(k)];
      sum += surface.evaluate(CGAL_ext::Face_index(f), uv[0], uv[1]).point.x();
    }
  return sum;
}

#if CGAL_EXT_HAVE_OPENSUBDIV
namespace Far = OpenSubdiv::Far;
namespace Bfr = OpenSubdiv::Bfr;

// The mesh as OpenSubdiv takes it: coordinates and face lists.
struct Osd_input
{
  std::vector<double> xyz;
  std::vector<int> sizes, indices;
};

Osd_input osd_input(const Mesh& m)
{
  Osd_input o;
  for (CGAL_ext::Vertex_index v : m.vertices())
    o.xyz.insert(o.xyz.end(), {m.point(v).x(), m.point(v).y(), m.point(v).z()});
  for (CGAL_ext::Face_index f : m.faces()) {
    o.sizes.push_back(int(m.degree(f)));
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(m.halfedge(f), m))
      o.indices.push_back(int(v.idx()));
  }
  return o;
}

template <class Mask>
std::unique_ptr<Far::TopologyRefiner> osd_refiner(const Osd_input& o)
{
  Far::TopologyDescriptor desc;
  desc.numVertices = int(o.xyz.size() / 3);
  desc.numFaces = int(o.sizes.size());
  desc.numVertsPerFace = o.sizes.data();
  desc.vertIndicesPerFace = o.indices.data();
  OpenSubdiv::Sdc::Options options;
  options.SetVtxBoundaryInterpolation(OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(
    Factory::Create(desc, Factory::Options(std::is_same_v<Mask, S::Loop_mask> ? OpenSubdiv::Sdc::SCHEME_LOOP
                                                                              : OpenSubdiv::Sdc::SCHEME_CATMARK,
                                           options)));
}

// Bfr on faces [begin, end), one Surface and one buffer of patch points
// for the range; `out` (if given) receives the positions.
double evaluate_bfr(const Bfr::SurfaceFactory& factory, const Osd_input& o, const Input& in,
                    std::size_t begin, std::size_t end, std::vector<double>* out = nullptr)
{
  Bfr::Surface<double> surface;
  std::vector<double> patch_points;
  double sum = 0;
  for (std::size_t f = begin; f < end; ++f) {
    factory.InitVertexSurface(int(f), &surface);
    patch_points.resize(std::size_t(surface.GetNumPatchPoints()) * 3);
    surface.PreparePatchPoints(o.xyz.data(), 3, patch_points.data(), 3);
    for (int k = 0; k < points_per_face; ++k) {
      const auto& uv = in.parameters[f * points_per_face + std::size_t(k)];
      double p[3], du[3], dv[3], duu[3], duv[3], dvv[3];
      surface.Evaluate(uv.data(), patch_points.data(), 3, p, du, dv, duu, duv, dvv);
      sum += p[0];
      if (out)
        out->insert(out->end(), {p[0], p[1], p[2]});
    }
  }
  return sum;
}

// Both give the same points, or the comparison is void.
template <class Mask>
bool same_points(const std::string& name)
{
  const Input& in = input(name);
  const Surface<Mask> surface(in.mesh);
  const Osd_input o = osd_input(in.mesh);
  const auto refiner = osd_refiner<Mask>(o);
  const Bfr::RefinerSurfaceFactory<> factory(*refiner);
  std::vector<double> theirs;
  evaluate_bfr(factory, o, in, 0, in.mesh.number_of_faces(), &theirs);
  double worst = 0, size = 0;
  for (std::size_t f = 0; f < in.mesh.number_of_faces(); ++f)
    for (int k = 0; k < points_per_face; ++k) {
      const std::size_t i = f * points_per_face + std::size_t(k);
      const Point p = surface.evaluate(CGAL_ext::Face_index(f), in.parameters[i][0], in.parameters[i][1]).point;
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(p[c] - theirs[3 * i + std::size_t(c)]));
        size = std::max(size, std::abs(p[c]));
      }
    }
  if (worst <= 1e-9 * size)
    return true;
  std::cerr << name << ": Limit_surface and Bfr differ by " << worst << " (size " << size << ")\n";
  return false;
}
#endif

// Runs `work(begin, end)` over the faces on `threads` TBB threads (serially
// without TBB).
template <class Work>
double over_faces(std::size_t faces, int threads, const Work& work)
{
#ifdef CGAL_LINKED_WITH_TBB
  if (threads > 1) {
    return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, faces, 256), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double sum) { return sum + work(r.begin(), r.end()); },
      [](double a, double b) { return a + b; });
  }
#endif
  (void)threads;
  return work(0, faces);
}

struct Thread_cap
{
#ifdef CGAL_LINKED_WITH_TBB
  explicit Thread_cap(int threads)
    : control(tbb::global_control::max_allowed_parallelism, std::size_t(std::max(threads, 1)))
  {}
  tbb::global_control control;
#else
  explicit Thread_cap(int) {}
#endif
};

template <class Mask>
void ours(benchmark::State& state, const std::string& name, int threads)
{
  const Input& in = input(name);
  const Thread_cap cap(threads);
  for (auto _ : state) {
    const Surface<Mask> surface(in.mesh);
    benchmark::DoNotOptimize(over_faces(in.mesh.number_of_faces(), threads, [&](std::size_t b, std::size_t e) {
      return evaluate_ours(surface, in, b, e);
    }));
  }
  state.counters["points"] = double(in.parameters.size());
}

template <class Mask>
void refinement(benchmark::State& state, const std::string& name, int levels)
{
  const Input& in = input(name);
  for (auto _ : state) {
    state.PauseTiming();
    Mesh m = in.mesh;
    state.ResumeTiming();
    if constexpr (std::is_same_v<Mask, S::Loop_mask>)
      S::loop(m, CGAL_ext::parameters::number_of_iterations(unsigned(levels)));
    else
      S::catmull_clark(m, CGAL_ext::parameters::number_of_iterations(unsigned(levels)));
    benchmark::DoNotOptimize(m.number_of_vertices());
  }
  state.counters["faces"] = double(in.mesh.number_of_faces() << (2 * levels)); // both schemes: 4 faces a face a level
}

#if CGAL_EXT_HAVE_OPENSUBDIV
// A cache that threads may share: the factory's default one may not be
// (OpenSubdiv's refinerSurfaceFactory.h), and irregular faces write to it.
using Shared_cache = Bfr::SurfaceFactoryCacheThreaded<std::shared_mutex, std::shared_lock<std::shared_mutex>,
                                                      std::unique_lock<std::shared_mutex>>;

// Calls body(factory) with a factory on `refiner` whose cache several
// threads may use if `shared`, else Bfr's default one.
template <class Body>
void with_bfr_factory(const Far::TopologyRefiner& refiner, bool shared, const Body& body)
{
  if (shared) {
    const Bfr::RefinerSurfaceFactory<Shared_cache> factory(refiner);
    body(factory);
  } else {
    const Bfr::RefinerSurfaceFactory<> factory(refiner);
    body(factory);
  }
}

template <class Mask>
void bfr(benchmark::State& state, const std::string& name, int threads)
{
  const Input& in = input(name);
  const Osd_input o = osd_input(in.mesh);
  const Thread_cap cap(threads);
  for (auto _ : state) {
    const auto refiner = osd_refiner<Mask>(o);
    with_bfr_factory(*refiner, threads > 1, [&](const Bfr::SurfaceFactory& factory) {
      benchmark::DoNotOptimize(over_faces(in.mesh.number_of_faces(), threads, [&](std::size_t b, std::size_t e) {
        return evaluate_bfr(factory, o, in, b, e);
      }));
    });
  }
  state.counters["points"] = double(in.parameters.size());
}
#endif

// Serially with threads = 0, else under CGAL::Parallel_tag on that many threads.
template <class Mask>
void tessellate_ours(benchmark::State& state, const std::string& name, int rate, int threads)
{
  const Input& in = input(name);
  const Thread_cap cap(threads);
  std::size_t faces = 0;
  for (auto _ : state) {
    const Surface<Mask> surface(in.mesh);
#ifdef CGAL_LINKED_WITH_TBB
    const Mesh t = threads > 0 ? surface.template tessellate<CGAL::Parallel_tag>(rate) : surface.tessellate(rate);
#else
    const Mesh t = surface.tessellate(rate);
#endif
    faces = t.number_of_faces();
    benchmark::DoNotOptimize(faces);
  }
  state.counters["facets"] = double(faces);
}

#if CGAL_EXT_HAVE_OPENSUBDIV
// A soup of Bfr's tessellations: points, their first derivatives (for the
// normals), and triangles.
struct Bfr_soup
{
  std::vector<double> points, derivatives;
  std::vector<int> facets;
};

// Per face of [begin, end): Bfr's tessellation at `rate` (triangles), its
// coordinates evaluated with first derivatives, points and facets appended to `soup`.
void tessellate_bfr_faces(const Bfr::SurfaceFactory& factory, const Osd_input& o, int rate, std::size_t begin,
                          std::size_t end, Bfr_soup& soup)
{
  Bfr::Surface<double> surface;
  std::vector<double> patch_points, coords;
  for (std::size_t f = begin; f < end; ++f) {
    factory.InitVertexSurface(int(f), &surface);
    patch_points.resize(std::size_t(surface.GetNumPatchPoints()) * 3);
    surface.PreparePatchPoints(o.xyz.data(), 3, patch_points.data(), 3);
    const Bfr::Tessellation tessellation(surface.GetParameterization(), rate);
    coords.resize(2 * std::size_t(tessellation.GetNumCoords()));
    tessellation.GetCoords(coords.data());
    const int first = int(soup.points.size() / 3);
    for (std::size_t i = 0; i < coords.size(); i += 2) {
      double p[3], du[3], dv[3];
      surface.Evaluate(&coords[i], patch_points.data(), 3, p, du, dv);
      soup.points.insert(soup.points.end(), p, p + 3);
      soup.derivatives.insert(soup.derivatives.end(), {du[0], du[1], du[2], dv[0], dv[1], dv[2]});
    }
    const std::size_t at = soup.facets.size();
    soup.facets.resize(at + 3 * std::size_t(tessellation.GetNumFacets()));
    tessellation.GetFacets(soup.facets.data() + at);
    for (std::size_t i = at; i < soup.facets.size(); ++i)
      soup.facets[i] += first;
  }
}

#ifdef CGAL_LINKED_WITH_TBB
// Faces [0, nf) in blocks of 256 on the TBB threads, each block into a soup
// of its own, the soups joined in face order into `soup`.
inline void tessellate_bfr_in_blocks(const Bfr::SurfaceFactory& factory, const Osd_input& o, int rate, std::size_t nf,
                                     Bfr_soup& soup)
{
  constexpr std::size_t block = 256;
  std::vector<Bfr_soup> parts((nf + block - 1) / block);
  tbb::parallel_for(std::size_t(0), parts.size(), [&](std::size_t b) {
    tessellate_bfr_faces(factory, o, rate, b * block, std::min(nf, (b + 1) * block), parts[b]);
  });
  std::size_t points = 0, corners = 0;
  for (const Bfr_soup& part : parts) {
    points += part.points.size();
    corners += part.facets.size();
  }
  soup.points.reserve(points);
  soup.derivatives.reserve(2 * points);
  soup.facets.reserve(corners);
  for (const Bfr_soup& part : parts) {
    const int first = int(soup.points.size() / 3);
    soup.points.insert(soup.points.end(), part.points.begin(), part.points.end());
    soup.derivatives.insert(soup.derivatives.end(), part.derivatives.begin(), part.derivatives.end());
    for (int i : part.facets)
      soup.facets.push_back(i + first);
  }
}
#else
inline void tessellate_bfr_in_blocks(const Bfr::SurfaceFactory& factory, const Osd_input& o, int rate, std::size_t nf,
                                     Bfr_soup& soup)
{
  tessellate_bfr_faces(factory, o, rate, 0, nf, soup);
}
#endif

// The whole mesh into one soup: serially with threads = 0; else blocks of
// faces on `threads` TBB threads (one factory with a shared cache, a Surface per block), each
// into a soup of its own, joined in face order.
template <class Mask>
void tessellate_bfr(benchmark::State& state, const std::string& name, int rate, int threads)
{
  const Input& in = input(name);
  const Osd_input o = osd_input(in.mesh);
  const Thread_cap cap(threads);
  const std::size_t nf = in.mesh.number_of_faces();
  std::size_t facets = 0;
  for (auto _ : state) {
    const auto refiner = osd_refiner<Mask>(o);
    Bfr_soup soup;
    with_bfr_factory(*refiner, threads > 0, [&](const Bfr::SurfaceFactory& factory) {
      if (threads == 0)
        tessellate_bfr_faces(factory, o, rate, 0, nf, soup);
      else
        tessellate_bfr_in_blocks(factory, o, rate, nf, soup);
    });
    facets = soup.facets.size() / 3;
    benchmark::DoNotOptimize(soup.points.data());
  }
  state.counters["facets"] = double(facets);
}
#endif

// Queries pushed off the surface along its normal by 1 % of the size, from
// fresh parameters of random faces.
template <class Mask>
void closest_points(benchmark::State& state, const std::string& name)
{
  const Input& in = input(name);
  std::vector<Point> queries;
  {
    const Surface<Mask> surface(in.mesh);
    CGAL::Random random(2);
    for (int i = 0; i < 10000; ++i) {
      const auto f = CGAL_ext::Face_index(std::size_t(random.get_int(0, int(in.mesh.number_of_faces()))));
      const double u = random.get_double(0, 1), v = random.get_double(0, 1 - (std::is_same_v<Mask, S::Loop_mask> ? u : 0));
      const auto e = surface.evaluate(f, u, v);
      queries.push_back(e.point + 0.01 * e.normal);
    }
  }
  for (auto _ : state) {
    const Surface<Mask> surface(in.mesh);
    double sum = 0;
    for (const Point& q : queries)
      sum += surface.closest_point(q).squared_distance;
    benchmark::DoNotOptimize(sum);
  }
  state.counters["queries"] = double(queries.size());
}

std::vector<int> thread_counts()
{
  std::vector<int> counts;
  const int hardware = int(std::max(std::thread::hardware_concurrency(), 1u));
  for (int t = 1; t < hardware; t *= 2)
    counts.push_back(t);
  counts.push_back(hardware);
  return counts;
}

// Real time (threads work beside the main one), in milliseconds.
template <class... Args>
void add(const std::string& benchmark_name, Args&&... args)
{
  benchmark::RegisterBenchmark(benchmark_name.c_str(), std::forward<Args>(args)...)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
}

// Ours and Bfr's tessellation at `rate`, serially and on each thread count.
template <class Mask>
void register_tessellation(const std::string& group, const std::string& name, int rate)
{
  add(group + "CGAL_ext_Limit_surface", tessellate_ours<Mask>, name, rate, 0);
#ifdef CGAL_LINKED_WITH_TBB
  for (int t : thread_counts())
    add(group + "CGAL_ext_Limit_surface_parallel/threads:" + std::to_string(t), tessellate_ours<Mask>, name, rate, t);
#endif
#if CGAL_EXT_HAVE_OPENSUBDIV
  add(group + "OpenSubdiv_Bfr", tessellate_bfr<Mask>, name, rate, 0);
#ifdef CGAL_LINKED_WITH_TBB
  for (int t : thread_counts())
    add(group + "OpenSubdiv_Bfr_parallel/threads:" + std::to_string(t), tessellate_bfr<Mask>, name, rate, t);
#endif
#endif
}

template <class Mask>
void register_case(const std::string& name)
{
  const std::string group = "limit_surface/evaluate/" + name + "/";
  add(group + "CGAL_ext_Limit_surface", ours<Mask>, name, 1);
#ifdef CGAL_LINKED_WITH_TBB
  for (int t : thread_counts())
    add(group + "CGAL_ext_Limit_surface_parallel/threads:" + std::to_string(t), ours<Mask>, name, t);
#endif
#if CGAL_EXT_HAVE_OPENSUBDIV
  add(group + "OpenSubdiv_Bfr", bfr<Mask>, name, 1);
#ifdef CGAL_LINKED_WITH_TBB
  for (int t : thread_counts())
    add(group + "OpenSubdiv_Bfr_parallel/threads:" + std::to_string(t), bfr<Mask>, name, t);
#endif
#endif
  add(group + "CGAL_ext_uniform_2_levels", refinement<Mask>, name, 2);
  register_tessellation<Mask>("limit_surface/tessellate/" + name + "/", name, 4);
  add("limit_surface/closest_point/" + name + "/CGAL_ext_Limit_surface", closest_points<Mask>, name);
}

// Tessellations of about ten million triangles: rate 8, 64 facets a face,
// and uniform refinement by three levels to the same density.
template <class Mask>
void register_large_tessellation(const std::string& name)
{
  const std::string group = "limit_surface/tessellate_rate8/" + name + "/";
  register_tessellation<Mask>(group, name, 8);
  add(group + "CGAL_ext_uniform_3_levels", refinement<Mask>, name, 3);
}

void register_all()
{
  register_case<S::Catmull_clark_mask>("torus320x320");
  register_case<S::Catmull_clark_mask>("cube_level7");
  register_case<S::Loop_mask>("octahedron_level7");
  register_large_tessellation<S::Catmull_clark_mask>("torus320x320");
  register_large_tessellation<S::Loop_mask>("octahedron_level7");
}

} // namespace

int main(int argc, char** argv)
{
#if CGAL_EXT_HAVE_OPENSUBDIV
  if (!same_points<S::Catmull_clark_mask>("torus320x320") || !same_points<S::Catmull_clark_mask>("cube_level7") ||
      !same_points<S::Loop_mask>("octahedron_level7"))
    return 1;
#endif
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
