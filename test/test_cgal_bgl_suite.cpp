// CGAL 5.5's BGL test programs (BGL/test/BGL/ of the CGAL sources), their
// checks written again as typed tests and run on CGAL::Surface_mesh and on
// CGAL_ext::Mobius_mesh alike: the same CGAL algorithms called on each mesh
// type, the same values asserted. Each test names the original test function
// it re-expresses; the inputs are the original ones (test/data/cgal_bgl/,
// see SOURCES.md there). Where an assertion cannot hold on Mobius_mesh for a
// reason of the model, it is skipped there and doc/graph_traits.md says why.
#include "test_util.h"

#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/graph_concepts.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/internal/initialized_index_maps_helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_concepts.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/unordered_map.hpp>
#include <boost/unordered_set.hpp>

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <list>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace cgal_bgl_suite {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using K = test::Epick;
using Point_3 = K::Point_3;
using SM = CGAL::Surface_mesh<Point_3>;
using MM = CGAL_ext::Mobius_mesh<Point_3>;

template <class Mesh>
constexpr bool is_mobius = std::is_same_v<Mesh, MM>;

using Meshes = ::testing::Types<SM, MM>;
struct Mesh_names
{
  template <class T>
  static std::string GetName(int)
  {
    return is_mobius<T> ? "Mobius_mesh" : "Surface_mesh";
  }
};

std::string bgl_data(const std::string& name) { return test::data("cgal_bgl/" + name); }

using id_set = boost::unordered_set<std::size_t>;

// ============================================================================
// test_Prefix.h: the mesh list, the reader and the fixtures
// ============================================================================

// The list of test_Prefix.h. BGL/test/BGL/data/genus3.off is replaced by
// CGAL's meshes/3torus.off (also closed, genus 3); rombus.off is not in the
// stored copies of CGAL's sources and is left out.
const std::vector<std::string>& prefix_files()
{
  static const std::vector<std::string> files = {
    "data/7_faces_triangle.off", "meshes/3torus.off",    "meshes/head.off",
    "meshes/hedra.off",          "meshes/hedra_open.off", "meshes/open_cube.off",
    "data/tetrahedron.off",      "data/triangle.off",     "meshes/triangular_hole.off",
    "data/cube.off"};
  return files;
}

template <class Mesh>
bool read_a_mesh(Mesh& m, const std::string& name)
{
  return CGAL::IO::read_polygon_mesh(bgl_data(name), m);
}

// t_data<T>() of test_Prefix.h: every mesh of the list, read.
template <class Mesh>
std::vector<Mesh> t_data()
{
  std::vector<Mesh> meshes;
  for (const std::string& name : prefix_files()) {
    meshes.emplace_back();
    EXPECT_TRUE(read_a_mesh(meshes.back(), name)) << "failed to read test data: " << name;
  }
  return meshes;
}

template <class Graph>
using GT = boost::graph_traits<Graph>;

template <class Graph>
typename GT<Graph>::vertex_descriptor vertex_at(const Graph& m, const Point_3& p)
{
  const auto pm = get(CGAL::vertex_point, m);
  for (auto v : vertices(m))
    if (get(pm, v) == p)
      return v;
  return GT<Graph>::null_vertex();
}

// Surface_fixture_1: fixture1.off, vertices u v w x y and faces f1 f2 f3.
template <class Graph>
struct Surface_fixture_1
{
  Graph m;
  typename GT<Graph>::vertex_descriptor u, v, w, x, y;
  typename GT<Graph>::face_descriptor f1, f2, f3;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/fixture1.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    u = vertex_at(m, Point_3(0, 0, 0));
    v = vertex_at(m, Point_3(1, 0, 0));
    w = vertex_at(m, Point_3(0, 1, 0));
    x = vertex_at(m, Point_3(1, 1, 0));
    y = vertex_at(m, Point_3(2, 0, 0));
    for (auto vd : {u, v, w, x, y})
      ASSERT_NE(vd, GT<Graph>::null_vertex());
    f1 = CGAL::is_border(halfedge(u, m), m) ? face(opposite(halfedge(u, m), m), m) : face(halfedge(u, m), m);
    ASSERT_NE(f1, GT<Graph>::null_face());
    for (auto h : CGAL::halfedges_around_face(halfedge(f1, m), m))
      if (!CGAL::is_border(opposite(h, m), m))
        f2 = face(opposite(h, m), m);
    for (auto f : faces(m))
      if (f != f1 && f != f2)
        f3 = f;
    ASSERT_NE(f2, GT<Graph>::null_face());
    ASSERT_NE(f3, GT<Graph>::null_face());
  }
};

// Surface_fixture_2: fixture2.off, vertices u v w x y, faces f1..f4 found
// from the halfedges x->v, v->u, u->w, w->x.
template <class Graph>
struct Surface_fixture_2
{
  Graph m;
  typename GT<Graph>::vertex_descriptor u, v, w, x, y;
  typename GT<Graph>::face_descriptor f1, f2, f3, f4;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/fixture2.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    u = vertex_at(m, Point_3(0, 2, 0));
    v = vertex_at(m, Point_3(2, 2, 0));
    w = vertex_at(m, Point_3(0, 0, 0));
    x = vertex_at(m, Point_3(2, 0, 0));
    y = vertex_at(m, Point_3(1, 1, 0));
    for (auto vd : {u, v, w, x, y})
      ASSERT_NE(vd, GT<Graph>::null_vertex());
    auto face_of = [&](auto a, auto b, typename GT<Graph>::face_descriptor& f) {
      const auto [h, found] = halfedge(a, b, m);
      ASSERT_TRUE(found);
      ASSERT_FALSE(CGAL::is_border(h, m));
      f = face(h, m);
      ASSERT_NE(f, GT<Graph>::null_face());
    };
    ASSERT_NO_FATAL_FAILURE(face_of(x, v, f1));
    ASSERT_NO_FATAL_FAILURE(face_of(v, u, f2));
    ASSERT_NO_FATAL_FAILURE(face_of(u, w, f3));
    ASSERT_NO_FATAL_FAILURE(face_of(w, x, f4));
  }
};

// Surface_fixture_3: fixture3.off, vertices u v w x y z, the faces f1 at u
// and f2 at z.
template <class Graph>
struct Surface_fixture_3
{
  Graph m;
  typename GT<Graph>::vertex_descriptor u, v, w, x, y, z;
  typename GT<Graph>::face_descriptor f1, f2;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/fixture3.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    u = vertex_at(m, Point_3(0, 1, 0));
    v = vertex_at(m, Point_3(0, 0, 0));
    w = vertex_at(m, Point_3(1, 0, 0));
    x = vertex_at(m, Point_3(1, 1, 0));
    y = vertex_at(m, Point_3(2, 0, 0));
    z = vertex_at(m, Point_3(2, 1, 0));
    for (auto vd : {u, v, w, x, y, z})
      ASSERT_NE(vd, GT<Graph>::null_vertex());
    f1 = CGAL::is_border(halfedge(u, m), m) ? face(opposite(halfedge(u, m), m), m) : face(halfedge(u, m), m);
    f2 = CGAL::is_border(halfedge(z, m), m) ? face(opposite(halfedge(z, m), m), m) : face(halfedge(z, m), m);
    ASSERT_NE(f1, GT<Graph>::null_face());
    ASSERT_NE(f2, GT<Graph>::null_face());
  }
};

// Surface_fixture_4: fixture4.off, the first two border halfedges that end
// at (0, 0, 0).
template <class Graph>
struct Surface_fixture_4
{
  Graph m;
  typename GT<Graph>::halfedge_descriptor h1, h2;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/fixture4.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    const auto pm = get(CGAL::vertex_point, m);
    int found = 0;
    for (auto h : halfedges(m))
      if (CGAL::is_border(h, m) && get(pm, target(h, m)) == Point_3(0, 0, 0)) {
        if (found == 0)
          h1 = h;
        else if (found == 1)
          h2 = h;
        ++found;
      }
    ASSERT_EQ(found, 2);
  }
};

// Surface_fixture_5: add_face_to_border.off, the border halfedges that end
// at (2, 1, 0) and (2, -1, 0).
template <class Graph>
struct Surface_fixture_5
{
  Graph m;
  typename GT<Graph>::halfedge_descriptor h1, h2;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/add_face_to_border.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    const auto pm = get(CGAL::vertex_point, m);
    int found = 0;
    for (auto h : halfedges(m))
      if (CGAL::is_border(h, m)) {
        if (get(pm, target(h, m)) == Point_3(2, 1, 0)) {
          h1 = h;
          ++found;
        } else if (get(pm, target(h, m)) == Point_3(2, -1, 0)) {
          h2 = h;
          ++found;
        }
      }
    ASSERT_EQ(found, 2);
  }
};

// Surface_fixture_6: quad.off, the first face's halfedge and the one two
// steps further.
template <class Graph>
struct Surface_fixture_6
{
  Graph m;
  typename GT<Graph>::halfedge_descriptor h1, h2;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/quad.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    h1 = halfedge(*faces(m).first, m);
    h2 = next(next(h1, m), m);
  }
};

// Surface_fixture_7: cube.off and its first halfedge.
template <class Graph>
struct Surface_fixture_7
{
  Graph m;
  typename GT<Graph>::halfedge_descriptor h;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/cube.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    h = *halfedges(m).first;
  }
};

// Surface_fixture_8: fixture5.off, the halfedges (0,0,0)->(1,0,0),
// (1,0,0)->(0,1,0) and (0,1,0)->(0,0,0).
template <class Graph>
struct Surface_fixture_8
{
  Graph m;
  typename GT<Graph>::halfedge_descriptor h1, h2, h3;

  void init()
  {
    ASSERT_TRUE(read_a_mesh(m, "data/fixture5.off"));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
    const auto pm = get(CGAL::vertex_point, m);
    int found = 0;
    for (auto h : halfedges(m)) {
      const Point_3& s = get(pm, source(h, m));
      const Point_3& t = get(pm, target(h, m));
      if (s == Point_3(0, 0, 0) && t == Point_3(1, 0, 0)) {
        h1 = h;
        ++found;
      } else if (s == Point_3(1, 0, 0) && t == Point_3(0, 1, 0)) {
        h2 = h;
        ++found;
      } else if (s == Point_3(0, 1, 0) && t == Point_3(0, 0, 0)) {
        h3 = h;
        ++found;
      }
    }
    ASSERT_EQ(found, 3);
  }
};

template <class T>
class CgalBglPrefix : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglPrefix, Meshes, Mesh_names);

// CGAL 5.5 BGL/test/BGL/test_Prefix.h, t_data() over its list of meshes
TYPED_TEST(CgalBglPrefix, t_data)
{
  const std::vector<TypeParam> meshes = t_data<TypeParam>();
  ASSERT_EQ(meshes.size(), prefix_files().size());
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SCOPED_TRACE(prefix_files()[i]);
    EXPECT_FALSE(CGAL::is_empty(meshes[i]));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(meshes[i]));
  }
}

// CGAL 5.5 BGL/test/BGL/test_Prefix.h, Surface_fixture_1 .. Surface_fixture_8
TYPED_TEST(CgalBglPrefix, Surface_fixtures)
{
  { Surface_fixture_1<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
  { Surface_fixture_2<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
  { Surface_fixture_3<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
  { Surface_fixture_4<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
  { Surface_fixture_5<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
  { Surface_fixture_6<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
  { Surface_fixture_7<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
  { Surface_fixture_8<TypeParam> f; ASSERT_NO_FATAL_FAILURE(f.init()); }
}

// ============================================================================
// graph_concept_Surface_mesh.cpp: Boost's and CGAL's concept checks
// ============================================================================

template <class Graph>
void concept_check()
{
  using Traits = boost::graph_traits<Graph>;
  using vertex_descriptor = typename Traits::vertex_descriptor;
  using halfedge_descriptor = typename Traits::halfedge_descriptor;
  using edge_descriptor = typename Traits::edge_descriptor;
  using face_descriptor = typename Traits::face_descriptor;
  BOOST_CONCEPT_ASSERT((boost::GraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::EdgeListGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::IncidenceGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::AdjacencyMatrixConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::BidirectionalGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((CGAL::HalfedgeGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((CGAL::HalfedgeListGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((CGAL::FaceGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((CGAL::FaceListGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((CGAL::MutableHalfedgeGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((CGAL::MutableFaceGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::concepts::ReadablePropertyGraph<Graph, halfedge_descriptor, CGAL::halfedge_index_t>));
  BOOST_CONCEPT_ASSERT((boost::concepts::ReadablePropertyGraph<Graph, edge_descriptor, boost::edge_index_t>));
  BOOST_CONCEPT_ASSERT((boost::concepts::ReadablePropertyGraph<Graph, edge_descriptor, boost::edge_weight_t>));
  BOOST_CONCEPT_ASSERT((boost::concepts::PropertyGraph<Graph, vertex_descriptor, CGAL::vertex_point_t>));
  BOOST_CONCEPT_ASSERT((boost::concepts::ReadablePropertyGraph<Graph, vertex_descriptor, boost::vertex_index_t>));
  BOOST_CONCEPT_ASSERT((boost::concepts::ReadablePropertyGraph<Graph, face_descriptor, CGAL::face_index_t>));
}

template <class T>
class CgalBglGraphConcept : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglGraphConcept, Meshes, Mesh_names);

// CGAL 5.5 BGL/test/BGL/graph_concept_Surface_mesh.cpp, concept_check_surface_mesh()
TYPED_TEST(CgalBglGraphConcept, concept_check_surface_mesh)
{
  concept_check<TypeParam>();
  EXPECT_FALSE(GT<TypeParam>::null_vertex() != typename GT<TypeParam>::vertex_descriptor());
  EXPECT_FALSE(GT<TypeParam>::null_face() != typename GT<TypeParam>::face_descriptor());
}

// ============================================================================
// test_graph_traits.cpp
// ============================================================================

template <class T>
class CgalBglGraphTraits : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglGraphTraits, Meshes, Mesh_names);

// Runs `check(mesh)` on every mesh of test_Prefix.h's list.
template <class Mesh, class Check>
void for_each_prefix_mesh(Check check)
{
  const std::vector<Mesh> meshes = t_data<Mesh>();
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SCOPED_TRACE(prefix_files()[i]);
    check(meshes[i]);
  }
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_isolated_vertex()
TYPED_TEST(CgalBglGraphTraits, test_isolated_vertex)
{
  TypeParam g;
  const auto v = add_vertex(g);
  // the connectivity of v may be anything
  set_halfedge(v, GT<TypeParam>::null_halfedge(), g);
  const auto h = halfedge(v, g);
  (void)h;
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_halfedge_around_vertex_iterator()
TYPED_TEST(CgalBglGraphTraits, test_halfedge_around_vertex_iterator)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    for (auto v : vertices(g)) {
      auto [it, end] = CGAL::halfedges_around_target(halfedge(v, g), g);
      for (; it != end; ++it) {
        ASSERT_EQ(target(*it, g), v);
        auto step = std::next(it);
        if (step != end) {
          ASSERT_EQ(*step, opposite(next(*it, g), g)); // clockwise
        }
      }
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_halfedge_around_face_iterator()
TYPED_TEST(CgalBglGraphTraits, test_halfedge_around_face_iterator)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    for (auto f : faces(g)) {
      auto [it, end] = CGAL::halfedges_around_face(halfedge(f, g), g);
      ASSERT_NE(std::distance(it, end), 0);
      for (; it != end; ++it)
        ASSERT_EQ(face(*it, g), f);
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_edge_iterators()
TYPED_TEST(CgalBglGraphTraits, test_edge_iterators)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    auto [eb, ee] = edges(g);
    ASSERT_EQ(std::size_t(std::distance(eb, ee)), std::size_t(num_edges(g)));
    id_set ids;
    std::size_t count = 0;
    for (auto e : edges(g)) {
      ASSERT_TRUE(ids.insert(get(boost::edge_index, g, e)).second); // unique
      ++count;
    }
    ASSERT_EQ(count, std::size_t(num_edges(g)));
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_vertex_iterators()
TYPED_TEST(CgalBglGraphTraits, test_vertex_iterators)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    std::size_t count = 0;
    for (auto v : vertices(g)) {
      (void)v;
      ++count;
    }
    ASSERT_EQ(count, std::size_t(num_vertices(g)));
    id_set ids;
    count = 0;
    for (auto v : vertices(g)) {
      ASSERT_TRUE(ids.insert(get(boost::vertex_index, g, v)).second);
      ++count;
    }
    ASSERT_EQ(count, std::size_t(num_vertices(g)));
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_out_edges()
TYPED_TEST(CgalBglGraphTraits, test_out_edges)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    for (auto around : vertices(g)) {
      id_set v_ids;
      auto [it, end] = out_edges(around, g);
      for (; it != end; ++it) {
        const auto t = target(*it, g), s = source(*it, g);
        ASSERT_NE(s, t);
        ASSERT_EQ(s, around);
        ASSERT_NE(t, around);
        ASSERT_TRUE(v_ids.insert(get(boost::vertex_index, g, t)).second);
      }
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_in_edges()
TYPED_TEST(CgalBglGraphTraits, test_in_edges)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    for (auto around : vertices(g)) {
      id_set v_ids;
      auto [it, end] = in_edges(around, g);
      for (; it != end; ++it) {
        const auto t = target(*it, g), s = source(*it, g);
        ASSERT_EQ(t, around);
        ASSERT_NE(s, around);
        ASSERT_TRUE(v_ids.insert(get(boost::vertex_index, g, s)).second);
      }
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_in_out_edges()
template <class Graph>
void check_in_out_edges(const Graph& g)
{
  for (auto v : vertices(g)) {
    id_set v_ids;
    std::vector<typename GT<Graph>::vertex_descriptor> in, out;
    {
      auto [it, end] = in_edges(v, g);
      for (; it != end; ++it) {
        ASSERT_TRUE(v_ids.insert(get(CGAL::vertex_index, g, source(*it, g))).second);
        in.push_back(source(*it, g));
      }
    }
    {
      auto [it, end] = out_edges(v, g);
      for (; it != end; ++it) {
        ASSERT_FALSE(v_ids.insert(get(CGAL::vertex_index, g, target(*it, g))).second); // must fail
        out.push_back(target(*it, g));
      }
    }
    // the same vertices, in the same order
    ASSERT_EQ(in, out);
    ASSERT_EQ(in.size(), std::size_t(in_degree(v, g)));
    ASSERT_EQ(out.size(), std::size_t(out_degree(v, g)));
    ASSERT_EQ(in.size(), std::size_t(degree(v, g)));
    ASSERT_EQ(degree(v, g), in_degree(v, g));
    ASSERT_EQ(degree(v, g), out_degree(v, g));
  }
}
TYPED_TEST(CgalBglGraphTraits, test_in_out_edges)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) { check_in_out_edges(g); });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_edge_find()
TYPED_TEST(CgalBglGraphTraits, test_edge_find)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    for (auto e : edges(g)) {
      const auto s = source(e, g), t = target(e, g);
      const auto found = edge(s, t, g), found2 = edge(t, s, g);
      ASSERT_TRUE(found.second);
      ASSERT_TRUE(found2.second);
      ASSERT_EQ(found.first, e);
      ASSERT_EQ(found2.first, e);
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_faces()
TYPED_TEST(CgalBglGraphTraits, test_faces)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) {
    std::size_t count = 0;
    for (auto f : faces(g)) {
      ++count;
      ASSERT_EQ(face(halfedge(f, g), g), f); // reverse look-up
      for (auto h : CGAL::halfedges_around_face(halfedge(f, g), g))
        ASSERT_EQ(face(h, g), f);
    }
    ASSERT_EQ(count, std::size_t(num_faces(g)));
  });
}

// CGAL 5.5 BGL/test/BGL/test_graph_traits.cpp, test_read()
TYPED_TEST(CgalBglGraphTraits, test_read)
{
  for_each_prefix_mesh<TypeParam>([](const TypeParam& g) { ASSERT_TRUE(CGAL::is_valid_polygon_mesh(g)); });
}

// ============================================================================
// test_Properties.cpp
// ============================================================================

template <class T>
class CgalBglProperties : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglProperties, Meshes, Mesh_names);

// test_uniqueness(): the index map gives each element of the range its own id.
template <class Graph, class Range, class IndexMap>
void test_uniqueness(const Graph&, const Range& range, IndexMap index_map)
{
  boost::unordered_set<typename boost::property_traits<IndexMap>::value_type> ids;
  std::ptrdiff_t n = 0;
  for (const auto& k : range) {
    ASSERT_TRUE(ids.insert(get(index_map, k)).second) << "id seen already";
    ++n;
  }
  ASSERT_EQ(n, std::ptrdiff_t(ids.size()));
}

// A readable, not writable, map over a container (test_Properties.cpp's
// Non_mutable_property_map), and a read-write one (its RW_property_map).
template <class Key, class Value, class Container>
struct Read_only_map
{
  using key_type = Key;
  using value_type = Value;
  using reference = Value;
  using category = boost::readable_property_map_tag;
  const Container* c;
  friend Value get(const Read_only_map& m, const Key& k) { return m.c->at(k); }
};
template <class Key, class Value, class Container>
struct Read_write_map
{
  using key_type = Key;
  using value_type = Value;
  using reference = Value&;
  using category = boost::read_write_property_map_tag;
  Container* c;
  friend void put(const Read_write_map& m, const Key& k, const Value& v) { (*m.c)[k] = v; }
  friend Value& get(const Read_write_map& m, const Key& k) { return (*m.c)[k]; }
};

template <class Graph>
void internal_index_maps(const Graph& g)
{
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, vertices(g), get(boost::vertex_index, g)));
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, halfedges(g), get(boost::halfedge_index, g)));
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, edges(g), get(boost::edge_index, g)));
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, faces(g), get(boost::face_index, g)));
}

// test_initialized_index_maps() and its const twin: CGAL's initialized maps,
// then maps passed as named parameters (a reversed vertex map, a read-only
// halfedge map, a writable edge map that CGAL initializes, a face map).
template <class Graph, class G>
void initialized_index_maps(G& g)
{
  constexpr bool is_const = std::is_const_v<G>;
  using VIM = std::conditional_t<is_const, typename CGAL::GetInitializedVertexIndexMap<Graph>::const_type,
                                 typename CGAL::GetInitializedVertexIndexMap<Graph>::type>;
  using HIM = std::conditional_t<is_const, typename CGAL::GetInitializedHalfedgeIndexMap<Graph>::const_type,
                                 typename CGAL::GetInitializedHalfedgeIndexMap<Graph>::type>;
  using EIM = std::conditional_t<is_const, typename CGAL::GetInitializedEdgeIndexMap<Graph>::const_type,
                                 typename CGAL::GetInitializedEdgeIndexMap<Graph>::type>;
  using FIM = std::conditional_t<is_const, typename CGAL::GetInitializedFaceIndexMap<Graph>::const_type,
                                 typename CGAL::GetInitializedFaceIndexMap<Graph>::type>;
  VIM ivim = CGAL::get_initialized_vertex_index_map(g);
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, vertices(g), ivim));
  HIM ihim = CGAL::get_initialized_halfedge_index_map(g);
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, halfedges(g), ihim));
  EIM ieim = CGAL::get_initialized_edge_index_map(g);
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, edges(g), ieim));
  FIM ifim = CGAL::get_initialized_face_index_map(g);
  ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, faces(g), ifim));

  using vertex_descriptor = typename GT<Graph>::vertex_descriptor;
  using halfedge_descriptor = typename GT<Graph>::halfedge_descriptor;
  using edge_descriptor = typename GT<Graph>::edge_descriptor;
  using face_descriptor = typename GT<Graph>::face_descriptor;

  // a vertex index map passed by named parameter (an lvalue map)
  std::map<vertex_descriptor, int> vim;
  boost::associative_property_map<std::map<vertex_descriptor, int>> external_vim(vim);
  int vi = static_cast<int>(num_vertices(g));
  for (vertex_descriptor v : vertices(g))
    put(external_vim, v, --vi);
  {
    const auto np = CGAL::parameters::vertex_index_map(external_vim);
    using M = typename CGAL::GetInitializedVertexIndexMap<Graph, decltype(np)>::type;
    using CM = typename CGAL::GetInitializedVertexIndexMap<Graph, decltype(np)>::const_type;
    static_assert(std::is_same_v<M, CM>, "a map passed by named parameter has one type");
    ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, vertices(g), CGAL::get_initialized_vertex_index_map(g, np)));
  }

  // a read-only halfedge index map
  std::map<halfedge_descriptor, int> him;
  int hi = 0;
  for (halfedge_descriptor h : halfedges(g))
    him[h] = hi++;
  Read_only_map<halfedge_descriptor, int, std::map<halfedge_descriptor, int>> external_him{&him};
  {
    const auto np = CGAL::parameters::halfedge_index_map(external_him);
    using M = typename CGAL::GetInitializedHalfedgeIndexMap<Graph, decltype(np)>::type;
    using CM = typename CGAL::GetInitializedHalfedgeIndexMap<Graph, decltype(np)>::const_type;
    static_assert(std::is_same_v<M, CM>, "a map passed by named parameter has one type");
    ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, halfedges(g), CGAL::get_initialized_halfedge_index_map(g, np)));
  }

  // a writable edge index map, initialized by CGAL
  boost::unordered_map<edge_descriptor, int> eim;
  Read_write_map<edge_descriptor, int, boost::unordered_map<edge_descriptor, int>> external_eim{&eim};
  CGAL::BGL::internal::initialize_edge_index_map(external_eim, g);
  {
    const auto np = CGAL::parameters::edge_index_map(external_eim);
    using M = typename CGAL::GetInitializedEdgeIndexMap<Graph, decltype(np)>::type;
    using CM = typename CGAL::GetInitializedEdgeIndexMap<Graph, decltype(np)>::const_type;
    static_assert(std::is_same_v<M, CM>, "a map passed by named parameter has one type");
    ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, edges(g), CGAL::get_initialized_edge_index_map(g, np)));
  }

  // a face index map (const associative: not writable)
  std::map<face_descriptor, int> fim;
  int fi = 0;
  for (face_descriptor f : faces(g))
    fim[f] = fi++;
  boost::const_associative_property_map<std::map<face_descriptor, int>> external_fim(fim);
  {
    const auto np = CGAL::parameters::face_index_map(external_fim);
    using M = typename CGAL::GetInitializedFaceIndexMap<Graph, decltype(np)>::type;
    using CM = typename CGAL::GetInitializedFaceIndexMap<Graph, decltype(np)>::const_type;
    static_assert(std::is_same_v<M, CM>, "a map passed by named parameter has one type");
    ASSERT_NO_FATAL_FAILURE(test_uniqueness(g, faces(g), CGAL::get_initialized_face_index_map(g, np)));
  }
}

// The meshes of test_Properties.cpp's main(): the list, each with some
// garbage (Euler::join_vertex() on its first halfedge).
template <class Mesh>
std::vector<Mesh> meshes_with_garbage()
{
  std::vector<Mesh> meshes = t_data<Mesh>();
  for (Mesh& m : meshes) {
    EXPECT_FALSE(CGAL::is_empty(m));
    CGAL::Euler::join_vertex(*halfedges(m).begin(), m);
  }
  return meshes;
}

// CGAL 5.5 BGL/test/BGL/test_Properties.cpp, test_internal_index_maps()
TYPED_TEST(CgalBglProperties, test_internal_index_maps)
{
  for (TypeParam& g : meshes_with_garbage<TypeParam>())
    ASSERT_NO_FATAL_FAILURE(internal_index_maps<TypeParam>(g));
}

// CGAL 5.5 BGL/test/BGL/test_Properties.cpp, test_internal_index_maps_const()
TYPED_TEST(CgalBglProperties, test_internal_index_maps_const)
{
  for (const TypeParam& g : meshes_with_garbage<TypeParam>())
    ASSERT_NO_FATAL_FAILURE(internal_index_maps<TypeParam>(g));
}

// CGAL 5.5 BGL/test/BGL/test_Properties.cpp, test_initialized_index_maps()
TYPED_TEST(CgalBglProperties, test_initialized_index_maps)
{
  for (TypeParam& g : meshes_with_garbage<TypeParam>())
    ASSERT_NO_FATAL_FAILURE((initialized_index_maps<TypeParam, TypeParam>(g)));
}

// CGAL 5.5 BGL/test/BGL/test_Properties.cpp, test_initialized_index_maps_const()
TYPED_TEST(CgalBglProperties, test_initialized_index_maps_const)
{
  for (const TypeParam& g : meshes_with_garbage<TypeParam>())
    ASSERT_NO_FATAL_FAILURE((initialized_index_maps<TypeParam, const TypeParam>(g)));
}

// CGAL 5.5 BGL/test/BGL/test_Properties.cpp, test_graph() and main(): all of
// the above on the meshes with garbage, then the initialized maps of a
// Seam_mesh over each (a graph with no internal index maps).
TYPED_TEST(CgalBglProperties, test_graph)
{
  for (TypeParam& g : meshes_with_garbage<TypeParam>()) {
    ASSERT_NO_FATAL_FAILURE(internal_index_maps<TypeParam>(g));
    ASSERT_NO_FATAL_FAILURE((initialized_index_maps<TypeParam, TypeParam>(g)));
    ASSERT_NO_FATAL_FAILURE(internal_index_maps<TypeParam>(std::as_const(g)));
    ASSERT_NO_FATAL_FAILURE((initialized_index_maps<TypeParam, const TypeParam>(std::as_const(g))));

    using Seam_edges = typename boost::property_map<TypeParam, CGAL::dynamic_edge_property_t<bool>>::type;
    using Seam_vertices = typename boost::property_map<TypeParam, CGAL::dynamic_vertex_property_t<bool>>::type;
    Seam_edges seam_edges = get(CGAL::dynamic_edge_property_t<bool>(), g);
    Seam_vertices seam_vertices = get(CGAL::dynamic_vertex_property_t<bool>(), g);
    for (auto e : edges(g))
      put(seam_edges, e, false);
    for (auto v : vertices(g))
      put(seam_vertices, v, false);
    using Seam = CGAL::Seam_mesh<TypeParam, Seam_edges, Seam_vertices>;
    Seam seam_mesh(g, seam_edges, seam_vertices);
    ASSERT_NO_FATAL_FAILURE((initialized_index_maps<Seam, Seam>(seam_mesh)));
    ASSERT_NO_FATAL_FAILURE((initialized_index_maps<Seam, const Seam>(std::as_const(seam_mesh))));
  }
}

// ============================================================================
// test_helpers.cpp
// ============================================================================

template <class T>
class CgalBglHelpers : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglHelpers, Meshes, Mesh_names);

// CGAL 5.5 BGL/test/BGL/test_helpers.cpp, test_validity()
TYPED_TEST(CgalBglHelpers, test_validity)
{
  using Mesh = TypeParam;
  using vertex_descriptor = typename GT<Mesh>::vertex_descriptor;
  using edge_descriptor = typename GT<Mesh>::edge_descriptor;
  using face_descriptor = typename GT<Mesh>::face_descriptor;

  Mesh mesh;
  auto vpmap = get(CGAL::vertex_point, mesh);
  vertex_descriptor vs[4];
  edge_descriptor es[4];
  for (int i = 0; i < 4; ++i)
    vs[i] = add_vertex(mesh);
  put(vpmap, vs[0], Point_3(0, 0, 0));
  put(vpmap, vs[1], Point_3(1, 0, 0));
  put(vpmap, vs[2], Point_3(1, 1, 0));
  put(vpmap, vs[3], Point_3(0, 1, 0));
  for (int i = 0; i < 4; ++i)
    es[i] = add_edge(mesh);
  EXPECT_FALSE(CGAL::is_valid_halfedge_graph(mesh));
  for (int i = 0; i < 4; ++i) {
    set_target(halfedge(es[i], mesh), vs[i], mesh);
    set_halfedge(vs[i], halfedge(es[i], mesh), mesh);
  }
  for (int i = 0; i < 4; ++i)
    set_target(opposite(halfedge(es[i], mesh), mesh), vs[(i + 1) % 4], mesh);
  for (int i = 0; i < 4; ++i) {
    set_next(halfedge(es[(i + 1) % 4], mesh), halfedge(es[i], mesh), mesh);
    set_next(opposite(halfedge(es[i], mesh), mesh), opposite(halfedge(es[(i + 1) % 4], mesh), mesh), mesh);
  }
  EXPECT_TRUE(CGAL::is_valid_halfedge_graph(mesh));
  face_descriptor f = add_face(mesh);
  EXPECT_FALSE(CGAL::is_valid_face_graph(mesh));
  for (int i = 0; i < 4; ++i)
    set_face(opposite(halfedge(es[i], mesh), mesh), f, mesh);
  set_halfedge(f, opposite(halfedge(es[0], mesh), mesh), mesh);
  EXPECT_TRUE(CGAL::is_valid_face_graph(mesh));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));

  // one edge whose two halfedges bound one face: a face graph, not a polygon mesh
  Mesh dummy;
  vs[0] = add_vertex(dummy);
  vs[1] = add_vertex(dummy);
  es[0] = add_edge(dummy);
  const auto h = halfedge(es[0], dummy), oh = opposite(h, dummy);
  set_target(h, vs[0], dummy);
  set_halfedge(vs[0], h, dummy);
  set_target(oh, vs[1], dummy);
  set_halfedge(vs[1], oh, dummy);
  set_next(h, oh, dummy);
  set_next(oh, h, dummy);
  f = add_face(dummy);
  set_halfedge(f, oh, dummy);
  set_face(h, f, dummy);
  set_face(oh, f, dummy);
  EXPECT_TRUE(CGAL::is_valid_face_graph(dummy));
  EXPECT_FALSE(CGAL::is_valid_polygon_mesh(dummy));
}

// CGAL 5.5 BGL/test/BGL/test_helpers.cpp, test(fname, triangle, quad, tetrahedron, hexahedron)
// on the five files test_generators() gives it
TYPED_TEST(CgalBglHelpers, test)
{
  struct Case
  {
    const char* file;
    bool triangle, quad, tetrahedron, hexahedron;
  };
  for (const Case& c : {Case{"data/triangle.off", true, false, false, false},
                        Case{"data/quad.off", false, true, false, false},
                        Case{"data/tetrahedron.off", false, false, true, false},
                        Case{"data/cube.off", false, false, false, false},
                        Case{"data/cube-quads.off", false, false, false, true}}) {
    SCOPED_TRACE(c.file);
    TypeParam m;
    ASSERT_TRUE(read_a_mesh(m, c.file));
    const auto hd = *halfedges(m).first;
    EXPECT_EQ(CGAL::is_isolated_triangle(hd, m), c.triangle);
    EXPECT_EQ(CGAL::is_isolated_quad(hd, m), c.quad);
    EXPECT_EQ(CGAL::is_tetrahedron(hd, m), c.tetrahedron);
    EXPECT_EQ(CGAL::is_hexahedron(hd, m), c.hexahedron);
  }
}

// CGAL 5.5 BGL/test/BGL/test_helpers.cpp, test_generators() (the generators
// and the random element pickers; the files are in `test` above)
TYPED_TEST(CgalBglHelpers, test_generators)
{
  using Mesh = TypeParam;
  const Point_3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
  const Point_3 aa(0, 0, 1), bb(1, 0, 1), cc(1, 1, 1), dd(0, 1, 1);

  Mesh m;
  auto hd = CGAL::make_triangle(a, b, c, m);
  EXPECT_TRUE(CGAL::is_isolated_triangle(hd, m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));

  CGAL::clear(m);
  hd = CGAL::make_quad(a, b, c, d, m);
  EXPECT_TRUE(CGAL::is_isolated_quad(hd, m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_TRUE(CGAL::is_quad_mesh(m));

  CGAL::clear(m);
  hd = CGAL::make_tetrahedron(a, b, c, d, m);
  EXPECT_TRUE(CGAL::is_tetrahedron(hd, m));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));

  CGAL::clear(m);
  hd = CGAL::make_hexahedron(a, b, c, d, dd, aa, bb, cc, m);
  EXPECT_TRUE(CGAL::is_hexahedron(hd, m));
  EXPECT_TRUE(CGAL::is_quad_mesh(m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));

  CGAL::clear(m);
  CGAL::make_icosahedron<Mesh, Point_3>(m);
  EXPECT_EQ(num_faces(m), 20u);
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));

  CGAL::clear(m);
  hd = CGAL::make_pyramid<Mesh, Point_3>(3, m);
  EXPECT_EQ(num_faces(m), 6u);
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));

  CGAL::clear(m);
  hd = CGAL::make_regular_prism<Mesh, Point_3>(4, m);
  EXPECT_EQ(num_faces(m), 16u);
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));

  CGAL::clear(m);
  CGAL::make_grid(3, 3, m);
  EXPECT_EQ(num_faces(m), 9u);
  EXPECT_TRUE(CGAL::is_quad_mesh(m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));

  // the random element pickers
  CGAL::Random rnd;
  auto v = CGAL::internal::random_vertex_in_mesh(m, rnd);
  EXPECT_NE(v, GT<Mesh>::null_vertex());
  auto h = CGAL::internal::random_halfedge_in_mesh(m, rnd);
  EXPECT_NE(h, GT<Mesh>::null_halfedge());
  (void)CGAL::internal::random_edge_in_mesh(m, rnd);
  const auto f = CGAL::internal::random_face_in_mesh(m, rnd);
  EXPECT_NE(f, GT<Mesh>::null_face());

  h = CGAL::internal::random_halfedge_in_face(f, m, rnd);
  EXPECT_NE(h, GT<Mesh>::null_halfedge());
  EXPECT_EQ(face(h, m), f);
  v = CGAL::internal::random_vertex_in_face(f, m, rnd);
  EXPECT_NE(v, GT<Mesh>::null_vertex());
  bool has_vertex = false;
  const auto done = h;
  do {
    if (target(h, m) == v) {
      has_vertex = true;
      break;
    }
    h = next(h, m);
  } while (h != done);
  EXPECT_TRUE(has_vertex);
}

// ============================================================================
// test_Euler_operations.cpp
// ============================================================================

template <class T>
class CgalBglEuler : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglEuler, Meshes, Mesh_names);

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, test_copy_face_graph_nm_umbrella()
TYPED_TEST(CgalBglEuler, test_copy_face_graph_nm_umbrella)
{
  using T = TypeParam;
  T g;
  const Point_3 p(0, 0, 0);
  // two connected components
  CGAL::make_tetrahedron(p, p, p, p, g);
  CGAL::make_tetrahedron(p, p, p, p, g);
  std::vector<typename GT<T>::vertex_descriptor> verts(vertices(g).begin(), vertices(g).end());
  // merge verts[0] and verts[4]
  for (auto h : CGAL::halfedges_around_target(verts[4], g))
    set_target(h, verts[0], g);
  remove_vertex(verts[4], g);

  T g_copy;
  CGAL::copy_face_graph(g, g_copy);
  for (auto h : halfedges(g_copy))
    ASSERT_NE(target(h, g_copy), GT<T>::null_vertex());
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, test_copy_face_graph_isolated_vertices()
TYPED_TEST(CgalBglEuler, test_copy_face_graph_isolated_vertices)
{
  using T = TypeParam;
  const Point_3 p(0, 0, 0);
  {
    T s, t;
    add_vertex(s);
    CGAL::copy_face_graph(s, t);
  }
  {
    T s, t;
    add_vertex(t);
    CGAL::copy_face_graph(s, t);
  }
  {
    T s, t;
    CGAL::make_triangle(p, p, p, s);
    add_vertex(s);
    t = s;
    CGAL::copy_face_graph(s, t);
  }
  {
    T s, t;
    CGAL::make_triangle(p, p, p, s);
    add_vertex(s);
    add_vertex(t);
    CGAL::copy_face_graph(s, t);
  }
  {
    T s, t;
    CGAL::make_tetrahedron(p, p, p, p, s);
    add_vertex(s);
    t = s;
    CGAL::copy_face_graph(s, t);
  }
  {
    T s, t;
    CGAL::make_tetrahedron(p, p, p, p, s);
    add_vertex(s);
    add_vertex(t);
    CGAL::copy_face_graph(s, t);
  }
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, join_face_test()
TYPED_TEST(CgalBglEuler, join_face_test)
{
  using T = TypeParam;
  Surface_fixture_1<T> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  const auto [e, found] = halfedge(f.w, f.v, f.m);
  ASSERT_TRUE(found);
  // the halfedge of f1 set to the edge to be removed: a special case
  set_halfedge(f.f1, e, f.m);
  CGAL::Euler::join_face(e, f.m);

  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 2u);
  EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 6u);
  auto [begin, end] = CGAL::halfedges_around_face(halfedge(f.f1, f.m), f.m);
  EXPECT_EQ(std::distance(begin, end), 4);
  for (; begin != end; ++begin)
    EXPECT_EQ(face(*begin, f.m), f.f1);
  for (auto fd : faces(f.m))
    EXPECT_TRUE(fd == f.f1 || fd == f.f3);
  EXPECT_EQ(degree(f.w, f.m), 2u);
  EXPECT_EQ(degree(f.v, f.m), 3u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, remove_face_test_1()
TYPED_TEST(CgalBglEuler, remove_face_test_1)
{
  using T = TypeParam;
  Surface_fixture_1<T> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  const auto [e, found] = halfedge(f.x, f.y, f.m); // between x and y
  ASSERT_TRUE(found);
  ASSERT_EQ(face(e, f.m), f.f3);
  CGAL::Euler::remove_face(e, f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
  EXPECT_EQ(degree(f.v, f.m), 3u);
  EXPECT_EQ(degree(f.x, f.m), 2u);
  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 2u);
  EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 5u);
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 4u);
  int count = 0;
  for (auto h : halfedges(f.m))
    if (face(h, f.m) == GT<T>::null_face())
      ++count;
  EXPECT_EQ(count, 4);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, remove_face_test_2()
TYPED_TEST(CgalBglEuler, remove_face_test_2)
{
  using T = TypeParam;
  Surface_fixture_2<T> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  auto [e, found] = halfedge(f.x, f.w, f.m);
  ASSERT_TRUE(found);
  std::tie(e, found) = halfedge(f.x, f.v, f.m);
  ASSERT_TRUE(found);
  ASSERT_EQ(face(e, f.m), f.f1);
  CGAL::Euler::remove_face(e, f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 3u);
  EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 7u);
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 5u);
  std::tie(e, found) = halfedge(f.x, f.w, f.m);
  ASSERT_TRUE(found);
  EXPECT_EQ(face(e, f.m), GT<T>::null_face());
  // the border
  for (auto n = next(e, f.m); n != e; n = next(n, f.m))
    ASSERT_EQ(face(n, f.m), GT<T>::null_face());
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, add_face_to_border_test()
TYPED_TEST(CgalBglEuler, add_face_to_border_test)
{
  Surface_fixture_5<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  CGAL::Euler::add_face_to_border(f.h1, f.h2, f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, add_vertex_and_face_to_border_test()
TYPED_TEST(CgalBglEuler, add_vertex_and_face_to_border_test)
{
  Surface_fixture_5<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  const TypeParam& m = f.m;
  int dist = 0;
  for (auto hd = f.h1; hd != f.h2; hd = next(hd, m))
    ++dist;
  EXPECT_EQ(dist, 2);
  int blength = 0;
  for (auto hd : CGAL::halfedges_around_face(f.h1, m)) {
    (void)hd;
    ++blength;
  }
  auto res = CGAL::Euler::add_vertex_and_face_to_border(f.h1, f.h2, f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
  EXPECT_FALSE(CGAL::is_border(res, m));
  EXPECT_TRUE(CGAL::is_border(opposite(res, m), m));
  res = opposite(res, m);
  for (auto hd : CGAL::halfedges_around_face(res, m)) {
    (void)hd;
    --blength;
  }
  EXPECT_EQ(blength, 0);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, join_vertex_interior_test()
TYPED_TEST(CgalBglEuler, join_vertex_interior_test)
{
  Surface_fixture_3<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  const auto [e, found] = halfedge(f.w, f.x, f.m);
  ASSERT_TRUE(found);
  CGAL::Euler::join_vertex(e, f.m);
  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 2u);
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 5u);
  EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 6u);
  EXPECT_EQ(CGAL::halfedges_around_face(halfedge(f.f1, f.m), f.m).size(), 3u);
  EXPECT_EQ(CGAL::halfedges_around_face(halfedge(f.f2, f.m), f.m).size(), 3u);
  EXPECT_EQ(degree(f.x, f.m), 4u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, join_vertex_exterior_test()
TYPED_TEST(CgalBglEuler, join_vertex_exterior_test)
{
  {
    // an exterior edge collapsed
    Surface_fixture_3<TypeParam> f;
    ASSERT_NO_FATAL_FAILURE(f.init());
    const auto [e, found] = halfedge(f.w, f.y, f.m);
    ASSERT_TRUE(found);
    EXPECT_EQ(source(e, f.m), f.w);
    EXPECT_EQ(target(e, f.m), f.y);
    CGAL::Euler::join_vertex(e, f.m);
    EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 2u);
    EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 5u);
    EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 6u);
    EXPECT_EQ(CGAL::halfedges_around_face(halfedge(f.f1, f.m), f.m).size(), 4u);
    EXPECT_EQ(CGAL::halfedges_around_face(halfedge(f.f2, f.m), f.m).size(), 3u);
    EXPECT_EQ(degree(f.y, f.m), 3u);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
  }
  {
    Surface_fixture_3<TypeParam> f;
    ASSERT_NO_FATAL_FAILURE(f.init());
    const auto [e, found] = halfedge(f.y, f.w, f.m);
    ASSERT_TRUE(found);
    EXPECT_EQ(source(e, f.m), f.y);
    EXPECT_EQ(target(e, f.m), f.w);
    CGAL::Euler::join_vertex(e, f.m);
    EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 2u);
    EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 5u);
    EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 6u);
    EXPECT_EQ(CGAL::halfedges_around_face(halfedge(f.f1, f.m), f.m).size(), 4u);
    EXPECT_EQ(CGAL::halfedges_around_face(halfedge(f.f2, f.m), f.m).size(), 3u);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
    EXPECT_EQ(degree(f.w, f.m), 3u);
  }
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, split_vertex()
TYPED_TEST(CgalBglEuler, split_vertex)
{
  Surface_fixture_3<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  auto [h1, found1] = halfedge(f.w, f.y, f.m);
  ASSERT_TRUE(found1);
  auto [h2, found2] = halfedge(f.z, f.y, f.m);
  ASSERT_TRUE(found2);
  ASSERT_EQ(face(h2, f.m), GT<TypeParam>::null_face());
  // split the border vertex y
  CGAL::Euler::split_vertex(h1, h2, f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 7u);
  EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 8u);
  EXPECT_EQ(CGAL::halfedges_around_face(h1, f.m).size(), 5u);
  EXPECT_EQ(CGAL::halfedges_around_face(h2, f.m).size(), 7u);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, split_join_vertex_inverse()
TYPED_TEST(CgalBglEuler, split_join_vertex_inverse)
{
  Surface_fixture_3<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  auto [h, found] = halfedge(f.w, f.x, f.m);
  ASSERT_TRUE(found);
  CGAL::Euler::join_vertex(h, f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
  auto [h1, found1] = halfedge(f.z, f.x, f.m);
  ASSERT_TRUE(found1);
  auto [h2, found2] = halfedge(f.v, f.x, f.m);
  ASSERT_TRUE(found2);
  CGAL::Euler::join_vertex(CGAL::Euler::split_vertex(h1, h2, f.m), f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 5u);
  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 2u);
  EXPECT_EQ(CGAL::internal::exact_num_edges(f.m), 6u);
  EXPECT_EQ(CGAL::internal::exact_num_halfedges(f.m), 12u);
  EXPECT_EQ(CGAL::halfedges_around_face(h1, f.m).size(), 3u);
  EXPECT_EQ(CGAL::halfedges_around_face(h2, f.m).size(), 3u);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, join_loop_test()
TYPED_TEST(CgalBglEuler, join_loop_test)
{
  Surface_fixture_4<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  CGAL::Euler::join_loop(f.h1, f.h2, f.m);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, split_loop_test()
TYPED_TEST(CgalBglEuler, split_loop_test)
{
  Surface_fixture_8<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  CGAL::Euler::split_loop(f.h1, f.h2, f.h3, f.m);
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), 8u);
  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), 8u);
  EXPECT_EQ(CGAL::internal::exact_num_halfedges(f.m), 24u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(f.m));
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, split_face_test()
TYPED_TEST(CgalBglEuler, split_face_test)
{
  Surface_fixture_6<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  CGAL::Euler::split_face(f.h1, f.h2, f.m);
  EXPECT_EQ(num_vertices(f.m), 4u);
  EXPECT_EQ(num_faces(f.m), 2u);
  EXPECT_EQ(num_halfedges(f.m), 10u);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, make_hole_test()
TYPED_TEST(CgalBglEuler, make_hole_test)
{
  Surface_fixture_7<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  const std::size_t nv = num_vertices(f.m), nf = num_faces(f.m), nh = num_halfedges(f.m);
  CGAL::Euler::make_hole(f.h, f.m);
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), nv);
  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), nf - 1);
  EXPECT_EQ(CGAL::internal::exact_num_halfedges(f.m), nh);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, remove_center_vertex_test()
TYPED_TEST(CgalBglEuler, remove_center_vertex_test)
{
  Surface_fixture_7<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  const std::size_t nv = num_vertices(f.m), nf = num_faces(f.m), nh = num_halfedges(f.m);
  const std::size_t deg = degree(target(f.h, f.m), f.m);
  CGAL::Euler::remove_center_vertex(f.h, f.m);
  EXPECT_EQ(CGAL::internal::exact_num_vertices(f.m), nv - 1);
  EXPECT_EQ(CGAL::internal::exact_num_faces(f.m), (nf - deg) + 1);
  EXPECT_EQ(CGAL::internal::exact_num_halfedges(f.m), nh - 2 * deg);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, does_satisfy_link_condition()
TYPED_TEST(CgalBglEuler, does_satisfy_link_condition)
{
  Surface_fixture_7<TypeParam> f;
  ASSERT_NO_FATAL_FAILURE(f.init());
  EXPECT_TRUE(CGAL::Euler::does_satisfy_link_condition(*edges(f.m).first, f.m));
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, test_swap_edges()
TYPED_TEST(CgalBglEuler, test_swap_edges)
{
  const std::size_t nbh = 12;
  const Point_3 pt(0, 0, 0);
  // every pair of halfedges of a tetrahedron
  for (std::size_t i = 0; i + 1 < nbh; ++i)
    for (std::size_t j = i + 1; j < nbh; ++j) {
      TypeParam g;
      CGAL::make_tetrahedron(pt, pt, pt, pt, g);
      const auto h1 = *std::next(std::begin(halfedges(g)), i);
      const auto h2 = *std::next(std::begin(halfedges(g)), j);
      CGAL::internal::swap_edges(h1, h2, g);
      ASSERT_TRUE(CGAL::is_valid_polygon_mesh(g)) << i << " " << j;
    }
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, add_face_bug()
TYPED_TEST(CgalBglEuler, add_face_bug)
{
  using T = TypeParam;
  T g;
  std::vector<typename GT<T>::vertex_descriptor> vs;
  for (int i = 0; i < 4; ++i)
    vs.push_back(add_vertex(g));
  CGAL::Euler::add_face(CGAL::make_array(vs[0], vs[1], vs[2]), g);
  CGAL::Euler::add_face(CGAL::make_array(vs[1], vs[3], vs[2]), g);
  // force the halfedge of each vertex off the border
  for (auto v : vertices(g)) {
    const auto h = halfedge(v, g);
    if (CGAL::is_border(h, g))
      set_halfedge(v, prev(opposite(h, g), g), g);
    ASSERT_EQ(target(halfedge(v, g), g), v);
  }
  vs.push_back(add_vertex(g));
  vs.push_back(add_vertex(g));
  CGAL::Euler::add_face(CGAL::make_array(vs[4], vs[5], vs[0]), g);
  vs.push_back(add_vertex(g));
  vs.push_back(add_vertex(g));
  CGAL::Euler::add_face(CGAL::make_array(vs[6], vs[7], vs[1]), g);
  CGAL::Euler::add_face(CGAL::make_array(vs[7], vs[3], vs[1]), g);
  // the original asserts nothing more: it must not crash nor assert
  EXPECT_EQ(CGAL::internal::exact_num_faces(g), 5u);
}

// CGAL 5.5 BGL/test/BGL/test_Euler_operations.cpp, add_faces()
TYPED_TEST(CgalBglEuler, add_faces)
{
  using T = TypeParam;
  using vertex_descriptor = typename GT<T>::vertex_descriptor;
  // a mesh with a border, read twice into one mesh
  {
    T m;
    for (int i = 0; i < 2; ++i) {
      std::ifstream in(bgl_data("meshes/head.off"));
      std::vector<Point_3> points;
      std::vector<std::array<std::size_t, 3>> faces_ids;
      ASSERT_TRUE(CGAL::IO::read_OFF(in, points, faces_ids));
      std::vector<vertex_descriptor> verts;
      verts.reserve(points.size());
      std::vector<std::array<vertex_descriptor, 3>> faces_vs;
      faces_vs.reserve(faces_ids.size());
      for (std::size_t k = 0; k < points.size(); ++k)
        verts.push_back(add_vertex(m));
      for (const auto& f : faces_ids)
        faces_vs.push_back(CGAL::make_array(verts[f[0]], verts[f[1]], verts[f[2]]));
      CGAL::Euler::add_faces(faces_vs, m);
    }
    EXPECT_EQ(faces(m).size(), std::size_t(2 * 2918));
    EXPECT_EQ(vertices(m).size(), std::size_t(2 * 1487));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  }
  // closing a cube, no extra vertex
  {
    std::ifstream in(bgl_data("meshes/open_cube.off"));
    T m;
    ASSERT_TRUE(CGAL::IO::read_OFF(in, m));
    std::vector<vertex_descriptor> verts(vertices(m).begin(), vertices(m).end());
    std::list<std::vector<vertex_descriptor>> new_faces;
    new_faces.push_back({verts[1], verts[7], verts[4]});
    new_faces.push_back({verts[1], verts[0], verts[7]});
    CGAL::Euler::add_faces(new_faces, m);
    EXPECT_TRUE(CGAL::is_closed(m));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  }
  // closing a cube with an extra vertex
  {
    std::ifstream in(bgl_data("meshes/open_cube.off"));
    T m;
    ASSERT_TRUE(CGAL::IO::read_OFF(in, m));
    std::vector<vertex_descriptor> verts(vertices(m).begin(), vertices(m).end());
    verts.push_back(add_vertex(m));
    put(CGAL::vertex_point, m, verts.back(), Point_3(50, 0, 50));
    std::list<std::vector<vertex_descriptor>> new_faces;
    new_faces.push_back({verts[1], verts[0], verts.back()});
    new_faces.push_back({verts[0], verts[7], verts.back()});
    new_faces.push_back({verts[7], verts[4], verts.back()});
    new_faces.push_back({verts[4], verts[1], verts.back()});
    CGAL::Euler::add_faces(new_faces, m);
    EXPECT_TRUE(CGAL::is_closed(m));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  }
  // a model with non-manifold vertices
  for (int run = 0; run < 4; ++run) {
    SCOPED_TRACE(run);
    T m;
    const std::vector<Point_3> points = {
      {0, 0, 0}, {4, 0, 0}, {8, 0, 0}, {4, 1, 0}, {4, 2, 0}, {4, 3, 0}, {0, 3, 0},
      {1, 0, 3}, {2, 0, 3}, {3, 0, 3}, {5, 0, 3}, {6, 0, 3}, {7, 0, 3}, {4, -3, 0}};
    std::vector<vertex_descriptor> v;
    for (const Point_3& p : points) {
      v.push_back(add_vertex(m));
      put(CGAL::vertex_point, m, v.back(), p);
    }
    // which border halfedge is created first
    std::vector<std::array<vertex_descriptor, 3>> face_array;
    face_array.push_back(CGAL::make_array(v[0], v[1], v[3]));
    face_array.push_back(CGAL::make_array(v[2], v[3], v[1]));
    if (run > 1)
      std::swap(face_array[0], face_array[1]);
    CGAL::Euler::add_face(face_array[0], m);
    CGAL::Euler::add_face(face_array[1], m);
    const auto to_be_removed1 = CGAL::Euler::add_face(CGAL::make_array(v[0], v[3], v[4]), m);
    const auto to_be_removed2 = CGAL::Euler::add_face(CGAL::make_array(v[2], v[4], v[3]), m);
    CGAL::Euler::add_face(CGAL::make_array(v[0], v[4], v[5], v[6]), m);
    CGAL::Euler::add_face(CGAL::make_array(v[2], v[5], v[4]), m);
    CGAL::Euler::add_face(CGAL::make_array(v[1], v[7], v[8]), m);
    CGAL::Euler::add_face(CGAL::make_array(v[1], v[8], v[9]), m);
    CGAL::Euler::add_face(CGAL::make_array(v[1], v[10], v[11]), m);
    CGAL::Euler::add_face(CGAL::make_array(v[1], v[11], v[12]), m);
    const auto removed = run % 2 == 0 ? to_be_removed1 : to_be_removed2;
    for (auto h : CGAL::halfedges_around_face(halfedge(removed, m), m))
      set_face(h, GT<T>::null_face(), m);
    remove_face(removed, m);

    std::vector<std::vector<vertex_descriptor>> new_faces;
    new_faces.push_back({v[0], v[13], v[1]});
    new_faces.push_back({v[1], v[13], v[2]});
    std::vector<typename GT<T>::halfedge_descriptor> border_hedges;
    PMP::extract_boundary_cycles(m, std::back_inserter(border_hedges));
    EXPECT_EQ(border_hedges.size(), 2u);
    CGAL::Euler::add_faces(new_faces, m);
    border_hedges.clear();
    PMP::extract_boundary_cycles(m, std::back_inserter(border_hedges));
    EXPECT_EQ(border_hedges.size(), 3u);
  }
}

// ============================================================================
// test_Collapse_edge.cpp
// ============================================================================

template <class T>
class CgalBglCollapseEdge : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglCollapseEdge, Meshes, Mesh_names);

// find_halfedge(): the halfedge from (x1, y1, 0) to (x2, y2, 0), or its
// opposite, whichever is (or is not) a border halfedge as asked.
template <class Mesh>
typename GT<Mesh>::halfedge_descriptor find_halfedge(double x1, double y1, double x2, double y2, const Mesh& m,
                                                      bool is_border = false)
{
  const auto vpmap = get(CGAL::vertex_point, m);
  for (auto h : halfedges(m))
    if (get(vpmap, source(h, m)) == Point_3(x1, y1, 0) && get(vpmap, target(h, m)) == Point_3(x2, y2, 0))
      return is_border == CGAL::is_border(h, m) ? h : opposite(h, m);
  return GT<Mesh>::null_halfedge();
}

// How many halfedges around v are among `wanted`.
template <class Mesh>
int count_around_target(typename GT<Mesh>::vertex_descriptor v, const Mesh& m,
                        std::initializer_list<typename GT<Mesh>::halfedge_descriptor> wanted)
{
  int found = 0;
  for (auto it : CGAL::halfedges_around_target(v, m))
    for (auto w : wanted)
      if (it == w) {
        ++found;
        break;
      }
  return found;
}

// CGAL 5.5 BGL/test/BGL/test_Collapse_edge.cpp, collapse_edge_test()
TYPED_TEST(CgalBglCollapseEdge, collapse_edge_test)
{
  using Mesh = TypeParam;
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_OFF(bgl_data("data/flat_hexahedron.off"), m));
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
  Mesh test_mesh;
  CGAL::copy_face_graph(m, test_mesh);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));

  auto collapse_and_check = [&](bool with_ep_prime) {
    const auto he = find_halfedge(-0.5, 0, 0.5, 0, test_mesh);
    ASSERT_NE(he, GT<Mesh>::null_halfedge());
    const auto eno = opposite(next(he, test_mesh), test_mesh);
    const auto ep_prime = prev(opposite(he, test_mesh), test_mesh);
    const auto eno_prime = opposite(next(opposite(he, test_mesh), test_mesh), test_mesh);
    const auto v1 = target(he, test_mesh);
    ASSERT_EQ(CGAL::Euler::collapse_edge(edge(he, test_mesh), test_mesh), v1);
    if (with_ep_prime)
      EXPECT_EQ(count_around_target(v1, test_mesh, {eno, eno_prime, ep_prime}), 3);
    else
      EXPECT_EQ(count_around_target(v1, test_mesh, {eno, eno_prime}), 2);
    CGAL::clear(test_mesh);
  };

  {
    SCOPED_TRACE("case 1: general case");
    collapse_and_check(false);
  }
  {
    SCOPED_TRACE("case 2: not a border, next to a border edge that is removed");
    CGAL::copy_face_graph(m, test_mesh);
    CGAL::Euler::remove_face(find_halfedge(0, 0.5, -0.75, 0.5, test_mesh), test_mesh);
    collapse_and_check(false);
  }
  {
    SCOPED_TRACE("case 3: not a border, next to a border edge that is not removed");
    CGAL::copy_face_graph(m, test_mesh);
    CGAL::Euler::remove_face(find_halfedge(1.5, 0, 0.75, 0.5, test_mesh), test_mesh);
    collapse_and_check(false);
  }
  {
    SCOPED_TRACE("case 4: a border edge");
    CGAL::copy_face_graph(m, test_mesh);
    CGAL::Euler::remove_face(find_halfedge(-0.5, 0, 0, -0.5, test_mesh), test_mesh);
    CGAL::Euler::remove_face(find_halfedge(0, -0.5, -0.5, 0, test_mesh), test_mesh);
    CGAL::Euler::remove_face(find_halfedge(0, -0.5, 0.75, -0.5, test_mesh), test_mesh);
    collapse_and_check(true);
  }
  {
    SCOPED_TRACE("case 5: the singular case");
    CGAL::copy_face_graph(m, test_mesh);
    CGAL::Euler::remove_face(find_halfedge(0.75, 0.5, 1.5, 0, test_mesh), test_mesh);
    CGAL::Euler::remove_face(find_halfedge(0.75, -0.5, 1.5, 0, test_mesh), test_mesh);
    CGAL::Euler::remove_face(find_halfedge(0, 0.5, 0.5, 0, test_mesh), test_mesh);
    CGAL::Euler::remove_face(find_halfedge(0.5, 0, 0, -0.5, test_mesh), test_mesh);
    const auto he = find_halfedge(-0.5, 0, 0.5, 0, test_mesh);
    CGAL::Euler::remove_face(he, test_mesh);
    const auto ep = prev(he, test_mesh);
    const auto eno_prime = opposite(next(opposite(he, test_mesh), test_mesh), test_mesh);
    const auto v1 = target(he, test_mesh);
    ASSERT_EQ(CGAL::Euler::collapse_edge(edge(he, test_mesh), test_mesh), v1);
    EXPECT_EQ(count_around_target(v1, test_mesh, {ep, eno_prime}), 2);
    CGAL::clear(test_mesh);
  }
}

// ============================================================================
// test_Face_filtered_graph.cpp
// ============================================================================

template <class T>
class CgalBglFaceFilteredGraph : public ::testing::Test
{};
TYPED_TEST_SUITE(CgalBglFaceFilteredGraph, Meshes, Mesh_names);

// The adapter of the original: the faces of g's connected component 0.
template <class Graph>
struct Component_zero
{
  using face_descriptor = typename GT<Graph>::face_descriptor;
  std::map<face_descriptor, std::size_t> ids;
  CGAL::Face_filtered_graph<Graph> fg;

  explicit Component_zero(const Graph& g, long component = 0) : fg(g)
  {
    PMP::connected_components(g, boost::make_assoc_property_map(ids));
    fg.set_selected_faces(std::size_t(component), boost::make_assoc_property_map(ids));
  }
};

template <class Mesh, class Check>
void for_each_filtered_prefix_mesh(Check check)
{
  const std::vector<Mesh> meshes = t_data<Mesh>();
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SCOPED_TRACE(prefix_files()[i]);
    Component_zero<Mesh> c(meshes[i]);
    check(meshes[i], c.fg);
  }
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_halfedge_around_vertex_iterator()
TYPED_TEST(CgalBglFaceFilteredGraph, test_halfedge_around_vertex_iterator)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam&, const auto& fg) {
    for (auto v : vertices(fg)) {
      auto [it, end] = CGAL::halfedges_around_target(halfedge(v, fg), fg);
      for (; it != end; ++it) {
        ASSERT_EQ(target(*it, fg), v);
        auto step = std::next(it);
        if (step != end) {
          ASSERT_EQ(*step, opposite(next(*it, fg), fg));
        }
      }
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_halfedge_around_face_iterator()
TYPED_TEST(CgalBglFaceFilteredGraph, test_halfedge_around_face_iterator)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam&, const auto& fg) {
    for (auto f : faces(fg)) {
      auto [it, end] = CGAL::halfedges_around_face(halfedge(f, fg), fg);
      ASSERT_NE(std::distance(it, end), 0);
      for (; it != end; ++it)
        ASSERT_EQ(face(*it, fg), f);
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_edge_iterators()
TYPED_TEST(CgalBglFaceFilteredGraph, test_edge_iterators)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam& g, const auto& fg) {
    auto [eb, ee] = edges(fg);
    ASSERT_EQ(std::size_t(std::distance(eb, ee)), std::size_t(num_edges(g)));
    id_set ids;
    std::size_t count = 0;
    for (auto e : edges(fg)) {
      ASSERT_TRUE(ids.insert(get(boost::edge_index, g, e)).second);
      ++count;
    }
    ASSERT_EQ(count, std::size_t(num_edges(fg)));
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_vertex_iterators()
TYPED_TEST(CgalBglFaceFilteredGraph, test_vertex_iterators)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam& g, const auto& fg) {
    std::size_t count = 0;
    for (auto v : vertices(fg)) {
      (void)v;
      ++count;
    }
    ASSERT_EQ(count, std::size_t(num_vertices(fg)));
    id_set ids;
    count = 0;
    for (auto v : vertices(fg)) {
      ASSERT_TRUE(ids.insert(get(boost::vertex_index, g, v)).second);
      ++count;
    }
    ASSERT_EQ(count, std::size_t(num_vertices(fg)));
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_out_edges()
TYPED_TEST(CgalBglFaceFilteredGraph, test_out_edges)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam& g, const auto& fg) {
    for (auto around : vertices(fg)) {
      id_set v_ids;
      auto [it, end] = out_edges(around, fg);
      for (; it != end; ++it) {
        const auto t = target(*it, fg), s = source(*it, fg);
        ASSERT_NE(s, t);
        ASSERT_EQ(s, around);
        ASSERT_NE(t, around);
        ASSERT_TRUE(v_ids.insert(get(boost::vertex_index, g, t)).second);
      }
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_in_edges()
TYPED_TEST(CgalBglFaceFilteredGraph, test_in_edges)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam& g, const auto& fg) {
    for (auto around : vertices(fg)) {
      id_set v_ids;
      auto [it, end] = in_edges(around, fg);
      for (; it != end; ++it) {
        const auto t = target(*it, fg), s = source(*it, fg);
        ASSERT_EQ(t, around);
        ASSERT_NE(s, around);
        ASSERT_TRUE(v_ids.insert(get(boost::vertex_index, g, s)).second);
      }
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_in_out_edges()
TYPED_TEST(CgalBglFaceFilteredGraph, test_in_out_edges)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam&, const auto& fg) { check_in_out_edges(fg); });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_edge_find()
TYPED_TEST(CgalBglFaceFilteredGraph, test_edge_find)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam&, const auto& fg) {
    for (auto e : edges(fg)) {
      const auto s = source(e, fg), t = target(e, fg);
      const auto found = edge(s, t, fg), found2 = edge(t, s, fg);
      ASSERT_TRUE(found.second);
      ASSERT_TRUE(found2.second);
      ASSERT_EQ(found.first, e);
      ASSERT_EQ(found2.first, e);
    }
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_faces()
TYPED_TEST(CgalBglFaceFilteredGraph, test_faces)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam&, const auto& fg) {
    std::size_t count = 0;
    for (auto f : faces(fg)) {
      ++count;
      ASSERT_EQ(face(halfedge(f, fg), fg), f);
      for (auto h : CGAL::halfedges_around_face(halfedge(f, fg), fg))
        ASSERT_EQ(face(h, fg), f);
    }
    ASSERT_EQ(count, std::size_t(num_faces(fg)));
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_read()
TYPED_TEST(CgalBglFaceFilteredGraph, test_read)
{
  for_each_filtered_prefix_mesh<TypeParam>([](const TypeParam&, const auto& fg) {
    ASSERT_TRUE(fg.is_selection_valid());
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(fg));
  });
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_index_property_maps()
TYPED_TEST(CgalBglFaceFilteredGraph, test_index_property_maps)
{
  using Adapter = CGAL::Face_filtered_graph<TypeParam>;
  const std::vector<TypeParam> meshes = t_data<TypeParam>();
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SCOPED_TRACE(prefix_files()[i]);
    const TypeParam& g = meshes[i];
    std::map<typename GT<TypeParam>::face_descriptor, std::size_t> map;
    PMP::connected_components(g, boost::make_assoc_property_map(map));
    Adapter fg(g, std::size_t(-1), boost::make_assoc_property_map(map));
    EXPECT_TRUE(CGAL::is_empty(fg));

    using CGAL::BGL::internal::is_index_map_valid;
    auto vim = CGAL::get_initialized_vertex_index_map(fg);
    EXPECT_TRUE(is_index_map_valid(vim, num_vertices(fg), vertices(fg)));
    auto him = CGAL::get_initialized_halfedge_index_map(fg);
    EXPECT_TRUE(is_index_map_valid(him, num_halfedges(fg), halfedges(fg)));
    auto fim = CGAL::get_initialized_face_index_map(fg);
    EXPECT_TRUE(is_index_map_valid(fim, num_faces(fg), faces(fg)));

    fg.set_selected_faces(0, boost::make_assoc_property_map(map));
    EXPECT_FALSE(CGAL::is_empty(fg));
    EXPECT_TRUE(is_index_map_valid(vim, num_vertices(fg), vertices(fg)));
    EXPECT_TRUE(is_index_map_valid(him, num_halfedges(fg), halfedges(fg)));
    EXPECT_TRUE(is_index_map_valid(fim, num_faces(fg), faces(fg)));

    const Adapter cfg(g, 0, boost::make_assoc_property_map(map));
    auto cvim = CGAL::get_initialized_vertex_index_map(cfg);
    EXPECT_TRUE(is_index_map_valid(cvim, num_vertices(cfg), vertices(cfg)));
    auto chim = CGAL::get_initialized_halfedge_index_map(cfg);
    EXPECT_TRUE(is_index_map_valid(chim, num_halfedges(cfg), halfedges(cfg)));
    auto cfim = CGAL::get_initialized_face_index_map(cfg);
    EXPECT_TRUE(is_index_map_valid(cfim, num_faces(cfg), faces(cfg)));
  }
}

// merge_vertices() of the original: v_rm's fan moved to v_keep, v_rm
// removed; the faces around both are collected.
template <class Mesh>
void merge_vertices(typename GT<Mesh>::vertex_descriptor v_keep, typename GT<Mesh>::vertex_descriptor v_rm,
                    std::vector<typename GT<Mesh>::face_descriptor>& incident_faces, Mesh& mesh)
{
  auto oh = halfedge(v_keep, mesh);
  const auto done = oh;
  do {
    incident_faces.push_back(face(oh, mesh));
    oh = opposite(next(oh, mesh), mesh);
  } while (oh != done);
  auto h = halfedge(v_rm, mesh);
  const auto start = h;
  do {
    set_target(h, v_keep, mesh);
    incident_faces.push_back(face(h, mesh));
    h = opposite(next(h, mesh), mesh);
  } while (h != start);
  remove_vertex(v_rm, mesh);
}

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_invalid_selections()
// (genus3.off and its vertices 1337 and 87 replaced by 3torus.off and two of
// its vertices that share no face). The stored copy of the original also
// selects faces 1, 2, 3 of 7_faces_triangle.off, a vertex pinched between
// two selected faces, and expects is_selection_valid() to be false: that
// check comes from a later CGAL, whose is_selection_valid() sees pinched
// vertices; CGAL 5.5.1's does not (it counts the halfedges beside the
// selection as part of it), on Surface_mesh as on Mobius_mesh, so it is
// left out here.
TYPED_TEST(CgalBglFaceFilteredGraph, test_invalid_selections)
{
  using Mesh = TypeParam;
  using face_descriptor = typename GT<Mesh>::face_descriptor;
  using vertex_descriptor = typename GT<Mesh>::vertex_descriptor;
  Mesh mesh;
  std::vector<face_descriptor> face_range;

  // a non-manifold vertex (several umbrellas)
  ASSERT_TRUE(read_a_mesh(mesh, "meshes/3torus.off"));
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  const vertex_descriptor v_keep = *vertices(mesh).begin();
  std::set<vertex_descriptor> near;
  for (auto f : CGAL::faces_around_target(halfedge(v_keep, mesh), mesh))
    for (auto w : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      near.insert(w);
  vertex_descriptor v_rm = GT<Mesh>::null_vertex();
  for (auto w : vertices(mesh))
    if (!near.count(w)) {
      v_rm = w;
      break;
    }
  ASSERT_NE(v_rm, GT<Mesh>::null_vertex());
  face_range.clear();
  merge_vertices(v_keep, v_rm, face_range, mesh);
  CGAL::Face_filtered_graph<Mesh> bad_fg_2(mesh, face_range);
  EXPECT_FALSE(bad_fg_2.is_selection_valid());
}

// The original's Constraint map: the edges among (1,1,1), (0,0,0), (0,0,1)
// and (1,0,1) that split the tetrahedron into single faces but two.
template <class Mesh>
struct Constraint
{
  using key_type = typename GT<Mesh>::edge_descriptor;
  using value_type = bool;
  using reference = bool;
  using category = boost::readable_property_map_tag;
  const Mesh* g = nullptr;

  friend bool get(const Constraint& c, const key_type& e)
  {
    const auto pm = get(CGAL::vertex_point, *c.g);
    const Point_3 &s = get(pm, source(e, *c.g)), &t = get(pm, target(e, *c.g));
    auto is = [&](const Point_3& a, const Point_3& b) { return (s == a || t == a) && (s == b || t == b); };
    const Point_3 p111(1, 1, 1), p000(0, 0, 0), p001(0, 0, 1), p101(1, 0, 1);
    return is(p111, p000) || is(p111, p001) || is(p001, p000) || is(p101, p000) || is(p111, p101);
  }
};

// CGAL 5.5 BGL/test/BGL/test_Face_filtered_graph.cpp, test_mesh() on the
// tetrahedron of main(): patches 0 and 2 of its constrained components
TYPED_TEST(CgalBglFaceFilteredGraph, test_mesh)
{
  using Mesh = TypeParam;
  Mesh sm;
  CGAL::make_tetrahedron(Point_3(1, 1, 1), Point_3(0, 0, 0), Point_3(0, 0, 1), Point_3(1, 0, 1), sm);
  auto fccmap = get(CGAL::dynamic_face_property_t<std::size_t>(), sm);
  PMP::connected_components(sm, fccmap, CGAL::parameters::edge_is_constrained_map(Constraint<Mesh>{&sm}));
  boost::unordered_set<std::size_t> pids = {0, 2};
  CGAL::Face_filtered_graph<Mesh> fga(sm, pids, fccmap);

  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(fga));
  EXPECT_EQ(num_faces(fga), 2u);
  EXPECT_EQ(num_edges(fga), 5u);
  EXPECT_EQ(num_halfedges(fga), 10u);
  EXPECT_EQ(num_vertices(fga), 4u);
  auto h = halfedge(*faces(fga).first, fga);
  const auto v = source(h, fga);
  // next() inside the patch and on its border
  EXPECT_EQ(next(next(next(h, fga), fga), fga), h);
  h = opposite(h, fga);
  EXPECT_EQ(next(next(next(next(h, fga), fga), fga), fga), h);
  // prev() inside the patch and on its border
  h = halfedge(*faces(fga).first, fga);
  EXPECT_EQ(prev(prev(prev(h, fga), fga), fga), h);
  h = opposite(h, fga);
  EXPECT_EQ(prev(prev(prev(prev(h, fga), fga), fga), fga), h);
  EXPECT_EQ(degree(v, fga), 3u);
  EXPECT_EQ(std::distance(in_edges(v, fga).first, in_edges(v, fga).second), 3);
  EXPECT_EQ(std::distance(out_edges(v, fga).first, out_edges(v, fga).second), 3);

  Mesh copy;
  CGAL::copy_face_graph(fga, copy);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(copy));
  EXPECT_EQ(CGAL::internal::exact_num_faces(copy), 2u);
}

} // namespace
} // namespace cgal_bgl_suite
