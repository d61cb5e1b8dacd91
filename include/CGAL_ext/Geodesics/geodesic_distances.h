// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Geodesic distances on a Mobius_mesh, one-sided surfaces included: CGAL's
// heat method and CGAL's exact shortest paths, run on the mesh where CGAL can
// walk it and on its orientation double cover where it cannot.

#ifndef CGAL_EXT_GEODESICS_GEODESIC_DISTANCES_H
#define CGAL_EXT_GEODESICS_GEODESIC_DISTANCES_H

#include <CGAL_ext/Geodesics/internal/Orientation_double_cover.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {

namespace internal {

template <class P, class VertexRange>
std::vector<Vertex_index> geodesic_sources(const Mobius_mesh<P>& mesh, const VertexRange& sources, const char* what)
{
  std::vector<Vertex_index> out;
  for (Vertex_index v : sources) {
    if (!mesh.is_valid(v) || mesh.is_removed(v))
      throw Parameter_error(std::string(what) + ": source vertex " + std::to_string(v.idx()) + " is not in the mesh");
    out.push_back(v);
  }
  if (out.empty())
    throw Parameter_error(std::string(what) + ": no source vertex");
  return out;
}

template <class P>
void require_geodesic_input(const Mobius_mesh<P>& mesh, const char* what)
{
  if (!CGAL::is_triangle_mesh(mesh))
    throw Parameter_error(std::string(what) + ": the mesh must be a triangle mesh (PMP::triangulate_faces() makes one)");
}

} // namespace internal

/// \ingroup PkgMobiusMeshGeodesics
/// \brief approximates the geodesic distance from `sources` to every vertex of
/// `mesh` with CGAL's heat method (`CGAL::Heat_method_3`), on any triangle
/// mesh, one-sided ones included.
///
/// Geodesic distance is intrinsic: it does not depend on an orientation.
/// With `Mode` = `CGAL::Heat_method_3::Direct` CGAL's heat method runs on the
/// mesh itself (its cotangent Laplacian and gradients are taken face by face,
/// which the darts of a one-sided mesh give it). With
/// `CGAL::Heat_method_3::Intrinsic_Delaunay` on a mesh with Möbius edges it
/// runs on the orientation double cover of the mesh, with both lifts of each
/// source as sources: CGAL's intrinsic Delaunay triangulation copies the
/// mesh into a `Surface_mesh`, which cannot hold a one-sided surface. The
/// cover's distance at either lift of a vertex is the distance on the mesh
/// (heat spreading from both lifts is the lift of heat spreading on the
/// mesh, and the Delaunay flips of the cover are the lifts of the mesh's).
///
/// \tparam Mode `CGAL::Heat_method_3::Direct` or `CGAL::Heat_method_3::Intrinsic_Delaunay`
/// \param mesh a triangle mesh
/// \param distances a writable property map from `Vertex_index` to a floating-point type
/// \param sources a range of source vertices (at least one)
/// \throws Parameter_error if `mesh` is not a triangle mesh, or a source is
///   not a vertex of it; `distances` is then left unchanged.
template <class Mode = CGAL::Heat_method_3::Direct, class P, class VertexDistanceMap, class VertexRange>
void estimate_geodesic_distances(const Mobius_mesh<P>& mesh, VertexDistanceMap distances, const VertexRange& sources,
                                 Mode = Mode())
{
  const char* what = "estimate_geodesic_distances";
  internal::require_geodesic_input(mesh, what);
  const std::vector<Vertex_index> src = internal::geodesic_sources(mesh, sources, what);
  if (std::is_same<Mode, CGAL::Heat_method_3::Direct>::value || !has_mobius_edges(mesh)) {
    CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mobius_mesh<P>, Mode> hm(mesh);
    for (Vertex_index s : src)
      hm.add_source(s);
    hm.estimate_geodesic_distances(distances);
    return;
  }
  const internal::Orientation_double_cover<P> c = internal::make_orientation_double_cover(mesh, what);
  using Cover = typename internal::Orientation_double_cover<P>::Cover;
  auto cover_distance = get(CGAL::dynamic_vertex_property_t<double>(), c.mesh);
  CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Cover, Mode> hm(c.mesh);
  for (Vertex_index s : src)
    for (int side : {0, 1})
      hm.add_source(c.sheet[s.idx()][side]);
  hm.estimate_geodesic_distances(cover_distance);
  using Value = typename boost::property_traits<VertexDistanceMap>::value_type;
  for (Vertex_index v : mesh.vertices())
    put(distances, v, Value(get(cover_distance, c.sheet[v.idx()][0])));
}

/// \ingroup PkgMobiusMeshGeodesics
/// \brief `estimate_geodesic_distances()` from one source vertex.
template <class Mode = CGAL::Heat_method_3::Direct, class P, class VertexDistanceMap>
void estimate_geodesic_distances(const Mobius_mesh<P>& mesh, VertexDistanceMap distances, Vertex_index source,
                                 Mode mode = Mode())
{
  estimate_geodesic_distances(mesh, distances, std::vector<Vertex_index>{source}, mode);
}

/// \ingroup PkgMobiusMeshGeodesics
/// \brief computes the exact geodesic distance (along the surface of the
/// piecewise-flat mesh) from `sources` to every vertex of `mesh`, with CGAL's
/// `Surface_mesh_shortest_path`, on any triangle mesh, one-sided ones included.
///
/// On a mesh without Möbius edges CGAL's algorithm runs on the mesh itself.
/// With Möbius edges it runs on the orientation double cover, with both lifts
/// of each source as sources: CGAL's algorithm locates a point by the
/// position of its dart in the face's cycle (`halfedge(f)`, `next()`, ...), and
/// across a Möbius edge it meets the other dart of the halfedge, which that
/// cycle does not hold (it walks the cycle for ever). A shortest path on the
/// mesh lifts to one on the cover of the same length from one of the lifts
/// of its source, so the cover's distance at either lift of a vertex is the
/// mesh's.
///
/// \param mesh a triangle mesh
/// \param distances a writable property map from `Vertex_index` to a number type
/// \param sources a range of source vertices (at least one)
/// \throws Parameter_error as `estimate_geodesic_distances()`.
template <class P, class VertexDistanceMap, class VertexRange>
void exact_geodesic_distances(const Mobius_mesh<P>& mesh, VertexDistanceMap distances, const VertexRange& sources)
{
  const char* what = "exact_geodesic_distances";
  internal::require_geodesic_input(mesh, what);
  const std::vector<Vertex_index> src = internal::geodesic_sources(mesh, sources, what);
  using Kernel = typename CGAL::Kernel_traits<P>::Kernel;
  using Value = typename boost::property_traits<VertexDistanceMap>::value_type;
  if (!has_mobius_edges(mesh)) {
    using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Mobius_mesh<P>>;
    CGAL::Surface_mesh_shortest_path<Traits> sp(mesh);
    sp.add_source_points(src.begin(), src.end());
    sp.build_sequence_tree();
    for (Vertex_index v : mesh.vertices())
      put(distances, v, Value(sp.shortest_distance_to_source_points(v).first));
    return;
  }
  const internal::Orientation_double_cover<P> c = internal::make_orientation_double_cover(mesh, what);
  using Cover = typename internal::Orientation_double_cover<P>::Cover;
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Cover>;
  CGAL::Surface_mesh_shortest_path<Traits> sp(c.mesh);
  std::vector<typename Cover::Vertex_index> lifts;
  for (Vertex_index s : src)
    for (int side : {0, 1})
      lifts.push_back(c.sheet[s.idx()][side]);
  sp.add_source_points(lifts.begin(), lifts.end());
  sp.build_sequence_tree();
  for (Vertex_index v : mesh.vertices())
    put(distances, v, Value(sp.shortest_distance_to_source_points(c.sheet[v.idx()][0]).first));
}

/// \ingroup PkgMobiusMeshGeodesics
/// \brief `exact_geodesic_distances()` from one source vertex.
template <class P, class VertexDistanceMap>
void exact_geodesic_distances(const Mobius_mesh<P>& mesh, VertexDistanceMap distances, Vertex_index source)
{
  exact_geodesic_distances(mesh, distances, std::vector<Vertex_index>{source});
}

namespace internal {

// The traits of CGAL's shortest paths on a Mobius_mesh under another name, so
// that the class below can be CGAL's class for them.
template <class K, class P>
struct Mobius_shortest_path_traits : CGAL::Surface_mesh_shortest_path_traits<K, Mobius_mesh<P>>
{
  using Base = CGAL::Surface_mesh_shortest_path_traits<K, Mobius_mesh<P>>;
  Mobius_shortest_path_traits() = default;
  Mobius_shortest_path_traits(const Base& traits) : Base(traits) {}
};

template <class P>
const Mobius_mesh<P>& checked_for_shortest_paths(const Mobius_mesh<P>& mesh)
{
  require_orientable_model(mesh, "CGAL::Surface_mesh_shortest_path (CGAL_ext::exact_geodesic_distances() "
                                 "runs it on the orientation double cover)");
  return mesh;
}

} // namespace internal

} // namespace CGAL_ext

namespace CGAL {

/// CGAL's `Surface_mesh_shortest_path` on a `Mobius_mesh`: CGAL's class,
/// whose constructors first refuse a mesh with Möbius edges with
/// `CGAL_ext::Parameter_error` (CGAL's algorithm would walk a face's cycle for
/// ever looking for a flipped dart); `CGAL_ext::exact_geodesic_distances()`
/// computes the distances on such a mesh. Seen by code that includes
/// `<CGAL_ext/Geodesics/geodesic_distances.h>` before it names the class.
template <class K, class P, class VIM, class HIM, class FIM, class VPM>
class Surface_mesh_shortest_path<Surface_mesh_shortest_path_traits<K, CGAL_ext::Mobius_mesh<P>>, VIM, HIM, FIM, VPM>
  : public Surface_mesh_shortest_path<CGAL_ext::internal::Mobius_shortest_path_traits<K, P>, VIM, HIM, FIM, VPM>
{
  using Base = Surface_mesh_shortest_path<CGAL_ext::internal::Mobius_shortest_path_traits<K, P>, VIM, HIM, FIM, VPM>;
  using Base_traits = CGAL_ext::internal::Mobius_shortest_path_traits<K, P>;

public:
  /// The traits the class was named with.
  using Traits = Surface_mesh_shortest_path_traits<K, CGAL_ext::Mobius_mesh<P>>;
  using typename Base::Face_index_map;
  using typename Base::Halfedge_index_map;
  using typename Base::Triangle_mesh;
  using typename Base::Vertex_index_map;
  using typename Base::Vertex_point_map;

  /// CGAL's constructor, after the check.
  Surface_mesh_shortest_path(const Triangle_mesh& tm, const Traits& traits = Traits())
    : Base(CGAL_ext::internal::checked_for_shortest_paths(tm), Base_traits(traits))
  {}
  /// CGAL's constructor with index and point maps, after the check.
  Surface_mesh_shortest_path(const Triangle_mesh& tm, Vertex_index_map vertex_index_map,
                             Halfedge_index_map halfedge_index_map, Face_index_map face_index_map,
                             Vertex_point_map vertex_point_map, const Traits& traits = Traits())
    : Base(CGAL_ext::internal::checked_for_shortest_paths(tm), vertex_index_map, halfedge_index_map, face_index_map,
           vertex_point_map, Base_traits(traits))
  {}
};

} // namespace CGAL

#endif // CGAL_EXT_GEODESICS_GEODESIC_DISTANCES_H
