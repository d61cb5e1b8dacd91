// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of <CGAL_ext/subdivision.h>: the driver of the subdivision functions: parameters, carried maps, writing the result.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_SUBDIVISION_DRIVER_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_SUBDIVISION_DRIVER_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_array.h>
#include <CGAL_ext/Mobius_mesh/internal/Linear_values.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/Refiner.h>
#include <CGAL_ext/internal/Huge_page_allocator.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// Coordinates in a flat, fast form for floating-point kernels.
struct Vec3
{
  double x, y, z;
};
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator*(double w, const Vec3& a) { return {w * a.x, w * a.y, w * a.z}; }

// How points are interpolated: as Vec3 with double weights for
// floating-point kernels, as the kernel's vectors with its field type as
// weights otherwise (exact kernels stay exact).
template <class P, class K = typename CGAL::Kernel_traits<P>::Kernel,
          bool = std::is_floating_point_v<typename K::FT>>
struct Point_values
{
  using Value = Vec3;
  using Weight = double;
  static Value from(const P& p) { return {double(p.x()), double(p.y()), double(p.z())}; }
  static P to(const Value& v) { return P(v.x, v.y, v.z); }
  // Whether from(to(v)) is v, bit for bit (a point of doubles holds a Vec3
  // exactly), and a point is plain data (not the reference-counted points
  // of CGAL::Cartesian, which allocate even when default-constructed): then
  // the last level is interpolated straight into the result's points
  // (Refiner::refine_and_interpolate_points()).
  static constexpr bool round_trips = std::is_same_v<typename K::FT, double> && std::is_trivially_copyable_v<P>;
};
template <class P, class K>
struct Point_values<P, K, false>
{
  using Value = typename K::Vector_3;
  using Weight = typename K::FT;
  // Exact: values would be rebuilt from points wherever they were read back.
  static constexpr bool round_trips = false;
  static Value from(const P& p) { return p - CGAL::ORIGIN; }
  static P to(const Value& v) { return CGAL::ORIGIN + v; }
};

// ---- the property maps carried through subdivision

// How values are combined (Linear_values.h), named here as the refiner's own.
using CGAL_ext::internal::Linear_value;
using CGAL_ext::internal::for_each_interpolated_type;
using CGAL_ext::internal::for_each_interpolated_channel_type;

// The maps of `mesh` that a subdivision carries: vertex maps of the interpolated types
// (Linear_values.h), face maps of any type (but the points, the sharpness and the hole
// flags, which the subdivision writes itself), corner channels.
inline bool is_carried_vertex_map(const std::string& name)
{
  return name != "v:point" && name != vertex_sharpness_name;
}
template <class P>
bool has_carried_face_maps(const Mobius_mesh<P>& mesh)
{
  const auto names = mesh.template properties<Face_index>();
  return std::any_of(names.begin(), names.end(), [](const std::string& name) { return name != "f:hole"; });
}
template <class P>
bool has_carried_maps(const Mobius_mesh<P>& mesh)
{
  if (!mesh.corner_channels().empty() || has_carried_face_maps(mesh))
    return true;
  const auto names = mesh.template properties<Vertex_index>();
  // A map perhaps not of an interpolated type: then it is merely dropped.
  return std::any_of(names.begin(), names.end(), is_carried_vertex_map);
}

// Calls body(tag) for work on n elements of the maps: tag is `ConcurrencyTag`
// where a level of n vertices would be refined with threads
// (runs_in_parallel()), `CGAL::Sequential_tag` otherwise.
template <class ConcurrencyTag, class Body>
void with_concurrency_for(u32 n, const Refinement_options& options, const Body& body)
{
  with_concurrency<ConcurrencyTag>(runs_in_parallel(n, options.parallel_min_vertices), body);
}

// Calls body(v) for the vertices v in [0, n), with threads as
// with_concurrency_for() says.
template <class ConcurrencyTag, class Body>
void for_each_vertex(u32 n, const Refinement_options& options, const Body& body)
{
  with_concurrency_for<ConcurrencyTag>(n, options, [&](auto tag) { for_each_index<decltype(tag)>(n, body); });
}

// Calls body(name, map, tag) for each vertex map of `mesh` that a
// subdivision interpolates: `map` of type T, tag a `Type_tag<T>`, whose
// Linear_value<W, K, T> is defined.
template <class W, class P, class Body>
void for_each_carried_vertex_map(const Mobius_mesh<P>& mesh, const Body& body)
{
  using K = typename CGAL::Kernel_traits<P>::Kernel;
  for (const std::string& name : mesh.template properties<Vertex_index>()) {
    if (!is_carried_vertex_map(name))
      continue;
    for_each_interpolated_type<K>([&](auto tag) {
      using T = typename decltype(tag)::type;
      if constexpr (Linear_value<W, K, T>::defined)
        if (const auto from = mesh.template property_map<Vertex_index, T>(name))
          body(name, *from, tag);
    });
  }
}

// The values of vertex map `from` of `mesh` as interpolated values (`L`, a
// Linear_value), and back as a new map of `out`.
template <class ConcurrencyTag, class L, class P, class Map, class Values>
void read_vertex_map(const Mobius_mesh<P>& mesh, const Map& from, const Refinement_options& options, Values& values)
{
  const u32 n = u32(mesh.number_of_vertices());
  values.resize(n);
  for_each_vertex<ConcurrencyTag>(n, options, [&](u32 v) { values[v] = L::from(from[Vertex_index(v)]); });
}
template <class ConcurrencyTag, class L, class Values, class Map, class P>
void write_vertex_map(const Values& values, const std::string& name, const Map& from,
                      const Refinement_options& options, Mobius_mesh<P>& out)
{
  using T = typename Map::value_type;
  auto to = out.template add_property_map<Vertex_index, T>(name, from.array()->default_value()).first;
  const u32 m = u32(out.number_of_vertices());
  for_each_vertex<ConcurrencyTag>(m, options, [&](u32 v) { to[Vertex_index(v)] = L::to(values[v]); });
}

// Interpolates the vertex maps of `mesh` through the levels of `refiner`
// into new maps of `out` (the dual and sqrt(3) splits, whose faces lie
// across several parent faces: face maps are not carried).
template <class ConcurrencyTag, class W, class Mask, class P>
void carry_maps(const Refiner<Mask, W>& refiner, const Mobius_mesh<P>& mesh, Mobius_mesh<P>& out)
{
  using K = typename CGAL::Kernel_traits<P>::Kernel;
  for_each_carried_vertex_map<W>(mesh, [&](const std::string& name, const auto& from, auto tag) {
    using T = typename decltype(tag)::type;
    using L = Linear_value<W, K, T>;
    internal::Array<typename L::Value> base, result; // written in full: no zero-fill
    read_vertex_map<ConcurrencyTag, L>(mesh, from, refiner.options(), base);
    refiner.template interpolate<ConcurrencyTag>(base, result);
    write_vertex_map<ConcurrencyTag, L>(result, name, from, refiner.options(), out);
  });
}

// The value index of each halfedge's corner in `channel` (null on the
// border), as the refiner takes a channel. A face corner without a valid
// index is refused, in the words of `function`.
template <class P, class Channel>
std::vector<u32> base_corners(const char* function, const Mobius_mesh<P>& mesh, const Channel& channel)
{
  std::vector<u32> corners(mesh.number_of_halfedges(), null_u32);
  const std::size_t n = channel.number_of_values();
  for (Halfedge_index h : mesh.halfedges()) {
    if (mesh.is_border(h))
      continue;
    const u32 i = channel.index(h);
    if (i == Channel::no_value() || i >= n) {
      std::ostringstream what;
      what << function << ": corner channel \"" << channel.name() << "\": the corner of face " << mesh.face(h)
           << " at vertex " << mesh.target(h) << " (" << h << ") has "
           << (i == Channel::no_value() ? std::string("no value") : "value index " + std::to_string(i) + " of " + std::to_string(n));
      throw Parameter_error(what.str());
    }
    corners[h.idx()] = i;
  }
  return corners;
}

// A channel `name` of `out` (values of type T) made of the last level's
// `corners` (a value index per halfedge), taken as the channel's index array
// unfilled and uncopied, and `values` (interpolated, `L`).
template <class T, class L, class Values, class P>
void adopt_channel(const std::string& name, internal::Array<u32>& corners, const Values& values, Mobius_mesh<P>& out)
{
  auto channel = std::make_unique<CGAL_ext::internal::Corner_channel_array<T>>(name);
  const std::size_t slots = corners.size();
  channel->indices().swap(corners);
  std::vector<T>& to = channel->values();
  to.reserve(values.size());
  CGAL_ext::internal::advise_huge_pages(to.data(), values.size() * sizeof(T)); // before the first touch
  for (const auto& v : values)
    to.push_back(L::to(v));
  auto& halfedge_maps = CGAL_ext::internal::Connectivity_access::properties<Halfedge_index>(out);
  if (!halfedge_maps.adopt_array(std::move(channel), slots))
    throw Parameter_error("subdivision: internal error, the corner channel \"" + name +
                          "\" does not fit the result's halfedges");
}

// The maps of a mesh carried through a one-pass refinement by a quad or
// triangle split (Refiner::refine_and_interpolate_carrying()): each vertex
// map and each corner channel goes one level down in each step, and the
// face maps follow the base face of each face; finish() gives them to the
// result. Only two levels of each are alive at a time, and the last level
// of the mesh is split straight into the result.
template <class ConcurrencyTag, class Refiner, class P>
class Carried_maps
{
  using W = typename Refiner::Weight;
  using K = typename CGAL::Kernel_traits<P>::Kernel;
  using Mask = std::decay_t<decltype(std::declval<const Refiner&>().mask())>;

  struct Item
  {
    virtual ~Item() = default;
    virtual void step(const Refiner& r, const Child_level_view& child, bool parallel) = 0;
    virtual void finish(const Refiner& r, Mobius_mesh<P>& out) = 0;
  };

  template <class Map>
  struct Vertex_map : Item
  {
    using L = Linear_value<W, K, typename Map::value_type>;
    std::string name;
    Map from;
    internal::Array<typename L::Value> values; // written in full: no zero-fill

    Vertex_map(const Refiner& r, const Mobius_mesh<P>& mesh, const std::string& n, const Map& m) : name(n), from(m)
    {
      read_vertex_map<ConcurrencyTag, L>(mesh, from, r.options(), values);
    }
    void step(const Refiner& r, const Child_level_view& child, bool parallel) override
    {
      decltype(values) next(child.nv); // the parent's buffer, smaller, is not reused
      with_concurrency<ConcurrencyTag>(parallel, [&](auto tag) {
        r.template interpolate_level<decltype(tag)>(0, values.data(), next.data());
        normalize_values<decltype(tag)>(next.data(), child.nv);
      });
      values.swap(next);
    }
    void finish(const Refiner& r, Mobius_mesh<P>& out) override
    {
      write_vertex_map<ConcurrencyTag, L>(values, name, from, r.options(), out);
    }
  };

  template <class T>
  struct Channel : Item
  {
    using L = Linear_value<W, K, T>;
    using Values = internal::Array<typename L::Value>;
    std::string name;
    internal::Array<u32> corners; // of the base until the first step, then of the last level at finish()
    Fvar_pass<Refiner, Values> pass;
    bool started = false;

    template <class From>
    Channel(const Refiner& r, Face_varying_interpolation mode, const Mobius_mesh<P>& mesh, const std::string& n,
            const From& from)
      : name(n), pass(r, mode)
    {
      const std::vector<u32> base = base_corners("subdivision", mesh, from);
      corners.assign(base.begin(), base.end());
      pass.values().resize(from.number_of_values());
      for (std::size_t i = 0; i < pass.values().size(); ++i)
        pass.values()[i] = L::from(from.values()[i]);
    }
    void step(const Refiner& r, const Child_level_view& child, bool parallel) override
    {
      if (!started) { // the refiner's level 0 is the base now
        Values values;
        values.swap(pass.values());
        pass.start(r, corners, std::move(values));
        internal::Array<u32>().swap(corners);
        started = true;
      }
      with_concurrency<ConcurrencyTag>(parallel,
                                       [&](auto tag) { pass.template step<decltype(tag)>(r, 0, child); });
    }
    void finish(const Refiner&, Mobius_mesh<P>& out) override
    {
      if (started) // the last level's vertex values are its values
        corners.swap(pass.level().corner);
      adopt_channel<T, L>(name, corners, pass.values(), out);
    }
  };

  // The base face of each face of the current level, for the face maps.
  struct Face_maps : Item
  {
    const Mobius_mesh<P>& mesh;
    std::vector<u32> origin, scratch;

    explicit Face_maps(const Mobius_mesh<P>& m) : mesh(m), origin(m.number_of_faces())
    {
      for (u32 f = 0; f < u32(origin.size()); ++f)
        origin[f] = f;
    }
    void step(const Refiner& r, const Child_level_view&, bool parallel) override
    {
      with_concurrency<ConcurrencyTag>(parallel, [&](auto tag) {
        child_face_origins<decltype(tag), Mask::split>(level_of(r, 0), origin, scratch);
      });
    }
    void finish(const Refiner& r, Mobius_mesh<P>& out) override
    {
      auto parent_of = [&](Face_index f) { return Face_index(origin[f.idx()]); };
      with_concurrency_for<ConcurrencyTag>(u32(out.number_of_faces()), r.options(), [&](auto tag) {
        CGAL_ext::internal::transfer_properties<Face_index, decltype(tag)>(mesh, out, 0, out.number_of_faces(),
                                                                           parent_of, "f:hole");
      });
    }
  };

public:
  // Reads the maps of `mesh` (which must outlive this object: its face maps
  // are read by finish()).
  Carried_maps(const Refiner& r, Face_varying_interpolation mode, const Mobius_mesh<P>& mesh)
  {
    for_each_carried_vertex_map<W>(mesh, [&](const std::string& name, const auto& from, auto) {
      items_.push_back(std::make_unique<Vertex_map<std::decay_t<decltype(from)>>>(r, mesh, name, from));
    });
    if (has_carried_face_maps(mesh))
      items_.push_back(std::make_unique<Face_maps>(mesh));
    for (const std::string& name : mesh.corner_channels())
      for_each_interpolated_channel_type<K>([&](auto tag) {
        using T = typename decltype(tag)::type;
        if constexpr (Linear_value<W, K, T>::defined)
          if (const auto from = mesh.template corner_channel<T>(name))
            items_.push_back(std::make_unique<Channel<T>>(r, mode, mesh, name, *from));
      });
  }

  template <class Tag>
  void step(const Refiner& r, const Child_level_view& child)
  {
    for (auto& item : items_)
      item->step(r, child, is_parallel_tag<Tag>);
  }

  void finish(const Refiner& r, Mobius_mesh<P>& out)
  {
    for (auto& item : items_)
      item->finish(r, out);
  }

private:
  std::vector<std::unique_ptr<Item>> items_;
};

// Refuses, before anything is refined, a mesh with a corner channel that a
// subdivision by `Mask` cannot carry: any channel for the dual and √3 splits,
// whose new corners lie across several parent faces, or one whose values have
// no linear combination.
template <class W, class Mask, class P>
void check_channels(const Mobius_mesh<P>& mesh)
{
  if ((Mask::split == Split::dual || Mask::split == Split::sqrt3) && !mesh.corner_channels().empty())
    throw Parameter_error("subdivision: Doo-Sabin and sqrt(3) subdivision do not carry corner channels (\"" +
                          mesh.corner_channels().front() +
                          "\"); remove the channel or subdivide with Catmull-Clark, Loop, bilinear or linear");
  CGAL_ext::internal::require_interpolated_channels<W>(mesh, "subdivision");
}

template <class Key, class Sharpness>
std::vector<float> gather_sharpness(const Sharpness& sharpness, std::size_t n)
{
  std::vector<float> s(n);
  for (std::size_t i = 0; i < n; ++i)
    s[i] = sharpness(Key(typename Key::size_type(i)));
  return s;
}

// The sharpness of `mesh`: the maps given, else its "e:sharpness" /
// "v:sharpness". Returns whether there is any.
template <class P, class NamedParameters>
bool gather_sharpness(const Mobius_mesh<P>& mesh, const NamedParameters& np, std::vector<float>& es,
                      std::vector<float>& vs)
{
  const auto edge_sharpness = CGAL_ext::internal::edge_sharpness_of(mesh, np);
  const auto vertex_sharpness = CGAL_ext::internal::vertex_sharpness_of(mesh, np);
  if (edge_sharpness.has_map())
    es = gather_sharpness<Edge_index>(edge_sharpness, mesh.number_of_edges());
  if (vertex_sharpness.has_map())
    vs = gather_sharpness<Vertex_index>(vertex_sharpness, mesh.number_of_vertices());
  return edge_sharpness.has_map() || vertex_sharpness.has_map();
}

// Subdivision in double adds a ring's points up before it weights the sum:
// beyond +-1e300 the sum of a ring of a few hundred points overflows to
// infinity. Exact numbers do not overflow.
constexpr double max_abs_subdivided_coordinate = 1e300;

// Refuses a point in double beyond max_abs_subdivided_coordinate or not
// finite (a NaN spreads to every point it is a term of), naming the first
// such vertex.
template <class ConcurrencyTag, class Values>
void require_points_in_range(const Values& values)
{
  const u32 n = u32(values.size());
  const auto out_of_range = [&](u32 v) {
    const Vec3& p = values[v];
    const double b = max_abs_subdivided_coordinate;
    return !(std::abs(p.x) <= b && std::abs(p.y) <= b && std::abs(p.z) <= b); // true for NaN too
  };
  const u32 bad = reduce<ConcurrencyTag>(
    n, null_u32, [&](u32 v) { return out_of_range(v) ? v : null_u32; }, [](u32 a, u32 b) { return (std::min)(a, b); });
  if (bad == null_u32)
    return;
  std::ostringstream what;
  what << "subdivision: vertex v" << bad << " at (" << values[bad].x << ", " << values[bad].y << ", "
       << values[bad].z << ") has a coordinate that is not finite or beyond +-" << max_abs_subdivided_coordinate
       << ", where the sums of a ring's points in double overflow";
  throw Parameter_error(what.str());
}

// The points of `mesh` as interpolated values, in parallel if the mesh is
// large enough (`options`, as the refiner decides for a level); in double,
// refused where they would overflow.
template <class ConcurrencyTag, class P, class VertexPointMap, class Values>
void read_points(const Mobius_mesh<P>& mesh, const VertexPointMap& vpm, const Refinement_options& options,
                 Values& values)
{
  const u32 n = u32(mesh.number_of_vertices());
  values.resize(n);
  for_each_vertex<ConcurrencyTag>(n, options, [&](u32 v) { values[v] = Point_values<P>::from(get(vpm, Vertex_index(v))); });
  if constexpr (std::is_same_v<typename Values::value_type, Vec3>)
    require_points_in_range<ConcurrencyTag>(values);
}

// The interpolated `values` as the points of `out`.
template <class ConcurrencyTag, class Values, class P>
void write_points(const Values& values, const Refinement_options& options, Mobius_mesh<P>& out)
{
  const u32 n = u32(out.number_of_vertices());
  for_each_vertex<ConcurrencyTag>(n, options, [&](u32 v) { out.point(Vertex_index(v)) = Point_values<P>::to(values[v]); });
}

// Subdivides a 2-manifold (see Joined_subdivision.h for sheets of
// non-manifold input).
template <class ConcurrencyTag, class Mask, class P, class NamedParameters>
void subdivide_sheets(Mobius_mesh<P>& mesh, const Mask& mask, const NamedParameters& np)
{
  namespace pm = CGAL_ext::parameters;
  using Traits = Point_values<P>;
  using Value = typename Traits::Value;
  // Exact kernels stay serial: their lazy numbers share construction history
  // between threads.
  using Tag = std::conditional_t<std::is_same_v<Value, Vec3>, ConcurrencyTag, CGAL::Sequential_tag>;

  const unsigned levels =
    unsigned(pm::choose_parameter(pm::get_parameter(np, CGAL::internal_np::number_of_iterations), 1));
  auto vpm = pm::choose_parameter(pm::get_parameter(np, CGAL::internal_np::vertex_point), mesh.points());
  Refinement_options options;
  options.boundary_interpolation = CGAL_ext::internal::boundary_interpolation_of(np);
  options.crease_method = CGAL_ext::internal::crease_method_of(np);
  options.maximum_memory = pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::maximum_memory),
                                                options.maximum_memory);
  const Face_varying_interpolation fvar_mode =
    pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::face_varying_interpolation),
                         Face_varying_interpolation::corners_plus1);
  std::vector<float> es, vs;
  const bool write_sharpness = gather_sharpness(mesh, np, es, vs) && Mask::creases;
  check_channels<typename Traits::Weight, Mask>(mesh);

  // Build the result aside: on failure the caller's mesh stays as it was.
  Mobius_mesh<P> out;
  Refiner<Mask, typename Traits::Weight> refiner(mask, options);
  if (!has_carried_maps(mesh)) {
    // Points only: one pass, two levels alive at a time.
    internal::Array<Value> values; // each level's points are written in full: no zero-fill
    read_points<Tag>(mesh, vpm, options, values);
    if constexpr (Traits::round_trips) {
      refiner.template refine_and_interpolate_points<Traits, Tag>(mesh, levels, values, out, es, vs, write_sharpness);
    } else {
      refiner.template refine_and_interpolate<Tag>(mesh, levels, values, out, es, vs, write_sharpness);
      write_points<Tag>(values, options, out);
    }
  } else if constexpr (Mask::split == Split::quad || Mask::split == Split::triangle) {
    // Other maps too: one pass, each map carried a level at a time.
    Carried_maps<Tag, decltype(refiner), P> carried(refiner, fvar_mode, mesh);
    internal::Array<Value> values;
    read_points<Tag>(mesh, vpm, options, values);
    if constexpr (Traits::round_trips) {
      refiner.template refine_and_interpolate_carrying<Traits, Tag>(mesh, levels, values, out, carried, es, vs,
                                                                    write_sharpness);
    } else {
      refiner.template refine_and_interpolate_carrying<void, Tag>(mesh, levels, values, out, carried, es, vs,
                                                                  write_sharpness);
      write_points<Tag>(values, options, out);
    }
    carried.finish(refiner, out);
  } else {
    // Doo-Sabin and sqrt(3): every level is kept, and each map interpolated through them.
    internal::Array<Value> values, result; // written in full: no zero-fill
    read_points<Tag>(mesh, vpm, options, values);
    refiner.template refine<Tag>(mesh, levels, es, vs);
    refiner.template interpolate<Tag>(values, result);
    refiner.template build_mesh<Tag>(out, write_sharpness);
    write_points<Tag>(result, options, out);
    carry_maps<Tag>(refiner, mesh, out);
  }
  mesh = std::move(out);
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_SUBDIVISION_DRIVER_H
