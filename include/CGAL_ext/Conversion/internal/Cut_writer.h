// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The body of to_surface_mesh(): the wedges around each vertex, the
// Surface_mesh written from an oriented Mobius_mesh cut along its Möbius
// edges, with its seam map, and the user's property maps and output
// iterators.

#ifndef CGAL_EXT_CONVERSION_INTERNAL_CUT_WRITER_H
#define CGAL_EXT_CONVERSION_INTERNAL_CUT_WRITER_H

#include <CGAL_ext/Conversion/Conversion_result.h>
#include <CGAL_ext/Conversion/Seam_map.h>
#include <CGAL_ext/Conversion/internal/Channel_transfer.h>
#include <CGAL_ext/Conversion/internal/Property_transfer.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Union_find.h>

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
namespace internal {

// Wedges: around each vertex, faces between two Möbius edges share a vertex
// copy. `wedge[h]` is the copy at the target of the (oriented) face halfedge
// h; `wedge_vertex[w]` the vertex of copy w (copy v is vertex v). Around an
// interior vertex the Möbius edges come in even numbers (its star is a disc),
// so a Möbius edge always has distinct copies at both ends on its two sides:
// the cut is a 2-manifold.
template <class O>
void label_wedges(const Mobius_mesh<O>& oriented, std::size_t mobius_left, std::vector<std::uint32_t>& wedge,
                  std::vector<Vertex_index>& wedge_vertex)
{
  constexpr std::uint32_t none = Vertex_index::null_value;
  wedge.assign(oriented.number_of_halfedges(), none);
  wedge_vertex.resize(oriented.number_of_vertices());
  for (std::size_t i = 0; i < wedge_vertex.size(); ++i)
    wedge_vertex[i] = Vertex_index(i);
  if (mobius_left == 0) {
    // Nothing is cut: each corner is its own vertex, no walk around vertices.
    for (Halfedge_index h : oriented.halfedges())
      if (!oriented.is_border(h))
        wedge[h.idx()] = oriented.target(Dart(h, false)).idx();
    return;
  }
  for (Vertex_index v : oriented.vertices()) {
    Dart start = oriented.halfedge(v);
    if (!start.is_valid())
      continue;
    if (!oriented.is_border(start)) {
      // Start on a Möbius edge, so that the walk's wrap-around is not inside a wedge.
      for (Dart d : CGAL_ext::halfedges_around_target(start, oriented))
        if (oriented.is_mobius(oriented.edge(d))) {
          start = d;
          break;
        }
    }
    std::uint32_t label = none;
    for (Dart d : CGAL_ext::halfedges_around_target(start, oriented)) {
      if (oriented.is_border(d))
        continue;
      if (label == none)
        label = v.idx();
      else if (oriented.is_mobius(oriented.edge(d))) {
        label = std::uint32_t(wedge_vertex.size());
        wedge_vertex.push_back(v);
      }
      // A flipped incoming dart is the halfedge leaving v in its face: the
      // corner at v ends the previous halfedge of the face.
      const Halfedge_index corner = d.is_flipped() ? oriented.next(d).halfedge() : d.halfedge();
      wedge[corner.idx()] = label;
    }
  }
}

// The Surface_mesh written from an oriented Mobius_mesh cut along its Möbius
// edges: its elements for ours, built directly (linear, no search) in arrays
// reserved once; each cut Möbius edge becomes two edges.
template <class O, class Q>
struct Cut_writer
{
  using SM = CGAL::Surface_mesh<Q>;
  using SV = typename SM::Vertex_index;
  using SH = typename SM::Halfedge_index;
  using SE = typename SM::Edge_index;
  using SF = typename SM::Face_index;

  const Mobius_mesh<O>& oriented;
  SM& sm;
  std::vector<std::uint32_t> wedge;
  std::vector<Vertex_index> wedge_vertex;
  std::vector<SV> sm_vertex;
  std::vector<SH> face_he; // the face halfedge of sm for a face halfedge of ours
  std::vector<SH> seam_he; // its border partner, where the edge was cut
  std::vector<std::pair<Edge_index, SE>> edge_pairs;
  std::vector<std::pair<Face_index, SF>> face_pairs;
  std::size_t seam_edges = 0;

  template <class P>
  void add_vertices(const Mobius_mesh<P>& mesh, std::size_t mobius_left)
  {
    sm.reserve(typename SM::size_type(sm.number_of_vertices() + sm.number_of_removed_vertices() + wedge_vertex.size()),
               typename SM::size_type(sm.number_of_edges() + sm.number_of_removed_edges() + mesh.number_of_edges() +
                                      mobius_left),
               typename SM::size_type(sm.number_of_faces() + sm.number_of_removed_faces() + mesh.number_of_faces()));
    const Point_converter<P, Q> convert;
    sm_vertex.resize(wedge_vertex.size());
    for (std::size_t w = 0; w < wedge_vertex.size(); ++w)
      sm_vertex[w] = sm.add_vertex(convert(mesh.point(wedge_vertex[w])));
  }

  void add_edges(bool want_edge_pairs, std::size_t mobius_left)
  {
    face_he.resize(oriented.number_of_halfedges());
    seam_he.resize(mobius_left > 0 ? oriented.number_of_halfedges() : 0);
    if (want_edge_pairs)
      edge_pairs.reserve(oriented.number_of_edges() + mobius_left);
    for (Edge_index e : oriented.edges()) {
      const Halfedge_index h0 = Mobius_mesh<O>::halfedge(e, 0), h1 = Mobius_mesh<O>::halfedge(e, 1);
      if (!oriented.is_border(h0) && !oriented.is_border(h1) && !oriented.is_mobius(e)) {
        const SH s = sm.add_edge();
        face_he[h0.idx()] = s;
        face_he[h1.idx()] = sm.opposite(s);
        if (want_edge_pairs)
          edge_pairs.emplace_back(e, sm.edge(s));
        continue;
      }
      for (Halfedge_index h : {h0, h1}) {
        if (oriented.is_border(h))
          continue;
        const SH s = sm.add_edge();
        face_he[h.idx()] = s;
        if (want_edge_pairs)
          edge_pairs.emplace_back(e, sm.edge(s));
        if (oriented.is_mobius(e))
          seam_he[h.idx()] = sm.opposite(s);
      }
      seam_edges += oriented.is_mobius(e) ? 1 : 0;
    }
  }

  void add_faces()
  {
    face_pairs.resize(oriented.number_of_faces());
    std::vector<SH> border_in(wedge_vertex.size()), border_out(wedge_vertex.size());
    for (Face_index f : oriented.faces()) {
      const SF sf = sm.add_face();
      face_pairs[f.idx()] = {f, sf};
      const Dart first = oriented.halfedge(f);
      sm.set_halfedge(sf, face_he[first.halfedge().idx()]);
      for (Dart d : CGAL_ext::halfedges_around_face(first, oriented)) {
        // Darts of a face cycle are valid: the halfedge is read off the bits,
        // where d.halfedge() would show GCC 12 its null branch and a false
        // -Warray-bounds at -O3.
        const Halfedge_index h(dart_encoding::halfedge_of_dart(d.bits()));
        const SH s = face_he[h.idx()];
        const std::uint32_t t = wedge[h.idx()], src = wedge[oriented.prev(d).halfedge().idx()];
        sm.set_target(s, sm_vertex[t]);
        sm.set_face(s, sf);
        sm.set_next(s, face_he[oriented.next(d).halfedge().idx()]);
        sm.set_halfedge(sm_vertex[t], s);
        // A face halfedge without a face on the other side: its partner is a
        // border halfedge of sm, running from t to src.
        if (oriented.is_border(Mobius_mesh<O>::opposite_halfedge(h)) || oriented.is_mobius(oriented.edge(d))) {
          const SH b = sm.opposite(s);
          sm.set_target(b, sm_vertex[src]);
          sm.set_face(b, SF());
          border_in[src] = b;
          border_out[t] = b;
        }
      }
    }
    for (std::size_t w = 0; w < wedge_vertex.size(); ++w) {
      if (border_in[w] == SH())
        continue;
      sm.set_next(border_in[w], border_out[w]);
      sm.set_halfedge(sm_vertex[w], border_in[w]);
    }
  }

  // The seam and orientation records that from_surface_mesh() reads.
  void record_seam_and_reversals(const std::vector<bool>& reversed, std::size_t reversed_faces)
  {
    if (seam_edges > 0) {
      auto seam = sm.template add_property_map<SH, Seam_link>(seam_map_name, Seam_link()).first;
      for (Edge_index e : oriented.edges()) {
        if (!oriented.is_mobius(e))
          continue;
        const SH b0 = seam_he[Mobius_mesh<O>::halfedge(e, 0).idx()], b1 = seam_he[Mobius_mesh<O>::halfedge(e, 1).idx()];
        seam[b0] = Seam_link{b1, true};
        seam[b1] = Seam_link{b0, true};
      }
    }
    if (reversed_faces > 0) {
      auto flag = sm.template add_property_map<SF, bool>(reversed_faces_map_name, false).first;
      for (const auto& [f, sf] : face_pairs)
        flag[sf] = reversed[f.idx()];
    }
  }
};

// The user's property maps and the output iterators of to_surface_mesh().
template <class P, class O, class Q, class NamedParameters>
void carry_to_surface_mesh(const Mobius_mesh<P>& mesh, const Cut_writer<O, Q>& w, const std::vector<bool>& reversed,
                           const NamedParameters& np)
{
  using SV = typename Cut_writer<O, Q>::SV;
  using SH = typename Cut_writer<O, Q>::SH;
  std::vector<std::pair<Vertex_index, SV>> vertex_pairs;
  if (has_user_properties<Vertex_index>(mesh) ||
      has_output<NamedParameters>(CGAL::internal_np::vertex_to_vertex_output_iterator)) {
    vertex_pairs.resize(w.wedge_vertex.size());
    for (std::size_t i = 0; i < w.wedge_vertex.size(); ++i)
      vertex_pairs[i] = {w.wedge_vertex[i], w.sm_vertex[i]};
  }
  std::vector<std::pair<Halfedge_index, SH>> halfedge_pairs;
  if (has_user_properties<Halfedge_index>(mesh) ||
      has_output<NamedParameters>(CGAL::internal_np::halfedge_to_halfedge_output_iterator)) {
    halfedge_pairs.reserve(mesh.number_of_halfedges());
    for (Halfedge_index h : mesh.halfedges())
      if (!mesh.is_border(h)) {
        halfedge_pairs.emplace_back(h, w.face_he[h.idx()]);
        if (mesh.is_border(Mobius_mesh<P>::opposite_halfedge(h)))
          halfedge_pairs.emplace_back(Mobius_mesh<P>::opposite_halfedge(h), w.sm.opposite(w.face_he[h.idx()]));
      }
  }
  properties_to_surface_mesh(mesh, w.sm, vertex_pairs);
  properties_to_surface_mesh(mesh, w.sm, halfedge_pairs);
  properties_to_surface_mesh(mesh, w.sm, w.edge_pairs);
  properties_to_surface_mesh(mesh, w.sm, w.face_pairs);

  write_pairs(np, CGAL::internal_np::vertex_to_vertex_output_iterator, [&](auto out) {
    for (const auto& p : vertex_pairs)
      out(p);
  });
  write_pairs(np, CGAL::internal_np::halfedge_to_halfedge_output_iterator, [&](auto out) {
    for (const auto& [h, s] : halfedge_pairs) {
      const Halfedge_index fh = mesh.is_border(h) ? Mobius_mesh<P>::opposite_halfedge(h) : h;
      const Dart d(fh, reversed[mesh.face(fh).idx()]);
      out(std::make_pair(mesh.is_border(h) ? mesh.opposite(d) : d, s));
    }
  });
  write_pairs(np, CGAL::internal_np::face_to_face_output_iterator, [&](auto out) {
    for (const auto& p : w.face_pairs)
      out(p);
  });
}

// The body of to_surface_mesh(), given `oriented`: the connectivity of `mesh`
// with its faces oriented and `mobius_left` Möbius edges left (`mesh` itself
// when it has none).
template <class P, class O, class Q, class NamedParameters>
Conversion_result to_surface_mesh(const Mobius_mesh<P>& mesh, const Mobius_mesh<O>& oriented, std::size_t mobius_left,
                                  CGAL::Surface_mesh<Q>& sm, const NamedParameters& np)
{
  Conversion_result result;
  // Which faces orient() turned.
  std::vector<bool> reversed(mesh.number_of_faces(), false);
  for (Face_index f : mesh.faces()) {
    const Halfedge_index h = mesh.halfedge(f).halfedge();
    reversed[f.idx()] = oriented.target(Dart(h, false)) != mesh.target(Dart(h, false));
    result.reversed_faces += reversed[f.idx()] ? 1 : 0;
  }
  Cut_writer<O, Q> w{oriented, sm, {}, {}, {}, {}, {}, {}, {}, 0};
  label_wedges(oriented, mobius_left, w.wedge, w.wedge_vertex);
  result.added_vertices = w.wedge_vertex.size() - mesh.number_of_vertices();
  w.add_vertices(mesh, mobius_left);
  w.add_edges(has_user_properties<Edge_index>(mesh), mobius_left);
  w.add_faces();
  result.seam_edges = w.seam_edges;
  w.record_seam_and_reversals(reversed, result.reversed_faces);
  carry_to_surface_mesh(mesh, w, reversed, np);
  if (!mesh.corner_channels().empty()) {
    // Each face halfedge of sm ends at the corner of its face at the
    // oriented target: the source of a reversed face's halfedge.
    std::vector<std::pair<Halfedge_index, typename Cut_writer<O, Q>::SH>> corners;
    corners.reserve(mesh.number_of_halfedges());
    for (Halfedge_index h : mesh.halfedges())
      if (!mesh.is_border(h))
        corners.emplace_back(mesh.corner(Dart(h, reversed[mesh.face(h).idx()])), w.face_he[h.idx()]);
    const Channel_transfer_report report = channels_to_surface_mesh(mesh, sm, corners);
    result.corner_channels_not_carried = report.not_carried;
    result.corners_without_value = report.corners_without_value;
  }
  return result;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_CONVERSION_INTERNAL_CUT_WRITER_H
