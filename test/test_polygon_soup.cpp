// Polygon-soup import: counts and topology against the figures stated in the
// test meshes' headers, and each kind of bad input.
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace polygon_soup_tests {

namespace {

using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;

// The smallest Möbius strip: five triangles around a pentagon, each
// consecutive pair sharing an edge; the last pair shares one the same way round.
const std::vector<Point> pentagon_points = {{1.4, 0, 0}, {0.2, 0.6, -0.2}, {-0.9, 0.7, 0.4}, {-0.9, -0.7, -0.4},
                                            {0.2, -0.6, 0.2}};
const std::vector<std::vector<int>> mobius_min_polygons = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}, {3, 4, 0}, {4, 0, 1}};

TEST(PolygonSoup, SmallestMobiusStrip)
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(pentagon_points, mobius_min_polygons, m);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), 5u);
  EXPECT_EQ(m.number_of_edges(), 10u);
  EXPECT_EQ(m.number_of_faces(), 5u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  EXPECT_FALSE(CGAL_ext::is_orientable(m));
  // Consecutive triangles (a,b,c), (b,c,d) share (b,c) in the same direction:
  // every interior edge is a Möbius edge as given.
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 5u);
  EXPECT_EQ(CGAL_ext::orient(m), 1u);
  EXPECT_TRUE(m.is_valid(true));
}

TEST(PolygonSoup, CubeIsClosedOrientable)
{
  const std::vector<Point> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<std::array<std::size_t, 4>> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                         {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(pts, quads, m);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 2);
  EXPECT_TRUE(CGAL_ext::is_closed(m));
  EXPECT_TRUE(CGAL_ext::is_orientable(m));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
}

// A Möbius strip large enough that the import's temporaries and the mesh's
// arrays pass the huge-page threshold (2 MiB: 655 360 corners of 4 bytes,
// 164 864 points of 24). Vertex (i, j) is point i * (m + 1) + j; column
// n - 1 joins column 0 upside down.
TEST(PolygonSoup, LargeMobiusStripMatchesItsSoup)
{
  const std::size_t n = 1024, m = 160;
  auto vertex = [&](std::size_t i, std::size_t j) { return i == n ? m - j : i * (m + 1) + j; };
  std::vector<Point> points;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j <= m; ++j)
      points.emplace_back(double(i), double(j), double(i * j % 7));
  std::vector<std::array<std::size_t, 4>> quads;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j)
      quads.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
  Mesh mesh;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, quads, mesh);
  EXPECT_TRUE(mesh.is_valid(true));
  // V = n(m+1), E = n(m+1) along + nm across, F = nm: a Möbius strip, one
  // border, the m edges of the seam run the same way in both their quads.
  EXPECT_EQ(mesh.number_of_vertices(), n * (m + 1));
  EXPECT_EQ(mesh.number_of_edges(), n * (2 * m + 1));
  EXPECT_EQ(mesh.number_of_faces(), n * m);
  EXPECT_EQ(CGAL_ext::euler_characteristic(mesh), 0);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(mesh), 1u);
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(mesh), m);
  EXPECT_FALSE(CGAL_ext::is_orientable(mesh));
  // Every face runs through its quad's corners in the quad's order.
  for (std::size_t f = 0; f < quads.size(); ++f) {
    std::vector<std::size_t> cycle;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(CGAL_ext::Face_index(std::uint32_t(f)), mesh))
      cycle.push_back(v.idx());
    ASSERT_EQ(cycle.size(), 4u);
    std::rotate(cycle.begin(), std::find(cycle.begin(), cycle.end(), quads[f][0]), cycle.end());
    ASSERT_TRUE(std::equal(cycle.begin(), cycle.end(), quads[f].begin())) << "face " << f;
  }
  for (std::size_t v = 0; v < points.size(); ++v)
    ASSERT_EQ(mesh.point(CGAL_ext::Vertex_index(std::uint32_t(v))), points[v]);
}

// Two polygons of 130 corners glued along all their sides (a closed
// "pillow"): faces longer than a machine word of corners, the second one
// starting inside a word.
TEST(PolygonSoup, LongPolygonsAreWalkedWhole)
{
  const std::size_t n = 130;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons(2);
  for (std::size_t i = 0; i < n; ++i) {
    points.emplace_back(std::cos(0.05 * double(i)), std::sin(0.05 * double(i)), 0.0);
    polygons[0].push_back(i);
    polygons[1].push_back(n - 1 - i);
  }
  Mesh mesh;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, mesh);
  EXPECT_TRUE(mesh.is_valid(true));
  EXPECT_EQ(mesh.number_of_edges(), n);
  EXPECT_EQ(CGAL_ext::euler_characteristic(mesh), 2); // V - E + F = n - n + 2
  EXPECT_TRUE(CGAL_ext::is_closed(mesh));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(mesh), 0u);
  for (std::size_t f = 0; f < 2; ++f) {
    std::vector<std::size_t> cycle;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(CGAL_ext::Face_index(std::uint32_t(f)), mesh))
      cycle.push_back(v.idx());
    std::rotate(cycle.begin(), std::find(cycle.begin(), cycle.end(), polygons[f][0]), cycle.end());
    EXPECT_EQ(cycle, polygons[f]) << "face " << f;
  }
}

} // namespace

namespace {

using CGAL_ext::Soup_error;
using Kind = CGAL_ext::Soup_error::Kind;

// A target mesh that already holds something: failures must leave it as it is.
Mesh prefilled()
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(pentagon_points, mobius_min_polygons, m);
  return m;
}

void expect_untouched(const Mesh& m)
{
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), 5u);
  EXPECT_EQ(m.number_of_edges(), 10u);
  EXPECT_EQ(m.number_of_faces(), 5u);
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0u)), pentagon_points[0]);
}

template <class Points, class Polygons>
Soup_error expect_soup_error(const Points& points, const Polygons& polygons, Kind kind)
{
  Mesh m = prefilled();
  try {
    CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m);
  } catch (const Soup_error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    expect_untouched(m);
    Mesh empty;
    EXPECT_THROW(CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, empty), Soup_error);
    EXPECT_EQ(empty.number_of_vertices(), 0u);
    EXPECT_EQ(empty.number_of_faces(), 0u);
    return e;
  }
  ADD_FAILURE() << "no Soup_error thrown";
  return Soup_error(kind, "", {}, {});
}

const std::vector<Point> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}, {2, 2, 2}};

TEST(PolygonSoupErrors, IndexOutOfRange)
{
  const std::vector<std::vector<int>> polygons = {{0, 1, 2}, {0, 2, 6}};
  const Soup_error e = expect_soup_error(square, polygons, Kind::index_out_of_range);
  EXPECT_EQ(e.polygons(), std::vector<std::size_t>{1});
  EXPECT_NE(std::string(e.what()).find("point 6"), std::string::npos) << e.what();
  const std::vector<std::vector<int>> negative = {{0, 1, -1}};
  expect_soup_error(square, negative, Kind::index_out_of_range);
}

TEST(PolygonSoupErrors, DegenerateAndRepeated)
{
  const std::vector<std::vector<int>> two = {{0, 1, 2}, {2, 3}};
  EXPECT_EQ(expect_soup_error(square, two, Kind::degenerate_polygon).polygons(), std::vector<std::size_t>{1});
  const std::vector<std::vector<int>> repeated = {{0, 1, 2, 1}};
  const Soup_error e = expect_soup_error(square, repeated, Kind::repeated_vertex);
  EXPECT_EQ(e.polygons(), std::vector<std::size_t>{0});
  EXPECT_EQ(e.vertices(), std::vector<std::size_t>{1});
}

TEST(PolygonSoupErrors, EdgeWithThreeFaces)
{
  const std::vector<std::vector<int>> fin = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 3, 4}};
  const Soup_error e = expect_soup_error(square, fin, Kind::non_manifold_edge);
  EXPECT_EQ(e.polygons(), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(e.vertices(), (std::vector<std::size_t>{0, 1}));
}

TEST(PolygonSoupErrors, NonManifoldVertexAndItsSplitting)
{
  // Two triangles touching at point 4 only: a bowtie.
  const std::vector<std::vector<int>> bowtie = {{0, 1, 4}, {2, 3, 4}};
  const Soup_error e = expect_soup_error(square, bowtie, Kind::non_manifold_vertex);
  EXPECT_EQ(e.vertices(), std::vector<std::size_t>{4});
  EXPECT_EQ(e.polygons(), (std::vector<std::size_t>{0, 1}));

  Mesh m;
  const std::size_t added = CGAL_ext::polygon_soup_to_mobius_mesh(
    square, bowtie, m, CGAL_ext::parameters::split_non_manifold_vertices(true));
  EXPECT_EQ(added, 1u);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), 7u); // 6 points + 1 copy of point 4
  EXPECT_EQ(CGAL_ext::connected_components(m).count, 3u); // two triangles and the unused point 5
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(6u)), square[4]);

  // A cone of four triangles whose apex is also the tip of a fifth one.
  const std::vector<std::vector<int>> cone_and_fin = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {4, 5, 2}};
  EXPECT_THROW(
    {
      Mesh n;
      CGAL_ext::polygon_soup_to_mobius_mesh(square, cone_and_fin, n);
    },
    Soup_error);
}

// Three triangles at point 1: polygons 0 and 1 run the same way along their
// shared edge (1, 2), a Möbius edge, and form one fan; polygon 2 touches
// them at point 1 only, a second fan. Splitting gives each fan its own vertex.
TEST(PolygonSoupErrors, SplittingAFanWithAMobiusEdge)
{
  const std::vector<Point> points = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 2, 0}, {2, 1, 0}, {2, 2, 0}};
  const std::vector<std::vector<int>> polygons = {{0, 1, 2}, {2, 3, 1}, {1, 4, 5}};
  for (const bool keep : {false, true}) {
    SCOPED_TRACE(keep ? "keep_orientation" : "oriented");
    Mesh m;
    const std::size_t added = CGAL_ext::polygon_soup_to_mobius_mesh(
      points, polygons, m, CGAL_ext::parameters::split_non_manifold_vertices(true).keep_orientation(keep));
    EXPECT_EQ(added, 1u);
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(m.number_of_vertices(), 7u);
    EXPECT_EQ(m.number_of_faces(), 3u);
    // The two strip triangles agree once oriented; kept as given, they meet
    // along the Möbius edge.
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), keep ? 1u : 0u);
    std::vector<std::vector<std::size_t>> fans;
    for (const CGAL_ext::Vertex_index v : m.vertices()) {
      if (m.point(v) != points[1])
        continue;
      std::vector<std::size_t> faces;
      for (const CGAL_ext::Face_index f : CGAL_ext::faces_around_target(v, m))
        if (f != Mesh::null_face())
          faces.push_back(f.idx());
      std::sort(faces.begin(), faces.end());
      fans.push_back(faces);
    }
    std::sort(fans.begin(), fans.end());
    EXPECT_EQ(fans, (std::vector<std::vector<std::size_t>>{{0, 1}, {2}}));
  }
}

// The vertices a soup of triangles gives once its non-manifold points are
// split, counted from the soup alone: the fans of each point (its triangles,
// joined where two share an edge at it), and one for each unused point.
std::size_t number_of_fans(std::size_t n_points, const std::vector<std::array<int, 3>>& triangles)
{
  auto has = [](const std::array<int, 3>& t, int v) { return std::find(t.begin(), t.end(), v) != t.end(); };
  std::size_t count = 0;
  for (int v = 0; v < int(n_points); ++v) {
    std::vector<std::size_t> around;
    for (std::size_t i = 0; i < triangles.size(); ++i)
      if (has(triangles[i], v))
        around.push_back(i);
    if (around.empty()) {
      ++count;
      continue;
    }
    std::vector<std::size_t> parent(around.size());
    for (std::size_t i = 0; i < parent.size(); ++i)
      parent[i] = i;
    auto root = [&](std::size_t i) {
      while (parent[i] != i)
        i = parent[i];
      return i;
    };
    // Any two corners of a triangle are an edge of it.
    for (std::size_t a = 0; a < around.size(); ++a)
      for (std::size_t b = a + 1; b < around.size(); ++b)
        for (const int w : triangles[around[a]])
          if (w != v && has(triangles[around[b]], w))
            parent[root(a)] = root(b);
    for (std::size_t i = 0; i < parent.size(); ++i)
      count += root(i) == i;
  }
  return count;
}

// Edges along which two triangles of the soup run the same way.
std::size_t number_of_mobius_edges(const std::vector<std::array<int, 3>>& triangles)
{
  std::size_t count = 0;
  for (std::size_t a = 0; a < triangles.size(); ++a)
    for (std::size_t b = a + 1; b < triangles.size(); ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          count += triangles[a][i] == triangles[b][j] && triangles[a][(i + 1) % 3] == triangles[b][(j + 1) % 3];
  return count;
}

// Small soups of triangles on a few points, each triangle in a random
// orientation, so that Möbius edges and vertices of several fans (with
// Möbius edges in them, and fans on the border) are common; a triangle that
// would give an edge a third face, or repeat another's corners, is dropped.
TEST(PolygonSoupErrors, SplittingRandomSoupsGivesAVertexPerFan)
{
  std::mt19937 random(20260311);
  std::size_t with_copies = 0, with_mobius_copies = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n_points = std::uniform_int_distribution<int>(4, 8)(random);
    const int n_tries = std::uniform_int_distribution<int>(2, 9)(random);
    std::vector<Point> points;
    for (int i = 0; i < n_points; ++i)
      points.emplace_back(i, (i * i) % 5, i % 3);
    std::vector<std::array<int, 3>> triangles;
    auto faces_on_edge = [&](int a, int b) {
      std::size_t n = 0;
      for (const auto& t : triangles)
        n += std::find(t.begin(), t.end(), a) != t.end() && std::find(t.begin(), t.end(), b) != t.end();
      return n;
    };
    for (int k = 0; k < n_tries; ++k) {
      std::vector<int> all(std::size_t(n_points), 0);
      std::iota(all.begin(), all.end(), 0);
      std::shuffle(all.begin(), all.end(), random);
      const std::array<int, 3> t = {all[0], all[1], all[2]};
      std::array<int, 3> sorted = t;
      std::sort(sorted.begin(), sorted.end());
      bool ok = faces_on_edge(t[0], t[1]) < 2 && faces_on_edge(t[1], t[2]) < 2 && faces_on_edge(t[2], t[0]) < 2;
      for (std::array<int, 3> u : triangles) {
        std::sort(u.begin(), u.end());
        ok = ok && u != sorted;
      }
      if (ok)
        triangles.push_back(t);
    }
    const std::size_t fans = number_of_fans(points.size(), triangles);
    const std::size_t mobius = number_of_mobius_edges(triangles);
    with_copies += fans > points.size();
    with_mobius_copies += fans > points.size() && mobius > 0;
    for (const bool keep : {false, true}) {
      SCOPED_TRACE("trial " + std::to_string(trial) + (keep ? ", keep_orientation" : ", oriented"));
      Mesh m;
      const std::size_t added = CGAL_ext::polygon_soup_to_mobius_mesh(
        points, triangles, m, CGAL_ext::parameters::split_non_manifold_vertices(true).keep_orientation(keep));
      ASSERT_TRUE(m.is_valid(true));
      EXPECT_EQ(m.number_of_vertices(), fans);
      EXPECT_EQ(added, fans - points.size());
      EXPECT_EQ(m.number_of_faces(), triangles.size());
      if (keep) {
        EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), mobius);
      }
      for (std::size_t v = points.size(); v < m.number_of_vertices(); ++v)
        EXPECT_NE(std::find(points.begin(), points.end(), m.point(CGAL_ext::Vertex_index(std::uint32_t(v)))),
                  points.end());
    }
  }
  // The soups are of the kinds the test is about.
  EXPECT_GT(with_copies, 300u);
  EXPECT_GT(with_mobius_copies, 100u);
}

TEST(PolygonSoupErrors, NonFinitePoint)
{
  std::vector<Point> points = square;
  points[2] = Point(std::nan(""), 0, 0);
  const std::vector<std::vector<int>> polygons = {{0, 1, 2}};
  EXPECT_EQ(expect_soup_error(points, polygons, Kind::non_finite_point).vertices(), std::vector<std::size_t>{2});
  points[2] = Point(0, HUGE_VAL, 0);
  expect_soup_error(points, polygons, Kind::non_finite_point);
}

TEST(PolygonSoupErrors, BadTolerance)
{
  const std::vector<std::vector<int>> polygons = {{0, 1, 2}};
  Mesh m = prefilled();
  EXPECT_THROW(CGAL_ext::polygon_soup_to_mobius_mesh(square, polygons, m, CGAL_ext::parameters::tolerance(-1.0)),
               CGAL_ext::Parameter_error);
  EXPECT_THROW(
    CGAL_ext::polygon_soup_to_mobius_mesh(square, polygons, m, CGAL_ext::parameters::tolerance(std::nan(""))),
    CGAL_ext::Parameter_error);
  expect_untouched(m);
}

// Two triangles of a square given with their own copies of the diagonal's points.
template <class K>
void check_tolerance_is_exact()
{
  using P = typename K::Point_3;
  using FT = typename K::FT;
  const double t = 0.1;
  const double beyond = std::nextafter(t, 1.0);
  for (const auto& [offset, merges] : {std::pair<double, bool>{0.0, true}, {t, true}, {beyond, false}}) {
    SCOPED_TRACE(offset);
    // The second triangle's copy of the shared side (on the y axis) is
    // shifted by `offset` along x, so both copies are exactly `offset` away.
    const std::vector<P> points = {P(0, 0, 0),      P(0, 1, 0),   P(-1, 0.5, 0),
                                   P(offset, 0, 0), P(1, 0.5, 0), P(offset, 1, 0)};
    const std::vector<std::vector<int>> polygons = {{0, 1, 2}, {3, 4, 5}};
    CGAL_ext::Mobius_mesh<P> m;
    CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m, CGAL_ext::parameters::tolerance(FT(t)));
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(m.number_of_vertices(), merges ? 4u : 6u);
    EXPECT_EQ(m.number_of_edges(), merges ? 5u : 6u);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), merges ? 1u : 2u);
    // The first point of a cluster is kept.
    EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0u)), P(0, 0, 0));
  }
}

TEST(PolygonSoupTolerance, ExactAtTheBoundaryDouble) { check_tolerance_is_exact<test::Kd>(); }
TEST(PolygonSoupTolerance, ExactAtTheBoundaryEpick) { check_tolerance_is_exact<test::Epick>(); }
TEST(PolygonSoupTolerance, ExactAtTheBoundaryEpeck) { check_tolerance_is_exact<test::Epeck>(); }

// A distance that is exactly the tolerance with rational coordinates that no
// double holds: only exact arithmetic decides it right.
TEST(PolygonSoupTolerance, ExactWhereDoublesRound)
{
  using P = test::Epeck::Point_3;
  using FT = test::Epeck::FT;
  // The second triangle's copy of the shared side is moved by (1/3, 2/3, 2/3),
  // at squared distance 1/9 + 4/9 + 4/9 = 1 exactly; all other points are far apart.
  const FT third = FT(1) / FT(3);
  const P p0(0, 0, 0), p1(10, 0, 0);
  const test::Epeck::Vector_3 shift(third, 2 * third, 2 * third);
  const std::vector<P> points = {p0, p1, P(5, -10, 0), p0 + shift, p1 + shift, P(5, 10, 0)};
  const std::vector<std::vector<int>> polygons = {{0, 1, 2}, {4, 3, 5}};
  CGAL_ext::Mobius_mesh<P> merged;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, merged, CGAL_ext::parameters::tolerance(FT(1)));
  EXPECT_EQ(merged.number_of_vertices(), 4u);
  EXPECT_EQ(merged.number_of_edges(), 5u);
  CGAL_ext::Mobius_mesh<P> apart;
  const FT just_below = FT(1) - FT(1) / FT(1e30);
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, apart, CGAL_ext::parameters::tolerance(just_below));
  EXPECT_EQ(apart.number_of_vertices(), 6u);
}

TEST(PolygonSoup, PointMapAndArrayPolygons)
{
  // Points as (point, label) pairs read through a property map; polygons as arrays.
  std::vector<std::pair<Point, int>> points;
  for (std::size_t i = 0; i < pentagon_points.size(); ++i)
    points.emplace_back(pentagon_points[i], int(i));
  std::vector<std::array<unsigned, 3>> polygons;
  for (const auto& p : mobius_min_polygons)
    polygons.push_back({unsigned(p[0]), unsigned(p[1]), unsigned(p[2])});
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m,
                                        CGAL_ext::parameters::point_map(CGAL::First_of_pair_property_map<
                                                                        std::pair<Point, int>>()));
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_faces(), 5u);
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(3u)), pentagon_points[3]);
}

TEST(PolygonSoup, AppendsToANonEmptyMesh)
{
  Mesh m = prefilled();
  auto tag = m.add_property_map<CGAL_ext::Vertex_index, int>("v:tag", -1).first;
  tag[CGAL_ext::Vertex_index(0u)] = 5;
  CGAL_ext::polygon_soup_to_mobius_mesh(pentagon_points, mobius_min_polygons, m);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_faces(), 10u);
  EXPECT_EQ(CGAL_ext::connected_components(m).count, 2u);
  EXPECT_EQ(tag[CGAL_ext::Vertex_index(0u)], 5);
  EXPECT_EQ(tag[CGAL_ext::Vertex_index(7u)], -1);
}

} // namespace

// The connectivity builder with CGAL::Parallel_tag writes the arrays the
// serial builder writes, byte for byte, and fails with the same error.
namespace {

namespace ci = CGAL_ext::internal;

struct Builder_output
{
  std::vector<std::uint32_t> target, next, prev, face, vertex_dart, face_halfedge, copies;
  std::vector<std::uint8_t> mobius;
  std::string error;

  bool operator==(const Builder_output& o) const
  {
    return target == o.target && next == o.next && prev == o.prev && face == o.face &&
           vertex_dart == o.vertex_dart && face_halfedge == o.face_halfedge && copies == o.copies &&
           mobius == o.mobius && error == o.error;
  }
};

template <class Tag>
Builder_output build_with(const ci::Face_list& faces, std::uint32_t nv, bool split)
{
  Builder_output r;
  try {
    ci::Connectivity_builder builder(faces.view(nv), Tag());
    const std::size_t ne = builder.number_of_edges(), nf = builder.number_of_faces();
    r.target.resize(2 * ne);
    r.next.resize(2 * ne);
    r.prev.resize(2 * ne);
    r.face.resize(2 * ne);
    r.mobius.resize(ne);
    r.vertex_dart.resize(nv);
    r.face_halfedge.resize(nf);
    const ci::Connectivity_arrays arrays{r.target.data(),      r.next.data(),          r.prev.data(), r.face.data(),
                                         r.vertex_dart.data(), r.face_halfedge.data(), r.mobius.data()};
    for (const ci::Split_vertex& c : builder.build(arrays, split)) {
      r.copies.push_back(c.original);
      r.copies.push_back(c.dart);
    }
  } catch (const CGAL_ext::Soup_error& e) {
    r.error = e.what();
  }
  return r;
}

// A strip of n x m quads closed into a band, every `flip`-th quad listed
// backwards (a Möbius edge on each of its sides that meets a forward one),
// with a border on both sides.
ci::Face_list band_of_quads(std::uint32_t n, std::uint32_t m, std::uint32_t flip)
{
  ci::Face_list faces;
  auto vertex = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * (m + 1) + j; };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < m; ++j) {
      const std::uint32_t q[4] = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
      if ((i * m + j) % flip == 0)
        faces.add({q[3], q[2], q[1], q[0]});
      else
        faces.add(q, q + 4);
    }
  return faces;
}

void expect_same_builds(const std::string& what, const ci::Face_list& faces, std::uint32_t nv, bool split)
{
  SCOPED_TRACE(what);
  const Builder_output s = build_with<CGAL::Sequential_tag>(faces, nv, split);
  const Builder_output p = build_with<CGAL::Parallel_tag>(faces, nv, split);
  EXPECT_TRUE(s == p) << "serial: '" << s.error << "', parallel: '" << p.error << "'";
}

} // namespace

TEST(ConnectivityBuilder, ParallelBuildIsTheSerialBuild)
{
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  tbb::task_arena arena(4);
  arena.execute([] {
    const std::uint32_t n = 300, m = 100, nv = n * (m + 1);
    ci::Face_list band = band_of_quads(n, m, 7);
    const Builder_output built = build_with<CGAL::Sequential_tag>(band, nv, false);
    ASSERT_EQ(built.error, "");
    // 7 does not divide m: forward and backward quads meet across both kinds of edges.
    EXPECT_GT(std::count(built.mobius.begin(), built.mobius.end(), 1), 0);
    expect_same_builds("band", band, nv, false);

    // A third quad on an edge deep inside: the serial build's error.
    ci::Face_list fin = band;
    fin.add({5 * (m + 1) + 7, 5 * (m + 1) + 8, nv});
    expect_same_builds("edge of three faces", fin, nv + 1, false);
    EXPECT_NE(build_with<CGAL::Parallel_tag>(fin, nv + 1, false).error.find("shared by 3"), std::string::npos);

    ci::Face_list repeated = band;
    repeated.add({nv, nv + 1, nv});
    expect_same_builds("repeated vertex", repeated, nv + 2, false);

    // A triangle touching the band at one inner vertex only: refused, or split.
    ci::Face_list touching = band;
    touching.add({200 * (m + 1) + 50, nv, nv + 1});
    expect_same_builds("non-manifold vertex", touching, nv + 2, false);
    expect_same_builds("non-manifold vertex split", touching, nv + 2, true);
    EXPECT_EQ(build_with<CGAL::Parallel_tag>(touching, nv + 2, true).copies.size(), 2u);
  });
}

} // namespace polygon_soup_tests
