// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The orientation double cover of a Mobius_mesh, as a CGAL::Surface_mesh, for
// tests: every face twice, once per side, glued so that crossing a Möbius
// edge switches copies. Built from the mesh's faces and darts only, with
// CGAL's own Surface_mesh, so that a CGAL algorithm run on it is a reference
// independent of the graph traits of Mobius_mesh.

#ifndef CGAL_EXT_TEST_DOUBLE_COVER_H
#define CGAL_EXT_TEST_DOUBLE_COVER_H

#include <CGAL_ext/Mobius_mesh.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace cgal_ext_test {

template <class P>
struct Double_cover
{
  CGAL::Surface_mesh<P> mesh;
  /// Cover vertex index -> base vertex index (two cover vertices per base vertex).
  std::vector<std::size_t> base_vertex;
  /// Base vertex index -> its two cover vertices, {sheet 0, sheet 1}.
  std::vector<std::pair<typename CGAL::Surface_mesh<P>::Vertex_index, typename CGAL::Surface_mesh<P>::Vertex_index>>
    cover_vertices;
  /// Cover face index -> (base face index, side): side 0 runs along the base
  /// face's orientation, side 1 against it.
  std::vector<std::pair<std::size_t, int>> base_face;
};

/// Vertex v of `base` gets the cover vertices 2v and 2v+1 (sheets 0 and 1);
/// the sheet of face f at v is whether f runs against the orientation that the
/// walk round v carries from halfedge(v). Side s of f takes at v the sheet
/// s ^ sheet(f, v), and side 1 runs backwards. Needs a mesh without removed
/// elements, each vertex at most once on a face.
template <class P>
Double_cover<P> make_double_cover(const CGAL_ext::Mobius_mesh<P>& base)
{
  using SM = CGAL::Surface_mesh<P>;
  Double_cover<P> c;
  const std::size_t nv = base.num_vertices();
  c.base_vertex.resize(2 * nv);
  c.cover_vertices.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const P& p = base.point(CGAL_ext::Vertex_index(v));
    auto a = c.mesh.add_vertex(p);
    auto b = c.mesh.add_vertex(p);
    c.base_vertex[2 * v] = c.base_vertex[2 * v + 1] = v;
    c.cover_vertices[v] = {a, b};
  }
  std::vector<std::vector<std::pair<std::size_t, int>>> sheet(base.num_faces());
  for (CGAL_ext::Vertex_index v : base.vertices())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(v, base))
      if (!base.is_border(d))
        sheet[base.face(d).idx()].push_back({v.idx(), d.is_flipped() ? 1 : 0});
  for (CGAL_ext::Face_index f : base.faces()) {
    std::vector<std::size_t> vs;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, base))
      vs.push_back(v.idx());
    for (int side : {0, 1}) {
      std::vector<typename SM::Vertex_index> face;
      for (std::size_t v : vs) {
        int s = -1;
        for (auto [w, t] : sheet[f.idx()])
          if (w == v)
            s = t;
        if (s < 0)
          throw std::logic_error("make_double_cover: a face is not round its vertex");
        face.push_back(typename SM::Vertex_index(typename SM::size_type(2 * v + (side ^ s))));
      }
      if (side)
        std::reverse(face.begin(), face.end());
      if (c.mesh.add_face(face) == SM::null_face())
        throw std::logic_error("make_double_cover: the cover is not a manifold");
      c.base_face.push_back({f.idx(), side});
    }
  }
  return c;
}

} // namespace cgal_ext_test

#endif // CGAL_EXT_TEST_DOUBLE_COVER_H
