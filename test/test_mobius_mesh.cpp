// The Möbius-aware halfedge mesh: dart identities, circulators, add_face.
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh.h>

#include <gtest/gtest.h>

namespace {

using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;

TEST(MobiusMesh, EmptyMeshIsValid)
{
  Mesh m;
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), 0u);
}

} // namespace
