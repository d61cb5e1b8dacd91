// Conversion between Mobius_mesh and CGAL::Surface_mesh.
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace conversion_tests {

namespace {

using Kd = test::Kd;
using Epeck = test::Epeck;
using Epick = test::Epick;

struct Soup
{
  std::vector<Kd::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  // From the first line of the test files: expected V, E, F, chi, orientability, border loops.
  std::size_t v = 0, e = 0, f = 0, loops = 0;
  long chi = 0;
  bool orientable = false;
};

// A minimal OBJ reader for the test meshes: `v x y z` and `f a b c ...` (1-based, `a/t/n` allowed).
Soup read_obj(const std::string& relative)
{
  Soup soup;
  const bool opened = test::read_obj_lines(
    test::data(relative), [&](double x, double y, double z) { soup.points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& polygon) { soup.polygons.push_back(polygon); },
    [&](const std::string& tag, const std::string& line, std::istream&) {
      if (tag != "#" || line.find("V=") == std::string::npos)
        return;
      auto value = [&](const std::string& key) {
        const std::size_t at = line.find(key);
        return line.substr(at + key.size(), line.find(' ', at) - at - key.size());
      };
      soup.v = std::stoul(value("V="));
      soup.e = std::stoul(value("E="));
      soup.f = std::stoul(value("F="));
      soup.chi = std::stol(value("chi="));
      soup.orientable = value("orientable=") == "True";
      soup.loops = std::stoul(value("boundary_loops="));
    });
  EXPECT_TRUE(opened) << relative;
  return soup;
}

template <class P>
CGAL_ext::Mobius_mesh<P> mesh_of(const Soup& soup)
{
  std::vector<P> points;
  CGAL::Cartesian_converter<Kd, typename CGAL::Kernel_traits<P>::Kernel> convert;
  for (const auto& p : soup.points)
    points.push_back(convert(p));
  CGAL_ext::Mobius_mesh<P> mesh;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, soup.polygons, mesh);
  return mesh;
}

// Face cycles as vertex-index lists, starting at the source of halfedge(f).
template <class P>
std::vector<std::vector<std::size_t>> face_cycles(const CGAL_ext::Mobius_mesh<P>& m)
{
  std::vector<std::vector<std::size_t>> cycles;
  for (auto f : m.faces()) {
    std::vector<std::size_t> c;
    for (auto d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      c.push_back(m.source(d).idx());
    cycles.push_back(c);
  }
  return cycles;
}

template <class P>
std::set<std::pair<std::size_t, std::size_t>> mobius_edge_set(const CGAL_ext::Mobius_mesh<P>& m)
{
  std::set<std::pair<std::size_t, std::size_t>> s;
  for (auto e : m.edges())
    if (m.is_mobius(e)) {
      const std::size_t a = m.vertex(e, 0).idx(), b = m.vertex(e, 1).idx();
      s.emplace((std::min)(a, b), (std::max)(a, b));
    }
  return s;
}

template <class SM>
std::size_t number_of_border_halfedges(const SM& sm)
{
  std::size_t n = 0;
  for (auto h : sm.halfedges())
    n += sm.is_border(h) ? 1 : 0;
  return n;
}

const char* const all_files[] = {"nonorientable/boys_surface_quads.obj", "nonorientable/klein_fig8_24x12_quads.obj",
                                 "nonorientable/mobius_20x4_quads.obj",  "nonorientable/mobius_20x4_tris.obj",
                                 "nonorientable/mobius_min_5tris.obj",   "nonorientable/rp2_hemi_icosahedron.obj",
                                 "nonorientable/torus_24x12_quads.obj"};

// ---------------------------------------------------------------------------- orientable

TEST(Conversion, TorusMatchesCgalsOwnImport)
{
  const Soup soup = read_obj("nonorientable/torus_24x12_quads.obj");
  const auto mesh = mesh_of<Kd::Point_3>(soup);
  CGAL::Surface_mesh<Kd::Point_3> sm;
  const auto r = CGAL_ext::to_surface_mesh(mesh, sm);
  EXPECT_EQ(r.seam_edges, 0u);
  EXPECT_EQ(r.added_vertices, 0u);
  EXPECT_EQ(r.reversed_faces, 0u);
  ASSERT_TRUE(sm.is_valid(false));

  // CGAL's own soup import is the reference.
  CGAL::Surface_mesh<Kd::Point_3> ref;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, ref);
  EXPECT_EQ(sm.number_of_vertices(), ref.number_of_vertices());
  EXPECT_EQ(sm.number_of_edges(), ref.number_of_edges());
  EXPECT_EQ(sm.number_of_faces(), ref.number_of_faces());
  EXPECT_TRUE(CGAL::is_closed(sm));
  const bool has_seam =
    sm.property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).second;
  EXPECT_FALSE(has_seam);
  // Same face cycles (as cyclic sequences) and same points.
  for (auto f : ref.faces()) {
    std::vector<std::size_t> a, b;
    for (auto v : CGAL::vertices_around_face(ref.halfedge(f), ref))
      a.push_back(std::size_t(v));
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
      b.push_back(std::size_t(v));
    std::rotate(b.begin(), std::find(b.begin(), b.end(), a[0]), b.end());
    EXPECT_EQ(a, b) << "face " << f;
  }
  for (auto v : ref.vertices())
    EXPECT_EQ(sm.point(v), ref.point(v));
  EXPECT_NEAR(CGAL::Polygon_mesh_processing::area(sm), CGAL::Polygon_mesh_processing::area(ref), 1e-12);
}

TEST(Conversion, InconsistentOrientationIsOrientedAndRestored)
{
  // A unit cube whose face 3 runs the wrong way: four Möbius edges.
  std::vector<Epick::Point_3> pts;
  for (int i = 0; i < 8; ++i)
    pts.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<std::vector<int>> quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::reverse(quads[3].begin(), quads[3].end());
  CGAL_ext::Mobius_mesh<Epick::Point_3> mesh;
  CGAL_ext::polygon_soup_to_mobius_mesh(pts, quads, mesh, CGAL_ext::parameters::keep_orientation(true));
  ASSERT_EQ(CGAL_ext::number_of_mobius_edges(mesh), 4u);
  const auto before = face_cycles(mesh);

  CGAL::Surface_mesh<Epick::Point_3> sm;
  const auto r = CGAL_ext::to_surface_mesh(mesh, sm);
  EXPECT_EQ(r.seam_edges, 0u);
  EXPECT_EQ(r.reversed_faces, 1u);
  ASSERT_TRUE(sm.is_valid(false));
  EXPECT_TRUE(CGAL::is_closed(sm));
  // Consistently oriented: the signed volume (of a triangulated copy) is +-1;
  // with the face left reversed it would be +-1/3. (Summed in doubles, so
  // it may miss 1 by an ulp.)
  auto triangulated = sm;
  CGAL::Polygon_mesh_processing::triangulate_faces(triangulated);
  const double volume = CGAL::to_double(CGAL::Polygon_mesh_processing::volume(triangulated));
  EXPECT_NEAR(std::abs(volume), 1.0, 1e-12) << volume;
  EXPECT_EQ(face_cycles(mesh), before); // the input is untouched

  CGAL_ext::Mobius_mesh<Epick::Point_3> back;
  const auto rb = CGAL_ext::from_surface_mesh(sm, back);
  EXPECT_EQ(rb.reversed_faces, 1u);
  EXPECT_TRUE(back.is_valid(true));
  EXPECT_EQ(face_cycles(back), before);
  EXPECT_EQ(mobius_edge_set(back), mobius_edge_set(mesh));
}

// ---------------------------------------------------------------------------- round trips

template <class P, class Q>
void round_trip(const std::string& file)
{
  SCOPED_TRACE(file);
  const Soup soup = read_obj(file);
  auto mesh = mesh_of<P>(soup);
  CGAL_ext::orient(mesh); // as few Möbius edges as orient() finds: the round trip must keep them
  const std::size_t mobius = CGAL_ext::number_of_mobius_edges(mesh);
  EXPECT_EQ(mobius == 0, soup.orientable);

  CGAL::Surface_mesh<Q> sm;
  const auto r = CGAL_ext::to_surface_mesh(mesh, sm);
  ASSERT_TRUE(sm.is_valid(false));
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(sm));
  EXPECT_EQ(r.seam_edges, mobius);
  EXPECT_EQ(sm.number_of_faces(), soup.f);
  EXPECT_EQ(sm.number_of_edges(), soup.e + mobius);       // each cut edge doubles
  EXPECT_EQ(sm.number_of_vertices(), soup.v + r.added_vertices);
  // Border halfedges: the original borders and both sides of each cut edge.
  std::size_t original_border = 0;
  for (auto h : mesh.halfedges())
    original_border += mesh.is_border(h) ? 1 : 0;
  EXPECT_EQ(number_of_border_halfedges(sm), original_border + 2 * mobius);

  CGAL_ext::Mobius_mesh<P> back;
  const auto rb = CGAL_ext::from_surface_mesh(sm, back);
  EXPECT_EQ(rb.seam_edges, mobius);
  ASSERT_TRUE(back.is_valid(true));
  EXPECT_EQ(back.number_of_vertices(), soup.v);
  EXPECT_EQ(back.number_of_edges(), soup.e);
  EXPECT_EQ(back.number_of_faces(), soup.f);
  EXPECT_EQ(CGAL_ext::euler_characteristic(back), soup.chi);
  EXPECT_EQ(CGAL_ext::is_orientable(back), soup.orientable);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(back), soup.loops);
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(back), mobius);
  EXPECT_EQ(mobius_edge_set(back), mobius_edge_set(mesh));
  EXPECT_EQ(face_cycles(back), face_cycles(mesh));
  for (auto v : mesh.vertices())
    EXPECT_EQ(back.point(v), mesh.point(v));
}

TEST(Conversion, RoundTripEveryTestMeshDouble)
{
  for (const char* file : all_files)
    round_trip<Kd::Point_3, Kd::Point_3>(file);
}

TEST(Conversion, RoundTripEveryTestMeshEpeckThroughEpick)
{
  // Points read from decimal text are doubles: EPECK -> EPICK -> EPECK is exact on them.
  for (const char* file : all_files)
    round_trip<Epeck::Point_3, Epick::Point_3>(file);
}

TEST(Conversion, RemovedElementsAreSkipped)
{
  const Soup soup = read_obj("nonorientable/mobius_min_5tris.obj");
  const auto mesh = mesh_of<Kd::Point_3>(soup);
  CGAL::Surface_mesh<Kd::Point_3> sm;
  const auto stray = sm.add_vertex(Kd::Point_3(7, 7, 7)); // removed below: index 0 becomes garbage
  CGAL_ext::to_surface_mesh(mesh, sm);
  sm.remove_vertex(stray);
  ASSERT_TRUE(sm.has_garbage());
  CGAL_ext::Mobius_mesh<Kd::Point_3> back;
  CGAL_ext::from_surface_mesh(sm, back);
  ASSERT_TRUE(back.is_valid(true));
  EXPECT_EQ(back.number_of_vertices(), 5u);
  EXPECT_EQ(back.number_of_edges(), 10u);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(back), 1u);
  EXPECT_FALSE(CGAL_ext::is_orientable(back));
  EXPECT_EQ(face_cycles(back), face_cycles(mesh));
}

TEST(Conversion, UnorientedInputRoundTripsExactly)
{
  // Without orient(): the Möbius strip as imported, its faces as the file has them.
  const Soup soup = read_obj("nonorientable/mobius_20x4_tris.obj");
  const auto mesh = mesh_of<Kd::Point_3>(soup);
  CGAL::Surface_mesh<Kd::Point_3> sm;
  CGAL_ext::to_surface_mesh(mesh, sm);
  CGAL_ext::Mobius_mesh<Kd::Point_3> back;
  CGAL_ext::from_surface_mesh(sm, back);
  EXPECT_EQ(face_cycles(back), face_cycles(mesh));
  EXPECT_EQ(mobius_edge_set(back), mobius_edge_set(mesh));
}

TEST(Conversion, ExactRationalPointsSurviveEpeck)
{
  const Soup soup = read_obj("nonorientable/mobius_min_5tris.obj");
  auto mesh = mesh_of<Epeck::Point_3>(soup);
  for (auto v : mesh.vertices())
    mesh.point(v) = Epeck::Point_3(mesh.point(v).x() / 3, Epeck::FT(1) / 7, mesh.point(v).z());
  CGAL::Surface_mesh<Epeck::Point_3> sm;
  CGAL_ext::to_surface_mesh(mesh, sm);
  CGAL_ext::Mobius_mesh<Epeck::Point_3> back;
  CGAL_ext::from_surface_mesh(sm, back);
  for (auto v : mesh.vertices()) {
    EXPECT_EQ(back.point(v).y(), Epeck::FT(1) / 7);
    EXPECT_EQ(back.point(v).x() * 3, Epeck::FT(soup.points[v.idx()].x()));
  }
  // Doubles into Simple_cartesian<Gmpq> and back: exact both ways.
  const auto dmesh = mesh_of<Kd::Point_3>(soup);
  CGAL::Surface_mesh<CGAL::Simple_cartesian<CGAL::Gmpq>::Point_3> qsm;
  CGAL_ext::to_surface_mesh(dmesh, qsm);
  CGAL_ext::Mobius_mesh<Kd::Point_3> dback;
  CGAL_ext::from_surface_mesh(qsm, dback);
  for (auto v : dmesh.vertices())
    EXPECT_EQ(dback.point(v), dmesh.point(v));
}

// ---------------------------------------------------------------------------- properties and maps

TEST(Conversion, SharpnessAndCorrespondences)
{
  const Soup soup = read_obj("nonorientable/mobius_20x4_quads.obj");
  auto mesh = mesh_of<Kd::Point_3>(soup);
  auto es = CGAL_ext::edge_sharpness_map(mesh);
  auto vs = CGAL_ext::vertex_sharpness_map(mesh);
  auto label = mesh.add_property_map<CGAL_ext::Face_index, std::string>("f:label", "").first;
  for (auto e : mesh.edges())
    es[e] = float(e.idx() % 7) * 0.5f;
  for (auto v : mesh.vertices())
    vs[v] = float(v.idx() % 5);
  for (auto f : mesh.faces())
    label[f] = "face" + std::to_string(f.idx());

  using SM = CGAL::Surface_mesh<Kd::Point_3>;
  SM sm;
  std::vector<std::pair<CGAL_ext::Vertex_index, SM::Vertex_index>> vpairs;
  std::vector<std::pair<CGAL_ext::Dart, SM::Halfedge_index>> hpairs;
  std::vector<std::pair<CGAL_ext::Face_index, SM::Face_index>> fpairs;
  const auto r = CGAL_ext::to_surface_mesh(mesh, sm,
                                           CGAL_ext::parameters::vertex_to_vertex_output_iterator(std::back_inserter(vpairs))
                                             .halfedge_to_halfedge_output_iterator(std::back_inserter(hpairs))
                                             .face_to_face_output_iterator(std::back_inserter(fpairs)));
  ASSERT_GT(r.seam_edges, 0u);
  EXPECT_EQ(vpairs.size(), sm.number_of_vertices());
  EXPECT_EQ(fpairs.size(), sm.number_of_faces());
  // Each face halfedge, and each border halfedge that is not on the cut, has a pair.
  EXPECT_EQ(hpairs.size(), sm.number_of_halfedges() - 2 * r.seam_edges);
  std::map<SM::Vertex_index, CGAL_ext::Vertex_index> original;
  for (const auto& [v, s] : vpairs) {
    original[s] = v;
    EXPECT_EQ(sm.point(s), mesh.point(v));
  }
  for (const auto& [d, s] : hpairs) {
    EXPECT_EQ(original[sm.source(s)], mesh.source(d));
    EXPECT_EQ(original[sm.target(s)], mesh.target(d));
  }
  auto sm_es = sm.property_map<SM::Edge_index, float>("e:sharpness");
  auto sm_vs = sm.property_map<SM::Vertex_index, float>("v:sharpness");
  auto sm_label = sm.property_map<SM::Face_index, std::string>("f:label");
  ASSERT_TRUE(sm_es.second && sm_vs.second && sm_label.second);
  for (const auto& [v, s] : vpairs)
    EXPECT_EQ(sm_vs.first[s], vs[v]);
  for (const auto& [d, s] : hpairs)
    EXPECT_EQ(sm_es.first[sm.edge(s)], es[mesh.edge(d)]);
  for (const auto& [f, s] : fpairs)
    EXPECT_EQ(sm_label.first[s], label[f]);

  CGAL_ext::Mobius_mesh<Kd::Point_3> back;
  std::vector<std::pair<SM::Halfedge_index, CGAL_ext::Dart>> back_pairs;
  CGAL_ext::from_surface_mesh(sm, back,
                              CGAL_ext::parameters::halfedge_to_halfedge_output_iterator(std::back_inserter(back_pairs)));
  auto bes = back.property_map<CGAL_ext::Edge_index, float>("e:sharpness");
  auto bvs = back.property_map<CGAL_ext::Vertex_index, float>("v:sharpness");
  ASSERT_TRUE(bes && bvs);
  for (auto v : mesh.vertices())
    EXPECT_EQ((*bvs)[v], vs[v]);
  std::map<std::pair<std::size_t, std::size_t>, float> by_ends;
  for (auto e : mesh.edges())
    by_ends[std::minmax(mesh.vertex(e, 0).idx(), mesh.vertex(e, 1).idx())] = es[e];
  for (auto e : back.edges())
    EXPECT_EQ((*bes)[e], by_ends.at(std::minmax(back.vertex(e, 0).idx(), back.vertex(e, 1).idx())));
  for (const auto& [s, d] : back_pairs) {
    EXPECT_EQ(std::size_t(back.source(d).idx()), std::size_t(original[sm.source(s)].idx()));
    EXPECT_EQ(std::size_t(back.target(d).idx()), std::size_t(original[sm.target(s)].idx()));
  }
}

TEST(Conversion, PropertiesWithoutOutputIterators)
{
  // The element correspondences are built only for property maps or output
  // iterators: with maps alone, every value must still go both ways.
  auto key = [](auto a, auto b) {
    return std::make_pair(std::size_t((std::min)(a, b)), std::size_t((std::max)(a, b)));
  };
  for (const char* file : {"nonorientable/mobius_20x4_quads.obj", "nonorientable/torus_24x12_quads.obj"}) {
    SCOPED_TRACE(file);
    auto mesh = mesh_of<Kd::Point_3>(read_obj(file));
    auto es = CGAL_ext::edge_sharpness_map(mesh);
    auto vs = CGAL_ext::vertex_sharpness_map(mesh);
    auto hl = mesh.add_property_map<CGAL_ext::Halfedge_index, int>("h:label", -1).first;
    std::map<std::pair<std::size_t, std::size_t>, float> by_ends;
    for (auto e : mesh.edges()) {
      es[e] = float(e.idx() % 7) * 0.5f;
      by_ends[key(mesh.vertex(e, 0).idx(), mesh.vertex(e, 1).idx())] = es[e];
    }
    for (auto v : mesh.vertices())
      vs[v] = float(v.idx() % 5);
    for (auto h : mesh.halfedges())
      hl[h] = int(h.idx());

    using SM = CGAL::Surface_mesh<Kd::Point_3>;
    SM sm;
    CGAL_ext::to_surface_mesh(mesh, sm);
    auto sm_es = sm.property_map<SM::Edge_index, float>("e:sharpness");
    auto sm_vs = sm.property_map<SM::Vertex_index, float>("v:sharpness");
    auto sm_hl = sm.property_map<SM::Halfedge_index, int>("h:label");
    ASSERT_TRUE(sm_es.second && sm_vs.second && sm_hl.second);
    // Seam copies of a vertex share its point.
    std::map<Kd::Point_3, CGAL_ext::Vertex_index> by_point;
    for (auto v : mesh.vertices())
      by_point.emplace(mesh.point(v), v);
    ASSERT_EQ(by_point.size(), mesh.number_of_vertices());
    auto original = [&](SM::Vertex_index s) { return by_point.at(sm.point(s)).idx(); };
    for (auto s : sm.vertices())
      EXPECT_EQ(sm_vs.first[s], vs[CGAL_ext::Vertex_index(original(s))]);
    for (auto h : sm.halfedges()) {
      const auto ends = key(original(sm.source(h)), original(sm.target(h)));
      EXPECT_EQ(sm_es.first[sm.edge(h)], by_ends.at(ends));
      if (sm_hl.first[h] < 0) { // only a border halfedge made by the cut has no source
        EXPECT_TRUE(sm.is_border(h));
        continue;
      }
      const CGAL_ext::Halfedge_index g(std::size_t(sm_hl.first[h]));
      EXPECT_EQ(key(mesh.source(g).idx(), mesh.target(g).idx()), ends);
    }

    CGAL_ext::Mobius_mesh<Kd::Point_3> back;
    CGAL_ext::from_surface_mesh(sm, back);
    auto bes = back.property_map<CGAL_ext::Edge_index, float>("e:sharpness");
    auto bvs = back.property_map<CGAL_ext::Vertex_index, float>("v:sharpness");
    auto bhl = back.property_map<CGAL_ext::Halfedge_index, int>("h:label");
    ASSERT_TRUE(bes && bvs && bhl);
    for (auto v : mesh.vertices())
      EXPECT_EQ((*bvs)[v], vs[v]);
    for (auto e : back.edges())
      EXPECT_EQ((*bes)[e], by_ends.at(key(back.vertex(e, 0).idx(), back.vertex(e, 1).idx())));
    for (auto h : back.halfedges()) {
      if (back.is_border(h))
        continue;
      const CGAL_ext::Halfedge_index g(static_cast<std::size_t>((*bhl)[h]));
      EXPECT_EQ(key(mesh.source(g).idx(), mesh.target(g).idx()), key(back.source(h).idx(), back.target(h).idx()));
    }
  }
}

// ---------------------------------------------------------------------------- hand-made seams

// A strip of n unit quads along x, as a Surface_mesh; its two end edges are
// the border halfedges at x = 0 and x = n.
CGAL::Surface_mesh<Kd::Point_3> strip(int n)
{
  CGAL::Surface_mesh<Kd::Point_3> sm;
  std::vector<CGAL::SM_Vertex_index> bottom, top;
  for (int i = 0; i <= n; ++i) {
    bottom.push_back(sm.add_vertex(Kd::Point_3(i, 0, 0)));
    top.push_back(sm.add_vertex(Kd::Point_3(i, 1, 0)));
  }
  for (int i = 0; i < n; ++i)
    sm.add_face(bottom[i], bottom[i + 1], top[i + 1], top[i]);
  return sm;
}

CGAL::SM_Halfedge_index end_border(const CGAL::Surface_mesh<Kd::Point_3>& sm, double x)
{
  for (auto h : sm.halfedges())
    if (sm.is_border(h) && sm.point(sm.source(h)).x() == x && sm.point(sm.target(h)).x() == x)
      return h;
  return CGAL::SM_Halfedge_index();
}

// A band of n quads round a circle of radius 2, cut open at angle 0: with
// `twisted`, a Möbius band (its cross-section turns half round), else an
// annulus. The two end edges lie on each other: the border halfedge `first`
// at the start and `last` at the end, glued source to source when twisted
// (the half-turn swaps the ends of the cross-section), source to target if not.
struct Cut_band
{
  CGAL::Surface_mesh<Kd::Point_3> sm;
  CGAL::SM_Halfedge_index first, last;
};
Cut_band cut_band(int n, bool twisted)
{
  const double pi = std::acos(-1.0);
  Cut_band band;
  std::vector<CGAL::SM_Vertex_index> bottom, top;
  for (int i = 0; i <= n; ++i) {
    auto at = [&](double s) {
      const double u = 2 * pi * (i % n) / n, t = twisted ? u / 2 : 0, r = 2 + s * std::cos(t);
      return Kd::Point_3(r * std::cos(u), r * std::sin(u), s * std::sin(t));
    };
    // At the end the half-turn has swapped the cross-section's ends: the
    // points are written as the start's, exactly.
    const bool swapped = twisted && i == n;
    bottom.push_back(band.sm.add_vertex(at(swapped ? 0.5 : -0.5)));
    top.push_back(band.sm.add_vertex(at(swapped ? -0.5 : 0.5)));
  }
  for (int i = 0; i < n; ++i)
    band.sm.add_face(bottom[i], bottom[i + 1], top[i + 1], top[i]);
  band.first = band.sm.halfedge(bottom[0], top[0]);
  band.last = band.sm.halfedge(top[n], bottom[n]);
  return band;
}

TEST(Conversion, HandMadeSeamMakesMobiusStripOrAnnulus)
{
  for (bool twisted : {true, false}) {
    auto [sm, a, b] = cut_band(4, twisted);
    ASSERT_TRUE(sm.is_border(a));
    ASSERT_TRUE(sm.is_border(b));
    auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
    seam[a] = {b, twisted};
    seam[b] = {a, twisted};
    CGAL_ext::Mobius_mesh<Kd::Point_3> m;
    CGAL_ext::from_surface_mesh(sm, m);
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(m.number_of_vertices(), 8u);
    EXPECT_EQ(m.number_of_faces(), 4u);
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
    EXPECT_EQ(CGAL_ext::is_orientable(m), !twisted);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), twisted ? 1u : 2u);
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), twisted ? 1u : 0u);
  }
}

TEST(Conversion, BadSeamMapsThrowAndLeaveTheMeshAlone)
{
  const Soup soup = read_obj("nonorientable/mobius_min_5tris.obj");
  auto target = mesh_of<Kd::Point_3>(soup);
  const auto cycles = face_cycles(target);
  // `what` is the case, `says` a fragment of the message that names it.
  auto expect_error = [&](CGAL::Surface_mesh<Kd::Point_3>& sm, const std::string& what, const std::string& says) {
    try {
      CGAL_ext::from_surface_mesh(sm, target);
      ADD_FAILURE() << what << ": no Seam_error";
    } catch (const CGAL_ext::Seam_error& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << what << ": " << e.what();
    }
    EXPECT_EQ(target.number_of_vertices(), 5u) << what;
    EXPECT_EQ(face_cycles(target), cycles) << what;
  };
  {
    auto sm = strip(3);
    auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
    const auto a = end_border(sm, 0);
    const auto inner = sm.opposite(a); // a face halfedge
    seam[a] = {inner, true};
    seam[inner] = {a, true};
    expect_error(sm, "not a border halfedge", "not a border halfedge");
  }
  {
    auto sm = strip(3);
    auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
    seam[end_border(sm, 0)] = {end_border(sm, 3), true}; // one-sided
    expect_error(sm, "asymmetric", "is not matched by");
  }
  {
    // Gluing the two end edges of a single quad with a twist identifies its
    // diagonal corners: the quad would visit a vertex twice. (Its far corners
    // are put on the near ones, swapped, so that the ends are copies.)
    auto sm = strip(1);
    auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
    const auto a = end_border(sm, 0), b = end_border(sm, 1);
    sm.point(sm.source(b)) = sm.point(sm.source(a));
    sm.point(sm.target(b)) = sm.point(sm.target(a));
    seam[a] = {b, true};
    seam[b] = {a, true};
    expect_error(sm, "collapsing a face", "does not give a 2-manifold");
  }
  {
    // The end edges of a flat strip: equal lengths, but four units apart.
    auto sm = strip(4);
    auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
    const auto a = end_border(sm, 0), b = end_border(sm, 4);
    seam[a] = {b, false};
    seam[b] = {a, false};
    expect_error(sm, "copies apart", "which lie apart");
  }
  {
    // One end of a band stretched: the linked edges differ in length.
    auto [sm, a, b] = cut_band(4, true);
    auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
    seam[a] = {b, true};
    seam[b] = {a, true};
    sm.point(sm.target(b)) = sm.point(sm.target(b)) + Kd::Vector_3(0, 0, 0.25);
    expect_error(sm, "lengths differ", "differ in length");
  }
  {
    // A link to a removed halfedge (an edit without collect_garbage()).
    auto [sm, a, b] = cut_band(4, true);
    auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
    seam[a] = {b, true};
    seam[b] = {a, true};
    CGAL::Euler::remove_face(sm.opposite(b), sm);
    expect_error(sm, "removed partner", "has been removed");
  }
}

TEST(Conversion, SeamSplitOnBothSidesIsRefused)
{
  // An annulus of 4 quads cut open, whose two end edges were both split at
  // their midpoints (the end faces are pentagons): only the lower halves are
  // linked, the upper halves would stay a slit.
  const double pi = std::acos(-1.0);
  CGAL::Surface_mesh<Kd::Point_3> sm;
  std::vector<CGAL::SM_Vertex_index> bottom, top;
  for (int i = 0; i <= 4; ++i) {
    const double u = pi / 2 * (i % 4);
    bottom.push_back(sm.add_vertex(Kd::Point_3(2 * std::cos(u), 2 * std::sin(u), 0)));
    top.push_back(sm.add_vertex(Kd::Point_3(2 * std::cos(u), 2 * std::sin(u), 1)));
  }
  const auto mid_first = sm.add_vertex(Kd::Point_3(2, 0, 0.5)), mid_last = sm.add_vertex(Kd::Point_3(2, 0, 0.5));
  sm.add_face(std::vector<CGAL::SM_Vertex_index>{bottom[0], bottom[1], top[1], top[0], mid_first});
  for (int i = 1; i < 3; ++i)
    sm.add_face(bottom[i], bottom[i + 1], top[i + 1], top[i]);
  sm.add_face(std::vector<CGAL::SM_Vertex_index>{bottom[3], bottom[4], mid_last, top[4], top[3]});
  const auto lower_first = sm.halfedge(bottom[0], mid_first), lower_last = sm.halfedge(mid_last, bottom[4]);
  ASSERT_TRUE(sm.is_border(lower_first));
  ASSERT_TRUE(sm.is_border(lower_last));
  auto seam = sm.add_property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
  seam[lower_first] = {lower_last, false};
  seam[lower_last] = {lower_first, false};
  CGAL_ext::Mobius_mesh<Kd::Point_3> m;
  EXPECT_THROW(CGAL_ext::from_surface_mesh(sm, m), CGAL_ext::Seam_error);
  EXPECT_EQ(m.number_of_vertices(), 0u);
  // Linking the upper halves as well makes it whole: a closed-up annulus.
  const auto upper_first = sm.halfedge(mid_first, top[0]), upper_last = sm.halfedge(top[4], mid_last);
  seam[upper_first] = {upper_last, false};
  seam[upper_last] = {upper_first, false};
  CGAL_ext::from_surface_mesh(sm, m);
  EXPECT_EQ(m.number_of_vertices(), 9u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 2u);
  EXPECT_TRUE(CGAL_ext::is_orientable(m));
}

// The Klein bottle cut open and triangulated (triangulate_faces() keeps the
// seam: it adds diagonals inside faces only), and the length of its longest
// seam edge.
std::pair<CGAL::Surface_mesh<Kd::Point_3>, double> cut_klein_bottle()
{
  CGAL_ext::Mobius_mesh<Kd::Point_3> klein;
  CGAL_ext::make_klein_bottle(klein, 12, 8);
  CGAL::Surface_mesh<Kd::Point_3> sm;
  CGAL_ext::to_surface_mesh(klein, sm);
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  const auto seam = sm.property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
  double longest = 0;
  for (auto h : sm.halfedges())
    if (seam[h].partner != CGAL::SM_Halfedge_index())
      longest = std::max(longest, std::sqrt(CGAL::squared_distance(sm.point(sm.source(h)), sm.point(sm.target(h)))));
  return {std::move(sm), longest};
}

TEST(Conversion, RemeshingAcrossTheSeamIsRefused)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  for (double scale : {0.5, 1.0})
    for (bool collect_garbage : {false, true}) {
      auto [sm, longest] = cut_klein_bottle();
      PMP::isotropic_remeshing(faces(sm), scale * longest, sm);
      if (collect_garbage)
        sm.collect_garbage();
      CGAL_ext::Mobius_mesh<Kd::Point_3> target;
      CGAL_ext::make_mobius_strip(target, 3, 1);
      const auto cycles = face_cycles(target);
      EXPECT_THROW(CGAL_ext::from_surface_mesh(sm, target), CGAL_ext::Seam_error)
        << "target length " << scale << " x longest seam edge, collect_garbage " << collect_garbage;
      EXPECT_EQ(target.number_of_vertices(), 6u); // 3 around x 2 across
      EXPECT_EQ(face_cycles(target), cycles);
    }
}

TEST(Conversion, RemeshingWithTheSeamProtectedGluesBack)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto [sm, longest] = cut_klein_bottle();
  const std::size_t faces_before = sm.number_of_faces();
  // As doc/conversion_and_merging.md shows: the seam edges constrained.
  const auto seam = sm.property_map<CGAL::SM_Halfedge_index, CGAL_ext::Seam_link>(CGAL_ext::seam_map_name).first;
  auto on_seam = sm.add_property_map<CGAL::SM_Edge_index, bool>("e:on_seam", false).first;
  for (auto h : sm.halfedges())
    if (seam[h].partner != CGAL::SM_Halfedge_index())
      on_seam[sm.edge(h)] = true;
  PMP::isotropic_remeshing(faces(sm), longest, sm,
                           CGAL::parameters::edge_is_constrained_map(on_seam).protect_constraints(true));
  sm.remove_property_map(on_seam);
  ASSERT_NE(sm.number_of_faces(), faces_before); // the remeshing did change the mesh
  CGAL_ext::Mobius_mesh<Kd::Point_3> back;
  const auto glued = CGAL_ext::from_surface_mesh(sm, back);
  ASSERT_TRUE(back.is_valid(true));
  EXPECT_EQ(glued.seam_edges, 8u); // the weld's 8 edges, as cut
  EXPECT_EQ(CGAL_ext::euler_characteristic(back), 0);
  EXPECT_TRUE(CGAL_ext::is_closed(back));
  EXPECT_FALSE(CGAL_ext::is_orientable(back));
  EXPECT_EQ(back.number_of_faces(), sm.number_of_faces());
}

TEST(Conversion, BoolMapsGoBothWays)
{
  auto mesh = mesh_of<Kd::Point_3>(read_obj("nonorientable/torus_24x12_quads.obj"));
  auto even = mesh.add_property_map<CGAL_ext::Face_index, bool>("f:even", false).first;
  for (auto f : mesh.faces())
    even[f] = f.idx() % 2 == 0;
  using SM = CGAL::Surface_mesh<Kd::Point_3>;
  SM sm;
  CGAL_ext::to_surface_mesh(mesh, sm); // orientable and empty: faces keep their indices
  const auto [sm_even, found] = sm.property_map<SM::Face_index, bool>("f:even");
  ASSERT_TRUE(found);
  std::size_t n = 0;
  for (auto f : sm.faces()) {
    EXPECT_EQ(bool(sm_even[f]), f.idx() % 2 == 0);
    n += sm_even[f] ? 1 : 0;
  }
  EXPECT_EQ(n, 288u / 2);
  CGAL_ext::Mobius_mesh<Kd::Point_3> back;
  CGAL_ext::from_surface_mesh(sm, back);
  const auto back_even = back.property_map<CGAL_ext::Face_index, bool>("f:even");
  ASSERT_TRUE(back_even);
  for (auto f : back.faces())
    EXPECT_EQ((*back_even)[f], f.idx() % 2 == 0);
}

} // namespace

} // namespace conversion_tests
