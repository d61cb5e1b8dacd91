// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The internal property maps of Mobius_mesh as a CGAL graph: points, the
// four index maps, and dynamic maps kept in the mesh's own property arrays
// (so that they grow with the elements that CGAL's Euler operations add).

#ifndef CGAL_EXT_BOOST_GRAPH_PROPERTIES_MOBIUS_MESH_H
#define CGAL_EXT_BOOST_GRAPH_PROPERTIES_MOBIUS_MESH_H

#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>
#include <CGAL_ext/boost/graph/internal/Property_maps.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
} // namespace CGAL_ext

// The property maps of CGAL's graph concepts (vertex_point, the four index
// maps, the four dynamic property tags), documented by the concepts and in
// doc/graph_traits.md, as CGAL documents those of Surface_mesh.
/// \cond
namespace boost {

template <class P>
struct property_map<CGAL_ext::Mobius_mesh<P>, CGAL::vertex_point_t>
{
  using type = CGAL_ext::internal::Property_map<CGAL_ext::Vertex_index, P>;
  using const_type = type;
};

#define CGAL_EXT_INDEX_PROPERTY_MAP(TAG, KEY)                                                                  \
  template <class P>                                                                                           \
  struct property_map<CGAL_ext::Mobius_mesh<P>, TAG>                                                           \
  {                                                                                                            \
    using type = CGAL_ext::internal::Graph_index_map<KEY>;                                                     \
    using const_type = type;                                                                                   \
  };
CGAL_EXT_INDEX_PROPERTY_MAP(boost::vertex_index_t, CGAL_ext::Vertex_index)
CGAL_EXT_INDEX_PROPERTY_MAP(boost::halfedge_index_t, CGAL_ext::Dart)
CGAL_EXT_INDEX_PROPERTY_MAP(boost::edge_index_t, CGAL_ext::Dart_edge)
CGAL_EXT_INDEX_PROPERTY_MAP(boost::face_index_t, CGAL_ext::Face_index)
#undef CGAL_EXT_INDEX_PROPERTY_MAP

template <class P>
struct property_map<CGAL_ext::Mobius_mesh<P>, boost::edge_weight_t>
{
  using type = CGAL_ext::internal::Edge_length_map<P>;
  using const_type = type;
};

template <class P, class T>
struct property_map<CGAL_ext::Mobius_mesh<P>, CGAL::dynamic_vertex_property_t<T>>
{
  using type = typename CGAL_ext::internal::Dynamic_maps<P, T>::Vertex;
  using const_type = CGAL_ext::internal::Vector_property_map<CGAL_ext::Vertex_index, T>;
};
template <class P, class T>
struct property_map<CGAL_ext::Mobius_mesh<P>, CGAL::dynamic_halfedge_property_t<T>>
{
  using type = typename CGAL_ext::internal::Dynamic_maps<P, T>::Halfedge;
  using const_type = CGAL_ext::internal::Vector_property_map<CGAL_ext::Dart, T>;
};
template <class P, class T>
struct property_map<CGAL_ext::Mobius_mesh<P>, CGAL::dynamic_edge_property_t<T>>
{
  using type = typename CGAL_ext::internal::Dynamic_maps<P, T>::Edge;
  using const_type = CGAL_ext::internal::Vector_property_map<CGAL_ext::Dart_edge, T>;
};
template <class P, class T>
struct property_map<CGAL_ext::Mobius_mesh<P>, CGAL::dynamic_face_property_t<T>>
{
  using type = typename CGAL_ext::internal::Dynamic_maps<P, T>::Face;
  using const_type = CGAL_ext::internal::Vector_property_map<CGAL_ext::Face_index, T>;
};

} // namespace boost

namespace CGAL {

template <class P>
struct graph_has_property<CGAL_ext::Mobius_mesh<P>, boost::vertex_index_t> : CGAL::Tag_true {};
template <class P>
struct graph_has_property<CGAL_ext::Mobius_mesh<P>, boost::halfedge_index_t> : CGAL::Tag_true {};
template <class P>
struct graph_has_property<CGAL_ext::Mobius_mesh<P>, boost::edge_index_t> : CGAL::Tag_true {};
template <class P>
struct graph_has_property<CGAL_ext::Mobius_mesh<P>, boost::face_index_t> : CGAL::Tag_true {};
template <class P>
struct graph_has_property<CGAL_ext::Mobius_mesh<P>, CGAL::vertex_point_t> : CGAL::Tag_true {};

} // namespace CGAL

namespace CGAL_ext {

/// \name Internal property maps of the graph
/// @{
template <class P>
internal::Property_map<Vertex_index, P> get(CGAL::vertex_point_t, const Mobius_mesh<P>& m) { return m.points(); }
template <class P>
internal::Graph_index_map<Vertex_index> get(boost::vertex_index_t, const Mobius_mesh<P>&) { return {}; }
template <class P>
internal::Graph_index_map<Dart> get(boost::halfedge_index_t, const Mobius_mesh<P>&) { return {}; }
template <class P>
internal::Graph_index_map<Dart_edge> get(boost::edge_index_t, const Mobius_mesh<P>&) { return {}; }
template <class P>
internal::Graph_index_map<Face_index> get(boost::face_index_t, const Mobius_mesh<P>&) { return {}; }

template <class P>
internal::Edge_length_map<P> get(boost::edge_weight_t, const Mobius_mesh<P>& m) { return internal::Edge_length_map<P>(m); }
template <class P>
auto get(boost::edge_weight_t, const Mobius_mesh<P>& m, Dart_edge e) { return internal::Edge_length_map<P>(m)[e]; }

template <class P>
const P& get(CGAL::vertex_point_t, const Mobius_mesh<P>& m, Vertex_index v) { return m.point(v); }
template <class P>
void put(CGAL::vertex_point_t, Mobius_mesh<P>& m, Vertex_index v, const P& p) { m.point(v) = p; }
template <class P>
std::uint32_t get(boost::vertex_index_t, const Mobius_mesh<P>&, Vertex_index v) { return v.idx(); }
template <class P>
std::uint32_t get(boost::halfedge_index_t, const Mobius_mesh<P>& m, Dart d) { return get(get(boost::halfedge_index, m), d); }
template <class P>
std::uint32_t get(boost::edge_index_t, const Mobius_mesh<P>&, Dart_edge e) { return e.idx(); }
template <class P>
std::uint32_t get(boost::face_index_t, const Mobius_mesh<P>&, Face_index f) { return f.idx(); }

template <class P, class T>
auto get(CGAL::dynamic_vertex_property_t<T>, Mobius_mesh<P>& m)
{
  using Map = internal::Property_map<Vertex_index, T>;
  return typename internal::Dynamic_maps<P, T>::Vertex(
    m, new Map(internal::add_unnamed_property_map<Vertex_index, T>(m)));
}
template <class P, class T>
auto get(CGAL::dynamic_halfedge_property_t<T>, Mobius_mesh<P>& m)
{
  using Map = internal::Dart_property_map<T>;
  return typename internal::Dynamic_maps<P, T>::Halfedge(
    m, new Map(internal::add_unnamed_property_map<Halfedge_index, std::array<T, 2>>(m)));
}
template <class P, class T>
auto get(CGAL::dynamic_edge_property_t<T>, Mobius_mesh<P>& m)
{
  using Map = internal::Dart_edge_property_map<T>;
  return typename internal::Dynamic_maps<P, T>::Edge(m, new Map(internal::add_unnamed_property_map<Edge_index, T>(m)));
}
template <class P, class T>
auto get(CGAL::dynamic_face_property_t<T>, Mobius_mesh<P>& m)
{
  using Map = internal::Property_map<Face_index, T>;
  return typename internal::Dynamic_maps<P, T>::Face(m, new Map(internal::add_unnamed_property_map<Face_index, T>(m)));
}

template <class P, class T>
auto get(CGAL::dynamic_vertex_property_t<T>, const Mobius_mesh<P>& m)
{
  return internal::Vector_property_map<Vertex_index, T>(num_vertices(m));
}
template <class P, class T>
auto get(CGAL::dynamic_halfedge_property_t<T>, const Mobius_mesh<P>& m)
{
  return internal::Vector_property_map<Dart, T>(2 * std::size_t(m.num_halfedges())); // by dart: two per halfedge
}
template <class P, class T>
auto get(CGAL::dynamic_edge_property_t<T>, const Mobius_mesh<P>& m)
{
  return internal::Vector_property_map<Dart_edge, T>(num_edges(m));
}
template <class P, class T>
auto get(CGAL::dynamic_face_property_t<T>, const Mobius_mesh<P>& m)
{
  return internal::Vector_property_map<Face_index, T>(num_faces(m));
}
/// @}

} // namespace CGAL_ext
/// \endcond

#endif // CGAL_EXT_BOOST_GRAPH_PROPERTIES_MOBIUS_MESH_H
