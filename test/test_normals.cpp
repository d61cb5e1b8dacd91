// Face and vertex normals: Newell vectors against hand-computed area
// vectors, CGAL's normals on the converted Surface_mesh, the radial direction
// on a sphere, and the sign that a Möbius strip's core reverses.
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace normals_tests {

namespace {

namespace X = CGAL_ext;
namespace PMP = CGAL::Polygon_mesh_processing;
using Kd = test::Kd;
using Epeck = test::Epeck;
using Kq = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using W = X::Vertex_normal_weighting;
constexpr double pi = 3.14159265358979323846;
const W all_weightings[] = {W::uniform, W::area, W::angle};

template <class K>
constexpr bool is_exact = !std::is_same_v<typename K::FT, double>;

template <class K>
typename K::Vector_3 vec(double x, double y, double z)
{
  return typename K::Vector_3(x, y, z);
}

double relative_difference(const Kd::Vector_3& a, const Kd::Vector_3& b)
{
  return std::sqrt((a - b).squared_length()) / (std::max)(1.0, std::sqrt(b.squared_length()));
}

template <class V>
Kd::Vector_3 as_double(const V& v)
{
  return Kd::Vector_3(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
}

// Coordinate by coordinate: exact on exact kernels. (EPECK's Vector_3 ==
// goes through a static filter that GCC's -Wmaybe-uninitialized flags.)
template <class V>
bool same_vector(const V& a, const V& b)
{
  return a.x() == b.x() && a.y() == b.y() && a.z() == b.z();
}

// Equal on exact kernels; within `tolerance` (relative) on double.
template <class K>
void expect_same(const typename K::Vector_3& actual, const typename K::Vector_3& expected, double tolerance = 1e-12)
{
  if constexpr (is_exact<K>)
    EXPECT_TRUE(same_vector(actual, expected)) << actual << " vs " << expected;
  else
    EXPECT_LE(relative_difference(as_double(actual), as_double(expected)), tolerance) << actual << " vs " << expected;
}

// Within `tolerance` on every kernel: for unit vectors, whose square root is
// approximate even on exact kernels.
template <class V>
void expect_close(const V& actual, const V& expected, double tolerance = 1e-12)
{
  EXPECT_LE(relative_difference(as_double(actual), as_double(expected)), tolerance) << actual << " vs " << expected;
}

double angle_between(const Kd::Vector_3& a, const Kd::Vector_3& b)
{
  return std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
}

template <class K>
X::Mobius_mesh<typename K::Point_3> soup_mesh(const std::vector<std::array<double, 3>>& coordinates,
                                              const std::vector<std::vector<int>>& polygons)
{
  std::vector<typename K::Point_3> points;
  for (const auto& c : coordinates)
    points.emplace_back(c[0], c[1], c[2]);
  X::Mobius_mesh<typename K::Point_3> mesh;
  X::polygon_soup_to_mobius_mesh(points, polygons, mesh, X::parameters::keep_orientation(true)); // as given
  return mesh;
}

template <class Mesh>
void reverse_random_faces(Mesh& mesh, unsigned seed)
{
  std::mt19937 random(seed);
  for (auto f : mesh.faces())
    if (random() % 2)
      mesh.reverse_face_orientation(f);
}

template <class K>
class Normals : public ::testing::Test
{};
using Kernels = ::testing::Types<Kd, Epeck, Kq>;
TYPED_TEST_SUITE(Normals, Kernels);

// ---------------------------------------------------------------- Newell vectors in closed form

TYPED_TEST(Normals, PlanarPolygonsGiveTwiceTheirVectorArea)
{
  using K = TypeParam;
  // A right triangle in the plane z = 0 with legs 2 and 3: area 3.
  const auto right = soup_mesh<K>({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, {{0, 1, 2}});
  expect_same<K>(X::face_normal(X::Face_index(0u), right), vec<K>(0, 0, 6));
  // The triangle cut from the axes at 1, 2, 3: (-1,2,0) x (-1,0,3) = (6,3,2), length 7.
  const auto tilted = soup_mesh<K>({{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}, {{0, 1, 2}});
  expect_same<K>(X::face_normal(X::Face_index(0u), tilted), vec<K>(6, 3, 2));
  // A non-convex L-shaped hexagon of area 3, lifted to the plane z = x + 2y + 5:
  // its vector area is 3 (-1, -2, 1), whichever corner the sum starts from.
  const std::vector<std::array<double, 2>> l_shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (std::size_t start = 0; start < l_shape.size(); ++start) {
    std::vector<std::array<double, 3>> lifted;
    for (std::size_t i = 0; i < l_shape.size(); ++i) {
      const auto& q = l_shape[(start + i) % l_shape.size()];
      lifted.push_back({q[0], q[1], q[0] + 2 * q[1] + 5});
    }
    const auto l = soup_mesh<K>(lifted, {{0, 1, 2, 3, 4, 5}});
    expect_same<K>(X::face_normal(X::Face_index(0u), l), vec<K>(-6, -12, 6));
    // Seen from the flipped dart, the other side.
    expect_same<K>(X::face_normal(l.halfedge(X::Face_index(0u)).flipped(), l), vec<K>(6, 12, -6));
  }
  // The same hexagon 10^8 away from the origin: the products of Newell's
  // sum taken about the origin would reach 10^16 and round in double.
  std::vector<std::array<double, 3>> far;
  for (const auto& q : l_shape)
    far.push_back({q[0] + 1e8, q[1] - 3e7, 2e8});
  const auto far_mesh = soup_mesh<K>(far, {{0, 1, 2, 3, 4, 5}});
  EXPECT_TRUE(same_vector(X::face_normal(X::Face_index(0u), far_mesh), vec<K>(0, 0, 6)));
}

TYPED_TEST(Normals, NonPlanarQuadGivesNewellsVector)
{
  using K = TypeParam;
  // (0,0,0) (1,0,0) (1,1,1) (0,1,0): Newell's sum of p_i x p_{i+1} is
  // 0 + (0,-1,1) + (-1,0,1) + 0 = (-1,-1,2), which is also the cross product
  // of the diagonals (p2 - p0) x (p3 - p1) = (1,1,1) x (-1,1,0).
  for (double shift : {0.0, 10.0, -7.5}) {
    const double x = shift, y = 2 * shift;
    const auto quad = soup_mesh<K>({{x, y, 0}, {1 + x, y, 0}, {1 + x, 1 + y, 1}, {x, 1 + y, 0}}, {{0, 1, 2, 3}});
    expect_same<K>(X::face_normal(X::Face_index(0u), quad), vec<K>(-1, -1, 2));
    const auto unit = as_double(X::face_normal(X::Face_index(0u), quad, X::parameters::normalize(true)));
    EXPECT_LE(relative_difference(unit, Kd::Vector_3(-1, -1, 2) / std::sqrt(6.0)), 1e-15);
  }
  // A degenerate face: zero, also when asked to normalise.
  const auto flat = soup_mesh<K>({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 1, 2}});
  EXPECT_TRUE(same_vector(X::face_normal(X::Face_index(0u), flat, X::parameters::normalize(true)), vec<K>(0, 0, 0)));
}

// A box [0,1] x [0,2] x [0,3] with outward faces: at the corner at the
// origin the three faces have outward Newell vectors (-2*6, 0, 0),
// (0, -2*3, 0) and (0, 0, -2*2), unit normals -x, -y, -z and right angles.
TYPED_TEST(Normals, BoxCornerInClosedForm)
{
  using K = TypeParam;
  std::vector<std::array<double, 3>> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back({double(i & 1), double(2 * ((i >> 1) & 1)), double(3 * ((i >> 2) & 1))});
  auto box =
    soup_mesh<K>(corners, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
  reverse_random_faces(box, 3); // the darts carry the side, whatever the faces' orientations
  const X::Vertex_index origin(0u);
  const double a = pi / 2;
  for (auto d : X::halfedges_around_target(origin, box))
    for (auto side : {d, box.next(d).flipped()}) {
      // Outward if this dart sees its face from outside.
      const bool outward = CGAL::to_double(X::face_normal(side, box) * vec<K>(-1, -1, -1)) > 0;
      const double s = outward ? 1 : -1;
      expect_same<K>(X::vertex_normal(side, box), vec<K>(-12 * s, -6 * s, -4 * s));
      expect_same<K>(X::vertex_normal(side, box, X::parameters::vertex_normal_weighting(W::area)),
                     vec<K>(-12 * s, -6 * s, -4 * s));
      const auto uniform = X::vertex_normal(side, box, X::parameters::vertex_normal_weighting(W::uniform));
      EXPECT_LE(relative_difference(as_double(uniform), Kd::Vector_3(-s, -s, -s)), 1e-15);
      const auto angle = X::vertex_normal(side, box, X::parameters::vertex_normal_weighting(W::angle));
      EXPECT_LE(relative_difference(as_double(angle), Kd::Vector_3(-a * s, -a * s, -a * s)), 1e-15);
      const auto unit = X::vertex_normal(side, box, X::parameters::normalize(true));
      EXPECT_LE(relative_difference(as_double(unit), Kd::Vector_3(-12 * s, -6 * s, -4 * s) / 14.0), 1e-15);
    }
  // The vertex's own normal is seen from the side of the orientation of the face of its stored dart.
  const auto stored_face = box.face(box.halfedge(origin));
  const double s = CGAL::to_double(X::face_normal(stored_face, box) * vec<K>(-1, -1, -1)) > 0 ? 1 : -1;
  expect_same<K>(X::vertex_normal(origin, box), vec<K>(-12 * s, -6 * s, -4 * s));
}

// ---------------------------------------------------------------- Möbius strip

// The unflipped dart of the face on the y > 0 side of the strip's cross edge
// at u = 0 that crosses the core circle (radius 1): both ends have y == 0.
template <class Mesh>
X::Dart core_cross_dart(const Mesh& mesh)
{
  for (auto f : mesh.faces())
    for (auto d : X::halfedges_around_face(f, mesh)) {
      const auto p = mesh.point(mesh.source(d)), q = mesh.point(mesh.target(d));
      const auto r = mesh.point(mesh.target(mesh.next(d)));
      if (p.y() == 0 && q.y() == 0 && (p.x() - 1) * (q.x() - 1) < 0 && r.y() > 0)
        return d;
    }
  return X::Dart();
}

// Carries the face normal from face to face across the strip, once round:
// d -> opposite(next(next(d))) crosses each quad to the next along the core.
template <class K>
void carry_normal_round(int half_twists)
{
  SCOPED_TRACE(half_twists);
  X::Mobius_mesh<typename K::Point_3> strip;
  const std::size_t n = 24;
  X::make_mobius_strip(strip, n, 3, half_twists, 1.0, 0.5, true);
  reverse_random_faces(strip, 11); // the walk is the same whatever the faces' orientations
  const X::Dart start = core_cross_dart(strip);
  ASSERT_TRUE(start.is_valid());
  X::Dart d = start;
  for (std::size_t k = 0; k < n; ++k) {
    const X::Dart across = strip.opposite(strip.next(strip.next(d)));
    ASSERT_FALSE(strip.is_border(across));
    // Neighbouring faces of a smooth strip, seen from one side, point alike.
    EXPECT_GT(as_double(X::face_normal(d, strip)) * as_double(X::face_normal(across, strip)), 0.0) << k;
    d = across;
    if (k + 1 < n) {
      EXPECT_NE(strip.face(d), strip.face(start));
    }
  }
  // Back at the first face: an odd number of half-twists brings the walk
  // back on the other side of it, an even number on the same side.
  const bool one_sided = half_twists % 2 != 0;
  EXPECT_EQ(d, one_sided ? start.flipped() : start);
  const auto back = X::face_normal(d, strip), first = X::face_normal(start, strip);
  EXPECT_TRUE(same_vector(back, one_sided ? -first : first));
}

TYPED_TEST(Normals, NormalCarriedRoundAMobiusStripComesBackNegated)
{
  carry_normal_round<TypeParam>(1);
  carry_normal_round<TypeParam>(3);
  carry_normal_round<TypeParam>(2);
}

TYPED_TEST(Normals, VertexNormalsOnAMobiusStripFollowTheDart)
{
  using K = TypeParam;
  for (bool quads : {true, false}) {
    SCOPED_TRACE(quads);
    X::Mobius_mesh<typename K::Point_3> strip;
    X::make_mobius_strip(strip, 16, 2, 1, 1.0, 0.5, quads);
    reverse_random_faces(strip, 5);
    ASSERT_GT(X::number_of_mobius_edges(strip), 0u);
    for (W w : all_weightings) {
      const auto np = X::parameters::vertex_normal_weighting(w);
      for (auto h : strip.halfedges())
        for (bool flipped : {false, true}) {
          const X::Dart d(h, flipped);
          const auto n = X::vertex_normal(d, strip, np);
          if (strip.is_border(d)) {
            // A border dart sees the side of the face that runs against it.
            EXPECT_GT(as_double(n) * as_double(X::face_normal(strip.opposite(d), strip)), 0.0);
            continue;
          }
          // The same corner seen from the other side of the face.
          expect_same<K>(X::vertex_normal(strip.next(d).flipped(), strip, np), -n);
          // On a smooth strip the vertex normal leans the way of its face.
          EXPECT_GT(as_double(n) * as_double(X::face_normal(d, strip)), 0.0) << d;
        }
    }
  }
}

TYPED_TEST(Normals, ReversingFacesKeepsTheNormalsOfTheSameSide)
{
  using K = TypeParam;
  X::Mobius_mesh<typename K::Point_3> strip;
  X::make_mobius_strip(strip, 12, 2, 1, 1.0, 0.5, true);
  auto reversed = strip;
  std::vector<bool> turned(strip.number_of_faces(), false);
  std::mt19937 random(7);
  for (auto f : reversed.faces())
    if (random() % 2) {
      reversed.reverse_face_orientation(f);
      turned[f.idx()] = true;
    }
  for (auto h : strip.halfedges()) {
    if (strip.is_border(h))
      continue;
    // A reversed face's halfedge is walked the old way by the other dart.
    const X::Dart same_walk(h, turned[strip.face(h).idx()]);
    expect_same<K>(X::face_normal(same_walk, reversed), X::face_normal(X::Dart(h), strip));
    expect_same<K>(X::vertex_normal(same_walk, reversed), X::vertex_normal(X::Dart(h), strip));
  }
}

// Once orient() has left no Möbius edge, every vertex normal agrees with the
// normals of all faces around it, although reversing faces has flipped some
// of the darts the vertices store.
TYPED_TEST(Normals, OrientedMeshesGetVertexNormalsThatAgreeWithTheirFaces)
{
  using K = TypeParam;
  X::Mobius_mesh<typename K::Point_3> annulus;
  X::make_mobius_strip(annulus, 12, 2, 2, 1.0, 0.5, false);
  X::make_torus(annulus, 8, 6); // a second component, closed
  reverse_random_faces(annulus, 6);
  ASSERT_EQ(X::orient(annulus), 0u);
  std::size_t flipped_stored = 0;
  for (auto v : annulus.vertices())
    flipped_stored += annulus.halfedge(v).is_flipped() ? 1 : 0;
  ASSERT_GT(flipped_stored, 0u);
  auto normals = annulus.template add_property_map<X::Vertex_index, typename K::Vector_3>("v:normal").first;
  for (W w : all_weightings) {
    X::compute_vertex_normals(annulus, normals, X::parameters::vertex_normal_weighting(w));
    for (auto v : annulus.vertices()) {
      const auto n = X::vertex_normal(v, annulus, X::parameters::vertex_normal_weighting(w));
      expect_same<K>(normals[v], n);
      for (auto f : X::faces_around_target(v, annulus)) {
        if (!f.is_valid())
          continue; // the border gap
        EXPECT_GT(as_double(n) * as_double(X::face_normal(f, annulus)), 0.0) << v << " " << f;
      }
    }
  }
}

TYPED_TEST(Normals, PropertyMapsHoldTheSameNormals)
{
  using K = TypeParam;
  using Vector = typename K::Vector_3;
  X::Mobius_mesh<typename K::Point_3> strip;
  X::make_mobius_strip(strip, 10, 2, 1, 1.0, 0.5, false);
  reverse_random_faces(strip, 2);
  auto faces = strip.template add_property_map<X::Face_index, Vector>("f:normal").first;
  auto vertices = strip.template add_property_map<X::Vertex_index, Vector>("v:normal").first;
  auto corners = strip.template add_property_map<X::Halfedge_index, Vector>("h:normal").first;
  for (W w : all_weightings) {
    const auto np = X::parameters::vertex_normal_weighting(w).normalize(true);
    X::compute_face_normals(strip, faces, np);
    X::compute_vertex_normals(strip, vertices, np);
    X::compute_corner_normals(strip, corners, np);
    for (auto f : strip.faces())
      expect_same<K>(faces[f], X::face_normal(f, strip, np));
    for (auto v : strip.vertices())
      expect_same<K>(vertices[v], X::vertex_normal(v, strip, np));
    for (auto h : strip.halfedges())
      if (!strip.is_border(h)) {
        // Summed from another dart of the fan: the same sum in another order.
        expect_close(corners[h], X::vertex_normal(X::Dart(h), strip, np));
        EXPECT_GT(as_double(corners[h]) * as_double(faces[strip.face(h)]), 0.0);
      }
  }
}

// ---------------------------------------------------------------- sphere

// The octahedron |x| + |y| + |z| = n split into n^2 triangles per face at
// its integer points, projected onto the unit sphere.
template <class K>
X::Mobius_mesh<typename K::Point_3> octahedral_sphere(int n)
{
  std::map<std::array<int, 3>, int> index;
  std::vector<typename K::Point_3> points;
  auto point = [&](int a, int b, int c) {
    const auto [it, added] = index.emplace(std::array<int, 3>{a, b, c}, int(points.size()));
    if (added) {
      const double r = std::sqrt(double(a * a + b * b + c * c));
      points.emplace_back(a / r, b / r, c / r);
    }
    return it->second;
  };
  std::vector<std::vector<int>> triangles;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1})
        for (int i = 0; i < n; ++i)
          for (int j = 0; i + j < n; ++j) {
            const int k = n - i - j;
            auto corner = [&](int di, int dj) { return point(sx * (i + di), sy * (j + dj), sz * (k - di - dj)); };
            std::vector<std::vector<int>> cells = {{corner(0, 0), corner(1, 0), corner(0, 1)}};
            if (i + j + 1 < n)
              cells.push_back({corner(1, 0), corner(1, 1), corner(0, 1)});
            for (auto& t : cells) {
              if (sx * sy * sz < 0)
                std::swap(t[1], t[2]); // outward
              triangles.push_back(t);
            }
          }
  X::Mobius_mesh<typename K::Point_3> mesh;
  X::polygon_soup_to_mobius_mesh(points, triangles, mesh);
  return mesh;
}

// Each face's plane cuts the unit sphere in its circumcircle, of radius R, so
// its unit normal is at angle asin(R) from the radial direction at each of its
// corners. A sum of those normals with positive weights stays in the cone of
// the largest such angle around the vertex: asin(max R) bounds every vertex
// normal's angle from the radial direction, for every weighting.
TYPED_TEST(Normals, SphereVertexNormalsAreRadial)
{
  using K = TypeParam;
  const int n = 6;
  auto sphere = octahedral_sphere<K>(n);
  ASSERT_EQ(X::euler_characteristic(sphere), 2);
  ASSERT_EQ(sphere.number_of_faces(), std::size_t(8 * n * n));
  double max_squared_radius = 0;
  for (auto f : sphere.faces()) {
    const auto d = sphere.halfedge(f);
    const auto& p = sphere.point(sphere.source(d));
    const auto& q = sphere.point(sphere.target(d));
    const auto& r = sphere.point(sphere.target(sphere.next(d)));
    max_squared_radius = (std::max)(max_squared_radius, CGAL::to_double(CGAL::squared_radius(p, q, r)));
  }
  const double bound = std::asin(std::sqrt(max_squared_radius));
  EXPECT_LT(bound, 0.25); // about the triangles' size, 1/n of a right angle
  reverse_random_faces(sphere, 9);
  for (W w : all_weightings) {
    double worst = 0;
    std::size_t symmetric_corners = 0;
    for (auto v : sphere.vertices()) {
      const auto radial = as_double(sphere.point(v) - CGAL::ORIGIN);
      for (auto d : X::halfedges_around_target(v, sphere)) {
        const auto normal = as_double(X::vertex_normal(d, sphere, X::parameters::vertex_normal_weighting(w)));
        // Outward exactly when the dart sees its face from outside.
        const bool outward = as_double(X::face_normal(d, sphere)) * radial > 0;
        const double angle = angle_between(outward ? normal : -normal, radial);
        worst = (std::max)(worst, angle);
        // The octahedron's corners, edge midpoints and face centres are
        // fixed by mirror symmetries whose planes meet in the radial line.
        std::array<double, 3> m = {std::abs(radial.x()), std::abs(radial.y()), std::abs(radial.z())};
        std::sort(m.begin(), m.end());
        const bool symmetric = (m[0] < 1e-12 && m[1] < 1e-12) ||              // a corner
                               (m[0] < 1e-12 && m[2] - m[1] < 1e-12) ||       // an edge's midpoint
                               (m[1] - m[0] < 1e-12 && m[2] - m[1] < 1e-12);  // a face's centre
        if (symmetric) {
          EXPECT_LT(angle, 1e-12) << v;
          ++symmetric_corners;
        }
      }
    }
    // 6 corners of valence 4, 12 edge midpoints and 8 face centres of valence 6.
    EXPECT_EQ(symmetric_corners, 6u * 4 + 12u * 6 + 8u * 6);
    EXPECT_LE(worst, bound + 1e-12) << int(w);
    EXPECT_GT(worst, 0.0) << int(w);
  }
}

// ---------------------------------------------------------------- against CGAL

using SM = CGAL::Surface_mesh<Kd::Point_3>;
using Dart_pairs = std::vector<std::pair<X::Dart, SM::Halfedge_index>>;

Dart_pairs convert(const X::Mobius_mesh<Kd::Point_3>& mesh, SM& sm)
{
  Dart_pairs pairs;
  const auto r =
    X::to_surface_mesh(mesh, sm, X::parameters::halfedge_to_halfedge_output_iterator(std::back_inserter(pairs)));
  EXPECT_EQ(r.seam_edges, 0u);
  return pairs;
}

// The weighted sum at target(h) computed on the Surface_mesh from CGAL's unit
// face normals, CGAL's angles (acos-based, in degrees) and areas.
Kd::Vector_3 cgal_weighted_sum(SM::Halfedge_index h, const SM& sm, W w)
{
  Kd::Vector_3 sum(0, 0, 0);
  for (auto g : CGAL::halfedges_around_target(h, sm)) {
    if (sm.is_border(g))
      continue;
    const auto unit = PMP::compute_face_normal(sm.face(g), sm);
    if (w == W::uniform)
      sum = sum + unit;
    else if (w == W::area)
      sum = sum + 2 * PMP::face_area(sm.face(g), sm) * unit;
    else
      sum = sum + CGAL::approximate_angle(sm.point(sm.source(g)), sm.point(sm.target(g)),
                                          sm.point(sm.target(sm.next(g)))) * pi / 180 * unit;
  }
  return sum;
}

TEST(NormalsAgainstCgal, FaceNormalsAndWeightedSums)
{
  // A triangulated annulus with two half-twists (curved, with two borders)
  // and a quad torus, with faces reversed at random: Möbius edges that the
  // darts must see through. The conversion orients the faces consistently.
  X::Mobius_mesh<Kd::Point_3> annulus, torus;
  X::make_mobius_strip(annulus, 14, 3, 2, 1.0, 0.6, false);
  X::make_torus(torus, 12, 8, 2.0, 0.7);
  for (auto* mesh : {&annulus, &torus}) {
    const bool triangles = mesh == &annulus;
    SCOPED_TRACE(triangles ? "annulus" : "torus");
    reverse_random_faces(*mesh, 4);
    ASSERT_GT(X::number_of_mobius_edges(*mesh), 0u);
    SM sm;
    const auto pairs = convert(*mesh, sm);
    ASSERT_EQ(pairs.size(), sm.number_of_halfedges());
    for (const auto& [d, h] : pairs) {
      if (!sm.is_border(h)) {
        EXPECT_LE(relative_difference(X::face_normal(d, *mesh, X::parameters::normalize(true)),
                                      PMP::compute_face_normal(sm.face(h), sm)),
                  1e-14);
      }
      for (W w : all_weightings) {
        if (w == W::area && !triangles)
          continue; // PMP::face_area() is for triangles
        const auto ours = X::vertex_normal(d, *mesh, X::parameters::vertex_normal_weighting(w));
        EXPECT_LE(relative_difference(ours, cgal_weighted_sum(h, sm, w)), 1e-10) << int(w) << " " << d;
      }
    }
  }
}

// CGAL 5.5's compute_vertex_normal() takes the centre of the smallest cap of
// the sphere that holds the unit face normals (Aubry et al.'s "most visible"
// normal), which is none of the weighted sums. It agrees with all of them
// where symmetry fixes the normal, and with the uniform one where a vertex
// has one or two faces (the cap's centre is then their bisector).
TEST(NormalsAgainstCgal, VertexNormalsWhereCgalsNormalIsAWeightedSum)
{
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> icosahedron;
  for (double s : {-1.0, 1.0})
    for (double t : {-phi, phi}) {
      icosahedron.push_back({0, s, t});
      icosahedron.push_back({s, t, 0});
      icosahedron.push_back({t, 0, s});
    }
  // Faces: the triples of mutually adjacent vertices (edge length 2).
  std::vector<std::vector<int>> faces;
  auto adjacent = [&](int a, int b) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k)
      d2 += (icosahedron[a][k] - icosahedron[b][k]) * (icosahedron[a][k] - icosahedron[b][k]);
    return std::abs(d2 - 4) < 1e-9;
  };
  for (int a = 0; a < 12; ++a)
    for (int b = a + 1; b < 12; ++b)
      for (int c = b + 1; c < 12; ++c)
        if (adjacent(a, b) && adjacent(b, c) && adjacent(a, c))
          faces.push_back({a, b, c}); // any orientation: the mesh takes each as it comes
  ASSERT_EQ(faces.size(), 20u);
  auto ico = soup_mesh<Kd>(icosahedron, faces);
  ASSERT_GT(X::number_of_mobius_edges(ico), 0u);

  // A height field over a skewed 5 x 4 grid of non-planar quads: its border
  // vertices have one or two faces.
  std::vector<std::array<double, 3>> grid;
  std::vector<std::vector<int>> quads;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 5; ++i) {
      const double x = i + 0.3 * std::sin(j), y = j + 0.2 * std::cos(i);
      grid.push_back({x, y, 0.1 * (x * x - y * y) + 0.05 * x * y});
    }
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i)
      quads.push_back({j * 6 + i, j * 6 + i + 1, (j + 1) * 6 + i + 1, (j + 1) * 6 + i});
  auto field = soup_mesh<Kd>(grid, quads);
  reverse_random_faces(field, 8);

  std::size_t compared = 0;
  for (auto* mesh : {&ico, &field}) {
    SM sm;
    for (const auto& [d, h] : convert(*mesh, sm)) {
      const auto v = sm.target(h);
      if (sm.halfedge(v) != h)
        continue; // CGAL's vertex normal is seen from the side of its halfedge(v)
      std::size_t incident = 0;
      for (auto f : CGAL::faces_around_target(h, sm))
        incident += f != SM::null_face() ? 1 : 0;
      const bool is_sum = mesh == &ico || incident <= 2;
      if (!is_sum)
        continue;
      const auto cgal = PMP::compute_vertex_normal(v, sm);
      for (W w : all_weightings) {
        if (mesh == &field && w != W::uniform && incident == 2)
          continue;
        const auto ours = X::vertex_normal(d, *mesh, X::parameters::vertex_normal_weighting(w).normalize(true));
        EXPECT_LE(relative_difference(ours, cgal), 1e-12) << int(w) << " " << v;
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 12u + 18u); // the icosahedron's vertices, the grid's border vertices
}

// Unit normals of a tetrahedron at scales where the squares of its normals
// underflow or overflow in double (at 1e-140 a face's normal has length
// 1e-280, whose square is 0): the same directions as at scale 1, of unit
// length, for every weighting; angles are scale-free.
TEST(NormalsAtExtremeScales, UnitNormalsDoNotDependOnTheScale)
{
  const auto tetrahedron = [](double s) {
    X::Mobius_mesh<Kd::Point_3> m;
    X::polygon_soup_to_mobius_mesh(
      std::vector<Kd::Point_3>{Kd::Point_3(0, 0, 0), Kd::Point_3(s, 0, 0), Kd::Point_3(0, s, 0), Kd::Point_3(0, 0, s)},
      std::vector<std::vector<std::size_t>>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, m);
    return m;
  };
  const auto unit = tetrahedron(1);
  for (double scale : {1e-140, 1e-150, 1e140, 1e150}) {
    const auto m = tetrahedron(scale);
    for (X::Face_index f : m.faces())
      EXPECT_LT(relative_difference(X::face_normal(f, m, X::parameters::normalize(true)),
                                    X::face_normal(f, unit, X::parameters::normalize(true))),
                1e-14)
        << scale;
    for (W w : all_weightings)
      for (X::Vertex_index v : m.vertices()) {
        const auto np = X::parameters::normalize(true).vertex_normal_weighting(w);
        EXPECT_LT(relative_difference(X::vertex_normal(v, m, np), X::vertex_normal(v, unit, np)), 1e-14)
          << scale << " weighting " << int(w) << " vertex " << v.idx();
      }
  }
}

// ---------------------------------------------------------------- errors

TEST(NormalsErrors, BadHandlesAreNamed)
{
  X::Mobius_mesh<Kd::Point_3> strip;
  const X::Dart border = X::make_mobius_strip(strip, 5, 1);
  ASSERT_TRUE(strip.is_border(border));
  EXPECT_THROW(X::face_normal(border, strip), X::Parameter_error);
  EXPECT_THROW(X::face_normal(X::Face_index(99u), strip), X::Parameter_error);
  EXPECT_THROW(X::vertex_normal(X::Vertex_index(99u), strip), X::Parameter_error);
  EXPECT_THROW(X::vertex_normal(X::Dart(X::Halfedge_index(999u)), strip), X::Parameter_error);
  try {
    X::face_normal(border, strip);
  } catch (const X::Parameter_error& e) {
    EXPECT_NE(std::string(e.what()).find("border dart"), std::string::npos) << e.what();
  }
  // An isolated vertex has no normal: the zero vector, as in CGAL.
  const auto lonely = strip.add_vertex(Kd::Point_3(5, 5, 5));
  EXPECT_EQ(X::vertex_normal(lonely, strip), Kd::Vector_3(0, 0, 0));
}

} // namespace

} // namespace normals_tests
