// Isotropic remeshing. References: what stays true of a surface under any
// remeshing (Euler characteristic, border loops, orientability, components,
// is_valid()), the band [4/5 L, 4/3 L] that Botsch and Kobbelt's loop aims
// at, CGAL's PMP::isotropic_remeshing on the same input (the share of edges
// in the band, and the Hausdorff distance to the input by
// PMP::approximate_symmetric_Hausdorff_distance), and the input's own points
// for what is protected.

#include "test_util.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/isotropic_remeshing.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace {

using CGAL_ext::Edge_index;
using CGAL_ext::Vertex_index;
using Point = test::Epick::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using SM = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace np = CGAL_ext::parameters;

// What a remeshing must not change.
struct Shape
{
  long long euler_characteristic;
  std::size_t border_loops;
  bool orientable;
  std::size_t components;
  bool operator==(const Shape& o) const
  {
    return std::tie(euler_characteristic, border_loops, orientable, components) ==
           std::tie(o.euler_characteristic, o.border_loops, o.orientable, o.components);
  }
};

template <class P>
Shape shape_of(const CGAL_ext::Mobius_mesh<P>& m)
{
  return {CGAL_ext::euler_characteristic(m), CGAL_ext::number_of_border_cycles(m), CGAL_ext::is_orientable(m),
          CGAL_ext::connected_components(m).count};
}

template <class P>
CGAL_ext::Mobius_mesh<P> read_mesh(const std::string& name)
{
  CGAL_ext::Mobius_mesh<P> m;
  CGAL_ext::IO::read_polygon_mesh(test::data("nonorientable/" + name), m);
  return m;
}

template <class P>
double mean_edge_length(const CGAL_ext::Mobius_mesh<P>& m)
{
  double sum = 0;
  for (Edge_index e : m.edges())
    sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)))));
  return sum / double(m.number_of_edges());
}

bool in_band(double squared_length, double L)
{
  return squared_length >= 0.64 * L * L && squared_length <= 16.0 / 9.0 * L * L;
}

template <class P>
double share_in_band(const CGAL_ext::Mobius_mesh<P>& m, double L)
{
  std::size_t inside = 0;
  for (Edge_index e : m.edges())
    inside += in_band(CGAL::to_double(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)))), L);
  return double(inside) / double(m.number_of_edges());
}

double share_in_band(const SM& m, double L)
{
  std::size_t inside = 0;
  for (SM::Edge_index e : m.edges())
    inside += in_band(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))), L);
  return double(inside) / double(m.number_of_edges());
}

template <class P>
bool all_triangles(const CGAL_ext::Mobius_mesh<P>& m)
{
  for (CGAL_ext::Face_index f : m.faces())
    if (m.degree(f) != 3)
      return false;
  return true;
}

// A one-sided surface with one border loop stays so, and its edges come into
// the band as well as CGAL's come on the same strip cut open along its seam
// (an orientable surface that CGAL can remesh, the seam a border it may
// move): on a strip this narrow, how many border edges fit the band depends
// on how L divides the border, for CGAL as for us, so the reference is
// CGAL's share at the same L, over lengths from 1/4 to 5/6 of the input's
// mean edge (0.297).
TEST(IsotropicRemeshing, MobiusStripStaysOneNonOrientableStrip)
{
  const Mesh input = read_mesh<Point>("mobius_20x4_tris.obj");
  const Shape before = shape_of(input);
  ASSERT_EQ(before, (Shape{0, 1, false, 1}));
  for (const double L : {0.08, 0.12, 0.18, 0.25}) {
    Mesh m = input;
    CGAL_ext::isotropic_remeshing(m, L, np::number_of_iterations(5));
    EXPECT_TRUE(m.is_valid(true));
    EXPECT_FALSE(m.has_garbage());
    EXPECT_TRUE(all_triangles(m));
    EXPECT_EQ(shape_of(m), before) << L;
    EXPECT_GT(m.number_of_faces(), 160u);

    SM cut;
    CGAL_ext::to_surface_mesh(input, cut);
    PMP::isotropic_remeshing(faces(cut), L, cut, CGAL::parameters::number_of_iterations(5));
    cut.collect_garbage();
    const double our_share = share_in_band(m, L), their_share = share_in_band(cut, L);
    EXPECT_GE(our_share, their_share - 0.02) << "L = " << L << ", CGAL's share on the cut strip: " << their_share;
    EXPECT_GE(our_share, 0.8) << L;
  }
}

// A closed one-sided surface of quads: triangulated first, then remeshed.
TEST(IsotropicRemeshing, KleinBottleStaysClosedAndOneSided)
{
  Mesh m = read_mesh<Point>("klein_fig8_24x12_quads.obj");
  const Shape before = shape_of(m);
  ASSERT_EQ(before, (Shape{0, 0, false, 1}));
  const double L = 0.8 * mean_edge_length(m);
  CGAL_ext::isotropic_remeshing(m, L, np::number_of_iterations(5));
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_TRUE(all_triangles(m));
  EXPECT_EQ(shape_of(m), before);
  EXPECT_GE(share_in_band(m, L), 0.9);
}

// On an orientable surface CGAL's PMP::isotropic_remeshing is the
// reference: from the same triangles, as many edges in the band, and a
// Hausdorff distance to the input within twice CGAL's.
TEST(IsotropicRemeshing, TorusMatchesCgal)
{
  const Mesh quads = read_mesh<Point>("torus_24x12_quads.obj");
  SM input;
  CGAL_ext::to_surface_mesh(quads, input);
  PMP::triangulate_faces(input);
  Mesh ours;
  CGAL_ext::from_surface_mesh(input, ours);
  const Shape before = shape_of(ours);
  ASSERT_EQ(before, (Shape{0, 0, true, 1}));
  const double L = 0.6 * mean_edge_length(ours);

  SM theirs = input;
  PMP::isotropic_remeshing(faces(theirs), L, theirs, CGAL::parameters::number_of_iterations(5));
  theirs.collect_garbage();
  CGAL_ext::isotropic_remeshing(ours, L, np::number_of_iterations(5));

  EXPECT_TRUE(ours.is_valid(true));
  EXPECT_EQ(shape_of(ours), before);
  const double our_share = share_in_band(ours, L), their_share = share_in_band(theirs, L);
  EXPECT_GE(our_share, their_share) << "CGAL's share in the band: " << their_share;
  EXPECT_GE(our_share, 0.9);

  SM ours_sm;
  CGAL_ext::to_surface_mesh(ours, ours_sm);
  const double our_error = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(ours_sm, input);
  const double their_error = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(theirs, input);
  EXPECT_LE(our_error, 2 * their_error) << "ours " << our_error << ", CGAL's " << their_error;
}

std::set<std::array<double, 3>> border_points(const Mesh& m)
{
  std::set<std::array<double, 3>> points;
  for (Vertex_index v : m.vertices())
    if (m.is_border(v))
      points.insert({m.point(v).x(), m.point(v).y(), m.point(v).z()});
  return points;
}

// Protected, the border neither moves nor changes: the same points, the same number of edges.
TEST(IsotropicRemeshing, ProtectedBorderKeepsItsExactPoints)
{
  Mesh m = read_mesh<Point>("mobius_20x4_tris.obj");
  const auto points = border_points(m);
  ASSERT_EQ(points.size(), 40u); // 20 around, twice round the one loop
  const double L = 0.5 * mean_edge_length(m);
  CGAL_ext::isotropic_remeshing(m, L, np::number_of_iterations(3).protect_borders(true));
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(shape_of(m), (Shape{0, 1, false, 1}));
  EXPECT_EQ(border_points(m), points);
  std::size_t border_edges = 0;
  for (Edge_index e : m.edges())
    border_edges += m.is_border(e);
  EXPECT_EQ(border_edges, 40u);
}

// A roof (two slopes meeting at a ridge along y = 0), its ridge marked sharp:
// protected, the ridge keeps every point and edge, with its sharpness.
TEST(IsotropicRemeshing, ProtectedSharpEdgesStay)
{
  const int n = 8;
  std::vector<Point> points;
  for (int i = 0; i <= n; ++i)
    for (int j = -n / 2; j <= n / 2; ++j)
      points.emplace_back(i, j, 0.5 * std::abs(j));
  const auto index = [&](int i, int j) { return std::size_t(i * (n + 1) + j + n / 2); };
  std::vector<std::array<std::size_t, 3>> triangles;
  for (int i = 0; i < n; ++i)
    for (int j = -n / 2; j < n / 2; ++j) {
      triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, triangles, m);
  auto sharpness = CGAL_ext::edge_sharpness_map(m);
  const auto on_ridge = [&](Vertex_index v) { return m.point(v).y() == 0; };
  for (Edge_index e : m.edges())
    if (on_ridge(m.vertex(e, 0)) && on_ridge(m.vertex(e, 1)))
      sharpness[e] = CGAL_ext::infinitely_sharp;

  CGAL_ext::isotropic_remeshing(m, 0.7, np::number_of_iterations(3).protect_sharp_edges(true).protect_borders(true));
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(shape_of(m), (Shape{1, 1, true, 1}));
  sharpness = CGAL_ext::edge_sharpness_map(m);
  std::set<double> ridge_x;
  std::size_t sharp_edges = 0;
  for (Edge_index e : m.edges()) {
    if (sharpness[e] <= 0)
      continue;
    ++sharp_edges;
    for (unsigned k : {0u, 1u}) {
      EXPECT_EQ(m.point(m.vertex(e, k)).y(), 0);
      EXPECT_EQ(m.point(m.vertex(e, k)).z(), 0);
      ridge_x.insert(m.point(m.vertex(e, k)).x());
    }
    EXPECT_EQ(std::abs(m.point(m.vertex(e, 0)).x() - m.point(m.vertex(e, 1)).x()), 1);
  }
  EXPECT_EQ(sharp_edges, std::size_t(n));
  EXPECT_EQ(ridge_x.size(), std::size_t(n + 1));
  std::size_t on_ridge_vertices = 0;
  for (Vertex_index v : m.vertices())
    on_ridge_vertices += on_ridge(v);
  EXPECT_EQ(on_ridge_vertices, std::size_t(n + 1));
}

// An exact kernel: midpoints exact, moved points rounded; the topology stays.
TEST(IsotropicRemeshing, ExactKernelKeepsTheStrip)
{
  using Exact_point = test::Epeck::Point_3;
  CGAL_ext::Mobius_mesh<Exact_point> m;
  CGAL_ext::IO::read_polygon_mesh(test::data("nonorientable/mobius_20x4_tris.obj"), m);
  const double L = 0.7 * mean_edge_length(m);
  CGAL_ext::isotropic_remeshing(m, L);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_TRUE(all_triangles(m));
  EXPECT_EQ(shape_of(m), (Shape{0, 1, false, 1}));
}

// Bad parameters and garbage are refused before the mesh is touched.
TEST(IsotropicRemeshing, BadParametersLeaveTheMeshUntouched)
{
  Mesh m = read_mesh<Point>("mobius_20x4_quads.obj");
  const Mesh copy = m;
  const auto unchanged = [&] {
    if (m.number_of_faces() != copy.number_of_faces() || m.number_of_vertices() != copy.number_of_vertices())
      return false;
    for (Vertex_index v : m.vertices())
      if (m.point(v) != copy.point(v))
        return false;
    return true;
  };
  for (double L : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(CGAL_ext::isotropic_remeshing(m, L), CGAL_ext::Parameter_error) << L;
    EXPECT_TRUE(unchanged());
  }
  EXPECT_THROW(CGAL_ext::isotropic_remeshing(m, 0.1, np::number_of_iterations(-1)), CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::isotropic_remeshing(m, 0.1, np::number_of_iterations(1001)), CGAL_ext::Parameter_error);
  EXPECT_TRUE(unchanged());
  m.remove_face(*m.faces().begin());
  try {
    CGAL_ext::isotropic_remeshing(m, 0.1);
    ADD_FAILURE() << "a mesh with removed elements was remeshed";
  } catch (const CGAL_ext::Parameter_error& e) {
    EXPECT_NE(std::string(e.what()).find("removed elements"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m.number_of_faces(), copy.number_of_faces() - 1);
}

} // namespace
