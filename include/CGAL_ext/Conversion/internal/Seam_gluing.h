// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The body of from_surface_mesh(): a Surface_mesh read back, the vertices
// that its seam map glues identified, the glued mesh built, and the
// correspondences of the elements, for the property maps and the output
// iterators.

#ifndef CGAL_EXT_CONVERSION_INTERNAL_SEAM_GLUING_H
#define CGAL_EXT_CONVERSION_INTERNAL_SEAM_GLUING_H

#include <CGAL_ext/Conversion/Seam_map.h>
#include <CGAL_ext/Conversion/internal/Channel_transfer.h>
#include <CGAL_ext/Conversion/internal/Property_transfer.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Union_find.h>

#include <CGAL/Surface_mesh.h>

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

// Reading a Surface_mesh back: its elements densely numbered, the vertices
// that its seam map glues identified, the glued mesh built through the
// connectivity builder, and the correspondences of the elements.
template <class Q>
struct Seam_gluing
{
  using SM = CGAL::Surface_mesh<Q>;
  using SV = typename SM::Vertex_index;
  using SH = typename SM::Halfedge_index;
  using SE = typename SM::Edge_index;
  using SF = typename SM::Face_index;

  const SM& sm;
  std::vector<std::uint32_t> dense; // dense number of each vertex not removed
  std::vector<SV> vertex_of;
  std::vector<SF> face_of;
  std::vector<bool> glued;          // per halfedge: glued by the seam map
  std::vector<std::uint32_t> class_index;
  std::vector<SV> class_rep;        // the lowest vertex of each class
  std::uint32_t n_classes = 0;

  explicit Seam_gluing(const SM& mesh)
    : sm(mesh), dense(sm.number_of_vertices() + sm.number_of_removed_vertices(), Vertex_index::null_value),
      face_of(sm.faces().begin(), sm.faces().end()), glued(sm.number_of_halfedges() + sm.number_of_removed_halfedges())
  {
    vertex_of.reserve(sm.number_of_vertices());
    for (SV v : sm.vertices()) {
      dense[std::size_t(v)] = std::uint32_t(vertex_of.size());
      vertex_of.push_back(v);
    }
  }

  // Checks the seam map and identifies the vertices it glues; returns the
  // number of glued edges.
  std::size_t glue()
  {
    Union_find glued_vertices{std::uint32_t(vertex_of.size())};
    auto unite = [&](SV a, SV b) { glued_vertices.unite(dense[std::size_t(a)], dense[std::size_t(b)]); };
    std::size_t seam_edges = 0;
    const auto [seam, has_seam] = sm.template property_map<SH, Seam_link>(seam_map_name);
    for (SH h : sm.halfedges()) {
      if (!has_seam)
        break;
      const Seam_link link = seam[h];
      if (link.partner == SH())
        continue;
      const SH g = link.partner;
      check_link(seam, h, link);
      check_link_geometry(h, link);
      glued[std::size_t(h)] = true;
      if (h < g) {
        ++seam_edges;
        unite(sm.source(h), link.twisted ? sm.source(g) : sm.target(g));
        unite(sm.target(h), link.twisted ? sm.target(g) : sm.source(g));
      }
    }
    class_index = glued_vertices.classes(n_classes);
    class_rep.resize(n_classes);
    for (std::uint32_t i = std::uint32_t(vertex_of.size()); i-- > 0;)
      class_rep[class_index[i]] = vertex_of[i];
    return seam_edges;
  }

  static std::string name(SH x) { return "h" + std::to_string(std::size_t(x)); }
  static std::string name(SV x) { return "v" + std::to_string(std::size_t(x)); }
  std::string where(SV v) const
  {
    const auto& p = sm.point(v);
    return name(v) + " (" + std::to_string(CGAL::to_double(p.x())) + ", " + std::to_string(CGAL::to_double(p.y())) +
           ", " + std::to_string(CGAL::to_double(p.z())) + ")";
  }

  template <class SeamMap>
  void check_link(const SeamMap& seam, SH h, const Seam_link& link) const
  {
    const SH g = link.partner;
    if (!sm.is_border(h))
      throw Seam_error("seam map: " + name(h) + " is glued but is not a border halfedge");
    if (std::size_t(g) >= sm.number_of_halfedges() + sm.number_of_removed_halfedges())
      throw Seam_error("seam map: the partner " + name(g) + " of " + name(h) + " does not exist");
    if (sm.is_removed(g))
      throw Seam_error("seam map: the partner " + name(g) + " of " + name(h) +
                       " has been removed (the mesh was edited across the seam after the cut)");
    if (!sm.is_border(g))
      throw Seam_error("seam map: the partner " + name(g) + " of " + name(h) + " is not a border halfedge");
    if (g == h || seam[g].partner != h || seam[g].twisted != link.twisted)
      throw Seam_error("seam map: " + name(h) + " -> " + name(g) + " is not matched by " + name(g) + " -> " +
                       name(h) + " with the same twist");
  }

  // Two copies of one point: equal up to a relative rounding error of `scale`
  // (a seam copied by to_surface_mesh() or kept by an edit is exact; a seam
  // written by hand may be computed twice).
  bool same_point(SV a, SV b, double scale) const
  {
    const double tolerance = 1e-9 * scale;
    return CGAL::to_double(CGAL::squared_distance(sm.point(a), sm.point(b))) <= tolerance * tolerance;
  }
  double length(SH h) const
  {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(sm.point(sm.source(h)), sm.point(sm.target(h)))));
  }

  // A link describes the mesh only if the two halfedges are copies of one
  // edge: same length, end points on each other. An edit that moved, split or
  // collapsed one side of the seam (or both differently) fails this.
  void check_link_geometry(SH h, const Seam_link& link) const
  {
    const SH g = link.partner;
    const double lh = length(h), lg = length(g);
    if (std::abs(lh - lg) > 1e-9 * std::max(lh, lg))
      throw Seam_error("seam map: " + name(h) + " and its partner " + name(g) + " differ in length (" +
                       std::to_string(lh) + " against " + std::to_string(lg) +
                       "): the mesh was edited along the seam after the cut");
    const SV hs = sm.source(h), ht = sm.target(h);
    const SV gs = link.twisted ? sm.source(g) : sm.target(g), gt = link.twisted ? sm.target(g) : sm.source(g);
    for (const auto& [a, b] : {std::make_pair(hs, gs), std::make_pair(ht, gt)})
      if (!same_point(a, b, std::max(lh, lg)))
        throw Seam_error("seam map: " + name(h) + " and its partner " + name(g) + " would glue " + where(a) +
                         " to " + where(b) + ", which lie apart: the seam no longer describes the mesh");
  }

  // An edit that split both sides of a seam edge alike leaves links that
  // check out and halves that are linked to nothing: two unglued border
  // halfedges at one glued vertex side by side (their other ends on each
  // other; in the same direction across a twisted seam, in opposite ones
  // across a plain one), where the cut had a seam. Gluing would leave a slit.
  void check_seam_is_whole() const
  {
    std::vector<std::uint32_t> class_size(n_classes, 0);
    for (std::uint32_t c : class_index)
      ++class_size[c];
    // (glued vertex class, the other end's point) -> halfedge
    std::map<std::tuple<std::uint32_t, double, double, double>, SH> side_by_side;
    for (SH h : sm.halfedges()) {
      if (!sm.is_border(h) || glued[std::size_t(h)])
        continue;
      for (bool at_source : {true, false}) {
        const SV at = at_source ? sm.source(h) : sm.target(h), other = at_source ? sm.target(h) : sm.source(h);
        const std::uint32_t c = class_index[dense[std::size_t(at)]];
        if (class_size[c] < 2)
          continue;
        const auto& p = sm.point(other);
        const auto [it, added] = side_by_side.emplace(
          std::make_tuple(c, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())), h);
        if (!added)
          throw Seam_error("seam map: border halfedges " + name(it->second) + " and " + name(h) +
                           " run side by side from the glued vertex " + where(at) + " to " + where(other) +
                           " but are not linked: the seam was split after the cut and its halves not relinked");
      }
    }
  }

  // One vertex per class, one face per face starting at the source of the
  // face's halfedge, so that the new face's halfedge is the same one.
  template <class P>
  void build(Mobius_mesh<P>& part) const
  {
    // Corners in one flat array: a vector per face would cost one
    // allocation per face, a third of the conversion.
    Face_list faces;
    faces.vertex.reserve(sm.number_of_halfedges());
    faces.offset.reserve(face_of.size() + 1);
    for (SF f : face_of) {
      for (SH h : CGAL::halfedges_around_face(sm.halfedge(f), sm))
        faces.vertex.push_back(class_index[dense[std::size_t(sm.source(h))]]);
      faces.offset.push_back(std::uint32_t(faces.vertex.size()));
    }
    try {
      const Point_converter<Q, P> convert;
      build_mesh_from_faces(
        faces.view(n_classes), [&](std::uint32_t v) { return convert(sm.point(class_rep[v])); }, false, part);
    } catch (const Soup_error& e) {
      std::vector<std::size_t> where;
      for (std::size_t c : e.vertices())
        for (std::uint32_t i = 0; i < vertex_of.size(); ++i)
          if (class_index[i] == c)
            where.push_back(std::size_t(vertex_of[i]));
      throw Seam_error("gluing the seam does not give a 2-manifold at vertices {" +
                       join_ids(where, "v", where.size()) + "}: " + e.what());
    }
  }

  // Correspondences, read off the face cycles in step (halfedges and edges
  // only if a property map or the caller needs them), and the property maps
  // carried over. Returns the halfedge and face pairs.
  template <class P>
  std::pair<std::vector<std::pair<SH, Halfedge_index>>, std::vector<std::pair<SF, Face_index>>>
  carry_properties(Mobius_mesh<P>& part, bool want_halfedges) const
  {
    std::vector<std::pair<SH, Halfedge_index>> halfedge_pairs;
    std::vector<std::pair<SE, Edge_index>> edge_pairs;
    want_halfedges = want_halfedges || has_user_properties<SH>(sm) || has_user_properties<SE>(sm);
    if (want_halfedges) {
      halfedge_pairs.reserve(sm.number_of_halfedges());
      edge_pairs.reserve(sm.number_of_edges());
    }
    std::vector<bool> edge_done(want_halfedges ? part.number_of_edges() : 0, false);
    for (std::size_t f = 0; want_halfedges && f < face_of.size(); ++f) {
      Dart d = part.halfedge(Face_index(f));
      for (SH h : CGAL::halfedges_around_face(sm.halfedge(face_of[f]), sm)) {
        halfedge_pairs.emplace_back(h, d.halfedge());
        const SH o = sm.opposite(h);
        if (sm.is_border(o) && !glued[std::size_t(o)])
          halfedge_pairs.emplace_back(o, Mobius_mesh<P>::opposite_halfedge(d.halfedge()));
        const Edge_index e = part.edge(d);
        if (!edge_done[e.idx()]) { // a glued edge takes the first of its two copies' values
          edge_done[e.idx()] = true;
          edge_pairs.emplace_back(sm.edge(h), e);
        }
        d = part.next(d);
      }
    }
    std::vector<std::pair<SV, Vertex_index>> rep_pairs(n_classes);
    for (std::uint32_t c = 0; c < n_classes; ++c)
      rep_pairs[c] = {class_rep[c], Vertex_index(c)};
    std::vector<std::pair<SF, Face_index>> face_pairs(face_of.size());
    for (std::size_t f = 0; f < face_of.size(); ++f)
      face_pairs[f] = {face_of[f], Face_index(f)};
    properties_from_surface_mesh(sm, part, rep_pairs);
    properties_from_surface_mesh(sm, part, halfedge_pairs);
    if (want_halfedges) {
      // The corners: the face halfedges, each ending at the corner of the
      // part's face where it does (the part's faces are not reversed yet).
      std::vector<std::pair<SH, Halfedge_index>> corners;
      corners.reserve(halfedge_pairs.size());
      for (const auto& [s, h] : halfedge_pairs)
        if (!sm.is_border(s))
          corners.emplace_back(s, h);
      channels_from_surface_mesh(sm, part, corners);
    }
    properties_from_surface_mesh(sm, part, edge_pairs);
    properties_from_surface_mesh(sm, part, face_pairs);
    return {std::move(halfedge_pairs), std::move(face_pairs)};
  }
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_CONVERSION_INTERNAL_SEAM_GLUING_H
