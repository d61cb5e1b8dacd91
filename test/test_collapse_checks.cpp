// The collapse predicate that decimation and remeshing stand on
// (Mobius_mesh/internal/Collapse_checks.h). References: angles worked out by
// hand on small meshes, and invariance under reversing faces (which moves
// Möbius edges but not the surface).

#include "test_util.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace collapse_checks_tests {

namespace {

using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using CGAL_ext::Dart;
using CGAL_ext::Edge_index;
using CGAL_ext::Face_index;
using CGAL_ext::Halfedge_index;
using CGAL_ext::Vertex_index;
using CGAL_ext::internal::Collapse_options;
using CGAL_ext::internal::Collapse_verdict;
using CGAL_ext::internal::check_collapse;

template <class P>
CGAL_ext::Mobius_mesh<P> mesh_of(const std::vector<P>& points, const std::vector<std::vector<std::size_t>>& faces)
{
  CGAL_ext::Mobius_mesh<P> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  return m;
}

// A flat hexagon fanned from its centre (vertex 0) with corners at integer
// coordinates, so that collinearity is exact: r1 = (1,2) and r2 = (-1,2) lie
// on the line y = 2.
Mesh flat_fan()
{
  std::vector<Point> points{Point(0, 0, 0), Point(2, 0, 0),   Point(1, 2, 0),
                            Point(-1, 2, 0), Point(-2, 0, 0), Point(-1, -2, 0), Point(1, -2, 0)};
  std::vector<std::vector<std::size_t>> faces;
  for (std::size_t i = 0; i < 6; ++i)
    faces.push_back({0, 1 + i, 1 + (i + 1) % 6});
  return mesh_of(points, faces);
}

template <class P>
Dart dart_from_to(const CGAL_ext::Mobius_mesh<P>& m, Vertex_index s, Vertex_index t)
{
  for (Halfedge_index h : m.halfedges())
    for (bool flipped : {false, true})
      if (m.source(Dart(h, flipped)) == s && m.target(Dart(h, flipped)) == t)
        return Dart(h, flipped);
  return Dart();
}

Edge_index edge_between(const Mesh& m, std::size_t a, std::size_t b)
{
  return m.edge(dart_from_to(m, Vertex_index(Vertex_index::size_type(a)), Vertex_index(Vertex_index::size_type(b))));
}

Collapse_options turn_bound(double degrees)
{
  Collapse_options o;
  o.min_cos_normal_turn = std::cos(degrees * CGAL_PI / 180);
  return o;
}

} // namespace

TEST(CollapseChecks, FlatFanAllowsCollapsesThatKeepItFlatAndRefusesFlipsAndDegenerateFaces)
{
  const Mesh m = flat_fan();
  const Dart d = dart_from_to(m, Vertex_index(0), Vertex_index(1)); // centre into r0 = (2,0)
  ASSERT_TRUE(d.is_valid());
  const Collapse_options o; // 90 degrees
  EXPECT_EQ(check_collapse(d, Point(2, 0, 0), m, o), Collapse_verdict::allowed);
  EXPECT_EQ(check_collapse(d, Point(1, 0, 0), m, o), Collapse_verdict::allowed);
  // Above the line y = 2 the triangle (centre, r1, r2) turns over.
  EXPECT_EQ(check_collapse(d, Point(0, 3, 0), m, o), Collapse_verdict::folds_over);
  // On it, that triangle has no area left.
  EXPECT_EQ(check_collapse(d, Point(0, 2, 0), m, o), Collapse_verdict::degenerates);
}

TEST(CollapseChecks, TheTurnBoundIsTheLargestAngleOfASurvivingFace)
{
  // Moving the centre to (1, 0, 1): the triangles next to the edge's own turn
  // by atan(1/2) = 26.57 degrees (normal (0, 2, 4) by hand), the two far ones
  // by atan(sqrt(5)/6) = 20.44 degrees.
  const Mesh m = flat_fan();
  const Dart d = dart_from_to(m, Vertex_index(0), Vertex_index(1));
  EXPECT_EQ(check_collapse(d, Point(1, 0, 1), m, turn_bound(26.0)), Collapse_verdict::folds_over);
  EXPECT_EQ(check_collapse(d, Point(1, 0, 1), m, turn_bound(27.0)), Collapse_verdict::allowed);
  // Lowered so that only the far ones would count: 20.44 < 21 < 26.57.
  EXPECT_EQ(check_collapse(d, Point(1, 0, 1), m, turn_bound(21.0)), Collapse_verdict::folds_over);
}

TEST(CollapseChecks, ProtectedEdgesStayAndTheirEndsDoNotMove)
{
  const Mesh m = flat_fan();
  const Dart d = dart_from_to(m, Vertex_index(0), Vertex_index(1));
  Collapse_options o;
  std::set<Edge_index> protected_edges{edge_between(m, 0, 1)};
  o.is_protected = [&](Edge_index e) { return protected_edges.count(e) != 0; };
  EXPECT_EQ(check_collapse(d, Point(2, 0, 0), m, o), Collapse_verdict::protected_edge);

  protected_edges = {edge_between(m, 1, 2)}; // r0 is on a protected edge: it must stay put
  EXPECT_EQ(check_collapse(d, Point(2, 0, 0), m, o), Collapse_verdict::allowed);
  EXPECT_EQ(check_collapse(d, Point(1, 0, 0), m, o), Collapse_verdict::moves_protected_end);

  protected_edges = {edge_between(m, 1, 2), edge_between(m, 0, 4)}; // both ends on features, the edge not
  EXPECT_EQ(check_collapse(d, Point(2, 0, 0), m, o), Collapse_verdict::moves_protected_end);
  EXPECT_EQ(check_collapse(d, Point(0, 0, 0), m, o), Collapse_verdict::moves_protected_end);
}

TEST(CollapseChecks, ATetrahedronCannotShrinkAndABorderTriangleCannotClose)
{
  const std::vector<Point> corners{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  const Mesh tetrahedron = mesh_of(corners, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  const Mesh triangle = mesh_of(corners, {{0, 1, 2}});
  for (const Mesh* m : {&tetrahedron, &triangle})
    for (Halfedge_index h : m->halfedges()) {
      const Dart d(h, false);
      EXPECT_EQ(check_collapse(d, m->point(m->target(d)), *m, Collapse_options()),
                Collapse_verdict::breaks_topology);
    }
}

TEST(CollapseChecks, VerdictsDoNotDependOnHowTheFacesAreOriented)
{
  // Every edge of a Möbius strip, to its midpoint and to a point lifted off the
  // strip, before and after reversing every other face (which moves the
  // Möbius edges): the same verdicts, since each face is compared with itself.
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3, 1, 1.0, 0.5, false);
  auto verdicts = [](const Mesh& mesh) {
    std::vector<std::pair<std::pair<Vertex_index, Vertex_index>, Collapse_verdict>> out;
    for (Edge_index e : mesh.edges()) {
      const Dart d = mesh.halfedge(e);
      Vertex_index s = mesh.source(d), t = mesh.target(d);
      const Dart along = s < t ? d : mesh.opposite(d);
      const Point a = mesh.point(mesh.source(along)), b = mesh.point(mesh.target(along));
      for (const Point& p : {CGAL::midpoint(a, b), Point(a.x(), a.y(), a.z() + 0.8)})
        out.push_back({{mesh.source(along), mesh.target(along)}, check_collapse(along, p, mesh, Collapse_options())});
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto before = verdicts(m);
  std::size_t refused = 0;
  for (const auto& v : before)
    refused += v.second != Collapse_verdict::allowed ? 1 : 0;
  EXPECT_GT(refused, 0u);
  EXPECT_LT(refused, before.size());
  const std::size_t mobius_before = CGAL_ext::number_of_mobius_edges(m);
  for (Face_index f : m.faces())
    if (f.idx() % 2 == 1)
      m.reverse_face_orientation(f);
  ASSERT_NE(CGAL_ext::number_of_mobius_edges(m), mobius_before);
  EXPECT_EQ(verdicts(m), before);
}

} // namespace collapse_checks_tests
