// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The limit surface of a corner channel (texture coordinates, corner
// normals...) at any parameter of any face: OpenSubdiv's face-varying
// Bfr::Surface.

#ifndef CGAL_EXT_LIMIT_SURFACE_CORNER_CHANNEL_LIMIT_SURFACE_H
#define CGAL_EXT_LIMIT_SURFACE_CORNER_CHANNEL_LIMIT_SURFACE_H

#include <CGAL_ext/Limit_surface.h>
#include <CGAL_ext/Limit_surface/internal/Channel_cage.h>
#include <CGAL_ext/Limit_surface/internal/Parameterization.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {

/// \ingroup PkgSubdivision
/// \brief The limit surface of a corner channel of a mesh under `Mask`
/// (`Catmull_clark_mask` or `Loop_mask`): the channel's value, with its
/// first derivatives, at any parameter of any face, as OpenSubdiv's
/// `Bfr::SurfaceFactory::InitFaceVaryingSurface()` and `Bfr::Surface::Evaluate()`
/// give it, on the parameterisation of `Limit_surface` (so one (face, u, v)
/// gives the point of the mesh's limit surface and, here, its texture
/// coordinates).
///
/// The channel's values are the control points of a surface over the
/// channel's own topology: the mesh cut open along the channel's seams, its
/// creases and corners kept, each value made a corner, a crease of its seam
/// or left smooth by the `face_varying_interpolation` mode, as subdivision
/// makes them (see the manual's corner data page); with
/// `Face_varying_interpolation::all` the channel is linear in each face
/// (bilinear in a quad or a quad sub-face, whose corners are the face's
/// corner, the midpoints of its two edges there and its centroid; linear in
/// a Loop triangle). Across a seam the two faces see their own values; a
/// face's value at a corner is the limit of its corner's value
/// (`limit_corner_values()`). A Möbius edge needs nothing special: values are
/// addressed by face corners.
///
/// The surface is built once (the mesh and the channel are copied); the
/// evaluation is that of `Limit_surface` (Bfr's patches, the same
/// approximation levels) on one surface per three coordinates of the value,
/// so several threads may evaluate one channel surface at once.
///
/// \tparam Mask `Catmull_clark_mask` or `Loop_mask`
/// \tparam P the point type of the mesh, of a CGAL kernel
/// \tparam T the channel's value type: `float`, `double`, `std::array` of
/// them (2 to 4), the kernel's `Point_2`, `Vector_2`, `Point_3` or `Vector_3`
template <class Mask, class P, class T>
class Corner_channel_limit_surface
{
public:
  /// The kernel of `P`.
  using Kernel = typename CGAL::Kernel_traits<P>::Kernel;
  /// The number type of the kernel.
  using FT = typename Kernel::FT;

private:
  using Coordinates = CGAL_ext::internal::Channel_coordinates<Kernel, T>;
  static_assert(Coordinates::defined, "a corner channel limit surface needs values of float, double, arrays of them, "
                                      "or the kernel's 2D and 3D points and vectors");
  static constexpr bool is_loop = std::is_same_v<Mask, Loop_mask>;

public:
  /// How many coordinates a value has (2 for texture coordinates).
  static constexpr std::size_t dimension = Coordinates::dimension;

  /// What `evaluate()` returns: the value and its derivatives along u and v,
  /// coordinate by coordinate.
  struct Evaluation
  {
    T value;                      ///< the channel's value at the parameter
    std::array<FT, dimension> du; ///< ∂/∂u of each coordinate of the value
    std::array<FT, dimension> dv; ///< ∂/∂v of each coordinate of the value
  };

  /// \brief makes the limit surface of the corner channel `name` of `mesh`,
  /// whose values are of type `T`.
  ///
  /// The named parameters are those of `Limit_surface` (the sharpness
  /// maps, `boundary_interpolation`, `crease_method`, `triangle_subdivision`), and:
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{face_varying_interpolation}
  ///     \cgalParamDefault{`Face_varying_interpolation::corners_plus1`, as OpenSubdiv's}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws Parameter_error if `mesh` has no corner channel `name` with
  /// values of type `T`, a face corner has no value or an index past the
  /// values, or as `Limit_surface`'s constructor.
  template <class NP = parameters::Default_named_parameters>
  Corner_channel_limit_surface(const Mobius_mesh<P>& mesh, const std::string& name,
                               const NP& np = parameters::default_values(),
                               const Limit_surface_options& options = Limit_surface_options())
  {
    namespace pm = CGAL_ext::parameters;
    const char* function = "Corner_channel_limit_surface";
    CGAL_ext::internal::require_no_garbage(mesh, function);
    const auto channel = mesh.template corner_channel<T>(name);
    if (!channel)
      throw Parameter_error(std::string(function) + ": the mesh has no corner channel \"" + name +
                            "\" with values of the type asked for");
    check_options(mesh, options);
    const std::vector<std::uint32_t> user = internal::base_corners(function, mesh, *channel);
    const Face_varying_interpolation mode = pm::choose_parameter(
      pm::get_parameter(np, CGAL_ext::internal_np::face_varying_interpolation), Face_varying_interpolation::corners_plus1);
    cage_ = CGAL_ext::internal::make_channel_cage(function, mesh, user, mode, np);
    holes_ = internal::hole_faces(mesh, CGAL_ext::internal::boundary_interpolation_of(np));
    linear_ = cage_.linear;
    std::vector<std::array<FT, dimension>> coordinates;
    coordinates.reserve(channel->number_of_values());
    for (const T& t : channel->values())
      coordinates.push_back(Coordinates::split(t));
    if (linear_) {
      for (Face_index f : mesh.faces()) {
        std::vector<std::array<FT, dimension>> corners;
        for (Dart d : halfedges_around_face(mesh.halfedge(f), mesh))
          corners.push_back(coordinates[channel->index(mesh.corner(d))]);
        corners_.push_back(std::move(corners));
      }
      return;
    }
    const auto surface_np = pm::boundary_interpolation(Boundary_interpolation::edge_only)
                              .crease_method(CGAL_ext::internal::crease_method_of(np))
                              .triangle_subdivision(CGAL_ext::internal::triangle_subdivision_of(np));
    for (std::size_t first = 0; first < dimension; first += 3) {
      for (Vertex_index c : cage_.mesh.vertices()) {
        const std::array<FT, dimension>& x = coordinates[cage_.value_of[c.idx()]];
        const auto at = [&](std::size_t i) { return first + i < dimension ? x[first + i] : FT(0); };
        cage_.mesh.point(c) = P(at(0), at(1), at(2));
      }
      lanes_.push_back(std::make_unique<Limit_surface<Mask, P>>(cage_.mesh, surface_np, options));
    }
  }

  /// \brief the channel's value at parameter (`u`, `v`) of face `f` (see
  /// `Limit_surface` for the parameterisation), with its derivatives.
  /// \throws Parameter_error if `f` is not a face of the mesh, is a hole
  /// or (`u`, `v`) lies outside its parameter domain.
  Evaluation evaluate(Face_index f, const FT& u, const FT& v) const
  {
    if (is_hole(f))
      throw Parameter_error("Corner_channel_limit_surface::evaluate: face f" + std::to_string(f.idx()) +
                            " is a hole (it has a vertex on a border, and the boundary interpolation is none)");
    const Coordinate_evaluation c = evaluate_coordinates(f, u, v);
    return {Coordinates::join(c.value), c.du, c.dv};
  }

  /// Whether the channel is linear in each face (`Face_varying_interpolation::all`).
  bool is_linear() const { return linear_; }

  /// Whether face `f` is a hole, without a surface (as `Limit_surface::is_hole()`:
  /// under `Boundary_interpolation::none`, a face with a vertex on a border).
  bool is_hole(Face_index f) const { return f.idx() < holes_.size() && holes_[f.idx()]; }

private:
  template <class, class>
  friend class Limit_surface;
  using Values = std::array<FT, dimension>;
  struct Coordinate_evaluation
  {
    Values value, du, dv;
  };

  // The coordinates of lanes [first_lane, last_lane) (all of a linear
  // channel's); the others are left as they are.
  Coordinate_evaluation evaluate_coordinates(Face_index f, const FT& u, const FT& v, std::size_t first_lane = 0,
                                             std::size_t last_lane = std::size_t(-1)) const
  {
    if (linear_)
      return evaluate_linear(f, u, v);
    Coordinate_evaluation e{};
    for (std::size_t lane = first_lane; lane < (std::min)(last_lane, lanes_.size()); ++lane) {
      const typename Limit_surface<Mask, P>::Evaluation r = lanes_[lane]->evaluate(f, u, v);
      const FT p[3] = {r.point.x(), r.point.y(), r.point.z()};
      const FT du[3] = {r.du.x(), r.du.y(), r.du.z()}, dv[3] = {r.dv.x(), r.dv.y(), r.dv.z()};
      for (std::size_t i = 0; i < 3 && 3 * lane + i < dimension; ++i) {
        e.value[3 * lane + i] = p[i];
        e.du[3 * lane + i] = du[i];
        e.dv[3 * lane + i] = dv[i];
      }
    }
    return e;
  }

  // What Limit_surface refuses, refused here too, for a linear channel as well.
  static void check_options(const Mobius_mesh<P>& mesh, const Limit_surface_options& options)
  {
    if ((std::max)(options.approx_level_smooth, options.approx_level_sharp) > Limit_surface<Mask, P>::max_approximation_level)
      throw Parameter_error("Corner_channel_limit_surface: an approximation level is above " +
                            std::to_string(Limit_surface<Mask, P>::max_approximation_level));
    if constexpr (is_loop)
      for (Face_index f : mesh.faces())
        if (mesh.degree(f) != 3)
          throw Parameter_error("Corner_channel_limit_surface: face f" + std::to_string(f.idx()) +
                                " is not a triangle, which Loop's limit surface needs");
  }

  // Coordinates first .. first + 2 of the channel as a surface that the
  // tessellator samples (it reads the points only).
  struct Lane_surface
  {
    using Kernel = typename Corner_channel_limit_surface::Kernel;
    using FT = typename Corner_channel_limit_surface::FT;
    using Evaluation = Limit_surface_point<Kernel>;
    const Corner_channel_limit_surface* channel;
    std::size_t first;

    bool is_hole(Face_index f) const { return channel->is_hole(f); }
    Evaluation evaluate(Face_index f, const FT& u, const FT& v) const
    {
      const Values c = channel->evaluate_coordinates(f, u, v, first / 3, first / 3 + 1).value;
      const auto at = [&](std::size_t i) { return first + i < dimension ? c[first + i] : FT(0); };
      Evaluation e;
      e.point = P(at(0), at(1), at(2));
      e.normal = CGAL::NULL_VECTOR;
      return e;
    }
  };

  // The channel at the samples of the mesh's tessellation at `rates` (as
  // Limit_surface::tessellate() makes it): the cage tessellated at the same
  // rates has the same facets, a sample per value of each sample (a seam's
  // samples twice). Returns the value index of each facet's corners, in the
  // order the tessellator made them (the mesh's facet lists' layout), and
  // the values (evaluated in parallel for `CGAL::Parallel_tag`, the same).
  template <class ConcurrencyTag>
  std::pair<CGAL_ext::internal::Face_list, std::vector<T>> tessellated(const internal::Tessellation_rates& rates) const
  {
    internal::Tessellation_rates cage_rates{std::vector<int>(), rates.inner};
    cage_rates.edge.reserve(cage_.edge_of.size());
    for (std::uint32_t e : cage_.edge_of)
      cage_rates.edge.push_back(rates.edge[e]);
    CGAL_ext::internal::Face_list facets;
    std::vector<Values> values;
    const auto evaluated = [](Vertex_index, Face_index, const P& p) { return p; };
    for (std::size_t first = 0; first < dimension; first += 3) {
      const Lane_surface lane{this, first};
      internal::Limit_tessellator<Lane_surface, P, decltype(evaluated)> t(lane, cage_.mesh, cage_rates, evaluated, is_loop);
      t.template sample<ConcurrencyTag>();
      if (first == 0) {
        facets = t.facets();
        values.resize(t.points().size());
      }
      for (std::size_t i = 0; i < values.size(); ++i) {
        const FT p[3] = {t.points()[i].x(), t.points()[i].y(), t.points()[i].z()};
        for (std::size_t k = 0; k < 3 && first + k < dimension; ++k)
          values[i][first + k] = p[k];
      }
    }
    std::vector<T> out;
    out.reserve(values.size());
    for (const Values& x : values)
      out.push_back(Coordinates::join(x));
    return {std::move(facets), std::move(out)};
  }

  static Values combine(const FT (&w)[4], const Values* (&x)[4])
  {
    Values r;
    for (std::size_t i = 0; i < dimension; ++i)
      r[i] = w[0] * (*x[0])[i] + w[1] * (*x[1])[i] + w[2] * (*x[2])[i] + w[3] * (*x[3])[i];
    return r;
  }

  // Bilinear over the quad x[0..3] at (s, t), its derivatives times `scale`.
  static Coordinate_evaluation bilinear(const Values* (&x)[4], const FT& s, const FT& t, const FT& scale)
  {
    const FT w[4] = {(FT(1) - s) * (FT(1) - t), s * (FT(1) - t), s * t, (FT(1) - s) * t};
    const FT ws[4] = {-(FT(1) - t) * scale, (FT(1) - t) * scale, t * scale, -t * scale};
    const FT wt[4] = {-(FT(1) - s) * scale, -s * scale, s * scale, (FT(1) - s) * scale};
    return {combine(w, x), combine(ws, x), combine(wt, x)};
  }

  Coordinate_evaluation evaluate_linear(Face_index f, const FT& u, const FT& v) const
  {
    if (f.idx() >= corners_.size())
      throw Parameter_error("Corner_channel_limit_surface::evaluate: f" + std::to_string(f.idx()) +
                            " is not a face of the mesh");
    const std::vector<Values>& c = corners_[f.idx()];
    const int n = int(c.size());
    if constexpr (is_loop) {
      if (u < FT(0) || v < FT(0) || u + v > FT(1) + FT(4e-16))
        throw_outside(f);
      const Values zero{};
      const Values* x[4] = {&c[0], &c[1], &c[2], &zero};
      const FT w[4] = {FT(1) - u - v, u, v, FT(0)}, wu[4] = {FT(-1), FT(1), FT(0), FT(0)},
               wv[4] = {FT(-1), FT(0), FT(1), FT(0)};
      return {combine(w, x), combine(wu, x), combine(wv, x)};
    } else if (n == 4) {
      if (u < FT(0) || v < FT(0) || u > FT(1) || v > FT(1))
        throw_outside(f);
      const Values* x[4] = {&c[0], &c[1], &c[2], &c[3]};
      return bilinear(x, u, v, FT(1));
    } else {
      const internal::Sub_face_point<FT> at = internal::locate_sub_face(n, u, v);
      if (at.su < FT(0) || at.sv < FT(0) || at.su > FT(1) || at.sv > FT(1))
        throw_outside(f);
      // The sub-face at corner k: the corner, the midpoint of the edge
      // after it, the centroid, the midpoint of the edge before it.
      Values after, centroid, before;
      for (std::size_t i = 0; i < dimension; ++i) {
        after[i] = (c[at.k][i] + c[(at.k + 1) % n][i]) / FT(2);
        before[i] = (c[at.k][i] + c[(at.k + n - 1) % n][i]) / FT(2);
        centroid[i] = FT(0);
        for (const Values& y : c)
          centroid[i] += y[i];
        centroid[i] /= FT(n);
      }
      const Values* x[4] = {&c[at.k], &after, &centroid, &before};
      return bilinear(x, at.su, at.sv, FT(2));
    }
  }

  [[noreturn]] static void throw_outside(Face_index f)
  {
    throw Parameter_error("Corner_channel_limit_surface::evaluate: (u, v) lies outside the parameter domain of face f" +
                          std::to_string(f.idx()));
  }

  bool linear_ = false;
  CGAL_ext::internal::Channel_cage<P> cage_; // the channel's topology, whose tessellation the channel's is
  std::vector<std::unique_ptr<Limit_surface<Mask, P>>> lanes_; // a surface per three coordinates
  std::vector<std::vector<Values>> corners_; // per face, its corners' values (linear channels)
  std::vector<bool> holes_;                  // by face index, as Limit_surface's
};

} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_CORNER_CHANNEL_LIMIT_SURFACE_H
