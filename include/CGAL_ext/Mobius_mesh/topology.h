// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Global topological queries on a Mobius_mesh: border loops, Euler
// characteristic, connected components, orientability, and `orient()`.

#ifndef CGAL_EXT_MOBIUS_MESH_TOPOLOGY_H
#define CGAL_EXT_MOBIUS_MESH_TOPOLOGY_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/internal/Union_find.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL_ext {

/// One border dart per border loop. Walk a loop with
/// `halfedges_around_face(d, mesh)`: its darts may be flipped where the loop
/// passes a Möbius connection (the source design's Möbius boundary links).
template <class P>
std::vector<Dart> border_cycles(const Mobius_mesh<P>& mesh)
{
  std::vector<Dart> cycles;
  std::vector<bool> seen(mesh.num_halfedges(), false);
  for (Halfedge_index h : mesh.halfedges()) {
    if (!mesh.is_border(h) || seen[h.idx()])
      continue;
    cycles.push_back(Dart(h, false));
    for (Dart d : CGAL_ext::halfedges_around_face(Dart(h, false), mesh))
      seen[d.halfedge().idx()] = true;
  }
  return cycles;
}

/// The number of border cycles of `mesh`: `border_cycles(mesh).size()`.
template <class P>
std::size_t number_of_border_cycles(const Mobius_mesh<P>& mesh)
{
  return CGAL_ext::border_cycles(mesh).size();
}

/// True if the mesh has no border halfedge.
template <class P>
bool is_closed(const Mobius_mesh<P>& mesh)
{
  for (Halfedge_index h : mesh.halfedges())
    if (mesh.is_border(h))
      return false;
  return true;
}

/// V - E + F.
template <class P>
long long euler_characteristic(const Mobius_mesh<P>& mesh)
{
  return static_cast<long long>(mesh.number_of_vertices()) - static_cast<long long>(mesh.number_of_edges()) +
         static_cast<long long>(mesh.number_of_faces());
}

/// The number of Möbius edges of `mesh` (see `Mobius_mesh::is_mobius()`).
template <class P>
std::size_t number_of_mobius_edges(const Mobius_mesh<P>& mesh)
{
  std::size_t n = 0;
  for (Edge_index e : mesh.edges())
    n += mesh.is_mobius(e) ? 1 : 0;
  return n;
}

/// Connected components (an isolated vertex is a component of its own).
/// The vectors are indexed by vertex and face index; removed elements have
/// no component (`no_component`).
struct Mesh_components
{
  /// The component of a removed element.
  static constexpr std::uint32_t no_component = Vertex_index::null_value;
  /// The number of components; they are numbered from 0.
  std::size_t count = 0;
  std::vector<std::uint32_t> vertex_component; ///< component of each vertex
  std::vector<std::uint32_t> face_component;   ///< component of each face
};

/// The connected components of `mesh`: vertices linked by edges are in one
/// component, and each face is in that of its vertices.
template <class P>
Mesh_components connected_components(const Mobius_mesh<P>& mesh)
{
  const std::size_t nv = mesh.num_vertices();
  internal::Union_find linked{std::uint32_t(nv)};
  for (Edge_index e : mesh.edges())
    linked.unite(mesh.vertex(e, 0).idx(), mesh.vertex(e, 1).idx());
  Mesh_components result;
  std::uint32_t count = 0;
  result.vertex_component = linked.classes(count);
  if (mesh.number_of_removed_vertices() != 0) {
    // Removed vertices are classes of their own: number the live classes again.
    std::vector<std::uint32_t> renumbered(count, Mesh_components::no_component);
    count = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      std::uint32_t& c = result.vertex_component[v];
      if (mesh.is_removed(Vertex_index(std::uint32_t(v)))) {
        c = Mesh_components::no_component;
        continue;
      }
      if (renumbered[c] == Mesh_components::no_component)
        renumbered[c] = count++;
      c = renumbered[c];
    }
  }
  result.count = count;
  result.face_component.assign(mesh.num_faces(), Mesh_components::no_component);
  for (Face_index f : mesh.faces())
    result.face_component[f.idx()] = result.vertex_component[mesh.target(mesh.halfedge(f)).idx()];
  return result;
}

namespace internal {

// Breadth-first orientation: the parity each face must be flipped by so that
// tree edges are not Möbius, and whether each component closed consistently.
template <class P>
void orientation_parities(const Mobius_mesh<P>& mesh, std::vector<std::uint8_t>& flip,
                          std::vector<std::uint32_t>& face_component, std::vector<bool>& component_orientable,
                          Face_index first_root = Face_index(0u))
{
  const std::size_t nf = mesh.num_faces();
  flip.assign(nf, 0);
  face_component.assign(nf, Face_index::null_value);
  component_orientable.clear();
  std::vector<Face_index> queue;
  queue.reserve(nf);
  std::vector<Face_index> roots;
  if (first_root.idx() < nf && !mesh.is_removed(first_root))
    roots.push_back(first_root);
  roots.insert(roots.end(), mesh.faces().begin(), mesh.faces().end());
  for (Face_index root : roots) {
    if (face_component[root.idx()] != Face_index::null_value)
      continue;
    const std::uint32_t c = std::uint32_t(component_orientable.size());
    component_orientable.push_back(true);
    face_component[root.idx()] = c;
    queue.clear();
    queue.push_back(root);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const Face_index f = queue[q];
      for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
        const Face_index g = mesh.face(mesh.opposite(d));
        if (!g.is_valid() || g == f)
          continue;
        const std::uint8_t wanted = flip[f.idx()] ^ (mesh.is_mobius(mesh.edge(d)) ? 1 : 0);
        if (face_component[g.idx()] == Face_index::null_value) {
          face_component[g.idx()] = c;
          flip[g.idx()] = wanted;
          queue.push_back(g);
        } else if (flip[g.idx()] != wanted) {
          component_orientable[c] = false;
        }
      }
    }
  }
}

} // namespace internal

/// Orientability of each connected component that has faces, in the order of
/// the lowest face index of each component.
template <class P>
std::vector<bool> orientable_components(const Mobius_mesh<P>& mesh)
{
  std::vector<std::uint8_t> flip;
  std::vector<std::uint32_t> component;
  std::vector<bool> orientable;
  internal::orientation_parities(mesh, flip, component, orientable);
  return orientable;
}

/// True if every component is orientable.
template <class P>
bool is_orientable(const Mobius_mesh<P>& mesh)
{
  for (bool o : CGAL_ext::orientable_components(mesh))
    if (!o)
      return false;
  return true;
}

namespace internal {

// Möbius edges left in each component if the faces with `flip` set were reversed.
template <class P>
std::vector<std::size_t> mobius_edges_per_component(const Mobius_mesh<P>& mesh, const std::vector<std::uint8_t>& flip,
                                                    const std::vector<std::uint32_t>& face_component,
                                                    std::size_t n_components)
{
  std::vector<std::size_t> count(n_components, 0);
  for (Edge_index e : mesh.edges()) {
    const Face_index f = mesh.face(mesh.halfedge(e)), g = mesh.face(mesh.opposite(mesh.halfedge(e)));
    if (f.is_valid() && g.is_valid() && ((mesh.is_mobius(e) ? 1 : 0) ^ flip[f.idx()] ^ flip[g.idx()]))
      ++count[face_component[f.idx()]];
  }
  return count;
}

// Reverses single faces (in `flip`) while that removes more Möbius edges than it makes.
template <class P>
void improve_orientation_locally(const Mobius_mesh<P>& mesh, std::vector<std::uint8_t>& flip)
{
  bool improved = true;
  while (improved) {
    improved = false;
    for (Face_index f : mesh.faces()) {
      long gain = 0;
      for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
        const Face_index g = mesh.face(mesh.opposite(d));
        if (g.is_valid() && g != f)
          gain += ((mesh.is_mobius(mesh.edge(d)) ? 1 : 0) ^ flip[f.idx()] ^ flip[g.idx()]) ? 1 : -1;
      }
      if (gain > 0) {
        flip[f.idx()] ^= 1u;
        improved = true;
      }
    }
  }
}

} // namespace internal

/// Reverses faces so that every orientable connected component has no Möbius
/// edge, each keeping the orientation of its lowest-numbered face, as CGAL's
/// `orient_polygon_soup()` orients a soup before it becomes a `Surface_mesh`;
/// non-orientable components keep their faces' orientations (`orient()`
/// reduces their Möbius edges). Linear in the mesh's size.
/// Returns the number of faces reversed.
template <class P>
std::size_t orient_orientable_components(Mobius_mesh<P>& mesh)
{
  std::vector<std::uint8_t> flip;
  std::vector<std::uint32_t> component;
  std::vector<bool> orientable;
  internal::orientation_parities(mesh, flip, component, orientable);
  std::size_t reversed = 0;
  for (Face_index f : mesh.faces())
    if (flip[f.idx()] && orientable[component[f.idx()]]) {
      mesh.reverse_face_orientation(f);
      ++reversed;
    }
  return reversed;
}

/// Reverses faces so that as few Möbius edges as possible remain: none on an
/// orientable component. On a non-orientable component the Möbius edges form
/// a seam that every orientation-reversing loop crosses; the shortest such
/// seam is NP-hard to find in general, so this is a heuristic: it starts from
/// the current orientations and from breadth-first orientations grown from
/// several faces, improves each by reversing single faces while that removes
/// more Möbius edges than it makes, and keeps, per component, the best.
/// It never leaves more Möbius edges than there were.
/// Returns the number of Möbius edges left.
template <class P>
std::size_t orient(Mobius_mesh<P>& mesh, unsigned number_of_starts = 8)
{
  std::vector<std::uint8_t> bfs_flip;
  std::vector<std::uint32_t> component;
  std::vector<bool> orientable;
  internal::orientation_parities(mesh, bfs_flip, component, orientable);
  const std::size_t nf = mesh.num_faces(), nc = orientable.size();

  // Candidate 0: the faces as they are (improved locally).
  std::vector<std::uint8_t> best(nf, 0);
  bool any_non_orientable = false;
  for (bool o : orientable)
    any_non_orientable = any_non_orientable || !o;
  if (any_non_orientable)
    internal::improve_orientation_locally(mesh, best);
  std::vector<std::size_t> best_count = internal::mobius_edges_per_component(mesh, best, component, nc);

  auto consider = [&](std::vector<std::uint8_t> flip) {
    internal::improve_orientation_locally(mesh, flip);
    const std::vector<std::size_t> count = internal::mobius_edges_per_component(mesh, flip, component, nc);
    for (Face_index f : mesh.faces()) {
      const std::uint32_t c = component[f.idx()];
      if (count[c] < best_count[c])
        best[f.idx()] = flip[f.idx()];
    }
    for (std::size_t c = 0; c < nc; ++c)
      best_count[c] = (std::min)(best_count[c], count[c]);
  };
  // Breadth-first from the lowest face of each component: exact on orientable ones.
  {
    std::vector<std::uint8_t> flip = bfs_flip;
    const std::vector<std::size_t> count = internal::mobius_edges_per_component(mesh, flip, component, nc);
    for (Face_index f : mesh.faces()) {
      const std::uint32_t c = component[f.idx()];
      if (orientable[c] || count[c] < best_count[c])
        best[f.idx()] = flip[f.idx()];
    }
    for (std::size_t c = 0; c < nc; ++c)
      best_count[c] = orientable[c] ? 0 : (std::min)(best_count[c], count[c]);
    if (any_non_orientable)
      consider(std::move(flip));
  }
  // Breadth-first from other roots, spread over the face indices.
  for (unsigned k = 1; any_non_orientable && k < number_of_starts && nf > 0; ++k) {
    const std::size_t root = (nf * k) / number_of_starts;
    std::vector<std::uint8_t> flip;
    std::vector<std::uint32_t> comp;
    std::vector<bool> orient_ok;
    internal::orientation_parities(mesh, flip, comp, orient_ok, Face_index(root));
    consider(std::move(flip));
  }

  for (Face_index f : mesh.faces())
    if (best[f.idx()])
      mesh.reverse_face_orientation(f);
  return CGAL_ext::number_of_mobius_edges(mesh);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_TOPOLOGY_H
