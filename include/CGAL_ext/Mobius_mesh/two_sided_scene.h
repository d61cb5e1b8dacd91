// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What a renderer draws to show the two sides of a surface: the orientation
// double cover of the mesh, each face twice, a hair apart along its normals,
// one colour per side, and the edges that matter (borders, Möbius edges,
// sharp edges) in their own colours. Free of any GUI library, so that a
// program with its own renderer, and the tests, can use it; the Qt viewer of
// draw_mobius_mesh.h draws it.

#ifndef CGAL_EXT_MOBIUS_MESH_TWO_SIDED_SCENE_H
#define CGAL_EXT_MOBIUS_MESH_TWO_SIDED_SCENE_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshDrawing
/// How `make_two_sided_scene()` and `draw()` show a mesh.
struct Two_sided_style
{
  /// The side each face's orientation points to (its unflipped darts' side).
  CGAL::IO::Color front{60, 110, 220};
  /// The other side.
  CGAL::IO::Color back{235, 150, 30};
  /// Edges that are none of the below.
  CGAL::IO::Color edge{30, 30, 30};
  /// Border edges.
  CGAL::IO::Color border{220, 20, 20};
  /// Möbius edges (the two faces' orientations disagree): where the colours swap.
  CGAL::IO::Color mobius{20, 170, 50};
  /// Edges of infinite sharpness (10, OpenSubdiv's `SHARPNESS_INFINITE`, or
  /// more); a semi-sharp edge blends `edge` and `sharp` by its sharpness / 10.
  CGAL::IO::Color sharp{150, 0, 190};
  /// The gap between the two sides, as a fraction of the bounding box's
  /// diagonal: each side lies `gap / 2` away from the surface.
  double gap = 2e-3;
  /// Whether edges that are neither border, Möbius nor sharp are drawn:
  /// `false` leaves a fine mesh's faces clear and still shows its features.
  bool plain_edges = true;
};

/// \ingroup PkgMobiusMeshDrawing
/// The orientation double cover of a mesh, ready to draw: `double` points,
/// whatever the mesh's kernel.
struct Two_sided_scene
{
  /// The point type of the scene.
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  /// The vector type of the scene.
  using Vector = CGAL::Simple_cartesian<double>::Vector_3;

  /// One side of one face of the mesh.
  struct Face
  {
    std::size_t first_corner; ///< index of its first corner in `corners` and `normals`
    std::size_t size;         ///< its number of corners
    bool back;                ///< on the back side of its mesh face
    Face_index face;          ///< the mesh face it shows
    CGAL::IO::Color color;    ///< its colour
  };
  /// What kind of edge a segment shows, by priority: a border edge that is
  /// also sharp is a border edge.
  enum class Edge_kind { plain, border, mobius, sharp };
  /// One side of one edge of the mesh.
  struct Segment
  {
    Point source;           ///< its first end, on the side's sheet
    Point target;           ///< its other end
    Edge_index edge;        ///< the mesh edge it shows
    Edge_kind kind;         ///< why it has its colour
    CGAL::IO::Color color;  ///< its colour
  };

  std::vector<Point> corners;     ///< the corners of all faces, face after face
  std::vector<Vector> normals;    ///< the unit normal at each corner, seen from its side
  std::vector<Face> faces;        ///< two per mesh face: the front, then the back
  std::vector<Segment> segments;  ///< two per mesh edge with a face: one on each sheet
  CGAL::Bbox_3 bbox;              ///< of the mesh's points
};

namespace internal {

// A mesh's points in double, and the unit vertex normals seen from darts,
// each computed once: faces and edges ask for the same darts' normals.
template <class P, class NP>
class Two_sided_geometry
{
  using Types = Normal_types<P, NP>;
  using Double_kernel = CGAL::Simple_cartesian<double>;
  using To_double = CGAL::Cartesian_converter<typename Types::Traits, Double_kernel>;

public:
  Two_sided_geometry(const Mobius_mesh<P>& mesh, const NP& np)
    : mesh_(mesh),
      points_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                 mesh.points())),
      normals_(2 * std::size_t(mesh.num_halfedges())), known_(normals_.size(), 0)
  {}

  Two_sided_scene::Point point(Vertex_index v) const { return To_double()(get(points_, v)); }

  // The unit normal at target(d) from the side of d; the face's own normal
  // where the fan's sum is zero, and zero where that is too.
  Two_sided_scene::Vector normal(Dart d) const
  {
    if (!known_[d.bits()]) {
      normals_[d.bits()] = compute_normal(d);
      known_[d.bits()] = 1;
    }
    return normals_[d.bits()];
  }

private:
  using Point_map = typename Types::Point_map;

  Two_sided_scene::Vector compute_normal(Dart d) const
  {
    const CGAL::Cartesian_converter_property_map<Double_kernel::Point_3, Point_map> double_points(points_);
    const auto np = parameters::vertex_point_map(double_points).geom_traits(Double_kernel());
    Two_sided_scene::Vector n = vertex_normal(d, mesh_, np);
    if (n.squared_length() == 0 && !mesh_.is_border(d))
      n = face_normal(d, mesh_, np);
    const double length = std::sqrt(n.squared_length());
    return length > 0 ? n / length : n;
  }

  const Mobius_mesh<P>& mesh_;
  Point_map points_;
  mutable std::vector<Two_sided_scene::Vector> normals_; // by dart bits
  mutable std::vector<char> known_;
};

inline CGAL::IO::Color blend(const CGAL::IO::Color& a, const CGAL::IO::Color& b, double t)
{
  const auto mix = [t](unsigned char x, unsigned char y) {
    return static_cast<unsigned char>(std::lround((1 - t) * x + t * y));
  };
  return CGAL::IO::Color(mix(a.red(), b.red()), mix(a.green(), b.green()), mix(a.blue(), b.blue()));
}

template <class P, class Geometry>
void add_two_sided_faces(const Mobius_mesh<P>& mesh, const Geometry& geometry, const Two_sided_style& style,
                         double half_gap, Two_sided_scene& scene)
{
  std::vector<Dart> darts;
  std::vector<Two_sided_scene::Point> points;
  std::vector<Two_sided_scene::Vector> normals;
  for (Face_index f : mesh.faces()) {
    darts.assign(halfedges_around_face(f, mesh).begin(), halfedges_around_face(f, mesh).end());
    points.clear();
    normals.clear();
    for (Dart d : darts) {
      points.push_back(geometry.point(mesh.target(d)));
      normals.push_back(geometry.normal(d));
    }
    for (const bool back : {false, true}) {
      scene.faces.push_back({scene.corners.size(), darts.size(), back, f, back ? style.back : style.front});
      // The back side runs the other way round, so that its corners' order
      // agrees with its normals for a renderer that culls.
      for (std::size_t i = 0; i < darts.size(); ++i) {
        const std::size_t k = back ? darts.size() - 1 - i : i;
        const auto n = back ? -normals[k] : normals[k];
        scene.corners.push_back(points[k] + half_gap * n);
        scene.normals.push_back(n);
      }
    }
  }
}

template <class P, class NP>
std::vector<float> edge_sharpness_values(const Mobius_mesh<P>& mesh, const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  std::vector<float> values(mesh.num_edges(), 0.0f);
  if constexpr (!pm::is_default_parameter<NP, CGAL_ext::internal_np::edge_sharpness_t>::value) {
    const auto given = pm::get_parameter(np, CGAL_ext::internal_np::edge_sharpness);
    for (Edge_index e : mesh.edges())
      values[e.idx()] = float(get(given, e));
  } else if (const auto own = mesh.template property_map<Edge_index, float>(edge_sharpness_name)) {
    for (Edge_index e : mesh.edges())
      values[e.idx()] = (*own)[e];
  }
  return values;
}

template <class P>
Two_sided_scene::Edge_kind edge_kind(Edge_index e, const Mobius_mesh<P>& mesh, float sharpness)
{
  if (mesh.is_border(e))
    return Two_sided_scene::Edge_kind::border;
  if (mesh.is_mobius(e))
    return Two_sided_scene::Edge_kind::mobius;
  if (sharpness > 0)
    return Two_sided_scene::Edge_kind::sharp;
  return Two_sided_scene::Edge_kind::plain;
}

inline CGAL::IO::Color edge_color(Two_sided_scene::Edge_kind kind, float sharpness, const Two_sided_style& style)
{
  using Kind = Two_sided_scene::Edge_kind;
  switch (kind) {
  case Kind::border: return style.border;
  case Kind::mobius: return style.mobius;
  case Kind::sharp: return blend(style.edge, style.sharp, std::min(double(sharpness), 10.0) / 10.0);
  default: return style.edge;
  }
}

template <class P, class Geometry>
void add_two_sided_segments(const Mobius_mesh<P>& mesh, const Geometry& geometry,
                            const std::vector<float>& sharpness, const Two_sided_style& style, double half_gap,
                            Two_sided_scene& scene)
{
  for (Edge_index e : mesh.edges()) {
    Dart d = mesh.halfedge(e);
    if (mesh.is_border(d))
      d = mesh.opposite(d);
    if (mesh.is_border(d))
      continue; // an edge with no face has no side to be drawn on
    const auto kind = edge_kind(e, mesh, sharpness[e.idx()]);
    if (kind == Two_sided_scene::Edge_kind::plain && !style.plain_edges)
      continue;
    const CGAL::IO::Color color = edge_color(kind, sharpness[e.idx()], style);
    // Seen from the side of d, the edge runs from source(d) (the normal of
    // prev(d)) to target(d); on the back sheet along the negated normals.
    const auto s = geometry.point(mesh.source(d)), t = geometry.point(mesh.target(d));
    const auto ns = geometry.normal(mesh.prev(d)), nt = geometry.normal(d);
    scene.segments.push_back({s + half_gap * ns, t + half_gap * nt, e, kind, color});
    scene.segments.push_back({s - half_gap * ns, t - half_gap * nt, e, kind, color});
  }
}

} // namespace internal

/// \ingroup PkgMobiusMeshDrawing
/// \brief builds the orientation double cover of `mesh` for drawing.
///
/// A one-sided surface has no normal field, so no renderer can shade "the
/// front" of it; it can shade the front of each face. Each face is drawn
/// twice, `style.gap / 2` of the bounding box's diagonal to either side of
/// the surface along the unit vertex normals seen from its darts
/// (`vertex_normal(Dart, ...)`): the side its orientation points to in
/// `style.front`, the other in `style.back`. Faces that agree in orientation
/// share their sheets, so an orientable patch shows one colour per side, and
/// the colours swap across each Möbius edge: on a one-sided surface both
/// colours meet on one side. Each edge with a face is drawn on both sheets,
/// coloured by kind (border, Möbius, sharp by its sharpness, or plain; plain
/// edges only if `style.plain_edges`).
///
/// \param mesh a mesh without garbage
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{two_sided_style}
///     \cgalParamDescription{a `Two_sided_style`: colours and gap}
///     \cgalParamDefault{`Two_sided_style()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_sharpness_map}
///     \cgalParamDescription{a readable property map from `Edge_index` to sharpness}
///     \cgalParamDefault{the mesh's `e:sharpness` map where it has one, else no sharp edges}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDefault{`mesh.points()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDefault{the kernel of the point type, through `CGAL::Kernel_traits`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Parameter_error if the mesh has garbage or the gap is negative or not finite.
template <class P, class NP = parameters::Default_named_parameters>
Two_sided_scene make_two_sided_scene(const Mobius_mesh<P>& mesh, const NP& np = parameters::default_values())
{
  namespace pm = CGAL_ext::parameters;
  internal::require_no_garbage(mesh, "make_two_sided_scene");
  const Two_sided_style style =
    pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::two_sided_style), Two_sided_style());
  if (!(style.gap >= 0) || !std::isfinite(style.gap))
    throw Parameter_error("make_two_sided_scene: the gap " + std::to_string(style.gap) +
                          " is not a finite number >= 0");
  const internal::Two_sided_geometry<P, NP> geometry(mesh, np);
  Two_sided_scene scene;
  for (Vertex_index v : mesh.vertices())
    scene.bbox += geometry.point(v).bbox();
  const double diagonal = std::sqrt(CGAL::square(scene.bbox.x_span()) + CGAL::square(scene.bbox.y_span()) +
                                    CGAL::square(scene.bbox.z_span()));
  const double half_gap = mesh.number_of_vertices() ? style.gap * diagonal / 2 : 0;
  internal::add_two_sided_faces(mesh, geometry, style, half_gap, scene);
  internal::add_two_sided_segments(mesh, geometry, internal::edge_sharpness_values(mesh, np), style, half_gap,
                                   scene);
  return scene;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TWO_SIDED_SCENE_H
