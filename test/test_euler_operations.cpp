// Editing a Mobius_mesh: removal and garbage collection, and the Euler
// operations on darts. References: the counts each operation's contract gives
// (vertices, edges, faces, border loops), Euler characteristic and
// orientability (which no Euler operation changes, and filling or punching a
// hole changes by a known amount), and CGAL::Euler on Surface_mesh, run on the
// same sequence of operations.

#include "test_util.h"
#include "topology_checks.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/merge_borders.h>
#include <CGAL_ext/offset_mesh.h>
#include <CGAL_ext/subdivision.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace editing_tests {

namespace {

using CGAL_ext::Dart;
using CGAL_ext::Edge_index;
using CGAL_ext::Face_index;
using CGAL_ext::Halfedge_index;
using CGAL_ext::Vertex_index;
namespace Euler = CGAL_ext::Euler;
using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using topology_checks::canonical_cycle;
using topology_checks::face_signature;
using topology_checks::Key;
using topology_checks::key_of;

std::vector<std::vector<Key>> face_signature(const CGAL::Surface_mesh<Point>& sm)
{
  std::vector<std::vector<Key>> faces;
  for (auto f : sm.faces()) {
    std::vector<Key> c;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
      c.push_back(key_of(sm.point(v)));
    faces.push_back(canonical_cycle(c));
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// The five-triangle Möbius band: triangles (i, i+1, i+2) mod 5, one border
// loop 0-2-4-1-3 of five edges; every vertex is on the seam.
template <class P>
CGAL_ext::Mobius_mesh<P> five_triangle_band(bool reverse_some = false)
{
  std::vector<P> points;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * CGAL_PI * i / 5;
    points.emplace_back(2 * std::cos(a), 2 * std::sin(a), 0.25 * i);
  }
  std::vector<std::vector<std::size_t>> triangles;
  for (std::size_t i = 0; i < 5; ++i) {
    std::vector<std::size_t> t{i, (i + 1) % 5, (i + 2) % 5};
    if (reverse_some && i % 2 == 1)
      std::reverse(t.begin(), t.end());
    triangles.push_back(t);
  }
  CGAL_ext::Mobius_mesh<P> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, triangles, m);
  return m;
}

// A hexagon fanned from its centre: seven vertices, six triangles.
Mesh hexagon_fan()
{
  std::vector<Point> points{Point(0, 0, 0)};
  for (int i = 0; i < 6; ++i)
    points.emplace_back(std::cos(CGAL_PI * i / 3), std::sin(CGAL_PI * i / 3), 0);
  std::vector<std::vector<std::size_t>> triangles;
  for (std::size_t i = 0; i < 6; ++i)
    triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, triangles, m);
  return m;
}

std::vector<Dart> all_darts(const Mesh& m)
{
  std::vector<Dart> darts;
  for (Halfedge_index h : m.halfedges())
    for (bool flipped : {false, true})
      darts.push_back(Dart(h, flipped));
  return darts;
}

struct Counts
{
  long long v, e, f, chi;
  std::size_t borders;
  bool orientable;
};

template <class P>
Counts counts(const CGAL_ext::Mobius_mesh<P>& m)
{
  return {m.number_of_vertices(), m.number_of_edges(), m.number_of_faces(), CGAL_ext::euler_characteristic(m),
          CGAL_ext::number_of_border_cycles(m), CGAL_ext::is_orientable(m)};
}

// The dart of `m` from the vertex at point `s` to the vertex at point `t`.
template <class P>
Dart dart_between(const CGAL_ext::Mobius_mesh<P>& m, const Key& s, const Key& t)
{
  for (Halfedge_index h : m.halfedges())
    for (bool flipped : {false, true}) {
      const Dart d(h, flipped);
      if (key_of(m.point(m.source(d))) == s && key_of(m.point(m.target(d))) == t)
        return d;
    }
  return Dart();
}

} // namespace

// ---------------------------------------------------------------- removal and garbage collection

TEST(Removal, RangesSkipRemovedElementsAndCountsExcludeThem)
{
  Mesh m = hexagon_fan();
  ASSERT_EQ(m.number_of_faces(), 6u);
  m.remove_face(Face_index(2u));
  m.remove_face(Face_index(2u)); // twice is once
  EXPECT_TRUE(m.has_garbage());
  EXPECT_TRUE(m.is_removed(Face_index(2u)));
  EXPECT_EQ(m.number_of_faces(), 5u);
  EXPECT_EQ(m.num_faces(), 6u);
  EXPECT_EQ(m.number_of_removed_faces(), 1u);
  EXPECT_EQ(m.faces().size(), 5u);
  std::vector<Face_index> seen(m.faces().begin(), m.faces().end());
  EXPECT_EQ(seen, (std::vector<Face_index>{Face_index(0u), Face_index(1u), Face_index(3u), Face_index(4u),
                                           Face_index(5u)}));
  // The face is still linked: the mesh says so.
  EXPECT_NE(m.validity_report().find("removed"), std::string::npos) << m.validity_report();

  m.remove_edge(Edge_index(0u));
  EXPECT_EQ(m.number_of_edges(), 11u);
  EXPECT_EQ(m.number_of_halfedges(), 22u);
  EXPECT_EQ(m.halfedges().size(), 22u);
  for (Halfedge_index h : m.halfedges())
    EXPECT_GE(h.idx(), 2u);

  // Copies and joins carry the marks.
  Mesh copy = m;
  EXPECT_EQ(copy.number_of_faces(), 5u);
  EXPECT_TRUE(copy.is_removed(Edge_index(0u)));
  Mesh joined = hexagon_fan();
  const auto off = joined.join(m);
  EXPECT_EQ(joined.number_of_faces(), 11u);
  EXPECT_TRUE(joined.is_removed(Face_index(off.faces + 2)));

  // Adding appends by default: removed slots are not reused before collect_garbage().
  const Vertex_index v = m.add_vertex(Point(5, 5, 5));
  EXPECT_EQ(v.idx(), 7u);
  // The flags are the mesh's own: they cannot be removed as a property map.
  auto flags = m.property_map<Face_index, bool>("f:removed");
  ASSERT_TRUE(flags.has_value());
  EXPECT_FALSE(m.remove_property_map(*flags));
}

TEST(Removal, RecyclingTakesBackTheLastRemovedSlotsWithDefaultValues)
{
  Mesh m = hexagon_fan();
  auto weight = m.add_property_map<Vertex_index, int>("v:weight", 7).first;
  auto mark = m.add_property_map<Halfedge_index, int>("h:mark", -1).first;
  weight[Vertex_index(3u)] = 42;
  mark[Halfedge_index(5u)] = 9;
  m.remove_vertex(Vertex_index(3u));
  m.remove_vertex(Vertex_index(5u));
  m.remove_edge(Edge_index(2u));
  m.remove_face(Face_index(4u));
  EXPECT_FALSE(m.does_recycle_garbage()); // appending is the default

  // A copy keeps the free slots and the choice.
  m.set_recycle_garbage(true);
  Mesh copy = m;
  EXPECT_TRUE(copy.does_recycle_garbage());
  for (Mesh* mesh : {&m, &copy}) {
    auto w = mesh->property_map<Vertex_index, int>("v:weight").value();
    auto hm = mesh->property_map<Halfedge_index, int>("h:mark").value();
    // Slots removed before recycling was turned on come back highest index
    // first: vertex 5, then vertex 3; then new slots are appended.
    EXPECT_EQ(mesh->add_vertex(Point(1, 2, 3)).idx(), 5u);
    const Vertex_index v = mesh->add_vertex(Point(4, 5, 6));
    EXPECT_EQ(v.idx(), 3u);
    EXPECT_FALSE(mesh->is_removed(v));
    EXPECT_EQ(w[v], 7); // the default again, not 42
    EXPECT_EQ(mesh->point(v), Point(4, 5, 6));
    EXPECT_EQ(mesh->add_vertex().idx(), 7u);
    EXPECT_EQ(mesh->number_of_removed_vertices(), 0u);

    const Edge_index e = mesh->add_edge(Vertex_index(0u), v);
    EXPECT_EQ(e.idx(), 2u);
    const Halfedge_index h0(4u), h1(5u);
    EXPECT_EQ(mesh->target(mesh->dart(h0)), Vertex_index(0u));
    EXPECT_EQ(mesh->target(mesh->dart(h1)), v);
    EXPECT_FALSE(mesh->next(mesh->dart(h0)).is_valid());
    EXPECT_FALSE(mesh->face(h1).is_valid());
    EXPECT_FALSE(mesh->is_mobius(e));
    EXPECT_EQ(hm[h1], -1);
    EXPECT_EQ(mesh->add_face_record(h0).idx(), 4u);
    EXPECT_FALSE(mesh->has_garbage());
    EXPECT_EQ(mesh->num_faces(), 6u);
  }

  // Slots removed while recycling come back last removed first.
  Mesh recycling = hexagon_fan();
  recycling.set_recycle_garbage(true);
  for (unsigned f : {1u, 4u, 2u})
    recycling.remove_face(Face_index(f));
  for (unsigned f : {2u, 4u, 1u})
    EXPECT_EQ(recycling.add_face_record().idx(), f);

  // A join lists the other's removed slots too; collect_garbage() empties the lists.
  Mesh joined = hexagon_fan(), other = hexagon_fan();
  other.remove_face(Face_index(1u));
  joined.set_recycle_garbage(true);
  const auto off = joined.join(other);
  EXPECT_EQ(joined.add_face_record().idx(), off.faces + 1);
  joined.remove_face(Face_index(0u));
  joined.collect_garbage();
  const std::size_t faces = joined.num_faces();
  EXPECT_EQ(joined.add_face_record().idx(), faces); // appended: no free slot left
}

TEST(GarbageCollection, CompactsArraysAndPropertyMapsFollowTheirElements)
{
  Mesh m;
  CGAL_ext::make_klein_bottle(m, 8, 6);
  auto vid = m.add_property_map<Vertex_index, int>("v:id", -1).first;
  auto hid = m.add_property_map<Halfedge_index, int>("h:id", -1).first;
  auto eid = m.add_property_map<Edge_index, double>("e:id", -1).first;
  auto fid = m.add_property_map<Face_index, bool>("f:odd", false).first;
  for (Vertex_index v : m.vertices()) vid[v] = int(v.idx());
  for (Halfedge_index h : m.halfedges()) hid[h] = int(h.idx());
  for (Edge_index e : m.edges()) eid[e] = 0.5 * e.idx();
  for (Face_index f : m.faces()) fid[f] = f.idx() % 2 == 1;

  // Edit: join faces and vertices here and there, so elements go all over.
  const Counts before = counts(m);
  std::mt19937 rng(7);
  for (int k = 0; k < 60; ++k) {
    const std::vector<Dart> darts = all_darts(m);
    const Dart d = darts[rng() % darts.size()];
    if (k % 2 == 0 && Euler::can_join_face(d, m))
      Euler::join_face(d, m);
    else if (Euler::does_satisfy_link_condition(d, m) && m.number_of_faces() > 20)
      Euler::collapse_edge(d, m);
  }
  ASSERT_TRUE(m.has_garbage());
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), before.chi);
  const auto signature = face_signature(m);

  std::map<int, Key> point_of_id;
  std::vector<std::pair<Halfedge_index, int>> halfedge_ids;
  std::vector<std::pair<Edge_index, double>> edge_ids;
  std::vector<std::pair<Face_index, bool>> face_flags;
  for (Vertex_index v : m.vertices()) point_of_id[vid[v]] = key_of(m.point(v));
  for (Halfedge_index h : m.halfedges()) halfedge_ids.push_back({h, hid[h]});
  for (Edge_index e : m.edges()) edge_ids.push_back({e, eid[e]});
  for (Face_index f : m.faces()) face_flags.push_back({f, fid[f]});
  const auto live_v = m.number_of_vertices(), live_e = m.number_of_edges(), live_f = m.number_of_faces();

  Mesh::Garbage_collection_maps maps;
  m.collect_garbage(maps);
  EXPECT_FALSE(m.has_garbage());
  EXPECT_EQ(m.num_vertices(), live_v);
  EXPECT_EQ(m.num_edges(), live_e);
  EXPECT_EQ(m.num_faces(), live_f);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(face_signature(m), signature);
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), before.chi);
  EXPECT_FALSE(CGAL_ext::is_orientable(m));
  for (const std::string& name : m.properties<Vertex_index>())
    EXPECT_NE(name, "v:removed");
  // Every map followed its elements: the point of the vertex with each id is unchanged.
  for (Vertex_index v : m.vertices())
    EXPECT_EQ(key_of(m.point(v)), point_of_id.at(vid[v]));
  for (const auto& [h, id] : halfedge_ids)
    EXPECT_EQ(hid[maps(h)], id);
  for (const auto& [e, id] : edge_ids)
    EXPECT_EQ(eid[maps(e)], id);
  for (const auto& [f, odd] : face_flags)
    EXPECT_EQ(fid[maps(f)], odd);
}

TEST(GarbageCollection, AlgorithmsThatNeedCompactIndicesRefuseGarbageAndCopiesKeepIt)
{
  Mesh m;
  CGAL_ext::make_klein_bottle(m, 6, 5);
  Euler::join_face(m.halfedge(Face_index(0u)), m);
  ASSERT_TRUE(m.has_garbage());
  const auto signature = face_signature(m);
  Mesh other = hexagon_fan(), out;
  CGAL::Surface_mesh<Point> sm;
  EXPECT_THROW(CGAL_ext::Subdivision::catmull_clark(m, CGAL_ext::parameters::number_of_iterations(1)),
               CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::to_surface_mesh(m, sm), CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::IO::write_polygon_mesh("never_written.obj", m), CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::merge_borders(other, m), CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::offset_mesh(m, 0.1, out), CGAL_ext::Parameter_error);
  EXPECT_EQ(face_signature(m), signature);

  // Copies keep the garbage, marks and all, to other point types too.
  CGAL_ext::Mobius_mesh<test::Epeck::Point_3> exact;
  CGAL_ext::copy_mesh(m, exact);
  EXPECT_EQ(exact.number_of_faces(), m.number_of_faces());
  EXPECT_EQ(exact.number_of_removed_faces(), 1u);
  EXPECT_TRUE(exact.is_valid(true));
  exact.collect_garbage();
  m.collect_garbage();
  EXPECT_EQ(face_signature(exact), face_signature(m));
  EXPECT_NO_THROW(CGAL_ext::Subdivision::catmull_clark(m, CGAL_ext::parameters::number_of_iterations(1)));
}

// ---------------------------------------------------------------- each operation on every dart

// Applies `op` to a copy of `m` at every dart where `can` allows it and
// checks the result with `check(before, after, d, result)`.
template <class Can, class Op, class Check>
int on_every_dart(const Mesh& m, Can can, Op op, Check check)
{
  int applied = 0;
  for (Dart d : all_darts(m)) {
    if (!can(m, d))
      continue;
    Mesh e = m;
    const auto result = op(e, d);
    EXPECT_TRUE(e.is_valid(true)) << d;
    check(m, e, d, result);
    ++applied;
  }
  return applied;
}

class EulerOnEveryDart : public ::testing::TestWithParam<int>
{
protected:
  Mesh mesh() const
  {
    switch (GetParam()) {
    case 0: return five_triangle_band<Point>();
    case 1: return hexagon_fan();
    default: {
      Mesh k;
      CGAL_ext::make_klein_bottle(k, 4, 4);
      return k;
    }
    }
  }
};

TEST_P(EulerOnEveryDart, SplitAndJoinEdgesAndFaces)
{
  const Mesh m = mesh();
  const Counts c = counts(m);
  auto same_surface = [&](const Mesh& e) {
    const Counts a = counts(e);
    EXPECT_EQ(a.chi, c.chi);
    EXPECT_EQ(a.borders, c.borders);
    EXPECT_EQ(a.orientable, c.orientable);
  };
  const int split_edges = on_every_dart(
    m, [](const Mesh&, Dart) { return true; }, [](Mesh& e, Dart d) { return Euler::split_edge(d, e); },
    [&](const Mesh& b, const Mesh& e, Dart d, Dart n) {
      same_surface(e);
      EXPECT_EQ(e.number_of_vertices(), b.number_of_vertices() + 1);
      EXPECT_EQ(e.number_of_edges(), b.number_of_edges() + 1);
      EXPECT_EQ(e.source(n), b.source(d));
      EXPECT_EQ(e.target(n), Vertex_index(b.num_vertices()));
      EXPECT_EQ(e.next(n).halfedge(), d.halfedge());
      EXPECT_EQ(e.target(e.next(n)), b.target(d));
    });
  EXPECT_EQ(split_edges, int(2 * m.number_of_halfedges()));

  on_every_dart(
    m, [](const Mesh& b, Dart d) { return Euler::can_join_face(d, b); },
    [](Mesh& e, Dart d) { return Euler::join_face(d, e); },
    [&](const Mesh& b, const Mesh& e, Dart d, Dart r) {
      same_surface(e);
      EXPECT_EQ(e.number_of_edges(), b.number_of_edges() - 1);
      EXPECT_EQ(e.number_of_faces(), b.number_of_faces() - 1);
      EXPECT_EQ(e.degree(e.face(r)), b.degree(b.face(d)) + b.degree(b.face(b.opposite(d))) - 2);
    });

  // Split a quad or larger face between opposite corners; triangles first get a split edge.
  on_every_dart(
    m, [](const Mesh& b, Dart d) { return !b.is_border(d); },
    [](Mesh& e, Dart d) {
      if (e.degree(e.face(d)) == 3)
        Euler::split_edge(e.next(d), e);
      const Dart g = e.next(e.next(d));
      if (!Euler::can_split_face(d, g, e)) // the corners are joined elsewhere already
        return std::make_pair(Dart(), Vertex_index());
      const Vertex_index corner = e.target(g); // before the split (argument order is unspecified)
      return std::make_pair(Euler::split_face(d, g, e), corner);
    },
    [&](const Mesh& b, const Mesh& e, Dart, std::pair<Dart, Vertex_index> r) {
      if (!r.first.is_valid())
        return;
      same_surface(e);
      EXPECT_EQ(e.number_of_faces(), b.number_of_faces() + 1);
      EXPECT_EQ(e.target(r.first), r.second);
      EXPECT_EQ(e.degree(e.face(r.first)) + e.degree(e.face(e.opposite(r.first))), 3u + 3u);
    });
}

TEST_P(EulerOnEveryDart, VertexOperations)
{
  const Mesh m = mesh();
  const Counts c = counts(m);
  auto same_surface = [&](const Mesh& e) {
    const Counts a = counts(e);
    EXPECT_EQ(a.chi, c.chi);
    EXPECT_EQ(a.borders, c.borders);
    EXPECT_EQ(a.orientable, c.orientable);
  };
  // add_center_vertex then remove_center_vertex gives the mesh back.
  on_every_dart(
    m, [](const Mesh& b, Dart d) { return !b.is_border(d); },
    [](Mesh& e, Dart d) {
      const Dart n = Euler::add_center_vertex(d, e);
      e.point(e.target(n)) = Point(9, 9, 9);
      return n;
    },
    [&](const Mesh& b, const Mesh& e, Dart d, Dart n) {
      same_surface(e);
      const auto k = b.degree(b.face(d));
      EXPECT_EQ(e.degree(e.target(n)), k);
      EXPECT_EQ(e.number_of_faces(), b.number_of_faces() + k - 1);
      Mesh back = e;
      ASSERT_TRUE(Euler::can_remove_center_vertex(n, back));
      Euler::remove_center_vertex(n, back);
      EXPECT_TRUE(back.is_valid(true));
      EXPECT_EQ(face_signature(back), face_signature(b));
    });

  // split_vertex then join_vertex gives the mesh back.
  on_every_dart(
    m,
    [](const Mesh& b, Dart d) {
      return b.degree(b.target(d)) >= 4 && !b.is_border(d);
    },
    [](Mesh& e, Dart h1) {
      const Dart h2 = e.opposite(e.next(e.opposite(e.next(h1))));
      const Dart x = Euler::split_vertex(h1, h2, e);
      e.point(e.source(x)) = Point(9, 9, 9);
      return x;
    },
    [&](const Mesh& b, const Mesh& e, Dart h1, Dart x) {
      same_surface(e);
      EXPECT_EQ(e.number_of_vertices(), b.number_of_vertices() + 1);
      EXPECT_EQ(e.target(x), b.target(h1));
      EXPECT_EQ(e.degree(e.source(x)) + e.degree(e.target(x)), b.degree(b.target(h1)) + 2);
      Mesh back = e;
      if (Euler::can_join_vertex(x, back)) {
        Euler::join_vertex(x, back);
        EXPECT_TRUE(back.is_valid(true));
        EXPECT_EQ(face_signature(back), face_signature(b));
      }
    });
}

TEST_P(EulerOnEveryDart, CollapseRemoveAndFill)
{
  const Mesh m = mesh();
  const Counts c = counts(m);
  on_every_dart(
    m, [](const Mesh& b, Dart d) { return Euler::does_satisfy_link_condition(d, b); },
    [](Mesh& e, Dart d) { return Euler::collapse_edge(d, e); },
    [&](const Mesh& b, const Mesh& e, Dart d, Vertex_index kept) {
      const Counts a = counts(e);
      EXPECT_EQ(a.chi, c.chi);
      EXPECT_EQ(a.orientable, c.orientable);
      EXPECT_EQ(kept, b.target(d));
      EXPECT_TRUE(e.is_removed(b.source(d)));
      std::size_t triangles = 0;
      for (Dart side : {d, b.opposite(d)})
        triangles += !b.is_border(side) && b.degree(b.face(side)) == 3;
      EXPECT_EQ(e.number_of_faces(), b.number_of_faces() - triangles);
    });

  on_every_dart(
    m, [](const Mesh& b, Dart d) { return Euler::can_make_hole(d, b); },
    [](Mesh& e, Dart d) { return Euler::make_hole(d, e); },
    [&](const Mesh& b, const Mesh& e, Dart d, Dart h) {
      const Counts a = counts(e);
      EXPECT_EQ(a.chi, c.chi - 1);
      EXPECT_EQ(a.borders, c.borders + 1);
      EXPECT_EQ(a.orientable, c.orientable);
      EXPECT_TRUE(e.is_border(h));
      EXPECT_EQ(CGAL_ext::halfedges_around_face(h, e).size(), b.degree(b.face(d)));
      // Filling the hole gives the surface back.
      Mesh back = e;
      Euler::fill_hole(h, back);
      EXPECT_TRUE(back.is_valid(true));
      EXPECT_EQ(face_signature(back), face_signature(b));
      EXPECT_EQ(CGAL_ext::number_of_border_cycles(back), c.borders);
    });

  on_every_dart(
    m, [](const Mesh& b, Dart d) { return Euler::can_remove_face(d, b); },
    [](Mesh& e, Dart d) {
      Euler::remove_face(d, e);
      return 0;
    },
    [&](const Mesh& b, const Mesh& e, Dart d, int) {
      // The face goes, with each side whose other side was border, and each
      // corner between two such sides.
      long long edges_gone = 0, vertices_gone = 0;
      for (Dart s : CGAL_ext::halfedges_around_face(d, b)) {
        edges_gone += b.is_border(b.opposite(s));
        vertices_gone += b.is_border(b.opposite(s)) && b.is_border(b.opposite(b.next(s)));
      }
      EXPECT_EQ(e.number_of_faces(), b.number_of_faces() - 1);
      EXPECT_EQ(e.number_of_edges(), b.number_of_edges() - edges_gone);
      EXPECT_EQ(e.number_of_vertices(), b.number_of_vertices() - vertices_gone);
      EXPECT_EQ(counts(e).chi, c.chi - 1 + edges_gone - vertices_gone);
    });
}

// The whole connectivity, element by element: two meshes edited the same
// way must agree on every link, bit and removal mark.
void expect_same_connectivity(const Mesh& a, const Mesh& b, Dart d)
{
  ASSERT_EQ(a.num_halfedges(), b.num_halfedges()) << d;
  ASSERT_EQ(a.num_vertices(), b.num_vertices()) << d;
  ASSERT_EQ(a.num_faces(), b.num_faces()) << d;
  for (std::uint32_t i = 0; i < a.num_halfedges(); ++i) {
    const Halfedge_index h(i);
    EXPECT_EQ(a.is_removed(h), b.is_removed(h)) << d;
    if (a.is_removed(h))
      continue;
    EXPECT_EQ(a.next(Dart(h)), b.next(Dart(h))) << d;
    EXPECT_EQ(a.prev(Dart(h)), b.prev(Dart(h))) << d;
    EXPECT_EQ(a.target(h), b.target(h)) << d;
    EXPECT_EQ(a.face(h), b.face(h)) << d;
    EXPECT_EQ(a.is_mobius(a.edge(h)), b.is_mobius(b.edge(h))) << d;
  }
  for (std::uint32_t i = 0; i < a.num_vertices(); ++i) {
    const Vertex_index v(i);
    EXPECT_EQ(a.is_removed(v), b.is_removed(v)) << d;
    if (!a.is_removed(v)) {
      EXPECT_EQ(a.halfedge(v), b.halfedge(v)) << d;
    }
  }
  for (std::uint32_t i = 0; i < a.num_faces(); ++i) {
    const Face_index f(i);
    EXPECT_EQ(a.is_removed(f), b.is_removed(f)) << d;
    if (!a.is_removed(f)) {
      EXPECT_EQ(a.halfedge(f), b.halfedge(f)) << d;
    }
  }
}

// Runs `checked` and `unchecked` on two copies of `m` at every dart where
// `can` allows it: same result, same mesh, and a valid one.
template <class Can, class Op, class Unchecked_op>
int checked_against_unchecked(const Mesh& m, Can can, Op checked, Unchecked_op unchecked)
{
  int applied = 0;
  for (Dart d : all_darts(m)) {
    if (!can(m, d))
      continue;
    Mesh a = m, b = m;
    const auto r = checked(a, d);
    EXPECT_EQ(r, unchecked(b, d)) << d;
    EXPECT_TRUE(b.is_valid(true)) << d;
    expect_same_connectivity(a, b, d);
    ++applied;
  }
  return applied;
}

TEST_P(EulerOnEveryDart, UncheckedOverloadsDoWhatTheCheckedOnesDo)
{
  Mesh m = mesh();
  // Quads and larger faces too, so that split_face and join_vertex apply.
  for (Dart d : all_darts(m))
    if (!m.is_removed(d.halfedge()) && !d.is_flipped() && Euler::can_join_face(d, m) &&
        m.number_of_faces() > m.number_of_vertices() / 2)
      Euler::join_face(d, m);
  ASSERT_TRUE(m.is_valid(true));
  m.collect_garbage();
  auto two_on = [](const Mesh& e, Dart d) { return e.next(e.next(d)); };
  int applied = 0;
  applied += checked_against_unchecked(
    m, [](const Mesh& e, Dart d) { return Euler::can_flip_edge(d, e); },
    [](Mesh& e, Dart d) { return Euler::flip_edge(d, e); },
    [](Mesh& e, Dart d) { return Euler::flip_edge(d, e, Euler::unchecked); });
  applied += checked_against_unchecked(
    m, [](const Mesh& e, Dart d) { return Euler::can_join_face(d, e); },
    [](Mesh& e, Dart d) { return Euler::join_face(d, e); },
    [](Mesh& e, Dart d) { return Euler::join_face(d, e, Euler::unchecked); });
  applied += checked_against_unchecked(
    m, [&](const Mesh& e, Dart d) { return !e.is_border(d) && Euler::can_split_face(d, two_on(e, d), e); },
    [&](Mesh& e, Dart d) { return Euler::split_face(d, two_on(e, d), e); },
    [&](Mesh& e, Dart d) { return Euler::split_face(d, two_on(e, d), e, Euler::unchecked); });
  applied += checked_against_unchecked(
    m, [](const Mesh& e, Dart d) { return Euler::can_join_vertex(d, e); },
    [](Mesh& e, Dart d) { return Euler::join_vertex(d, e); },
    [](Mesh& e, Dart d) { return Euler::join_vertex(d, e, Euler::unchecked); });
  applied += checked_against_unchecked(
    m, [](const Mesh& e, Dart d) { return Euler::can_remove_center_vertex(d, e); },
    [](Mesh& e, Dart d) { return Euler::remove_center_vertex(d, e); },
    [](Mesh& e, Dart d) { return Euler::remove_center_vertex(d, e, Euler::unchecked); });
  applied += checked_against_unchecked(
    m, [](const Mesh& e, Dart d) { return Euler::does_satisfy_link_condition(d, e); },
    [](Mesh& e, Dart d) { return Euler::collapse_edge(d, e); },
    [](Mesh& e, Dart d) { return Euler::collapse_edge(d, e, Euler::unchecked); });
  applied += checked_against_unchecked(
    m, [](const Mesh& e, Dart d) { return Euler::can_make_hole(d, e); },
    [](Mesh& e, Dart d) { return Euler::make_hole(d, e); },
    [](Mesh& e, Dart d) { return Euler::make_hole(d, e, Euler::unchecked); });
  applied += checked_against_unchecked(
    m, [](const Mesh& e, Dart d) { return Euler::can_remove_face(d, e); },
    [](Mesh& e, Dart d) {
      Euler::remove_face(d, e);
      return 0;
    },
    [](Mesh& e, Dart d) {
      Euler::remove_face(d, e, Euler::unchecked);
      return 0;
    });
  applied += checked_against_unchecked(
    m, [&](const Mesh& e, Dart d) { return e.is_border(d) && Euler::can_add_face_to_border(d, two_on(e, d), e); },
    [&](Mesh& e, Dart d) { return Euler::add_face_to_border(d, two_on(e, d), e); },
    [&](Mesh& e, Dart d) { return Euler::add_face_to_border(d, two_on(e, d), e, Euler::unchecked); });
  EXPECT_GT(applied, 0);
}

INSTANTIATE_TEST_SUITE_P(Meshes, EulerOnEveryDart, ::testing::Values(0, 1, 2));

TEST(Euler, FillingTheBorderOfAMobiusBandMakesAProjectivePlane)
{
  Mesh m = five_triangle_band<Point>();
  ASSERT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  const Face_index f = Euler::fill_hole(CGAL_ext::border_cycles(m).front(), m);
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.degree(f), 5u);
  EXPECT_TRUE(CGAL_ext::is_closed(m));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 1); // RP^2
  EXPECT_FALSE(CGAL_ext::is_orientable(m));
}

TEST(Euler, AddFaceToBorderAcrossTheSeam)
{
  // Every two consecutive border darts (after h1) of a triangulated strip's one loop,
  // both ways round the loop, across the seam too.
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 6, 1, 1, 1.0, 0.5, false);
  ASSERT_EQ(CGAL_ext::halfedges_around_face(CGAL_ext::border_cycles(m).front(), m).size(), 12u);
  int added = 0;
  for (Dart h1 : all_darts(m)) {
    if (!m.is_border(h1))
      continue;
    const Dart h2 = m.next(m.next(h1));
    if (!Euler::can_add_face_to_border(h1, h2, m))
      continue;
    Mesh e = m;
    const Dart n = Euler::add_face_to_border(h1, h2, e);
    ASSERT_TRUE(e.is_valid(true)) << h1;
    EXPECT_EQ(e.number_of_faces(), m.number_of_faces() + 1);
    EXPECT_EQ(e.degree(e.face(n)), 3u);
    EXPECT_EQ(e.source(n), m.target(h2));
    EXPECT_EQ(e.target(n), m.target(h1));
    EXPECT_TRUE(e.is_border(h1));
    EXPECT_TRUE(e.is_border(e.opposite(n)));
    EXPECT_EQ(CGAL_ext::halfedges_around_face(e.opposite(n), e).size(), 11u);
    EXPECT_EQ(CGAL_ext::euler_characteristic(e), 0);
    EXPECT_FALSE(CGAL_ext::is_orientable(e));
    ++added;
  }
  // Both ways round, at each of the 12 border vertices where the two
  // neighbours along the loop are not adjacent yet.
  EXPECT_GT(added, 0);
  EXPECT_EQ(added % 2, 0);
}

TEST(Euler, TheResultDoesNotDependOnHowTheFacesWereOriented)
{
  const Mesh a = five_triangle_band<Point>(false), b = five_triangle_band<Point>(true);
  ASSERT_EQ(face_signature(a), face_signature(b));
  for (Dart da : all_darts(a)) {
    const Key s = key_of(a.point(a.source(da))), t = key_of(a.point(a.target(da)));
    const Dart db = dart_between(b, s, t);
    ASSERT_TRUE(db.is_valid());
    Mesh ea = a, eb = b;
    ea.point(ea.target(Euler::split_edge(da, ea))) = Point(7, 7, 7);
    eb.point(eb.target(Euler::split_edge(db, eb))) = Point(7, 7, 7);
    EXPECT_EQ(face_signature(ea), face_signature(eb));
    ea = a, eb = b;
    ASSERT_EQ(Euler::does_satisfy_link_condition(da, ea), Euler::does_satisfy_link_condition(db, eb));
    if (Euler::does_satisfy_link_condition(da, ea)) {
      Euler::collapse_edge(da, ea);
      Euler::collapse_edge(db, eb);
      EXPECT_EQ(face_signature(ea), face_signature(eb));
    }
  }
}

// The operations take a shorter path, by halfedge index, where the darts
// they are given are unflipped and no Möbius edge is near, and the walk of
// darts elsewhere. The same surface oriented three ways (as built; every
// face reversed, so that every walk is a flipped dart and no short path
// applies; one face reversed, so that Möbius edges surround it and only the
// operations far from it take the short path) must give the same answers
// and the same meshes, operation by operation, at every dart.
TEST(Euler, ShortPathsAndDartWalksGiveTheSameMeshes)
{
  Mesh a;
  CGAL_ext::make_torus(a, 7, 5);
  CGAL_ext::triangulate_faces(a);
  Euler::make_hole(a.halfedge(Face_index(0u)), a); // a border too
  a.collect_garbage();
  Mesh all_reversed = a, one_reversed = a;
  for (Face_index f : all_reversed.faces())
    all_reversed.reverse_face_orientation(f);
  one_reversed.reverse_face_orientation(Face_index(a.number_of_faces() / 2));
  ASSERT_TRUE(all_reversed.is_valid(true) && one_reversed.is_valid(true));
  ASSERT_EQ(face_signature(all_reversed), face_signature(a));
  ASSERT_EQ(face_signature(one_reversed), face_signature(a));

  const Point fresh(7, 7, 7);
  // Operation `op` at `d` if its check allows it; whether it did.
  auto apply = [&](Mesh& e, Dart d, int op) {
    switch (op) {
    case 0: e.point(e.target(Euler::split_edge(d, e))) = fresh; return true;
    case 1: {
      if (e.is_border(d))
        return false;
      const Dart n = Euler::split_edge(d, e);
      e.point(e.target(n)) = fresh;
      if (!Euler::can_split_face(n, e.next(e.next(n)), e))
        return false;
      Euler::split_face(n, e.next(e.next(n)), e, Euler::unchecked);
      return true;
    }
    case 2: return Euler::can_flip_edge(d, e) && (Euler::flip_edge(d, e), true);
    case 3: return Euler::can_flip_edge(d, e) && (Euler::flip_edge(d, e, Euler::unchecked), true);
    case 4: return Euler::can_join_face(d, e) && (Euler::join_face(d, e), true);
    case 5: return Euler::can_join_vertex(d, e) && (Euler::join_vertex(d, e, Euler::unchecked), true);
    case 6: return Euler::does_satisfy_link_condition(d, e) && (Euler::collapse_edge(d, e), true);
    default:
      return Euler::does_satisfy_link_condition(d, e) && (Euler::collapse_edge(d, e, Euler::unchecked), true);
    }
  };
  int applied = 0;
  for (Dart d : all_darts(a)) {
    for (int op = 0; op < 8; ++op) {
      Mesh ea = a;
      const bool done = apply(ea, d, op);
      for (const Mesh* other : {&all_reversed, &one_reversed}) {
        Mesh eo = *other;
        // The same halfedge (reversing keeps the indices), walked the same way.
        const Dart od(d.halfedge(), eo.target(Dart(d.halfedge(), false)) != a.target(d));
        ASSERT_EQ(eo.target(od), a.target(d));
        ASSERT_EQ(apply(eo, od, op), done) << "operation " << op << " at " << d;
        if (done) {
          ASSERT_TRUE(eo.is_valid(true)) << "operation " << op << " at " << d;
          EXPECT_EQ(face_signature(eo), face_signature(ea)) << "operation " << op << " at " << d;
        }
      }
      if (done) {
        ASSERT_TRUE(ea.is_valid(true)) << "operation " << op << " at " << d;
        ++applied;
      }
    }
  }
  EXPECT_GT(applied, 1000);
}

TEST(Euler, RefusalsThrowAndLeaveTheMeshAlone)
{
  Mesh m = five_triangle_band<Point>();
  const auto signature = face_signature(m);
  const Counts c = counts(m);
  const Dart d = m.halfedge(Face_index(0u));
  // Joining the ends of a triangle's side would leave a face of two sides.
  EXPECT_FALSE(Euler::can_join_vertex(d, m));
  EXPECT_THROW(Euler::join_vertex(d, m), CGAL_ext::Euler_error);
  // Adjacent corners of a triangle are joined already.
  EXPECT_THROW(Euler::split_face(d, m.next(d), m), CGAL_ext::Euler_error);
  // Every vertex of the band is on its border: removing a face would pinch one.
  EXPECT_FALSE(Euler::can_remove_face(d, m));
  EXPECT_THROW(Euler::remove_face(d, m), CGAL_ext::Euler_error);
  // Not a border dart.
  EXPECT_THROW(Euler::fill_hole(d, m), CGAL_ext::Euler_error);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_FALSE(m.has_garbage());
  EXPECT_EQ(face_signature(m), signature);
  EXPECT_EQ(counts(m).chi, c.chi);
}

// ---------------------------------------------------------------- against CGAL::Euler

// Runs the same random operations through CGAL::Euler on a Surface_mesh and
// through ours, with their checks or (`unchecked`) without.
// `recycle`: both meshes take removed slots back (Surface_mesh's default),
// else both append; either way they hold the same numbers of slots.
void same_sequence_as_cgal_euler(bool unchecked, bool recycle)
{
  using SM = CGAL::Surface_mesh<Point>;
  Mesh m;
  CGAL_ext::make_torus(m, 7, 5);
  m.set_recycle_garbage(recycle);
  // Triangulate it the same way in both, so that collapses and flips apply.
  SM sm;
  sm.set_recycle_garbage(recycle);
  std::map<Key, SM::Vertex_index> sm_vertex;
  for (Vertex_index v : m.vertices())
    sm_vertex[key_of(m.point(v))] = sm.add_vertex(m.point(v));
  for (Face_index f : std::vector<Face_index>(m.faces().begin(), m.faces().end())) {
    std::vector<SM::Vertex_index> vs;
    for (Vertex_index v : CGAL_ext::vertices_around_face(f, m))
      vs.push_back(sm_vertex[key_of(m.point(v))]);
    ASSERT_TRUE(sm.add_face(vs).is_valid());
  }
  ASSERT_EQ(face_signature(m), face_signature(sm));

  auto sm_halfedge = [&](Dart d) {
    const auto s = sm_vertex.at(key_of(m.point(m.source(d)))), t = sm_vertex.at(key_of(m.point(m.target(d))));
    const auto r = CGAL::halfedge(s, t, sm);
    EXPECT_TRUE(r.second);
    return r.first;
  };
  std::mt19937 rng(11);
  int fresh = 0;
  auto place_new_vertex = [&](Vertex_index v, SM::Vertex_index w) {
    const Point p(100 + fresh++, 0, 0);
    m.point(v) = p;
    sm.point(w) = p;
    sm_vertex[key_of(p)] = w;
  };
  int applied = 0;
  for (int step = 0; step < 400; ++step) {
    // Unflipped darts: they walk as Surface_mesh's halfedges do (both meshes
    // are oriented alike, and no operation here needs to turn a face).
    const std::vector<Halfedge_index> hs(m.halfedges().begin(), m.halfedges().end());
    const Dart d(hs[rng() % hs.size()], false);
    const auto h = sm_halfedge(d);
    switch (rng() % 10) {
    case 7:
      if (!Euler::can_make_hole(d, m) || CGAL_ext::number_of_border_cycles(m) > 2)
        continue;
      CGAL::Euler::make_hole(h, sm);
      unchecked ? Euler::make_hole(d, m, Euler::unchecked) : Euler::make_hole(d, m);
      break;
    case 8:
      if (!m.is_border(d))
        continue;
      CGAL::Euler::fill_hole(h, sm);
      Euler::fill_hole(d, m);
      break;
    case 9: {
      if (!m.is_border(d) || !Euler::can_add_face_to_border(d, m.next(m.next(d)), m))
        continue;
      CGAL::Euler::add_face_to_border(h, sm_halfedge(m.next(m.next(d))), sm);
      if (unchecked)
        Euler::add_face_to_border(d, m.next(m.next(d)), m, Euler::unchecked);
      else
        Euler::add_face_to_border(d, m.next(m.next(d)), m);
      break;
    }
    case 0: {
      const Dart n = Euler::split_edge(d, m);
      const auto hn = CGAL::Euler::split_edge(h, sm);
      place_new_vertex(m.target(n), sm.target(hn));
      break;
    }
    case 1:
      if (!Euler::can_join_face(d, m))
        continue;
      CGAL::Euler::join_face(h, sm);
      unchecked ? Euler::join_face(d, m, Euler::unchecked) : Euler::join_face(d, m);
      break;
    case 2: {
      if (m.is_border(d) || m.degree(m.face(d)) < 4)
        continue;
      const Dart g = m.next(m.next(d));
      if (!Euler::can_split_face(d, g, m))
        continue;
      CGAL::Euler::split_face(h, sm_halfedge(g), sm);
      unchecked ? Euler::split_face(d, g, m, Euler::unchecked) : Euler::split_face(d, g, m);
      break;
    }
    case 3:
      if (!Euler::can_join_vertex(d, m))
        continue;
      CGAL::Euler::join_vertex(h, sm);
      unchecked ? Euler::join_vertex(d, m, Euler::unchecked) : Euler::join_vertex(d, m);
      break;
    case 4: {
      if (m.is_border(d))
        continue;
      const Dart n = Euler::add_center_vertex(d, m);
      const auto hn = CGAL::Euler::add_center_vertex(h, sm);
      place_new_vertex(m.target(n), sm.target(hn));
      break;
    }
    case 5:
      if (!Euler::can_remove_center_vertex(d, m))
        continue;
      CGAL::Euler::remove_center_vertex(h, sm);
      unchecked ? Euler::remove_center_vertex(d, m, Euler::unchecked) : Euler::remove_center_vertex(d, m);
      break;
    default: {
      // CGAL collapses edges between triangles: keep to those, and collapse
      // our dart the way CGAL does (it keeps the target of halfedge(e)).
      const auto e = sm.edge(h);
      const Dart dd = sm.halfedge(e) == h ? d : m.opposite(d);
      bool triangles = true;
      for (Dart side : {dd, m.opposite(dd)})
        triangles = triangles && !m.is_border(side) && m.degree(m.face(side)) == 3;
      if (!triangles)
        continue;
      const bool ours = Euler::does_satisfy_link_condition(dd, m);
      EXPECT_EQ(ours, CGAL::Euler::does_satisfy_link_condition(e, sm)) << "step " << step;
      if (!ours || !CGAL::Euler::does_satisfy_link_condition(e, sm))
        continue;
      CGAL::Euler::collapse_edge(e, sm);
      unchecked ? Euler::collapse_edge(dd, m, Euler::unchecked) : Euler::collapse_edge(dd, m);
    }
    }
    ++applied;
    ASSERT_TRUE(m.is_valid(true)) << "step " << step;
    ASSERT_TRUE(sm.is_valid(true)) << "step " << step;
    ASSERT_EQ(face_signature(m), face_signature(sm)) << "step " << step;
    ASSERT_EQ(m.num_vertices(), sm.num_vertices()) << "step " << step;
    ASSERT_EQ(m.num_edges(), sm.num_edges()) << "step " << step;
    ASSERT_EQ(m.num_faces(), sm.num_faces()) << "step " << step;
  }
  EXPECT_GT(applied, 150);
  m.collect_garbage();
  sm.collect_garbage();
  EXPECT_EQ(face_signature(m), face_signature(sm));
}

TEST(Euler, SameSequenceAsCgalEulerOnSurfaceMesh) { same_sequence_as_cgal_euler(false, false); }

TEST(Euler, UncheckedSameSequenceAsCgalEulerOnSurfaceMesh) { same_sequence_as_cgal_euler(true, false); }

TEST(Euler, SameSequenceAsCgalEulerRecyclingTheSlots)
{
  same_sequence_as_cgal_euler(false, true);
  same_sequence_as_cgal_euler(true, true);
}

#if !defined(NDEBUG) && !defined(CGAL_NO_PRECONDITIONS)
// Without their checks, the operations still assert them where CGAL's
// preconditions are on (CGAL's default failure behaviour throws).
TEST(Euler, UncheckedOverloadsAssertTheirChecksInDebugBuilds)
{
  Mesh m = five_triangle_band<Point>();
  const Dart d = m.halfedge(Face_index(0u));
  EXPECT_THROW(Euler::split_face(d, m.next(d), m, Euler::unchecked), CGAL::Precondition_exception);
  EXPECT_THROW(Euler::join_vertex(d, m, Euler::unchecked), CGAL::Precondition_exception);
  EXPECT_THROW(Euler::remove_face(d, m, Euler::unchecked), CGAL::Precondition_exception);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_FALSE(m.has_garbage());
}
#endif

// ---------------------------------------------------------------- random stress

// Random valid operations on a one-sided surface, with the mesh checked after
// each: χ and orientability never change but by the holes made and filled.
// `recycle`: the mesh takes removed slots back; it then never holds more
// slots than it had live elements at its largest.
template <class P>
void stress(CGAL_ext::Mobius_mesh<P> m, int steps, unsigned seed, bool recycle = false)
{
  using M = CGAL_ext::Mobius_mesh<P>;
  std::mt19937 rng(seed);
  m.set_recycle_garbage(recycle);
  std::size_t peak_v = m.number_of_vertices(), peak_e = m.number_of_edges(), peak_f = m.number_of_faces();
  Counts expected = counts(m);
  auto tag = m.template add_property_map<Vertex_index, int>("v:tag", -1).first;
  int next_tag = 0;
  for (Vertex_index v : m.vertices())
    tag[v] = next_tag++;
  std::map<int, Key> point_of_tag;
  auto cap = [&m] { return m.number_of_vertices() < 150; };
  for (int s = 0; s < steps; ++s) {
    std::vector<Halfedge_index> hs(m.halfedges().begin(), m.halfedges().end());
    const Dart d(hs[rng() % hs.size()], rng() % 2 == 1);
    switch (rng() % 12) {
    case 0: if (Euler::can_flip_edge(d, m)) Euler::flip_edge(d, m); break;
    case 1: if (cap()) tag[m.target(Euler::split_edge(d, m))] = next_tag++; break;
    case 2: if (Euler::can_join_face(d, m)) Euler::join_face(d, m); break;
    case 3:
      if (!m.is_border(d) && Euler::can_split_face(d, m.next(m.next(d)), m))
        Euler::split_face(d, m.next(m.next(d)), m);
      break;
    case 4: if (Euler::can_join_vertex(d, m)) Euler::join_vertex(d, m); break;
    case 5: {
      const Dart h2 = m.opposite(m.next(m.opposite(m.next(d))));
      if (cap() && h2 != d && m.target(h2) == m.target(d))
        tag[m.source(Euler::split_vertex(d, h2, m))] = next_tag++;
      break;
    }
    case 6: if (cap() && !m.is_border(d)) tag[m.target(Euler::add_center_vertex(d, m))] = next_tag++; break;
    case 7: if (Euler::can_remove_center_vertex(d, m)) Euler::remove_center_vertex(d, m); break;
    case 8:
      if (m.number_of_faces() > 30 && Euler::does_satisfy_link_condition(d, m))
        Euler::collapse_edge(d, m);
      break;
    case 9:
      if (m.number_of_faces() > 30 && expected.borders < 5 && Euler::can_make_hole(d, m)) {
        Euler::make_hole(d, m);
        expected.chi -= 1;
        expected.borders += 1;
      }
      break;
    case 10:
      if (m.is_border(d)) {
        Euler::fill_hole(d, m);
        expected.chi += 1;
        expected.borders -= 1;
      }
      break;
    default:
      if (m.is_border(d) && Euler::can_add_face_to_border(d, m.next(m.next(d)), m))
        Euler::add_face_to_border(d, m.next(m.next(d)), m);
    }
    ASSERT_TRUE(m.is_valid(true)) << "step " << s;
    const Counts now = counts(m);
    ASSERT_EQ(now.chi, expected.chi) << "step " << s;
    ASSERT_EQ(now.borders, expected.borders) << "step " << s;
    ASSERT_EQ(now.orientable, expected.orientable) << "step " << s;
    peak_v = (std::max)(peak_v, std::size_t(m.number_of_vertices()));
    peak_e = (std::max)(peak_e, std::size_t(m.number_of_edges()));
    peak_f = (std::max)(peak_f, std::size_t(m.number_of_faces()));
  }
  if (recycle) {
    EXPECT_EQ(m.num_vertices(), peak_v);
    EXPECT_EQ(m.num_edges(), peak_e);
    EXPECT_EQ(m.num_faces(), peak_f);
  }
  for (Vertex_index v : m.vertices())
    point_of_tag[tag[v]] = key_of(m.point(v));
  m.collect_garbage();
  ASSERT_TRUE(m.is_valid(true));
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), expected.chi);
  EXPECT_EQ(m.number_of_vertices(), point_of_tag.size());
  for (Vertex_index v : m.vertices())
    EXPECT_EQ(key_of(m.point(v)), point_of_tag.at(tag[v])); // the map followed the points
  (void)sizeof(M);
}

TEST(EulerStress, MobiusStripKleinBottleAndBoysSurfaceDouble)
{
  Mesh strip, triangles, klein, boy;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  CGAL_ext::make_mobius_strip(triangles, 10, 2, 1, 1.0, 0.5, false);
  CGAL_ext::make_klein_bottle(klein, 8, 6);
  CGAL_ext::make_projective_plane(boy, 2);
  stress(strip, 1500, 1);
  stress(triangles, 1500, 2);
  stress(klein, 1500, 3);
  stress(boy, 1500, 4);
  stress(strip, 1500, 7, true);
  stress(klein, 1500, 8, true);
}

TEST(EulerStress, KleinBottleAndBoysSurfaceEpeck)
{
  CGAL_ext::Mobius_mesh<test::Epeck::Point_3> klein, boy;
  CGAL_ext::make_klein_bottle(klein, 6, 5);
  CGAL_ext::make_projective_plane(boy, 2);
  stress(klein, 500, 5);
  stress(boy, 500, 6, true);
}

} // namespace editing_tests
