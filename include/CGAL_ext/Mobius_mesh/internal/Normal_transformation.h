// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The engine of transform() in <CGAL_ext/Mobius_mesh/transform.h>: the
// transformation of corner normals (the inverse transpose of the linear part),
// refused where the kernel's numbers cannot invert it.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_NORMAL_TRANSFORMATION_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_NORMAL_TRANSFORMATION_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Whether a transformation shows its matrix, as CGAL::Aff_transformation_3
// does (`cartesian(i, j)`): only then can normals be transformed.
template <class T, class = void>
struct Has_cartesian_matrix : std::false_type
{};
template <class T>
struct Has_cartesian_matrix<T, std::void_t<decltype(std::declval<const T&>().cartesian(0, 0))>> : std::true_type
{};

// n -> sign(det A) A^-T n = cof(A) n / |det A|, A the linear part of t.
// The cofactor matrix is what cross products of transformed edges give, so
// a normal keeps agreeing with its face's cycle, which transform() keeps
// also where t mirrors the surface (there A^-T n alone would point the other
// way). No division but by |det A|: exact with an exact kernel.
template <class Vector_3>
class Normal_transformation
{
public:
  using FT = typename CGAL::Kernel_traits<Vector_3>::Kernel::FT;

  template <class Transformation>
  explicit Normal_transformation(const Transformation& t)
  {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        cofactor_[i][j] = t.cartesian((i + 1) % 3, (j + 1) % 3) * t.cartesian((i + 2) % 3, (j + 2) % 3) -
                          t.cartesian((i + 1) % 3, (j + 2) % 3) * t.cartesian((i + 2) % 3, (j + 1) % 3);
    det_ = t.cartesian(0, 0) * cofactor_[0][0] + t.cartesian(0, 1) * cofactor_[0][1] +
           t.cartesian(0, 2) * cofactor_[0][2];
    if (det_ < 0)
      det_ = -det_;
  }

  bool is_singular() const { return det_ == 0; }

  Vector_3 operator()(const Vector_3& n) const
  {
    const auto row = [&](int i) {
      return (cofactor_[i][0] * n.x() + cofactor_[i][1] * n.y() + cofactor_[i][2] * n.z()) / det_;
    };
    return Vector_3(row(0), row(1), row(2));
  }

private:
  FT cofactor_[3][3];
  FT det_;
};

// The channel "c:normal" transformed as the normals of the transformed
// surface: each value by Normal_transformation, then given back its length
// where the number type is not exact (a square root would make an exact one
// inexact). Refused (Parameter_error, before the mesh is touched) where the
// normals cannot follow: a transformation without a matrix, a singular one,
// or values of another type than the readers make.
template <class P, class Transformation>
std::optional<Normal_transformation<Corner_normal<P>>> checked_normal_transformation(const Mobius_mesh<P>& mesh,
                                                                                     const Transformation& t)
{
  const std::vector<std::string> names = mesh.corner_channels();
  if (std::find(names.begin(), names.end(), corner_normal_name) == names.end())
    return std::nullopt;
  const std::string why = std::string("transform: the mesh has the corner channel \"") + corner_normal_name + "\", ";
  if (!mesh.template corner_channel<Corner_normal<P>>(corner_normal_name))
    throw Parameter_error(why + "whose values are not the kernel's Vector_3, which transform() knows how to transform");
  if constexpr (!Has_cartesian_matrix<Transformation>::value) {
    throw Parameter_error(why + "whose normals need the transformation's matrix: pass a CGAL::Aff_transformation_3");
  } else {
    Normal_transformation<Corner_normal<P>> normal(t);
    if (normal.is_singular())
      throw Parameter_error(why + "whose normals a singular transformation (determinant 0) does not carry");
    return normal;
  }
}

template <class P>
void transform_corner_normals(Mobius_mesh<P>& mesh, const Normal_transformation<Corner_normal<P>>& normal)
{
  using FT = typename Normal_transformation<Corner_normal<P>>::FT;
  constexpr bool exact = std::is_same_v<typename CGAL::Algebraic_structure_traits<FT>::Is_exact, CGAL::Tag_true>;
  for (Corner_normal<P>& n : mesh.template corner_channel<Corner_normal<P>>(corner_normal_name)->values()) {
    const Corner_normal<P> m = normal(n);
    const FT before = n.squared_length(), after = m.squared_length();
    if (exact || after == 0 || before == after)
      n = m;
    else
      n = m * CGAL::approximate_sqrt(before / after);
  }
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_NORMAL_TRANSFORMATION_H
