// Non-manifold input: the soup import's policy on each kind of
// non-manifoldness, and the subdivision of the sheets against OpenSubdiv on
// the joined input (OpenSubdiv's Vtr holds non-manifold topology).
#include "subdivision_shapes.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh/Euler_operations.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/Subdivision/limit.h>
#include <CGAL_ext/isotropic_remeshing.h>
#include <CGAL_ext/offset_mesh.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

namespace {

using namespace subdivision_shapes;
namespace PM = CGAL_ext::parameters;
using CGAL_ext::Non_manifold_policy;

const auto split_policy = PM::non_manifold_policy(Non_manifold_policy::split);

// n quads around the edge (0, 1) of the z axis, as pages of a book.
Shape book(int pages)
{
  Shape s;
  s.points = {Point(0, 0, 0), Point(0, 0, 1)};
  for (int k = 0; k < pages; ++k) {
    const double a = 2 * M_PI * k / pages;
    s.points.emplace_back(std::cos(a), std::sin(a), 0);
    s.points.emplace_back(std::cos(a), std::sin(a), 1);
    s.faces.push_back({0, 2 + 2 * k, 3 + 2 * k, 1});
  }
  return s;
}

// The Soup_error that importing the soup into an empty mesh with `np`
// throws (none if it succeeds); a failed import leaves the mesh empty.
template <class NamedParameters>
std::optional<CGAL_ext::Soup_error> import_error(const std::vector<Point>& points,
                                                 const std::vector<std::vector<int>>& polygons,
                                                 const NamedParameters& np)
{
  Mesh m;
  try {
    CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m, np);
  } catch (const CGAL_ext::Soup_error& e) {
    EXPECT_EQ(m.number_of_vertices(), 0u);
    return e;
  }
  return std::nullopt;
}

TEST(NonManifold, an_edge_of_three_or_more_polygons_is_refused_by_default)
{
  const Shape s = book(3);
  const auto e = import_error(s.points, s.faces, PM::default_values());
  ASSERT_TRUE(e) << "no Soup_error";
  EXPECT_EQ(e->kind(), CGAL_ext::Soup_error::Kind::non_manifold_edge);
  EXPECT_EQ(e->polygons(), (std::vector<std::size_t>{0, 1, 2}));
}

TEST(NonManifold, an_edge_of_3_4_or_100_polygons_becomes_a_border_per_polygon)
{
  for (int pages : {3, 4, 100}) {
    const Shape s = book(pages);
    Mesh m;
    // Each page keeps the spine's two points: one vertex per page and end.
    EXPECT_EQ(CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m, split_policy), std::size_t(2 * (pages - 1)));
    EXPECT_TRUE(m.is_valid(true));
    EXPECT_EQ(m.number_of_faces(), std::size_t(pages));
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), std::size_t(pages));
    const CGAL_ext::Non_manifold_counts counts = CGAL_ext::non_manifold_counts(m);
    EXPECT_EQ(counts.edges, 1u);
    EXPECT_EQ(counts.vertices, 2u);
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    CGAL_ext::joined_polygon_soup(m, points, polygons);
    EXPECT_EQ(points, s.points);
    std::multiset<std::set<std::size_t>> ours, theirs;
    for (const auto& p : polygons)
      ours.insert({p.begin(), p.end()});
    for (const auto& f : s.faces)
      theirs.insert({f.begin(), f.end()});
    EXPECT_EQ(ours, theirs);
  }
}

TEST(NonManifold, a_pinched_vertex_splits_and_a_bare_vertex_stays)
{
  // Two triangles that meet at point 0 only, and point 5 in no polygon.
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0),
                                     Point(-1, 0, 0), Point(0, -1, 0), Point(3, 3, 3)};
  const std::vector<std::vector<int>> polygons = {{0, 1, 2}, {0, 3, 4}};
  Mesh refused;
  EXPECT_THROW(CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, refused), CGAL_ext::Soup_error);
  Mesh duplicated; // CGAL's duplicate_non_manifold_vertices(): no joins kept
  EXPECT_EQ(CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, duplicated, PM::split_non_manifold_vertices(true)),
            1u);
  EXPECT_FALSE(CGAL_ext::non_manifold_join_map(duplicated));
  Mesh m;
  EXPECT_EQ(CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m, split_policy), 1u);
  EXPECT_EQ(m.number_of_vertices(), 7u);
  EXPECT_EQ(CGAL_ext::non_manifold_counts(m).vertices, 1u);
  EXPECT_EQ(CGAL_ext::non_manifold_counts(m).edges, 0u);
  EXPECT_EQ(CGAL_ext::non_manifold_representative(m, CGAL_ext::Vertex_index(6)), CGAL_ext::Vertex_index(0));
  EXPECT_EQ((*CGAL_ext::non_manifold_join_map(m))[CGAL_ext::Vertex_index(0)], CGAL_ext::no_non_manifold_join);
  // Subdivided as OpenSubdiv does: the pinched vertex is a corner, the bare one stays.
  CGAL_ext::Subdivision::loop(m, PM::number_of_iterations(2));
  std::vector<Point> out;
  std::vector<std::vector<std::size_t>> faces;
  CGAL_ext::joined_polygon_soup(m, out, faces);
  EXPECT_EQ(out[0], Point(0, 0, 0));
  EXPECT_EQ(out[5], Point(3, 3, 3));
  EXPECT_EQ(faces.size(), 32u);
}

TEST(NonManifold, a_polygon_that_visits_a_vertex_twice_is_refused_by_default)
{
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  const auto e = import_error(points, {{0, 1, 2, 2}}, PM::default_values());
  ASSERT_TRUE(e) << "no Soup_error";
  EXPECT_EQ(e->kind(), CGAL_ext::Soup_error::Kind::repeated_vertex);
}

// A hexagon (0, 1, 2, 0, 3, 4) that visits vertex 0 twice, and polygons
// round vertex 0 that put both visits in one fan: with `fan` = {1, 0, 2}
// the fan is open and starts (its side leaving vertex 0 a border) at the
// hexagon's second visit; with {3, 0, 4} at its first; with both the fan
// is closed.
std::vector<Point> folded_hexagon_points()
{
  return {Point(0, 0, 0.1),  Point(1, 0, 0),     Point(0.7, 0.7, 0.2), Point(-1, 0, 0.1),
          Point(-0.6, -0.8, 0), Point(0.3, -1, 0.5), Point(0.8, -0.9, 0.4)};
}

// Where OpenSubdiv orders the polygons round the vertex, it gives both
// visits one corner (the hexagon's first at vertex 0: Vtr::Level::
// populateLocalIndices() runs after the ordering), so that the next level
// holds one of the hexagon's faces twice round the vertex and the other
// not at all: no sheet holds that; refused, by polygon and vertex. So is a
// fan where two polygons run along a side the same way (Vtr makes it a
// non-manifold edge, the sheets a Möbius edge).
TEST(NonManifold, a_polygon_that_visits_a_vertex_twice_within_one_fan_opensubdiv_orders_is_refused)
{
  const std::vector<Point> points = folded_hexagon_points();
  const std::vector<std::pair<std::vector<std::vector<int>>, std::string>> cases = {
    {{{0, 1, 2, 0, 3, 4}, {3, 0, 4}}, "orders the fan"},
    {{{0, 1, 2, 0, 3, 4}, {1, 0, 2}, {3, 0, 4}}, "orders the fan"},
    {{{0, 1, 2, 0, 3, 4}, {0, 3, 1}}, "the same way"}};
  for (const auto& [polygons, why] : cases) {
    SCOPED_TRACE(polygons.size());
    const auto e = import_error(points, polygons, split_policy);
    ASSERT_TRUE(e) << "no Soup_error";
    EXPECT_EQ(e->kind(), CGAL_ext::Soup_error::Kind::repeated_vertex);
    EXPECT_EQ(e->polygons(), std::vector<std::size_t>{0});
    EXPECT_EQ(e->vertices(), std::vector<std::size_t>{0});
    EXPECT_NE(std::string(e->what()).find(why), std::string::npos) << e->what();
  }
}

// What cannot follow the joins refuses them, before it touches the mesh.
TEST(NonManifold, operations_that_renumber_vertices_refuse_sheets)
{
  const Shape s = book(3);
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m, split_policy);
  const std::size_t vertices = m.number_of_vertices();
  EXPECT_THROW(CGAL_ext::Subdivision::doo_sabin(m), CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::Subdivision::sqrt3(m), CGAL_ext::Parameter_error);
  EXPECT_THROW(CGAL_ext::isotropic_remeshing(m, 0.5), CGAL_ext::Parameter_error);
  Mesh offset;
  EXPECT_THROW(CGAL_ext::offset_mesh(m, 0.1, offset), CGAL_ext::Parameter_error);
  Mesh copy = m;
  auto limits = copy.add_property_map<CGAL_ext::Vertex_index, Point>("v:limit").first;
  EXPECT_THROW(CGAL_ext::Subdivision::limit_points<CGAL_ext::Subdivision::Catmull_clark_mask>(copy, limits),
               CGAL_ext::Parameter_error);
  EXPECT_EQ(m.number_of_vertices(), vertices);
  EXPECT_TRUE(CGAL_ext::non_manifold_join_map(m).has_value());
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV

// Where the position of each point lies among OpenSubdiv's: the lowest index
// of its points within `tolerance` (a bare vertex may lie on another).
struct Position_index
{
  std::vector<std::pair<double, int>> by_x;
  const std::vector<Osd_vertex>* points;
  double tolerance;

  Position_index(const std::vector<Osd_vertex>& p, double t) : points(&p), tolerance(t)
  {
    for (int i = 0; i < int(p.size()); ++i)
      by_x.push_back({p[i].p[0], i});
    std::sort(by_x.begin(), by_x.end());
  }
  int find(double x, double y, double z) const
  {
    int best = -1;
    for (auto it = std::lower_bound(by_x.begin(), by_x.end(), std::make_pair(x - tolerance, -1));
         it != by_x.end() && it->first <= x + tolerance; ++it) {
      const double* q = (*points)[it->second].p;
      if (std::abs(q[1] - y) <= tolerance && std::abs(q[2] - z) <= tolerance && (best < 0 || it->second < best))
        best = it->second;
    }
    return best;
  }
};

// OpenSubdiv takes two faces that run the same way along an edge as a
// non-manifold edge; the soup import connects them (reversing one, or as a
// Möbius edge). OpenSubdiv is given the faces as the import oriented them.
Shape as_oriented(const Shape& s, const Mesh& m)
{
  Shape r = s;
  for (std::size_t f = 0; f < r.faces.size(); ++f) {
    std::vector<int> vs;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(m.halfedge(CGAL_ext::Face_index(f)), m))
      vs.push_back(int(CGAL_ext::non_manifold_representative(m, v).idx()));
    // A polygon that visits a vertex twice may start at either visit.
    bool same_way = false;
    for (std::size_t k = 0; k < vs.size() && !same_way; ++k) {
      std::rotate(vs.begin(), vs.begin() + 1, vs.end());
      same_way = vs == r.faces[f];
    }
    if (!same_way)
      std::reverse(r.faces[f].begin() + 1, r.faces[f].end());
  }
  return r;
}

// The crease tags of `s` on the edges of `m` whose ends are the tag's points.
template <class M>
void set_crease_tags(const Shape& s, M& m)
{
  if (s.crease_pairs.empty())
    return;
  auto sharpness = CGAL_ext::edge_sharpness_map(m);
  for (std::size_t i = 0; i < s.crease_pairs.size(); ++i)
    for (CGAL_ext::Edge_index e : m.edges()) {
      const auto a = m.vertex(e, 0), b = m.vertex(e, 1);
      const std::set<int> ends = {int(CGAL_ext::non_manifold_representative(m, a).idx()),
                                  int(CGAL_ext::non_manifold_representative(m, b).idx())};
      if (ends == std::set<int>{s.crease_pairs[i][0], s.crease_pairs[i][1]})
        sharpness[e] = s.crease_values[i];
    }
}

// Subdivides `s` n times through the sheets and compares the joined result
// with OpenSubdiv's level n: every point within 1e-12 of one of its, each
// of its points met, the same faces (as sets of points).
template <class K = test::Kd>
void expect_opensubdiv_result(Shape s, Sdc::SchemeType type, int n)
{
  using KPoint = typename K::Point_3;
  CGAL_ext::Mobius_mesh<KPoint> m;
  std::vector<KPoint> input;
  for (const Point& p : s.points)
    input.emplace_back(p.x(), p.y(), p.z());
  CGAL_ext::polygon_soup_to_mobius_mesh(input, s.faces, m, split_policy);
  set_crease_tags(s, m);
  Mesh oriented;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, oriented, split_policy);
  const Shape reference = as_oriented(s, oriented);
  const Osd_run osd = run_opensubdiv(reference, s, type, n);
  const auto boundary = test::opensubdiv_options(s).GetVtxBoundaryInterpolation() ==
                            Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
                          ? Boundary_interpolation::edge_and_corner
                          : Boundary_interpolation::edge_only;
  const auto np = PM::number_of_iterations(unsigned(n)).boundary_interpolation(boundary).crease_method(s.crease_method);
  if (type == Sdc::SCHEME_CATMARK)
    CGAL_ext::Subdivision::catmull_clark(m, np);
  else
    CGAL_ext::Subdivision::loop(m, np);
  // The copies of a joined vertex are at one point.
  for (CGAL_ext::Vertex_index v : m.vertices()) {
    const CGAL_ext::Vertex_index r = CGAL_ext::non_manifold_representative(m, v);
    ASSERT_LE(CGAL::to_double(CGAL::squared_distance(m.point(v), m.point(r))), 1e-24)
      << "vertex " << v.idx() << " and its join " << r.idx();
  }
  std::vector<KPoint> points;
  std::vector<std::vector<std::size_t>> polygons;
  CGAL_ext::joined_polygon_soup(m, points, polygons);
  // The non-manifold vertices and edges are OpenSubdiv's.
  const auto& base = osd.refiner->GetLevel(0);
  std::size_t vertices = 0, edges = 0;
  for (int v = 0; v < base.GetNumVertices(); ++v)
    vertices += base.IsVertexNonManifold(v) && base.GetVertexFaces(v).size() > 0 ? 1 : 0;
  for (int e = 0; e < base.GetNumEdges(); ++e)
    edges += base.IsEdgeNonManifold(e) ? 1 : 0;
  EXPECT_EQ(CGAL_ext::non_manifold_counts(oriented).vertices, vertices);
  EXPECT_EQ(CGAL_ext::non_manifold_counts(oriented).edges, edges);
  const auto& level = osd.refiner->GetLevel(n);
  ASSERT_EQ(points.size(), std::size_t(level.GetNumVertices()));
  ASSERT_EQ(polygons.size(), std::size_t(level.GetNumFaces()));
  const Position_index index(osd.levels[n], 1e-12);
  std::vector<int> ours(points.size());
  std::set<int> met;
  for (std::size_t v = 0; v < points.size(); ++v) {
    ours[v] = index.find(CGAL::to_double(points[v].x()), CGAL::to_double(points[v].y()),
                         CGAL::to_double(points[v].z()));
    ASSERT_GE(ours[v], 0) << "vertex " << v << " at " << points[v] << " is not a point of OpenSubdiv's";
    met.insert(ours[v]);
  }
  std::set<int> theirs_met;
  for (const Osd_vertex& p : osd.levels[n])
    theirs_met.insert(index.find(p.p[0], p.p[1], p.p[2]));
  EXPECT_EQ(met, theirs_met);
  std::multiset<std::set<int>> our_faces, their_faces;
  for (const auto& f : polygons) {
    std::set<int> face;
    for (std::size_t v : f)
      face.insert(ours[v]);
    our_faces.insert(face);
  }
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    std::set<int> face;
    const auto fv = level.GetFaceVertices(f);
    for (int i = 0; i < fv.size(); ++i)
      face.insert(index.find(osd.levels[n][fv[i]].p[0], osd.levels[n][fv[i]].p[1], osd.levels[n][fv[i]].p[2]));
    their_faces.insert(face);
  }
  EXPECT_EQ(our_faces, their_faces);
}

Shape nonmanifold_shape(const std::string& name) { return read_shape(test::data("opensubdiv/" + name)); }

// A 3 x 3 grid of unit quads (points 4 * j + i), cell `cell` (j * 3 + i)
// replaced by `polygon`, on the grid's points, which visits one twice, and
// cell `removed` left out.
Shape grid_with(int cell, const std::vector<int>& polygon, int removed = -1)
{
  Shape s;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      s.points.emplace_back(i, j, 0.1 * ((i * 7 + j * 3) % 5)); // off the plane: the rules move points
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (3 * j + i == cell)
        s.faces.push_back(polygon);
      else if (3 * j + i != removed)
        s.faces.push_back({4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4});
  return s;
}

// Catmull-Clark on each shape, levels 1-3, under both boundary rules, as
// OpenSubdiv.
void expect_catmull_clark_as_opensubdiv(const std::vector<Shape>& shapes)
{
  for (std::size_t k = 0; k < shapes.size(); ++k)
    for (int n = 1; n <= 3; ++n) {
      SCOPED_TRACE("shape " + std::to_string(k) + ", level " + std::to_string(n));
      expect_opensubdiv_result(shapes[k], Sdc::SCHEME_CATMARK, n);
      Shape corners = shapes[k];
      corners.boundary = Boundary_interpolation::edge_and_corner;
      expect_opensubdiv_result(corners, Sdc::SCHEME_CATMARK, n);
    }
}

// Each kind of repeated vertex OpenSubdiv takes: a degenerate edge (1, 1)
// on the border; a polygon that runs along the pair (5, 6) three times; one
// over two cells whose two visits of vertex 5 are apart, its sides all
// distinct (its corners there in two fans); a triangle on one vertex.
// Subdivided through the sheets and joined, as OpenSubdiv.
TEST(NonManifold, polygons_that_visit_a_vertex_twice_as_opensubdiv)
{
  REQUIRE_OPENSUBDIV();
  Shape thrice; // a triangle (v, v, v) at a corner of another
  thrice.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0.2)};
  thrice.faces = {{0, 1, 2}, {0, 0, 0}};
  expect_catmull_clark_as_opensubdiv({grid_with(0, {0, 1, 1, 5, 4}), grid_with(4, {5, 6, 5, 6, 10, 9}),
                                      grid_with(4, {5, 6, 10, 9, 5, 4, 0, 1}, 0), thrice});
}

// Where OpenSubdiv's ordering fails, the vertex is non-manifold (infinitely
// sharp) and keeps the polygons' corners: the open fan that starts at the
// hexagon's second visit, either way round the hexagon, and a vertex with a
// second fan. The polygon keeps visiting the vertex twice in the sheet.
TEST(NonManifold, a_polygon_that_visits_a_vertex_twice_within_one_fan_as_opensubdiv)
{
  const std::vector<Point> points = folded_hexagon_points();
  std::vector<Shape> shapes;
  for (const std::vector<std::vector<int>>& polygons :
       {std::vector<std::vector<int>>{{0, 1, 2, 0, 3, 4}, {1, 0, 2}},
        std::vector<std::vector<int>>{{1, 2, 0, 3, 4, 0}, {3, 0, 4}},
        std::vector<std::vector<int>>{{0, 1, 2, 0, 3, 4}, {1, 0, 2}, {0, 5, 6}}}) {
    Shape s;
    s.points = points;
    s.faces = polygons;
    Mesh m;
    CGAL_ext::polygon_soup_to_mobius_mesh(points, polygons, m, split_policy);
    EXPECT_TRUE(m.is_valid(true));
    EXPECT_EQ(CGAL_ext::non_manifold_counts(m).vertices, 1u);
    CGAL::Surface_mesh<Point> sm;
    EXPECT_THROW(CGAL_ext::to_surface_mesh(m, sm), CGAL_ext::Parameter_error); // it cannot rebuild the folded face
    shapes.push_back(s);
  }
  REQUIRE_OPENSUBDIV();
  expect_catmull_clark_as_opensubdiv(shapes);
}

// A degenerate edge at an interior vertex: the vertex's polygons form one
// fan from one end of the edge round to the other, so the edge is a loop
// of the sheet (a border from the vertex to itself).
TEST(NonManifold, a_degenerate_edge_inside_a_fan_is_a_loop)
{
  const Shape s = grid_with(4, {5, 5, 6, 10, 9});
  Mesh m;
  EXPECT_EQ(CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m, split_policy), 0u);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_vertices(), 16u);
  EXPECT_EQ(m.number_of_edges(), 25u); // the grid's 24, with the degenerate one
  ASSERT_TRUE(CGAL_ext::non_manifold_join_map(m)); // none joined, but not a manifold
  EXPECT_EQ(CGAL_ext::non_manifold_counts(m).vertices, 1u);
  EXPECT_EQ(CGAL_ext::non_manifold_counts(m).edges, 1u);
  std::vector<CGAL_ext::Edge_index> loops;
  for (CGAL_ext::Edge_index e : m.edges())
    if (m.vertex(e, 0) == m.vertex(e, 1))
      loops.push_back(e);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(m.vertex(loops[0], 0), CGAL_ext::Vertex_index(5));
  EXPECT_TRUE(m.is_border(loops[0]));
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 2u); // the grid's and the loop's own
  // No Euler operation folds it away; the mesh stays as it was.
  EXPECT_FALSE(CGAL_ext::Euler::does_satisfy_link_condition(m.halfedge(loops[0]), m));
  for (bool join : {false, true})
    try {
      if (join)
        CGAL_ext::Euler::join_vertex(m.halfedge(loops[0]), m);
      else
        CGAL_ext::Euler::collapse_edge(m.halfedge(loops[0]), m);
      ADD_FAILURE() << "no Euler_error";
    } catch (const CGAL_ext::Euler_error& e) {
      EXPECT_NE(std::string(e.what()).find("loop"), std::string::npos) << e.what();
    }
  const CGAL_ext::Face_index polygon(4);
  std::vector<CGAL_ext::Dart> at_5;
  for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(polygon), m))
    if (m.target(d) == CGAL_ext::Vertex_index(5))
      at_5.push_back(d);
  ASSERT_EQ(at_5.size(), 2u);
  EXPECT_THROW(CGAL_ext::Euler::split_face(at_5[0], at_5[1], m), CGAL_ext::Euler_error);
  EXPECT_THROW(CGAL_ext::Euler::remove_face(at_5[0], m), CGAL_ext::Euler_error);
  EXPECT_TRUE(m.is_valid(true));
  EXPECT_EQ(m.number_of_edges(), 25u);
  EXPECT_EQ(m.number_of_faces(), 9u);
  // The Newell normal sums every corner, not only those before the second
  // visit (up to sign: the import may have turned the polygon round).
  const auto n = CGAL_ext::face_normal(polygon, m);
  using Vector = CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  Vector newell(0, 0, 0);
  for (std::size_t i = 0; i < s.faces[4].size(); ++i)
    newell = newell + CGAL::cross_product(s.points[s.faces[4][i]] - CGAL::ORIGIN,
                                          s.points[s.faces[4][(i + 1) % s.faces[4].size()]] - CGAL::ORIGIN);
  EXPECT_LE(std::min((n - newell).squared_length(), (n + newell).squared_length()), 1e-24) << n << " against " << newell;
  // Written joined, it is the soup again.
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  CGAL_ext::joined_polygon_soup(m, points, polygons);
  EXPECT_EQ(points, s.points);
  auto least_rotation = [](std::vector<std::size_t> p) {
    std::vector<std::size_t> least = p;
    for (std::size_t k = 1; k < p.size(); ++k) {
      std::rotate(p.begin(), p.begin() + 1, p.end());
      least = std::min(least, p);
    }
    return least;
  };
  std::multiset<std::vector<std::size_t>> ours, theirs;
  for (const auto& p : polygons)
    ours.insert(least_rotation(p));
  for (const auto& f : s.faces)
    theirs.insert(least_rotation({f.begin(), f.end()}));
  EXPECT_EQ(ours, theirs);
}

// Degenerate edges inside one fan (loops): between two corners and across
// the polygon's first corner; in a polygon the import turns round to agree
// with its neighbours (the loop's border, its own neighbour, turns with
// it), beside a degenerate edge on the border; two in a row.
TEST(NonManifold, a_degenerate_edge_inside_a_fan_as_opensubdiv)
{
  REQUIRE_OPENSUBDIV();
  Shape turned;
  turned.points = {Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0.2), Point(0, 1, 0.1),
                   Point(1, 1, 0.3), Point(2, 1, 0), Point(1, 2, 0.2)};
  turned.faces = {{0, 1, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 6}, {3, 5, 4, 6, 6}};
  // With two in a row, the middle corner is a fan of its own (a copy of the
  // vertex), the outer two lie in one fan: a folded face.
  expect_catmull_clark_as_opensubdiv(
    {grid_with(4, {5, 5, 6, 10, 9}), grid_with(4, {5, 6, 10, 9, 5}), turned, grid_with(4, {5, 5, 5, 6, 10, 9})});
}

TEST(NonManifold, catmull_clark_equals_opensubdiv_on_its_non_manifold_shapes)
{
  REQUIRE_OPENSUBDIV();
  for (const char* name :
       {"catmark_nonman_edges.obj", "catmark_nonman_verts.obj", "catmark_nonman_bareverts.obj",
        "catmark_nonman_quadpole8.obj", "catmark_nonman_quadpole64.obj", "catmark_val2_nonman.obj", "catmark_fan.obj",
        "catmark_gregory_test4.obj"})
    for (int n = 1; n <= 3; ++n) {
      SCOPED_TRACE(std::string(name) + " level " + std::to_string(n));
      expect_opensubdiv_result(nonmanifold_shape(name), Sdc::SCHEME_CATMARK, n);
    }
}

TEST(NonManifold, loop_equals_opensubdiv_on_its_non_manifold_shapes)
{
  REQUIRE_OPENSUBDIV();
  for (int n = 1; n <= 3; ++n) {
    SCOPED_TRACE("level " + std::to_string(n));
    for (const char* name : {"loop_nonman_edges.obj", "loop_nonman_verts.obj", "loop_val2_interior.obj"}) {
      SCOPED_TRACE(name);
      expect_opensubdiv_result(nonmanifold_shape(name), Sdc::SCHEME_LOOP, n);
    }
  }
}

TEST(NonManifold, with_an_exact_kernel_too)
{
  REQUIRE_OPENSUBDIV();
  expect_opensubdiv_result<CGAL::Exact_predicates_exact_constructions_kernel>(
    nonmanifold_shape("catmark_val2_nonman.obj"), Sdc::SCHEME_CATMARK, 2);
}

TEST(NonManifold, a_book_of_pages_and_its_spine_as_opensubdiv)
{
  REQUIRE_OPENSUBDIV();
  for (int pages : {3, 4, 7})
    expect_opensubdiv_result(book(pages), Sdc::SCHEME_CATMARK, 2);
}

// Pages of two quads each on a spine of two edges (0, 1) and (1, 2): vertex
// 1 lies on an interior non-manifold crease, whose rule no copy of it sees
// from its own page once a page edge at it is semi-sharp, or once a page is
// a single triangle on both spine edges (a corner of its sheet).
Shape spine_book(int pages, bool triangle_page)
{
  Shape s;
  s.points = {Point(0, 0, 0), Point(0.3, -0.2, 1), Point(0, 0, 2)}; // a bent spine: its crease rule moves vertex 1
  for (int k = 0; k < pages; ++k) {
    const double a = 2 * M_PI * k / pages, r = 1 + 0.25 * k;
    const int first = int(s.points.size());
    for (int z = 0; z < 3; ++z)
      s.points.emplace_back(r * std::cos(a), r * std::sin(a), z + 0.1 * k * (z == 1));
    s.faces.push_back({0, first, first + 1, 1});
    s.faces.push_back({1, first + 1, first + 2, 2});
  }
  if (triangle_page)
    s.faces.push_back({0, 1, 2});
  return s;
}

TEST(NonManifold, an_interior_non_manifold_crease_as_opensubdiv)
{
  REQUIRE_OPENSUBDIV();
  Shape semi_sharp = spine_book(3, false);
  semi_sharp.crease_pairs = {{1, 4}};
  semi_sharp.crease_values = {1.5f};
  Shape triangle = spine_book(3, true);
  triangle.boundary = Boundary_interpolation::edge_and_corner;
  // Chaikin's rule decays a semi-sharp edge by the average of those around
  // its vertex: all the joined vertex's, in every sheet (two here).
  Shape chaikin = spine_book(3, false);
  chaikin.crease_pairs = {{1, 4}, {1, 7}, {0, 3}};
  chaikin.crease_values = {1.5f, 3.25f, 2.0f};
  chaikin.crease_method = CGAL_ext::Crease_method::chaikin;
  for (int n = 1; n <= 3; ++n) {
    expect_opensubdiv_result(semi_sharp, Sdc::SCHEME_CATMARK, n);
    expect_opensubdiv_result(triangle, Sdc::SCHEME_CATMARK, n);
    expect_opensubdiv_result(chaikin, Sdc::SCHEME_CATMARK, n);
  }
}

// A Möbius strip of 8 x 2 quads with a fin: a quad on the edge between
// columns 3 and 4 of its middle row, which then has three faces.
Shape mobius_with_fin()
{
  Shape s;
  const int n = 8;
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 3; ++r) {
      const double t = 2 * M_PI * i / n, w = 0.5 * (r - 1), c = 2 + w * std::cos(t / 2);
      s.points.emplace_back(c * std::cos(t), c * std::sin(t), w * std::sin(t / 2));
    }
  auto at = [](int i, int r) { return 3 * i + r; };
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 2; ++r) {
      if (i + 1 < n)
        s.faces.push_back({at(i, r), at(i + 1, r), at(i + 1, r + 1), at(i, r + 1)});
      else // the half twist: row r meets row 2 - r
        s.faces.push_back({at(i, r), at(0, 2 - r), at(0, 1 - r), at(i, r + 1)});
    }
  const int f = int(s.points.size());
  s.points.emplace_back(0.2, 2.6, 1.0);
  s.points.emplace_back(-0.6, 2.3, 1.1);
  s.faces.push_back({at(3, 1), at(4, 1), f + 1, f});
  return s;
}

// OpenSubdiv's reference for a one-sided sheet with a fin: the orientation
// double cover of the strip (two twins per vertex), and a copy of the fin on
// each of the two twins of the edge it stands on.
Shape mobius_with_fin_cover(const Shape& s)
{
  Built strip;
  const std::vector<std::vector<int>> strip_faces(s.faces.begin(), s.faces.end() - 1);
  const std::vector<Point> strip_points(s.points.begin(), s.points.end() - 2);
  CGAL_ext::polygon_soup_to_mobius_mesh(strip_points, strip_faces, strip.mesh);
  Shape cover = double_cover(strip.mesh, strip);
  const std::vector<int>& fin = s.faces.back();
  for (const auto& f : std::vector<std::vector<int>>(cover.faces))
    for (std::size_t i = 0; i < f.size(); ++i) {
      const int a = f[i], b = f[(i + 1) % f.size()];
      if (a / 2 == fin[0] && b / 2 == fin[1]) { // a twin of the fin's edge, once per twin
        const int first = int(cover.points.size());
        cover.points.push_back(s.points[fin[2]]);
        cover.points.push_back(s.points[fin[3]]);
        cover.faces.push_back({a, b, first, first + 1});
      }
    }
  EXPECT_EQ(cover.points.size(), 2 * strip_points.size() + 4);
  return cover;
}

TEST(NonManifold, a_one_sided_sheet_with_a_fin_as_opensubdiv_on_its_double_cover)
{
  REQUIRE_OPENSUBDIV();
  const Shape s = mobius_with_fin();
  const Shape cover = mobius_with_fin_cover(s);
  for (int n = 1; n <= 3; ++n) {
    SCOPED_TRACE("level " + std::to_string(n));
    Mesh m;
    CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m, split_policy);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(CGAL_ext::non_manifold_counts(m).edges, 1u);
    CGAL_ext::Subdivision::catmull_clark(m, PM::number_of_iterations(unsigned(n)));
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    CGAL_ext::joined_polygon_soup(m, points, polygons);
    const Osd_run osd = run_opensubdiv(cover, cover, Sdc::SCHEME_CATMARK, n);
    // Each point of ours is a point of the cover's, and each of the cover's one of ours.
    const Position_index theirs(osd.levels[n], 1e-12);
    std::vector<Osd_vertex> our_points;
    for (const Point& p : points) {
      EXPECT_GE(theirs.find(p.x(), p.y(), p.z()), 0) << p;
      our_points.push_back({{p.x(), p.y(), p.z()}});
    }
    const Position_index ours(our_points, 1e-12);
    for (const Osd_vertex& p : osd.levels[n])
      EXPECT_GE(ours.find(p.p[0], p.p[1], p.p[2]), 0) << p.p[0] << ' ' << p.p[1] << ' ' << p.p[2];
    // Every face twice in the cover (the fin once per twin of its edge).
    EXPECT_EQ(polygons.size() * 2, std::size_t(osd.refiner->GetLevel(n).GetNumFaces()));
  }
}
#endif

TEST(NonManifold, files_are_read_as_sheets_and_written_joined)
{
  Mesh m;
  const std::string in = test::data("opensubdiv/catmark_val2_nonman.obj");
  EXPECT_THROW(CGAL_ext::IO::read_polygon_mesh(in, m), CGAL_ext::IO_error);
  CGAL_ext::IO::read_polygon_mesh(in, m, split_policy);
  EXPECT_EQ(CGAL_ext::non_manifold_counts(m).edges, 2u);
  CGAL_ext::Subdivision::catmull_clark(m);
  const std::string out = (std::filesystem::temp_directory_path() / "cgal_ext_non_manifold.obj").string();
  CGAL_ext::IO::write_polygon_mesh(out, m);
  // CGAL's own reader, which knows nothing of joins, reads the joined soup.
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  ASSERT_TRUE(CGAL::IO::read_polygon_soup(out, points, polygons));
  std::vector<Point> joined;
  std::vector<std::vector<std::size_t>> joined_polygons;
  CGAL_ext::joined_polygon_soup(m, joined, joined_polygons);
  EXPECT_EQ(points.size(), joined.size());
  EXPECT_LT(points.size(), m.number_of_vertices());
  EXPECT_EQ(polygons, joined_polygons);
  std::filesystem::remove(out);
}

} // namespace
