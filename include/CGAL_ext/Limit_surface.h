// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The limit surface of a Catmull–Clark or Loop mesh at any point of any
// face, with derivatives and normal, parameterised as OpenSubdiv's Bfr
// parameterises a base face, and evaluated as Bfr evaluates it.

#ifndef CGAL_EXT_LIMIT_SURFACE_H
#define CGAL_EXT_LIMIT_SURFACE_H

#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/Limit_surface/internal/Channel_cage.h>
#include <CGAL_ext/Limit_surface/internal/Face_cache.h>
#include <CGAL_ext/Limit_surface/internal/Loop_patch_builder.h>
#include <CGAL_ext/Limit_surface/internal/Patch_builder.h>
#include <CGAL_ext/Limit_surface/internal/Parameterization.h>
#include <CGAL_ext/Limit_surface/internal/Patches.h>
#include <CGAL_ext/Limit_surface/internal/Projection.h>
#include <CGAL_ext/Limit_surface/internal/Tessellation.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Linear_values.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Masks.h>
#include <CGAL_ext/Subdivision/limit.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Parallel_loops.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {

/// \ingroup PkgSubdivision
/// The refinement depths at which `Limit_surface` stops and approximates
/// the surface near irregular features, as OpenSubdiv's
/// `Bfr::SurfaceFactory::Options` (same names, same defaults).
struct Limit_surface_options
{
  /// Depth of refinement around smooth extraordinary vertices, irregular
  /// borders and faces that are not quads (OpenSubdiv's `approxLevelSmooth`).
  unsigned approx_level_smooth = 2;
  /// Depth of refinement around semi-sharp creases and irregular corners
  /// (OpenSubdiv's `approxLevelSharp`); at least `approx_level_smooth`.
  unsigned approx_level_sharp = 6;
  /// Samples per base edge of the search structure that
  /// `Limit_surface::closest_point()` starts from (a quad is sampled on a
  /// grid of this many cells a side, each sub-face of another face on half
  /// as many, a triangle of a Loop surface on a triangular grid of this many
  /// cells a side; 0 counts as 1, more than 1024 as 1024): more makes the
  /// structure larger and the search try fewer faces. The faces tried are
  /// those whose samples come within the nearest sample's distance plus four
  /// times the largest gap between the surface and its samples measured at
  /// the cells' centres, an estimate: a finer rate makes a miss less likely
  /// where the surface curves sharply within a cell.
  unsigned projection_rate = 4;
  /// The most segments `Limit_surface::tessellate_to_tolerance()` puts
  /// along a base edge or across a face (0 counts as 1, more than 4096 as 4096).
  unsigned max_tessellation_rate = 64;
  /// The most bytes of patches kept for faces already evaluated (the
  /// patches' arrays: about 600 bytes for a regular face in double, a few
  /// kilobytes around an extraordinary vertex). Past it, a face's patches
  /// are built for each evaluation and dropped after it: the memory stays
  /// bounded, the evaluation of those faces slower (as Bfr without its
  /// `SurfaceFactoryCache`). The default, 1 GiB, keeps a million regular faces.
  std::size_t max_cache_bytes = std::size_t(1) << 30;
};

/// \ingroup PkgSubdivision
/// A point of a limit surface with its derivatives, as
/// `Limit_surface::evaluate()` returns it.
template <class Kernel>
struct Limit_surface_point
{
  typename Kernel::Point_3 point;  ///< the position
  typename Kernel::Vector_3 du;    ///< ∂/∂u
  typename Kernel::Vector_3 dv;    ///< ∂/∂v
  typename Kernel::Vector_3 duu;   ///< ∂²/∂u²
  typename Kernel::Vector_3 duv;   ///< ∂²/∂u∂v
  typename Kernel::Vector_3 dvv;   ///< ∂²/∂v²
  typename Kernel::Vector_3 normal; ///< `du × dv`, of unit length (the null vector where it vanishes: |du × dv| ≤ 1e-10 |du| |dv|)
};

/// \ingroup PkgSubdivision
/// The point of a limit surface closest to a query, as
/// `Limit_surface::closest_point()` returns it.
template <class Kernel>
struct Limit_surface_location
{
  Face_index face;                      ///< the face the point lies on
  typename Kernel::FT u;                ///< its parameter in `face` (see `Limit_surface`), first coordinate
  typename Kernel::FT v;                ///< its parameter in `face`, second coordinate
  typename Kernel::Point_3 point;       ///< the surface at (`u`, `v`) of `face`
  typename Kernel::Vector_3 normal;     ///< the unit normal there, seen from `face`'s orientation
  typename Kernel::FT squared_distance; ///< from the query to `point`
};

template <class Mask, class P, class T>
class Corner_channel_limit_surface;

/// \ingroup PkgSubdivision
/// \brief The limit surface of a mesh under `Mask` (`Catmull_clark_mask` or
/// `Loop_mask`), evaluated at any parameter of any face, with first and second
/// derivatives and the unit normal.
///
/// Built once from a mesh; the patches of a face are made the first time
/// the face is evaluated and kept (one lock per face, so many threads may
/// evaluate one surface at once). The mesh is copied: later changes to it
/// do not reach the surface.
///
/// **Parameterisation** (OpenSubdiv's `Bfr::Parameterization`): a quad is
/// [0, 1]², its corner i being the i-th vertex of
/// `vertices_around_face(f)` at (0, 0), (1, 0), (1, 1), (0, 1). A face of n ≠ 4
/// sides is split into n quad sub-faces, laid out in rows of
/// `ceil(sqrt(n))` unit tiles: sub-face k (the quarter at corner k, its u
/// from corner k towards corner k + 1) covers [x, x + ½] × [y, y + ½] with
/// x = k mod the row length, y = k div it; derivatives are with respect to
/// those (u, v). Under `Loop_mask` every face is a triangle, its corner i
/// at (0, 0), (1, 0), (0, 1): the domain is u, v ≥ 0, u + v ≤ 1.
///
/// **How it is evaluated** (as OpenSubdiv's `Bfr::Surface`): a quad whose four
/// corners are regular (valence 4 inside, two faces at a border or along an
/// infinitely sharp crease, one face at a corner, no semi-sharp edge at a
/// corner) is one bicubic B-spline patch of its 16 points, gathered by
/// darts: exact, and exact in an exact kernel at rational (u, v); a border
/// or infinite crease extrapolates the missing row (2 P − Q). Other faces
/// are refined, their neighbourhood subdivided by the library's own
/// Catmull–Clark rules, regular sub-faces becoming B-spline patches, to
/// `approx_level_smooth` levels around smooth irregularities and
/// `approx_level_sharp` around semi-sharp ones; an irregular sub-face at the
/// last level is OpenSubdiv's 20-point Gregory patch. The Gregory points and
/// its derivatives (those of the Bezier patch its blended points make) are
/// those of OpenSubdiv's `Far::PatchBuilder`. At a corner of a face the
/// position is the limit position of that vertex (`limit_point()`).
///
/// Under `Loop_mask` likewise: a triangle whose three corners are regular
/// (valence 6 inside, three faces at a border or along an infinitely sharp
/// crease, one face at a corner) is the quartic box-spline patch of its 12
/// points (beyond a border the missing points are reflected, as
/// OpenSubdiv's boundary patches do), exact in an exact kernel; other
/// triangles are refined by the library's Loop rules into four children
/// (the middle one turned half a turn, as in Bfr's patch tree), down to the
/// same levels, and an irregular triangle at the last level is OpenSubdiv's
/// 18-point quartic Gregory triangle, built as its `Far::LoopPatchBuilder`
/// builds it.
///
/// On a one-sided surface every neighbourhood is gathered by darts, so a
/// patch across a Möbius edge is the patch of the orientation double cover;
/// the normal is that of the face's own orientation.
///
/// \tparam Mask `Catmull_clark_mask` or `Loop_mask`
/// \tparam P the point type of the mesh, of a CGAL kernel
template <class Mask, class P>
class Limit_surface
{
  static_assert(std::is_same_v<Mask, Catmull_clark_mask> || std::is_same_v<Mask, Loop_mask>,
                "Limit_surface evaluates Catmull-Clark and Loop surfaces");
  static constexpr bool is_loop = std::is_same_v<Mask, Loop_mask>;

public:
  /// The kernel of `P`.
  using Kernel = typename CGAL::Kernel_traits<P>::Kernel;
  /// The number type of the kernel.
  using FT = typename Kernel::FT;
  /// What `evaluate()` returns.
  using Evaluation = Limit_surface_point<Kernel>;
  /// What `closest_point()` returns.
  using Location = Limit_surface_location<Kernel>;
  /// The deepest approximation level the constructor takes.
  static constexpr unsigned max_approximation_level = 31;

  /// \brief makes the limit surface of `mesh` (which may be freed afterwards).
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{edge_sharpness_map, vertex_sharpness_map}
  ///     \cgalParamDefault{the maps `"e:sharpness"` / `"v:sharpness"` of `mesh` if it has them, else all 0}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{boundary_interpolation}
  ///     \cgalParamDescription{as subdivision's; with `none` every face with a vertex on a border is a hole (`is_hole()`), as OpenSubdiv makes it, the others' surface that of `edge_only`}
  ///     \cgalParamDefault{`Boundary_interpolation::edge_only`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{crease_method}
  ///     \cgalParamDefault{`Crease_method::uniform`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{triangle_subdivision}
  ///     \cgalParamDescription{`Catmull_clark_mask` only: OpenSubdiv's rule at triangles, as `catmull_clark()` takes it}
  ///     \cgalParamDefault{`Triangle_subdivision::catmark`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDefault{`mesh.points()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{face_varying_interpolation}
  ///     \cgalParamDescription{how `tessellate()` and `tessellate_to_tolerance()` carry the mesh's corner channels (see `Corner_channel_limit_surface`)}
  ///     \cgalParamDefault{`Face_varying_interpolation::corners_plus1`, as OpenSubdiv's}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws Parameter_error if `mesh` has removed elements, a sharpness is
  /// NaN or negative, an approximation level is above `max_approximation_level` (31), or (`Loop_mask`) a face
  /// is not a triangle.
  template <class NP = parameters::Default_named_parameters>
  explicit Limit_surface(const Mobius_mesh<P>& mesh, const NP& np = parameters::default_values(),
                         const Limit_surface_options& options = Limit_surface_options())
  {
    namespace pm = CGAL_ext::parameters;
    CGAL_ext::internal::require_no_garbage(mesh, "Limit_surface");
    CGAL_ext::internal::refuse_non_manifold_joins(mesh, "Limit_surface");
    options_.boundary = CGAL_ext::internal::boundary_interpolation_of(np);
    options_.crease = CGAL_ext::internal::crease_method_of(np);
    options_.triangles = CGAL_ext::internal::triangle_subdivision_of(np);
    options_.level_smooth = options.approx_level_smooth;
    options_.level_sharp = std::max(options.approx_level_sharp, options.approx_level_smooth);
    // A patch's place in a Loop triangle's quadtree is two bits a level of
    // one 64-bit word (and 31 levels refine a face 2^31 times a side).
    if (options_.level_sharp > max_approximation_level)
      throw Parameter_error("Limit_surface: approximation level " + std::to_string(options_.level_sharp) +
                            " is above " + std::to_string(max_approximation_level));
    if constexpr (is_loop)
      for (Face_index f : mesh.faces())
        if (mesh.degree(f) != 3)
          throw Parameter_error("Limit_surface: face f" + std::to_string(f.idx()) +
                                " is not a triangle, which Loop's limit surface needs");
    fvar_mode_ = pm::choose_parameter(pm::get_parameter(np, CGAL_ext::internal_np::face_varying_interpolation),
                                      Face_varying_interpolation::corners_plus1);
    base_.mesh = mesh;
    const auto points = pm::choose_parameter(pm::get_parameter(np, CGAL::internal_np::vertex_point), mesh.points());
    for (Vertex_index v : mesh.vertices())
      base_.mesh.point(v) = get(points, v);
    copy_sharpness(mesh, np);
    faces_ = internal::Face_cache<Face_patches>(mesh.number_of_faces(), options.max_cache_bytes);
    holes_ = internal::hole_faces(mesh, options_.boundary);
    projection_rate_ = int(std::min(options.projection_rate, 1024u));
    max_tessellation_rate_ = int(std::min(std::max(options.max_tessellation_rate, 1u), 4096u));
  }

  /// \brief whether face `f` has no limit surface: under
  /// `Boundary_interpolation::none`, a face with a vertex on a border (as
  /// OpenSubdiv's `Bfr` gives it no surface, and subdivision marks its
  /// children in `"f:hole"`). `evaluate()` refuses a hole; `tessellate()`,
  /// `tessellate_to_tolerance()` and `closest_point()` leave it out. False
  /// under the other boundary rules.
  bool is_hole(Face_index f) const { return f.idx() < holes_.size() && holes_[f.idx()]; }

  /// \brief the limit surface at parameter (`u`, `v`) of face `f` (see the
  /// class for the parameterisation; for a Loop triangle in a floating-point
  /// kernel, u + v may pass 1 by rounding, up to 4e-16).
  /// \throws Parameter_error if `f` is not a face of the mesh, is a hole
  /// (`is_hole()`) or (`u`, `v`) lies outside its parameter domain.
  Evaluation evaluate(Face_index f, const FT& u, const FT& v) const
  {
    if (!base_.mesh.is_valid(f) || f.idx() >= faces_.size())
      throw Parameter_error("Limit_surface::evaluate: f" + std::to_string(f.idx()) + " is not a face of the mesh");
    if (is_hole(f))
      throw Parameter_error("Limit_surface::evaluate: face f" + std::to_string(f.idx()) +
                            " is a hole (it has a vertex on a border, and the boundary interpolation is none)");
    std::unique_ptr<Face_patches> spill;
    const Face_patches& patches = patches_of(f, spill);
    if constexpr (is_loop)
      return evaluate_triangle(f, patches.sub_faces[0], u, v);
    std::size_t list = 0;
    FT su = u, sv = v, scale = FT(1);
    if (patches.sub_faces.size() > 1) { // Bfr's quad sub-faces
      const internal::Sub_face_point<FT> at = internal::locate_sub_face(int(patches.sub_faces.size()), u, v);
      list = std::size_t(at.k);
      su = at.su;
      sv = at.sv;
      scale = FT(2);
    }
    // Half-open squares, as Bfr's quadtree descends (a parameter on the
    // line between two patches belongs to the upper one), closed at 1.
    if (su < FT(0) || sv < FT(0) || su > FT(1) || sv > FT(1))
      throw Parameter_error("Limit_surface::evaluate: (u, v) lies outside the parameter domain of face f" +
                            std::to_string(f.idx()));
    for (const auto& patch : patches.sub_faces[list]) {
      const FT u0(patch.u0), v0(patch.v0), u1(patch.u0 + patch.size), v1(patch.v0 + patch.size), size(patch.size);
      if (su < u0 || sv < v0 || (su >= u1 && u1 < FT(1)) || (sv >= v1 && v1 < FT(1)))
        continue;
      return finish(internal::evaluate_patch(patch, (su - u0) / size, (sv - v0) / size), scale / size);
    }
    throw Parameter_error("Limit_surface::evaluate: (u, v) lies outside the parameter domain of face f" +
                          std::to_string(f.idx()));
  }

  /// \brief the limit surface at parameter (`u`, `v`) of the face of dart
  /// `d`, parameterised from `d`: as `evaluate()` parameterises a face whose
  /// corners are listed from `source(d)` (corner 0) to `target(d)` (corner
  /// 1) and on in the direction of `d`, whichever way `d` runs along its
  /// face. The derivatives are taken in those parameters, and the normal
  /// (du × dv) is seen from `d`'s orientation: on a one-sided surface, from
  /// either side of a face. For `next(halfedge(f))`, it is `evaluate(f, u, v)`.
  /// \throws Parameter_error if `d` is not a dart of a face of the mesh, the
  /// face is a hole or (`u`, `v`) lies outside the parameter domain.
  Evaluation evaluate(Dart d, const FT& u, const FT& v) const
  {
    const Mobius_mesh<P>& m = base_.mesh;
    if (d == Dart() || d.halfedge().idx() >= m.number_of_halfedges() || !m.is_valid(m.face(d)))
      throw Parameter_error("Limit_surface::evaluate: the dart is not a dart of a face of the mesh");
    const Face_index f = m.face(d);
    const int n = int(m.degree(f));
    // Corner k of the face's own frame is where d's halfedge starts, walked
    // the face's way; d flipped starts at corner k + 1 and runs backwards.
    const Dart along = d.is_flipped() ? d.flipped() : d;
    int k = 0;
    for (Dart x = m.next(m.halfedge(f)); x != along && k < n; x = m.next(x))
      ++k;
    const bool reversed = d.is_flipped();
    const int start = reversed ? (k + 1) % n : k;
    if (!reversed && start == 0)
      return evaluate(f, u, v);
    const auto corner = [&](int j) { return reversed ? (start - j % n + n) % n : (start + j) % n; };
    const auto outside = [&] {
      return Parameter_error("Limit_surface::evaluate: (u, v) lies outside the parameter domain of face f" +
                             std::to_string(f.idx()) + " seen from its dart");
    };
    if (internal::has_own_domain(n, is_loop)) {
      // A symmetry of the square or the triangle: affine, with integer
      // coefficients, exact in an exact kernel.
      const auto c0 = internal::corner_parameter<FT>(n, is_loop, corner(0));
      const auto c1 = internal::corner_parameter<FT>(n, is_loop, corner(1));
      const auto c2 = internal::corner_parameter<FT>(n, is_loop, corner(n - 1));
      const std::array<FT, 4> J = {c1[0] - c0[0], c2[0] - c0[0], c1[1] - c0[1], c2[1] - c0[1]};
      FT fu = c0[0] + J[0] * u + J[1] * v, fv = c0[1] + J[2] * u + J[3] * v;
      if (is_loop ? outside_triangle(u, v) : (u < FT(0) || v < FT(0) || u > FT(1) || v > FT(1)))
        throw outside();
      // A triangle's far side, 1 - u - v, may round below 0.
      fu = fu < FT(0) ? FT(0) : fu;
      fv = fv < FT(0) ? FT(0) : fv;
      return in_frame(evaluate(f, fu, fv), J);
    }
    const internal::Sub_face_point<FT> at = internal::locate_sub_face(n, u, v);
    if (at.su < FT(0) || at.sv < FT(0) || at.su > FT(1) || at.sv > FT(1))
      throw outside();
    // Sub-face j of d's frame is the sub-face at face corner corner(j), its
    // two local axes exchanged when d runs against the face.
    const auto uv = internal::sub_face_parameter(n, corner(at.k), reversed ? at.sv : at.su, reversed ? at.su : at.sv);
    const std::array<FT, 4> J = reversed ? std::array<FT, 4>{FT(0), FT(1), FT(1), FT(0)}
                                         : std::array<FT, 4>{FT(1), FT(0), FT(0), FT(1)};
    return in_frame(evaluate(f, uv[0], uv[1]), J);
  }

  /// \brief the point of the limit surface closest to `query`: its face,
  /// parameter, position, normal and squared distance.
  ///
  /// A search structure is built the first time (an AABB tree over the
  /// surface sampled at `Limit_surface_options::projection_rate`, kept, so
  /// several threads may ask at once); it gives a start in each face that
  /// comes near the query, from which Newton's method on the surface's first
  /// and second derivatives, held inside the face's parameter domain (each
  /// sub-face's, for a face that is not a quad; under `Loop_mask` the
  /// triangle u, v ≥ 0, u + v ≤ 1, its long side held as the others), finds
  /// the nearest point;
  /// the nearest of those is returned. So the result is the closest point
  /// wherever a start lies in its basin, which the sampling ensures where the
  /// query is nearer the surface than its curvature radius; a query
  /// equally far from several places (the centre of a sphere) gets one of them.
  ///
  /// The search runs in `double`; `point` and `normal` are then evaluated
  /// at the parameter found, in the kernel (exactly, in an exact kernel, at
  /// that rational parameter), and `squared_distance` computed from them.
  /// \throws Parameter_error if a coordinate of `query` is not a finite
  /// number, or the mesh has no face (or only degenerate ones).
  /// \throws Size_error if the sampling would make more than 2³² − 1
  /// triangles (a lower `projection_rate` makes fewer).
  Location closest_point(const P& query) const
  {
    std::call_once(*projection_once_, [&] {
      projection_ =
        std::make_unique<internal::Limit_projection<Limit_surface>>(*this, base_.mesh, projection_rate_, is_loop);
    });
    if (!(std::isfinite(CGAL::to_double(query.x())) && std::isfinite(CGAL::to_double(query.y())) &&
          std::isfinite(CGAL::to_double(query.z()))))
      throw Parameter_error("Limit_surface::closest_point: the query has a coordinate that is not a finite number");
    if (projection_->empty())
      throw Parameter_error("Limit_surface::closest_point: no surface to project onto (the mesh has no face, "
                            "every face is a hole, or every sample of its faces is degenerate)");
    const internal::Projection_result r = projection_->closest(
      *this, CGAL::Simple_cartesian<double>::Point_3(CGAL::to_double(query.x()), CGAL::to_double(query.y()), CGAL::to_double(query.z())));
    Location location;
    location.face = projection_->tile(r.tile).face;
    const std::array<FT, 2> at =
      internal::Limit_projection<Limit_surface>::kernel_parameters(projection_->tile(r.tile), r.u, r.v);
    location.u = at[0];
    location.v = at[1];
    const Evaluation e = evaluate(location.face, location.u, location.v);
    location.point = e.point;
    location.normal = e.normal;
    location.squared_distance = CGAL::squared_distance(query, e.point);
    return location;
  }

  /// The number of patches face `f` is pieced from (built if not yet; 0 for a hole).
  std::size_t number_of_patches(Face_index f) const
  {
    if (is_hole(f))
      return 0;
    std::unique_ptr<Face_patches> spill;
    std::size_t n = 0;
    for (const auto& list : patches_of(f, spill).sub_faces)
      n += list.size();
    return n;
  }

  /// The bytes of the patches kept so far (their arrays, as counted against
  /// `Limit_surface_options::max_cache_bytes`; numbers of an exact kernel
  /// may hold more memory of their own).
  std::size_t cached_bytes() const { return faces_.bytes(); }

  /// \brief a mesh of the limit surface sampled uniformly at `rate`
  /// samples per base edge, laid out in each base face as OpenSubdiv's
  /// `Bfr::Tessellation` lays it out at that uniform rate with quads
  /// preserved, and watertight by construction.
  ///
  /// A quad becomes `rate` × `rate` quads, sample (i, j) at parameter
  /// (i / rate, j / rate). A face of n ≠ 4 sides holds in each sub-face k a
  /// grid of (M + 1)² samples, M = `rate` div 2, at sub-face parameters
  /// (2i / rate, 2j / rate); at an even rate these are M × M quads per
  /// sub-face meeting at the centre; at an odd rate a strip of M quads joins
  /// neighbouring sub-faces, and the centre is a triangle (n = 3) or a fan of
  /// n triangles round the face's centre point (so `rate` 1 fans an n-gon).
  /// Under `Loop_mask` a triangle becomes `rate`² triangles, sample (i, j)
  /// at parameter (i / rate, j / rate), i + j ≤ `rate` (Bfr's layout of a
  /// triangle).
  ///
  /// Shared samples are computed once: the limit point of each base vertex
  /// (`limit_point()` where no semi-sharp edge or sharpness is at it and,
  /// under `Catmull_clark_mask`, all faces around it are quads, else the
  /// evaluation at the corner of the first face that reaches it), the
  /// `rate` − 1 samples inside each base edge (evaluated from the first face
  /// that reaches it, reused in reverse order by the face across, in the
  /// same order across a Möbius edge), then each face's interior. Vertex i
  /// of the result, for i below the number of base vertices, is base vertex
  /// i (an isolated vertex keeps its point). Holes (`is_hole()`) have no
  /// facets: the base vertices that only holes reach are left out (the
  /// others come first, in their order), and where faces with a surface meet
  /// at a vertex only, between holes, the result has a copy of the vertex per
  /// further fan, after the others. Each facet keeps the
  /// orientation of its base face, so a Möbius edge stays a run of Möbius
  /// edges, borders stay borders and a one-sided surface stays one-sided.
  ///
  /// Normals (`du × dv` of unit length, the null vector where it vanishes):
  /// a vertex property `"v:normal"`, each seen from the orientation of the
  /// face that evaluated it, so consistent on a mesh without Möbius edges;
  /// where the base has Möbius edges also a halfedge property `"h:normal"`,
  /// for each halfedge of a face the normal at its target seen from that
  /// face's orientation (as `compute_corner_normals()` writes them), which
  /// is what a renderer wants on a one-sided surface.
  ///
  /// Corner channels (texture coordinates, corner normals) are carried,
  /// each sampled on its own limit surface (`Corner_channel_limit_surface`)
  /// at the same samples, with the constructor's `face_varying_interpolation`:
  /// a sample on a seam has a value per side.
  ///
  /// With `CGAL::Parallel_tag` (and TBB) the samples are evaluated and the
  /// mesh is built on the threads of the current task arena; the result is
  /// the serial one, bit for bit.
  /// \throws Parameter_error if `rate` is not positive, or a corner channel
  /// has values without a linear combination (before any work).
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  Mobius_mesh<P> tessellate(int rate) const
  {
    if (rate < 1)
      throw Parameter_error("Limit_surface::tessellate: the rate " + std::to_string(rate) + " is not positive");
    CGAL_ext::internal::require_interpolated_channels<FT>(base_.mesh, "Limit_surface::tessellate");
    return tessellate_at<ConcurrencyTag>(
      internal::Tessellation_rates::uniform(base_.mesh.number_of_edges(), base_.mesh.number_of_faces(), rate));
  }

  /// \brief a mesh of the limit surface whose rates are chosen from
  /// `tolerance` (a distance in the mesh's units): each base edge gets its
  /// own number of segments, each face its own inner rates (two for a quad,
  /// along u and v), as OpenSubdiv's `Bfr::Tessellation` takes them, so flat
  /// regions get few facets and curved ones many.
  ///
  /// An edge gets the fewest segments whose midpoints lie within `tolerance`
  /// of the surface (their distance found by two Newton steps from the
  /// limit curve's point halfway along each segment, kept in the face); a
  /// border edge the fewest whose border curve passes within `tolerance` of
  /// each segment at its middle. A face gets the larger of the inner rates
  /// Bfr infers from its edges' (the mean of opposite edges' for a quad, of
  /// all edges' for another face) and those at which the segments along
  /// its inner lines lie within `tolerance` (a quad's lines at 1/4, 1/2 and
  /// 3/4 each way, a Loop triangle's three mid-lines, the lines at 1/4, 1/2
  /// and 3/4 of each sub-face of another face); a quad with an inner rate of
  /// 1 one way and more the other gets 2. Every rate is found by doubling,
  /// then bisection, up to `Limit_surface_options::max_tessellation_rate`.
  /// The tolerance bounds segments, not facets: a facet's centre can lie off
  /// by the sum of its two directions' deviations (measured up to 2.6
  /// `tolerance`, see the manual).
  ///
  /// The samples of each face are those of `Bfr::Tessellation` at the same
  /// rates: `i` / N along an edge of rate N, and inside the face Bfr's grid
  /// at its inner rates (only its centre where an inner rate is 1, or at
  /// most 3 for a Loop triangle). A face whose edges and inner rates are all
  /// one rate is laid out as `tessellate()` lays it out at that rate; in
  /// another, the interior grid less its outermost ring of cells is joined to
  /// the samples of each edge by a strip of triangles. Shared samples, the
  /// normals, and the orientation of the facets are as in `tessellate()`:
  /// the result is watertight and a one-sided surface stays one-sided.
  /// Corner channels are carried as by `tessellate()`. With
  /// `CGAL::Parallel_tag` the rates are chosen, the samples evaluated and the
  /// mesh built on the task arena's threads, with the serial result.
  /// \throws Parameter_error if `tolerance` is not positive and finite, or
  /// a corner channel has values without a linear combination (before any work).
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  Mobius_mesh<P> tessellate_to_tolerance(double tolerance) const
  {
    if (!(tolerance > 0) || !std::isfinite(tolerance))
      throw Parameter_error("Limit_surface::tessellate_to_tolerance: the tolerance " + std::to_string(tolerance) +
                            " is not positive and finite");
    CGAL_ext::internal::require_interpolated_channels<FT>(base_.mesh, "Limit_surface::tessellate_to_tolerance");
    return tessellate_at<ConcurrencyTag>(
      internal::tolerance_rates<ConcurrencyTag>(*this, base_.mesh, tolerance, max_tessellation_rate_, is_loop));
  }

private:
  template <class ConcurrencyTag>
  Mobius_mesh<P> tessellate_at(const internal::Tessellation_rates& rates) const
  {
    const auto& m = base_.mesh;
    const auto np = CGAL_ext::parameters::boundary_interpolation(options_.boundary);
    // A base vertex's sample is limit_point() where that is the surface's
    // limit there, else the corner evaluation (Bfr's limit point):
    // limit_point() reads quad rings only (Catmull–Clark), and takes a
    // semi-sharp vertex's crease or corner rule at once where the surface
    // reaches it only after the sharpness has decayed (both schemes).
    const auto limit_point_is_the_limit = [&](Vertex_index v) {
      if (Crease::is_semi_sharp(base_.vertex_sharpness(v)))
        return false;
      for (Dart d : CGAL_ext::halfedges_around_target(m.halfedge(v), m))
        if (Crease::is_semi_sharp(base_.edge_sharpness(d)))
          return false;
      if constexpr (!is_loop) {
        for (Face_index g : CGAL_ext::faces_around_target(m.halfedge(v), m))
          if (g != Face_index() && m.degree(g) != 4)
            return false;
      }
      return true;
    };
    const auto corner_point = [&](Vertex_index v, Face_index, const P& evaluated) {
      return limit_point_is_the_limit(v) ? P(limit_point<Mask>(v, m, np)) : evaluated;
    };
    internal::Limit_tessellator<Limit_surface, P, decltype(corner_point)> tessellator(*this, m, rates, corner_point,
                                                                                     is_loop);
    Mobius_mesh<P> out = tessellator.template run<ConcurrencyTag>();
    if (!m.corner_channels().empty())
      carry_corner_channels<ConcurrencyTag>(
        rates, tessellator.facets(), [&](Vertex_index v) { return tessellator.sample_of(v); }, out);
    if (!holes_.empty())
      remove_vertices_of_holes(out);
    return out;
  }

  // The base vertices of the tessellation that only holes reach: isolated
  // there, not in the base.
  void remove_vertices_of_holes(Mobius_mesh<P>& out) const
  {
    const auto& m = base_.mesh;
    for (Vertex_index v : m.vertices())
      if (!m.is_isolated(v) && out.is_isolated(v))
        out.remove_vertex(v);
    out.collect_garbage();
  }

  // Each corner channel of the mesh on the tessellation: its limit surface
  // sampled where the mesh's is, each facet corner taking the value its
  // face sees there (so a seam stays a seam).
  template <class ConcurrencyTag, class SampleOf>
  void carry_corner_channels(const internal::Tessellation_rates& rates, const CGAL_ext::internal::Face_list& facets,
                             const SampleOf& sample_of, Mobius_mesh<P>& out) const
  {
    const auto& m = base_.mesh;
    const auto np = parameters::boundary_interpolation(options_.boundary)
                      .crease_method(options_.crease)
                      .triangle_subdivision(options_.triangles)
                      .face_varying_interpolation(fvar_mode_);
    for (const std::string& name : m.corner_channels()) {
      bool carried = false;
      CGAL_ext::internal::for_each_interpolated_channel_type<Kernel>([&](auto tag) {
        using T = typename decltype(tag)::type;
        if constexpr (CGAL_ext::internal::Channel_coordinates<Kernel, T>::defined) {
          if (carried || !m.template corner_channel<T>(name))
            return;
          carried = true;
          auto sampled = Corner_channel_limit_surface<Mask, P, T>(m, name, np, surface_options())
                           .template tessellated<ConcurrencyTag>(rates);
          const CGAL_ext::internal::Face_list& indices = sampled.first;
          std::vector<T>& values = sampled.second;
          auto channel = out.template add_corner_channel<T>(name).first;
          // The value index of each corner of facet f of the result.
          const auto for_each_corner = [&](std::uint32_t f, const auto& take) {
            const auto first = facets.vertex.begin() + facets.offset[f];
            const auto end = facets.vertex.begin() + facets.offset[f + 1];
            for (Dart d : CGAL_ext::halfedges_around_face(out.halfedge(Face_index(f)), out)) {
              const auto c = std::find(first, end, sample_of(out.target(d))) - facets.vertex.begin();
              take(d, indices.vertex[std::size_t(c)]);
            }
          };
          if (holes_.empty()) {
            channel.values() = std::move(values);
            const auto set_indices = [&](std::uint32_t f) {
              for_each_corner(f, [&](Dart d, std::uint32_t i) { channel.set_index(out.corner(d), i); });
            };
            CGAL_ext::internal::for_each_index<ConcurrencyTag>(std::uint32_t(out.number_of_faces()), set_indices);
            return;
          }
          // With holes, the channel's samples that only holes reach (cage
          // points, not values of its surface) are left out: the values are
          // kept in order of first use.
          constexpr std::uint32_t unused = std::uint32_t(-1);
          std::vector<std::uint32_t> kept(values.size(), unused);
          for (Face_index f : out.faces())
            for_each_corner(std::uint32_t(f.idx()), [&](Dart d, std::uint32_t i) {
              if (kept[i] == unused) {
                kept[i] = std::uint32_t(channel.values().size());
                channel.values().push_back(values[i]);
              }
              channel.set_index(out.corner(d), kept[i]);
            });
        }
      });
      if (!carried)
        // require_interpolated_channels() refused the others before the work.
        throw Parameter_error("Limit_surface::tessellate: internal error, corner channel \"" + name +
                              "\" has a value type without coordinates");
    }
  }

  // One allocation for a face whose single patch needs no refinement.
  struct Face_patches
  {
    typename internal::Patch_tree_builder<FT, P>::Sub_face_lists sub_faces;
  };

  template <class NP>
  void copy_sharpness(const Mobius_mesh<P>& mesh, const NP& np)
  {
    std::vector<float> es, vs;
    internal::gather_sharpness(mesh, np, es, vs);
    for (float s : es)
      if (!CGAL_ext::internal::is_valid_sharpness(s))
        throw Parameter_error("Limit_surface: a sharpness is NaN or negative");
    for (float s : vs)
      if (!CGAL_ext::internal::is_valid_sharpness(s))
        throw Parameter_error("Limit_surface: a sharpness is NaN or negative");
    if (!es.empty())
      base_.mesh.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first.data() = es;
    if (!vs.empty())
      base_.mesh.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first.data() = vs;
    base_.bind();
  }

  // The patches of f, kept or, past the cache's budget, made into `spill`.
  const Face_patches& patches_of(Face_index f, std::unique_ptr<Face_patches>& spill) const
  {
    // The inline storage is in sizeof(); the heap's where a list outgrew it
    // (counted whole where a list might be inline but hold more than its
    // nominal capacity: over, never under).
    const auto size_of = [](const Face_patches& p) {
      using Lists = decltype(p.sub_faces);
      using List = internal::Patch_list<FT>;
      std::size_t bytes = sizeof(Face_patches);
      if (p.sub_faces.capacity() > Lists::static_capacity)
        bytes += p.sub_faces.capacity() * sizeof(List);
      for (const List& list : p.sub_faces)
        if (list.capacity() > List::static_capacity)
          bytes += list.capacity() * sizeof(internal::Patch<FT>);
      return bytes;
    };
    return faces_.get(f.idx(), [&] {
      auto patches = std::make_unique<Face_patches>();
      const Dart d = base_.mesh.next(base_.mesh.halfedge(f)); // corner 0 -> corner 1
      if constexpr (is_loop) {
        patches->sub_faces.resize(1);
        internal::Loop_patch_tree_builder<FT, P>(options_, patches->sub_faces[0]).build(base_, d, internal::Patch<FT>());
      } else if (base_.mesh.degree(f) == 4) {
        patches->sub_faces.resize(1);
        internal::Patch_tree_builder<FT, P>(options_, patches->sub_faces[0]).build(base_, d, 0, 0.0, 0.0, 1.0);
      } else {
        internal::Patch_list<FT> unused;
        internal::Patch_tree_builder<FT, P>(options_, unused).build_sub_faces(base_, d, patches->sub_faces);
      }
      return patches;
    }, size_of, spill);
  }

  // A triangle's patch is found by Bfr's descent of its patch tree; the
  // patch's own (s, t) run against (u, v) where it is turned.
  // Whether (u, v) lies outside the triangle (0, 0), (1, 0), (0, 1); in
  // floating point, u + v may pass 1 by rounding (1 - t and t summed).
  static bool outside_triangle(const FT& u, const FT& v)
  {
    const FT excess = u + v - FT(1);
    const bool beyond = excess > FT(0) && !(std::is_floating_point_v<FT> && CGAL::to_double(excess) <= 4e-16);
    return u < FT(0) || v < FT(0) || beyond;
  }

  Evaluation evaluate_triangle(Face_index f, const internal::Patch_list<FT>& patches, const FT& u,
                               const FT& v) const
  {
    if (outside_triangle(u, v))
      throw Parameter_error("Limit_surface::evaluate: (u, v) lies outside the parameter domain of face f" +
                            std::to_string(f.idx()));
    unsigned depth = 0;
    for (const auto& patch : patches)
      depth = std::max(depth, patch.depth);
    const std::uint64_t path = internal::triangle_path(u, v, depth);
    for (const auto& patch : patches) {
      const std::uint64_t mask = patch.depth == 0 ? 0 : (~std::uint64_t(0) >> (64 - 2 * patch.depth));
      if ((path & mask) != patch.path)
        continue;
      const FT sign(patch.rotated ? -1 : 1), size(patch.size);
      const FT s = sign * (u - FT(patch.u0)) / size, t = sign * (v - FT(patch.v0)) / size;
      return finish(internal::evaluate_patch(patch, s, t), sign / size);
    }
    throw Parameter_error("Limit_surface: internal error, no patch at a parameter of face f" + std::to_string(f.idx()));
  }

  // An evaluation in other parameters (s, t) of the face, related by the
  // constant Jacobian J = [∂u/∂s, ∂u/∂t, ∂v/∂s, ∂v/∂t]: the derivatives by
  // the chain rule, the normal that of the new ones.
  static Evaluation in_frame(const Evaluation& e, const std::array<FT, 4>& J)
  {
    Evaluation r = e;
    r.du = e.du * J[0] + e.dv * J[2];
    r.dv = e.du * J[1] + e.dv * J[3];
    r.duu = e.duu * (J[0] * J[0]) + e.duv * (FT(2) * J[0] * J[2]) + e.dvv * (J[2] * J[2]);
    r.duv = e.duu * (J[0] * J[1]) + e.duv * (J[0] * J[3] + J[2] * J[1]) + e.dvv * (J[2] * J[3]);
    r.dvv = e.duu * (J[1] * J[1]) + e.duv * (FT(2) * J[1] * J[3]) + e.dvv * (J[3] * J[3]);
    set_normal(r);
    return r;
  }

  // The unit normal du × dv, null where du and dv are parallel to rounding
  // (at some corners of faces that are not quads), where its direction is noise.
  static void set_normal(Evaluation& e)
  {
    const typename Kernel::Vector_3 n = CGAL::cross_product(e.du, e.dv);
    const double length = std::sqrt(CGAL::to_double(n.squared_length()));
    const double parallel = 1e-10 * std::sqrt(CGAL::to_double(e.du.squared_length() * e.dv.squared_length()));
    e.normal = length > parallel && length > 0 ? n / FT(length) : CGAL::NULL_VECTOR;
  }

  Evaluation finish(const internal::Patch_value<FT>& r, const FT& scale) const
  {
    auto vec = [](const internal::Coordinates<FT>& c, const FT& s) {
      return typename Kernel::Vector_3(c[0] * s, c[1] * s, c[2] * s);
    };
    Evaluation e;
    e.point = typename Kernel::Point_3(r.p[0], r.p[1], r.p[2]);
    e.du = vec(r.ds, scale);
    e.dv = vec(r.dt, scale);
    const FT s2 = scale * scale;
    e.duu = vec(r.dss, s2);
    e.duv = vec(r.dst, s2);
    e.dvv = vec(r.dtt, s2);
    set_normal(e);
    return e;
  }

  // The options this surface was made with, as the constructor took them
  // (the channels' surfaces are made alike).
  Limit_surface_options surface_options() const
  {
    Limit_surface_options o;
    o.approx_level_smooth = options_.level_smooth;
    o.approx_level_sharp = options_.level_sharp;
    o.projection_rate = unsigned(projection_rate_);
    o.max_tessellation_rate = unsigned(max_tessellation_rate_);
    o.max_cache_bytes = faces_.budget();
    return o;
  }

  internal::Level_mesh<P> base_;
  internal::Limit_options options_;
  Face_varying_interpolation fvar_mode_ = Face_varying_interpolation::corners_plus1;
  internal::Face_cache<Face_patches> faces_;
  std::vector<bool> holes_; // by face index; empty unless the boundary interpolation is none
  int projection_rate_ = 4;
  int max_tessellation_rate_ = 64;
  mutable std::unique_ptr<internal::Limit_projection<Limit_surface>> projection_;
  std::unique_ptr<std::once_flag> projection_once_ = std::make_unique<std::once_flag>();
};

/// \ingroup PkgSubdivision
/// \brief the limit surface of `mesh` under `Mask` (`Catmull_clark_mask` or
/// `Loop_mask`) tessellated uniformly at `rate` samples per base edge:
/// `Limit_surface<Mask, P>(mesh, np, options).tessellate(rate)` (see there
/// for the layout, the watertightness and the normals).
/// With `ConcurrencyTag` `CGAL::Parallel_tag`, in parallel (the same mesh).
/// \throws Parameter_error as the constructor of `Limit_surface` and
/// `Limit_surface::tessellate()`.
template <class Mask, class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NP = parameters::Default_named_parameters>
Mobius_mesh<P> tessellate(const Mobius_mesh<P>& mesh, int rate, const NP& np = parameters::default_values(),
                          const Limit_surface_options& options = Limit_surface_options())
{
  return Limit_surface<Mask, P>(mesh, np, options).template tessellate<ConcurrencyTag>(rate);
}

/// \ingroup PkgSubdivision
/// \brief the limit surface of `mesh` under `Mask` (`Catmull_clark_mask` or
/// `Loop_mask`) tessellated with rates chosen so that it lies within about
/// `tolerance` of the surface:
/// `Limit_surface<Mask, P>(mesh, np, options).tessellate_to_tolerance(tolerance)`
/// (see there for the rates and the layout).
/// With `ConcurrencyTag` `CGAL::Parallel_tag`, in parallel (the same mesh).
/// \throws Parameter_error as the constructor of `Limit_surface` and
/// `Limit_surface::tessellate_to_tolerance()`.
template <class Mask, class ConcurrencyTag = CGAL::Sequential_tag, class P,
          class NP = parameters::Default_named_parameters>
Mobius_mesh<P> tessellate_to_tolerance(const Mobius_mesh<P>& mesh, double tolerance,
                                       const NP& np = parameters::default_values(),
                                       const Limit_surface_options& options = Limit_surface_options())
{
  return Limit_surface<Mask, P>(mesh, np, options).template tessellate_to_tolerance<ConcurrencyTag>(tolerance);
}

/// \ingroup PkgSubdivision
/// \brief the point of `surface` closest to `query`:
/// `surface.closest_point(query)` (see there). Keep the surface to ask for
/// many points: its search structure is built once.
template <class Mask, class P>
Limit_surface_location<typename Limit_surface<Mask, P>::Kernel>
closest_point_on_limit(const Limit_surface<Mask, P>& surface, const P& query)
{
  return surface.closest_point(query);
}

/// \ingroup PkgSubdivision
/// \brief the point of the limit surface of `mesh` under `Mask`
/// (`Catmull_clark_mask` or `Loop_mask`) closest to `query`:
/// `Limit_surface<Mask, P>(mesh, np, options).closest_point(query)`.
/// \throws Parameter_error as the constructor of `Limit_surface` and
/// `Limit_surface::closest_point()`.
template <class Mask, class P, class NP = parameters::Default_named_parameters>
Limit_surface_location<typename CGAL::Kernel_traits<P>::Kernel>
closest_point_on_limit(const Mobius_mesh<P>& mesh, const P& query, const NP& np = parameters::default_values(),
                       const Limit_surface_options& options = Limit_surface_options())
{
  return Limit_surface<Mask, P>(mesh, np, options).closest_point(query);
}

} // namespace Subdivision
} // namespace CGAL_ext

// The limit surfaces of corner channels, which tessellate() carries.
#include <CGAL_ext/Limit_surface/Corner_channel_limit_surface.h>

#endif // CGAL_EXT_LIMIT_SURFACE_H
