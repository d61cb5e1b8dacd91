// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// One level of a subdivision hierarchy: the connectivity of a Mobius_mesh in
// flat arrays, plus sharpness and a numbering of face corners, and the two
// topological splits (quad and triangle) that build level k+1 from level k by
// index arithmetic alone.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_LEVEL_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_LEVEL_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/internal/Parallel_loops.h>
#include <CGAL_ext/internal/Uninitialized_array.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>
#include <CGAL/use.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

using u32 = std::uint32_t;
constexpr u32 null_u32 = CGAL_ext::internal::dart_encoding::null;
namespace dart_encoding = CGAL_ext::internal::dart_encoding;

// Whether halfedge h is the first of its edge's two (2e, not 2e+1).
constexpr bool is_first_halfedge(u32 h)
{
  return h == dart_encoding::halfedge_of_edge(dart_encoding::edge_of_halfedge(h), 0);
}

// Every array of a child level is written in full by the split: not zeroed first.
template <class T>
using Array = CGAL_ext::internal::Uninitialized_array<T>;

using CGAL_ext::internal::atomic_add;
using CGAL_ext::internal::count_if;
using CGAL_ext::internal::for_each_block;
using CGAL_ext::internal::for_each_index;
using CGAL_ext::internal::is_parallel_tag;
using CGAL_ext::internal::mark;
using CGAL_ext::internal::parallel_grain;
using CGAL_ext::internal::prefix_sum;
using CGAL_ext::internal::reduce;
using CGAL_ext::internal::sort_short;
using CGAL_ext::internal::with_concurrency;

// Arrays mirror Mobius_mesh: halfedges 2e and 2e+1 of edge e, `next`/`prev`
// hold dart bits (halfedge << 1 | flipped), face cycles are unflipped.
struct Level
{
  u32 nv = 0, ne = 0, nf = 0, nc = 0;
  Array<u32> h_target, h_next, h_prev, h_face;
  Array<std::uint8_t> e_mobius;
  Array<u32> v_dart, f_first;
  // Corners are the face halfedges numbered face by face: the corners of face
  // f are [f_offset[f], f_offset[f+1]) in cycle order from f_first[f].
  // Empty in a level that is neither split nor interpolated from (the last
  // level of a one-pass refinement), as nothing but the mesh is made of it.
  Array<u32> f_offset, corner_h;
  // The corner of each face halfedge (null on the border): read by the dual
  // and √3 splits and by the walk that makes a base level's incidence tables
  // (Incidence.h), filled only by fill_level(), which builds those levels.
  Array<u32> h_corner;
  // Sharpness: empty when `sharp` is false, meaning every edge and vertex is
  // smooth (and there is no border, whose edges are infinitely sharp).
  bool sharp = false;
  Array<float> e_sharp, v_sharp;
  Array<std::uint8_t> f_hole; // empty if no face is a hole
  // The degree of every face, where the split that made the level gives all
  // its faces one (quads, triangles); 0 otherwise.
  u32 face_degree = 0;

  // What resize() allocates besides the connectivity.
  enum Parts : unsigned { corner_table = 1, sharpness = 2, halfedge_corners = 4 };

  void resize(u32 v, u32 e, u32 f, u32 c, unsigned parts)
  {
    nv = v;
    ne = e;
    nf = f;
    nc = c;
    face_degree = 0;
    sharp = (parts & sharpness) != 0;
    // Old contents are not kept: cleared first, a growing array is not copied.
    for (auto* a : {&h_target, &h_next, &h_prev, &h_face, &h_corner, &v_dart, &f_first, &f_offset, &corner_h})
      a->clear();
    e_mobius.clear();
    e_sharp.clear();
    v_sharp.clear();
    h_target.resize(2 * std::size_t(e));
    h_next.resize(2 * std::size_t(e));
    h_prev.resize(2 * std::size_t(e));
    h_face.resize(2 * std::size_t(e));
    e_mobius.resize(e);
    v_dart.resize(v);
    f_first.resize(f);
    if (parts & corner_table) {
      f_offset.resize(std::size_t(f) + 1);
      corner_h.resize(c);
    }
    if (parts & halfedge_corners)
      h_corner.resize(2 * std::size_t(e));
    if (sharp) {
      e_sharp.resize(e);
      v_sharp.resize(v);
    }
  }

  // Forgets the sharpness (all of it is zero).
  void drop_sharpness()
  {
    sharp = false;
    decltype(e_sharp)().swap(e_sharp);
    decltype(v_sharp)().swap(v_sharp);
  }

  // Dart navigation, as in Mobius_mesh.
  bool is_border_dart(u32 d) const { return h_face[dart_encoding::halfedge_of_dart(d)] == null_u32; }
  u32 source_of(u32 h) const
  {
    namespace de = dart_encoding;
    return e_mobius[de::edge_of_halfedge(h)] ? h_target[de::halfedge_of_dart(h_prev[h])]
                                             : h_target[de::opposite_halfedge(h)];
  }
  u32 target(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    return dart_encoding::is_flipped(d) ? source_of(h) : h_target[h];
  }
  u32 source(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    return dart_encoding::is_flipped(d) ? h_target[h] : source_of(h);
  }
  u32 next(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    return dart_encoding::is_flipped(d) ? dart_encoding::flip(h_prev[h]) : h_next[h];
  }
  u32 prev(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    return dart_encoding::is_flipped(d) ? dart_encoding::flip(h_next[h]) : h_prev[h];
  }
  u32 opposite(u32 d) const
  {
    return dart_encoding::opposite_dart(d, e_mobius[dart_encoding::edge_of_dart(d)] != 0);
  }
  u32 degree(u32 f) const { return f_offset[f + 1] - f_offset[f]; }
  // Calls body(d) for each dart d that ends at vertex v, in the order of the
  // walk around v: one per end of an edge at v (an edge from v to v twice).
  template <class Body>
  void for_each_dart_at(u32 v, const Body& body) const
  {
    const u32 d0 = v_dart[v];
    if (d0 == null_u32)
      return;
    u32 d = d0;
    do {
      body(d);
      d = opposite(next(d));
    } while (d != d0);
  }

  // Child halfedges of parent halfedge h: the half at h's source and the half
  // at its target. Child edge 2e lies at source(2e), 2e+1 at target(2e); on a
  // Möbius edge both halfedges run the same way, so 2e+1 starts at the source.
  u32 first_child(u32 h) const
  {
    const u32 e = dart_encoding::edge_of_halfedge(h);
    if (is_first_halfedge(h))
      return dart_encoding::halfedge_of_edge(2 * e, 0);
    return e_mobius[e] ? dart_encoding::halfedge_of_edge(2 * e, 1) : dart_encoding::halfedge_of_edge(2 * e + 1, 1);
  }
  // The other child of the parent halfedge of `child`: the children of a
  // halfedge of edge e are 4e + i and 4e + 2 + i, which differ in bit 1.
  static u32 other_child(u32 child) { return child ^ 2u; }
  u32 second_child(u32 h) const
  {
    const u32 e = dart_encoding::edge_of_halfedge(h);
    if (is_first_halfedge(h))
      return dart_encoding::halfedge_of_edge(2 * e + 1, 0);
    return e_mobius[e] ? dart_encoding::halfedge_of_edge(2 * e + 1, 1) : dart_encoding::halfedge_of_edge(2 * e, 1);
  }
  // The child dart that starts where parent dart d starts / ends where it
  // ends, with d's orientation.
  u32 child_dart_from_source(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    const bool flipped = dart_encoding::is_flipped(d);
    return dart_encoding::dart(flipped ? second_child(h) : first_child(h), flipped);
  }
  u32 child_dart_to_target(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    const bool flipped = dart_encoding::is_flipped(d);
    return dart_encoding::dart(flipped ? first_child(h) : second_child(h), flipped);
  }
};

// What the engine (face-varying interpolation) and the white-box tests read
// of a Refiner beyond its interface: the arrays of its levels, their
// incidence tables and how their vertex weights group their sums.
struct Refiner_access
{
  template <class Refiner>
  static const Level& level(const Refiner& r, unsigned k)
  {
    return r.level(k);
  }
  // The incidence tables of level k, null if the refiner has none for it.
  template <class Refiner>
  static auto incidence(const Refiner& r, unsigned k)
  {
    return r.incidence_tables(k);
  }
  // How the vertex weights of step k group their sums (Weights.h's Vertex_sums).
  template <class Refiner>
  static const auto& vertex_sums(const Refiner& r, unsigned k)
  {
    return r.weights_[k].sums;
  }
};

// The arrays of level `k` of refiner `r`.
template <class Refiner>
const Level& level_of(const Refiner& r, unsigned k)
{
  return Refiner_access::level(r, k);
}

// The unflipped dart of halfedge h: how face cycles are linked.
constexpr u32 face_dart(u32 h) { return dart_encoding::dart(h, false); }

// The first element of an array of a Level or a Mesh_writer.
template <class T>
T* data_of(Array<T>& a)
{
  return a.data();
}
template <class T>
T* data_of(T* a)
{
  return a;
}

// Links dart `a` to dart `b` in a level or a Mesh_writer, as Mobius_mesh::set_next().
template <class Child>
void link(Child& c, u32 a, u32 b)
{
  namespace de = dart_encoding;
  if (de::is_flipped(a))
    c.h_prev[de::halfedge_of_dart(a)] = de::flip(b);
  else
    c.h_next[de::halfedge_of_dart(a)] = b;
  if (de::is_flipped(b))
    c.h_next[de::halfedge_of_dart(b)] = de::flip(a);
  else
    c.h_prev[de::halfedge_of_dart(b)] = a;
}

// Writes `first` and `second` to the entries h and h + 1 of `array` (h even:
// the two halfedges of an edge) in one 8-byte store. The splits are bound by
// the number of stores: the compiler does not merge two of values it computes.
template <class Array_or_pointer>
inline void store_halfedge_pair(Array_or_pointer& array, u32 h, u32 first, u32 second)
{
  const u32 pair[2] = {first, second};
  std::memcpy(data_of(array) + h, pair, sizeof(pair));
}

// Stands for the last level of a refinement in the splits, which then write
// its connectivity straight into the arrays of `mesh`: that level is not
// made twice. It has no corner table.
template <class Mesh>
struct Mesh_writer
{
  explicit Mesh_writer(Mesh& m) : mesh(m) {}

  Mesh& mesh;
  u32 nv = 0, ne = 0, nf = 0, nc = 0;
  u32 *h_target = nullptr, *h_next = nullptr, *h_prev = nullptr, *h_face = nullptr;
  std::uint8_t* e_mobius = nullptr;
  u32 *v_dart = nullptr, *f_first = nullptr;
  u32 *f_offset = nullptr, *corner_h = nullptr;
  Array<std::uint8_t> f_hole;
  u32 face_degree = 0;

  void resize(u32 v, u32 e, u32 f, u32 c, unsigned parts)
  {
    CGAL_precondition(parts == 0); // no corner table
    CGAL_USE(parts);
    nv = v;
    ne = e;
    nf = f;
    nc = c;
    const auto a = CGAL_ext::internal::Connectivity_access::overwrite(mesh, v, e, f);
    h_target = a.target;
    h_next = a.next_bits;
    h_prev = a.prev_bits;
    h_face = a.face;
    e_mobius = a.mobius;
    v_dart = a.vertex_dart_bits;
    f_first = a.face_halfedge;
  }
};

// `origin` (a value per face of `p`, such as the base face it lies in)
// carried to the faces of p's child by a quad or triangle split, which
// replaces it. The split's layout: child face c is the one at parent corner
// c, and the triangle split's centre triangles follow the corners.
template <class ConcurrencyTag, Split S>
void child_face_origins(const Level& p, std::vector<u32>& origin, std::vector<u32>& scratch)
{
  static_assert(S == Split::quad || S == Split::triangle, "the faces of the other splits have no single parent");
  scratch.resize(S == Split::triangle ? p.nc + p.nf : p.nc);
  for_each_index<ConcurrencyTag>(p.nf, [&](u32 f) {
    for (u32 c = p.f_offset[f]; c < p.f_offset[f + 1]; ++c)
      scratch[c] = origin[f];
    if constexpr (S == Split::triangle)
      scratch[p.nc + f] = origin[f];
  });
  origin.swap(scratch);
}

// Completes a level whose connectivity is written: no sharpness, no holes,
// corners numbered face by face from each face's first halfedge (the
// offsets are the face degrees' prefix sums, so that the faces may be
// walked in parallel).
template <class ConcurrencyTag = CGAL::Sequential_tag>
void index_corners(Level& L)
{
  namespace de = dart_encoding;
  for_each_index<ConcurrencyTag>(2 * L.ne, [&](u32 h) { L.h_corner[h] = null_u32; });
  for_each_index<ConcurrencyTag>(u32(L.e_sharp.size()), [&](u32 e) { L.e_sharp[e] = 0.0f; });
  for_each_index<ConcurrencyTag>(u32(L.v_sharp.size()), [&](u32 v) { L.v_sharp[v] = 0.0f; });
  L.f_offset[0] = 0;
  for_each_index<ConcurrencyTag>(L.nf, [&](u32 f) {
    u32 n = 0, h = L.f_first[f];
    do {
      ++n;
      h = de::halfedge_of_dart(L.h_next[h]);
    } while (h != L.f_first[f]);
    L.f_offset[f + 1] = n;
  });
  prefix_sum<ConcurrencyTag>(L.f_offset.data(), L.nf);
  for_each_index<ConcurrencyTag>(L.nf, [&](u32 f) {
    u32 k = L.f_offset[f], h = L.f_first[f];
    do {
      L.corner_h[k] = h;
      L.h_corner[h] = k;
      ++k;
      h = de::halfedge_of_dart(L.h_next[h]);
    } while (h != L.f_first[f]);
  });
  L.f_hole.clear();
}

// The connectivity of `m` as a level (sharpness 0, no holes).
template <class ConcurrencyTag = CGAL::Sequential_tag, class P>
void fill_level(const Mobius_mesh<P>& m, Level& L)
{
  const u32 nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  const u32 nc = count_if<ConcurrencyTag>(2 * ne, [&](u32 h) { return !m.is_border(Halfedge_index(h)); });
  L.resize(nv, ne, nf, nc, Level::corner_table | Level::sharpness | Level::halfedge_corners);
  for_each_index<ConcurrencyTag>(2 * ne, [&](u32 h) {
    const Dart d(Halfedge_index(h), false);
    L.h_target[h] = m.target(d).idx();
    L.h_next[h] = m.next(d).bits();
    L.h_prev[h] = m.prev(d).bits();
    const Face_index f = m.face(d);
    L.h_face[h] = f.is_valid() ? f.idx() : null_u32;
  });
  for_each_index<ConcurrencyTag>(ne, [&](u32 e) { L.e_mobius[e] = m.is_mobius(Edge_index(e)) ? 1 : 0; });
  for_each_index<ConcurrencyTag>(nv, [&](u32 v) { L.v_dart[v] = m.halfedge(Vertex_index(v)).bits(); });
  for_each_index<ConcurrencyTag>(nf, [&](u32 f) { L.f_first[f] = m.halfedge(Face_index(f)).halfedge().idx(); });
  index_corners<ConcurrencyTag>(L);
}

// What both splits share: parent edges split in two, parent vertices keep
// their index, border loops and Möbius bits are inherited. Each parent
// halfedge writes only the entries of its own two children: a border link
// also touches the neighbour's child, whose own iteration writes the same
// value, so every entry has one writer and the loops may run in parallel.
template <class ConcurrencyTag, class Child>
void split_edges_and_border(const Level& p, Child& c, u32 edge_point_offset)
{
  // The border loop of parent halfedge h (with no face), h0 its first
  // child: h0 -> h1 -> (child of the next border halfedge), and (child of
  // the previous one) -> h0, as link() would set them here.
  auto split_border_halfedge = [&](u32 h, u32 h0) {
    const u32 h1 = Level::other_child(h0);
    c.h_face[h0] = c.h_face[h1] = null_u32;
    c.h_next[h0] = face_dart(h1);
    c.h_prev[h1] = face_dart(h0);
    c.h_next[h1] = p.child_dart_from_source(p.h_next[h]);
    c.h_prev[h0] = p.child_dart_to_target(p.h_prev[h]);
  };
  // An edge and its two halfedges in one loop: one fork and join fewer.
  for_each_index<ConcurrencyTag>(p.ne, [&, edge_point_offset](u32 e) {
    const u32 h0 = dart_encoding::halfedge_of_edge(e, 0), h1 = dart_encoding::halfedge_of_edge(e, 1);
    const u32 first0 = p.first_child(h0), first1 = p.first_child(h1);
    // The targets of the edge's four children, 4e to 4e + 3, in one store
    // (the splits are bound by their stores): the first child of each
    // halfedge ends at the edge point, the second where the halfedge ends.
    // first0 is 4e; first1 is 4e + 1 on a Möbius edge, 4e + 3 otherwise.
    const u32 edge_point = edge_point_offset + e, end0 = p.h_target[h0], end1 = p.h_target[h1];
    const bool first1_is_1 = (first1 & 2u) == 0;
    const u32 targets[4] = {edge_point, first1_is_1 ? edge_point : end1, end0, first1_is_1 ? end1 : edge_point};
    std::memcpy(data_of(c.h_target) + 4 * std::size_t(e), targets, sizeof(targets));
    const bool border0 = p.h_face[h0] == null_u32, border1 = p.h_face[h1] == null_u32;
    if (border0)
      split_border_halfedge(h0, first0);
    if (border1)
      split_border_halfedge(h1, first1);
    // The edge point's dart: on the border halfedge, if the edge has one.
    c.v_dart[edge_point] = face_dart(!border0 && border1 ? first1 : first0);
  });
  for_each_index<ConcurrencyTag>(
    p.nv, [&](u32 v) { c.v_dart[v] = p.v_dart[v] == null_u32 ? null_u32 : p.child_dart_to_target(p.v_dart[v]); });
  // The Möbius bits in loops of their own, through addresses held in local
  // variables: a store of a byte may alias any object, so the compiler
  // reloads after it every address it reads from memory. The inner edges
  // (one per parent corner) have none.
  for_each_block<ConcurrencyTag>(p.ne, [&](u32 begin, u32 end) {
    const std::uint8_t* const parent = p.e_mobius.data();
    std::uint8_t* const child = data_of(c.e_mobius);
    for (u32 e = begin; e != end; ++e) { // both halves in one store
      const std::uint16_t halves = std::uint16_t(parent[e] * 0x101u);
      std::memcpy(child + 2 * std::size_t(e), &halves, sizeof(halves));
    }
  });
  for_each_block<ConcurrencyTag>(p.nc, [&](u32 begin, u32 end) {
    std::uint8_t* const inner = data_of(c.e_mobius) + 2 * std::size_t(p.ne);
    std::fill(inner + begin, inner + end, std::uint8_t(0));
  });
}

// The holes of a child: each child face of a parent face that is a hole
// (corner faces c, and the centre faces nc + f of the triangle split).
template <class ConcurrencyTag, class Child>
void inherit_holes(const Level& p, Child& c, u32 child_faces, bool centres)
{
  if (p.f_hole.empty()) {
    c.f_hole.clear();
    return;
  }
  c.f_hole.resize(child_faces);
  for_each_index<ConcurrencyTag>(p.nf, [&](u32 f) {
    for (u32 k = p.f_offset[f]; k < p.f_offset[f + 1]; ++k)
      c.f_hole[k] = p.f_hole[f];
    if (centres)
      c.f_hole[p.nc + f] = p.f_hole[f];
  });
}

// Calls body(std::true_type()) or body(std::false_type()), so that a flag
// tested in an inner loop is a constant there.
template <class Body>
void with_flag(bool flag, const Body& body)
{
  if (flag)
    body(std::true_type());
  else
    body(std::false_type());
}

// Calls body(std::integral_constant<u32, i>()) for i = 0, ..., N − 1: a loop
// whose index is a constant in each copy of its body.
template <class Body, u32... I>
void unroll(const Body& body, std::integer_sequence<u32, I...>)
{
  (body(std::integral_constant<u32, I>()), ...);
}
template <u32 N, class Body>
void unroll(const Body& body)
{
  unroll(body, std::make_integer_sequence<u32, N>());
}

// Catmull–Clark / bilinear split: child vertices [vertex points | edge points
// | face points]; child edges [2e, 2e+1 halves of parent edge e | one inner
// edge per parent corner c at 2ne + c]; child face c is the quad at corner c.
// Faces write disjoint parts of the child, so they may be split in parallel.
// The child (a Level or a Mesh_writer) gets a corner table if
// `corner_table`; its sharpness is left to the caller.
template <class ConcurrencyTag = CGAL::Sequential_tag, class Child>
void quad_split(const Level& p, Child& c, bool corner_table)
{
  const u32 ne = p.ne, nv = p.nv, nf = p.nf, nc = p.nc;
  c.resize(nv + ne + nf, 2 * ne + nc, nc, 4 * nc, corner_table ? Level::corner_table : 0u);
  c.face_degree = 4;
  split_edges_and_border<ConcurrencyTag>(p, c, nv);
  const u32 fp = nv + ne;
  with_flag(corner_table, [&](auto with_corners) {
    for_each_index<ConcurrencyTag>(nf, [&](u32 f) {
      const u32 k0 = p.f_offset[f], k1 = p.f_offset[f + 1];
      namespace de = dart_encoding;
      c.v_dart[fp + f] = face_dart(de::halfedge_of_edge(2 * ne + k0, 0));
      for (u32 k = k0; k < k1; ++k) {
        const u32 kn = (k + 1 == k1) ? k0 : k + 1, kp = (k == k0) ? k1 - 1 : k - 1;
        // Corners run in cycle order: the next halfedge is the next corner's,
        // read in order rather than through h_next at a scattered index.
        const u32 h = p.corner_h[k], hn = p.corner_h[kn];
        const u32 ie = 2 * ne + k;
        // Quad k, at the corner where h ends: vertex point, edge point of
        // hn, face point, edge point of h.
        const u32 q[4] = {p.first_child(hn), de::halfedge_of_edge(2 * ne + kn, 0), de::halfedge_of_edge(ie, 1),
                          p.second_child(h)};
        // Inner edge ie, written whole (its halfedges together): halfedge 0
        // runs to the face point in quad kp, from the first child of h to
        // the inner edge of corner kp; halfedge 1 to the edge point of h in
        // quad k (q[2]).
        const u32 h_first = Level::other_child(q[3]), inner = de::halfedge_of_edge(ie, 0);
        store_halfedge_pair(c.h_target, inner, fp + f, nv + de::edge_of_halfedge(h));
        store_halfedge_pair(c.h_next, inner, face_dart(de::halfedge_of_edge(2 * ne + kp, 1)), face_dart(q[3]));
        store_halfedge_pair(c.h_prev, inner, face_dart(h_first), face_dart(q[1]));
        store_halfedge_pair(c.h_face, inner, kp, k);
        for (int i = 0; i < 4; i += 3) { // the halves of the parent's edges
          c.h_next[q[i]] = face_dart(q[(i + 1) % 4]);
          c.h_prev[q[i]] = face_dart(q[(i + 3) % 4]);
          c.h_face[q[i]] = k;
        }
        c.f_first[k] = q[0];
        if constexpr (decltype(with_corners)::value) {
          for (u32 i = 0; i < 4; ++i)
            c.corner_h[4 * k + i] = q[i];
          c.f_offset[k] = 4 * k;
        }
      }
    });
  });
  if (corner_table)
    c.f_offset[nc] = 4 * nc;
  inherit_holes<ConcurrencyTag>(p, c, nc, false);
}

// Loop / linear triangle split (triangles only): child vertices [vertex
// points | edge points]; child edges [halves | inner edge 2ne + c opposite
// corner c]; child faces [corner triangle c | centre triangle nc + f].
// Child, corner table and sharpness as quad_split().
template <class ConcurrencyTag = CGAL::Sequential_tag, class Child>
void triangle_split(const Level& p, Child& c, bool corner_table)
{
  const u32 ne = p.ne, nv = p.nv, nf = p.nf, nc = p.nc;
  c.resize(nv + ne, 2 * ne + nc, nc + nf, 3 * (nc + nf), corner_table ? Level::corner_table : 0u);
  c.face_degree = 3;
  split_edges_and_border<ConcurrencyTag>(p, c, nv);
  with_flag(corner_table, [&](auto with_corners) {
    constexpr bool corners = decltype(with_corners)::value;
    for_each_index<ConcurrencyTag>(nf, [&](u32 f) {
      namespace de = dart_encoding;
      const u32 k0 = p.f_offset[f];
      const u32 centre = nc + f;
      unroll<3>([&](auto corner) {
        constexpr u32 i = decltype(corner)::value, i_next = (i + 1) % 3;
        const u32 k = k0 + i, kn = k0 + i_next;
        const u32 h = p.corner_h[k], hn = p.corner_h[kn];
        const u32 ie = 2 * ne + k;
        // Inner edge ie, across corner k: halfedge 0 (in the corner triangle)
        // to the edge point of h, 1 (in the centre one, whose halfedges run
        // from edge point to edge point) to that of hn. Its two halfedges
        // are written together.
        const u32 q[3] = {p.first_child(hn), de::halfedge_of_edge(ie, 0), p.second_child(h)};
        const u32 in = de::halfedge_of_edge(ie, 1), in_next = de::halfedge_of_edge(2 * ne + kn, 1),
                  in_prev = de::halfedge_of_edge(2 * ne + k0 + (i + 2) % 3, 1);
        store_halfedge_pair(c.h_target, q[1], nv + de::edge_of_halfedge(h), nv + de::edge_of_halfedge(hn));
        store_halfedge_pair(c.h_next, q[1], face_dart(q[2]), face_dart(in_next));
        store_halfedge_pair(c.h_prev, q[1], face_dart(q[0]), face_dart(in_prev));
        store_halfedge_pair(c.h_face, q[1], k, centre);
        for (u32 j = 0; j < 3; j += 2) { // the halves of the parent's edges
          c.h_next[q[j]] = face_dart(q[(j + 1) % 3]);
          c.h_prev[q[j]] = face_dart(q[(j + 2) % 3]);
          c.h_face[q[j]] = k;
        }
        c.f_first[k] = q[0];
        if constexpr (corners) {
          for (u32 j = 0; j < 3; ++j)
            c.corner_h[3 * k + j] = q[j];
          c.f_offset[k] = 3 * k;
          c.corner_h[3 * centre + i] = in;
        }
      });
      c.f_first[centre] = de::halfedge_of_edge(2 * ne + k0, 1);
      if constexpr (corners)
        c.f_offset[centre] = 3 * centre;
    });
  });
  if (corner_table)
    c.f_offset[nc + nf] = 3 * (nc + nf);
  inherit_holes<ConcurrencyTag>(p, c, nc + nf, true);
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_LEVEL_H
