// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The style and the result of a two-sided scene: colours per side and the triangles, edges and points to draw.

#ifndef CGAL_EXT_MOBIUS_MESH_TWO_SIDED_STYLE_H
#define CGAL_EXT_MOBIUS_MESH_TWO_SIDED_STYLE_H

#include <CGAL_ext/Mobius_mesh.h>

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

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TWO_SIDED_STYLE_H
