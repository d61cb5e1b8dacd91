// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/boost/graph/properties_Mobius_mesh.h>: the index maps,
// the maps of darts and edges, and the dynamic maps kept in the mesh's own
// property arrays (so that they grow with the elements that CGAL's Euler
// operations add). It is included through that header, after
// graph_traits_Mobius_mesh.h (which defines Dart_edge and includes that header last).

#ifndef CGAL_EXT_BOOST_GRAPH_INTERNAL_PROPERTY_MAPS_H
#define CGAL_EXT_BOOST_GRAPH_INTERNAL_PROPERTY_MAPS_H

#include <CGAL_ext/Mobius_mesh.h>

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
namespace internal {

// The index of a descriptor in the vectors of the dynamic maps of a const
// mesh: a dart's is its bits, so the two darts of a halfedge have two cells
// (those vectors have two per halfedge). The halfedge index map that CGAL's
// algorithms see is numbered otherwise: below.
inline std::uint32_t graph_index(Vertex_index v) { return v.idx(); }
inline std::uint32_t graph_index(Face_index f) { return f.idx(); }
inline std::uint32_t graph_index(Dart d) { return d.bits(); }
inline std::uint32_t graph_index(Dart_edge e) { return e.idx(); }

template <class Key>
struct Graph_index_map
{
  using key_type = Key;
  using value_type = std::uint32_t;
  using reference = std::uint32_t;
  using category = boost::readable_property_map_tag;

  value_type operator[](Key k) const { return graph_index(k); }
  friend value_type get(Graph_index_map, Key k) { return graph_index(k); }
};

// The halfedge index CGAL's algorithms see: the index of the dart's halfedge,
// for both darts of it. So, as in Surface_mesh, the two halfedges of edge e
// are 2e and 2e + 1 (Surface_mesh_simplification takes index / 2 as the
// edge's index), and the indices stay below num_halfedges(g), the halfedge
// slots, which CGAL's tests compare with the halfedges they count. The map is
// one-to-one over `halfedges(g)`, which yields each halfedge once; what must
// tell the two darts apart uses the dynamic halfedge maps, one value per dart.
template <>
struct Graph_index_map<Dart>
{
  using key_type = Dart;
  using value_type = std::uint32_t;
  using reference = std::uint32_t;
  using category = boost::readable_property_map_tag;

  value_type operator[](Dart d) const { return d.halfedge().idx(); }
  friend value_type get(const Graph_index_map& map, Dart d) { return map[d]; }
};

// A dart property kept in the mesh's halfedge arrays: one pair of values per
// halfedge, the unflipped dart's first.
template <class T>
class Dart_property_map
{
public:
  using key_type = Dart;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;
  using Base = Property_map<Halfedge_index, std::array<T, 2>>;

  Dart_property_map() = default;
  explicit Dart_property_map(Base base) : base_(base) {}

  reference operator[](Dart d) const { return base_[d.halfedge()][d.is_flipped() ? 1 : 0]; }
  friend reference get(const Dart_property_map& m, Dart d) { return m[d]; }
  friend void put(const Dart_property_map& m, Dart d, const T& v) { m[d] = v; }
  Base base() const { return base_; }

private:
  Base base_;
};

// An edge property kept in the mesh's edge arrays, keyed by edge descriptors.
template <class T>
class Dart_edge_property_map
{
public:
  using key_type = Dart_edge;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;
  using Base = Property_map<Edge_index, T>;

  Dart_edge_property_map() = default;
  explicit Dart_edge_property_map(Base base) : base_(base) {}

  reference operator[](Dart_edge e) const { return base_[e.edge()]; }
  friend reference get(const Dart_edge_property_map& m, Dart_edge e) { return m[e]; }
  friend void put(const Dart_edge_property_map& m, Dart_edge e, const T& v) { m[e] = v; }
  Base base() const { return base_; }

private:
  Base base_;
};

// What a dynamic property of a const mesh uses: a vector beside the mesh,
// sized by the `num_*()` of the moment (the mesh cannot grow meanwhile).
template <class Key, class T>
class Vector_property_map
{
public:
  using key_type = Key;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;

  Vector_property_map() = default;
  explicit Vector_property_map(std::size_t n) : values_(std::make_shared<std::vector<Stored_value<T>>>(n, T())) {}

  reference operator[](Key k) const
  {
    auto& cell = (*values_)[graph_index(k)];
    if constexpr (std::is_same_v<T, bool>)
      return cell.value;
    else
      return cell;
  }
  friend reference get(const Vector_property_map& m, Key k) { return m[k]; }
  friend void put(const Vector_property_map& m, Key k, const T& v) { m[k] = v; }

private:
  std::shared_ptr<std::vector<Stored_value<T>>> values_;
};

// An unnamed property array of element kind `I`: a fresh name each time, as
// the mesh's maps are found by name.
template <class I, class T, class P>
Property_map<I, T> add_unnamed_property_map(Mobius_mesh<P>& m)
{
  for (std::size_t k = 0;; ++k) {
    auto [map, created] = m.template add_property_map<I, T>("dynamic:" + std::to_string(k), T());
    if (created)
      return map;
  }
}

// Called by CGAL's dynamic map deleter when the last copy of a map goes.
template <class I, class T, class P>
void remove_property(Property_map<I, T> map, Mobius_mesh<P>& m)
{
  m.remove_property_map(map);
}
template <class T, class P>
void remove_property(Dart_property_map<T> map, Mobius_mesh<P>& m)
{
  auto base = map.base();
  m.remove_property_map(base);
}
template <class T, class P>
void remove_property(Dart_edge_property_map<T> map, Mobius_mesh<P>& m)
{
  auto base = map.base();
  m.remove_property_map(base);
}

// The edge_weight map: an edge's length, as Surface_mesh and Polyhedron_3
// give (Boost's shortest paths and CGAL's concept checks read it).
template <class P>
class Edge_length_map
{
public:
  using key_type = Dart_edge;
  using value_type = typename CGAL::Kernel_traits<P>::Kernel::FT;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  Edge_length_map() = default;
  explicit Edge_length_map(const Mobius_mesh<P>& m) : m_(&m) {}

  value_type operator[](Dart_edge e) const
  {
    return CGAL::approximate_sqrt(CGAL::squared_distance(m_->point(m_->source(e.dart())), m_->point(m_->target(e.dart()))));
  }
  friend value_type get(const Edge_length_map& m, Dart_edge e) { return m[e]; }

private:
  const Mobius_mesh<P>* m_ = nullptr;
};

// The maps behind CGAL's dynamic property tags, by element kind.
template <class P, class T>
struct Dynamic_maps
{
  using Mesh = Mobius_mesh<P>;
  using Vertex = CGAL::internal::Dynamic<Mesh, Property_map<Vertex_index, T>>;
  using Halfedge = CGAL::internal::Dynamic<Mesh, Dart_property_map<T>>;
  using Edge = CGAL::internal::Dynamic<Mesh, Dart_edge_property_map<T>>;
  using Face = CGAL::internal::Dynamic<Mesh, Property_map<Face_index, T>>;
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_BOOST_GRAPH_INTERNAL_PROPERTY_MAPS_H
