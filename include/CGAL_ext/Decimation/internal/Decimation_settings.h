// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The options of decimate(), read and checked before the mesh is touched:
// the stop conditions, the sharpness it reads, and the feature edges it keeps.

#ifndef CGAL_EXT_DECIMATION_INTERNAL_DECIMATION_SETTINGS_H
#define CGAL_EXT_DECIMATION_INTERNAL_DECIMATION_SETTINGS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace internal {

// The options of decimate(), read and checked before the mesh is touched.
struct Decimation_settings
{
  std::size_t target_faces = 0;                                   // stop at or below this many faces
  double maximum_error = std::numeric_limits<double>::infinity(); // stop when the cheapest collapse costs more
  double min_cos_normal_turn = 0;
  bool protect_borders = false;
  bool relocate_vertices = true;
  double corner_value_weight = 1; // of the corner values' error against the points'
};

template <class NP>
Decimation_settings decimation_settings(std::size_t faces, const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  const char* fn = "decimate: ";
  Decimation_settings s;
  const bool has_count = !pm::is_default_parameter<NP, CGAL_ext::internal_np::number_of_faces_t>::value;
  const bool has_ratio = !pm::is_default_parameter<NP, CGAL_ext::internal_np::face_ratio_t>::value;
  const bool has_error = !pm::is_default_parameter<NP, CGAL_ext::internal_np::maximum_error_t>::value;
  if (!has_count && !has_ratio && !has_error)
    throw Parameter_error(std::string(fn) + "no stop condition: give number_of_faces, face_ratio or maximum_error");
  s.target_faces = 0;
  if (has_count) {
    const double n = double(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::number_of_faces), 0));
    if (!(n >= 0) || !std::isfinite(n))
      throw Parameter_error(std::string(fn) + "number_of_faces must be a finite number >= 0, not " + std::to_string(n));
    // A count past what a size_t holds saturates (and is reached at once)
    // rather than being cast, which would be undefined.
    const double most = double((std::numeric_limits<std::size_t>::max)()); // rounds up to 2^64 (or 2^32)
    s.target_faces = n < most ? std::size_t(n) : (std::numeric_limits<std::size_t>::max)();
  }
  if (has_ratio) {
    const double r = double(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::face_ratio), 1.0));
    if (!(r >= 0 && r <= 1))
      throw Parameter_error(std::string(fn) + "face_ratio must be in [0, 1], not " + std::to_string(r));
    s.target_faces = (std::max)(s.target_faces, std::size_t(std::floor(r * double(faces))));
  }
  if (has_error) {
    s.maximum_error = double(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::maximum_error), 0.0));
    if (!(s.maximum_error >= 0) || std::isnan(s.maximum_error))
      throw Parameter_error(std::string(fn) + "maximum_error must be >= 0, not " + std::to_string(s.maximum_error));
  }
  const double degrees =
    double(pm::choose_parameter(pm::get_parameter(np, CGAL::internal_np::maximum_normal_deviation), 90.0));
  if (!(degrees > 0 && degrees <= 180))
    throw Parameter_error(std::string(fn) + "maximum_normal_deviation must be in (0, 180] degrees, not " +
                          std::to_string(degrees));
  s.min_cos_normal_turn = degrees == 180 ? -1.0 : std::cos(degrees * 3.14159265358979323846 / 180);
  s.protect_borders = pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::protect_borders), false);
  s.relocate_vertices =
    pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::relocate_vertices), true);
  s.corner_value_weight =
    double(pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::corner_value_weight), 1.0));
  if (!(s.corner_value_weight >= 0) || !std::isfinite(s.corner_value_weight))
    throw Parameter_error(std::string(fn) + "corner_value_weight must be a finite number >= 0, not " +
                          std::to_string(s.corner_value_weight));
  return s;
}

// Refuses a NaN or negative sharpness in the map given or the mesh's
// "e:sharpness", the one that feature_edges() reads.
template <class P, class NP>
void require_valid_sharpness(const Mobius_mesh<P>& mesh, const NP& np)
{
  CGAL_ext::internal::require_valid_edge_sharpness(mesh, np, "decimate");
}

// Which edges are features, by edge index: sharpness > 0 (the map given or
// the mesh's "e:sharpness"), constrained edges, and borders if asked.
template <class P, class NP>
std::vector<char> feature_edges(const Mobius_mesh<P>& mesh, const NP& np, bool protect_borders)
{
  namespace pm = CGAL_ext::parameters;
  std::vector<char> feature(mesh.num_edges(), 0);
  const auto sharpness = CGAL_ext::internal::edge_sharpness_of(mesh, np);
  const auto constrained = pm::get_parameter(np, CGAL::internal_np::edge_is_constrained);
  for (Edge_index e : mesh.edges()) {
    bool f = (protect_borders && mesh.is_border(e)) || sharpness(e) > 0;
    if constexpr (!pm::is_default_parameter<NP, CGAL::internal_np::edge_is_constrained_t>::value)
      f = f || get(constrained, e);
    feature[e.idx()] = f;
  }
  return feature;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_INTERNAL_DECIMATION_SETTINGS_H
