// The two-sided scene that draws a Mobius_mesh (Mobius_mesh/two_sided_scene.h)
// and the screenshot settings of its viewer (draw_mobius_mesh.h): the two
// sheets of a Möbius strip the gap apart and swapping across Möbius edges, the
// front sheet of an outward torus outside, edges coloured by sharpness, and
// bad input refused.

#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/two_sided_scene.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/draw_mobius_mesh.h>

#include <CGAL/Bbox_3.h>
#include <boost/property_map/function_property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace two_sided_scene_tests {

namespace {

namespace X = CGAL_ext;
using Kd = test::Kd;
using Epeck = test::Epeck;

// The two sheets of a scene: for each face, the front and back corner of each
// of its vertices (the back runs the other way round).
struct Sheets
{
  std::map<std::pair<std::size_t, std::size_t>, Kd::Point_3> front, back; // (face, vertex)
};

template <class P>
Sheets sheets_of(const X::Two_sided_scene& scene, const X::Mobius_mesh<P>& mesh)
{
  Sheets sheets;
  for (const auto& face : scene.faces) {
    std::vector<X::Vertex_index> vertices;
    for (X::Dart d : X::halfedges_around_face(face.face, mesh))
      vertices.push_back(mesh.target(d));
    if (face.back)
      std::reverse(vertices.begin(), vertices.end());
    EXPECT_EQ(face.size, vertices.size());
    for (std::size_t i = 0; i < face.size; ++i)
      (face.back ? sheets.back : sheets.front)[{face.face.idx(), vertices[i].idx()}] = scene.corners[face.first_corner + i];
  }
  return sheets;
}

double diagonal_of(const CGAL::Bbox_3& b)
{
  return std::sqrt(CGAL::square(b.x_span()) + CGAL::square(b.y_span()) + CGAL::square(b.z_span()));
}

template <class K>
void check_strip_scene()
{
  X::Mobius_mesh<typename K::Point_3> strip;
  X::make_mobius_strip(strip, 12, 3);
  const X::Two_sided_style style;
  const X::Two_sided_scene scene = X::make_two_sided_scene(strip);
  std::size_t corners = 0;
  for (X::Face_index f : strip.faces())
    corners += strip.degree(f);
  EXPECT_EQ(scene.faces.size(), 2 * strip.number_of_faces());
  EXPECT_EQ(scene.corners.size(), 2 * corners);
  EXPECT_EQ(scene.normals.size(), 2 * corners);
  EXPECT_EQ(scene.segments.size(), 2 * strip.number_of_edges()); // every edge of a strip has a face
  using Kind = X::Two_sided_scene::Edge_kind;
  const auto count = [&](Kind kind) {
    return std::size_t(std::count_if(scene.segments.begin(), scene.segments.end(),
                                     [kind](const auto& s) { return s.kind == kind; }));
  };
  EXPECT_EQ(count(Kind::border), 2u * 2u * 12u); // one border loop around twice: 24 edges, drawn on both sheets
  ASSERT_GT(X::number_of_mobius_edges(strip), 0u);
  EXPECT_EQ(count(Kind::mobius), 2 * X::number_of_mobius_edges(strip));
  for (const auto& s : scene.segments) {
    if (s.kind == Kind::mobius) {
      EXPECT_EQ(s.color, style.mobius);
    }
  }

  // Each vertex of each face lies halfway between its two sheets, the gap apart.
  CGAL::Bbox_3 box;
  for (X::Vertex_index v : strip.vertices())
    box += strip.point(v).bbox();
  const double diagonal = diagonal_of(box);
  const Sheets sheets = sheets_of(scene, strip);
  for (const auto& [key, front] : sheets.front) {
    const auto& p = strip.point(X::Vertex_index(std::uint32_t(key.second)));
    const Kd::Point_3 point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    const Kd::Point_3& back = sheets.back.at(key);
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(front, back)), style.gap * diagonal, 1e-12 * diagonal);
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(CGAL::midpoint(front, back), point)), 0.0, 1e-12 * diagonal);
  }
  // Faces that agree in orientation share their sheets; across a Möbius edge
  // one face's front is the other's back: the colours swap there.
  std::size_t mobius_seen = 0;
  for (X::Edge_index e : strip.edges()) {
    const X::Dart d = strip.halfedge(e);
    if (strip.is_border(e))
      continue;
    const std::size_t f1 = strip.face(d).idx(), f2 = strip.face(strip.opposite(d)).idx();
    for (X::Vertex_index v : {strip.source(d), strip.target(d)}) {
      const auto& mine = sheets.front.at({f1, v.idx()});
      const auto& theirs = strip.is_mobius(e) ? sheets.back.at({f2, v.idx()}) : sheets.front.at({f2, v.idx()});
      EXPECT_LE(std::sqrt(CGAL::squared_distance(mine, theirs)), 1e-12 * diagonal) << e << " " << v;
    }
    mobius_seen += strip.is_mobius(e);
  }
  EXPECT_EQ(mobius_seen, X::number_of_mobius_edges(strip));
}

TEST(TwoSidedScene, StripSheetsAreTheGapApartAndSwapAcrossMobiusEdges)
{
  check_strip_scene<Kd>();
  check_strip_scene<Epeck>();
}

// On an outward-oriented torus the front sheet is outside: farther from the
// core circle (radius R in the xy plane) than the tube's radius r, up to the
// chord's sag, and the back sheet inside.
TEST(TwoSidedScene, FrontSheetOfAnOutwardTorusIsOutside)
{
  X::Mobius_mesh<Kd::Point_3> torus;
  const double R = 2, r = 0.7;
  X::make_torus(torus, 24, 16, R, r);
  const auto tube_distance = [R](const Kd::Point_3& p) {
    return std::hypot(std::hypot(p.x(), p.y()) - R, p.z());
  };
  const X::Two_sided_scene scene = X::make_two_sided_scene(torus);
  ASSERT_EQ(scene.faces.size(), 2 * torus.number_of_faces());
  for (const auto& face : scene.faces)
    for (std::size_t i = face.first_corner; i < face.first_corner + face.size; ++i) {
      if (face.back) {
        EXPECT_LT(tube_distance(scene.corners[i]), r) << face.face;
      } else {
        EXPECT_GT(tube_distance(scene.corners[i]), r) << face.face;
      }
    }
  // A closed surface: every edge has faces on both sides, none is a border.
  for (const auto& s : scene.segments)
    EXPECT_EQ(s.kind, X::Two_sided_scene::Edge_kind::plain);
}

TEST(TwoSidedScene, SharpEdgesAreColouredBySharpness)
{
  X::Mobius_mesh<Kd::Point_3> torus;
  X::make_torus(torus, 6, 4);
  auto sharpness = X::edge_sharpness_map(torus);
  sharpness[X::Edge_index(0u)] = 10.0f;
  sharpness[X::Edge_index(1u)] = 5.0f;
  const X::Two_sided_style style;
  const auto halfway = [](unsigned char a, unsigned char b) {
    return static_cast<unsigned char>(std::lround((double(a) + double(b)) / 2));
  };
  const CGAL::IO::Color half(halfway(style.edge.red(), style.sharp.red()),
                             halfway(style.edge.green(), style.sharp.green()),
                             halfway(style.edge.blue(), style.sharp.blue()));
  const auto colour_of = [](const X::Two_sided_scene& scene, X::Edge_index e) {
    const auto it = std::find_if(scene.segments.begin(), scene.segments.end(),
                                 [e](const auto& s) { return s.edge == e; });
    return it->color;
  };
  const X::Two_sided_scene scene = X::make_two_sided_scene(torus);
  EXPECT_EQ(colour_of(scene, X::Edge_index(0u)), style.sharp);
  EXPECT_EQ(colour_of(scene, X::Edge_index(1u)), half);
  EXPECT_EQ(colour_of(scene, X::Edge_index(2u)), style.edge);
  // Without plain edges: the two sharp edges, each on both sheets.
  X::Two_sided_style features_only;
  features_only.plain_edges = false;
  EXPECT_EQ(X::make_two_sided_scene(torus, X::parameters::two_sided_style(features_only)).segments.size(), 4u);
  // A map given as a named parameter replaces the mesh's own.
  auto other = torus.template add_property_map<X::Edge_index, float>("e:other", 0.0f).first;
  other[X::Edge_index(2u)] = 10.0f;
  const X::Two_sided_scene given = X::make_two_sided_scene(torus, X::parameters::edge_sharpness_map(other));
  EXPECT_EQ(colour_of(given, X::Edge_index(0u)), style.edge);
  EXPECT_EQ(colour_of(given, X::Edge_index(2u)), style.sharp);
}

// A colour per face (a scalar field's ramp) paints both sides of each face
// alike, across Möbius edges too; the sheets and edges are those of the
// two-sided scene.
TEST(TwoSidedScene, FaceColourMapPaintsBothSides)
{
  X::Mobius_mesh<Kd::Point_3> strip;
  X::make_mobius_strip(strip, 12, 3);
  auto colour = strip.template add_property_map<X::Face_index, CGAL::IO::Color>("f:colour").first;
  for (X::Face_index f : strip.faces())
    colour[f] = CGAL::IO::Color(static_cast<unsigned char>(f.idx() * 7), 100, static_cast<unsigned char>(255 - f.idx()));
  const X::Two_sided_scene plain = X::make_two_sided_scene(strip);
  const X::Two_sided_scene painted = X::make_two_sided_scene(strip, X::parameters::face_color_map(colour));
  ASSERT_EQ(painted.faces.size(), 2 * strip.number_of_faces());
  std::size_t back = 0;
  for (const auto& face : painted.faces) {
    EXPECT_EQ(face.color, colour[face.face]) << face.face;
    back += face.back ? 1 : 0;
  }
  EXPECT_EQ(back, strip.number_of_faces());
  EXPECT_EQ(painted.corners, plain.corners);
  ASSERT_EQ(painted.segments.size(), plain.segments.size());
  for (std::size_t i = 0; i < plain.segments.size(); ++i)
    EXPECT_EQ(painted.segments[i].color, plain.segments[i].color);
}

// A colour per dart paints each side of a face in the colour of the side
// seen from that dart: the front from halfedge(f), the back from its flip.
TEST(TwoSidedScene, FaceColourMapByDartPaintsEachSide)
{
  X::Mobius_mesh<Kd::Point_3> strip;
  X::make_mobius_strip(strip, 12, 3);
  const auto side_colour = [&strip](X::Dart d) {
    const X::Face_index f = strip.face(d);
    return CGAL::IO::Color(static_cast<unsigned char>(f.idx() * 5), d.is_flipped() ? 200 : 50, 7);
  };
  const auto by_dart = boost::make_function_property_map<X::Dart>(side_colour);
  const X::Two_sided_scene plain = X::make_two_sided_scene(strip);
  const X::Two_sided_scene painted = X::make_two_sided_scene(strip, X::parameters::face_color_map(by_dart));
  ASSERT_EQ(painted.faces.size(), 2 * strip.number_of_faces());
  for (const auto& face : painted.faces) {
    const X::Dart d = strip.halfedge(face.face);
    EXPECT_EQ(face.color, side_colour(face.back ? d.flipped() : d)) << face.face << (face.back ? " back" : " front");
  }
  EXPECT_EQ(painted.corners, plain.corners);
}

TEST(TwoSidedScene, BadInputIsRefused)
{
  X::Mobius_mesh<Kd::Point_3> strip;
  X::make_mobius_strip(strip, 6, 2);
  for (const double gap : {-0.1, std::nan(""), HUGE_VAL}) {
    X::Two_sided_style style;
    style.gap = gap;
    EXPECT_THROW(X::make_two_sided_scene(strip, X::parameters::two_sided_style(style)), X::Parameter_error);
  }
  X::Screenshot_settings tiny;
  tiny.width = 8;
  EXPECT_THROW(X::save_screenshot(strip, "never_written.png", tiny), X::Parameter_error);
#ifndef CGAL_USE_BASIC_VIEWER
  // Built without the viewer: a clear error, not a silent nothing.
  EXPECT_THROW(X::save_screenshot(strip, "never_written.png"), X::IO_error);
#endif
  strip.remove_face(*strip.faces().begin());
  EXPECT_THROW(X::make_two_sided_scene(strip), X::Parameter_error);
}

// The range of the library's algorithms in double, for the scene too: its
// normals and gap come from squared lengths. A strip scaled to 1e50 is drawn
// (its normals are the unit strip's), one scaled to 1e155 is refused naming
// a vertex, and so is one scaled to 1e-70 (its areas underflow). The view
// direction and up vector of a picture must be finite and not zero; their
// length does not matter.
TEST(TwoSidedScene, CoordinatesBeyondTheRangeAreRefused)
{
  using P = Kd::Point_3;
  X::Mobius_mesh<P> strip;
  X::make_mobius_strip(strip, 6, 2);
  const X::Two_sided_scene unit = X::make_two_sided_scene(strip);
  const auto scaled = [&](double factor) {
    X::Mobius_mesh<P> m = strip;
    for (X::Vertex_index v : m.vertices())
      m.point(v) = P(m.point(v).x() * factor, m.point(v).y() * factor, m.point(v).z() * factor);
    return m;
  };
  const X::Two_sided_scene large = X::make_two_sided_scene(scaled(1e50));
  ASSERT_EQ(large.normals.size(), unit.normals.size());
  for (std::size_t i = 0; i < unit.normals.size(); ++i)
    EXPECT_LT(std::sqrt((large.normals[i] - unit.normals[i]).squared_length()), 1e-12);
  for (const double factor : {1e155, 1e-70}) {
    try {
      X::make_two_sided_scene(scaled(factor));
      ADD_FAILURE() << "a strip scaled by " << factor << " was drawn";
    } catch (const X::Parameter_error& e) {
      EXPECT_NE(std::string(e.what()).find("make_two_sided_scene"), std::string::npos) << e.what();
    }
  }
  for (const std::array<double, 3>& bad : {std::array<double, 3>{0, 0, 0}, std::array<double, 3>{HUGE_VAL, 0, 0},
                                           std::array<double, 3>{std::nan(""), 1, 0}}) {
    X::Screenshot_settings settings;
    settings.view_direction = bad;
    EXPECT_THROW(X::save_screenshot(strip, "never_written.png", settings), X::Parameter_error);
    settings = X::Screenshot_settings();
    settings.up_vector = bad;
    EXPECT_THROW(X::save_screenshot(strip, "never_written.png", settings), X::Parameter_error);
  }
}

} // namespace

} // namespace two_sided_scene_tests
