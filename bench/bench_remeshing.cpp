// Isotropic remeshing, against CGAL's PMP::isotropic_remeshing on the same
// input: an n x n torus of triangles (each quad split along one diagonal),
// remeshed to its own mean edge length, 3 iterations. Counters: the peak of
// the heap during one run (bytes), the symmetric Hausdorff distance of the
// result to the input (PMP::approximate_symmetric_Hausdorff_distance, the
// same sampling for both), and the share of edges in [4/5 L, 4/3 L].
//
// relax_constraints: an n x n planar patch whose grid steps alternate 0.7
// and 1.3 of h = 1/n (half the border edges below the band at L = h, none
// above 4/3 h, as CGAL's protect_constraints asks), remeshed
// to h with the border protected and relaxed along itself, 3 iterations;
// counters as above, and the border edges' share in the band and coefficient
// of variation.

#include "heap_accounting.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
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

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <type_traits>
#include <utility>
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

// The unit square in the plane z = 0, its grid steps alternately 0.7 h and 1.3 h.
SM uneven_patch(std::size_t n)
{
  std::vector<double> grid{0};
  for (std::size_t i = 0; i < n; ++i)
    grid.push_back(i + 1 == n ? 1.0 : grid.back() + (i % 2 == 0 ? 0.7 : 1.3) / double(n));
  std::vector<Point> points;
  for (double x : grid)
    for (double y : grid)
      points.emplace_back(x, y, 0);
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t a = i * (n + 1) + j, b = a + n + 1;
      triangles.push_back({a, b, b + 1});
      triangles.push_back({a, b + 1, a + 1});
    }
  SM sm;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, sm);
  return sm;
}

// Texture coordinates of the torus's own parameters (its two angles over
// 2 pi), cut where they wrap: the corners of a face that straddles a wrap
// take 1 more on the low side, and a corner's value is shared by the corners
// of its vertex with the same shifts, so the channel is continuous elsewhere.
void add_torus_uv(Mesh& m)
{
  const double pi = std::acos(-1.0);
  auto uv = m.add_corner_channel<CGAL_ext::Corner_uv<Point>>(CGAL_ext::corner_uv_name).first;
  std::map<std::tuple<std::uint32_t, bool, bool>, std::uint32_t> index_of;
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<std::pair<CGAL_ext::Dart, std::array<double, 2>>> corners;
    std::array<double, 2> low{1, 1}, high{0, 0};
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const Point& p = m.point(m.target(d));
      const double u = std::atan2(p.y(), p.x()) / (2 * pi), v = std::atan2(p.z(), std::hypot(p.x(), p.y()) - 2) / (2 * pi);
      corners.push_back({d, {u < 0 ? u + 1 : u, v < 0 ? v + 1 : v}});
      for (int k : {0, 1}) {
        low[k] = (std::min)(low[k], corners.back().second[k]);
        high[k] = (std::max)(high[k], corners.back().second[k]);
      }
    }
    for (auto& [d, t] : corners) {
      const bool shift_u = high[0] - low[0] > 0.5 && t[0] < 0.5, shift_v = high[1] - low[1] > 0.5 && t[1] < 0.5;
      const auto key = std::make_tuple(m.target(d).idx(), shift_u, shift_v);
      auto at = index_of.find(key);
      if (at == index_of.end())
        at = index_of.emplace(key, uv.add_value({t[0] + shift_u, t[1] + shift_v})).first;
      uv.set_index(m.corner(d), at->second);
    }
  }
}

void remesh(Mesh& m, double L, bool relaxed)
{
  CGAL_ext::isotropic_remeshing(
    m, L, CGAL_ext::parameters::number_of_iterations(iterations).protect_borders(relaxed).relax_constraints(relaxed));
}
void remesh(SM& m, double L, bool relaxed)
{
  PMP::isotropic_remeshing(
    faces(m), L, m,
    CGAL::parameters::number_of_iterations(iterations).protect_constraints(relaxed).relax_constraints(relaxed));
  m.collect_garbage();
}

// The border edges' share in [4/5 L, 4/3 L] and their coefficient of variation.
std::pair<double, double> border_evenness(const SM& sm, double L)
{
  std::size_t count = 0, inside = 0;
  double sum = 0, sum2 = 0;
  for (SM::Edge_index e : sm.edges()) {
    if (!sm.is_border(e))
      continue;
    const double l2 = CGAL::squared_distance(sm.point(sm.vertex(e, 0)), sm.point(sm.vertex(e, 1)));
    ++count;
    inside += l2 >= 0.64 * L * L && l2 <= 16.0 / 9.0 * L * L;
    sum += std::sqrt(l2);
    sum2 += l2;
  }
  const double mean = sum / double(count);
  return {double(inside) / double(count), std::sqrt(std::max(0.0, sum2 / double(count) - mean * mean)) / mean};
}

SM as_surface_mesh(const Mesh& m)
{
  SM sm;
  CGAL_ext::to_surface_mesh(m, sm);
  return sm;
}
const SM& as_surface_mesh(const SM& m) { return m; }

// One implementation: timed runs on fresh copies, then one counted run and one measured.
template <class M, bool relaxed = false, bool textured = false>
void remeshing(benchmark::State& state)
{
  const std::size_t n = std::size_t(state.range(0));
  const SM input = relaxed ? uneven_patch(n) : torus(n);
  const double L = relaxed ? 1.0 / double(n) : mean_edge_length(input);
  M prepared;
  if constexpr (std::is_same_v<M, Mesh>) {
    CGAL_ext::from_surface_mesh(input, prepared);
    if (textured)
      add_torus_uv(prepared);
  } else
    prepared = input;
  for (auto _ : state) {
    state.PauseTiming();
    M m = prepared;
    state.ResumeTiming();
    remesh(m, L, relaxed);
    benchmark::DoNotOptimize(m.number_of_faces());
  }
  // The peak counts the copy of the input too, the same for both: the
  // blocks counted are freed while counting, as heap_accounting.h asks.
  heap::live = heap::peak = 0;
  heap::counting = true;
  {
    M m = prepared;
    remesh(m, L, relaxed);
  }
  heap::counting = false;
  state.counters["peak_heap_bytes"] = double(heap::peak);
  M m = prepared;
  remesh(m, L, relaxed);
  const SM out = as_surface_mesh(m);
  if (relaxed) {
    const auto [border_in_band, border_cv] = border_evenness(out, L);
    state.counters["border_in_band"] = border_in_band;
    state.counters["border_cv"] = border_cv;
  }
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
  // Ours with a texture channel carried (PMP has none to carry): its cost.
  benchmark::RegisterBenchmark("remeshing/torus_250x250/CGAL_ext_with_uv", remeshing<Mesh, false, true>)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("remeshing/relaxed_border_patch_250x250/CGAL_ext", remeshing<Mesh, true>)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("remeshing/relaxed_border_patch_250x250/CGAL_PMP", remeshing<SM, true>)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
