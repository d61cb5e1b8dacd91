// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Conversion between Mobius_mesh and CGAL::Surface_mesh. Orientable meshes
// convert losslessly; non-orientable ones are cut along their Möbius edges,
// and the cut is recorded in a Surface_mesh property map so that converting
// back glues it again.

#ifndef CGAL_EXT_SURFACE_MESH_CONVERSION_H
#define CGAL_EXT_SURFACE_MESH_CONVERSION_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>
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

/// \ingroup PkgMobiusMeshConversion
/// One entry of the seam map of a cut `Surface_mesh` (see `to_surface_mesh()`):
/// the border halfedge this border halfedge is glued to, and how. With
/// `twisted == true` the two halfedges are glued running the *same* way
/// (source to source, target to target): the glued edge is a Möbius edge.
/// With `twisted == false` they are glued running opposite ways (source to
/// target), as the two halfedges of an ordinary edge. Halfedges that are not
/// glued hold a null `partner`.
struct Seam_link
{
  /// The border halfedge glued to this one; null if none.
  CGAL::SM_Halfedge_index partner;
  /// True if the two halfedges are glued running the same way (a Möbius edge).
  bool twisted = false;
};

/// Name of the `Surface_mesh` halfedge property map of `Seam_link`s.
inline constexpr const char* seam_map_name = "h:mobius_seam";
/// Name of the `Surface_mesh` face property map (`bool`) that marks the faces
/// whose orientation `to_surface_mesh()` reversed.
inline constexpr const char* reversed_faces_map_name = "f:mobius_reversed";

/// \ingroup PkgMobiusMeshConversion
/// What a conversion did.
struct Conversion_result
{
  std::size_t seam_edges = 0;     ///< edges cut (to) or glued (from) along the seam
  std::size_t reversed_faces = 0; ///< faces whose orientation was reversed (to) or restored (from)
  std::size_t added_vertices = 0; ///< vertex copies made along the seam (to) or removed by gluing (from)
};

namespace internal {

template <class Q>
bool is_surface_mesh_internal_property(const std::string& name)
{
  return name == "v:connectivity" || name == "h:connectivity" || name == "f:connectivity" || name == "v:point" ||
         name == "v:removed" || name == "e:removed" || name == "f:removed" || name == seam_map_name ||
         name == reversed_faces_map_name;
}

// The value types whose property maps the conversions carry. Surface_mesh
// makes a property array only through `add_property_map<I, T>()`, with `T`
// named at compile time, so a list is needed here (copies between
// Mobius_meshes carry any type): bool, the arithmetic types, strings, and,
// when both sides use the same point type, points and vectors of its kernel.
template <class P1, class P2, class F>
void for_each_transferable_type(F&& f)
{
  f(Type_tag<bool>());
  f(Type_tag<char>());
  f(Type_tag<signed char>());
  f(Type_tag<unsigned char>());
  f(Type_tag<short>());
  f(Type_tag<unsigned short>());
  f(Type_tag<int>());
  f(Type_tag<unsigned int>());
  f(Type_tag<long>());
  f(Type_tag<unsigned long>());
  f(Type_tag<long long>());
  f(Type_tag<unsigned long long>());
  f(Type_tag<float>());
  f(Type_tag<double>());
  f(Type_tag<std::string>());
  if constexpr (std::is_same_v<P1, P2>) {
    using K = typename CGAL::Kernel_traits<P1>::Kernel;
    f(Type_tag<typename K::Point_3>());
    f(Type_tag<typename K::Vector_3>());
  }
}

// True if there are property maps of kind `I` to carry over (points and
// Surface_mesh's own maps aside): the element correspondences, a pair per
// element, are built only then (or for an output iterator).
template <class I, class P>
bool has_user_properties(const Mobius_mesh<P>& mesh)
{
  for (const std::string& name : mesh.template properties<I>())
    if (name != "v:point")
      return true;
  return false;
}
template <class SI, class Q>
bool has_user_properties(const CGAL::Surface_mesh<Q>& sm)
{
  for (const std::string& name : sm.template properties<SI>())
    if (!is_surface_mesh_internal_property<Q>(name))
      return true;
  return false;
}

// Mobius_mesh -> Surface_mesh properties of kind `I` (Mobius index type) / `SI`
// (Surface_mesh index type): `pairs` lists (Mobius element, Surface_mesh element).
template <class I, class SI, class P, class Q>
void properties_to_surface_mesh(const Mobius_mesh<P>& src, CGAL::Surface_mesh<Q>& dst,
                                const std::vector<std::pair<I, SI>>& pairs)
{
  for (const std::string& name : src.template properties<I>()) {
    if (name == "v:point" || is_surface_mesh_internal_property<Q>(name))
      continue;
    for_each_transferable_type<P, Q>([&](auto tag) {
      using T = typename decltype(tag)::type;
      const auto from = src.template property_map<I, T>(name);
      if (!from)
        return;
      auto to = dst.template add_property_map<SI, T>(name, from->array()->default_value()).first;
      for (const auto& [i, si] : pairs)
        to[si] = (*from)[i];
    });
  }
}

// A defined default value: CGAL's default points and vectors of a
// floating-point kernel hold uninitialized coordinates.
template <class T>
T initialized_value()
{
  if constexpr (std::is_constructible_v<T, CGAL::Origin>)
    return T(CGAL::ORIGIN);
  else if constexpr (std::is_constructible_v<T, CGAL::Null_vector>)
    return T(CGAL::NULL_VECTOR);
  else
    return T();
}

// Surface_mesh -> Mobius_mesh properties; `pairs` lists (Surface_mesh element, Mobius element).
template <class SI, class I, class Q, class P>
void properties_from_surface_mesh(const CGAL::Surface_mesh<Q>& src, Mobius_mesh<P>& dst,
                                  const std::vector<std::pair<SI, I>>& pairs)
{
  for (const std::string& name : src.template properties<SI>()) {
    if (is_surface_mesh_internal_property<Q>(name))
      continue;
    for_each_transferable_type<Q, P>([&](auto tag) {
      using T = typename decltype(tag)::type;
      const auto [from, found] = src.template property_map<SI, T>(name);
      if (!found)
        return;
      auto to = dst.template add_property_map<I, T>(name, initialized_value<T>()).first;
      if (!to)
        return;
      for (const auto& [si, i] : pairs)
        to[i] = from[si];
    });
  }
}

// The body of to_surface_mesh(), given `oriented`: the connectivity of `mesh`
// with its faces oriented and `mobius_left` Möbius edges left (`mesh` itself
// when it has none).
template <class P, class O, class Q, class NamedParameters>
Conversion_result to_surface_mesh(const Mobius_mesh<P>& mesh, const Mobius_mesh<O>& oriented, std::size_t mobius_left,
                                  CGAL::Surface_mesh<Q>& sm, const NamedParameters& np);

} // namespace internal

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
  // Without Möbius edges the faces are oriented alike already: orient()
  // would reverse none, and the mesh serves as its own oriented copy.
  if (CGAL_ext::number_of_mobius_edges(mesh) == 0)
    return internal::to_surface_mesh(mesh, mesh, 0, sm, np);
  Mobius_mesh<std::uint8_t> oriented; // connectivity only
  internal::copy_connectivity(mesh, oriented);
  const std::size_t mobius_left = CGAL_ext::orient(oriented);
  return internal::to_surface_mesh(mesh, oriented, mobius_left, sm, np);
}

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
  return result;
}

} // namespace internal

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
    properties_from_surface_mesh(sm, part, edge_pairs);
    properties_from_surface_mesh(sm, part, face_pairs);
    return {std::move(halfedge_pairs), std::move(face_pairs)};
  }
};

} // namespace internal

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
