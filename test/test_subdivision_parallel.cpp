// The parallel paths of subdivision: every stage bit for bit the serial one,
// on OpenSubdiv's shapes and on generated meshes large enough to be split
// among threads, the incidence tables, the thresholds and the tuner that
// decides when threads pay, and the carried property maps.
#include "same_mesh.h"
#include "subdivision_shapes.h"
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <gtest/gtest.h>

#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace subdivision_parallel_tests {

namespace {

using namespace subdivision_shapes;
using test::Connectivity;
using test::connectivity_of;
using test::same_bytes;
using test::same_connectivity;

#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
// ----------------------------------------------------------------- parallel stages

struct Refined
{
  Mesh mesh;
  std::vector<V3> points;
};

// `n` steps of `Mask` on `b` under `ConcurrencyTag`, by the two paths of the
// free functions: one pass, or refine(), interpolate() and build_mesh().
template <class Mask, class ConcurrencyTag>
Refined refine_with(const Built& b, const S::Refinement_options& options, unsigned n, bool one_pass)
{
  Refined r;
  std::vector<V3> base;
  for (const Point& p : b.mesh.points().data())
    base.push_back({p.x(), p.y(), p.z()});
  S::Refiner<Mask> refiner(Mask(), options);
  if (one_pass) {
    r.points = base;
    refiner.template refine_and_interpolate<ConcurrencyTag>(b.mesh, n, r.points, r.mesh, b.edge_sharpness,
                                                            b.vertex_sharpness, true);
  } else {
    refiner.template refine<ConcurrencyTag>(b.mesh, n, b.edge_sharpness, b.vertex_sharpness);
    refiner.template interpolate<ConcurrencyTag>(base, r.points);
    refiner.template build_mesh<ConcurrencyTag>(r.mesh, true);
  }
  return r;
}

// Serial and parallel refinement of `b` (the parallel path forced on every
// level) give the same mesh, array for array, the same points, sharpness
// and holes, bit for bit.
//
// Then again with threads from the last step only (the threshold at its
// parent's vertex count): the serial steps before it make the incidence
// tables that the parallel one reads.
template <class Mask>
void check_parallel_stages(const std::string& what, const Built& b, S::Refinement_options options, unsigned n)
{
  const std::uint32_t last_parent =
    std::uint32_t(S::refined_size(Mask::split, S::internal::size_of(b.mesh), n - 1).vertices);
  for (bool one_pass : {true, false}) {
    // The serial result does not depend on the threshold.
    const Refined s = refine_with<Mask, CGAL::Sequential_tag>(b, options, n, one_pass);
    for (std::uint32_t threshold : {std::uint32_t(0), last_parent}) {
      options.parallel_min_vertices = threshold;
      SCOPED_TRACE(what + (one_pass ? ", one pass" : ", level by level") + ", threads from " +
                   std::to_string(threshold) + " vertices");
      const Refined p = refine_with<Mask, CGAL::Parallel_tag>(b, options, n, one_pass);
      ASSERT_TRUE(p.mesh.is_valid(true));
      ASSERT_EQ(p.mesh.number_of_faces(), s.mesh.number_of_faces());
      const Connectivity cs = connectivity_of(s.mesh), cp = connectivity_of(p.mesh);
      EXPECT_TRUE(same_bytes(cs.target, cp.target));
      EXPECT_TRUE(same_bytes(cs.next, cp.next));
      EXPECT_TRUE(same_bytes(cs.prev, cp.prev));
      EXPECT_TRUE(same_bytes(cs.face, cp.face));
      EXPECT_TRUE(same_bytes(cs.mobius, cp.mobius));
      EXPECT_TRUE(same_bytes(cs.vertex_dart, cp.vertex_dart));
      EXPECT_TRUE(same_bytes(cs.face_dart, cp.face_dart));
      EXPECT_TRUE(same_bytes(s.points, p.points));
      for (const char* name : {CGAL_ext::edge_sharpness_name, CGAL_ext::vertex_sharpness_name}) {
        const bool on_edges = name == std::string(CGAL_ext::edge_sharpness_name);
        std::vector<float> ss, sp;
        if (on_edges) {
          ss = s.mesh.property_map<CGAL_ext::Edge_index, float>(name)->data();
          sp = p.mesh.property_map<CGAL_ext::Edge_index, float>(name)->data();
        } else {
          ss = s.mesh.property_map<CGAL_ext::Vertex_index, float>(name)->data();
          sp = p.mesh.property_map<CGAL_ext::Vertex_index, float>(name)->data();
        }
        EXPECT_TRUE(same_bytes(ss, sp)) << name;
      }
      auto hs = s.mesh.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
      auto hp = p.mesh.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
      ASSERT_EQ(hs.has_value(), hp.has_value());
      if (hs) {
        EXPECT_TRUE(same_bytes(hs->data(), hp->data()));
      }
    }
  }
}

// A generated mesh with, if `sharp`, a fixed mix of smooth, semi-sharp and
// infinitely sharp edges and a few corners.
Built generated(Mesh m, bool sharp)
{
  Built b;
  b.mesh = std::move(m);
  b.edge_sharpness.assign(b.mesh.number_of_edges(), 0.0f);
  b.vertex_sharpness.assign(b.mesh.number_of_vertices(), 0.0f);
  if (sharp) {
    for (std::size_t e = 0; e < b.edge_sharpness.size(); ++e)
      b.edge_sharpness[e] = e % 7 == 0 ? 10.0f : (e % 5 == 0 ? 0.25f + float(e % 11) / 4.0f : 0.0f);
    for (std::size_t v = 0; v < b.vertex_sharpness.size(); v += 19)
      b.vertex_sharpness[v] = 2.5f;
  }
  return b;
}

// A scheme with every crease method and, on a surface with a border, every
// boundary rule (`all_rules`; else the defaults), on a one-sided surface
// large enough that the loops of the last step are split among threads (a
// TBB task takes 4096 elements at least), with and without sharpness.
template <class Mask>
void check_schemes_on(const std::string& name, const Mesh& m, unsigned n, bool all_rules)
{
  using B = Boundary_interpolation;
  const std::vector<Crease_method> methods =
    all_rules ? std::vector<Crease_method>{Crease_method::uniform, Crease_method::chaikin}
              : std::vector<Crease_method>{Crease_method::uniform};
  const auto edges = m.edges();
  const bool border = std::any_of(edges.begin(), edges.end(), [&](CGAL_ext::Edge_index e) { return m.is_border(e); });
  const std::vector<B> rules = all_rules && border
                                 ? std::vector<B>{B::edge_only, B::edge_and_corner, B::none}
                                 : std::vector<B>{B::edge_only};
  for (bool sharp : {false, true}) {
    const Built b = generated(m, sharp);
    for (Crease_method c : methods)
      for (Boundary_interpolation bi : rules) {
        if (!sharp && c == Crease_method::chaikin)
          continue; // the crease methods differ only at semi-sharp edges

        S::Refinement_options options;
        options.crease_method = c;
        options.boundary_interpolation = bi;
        check_parallel_stages<Mask>(name + (sharp ? ", sharp" : ", smooth") + ", crease method " +
                                      std::to_string(int(c)) + ", boundary " + std::to_string(int(bi)),
                                    b, options, n);
      }
  }
}

// A double cone over a regular n-gon: two apexes of valence n, whose
// incidence lists (n > 32) the parallel pass sorts with std::sort rather
// than its insertion sort for short lists.
Mesh bipyramid(std::size_t n)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * CGAL_PI * double(i) / double(n);
    points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  points.emplace_back(0.0, 0.0, 1.0);
  points.emplace_back(0.0, 0.0, -1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    faces.push_back({i, j, n});
    faces.push_back({j, i, n + 1});
  }
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  return m;
}

// A non-finite point spoils only the child points made from it, in both
// passes. Catmull–Clark of an 8 × 8 torus of quads (every vertex of valence
// 4) with vertex 0 at NaN: its own vertex point, those of the 8 vertices that
// share a face with it, the 12 edge points and the 4 face points of its 4
// faces read it, 25 points of 256; every other stays finite.
TEST(SubdivisionParallel, NonFinitePointSpoilsOnlyThePointsMadeFromIt)
{
  Mesh torus;
  CGAL_ext::make_torus(torus, 8, 8);
  torus.point(CGAL_ext::Vertex_index(0)) = Point(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  const Built b = generated(torus, false);
  S::Refinement_options options;
  options.parallel_min_vertices = 0; // the gather on the level, however small
  auto count_non_finite = [](const std::vector<V3>& points) {
    return std::count_if(points.begin(), points.end(), [](const V3& p) {
      return !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    });
  };
  const Refined s = refine_with<S::Catmull_clark_mask, CGAL::Sequential_tag>(b, options, 1, true);
  const Refined p = refine_with<S::Catmull_clark_mask, CGAL::Parallel_tag>(b, options, 1, true);
  ASSERT_EQ(s.points.size(), 256u);
  EXPECT_EQ(count_non_finite(s.points), 25);
  EXPECT_EQ(count_non_finite(p.points), 25);
}

TEST(SubdivisionParallel, EveryStageBitIdenticalToSerial)
{
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  tbb::task_arena arena(4);
  arena.execute([] {
    Mesh strip, strip_tris, klein;
    CGAL_ext::make_mobius_strip(strip, 64, 16);
    CGAL_ext::make_mobius_strip(strip_tris, 64, 16, 1, 1.0, 0.5, false);
    CGAL_ext::make_klein_bottle(klein, 40, 40);
    // Doo–Sabin and √3 have border rules of their own and no creases.
    check_schemes_on<S::Catmull_clark_mask>("Catmull-Clark, Moebius strip", strip, 2, true);
    check_schemes_on<S::Catmull_clark_mask>("Catmull-Clark, Klein bottle", klein, 2, true);
    check_schemes_on<S::Bilinear_mask>("bilinear, Moebius strip", strip, 2, true);
    check_schemes_on<S::Doo_sabin_mask>("Doo-Sabin, Moebius strip", strip, 2, false);
    check_schemes_on<S::Doo_sabin_mask>("Doo-Sabin, Klein bottle", klein, 2, false);
    check_schemes_on<Unequal_weights_mask<3>>("three vertex sums, Moebius strip", strip, 2, true);
    check_schemes_on<Unequal_weights_mask<2>>("two vertex sums, Klein bottle", klein, 2, false);
    check_schemes_on<S::Loop_mask>("Loop, Moebius strip", strip_tris, 2, true);
    check_schemes_on<S::Linear_mask>("linear, Moebius strip", strip_tris, 2, true);
    check_schemes_on<S::Sqrt3_mask>("sqrt(3), Moebius strip", strip_tris, 3, false);
    const Mesh cone = bipyramid(48);
    check_schemes_on<S::Catmull_clark_mask>("Catmull-Clark, vertices of valence 48", cone, 3, false);
    check_schemes_on<S::Loop_mask>("Loop, vertices of valence 48", cone, 3, false);
  });
}

// The faces of the corners of level `L`, from its corner table.
std::vector<std::uint32_t> faces_of_corners(const Level& L)
{
  std::vector<std::uint32_t> faces(L.nc);
  for (std::uint32_t f = 0; f < L.nf; ++f)
    for (std::uint32_t k = L.f_offset[f]; k < L.f_offset[f + 1]; ++k)
      faces[k] = f;
  return faces;
}

// The tables `t` of level `L` are `reference`'s (a counting sort over `L`),
// and give each corner its face.
void expect_incidence(const Level& L, const S::internal::Incidence& t, const S::internal::Incidence& reference)
{
  EXPECT_TRUE(same_bytes(t.edge_offset, reference.edge_offset));
  EXPECT_TRUE(same_bytes(t.edge_ends, reference.edge_ends));
  EXPECT_TRUE(same_bytes(t.corner_offset, reference.corner_offset));
  EXPECT_TRUE(same_bytes(t.corners, reference.corners));
  if (t.corners.empty())
    return;
  const std::vector<std::uint32_t> faces = faces_of_corners(L);
  std::size_t wrong = 0;
  for (std::uint32_t k = 0; k < L.nc; ++k)
    wrong += t.face_of_corner(k) == faces[k] ? 0 : 1;
  EXPECT_EQ(wrong, 0u);
}

// Each level's incidence tables, walked around its vertices in parallel and
// derived by the split from its parent's, are those of a counting sort over
// the level itself: every list in order, every corner's face. (How the
// refiner hands them from level to level is covered by the bit-identical
// results of the parallel pass above.)
template <class Mask>
void check_incidence_tables(const std::string& what, const Mesh& m, unsigned n)
{
  SCOPED_TRACE(what);
  constexpr bool corners = Mask::split == S::Split::quad;
  S::Refiner<Mask> r{Mask()};
  r.refine(m, n);
  ASSERT_EQ(r.number_of_levels(), n);
  for (unsigned k = 0; k <= n; ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    const Level& L = S::internal::level_of(r, k);
    S::internal::Incidence reference, walked;
    S::internal::build_incidence_serially(L, corners, reference);
    ASSERT_EQ(reference.edge_ends.size(), 2 * std::size_t(L.ne));
    ASSERT_EQ(reference.corners.size(), corners ? std::size_t(L.nc) : 0u);
    S::internal::build_incidence<CGAL::Parallel_tag>(L, corners, walked);
    expect_incidence(L, walked, reference);
    if (k == 0)
      continue;
    S::internal::Incidence parent, derived;
    S::internal::build_incidence_serially(S::internal::level_of(r, k - 1), corners, parent);
    S::internal::derive_incidence<CGAL::Parallel_tag, Mask::split>(S::internal::level_of(r, k - 1), parent, derived);
    expect_incidence(L, derived, reference);
  }
}

TEST(SubdivisionParallel, IncidenceTablesOfEveryLevelAsACountingSort)
{
  Mesh strip, strip_tris, klein;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  CGAL_ext::make_mobius_strip(strip_tris, 12, 3, 1, 1.0, 0.5, false);
  CGAL_ext::make_klein_bottle(klein, 6, 6);
  // Vertices on no edge keep empty lists.
  klein.add_vertex(Point(9, 9, 9));
  strip_tris.add_vertex(Point(9, 9, 9));
  check_incidence_tables<S::Catmull_clark_mask>("Catmull-Clark, Moebius strip", strip, 3);
  check_incidence_tables<S::Catmull_clark_mask>("Catmull-Clark, Klein bottle", klein, 3);
  check_incidence_tables<S::Loop_mask>("Loop, Moebius strip", strip_tris, 3);
  check_incidence_tables<S::Catmull_clark_mask>("Catmull-Clark, vertices of valence 48", bipyramid(48), 2);
  check_incidence_tables<S::Loop_mask>("Loop, vertices of valence 48", bipyramid(48), 2);
  for (const char* file : {"catmark_nonquads.obj", "catmark_pole64.obj", "catmark_edgecorner.obj", "catmark_smoothtris1.obj"})
    check_incidence_tables<S::Catmull_clark_mask>(file, build(read_shape(test::data(std::string("opensubdiv/") + file))).mesh, 2);
  for (const char* file : {"loop_tetrahedron.obj", "loop_triangle_edgeonly.obj"})
    check_incidence_tables<S::Loop_mask>(file, build(read_shape(test::data(std::string("opensubdiv/") + file))).mesh, 2);
}

TEST(SubdivisionParallel, OpenSubdivShapesBitIdenticalToSerial)
{
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  tbb::task_arena arena(4);
  arena.execute([] {
    auto check = [](auto mask, const std::string& file, unsigned n) {
      using Mask = decltype(mask);
      const Shape s = read_shape(test::data("opensubdiv/" + file));
      S::Refinement_options options;
      options.crease_method = s.crease_method;
      options.boundary_interpolation = s.boundary;
      check_parallel_stages<Mask>(file, build(s), options, n);
    };
    check(S::Catmull_clark_mask(), "catmark_cube_creases1.obj", 5);
    check(S::Catmull_clark_mask(), "catmark_chaikin1.obj", 4);
    check(S::Catmull_clark_mask(), "catmark_edgecorner.obj", 5);
    check(S::Catmull_clark_mask(), "catmark_torus_creases1.obj", 4);
    check(S::Bilinear_mask(), "catmark_cube_creases1.obj", 5);
    check(S::Doo_sabin_mask(), "catmark_cube_creases1.obj", 5);
    check(S::Loop_mask(), "loop_icos_semisharp.obj", 5);
    check(S::Loop_mask(), "loop_triangle_edgeonly.obj", 6);
    check(S::Linear_mask(), "loop_icos_semisharp.obj", 5);
    check(S::Sqrt3_mask(), "loop_icos_semisharp.obj", 6);
  });
}

// The automatic threshold is the documented rule: more than one thread, and
// at least parallel_vertices_per_thread vertices per thread; any other value
// of the option is a plain minimum.
TEST(SubdivisionParallel, ThresholdFollowsThreadsAndSize)
{
  const std::uint32_t g = S::parallel_vertices_per_thread, automatic = S::Refinement_options::automatic;
  EXPECT_EQ(S::Refinement_options().parallel_min_vertices, automatic);
  {
    tbb::task_arena one(1);
    one.execute([&] { EXPECT_FALSE(S::runs_in_parallel(1u << 30, automatic)); });
    one.execute([&] { EXPECT_TRUE(S::runs_in_parallel(5, 0)); }); // an explicit minimum is obeyed
  }
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 4);
  for (int t : {2, 4}) {
    tbb::task_arena arena(t);
    arena.execute([&] {
      EXPECT_FALSE(S::runs_in_parallel(std::uint32_t(t) * g - 1, automatic)) << t;
      EXPECT_TRUE(S::runs_in_parallel(std::uint32_t(t) * g, automatic)) << t;
    });
  }
  EXPECT_TRUE(S::runs_in_parallel(0, 0));
  EXPECT_FALSE(S::runs_in_parallel(99, 100));
  EXPECT_TRUE(S::runs_in_parallel(100, 100));
}

// The tuner's rule on given timings: the smallest class without a verdict
// runs with threads three times, then serially three times, and the faster
// (per parent vertex, best of) is its verdict; a win of the threads carries
// to larger classes, a loss to smaller ones; each number of threads learns
// on its own.
TEST(SubdivisionParallel, TunerTriesTheSmallestOpenClassBothWays)
{
  using Plan = S::internal::Parallel_plan;
  using Modes = std::array<bool, 3>;
  S::internal::Parallel_step_tuner tuner;
  ASSERT_EQ(S::internal::Parallel_step_tuner::samples_per_verdict, 3u);
  const auto prior = [](std::uint32_t n) { return n >= 16384; };
  // Parents of 4 096 (class 12, below the prior), 20 000 (class 14), 80 000
  // (class 16) and 320 000 (class 18) vertices.
  const std::vector<std::uint32_t> parents = {4096, 20000, 80000, 320000};
  auto modes = [&](unsigned threads) {
    const Plan p = tuner.plan(threads, parents, prior);
    return Modes{p.parallel_class(14), p.parallel_class(16), p.parallel_class(18)};
  };
  auto record = [&](std::uint32_t parent, bool parallel, std::initializer_list<double> seconds) {
    for (double t : seconds)
      tuner.record(2, parent, parallel, t);
  };
  EXPECT_EQ(modes(2), (Modes{true, true, true}));
  EXPECT_EQ(tuner.plan(2, parents, prior).tried, 14);
  EXPECT_EQ(tuner.plan(2, parents, prior, false).tried, -1); // refine(): follows verdicts, tries nothing
  // Class 14: threads at 2, 1.8 and 1.9 ms a step, serially 1, 1.2 and 1.1 ms.
  record(20000, true, {2e-3, 1.8e-3});
  EXPECT_EQ(modes(2), (Modes{true, true, true}));
  record(20000, true, {1.9e-3});
  EXPECT_EQ(modes(2), (Modes{false, true, true})); // now the serial tries
  record(20000, false, {1e-3, 1.2e-3});
  EXPECT_EQ(tuner.verdict(2, 14), -1);
  EXPECT_EQ(modes(2), (Modes{false, true, true}));
  record(20000, false, {1.1e-3});
  EXPECT_EQ(tuner.verdict(2, 14), Plan::serial);
  // Class 16 is next; class 14 stays serial, as do the classes below it.
  EXPECT_EQ(modes(2), (Modes{false, true, true}));
  EXPECT_EQ(tuner.plan(2, parents, prior).tried, 16);
  EXPECT_FALSE(tuner.plan(2, parents, prior).parallel_class(13));
  record(80000, true, {2e-3, 2.5e-3, 2.2e-3});
  EXPECT_EQ(modes(2), (Modes{false, false, true}));
  record(80000, false, {4e-3, 3.5e-3, 3.9e-3});
  EXPECT_EQ(tuner.verdict(2, 16), Plan::parallel);
  // Class 18 follows the win at 16 without a try; class 15, between a loss
  // and a win, has no verdict yet.
  EXPECT_EQ(modes(2), (Modes{false, true, true}));
  EXPECT_EQ(tuner.plan(2, parents, prior).tried, -1);
  EXPECT_EQ(tuner.verdict(2, 18), -1);
  EXPECT_EQ(tuner.verdict(2, 15), -1);
  // Class 15, between a loss below and a win above, is implied nothing: it
  // uses threads, as a class with no verdict does, and is tried.
  EXPECT_TRUE(tuner.plan(2, {32768}, prior).parallel_class(15));
  EXPECT_EQ(tuner.plan(2, {32768}, prior).tried, 15);
  // The time per vertex decides, not the time: serial steps from 65 536
  // vertices (class 16 too) at 2.6 ms are faster per vertex than steps with
  // threads from 80 000 at 3.5 ms.
  S::internal::Parallel_step_tuner per_vertex;
  for (int i = 0; i < 3; ++i) {
    per_vertex.record(2, 80000, true, 3.5e-3);
    per_vertex.record(2, 65536, false, 2.6e-3);
  }
  EXPECT_EQ(per_vertex.verdict(2, 16), Plan::serial);
  // Four threads have learnt nothing.
  EXPECT_EQ(modes(4), (Modes{true, true, true}));
  EXPECT_EQ(tuner.verdict(4, 14), -1);
}

// A mask type of its own, so that its refiners' tuner starts empty here
// whatever other tests ran before in this process.
struct Tuned_catmull_clark_mask : S::Catmull_clark_mask
{};

// Refinements under CGAL::Parallel_tag with the automatic choice time their
// steps: after three runs each way a class has its verdict, and every run,
// whichever way each step went, gives the serial result bit for bit. An
// explicit threshold times nothing.
TEST(SubdivisionParallel, RepeatedRefinementsLearnAndStayBitIdentical)
{
  using R = S::Refiner<Tuned_catmull_clark_mask>;
  R::tuner().clear(); // as new, also when the test repeats
  Mesh torus;
  CGAL_ext::make_torus(torus, 128, 128); // 16 384 vertices: the prior's least on two threads
  const Built b = generated(torus, true);
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 2);
  tbb::task_arena arena(2);
  arena.execute([&] {
    const unsigned c = S::internal::size_class(16384);
    S::Refinement_options fixed;
    fixed.parallel_min_vertices = 16384;
    refine_with<Tuned_catmull_clark_mask, CGAL::Parallel_tag>(b, fixed, 1, true);
    EXPECT_EQ(R::tuner().verdict(2, c), -1);
    const Refined s = refine_with<Tuned_catmull_clark_mask, CGAL::Sequential_tag>(b, S::Refinement_options(), 1, true);
    for (int run = 0; run < 6; ++run) {
      EXPECT_EQ(R::tuner().verdict(2, c), -1) << run;
      const Refined p = refine_with<Tuned_catmull_clark_mask, CGAL::Parallel_tag>(b, S::Refinement_options(), 1, true);
      EXPECT_TRUE(same_bytes(s.points, p.points)) << run;
      EXPECT_TRUE(same_connectivity(s.mesh, p.mesh)) << run;
    }
    EXPECT_NE(R::tuner().verdict(2, c), -1);
  });
}

// Threads in one step and none in the next, which no minimum size gives but
// verdicts may (a win at 16 384 vertices, a loss at 65 536): the serial step
// after a parallel one, in one pass and level by level, gives the serial
// result bit for bit, whether the base uses threads or not.
struct Mixed_catmull_clark_mask : S::Catmull_clark_mask
{};

TEST(SubdivisionParallel, ThreadsThenNoneStayBitIdentical)
{
  using R = S::Refiner<Mixed_catmull_clark_mask>;
  using Plan = S::internal::Parallel_plan;
  R::tuner().clear();
  for (int i = 0; i < 3; ++i) {
    R::tuner().record(2, 16384, true, 1e-3);
    R::tuner().record(2, 16384, false, 2e-3);
    R::tuner().record(2, 65536, true, 2e-3);
    R::tuner().record(2, 65536, false, 1e-3);
  }
  ASSERT_EQ(R::tuner().verdict(2, 14), Plan::parallel);
  ASSERT_EQ(R::tuner().verdict(2, 16), Plan::serial);
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 2);
  tbb::task_arena arena(2);
  arena.execute([&] {
    const Plan plan =
      R::tuner().plan(2, {16384, 65536}, [](std::uint32_t n) { return S::runs_in_parallel(n, S::Refinement_options::automatic); });
    ASSERT_TRUE(plan.parallel_class(14));
    ASSERT_FALSE(plan.parallel_class(16));
    EXPECT_TRUE(plan.parallel_class(15)); // a win below and a loss above as near: the win
    EXPECT_EQ(plan.tried, -1);
    // From 16 384 vertices: threads, then none. From 4 096 (below the
    // floor): none, threads, none, the serial base making the tables of the
    // step with threads.
    for (auto [n, levels] : {std::pair<std::size_t, unsigned>{128, 2}, std::pair<std::size_t, unsigned>{64, 3}}) {
      Mesh torus;
      CGAL_ext::make_torus(torus, n, n);
      const Built b = generated(torus, true);
      for (bool one_pass : {true, false}) {
        SCOPED_TRACE(std::to_string(n) + (one_pass ? ", one pass" : ", level by level"));
        const Refined s =
          refine_with<Mixed_catmull_clark_mask, CGAL::Sequential_tag>(b, S::Refinement_options(), levels, one_pass);
        const Refined p =
          refine_with<Mixed_catmull_clark_mask, CGAL::Parallel_tag>(b, S::Refinement_options(), levels, one_pass);
        EXPECT_TRUE(same_bytes(s.points, p.points));
        EXPECT_TRUE(same_connectivity(s.mesh, p.mesh));
        EXPECT_TRUE(same_bytes(s.mesh.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name)->data(),
                               p.mesh.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name)->data()));
      }
    }
  });
}

// A mesh with maps of its own refines level by level; then each vertex map
// is interpolated and each child face takes its base face's value. Under
// CGAL::Parallel_tag, with threads in the last step (mask types of their own,
// so that their refiners have no verdicts) and in the maps' loops, the
// points and every map are the serial run's, bit for bit.
struct Carried_catmull_clark_mask : S::Catmull_clark_mask
{};
struct Carried_loop_mask : S::Loop_mask
{};

template <class Mask>
void expect_carried_maps_bit_identical(const std::string& what, const Mesh& base)
{
  SCOPED_TRACE(what);
  using CGAL_ext::Face_index;
  using CGAL_ext::Vertex_index;
  S::Refiner<Mask>::tuner().clear();
  Mesh m = base;
  auto scalar = m.add_property_map<Vertex_index, double>("v:scalar").first;
  auto colour = m.add_property_map<Vertex_index, std::array<float, 3>>("v:colour").first;
  auto label = m.add_property_map<Face_index, int>("f:label").first;
  auto name = m.add_property_map<Face_index, std::string>("f:name").first;
  for (auto v : m.vertices()) {
    const double t = double(v.idx());
    scalar[v] = std::sin(0.37 * t) + 1e-3 * t;
    colour[v] = {float(std::cos(t)), float(0.5 + 0.25 * std::sin(2 * t)), float(t / 7)};
  }
  for (auto f : m.faces()) {
    label[f] = int(7 * f.idx() + 1);
    name[f] = "face " + std::to_string(f.idx());
  }
  // A channel with a seam: a value per vertex, and every corner of the
  // faces of one band of its own value (the band's sides are seams).
  auto uv = m.add_corner_channel<std::array<double, 2>>("c:uv").first;
  for (auto v : m.vertices())
    uv.add_value({std::cos(0.11 * double(v.idx())), 1e-3 * double(v.idx())});
  for (auto f : m.faces())
    for (auto d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      uv.set_index(m.corner(d), f.idx() % 16 == 3 ? std::uint32_t(uv.add_value({0.5, double(m.corner(d).idx())}))
                                                  : std::uint32_t(m.target(d).idx()));
  Mesh serial = m, parallel = m;
  const auto two = CGAL_ext::parameters::number_of_iterations(2);
  S::subdivide(serial, Mask(), two);
  {
    tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 2);
    tbb::task_arena arena(2);
    arena.execute([&] { S::subdivide<CGAL::Parallel_tag>(parallel, Mask(), two); });
  }
  ASSERT_EQ(serial.number_of_faces(), 16 * base.number_of_faces());
  // The result is large enough for threads in its maps' loops.
  ASSERT_GE(serial.number_of_vertices(), 2 * S::parallel_vertices_per_thread);
  EXPECT_TRUE(same_bytes(serial.points().data(), parallel.points().data()));
  EXPECT_TRUE(same_connectivity(serial, parallel));
  auto data = [](const Mesh& mesh, auto key, auto value, const char* map) {
    return mesh.property_map<decltype(key), decltype(value)>(map).value().data();
  };
  EXPECT_TRUE(same_bytes(data(serial, Vertex_index(), 0.0, "v:scalar"), data(parallel, Vertex_index(), 0.0, "v:scalar")));
  const std::array<float, 3> c{};
  EXPECT_TRUE(same_bytes(data(serial, Vertex_index(), c, "v:colour"), data(parallel, Vertex_index(), c, "v:colour")));
  EXPECT_EQ(data(serial, Face_index(), 0, "f:label"), data(parallel, Face_index(), 0, "f:label"));
  EXPECT_EQ(data(serial, Face_index(), std::string(), "f:name"), data(parallel, Face_index(), std::string(), "f:name"));
  const auto su = serial.corner_channel<std::array<double, 2>>("c:uv"), pu = parallel.corner_channel<std::array<double, 2>>("c:uv");
  ASSERT_TRUE(su && pu);
  ASSERT_EQ(su->values().size(), pu->values().size());
  EXPECT_TRUE(same_bytes(su->values(), pu->values()));
  std::size_t differing = 0;
  for (auto h : serial.halfedges())
    differing += su->index(h) != pu->index(h);
  EXPECT_EQ(differing, 0u);
}

TEST(SubdivisionParallel, CarriedMapsBitIdenticalToSerial)
{
  Mesh torus, strip;
  CGAL_ext::make_torus(torus, 64, 64); // level 1: 16 384 vertices, threads from there on two
  expect_carried_maps_bit_identical<Carried_catmull_clark_mask>("Catmull-Clark, torus", torus);
  CGAL_ext::make_mobius_strip(strip, 128, 32, 1, 1.0, 0.5, false); // triangles, a border
  expect_carried_maps_bit_identical<Carried_loop_mask>("Loop, Moebius strip", strip);
}
#endif

} // namespace

} // namespace subdivision_parallel_tests
