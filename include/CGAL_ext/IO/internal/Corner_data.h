// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Texture coordinates and normals between files and corner channels: what a
// reader found (values, and the value of each corner of the soup), put on the
// mesh the soup becomes; and the channels as the writers take them (values
// as doubles, per face corner), with the checks that nothing is dropped.

#ifndef CGAL_EXT_IO_INTERNAL_CORNER_DATA_H
#define CGAL_EXT_IO_INTERNAL_CORNER_DATA_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/internal/Property_container.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace IO {
namespace internal {

constexpr std::uint32_t no_corner_value = CGAL_ext::internal::Base_corner_channel::no_value;

// One channel as a file gives it: its values, and either the value index of
// each corner of the soup, polygon after polygon (OBJ's `f v/vt/vn`), or one
// value per point (PLY and OFF: a corner takes its point's value).
template <std::size_t N>
struct Read_channel
{
  std::vector<std::array<double, N>> values;
  std::vector<std::uint32_t> corner_index; // empty if per_vertex, or if no corner has a value
  bool per_vertex = false;

  bool is_used() const { return per_vertex ? !values.empty() : !corner_index.empty(); }
};

struct Read_corner_data
{
  Read_channel<2> uv;
  Read_channel<3> normal;
};

// Puts one channel on `mesh`, built from `polygons` by
// `polygon_soup_to_mobius_mesh()` and not yet oriented: face p is polygon p,
// its halfedge ending at the polygon's corner 1.
template <class T, std::size_t N, class Polygons, class P, class Make>
void add_read_channel(const Read_channel<N>& in, const char* name, const Polygons& polygons, Mobius_mesh<P>& mesh,
                      Make make)
{
  if (!in.is_used())
    return;
  auto channel = mesh.template add_corner_channel<T>(name).first;
  channel.values().reserve(in.values.size());
  for (const std::array<double, N>& v : in.values)
    channel.values().push_back(make(v));
  std::size_t first = 0; // the polygon's first corner in corner_index
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const auto& polygon = polygons[p];
    const std::size_t n = polygon.size();
    std::size_t k = 1;
    for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(Face_index(p)), mesh)) {
      const std::size_t c = k++ % n;
      channel.set_index(mesh.corner(d), in.per_vertex ? std::uint32_t(polygon[c]) : in.corner_index[first + c]);
    }
    first += n;
  }
}

template <class Polygons, class P>
void add_read_channels(const Read_corner_data& data, const Polygons& polygons, Mobius_mesh<P>& mesh)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  add_read_channel<Corner_uv<P>>(data.uv, corner_uv_name, polygons, mesh,
                                 [](const std::array<double, 2>& a) { return Corner_uv<P>(FT(a[0]), FT(a[1])); });
  add_read_channel<Corner_normal<P>>(data.normal, corner_normal_name, polygons, mesh, [](const std::array<double, 3>& a) {
    return Corner_normal<P>(FT(a[0]), FT(a[1]), FT(a[2]));
  });
}

// ---- writing

// A channel as the writers take it: its values in double, and the index of
// each face corner's value (faces in order, each walked from its halfedge,
// as the writers list the faces' vertices), `no_corner_value` where none.
template <std::size_t N>
struct Written_channel
{
  std::string name;
  std::vector<std::array<double, N>> values;
  std::vector<std::uint32_t> corner;

  bool is_present() const { return !name.empty(); }
  bool has_value(std::size_t c) const { return corner[c] != no_corner_value; }
};

// Calls f(tag) for the value types that a channel of N components may have
// for the writers: what the readers make, and what users build by hand.
template <std::size_t N, class K, class F>
void for_each_written_type(F&& f)
{
  using CGAL_ext::internal::Type_tag;
  f(Type_tag<std::array<double, N>>());
  f(Type_tag<std::array<float, N>>());
  if constexpr (N == 2) {
    f(Type_tag<typename K::Point_2>());
    f(Type_tag<typename K::Vector_2>());
  } else {
    f(Type_tag<typename K::Vector_3>());
    f(Type_tag<typename K::Point_3>());
  }
}

template <class T>
double component(const T& t, std::size_t i)
{
  return CGAL::to_double(t[int(i)]);
}
template <class E, std::size_t N>
double component(const std::array<E, N>& t, std::size_t i)
{
  return double(t[i]);
}

// The channel `name` of `mesh` for a writer, or an absent one; a channel of
// a value type the writers do not know, or with a value that is not a finite
// double, is refused (`IO_error` naming `filename`).
template <std::size_t N, class P>
Written_channel<N> written_channel(const Mobius_mesh<P>& mesh, const std::string& name, const std::string& filename)
{
  using K = typename CGAL::Kernel_traits<P>::Kernel;
  Written_channel<N> out;
  bool found = false;
  for_each_written_type<N, K>([&](auto tag) {
    using T = typename decltype(tag)::type;
    const auto channel = mesh.template corner_channel<T>(name);
    if (found || !channel)
      return;
    found = true;
    out.name = name;
    std::vector<std::uint32_t> renumber(channel->number_of_values(), no_corner_value);
    for (Face_index f : mesh.faces())
      for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
        const std::uint32_t i = channel->index(mesh.corner(d));
        if (i == no_corner_value || i >= renumber.size()) {
          out.corner.push_back(no_corner_value);
          continue;
        }
        // Each value that a corner uses, once, in order of first use; two
        // indices stay two even if their values agree (they make a seam).
        if (renumber[i] == no_corner_value) {
          renumber[i] = std::uint32_t(out.values.size());
          std::array<double, N> v;
          for (std::size_t k = 0; k < N; ++k) {
            v[k] = component(channel->values()[i], k);
            if (!std::isfinite(v[k]))
              throw IO_error(filename, 0,
                             "corner channel \"" + name + "\": value " + std::to_string(i) +
                               " is not a finite double; nothing was written");
          }
          out.values.push_back(v);
        }
        out.corner.push_back(renumber[i]);
      }
  });
  if (!found && !mesh.corner_channels().empty())
    for (const std::string& n : mesh.corner_channels())
      if (n == name)
        throw IO_error(filename, 0,
                       "corner channel \"" + name + "\" has values of a type the writers do not know (" +
                         std::to_string(N) + " floats or doubles in an std::array, or the kernel's " +
                         (N == 2 ? "Point_2 or Vector_2" : "Vector_3 or Point_3") + "); nothing was written");
  return out;
}

// Refuses a channel that the file cannot hold at all: any but "c:uv" and
// "c:normal" (`format` names the file's kind).
template <class P>
void refuse_unwritten_channels(const Mobius_mesh<P>& mesh, const std::string& filename, const char* format)
{
  for (const std::string& name : mesh.corner_channels())
    if (name != corner_uv_name && name != corner_normal_name)
      throw IO_error(filename, 0,
                     "the mesh has the corner channel \"" + name + "\", which " + format +
                       " files cannot hold (they hold \"" + corner_uv_name + "\" and \"" + corner_normal_name +
                       "\" only); remove it (Mobius_mesh::remove_corner_channel()) to write the mesh without "
                       "it; nothing was written");
}

template <std::size_t N>
std::string value_text(const std::array<double, N>& v)
{
  std::ostringstream s;
  s.precision(17);
  s << '(';
  for (std::size_t k = 0; k < N; ++k)
    s << (k ? ", " : "") << v[k];
  s << ')';
  return s.str();
}

// The value of each vertex, for the formats that hold one per vertex (PLY,
// OFF): every corner at a vertex must hold the same value (a seam, or a
// corner without a value beside one with a value, is refused, naming the
// vertex). A vertex without corners gets 0.
template <std::size_t N, class P>
std::vector<std::array<double, N>> per_vertex_values(const Written_channel<N>& channel, const Mobius_mesh<P>& mesh,
                                                     const std::string& filename, const char* format)
{
  std::vector<std::array<double, N>> value(mesh.number_of_vertices(), std::array<double, N>{});
  std::vector<std::uint32_t> first(mesh.number_of_vertices(), no_corner_value); // corner number, or none yet
  std::size_t c = 0;
  auto refuse = [&](Vertex_index v, const std::string& what, const std::string& detail) {
    throw IO_error(filename, 0,
                   "corner channel \"" + channel.name + "\" " + what + " at vertex " + std::to_string(v.idx()) +
                     detail + "; " + format +
                     " files hold one value per vertex: write OBJ, which holds a value per face corner (vt, vn); "
                     "nothing was written");
  };
  for (Face_index f : mesh.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const Vertex_index v = mesh.target(d);
      const std::uint32_t seen = first[v.idx()];
      if (seen == no_corner_value) {
        first[v.idx()] = std::uint32_t(c);
        if (channel.has_value(c))
          value[v.idx()] = channel.values[channel.corner[c]];
      } else if (channel.has_value(seen) != channel.has_value(c)) {
        refuse(v, "has corners with a value and corners without one", "");
      } else if (channel.has_value(c) && channel.values[channel.corner[c]] != value[v.idx()]) {
        refuse(v, "has a seam", " (its corners hold " + value_text(value[v.idx()]) + " and " +
                                  value_text(channel.values[channel.corner[c]]) + ")");
      }
      ++c;
    }
  for (Vertex_index v : mesh.vertices())
    if (first[v.idx()] != no_corner_value && !channel.has_value(first[v.idx()]))
      refuse(v, "has no value", "");
  return value;
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_CORNER_DATA_H
