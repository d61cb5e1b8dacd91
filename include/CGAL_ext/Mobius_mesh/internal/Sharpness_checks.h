// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The checks of sharpness values: a sharpness is a number of levels, and NaN
// or a negative value is refused wherever one is read, naming its element.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_SHARPNESS_CHECKS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_SHARPNESS_CHECKS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Sharp_feature_options.h>
#include <CGAL_ext/exceptions.h>

#include <cstddef>
#include <string>

namespace CGAL_ext {
namespace internal {

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
void require_valid_edge_sharpness(const Mobius_mesh<P>& mesh, const Sharpness& sharpness_of,
                                  const std::string& function)
{
  for (Edge_index e : mesh.edges())
    if (const double s = sharpness_of(e); !is_valid_sharpness(s))
      throw invalid_sharpness(function, "edge e", e.idx(), s);
}

// The same for the mesh's own "e:sharpness", if it has one.
template <class P>
void require_valid_edge_sharpness(const Mobius_mesh<P>& mesh, const std::string& function)
{
  if (const auto own = mesh.template property_map<Edge_index, float>(edge_sharpness_name))
    require_valid_edge_sharpness(mesh, [&](Edge_index e) { return (*own)[e]; }, function);
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_SHARPNESS_CHECKS_H
