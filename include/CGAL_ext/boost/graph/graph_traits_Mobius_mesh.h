// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mobius_mesh as a model of CGAL's graph concepts (HalfedgeListGraph,
// FaceListGraph, MutableFaceGraph), with darts as halfedge descriptors, so
// that CGAL's algorithms run on it directly. What holds on a mesh with Möbius
// edges, and which algorithms stay exact there, is in doc/graph_traits.md.

#ifndef CGAL_EXT_BOOST_GRAPH_GRAPH_TRAITS_MOBIUS_MESH_H
#define CGAL_EXT_BOOST_GRAPH_GRAPH_TRAITS_MOBIUS_MESH_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Iterator_range.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/transform_iterator.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <utility>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshGraph
/// The edge descriptor: an edge seen from one of its darts. Two descriptors
/// are equal when they name the same edge, whichever dart they hold, and
/// `halfedge(edge(d, g), g) == d` for every dart `d` (as CGAL's `SM_Edge_index`
/// holds a halfedge).
class Dart_edge
{
public:
  /// The type of edge indices.
  using size_type = std::uint32_t;

  /// The null descriptor, or the edge of dart `d`.
  ///@{
  Dart_edge() = default;
  explicit Dart_edge(Dart d) : dart_(d) {}
  ///@}

  /// The dart it holds, the edge it names, that edge's index, and whether it
  /// names one.
  ///@{
  Dart dart() const { return dart_; }
  Edge_index edge() const { return dart_.is_valid() ? Edge_index(idx()) : Edge_index(); }
  size_type idx() const { return internal::dart_encoding::edge_of_dart(dart_.bits()); }
  bool is_valid() const { return dart_.is_valid(); }
  ///@}

  /// Comparisons of the edges named, whichever darts hold them.
  ///@{
  bool operator==(Dart_edge o) const { return edge() == o.edge(); }
  bool operator!=(Dart_edge o) const { return edge() != o.edge(); }
  bool operator<(Dart_edge o) const { return edge() < o.edge(); }
  ///@}

  /// Printing and hashing (by the edge named).
  ///@{
  friend std::ostream& operator<<(std::ostream& os, Dart_edge e) { return os << e.edge() << " on " << e.dart_; }
  friend std::size_t hash_value(Dart_edge e) { return hash_value(e.edge()); }
  ///@}

private:
  Dart dart_;
};

namespace internal {

// The graph's ranges: halfedges as their unflipped darts, edges as edges
// seen from their first halfedge.
struct To_unflipped_dart
{
  Dart operator()(Halfedge_index h) const { return Dart(h, false); }
};
struct To_graph_edge
{
  Dart_edge operator()(Edge_index e) const
  {
    return Dart_edge(Dart(Halfedge_index(dart_encoding::halfedge_of_edge(e.idx(), 0)), false));
  }
};

} // namespace internal
} // namespace CGAL_ext

namespace boost {

/// \ingroup PkgMobiusMeshGraph
/// `Mobius_mesh` as a model of CGAL's `HalfedgeListGraph`, `FaceListGraph`
/// and `MutableFaceGraph`: vertices and faces by index, halfedges as darts
/// (each halfedge yielded once, unflipped, by `halfedges(g)`), edges as
/// `Dart_edge`. What holds on a mesh with Möbius edges: doc/graph_traits.md.
template <class P>
struct graph_traits<CGAL_ext::Mobius_mesh<P>>
{
private:
  using Mesh = CGAL_ext::Mobius_mesh<P>;
  struct Traversal_category : public virtual boost::bidirectional_graph_tag,
                              public virtual boost::vertex_list_graph_tag,
                              public virtual boost::edge_list_graph_tag,
                              public virtual boost::adjacency_graph_tag
  {};

public:
  /// The types and functions the concepts ask for.
  ///@{
  using vertex_descriptor = CGAL_ext::Vertex_index;
  using halfedge_descriptor = CGAL_ext::Dart;
  using edge_descriptor = CGAL_ext::Dart_edge;
  using face_descriptor = CGAL_ext::Face_index;
  using vertex_property_type = P;

  using directed_category = boost::undirected_tag;
  using edge_parallel_category = boost::disallow_parallel_edge_tag;
  using traversal_category = Traversal_category;

  using vertex_iterator = CGAL_ext::internal::Index_iterator<CGAL_ext::Vertex_index>;
  using halfedge_iterator =
    boost::transform_iterator<CGAL_ext::internal::To_unflipped_dart,
                              CGAL_ext::internal::Index_iterator<CGAL_ext::Halfedge_index>>;
  using edge_iterator =
    boost::transform_iterator<CGAL_ext::internal::To_graph_edge,
                              CGAL_ext::internal::Index_iterator<CGAL_ext::Edge_index>>;
  using face_iterator = CGAL_ext::internal::Index_iterator<CGAL_ext::Face_index>;

  using vertices_size_type = typename Mesh::size_type;
  using halfedges_size_type = typename Mesh::size_type;
  using edges_size_type = typename Mesh::size_type;
  using faces_size_type = typename Mesh::size_type;
  using degree_size_type = typename Mesh::size_type;

  using in_edge_iterator = CGAL::In_edge_iterator<Mesh>;
  using out_edge_iterator = CGAL::Out_edge_iterator<Mesh>;
  using adjacency_iterator = CGAL::Vertex_around_target_iterator<Mesh>;

  static vertex_descriptor null_vertex() { return vertex_descriptor(); }
  static halfedge_descriptor null_halfedge() { return halfedge_descriptor(); }
  static face_descriptor null_face() { return face_descriptor(); }
  ///@}
};

/// The same for a const mesh.
template <class P>
struct graph_traits<const CGAL_ext::Mobius_mesh<P>> : graph_traits<CGAL_ext::Mobius_mesh<P>>
{};

} // namespace boost

namespace CGAL_ext {

// The free functions of CGAL's HalfedgeListGraph, FaceListGraph and
// MutableFaceGraph concepts, documented by the concepts themselves (see
// doc/graph_traits.md), as CGAL documents those of Surface_mesh.
/// \cond

// ============================================================================
// HalfedgeGraph and FaceGraph: the dart operations
// ============================================================================

template <class P>
Vertex_index target(Dart d, const Mobius_mesh<P>& m) { return m.target(d); }
template <class P>
Vertex_index source(Dart d, const Mobius_mesh<P>& m) { return m.source(d); }
template <class P>
Dart next(Dart d, const Mobius_mesh<P>& m) { return m.next(d); }
template <class P>
Dart prev(Dart d, const Mobius_mesh<P>& m) { return m.prev(d); }
template <class P>
Dart opposite(Dart d, const Mobius_mesh<P>& m) { return m.opposite(d); }
template <class P>
Face_index face(Dart d, const Mobius_mesh<P>& m) { return m.face(d); }
template <class P>
Dart_edge edge(Dart d, const Mobius_mesh<P>&) { return Dart_edge(d); }
template <class P>
Dart halfedge(Dart_edge e, const Mobius_mesh<P>&) { return e.dart(); }
template <class P>
Dart halfedge(Face_index f, const Mobius_mesh<P>& m) { return m.halfedge(f); }
template <class P>
Vertex_index source(Dart_edge e, const Mobius_mesh<P>& m) { return m.source(e.dart()); }
template <class P>
Vertex_index target(Dart_edge e, const Mobius_mesh<P>& m) { return m.target(e.dart()); }

/// An incoming dart of `v`, a border dart if `v` is on the border. The mesh
/// may store a flipped dart (after `reverse_face_orientation()`), and a walk
/// from it would visit mirror darts that the graph's ranges never yield; it
/// is replaced by the unflipped dart into `v` across its edge (or before it
/// on the border) when that one is unflipped, which is always the case on a
/// mesh without Möbius edges.
template <class P>
Dart halfedge(Vertex_index v, const Mobius_mesh<P>& m)
{
  const Dart d = m.halfedge(v);
  if (!d.is_valid() || !d.is_flipped())
    return d;
  // The mirror of `d` leaves `v`; the unflipped dart into `v` before it in
  // the same face (or border loop) or across its edge is the one we want.
  const Dart mirror = d.flipped();
  const Dart candidate = m.is_border(d) ? m.prev(mirror) : m.opposite(mirror);
  return candidate.is_flipped() || m.is_border(candidate) != m.is_border(d) ? d : candidate;
}

/// The dart from `u` to `v`, if they are adjacent.
template <class P>
std::pair<Dart, bool> halfedge(Vertex_index u, Vertex_index v, const Mobius_mesh<P>& m)
{
  if (!m.is_isolated(v))
    for (Dart d : CGAL_ext::halfedges_around_target(CGAL_ext::halfedge(v, m), m))
      if (m.source(d) == u)
        return {d, true};
  return {Dart(), false};
}
template <class P>
std::pair<Dart_edge, bool> edge(Vertex_index u, Vertex_index v, const Mobius_mesh<P>& m)
{
  const auto [d, found] = CGAL_ext::halfedge(u, v, m);
  return {Dart_edge(d), found};
}

template <class P>
typename Mobius_mesh<P>::size_type degree(Vertex_index v, const Mobius_mesh<P>& m) { return m.degree(v); }
template <class P>
typename Mobius_mesh<P>::size_type degree(Face_index f, const Mobius_mesh<P>& m) { return m.degree(f); }
template <class P>
typename Mobius_mesh<P>::size_type out_degree(Vertex_index v, const Mobius_mesh<P>& m) { return m.degree(v); }
template <class P>
typename Mobius_mesh<P>::size_type in_degree(Vertex_index v, const Mobius_mesh<P>& m) { return m.degree(v); }

// ============================================================================
// The list concepts: ranges skip removed elements, num_*() count the slots
// (as for Surface_mesh). num_halfedges() is the halfedge slots, as for
// Surface_mesh: the halfedge index map gives both darts of a halfedge that
// halfedge's index, so the slots bound it, and CGAL's own tests and
// algorithms, which compare num_halfedges() with the halfedges they count or
// size per-halfedge arrays with it, see the numbers they expect.
// ============================================================================

template <class P>
auto vertices(const Mobius_mesh<P>& m)
{
  const auto r = m.vertices();
  return CGAL::make_range(r.begin(), r.end());
}
template <class P>
auto halfedges(const Mobius_mesh<P>& m)
{
  const auto r = m.halfedges();
  using It = typename boost::graph_traits<Mobius_mesh<P>>::halfedge_iterator;
  return CGAL::make_range(It(r.begin()), It(r.end()));
}
template <class P>
auto edges(const Mobius_mesh<P>& m)
{
  const auto r = m.edges();
  using It = typename boost::graph_traits<Mobius_mesh<P>>::edge_iterator;
  return CGAL::make_range(It(r.begin()), It(r.end()));
}
template <class P>
auto faces(const Mobius_mesh<P>& m)
{
  const auto r = m.faces();
  return CGAL::make_range(r.begin(), r.end());
}

template <class P>
typename Mobius_mesh<P>::size_type num_vertices(const Mobius_mesh<P>& m) { return m.num_vertices(); }
template <class P>
typename Mobius_mesh<P>::size_type num_halfedges(const Mobius_mesh<P>& m) { return m.num_halfedges(); }
template <class P>
typename Mobius_mesh<P>::size_type num_edges(const Mobius_mesh<P>& m) { return m.num_edges(); }
template <class P>
typename Mobius_mesh<P>::size_type num_faces(const Mobius_mesh<P>& m) { return m.num_faces(); }

namespace internal {
// The range of a CGAL circulator-based iterator around `v`, from halfedge(v).
template <class Iterator, class P>
auto range_around(Vertex_index v, const Mobius_mesh<P>& m)
{
  const Dart h = CGAL_ext::halfedge(v, m);
  return CGAL::make_range(Iterator(h, m), Iterator(h, m, 1));
}
} // namespace internal

template <class P>
auto out_edges(Vertex_index v, const Mobius_mesh<P>& m)
{
  return internal::range_around<CGAL::Out_edge_iterator<Mobius_mesh<P>>>(v, m);
}
template <class P>
auto in_edges(Vertex_index v, const Mobius_mesh<P>& m)
{
  return internal::range_around<CGAL::In_edge_iterator<Mobius_mesh<P>>>(v, m);
}
template <class P>
auto adjacent_vertices(Vertex_index v, const Mobius_mesh<P>& m)
{
  return internal::range_around<CGAL::Vertex_around_target_iterator<Mobius_mesh<P>>>(v, m);
}

// ============================================================================
// MutableHalfedgeGraph and MutableFaceGraph. They build and edit meshes
// without Möbius edges (what CGAL's Euler operations and copy_face_graph()
// produce): a new edge is not Möbius, and the links are set on darts.
// ============================================================================

template <class P>
Vertex_index add_vertex(Mobius_mesh<P>& m) { return m.add_vertex(); }
template <class P>
Vertex_index add_vertex(const P& p, Mobius_mesh<P>& m) { return m.add_vertex(p); }
template <class P>
void remove_vertex(Vertex_index v, Mobius_mesh<P>& m) { m.remove_vertex(v); }

/// A new edge with two unlinked halfedges; the descriptor's dart is the first.
template <class P>
Dart_edge add_edge(Mobius_mesh<P>& m)
{
  const Edge_index e = m.add_edge(Vertex_index(), Vertex_index());
  return Dart_edge(Dart(Mobius_mesh<P>::halfedge(e, 0), false));
}
template <class P>
void remove_edge(Dart_edge e, Mobius_mesh<P>& m) { m.remove_edge(e.edge()); }

template <class P>
Face_index add_face(Mobius_mesh<P>& m) { return m.add_face_record(); }
template <class P>
void remove_face(Face_index f, Mobius_mesh<P>& m) { m.remove_face(f); }

template <class P>
void set_next(Dart a, Dart b, Mobius_mesh<P>& m) { m.set_next(a, b); }

/// Sets the target of an unflipped dart. The target of a flipped dart is the
/// target of another halfedge, so setting it is refused.
template <class P>
void set_target(Dart d, Vertex_index v, Mobius_mesh<P>& m)
{
  if (d.is_flipped())
    throw Parameter_error("set_target(): dart " + std::to_string(d.halfedge().idx()) +
                          "~ is flipped; the target of a flipped dart is set through its halfedge's partner");
  m.set_target(d.halfedge(), v);
}
/// Sets the face of `d`'s halfedge and nothing else, as CGAL's
/// `MutableFaceGraph` requires (a null face makes it a border halfedge). A
/// vertex whose stored dart is then no longer a border dart stays valid:
/// `is_border(v)` looks at every dart around `v`, as `Surface_mesh` does.
template <class P>
void set_face(Dart d, Face_index f, Mobius_mesh<P>& m)
{
  m.set_face(d.halfedge(), f);
}
template <class P>
void set_halfedge(Vertex_index v, Dart d, Mobius_mesh<P>& m) { m.set_halfedge(v, d); }
/// A face keeps a halfedge; its orientation is that of its cycle.
template <class P>
void set_halfedge(Face_index f, Dart d, Mobius_mesh<P>& m) { m.set_halfedge(f, d.halfedge()); }

template <class P>
void reserve(Mobius_mesh<P>& m, typename Mobius_mesh<P>::size_type nv, typename Mobius_mesh<P>::size_type ne,
             typename Mobius_mesh<P>::size_type nf)
{
  m.reserve(nv, ne, nf);
}
template <class P>
void collect_garbage(Mobius_mesh<P>& m) { m.collect_garbage(); }

/// \endcond

// ============================================================================
// Orientation guard
// ============================================================================

/// True if some edge of `mesh` is a Möbius edge: the darts of its faces do
/// not all run along one global orientation.
template <class P>
bool has_mobius_edges(const Mobius_mesh<P>& mesh)
{
  for (Edge_index e : mesh.edges())
    if (mesh.is_mobius(e))
      return true;
  return false;
}

/// Throws `Parameter_error` if `mesh` has Möbius edges: guards a call of a
/// CGAL algorithm that needs a globally oriented mesh (normals, volumes,
/// inside tests, remeshing, simplification, CGAL's Euler operations; see
/// doc/graph_traits.md). `what` names the algorithm in the message.
template <class P>
void require_orientable_model(const Mobius_mesh<P>& mesh, const std::string& what)
{
  if (!has_mobius_edges(mesh))
    return;
  const std::size_t n = number_of_mobius_edges(mesh);
  throw Parameter_error(what + ": the mesh has " + std::to_string(n) + " Möbius edge" + (n == 1 ? "" : "s") +
                        ", so CGAL would see no global orientation; call CGAL_ext::orient() first" +
                        (is_orientable(mesh) ? "" : " (this mesh is non-orientable: no orientation exists)"));
}

} // namespace CGAL_ext

namespace CGAL {

/// `CGAL::copy_face_graph()` from a `Mobius_mesh`: CGAL's copy maps each
/// halfedge of the source to one of the target, which needs one global
/// orientation; a mesh with Möbius edges is refused with
/// `CGAL_ext::Parameter_error` before anything is copied (CGAL's generic copy
/// would build a broken target). Without Möbius edges it is CGAL's copy.
template <class P, class TargetMesh, class NamedParameters1 = parameters::Default_named_parameters,
          class NamedParameters2 = parameters::Default_named_parameters>
void copy_face_graph(const CGAL_ext::Mobius_mesh<P>& sm, TargetMesh& tm,
                     const NamedParameters1& np1 = parameters::default_values(),
                     const NamedParameters2& np2 = parameters::default_values())
{
  CGAL_ext::require_orientable_model(sm, "CGAL::copy_face_graph()");
  // Explicit template arguments leave only CGAL's generic overload viable.
  CGAL::copy_face_graph<CGAL_ext::Mobius_mesh<P>, TargetMesh, NamedParameters1, NamedParameters2>(sm, tm, np1, np2);
}

} // namespace CGAL

// The graph functions are found by argument-dependent lookup, but some of
// CGAL's generic code calls them qualified, as `CGAL::halfedges(tm)`
// (`CGAL::Seam_mesh` does, and finds those of Surface_mesh and Polyhedron_3,
// which CGAL defines in its own namespace): the same functions, named in
// namespace CGAL as well.
/// \cond
namespace CGAL {
using CGAL_ext::target;
using CGAL_ext::source;
using CGAL_ext::next;
using CGAL_ext::prev;
using CGAL_ext::opposite;
using CGAL_ext::face;
using CGAL_ext::edge;
using CGAL_ext::halfedge;
using CGAL_ext::vertices;
using CGAL_ext::halfedges;
using CGAL_ext::edges;
using CGAL_ext::faces;
using CGAL_ext::num_vertices;
using CGAL_ext::num_halfedges;
using CGAL_ext::num_edges;
using CGAL_ext::num_faces;
using CGAL_ext::degree;
using CGAL_ext::out_degree;
using CGAL_ext::in_degree;
using CGAL_ext::out_edges;
using CGAL_ext::in_edges;
using CGAL_ext::adjacent_vertices;
} // namespace CGAL
/// \endcond

namespace std {
/// Hashes an edge descriptor by the edge it names.
template <>
struct hash<CGAL_ext::Dart_edge>
{
  /// The hash of `e`.
  std::size_t operator()(CGAL_ext::Dart_edge e) const { return hash_value(e); }
};
} // namespace std

#include <CGAL_ext/boost/graph/properties_Mobius_mesh.h>

#endif // CGAL_EXT_BOOST_GRAPH_GRAPH_TRAITS_MOBIUS_MESH_H
