// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The orientation double cover of a Mobius_mesh as a CGAL::Surface_mesh: the
// orientable surface on which CGAL's algorithms that cannot walk a mesh with
// Möbius edges run for it.

#ifndef CGAL_EXT_GEODESICS_INTERNAL_ORIENTATION_DOUBLE_COVER_H
#define CGAL_EXT_GEODESICS_INTERNAL_ORIENTATION_DOUBLE_COVER_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

/// The orientation double cover of a mesh: each face twice, once per side,
/// glued so that crossing a Möbius edge switches sides. Vertex `v` of the
/// mesh has the two cover vertices `sheet[v][0]` and `sheet[v][1]` at its
/// point; on an orientable component they lie on two separate copies.
template <class P>
struct Orientation_double_cover
{
  using Cover = CGAL::Surface_mesh<P>;
  Cover mesh;
  std::vector<std::array<typename Cover::Vertex_index, 2>> sheet;
};

/// Builds the double cover of `m`. The side of a face at a corner is whether
/// the face runs against the orientation that the walk round the corner's
/// vertex carries (one orientation round a manifold fan, across Möbius edges
/// too); side `s` of a face takes, at each corner, the sheet `s` xor that.
/// \throws Parameter_error if the mesh has a vertex twice on one face.
template <class P>
Orientation_double_cover<P> make_orientation_double_cover(const Mobius_mesh<P>& m, const char* what)
{
  using Cover = CGAL::Surface_mesh<P>;
  using CV = typename Cover::Vertex_index;
  Orientation_double_cover<P> c;
  c.sheet.resize(m.num_vertices());
  c.mesh.reserve(typename Cover::size_type(2 * m.number_of_vertices()),
                 typename Cover::size_type(2 * m.number_of_edges()),
                 typename Cover::size_type(2 * m.number_of_faces()));
  for (Vertex_index v : m.vertices())
    for (int s : {0, 1})
      c.sheet[v.idx()][s] = c.mesh.add_vertex(m.point(v));

  // side_at[f][i]: the side of face f at its i-th corner (the target of the
  // i-th dart from halfedge(f)).
  std::vector<std::vector<std::uint8_t>> side_at(m.num_faces());
  std::vector<std::vector<Vertex_index>> corners(m.num_faces());
  for (Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      corners[f.idx()].push_back(m.target(d));
  for (Face_index f : m.faces())
    side_at[f.idx()].assign(corners[f.idx()].size(), 2);
  for (Vertex_index v : m.vertices()) {
    if (!m.halfedge(v).is_valid())
      continue;
    for (Dart d : CGAL_ext::halfedges_around_target(m.halfedge(v), m)) {
      if (m.is_border(d))
        continue;
      const Face_index f = m.face(d);
      const std::vector<Vertex_index>& cs = corners[f.idx()];
      std::size_t n = 0;
      for (std::size_t i = 0; i < cs.size(); ++i)
        if (cs[i] == v) {
          side_at[f.idx()][i] = d.is_flipped() ? 1 : 0;
          ++n;
        }
      if (n != 1)
        throw Parameter_error(std::string(what) + ": face " + std::to_string(f.idx()) +
                              " passes a vertex twice; the double cover needs faces without repeated vertices");
    }
  }
  std::vector<CV> face;
  for (Face_index f : m.faces()) {
    const std::vector<Vertex_index>& cs = corners[f.idx()];
    for (int s : {0, 1}) {
      face.clear();
      for (std::size_t i = 0; i < cs.size(); ++i)
        face.push_back(c.sheet[cs[i].idx()][s ^ side_at[f.idx()][i]]);
      if (s == 1)
        std::reverse(face.begin(), face.end());
      if (c.mesh.add_face(face) == Cover::null_face())
        throw Parameter_error(std::string(what) + ": the mesh is not a 2-manifold around face " +
                              std::to_string(f.idx()));
    }
  }
  return c;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_INTERNAL_ORIENTATION_DOUBLE_COVER_H
