// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A uniform tessellation of a limit surface, watertight by construction:
// every sample the faces share (the limit point of a base vertex, the
// samples inside a base edge) is evaluated once and its index reused, so
// neighbouring faces cannot disagree even by rounding. The layout of each
// face is that of OpenSubdiv's Bfr::Tessellation at a uniform rate with
// quads preserved (Catmull–Clark), or of a triangle's domain (Loop).

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_TESSELLATION_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_TESSELLATION_H

#include <CGAL_ext/Limit_surface/internal/Parameterization.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Origin.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// Builds the tessellation of `mesh` (the surface's own copy of the base
// mesh) at `rate` samples per edge. `Surface` is Limit_surface;
// `corner_point(v, f, evaluated)` gives the point of base vertex v, first
// met at a corner of f where the surface evaluates to `evaluated`. With
// `triangle_domain` (Loop) a triangle is parameterised over the triangle
// (0, 0), (1, 0), (0, 1), not split into sub-faces.
template <class Surface, class P, class CornerPoint>
class Uniform_tessellator
{
  using FT = typename Surface::FT;
  using Vector = typename Surface::Kernel::Vector_3;
  using Evaluation = typename Surface::Evaluation;
  static constexpr std::size_t none = std::size_t(-1);

public:
  Uniform_tessellator(const Surface& surface, const Mobius_mesh<P>& mesh, int rate, const CornerPoint& corner_point,
                      bool triangle_domain = false)
      : s_(surface), m_(mesh), n_(rate), corner_point_(corner_point), triangle_domain_(triangle_domain)
  {}

  // The result, with "v:normal" and, where the base has Möbius edges, "h:normal".
  Mobius_mesh<P> run()
  {
    bool mobius = false;
    for (Edge_index e : m_.edges())
      mobius = mobius || m_.is_mobius(e);
    corner_normals_ = mobius;
    points_.assign(m_.number_of_vertices(), P(CGAL::ORIGIN));
    normals_.assign(m_.number_of_vertices(), Vector(CGAL::NULL_VECTOR));
    vertex_done_.assign(m_.number_of_vertices(), false);
    edge_owner_.assign(m_.number_of_edges(), Dart());
    edge_first_.assign(m_.number_of_edges(), none);
    for (Vertex_index v : m_.vertices())
      points_[v.idx()] = m_.point(v); // an isolated vertex stays where it is
    for (Face_index f : m_.faces())
      add_face(f);
    return build();
  }

private:
  // One face: its corners' darts, and the sample index of each position of its layout.
  struct Face_state
  {
    Face_index f;
    std::vector<Dart> darts; // darts[k] runs from corner k to corner k + 1
    std::unordered_map<std::size_t, Vector> boundary_normals; // in f's orientation
  };

  // (u, v) of a point of sub-face k (local (su, sv)) of an n-gon, or of a quad (k unused).
  std::array<FT, 2> param(int sides, int k, const FT& su, const FT& sv) const
  {
    if (sides == 4)
      return {su, sv};
    const std::array<int, 2> tile = sub_face_tile(sides, k);
    return {FT(tile[0]) + su / FT(2), FT(tile[1]) + sv / FT(2)};
  }

  // The parameter at fraction i / N along edge k from corner k, as Bfr
  // gives it: in sub-face k for the first half, in sub-face k + 1 after.
  std::array<FT, 2> edge_param(int sides, int k, int i) const
  {
    const FT t = FT(i) / FT(n_);
    if (whole_triangle(sides)) {
      switch (k) {
        case 0: return {t, FT(0)};
        case 1: return {FT(1) - t, t};
        default: return {FT(0), FT(1) - t};
      }
    }
    if (sides == 4) {
      switch (k) {
        case 0: return {t, FT(0)};
        case 1: return {FT(1), t};
        case 2: return {FT(1) - t, FT(1)};
        default: return {FT(0), FT(1) - t};
      }
    }
    if (2 * i < n_)
      return param(sides, k, FT(2) * t, FT(0));
    return param(sides, (k + 1) % sides, FT(0), FT(2) * (FT(1) - t));
  }

  std::array<FT, 2> corner_param(int sides, int k) const
  {
    if (whole_triangle(sides)) {
      const int uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      return {FT(uv[k][0]), FT(uv[k][1])};
    }
    if (sides == 4) {
      const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      return {FT(uv[k][0]), FT(uv[k][1])};
    }
    return param(sides, k, FT(0), FT(0));
  }

  Evaluation eval(Face_index f, const std::array<FT, 2>& uv) const { return s_.evaluate(f, uv[0], uv[1]); }

  std::size_t add_sample(const Evaluation& e)
  {
    points_.push_back(e.point);
    normals_.push_back(e.normal);
    return points_.size() - 1;
  }

  // The sample of corner k of the face: the base vertex, its point given once.
  std::size_t corner(Face_state& st, int k)
  {
    const Vertex_index v = m_.source(st.darts[std::size_t(k)]);
    const Evaluation e = eval(st.f, corner_param(int(st.darts.size()), k));
    if (!vertex_done_[v.idx()]) {
      vertex_done_[v.idx()] = true;
      points_[v.idx()] = corner_point_(v, st.f, e.point);
      normals_[v.idx()] = e.normal;
    }
    st.boundary_normals[v.idx()] = e.normal;
    return v.idx();
  }

  // The sample at fraction i / N (0 < i < N) along edge k from corner k.
  // The first face to reach an edge evaluates its samples, in the order
  // from its dart's source; another dart reads them backwards if it runs
  // the other way, as a neighbour of the same orientation does, and
  // forwards if it runs the same way: across a Möbius edge, whose far face
  // sees the surface from the other side, so its normal is the negation.
  std::size_t edge_sample(Face_state& st, int k, int i)
  {
    const int sides = int(st.darts.size());
    const Dart d = st.darts[std::size_t(k)];
    const Edge_index e = m_.edge(d);
    if (edge_first_[e.idx()] == none) {
      edge_owner_[e.idx()] = d;
      edge_first_[e.idx()] = points_.size();
      for (int j = 1; j < n_; ++j)
        add_sample(eval(st.f, edge_param(sides, k, j)));
    }
    const Dart owner = edge_owner_[e.idx()];
    const bool same_way = m_.source(owner) == m_.source(d); // an edge's ends differ
    const std::size_t id = edge_first_[e.idx()] + std::size_t(same_way ? i - 1 : n_ - i - 1);
    st.boundary_normals[id] = same_way && !(owner == d) ? -normals_[id] : normals_[id];
    return id;
  }

  void add_face(Face_index f)
  {
    Face_state st;
    st.f = f;
    for (Dart d : CGAL_ext::halfedges_around_face(m_.halfedge(f), m_))
      st.darts.push_back(m_.next(d));
    if (whole_triangle(int(st.darts.size())))
      add_triangle(st);
    else if (st.darts.size() == 4)
      add_quad(st);
    else
      add_polygon(st);
  }

  bool whole_triangle(int sides) const { return triangle_domain_ && sides == 3; }

  // A triangle over its own domain: N² triangles, (i, j) at parameter
  // (i / N, j / N), i + j <= N, the lattice's lines parallel to the sides.
  void add_triangle(Face_state& st)
  {
    const int N = n_;
    std::vector<std::size_t> g(std::size_t((N + 1) * (N + 1)), none);
    auto at = [&](int i, int j) -> std::size_t& { return g[std::size_t(j * (N + 1) + i)]; };
    at(0, 0) = corner(st, 0);
    at(N, 0) = corner(st, 1);
    at(0, N) = corner(st, 2);
    for (int i = 1; i < N; ++i) {
      at(i, 0) = edge_sample(st, 0, i);
      at(N - i, i) = edge_sample(st, 1, i);
      at(0, N - i) = edge_sample(st, 2, i);
    }
    for (int j = 1; j < N; ++j)
      for (int i = 1; i + j < N; ++i)
        at(i, j) = add_sample(eval(st.f, {FT(i) / FT(N), FT(j) / FT(N)}));
    for (int j = 0; j < N; ++j)
      for (int i = 0; i + j < N; ++i) {
        emit(st, {at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < N)
          emit(st, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }

  // A quad: an N × N grid of quads, (i, j) at parameter (i / N, j / N).
  void add_quad(Face_state& st)
  {
    const int N = n_;
    std::vector<std::size_t> g(std::size_t((N + 1) * (N + 1)), none);
    auto at = [&](int i, int j) -> std::size_t& { return g[std::size_t(j * (N + 1) + i)]; };
    at(0, 0) = corner(st, 0);
    at(N, 0) = corner(st, 1);
    at(N, N) = corner(st, 2);
    at(0, N) = corner(st, 3);
    for (int i = 1; i < N; ++i) {
      at(i, 0) = edge_sample(st, 0, i);
      at(N, i) = edge_sample(st, 1, i);
      at(N - i, N) = edge_sample(st, 2, i);
      at(0, N - i) = edge_sample(st, 3, i);
    }
    for (int j = 1; j < N; ++j) // rows, as Bfr orders its interior points
      for (int i = 1; i < N; ++i)
        at(i, j) = add_sample(eval(st.f, {FT(i) / FT(N), FT(j) / FT(N)}));
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
        emit(st, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  }

  // An n-gon, as Bfr lays it out: sub-face k holds the grid G_k(i, j),
  // 0 <= i, j <= M = N div 2, at local parameter (2i / N, 2j / N), G_k(i, 0)
  // on edge k and G_k(0, j) on edge k - 1. At an even rate the grids meet
  // along the spokes (G_k(M, j) = G_{k+1}(j, M)) and at the centre; at an
  // odd rate a strip of quads joins neighbouring grids and their inner
  // corners make a triangle (n = 3) or a fan of triangles round the centre.
  void add_polygon(Face_state& st)
  {
    const int n = int(st.darts.size()), N = n_, M = N / 2;
    const bool even = N % 2 == 0;
    std::vector<std::vector<std::size_t>> g(std::size_t(n), std::vector<std::size_t>(std::size_t((M + 1) * (M + 1)), none));
    auto at = [&](int k, int i, int j) -> std::size_t& { return g[std::size_t((k + n) % n)][std::size_t(j * (M + 1) + i)]; };
    for (int k = 0; k < n; ++k) {
      at(k, 0, 0) = corner(st, k);
      for (int i = 1; i <= M; ++i)
        at(k, i, 0) = edge_sample(st, k, i);
    }
    for (int k = 0; k < n; ++k)
      for (int j = 1; j <= M; ++j)
        at(k, 0, j) = edge_sample(st, (k + n - 1) % n, N - j);
    std::size_t centre = none;
    if (even || n > 3)
      centre = add_sample(eval(st.f, param(n, 0, FT(1), FT(1))));
    for (int k = 0; k < n; ++k) {
      for (int j = 1; j <= M; ++j)
        for (int i = 1; i <= M; ++i) {
          if (even && i == M && j == M)
            at(k, i, j) = centre;
          else if (!(even && i == M)) // G_k(M, j) is the next sub-face's row M
            at(k, i, j) = add_sample(eval(st.f, param(n, k, FT(2 * i) / FT(N), FT(2 * j) / FT(N))));
        }
    }
    if (even)
      for (int k = 0; k < n; ++k)
        for (int j = 1; j < M; ++j)
          at(k, M, j) = at(k + 1, j, M);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < M; ++j)
        for (int i = 0; i < M; ++i)
          emit(st, {at(k, i, j), at(k, i + 1, j), at(k, i + 1, j + 1), at(k, i, j + 1)});
    if (even)
      return;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < M; ++j)
        emit(st, {at(k, M, j), at(k + 1, j, M), at(k + 1, j + 1, M), at(k, M, j + 1)});
    if (n == 3)
      emit(st, {at(0, M, M), at(1, M, M), at(2, M, M)});
    else
      for (int k = 0; k < n; ++k)
        emit(st, {at(k, M, M), at(k + 1, M, M), centre});
  }

  void emit(const Face_state& st, std::vector<std::size_t> facet)
  {
    if (corner_normals_) {
      std::vector<Vector> ns;
      for (std::size_t id : facet) {
        const auto it = st.boundary_normals.find(id);
        ns.push_back(it != st.boundary_normals.end() ? it->second : normals_[id]);
      }
      facet_normals_.push_back(std::move(ns));
    }
    facets_.push_back(std::move(facet));
  }

  Mobius_mesh<P> build() const
  {
    Mobius_mesh<P> out;
    for (const P& p : points_)
      out.add_vertex(p);
    for (const auto& facet : facets_) {
      std::vector<Vertex_index> vs;
      for (std::size_t id : facet)
        vs.push_back(Vertex_index(id));
      std::string why;
      if (out.add_face(vs, &why) == Face_index())
        throw Parameter_error("Limit_surface::tessellate: internal error, a facet was refused: " + why);
    }
    auto vn = out.template add_property_map<Vertex_index, Vector>("v:normal", Vector(CGAL::NULL_VECTOR)).first;
    for (Vertex_index v : out.vertices())
      vn[v] = normals_[v.idx()];
    if (!corner_normals_)
      return out;
    auto hn = out.template add_property_map<Halfedge_index, Vector>("h:normal", Vector(CGAL::NULL_VECTOR)).first;
    for (Face_index f : out.faces()) {
      const auto& facet = facets_[f.idx()];
      for (Dart d : CGAL_ext::halfedges_around_face(out.halfedge(f), out))
        for (std::size_t c = 0; c < facet.size(); ++c)
          if (facet[c] == out.target(d).idx())
            hn[d.halfedge()] = facet_normals_[f.idx()][c];
    }
    return out;
  }

  const Surface& s_;
  const Mobius_mesh<P>& m_;
  int n_;
  const CornerPoint& corner_point_;
  bool triangle_domain_ = false;
  bool corner_normals_ = false;
  std::vector<P> points_;
  std::vector<Vector> normals_;
  std::vector<bool> vertex_done_;
  std::vector<Dart> edge_owner_; // the dart whose face evaluated the edge's samples
  std::vector<std::size_t> edge_first_;
  std::vector<std::vector<std::size_t>> facets_;
  std::vector<std::vector<Vector>> facet_normals_;
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_TESSELLATION_H
