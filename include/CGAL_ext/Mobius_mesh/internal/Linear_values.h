// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Which values of the mesh's maps and corner channels have a linear
// combination, and how it is taken: the one rule of the operations that make
// new values from old ones (subdivision, the limit values of a channel, the
// corners that decimation merges).

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_LINEAR_VALUES_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_LINEAR_VALUES_H

#include <CGAL_ext/Mobius_mesh/internal/Property_container.h>

#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL_ext {
namespace internal {

// How a vertex value of type T is interpolated: as `Value`, which has
// `Value + Value` and `W * Value`, the weights being of type W. Not defined
// for types without a linear combination (integers, strings, colours of
// bytes): their maps are dropped.
template <class W, class K, class T, class = void>
struct Linear_value
{
  static constexpr bool defined = false;
};
// Floating-point numbers, as the weights' number type (exact with an exact kernel).
template <class W, class K, class T>
struct Linear_value<W, K, T, std::enable_if_t<std::is_floating_point_v<T>>>
{
  static constexpr bool defined = true;
  using Value = W;
  static Value from(const T& t) { return W(t); }
  static T to(const Value& v) { return T(CGAL::to_double(v)); }
};
// The kernel's points (as vectors from the origin) and vectors, 2D and 3D,
// when its number type is the weights'.
template <class K, class T>
constexpr bool is_kernel_point = std::is_same_v<T, typename K::Point_2> || std::is_same_v<T, typename K::Point_3>;
template <class K, class T>
constexpr bool is_kernel_vector = std::is_same_v<T, typename K::Vector_2> || std::is_same_v<T, typename K::Vector_3>;
template <class W, class K, class T>
struct Linear_value<W, K, T, std::enable_if_t<std::is_same_v<typename K::FT, W> && is_kernel_point<K, T>>>
{
  static constexpr bool defined = true;
  using Value = decltype(std::declval<T>() - CGAL::ORIGIN);
  static Value from(const T& p) { return p - CGAL::ORIGIN; }
  static T to(const Value& v) { return CGAL::ORIGIN + v; }
};
template <class W, class K, class T>
struct Linear_value<W, K, T, std::enable_if_t<std::is_same_v<typename K::FT, W> && is_kernel_vector<K, T>>>
{
  static constexpr bool defined = true;
  using Value = T;
  static Value from(const T& v) { return v; }
  static T to(const Value& v) { return v; }
};

// A fixed-size array of interpolated values (colours, texture coordinates).
template <class V, std::size_t N>
struct Value_array
{
  std::array<V, N> a;
};
template <class V, std::size_t N>
Value_array<V, N> operator+(const Value_array<V, N>& x, const Value_array<V, N>& y)
{
  Value_array<V, N> r = x;
  for (std::size_t i = 0; i < N; ++i)
    r.a[i] = r.a[i] + y.a[i];
  return r;
}
template <class W, class V, std::size_t N>
Value_array<V, N> operator*(const W& w, const Value_array<V, N>& x)
{
  Value_array<V, N> r = x;
  for (std::size_t i = 0; i < N; ++i)
    r.a[i] = w * r.a[i];
  return r;
}
template <class W, class K, class E, std::size_t N>
struct Linear_value<W, K, std::array<E, N>, std::enable_if_t<Linear_value<W, K, E>::defined>>
{
  static constexpr bool defined = true;
  using Element = Linear_value<W, K, E>;
  using Value = Value_array<typename Element::Value, N>;
  static Value from(const std::array<E, N>& t)
  {
    Value v{};
    for (std::size_t i = 0; i < N; ++i)
      v.a[i] = Element::from(t[i]);
    return v;
  }
  static std::array<E, N> to(const Value& v)
  {
    std::array<E, N> t{};
    for (std::size_t i = 0; i < N; ++i)
      t[i] = Element::to(v.a[i]);
    return t;
  }
};

// A value of type T as a vector of doubles, and back: for what works on
// values in double (decimation's attribute quadrics). Floating-point
// numbers, the kernel's 2D and 3D points and vectors (their coordinates, made
// back exactly from the doubles with an exact kernel), arrays of them.
template <class K, class T, class = void>
struct Value_doubles
{
  static constexpr bool defined = false;
  static constexpr std::size_t size = 0;
};
template <class K, class T>
struct Value_doubles<K, T, std::enable_if_t<std::is_floating_point_v<T>>>
{
  static constexpr bool defined = true;
  static constexpr std::size_t size = 1;
  static void read(const T& t, double* x) { x[0] = double(t); }
  static T make(const double* x) { return T(x[0]); }
};
template <class K, class T>
constexpr std::size_t kernel_dimension = std::is_same_v<T, typename K::Point_2> || std::is_same_v<T, typename K::Vector_2>
                                           ? 2
                                         : std::is_same_v<T, typename K::Point_3> || std::is_same_v<T, typename K::Vector_3>
                                           ? 3
                                           : 0;
template <class K, class T>
struct Value_doubles<K, T, std::enable_if_t<kernel_dimension<K, T> != 0>>
{
  static constexpr bool defined = true;
  static constexpr std::size_t size = kernel_dimension<K, T>;
  static void read(const T& t, double* x)
  {
    for (std::size_t i = 0; i < size; ++i)
      x[i] = CGAL::to_double(t.cartesian(int(i)));
  }
  static T make(const double* x)
  {
    using FT = typename K::FT;
    if constexpr (size == 2)
      return T(FT(x[0]), FT(x[1]));
    else
      return T(FT(x[0]), FT(x[1]), FT(x[2]));
  }
};
template <class K, class E, std::size_t N>
struct Value_doubles<K, std::array<E, N>, std::enable_if_t<Value_doubles<K, E>::defined>>
{
  using Element = Value_doubles<K, E>;
  static constexpr bool defined = true;
  static constexpr std::size_t size = N * Element::size;
  static void read(const std::array<E, N>& t, double* x)
  {
    for (std::size_t i = 0; i < N; ++i)
      Element::read(t[i], x + i * Element::size);
  }
  static std::array<E, N> make(const double* x)
  {
    std::array<E, N> t{};
    for (std::size_t i = 0; i < N; ++i)
      t[i] = Element::make(x + i * Element::size);
    return t;
  }
};

// The vertex value types whose maps are interpolated: a list, as the maps'
// types are known only at run time (by name and type_info).
template <class K, class F>
void for_each_interpolated_type(F&& f)
{
  f(Type_tag<float>());
  f(Type_tag<double>());
  f(Type_tag<typename K::Point_3>());
  f(Type_tag<typename K::Vector_3>());
  for_each_small_array_type(f);
}

// The value types of the corner channels that are interpolated: those of the
// vertex maps, and the kernel's 2D points and vectors.
template <class K, class F>
void for_each_interpolated_channel_type(F&& f)
{
  for_each_interpolated_type<K>(f);
  f(Type_tag<typename K::Point_2>());
  f(Type_tag<typename K::Vector_2>());
}

// Refuses, before `function` touches `mesh`, a corner channel whose values
// have no linear combination with weights of type W: no new value could be
// made for it.
template <class W, class Mesh>
void require_interpolated_channels(const Mesh& mesh, const std::string& function)
{
  using K = typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel;
  for (const std::string& name : mesh.corner_channels()) {
    bool interpolated = false;
    for_each_interpolated_channel_type<K>([&](auto tag) {
      using T = typename decltype(tag)::type;
      if constexpr (Linear_value<W, K, T>::defined)
        interpolated = interpolated || mesh.template corner_channel<T>(name).has_value();
    });
    if (!interpolated)
      throw Parameter_error(function + ": corner channel \"" + name +
                            "\" has values of a type that is not interpolated (floating-point numbers, arrays of them, "
                            "the kernel's points and vectors are); remove it first (Mobius_mesh::remove_corner_channel())");
  }
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_LINEAR_VALUES_H
