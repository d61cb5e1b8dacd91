// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Sharp features of a mesh, with OpenSubdiv's names and conventions: edge
// and vertex sharpness, the mesh-level options that OpenSubdiv's OBJ tags
// carry, and every other option enum of subdivision (all in namespace
// CGAL_ext; `CGAL_ext::Subdivision` names them too). Read and written by
// the OBJ reader and writer, used by subdivision.

#ifndef CGAL_EXT_SHARP_FEATURES_H
#define CGAL_EXT_SHARP_FEATURES_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <optional>
#include <string>

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

/// The edge sharpness map of `mesh` (created, all 0, if missing).
template <class P>
typename Mobius_mesh<P>::template Property_map<Edge_index, float> edge_sharpness_map(Mobius_mesh<P>& mesh)
{
  return mesh.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first;
}

/// The vertex sharpness map of `mesh` (created, all 0, if missing).
template <class P>
typename Mobius_mesh<P>::template Property_map<Vertex_index, float> vertex_sharpness_map(Mobius_mesh<P>& mesh)
{
  return mesh.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first;
}

namespace internal {

// A sharpness is a number of levels: NaN or negative means nothing, and is
// refused wherever a sharpness is read, with the element it belongs to.
inline bool is_valid_sharpness(double s) { return s >= 0; }

// `element` names the element, as in "edge e" or "vertex v", before its index.
inline Parameter_error invalid_sharpness(const std::string& function, const char* element, std::size_t index,
                                         double value)
{
  return Parameter_error(function + ": the sharpness of " + element + std::to_string(index) + " is " +
                         std::to_string(value) + " (NaN or negative; 0 is smooth)");
}

// Refuses the first edge of `mesh` whose sharpness, `sharpness_of(e)`, is
// NaN or negative.
template <class P, class Sharpness>
void require_valid_edge_sharpness(const Mobius_mesh<P>& mesh, const Sharpness& sharpness_of,
                                  const std::string& function)
{
  for (Edge_index e : mesh.edges())
    if (const double s = sharpness_of(e); !is_valid_sharpness(s))
      throw invalid_sharpness(function, "edge e", e.idx(), s);
}

// The same for the mesh's own "e:sharpness", if it has one.
template <class P>
void require_valid_edge_sharpness(const Mobius_mesh<P>& mesh, const std::string& function)
{
  if (const auto own = mesh.template property_map<Edge_index, float>(edge_sharpness_name))
    require_valid_edge_sharpness(mesh, [&](Edge_index e) { return (*own)[e]; }, function);
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_SHARP_FEATURES_H
