// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Builds a Mobius_mesh from a polygon soup, in time linear in the soup's
// size, finding normal and Möbius connections between polygons.

#ifndef CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H
#define CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace internal {

inline std::string join_ids(const std::vector<std::size_t>& ids, std::size_t max_shown = 8)
{
  std::ostringstream out;
  for (std::size_t i = 0; i < ids.size() && i < max_shown; ++i)
    out << (i ? ", " : "") << ids[i];
  if (ids.size() > max_shown)
    out << ", ... (" << ids.size() << " in all)";
  return out.str();
}

template <class FT>
bool is_finite_number(const FT& x)
{
  if constexpr (std::is_floating_point_v<FT>)
    return std::isfinite(x);
  else
    return true; // exact number types hold no infinities or NaNs
}

// Union of the points within `tolerance` of each other (closed ball), with
// the smallest index as representative. Candidates come from a box
// intersection on conservative double boxes; the decision is the kernel's
// exact `Compare_squared_distance_3`.
template <class PointRange, class PointMap, class Traits>
std::vector<std::size_t> merge_close_points(const PointRange& points, PointMap point_map, const Traits& traits,
                                            const typename Traits::FT& tolerance)
{
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  const std::size_t n = std::size(points);
  const double pad = CGAL::to_interval(tolerance).second;
  std::vector<Box> boxes;
  boxes.reserve(n);
  std::size_t i = 0;
  for (auto it = std::begin(points); it != std::end(points); ++it, ++i) {
    const CGAL::Bbox_3 b = get(point_map, *it).bbox();
    double lo[3] = {std::nextafter(b.xmin() - pad, -HUGE_VAL), std::nextafter(b.ymin() - pad, -HUGE_VAL),
                          std::nextafter(b.zmin() - pad, -HUGE_VAL)};
    double hi[3] = {std::nextafter(b.xmax() + pad, HUGE_VAL), std::nextafter(b.ymax() + pad, HUGE_VAL),
                          std::nextafter(b.zmax() + pad, HUGE_VAL)};
    boxes.emplace_back(lo, hi, i);
  }
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&parent](std::size_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<typename std::iterator_traits<decltype(std::begin(points))>::value_type const*> by_index;
  by_index.reserve(n);
  for (auto it = std::begin(points); it != std::end(points); ++it)
    by_index.push_back(&*it);
  const typename Traits::FT squared_tolerance = tolerance * tolerance;
  auto compare = traits.compare_squared_distance_3_object();
  CGAL::box_self_intersection_d(
    boxes.begin(), boxes.end(),
    [&](const Box& a, const Box& b) {
      const std::size_t ia = a.info(), ib = b.info();
      if (compare(get(point_map, *by_index[ia]), get(point_map, *by_index[ib]), squared_tolerance) ==
          CGAL::LARGER)
        return;
      const std::size_t ra = find(ia), rb = find(ib);
      if (ra != rb)
        parent[(std::max)(ra, rb)] = (std::min)(ra, rb);
    }); // closed boxes: points exactly at the tolerance are candidates
  for (std::size_t k = 0; k < n; ++k)
    parent[k] = find(k);
  return parent;
}

} // namespace internal

/// \ingroup PkgMobiusMeshSoup
///
/// Builds a 2-manifold `Mobius_mesh` from a polygon soup and appends it to
/// `mesh`. Two polygons that share an edge are connected whichever way they
/// run along it: in opposite directions (a normal connection) or in the same
/// direction (a Möbius connection). The polygons' orientations are kept; call
/// `orient()` to reduce the Möbius edges to the fewest.
///
/// The soup is checked before anything is built, and bad input throws a
/// `Soup_error` that names the polygons and points at fault; `mesh` is then
/// left unchanged.
///
/// \param points a range of points
/// \param polygons a range of ranges of indices into `points`
/// \param mesh the mesh the soup's polygons are added to
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map giving the point of an element of `points`}
///     \cgalParamDefault{`CGAL::Identity_property_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel whose `Compare_squared_distance_3` decides merges}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{points at distance at most this value are merged first
///                           (transitively), compared exactly with the kernel's predicate;
///                           0 merges exact duplicates only}
///     \cgalParamType{the kernel's `FT`}
///     \cgalParamDefault{no merging}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_non_manifold_vertices}
///     \cgalParamDescription{if `true`, a vertex whose polygons form several fans is
///                           split into one vertex per fan (as CGAL's
///                           `duplicate_non_manifold_vertices()` does) instead of refused}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of vertices added by splitting non-manifold vertices.
/// \throws Soup_error for an index out of range, a polygon with fewer than
///   three vertices or a repeated vertex, an edge shared by three or more
///   polygons, a non-manifold vertex (unless split), a non-finite coordinate.
/// \throws Parameter_error for a negative or NaN tolerance.
template <class PointRange, class PolygonRange, class P, class NamedParameters = parameters::Default_named_parameters>
std::size_t polygon_soup_to_mobius_mesh(const PointRange& points, const PolygonRange& polygons, Mobius_mesh<P>& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Mesh = Mobius_mesh<P>;
  using Input_point_map = decltype(choose_parameter(get_parameter(np, CGAL::internal_np::point_map),
                                                    CGAL::Identity_property_map<P>()));
  const Input_point_map point_map =
    choose_parameter(get_parameter(np, CGAL::internal_np::point_map), CGAL::Identity_property_map<P>());
  using Input_point = std::decay_t<decltype(get(point_map, *std::begin(points)))>;
  using Default_traits = typename CGAL::Kernel_traits<Input_point>::Kernel;
  const auto traits = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Default_traits());
  using Traits = std::decay_t<decltype(traits)>;
  using FT = typename Traits::FT;
  using Kind = Soup_error::Kind;
  using V = std::uint32_t;
  constexpr V none = (std::numeric_limits<V>::max)();

  const std::size_t n_points = std::size(points);
  const std::size_t n_polygons = std::size(polygons);

  // ---- 1. Check the points and polygons; flatten the polygons.
  {
    std::size_t i = 0;
    for (auto it = std::begin(points); it != std::end(points); ++it, ++i) {
      const auto& p = get(point_map, *it);
      if (!internal::is_finite_number(p.x()) || !internal::is_finite_number(p.y()) ||
          !internal::is_finite_number(p.z()))
        throw Soup_error(Kind::non_finite_point, "point " + std::to_string(i) + " has a non-finite coordinate", {},
                         {i});
    }
  }
  std::vector<std::size_t> poly_start;
  poly_start.reserve(n_polygons + 1);
  std::vector<V> corner_vertex;
  {
    std::size_t total = 0;
    for (const auto& polygon : polygons)
      total += std::size(polygon);
    corner_vertex.reserve(total);
  }
  std::vector<V> seen_in_polygon; // per point: last polygon that named it, for repeats
  poly_start.push_back(0);
  {
    std::size_t p = 0;
    for (const auto& polygon : polygons) {
      const std::size_t size = std::size(polygon);
      if (size < 3)
        throw Soup_error(Kind::degenerate_polygon,
                         "polygon " + std::to_string(p) + " has " + std::to_string(size) +
                           " vertices; a polygon needs at least three",
                         {p}, {});
      for (const auto& raw : polygon) {
        const auto index = raw;
        bool negative = false;
        if constexpr (std::is_signed_v<std::decay_t<decltype(index)>>)
          negative = index < 0;
        if (negative || std::size_t(index) >= n_points)
          throw Soup_error(Kind::index_out_of_range,
                           "polygon " + std::to_string(p) + " names point " + std::to_string(index) +
                             ", but there are only " + std::to_string(n_points) + " points",
                           {p}, {});
        corner_vertex.push_back(V(index));
      }
      poly_start.push_back(corner_vertex.size());
      ++p;
    }
  }

  // ---- 2. Merge points closer than the tolerance, if asked.
  std::vector<V> new_index; // soup point -> mesh vertex
  std::vector<std::size_t> representative;
  std::size_t n_vertices = n_points;
  const auto tolerance_param = get_parameter(np, CGAL_ext::internal_np::tolerance);
  constexpr bool merge = !std::is_same_v<std::decay_t<decltype(tolerance_param)>, CGAL::internal_np::Param_not_found>;
  if constexpr (merge) {
    if (!internal::is_finite_number(tolerance_param))
      throw Parameter_error("the merge tolerance must be a finite number >= 0");
    const FT tolerance(tolerance_param);
    if (CGAL::is_negative(tolerance))
      throw Parameter_error("the merge tolerance must be a finite number >= 0");
    const std::vector<std::size_t> rep = internal::merge_close_points(points, point_map, traits, tolerance);
    new_index.assign(n_points, none);
    n_vertices = 0;
    for (std::size_t i = 0; i < n_points; ++i) {
      if (rep[i] == i) {
        new_index[i] = V(n_vertices++);
        representative.push_back(i);
      }
    }
    for (std::size_t i = 0; i < n_points; ++i)
      new_index[i] = new_index[rep[i]];
    for (V& v : corner_vertex)
      v = new_index[v];
  }

  // Repeated vertices (checked after merging: merging can create them).
  seen_in_polygon.assign(n_vertices, none);
  for (std::size_t p = 0; p < n_polygons; ++p) {
    for (std::size_t t = poly_start[p]; t < poly_start[p + 1]; ++t) {
      const V v = corner_vertex[t];
      if (seen_in_polygon[v] == V(p))
        throw Soup_error(Kind::repeated_vertex,
                         "polygon " + std::to_string(p) + " visits vertex " + std::to_string(v) + " twice", {p},
                         {std::size_t(v)});
      seen_in_polygon[v] = V(p);
    }
  }
  std::vector<V>().swap(seen_in_polygon);

  // ---- 3. Pair the polygons' sides into edges. Sides are bucketed by their
  //      lower vertex; within a bucket a stamped slot per upper vertex finds
  //      the partner in O(1).
  const std::size_t n_corners = corner_vertex.size();
  std::vector<V> corner_polygon(n_corners);
  for (std::size_t p = 0; p < n_polygons; ++p)
    for (std::size_t t = poly_start[p]; t < poly_start[p + 1]; ++t)
      corner_polygon[t] = V(p);
  auto next_corner = [&](std::size_t t) {
    const std::size_t p = corner_polygon[t];
    return t + 1 == poly_start[p + 1] ? poly_start[p] : t + 1;
  };
  std::vector<std::uint32_t> bucket_start(n_vertices + 1, 0);
  for (std::size_t t = 0; t < n_corners; ++t)
    ++bucket_start[(std::min)(corner_vertex[t], corner_vertex[next_corner(t)]) + 1];
  std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
  std::vector<std::uint32_t> bucket(n_corners);
  {
    std::vector<std::uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (std::size_t t = 0; t < n_corners; ++t)
      bucket[fill[(std::min)(corner_vertex[t], corner_vertex[next_corner(t)])]++] = std::uint32_t(t);
  }
  constexpr std::uint32_t no_partner = (std::numeric_limits<std::uint32_t>::max)();
  std::vector<std::uint32_t> partner(n_corners, no_partner);
  {
    std::vector<V> stamp(n_vertices, none);
    std::vector<std::uint32_t> first(n_vertices);
    for (V lo = 0; lo < n_vertices; ++lo) {
      for (std::uint32_t k = bucket_start[lo]; k < bucket_start[lo + 1]; ++k) {
        const std::uint32_t t = bucket[k];
        const V hi = (std::max)(corner_vertex[t], corner_vertex[next_corner(t)]);
        if (stamp[hi] != lo) {
          stamp[hi] = lo;
          first[hi] = t;
          continue;
        }
        const std::uint32_t f = first[hi];
        if (partner[f] == no_partner) {
          partner[f] = t;
          partner[t] = f;
          continue;
        }
        // Three or more polygons on the edge (lo, hi): name them all.
        std::vector<std::size_t> offenders;
        for (std::uint32_t j = bucket_start[lo]; j < bucket_start[lo + 1]; ++j) {
          const std::uint32_t s = bucket[j];
          if ((std::max)(corner_vertex[s], corner_vertex[next_corner(s)]) == hi)
            offenders.push_back(corner_polygon[s]);
        }
        throw Soup_error(Kind::non_manifold_edge,
                         "edge (" + std::to_string(lo) + ", " + std::to_string(hi) + ") is shared by " +
                           std::to_string(offenders.size()) + " polygons (" + internal::join_ids(offenders) +
                           "); a 2-manifold edge has at most two",
                         offenders, {std::size_t(lo), std::size_t(hi)});
      }
    }
  }
  std::vector<std::uint32_t>().swap(bucket);
  std::vector<std::uint32_t>().swap(bucket_start);

  // ---- 4. Build the connectivity: edges numbered in order of first use.
  Mesh result;
  std::vector<std::uint32_t> corner_halfedge(n_corners, no_partner);
  std::uint32_t n_edges = 0;
  for (std::size_t t = 0; t < n_corners; ++t) {
    if (corner_halfedge[t] != no_partner)
      continue;
    corner_halfedge[t] = 2 * n_edges;
    if (partner[t] != no_partner)
      corner_halfedge[partner[t]] = 2 * n_edges + 1;
    ++n_edges;
  }
  result.resize(typename Mesh::size_type(n_vertices), n_edges, typename Mesh::size_type(n_polygons));
  {
    auto pts = result.points();
    if (representative.empty()) {
      std::size_t i = 0;
      for (auto it = std::begin(points); it != std::end(points); ++it, ++i)
        pts[Vertex_index(i)] = P(get(point_map, *it));
    } else {
      std::size_t i = 0;
      auto it = std::begin(points);
      for (std::size_t v = 0; v < representative.size(); ++v) {
        std::advance(it, std::ptrdiff_t(representative[v] - i));
        i = representative[v];
        pts[Vertex_index(v)] = P(get(point_map, *it));
      }
    }
  }
  std::vector<std::uint32_t> corners_at(n_vertices, 0);
  std::vector<Dart> some_incoming(n_vertices);
  for (std::size_t p = 0; p < n_polygons; ++p) {
    const Face_index f(p);
    const std::size_t begin = poly_start[p], end = poly_start[p + 1];
    result.set_halfedge(f, Halfedge_index(corner_halfedge[begin]));
    for (std::size_t t = begin; t < end; ++t) {
      const std::size_t u = t + 1 == end ? begin : t + 1;
      const Halfedge_index h(corner_halfedge[t]);
      const V target = corner_vertex[u];
      result.set_target(h, Vertex_index(target));
      result.set_face(h, f);
      result.set_next(Dart(h, false), Dart(Halfedge_index(corner_halfedge[u]), false));
      ++corners_at[target];
      some_incoming[target] = Dart(h, false);
      if (partner[t] == no_partner) {
        result.set_target(Mesh::opposite_halfedge(h), Vertex_index(corner_vertex[t]));
      } else if (t < partner[t]) {
        const std::size_t s = partner[t];
        result.set_mobius(Mesh::edge(h), corner_vertex[s] == corner_vertex[t]);
      }
    }
  }
  std::vector<std::uint32_t>().swap(partner);

  // ---- 5. Walk each vertex's fan through its faces. A manifold vertex has
  //      one fan holding all its corners; its two border halfedges (if any)
  //      are linked to each other.
  std::vector<V> face_stamp(n_polygons, none);
  auto walk_fan = [&](Vertex_index v, Dart start, std::vector<Halfedge_index>* touched) {
    std::uint32_t visited = 0;
    auto visit = [&](Dart d) {
      face_stamp[result.face(d).idx()] = v.idx();
      ++visited;
      if (touched) {
        touched->push_back(d.halfedge());
        touched->push_back(Mesh::opposite_halfedge(d.halfedge()));
      }
    };
    visit(start);
    Dart in = start;
    for (;;) {
      const Dart o = result.opposite(result.next(in));
      if (o == start)
        break;
      in = o;
      if (result.is_border(in)) {
        if (touched)
          touched->push_back(in.halfedge());
        break;
      }
      visit(in);
    }
    if (result.is_border(in)) {
      Dart out = result.opposite(start);
      while (!result.is_border(out)) {
        const Dart d = result.prev(out);
        visit(d);
        out = result.opposite(d);
      }
      if (touched)
        touched->push_back(out.halfedge());
      result.set_next(in, out);
      result.set_halfedge(v, in);
    } else {
      result.set_halfedge(v, start);
    }
    return visited;
  };

  const bool split = choose_parameter(get_parameter(np, CGAL_ext::internal_np::split_non_manifold_vertices), false);
  std::vector<std::vector<std::size_t>> polygons_at; // built on the first non-manifold vertex
  std::size_t added_vertices = 0;
  for (V vi = 0; vi < n_vertices; ++vi) {
    const Vertex_index v(vi);
    if (corners_at[vi] == 0)
      continue; // isolated
    const std::uint32_t visited = walk_fan(v, some_incoming[vi], nullptr);
    if (visited == corners_at[vi])
      continue;
    if (polygons_at.empty()) {
      polygons_at.resize(n_vertices);
      for (std::size_t p = 0; p < n_polygons; ++p)
        for (std::size_t t = poly_start[p]; t < poly_start[p + 1]; ++t)
          polygons_at[corner_vertex[t]].push_back(p);
    }
    if (!split) {
      std::vector<std::size_t> first_fan, others;
      for (std::size_t p : polygons_at[vi])
        (face_stamp[p] == vi ? first_fan : others).push_back(p);
      std::vector<std::size_t> all = first_fan;
      all.insert(all.end(), others.begin(), others.end());
      std::sort(all.begin(), all.end());
      throw Soup_error(Kind::non_manifold_vertex,
                       "vertex " + std::to_string(vi) + " is non-manifold: its polygons form separate fans (" +
                         internal::join_ids(first_fan) + " | " + internal::join_ids(others) + ")",
                       all, {std::size_t(vi)});
    }
    // Give every further fan a vertex of its own.
    for (std::size_t p : polygons_at[vi]) {
      if (face_stamp[p] == vi)
        continue;
      Dart start;
      for (Dart d : CGAL_ext::halfedges_around_face(result.halfedge(Face_index(p)), result))
        if (result.target(d) == v)
          start = d;
      const Vertex_index copy = result.add_vertex(result.point(v));
      std::vector<Halfedge_index> touched;
      walk_fan(copy, start, &touched);
      // walk_fan stamped with the copy's index; mark these faces as done for v.
      for (Face_index f : CGAL_ext::faces_around_target(start, result))
        if (f.is_valid())
          face_stamp[f.idx()] = vi;
      for (Halfedge_index h : touched)
        if (result.target(Dart(h, false)) == v)
          result.set_target(h, copy);
      ++added_vertices;
    }
  }

  if (mesh.is_empty() && mesh.number_of_faces() == 0 && mesh.template properties<Vertex_index>().size() == 1 &&
      mesh.template properties<Halfedge_index>().empty() && mesh.template properties<Edge_index>().empty() &&
      mesh.template properties<Face_index>().empty())
    mesh = std::move(result);
  else
    mesh.join(result);
  return added_vertices;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_POLYGON_SOUP_TO_MOBIUS_MESH_H
