// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The named parameters that CGAL_ext adds to CGAL's, one per line, in the
// form of CGAL's own list: (tag type, tag value, function name).
// No include guard: this list is expanded several times.

// polygon soups and merging
CGAL_EXT_add_named_parameter(tolerance_t, tolerance, tolerance)
CGAL_EXT_add_named_parameter(split_non_manifold_vertices_t, split_non_manifold_vertices, split_non_manifold_vertices)
CGAL_EXT_add_named_parameter(keep_orientation_t, keep_orientation, keep_orientation)
CGAL_EXT_add_named_parameter(non_manifold_policy_t, non_manifold_policy, non_manifold_policy)
// sharp features, read and written by the OBJ tag reader and used by subdivision
CGAL_EXT_add_named_parameter(edge_sharpness_t, edge_sharpness, edge_sharpness_map)
CGAL_EXT_add_named_parameter(vertex_sharpness_t, vertex_sharpness, vertex_sharpness_map)
CGAL_EXT_add_named_parameter(write_subdivision_tags_t, write_subdivision_tags, write_subdivision_tags)
// subdivision
CGAL_EXT_add_named_parameter(boundary_interpolation_t, boundary_interpolation, boundary_interpolation)
CGAL_EXT_add_named_parameter(crease_method_t, crease_method, crease_method)
CGAL_EXT_add_named_parameter(vertex_rule_t, vertex_rule, vertex_rule)
CGAL_EXT_add_named_parameter(triangle_subdivision_t, triangle_subdivision, triangle_subdivision)
CGAL_EXT_add_named_parameter(maximum_memory_t, maximum_memory, maximum_memory)
CGAL_EXT_add_named_parameter(face_varying_interpolation_t, face_varying_interpolation, face_varying_interpolation)
// offsets
CGAL_EXT_add_named_parameter(solid_t, solid, solid)
CGAL_EXT_add_named_parameter(vertex_displacement_t, vertex_displacement, vertex_displacement_map)
// normals
CGAL_EXT_add_named_parameter(normalize_t, normalize, normalize)
CGAL_EXT_add_named_parameter(vertex_normal_weighting_t, vertex_normal_weighting, vertex_normal_weighting)
// decimation (with CGAL's maximum_normal_deviation and edge_is_constrained_map)
CGAL_EXT_add_named_parameter(number_of_faces_t, number_of_faces, number_of_faces)
CGAL_EXT_add_named_parameter(face_ratio_t, face_ratio, face_ratio)
CGAL_EXT_add_named_parameter(maximum_error_t, maximum_error, maximum_error)
CGAL_EXT_add_named_parameter(relocate_vertices_t, relocate_vertices, relocate_vertices)
CGAL_EXT_add_named_parameter(corner_value_weight_t, corner_value_weight, corner_value_weight)
// decimation and isotropic remeshing
CGAL_EXT_add_named_parameter(protect_borders_t, protect_borders, protect_borders)
// isotropic remeshing
CGAL_EXT_add_named_parameter(protect_sharp_edges_t, protect_sharp_edges, protect_sharp_edges)
CGAL_EXT_add_named_parameter(stop_when_converged_t, stop_when_converged, stop_when_converged)
CGAL_EXT_add_named_parameter(allow_narrow_regions_t, allow_narrow_regions, allow_narrow_regions)
CGAL_EXT_add_named_parameter(project_to_limit_surface_t, project_to_limit_surface, project_to_limit_surface)
// drawing
CGAL_EXT_add_named_parameter(two_sided_style_t, two_sided_style, two_sided_style)
