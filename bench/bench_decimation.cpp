// Garland–Heckbert decimation, against CGAL's edge_collapse with
// GarlandHeckbert_plane_policies (on Surface_mesh) and OpenMesh's Decimater
// with ModQuadricT (on a TriMesh), on the same input: an n x n torus of
// triangles (each quad split along one diagonal; 708 x 708 gives 1 002 528
// triangles), decimated to 10 % and to 1 % of its faces.
//
// Ours runs twice: as decimate() does by default, the collapses and then the
// relocation of the vertices toward the input, and the collapses alone; and
// twice more with the torus's texture coordinates as a corner channel (grid
// node (i, j) at (i/n, j/n), cut where the grid wraps), its values weighed by
// attribute quadrics (corner_value_weight 1, the default) or not (0). The
// peers carry no texture coordinates.
//
// Timed: the decimation alone, one call per iteration; the copy of the input
// into each library's mesh is made with the timers paused. OpenMesh also runs
// with ModNormalFlippingT (90°, the normal test ours and CGAL's edge_collapse
// make), and its garbage collection is timed, as ours and CGAL's are.
//
// Counters, from one extra run after the timed loop: peak_heap_bytes, the
// highest heap during that run, the copy of the input into the mesh included
// (bench/heap_accounting.h); faces, of the result; hausdorff, the symmetric
// Hausdorff distance of the result to the input, both as Surface_mesh copies
// (PMP::approximate_symmetric_Hausdorff_distance, random uniform sampling of
// a fixed number of points with a fixed seed, and the vertices, the same for
// all three); torus_mean, torus_p999 and torus_max, the distribution of the
// distance from points of the result to the torus in closed form;
// uv_to_surface (with the channel), the largest distance from a vertex to
// the torus's closed form at the texture coordinates of one of its corners.

#include "heap_accounting.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/decimation.h>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#if CGAL_EXT_HAVE_OPENMESH
// OpenMesh's VectorT leaves its coordinates uninitialised, which its property
// arrays then copy (PropertyT::push_back).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#pragma GCC diagnostic pop
#endif

#include "bench_shapes.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace {

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using SM = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SMS = CGAL::Surface_mesh_simplification;

constexpr std::size_t grid = 708;
// Points sampled on each mesh for the Hausdorff distance, in both directions.
constexpr std::size_t hausdorff_samples = 400000;

using Soup = bench_shapes::Triangle_soup<Point>;

// The input, built once for all benchmarks, before any timing or counting.
const Soup& input_soup()
{
  static const Soup soup = bench_shapes::torus_triangle_soup<Point>(grid);
  return soup;
}
const SM& input_surface_mesh()
{
  static const SM sm = [] {
    SM m;
    PMP::polygon_soup_to_polygon_mesh(input_soup().points, input_soup().triangles, m);
    return m;
  }();
  return sm;
}

// Each implementation: its mesh type, how it is built from the input
// Surface_mesh, how it decimates, and how its result becomes a Surface_mesh.
template <bool relocate>
struct Ours_with
{
  using M = Mesh;
  static void load(M& m) { CGAL_ext::from_surface_mesh(input_surface_mesh(), m); }
  static void decimate(M& m, std::size_t target)
  {
    CGAL_ext::decimate(m, CGAL_ext::parameters::number_of_faces(target).relocate_vertices(relocate));
  }
  static std::size_t faces(const M& m) { return m.number_of_faces(); }
  static SM to_sm(const M& m)
  {
    SM sm;
    CGAL_ext::to_surface_mesh(m, sm);
    return sm;
  }
};

using Ours = Ours_with<true>;
using Ours_unrelocated = Ours_with<false>; // the collapses alone

// The torus's texture coordinates: grid node (i, j) holds (i/n, j/n), so the
// channel is cut along the two circles where the grid wraps.
using Uv = std::array<double, 2>;
void add_torus_uv(Mesh& m)
{
  auto uv = m.add_corner_channel<Uv>("c:uv").first;
  for (std::size_t i = 0; i <= grid; ++i)
    for (std::size_t j = 0; j <= grid; ++j)
      uv.add_value({double(i) / grid, double(j) / grid});
  const auto node = [](std::size_t i, std::size_t j) { return std::uint32_t(i * (grid + 1) + j); };
  for (CGAL_ext::Face_index f : m.faces()) {
    // Face p is triangle p of torus_triangle_soup(): its cell and half.
    const std::size_t p = f.idx(), i = p / 2 / grid, j = p / 2 % grid;
    const std::array<std::uint32_t, 3> nodes =
      p % 2 == 0 ? std::array<std::uint32_t, 3>{node(i, j), node(i + 1, j), node(i + 1, j + 1)}
                 : std::array<std::uint32_t, 3>{node(i, j), node(i + 1, j + 1), node(i, j + 1)};
    const auto& corners = input_soup().triangles[p];
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      for (std::size_t k = 0; k < 3; ++k)
        if (corners[k] == m.target(d).idx())
          uv.set_index(m.corner(d), nodes[k]);
  }
}

// Ours with the texture coordinates as a corner channel, the values weighed
// by `weight` (corner_value_weight), the relocation on.
template <int weight>
struct Ours_uv
{
  using M = Mesh;
  static void load(M& m)
  {
    CGAL_ext::from_surface_mesh(input_surface_mesh(), m);
    add_torus_uv(m);
  }
  static void decimate(M& m, std::size_t target)
  {
    CGAL_ext::decimate(m, CGAL_ext::parameters::number_of_faces(target).corner_value_weight(double(weight)));
  }
  static std::size_t faces(const M& m) { return m.number_of_faces(); }
  static SM to_sm(const M& m) { return Ours::to_sm(m); }
};

// The largest distance from a vertex of `m` to the torus's closed form at
// the texture coordinates of one of its corners: how far the values have
// strayed from their points.
double uv_to_surface(const Mesh& m)
{
  const auto uv = m.corner_channel<Uv>("c:uv");
  if (!uv)
    return 0;
  const double pi = std::acos(-1.0);
  double largest = 0;
  for (CGAL_ext::Face_index f : m.faces())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const Uv& t = (*uv)[m.corner(d)];
      const Point on_torus = bench_shapes::torus_point<Point>(2 * pi * t[0], 2 * pi * t[1]);
      largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(m.point(m.target(d)), on_torus)));
    }
  return largest;
}
template <class Other>
double uv_to_surface(const Other&) // the peers carry no texture coordinates
{
  return 0;
}

struct Cgal
{
  using M = SM;
  static void load(M& m) { m = input_surface_mesh(); }
  static void decimate(M& m, std::size_t target)
  {
    SMS::GarlandHeckbert_plane_policies<SM, K> policies(m);
    auto stop = [&m, target](const auto&, const auto&, std::size_t, std::size_t) {
      return m.number_of_faces() <= target;
    };
    SMS::edge_collapse(m, stop, CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
    m.collect_garbage();
  }
  static std::size_t faces(const M& m) { return m.number_of_faces(); }
  static SM to_sm(const M& m) { return m; }
};

#if CGAL_EXT_HAVE_OPENMESH
// Double coordinates, as the others (OpenMesh's default is float).
struct Om_traits : OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Om_mesh = OpenMesh::TriMesh_ArrayKernelT<Om_traits>;

template <bool normal_flipping>
struct Open_mesh
{
  using M = Om_mesh;
  static void load(M& m)
  {
    const SM& sm = input_surface_mesh();
    std::vector<M::VertexHandle> handle;
    handle.reserve(sm.number_of_vertices());
    for (SM::Vertex_index v : sm.vertices()) {
      const Point& p = sm.point(v);
      handle.push_back(m.add_vertex(M::Point(p.x(), p.y(), p.z())));
    }
    for (SM::Face_index f : sm.faces()) {
      std::array<M::VertexHandle, 3> corners;
      int i = 0;
      for (SM::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm))
        corners[i++] = handle[v.idx()];
      m.add_face(corners[0], corners[1], corners[2]);
    }
  }
  static void decimate(M& m, std::size_t target)
  {
    OpenMesh::Decimater::DecimaterT<M> decimater(m);
    OpenMesh::Decimater::ModQuadricT<M>::Handle quadric;
    decimater.add(quadric);
    decimater.module(quadric).unset_max_err();
    OpenMesh::Decimater::ModNormalFlippingT<M>::Handle flipping;
    if (normal_flipping) {
      // The module reads face normals; it would otherwise compute them itself and say so on stderr.
      m.request_face_normals();
      m.update_face_normals();
      decimater.add(flipping);
      decimater.module(flipping).set_max_normal_deviation(90.0);
    }
    decimater.initialize();
    decimater.decimate_to_faces(0, target);
    m.garbage_collection();
  }
  static std::size_t faces(const M& m) { return m.n_faces(); }
  static SM to_sm(const M& m)
  {
    std::vector<Point> points;
    std::vector<std::array<std::size_t, 3>> triangles;
    for (auto v : m.vertices()) {
      const auto& p = m.point(v);
      points.emplace_back(p[0], p[1], p[2]);
    }
    for (auto f : m.faces()) {
      std::array<std::size_t, 3> t;
      int i = 0;
      for (auto v : m.fv_range(f))
        t[i++] = std::size_t(v.idx());
      triangles.push_back(t);
    }
    SM sm;
    PMP::polygon_soup_to_polygon_mesh(points, triangles, sm);
    return sm;
  }
};
#endif

double hausdorff_to_input(const SM& out)
{
  // Edges are not sampled: CGAL 5.5 samples them from its default random
  // generator, not from the seed, and the distances then differ run to run.
  const auto sampling = CGAL::parameters::use_random_uniform_sampling(true)
                          .number_of_points_on_faces(hausdorff_samples)
                          .random_seed(1)
                          .do_sample_edges(false);
  return PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(out, input_surface_mesh(), sampling,
                                                                            sampling);
}

// The distance of points of the result to the torus the input samples
// (radii 2 and 1, closed form), at the 66 points of a barycentric grid of
// step 1/10 on each triangle: an independent measure of the whole
// distribution of the error, where the Hausdorff distance is its largest
// value alone. Returns the mean, the 99.9th percentile and the largest.
struct Torus_error
{
  double mean = 0, p999 = 0, largest = 0;
};
Torus_error distance_to_the_torus(const SM& m)
{
  const auto distance = [](double x, double y, double z) {
    const double rho = std::sqrt(x * x + y * y) - 2;
    return std::abs(std::sqrt(rho * rho + z * z) - 1);
  };
  std::vector<double> d;
  d.reserve(m.number_of_faces() * 66);
  for (auto f : m.faces()) {
    std::array<Point, 3> t;
    int i = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      t[i++] = m.point(v);
    for (int a = 0; a <= 10; ++a)
      for (int b = 0; a + b <= 10; ++b) {
        const double wa = a / 10.0, wb = b / 10.0, wc = 1 - wa - wb;
        d.push_back(distance(wa * t[0].x() + wb * t[1].x() + wc * t[2].x(),
                             wa * t[0].y() + wb * t[1].y() + wc * t[2].y(),
                             wa * t[0].z() + wb * t[1].z() + wc * t[2].z()));
      }
  }
  Torus_error e;
  for (double x : d)
    e.mean += x;
  e.mean /= double(d.size());
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() * 999 / 1000), d.end());
  e.p999 = d[d.size() * 999 / 1000];
  e.largest = *std::max_element(d.begin(), d.end());
  return e;
}

// Timed runs on fresh copies, then one counted run whose result is measured.
// The target is given in per mille of the input's faces.
template <class Impl>
void decimation(benchmark::State& state, std::size_t per_mille)
{
  const std::size_t target = input_soup().triangles.size() * per_mille / 1000;
  for (auto _ : state) {
    state.PauseTiming();
    typename Impl::M m;
    Impl::load(m);
    state.ResumeTiming();
    Impl::decimate(m, target);
    benchmark::DoNotOptimize(Impl::faces(m));
    state.PauseTiming(); // the destruction of the result is not timed
    m = typename Impl::M();
    state.ResumeTiming();
  }
  // Counted from an empty mesh: every block counted is the run's own. The
  // result is kept after counting stops, which heap_accounting.h allows.
  typename Impl::M m;
  heap::live = heap::peak = 0;
  heap::counting = true;
  Impl::load(m);
  Impl::decimate(m, target);
  heap::counting = false;
  state.counters["peak_heap_bytes"] = double(heap::peak);
  state.counters["faces"] = double(Impl::faces(m));
  if (const double uv = uv_to_surface(m); uv > 0)
    state.counters["uv_to_surface"] = uv;
  // Computed once per implementation and target, not once per repetition.
  static std::map<std::size_t, std::pair<double, Torus_error>> errors;
  auto known = errors.find(target);
  if (known == errors.end()) {
    const SM result = Impl::to_sm(m);
    known = errors.emplace(target, std::make_pair(hausdorff_to_input(result), distance_to_the_torus(result))).first;
  }
  state.counters["hausdorff"] = known->second.first;
  state.counters["torus_mean"] = known->second.second.mean;
  state.counters["torus_p999"] = known->second.second.p999;
  state.counters["torus_max"] = known->second.second.largest;
}

template <class Impl>
void add(const std::string& name, int per_mille)
{
  benchmark::RegisterBenchmark(name.c_str(), decimation<Impl>, std::size_t(per_mille))
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
}

} // namespace

int main(int argc, char** argv)
{
  input_surface_mesh(); // built before anything is timed or counted
  // Names are group/case/implementation, as scripts/bench.sh pairs them.
  for (int per_mille : {100, 10}) {
    const std::string c = "decimation/torus_" + std::to_string(grid) + "x" + std::to_string(grid) + "x2_to_" +
                          (per_mille == 100 ? "10" : "1") + "_percent/";
    add<Ours>(c + "CGAL_ext", per_mille);
    add<Ours_unrelocated>(c + "CGAL_ext_no_relocation", per_mille);
    add<Ours_uv<1>>(c + "CGAL_ext_uv_channel", per_mille);
    add<Ours_uv<0>>(c + "CGAL_ext_uv_channel_weight_0", per_mille);
    add<Cgal>(c + "CGAL_edge_collapse_GH", per_mille);
#if CGAL_EXT_HAVE_OPENMESH
    add<Open_mesh<false>>(c + "OpenMesh_Decimater_quadric", per_mille);
    add<Open_mesh<true>>(c + "OpenMesh_Decimater_quadric_normal_flipping", per_mille);
#endif
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
