// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The subdivision engine: refines the topology of a Mobius_mesh level by
// level, keeps each level's weights, and interpolates any vertex data
// through the levels without refining again.

#ifndef CGAL_EXT_SUBDIVISION_REFINER_H
#define CGAL_EXT_SUBDIVISION_REFINER_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Size_limits.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/internal/Face_varying.h>
#include <CGAL_ext/Subdivision/internal/Interpolation.h>
#include <CGAL_ext/Subdivision/internal/Level.h>
#include <CGAL_ext/Subdivision/internal/Parallel_step_tuner.h>
#include <CGAL_ext/Subdivision/internal/Stencil_splits.h>
#include <CGAL_ext/Subdivision/internal/Weights.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Huge_page_allocator.h>

#include <CGAL/tags.h>
#include <CGAL/use.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {

/// The rules of a refinement that do not depend on the scheme.
struct Refinement_options
{
  /// Which border edges and vertices are sharp (named parameter `boundary_interpolation`).
  Boundary_interpolation boundary_interpolation = Boundary_interpolation::edge_only;
  /// How semi-sharp creases decay from level to level (named parameter `crease_method`).
  Crease_method crease_method = Crease_method::uniform;
  /// The value of `parallel_min_vertices` that leaves the choice to
  /// `runs_in_parallel()`, from the level's size and the number of threads.
  static constexpr std::uint32_t automatic = 0xFFFFFFFFu;
  /// With `CGAL::Parallel_tag`, which levels are refined and interpolated
  /// with threads: `automatic` (the default), those that give every thread
  /// of the task arena enough work (see `runs_in_parallel()`) unless this
  /// process has found, from its timings, that threads lose at their size
  /// (see `Refiner`); any other value, those of at least that
  /// many vertices (0: every level, however small), with no timing. The other
  /// levels are done serially, with the same result: on small levels the
  /// threads and the tables of the parallel passes cost more than they save.
  /// `CGAL::Sequential_tag` never uses threads.
  std::uint32_t parallel_min_vertices = automatic;
  /// The most bytes a refinement may take (named parameter `maximum_memory`
  /// of the subdivision functions); by default the memory available when the
  /// options are made (Linux's `MemAvailable`, else the physical memory).
  /// A refinement whose estimated peak is larger is refused before anything
  /// is allocated.
  double maximum_memory = CGAL_ext::internal::available_memory();
};

/// With `Refinement_options::automatic`, the fewest vertices per thread of a
/// level (the parent of a step) for the step to run in parallel.
///
/// A level is split among T threads when each gets at least this many of
/// its vertices: the per-thread work must outweigh waking and joining the
/// threads, whose cost grows with T. The rows `parallel_threshold` of
/// bench_subdivision time one Catmull–Clark step of tori of 2^10 to 2^18
/// vertices, serially against T threads (doc/benchmarks/subdivision_parallel.md,
/// "Parallel threshold"). On 2 idle cores, in three runs, two threads lose below
/// 8 192 vertices (0.54–0.69× the serial speed), are as often slower as
/// faster at 8 281 (0.55–1.11×) and win from 16 384 on in every run
/// (1.12–1.55×): a level needs 16 384 vertices on two threads. On another
/// 2-core VM, whose cores read each other's writes 2–2.5 times slower than
/// their own, two threads lost up to 131 072 vertices: 8 192 per thread
/// stays the floor, and with `automatic` a refinement raises it from its
/// process's timings (see `Refiner`). Keeping the work per thread fixed is
/// the conservative floor, since the threads' start-up grows with T while
/// the serial time does not.
constexpr std::uint32_t parallel_vertices_per_thread = 8192;

namespace internal {

// The threads a parallel step may use: the current task arena's slots,
// within the cap of any tbb::global_control alive (1 without TBB).
inline unsigned available_threads()
{
#ifdef CGAL_LINKED_WITH_TBB
  return unsigned((std::min)(std::size_t(tbb::this_task_arena::max_concurrency()),
                             tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
#else
  return 1;
#endif
}

} // namespace internal

/// \ingroup PkgSubdivision
///
/// Whether a step from a level of `level_vertices` vertices may run in
/// parallel under `CGAL::Parallel_tag`, given the option
/// `Refinement_options::parallel_min_vertices`: with `automatic`, if the
/// current task arena has more than one thread
/// (`tbb::this_task_arena::max_concurrency()`, and at most the
/// `max_allowed_parallelism` of a `tbb::global_control`) and each gets at least
/// `parallel_vertices_per_thread` vertices (a refinement then also asks what
/// its process measured: see `Refiner`); otherwise if `level_vertices`
/// is at least the option. Always false without TBB.
inline bool runs_in_parallel(std::uint32_t level_vertices, std::uint32_t parallel_min_vertices)
{
#ifdef CGAL_LINKED_WITH_TBB
  if (parallel_min_vertices != Refinement_options::automatic)
    return level_vertices >= parallel_min_vertices;
  const unsigned threads = internal::available_threads();
  return threads > 1 && level_vertices / threads >= parallel_vertices_per_thread;
#else
  CGAL_USE(level_vertices);
  CGAL_USE(parallel_min_vertices);
  return false;
#endif
}

/// \ingroup PkgSubdivision
///
/// The element counts after `levels` steps of a split of kind `split` from a
/// mesh of counts `base`, computed in 64 bits without refining anything:
/// exact for the quad and triangle splits, upper bounds for the dual and √3
/// splits (whose growth depends on the border). Stops at the first level
/// whose counts pass what a `Mobius_mesh` indexes and returns those, so
/// that nothing wraps however many levels are asked for.
inline Mesh_size refined_size(Split split, const Mesh_size& base, unsigned levels)
{
  auto indexable = [](const Mesh_size& s) {
    return s.edges <= CGAL_ext::internal::max_edges && s.vertices <= CGAL_ext::internal::max_vertices &&
           s.faces <= CGAL_ext::internal::max_faces;
  };
  Mesh_size s = base;
  for (unsigned k = 0; k < levels && indexable(s); ++k) {
    const unsigned long long V = s.vertices, E = s.edges, F = s.faces, B = s.border_edges;
    const unsigned long long C = 2 * E - B; // corners: one per halfedge with a face
    switch (split) {
    case Split::quad: // a vertex per vertex, edge and face; an n-gon into n quads
      s = Mesh_size{V + E + F, 2 * E + C, C, 2 * B};
      break;
    case Split::triangle: // a vertex per vertex and edge; a triangle into four
      s = Mesh_size{V + E, 2 * E + C, F + C, 2 * B};
      break;
    case Split::dual: // a vertex per corner, of at most four edges; a face per face, edge and vertex
      s = Mesh_size{C, 2 * C, F + E + V, 0};
      break;
    case Split::sqrt3: { // a vertex per face, two per border edge; each triangle into three
      const unsigned long long faces = 3 * F + 2 * B, border = 3 * B;
      s = Mesh_size{V + F + 2 * B, (3 * faces + border) / 2, faces, border};
      break;
    }
    }
  }
  return s;
}

namespace internal {

// The counts of `mesh` that refined_size() starts from.
template <class P>
Mesh_size size_of(const Mobius_mesh<P>& mesh)
{
  Mesh_size s{mesh.number_of_vertices(), mesh.number_of_edges(), mesh.number_of_faces(), 0};
  for (Edge_index e : mesh.edges())
    s.border_edges += mesh.is_border(e) ? 1 : 0;
  return s;
}

template <class V>
auto normalize_value(V& v, int) -> decltype(v.exact(), void())
{
  v.exact(); // evaluates a lazy exact value and drops its construction history
}
template <class V>
void normalize_value(V&, long)
{}

// Whether normalize_value() does something for V (lazy exact numbers): the
// loops that call it are skipped otherwise.
template <class V, class = void>
struct Normalizes : std::false_type
{};
template <class V>
struct Normalizes<V, std::void_t<decltype(std::declval<V&>().exact())>> : std::true_type
{};

// normalize_value() on the n values at `values`.
template <class ConcurrencyTag, class V>
void normalize_values(V* values, u32 n)
{
  if constexpr (Normalizes<V>::value)
    for_each_index<ConcurrencyTag>(n, [&](u32 v) { normalize_value(values[v], 0); });
  else
    CGAL_USE(values), CGAL_USE(n);
}

} // namespace internal

/// \ingroup PkgSubdivision
///
/// Refines a `Mobius_mesh` with a subdivision mask and keeps what it needs to
/// interpolate vertex data through the levels: each level's topology
/// (`internal::Level`) and each level's edge and vertex weights. Refining is
/// done once; `interpolate()` then maps any vertex data (points in any kernel,
/// normals, colours) from the base mesh to the last level, as often as needed.
/// Buffers are kept and reused when the same refiner refines again.
///
/// Under `CGAL::Parallel_tag` with `Refinement_options::automatic`, which
/// steps of a quad or triangle split (Catmull–Clark, Loop, bilinear) use
/// threads is learnt per process, per refiner type and per number of threads,
/// by size class (a power of two of the parent's vertices), among those that
/// `runs_in_parallel()` allows. In `refine_and_interpolate()` and
/// `refine_and_interpolate_points()` (which the subdivision functions call
/// when the mesh carries no other property maps), the smallest class without
/// a verdict runs with threads in the next three refinements that reach it,
/// then without in the next three, each timed from the start of the
/// refinement (a step with threads makes the serial steps before it build
/// its incidence tables); the faster way, best of three, becomes its
/// verdict. The gain from threads growing with size, a class also follows a
/// win of the threads in a smaller class or a loss in a larger one; a class
/// with no verdict uses threads. `refine()` follows the verdicts and tries
/// nothing. Doo–Sabin and √3 keep `runs_in_parallel()`. Only the time
/// changes: both ways give the same bits.
///
/// \tparam Mask a model of `SubdivisionMask`
/// \tparam W the weight type: `double`, or the field type of an exact kernel
template <class Mask, class W = double>
class Refiner
{
public:
  /// The weight type.
  using Weight = W;
  /// The type of the element indices of a level (32 bits, as in `Mobius_mesh`).
  using u32 = internal::u32;

  /// A refiner that applies `mask` with `options`; it refines nothing yet.
  explicit Refiner(const Mask& mask = Mask(), const Refinement_options& options = Refinement_options())
    : mask_(mask), options_(options)
  {}

  /// The mask.
  const Mask& mask() const { return mask_; }
  /// The options.
  const Refinement_options& options() const { return options_; }

  /// What this process has timed and concluded of the steps of refiners of
  /// this type, shared by all of them (see the class description).
  static internal::Parallel_step_tuner& tuner()
  {
    static internal::Parallel_step_tuner shared;
    return shared;
  }

  /// Refines `mesh` `levels` times. `edge_sharpness` and `vertex_sharpness`
  /// hold one value per edge / vertex (an empty vector means all 0).
  ///
  /// With `ConcurrencyTag` = `CGAL::Parallel_tag` (TBB needed), every step
  /// from a level that `runs_in_parallel()` allows and, with the automatic
  /// choice, that the timings of this process favour (see the class
  /// description and `Refinement_options::parallel_min_vertices`) runs all its stages in
  /// parallel (the splits, the weights, the incidence tables), with the
  /// serial numbering and bits, and gets the incidence tables of the
  /// parallel interpolation: only then does
  /// `interpolate<CGAL::Parallel_tag>()` run that level in parallel (without
  /// them it is serial, with the same result). The mask's functions are then
  /// called from several threads.
  /// \throws Parameter_error if a sharpness is NaN or negative, or if the mask splits
  /// triangles and `mesh` has a face that is not a triangle.
  /// \throws Size_error, before anything is allocated, if the last level
  /// would have more elements than a `Mobius_mesh` indexes (see `refined_size()`),
  /// or if the refinement's estimated peak of memory (all its levels) is more
  /// than `Refinement_options::maximum_memory` (element `"bytes"`).
  template <class ConcurrencyTag = CGAL::Sequential_tag, class P>
  void refine(const Mobius_mesh<P>& mesh, unsigned levels, const std::vector<float>& edge_sharpness = {},
              const std::vector<float>& vertex_sharpness = {})
  {
    const Mesh_size base = check_size(mesh, levels, 2.5, 0);
    levels_.resize(levels + 1);
    weights_.resize(uses_stencils ? 0 : levels);
    stencils_.resize(uses_stencils ? levels : 0);
    incidence_.assign(uses_stencils ? 0 : levels, internal::Incidence());
    make_plan<ConcurrencyTag>(base, levels, false);
    serial_tables_ = later_step_in_parallel<ConcurrencyTag>(base, levels);
    build_base<ConcurrencyTag>(mesh, edge_sharpness, vertex_sharpness);
    for (unsigned k = 0; k < levels; ++k)
      internal::with_concurrency<ConcurrencyTag>(parallel_level(levels_[k].nv),
                                                 [&](auto tag) { step<decltype(tag)>(k, k); });
  }

  /// Refines `mesh` `levels` times into `out`, interpolating `values` (one
  /// per vertex of `mesh`, replaced by one per vertex of `out`) on the way.
  /// Only two levels are alive at a time, and the last one is written
  /// straight into `out`'s arrays: less memory and faster than `refine()`,
  /// `interpolate()` and `build_mesh()`, for when nothing else is to be
  /// interpolated. `out` gets the sharpness maps and the holes as with
  /// `build_mesh()`. The refiner keeps no level afterwards
  /// (`number_of_levels()` is 0).
  /// `Values` is a `std::vector` of any value type and allocator.
  /// \throws Parameter_error or Size_error as `refine()`, before `out` is touched.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class P, class Values, class Q>
  void refine_and_interpolate(const Mobius_mesh<P>& mesh, unsigned levels, Values& values, Mobius_mesh<Q>& out,
                              const std::vector<float>& edge_sharpness = {},
                              const std::vector<float>& vertex_sharpness = {}, bool write_sharpness = false)
  {
    one_pass<ConcurrencyTag, void>(mesh, levels, values, out, edge_sharpness, vertex_sharpness, write_sharpness);
  }

  /// As `refine_and_interpolate()`, with `values` the points of `mesh` as
  /// `Convert::Value`s: the last level's values are written straight into
  /// the points of `out`, each converted by `Convert::to()`, with no array
  /// of values of their own and no copy; `values` is left empty. Where the
  /// last pass reads back a value it has written (a face or edge point), it
  /// converts the point back with `Convert::from()`, which must give the
  /// value back bit for bit (true of points of doubles); then `out`'s points
  /// are `refine_and_interpolate()`'s values, converted. `Convert` has a type
  /// `Value` (that of `values`, not one that is normalized, as exact numbers
  /// are) and static functions `to()` and `from()`, called from several
  /// threads at once under `CGAL::Parallel_tag`. The point array is
  /// allocated, and advised onto huge pages, before the last pass writes it;
  /// where `Q`'s default constructor writes nothing (CGAL's points of
  /// doubles) that pass is the array's first touch.
  template <class Convert, class ConcurrencyTag = CGAL::Sequential_tag, class P, class Values, class Q>
  void refine_and_interpolate_points(const Mobius_mesh<P>& mesh, unsigned levels, Values& values,
                                     Mobius_mesh<Q>& out, const std::vector<float>& edge_sharpness = {},
                                     const std::vector<float>& vertex_sharpness = {}, bool write_sharpness = false)
  {
    static_assert(std::is_same_v<typename Values::value_type, typename Convert::Value> &&
                    !internal::Normalizes<typename Convert::Value>::value,
                  "the values are the points as Convert::Value, which are not normalized");
    one_pass<ConcurrencyTag, Convert>(mesh, levels, values, out, edge_sharpness, vertex_sharpness, write_sharpness);
  }

  /// As `refine_and_interpolate_points()` (with `Convert`) or
  /// `refine_and_interpolate()` (`Convert` void), with more data carried
  /// along, one level at a time: in each step, once the weights of its parent
  /// level are made and before the parent is split, `carried` is called as
  /// `carried.template step<Tag>(refiner, child)`, where `Tag` is the step's
  /// concurrency, the parent is level 0 of `refiner` (`edge_weights(0, e)`,
  /// `interpolate_level<Tag>(0, src, dst)`), and `child`
  /// (`internal::Child_level_view`) gives the child's vertex and edge counts
  /// and its sharpness. Quad and triangle splits. The estimated peak of
  /// memory checked is 2.5 times the result, as `refine()`'s (the carried
  /// data's own levels are not counted: an estimate).
  template <class Convert, class ConcurrencyTag = CGAL::Sequential_tag, class P, class Values, class Q, class Carried>
  void refine_and_interpolate_carrying(const Mobius_mesh<P>& mesh, unsigned levels, Values& values,
                                       Mobius_mesh<Q>& out, Carried& carried,
                                       const std::vector<float>& edge_sharpness = {},
                                       const std::vector<float>& vertex_sharpness = {}, bool write_sharpness = false)
  {
    static_assert(!uses_stencils, "the dual and sqrt(3) splits carry data through refine() and interpolate()");
    if constexpr (!std::is_void_v<Convert>)
      static_assert(std::is_same_v<typename Values::value_type, typename Convert::Value> &&
                      !internal::Normalizes<typename Convert::Value>::value,
                    "the values are the points as Convert::Value, which are not normalized");
    one_pass<ConcurrencyTag, Convert>(mesh, levels, values, out, edge_sharpness, vertex_sharpness, write_sharpness,
                                      carried);
  }

  /// The number of refinement steps done by the last `refine()`.
  unsigned number_of_levels() const { return levels_.empty() ? 0u : unsigned(levels_.size() - 1); }
  /// The counts of level `k` (0 is the base mesh): its vertices, edges,
  /// faces and border edges.
  Mesh_size level_size(unsigned k) const
  {
    const Level& L = levels_[k];
    Mesh_size s{L.nv, L.ne, L.nf, 0};
    for (u32 h = 0; h < 2 * L.ne; h += 2)
      s.border_edges += L.is_border_dart(internal::face_dart(h)) || L.is_border_dart(internal::face_dart(h + 1));
    return s;
  }
  /// The weights of edge `e` of level `k` in step `k` (primal schemes: quad
  /// and triangle splits).
  const Edge_weights<W>& edge_weights(unsigned k, u32 e) const { return weights_[k].edge(e); }
  /// The weights of vertex `v` of level `k` in step `k` (primal schemes).
  const Vertex_weights<W>& vertex_weights(unsigned k, u32 v) const { return weights_[k].vertex(v); }
  /// Interpolates one level: `src` holds a value per vertex of level `k`,
  /// `dst` receives one per vertex of level `k+1`. `Value` needs `Value + Value`
  /// and `W * Value`.
  template <class Value>
  void interpolate_level(unsigned k, const Value* src, Value* dst) const;

  /// As `interpolate_level()`, in parallel with TBB for `CGAL::Parallel_tag`;
  /// the result is bit for bit the serial one (each value is summed in the
  /// same order). A level of a quad or triangle split is interpolated in
  /// parallel only if `refine<CGAL::Parallel_tag>()` made its incidence
  /// tables, serially otherwise. Nothing is written into the refiner, so
  /// several threads may interpolate with one refiner at once.
  template <class ConcurrencyTag, class Value>
  void interpolate_level(unsigned k, const Value* src, Value* dst) const;

  /// Interpolates `base` (one value per vertex of the base mesh) through all
  /// levels into `result` (resized to the vertices of the last level).
  /// `scratch` holds intermediate levels; pass the same vectors again to
  /// avoid allocating.
  ///
  /// With `ConcurrencyTag` = `CGAL::Parallel_tag` (TBB needed), each level
  /// that `refine<CGAL::Parallel_tag>()` prepared is interpolated in
  /// parallel, bit for bit as the serial result. `interpolate()` is const and
  /// writes only into its arguments: threads may share one refiner.
  /// `Values` is `std::vector<Value>` or another vector of `Value`s (the
  /// library passes arrays that spare large levels their zero-fill).
  template <class ConcurrencyTag = CGAL::Sequential_tag, class Values>
  void interpolate(const Values& base, Values& result, Values& scratch) const
  {
    using Value = typename Values::value_type;
    const unsigned n = number_of_levels();
    if (n == 0) {
      result = base;
      return;
    }
    result.resize(levels_[n].nv);
    if (n > 1)
      scratch.resize(levels_[n - 1].nv);
    const Value* src = base.data();
    for (unsigned k = 0; k < n; ++k) {
      Value* dst = ((n - 1 - k) % 2 == 0) ? result.data() : scratch.data();
      interpolate_level<ConcurrencyTag>(k, src, dst);
      internal::with_concurrency<ConcurrencyTag>(parallel_level(levels_[k].nv), [&](auto tag) {
        internal::normalize_values<decltype(tag)>(dst, levels_[k + 1].nv);
      });
      src = dst;
    }
  }
  /// As the three-argument `interpolate()`, with a scratch buffer of its own.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class Values>
  void interpolate(const Values& base, Values& result) const
  {
    Values scratch;
    interpolate<ConcurrencyTag>(base, result, scratch);
  }

  /// Interpolates a corner channel (face-varying data) through all levels,
  /// with OpenSubdiv's face-varying rules: away from seams the channel
  /// follows the vertex rules (creases and borders included), along seams and
  /// at the channel's own corners `mode` decides what stays linear
  /// (`Face_varying_interpolation`). `corners` holds, per halfedge of the base
  /// mesh, the index in `values` of the value of its corner (the corner of
  /// its face at its target; `internal::null_u32` on border halfedges), and
  /// is replaced by the same per halfedge of the last level, `values` by that
  /// level's values. `Value` needs `Value + Value` and `W * Value`. Quad and
  /// triangle splits only; every face corner must have an index.
  /// With `CGAL::Parallel_tag` (TBB needed) the levels that
  /// `refine<CGAL::Parallel_tag>()` ran with threads run with threads,
  /// bit for bit as the serial result.
  /// `Corners` is `std::vector<std::uint32_t>` and `Values` `std::vector<Value>`,
  /// or other vectors of those elements (the library passes arrays that
  /// spare large levels their zero-fill).
  template <class ConcurrencyTag = CGAL::Sequential_tag, class Corners, class Values>
  void interpolate_face_varying(Face_varying_interpolation mode, Corners& corners, Values& values) const
  {
    static_assert(!uses_stencils, "the dual and sqrt(3) splits have no face-varying rules");
    internal::interpolate_face_varying<ConcurrencyTag>(*this, mode, corners, values,
                                                       [this](u32 nv) { return parallel_level(nv); });
  }

  /// For each face of the last level, the face of the base mesh it lies in
  /// (quad and triangle splits, whose child faces each lie in one parent
  /// face; the dual and √3 splits make faces across several). Each level's
  /// faces are numbered in parallel under `CGAL::Parallel_tag` where its
  /// refinement step used threads.
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  std::vector<u32> base_faces() const
  {
    static_assert(!uses_stencils, "the faces of the dual and sqrt(3) splits have no single parent face");
    if (levels_.empty())
      return {};
    std::vector<u32> origin(levels_[0].nf), next;
    internal::with_concurrency<ConcurrencyTag>(parallel_level(levels_[0].nv), [&](auto tag) {
      internal::for_each_index<decltype(tag)>(levels_[0].nf, [&](u32 f) { origin[f] = f; });
    });
    for (unsigned k = 0; k + 1 < levels_.size(); ++k)
      internal::with_concurrency<ConcurrencyTag>(parallel_level(levels_[k].nv), [&](auto tag) {
        internal::child_face_origins<decltype(tag), Mask::split>(levels_[k], origin, next);
      });
    return origin;
  }

  /// Replaces the connectivity of `out` with that of the last level. If
  /// `write_sharpness`, the property maps "e:sharpness" and "v:sharpness" get
  /// the sharpness of the last level (border edges: 0, as they are sharp by
  /// rule). If the base had holes (boundary interpolation `none`), the face
  /// property "f:hole" marks the faces that descend from them.
  /// With `ConcurrencyTag` = `CGAL::Parallel_tag`, the arrays and maps are
  /// written in parallel if the step into the level ran in parallel, or
  /// would have (`runs_in_parallel()`, and the last refinement's plan).
  template <class ConcurrencyTag = CGAL::Sequential_tag, class P>
  void build_mesh(Mobius_mesh<P>& out, bool write_sharpness) const;

private:
  // The engine's arrays of a level, for the engine (internal::level_of()) and
  // its white-box tests: not part of the interface.
  using Level = internal::Level;
  friend struct internal::Refiner_access;
  const Level& level(unsigned k) const { return levels_[k]; }
  const internal::Incidence* incidence_tables(unsigned k) const
  {
    return k < incidence_.size() && !incidence_[k].empty() ? &incidence_[k] : nullptr;
  }

  // interpolate_level() into `dst`: values, or a mesh's points (internal::Point_output).
  template <class ConcurrencyTag, class Value, class Out>
  void interpolate_level_into(unsigned k, const Value* src, const Out& dst) const;

  // Refuses, before anything is allocated, a refinement of `mesh` whose
  // last level a Mobius_mesh cannot index, or whose estimated peak of memory
  // passes `options().maximum_memory`: `kept` times the bytes of the result
  // mesh's arrays, plus `value_bytes` per result vertex. The factors are
  // measured peaks: a one-pass refinement holds its last two levels, a
  // quarter more than the result (123 bytes per quad of double points
  // against the result's 98); by Doo–Sabin or √3, whose last step also holds
  // the child's face list and the builder's tables, twice (212 and 136
  // bytes per face against 98 and 68); one that keeps every level, two and
  // a half. Returns the counts of `mesh` that refined_size() starts from.
  template <class P>
  Mesh_size check_size(const Mobius_mesh<P>& mesh, unsigned levels, double kept, double value_bytes) const
  {
    CGAL_ext::internal::require_no_garbage(mesh, "subdivision");
    if (!(options_.maximum_memory > 0))
      throw Parameter_error("subdivision: maximum_memory " + std::to_string(options_.maximum_memory) +
                            " is not a positive number");
    const std::string what = "subdividing " + std::to_string(levels) + " levels";
    const Mesh_size base = internal::size_of(mesh);
    const Mesh_size result = refined_size(Mask::split, base, levels);
    CGAL_ext::internal::check_mesh_size(what, result);
    CGAL_ext::internal::check_memory(what,
                                     CGAL_ext::internal::mesh_bytes<P>(result) * kept +
                                       double(result.vertices) * value_bytes,
                                     options_.maximum_memory);
    return base;
  }

  // Whether the step from a level of `nv` vertices runs in parallel (if
  // the tag asks for it): as the plan of the refinement says, within what
  // runs_in_parallel() allows.
  bool parallel_level(u32 nv) const
  {
    if (!runs_in_parallel(nv, options_.parallel_min_vertices))
      return false;
    return options_.parallel_min_vertices != Refinement_options::automatic ||
           plan_.parallel_class(internal::size_class(nv));
  }

  // The plan of a refinement by `levels` steps of a mesh of counts `base`: which size
  // classes use threads (a refinement under CGAL::Parallel_tag with the
  // automatic choice, on more than one thread, by a quad or triangle split,
  // whose level sizes refined_size() gives exactly), and, if it may try one
  // (`try_class`: a refinement that times its steps), which class it times
  // for the tuner.
  template <class ConcurrencyTag>
  void make_plan(const Mesh_size& base, unsigned levels, bool try_class)
  {
    plan_ = internal::Parallel_plan();
    if constexpr (internal::is_parallel_tag<ConcurrencyTag> && !uses_stencils) {
      plan_threads_ = internal::available_threads();
      if (options_.parallel_min_vertices != Refinement_options::automatic || plan_threads_ < 2)
        return;
      std::vector<u32> parents;
      for (unsigned k = 0; k < levels; ++k)
        parents.push_back(u32(refined_size(Mask::split, base, k).vertices)); // check_size() bounded them
      plan_ = tuner().plan(
        plan_threads_, parents, [](u32 n) { return runs_in_parallel(n, Refinement_options::automatic); }, try_class);
    } else {
      CGAL_USE(base);
      CGAL_USE(levels);
      CGAL_USE(try_class);
    }
  }

  // Whether a refinement by `levels` steps of a mesh of counts `base` under
  // `ConcurrencyTag` has a step that runs in parallel after the first, which
  // does not (the plan, not only the levels' growth, decides which do). Then
  // the serial steps make incidence tables too (the base's by a walk around
  // its vertices, each child's derived by the split), so that the first
  // level with threads gets its tables from its parent's split instead of
  // walking around every one of its vertices; the walk cost more than the
  // threads saved where only the last step runs in parallel
  // (doc/benchmarks/subdivision_parallel.md).
  template <class ConcurrencyTag>
  bool later_step_in_parallel(const Mesh_size& base, unsigned levels) const
  {
    if constexpr (!internal::is_parallel_tag<ConcurrencyTag> || uses_stencils) {
      CGAL_USE(base);
      CGAL_USE(levels);
      return false;
    } else {
      if (levels < 2 || parallel_level(u32(base.vertices)))
        return false;
      for (unsigned k = 1; k < levels; ++k)
        if (parallel_level(u32(refined_size(Mask::split, base, k).vertices)))
          return true;
      return false;
    }
  }

  // No data carried besides the values.
  struct Nothing_carried
  {
    template <class Tag>
    void step(const Refiner&, const internal::Child_level_view&)
    {}
  };

  // The child of slot `slot` as a channel's step sees it, after
  // compute_weights(slot), before the split (primal schemes).
  internal::Child_level_view child_view(unsigned slot) const
  {
    const Level& p = levels_[slot];
    internal::Child_level_view c;
    c.nv = child_vertex_count(slot);
    c.ne = 2 * p.ne + p.nc; // two halves per edge, and one inner edge per corner
    if (child_sharpness_.any) {
      c.e_sharp = child_sharpness_.edges.data();
      c.v_sharp = child_sharpness_.vertices.data();
    }
    return c;
  }

  // refine_and_interpolate(), or with `Convert` (not void)
  // refine_and_interpolate_points(); with `carried`,
  // refine_and_interpolate_carrying().
  template <class ConcurrencyTag, class Convert, class P, class Values, class Q, class Carried = Nothing_carried>
  void one_pass(const Mobius_mesh<P>& mesh, unsigned levels, Values& values, Mobius_mesh<Q>& out,
                const std::vector<float>& edge_sharpness, const std::vector<float>& vertex_sharpness,
                bool write_sharpness, Carried&& carried = Carried())
  {
    constexpr bool carries = !std::is_same_v<std::decay_t<Carried>, Nothing_carried>;
    const Mesh_size base = check_size(mesh, levels, carries ? 2.5 : uses_stencils ? 2.0 : 1.25,
                                      carries ? 0.0 : double(sizeof(typename Values::value_type)));
    levels_.resize(levels == 0 ? 1 : 2);
    incidence_.clear();
    make_plan<ConcurrencyTag>(base, levels, true);
    // A step is timed from the start: a later step with threads makes the
    // serial steps before it build its incidence tables, which it costs.
    const auto start = std::chrono::steady_clock::now();
    serial_tables_ = later_step_in_parallel<ConcurrencyTag>(base, levels);
    build_base<ConcurrencyTag>(mesh, edge_sharpness, vertex_sharpness);
    for (unsigned k = 0; k < levels; ++k) {
      bool done = false;
      const u32 parent = levels_[0].nv;
      const bool parallel = parallel_level(parent);
      internal::with_concurrency<ConcurrencyTag>(parallel, [&](auto tag) {
        done = one_pass_step<decltype(tag), Convert>(k, k + 1 == levels, values, out, write_sharpness, carried);
      });
      if (int(internal::size_class(parent)) == plan_.tried)
        tuner().record(plan_threads_, parent, parallel,
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (done)
        return;
    }
    levels_.resize(1);
    build_mesh<ConcurrencyTag>(out, write_sharpness);
    levels_.clear();
    clear_scratch();
    if constexpr (!std::is_void_v<Convert>) { // no level: the points are the values
      internal::with_concurrency<ConcurrencyTag>(parallel_level(u32(values.size())), [&](auto tag) {
        internal::for_each_index<decltype(tag)>(u32(values.size()),
                                                [&](u32 v) { out.point(Vertex_index(v)) = Convert::to(values[v]); });
      });
      Values().swap(values);
    }
  }

  // One step of one_pass(): levels_[0] into levels_[1], or into `out` if
  // `last` (then returns true, the refiner emptied), and `values`
  // interpolated on the way (the last time into `out`'s points, if
  // `Convert` is not void).
  template <class ConcurrencyTag, class Convert, class Values, class Q, class Carried>
  bool one_pass_step(unsigned k, bool last, Values& values, Mobius_mesh<Q>& out, bool write_sharpness,
                     Carried& carried)
  {
    constexpr bool into_points = !std::is_void_v<Convert>;
    if constexpr (uses_stencils) {
      if (last) {
        stencil_split_into_mesh<ConcurrencyTag>(k, out, write_sharpness);
        if constexpr (into_points)
          values_into_points<ConcurrencyTag, Convert>(values, out.points().data());
        else
          advance_values<ConcurrencyTag>(values);
        levels_.clear();
        clear_scratch();
        return true;
      }
      step<ConcurrencyTag>(0, k);
      advance_values<ConcurrencyTag>(values);
    } else {
      if (weights_.empty())
        weights_.resize(1);
      prepare_interpolation<ConcurrencyTag>(0);
      compute_weights<ConcurrencyTag>(0);
      Point_vector<Q> points;
      if constexpr (into_points) {
        if (last) {
          // Written in full below; here allocated and advised onto huge
          // pages before anything touches them, as the mesh's own arrays
          // (resize() writes nothing where the default constructor writes
          // nothing, as that of CGAL's points of doubles).
          points.reserve(child_vertex_count(0));
          CGAL_ext::internal::advise_huge_pages(points.data(), points.capacity() * sizeof(points[0]));
          points.resize(child_vertex_count(0));
          values_into_points<ConcurrencyTag, Convert>(values, points);
        } else {
          advance_values<ConcurrencyTag>(values);
        }
      } else {
        advance_values<ConcurrencyTag>(values);
      }
      carried.template step<ConcurrencyTag>(*this, child_view(0));
      weights_[0] = internal::Step_weights<W>(); // the split does not need them
      if (last) {
        incidence_.clear();
        split_into_mesh<ConcurrencyTag>(out, write_sharpness, into_points ? &points : nullptr);
        levels_.clear();
        clear_scratch();
        return true;
      }
      incidence_.resize(2); // a slot for the child's tables, which the split derives
      split<ConcurrencyTag>(0, true);
      incidence_[0] = std::move(incidence_[1]);
      incidence_.resize(1);
    }
    std::swap(levels_[0], levels_[1]);
    levels_[1] = Level(); // the parent: too small to hold the next level
    return false;
  }

  // Interpolates `values` (of level 0) into level 1 and keeps only the new
  // values: what a step needs of its parent level is its topology and its weights.
  template <class ConcurrencyTag, class Values>
  void advance_values(Values& values) const
  {
    Values next;
    next.resize(child_vertex_count(0));
    interpolate_level_into<ConcurrencyTag>(0, values.data(), next.data());
    internal::normalize_values<ConcurrencyTag>(next.data(), u32(next.size()));
    values.swap(next);
  }

  // The point array of a mesh of points `Q`.
  template <class Q>
  using Point_vector = std::vector<CGAL_ext::internal::Stored_value<Q>>;

  // Interpolates `values` (of level 0) into `points`, one per vertex of
  // level 1, and frees them.
  template <class ConcurrencyTag, class Convert, class Values, class Q>
  void values_into_points(Values& values, std::vector<Q>& points) const
  {
    CGAL_precondition(points.size() == child_vertex_count(0));
    interpolate_level_into<ConcurrencyTag>(0, values.data(), internal::Point_output<Convert, Q>{points.data()});
    Values().swap(values);
  }

  // Refines levels_[slot] into levels_[slot + 1] with the weights or
  // stencils of slot `slot`; `k` is the step's number (√3 alternates).
  // Every stage runs as `ConcurrencyTag` says: the caller has chosen.
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  void step(unsigned slot, unsigned k)
  {
    if (levels_.size() < slot + 2)
      levels_.resize(slot + 2);
    if constexpr (uses_stencils) {
      internal::Face_list faces;
      stencil_split<ConcurrencyTag>(slot, k, faces);
      internal::level_from_faces<ConcurrencyTag>(stencils_[slot].size(), faces, levels_[slot + 1]);
    } else {
      CGAL_USE(k);
      if (weights_.size() < slot + 1)
        weights_.resize(slot + 1);
      prepare_interpolation<ConcurrencyTag>(slot);
      compute_weights<ConcurrencyTag>(slot);
      split<ConcurrencyTag>(slot, true);
    }
  }

  // The stencils of slot `slot` and the child faces (Doo–Sabin and √3);
  // `k` is the step's number (√3 alternates).
  template <class ConcurrencyTag>
  void stencil_split(unsigned slot, unsigned k, internal::Face_list& faces)
  {
    if (stencils_.size() < slot + 1)
      stencils_.resize(slot + 1);
    using Tag = Weight_tag<ConcurrencyTag>;
    if constexpr (Mask::split == Split::dual)
      internal::dual_split<Tag>(levels_[slot], mask_, faces, stencils_[slot]);
    else
      internal::sqrt3_split<Tag>(levels_[slot], mask_, k % 2 == 1, faces, stencils_[slot]);
  }

  // The last step of a one-pass refinement by Doo–Sabin or √3: the child
  // built from its faces straight into the arrays of `out`, with no level
  // of its own (no corner table, no copy), the parent freed first. Its
  // sharpness, if asked for, is 0 (these schemes have no creases), and it
  // has no holes, as build_mesh() would give it.
  template <class ConcurrencyTag, class Q>
  void stencil_split_into_mesh(unsigned k, Mobius_mesh<Q>& out, bool write_sharpness)
  {
    internal::Face_list faces;
    stencil_split<ConcurrencyTag>(0, k, faces);
    levels_.clear();
    out.clear();
    CGAL_ext::internal::build_connectivity_from_faces<ConcurrencyTag>(faces.view(stencils_[0].size()), false, out);
    if (write_sharpness)
      add_sharpness_maps<ConcurrencyTag>(out, nullptr, nullptr);
  }

  // How weights and stencils are made: serially for exact weights, whose
  // numbers may share representations between threads.
  template <class ConcurrencyTag>
  using Weight_tag = std::conditional_t<std::is_floating_point_v<W>, ConcurrencyTag, CGAL::Sequential_tag>;

  // The weights of levels_[slot] into weights_[slot], and the sharpness of
  // its child into child_sharpness_; after prepare_interpolation(slot), whose
  // tables, if any, give the edges at each vertex.
  template <class ConcurrencyTag>
  void compute_weights(unsigned slot)
  {
    using Tag = Weight_tag<ConcurrencyTag>;
    weight_builder_.template build<Tag>(mask_, options_.crease_method, levels_[slot], child_vertex_count(slot),
                                        weights_[slot], child_sharpness_, incidence_tables(slot));
  }

  // The incidence tables of levels_[slot] if it is to be interpolated in
  // parallel, unless the split that made it derived them (refine() and
  // refine_and_interpolate() start without tables).
  template <class ConcurrencyTag>
  void prepare_interpolation(unsigned slot)
  {
    if (incidence_.size() < slot + 1)
      incidence_.resize(slot + 1);
    if (internal::is_parallel_tag<ConcurrencyTag> || serial_tables_) {
      if (incidence_[slot].empty())
        internal::build_incidence<ConcurrencyTag>(levels_[slot], Mask::split == Split::quad, incidence_[slot]);
    } else {
      incidence_[slot].clear();
    }
  }

  // The topological split of levels_[slot] into levels_[slot + 1] (primal
  // schemes), after compute_weights(slot), whose child sharpness it takes.
  // A level interpolated in parallel passes its incidence tables on to its
  // child if the child has a slot for them (it is interpolated in turn, and
  // in parallel too, being larger).
  template <class ConcurrencyTag>
  void split(unsigned slot, bool corner_table)
  {
    Level& c = levels_[slot + 1];
    split_level<ConcurrencyTag>(levels_[slot], c, corner_table);
    if (slot + 1 < incidence_.size() && !incidence_[slot].empty())
      internal::derive_incidence<ConcurrencyTag, Mask::split>(levels_[slot], incidence_[slot], incidence_[slot + 1]);
    if (child_sharpness_.any) {
      c.sharp = true;
      c.e_sharp.swap(child_sharpness_.edges);
      c.v_sharp.swap(child_sharpness_.vertices);
    }
  }

  // The mask's split of `p` into `c`, a Level or a Mesh_writer.
  template <class ConcurrencyTag, class Child>
  static void split_level(const Level& p, Child& c, bool corner_table)
  {
    if constexpr (Mask::split == Split::quad)
      internal::quad_split<ConcurrencyTag>(p, c, corner_table);
    else
      internal::triangle_split<ConcurrencyTag>(p, c, corner_table);
  }

  // The last split of a one-pass refinement: levels_[0] into `out`, with
  // `points` (if not null, one per vertex) as its points.
  template <class ConcurrencyTag, class Q>
  void split_into_mesh(Mobius_mesh<Q>& out, bool write_sharpness, Point_vector<Q>* points)
  {
    out.clear();
    internal::Mesh_writer<Mobius_mesh<Q>> c(out);
    split_level<ConcurrencyTag>(levels_[0], c, false);
    levels_[0] = Level(); // freed before the maps are made
    if (points)
      CGAL_ext::internal::Connectivity_access::reset_property_maps(out, *points);
    else
      CGAL_ext::internal::Connectivity_access::reset_property_maps(out);
    if (write_sharpness)
      add_sharpness_maps<ConcurrencyTag>(out, child_sharpness_.any ? child_sharpness_.edges.data() : nullptr,
                                         child_sharpness_.any ? child_sharpness_.vertices.data() : nullptr);
    add_hole_map<ConcurrencyTag>(out, c.f_hole);
  }

  // The number of vertices of the child of level `k` (primal schemes).
  u32 child_vertex_count(unsigned k) const
  {
    if constexpr (uses_stencils) {
      return stencils_[k].size();
    } else {
      const Level& p = levels_[k];
      return p.nv + p.ne + (Mask::split == Split::quad ? p.nf : 0u);
    }
  }

  void clear_scratch()
  {
    weights_.clear();
    stencils_.clear();
    incidence_.clear();
    child_sharpness_.release();
    weight_builder_.clear();
  }

  // The maps build_mesh() documents; null sharpness means all 0.
  template <class ConcurrencyTag, class Q>
  static void add_sharpness_maps(Mobius_mesh<Q>& out, const float* edge_sharpness, const float* vertex_sharpness)
  {
    auto es = out.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first;
    auto vs = out.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first;
    if (edge_sharpness)
      internal::for_each_index<ConcurrencyTag>(u32(out.number_of_edges()), [&](u32 e) {
        if (!out.is_border(Edge_index(e)))
          es[Edge_index(e)] = edge_sharpness[e]; // border edges are sharp by rule
      });
    if (vertex_sharpness)
      internal::for_each_index<ConcurrencyTag>(u32(out.number_of_vertices()),
                                               [&](u32 v) { vs[Vertex_index(v)] = vertex_sharpness[v]; });
  }
  template <class ConcurrencyTag, class Q, class Holes>
  static void add_hole_map(Mobius_mesh<Q>& out, const Holes& holes)
  {
    if (holes.empty())
      return;
    auto map = out.template add_property_map<Face_index, std::uint8_t>("f:hole", 0).first;
    internal::for_each_index<ConcurrencyTag>(u32(out.number_of_faces()),
                                             [&](u32 f) { map[Face_index(f)] = holes[f]; });
  }

  template <class ConcurrencyTag, class P>
  void build_base(const Mobius_mesh<P>& mesh, const std::vector<float>& es, const std::vector<float>& vs);
  template <class ConcurrencyTag>
  static void check_sharpness(Level& L, const std::vector<float>& es, const std::vector<float>& vs);
  template <class ConcurrencyTag>
  void mark_border(Level& L) const;

  static constexpr bool uses_stencils = Mask::split == Split::dual || Mask::split == Split::sqrt3;

  Mask mask_;
  Refinement_options options_;
  std::vector<Level> levels_;
  std::vector<internal::Stencils<W>> stencils_;
  // The vertex-to-edge and vertex-to-corner tables of each level that is to
  // be interpolated in parallel, and, if serial_tables_, of the serial levels
  // before the first such one (empty for the others): derived by the split
  // that made the level, or made before its weights (prepare_interpolation()).
  std::vector<internal::Incidence> incidence_;
  // Whether the serial steps of this refinement make incidence tables for a
  // later step that runs in parallel (see later_step_in_parallel()).
  bool serial_tables_ = false;
  // Which size classes the current refinement runs with threads, on how
  // many, and which it times (make_plan()).
  internal::Parallel_plan plan_;
  unsigned plan_threads_ = 1;
  std::vector<internal::Step_weights<W>> weights_;
  internal::Weight_builder<Mask, W> weight_builder_;
  // The sharpness of the next level, made by compute_weights() before the split.
  internal::Child_sharpness child_sharpness_;
};

// ---------------------------------------------------------------------------

template <class Mask, class W>
template <class ConcurrencyTag, class P>
void Refiner<Mask, W>::build_base(const Mobius_mesh<P>& m, const std::vector<float>& es,
                                  const std::vector<float>& vs)
{
  internal::with_concurrency<ConcurrencyTag>(parallel_level(u32(m.number_of_vertices())), [&](auto tag) {
    using Tag = decltype(tag);
    Level& L = levels_[0];
    internal::fill_level<Tag>(m, L);
    check_sharpness<Tag>(L, es, vs);
    if constexpr (uses_stencils)
      return; // Doo–Sabin and √3 have border rules of their own
    mark_border<Tag>(L);
    // A level without sharpness skips its bookkeeping, and so do its children.
    auto positive = [](float s) { return s > 0.0f; };
    if (internal::count_if<Tag>(L.ne, [&](u32 e) { return positive(L.e_sharp[e]); }) == 0 &&
        internal::count_if<Tag>(L.nv, [&](u32 v) { return positive(L.v_sharp[v]); }) == 0)
      L.drop_sharpness();
  });
}

// The sharpness of the base level, border edges infinitely sharp; refuses
// the first NaN or negative value (the first by index, as a serial pass
// finds it), and a face that is not a triangle where the scheme needs them.
template <class Mask, class W>
template <class ConcurrencyTag>
void Refiner<Mask, W>::check_sharpness(Level& L, const std::vector<float>& es, const std::vector<float>& vs)
{
  using internal::null_u32;
  const u32 nv = L.nv, ne = L.ne, nf = L.nf;
  auto first = [](u32 n, const auto& bad) {
    return internal::reduce<ConcurrencyTag>(
      n, null_u32, [&](u32 i) { return bad(i) ? i : null_u32; }, [](u32 a, u32 b) { return (std::min)(a, b); });
  };
  auto value = [](const std::vector<float>& s, u32 i) { return s.empty() ? 0.0f : s[i]; };
  const u32 bad_edge = first(ne, [&](u32 e) { return !CGAL_ext::internal::is_valid_sharpness(value(es, e)); });
  if (bad_edge != null_u32)
    throw CGAL_ext::internal::invalid_sharpness("subdivision", "edge e", bad_edge, es[bad_edge]);
  const u32 bad_vertex = first(nv, [&](u32 v) { return !CGAL_ext::internal::is_valid_sharpness(value(vs, v)); });
  if (bad_vertex != null_u32)
    throw CGAL_ext::internal::invalid_sharpness("subdivision", "vertex v", bad_vertex, vs[bad_vertex]);
  internal::for_each_index<ConcurrencyTag>(ne, [&](u32 e) {
    const bool border = L.h_face[CGAL_ext::internal::dart_encoding::halfedge_of_edge(e, 0)] == null_u32 ||
                          L.h_face[CGAL_ext::internal::dart_encoding::halfedge_of_edge(e, 1)] == null_u32;
    L.e_sharp[e] = border ? infinitely_sharp : value(es, e); // border edges are infinitely sharp, as in OpenSubdiv
  });
  internal::for_each_index<ConcurrencyTag>(nv, [&](u32 v) { L.v_sharp[v] = value(vs, v); });
  if constexpr (Mask::split == Split::triangle || Mask::split == Split::sqrt3) {
    const u32 f = first(nf, [&](u32 g) { return L.degree(g) != 3; });
    if (f != null_u32)
      throw Parameter_error("subdivision: the scheme needs a triangle mesh, but face f" + std::to_string(f) +
                            " has " + std::to_string(L.degree(f)) + " sides");
  }
}

// Border vertices: corners (edge and corner), or their faces become holes (none).
template <class Mask, class W>
template <class ConcurrencyTag>
void Refiner<Mask, W>::mark_border(Level& L) const
{
  using internal::null_u32;
  L.f_hole.clear();
  if (options_.boundary_interpolation == Boundary_interpolation::none) {
    L.f_hole.resize(L.nf);
    internal::for_each_index<ConcurrencyTag>(L.nf, [&](u32 f) { L.f_hole[f] = 0; });
  }
  internal::for_each_index<ConcurrencyTag>(L.nv, [&](u32 v) {
    const u32 d0 = L.v_dart[v];
    if (d0 == null_u32 || !L.is_border_dart(d0))
      return;
    u32 edges = 0, d = d0;
    do {
      ++edges;
      const u32 f = L.h_face[internal::dart_encoding::halfedge_of_dart(d)];
      if (f != null_u32 && !L.f_hole.empty())
        internal::mark<ConcurrencyTag>(L.f_hole[f]); // a face may be marked from several vertices
      d = L.opposite(L.next(d));
    } while (d != d0);
    if (options_.boundary_interpolation == Boundary_interpolation::edge_and_corner && edges == 2)
      L.v_sharp[v] = infinitely_sharp;
  });
}

template <class Mask, class W>
template <class Value>
void Refiner<Mask, W>::interpolate_level(unsigned k, const Value* src, Value* dst) const
{
  interpolate_level_into<CGAL::Sequential_tag>(k, src, dst);
}

template <class Mask, class W>
template <class ConcurrencyTag, class Value>
void Refiner<Mask, W>::interpolate_level(unsigned k, const Value* src, Value* dst) const
{
  interpolate_level_into<ConcurrencyTag>(k, src, dst);
}

template <class Mask, class W>
template <class ConcurrencyTag, class Value, class Out>
void Refiner<Mask, W>::interpolate_level_into(unsigned k, const Value* src, const Out& dst) const
{
  if constexpr (!std::is_convertible_v<ConcurrencyTag, CGAL::Parallel_tag>) {
    if constexpr (uses_stencils)
      internal::interpolate_stencils<CGAL::Sequential_tag>(stencils_[k], src, dst);
    else
      internal::interpolate_primal<Mask::split>(levels_[k], weights_[k], src, dst);
  } else if constexpr (uses_stencils) {
    // The last step of a one-pass refinement has freed its parent level:
    // its caller chose the tag from that level already.
    const bool parallel = k >= levels_.size() || parallel_level(levels_[k].nv);
    internal::with_concurrency<ConcurrencyTag>(parallel, [&](auto tag) {
      internal::interpolate_stencils<decltype(tag)>(stencils_[k], src, dst);
    });
  } else if (k >= incidence_.size() || incidence_[k].empty() || !parallel_level(levels_[k].nv)) {
    // Serial levels may have tables too, made for a later level's sake.
    interpolate_level_into<CGAL::Sequential_tag>(k, src, dst);
  } else {
    internal::interpolate_primal<ConcurrencyTag, Mask::split>(levels_[k], weights_[k], incidence_[k], src, dst);
  }
}

template <class Mask, class W>
template <class ConcurrencyTag, class P>
void Refiner<Mask, W>::build_mesh(Mobius_mesh<P>& out, bool write_sharpness) const
{
  const Level& L = levels_.back();
  // The level already holds the mesh's arrays, index for index: copied in
  // blocks, by several threads if the level is large enough.
  out.clear();
  const auto a = CGAL_ext::internal::Connectivity_access::overwrite(out, L.nv, L.ne, L.nf);
  internal::with_concurrency<ConcurrencyTag>(parallel_level(L.nv), [&](auto tag) {
    using Tag = decltype(tag);
    auto copy = [](const auto& from, auto* to, u32 n) {
      internal::for_each_block<Tag>(n, [&](u32 begin, u32 end) {
        std::copy(from.begin() + begin, from.begin() + end, to + begin);
      });
    };
    copy(L.h_target, a.target, 2 * L.ne);
    copy(L.h_next, a.next_bits, 2 * L.ne);
    copy(L.h_prev, a.prev_bits, 2 * L.ne);
    copy(L.h_face, a.face, 2 * L.ne);
    copy(L.e_mobius, a.mobius, L.ne);
    copy(L.v_dart, a.vertex_dart_bits, L.nv);
    copy(L.f_first, a.face_halfedge, L.nf);
    CGAL_ext::internal::Connectivity_access::reset_property_maps(out);
    if (write_sharpness)
      add_sharpness_maps<Tag>(out, L.sharp ? L.e_sharp.data() : nullptr, L.sharp ? L.v_sharp.data() : nullptr);
    add_hole_map<Tag>(out, L.f_hole);
  });
}

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_REFINER_H
