// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The limit surface of a corner channel, as OpenSubdiv's Bfr makes a
// face-varying surface (SurfaceFactory::InitFaceVaryingSurface()): the
// channel's values are the control points of a surface over the channel's
// own topology, the mesh cut open along the channel's seams, with the
// sharpness that the face-varying interpolation mode gives its values.
//
// That topology is a mesh of its own here, the channel's cage: a vertex per
// value of each vertex (OpenSubdiv's sibling), the faces of the mesh in the
// same order and orientation, each starting at the same corner, so that a
// face's (u, v) means the same on both; a seam is a border of the cage. Its
// sharpness is the mesh's, but where the face-varying interpolation mode
// makes a value a corner of the channel, by Bfr's rules for a face-varying
// subset (is_channel_corner()): its seam's two edges make any other value
// on a seam a crease of the cage, the semi-sharp edges of its faces a
// corner until they are spent. The points of the cage are the values, up to
// three coordinates at a time (a "lane"): the limit surface machinery is
// that of the mesh's points.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_CHANNEL_CAGE_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_CHANNEL_CAGE_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/internal/Face_varying.h>
#include <CGAL_ext/Subdivision/internal/Limit_face_varying.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace internal {

// The coordinates of a channel value of type T in the kernel's number type
// FT: `dimension` of them, `split()` and `join()` between the two.
template <class K, class T, class = void>
struct Channel_coordinates
{
  static constexpr bool defined = false;
};
template <class K, class T>
struct Channel_coordinates<K, T, std::enable_if_t<std::is_floating_point_v<T>>>
{
  static constexpr bool defined = true;
  static constexpr std::size_t dimension = 1;
  using FT = typename K::FT;
  static std::array<FT, 1> split(const T& t) { return {FT(t)}; }
  static T join(const std::array<FT, 1>& c) { return T(CGAL::to_double(c[0])); }
};
template <class K, class E, std::size_t N>
struct Channel_coordinates<K, std::array<E, N>, std::enable_if_t<std::is_floating_point_v<E>>>
{
  static constexpr bool defined = true;
  static constexpr std::size_t dimension = N;
  using FT = typename K::FT;
  static std::array<FT, N> split(const std::array<E, N>& t)
  {
    std::array<FT, N> c;
    for (std::size_t i = 0; i < N; ++i)
      c[i] = FT(t[i]);
    return c;
  }
  static std::array<E, N> join(const std::array<FT, N>& c)
  {
    std::array<E, N> t;
    for (std::size_t i = 0; i < N; ++i)
      t[i] = E(CGAL::to_double(c[i]));
    return t;
  }
};
// The kernel's 2D and 3D points and vectors (is_kernel_point/_vector of
// Linear_values.h, the types a channel interpolates).
template <class K, class T>
struct Channel_coordinates<K, T, std::enable_if_t<is_kernel_point<K, T> || is_kernel_vector<K, T>>>
{
  static constexpr bool defined = true;
  static constexpr std::size_t dimension =
    std::is_same_v<T, typename K::Point_2> || std::is_same_v<T, typename K::Vector_2> ? 2 : 3;
  using FT = typename K::FT;
  static std::array<FT, dimension> split(const T& t)
  {
    std::array<FT, dimension> c;
    for (std::size_t i = 0; i < dimension; ++i)
      c[i] = t.cartesian(int(i));
    return c;
  }
  static T join(const std::array<FT, dimension>& c)
  {
    if constexpr (dimension == 2)
      return T(c[0], c[1]);
    else
      return T(c[0], c[1], c[2]);
  }
};

// The cage of a channel (see the top of this file), its points left at the
// origin: `value_of[c]` is the channel's value index at cage vertex c,
// `edge_of[e]` the mesh's edge of cage edge e.
template <class P>
struct Channel_cage
{
  Mobius_mesh<P> mesh;
  std::vector<std::uint32_t> value_of, edge_of;
  bool linear = false; // the mode is Face_varying_interpolation::all: the channel is linear in each face
};

// Cage vertex per face corner (the vertex values of F), face after face
// from its first dart.
template <class P>
Face_list channel_cage_faces(const Mobius_mesh<P>& mesh, const Subdivision::internal::Fvar_level& F)
{
  Face_list faces;
  std::vector<std::uint32_t> corners;
  for (Face_index f : mesh.faces()) {
    corners.clear();
    for (Dart d : halfedges_around_face(mesh.halfedge(f), mesh))
      corners.push_back(F.corner[mesh.corner(d).idx()]);
    faces.add(corners.begin(), corners.end());
  }
  return faces;
}

// Each face of the cage starts at the corner its face of `mesh` starts at;
// the cage's edges learn their edges of `mesh`, and take their sharpness.
template <class P>
void align_channel_cage(const Mobius_mesh<P>& mesh, const Subdivision::internal::Level& L,
                        const Subdivision::internal::Fvar_level& F, const std::vector<std::uint32_t>& original,
                        Channel_cage<P>& cage)
{
  Mobius_mesh<P>& c = cage.mesh;
  cage.edge_of.assign(c.number_of_edges(), 0);
  auto sharpness = c.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first;
  const auto value_at = [&](Dart m) { return F.corner[mesh.corner(m).idx()]; };
  for (Face_index f : mesh.faces()) {
    // The builder may start the face at another of the corners listed.
    Dart d = c.halfedge(f);
    for (std::size_t k = 0; k < mesh.degree(f) && original[c.target(d).idx()] != value_at(mesh.halfedge(f)); ++k)
      d = c.next(d);
    c.set_halfedge(f, d.halfedge());
    Dart m = mesh.halfedge(f);
    for (std::size_t k = 0; k < mesh.degree(f); ++k, d = c.next(d), m = mesh.next(m)) {
      if (original[c.target(d).idx()] != value_at(m))
        throw Parameter_error("Limit_surface: internal error, the channel's cage does not follow face f" +
                              std::to_string(f.idx()));
      const std::uint32_t e = mesh.edge(m).idx();
      cage.edge_of[c.edge(d).idx()] = e;
      sharpness[c.edge(d)] = L.e_sharp.empty() ? 0.0f : L.e_sharp[e];
    }
  }
}

// What Bfr's rules for a face-varying subset read of one value at a vertex
// (one vertex of the cage).
struct Channel_value_ring
{
  std::size_t faces = 0;         // the value's faces round its vertex here
  std::size_t value_faces = 0;   // the faces of that value round the vertex, here or not
  std::size_t vertex_faces = 0;  // the faces round the vertex
  std::size_t values = 0;        // the vertex's values
  std::size_t other_spans = 1;   // where the vertex has two values, the spans of the other
  bool on_seam = false;          // the value's faces stop at a seam or a border
  bool vertex_on_border = false; // the vertex lies on the mesh's border
  bool sharp_inside = false;     // a sharp edge between two of the value's faces
  bool sharp_at_vertex = false;  // a sharp edge between two faces round the vertex
  float vertex_sharpness = 0.0f;
  float outside_sharpness = 0.0f; // the sharpest edge between two faces round the vertex, but the value's own seams
};

// The sharpness Bfr gives a value (FaceVertex::FindFaceVaryingSubset() and
// FaceSurface::sharpenBySdcFVarLinearInterpolation() of OpenSubdiv 3.5): a
// value met again past its faces is a corner; on a seam or a border, the
// mode's rules: corners-only sharpens a value on one face, corners-plus1
// also every value of a vertex with three or more subsets of faces, and
// gives a value without sharp edges the sharpness of its sibling's
// ("dependent sharpness"), corners-plus2 also a dart (a seam ending inside)
// and a value whose sibling is on a single face, boundaries every value.
inline float channel_value_sharpness(Face_varying_interpolation mode, const Channel_value_ring& r)
{
  using F = Face_varying_interpolation;
  const float infinite = infinitely_sharp;
  if (r.faces < r.value_faces)
    return infinite;
  if (!r.on_seam)
    return r.vertex_sharpness;
  const bool corner = r.faces == 1, more_than_two = r.values > 2 || (r.values == 2 && r.other_spans > 1);
  const bool dependent = r.vertex_faces - r.faces > 1 && r.sharp_at_vertex && !r.sharp_inside;
  const float depending = dependent && r.outside_sharpness > r.vertex_sharpness ? r.outside_sharpness : r.vertex_sharpness;
  switch (mode) {
  case F::none: return r.vertex_sharpness;
  case F::corners_only: return corner ? infinite : r.vertex_sharpness;
  case F::corners_plus1: return corner || more_than_two ? infinite : depending;
  case F::corners_plus2: {
    if (corner || more_than_two)
      return infinite;
    const std::size_t others = r.vertex_faces - r.faces;
    if (others == 0)
      return r.vertex_on_border ? r.vertex_sharpness : infinite; // a dart
    return others == 1 ? infinite : depending;
  }
  case F::boundaries:
  case F::all: return infinite;
  }
  return r.vertex_sharpness;
}

// The sharpness of each vertex of the cage (channel_value_sharpness()); the
// channel's creases need no rule of their own: a seam is a border of the
// cage, and the sharp edges of a value's faces are in the cage with their
// sharpness.
template <class P>
void sharpen_channel_cage(const Mobius_mesh<P>& mesh, const Subdivision::internal::Level& L,
                          const Subdivision::internal::Fvar_level& F, Face_varying_interpolation mode,
                          const std::vector<std::uint32_t>& original, const std::vector<std::uint32_t>& vertex_of,
                          Channel_cage<P>& cage)
{
  const Mobius_mesh<P>& c = cage.mesh;
  const auto edge_sharpness = [&](std::uint32_t e) { return L.e_sharp.empty() ? 0.0f : L.e_sharp[e]; };
  std::vector<std::uint32_t> spans(F.v_offset[L.nv], 0), value_faces(F.v_offset[L.nv], 0);
  for (Vertex_index x : c.vertices())
    ++spans[original[x.idx()]];
  for (Halfedge_index h : mesh.halfedges())
    if (!mesh.is_border(h))
      ++value_faces[F.corner[h.idx()]];
  auto vs = cage.mesh.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first;
  std::vector<std::uint32_t> seams;
  for (Vertex_index x : c.vertices()) {
    const std::uint32_t value = original[x.idx()], v = vertex_of[value];
    Channel_value_ring r;
    r.value_faces = value_faces[value];
    r.values = F.v_offset[v + 1] - F.v_offset[v];
    if (r.values == 2)
      r.other_spans = spans[value == F.v_offset[v] ? value + 1 : F.v_offset[v]];
    r.vertex_on_border = mesh.is_border(Vertex_index(v));
    r.vertex_sharpness = L.v_sharp.empty() ? 0.0f : L.v_sharp[v];
    seams.clear();
    for (Dart d : halfedges_around_target(c.halfedge(x), c)) {
      r.faces += c.is_border(d) ? 0 : 1;
      if (c.is_border(c.edge(d)))
        seams.push_back(cage.edge_of[c.edge(d).idx()]);
      else
        r.sharp_inside = r.sharp_inside || edge_sharpness(cage.edge_of[c.edge(d).idx()]) > 0.0f;
    }
    r.on_seam = !seams.empty();
    for (Dart d : halfedges_around_target(mesh.halfedge(Vertex_index(v)), mesh)) {
      r.vertex_faces += mesh.is_border(d) ? 0 : 1;
      const std::uint32_t e = mesh.edge(d).idx();
      if (mesh.is_border(mesh.edge(d)) || !(edge_sharpness(e) > 0.0f))
        continue;
      r.sharp_at_vertex = true;
      if (std::find(seams.begin(), seams.end(), e) == seams.end())
        r.outside_sharpness = (std::max)(r.outside_sharpness, edge_sharpness(e));
    }
    vs[x] = channel_value_sharpness(mode, r);
  }
}

// The cage of the channel whose value index per halfedge is `user` (see
// base_corners()), with the mode `mode` and the mesh's sharpness and
// boundary interpolation from `np`.
template <class P, class NP>
Channel_cage<P> make_channel_cage(const char* function, const Mobius_mesh<P>& mesh, const std::vector<std::uint32_t>& user,
                                  Face_varying_interpolation mode, const NP& np)
{
  namespace si = Subdivision::internal;
  const si::Limit_settings<P, NP> s(mesh, np);
  const si::Fvar_rules rules(mode, boundary_interpolation_of(np));
  si::Level L;
  si::Fvar_level F;
  si::channel_topology(function, mesh, s, user, rules, L, F);
  Channel_cage<P> cage;
  cage.linear = rules.linear_all;
  const std::uint32_t n_values = F.v_offset[L.nv];
  const Face_list faces = channel_cage_faces(mesh, F);
  // A value met twice round its vertex (two spans) is a corner of the
  // channel: its spans become two vertices of the cage, both held.
  const std::vector<Split_vertex> copies =
    build_mesh_from_faces(faces.view(n_values), [](std::uint32_t) { return P(CGAL::ORIGIN); }, true, cage.mesh);
  std::vector<std::uint32_t> original(cage.mesh.number_of_vertices()), vertex_of(n_values);
  for (std::uint32_t v = 0; v < L.nv; ++v)
    for (std::uint32_t x = F.v_offset[v]; x < F.v_offset[v + 1]; ++x)
      vertex_of[x] = v;
  for (std::uint32_t x = 0; x < n_values; ++x)
    original[x] = x;
  for (std::size_t k = 0; k < copies.size(); ++k)
    original[n_values + k] = copies[k].original;
  align_channel_cage(mesh, L, F, original, cage);
  sharpen_channel_cage(mesh, L, F, mode, original, vertex_of, cage);
  cage.value_of.resize(original.size());
  for (std::size_t c = 0; c < original.size(); ++c)
    cage.value_of[c] = F.value(original[c]);
  return cage;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_CHANNEL_CAGE_H
