// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/Mobius_mesh/two_sided_scene.h>: the geometry of the two sides: offset copies of the faces, colours per side, feature edges.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_TWO_SIDED_GEOMETRY_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_TWO_SIDED_GEOMETRY_H

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
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>
#include <CGAL_ext/Mobius_mesh/Two_sided_style.h>

namespace CGAL_ext {
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

// A face's colours: its front side's, then its back side's.
using Side_colors = std::array<CGAL::IO::Color, 2>;

inline CGAL::IO::Color blend(const CGAL::IO::Color& a, const CGAL::IO::Color& b, double t)
{
  const auto mix = [t](unsigned char x, unsigned char y) {
    return static_cast<unsigned char>(std::lround((1 - t) * x + t * y));
  };
  return CGAL::IO::Color(mix(a.red(), b.red()), mix(a.green(), b.green()), mix(a.blue(), b.blue()));
}

template <class P, class Geometry>
void add_two_sided_faces(const Mobius_mesh<P>& mesh, const Geometry& geometry, const Two_sided_style& style,
                         double half_gap, const std::vector<Side_colors>& face_colors, Two_sided_scene& scene)
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
      const CGAL::IO::Color color = face_colors.empty() ? back ? style.back : style.front : face_colors[f.idx()][back];
      scene.faces.push_back({scene.corners.size(), darts.size(), back, f, color});
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

// The colours of each face's two sides (front, back) from the
// `face_color_map` parameter, by face index; none without it. A map keyed by
// `Face_index` gives both sides the face's colour; one keyed by `Dart` gives
// each side the colour of the side of `face(d)` seen from `d`: the front is
// asked for with `halfedge(f)`, the back with its flip.
template <class P, class NP>
std::vector<Side_colors> face_color_values(const Mobius_mesh<P>& mesh, const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  std::vector<Side_colors> values;
  if constexpr (!pm::is_default_parameter<NP, CGAL::internal_np::face_color_map_t>::value) {
    const auto given = pm::get_parameter(np, CGAL::internal_np::face_color_map);
    using Key = typename boost::property_traits<std::decay_t<decltype(given)>>::key_type;
    static_assert(std::is_same_v<Key, Face_index> || std::is_same_v<Key, Dart>,
                  "face_color_map: a property map keyed by Face_index (both sides) or by Dart (each side)");
    values.resize(mesh.num_faces());
    for (Face_index f : mesh.faces()) {
      if constexpr (std::is_same_v<Key, Dart>)
        values[f.idx()] = {get(given, mesh.halfedge(f)), get(given, mesh.halfedge(f).flipped())};
      else
        values[f.idx()] = {get(given, f), get(given, f)};
    }
  }
  return values;
}

template <class P, class NP>
std::vector<float> edge_sharpness_values(const Mobius_mesh<P>& mesh, const NP& np)
{
  std::vector<float> values(mesh.num_edges(), 0.0f);
  const auto sharpness = edge_sharpness_of(mesh, np);
  for (Edge_index e : mesh.edges())
    values[e.idx()] = sharpness(e);
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
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_TWO_SIDED_GEOMETRY_H
