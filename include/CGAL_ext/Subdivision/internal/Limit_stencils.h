// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/Subdivision/limit.h>: the limit stencils of a vertex: its ring gathered by darts and OpenSubdiv's limit masks.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_LIMIT_STENCILS_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_LIMIT_STENCILS_H

#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/normals.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/exceptions.h>
#include <cmath>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>
#include <CGAL_ext/Subdivision/Limit_tangents.h>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

using CGAL_ext::internal::check_dart;
using CGAL_ext::internal::describe;
using CGAL_ext::internal::Normal_settings;
using CGAL_ext::internal::Normal_types;
using CGAL_ext::internal::unit_vector;
using CGAL_ext::internal::vertex_side_dart;

template <class Mask>
constexpr bool has_limit_masks =
  std::is_same_v<Mask, Catmull_clark_mask> || std::is_same_v<Mask, Loop_mask>;

// The neighbourhood of a vertex as a limit mask reads it (OpenSubdiv's
// vertex neighbourhood at the last level): the far ends of its edges in
// order around it, as the darts walk from the face the walk starts in, the
// corner opposite the vertex in each face (quads), and each edge's
// sharpness, a border edge being infinitely sharp. At a border vertex the
// walk starts at the border, as OpenSubdiv orders a border vertex's edges.
template <class P>
struct Limit_ring
{
  Vertex_index center;
  std::vector<Vertex_index> edge_ends, face_corners;
  std::vector<float> edge_sharpness;
  float vertex_sharpness = 0.0f;
  Crease::Rule rule = Crease::Rule::smooth;
  unsigned crease_ends[2] = {0, 0};

  // Walks the ring of target(d) from next(d), the dart leaving it in d's
  // face; `function` names the caller in the error for a bad sharpness.
  template <class EdgeSharpness>
  void gather(const char* function, Dart d, const Mobius_mesh<P>& mesh, const EdgeSharpness& es, float vs,
              bool corner_if_one_face)
  {
    center = mesh.target(d);
    edge_ends.clear();
    face_corners.clear();
    edge_sharpness.clear();
    Dart o = mesh.next(d);
    const Dart first = o;
    bool border = false;
    while (!mesh.is_border(mesh.opposite(o))) { // rewind to the border, if any
      o = mesh.next(mesh.opposite(o));
      if (o == first)
        break;
    }
    border = mesh.is_border(mesh.opposite(o));
    const Dart start = o;
    do {
      add_edge(function, o, mesh, es);
      face_corners.push_back(mesh.target(mesh.next(o)));
      o = mesh.opposite(mesh.prev(o)); // the next dart leaving the vertex, around it
      if (mesh.is_border(o)) {
        add_edge(function, o, mesh, es); // the trailing border edge
        break;
      }
    } while (o != start);
    if (!CGAL_ext::internal::is_valid_sharpness(vs))
      throw CGAL_ext::internal::invalid_sharpness(function, "vertex v", center.idx(), vs);
    vertex_sharpness = vs;
    if (border && corner_if_one_face && face_corners.size() == 1)
      vertex_sharpness = infinitely_sharp;
    classify();
  }

  template <class EdgeSharpness>
  void add_edge(const char* function, Dart o, const Mobius_mesh<P>& mesh, const EdgeSharpness& es)
  {
    edge_ends.push_back(mesh.target(o));
    const Edge_index e = mesh.edge(o);
    const float s = mesh.is_border(e) ? infinitely_sharp : es(e);
    if (!CGAL_ext::internal::is_valid_sharpness(s))
      throw CGAL_ext::internal::invalid_sharpness(function, "edge e", e.idx(), s);
    edge_sharpness.push_back(s);
  }

  // OpenSubdiv's vertex rule at the last level, and the first two sharp edges.
  void classify()
  {
    unsigned sharp = 0;
    for (unsigned i = 0; i < edge_sharpness.size(); ++i)
      if (Crease::is_sharp(edge_sharpness[i])) {
        if (sharp < 2)
          crease_ends[sharp] = i;
        ++sharp;
      }
    rule = Crease::vertex_rule(vertex_sharpness, sharp);
  }
};

// A mask over a ring: a weight for the vertex, its edges' far ends and its
// faces' opposite corners.
template <class W>
struct Limit_mask
{
  W vertex = W(0);
  std::vector<W> edge, face;

  void reset(std::size_t edges, std::size_t faces)
  {
    vertex = W(0);
    edge.assign(edges, W(0));
    face.assign(faces, W(0));
  }
};

// cos(2π k / n) in W: exact where it is rational (a multiple of 1/2).
template <class W>
W cosine(unsigned k, unsigned n)
{
  int two_cos;
  if (integer_two_cos(k, n, two_cos))
    return W(two_cos) / W(2);
  return W(std::cos(2.0 * M_PI * double(k) / double(n)));
}

// The position masks (OpenSubdiv's assign*LimitMask), in the exact field
// `W`: every weight of Catmull–Clark is rational, and Loop's are at valences
// 3, 4 and 6 and on creases and corners. Of a ring of `ne` edges and `nf`
// faces whose vertex has rule `rule`, `crease_ends` its first two sharp edges.
template <class Mask, class W>
void position_mask(std::size_t ne, std::size_t nf, Crease::Rule rule, const unsigned* crease_ends, Limit_mask<W>& m)
{
  m.reset(ne, nf);
  if (rule == Crease::Rule::corner || (std::is_same_v<Mask, Catmull_clark_mask> && rule != Crease::Rule::crease &&
                                       nf == 2)) {
    m.vertex = W(1);
  } else if (rule == Crease::Rule::crease) {
    m.vertex = W(2) / W(3);
    m.edge[crease_ends[0]] = m.edge[crease_ends[1]] = W(1) / W(6);
  } else if constexpr (std::is_same_v<Mask, Catmull_clark_mask>) {
    const W n = W(int(nf));
    const W f = W(1) / (n * (n + W(5)));
    for (std::size_t i = 0; i < nf; ++i) {
      m.face[i] = f;
      m.edge[i] = W(4) * f;
    }
    m.vertex = W(1) - n * W(5) * f;
  } else {
    const unsigned n = unsigned(ne);
    int two_cos;
    W e;
    if (integer_two_cos(1, n, two_cos)) {
      const W beta = W(two_cos) / W(8) + W(3) / W(8);
      const W gamma = (W(5) / W(8) - beta * beta) / W(int(n));
      e = W(1) / (W(int(n)) + W(3) / (W(8) * gamma));
    } else { // OpenSubdiv's formula, in its order of operations
      const double beta = 0.25 * std::cos(2.0 * M_PI / double(n)) + 0.375;
      const double gamma = (0.625 - beta * beta) * (1.0 / double(n));
      e = W(1.0 / (double(n) + 3.0 / (8.0 * gamma)));
    }
    for (std::size_t i = 0; i < ne; ++i)
      m.edge[i] = e;
    m.vertex = W(1) - e * W(int(n));
  }
}

template <class Mask, class W, class P>
void position_mask(const Limit_ring<P>& r, Limit_mask<W>& m)
{
  position_mask<Mask>(r.edge_ends.size(), r.face_corners.size(), r.rule, r.crease_ends, m);
}

// Catmull–Clark's tangent masks (OpenSubdiv's assign*LimitTangentMasks).
template <class P>
void catmull_clark_tangent_masks(const Limit_ring<P>& r, Limit_mask<double>& t1, Limit_mask<double>& t2)
{
  const std::size_t ne = r.edge_ends.size(), nf = r.face_corners.size();
  t1.reset(ne, nf);
  t2.reset(ne, nf);
  if (r.rule == Crease::Rule::corner || (r.rule != Crease::Rule::crease && nf == 2)) {
    t1.vertex = t2.vertex = -1.0;
    t1.edge[0] = 1.0;
    t2.edge[1] = 1.0;
  } else if (r.rule == Crease::Rule::crease) {
    const unsigned c0 = r.crease_ends[0], c1 = r.crease_ends[1];
    t1.edge[c0] = 0.5;
    t1.edge[c1] = -0.5;
    const unsigned interior = c1 - c0 - 1;
    if (interior == 1) { // the regular case: the uniform B-spline cross tangent
      t2.vertex = -4.0 / 6.0;
      t2.edge[c0] = t2.edge[c1] = -1.0 / 6.0;
      t2.edge[c0 + 1] = 4.0 / 6.0;
      t2.face[c0] = t2.face[c0 + 1] = 1.0 / 6.0;
    } else if (interior > 1) { // Biermann et al.
      const double k = double(interior + 1), theta = M_PI / k;
      const double c = std::cos(theta), s = std::sin(theta);
      const double denominator = 1.0 / (k * (3.0 + c));
      const double R = (c + 1.0) / s;
      t2.vertex = 4.0 * R * (c - 1.0) * denominator;
      t2.edge[c0] = t2.edge[c1] = -R * (1.0 + 2.0 * c) * denominator;
      t2.face[c0] = s * denominator;
      for (unsigned i = 1; i < interior + 1; ++i) {
        t2.edge[c0 + i] = 4.0 * std::sin(i * theta) * denominator;
        t2.face[c0 + i] = (std::sin(i * theta) + std::sin((i + 1) * theta)) * denominator;
      }
    } else { // one face: the average of its two border edges
      t2.vertex = -6.0;
      t2.edge[c0] = t2.edge[c1] = 3.0;
    }
  } else {
    const double theta = 2.0 * M_PI / double(nf);
    const double lambda =
      5.0 / 16.0 + (std::cos(theta) + std::cos(0.5 * theta) * std::sqrt(2.0 * (9.0 + std::cos(theta)))) / 16.0;
    // The regular case in integers, as OpenSubdiv has it (4λ − 1 = 1 there).
    const double face_scale = nf == 4 ? 1.0 : 1.0 / (4.0 * lambda - 1.0);
    auto cos_i = [&](std::size_t i) { return nf == 4 ? cosine<double>(unsigned(i), 4) : std::cos(double(i) * theta); };
    for (std::size_t i = 0; i < nf; ++i) {
      t1.edge[i] = 4.0 * cos_i(i);
      t1.face[i] = face_scale * (cos_i(i) + cos_i(i + 1));
    }
    for (std::size_t i = 0; i < nf; ++i) { // tangent 2 is tangent 1 turned by one edge
      t2.edge[i] = t1.edge[(i + nf - 1) % nf];
      t2.face[i] = t1.face[(i + nf - 1) % nf];
    }
  }
}

// Loop's tangent masks (OpenSubdiv's, with its scale factors, which make
// tangents at borders and corners about as long as those inside).
template <class P>
void loop_tangent_masks(const Limit_ring<P>& r, Limit_mask<double>& t1, Limit_mask<double>& t2)
{
  const std::size_t ne = r.edge_ends.size(), nf = r.face_corners.size();
  t1.reset(ne, nf);
  t2.reset(ne, nf);
  const double root3 = 1.73205080756887729352;
  if (r.rule == Crease::Rule::corner) {
    t1.vertex = t2.vertex = -3.0;
    t1.edge[0] = 3.0;
    t2.edge[1] = 3.0;
  } else if (r.rule == Crease::Rule::crease) {
    const unsigned c0 = r.crease_ends[0], c1 = r.crease_ends[1];
    t1.edge[c0] = 1.5;
    t1.edge[c1] = -1.5;
    const unsigned interior = c1 - c0 - 1;
    if (interior == 2) { // the regular case, scaled by sin 60°
      t2.vertex = -root3;
      t2.edge[c0] = t2.edge[c1] = -0.5 * root3;
      t2.edge[c0 + 1] = t2.edge[c0 + 2] = root3;
    } else if (interior > 2) {
      const double theta = M_PI / double(interior + 1);
      t2.edge[c0] = t2.edge[c1] = -3.0 * std::sin(theta);
      const double coefficient = -3.0 * 2.0 * (std::cos(theta) - 1.0);
      for (unsigned i = 1; i <= interior; ++i)
        t2.edge[c0 + i] = coefficient * std::sin(double(i) * theta);
    } else if (interior == 1) {
      t2.vertex = -3.0;
      t2.edge[c0 + 1] = 3.0;
    } else {
      t2.vertex = -6.0;
      t2.edge[c0] = t2.edge[c1] = 3.0;
    }
  } else {
    const double alpha = 2.0 * M_PI / double(nf);
    for (std::size_t i = 0; i < nf; ++i) {
      if (nf == 6) { // the regular case, with OpenSubdiv's rounded constants
        const double c[6] = {1.0, 0.5, -0.5, -1.0, -0.5, 0.5};
        const double s[6] = {0.0, 0.5 * root3, 0.5 * root3, 0.0, -0.5 * root3, -0.5 * root3};
        t1.edge[i] = c[i];
        t2.edge[i] = s[i];
      } else {
        t1.edge[i] = std::cos(alpha * double(i));
        t2.edge[i] = std::sin(alpha * double(i));
      }
    }
  }
}

// What a limit function reads from its named parameters.
// The sharpness maps are read where needed, not copied: a call for one
// vertex costs what its ring costs.
template <class P, class NP>
struct Limit_settings : Normal_settings<P, NP>
{
  std::function<float(Edge_index)> edge_sharpness;
  std::function<float(Vertex_index)> vertex_sharpness;
  bool corner_if_one_face;

  Limit_settings(const Mobius_mesh<P>& mesh, const NP& np) : Normal_settings<P, NP>(mesh, np)
  {
    // The limit of a joined vertex needs the rings of all its sheets at
    // once, which the limit stencils do not gather: subdivide first.
    CGAL_ext::internal::refuse_non_manifold_joins(mesh, "the limit functions");
    edge_sharpness = CGAL_ext::internal::edge_sharpness_of(mesh, np);
    vertex_sharpness = CGAL_ext::internal::vertex_sharpness_of(mesh, np);
    corner_if_one_face =
      CGAL_ext::internal::boundary_interpolation_of(np) == Boundary_interpolation::edge_and_corner;
  }
  float sharpness(Vertex_index v) const { return vertex_sharpness(v); }
};

template <class Mask, class P>
void check_face_degree(const char* function, Face_index f, const Mobius_mesh<P>& mesh)
{
  constexpr unsigned degree = std::is_same_v<Mask, Catmull_clark_mask> ? 4 : 3;
  const std::size_t n = mesh.degree(f);
  if (n != degree)
    throw Parameter_error(std::string(function) + ": the limit masks of " +
                          (degree == 4 ? "Catmull-Clark need a quad mesh (refine once first)"
                                       : "Loop need a triangle mesh") +
                          ", but face f" + std::to_string(f.idx()) + " has " + std::to_string(n) + " sides");
}

// The ring of target(d), its faces checked.
template <class Mask, class P, class NP>
void gather_ring(const char* function, Dart d, const Mobius_mesh<P>& mesh, const Limit_settings<P, NP>& s,
                 Limit_ring<P>& ring)
{
  for (Dart c : CGAL_ext::halfedges_around_target(d, mesh))
    if (!mesh.is_border(c))
      check_face_degree<Mask>(function, mesh.face(c), mesh);
  ring.gather(function, d, mesh, s.edge_sharpness, s.sharpness(mesh.target(d)), s.corner_if_one_face);
}


// Σ w_i (p_i − c) over a mask: a tangent (the weights sum to 0) or, from
// the origin, a position.
template <class W, class P, class NP>
auto apply_mask(const Limit_mask<W>& m, const Limit_ring<P>& r, const typename Normal_types<P, NP>::Point& c,
                const Limit_settings<P, NP>& s)
{
  using FT = typename Normal_types<P, NP>::Traits::FT;
  const auto vector = s.traits.construct_vector_3_object();
  const auto scale = s.traits.construct_scaled_vector_3_object();
  const auto sum = s.traits.construct_sum_of_vectors_3_object();
  auto total = vector(CGAL::NULL_VECTOR);
  auto add = [&](const W& w, Vertex_index v) {
    if (!CGAL::is_zero(w))
      total = sum(total, scale(vector(c, get(s.points, v)), FT(w)));
  };
  // Smaller weights first, as OpenSubdiv adds them: faces, edges, vertex.
  for (std::size_t i = 0; i < m.face.size(); ++i)
    add(m.face[i], r.face_corners[i]);
  for (std::size_t i = 0; i < m.edge.size(); ++i)
    add(m.edge[i], r.edge_ends[i]);
  add(m.vertex, r.center);
  return total;
}

template <class Mask, class P, class NP>
auto limit_point_of_ring(const Limit_ring<P>& r, const Limit_settings<P, NP>& s)
{
  using Types = Normal_types<P, NP>;
  using FT = typename Types::Traits::FT;
  Limit_mask<FT> m;
  position_mask<Mask>(r, m);
  const typename Types::Point origin = s.traits.construct_point_3_object()(CGAL::ORIGIN);
  return s.traits.construct_translated_point_3_object()(origin, apply_mask(m, r, origin, s));
}

template <class Mask, class P, class NP>
auto limit_tangents_of_ring(const Limit_ring<P>& r, const Limit_settings<P, NP>& s)
{
  Limit_mask<double> t1, t2;
  if constexpr (std::is_same_v<Mask, Catmull_clark_mask>)
    catmull_clark_tangent_masks(r, t1, t2);
  else
    loop_tangent_masks(r, t1, t2);
  const auto center = get(s.points, r.center);
  return Limit_tangents<typename Normal_types<P, NP>::Vector>{apply_mask(t1, r, center, s),
                                                              apply_mask(t2, r, center, s)};
}

template <class P>
void check_limit_dart(const char* function, Dart d, const Mobius_mesh<P>& mesh)
{
  check_dart(function, d, mesh);
  if (mesh.is_border(d))
    throw Parameter_error(std::string(function) + ": " + describe(d) +
                          " is a border dart; give a dart of a face, whose side the result is seen from");
}

template <class Mask, class P, class NP>
auto limit_tangents_at(const char* function, Dart d, const Mobius_mesh<P>& mesh, const Limit_settings<P, NP>& s)
{
  check_limit_dart(function, d, mesh);
  Limit_ring<P> ring;
  gather_ring<Mask>(function, d, mesh, s, ring);
  return limit_tangents_of_ring<Mask>(ring, s);
}

// Fills `map` with `of_ring(ring)` for every vertex (`isolated(v)` for a
// vertex of no face), the ring walked from the side of vertex_normal(v): all
// values are computed before any is written, so `map` may be what they are
// read from.
template <class Mask, class P, class NP, class Map, class Isolated, class OfRing>
void write_per_vertex(const char* function, const Mobius_mesh<P>& mesh, const Limit_settings<P, NP>& s, Map map,
                      const Isolated& isolated, const OfRing& of_ring)
{
  using Value = decltype(isolated(Vertex_index()));
  CGAL_ext::internal::require_no_garbage(mesh, function);
  for (Face_index f : mesh.faces())
    check_face_degree<Mask>(function, f, mesh);
  std::vector<Value> result;
  result.reserve(mesh.number_of_vertices());
  Limit_ring<P> ring;
  for (Vertex_index v : mesh.vertices()) {
    if (mesh.is_isolated(v)) {
      result.push_back(isolated(v));
      continue;
    }
    ring.gather(function, vertex_side_dart(v, mesh), mesh, s.edge_sharpness, s.sharpness(v), s.corner_if_one_face);
    result.push_back(of_ring(ring));
  }
  for (Vertex_index v : mesh.vertices())
    put(map, v, result[v.idx()]);
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_LIMIT_STENCILS_H
