// Topology of a Mobius_mesh (Mobius_mesh/topology.h): orient() on meshes
// whose faces were reversed at random (an orientable one comes back as built
// or all reversed, a one-sided one keeps its topology), connected components
// and orientable components of joined meshes, against the test meshes in
// test/data/nonorientable as an outside reference.

#include "test_util.h"
#include "topology_checks.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace topology_tests {

namespace {

using namespace topology_checks;
namespace X = CGAL_ext;
using Kd_mesh = X::Mobius_mesh<test::Kd::Point_3>;
using Epeck_mesh = X::Mobius_mesh<test::Epeck::Point_3>;

// Reverses each face with probability 1/2; returns how many were reversed.
template <class Mesh>
std::size_t reverse_random_faces(Mesh& m, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  std::size_t n = 0;
  for (X::Face_index f : m.faces())
    if (rng() & 1u) {
      m.reverse_face_orientation(f);
      ++n;
    }
  return n;
}

// Orientable meshes: after random reversals, orient() must undo them all,
// leaving each face as built or each face reversed.
template <class Mesh>
void check_orient_restores(Mesh m, std::uint32_t seed)
{
  ASSERT_TRUE(X::is_orientable(m));
  const auto original = face_cycles(m);
  const std::size_t V = m.number_of_vertices(), E = m.number_of_edges(), F = m.number_of_faces();
  const std::size_t loops = X::number_of_border_cycles(m);
  const std::size_t reversed = reverse_random_faces(m, seed);
  ASSERT_GT(reversed, 0u);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_GT(X::number_of_mobius_edges(m), 0u);
  EXPECT_EQ(X::number_of_mobius_edges(m), same_direction_edges(m));
  EXPECT_TRUE(X::is_orientable(m));

  EXPECT_EQ(X::orient(m), 0u);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(X::number_of_mobius_edges(m), 0u);
  EXPECT_EQ(same_direction_edges(m), 0u);
  EXPECT_EQ(m.number_of_vertices(), V);
  EXPECT_EQ(m.number_of_edges(), E);
  EXPECT_EQ(m.number_of_faces(), F);
  EXPECT_EQ(X::number_of_border_cycles(m), loops);
  const auto now = face_cycles(m);
  std::size_t as_built = 0, turned = 0;
  for (std::size_t f = 0; f < F; ++f) {
    as_built += same_cycle(original[f], now[f]) ? 1 : 0;
    turned += reversed_cycle(original[f], now[f]) ? 1 : 0;
  }
  EXPECT_TRUE(as_built == F || turned == F) << as_built << " as built, " << turned << " reversed";
}

TEST(Orientation, OrientableMeshesDouble)
{
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    Kd_mesh t;
    X::make_torus(t, 8, 5);
    check_orient_restores(t, seed);
    for (int twists : {0, 2, 4}) {
      Kd_mesh a;
      X::make_mobius_strip(a, 9, 3, twists, 1.0, 0.5, seed % 2 == 0);
      check_orient_restores(a, seed);
    }
    const std::vector<test::Kd::Point_3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const std::vector<std::array<std::size_t, 4>> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    Kd_mesh cube;
    X::polygon_soup_to_mobius_mesh(pts, quads, cube);
    expect_topology(cube, {8, 12, 6, 2, true, 0, true});
    check_orient_restores(cube, seed);
  }
}

TEST(Orientation, OrientableMeshesEpeck)
{
  Epeck_mesh t;
  X::make_torus(t, 6, 4);
  check_orient_restores(t, 7);
  Epeck_mesh a;
  X::make_mobius_strip(a, 6, 2, 2, 1.0, 0.5, false);
  check_orient_restores(a, 8);
}

// Non-orientable meshes keep their topology through random reversals, and
// orient() cannot remove every Möbius edge.
template <class Mesh>
void check_orient_keeps_one_sided(Mesh m, std::uint32_t seed)
{
  const std::size_t V = m.number_of_vertices(), E = m.number_of_edges(), F = m.number_of_faces();
  const long long chi = X::euler_characteristic(m);
  const std::size_t loops = X::number_of_border_cycles(m);
  ASSERT_FALSE(X::is_orientable(m));
  ASSERT_GT(reverse_random_faces(m, seed), 0u);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(X::number_of_mobius_edges(m), same_direction_edges(m));
  EXPECT_FALSE(X::is_orientable(m));
  const std::size_t before = X::number_of_mobius_edges(m);

  const std::size_t left = X::orient(m);
  EXPECT_GE(left, 1u);
  EXPECT_LE(left, before);
  EXPECT_EQ(left, X::number_of_mobius_edges(m));
  EXPECT_EQ(left, same_direction_edges(m));
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_FALSE(X::is_orientable(m));
  EXPECT_EQ(m.number_of_vertices(), V);
  EXPECT_EQ(m.number_of_edges(), E);
  EXPECT_EQ(m.number_of_faces(), F);
  EXPECT_EQ(X::euler_characteristic(m), chi);
  EXPECT_EQ(X::number_of_border_cycles(m), loops);
}

TEST(Orientation, NonOrientableGenerated)
{
  for (std::uint32_t seed : {11u, 12u}) {
    for (int twists : {1, 3}) {
      for (bool quads : {true, false}) {
        Kd_mesh m;
        X::make_mobius_strip(m, 10, 3, twists, 1.0, 0.5, quads);
        SCOPED_TRACE("Möbius strip, twists " + std::to_string(twists));
        check_orient_keeps_one_sided(m, seed);
      }
    }
    Kd_mesh k;
    X::make_klein_bottle(k, 12, 6);
    check_orient_keeps_one_sided(k, seed);
    Kd_mesh p;
    X::make_projective_plane(p, 3);
    check_orient_keeps_one_sided(p, seed);
  }
  Epeck_mesh e;
  X::make_mobius_strip(e, 8, 2, 3);
  check_orient_keeps_one_sided(e, 5);
}

TEST(Orientation, TestMeshes)
{
  for (const std::string& file : nonorientable_files) {
    SCOPED_TRACE(file);
    const Obj obj = read_obj(test::data("nonorientable/" + file));
    const Expected x = expected_from_header(obj);
    Kd_mesh m;
    X::polygon_soup_to_mobius_mesh(obj.points, obj.polygons, m);
    expect_topology(m, x);
    EXPECT_EQ(X::number_of_mobius_edges(m), same_direction_edges(m));
    for (std::uint32_t seed : {21u, 22u}) {
      if (x.orientable)
        check_orient_restores(m, seed);
      else
        check_orient_keeps_one_sided(m, seed);
    }
  }
}

TEST(Orientation, JoinedTorusAndMobiusStrip)
{
  Kd_mesh m;
  X::make_torus(m, 7, 4);
  const std::size_t torus_edges = m.number_of_edges(), torus_faces = m.number_of_faces();
  Kd_mesh strip;
  X::make_mobius_strip(strip, 9, 2, 1);
  const auto off = m.join(strip);
  EXPECT_EQ(off.edges, torus_edges);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(X::orientable_components(m), (std::vector<bool>{true, false}));
  EXPECT_FALSE(X::is_orientable(m));

  const X::Mesh_components cc = X::connected_components(m);
  ASSERT_EQ(cc.count, 2u);
  for (X::Vertex_index v : m.vertices())
    EXPECT_EQ(cc.vertex_component[v.idx()], v.idx() < off.vertices ? 0u : 1u);
  for (X::Face_index f : m.faces())
    EXPECT_EQ(cc.face_component[f.idx()], f.idx() < off.faces ? 0u : 1u);

  reverse_random_faces(m, 31);
  EXPECT_GE(X::orient(m), 1u);
  EXPECT_TRUE(m.is_valid(true));
  std::size_t on_torus = 0;
  for (X::Edge_index e : m.edges())
    if (e.idx() < torus_edges && m.is_mobius(e))
      ++on_torus;
  EXPECT_EQ(on_torus, 0u);
  // Torus faces consistent with each other, read from their vertex cycles.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  const auto cycles = face_cycles(m);
  for (std::size_t f = 0; f < torus_faces; ++f)
    for (std::size_t i = 0; i < cycles[f].size(); ++i)
      EXPECT_EQ(++directed[std::make_pair(cycles[f][i], cycles[f][(i + 1) % cycles[f].size()])], 1);
}

TEST(Orientation, ComponentsOfJoinedMeshes)
{
  Kd_mesh parts[4];
  X::make_projective_plane(parts[0], 2);
  X::make_torus(parts[1], 4, 3);
  X::make_mobius_strip(parts[2], 5, 1, 2); // annulus
  X::make_klein_bottle(parts[3], 3, 4);
  Kd_mesh m;
  std::vector<std::uint32_t> first_vertex;
  for (const Kd_mesh& p : parts) {
    first_vertex.push_back(m.number_of_vertices());
    m.join(p);
  }
  first_vertex.push_back(m.number_of_vertices());
  m.add_vertex(test::Kd::Point_3(9, 9, 9)); // isolated: a component without faces
  ASSERT_TRUE(m.is_valid(true));
  const X::Mesh_components cc = X::connected_components(m);
  EXPECT_EQ(cc.count, 5u);
  for (std::size_t p = 0; p < 4; ++p)
    for (std::uint32_t v = first_vertex[p]; v < first_vertex[p + 1]; ++v)
      EXPECT_EQ(cc.vertex_component[v], p);
  EXPECT_EQ(cc.vertex_component.back(), 4u);
  EXPECT_EQ(X::orientable_components(m), (std::vector<bool>{false, true, true, false}));
  EXPECT_EQ(X::euler_characteristic(m), 1 + 0 + 0 + 0 + 1);
  EXPECT_EQ(X::number_of_border_cycles(m), 2u);
}

} // namespace

} // namespace topology_tests
