// Shape generators and orientation: closed-form counts, the test meshes in
// test/data/nonorientable as an outside reference, and orient() on meshes
// whose faces were reversed at random.
#include "test_util.h"

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

namespace X = CGAL_ext;
using Kd_mesh = X::Mobius_mesh<test::Kd::Point_3>;
using Epeck_mesh = X::Mobius_mesh<test::Epeck::Point_3>;
using Gmpq_mesh = X::Mobius_mesh<CGAL::Simple_cartesian<CGAL::Gmpq>::Point_3>;

// ---------------------------------------------------------------- expected figures

struct Expected
{
  std::size_t V, E, F;
  long long chi;
  bool closed;
  std::size_t border_loops;
  bool orientable;
};

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

template <class Mesh>
void expect_topology(const Mesh& m, const Expected& x)
{
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), x.V);
  EXPECT_EQ(m.number_of_edges(), x.E);
  EXPECT_EQ(m.number_of_faces(), x.F);
  EXPECT_EQ(X::euler_characteristic(m), x.chi);
  EXPECT_EQ(X::is_closed(m), x.closed);
  EXPECT_EQ(X::number_of_border_cycles(m), x.border_loops);
  EXPECT_EQ(X::is_orientable(m), x.orientable);
  // Sides of faces: each interior edge is two sides, each border edge one.
  std::size_t sides = 0, border_edges = 0;
  for (X::Face_index f : m.faces())
    sides += m.degree(f);
  for (X::Edge_index e : m.edges())
    border_edges += m.is_border(e) ? 1 : 0;
  EXPECT_EQ(sides, 2 * m.number_of_edges() - border_edges);
}

// ---------------------------------------------------------------- face cycles

template <class Mesh>
std::vector<std::vector<std::uint32_t>> face_cycles(const Mesh& m)
{
  std::vector<std::vector<std::uint32_t>> cycles;
  for (X::Face_index f : m.faces()) {
    std::vector<std::uint32_t> c;
    for (X::Vertex_index v : vertices_around_face(f, m))
      c.push_back(v.idx());
    cycles.push_back(c);
  }
  return cycles;
}

bool same_cycle(const std::vector<std::uint32_t>& a, std::vector<std::uint32_t> b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t r = 0; r < b.size(); ++r) {
    if (a == b)
      return true;
    std::rotate(b.begin(), b.begin() + 1, b.end());
  }
  return false;
}

bool reversed_cycle(const std::vector<std::uint32_t>& a, std::vector<std::uint32_t> b)
{
  std::reverse(b.begin(), b.end());
  return same_cycle(a, b);
}

// Edges whose two faces run along them the same way, read from the faces'
// vertex cycles alone (never from the Möbius bits).
template <class Mesh>
std::size_t same_direction_edges(const Mesh& m)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& c : face_cycles(m))
    for (std::size_t i = 0; i < c.size(); ++i)
      ++directed[{c[i], c[(i + 1) % c.size()]}];
  std::size_t n = 0;
  for (const auto& [pair, count] : directed) {
    EXPECT_LE(count, 2);
    n += count == 2 ? 1 : 0;
  }
  return n;
}

// Reverses each face with probability 1/2; returns how many were reversed.
template <class Mesh>
std::size_t reverse_random_faces(Mesh& m, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  std::size_t n = 0;
  for (X::Face_index f : m.faces())
    if (rng() & 1u) {
      m.reverse_face_orientation(f);
      ++n;
    }
  return n;
}

// ---------------------------------------------------------------- a small OBJ reader

struct Obj
{
  std::vector<test::Kd::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::map<std::string, std::string> header; // "key=value" fields of the first comment line
};

Obj read_obj(const std::string& file)
{
  Obj obj;
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (first && tag == "#") {
      std::string field;
      while (ls >> field)
        if (const auto eq = field.find('='); eq != std::string::npos)
          obj.header[field.substr(0, eq)] = field.substr(eq + 1);
    } else if (tag == "v") {
      double x, y, z;
      ls >> x >> y >> z;
      obj.points.emplace_back(x, y, z);
    } else if (tag == "f") {
      std::vector<std::size_t> polygon;
      std::string corner;
      while (ls >> corner)
        polygon.push_back(std::stoul(corner.substr(0, corner.find('/'))) - 1);
      obj.polygons.push_back(polygon);
    }
    first = false;
  }
  return obj;
}

Expected expected_from_header(const Obj& obj)
{
  const auto& h = obj.header;
  const auto n = [&](const char* key) { return std::size_t(std::stoul(h.at(key))); };
  const std::size_t loops = n("boundary_loops");
  return {n("V"), n("E"), n("F"), std::stoll(h.at("chi")), loops == 0, loops, h.at("orientable") == "True"};
}

const std::vector<std::string> nonorientable_files = {
  "mobius_20x4_quads.obj",  "mobius_20x4_tris.obj",    "mobius_min_5tris.obj", "klein_fig8_24x12_quads.obj",
  "boys_surface_quads.obj", "rp2_hemi_icosahedron.obj", "torus_24x12_quads.obj"};

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

// ================================================================ orientation

// Orientable meshes: after random reversals, orient() must undo them all,
// leaving each face as built or each face reversed.
template <class Mesh>
void check_orient_restores(Mesh m, std::uint32_t seed)
{
  ASSERT_TRUE(X::is_orientable(m));
  const auto original = face_cycles(m);
  const std::size_t V = m.number_of_vertices(), E = m.number_of_edges(), F = m.number_of_faces();
  const std::size_t loops = X::number_of_border_cycles(m);
  const std::size_t reversed = reverse_random_faces(m, seed);
  ASSERT_GT(reversed, 0u);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_GT(X::number_of_mobius_edges(m), 0u);
  EXPECT_EQ(X::number_of_mobius_edges(m), same_direction_edges(m));
  EXPECT_TRUE(X::is_orientable(m));

  EXPECT_EQ(X::orient(m), 0u);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(X::number_of_mobius_edges(m), 0u);
  EXPECT_EQ(same_direction_edges(m), 0u);
  EXPECT_EQ(m.number_of_vertices(), V);
  EXPECT_EQ(m.number_of_edges(), E);
  EXPECT_EQ(m.number_of_faces(), F);
  EXPECT_EQ(X::number_of_border_cycles(m), loops);
  const auto now = face_cycles(m);
  std::size_t as_built = 0, turned = 0;
  for (std::size_t f = 0; f < F; ++f) {
    as_built += same_cycle(original[f], now[f]) ? 1 : 0;
    turned += reversed_cycle(original[f], now[f]) ? 1 : 0;
  }
  EXPECT_TRUE(as_built == F || turned == F) << as_built << " as built, " << turned << " reversed";
}

TEST(Orientation, OrientableMeshesDouble)
{
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    Kd_mesh t;
    X::make_torus(t, 8, 5);
    check_orient_restores(t, seed);
    for (int twists : {0, 2, 4}) {
      Kd_mesh a;
      X::make_mobius_strip(a, 9, 3, twists, 1.0, 0.5, seed % 2 == 0);
      check_orient_restores(a, seed);
    }
    const std::vector<test::Kd::Point_3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const std::vector<std::array<std::size_t, 4>> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    Kd_mesh cube;
    X::polygon_soup_to_mobius_mesh(pts, quads, cube);
    expect_topology(cube, {8, 12, 6, 2, true, 0, true});
    check_orient_restores(cube, seed);
  }
}

TEST(Orientation, OrientableMeshesEpeck)
{
  Epeck_mesh t;
  X::make_torus(t, 6, 4);
  check_orient_restores(t, 7);
  Epeck_mesh a;
  X::make_mobius_strip(a, 6, 2, 2, 1.0, 0.5, false);
  check_orient_restores(a, 8);
}

// Non-orientable meshes keep their topology through random reversals, and
// orient() cannot remove every Möbius edge.
template <class Mesh>
void check_orient_keeps_one_sided(Mesh m, std::uint32_t seed)
{
  const std::size_t V = m.number_of_vertices(), E = m.number_of_edges(), F = m.number_of_faces();
  const long long chi = X::euler_characteristic(m);
  const std::size_t loops = X::number_of_border_cycles(m);
  ASSERT_FALSE(X::is_orientable(m));
  ASSERT_GT(reverse_random_faces(m, seed), 0u);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(X::number_of_mobius_edges(m), same_direction_edges(m));
  EXPECT_FALSE(X::is_orientable(m));
  const std::size_t before = X::number_of_mobius_edges(m);

  const std::size_t left = X::orient(m);
  EXPECT_GE(left, 1u);
  EXPECT_LE(left, before);
  EXPECT_EQ(left, X::number_of_mobius_edges(m));
  EXPECT_EQ(left, same_direction_edges(m));
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_FALSE(X::is_orientable(m));
  EXPECT_EQ(m.number_of_vertices(), V);
  EXPECT_EQ(m.number_of_edges(), E);
  EXPECT_EQ(m.number_of_faces(), F);
  EXPECT_EQ(X::euler_characteristic(m), chi);
  EXPECT_EQ(X::number_of_border_cycles(m), loops);
}

TEST(Orientation, NonOrientableGenerated)
{
  for (std::uint32_t seed : {11u, 12u}) {
    for (int twists : {1, 3}) {
      for (bool quads : {true, false}) {
        Kd_mesh m;
        X::make_mobius_strip(m, 10, 3, twists, 1.0, 0.5, quads);
        SCOPED_TRACE("Möbius strip, twists " + std::to_string(twists));
        check_orient_keeps_one_sided(m, seed);
      }
    }
    Kd_mesh k;
    X::make_klein_bottle(k, 12, 6);
    check_orient_keeps_one_sided(k, seed);
    Kd_mesh p;
    X::make_projective_plane(p, 3);
    check_orient_keeps_one_sided(p, seed);
  }
  Epeck_mesh e;
  X::make_mobius_strip(e, 8, 2, 3);
  check_orient_keeps_one_sided(e, 5);
}

TEST(Orientation, TestMeshes)
{
  for (const std::string& file : nonorientable_files) {
    SCOPED_TRACE(file);
    const Obj obj = read_obj(test::data("nonorientable/" + file));
    const Expected x = expected_from_header(obj);
    Kd_mesh m;
    X::polygon_soup_to_mobius_mesh(obj.points, obj.polygons, m);
    expect_topology(m, x);
    EXPECT_EQ(X::number_of_mobius_edges(m), same_direction_edges(m));
    for (std::uint32_t seed : {21u, 22u}) {
      if (x.orientable)
        check_orient_restores(m, seed);
      else
        check_orient_keeps_one_sided(m, seed);
    }
  }
}

TEST(Orientation, JoinedTorusAndMobiusStrip)
{
  Kd_mesh m;
  X::make_torus(m, 7, 4);
  const std::size_t torus_edges = m.number_of_edges(), torus_faces = m.number_of_faces();
  Kd_mesh strip;
  X::make_mobius_strip(strip, 9, 2, 1);
  const auto off = m.join(strip);
  EXPECT_EQ(off.edges, torus_edges);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(X::orientable_components(m), (std::vector<bool>{true, false}));
  EXPECT_FALSE(X::is_orientable(m));

  const X::Mesh_components cc = X::connected_components(m);
  ASSERT_EQ(cc.count, 2u);
  for (X::Vertex_index v : m.vertices())
    EXPECT_EQ(cc.vertex_component[v.idx()], v.idx() < off.vertices ? 0u : 1u);
  for (X::Face_index f : m.faces())
    EXPECT_EQ(cc.face_component[f.idx()], f.idx() < off.faces ? 0u : 1u);

  reverse_random_faces(m, 31);
  EXPECT_GE(X::orient(m), 1u);
  EXPECT_TRUE(m.is_valid(true));
  std::size_t on_torus = 0;
  for (X::Edge_index e : m.edges())
    if (e.idx() < torus_edges && m.is_mobius(e))
      ++on_torus;
  EXPECT_EQ(on_torus, 0u);
  // Torus faces consistent with each other, read from their vertex cycles.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  const auto cycles = face_cycles(m);
  for (std::size_t f = 0; f < torus_faces; ++f)
    for (std::size_t i = 0; i < cycles[f].size(); ++i)
      EXPECT_EQ(++directed[std::make_pair(cycles[f][i], cycles[f][(i + 1) % cycles[f].size()])], 1);
}

TEST(Orientation, ComponentsOfJoinedMeshes)
{
  Kd_mesh parts[4];
  X::make_projective_plane(parts[0], 2);
  X::make_torus(parts[1], 4, 3);
  X::make_mobius_strip(parts[2], 5, 1, 2); // annulus
  X::make_klein_bottle(parts[3], 3, 4);
  Kd_mesh m;
  std::vector<std::uint32_t> first_vertex;
  for (const Kd_mesh& p : parts) {
    first_vertex.push_back(m.number_of_vertices());
    m.join(p);
  }
  first_vertex.push_back(m.number_of_vertices());
  m.add_vertex(test::Kd::Point_3(9, 9, 9)); // isolated: a component without faces
  ASSERT_TRUE(m.is_valid(true));
  const X::Mesh_components cc = X::connected_components(m);
  EXPECT_EQ(cc.count, 5u);
  for (std::size_t p = 0; p < 4; ++p)
    for (std::uint32_t v = first_vertex[p]; v < first_vertex[p + 1]; ++v)
      EXPECT_EQ(cc.vertex_component[v], p);
  EXPECT_EQ(cc.vertex_component.back(), 4u);
  EXPECT_EQ(X::orientable_components(m), (std::vector<bool>{false, true, true, false}));
  EXPECT_EQ(X::euler_characteristic(m), 1 + 0 + 0 + 0 + 1);
  EXPECT_EQ(X::number_of_border_cycles(m), 2u);
}

} // namespace

} // namespace generators_tests
