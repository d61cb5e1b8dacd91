// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of limit_corner_values() (<CGAL_ext/Subdivision/limit.h>): the
// limit of every value of a corner channel, by OpenSubdiv's rules
// (Far::PrimvarRefiner::LimitFaceVarying()): the channel's topology on the
// mesh as it stands decides per value whether the vertex's limit mask, the
// crease rule along its seam or the corner rule applies.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_LIMIT_FACE_VARYING_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_LIMIT_FACE_VARYING_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Face_varying.h>
#include <CGAL_ext/Subdivision/internal/Level.h>
#include <CGAL_ext/Subdivision/internal/Limit_stencils.h>
#include <CGAL_ext/Subdivision/internal/Subdivision_driver.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

template <class T>
using Channel_of = CGAL_ext::internal::Corner_channel<Halfedge_index, T>;

// The connectivity and sharpness of `mesh` as a level, and the topology of
// the channel whose value index per halfedge is `user`
// (FVarLevel::completeTopologyFromFaceValues() on the mesh as it stands). A
// border vertex of one face is a corner under `edge_and_corner`, as the
// refiner makes it (Refiner::mark_border()), which the channel's rules read.
template <class P, class NP>
void channel_topology(const char* function, const Mobius_mesh<P>& mesh, const Limit_settings<P, NP>& s,
                      const std::vector<u32>& user, const Fvar_rules& rules, Level& L, Fvar_level& F)
{
  fill_level(mesh, L);
  for (u32 e = 0; e < L.ne; ++e) {
    const float x = s.edge_sharpness(Edge_index(e));
    if (!CGAL_ext::internal::is_valid_sharpness(x))
      throw CGAL_ext::internal::invalid_sharpness(function, "edge e", e, x);
    L.e_sharp[e] = x;
  }
  for (u32 v = 0; v < L.nv; ++v) {
    const float x = s.sharpness(Vertex_index(v));
    if (!CGAL_ext::internal::is_valid_sharpness(x))
      throw CGAL_ext::internal::invalid_sharpness(function, "vertex v", v, x);
    L.v_sharp[v] = x;
    if (!s.corner_if_one_face || L.v_dart[v] == null_u32 || !L.is_border_dart(L.v_dart[v]))
      continue;
    u32 darts = 0;
    L.for_each_dart_at(v, [&](u32) { ++darts; });
    if (darts == 2)
      L.v_sharp[v] = infinitely_sharp;
  }
  analyse_base(L, user, rules, F);
}

// OpenSubdiv weighs a crease of a channel with the float constants 1/6 and
// 2/3 (which sum to 1 + 3e-8): floating-point values follow it, to agree
// with it to rounding; exact number types take the exact crease rule.
template <class W>
W crease_end_weight()
{
  if constexpr (std::is_floating_point_v<W>)
    return W(1.0f / 6.0f);
  else
    return W(1) / W(6);
}
template <class W>
W crease_center_weight()
{
  if constexpr (std::is_floating_point_v<W>)
    return W(2.0f / 3.0f);
  else
    return W(2) / W(3);
}

// Σ w x over the terms added, zero weights left out (exact numbers stay
// short); the first term starts the sum, as a value type may have no zero.
template <class W, class Value>
struct Weighted_sum
{
  std::optional<Value> sum;
  void add(const W& w, const Value& x)
  {
    if (CGAL::is_zero(w))
      return;
    sum = sum ? Value(*sum + w * x) : Value(w * x);
  }
};

// The ring of a vertex of a level as a limit mask reads it (Limit_ring's,
// on a level): the corner slots that hold, in the ring's faces, the far end
// of each edge (the trailing border edge's in the last face) and the corner
// opposite the vertex; its rule and first two sharp edges, a border edge
// being infinitely sharp and a border vertex of one face a corner under
// `edge_and_corner`.
struct Fvar_limit_ring
{
  Fvar_ring walk;
  std::vector<u32> edge_slots, face_slots;
  Crease::Rule rule = Crease::Rule::smooth;
  unsigned crease_ends[2] = {0, 0};

  void gather(const Level& L, u32 v, bool corner_if_one_face)
  {
    walk.walk(L, v);
    const u32 m = walk.faces();
    edge_slots.clear();
    face_slots.clear();
    unsigned sharp = 0;
    for (u32 i = 0; i < u32(walk.edge.size()); ++i) {
      edge_slots.push_back(i < m ? corner_slot(L, L.prev(walk.dart[i])) : corner_slot(L, L.next(walk.dart[m - 1])));
      const u32 e = walk.edge[i];
      if (Crease::is_sharp(is_border_edge(L, e) ? infinitely_sharp : sharpness_of_edge(L, e))) {
        if (sharp < 2)
          crease_ends[sharp] = i;
        ++sharp;
      }
    }
    for (u32 i = 0; i < m; ++i)
      face_slots.push_back(corner_slot(L, L.next(L.next(walk.dart[i]))));
    const bool corner = walk.border && corner_if_one_face && m == 1;
    rule = Crease::vertex_rule(corner ? infinitely_sharp : sharpness_of_vertex(L, v), sharp);
  }
};

// The limit of each vertex value of channel F on level L (F's numbering),
// `values` indexed as F's values (F.value()): OpenSubdiv's
// PrimvarRefiner::limitFVar(). A value whose topology matches its vertex's
// takes the vertex's limit mask on the values of its ring; otherwise a
// value tagged as a crease of the channel takes the crease rule towards the
// far ends of the two edges that bound its span, and any other is a corner.
template <class Mask, class W, class Value>
std::vector<Value> limit_vertex_values(const Level& L, const Fvar_level& F, const std::vector<Value>& values,
                                       bool corner_if_one_face)
{
  std::vector<Value> out;
  out.reserve(std::size_t(F.v_offset[L.nv]));
  Fvar_limit_ring ring;
  Limit_mask<W> m;
  std::vector<u32> vv;
  const auto at = [&](u32 slot) -> const Value& { return values[F.value(F.corner[slot])]; };
  for (u32 v = 0; v < L.nv; ++v) {
    const u32 first = F.v_offset[v], count = F.v_offset[v + 1] - first;
    if (count == 0)
      continue;
    ring.gather(L, v, corner_if_one_face);
    if (F.value_tag[first] == 0) {
      position_mask<Mask>(ring.edge_slots.size(), ring.face_slots.size(), ring.rule, ring.crease_ends, m);
      // Smaller weights first, as OpenSubdiv adds them: faces, edges, vertex.
      Weighted_sum<W, Value> x;
      for (std::size_t i = 0; i < m.face.size(); ++i)
        x.add(m.face[i], at(ring.face_slots[i]));
      for (std::size_t i = 0; i < m.edge.size(); ++i)
        x.add(m.edge[i], at(ring.edge_slots[i]));
      x.add(m.vertex, values[F.value(first)]);
      out.push_back(x.sum ? *x.sum : values[F.value(first)]);
      continue;
    }
    ring_values(L, F, ring.walk, vv);
    for (u32 j = 0; j < count; ++j) {
      const Value& x = values[F.value(first + j)];
      if (!(F.value_tag[first + j] & Fvar_level::crease)) {
        out.push_back(x);
        continue;
      }
      const std::pair<u32, u32> span = span_ends(F, ring.walk, vv, first + j, count);
      const Value& a = at(corner_slot(L, L.prev(ring.walk.dart[span.first])));
      const Value& b = at(corner_slot(L, L.next(ring.walk.dart[span.second])));
      const W we = crease_end_weight<W>();
      out.push_back(Value(Value(we * a + we * b) + crease_center_weight<W>() * x));
    }
  }
  return out;
}

// A channel through the levels of `r` and to the limit (OpenSubdiv's
// InterpolateFaceVarying() at each level, then LimitFaceVarying()): the tags
// that decide each value's rule are those the levels carried down, which
// remember sharpness since spent. `corners` and `values` as
// Refiner::interpolate_face_varying() takes them; out, the last level's
// corners and the limits of its values.
// The limit masks read quad (Catmull–Clark) or triangle (Loop) rings: a
// refiner without levels may still hold the base's other faces.
template <class Mask>
void check_level_face_degrees(const char* function, const Level& L)
{
  constexpr u32 degree = std::is_same_v<Mask, Catmull_clark_mask> ? 4 : 3;
  if (L.face_degree == degree)
    return;
  for (u32 f = 0; f < L.nf; ++f) {
    u32 n = 0, h = L.f_first[f];
    do {
      ++n;
      h = dart_encoding::halfedge_of_dart(L.h_next[h]);
    } while (h != L.f_first[f]);
    if (n != degree)
      throw Parameter_error(std::string(function) + ": the limit masks of " +
                            (degree == 4 ? "Catmull-Clark need a quad mesh (refine once first)"
                                         : "Loop need a triangle mesh") +
                            ", but face f" + std::to_string(f) + " of the last level has " + std::to_string(n) +
                            " sides");
  }
}

template <class Mask, class W, class Value>
void limit_face_varying(const Refiner<Mask, W>& r, Face_varying_interpolation mode, std::vector<u32>& corners,
                        std::vector<Value>& values)
{
  check_level_face_degrees<Mask>("limit_face_varying", level_of(r, r.number_of_levels()));
  Fvar_level last;
  interpolate_face_varying<CGAL::Sequential_tag>(r, mode, corners, values, [](u32) { return false; }, &last);
  const Fvar_rules rules(mode, r.options().boundary_interpolation);
  const bool corner_if_one_face = r.options().boundary_interpolation == Boundary_interpolation::edge_and_corner;
  // The corners name vertex values (without levels, the base's values are
  // named otherwise): the limits are numbered so.
  if (rules.linear_all) {
    std::vector<Value> kept;
    kept.reserve(std::size_t(last.v_offset.back()));
    for (u32 x = 0; x < last.v_offset.back(); ++x)
      kept.push_back(values[last.value(x)]);
    values.swap(kept);
  } else {
    values = limit_vertex_values<Mask, W>(level_of(r, r.number_of_levels()), last, values, corner_if_one_face);
  }
  corners.assign(last.corner.begin(), last.corner.end()); // vertex values, as the limits are numbered
}

template <class P, class T>
void require_channel_of(const char* function, const Mobius_mesh<P>& mesh, const Channel_of<T>& c, const char* role)
{
  const auto found = c ? mesh.template corner_channel<T>(c.name()) : std::nullopt;
  if (!found || *found != c)
    throw Parameter_error(std::string(function) + ": the " + role + " channel is not a corner channel of the mesh");
}

// Writes into `to` the limits of the values of `from` (both channels of
// `mesh`, perhaps one): each corner of `to` gets the limit of its value at
// its vertex. A value index used at one vertex keeps its index (so a
// subdivided mesh's channel keeps its indices); one used at several vertices
// gets one more value per further vertex, each vertex's limit being its own;
// unused values are kept. Everything is checked and computed before
// anything is written.
template <class Mask, class P, class T, class NP>
void write_corner_limits(const char* function, const Mobius_mesh<P>& mesh, const Channel_of<T>& from,
                         const Channel_of<T>& to, const NP& np)
{
  namespace pm = CGAL_ext::parameters;
  using K = typename CGAL::Kernel_traits<P>::Kernel;
  using W = typename Point_values<P>::Weight;
  using Linear = Linear_value<W, K, T>;
  static_assert(Linear::defined, "the channel's values need a linear combination (see doc/corner_data.md)");
  CGAL_ext::internal::require_no_garbage(mesh, function);
  require_channel_of(function, mesh, from, "input");
  require_channel_of(function, mesh, to, "output");
  for (Face_index f : mesh.faces())
    check_face_degree<Mask>(function, f, mesh);
  const Limit_settings<P, NP> s(mesh, np);
  const std::vector<u32> user = base_corners(function, mesh, from);
  const Face_varying_interpolation mode = pm::choose_parameter(
    pm::get_parameter(np, CGAL_ext::internal_np::face_varying_interpolation), Face_varying_interpolation::corners_plus1);
  const Fvar_rules rules(mode, CGAL_ext::internal::boundary_interpolation_of(np));
  Level L;
  Fvar_level F;
  channel_topology(function, mesh, s, user, rules, L, F);

  using Value = typename Linear::Value;
  std::vector<Value> values;
  values.reserve(from.number_of_values());
  for (const T& t : from.values())
    values.push_back(Linear::from(t));
  std::vector<Value> limits;
  if (rules.linear_all) { // OpenSubdiv's linear channel: every value is its own limit
    for (u32 x = 0; x < F.v_offset.back(); ++x)
      limits.push_back(values[F.value(x)]);
  } else {
    limits = limit_vertex_values<Mask, W>(L, F, values, s.corner_if_one_face);
  }

  std::vector<T> out = from.values();
  std::vector<u32> index_of(F.value_of.size());
  std::vector<char> claimed(out.size(), 0);
  for (u32 x = 0; x < u32(F.value_of.size()); ++x) {
    const u32 u = F.value(x);
    index_of[x] = claimed[u] ? u32(out.size()) : u;
    if (claimed[u])
      out.push_back(Linear::to(limits[x]));
    else
      out[u] = Linear::to(limits[x]);
    claimed[u] = 1;
  }
  std::vector<u32> indices(mesh.number_of_halfedges());
  for (Halfedge_index h : mesh.halfedges())
    indices[h.idx()] = mesh.is_border(h) ? from.index(h) : index_of[F.corner[h.idx()]];
  to.values() = std::move(out);
  for (Halfedge_index h : mesh.halfedges())
    to.set_index(h, indices[h.idx()]);
}

// The same in place on the channel named `name`, whatever its value type
// among those subdivision carries.
template <class Mask, class P, class NP>
void write_corner_limits(const char* function, const Mobius_mesh<P>& mesh, const std::string& name, const NP& np)
{
  using K = typename CGAL::Kernel_traits<P>::Kernel;
  using W = typename Point_values<P>::Weight;
  bool found = false;
  for_each_interpolated_channel_type<K>([&](auto tag) {
    using T = typename decltype(tag)::type;
    if constexpr (Linear_value<W, K, T>::defined) {
      if (found)
        return;
      if (const auto c = mesh.template corner_channel<T>(name)) {
        found = true;
        write_corner_limits<Mask>(function, mesh, *c, *c, np);
      }
    }
  });
  if (found)
    return;
  const std::vector<std::string> names = mesh.corner_channels();
  const bool exists = std::find(names.begin(), names.end(), name) != names.end();
  throw Parameter_error(std::string(function) + ": " +
                        (exists ? "the values of corner channel \"" + name + "\" have no linear combination"
                                : "the mesh has no corner channel \"" + name + "\""));
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_LIMIT_FACE_VARYING_H
