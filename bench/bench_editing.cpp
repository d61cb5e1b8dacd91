// Editing, against CGAL::Euler on Surface_mesh: random rounds of Euler
// operations on a triangulated torus (the same kind of round in both), and
// garbage collection after many removals.
//
// A round splits a random edge, splits its two quads back into triangles,
// flips one of the new edges (and back) and collapses the new vertex into an
// end of the split edge: six Euler operations (and their checks) that leave
// the mesh as large as it was. Ours run twice: with the operations' own
// checks (each throws rather than break the mesh), and with
// `Euler::unchecked`, as CGAL::Euler's operations run (the round still asks
// can_flip_edge() and the link condition once). Both meshes reuse the slots
// of removed elements (Surface_mesh by default, Mobius_mesh with
// set_recycle_garbage(true)); one more row runs Mobius_mesh's default,
// appending, which collects the garbage every 2^16 rounds inside the timing.

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include "bench_shapes.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using SM = CGAL::Surface_mesh<Point>;

using Soup = bench_shapes::Triangle_soup<Point>;

Soup torus(std::size_t n) { return bench_shapes::torus_triangle_soup<Point>(n); }

Mesh ours(const Soup& s)
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.triangles, m);
  return m;
}

SM theirs(const Soup& s)
{
  SM sm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.triangles, sm);
  return sm;
}

// One round on Mobius_mesh; returns the number of operations done. Given
// `Euler::unchecked`, the operations skip their checks (the round asks
// can_flip_edge() and the link condition once, as a caller would); without
// it, each operation checks again and would throw rather than break the mesh.
// Rounds are kept out of line so that a profile (callgrind) counts them.
template <class... Unchecked>
[[gnu::noinline]] int round(Mesh& m, std::mt19937& rng, Unchecked... unchecked)
{
  namespace E = CGAL_ext::Euler;
  CGAL_ext::Halfedge_index h;
  do
    h = CGAL_ext::Halfedge_index(std::uint32_t(rng() % m.num_halfedges()));
  while (m.is_removed(h));
  const CGAL_ext::Dart d(h, false);
  const CGAL_ext::Dart n = E::split_edge(d, m); // a -> w, then d: w -> b
  const CGAL_ext::Dart x = E::split_face(n, m.next(m.next(n)), m, unchecked...);
  const CGAL_ext::Dart od = m.opposite(d);
  E::split_face(od, m.next(m.next(od)), m, unchecked...);
  int ops = 3;
  if (E::can_flip_edge(x, m)) {
    E::flip_edge(E::flip_edge(x, m, unchecked...), m, unchecked...); // the same edge, back again
    ops += 2;
  }
  const CGAL_ext::Dart back = m.opposite(n); // w -> a
  if (E::does_satisfy_link_condition(back, m)) {
    E::collapse_edge(back, m, unchecked...);
    ++ops;
  }
  return ops;
}

[[gnu::noinline]] int round(SM& sm, std::mt19937& rng)
{
  namespace E = CGAL::Euler;
  SM::Halfedge_index h;
  do
    h = SM::Halfedge_index(SM::size_type(rng() % sm.num_halfedges()));
  while (sm.is_removed(h));
  const auto n = E::split_edge(h, sm);
  const auto x = E::split_face(n, sm.next(sm.next(n)), sm);
  const auto oh = sm.opposite(h);
  E::split_face(oh, sm.next(sm.next(oh)), sm);
  int ops = 3;
  // Surface_mesh has no can_flip_edge: the quad of x is convex here, and
  // the far corners are not adjacent on a torus of this size.
  E::flip_edge(x, sm); // CGAL flips in place: the same halfedge, back again
  E::flip_edge(x, sm);
  ops += 2;
  const auto back = sm.edge(sm.opposite(n));
  if (E::does_satisfy_link_condition(back, sm)) {
    // CGAL keeps the target of halfedge(e): make it the old vertex.
    E::collapse_edge(back, sm);
    ++ops;
  }
  return ops;
}

// Rounds on `mesh`; `collect`: collect the garbage every 2^16 rounds (a mesh
// that appends would otherwise grow without end).
template <class M, class Round>
void random_rounds(benchmark::State& state, M mesh, Round round, bool collect)
{
  std::mt19937 rng(1);
  std::int64_t ops = 0, rounds = 0;
  // Room for the rounds between two collections (a round adds a vertex,
  // three edges and two faces; a recycling mesh grows in its first round
  // only), so that the first round does not pay the arrays' first growth, a
  // copy of the whole mesh: that would weigh on short runs only (as under
  // callgrind).
  mesh.reserve(mesh.number_of_vertices() + (1 << 16), mesh.number_of_edges() + 3 * (1 << 16),
               mesh.number_of_faces() + 2 * (1 << 16));
  for (auto _ : state) {
    ops += round(mesh, rng);
    if ((++rounds & 0xffff) == 0 && collect)
      mesh.collect_garbage();
  }
  state.SetItemsProcessed(ops);
  state.counters["ops_per_round"] = double(ops) / double(rounds);
}

Mesh recycling(Mesh m)
{
  m.set_recycle_garbage(true);
  return m;
}

void Euler_random_rounds_CGAL_ext(benchmark::State& state)
{
  random_rounds(
    state, recycling(ours(torus(std::size_t(state.range(0))))),
    [](Mesh& m, std::mt19937& r) { return round(m, r); }, false);
}
void Euler_random_rounds_CGAL_ext_unchecked(benchmark::State& state)
{
  random_rounds(
    state, recycling(ours(torus(std::size_t(state.range(0))))),
    [](Mesh& m, std::mt19937& r) { return round(m, r, CGAL_ext::Euler::unchecked); }, false);
}
void Euler_random_rounds_CGAL_ext_appending(benchmark::State& state)
{
  random_rounds(
    state, ours(torus(std::size_t(state.range(0)))),
    [](Mesh& m, std::mt19937& r) { return round(m, r, CGAL_ext::Euler::unchecked); }, true);
}
void Euler_random_rounds_CGAL(benchmark::State& state)
{
  random_rounds(state, theirs(torus(std::size_t(state.range(0)))), [](SM& m, std::mt19937& r) { return round(m, r); },
                false);
}

// Removes about a tenth of the elements by collapses, then times the compaction.
template <class M, class Collapse, class Collect>
void garbage(benchmark::State& state, M prepared, Collapse collapse, Collect collect)
{
  std::mt19937 rng(2);
  const std::size_t target = prepared.number_of_faces() / 20; // two faces per collapse
  for (std::size_t k = 0; k < target;)
    k += collapse(prepared, rng) ? 1 : 0;
  for (auto _ : state) {
    state.PauseTiming();
    M m = prepared;
    state.ResumeTiming();
    collect(m);
    benchmark::DoNotOptimize(m.number_of_faces());
  }
}

void Collect_garbage_CGAL_ext(benchmark::State& state)
{
  garbage(
    state, ours(torus(std::size_t(state.range(0)))),
    [](Mesh& m, std::mt19937& rng) {
      const CGAL_ext::Halfedge_index h(std::uint32_t(rng() % m.num_halfedges()));
      if (m.is_removed(h) || !CGAL_ext::Euler::does_satisfy_link_condition(CGAL_ext::Dart(h), m))
        return false;
      CGAL_ext::Euler::collapse_edge(CGAL_ext::Dart(h), m);
      return true;
    },
    [](Mesh& m) { m.collect_garbage(); });
}
void Collect_garbage_CGAL(benchmark::State& state)
{
  SM sm = theirs(torus(std::size_t(state.range(0))));
  sm.set_recycle_garbage(false);
  garbage(
    state, sm,
    [](SM& m, std::mt19937& rng) {
      const SM::Halfedge_index h(SM::size_type(rng() % m.num_halfedges()));
      if (m.is_removed(h) || !CGAL::Euler::does_satisfy_link_condition(m.edge(h), m))
        return false;
      CGAL::Euler::collapse_edge(m.edge(h), m);
      return true;
    },
    [](SM& m) { m.collect_garbage(); });
}

} // namespace

int main(int argc, char** argv)
{
  // Names are group/case/implementation, as scripts/bench.sh pairs them.
  auto add = [](const char* name, void (*f)(benchmark::State&), std::int64_t n, benchmark::TimeUnit unit) {
    benchmark::RegisterBenchmark(name, f)->Arg(n)->Unit(unit);
  };
  add("euler/random_rounds/torus_256x256/CGAL_ext", Euler_random_rounds_CGAL_ext, 256, benchmark::kMicrosecond);
  add("euler/random_rounds_unchecked/torus_256x256/CGAL_ext", Euler_random_rounds_CGAL_ext_unchecked, 256,
      benchmark::kMicrosecond);
  add("euler/random_rounds_unchecked/torus_256x256/CGAL_Surface_mesh", Euler_random_rounds_CGAL, 256,
      benchmark::kMicrosecond);
  add("euler/random_rounds_appending/torus_256x256/CGAL_ext", Euler_random_rounds_CGAL_ext_appending, 256,
      benchmark::kMicrosecond);
  add("euler/random_rounds/torus_256x256/CGAL_Surface_mesh", Euler_random_rounds_CGAL, 256, benchmark::kMicrosecond);
  add("collect_garbage/torus_512x512_tenth_collapsed/CGAL_ext", Collect_garbage_CGAL_ext, 512,
      benchmark::kMillisecond);
  add("collect_garbage/torus_512x512_tenth_collapsed/CGAL_Surface_mesh", Collect_garbage_CGAL, 512,
      benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
