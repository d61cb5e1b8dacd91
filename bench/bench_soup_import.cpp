// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Polygon soup import, side by side: CGAL_ext::polygon_soup_to_mobius_mesh
// into a Mobius_mesh versus CGAL's polygon_soup_to_polygon_mesh into a
// Surface_mesh, on the same in-memory soups (a torus grid of quads, the same
// grid triangulated, and a Möbius strip grid).
//
// Timed: building the mesh and destroying it; the soup is built beforehand.
// Counters (measured once per run, outside the timed loop):
//   faces                 faces of the soup
//   bytes_per_face        heap the built mesh keeps, per face
//   peak_bytes_per_face   highest heap above the starting level while building
//   faults_per_face       minor page faults per face and iteration (first
//                         touches of fresh memory, which cost ~10 µs per page here)
//
// Benchmark names follow `group/case/implementation`; scripts/bench.sh takes
// the implementation whose name starts with `CGAL_ext` as the reference of its
// case and prints each peer's time and bytes relative to it.
//
// Options (before Google Benchmark's own): --grid=N makes the torus N x N and
// the Möbius strip 2N x N/2 (default 1000, about 1M faces each).

#include "bench_soup_import.h"
// The counting operator new / delete: in this translation unit only.
#include "heap_accounting.h"
#include "heap_modes.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace {

using namespace soup_import;
using CGAL_mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct Soup
{
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  long long euler_characteristic = 0;
};

// Torus grid of n x m quads (or 2 n m triangles), closed in both directions.
Soup torus_soup(std::size_t n, std::size_t m, bool triangles)
{
  const double pi = std::acos(-1.0), R = 3.0, r = 1.0;
  Soup s;
  s.points.reserve(n * m);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const double u = 2 * pi * double(i) / double(n), v = 2 * pi * double(j) / double(m);
      s.points.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % n) * m + (j % m); };
  s.polygons.reserve(triangles ? 2 * n * m : n * m);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangles) {
        s.polygons.push_back({a, b, c});
        s.polygons.push_back({a, c, d});
      } else {
        s.polygons.push_back({a, b, c, d});
      }
    }
  s.euler_characteristic = 0;
  return s;
}

// Möbius strip grid: n quads along the strip, m across; the last column of
// quads joins the first one with a half twist, so the soup is not orientable.
Soup mobius_soup(std::size_t n, std::size_t m)
{
  const double pi = std::acos(-1.0), R = 3.0, w = 1.0;
  Soup s;
  s.points.reserve(n * (m + 1));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j <= m; ++j) {
      const double u = 2 * pi * double(i) / double(n), v = w * (double(j) / double(m) - 0.5);
      s.points.emplace_back((R + v * std::cos(u / 2)) * std::cos(u), (R + v * std::cos(u / 2)) * std::sin(u),
                            v * std::sin(u / 2));
    }
  auto id = [&](std::size_t i, std::size_t j) { return i == n ? (m - j) : i * (m + 1) + j; };
  s.polygons.reserve(n * m);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j)
      s.polygons.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  s.euler_characteristic = 0;
  return s;
}

std::size_t grid = 1000;

enum class Soup_kind { torus_quads, torus_triangles, mobius_quads };

// One soup at a time is kept: the benchmarks of a case run one after another.
const Soup& soup(Soup_kind kind)
{
  static Soup_kind cached_kind;
  static std::unique_ptr<Soup> cached;
  if (!cached || cached_kind != kind) {
    cached.reset();
    switch (kind) {
    case Soup_kind::torus_quads: cached = std::make_unique<Soup>(torus_soup(grid, grid, false)); break;
    case Soup_kind::torus_triangles: cached = std::make_unique<Soup>(torus_soup(grid, grid, true)); break;
    case Soup_kind::mobius_quads:
      cached = std::make_unique<Soup>(mobius_soup(2 * grid, (std::max)(std::size_t(1), grid / 2)));
      break;
    }
    cached_kind = kind;
  }
  return *cached;
}

long minor_faults()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// Heap use of one build: what the mesh keeps, and the highest heap above the
// baseline while building. Everything counted is allocated after `start()`;
// input copies made in between are set aside with `set_baseline()` and freed
// before `read()`, so only the mesh remains counted.
struct Heap_meter
{
  std::int64_t base = 0;
  double kept = 0, peak = 0;

  void start()
  {
    heap::live = heap::peak = base = 0;
    heap::counting = true;
  }
  void set_baseline() { base = heap::peak = heap::live; }
  void read()
  {
    kept = double(heap::live);
    peak = double(heap::peak - base);
    heap::counting = false; // the mesh is freed uncounted
  }
};

void report(benchmark::State& state, const Soup& s, const Heap_meter& use, long faults)
{
  const double f = double(s.polygons.size());
  state.counters["faces"] = f;
  state.counters["bytes_per_face"] = use.kept / f;
  state.counters["peak_bytes_per_face"] = use.peak / f;
  state.counters["faults_per_face"] = double(faults) / double(state.iterations()) / f;
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(s.polygons.size()));
}

bool check(benchmark::State& state, const Soup& s, const Mesh_stats& m, bool check_euler)
{
  if (m.faces != s.polygons.size()) {
    state.SkipWithError(("built " + std::to_string(m.faces) + " faces of " + std::to_string(s.polygons.size())).c_str());
    return false;
  }
  const long long chi = (long long)m.vertices - (long long)m.edges + (long long)m.faces;
  if (check_euler && chi != s.euler_characteristic) {
    state.SkipWithError(("wrong Euler characteristic " + std::to_string(chi)).c_str());
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------

enum class Cgal_mode {
  plain,  // polygon_soup_to_polygon_mesh alone: no manifold check in Release
  check,  // is_polygon_soup_a_polygon_mesh first, as careful code does
  orient  // orient_polygon_soup first: the way to a Surface_mesh from a non-orientable soup
};

// A Surface_mesh from the soup, checked first or not; `while_built` runs while the mesh exists.
Mesh_stats import_into_surface_mesh(const std::vector<Point>& points, const std::vector<Polygon>& polygons,
                                    Cgal_mode mode, const std::function<void()>& while_built)
{
  CGAL_mesh mesh;
  if (mode == Cgal_mode::check && !PMP::is_polygon_soup_a_polygon_mesh(polygons))
    return {};
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (while_built)
    while_built();
  return {mesh.number_of_vertices(), mesh.number_of_edges(), mesh.number_of_faces()};
}

// The same after orient_polygon_soup, which works on the soup in place.
Mesh_stats orient_and_import_into_surface_mesh(std::vector<Point>& points, std::vector<Polygon>& polygons,
                                               const std::function<void()>& while_built)
{
  CGAL_mesh mesh;
  PMP::orient_polygon_soup(points, polygons);
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (while_built)
    while_built();
  return {mesh.number_of_vertices(), mesh.number_of_edges(), mesh.number_of_faces()};
}


// Times `build(points, polygons, while_built)` (one import, mesh destroyed), then
// measures the heap of one more build. With `needs_copy`, `build` gets a private
// copy of the soup, made outside the timed part; otherwise the shared soup.
template <bool needs_copy, class Build>
void run(benchmark::State& state, Soup_kind kind, Heap_mode heap_mode, bool check_euler, Build build)
{
  const Soup& s = soup(kind);
  set_heap_mode(heap_mode);
  const std::function<void()> nothing;
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  auto copy_soup = [&] {
    if (needs_copy) {
      points = s.points;
      polygons = s.polygons;
    }
  };
  auto build_once = [&](const std::function<void()>& while_built) {
    if constexpr (needs_copy)
      return build(points, polygons, while_built);
    else
      return build(s.points, s.polygons, while_built);
  };
  if (heap_mode == Heap_mode::warm) { // one untimed build leaves the pages in the heap
    copy_soup();
    build_once(nothing);
  }
  long faults = 0;
  for (auto _ : state) {
    if (needs_copy) {
      state.PauseTiming();
      copy_soup();
      state.ResumeTiming();
    }
    const long before = minor_faults();
    benchmark::DoNotOptimize(build_once(nothing).faces);
    faults += minor_faults() - before;
  }

  std::vector<Point>().swap(points); // no capacity left from the timed copies
  std::vector<Polygon>().swap(polygons);
  Heap_meter meter;
  meter.start();
  if (needs_copy) {
    points = s.points;
    polygons = s.polygons;
  }
  meter.set_baseline();
  const Mesh_stats stats = build_once([&] {
    if (needs_copy) { // free the copy, counted, so that only the mesh remains
      std::vector<Point>().swap(points);
      std::vector<Polygon>().swap(polygons);
    }
    meter.read();
  });
  std::vector<Point>().swap(points);
  std::vector<Polygon>().swap(polygons);
  if (check(state, s, stats, check_euler))
    report(state, s, meter, faults);
}

void register_all()
{
  const std::string n = std::to_string(grid);
  const std::string mobius_size = std::to_string(2 * grid) + "x" + std::to_string((std::max)(std::size_t(1), grid / 2));
  struct Case
  {
    std::string name;
    Soup_kind kind;
  };
  const Case cases[] = {{"torus_quads/" + n + "x" + n, Soup_kind::torus_quads},
                        {"torus_triangles/" + n + "x" + n + "x2", Soup_kind::torus_triangles},
                        {"mobius_quads/" + mobius_size, Soup_kind::mobius_quads}};
  auto add = [](const std::string& name, std::function<void(benchmark::State&)> f) {
    benchmark::RegisterBenchmark(("soup_import/" + name).c_str(), [f](benchmark::State& st) { f(st); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  };
  for (const Case& c : cases) {
    for (Heap_mode heap_mode : {Heap_mode::cold, Heap_mode::warm}) {
      const Soup_kind kind = c.kind;
      const std::string name = c.name + (heap_mode == Heap_mode::cold ? "/cold" : "/warm");
      const bool orientable = kind != Soup_kind::mobius_quads;
      add(name + "/CGAL_ext_Mobius_mesh", [=](benchmark::State& st) {
        run<false>(st, kind, heap_mode, true, [](const auto& points, const auto& polygons, const auto& f) {
          return import_into_mobius_mesh(points, polygons, f);
        });
      });
      auto add_cgal = [&](const std::string& impl, Cgal_mode mode) {
        add(name + "/" + impl, [=](benchmark::State& st) {
          if (mode == Cgal_mode::orient) {
            // Orienting cuts the Möbius strip open along a seam of duplicated vertices.
            run<true>(st, kind, heap_mode, false, [](auto& points, auto& polygons, const auto& f) {
              return orient_and_import_into_surface_mesh(points, polygons, f);
            });
          } else {
            run<false>(st, kind, heap_mode, true, [mode](const auto& points, const auto& polygons, const auto& f) {
              return import_into_surface_mesh(points, polygons, mode, f);
            });
          }
        });
      };
      if (orientable) {
        // A non-orientable soup breaks polygon_soup_to_polygon_mesh's precondition.
        add_cgal("CGAL_Surface_mesh", Cgal_mode::plain);
        add_cgal("CGAL_Surface_mesh_checked", Cgal_mode::check);
      }
      add_cgal("CGAL_Surface_mesh_oriented", Cgal_mode::orient);
    }
  }
}

} // namespace

int main(int argc, char** argv)
{
  // Take out our own option before Google Benchmark reads the rest.
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--grid=", 7) == 0)
      grid = std::size_t((std::max)(2L, std::strtol(argv[i] + 7, nullptr, 10)));
    else
      argv[kept++] = argv[i];
  }
  argc = kept;
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
