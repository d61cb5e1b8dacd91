// Limit positions, tangents and normals (Subdivision/limit.h): against
// OpenSubdiv's Far::PrimvarRefiner::Limit() on its regression shapes, against
// the orientation double cover for one-sided surfaces, against closed forms in
// exact arithmetic, and bad input refused.
#include "subdivision_shapes.h"
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>
#include <CGAL_ext/Subdivision/limit.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace limit_tests {

namespace {

using namespace subdivision_shapes;

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
double relative_gap(const Point& p, const double* q)
{
  const double scale = std::max({1.0, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
  return std::max({std::abs(p.x() - q[0]), std::abs(p.y() - q[1]), std::abs(p.z() - q[2])}) / scale;
}
double relative_gap(const test::Kd::Vector_3& p, const double* q)
{
  return relative_gap(Point(p.x(), p.y(), p.z()), q);
}
std::array<double, 3> unit_cross(const double* a, const double* b)
{
  std::array<double, 3> c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for (double& x : c)
    x /= l;
  return c;
}

// The dart of `m` ending at `v` whose face holds the edges to `first` (leaving
// v, first in the walk) and from `second`: OpenSubdiv's first face of v.
CGAL_ext::Dart dart_of_first_face(const Mesh& m, CGAL_ext::Vertex_index v, CGAL_ext::Vertex_index first,
                                  CGAL_ext::Vertex_index second)
{
  for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(v, m))
    if (!m.is_border(d) && m.target(m.next(d)) == first && m.source(d) == second)
      return d;
  ADD_FAILURE() << "no face at v" << v.idx() << " from v" << first.idx() << " to v" << second.idx();
  return CGAL_ext::Dart();
}

// Our limit points, tangents and normals on level `k` of `b` against
// OpenSubdiv's Far::PrimvarRefiner::Limit() on level k of `osd_shape` (the
// shape itself, `map` the identity, or its double cover, `map` the twins).
// Tangents and normals are compared one for one on the shape itself, seen
// from OpenSubdiv's first face; on a double cover (no creases), the unit
// normal of limit_normals() at each vertex is one of its twins'.
template <class Mask>
void compare_limit(const Built& b, const Shape& osd_shape, const Shape& tags, Mask mask, Sdc::SchemeType type,
                   unsigned k, Vertex_map map)
{
  SCOPED_TRACE("level " + std::to_string(k));
  const bool quad = Mask::split == S::Split::quad;
  S::Refinement_options options;
  options.boundary_interpolation = tags.boundary;
  options.crease_method = tags.crease_method;
  S::Refiner<Mask> r(mask, options);
  const auto ours = our_levels(r, b, k);
  const Osd_run osd = run_opensubdiv(osd_shape, tags, type, int(k));
  for (unsigned j = 0; j < k; ++j)
    map = child_map(S::internal::level_of(r, j), map, osd.refiner->GetLevel(int(j)), quad);
  Mesh m;
  r.build_mesh(m, true);
  for (CGAL_ext::Vertex_index v : m.vertices())
    m.point(v) = Point(ours[k][v.idx()].x, ours[k][v.idx()].y, ours[k][v.idx()].z);

  const std::size_t n = osd.levels[k].size();
  std::vector<Osd_vertex> position(n), tangent1(n), tangent2(n);
  Far::PrimvarRefinerReal<double>(*osd.refiner).Limit(osd.levels[k], position, tangent1, tangent2);
  const auto np = CGAL_ext::parameters::boundary_interpolation(tags.boundary);
  auto limit = m.add_property_map<CGAL_ext::Vertex_index, Point>("v:limit", Point(0, 0, 0)).first;
  S::limit_points<Mask>(m, limit, np);
  using Vector = test::Kd::Vector_3;
  auto normal = m.add_property_map<CGAL_ext::Vertex_index, Vector>("v:limit_normal", Vector(0, 0, 0)).first;
  S::limit_normals<Mask>(m, normal, np.normalize(true));

  const Far::TopologyLevel& level = osd.refiner->GetLevel(int(k));
  std::vector<int> back(n, -1);
  for (std::size_t v = 0; v < map.size(); ++v)
    for (int x : map[v])
      back[x] = int(v);
  double worst_point = 0, worst_tangent = 0, worst_normal = 0;
  for (CGAL_ext::Vertex_index v : m.vertices()) {
    for (int x : map[v.idx()])
      worst_point = std::max(worst_point, relative_gap(limit[v], position[x].p));
    const int x = map[v.idx()][0];
    if (level.GetVertexFaces(x).size() == 0)
      continue;
    if (map[v.idx()].size() == 1) {
      auto other_end = [&](int e) {
        const auto ev = level.GetEdgeVertices(level.GetVertexEdges(x)[e]);
        return CGAL_ext::Vertex_index(back[ev[0] == x ? ev[1] : ev[0]]);
      };
      const CGAL_ext::Dart d = dart_of_first_face(m, v, other_end(0), other_end(1));
      const auto t = S::limit_tangents<Mask>(d, m, np);
      worst_tangent = std::max({worst_tangent, relative_gap(t.tangent1, tangent1[x].p),
                                relative_gap(t.tangent2, tangent2[x].p)});
      // A crease vertex has a normal on each side of the crease: the one of
      // the span the walk from OpenSubdiv's first edge meets first.
      const auto o = unit_cross(tangent1[x].p, tangent2[x].p);
      worst_normal = std::max(worst_normal, relative_gap(S::limit_normal<Mask>(d, m, np.normalize(true)), o.data()));
      continue;
    }
    double gap = 2.0; // on a double cover: one of the two twins' normals
    for (int y : map[v.idx()]) {
      const auto o = unit_cross(tangent1[y].p, tangent2[y].p);
      gap = std::min(gap, relative_gap(normal[v], o.data()));
    }
    worst_normal = std::max(worst_normal, gap);
  }
  EXPECT_LE(worst_point, 1e-12);
  EXPECT_LE(worst_tangent, 1e-12);
  EXPECT_LE(worst_normal, 1e-11);
}

template <class Mask>
void check_limit_shape(const std::string& name, Mask mask, Sdc::SchemeType type, unsigned first_level)
{
  SCOPED_TRACE(name);
  const Shape s = read_shape(test::data("opensubdiv/" + name));
  const Built b = build(s);
  for (unsigned k = first_level; k <= 2; ++k)
    compare_limit(b, s, s, mask, type, k, identity_map(s.points.size()));
}
#endif

TEST(SubdivisionLimit, CatmullClarkMatchesOpenSubdiv)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_cube.obj", "catmark_cube_corner4.obj", "catmark_cube_creases1.obj",
                           "catmark_chaikin1.obj", "catmark_edgecorner.obj", "catmark_torus_creases1.obj"})
    check_limit_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 0);
  // Faces of other degrees: from level 1 on, where every face is a quad.
  for (const char* name : {"catmark_nonquads.obj", "catmark_pole64.obj"})
    check_limit_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 1);
#endif
}

TEST(SubdivisionLimit, LoopMatchesOpenSubdiv)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"loop_tetrahedron.obj", "loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"})
    check_limit_shape(name, S::Loop_mask(), Sdc::SCHEME_LOOP, 0);
#endif
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// A one-sided surface against its orientation double cover: the same limit
// points, and each vertex's limit normal one of its twins'; the normal seen
// from the other side of a face is the opposite one.
template <class Mask>
void check_limit_cover(const std::string& file, Mask mask, Sdc::SchemeType type)
{
  SCOPED_TRACE(file);
  const Shape s = read_shape(test::data(file));
  const Built b = build(s);
  ASSERT_FALSE(CGAL_ext::is_orientable(b.mesh));
  Shape tags;
  const Shape cover = double_cover(b.mesh, b, &tags);
  Vertex_map twins(s.points.size());
  for (std::size_t v = 0; v < twins.size(); ++v)
    twins[v] = {int(2 * v), int(2 * v + 1)};
  for (unsigned k : {1u, 2u})
    compare_limit(b, cover, tags, mask, type, k, twins);

  Mesh m = b.mesh;
  S::catmull_clark(m); // a quad mesh either way; its Möbius edges are crossed below
  ASSERT_GT(CGAL_ext::number_of_mobius_edges(m), 0u);
  double worst = 0.0;
  const auto unit = CGAL_ext::parameters::normalize(true);
  for (CGAL_ext::Face_index f : m.faces())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const auto n = S::limit_normal<S::Catmull_clark_mask>(d, m, unit);
      const auto other_side = S::limit_normal<S::Catmull_clark_mask>(m.next(d).flipped(), m, unit);
      worst = std::max(worst, std::sqrt(CGAL::to_double((n + other_side).squared_length())));
    }
  EXPECT_LE(worst, 1e-12);
}
#endif

TEST(SubdivisionLimit, OneSidedSurfacesMatchTheirDoubleCover)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* f : {"nonorientable/mobius_20x4_quads.obj", "nonorientable/klein_fig8_24x12_quads.obj"})
    check_limit_cover(f, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK);
  check_limit_cover("nonorientable/mobius_20x4_tris.obj", S::Loop_mask(), Sdc::SCHEME_LOOP);
#endif
}

TEST(SubdivisionLimit, WrongFacesAndBorderDartsAreRefused)
{
  const Shape s = read_shape(test::data("opensubdiv/catmark_nonquads.obj"));
  Mesh mesh = build(s).mesh;
  const std::vector<Point> before(mesh.points().data().begin(), mesh.points().data().end());
  auto points = mesh.points(); // all are computed before any is written: none is, on failure
  EXPECT_THROW(S::limit_points<S::Catmull_clark_mask>(mesh, points), CGAL_ext::Parameter_error);
  EXPECT_THROW(S::limit_points<S::Loop_mask>(mesh, points), CGAL_ext::Parameter_error);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), mesh.points().data().begin()));
  // A sharpness that is no number of levels is refused, naming the element.
  Mesh quads;
  CGAL_ext::make_torus(quads, 6, 4);
  const std::vector<Point> quads_before(quads.points().data().begin(), quads.points().data().end());
  for (const bool on_edge : {true, false}) {
    Mesh m = quads;
    if (on_edge)
      CGAL_ext::edge_sharpness_map(m)[CGAL_ext::Edge_index(4)] = std::nanf("");
    else
      CGAL_ext::vertex_sharpness_map(m)[CGAL_ext::Vertex_index(6)] = -1.0f;
    auto m_points = m.points();
    try {
      S::limit_points<S::Catmull_clark_mask>(m, m_points);
      ADD_FAILURE() << "a NaN or negative sharpness was read";
    } catch (const CGAL_ext::Parameter_error& e) {
      EXPECT_NE(std::string(e.what()).find(on_edge ? "edge e4 " : "vertex v6 "), std::string::npos) << e.what();
    }
    EXPECT_TRUE(std::equal(quads_before.begin(), quads_before.end(), m.points().data().begin()));
  }
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 8, 2);
  for (CGAL_ext::Halfedge_index h : strip.halfedges())
    if (strip.is_border(h)) {
      EXPECT_THROW(S::limit_normal<S::Catmull_clark_mask>(CGAL_ext::Dart(h), strip), CGAL_ext::Parameter_error);
      break;
    }
}

} // namespace

// Closed forms in exact arithmetic: the Catmull–Clark limit of a cube's
// corner is (3/8) V + (1/6) Σ neighbours + (1/24) Σ opposite corners, which
// is (1/4, 1/4, 1/4) at the origin of the unit cube; the Loop limit of a
// vertex of valence 4 is (1 − 4χ) V + χ Σ neighbours with χ = 31/220
// (Loop's β = 31/256), so (24/55, 0, 0) at (1, 0, 0) of the octahedron.
TEST(SubdivisionLimit, ExactClosedForms)
{
  using K = test::Epeck;
  using FT = K::FT;
  const auto cube = unit_cube<K>();
  EXPECT_EQ(S::limit_point<S::Catmull_clark_mask>(CGAL_ext::Vertex_index(0), cube),
            K::Point_3(FT(1) / 4, FT(1) / 4, FT(1) / 4));
  EXPECT_EQ(S::limit_point<S::Catmull_clark_mask>(CGAL_ext::Vertex_index(6), cube),
            K::Point_3(FT(3) / 4, FT(3) / 4, FT(3) / 4));
  std::vector<K::Point_3> points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<std::size_t, 3>> faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  CGAL_ext::Mobius_mesh<K::Point_3> octahedron;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, octahedron);
  EXPECT_EQ(S::limit_point<S::Loop_mask>(CGAL_ext::Vertex_index(0), octahedron),
            K::Point_3(FT(24) / 55, 0, 0));
  // By symmetry the limit normal at a vertex of the octahedron is radial.
  const auto n = S::limit_normal<S::Loop_mask>(CGAL_ext::internal::vertex_side_dart(CGAL_ext::Vertex_index(0),
                                                                                    octahedron),
                                               octahedron);
  EXPECT_GT(CGAL::to_double(n.x()), 0.0);
  EXPECT_LE(std::abs(CGAL::to_double(n.y())) + std::abs(CGAL::to_double(n.z())), 1e-12 * CGAL::to_double(n.x()));
}

} // namespace limit_tests
