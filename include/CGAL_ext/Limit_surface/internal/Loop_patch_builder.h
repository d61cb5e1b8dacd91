// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The patches of one base triangle of a Loop surface, found as OpenSubdiv's
// Bfr finds them: a regular triangle is one quartic box-spline patch of the
// 12 points around it (beyond a border or an infinitely sharp crease the
// missing points are reflected, as OpenSubdiv's boundary weights do); any
// other triangle is refined, its neighbourhood copied and subdivided by the
// library's Loop rules, its four children treated in turn, down to the
// approximation levels, where an irregular triangle becomes OpenSubdiv's
// 18-point quartic Gregory triangle, built as its LoopPatchBuilder builds it.
// Everything is walked by darts, so a neighbourhood across a Möbius edge is
// that of the orientation double cover.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_LOOP_PATCH_BUILDER_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_LOOP_PATCH_BUILDER_H

#include <CGAL_ext/Limit_surface/internal/Patch_builder.h>
#include <CGAL_ext/Limit_surface/internal/Patches.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/internal/Limit_stencils.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/subdivision.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// The three darts of the triangle of frame d (d runs from corner 0 to corner 1).
template <class P>
std::array<Dart, 3> triangle_darts(const Mobius_mesh<P>& m, Dart d)
{
  return {d, m.next(d), m.next(m.next(d))};
}

// The 12 points of the box-spline patch of a regular triangle (see
// Box_spline_monomials for their layout). Around each corner the six
// neighbours, counter-clockwise from the next corner, are on the lattice
// where `around` says (the next and previous corners first); where the
// corner's span is bounded, the missing neighbours are reflected through
// the border, each from the two before it on its side (X = V + A - B), half
// from each end of the span: OpenSubdiv's phantom points.
template <class FT, class P>
void box_spline_points(const Mobius_mesh<P>& m, Dart d, const std::array<Corner, 3>& corners,
                       std::array<Coordinates<FT>, 20>& out)
{
  static const int corner_at[3] = {4, 5, 8};
  static const int around[3][6] = {{5, 8, 7, 3, 0, 1}, {8, 4, 1, 2, 6, 9}, {4, 5, 9, 11, 10, 7}};
  const auto dk = triangle_darts(m, d);
  bool known[12] = {};
  std::array<Coordinates<FT>, 6> ring[3];
  bool present[3][6] = {};
  for (int k = 0; k < 3; ++k) {
    // Full-ring position j is span index face_in_ring + j, turning round
    // the fan; the span holds indices 0 to its size - 1.
    const Corner& c = corners[k];
    for (int j = 0; j < 6; ++j) {
      const std::size_t i = (c.face_in_ring + unsigned(j)) % 6;
      if (i < c.ring.size()) {
        ring[k][j] = coordinates<FT>(m, c.ring[i]);
        present[k][j] = true;
      }
    }
  }
  for (int k = 0; k < 3; ++k) { // real points first: a phantom never replaces one
    out[corner_at[k]] = coordinates<FT>(m, m.source(dk[k]));
    known[corner_at[k]] = true;
    for (int j = 2; j < 6; ++j)
      if (present[k][j]) {
        out[around[k][j]] = ring[k][j];
        known[around[k][j]] = true;
      }
  }
  for (int k = 0; k < 3; ++k) {
    // The missing positions are a run inside 2..5 (the face is in the span):
    // the first half of the run is reflected from the trailing side, the
    // rest from the leading side.
    const Coordinates<FT> v = coordinates<FT>(m, m.source(dk[k]));
    auto reflect = [&](int j, int a, int b) {
      for (int x = 0; x < 3; ++x)
        ring[k][j][x] = v[x] + ring[k][a][x] - ring[k][b][x];
    };
    int missing = 0;
    for (int j = 2; j < 6; ++j)
      missing += present[k][j] ? 0 : 1;
    for (int j = 2, n = 0; j < 6 && n < (missing + 1) / 2; ++j)
      if (!present[k][j]) {
        reflect(j, j - 1, j - 2);
        ++n;
      }
    for (int j = 5, n = 0; j >= 2 && n < missing / 2; --j)
      if (!present[k][j]) {
        reflect(j, (j + 1) % 6, (j + 2) % 6);
        ++n;
      }
    for (int j = 2; j < 6; ++j)
      if (!known[around[k][j]]) {
        out[around[k][j]] = ring[k][j];
        known[around[k][j]] = true;
      }
  }
}

// What the Gregory triangle reads of a corner (LoopPatchBuilder's corner
// topology): "regular" here means six faces inside or three along a crease,
// not sharp; the face angle is that of an even fan.
struct Gregory_triangle_corner
{
  Vertex_index v;
  const Corner* c = nullptr;
  bool regular = false, boundary = false, sharp = false, single_face = false;
  bool ep_on_boundary = false, em_on_boundary = false;
  bool fp_regular = false, fm_regular = false, fp_copied = false, fm_copied = false;
  unsigned valence = 0, faces = 0, face_in_ring = 0;
  double cosine = 0.5;
};

inline std::array<Gregory_triangle_corner, 3> gregory_triangle_corners(const std::array<Corner, 3>& corners,
                                                                       const std::array<Vertex_index, 3>& cv)
{
  std::array<Gregory_triangle_corner, 3> g;
  for (int k = 0; k < 3; ++k) {
    Gregory_triangle_corner& x = g[k];
    x.v = cv[k];
    x.c = &corners[k];
    x.boundary = corners[k].boundary;
    x.sharp = corners[k].sharp;
    x.faces = corners[k].faces;
    x.face_in_ring = corners[k].face_in_ring;
    x.single_face = x.faces == 1;
    x.valence = x.faces + (x.boundary ? 1 : 0);
    x.regular = (x.faces << (x.boundary ? 1 : 0)) == 6 && !x.sharp;
    if (!x.regular)
      x.cosine = std::cos((x.boundary ? CGAL_PI : 2.0 * CGAL_PI) / double(x.faces));
  }
  for (int k = 0; k < 3; ++k) {
    Gregory_triangle_corner& x = g[k];
    x.fp_regular = x.regular && g[(k + 1) % 3].regular;
    x.fm_regular = x.regular && g[(k + 2) % 3].regular;
    if (!x.boundary)
      continue;
    x.ep_on_boundary = x.face_in_ring == 0;
    x.em_on_boundary = x.face_in_ring == x.faces - 1;
    if (x.faces == 1) { // a corner's face points are always the regular ones
      x.fp_regular = x.fm_regular = true;
      continue;
    }
    // Beside a border edge both face points are one, copied unless regular.
    if (x.ep_on_boundary) {
      x.fp_regular = x.fm_regular;
      x.fp_copied = !x.fp_regular;
    }
    if (x.em_on_boundary) {
      x.fm_regular = x.fp_regular;
      x.fm_copied = !x.fm_regular;
    }
  }
  return g;
}

// A ring of the library's limit masks for a corner's fan: `edges` edges,
// `faces` faces, smooth or a crease between the first and last edge.
template <class P>
Limit_ring<P> fan_ring(unsigned edges, unsigned faces, bool crease)
{
  Limit_ring<P> r;
  r.edge_ends.assign(edges, Vertex_index());
  r.face_corners.assign(faces, Vertex_index());
  r.rule = crease ? Crease::Rule::crease : Crease::Rule::smooth;
  r.crease_ends[0] = 0;
  r.crease_ends[1] = edges - 1;
  return r;
}

// Limit point and the two cubic edge points of an irregular corner that is
// not sharp, as rows on the corner and its ring: inside, the tangent along
// each edge scaled by Loop's subdominant eigenvalue; along a crease, the
// crease tangent and the interior tangent turned to the edge.
template <class P>
void irregular_edge_rows(const Gregory_triangle_corner& x, Row& p, Row& ep, Row& em)
{
  const Corner::Ring& ring = x.c->ring;
  Limit_mask<double> pm, t1, t2;
  if (!x.boundary) {
    const unsigned n = x.faces;
    const Limit_ring<P> r = fan_ring<P>(n, n, false);
    position_mask<Loop_mask, double>(r, pm);
    loop_tangent_masks(r, t1, t2);
    const double scale = (3.0 + 2.0 * std::cos(2.0 * CGAL_PI / double(n))) / (6.0 * double(n));
    std::vector<double> t(n);
    for (unsigned i = 0; i < n; ++i)
      t[i] = pm.edge[i] + t1.edge[i] * scale;
    p = {{x.v, pm.vertex}};
    ep = {{x.v, pm.vertex + t1.vertex * scale}};
    em = ep;
    for (unsigned i = 0; i < n; ++i) { // the tangent along ring edge j is the one along edge 0 turned by j
      p.push_back({ring[i], pm.edge[i]});
      ep.push_back({ring[i], t[(i + n - x.face_in_ring) % n]});
      em.push_back({ring[i], t[(i + 2 * n - x.face_in_ring - 1) % n]});
    }
    return;
  }
  const unsigned N = x.faces; // ring[0] and ring[N] lie on the crease
  const Limit_ring<P> r = fan_ring<P>(N + 1, N, true);
  position_mask<Loop_mask, double>(r, pm);
  loop_tangent_masks(r, t1, t2);
  p = {{x.v, pm.vertex}, {ring[0], pm.edge[0]}, {ring[N], pm.edge[N]}};
  auto edge_point = [&](Row& e, unsigned ring_edge) {
    const double a = CGAL_PI / double(N) * double(ring_edge), c = std::cos(a), s = std::sin(a);
    e = {{x.v, t2.vertex * s / 24.0 + pm.vertex}};
    for (unsigned i = 0; i <= N; ++i)
      e.push_back({ring[i], t2.edge[i] * s / 24.0});
    e.push_back({ring[0], pm.edge[0] + c / 6.0});
    e.push_back({ring[N], pm.edge[N] - c / 6.0});
  };
  if (x.ep_on_boundary)
    ep = {{x.v, 2.0 / 3.0}, {ring[0], 1.0 / 3.0}};
  else
    edge_point(ep, x.face_in_ring);
  if (x.em_on_boundary)
    em = {{x.v, 2.0 / 3.0}, {ring[N], 1.0 / 3.0}};
  else
    edge_point(em, (x.face_in_ring + 1) % (N + 1));
}

// The limit point and cubic edge points of corner k.
template <class P>
void gregory_triangle_edge_rows(const std::array<Gregory_triangle_corner, 3>& g, int k, Row& p, Row& ep, Row& em)
{
  const Gregory_triangle_corner& x = g[k];
  const Vertex_index next = g[(k + 1) % 3].v, prev = g[(k + 2) % 3].v;
  const Corner::Ring& r = x.c->ring;
  if (x.regular && !x.boundary) {
    static const double w[6] = {7, 5, 1, -1, 1, 5};
    p = {{x.v, 0.5}};
    ep = {{x.v, 0.5}};
    em = {{x.v, 0.5}};
    for (unsigned i = 0; i < 6; ++i) {
      p.push_back({r[i], 1.0 / 12.0});
      ep.push_back({r[(x.face_in_ring + i) % 6], w[i] / 36.0});
      em.push_back({r[(x.face_in_ring + 1 + i) % 6], w[i] / 36.0});
    }
  } else if (x.regular) { // three faces along a crease: the phantom points folded in
    p = {{x.v, 2.0 / 3.0}, {r[0], 1.0 / 6.0}, {r[3], 1.0 / 6.0}};
    const Row inner = {{x.v, 0.5}, {r[1], 1.0 / 6.0}, {r[2], 1.0 / 6.0}};
    if (x.ep_on_boundary)
      ep = {{x.v, 2.0 / 3.0}, {r[0], 1.0 / 3.0}};
    else
      (ep = inner).push_back({r[x.em_on_boundary ? 3 : 0], 1.0 / 6.0});
    if (x.em_on_boundary)
      em = {{x.v, 2.0 / 3.0}, {r[3], 1.0 / 3.0}};
    else
      (em = inner).push_back({r[x.ep_on_boundary ? 0 : 3], 1.0 / 6.0});
  } else if (x.sharp) { // OpenSubdiv's approximation
    p = {{x.v, 1.0}};
    ep = {{x.v, 2.0 / 3.0}, {next, 1.0 / 3.0}};
    em = {{x.v, 2.0 / 3.0}, {prev, 1.0 / 3.0}};
  } else if (x.boundary && x.single_face) { // a smooth corner of one face
    p = {{x.v, 4.0 / 6.0}, {next, 1.0 / 6.0}, {prev, 1.0 / 6.0}};
    ep = {{x.v, 2.0 / 3.0}, {next, 1.0 / 3.0}};
    em = {{x.v, 2.0 / 3.0}, {prev, 1.0 / 3.0}};
  } else {
    irregular_edge_rows<P>(x, p, ep, em);
  }
}

// A face point from the Gregory triangle's rules (Loop, Schaefer, Ni and
// Castaño, for triangles): F = (c_far P + (4 - 2 c_near - c_far) E_near +
// 2 c_near E_far) / 4 + R, R from the two ring points beside the edge.
inline Row irregular_triangle_face_row(const Gregory_triangle_corner& near, const Gregory_triangle_corner& far,
                                       unsigned ring_edge, const Row& p, const Row& e_near, const Row& e_far,
                                       double sign)
{
  Row f;
  add_row(f, p, far.cosine / 4.0);
  add_row(f, e_near, (4.0 - 2.0 * near.cosine - far.cosine) / 4.0);
  add_row(f, e_far, 2.0 * near.cosine / 4.0);
  const unsigned n = near.valence;
  const double r = 0.25 * (7.0 / 18.0);
  f.push_back({near.c->ring[(ring_edge + n - 1) % n], -sign * r});
  f.push_back({near.c->ring[(ring_edge + 1) % n], sign * r});
  return f;
}

// The face points of corner k, from the cubic edge points.
inline void gregory_triangle_face_rows(const std::array<Gregory_triangle_corner, 3>& g, int k,
                                       std::array<Row, 18>& rows)
{
  const Gregory_triangle_corner& x = g[k];
  const int next = (k + 1) % 3, prev = (k + 2) % 3;
  const Corner::Ring& r = x.c->ring;
  for (int minus = 0; minus < 2; ++minus) {
    if (!(minus ? x.fm_regular : x.fp_regular))
      continue;
    Row& f = rows[std::size_t(5 * k + 3 + minus)];
    if (x.single_face) {
      f = {{x.v, 0.5}, {g[next].v, 0.25}, {g[prev].v, 0.25}};
    } else if (x.ep_on_boundary) {
      f = {{x.v, 11.0 / 24.0}, {r[0], 7.0 / 24.0}, {r[1], 5.0 / 24.0}, {r[2], 1.0 / 24.0}};
    } else if (x.em_on_boundary) {
      f = {{x.v, 11.0 / 24.0}, {r[3], 7.0 / 24.0}, {r[2], 5.0 / 24.0}, {r[1], 1.0 / 24.0}};
    } else {
      const unsigned e_next = x.boundary ? 0 : (x.face_in_ring + 5) % 6;
      const unsigned e_prev = x.boundary ? 3 : (x.face_in_ring + 2) % 6;
      f = {{x.v, 10.0 / 24.0}, {g[prev].v, 0.25}, {g[next].v, 0.25}, {r[e_prev], 1.0 / 24.0}, {r[e_next], 1.0 / 24.0}};
    }
  }
  const std::size_t P0 = std::size_t(5 * k);
  if (!x.fp_regular && !x.fp_copied)
    rows[P0 + 3] = irregular_triangle_face_row(x, g[next], x.face_in_ring, rows[P0], rows[P0 + 1],
                                               rows[std::size_t(5 * next + 2)], 1.0);
  if (!x.fm_regular && !x.fm_copied)
    rows[P0 + 4] = irregular_triangle_face_row(x, g[prev], (x.face_in_ring + 1) % x.valence, rows[P0], rows[P0 + 2],
                                               rows[std::size_t(5 * prev + 1)], -1.0);
  if (x.fp_copied)
    rows[P0 + 3] = rows[P0 + 4];
  if (x.fm_copied)
    rows[P0 + 4] = rows[P0 + 3];
}

// The 18 points of the Gregory triangle of frame d as rows on the
// vertices of its level: limit points and edge points of the corners, face
// points, the quartic middle points of the edges, and the cubic edge points
// raised to quartic (E = P / 4 + 3 E / 4).
template <class P>
std::array<Row, 18> gregory_triangle_rows(const Mobius_mesh<P>& m, Dart d, const std::array<Corner, 3>& corners)
{
  const auto dk = triangle_darts(m, d);
  const std::array<Vertex_index, 3> cv = {m.source(dk[0]), m.source(dk[1]), m.source(dk[2])};
  const auto g = gregory_triangle_corners(corners, cv);
  std::array<Row, 18> rows;
  for (int k = 0; k < 3; ++k)
    gregory_triangle_edge_rows<P>(g, k, rows[std::size_t(5 * k)], rows[std::size_t(5 * k + 1)],
                                  rows[std::size_t(5 * k + 2)]);
  for (int k = 0; k < 3; ++k)
    gregory_triangle_face_rows(g, k, rows);
  for (int k = 0; k < 3; ++k) { // edge k, from corner k to corner k + 1
    const Gregory_triangle_corner &a = g[k], &b = g[(k + 1) % 3];
    const bool border = a.ep_on_boundary && b.em_on_boundary, dart = a.ep_on_boundary != b.em_on_boundary;
    Row& mid = rows[std::size_t(15 + k)];
    if (border) {
      mid = {{a.v, 0.5}, {b.v, 0.5}};
    } else if (a.regular && b.regular && !dart) {
      const unsigned opposite = a.boundary ? a.face_in_ring - 1 : (a.face_in_ring + 5) % 6;
      mid = {{a.v, 1.0 / 3.0}, {b.v, 1.0 / 3.0}, {g[(k + 2) % 3].v, 1.0 / 6.0}, {a.c->ring[opposite], 1.0 / 6.0}};
    } else {
      mid.clear();
      add_row(mid, rows[std::size_t(5 * k + 1)], 0.5);
      add_row(mid, rows[std::size_t(5 * ((k + 1) % 3) + 2)], 0.5);
    }
  }
  for (int k = 0; k < 3; ++k)
    for (int e = 1; e <= 2; ++e) {
      Row quartic;
      add_row(quartic, rows[std::size_t(5 * k)], 0.25);
      add_row(quartic, rows[std::size_t(5 * k + e)], 0.75);
      rows[std::size_t(5 * k + e)] = quartic;
    }
  return rows;
}

// The triangle of the three vertices a, b, c (found round a).
template <class P>
Face_index triangle_of(const Mobius_mesh<P>& m, Vertex_index a, Vertex_index b, Vertex_index c)
{
  for (Dart x : halfedges_around_target(a, m)) {
    if (m.is_border(x))
      continue;
    const Face_index f = m.face(x);
    bool has_b = false, has_c = false;
    for (Vertex_index v : vertices_around_face(m.halfedge(f), m)) {
      has_b |= v == b;
      has_c |= v == c;
    }
    if (has_b && has_c)
      return f;
  }
  throw Parameter_error("Limit_surface: internal error, a child triangle was not found");
}

// Builds the patches of the triangle of frame d of level mesh L. Its part
// of the face's parameters is the patch `where` describes (u0, v0, size,
// rotated, depth, path); its children are Bfr's quadrants: 0, 1, 2 at
// corners 0, 1, 2, and 3 the middle one, turned half a turn.
template <class FT, class P>
class Loop_patch_tree_builder
{
public:
  Loop_patch_tree_builder(const Limit_options& options, Patch_list<FT>& out) : opt_(options), out_(out) {}

  void build(const Level_mesh<P>& L, Dart d, const Patch<FT>& where)
  {
    const auto dk = triangle_darts(L.mesh, d);
    std::array<Corner, 3> corners;
    Face_features features;
    for (int k = 0; k < 3; ++k) {
      corners[k] = analyse_corner(L, dk[k], opt_, 3);
      features.add(corners[k], 3);
    }
    const bool regular = features.regular;
    if (!features.refines(opt_, where.depth)) {
      Patch<FT> patch = where;
      if (regular) {
        patch.type = Patch_type::box_spline;
        box_spline_points<FT>(L.mesh, d, corners, patch.points);
        box_spline_to_monomials(patch.points);
      } else {
        patch.type = Patch_type::gregory_triangle;
        const std::array<Row, 18> rows = gregory_triangle_rows(L.mesh, d, corners);
        for (std::size_t k = 0; k < 18; ++k) {
          patch.points[k] = {FT(0), FT(0), FT(0)};
          for (const auto& [v, w] : rows[k])
            add_scaled(patch.points[k], FT(w), coordinates<FT>(L.mesh, v));
        }
      }
      out_.push_back(patch);
      return;
    }
    refine_children(L, d, where);
  }

private:
  // Copies the neighbourhood of face(d), subdivides it once and builds the
  // four children.
  void refine_children(const Level_mesh<P>& L, Dart d, const Patch<FT>& where)
  {
    Level_mesh<P> child;
    const Dart c = copy_neighbourhood(L, d, child, needs_two_rings(L, opt_));
    const auto nv = child.mesh.number_of_vertices();
    Vertex_index vp[3], ep[3]; // corner k's child, and the edge point of edge k (corner k to k + 1)
    const auto ck = triangle_darts(child.mesh, c);
    for (int k = 0; k < 3; ++k) {
      vp[k] = child.mesh.source(ck[k]);
      ep[k] = Vertex_index(nv + child.mesh.edge(ck[k]).idx());
    }
    loop(child.mesh, refinement_parameters(opt_));
    child.bind();
    const Mobius_mesh<P>& m = child.mesh;
    // (first corner, second corner, third corner) of each child, in the parent's orientation.
    const Vertex_index frames[4][3] = {
      {vp[0], ep[0], ep[2]}, {ep[0], vp[1], ep[1]}, {ep[2], ep[1], vp[2]}, {ep[1], ep[2], ep[0]}};
    const double h = where.size / 2, sign = where.rotated ? -1.0 : 1.0;
    const double offset[4][2] = {{0, 0}, {h, 0}, {0, h}, {h, h}};
    for (int q = 0; q < 4; ++q) {
      Patch<FT> sub;
      sub.u0 = where.u0 + sign * offset[q][0];
      sub.v0 = where.v0 + sign * offset[q][1];
      sub.size = h;
      sub.rotated = q == 3 ? !where.rotated : where.rotated;
      sub.depth = where.depth + 1;
      sub.path = where.path | (std::uint64_t(q) << (2 * where.depth));
      const Face_index f = triangle_of(m, frames[q][0], frames[q][1], frames[q][2]);
      build(child, dart_between(m, f, frames[q][0], frames[q][1]), sub);
    }
  }

  const Limit_options& opt_;
  Patch_list<FT>& out_;
};

// The quadrants that lead to (u, v) in a triangle's patch tree, `depth`
// deep, two bits per level (Bfr's descent: a parameter on the line between
// two children belongs to the one of larger u, then larger v, then the
// middle one).
template <class FT>
std::uint64_t triangle_path(FT u, FT v, unsigned depth)
{
  std::uint64_t path = 0;
  bool rotated = false;
  FT half(FT(1) / FT(2));
  for (unsigned level = 0; level < depth; ++level, half = half / FT(2)) {
    std::uint64_t q;
    if (!rotated) {
      if (u >= half) {
        u -= half;
        q = 1;
      } else if (v >= half) {
        v -= half;
        q = 2;
      } else if (u + v >= half) {
        q = 3;
        rotated = true;
      } else {
        q = 0;
      }
    } else {
      if (u < half) {
        v -= half;
        q = 1;
      } else if (v < half) {
        u -= half;
        q = 2;
      } else {
        u -= half;
        v -= half;
        q = u + v < half ? 3 : 0;
        rotated = q != 3;
      }
    }
    path |= q << (2 * level);
  }
  return path;
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_LOOP_PATCH_BUILDER_H
