// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Named parameters: CGAL's, plus the ones CGAL_ext adds, chainable in any
// order. `CGAL_ext::parameters::x(a).y(b)` is a `CGAL::Named_function_parameters`,
// so every CGAL_ext function also accepts `CGAL::parameters::...` objects.

#ifndef CGAL_EXT_NAMED_PARAMETERS_H
#define CGAL_EXT_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL_ext {
namespace internal_np {

#define CGAL_EXT_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL_ext/internal/parameters_interface.h>
#undef CGAL_EXT_add_named_parameter

} // namespace internal_np

/// A `CGAL::Named_function_parameters` whose chaining functions also know
/// CGAL_ext's parameters: `.x(a)` appends parameter `x` with value `a`, for
/// every parameter of CGAL and of CGAL_ext (see \ref md_doc_named_parameters "doc/named_parameters.md").
/// It holds the value `T` of the parameter tagged `Tag`, and the parameters
/// before it in `Base`.
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// The CGAL class it extends, which every CGAL function accepts.
  using cgal_type = CGAL::Named_function_parameters<T, Tag, Base>;
  /// This class.
  using self = Named_function_parameters<T, Tag, Base>;

  /// An empty list of parameters.
  Named_function_parameters() : cgal_type() {}
  /// The list of one parameter of value `v`.
  Named_function_parameters(const T& v) : cgal_type(v) {}
  /// The list `b` followed by a parameter of value `v`.
  Named_function_parameters(const T& v, const Base& b) : cgal_type(v, b) {}

#define CGAL_add_named_parameter(X, Y, Z)                                                                   \
  template <class K>                                                                                       \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const                             \
  {                                                                                                        \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);                             \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_EXT_add_named_parameter(X, Y, Z)                                                               \
  template <class K>                                                                                       \
  Named_function_parameters<K, CGAL_ext::internal_np::X, self> Z(const K& k) const                         \
  {                                                                                                        \
    return Named_function_parameters<K, CGAL_ext::internal_np::X, self>(k, *this);                         \
  }
#include <CGAL_ext/internal/parameters_interface.h>
#undef CGAL_EXT_add_named_parameter
};

/// The named parameters: each function of this namespace named after a
/// parameter (`tolerance()`, `geom_traits()`, ...) starts a list with that
/// parameter, as in `CGAL::parameters` (see \ref md_doc_named_parameters "doc/named_parameters.md").
namespace parameters {

/// The type of an empty list of named parameters, where every parameter takes its default.
using Default_named_parameters = CGAL::parameters::Default_named_parameters;

/// An empty list of named parameters: every parameter takes its default.
inline Default_named_parameters default_values() { return Default_named_parameters(); }

#define CGAL_add_named_parameter(X, Y, Z)                                                                   \
  template <class K>                                                                                       \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k)                                         \
  {                                                                                                        \
    return Named_function_parameters<K, CGAL::internal_np::X>(k);                                          \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_EXT_add_named_parameter(X, Y, Z)                                                               \
  template <class K>                                                                                       \
  Named_function_parameters<K, CGAL_ext::internal_np::X> Z(const K& k)                                     \
  {                                                                                                        \
    return Named_function_parameters<K, CGAL_ext::internal_np::X>(k);                                      \
  }
#include <CGAL_ext/internal/parameters_interface.h>
#undef CGAL_EXT_add_named_parameter

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;

} // namespace parameters
} // namespace CGAL_ext

#endif // CGAL_EXT_NAMED_PARAMETERS_H
