// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The one connectivity builder: from faces given as lists of vertex indices
// to halfedges, darts, Möbius bits and border links, in time linear in the
// number of corners. It knows no geometry; the soup import, the generators,
// merging, the Surface_mesh conversion and the subdivision splits that list
// their child faces all build through it.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_CONNECTIVITY_BUILDER_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_CONNECTIVITY_BUILDER_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>
#include <CGAL_ext/Mobius_mesh/internal/Size_limits.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Huge_page_allocator.h>
#include <CGAL_ext/internal/Parallel_loops.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

/// Faces as one flat array of vertex indices: face f is
/// `vertex[offset[f]] ... vertex[offset[f + 1] - 1]`, in cycle order.
struct Face_lists
{
  std::uint32_t n_vertices = 0;
  std::uint32_t n_faces = 0;
  const std::uint32_t* offset = nullptr; ///< n_faces + 1 entries
  const std::uint32_t* vertex = nullptr;
  /// Corners (flat indices) whose side, to the next corner, is a
  /// border of its own whatever other side has its two ends: where the
  /// caller knows better than the ends (the sides of a polygon that visits a
  /// vertex twice, see Repeated_vertex_split.h).
  const std::uint32_t* lone_side = nullptr;
  std::size_t n_lone_sides = 0;
  /// Corners (flat indices, sorted) at a vertex that their face visited
  /// before, within the same fan: where the caller has checked that a
  /// face may visit a vertex twice (see Repeated_vertex_split.h).
  const std::uint32_t* folded_corner = nullptr;
  std::size_t n_folded_corners = 0;
};

/// Faces listed one after the other, in arrays of their own (on huge pages
/// when large, as the builder's); `view()` gives the builder its input.
struct Face_list
{
  Huge_page_vector<std::uint32_t> offset{0}, vertex;

  void clear()
  {
    offset.assign(1, 0);
    vertex.clear();
  }
  void add(std::initializer_list<std::uint32_t> vs) { add(vs.begin(), vs.end()); }
  template <class It>
  void add(It begin, It end)
  {
    vertex.insert(vertex.end(), begin, end);
    offset.push_back(std::uint32_t(vertex.size()));
  }
  std::uint32_t size() const { return std::uint32_t(offset.size() - 1); }
  Face_lists view(std::uint32_t n_vertices) const { return {n_vertices, size(), offset.data(), vertex.data()}; }
};

/// A vertex whose faces form several fans gets a copy per further fan when
/// splitting is asked for: copy `n_vertices + k` is `split[k].original`, its
/// incoming dart `split[k].dart`.
struct Split_vertex
{
  std::uint32_t original;
  std::uint32_t dart;
};

/// Builds the connectivity of a 2-manifold from face lists in two phases:
/// the constructor pairs the faces' sides into edges (so that the caller
/// can size the output), `build()` writes the links. Two faces that share an
/// edge are connected whichever way they run along it; running the same way
/// makes a Möbius edge. A face may visit a vertex twice only at a corner the
/// caller names (`Face_lists::folded_corner`); a lone side between two such
/// visits becomes a loop, a border edge from the vertex to itself and a
/// border loop of its own. Input that is not a 2-manifold throws
/// `Soup_error` naming the faces and vertices at fault: a repeated vertex or
/// an edge of three faces from the constructor, before anything is written;
/// a non-manifold vertex from `build()`, whose output the caller then drops.
class Connectivity_builder
{
public:
  using u32 = std::uint32_t;

  /// With `CGAL::Parallel_tag` (and TBB), every phase runs in parallel and
  /// gives the same arrays, bit for bit, as the serial build.
  /// With `split_non_manifold_edges`, the sides of an edge of three or more
  /// faces are not refused but left unpaired: each face gets a border edge
  /// of its own there (`number_of_non_manifold_edges()` counts such edges).
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  explicit Connectivity_builder(const Face_lists& faces, ConcurrencyTag = ConcurrencyTag(),
                                bool split_non_manifold_edges = false)
      : faces_(faces), parallel_(is_parallel_tag<ConcurrencyTag>), split_edges_(split_non_manifold_edges)
  {
    with_concurrency<ConcurrencyTag>(true, [&](auto tag) {
      using Tag = decltype(tag);
      number_corners<Tag>();
      if (faces_.n_lone_sides != 0) {
        lone_.assign(n_corners_, false);
        for (std::size_t k = 0; k < faces_.n_lone_sides; ++k)
          lone_[faces_.lone_side[k]] = true;
      }
      check_repeated_vertices<Tag>();
      pair_sides<Tag>();
      number_edges<Tag>();
    });
    check_mesh_size("the faces", Mesh_size{faces_.n_vertices, n_edges_, faces_.n_faces, 0});
  }

  u32 number_of_vertices() const { return faces_.n_vertices; }
  u32 number_of_edges() const { return n_edges_; }
  u32 number_of_faces() const { return faces_.n_faces; }
  /// The edges of three or more faces left as borders (see the constructor).
  u32 number_of_non_manifold_edges() const { return n_non_manifold_edges_; }

  /// Writes the links into `out`: arrays in the mesh's layout (see
  /// `Connectivity_arrays`), sized by the caller for the counts above. A
  /// non-manifold vertex throws unless `split_non_manifold_vertices`; then
  /// its further fans get new vertices (returned; their halfedges' targets
  /// are already set to the copies).
  std::vector<Split_vertex> build(const Connectivity_arrays& out, bool split_non_manifold_vertices)
  {
    out_ = out;
#ifdef CGAL_LINKED_WITH_TBB
    if (parallel_) {
      link_faces<CGAL::Parallel_tag>();
      if (link_fans_in_parallel<CGAL::Parallel_tag>()) {
        Array().swap(partner_);
        return {};
      }
      // The serial build names the fans at fault, or splits them.
    }
#endif
    link_faces<CGAL::Sequential_tag>();
    Array().swap(partner_);
    return link_fans(split_non_manifold_vertices);
  }

private:
  static constexpr u32 null = dart_encoding::null;
  // The temporaries are as large as the mesh, and a cold import spends most
  // of its time faulting in their fresh pages: on huge pages, one fault per
  // 2 MiB instead of one per 4 KiB.
  using Array = Huge_page_vector<u32>;

  u32 corner_vertex(std::size_t t) const { return faces_.vertex[t]; }
  // The next corner around a face is the following one, or after the face's
  // last corner its first, found by walking back: once per face and pass,
  // so in time linear in the corners. One bit per corner says where faces
  // start (an array of each corner's face took 32).
  bool is_face_start(std::size_t t) const { return (face_start_[t >> 6] >> (t & 63)) & 1; }
  std::size_t next_corner(std::size_t t) const
  {
    if (t + 1 < n_corners_ && !is_face_start(t + 1))
      return t + 1;
    while (!is_face_start(t))
      --t;
    return t;
  }
  // The face of corner `t`, for the error paths and splitting.
  u32 face_of_corner(std::size_t t) const
  {
    return u32(std::upper_bound(faces_.offset, faces_.offset + faces_.n_faces + 1, u32(t)) - faces_.offset - 1);
  }
  u32 side_low(std::size_t t) const { return (std::min)(corner_vertex(t), corner_vertex(next_corner(t))); }
  u32 side_high(std::size_t t) const { return (std::max)(corner_vertex(t), corner_vertex(next_corner(t))); }

  // Faces have at least one corner each, so no two faces start at the same one.
  template <class Tag>
  void number_corners()
  {
    n_corners_ = faces_.offset[faces_.n_faces];
    face_start_.assign((n_corners_ + 63) / 64, 0);
    for_each_index<Tag>(faces_.n_faces, [&](u32 f) {
      CGAL_precondition(faces_.offset[f] < faces_.offset[f + 1]);
      atomic_or<Tag>(face_start_[faces_.offset[f] >> 6], std::uint64_t(1) << (faces_.offset[f] & 63));
    });
  }

  // The threads only look for a face that visits a vertex twice, each in
  // its faces; the serial pass then names the first, as it always does. A
  // long face, which a quadratic look would take too long over, is left to
  // the serial pass too.
  template <class Tag>
  void check_repeated_vertices() const
  {
    if constexpr (is_parallel_tag<Tag>) {
      auto repeats = [&](u32 f) {
        const u32* begin = faces_.vertex + faces_.offset[f];
        const u32* end = faces_.vertex + faces_.offset[f + 1];
        if (end - begin > 64)
          return true;
        for (const u32* a = begin; a != end; ++a)
          if (std::find(a + 1, end, *a) != end)
            return true;
        return false;
      };
      if (count_if<Tag>(faces_.n_faces, repeats) == 0)
        return;
    }
    check_repeated_vertices_serially();
  }

  // A face may visit a vertex again only at a folded corner.
  void check_repeated_vertices_serially() const
  {
    Array seen_in_face(faces_.n_vertices, null);
    const u32* folded_end = faces_.folded_corner + faces_.n_folded_corners;
    for (u32 f = 0; f < faces_.n_faces; ++f) {
      for (u32 t = faces_.offset[f]; t < faces_.offset[f + 1]; ++t) {
        const u32 v = corner_vertex(t);
        if (seen_in_face[v] == f && !std::binary_search(faces_.folded_corner, folded_end, t))
          throw Soup_error(Soup_error::Kind::repeated_vertex,
                           "polygon " + std::to_string(f) + " visits vertex " + std::to_string(v) + " twice", {f},
                           {std::size_t(v)});
        seen_in_face[v] = f;
      }
    }
  }

  // Each side's partner: the other side with the same two ends.
  template <class Tag>
  void pair_sides()
  {
    if constexpr (is_parallel_tag<Tag>)
      if (faces_.n_lone_sides == 0)
        return pair_sides_in_parallel<Tag>();
    pair_sides_serially();
  }
  bool is_lone_side(u32 t) const { return !lone_.empty() && lone_[t]; }

  // Sides are bucketed by their lower vertex; within a bucket a stamped slot
  // per upper vertex finds the partner in O(1).
  void pair_sides_serially()
  {
    const u32 nv = faces_.n_vertices;
    Array bucket_start(std::size_t(nv) + 1, 0);
    for (std::size_t t = 0; t < n_corners_; ++t)
      ++bucket_start[side_low(t) + 1];
    std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
    Array bucket(n_corners_);
    {
      Array fill(bucket_start.begin(), bucket_start.end() - 1);
      for (std::size_t t = 0; t < n_corners_; ++t)
        bucket[fill[side_low(t)]++] = u32(t);
    }
    partner_.assign(n_corners_, null);
    Array stamp(nv, null), first(nv);
    for (u32 lo = 0; lo < nv; ++lo) {
      for (u32 k = bucket_start[lo]; k < bucket_start[lo + 1]; ++k) {
        const u32 t = bucket[k], hi = side_high(t);
        if (is_lone_side(t)) {
          // A border side of its own, seen by no other.
        } else if (stamp[hi] != lo) {
          stamp[hi] = lo;
          first[hi] = t;
        } else if (first[hi] == null) {
          // A further side of an edge already split: a border side of its own.
        } else if (partner_[first[hi]] == null) {
          partner_[first[hi]] = t;
          partner_[t] = first[hi];
        } else if (split_edges_) {
          // The third side: none of them pairs (null marks the split edge).
          partner_[partner_[first[hi]]] = null;
          partner_[first[hi]] = null;
          first[hi] = null;
          ++n_non_manifold_edges_;
        } else {
          throw_non_manifold_edge(lo, hi, bucket.data() + bucket_start[lo], bucket.data() + bucket_start[lo + 1]);
        }
      }
    }
  }

  [[noreturn]] void throw_non_manifold_edge(u32 lo, u32 hi, const u32* begin, const u32* end) const
  {
    std::vector<std::size_t> offenders;
    for (const u32* s = begin; s != end; ++s)
      if (side_high(*s) == hi)
        offenders.push_back(face_of_corner(*s));
    throw Soup_error(Soup_error::Kind::non_manifold_edge,
                     "edge (" + std::to_string(lo) + ", " + std::to_string(hi) + ") is shared by " +
                       std::to_string(offenders.size()) + " polygons (" + join_ids(offenders) +
                       "); a 2-manifold edge has at most two",
                     offenders, {std::size_t(lo), std::size_t(hi)});
  }

  // The same pairs by threads: each bucket sorted by upper vertex (threads
  // fill the buckets in any order), two sides with the same ends pair up,
  // a third makes a non-manifold edge, which the serial pass then names.
  template <class Tag>
  void pair_sides_in_parallel()
  {
    const u32 nv = faces_.n_vertices, nt = u32(n_corners_);
    Array bucket_start(std::size_t(nv) + 1, 0);
    for_each_index<Tag>(nt, [&](u32 t) { atomic_add<Tag>(bucket_start[side_low(t) + 1], 1); });
    prefix_sum<Tag>(bucket_start.data(), nv);
    // Entries are (upper vertex, corner) in one word, sorted as numbers.
    Huge_page_vector<std::uint64_t> bucket(n_corners_);
    {
      Array fill(bucket_start.begin(), bucket_start.end() - 1);
      for_each_index<Tag>(nt, [&](u32 t) {
        bucket[atomic_add<Tag>(fill[side_low(t)], 1)] = std::uint64_t(side_high(t)) << 32 | t;
      });
    }
    partner_.assign(n_corners_, null);
    auto pairs = [&](u32 lo) {
      return pair_bucket(bucket.data() + bucket_start[lo], bucket.data() + bucket_start[lo + 1]);
    };
    const u32 bad = reduce<Tag>(
      nv, null, [&](u32 lo) { return pairs(lo) ? null : lo; }, [](u32 a, u32 b) { return (std::min)(a, b); });
    if (bad != null)
      pair_sides_serially();
  }

  static u32 high_of(std::uint64_t entry) { return u32(entry >> 32); }
  static u32 corner_of(std::uint64_t entry) { return u32(entry); }

  // Pairs the sides of one bucket; false if three share their ends.
  bool pair_bucket(std::uint64_t* begin, std::uint64_t* end)
  {
    sort_short(begin, end); // a few sides each
    for (std::uint64_t* s = begin; s != end;) {
      std::uint64_t* run_end = s + 1;
      while (run_end != end && high_of(*run_end) == high_of(*s))
        ++run_end;
      if (run_end - s > 2)
        return false;
      if (run_end - s == 2) {
        partner_[corner_of(s[0])] = corner_of(s[1]);
        partner_[corner_of(s[1])] = corner_of(s[0]);
      }
      s = run_end;
    }
    return true;
  }

  // Edges are numbered in order of first use; the corner that uses an edge
  // first gets its halfedge 2e, the partner 2e+1. Edges past what darts
  // index are only counted (the constructor then refuses them): their
  // halfedge numbers would wrap. Threads number alike: an edge's number is
  // the count of first uses before it, a prefix sum.
  template <class Tag>
  void number_edges()
  {
    auto first_use = [&](u32 t) { return partner_[t] == null || t < partner_[t]; };
    auto halfedge = [](u32 e, int i) { return e < max_edges ? dart_encoding::halfedge_of_edge(e, i) : 0; };
    const u32 nt = u32(n_corners_);
    if constexpr (!is_parallel_tag<Tag>) {
      corner_halfedge_.assign(n_corners_, null);
      n_edges_ = 0;
      for (u32 t = 0; t < nt; ++t) {
        if (!first_use(t))
          continue;
        corner_halfedge_[t] = halfedge(n_edges_, 0);
        if (partner_[t] != null)
          corner_halfedge_[partner_[t]] = halfedge(n_edges_, 1);
        ++n_edges_;
      }
      return;
    }
    // Entry t + 1 counts t's first use; summed, entry t is t's edge number.
    corner_halfedge_.resize(n_corners_ + 1);
    corner_halfedge_[0] = 0;
    for_each_index<Tag>(nt, [&](u32 t) { corner_halfedge_[t + 1] = first_use(t) ? 1 : 0; });
    prefix_sum<Tag>(corner_halfedge_.data(), nt);
    n_edges_ = corner_halfedge_[nt];
    // Partners read the number of their first corner before it is replaced.
    for_each_index<Tag>(nt, [&](u32 t) {
      if (!first_use(t))
        corner_halfedge_[t] = halfedge(corner_halfedge_[partner_[t]], 1);
    });
    for_each_index<Tag>(nt, [&](u32 t) {
      if (first_use(t))
        corner_halfedge_[t] = halfedge(corner_halfedge_[t], 0);
    });
    corner_halfedge_.pop_back();
  }

  // Face cycles, border targets, Möbius bits. A vertex's dart is the one of
  // its last corner (the largest), whichever thread writes it.
  template <class Tag>
  void link_faces()
  {
    const u32 nh = 2 * n_edges_, nv = faces_.n_vertices;
    for_each_index<Tag>(nh, [&](u32 h) {
      out_.next_bits[h] = out_.prev_bits[h] = out_.face[h] = null;
    });
    for_each_index<Tag>(n_edges_, [&](u32 e) { out_.mobius[e] = 0; });
    corners_at_.assign(nv, 0);
    if constexpr (is_parallel_tag<Tag>)
      last_corner_.assign(nv, 0); // 1 + the corner, 0 for none
    else
      std::fill(out_.vertex_dart_bits, out_.vertex_dart_bits + nv, null);
    for_each_index<Tag>(faces_.n_faces, [&](u32 f) {
      out_.face_halfedge[f] = corner_halfedge_[faces_.offset[f]];
      for (u32 t = faces_.offset[f]; t < faces_.offset[f + 1]; ++t) {
        const u32 u = t + 1 < faces_.offset[f + 1] ? t + 1 : faces_.offset[f];
        const u32 h = corner_halfedge_[t], target = corner_vertex(u);
        out_.target[h] = target;
        out_.face[h] = f;
        set_next(dart_encoding::dart(h, false), dart_encoding::dart(corner_halfedge_[u], false));
        atomic_add<Tag>(corners_at_[target], 1);
        if constexpr (is_parallel_tag<Tag>)
          atomic_max<Tag>(last_corner_[target], t + 1);
        else
          out_.vertex_dart_bits[target] = dart_encoding::dart(h, false);
        if (partner_[t] == null)
          out_.target[dart_encoding::opposite_halfedge(h)] = corner_vertex(t);
        else if (t < partner_[t])
          out_.mobius[dart_encoding::edge_of_halfedge(h)] = corner_vertex(partner_[t]) == corner_vertex(t);
      }
    });
    if constexpr (is_parallel_tag<Tag>) {
      for_each_index<Tag>(nv, [&](u32 v) {
        out_.vertex_dart_bits[v] =
          last_corner_[v] == 0 ? null : dart_encoding::dart(corner_halfedge_[last_corner_[v] - 1], false);
      });
      Array().swap(last_corner_);
    }
  }

  // Dart navigation on the output arrays, as in Mobius_mesh.
  u32 next(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    return dart_encoding::is_flipped(d) ? dart_encoding::flip(out_.prev_bits[h]) : out_.next_bits[h];
  }
  u32 prev(u32 d) const
  {
    const u32 h = dart_encoding::halfedge_of_dart(d);
    return dart_encoding::is_flipped(d) ? dart_encoding::flip(out_.next_bits[h]) : out_.prev_bits[h];
  }
  u32 opposite(u32 d) const { return dart_encoding::opposite_dart(d, out_.mobius[dart_encoding::edge_of_dart(d)] != 0); }
  bool is_border(u32 d) const { return out_.face[dart_encoding::halfedge_of_dart(d)] == null; }
  u32 face(u32 d) const { return out_.face[dart_encoding::halfedge_of_dart(d)]; }
  void set_next(u32 a, u32 b)
  {
    using namespace dart_encoding;
    if (is_flipped(a))
      out_.prev_bits[halfedge_of_dart(a)] = flip(b);
    else
      out_.next_bits[halfedge_of_dart(a)] = b;
    if (is_flipped(b))
      out_.next_bits[halfedge_of_dart(b)] = flip(a);
    else
      out_.prev_bits[halfedge_of_dart(b)] = a;
  }

  // Walks the fan of incoming darts from `start` through its faces, stamping
  // them with `stamp` (unless null); on the border, links the fan's two border darts to
  // each other. Returns the fan's first dart (the border dart, if any) and
  // how many faces it has. `touched`, if given, receives both halfedges of
  // every edge of the fan at its vertex (each face's two edges there, of
  // its incoming dart and of the next one), so that every halfedge that
  // stores the vertex as its target is among them, whichever way the darts
  // run: at the border end of a walk whose last dart is flipped, the one
  // storing it is that face's halfedge on the border edge.
  std::pair<u32, u32> walk_fan(u32 start, u32 stamp, std::vector<u32>* touched)
  {
    u32 visited = 0;
    auto visit = [&](u32 d) {
      if (stamp != null)
        face_stamp_[face(d)] = stamp;
      ++visited;
      if (touched) {
        for (const u32 side : {d, next(d)}) {
          const u32 h = dart_encoding::halfedge_of_dart(side);
          touched->push_back(h);
          touched->push_back(dart_encoding::opposite_halfedge(h));
        }
      }
    };
    visit(start);
    u32 in = start;
    for (;;) {
      const u32 o = opposite(next(in));
      if (o == start)
        return {start, visited};
      in = o;
      if (is_border(in))
        break;
      visit(in);
    }
    u32 out = opposite(start);
    while (!is_border(out)) {
      const u32 d = prev(out);
      visit(d);
      out = opposite(d);
    }
    set_next(in, out);
    return {in, visited};
  }

  std::vector<Split_vertex> link_fans(bool split)
  {
    face_stamp_.assign(faces_.n_faces, null);
    std::vector<Split_vertex> copies;
    for (u32 v = 0; v < faces_.n_vertices; ++v) {
      if (corners_at_[v] == 0)
        continue; // isolated
      const auto [first, visited] = walk_fan(out_.vertex_dart_bits[v], v, nullptr);
      out_.vertex_dart_bits[v] = first;
      if (visited == corners_at_[v])
        continue;
      if (!split)
        throw_non_manifold_vertex(v);
      split_vertex(v, copies);
    }
    return copies;
  }

  // link_fans() by threads, a vertex each: a walk reads only face links and
  // writes only the links of its own border darts. Without stamps (faces
  // are shared between vertices), so a vertex with several fans is only
  // detected: false, and the serial pass then deals with it.
  template <class Tag>
  bool link_fans_in_parallel()
  {
    return count_if<Tag>(faces_.n_vertices, [&](u32 v) {
             if (corners_at_[v] == 0)
               return false;
             const auto [first, visited] = walk_fan(out_.vertex_dart_bits[v], null, nullptr);
             out_.vertex_dart_bits[v] = first;
             return visited != corners_at_[v];
           }) == 0;
  }

  // The corners whose side ends at each vertex, indexed only once a vertex
  // turns out to be non-manifold.
  void index_incoming_corners()
  {
    if (!incoming_start_.empty())
      return;
    incoming_start_.assign(std::size_t(faces_.n_vertices) + 1, 0);
    for (std::size_t t = 0; t < n_corners_; ++t)
      ++incoming_start_[corner_vertex(next_corner(t)) + 1];
    std::partial_sum(incoming_start_.begin(), incoming_start_.end(), incoming_start_.begin());
    incoming_corner_.resize(n_corners_);
    Array fill(incoming_start_.begin(), incoming_start_.end() - 1);
    for (std::size_t t = 0; t < n_corners_; ++t)
      incoming_corner_[fill[corner_vertex(next_corner(t))]++] = u32(t);
  }

  [[noreturn]] void throw_non_manifold_vertex(u32 v)
  {
    index_incoming_corners();
    std::vector<std::size_t> first_fan, others;
    for (u32 k = incoming_start_[v]; k < incoming_start_[v + 1]; ++k) {
      const u32 f = face_of_corner(incoming_corner_[k]);
      (face_stamp_[f] == v ? first_fan : others).push_back(f);
    }
    std::vector<std::size_t> all = first_fan;
    all.insert(all.end(), others.begin(), others.end());
    std::sort(all.begin(), all.end());
    throw Soup_error(Soup_error::Kind::non_manifold_vertex,
                     "vertex " + std::to_string(v) + " is non-manifold: its polygons form separate fans (" +
                       join_ids(first_fan) + " | " + join_ids(others) + ")",
                     all, {std::size_t(v)});
  }

  // Gives every fan of `v` but the first a vertex of its own.
  void split_vertex(u32 v, std::vector<Split_vertex>& copies)
  {
    index_incoming_corners();
    for (u32 k = incoming_start_[v]; k < incoming_start_[v + 1]; ++k) {
      const u32 t = incoming_corner_[k];
      if (face_stamp_[face_of_corner(t)] == v)
        continue;
      const u32 copy = faces_.n_vertices + u32(copies.size());
      std::vector<u32> touched;
      const u32 first = walk_fan(dart_encoding::dart(corner_halfedge_[t], false), v, &touched).first;
      for (u32 h : touched)
        if (out_.target[h] == v)
          out_.target[h] = copy;
      copies.push_back({v, first});
    }
  }

  Face_lists faces_;
  Connectivity_arrays out_{};
  std::size_t n_corners_ = 0;
  u32 n_edges_ = 0;
  Huge_page_vector<std::uint64_t> face_start_;
  [[maybe_unused]] bool parallel_ = false; // read only where TBB is linked
  bool split_edges_ = false;
  u32 n_non_manifold_edges_ = 0;
  std::vector<bool> lone_; // one bit per corner: its side stays a border
  Array partner_, corner_halfedge_, corners_at_, last_corner_, face_stamp_;
  Array incoming_start_, incoming_corner_;
};


/// Replaces the connectivity of `out` by that of the face lists, written
/// through the builder straight into the mesh's arrays (in parallel for
/// `CGAL::Parallel_tag`), its property maps reset; the points are left to
/// the caller. Returns the vertices split off (see `Connectivity_builder`).
/// On a `Soup_error` `out` is emptied: its arrays were half written.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P>
std::vector<Split_vertex> build_connectivity_from_faces(const Face_lists& faces, bool split_non_manifold_vertices,
                                                        Mobius_mesh<P>& out, bool split_non_manifold_edges = false)
{
  Connectivity_builder builder(faces, ConcurrencyTag(), split_non_manifold_edges);
  const Connectivity_arrays arrays = Connectivity_access::overwrite(
    out, builder.number_of_vertices(), builder.number_of_edges(), builder.number_of_faces());
  std::vector<Split_vertex> copies;
  try {
    copies = builder.build(arrays, split_non_manifold_vertices);
  } catch (...) {
    out = Mobius_mesh<P>();
    throw;
  }
  Connectivity_access::reset_property_maps(out);
  return copies;
}

/// Builds `out` (empty) from face lists: the connectivity through the
/// builder, written straight into the mesh's arrays, and the point of each
/// vertex from `point_of(v)` (a copy made by splitting a non-manifold vertex
/// takes its original's point). Returns the copies. With
/// `CGAL::Parallel_tag` the connectivity and the points are written in
/// parallel (`point_of` is then called from several threads), the same mesh.
template <class ConcurrencyTag = CGAL::Sequential_tag, class P, class PointOf>
std::vector<Split_vertex> build_mesh_from_faces(const Face_lists& faces, PointOf point_of,
                                                bool split_non_manifold_vertices, Mobius_mesh<P>& out,
                                                bool split_non_manifold_edges = false)
{
  const std::vector<Split_vertex> copies = build_connectivity_from_faces<ConcurrencyTag>(
    faces, split_non_manifold_vertices, out, split_non_manifold_edges);
  auto points = out.points();
  for_each_index<ConcurrencyTag>(faces.n_vertices, [&](std::uint32_t v) { points[Vertex_index(v)] = point_of(v); });
  for (const Split_vertex& copy : copies) {
    const Vertex_index v = out.add_vertex(points[Vertex_index(copy.original)]);
    out.set_halfedge(v, Dart::from_bits(copy.dart));
  }
  return copies;
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_CONNECTIVITY_BUILDER_H
