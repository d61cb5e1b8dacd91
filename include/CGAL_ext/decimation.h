// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Garland–Heckbert decimation of a Mobius_mesh: edge collapses ordered by
// quadric error, on any surface, one-sided ones included.

#ifndef CGAL_EXT_DECIMATION_H
#define CGAL_EXT_DECIMATION_H

#include <CGAL_ext/Decimation/Decimation_result.h>
#include <CGAL_ext/Decimation/internal/Decimation_settings.h>
#include <CGAL_ext/Decimation/internal/Decimator.h>
#include <CGAL_ext/Decimation/internal/Distance_relocation.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/internal/Linear_values.h>
#include <CGAL_ext/Mobius_mesh/triangulate_faces.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Modifiable_priority_queue.h>
#include <CGAL/assertions.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshDecimation
/// \brief Simplifies `mesh` by edge collapses, cheapest first by
/// Garland–Heckbert quadric error, until a stop condition holds.
///
/// Works on any `Mobius_mesh`, one-sided surfaces included: quadrics are
/// orientation-free, and the fold-over check compares each face with itself,
/// seen from one dart, so it means the same across Möbius edges. Faces with
/// more than three sides are triangulated first (`triangulate_faces()`); the
/// result has triangles only. Every collapse keeps the Euler characteristic,
/// the number of border loops and orientability.
///
/// After the collapses, vertices are moved to lower the largest distance
/// between the result and the input (`relocate_vertices`): the quadrics
/// measure the distance at the vertices, and the largest one lies inside the
/// triangles, where the surface bends little along a long edge. Each vertex
/// whose star holds the largest distances (from its vertex, edge midpoints
/// and face centroids to their closest points on the input, found in an AABB
/// tree of a copy of the input) moves along their main direction by the step
/// that minimises the largest of them; a move is kept only if the largest
/// distance of its star went down and no face turned over. Border vertices
/// and the ends of feature edges do not move.
///
/// Corner channels (texture coordinates, corner normals) are carried: the
/// seams of each channel are feature edges (never collapsed, their ends never
/// moved), so seams stay where they were, with their values. A collapse off
/// the seams that meets one gives the faces it moves the seam side's values.
/// Off the seams the values weigh in the collapses, by attribute quadrics
/// (Garland and Heckbert 1998, in Hoppe's form of 1999): each input
/// triangle gives its values as an affine field over its plane, a vertex
/// sums the squared distances of a value to the fields of the triangles
/// merged into it, and that sum, at the best value, is added to the cost of
/// a collapse and to the quadric its point minimises; the merged vertex
/// takes that best value, the area-weighted mean of the fields at its point
/// (kept within the bounding box of the channel's values). Where a collapse
/// keeps a value instead (an end is on a seam, the point is an end's own, or
/// both ends hold the value), the cost is taken at that value.
/// A channel is weighed so that a value off by a share of its range costs as
/// a point off by that share of the bounding box's diagonal, and
/// `maximum_error` bounds this sum. The relocation moves vertices without
/// changing their values; where one end's corners have no value, the merged
/// corners take the other's. An edge between two vertices on seams is not
/// collapsed. The values are renumbered at the end: those no corner names
/// (the input's unused ones too) are dropped.
///
/// \param mesh a mesh without removed elements; it is garbage-collected at the end and its
///   unused capacity released
/// \param np named parameters, at least one stop condition:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_faces}
///     \cgalParamDescription{stop when the mesh has at most this many faces}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_ratio}
///     \cgalParamDescription{in [0, 1]: stop at most at this fraction of the (triangulated) faces}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_error}
///     \cgalParamDescription{stop when the cheapest collapse's error is larger: its quadric's value at the
///                           placement divided by the area of the faces whose planes it sums (an area-weighted
///                           mean squared distance, in squared length units; with corner channels, their
///                           values' error, weighed as above, is part of it)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_normal_deviation}
///     \cgalParamDescription{in degrees, (0, 180]: no face's normal may turn by more in one collapse}
///     \cgalParamDefault{90, as OpenMesh's normal-flipping module}
///   \cgalParamNEnd
///   \cgalParamNBegin{protect_borders}
///     \cgalParamDescription{`true` to keep border edges as they are; otherwise they may collapse along the
///                           border, held by their quadrics}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{relocate_vertices}
///     \cgalParamDescription{`false` to leave the vertices where the collapses put them, without the
///                           copy of the input and its AABB tree that the relocation needs}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{corner_value_weight}
///     \cgalParamDescription{finite, >= 0: how much the corner channels' values weigh against the points
///                           in the cost and the point of a collapse, relative to their ranges (above); 0:
///                           the points alone decide, and a merged corner takes the value interpolated
///                           along the collapsed edge at the projection of its point}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_sharpness_map}
///     \cgalParamDescription{edges of sharpness > 0 are features: never collapsed, their ends never moved}
///     \cgalParamDefault{the mesh's `"e:sharpness"` map if it has one}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{a readable map from `Edge_index` to `bool`: `true` edges are features too}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Parameter_error if a parameter is out of range, no stop condition
///   is given, the mesh has a corner channel whose values have no linear
///   combination or a corner whose value index is past its values, an edge's sharpness is NaN or negative, `mesh` has removed
///   elements, a point has a coordinate
///   beyond +-1e60 (where quadrics in double overflow), or the mesh is less
///   than 1e-60 across (where its areas underflow).
/// \throws Euler_error if a polygon cannot be triangulated (triangulate_faces()).
/// All are thrown before `mesh` is touched.
template <class P, class NP = parameters::Default_named_parameters>
Decimation_result decimate(Mobius_mesh<P>& mesh, const NP& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh, "decimate");
  CGAL_ext::internal::refuse_non_manifold_joins(mesh, "decimate");
  CGAL_ext::internal::require_interpolated_channels<typename CGAL::Kernel_traits<P>::Kernel::FT>(mesh, "decimate");
  CGAL_ext::internal::require_valid_corner_indices(mesh, "decimate");
  std::size_t triangles = 0;
  for (Face_index f : mesh.faces())
    triangles += mesh.degree(f) - 2;
  const internal::Decimation_settings settings = internal::decimation_settings(triangles, np);
  internal::require_coordinates_in_range(mesh, "decimate");
  internal::require_valid_sharpness(mesh, np);
  triangulate_faces(mesh);
  // The input, for the distances of the relocation: a copy of its points
  // and triangles now, its tree once the decimator and the removed elements
  // are gone, so that the tree is never held beside them.
  std::optional<internal::Input_triangles> input;
  if (settings.relocate_vertices)
    input.emplace(mesh);
  Decimation_result result;
  const std::vector<std::size_t> values_before = internal::corner_value_counts(mesh);
  std::vector<char> on_feature; // by vertex index, for the relocation only
  {
    internal::Decimator<P> decimator(mesh, settings, internal::feature_edges(mesh, np, settings.protect_borders));
    result = decimator.run();
    if (input) {
      // Feature edges keep their ends where they are, as during the collapses.
      const std::vector<char> feature = decimator.take_features();
      on_feature.assign(mesh.num_vertices(), 0);
      for (Edge_index e : mesh.edges())
        if (feature[e.idx()])
          on_feature[mesh.vertex(e, 0).idx()] = on_feature[mesh.vertex(e, 1).idx()] = 1;
    }
  }
  typename Mobius_mesh<P>::Garbage_collection_maps moved;
  mesh.collect_garbage(moved);
  result.corner_values_interpolated = internal::added_values_in_use(mesh, values_before);
  CGAL_ext::internal::remove_unused_corner_values(mesh);
  mesh.shrink_to_fit();
  if (input && result.collapses > 0) {
    // Each vertex's input vertex of the same old index: a point of the input near it.
    std::vector<std::uint32_t> origin(mesh.num_vertices());
    std::vector<char> movable(mesh.num_vertices());
    for (std::size_t old = 0; old < moved.vertices.size(); ++old)
      if (const Vertex_index v = moved.vertices[old]; v.is_valid()) {
        origin[v.idx()] = std::uint32_t(old);
        movable[v.idx()] = !on_feature[old];
      }
    std::vector<char>().swap(on_feature);
    moved = {};
    input->build_tree();
    internal::Distance_relocation<P> relocation(mesh, *input, std::move(origin), std::move(movable));
    result.relocations = relocation.run(3);
  }
  return result;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_H
