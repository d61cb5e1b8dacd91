// What the subdivision tests share: OpenSubdiv's regression shapes read with
// their tags, a mesh built from them with its sharpness, our levels by the
// refiner, the orientation double cover of a one-sided mesh, OpenSubdiv's
// levels of the same shape and the map from our vertices to its, a unit cube,
// and a mask of unequal weights.
#ifndef CGAL_EXT_TEST_SUBDIVISION_SHAPES_H
#define CGAL_EXT_TEST_SUBDIVISION_SHAPES_H

#include "opensubdiv_tags.h"
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

namespace subdivision_shapes {

namespace S = CGAL_ext::Subdivision;
using CGAL_ext::Boundary_interpolation;
using CGAL_ext::Crease_method;
using CGAL_ext::Triangle_subdivision;
using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using V3 = S::internal::Vec3;
using Level = S::internal::Level;

// ----------------------------------------------------------------- shapes

// An OBJ file with OpenSubdiv's tags.
struct Shape : test::Osd_tags
{
  std::vector<Point> points;
  std::vector<std::vector<int>> faces;
};

inline Shape read_shape(const std::string& file)
{
  Shape s;
  const bool opened = test::read_obj_lines(
    file, [&](double x, double y, double z) { s.points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& f) { s.faces.emplace_back(f.begin(), f.end()); },
    [&](const std::string& tag, const std::string&, std::istream& ls) {
      if (tag == "t")
        s.read(ls);
    });
  EXPECT_TRUE(opened) << file;
  return s;
}

inline CGAL_ext::Edge_index find_edge(const Mesh& m, int a, int b)
{
  for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(CGAL_ext::Vertex_index(b), m))
    if (m.source(d) == CGAL_ext::Vertex_index(a))
      return m.edge(d);
  ADD_FAILURE() << "no edge " << a << "-" << b;
  return CGAL_ext::Edge_index();
}

struct Built
{
  Mesh mesh;
  std::vector<float> edge_sharpness, vertex_sharpness;
};

inline Built build(const Shape& s)
{
  Built b;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, b.mesh);
  EXPECT_TRUE(b.mesh.is_valid(true));
  EXPECT_EQ(b.mesh.number_of_vertices(), s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) // import keeps the soup's vertex order
    EXPECT_EQ(b.mesh.point(CGAL_ext::Vertex_index(i)), s.points[i]);
  b.edge_sharpness.assign(b.mesh.number_of_edges(), 0.0f);
  b.vertex_sharpness.assign(b.mesh.number_of_vertices(), 0.0f);
  for (std::size_t i = 0; i < s.crease_pairs.size(); ++i)
    b.edge_sharpness[find_edge(b.mesh, s.crease_pairs[i][0], s.crease_pairs[i][1]).idx()] = s.crease_values[i];
  for (std::size_t i = 0; i < s.corners.size(); ++i)
    b.vertex_sharpness[s.corners[i]] = s.corner_values[i];
  return b;
}

// Our levels 0..n, by the refiner, level by level.
template <class Mask>
std::vector<std::vector<V3>> our_levels(S::Refiner<Mask>& r, const Built& b, unsigned n)
{
  r.refine(b.mesh, n, b.edge_sharpness, b.vertex_sharpness);
  std::vector<std::vector<V3>> levels(n + 1);
  for (const Point& p : b.mesh.points().data())
    levels[0].push_back({p.x(), p.y(), p.z()});
  for (unsigned k = 0; k < n; ++k) {
    levels[k + 1].resize(r.level_size(k + 1).vertices);
    r.interpolate_level(k, levels[k].data(), levels[k + 1].data());
  }
  return levels;
}

// The orientation double cover: two copies of each face, one per
// orientation, glued so that the cover is orientable. Vertex v has the twins
// 2v and 2v+1; the sheet of a face at v is whether the face runs against the
// walk around v.
inline Shape double_cover(const Mesh& m, const Built& b, Shape* tags = nullptr)
{
  Shape c;
  for (const Point& p : m.points().data()) {
    c.points.push_back(p);
    c.points.push_back(p);
  }
  std::vector<std::vector<std::pair<int, int>>> sheet(m.number_of_faces()); // (vertex, sheet)
  for (CGAL_ext::Vertex_index v : m.vertices())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(v, m))
      if (!m.is_border(d))
        sheet[m.face(d).idx()].push_back({int(v.idx()), d.is_flipped() ? 1 : 0});
  auto sheet_of = [&](CGAL_ext::Face_index f, int v) {
    for (auto [w, s] : sheet[f.idx()])
      if (w == v)
        return s;
    ADD_FAILURE();
    return 0;
  };
  for (CGAL_ext::Face_index f : m.faces()) {
    std::vector<int> vs;
    for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m))
      vs.push_back(int(v.idx()));
    for (int sigma : {0, 1}) {
      std::vector<int> face;
      for (int v : vs)
        face.push_back(2 * v + (sigma ^ sheet_of(f, v)));
      if (sigma)
        std::reverse(face.begin(), face.end());
      c.faces.push_back(face);
    }
  }
  if (tags) { // both twins of a sharp edge or vertex are sharp
    std::set<std::pair<int, int>> cover_edges;
    for (const auto& f : c.faces)
      for (std::size_t i = 0; i < f.size(); ++i)
        cover_edges.insert(std::minmax(f[i], f[(i + 1) % f.size()]));
    for (CGAL_ext::Edge_index e : m.edges()) {
      if (b.edge_sharpness[e.idx()] <= 0.0f)
        continue;
      const int a = int(m.vertex(e, 0).idx()), bb = int(m.vertex(e, 1).idx());
      int twins = 0;
      for (int i : {0, 1})
        for (int j : {0, 1})
          if (cover_edges.count(std::minmax(2 * a + i, 2 * bb + j))) {
            tags->crease_pairs.push_back({2 * a + i, 2 * bb + j});
            tags->crease_values.push_back(b.edge_sharpness[e.idx()]);
            ++twins;
          }
      EXPECT_EQ(twins, 2);
    }
    for (CGAL_ext::Vertex_index v : m.vertices())
      if (b.vertex_sharpness[v.idx()] > 0.0f)
        for (int i : {0, 1}) {
          tags->corners.push_back(2 * int(v.idx()) + i);
          tags->corner_values.push_back(b.vertex_sharpness[v.idx()]);
        }
  }
  return c;
}

// ----------------------------------------------------------------- OpenSubdiv

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

struct Osd_vertex
{
  double p[3];
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0.0; }
  void AddWithWeight(const Osd_vertex& s, double w)
  {
    for (int i = 0; i < 3; ++i)
      p[i] += w * s.p[i];
  }
};

struct Osd_run
{
  std::unique_ptr<Far::TopologyRefiner> refiner;
  std::vector<std::vector<Osd_vertex>> levels;
};

// `tags` gives the options; creases and corners come from `tags` too, unless
// it has none and `sharp` does.
inline Osd_run run_opensubdiv(const Shape& s, const Shape& tags, Sdc::SchemeType type, int n)
{
  std::vector<int> sizes, indices;
  for (const auto& f : s.faces) {
    sizes.push_back(int(f.size()));
    indices.insert(indices.end(), f.begin(), f.end());
  }
  const std::vector<int> crease_indices = tags.crease_indices();
  Far::TopologyDescriptor desc;
  desc.numVertices = int(s.points.size());
  desc.numFaces = int(s.faces.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  desc.numCreases = int(tags.crease_pairs.size());
  desc.creaseVertexIndexPairs = crease_indices.data();
  desc.creaseWeights = tags.crease_values.data();
  desc.numCorners = int(tags.corners.size());
  desc.cornerVertexIndices = tags.corners.data();
  desc.cornerWeights = tags.corner_values.data();

  const Sdc::Options options = test::opensubdiv_options(tags);
  Osd_run run;
  run.refiner.reset(Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
    desc, Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(type, options)));
  Far::TopologyRefiner::UniformOptions uniform(n);
  uniform.fullTopologyInLastLevel = true; // the limit masks read the last level's rings
  run.refiner->RefineUniform(uniform);
  run.levels.resize(n + 1);
  for (const Point& p : s.points)
    run.levels[0].push_back({{p.x(), p.y(), p.z()}});
  Far::PrimvarRefinerReal<double> primvar(*run.refiner);
  for (int k = 1; k <= n; ++k) {
    run.levels[k].resize(run.refiner->GetLevel(k).GetNumVertices());
    Osd_vertex* src = run.levels[k - 1].data();
    Osd_vertex* dst = run.levels[k].data();
    primvar.Interpolate(k, src, dst);
  }
  return run;
}

using Vertex_map = std::vector<std::vector<int>>; // our vertex -> OpenSubdiv vertices

// Our child layout [vertex points | edge points | face points] mapped to
// OpenSubdiv's children through its parent-to-child queries.
inline Vertex_map child_map(const Level& p, const Vertex_map& m, const Far::TopologyLevel& o, bool quad)
{
  std::vector<int> back(o.GetNumVertices(), -1);
  for (std::size_t v = 0; v < m.size(); ++v)
    for (int x : m[v])
      back[x] = int(v);
  Vertex_map c(p.nv + p.ne + (quad ? p.nf : 0));
  for (std::uint32_t v = 0; v < p.nv; ++v)
    for (int x : m[v])
      c[v].push_back(o.GetVertexChildVertex(x));
  for (std::uint32_t e = 0; e < p.ne; ++e) {
    const std::uint32_t a = p.source(4 * e), b = p.h_target[2 * e];
    for (int x : m[a])
      for (int y : m[b]) {
        const int oe = o.FindEdge(x, y);
        if (oe >= 0)
          c[p.nv + e].push_back(o.GetEdgeChildVertex(oe));
      }
  }
  if (quad) {
    for (std::uint32_t f = 0; f < p.nf; ++f) {
      std::vector<int> ours;
      for (std::uint32_t k = p.f_offset[f]; k < p.f_offset[f + 1]; ++k)
        ours.push_back(int(p.h_target[p.corner_h[k]]));
      std::sort(ours.begin(), ours.end());
      for (int x : m[ours[0]]) {
        const auto faces = o.GetVertexFaces(x);
        for (int i = 0; i < faces.size(); ++i) {
          const auto fv = o.GetFaceVertices(faces[i]);
          std::vector<int> theirs;
          for (int j = 0; j < fv.size(); ++j)
            theirs.push_back(back[fv[j]]);
          std::sort(theirs.begin(), theirs.end());
          if (theirs == ours)
            c[p.nv + p.ne + f].push_back(o.GetFaceChildVertex(faces[i]));
        }
      }
    }
  }
  return c;
}

inline Vertex_map identity_map(std::size_t n)
{
  Vertex_map m(n);
  for (std::size_t i = 0; i < n; ++i)
    m[i] = {int(i)};
  return m;
}
#endif

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#define REQUIRE_OPENSUBDIV()
#else
#define REQUIRE_OPENSUBDIV() GTEST_SKIP() << "OpenSubdiv not found"
#endif

inline const std::vector<std::array<int, 3>> cube_points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
inline const std::vector<std::array<std::size_t, 4>> cube_quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                            {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

template <class K>
CGAL_ext::Mobius_mesh<typename K::Point_3> unit_cube()
{
  std::vector<typename K::Point_3> pts;
  for (const auto& p : cube_points)
    pts.emplace_back(p[0], p[1], p[2]);
  CGAL_ext::Mobius_mesh<typename K::Point_3> m;
  CGAL_ext::polygon_soup_to_mobius_mesh(pts, cube_quads, m);
  return m;
}

// A quad mask whose smooth vertex rule weights the neighbours, the face
// points and the new edge points apart: with `Sums` 3 the three weights
// differ, with 2 the last two are equal, so that the interpolation keeps
// three or two sums per vertex where the standard masks need one. The
// weights sum to 1: (n − 2)/n of the standard rule is here 1/2.
template <int Sums>
struct Unequal_weights_mask
{
  static constexpr S::Split split = S::Split::quad;
  static constexpr bool creases = true;
  template <class W>
  void smooth_edge(unsigned, unsigned, S::Edge_weights<W>& w) const
  {
    w.vertex = W(1) / W(4);
    w.face = W(1) / W(4);
  }
  template <class W>
  void smooth_vertex(unsigned n, S::Vertex_weights<W>& w) const
  {
    const W k = W(int(n));
    w.vertex = W(1) / W(2);
    w.edge = W(1) / (W(4) * k);
    w.face = W(Sums == 3 ? 3 : 2) / (W(16) * k);
    w.edge_point = W(Sums == 3 ? 1 : 2) / (W(16) * k);
  }
};

} // namespace subdivision_shapes

#endif
