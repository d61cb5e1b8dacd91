// The Möbius-aware halfedge mesh: dart identities, the four vertex walks of
// the source design, border loops, add_face and its refusals, properties,
// copies, face reversal and the classic halfedge records with an edge flip.
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace mobius_mesh_tests {

namespace {

using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using CGAL_ext::Dart;
using CGAL_ext::Face_index;
using CGAL_ext::Vertex_index;

// A plain v/f reader, independent of the library's I/O.
void read_obj(const std::string& file, std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons)
{
  const bool opened = test::read_obj_lines(
    file, [&](double x, double y, double z) { points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& polygon) { polygons.push_back(polygon); },
    [](const std::string&, const std::string&, std::istream&) {});
  ASSERT_TRUE(opened) << file;
}

Mesh load(const std::string& relative)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  read_obj(test::data(relative), points, polygons);
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m);
  return m;
}

const std::vector<std::string> all_manifold_files = {
  "nonorientable/boys_surface_quads.obj",    "nonorientable/klein_fig8_24x12_quads.obj",
  "nonorientable/mobius_20x4_quads.obj",     "nonorientable/mobius_20x4_tris.obj",
  "nonorientable/mobius_min_5tris.obj",      "nonorientable/rp2_hemi_icosahedron.obj",
  "nonorientable/torus_24x12_quads.obj",     "opensubdiv/catmark_cube.obj",
  "opensubdiv/catmark_edgecorner.obj",       "opensubdiv/catmark_nonquads.obj",
  "opensubdiv/catmark_pole64.obj",           "opensubdiv/loop_triangle_edgeonly.obj"};

// Every dart of every mesh obeys the orientable halfedge identities.
TEST(MobiusMesh, DartIdentitiesHoldOnEveryMesh)
{
  for (const std::string& file : all_manifold_files) {
    SCOPED_TRACE(file);
    const Mesh m = load(file);
    ASSERT_TRUE(m.is_valid(true));
    for (auto h : m.halfedges()) {
      for (bool flipped : {false, true}) {
        const Dart d(h, flipped);
        EXPECT_EQ(m.opposite(m.opposite(d)), d);
        EXPECT_EQ(m.next(m.prev(d)), d);
        EXPECT_EQ(m.prev(m.next(d)), d);
        EXPECT_EQ(m.target(m.opposite(d)), m.source(d));
        EXPECT_EQ(m.source(m.next(d)), m.target(d));
        EXPECT_EQ(m.target(d.flipped()), m.source(d));
        EXPECT_EQ(m.next(d.flipped()), m.prev(d).flipped());
        EXPECT_EQ(m.edge(m.opposite(d)), m.edge(d));
        EXPECT_NE(m.opposite(d).halfedge(), d.halfedge());
      }
    }
  }
}

// The 1-ring of every vertex, walked with opposite(next(d)), is one cycle in
// which consecutive neighbours share a face with the vertex (except across
// the border gap), and every incident face is met once. This is the
// definition of a manifold vertex star, checked from the face lists.
TEST(MobiusMesh, VertexWalksMatchTheFaceLists)
{
  for (const std::string& file : all_manifold_files) {
    SCOPED_TRACE(file);
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    read_obj(test::data(file), points, polygons);
    Mesh m;
    CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m);
    // Triples (v, a, b): a and b follow each other around v in some polygon.
    std::set<std::tuple<std::size_t, std::size_t, std::size_t>> corners;
    std::vector<std::size_t> faces_at(points.size(), 0);
    for (const auto& p : polygons) {
      for (std::size_t i = 0; i < p.size(); ++i) {
        const std::size_t prev = p[(i + p.size() - 1) % p.size()], v = p[i], next = p[(i + 1) % p.size()];
        corners.insert({v, (std::min)(prev, next), (std::max)(prev, next)});
        ++faces_at[v];
      }
    }
    for (Vertex_index v : m.vertices()) {
      std::vector<Vertex_index> ring;
      std::vector<Face_index> faces;
      std::vector<bool> border_dart;
      for (Dart d : CGAL_ext::halfedges_around_target(v, m)) {
        EXPECT_EQ(m.target(d), v);
        ring.push_back(m.source(d));
        border_dart.push_back(m.is_border(d));
        if (!m.is_border(d))
          faces.push_back(m.face(d));
      }
      EXPECT_EQ(faces.size(), faces_at[v.idx()]);
      EXPECT_EQ(std::set<Face_index>(faces.begin(), faces.end()).size(), faces.size());
      EXPECT_EQ(ring.size(), m.degree(v));
      EXPECT_EQ(std::count(border_dart.begin(), border_dart.end(), true), m.is_border(v) ? 1 : 0);
      // The face of an incoming dart holds the vertex between that dart's
      // source and the next neighbour of the walk.
      for (std::size_t i = 0; i < ring.size(); ++i) {
        if (border_dart[i])
          continue;
        const std::size_t a = ring[i].idx(), b = ring[(i + 1) % ring.size()].idx();
        EXPECT_TRUE(corners.count({v.idx(), (std::min)(a, b), (std::max)(a, b)})) << "at " << v;
      }
      // The reverse walk visits the same darts in the opposite order.
      std::vector<Vertex_index> reverse_ring;
      for (Dart d : CGAL_ext::halfedges_around_target_reverse(m.halfedge(v), m))
        reverse_ring.push_back(m.source(d));
      ASSERT_EQ(reverse_ring.size(), ring.size());
      for (std::size_t i = 1; i < ring.size(); ++i)
        EXPECT_EQ(reverse_ring[i], ring[ring.size() - i]);
    }
  }
}

// The four vertex walks of the source design (its figures 3 to 6): a vertex
// with four quads around it, interior or on the border, with and without
// Möbius connections. The walk must give the neighbours in their geometric
// cyclic order (by angle in the plane), whichever way the faces run.
class Four_walks : public ::testing::Test
{
protected:
  // Centre 0 and ring vertices 1..8 at angles k*45°: quads (0, 2k+1, 2k+2, 2k+3).
  static std::vector<Point> ring_points()
  {
    std::vector<Point> pts = {Point(0, 0, 0)};
    for (int k = 0; k < 8; ++k)
      pts.emplace_back(std::cos(k * M_PI / 4), std::sin(k * M_PI / 4), 0);
    return pts;
  }
  // Quads around the centre; `reversed` faces are given in the other orientation;
  // `count` quads (4: interior vertex, fewer: on the border).
  static Mesh fan(const std::vector<bool>& reversed, int count)
  {
    std::vector<std::vector<std::size_t>> quads;
    for (int k = 0; k < count; ++k) {
      std::vector<std::size_t> q = {0, std::size_t(2 * k + 1), std::size_t(2 * k + 2),
                                    std::size_t((2 * k + 2) % 8 + 1)};
      if (reversed[std::size_t(k)])
        std::reverse(q.begin(), q.end());
      quads.push_back(q);
    }
    Mesh m;
    CGAL_ext::polygon_soup_to_mobius_mesh(ring_points(), quads, m, CGAL_ext::parameters::keep_orientation(true)); // Möbius connections as drawn
    return m;
  }
  // Edge neighbours of the centre in walk order, as angles' indices 1, 3, 5, 7.
  static std::vector<std::size_t> walk(const Mesh& m)
  {
    std::vector<std::size_t> order;
    for (Vertex_index w : CGAL_ext::vertices_around_target(Vertex_index(0u), m))
      order.push_back(w.idx());
    return order;
  }
  // True if `order` is a rotation of `cycle` or of its reverse.
  static bool same_cycle(std::vector<std::size_t> order, const std::vector<std::size_t>& cycle)
  {
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t r = 0; r < order.size(); ++r) {
        std::rotate(order.begin(), order.begin() + 1, order.end());
        if (order == cycle)
          return true;
      }
      std::reverse(order.begin(), order.end());
    }
    return false;
  }
};

TEST_F(Four_walks, InteriorWithoutMobius) // figure 3
{
  const Mesh m = fan({false, false, false, false}, 4);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
  EXPECT_FALSE(m.is_border(Vertex_index(0u)));
  EXPECT_TRUE(same_cycle(walk(m), {1, 3, 5, 7}));
}

TEST_F(Four_walks, InteriorWithMobius) // figure 4: e1 and e3 are Möbius connections
{
  const Mesh m = fan({false, true, true, false}, 4);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 2u);
  EXPECT_TRUE(m.is_on_mobius_connection(Vertex_index(0u)));
  EXPECT_FALSE(m.is_border(Vertex_index(0u)));
  EXPECT_TRUE(same_cycle(walk(m), {1, 3, 5, 7}));
  // The walk passes flipped darts: it switches between successor and
  // predecessor at each Möbius connection, as the source design does by hand.
  std::size_t flipped = 0;
  for (Dart d : CGAL_ext::halfedges_around_target(Vertex_index(0u), m))
    flipped += (d.is_flipped() != m.halfedge(Vertex_index(0u)).is_flipped()) ? 1 : 0;
  EXPECT_EQ(flipped, 2u);
}

TEST_F(Four_walks, BorderWithoutMobius) // figure 5
{
  const Mesh m = fan({false, false, false, false}, 2);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_TRUE(m.is_border(Vertex_index(0u)));
  EXPECT_TRUE(m.is_border(m.halfedge(Vertex_index(0u))));
  EXPECT_TRUE(same_cycle(walk(m), {1, 3, 5}));
}

TEST_F(Four_walks, BorderWithMobius) // figure 6: a Möbius connection and a Möbius boundary link
{
  const Mesh m = fan({false, true, false, false}, 2);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 1u);
  EXPECT_TRUE(m.is_border(Vertex_index(0u)));
  EXPECT_TRUE(same_cycle(walk(m), {1, 3, 5}));
  // The border loop through the centre links two border halfedges that both
  // end (or both start) there: the link between them is flipped.
  const Dart in = m.halfedge(Vertex_index(0u));
  const Dart out = m.next(in);
  EXPECT_EQ(m.source(out), Vertex_index(0u));
  const auto h_in = in.halfedge(), h_out = out.halfedge();
  const bool same_way = (m.target(Dart(h_in, false)) == Vertex_index(0u)) ==
                        (m.target(Dart(h_out, false)) == Vertex_index(0u));
  EXPECT_TRUE(same_way);
}

// The smallest Möbius strip, built face by face with add_face.
TEST(MobiusMesh, AddFaceBuildsAMobiusStrip)
{
  Mesh m;
  std::vector<Vertex_index> v;
  for (int i = 0; i < 5; ++i)
    v.push_back(m.add_vertex(Point(std::cos(i * 0.4 * M_PI), std::sin(i * 0.4 * M_PI), 0)));
  for (int i = 0; i < 5; ++i) {
    std::string why;
    const Face_index f = m.add_face({v[std::size_t(i)], v[std::size_t((i + 1) % 5)], v[std::size_t((i + 2) % 5)]}, &why);
    ASSERT_TRUE(f.is_valid()) << why;
  }
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_edges(), 10u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  EXPECT_FALSE(CGAL_ext::is_orientable(m));
  // Each triangle shares its edge (i+1, i+2) with the next, which runs the same way.
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 5u);
  // Triangle (i, i+1, i+2) shares its sides (i, i+1) and (i+1, i+2) with its
  // neighbours; its third side (i, i+2) is on the border.
  std::set<std::pair<std::size_t, std::size_t>> border;
  for (Dart d : CGAL_ext::halfedges_around_face(CGAL_ext::border_cycles(m).front(), m)) {
    const std::size_t a = m.source(d).idx(), b = m.target(d).idx();
    border.insert({(std::min)(a, b), (std::max)(a, b)});
  }
  EXPECT_EQ(border, (std::set<std::pair<std::size_t, std::size_t>>{{0, 2}, {1, 3}, {2, 4}, {0, 3}, {1, 4}}));
}

TEST(MobiusMesh, AddFaceRefusalsLeaveTheMeshUnchanged)
{
  Mesh m;
  std::vector<Vertex_index> v;
  for (int i = 0; i < 8; ++i)
    v.push_back(m.add_vertex(Point(i, i * i, 0)));
  ASSERT_TRUE(m.add_face({v[0], v[1], v[2]}).is_valid());
  ASSERT_TRUE(m.add_face({v[0], v[2], v[3]}).is_valid());
  const auto nh = m.number_of_halfedges();
  auto expect_refused = [&](std::initializer_list<Vertex_index> face, const std::string& reason_part) {
    std::string why;
    EXPECT_FALSE(m.add_face(face, &why).is_valid());
    EXPECT_NE(why.find(reason_part), std::string::npos) << why;
    EXPECT_EQ(m.number_of_faces(), 2u);
    EXPECT_EQ(m.number_of_halfedges(), nh);
    EXPECT_TRUE(m.is_valid(true));
  };
  expect_refused({v[0], v[1]}, "three vertices");
  expect_refused({v[0], v[1], v[0]}, "repeated");
  expect_refused({v[0], v[1], Vertex_index(42u)}, "not in the mesh");
  expect_refused({v[0], v[2], v[5]}, "already has two faces");
  // A second fan at v0 (a bowtie) is allowed while building, and reported.
  ASSERT_TRUE(m.add_face({v[0], v[6], v[7]}).is_valid());
  EXPECT_NE(m.validity_report().find("non-manifold vertex"), std::string::npos) << m.validity_report();
  ASSERT_TRUE(m.add_face({v[0], v[3], v[4]}).is_valid());
  // Closing the first fan while the second remains would leave v0 non-manifold for good.
  std::string why;
  EXPECT_FALSE(m.add_face({v[0], v[4], v[1]}, &why).is_valid());
  EXPECT_NE(why.find("close one fan"), std::string::npos) << why;
  EXPECT_EQ(m.number_of_faces(), 4u);
  // Bridging the two fans, then closing the single fan, makes v0 interior.
  ASSERT_TRUE(m.add_face({v[0], v[4], v[6]}).is_valid());
  ASSERT_TRUE(m.is_valid(true));
  ASSERT_TRUE(m.add_face({v[0], v[7], v[1]}).is_valid());
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_FALSE(m.is_border(v[0]));
  EXPECT_EQ(m.degree(v[0]), 6u);
  EXPECT_FALSE(m.add_face({v[0], v[5], v[3]}, &why).is_valid());
  EXPECT_NE(why.find("interior"), std::string::npos) << why;
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 8 - 12 + 6); // a disk and the isolated v5
}

// Faces in any order: the smallest Möbius strip cannot be built keeping one
// fan per vertex at every step, whatever the order; every order must work.
TEST(MobiusMesh, AddFaceInAnyOrder)
{
  std::vector<int> order = {0, 1, 2, 3, 4};
  do {
    Mesh m;
    std::vector<Vertex_index> v;
    for (int i = 0; i < 5; ++i)
      v.push_back(m.add_vertex(Point(std::cos(i * 0.4 * M_PI), std::sin(i * 0.4 * M_PI), 0)));
    for (int i : order) {
      std::string why;
      ASSERT_TRUE(m.add_face({v[std::size_t(i)], v[std::size_t((i + 1) % 5)], v[std::size_t((i + 2) % 5)]}, &why)
                    .is_valid())
        << why;
    }
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
  } while (std::next_permutation(order.begin(), order.end()));
}

// The 7-vertex mesh of the classic records: six triangles around v4.
// Border loop origins from the records' table: v3, v1, v2, v5, v7, v6.
TEST(MobiusMesh, ClassicRecords)
{
  Mesh m;
  std::vector<Vertex_index> v(8);
  const double xy[7][2] = {{1, 4}, {3, 4}, {0, 2}, {2, 2}, {4, 2}, {1, 0}, {3, 0}};
  for (int i = 1; i <= 7; ++i)
    v[std::size_t(i)] = m.add_vertex(Point(xy[i - 1][0], xy[i - 1][1], 0));
  const int faces[6][3] = {{1, 3, 4}, {1, 4, 2}, {2, 4, 5}, {3, 6, 4}, {4, 6, 7}, {4, 7, 5}};
  for (const auto& f : faces)
    ASSERT_TRUE(m.add_face({v[std::size_t(f[0])], v[std::size_t(f[1])], v[std::size_t(f[2])]}).is_valid());
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_halfedges(), 24u); // e0..e23 in the table
  EXPECT_EQ(m.degree(v[4]), 6u);
  EXPECT_FALSE(m.is_border(v[4]));
  const auto cycles = CGAL_ext::border_cycles(m);
  ASSERT_EQ(cycles.size(), 1u);
  std::vector<std::size_t> origins;
  for (Dart d : CGAL_ext::halfedges_around_face(cycles.front(), m))
    origins.push_back(m.source(d).idx()); // our v[i] has index i-1
  std::vector<std::size_t> expected = {2, 0, 1, 4, 6, 5};
  auto it = std::find(origins.begin(), origins.end(), expected.front());
  ASSERT_NE(it, origins.end());
  std::rotate(origins.begin(), it, origins.end());
  EXPECT_EQ(origins, expected);
}

// The records' edge flip: two triangles (v1, v3, v4), (v1, v4, v2) of the unit
// square; flipping the diagonal v1-v4 gives (v1, v3, v2) and (v3, v4, v2).
TEST(MobiusMesh, ClassicEdgeFlip)
{
  for (bool mobius : {false, true}) {
    SCOPED_TRACE(mobius ? "across a Möbius edge" : "orientable");
    Mesh m;
    const Vertex_index v1 = m.add_vertex(Point(0, 1, 0)), v2 = m.add_vertex(Point(1, 1, 0)),
                       v3 = m.add_vertex(Point(0, 0, 0)), v4 = m.add_vertex(Point(1, 0, 0));
    m.add_face({v1, v3, v4});
    if (mobius)
      m.add_face({v2, v4, v1});
    else
      m.add_face({v1, v4, v2});
    ASSERT_EQ(CGAL_ext::number_of_mobius_edges(m), mobius ? 1u : 0u);
    Dart diagonal;
    for (Dart d : CGAL_ext::halfedges_around_face(Face_index(0u), m))
      if (!m.is_border(m.edge(d)))
        diagonal = d;
    ASSERT_TRUE(CGAL_ext::Euler::can_flip_edge(diagonal, m));
    CGAL_ext::Euler::flip_edge(diagonal, m);
    ASSERT_TRUE(m.is_valid(true));
    std::set<std::set<std::size_t>> faces;
    for (Face_index f : m.faces()) {
      std::set<std::size_t> vs;
      for (Vertex_index w : CGAL_ext::vertices_around_face(f, m))
        vs.insert(w.idx());
      faces.insert(vs);
    }
    EXPECT_EQ(faces, (std::set<std::set<std::size_t>>{{v1.idx(), v3.idx(), v2.idx()}, {v3.idx(), v4.idx(), v2.idx()}}));
    EXPECT_EQ(m.degree(v1), 2u);
    EXPECT_EQ(m.degree(v4), 2u);
    EXPECT_EQ(m.degree(v2), 3u);
    EXPECT_EQ(m.degree(v3), 3u);
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
    EXPECT_FALSE(CGAL_ext::Euler::can_flip_edge(m.halfedge(m.edge(m.halfedge(v1))), m));
  }
}

TEST(MobiusMesh, PropertyMaps)
{
  Mesh m = load("nonorientable/mobius_min_5tris.obj");
  auto [weight, created] = m.add_property_map<CGAL_ext::Edge_index, double>("e:weight", 1.5);
  EXPECT_TRUE(created);
  EXPECT_EQ(weight[CGAL_ext::Edge_index(3u)], 1.5);
  put(weight, CGAL_ext::Edge_index(3u), 2.5);
  EXPECT_EQ(get(weight, CGAL_ext::Edge_index(3u)), 2.5);
  auto again = m.add_property_map<CGAL_ext::Edge_index, double>("e:weight", 7.0);
  EXPECT_FALSE(again.second);
  EXPECT_EQ(again.first[CGAL_ext::Edge_index(3u)], 2.5);
  // Same name, another type: refused.
  EXPECT_FALSE(bool(m.add_property_map<CGAL_ext::Edge_index, int>("e:weight").first));
  const bool found_as_int = m.property_map<CGAL_ext::Edge_index, int>("e:weight").has_value();
  const bool found_as_double = m.property_map<CGAL_ext::Edge_index, double>("e:weight").has_value();
  EXPECT_FALSE(found_as_int);
  EXPECT_TRUE(found_as_double);
  // Maps follow element insertion.
  auto label = m.add_property_map<Vertex_index, std::string>("v:label", "none").first;
  const Vertex_index w = m.add_vertex(Point(9, 9, 9));
  EXPECT_EQ(label[w], "none");
  EXPECT_TRUE(m.remove_property_map(label));
  const bool label_found = m.property_map<Vertex_index, std::string>("v:label").has_value();
  EXPECT_FALSE(label_found);
  auto points = m.points();
  EXPECT_FALSE(m.remove_property_map(points));
}

// Bool maps store a byte per element, so they hand out `bool&` like any other map.
TEST(MobiusMesh, BoolPropertyMaps)
{
  using Flag_map = Mesh::Property_map<Vertex_index, bool>;
  static_assert(std::is_same_v<decltype(std::declval<Flag_map>()[Vertex_index()]), bool&>,
                "a bool map hands out a real reference");
  Mesh m = load("nonorientable/mobius_20x4_quads.obj"); // 100 vertices
  auto [flag, created] = m.add_property_map<Vertex_index, bool>("v:flag", false);
  ASSERT_TRUE(created);
  // Every third vertex through operator[], one through put(): 34 + 1 set.
  for (Vertex_index v : m.vertices())
    if (v.idx() % 3 == 0) {
      bool& cell = flag[v];
      cell = true;
    }
  put(flag, Vertex_index(1u), true);
  auto count = [](const Mesh& mesh, const Flag_map& map) {
    std::size_t n = 0;
    for (Vertex_index v : mesh.vertices())
      n += get(map, v) ? 1 : 0;
    return n;
  };
  EXPECT_EQ(count(m, flag), 34u + 1u);
  EXPECT_TRUE(get(flag, Vertex_index(99u)));
  EXPECT_FALSE(get(flag, Vertex_index(2u)));

  // A new vertex gets the default; a map with default true fills with true.
  const Vertex_index w = m.add_vertex(Point(5, 5, 5));
  EXPECT_FALSE(flag[w]);
  auto on = m.add_property_map<Vertex_index, bool>("v:on", true).first;
  EXPECT_EQ(count(m, on), 101u);

  // Copies own their bytes.
  Mesh copy = m;
  auto copied = *copy.property_map<Vertex_index, bool>("v:flag");
  copied[Vertex_index(0u)] = false;
  EXPECT_TRUE(flag[Vertex_index(0u)]);
  EXPECT_EQ(count(copy, copied), 34u);

  // Join carries the values, shifted; the joined vertices of a mesh without
  // the map get the default.
  Mesh joined = load("nonorientable/mobius_min_5tris.obj");
  const std::size_t n0 = joined.number_of_vertices();
  joined.join(m);
  auto joined_flag = *joined.property_map<Vertex_index, bool>("v:flag");
  EXPECT_EQ(count(joined, joined_flag), 35u);
  for (Vertex_index v : m.vertices())
    EXPECT_EQ(joined_flag[Vertex_index(v.idx() + n0)], flag[v]);

  EXPECT_TRUE(m.remove_property_map(flag));
  const bool still_there = m.property_map<Vertex_index, bool>("v:flag").has_value();
  EXPECT_FALSE(still_there);
}

TEST(MobiusMesh, CopiesShareNothing)
{
  Mesh original = load("nonorientable/mobius_20x4_quads.obj");
  auto tag = original.add_property_map<Face_index, int>("f:tag", 7).first;
  Mesh copy = original;
  ASSERT_TRUE(copy.is_valid(true));
  copy.point(Vertex_index(0u)) = Point(100, 100, 100);
  (*copy.property_map<Face_index, int>("f:tag"))[Face_index(0u)] = 3;
  copy.reverse_face_orientation(Face_index(0u));
  EXPECT_NE(original.point(Vertex_index(0u)), Point(100, 100, 100));
  EXPECT_EQ(tag[Face_index(0u)], 7);
  EXPECT_TRUE(original.is_valid(true));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(original) + 0, CGAL_ext::number_of_mobius_edges(load("nonorientable/mobius_20x4_quads.obj")));
  Mesh moved = std::move(copy);
  EXPECT_TRUE(moved.is_valid(true));
  EXPECT_EQ(moved.number_of_faces(), 80u);
  copy.clear();
  EXPECT_TRUE(copy.is_valid(true));
  EXPECT_EQ(copy.number_of_vertices(), 0u);
}

TEST(MobiusMesh, JoinIsADisjointUnion)
{
  Mesh a = load("nonorientable/mobius_20x4_quads.obj");
  const Mesh b = load("nonorientable/torus_24x12_quads.obj");
  const auto offsets = a.join(b);
  EXPECT_EQ(offsets.vertices, 100u);
  ASSERT_TRUE(a.is_valid(true));
  EXPECT_EQ(a.number_of_vertices(), 100u + 288u);
  EXPECT_EQ(CGAL_ext::connected_components(a).count, 2u);
  EXPECT_EQ(CGAL_ext::orientable_components(a), (std::vector<bool>{false, true}));
  EXPECT_EQ(a.point(Vertex_index(100u + 5u)), b.point(Vertex_index(5u)));
}

// Joining grows every array of the first mesh: each value of both meshes
// comes through, in the points, in a map of strings both have, and in maps
// only one of them has (the other's part then takes the map's default).
TEST(MobiusMesh, JoinKeepsEveryValue)
{
  Mesh a = load("nonorientable/mobius_20x4_quads.obj");
  Mesh b = load("nonorientable/torus_24x12_quads.obj");
  auto label_a = a.add_property_map<Vertex_index, std::string>("v:label", "none").first;
  auto label_b = b.add_property_map<Vertex_index, std::string>("v:label", "none").first;
  auto flag = a.add_property_map<Vertex_index, bool>("v:flag", false).first;
  auto weight = b.add_property_map<Vertex_index, double>("v:weight", -1.0).first;
  const auto name = [](const char* mesh, Vertex_index v) { return mesh + std::to_string(v.idx()); };
  for (Vertex_index v : a.vertices()) {
    label_a[v] = name("a", v);
    flag[v] = v.idx() % 2 == 0;
  }
  for (Vertex_index v : b.vertices()) {
    label_b[v] = name("b", v);
    weight[v] = 0.5 * v.idx();
  }
  const Mesh before = a;
  const auto offsets = a.join(b);
  ASSERT_TRUE(a.is_valid(true));
  const auto joined_weight = a.property_map<Vertex_index, double>("v:weight");
  ASSERT_TRUE(joined_weight.has_value());
  for (Vertex_index v : before.vertices()) {
    EXPECT_EQ(a.point(v), before.point(v));
    EXPECT_EQ(label_a[v], name("a", v));
    EXPECT_EQ(flag[v], v.idx() % 2 == 0);
    EXPECT_EQ((*joined_weight)[v], -1.0);
  }
  for (Vertex_index v : b.vertices()) {
    const Vertex_index w(offsets.vertices + v.idx());
    EXPECT_EQ(a.point(w), b.point(v));
    EXPECT_EQ(label_a[w], name("b", v));
    EXPECT_FALSE(flag[w]);
    EXPECT_EQ((*joined_weight)[w], 0.5 * v.idx());
  }
}

// Reversing faces moves Möbius edges but never changes the surface.
TEST(MobiusMesh, ReversingFacesKeepsTheSurface)
{
  std::mt19937 rng(42);
  for (const std::string& file : all_manifold_files) {
    SCOPED_TRACE(file);
    Mesh m = load(file);
    const bool orientable = CGAL_ext::is_orientable(m);
    const auto loops = CGAL_ext::number_of_border_cycles(m);
    for (int k = 0; k < 20; ++k) {
      const Face_index f(std::size_t(rng() % m.number_of_faces()));
      std::vector<Vertex_index> before;
      for (Vertex_index w : CGAL_ext::vertices_around_face(f, m))
        before.push_back(w);
      m.reverse_face_orientation(f);
      ASSERT_TRUE(m.is_valid(true));
      std::vector<Vertex_index> after;
      for (Vertex_index w : CGAL_ext::vertices_around_face(f, m))
        after.push_back(w);
      std::reverse(after.begin(), after.end());
      // Same cycle, other direction.
      auto it = std::find(after.begin(), after.end(), before.front());
      ASSERT_NE(it, after.end());
      std::rotate(after.begin(), it, after.end());
      EXPECT_EQ(after, before);
    }
    EXPECT_EQ(CGAL_ext::is_orientable(m), orientable);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), loops);
    const std::size_t left = CGAL_ext::orient(m);
    EXPECT_TRUE(m.is_valid(true));
    if (orientable)
      EXPECT_EQ(left, 0u);
    else
      EXPECT_GE(left, 1u);
  }
}

} // namespace

} // namespace mobius_mesh_tests
