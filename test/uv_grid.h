// A torus and a Möbius strip of triangles with texture coordinates of their
// closed forms (a corner channel cut where the grid wraps), and what the
// decimation and remeshing tests measure on them: how far each corner's
// value lies from its vertex, and the values at the seams.
#ifndef CGAL_EXT_TEST_UV_GRID_H
#define CGAL_EXT_TEST_UV_GRID_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace test {

template <class P>
std::array<double, 3> uv_grid_point(const P& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

// A surface of nu x nv grid cells split into triangles, with texture
// coordinates: each corner holds its grid node's parameter (i/nu, j/nv) taken
// along the face, so the channel is cut where the grid wraps. A torus of radii
// 2 and 1 (wrapping in u and v), or a Möbius strip of radius 1 and width 1
// (wrapping in u with a half-twist: node (nu, j) is node (0, nv - j)).
struct Uv_grid
{
  int nu, nv;
  bool torus;

  std::size_t vertex(int i, int j) const
  {
    if (torus)
      return std::size_t((i % nu) * nv + (j % nv));
    if (i == nu) {
      i = 0;
      j = nv - j;
    }
    return std::size_t(i * (nv + 1) + j);
  }
  // The closed form of the surface at parameter (u, v).
  std::array<double, 3> at(double u, double v) const
  {
    const double a = 2 * CGAL_PI * u;
    if (torus) {
      const double b = 2 * CGAL_PI * v;
      return {(2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b)};
    }
    const double s = v - 0.5, r = 1 + s * std::cos(a / 2);
    return {r * std::cos(a), r * std::sin(a), s * std::sin(a / 2)};
  }

  template <class P>
  CGAL_ext::Mobius_mesh<P> mesh() const
  {
    const int rows = torus ? nv : nv + 1;
    std::vector<P> points;
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < rows; ++j) {
        const auto x = at(double(i) / nu, double(j) / nv);
        points.emplace_back(x[0], x[1], x[2]);
      }
    std::vector<std::vector<std::size_t>> faces;
    std::vector<std::vector<std::pair<int, int>>> nodes; // of each face's corners
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
        for (const auto& t : {std::vector<std::pair<int, int>>{{i, j}, {i + 1, j}, {i + 1, j + 1}},
                              std::vector<std::pair<int, int>>{{i, j}, {i + 1, j + 1}, {i, j + 1}}}) {
          nodes.push_back(t);
          faces.push_back({});
          for (auto [a, b] : t)
            faces.back().push_back(vertex(a, b));
        }
    CGAL_ext::Mobius_mesh<P> m;
    CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
    auto uv = m.template add_corner_channel<CGAL_ext::Corner_uv<P>>(CGAL_ext::corner_uv_name).first;
    for (int i = 0; i <= nu; ++i)
      for (int j = 0; j <= nv; ++j)
        uv.add_value({double(i) / nu, double(j) / nv});
    // Face p is polygon p; a corner is found by its vertex.
    for (std::size_t p = 0; p < faces.size(); ++p)
      for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(CGAL_ext::Face_index(p)), m))
        for (std::size_t k = 0; k < 3; ++k)
          if (faces[p][k] == m.target(d).idx())
            uv.set_index(m.corner(d), std::uint32_t(nodes[p][k].first * (nv + 1) + nodes[p][k].second));
    return m;
  }
};

// How far the texture coordinates are from their vertices: the largest
// distance from a vertex to the closed form at a corner's value, and the
// largest difference between two corners of one face in the coordinates that
// wrap (u, and v on the torus): under a half unless a face spans a seam with
// values of both sides.
template <class P>
std::pair<double, double> uv_errors(const CGAL_ext::Mobius_mesh<P>& m, const Uv_grid& g)
{
  const auto uv = m.template corner_channel<CGAL_ext::Corner_uv<P>>(CGAL_ext::corner_uv_name);
  double distance = 0, span = 0;
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<std::array<double, 2>> corners;
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const auto& t = (*uv)[m.corner(d)];
      corners.push_back({CGAL::to_double(t.x()), CGAL::to_double(t.y())});
      const auto x = g.at(corners.back()[0], corners.back()[1]);
      const auto p = uv_grid_point(m.point(m.target(d)));
      distance = (std::max)(distance, std::sqrt(CGAL::square(x[0] - p[0]) + CGAL::square(x[1] - p[1]) +
                                                CGAL::square(x[2] - p[2])));
    }
    for (const auto& a : corners)
      for (const auto& b : corners)
        span = (std::max)({span, std::abs(a[0] - b[0]), g.torus ? std::abs(a[1] - b[1]) : 0.0});
  }
  return {distance, span};
}

// The values at each seam vertex (a vertex whose corners hold several
// indices), by its point: what decimation must keep as it was.
template <class P>
std::map<std::array<double, 3>, std::set<std::array<double, 2>>> seam_values(const CGAL_ext::Mobius_mesh<P>& m)
{
  const auto uv = m.template corner_channel<CGAL_ext::Corner_uv<P>>(CGAL_ext::corner_uv_name);
  std::map<std::array<double, 3>, std::set<std::array<double, 2>>> result;
  for (CGAL_ext::Vertex_index v : m.vertices()) {
    std::set<std::uint32_t> indices;
    std::set<std::array<double, 2>> values;
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(m.halfedge(v), m))
      if (!m.is_border(d)) {
        indices.insert(uv->index(m.corner(d)));
        values.insert({CGAL::to_double((*uv)[m.corner(d)].x()), CGAL::to_double((*uv)[m.corner(d)].y())});
      }
    if (indices.size() > 1)
      result[uv_grid_point(m.point(v))] = values;
  }
  return result;
}

} // namespace test

#endif // CGAL_EXT_TEST_UV_GRID_H
