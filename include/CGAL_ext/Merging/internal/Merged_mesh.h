// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The merged mesh, made two ways: rebuilt through a soup with the glued
// vertices identified (bridging, which adds faces), or glued in place with
// Border_glue; and the second mesh appended for a merge, taken out again
// unless the merge succeeds.

#ifndef CGAL_EXT_MERGING_INTERNAL_MERGED_MESH_H
#define CGAL_EXT_MERGING_INTERNAL_MERGED_MESH_H

#include <CGAL_ext/Merging/Merge_types.h>
#include <CGAL_ext/Merging/internal/Border_glue.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Bridging only (the in-place glue adds no faces): rebuilds `work` with the
// vertices of each class of `cls` identified (and `extra` polygons added, by
// class), through a soup: linear time, and the
// soup import finds every normal and Möbius connection and refuses what is
// not a 2-manifold. `position[c]` is the point of class c. Properties are
// carried over: faces one to one, a vertex from the lowest member of its
// class, an edge from the first of the edges glued into it.
template <class P>
Mobius_mesh<P> rebuild_glued(const Mobius_mesh<P>& work, const std::vector<std::uint32_t>& cls,
                             const std::vector<P>& position, const std::vector<std::vector<std::uint32_t>>& extra,
                             Merge_result& result)
{
  // The faces in one flat array of corners: a vector per face would cost
  // one allocation per face, a third of the whole merge.
  const std::size_t nf = work.number_of_faces();
  Face_list faces;
  faces.vertex.reserve(work.number_of_halfedges());
  faces.offset.reserve(nf + extra.size() + 1);
  for (Face_index f : work.faces()) {
    for (Dart d : CGAL_ext::halfedges_around_face(work.halfedge(f), work))
      faces.vertex.push_back(cls[work.source(d).idx()]);
    faces.offset.push_back(std::uint32_t(faces.vertex.size()));
  }
  for (const std::vector<std::uint32_t>& polygon : extra)
    faces.add(polygon.begin(), polygon.end());

  Mobius_mesh<P> out;
  try {
    build_mesh_from_faces(faces.view(std::uint32_t(position.size())), [&position](std::uint32_t v) { return position[v]; }, false, out);
  } catch (const Soup_error& e) {
    std::vector<std::size_t> vs;
    for (std::size_t c : e.vertices())
      for (std::size_t v = 0; v < cls.size(); ++v)
        if (cls[v] == c)
          vs.push_back(v);
    using K = Merge_error::Kind;
    switch (e.kind()) {
    case Soup_error::Kind::repeated_vertex:
      throw Merge_error(K::collapsed_face,
                        "the merge would identify two vertices of one face (" + join_ids(vs, "v") +
                          "): is the tolerance larger than the mesh's edges?",
                        vs);
    case Soup_error::Kind::non_manifold_edge:
      throw Merge_error(K::non_manifold_edge,
                        "the merge would give the edge between " + join_ids(vs, "v") + " three or more faces", vs);
    default:
      throw Merge_error(K::non_manifold_vertex,
                        "the merge would make a non-manifold vertex of " + join_ids(vs, "v") +
                          " (its faces would form separate fans)",
                        vs);
    }
  }

  // Correspondences, read off the face cycles in step.
  std::vector<Vertex_index> vertex_src(out.number_of_vertices());
  for (std::size_t v = cls.size(); v-- > 0;)
    vertex_src[cls[v]] = Vertex_index(v);
  // Halfedges and edges are walked only if they have property maps to carry.
  const bool walk = !work.template properties<Halfedge_index>().empty() ||
                    !work.template properties<Edge_index>().empty();
  std::vector<Halfedge_index> halfedge_src(walk ? out.number_of_halfedges() : 0);
  std::vector<Edge_index> edge_src(walk ? out.number_of_edges() : 0);
  if (walk) {
    for (Face_index f : work.faces()) {
      Dart d = out.halfedge(f);
      for (Dart w : CGAL_ext::halfedges_around_face(work.halfedge(f), work)) {
        halfedge_src[d.halfedge().idx()] = w.halfedge();
        const Halfedge_index wo = Mobius_mesh<P>::opposite_halfedge(w.halfedge());
        const Halfedge_index o = Mobius_mesh<P>::opposite_halfedge(d.halfedge());
        if (work.is_border(wo) && out.is_border(o))
          halfedge_src[o.idx()] = wo;
        if (!edge_src[out.edge(d).idx()].is_valid())
          edge_src[out.edge(d).idx()] = work.edge(w);
        d = out.next(d);
      }
    }
  }
  std::vector<Face_index> face_src(out.number_of_faces());
  for (std::size_t f = 0; f < nf; ++f)
    face_src[f] = Face_index(f);
  transfer_properties<Vertex_index>(work, out, 0, out.number_of_vertices(),
                                    [&](Vertex_index v) { return vertex_src[v.idx()]; });
  transfer_properties<Halfedge_index>(work, out, 0, out.number_of_halfedges(),
                                      [&](Halfedge_index h) { return halfedge_src[h.idx()]; });
  transfer_properties<Edge_index>(work, out, 0, out.number_of_edges(),
                                  [&](Edge_index e) { return edge_src[e.idx()]; });
  transfer_properties<Face_index>(work, out, 0, out.number_of_faces(),
                                  [&](Face_index f) { return face_src[f.idx()]; });

  result.vertex_map.resize(cls.size());
  for (std::size_t v = 0; v < cls.size(); ++v)
    result.vertex_map[v] = Vertex_index(cls[v]);
  result.merged_vertices = cls.size() - out.number_of_vertices();
  result.new_faces = extra.size();
  return out;
}

inline std::vector<Vertex_index> identity_vertex_map(std::size_t nv)
{
  std::vector<Vertex_index> map(nv);
  for (std::size_t v = 0; v < nv; ++v)
    map[v] = Vertex_index(v);
  return map;
}

// Glues `pairs` of border darts of `mesh` in place (see Border_glue);
// throws Merge_error, `mesh` unchanged, if the result is not a 2-manifold.
template <class P>
void glue_in_place(Mobius_mesh<P>& mesh, std::vector<Glue_pair> pairs, Merge_result& result)
{
  if (pairs.empty()) {
    result.vertex_map = identity_vertex_map(mesh.number_of_vertices());
    return;
  }
  const std::size_t given = pairs.size();
  Border_glue<P> glue(mesh, std::move(pairs));
  glue.check();
  // Border edges that end up between the same two vertices are glued too:
  // they count as the given pairs do (a Möbius edge where the faces agree).
  for (std::size_t i = given; i < glue.pairs().size(); ++i) {
    const Glue_pair& p = glue.pairs()[i];
    result.halfedge_pairs.emplace_back(p.first.halfedge().idx(), p.second.halfedge().idx());
    ++result.glued_edges;
    result.mobius_edges += p.second.is_flipped() ? 0 : 1;
  }
  result.merged_vertices = glue.apply(result.vertex_map);
}

// Appends `b` to `a` for a merge, and takes it out again (`a` as it was)
// unless `keep()` is called: a failed merge leaves its first mesh unchanged.
template <class P>
class Joined
{
public:
  Joined(Mobius_mesh<P>& a, const Mobius_mesh<P>& b)
    : a_(a), nv_(a.num_vertices()), ne_(a.num_edges()), nf_(a.num_faces())
  {
    record<Vertex_index>(0);
    record<Halfedge_index>(1);
    record<Edge_index>(2);
    record<Face_index>(3);
    offsets_ = a.join(b);
  }
  Joined(const Joined&) = delete;
  Joined& operator=(const Joined&) = delete;
  ~Joined()
  {
    if (kept_)
      return;
    a_.resize(nv_, ne_, nf_);
    drop_added<Vertex_index>(0);
    drop_added<Halfedge_index>(1);
    drop_added<Edge_index>(2);
    drop_added<Face_index>(3);
  }
  void keep() { kept_ = true; }
  const typename Mobius_mesh<P>::Join_offsets& offsets() const { return offsets_; }

private:
  template <class I>
  void record(int k)
  {
    for (const auto& array : Connectivity_access::properties<I>(a_).arrays())
      arrays_[k].push_back(array.get());
  }
  // Property maps that only the second mesh had.
  template <class I>
  void drop_added(int k)
  {
    Property_container& props = Connectivity_access::properties<I>(a_);
    std::vector<const Base_property_array*> added;
    for (const auto& array : props.arrays())
      if (std::find(arrays_[k].begin(), arrays_[k].end(), array.get()) == arrays_[k].end())
        added.push_back(array.get());
    for (const Base_property_array* array : added)
      props.remove(array);
  }

  Mobius_mesh<P>& a_;
  typename Mobius_mesh<P>::size_type nv_, ne_, nf_;
  std::vector<const Base_property_array*> arrays_[4];
  typename Mobius_mesh<P>::Join_offsets offsets_{};
  bool kept_ = false;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MERGING_INTERNAL_MERGED_MESH_H
