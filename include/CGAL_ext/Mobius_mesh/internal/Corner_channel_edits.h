// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The corner channels through the edits of decimate() and
// isotropic_remeshing(): seams kept as feature edges, the corners of two
// merged vertices given one value, the corners of a new vertex in the middle
// of an edge, and those of a vertex that moves.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_EDITS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_EDITS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_checks.h>
#include <CGAL_ext/Mobius_mesh/internal/Linear_values.h>
#include <CGAL_ext/Mobius_mesh/internal/Triangles_round_collapse.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/assertions.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// The barycentric coordinates, with respect to the triangle (a, b, c), of
// the projection of q onto its plane; all -infinity if it has no area.
inline std::array<double, 3> barycentric_d(const Point_d& a, const Point_d& b, const Point_d& c, const Point_d& q)
{
  const Point_d e0 = minus_d(b, a), e1 = minus_d(c, a), eq = minus_d(q, a);
  const double d00 = dot_d(e0, e0), d01 = dot_d(e0, e1), d11 = dot_d(e1, e1);
  const double det = d00 * d11 - d01 * d01;
  if (!(det > 0))
    return {-std::numeric_limits<double>::infinity(), 0, 0};
  const double d0 = dot_d(eq, e0), d1 = dot_d(eq, e1);
  const double wb = (d11 * d0 - d01 * d1) / det, wc = (d00 * d1 - d01 * d0) / det;
  return {1 - wb - wc, wb, wc};
}

// The seams of every channel are feature edges, never collapsed, split or
// flipped, and their ends never moved: a collapse then meets at most one
// *seam vertex* (a vertex whose corners hold several indices of a channel;
// an edge between two is never collapsed, see can_collapse()), and
// * where one end is a seam vertex, it stays where it is, and the faces of
//   the other end take, at the kept vertex, the indices the faces along the
//   edge hold at the seam vertex: the region of the channel grows over them,
//   every value stays as it was;
// * where neither is, each end has one index per channel, and the kept
//   vertex's corners take one new value (so that corners of other vertices
//   sharing an index keep theirs): the one the caller fitted (decimation,
//   from its attribute quadrics), else one made from both ends, interpolated
//   along the edge at the projection of the collapse's point onto it. Along
//   the edge rather than at the nearest point of the triangles round it: the
//   point of a collapse lies off the surface where it bends, and its nearest
//   point on a triangle can then slide far across the triangle, taking the
//   far corner's value (up to three times the error, measured on a torus).
// A vertex made in the middle of an edge off the seams takes, on each side,
// the value halfway between that side's corners at the ends; a vertex off
// the seams that moves takes the value at its new point of a triangle that
// holds it: of the input, where the caller knows one on the same side of the
// seams (remeshing, which projects onto the input), else of its star before
// the move. Values are made, never changed: corners of other vertices may
// share an index.
// Outside decimation, the values follow the points that the loop places:
// they do not weigh in the placement.
template <class P>
class Corner_channel_edits
{
  using u32 = std::uint32_t;

public:
  // Call after the mesh is triangulated.
  explicit Corner_channel_edits(Mobius_mesh<P>& mesh) : m_(mesh)
  {
    using K = typename CGAL::Kernel_traits<P>::Kernel;
    using W = typename K::FT;
    for (const std::string& name : mesh.corner_channels())
      for_each_interpolated_channel_type<K>([&](auto tag) {
        using T = typename decltype(tag)::type;
        using L = Linear_value<W, K, T>;
        if constexpr (L::defined) {
          if (const auto c = mesh.template corner_channel<T>(name))
            channels_.push_back({c->array(), c->number_of_values(), doubles_of<K, T>(*c),
                                 [c = *c](const u32* index, const double* weight, std::size_t n) {
                                   // The first weight is 1 minus the others in W: they sum to 1
                                   // exactly with an exact kernel.
                                   W first(1);
                                   auto sum = W(weight[1]) * L::from(c.values()[index[1]]);
                                   first -= W(weight[1]);
                                   for (std::size_t k = 2; k < n; ++k) {
                                     sum = sum + W(weight[k]) * L::from(c.values()[index[k]]);
                                     first -= W(weight[k]);
                                   }
                                   return c.add_value(L::to(first * L::from(c.values()[index[0]]) + sum));
                                 }});
        }
      });
    if (channels_.empty())
      return;
    seam_vertex_.assign(mesh.num_vertices(), 0);
    for (Vertex_index v : mesh.vertices())
      mark_if_several_indices(v);
  }
  // The same, adding the seams to decimation's feature edges.
  Corner_channel_edits(Mobius_mesh<P>& mesh, std::vector<char>& feature) : Corner_channel_edits(mesh)
  {
    if (!channels_.empty())
      for (Edge_index e : mesh.edges())
        if (is_seam(e))
          feature[e.idx()] = 1;
  }

  bool has_channels() const { return !channels_.empty(); }
  std::size_t number_of_channels() const { return channels_.size(); }
  // The doubles a value of channel k is read as (0: it is not).
  std::size_t value_size(std::size_t k) const { return channels_[k].doubles.size; }
  // The value of the corner of face(h) at target(h) in channel k, as
  // value_size(k) doubles into x; false if the corner has none.
  bool read_corner(std::size_t k, Dart h, double* x) const
  {
    const u32 i = channels_[k].array->indices()[m_.corner(h).idx()];
    if (i == Base_corner_channel::no_value || channels_[k].doubles.size == 0)
      return false;
    channels_[k].doubles.read(i, x);
    return true;
  }

  // Drops the values made since the start that no corner names any more, the
  // others renumbered in their order: most edits make a value (a move one
  // for its vertex's corners, a split one a side, a collapse one), and a loop
  // of many passes would otherwise hold them all. Indices taken since the
  // start are stale after it.
  void remove_unused_values()
  {
    for (Channel& c : channels_)
      internal::remove_unused_values(m_, *c.array, c.values_at_start);
  }

  // Whether e is a seam of some channel: the corners of its two faces at an
  // end hold different indices.
  bool is_seam(Edge_index e) const
  {
    if (channels_.empty() || m_.is_border(e))
      return false;
    for (const Channel& c : channels_)
      if (is_channel_cut(m_, c.array->indices(), e))
        return true;
    return false;
  }

  // False for an edge between two seam vertices.
  bool can_collapse(Dart d) const
  {
    return channels_.empty() || !(is_seam_vertex(m_.source(d)) && is_seam_vertex(m_.target(d)));
  }

  // The end of `d` that is a seam vertex, if one is.
  Vertex_index seam_end(Dart d) const
  {
    if (!channels_.empty())
      for (Vertex_index end : {m_.source(d), m_.target(d)})
        if (is_seam_vertex(end))
          return end;
    return Vertex_index();
  }

  // What the corners of the faces round the kept vertex will hold after the
  // collapse of `d` (source(d) removed, target(d) kept) to `point` (an end's
  // own point where the collapse keeps it), read before the collapse: for
  // each face of either end but the two along the edge, the indices of its
  // three corners, by channel. They are written back after the collapse
  // whatever the Euler operations did with the faces and corners, so that
  // the rule is this class's alone.
  struct Face_corners
  {
    std::vector<u32> at_x, at_y, at_kept; // by channel
  };
  using Plan = Triangles_round_collapse<Face_corners>;
  // `fitted`, if given, holds by channel the value (as doubles) that a
  // collapse between two vertices off the seams gives the merged corners
  // where it makes a new value (decimation's attribute quadrics); an empty
  // one, or none, interpolates along the edge.
  Plan plan(Dart d, const P& point, const std::vector<std::vector<double>>* fitted = nullptr) const
  {
    if (channels_.empty())
      return Plan();
    const Vertex_index p = m_.source(d), q = m_.target(d);
    const bool seam_p = is_seam_vertex(p), seam_q = is_seam_vertex(q);
    const Dart at_p = dart_along(d, p), at_q = dart_along(d, q);
    std::vector<u32> moved = indices_at(seam_p ? at_p : at_q); // what the corners at an end off the seams take
    if (!seam_p && !seam_q) {
      const std::vector<u32> ip = indices_at(at_p);
      const double t = parameter_along(p, q, point);
      // A fitted value stands wherever the point is not an end's own (its
      // projection onto the edge may still fall on an end).
      const double t_fitted = point == m_.point(p) ? 0.0 : point == m_.point(q) ? 1.0 : 0.5;
      for (std::size_t k = 0; k < channels_.size(); ++k) {
        const bool fits = fitted && k < fitted->size() && !(*fitted)[k].empty();
        moved[k] = merged(channels_[k], ip[k], moved[k], fits ? t_fitted : t, fits ? (*fitted)[k].data() : nullptr);
      }
    }
    return Plan(m_, d, [&](const typename Plan::Darts& f) {
      const bool keeps = m_.target(f.at_end) == p ? seam_p : seam_q;
      return Face_corners{indices_at(f.at_x), indices_at(f.at_y), keeps ? indices_at(f.at_end) : moved};
    });
  }

  // The dart of a face along the edge of d (d's own, or its opposite's on
  // the border) that ends at `end`, an end of d: where the corner of `end`
  // that a collapse of d hands on lies.
  Dart dart_along(Dart d, Vertex_index end) const
  {
    const Dart along = m_.is_border(d) ? m_.opposite(d) : d;
    const bool at_target = end == m_.target(d);
    if (along == d)
      return at_target ? d : m_.prev(d);
    return at_target ? m_.prev(along) : along;
  }

  // Writes the plan's indices into the faces round `kept`, after the collapse.
  void apply(const Plan& plan, Vertex_index kept)
  {
    plan.for_each_after(m_, kept, [&](const typename Plan::Darts& f, const Face_corners& corners) {
      for (std::size_t i = 0; i < channels_.size(); ++i) {
        Base_corner_channel::Index_array& index = channels_[i].array->indices();
        index[m_.corner(f.at_end).idx()] = corners.at_kept[i];
        index[m_.corner(f.at_x).idx()] = corners.at_x[i];
        index[m_.corner(f.at_y).idx()] = corners.at_y[i];
      }
    });
  }

  // The corners of the new vertex that splitting an edge off the seams at
  // its midpoint makes: on each side, by channel, the value halfway between
  // that side's corners at the ends (one value for both sides where they
  // agree at both ends). Read before Euler::split_edge(d), written after it
  // by apply_split().
  struct Split_side
  {
    Face_index face;
    std::vector<u32> at_source, at_target, at_middle; // by channel; source and target of the edge's dart d
  };
  using Split_plan = boost::container::small_vector<Split_side, 2>;
  Split_plan split_plan(Dart d) const
  {
    Split_plan plan;
    if (channels_.empty())
      return plan;
    for (Dart side : {d, m_.opposite(d)}) {
      if (m_.is_border(side))
        continue;
      const bool along = side == d;
      Split_side s{m_.face(side), indices_at(along ? m_.prev(side) : side), indices_at(along ? side : m_.prev(side)), {}};
      const bool as_first = !plan.empty() && plan[0].at_source == s.at_source && plan[0].at_target == s.at_target;
      for (std::size_t k = 0; k < channels_.size(); ++k)
        s.at_middle.push_back(as_first ? plan[0].at_middle[k] : merged(channels_[k], s.at_source[k], s.at_target[k], 0.5));
      plan.push_back(std::move(s));
    }
    return plan;
  }
  // Writes the plan into the corners of `middle`, the vertex Euler::split_edge() made.
  void apply_split(const Split_plan& plan, Vertex_index middle)
  {
    for (const Split_side& s : plan)
      for (Dart h : CGAL_ext::halfedges_around_target(m_.halfedge(middle), m_))
        if (!m_.is_border(h) && m_.face(h) == s.face)
          set_indices(h, s.at_middle);
  }

  // The indices, by channel, that the corners of `v`, a vertex off the
  // seams, take when it moves to `to`: the values at the point of its star
  // (as it is before the move) nearest to `to`, interpolated in that
  // triangle. Written by apply_move() after the move.
  std::vector<u32> move_plan(Vertex_index v, const P& to) const
  {
    if (channels_.empty())
      return {};
    Dart best;
    std::array<double, 3> weight{1, 0, 0};
    double best_score = -std::numeric_limits<double>::infinity();
    const Point_d q = to_point_d(to), a = to_point_d(m_.point(v));
    for (Dart h : CGAL_ext::halfedges_around_target(m_.halfedge(v), m_)) {
      if (m_.is_border(h))
        continue;
      const std::array<double, 3> w =
        barycentric_d(a, to_point_d(m_.point(m_.target(m_.next(h)))), to_point_d(m_.point(m_.source(h))), q);
      const double score = (std::min)({w[0], w[1], w[2]});
      if (score > best_score) {
        best_score = score;
        best = h;
        weight = w;
      }
    }
    std::vector<u32> plan = indices_at(best);
    if (best_score == -std::numeric_limits<double>::infinity())
      return plan; // no triangle of the star has an area: the values stay
    const std::vector<u32> at_next = indices_at(m_.next(best)), at_prev = indices_at(m_.prev(best));
    for (std::size_t k = 0; k < channels_.size(); ++k)
      plan[k] = mixed(k, {plan[k], at_next[k], at_prev[k]}, weight, plan[k]);
    return plan;
  }
  // The same, from a triangle of the input and the weights of `to` in it:
  // `corners` are that triangle's indices (triangle_corners(), read before
  // the edits began), three times the number of channels.
  std::vector<u32> move_plan(Vertex_index v, const u32* corners, const std::array<double, 3>& weight) const
  {
    std::vector<u32> plan;
    for (Dart h : CGAL_ext::halfedges_around_target(m_.halfedge(v), m_))
      if (!m_.is_border(h)) { // (a border vertex's halfedge is its border one)
        plan = indices_at(h);
        break;
      }
    const std::size_t n = channels_.size();
    for (std::size_t k = 0; k < n; ++k)
      plan[k] = mixed(k, {corners[k], corners[n + k], corners[2 * n + k]}, weight, plan[k]);
    return plan;
  }
  // The indices of the corners of triangle f at the source, the target and
  // the next target of halfedge(f), by channel, in that order.
  std::vector<u32> triangle_corners(Face_index f) const
  {
    std::vector<u32> corners;
    const Dart d = m_.halfedge(f);
    for (Dart h : {m_.prev(d), d, m_.next(d)})
      for (u32 i : indices_at(h))
        corners.push_back(i);
    return corners;
  }
  // Gives every corner of `v` the plan's indices.
  void apply_move(const std::vector<u32>& plan, Vertex_index v)
  {
    if (channels_.empty())
      return;
    for (Dart h : CGAL_ext::halfedges_around_target(m_.halfedge(v), m_))
      if (!m_.is_border(h))
        set_indices(h, plan);
  }

  // Whether v's corners hold several indices of a channel.
  bool is_seam_vertex(Vertex_index v) const { return v.idx() < seam_vertex_.size() && seam_vertex_[v.idx()]; }

  // The kept vertex is a seam vertex if either end was.
  void merge_flags(Vertex_index removed, Vertex_index kept)
  {
    if (channels_.empty())
      return;
    seam_vertex_.resize((std::max)(seam_vertex_.size(), std::size_t(m_.num_vertices())), 0);
    seam_vertex_[kept.idx()] = seam_vertex_[kept.idx()] || seam_vertex_[removed.idx()];
  }

private:
  // A channel's values as doubles (Value_doubles), where they can be.
  struct Doubles
  {
    std::size_t size = 0; // per value; 0: not read as doubles
    std::function<void(u32 index, double* x)> read;
    std::function<u32(const double* x)> make; // appends the value, returns its index
  };
  template <class K, class T, class Channel_map>
  static Doubles doubles_of(const Channel_map& c)
  {
    using D = Value_doubles<K, T>;
    if constexpr (D::defined)
      return {D::size, [c](u32 i, double* x) { D::read(c.values()[i], x); },
              [c](const double* x) { return c.add_value(D::make(x)); }};
    else
      return {};
  }

  struct Channel
  {
    Base_corner_channel* array;
    std::size_t values_at_start; // kept where they are: callers hold their indices
    Doubles doubles;
    // Appends the combination of the n values of `index` with weights
    // `weight` (the first one's taken as 1 minus the others), returns its index.
    std::function<u32(const u32* index, const double* weight, std::size_t n)> mix;
  };

  void set_indices(Dart h, const std::vector<u32>& by_channel)
  {
    for (std::size_t k = 0; k < channels_.size(); ++k)
      channels_[k].array->indices()[m_.corner(h).idx()] = by_channel[k];
  }

  // The index of the combination of the values `index` with weights
  // `weight` of channel k, over the corners that have a value, the weights
  // clamped to [0, 1] and scaled to sum to 1 (so that the value stays among
  // theirs); `keep` (v's own) where it has none or none has, and the one
  // index where they all hold it.
  u32 mixed(std::size_t k, std::array<u32, 3> index, std::array<double, 3> weight, u32 keep) const
  {
    if (keep == Base_corner_channel::no_value)
      return keep;
    std::size_t n = 0;
    double total = 0;
    for (std::size_t i = 0; i < 3; ++i)
      if (index[i] != Base_corner_channel::no_value && weight[i] > 0) {
        index[n] = index[i];
        total += (weight[n++] = weight[i]);
      }
    if (n == 0)
      return keep;
    if (std::all_of(index.begin(), index.begin() + std::ptrdiff_t(n), [&](u32 i) { return i == index[0]; }))
      return index[0]; // one value (a channel constant there): no new one
    for (std::size_t i = 0; i < n; ++i)
      weight[i] /= total;
    return channels_[k].mix(index.data(), weight.data(), n);
  }

  // The index of the corner of face(h) at target(h), by channel.
  std::vector<u32> indices_at(Dart h) const
  {
    std::vector<u32> result;
    for (const Channel& c : channels_)
      result.push_back(c.array->indices()[m_.corner(h).idx()]);
    return result;
  }

  void mark_if_several_indices(Vertex_index v)
  {
    for (const Channel& c : channels_) {
      u32 first = Base_corner_channel::no_value;
      bool any = false;
      for (Dart h : CGAL_ext::halfedges_around_target(m_.halfedge(v), m_)) {
        if (m_.is_border(h))
          continue;
        const u32 i = c.array->indices()[m_.corner(h).idx()];
        if (any && i != first)
          seam_vertex_[v.idx()] = 1;
        first = any ? first : i;
        any = true;
      }
    }
  }

  // Where `point` projects onto the segment from p to q, in [0, 1].
  double parameter_along(Vertex_index p, Vertex_index q, const P& point) const
  {
    if (point == m_.point(p))
      return 0;
    if (point == m_.point(q))
      return 1;
    const Point_d a = to_point_d(m_.point(p)), ab = minus_d(to_point_d(m_.point(q)), a);
    const double length = dot_d(ab, ab);
    return length > 0 ? (std::clamp)(dot_d(minus_d(to_point_d(point), a), ab) / length, 0.0, 1.0) : 0.0;
  }

  // The one index of two ends that each have one: theirs where they agree
  // or the point is at an end, the other's where one end's corners have no
  // value (the merged region has one value or none: the one there is, rather
  // than dropping it), else a new value: `fitted` where given, else the
  // value between them at t.
  static u32 merged(const Channel& c, u32 ip, u32 iq, double t, const double* fitted = nullptr)
  {
    if (ip == iq || iq == Base_corner_channel::no_value || t == 0)
      return ip == Base_corner_channel::no_value ? iq : ip;
    if (ip == Base_corner_channel::no_value || t == 1)
      return iq;
    if (fitted)
      return c.doubles.make(fitted);
    const u32 index[2] = {ip, iq};
    const double weight[2] = {1 - t, t};
    return c.mix(index, weight, 2);
  }

  Mobius_mesh<P>& m_;
  std::vector<Channel> channels_;
  std::vector<char> seam_vertex_; // by vertex index
};

// The number of values of each corner channel of `mesh`, in order of creation.
template <class P>
std::vector<std::size_t> corner_value_counts(const Mobius_mesh<P>& mesh)
{
  std::vector<std::size_t> counts;
  Connectivity_access::properties<Halfedge_index>(mesh).template for_each_array<Base_corner_channel>(
    [&](const Base_corner_channel& c) { counts.push_back(c.number_of_values()); });
  return counts;
}

// The values of the corner channels of `mesh` that a face corner names and
// that were added after the first `counts_before` of each channel (those the
// channel held before): the values interpolated by collapses that remain.
template <class P>
std::size_t added_values_in_use(const Mobius_mesh<P>& mesh, const std::vector<std::size_t>& counts_before)
{
  std::size_t added = 0, channel = 0;
  Connectivity_access::properties<Halfedge_index>(mesh).template for_each_array<Base_corner_channel>(
    [&](const Base_corner_channel& c) {
      const std::size_t before = counts_before[channel++];
      std::vector<char> used(c.number_of_values() > before ? c.number_of_values() - before : 0, 0);
      for (Face_index f : mesh.faces())
        for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
          const std::uint32_t i = c.indices()[mesh.corner(d).idx()];
          if (i != Base_corner_channel::no_value && i >= before && !std::exchange(used[i - before], 1))
            ++added;
        }
    });
  return added;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_CORNER_CHANNEL_EDITS_H
