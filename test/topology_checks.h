// What the generator and topology tests check a mesh against: the counts
// and invariants it should have, its faces' vertex cycles, its faces by their
// points (equal up to orientation and numbering), and the test meshes
// in test/data/nonorientable with the figures their first line states.
#ifndef CGAL_EXT_TEST_TOPOLOGY_CHECKS_H
#define CGAL_EXT_TEST_TOPOLOGY_CHECKS_H

#include "test_util.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace topology_checks {

namespace X = CGAL_ext;

// A point as a key that compares exactly.
using Key = std::tuple<double, double, double>;

template <class P>
Key key_of(const P& p)
{
  return Key(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// A face as the cycle of its corners' points, up to rotation and direction.
std::vector<Key> canonical_cycle(std::vector<Key> c)
{
  std::vector<Key> best;
  for (int pass = 0; pass < 2; ++pass) {
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    if (best.empty() || c < best)
      best = c;
    std::reverse(c.begin(), c.end());
  }
  return best;
}

// The mesh as a sorted list of faces by points: equal for two meshes that
// are the same surface up to face orientation and element numbering.
template <class P>
std::vector<std::vector<Key>> face_signature(const CGAL_ext::Mobius_mesh<P>& m)
{
  std::vector<std::vector<Key>> faces;
  for (X::Face_index f : m.faces()) {
    std::vector<Key> c;
    for (X::Vertex_index v : X::vertices_around_face(f, m))
      c.push_back(key_of(m.point(v)));
    faces.push_back(canonical_cycle(c));
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

struct Expected
{
  std::size_t V, E, F;
  long long chi;
  bool closed;
  std::size_t border_loops;
  bool orientable;
};

template <class Mesh>
void expect_topology(const Mesh& m, const Expected& x)
{
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), x.V);
  EXPECT_EQ(m.number_of_edges(), x.E);
  EXPECT_EQ(m.number_of_faces(), x.F);
  EXPECT_EQ(X::euler_characteristic(m), x.chi);
  EXPECT_EQ(X::is_closed(m), x.closed);
  EXPECT_EQ(X::number_of_border_cycles(m), x.border_loops);
  EXPECT_EQ(X::is_orientable(m), x.orientable);
  // Sides of faces: each interior edge is two sides, each border edge one.
  std::size_t sides = 0, border_edges = 0;
  for (X::Face_index f : m.faces())
    sides += m.degree(f);
  for (X::Edge_index e : m.edges())
    border_edges += m.is_border(e) ? 1 : 0;
  EXPECT_EQ(sides, 2 * m.number_of_edges() - border_edges);
}

// ---------------------------------------------------------------- face cycles

template <class Mesh>
std::vector<std::vector<std::uint32_t>> face_cycles(const Mesh& m)
{
  std::vector<std::vector<std::uint32_t>> cycles;
  for (X::Face_index f : m.faces()) {
    std::vector<std::uint32_t> c;
    for (X::Vertex_index v : vertices_around_face(f, m))
      c.push_back(v.idx());
    cycles.push_back(c);
  }
  return cycles;
}

inline bool same_cycle(const std::vector<std::uint32_t>& a, std::vector<std::uint32_t> b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t r = 0; r < b.size(); ++r) {
    if (a == b)
      return true;
    std::rotate(b.begin(), b.begin() + 1, b.end());
  }
  return false;
}

inline bool reversed_cycle(const std::vector<std::uint32_t>& a, std::vector<std::uint32_t> b)
{
  std::reverse(b.begin(), b.end());
  return same_cycle(a, b);
}

// Edges whose two faces run along them the same way, read from the faces'
// vertex cycles alone (never from the Möbius bits).
template <class Mesh>
std::size_t same_direction_edges(const Mesh& m)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& c : face_cycles(m))
    for (std::size_t i = 0; i < c.size(); ++i)
      ++directed[{c[i], c[(i + 1) % c.size()]}];
  std::size_t n = 0;
  for (const auto& [pair, count] : directed) {
    EXPECT_LE(count, 2);
    n += count == 2 ? 1 : 0;
  }
  return n;
}

// ---------------------------------------------------------------- a small OBJ reader

struct Obj
{
  std::vector<test::Kd::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::map<std::string, std::string> header; // "key=value" fields of the first comment line
};

inline Obj read_obj(const std::string& file)
{
  Obj obj;
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (first && tag == "#") {
      std::string field;
      while (ls >> field)
        if (const auto eq = field.find('='); eq != std::string::npos)
          obj.header[field.substr(0, eq)] = field.substr(eq + 1);
    } else if (tag == "v") {
      double x, y, z;
      ls >> x >> y >> z;
      obj.points.emplace_back(x, y, z);
    } else if (tag == "f") {
      std::vector<std::size_t> polygon;
      std::string corner;
      while (ls >> corner)
        polygon.push_back(std::stoul(corner.substr(0, corner.find('/'))) - 1);
      obj.polygons.push_back(polygon);
    }
    first = false;
  }
  return obj;
}

inline Expected expected_from_header(const Obj& obj)
{
  const auto& h = obj.header;
  const auto n = [&](const char* key) { return std::size_t(std::stoul(h.at(key))); };
  const std::size_t loops = n("boundary_loops");
  return {n("V"), n("E"), n("F"), std::stoll(h.at("chi")), loops == 0, loops, h.at("orientable") == "True"};
}

inline const std::vector<std::string> nonorientable_files = {
  "mobius_20x4_quads.obj",  "mobius_20x4_tris.obj",    "mobius_min_5tris.obj", "klein_fig8_24x12_quads.obj",
  "boys_surface_quads.obj", "rp2_hemi_icosahedron.obj", "torus_24x12_quads.obj"};

} // namespace topology_checks

#endif
