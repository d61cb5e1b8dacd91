// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The corner channels through decimate()'s collapses: seams kept as feature
// edges, and the corners of the two merged vertices given one value.

#ifndef CGAL_EXT_DECIMATION_INTERNAL_CORNER_MERGING_H
#define CGAL_EXT_DECIMATION_INTERNAL_CORNER_MERGING_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/internal/Linear_values.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// The seams of every channel are feature edges, never collapsed and their
// ends never moved: a collapse then meets at most one *seam vertex* (a vertex
// whose corners hold several indices of a channel; an edge between two is
// never collapsed, see can_collapse()), and
// * where one end is a seam vertex, it stays where it is, and the faces of
//   the other end take, at the kept vertex, the indices the faces along the
//   edge hold at the seam vertex: the region of the channel grows over them,
//   every value stays as it was;
// * where neither is, each end has one index per channel, and the kept
//   vertex's corners take one value made from both, interpolated along the
//   edge at the projection of the collapse's point onto it (a new value, so
//   that corners of other vertices sharing an index keep theirs). Along the
//   edge rather than at the nearest point of the triangles round it: the
//   point of a collapse lies off the surface where it bends, and its nearest
//   point on a triangle can then slide far across the triangle, taking the
//   far corner's value (up to three times the error, measured on a torus).
// This is the approximation of the values (Garland and Heckbert's attribute
// quadrics would weigh them in the placement; here they follow it).
template <class P>
class Corner_merging
{
  using u32 = std::uint32_t;

public:
  // Call after the mesh is triangulated, with the decimation's feature edges,
  // to which the seams are added.
  Corner_merging(Mobius_mesh<P>& mesh, std::vector<char>& feature) : m_(mesh)
  {
    using K = typename CGAL::Kernel_traits<P>::Kernel;
    using W = typename K::FT;
    for (const std::string& name : mesh.corner_channels())
      for_each_interpolated_channel_type<K>([&](auto tag) {
        using T = typename decltype(tag)::type;
        using L = Linear_value<W, K, T>;
        if constexpr (L::defined) {
          if (const auto c = mesh.template corner_channel<T>(name))
            channels_.push_back({&c->array()->indices(), [c = *c](u32 a, u32 b, double t) {
                                   // 1 - t in W: the weights sum to 1 exactly with an exact kernel.
                                   const W wt(t);
                                   return c.add_value(L::to((W(1) - wt) * L::from(c.values()[a]) +
                                                            wt * L::from(c.values()[b])));
                                 }});
        }
      });
    if (channels_.empty())
      return;
    const std::vector<char> seam = corner_seam_edges(mesh);
    seam_vertex_.assign(mesh.num_vertices(), 0);
    for (Edge_index e : mesh.edges())
      if (seam[e.idx()]) {
        feature[e.idx()] = 1;
        for (int i : {0, 1})
          mark_if_several_indices(mesh.vertex(e, i));
      }
  }

  // False for an edge between two seam vertices.
  bool can_collapse(Dart d) const
  {
    return channels_.empty() || !(seam_vertex_[m_.source(d).idx()] && seam_vertex_[m_.target(d).idx()]);
  }

  // The end of `d` that is a seam vertex, if one is.
  Vertex_index seam_end(Dart d) const
  {
    if (!channels_.empty())
      for (Vertex_index end : {m_.source(d), m_.target(d)})
        if (seam_vertex_[end.idx()])
          return end;
    return Vertex_index();
  }

  // What the corners of the faces round the kept vertex will hold after the
  // collapse of `d` (source(d) removed, target(d) kept) to `point` (an end's
  // own point where the collapse keeps it), read before the collapse: for
  // each face of either end but the two along the edge, by its two other
  // vertices, the indices of its three corners. They are written back after
  // the collapse whatever the Euler operations did with the faces (which
  // face of a collapsed triangle's neighbours keeps its index, which of two
  // corners survives), so that the rule is this class's alone.
  struct Face_corners
  {
    Vertex_index x, y;              // its corners other than at the kept vertex, x < y
    std::vector<u32> at_x, at_y, at_kept; // by channel
    bool operator<(const Face_corners& o) const { return std::tie(x, y) < std::tie(o.x, o.y); }
  };
  using Plan = std::vector<Face_corners>;
  Plan plan(Dart d, const P& point) const
  {
    Plan plan;
    if (channels_.empty())
      return plan;
    const Vertex_index p = m_.source(d), q = m_.target(d);
    const bool seam_p = seam_vertex_[p.idx()], seam_q = seam_vertex_[q.idx()];
    // A face along the edge and its darts that end at p and at q.
    const Dart along = m_.is_border(d) ? m_.opposite(d) : d;
    const Dart at_q = along == d ? d : m_.prev(along), at_p = along == d ? m_.prev(d) : along;
    std::vector<u32> moved = indices_at(seam_p ? at_p : at_q); // what the corners at an end off the seams take
    if (!seam_p && !seam_q) {
      const std::vector<u32> ip = indices_at(at_p);
      const double t = parameter_along(p, q, point);
      for (std::size_t k = 0; k < channels_.size(); ++k)
        moved[k] = merged(channels_[k], ip[k], moved[k], t);
    }
    const Face_index gone[2] = {m_.face(d), m_.face(m_.opposite(d))};
    for (Vertex_index end : {p, q})
      for (Dart h : CGAL_ext::halfedges_around_target(m_.halfedge(end), m_)) {
        if (m_.is_border(h) || m_.face(h) == gone[0] || m_.face(h) == gone[1])
          continue;
        const bool keeps = end == p ? seam_p : seam_q;
        Dart hx = m_.next(h), hy = m_.next(hx);
        if (m_.target(hy) < m_.target(hx))
          std::swap(hx, hy);
        Face_corners f{m_.target(hx), m_.target(hy), indices_at(hx), indices_at(hy), keeps ? indices_at(h) : moved};
        plan.push_back(std::move(f));
      }
    std::sort(plan.begin(), plan.end());
    return plan;
  }

  // Writes the plan's indices into the faces round `kept`, after the collapse.
  void apply(const Plan& plan, Vertex_index kept)
  {
    if (channels_.empty())
      return;
    for (Dart h : CGAL_ext::halfedges_around_target(m_.halfedge(kept), m_)) {
      if (m_.is_border(h))
        continue;
      Dart hx = m_.next(h), hy = m_.next(hx);
      if (m_.target(hy) < m_.target(hx))
        std::swap(hx, hy);
      Face_corners key;
      key.x = m_.target(hx);
      key.y = m_.target(hy);
      const auto f = std::lower_bound(plan.begin(), plan.end(), key);
      CGAL_assertion(f != plan.end() && f->x == key.x && f->y == key.y);
      if (f == plan.end() || f->x != key.x || f->y != key.y)
        continue;
      for (std::size_t i = 0; i < channels_.size(); ++i) {
        Base_corner_channel::Index_array& index = *channels_[i].index;
        index[m_.corner(h).idx()] = f->at_kept[i];
        index[m_.corner(hx).idx()] = f->at_x[i];
        index[m_.corner(hy).idx()] = f->at_y[i];
      }
    }
  }

  // The kept vertex is a seam vertex if either end was.
  void merge_flags(Vertex_index removed, Vertex_index kept)
  {
    if (!channels_.empty())
      seam_vertex_[kept.idx()] = seam_vertex_[kept.idx()] || seam_vertex_[removed.idx()];
  }

private:
  struct Channel
  {
    Base_corner_channel::Index_array* index; // by corner slot
    std::function<u32(u32, u32, double)> mix; // appends (1 - t) a + t b, returns its index
  };

  // The index of the corner of face(h) at target(h), by channel.
  std::vector<u32> indices_at(Dart h) const
  {
    std::vector<u32> result;
    for (const Channel& c : channels_)
      result.push_back((*c.index)[m_.corner(h).idx()]);
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
        const u32 i = (*c.index)[m_.corner(h).idx()];
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
  // than dropping it), else a new value between them.
  static u32 merged(const Channel& c, u32 ip, u32 iq, double t)
  {
    if (ip == iq || iq == Base_corner_channel::no_value || t == 0)
      return ip == Base_corner_channel::no_value ? iq : ip;
    if (ip == Base_corner_channel::no_value || t == 1)
      return iq;
    return c.mix(ip, iq, t);
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

#endif // CGAL_EXT_DECIMATION_INTERNAL_CORNER_MERGING_H
