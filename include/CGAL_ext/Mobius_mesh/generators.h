// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shape generators, in the manner of CGAL's `make_*` helpers: Möbius strips
// and annuli with any number of half-twists, the figure-8 Klein bottle, Boy's
// surface (a projective plane) and the torus.

#ifndef CGAL_EXT_MOBIUS_MESH_GENERATORS_H
#define CGAL_EXT_MOBIUS_MESH_GENERATORS_H

#include <CGAL_ext/Mobius_mesh/internal/Shape_builders.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Mobius_mesh/transform.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshGenerators
/// \brief creates a twisted band — a Möbius strip for an odd number of
/// half-twists, an annulus for an even number — of `n_around` x `n_across`
/// quads (or twice as many triangles) and adds it to `mesh`.
///
/// Vertex (i, j), i < `n_around`, j <= `n_across`, lies at
/// ((R + s cos t) cos u, (R + s cos t) sin u, s sin t) with u = 2πi / `n_around`,
/// s = `width` (j / `n_across` - 1/2) and t = `half_twists` u / 2. After a
/// full turn, the last column of cells is welded, by index, to the first,
/// mirrored across the band when the number of half-twists is odd.
///
/// The band has V = `n_around` (`n_across` + 1) vertices,
/// E = `n_around` (2 `n_across` + 1) edges and F = `n_around` `n_across` quads,
/// Euler characteristic 0, one border loop of 2 `n_around` edges for an odd
/// number of half-twists and two loops of `n_around` edges for an even one.
/// Triangles split each quad along the diagonal from (i, j) to (i+1, j+1):
/// E = `n_around` (3 `n_across` + 1) and F = 2 `n_around` `n_across`.
/// Faces are oriented alike, so the only Möbius edges are the `n_across`
/// edges of the weld when the number of half-twists is odd.
///
/// \tparam P a point type of a CGAL kernel
/// \param mesh the mesh the band is appended to
/// \param n_around number of cells around the band, at least 3
/// \param n_across number of cells across the band, at least 1
/// \param half_twists number of half-twists (negative twists the other way)
/// \param radius radius of the centre circle, finite and > 0
/// \param width width of the band, finite and > 0
/// \param quads quads if `true`, triangles otherwise
///
/// \returns a border dart of the new band whose target is the vertex (0, 0).
/// \throws Parameter_error if a resolution is below its minimum, or a length
///   is not finite and positive; `Size_error` (a `Parameter_error`) if the new
///   part is too large for the index type or for the memory available;
///   `mesh` is then left unchanged.
template <class P>
Dart make_mobius_strip(Mobius_mesh<P>& mesh, std::size_t n_around, std::size_t n_across, int half_twists = 1,
                       double radius = 1.0, double width = 0.5, bool quads = true)
{
  const char* fn = "make_mobius_strip";
  internal::check_resolution(fn, "n_around", n_around, 3);
  internal::check_resolution(fn, "n_across", n_across, 1);
  internal::check_length(fn, "radius", radius);
  internal::check_length(fn, "width", width);
  internal::check_edge_count<P>(fn, mesh.num_edges(), n_around, n_across + 1, quads ? 2 : 3);
  const internal::Periodic_grid grid{n_around, n_across + 1, false, half_twists % 2 != 0};
  return internal::make_periodic_grid(mesh, grid, quads, [&](std::size_t i, std::size_t j) {
    const double u = 2 * internal::generator_pi * double(i) / double(n_around);
    const double s = width * (double(j) / double(n_across) - 0.5);
    const double t = double(half_twists) * u / 2;
    const double r = radius + s * std::cos(t);
    return std::array<double, 3>{r * std::cos(u), r * std::sin(u), s * std::sin(t)};
  });
}

/// \ingroup PkgMobiusMeshGenerators
/// \brief creates the figure-8 immersion of the Klein bottle with `nu` x `nv`
/// quads and adds it to `mesh`.
///
/// Vertex (i, j) lies at ((R + a) cos u, (R + a) sin u, sin(u/2) sin v + cos(u/2) sin 2v)
/// with a = cos(u/2) sin v - sin(u/2) sin 2v, u = 2πi / `nu`, v = 2π(j + 1/2) / `nv`.
/// The figure-8 cross-section turns half round over a full turn, so the last
/// column of quads is welded, by index, to the first mirrored (j -> `nv` - 1 - j).
/// The surface passes through itself; nothing is welded by position.
///
/// The result is closed and non-orientable with V = `nu` `nv`, E = 2 `nu` `nv`,
/// F = `nu` `nv` and Euler characteristic 0. Faces are oriented alike, so the
/// only Möbius edges are the `nv` edges of the weld.
///
/// \param mesh the mesh the Klein bottle is appended to
/// \param nu number of quads around the centre circle, at least 3
/// \param nv number of quads around the figure-8 cross-section, at least 3
/// \param radius radius of the centre circle, finite and > 0 (above 1.25, the
///   largest distance of the cross-section from the centre circle, the
///   surface stays clear of the axis)
///
/// \returns the unflipped dart of the first new face from vertex (0, 0) to vertex (1, 0).
/// \throws Parameter_error as `make_mobius_strip()` does; `mesh` is then left unchanged.
template <class P>
Dart make_klein_bottle(Mobius_mesh<P>& mesh, std::size_t nu, std::size_t nv, double radius = 2.0)
{
  const char* fn = "make_klein_bottle";
  internal::check_resolution(fn, "nu", nu, 3);
  internal::check_resolution(fn, "nv", nv, 3);
  internal::check_length(fn, "radius", radius);
  internal::check_edge_count<P>(fn, mesh.num_edges(), nu, nv, 2);
  const internal::Periodic_grid grid{nu, nv, true, true};
  return internal::make_periodic_grid(mesh, grid, true, [&](std::size_t i, std::size_t j) {
    const double u = 2 * internal::generator_pi * double(i) / double(nu);
    const double v = 2 * internal::generator_pi * (double(j) + 0.5) / double(nv);
    const double cu = std::cos(u / 2), su = std::sin(u / 2), sv = std::sin(v), s2v = std::sin(2 * v);
    const double r = radius + cu * sv - su * s2v;
    return std::array<double, 3>{r * std::cos(u), r * std::sin(u), su * sv + cu * s2v};
  });
}

/// \ingroup PkgMobiusMeshGenerators
/// \brief creates a torus of `nu` x `nv` quads, outward oriented, and adds it to `mesh`.
///
/// Vertex (i, j) lies at ((R + r cos v) cos u, (R + r cos v) sin u, r sin v)
/// with u = 2πi / `nu`, v = 2πj / `nv`. The result is closed and orientable
/// with V = `nu` `nv`, E = 2 `nu` `nv`, F = `nu` `nv`, Euler characteristic 0
/// and no Möbius edge.
///
/// \param mesh the mesh the torus is appended to
/// \param nu number of quads around the centre circle, at least 3
/// \param nv number of quads around the tube, at least 3
/// \param R radius of the centre circle, finite and > 0
/// \param r radius of the tube, finite and > 0
///
/// \returns the unflipped dart of the first new face from vertex (0, 0) to vertex (1, 0).
/// \throws Parameter_error as `make_mobius_strip()` does; `mesh` is then left unchanged.
template <class P>
Dart make_torus(Mobius_mesh<P>& mesh, std::size_t nu, std::size_t nv, double R = 2.0, double r = 0.7)
{
  const char* fn = "make_torus";
  internal::check_resolution(fn, "nu", nu, 3);
  internal::check_resolution(fn, "nv", nv, 3);
  internal::check_length(fn, "R", R);
  internal::check_length(fn, "r", r);
  internal::check_edge_count<P>(fn, mesh.num_edges(), nu, nv, 2);
  const internal::Periodic_grid grid{nu, nv, true, false};
  return internal::make_periodic_grid(mesh, grid, true, [&](std::size_t i, std::size_t j) {
    const double u = 2 * internal::generator_pi * double(i) / double(nu);
    const double v = 2 * internal::generator_pi * double(j) / double(nv);
    const double q = R + r * std::cos(v);
    return std::array<double, 3>{q * std::cos(u), q * std::sin(u), r * std::sin(v)};
  });
}

/// \ingroup PkgMobiusMeshGenerators
/// \brief creates a real projective plane as Boy's surface, with 3 `k`²
/// quads, and adds it to `mesh`.
///
/// The projective plane is the unit disk with antipodal points of its border
/// identified. The disk is cut into three sectors of 120° from its centre,
/// each meshed by a `k` x `k` grid of quads (a Coons patch bounded by two
/// radii and two arcs of 60°); the 6 `k` border vertices are welded, by index,
/// to their antipodes. Bryant and Kusner's parametrization (Kusner, 1987)
/// maps the disk onto Boy's surface, an immersion with three-fold symmetry
/// whose centre point lies at (0, 0, -2).
///
/// The result is closed and non-orientable with V = 3 `k`² + 1,
/// E = 6 `k`², F = 3 `k`² and Euler characteristic 1; for `k` = 1 it is the
/// hemi-cube (4 vertices, 6 edges, 3 quads). Faces are oriented alike in the
/// disk, so the only Möbius edges are the 3 `k` welded border edges.
///
/// \param mesh the mesh the surface is appended to
/// \param k number of quads along each side of a sector, at least 1
///
/// \returns the unflipped dart of the first new face from the centre vertex.
/// \throws Parameter_error if `k` is 0; `Size_error` if it is too large for the
///   index type or for the memory available; `mesh` is then left unchanged.
template <class P>
Dart make_projective_plane(Mobius_mesh<P>& mesh, std::size_t k)
{
  const char* fn = "make_projective_plane";
  internal::check_resolution(fn, "k", k, 1);
  internal::check_edge_count<P>(fn, mesh.num_edges(), k, k, 6);
  using Complex = std::complex<double>;
  const double pi = internal::generator_pi;

  // Canonical keys of the sector-grid points (s, i, j), i along the sector's
  // first radius, j along its second: the centre, the three radii (shared by
  // neighbouring sectors), the border (3k vertices after the antipodal
  // weld), then the interior points of each sector.
  const std::size_t n_border = 3 * k;
  const std::size_t radius_base = 1, border_base = radius_base + 3 * (k - 1),
                    interior_base = border_base + n_border;
  const std::size_t n_keys = interior_base + 3 * (k - 1) * (k - 1);
  auto key = [&](std::size_t s, std::size_t i, std::size_t j) -> std::size_t {
    if (i == k || j == k) {
      // Border position m of 6k, counter-clockwise from sector 0's first radius.
      const std::size_t m = (i == k ? 2 * k * s + j : 2 * k * (s + 1) - i) % (6 * k);
      return border_base + m % n_border;
    }
    if (i == 0 && j == 0)
      return 0;
    if (j == 0)
      return radius_base + s * (k - 1) + (i - 1);
    if (i == 0)
      return radius_base + ((s + 1) % 3) * (k - 1) + (j - 1);
    return interior_base + (s * (k - 1) + (i - 1)) * (k - 1) + (j - 1);
  };
  // Point of the disk at (s, i, j): a Coons patch on the sector, exact on
  // its two radii and its two border arcs.
  auto disk_point = [&](std::size_t s, std::size_t i, std::size_t j) -> Complex {
    const double a = double(i) / double(k), b = double(j) / double(k);
    const double alpha = 2 * pi * double(s) / 3;
    const Complex e0 = std::polar(1.0, alpha), e1 = std::polar(1.0, alpha + 2 * pi / 3),
                  mid = std::polar(1.0, alpha + pi / 3);
    const Complex side_b0 = a * e0, side_a0 = b * e1;
    const Complex side_a1 = std::polar(1.0, alpha + b * pi / 3), side_b1 = std::polar(1.0, alpha + 2 * pi / 3 - a * pi / 3);
    if (i == k)
      return side_a1;
    if (j == k)
      return side_b1;
    const Complex bilinear = a * (1 - b) * e0 + (1 - a) * b * e1 + a * b * mid;
    return (1 - a) * side_a0 + a * side_a1 + (1 - b) * side_b0 + b * side_b1 - bilinear;
  };

  std::vector<std::uint32_t> vertex_of_key(n_keys, std::numeric_limits<std::uint32_t>::max());
  std::vector<P> points;
  points.reserve(3 * k * k + 1);
  auto vertex = [&](std::size_t s, std::size_t i, std::size_t j) {
    std::uint32_t& v = vertex_of_key[key(s, i, j)];
    if (v == std::numeric_limits<std::uint32_t>::max()) {
      v = std::uint32_t(points.size());
      const std::array<double, 3> c = internal::boy_surface_point(disk_point(s, i, j));
      points.push_back(internal::make_generator_point<P>(c[0], c[1], c[2]));
    }
    return v;
  };
  internal::Face_list faces;
  for (std::size_t s = 0; s < 3; ++s)
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = 0; j < k; ++j)
        faces.add({vertex(s, i, j), vertex(s, i + 1, j), vertex(s, i + 1, j + 1), vertex(s, i, j + 1)});

  const Face_index first_face(mesh.num_faces());
  internal::append_generated(mesh, points, faces);
  return mesh.halfedge(first_face);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_GENERATORS_H
