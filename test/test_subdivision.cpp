// Subdivision: against OpenSubdiv 3.5 on its own regression shapes (levels
// 1-4, 1e-12), against OpenSubdiv on the orientation double cover for
// non-orientable meshes, against hand-computed rationals with an exact
// kernel, and topological invariants (Euler characteristic, border loops).
#include "subdivision_shapes.h"
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Gmpq.h>

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
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

namespace subdivision_tests {

namespace {

using namespace subdivision_shapes;

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// Compares our levels with OpenSubdiv's; `twins` is 1, or 2 for a double cover.
template <class Mask>
void compare(const S::Refiner<Mask>& r, const std::vector<std::vector<V3>>& ours, const Osd_run& osd,
             Vertex_map map, std::size_t twins, double tolerance = 1e-12)
{
  const bool quad = Mask::split == S::Split::quad;
  for (std::size_t k = 0; k < ours.size(); ++k) {
    if (k > 0)
      map = child_map(S::internal::level_of(r, unsigned(k - 1)), map, osd.refiner->GetLevel(int(k - 1)), quad);
    ASSERT_EQ(osd.levels[k].size(), twins * ours[k].size()) << "level " << k;
    ASSERT_EQ(osd.refiner->GetLevel(int(k)).GetNumFaces(), int(twins * r.level_size(unsigned(k)).faces));
    double worst = 0.0;
    std::size_t mapped = 0;
    for (std::size_t v = 0; v < ours[k].size(); ++v) {
      ASSERT_EQ(map[v].size(), twins) << "level " << k << " vertex " << v;
      for (int x : map[v]) {
        const double* q = osd.levels[k][x].p;
        const V3& p = ours[k][v];
        const double scale = std::max({1.0, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
        worst = std::max({worst, std::abs(p.x - q[0]) / scale, std::abs(p.y - q[1]) / scale,
                          std::abs(p.z - q[2]) / scale});
        ++mapped;
      }
    }
    EXPECT_EQ(mapped, osd.levels[k].size());
    EXPECT_LE(worst, tolerance) << "level " << k;
  }
}

template <class Mask>
void check_shape(const Shape& s, Mask mask, Sdc::SchemeType type, int levels);

// One OpenSubdiv shape: ours against OpenSubdiv at levels 1-4 with the
// shape's own tags, possibly overridden.
template <class Mask>
void check_shape(const std::string& name, Mask mask, Sdc::SchemeType type, const Shape* override_tags = nullptr,
                 int levels = 4)
{
  SCOPED_TRACE(name);
  Shape s = read_shape(test::data("opensubdiv/" + name));
  if (override_tags) {
    s.boundary = override_tags->boundary;
    s.crease_method = override_tags->crease_method;
    s.triangles = override_tags->triangles;
  }
  check_shape(s, mask, type, levels);
}

template <class Mask>
void check_shape(const Shape& s, Mask mask, Sdc::SchemeType type, int levels)
{
  const Built b = build(s);
  S::Refinement_options options;
  options.boundary_interpolation = s.boundary;
  options.crease_method = s.crease_method;
  if constexpr (std::is_same_v<Mask, S::Catmull_clark_mask>)
    mask.triangle_subdivision = s.triangles;
  S::Refiner<Mask> r(mask, options);
  const auto ours = our_levels(r, b, unsigned(levels));
  const Osd_run osd = run_opensubdiv(s, s, type, levels);
  compare(r, ours, osd, identity_map(s.points.size()), 1);
  if (s.boundary == Boundary_interpolation::none) {
    for (int k = 0; k <= levels; ++k) {
      const Level& L = S::internal::level_of(r, unsigned(k));
      int holes_ours = 0, holes_osd = 0;
      for (auto h : L.f_hole)
        holes_ours += h;
      for (int f = 0; f < osd.refiner->GetLevel(k).GetNumFaces(); ++f)
        holes_osd += osd.refiner->GetLevel(k).IsFaceHole(f) ? 1 : 0;
      EXPECT_EQ(holes_ours, holes_osd) << "level " << k;
    }
  }
}
#endif

// ----------------------------------------------------------------- OpenSubdiv shapes

TEST(SubdivisionOpenSubdiv, CatmullClarkShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_cube.obj", "catmark_cube_corner4.obj", "catmark_cube_creases1.obj",
                           "catmark_chaikin1.obj", "catmark_edgecorner.obj", "catmark_nonquads.obj",
                           "catmark_pole64.obj", "catmark_smoothtris1.obj", "catmark_torus_creases1.obj"})
    check_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK);
#endif
}

TEST(SubdivisionOpenSubdiv, CatmullClarkOptionsOverridden)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (auto boundary :
       {Boundary_interpolation::none, Boundary_interpolation::edge_only, Boundary_interpolation::edge_and_corner})
    for (auto crease : {Crease_method::uniform, Crease_method::chaikin})
      for (const char* name : {"catmark_edgecorner.obj", "catmark_nonquads.obj", "catmark_torus_creases1.obj",
                               "catmark_chaikin1.obj", "catmark_cube_creases1.obj"}) {
        Shape o;
        o.boundary = boundary;
        o.crease_method = crease;
        o.triangles = Triangle_subdivision::smooth;
        check_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, &o, 3);
      }
#endif
}

TEST(SubdivisionOpenSubdiv, LoopShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"loop_tetrahedron.obj", "loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"})
    check_shape(name, S::Loop_mask(), Sdc::SCHEME_LOOP);
  Shape o;
  o.boundary = Boundary_interpolation::edge_and_corner;
  o.crease_method = Crease_method::chaikin;
  for (const char* name : {"loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"})
    check_shape(name, S::Loop_mask(), Sdc::SCHEME_LOOP, &o);
#endif
}

// A Chaikin crease of sharpness above 1 whose one half decays to 0 (a
// weaker semi-sharp edge at that end) and the other not: OpenSubdiv's
// refiner gives its edge point the smooth mask blended by the sharpness (the
// child point is a dart, not a crease), not the crease mask.
TEST(SubdivisionOpenSubdiv, ChaikinCreaseWithOneHalfDecayed)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  Shape s = read_shape(test::data("opensubdiv/catmark_cube.obj"));
  s.crease_method = Crease_method::chaikin;
  s.crease_pairs = {{0, 1}, {1, 3}, {4, 5}};
  s.crease_values = {1.2f, 0.2f, 1.5f};
  check_shape(s, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 3);
  s.crease_method = Crease_method::uniform;
  check_shape(s, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 3);
#endif
}

TEST(SubdivisionOpenSubdiv, BilinearShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_nonquads.obj", "catmark_cube_creases1.obj", "catmark_edgecorner.obj"})
    check_shape(name, S::Bilinear_mask(), Sdc::SCHEME_BILINEAR, nullptr, 3);
#endif
}

// ----------------------------------------------------------------- non-orientable

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
template <class Mask>
void check_cover(const std::string& file, Mask mask, Sdc::SchemeType type, bool with_creases, int levels = 3)
{
  SCOPED_TRACE(file);
  const Shape s = read_shape(test::data(file));
  Built b = build(s);
  ASSERT_FALSE(CGAL_ext::is_orientable(b.mesh));
  if (with_creases) { // a semi-sharp and an infinitely sharp interior edge, one of them Möbius if any
    int placed = 0;
    for (CGAL_ext::Edge_index e : b.mesh.edges()) {
      if (b.mesh.is_border(e) || placed == 2)
        continue;
      if (placed == 0 && CGAL_ext::number_of_mobius_edges(b.mesh) > 0 && !b.mesh.is_mobius(e))
        continue;
      b.edge_sharpness[e.idx()] = placed == 0 ? 1.5f : 10.0f;
      ++placed;
    }
    b.vertex_sharpness[3] = 2.25f;
  }
  Shape tags;
  const Shape cover = double_cover(b.mesh, b, &tags);
  {
    Mesh cm;
    CGAL_ext::polygon_soup_to_mobius_mesh(cover.points, cover.faces, cm);
    EXPECT_TRUE(CGAL_ext::is_orientable(cm));
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(cm), 0u);
    EXPECT_EQ(CGAL_ext::connected_components(cm).count, CGAL_ext::connected_components(b.mesh).count);
    EXPECT_EQ(CGAL_ext::euler_characteristic(cm), 2 * CGAL_ext::euler_characteristic(b.mesh));
  }
  S::Refiner<Mask> r(mask);
  const auto ours = our_levels(r, b, unsigned(levels));
  const Osd_run osd = run_opensubdiv(cover, tags, type, levels);
  Vertex_map twins(s.points.size());
  for (std::size_t v = 0; v < twins.size(); ++v)
    twins[v] = {int(2 * v), int(2 * v + 1)};
  compare(r, ours, osd, twins, 2);
}
#endif

TEST(SubdivisionMobius, CatmullClarkMatchesOpenSubdivOnDoubleCover)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* f : {"nonorientable/mobius_20x4_quads.obj", "nonorientable/klein_fig8_24x12_quads.obj",
                        "nonorientable/boys_surface_quads.obj"}) {
    check_cover(f, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, false);
    check_cover(f, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, true);
  }
#endif
}

TEST(SubdivisionMobius, LoopMatchesOpenSubdivOnDoubleCover)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* f : {"nonorientable/mobius_20x4_tris.obj", "nonorientable/mobius_min_5tris.obj",
                        "nonorientable/rp2_hemi_icosahedron.obj"}) {
    check_cover(f, S::Loop_mask(), Sdc::SCHEME_LOOP, false);
    check_cover(f, S::Loop_mask(), Sdc::SCHEME_LOOP, true);
  }
#endif
}

Mesh load(const std::string& file)
{
  const Shape s = read_shape(test::data(file));
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m);
  return m;
}

TEST(SubdivisionMobius, TopologyIsKept)
{
  struct Case
  {
    const char* file;
    bool loop;
    long long chi;
    std::size_t borders;
  };
  for (const Case& c : {Case{"nonorientable/mobius_20x4_quads.obj", false, 0, 1},
                        Case{"nonorientable/mobius_min_5tris.obj", true, 0, 1},
                        Case{"nonorientable/mobius_min_5tris.obj", false, 0, 1},
                        Case{"nonorientable/klein_fig8_24x12_quads.obj", false, 0, 0},
                        Case{"nonorientable/rp2_hemi_icosahedron.obj", true, 1, 0}}) {
    SCOPED_TRACE(c.file);
    Mesh m = load(c.file);
    const std::size_t v0 = m.number_of_vertices(), e0 = m.number_of_edges(), f0 = m.number_of_faces();
    std::size_t corners = 0;
    for (CGAL_ext::Face_index f : m.faces())
      corners += m.degree(f);
    Mesh linear = m; // the midpoint split keeps the same counts as Loop's or Catmull-Clark's
    if (c.loop) {
      S::loop(m, CGAL_ext::parameters::number_of_iterations(2));
      S::linear(linear, CGAL_ext::parameters::number_of_iterations(2));
    } else {
      S::catmull_clark(m, CGAL_ext::parameters::number_of_iterations(2));
      S::bilinear(linear, CGAL_ext::parameters::number_of_iterations(2));
    }
    ASSERT_TRUE(linear.is_valid(true));
    EXPECT_EQ(CGAL_ext::euler_characteristic(linear), c.chi);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(linear), c.borders);
    EXPECT_FALSE(CGAL_ext::is_orientable(linear));
    EXPECT_EQ(linear.number_of_faces(), m.number_of_faces());
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), c.chi);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), c.borders);
    EXPECT_EQ(CGAL_ext::is_closed(m), c.borders == 0);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(CGAL_ext::connected_components(m).count, 1u);
    // Counts after one step, from the split alone: Loop V+E, 2E+3F, 4F;
    // Catmull-Clark V+E+F, 2E+C, C (C = sum of face degrees).
    const std::size_t v1 = c.loop ? v0 + e0 : v0 + e0 + f0, e1 = c.loop ? 2 * e0 + 3 * f0 : 2 * e0 + corners,
                      f1 = c.loop ? 4 * f0 : corners;
    const std::size_t v2 = c.loop ? v1 + e1 : v1 + e1 + f1, e2 = c.loop ? 2 * e1 + 3 * f1 : 2 * e1 + 4 * f1,
                      f2 = c.loop ? 4 * f1 : 4 * f1;
    EXPECT_EQ(m.number_of_vertices(), v2);
    EXPECT_EQ(m.number_of_edges(), e2);
    EXPECT_EQ(m.number_of_faces(), f2);
  }
}

// Doo-Sabin and sqrt3 keep the surface: Euler characteristic, border loops,
// non-orientability, one component; counts from the split rules.
TEST(SubdivisionMobius, DooSabinAndSqrt3KeepTopology)
{
  struct Case
  {
    const char* file;
    bool sqrt3;
    long long chi;
    std::size_t borders;
  };
  for (const Case& c : {Case{"nonorientable/mobius_20x4_quads.obj", false, 0, 1},
                        Case{"nonorientable/klein_fig8_24x12_quads.obj", false, 0, 0},
                        Case{"nonorientable/boys_surface_quads.obj", false, 1, 0},
                        Case{"nonorientable/mobius_min_5tris.obj", false, 0, 1},
                        Case{"nonorientable/mobius_20x4_tris.obj", true, 0, 1},
                        Case{"nonorientable/mobius_min_5tris.obj", true, 0, 1},
                        Case{"nonorientable/rp2_hemi_icosahedron.obj", true, 1, 0}}) {
    SCOPED_TRACE(std::string(c.file) + (c.sqrt3 ? " sqrt3" : " doo-sabin"));
    Mesh m = load(c.file);
    const std::size_t v0 = m.number_of_vertices(), e0 = m.number_of_edges(), f0 = m.number_of_faces();
    std::size_t corners = 0, border_edges = 0, fan_vertices = 0;
    for (CGAL_ext::Face_index f : m.faces())
      corners += m.degree(f);
    for (CGAL_ext::Edge_index e : m.edges())
      border_edges += m.is_border(e) ? 1 : 0;
    for (CGAL_ext::Vertex_index v : m.vertices()) {
      std::size_t faces = 0;
      for (CGAL_ext::Face_index f : CGAL_ext::faces_around_target(v, m))
        faces += f.is_valid() ? 1 : 0;
      fan_vertices += faces >= 3 ? 1 : 0;
    }
    if (c.sqrt3) {
      S::sqrt3(m);
      // A centroid per triangle, three triangles per triangle.
      EXPECT_EQ(m.number_of_vertices(), v0 + f0);
      EXPECT_EQ(m.number_of_faces(), 3 * f0);
      // The second step trisects each border edge: two points per edge, and
      // each border triangle becomes one triangle instead of three.
      const std::size_t v1 = m.number_of_vertices(), f1 = m.number_of_faces();
      S::sqrt3(m, CGAL_ext::parameters::number_of_iterations(1));
      EXPECT_EQ(m.number_of_vertices(), v1 + f1);
      m = load(c.file);
      S::sqrt3(m, CGAL_ext::parameters::number_of_iterations(2));
      EXPECT_EQ(m.number_of_vertices(), v1 + (f1 - border_edges) + 2 * border_edges);
      EXPECT_EQ(m.number_of_faces(), 3 * f1); // a border triangle is cut in three by its two new points
      EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), c.borders);
    } else {
      S::doo_sabin(m);
      // A point per corner; a face per face, interior edge and vertex of 3+ faces.
      EXPECT_EQ(m.number_of_vertices(), corners);
      EXPECT_EQ(m.number_of_faces(), f0 + (e0 - border_edges) + fan_vertices);
      S::doo_sabin(m);
    }
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), c.chi);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), c.borders);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(CGAL_ext::connected_components(m).count, 1u);
  }
}

// On a non-orientable mesh, Doo-Sabin and sqrt3 give the points that the
// same scheme gives on the orientation double cover, each twice.
TEST(SubdivisionMobius, DooSabinAndSqrt3MatchDoubleCover)
{
  for (bool sqrt3 : {false, true}) {
    for (const char* file : {"nonorientable/mobius_20x4_quads.obj", "nonorientable/klein_fig8_24x12_quads.obj",
                             "nonorientable/mobius_20x4_tris.obj", "nonorientable/rp2_hemi_icosahedron.obj"}) {
      const Shape s = read_shape(test::data(file));
      if (sqrt3 && s.faces[0].size() != 3)
        continue;
      SCOPED_TRACE(std::string(file) + (sqrt3 ? " sqrt3" : " doo-sabin"));
      Built b = build(s);
      const Shape cover = double_cover(b.mesh, b);
      Mesh cm;
      CGAL_ext::polygon_soup_to_mobius_mesh(cover.points, cover.faces, cm);
      ASSERT_TRUE(CGAL_ext::is_orientable(cm));
      const auto np = CGAL_ext::parameters::number_of_iterations(3);
      if (sqrt3) {
        S::sqrt3(b.mesh, np);
        S::sqrt3(cm, np);
      } else {
        S::doo_sabin(b.mesh, np);
        S::doo_sabin(cm, np);
      }
      ASSERT_EQ(cm.number_of_vertices(), 2 * b.mesh.number_of_vertices());
      EXPECT_EQ(cm.number_of_faces(), 2 * b.mesh.number_of_faces());
      const std::vector<Point> ours(b.mesh.points().data().begin(), b.mesh.points().data().end()),
        theirs(cm.points().data().begin(), cm.points().data().end());
      EXPECT_EQ(test::unmatched_points(ours, theirs, 1e-12), 0u);
      EXPECT_EQ(test::unmatched_points(theirs, ours, 1e-12), 0u);
    }
  }
}

// Reversing faces moves the Möbius seam but not the surface: same points.
TEST(SubdivisionMobius, IndependentOfFaceOrientations)
{
  enum Scheme { catmull_clark, loop, doo_sabin, sqrt3 };
  for (Scheme scheme : {catmull_clark, loop, doo_sabin, sqrt3}) {
    SCOPED_TRACE(scheme);
    const bool triangles = scheme == loop || scheme == sqrt3;
    Mesh a = load(triangles ? "nonorientable/mobius_20x4_tris.obj" : "nonorientable/klein_fig8_24x12_quads.obj");
    auto es = CGAL_ext::edge_sharpness_map(a);
    es[CGAL_ext::Edge_index(7)] = 1.3f;
    es[CGAL_ext::Edge_index(40)] = 10.0f;
    Mesh b = a;
    std::mt19937 rng(7);
    std::size_t reversed = 0;
    for (CGAL_ext::Face_index f : b.faces())
      if (rng() % 3 == 0) {
        b.reverse_face_orientation(f);
        ++reversed;
      }
    ASSERT_GT(reversed, 10u);
    ASSERT_TRUE(b.is_valid(true));
    ASSERT_NE(CGAL_ext::number_of_mobius_edges(a), CGAL_ext::number_of_mobius_edges(b));
    const auto np = CGAL_ext::parameters::number_of_iterations(3);
    for (Mesh* m : {&a, &b}) {
      if (scheme == loop)
        S::loop(*m, np);
      else if (scheme == catmull_clark)
        S::catmull_clark(*m, np);
      else if (scheme == doo_sabin)
        S::doo_sabin(*m, np);
      else
        S::sqrt3(*m, np);
    }
    // Orientation changes the numbering of the children of edges and corners
    // from the second level on, so compare the point sets.
    ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
    const std::vector<Point> pa(a.points().data().begin(), a.points().data().end()),
      pb(b.points().data().begin(), b.points().data().end());
    EXPECT_EQ(test::unmatched_points(pa, pb, 1e-12), 0u);
  }
}

// ----------------------------------------------------------------- exact kernels

TEST(SubdivisionExact, CubeOneLevelByHand)
{
  using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Q = CGAL::Gmpq;
  auto m = unit_cube<K>();
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
  // Edge (v0, v1) and face z = 0, found before subdividing.
  const auto e01 = [&] {
    for (auto e : m.edges())
      if ((m.vertex(e, 0).idx() == 0 && m.vertex(e, 1).idx() == 1) ||
          (m.vertex(e, 0).idx() == 1 && m.vertex(e, 1).idx() == 0))
        return e.idx();
    return 0u;
  }();
  S::catmull_clark(m);
  // Corner of valence 3: V/3 + (sum of 3 neighbours)/9 + (sum of 3 face centres)/9.
  // At (0,0,0): neighbours sum to (1,1,1), face centres to (1,1,1): 2/9 each.
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), K::Point_3(Q(2, 9), Q(2, 9), Q(2, 9)));
  // At (1,1,1): 1/3 + (2,2,2)/9 + (2,2,2)/9 = 7/9.
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(6)), K::Point_3(Q(7, 9), Q(7, 9), Q(7, 9)));
  // Edge (0,0,0)-(1,0,0): (v0+v1)/4 + (faces z=0 and y=0 centres)/4 = (1/2, 1/8, 1/8).
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(nv + e01)), K::Point_3(Q(1, 2), Q(1, 8), Q(1, 8)));
  // Face z = 0 (face 0): its centroid.
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(nv + ne + 0)), K::Point_3(Q(1, 2), Q(1, 2), Q(0)));
  // Face x = 1 (face 3).
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(nv + ne + 3)), K::Point_3(Q(1), Q(1, 2), Q(1, 2)));
}

// EPECK's exact numbers (Boost's gmp_rational or gmpxx's mpq_class, as CGAL
// was configured) and CGAL::Gmpq are all GMP rationals.
template <class ET>
auto mpq_of(const ET& a, int) -> decltype(a.backend().data())
{
  return a.backend().data();
}
template <class ET>
auto mpq_of(const ET& a, long) -> decltype(a.get_mpq_t())
{
  return a.get_mpq_t();
}
template <class ET>
bool same(const ET& a, const CGAL::Gmpq& b)
{
  return mpq_equal(mpq_of(a, 0), b.mpq()) != 0;
}

TEST(SubdivisionExact, EpeckThreeLevelsEqualsGmpqAndDouble)
{
  using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;
  auto e = unit_cube<test::Epeck>();
  auto q = unit_cube<Kq>();
  auto d = unit_cube<test::Kd>();
  // A semi-sharp edge and a corner exercise the blends in exact arithmetic.
  CGAL_ext::edge_sharpness_map(e)[CGAL_ext::Edge_index(0)] = 1.5f;
  CGAL_ext::edge_sharpness_map(q)[CGAL_ext::Edge_index(0)] = 1.5f;
  CGAL_ext::edge_sharpness_map(d)[CGAL_ext::Edge_index(0)] = 1.5f;
  CGAL_ext::vertex_sharpness_map(e)[CGAL_ext::Vertex_index(6)] = 0.5f;
  CGAL_ext::vertex_sharpness_map(q)[CGAL_ext::Vertex_index(6)] = 0.5f;
  CGAL_ext::vertex_sharpness_map(d)[CGAL_ext::Vertex_index(6)] = 0.5f;
  const auto np = CGAL_ext::parameters::number_of_iterations(3);
  S::catmull_clark(e, np);
  S::catmull_clark(q, np);
  S::catmull_clark(d, np);
  ASSERT_EQ(e.number_of_vertices(), 386u); // 8 -> 26 -> 98 -> 386
  for (auto v : e.vertices()) {
    const auto& pe = e.point(v);
    const auto& pq = q.point(v);
    EXPECT_TRUE(same(pe.x().exact(), pq.x()) && same(pe.y().exact(), pq.y()) && same(pe.z().exact(), pq.z()));
    EXPECT_NEAR(CGAL::to_double(pq.x()), d.point(v).x(), 1e-14);
    EXPECT_NEAR(CGAL::to_double(pq.y()), d.point(v).y(), 1e-14);
    EXPECT_NEAR(CGAL::to_double(pq.z()), d.point(v).z(), 1e-14);
  }
}

// ----------------------------------------------------------------- API

// A read-only sharpness map over a vector, as a user might pass.
struct Vector_edge_map
{
  const std::vector<float>* values;
  friend float get(const Vector_edge_map& m, CGAL_ext::Edge_index e) { return (*m.values)[e.idx()]; }
};

TEST(SubdivisionApi, SharpnessMapsFromMeshAndParameters)
{
  // The same creases given as the mesh's "e:sharpness" map and as a parameter.
  Mesh a = load("opensubdiv/catmark_cube_creases1.obj");
  Mesh b = a;
  const Shape s = read_shape(test::data("opensubdiv/catmark_cube_creases1.obj"));
  auto es = CGAL_ext::edge_sharpness_map(a);
  std::vector<float> values(b.number_of_edges(), 0.0f);
  for (std::size_t i = 0; i < s.crease_pairs.size(); ++i) {
    const auto e = find_edge(a, s.crease_pairs[i][0], s.crease_pairs[i][1]);
    es[e] = s.crease_values[i];
    values[e.idx()] = s.crease_values[i];
  }
  Mesh c = b; // no sharpness at all
  S::catmull_clark(a, CGAL_ext::parameters::number_of_iterations(2));
  S::catmull_clark(b, CGAL_ext::parameters::number_of_iterations(2).edge_sharpness_map(Vector_edge_map{&values}));
  S::catmull_clark(c, CGAL_ext::parameters::number_of_iterations(2));
  double ab = 0, ac = 0;
  for (auto v : a.vertices()) {
    ab = std::max(ab, CGAL::squared_distance(a.point(v), b.point(v)));
    ac = std::max(ac, CGAL::squared_distance(a.point(v), c.point(v)));
  }
  EXPECT_EQ(ab, 0.0);
  EXPECT_GT(ac, 1e-6);
  // The result carries the decayed sharpness: 5 -> 3 after two steps.
  auto out = a.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name);
  ASSERT_TRUE(out.has_value());
  int threes = 0, fives = 0;
  for (auto e : a.edges())
    threes += (*out)[e] == 3.0f ? 1 : 0;
  for (float x : s.crease_values)
    fives += x == 5.0f ? 1 : 0;
  EXPECT_EQ(fives, 11);
  EXPECT_EQ(threes, 4 * fives); // each edge of sharpness 5 in four pieces of sharpness 3
}

// The option enums live in one place, namespace CGAL_ext; the subdivision
// namespace names the same types (checked when this file compiles).
TEST(SubdivisionApi, OptionEnumsAreOneTypeEach)
{
  static_assert(std::is_same_v<S::Vertex_rule, CGAL_ext::Vertex_rule>);
  static_assert(std::is_same_v<S::Boundary_interpolation, CGAL_ext::Boundary_interpolation>);
  static_assert(std::is_same_v<S::Crease_method, CGAL_ext::Crease_method>);
  static_assert(std::is_same_v<S::Triangle_subdivision, CGAL_ext::Triangle_subdivision>);
}

TEST(SubdivisionApi, BadInputLeavesMeshUnchanged)
{
  Mesh m = load("opensubdiv/catmark_cube.obj");
  const Mesh before = m;
  EXPECT_THROW(S::loop(m), CGAL_ext::Parameter_error); // quads
  auto es = CGAL_ext::edge_sharpness_map(m);
  es[CGAL_ext::Edge_index(2)] = std::nanf("");
  EXPECT_THROW(S::catmull_clark(m), CGAL_ext::Parameter_error);
  EXPECT_EQ(m.number_of_vertices(), before.number_of_vertices());
  EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
  for (auto v : m.vertices())
    EXPECT_EQ(m.point(v), before.point(v));
}

// A negative sharpness means nothing (OpenSubdiv's sharpness is a number of
// levels): refused as NaN is, naming the edge or vertex, not taken as smooth.
TEST(SubdivisionApi, NegativeSharpnessIsRefused)
{
  for (bool on_edge : {true, false}) {
    SCOPED_TRACE(on_edge ? "edge" : "vertex");
    Mesh m = load("opensubdiv/catmark_cube.obj");
    if (on_edge)
      CGAL_ext::edge_sharpness_map(m)[CGAL_ext::Edge_index(2)] = -1.0f;
    else
      CGAL_ext::vertex_sharpness_map(m)[CGAL_ext::Vertex_index(3)] = -0.5f;
    const Mesh before = m;
    for (int scheme = 0; scheme < 2; ++scheme) {
      try {
        scheme == 0 ? S::catmull_clark(m) : S::doo_sabin(m);
        ADD_FAILURE() << "a negative sharpness was accepted";
      } catch (const CGAL_ext::Parameter_error& e) {
        EXPECT_NE(std::string(e.what()).find(on_edge ? "edge e2 " : "vertex v3 "), std::string::npos) << e.what();
      }
      EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
    }
  }
}

// In double the rules add a ring's points up before they weight the sum:
// points beyond +-1e300, or not finite, are refused naming the vertex, with
// the mesh unchanged; up to there the result is the scaled result.
TEST(SubdivisionApi, PointsWhoseSumsWouldOverflowAreRefused)
{
  const Mesh unit = load("opensubdiv/catmark_cube.obj"); // coordinates up to sqrt(2)
  double largest = 0;
  for (auto v : unit.vertices())
    for (int i = 0; i < 3; ++i)
      largest = (std::max)(largest, std::abs(unit.point(v)[i]));
  const double scale = 0.999e300 / largest;
  Mesh large = unit;
  for (auto v : large.vertices())
    large.point(v) = CGAL::ORIGIN + scale * (large.point(v) - CGAL::ORIGIN);
  Mesh unit_refined = unit;
  S::catmull_clark(unit_refined, CGAL_ext::parameters::number_of_iterations(3));
  S::catmull_clark(large, CGAL_ext::parameters::number_of_iterations(3));
  ASSERT_EQ(large.number_of_vertices(), unit_refined.number_of_vertices());
  for (auto v : large.vertices())
    for (int i = 0; i < 3; ++i) {
      ASSERT_TRUE(std::isfinite(large.point(v)[i]));
      EXPECT_NEAR(large.point(v)[i] / scale, unit_refined.point(v)[i], 1e-14);
    }
  for (const double bad : {1e301, -1e305, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    Mesh m = unit;
    m.point(CGAL_ext::Vertex_index(5)) = Point(0.5, bad, 0.5);
    const Mesh before = m;
    for (int scheme = 0; scheme < 3; ++scheme) {
      try {
        scheme == 0 ? S::catmull_clark(m) : scheme == 1 ? S::doo_sabin(m) : S::linear(m);
        ADD_FAILURE() << "a point at " << bad << " was subdivided";
      } catch (const CGAL_ext::Parameter_error& e) {
        EXPECT_NE(std::string(e.what()).find("vertex v5 "), std::string::npos) << e.what();
      }
      ASSERT_EQ(m.number_of_vertices(), before.number_of_vertices());
      ASSERT_EQ(m.number_of_faces(), before.number_of_faces());
      for (auto v : m.vertices())
        for (int i = 0; i < 3; ++i) { // bit for bit: NaN is not equal to itself
          const double now = m.point(v)[i], was = before.point(v)[i];
          EXPECT_EQ(std::memcmp(&now, &was, sizeof(double)), 0);
        }
    }
  }
}

TEST(SubdivisionApi, EdgePointsVertexRule)
{
  // On the cube, the variant rule at a corner of valence 3:
  // V/3 + (sum of new edge points)/9 + (sum of face points)/9, with the edge
  // points (1/2,1/8,1/8) and permutations: sum (3/4,3/4,3/4); face centres
  // sum (1,1,1): (3/4 + 1)/9 = 7/36.
  using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
  auto m = unit_cube<K>();
  S::catmull_clark(m, CGAL_ext::parameters::vertex_rule(S::Vertex_rule::edge_points));
  const CGAL::Gmpq c(7, 36);
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), K::Point_3(c, c, c));
}

TEST(SubdivisionApi, VertexRuleOfUnequalWeightsByHand)
{
  // Cube corners of valence 3. At (0,0,0) the neighbours and the face centres
  // each sum to (1,1,1), the new edge points to (3/4,3/4,3/4) (as in
  // EdgePointsVertexRule); at (1,1,1), to (2,2,2), (2,2,2) and (9/4,9/4,9/4).
  // Three weights 1/12, 1/16, 1/48: 1/12 + 1/16 + 3/4 · 1/48 = 31/192, and
  // 1/2 + 2/12 + 2/16 + 9/4 · 1/48 = 161/192. Two weights 1/12, 1/24, 1/24:
  // 1/12 + 1/24 + 3/4 · 1/24 = 5/32 and 1/2 + 2/12 + 2/24 + 9/4 · 1/24 = 27/32.
  using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Q = CGAL::Gmpq;
  auto check = [](auto mask, const Q& low, const Q& high) {
    auto m = unit_cube<K>();
    S::subdivide(m, mask);
    EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), K::Point_3(low, low, low));
    EXPECT_EQ(m.point(CGAL_ext::Vertex_index(6)), K::Point_3(high, high, high));
  };
  check(Unequal_weights_mask<3>(), Q(31, 192), Q(161, 192));
  check(Unequal_weights_mask<2>(), Q(5, 32), Q(27, 32));
}

// The one-pass path (used by the free functions) against refine(),
// interpolate_level() and build_mesh(): the same mesh, bit for bit the same
// points, the same sharpness and hole maps.
template <class Mask, class ConcurrencyTag = CGAL::Sequential_tag>
void check_one_pass(const std::string& file, unsigned n, const Boundary_interpolation* boundary = nullptr)
{
  SCOPED_TRACE(file);
  const Shape s = read_shape(test::data(file));
  const Built b = build(s);
  S::Refinement_options options;
  options.boundary_interpolation = boundary ? *boundary : s.boundary;
  options.crease_method = s.crease_method;
  options.parallel_min_vertices = 0; // the parallel pass on every level, however small
  S::Refiner<Mask> r(Mask(), options);
  const std::vector<std::vector<V3>> levels = our_levels(r, b, n);
  Mesh expected;
  r.build_mesh(expected, true);

  S::Refiner<Mask> one(Mask(), options);
  std::vector<V3> values = levels[0];
  Mesh out;
  one.template refine_and_interpolate<ConcurrencyTag>(b.mesh, n, values, out, b.edge_sharpness,
                                                      b.vertex_sharpness, true);
  EXPECT_EQ(one.number_of_levels(), 0u);
  ASSERT_TRUE(out.is_valid(true));
  ASSERT_EQ(out.number_of_vertices(), expected.number_of_vertices());
  ASSERT_EQ(out.number_of_edges(), expected.number_of_edges());
  ASSERT_EQ(out.number_of_faces(), expected.number_of_faces());
  for (auto h : out.halfedges()) {
    const CGAL_ext::Dart d(h, false);
    ASSERT_EQ(out.target(d), expected.target(d));
    ASSERT_EQ(out.next(d), expected.next(d));
    ASSERT_EQ(out.face(h), expected.face(h));
  }
  for (auto e : out.edges())
    ASSERT_EQ(out.is_mobius(e), expected.is_mobius(e));
  for (auto v : out.vertices())
    ASSERT_EQ(out.halfedge(v), expected.halfedge(v));
  ASSERT_EQ(values.size(), levels[n].size());
  EXPECT_EQ(std::memcmp(values.data(), levels[n].data(), values.size() * sizeof(V3)), 0);
  auto es = out.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name);
  auto es_expected = expected.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name);
  auto vs = out.property_map<CGAL_ext::Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  auto vs_expected = expected.property_map<CGAL_ext::Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(es && es_expected && vs && vs_expected);
  EXPECT_EQ(es->data(), es_expected->data());
  EXPECT_EQ(vs->data(), vs_expected->data());
  auto holes = out.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  auto holes_expected = expected.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  ASSERT_EQ(holes.has_value(), holes_expected.has_value());
  if (holes) {
    EXPECT_EQ(holes->data(), holes_expected->data());
  }
}

TEST(SubdivisionApi, OnePassEqualsLevelByLevel)
{
  const Boundary_interpolation none = Boundary_interpolation::none;
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_cube_creases1.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_chaikin1.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_edgecorner.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_edgecorner.obj", 2, &none);
  check_one_pass<S::Catmull_clark_mask>("nonorientable/mobius_20x4_quads.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("nonorientable/torus_24x12_quads.obj", 2);
  check_one_pass<S::Loop_mask>("opensubdiv/loop_icos_semisharp.obj", 3);
  check_one_pass<S::Loop_mask>("opensubdiv/loop_triangle_edgeonly.obj", 3);
  check_one_pass<S::Loop_mask>("opensubdiv/loop_triangle_edgeonly.obj", 2, &none);
  check_one_pass<S::Loop_mask>("nonorientable/mobius_20x4_tris.obj", 3, &none);
  check_one_pass<S::Bilinear_mask>("opensubdiv/catmark_cube_creases1.obj", 2);
  check_one_pass<S::Linear_mask>("nonorientable/mobius_20x4_tris.obj", 2);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_cube_creases1.obj", 0);
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  check_one_pass<S::Catmull_clark_mask, CGAL::Parallel_tag>("opensubdiv/catmark_chaikin1.obj", 3);
  check_one_pass<S::Loop_mask, CGAL::Parallel_tag>("opensubdiv/loop_icos_semisharp.obj", 3);
#endif
}

// The one-pass path that writes the last level straight into the result's
// points (the free functions' path for points of doubles) against the one
// that returns the values: the same mesh and maps, and the points are the
// values, bit for bit, in every scheme.
template <class Mask, class ConcurrencyTag = CGAL::Sequential_tag>
void check_points_pass(const std::string& file, unsigned n, const Boundary_interpolation* boundary = nullptr)
{
  SCOPED_TRACE(file + ", " + std::to_string(n) + " levels");
  const Shape s = read_shape(test::data(file));
  const Built b = build(s);
  S::Refinement_options options;
  options.boundary_interpolation = boundary ? *boundary : s.boundary;
  options.crease_method = s.crease_method;
  options.parallel_min_vertices = 0; // the parallel pass on every level, however small
  std::vector<V3> values;
  for (const Point& p : b.mesh.points().data())
    values.push_back({p.x(), p.y(), p.z()});
  std::vector<V3> into_points = values;

  Mesh expected;
  S::Refiner<Mask>(Mask(), options)
    .template refine_and_interpolate<ConcurrencyTag>(b.mesh, n, values, expected, b.edge_sharpness,
                                                     b.vertex_sharpness, true);
  Mesh out;
  S::Refiner<Mask> r(Mask(), options);
  r.template refine_and_interpolate_points<S::internal::Point_values<Point>, ConcurrencyTag>(
    b.mesh, n, into_points, out, b.edge_sharpness, b.vertex_sharpness, true);
  EXPECT_TRUE(into_points.empty());
  EXPECT_EQ(r.number_of_levels(), 0u);
  ASSERT_TRUE(out.is_valid(true));
  ASSERT_EQ(out.number_of_vertices(), values.size());
  ASSERT_EQ(out.number_of_halfedges(), expected.number_of_halfedges());
  ASSERT_EQ(out.number_of_faces(), expected.number_of_faces());
  std::vector<V3> points;
  for (const Point& p : out.points().data())
    points.push_back({p.x(), p.y(), p.z()});
  EXPECT_EQ(std::memcmp(points.data(), values.data(), values.size() * sizeof(V3)), 0);
  for (auto h : out.halfedges()) {
    const CGAL_ext::Dart d(h, false);
    ASSERT_EQ(out.target(d), expected.target(d));
    ASSERT_EQ(out.next(d), expected.next(d));
    ASSERT_EQ(out.face(h), expected.face(h));
  }
  for (auto e : out.edges())
    ASSERT_EQ(out.is_mobius(e), expected.is_mobius(e));
  for (auto v : out.vertices())
    ASSERT_EQ(out.halfedge(v), expected.halfedge(v));
  auto holes = out.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  auto holes_expected = expected.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  ASSERT_EQ(holes.has_value(), holes_expected.has_value());
  if (holes) {
    EXPECT_EQ(holes->data(), holes_expected->data());
  }
  auto sharpness = [](const Mesh& m, auto key) {
    using Key = decltype(key);
    auto map = m.property_map<Key, float>(std::is_same_v<Key, CGAL_ext::Edge_index> ? CGAL_ext::edge_sharpness_name
                                                                                     : CGAL_ext::vertex_sharpness_name);
    return map ? map->data() : std::vector<float>{-1.0f}; // a missing map differs from every map
  };
  EXPECT_EQ(sharpness(out, CGAL_ext::Edge_index()), sharpness(expected, CGAL_ext::Edge_index()));
  EXPECT_EQ(sharpness(out, CGAL_ext::Vertex_index()), sharpness(expected, CGAL_ext::Vertex_index()));
}

TEST(SubdivisionApi, PointsWrittenInPlaceAreTheOnePassValues)
{
  auto each_tag = [](auto check) {
    check(CGAL::Sequential_tag());
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
    check(CGAL::Parallel_tag());
#endif
  };
  const Boundary_interpolation none = Boundary_interpolation::none;
  each_tag([&](auto tag) {
    using Tag = decltype(tag);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_edgecorner.obj", 2, &none); // holes
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_chaikin1.obj", 3);
    check_points_pass<S::Loop_mask, Tag>("opensubdiv/loop_triangle_edgeonly.obj", 2, &none);
    check_points_pass<Unequal_weights_mask<2>, Tag>("opensubdiv/catmark_cube_creases1.obj", 2); // two sums
    check_points_pass<Unequal_weights_mask<3>, Tag>("nonorientable/mobius_20x4_quads.obj", 2);  // three
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 3);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_edgecorner.obj", 3);
    check_points_pass<S::Catmull_clark_mask, Tag>("nonorientable/mobius_20x4_quads.obj", 3);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 1);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 0);
    check_points_pass<S::Loop_mask, Tag>("opensubdiv/loop_icos_semisharp.obj", 3);
    check_points_pass<S::Loop_mask, Tag>("nonorientable/mobius_20x4_tris.obj", 2);
    check_points_pass<S::Bilinear_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 2);
    check_points_pass<S::Linear_mask, Tag>("nonorientable/mobius_20x4_tris.obj", 2);
    check_points_pass<S::Doo_sabin_mask, Tag>("nonorientable/mobius_20x4_quads.obj", 2);
    check_points_pass<S::Sqrt3_mask, Tag>("opensubdiv/loop_icos_semisharp.obj", 3);
  });
}

TEST(SubdivisionApi, RefinerReinterpolatesOtherData)
{
  // Interpolating the points moved by a translation gives the translated
  // result: subdivision is affine invariant (weights sum to 1).
  Mesh m = load("nonorientable/mobius_20x4_quads.obj");
  S::Refiner<S::Catmull_clark_mask> r;
  r.refine(m, 3);
  std::vector<V3> base, moved, out1, out2, scratch;
  for (auto v : m.vertices()) {
    const Point& p = m.point(v);
    base.push_back({p.x(), p.y(), p.z()});
    moved.push_back({p.x() + 1.0, p.y() - 2.0, p.z() + 0.5});
  }
  r.interpolate(base, out1, scratch);
  r.interpolate(moved, out2, scratch);
  ASSERT_EQ(out1.size(), out2.size());
  double worst = 0;
  for (std::size_t i = 0; i < out1.size(); ++i)
    worst = std::max({worst, std::abs(out2[i].x - out1[i].x - 1.0), std::abs(out2[i].y - out1[i].y + 2.0),
                      std::abs(out2[i].z - out1[i].z - 0.5)});
  EXPECT_LE(worst, 1e-12);
  // A scalar field: constants stay constant.
  std::vector<double> ones(m.number_of_vertices(), 1.0), res, tmp;
  r.interpolate(ones, res, tmp);
  for (double x : res)
    EXPECT_NEAR(x, 1.0, 1e-14);
}

// interpolate() is const and writes nothing into the refiner: threads that
// share one refiner get the same bits as one thread alone.
TEST(SubdivisionApi, RefinerInterpolatesFromSeveralThreads)
{
  const Shape s = read_shape(test::data("opensubdiv/catmark_chaikin1.obj"));
  const Built b = build(s);
  S::Refinement_options options;
  options.crease_method = s.crease_method;
  options.parallel_min_vertices = 0; // incidence tables on every level
  S::Refiner<S::Catmull_clark_mask> r(S::Catmull_clark_mask(), options);
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  r.refine<CGAL::Parallel_tag>(b.mesh, 3, b.edge_sharpness, b.vertex_sharpness);
#else
  r.refine(b.mesh, 3, b.edge_sharpness, b.vertex_sharpness);
#endif
  std::vector<V3> base;
  for (auto v : b.mesh.vertices()) {
    const Point& p = b.mesh.point(v);
    base.push_back({p.x(), p.y(), p.z()});
  }
  std::vector<V3> expected;
  r.interpolate(base, expected);
  std::vector<std::vector<V3>> results(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < results.size(); ++i)
    threads.emplace_back([&, i]() {
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
      if (i % 2 == 1) {
        r.interpolate<CGAL::Parallel_tag>(base, results[i]);
        return;
      }
#endif
      r.interpolate(base, results[i]);
    });
  for (std::thread& t : threads)
    t.join();
  for (const std::vector<V3>& result : results) {
    ASSERT_EQ(result.size(), expected.size());
    EXPECT_EQ(std::memcmp(result.data(), expected.data(), expected.size() * sizeof(V3)), 0);
  }
}

// Doo–Sabin's vertex faces are oriented against most of the edge quads
// around them, so the Möbius edges do not multiply from level to level. A
// strip needs at least one Möbius edge per row of faces across it (a seam
// from border to border), and a step makes 2r − 1 rows of r (the faces and
// the quads of the edges between them): on a 12×3 Möbius strip the counts
// are 3, 5, 9, 17, that minimum, where orienting the vertex faces like most
// of their faces gave 3, 9, 13, 37. The surface stays a one-sided strip.
TEST(SubdivisionMobius, DooSabinKeepsFewMobiusEdges)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3);
  const std::size_t base = CGAL_ext::number_of_mobius_edges(m);
  ASSERT_EQ(base, 3u);
  ASSERT_EQ(CGAL_ext::euler_characteristic(m), 0);
  std::vector<std::size_t> counts{base};
  for (int level = 1; level <= 3; ++level) {
    S::doo_sabin(m);
    ASSERT_TRUE(m.is_valid(true));
    counts.push_back(CGAL_ext::number_of_mobius_edges(m));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  }
  for (std::size_t k = 1; k < counts.size(); ++k)
    EXPECT_LE(counts[k], 2 * counts[k - 1] - 1) << ::testing::PrintToString(counts);
  // An orientable mesh stays without Möbius edges.
  Mesh torus;
  CGAL_ext::make_torus(torus, 8, 6);
  S::doo_sabin(torus, CGAL_ext::parameters::number_of_iterations(2));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(torus), 0u);
  EXPECT_TRUE(CGAL_ext::is_orientable(torus));
}

} // namespace

// ----------------------------------------------------------------- sizes

namespace {

CGAL_ext::Mesh_size counts(const Mesh& m)
{
  CGAL_ext::Mesh_size s{m.number_of_vertices(), m.number_of_edges(), m.number_of_faces(), 0};
  for (auto e : m.edges())
    s.border_edges += m.is_border(e) ? 1 : 0;
  return s;
}

} // namespace

// The limit, from the dart encoding by hand: the flipped dart of the last
// halfedge of edge e is 4e + 3, which must stay below the null dart 2^32 - 1.
TEST(MeshSize, EdgeLimitIsTheLastEdgeWithDarts)
{
  namespace X = CGAL_ext;
  const unsigned long long last = X::internal::max_edges - 1; // the last edge index
  EXPECT_EQ(X::internal::max_edges, (1ull << 30) - 1);
  EXPECT_LT(4 * last + 3, 0xFFFFFFFFull);
  EXPECT_EQ(4 * (last + 1) + 3, 0xFFFFFFFFull); // one edge more: its dart is the null dart
  EXPECT_NE(X::Dart(X::Halfedge_index(std::uint32_t(2 * last + 1)), true), X::Dart());
  X::Mesh_size most, one_more, vertices;
  most.edges = X::internal::max_edges;
  one_more.edges = X::internal::max_edges + 1;
  vertices.vertices = 1ull << 32;
  EXPECT_NO_THROW(X::internal::check_mesh_size("test", most));
  EXPECT_THROW(X::internal::check_mesh_size("test", one_more), X::Size_error);
  EXPECT_THROW(X::internal::check_mesh_size("test", vertices), X::Size_error);
}

// Twelve levels of a strip of 80 quads need about 2.7e9 edges, past the
// 2^30 - 1 that darts index: refused, from counts computed by closed forms,
// before anything is allocated (under ASan, allocating them would abort).
TEST(MeshSize, SubdivisionPastTheLimitIsRefusedBeforeAllocating)
{
  Mesh quads;
  CGAL_ext::make_mobius_strip(quads, 40, 2);
  const CGAL_ext::Mesh_size q0 = counts(quads);
  ASSERT_EQ(q0.faces, 80u);
  const unsigned long long c0 = 4 * q0.faces; // corners
  const long long chi = CGAL_ext::euler_characteristic(quads);
  // Catmull–Clark: all faces quads after one step, F_k = c0 4^(k-1),
  // E_k = 2^k E0 + c0 (4^k - 2^k) / 2, the border doubles, chi is kept.
  for (unsigned k : {1u, 2u, 7u, 11u, 12u}) {
    const auto s = S::refined_size(S::Split::quad, q0, k);
    const unsigned long long p2 = 1ull << k, p4 = 1ull << (2 * k);
    EXPECT_EQ(s.faces, c0 * p4 / 4) << k;
    EXPECT_EQ(s.edges, p2 * q0.edges + c0 * (p4 - p2) / 2) << k;
    EXPECT_EQ(s.border_edges, p2 * q0.border_edges) << k;
    EXPECT_EQ((long long)(s.vertices + s.faces) - (long long)s.edges, chi) << k;
  }
  const unsigned long long e12 = 4096 * q0.edges + c0 * ((1ull << 24) - 4096) / 2;
  EXPECT_GT(e12, 2'600'000'000ull);
  // One level in the real refinement against the closed form.
  Mesh once = quads;
  S::catmull_clark(once);
  EXPECT_EQ(once.number_of_edges(), 2 * q0.edges + c0);
  EXPECT_EQ(once.number_of_vertices(), S::refined_size(S::Split::quad, q0, 1).vertices);

  S::Refiner<S::Catmull_clark_mask> refiner;
  try {
    refiner.refine(quads, 12);
    ADD_FAILURE() << "no Size_error";
  } catch (const CGAL_ext::Size_error& e) {
    EXPECT_EQ(e.element(), "edges");
    EXPECT_EQ(e.count(), e12);
    EXPECT_EQ(e.limit(), (1ull << 30) - 1);
    EXPECT_NE(std::string(e.what()).find(std::to_string(e12)), std::string::npos) << e.what();
  }
  const Mesh before = quads;
  EXPECT_THROW(S::catmull_clark(quads, CGAL_ext::parameters::number_of_iterations(12)), CGAL_ext::Size_error);
  EXPECT_EQ(quads.number_of_edges(), before.number_of_edges());
  // A thousand levels: the estimate stops at the first level past the limit, nothing wraps.
  EXPECT_THROW(S::catmull_clark(quads, CGAL_ext::parameters::number_of_iterations(1000)), CGAL_ext::Size_error);

  // Loop on 160 triangles: F_k = 4^k F0, E_k = 2^k E0 + 3 F0 (4^k - 2^k) / 2.
  Mesh triangles;
  CGAL_ext::make_mobius_strip(triangles, 40, 2, 1, 1.0, 0.5, false);
  const CGAL_ext::Mesh_size t0 = counts(triangles);
  ASSERT_EQ(t0.faces, 160u);
  const auto t12 = S::refined_size(S::Split::triangle, t0, 12);
  EXPECT_EQ(t12.faces, (1ull << 24) * t0.faces);
  EXPECT_EQ(t12.edges, 4096 * t0.edges + 3 * t0.faces * ((1ull << 24) - 4096) / 2);
  EXPECT_THROW(S::loop(triangles, CGAL_ext::parameters::number_of_iterations(12)), CGAL_ext::Size_error);
  // Doo–Sabin and √3: upper bounds, refused alike.
  EXPECT_THROW(S::doo_sabin(quads, CGAL_ext::parameters::number_of_iterations(40)), CGAL_ext::Size_error);
  EXPECT_THROW(S::sqrt3(triangles, CGAL_ext::parameters::number_of_iterations(40)), CGAL_ext::Size_error);
}

// Memory: the estimate is refused up front, naming the gigabytes, and the
// mesh is unchanged. Twelve Catmull–Clark levels of a cube make 6 * 4^12 =
// 100 663 296 quads, which index (201 M edges) but take about 10 GB.
bool same_points(const Mesh& a, const Mesh& b)
{
  if (a.number_of_vertices() != b.number_of_vertices())
    return false;
  for (CGAL_ext::Vertex_index v : a.vertices())
    if (a.point(v) != b.point(v))
      return false;
  return true;
}

TEST(MeshSize, SubdivisionPastTheMemoryLimitIsRefusedBeforeAllocating)
{
  Mesh cube;
  CGAL_ext::polygon_soup_to_mobius_mesh(
    std::vector<Point>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
    std::vector<std::vector<std::size_t>>{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                          {3, 0, 4, 7}},
    cube);
  const Mesh before = cube;
  const auto started = std::chrono::steady_clock::now();
  try {
    S::catmull_clark(cube, CGAL_ext::parameters::number_of_iterations(12).maximum_memory(1e9));
    ADD_FAILURE() << "no Size_error";
  } catch (const CGAL_ext::Size_error& e) {
    EXPECT_EQ(e.element(), "bytes");
    EXPECT_EQ(e.limit(), 1'000'000'000ull);
    // At least the result's points and two halfedges of four indices per edge.
    const unsigned long long quads = 6ull << 24, edges = 2 * quads, vertices = quads + 2;
    EXPECT_GE(e.count(), vertices * sizeof(Point) + edges * 2 * 16) << e.what();
    EXPECT_NE(std::string(e.what()).find("GB of memory"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1.0);
  EXPECT_TRUE(same_points(cube, before));
  EXPECT_EQ(cube.number_of_faces(), 6u);

  // Every scheme reads the limit; a limit that is not positive is refused.
  Mesh triangles;
  CGAL_ext::make_mobius_strip(triangles, 40, 2, 1, 1.0, 0.5, false);
  const auto tight = CGAL_ext::parameters::number_of_iterations(6).maximum_memory(1e6);
  EXPECT_THROW(S::loop(triangles, tight), CGAL_ext::Size_error);
  EXPECT_THROW(S::sqrt3(triangles, tight), CGAL_ext::Size_error);
  EXPECT_THROW(S::doo_sabin(cube, tight), CGAL_ext::Size_error);
  EXPECT_THROW(S::bilinear(cube, tight), CGAL_ext::Size_error);
  for (const double bad : {0.0, -1.0, std::nan("")}) {
    try {
      S::catmull_clark(cube, CGAL_ext::parameters::maximum_memory(bad));
      ADD_FAILURE() << "no error for maximum_memory " << bad;
    } catch (const CGAL_ext::Size_error& e) {
      ADD_FAILURE() << "maximum_memory " << bad << " taken as a limit: " << e.what();
    } catch (const CGAL_ext::Parameter_error& e) {
      EXPECT_NE(std::string(e.what()).find("maximum_memory"), std::string::npos) << e.what();
    }
  }
  // Within the limit, the same result as without one.
  Mesh limited = cube, unlimited = cube;
  S::catmull_clark(limited, CGAL_ext::parameters::number_of_iterations(2).maximum_memory(1e6));
  S::catmull_clark(unlimited, CGAL_ext::parameters::number_of_iterations(2));
  EXPECT_TRUE(same_points(limited, unlimited));

  // By default the limit is the memory available: 13 levels of a cube
  // (403 M quads, 805 M edges: indexable) need about 40 GB.
  const double available = CGAL_ext::internal::available_memory();
  EXPECT_GT(available, 0);
  EXPECT_LE(available, CGAL_ext::internal::physical_memory());
  if (available > 45e9)
    GTEST_SKIP() << "this machine has " << available / 1e9 << " GB available: 13 levels of a cube may fit";
  EXPECT_THROW(S::catmull_clark(cube, CGAL_ext::parameters::number_of_iterations(13)), CGAL_ext::Size_error);
}

// A Refiner used directly reads the same limit from its options, in both of
// its ways of refining, and keeps nothing of a refused refinement.
TEST(MeshSize, RefinerPastItsMemoryLimitIsRefusedBeforeAllocating)
{
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 40, 2, 1, 1.0, 0.5, false);
  S::Refinement_options options;
  options.maximum_memory = 1e6;
  S::Refiner<S::Catmull_clark_mask> refiner(S::Catmull_clark_mask(), options);
  refiner.refine(strip, 1); // 320 quads: well under a megabyte
  ASSERT_EQ(refiner.number_of_levels(), 1u);
  // 7 levels: 80 * 4^7 = 1.3 M quads, at least 1.3 M points of 24 bytes.
  const unsigned long long points = 80ull << 14;
  try {
    refiner.refine(strip, 7);
    ADD_FAILURE() << "no Size_error from refine()";
  } catch (const CGAL_ext::Size_error& e) {
    EXPECT_EQ(e.element(), "bytes");
    EXPECT_EQ(e.limit(), 1'000'000ull);
    EXPECT_GE(e.count(), points * sizeof(Point)) << e.what();
  }
  EXPECT_EQ(refiner.number_of_levels(), 1u) << "the refused call kept nothing of its own";
  std::vector<V3> values(strip.number_of_vertices(), V3{0, 0, 0});
  const std::vector<V3> before = values;
  Mesh out;
  EXPECT_THROW(refiner.refine_and_interpolate(strip, 7, values, out), CGAL_ext::Size_error);
  EXPECT_EQ(values.size(), before.size());
  EXPECT_EQ(out.number_of_vertices(), 0u);
  options.maximum_memory = 0;
  EXPECT_THROW(S::Refiner<S::Catmull_clark_mask>(S::Catmull_clark_mask(), options).refine(strip, 1),
               CGAL_ext::Parameter_error);
}

// ----------------------------------------------------------------- property maps

// Every rule's weights sum to one, and the maps take the points' weights: a
// map that is an affine function of the points is, after subdivision, that
// function of the new points (at borders and creases too). Checked against
// the function evaluated on the result's points.
TEST(SubdivisionMaps, VertexMapsFollowTheirAffineFunctionOfThePoints)
{
  auto scalar = [](const Point& p) { return 2 * p.x() - 3 * p.y() + 0.5 * p.z() + 1; };
  auto colour = [](const Point& p) {
    return std::array<double, 3>{0.5 + 0.1 * p.x(), 0.5 + 0.1 * (p.y() + p.z()), 1 - 0.2 * p.z()};
  };
  auto with_maps = [&](Mesh m) {
    auto s = m.add_property_map<CGAL_ext::Vertex_index, double>("v:scalar").first;
    auto c = m.add_property_map<CGAL_ext::Vertex_index, std::array<double, 3>>("v:colour").first;
    auto rest = m.add_property_map<CGAL_ext::Vertex_index, Point>("v:rest", CGAL::ORIGIN).first;
    auto id = m.add_property_map<CGAL_ext::Vertex_index, int>("v:id").first;
    for (auto v : m.vertices()) {
      s[v] = scalar(m.point(v));
      c[v] = colour(m.point(v));
      rest[v] = m.point(v);
      id[v] = int(v.idx());
    }
    return m;
  };
  auto check = [&](const Mesh& m, const std::string& what) {
    const auto s = m.property_map<CGAL_ext::Vertex_index, double>("v:scalar");
    const auto c = m.property_map<CGAL_ext::Vertex_index, std::array<double, 3>>("v:colour");
    const auto rest = m.property_map<CGAL_ext::Vertex_index, Point>("v:rest");
    ASSERT_TRUE(s && c && rest) << what;
    double worst = 0;
    for (auto v : m.vertices()) {
      const Point& p = m.point(v);
      worst = std::max(worst, std::abs((*s)[v] - scalar(p)));
      for (int i = 0; i < 3; ++i)
        worst = std::max(worst, std::abs((*c)[v][i] - colour(p)[i]));
      worst = std::max(worst, std::sqrt(CGAL::squared_distance((*rest)[v], p)));
    }
    EXPECT_LE(worst, 1e-12) << what;
    // Integers have no linear combination: the map is dropped.
    EXPECT_FALSE((m.property_map<CGAL_ext::Vertex_index, int>("v:id"))) << what;
  };
  Mesh klein;
  CGAL_ext::make_klein_bottle(klein, 8, 6);
  Mesh cc = with_maps(klein);
  S::catmull_clark(cc, CGAL_ext::parameters::number_of_iterations(2));
  ASSERT_EQ(cc.number_of_faces(), 16 * klein.number_of_faces());
  check(cc, "Catmull-Clark, Klein bottle");

  Mesh strip; // triangles, with a border and a crease
  CGAL_ext::make_mobius_strip(strip, 12, 3, 1, 1.0, 0.5, false);
  Mesh lp = with_maps(strip);
  auto sharp = lp.add_property_map<CGAL_ext::Edge_index, float>("e:sharpness", 0.0f).first;
  sharp[CGAL_ext::Edge_index(std::uint32_t(5))] = 2.0f;
  S::loop(lp, CGAL_ext::parameters::number_of_iterations(2));
  ASSERT_EQ(lp.number_of_faces(), 16 * strip.number_of_faces());
  check(lp, "Loop, Möbius strip with a crease");
}

// Each child face takes the value of the face it lies in. The parent is
// read off the result's vertices by the documented layout: Catmull–Clark
// gives face f the vertex nv + ne + f, one per child face; a Loop child face
// has two edge points (nv + e) of two edges of its parent.
TEST(SubdivisionMaps, FaceMapsGoToTheChildFaces)
{
  auto label = [](std::size_t f) { return int(7 * f + 1); };
  auto with_maps = [&](Mesh m) {
    auto l = m.add_property_map<CGAL_ext::Face_index, int>("f:label").first;
    auto n = m.add_property_map<CGAL_ext::Face_index, std::string>("f:name").first;
    for (auto f : m.faces()) {
      l[f] = label(f.idx());
      n[f] = "face " + std::to_string(f.idx());
    }
    return m;
  };
  {
    Mesh torus;
    CGAL_ext::make_torus(torus, 5, 4);
    const std::size_t nv = torus.number_of_vertices(), ne = torus.number_of_edges();
    Mesh m = with_maps(torus);
    S::catmull_clark(m);
    const auto l = m.property_map<CGAL_ext::Face_index, int>("f:label");
    const auto n = m.property_map<CGAL_ext::Face_index, std::string>("f:name");
    ASSERT_TRUE(l && n);
    for (auto g : m.faces()) {
      std::vector<std::size_t> face_points;
      for (auto v : CGAL_ext::vertices_around_face(m.halfedge(g), m))
        if (v.idx() >= nv + ne)
          face_points.push_back(v.idx() - nv - ne);
      ASSERT_EQ(face_points.size(), 1u);
      EXPECT_EQ((*l)[g], label(face_points[0]));
      EXPECT_EQ((*n)[g], "face " + std::to_string(face_points[0]));
    }
  }
  {
    Mesh strip;
    CGAL_ext::make_mobius_strip(strip, 6, 2, 1, 1.0, 0.5, false);
    const std::size_t nv = strip.number_of_vertices();
    auto faces_of_edge = [&](std::size_t e) {
      std::set<std::size_t> faces;
      for (int i : {0, 1}) {
        const auto f = strip.face(Mesh::halfedge(CGAL_ext::Edge_index(std::uint32_t(e)), i));
        if (f.is_valid())
          faces.insert(f.idx());
      }
      return faces;
    };
    Mesh m = with_maps(strip);
    S::loop(m);
    const auto l = m.property_map<CGAL_ext::Face_index, int>("f:label");
    ASSERT_TRUE(l);
    for (auto g : m.faces()) {
      std::vector<std::size_t> edges;
      for (auto v : CGAL_ext::vertices_around_face(m.halfedge(g), m))
        if (v.idx() >= nv)
          edges.push_back(v.idx() - nv);
      ASSERT_GE(edges.size(), 2u);
      const auto a = faces_of_edge(edges[0]), b = faces_of_edge(edges[1]);
      std::vector<std::size_t> common;
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
      ASSERT_EQ(common.size(), 1u);
      EXPECT_EQ((*l)[g], label(common[0]));
    }
  }
}

} // namespace subdivision_tests
