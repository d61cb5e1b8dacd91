// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Conversion between Mobius_mesh and CGAL::Surface_mesh. Orientable meshes
// convert losslessly; non-orientable ones are cut along their Möbius edges,
// and the cut is recorded in a Surface_mesh property map so that converting
// back glues it again.

#ifndef CGAL_EXT_SURFACE_MESH_CONVERSION_H
#define CGAL_EXT_SURFACE_MESH_CONVERSION_H

#include <CGAL_ext/Conversion/Conversion_result.h>
#include <CGAL_ext/Conversion/Seam_map.h>
#include <CGAL_ext/Conversion/internal/Cut_writer.h>
#include <CGAL_ext/Conversion/internal/Seam_gluing.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshConversion
///
/// Appends `mesh` to the `CGAL::Surface_mesh` `sm`, as `CGAL::copy_face_graph()` does.
///
/// The input is never modified. Its faces are oriented on a copy with
/// `orient()` (as few Möbius edges as it finds; none on an orientable
/// component), reversing faces where needed. If Möbius edges remain (the
/// mesh is non-orientable), the surface is cut along them: each Möbius edge
/// becomes two border edges, and each vertex on the cut is duplicated once
/// per wedge of faces between cuts. The result is an oriented 2-manifold.
///
/// Two property maps of `sm` record what was done, so that
/// `from_surface_mesh()` can undo it:
/// - `"h:mobius_seam"` (`Seam_link`, created if any edge is cut): for each
///   border halfedge made by the cut, its partner border halfedge and
///   `twisted == true` (the two run the same way along the seam);
/// - `"f:mobius_reversed"` (`bool`, created if any face was reversed): the
///   faces whose orientation was reversed.
///
/// Vertex `v` of `mesh` becomes the vertex of `sm` created first for it;
/// with an empty `sm` that is vertex `v` again, and the seam copies come
/// after all vertices. Faces keep their order. Points are converted with
/// `CGAL::Cartesian_converter`. Property maps of the same name are copied for
/// `bool`, the arithmetic types, `std::string` and, with one point type, the
/// kernel's `Point_3` and `Vector_3` (`Surface_mesh` makes property maps only
/// of types named at compile time); on a cut vertex every copy gets the
/// value, on a cut edge both edges do.
///
/// Corner channels (texture coordinates, corner normals) become halfedge
/// maps of `sm` of the same name (`"c:uv"`, `"c:normal"`): each face halfedge
/// holds the value of the corner at its target, also where a face was
/// reversed or a vertex cut, for the value types above, 2 to 4 floats or
/// doubles in an `std::array` and, with one point type, the kernel's `Point_2`
/// and `Vector_2`. A channel of another type is not carried and is named in
/// `Conversion_result::corner_channels_not_carried`; a corner without a value
/// gets the type's default (the origin), counted in
/// `Conversion_result::corners_without_value`.
///
/// \param mesh the mesh to convert
/// \param sm the `Surface_mesh` it is appended to
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_to_vertex_output_iterator}
///     \cgalParamDescription{receives `std::pair<Vertex_index, SM_Vertex_index>` for each vertex
///                           copy (several per cut vertex)}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_to_halfedge_output_iterator}
///     \cgalParamDescription{receives `std::pair<Dart, SM_Halfedge_index>`: the dart of `mesh`
///                           that runs the way the `sm` halfedge does (flipped where the face was
///                           reversed); border halfedges made by the cut have no pair}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_to_face_output_iterator}
///     \cgalParamDescription{receives `std::pair<Face_index, SM_Face_index>` per face}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class P, class Q, class NamedParameters = parameters::Default_named_parameters>
Conversion_result to_surface_mesh(const Mobius_mesh<P>& mesh, CGAL::Surface_mesh<Q>& sm,
                                  const NamedParameters& np = parameters::default_values())
{
  CGAL_ext::internal::require_no_garbage(mesh, "to_surface_mesh");
  CGAL_ext::internal::refuse_folded_faces(mesh, "to_surface_mesh");
  // Without Möbius edges the faces are oriented alike already: orient()
  // would reverse none, and the mesh serves as its own oriented copy.
  if (CGAL_ext::number_of_mobius_edges(mesh) == 0)
    return internal::to_surface_mesh(mesh, mesh, 0, sm, np);
  Mobius_mesh<std::uint8_t> oriented; // connectivity only
  internal::copy_connectivity(mesh, oriented);
  const std::size_t mobius_left = CGAL_ext::orient(oriented);
  return internal::to_surface_mesh(mesh, oriented, mobius_left, sm, np);
}

/// \ingroup PkgMobiusMeshConversion
///
/// Appends the `CGAL::Surface_mesh` `sm` to `mesh`, gluing it along its seam
/// map if it has one, and restoring the orientation of the faces marked in
/// `"f:mobius_reversed"`: for a `Surface_mesh` made by `to_surface_mesh()`
/// this gives back the original mesh (same vertex and face indices, points,
/// face cycles, Möbius edges and copied properties; edges may be numbered
/// differently). A `Surface_mesh` without these maps is copied as it is.
///
/// The seam map `"h:mobius_seam"` (see `Seam_link`) may also be written by
/// hand, between copies of one edge: each listed border halfedge is glued to
/// its partner, twisted (a Möbius edge) or not. Gluing identifies the
/// partners' end vertices, which must lie on each other; glued vertices take
/// the point and vertex properties of the copy with the lowest index. Removed elements of `sm` are skipped; indices are then compacted.
/// Halfedge maps whose name starts with `"c:"` become corner channels of
/// that name (each face halfedge gives the value of its face's corner at its
/// target; corners at one vertex with equal values share one value, so that
/// the channel has seams where they differ), for the value types that
/// `to_surface_mesh()` carries.
///
/// \param sm the `Surface_mesh` to convert
/// \param mesh the mesh it is appended to; unchanged if an exception is thrown
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_to_vertex_output_iterator}
///     \cgalParamDescription{receives `std::pair<SM_Vertex_index, Vertex_index>` per vertex of `sm`}
///   \cgalParamNEnd
///   \cgalParamNBegin{halfedge_to_halfedge_output_iterator}
///     \cgalParamDescription{receives `std::pair<SM_Halfedge_index, Dart>`: the dart of `mesh`
///                           that runs the way the `sm` halfedge does; glued seam border
///                           halfedges have no pair}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_to_face_output_iterator}
///     \cgalParamDescription{receives `std::pair<SM_Face_index, Face_index>` per face}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Seam_error if the seam map does not describe `sm`: a link on or to
///   a halfedge that is not a live border halfedge, a link not matched the
///   other way, linked halfedges of different lengths or whose glued ends
///   lie apart, unlinked border halfedges side by side at a glued vertex (a
///   seam split after the cut), or a gluing that is not a 2-manifold. The
///   seam map stays valid through edits that leave the seam's border
///   halfedges and their end points alone (doc/conversion_and_merging.md).
template <class Q, class P, class NamedParameters = parameters::Default_named_parameters>
Conversion_result from_surface_mesh(const CGAL::Surface_mesh<Q>& sm, Mobius_mesh<P>& mesh,
                                    const NamedParameters& np = parameters::default_values())
{
  using SH = typename CGAL::Surface_mesh<Q>::Halfedge_index;
  using SF = typename CGAL::Surface_mesh<Q>::Face_index;
  Conversion_result result;
  internal::Seam_gluing<Q> gluing(sm);
  result.seam_edges = gluing.glue();
  result.added_vertices = gluing.vertex_of.size() - gluing.n_classes;
  Mobius_mesh<P> part;
  gluing.build(part);
  if (result.seam_edges > 0)
    gluing.check_seam_is_whole();
  const auto carried = gluing.carry_properties(
    part, internal::has_output<NamedParameters>(CGAL::internal_np::halfedge_to_halfedge_output_iterator));
  const auto& halfedge_pairs = carried.first;
  const auto& face_pairs = carried.second;
  const std::vector<SF>& face_of = gluing.face_of;

  // Restore the orientations that to_surface_mesh() changed.
  std::vector<bool> reversed(face_of.size(), false);
  const auto [flag, has_flag] = sm.template property_map<SF, bool>(reversed_faces_map_name);
  if (has_flag)
    for (std::size_t f = 0; f < face_of.size(); ++f)
      if (flag[face_of[f]]) {
        part.reverse_face_orientation(Face_index(f));
        reversed[f] = true;
        ++result.reversed_faces;
      }

  // The dart of `part` that runs as each sm halfedge does: the halfedges of a
  // reversed face, and their border partners, are walked against the face.
  std::vector<std::pair<SH, Dart>> dart_pairs;
  if (internal::has_output<NamedParameters>(CGAL::internal_np::halfedge_to_halfedge_output_iterator)) {
    dart_pairs.reserve(halfedge_pairs.size());
    for (const auto& [s, h] : halfedge_pairs) {
      const bool border = sm.is_border(s);
      const Halfedge_index fh = border ? Mobius_mesh<P>::opposite_halfedge(h) : h;
      const Dart d(fh, reversed[part.face(fh).idx()]);
      dart_pairs.emplace_back(s, border ? part.opposite(d) : d);
    }
  }

  const auto off = internal::append_mesh(mesh, std::move(part));
  internal::write_pairs(np, CGAL::internal_np::vertex_to_vertex_output_iterator, [&](auto out) {
    for (std::uint32_t i = 0; i < gluing.vertex_of.size(); ++i)
      out(std::make_pair(gluing.vertex_of[i], Vertex_index(gluing.class_index[i] + off.vertices)));
  });
  internal::write_pairs(np, CGAL::internal_np::halfedge_to_halfedge_output_iterator, [&](auto out) {
    for (const auto& [s, d] : dart_pairs)
      out(std::make_pair(s, Dart::from_bits(internal::dart_encoding::shift_dart(d.bits(), off.edges))));
  });
  internal::write_pairs(np, CGAL::internal_np::face_to_face_output_iterator, [&](auto out) {
    for (const auto& [s, f] : face_pairs)
      out(std::make_pair(s, Face_index(f.idx() + off.faces)));
  });
  return result;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_SURFACE_MESH_CONVERSION_H
