// Shape generators: closed-form counts, and the test meshes in
// test/data/nonorientable as an outside reference.
#include "test_util.h"
#include "topology_checks.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Gmpq.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace generators_tests {

namespace {

using namespace topology_checks;
namespace X = CGAL_ext;
using Kd_mesh = X::Mobius_mesh<test::Kd::Point_3>;
using Epeck_mesh = X::Mobius_mesh<test::Epeck::Point_3>;
using Gmpq_mesh = X::Mobius_mesh<CGAL::Simple_cartesian<CGAL::Gmpq>::Point_3>;

// ---------------------------------------------------------------- expected figures

// Band of a columns around and c rows across: a (c+1) vertices; a (c+1)
// edges along and a c across (plus a c diagonals with triangles); one loop
// of 2a edges if the weld mirrors the band, two of a edges otherwise.
Expected band(std::size_t a, std::size_t c, int half_twists, bool quads)
{
  const bool odd = half_twists % 2 != 0;
  return {a * (c + 1), quads ? a * (2 * c + 1) : a * (3 * c + 1), quads ? a * c : 2 * a * c, 0, false,
          odd ? std::size_t(1) : std::size_t(2), !odd};
}
// Closed grid of nu x nv quads: one vertex and two edges per quad.
Expected torus(std::size_t nu, std::size_t nv) { return {nu * nv, 2 * nu * nv, nu * nv, 0, true, 0, true}; }
Expected klein(std::size_t nu, std::size_t nv) { return {nu * nv, 2 * nu * nv, nu * nv, 0, true, 0, false}; }
// 3 k x k sector grids: (k+1)^2 points each; the centre is shared by three,
// each of the 3 radii's k points (without the centre) by two, and the 6k
// border points are welded in antipodal pairs. Each quad has 4 sides and
// every edge 2 sides, so E = 2F.
Expected projective_plane(std::size_t k)
{
  const std::size_t points = 3 * (k + 1) * (k + 1) - 2 - 3 * k - 3 * k;
  return {points, 6 * k * k, 3 * k * k, 1, true, 0, false};
}

// ================================================================ generators

template <class Mesh>
void check_bands()
{
  for (std::size_t a : {3, 4, 5, 8, 13})
    for (std::size_t c : {1, 2, 3, 4})
      for (int t : {-3, -1, 0, 1, 2, 3, 4, 5})
        for (bool quads : {true, false}) {
          SCOPED_TRACE("band " + std::to_string(a) + "x" + std::to_string(c) + " twists " + std::to_string(t) +
                       (quads ? " quads" : " triangles"));
          Mesh m;
          const X::Dart d = X::make_mobius_strip(m, a, c, t, 1.0, 0.5, quads);
          expect_topology(m, band(a, c, t, quads));
          // Faces come out alike; only the weld of a mirrored band is Möbius.
          EXPECT_EQ(X::number_of_mobius_edges(m), t % 2 != 0 ? c : 0u);
          EXPECT_EQ(same_direction_edges(m), X::number_of_mobius_edges(m));
          ASSERT_TRUE(m.is_valid(d));
          EXPECT_TRUE(m.is_border(d));
          EXPECT_EQ(m.target(d), X::Vertex_index(0u));
        }
}

TEST(Generators, MobiusStripsAndAnnuliDouble) { check_bands<Kd_mesh>(); }
TEST(Generators, MobiusStripsAndAnnuliEpeck) { check_bands<Epeck_mesh>(); }

template <class Mesh>
void check_closed_grids()
{
  for (std::size_t nu : {3, 4, 5, 9})
    for (std::size_t nv : {3, 4, 7, 8}) {
      SCOPED_TRACE(std::to_string(nu) + "x" + std::to_string(nv));
      Mesh k;
      const X::Dart dk = X::make_klein_bottle(k, nu, nv);
      expect_topology(k, klein(nu, nv));
      EXPECT_EQ(X::number_of_mobius_edges(k), nv);
      EXPECT_EQ(same_direction_edges(k), nv);
      EXPECT_EQ(k.face(dk), X::Face_index(0u));
      EXPECT_EQ(k.source(dk), X::Vertex_index(0u));
      EXPECT_EQ(k.target(dk), X::Vertex_index(std::uint32_t(nv))); // vertex (1, 0)

      Mesh t;
      const X::Dart dt = X::make_torus(t, nu, nv, 1.0, 0.3);
      expect_topology(t, torus(nu, nv));
      EXPECT_EQ(X::number_of_mobius_edges(t), 0u);
      EXPECT_EQ(same_direction_edges(t), 0u);
      EXPECT_EQ(t.face(dt), X::Face_index(0u));
    }
}

TEST(Generators, KleinBottleAndTorusDouble) { check_closed_grids<Kd_mesh>(); }
TEST(Generators, KleinBottleAndTorusEpeck) { check_closed_grids<Epeck_mesh>(); }

template <class Mesh>
void check_projective_planes()
{
  for (std::size_t k : {1, 2, 3, 4, 6, 9}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    Mesh m;
    const X::Dart d = X::make_projective_plane(m, k);
    expect_topology(m, projective_plane(k));
    // The 3k welded border edges are the Möbius ones: antipodal arcs run the
    // same way round the circle.
    EXPECT_EQ(X::number_of_mobius_edges(m), 3 * k);
    EXPECT_EQ(same_direction_edges(m), 3 * k);
    // The centre of the disk: degree 3, at Bryant-Kusner's (0, 0, -2)
    // (g = (0, 0, -1/2) at w = 0, then divided by |g|^2 = 1/4).
    const X::Vertex_index centre = m.source(d);
    EXPECT_EQ(m.degree(centre), 3u);
    EXPECT_NEAR(CGAL::to_double(m.point(centre).x()), 0.0, 1e-15);
    EXPECT_NEAR(CGAL::to_double(m.point(centre).y()), 0.0, 1e-15);
    EXPECT_NEAR(CGAL::to_double(m.point(centre).z()), -2.0, 1e-15);
  }
}

TEST(Generators, ProjectivePlaneDouble) { check_projective_planes<Kd_mesh>(); }
TEST(Generators, ProjectivePlaneEpeck) { check_projective_planes<Epeck_mesh>(); }

TEST(Generators, EverySmallResolution)
{
  // Minimal resolutions are where welds by index can go wrong (a cell
  // meeting itself, two cells sharing a side twice): try them all.
  for (std::size_t a = 3; a <= 9; ++a)
    for (std::size_t c = 1; c <= 5; ++c)
      for (int t = 0; t <= 3; ++t)
        for (bool quads : {true, false}) {
          Kd_mesh m;
          X::make_mobius_strip(m, a, c, t, 1.0, 0.5, quads);
          SCOPED_TRACE("band " + std::to_string(a) + "x" + std::to_string(c) + " twists " + std::to_string(t));
          expect_topology(m, band(a, c, t, quads));
        }
  for (std::size_t nu = 3; nu <= 9; ++nu)
    for (std::size_t nv = 3; nv <= 9; ++nv) {
      SCOPED_TRACE(std::to_string(nu) + "x" + std::to_string(nv));
      Kd_mesh k, t;
      X::make_klein_bottle(k, nu, nv);
      expect_topology(k, klein(nu, nv));
      X::make_torus(t, nu, nv);
      expect_topology(t, torus(nu, nv));
    }
  for (std::size_t k = 1; k <= 12; ++k) {
    SCOPED_TRACE("k = " + std::to_string(k));
    Kd_mesh m;
    X::make_projective_plane(m, k);
    expect_topology(m, projective_plane(k));
  }
}

TEST(Generators, HemiCube)
{
  // k = 1: three squares on four vertices, each pair of squares sharing two
  // edges; every vertex has degree 3.
  Kd_mesh m;
  X::make_projective_plane(m, 1);
  ASSERT_EQ(m.number_of_vertices(), 4u);
  for (X::Vertex_index v : m.vertices())
    EXPECT_EQ(m.degree(v), 3u);
  for (X::Face_index f : m.faces()) {
    std::set<X::Face_index> across;
    for (X::Face_index g : faces_around_face(f, m))
      across.insert(g);
    EXPECT_EQ(across.size(), 2u);
    EXPECT_EQ(across.count(f), 0u);
  }
}

TEST(Generators, BoysSurfaceGeometry)
{
  // Bryant and Kusner's Boy's surface is symmetric under a rotation by 120
  // degrees about the z axis: the rotated point of every vertex is a vertex.
  Kd_mesh m;
  X::make_projective_plane(m, 5);
  const double pi = std::acos(-1.0);
  const double c = std::cos(2 * pi / 3), s = std::sin(2 * pi / 3);
  for (X::Vertex_index v : m.vertices()) {
    const test::Kd::Point_3& p = m.point(v);
    const test::Kd::Point_3 q(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z());
    double closest = HUGE_VAL;
    for (X::Vertex_index w : m.vertices())
      closest = (std::min)(closest, CGAL::squared_distance(q, m.point(w)));
    EXPECT_LT(std::sqrt(closest), 1e-12) << v;
  }
  // Antipodal points of the disk's border have one image, so the weld by
  // index is also a weld in space.
  for (double t : {0.0, 0.1, 0.7, 1.3, 2.9}) {
    const auto a = X::internal::boy_surface_point(std::polar(1.0, t));
    const auto b = X::internal::boy_surface_point(std::polar(1.0, t + pi));
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(a[i], b[i], 1e-12);
  }
}

TEST(Generators, GmpqKleinBottle)
{
  Gmpq_mesh m;
  X::make_klein_bottle(m, 6, 4);
  expect_topology(m, klein(6, 4));
  EXPECT_GE(X::orient(m), 1u);
  EXPECT_TRUE(m.is_valid(true));
  // Same points as in double: the coordinates are computed once in double.
  Kd_mesh d;
  X::make_klein_bottle(d, 6, 4);
  for (X::Vertex_index v : m.vertices()) {
    EXPECT_EQ(CGAL::to_double(m.point(v).x()), d.point(v).x());
    EXPECT_EQ(CGAL::to_double(m.point(v).z()), d.point(v).z());
  }
}

TEST(Generators, ExactKernelGetsTheDoublePoints)
{
  Epeck_mesh e;
  Kd_mesh d;
  X::make_projective_plane(e, 4);
  X::make_projective_plane(d, 4);
  ASSERT_EQ(e.number_of_vertices(), d.number_of_vertices());
  for (X::Vertex_index v : d.vertices())
    EXPECT_EQ(test::Epeck::Point_3(d.point(v).x(), d.point(v).y(), d.point(v).z()), e.point(v));
}

// The test meshes were written independently: same points (to their 9
// decimals) and same polygons, one for one.
template <class Build>
void expect_same_as_file(const std::string& file, Build build)
{
  SCOPED_TRACE(file);
  const Obj obj = read_obj(test::data("nonorientable/" + file));
  Kd_mesh m;
  build(m);
  ASSERT_EQ(m.number_of_vertices(), obj.points.size());
  ASSERT_EQ(m.number_of_faces(), obj.polygons.size());
  for (X::Vertex_index v : m.vertices())
    EXPECT_LT(std::sqrt(CGAL::squared_distance(m.point(v), obj.points[v.idx()])), 1e-8) << v;
  const auto cycles = face_cycles(m);
  for (std::size_t p = 0; p < obj.polygons.size(); ++p)
    EXPECT_TRUE(same_cycle(cycles[p], std::vector<std::uint32_t>(obj.polygons[p].begin(), obj.polygons[p].end())))
      << "polygon " << p;
  expect_topology(m, expected_from_header(obj));
}

TEST(Generators, MatchTheTestMeshes)
{
  expect_same_as_file("klein_fig8_24x12_quads.obj", [](Kd_mesh& m) { X::make_klein_bottle(m, 24, 12, 2.0); });
  expect_same_as_file("torus_24x12_quads.obj", [](Kd_mesh& m) { X::make_torus(m, 24, 12, 2.0, 0.7); });
  expect_same_as_file("mobius_20x4_quads.obj", [](Kd_mesh& m) { X::make_mobius_strip(m, 20, 4, 1, 1.0, 0.8); });
  expect_same_as_file("mobius_20x4_tris.obj",
                      [](Kd_mesh& m) { X::make_mobius_strip(m, 20, 4, 1, 1.0, 0.8, false); });
}

TEST(Generators, BoysSurfaceHasTheTestMeshCounts)
{
  const Obj obj = read_obj(test::data("nonorientable/boys_surface_quads.obj"));
  Kd_mesh m;
  X::make_projective_plane(m, 6);
  expect_topology(m, expected_from_header(obj));
}

TEST(Generators, BorderWalkOfMobiusStrip)
{
  for (int t : {1, 3, -1, 2, 4})
    for (bool quads : {true, false}) {
      SCOPED_TRACE("twists " + std::to_string(t));
      const std::size_t a = 7, c = 3;
      Kd_mesh m;
      X::make_mobius_strip(m, a, c, t, 1.0, 0.5, quads);
      std::set<X::Edge_index> border_edges;
      for (X::Edge_index e : m.edges())
        if (m.is_border(e))
          border_edges.insert(e);
      ASSERT_EQ(border_edges.size(), 2 * a);
      const auto loops = X::border_cycles(m);
      ASSERT_EQ(loops.size(), t % 2 != 0 ? 1u : 2u);
      std::multiset<X::Edge_index> walked;
      std::set<X::Vertex_index> vertices;
      std::size_t flipped = 0;
      for (X::Dart start : loops) {
        std::size_t length = 0;
        for (X::Dart d : halfedges_around_face(start, m)) {
          EXPECT_TRUE(m.is_border(d));
          EXPECT_EQ(m.source(m.next(d)), m.target(d));
          walked.insert(m.edge(d));
          vertices.insert(m.target(d));
          flipped += d.is_flipped() ? 1 : 0;
          ASSERT_LE(++length, 2 * a);
        }
        EXPECT_EQ(length, loops.size() == 1 ? 2 * a : a);
      }
      EXPECT_EQ(walked, std::multiset<X::Edge_index>(border_edges.begin(), border_edges.end()));
      EXPECT_EQ(vertices.size(), 2 * a);
      // With the faces alike, the single loop of a Möbius strip meets its
      // border halfedges running both ways; an annulus's loops do not.
      if (t % 2 != 0)
        EXPECT_GT(flipped, 0u);
      else
        EXPECT_EQ(flipped, 0u);
    }
}

TEST(Generators, AppendToAMesh)
{
  Kd_mesh m;
  X::make_torus(m, 5, 4);
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  const X::Dart d = X::make_mobius_strip(m, 6, 2);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), nv + 6 * 3);
  EXPECT_EQ(m.number_of_edges(), ne + 6 * 5);
  EXPECT_EQ(m.number_of_faces(), nf + 6 * 2);
  EXPECT_TRUE(m.is_border(d));
  EXPECT_EQ(m.target(d), X::Vertex_index(std::uint32_t(nv)));
  const X::Dart k = X::make_klein_bottle(m, 3, 3);
  EXPECT_EQ(m.face(k), X::Face_index(std::uint32_t(nf + 12)));
  EXPECT_EQ(X::connected_components(m).count, 3u);
  EXPECT_EQ(X::orientable_components(m), (std::vector<bool>{true, false, false}));
}

TEST(Generators, BadParametersThrowAndLeaveTheMeshAlone)
{
  Kd_mesh m;
  X::make_torus(m, 3, 3);
  const Kd_mesh before = m;
  auto unchanged = [&] {
    EXPECT_EQ(m.number_of_vertices(), before.number_of_vertices());
    EXPECT_EQ(m.number_of_edges(), before.number_of_edges());
    EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
    EXPECT_TRUE(m.is_valid(true));
  };
  EXPECT_THROW(X::make_mobius_strip(m, 2, 3), X::Parameter_error);
  EXPECT_THROW(X::make_mobius_strip(m, 5, 0), X::Parameter_error);
  EXPECT_THROW(X::make_mobius_strip(m, 5, 2, 1, 0.0), X::Parameter_error);
  EXPECT_THROW(X::make_mobius_strip(m, 5, 2, 1, 1.0, -0.5), X::Parameter_error);
  EXPECT_THROW(X::make_mobius_strip(m, 5, 2, 1, std::nan(""), 0.5), X::Parameter_error);
  EXPECT_THROW(X::make_mobius_strip(m, 5, 2, 1, 1.0, HUGE_VAL), X::Parameter_error);
  EXPECT_THROW(X::make_klein_bottle(m, 2, 5), X::Parameter_error);
  EXPECT_THROW(X::make_klein_bottle(m, 5, 2), X::Parameter_error);
  EXPECT_THROW(X::make_torus(m, 3, 2), X::Parameter_error);
  EXPECT_THROW(X::make_torus(m, 3, 3, 1.0, 0.0), X::Parameter_error);
  EXPECT_THROW(X::make_projective_plane(m, 0), X::Parameter_error);
  // Too many elements for 32-bit indices: refused before any allocation.
  EXPECT_THROW(X::make_torus(m, std::size_t(1) << 20, std::size_t(1) << 20), X::Parameter_error);
  EXPECT_THROW(X::make_projective_plane(m, std::size_t(-1)), X::Parameter_error);
  unchanged();
  try {
    X::make_mobius_strip(m, 2, 3);
  } catch (const X::Parameter_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("n_around"), std::string::npos) << what;
    EXPECT_NE(what.find("3"), std::string::npos) << what;
  }
}

} // namespace

} // namespace generators_tests
