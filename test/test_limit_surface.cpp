// The limit surface at any point, Catmull–Clark and Loop: against
// OpenSubdiv 3.5's Bfr (surface factory on a Far refiner, same options) at a
// grid of parameters in every face of its regression shapes; against the
// closed-form bicubic B-spline (quartic box spline) on a regular torus, in
// double and exactly with rationals; against limit_point() at the corners;
// and a Möbius strip against Bfr on its orientation double cover.
#include "opensubdiv_tags.h"
#include "same_mesh.h"
#include "test_util.h"
#include "uv_grid.h"

#include <CGAL_ext/Limit_surface.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Subdivision/limit.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/tags.h>

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace limit_surface_tests {

namespace {

namespace S = CGAL_ext::Subdivision;
using K = test::Kd;
using Point = K::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using Surface = S::Limit_surface<S::Catmull_clark_mask, Point>;
using Loop_surface = S::Limit_surface<S::Loop_mask, Point>;

// An OBJ file with OpenSubdiv's tags.
struct Shape : test::Osd_tags
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
};

Shape read_shape(const std::string& file)
{
  Shape s;
  const bool opened = test::read_obj_lines(
    file, [&](double x, double y, double z) { s.points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& f) { s.faces.push_back(f); },
    [&](const std::string& tag, const std::string&, std::istream& ls) {
      if (tag == "t")
        s.read(ls);
    });
  EXPECT_TRUE(opened) << file;
  return s;
}

// The mesh of a shape with its sharpness in the mesh's own maps.
Mesh build(const Shape& s)
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m);
  s.add_sharpness_maps(m);
  return m;
}

double largest_coordinate(const Mesh& m)
{
  double b = 0;
  for (const Point& p : m.points().data())
    b = std::max({b, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
  return b;
}

// A figure for the test report, in scientific notation.
std::string sci(double x)
{
  std::ostringstream o;
  o << std::scientific << std::setprecision(1) << x;
  return o.str();
}

double gap(const K::Vector_3& a, const double b[3])
{
  return std::max({std::abs(a.x() - b[0]), std::abs(a.y() - b[1]), std::abs(a.z() - b[2])});
}

// Bfr's row length of the sub-faces of an n-gon.
int sub_face_row(int n) { return n < 10 ? (2 + (n > 4)) : (1 + int(std::sqrt(float(n - 1)))); }

// The parameters of a grid of (k + 1)² points in each quad or sub-face of a face of n sides.
std::vector<std::array<double, 2>> parameter_grid(int n, int k)
{
  std::vector<std::array<double, 2>> uv;
  const int subs = n == 4 ? 1 : n, row = sub_face_row(n);
  for (int s = 0; s < subs; ++s)
    for (int i = 0; i <= k; ++i)
      for (int j = 0; j <= k; ++j) {
        double u = double(i) / k, v = double(j) / k;
        if (n != 4) {
          u = s % row + 0.5 * u;
          v = s / row + 0.5 * v;
        }
        uv.push_back({u, v});
      }
  return uv;
}

// The parameters (i / k, j / k), i + j <= k, of a triangle (Loop).
std::vector<std::array<double, 2>> triangle_grid(int k)
{
  std::vector<std::array<double, 2>> uv;
  for (int i = 0; i <= k; ++i)
    for (int j = 0; i + j <= k; ++j)
      uv.push_back({double(i) / k, double(j) / k});
  return uv;
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
namespace Far = OpenSubdiv::Far;
namespace Bfr = OpenSubdiv::Bfr;
namespace Sdc = OpenSubdiv::Sdc;

// The descriptor of faces (`sizes`, `indices`) over `vertices` vertices
// with creases (pairs of vertices, and values); the arrays outlive it.
Far::TopologyDescriptor descriptor(int vertices, const std::vector<int>& sizes, const std::vector<int>& indices,
                                   const std::vector<int>& crease_indices, const std::vector<float>& crease_values)
{
  Far::TopologyDescriptor desc;
  desc.numVertices = vertices;
  desc.numFaces = int(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  desc.numCreases = int(crease_values.size());
  desc.creaseVertexIndexPairs = crease_indices.data();
  desc.creaseWeights = crease_values.data();
  return desc;
}

// A surface evaluated from one chosen dart of each face (the face's frame
// turned), for against_bfr().
template <class Surf>
struct From_darts
{
  const Surf& surface;
  std::vector<CGAL_ext::Dart> dart; // by face
  auto evaluate(CGAL_ext::Face_index f, double u, double v) const { return surface.evaluate(dart[f.idx()], u, v); }
  bool is_hole(CGAL_ext::Face_index f) const { return surface.is_hole(f); }
};

template <class Surf>
struct Is_loop : std::is_same<Surf, Loop_surface>
{};
template <class Surf>
struct Is_loop<From_darts<Surf>> : Is_loop<Surf>
{};

struct Differences
{
  double position = 0, first = 0, second = 0;
  // The same off the corners of the faces and of their sub-faces (parameters
  // that are multiples of 1/2): a Gregory patch there blends two interior
  // points by weights 0/0, which a face seen the other way round takes the
  // other way.
  double second_off_corners = 0;
  // Loop: OpenSubdiv 3.5's EvaluatePatchBasis scales the second derivatives
  // of a sub-triangle turned half a turn (the middle child of a triangle) by
  // -(2^depth)² instead of (2^depth)², so Bfr's second derivatives there
  // have the wrong sign; this compares them up to sign.
  double second_up_to_sign = 0;
  std::size_t holes = 0; // faces without a surface in both (Boundary_interpolation::none)
};

// Bfr on the faces, creases and corners of `faces` / the maps of `m`
// (which share the vertex numbering), against `surface` on the faces of `m`:
// `face_of(f)` is the face of the reference standing for f. The scheme is
// that of the surface.
template <class Surf, class FaceOf>
Differences against_bfr(const Mesh& m, const Surf& surface, const std::vector<std::vector<int>>& faces,
                        const std::vector<Point>& points, const std::vector<std::array<int, 2>>& creases,
                        const std::vector<float>& crease_values, CGAL_ext::Boundary_interpolation boundary,
                        CGAL_ext::Crease_method method, const FaceOf& face_of, int grid = 8,
                        CGAL_ext::Triangle_subdivision triangles = CGAL_ext::Triangle_subdivision::catmark)
{
  constexpr bool loop = Is_loop<Surf>::value;
  std::vector<int> sizes, indices, crease_indices, corner_indices;
  std::vector<float> corner_values;
  for (const auto& f : faces) {
    sizes.push_back(int(f.size()));
    indices.insert(indices.end(), f.begin(), f.end());
  }
  for (const auto& c : creases)
    crease_indices.insert(crease_indices.end(), c.begin(), c.end());
  if (auto vs = m.property_map<CGAL_ext::Vertex_index, float>("v:sharpness"); vs && points.size() == m.number_of_vertices())
    for (CGAL_ext::Vertex_index v : m.vertices())
      if ((*vs)[v] > 0) {
        corner_indices.push_back(int(v.idx()));
        corner_values.push_back((*vs)[v]);
      }
  Far::TopologyDescriptor desc = descriptor(int(points.size()), sizes, indices, crease_indices, crease_values);
  desc.numCorners = int(corner_values.size());
  desc.cornerVertexIndices = corner_indices.data();
  desc.cornerWeights = corner_values.data();
  const Sdc::Options options = test::opensubdiv_options(boundary, method, triangles);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(desc, Factory::Options(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, options)));
  Bfr::RefinerSurfaceFactory<> factory(*refiner); // approxLevelSmooth 2, approxLevelSharp 6
  std::vector<double> xyz;
  for (const Point& p : points)
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  Differences d;
  for (CGAL_ext::Face_index f : m.faces()) {
    Bfr::Surface<double> bfr;
    const bool has_surface = factory.InitVertexSurface(face_of(f), &bfr);
    EXPECT_EQ(has_surface, !surface.is_hole(f)) << "f" << f.idx();
    if (!has_surface) { // a hole: Boundary_interpolation::none
      d.holes += surface.is_hole(f) ? 1 : 0;
      EXPECT_THROW(surface.evaluate(f, 0.25, 0.25), CGAL_ext::Parameter_error) << "f" << f.idx();
      continue;
    }
    std::vector<double> patch_points(std::size_t(bfr.GetNumPatchPoints()) * 3);
    bfr.PreparePatchPoints(xyz.data(), 3, patch_points.data(), 3);
    for (const auto& uv : loop ? triangle_grid(grid) : parameter_grid(int(m.degree(f)), grid)) {
      double p[3], du[3], dv[3], duu[3], duv[3], dvv[3];
      bfr.Evaluate(uv.data(), patch_points.data(), 3, p, du, dv, duu, duv, dvv);
      const auto r = surface.evaluate(f, uv[0], uv[1]);
      d.position = std::max(d.position, gap(r.point - CGAL::ORIGIN, p));
      d.first = std::max({d.first, gap(r.du, du), gap(r.dv, dv)});
      d.second = std::max({d.second, gap(r.duu, duu), gap(r.duv, duv), gap(r.dvv, dvv)});

      const double negated[3][3] = {{-duu[0], -duu[1], -duu[2]}, {-duv[0], -duv[1], -duv[2]}, {-dvv[0], -dvv[1], -dvv[2]}};
      const double second = std::min(std::max({gap(r.duu, duu), gap(r.duv, duv), gap(r.dvv, dvv)}),
                                     std::max({gap(r.duu, negated[0]), gap(r.duv, negated[1]), gap(r.dvv, negated[2])}));
      d.second_up_to_sign = std::max(d.second_up_to_sign, second);
      if (2 * uv[0] != std::floor(2 * uv[0]) || 2 * uv[1] != std::floor(2 * uv[1]))
        d.second_off_corners = std::max(d.second_off_corners, second);
    }
  }
  return d;
}

class Against_bfr : public ::testing::TestWithParam<const char*>
{};

// The dart of face f of m that runs from a to b, flipped if the face runs
// the other way.
CGAL_ext::Dart dart_from_to(const Mesh& m, CGAL_ext::Face_index f, CGAL_ext::Vertex_index a, CGAL_ext::Vertex_index b)
{
  for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
    if (m.source(d) == a && m.target(d) == b)
      return d;
    if (m.source(d) == b && m.target(d) == a)
      return d.flipped();
  }
  ADD_FAILURE() << "no dart from " << a << " to " << b << " in face f" << f.idx();
  return m.halfedge(f);
}

// Bfr on the faces of `m` as the mesh walks them, with every edge's
// sharpness from the mesh's map (so that both see the same creases). With
// `turned`, each face is listed from another corner (f mod n), and all of
// them reversed if `reversed` (OpenSubdiv needs them oriented alike); ours
// is then evaluated from the dart of each face that runs from the first
// corner of its list to the second.
template <class Surf>
Differences against_bfr_on_mesh(const Mesh& m, const Surf& surface, CGAL_ext::Boundary_interpolation boundary,
                                CGAL_ext::Crease_method method, bool turned = false, bool reversed = false,
                                int grid = 8,
                                CGAL_ext::Triangle_subdivision triangles = CGAL_ext::Triangle_subdivision::catmark)
{
  std::vector<std::vector<int>> faces;
  From_darts<Surf> from_darts{surface, {}};
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<int> face;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(m.halfedge(f), m))
      face.push_back(int(v.idx()));
    if (turned) {
      if (reversed)
        std::reverse(face.begin(), face.end());
      std::rotate(face.begin(), face.begin() + std::ptrdiff_t(f.idx() % face.size()), face.end());
      from_darts.dart.push_back(dart_from_to(m, f, CGAL_ext::Vertex_index(face[0]), CGAL_ext::Vertex_index(face[1])));
    }
    faces.push_back(face);
  }
  std::vector<std::array<int, 2>> creases;
  std::vector<float> values;
  if (const auto es = m.property_map<CGAL_ext::Edge_index, float>("e:sharpness"))
    for (CGAL_ext::Edge_index e : m.edges())
      if ((*es)[e] > 0 && !m.is_border(e)) {
        creases.push_back({int(m.vertex(e, 0).idx()), int(m.vertex(e, 1).idx())});
        values.push_back((*es)[e]);
      }
  const auto same = [](CGAL_ext::Face_index f) { return int(f.idx()); };
  if (turned)
    return against_bfr(m, from_darts, faces, m.points().data(), creases, values, boundary, method, same, grid, triangles);
  return against_bfr(m, surface, faces, m.points().data(), creases, values, boundary, method, same, grid, triangles);
}

void record(const Differences& d, double scale)
{
  ::testing::Test::RecordProperty("position", sci(d.position / scale));
  ::testing::Test::RecordProperty("first_derivatives", sci(d.first / scale));
  ::testing::Test::RecordProperty("second_derivatives", sci(d.second / scale));
  ::testing::Test::RecordProperty("second_derivatives_up_to_sign", sci(d.second_up_to_sign / scale));
}

TEST_P(Against_bfr, PositionsAndDerivatives)
{
  const Shape s = read_shape(test::data(std::string("opensubdiv/") + GetParam() + ".obj"));
  const Mesh m = build(s);
  const Surface surface(
    m, CGAL_ext::parameters::boundary_interpolation(s.boundary).crease_method(s.crease_method).triangle_subdivision(s.triangles));
  const Differences d = against_bfr_on_mesh(m, surface, s.boundary, s.crease_method, false, false, 8, s.triangles);
  const double scale = largest_coordinate(m);
  EXPECT_LE(d.position, 1e-10 * scale) << GetParam();
  EXPECT_LE(d.first, 1e-10 * scale) << GetParam();
  EXPECT_LE(d.second, 1e-9 * scale) << GetParam();
  record(d, scale);
}

// Regular and extraordinary, closed and bordered, quads and n-gons, semi-sharp
// and infinitely sharp creases, corners under both boundary rules.
INSTANTIATE_TEST_SUITE_P(Shapes, Against_bfr,
                         ::testing::Values("catmark_cube", "catmark_cube_creases1", "catmark_cube_corner4",
                                           "catmark_edgecorner", "catmark_nonquads", "catmark_pole64",
                                           "catmark_torus_creases1", "catmark_smoothtris1"));

// catmark_smoothtris1 carries OpenSubdiv's smooth triangle rule, which
// Against_bfr gives both libraries: the rule moves the surface, so that
// comparison tells the rules apart.
TEST(Limit_surface, SmoothTriangleRuleMovesTheSurface)
{
  const Shape s = read_shape(test::data("opensubdiv/catmark_smoothtris1.obj"));
  ASSERT_EQ(s.triangles, CGAL_ext::Triangle_subdivision::smooth);
  const Mesh m = build(s);
  const auto np = CGAL_ext::parameters::boundary_interpolation(s.boundary).crease_method(s.crease_method);
  const Surface smooth(m, np.triangle_subdivision(CGAL_ext::Triangle_subdivision::smooth)), catmark(m, np);
  double moved = 0;
  for (CGAL_ext::Face_index f : m.faces())
    moved = std::max(moved, std::sqrt(CGAL::squared_distance(smooth.evaluate(f, 0.25, 0.25).point,
                                                              catmark.evaluate(f, 0.25, 0.25).point)));
  EXPECT_GT(moved, 1e-3 * largest_coordinate(m));
}

// A one-sided mesh evaluated as Bfr evaluates its orientation double cover:
// each face twice (once reversed), vertex v doubled into 2v and 2v + 1, the
// copy of a face taken on the sheet its darts give each of its corners.
// With `from_other_side`, each face is evaluated from its dart from the
// first to the second corner of its reversed copy, against that copy.
template <class Surf>
Differences against_bfr_on_double_cover(const Mesh& m, const Surf& surface, bool from_other_side = false,
                                        CGAL_ext::Boundary_interpolation boundary = CGAL_ext::Boundary_interpolation::edge_only)
{
  std::vector<Point> points;
  for (const Point& p : m.points().data()) {
    points.push_back(p);
    points.push_back(p);
  }
  std::vector<std::vector<std::pair<int, int>>> sheet(m.number_of_faces());
  for (CGAL_ext::Vertex_index v : m.vertices())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(v, m))
      if (!m.is_border(d))
        sheet[m.face(d).idx()].push_back({int(v.idx()), d.is_flipped() ? 1 : 0});
  std::vector<std::vector<int>> faces;
  From_darts<Surf> turned{surface, {}};
  for (CGAL_ext::Face_index f : m.faces())
    for (int sigma : {0, 1}) {
      std::vector<int> face;
      for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(m.halfedge(f), m))
        for (auto [w, s] : sheet[f.idx()])
          if (w == int(v.idx())) {
            face.push_back(2 * w + (sigma ^ s));
            break;
          }
      if (sigma) {
        std::reverse(face.begin(), face.end());
        turned.dart.push_back(dart_from_to(m, f, CGAL_ext::Vertex_index(face[0] / 2), CGAL_ext::Vertex_index(face[1] / 2)));
      }
      faces.push_back(face);
    }
  if (from_other_side)
    return against_bfr(m, turned, faces, points, {}, {}, boundary, CGAL_ext::Crease_method::uniform,
                       [](CGAL_ext::Face_index f) { return 2 * int(f.idx()) + 1; });
  return against_bfr(m, surface, faces, points, {}, {}, boundary, CGAL_ext::Crease_method::uniform,
                     [](CGAL_ext::Face_index f) { return 2 * int(f.idx()); });
}

// Under Boundary_interpolation::none Bfr has no surface on a face with a
// vertex on a border: the same faces are holes here (evaluate() refuses
// them), the others are evaluated as Bfr evaluates them; a Möbius strip as
// its double cover. Each mesh has holes and faces that are not.
TEST(Limit_surface, BoundaryNoneHasBfrsHoles)
{
  const auto none = CGAL_ext::Boundary_interpolation::none;
  const auto check = [](const std::string& what, const Mesh& m, const Differences& d) {
    SCOPED_TRACE(what);
    const double scale = largest_coordinate(m);
    EXPECT_GT(d.holes, 0u);
    EXPECT_LT(d.holes, m.number_of_faces());
    EXPECT_LE(d.position, 1e-10 * scale);
    EXPECT_LE(d.first, 1e-10 * scale);
    EXPECT_LE(d.second_off_corners, 1e-9 * scale);
  };
  for (const std::string name : {"catmark_edgecorner", "catmark_nonquads", "loop_triangle_edgeonly"}) {
    Shape s = read_shape(test::data("opensubdiv/" + name + ".obj"));
    s.boundary = none;
    const Mesh m = build(s);
    const auto np = CGAL_ext::parameters::boundary_interpolation(none).crease_method(s.crease_method);
    check(name, m,
          name[0] == 'l' ? against_bfr_on_mesh(m, Loop_surface(m, np), none, s.crease_method)
                         : against_bfr_on_mesh(m, Surface(m, np), none, s.crease_method));
    if (name[0] == 'l')
      continue;
    // The closest point lies on a face with a surface, even from a point of a hole.
    const Surface surface(m, np);
    for (CGAL_ext::Vertex_index v : m.vertices()) {
      const auto at = surface.closest_point(m.point(v));
      EXPECT_FALSE(surface.is_hole(at.face)) << name << " v" << v.idx();
      EXPECT_EQ(at.point, surface.evaluate(at.face, at.u, at.v).point);
    }
  }
  for (bool quads : {true, false}) {
    Mesh m;
    CGAL_ext::make_mobius_strip(m, 12, 3, 1, 1.0, 0.5, quads);
    const auto np = CGAL_ext::parameters::boundary_interpolation(none);
    check(quads ? "Mobius strip of quads" : "Mobius strip of triangles", m,
          quads ? against_bfr_on_double_cover(m, Surface(m, np), false, none)
                : against_bfr_on_double_cover(m, Loop_surface(m, np), false, none));
  }
}

TEST(Limit_surface, MobiusStripAgainstBfrOnItsDoubleCover)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3);
  const Differences d = against_bfr_on_double_cover(m, Surface(m));
  const double scale = largest_coordinate(m);
  EXPECT_LE(d.position, 1e-10 * scale);
  EXPECT_LE(d.first, 1e-10 * scale);
  RecordProperty("position", std::to_string(d.position / scale));
  RecordProperty("first_derivatives", std::to_string(d.first / scale));
}

TEST(Limit_surface, EvaluatedFromAnyDartAsBfrOnTheFaceTurned)
{
  for (const char* name : {"catmark_nonquads", "catmark_cube_creases1", "loop_icos_semisharp"}) {
    SCOPED_TRACE(name);
    const Shape s = read_shape(test::data(std::string("opensubdiv/") + name + ".obj"));
    const Mesh m = build(s);
    const auto np = CGAL_ext::parameters::boundary_interpolation(s.boundary).crease_method(s.crease_method);
    for (bool reversed : {false, true}) {
      const Differences d =
        name[0] == 'l' ? against_bfr_on_mesh(m, Loop_surface(m, np), s.boundary, s.crease_method, true, reversed, 7)
                       : against_bfr_on_mesh(m, Surface(m, np), s.boundary, s.crease_method, true, reversed, 7);
      const double scale = largest_coordinate(m);
      EXPECT_LE(d.position, 1e-10 * scale) << reversed;
      EXPECT_LE(d.first, 1e-10 * scale) << reversed;
      EXPECT_LE(d.second_off_corners, 1e-9 * scale) << reversed;
      const std::string what = std::string(name) + (reversed ? "_reversed" : "_turned");
      RecordProperty(what + "_position", sci(d.position / scale));
      RecordProperty(what + "_first", sci(d.first / scale));
      RecordProperty(what + "_second_off_corners", sci(d.second_off_corners / scale));
      RecordProperty(what + "_second_at_corners_too", sci(d.second_up_to_sign / scale));
    }
  }
  for (bool quads : {true, false}) {
    SCOPED_TRACE(quads ? "Mobius strip of quads" : "Mobius strip of triangles");
    Mesh m;
    CGAL_ext::make_mobius_strip(m, 12, 3, 1, 1.0, 0.5, quads);
    const Differences d = quads ? against_bfr_on_double_cover(m, Surface(m), true)
                                : against_bfr_on_double_cover(m, Loop_surface(m), true);
    const double scale = largest_coordinate(m);
    EXPECT_LE(d.position, 1e-10 * scale);
    EXPECT_LE(d.first, 1e-10 * scale);
    RecordProperty(std::string(quads ? "mobius_quads" : "mobius_triangles") + "_first", sci(d.first / scale));
  }
  // From its first corner the other way round, a face's (u, v) are
  // exchanged and its normal is turned over.
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3);
  const Surface surface(m);
  for (CGAL_ext::Face_index f : m.faces()) {
    const CGAL_ext::Dart d = m.halfedge(f).flipped(); // from corner 0 to corner 3
    const auto a = surface.evaluate(f, 0.3, 0.6), b = surface.evaluate(d, 0.6, 0.3);
    EXPECT_LE(CGAL::squared_distance(a.point, b.point), 1e-24);
    EXPECT_LE((a.normal + b.normal).squared_length(), 1e-24);
  }
  EXPECT_THROW(surface.evaluate(m.next(m.halfedge(CGAL_ext::Face_index(0))), 1.5, 0.5), CGAL_ext::Parameter_error);
}

class Tessellation_against_bfr : public ::testing::TestWithParam<const char*>
{};

// The tessellation against Bfr::Tessellation (uniform rate, quads
// preserved) face by face: the same number of samples and facets, each of
// Bfr's coordinates evaluated to a sample of ours (the nearest one, within
// 1e-10 of the size, and no two on one), and the same facets on those
// samples. With `boundary`, the shape's boundary rule is replaced: under
// `none`, holes (as Bfr has them: evaluation tests) have no facets, and no
// vertex is left without one.
template <class Surf>
void tessellation_against_bfr(const std::string& name, std::optional<CGAL_ext::Boundary_interpolation> boundary = {})
{
  constexpr bool loop = std::is_same_v<Surf, Loop_surface>;
  Shape s = read_shape(test::data(std::string("opensubdiv/") + name + ".obj"));
  s.boundary = boundary.value_or(s.boundary);
  const Mesh m = build(s);
  const Surf surface(m, CGAL_ext::parameters::boundary_interpolation(s.boundary).crease_method(s.crease_method));
  const double scale = largest_coordinate(m);
  for (int rate = 1; rate <= 8; ++rate) {
    const Mesh out = surface.tessellate(rate);
    std::size_t facet = 0, coords = 0;
    double worst = 0;
    for (CGAL_ext::Vertex_index v : out.vertices())
      EXPECT_FALSE(out.is_isolated(v)) << name << " rate " << rate;
    for (CGAL_ext::Face_index f : m.faces()) {
      if (surface.is_hole(f))
        continue;
      Bfr::Tessellation::Options options;
      options.SetFacetSize(4).PreserveQuads(true);
      const Bfr::Tessellation t(Bfr::Parameterization(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, int(m.degree(f))), rate, options);
      ASSERT_TRUE(t.IsValid());
      std::vector<double> uv(2 * std::size_t(t.GetNumCoords()));
      t.GetCoords(uv.data());
      // Bfr gives a triangle's coordinates i / N to float precision only (so
      // u + v may pass 1): they are taken at the multiple of 1 / N they stand for.
      if (loop)
        for (double& x : uv) {
          const double snapped = std::round(x * rate) / rate;
          EXPECT_LE(std::abs(x - snapped), 1e-6) << name << " rate " << rate;
          x = snapped;
        }
      std::vector<int> facets(4 * std::size_t(t.GetNumFacets()));
      t.GetFacets(facets.data());
      ASSERT_LE(facet + std::size_t(t.GetNumFacets()), out.number_of_faces()) << name << " rate " << rate;
      // Our facets of f and their samples.
      std::set<std::vector<std::size_t>> ours;
      std::set<std::size_t> samples;
      for (std::size_t k = 0; k < std::size_t(t.GetNumFacets()); ++k) {
        std::vector<std::size_t> c;
        for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(out.halfedge(CGAL_ext::Face_index(facet + k)), out))
          c.push_back(v.idx());
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        ours.insert(c);
        samples.insert(c.begin(), c.end());
      }
      facet += std::size_t(t.GetNumFacets());
      EXPECT_EQ(samples.size(), std::size_t(t.GetNumCoords())) << name << " rate " << rate << " f" << f.idx();
      std::vector<std::size_t> match;
      for (std::size_t c = 0; c < std::size_t(t.GetNumCoords()); ++c) {
        const Point p = surface.evaluate(f, uv[2 * c], uv[2 * c + 1]).point;
        std::size_t best = 0;
        double d = 1e300;
        for (std::size_t id : samples)
          if (const double x = std::sqrt(CGAL::squared_distance(p, out.point(CGAL_ext::Vertex_index(id)))); x < d) {
            d = x;
            best = id;
          }
        worst = std::max(worst, d);
        match.push_back(best);
      }
      coords += match.size();
      EXPECT_EQ(std::set<std::size_t>(match.begin(), match.end()).size(), match.size()) << name << " rate " << rate;
      std::set<std::vector<std::size_t>> theirs;
      for (std::size_t k = 0; k < std::size_t(t.GetNumFacets()); ++k) {
        std::vector<std::size_t> c;
        for (int i = 0; i < 4; ++i)
          if (facets[4 * k + std::size_t(i)] >= 0)
            c.push_back(match[std::size_t(facets[4 * k + std::size_t(i)])]);
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        theirs.insert(c);
      }
      EXPECT_EQ(ours, theirs) << name << " rate " << rate << " f" << f.idx();
    }
    EXPECT_EQ(facet, out.number_of_faces()) << name << " rate " << rate;
    EXPECT_LE(worst, 1e-10 * scale) << name << " rate " << rate;
    ::testing::Test::RecordProperty(std::string("rate") + std::to_string(rate) + "_position", std::to_string(worst / scale));
    (void)coords;
  }
}

TEST_P(Tessellation_against_bfr, SameSamplesAndFacets) { tessellation_against_bfr<Surface>(GetParam()); }

#endif // CGAL_EXT_HAVE_OPENSUBDIV

// Faces with a surface that meet at one vertex only, between holes (under
// Boundary_interpolation::none): a 6 x 6 grid of unit quads in the plane
// without the cells (1, 1) and (4, 4) keeps a surface on two blocks of
// 2 x 2 cells, (1..2, 3..4) and (3..4, 1..2), which meet at the point
// (3, 3) (the cells to its north-east and south-west reach the cut-out
// cells' corners). With the texture channel (x, y) / 6 in "c:uv".
Mesh pinched_grid()
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> cells;
  for (int j = 0; j <= 6; ++j)
    for (int i = 0; i <= 6; ++i)
      points.emplace_back(i, j, 0);
  for (std::size_t j = 0; j < 6; ++j)
    for (std::size_t i = 0; i < 6; ++i)
      if ((i != 1 || j != 1) && (i != 4 || j != 4))
        cells.push_back({7 * j + i, 7 * j + i + 1, 7 * j + i + 8, 7 * j + i + 7});
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, cells, m);
  auto uv = m.add_corner_channel<std::array<double, 2>>("c:uv").first;
  for (const Point& p : m.points().data())
    uv.values().push_back({p.x() / 6, p.y() / 6});
  for (CGAL_ext::Face_index f : m.faces())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      uv.set_index(m.corner(d), std::uint32_t(m.target(d).idx()));
  return m;
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
TEST(Limit_surface, TessellationLeavesOutHoles)
{
  for (const char* name : {"catmark_edgecorner", "catmark_nonquads"})
    tessellation_against_bfr<Surface>(name, CGAL_ext::Boundary_interpolation::none);
  tessellation_against_bfr<Loop_surface>("loop_triangle_edgeonly", CGAL_ext::Boundary_interpolation::none);

  // On the pinched grid at rate 2 each block is 5 x 5 samples, the point
  // (3, 3) once per block. The texture channel is affine in the points, and
  // so is its limit on these regular faces: each corner keeps its point's value.
  const auto holes = CGAL_ext::parameters::boundary_interpolation(CGAL_ext::Boundary_interpolation::none);
  const Surface surface(pinched_grid(), holes);
  const Mesh out = surface.tessellate(2);
  EXPECT_EQ(out.number_of_faces(), 32u);
  EXPECT_EQ(out.number_of_vertices(), 50u);
  std::size_t at_pinch = 0;
  for (CGAL_ext::Vertex_index v : out.vertices()) {
    EXPECT_FALSE(out.is_isolated(v));
    at_pinch += CGAL::squared_distance(out.point(v), Point(3, 3, 0)) < 1e-20 ? 1 : 0;
  }
  EXPECT_EQ(at_pinch, 2u);
  const auto out_uv = out.corner_channel<std::array<double, 2>>("c:uv");
  ASSERT_TRUE(out_uv.has_value());
  EXPECT_EQ(out_uv->number_of_values(), 49u); // one per point: none of the holes' samples
  for (CGAL_ext::Face_index f : out.faces())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(out.halfedge(f), out)) {
      const Point& p = out.point(out.target(d));
      const std::array<double, 2> w = out_uv->values()[out_uv->index(out.corner(d))];
      EXPECT_NEAR(w[0], p.x() / 6, 1e-12);
      EXPECT_NEAR(w[1], p.y() / 6, 1e-12);
    }
}

// Quads, borders and corners, n-gons, triangles.
INSTANTIATE_TEST_SUITE_P(Shapes, Tessellation_against_bfr,
                         ::testing::Values("catmark_cube", "catmark_edgecorner", "catmark_nonquads",
                                           "catmark_smoothtris1"));
#endif // CGAL_EXT_HAVE_OPENSUBDIV

// The uniform cubic B-spline basis, written out here from its definition.
template <class FT>
std::array<FT, 4> bspline(const FT& t)
{
  const FT s = FT(1) - t;
  return {s * s * s / FT(6), (FT(3) * t * t * t - FT(6) * t * t + FT(4)) / FT(6),
          (-FT(3) * t * t * t + FT(3) * t * t + FT(3) * t + FT(1)) / FT(6), t * t * t / FT(6)};
}

// A torus of nu x nv quads, every vertex of valence 4, with rational
// coordinates (a bumpy square torus: the closed form does not care about
// the shape), built face (i, j) = (i, j), (i+1, j), (i+1, j+1), (i, j+1).
template <class P>
CGAL_ext::Mobius_mesh<P> torus(int nu, int nv, std::vector<P>& points)
{
  points.clear();
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      points.emplace_back(i * 4 + (j % 3), j * 5 - (i % 2), (i * j) % 7);
  std::vector<std::vector<std::size_t>> faces;
  auto id = [&](int i, int j) { return std::size_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  CGAL_ext::Mobius_mesh<P> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  return m;
}

// The closed form at (u, v) of face (i, j): Σ B_a(u) B_b(v) P(i - 1 + a, j - 1 + b),
// oriented by the face's own first corner (which the import may have rotated).
template <class P, class FT>
P closed_form(const CGAL_ext::Mobius_mesh<P>& m, CGAL_ext::Face_index f, int nu, int nv, const FT& u, const FT& v)
{
  std::vector<CGAL_ext::Vertex_index> c;
  for (CGAL_ext::Vertex_index x : CGAL_ext::vertices_around_face(m.halfedge(f), m))
    c.push_back(x);
  // Grid coordinates of the corners, and the directions of u and v.
  auto ij = [&](CGAL_ext::Vertex_index x) { return std::array<int, 2>{int(x.idx()) / nv, int(x.idx()) % nv}; };
  auto step = [&](int a, int b, int n) { return ((b - a) % n + n) % n == 1 ? 1 : -1; };
  const auto o = ij(c[0]), x1 = ij(c[1]), x3 = ij(c[3]);
  // u runs from corner 0 to corner 1, v from corner 0 to corner 3, each along i or j.
  const bool u_along_i = x1[0] != o[0];
  const int su = u_along_i ? step(o[0], x1[0], nu) : step(o[1], x1[1], nv);
  const int sv = u_along_i ? step(o[1], x3[1], nv) : step(o[0], x3[0], nu);
  const auto bu = bspline(u), bv = bspline(v);
  FT x(0), y(0), z(0);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const int di = u_along_i ? su * (a - 1) : sv * (b - 1), dj = u_along_i ? sv * (b - 1) : su * (a - 1);
      const P& p = m.point(CGAL_ext::Vertex_index(std::size_t(((o[0] + di) % nu + nu) % nu * nv + ((o[1] + dj) % nv + nv) % nv)));
      const FT w = bu[a] * bv[b];
      x += w * p.x();
      y += w * p.y();
      z += w * p.z();
    }
  return P(x, y, z);
}

TEST(Limit_surface, RegularTorusIsTheBicubicBSpline)
{
  std::vector<Point> points;
  const Mesh m = torus<Point>(6, 5, points);
  const Surface surface(m);
  const double scale = largest_coordinate(m);
  double worst = 0;
  for (CGAL_ext::Face_index f : m.faces()) {
    EXPECT_EQ(surface.number_of_patches(f), 1u);
    for (const auto& uv : parameter_grid(4, 5)) {
      const Point a = surface.evaluate(f, uv[0], uv[1]).point, b = closed_form(m, f, 6, 5, uv[0], uv[1]);
      worst = std::max(worst, std::sqrt(CGAL::squared_distance(a, b)));
    }
  }
  EXPECT_LE(worst, 1e-14 * scale);
}

TEST(Limit_surface, RegularTorusIsExactWithRationals)
{
  using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Pq = Kq::Point_3;
  std::vector<Pq> points;
  const CGAL_ext::Mobius_mesh<Pq> m = torus<Pq>(5, 4, points);
  const S::Limit_surface<S::Catmull_clark_mask, Pq> surface(m);
  for (CGAL_ext::Face_index f : m.faces())
    for (const auto& uv : {std::array<CGAL::Gmpq, 2>{CGAL::Gmpq(1, 3), CGAL::Gmpq(2, 7)},
                           std::array<CGAL::Gmpq, 2>{CGAL::Gmpq(0), CGAL::Gmpq(1)},
                           std::array<CGAL::Gmpq, 2>{CGAL::Gmpq(5, 9), CGAL::Gmpq(1, 2)}})
    {
      EXPECT_EQ(surface.evaluate(f, uv[0], uv[1]).point, closed_form(m, f, 5, 4, uv[0], uv[1]));
      // From corner 2 the other way round, (u, v) is (1 - v, 1 - u): the
      // same closed form, exactly.
      const CGAL_ext::Dart d = m.next(m.next(m.halfedge(f))).flipped(); // corner 2 to corner 1
      const auto e = surface.evaluate(d, CGAL::Gmpq(1) - uv[1], CGAL::Gmpq(1) - uv[0]);
      EXPECT_EQ(e.point, closed_form(m, f, 5, 4, uv[0], uv[1]));
      EXPECT_EQ(e.du, -surface.evaluate(f, uv[0], uv[1]).dv);
    }
}

// At the corners of a face, the limit position of the vertex there.
TEST(Limit_surface, CornersAreLimitPoints)
{
  // Quad meshes only: limit_point() reads the limit masks of a quad ring.
  for (const char* name : {"catmark_cube", "catmark_cube_corner4", "catmark_edgecorner"}) {
    const Shape s = read_shape(test::data(std::string("opensubdiv/") + name + ".obj"));
    const Mesh m = build(s);
    const auto np = CGAL_ext::parameters::boundary_interpolation(s.boundary);
    const Surface surface(m, np);
    double worst = 0;
    for (CGAL_ext::Face_index f : m.faces()) {
      std::vector<CGAL_ext::Vertex_index> c;
      for (CGAL_ext::Vertex_index x : CGAL_ext::vertices_around_face(m.halfedge(f), m))
        c.push_back(x);
      const double uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; ++k) {
        const Point a = surface.evaluate(f, uv[k][0], uv[k][1]).point;
        const Point b = S::limit_point<S::Catmull_clark_mask>(c[k], m, np);
        worst = std::max(worst, std::sqrt(CGAL::squared_distance(a, b)));
      }
    }
    EXPECT_LE(worst, 1e-14 * largest_coordinate(m)) << name;
    RecordProperty(std::string("corners_") + name, std::to_string(worst));
  }
}

TEST(Limit_surface, RefusesWhatItCannotEvaluate)
{
  std::vector<Point> points;
  const Mesh m = torus<Point>(4, 4, points);
  const Surface surface(m);
  EXPECT_THROW(surface.evaluate(CGAL_ext::Face_index(99), 0.5, 0.5), CGAL_ext::Parameter_error);
  EXPECT_THROW(surface.evaluate(CGAL_ext::Face_index(0), 1.5, 0.5), CGAL_ext::Parameter_error);
  // Without a border, no face is a hole under Boundary_interpolation::none.
  const Surface closed(m, CGAL_ext::parameters::boundary_interpolation(CGAL_ext::Boundary_interpolation::none));
  EXPECT_EQ(CGAL::squared_distance(closed.evaluate(CGAL_ext::Face_index(5), 0.25, 0.5).point,
                                   surface.evaluate(CGAL_ext::Face_index(5), 0.25, 0.5).point),
            0.0);
  EXPECT_EQ(closed.tessellate(2).number_of_faces(), 4 * m.number_of_faces());
}

// Samples inside a base face of n sides at rate N, as Bfr counts them.
std::size_t interior_samples(std::size_t n, std::size_t N)
{
  if (n == 4)
    return (N - 1) * (N - 1);
  const std::size_t M = N / 2;
  if (N % 2 == 0)
    return n * (M - 1) * M + 1;
  return n * M * M + (n == 3 ? 0 : 1);
}

// Watertight: a valid mesh of the same Euler characteristic, borders and
// orientability, whose base vertices and edge samples are shared (the
// count of vertices leaves no room for duplicates).
TEST(Limit_surface, TessellationIsWatertight)
{
  std::vector<std::pair<std::string, Mesh>> meshes;
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  meshes.emplace_back("mobius_strip", strip);
  for (const char* name : {"catmark_cube", "catmark_edgecorner", "catmark_nonquads", "catmark_smoothtris1"})
    meshes.emplace_back(name, build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj"))));
  for (const auto& [name, m] : meshes) {
    const Surface surface(m);
    for (std::size_t N = 1; N <= 5; ++N) {
      const Mesh out = surface.tessellate(int(N));
      EXPECT_TRUE(out.is_valid()) << name << " rate " << N;
      EXPECT_EQ(CGAL_ext::euler_characteristic(out), CGAL_ext::euler_characteristic(m)) << name << " rate " << N;
      EXPECT_EQ(CGAL_ext::number_of_border_cycles(out), CGAL_ext::number_of_border_cycles(m)) << name << " rate " << N;
      EXPECT_EQ(CGAL_ext::is_orientable(out), CGAL_ext::is_orientable(m)) << name << " rate " << N;
      std::size_t expected = m.number_of_vertices() + m.number_of_edges() * (N - 1);
      for (CGAL_ext::Face_index f : m.faces())
        expected += interior_samples(m.degree(f), N);
      EXPECT_EQ(out.number_of_vertices(), expected) << name << " rate " << N;
      const auto normals = out.property_map<CGAL_ext::Vertex_index, K::Vector_3>("v:normal");
      ASSERT_TRUE(normals.has_value()) << name;
      // Unit normals, but where du × dv vanishes: only at base vertices (a
      // border vertex of one face under edge_only, some n-gon corners).
      for (CGAL_ext::Vertex_index v : out.vertices()) {
        const double length = std::sqrt((*normals)[v].squared_length());
        if (length == 0)
          EXPECT_LT(v.idx(), m.number_of_vertices()) << name << " rate " << N;
        else
          EXPECT_NEAR(length, 1.0, 1e-12) << name << " rate " << N;
      }
      // Per-corner normals on the strip agree with each facet's own normal.
      const bool mobius = name == "mobius_strip";
      const auto corners = out.property_map<CGAL_ext::Halfedge_index, K::Vector_3>("h:normal");
      EXPECT_EQ(corners.has_value(), mobius) << name;
      if (mobius && N >= 2)
        for (CGAL_ext::Face_index f : out.faces()) {
          const K::Vector_3 fn = CGAL_ext::face_normal(f, out);
          for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(out.halfedge(f), out))
            EXPECT_GT((*corners)[d.halfedge()] * fn, 0) << "facet " << f.idx() << " rate " << N;
        }
    }
  }
  EXPECT_FALSE(CGAL_ext::is_orientable(Surface(strip).tessellate(3)));
  EXPECT_THROW(Surface(strip).tessellate(0), CGAL_ext::Parameter_error);
}

#ifdef CGAL_LINKED_WITH_TBB
// Whether two tessellations are the same, byte for byte: connectivity,
// points, normals, corner normals, and each corner channel's values and indices.
using test::same_bytes;

template <class Map>
std::vector<typename Map::value_type> values_of(const std::optional<Map>& map, std::size_t n)
{
  std::vector<typename Map::value_type> out;
  if (map)
    for (std::size_t i = 0; i < n; ++i)
      out.push_back((*map)[typename Map::key_type(i)]);
  return out;
}

// Whether `a` has a channel `name` of values T; if so, expects `b`'s to hold
// the same values and indices.
template <class T>
bool same_channel(const Mesh& a, const Mesh& b, const std::string& name, const std::string& what)
{
  const auto ca = a.corner_channel<T>(name);
  if (!ca)
    return false;
  const auto cb = b.corner_channel<T>(name);
  EXPECT_TRUE(cb.has_value()) << what << ": " << name;
  if (!cb)
    return true;
  EXPECT_TRUE(same_bytes(ca->values(), cb->values())) << what << ": " << name << " values";
  for (CGAL_ext::Halfedge_index h : a.halfedges())
    if (!a.is_border(h) && ca->index(a.corner(CGAL_ext::Dart(h))) != cb->index(b.corner(CGAL_ext::Dart(h)))) {
      ADD_FAILURE() << what << ": " << name << " indices";
      break;
    }
  return true;
}

void expect_same_tessellation(const Mesh& a, const Mesh& b, const std::string& what)
{
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices()) << what;
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces()) << what;
  EXPECT_TRUE(test::same_connectivity(a, b)) << what << ": connectivity";
  EXPECT_TRUE(same_bytes(a.points().data(), b.points().data())) << what << ": points";
  using V = K::Vector_3;
  EXPECT_TRUE(same_bytes(values_of(a.property_map<CGAL_ext::Vertex_index, V>("v:normal"), a.number_of_vertices()),
                         values_of(b.property_map<CGAL_ext::Vertex_index, V>("v:normal"), b.number_of_vertices())))
    << what << ": normals";
  const auto ha = a.property_map<CGAL_ext::Halfedge_index, V>("h:normal");
  const auto hb = b.property_map<CGAL_ext::Halfedge_index, V>("h:normal");
  EXPECT_EQ(ha.has_value(), hb.has_value()) << what;
  EXPECT_TRUE(same_bytes(values_of(ha, a.number_of_halfedges()), values_of(hb, b.number_of_halfedges())))
    << what << ": corner normals";
  EXPECT_EQ(a.corner_channels(), b.corner_channels()) << what;
  for (const std::string& name : a.corner_channels())
    EXPECT_TRUE((same_channel<CGAL_ext::Corner_uv<Point>>(a, b, name, what) ||
                 same_channel<std::array<double, 2>>(a, b, name, what)))
      << what << ": " << name << " holds neither type";
}

// Under CGAL::Parallel_tag, on four threads, the serial tessellation bit for
// bit: uniform rates and rates from a tolerance, meshes large enough for
// several batches of samples and the parallel mesh builder, with corner
// normals (a Möbius strip), a texture channel with seams, holes, and a pinch
// between holes, both schemes, and a cache too small for the faces' patches.
// The parallel call comes first, on a surface of its own, so that its
// threads build the faces' patches as they meet them.
TEST(Limit_surface, ParallelTessellationIsTheSerialOne)
{
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  tbb::task_arena arena(4);
  const Mesh strip = test::Uv_grid{60, 8, false}.mesh<Point>(), torus = test::Uv_grid{48, 24, true}.mesh<Point>();
  const Mesh quads = build(read_shape(test::data("opensubdiv/catmark_nonquads.obj"))), pinched = pinched_grid();
  const auto holes = CGAL_ext::parameters::boundary_interpolation(CGAL_ext::Boundary_interpolation::none);
  Mesh quad_strip;
  CGAL_ext::make_mobius_strip(quad_strip, 12, 3);
  S::Limit_surface_options small;
  small.max_cache_bytes = 2048; // a few faces kept, the others built for each evaluation
  std::size_t most = 0; // samples
  const auto both = [&](const std::string& what, const auto& make, int rate, double tolerance) {
    arena.execute([&] {
      const Mesh parallel = make().template tessellate<CGAL::Parallel_tag>(rate);
      const Mesh serial = make().tessellate(rate);
      most = std::max<std::size_t>(most, serial.number_of_vertices());
      expect_same_tessellation(serial, parallel, what + " rate " + std::to_string(rate));
      const Mesh parallel_to_tolerance = make().template tessellate_to_tolerance<CGAL::Parallel_tag>(tolerance);
      expect_same_tessellation(make().tessellate_to_tolerance(tolerance), parallel_to_tolerance,
                               what + " tolerance " + sci(tolerance));
    });
  };
  both("strip", [&] { return Surface(strip); }, 7, 1e-3);
  both("loop strip", [&] { return Loop_surface(strip); }, 9, 1e-3);
  both("torus", [&] { return Surface(torus); }, 10, 1e-3);
  both("quad strip, a small cache", [&] { return Surface(quad_strip, CGAL_ext::parameters::default_values(), small); }, 6,
       1e-3);
  both("strip without its borders' faces", [&] { return Surface(strip, holes); }, 5, 1e-2);
  both("pinched grid", [&] { return Surface(pinched, holes); }, 9, 1e-3);
  both("catmark_nonquads", [&] { return Surface(quads); }, 20, 1e-4);
  EXPECT_GT(most, 2 * (std::size_t(1) << 16)); // several batches of samples
  arena.execute([&] {
    const Mesh parallel = S::tessellate<S::Loop_mask, CGAL::Parallel_tag>(strip, 4);
    expect_same_tessellation(Loop_surface(strip).tessellate(4), parallel, "the free function");
  });
}
#endif

// At rate 1 a quad mesh tessellates to its limit points, exactly those of limit_point().
TEST(Limit_surface, TessellationAtRateOneIsTheLimitPoints)
{
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  std::vector<std::pair<std::string, Mesh>> meshes{{"mobius_strip", strip}};
  for (const char* name : {"catmark_cube", "catmark_cube_corner4", "catmark_edgecorner"})
    meshes.emplace_back(name, build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj"))));
  for (const auto& [name, m] : meshes) {
    const auto np = CGAL_ext::parameters::boundary_interpolation(CGAL_ext::Boundary_interpolation::edge_only);
    const Mesh out = Surface(m, np).tessellate(1);
    ASSERT_EQ(out.number_of_vertices(), m.number_of_vertices()) << name;
    EXPECT_EQ(out.number_of_faces(), m.number_of_faces()) << name;
    for (CGAL_ext::Vertex_index v : m.vertices())
      EXPECT_EQ(out.point(v), S::limit_point<S::Catmull_clark_mask>(v, m, np)) << name << " v" << v.idx();
  }
  // The free function is the member.
  const Mesh a = S::tessellate<S::Catmull_clark_mask>(strip, 2), b = Surface(strip).tessellate(2);
  EXPECT_EQ(a.points().data(), b.points().data());
}

// The shapes the projection tests walk: one-sided, n-gons, borders, creases, a high valence.
std::vector<std::pair<std::string, Mesh>> projection_shapes()
{
  std::vector<std::pair<std::string, Mesh>> meshes;
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  meshes.emplace_back("mobius_strip", strip);
  for (const char* name : {"catmark_cube", "catmark_nonquads", "catmark_edgecorner", "catmark_torus_creases1"})
    meshes.emplace_back(name, build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj"))));
  return meshes;
}

// Whether the derivatives at (u, v) of f are those of the positions, by
// central differences: on B-spline patches they are; on the Gregory patches
// near irregular vertices they are Bfr's (those of the Bezier patch that the
// blended points make), which differ by up to a few percent. Only a
// parameter inside a sub-face, clear of its sides, is told.
template <class Surf>
bool derivatives_are_exact(const Surf& surface, CGAL_ext::Face_index f, int sides, double u, double v)
{
  const double step = 1e-6, half = sides == 4 ? 1.0 : 0.5;
  const double su = std::fmod(u, half), sv = std::fmod(v, half);
  if (std::is_same_v<Surf, Loop_surface> ? (u < 1e-4 || v < 1e-4 || u + v > 1 - 1e-4)
                                          : (su < 1e-4 || sv < 1e-4 || su > half - 1e-4 || sv > half - 1e-4))
    return false;
  const typename Surf::Evaluation e = surface.evaluate(f, u, v);
  const K::Vector_3 du = (surface.evaluate(f, u + step, v).point - surface.evaluate(f, u - step, v).point) / (2 * step);
  const K::Vector_3 dv = (surface.evaluate(f, u, v + step).point - surface.evaluate(f, u, v - step).point) / (2 * step);
  return std::sqrt((du - e.du).squared_length()) <= 1e-6 * std::sqrt(e.du.squared_length()) &&
         std::sqrt((dv - e.dv).squared_length()) <= 1e-6 * std::sqrt(e.dv.squared_length());
}

// A point of the surface pushed off along its normal, by less than the
// surface's curvature radius, comes back to that point: the closest point
// of the surface is the foot of the normal through the query. Where the
// normal is Bfr's approximation (Gregory patches), the foot moves by a
// little: the point found is then no farther than the push and close to
// the point pushed.
template <class Surf>
void closest_point_finds_the_foot_of_the_normal(const std::vector<std::pair<std::string, Mesh>>& shapes)
{
  for (const auto& [name, m] : shapes) {
    const Surf surface(m);
    const double scale = largest_coordinate(m), h = 1e-3 * scale;
    double worst = 0, worst_approximate = 0;
    std::size_t exact = 0;
    for (CGAL_ext::Face_index f : m.faces())
      for (const auto& uv : std::is_same_v<Surf, Loop_surface> ? triangle_grid(5) : parameter_grid(int(m.degree(f)), 5)) {
        const typename Surf::Evaluation e = surface.evaluate(f, uv[0], uv[1]);
        if (e.normal == CGAL::NULL_VECTOR)
          continue;
        const bool on_patch = derivatives_are_exact(surface, f, int(m.degree(f)), uv[0], uv[1]);
        for (double side : {1.0, -1.0}) {
          const auto found = surface.closest_point(e.point + side * h * e.normal);
          const double miss = std::sqrt(CGAL::squared_distance(found.point, e.point));
          EXPECT_EQ(found.point, surface.evaluate(found.face, found.u, found.v).point) << name;
          if (on_patch) {
            EXPECT_NEAR(std::sqrt(found.squared_distance), h, 1e-9 * scale) << name << " f" << f.idx();
            worst = std::max(worst, miss);
            ++exact;
          } else {
            EXPECT_LE(std::sqrt(found.squared_distance), h * (1 + 1e-9)) << name << " f" << f.idx();
            worst_approximate = std::max(worst_approximate, miss);
          }
        }
      }
    EXPECT_LE(worst, 1e-9 * scale) << name;
    EXPECT_LE(worst_approximate, 1e-2 * h) << name;
    EXPECT_GT(exact, 4 * m.number_of_faces()) << name;
    std::ostringstream figures;
    figures << std::scientific << std::setprecision(1) << worst / scale << " of the size; " << worst_approximate / h
            << " of the push near Gregory patches";
    ::testing::Test::RecordProperty("foot_" + name, figures.str());
  }
}

TEST(Limit_surface, ClosestPointFindsTheFootOfTheNormal)
{
  closest_point_finds_the_foot_of_the_normal<Surface>(projection_shapes());
}

// Against brute force: no sample of a fine tessellation is closer to a
// query than the point found; where the derivatives are the positions'
// and the point is inside a sub-face, the offset is normal to the surface.
template <class Surf>
void closest_point_is_no_farther_than_any_sample(const std::vector<std::pair<std::string, Mesh>>& shapes)
{
  CGAL::Random random(7);
  for (const auto& [name, m] : shapes) {
    const Surf surface(m);
    const Mesh fine = surface.tessellate(24);
    const double scale = largest_coordinate(m);
    std::size_t stationary = 0;
    for (int i = 0; i < 40; ++i) {
      const Point q(random.get_double(-1.5, 1.5) * scale, random.get_double(-1.5, 1.5) * scale,
                    random.get_double(-1.5, 1.5) * scale);
      double nearest = std::numeric_limits<double>::infinity();
      for (CGAL_ext::Vertex_index v : fine.vertices())
        nearest = std::min(nearest, CGAL::squared_distance(q, fine.point(v)));
      const auto found = surface.closest_point(q);
      EXPECT_LE(std::sqrt(found.squared_distance), std::sqrt(nearest) + 1e-12 * scale) << name << " query " << i;
      const double u = CGAL::to_double(found.u), v = CGAL::to_double(found.v);
      if (!derivatives_are_exact(surface, found.face, int(m.degree(found.face)), u, v))
        continue;
      const typename Surf::Evaluation e = surface.evaluate(found.face, u, v);
      const K::Vector_3 r = q - found.point;
      const double length = std::sqrt(r.squared_length());
      EXPECT_LE(std::abs(r * e.du) / (length * std::sqrt(e.du.squared_length())), 1e-9) << name << " query " << i;
      EXPECT_LE(std::abs(r * e.dv) / (length * std::sqrt(e.dv.squared_length())), 1e-9) << name << " query " << i;
      ++stationary;
    }
    ::testing::Test::RecordProperty("stationary_" + name, std::to_string(stationary));
  }
}

TEST(Limit_surface, ClosestPointIsNoFartherThanAnySample)
{
  closest_point_is_no_farther_than_any_sample<Surface>(projection_shapes());
}

TEST(Limit_surface, ClosestPointFromSeveralThreads)
{
  Mesh m = build(read_shape(test::data("opensubdiv/catmark_nonquads.obj")));
  const double scale = largest_coordinate(m);
  std::vector<Point> queries;
  CGAL::Random random(11);
  for (int i = 0; i < 64; ++i)
    queries.emplace_back(random.get_double(-1, 1) * scale, random.get_double(-1, 1) * scale,
                         random.get_double(-1, 1) * scale);
  std::vector<Surface::Location> serial;
  for (const Point& q : queries)
    serial.push_back(Surface(m).closest_point(q));
  const Surface shared(m); // the search structure is built by whichever thread asks first
  std::vector<Surface::Location> parallel(queries.size());
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = t; i < queries.size(); i += 4)
        parallel[i] = shared.closest_point(queries[i]);
    });
  for (std::thread& t : threads)
    t.join();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(parallel[i].face, serial[i].face) << i;
    EXPECT_EQ(parallel[i].point, serial[i].point) << i;
  }
  // The free functions are the member; a surface moved after its first query answers the same.
  EXPECT_EQ(S::closest_point_on_limit(shared, queries[0]).point, serial[0].point);
  Surface first(m);
  EXPECT_EQ(first.closest_point(queries[1]).point, serial[1].point);
  const Surface moved(std::move(first));
  EXPECT_EQ(moved.closest_point(queries[2]).point, serial[2].point);
  EXPECT_EQ(S::closest_point_on_limit<S::Catmull_clark_mask>(m, queries[0]).point, serial[0].point);
}

// The patches kept stay within Limit_surface_options::max_cache_bytes,
// several threads evaluating at once; a face past the budget is built for
// each evaluation, and the surface is the same to the bit.
TEST(Limit_surface, CacheStaysWithinItsBudget)
{
  const Mesh m = build(read_shape(test::data("opensubdiv/catmark_nonquads.obj")));
  const std::size_t per_face = 8; // samples of each face's grid (cycled through)
  // Each thread evaluates every face, from its own first face on (so that
  // threads build some faces at once), into its own list, in face order.
  const auto evaluate_all = [&](const Surface& surface, int threads) {
    const std::size_t nf = m.number_of_faces();
    std::vector<std::vector<Point>> points(std::size_t(threads), std::vector<Point>(nf * per_face));
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
      workers.emplace_back([&, t] {
        for (std::size_t i = 0; i < nf; ++i) {
          const std::size_t f = (i + std::size_t(t) * nf / std::size_t(threads)) % nf;
          const auto grid = parameter_grid(int(m.degree(CGAL_ext::Face_index(f))), 3);
          for (std::size_t k = 0; k < per_face; ++k)
            points[std::size_t(t)][f * per_face + k] =
              surface.evaluate(CGAL_ext::Face_index(f), grid[k % grid.size()][0], grid[k % grid.size()][1]).point;
        }
      });
    for (std::thread& w : workers)
      w.join();
    for (std::size_t t = 1; t < points.size(); ++t)
      EXPECT_EQ(points[t], points[0]) << "thread " << t;
    return points[0];
  };
  const Surface unbounded(m);
  const std::vector<Point> reference = evaluate_all(unbounded, 1);
  const std::size_t all = unbounded.cached_bytes();
  ASSERT_GT(all, 0u);
  for (std::size_t budget : {all / 3, std::size_t(0)}) {
    SCOPED_TRACE("budget " + std::to_string(budget));
    S::Limit_surface_options options;
    options.max_cache_bytes = budget;
    const Surface bounded(m, CGAL_ext::parameters::default_values(), options);
    EXPECT_EQ(evaluate_all(bounded, 4), reference); // kept faces and rebuilt ones alike
    EXPECT_LE(bounded.cached_bytes(), budget);
    if (budget > 0)
      EXPECT_GT(bounded.cached_bytes(), 0u);
  }
}

// In an exact kernel the point found is the surface exactly at the
// parameter found, the same parameter as in double.
TEST(Limit_surface, ClosestPointInAnExactKernel)
{
  using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Pq = Kq::Point_3;
  std::vector<Pq> exact_points;
  std::vector<Point> points;
  const CGAL_ext::Mobius_mesh<Pq> mq = torus<Pq>(5, 4, exact_points);
  const Mesh m = torus<Point>(5, 4, points);
  const S::Limit_surface<S::Catmull_clark_mask, Pq> exact(mq);
  const Surface inexact(m);
  for (const Point& q : {Point(3, 4, 20), Point(10, 1, -5), Point(7.5, 9.25, 2)}) {
    const auto a = exact.closest_point(Pq(q.x(), q.y(), q.z()));
    const auto b = inexact.closest_point(q);
    EXPECT_EQ(a.face, b.face);
    EXPECT_NEAR(CGAL::to_double(a.squared_distance), b.squared_distance, 1e-9 * b.squared_distance + 1e-12);
  }
  EXPECT_THROW(Surface(Mesh()).closest_point(Point(0, 0, 0)), CGAL_ext::Parameter_error);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(inexact.closest_point(Point(nan, 0, 0)), CGAL_ext::Parameter_error);
  EXPECT_THROW(Surface(m, CGAL_ext::parameters::default_values(), S::Limit_surface_options{2, 40}),
               CGAL_ext::Parameter_error);
}

// A sampling of more triangles than 32 bits number is refused before it is
// made: 2 112 quads at projection_rate 1024 would be 2 · 1024² each, 4.4e9.
// (Were the check gone, the structure would ask for some 100 GB and this
// test would stop on the allocation.)
TEST(Limit_surface, ClosestPointRefusesASamplingTooLargeToNumber)
{
  Mesh m;
  CGAL_ext::make_torus(m, 64, 33);
  S::Limit_surface_options options;
  options.projection_rate = 1024;
  const Surface surface(m, CGAL_ext::parameters::default_values(), options);
  try {
    surface.closest_point(Point(3, 0, 0));
    ADD_FAILURE() << "no Size_error";
  } catch (const CGAL_ext::Size_error& e) {
    EXPECT_EQ(e.element(), "triangles");
    EXPECT_EQ(e.count(), 2ull * 1024 * 1024 * m.number_of_faces());
    EXPECT_EQ(e.limit(), 4294967295ull);
  }
  options.projection_rate = 2; // the same surface at a rate that fits: a point off it comes back
  const auto e = surface.evaluate(CGAL_ext::Face_index(0), 0.5, 0.5);
  const auto at = Surface(m, CGAL_ext::parameters::default_values(), options).closest_point(e.point + 0.1 * e.normal);
  EXPECT_NEAR(at.squared_distance, 0.01, 1e-9);
}

// ---- Loop ----

// A torus of 2 nu nv triangles, every vertex of valence 6, with rational
// coordinates: the quads of torus() split along (i + 1, j) - (i, j + 1), so
// that grid steps (1, 0), (0, 1), (-1, 1) are the edges.
template <class P>
CGAL_ext::Mobius_mesh<P> triangle_torus(int nu, int nv, std::vector<P>& points)
{
  points.clear();
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      points.emplace_back(i * 4 + (j % 3), j * 5 - (i % 2), (i * j) % 7);
  std::vector<std::vector<std::size_t>> faces;
  auto id = [&](int i, int j) { return std::size_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  CGAL_ext::Mobius_mesh<P> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  return m;
}

// Stam's quartic box-spline basis in barycentric coordinates (a, b, c of
// the triangle's corners 0, 1, 2): the function of the point over a corner,
// of the point across an edge, and of a far point near corner `a` on the
// side of `b`.
template <class FT>
FT stam_corner(const FT& a, const FT& b, const FT& c)
{
  auto p = [](const FT& x, int k) { FT r(1); for (int i = 0; i < k; ++i) r *= x; return r; };
  return (p(b, 4) + 6 * p(b, 3) * c + 8 * p(b, 3) * a + 36 * p(b, 2) * c * a + 24 * p(b, 2) * p(a, 2) +
          24 * b * p(a, 3) + p(c, 4) + 6 * p(c, 3) * b + 8 * p(c, 3) * a + 36 * p(c, 2) * b * a +
          24 * p(c, 2) * p(a, 2) + 24 * c * p(a, 3) + 6 * p(a, 4) + 60 * p(a, 2) * b * c + 12 * p(b, 2) * p(c, 2)) /
         FT(12);
}
template <class FT>
FT stam_edge(const FT& a, const FT& b, const FT& c)
{
  auto p = [](const FT& x, int k) { FT r(1); for (int i = 0; i < k; ++i) r *= x; return r; };
  return (p(a, 4) + 2 * p(a, 3) * c + 6 * p(a, 3) * b + 6 * p(a, 2) * b * c + 12 * p(a, 2) * p(b, 2) + p(b, 4) +
          2 * p(b, 3) * c + 6 * p(b, 3) * a + 6 * p(b, 2) * a * c) /
         FT(12);
}
template <class FT>
FT stam_far(const FT& a, const FT& b)
{
  return (a * a * a * a + 2 * a * a * a * b) / FT(12);
}

// The closed form at (u, v) of a triangle of triangle_torus(): the twelve
// lattice points around it, each at P0 + x (P1 - P0) + y (P2 - P0) on the
// grid, weighted by Stam's functions of the barycentric coordinates.
template <class P, class FT>
P box_spline_closed_form(const CGAL_ext::Mobius_mesh<P>& m, CGAL_ext::Face_index f, int nu, int nv, const FT& u,
                         const FT& v)
{
  std::vector<std::array<int, 2>> c;
  for (CGAL_ext::Vertex_index x : CGAL_ext::vertices_around_face(m.halfedge(f), m))
    c.push_back({int(x.idx()) / nv, int(x.idx()) % nv});
  auto step = [](int d, int n) { d = ((d % n) + n) % n; return d > n / 2 ? d - n : d; };
  const std::array<int, 2> e1{step(c[1][0] - c[0][0], nu), step(c[1][1] - c[0][1], nv)};
  const std::array<int, 2> e2{step(c[2][0] - c[0][0], nu), step(c[2][1] - c[0][1], nv)};
  const FT a = FT(1) - u - v, b = u, cc = v;
  const struct
  {
    int x, y;
    FT w;
  } terms[12] = {{0, 0, stam_corner(a, b, cc)},  {1, 0, stam_corner(b, cc, a)},  {0, 1, stam_corner(cc, a, b)},
                 {1, -1, stam_edge(a, b, cc)},   {1, 1, stam_edge(b, cc, a)},    {-1, 1, stam_edge(cc, a, b)},
                 {0, -1, stam_far(a, b)},        {-1, 0, stam_far(a, cc)},       {2, 0, stam_far(b, cc)},
                 {2, -1, stam_far(b, a)},        {-1, 2, stam_far(cc, a)},       {0, 2, stam_far(cc, b)}};
  FT x(0), y(0), z(0);
  for (const auto& t : terms) {
    const int i = c[0][0] + t.x * e1[0] + t.y * e2[0], j = c[0][1] + t.x * e1[1] + t.y * e2[1];
    const P& p = m.point(CGAL_ext::Vertex_index(std::size_t(((i % nu) + nu) % nu * nv + ((j % nv) + nv) % nv)));
    x += t.w * p.x();
    y += t.w * p.y();
    z += t.w * p.z();
  }
  return P(x, y, z);
}

TEST(Limit_surface, RegularLoopTorusIsTheBoxSpline)
{
  std::vector<Point> points;
  const Mesh m = triangle_torus<Point>(6, 7, points);
  const Loop_surface surface(m);
  const double scale = largest_coordinate(m);
  double worst = 0;
  for (CGAL_ext::Face_index f : m.faces()) {
    EXPECT_EQ(surface.number_of_patches(f), 1u);
    for (const auto& uv : triangle_grid(6)) {
      const Point a = surface.evaluate(f, uv[0], uv[1]).point;
      const Point b = box_spline_closed_form(m, f, 6, 7, uv[0], uv[1]);
      worst = std::max(worst, std::sqrt(CGAL::squared_distance(a, b)));
    }
  }
  EXPECT_LE(worst, 1e-14 * scale);
  RecordProperty("position", sci(worst / scale));
}

TEST(Limit_surface, RegularLoopTorusIsExactWithRationals)
{
  using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Pq = Kq::Point_3;
  std::vector<Pq> points;
  const CGAL_ext::Mobius_mesh<Pq> m = triangle_torus<Pq>(5, 6, points);
  const S::Limit_surface<S::Loop_mask, Pq> surface(m);
  for (CGAL_ext::Face_index f : m.faces())
    for (const auto& uv : {std::array<CGAL::Gmpq, 2>{CGAL::Gmpq(1, 3), CGAL::Gmpq(2, 7)},
                           std::array<CGAL::Gmpq, 2>{CGAL::Gmpq(0), CGAL::Gmpq(1)},
                           std::array<CGAL::Gmpq, 2>{CGAL::Gmpq(5, 9), CGAL::Gmpq(1, 3)}})
      EXPECT_EQ(surface.evaluate(f, uv[0], uv[1]).point, box_spline_closed_form(m, f, 5, 6, uv[0], uv[1]));
}

// Whether v or an edge at it is semi-sharp: limit_point() then takes the
// crease or corner rule at once, where the surface reaches it only after
// the sharpness has decayed.
bool semi_sharp_at(const Mesh& m, CGAL_ext::Vertex_index v)
{
  auto semi = [](float s) { return s > 0 && s < 10; };
  if (const auto vs = m.property_map<CGAL_ext::Vertex_index, float>("v:sharpness"); vs && semi((*vs)[v]))
    return true;
  if (const auto es = m.property_map<CGAL_ext::Edge_index, float>("e:sharpness"))
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(v, m))
      if (semi((*es)[m.edge(d)]))
        return true;
  return false;
}

// At the corners of a triangle, the limit position of the vertex there
// (where no semi-sharpness is left to decay).
TEST(Limit_surface, LoopCornersAreLimitPoints)
{
  std::vector<std::pair<std::string, Mesh>> meshes;
  std::vector<Point> points;
  meshes.emplace_back("triangle_torus", triangle_torus<Point>(6, 7, points));
  for (const char* name : {"loop_tetrahedron", "loop_icos_semisharp", "loop_triangle_edgeonly"})
    meshes.emplace_back(name, build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj"))));
  for (const auto& [name, m] : meshes)
    for (auto boundary : {CGAL_ext::Boundary_interpolation::edge_only, CGAL_ext::Boundary_interpolation::edge_and_corner}) {
      const auto np = CGAL_ext::parameters::boundary_interpolation(boundary);
      const Loop_surface surface(m, np);
      double worst = 0;
      std::size_t compared = 0;
      for (CGAL_ext::Face_index f : m.faces()) {
        std::vector<CGAL_ext::Vertex_index> c;
        for (CGAL_ext::Vertex_index x : CGAL_ext::vertices_around_face(m.halfedge(f), m))
          c.push_back(x);
        const double uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
        for (std::size_t k = 0; k < 3; ++k) {
          if (semi_sharp_at(m, c[k]))
            continue;
          const Point a = surface.evaluate(f, uv[k][0], uv[k][1]).point;
          const Point b = S::limit_point<S::Loop_mask>(c[k], m, np);
          worst = std::max(worst, std::sqrt(CGAL::squared_distance(a, b)));
          ++compared;
        }
      }
      EXPECT_LE(worst, 1e-14 * largest_coordinate(m)) << name;
      EXPECT_GT(compared, m.number_of_faces()) << name;
      RecordProperty("corners_" + name, sci(worst / largest_coordinate(m)));
    }
}

TEST(Limit_surface, LoopRefusesWhatItCannotEvaluate)
{
  std::vector<Point> points;
  const Mesh m = triangle_torus<Point>(5, 5, points);
  const Loop_surface surface(m);
  EXPECT_THROW(surface.evaluate(CGAL_ext::Face_index(0), 0.75, 0.5), CGAL_ext::Parameter_error);
  EXPECT_THROW(surface.evaluate(CGAL_ext::Face_index(0), -0.25, 0.5), CGAL_ext::Parameter_error);
  EXPECT_THROW(surface.tessellate(0), CGAL_ext::Parameter_error);
  EXPECT_THROW(Loop_surface(Mesh()).closest_point(Point(0, 0, 0)), CGAL_ext::Parameter_error);
  const Mesh quads = torus<Point>(4, 4, points);
  EXPECT_THROW(Loop_surface{quads}, CGAL_ext::Parameter_error);
}

// Watertight: a valid mesh of the same Euler characteristic, borders and
// orientability, with V + E (N - 1) + F (N - 1)(N - 2) / 2 samples (no
// room for duplicates), unit normals but at base vertices, and at rate 1
// the base vertices' limit points (limit_point() where no semi-sharpness
// is left, exactly).
TEST(Limit_surface, LoopTessellationIsWatertight)
{
  std::vector<std::pair<std::string, Mesh>> meshes;
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 12, 3, 1, 1.0, 0.5, false);
  meshes.emplace_back("mobius_strip", strip);
  std::vector<Point> points;
  meshes.emplace_back("triangle_torus", triangle_torus<Point>(5, 6, points));
  for (const char* name : {"loop_tetrahedron", "loop_icos_semisharp", "loop_triangle_edgeonly"})
    meshes.emplace_back(name, build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj"))));
  for (const auto& [name, m] : meshes) {
    const Loop_surface surface(m);
    for (std::size_t N = 1; N <= 5; ++N) {
      const Mesh out = surface.tessellate(int(N));
      EXPECT_TRUE(out.is_valid()) << name << " rate " << N;
      EXPECT_EQ(out.number_of_faces(), m.number_of_faces() * N * N) << name << " rate " << N;
      EXPECT_EQ(CGAL_ext::euler_characteristic(out), CGAL_ext::euler_characteristic(m)) << name << " rate " << N;
      EXPECT_EQ(CGAL_ext::number_of_border_cycles(out), CGAL_ext::number_of_border_cycles(m)) << name << " rate " << N;
      EXPECT_EQ(CGAL_ext::is_orientable(out), CGAL_ext::is_orientable(m)) << name << " rate " << N;
      EXPECT_EQ(out.number_of_vertices(),
                m.number_of_vertices() + m.number_of_edges() * (N - 1) + m.number_of_faces() * (N - 1) * (N - 2) / 2)
        << name << " rate " << N;
      const auto normals = out.property_map<CGAL_ext::Vertex_index, K::Vector_3>("v:normal");
      ASSERT_TRUE(normals.has_value()) << name;
      for (CGAL_ext::Vertex_index v : out.vertices()) {
        const double length = std::sqrt((*normals)[v].squared_length());
        if (length == 0)
          EXPECT_LT(v.idx(), m.number_of_vertices()) << name << " rate " << N;
        else
          EXPECT_NEAR(length, 1.0, 1e-12) << name << " rate " << N;
      }
      if (N == 1)
        for (CGAL_ext::Vertex_index v : m.vertices())
          if (!semi_sharp_at(m, v)) {
            EXPECT_EQ(out.point(v), S::limit_point<S::Loop_mask>(v, m)) << name << " v" << v.idx();
          }
    }
  }
  EXPECT_EQ(S::tessellate<S::Loop_mask>(strip, 2).points().data(), Loop_surface(strip).tessellate(2).points().data());
}

// The shapes the Loop projection tests walk: one-sided (with regular
// triangles inside), valence 3, borders and corners.
std::vector<std::pair<std::string, Mesh>> loop_projection_shapes()
{
  std::vector<std::pair<std::string, Mesh>> meshes;
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 12, 3, 1, 1.0, 0.5, false);
  meshes.emplace_back("mobius_strip", strip);
  for (const char* name : {"loop_tetrahedron", "loop_triangle_edgeonly"})
    meshes.emplace_back(name, build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj"))));
  return meshes;
}

TEST(Limit_surface, LoopClosestPointFindsTheFootOfTheNormal)
{
  closest_point_finds_the_foot_of_the_normal<Loop_surface>(loop_projection_shapes());
}

TEST(Limit_surface, LoopClosestPointIsNoFartherThanAnySample)
{
  closest_point_is_no_farther_than_any_sample<Loop_surface>(loop_projection_shapes());
}

// A Loop triangle's long side, u + v = 1, in an exact kernel: the search runs
// in double, where 1 - t + t may pass 1; the parameter found is in the
// triangle exactly, and the distances are the double surface's. Queries
// pushed off the middle of each long side, and a projection rate (5) whose
// samples i/5 + j/5 pass 1 in double.
TEST(Limit_surface, LoopClosestPointInAnExactKernel)
{
  using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Pq = Kq::Point_3;
  std::vector<Pq> exact_points;
  std::vector<Point> points;
  const CGAL_ext::Mobius_mesh<Pq> mq = triangle_torus<Pq>(5, 6, exact_points);
  const Mesh m = triangle_torus<Point>(5, 6, points);
  S::Limit_surface_options options;
  options.projection_rate = 5;
  const S::Limit_surface<S::Loop_mask, Pq> exact(mq, CGAL_ext::parameters::default_values(), options);
  const Loop_surface inexact(m, CGAL_ext::parameters::default_values(), options);
  std::size_t tried = 0;
  for (CGAL_ext::Face_index f : m.faces()) {
    if (f.idx() % 3 != 0) // a third of the faces, spread round the torus: Gmpq is slow
      continue;
    const auto e = inexact.evaluate(f, 0.3, 0.7);
    const Point q = e.point + 0.05 * e.normal;
    const auto a = exact.closest_point(Pq(q.x(), q.y(), q.z()));
    const auto b = inexact.closest_point(q);
    EXPECT_GE(a.u, 0);
    EXPECT_GE(a.v, 0);
    EXPECT_LE(a.u + a.v, 1);
    EXPECT_NEAR(CGAL::to_double(a.squared_distance), b.squared_distance, 1e-9 * b.squared_distance + 1e-12);
    ++tried;
  }
  EXPECT_EQ(tried, (m.number_of_faces() + 2) / 3);
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
class Loop_against_bfr : public ::testing::TestWithParam<const char*>
{};

TEST_P(Loop_against_bfr, PositionsAndDerivatives)
{
  const Shape s = read_shape(test::data(std::string("opensubdiv/") + GetParam() + ".obj"));
  const Mesh m = build(s);
  const Loop_surface surface(m, CGAL_ext::parameters::boundary_interpolation(s.boundary).crease_method(s.crease_method));
  const Differences d = against_bfr_on_mesh(m, surface, s.boundary, s.crease_method);
  const double scale = largest_coordinate(m);
  EXPECT_LE(d.position, 1e-10 * scale) << GetParam();
  EXPECT_LE(d.first, 1e-10 * scale) << GetParam();
  EXPECT_LE(d.second_up_to_sign, 1e-9 * scale) << GetParam();
  record(d, scale);
}

// Valence 3 everywhere; valence 5 with semi-sharp creases; borders.
INSTANTIATE_TEST_SUITE_P(Shapes, Loop_against_bfr,
                         ::testing::Values("loop_tetrahedron", "loop_icos_semisharp", "loop_triangle_edgeonly"));

// A bumpy triangulated grid with a border: regular border vertices (three
// faces), corners of one and of two faces, an interior vertex of valence 5
// and one of 7, under both boundary rules, and with an infinitely sharp and
// a semi-sharp crease under both crease methods.
TEST(Limit_surface, LoopGridAgainstBfr)
{
  const int n = 6;
  std::vector<Point> points;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      points.emplace_back(i + 0.1 * (j % 2), j, 0.3 * std::sin(i * 1.3 + j * 0.7));
  auto id = [&](int i, int j) { return std::size_t(j * (n + 1) + i); };
  std::vector<std::vector<std::size_t>> faces;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // One quad split the other way: valences 5 and 7 next to each other.
      if (i == 3 && j == 2) {
        faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  const double scale = largest_coordinate(m);
  for (auto boundary : {CGAL_ext::Boundary_interpolation::edge_only, CGAL_ext::Boundary_interpolation::edge_and_corner})
    for (int creased = 0; creased < 3; ++creased) { // none; uniform; Chaikin
      const auto method = creased == 2 ? CGAL_ext::Crease_method::chaikin : CGAL_ext::Crease_method::uniform;
      Mesh c = m;
      if (creased) {
        auto es = c.add_property_map<CGAL_ext::Edge_index, float>("e:sharpness", 0.0f).first;
        for (CGAL_ext::Edge_index e : c.edges()) {
          const auto a = c.vertex(e, 0).idx(), b = c.vertex(e, 1).idx();
          if (a / (n + 1) == 4 && b / (n + 1) == 4) // the row j = 4: infinitely sharp
            es[e] = 10.0f;
          if (a % (n + 1) == 1 && b % (n + 1) == 1 && a / (n + 1) < 3 && b / (n + 1) < 3) // a semi-sharp column, 1.5 then 2.5
            es[e] = 1.5f + float(std::min(a, b) / (n + 1));
        }
      }
      const Loop_surface surface(c, CGAL_ext::parameters::boundary_interpolation(boundary).crease_method(method));
      const Differences d = against_bfr_on_mesh(c, surface, boundary, method);
      EXPECT_LE(d.position, 1e-10 * scale) << int(boundary) << creased;
      EXPECT_LE(d.first, 1e-10 * scale) << int(boundary) << creased;
      EXPECT_LE(d.second_up_to_sign, 1e-9 * scale) << int(boundary) << creased;
      const std::string what = std::string(boundary == CGAL_ext::Boundary_interpolation::edge_only ? "edge_only" : "edge_and_corner") +
                               (creased == 1 ? "_creased" : creased == 2 ? "_creased_chaikin" : "");
      RecordProperty(what + "_position", sci(d.position / scale));
      RecordProperty(what + "_first", sci(d.first / scale));
      RecordProperty(what + "_second", sci(d.second_up_to_sign / scale));
    }
}

TEST(Limit_surface, RegularLoopTorusAgainstBfr)
{
  std::vector<Point> points;
  const Mesh m = triangle_torus<Point>(6, 7, points);
  const Loop_surface surface(m);
  const Differences d = against_bfr_on_mesh(m, surface, CGAL_ext::Boundary_interpolation::edge_only,
                                            CGAL_ext::Crease_method::uniform);
  const double scale = largest_coordinate(m);
  EXPECT_LE(d.position, 1e-12 * scale);
  EXPECT_LE(d.first, 1e-12 * scale);
  EXPECT_LE(d.second, 1e-12 * scale);
  record(d, scale);
}
// Far's uniform refinement as the reference where the surface is exact:
// the limit points of its level `level` are points of the surface, and a
// face-varying channel holding each base face's own corner parameters
// (and the face), linear everywhere, says where. The largest difference
// from `surface` there.
struct Far_point
{
  double p[3];
  void Clear() { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Far_point& q, double w)
  {
    for (int i = 0; i < 3; ++i)
      p[i] += w * q.p[i];
  }
};

template <class Surf>
double gap_to_far_refinement(const Mesh& m, const Surf& surface, CGAL_ext::Crease_method method, int level)
{
  constexpr bool loop = std::is_same_v<Surf, Loop_surface>;
  std::vector<int> sizes, indices, at_corner, crease_indices;
  std::vector<Far_point> points, parameters; // parameters: (u, v, face)
  std::vector<float> crease_values;
  for (const Point& p : m.points().data())
    points.push_back({{p.x(), p.y(), p.z()}});
  for (CGAL_ext::Face_index f : m.faces()) {
    const std::vector<std::array<double, 2>> corner_uv =
      loop ? std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {0, 1}}
           : std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::size_t k = 0;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(m.halfedge(f), m)) {
      indices.push_back(int(v.idx()));
      at_corner.push_back(int(parameters.size()));
      parameters.push_back({{corner_uv[k][0], corner_uv[k][1], double(f.idx())}});
      ++k;
    }
    sizes.push_back(int(k));
  }
  const auto es = m.property_map<CGAL_ext::Edge_index, float>("e:sharpness");
  for (CGAL_ext::Edge_index e : m.edges())
    if (es && (*es)[e] > 0) {
      crease_indices.insert(crease_indices.end(), {int(m.vertex(e, 0).idx()), int(m.vertex(e, 1).idx())});
      crease_values.push_back((*es)[e]);
    }
  Far::TopologyDescriptor desc = descriptor(int(points.size()), sizes, indices, crease_indices, crease_values);
  Far::TopologyDescriptor::FVarChannel channel;
  channel.numValues = int(parameters.size());
  channel.valueIndices = at_corner.data();
  desc.numFVarChannels = 1;
  desc.fvarChannels = &channel;
  Sdc::Options options = test::opensubdiv_options(CGAL_ext::Boundary_interpolation::edge_only, method);
  options.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_ALL);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(desc, Factory::Options(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, options)));
  Far::TopologyRefiner::UniformOptions uniform(level);
  uniform.fullTopologyInLastLevel = true; // Limit() needs it
  refiner->RefineUniform(uniform);
  points.resize(std::size_t(refiner->GetNumVerticesTotal()));
  parameters.resize(std::size_t(refiner->GetNumFVarValuesTotal(0)));
  Far::PrimvarRefinerReal<double> primvars(*refiner);
  Far_point* p = points.data();
  Far_point* t = parameters.data();
  for (int l = 1; l <= level; ++l) {
    Far_point* next_p = p + refiner->GetLevel(l - 1).GetNumVertices();
    Far_point* next_t = t + refiner->GetLevel(l - 1).GetNumFVarValues(0);
    primvars.Interpolate(l, p, next_p);
    primvars.InterpolateFaceVarying(l, t, next_t, 0);
    p = next_p;
    t = next_t;
  }
  const Far::TopologyLevel& last = refiner->GetLevel(level);
  std::vector<Far_point> limit(std::size_t(last.GetNumVertices()));
  Far_point* limit_points = limit.data();
  primvars.Limit(p, limit_points);
  std::vector<bool> seen(limit.size(), false);
  double largest = 0;
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const auto vertices = last.GetFaceVertices(f);
    const auto values = last.GetFaceFVarValues(f, 0);
    for (int k = 0; k < vertices.size(); ++k) {
      if (seen[std::size_t(vertices[k])])
        continue;
      seen[std::size_t(vertices[k])] = true;
      const Far_point& uvf = t[values[k]];
      const auto r = surface.evaluate(CGAL_ext::Face_index(std::size_t(std::lround(uvf.p[2]))), uvf.p[0], uvf.p[1]);
      largest = std::max(largest, gap(r.point - CGAL::ORIGIN, limit[std::size_t(vertices[k])].p));
    }
  }
  return largest;
}

// Chaikin's rule gives a child edge at a vertex the average of the vertex's
// semi-sharp edges, and the point of an edge takes its rule from both of its
// children: the surface over a face depends on the whole rings of its
// corners' neighbours. Regular tori (no patch is approximated) with random
// semi-sharp creases, against Far's refinement (Bfr's local meshes keep one
// ring and differ from it there, see limit_surface.md).
TEST(Limit_surface, ChaikinCreasesAsFarsRefinement)
{
  std::mt19937 random(7);
  const float sharpness[] = {0.5f, 1.0f, 1.5f, 2.7f, 4.0f};
  for (bool loop : {false, true})
    for (int round = 0; round < 3; ++round) {
      std::vector<Point> points;
      Mesh m = loop ? triangle_torus<Point>(6, 7, points) : torus<Point>(6, 7, points);
      auto es = m.add_property_map<CGAL_ext::Edge_index, float>("e:sharpness", 0.0f).first;
      for (CGAL_ext::Edge_index e : m.edges())
        if (std::uniform_int_distribution<int>(0, 2)(random) == 0)
          es[e] = sharpness[std::uniform_int_distribution<int>(0, 4)(random)];
      const auto np = CGAL_ext::parameters::crease_method(CGAL_ext::Crease_method::chaikin);
      const double d = loop ? gap_to_far_refinement(m, Loop_surface(m, np), CGAL_ext::Crease_method::chaikin, 4)
                            : gap_to_far_refinement(m, Surface(m, np), CGAL_ext::Crease_method::chaikin, 4);
      const double scale = largest_coordinate(m);
      // Sharpness is a float, and Chaikin's mean of a vertex's semi-sharp
      // edges is summed in the order of its ring, which a copied
      // neighbourhood need not share with the whole mesh: a last bit of a
      // sharpness moves a point by about 1e-7 of its scale (1e-9 here);
      // a neighbour's ring left out moves it by 6e-5 to 1.3e-3.
      EXPECT_LE(d, 1e-6 * scale) << (loop ? "Loop, round " : "Catmull-Clark, round ") << round;
      RecordProperty(std::string(loop ? "loop_" : "catmull_clark_") + std::to_string(round), sci(d / scale));
    }
}

class Loop_tessellation_against_bfr : public ::testing::TestWithParam<const char*>
{};

TEST_P(Loop_tessellation_against_bfr, SameSamplesAndFacets) { tessellation_against_bfr<Loop_surface>(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Shapes, Loop_tessellation_against_bfr,
                         ::testing::Values("loop_tetrahedron", "loop_triangle_edgeonly"));

// A Möbius strip of triangles (valence 6 inside, regular and irregular
// border vertices) against Bfr on its orientation double cover.
TEST(Limit_surface, LoopMobiusStripAgainstBfrOnItsDoubleCover)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3, 1, 1.0, 0.5, false);
  ASSERT_FALSE(CGAL_ext::is_orientable(m));
  const Differences d = against_bfr_on_double_cover(m, Loop_surface(m));
  const double scale = largest_coordinate(m);
  EXPECT_LE(d.position, 1e-10 * scale);
  EXPECT_LE(d.first, 1e-10 * scale);
  EXPECT_LE(d.second_up_to_sign, 1e-9 * scale);
  record(d, scale);
}

#endif // CGAL_EXT_HAVE_OPENSUBDIV

// Our second derivatives are those of our first derivatives (which agree
// with Bfr's), by central differences at the inner points of a grid of
// every triangle: box-spline patches, turned middle children (where Bfr's
// have the other sign) and Gregory triangles near the irregular vertices.
TEST(Limit_surface, LoopSecondDerivativesAreThoseOfTheFirst)
{
  for (const char* name : {"loop_tetrahedron", "loop_icos_semisharp"}) {
    const Mesh m = build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj")));
    const Loop_surface surface(m);
    const double h = 1e-5, scale = largest_coordinate(m);
    double worst = 0;
    for (CGAL_ext::Face_index f : m.faces())
      for (int i = 1; i < 7; ++i)
        for (int j = 1; i + j < 7; ++j) {
          const double u = i / 7.0, v = j / 7.0;
          const auto e = surface.evaluate(f, u, v);
          const auto up = surface.evaluate(f, u + h, v), um = surface.evaluate(f, u - h, v);
          const auto vp = surface.evaluate(f, u, v + h), vm = surface.evaluate(f, u, v - h);
          for (const auto& [exact, difference] :
               {std::pair{e.duu, (up.du - um.du) / (2 * h)}, std::pair{e.duv, (vp.du - vm.du) / (2 * h)},
                std::pair{e.duv, (up.dv - um.dv) / (2 * h)}, std::pair{e.dvv, (vp.dv - vm.dv) / (2 * h)}})
            worst = std::max(worst, std::sqrt((exact - difference).squared_length()));
        }
    EXPECT_LE(worst, 1e-7 * scale) << name; // 1.1e-9 and 1.3e-9 measured: the differences' own error
    RecordProperty(std::string("central_differences_") + name, sci(worst / scale));
  }
}


// Tessellation to a tolerance: the shapes, with the Möbius strip, under
// both schemes.
struct Tolerance_case
{
  std::string name;
  Mesh mesh;
  bool loop;
};

std::vector<Tolerance_case> tolerance_cases()
{
  std::vector<Tolerance_case> cases;
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  cases.push_back({"mobius_strip", strip, false});
  for (const char* name : {"catmark_nonquads", "catmark_edgecorner", "catmark_smoothtris1", "loop_tetrahedron"})
    cases.push_back({name, build(read_shape(test::data(std::string("opensubdiv/") + name + ".obj"))),
                     std::string(name).rfind("loop", 0) == 0});
  return cases;
}

// The samples of each face are Bfr::Tessellation's at the rates chosen (its
// coordinates, the face's outer rates from corner 0 and its inner rates,
// evaluated to a sample of ours within 1e-12 of the size), every sample is
// one of them, and the result is watertight with the base's topology.
template <class Surf>
void tolerance_tessellation_against_bfr(const Tolerance_case& c, double tolerance)
{
  const Surf surface(c.mesh);
  const Mesh& m = c.mesh;
  const double scale = largest_coordinate(m);
  const Mesh out = surface.tessellate_to_tolerance(tolerance * scale);
  const S::internal::Tessellation_rates rates =
    S::internal::tolerance_rates(surface, m, tolerance * scale, 64, c.loop);
  EXPECT_TRUE(out.is_valid()) << c.name;
  EXPECT_EQ(CGAL_ext::euler_characteristic(out), CGAL_ext::euler_characteristic(m)) << c.name;
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(out), CGAL_ext::number_of_border_cycles(m)) << c.name;
  EXPECT_EQ(CGAL_ext::is_orientable(out), CGAL_ext::is_orientable(m)) << c.name;
  // Every facet keeps its base face's orientation: a Möbius edge of the base
  // becomes as many Möbius edges as its segments, and no other edge is one
  // (a strip's triangle turned over would make its edges Möbius edges).
  std::size_t mobius = 0, expected_mobius = 0;
  for (CGAL_ext::Edge_index e : out.edges())
    mobius += out.is_mobius(e) ? 1 : 0;
  for (CGAL_ext::Edge_index e : m.edges())
    expected_mobius += m.is_mobius(e) ? std::size_t(rates.edge[e.idx()]) : 0;
  EXPECT_EQ(mobius, expected_mobius) << c.name << " at " << tolerance;
  // The per-corner normals of a one-sided result agree with each facet's own.
  if (const auto corners = out.property_map<CGAL_ext::Halfedge_index, K::Vector_3>("h:normal"))
    for (CGAL_ext::Face_index g : out.faces()) {
      const K::Vector_3 fn = CGAL_ext::face_normal(g, out);
      for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(out.halfedge(g), out))
        EXPECT_GT((*corners)[d.halfedge()] * fn, 0) << c.name << " facet " << g.idx();
    }
  std::set<std::size_t> matched;
  double worst = 0;
  // The samples by x, so that a point's nearest sample is looked for among
  // those of nearly its x (within 1e-9 of the size: none farther can match).
  std::vector<std::pair<double, std::size_t>> by_x;
  for (CGAL_ext::Vertex_index w : out.vertices())
    by_x.emplace_back(out.point(w).x(), w.idx());
  std::sort(by_x.begin(), by_x.end());
  const double window = 1e-9 * scale;
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<int> r;
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      r.push_back(rates.edge[m.edge(m.next(d)).idx()]);
    const auto inner = rates.inner[f.idx()];
    r.push_back(inner[0]);
    if (m.degree(f) == 4)
      r.push_back(inner[1]);
    const Bfr::Tessellation t(Bfr::Parameterization(c.loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, int(m.degree(f))),
                              int(r.size()), r.data());
    ASSERT_TRUE(t.IsValid()) << c.name;
    std::vector<double> uv(2 * std::size_t(t.GetNumCoords()));
    t.GetCoords(uv.data());
    for (std::size_t k = 0; k < std::size_t(t.GetNumCoords()); ++k) {
      double u = uv[2 * k], v = uv[2 * k + 1];
      if (c.loop) { // to float precision in Bfr: taken at the fraction of a rate (or 1 / 3) they stand for
        const auto snap = [&](double x) {
          double best = std::round(x * 3) / 3;
          for (int den : r)
            if (std::abs(std::round(x * den) / den - x) < std::abs(best - x))
              best = std::round(x * den) / den;
          EXPECT_LE(std::abs(best - x), 1e-6) << c.name;
          return best;
        };
        u = snap(u);
        v = std::min(snap(v), 1.0 - u);
      }
      const Point p = surface.evaluate(f, u, v).point;
      double d = 1e300;
      std::size_t best = 0;
      for (auto it = std::lower_bound(by_x.begin(), by_x.end(), std::pair<double, std::size_t>(p.x() - window, 0));
           it != by_x.end() && it->first <= p.x() + window; ++it)
        if (const double x = std::sqrt(CGAL::squared_distance(p, out.point(CGAL_ext::Vertex_index(it->second)))); x < d) {
          d = x;
          best = it->second;
        }
      worst = std::max(worst, d);
      matched.insert(best);
    }
  }
  EXPECT_LE(worst, 1e-12 * scale) << c.name << " at " << tolerance;
  EXPECT_EQ(matched.size(), out.number_of_vertices()) << c.name << " at " << tolerance;
}

TEST(Limit_surface, TessellationToToleranceHasBfrsSamples)
{
  for (const Tolerance_case& c : tolerance_cases())
    for (double tolerance : {1e-2, 1e-3}) {
      if (c.loop)
        tolerance_tessellation_against_bfr<Loop_surface>(c, tolerance);
      else
        tolerance_tessellation_against_bfr<Surface>(c, tolerance);
    }
}

template <class Surf>
void tolerance_bounds_its_edges(const Tolerance_case& c)
{
  const Surf surface(c.mesh);
  const Mesh& m = c.mesh;
  const double T = 1e-3 * largest_coordinate(m);
  const auto rates = S::internal::tolerance_rates(surface, m, T, 64, c.loop);
  const auto deviation = [&](CGAL_ext::Face_index f, int k, int rate) {
    const int n = int(m.degree(f));
    const auto at = [&](int i, int of) {
      const auto uv = S::internal::edge_parameter<double>(n, c.loop, k, i, of);
      return surface.evaluate(f, uv[0], uv[1]).point;
    };
    double chord = 0, curve = 0;
    for (int i = 0; i < rate; ++i) {
      const K::Segment_3 segment(at(i, rate), at(i + 1, rate));
      chord = std::max(chord, std::sqrt(surface.closest_point(CGAL::midpoint(segment.source(), segment.target())).squared_distance));
      curve = std::max(curve, std::sqrt(CGAL::squared_distance(at(2 * i + 1, 2 * rate), segment)));
    }
    return std::array<double, 2>{chord, curve};
  };
  for (CGAL_ext::Face_index f : m.faces()) {
    int k = 0;
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const int r = rates.edge[m.edge(m.next(d)).idx()];
      const bool border = m.is_border(m.edge(m.next(d)));
      EXPECT_LE(deviation(f, k, r)[border ? 1 : 0], 1.01 * T) << c.name << " f" << f.idx() << " edge " << k;
      ++k;
    }
  }
  const Mesh out = surface.tessellate_to_tolerance(T);
  double worst = 0;
  for (CGAL_ext::Face_index g : out.faces()) {
    K::Vector_3 sum = CGAL::NULL_VECTOR;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(out.halfedge(g), out))
      sum = sum + (out.point(v) - CGAL::ORIGIN);
    const Point centre = CGAL::ORIGIN + sum / double(out.degree(g));
    worst = std::max(worst, std::sqrt(CGAL::to_double(surface.closest_point(centre).squared_distance)));
  }
  EXPECT_LE(worst, 4 * T) << c.name;
  ::testing::Test::RecordProperty(c.name + "_worst_over_tolerance", std::to_string(worst / T));
  EXPECT_GT(surface.tessellate_to_tolerance(T / 4).number_of_vertices(), out.number_of_vertices()) << c.name;
}

// At the rate of each edge its segments lie within the tolerance of the
// surface at their midpoints (their distance to it found by closest_point(),
// not by the local Newton steps the rates are chosen with) and, on a border,
// within it of the border curve at its middle. The facets' centres lie
// within a few tolerances (measured: up to 2.6), and a finer tolerance gives
// more samples.
TEST(Limit_surface, TessellationToToleranceBoundsItsEdges)
{
  for (const Tolerance_case& c : tolerance_cases()) {
    if (c.name == "catmark_smoothtris1")
      continue; // one of each kind of face suffices here
    if (c.loop)
      tolerance_bounds_its_edges<Loop_surface>(c);
    else
      tolerance_bounds_its_edges<Surface>(c);
  }
}

TEST(Limit_surface, TessellationToToleranceRefusesABadTolerance)
{
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  const Surface surface(strip);
  for (double t : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(surface.tessellate_to_tolerance(t), CGAL_ext::Parameter_error) << t;
  // In exact numbers, the same rates and samples as in double.
  using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;
  CGAL_ext::Mobius_mesh<Kq::Point_3> exact;
  CGAL_ext::make_mobius_strip(exact, 12, 3);
  const S::Limit_surface<S::Catmull_clark_mask, Kq::Point_3> exact_surface(exact);
  const double T = 1e-2 * largest_coordinate(strip);
  const auto q = exact_surface.tessellate_to_tolerance(T);
  const Mesh d = surface.tessellate_to_tolerance(T);
  ASSERT_EQ(q.number_of_vertices(), d.number_of_vertices());
  EXPECT_EQ(q.number_of_faces(), d.number_of_faces());
  for (CGAL_ext::Vertex_index v : d.vertices())
    EXPECT_LE(std::sqrt(CGAL::squared_distance(d.point(v), Point(CGAL::to_double(q.point(v).x()), CGAL::to_double(q.point(v).y()),
                                                                 CGAL::to_double(q.point(v).z())))),
              1e-12);
}

} // namespace
} // namespace limit_surface_tests
