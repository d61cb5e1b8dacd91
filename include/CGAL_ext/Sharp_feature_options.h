// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The option enums of sharp features and subdivision, with OpenSubdiv's
// names: how the border is interpolated, how creases decay, the rule on
// triangles and the vertex rule; the mesh-level options that OpenSubdiv's
// OBJ tags carry; and the names of the sharpness maps. Includes nothing of
// the library, so that the mesh and the subdivision masks can name them
// without the mesh's functions (`<CGAL_ext/Sharp_features.h>` includes it).

#ifndef CGAL_EXT_SHARP_FEATURE_OPTIONS_H
#define CGAL_EXT_SHARP_FEATURE_OPTIONS_H

#include <optional>

namespace CGAL_ext {

/// Sharpness at or above this value is infinite (OpenSubdiv's `SHARPNESS_INFINITE`).
/// Sharpness is a `float`, as in OpenSubdiv: its arithmetic is float
/// arithmetic, which matters when matching OpenSubdiv's results.
constexpr float infinitely_sharp = 10.0f;

/// How the border is interpolated (OpenSubdiv's `VtxBoundaryInterpolation`).
enum class Boundary_interpolation {
  none,           ///< border faces are not part of the limit surface
  edge_only,      ///< border edges are infinitely sharp creases
  edge_and_corner ///< also border vertices with one face are corners
};

/// How semi-sharp creases decay from level to level (OpenSubdiv's `CreasingMethod`):
/// `uniform` takes 1 off each sharpness per level; `chaikin` takes ¾ of it plus
/// ¼ of the mean of the other semi-sharp edges at the end vertex, then 1 off.
enum class Crease_method { uniform, chaikin };

/// Catmull–Clark rule on triangles (OpenSubdiv's `TriangleSubdivision`):
/// `catmark`, the ordinary rule, or `smooth`, OpenSubdiv's smoother edge
/// weights next to triangles.
enum class Triangle_subdivision { catmark, smooth };

/// How corner channels are smoothed where they are not continuous
/// (OpenSubdiv's `FVarLinearInterpolation`): which values along a seam or
/// the border of a channel are kept linear (as sharp corners or creases) and
/// which are smoothed. Away from seams a channel follows the vertex rules.
enum class Face_varying_interpolation {
  none,          ///< smooth everywhere, seams as smooth borders ("edge only")
  corners_only,  ///< corners of the channel (a value on one face) kept
  corners_plus1, ///< also values where three or more regions of the channel meet (OpenSubdiv's default)
  corners_plus2, ///< also darts and concave corners of the channel
  boundaries,    ///< linear along every seam and border of the channel
  all            ///< linear everywhere (as bilinear subdivision)
};

/// The smooth Catmull–Clark vertex rule.
enum class Vertex_rule {
  standard,   ///< (n−2)/n V + 1/n² Σ neighbours + 1/n² Σ face points (DeRose et al., OpenSubdiv)
  edge_points ///< (n−2)/n V + 1/n² Σ new edge points + 1/n² Σ face points
};

/// The mesh-level options of a shape, as OpenSubdiv's OBJ tags give them;
/// unset where a file says nothing.
struct Sharp_feature_options
{
  /// The `t interpolateboundary` tag.
  std::optional<Boundary_interpolation> boundary_interpolation;
  /// The `t creasemethod` tag.
  std::optional<Crease_method> crease_method;
  /// The `t smoothtriangles` tag.
  std::optional<Triangle_subdivision> triangle_subdivision;
};

///@{
/// The names of the property maps that hold sharpness (edge map, vertex map).
inline constexpr const char* edge_sharpness_name = "e:sharpness";
inline constexpr const char* vertex_sharpness_name = "v:sharpness";
///@}

} // namespace CGAL_ext

#endif // CGAL_EXT_SHARP_FEATURE_OPTIONS_H
