// CGAL's graph concepts on Mobius_mesh: CGAL's own algorithms run directly
// on the mesh, checked against the same algorithms on the Surface_mesh that
// the library's conversion makes, and against closed forms.
#include "test_util.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_concepts.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace graph_traits_tests {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using K = test::Epick;
using Point = K::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using SM = CGAL::Surface_mesh<Point>;
using GT = boost::graph_traits<Mesh>;

// The faces as cycles of points, each started at its least point (so that two
// meshes with the same faces in another order or numbering compare equal,
// orientation included), sorted.
using Face_points = std::vector<Point>;
Face_points started_at_least(Face_points f)
{
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}
// Through the library's own walks, not the graph traits.
std::vector<Face_points> faces_of(const Mesh& m)
{
  std::vector<Face_points> out;
  for (CGAL_ext::Face_index f : m.faces()) {
    Face_points ps;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m))
      ps.push_back(m.point(v));
    out.push_back(started_at_least(ps));
  }
  std::sort(out.begin(), out.end());
  return out;
}
std::vector<Face_points> faces_of(const SM& m)
{
  std::vector<Face_points> out;
  for (SM::Face_index f : m.faces()) {
    Face_points ps;
    for (SM::Vertex_index v : m.vertices_around_face(m.halfedge(f)))
      ps.push_back(m.point(v));
    out.push_back(started_at_least(ps));
  }
  std::sort(out.begin(), out.end());
  return out;
}

Mesh read_mesh(const std::string& name)
{
  Mesh m;
  CGAL_ext::IO::read_polygon_mesh(test::data("nonorientable/" + name), m);
  return m;
}
// An orientable mesh, oriented: no Möbius edges, the exact model.
Mesh oriented_torus()
{
  Mesh m = read_mesh("torus_24x12_quads.obj");
  CGAL_ext::orient(m);
  return m;
}
SM converted(const Mesh& m)
{
  SM sm;
  CGAL_ext::to_surface_mesh(m, sm);
  return sm;
}
template <class G>
void triangulate(G& g)
{
  PMP::triangulate_faces(g);
}

// The non-orientable test shapes (Euler characteristic, border loops).
struct Shape
{
  const char* file;
  long long chi;
  std::size_t border_loops;
};
const Shape non_orientable_shapes[] = {
  {"mobius_20x4_tris.obj", 0, 1}, {"klein_fig8_24x12_quads.obj", 0, 0}, {"boys_surface_quads.obj", 1, 0}};

double relative_difference(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// ---------------------------------------------------------------- the model

TEST(GraphTraits, DescriptorsAreTheDartTypes)
{
  static_assert(std::is_same_v<GT::vertex_descriptor, CGAL_ext::Vertex_index>);
  static_assert(std::is_same_v<GT::halfedge_descriptor, CGAL_ext::Dart>);
  static_assert(std::is_same_v<GT::edge_descriptor, CGAL_ext::Dart_edge>);
  static_assert(std::is_same_v<GT::face_descriptor, CGAL_ext::Face_index>);
  static_assert(std::is_same_v<boost::graph_traits<const Mesh>::halfedge_descriptor, CGAL_ext::Dart>);
}

TEST(GraphTraits, RangesYieldUnflippedDartsAndIdentitiesHoldOnAMobiusStrip)
{
  Mesh m = read_mesh("mobius_20x4_quads.obj");
  CGAL_ext::orient(m);
  ASSERT_EQ(CGAL_ext::number_of_mobius_edges(m), 4u); // one seam across the 4 quads of the band
  // 21 x 5 grid points glued with a twist: 100 vertices, 180 edges, 80 faces.
  EXPECT_EQ(std::distance(vertices(m).begin(), vertices(m).end()), 100);
  EXPECT_EQ(std::distance(edges(m).begin(), edges(m).end()), 180);
  EXPECT_EQ(std::distance(halfedges(m).begin(), halfedges(m).end()), 360);
  EXPECT_EQ(std::distance(faces(m).begin(), faces(m).end()), 80);
  std::size_t flipped_opposites = 0;
  for (GT::halfedge_descriptor h : halfedges(m)) {
    EXPECT_FALSE(h.is_flipped());
    EXPECT_EQ(opposite(opposite(h, m), m), h);
    EXPECT_EQ(next(prev(h, m), m), h);
    EXPECT_EQ(target(opposite(h, m), m), source(h, m));
    EXPECT_EQ(halfedge(edge(h, m), m), h);
    EXPECT_EQ(edge(opposite(h, m), m), edge(h, m));
    flipped_opposites += opposite(h, m).is_flipped() ? 1 : 0;
  }
  // Only across the 4 Möbius edges is the opposite of a range dart a flipped
  // dart (both halfedges of each: 8).
  EXPECT_EQ(flipped_opposites, 8u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
}

TEST(GraphTraits, EveryDartReachedOnAnOrientedMeshIsUnflipped)
{
  // A closed and a bordered orientable mesh (a band with two half twists).
  std::vector<Mesh> meshes(2);
  meshes[0] = oriented_torus();
  CGAL_ext::make_mobius_strip(meshes[1], 12, 3, 2);
  for (Mesh& mesh : meshes) {
    Mesh* m = &mesh;
    // Reversing every face keeps the mesh oriented but leaves flipped vertex
    // darts in it; the graph's halfedge(v) names the same fan with an
    // unflipped dart.
    for (CGAL_ext::Face_index f : m->faces())
      m->reverse_face_orientation(f);
    ASSERT_FALSE(CGAL_ext::has_mobius_edges(*m));
    std::size_t stored_flipped = 0;
    for (GT::vertex_descriptor v : vertices(*m))
      stored_flipped += m->halfedge(v).is_flipped() ? 1 : 0;
    EXPECT_GT(stored_flipped, 0u);
    for (GT::vertex_descriptor v : vertices(*m)) {
      const GT::halfedge_descriptor h = halfedge(v, *m);
      EXPECT_FALSE(h.is_flipped());
      EXPECT_EQ(target(h, *m), v);
      EXPECT_EQ(CGAL::is_border(h, *m), m->is_border(v));
      for (GT::halfedge_descriptor g : CGAL::halfedges_around_target(h, *m))
        EXPECT_FALSE(g.is_flipped());
    }
    for (GT::halfedge_descriptor h : halfedges(*m))
      EXPECT_FALSE(opposite(h, *m).is_flipped() || next(h, *m).is_flipped() || prev(h, *m).is_flipped());
  }
}

TEST(GraphTraits, BorderVerticesGetBorderHalfedges)
{
  Mesh m = read_mesh("mobius_20x4_tris.obj");
  CGAL_ext::orient(m);
  std::size_t border_vertices = 0;
  for (GT::vertex_descriptor v : vertices(m))
    if (m.is_border(v)) {
      ++border_vertices;
      EXPECT_TRUE(CGAL::is_border(halfedge(v, m), m));
    }
  EXPECT_EQ(border_vertices, 40u); // the one border loop runs twice round the 20 columns
}

TEST(GraphTraits, LibraryAndCgalCirculatorsCoexist)
{
  Mesh m = oriented_torus();
  const GT::halfedge_descriptor h = halfedge(*faces(m).begin(), m);
  const GT::vertex_descriptor v = target(h, m);
  // Unqualified, CGAL's templates win (CGAL's algorithms rely on their result
  // types); qualified, the library's own circulators are called.
  static_assert(std::is_same_v<decltype(halfedges_around_face(h, m)), decltype(CGAL::halfedges_around_face(h, m))>);
  static_assert(std::is_same_v<decltype(vertices_around_target(v, m)), decltype(CGAL::vertices_around_target(v, m))>);
  static_assert(!std::is_same_v<decltype(CGAL_ext::halfedges_around_face(h, m)),
                                decltype(CGAL::halfedges_around_face(h, m))>);
  // Both walk the same darts.
  std::vector<GT::halfedge_descriptor> ours, cgals;
  for (GT::halfedge_descriptor g : CGAL_ext::halfedges_around_face(h, m))
    ours.push_back(g);
  for (GT::halfedge_descriptor g : halfedges_around_face(h, m))
    cgals.push_back(g);
  EXPECT_EQ(ours, cgals);
  EXPECT_EQ(ours.size(), 4u);
  ours.clear();
  cgals.clear();
  for (GT::halfedge_descriptor g : CGAL_ext::halfedges_around_target(v, m))
    ours.push_back(g);
  for (GT::halfedge_descriptor g : halfedges_around_target(v, m))
    cgals.push_back(g);
  EXPECT_EQ(ours, cgals);
  EXPECT_EQ(ours.size(), 4u); // a regular quad grid
  EXPECT_EQ(out_degree(v, m), 4u);
  // The library's is_closed() (exact overload) and CGAL's agree.
  EXPECT_TRUE(is_closed(m));
  EXPECT_TRUE(CGAL::is_closed(m));
}

TEST(GraphTraits, HalfedgeIndexMapIsOneToOneOverHalfedgesAndSharedByTheirDarts)
{
  // As for Surface_mesh: num_halfedges() is the halfedge slots and bounds the
  // index map, which is one-to-one over halfedges(g); the flipped dart of a
  // halfedge (reached across a Möbius edge) has its halfedge's index.
  Mesh m = read_mesh("mobius_20x4_quads.obj");
  auto him = get(boost::halfedge_index, m);
  std::set<std::uint32_t> seen;
  for (GT::halfedge_descriptor h : halfedges(m)) {
    EXPECT_LT(get(him, h), num_halfedges(m));
    EXPECT_TRUE(seen.insert(get(him, h)).second);
    EXPECT_EQ(get(him, h.flipped()), get(him, h));
  }
  EXPECT_EQ(seen.size(), std::size_t(num_halfedges(m)));
  EXPECT_EQ(num_halfedges(m), m.number_of_halfedges());
  EXPECT_EQ(get(boost::edge_index, m, edge(halfedges(m).begin()->flipped(), m)), 0u);
}

TEST(GraphTraits, DynamicMapsKeepTheTwoDartsApartAndGrowWithTheMesh)
{
  Mesh m = oriented_torus();
  const auto names_before = m.properties<CGAL_ext::Halfedge_index>();
  {
    auto marks = get(CGAL::dynamic_halfedge_property_t<int>(), m);
    const GT::halfedge_descriptor h = *halfedges(m).begin();
    put(marks, h, 1);
    put(marks, h.flipped(), 2);
    EXPECT_EQ(get(marks, h), 1);
    EXPECT_EQ(get(marks, h.flipped()), 2);
    auto edge_marks = get(CGAL::dynamic_edge_property_t<bool>(), m);
    put(edge_marks, edge(h, m), true);
    EXPECT_TRUE(get(edge_marks, edge(opposite(h, m), m)));
    const GT::edge_descriptor e = add_edge(m);
    put(marks, halfedge(e, m), 7);
    EXPECT_EQ(get(marks, halfedge(e, m)), 7);
    EXPECT_FALSE(get(edge_marks, e));
  }
  // The last copy of a dynamic map removes its array.
  EXPECT_EQ(m.properties<CGAL_ext::Halfedge_index>(), names_before);
  const Mesh& cm = m;
  auto const_marks = get(CGAL::dynamic_vertex_property_t<bool>(), cm);
  put(const_marks, *vertices(cm).begin(), true);
  EXPECT_TRUE(get(const_marks, *vertices(cm).begin()));
}

// The graph concepts that CGAL's algorithms require, checked by CGAL's and
// Boost's own concept classes.
BOOST_CONCEPT_ASSERT((CGAL::concepts::HalfedgeListGraph<Mesh>));
BOOST_CONCEPT_ASSERT((CGAL::concepts::FaceListGraph<Mesh>));
BOOST_CONCEPT_ASSERT((CGAL::concepts::MutableFaceGraph<Mesh>));
BOOST_CONCEPT_ASSERT((boost::concepts::VertexListGraph<Mesh>));
BOOST_CONCEPT_ASSERT((boost::concepts::EdgeListGraph<Mesh>));
BOOST_CONCEPT_ASSERT((boost::concepts::BidirectionalGraph<Mesh>));
BOOST_CONCEPT_ASSERT((boost::concepts::AdjacencyGraph<Mesh>));

// The invariants that CGAL's own graph-traits test suite (BGL/test) checks on
// each of its models, on every test shape: one-sided, bordered, closed.
void expect_cgal_graph_invariants(const Mesh& g)
{
  std::unordered_set<std::size_t> ids;
  for (GT::vertex_descriptor v : vertices(g))
    EXPECT_TRUE(ids.insert(get(boost::vertex_index, g, v)).second);
  EXPECT_EQ(ids.size(), num_vertices(g));
  ids.clear();
  for (GT::edge_descriptor e : edges(g)) {
    EXPECT_TRUE(ids.insert(get(boost::edge_index, g, e)).second);
    // Every edge is found from both ends.
    const auto [found, is_edge] = edge(source(e, g), target(e, g), g);
    const auto [found_back, is_edge_back] = edge(target(e, g), source(e, g), g);
    EXPECT_TRUE(is_edge && is_edge_back);
    EXPECT_TRUE(found == e && found_back == e);
  }
  EXPECT_EQ(ids.size(), num_edges(g));
  for (GT::vertex_descriptor v : vertices(g)) {
    // Out- and in-edges meet the same neighbours, once each, in the same order.
    std::vector<GT::vertex_descriptor> out, in;
    for (GT::edge_descriptor e : out_edges(v, g)) {
      EXPECT_EQ(source(e, g), v);
      out.push_back(target(e, g));
    }
    for (GT::edge_descriptor e : in_edges(v, g)) {
      EXPECT_EQ(target(e, g), v);
      in.push_back(source(e, g));
    }
    EXPECT_EQ(out, in);
    EXPECT_EQ(std::set<GT::vertex_descriptor>(out.begin(), out.end()).size(), out.size());
    EXPECT_EQ(std::count(out.begin(), out.end(), v), 0);
    EXPECT_EQ(out.size(), degree(v, g));
    EXPECT_EQ(out_degree(v, g), degree(v, g));
    EXPECT_EQ(in_degree(v, g), degree(v, g));
    // Around a target, clockwise: each step is opposite(next(h)).
    const auto around = CGAL::halfedges_around_target(halfedge(v, g), g);
    for (auto h = around.begin(); h != around.end(); ++h) {
      EXPECT_EQ(target(*h, g), v);
      const auto step = std::next(h);
      if (step != around.end()) {
        EXPECT_EQ(*step, opposite(next(*h, g), g));
      }
    }
  }
  std::size_t face_count = 0;
  for (GT::face_descriptor f : faces(g)) {
    ++face_count;
    EXPECT_EQ(face(halfedge(f, g), g), f);
    const auto around = CGAL::halfedges_around_face(halfedge(f, g), g);
    EXPECT_GE(std::distance(around.begin(), around.end()), 3);
    for (GT::halfedge_descriptor h : around)
      EXPECT_EQ(face(h, g), f);
  }
  EXPECT_EQ(face_count, num_faces(g));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(g));
}

TEST(GraphTraits, InvariantsOfCgalsGraphTestSuiteOnEveryShape)
{
  for (const Shape& s : non_orientable_shapes) {
    SCOPED_TRACE(s.file);
    expect_cgal_graph_invariants(read_mesh(s.file));
  }
  expect_cgal_graph_invariants(read_mesh("mobius_20x4_quads.obj"));
  expect_cgal_graph_invariants(oriented_torus());
}

TEST(GraphTraits, AnIsolatedVertexHasNoHalfedgeAndNoNeighbours)
{
  Mesh g = read_mesh("mobius_20x4_quads.obj");
  const GT::vertex_descriptor v = add_vertex(g);
  set_halfedge(v, GT::null_halfedge(), g);
  EXPECT_EQ(halfedge(v, g), GT::null_halfedge());
  EXPECT_EQ(degree(v, g), 0u);
  EXPECT_TRUE(out_edges(v, g).empty());
  EXPECT_TRUE(in_edges(v, g).empty());
  EXPECT_TRUE(adjacent_vertices(v, g).empty());
  EXPECT_FALSE(edge(v, *vertices(g).begin(), g).second);
  EXPECT_FALSE(edge(*vertices(g).begin(), v, g).second);
  EXPECT_EQ(num_vertices(g), 101u);
  // The mesh's own check allows isolated vertices; CGAL's refuses them, on
  // Surface_mesh as here.
  EXPECT_TRUE(g.is_valid());
  SM sm = converted(read_mesh("mobius_20x4_quads.obj"));
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(sm));
  add_vertex(sm);
  EXPECT_FALSE(CGAL::is_valid_polygon_mesh(sm));
  EXPECT_FALSE(CGAL::is_valid_polygon_mesh(g));
}

// ---------------------------------------------------------------- CGAL's entry points build the mesh

// The torus's soup, with every other polygon reversed if `mixed`: still an
// orientable surface, stored as a careless exporter writes it.
struct Soup
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};
Soup torus_soup(bool mixed)
{
  const Mesh m = oriented_torus();
  Soup s;
  for (CGAL_ext::Vertex_index v : m.vertices())
    s.points.push_back(m.point(v));
  std::size_t i = 0;
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<std::size_t> polygon;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m))
      polygon.push_back(v.idx());
    if (mixed && i++ % 2 == 1)
      std::reverse(polygon.begin(), polygon.end());
    s.polygons.push_back(polygon);
  }
  return s;
}

TEST(GraphTraits, CgalReadPolygonMeshAsOnSurfaceMesh)
{
  const std::string file = test::data("nonorientable/torus_24x12_quads.obj");
  Mesh m;
  SM sm;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(file, m));
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(file, sm));
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_EQ(faces_of(m), faces_of(sm));
  EXPECT_EQ(num_halfedges(m), num_halfedges(sm));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
  // A non-orientable file: CGAL's builder refuses it on both meshes alike
  // (it adds faces with Euler::add_face, which needs one orientation).
  Mesh strip;
  SM strip_sm;
  EXPECT_EQ(CGAL::IO::read_polygon_mesh(test::data("nonorientable/mobius_20x4_quads.obj"), strip),
            CGAL::IO::read_polygon_mesh(test::data("nonorientable/mobius_20x4_quads.obj"), strip_sm));
}

TEST(GraphTraits, CgalEulerAddFaceFromAnEmptyMesh)
{
  Mesh m;
  SM sm;
  const Point p[] = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(2, 0, 0)};
  std::vector<GT::vertex_descriptor> v;
  std::vector<SM::Vertex_index> w;
  for (const Point& q : p) {
    v.push_back(add_vertex(q, m));
    w.push_back(sm.add_vertex(q));
  }
  // A face on isolated vertices, one beside it, one on its other side.
  const std::vector<std::vector<int>> faces = {{0, 1, 2}, {1, 4, 2}, {0, 2, 3}};
  for (const auto& f : faces) {
    std::vector<GT::vertex_descriptor> fv;
    std::vector<SM::Vertex_index> fw;
    for (int i : f) {
      fv.push_back(v[std::size_t(i)]);
      fw.push_back(w[std::size_t(i)]);
    }
    EXPECT_NE(CGAL::Euler::add_face(fv, m), GT::null_face());
    EXPECT_NE(CGAL::Euler::add_face(fw, sm), SM::null_face());
    EXPECT_TRUE(m.is_valid(true));
    // CGAL's check refuses the vertices that no face uses yet, on both.
    EXPECT_EQ(CGAL::is_valid_polygon_mesh(m), CGAL::is_valid_polygon_mesh(sm));
    EXPECT_EQ(faces_of(m), faces_of(sm));
  }
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m)); // every vertex on a face now
  // A face that would make an edge non-manifold is refused on both.
  std::vector<GT::vertex_descriptor> bad = {v[0], v[1], v[4]};
  std::vector<SM::Vertex_index> bad_sm = {w[0], w[1], w[4]};
  EXPECT_EQ(CGAL::Euler::add_face(bad, m), GT::null_face());
  EXPECT_EQ(CGAL::Euler::add_face(bad_sm, sm), SM::null_face());
  EXPECT_EQ(num_faces(m), 3u);
}

TEST(GraphTraits, CgalPolygonSoupToPolygonMeshAsOnSurfaceMesh)
{
  Soup s = torus_soup(true);
  PMP::orient_polygon_soup(s.points, s.polygons);
  Mesh m;
  SM sm;
  PMP::polygon_soup_to_polygon_mesh(s.points, s.polygons, m);
  PMP::polygon_soup_to_polygon_mesh(s.points, s.polygons, sm);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(faces_of(m), faces_of(sm));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
  triangulate(m);
  triangulate(sm);
  EXPECT_LT(relative_difference(PMP::volume(m), PMP::volume(sm)), 1e-12);
}

TEST(GraphTraits, SettersChangeWhatTheyNameOnly)
{
  Mesh m = oriented_torus();
  const GT::face_descriptor f = *faces(m).begin();
  const GT::halfedge_descriptor h = halfedge(f, m);
  const GT::vertex_descriptor t = target(h, m);
  const GT::halfedge_descriptor stored = halfedge(t, m);
  set_face(h, GT::null_face(), m);
  EXPECT_EQ(face(h, m), GT::null_face());
  EXPECT_EQ(halfedge(t, m), stored);
  set_face(h, f, m);
  EXPECT_TRUE(m.is_valid(true));
  // A fresh edge's halfedges are unlinked: null, as CGAL expects.
  const GT::edge_descriptor e = add_edge(m);
  EXPECT_EQ(next(halfedge(e, m), m), GT::null_halfedge());
  EXPECT_EQ(target(halfedge(e, m), m), GT::null_vertex());
}

TEST(GraphTraits, CgalRemoveFaceOpensAClosedFan)
{
  Mesh m = oriented_torus();
  SM sm = converted(m);
  const GT::halfedge_descriptor h = halfedge(*faces(m).begin(), m);
  std::vector<GT::vertex_descriptor> corners;
  for (GT::vertex_descriptor v : vertices_around_face(h, m))
    corners.push_back(v);
  CGAL::Euler::remove_face(h, m);
  CGAL::Euler::remove_face(halfedge(*sm.faces().begin(), sm), sm);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  for (GT::vertex_descriptor v : corners) {
    EXPECT_TRUE(m.is_border(v));
    EXPECT_TRUE(bool(CGAL::is_border(v, m)));
  }
  EXPECT_EQ(faces_of(m), faces_of(sm));
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  // Refilled by CGAL's Euler::add_face, the fan closes again.
  EXPECT_NE(CGAL::Euler::add_face(corners, m), GT::null_face());
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(faces_of(m), faces_of(oriented_torus()));
}

TEST(GraphTraits, ReadersOrientAnOrientableSoup)
{
  const Soup mixed = torus_soup(true);
  Mesh oriented, kept;
  CGAL_ext::polygon_soup_to_mobius_mesh(mixed.points, mixed.polygons, oriented);
  CGAL_ext::polygon_soup_to_mobius_mesh(mixed.points, mixed.polygons, kept,
                                        CGAL_ext::parameters::keep_orientation(true));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(oriented), 0u);
  EXPECT_GT(CGAL_ext::number_of_mobius_edges(kept), 0u); // every other face reversed
  // The lowest polygon keeps its orientation; so all agree with the torus as built.
  EXPECT_EQ(faces_of(oriented), faces_of(oriented_torus()));
  // Non-orientable components keep the file's orientations.
  Mesh strip = read_mesh("mobius_20x4_quads.obj");
  Mesh strip_kept;
  CGAL_ext::IO::read_polygon_mesh(test::data("nonorientable/mobius_20x4_quads.obj"), strip_kept,
                                  CGAL_ext::parameters::keep_orientation(true));
  EXPECT_EQ(faces_of(strip), faces_of(strip_kept));
  // The oriented torus converts through CGAL's copy and measures as CGAL does.
  SM copy;
  CGAL::copy_face_graph(oriented, copy);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(copy));
  triangulate(oriented);
  triangulate(copy);
  SM reference = converted(oriented_torus());
  triangulate(reference);
  EXPECT_GT(PMP::volume(oriented), 0.0);
  EXPECT_LT(relative_difference(PMP::volume(oriented), PMP::volume(reference)), 1e-12);
  EXPECT_LT(relative_difference(PMP::volume(copy), PMP::volume(reference)), 1e-12);
}

TEST(GraphTraits, CopyFaceGraphRefusesMobiusEdgesBeforeCopying)
{
  for (const char* file : {"mobius_20x4_quads.obj", "klein_fig8_24x12_quads.obj"}) {
    SCOPED_TRACE(file);
    const Mesh m = read_mesh(file);
    SM sm = converted(oriented_torus());
    const std::size_t faces_before = sm.number_of_faces();
    EXPECT_THROW(CGAL::copy_face_graph(m, sm), CGAL_ext::Parameter_error);
    EXPECT_EQ(sm.number_of_faces(), faces_before);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(sm));
  }
  // The torus as stored with mixed orientations, read keeping them: refused too.
  const Soup mixed = torus_soup(true);
  Mesh kept;
  CGAL_ext::polygon_soup_to_mobius_mesh(mixed.points, mixed.polygons, kept,
                                        CGAL_ext::parameters::keep_orientation(true));
  SM sm;
  EXPECT_THROW(CGAL::copy_face_graph(kept, sm), CGAL_ext::Parameter_error);
  EXPECT_EQ(sm.number_of_faces(), 0u);
}

// ---------------------------------------------------------------- orientable: same as on Surface_mesh

TEST(GraphTraits, CopyFaceGraphBothWays)
{
  const Mesh m = oriented_torus();
  const SM reference = converted(m); // the library's own conversion
  SM copy;
  CGAL::copy_face_graph(m, copy);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(copy));
  EXPECT_EQ(faces_of(copy), faces_of(reference));

  Mesh back;
  CGAL::copy_face_graph(reference, back);
  EXPECT_TRUE(back.is_valid(true));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(back), 0u);
  EXPECT_EQ(faces_of(back), faces_of(reference));
  EXPECT_EQ(CGAL_ext::euler_characteristic(back), 0);
}

TEST(GraphTraits, TriangulationAreaVolumeNormalsAsOnSurfaceMesh)
{
  Mesh m = oriented_torus();
  SM sm = converted(m);
  triangulate(m);
  triangulate(sm);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_faces(), 2u * 24 * 12);
  EXPECT_EQ(faces_of(m), faces_of(sm));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_TRUE(CGAL::is_closed(m));

  EXPECT_LT(relative_difference(PMP::area(m), PMP::area(sm)), 1e-12);
  const double volume = PMP::volume(m);
  EXPECT_LT(relative_difference(volume, PMP::volume(sm)), 1e-12);
  EXPECT_GT(volume, 0); // oriented outward, as the file's faces are

  // Per face normals, matched through the faces' points.
  std::map<Face_points, K::Vector_3> normals;
  for (SM::Face_index f : sm.faces()) {
    Face_points ps;
    for (SM::Vertex_index v : sm.vertices_around_face(sm.halfedge(f)))
      ps.push_back(sm.point(v));
    normals[started_at_least(ps)] = PMP::compute_face_normal(f, sm);
  }
  auto vnormals = get(CGAL::dynamic_vertex_property_t<K::Vector_3>(), m);
  PMP::compute_vertex_normals(m, vnormals);
  for (GT::face_descriptor f : faces(m)) {
    Face_points ps;
    for (GT::vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, m), m))
      ps.push_back(m.point(v));
    const K::Vector_3 n = PMP::compute_face_normal(f, m), r = normals.at(started_at_least(ps));
    EXPECT_LT(CGAL::squared_distance(CGAL::ORIGIN + n, CGAL::ORIGIN + r), 1e-24);
  }
  for (SM::Vertex_index v : sm.vertices()) {
    const K::Vector_3 r = PMP::compute_vertex_normal(v, sm);
    // The same vertex, found by its point.
    for (GT::vertex_descriptor w : vertices(m))
      if (m.point(w) == sm.point(v)) {
        EXPECT_LT(CGAL::squared_distance(CGAL::ORIGIN + get(vnormals, w), CGAL::ORIGIN + r), 1e-24);
      }
  }

  // The tube's centre circle has radius R = xmax - r, where 2r is the height.
  const CGAL::Bbox_3 box = PMP::bbox(m);
  const double R = box.xmax() - (box.zmax() - box.zmin()) / 2;
  const CGAL::Side_of_triangle_mesh<Mesh, K> inside(m);
  EXPECT_EQ(inside(Point(R, 0, 0)), CGAL::ON_BOUNDED_SIDE);
  EXPECT_EQ(inside(Point(0, 0, 0)), CGAL::ON_UNBOUNDED_SIDE); // the hole
  const CGAL::Side_of_triangle_mesh<SM, K> sm_inside(sm);
  for (const Point& q : {Point(0, 0, 0), Point(box.xmax() - 0.01, 0, 0), Point(1, 1, 0.1)})
    EXPECT_EQ(inside(q), sm_inside(q));
}

// Finds the dart from the vertex at `a` to the vertex at `b` in any graph.
template <class G>
typename boost::graph_traits<G>::halfedge_descriptor dart_between(const G& g, const Point& a, const Point& b)
{
  auto vpm = get(CGAL::vertex_point, g);
  for (auto h : halfedges(g))
    for (auto d : {h, opposite(h, g)})
      if (get(vpm, source(d, g)) == a && get(vpm, target(d, g)) == b)
        return d;
  return boost::graph_traits<G>::null_halfedge();
}

TEST(GraphTraits, CgalEulerOperationsAsOnSurfaceMesh)
{
  Mesh m = oriented_torus();
  SM sm = converted(m);
  triangulate(m);
  triangulate(sm);
  // Each operation on the edge at a given place of m's range, found in sm by
  // its end points; the places lie far apart on the 1728 darts.
  std::size_t place = 0;
  auto on_both = [&](auto op) {
    const GT::halfedge_descriptor h = *std::next(halfedges(m).begin(), std::ptrdiff_t(place));
    place += 200;
    const Point a = m.point(source(h, m)), b = m.point(target(h, m));
    op(m, dart_between(m, a, b), CGAL::midpoint(a, b));
    op(sm, dart_between(sm, a, b), CGAL::midpoint(a, b));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
    EXPECT_TRUE(m.is_valid(true));
    EXPECT_EQ(m.number_of_vertices(), sm.number_of_vertices());
    EXPECT_EQ(m.number_of_faces(), sm.number_of_faces());
    EXPECT_EQ(std::distance(faces(m).begin(), faces(m).end()), std::ptrdiff_t(sm.number_of_faces()));
    EXPECT_EQ(faces_of(m), faces_of(sm));
  };
  on_both([](auto& g, auto h, const Point&) { CGAL::Euler::collapse_edge(edge(h, g), g); });
  on_both([](auto& g, auto h, const Point&) { CGAL::Euler::flip_edge(h, g); });
  on_both([](auto& g, auto h, const Point& mid) {
    const auto v = target(CGAL::Euler::split_edge(h, g), g);
    put(get(CGAL::vertex_point, g), v, mid);
  });
  on_both([](auto& g, auto h, const Point& mid) {
    const auto v = target(CGAL::Euler::add_center_vertex(h, g), g);
    put(get(CGAL::vertex_point, g), v, mid);
  });
  on_both([](auto& g, auto h, const Point&) { CGAL::Euler::remove_center_vertex(h, g); });
  on_both([](auto& g, auto h, const Point&) { CGAL::Euler::remove_face(h, g); });
  EXPECT_TRUE(m.has_garbage());
  EXPECT_EQ(std::distance(faces(m).begin(), faces(m).end()), std::ptrdiff_t(m.number_of_faces()));
  m.collect_garbage();
  sm.collect_garbage();
  EXPECT_EQ(faces_of(m), faces_of(sm));
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
}

// CGAL's remeshing and simplification, run on the oriented mesh itself and on
// the converted Surface_mesh. They visit elements in slot order and CGAL's
// Euler operations fill removed slots of a Surface_mesh but append to a
// Mobius_mesh, so the two runs part ways after the first changes: the
// results are compared as surfaces (counts, topology, Hausdorff distance),
// and a stop by edge count stops both at the same count.
TEST(GraphTraits, CgalRemeshingAndSimplificationOnTheOrientedMesh)
{
  Mesh m = oriented_torus();
  triangulate(m);
  SM sm = converted(m);
  const SM input = sm;
  const double L = 0.3; // the torus's mean edge is about 0.4
  PMP::isotropic_remeshing(faces(m), L, m, CGAL::parameters::number_of_iterations(3));
  PMP::isotropic_remeshing(faces(sm), L, sm, CGAL::parameters::number_of_iterations(3));
  m.collect_garbage();
  sm.collect_garbage();
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_FALSE(CGAL_ext::has_mobius_edges(m));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_NEAR(double(m.number_of_faces()), double(sm.number_of_faces()), 0.02 * double(sm.number_of_faces()));
  const SM remeshed = converted(m);
  EXPECT_LE(PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(remeshed, sm), 0.1 * L);
  EXPECT_TRUE(PMP::is_outward_oriented(m));

  // Garland-Heckbert's rival, CGAL's default Lindstrom-Turk policies, down to 300 edges.
  namespace SMS = CGAL::Surface_mesh_simplification;
  const int removed = SMS::edge_collapse(m, SMS::Count_stop_predicate<Mesh>(300));
  const int removed_sm = SMS::edge_collapse(sm, SMS::Count_stop_predicate<SM>(300));
  m.collect_garbage();
  sm.collect_garbage();
  EXPECT_GT(removed, 0);
  EXPECT_EQ(m.number_of_edges(), sm.number_of_edges()) << removed << " " << removed_sm;
  EXPECT_EQ(m.number_of_faces(), sm.number_of_faces());
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_FALSE(CGAL_ext::has_mobius_edges(m));
  const SM simplified = converted(m);
  const double theirs = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(sm, input);
  EXPECT_LE(PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(simplified, input), 2 * theirs);
}

// ---------------------------------------------------------------- any mesh: orientation-free algorithms

TEST(GraphTraits, ValidityAndCountsOnNonOrientableShapes)
{
  for (const Shape& s : non_orientable_shapes) {
    SCOPED_TRACE(s.file);
    const Mesh m = read_mesh(s.file);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m, true));
    const long long chi = static_cast<long long>(std::distance(vertices(m).begin(), vertices(m).end())) -
                          std::distance(edges(m).begin(), edges(m).end()) +
                          std::distance(faces(m).begin(), faces(m).end());
    EXPECT_EQ(chi, s.chi);
    EXPECT_EQ(CGAL::is_closed(m), s.border_loops == 0);
    EXPECT_EQ(CGAL::is_quad_mesh(m), std::string(s.file).find("quads") != std::string::npos);
  }
}

TEST(GraphTraits, AreaBoxComponentsAndBordersOnNonOrientableShapes)
{
  for (const Shape& s : non_orientable_shapes) {
    SCOPED_TRACE(s.file);
    Mesh m = read_mesh(s.file);
    triangulate(m); // face by face: no global orientation needed
    EXPECT_TRUE(m.is_valid(true));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), s.chi);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    SM sm = converted(m); // cut along the Möbius edges: the same faces
    EXPECT_LT(relative_difference(PMP::area(m), PMP::area(sm)), 1e-12);
    const CGAL::Bbox_3 box = PMP::bbox(m), sm_box = PMP::bbox(sm);
    EXPECT_EQ(box, sm_box);

    auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
    EXPECT_EQ(PMP::connected_components(m, component), 1u);

    std::vector<GT::halfedge_descriptor> border;
    PMP::border_halfedges(m, std::back_inserter(border));
    EXPECT_EQ(border.size(), s.border_loops == 0 ? 0u : 40u);
    // A halfedge-marking walk sees the two darts of a border halfedge as two
    // halfedges: a border loop through a Möbius link is found once in each
    // direction (see doc/graph_traits.md).
    std::vector<GT::halfedge_descriptor> cycles;
    PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
    EXPECT_EQ(cycles.size(), 2 * s.border_loops);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), s.border_loops);
  }
}

TEST(GraphTraits, TwoCopiesAreTwoComponents)
{
  Mesh m = read_mesh("klein_fig8_24x12_quads.obj");
  m.join(read_mesh("boys_surface_quads.obj"));
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
  EXPECT_EQ(PMP::connected_components(m, component), 2u);
}

TEST(GraphTraits, SelfIntersectionOfImmersions)
{
  // Neither the Klein bottle nor the projective plane embeds in space: their
  // immersions must cross themselves. The Möbius band of the file is embedded.
  for (const Shape& s : non_orientable_shapes) {
    SCOPED_TRACE(s.file);
    Mesh m = read_mesh(s.file);
    triangulate(m);
    EXPECT_EQ(PMP::does_self_intersect(m), s.border_loops == 0);
  }
  Mesh torus = oriented_torus();
  triangulate(torus);
  EXPECT_FALSE(PMP::does_self_intersect(torus));
}

TEST(GraphTraits, AabbDistancesAndHausdorffOnNonOrientableShapes)
{
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  using SM_primitive = CGAL::AABB_face_graph_triangle_primitive<SM>;
  using SM_tree = CGAL::AABB_tree<CGAL::AABB_traits<K, SM_primitive>>;
  for (const Shape& s : non_orientable_shapes) {
    SCOPED_TRACE(s.file);
    Mesh m = read_mesh(s.file);
    triangulate(m);
    const SM sm = converted(m);
    Tree tree(faces(m).first, faces(m).second, m);
    SM_tree sm_tree(faces(sm).first, faces(sm).second, sm);
    // Vertices lie on the surface; points off it are as far as on the cut copy.
    for (GT::vertex_descriptor v : vertices(m))
      EXPECT_EQ(tree.squared_distance(m.point(v)), 0.0);
    for (const Point& q : {Point(3, 0, 0), Point(0.1, 0.2, 0.3), Point(-1, 2, 5)})
      EXPECT_LT(std::abs(tree.squared_distance(q) - sm_tree.squared_distance(q)), 1e-12);
    // The same surface through a round trip: Hausdorff distance 0 either way;
    // a copy moved by t is at most |t| away.
    Mesh back, moved = m;
    CGAL_ext::from_surface_mesh(sm, back);
    const auto np = PMP::parameters::number_of_points_on_faces(200);
    EXPECT_LT(PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(m, back, np, np), 1e-12);
    EXPECT_LT(PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(back, m, np, np), 1e-12);
    for (GT::vertex_descriptor v : vertices(moved))
      put(get(CGAL::vertex_point, moved), v, moved.point(v) + K::Vector_3(0, 0, 0.01));
    const double h = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(m, moved, np, np);
    EXPECT_GT(h, 0.0);
    EXPECT_LE(h, 0.01 + 1e-12);
  }
}

// ---------------------------------------------------------------- the guard

TEST(GraphTraits, OrientationGuard)
{
  Mesh strip = read_mesh("mobius_20x4_quads.obj");
  CGAL_ext::orient(strip);
  EXPECT_TRUE(CGAL_ext::has_mobius_edges(strip));
  try {
    CGAL_ext::require_orientable_model(strip, "PMP::compute_vertex_normals");
    FAIL() << "no exception";
  } catch (const CGAL_ext::Parameter_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "PMP::compute_vertex_normals: the mesh has 4 Möbius edges, so CGAL would see no global orientation; "
              "call CGAL_ext::orient() first (this mesh is non-orientable: no orientation exists)");
  }
  const Mesh torus = oriented_torus();
  EXPECT_FALSE(CGAL_ext::has_mobius_edges(torus));
  EXPECT_NO_THROW(CGAL_ext::require_orientable_model(torus, "PMP::volume"));
}

} // namespace

} // namespace graph_traits_tests
