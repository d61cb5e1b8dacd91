// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/Mobius_mesh/transform.h>: copying, appending and transforming meshes with their properties.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_MESH_COPY_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_MESH_COPY_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/internal/Parallel_loops.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/tags.h>
#include <boost/property_map/property_map.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Copies every property map of element kind `I` (but the points, and the
// map named `skip`) from `src` to `dst`, whatever its value type: element
// `i` of `dst` in [begin, end) takes the value of `src_of(i)` (skipped where
// that is invalid). A map of `dst` with the same name and another value type
// is left alone. Under `CGAL::Parallel_tag` the elements are copied in
// blocks by several threads (`src_of` is then called from several threads).
template <class I, class ConcurrencyTag = CGAL::Sequential_tag, class P1, class P2, class SrcOf>
void transfer_properties(const Mobius_mesh<P1>& src, Mobius_mesh<P2>& dst, std::size_t begin, std::size_t end,
                         SrcOf src_of, const std::string& skip = std::string())
{
  const Property_container& from = Connectivity_access::properties<I>(src);
  Property_container& to = Connectivity_access::properties<I>(dst);
  const std::uint32_t n = begin < end ? std::uint32_t(end - begin) : 0u;
  std::vector<std::uint32_t> source_of;
  for (const auto& array : from.arrays()) {
    if (array->name() == "v:point" || array->name() == skip)
      continue;
    if (source_of.empty() && n > 0) { // the correspondence, once for all maps of this kind
      source_of.resize(n);
      for_each_index<ConcurrencyTag>(n, [&](std::uint32_t i) {
        const I s = src_of(I(typename I::size_type(begin + i)));
        source_of[i] = s.is_valid() ? std::uint32_t(s.idx()) : Transfer_sources::no_source;
      });
    }
    Base_property_array* target = to.add_like(*array);
    if (!target)
      continue;
    for_each_block<ConcurrencyTag>(n, [&](std::uint32_t block_begin, std::uint32_t block_end) {
      target->transfer(*array, Transfer_sources{begin, source_of, block_begin, block_end});
    });
  }
}

// Converts points between kernels; the identity when the types agree. Also
// a readable property map from `P1` to `P2`, to feed soups of other points.
template <class P1, class P2>
struct Point_converter
{
  using key_type = P1;
  using value_type = P2;
  using reference = P2;
  using category = boost::readable_property_map_tag;

  P2 operator()(const P1& p) const
  {
    if constexpr (std::is_same_v<P1, P2>)
      return p;
    else {
      using K1 = typename CGAL::Kernel_traits<P1>::Kernel;
      using K2 = typename CGAL::Kernel_traits<P2>::Kernel;
      return CGAL::Cartesian_converter<K1, K2>()(p);
    }
  }
  friend P2 get(const Point_converter& c, const P1& p) { return c(p); }
};

// Copies the connectivity of `src` into the empty mesh `dst` (points are
// left default); indices are kept, removed elements stay removed.
template <class P1, class P2>
void copy_connectivity(const Mobius_mesh<P1>& src, Mobius_mesh<P2>& dst)
{
  dst.resize(src.num_vertices(), src.num_edges(), src.num_faces());
  for (std::uint32_t i = 0; i < src.num_vertices(); ++i)
    if (src.is_removed(Vertex_index(i)))
      dst.remove_vertex(Vertex_index(i));
  for (std::uint32_t i = 0; i < src.num_edges(); ++i)
    if (src.is_removed(Edge_index(i)))
      dst.remove_edge(Edge_index(i));
  for (std::uint32_t i = 0; i < src.num_faces(); ++i)
    if (src.is_removed(Face_index(i)))
      dst.remove_face(Face_index(i));
  for (Halfedge_index h : src.halfedges()) {
    const Dart d(h, false);
    dst.set_target(h, src.target(d));
    dst.set_face(h, src.face(h));
    // A link a -> b stores one half at a and one at b; setting the links out
    // of and into every unflipped dart sets every stored half.
    dst.set_next(d, src.next(d));
    dst.set_next(src.prev(d), d);
  }
  for (Edge_index e : src.edges())
    dst.set_mobius(e, src.is_mobius(e));
  for (Vertex_index v : src.vertices())
    dst.set_halfedge(v, src.halfedge(v));
  for (Face_index f : src.faces())
    dst.set_halfedge(f, src.halfedge(f).halfedge());
}

// True if `m` is as default-constructed: no elements, no property map but the points.
template <class P>
bool is_pristine(const Mobius_mesh<P>& m)
{
  return m.number_of_vertices() == 0 && m.number_of_edges() == 0 && m.number_of_faces() == 0 &&
         m.template properties<Vertex_index>().size() == 1 && m.template properties<Halfedge_index>().empty() &&
         m.template properties<Edge_index>().empty() && m.template properties<Face_index>().empty();
}

// Appends `part` to `dst`: moved in if `dst` is pristine, joined otherwise.
template <class P>
typename Mobius_mesh<P>::Join_offsets append_mesh(Mobius_mesh<P>& dst, Mobius_mesh<P>&& part)
{
  if (is_pristine(dst)) {
    dst = std::move(part);
    return {0, 0, 0};
  }
  return dst.join(part);
}

// True if the named parameter `Tag` is given in `NP`.
template <class NP, class Tag>
constexpr bool has_output(Tag)
{
  using Value = std::decay_t<decltype(parameters::get_parameter(std::declval<const NP&>(), std::declval<Tag>()))>;
  return !std::is_same_v<Value, CGAL::internal_np::Param_not_found>;
}

// Emits pairs through the named output iterator `tag` (it is taken by value
// from `np` once, so that successive writes advance the same iterator).
template <class NP, class Tag, class Emit>
void write_pairs(const NP& np, Tag tag, Emit emit)
{
  auto it = parameters::get_parameter(np, tag);
  if constexpr (!std::is_same_v<std::decay_t<decltype(it)>, CGAL::internal_np::Param_not_found>)
    emit([&it](const auto& pair) { *it++ = pair; });
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_MESH_COPY_H
