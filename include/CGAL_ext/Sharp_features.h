// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Sharp features of a mesh, with OpenSubdiv's names and conventions: the
// edge and vertex sharpness maps, and the checks of their values. The
// mesh-level options that OpenSubdiv's OBJ tags carry and every other option
// enum of subdivision are in <CGAL_ext/Sharp_feature_options.h>, included
// here (all in namespace CGAL_ext; `CGAL_ext::Subdivision` names them too).
// Read and written by the OBJ reader and writer, used by subdivision.

#ifndef CGAL_EXT_SHARP_FEATURES_H
#define CGAL_EXT_SHARP_FEATURES_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Sharpness_checks.h>
#include <CGAL_ext/Sharp_feature_options.h>
#include <CGAL_ext/exceptions.h>

#include <optional>
#include <string>

namespace CGAL_ext {

/// The edge sharpness map of `mesh` (created, all 0, if missing).
template <class P>
typename Mobius_mesh<P>::template Property_map<Edge_index, float> edge_sharpness_map(Mobius_mesh<P>& mesh)
{
  return mesh.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first;
}

/// The vertex sharpness map of `mesh` (created, all 0, if missing).
template <class P>
typename Mobius_mesh<P>::template Property_map<Vertex_index, float> vertex_sharpness_map(Mobius_mesh<P>& mesh)
{
  return mesh.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_SHARP_FEATURES_H
