// Isotropic remeshing, against CGAL's PMP::isotropic_remeshing on the same
// input: an n x n torus of triangles (each quad split along one diagonal),
// remeshed to its own mean edge length, 3 iterations. Counters: the peak of
// the heap during one run (bytes), the symmetric Hausdorff distance of the
// result to the input (PMP::approximate_symmetric_Hausdorff_distance, the
// same sampling for both), and the share of edges in [4/5 L, 4/3 L].

#include "heap_accounting.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/isotropic_remeshing.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include "bench_shapes.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

namespace {

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using SM = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

constexpr unsigned iterations = 3;

SM torus(std::size_t n)
{
  const auto soup = bench_shapes::torus_triangle_soup<Point>(n);
  SM sm;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, sm);
  return sm;
}

double mean_edge_length(const SM& sm)
{
  double sum = 0;
  for (SM::Edge_index e : sm.edges())
    sum += std::sqrt(CGAL::squared_distance(sm.point(sm.vertex(e, 0)), sm.point(sm.vertex(e, 1))));
  return sum / double(sm.number_of_edges());
}

double share_in_band(const SM& sm, double L)
{
  std::size_t inside = 0;
  for (SM::Edge_index e : sm.edges()) {
    const double l2 = CGAL::squared_distance(sm.point(sm.vertex(e, 0)), sm.point(sm.vertex(e, 1)));
    inside += l2 >= 0.64 * L * L && l2 <= 16.0 / 9.0 * L * L;
  }
  return double(inside) / double(sm.number_of_edges());
}

void remesh(Mesh& m, double L) { CGAL_ext::isotropic_remeshing(m, L, CGAL_ext::parameters::number_of_iterations(iterations)); }
void remesh(SM& m, double L)
{
  PMP::isotropic_remeshing(faces(m), L, m, CGAL::parameters::number_of_iterations(iterations));
  m.collect_garbage();
}

SM as_surface_mesh(const Mesh& m)
{
  SM sm;
  CGAL_ext::to_surface_mesh(m, sm);
  return sm;
}
const SM& as_surface_mesh(const SM& m) { return m; }

// One implementation: timed runs on fresh copies, then one counted run and one measured.
template <class M>
void remeshing(benchmark::State& state)
{
  const SM input = torus(std::size_t(state.range(0)));
  const double L = mean_edge_length(input);
  M prepared;
  if constexpr (std::is_same_v<M, Mesh>)
    CGAL_ext::from_surface_mesh(input, prepared);
  else
    prepared = input;
  for (auto _ : state) {
    state.PauseTiming();
    M m = prepared;
    state.ResumeTiming();
    remesh(m, L);
    benchmark::DoNotOptimize(m.number_of_faces());
  }
  // The peak counts the copy of the input too, the same for both: the
  // blocks counted are freed while counting, as heap_accounting.h asks.
  heap::live = heap::peak = 0;
  heap::counting = true;
  {
    M m = prepared;
    remesh(m, L);
  }
  heap::counting = false;
  state.counters["peak_heap_bytes"] = double(heap::peak);
  M m = prepared;
  remesh(m, L);
  const SM out = as_surface_mesh(m);
  state.counters["hausdorff"] = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(out, input);
  state.counters["in_band"] = share_in_band(out, L);
  state.counters["faces"] = double(out.number_of_faces());
}

} // namespace

int main(int argc, char** argv)
{
  // Names are group/case/implementation, as scripts/bench.sh pairs them.
  benchmark::RegisterBenchmark("remeshing/torus_250x250/CGAL_ext", remeshing<Mesh>)->Arg(250)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("remeshing/torus_250x250/CGAL_PMP", remeshing<SM>)->Arg(250)->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
