// Corner channels (face-varying data): the API, the mesh operations that
// keep them (copies, orientation, conversion to Surface_mesh and back,
// triangulation and the Euler operations, merging, decimation, remeshing,
// offsets), and subdivision against OpenSubdiv 3.5's
// PrimvarRefinerReal<double>::InterpolateFaceVarying in each of its six
// linear-interpolation modes, on its own shapes and on the orientation double
// cover of a Möbius strip; the parallel path against the serial one, bit for bit;
// limit values of a channel (limit_corner_values(), limit_face_varying())
// against PrimvarRefinerReal<double>::LimitFaceVarying() on the same shapes,
// random grids, a Möbius strip and a Klein bottle, and in exact arithmetic.
#include "opensubdiv_tags.h"
#include "test_util.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/decimation.h>
#include <CGAL_ext/isotropic_remeshing.h>
#include <CGAL_ext/merge_borders.h>
#include <CGAL_ext/offset_mesh.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/Limit_surface/Corner_channel_limit_surface.h>
#include <CGAL_ext/Subdivision/limit.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace corner_channel_tests {

namespace {

namespace S = CGAL_ext::Subdivision;
using CGAL_ext::Dart;
using CGAL_ext::Face_varying_interpolation;
using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using UV = std::array<double, 2>;

// Each corner gets its own value, (vertex, face): a seam everywhere, so the
// value of a corner tells where it must stay.
void fill_distinct(Mesh& m)
{
  auto uv = m.add_corner_channel<UV>("c:uv").first;
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, m))
      uv.set_index(m.corner(d), uv.add_value({double(m.target(d).idx()), double(f.idx())}));
}

// Every corner of `m` holds the value (its vertex, its face), up to the
// offsets of a copy.
void expect_at_their_corners(const Mesh& m, unsigned vertex_offset = 0, unsigned face_offset = 0,
                             unsigned first_face = 0, unsigned end_face = UINT32_MAX)
{
  const auto uv = m.corner_channel<UV>("c:uv");
  ASSERT_TRUE(uv.has_value());
  for (CGAL_ext::Face_index f : m.faces()) {
    if (f.idx() < first_face || f.idx() >= end_face)
      continue;
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      const UV& x = (*uv)[m.corner(d)];
      EXPECT_EQ(x[0] + vertex_offset, double(m.target(d).idx()));
      EXPECT_EQ(x[1] + face_offset, double(f.idx()));
      // The flipped dart walks the face the other way; its corner at its own target.
      EXPECT_EQ(m.corner(d.flipped()), m.corner(m.prev(d)));
    }
  }
}

TEST(CornerChannels, AddFindRemove)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 6, 2);
  auto [uv, created] = m.add_corner_channel<UV>("c:uv");
  EXPECT_TRUE(created);
  EXPECT_FALSE(m.add_corner_channel<UV>("c:uv").second);
  EXPECT_EQ(m.add_corner_channel<UV>("c:uv").first, uv);
  EXPECT_FALSE((m.add_corner_channel<std::array<float, 2>>("c:uv").first)); // the name is taken by another type
  EXPECT_FALSE((m.corner_channel<std::array<float, 2>>("c:uv").has_value()));
  EXPECT_FALSE((m.property_map<CGAL_ext::Halfedge_index, std::uint32_t>("c:uv").has_value()));
  auto normal = m.add_corner_channel<test::Kd::Vector_3>("c:normal").first;
  EXPECT_EQ(m.corner_channels(), (std::vector<std::string>{"c:uv", "c:normal"}));
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    EXPECT_EQ(uv.index(h), uv.no_value());
  const std::uint32_t i = uv.add_value({0.25, 0.5});
  const Dart d = m.halfedge(CGAL_ext::Face_index(0));
  uv.set_index(m.corner(d), i);
  EXPECT_EQ(uv[m.corner(d)], (UV{0.25, 0.5}));
  EXPECT_TRUE(m.remove_corner_channel(normal));
  EXPECT_FALSE(normal);
  EXPECT_EQ(m.corner_channels(), (std::vector<std::string>{"c:uv"}));
  EXPECT_TRUE(m.is_valid());
}

// Dropping the values no corner names keeps the order of the others and,
// where asked, a prefix whether named or not (an editor that holds indices
// into it: the remesher's table of the input's corners).
TEST(CornerChannels, UnusedValuesDroppedAfterAKeptPrefix)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 6, 2);
  auto uv = m.add_corner_channel<UV>("c:uv").first;
  for (int i = 0; i < 8; ++i)
    uv.add_value({double(i), 0});
  std::vector<CGAL_ext::Halfedge_index> corners;
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      corners.push_back(m.corner(d));
  // Values 1, 4 and 6 are named, 1 by all corners but two.
  for (const CGAL_ext::Halfedge_index h : corners)
    uv.set_index(h, 1);
  uv.set_index(corners[0], 6);
  uv.set_index(corners[1], 4);
  uv.array()->remove_unused_values(3);
  EXPECT_EQ(uv.values(), (std::vector<UV>{{0, 0}, {1, 0}, {2, 0}, {4, 0}, {6, 0}}));
  EXPECT_EQ(uv[corners[0]], (UV{6, 0}));
  EXPECT_EQ(uv[corners[1]], (UV{4, 0}));
  EXPECT_EQ(uv.index(corners[2]), 1u);
  uv.array()->remove_unused_values(0);
  EXPECT_EQ(uv.values(), (std::vector<UV>{{1, 0}, {4, 0}, {6, 0}}));
  EXPECT_EQ(uv[corners[0]], (UV{6, 0}));
  EXPECT_EQ(uv[corners[1]], (UV{4, 0}));
  EXPECT_EQ(uv[corners.back()], (UV{1, 0}));
  for (CGAL_ext::Halfedge_index h : m.halfedges()) // the border's slots name none
    if (m.is_border(h))
      EXPECT_EQ(uv.index(h), uv.no_value());
}

TEST(CornerChannels, MeshOperationsKeepCorners)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 10, 3);
  fill_distinct(m);
  for (CGAL_ext::Face_index f : m.faces()) // corners stay at their vertices
    if (f.idx() % 3 != 1)
      m.reverse_face_orientation(f);
  expect_at_their_corners(m);
  CGAL_ext::orient(m);
  expect_at_their_corners(m);
  const Mesh copy = m;
  expect_at_their_corners(copy);
  Mesh joined = m;
  const auto off = joined.join(m);
  expect_at_their_corners(joined, off.vertices, off.faces, off.faces);
  expect_at_their_corners(joined, 0, 0, 0, off.faces); // the first part
  EXPECT_EQ(joined.corner_channel<UV>("c:uv")->number_of_values(), 2 * m.corner_channel<UV>("c:uv")->number_of_values());
}

TEST(CornerChannels, GarbageCollection)
{
  Mesh m;
  CGAL_ext::make_torus(m, 6, 4, 2.0, 0.5);
  fill_distinct(m);
  // Remove a face, its edges and vertices that have no other face are kept: a hole.
  const CGAL_ext::Face_index gone(3);
  std::vector<std::pair<double, double>> expected; // (vertex, face) of the corners that stay, by old indices
  m.remove_face(gone);
  for (Dart d : CGAL_ext::halfedges_around_face(gone, m))
    m.set_face(d.halfedge(), CGAL_ext::Face_index());
  Mesh::Garbage_collection_maps maps;
  m.collect_garbage(maps);
  const auto uv = *m.corner_channel<UV>("c:uv");
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      const UV& x = uv[m.corner(d)];
      EXPECT_EQ(maps(CGAL_ext::Vertex_index(std::uint32_t(x[0]))), m.target(d));
      EXPECT_EQ(maps(CGAL_ext::Face_index(std::uint32_t(x[1]))), f);
    }
}

// Every corner of `m` holds the value (its vertex, something): the vertex
// part tells that each corner kept a value of its own vertex. Corners
// without a value are counted.
std::size_t expect_vertex_values(const Mesh& m)
{
  const auto uv = m.corner_channel<UV>("c:uv");
  EXPECT_TRUE(uv.has_value());
  std::size_t without = 0;
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      if (!uv->has_value(m.corner(d))) {
        ++without;
        continue;
      }
      EXPECT_EQ((*uv)[m.corner(d)][0], double(m.target(d).idx())) << "face " << f << " at " << m.target(d);
    }
  return without;
}

TEST(CornerChannels, SurfaceMeshConversionBothWays)
{
  using SM = CGAL::Surface_mesh<Point>;
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 10, 3);
  fill_distinct(m);
  // A channel of the kernel's 2D points, one of a type a Surface_mesh is not
  // given, and a corner without a value.
  auto st = m.add_corner_channel<test::Kd::Point_2>("c:st").first;
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, m))
      st.set_index(m.corner(d), st.add_value(test::Kd::Point_2(m.target(d).idx(), -double(f.idx()))));
  struct Tag { int x; };
  m.add_corner_channel<Tag>("c:tag");
  st.set_index(m.corner(m.halfedge(CGAL_ext::Face_index(4u))), st.no_value());
  SM sm;
  std::vector<std::pair<CGAL_ext::Vertex_index, SM::Vertex_index>> vertex_pairs;
  const CGAL_ext::Conversion_result r =
    CGAL_ext::to_surface_mesh(m, sm, CGAL_ext::parameters::vertex_to_vertex_output_iterator(std::back_inserter(vertex_pairs)));
  ASSERT_GT(r.seam_edges, 0u); // cut, and faces reversed
  EXPECT_EQ(r.corner_channels_not_carried, std::vector<std::string>{"c:tag"});
  EXPECT_EQ(r.corners_without_value, 1u);
  std::map<SM::Vertex_index, std::size_t> original;
  for (const auto& [v, s] : vertex_pairs)
    original[s] = v.idx();
  const auto [uv_sm, found] = sm.property_map<SM::Halfedge_index, UV>("c:uv");
  ASSERT_TRUE(found);
  for (SM::Face_index f : sm.faces())
    for (SM::Halfedge_index h : CGAL::halfedges_around_face(sm.halfedge(f), sm)) {
      EXPECT_EQ(uv_sm[h][0], double(original.at(sm.target(h))));
      EXPECT_EQ(uv_sm[h][1], double(std::size_t(f)));
    }
  Mesh back;
  CGAL_ext::from_surface_mesh(sm, back);
  expect_at_their_corners(back);
  EXPECT_EQ(CGAL_ext::corner_channel_summaries(back)[0].seam_edges, CGAL_ext::corner_channel_summaries(m)[0].seam_edges);
  const auto st_back = back.corner_channel<test::Kd::Point_2>("c:st");
  ASSERT_TRUE(st_back.has_value());
  for (CGAL_ext::Face_index f : back.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, back)) {
      const bool missing = f.idx() == 4 && back.target(d) == m.target(m.halfedge(f));
      EXPECT_EQ((*st_back)[back.corner(d)],
                missing ? test::Kd::Point_2(CGAL::ORIGIN) : test::Kd::Point_2(back.target(d).idx(), -double(f.idx())));
    }
  EXPECT_FALSE(back.corner_channel<Tag>("c:tag").has_value());
}

// Texture coordinates continuous across an edge come back continuous: the
// Surface_mesh holds a value per halfedge, and equal values at a vertex are
// one value again.
TEST(CornerChannels, SurfaceMeshConversionKeepsSeamsOnly)
{
  Mesh m;
  CGAL_ext::IO::read_polygon_mesh(test::data("opensubdiv/catmark_chaikin1.obj"), m);
  CGAL::Surface_mesh<Point> sm;
  CGAL_ext::to_surface_mesh(m, sm);
  Mesh back;
  CGAL_ext::from_surface_mesh(sm, back);
  const auto a = CGAL_ext::corner_channel_summaries(m), b = CGAL_ext::corner_channel_summaries(back);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(a[i].seam_edges, b[i].seam_edges) << a[i].name;
}

// The Euler operations' tests' surfaces: a Möbius strip or a torus of quads.
Mesh strip_or_torus(bool mobius)
{
  Mesh m;
  if (mobius)
    CGAL_ext::make_mobius_strip(m, 10, 3);
  else
    CGAL_ext::make_torus(m, 6, 4, 2.0, 0.5);
  return m;
}

// The value indices that the face corners of `m` name.
std::set<std::uint32_t> named_indices(const Mesh& m)
{
  const auto uv = *m.corner_channel<UV>("c:uv");
  std::set<std::uint32_t> named;
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      if (uv.has_value(m.corner(d)))
        named.insert(uv.index(m.corner(d)));
  return named;
}

TEST(CornerChannels, TriangulationAndEulerOperationsKeepValuesAtTheirVertices)
{
  for (bool mobius : {false, true}) {
    SCOPED_TRACE(mobius ? "Moebius strip" : "torus");
    Mesh m = strip_or_torus(mobius);
    fill_distinct(m);
    const std::size_t n_faces = m.number_of_faces();
    EXPECT_EQ(CGAL_ext::triangulate_faces(m), n_faces);
    EXPECT_EQ(expect_vertex_values(m), 0u);
    // Flips: the diagonal's corners take values their faces had at the far corners.
    std::size_t flips = 0;
    for (CGAL_ext::Edge_index e : m.edges())
      if (flips < 8 && CGAL_ext::Euler::can_flip_edge(Dart(Mesh::halfedge(e, 0), false), m)) {
        CGAL_ext::Euler::flip_edge(Dart(Mesh::halfedge(e, 0), false), m);
        ++flips;
      }
    EXPECT_EQ(flips, 8u);
    EXPECT_EQ(expect_vertex_values(m), 0u);
    // A centre vertex: its own corners have no value, the others keep theirs.
    const Dart d = m.halfedge(CGAL_ext::Face_index(2u));
    CGAL_ext::Euler::add_center_vertex(d, m);
    EXPECT_EQ(expect_vertex_values(m), 3u);
    // An edge split: the two faces' corners at the new vertex have none.
    CGAL_ext::Edge_index inner;
    for (CGAL_ext::Edge_index e : m.edges())
      if (!inner.is_valid() && !m.is_border(e))
        inner = e;
    CGAL_ext::Euler::split_edge(Dart(Mesh::halfedge(inner, 0), false), m);
    EXPECT_EQ(expect_vertex_values(m), 5u);
    // A hole made and filled again: the border held no corner, the new face has no values.
    CGAL_ext::Face_index last; // the last face off the border, so that the hole is its own
    for (CGAL_ext::Face_index f : m.faces()) {
      bool inner = true;
      for (Dart c : CGAL_ext::halfedges_around_face(f, m))
        inner = inner && !m.is_border(m.opposite(c));
      if (inner)
        last = f;
    }
    std::size_t valued = 0;
    for (Dart c : CGAL_ext::halfedges_around_face(last, m))
      valued += m.corner_channel<UV>("c:uv")->has_value(m.corner(c)) ? 1 : 0;
    CGAL_ext::Euler::fill_hole(CGAL_ext::Euler::make_hole(m.halfedge(last), m), m);
    EXPECT_EQ(expect_vertex_values(m), 5u + valued);
    EXPECT_TRUE(m.is_valid());
  }
}

// The Euler operations that remove edges leave their corners without a
// value, so that they keep none alive: after joins, collapses and a centre
// vertex removed, the values left once unused ones are dropped are those of
// the live corners, counted on their own.
TEST(CornerChannels, RemovedEdgesNameNoValue)
{
  for (bool mobius : {false, true}) {
    SCOPED_TRACE(mobius ? "Moebius strip" : "torus");
    Mesh m = strip_or_torus(mobius);
    CGAL_ext::triangulate_faces(m);
    fill_distinct(m);
    std::size_t joins = 0, collapses = 0;
    const std::vector<CGAL_ext::Edge_index> edges(m.edges().begin(), m.edges().end());
    for (CGAL_ext::Edge_index e : edges) {
      const Dart d(Mesh::halfedge(e, 0), false);
      if (m.is_removed(e))
        continue;
      if (joins < 3 && CGAL_ext::Euler::can_join_face(d, m)) {
        CGAL_ext::Euler::join_face(d, m);
        ++joins;
      } else if (collapses < 3 && CGAL_ext::Euler::does_satisfy_link_condition(d, m)) {
        CGAL_ext::Euler::collapse_edge(d, m);
        ++collapses;
      }
    }
    EXPECT_EQ(joins, 3u);
    EXPECT_EQ(collapses, 3u);
    Dart centre;
    for (CGAL_ext::Vertex_index v : m.vertices())
      if (!centre.is_valid() && CGAL_ext::Euler::can_remove_center_vertex(m.halfedge(v), m))
        centre = m.halfedge(v);
    ASSERT_TRUE(centre.is_valid());
    CGAL_ext::Euler::remove_center_vertex(centre, m);
    ASSERT_TRUE(m.is_valid());
    auto uv = *m.corner_channel<UV>("c:uv");
    const std::set<std::uint32_t> named = named_indices(m);
    for (std::uint32_t h = 0; h < m.num_halfedges(); ++h)
      if (m.is_removed(CGAL_ext::Halfedge_index(h)))
        EXPECT_EQ(uv.index(CGAL_ext::Halfedge_index(h)), uv.no_value()) << "removed halfedge " << h;
    uv.array()->remove_unused_values(0);
    EXPECT_EQ(uv.values().size(), named.size());
  }
}

// CGAL's generic Euler::remove_face() knows of no channel: the face's
// halfedges turn border ones with the indices they held. Remeshing drops
// the values that only they named, as those of the corners it removes.
TEST(CornerChannels, BorderSlotsLeftByCgalsRemoveFaceKeepNoValue)
{
  Mesh m;
  CGAL_ext::make_torus(m, 8, 6, 2.0, 0.5);
  CGAL_ext::triangulate_faces(m);
  fill_distinct(m);
  CGAL::Euler::remove_face(m.halfedge(CGAL_ext::Face_index(5u)), m);
  m.collect_garbage();
  auto uv = *m.corner_channel<UV>("c:uv");
  std::size_t border_indices = 0;
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    border_indices += m.is_border(h) && uv.has_value(h) ? 1 : 0;
  EXPECT_EQ(border_indices, 3u); // the case: the removed triangle's slots kept theirs
  CGAL_ext::isotropic_remeshing(m, 0.5, CGAL_ext::parameters::number_of_iterations(1));
  uv = *m.corner_channel<UV>("c:uv");
  const std::set<std::uint32_t> named = named_indices(m);
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    if (m.is_border(h))
      EXPECT_EQ(uv.index(h), uv.no_value()) << "border halfedge " << h;
  EXPECT_EQ(uv.values().size(), named.size());
}

TEST(CornerChannels, MergingKeepsEachCornersValue)
{
  // Two 2x2 grids side by side; the corners of the second hold x + 10.
  auto grid = [](double x0) {
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> quads;
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i)
        points.emplace_back(x0 + 0.5 * i, 0.5 * j, 0);
    for (std::size_t j = 0; j < 2; ++j)
      for (std::size_t i = 0; i < 2; ++i)
        quads.push_back({3 * j + i, 3 * j + i + 1, 3 * j + i + 4, 3 * j + i + 3});
    Mesh m;
    CGAL_ext::polygon_soup_to_mobius_mesh(points, quads, m);
    auto uv = m.add_corner_channel<UV>("c:uv").first;
    for (CGAL_ext::Vertex_index v : m.vertices()) // one value per vertex: no seam
      uv.add_value({m.point(v).x() + (x0 > 0 ? 10 : 0), m.point(v).y()});
    for (CGAL_ext::Face_index f : m.faces())
      for (Dart d : CGAL_ext::halfedges_around_face(f, m))
        uv.set_index(m.corner(d), m.target(d).idx());
    return m;
  };
  Mesh a = grid(0), b = grid(1);
  const CGAL_ext::Merge_result r = CGAL_ext::merge_borders(a, b);
  EXPECT_EQ(r.merged_vertices, 3u);
  const auto uv = *a.corner_channel<UV>("c:uv");
  for (CGAL_ext::Face_index f : a.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, a)) {
      const Point& p = a.point(a.target(d));
      EXPECT_EQ(uv[a.corner(d)], (UV{p.x() + (f.idx() >= 4 ? 10 : 0), p.y()})) << "face " << f;
    }
  EXPECT_EQ(CGAL_ext::corner_channel_summaries(a)[0].seam_edges, 2u); // the glued edges
}

TEST(CornerChannels, RemeshingAndDecimationKeepSeams)
{
  Mesh m;
  CGAL_ext::make_torus(m, 8, 6, 2.0, 0.5);
  fill_distinct(m);
  const std::size_t faces = m.number_of_faces();
  // Remeshing protects seams: here every edge of the quads is one (each
  // corner has a value of its own) and every vertex is on one, so only the
  // quads' diagonals (no seam: a triangulated quad's corners copy its
  // values) and what their splits make are edited. Every vertex of the
  // input keeps its point and, in every face, the value of the quad that
  // face lies in; every face's corners hold values of one quad.
  {
    Mesh remeshed = m;
    CGAL_ext::isotropic_remeshing(remeshed, 0.3, CGAL_ext::parameters::number_of_iterations(3));
    EXPECT_TRUE(remeshed.is_valid());
    EXPECT_GT(remeshed.number_of_faces(), 2 * faces);
    const auto uv = remeshed.corner_channel<UV>("c:uv");
    for (CGAL_ext::Vertex_index v : m.vertices())
      EXPECT_EQ(remeshed.point(v), m.point(v));
    for (CGAL_ext::Face_index f : remeshed.faces()) {
      const double quad = (*uv)[remeshed.corner(remeshed.halfedge(f))][1];
      for (Dart d : CGAL_ext::halfedges_around_face(f, remeshed)) {
        EXPECT_NEAR((*uv)[remeshed.corner(d)][1], quad, 1e-12); // a blend of the quad's values
        if (remeshed.target(d).idx() < m.number_of_vertices())
          EXPECT_EQ((*uv)[remeshed.corner(d)][0], double(remeshed.target(d).idx()));
      }
    }
  }
  // Decimation carries channels and never collapses a seam: here every corner
  // has a value of its own, so every edge of the quads is one and every
  // vertex a seam vertex (the triangulation's diagonals join two, which no
  // collapse joins). The quads are triangulated, nothing collapses or moves,
  // and each corner keeps its value.
  Mesh decimated = m;
  EXPECT_EQ(CGAL_ext::decimate(decimated, CGAL_ext::parameters::face_ratio(0.5)).collapses, 0u);
  EXPECT_EQ(decimated.number_of_faces(), 2 * faces);
  const auto uv = decimated.corner_channel<UV>("c:uv");
  for (CGAL_ext::Face_index f : decimated.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, decimated))
      EXPECT_EQ((*uv)[decimated.corner(d)][0], double(decimated.target(d).idx()));
  // Without the channel it decimates.
  EXPECT_TRUE(m.remove_corner_channel("c:uv"));
  CGAL_ext::decimate(m, CGAL_ext::parameters::face_ratio(0.25));
  EXPECT_LT(m.number_of_faces(), faces);
}

// Offsets carry channels. Each corner of the offset is matched to the input
// corner it copies by geometry alone: its point lies `distance` from the
// input vertex, and its face's points so from an input face's vertices. That
// corner's texture coordinates are the input corner's; its corner normal is
// the input's where the copy faces the way the input face does, and the
// opposite where it faces the other way (a copy on the face's back side).
// A rim corner has no value.
template <class K>
void expect_offset_carries_channels(const CGAL_ext::Mobius_mesh<typename K::Point_3>& in, double distance)
{
  using P = typename K::Point_3;
  using M = CGAL_ext::Mobius_mesh<P>;
  using Normal = CGAL_ext::Corner_normal<P>;
  M out;
  const CGAL_ext::Offset_result r = CGAL_ext::offset_mesh(in, distance, out, CGAL_ext::parameters::solid(true));
  const auto uv_in = *in.template corner_channel<UV>("c:uv"), uv_out = *out.template corner_channel<UV>("c:uv");
  const auto n_in = *in.template corner_channel<Normal>("c:normal");
  const auto n_out = *out.template corner_channel<Normal>("c:normal");
  const auto nearest = [&](const P& q) {
    CGAL_ext::Vertex_index best;
    double d = HUGE_VAL;
    for (CGAL_ext::Vertex_index v : in.vertices())
      if (CGAL::to_double(CGAL::squared_distance(q, in.point(v))) < d) {
        d = CGAL::to_double(CGAL::squared_distance(q, in.point(v)));
        best = v;
      }
    EXPECT_NEAR(std::sqrt(d), distance, 1e-9);
    return best;
  };
  const auto normal_of = [](const auto& mesh, CGAL_ext::Face_index f) {
    const Dart d = mesh.halfedge(f);
    return CGAL::cross_product(mesh.point(mesh.target(d)) - mesh.point(mesh.source(d)),
                               mesh.point(mesh.target(mesh.next(d))) - mesh.point(mesh.target(d)));
  };
  std::size_t without = 0, matched_front = 0, matched_back = 0;
  for (CGAL_ext::Face_index g : out.faces()) {
    std::map<std::size_t, Dart> corner_at; // input vertex -> the output corner
    for (Dart d : CGAL_ext::halfedges_around_face(g, out))
      corner_at[nearest(out.point(out.target(d))).idx()] = d;
    CGAL_ext::Face_index source;
    for (CGAL_ext::Face_index f : in.faces()) {
      std::map<std::size_t, Dart> at;
      for (Dart d : CGAL_ext::halfedges_around_face(f, in))
        at[in.target(d).idx()] = d;
      bool same = at.size() == corner_at.size();
      for (auto it = at.begin(), jt = corner_at.begin(); same && it != at.end(); ++it, ++jt)
        same = it->first == jt->first;
      if (same)
        source = f;
    }
    for (Dart d : CGAL_ext::halfedges_around_face(g, out)) {
      if (!source.is_valid()) { // a rim quad: its corners join two lifts of one border edge
        EXPECT_FALSE(uv_out.has_value(out.corner(d)));
        EXPECT_FALSE(n_out.has_value(out.corner(d)));
        ++without;
        continue;
      }
      Dart e;
      for (Dart c : CGAL_ext::halfedges_around_face(source, in))
        if (in.target(c).idx() == nearest(out.point(out.target(d))).idx())
          e = c;
      ASSERT_TRUE(uv_out.has_value(out.corner(d)));
      EXPECT_EQ(uv_out[out.corner(d)], uv_in[in.corner(e)]);
      const bool facing = CGAL::to_double(normal_of(out, g) * normal_of(in, source)) > 0;
      EXPECT_EQ(n_out[out.corner(d)], facing ? n_in[in.corner(e)] : -n_in[in.corner(e)]);
      ++(facing ? matched_front : matched_back);
    }
  }
  EXPECT_EQ(r.corners_without_values, without);
  EXPECT_EQ(without, 4 * r.rim_faces);
  EXPECT_GT(matched_front, 0u); // both sides of the input's faces
  EXPECT_EQ(matched_back, matched_front);
}

// Texture coordinates distinct at every corner, and as corner normals each
// face's own normal, tilted differently at each corner so that no two are
// equal. With `reverse_first`, the first face is taken the other way round
// (a Möbius edge on each of its sides, which the offset's orientation
// removes by reversing it: its normals must turn with it).
template <class K>
CGAL_ext::Mobius_mesh<typename K::Point_3> with_uv_and_normals(const Mesh& shape, bool reverse_first = false)
{
  using P = typename K::Point_3;
  CGAL_ext::Mobius_mesh<P> m;
  std::vector<P> points;
  for (CGAL_ext::Vertex_index v : shape.vertices())
    points.emplace_back(shape.point(v).x(), shape.point(v).y(), shape.point(v).z());
  std::vector<std::vector<std::size_t>> faces;
  for (CGAL_ext::Face_index f : shape.faces()) {
    faces.emplace_back();
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(shape.halfedge(f), shape))
      faces.back().push_back(v.idx());
  }
  if (reverse_first)
    std::reverse(faces[0].begin(), faces[0].end());
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m, CGAL_ext::parameters::keep_orientation(true));
  auto uv = m.template add_corner_channel<UV>("c:uv").first;
  auto normal = m.template add_corner_channel<CGAL_ext::Corner_normal<P>>("c:normal").first;
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      uv.set_index(m.corner(d), uv.add_value({double(m.target(d).idx()), double(f.idx())}));
      const auto n = CGAL::cross_product(m.point(m.target(d)) - m.point(m.source(d)),
                                         m.point(m.target(m.next(d))) - m.point(m.target(d)));
      normal.set_index(m.corner(d), normal.add_value(n + typename K::Vector_3(0, 0, 1e-3 * (d.halfedge().idx() + 1))));
    }
  return m;
}

TEST(CornerChannels, OffsetsCarryThemOnBothSides)
{
  Mesh torus, strip;
  CGAL_ext::make_torus(torus, 8, 6, 2.0, 0.5);
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  {
    SCOPED_TRACE("torus, double");
    expect_offset_carries_channels<test::Kd>(with_uv_and_normals<test::Kd>(torus), 0.1);
  }
  {
    SCOPED_TRACE("torus with a face the other way round, double");
    const auto m = with_uv_and_normals<test::Kd>(torus, true);
    ASSERT_TRUE(CGAL_ext::has_mobius_edges(m));
    expect_offset_carries_channels<test::Kd>(m, 0.1);
  }
  {
    SCOPED_TRACE("Möbius strip, double");
    expect_offset_carries_channels<test::Kd>(with_uv_and_normals<test::Kd>(strip), 0.05);
  }
  {
    SCOPED_TRACE("Möbius strip, EPECK");
    expect_offset_carries_channels<CGAL::Exact_predicates_exact_constructions_kernel>(
      with_uv_and_normals<CGAL::Exact_predicates_exact_constructions_kernel>(strip), 0.05);
  }
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// An OpenSubdiv shape with its `vt` corner indices, read by a small parser
// of its own for OpenSubdiv's side (the library's reader makes our side).
struct Shape : test::Osd_tags
{
  std::vector<Point> points;
  std::vector<UV> uvs;
  std::vector<std::vector<int>> faces, uv_faces;
};

Shape read_shape(const std::string& file)
{
  Shape s;
  std::ifstream in(file);
  EXPECT_TRUE(bool(in)) << file;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      double x, y, z;
      ls >> x >> y >> z;
      s.points.emplace_back(x, y, z);
    } else if (tag == "vt") {
      UV t;
      ls >> t[0] >> t[1];
      s.uvs.push_back(t);
    } else if (tag == "f") {
      std::vector<int> f, ft;
      std::string c;
      while (ls >> c) { // v/vt or v/vt/vn
        const std::size_t slash = c.find('/');
        f.push_back(std::stoi(c.substr(0, slash)) - 1);
        ft.push_back(std::stoi(c.substr(slash + 1)) - 1);
      }
      s.faces.push_back(f);
      s.uv_faces.push_back(ft);
    } else if (tag == "t") {
      s.read(ls);
    }
  }
  return s;
}

// The mesh of a shape with its sharpness maps and its channel "c:uv", filled
// through the API from the `f v/vt` indices.
Mesh build(const Shape& s)
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m);
  s.add_sharpness_maps(m);
  auto uv = m.add_corner_channel<UV>("c:uv").first;
  uv.values() = s.uvs;
  for (CGAL_ext::Face_index f : m.faces()) {
    const std::vector<int>& vs_of_f = s.faces[f.idx()]; // the import keeps the soup's order
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      const auto at = std::find(vs_of_f.begin(), vs_of_f.end(), int(m.target(d).idx()));
      EXPECT_NE(at, vs_of_f.end());
      uv.set_index(m.corner(d), std::uint32_t(s.uv_faces[f.idx()][std::size_t(at - vs_of_f.begin())]));
    }
  }
  return m;
}

struct Osd_value
{
  double p[3];
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0.0; }
  void AddWithWeight(const Osd_value& s, double w)
  {
    for (int i = 0; i < 3; ++i)
      p[i] += w * s.p[i];
  }
};

// A face corner of the last level: where it is, and its value.
struct Corner
{
  std::array<double, 3> centre, point;
  UV uv;
};

// OpenSubdiv's refiner of `reference` (faces, texture coordinates as
// channel 0), with the tags and options of `s` and the mode `mode`.
std::unique_ptr<Far::TopologyRefiner> refiner_with_uv(const Shape& reference, const Shape& s, bool loop,
                                                      Face_varying_interpolation mode)
{
  std::vector<int> sizes, indices, uv_indices;
  for (std::size_t f = 0; f < reference.faces.size(); ++f) {
    sizes.push_back(int(reference.faces[f].size()));
    indices.insert(indices.end(), reference.faces[f].begin(), reference.faces[f].end());
    uv_indices.insert(uv_indices.end(), reference.uv_faces[f].begin(), reference.uv_faces[f].end());
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = int(reference.points.size());
  desc.numFaces = int(reference.faces.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  const std::vector<int> crease_indices = reference.crease_indices();
  desc.numCreases = int(reference.crease_values.size());
  desc.creaseVertexIndexPairs = crease_indices.data();
  desc.creaseWeights = reference.crease_values.data();
  desc.numCorners = int(reference.corners.size());
  desc.cornerVertexIndices = reference.corners.data();
  desc.cornerWeights = reference.corner_values.data();
  Far::TopologyDescriptor::FVarChannel channel;
  channel.numValues = int(reference.uvs.size());
  channel.valueIndices = uv_indices.data();
  desc.numFVarChannels = 1;
  desc.fvarChannels = &channel;
  Sdc::Options options = test::opensubdiv_options(s);
  options.SetFVarLinearInterpolation(Sdc::Options::FVarLinearInterpolation(int(mode)));
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(
    Factory::Create(desc, Factory::Options(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, options)));
}

// OpenSubdiv's last level's corners after `levels` steps.
// With `limit`, the values are their limits (PrimvarRefiner::LimitFaceVarying()
// on the last level, which needs its full topology).
std::vector<Corner> opensubdiv_corners(const Shape& s, Sdc::SchemeType type, int levels, Face_varying_interpolation mode,
                                       bool limit = false)
{
  const std::unique_ptr<Far::TopologyRefiner> refiner = refiner_with_uv(s, s, type == Sdc::SCHEME_LOOP, mode);
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = limit;
  refiner->RefineUniform(uniform);
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  std::vector<Osd_value> points, uvs;
  for (const Point& p : s.points)
    points.push_back({{p.x(), p.y(), p.z()}});
  for (const UV& t : s.uvs)
    uvs.push_back({{t[0], t[1], 0.0}});
  for (int k = 1; k <= levels; ++k) {
    std::vector<Osd_value> p(refiner->GetLevel(k).GetNumVertices()), u(refiner->GetLevel(k).GetNumFVarValues(0));
    Osd_value *ps = points.data(), *pd = p.data(), *us = uvs.data(), *ud = u.data();
    primvar.Interpolate(k, ps, pd);
    primvar.InterpolateFaceVarying(k, us, ud, 0);
    points.swap(p);
    uvs.swap(u);
  }
  if (limit) {
    std::vector<Osd_value> u(uvs.size());
    primvar.LimitFaceVarying(uvs, u, 0);
    uvs.swap(u);
  }
  std::vector<Corner> corners;
  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const auto fv = last.GetFaceVertices(f);
    const auto fu = last.GetFaceFVarValues(f, 0);
    std::array<double, 3> c{0, 0, 0};
    for (int i = 0; i < fv.size(); ++i)
      for (int j = 0; j < 3; ++j)
        c[j] += points[fv[i]].p[j] / fv.size();
    for (int i = 0; i < fv.size(); ++i)
      corners.push_back({c, {points[fv[i]].p[0], points[fv[i]].p[1], points[fv[i]].p[2]}, {uvs[fu[i]].p[0], uvs[fu[i]].p[1]}});
  }
  return corners;
}

// The value of a corner: channels of std::array<double, 2> (built here) or
// of the kernel's Point_2 (made by the reader).
UV uv_at(const Mesh& m, Dart d)
{
  if (const auto uv = m.corner_channel<UV>("c:uv"))
    return (*uv)[m.corner(d)];
  const auto st = m.corner_channel<CGAL_ext::Corner_uv<Point>>("c:uv");
  const auto& p = (*st)[m.corner(d)];
  return {p.x(), p.y()};
}

std::vector<Corner> our_corners(const Mesh& m)
{
  std::vector<Corner> corners;
  for (CGAL_ext::Face_index f : m.faces()) {
    std::array<double, 3> c{0, 0, 0};
    const double n = double(CGAL_ext::halfedges_around_face(f, m).size());
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m)) {
      c[0] += m.point(v).x() / n;
      c[1] += m.point(v).y() / n;
      c[2] += m.point(v).z() / n;
    }
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      const Point& p = m.point(m.target(d));
      corners.push_back({c, {p.x(), p.y(), p.z()}, uv_at(m, d)});
    }
  }
  return corners;
}

// The largest difference of values between corners at the same place (face
// centre and point within 1e-9); every corner of each side must find one.
double max_difference(const std::vector<Corner>& ours, std::vector<Corner> theirs)
{
  EXPECT_EQ(ours.size(), theirs.size());
  auto before = [](const Corner& a, const Corner& b) { return a.centre[0] < b.centre[0]; };
  std::sort(theirs.begin(), theirs.end(), before);
  // A face may have two corners at one point (a degenerate edge's ends and
  // its midpoint): a corner is compared with the closest value among those
  // of its face and point.
  double worst = 0.0;
  std::size_t unmatched = 0;
  for (const Corner& c : ours) {
    Corner low = c;
    low.centre[0] -= 1e-9;
    double best = std::numeric_limits<double>::infinity();
    for (auto it = std::lower_bound(theirs.begin(), theirs.end(), low, before);
         it != theirs.end() && it->centre[0] <= c.centre[0] + 1e-9; ++it) {
      bool same = true;
      for (int j = 0; j < 3; ++j)
        same = same && std::abs(it->centre[j] - c.centre[j]) <= 1e-9 && std::abs(it->point[j] - c.point[j]) <= 1e-9;
      if (same)
        best = std::min(best, std::max(std::abs(it->uv[0] - c.uv[0]), std::abs(it->uv[1] - c.uv[1])));
    }
    if (std::isfinite(best))
      worst = std::max(worst, best);
    else
      ++unmatched;
  }
  EXPECT_EQ(unmatched, 0u);
  return worst;
}

constexpr Face_varying_interpolation all_modes[] = {
  Face_varying_interpolation::none,          Face_varying_interpolation::corners_only,
  Face_varying_interpolation::corners_plus1, Face_varying_interpolation::corners_plus2,
  Face_varying_interpolation::boundaries,    Face_varying_interpolation::all};

const char* mode_name(Face_varying_interpolation mode)
{
  static const char* names[] = {"none", "corners_only", "corners_plus1", "corners_plus2", "boundaries", "all"};
  return names[int(mode)];
}

template <class ConcurrencyTag = CGAL::Sequential_tag>
void subdivide(Mesh& m, bool loop, int levels, Face_varying_interpolation mode, const Shape& s)
{
  const auto np = CGAL_ext::parameters::number_of_iterations(levels)
                    .boundary_interpolation(s.boundary)
                    .crease_method(s.crease_method)
                    .triangle_subdivision(s.triangles)
                    .face_varying_interpolation(mode);
  if (loop)
    S::loop<ConcurrencyTag>(m, np);
  else
    S::catmull_clark<ConcurrencyTag>(m, np);
}

// Ours against OpenSubdiv, each mode, levels 1-3; returns the worst
// difference per mode. Our mesh, its sharpness and its channel come from
// the library's reader, OpenSubdiv's from the tests' parse of the file.
std::array<double, 6> compare_shape(const std::string& file, bool loop)
{
  const Shape s = read_shape(file);
  Mesh base;
  CGAL_ext::IO::read_polygon_mesh(file, base);
  std::array<double, 6> worst{};
  for (Face_varying_interpolation mode : all_modes)
    for (int levels = 1; levels <= 3; ++levels) {
      SCOPED_TRACE(std::string(mode_name(mode)) + ", levels " + std::to_string(levels));
      Mesh m = base;
      subdivide(m, loop, levels, mode, s);
      const double d = max_difference(
        our_corners(m), opensubdiv_corners(s, loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, levels, mode));
      EXPECT_LE(d, 1e-12);
      worst[int(mode)] = std::max(worst[int(mode)], d);
    }
  return worst;
}

void report(const std::string& name, const std::array<double, 6>& worst)
{
  std::ostringstream line;
  line << name << ":";
  for (double w : worst)
    line << " " << w;
  std::cout << "[ max |ours - OpenSubdiv| per mode none..all ] " << line.str() << "\n";
}
#endif

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#define REQUIRE_OPENSUBDIV()
#else
#define REQUIRE_OPENSUBDIV() GTEST_SKIP() << "OpenSubdiv not found"
#endif

TEST(CornerChannelsOpenSubdiv, CatmullClarkShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_cube.obj", "catmark_cube_corner4.obj", "catmark_cube_creases1.obj",
                           "catmark_chaikin1.obj", "catmark_edgecorner.obj", "catmark_nonquads.obj",
                           "catmark_smoothtris1.obj"}) {
    SCOPED_TRACE(name);
    report(name, compare_shape(test::data(std::string("opensubdiv/") + name), false));
  }
#endif
}

TEST(CornerChannelsOpenSubdiv, LoopShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"loop_tetrahedron.obj", "loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"}) {
    SCOPED_TRACE(name);
    report(name, compare_shape(test::data(std::string("opensubdiv/") + name), true));
  }
#endif
}

// On non-manifold input the channel is subdivided on the sheets, each split
// edge a border of the channel in each sheet, the values of a non-manifold
// vertex where the channel is cut corners: as OpenSubdiv's face-varying rules
// on the joined input, in every mode.
TEST(CornerChannelsOpenSubdiv, NonManifoldShape)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  // catmark_nonman_edges has polygons that visit a vertex twice, and six
  // edges whose two polygons run the same way along them, which OpenSubdiv
  // makes non-manifold and the import connects (reversing a polygon):
  // OpenSubdiv is given it as the import oriented it (written joined).
  const auto split = CGAL_ext::parameters::non_manifold_policy(CGAL_ext::Non_manifold_policy::split);
  const std::string oriented = (std::filesystem::temp_directory_path() /
                                ("cgal_ext_nonman_edges_" + std::to_string(::getpid()) + ".obj"))
                                 .string();
  {
    Mesh m;
    CGAL_ext::IO::read_polygon_mesh(test::data("opensubdiv/catmark_nonman_edges.obj"), m, split);
    CGAL_ext::IO::write_polygon_mesh(oriented, m);
  }
  // loop_val2_interior: a vertex pinched between two fans, an edge of four
  // triangles, valence-2 vertices, seams at each. grid_degenerate_edge_uv:
  // a degenerate edge inside one fan (a loop of the sheet), a seam and a
  // semi-sharp edge at its vertex.
  for (const std::string& file :
       {test::data("opensubdiv/catmark_fan.obj"), oriented, test::data("opensubdiv/loop_val2_interior.obj"),
        test::data("nonmanifold/grid_degenerate_edge_uv.obj")}) {
    const std::string name = std::filesystem::path(file).filename().string();
    const bool loop = name.rfind("loop_", 0) == 0;
    const Shape s = read_shape(file);
    Mesh base;
    CGAL_ext::IO::read_polygon_mesh(file, base, split);
    EXPECT_GT(CGAL_ext::non_manifold_counts(base).edges, 0u);
    for (Face_varying_interpolation mode : all_modes)
      for (int levels = 1; levels <= 3; ++levels) {
        SCOPED_TRACE(name + ", " + mode_name(mode) + ", levels " + std::to_string(levels));
        Mesh m = base;
        subdivide(m, loop, levels, mode, s);
        EXPECT_LE(max_difference(our_corners(m), opensubdiv_corners(s, loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK,
                                                                     levels, mode)),
                  1e-12);
      }
  }
  std::filesystem::remove(oriented);
#endif
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// A Möbius strip whose texture coordinates (angle around, height) have one
// seam, where the angle wraps; as a shape, with its `vt` indices.
Shape mobius_shape(bool quads)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3, 1, 1.0, 0.4, quads);
  Shape s;
  for (CGAL_ext::Vertex_index v : m.vertices())
    s.points.push_back(m.point(v));
  std::map<std::pair<int, int>, int> value_of; // (vertex, wrapped) -> value
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<int> vs;
    std::vector<double> u;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m)) {
      vs.push_back(int(v.idx()));
      const Point& p = m.point(v);
      u.push_back(std::atan2(p.y(), p.x()) / (2 * M_PI) + 0.5);
    }
    const bool straddles = *std::max_element(u.begin(), u.end()) - *std::min_element(u.begin(), u.end()) > 0.5;
    std::vector<int> ft;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      const int wrapped = straddles && u[i] < 0.5 ? 1 : 0;
      auto [it, fresh] = value_of.emplace(std::make_pair(vs[i], wrapped), int(s.uvs.size()));
      if (fresh)
        s.uvs.push_back({u[i] + wrapped, m.point(CGAL_ext::Vertex_index(vs[i])).z()});
      ft.push_back(it->second);
    }
    s.faces.push_back(vs);
    s.uv_faces.push_back(ft);
  }
  return s;
}

// The orientation double cover of a shape: two copies of each face, one per
// side, glued so that the cover is orientable (vertex v has the twins 2v and
// 2v + 1); each corner keeps its value index.
Shape double_cover(const Shape& s)
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m);
  Shape c;
  c.uvs = s.uvs;
  for (const Point& p : s.points)
    c.points.insert(c.points.end(), {p, p});
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<int> sheet_vs, sheet, values;
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      sheet_vs.push_back(int(m.target(d).idx()));
      // The sheet of the face at a vertex: whether it runs against the walk around the vertex.
      for (Dart a : CGAL_ext::halfedges_around_target(m.target(d), m))
        if (m.face(a) == f)
          sheet.push_back(a.is_flipped() ? 1 : 0);
      const std::vector<int>& sf = s.faces[f.idx()];
      values.push_back(s.uv_faces[f.idx()][std::size_t(std::find(sf.begin(), sf.end(), sheet_vs.back()) - sf.begin())]);
    }
    for (int sigma : {0, 1}) {
      std::vector<int> face, ft;
      for (std::size_t i = 0; i < sheet_vs.size(); ++i) {
        face.push_back(2 * sheet_vs[i] + (sigma ^ sheet[i]));
        ft.push_back(values[i]);
      }
      if (sigma) {
        std::reverse(face.begin(), face.end());
        std::reverse(ft.begin(), ft.end());
      }
      c.faces.push_back(face);
      c.uv_faces.push_back(ft);
    }
  }
  return c;
}
#endif

TEST(CornerChannelsOpenSubdiv, MobiusStripWithSeam)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (bool quads : {true, false}) {
    SCOPED_TRACE(quads ? "quads" : "triangles");
    const Shape s = mobius_shape(quads), cover = double_cover(s);
    std::array<double, 6> worst{};
    for (Face_varying_interpolation mode : all_modes)
      for (int levels = 1; levels <= 3; ++levels) {
        SCOPED_TRACE(std::string(mode_name(mode)) + ", levels " + std::to_string(levels));
        Mesh m = build(s);
        ASSERT_GT(CGAL_ext::number_of_mobius_edges(m), 0u);
        subdivide(m, !quads, levels, mode, s);
        std::vector<Corner> ours = our_corners(m), twice = ours;
        twice.insert(twice.end(), ours.begin(), ours.end()); // each corner's twin has its value
        const double d = max_difference(
          twice, opensubdiv_corners(cover, quads ? Sdc::SCHEME_CATMARK : Sdc::SCHEME_LOOP, levels, mode));
        EXPECT_LE(d, 1e-12);
        worst[int(mode)] = std::max(worst[int(mode)], d);
      }
    report(quads ? "mobius (Catmull-Clark)" : "mobius (Loop)", worst);
  }
#endif
}

// ---- limit values of a channel (limit_corner_values())

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// Replaces the values of "c:uv" by their limits, with the options the mesh
// was subdivided with.
void limit_in_place(Mesh& m, bool loop, Face_varying_interpolation mode, const Shape& s)
{
  const auto np = CGAL_ext::parameters::boundary_interpolation(s.boundary).face_varying_interpolation(mode);
  if (loop)
    S::limit_corner_values<S::Loop_mask>(m, "c:uv", np);
  else
    S::limit_corner_values<S::Catmull_clark_mask>(m, "c:uv", np);
}

// Texture coordinates as the refiner interpolates them.
struct Uv_value
{
  double u, v;
};
Uv_value operator+(const Uv_value& a, const Uv_value& b) { return {a.u + b.u, a.v + b.v}; }
Uv_value operator*(double w, const Uv_value& a) { return {w * a.u, w * a.v}; }

// The refiner's path: "c:uv" of `base` through a Refiner of `levels` levels
// and to the limit (limit_face_varying()), written as a channel of `m`,
// which is `base` subdivided so (the same numbering: subdivision builds its
// result from the same refiner).
void refiner_limits(const Mesh& base, bool loop, int levels, Face_varying_interpolation mode, const Shape& s, Mesh& m)
{
  S::Refinement_options options;
  options.boundary_interpolation = s.boundary;
  options.crease_method = s.crease_method;
  std::vector<float> es, vs;
  if (const auto e = base.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name))
    for (CGAL_ext::Edge_index x : base.edges())
      es.push_back((*e)[x]);
  if (const auto v = base.property_map<CGAL_ext::Vertex_index, float>(CGAL_ext::vertex_sharpness_name))
    for (CGAL_ext::Vertex_index x : base.vertices())
      vs.push_back((*v)[x]);
  std::vector<std::uint32_t> corners(base.number_of_halfedges(), S::internal::null_u32);
  std::vector<Uv_value> values;
  std::map<std::pair<double, double>, std::uint32_t> index_of; // the shapes' values are distinct
  for (CGAL_ext::Face_index f : base.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(f, base)) {
      const UV t = uv_at(base, d);
      auto [it, fresh] = index_of.emplace(std::make_pair(t[0], t[1]), std::uint32_t(values.size()));
      if (fresh)
        values.push_back({t[0], t[1]});
      corners[base.corner(d).idx()] = it->second;
    }
  if (loop) {
    S::Refiner<S::Loop_mask> r(S::Loop_mask(), options);
    r.refine(base, unsigned(levels), es, vs);
    S::limit_face_varying(r, mode, corners, values);
  } else {
    S::Refiner<S::Catmull_clark_mask> r(S::Catmull_clark_mask(), options);
    r.refine(base, unsigned(levels), es, vs);
    S::limit_face_varying(r, mode, corners, values);
  }
  m.remove_corner_channel("c:uv");
  auto uv = m.add_corner_channel<UV>("c:uv").first;
  for (const Uv_value& x : values)
    uv.add_value({x.u, x.v});
  ASSERT_EQ(corners.size(), m.number_of_halfedges());
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    uv.set_index(h, corners[h.idx()]);
}

// The worst difference per mode of each path to OpenSubdiv.
struct Limit_gaps
{
  std::array<double, 6> mesh{}, refiner{};
};

// Our limits after 1 and 2 steps against OpenSubdiv's LimitFaceVarying() on
// the same level, in each mode, by both paths: limit_corner_values() on the
// subdivided mesh, and limit_face_varying() on a refiner. The values are of
// the order of 1, so the differences are also relative. The comparison must
// be able to fail: in the linear mode `all` the limits are the refined
// values, in the others some move by more than `min_moved`. `cover`:
// OpenSubdiv runs on the orientation double cover of `s`. `mesh_history`:
// the mesh path is not held to OpenSubdiv in the modes of dependent
// sharpness (corners_plus1, corners_plus2), where its tags keep a history
// that the mesh does not (see doc/corner_data.md); it is reported.
Limit_gaps compare_limits(const Shape& s, const Mesh& base, bool loop, const Shape* cover = nullptr,
                          double min_moved = 1e-3, bool mesh_history = false)
{
  double moved_most = 0.0;
  Limit_gaps gaps;
  const Sdc::SchemeType type = loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
  auto doubled = [&](std::vector<Corner> c) { // each corner's twin has its value
    if (cover) {
      const std::vector<Corner> once = c;
      c.insert(c.end(), once.begin(), once.end());
    }
    return c;
  };
  for (Face_varying_interpolation mode : all_modes)
    for (int levels = 1; levels <= 2; ++levels) {
      SCOPED_TRACE(std::string(mode_name(mode)) + ", levels " + std::to_string(levels));
      Mesh m = base;
      subdivide(m, loop, levels, mode, s);
      const std::vector<Corner> refined = our_corners(m);
      const std::vector<Corner> theirs = opensubdiv_corners(cover ? *cover : s, type, levels, mode, true);
      Mesh by_refiner = m;
      limit_in_place(m, loop, mode, s);
      const std::vector<Corner> ours = our_corners(m);
      const double d = max_difference(doubled(ours), theirs);
      const bool dependent = mode == Face_varying_interpolation::corners_plus1 || mode == Face_varying_interpolation::corners_plus2;
      if (!(mesh_history && dependent)) {
        EXPECT_LE(d, 1e-12) << "limit_corner_values()";
      }
      gaps.mesh[int(mode)] = std::max(gaps.mesh[int(mode)], d);
      refiner_limits(base, loop, levels, mode, s, by_refiner);
      const double e = max_difference(doubled(our_corners(by_refiner)), theirs);
      EXPECT_LE(e, 1e-12) << "limit_face_varying()";
      gaps.refiner[int(mode)] = std::max(gaps.refiner[int(mode)], e);
      double moved = 0.0;
      for (std::size_t i = 0; i < refined.size(); ++i)
        moved = std::max({moved, std::abs(refined[i].uv[0] - ours[i].uv[0]), std::abs(refined[i].uv[1] - ours[i].uv[1])});
      if (mode == Face_varying_interpolation::all)
        EXPECT_EQ(moved, 0.0);
      else
        moved_most = std::max(moved_most, moved);
    }
  EXPECT_GT(moved_most, min_moved);
  return gaps;
}

// The shapes' texture coordinates are linear on each chart, which every
// limit rule keeps: an offset that is not (the same on both sides, by value
// index) lets a wrong rule show.
UV offset_of_value(std::size_t i) { return {0.01 * double(i % 7), 0.02 * double((3 * i) % 5)}; }

Limit_gaps compare_limits_of(const std::string& name, bool loop, double min_moved = 1e-3)
{
  const std::string file = test::data("opensubdiv/" + name);
  Mesh base;
  CGAL_ext::IO::read_polygon_mesh(file, base); // values of the kernel's Point_2
  Shape s = read_shape(file);
  auto& values = base.corner_channel<CGAL_ext::Corner_uv<Point>>("c:uv")->values();
  EXPECT_EQ(values.size(), s.uvs.size());
  for (std::size_t i = 0; i < s.uvs.size(); ++i) {
    const UV o = offset_of_value(i);
    s.uvs[i] = {s.uvs[i][0] + o[0], s.uvs[i][1] + o[1]};
    values[i] = {values[i].x() + o[0], values[i].y() + o[1]};
  }
  return compare_limits(s, base, loop, nullptr, min_moved);
}

void report_limits(const std::string& name, const Limit_gaps& gaps)
{
  std::ostringstream line;
  for (double w : gaps.mesh)
    line << " " << w;
  line << " | limit_face_varying():";
  for (double w : gaps.refiner)
    line << " " << w;
  std::cout << "[ max |limit ours - OpenSubdiv| per mode none..all, limit_corner_values(): ] " << name << ":"
            << line.str() << "\n";
}
#endif

TEST(CornerChannelsOpenSubdiv, LimitsCatmullClarkShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_cube.obj", "catmark_cube_corner4.obj", "catmark_chaikin1.obj",
                           "catmark_edgecorner.obj", "catmark_nonquads.obj"}) {
    SCOPED_TRACE(name);
    report_limits(name, compare_limits_of(name, false));
  }
  // Every edge of this cube is semi-sharp through level 2, so every value is
  // a corner or a crease of the channel, and the channel is bilinear between
  // them: the limits move only by the crease rule's float weights
  // (3e-8), which a corner taken for a crease, or the reverse, would miss.
  report_limits("catmark_cube_creases1.obj", compare_limits_of("catmark_cube_creases1.obj", false, 1e-8));
#endif
}

TEST(CornerChannelsOpenSubdiv, LimitsLoopShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"loop_tetrahedron.obj", "loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"}) {
    SCOPED_TRACE(name);
    report_limits(name, compare_limits_of(name, true));
  }
#endif
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// A closed surface of `m` (quads, or each quad cut in two triangles) with a
// channel of two charts, the faces on either side of the plane y = 0 (by
// their centres), each corner's value (the angle around the z axis, z) in
// its chart: two seams.
Shape charted_shape(const Mesh& m, bool triangles)
{
  Shape s;
  for (CGAL_ext::Vertex_index v : m.vertices())
    s.points.push_back(m.point(v));
  std::map<std::pair<int, int>, int> value_of; // (vertex, chart) -> value
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<int> vs;
    double y = 0.0;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m)) {
      vs.push_back(int(v.idx()));
      y += m.point(v).y();
    }
    const int chart = y < 0 ? 1 : 0;
    auto value = [&](int v) {
      auto [it, fresh] = value_of.emplace(std::make_pair(v, chart), int(s.uvs.size()));
      if (fresh) {
        const Point& p = s.points[std::size_t(v)];
        const double turn = std::atan2(p.y(), p.x()) / (2 * M_PI);
        s.uvs.push_back({chart == 1 && turn > 0 ? turn - 1.0 : turn, p.z() + 0.5 * chart});
      }
      return it->second;
    };
    std::vector<std::vector<int>> pieces{vs};
    if (triangles)
      pieces = {{vs[0], vs[1], vs[2]}, {vs[0], vs[2], vs[3]}};
    for (const std::vector<int>& piece : pieces) {
      std::vector<int> ft;
      for (int v : piece)
        ft.push_back(value(v));
      s.faces.push_back(piece);
      s.uv_faces.push_back(ft);
    }
  }
  return s;
}
#endif

// On one-sided surfaces (values of std::array<double, 2>), against
// OpenSubdiv on their orientation double covers: each ring is gathered by
// darts across the Möbius edges. A Möbius strip with one seam, and a Klein
// bottle with two.
TEST(CornerChannelsOpenSubdiv, LimitsOneSidedSurfaces)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  Mesh klein;
  CGAL_ext::make_klein_bottle(klein, 8, 6);
  for (bool quads : {true, false}) {
    SCOPED_TRACE(quads ? "quads" : "triangles");
    const Shape strip = mobius_shape(quads), bottle = charted_shape(klein, !quads);
    for (const Shape* s : {&strip, &bottle}) {
      const Mesh base = build(*s);
      ASSERT_GT(CGAL_ext::number_of_mobius_edges(base), 0u);
      const Shape cover = double_cover(*s);
      report_limits(std::string(s == &strip ? "mobius" : "klein") + (quads ? " (Catmull-Clark)" : " (Loop)"),
                    compare_limits(*s, base, !quads, &cover));
    }
  }
#endif
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// A bumpy 5 x 5 grid (quads, or triangles for Loop) whose faces lie in
// charts of the channel drawn at random (a seam between two charts), with
// semi-sharp, sharp and infinitely sharp creases and a sharp vertex drawn
// at random: the channel's values meet every kind of span. Charts 0 and 1
// are split by a staircase and the faces of chart 2 share no vertex: no
// vertex sees two values alternate (A B A B around it), where OpenSubdiv
// 3.5 counts one value twice (FVarLevel's unique-value scan compares a
// value with the first one found only) and subdivides it otherwise.
Shape random_grid(unsigned seed, bool triangles)
{
  std::mt19937 random(seed);
  const int n = 5;
  Shape s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      s.points.emplace_back(i, j, 0.2 * std::uniform_real_distribution<double>(-1, 1)(random));
  std::map<std::pair<int, int>, int> value_of; // (vertex, chart) -> value
  auto value = [&](int v, int chart) {
    auto [it, fresh] = value_of.emplace(std::make_pair(v, chart), int(s.uvs.size()));
    if (fresh)
      s.uvs.push_back({s.points[std::size_t(v)].x() / n + 0.3 * chart,
                       s.points[std::size_t(v)].y() / n + std::uniform_real_distribution<double>(0, 0.05)(random)});
    return it->second;
  };
  auto add = [&](std::vector<int> f, int chart) {
    std::vector<int> ft;
    for (int v : f)
      ft.push_back(value(v, chart));
    s.faces.push_back(f);
    s.uv_faces.push_back(ft);
  };
  std::vector<int> chart(n * n), staircase(n * n);
  for (int j = 0; j < n; ++j) {
    const int step = std::uniform_int_distribution<int>(1, 3)(random);
    for (int i = 0; i < n; ++i)
      chart[j * n + i] = staircase[j * n + i] = i < step ? 0 : 1;
  }
  for (int k = 0; k < 4; ++k) {
    const int i = std::uniform_int_distribution<int>(0, n - 1)(random), j = std::uniform_int_distribution<int>(0, n - 1)(random);
    bool alone = true;
    for (int b = std::max(0, j - 1); b <= std::min(n - 1, j + 1); ++b)
      for (int a = std::max(0, i - 1); a <= std::min(n - 1, i + 1); ++a)
        alone = alone && chart[b * n + a] != 2;
    if (alone)
      chart[j * n + i] = 2;
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1, x = chart[j * n + i];
      if (triangles) { // chart 2 on the second triangle only
        add({a, b, c}, staircase[j * n + i]);
        add({a, c, d}, x);
      } else {
        add({a, b, c, d}, x);
      }
    }
  const float sharpness[] = {0.5f, 1.0f, 1.5f, 2.7f, 4.0f};
  for (int j = 1; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (std::uniform_int_distribution<int>(0, 3)(random) == 0) { // a horizontal inner edge
        s.crease_pairs.push_back({j * (n + 1) + i, j * (n + 1) + i + 1});
        s.crease_values.push_back(sharpness[std::uniform_int_distribution<int>(0, 4)(random)]);
      }
  s.corners.push_back(2 * (n + 1) + 2);
  s.corner_values.push_back(1.5f);
  s.boundary = seed % 2 ? CGAL_ext::Boundary_interpolation::edge_and_corner : CGAL_ext::Boundary_interpolation::edge_only;
  s.crease_method = seed % 3 == 0 ? CGAL_ext::Crease_method::chaikin : CGAL_ext::Crease_method::uniform;
  return s;
}
#endif

TEST(CornerChannelsOpenSubdiv, LimitsRandomSeamsAndCreases)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (unsigned seed : {1u, 2u, 3u, 5u})
    for (bool loop : {false, true}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + (loop ? ", Loop" : ", Catmull-Clark"));
      const Shape s = random_grid(seed, loop);
      const Limit_gaps gaps = compare_limits(s, build(s), loop, nullptr, 1e-3, true);
      report_limits("grid " + std::to_string(seed) + (loop ? " (Loop)" : " (Catmull-Clark)"), gaps);
      // Here a sharp vertex whose sharpness is spent at level 2 leaves its
      // values creases in OpenSubdiv (and the refiner's path), while the mesh
      // as it stands makes one of them a corner dependent on the other,
      // whose faces still hold a semi-sharp edge: the one case known apart.
      if (seed == 5 && loop) {
        EXPECT_GT(gaps.mesh[int(Face_varying_interpolation::corners_plus1)], 1e-3);
      }
    }
#endif
}

// ---- the limit surface of a channel (Corner_channel_limit_surface)

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// Parameters spread over face f of `m`: a grid of a quad, of each quad
// sub-face of another face, of a Loop triangle.
std::vector<UV> channel_grid(const Mesh& m, CGAL_ext::Face_index f, bool loop)
{
  std::vector<UV> grid;
  const int n = int(m.degree(f));
  if (loop) {
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; i + j <= 4; ++j)
        grid.push_back({i / 4.0, j / 4.0});
  } else if (n == 4) {
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j)
        grid.push_back({i / 4.0, j / 4.0});
  } else {
    for (int k = 0; k < n; ++k) {
      const std::array<int, 2> tile = S::internal::sub_face_tile(n, k);
      for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j)
          grid.push_back({tile[0] + i / 6.0, tile[1] + j / 6.0});
    }
  }
  return grid;
}

struct Channel_gaps
{
  double value = 0, derivatives = 0;
  std::size_t holes = 0; // faces without a surface (Boundary_interpolation::none)
};

// Corner_channel_limit_surface of "c:uv" on `m` against Bfr's face-varying
// surfaces (SurfaceFactory::InitFaceVaryingSurface()) on `reference`, whose
// face `face_of(f)` lists the corners of face f of `m` from its first dart
// (so that both parameterise it alike), with the tags and options of `s`.
template <class FaceOf>
Channel_gaps channel_surface_against_bfr(const Mesh& m, const Shape& reference, const Shape& s, bool loop,
                                         Face_varying_interpolation mode, const FaceOf& face_of)
{
  const std::unique_ptr<Far::TopologyRefiner> refiner = refiner_with_uv(reference, s, loop, mode);
  OpenSubdiv::Bfr::RefinerSurfaceFactory<> factory(*refiner); // approxLevelSmooth 2, approxLevelSharp 6
  std::vector<double> values;
  for (const UV& t : reference.uvs)
    values.insert(values.end(), {t[0], t[1]});
  const auto np = CGAL_ext::parameters::face_varying_interpolation(mode)
                    .boundary_interpolation(s.boundary)
                    .crease_method(s.crease_method)
                    .triangle_subdivision(s.triangles);
  Channel_gaps gaps;
  auto compare = [&](const auto& ours) {
    for (CGAL_ext::Face_index f : m.faces()) {
      OpenSubdiv::Bfr::Surface<double> bfr;
      const bool has_surface = factory.InitFaceVaryingSurface(face_of(f), &bfr, 0);
      EXPECT_EQ(has_surface, !ours.is_hole(f)) << "f" << f.idx();
      if (!has_surface) { // a hole: Boundary_interpolation::none
        EXPECT_THROW(ours.evaluate(f, 0.25, 0.25), CGAL_ext::Parameter_error);
        ++gaps.holes;
        continue;
      }
      std::vector<double> patch_points(std::size_t(bfr.GetNumPatchPoints()) * 2);
      bfr.PreparePatchPoints(values.data(), 2, patch_points.data(), 2);
      for (const UV& at : channel_grid(m, f, loop)) {
        double p[2], du[2], dv[2];
        bfr.Evaluate(at.data(), patch_points.data(), 2, p, du, dv);
        const auto e = ours.evaluate(f, at[0], at[1]);
        for (int i = 0; i < 2; ++i) {
          gaps.value = std::max(gaps.value, std::abs(e.value[std::size_t(i)] - p[i]));
          gaps.derivatives = std::max({gaps.derivatives, std::abs(e.du[std::size_t(i)] - du[i]), std::abs(e.dv[std::size_t(i)] - dv[i])});
        }
      }
    }
  };
  if (loop)
    compare(S::Corner_channel_limit_surface<S::Loop_mask, Point, UV>(m, "c:uv", np));
  else
    compare(S::Corner_channel_limit_surface<S::Catmull_clark_mask, Point, UV>(m, "c:uv", np));
  return gaps;
}

// The shape with its faces listed as `m` walks them, each from its first dart.
Shape walked(const Shape& s, const Mesh& m)
{
  Shape w = s;
  for (CGAL_ext::Face_index f : m.faces()) {
    const std::vector<int>& vs = s.faces[f.idx()];
    w.faces[f.idx()].clear();
    w.uv_faces[f.idx()].clear();
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(m.halfedge(f), m)) {
      const std::size_t i = std::size_t(std::find(vs.begin(), vs.end(), int(v.idx())) - vs.begin());
      w.faces[f.idx()].push_back(vs[i]);
      w.uv_faces[f.idx()].push_back(s.uv_faces[f.idx()][i]);
    }
  }
  return w;
}

// Every mode on shape `s`: positions within 1e-12 of Bfr's, derivatives
// within 1e-10 (the values are of the order of 1); the largest gaps.
Channel_gaps expect_channel_surfaces_as_bfr(const Shape& s, bool loop)
{
  const Mesh m = build(s);
  const Shape reference = walked(s, m);
  Channel_gaps worst;
  for (Face_varying_interpolation mode : all_modes) {
    SCOPED_TRACE(mode_name(mode));
    const Channel_gaps g =
      channel_surface_against_bfr(m, reference, s, loop, mode, [](CGAL_ext::Face_index f) { return int(f.idx()); });
    EXPECT_LE(g.value, 1e-12);
    EXPECT_LE(g.derivatives, 1e-10);
    if (s.boundary == CGAL_ext::Boundary_interpolation::none) { // some holes, not all
      EXPECT_GT(g.holes, 0u);
      EXPECT_LT(g.holes, m.number_of_faces());
    }
    worst.value = std::max(worst.value, g.value);
    worst.derivatives = std::max(worst.derivatives, g.derivatives);
  }
  return worst;
}

void report_channel_surface(const std::string& name, const Channel_gaps& g)
{
  std::cout << "[ channel limit surface - Bfr, worst of six modes: value, derivatives ] " << name << ": " << g.value
            << " " << g.derivatives << "\n";
}
#endif

TEST(CornerChannelsOpenSubdiv, LimitSurfaceOfTheShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  const std::pair<const char*, bool> shapes[] = {
    {"catmark_cube.obj", false},        {"catmark_cube_corner4.obj", false}, {"catmark_cube_creases1.obj", false},
    {"catmark_edgecorner.obj", false},  {"catmark_nonquads.obj", false},
    {"catmark_smoothtris1.obj", false}, {"loop_tetrahedron.obj", true},      {"loop_icos_semisharp.obj", true},
    {"loop_triangle_edgeonly.obj", true}};
  // Not catmark_chaikin1: Bfr's surface of its points differs from Far's
  // refinement near two vertices with Chaikin creases (limit_surface.md,
  // "Chaikin creases").
  for (const auto& [name, loop] : shapes) {
    SCOPED_TRACE(name);
    Shape s = read_shape(test::data(std::string("opensubdiv/") + name));
    // Linear charts are kept by every rule: moved off them, a wrong rule shows.
    for (std::size_t i = 0; i < s.uvs.size(); ++i)
      s.uvs[i] = {s.uvs[i][0] + offset_of_value(i)[0], s.uvs[i][1] + offset_of_value(i)[1]};
    report_channel_surface(name, expect_channel_surfaces_as_bfr(s, loop));
  }
  // Under Boundary_interpolation::none the faces with a border vertex are
  // holes, in the channel as in the points.
  for (const auto& [name, loop] : {std::pair<const char*, bool>{"catmark_edgecorner.obj", false},
                                   {"catmark_nonquads.obj", false}, {"loop_triangle_edgeonly.obj", true}}) {
    SCOPED_TRACE(std::string(name) + ", none");
    Shape s = read_shape(test::data(std::string("opensubdiv/") + name));
    s.boundary = CGAL_ext::Boundary_interpolation::none;
    for (std::size_t i = 0; i < s.uvs.size(); ++i)
      s.uvs[i] = {s.uvs[i][0] + offset_of_value(i)[0], s.uvs[i][1] + offset_of_value(i)[1]};
    report_channel_surface(std::string(name) + " (none)", expect_channel_surfaces_as_bfr(s, loop));
  }
#endif
}

TEST(CornerChannelsOpenSubdiv, LimitSurfaceRandomSeamsAndCreases)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  // Seed 5 under Loop holds a value whose sibling's faces hold a semi-sharp
  // edge (Bfr's dependent sharpness); 3 and 6 Chaikin creases.
  for (unsigned seed : {1u, 2u, 3u, 5u, 6u})
    for (bool loop : {false, true}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + (loop ? ", Loop" : ", Catmull-Clark"));
      report_channel_surface("grid " + std::to_string(seed) + (loop ? " (Loop)" : ""),
                             expect_channel_surfaces_as_bfr(random_grid(seed, loop), loop));
    }
#endif
}

// A one-sided surface: face f of the Möbius strip against face 2f of Bfr's
// orientation double cover (its copy that runs as f does).
TEST(CornerChannelsOpenSubdiv, LimitSurfaceOfAMobiusStripWithSeam)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (bool quads : {true, false}) {
    SCOPED_TRACE(quads ? "quads" : "triangles");
    const Shape s = mobius_shape(quads);
    const Mesh m = build(s);
    ASSERT_GT(CGAL_ext::number_of_mobius_edges(m), 0u);
    const Shape cover = double_cover(s); // its face 2f runs as face f of m walks
    for (Face_varying_interpolation mode : all_modes) {
      SCOPED_TRACE(mode_name(mode));
      const Channel_gaps g = channel_surface_against_bfr(m, cover, s, !quads, mode,
                                                         [](CGAL_ext::Face_index f) { return 2 * int(f.idx()); });
      EXPECT_LE(g.value, 1e-12);
      EXPECT_LE(g.derivatives, 1e-10);
    }
  }
#endif
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// The tessellation at `rate` carries "c:uv": face by face, each corner of
// our facets of face f (as many as Bfr::Tessellation makes) has the value
// that Bfr's face-varying surface of f gives at the sample of its
// tessellation at that corner's point. Returns the largest difference.
double tessellated_channel_against_bfr(const Shape& s, bool loop, Face_varying_interpolation mode, int rate)
{
  namespace Bfr = OpenSubdiv::Bfr;
  const Mesh m = build(s);
  const std::unique_ptr<Far::TopologyRefiner> refiner = refiner_with_uv(walked(s, m), s, loop, mode);
  Bfr::RefinerSurfaceFactory<> factory(*refiner);
  const auto np = CGAL_ext::parameters::face_varying_interpolation(mode)
                    .boundary_interpolation(s.boundary)
                    .crease_method(s.crease_method)
                    .triangle_subdivision(s.triangles);
  const Mesh out = loop ? S::Limit_surface<S::Loop_mask, Point>(m, np).tessellate(rate)
                        : S::Limit_surface<S::Catmull_clark_mask, Point>(m, np).tessellate(rate);
  const auto uv = out.corner_channel<UV>("c:uv");
  EXPECT_TRUE(uv.has_value());
  if (!uv)
    return 1.0;
  std::vector<double> xyz, values;
  for (const Point& p : s.points)
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  for (const UV& t : s.uvs)
    values.insert(values.end(), {t[0], t[1]});
  double worst = 0;
  std::size_t facet = 0;
  for (CGAL_ext::Face_index f : m.faces()) {
    Bfr::Tessellation::Options options;
    options.SetFacetSize(4).PreserveQuads(true);
    const Bfr::Tessellation t(Bfr::Parameterization(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, int(m.degree(f))), rate, options);
    std::vector<double> coords(2 * std::size_t(t.GetNumCoords()));
    t.GetCoords(coords.data());
    if (loop) // Bfr gives a triangle's i / N to float precision only
      for (double& x : coords)
        x = std::round(x * rate) / rate;
    Bfr::Surface<double> position, value;
    if (!factory.InitVertexSurface(int(f.idx()), &position)) { // a hole: no facets
      EXPECT_EQ(s.boundary, CGAL_ext::Boundary_interpolation::none);
      continue;
    }
    EXPECT_TRUE(factory.InitFaceVaryingSurface(int(f.idx()), &value, 0));
    std::vector<double> pp(3 * std::size_t(position.GetNumPatchPoints())), vp(2 * std::size_t(value.GetNumPatchPoints()));
    position.PreparePatchPoints(xyz.data(), 3, pp.data(), 3);
    value.PreparePatchPoints(values.data(), 2, vp.data(), 2);
    std::vector<std::array<double, 5>> samples; // x, y, z, u, v
    for (std::size_t i = 0; i < coords.size(); i += 2) {
      std::array<double, 5> x;
      position.Evaluate(&coords[i], pp.data(), 3, x.data());
      value.Evaluate(&coords[i], vp.data(), 2, x.data() + 3);
      samples.push_back(x);
    }
    for (int k = 0; k < t.GetNumFacets(); ++k, ++facet) {
      const CGAL_ext::Face_index g = CGAL_ext::Face_index(std::uint32_t(facet));
      for (Dart d : CGAL_ext::halfedges_around_face(out.halfedge(g), out)) {
        const Point& q = out.point(out.target(d));
        const auto nearest = std::min_element(samples.begin(), samples.end(), [&](const auto& a, const auto& b) {
          return CGAL::squared_distance(q, Point(a[0], a[1], a[2])) < CGAL::squared_distance(q, Point(b[0], b[1], b[2]));
        });
        EXPECT_LE(std::sqrt(CGAL::squared_distance(q, Point((*nearest)[0], (*nearest)[1], (*nearest)[2]))), 1e-9);
        const UV w = uv->values()[uv->index(out.corner(d))];
        worst = std::max({worst, std::abs(w[0] - (*nearest)[3]), std::abs(w[1] - (*nearest)[4])});
      }
    }
  }
  EXPECT_EQ(facet, out.number_of_faces());
  return worst;
}
#endif

TEST(CornerChannelsOpenSubdiv, TessellationCarriesThemAsBfr)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  // The modes are the channel surface's (above): here the wiring, on an
  // n-gon mesh at an odd and an even rate in a smooth and a linear mode,
  // a mesh with creases and corners, and a Loop mesh.
  const std::tuple<const char*, bool, Face_varying_interpolation, int> runs[] = {
    {"catmark_nonquads.obj", false, Face_varying_interpolation::corners_plus1, 3},
    {"catmark_nonquads.obj", false, Face_varying_interpolation::all, 2},
    {"catmark_edgecorner.obj", false, Face_varying_interpolation::corners_plus2, 2},
    {"loop_icos_semisharp.obj", true, Face_varying_interpolation::corners_plus1, 3}};
  for (const auto& [name, loop, mode, rate] : runs) {
    SCOPED_TRACE(std::string(name) + ", " + mode_name(mode) + ", rate " + std::to_string(rate));
    Shape s = read_shape(test::data(std::string("opensubdiv/") + name));
    for (std::size_t i = 0; i < s.uvs.size(); ++i)
      s.uvs[i] = {s.uvs[i][0] + offset_of_value(i)[0], s.uvs[i][1] + offset_of_value(i)[1]};
    EXPECT_LE(tessellated_channel_against_bfr(s, loop, mode, rate), 1e-12);
  }
  // Under Boundary_interpolation::none, holes have no facets, as Bfr.
  for (const char* name : {"catmark_edgecorner.obj", "catmark_nonquads.obj"}) {
    SCOPED_TRACE(std::string(name) + ", none");
    Shape s = read_shape(test::data(std::string("opensubdiv/") + name));
    s.boundary = CGAL_ext::Boundary_interpolation::none;
    EXPECT_LE(tessellated_channel_against_bfr(s, false, Face_varying_interpolation::corners_plus1, 3), 1e-12);
  }
  // A seam stays a seam: a corner on each side of it keeps its side's value.
  Shape s = random_grid(2, false);
  const Mesh m = build(s);
  const Mesh out = S::Limit_surface<S::Catmull_clark_mask, Point>(m).tessellate(3);
  EXPECT_GT(CGAL_ext::corner_channel_summaries(m).front().seam_edges, 0u);
  EXPECT_GT(CGAL_ext::corner_channel_summaries(out).front().seam_edges,
            CGAL_ext::corner_channel_summaries(m).front().seam_edges);
  EXPECT_LE(tessellated_channel_against_bfr(s, false, Face_varying_interpolation::corners_plus1, 3), 1e-12);
#endif
}

// A channel whose values cannot be combined is refused, not dropped.
TEST(CornerChannels, TessellationRefusesAChannelItCannotCarry)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 8, 2);
  auto labels = m.add_corner_channel<int>("c:label").first;
  labels.values() = {7};
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    if (!m.is_border(h))
      labels.set_index(h, 0);
  EXPECT_THROW(S::tessellate<S::Catmull_clark_mask>(m, 2), CGAL_ext::Parameter_error);
  EXPECT_THROW(S::tessellate_to_tolerance<S::Catmull_clark_mask>(m, 0.01), CGAL_ext::Parameter_error);
  m.remove_corner_channel(labels);
  // The channel surface refuses what Limit_surface refuses, in the linear mode too.
  auto uv = m.add_corner_channel<UV>("c:uv").first;
  uv.values() = {UV{0.0, 0.0}};
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    if (!m.is_border(h))
      uv.set_index(h, 0);
  using Linear = S::Corner_channel_limit_surface<S::Loop_mask, Point, UV>;
  EXPECT_THROW(Linear(m, "c:uv", CGAL_ext::parameters::face_varying_interpolation(Face_varying_interpolation::all)),
               CGAL_ext::Parameter_error); // quads under Loop
  using Smooth = S::Corner_channel_limit_surface<S::Catmull_clark_mask, Point, UV>;
  // Under Boundary_interpolation::none every face of this strip touches
  // its border: a hole, without a value.
  const Smooth holes(m, "c:uv", CGAL_ext::parameters::boundary_interpolation(CGAL_ext::Boundary_interpolation::none));
  EXPECT_TRUE(holes.is_hole(CGAL_ext::Face_index(3)));
  EXPECT_THROW(holes.evaluate(CGAL_ext::Face_index(3), 0.5, 0.5), CGAL_ext::Parameter_error);
  EXPECT_THROW(Smooth(m, "c:label"), CGAL_ext::Parameter_error); // removed
  m.remove_corner_channel(uv);
  EXPECT_EQ(S::tessellate<S::Catmull_clark_mask>(m, 2).number_of_faces(), 4u * m.number_of_faces());
}

// Exact where the surface is polynomial: on a flat grid whose channel is
// the grid's own coordinates (i / n, j / n), every patch a bicubic
// B-spline (borders extrapolated), the channel's limit at (u, v) of face
// (i, j) is ((i + u) / n, (j + v) / n), exactly, in an exact kernel, and
// its derivatives the grid's steps.
TEST(CornerChannels, LimitSurfaceIsExactWhereLinear)
{
  using KE = CGAL::Exact_predicates_exact_constructions_kernel;
  using PE = KE::Point_3;
  const int n = 4;
  std::vector<PE> points;
  std::vector<std::vector<std::size_t>> faces;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      points.emplace_back(i, j, (i * j) % 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t a = std::size_t(j * (n + 1) + i);
      faces.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  CGAL_ext::Mobius_mesh<PE> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  auto uv = m.add_corner_channel<KE::Point_2>("c:uv").first;
  for (const PE& p : points)
    uv.values().push_back(KE::Point_2(p.x() / n, p.y() / n));
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    if (!m.is_border(h))
      uv.set_index(h, std::uint32_t(m.target(h).idx()));
  const S::Corner_channel_limit_surface<S::Catmull_clark_mask, PE, KE::Point_2> surface(m, "c:uv");
  for (CGAL_ext::Face_index f : m.faces()) {
    const PE corner0 = m.point(m.target(m.halfedge(f)));
    const KE::Vector_2 along = KE::Point_2(m.point(m.target(m.next(m.halfedge(f)))).x() / n,
                                           m.point(m.target(m.next(m.halfedge(f)))).y() / n) -
                               KE::Point_2(corner0.x() / n, corner0.y() / n);
    const KE::Vector_2 across(-along.y(), along.x()); // corner 3 - corner 0 of a grid quad, as walked
    for (const auto& [u, v] : {std::pair<int, int>{1, 3}, {2, 5}, {0, 7}, {7, 7}}) {
      const KE::FT fu = KE::FT(u) / 7, fv = KE::FT(v) / 7;
      const auto e = surface.evaluate(f, fu, fv);
      const KE::Point_2 expected = KE::Point_2(corner0.x() / n, corner0.y() / n) + along * fu + across * fv;
      EXPECT_EQ(e.value, expected) << "face " << f.idx() << " at (" << u << "/7, " << v << "/7)";
      EXPECT_EQ(e.du[0], along.x());
      EXPECT_EQ(e.du[1], along.y());
      EXPECT_EQ(e.dv[0], across.x());
      EXPECT_EQ(e.dv[1], across.y());
    }
  }
}

// In exact arithmetic, on a Möbius strip subdivided once: a channel without
// a seam whose values are the points' (x, y) has the limit points' (x, y) as
// limits, exactly (the same masks); a channel with a seam, moved by an exact
// offset, has limits moved by it, exactly (every rule's weights sum to 1,
// which the float weights of double do only to 3e-8); and the limits agree
// with those computed in double, to those float weights.
TEST(CornerChannels, LimitsExactKernel)
{
  using K = test::Epeck;
  using EMesh = CGAL_ext::Mobius_mesh<K::Point_3>;
  using P2 = K::Point_2;
  EMesh m;
  CGAL_ext::make_mobius_strip(m, 8, 2);
  const auto np = CGAL_ext::parameters::number_of_iterations(1);
  // "c:xy": one value per vertex; "c:uv": a seam where the angle wraps.
  auto xy = m.add_corner_channel<P2>("c:xy").first;
  auto uv = m.add_corner_channel<P2>("c:uv").first;
  for (CGAL_ext::Vertex_index v : m.vertices())
    xy.add_value(P2(m.point(v).x(), m.point(v).y()));
  // The angle around decides where the seam goes (in double: a decision, not a value).
  auto turn = [&](CGAL_ext::Vertex_index v) {
    return std::atan2(CGAL::to_double(m.point(v).y()), CGAL::to_double(m.point(v).x())) / (2 * M_PI) + 0.5;
  };
  std::map<std::pair<std::uint32_t, int>, std::uint32_t> value_of;
  for (CGAL_ext::Face_index f : m.faces()) {
    double low = 1.0, high = 0.0;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m)) {
      low = std::min(low, turn(v));
      high = std::max(high, turn(v));
    }
    for (Dart d : CGAL_ext::halfedges_around_face(f, m)) {
      const CGAL_ext::Vertex_index v = m.target(d);
      xy.set_index(m.corner(d), v.idx());
      const int wrapped = high - low > 0.5 && turn(v) < 0.5 ? 1 : 0;
      auto [it, fresh] = value_of.emplace(std::make_pair(v.idx(), wrapped), 0u);
      if (fresh)
        it->second = uv.add_value(P2(m.point(v).z() + wrapped, m.point(v).x() * m.point(v).y()));
      uv.set_index(m.corner(d), it->second);
    }
  }
  // The same channel in double, on the same strip.
  Mesh d;
  CGAL_ext::make_mobius_strip(d, 8, 2);
  auto duv = d.add_corner_channel<UV>("c:uv").first;
  for (const P2& p : uv.values())
    duv.add_value({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    duv.set_index(h, uv.index(h));
  S::catmull_clark(m, np);
  S::catmull_clark(d, np);
  ASSERT_GT(CGAL_ext::corner_channel_summaries(m)[1].seam_edges, 0u);
  auto sxy = *m.corner_channel<P2>("c:xy");
  auto suv = *m.corner_channel<P2>("c:uv");
  // The offset copy of "c:uv".
  const K::Vector_2 t(K::FT(1) / K::FT(3), K::FT(2) / K::FT(7));
  auto moved = m.add_corner_channel<P2>("c:moved").first;
  for (const P2& p : suv.values())
    moved.add_value(p + t);
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    moved.set_index(h, suv.index(h));
  const std::vector<P2> before = suv.values();
  S::limit_corner_values<S::Catmull_clark_mask>(m, sxy, sxy);
  S::limit_corner_values<S::Catmull_clark_mask>(m, suv, suv);
  S::limit_corner_values<S::Catmull_clark_mask>(m, moved, moved);
  S::limit_corner_values<S::Catmull_clark_mask>(d, "c:uv");
  double gap = 0.0;
  std::size_t changed = 0;
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart c : CGAL_ext::halfedges_around_face(f, m)) {
      const K::Point_3 p = S::limit_point<S::Catmull_clark_mask>(m.target(c), m);
      EXPECT_EQ(sxy[m.corner(c)], P2(p.x(), p.y()));
      EXPECT_EQ(moved[m.corner(c)], suv[m.corner(c)] + t);
      const UV& x = (*d.corner_channel<UV>("c:uv"))[d.corner(c)];
      gap = std::max({gap, std::abs(x[0] - CGAL::to_double(suv[m.corner(c)].x())),
                      std::abs(x[1] - CGAL::to_double(suv[m.corner(c)].y()))});
      changed += suv[m.corner(c)] != before[suv.index(m.corner(c))] ? 1 : 0;
    }
  EXPECT_LE(gap, 1e-7);
  EXPECT_GT(gap, 1e-10); // the seam's creases, weighted as OpenSubdiv does in double
  EXPECT_GT(changed, 0u);
}

// Bad input is refused, typed, and nothing is written; a value index used
// at several vertices gets a limit per vertex.
TEST(CornerChannels, LimitsRefusedAndShared)
{
  Mesh m;
  CGAL_ext::IO::read_polygon_mesh(test::data("opensubdiv/catmark_nonquads.obj"), m);
  auto uv = *m.corner_channel<CGAL_ext::Corner_uv<Point>>("c:uv");
  const auto values = uv.values();
  EXPECT_THROW(S::limit_corner_values<S::Catmull_clark_mask>(m, "c:uv"), CGAL_ext::Parameter_error); // not quads
  EXPECT_THROW(S::limit_corner_values<S::Loop_mask>(m, "c:uv"), CGAL_ext::Parameter_error);
  EXPECT_EQ(uv.values(), values);
  S::catmull_clark(m);
  EXPECT_THROW(S::limit_corner_values<S::Catmull_clark_mask>(m, "c:st"), CGAL_ext::Parameter_error); // no such channel
  m.add_corner_channel<int>("c:id");
  EXPECT_THROW(S::limit_corner_values<S::Catmull_clark_mask>(m, "c:id"), CGAL_ext::Parameter_error);
  uv = *m.corner_channel<CGAL_ext::Corner_uv<Point>>("c:uv");
  Mesh other = m; // a channel of another mesh
  auto foreign = *other.corner_channel<CGAL_ext::Corner_uv<Point>>("c:uv");
  EXPECT_THROW(S::limit_corner_values<S::Catmull_clark_mask>(m, uv, foreign), CGAL_ext::Parameter_error);
  EXPECT_THROW(S::limit_corner_values<S::Catmull_clark_mask>(m, foreign, uv), CGAL_ext::Parameter_error);
  // A corner without a value.
  const CGAL_ext::Halfedge_index h = m.corner(m.halfedge(CGAL_ext::Face_index(3)));
  const std::uint32_t i = uv.index(h);
  const auto refined = uv.values();
  uv.set_index(h, uv.no_value());
  EXPECT_THROW(S::limit_corner_values<S::Catmull_clark_mask>(m, "c:uv"), CGAL_ext::Parameter_error);
  EXPECT_EQ(uv.values(), refined);
  uv.set_index(h, i);
  // Into another channel: the indices are the input's, the input untouched.
  auto lim = m.add_corner_channel<CGAL_ext::Corner_uv<Point>>("c:limit").first;
  S::limit_corner_values<S::Catmull_clark_mask>(m, uv, lim);
  EXPECT_EQ(uv.values(), refined);
  EXPECT_EQ(lim.number_of_values(), refined.size());
  for (CGAL_ext::Halfedge_index g : m.halfedges())
    EXPECT_EQ(lim.index(g), uv.index(g));
  // Removed elements.
  Mesh removed = m;
  removed.remove_face(CGAL_ext::Face_index(0));
  EXPECT_THROW(S::limit_corner_values<S::Catmull_clark_mask>(removed, "c:uv"), CGAL_ext::Parameter_error);
  // One value for every corner: a value per vertex comes out, each the
  // limit of a constant (the value itself, to rounding).
  Mesh torus;
  CGAL_ext::make_torus(torus, 6, 4, 2.0, 0.5);
  auto one = torus.add_corner_channel<UV>("c:uv").first;
  one.add_value({0.25, 0.75});
  for (CGAL_ext::Halfedge_index g : torus.halfedges())
    if (!torus.is_border(g))
      one.set_index(g, 0);
  S::limit_corner_values<S::Catmull_clark_mask>(torus, "c:uv");
  EXPECT_EQ(one.number_of_values(), torus.number_of_vertices());
  for (const UV& x : one.values()) {
    EXPECT_NEAR(x[0], 0.25, 1e-15);
    EXPECT_NEAR(x[1], 0.75, 1e-15);
  }
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// The free functions carry maps and channels through a one-pass refinement,
// a level at a time; the refiner's own path keeps every level and
// interpolates each afterwards (Refiner::interpolate(),
// interpolate_face_varying(), base_faces()). Both must give the same
// indices and values, bit for bit, and each face its base face's values:
// on shapes with semi-sharp creases (Chaikin's rule on one), borders, seams
// and n-gons, in every mode, under Catmull-Clark and Loop.
TEST(CornerChannels, CarriedInOnePassAsThroughKeptLevels)
{
  using L = CGAL_ext::internal::Linear_value<double, test::Kd, UV>;
  using Weight_value = CGAL_ext::internal::Linear_value<double, test::Kd, double>;
  for (const char* name : {"catmark_chaikin1.obj", "catmark_nonquads.obj", "catmark_edgecorner.obj",
                           "loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"}) {
    const bool loop = name[0] == 'l';
    const Shape s = read_shape(test::data(std::string("opensubdiv/") + name));
    Mesh m = build(s);
    auto weight = m.add_property_map<CGAL_ext::Vertex_index, double>("v:weight").first;
    auto tag = m.add_property_map<CGAL_ext::Face_index, int>("f:tag").first;
    for (CGAL_ext::Vertex_index v : m.vertices())
      weight[v] = m.point(v).x() + 2 * m.point(v).y() + 1.0 / (1 + v.idx());
    for (CGAL_ext::Face_index f : m.faces())
      tag[f] = 7 * int(f.idx()) + 3;
    const auto uv = *m.corner_channel<UV>("c:uv");
    std::vector<float> es(m.number_of_edges()), vs;
    if (const auto map = m.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name))
      for (CGAL_ext::Edge_index e : m.edges())
        es[e.idx()] = (*map)[e];
    if (const auto map = m.property_map<CGAL_ext::Vertex_index, float>(CGAL_ext::vertex_sharpness_name))
      for (CGAL_ext::Vertex_index v : m.vertices())
        vs.push_back((*map)[v]);
    for (Face_varying_interpolation mode : all_modes) {
      SCOPED_TRACE(std::string(name) + ", " + mode_name(mode));
      const int levels = 3;
      Mesh one_pass = m;
      subdivide(one_pass, loop, levels, mode, s);

      S::Refinement_options options;
      options.boundary_interpolation = s.boundary;
      options.crease_method = s.crease_method;
      std::vector<std::uint32_t> corners(m.number_of_halfedges());
      for (CGAL_ext::Halfedge_index h : m.halfedges())
        corners[h.idx()] = m.is_border(h) ? S::internal::null_u32 : uv.index(h);
      std::vector<L::Value> values;
      for (const UV& t : uv.values())
        values.push_back(L::from(t));
      std::vector<double> weights, weights_out;
      for (CGAL_ext::Vertex_index v : m.vertices())
        weights.push_back(Weight_value::from(weight[v]));
      std::vector<std::uint32_t> base_faces;
      const auto kept = [&](auto mask) {
        S::Refiner<decltype(mask)> r(mask, options);
        r.refine(m, levels, es, vs);
        r.interpolate_face_varying(mode, corners, values);
        r.interpolate(weights, weights_out);
        base_faces = r.base_faces();
      };
      S::Catmull_clark_mask catmark;
      catmark.triangle_subdivision = s.triangles;
      if (loop)
        kept(S::Loop_mask());
      else
        kept(catmark);

      const auto out_uv = one_pass.corner_channel<UV>("c:uv");
      ASSERT_TRUE(out_uv);
      ASSERT_EQ(one_pass.number_of_halfedges(), corners.size());
      std::size_t differing_indices = 0;
      for (CGAL_ext::Halfedge_index h : one_pass.halfedges())
        differing_indices += one_pass.is_border(h) ? 0 : out_uv->index(h) != corners[h.idx()];
      EXPECT_EQ(differing_indices, 0u);
      ASSERT_EQ(out_uv->values().size(), values.size());
      for (std::size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(out_uv->values()[i], L::to(values[i])) << "value " << i;
      const auto out_weight = one_pass.property_map<CGAL_ext::Vertex_index, double>("v:weight");
      const auto out_tag = one_pass.property_map<CGAL_ext::Face_index, int>("f:tag");
      ASSERT_TRUE(out_weight && out_tag);
      ASSERT_EQ(one_pass.number_of_vertices(), weights_out.size());
      for (CGAL_ext::Vertex_index v : one_pass.vertices())
        ASSERT_EQ((*out_weight)[v], weights_out[v.idx()]) << "v" << v.idx();
      ASSERT_EQ(one_pass.number_of_faces(), base_faces.size());
      for (CGAL_ext::Face_index f : one_pass.faces())
        ASSERT_EQ((*out_tag)[f], 7 * int(base_faces[f.idx()]) + 3) << "f" << f.idx();
    }
    // No level: every map as it was.
    Mesh same = m;
    subdivide(same, loop, 0, Face_varying_interpolation::corners_plus1, s);
    const auto same_uv = same.corner_channel<UV>("c:uv");
    ASSERT_TRUE(same_uv);
    EXPECT_EQ(same_uv->values(), uv.values());
    for (CGAL_ext::Halfedge_index h : m.halfedges())
      ASSERT_EQ(same_uv->index(h), uv.index(h));
    const auto same_weight = same.property_map<CGAL_ext::Vertex_index, double>("v:weight");
    const auto same_tag = same.property_map<CGAL_ext::Face_index, int>("f:tag");
    ASSERT_TRUE(same_weight && same_tag);
    EXPECT_EQ(same_weight->data(), weight.data());
    EXPECT_EQ(same_tag->data(), tag.data());
  }
}
#endif

#if defined(CGAL_EXT_SUBDIVISION_PARALLEL) && defined(CGAL_EXT_HAVE_OPENSUBDIV)
// Texture coordinates as the refiner interpolates them.
struct Vec2
{
  double u, v;
};
Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.u + b.u, a.v + b.v}; }
Vec2 operator*(double w, const Vec2& a) { return {w * a.u, w * a.v}; }

// Every level with threads (parallel_min_vertices 0), against the serial
// refinement: the same indices and values, bit for bit; also with threads on
// the levels of a serial refinement, which made no incidence tables. The
// channel's values are rounded in their sums, so that their order shows.
template <class Mask>
void expect_parallel_is_serial(const Mesh& m, CGAL_ext::Crease_method crease, const std::vector<float>& es)
{
  const auto uv = *m.corner_channel<UV>("c:uv");
  std::vector<std::uint32_t> base(m.number_of_halfedges());
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    base[h.idx()] = m.is_border(h) ? S::internal::null_u32 : uv.index(h);
  const std::vector<float> vs(m.number_of_vertices());
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  for (Face_varying_interpolation mode : all_modes) {
    S::Refinement_options options;
    options.crease_method = crease;
    options.parallel_min_vertices = 0;
    S::Refiner<Mask> serial(Mask(), options), parallel(Mask(), options);
    serial.refine(m, 4, es, vs);
    parallel.template refine<CGAL::Parallel_tag>(m, 4, es, vs);
    std::vector<std::uint32_t> ca = base, cb = base, cc = base;
    std::vector<Vec2> va, vb, vc;
    for (const UV& t : uv.values()) {
      const double i = double(va.size());
      va.push_back({t[0] / 3 + 0.1 * std::sin(i), t[1] / 7 + 0.1 * std::cos(i)});
    }
    vc = vb = va;
    serial.template interpolate_face_varying<CGAL::Parallel_tag>(mode, cc, vc);
    serial.interpolate_face_varying(mode, ca, va);
    parallel.template interpolate_face_varying<CGAL::Parallel_tag>(mode, cb, vb);
    EXPECT_EQ(ca, cb);
    EXPECT_EQ(ca, cc);
    ASSERT_EQ(va.size(), vb.size());
    ASSERT_EQ(va.size(), vc.size());
    EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(Vec2)));
    EXPECT_EQ(0, std::memcmp(va.data(), vc.data(), va.size() * sizeof(Vec2)));
  }
}

// A Möbius strip whose channel is continuous but across the sides of every
// fifth face, a value per vertex elsewhere.
Mesh strip_with_seamed_band(bool triangles)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3);
  if (triangles)
    CGAL_ext::triangulate_faces(m);
  auto uv = m.add_corner_channel<UV>("c:uv").first;
  for (CGAL_ext::Vertex_index v : m.vertices())
    uv.add_value({double(v.idx()), double(v.idx() % 5)});
  for (CGAL_ext::Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      uv.set_index(m.corner(d), f.idx() % 5 == 2 ? std::uint32_t(uv.add_value({0.5, double(f.idx())}))
                                                 : std::uint32_t(m.target(d).idx()));
  return m;
}

TEST(CornerChannels, ParallelIsSerialBitForBit)
{
  const Shape s = read_shape(test::data("opensubdiv/catmark_chaikin1.obj"));
  const Mesh m = build(s);
  std::vector<float> es(m.number_of_edges());
  for (CGAL_ext::Edge_index e : m.edges())
    es[e.idx()] = (*m.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name))[e];
  expect_parallel_is_serial<S::Catmull_clark_mask>(m, s.crease_method, es);
  // Möbius edges, a border, and the triangle split.
  const Mesh quads = strip_with_seamed_band(false), triangles = strip_with_seamed_band(true);
  expect_parallel_is_serial<S::Catmull_clark_mask>(quads, CGAL_ext::Crease_method::uniform,
                                                   std::vector<float>(quads.number_of_edges()));
  expect_parallel_is_serial<S::Loop_mask>(triangles, CGAL_ext::Crease_method::uniform,
                                          std::vector<float>(triangles.number_of_edges()));
}
#endif

TEST(CornerChannels, RefusedWhereNotCarried)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 8, 2);
  fill_distinct(m);
  const Mesh before = m;
  EXPECT_THROW(S::doo_sabin(m), CGAL_ext::Parameter_error);
  EXPECT_THROW(S::sqrt3(m), CGAL_ext::Parameter_error);
  EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
  // A corner without a value.
  m.corner_channel<UV>("c:uv")->set_index(m.corner(m.halfedge(CGAL_ext::Face_index(2))), UINT32_MAX);
  EXPECT_THROW(S::catmull_clark(m), CGAL_ext::Parameter_error);
  // Values that have no linear combination.
  Mesh n;
  CGAL_ext::make_mobius_strip(n, 8, 2);
  n.add_corner_channel<int>("c:id");
  EXPECT_THROW(S::catmull_clark(n), CGAL_ext::Parameter_error);
}

} // namespace

} // namespace corner_channel_tests
