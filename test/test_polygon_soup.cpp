// Polygon-soup import: counts and topology against the figures stated in the
// test meshes' headers, and each kind of bad input.
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace {

using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;

// The smallest Möbius strip: five triangles around a pentagon, each
// consecutive pair sharing an edge; the last pair shares one the same way round.
const std::vector<Point> pentagon_points = {{1.4, 0, 0}, {0.2, 0.6, -0.2}, {-0.9, 0.7, 0.4}, {-0.9, -0.7, -0.4},
                                            {0.2, -0.6, 0.2}};
const std::vector<std::vector<int>> mobius_min_polygons = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}, {3, 4, 0}, {4, 0, 1}};

TEST(PolygonSoup, SmallestMobiusStrip)
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(pentagon_points, mobius_min_polygons, m);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), 5u);
  EXPECT_EQ(m.number_of_edges(), 10u);
  EXPECT_EQ(m.number_of_faces(), 5u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  EXPECT_FALSE(CGAL_ext::is_orientable(m));
  // Consecutive triangles (a,b,c), (b,c,d) share (b,c) in the same direction:
  // every interior edge is a Möbius edge as given.
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 5u);
  EXPECT_EQ(CGAL_ext::orient(m), 1u);
  EXPECT_TRUE(m.is_valid(true));
}

TEST(PolygonSoup, CubeIsClosedOrientable)
{
  const std::vector<Point> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<std::array<std::size_t, 4>> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                         {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(pts, quads, m);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 2);
  EXPECT_TRUE(CGAL_ext::is_closed(m));
  EXPECT_TRUE(CGAL_ext::is_orientable(m));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
}

} // namespace
