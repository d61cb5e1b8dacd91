// triangulate_faces(). References: areas and counts worked out by hand on
// small meshes, the Euler characteristic, border loops and orientability
// (which no triangulation changes).

#include "mesh_snapshot.h"
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/decimation.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace triangulate_faces_tests {

namespace {

using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using CGAL_ext::Dart;
using CGAL_ext::Face_index;
using CGAL_ext::Halfedge_index;
using CGAL_ext::Vertex_index;

template <class P>
CGAL_ext::Mobius_mesh<P> mesh_of(const std::vector<P>& points, const std::vector<std::vector<std::size_t>>& faces)
{
  CGAL_ext::Mobius_mesh<P> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  return m;
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

} // namespace

TEST(TriangulateFaces, KeepsChiAndAreaAndMakesSumOfNMinusTwoTriangles)
{
  // A planar convex hexagon, a square and two quads sharing edges, all walked
  // counterclockwise; areas by the shoelace formula.
  const std::vector<Point> points{Point(0, 0, 0),  Point(4, 0, 0),  Point(6, 2, 0), Point(4, 4, 0),
                                  Point(0, 4, 0),  Point(-2, 2, 0), Point(0, -4, 0), Point(4, -4, 0),
                                  Point(6, -2, 0), Point(2, -7, 0), Point(-1, -4, 0)};
  const std::vector<std::vector<std::size_t>> faces{
    {0, 1, 2, 3, 4, 5}, {6, 7, 1, 0}, {7, 8, 2, 1}, {6, 10, 9, 7}};
  Mesh m = mesh_of(points, faces);
  auto fm = m.add_property_map<Face_index, int>("f:label", -1).first;
  for (Face_index f : m.faces())
    fm[f] = int(f.idx()) * 10;
  const long long chi = CGAL_ext::euler_characteristic(m);
  const std::size_t borders = CGAL_ext::number_of_border_cycles(m);
  // Areas by hand: hexagon 24, square 16, quad 7-8-2-1: 8, quad 6-10-9-7: 7.5.
  const double area = 24 + 16 + 8 + 7.5;
  const std::size_t added = CGAL_ext::triangulate_faces(m);
  EXPECT_EQ(added, 3u + 1 + 1 + 1);
  EXPECT_EQ(m.number_of_faces(), (6u - 2) + (4 - 2) + (4 - 2) + (4 - 2));
  EXPECT_TRUE(m.is_valid());
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), chi);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), borders);
  double sum = 0;
  std::map<int, int> labels;
  for (Face_index f : m.faces()) {
    ASSERT_EQ(m.degree(f), 3u);
    std::vector<Point> t;
    for (Vertex_index v : CGAL_ext::vertices_around_face(f, m))
      t.push_back(m.point(v));
    const auto n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    EXPECT_GT(n.z(), 0) << "a triangle is flipped or degenerate";
    sum += n.z() / 2;
    ++labels[fm[f]];
  }
  EXPECT_NEAR(sum, area, 1e-12);
  EXPECT_EQ(labels, (std::map<int, int>{{0, 4}, {10, 2}, {20, 2}, {30, 2}}));
  // Quad 6 (0,-4) 10 (-1,-4) 9 (2,-7) 7 (4,-4): diagonal 6-9 has length^2 13, 10-7 has 25.
  EXPECT_NE(dart_from_to(m, Vertex_index(6), Vertex_index(9)), Dart());
  EXPECT_EQ(dart_from_to(m, Vertex_index(10), Vertex_index(7)), Dart());
}

TEST(TriangulateFaces, KeepsTheTopologyOfAQuadKleinBottleAndMobiusStrip)
{
  for (int shape = 0; shape < 2; ++shape) {
    Mesh m;
    if (shape == 0)
      CGAL_ext::make_klein_bottle(m, 8, 6);
    else
      CGAL_ext::make_mobius_strip(m, 10, 3);
    const std::size_t quads = m.number_of_faces();
    const long long chi = CGAL_ext::euler_characteristic(m);
    const std::size_t borders = CGAL_ext::number_of_border_cycles(m);
    EXPECT_EQ(CGAL_ext::triangulate_faces(m), quads);
    EXPECT_EQ(m.number_of_faces(), 2 * quads);
    EXPECT_TRUE(m.is_valid());
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), chi);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), borders);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
  }
}

// A disk: the quad a b c d, whose shorter diagonal a-c (length 1, against
// b-d's 2) is already an edge, of the triangle c e a; triangles b a e and
// c b e close the fan around e. The quad must take b-d.
TEST(TriangulateFaces, TakesTheOtherDiagonalWhereTheShorterIsAlreadyAnEdge)
{
  const std::vector<Point> points{Point(0, 0, 0), Point(0.5, -1, 0), Point(1, 0, 0), Point(0.5, 1, 0),
                                  Point(0.5, -0.3, 1)};
  const std::vector<std::vector<std::size_t>> faces{{0, 1, 2, 3}, {1, 0, 4}, {2, 1, 4}, {2, 4, 0}};
  Mesh m = mesh_of(points, faces);
  ASSERT_EQ(CGAL_ext::euler_characteristic(m), 1);
  EXPECT_EQ(CGAL_ext::triangulate_faces(m), 1u);
  EXPECT_TRUE(m.is_valid());
  EXPECT_EQ(m.number_of_faces(), 5u);
  EXPECT_EQ(m.number_of_edges(), 9u); // 8 + the diagonal, no edge doubled
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 1);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  EXPECT_NE(dart_from_to(m, Vertex_index(1), Vertex_index(3)), Dart());
}

// Two quads on the same four corners (a closed pillow, χ = 2): both have
// the same shorter diagonal, which only the first may take.
TEST(TriangulateFaces, TwoFacesDoNotTakeTheSameDiagonal)
{
  const std::vector<Point> points{Point(0, 0, 0), Point(2, -1, 0), Point(4, 0, 0), Point(2, 1, 0.5)};
  Mesh m = mesh_of(points, {{0, 1, 2, 3}, {3, 2, 1, 0}});
  ASSERT_EQ(CGAL_ext::euler_characteristic(m), 2);
  EXPECT_EQ(CGAL_ext::triangulate_faces(m), 2u);
  EXPECT_TRUE(m.is_valid());
  EXPECT_EQ(m.number_of_faces(), 4u);
  EXPECT_EQ(m.number_of_edges(), 6u); // a tetrahedron's: each pair of corners once
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 2);
  EXPECT_TRUE(CGAL_ext::is_closed(m));
  EXPECT_NE(dart_from_to(m, Vertex_index(1), Vertex_index(3)), Dart());
  EXPECT_NE(dart_from_to(m, Vertex_index(0), Vertex_index(2)), Dart());
}

// The hemi-cube: a cube with opposite corners identified, a projective plane
// of three quads on four vertices (χ = 1). Its six edges join every pair of
// vertices, so both diagonals of every quad are already edges: no face has a
// fan, and nothing may change.
TEST(TriangulateFaces, AFaceWithNoFanThrowsAndLeavesTheMeshUntouched)
{
  const std::vector<Point> points{Point(1, 1, 1), Point(1, 1, -1), Point(1, -1, 1), Point(-1, 1, 1)};
  const std::vector<std::vector<std::size_t>> quads{{0, 2, 3, 1}, {0, 1, 2, 3}, {0, 3, 1, 2}};
  Mesh m = mesh_of(points, quads);
  ASSERT_EQ(m.number_of_edges(), 6u);
  ASSERT_EQ(CGAL_ext::euler_characteristic(m), 1);
  ASSERT_FALSE(CGAL_ext::is_orientable(m));
  const std::string before = test::snapshot(m);
  try {
    CGAL_ext::triangulate_faces(m);
    FAIL() << "no exception";
  } catch (const CGAL_ext::Euler_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("triangulate_faces: face 0 (vertices ", 0), 0u) << what;
    EXPECT_NE(what.find("has no fan of triangles whose diagonals are not already edges; the mesh is unchanged"),
              std::string::npos) << what;
  }
  EXPECT_EQ(m.number_of_faces(), 3u);
  EXPECT_EQ(m.number_of_edges(), 6u);
  EXPECT_EQ(test::snapshot(m), before);
  // Decimation triangulates first, and so refuses the mesh alike.
  EXPECT_THROW(CGAL_ext::decimate(m, CGAL_ext::parameters::number_of_faces(1)), CGAL_ext::Euler_error);
  EXPECT_EQ(test::snapshot(m), before);
  EXPECT_TRUE(m.is_valid());
}

} // namespace triangulate_faces_tests
