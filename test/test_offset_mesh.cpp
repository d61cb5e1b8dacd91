// offset_mesh(): the thickened surface of a Mobius_mesh. References: the
// offset's own counts and topology (a one-sided surface thickens into its
// orientation double cover), every vertex at the distance from the input (by
// an AABB tree), no self-intersection, the volume of a closed offset, and on
// an exact kernel the lifts p ± D·n exactly.

#include "test_util.h"
#include "topology_checks.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/offset_mesh.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace offset_mesh_tests {

namespace {

using CGAL_ext::Face_index;
using CGAL_ext::Vertex_index;
using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using topology_checks::canonical_cycle;
using topology_checks::face_signature;
using topology_checks::Key;
using topology_checks::key_of;

// A hexagon fanned from its centre: seven vertices, six triangles.
Mesh hexagon_fan()
{
  std::vector<Point> points{Point(0, 0, 0)};
  for (int i = 0; i < 6; ++i)
    points.emplace_back(std::cos(CGAL_PI * i / 3), std::sin(CGAL_PI * i / 3), 0);
  std::vector<std::vector<std::size_t>> triangles;
  for (std::size_t i = 0; i < 6; ++i)
    triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, triangles, m);
  return m;
}

using Triangle = test::Kd::Triangle_3;
using Aabb_tree = CGAL::AABB_tree<CGAL::AABB_traits<test::Kd, CGAL::AABB_triangle_primitive<test::Kd, std::vector<Triangle>::const_iterator>>>;

// The faces of `m`, fanned into triangles, in double.
template <class P>
std::vector<Triangle> triangles_of(const CGAL_ext::Mobius_mesh<P>& m)
{
  std::vector<Triangle> ts;
  auto to_double = [&](Vertex_index v) {
    const Key k = key_of(m.point(v));
    return Point(std::get<0>(k), std::get<1>(k), std::get<2>(k));
  };
  for (Face_index f : m.faces()) {
    std::vector<Point> c;
    for (Vertex_index v : CGAL_ext::vertices_around_face(f, m))
      c.push_back(to_double(v));
    for (std::size_t i = 1; i + 1 < c.size(); ++i)
      ts.emplace_back(c[0], c[i], c[i + 1]);
  }
  return ts;
}

CGAL::Surface_mesh<Point> triangulated_surface_mesh(const std::vector<Triangle>& ts)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> faces;
  std::map<Key, std::size_t> index;
  for (const Triangle& t : ts) {
    std::array<std::size_t, 3> f;
    for (int i = 0; i < 3; ++i) {
      const auto [it, fresh] = index.emplace(key_of(t[i]), points.size());
      if (fresh)
        points.push_back(t[i]);
      f[i] = it->second;
    }
    faces.push_back(f);
  }
  CGAL::Surface_mesh<Point> sm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, sm);
  return sm;
}

double area_of(const std::vector<Triangle>& ts)
{
  double a = 0;
  for (const Triangle& t : ts)
    a += std::sqrt(t.squared_area());
  return a;
}

// The checks every offset must pass, measured on the output itself: valid,
// every vertex at `distance` from the input (nearest point on the input's
// faces by an AABB tree, not the normal it moved along) within `tolerance`
// relative, no self-intersection, and for a closed output a positive volume
// of about 2 * distance * area (the thickened surface).
template <class P>
void check_offset(const CGAL_ext::Mobius_mesh<P>& input, const CGAL_ext::Mobius_mesh<P>& out,
                  const CGAL_ext::Offset_result& r, double distance, double tolerance)
{
  ASSERT_TRUE(out.is_valid(true));
  EXPECT_EQ(r.faces, out.number_of_faces());
  const std::vector<Triangle> input_triangles = triangles_of(input);
  Aabb_tree tree(input_triangles.begin(), input_triangles.end());
  double worst = 0;
  for (Vertex_index v : out.vertices()) {
    const Key k = key_of(out.point(v));
    const double d = std::sqrt(tree.squared_distance(Point(std::get<0>(k), std::get<1>(k), std::get<2>(k))));
    worst = (std::max)(worst, std::abs(d - distance) / distance);
  }
  EXPECT_LE(worst, tolerance);
  const std::vector<Triangle> out_triangles = triangles_of(out);
  const auto sm = triangulated_surface_mesh(out_triangles);
  EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(sm));
  if (r.closed) {
    const double volume = CGAL::Polygon_mesh_processing::volume(sm);
    EXPECT_GT(volume, 0);
    EXPECT_NEAR(volume / (2 * distance * area_of(input_triangles)), 1.0, tolerance);
  }
}

} // namespace

TEST(Offset, ThickenedMobiusStripIsOneClosedOrientableSurfaceOfGenusOne)
{
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 48, 6);
  Mesh out;
  const auto r = CGAL_ext::offset_mesh(strip, 0.01, out);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.orientable);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 0); // genus 1
  // The double cover has every face twice; the one border loop of 2 x 48
  // edges gets one rim quad per edge.
  EXPECT_EQ(r.rim_faces, 96u);
  EXPECT_EQ(r.faces, 2 * strip.number_of_faces() + 96);
  EXPECT_EQ(r.vertices, 2 * strip.number_of_vertices());
  check_offset(strip, out, r, 0.01, 0.05);
}

TEST(Offset, KleinBottleAndBoysSurfaceGiveTheirOrientationDoubleCovers)
{
  Mesh klein, boy, out;
  CGAL_ext::make_klein_bottle(klein, 48, 24);
  auto r = CGAL_ext::offset_mesh(klein, 0.005, out);
  EXPECT_TRUE(r.closed && r.orientable);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 0); // a torus
  EXPECT_EQ(r.faces, 2 * klein.number_of_faces());
  ASSERT_TRUE(out.is_valid(true));

  CGAL_ext::make_projective_plane(boy, 6);
  r = CGAL_ext::offset_mesh(boy, 0.002, out);
  EXPECT_TRUE(r.closed && r.orientable);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 2); // a sphere
  ASSERT_TRUE(out.is_valid(true));
  // Both immerse with self-intersections, so only validity and topology here.
}

TEST(Offset, OrientableSurfacesGiveOneShellOrASolid)
{
  Mesh disk = hexagon_fan(), out;
  auto r = CGAL_ext::offset_mesh(disk, 0.1, out);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.faces, 6u);
  EXPECT_EQ(r.euler_characteristic, 1);
  // The one shell lies on the side the faces' normals point to (+z here).
  for (Vertex_index v : out.vertices())
    EXPECT_NEAR(out.point(v).z(), 0.1, 1e-12);
  check_offset(disk, out, r, 0.1, 1e-9);

  r = CGAL_ext::offset_mesh(disk, 0.1, out, CGAL_ext::parameters::solid(true));
  EXPECT_TRUE(r.closed && r.orientable);
  EXPECT_EQ(r.euler_characteristic, 2); // a flat box: a sphere
  EXPECT_EQ(r.rim_faces, 6u);
  check_offset(disk, out, r, 0.1, 1e-9);

  Mesh torus;
  CGAL_ext::make_torus(torus, 32, 16);
  r = CGAL_ext::offset_mesh(torus, 0.01, out, CGAL_ext::parameters::solid(true));
  EXPECT_EQ(r.components, 2u); // inner and outer skin
  EXPECT_EQ(r.euler_characteristic, 0);
  check_offset(torus, out, r, 0.01, 0.05);
}

TEST(Offset, ExactKernelAndBadDistances)
{
  CGAL_ext::Mobius_mesh<test::Epeck::Point_3> strip, out;
  CGAL_ext::make_mobius_strip(strip, 48, 6);
  const auto r = CGAL_ext::offset_mesh(strip, 0.01, out);
  EXPECT_TRUE(r.closed && r.orientable);
  EXPECT_EQ(r.euler_characteristic, 0);
  check_offset(strip, out, r, 0.01, 0.05);

  Mesh m = hexagon_fan(), kept;
  CGAL_ext::make_torus(kept, 3, 3);
  const auto before = face_signature(kept);
  // Beyond 1e60, as the coordinates, the lifted points' computations overflow.
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL, 1e61, 1e300})
    EXPECT_THROW(CGAL_ext::offset_mesh(m, bad, kept), CGAL_ext::Parameter_error) << bad;
  EXPECT_EQ(face_signature(kept), before);
  Mesh far_out;
  const auto far = CGAL_ext::offset_mesh(m, 1e60, far_out, CGAL_ext::parameters::solid(true));
  EXPECT_TRUE(far.closed);
  EXPECT_EQ(far_out.number_of_faces(), 2 * m.number_of_faces() + far.rim_faces);
  // Unit normals are made in double: a mesh whose squares overflow or whose
  // areas underflow there is refused (at 1e-140 across, the vertices would not
  // move at all; at 1e160 the normals would be NaN).
  for (double scale : {1e-140, 1e140, 1e160}) {
    Mesh scaled = hexagon_fan();
    for (auto v : scaled.vertices())
      scaled.point(v) = CGAL::ORIGIN + scale * (scaled.point(v) - CGAL::ORIGIN);
    try {
      CGAL_ext::offset_mesh(scaled, (std::min)(0.1 * scale, 1.0), kept); // the points refused, not the distance
      ADD_FAILURE() << "offset at scale " << scale;
    } catch (const CGAL_ext::Parameter_error& e) {
      EXPECT_NE(std::string(e.what()).find(scale < 1 ? "across" : "beyond"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(face_signature(kept), before);
}

// With the caller's displacement field, no square root is taken: on an
// exact kernel each vertex has its two lifts p ± D·n(v) exactly, n the
// area-weighted vertex normals (Newell sums, exact), whatever their signs.
TEST(Offset, DisplacementFieldIsExactOnExactKernels)
{
  using K = test::Epeck;
  using EMesh = CGAL_ext::Mobius_mesh<K::Point_3>;
  EMesh strip, out;
  CGAL_ext::make_mobius_strip(strip, 24, 4);
  auto normals = strip.add_property_map<Vertex_index, K::Vector_3>("v:n").first;
  CGAL_ext::compute_vertex_normals(strip, normals);
  std::size_t i = 0;
  for (Vertex_index v : strip.vertices()) // signs do not matter: the side is read from the surface
    if (++i % 3 == 0)
      normals[v] = -normals[v];
  const double distance = 0.0625;
  const auto r = CGAL_ext::offset_mesh(strip, distance, out, CGAL_ext::parameters::vertex_displacement_map(normals));
  EXPECT_TRUE(r.closed && r.orientable);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 0);
  ASSERT_TRUE(out.is_valid(true));
  std::set<std::array<K::FT::ET, 3>> lifts;
  for (Vertex_index w : out.vertices()) {
    const auto& p = out.point(w);
    lifts.insert({CGAL::exact(p.x()), CGAL::exact(p.y()), CGAL::exact(p.z())});
  }
  for (Vertex_index v : strip.vertices())
    for (int sign : {1, -1}) {
      const K::Point_3 q = strip.point(v) + normals[v] * K::FT(sign * distance);
      EXPECT_EQ(lifts.count({CGAL::exact(q.x()), CGAL::exact(q.y()), CGAL::exact(q.z())}), 1u) << v.idx();
    }

  // A displacement tangent to the surface has no side: refused, `out` kept.
  EMesh flat, kept = out;
  std::vector<K::Point_3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<std::array<std::size_t, 3>> face = {{0, 1, 2}};
  CGAL_ext::polygon_soup_to_mobius_mesh(points, face, flat);
  auto tangent = flat.add_property_map<Vertex_index, K::Vector_3>("v:t", K::Vector_3(1, 0, 0)).first;
  EXPECT_THROW(CGAL_ext::offset_mesh(flat, 0.5, out, CGAL_ext::parameters::vertex_displacement_map(tangent)),
               CGAL_ext::Parameter_error);
  EXPECT_EQ(out.number_of_faces(), kept.number_of_faces());
}

} // namespace offset_mesh_tests
