// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Subdivision of non-manifold input held as manifold sheets (the vertex map
// "v:non_manifold_join"), as OpenSubdiv subdivides the joined input: its
// Vtr level holds non-manifold topology and makes every non-manifold edge
// and vertex infinitely sharp, except a vertex on an interior non-manifold
// crease (two non-manifold edges, no border, more faces than edges), which
// follows the crease rule along its two non-manifold edges.
//
// On the sheets, an edge of three or more faces is a border per face: its
// point is the midpoint on every copy, as OpenSubdiv's infinitely sharp
// edge. A sharpened vertex gets infinite sharpness on every copy. A vertex
// on an interior non-manifold crease cannot be expressed by sharpness on its
// copies (a copy sees only its own sheet's edges and faces): its point is
// computed here, after each level, from the joined vertex's edges with the
// rules of Crease.h, and so is the Chaikin decay of the semi-sharp edges at
// a joined vertex (an average over its whole ring). Everything else is the
// manifold refiner's, one level at a time.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_JOINED_SUBDIVISION_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_JOINED_SUBDIVISION_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_array.h>
#include <CGAL_ext/Mobius_mesh/internal/Join_classes.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/internal/Subdivision_driver.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// A vertex of the input on an interior non-manifold crease: its copies in
// the sheets (the same indices at every level) and its own sharpness.
struct Joined_crease_vertex
{
  std::vector<u32> copies;
  float sharpness = 0.0f;
};

// The edges of a joined vertex at one level as OpenSubdiv's Level lists
// them: each edge of the input once, a degenerate one twice (it has the
// vertex at both ends); its far end and sharpness (a border edge, of the
// input or split off a non-manifold edge, is infinitely sharp, as
// OpenSubdiv makes it), and the counts by which OpenSubdiv classifies the
// vertex: its corners, the edges of fewer than two faces, the non-manifold
// edges.
template <class P>
struct Joined_ring
{
  std::vector<P> far;
  std::vector<float> sharpness;
  std::vector<u32> edge; // the class (its representative edge) of each entry
  std::size_t faces = 0, borders = 0, non_manifold = 0;
};

template <class P, class EdgeSharpness>
Joined_ring<P> joined_ring(const Mobius_mesh<P>& mesh, const CGAL_ext::internal::Join_classes& classes,
                           const std::vector<u32>& copies, const EdgeSharpness& edge_sharpness)
{
  Joined_ring<P> ring;
  std::unordered_set<u32> seen;
  for (u32 c : copies) {
    for (Dart d : CGAL_ext::halfedges_around_target(Vertex_index(c), mesh)) {
      ring.faces += mesh.is_border(d) ? 0 : 1;
      const Edge_index e = mesh.edge(d);
      if (!seen.insert(classes.edge_representative(e.idx())).second)
        continue;
      const bool border = mesh.is_border(e), non_manifold = classes.is_non_manifold_edge(e.idx());
      // A class of several edges has a face each (they are borders).
      const u32 members = classes.edge_members(e.idx()), faces = members > 1 ? members : (border ? 1 : 2);
      const int entries = classes.is_degenerate_edge(mesh.source(d).idx(), c) ? 2 : 1;
      for (int i = 0; i < entries; ++i) {
        ring.non_manifold += non_manifold ? 1 : 0;
        ring.borders += faces < 2 ? 1 : 0;
        ring.far.push_back(mesh.point(mesh.source(d)));
        ring.sharpness.push_back(border || non_manifold ? infinitely_sharp : float(edge_sharpness(e)));
        ring.edge.push_back(classes.edge_representative(e.idx()));
      }
    }
  }
  return ring;
}

// The vertices v < nv for which `selected(v)` holds, grouped by input
// vertex (at its representative's index; the other entries empty).
template <class Selected>
std::vector<std::vector<u32>> copies_by_input_vertex(const CGAL_ext::internal::Join_classes& classes, u32 nv,
                                                     Selected selected)
{
  std::vector<std::vector<u32>> copies(nv);
  for (u32 v = 0; v < nv; ++v)
    if (selected(v))
      copies[classes.representative(v)].push_back(v);
  return copies;
}

// Whether a corner channel of `mesh` holds several values at the vertices
// `copies` (one vertex of the input).
template <class P>
bool has_several_corner_values(const Mobius_mesh<P>& mesh, const std::vector<u32>& copies)
{
  bool several = false;
  const auto& hprops = CGAL_ext::internal::Connectivity_access::properties<Halfedge_index>(mesh);
  hprops.template for_each_array<CGAL_ext::internal::Base_corner_channel>(
    [&](const CGAL_ext::internal::Base_corner_channel& channel) {
      u32 first = CGAL_ext::internal::Base_corner_channel::no_value;
      for (u32 c : copies)
        for (Dart d : CGAL_ext::halfedges_around_target(Vertex_index(c), mesh)) {
          if (mesh.is_border(d))
            continue;
          const u32 value = channel.indices()[mesh.corner(d).idx()];
          several = several || (first != CGAL_ext::internal::Base_corner_channel::no_value && value != first);
          first = value;
        }
    });
  return several;
}

// OpenSubdiv's sharpening of the non-manifold vertices of the input
// (Far::TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness): each
// non-manifold vertex (joined, or on a non-manifold edge) gets the largest sharpness of its copies (a file's tag
// names one) and, unless it lies on an interior non-manifold crease,
// infinite sharpness; the crease vertices are returned.
template <class P, class EdgeSharpness>
std::vector<Joined_crease_vertex> sharpen_joined_vertices(const Mobius_mesh<P>& mesh,
                                                          const CGAL_ext::internal::Join_classes& classes,
                                                          const EdgeSharpness& edge_sharpness,
                                                          std::vector<float>& vertex_sharpness)
{
  const std::vector<std::vector<u32>> copies =
    copies_by_input_vertex(classes, u32(mesh.number_of_vertices()),
                           [&classes](u32 v) { return classes.is_non_manifold_vertex(v); });
  std::vector<Joined_crease_vertex> creases;
  for (const std::vector<u32>& c : copies) {
    if (c.empty())
      continue;
    float s = 0.0f;
    for (u32 v : c)
      s = (std::max)(s, vertex_sharpness[v]);
    const Joined_ring<P> ring = joined_ring(mesh, classes, c, edge_sharpness);
    const bool interior_crease = ring.non_manifold == 2 && ring.borders == 0 && ring.faces > ring.far.size();
    if (interior_crease)
      creases.push_back({c, s});
    // A crease vertex's points are computed apart (joined_crease_point());
    // its sharpness on the sheets decides only its corner values, which
    // OpenSubdiv makes corners where a channel is cut there
    // (Vtr::FVarLevel::completeTopologyFromFaceValues()).
    if (!interior_crease || has_several_corner_values(mesh, c))
      s = infinitely_sharp;
    for (u32 v : c)
      vertex_sharpness[v] = s;
  }
  return creases;
}

// The sharpness that OpenSubdiv's rules gave the non-manifold vertices is
// theirs, not the mesh's: the result's vertices keep the sharpness given
// (decayed), and gets no sharpness map where `mesh` had none to give.
template <class P, class NamedParameters>
void unsharpen_joined_vertices(const Mobius_mesh<P>& mesh, const NamedParameters& np,
                               const std::vector<float>& given_sharpness, Mobius_mesh<P>& result)
{
  auto vs = vertex_sharpness_map(result);
  std::copy(given_sharpness.begin(), given_sharpness.end(), vs.data().begin());
  if (!CGAL_ext::internal::vertex_sharpness_of(mesh, np).has_map())
    result.remove_property_map(vs);
  if (!CGAL_ext::internal::edge_sharpness_of(mesh, np).has_map()) {
    auto es = edge_sharpness_map(result);
    result.remove_property_map(es);
  }
}

// The sharpness of the child of each edge of `ring` at its joined vertex
// (Chaikin's rule averages the semi-sharp edges around the vertex: all of
// them, whatever sheet they lie in).
template <class P>
std::vector<float> joined_child_sharpness(const Joined_ring<P>& ring, Crease_method method)
{
  const unsigned m = unsigned(ring.far.size());
  Crease::Semi_sharp_edges around;
  for (float s : ring.sharpness)
    around.add(s);
  std::vector<float> child(m);
  for (unsigned i = 0; i < m; ++i)
    child[i] = Crease::is_sharp(ring.sharpness[i])
                 ? Crease::subdivide_edge_sharpness_at_vertex(method, ring.sharpness[i], m, around)
                 : 0.0f;
  return child;
}

// With Chaikin's rule, a copy of a joined vertex sees only its own sheet's
// semi-sharp edges: the halves at the copies of each joined vertex of
// `parent` get in `child` the sharpness the joined vertex's whole ring gives.
template <class P, class EdgeSharpness>
void decay_at_joined_vertices(const Mobius_mesh<P>& parent, const CGAL_ext::internal::Join_classes& classes,
                              const EdgeSharpness& edge_sharpness, Crease_method method, Mobius_mesh<P>& child)
{
  if (method != Crease_method::chaikin)
    return; // the uniform rule decays each edge by itself
  const u32 nv = u32(parent.number_of_vertices());
  const std::vector<std::vector<u32>> copies =
    copies_by_input_vertex(classes, nv, [&classes](u32 v) { return classes.is_joined(v); });
  auto child_sharpness = edge_sharpness_map(child);
  for (const std::vector<u32>& c : copies) {
    if (c.empty())
      continue;
    const Joined_ring<P> ring = joined_ring(parent, classes, c, edge_sharpness);
    if (std::none_of(ring.sharpness.begin(), ring.sharpness.end(), [](float s) { return Crease::is_semi_sharp(s); }))
      continue;
    const std::vector<float> decayed = joined_child_sharpness(ring, method);
    for (u32 v : c)
      for (Dart d : CGAL_ext::halfedges_around_target(Vertex_index(v), parent)) {
        const Edge_index e = parent.edge(d);
        const float s = edge_sharpness(e);
        if (parent.is_border(e) || !Crease::is_semi_sharp(s))
          continue;
        const u32 entry = u32(std::find(ring.edge.begin(), ring.edge.end(), classes.edge_representative(e.idx())) -
                              ring.edge.begin());
        CGAL_assertion(entry < decayed.size());
        for (Dart h : CGAL_ext::halfedges_around_target(Vertex_index(v), child))
          if (child.source(h).idx() == nv + e.idx())
            child_sharpness[child.edge(h)] = decayed[entry];
      }
  }
}

// The point of the child of a vertex at `p` with sharpness `vs` and edges
// `ring` (at least two of them infinitely sharp: a crease or a corner,
// blended where the rule changes), as OpenSubdiv's vertex-vertex rule.
template <class P>
P joined_crease_point(const P& p, const Joined_ring<P>& ring, float vs, Crease_method method)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  const unsigned m = unsigned(ring.far.size());
  const std::vector<float> child = joined_child_sharpness(ring, method);
  const float child_vs = Crease::subdivide_vertex_sharpness(vs);
  const Crease::Rule rule = Crease::vertex_rule(vs, m, ring.sharpness.data());
  const Crease::Rule child_rule = Crease::vertex_rule(child_vs, m, child.data());
  auto point_of = [&](Crease::Rule r, const std::vector<float>& sharpness) {
    if (r != Crease::Rule::crease)
      return p - CGAL::ORIGIN; // a corner: two infinitely sharp edges leave no smooth or dart rule
    std::vector<P> ends;
    for (unsigned i = 0; i < m && ends.size() < 2; ++i)
      if (Crease::is_sharp(sharpness[i]))
        ends.push_back(ring.far[i]);
    return (p - CGAL::ORIGIN) * FT(0.75) + ((ends[0] - CGAL::ORIGIN) + (ends[1] - CGAL::ORIGIN)) * FT(0.125);
  };
  if (rule == child_rule)
    return CGAL::ORIGIN + point_of(rule, ring.sharpness);
  const FT w(double(Crease::fractional_weight_at_vertex(vs, child_vs, m, ring.sharpness.data(), child.data())));
  return CGAL::ORIGIN + (point_of(rule, ring.sharpness) * w + point_of(child_rule, child) * (FT(1) - w));
}

// The joins of the child of `parent` (vertices of `child_vertices`): a
// vertex point is its parent's (parent vertices keep their index), the
// point of a copy of a non-manifold edge that of its class's first edge.
template <class P>
std::vector<u32> child_joins(const Mobius_mesh<P>& parent, const CGAL_ext::internal::Join_classes& classes,
                             std::size_t child_vertices)
{
  const u32 nv = u32(parent.number_of_vertices()), ne = u32(parent.number_of_edges());
  std::vector<u32> join(child_vertices);
  for (u32 v = 0; v < u32(child_vertices); ++v)
    join[v] = v < nv ? classes.representative(v) : v;
  for (u32 e = 0; e < ne; ++e)
    join[nv + e] = nv + classes.edge_representative(e);
  return join;
}

// The groups of the child's edges for its Join_classes: a half of a parent
// edge is one with the halves of the same input edge at the same input
// vertex (at the same copy for a degenerate edge, whose two halves both
// end at its vertex and stay two edges, as in OpenSubdiv's next level);
// every other child edge lies inside one parent face and is an edge of its
// own, even where a child of another face has the same two input vertices
// as ends (two faces on the same corners, as two triangles glued into a
// pillow whose edge points are copies of one vertex): a group of its own.
// (A half of an edge of its own class is a class of one, not tagged
// non-manifold as OpenSubdiv tags it: a border, it is infinitely sharp all
// the same.)
template <class P>
std::vector<std::uint64_t> child_edge_groups(const Mobius_mesh<P>& parent,
                                             const CGAL_ext::internal::Join_classes& classes,
                                             const Mobius_mesh<P>& child)
{
  const u32 nv = u32(parent.number_of_vertices()), ne = u32(parent.number_of_edges());
  std::vector<std::uint64_t> group(child.number_of_edges(), 0);
  for (Edge_index c : child.edges()) {
    u32 x = child.vertex(c, 0).idx(), y = child.vertex(c, 1).idx();
    if (x > y)
      std::swap(x, y);
    if (x >= nv || y < nv || y >= nv + ne) { // inside a parent face
      group[c.idx()] = c.idx(); // halves' groups are 2^32 and above
      continue;
    }
    const Edge_index e(y - nv);
    const bool degenerate = classes.is_degenerate_edge(parent.vertex(e, 0).idx(), parent.vertex(e, 1).idx());
    group[c.idx()] = std::uint64_t(classes.edge_representative(e.idx()) + 1) << 32 |
                     (degenerate ? x : classes.representative(x));
  }
  return group;
}

// Subdivides sheets joined by the vertex map "v:non_manifold_join" as
// OpenSubdiv subdivides the joined input (see the top of this file), a
// level at a time; the result carries the joins of its level.
template <class ConcurrencyTag, class Mask, class P, class NamedParameters>
void subdivide_joined(Mobius_mesh<P>& mesh, const Mask& mask, const NamedParameters& np)
{
  namespace pm = CGAL_ext::parameters;
  if constexpr (Mask::split == Split::dual || Mask::split == Split::sqrt3) {
    throw Parameter_error(std::string("subdivision: Doo-Sabin and sqrt(3) subdivision do not take non-manifold input "
                                      "(a mesh of sheets with the vertex map \"") +
                          non_manifold_join_name + "\"); Catmull-Clark, Loop, bilinear and linear do");
  } else {
    const unsigned levels =
      unsigned(pm::choose_parameter(pm::get_parameter(np, CGAL::internal_np::number_of_iterations), 1));
    const Crease_method method = CGAL_ext::internal::crease_method_of(np);
    const auto one_level =
      pm::number_of_iterations(1)
        .boundary_interpolation(CGAL_ext::internal::boundary_interpolation_of(np))
        .crease_method(method)
        .face_varying_interpolation(pm::choose_parameter(
          pm::get_parameter(np, CGAL_ext::internal_np::face_varying_interpolation), Face_varying_interpolation::corners_plus1))
        .maximum_memory(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::maximum_memory),
                                             CGAL_ext::internal::available_memory()));
    // The join map names vertices by index: a mesh with removed elements
    // has indices the refiner does not keep.
    CGAL_ext::internal::require_no_garbage(mesh, "subdivision");
    // Build the result aside: on failure the caller's mesh stays as it was.
    Mobius_mesh<P> work = mesh;
    const auto vpm = pm::choose_parameter(pm::get_parameter(np, CGAL::internal_np::vertex_point), mesh.points());
    for (Vertex_index v : mesh.vertices())
      work.point(v) = get(vpm, v);
    std::vector<float> es, vs;
    gather_sharpness(mesh, np, es, vs);
    es.resize(mesh.number_of_edges(), 0.0f);
    vs.resize(mesh.number_of_vertices(), 0.0f);
    auto join_map = *non_manifold_join_map(work);
    CGAL_ext::internal::Join_classes classes(work);
    work.remove_property_map(join_map);
    edge_sharpness_map(work).data() = es;
    std::vector<float> given_vs = vs;
    std::vector<Joined_crease_vertex> creases =
      sharpen_joined_vertices(work, classes, [&es](Edge_index e) { return es[e.idx()]; }, vs);
    vertex_sharpness_map(work).data() = vs;
    for (unsigned k = 0; k < levels; ++k) {
      Mobius_mesh<P> next = work;
      subdivide_sheets<ConcurrencyTag>(next, mask, one_level);
      if constexpr (Mask::creases) {
        const auto map = edge_sharpness_map(work);
        const auto sharpness = [&map](Edge_index e) { return map[e]; };
        decay_at_joined_vertices(work, classes, sharpness, method, next);
        for (Joined_crease_vertex& c : creases) {
          const P p = joined_crease_point(work.point(Vertex_index(c.copies[0])),
                                          joined_ring(work, classes, c.copies, sharpness), c.sharpness, method);
          for (u32 v : c.copies)
            next.point(Vertex_index(v)) = p;
          c.sharpness = Crease::subdivide_vertex_sharpness(c.sharpness);
        }
      }
      classes = CGAL_ext::internal::Join_classes(next, child_joins(work, classes, next.number_of_vertices()),
                                                 child_edge_groups(work, classes, next));
      work = std::move(next);
      for (float& s : given_vs)
        s = Crease::subdivide_vertex_sharpness(s);
    }
    unsharpen_joined_vertices(mesh, np, given_vs, work);
    classes.write_map(work);
    mesh = std::move(work);
  }
}

// The subdivision functions' engine: sheets with joins as the joined input,
// any other mesh as it is.
template <class ConcurrencyTag, class Mask, class P, class NamedParameters>
void subdivide(Mobius_mesh<P>& mesh, const Mask& mask, const NamedParameters& np)
{
  if (non_manifold_join_map(mesh))
    subdivide_joined<ConcurrencyTag>(mesh, mask, np);
  else
    subdivide_sheets<ConcurrencyTag>(mesh, mask, np);
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_JOINED_SUBDIVISION_H
