// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The sharpness an algorithm reads, and the checks of its values: a sharpness
// is a number of levels, and NaN or a negative value is refused wherever one
// is read, naming its element.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_SHARPNESS_CHECKS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_SHARPNESS_CHECKS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_feature_options.h>
#include <CGAL_ext/exceptions.h>

#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>

namespace CGAL_ext {
namespace internal {

// The sharpness of an element as an algorithm reads it: a map's value, or 0
// where there is no map. `has_map()` says whether there is one, for the
// algorithms that skip sharpness altogether without it.
template <class Key, class Map>
class Sharpness_of
{
public:
  explicit Sharpness_of(std::optional<Map> map) : map_(std::move(map)) {}
  bool has_map() const { return map_.has_value(); }
  float operator()(Key k) const { return map_ ? float(get(*map_, k)) : 0.0f; }

private:
  std::optional<Map> map_;
};

// The one rule of every algorithm that reads sharpness: the map given as the
// named parameter `Tag`, else the mesh's own map `name`, else none (all 0).
template <class Key, class Tag, class P, class NP>
auto sharpness_of(const Mobius_mesh<P>& mesh, const NP& np, Tag tag, const char* name)
{
  namespace pm = CGAL_ext::parameters;
  if constexpr (!pm::is_default_parameter<NP, Tag>::value) {
    const auto given = pm::get_parameter(np, tag);
    return Sharpness_of<Key, std::decay_t<decltype(given)>>(given);
  } else {
    using Own = typename Mobius_mesh<P>::template Property_map<Key, float>;
    return Sharpness_of<Key, Own>(mesh.template property_map<Key, float>(name));
  }
}

// The border rule, the crease method and the triangle rule that `np` asks
// for, OpenSubdiv's defaults (edge_only, uniform, catmark) where it does
// not: the one place of these defaults for subdivision, limits and the
// limit surface.
template <class NP>
Boundary_interpolation boundary_interpolation_of(const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  return pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::boundary_interpolation),
                              Boundary_interpolation::edge_only);
}

template <class NP>
Crease_method crease_method_of(const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  return pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::crease_method), Crease_method::uniform);
}

template <class NP>
Triangle_subdivision triangle_subdivision_of(const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  return pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::triangle_subdivision),
                              Triangle_subdivision::catmark);
}

// The edge sharpness that `np` and `mesh` give (named parameter
// `edge_sharpness_map`, else the mesh's "e:sharpness").
template <class P, class NP>
auto edge_sharpness_of(const Mobius_mesh<P>& mesh, const NP& np)
{
  return sharpness_of<Edge_index>(mesh, np, CGAL_ext::internal_np::edge_sharpness, edge_sharpness_name);
}

// The vertex sharpness that `np` and `mesh` give (named parameter
// `vertex_sharpness_map`, else the mesh's "v:sharpness").
template <class P, class NP>
auto vertex_sharpness_of(const Mobius_mesh<P>& mesh, const NP& np)
{
  return sharpness_of<Vertex_index>(mesh, np, CGAL_ext::internal_np::vertex_sharpness, vertex_sharpness_name);
}

// A sharpness is a number of levels: NaN or negative means nothing, and is
// refused wherever a sharpness is read, with the element it belongs to.
inline bool is_valid_sharpness(double s) { return s >= 0; }

// `element` names the element, as in "edge e" or "vertex v", before its index.
inline Parameter_error invalid_sharpness(const std::string& function, const char* element, std::size_t index,
                                         double value)
{
  return Parameter_error(function + ": the sharpness of " + element + std::to_string(index) + " is " +
                         std::to_string(value) + " (NaN or negative; 0 is smooth)");
}

// Refuses the first edge of `mesh` whose sharpness, `sharpness_of(e)`, is
// NaN or negative.
template <class P, class Sharpness>
void require_valid_edge_sharpness_values(const Mobius_mesh<P>& mesh, const Sharpness& sharpness_of,
                                         const std::string& function)
{
  for (Edge_index e : mesh.edges())
    if (const double s = sharpness_of(e); !is_valid_sharpness(s))
      throw invalid_sharpness(function, "edge e", e.idx(), s);
}

// The same for the edge sharpness that `np` and `mesh` give, if any.
template <class P, class NP>
void require_valid_edge_sharpness(const Mobius_mesh<P>& mesh, const NP& np, const std::string& function)
{
  if (const auto sharpness = edge_sharpness_of(mesh, np); sharpness.has_map())
    require_valid_edge_sharpness_values(mesh, sharpness, function);
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_SHARPNESS_CHECKS_H
