// Merging borders: automatic under a tolerance (exact with exact kernels),
// and manual along two chosen border loops with four strategies.
#include "mesh_snapshot.h"
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/merge_borders.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace merge_tests {

namespace {

using Kd = test::Kd;
using Epick = test::Epick;
using Epeck = test::Epeck;

template <class P>
using Mesh = CGAL_ext::Mobius_mesh<P>;

template <class P>
Mesh<P> from_soup(const std::vector<P>& points, const std::vector<std::vector<std::size_t>>& polygons)
{
  Mesh<P> m;
  // The faces as given: the merges keep orientations, and the tests count
  // the Möbius edges they leave.
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m, CGAL_ext::parameters::keep_orientation(true));
  return m;
}

// The quads of a grid of (columns + 1) x (rows + 1) points numbered column
// by column: quad (i, r) has corners (i, r), (i + 1, r), (i + 1, r + 1), (i, r + 1).
inline std::vector<std::vector<std::size_t>> grid_quads(int columns, int rows)
{
  std::vector<std::vector<std::size_t>> quads;
  auto id = [rows](int i, int r) { return std::size_t(i * (rows + 1) + r); };
  for (int i = 0; i < columns; ++i)
    for (int r = 0; r < rows; ++r)
      quads.push_back({id(i, r), id(i + 1, r), id(i + 1, r + 1), id(i, r + 1)});
  return quads;
}

// A rectangle grid of `columns` x `rows` quads bent into a ring of radius 3;
// the cross-section turns by `half_twists` half-turns along the ring. The last
// column is placed exactly on the first column's points (reversed for an odd
// number of half-twists), but as separate vertices: the strip is open, and
// merging its borders closes it.
template <class P>
Mesh<P> twisted_strip(int columns, int rows, int half_twists)
{
  std::vector<P> points;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= columns; ++i) {
    for (int r = 0; r <= rows; ++r) {
      if (i == columns) {
        const int r0 = half_twists % 2 ? rows - r : r;
        points.push_back(points[std::size_t(r0)]);
        continue;
      }
      const double theta = 2 * pi * i / columns, phi = half_twists * theta / 2;
      const double v = -1.0 + 2.0 * r / rows;
      const double radial = 3 + v * std::cos(phi), z = v * std::sin(phi);
      points.emplace_back(radial * std::cos(theta), radial * std::sin(theta), z);
    }
  }
  return from_soup(points, grid_quads(columns, rows));
}

// Half of a box [0,1]² x [z0, z1]: its z = z0 face (`bottom`) or its z = z1
// face, and the four sides; the other end is open. Faces face outward.
// `split` divides each side (and the border loop) into that many segments.
template <class P>
Mesh<P> box_half(bool lower, double z_closed, double z_open, int split = 1)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  std::vector<P> points;
  // The loop around the square, counter-clockwise seen from +z.
  std::vector<std::pair<FT, FT>> loop;
  const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int c = 0; c < 4; ++c)
    for (int s = 0; s < split; ++s) {
      const double* a = corners[c];
      const double* b = corners[(c + 1) % 4];
      loop.emplace_back(FT(a[0]) + (FT(b[0]) - FT(a[0])) * s / split, FT(a[1]) + (FT(b[1]) - FT(a[1])) * s / split);
    }
  const std::size_t n = loop.size();
  for (const auto& [x, y] : loop)
    points.emplace_back(x, y, FT(z_closed));
  for (const auto& [x, y] : loop)
    points.emplace_back(x, y, FT(z_open));
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<std::size_t> cap;
  for (std::size_t i = 0; i < n; ++i)
    cap.push_back(lower ? n - 1 - i : i); // bottom faces -z, top faces +z
  polygons.push_back(cap);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (lower)
      polygons.push_back({i, j, n + j, n + i}); // closed end below the open one
    else
      polygons.push_back({j, i, n + i, n + j}); // closed end above
  }
  return from_soup(points, polygons);
}

template <class P>
void expect_same(const Mesh<P>& a, const Mesh<P>& b)
{
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  ASSERT_EQ(a.number_of_edges(), b.number_of_edges());
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  for (auto v : a.vertices())
    EXPECT_EQ(a.point(v), b.point(v));
  for (auto h : a.halfedges())
    EXPECT_EQ(a.target(h), b.target(h));
}

// ---------------------------------------------------------------------------- strips

template <class P>
void strips(double tolerance)
{
  const int columns = 12, rows = 3;
  for (int twists : {0, 1, 3}) {
    SCOPED_TRACE("half-twists: " + std::to_string(twists));
    Mesh<P> m = twisted_strip<P>(columns, rows, twists);
    ASSERT_EQ(CGAL_ext::euler_characteristic(m), 1); // a disc before merging
    const auto r = CGAL_ext::merge_borders(m, CGAL_ext::parameters::tolerance(tolerance));
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(r.glued_edges, std::size_t(rows));
    EXPECT_EQ(r.merged_vertices, std::size_t(rows + 1));
    EXPECT_EQ(r.mobius_edges, twists % 2 ? std::size_t(rows) : 0u);
    EXPECT_EQ(m.number_of_vertices(), std::size_t(columns * (rows + 1)));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
    EXPECT_EQ(CGAL_ext::is_orientable(m), twists % 2 == 0);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), twists % 2 ? 1u : 2u);
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), twists % 2 ? std::size_t(rows) : 0u);
    EXPECT_EQ(CGAL_ext::connected_components(m).count, 1u);
    // Border length: a Möbius strip's single loop runs along both edges of the strip.
    const auto loops = CGAL_ext::border_cycles(m);
    std::size_t border_edges = 0;
    for (auto d : loops)
      border_edges += CGAL_ext::halfedges_around_face(d, m).size();
    EXPECT_EQ(border_edges, std::size_t(2 * columns));
  }
}

TEST(MergeAuto, StripsWithZeroOneThreeHalfTwistsDouble) { strips<Kd::Point_3>(0.0); }
TEST(MergeAuto, StripsWithZeroOneThreeHalfTwistsEpick) { strips<Epick::Point_3>(1e-9); }
TEST(MergeAuto, StripsWithZeroOneThreeHalfTwistsEpeck) { strips<Epeck::Point_3>(0.0); }

TEST(MergeAuto, NearlyClosedStripNeedsTheTolerance)
{
  Mesh<Kd::Point_3> m = twisted_strip<Kd::Point_3>(10, 2, 1);
  // Move the last column off by 1e-7 along z.
  for (auto v : m.vertices())
    if (v.idx() >= 10 * 3)
      m.point(v) = Kd::Point_3(m.point(v).x(), m.point(v).y(), m.point(v).z() + 1e-7);
  auto copy = m;
  const auto r0 = CGAL_ext::merge_borders(copy, CGAL_ext::parameters::tolerance(1e-8));
  EXPECT_EQ(r0.glued_edges, 0u);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(copy), 1u); // still the open strip
  const auto r1 = CGAL_ext::merge_borders(m, CGAL_ext::parameters::tolerance(1e-6));
  EXPECT_EQ(r1.glued_edges, 2u);
  EXPECT_FALSE(CGAL_ext::is_orientable(m));
}

// ---------------------------------------------------------------------------- tolerance boundary

// Two unit quads side by side, the second shifted right by `gap`.
template <class P>
std::pair<Mesh<P>, Mesh<P>> two_quads(double gap, bool flip_second = false)
{
  std::vector<P> a = {P(-1, 0, 0), P(0, 0, 0), P(0, 1, 0), P(-1, 1, 0)};
  std::vector<P> b = {P(gap, 0, 0), P(1, 0, 0), P(1, 1, 0), P(gap, 1, 0)};
  std::vector<std::vector<std::size_t>> quad = {{0, 1, 2, 3}};
  std::vector<std::vector<std::size_t>> flipped = {{3, 2, 1, 0}};
  return {from_soup(a, quad), from_soup(b, flip_second ? flipped : quad)};
}

template <class P>
void tolerance_boundary(double t)
{
  SCOPED_TRACE("tolerance " + std::to_string(t));
  {
    auto [a, b] = two_quads<P>(t);
    const auto r = CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(t));
    EXPECT_EQ(r.glued_edges, 1u) << "a point at exactly the tolerance merges";
    EXPECT_EQ(a.number_of_vertices(), 6u);
    EXPECT_EQ(a.number_of_edges(), 7u);
    EXPECT_EQ(r.mobius_edges, 0u);
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(a), 0u);
    // Glued vertices keep the first mesh's positions.
    EXPECT_EQ(a.point(CGAL_ext::Vertex_index(1u)), P(0, 0, 0));
    EXPECT_EQ(r.vertex_pairs.size(), 2u);
  }
  {
    auto [a, b] = two_quads<P>(std::nextafter(t, 1.0));
    const auto r = CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(t));
    EXPECT_EQ(r.glued_edges, 0u) << "one ulp beyond the tolerance does not merge";
    EXPECT_EQ(a.number_of_vertices(), 8u);
    EXPECT_EQ(CGAL_ext::connected_components(a).count, 2u);
  }
}

TEST(MergeAuto, ToleranceBoundaryIsExactEpeck)
{
  tolerance_boundary<Epeck::Point_3>(0.1); // 0.1² is not a double
  tolerance_boundary<Epeck::Point_3>(0.5);
  tolerance_boundary<Epeck::Point_3>(0.0); // exact coincidence only
}

TEST(MergeAuto, ToleranceBoundaryIsExactEpick)
{
  tolerance_boundary<Epick::Point_3>(0.1);
  tolerance_boundary<Epick::Point_3>(0.5);
  tolerance_boundary<Epick::Point_3>(0.0);
}

TEST(MergeAuto, ToleranceBoundaryDouble)
{
  tolerance_boundary<Kd::Point_3>(0.1);
  tolerance_boundary<Kd::Point_3>(0.5);
}

TEST(MergeAuto, ExactFtToleranceEpeck)
{
  // Rational gap and tolerance, 1/3: no double could express either.
  using FT = Epeck::FT;
  using P = Epeck::Point_3;
  const FT third = FT(1) / 3;
  Mesh<P> a = from_soup<P>({P(-1, 0, 0), P(0, 0, 0), P(0, 1, 0), P(-1, 1, 0)}, {{0, 1, 2, 3}});
  Mesh<P> b = from_soup<P>({P(third, 0, 0), P(1, 0, 0), P(1, 1, 0), P(third, 1, 0)}, {{0, 1, 2, 3}});
  auto a2 = a;
  EXPECT_EQ(CGAL_ext::merge_borders(a2, b, CGAL_ext::parameters::tolerance(third)).glued_edges, 1u);
  auto a3 = a;
  EXPECT_EQ(CGAL_ext::merge_borders(a3, b, CGAL_ext::parameters::tolerance(third - FT(1) / 1000000000)).glued_edges,
            0u);
}

TEST(MergeAuto, SameWayBordersMakeMobiusEdge)
{
  // The second quad runs the other way round: its border edge on the glue runs
  // the same way as the first's, so the glued edge is a Möbius edge, though
  // the surface (a rectangle) is orientable.
  auto [a, b] = two_quads<Epeck::Point_3>(0.0, true);
  const auto r = CGAL_ext::merge_borders(a, b);
  EXPECT_EQ(r.glued_edges, 1u);
  EXPECT_EQ(r.mobius_edges, 1u);
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(a), 1u);
  EXPECT_TRUE(CGAL_ext::is_orientable(a));
  EXPECT_EQ(CGAL_ext::orient(a), 0u);
}

// ---------------------------------------------------------------------------- halves

template <class P>
void cube_halves()
{
  Mesh<P> lower = box_half<P>(true, 0, 0.5), upper = box_half<P>(false, 1, 0.5);
  ASSERT_EQ(CGAL_ext::number_of_border_cycles(lower), 1u);
  ASSERT_EQ(CGAL_ext::number_of_border_cycles(upper), 1u);
  const auto r = CGAL_ext::merge_borders(lower, upper);
  ASSERT_TRUE(lower.is_valid(true));
  EXPECT_EQ(r.glued_edges, 4u);
  EXPECT_EQ(r.merged_vertices, 4u);
  EXPECT_EQ(lower.number_of_vertices(), 12u);
  EXPECT_EQ(lower.number_of_edges(), 20u);
  EXPECT_EQ(lower.number_of_faces(), 10u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(lower), 2);
  EXPECT_TRUE(CGAL_ext::is_closed(lower));
  EXPECT_TRUE(CGAL_ext::is_orientable(lower));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(lower), 0u); // both halves face outward
}

TEST(MergeAuto, CubeHalvesDouble) { cube_halves<Kd::Point_3>(); }
TEST(MergeAuto, CubeHalvesEpeck) { cube_halves<Epeck::Point_3>(); }

TEST(MergeAuto, HalfedgeEdgeAndFaceMapsAreCarried)
{
  // The merge builds the halfedge and edge correspondences only when such
  // maps exist: check that they still carry every value, the first mesh's
  // on a glued edge.
  using P = Kd::Point_3;
  Mesh<P> a = box_half<P>(true, 0, 0.5), b = box_half<P>(false, 1, 0.5);
  using Ends = std::pair<P, P>;
  auto ends = [](const Mesh<P>& m, CGAL_ext::Edge_index e) {
    const P p = m.point(m.vertex(e, 0)), q = m.point(m.vertex(e, 1));
    return q < p ? Ends(q, p) : Ends(p, q);
  };
  std::map<Ends, int> edge_label;            // the first mesh's label wins
  std::vector<std::vector<int>> face_sides;  // per face (a's, then b's), in cycle order
  std::vector<int> face_label;
  int next = 0;
  for (Mesh<P>* m : {&a, &b}) {
    auto el = m->add_property_map<CGAL_ext::Edge_index, int>("e:label", -1).first;
    auto hl = m->add_property_map<CGAL_ext::Halfedge_index, int>("h:label", -1).first;
    auto fl = m->add_property_map<CGAL_ext::Face_index, int>("f:label", -1).first;
    for (auto e : m->edges()) {
      el[e] = next++;
      edge_label.emplace(ends(*m, e), el[e]);
    }
    for (auto h : m->halfedges())
      hl[h] = next++;
    for (auto f : m->faces()) {
      fl[f] = next++;
      face_label.push_back(fl[f]);
      face_sides.emplace_back();
      for (auto d : CGAL_ext::halfedges_around_face(m->halfedge(f), *m))
        face_sides.back().push_back(hl[d.halfedge()]);
    }
  }
  CGAL_ext::merge_borders(a, b);
  ASSERT_TRUE(a.is_valid(true));
  auto el = a.property_map<CGAL_ext::Edge_index, int>("e:label");
  auto hl = a.property_map<CGAL_ext::Halfedge_index, int>("h:label");
  auto fl = a.property_map<CGAL_ext::Face_index, int>("f:label");
  ASSERT_TRUE(el && hl && fl);
  ASSERT_EQ(a.number_of_faces(), face_label.size());
  for (auto e : a.edges())
    EXPECT_EQ((*el)[e], edge_label.at(ends(a, e)));
  for (auto f : a.faces()) {
    EXPECT_EQ((*fl)[f], face_label[f.idx()]);
    std::vector<int> sides;
    for (auto d : CGAL_ext::halfedges_around_face(a.halfedge(f), a))
      sides.push_back((*hl)[d.halfedge()]);
    EXPECT_EQ(sides, face_sides[f.idx()]);
  }
}

TEST(MergeAuto, KleinBottleHalves)
{
  // Read the figure-8 Klein bottle and split its faces into two halves, each
  // with its own copies of the points.
  std::vector<Epeck::Point_3> points;
  std::vector<std::vector<std::size_t>> faces;
  ASSERT_TRUE(test::read_obj_lines(
    test::data("nonorientable/klein_fig8_24x12_quads.obj"),
    [&](double x, double y, double z) { points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& f) { faces.push_back(f); }, [](const auto&...) {}));
  ASSERT_EQ(faces.size(), 288u);
  std::vector<std::vector<std::size_t>> first(faces.begin(), faces.begin() + 144),
    second(faces.begin() + 144, faces.end());
  Mesh<Epeck::Point_3> a = from_soup(points, first), b = from_soup(points, second);
  // Each half keeps all 288 points; those it does not use are isolated
  // vertices, which merging leaves alone.
  const auto r = CGAL_ext::merge_borders(a, b);
  ASSERT_TRUE(a.is_valid(true));
  EXPECT_EQ(a.number_of_faces(), 288u);
  EXPECT_EQ(a.number_of_edges(), 576u);
  EXPECT_GT(r.glued_edges, 0u);
  std::size_t used = 0;
  for (auto v : a.vertices())
    used += a.is_isolated(v) ? 0 : 1;
  EXPECT_EQ(used, 288u);
  EXPECT_TRUE(CGAL_ext::is_closed(a));
  EXPECT_FALSE(CGAL_ext::is_orientable(a));
  // V - E + F over the surface (isolated vertices aside): a Klein bottle has chi = 0.
  EXPECT_EQ(std::int64_t(used) - 576 + 288, 0);
}

// ---------------------------------------------------------------------------- bad input

TEST(MergeAuto, BadToleranceThrowsAndLeavesInputAlone)
{
  auto [a, b] = two_quads<Kd::Point_3>(0.0);
  const auto a0 = a;
  EXPECT_THROW(CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(-1e-3)), CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(std::nan(""))),
               CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::merge_borders(a, CGAL_ext::parameters::tolerance(-0.5)), CGAL_ext::Parameter_error);
  expect_same(a, a0);
  Mesh<Epeck::Point_3> e = twisted_strip<Epeck::Point_3>(6, 1, 1);
  EXPECT_THROW(CGAL_ext::merge_borders(e, CGAL_ext::parameters::tolerance(Epeck::FT(-1) / 3)),
               CGAL_ext::Parameter_error);
}

TEST(MergeAuto, NonManifoldEdgeIsRefused)
{
  // A book of three pages: two quads of the second mesh both end on the
  // first quad's right edge.
  using P = Kd::Point_3;
  Mesh<P> a = from_soup<P>({P(-1, 0, 0), P(0, 0, 0), P(0, 1, 0), P(-1, 1, 0)}, {{0, 1, 2, 3}});
  Mesh<P> b = from_soup<P>({P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0), P(0, 0, 0), P(0, 0, 1), P(0, 1, 1),
                            P(0, 1, 0)},
                           {{0, 1, 2, 3}, {4, 7, 6, 5}});
  const auto a0 = a, b0 = b;
  try {
    CGAL_ext::merge_borders(a, b);
    FAIL() << "expected a Merge_error";
  } catch (const CGAL_ext::Merge_error& e) {
    EXPECT_EQ(e.kind(), CGAL_ext::Merge_error::Kind::non_manifold_edge);
    // Names the first mesh's edge (v1, v2).
    EXPECT_NE(std::find(e.vertices().begin(), e.vertices().end(), 1u), e.vertices().end()) << e.what();
    EXPECT_NE(std::find(e.vertices().begin(), e.vertices().end(), 2u), e.vertices().end()) << e.what();
  }
  expect_same(a, a0);
  expect_same(b, b0);
}

TEST(MergeAuto, ToleranceLargerThanEdgesIsRefused)
{
  // A strip one unit wide, glued under a tolerance of 2.5: its own border
  // vertices match each other and the glue would collapse faces.
  using P = Kd::Point_3;
  Mesh<P> m = twisted_strip<P>(12, 1, 0);
  const auto m0 = m;
  EXPECT_THROW(CGAL_ext::merge_borders(m, CGAL_ext::parameters::tolerance(2.5)), CGAL_ext::Merge_error);
  expect_same(m, m0);
}

// ---------------------------------------------------------------------------- manual

// The border dart of `m` whose target is at (x, y) in the plane, running as `next_xy` says.
template <class P>
CGAL_ext::Dart border_dart_at(const Mesh<P>& m, double x, double y, double nx, double ny)
{
  for (auto h : m.halfedges()) {
    if (!m.is_border(h))
      continue;
    for (bool flipped : {false, true}) {
      const CGAL_ext::Dart d(h, flipped);
      const auto& p = m.point(m.target(d));
      const auto& q = m.point(m.target(m.next(d)));
      if (p.x() == x && p.y() == y && q.x() == nx && q.y() == ny)
        return d;
    }
  }
  return CGAL_ext::Dart();
}

TEST(MergeManual, FourStrategiesOnCubeHalvesEpeck)
{
  using P = Epeck::Point_3;
  using FT = Epeck::FT;
  const Mesh<P> lower0 = box_half<P>(true, 0, 0.5), upper = box_half<P>(false, 1, 0.625);
  const CGAL_ext::Dart da = border_dart_at(lower0, 0, 0, 1, 0), db = border_dart_at(upper, 0, 0, 1, 0);
  ASSERT_TRUE(da.is_valid() && db.is_valid());
  ASSERT_NE(da.is_flipped(), db.is_flipped()); // both halves face outward: the walks differ

  const std::pair<CGAL_ext::Merge_strategy, FT> cases[] = {{CGAL_ext::Merge_strategy::keep_first, FT(1) / 2},
                                                           {CGAL_ext::Merge_strategy::keep_second, FT(5) / 8},
                                                           {CGAL_ext::Merge_strategy::average, FT(9) / 16}};
  for (const auto& [strategy, z] : cases) {
    SCOPED_TRACE("strategy " + std::to_string(int(strategy)));
    Mesh<P> m = lower0;
    const auto r = CGAL_ext::merge_borders(m, da, upper, db, strategy);
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(r.glued_edges, 4u);
    EXPECT_EQ(r.mobius_edges, 0u);
    EXPECT_EQ(m.number_of_vertices(), 12u);
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 2);
    EXPECT_TRUE(CGAL_ext::is_closed(m));
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
    std::size_t at_z = 0;
    for (auto v : m.vertices())
      at_z += m.point(v).z() == z ? 1 : 0;
    EXPECT_EQ(at_z, 4u); // the glued ring, exactly at the chosen height
  }

  // Walking both loops the same way glues a Möbius band of edges: still a
  // sphere once oriented (the two halves were glued with one reversed).
  Mesh<P> m = lower0;
  const auto r = CGAL_ext::merge_borders(m, da, upper, db.flipped(), CGAL_ext::Merge_strategy::keep_first);
  EXPECT_EQ(r.mobius_edges, 4u);
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 4u);
  EXPECT_TRUE(CGAL_ext::is_orientable(m));
  EXPECT_TRUE(m.is_valid(true));
}

// Traits whose "midpoint" lies a quarter of the way: `average` must use it.
struct Quarter_point_traits : Epeck
{
  struct Construct_midpoint_3
  {
    Epeck::Point_3 operator()(const Epeck::Point_3& p, const Epeck::Point_3& q) const { return p + (q - p) / 4; }
  };
  Construct_midpoint_3 construct_midpoint_3_object() const { return {}; }
};

TEST(MergeManual, AverageUsesTheGivenTraits)
{
  using P = Epeck::Point_3;
  const Mesh<P> lower = box_half<P>(true, 0, 0.5), upper = box_half<P>(false, 1, 0.625);
  const CGAL_ext::Dart da = border_dart_at(lower, 0, 0, 1, 0), db = border_dart_at(upper, 0, 0, 1, 0);
  Mesh<P> m = lower;
  CGAL_ext::merge_borders(m, da, upper, db, CGAL_ext::Merge_strategy::average,
                          CGAL_ext::parameters::geom_traits(Quarter_point_traits()));
  std::size_t at_quarter = 0; // 1/2 + (5/8 - 1/2) / 4
  for (auto v : m.vertices())
    at_quarter += m.point(v).z() == Epeck::FT(17) / 32 ? 1 : 0;
  EXPECT_EQ(at_quarter, 4u);
}

// A value type the library has never heard of, on vertices and faces.
struct Label
{
  int id = -1;
  std::string from;
};

template <class P>
void label(Mesh<P>& m, int base, const std::string& from)
{
  auto vl = m.template add_property_map<CGAL_ext::Vertex_index, Label>("v:label").first;
  for (auto v : m.vertices())
    vl[v] = Label{base + int(v.idx()), from};
  auto fl = m.template add_property_map<CGAL_ext::Face_index, Label>("f:label").first;
  for (auto f : m.faces())
    fl[f] = Label{base + int(f.idx()), from};
}

TEST(MergeManual, UserValueTypesAreCarried)
{
  using P = Epeck::Point_3;
  Mesh<P> lower = box_half<P>(true, 0, 0.5), upper = box_half<P>(false, 1, 0.5);
  label(lower, 0, "lower");
  label(upper, 100, "upper");
  const CGAL_ext::Dart da = border_dart_at(lower, 0, 0, 1, 0), db = border_dart_at(upper, 0, 0, 1, 0);
  for (bool manual : {true, false}) {
    SCOPED_TRACE(manual ? "manual" : "automatic");
    Mesh<P> m = lower;
    const auto r = manual ? CGAL_ext::merge_borders(m, da, upper, db, CGAL_ext::Merge_strategy::keep_first)
                          : CGAL_ext::merge_borders(m, upper, CGAL_ext::parameters::tolerance(0));
    EXPECT_EQ(r.glued_edges, 4u);
    ASSERT_EQ(m.number_of_vertices(), 12u);
    ASSERT_EQ(m.number_of_faces(), 10u);
    const auto vl = m.property_map<CGAL_ext::Vertex_index, Label>("v:label");
    const auto fl = m.property_map<CGAL_ext::Face_index, Label>("f:label");
    ASSERT_TRUE(vl && fl);
    // Faces one to one, the first mesh's first.
    for (std::size_t f = 0; f < 10; ++f) {
      const Label& l = (*fl)[CGAL_ext::Face_index(f)];
      EXPECT_EQ(l.id, f < 5 ? int(f) : 100 + int(f) - 5);
      EXPECT_EQ(l.from, f < 5 ? "lower" : "upper");
    }
    // The 8 vertices of the lower half (4 of them glued, keeping the lower
    // value) and the 4 of the upper half's closed end.
    std::size_t from_lower = 0, from_upper = 0;
    for (auto v : m.vertices()) {
      const Label& l = (*vl)[v];
      const bool is_lower = l.from == "lower";
      (is_lower ? from_lower : from_upper) += 1;
      EXPECT_TRUE(is_lower ? l.id < 8 : l.id >= 100 && l.id < 104) << l.id;
      EXPECT_EQ(m.point(v).z() == 1, !is_lower);
    }
    EXPECT_EQ(from_lower, 8u);
    EXPECT_EQ(from_upper, 4u);
  }
}

TEST(MergeManual, BridgeEqualAndUnequalLoops)
{
  using P = Kd::Point_3;
  const Mesh<P> lower = box_half<P>(true, 0, 0.5);
  for (int split : {1, 2, 3}) {
    SCOPED_TRACE("upper loop of " + std::to_string(4 * split) + " edges");
    const Mesh<P> upper = box_half<P>(false, 1, 0.75, split);
    const double step = 1.0 / split;
    const CGAL_ext::Dart da = border_dart_at(lower, 0, 0, 1, 0), db = border_dart_at(upper, 0, 0, step, 0);
    ASSERT_TRUE(da.is_valid() && db.is_valid());
    Mesh<P> m = lower;
    const auto r = CGAL_ext::merge_borders(m, da, upper, db, CGAL_ext::Merge_strategy::bridge);
    ASSERT_TRUE(m.is_valid(true));
    // 4 and 4s edges: 4 quads where both advance together, 4(s-1) triangles.
    EXPECT_EQ(r.new_faces, std::size_t(4 + 4 * (split - 1)));
    EXPECT_EQ(m.number_of_vertices(), std::size_t(8 + 8 * split));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 2);
    EXPECT_TRUE(CGAL_ext::is_closed(m));
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
    // Nothing moved.
    for (auto v : lower.vertices())
      EXPECT_EQ(m.point(v), lower.point(v));
  }
}

TEST(MergeManual, MismatchedChainsAndBadDartsAreRefused)
{
  using P = Epeck::Point_3;
  Mesh<P> lower = box_half<P>(true, 0, 0.5);
  const Mesh<P> upper = box_half<P>(false, 1, 0.75, 2);
  const auto lower0 = lower;
  const CGAL_ext::Dart da = border_dart_at(lower, 0, 0, 1, 0), db = border_dart_at(upper, 0, 0, 0.5, 0);
  for (auto s : {CGAL_ext::Merge_strategy::keep_first, CGAL_ext::Merge_strategy::keep_second,
                 CGAL_ext::Merge_strategy::average}) {
    try {
      CGAL_ext::merge_borders(lower, da, upper, db, s);
      FAIL() << "expected a Merge_error";
    } catch (const CGAL_ext::Merge_error& e) {
      EXPECT_EQ(e.kind(), CGAL_ext::Merge_error::Kind::mismatched_chains);
    }
  }
  const CGAL_ext::Dart face_dart = lower.halfedge(CGAL_ext::Face_index(0u));
  try {
    CGAL_ext::merge_borders(lower, face_dart, upper, db, CGAL_ext::Merge_strategy::bridge);
    FAIL() << "expected a Merge_error";
  } catch (const CGAL_ext::Merge_error& e) {
    EXPECT_EQ(e.kind(), CGAL_ext::Merge_error::Kind::not_a_border);
  }
  expect_same(lower, lower0);
}

// ---------------------------------------------------------------------------- facing borders

// An open tube around the z axis from z0 to z1, one ring of quads facing
// outward. With `square` the cross-section is the unit square [0,1]² with
// `n` / 4 vertices per side (exact coordinates); otherwise the regular
// n-gon of radius 1.
template <class P>
Mesh<P> tube(int n, double z0, double z1, bool square, bool reversed = false)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  std::vector<std::pair<FT, FT>> ring;
  const double pi = std::acos(-1.0);
  const double corners[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  for (int i = 0; i < n; ++i) {
    if (square) {
      const int side = i / (n / 4), s = i % (n / 4);
      const double* a = corners[side];
      const double* b = corners[side + 1];
      ring.emplace_back(FT(a[0]) + (FT(b[0]) - FT(a[0])) * s / (n / 4), FT(a[1]) + (FT(b[1]) - FT(a[1])) * s / (n / 4));
    } else {
      ring.emplace_back(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n));
    }
  }
  std::vector<P> points;
  for (double z : {z0, z1})
    for (const auto& [x, y] : ring)
      points.emplace_back(x, y, FT(z));
  std::vector<std::vector<std::size_t>> quads;
  for (std::size_t i = 0, un = std::size_t(n); i < un; ++i) {
    std::vector<std::size_t> q = {i, (i + 1) % un, un + (i + 1) % un, un + i};
    if (reversed)
      std::reverse(q.begin(), q.end());
    quads.push_back(q);
  }
  return from_soup(points, quads);
}

// The square [x0, x0 + 1] x [0, 1] at z = 0 in columns x rows quads.
template <class P>
Mesh<P> strip_half(double x0, int columns, int rows)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  std::vector<P> points;
  for (int i = 0; i <= columns; ++i)
    for (int r = 0; r <= rows; ++r)
      points.emplace_back(FT(x0) + FT(i) / columns, FT(r) / rows, FT(0));
  return from_soup(points, grid_quads(columns, rows));
}

template <class P>
std::set<std::string> distinct(const Mesh<P>& m, int coordinate)
{
  std::set<std::string> values;
  for (auto v : m.vertices()) {
    std::ostringstream s;
    s << CGAL::to_double(m.point(v)[coordinate]);
    values.insert(s.str());
  }
  return values;
}

// Two tubes end to end (z 0..1 and 1.5..2.5): the loops that face each other
// are A's upper one and B's lower one, whichever way B's faces turn, and the
// pairing neither twists nor shifts: every glued vertex stays above the
// square's own points.
TEST(MergeFacing, TubesEndToEndEpeck)
{
  using P = Epeck::Point_3;
  using FT = Epeck::FT;
  const int n = 8;
  const Mesh<P> a = tube<P>(n, 0, 1, true);
  for (bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "B's faces reversed" : "both facing outward");
    const Mesh<P> b = tube<P>(n, 1.5, 2.5, true, reversed);
    const CGAL_ext::Border_pairing pairing = CGAL_ext::facing_borders(a, b);
    EXPECT_EQ(pairing.first_edges, std::size_t(n));
    EXPECT_EQ(pairing.second_edges, std::size_t(n));
    EXPECT_EQ(a.point(a.source(pairing.first)).z(), FT(1));
    EXPECT_EQ(b.point(b.source(pairing.second)).z(), FT(3) / 2);
    const std::pair<CGAL_ext::Merge_strategy, FT> cases[] = {{CGAL_ext::Merge_strategy::keep_first, FT(1)},
                                                             {CGAL_ext::Merge_strategy::keep_second, FT(3) / 2},
                                                             {CGAL_ext::Merge_strategy::average, FT(5) / 4}};
    for (const auto& [strategy, z] : cases) {
      SCOPED_TRACE("strategy " + std::to_string(int(strategy)));
      Mesh<P> m = a;
      const auto r = CGAL_ext::merge_borders(m, b, pairing, strategy);
      ASSERT_TRUE(m.is_valid(true));
      EXPECT_EQ(r.glued_edges, std::size_t(n));
      // Faces reversed on one side: the glued edges run the same way.
      EXPECT_EQ(r.mobius_edges, reversed ? std::size_t(n) : 0u);
      EXPECT_EQ(m.number_of_vertices(), std::size_t(3 * n));
      EXPECT_EQ(m.number_of_faces(), std::size_t(2 * n));
      EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
      EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 2u);
      EXPECT_TRUE(CGAL_ext::is_orientable(m));
      std::set<FT> levels;
      for (auto v : m.vertices())
        levels.insert(m.point(v).z());
      EXPECT_EQ(levels, (std::set<FT>{FT(0), z, FT(5) / 2}));
      EXPECT_EQ(distinct(m, 0), distinct(a, 0));
      EXPECT_EQ(distinct(m, 1), distinct(a, 1));
    }
  }
}

// Two halves of a strip side by side (x 0..1 and 1.5..2.5): every strategy
// glues the facing sides, not the whole loops (which would close a sphere).
TEST(MergeFacing, StripHalvesGlueTheirFacingSides)
{
  using P = Epeck::Point_3;
  using FT = Epeck::FT;
  const int columns = 2, rows = 3;
  const Mesh<P> a = strip_half<P>(0, columns, rows), b = strip_half<P>(1.5, columns, rows);
  const CGAL_ext::Border_pairing pairing = CGAL_ext::facing_borders(a, b);
  EXPECT_EQ(pairing.first_edges, std::size_t(rows));
  EXPECT_EQ(pairing.second_edges, std::size_t(rows));
  const std::size_t v_half = (columns + 1) * (rows + 1), f_half = columns * rows;
  const std::pair<CGAL_ext::Merge_strategy, FT> cases[] = {{CGAL_ext::Merge_strategy::keep_first, FT(1)},
                                                           {CGAL_ext::Merge_strategy::keep_second, FT(3) / 2},
                                                           {CGAL_ext::Merge_strategy::average, FT(5) / 4},
                                                           {CGAL_ext::Merge_strategy::bridge, FT(1)}};
  for (const auto& [strategy, x] : cases) {
    SCOPED_TRACE("strategy " + std::to_string(int(strategy)));
    const bool bridge = strategy == CGAL_ext::Merge_strategy::bridge;
    Mesh<P> m = a;
    const auto r = CGAL_ext::merge_borders(m, b, pairing, strategy);
    ASSERT_TRUE(m.is_valid(true));
    // A disc: the rows + 1 facing vertices glued, or rows quads bridging.
    EXPECT_EQ(m.number_of_vertices(), 2 * v_half - (bridge ? 0 : rows + 1));
    EXPECT_EQ(m.number_of_faces(), 2 * f_half + (bridge ? rows : 0));
    EXPECT_EQ(r.new_faces, bridge ? std::size_t(rows) : 0u);
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 1);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
    std::size_t on_the_seam = 0;
    for (auto v : m.vertices())
      on_the_seam += m.point(v).x() == x ? 1 : 0;
    EXPECT_EQ(on_the_seam, std::size_t(rows + 1));
  }
}

// A square beside a Möbius strip: their borders face each other at one
// vertex (or a run of one on either side), which has no edge. The facing
// parts grow to one edge each, so that every manual strategy has edges to
// work on: the bridge joins the two into one surface of chi = 1 + 0 - 1.
TEST(MergeFacing, BordersFacingAtOneVertexGiveChainsOfOneEdgeAtLeast)
{
  using P = Kd::Point_3;
  for (const double gap : {0.25, 0.75, 2.0}) {
    for (const double y : {0.0, 0.3}) {
      SCOPED_TRACE("square at x = 1.25 + " + std::to_string(gap) + ", y = " + std::to_string(y));
      Mesh<P> strip;
      CGAL_ext::make_mobius_strip(strip, 20, 4);
      const double x = 1.25 + gap;
      const Mesh<P> square = from_soup<P>({P(x, y - 0.5, 0), P(x + 1, y - 0.5, 0), P(x + 1, y + 0.5, 0), P(x, y + 0.5, 0)},
                                          {{0, 1, 2, 3}});
      const CGAL_ext::Border_pairing pairing = CGAL_ext::facing_borders(strip, square);
      EXPECT_GE(pairing.first_edges, 1u);
      EXPECT_GE(pairing.second_edges, 1u);
      Mesh<P> bridged = strip;
      CGAL_ext::merge_borders(bridged, square, pairing, CGAL_ext::Merge_strategy::bridge);
      EXPECT_TRUE(bridged.is_valid(true));
      EXPECT_EQ(CGAL_ext::connected_components(bridged).count, 1u);
      EXPECT_EQ(CGAL_ext::euler_characteristic(bridged), 0);
      EXPECT_FALSE(CGAL_ext::is_orientable(bridged));
      for (const auto strategy : {CGAL_ext::Merge_strategy::keep_first, CGAL_ext::Merge_strategy::keep_second,
                                  CGAL_ext::Merge_strategy::average}) {
        Mesh<P> glued = strip;
        try {
          CGAL_ext::merge_borders(glued, square, pairing, strategy);
          EXPECT_TRUE(glued.is_valid(true));
        } catch (const CGAL_ext::Merge_error& e) {
          // Chains of different lengths cannot be glued edge to edge: said so.
          EXPECT_EQ(std::string(e.what()).find("chain has 0"), std::string::npos) << e.what();
        }
      }
    }
  }
}

// The bridge rule: chains of n and m edges get max(n, m) faces, min(n, m)
// quads and |n - m| triangles; here regular 6-, 8- and 8-gon tubes (whole
// loops) and strip sides of 2 and 3 edges (open chains).
TEST(MergeFacing, BridgeQuadsAndTrianglesFollowTheRule)
{
  using P = Kd::Point_3;
  struct Case
  {
    int n, m;
  };
  for (const Case c : {Case{6, 8}, Case{8, 6}, Case{8, 8}, Case{3, 8}}) {
    SCOPED_TRACE(std::to_string(c.n) + " and " + std::to_string(c.m) + " edges");
    Mesh<P> m = tube<P>(c.n, 0, 1, false);
    const Mesh<P> b = tube<P>(c.m, 1.5, 2.5, false);
    const CGAL_ext::Border_pairing pairing = CGAL_ext::facing_borders(m, b);
    ASSERT_EQ(pairing.first_edges, std::size_t(c.n));
    ASSERT_EQ(pairing.second_edges, std::size_t(c.m));
    const auto r = CGAL_ext::merge_borders(m, b, pairing, CGAL_ext::Merge_strategy::bridge);
    ASSERT_TRUE(m.is_valid(true));
    const std::size_t shortest = std::size_t(std::min(c.n, c.m)), longest = std::size_t(std::max(c.n, c.m));
    EXPECT_EQ(r.new_faces, longest);
    std::size_t quads = 0, triangles = 0;
    for (auto f : m.faces())
      (m.degree(f) == 4 ? quads : triangles) += 1;
    EXPECT_EQ(quads, std::size_t(c.n + c.m) + shortest);
    EXPECT_EQ(triangles, longest - shortest);
    EXPECT_EQ(m.number_of_vertices(), std::size_t(2 * (c.n + c.m)));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 2u);
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
  }
  // Open chains: the sides x = 1 (2 edges) and x = 1.5 (3 edges).
  Mesh<P> m = strip_half<P>(0, 2, 2);
  const Mesh<P> b = strip_half<P>(1.5, 2, 3);
  const CGAL_ext::Border_pairing pairing = CGAL_ext::facing_borders(m, b);
  ASSERT_EQ(pairing.first_edges, 2u);
  ASSERT_EQ(pairing.second_edges, 3u);
  const Mesh<P> m0 = m;
  EXPECT_THROW(CGAL_ext::merge_borders(m, b, pairing, CGAL_ext::Merge_strategy::average), CGAL_ext::Merge_error);
  expect_same(m, m0);
  const auto r = CGAL_ext::merge_borders(m, b, pairing, CGAL_ext::Merge_strategy::bridge);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(r.new_faces, 3u);
  std::size_t triangles = 0;
  for (auto f : m.faces())
    triangles += m.degree(f) == 3 ? 1 : 0;
  EXPECT_EQ(triangles, 1u);
  EXPECT_EQ(m.number_of_vertices(), 9u + 12u);
  EXPECT_EQ(m.number_of_faces(), 4u + 6u + 3u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 1);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
}

// aligned_border_loops: whole loops of one's choice, paired without a twist.
TEST(MergeFacing, ChosenLoopsAreAlignedWhole)
{
  using P = Epeck::Point_3;
  const Mesh<P> a = strip_half<P>(0, 2, 2), b = strip_half<P>(1.5, 2, 2);
  const CGAL_ext::Border_pairing pairing =
    CGAL_ext::aligned_border_loops(a, CGAL_ext::border_cycles(a)[0], b, CGAL_ext::border_cycles(b)[0]);
  EXPECT_EQ(pairing.first_edges, 8u);
  EXPECT_EQ(pairing.second_edges, 8u);
  Mesh<P> m = a;
  CGAL_ext::merge_borders(m, b, pairing, CGAL_ext::Merge_strategy::keep_first);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), 10u); // the two squares' borders as one: a sphere
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 2);
  EXPECT_TRUE(CGAL_ext::is_closed(m));
  // A closed mesh has no border to face anything.
  EXPECT_THROW(CGAL_ext::facing_borders(a, from_soup<P>({P(0, 0, 5), P(1, 0, 5), P(0, 1, 5), P(0, 0, 6)},
                                                         {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}})),
               CGAL_ext::Merge_error);
}

} // namespace

// ---------------------------------------------------------------------------- one tolerance rule

// The soup import and merge_borders decide "within the tolerance" by one
// rule: the exact distance against the exact value of the tolerance. The
// cases put a point at exactly the tolerance (merged) and a unit in the last
// place beyond it (not merged), with tolerances whose square no double holds,
// along an axis and along a diagonal whose every coordinate differs.
struct Tolerance_case
{
  double dx, dy, dz, tolerance;
  bool close;
};

std::vector<Tolerance_case> tolerance_cases()
{
  const double t = 0.10000000000000002;
  // m has 40 significant bits, so m, 2m and 3m are doubles and the distance
  // |(m, 2m, 2m)| = 3m is exact, while (3m)² needs about 80 bits.
  const double m = std::ldexp(std::round(std::ldexp(0.1, 40)), -40);
  const double below = std::nextafter(3 * m, 0.0), beyond = std::nextafter(m, 1.0);
  return {{t, 0, 0, t, true},          {t, 0, 0, std::nextafter(t, 0.0), false},
          {0, 0, t, t, true},          {m, 2 * m, 2 * m, 3 * m, true},
          {m, 2 * m, 2 * m, below, false}, {beyond, 2 * m, 2 * m, 3 * m, false},
          {-m, 2 * m, -2 * m, 3 * m, true}};
}

// Two triangles of a square, the second with its own copy of the shared
// side moved by (dx, dy, dz): 4 vertices if the copies merge, 6 if not.
template <class K>
std::size_t soup_vertices_after_merge(const Tolerance_case& c)
{
  using P = typename K::Point_3;
  const std::vector<P> points = {P(0, 0, 0),          P(0, 1, 0),      P(-1, 0.5, 0),
                                 P(c.dx, c.dy, c.dz), P(1, 0.5, 0),    P(c.dx, 1 + c.dy, c.dz)};
  const std::vector<std::vector<int>> polygons = {{0, 1, 2}, {3, 4, 5}};
  Mesh<P> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m, CGAL_ext::parameters::tolerance(c.tolerance).keep_orientation(true));
  return m.number_of_vertices();
}

// The same two sides as the borders of two quads, glued by merge_borders.
template <class K>
std::size_t glued_edges(const Tolerance_case& c)
{
  using P = typename K::Point_3;
  Mesh<P> a = from_soup<P>({P(-1, 0, 0), P(0, 0, 0), P(0, 1, 0), P(-1, 1, 0)}, {{0, 1, 2, 3}});
  const Mesh<P> b = from_soup<P>({P(c.dx, c.dy, c.dz), P(1, 0, 0), P(1, 1, 0), P(c.dx, 1 + c.dy, c.dz)}, {{0, 1, 2, 3}});
  return CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(c.tolerance)).glued_edges;
}

template <class K>
void one_tolerance_rule()
{
  for (const Tolerance_case& c : tolerance_cases()) {
    SCOPED_TRACE(::testing::Message() << std::hexfloat << "offset (" << c.dx << ", " << c.dy << ", " << c.dz
                                      << "), tolerance " << c.tolerance);
    EXPECT_EQ(soup_vertices_after_merge<K>(c), c.close ? 4u : 6u);
    EXPECT_EQ(glued_edges<K>(c), c.close ? 1u : 0u);
  }
}

TEST(ToleranceRule, SoupAndMergeAgreeAtTheBoundaryDouble) { one_tolerance_rule<Kd>(); }
TEST(ToleranceRule, SoupAndMergeAgreeAtTheBoundaryEpick) { one_tolerance_rule<Epick>(); }
TEST(ToleranceRule, SoupAndMergeAgreeAtTheBoundaryEpeck) { one_tolerance_rule<Epeck>(); }
TEST(ToleranceRule, SoupAndMergeAgreeAtTheBoundaryRationals)
{
  one_tolerance_rule<CGAL::Simple_cartesian<CGAL::Exact_rational>>();
}

// ---------------------------------------------------------------------------- in place, against references

namespace in_place {

using P = Kd::Point_3;
using Polygons = std::vector<std::vector<std::size_t>>;

struct Soup
{
  std::vector<P> points;
  Polygons polygons;

  // Appends `o`, its point indices shifted past this soup's points.
  void append(const Soup& o)
  {
    const std::size_t base = points.size();
    points.insert(points.end(), o.points.begin(), o.points.end());
    for (auto polygon : o.polygons) {
      for (std::size_t& i : polygon)
        i += base;
      polygons.push_back(polygon);
    }
  }
};

// The tube of cells i0 <= i < i1 of an n x m torus grid, with its own copies
// of its end columns (the same expression computes a shared column's points
// in both halves, so they coincide exactly). `reversed` flips its faces.
Soup torus_tube(int i0, int i1, int n, int m, bool reversed = false)
{
  Soup s;
  const double pi = std::acos(-1.0);
  for (int i = i0; i <= i1; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * pi * (i % n) / n, v = 2 * pi * j / m, q = 2 + 0.7 * std::cos(v);
      s.points.emplace_back(q * std::cos(u), q * std::sin(u), 0.7 * std::sin(v));
    }
  auto id = [&](int i, int j) { return std::size_t((i - i0) * m + j % m); };
  for (int i = i0; i < i1; ++i)
    for (int j = 0; j < m; ++j) {
      std::vector<std::size_t> quad = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      if (reversed)
        std::reverse(quad.begin(), quad.end());
      s.polygons.push_back(quad);
    }
  return s;
}

// Columns [c0, c1) of a strip of `rows` quads across, its cross-section
// turning by `half_twists` half-turns along a ring of `columns` columns; the
// end columns are its own copies (column `columns` lies on column 0,
// reversed for an odd number of half-twists).
Soup strip_part(int c0, int c1, int columns, int rows, int half_twists)
{
  Soup s;
  const double pi = std::acos(-1.0);
  for (int i = c0; i <= c1; ++i)
    for (int r = 0; r <= rows; ++r) {
      const int ring = i % columns, across = (i == columns && half_twists % 2) ? rows - r : r;
      const double theta = 2 * pi * ring / columns, phi = half_twists * theta / 2;
      const double v = -1.0 + 2.0 * across / rows, radial = 3 + v * std::cos(phi);
      s.points.emplace_back(radial * std::cos(theta), radial * std::sin(theta), v * std::sin(phi));
    }
  auto id = [&](int i, int r) { return std::size_t((i - c0) * (rows + 1) + r); };
  for (int i = c0; i < c1; ++i)
    for (int r = 0; r < rows; ++r)
      s.polygons.push_back({id(i, r), id(i + 1, r), id(i + 1, r + 1), id(i, r + 1)});
  return s;
}

// A tube of `columns` x `m` quads along x whose last column lies on its
// first reflected (row r on row -r): gluing its ends makes a Klein bottle.
Soup flipped_tube(int columns, int m)
{
  Soup s;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= columns; ++i)
    for (int j = 0; j < m; ++j) {
      const int k = i == columns ? (m - j) % m : j;
      s.points.emplace_back(i == columns ? 0.0 : double(i), std::cos(2 * pi * k / m), std::sin(2 * pi * k / m));
    }
  auto id = [&](int i, int j) { return std::size_t(i * m + j % m); };
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j < m; ++j)
      s.polygons.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

struct Topology
{
  std::size_t v = 0, e = 0, f = 0, border_cycles = 0;
  long long chi = 0;
  bool operator==(const Topology& o) const
  {
    return v == o.v && e == o.e && f == o.f && border_cycles == o.border_cycles && chi == o.chi;
  }
};
std::ostream& operator<<(std::ostream& os, const Topology& t)
{
  return os << "V=" << t.v << " E=" << t.e << " F=" << t.f << " chi=" << t.chi << " borders=" << t.border_cycles;
}

Topology topology(const Mesh<P>& m)
{
  return {m.number_of_vertices(), m.number_of_edges(), m.number_of_faces(), CGAL_ext::number_of_border_cycles(m),
          CGAL_ext::euler_characteristic(m)};
}

// CGAL's stitch of the same glue, on a Surface_mesh of the soup.
Topology stitched_by_cgal(const Soup& soup)
{
  CGAL::Surface_mesh<P> sm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, sm);
  CGAL::Polygon_mesh_processing::stitch_borders(sm);
  std::vector<CGAL::Surface_mesh<P>::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(sm, std::back_inserter(cycles));
  const std::size_t v = sm.number_of_vertices(), e = sm.number_of_edges(), f = sm.number_of_faces();
  return {v, e, f, cycles.size(), (long long)(v) - (long long)(e) + (long long)(f)};
}

// The soup import of the glued soup (coincident points merged): the mesh
// the merge made before it glued in place.
Mesh<P> imported_glued(const Soup& soup)
{
  Mesh<P> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(soup.points, soup.polygons, m,
                                        CGAL_ext::parameters::tolerance(0.0).keep_orientation(true));
  return m;
}

using test::snapshot;

// Merges `a` and `b` both ways (two meshes; one mesh holding both) and
// checks each result against the soup import of the glued soup.
std::vector<Mesh<P>> merge_both_ways(const Soup& a, const Soup& b)
{
  Mesh<P> two = from_soup(a.points, a.polygons), one = two;
  const Mesh<P> second = from_soup(b.points, b.polygons);
  one.join(second);
  CGAL_ext::merge_borders(two, second, CGAL_ext::parameters::tolerance(0.0));
  CGAL_ext::merge_borders(one, CGAL_ext::parameters::tolerance(0.0));
  Soup both = a;
  both.append(b);
  const Mesh<P> reference = imported_glued(both);
  for (const Mesh<P>* m : {&two, &one}) {
    EXPECT_TRUE(m->is_valid(true));
    EXPECT_FALSE(m->has_garbage());
    EXPECT_EQ(topology(*m), topology(reference));
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(*m), CGAL_ext::number_of_mobius_edges(reference));
    EXPECT_EQ(CGAL_ext::is_orientable(*m), CGAL_ext::is_orientable(reference));
  }
  return {two, one};
}

} // namespace in_place

TEST(MergeInPlace, TorusHalvesAsStitchedByCgal)
{
  using namespace in_place;
  for (const auto& [n, m] : {std::pair<int, int>(8, 6), std::pair<int, int>(5, 3), std::pair<int, int>(4, 3)}) {
    SCOPED_TRACE(std::to_string(n) + " x " + std::to_string(m));
    const Soup a = torus_tube(0, n / 2, n, m), b = torus_tube(n / 2, n, n, m);
    Soup both = a;
    both.append(b);
    const Topology cgal = stitched_by_cgal(both);
    EXPECT_EQ(cgal, (Topology{std::size_t(n * m), std::size_t(2 * n * m), std::size_t(n * m), 0, 0}));
    for (const Mesh<P>& merged : merge_both_ways(a, b)) {
      EXPECT_EQ(topology(merged), cgal);
      EXPECT_TRUE(CGAL_ext::is_orientable(merged));
      EXPECT_EQ(CGAL_ext::number_of_mobius_edges(merged), 0u);
    }
  }
}

TEST(MergeInPlace, StripHalvesAsStitchedByCgal)
{
  // Without a twist the halves make an annulus: two border loops.
  using namespace in_place;
  const Soup a = strip_part(0, 5, 12, 3, 0), b = strip_part(5, 12, 12, 3, 0);
  Soup both = a;
  both.append(b);
  const Topology cgal = stitched_by_cgal(both);
  EXPECT_EQ(cgal.border_cycles, 2u);
  EXPECT_EQ(cgal.chi, 0);
  for (const Mesh<P>& merged : merge_both_ways(a, b))
    EXPECT_EQ(topology(merged), cgal);
}

TEST(MergeInPlace, ReversedHalfGluesWithMobiusEdges)
{
  // The second tube's faces run the other way: every glued edge is a Möbius
  // edge, and the torus is still orientable (reverse one half).
  using namespace in_place;
  const Soup a = torus_tube(0, 3, 6, 4), b = torus_tube(3, 6, 6, 4, true);
  for (const Mesh<P>& merged : merge_both_ways(a, b)) {
    EXPECT_EQ(topology(merged), (Topology{24, 48, 24, 0, 0}));
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(merged), 8u);
    EXPECT_TRUE(CGAL_ext::is_orientable(merged));
  }
}

TEST(MergeInPlace, MobiusStripFromTwoHalves)
{
  // Half of a once-twisted strip and the other half: one glue is plain, the
  // other has the half-twist. A Möbius strip: chi = 0, one border loop.
  using namespace in_place;
  const Soup a = strip_part(0, 6, 12, 3, 1), b = strip_part(6, 12, 12, 3, 1);
  for (const Mesh<P>& merged : merge_both_ways(a, b)) {
    EXPECT_EQ(merged.number_of_vertices(), 12u * 4u);
    EXPECT_EQ(merged.number_of_faces(), 36u);
    EXPECT_EQ(CGAL_ext::euler_characteristic(merged), 0);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(merged), 1u);
    EXPECT_FALSE(CGAL_ext::is_orientable(merged));
  }
}

TEST(MergeInPlace, CylinderEndsGluedWithAFlipMakeAKleinBottle)
{
  using namespace in_place;
  const Soup tube = flipped_tube(5, 6);
  Mesh<P> m = from_soup(tube.points, tube.polygons);
  ASSERT_EQ(CGAL_ext::number_of_border_cycles(m), 2u);
  const auto r = CGAL_ext::merge_borders(m);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(r.glued_edges, 6u);
  EXPECT_EQ(r.merged_vertices, 6u);
  EXPECT_EQ(m.number_of_vertices(), 30u);
  EXPECT_EQ(m.number_of_faces(), 30u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_TRUE(CGAL_ext::is_closed(m));
  EXPECT_FALSE(CGAL_ext::is_orientable(m));
  const Mesh<P> reference = in_place::imported_glued(tube);
  EXPECT_EQ(in_place::topology(m), in_place::topology(reference));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), CGAL_ext::number_of_mobius_edges(reference));
  // Every input vertex maps to the result vertex at its position.
  ASSERT_EQ(r.vertex_map.size(), tube.points.size());
  for (std::size_t v = 0; v < tube.points.size(); ++v)
    EXPECT_EQ(m.point(r.vertex_map[v]), tube.points[v]);
}

TEST(MergeInPlace, RefusedMergesLeaveTheMeshesUntouched)
{
  using namespace in_place;
  // A quad split along its diagonal (0, 2), and a triangle lying on its first
  // half: gluing the triangle's two borders gives the diagonal a third face.
  const Mesh<P> quad = from_soup<P>({P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0)}, {{0, 1, 2}, {0, 2, 3}});
  Mesh<P> triangle = from_soup<P>({P(0, 0, 0), P(1, 0, 0), P(1, 1, 0)}, {{2, 1, 0}});
  // Maps on both sides: one only the second mesh has must not stay behind.
  auto weight = triangle.add_property_map<CGAL_ext::Vertex_index, int>("v:weight", 7).first;
  weight[CGAL_ext::Vertex_index(1u)] = 3;
  Mesh<P> a = quad;
  auto label = a.add_property_map<CGAL_ext::Edge_index, int>("e:label", -1).first;
  for (auto e : a.edges())
    label[e] = int(e.idx()) * 10;
  auto expect_refused = [](auto merge, Mesh<P>& m) {
    const std::string before = snapshot(m);
    try {
      merge();
      ADD_FAILURE() << "expected a Merge_error";
    } catch (const CGAL_ext::Merge_error& e) {
      EXPECT_EQ(e.kind(), CGAL_ext::Merge_error::Kind::non_manifold_edge) << e.what();
      EXPECT_NE(std::find(e.vertices().begin(), e.vertices().end(), 0u), e.vertices().end()) << e.what();
      EXPECT_NE(std::find(e.vertices().begin(), e.vertices().end(), 2u), e.vertices().end()) << e.what();
    }
    EXPECT_EQ(snapshot(m), before);
  };
  const std::string triangle_before = snapshot(triangle);
  expect_refused([&] { CGAL_ext::merge_borders(a, triangle); }, a);
  EXPECT_EQ(snapshot(triangle), triangle_before);
  Mesh<P> one = a;
  one.join(triangle);
  expect_refused([&] { CGAL_ext::merge_borders(one); }, one);

  // A collapsed face: the strip's own border vertices within the tolerance.
  Mesh<P> strip = twisted_strip<P>(12, 1, 0);
  const std::string strip_before = snapshot(strip);
  try {
    CGAL_ext::merge_borders(strip, CGAL_ext::parameters::tolerance(2.5));
    ADD_FAILURE() << "expected a Merge_error";
  } catch (const CGAL_ext::Merge_error&) {
  }
  EXPECT_EQ(snapshot(strip), strip_before);
}

// A point that is not finite is refused, naming its vertex, before anything
// is compared or glued: the searches for close and facing vertices compare
// distances, which a NaN or an infinity makes meaningless.
TEST(MergeInPlace, PointsThatAreNotFiniteAreRefusedWithTheirVertex)
{
  using namespace in_place;
  for (double bad : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    Mesh<P> a = twisted_strip<P>(12, 1, 0), b = a;
    a.point(CGAL_ext::Vertex_index(3u)) = P(bad, 0, 0);
    const std::string a_before = snapshot(a), b_before = snapshot(b);
    const auto refused = [&](auto call) {
      try {
        call();
        ADD_FAILURE() << "a point at " << bad << " was accepted";
      } catch (const CGAL_ext::Parameter_error& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 3 "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
      }
      EXPECT_EQ(snapshot(a), a_before);
      EXPECT_EQ(snapshot(b), b_before);
    };
    refused([&] { CGAL_ext::merge_borders(a, CGAL_ext::parameters::tolerance(0.5)); });
    refused([&] { CGAL_ext::merge_borders(b, a); });
    refused([&] { CGAL_ext::merge_borders(a, b); });
    refused([&] { CGAL_ext::facing_borders(b, a); });
    const CGAL_ext::Dart loop_a = CGAL_ext::border_cycles(a).front(), loop_b = CGAL_ext::border_cycles(b).front();
    refused([&] { CGAL_ext::aligned_border_loops(a, loop_a, b, loop_b); });
  }
}

TEST(MergeInPlace, RandomSplitsOfClosedSurfacesGlueBack)
{
  // A closed surface's faces dealt at random to two meshes (each with its
  // own copies of the points it uses, the second's faces reversed at
  // random) and merged back, as two meshes and as one: each result must be
  // the soup import of all the faces with coincident points merged.
  using namespace in_place;
  Soup klein;
  ASSERT_TRUE(test::read_obj_lines(
    test::data("nonorientable/klein_fig8_24x12_quads.obj"),
    [&](double x, double y, double z) { klein.points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& f) { klein.polygons.push_back(f); }, [](const auto&...) {}));
  // The closed torus: its last column's corners are the first column's points.
  Soup torus = torus_tube(0, 7, 7, 5);
  torus.points.resize(7 * 5);
  for (auto& polygon : torus.polygons)
    for (std::size_t& v : polygon)
      v %= 7 * 5;
  ASSERT_TRUE(CGAL_ext::is_closed(from_soup(torus.points, torus.polygons)));
  std::size_t split = 0;
  for (const Soup* surface : {&torus, &klein})
    for (unsigned seed = 1; seed <= 40; ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed));
      std::uint32_t state = seed * 2654435761u;
      auto coin = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 16) & 1u;
      };
      Soup part[2];
      std::vector<std::size_t> index[2];
      for (const auto& polygon : surface->polygons) {
        const unsigned k = coin();
        std::vector<std::size_t> face;
        index[k].resize(surface->points.size(), std::size_t(-1));
        for (std::size_t v : polygon) {
          if (index[k][v] == std::size_t(-1)) {
            index[k][v] = part[k].points.size();
            part[k].points.push_back(surface->points[v]);
          }
          face.push_back(index[k][v]);
        }
        if (k == 1 && coin())
          std::reverse(face.begin(), face.end());
        part[k].polygons.push_back(face);
      }
      // A vertex whose faces fall into several fans of one part becomes a
      // vertex per fan, at the same point: the merge must glue them back too.
      Mesh<P> a, b;
      for (unsigned k : {0u, 1u})
        CGAL_ext::polygon_soup_to_mobius_mesh(part[k].points, part[k].polygons, k ? b : a,
                                              CGAL_ext::parameters::split_non_manifold_vertices(true).keep_orientation(true));
      split += a.number_of_vertices() + b.number_of_vertices() - part[0].points.size() - part[1].points.size();
      Soup both = part[0];
      both.append(part[1]);
      const Mesh<P> reference = imported_glued(both);
      ASSERT_TRUE(CGAL_ext::is_closed(reference));
      Mesh<P> two = a, one = a;
      one.join(b);
      const auto r2 = CGAL_ext::merge_borders(two, b);
      const auto r1 = CGAL_ext::merge_borders(one);
      for (const Mesh<P>* m : {&two, &one}) {
        ASSERT_TRUE(m->is_valid(true));
        EXPECT_TRUE(CGAL_ext::is_closed(*m));
        EXPECT_EQ(topology(*m), topology(reference));
        EXPECT_EQ(CGAL_ext::number_of_mobius_edges(*m), CGAL_ext::number_of_mobius_edges(reference));
        EXPECT_EQ(CGAL_ext::is_orientable(*m), CGAL_ext::is_orientable(reference));
      }
      EXPECT_EQ(r1.glued_edges, r2.glued_edges);
      EXPECT_EQ(r1.mobius_edges, r2.mobius_edges);
      EXPECT_EQ(CGAL_ext::number_of_mobius_edges(two),
                CGAL_ext::number_of_mobius_edges(a) + CGAL_ext::number_of_mobius_edges(b) + r2.mobius_edges);
      for (std::size_t v = 0; v < r2.vertex_map.size(); ++v)
        EXPECT_EQ(two.point(r2.vertex_map[v]), v < a.number_of_vertices()
                                                 ? a.point(CGAL_ext::Vertex_index(v))
                                                 : b.point(CGAL_ext::Vertex_index(v - a.number_of_vertices())));
    }
  EXPECT_GT(split, 0u); // the splits were exercised
}

// ---------------------------------------------------------------------------- coincident border vertices

// Soups of separate faces, as a bad exporter writes them: many border
// vertices at one point. The merge groups coincident vertices once, so its
// time and memory stay near-linear in the border however many coincide
// (it used to list every pair of them: 4 000 copies of one triangle took
// 5.7 s and 200 MB). The large cases below would take minutes and
// gigabytes if it were quadratic (no time is asserted); the results are
// checked against an independent brute-force pairing.
namespace coincident {

using P = Kd::Point_3;
using in_place::Soup;

// `n` copies of one triangle, each with its own points; every other copy
// reversed if `alternate`.
Soup copies_of_a_triangle(std::size_t n, bool alternate = false)
{
  Soup s;
  for (std::size_t i = 0; i < n; ++i) {
    s.points.insert(s.points.end(), {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)});
    if (alternate && i % 2)
      s.polygons.push_back({3 * i, 3 * i + 2, 3 * i + 1});
    else
      s.polygons.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return s;
}

// A full fan of `n` separate triangles around the origin (each its own
// component), every other one reversed if `alternate`. Neighbours' copies
// of a rim point come from the same expression: they coincide exactly.
Soup fan(std::size_t n, bool alternate = false)
{
  Soup s;
  const double pi = std::acos(-1.0);
  auto rim = [&](std::size_t i) { return P(std::cos(2 * pi * (i % n) / n), std::sin(2 * pi * (i % n) / n), 0); };
  for (std::size_t i = 0; i < n; ++i) {
    s.points.insert(s.points.end(), {P(0, 0, 0), rim(i), rim(i + 1)});
    if (alternate && i % 2)
      s.polygons.push_back({3 * i, 3 * i + 2, 3 * i + 1});
    else
      s.polygons.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return s;
}

// What the automatic merge pairs, by brute force over every pair of border
// vertices and every pair of border halfedges, from the rule as documented:
// two border vertices match if they are within the tolerance (exactly; of
// different meshes for a two-mesh merge); border halfedge b (s -> t), in
// increasing order, is glued to the one other border edge whose ends match
// or are s and t (not another edge from s to t), unless it has several
// (refused) or that edge is taken (refused).
struct Pairing
{
  bool refused = false;
  std::vector<std::pair<std::size_t, std::size_t>> vertex_pairs, halfedge_pairs;
  std::size_t mobius_edges = 0, ignored_vertex_pairs = 0;
};

Pairing brute_force_pairing(const Mesh<P>& m, std::size_t split, bool self, double tolerance)
{
  using Q = CGAL::Exact_rational;
  auto within = [&](const P& p, const P& q) {
    // Far apart along an axis (beyond any rounding): not within; else exactly.
    if (std::abs(p.x() - q.x()) > tolerance + 1e-6 || std::abs(p.y() - q.y()) > tolerance + 1e-6 ||
        std::abs(p.z() - q.z()) > tolerance + 1e-6)
      return false;
    const Q dx = Q(p.x()) - Q(q.x()), dy = Q(p.y()) - Q(q.y()), dz = Q(p.z()) - Q(q.z());
    return dx * dx + dy * dy + dz * dz <= Q(tolerance) * Q(tolerance);
  };
  std::vector<CGAL_ext::Vertex_index> border_vertices;
  for (auto v : m.vertices())
    if (!m.is_isolated(v) && m.is_border(v))
      border_vertices.push_back(v);
  std::set<std::pair<CGAL_ext::Vertex_index, CGAL_ext::Vertex_index>> matching;
  for (auto u : border_vertices)
    for (auto w : border_vertices)
      if (u < w && (self || (u.idx() < split) != (w.idx() < split)) && within(m.point(u), m.point(w)))
        matching.emplace(u, w);
  auto near = [&](CGAL_ext::Vertex_index u, CGAL_ext::Vertex_index w) {
    return u == w || matching.count({(std::min)(u, w), (std::max)(u, w)}) > 0;
  };
  std::vector<CGAL_ext::Halfedge_index> border;
  for (auto h : m.halfedges())
    if (m.is_border(h))
      border.push_back(h);
  Pairing r;
  std::set<std::size_t> paired;
  for (auto b : border) {
    if (paired.count(b.idx()))
      continue;
    const auto s = m.source(b), t = m.target(b);
    std::vector<std::pair<CGAL_ext::Halfedge_index, bool>> found; // with "runs the same way"
    for (auto c : border) {
      const auto cs = m.source(c), ct = m.target(c);
      const bool same = near(s, cs) && near(t, ct) && !(cs == s && ct == t);
      const bool reverse = near(s, ct) && near(t, cs) && !(ct == s && cs == t);
      EXPECT_FALSE(same && reverse) << "the inputs keep the tolerance below half the edges";
      if (c != b && (same || reverse))
        found.emplace_back(c, same);
    }
    if (found.size() > 1 || (found.size() == 1 && paired.count(found[0].first.idx()))) {
      r.refused = true;
      return r;
    }
    if (found.empty())
      continue;
    const auto [g, same] = found[0];
    paired.insert({b.idx(), g.idx()});
    const auto s2 = same ? m.source(g) : m.target(g), t2 = same ? m.target(g) : m.source(g);
    for (auto [x, y] : {std::make_pair(s, s2), std::make_pair(t, t2)})
      if (x != y)
        r.vertex_pairs.emplace_back((std::min)(x.idx(), y.idx()), (std::max)(x.idx(), y.idx()));
    r.halfedge_pairs.emplace_back(b.idx(), g.idx());
    r.mobius_edges += same ? 1 : 0;
  }
  std::sort(r.vertex_pairs.begin(), r.vertex_pairs.end());
  r.vertex_pairs.erase(std::unique(r.vertex_pairs.begin(), r.vertex_pairs.end()), r.vertex_pairs.end());
  r.ignored_vertex_pairs = matching.size() - r.vertex_pairs.size();
  return r;
}

// The faces of `m` with the vertices of each class of the pairs identified
// (at the lowest member's point), imported as a soup: the mesh the glue
// must make, or a Soup_error where it must refuse.
Mesh<P> soup_with_pairs_identified(const Mesh<P>& m, const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                                   std::vector<std::size_t>& lowest)
{
  lowest.resize(m.number_of_vertices());
  for (std::size_t v = 0; v < lowest.size(); ++v)
    lowest[v] = v;
  auto find = [&](std::size_t v) {
    while (lowest[v] != v)
      v = lowest[v];
    return v;
  };
  for (auto [u, w] : pairs) {
    const std::size_t a = find(u), b = find(w);
    lowest[(std::max)(a, b)] = (std::min)(a, b);
  }
  for (std::size_t v = 0; v < lowest.size(); ++v)
    lowest[v] = find(v);
  // One point per class, numbered in order of the lowest members.
  Soup soup;
  std::vector<std::size_t> point_of(lowest.size());
  for (std::size_t v = 0; v < lowest.size(); ++v)
    if (lowest[v] == v) {
      point_of[v] = soup.points.size();
      soup.points.push_back(m.point(CGAL_ext::Vertex_index(std::uint32_t(v))));
    }
  for (auto f : m.faces()) {
    std::vector<std::size_t> polygon;
    for (auto d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      polygon.push_back(point_of[lowest[m.source(d).idx()]]);
    soup.polygons.push_back(polygon);
  }
  return from_soup(soup.points, soup.polygons);
}

// Merges `a` with `b` (or `a` with itself if `b` is null) and checks the
// result against the brute-force pairing and the soup with its pairs
// identified. Returns whether the merge glued (rather than refused).
bool expect_as_brute_force(Mesh<P> a, const Mesh<P>* b, double tolerance)
{
  Mesh<P> joined = a;
  if (b)
    joined.join(*b);
  const Pairing expected = brute_force_pairing(joined, a.number_of_vertices(), !b, tolerance);
  std::vector<std::size_t> lowest;
  std::optional<Mesh<P>> glued;
  if (!expected.refused) {
    try {
      glued = soup_with_pairs_identified(joined, expected.vertex_pairs, lowest);
    } catch (const CGAL_ext::Soup_error&) {
    }
  }
  const std::string before = test::snapshot(a);
  CGAL_ext::Merge_result r;
  try {
    r = b ? CGAL_ext::merge_borders(a, *b, CGAL_ext::parameters::tolerance(tolerance))
          : CGAL_ext::merge_borders(a, CGAL_ext::parameters::tolerance(tolerance));
  } catch (const CGAL_ext::Merge_error& e) {
    EXPECT_FALSE(glued) << "refused: " << e.what();
    EXPECT_EQ(test::snapshot(a), before);
    return false;
  }
  if (!glued) {
    ADD_FAILURE() << (expected.refused ? "the pairing is ambiguous" : "the glue is not a 2-manifold");
    return true;
  }
  EXPECT_TRUE(a.is_valid(true));
  EXPECT_EQ(r.vertex_pairs, expected.vertex_pairs);
  EXPECT_EQ(r.ignored_vertex_pairs, expected.ignored_vertex_pairs);
  // The pairs found come first; the glue adds border edges that end up between the same two vertices.
  EXPECT_GE(r.halfedge_pairs.size(), expected.halfedge_pairs.size());
  EXPECT_TRUE(r.halfedge_pairs.size() >= expected.halfedge_pairs.size() &&
              std::equal(expected.halfedge_pairs.begin(), expected.halfedge_pairs.end(), r.halfedge_pairs.begin()));
  EXPECT_EQ(r.glued_edges, r.halfedge_pairs.size());
  if (r.glued_edges == expected.halfedge_pairs.size()) {
    EXPECT_EQ(r.mobius_edges, expected.mobius_edges);
  }
  EXPECT_EQ(r.merged_vertices, joined.number_of_vertices() - a.number_of_vertices());
  EXPECT_EQ(r.vertex_map.size(), joined.number_of_vertices());
  for (std::size_t v = 0; v < lowest.size() && v < r.vertex_map.size(); ++v) {
    EXPECT_EQ(r.vertex_map[v], r.vertex_map[lowest[v]]);
    EXPECT_EQ(a.point(r.vertex_map[v]), joined.point(CGAL_ext::Vertex_index(std::uint32_t(lowest[v]))));
  }
  EXPECT_EQ(in_place::topology(a), in_place::topology(*glued));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(a), CGAL_ext::number_of_mobius_edges(*glued));
  EXPECT_EQ(CGAL_ext::is_orientable(a), CGAL_ext::is_orientable(*glued));
  return true;
}

// The triangles of an n x n grid of unit squares (each cut along a random
// diagonal), as separate components: a square at random as one component
// of its two triangles, or each triangle left out, reversed, copied 2 to 4
// times (every other copy reversed) or as it is. Each component has its
// own copies of its points, each moved by +-`jitter` along a random axis.
std::vector<Soup> random_triangles(std::uint32_t seed, int n, double jitter)
{
  std::uint32_t state = seed * 2654435761u + 1;
  auto random = [&state](std::uint32_t k) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % k;
  };
  auto point = [&](int i, int j) {
    double c[3] = {double(i), double(j), 0.25 * ((i * 3 + j) % 2)};
    if (jitter > 0)
      c[random(3)] += random(2) ? jitter : -jitter;
    return P(c[0], c[1], c[2]);
  };
  std::vector<Soup> parts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      // The square's corners counter-clockwise, and its two triangles.
      const int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
      const std::size_t d = random(2);
      const std::vector<std::size_t> triangles[2] = {{d, d + 1, (d + 2) % 4}, {(d + 2) % 4, (d + 3) % 4, d}};
      if (random(5) == 0) {
        Soup square;
        for (const auto& c : corner)
          square.points.push_back(point(c[0], c[1]));
        square.polygons = {triangles[0], triangles[1]};
        parts.push_back(square);
        continue;
      }
      for (const auto& triangle : triangles) {
        const std::uint32_t what = random(8); // 0: left out, 1: reversed, 2: copied
        const std::size_t copies = what == 0 ? 0 : what == 2 ? 2 + random(3) : 1;
        for (std::size_t c = 0; c < copies; ++c) {
          Soup s;
          for (std::size_t k : triangle)
            s.points.push_back(point(corner[k][0], corner[k][1]));
          const bool reversed = (what == 1) != (c % 2 == 1);
          s.polygons.push_back(reversed ? std::vector<std::size_t>{0, 2, 1} : std::vector<std::size_t>{0, 1, 2});
          parts.push_back(s);
        }
      }
    }
  return parts;
}

} // namespace coincident

TEST(MergeCoincident, CopiesOfATriangleAreRefusedAndLeftUnchanged)
{
  // Three or more copies of a triangle give each edge three faces or more:
  // refused, as one mesh or two, the meshes as they were.
  using namespace coincident;
  for (std::size_t n : {3u, 4u})
    for (double tolerance : {0.0, 1e-9}) {
      SCOPED_TRACE(std::to_string(n) + " copies, tolerance " + std::to_string(tolerance));
      const Soup copies = copies_of_a_triangle(n, true);
      Mesh<P> m = from_soup(copies.points, copies.polygons);
      const std::string before = test::snapshot(m);
      try {
        CGAL_ext::merge_borders(m, CGAL_ext::parameters::tolerance(tolerance));
        ADD_FAILURE() << "expected a Merge_error";
      } catch (const CGAL_ext::Merge_error& e) {
        EXPECT_EQ(e.kind(), CGAL_ext::Merge_error::Kind::non_manifold_edge);
        // The message counts every edge the first edge could be glued to.
        EXPECT_NE(std::string(e.what()).find("to " + std::to_string(n - 1) + " border edges"), std::string::npos)
          << e.what();
        EXPECT_EQ(e.vertices().size(), 2 * n); // the edge's ends and theirs
      }
      EXPECT_EQ(test::snapshot(m), before);
      Mesh<P> a = m;
      const Mesh<P> b = m;
      EXPECT_THROW(CGAL_ext::merge_borders(a, b, CGAL_ext::parameters::tolerance(tolerance)), CGAL_ext::Merge_error);
      EXPECT_EQ(test::snapshot(a), before);
      EXPECT_EQ(test::snapshot(b), before);
    }
}

TEST(MergeCoincident, TwentyThousandCopiesOfATriangleAreRefusedInNearLinearTime)
{
  // 60 000 border vertices at three points: listing their pairs, as the
  // merge once did, would take 6 * 10^8 of them (gigabytes, minutes); grouped,
  // they are refused at once.
  using namespace coincident;
  const std::size_t n = 20000;
  const Soup copies = copies_of_a_triangle(n);
  Mesh<P> m = from_soup(copies.points, copies.polygons);
  const std::string before = test::snapshot(m);
  try {
    CGAL_ext::merge_borders(m);
    ADD_FAILURE() << "expected a Merge_error";
  } catch (const CGAL_ext::Merge_error& e) {
    EXPECT_EQ(e.kind(), CGAL_ext::Merge_error::Kind::non_manifold_edge);
    EXPECT_NE(std::string(e.what()).find("could be glued to 19999 border edges"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("an edge takes at most two faces"), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::snapshot(m), before);
}

TEST(MergeCoincident, TwoCopiesOfATriangleCloseIntoAPillow)
{
  using namespace coincident;
  for (bool alternate : {false, true}) {
    const Soup copies = copies_of_a_triangle(2, alternate);
    Mesh<P> m = from_soup(copies.points, copies.polygons);
    const auto r = CGAL_ext::merge_borders(m);
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(in_place::topology(m), (in_place::Topology{3, 3, 2, 0, 2}));
    EXPECT_EQ(r.glued_edges, 3u);
    EXPECT_EQ(r.merged_vertices, 3u);
    EXPECT_EQ(r.ignored_vertex_pairs, 0u);
    // The same copies face the same way: the pillow has Möbius edges.
    EXPECT_EQ(r.mobius_edges, alternate ? 0u : 3u);
  }
}

TEST(MergeCoincident, FanOfSeparateTrianglesGluesIntoADisc)
{
  // 2 000 triangles around one centre, each a component of its own: the
  // 2 000 copies of the centre coincide, and each spoke glues to the one
  // neighbour that shares it. A disc with the centre inside: V = n + 1,
  // E = 2n, F = n, one border loop, chi = 1. With every other triangle
  // reversed (and a tolerance), the spokes are Möbius edges and the disc is
  // still orientable.
  using namespace coincident;
  const std::size_t n = 2000;
  for (const auto& [alternate, tolerance] : {std::make_pair(false, 0.0), std::make_pair(true, 1e-9)}) {
    SCOPED_TRACE(std::string(alternate ? "alternate" : "same") + " orientations");
    const Soup soup = fan(n, alternate);
    Mesh<P> m = from_soup(soup.points, soup.polygons);
    const auto r = CGAL_ext::merge_borders(m, CGAL_ext::parameters::tolerance(tolerance));
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(in_place::topology(m), (in_place::Topology{n + 1, 2 * n, n, 1, 1}));
    EXPECT_TRUE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(r.glued_edges, n);
    EXPECT_EQ(r.mobius_edges, alternate ? n : 0u);
    EXPECT_EQ(r.merged_vertices, 2 * n - 1);
    // n(n - 1)/2 pairs of centre copies match, and n pairs of rim copies;
    // each spoke identifies one pair of each.
    EXPECT_EQ(r.vertex_pairs.size(), 2 * n);
    EXPECT_EQ(r.ignored_vertex_pairs, n * (n - 1) / 2 + n - 2 * n);
    ASSERT_EQ(r.vertex_map.size(), 3 * n);
    for (std::size_t v = 0; v < 3 * n; ++v)
      ASSERT_EQ(m.point(r.vertex_map[v]), soup.points[v]);
  }
}

TEST(MergeCoincident, RandomTriangleSoupsAsByBruteForce)
{
  // Separate triangles of a grid, some reversed, some copied (refused), some
  // left out, merged as one mesh and as two, with coincident copies of the
  // points (tolerance 0) and with copies moved apart by up to 0.1 (tolerance
  // 0.1, at the boundary: two copies moved 0.05 apart each way may be just
  // within or just beyond it).
  using namespace coincident;
  std::size_t merged = 0, refused = 0;
  for (double jitter : {0.0, 0.05})
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", jitter " + std::to_string(jitter));
      const std::vector<Soup> parts = random_triangles(seed, 3, jitter);
      Mesh<P> one, a, b;
      for (std::size_t k = 0; k < parts.size(); ++k) {
        const Mesh<P> part = from_soup(parts[k].points, parts[k].polygons);
        one.join(part);
        (k % 3 == seed % 3 ? b : a).join(part);
      }
      for (const Mesh<P>* second : {static_cast<const Mesh<P>*>(nullptr), static_cast<const Mesh<P>*>(&b)})
        ++(expect_as_brute_force(second ? a : one, second, 2 * jitter) ? merged : refused);
    }
  // Both outcomes were exercised.
  EXPECT_GT(merged, 20u);
  EXPECT_GT(refused, 20u);
}

} // namespace merge_tests
