// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Border merging and Surface_mesh conversion, side by side with CGAL.
//
// merge/torus_halves/NxN/...: a closed N x N torus grid of quads cut at
//   u = 0 and u = pi into two tubes, each with its own copies of the cut
//   vertices (bit-identical coordinates).
//   two_meshes: CGAL_ext::merge_borders(a, b, tolerance(0)) on the two tubes;
//   one_mesh:   CGAL_ext::merge_borders(m, tolerance(0)) on one Mobius_mesh
//               holding both tubes.
//   CGAL_stitch_borders: PMP::stitch_borders on one Surface_mesh holding both
//   tubes (CGAL has no two-mesh stitch), in both cases; and for two meshes
//   CGAL_copy_face_graph_and_stitch_borders: copy_face_graph of the second
//   tube into the first, then stitch_borders, both timed.
// merge/fan_of_separate_triangles/N/...: N = 20 x grid triangles around one
//   centre, each a component of its own (N coincident copies of the centre,
//   two of each rim point), merged with itself into a disc by ours and by
//   PMP::stitch_borders. merge/copies_of_a_triangle/N/...: N copies of one
//   triangle, which merge_borders refuses (an edge would take N faces); the
//   time to refuse. Both stay near-linear in N however many points coincide.
// convert/to_surface_mesh/..., convert/from_surface_mesh/...: a torus of
//   N x N quads (orientable) and a Möbius strip of 2N x N/2 quads, converted
//   into an empty target; peers: CGAL::copy_face_graph Surface_mesh ->
//   Surface_mesh, and for the strip CGAL's only route from a non-orientable
//   surface to a Surface_mesh, orient_polygon_soup + polygon_soup_to_polygon_mesh.
//
// Timed: the operation alone. Copying the input (every operation here works
// in place or appends), emptying the target and destroying the previous
// result run with the timers paused. Each result is checked once after the
// timed loop (V/E/F); a wrong one aborts the program.
// Counter: faults, minor page faults per timed iteration.
//
// Options (before Google Benchmark's own):
//   --grid=N       grid size (default 1000: about 1M faces per case)
//   --heap=warm    (default) the C heap keeps freed pages, so iterations reuse
//                  them, as in a program that works on meshes repeatedly;
//   --heap=cold    every block of 128 KiB or more is a fresh mapping, returned
//                  on free, so each iteration touches new pages, as the only
//                  run of a command-line tool does.

// First: it declares the graph traits that keep CGAL's BGL overloads from
// breaking on Mobius_mesh when both are in one translation unit.
#include <CGAL_ext/Surface_mesh_conversion.h>

#include "heap_modes.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/merge_borders.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <benchmark/benchmark.h>

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using SM = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
using Polygon = std::vector<std::size_t>;

std::size_t grid = 1000;

struct Counts
{
  std::size_t v = 0, e = 0, f = 0;
  bool operator==(const Counts& o) const { return v == o.v && e == o.e && f == o.f; }
  std::string str() const
  {
    return "V=" + std::to_string(v) + " E=" + std::to_string(e) + " F=" + std::to_string(f);
  }
};
Counts counts(const Mesh& m) { return {m.number_of_vertices(), m.number_of_edges(), m.number_of_faces()}; }
Counts counts(const SM& m) { return {m.number_of_vertices(), m.number_of_edges(), m.number_of_faces()}; }

// A wrong result makes every time meaningless: stop the whole run.
void require(bool ok, const std::string& what)
{
  if (!ok) {
    std::fprintf(stderr, "bench_merge_conversion: %s\n", what.c_str());
    std::abort();
  }
}
template <class M>
void require_counts(const M& m, const Counts& expected, const std::string& what)
{
  require(counts(m) == expected, what + ": got " + counts(m).str() + ", expected " + expected.str());
}

// ---------------------------------------------------------------------------
// Inputs, built once, outside any timing.

// The torus point of grid vertex (i, j); i and j are taken modulo n so that
// the two halves compute their shared columns with the same expression.
Point torus_point(std::size_t i, std::size_t j, std::size_t n)
{
  const double pi = std::acos(-1.0), R = 2.0, r = 0.7;
  const double u = 2 * pi * double(i % n) / double(n), v = 2 * pi * double(j % n) / double(n);
  const double q = R + r * std::cos(v);
  return Point(q * std::cos(u), q * std::sin(u), r * std::sin(v));
}

// The tube of cells i0 <= i < i1 of the n x n torus, with its own vertex
// columns i0..i1, appended to the soup.
void add_tube(std::size_t i0, std::size_t i1, std::size_t n, std::vector<Point>& points,
              std::vector<Polygon>& polygons)
{
  const std::size_t base = points.size();
  for (std::size_t i = i0; i <= i1; ++i)
    for (std::size_t j = 0; j < n; ++j)
      points.push_back(torus_point(i, j, n));
  auto id = [&](std::size_t i, std::size_t j) { return base + (i - i0) * n + j % n; };
  for (std::size_t i = i0; i < i1; ++i)
    for (std::size_t j = 0; j < n; ++j)
      polygons.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
}

struct Halves
{
  Mesh a, b, both;   // the tubes, and both in one mesh
  SM sm_a, sm_b;     // the tubes as Surface_meshes
  SM sm_both;        // both tubes in one Surface_mesh
  Counts closed;   // the closed torus
};

const Halves& halves()
{
  static std::unique_ptr<Halves> h;
  if (!h) {
    h = std::make_unique<Halves>();
    const std::size_t n = grid, half = grid / 2;
    std::vector<Point> pa, pb;
    std::vector<Polygon> fa, fb;
    add_tube(0, half, n, pa, fa);
    add_tube(half, n, n, pb, fb);
    CGAL_ext::polygon_soup_to_mobius_mesh(pa, fa, h->a);
    CGAL_ext::polygon_soup_to_mobius_mesh(pb, fb, h->b);
    h->both = h->a;
    h->both.join(h->b);
    std::vector<Point> p = pa;
    std::vector<Polygon> f = fa;
    add_tube(half, n, n, p, f);
    PMP::polygon_soup_to_polygon_mesh(p, f, h->sm_both);
    PMP::polygon_soup_to_polygon_mesh(pa, fa, h->sm_a);
    PMP::polygon_soup_to_polygon_mesh(pb, fb, h->sm_b);
    h->closed = {n * n, 2 * n * n, n * n};
    const Counts tubes{h->closed.v + 2 * n, h->closed.e + 2 * n, h->closed.f};
    require_counts(h->both, tubes, "the two tubes");
    require_counts(h->sm_both, tubes, "the two tubes as a Surface_mesh");
  }
  return *h;
}

// Many border vertices at one point, as in a soup of duplicated faces from a
// bad exporter: n = 20 x grid separate triangles, around one centre (`fan`:
// they glue into a disc of n + 1 vertices, 2n edges) or all copies of one.
struct Coincident
{
  Mesh mesh;
  SM sm;
  Counts disc;
};

const Coincident& coincident(bool fan)
{
  static std::unique_ptr<Coincident> cached[2];
  std::unique_ptr<Coincident>& c = cached[fan ? 1 : 0];
  if (!c) {
    c = std::make_unique<Coincident>();
    const std::size_t n = 20 * grid;
    const double pi = std::acos(-1.0);
    auto rim = [&](std::size_t i) {
      const double a = 2 * pi * double(i % n) / double(n);
      return fan ? Point(std::cos(a), std::sin(a), 0) : Point(double(i % 2), double(1 - i % 2), 0);
    };
    std::vector<Point> points;
    std::vector<Polygon> polygons;
    for (std::size_t i = 0; i < n; ++i) {
      points.insert(points.end(), {Point(0, 0, 0), rim(fan ? i : 0), rim(fan ? i + 1 : 1)});
      polygons.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, c->mesh);
    PMP::polygon_soup_to_polygon_mesh(points, polygons, c->sm);
    c->disc = {n + 1, 2 * n, n};
  }
  return *c;
}

// A source mesh in both representations; for the Möbius strip, the
// Surface_mesh is to_surface_mesh's cut, and the soup is kept for CGAL's
// orient_polygon_soup route.
struct Source
{
  Mesh mesh;
  SM sm;
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

enum class Shape { torus, mobius };

std::string shape_name(Shape s)
{
  const std::string n = std::to_string(grid);
  if (s == Shape::torus)
    return "torus_quads/" + n + "x" + n;
  return "mobius_quads/" + std::to_string(2 * grid) + "x" + std::to_string((std::max)(std::size_t(1), grid / 2));
}

// One source at a time: the benchmarks of a shape run one after another.
const Source& source(Shape shape)
{
  static std::unique_ptr<Source> cached;
  static Shape cached_shape;
  if (!cached || cached_shape != shape) {
    cached.reset();
    cached = std::make_unique<Source>();
    Source& s = *cached;
    if (shape == Shape::torus)
      CGAL_ext::make_torus(s.mesh, grid, grid);
    else
      CGAL_ext::make_mobius_strip(s.mesh, 2 * grid, (std::max)(std::size_t(1), grid / 2));
    CGAL_ext::to_surface_mesh(s.mesh, s.sm);
    if (shape == Shape::mobius) {
      for (CGAL_ext::Vertex_index v : s.mesh.vertices())
        s.points.push_back(s.mesh.point(v));
      for (CGAL_ext::Face_index f : s.mesh.faces()) {
        Polygon p;
        for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(s.mesh.halfedge(f), s.mesh))
          p.push_back(s.mesh.source(d).idx());
        s.polygons.push_back(std::move(p));
      }
    }
    cached_shape = shape;
  }
  return *cached;
}

// ---------------------------------------------------------------------------
// The timed loop: `prepare` (paused) gives a fresh input or empty target and
// drops the previous result, `run` is timed, `check` sees the last result.
// With a warm heap, one untimed run first leaves the pages in the heap:
// otherwise the first iteration alone pays for first touches (~1 s of page
// faults for a 1M-face merge on these machines).

bool cold_heap = false;

// First touches of fresh pages, which cost ~10 µs each on these machines.
long minor_faults()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

template <class Prepare, class Run, class Check>
void timed(benchmark::State& state, Prepare prepare, Run run, Check check)
{
  if (!cold_heap) {
    prepare();
    run();
  }
  long faults = 0;
  for (auto _ : state) {
    state.PauseTiming();
    prepare();
    if (cold_heap) // free pages inside the heap go back too, else big blocks reuse them
      malloc_trim(0);
    state.ResumeTiming();
    const long before = minor_faults();
    run();
    faults += minor_faults() - before;
  }
  check();
  state.counters["faults"] = double(faults) / double(state.iterations());
}

// Heap behaviour (heap_modes.h); the cold runs also trim before each call.
void set_heap_mode(bool cold)
{
  cold_heap = cold;
  set_heap_mode(cold ? Heap_mode::cold : Heap_mode::warm);
}

// Iterations per repetition: about `per_million` on 1M faces, more on small
// grids, half as many with a cold heap (page faults make each 5-10x slower).
benchmark::IterationCount iterations(double per_million)
{
  const double faces = double(grid) * double(grid);
  const double n = per_million * 1e6 / faces / (cold_heap ? 2 : 1);
  return benchmark::IterationCount((std::max)(1.0, std::round(n)));
}

void add(const std::string& name, benchmark::IterationCount n, std::function<void(benchmark::State&)> f)
{
  benchmark::RegisterBenchmark(name.c_str(), [f](benchmark::State& st) { f(st); })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(n);
}

// ---------------------------------------------------------------------------

// The soups of separate triangles with coincident points, merged as one mesh.
void register_coincident_merge()
{
  const std::size_t n = 20 * grid;
  const std::string fan = "merge/fan_of_separate_triangles/" + std::to_string(n) + "/one_mesh";
  add(fan + "/CGAL_ext_merge_borders", iterations(10), [n](benchmark::State& st) {
    const Coincident& c = coincident(true);
    Mesh m;
    CGAL_ext::Merge_result r;
    timed(
      st, [&] { m = c.mesh; }, [&] { r = CGAL_ext::merge_borders(m); },
      [&] {
        require_counts(m, c.disc, "merge_borders (fan)");
        require(r.glued_edges == n, "merge_borders (fan) glued " + std::to_string(r.glued_edges) + " edges");
      });
  });
  add(fan + "/CGAL_stitch_borders", iterations(10), [n](benchmark::State& st) {
    const Coincident& c = coincident(true);
    SM sm;
    std::size_t stitched = 0;
    timed(
      st, [&] { sm = c.sm; }, [&] { stitched = PMP::stitch_borders(sm); },
      [&] {
        require_counts(sm, c.disc, "stitch_borders (fan)");
        require(stitched == n, "stitch_borders (fan) stitched " + std::to_string(stitched) + " edge pairs");
      });
  });
  // Refused: each edge could be glued to n - 1 others. No peer: CGAL's
  // stitch glues what it can of a non-manifold soup, another task.
  add("merge/copies_of_a_triangle/" + std::to_string(n) + "/one_mesh/CGAL_ext_merge_borders", iterations(10),
      [](benchmark::State& st) {
        const Coincident& c = coincident(false);
        Mesh m;
        bool refused = false;
        timed(
          st, [&] { m = c.mesh; },
          [&] {
            try {
              CGAL_ext::merge_borders(m);
              refused = false;
            } catch (const CGAL_ext::Merge_error&) {
              refused = true;
            }
          },
          [&] {
            require(refused, "merge_borders (copies of a triangle) was not refused");
            require_counts(m, counts(c.mesh), "merge_borders (copies of a triangle), refused");
          });
      });
}

void register_merge()
{
  const std::string n = std::to_string(grid);
  const std::string base = "merge/torus_halves/" + n + "x" + n;
  const auto tol0 = CGAL_ext::parameters::tolerance(0.0);

  auto check_merge = [](const Mesh& m, const CGAL_ext::Merge_result& r, const char* what) {
    require_counts(m, halves().closed, what);
    require(r.glued_edges == 2 * grid && r.mobius_edges == 0,
            std::string(what) + ": glued " + std::to_string(r.glued_edges) + " edges (" +
              std::to_string(r.mobius_edges) + " Möbius), expected " + std::to_string(2 * grid) + " (0)");
  };
  auto stitch = [](benchmark::State& st) {
    const Halves& h = halves();
    SM sm;
    std::size_t stitched = 0;
    timed(
      st, [&] { sm = h.sm_both; }, [&] { stitched = PMP::stitch_borders(sm); },
      [&] {
        require_counts(sm, h.closed, "stitch_borders");
        require(stitched == 2 * grid, "stitch_borders stitched " + std::to_string(stitched) + " edge pairs");
      });
  };

  // Two meshes: ours takes them as they are; CGAL's stitch takes one mesh, so
  // it gets the disjoint union, built beforehand (CGAL_stitch_borders) or in
  // the timing by copying the second tube into the first, as a user of CGAL
  // merging two meshes would (CGAL_copy_face_graph_and_stitch_borders).
  add(base + "/two_meshes/CGAL_ext_merge_borders", iterations(4), [=](benchmark::State& st) {
    const Halves& h = halves();
    Mesh m;
    CGAL_ext::Merge_result r;
    timed(
      st, [&] { m = h.a; }, [&] { r = CGAL_ext::merge_borders(m, h.b, tol0); },
      [&] { check_merge(m, r, "merge_borders (two meshes)"); });
  });
  add(base + "/two_meshes/CGAL_stitch_borders", iterations(10), stitch);
  add(base + "/two_meshes/CGAL_copy_face_graph_and_stitch_borders", iterations(4), [](benchmark::State& st) {
    const Halves& h = halves();
    SM sm;
    std::size_t stitched = 0;
    timed(
      st, [&] { sm = h.sm_a; },
      [&] {
        CGAL::copy_face_graph(h.sm_b, sm);
        stitched = PMP::stitch_borders(sm);
      },
      [&] {
        require_counts(sm, h.closed, "copy_face_graph + stitch_borders");
        require(stitched == 2 * grid, "stitch_borders stitched " + std::to_string(stitched) + " edge pairs");
      });
  });

  // One mesh holding both tubes on either side: like for like.
  add(base + "/one_mesh/CGAL_ext_merge_borders", iterations(4), [=](benchmark::State& st) {
    const Halves& h = halves();
    Mesh m;
    CGAL_ext::Merge_result r;
    timed(
      st, [&] { m = h.both; }, [&] { r = CGAL_ext::merge_borders(m, tol0); },
      [&] { check_merge(m, r, "merge_borders (one mesh)"); });
  });
  add(base + "/one_mesh/CGAL_stitch_borders", iterations(10), stitch);
  register_coincident_merge();
}

void register_conversion()
{
  for (Shape shape : {Shape::torus, Shape::mobius}) {
    const std::string name = shape_name(shape);
    const bool mobius = shape == Shape::mobius;

    // Mobius_mesh -> Surface_mesh.
    const std::string to = "convert/to_surface_mesh/" + name;
    add(to + "/CGAL_ext_to_surface_mesh", iterations(4), [=](benchmark::State& st) {
      const Source& s = source(shape);
      SM out;
      timed(
        st, [&] { out = SM(); }, [&] { CGAL_ext::to_surface_mesh(s.mesh, out); },
        [&] { require_counts(out, counts(s.sm), "to_surface_mesh"); });
    });
    // The same copy between two Surface_meshes (for the strip: of the cut
    // strip, the same output without the orienting and cutting).
    auto copy_face_graph = [=](benchmark::State& st) {
      const Source& s = source(shape);
      SM out;
      timed(
        st, [&] { out = SM(); }, [&] { CGAL::copy_face_graph(s.sm, out); },
        [&] { require_counts(out, counts(s.sm), "copy_face_graph"); });
    };
    add(to + "/CGAL_copy_face_graph", iterations(4), copy_face_graph);
    if (mobius) {
      // CGAL's closest equivalent from a non-orientable surface: orient the
      // soup (cutting it along a seam of duplicated vertices), then build.
      add(to + "/CGAL_orient_polygon_soup", iterations(1), [=](benchmark::State& st) {
        const Source& s = source(shape);
        std::vector<Point> points;
        std::vector<Polygon> polygons;
        SM out;
        timed(
          st,
          [&] {
            out = SM();
            points = s.points;
            polygons = s.polygons;
          },
          [&] {
            PMP::orient_polygon_soup(points, polygons);
            PMP::polygon_soup_to_polygon_mesh(points, polygons, out);
          },
          [&] {
            require(out.number_of_faces() == s.mesh.number_of_faces() &&
                      out.number_of_vertices() > s.mesh.number_of_vertices(),
                    "orient_polygon_soup: got " + counts(out).str());
          });
      });
    }

    // Surface_mesh -> Mobius_mesh (for the strip: the cut is glued again).
    const std::string from = "convert/from_surface_mesh/" + name;
    add(from + "/CGAL_ext_from_surface_mesh", iterations(4), [=](benchmark::State& st) {
      const Source& s = source(shape);
      Mesh out;
      timed(
        st, [&] { out = Mesh(); }, [&] { CGAL_ext::from_surface_mesh(s.sm, out); },
        [&] {
          require_counts(out, counts(s.mesh), "from_surface_mesh");
          require(CGAL_ext::number_of_mobius_edges(out) == CGAL_ext::number_of_mobius_edges(s.mesh),
                  "from_surface_mesh: the Möbius edges differ from the original's");
        });
    });
    add(from + "/CGAL_copy_face_graph", iterations(4), copy_face_graph);
  }
}

} // namespace

int main(int argc, char** argv)
{
  // Take out our own options before Google Benchmark reads the rest.
  bool cold = false;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--grid=", 7) == 0)
      grid = std::size_t((std::max)(4L, std::strtol(argv[i] + 7, nullptr, 10)));
    else if (std::strcmp(argv[i], "--heap=cold") == 0)
      cold = true;
    else if (std::strcmp(argv[i], "--heap=warm") == 0)
      cold = false;
    else
      argv[kept++] = argv[i];
  }
  argc = kept;
  set_heap_mode(cold);
  register_merge();
  register_conversion();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::AddCustomContext("heap", cold ? "cold" : "warm");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
