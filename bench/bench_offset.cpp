// Thickening a surface into one closed solid: CGAL_ext::offset_mesh (both
// sides, `solid(true)`) against CGAL::alpha_wrap_3 of the same surface given
// as a triangle soup, on a Möbius strip and on a band of the same size with
// two half-twists (orientable, two borders), from make_mobius_strip() with
// radius 1, width 0.5 and triangles.
//
// Distances: alpha = bbox diagonal / 100 and offset = alpha / 30 (CGAL's own
// default ratio) for the wrap; our offset distance d is that same offset, so
// both outputs lie about d from the input.
//
// Timed: the call alone, one per iteration, from the ready input (a mesh for
// us, the soup for alpha_wrap_3) to the ready output; destroying the output is
// not timed.
//
// Counters, from one extra run after the timed loop: peak_heap_bytes (the
// highest heap during the call, bench/heap_accounting.h); faces, closed
// (1 or 0) and euler (V - E + F) of the output; and, against the input S as
// a Surface_mesh (the strip cut open along its seam: the same triangles),
// with N random points (fixed seed) sampled on the output O, and its vertices:
//   out_to_in = max over the samples x of dist(x, S), the one-sided Hausdorff
//               distance O -> S; an exact offset has d;
//   in_to_out = the one-sided Hausdorff distance S -> O
//               (PMP::approximate_Hausdorff_distance, N samples on S); an
//               exact offset has d;
//   mean_dev  = mean over the samples of |dist(x, S) - d| / d: how far O is
//               from the exact offset surface at distance d (the rim quads
//               across the border, whose points are nearer, count too).

#include "heap_accounting.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/offset_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using SM = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<SM>>>;

// Points sampled on each surface for the distances.
constexpr std::size_t samples = 400000;

struct Case
{
  std::size_t n_around, n_across;
  int half_twists;
};

// One input, built once before anything of its case is timed or counted.
struct Input
{
  Mesh mesh;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  SM surface_mesh;
  std::unique_ptr<Tree> tree;
  double alpha = 0, offset = 0;
};

const Input& input(const Case& c)
{
  static std::map<std::array<std::size_t, 3>, std::unique_ptr<Input>> inputs;
  std::unique_ptr<Input>& in = inputs[{c.n_around, c.n_across, std::size_t(c.half_twists)}];
  if (in)
    return *in;
  in = std::make_unique<Input>();
  CGAL_ext::make_mobius_strip(in->mesh, c.n_around, c.n_across, c.half_twists, 1.0, 0.5, false);
  for (CGAL_ext::Vertex_index v : in->mesh.vertices())
    in->points.push_back(in->mesh.point(v));
  for (CGAL_ext::Face_index f : in->mesh.faces()) {
    std::array<std::size_t, 3> t;
    int i = 0;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, in->mesh))
      t[i++] = v.idx();
    in->triangles.push_back(t);
  }
  CGAL_ext::to_surface_mesh(in->mesh, in->surface_mesh);
  in->tree = std::make_unique<Tree>(faces(in->surface_mesh).first, faces(in->surface_mesh).second, in->surface_mesh);
  in->tree->accelerate_distance_queries();
  const CGAL::Bbox_3 box = CGAL::bbox_3(in->points.begin(), in->points.end());
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  in->alpha = diagonal / 100;
  in->offset = in->alpha / 30;
  return *in;
}

struct Ours
{
  using Output = Mesh;
  static void run(const Input& in, Output& out)
  {
    CGAL_ext::offset_mesh(in.mesh, in.offset, out, CGAL_ext::parameters::solid(true));
  }
  static SM to_sm(const Output& out)
  {
    SM sm;
    CGAL_ext::to_surface_mesh(out, sm);
    return sm;
  }
};

struct Alpha_wrap
{
  using Output = SM;
  static void run(const Input& in, Output& out) { CGAL::alpha_wrap_3(in.points, in.triangles, in.alpha, in.offset, out); }
  static SM to_sm(const Output& out) { return out; }
};

// The counters that compare an output with the input; see the file's head.
void measure(const Input& in, const SM& out, benchmark::State& state)
{
  // Edges are not sampled: CGAL 5.5 samples them from its default random
  // generator, not from the seed, and the distances then differ run to run.
  const auto sampling = CGAL::parameters::use_random_uniform_sampling(true)
                          .number_of_points_on_faces(samples)
                          .random_seed(1)
                          .do_sample_edges(false);
  std::vector<Point> on_output;
  PMP::sample_triangle_mesh(out, std::back_inserter(on_output), sampling);
  double farthest = 0, deviation = 0;
  for (const Point& x : on_output) {
    const double dist = std::sqrt(in.tree->squared_distance(x));
    farthest = (std::max)(farthest, dist);
    deviation += std::abs(dist - in.offset);
  }
  state.counters["d"] = in.offset;
  state.counters["out_to_in"] = farthest;
  state.counters["mean_dev"] = deviation / double(on_output.size()) / in.offset;
  state.counters["in_to_out"] = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
    in.surface_mesh, out, sampling, CGAL::parameters::default_values());
  state.counters["faces"] = double(out.number_of_faces());
  state.counters["closed"] = CGAL::is_closed(out) ? 1 : 0;
  state.counters["euler"] = double(out.number_of_vertices()) - double(out.number_of_edges()) + double(out.number_of_faces());
}

template <class Impl>
void offset(benchmark::State& state, Case c)
{
  const Input& in = input(c);
  for (auto _ : state) {
    typename Impl::Output out;
    Impl::run(in, out);
    benchmark::DoNotOptimize(out.number_of_faces());
    state.PauseTiming(); // the destruction of the output is not timed
    out = typename Impl::Output();
    state.ResumeTiming();
  }
  // Counted from an empty output; the input is only read. The output is kept
  // after counting stops, which heap_accounting.h allows.
  typename Impl::Output out;
  heap::live = heap::peak = 0;
  heap::counting = true;
  Impl::run(in, out);
  heap::counting = false;
  state.counters["peak_heap_bytes"] = double(heap::peak);
  // Measured once per case, not once per repetition.
  static std::map<std::array<std::size_t, 3>, benchmark::UserCounters> measured;
  const std::array<std::size_t, 3> key{c.n_around, c.n_across, std::size_t(c.half_twists)};
  auto known = measured.find(key);
  if (known == measured.end()) {
    measure(in, Impl::to_sm(out), state);
    known = measured.emplace(key, state.counters).first;
  }
  state.counters = known->second;
  state.counters["peak_heap_bytes"] = double(heap::peak);
}

void add(const Case& c, bool with_alpha_wrap)
{
  // Names are group/case/implementation, as scripts/bench.sh pairs them.
  const std::string name = std::string(c.half_twists % 2 ? "offset/mobius_" : "offset/two_twists_") +
                           std::to_string(c.n_around) + "x" + std::to_string(c.n_across) + "x2/";
  benchmark::RegisterBenchmark((name + "CGAL_ext").c_str(), offset<Ours>, c)->Iterations(1)->Unit(benchmark::kMillisecond);
  if (with_alpha_wrap)
    benchmark::RegisterBenchmark((name + "CGAL_alpha_wrap_3").c_str(), offset<Alpha_wrap>, c)
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

} // namespace

int main(int argc, char** argv)
{
  // 1 M triangles each, and a strip of 125 k. alpha_wrap_3 takes about a
  // minute of CPU per run on the 1 M strip, so it is not run on the band too:
  // at the same alpha and offset its work depends on the input's size and
  // extent, not on the number of twists.
  add({2000, 250, 1}, true);
  add({2000, 250, 2}, false);
  add({500, 125, 1}, true);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
