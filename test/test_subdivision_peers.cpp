// Subdivision against CGAL's Subdivision_method_3 (Catmull-Clark, Loop,
// Doo-Sabin, sqrt3) on closed orientable meshes, where the rules are the
// same; Doo-Sabin and sqrt3 with exact rationals computed by hand; the memory
// of EPECK subdivision over five levels; the parallel path against the
// serial one, bit for bit.
#include "test_util.h"

#include <cstddef>

#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

// AddressSanitizer's allocator, not malloc's, holds the heap under ASan: GCC
// says so with __SANITIZE_ADDRESS__, clang with __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define CGAL_EXT_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CGAL_EXT_TEST_UNDER_ASAN 1
#endif
#endif

#ifdef CGAL_EXT_TEST_UNDER_ASAN
// From the AddressSanitizer runtime (GCC ships no header for it).
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#else
#include <malloc.h>
#endif

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace subdivision_peers_tests {

namespace {

namespace S = CGAL_ext::Subdivision;
using K = test::Epick;
using Point = K::Point_3;

struct Soup
{
  std::string name;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
};

Soup cube()
{
  Soup s{"cube", {}, {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  for (int i = 0; i < 8; ++i)
    s.points.emplace_back((i & 1) ^ ((i >> 1) & 1), (i >> 1) & 1, (i >> 2) & 1);
  return s;
}

Soup octahedron()
{
  return {"octahedron",
          {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
          {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

// A torus grid with irregular radii, of quads or of triangles, and one
// quad-dominant variant with a pentagon and a triangle for Catmull-Clark.
Soup torus(std::size_t nu, std::size_t nv, bool triangles)
{
  Soup s{triangles ? "torus_triangles" : "torus_quads", {}, {}};
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * double(i) / double(nu), v = 2 * M_PI * double(j) / double(nv);
      const double r = 0.6 + 0.1 * std::sin(3 * u);
      s.points.emplace_back((2 + r * std::cos(v)) * std::cos(u), (2 + r * std::cos(v)) * std::sin(u),
                            r * std::sin(v));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % nu) * nv + (j % nv); };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangles) {
        s.faces.push_back({a, b, c});
        s.faces.push_back({a, c, d});
      } else {
        s.faces.push_back({a, b, c, d});
      }
    }
  return s;
}

Soup torus_mixed()
{
  Soup s = torus(6, 5, false);
  s.name = "torus_mixed";
  // Merge two neighbouring quads into a hexagon, and split another into
  // two triangles.
  s.faces[0] = {s.faces[0][0], s.faces[0][1], s.faces[5][1], s.faces[5][2], s.faces[0][2], s.faces[0][3]};
  s.faces.erase(s.faces.begin() + 5);
  const auto q = s.faces[12];
  s.faces[12] = {q[0], q[1], q[2]};
  s.faces.push_back({q[0], q[2], q[3]});
  return s;
}

Soup icosahedron()
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  return {"icosahedron",
          {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}},
          {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
           {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
           {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}}};
}

enum class Scheme { catmull_clark, loop, doo_sabin, sqrt3, linear, bilinear };
// (Its one-argument constructor does not compile in CGAL 5.5.)
using Cgal_linear_mask = CGAL::Linear_mask_3<CGAL::Surface_mesh<Point>>;

// Ours and CGAL's, n levels; the results as point sets and face counts.
void compare_with_cgal(const Soup& soup, Scheme scheme, unsigned levels)
{
  SCOPED_TRACE(soup.name + " levels " + std::to_string(levels));
  CGAL_ext::Mobius_mesh<Point> ours;
  CGAL_ext::polygon_soup_to_mobius_mesh(soup.points, soup.faces, ours);
  CGAL::Surface_mesh<Point> theirs;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.faces, theirs);
  const auto np = CGAL_ext::parameters::number_of_iterations(levels);
  const auto cgal_np = CGAL::parameters::number_of_iterations(int(levels));
  namespace SM3 = CGAL::Subdivision_method_3;
  switch (scheme) {
  case Scheme::catmull_clark:
    S::catmull_clark(ours, np);
    SM3::CatmullClark_subdivision(theirs, cgal_np);
    break;
  case Scheme::loop:
    S::loop(ours, np);
    SM3::Loop_subdivision(theirs, cgal_np);
    break;
  case Scheme::doo_sabin:
    S::doo_sabin(ours, np);
    SM3::DooSabin_subdivision(theirs, cgal_np);
    break;
  case Scheme::sqrt3:
    S::sqrt3(ours, np);
    SM3::Sqrt3_subdivision(theirs, cgal_np);
    break;
  case Scheme::linear: // CGAL's linear mask in its triangle and quad hosts
    S::linear(ours, np);
    SM3::PTQ(theirs, Cgal_linear_mask(&theirs, get(CGAL::vertex_point, theirs)), int(levels));
    break;
  case Scheme::bilinear:
    S::bilinear(ours, np);
    SM3::PQQ(theirs, Cgal_linear_mask(&theirs, get(CGAL::vertex_point, theirs)), int(levels));
    break;
  }
  ASSERT_TRUE(ours.is_valid(true));
  ASSERT_EQ(ours.number_of_vertices(), theirs.number_of_vertices());
  ASSERT_EQ(ours.number_of_edges(), theirs.number_of_edges());
  ASSERT_EQ(ours.number_of_faces(), theirs.number_of_faces());
  const std::vector<Point> a(ours.points().data().begin(), ours.points().data().end());
  std::vector<Point> b;
  for (auto v : theirs.vertices())
    b.push_back(theirs.point(v));
  EXPECT_EQ(test::unmatched_points(a, b, 1e-12), 0u);
  EXPECT_EQ(test::unmatched_points(b, a, 1e-12), 0u);
  // Face degrees as a multiset (Doo-Sabin keeps n-gons, the others make
  // quads or triangles).
  std::map<std::size_t, std::size_t> da, db;
  for (auto f : ours.faces())
    ++da[ours.degree(f)];
  for (auto f : theirs.faces())
    ++db[theirs.degree(f)];
  EXPECT_EQ(da, db);
}

TEST(SubdivisionCgal, CatmullClark)
{
  for (const Soup& s : {cube(), octahedron(), torus(8, 6, false), torus_mixed()})
    for (unsigned n = 1; n <= 3; ++n)
      compare_with_cgal(s, Scheme::catmull_clark, n);
}

TEST(SubdivisionCgal, Loop)
{
  for (const Soup& s : {octahedron(), icosahedron(), torus(8, 6, true)})
    for (unsigned n = 1; n <= 3; ++n)
      compare_with_cgal(s, Scheme::loop, n);
}

TEST(SubdivisionCgal, DooSabin)
{
  for (const Soup& s : {cube(), octahedron(), torus(8, 6, false), torus_mixed()})
    for (unsigned n = 1; n <= 3; ++n)
      compare_with_cgal(s, Scheme::doo_sabin, n);
}

TEST(SubdivisionCgal, Sqrt3)
{
  for (const Soup& s : {octahedron(), icosahedron(), torus(8, 6, true)})
    for (unsigned n = 1; n <= 4; ++n)
      compare_with_cgal(s, Scheme::sqrt3, n);
}

TEST(SubdivisionCgal, LinearAndBilinear)
{
  for (const Soup& s : {octahedron(), icosahedron(), torus(8, 6, true)})
    for (unsigned n = 1; n <= 3; ++n)
      compare_with_cgal(s, Scheme::linear, n);
  for (const Soup& s : {cube(), octahedron(), torus(8, 6, false), torus_mixed()})
    for (unsigned n = 1; n <= 3; ++n)
      compare_with_cgal(s, Scheme::bilinear, n);
}

// ----------------------------------------------------------------- exact, by hand

using Q = CGAL::Gmpq;
using Kq = CGAL::Simple_cartesian<Q>;

template <class Kernel>
CGAL_ext::Mobius_mesh<typename Kernel::Point_3> exact_mesh(const Soup& s)
{
  std::vector<typename Kernel::Point_3> pts;
  for (const Point& p : s.points)
    pts.emplace_back(int(p.x()), int(p.y()), int(p.z()));
  CGAL_ext::Mobius_mesh<typename Kernel::Point_3> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(pts, s.faces, m);
  return m;
}

TEST(SubdivisionExact, DooSabinCubeByHand)
{
  auto m = exact_mesh<Kq>(cube());
  S::doo_sabin(m);
  ASSERT_EQ(m.number_of_vertices(), 24u);
  // A quad's corner: 9/16 of its vertex, 3/16 of each neighbour, 1/16 of the
  // opposite vertex. On the unit cube every corner point lies 1/4 in from
  // its vertex along both edges of its face: (1/4 or 3/4, 1/4 or 3/4, 0 or 1)
  // in some order of the axes.
  std::size_t checked = 0;
  for (const auto& p : m.points().data()) {
    int quarters = 0, ends = 0;
    for (int i = 0; i < 3; ++i) {
      const Q c = p[i];
      quarters += (c == Q(1, 4) || c == Q(3, 4)) ? 1 : 0;
      ends += (c == Q(0) || c == Q(1)) ? 1 : 0;
    }
    EXPECT_EQ(quarters, 2) << p;
    EXPECT_EQ(ends, 1) << p;
    ++checked;
  }
  EXPECT_EQ(checked, 24u);
  // Corner 0 is face 0's first corner: face (0, 3, 2, 1) of the cube starts
  // with the halfedge into vertex 3 = (0,1,0); its neighbours in the face are
  // (0,0,0) and (1,1,0), the opposite vertex (1,0,0):
  // (9(0,1,0) + 3(0,0,0) + 3(1,1,0) + (1,0,0)) / 16 = (1/4, 3/4, 0).
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), Kq::Point_3(Q(1, 4), Q(3, 4), Q(0)));
}

TEST(SubdivisionExact, Sqrt3TetrahedronByHand)
{
  Soup tet{"tetrahedron", {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  auto m = exact_mesh<Kq>(tet);
  S::sqrt3(m);
  ASSERT_EQ(m.number_of_vertices(), 8u);
  ASSERT_EQ(m.number_of_faces(), 12u);
  // Valence 3: alpha = (4 - 2 cos(2 pi / 3)) / 9 = 5/9, so v' = 4/9 v + 5/27 (sum of
  // the three others); at (1,1,1) the others sum to (-1,-1,-1): 12/27 - 5/27 = 7/27.
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), Kq::Point_3(Q(7, 27), Q(7, 27), Q(7, 27)));
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(1)), Kq::Point_3(Q(7, 27), Q(-7, 27), Q(-7, 27)));
  // Centroid of face 0, vertices 0, 1, 2: (1/3, 1/3, -1/3).
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(4)), Kq::Point_3(Q(1, 3), Q(1, 3), Q(-1, 3)));
  // The same on EPECK, exactly.
  auto e = exact_mesh<test::Epeck>(tet);
  S::sqrt3(e);
  EXPECT_EQ(e.point(CGAL_ext::Vertex_index(0)), test::Epeck::Point_3(test::Epeck::FT(7) / 27, test::Epeck::FT(7) / 27,
                                                                   test::Epeck::FT(7) / 27));
}

TEST(SubdivisionExact, LinearTetrahedronTwoLevelsByHand)
{
  // Midpoint subdivision, twice: every vertex of the result is (a + b) / 2
  // of the ends of the parent edge it was made on, old vertices stay.
  Soup tet{"tetrahedron", {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  auto m = exact_mesh<Kq>(tet);
  for (int step = 0; step < 2; ++step) {
    const auto parent = m;
    S::linear(m);
    ASSERT_EQ(m.number_of_vertices(), parent.number_of_vertices() + parent.number_of_edges());
    ASSERT_EQ(m.number_of_faces(), 4 * parent.number_of_faces());
    for (auto v : parent.vertices())
      EXPECT_EQ(m.point(v), parent.point(v));
    for (auto e : parent.edges()) {
      const CGAL_ext::Dart d = parent.halfedge(e);
      const Kq::Point_3 a = parent.point(parent.source(d)), b = parent.point(parent.target(d));
      const Kq::Point_3 mid((a.x() + b.x()) / 2, (a.y() + b.y()) / 2, (a.z() + b.z()) / 2);
      EXPECT_EQ(m.point(CGAL_ext::Vertex_index(parent.number_of_vertices() + e.idx())), mid);
    }
  }
  // Two of them by hand: the midpoint of (1,1,1) and (1,-1,-1) is (1,0,0),
  // and a second-level point lies a quarter of the way along an edge.
  EXPECT_EQ(m.number_of_vertices(), 34u); // 4 + 6, then 10 + 24
  std::size_t found = 0;
  for (auto v : m.vertices())
    found += (m.point(v) == Kq::Point_3(1, 0, 0) || m.point(v) == Kq::Point_3(1, Q(1, 2), Q(1, 2))) ? 1 : 0;
  EXPECT_EQ(found, 2u);
}

// ----------------------------------------------------------------- memory

std::size_t heap_in_use()
{
#ifdef CGAL_EXT_TEST_UNDER_ASAN
  return __sanitizer_get_current_allocated_bytes();
#else
  return mallinfo2().uordblks;
#endif
}

// EPECK points carry the history of their construction. If each level's
// points kept the previous level's alive, the heap per vertex of the result
// would grow with the number of levels (CGAL's EPECK subdivision reaches
// ~1 GB at level 7 that way). Ours resolves each level exactly and drops the
// history: the heap per result vertex stays the same from level 3 to 5.
TEST(SubdivisionExact, EpeckMemoryStaysBounded)
{
  std::vector<double> bytes_per_vertex;
  for (unsigned levels : {3u, 4u, 5u}) {
    const std::size_t before = heap_in_use();
    std::size_t held = 0, vertices = 0;
    {
      auto m = exact_mesh<test::Epeck>(cube());
      S::catmull_clark(m, CGAL_ext::parameters::number_of_iterations(levels));
      vertices = m.number_of_vertices();
      held = heap_in_use() - before;
    }
    bytes_per_vertex.push_back(double(held) / double(vertices));
    SCOPED_TRACE(levels);
    EXPECT_LT(bytes_per_vertex.back(), 4096.0); // a few exact rationals per vertex, not a history
  }
  EXPECT_LT(bytes_per_vertex[2], 1.25 * bytes_per_vertex[0]);
  EXPECT_LT(bytes_per_vertex[1], 1.25 * bytes_per_vertex[0]);
}

// ----------------------------------------------------------------- parallel

#ifdef CGAL_EXT_SUBDIVISION_PARALLEL
template <class Run>
void expect_bit_identical(Run run)
{
  CGAL_ext::Mobius_mesh<Point> serial, parallel;
  run(serial, CGAL::Sequential_tag());
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
    run(parallel, CGAL::Parallel_tag());
  }
  ASSERT_EQ(serial.number_of_vertices(), parallel.number_of_vertices());
  ASSERT_EQ(serial.number_of_faces(), parallel.number_of_faces());
  for (auto v : serial.vertices())
    for (int i = 0; i < 3; ++i) {
      const double a = serial.point(v)[i], b = parallel.point(v)[i];
      ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "vertex " << v.idx();
    }
}

TEST(SubdivisionParallel, BitIdenticalToSerial)
{
  const Soup quads = torus(40, 30, false), tris = torus(40, 30, true);
  auto load = [](const Soup& s, CGAL_ext::Mobius_mesh<Point>& m) {
    CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m);
  };
  const auto np = CGAL_ext::parameters::number_of_iterations(3);
  expect_bit_identical([&](auto& m, auto tag) {
    load(quads, m);
    auto es = CGAL_ext::edge_sharpness_map(m); // semi-sharp and sharp creases
    for (std::size_t e = 0; e < m.number_of_edges(); e += 7)
      es[CGAL_ext::Edge_index(e)] = (e % 2) ? 1.5f : 10.0f;
    S::catmull_clark<decltype(tag)>(m, np.crease_method(CGAL_ext::Crease_method::chaikin));
  });
  expect_bit_identical([&](auto& m, auto tag) {
    load(tris, m);
    S::loop<decltype(tag)>(m, np);
  });
  expect_bit_identical([&](auto& m, auto tag) {
    load(quads, m);
    S::doo_sabin<decltype(tag)>(m, np);
  });
  expect_bit_identical([&](auto& m, auto tag) {
    load(tris, m);
    S::sqrt3<decltype(tag)>(m, np);
  });
}
#endif

} // namespace

} // namespace subdivision_peers_tests
