// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Input that is not a 2-manifold, held as manifold sheets: the policy of the
// soup import, the vertex map that records which vertices of the sheets were
// one vertex of the input, and what can be read off it (the non-manifold
// edges and vertices, the input's polygons joined again).

#ifndef CGAL_EXT_MOBIUS_MESH_NON_MANIFOLD_JOINS_H
#define CGAL_EXT_MOBIUS_MESH_NON_MANIFOLD_JOINS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Join_classes.h>
#include <CGAL_ext/exceptions.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshSoup
/// What `polygon_soup_to_mobius_mesh()` does with a soup that is not a
/// 2-manifold (named parameter `non_manifold_policy`).
enum class Non_manifold_policy {
  /// Throw a `Soup_error` naming the polygons and vertices at fault (the default).
  refuse,
  /// Split the soup into manifold sheets, as OpenSubdiv's rules see it: the
  /// polygons of an edge of three or more polygons each get a border edge of
  /// their own there, and a vertex whose polygons then form several fans
  /// gets a vertex per fan. The vertex map `non_manifold_join_name` records
  /// which vertices were one; subdivision subdivides the sheets as
  /// OpenSubdiv subdivides the joined input, and the writers join them again.
  split
};

/// \ingroup PkgMobiusMeshSoup
/// The name of the vertex property map (values `std::uint32_t`) in which a
/// mesh of manifold sheets records its joins: a vertex split off another
/// holds that vertex's index (the lowest of the input vertex's copies),
/// every other vertex `no_non_manifold_join` (the map's default: a vertex
/// added later is joined to none). Made by `polygon_soup_to_mobius_mesh()`
/// with `non_manifold_policy(Non_manifold_policy::split)` where it split
/// anything or holds a polygon that visits a vertex twice within one fan (a
/// loop's among them; then possibly with no vertex joined), and carried by
/// subdivision.
inline constexpr const char* non_manifold_join_name = internal::non_manifold_join_map_name;
/// \ingroup PkgMobiusMeshSoup
/// The value of a vertex in the join map that was split off no other.
inline constexpr std::uint32_t no_non_manifold_join = internal::no_join;

/// \ingroup PkgMobiusMeshSoup
/// The join map of `mesh` (see `non_manifold_join_name`), if it has one.
template <class P>
std::optional<typename Mobius_mesh<P>::template Property_map<Vertex_index, std::uint32_t>>
non_manifold_join_map(const Mobius_mesh<P>& mesh)
{
  return mesh.template property_map<Vertex_index, std::uint32_t>(non_manifold_join_name);
}

/// \ingroup PkgMobiusMeshSoup
/// The vertex that stands for `v`'s input vertex: the one `v` was split off,
/// or `v` itself. (Looks the map up by name: for many vertices, read
/// `non_manifold_join_map()` once.)
template <class P>
Vertex_index non_manifold_representative(const Mobius_mesh<P>& mesh, Vertex_index v)
{
  const auto map = non_manifold_join_map(mesh);
  return map && (*map)[v] != no_non_manifold_join ? Vertex_index((*map)[v]) : v;
}

/// \ingroup PkgMobiusMeshSoup
/// What the joins of a mesh of sheets stand for in the joined input.
struct Non_manifold_counts
{
  /// The non-manifold vertices of the input, as OpenSubdiv counts them:
  /// those that are several vertices of the mesh (where fans meet at a point
  /// or non-manifold edges end), the ends of non-manifold edges (a loop's
  /// vertex too) and the vertices a face visits twice.
  std::size_t vertices = 0;
  /// The non-manifold edges of the input, as OpenSubdiv counts them: those
  /// shared by three or more polygons (several border edges of the mesh
  /// each), and those of a polygon that visits a vertex twice where it runs
  /// along a pair of vertices again or from a vertex to itself.
  std::size_t edges = 0;
  /// The vertices of the joined input: the mesh's, each input vertex once.
  std::size_t input_vertices = 0;
  /// The edges of the joined input: the mesh's, each input edge once.
  std::size_t input_edges = 0;
};

/// \ingroup PkgMobiusMeshSoup
/// The non-manifold vertices and edges that the join map of `mesh` records
/// (none without one). Linear in the mesh's size.
template <class P>
Non_manifold_counts non_manifold_counts(const Mobius_mesh<P>& mesh)
{
  const internal::Join_classes classes(mesh);
  return {classes.non_manifold_vertices(), classes.non_manifold_edges(), classes.input_vertices(),
          classes.input_edges()};
}

/// \ingroup PkgMobiusMeshSoup
/// The polygon soup of `mesh` with its joins made again: one point per
/// vertex that holds its own index in the join map (in order), the polygons
/// on them. Without a join map, the mesh's own vertices and faces.
template <class P, class Point, class Polygon>
void joined_polygon_soup(const Mobius_mesh<P>& mesh, std::vector<Point>& points, std::vector<Polygon>& polygons)
{
  const internal::Join_classes classes(mesh);
  const std::vector<std::uint32_t> index = classes.joined_indices();
  points.clear();
  polygons.clear();
  for (Vertex_index v : mesh.vertices())
    if (classes.representative(v.idx()) == v.idx())
      points.push_back(Point(mesh.point(v)));
  for (Face_index f : mesh.faces()) {
    polygons.emplace_back();
    for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh))
      polygons.back().push_back(typename Polygon::value_type(index[mesh.target(d).idx()]));
  }
}

namespace internal {

// The refusal of the operations that remove or renumber vertices: a join
// map holds vertex indices, which they would leave pointing elsewhere.
template <class P>
void refuse_non_manifold_joins(const Mobius_mesh<P>& mesh, const std::string& function)
{
  if (non_manifold_join_map(mesh))
    throw Parameter_error(function + ": the mesh holds non-manifold input as sheets (the vertex map \"" +
                          non_manifold_join_name + "\"), whose joins " + function +
                          " would not keep; remove the map to work on the sheets apart");
}

// A face of non-manifold input that visits a vertex twice (see
// polygon_soup_to_mobius_mesh(); a loop's face is one), which `function`
// cannot rebuild: refused, by face and vertex. Such faces come only with a
// join map.
template <class P>
void refuse_folded_faces(const Mobius_mesh<P>& mesh, const std::string& function)
{
  if (!non_manifold_join_map(mesh))
    return;
  const auto folded = folded_vertices(mesh);
  if (folded.empty())
    return;
  throw Parameter_error(function + ": face " + std::to_string(folded.front().second.idx()) + " visits vertex " +
                        std::to_string(folded.front().first.idx()) +
                        " twice (non-manifold input), which " + function +
                        " cannot rebuild; subdivide the mesh first, or import it without that polygon");
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_NON_MANIFOLD_JOINS_H
