// Subdivision: against OpenSubdiv 3.5 on its own regression shapes (levels
// 1-4, 1e-12), against OpenSubdiv on the orientation double cover for
// non-orientable meshes, against hand-computed rationals with an exact
// kernel, and topological invariants (Euler characteristic, border loops).
#include "test_util.h"

#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>
#include <CGAL_ext/Subdivision/limit.h>

#include <CGAL/Gmpq.h>

#include <gtest/gtest.h>

#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

namespace subdivision_tests {

namespace {

namespace S = CGAL_ext::Subdivision;
using CGAL_ext::Boundary_interpolation;
using CGAL_ext::Crease_method;
using CGAL_ext::Triangle_subdivision;
using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using V3 = S::internal::Vec3;
using Level = S::internal::Level;

// ----------------------------------------------------------------- shapes

// An OBJ file with OpenSubdiv's tags, read by a small local parser.
struct Shape
{
  std::vector<Point> points;
  std::vector<std::vector<int>> faces;
  std::vector<std::array<int, 2>> crease_pairs;
  std::vector<float> crease_values;
  std::vector<int> corners;
  std::vector<float> corner_values;
  Boundary_interpolation boundary = Boundary_interpolation::edge_only;
  Crease_method crease_method = Crease_method::uniform;
  Triangle_subdivision triangles = Triangle_subdivision::catmark;
};

Shape read_shape(const std::string& file)
{
  Shape s;
  const bool opened = test::read_obj_lines(
    file, [&](double x, double y, double z) { s.points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& f) { s.faces.emplace_back(f.begin(), f.end()); },
    [&](const std::string& tag, const std::string&, std::istream& ls) {
      if (tag != "t")
        return;
      std::string name, counts;
      ls >> name >> counts;
      int ni = 0, nf = 0, ns = 0;
      char sep;
      std::istringstream cs(counts);
      cs >> ni >> sep >> nf >> sep >> ns;
      std::vector<int> ints(ni);
      std::vector<float> floats(nf);
      std::vector<std::string> strings(ns);
      for (int& i : ints)
        ls >> i;
      for (float& f : floats)
        ls >> f;
      for (std::string& t : strings)
        ls >> t;
      if (name == "crease") {
        for (int i = 0; i + 1 < ni; i += 2) {
          s.crease_pairs.push_back({ints[i], ints[i + 1]});
          s.crease_values.push_back(nf == 1 ? floats[0] : floats[i / 2]);
        }
      } else if (name == "corner") {
        for (int i = 0; i < ni; ++i) {
          s.corners.push_back(ints[i]);
          s.corner_values.push_back(nf == 1 ? floats[0] : floats[i]);
        }
      } else if (name == "interpolateboundary") {
        s.boundary = ints[0] == 0 ? Boundary_interpolation::none
                                  : (ints[0] == 1 ? Boundary_interpolation::edge_and_corner
                                                  : Boundary_interpolation::edge_only);
      } else if (name == "creasemethod") {
        s.crease_method = strings[0] == "chaikin" ? Crease_method::chaikin : Crease_method::uniform;
      } else if (name == "smoothtriangles") {
        s.triangles = strings[0] == "smooth" ? Triangle_subdivision::smooth : Triangle_subdivision::catmark;
      }
    });
  EXPECT_TRUE(opened) << file;
  return s;
}

CGAL_ext::Edge_index find_edge(const Mesh& m, int a, int b)
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

Built build(const Shape& s)
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
    levels[k + 1].resize(r.level(k + 1).nv);
    r.interpolate_level(k, levels[k].data(), levels[k + 1].data());
  }
  return levels;
}

// The orientation double cover: two copies of each face, one per
// orientation, glued so that the cover is orientable. Vertex v has the twins
// 2v and 2v+1; the sheet of a face at v is whether the face runs against the
// walk around v.
Shape double_cover(const Mesh& m, const Built& b, Shape* tags = nullptr)
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
Osd_run run_opensubdiv(const Shape& s, const Shape& tags, Sdc::SchemeType type, int n)
{
  std::vector<int> sizes, indices;
  for (const auto& f : s.faces) {
    sizes.push_back(int(f.size()));
    indices.insert(indices.end(), f.begin(), f.end());
  }
  std::vector<int> crease_indices;
  for (const auto& p : tags.crease_pairs) {
    crease_indices.push_back(p[0]);
    crease_indices.push_back(p[1]);
  }
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

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(
    tags.boundary == Boundary_interpolation::none
      ? Sdc::Options::VTX_BOUNDARY_NONE
      : (tags.boundary == Boundary_interpolation::edge_only ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                                            : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER));
  options.SetCreasingMethod(tags.crease_method == Crease_method::chaikin ? Sdc::Options::CREASE_CHAIKIN
                                                                          : Sdc::Options::CREASE_UNIFORM);
  options.SetTriangleSubdivision(tags.triangles == Triangle_subdivision::smooth ? Sdc::Options::TRI_SUB_SMOOTH
                                                                                : Sdc::Options::TRI_SUB_CATMARK);
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
Vertex_map child_map(const Level& p, const Vertex_map& m, const Far::TopologyLevel& o, bool quad)
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

// Compares our levels with OpenSubdiv's; `twins` is 1, or 2 for a double cover.
template <class Mask>
void compare(const S::Refiner<Mask>& r, const std::vector<std::vector<V3>>& ours, const Osd_run& osd,
             Vertex_map map, std::size_t twins, double tolerance = 1e-12)
{
  const bool quad = Mask::split == S::Split::quad;
  for (std::size_t k = 0; k < ours.size(); ++k) {
    if (k > 0)
      map = child_map(r.level(unsigned(k - 1)), map, osd.refiner->GetLevel(int(k - 1)), quad);
    ASSERT_EQ(osd.levels[k].size(), twins * ours[k].size()) << "level " << k;
    ASSERT_EQ(osd.refiner->GetLevel(int(k)).GetNumFaces(), int(twins * r.level(unsigned(k)).nf));
    double worst = 0.0;
    std::size_t mapped = 0;
    for (std::size_t v = 0; v < ours[k].size(); ++v) {
      ASSERT_EQ(map[v].size(), twins) << "level " << k << " vertex " << v;
      for (int x : map[v]) {
        const double* q = osd.levels[k][x].p;
        const V3& p = ours[k][v];
        const double scale = std::max({1.0, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
        worst = std::max({worst, std::abs(p.x - q[0]) / scale, std::abs(p.y - q[1]) / scale,
                          std::abs(p.z - q[2]) / scale});
        ++mapped;
      }
    }
    EXPECT_EQ(mapped, osd.levels[k].size());
    EXPECT_LE(worst, tolerance) << "level " << k;
  }
}

Vertex_map identity_map(std::size_t n)
{
  Vertex_map m(n);
  for (std::size_t i = 0; i < n; ++i)
    m[i] = {int(i)};
  return m;
}

template <class Mask>
void check_shape(const Shape& s, Mask mask, Sdc::SchemeType type, int levels);

// One OpenSubdiv shape: ours against OpenSubdiv at levels 1-4 with the
// shape's own tags, possibly overridden.
template <class Mask>
void check_shape(const std::string& name, Mask mask, Sdc::SchemeType type, const Shape* override_tags = nullptr,
                 int levels = 4)
{
  SCOPED_TRACE(name);
  Shape s = read_shape(test::data("opensubdiv/" + name));
  if (override_tags) {
    s.boundary = override_tags->boundary;
    s.crease_method = override_tags->crease_method;
    s.triangles = override_tags->triangles;
  }
  check_shape(s, mask, type, levels);
}

template <class Mask>
void check_shape(const Shape& s, Mask mask, Sdc::SchemeType type, int levels)
{
  const Built b = build(s);
  S::Refinement_options options;
  options.boundary_interpolation = s.boundary;
  options.crease_method = s.crease_method;
  if constexpr (std::is_same_v<Mask, S::Catmull_clark_mask>)
    mask.triangle_subdivision = s.triangles;
  S::Refiner<Mask> r(mask, options);
  const auto ours = our_levels(r, b, unsigned(levels));
  const Osd_run osd = run_opensubdiv(s, s, type, levels);
  compare(r, ours, osd, identity_map(s.points.size()), 1);
  if (s.boundary == Boundary_interpolation::none) {
    for (int k = 0; k <= levels; ++k) {
      const Level& L = r.level(unsigned(k));
      int holes_ours = 0, holes_osd = 0;
      for (auto h : L.f_hole)
        holes_ours += h;
      for (int f = 0; f < osd.refiner->GetLevel(k).GetNumFaces(); ++f)
        holes_osd += osd.refiner->GetLevel(k).IsFaceHole(f) ? 1 : 0;
      EXPECT_EQ(holes_ours, holes_osd) << "level " << k;
    }
  }
}
#endif

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#define REQUIRE_OPENSUBDIV()
#else
#define REQUIRE_OPENSUBDIV() GTEST_SKIP() << "OpenSubdiv not found"
#endif

// ----------------------------------------------------------------- OpenSubdiv shapes

TEST(SubdivisionOpenSubdiv, CatmullClarkShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_cube.obj", "catmark_cube_corner4.obj", "catmark_cube_creases1.obj",
                           "catmark_chaikin1.obj", "catmark_edgecorner.obj", "catmark_nonquads.obj",
                           "catmark_pole64.obj", "catmark_smoothtris1.obj", "catmark_torus_creases1.obj"})
    check_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK);
#endif
}

TEST(SubdivisionOpenSubdiv, CatmullClarkOptionsOverridden)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (auto boundary :
       {Boundary_interpolation::none, Boundary_interpolation::edge_only, Boundary_interpolation::edge_and_corner})
    for (auto crease : {Crease_method::uniform, Crease_method::chaikin})
      for (const char* name : {"catmark_edgecorner.obj", "catmark_nonquads.obj", "catmark_torus_creases1.obj",
                               "catmark_chaikin1.obj", "catmark_cube_creases1.obj"}) {
        Shape o;
        o.boundary = boundary;
        o.crease_method = crease;
        o.triangles = Triangle_subdivision::smooth;
        check_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, &o, 3);
      }
#endif
}

TEST(SubdivisionOpenSubdiv, LoopShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"loop_tetrahedron.obj", "loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"})
    check_shape(name, S::Loop_mask(), Sdc::SCHEME_LOOP);
  Shape o;
  o.boundary = Boundary_interpolation::edge_and_corner;
  o.crease_method = Crease_method::chaikin;
  for (const char* name : {"loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"})
    check_shape(name, S::Loop_mask(), Sdc::SCHEME_LOOP, &o);
#endif
}

// A Chaikin crease of sharpness above 1 whose one half decays to 0 (a
// weaker semi-sharp edge at that end) and the other not: OpenSubdiv's
// refiner gives its edge point the smooth mask blended by the sharpness (the
// child point is a dart, not a crease), not the crease mask.
TEST(SubdivisionOpenSubdiv, ChaikinCreaseWithOneHalfDecayed)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  Shape s = read_shape(test::data("opensubdiv/catmark_cube.obj"));
  s.crease_method = Crease_method::chaikin;
  s.crease_pairs = {{0, 1}, {1, 3}, {4, 5}};
  s.crease_values = {1.2f, 0.2f, 1.5f};
  check_shape(s, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 3);
  s.crease_method = Crease_method::uniform;
  check_shape(s, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 3);
#endif
}

TEST(SubdivisionOpenSubdiv, BilinearShapes)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_nonquads.obj", "catmark_cube_creases1.obj", "catmark_edgecorner.obj"})
    check_shape(name, S::Bilinear_mask(), Sdc::SCHEME_BILINEAR, nullptr, 3);
#endif
}

// ----------------------------------------------------------------- non-orientable

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
template <class Mask>
void check_cover(const std::string& file, Mask mask, Sdc::SchemeType type, bool with_creases, int levels = 3)
{
  SCOPED_TRACE(file);
  const Shape s = read_shape(test::data(file));
  Built b = build(s);
  ASSERT_FALSE(CGAL_ext::is_orientable(b.mesh));
  if (with_creases) { // a semi-sharp and an infinitely sharp interior edge, one of them Möbius if any
    int placed = 0;
    for (CGAL_ext::Edge_index e : b.mesh.edges()) {
      if (b.mesh.is_border(e) || placed == 2)
        continue;
      if (placed == 0 && CGAL_ext::number_of_mobius_edges(b.mesh) > 0 && !b.mesh.is_mobius(e))
        continue;
      b.edge_sharpness[e.idx()] = placed == 0 ? 1.5f : 10.0f;
      ++placed;
    }
    b.vertex_sharpness[3] = 2.25f;
  }
  Shape tags;
  const Shape cover = double_cover(b.mesh, b, &tags);
  {
    Mesh cm;
    CGAL_ext::polygon_soup_to_mobius_mesh(cover.points, cover.faces, cm);
    EXPECT_TRUE(CGAL_ext::is_orientable(cm));
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(cm), 0u);
    EXPECT_EQ(CGAL_ext::connected_components(cm).count, CGAL_ext::connected_components(b.mesh).count);
    EXPECT_EQ(CGAL_ext::euler_characteristic(cm), 2 * CGAL_ext::euler_characteristic(b.mesh));
  }
  S::Refiner<Mask> r(mask);
  const auto ours = our_levels(r, b, unsigned(levels));
  const Osd_run osd = run_opensubdiv(cover, tags, type, levels);
  Vertex_map twins(s.points.size());
  for (std::size_t v = 0; v < twins.size(); ++v)
    twins[v] = {int(2 * v), int(2 * v + 1)};
  compare(r, ours, osd, twins, 2);
}
#endif

TEST(SubdivisionMobius, CatmullClarkMatchesOpenSubdivOnDoubleCover)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* f : {"nonorientable/mobius_20x4_quads.obj", "nonorientable/klein_fig8_24x12_quads.obj",
                        "nonorientable/boys_surface_quads.obj"}) {
    check_cover(f, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, false);
    check_cover(f, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, true);
  }
#endif
}

TEST(SubdivisionMobius, LoopMatchesOpenSubdivOnDoubleCover)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* f : {"nonorientable/mobius_20x4_tris.obj", "nonorientable/mobius_min_5tris.obj",
                        "nonorientable/rp2_hemi_icosahedron.obj"}) {
    check_cover(f, S::Loop_mask(), Sdc::SCHEME_LOOP, false);
    check_cover(f, S::Loop_mask(), Sdc::SCHEME_LOOP, true);
  }
#endif
}

// ----------------------------------------------------------------- limit

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
double relative_gap(const Point& p, const double* q)
{
  const double scale = std::max({1.0, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
  return std::max({std::abs(p.x() - q[0]), std::abs(p.y() - q[1]), std::abs(p.z() - q[2])}) / scale;
}
double relative_gap(const test::Kd::Vector_3& p, const double* q)
{
  return relative_gap(Point(p.x(), p.y(), p.z()), q);
}
std::array<double, 3> unit_cross(const double* a, const double* b)
{
  std::array<double, 3> c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for (double& x : c)
    x /= l;
  return c;
}

// The dart of `m` ending at `v` whose face holds the edges to `first` (leaving
// v, first in the walk) and from `second`: OpenSubdiv's first face of v.
CGAL_ext::Dart dart_of_first_face(const Mesh& m, CGAL_ext::Vertex_index v, CGAL_ext::Vertex_index first,
                                  CGAL_ext::Vertex_index second)
{
  for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(v, m))
    if (!m.is_border(d) && m.target(m.next(d)) == first && m.source(d) == second)
      return d;
  ADD_FAILURE() << "no face at v" << v.idx() << " from v" << first.idx() << " to v" << second.idx();
  return CGAL_ext::Dart();
}

// Our limit points, tangents and normals on level `k` of `b` against
// OpenSubdiv's Far::PrimvarRefiner::Limit() on level k of `osd_shape` (the
// shape itself, `map` the identity, or its double cover, `map` the twins).
// Tangents and normals are compared one for one on the shape itself, seen
// from OpenSubdiv's first face; on a double cover (no creases), the unit
// normal of limit_normals() at each vertex is one of its twins'.
template <class Mask>
void compare_limit(const Built& b, const Shape& osd_shape, const Shape& tags, Mask mask, Sdc::SchemeType type,
                   unsigned k, Vertex_map map)
{
  SCOPED_TRACE("level " + std::to_string(k));
  const bool quad = Mask::split == S::Split::quad;
  S::Refinement_options options;
  options.boundary_interpolation = tags.boundary;
  options.crease_method = tags.crease_method;
  S::Refiner<Mask> r(mask, options);
  const auto ours = our_levels(r, b, k);
  const Osd_run osd = run_opensubdiv(osd_shape, tags, type, int(k));
  for (unsigned j = 0; j < k; ++j)
    map = child_map(r.level(j), map, osd.refiner->GetLevel(int(j)), quad);
  Mesh m;
  r.build_mesh(m, true);
  for (CGAL_ext::Vertex_index v : m.vertices())
    m.point(v) = Point(ours[k][v.idx()].x, ours[k][v.idx()].y, ours[k][v.idx()].z);

  const std::size_t n = osd.levels[k].size();
  std::vector<Osd_vertex> position(n), tangent1(n), tangent2(n);
  Far::PrimvarRefinerReal<double>(*osd.refiner).Limit(osd.levels[k], position, tangent1, tangent2);
  const auto np = CGAL_ext::parameters::boundary_interpolation(tags.boundary);
  auto limit = m.add_property_map<CGAL_ext::Vertex_index, Point>("v:limit", Point(0, 0, 0)).first;
  S::limit_points<Mask>(m, limit, np);
  using Vector = test::Kd::Vector_3;
  auto normal = m.add_property_map<CGAL_ext::Vertex_index, Vector>("v:limit_normal", Vector(0, 0, 0)).first;
  S::limit_normals<Mask>(m, normal, np.normalize(true));

  const Far::TopologyLevel& level = osd.refiner->GetLevel(int(k));
  std::vector<int> back(n, -1);
  for (std::size_t v = 0; v < map.size(); ++v)
    for (int x : map[v])
      back[x] = int(v);
  double worst_point = 0, worst_tangent = 0, worst_normal = 0;
  for (CGAL_ext::Vertex_index v : m.vertices()) {
    for (int x : map[v.idx()])
      worst_point = std::max(worst_point, relative_gap(limit[v], position[x].p));
    const int x = map[v.idx()][0];
    if (level.GetVertexFaces(x).size() == 0)
      continue;
    if (map[v.idx()].size() == 1) {
      auto other_end = [&](int e) {
        const auto ev = level.GetEdgeVertices(level.GetVertexEdges(x)[e]);
        return CGAL_ext::Vertex_index(back[ev[0] == x ? ev[1] : ev[0]]);
      };
      const CGAL_ext::Dart d = dart_of_first_face(m, v, other_end(0), other_end(1));
      const auto t = S::limit_tangents<Mask>(d, m, np);
      worst_tangent = std::max({worst_tangent, relative_gap(t.tangent1, tangent1[x].p),
                                relative_gap(t.tangent2, tangent2[x].p)});
      // A crease vertex has a normal on each side of the crease: the one of
      // the span the walk from OpenSubdiv's first edge meets first.
      const auto o = unit_cross(tangent1[x].p, tangent2[x].p);
      worst_normal = std::max(worst_normal, relative_gap(S::limit_normal<Mask>(d, m, np.normalize(true)), o.data()));
      continue;
    }
    double gap = 2.0; // on a double cover: one of the two twins' normals
    for (int y : map[v.idx()]) {
      const auto o = unit_cross(tangent1[y].p, tangent2[y].p);
      gap = std::min(gap, relative_gap(normal[v], o.data()));
    }
    worst_normal = std::max(worst_normal, gap);
  }
  EXPECT_LE(worst_point, 1e-12);
  EXPECT_LE(worst_tangent, 1e-12);
  EXPECT_LE(worst_normal, 1e-11);
}

template <class Mask>
void check_limit_shape(const std::string& name, Mask mask, Sdc::SchemeType type, unsigned first_level)
{
  SCOPED_TRACE(name);
  const Shape s = read_shape(test::data("opensubdiv/" + name));
  const Built b = build(s);
  for (unsigned k = first_level; k <= 2; ++k)
    compare_limit(b, s, s, mask, type, k, identity_map(s.points.size()));
}
#endif

TEST(SubdivisionLimit, CatmullClarkMatchesOpenSubdiv)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"catmark_cube.obj", "catmark_cube_corner4.obj", "catmark_cube_creases1.obj",
                           "catmark_chaikin1.obj", "catmark_edgecorner.obj", "catmark_torus_creases1.obj"})
    check_limit_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 0);
  // Faces of other degrees: from level 1 on, where every face is a quad.
  for (const char* name : {"catmark_nonquads.obj", "catmark_pole64.obj"})
    check_limit_shape(name, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK, 1);
#endif
}

TEST(SubdivisionLimit, LoopMatchesOpenSubdiv)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* name : {"loop_tetrahedron.obj", "loop_icos_semisharp.obj", "loop_triangle_edgeonly.obj"})
    check_limit_shape(name, S::Loop_mask(), Sdc::SCHEME_LOOP, 0);
#endif
}

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// A one-sided surface against its orientation double cover: the same limit
// points, and each vertex's limit normal one of its twins'; the normal seen
// from the other side of a face is the opposite one.
template <class Mask>
void check_limit_cover(const std::string& file, Mask mask, Sdc::SchemeType type)
{
  SCOPED_TRACE(file);
  const Shape s = read_shape(test::data(file));
  const Built b = build(s);
  ASSERT_FALSE(CGAL_ext::is_orientable(b.mesh));
  Shape tags;
  const Shape cover = double_cover(b.mesh, b, &tags);
  Vertex_map twins(s.points.size());
  for (std::size_t v = 0; v < twins.size(); ++v)
    twins[v] = {int(2 * v), int(2 * v + 1)};
  for (unsigned k : {1u, 2u})
    compare_limit(b, cover, tags, mask, type, k, twins);

  Mesh m = b.mesh;
  S::catmull_clark(m); // a quad mesh either way; its Möbius edges are crossed below
  ASSERT_GT(CGAL_ext::number_of_mobius_edges(m), 0u);
  double worst = 0.0;
  const auto unit = CGAL_ext::parameters::normalize(true);
  for (CGAL_ext::Face_index f : m.faces())
    for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const auto n = S::limit_normal<S::Catmull_clark_mask>(d, m, unit);
      const auto other_side = S::limit_normal<S::Catmull_clark_mask>(m.next(d).flipped(), m, unit);
      worst = std::max(worst, std::sqrt(CGAL::to_double((n + other_side).squared_length())));
    }
  EXPECT_LE(worst, 1e-12);
}
#endif

TEST(SubdivisionLimit, OneSidedSurfacesMatchTheirDoubleCover)
{
  REQUIRE_OPENSUBDIV();
#ifdef CGAL_EXT_HAVE_OPENSUBDIV
  for (const char* f : {"nonorientable/mobius_20x4_quads.obj", "nonorientable/klein_fig8_24x12_quads.obj"})
    check_limit_cover(f, S::Catmull_clark_mask(), Sdc::SCHEME_CATMARK);
  check_limit_cover("nonorientable/mobius_20x4_tris.obj", S::Loop_mask(), Sdc::SCHEME_LOOP);
#endif
}

TEST(SubdivisionLimit, WrongFacesAndBorderDartsAreRefused)
{
  const Shape s = read_shape(test::data("opensubdiv/catmark_nonquads.obj"));
  Mesh mesh = build(s).mesh;
  const std::vector<Point> before(mesh.points().data().begin(), mesh.points().data().end());
  auto points = mesh.points(); // all are computed before any is written: none is, on failure
  EXPECT_THROW(S::limit_points<S::Catmull_clark_mask>(mesh, points), CGAL_ext::Parameter_error);
  EXPECT_THROW(S::limit_points<S::Loop_mask>(mesh, points), CGAL_ext::Parameter_error);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), mesh.points().data().begin()));
  // A sharpness that is no number of levels is refused, naming the element.
  Mesh quads;
  CGAL_ext::make_torus(quads, 6, 4);
  const std::vector<Point> quads_before(quads.points().data().begin(), quads.points().data().end());
  for (const bool on_edge : {true, false}) {
    Mesh m = quads;
    if (on_edge)
      CGAL_ext::edge_sharpness_map(m)[CGAL_ext::Edge_index(4)] = std::nanf("");
    else
      CGAL_ext::vertex_sharpness_map(m)[CGAL_ext::Vertex_index(6)] = -1.0f;
    auto m_points = m.points();
    try {
      S::limit_points<S::Catmull_clark_mask>(m, m_points);
      ADD_FAILURE() << "a NaN or negative sharpness was read";
    } catch (const CGAL_ext::Parameter_error& e) {
      EXPECT_NE(std::string(e.what()).find(on_edge ? "edge e4 " : "vertex v6 "), std::string::npos) << e.what();
    }
    EXPECT_TRUE(std::equal(quads_before.begin(), quads_before.end(), m.points().data().begin()));
  }
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 8, 2);
  for (CGAL_ext::Halfedge_index h : strip.halfedges())
    if (strip.is_border(h)) {
      EXPECT_THROW(S::limit_normal<S::Catmull_clark_mask>(CGAL_ext::Dart(h), strip), CGAL_ext::Parameter_error);
      break;
    }
}

Mesh load(const std::string& file)
{
  const Shape s = read_shape(test::data(file));
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(s.points, s.faces, m);
  return m;
}

TEST(SubdivisionMobius, TopologyIsKept)
{
  struct Case
  {
    const char* file;
    bool loop;
    long long chi;
    std::size_t borders;
  };
  for (const Case& c : {Case{"nonorientable/mobius_20x4_quads.obj", false, 0, 1},
                        Case{"nonorientable/mobius_min_5tris.obj", true, 0, 1},
                        Case{"nonorientable/mobius_min_5tris.obj", false, 0, 1},
                        Case{"nonorientable/klein_fig8_24x12_quads.obj", false, 0, 0},
                        Case{"nonorientable/rp2_hemi_icosahedron.obj", true, 1, 0}}) {
    SCOPED_TRACE(c.file);
    Mesh m = load(c.file);
    const std::size_t v0 = m.number_of_vertices(), e0 = m.number_of_edges(), f0 = m.number_of_faces();
    std::size_t corners = 0;
    for (CGAL_ext::Face_index f : m.faces())
      corners += m.degree(f);
    Mesh linear = m; // the midpoint split keeps the same counts as Loop's or Catmull-Clark's
    if (c.loop) {
      S::loop(m, CGAL_ext::parameters::number_of_iterations(2));
      S::linear(linear, CGAL_ext::parameters::number_of_iterations(2));
    } else {
      S::catmull_clark(m, CGAL_ext::parameters::number_of_iterations(2));
      S::bilinear(linear, CGAL_ext::parameters::number_of_iterations(2));
    }
    ASSERT_TRUE(linear.is_valid(true));
    EXPECT_EQ(CGAL_ext::euler_characteristic(linear), c.chi);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(linear), c.borders);
    EXPECT_FALSE(CGAL_ext::is_orientable(linear));
    EXPECT_EQ(linear.number_of_faces(), m.number_of_faces());
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), c.chi);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), c.borders);
    EXPECT_EQ(CGAL_ext::is_closed(m), c.borders == 0);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(CGAL_ext::connected_components(m).count, 1u);
    // Counts after one step, from the split alone: Loop V+E, 2E+3F, 4F;
    // Catmull-Clark V+E+F, 2E+C, C (C = sum of face degrees).
    const std::size_t v1 = c.loop ? v0 + e0 : v0 + e0 + f0, e1 = c.loop ? 2 * e0 + 3 * f0 : 2 * e0 + corners,
                      f1 = c.loop ? 4 * f0 : corners;
    const std::size_t v2 = c.loop ? v1 + e1 : v1 + e1 + f1, e2 = c.loop ? 2 * e1 + 3 * f1 : 2 * e1 + 4 * f1,
                      f2 = c.loop ? 4 * f1 : 4 * f1;
    EXPECT_EQ(m.number_of_vertices(), v2);
    EXPECT_EQ(m.number_of_edges(), e2);
    EXPECT_EQ(m.number_of_faces(), f2);
  }
}

// Doo-Sabin and sqrt3 keep the surface: Euler characteristic, border loops,
// non-orientability, one component; counts from the split rules.
TEST(SubdivisionMobius, DooSabinAndSqrt3KeepTopology)
{
  struct Case
  {
    const char* file;
    bool sqrt3;
    long long chi;
    std::size_t borders;
  };
  for (const Case& c : {Case{"nonorientable/mobius_20x4_quads.obj", false, 0, 1},
                        Case{"nonorientable/klein_fig8_24x12_quads.obj", false, 0, 0},
                        Case{"nonorientable/boys_surface_quads.obj", false, 1, 0},
                        Case{"nonorientable/mobius_min_5tris.obj", false, 0, 1},
                        Case{"nonorientable/mobius_20x4_tris.obj", true, 0, 1},
                        Case{"nonorientable/mobius_min_5tris.obj", true, 0, 1},
                        Case{"nonorientable/rp2_hemi_icosahedron.obj", true, 1, 0}}) {
    SCOPED_TRACE(std::string(c.file) + (c.sqrt3 ? " sqrt3" : " doo-sabin"));
    Mesh m = load(c.file);
    const std::size_t v0 = m.number_of_vertices(), e0 = m.number_of_edges(), f0 = m.number_of_faces();
    std::size_t corners = 0, border_edges = 0, fan_vertices = 0;
    for (CGAL_ext::Face_index f : m.faces())
      corners += m.degree(f);
    for (CGAL_ext::Edge_index e : m.edges())
      border_edges += m.is_border(e) ? 1 : 0;
    for (CGAL_ext::Vertex_index v : m.vertices()) {
      std::size_t faces = 0;
      for (CGAL_ext::Face_index f : CGAL_ext::faces_around_target(v, m))
        faces += f.is_valid() ? 1 : 0;
      fan_vertices += faces >= 3 ? 1 : 0;
    }
    if (c.sqrt3) {
      S::sqrt3(m);
      // A centroid per triangle, three triangles per triangle.
      EXPECT_EQ(m.number_of_vertices(), v0 + f0);
      EXPECT_EQ(m.number_of_faces(), 3 * f0);
      // The second step trisects each border edge: two points per edge, and
      // each border triangle becomes one triangle instead of three.
      const std::size_t v1 = m.number_of_vertices(), f1 = m.number_of_faces();
      S::sqrt3(m, CGAL_ext::parameters::number_of_iterations(1));
      EXPECT_EQ(m.number_of_vertices(), v1 + f1);
      m = load(c.file);
      S::sqrt3(m, CGAL_ext::parameters::number_of_iterations(2));
      EXPECT_EQ(m.number_of_vertices(), v1 + (f1 - border_edges) + 2 * border_edges);
      EXPECT_EQ(m.number_of_faces(), 3 * f1); // a border triangle is cut in three by its two new points
      EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), c.borders);
    } else {
      S::doo_sabin(m);
      // A point per corner; a face per face, interior edge and vertex of 3+ faces.
      EXPECT_EQ(m.number_of_vertices(), corners);
      EXPECT_EQ(m.number_of_faces(), f0 + (e0 - border_edges) + fan_vertices);
      S::doo_sabin(m);
    }
    ASSERT_TRUE(m.is_valid(true));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), c.chi);
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), c.borders);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(CGAL_ext::connected_components(m).count, 1u);
  }
}

// On a non-orientable mesh, Doo-Sabin and sqrt3 give the points that the
// same scheme gives on the orientation double cover, each twice.
TEST(SubdivisionMobius, DooSabinAndSqrt3MatchDoubleCover)
{
  for (bool sqrt3 : {false, true}) {
    for (const char* file : {"nonorientable/mobius_20x4_quads.obj", "nonorientable/klein_fig8_24x12_quads.obj",
                             "nonorientable/mobius_20x4_tris.obj", "nonorientable/rp2_hemi_icosahedron.obj"}) {
      const Shape s = read_shape(test::data(file));
      if (sqrt3 && s.faces[0].size() != 3)
        continue;
      SCOPED_TRACE(std::string(file) + (sqrt3 ? " sqrt3" : " doo-sabin"));
      Built b = build(s);
      const Shape cover = double_cover(b.mesh, b);
      Mesh cm;
      CGAL_ext::polygon_soup_to_mobius_mesh(cover.points, cover.faces, cm);
      ASSERT_TRUE(CGAL_ext::is_orientable(cm));
      const auto np = CGAL_ext::parameters::number_of_iterations(3);
      if (sqrt3) {
        S::sqrt3(b.mesh, np);
        S::sqrt3(cm, np);
      } else {
        S::doo_sabin(b.mesh, np);
        S::doo_sabin(cm, np);
      }
      ASSERT_EQ(cm.number_of_vertices(), 2 * b.mesh.number_of_vertices());
      EXPECT_EQ(cm.number_of_faces(), 2 * b.mesh.number_of_faces());
      const std::vector<Point> ours(b.mesh.points().data().begin(), b.mesh.points().data().end()),
        theirs(cm.points().data().begin(), cm.points().data().end());
      EXPECT_EQ(test::unmatched_points(ours, theirs, 1e-12), 0u);
      EXPECT_EQ(test::unmatched_points(theirs, ours, 1e-12), 0u);
    }
  }
}

// Reversing faces moves the Möbius seam but not the surface: same points.
TEST(SubdivisionMobius, IndependentOfFaceOrientations)
{
  enum Scheme { catmull_clark, loop, doo_sabin, sqrt3 };
  for (Scheme scheme : {catmull_clark, loop, doo_sabin, sqrt3}) {
    SCOPED_TRACE(scheme);
    const bool triangles = scheme == loop || scheme == sqrt3;
    Mesh a = load(triangles ? "nonorientable/mobius_20x4_tris.obj" : "nonorientable/klein_fig8_24x12_quads.obj");
    auto es = CGAL_ext::edge_sharpness_map(a);
    es[CGAL_ext::Edge_index(7)] = 1.3f;
    es[CGAL_ext::Edge_index(40)] = 10.0f;
    Mesh b = a;
    std::mt19937 rng(7);
    std::size_t reversed = 0;
    for (CGAL_ext::Face_index f : b.faces())
      if (rng() % 3 == 0) {
        b.reverse_face_orientation(f);
        ++reversed;
      }
    ASSERT_GT(reversed, 10u);
    ASSERT_TRUE(b.is_valid(true));
    ASSERT_NE(CGAL_ext::number_of_mobius_edges(a), CGAL_ext::number_of_mobius_edges(b));
    const auto np = CGAL_ext::parameters::number_of_iterations(3);
    for (Mesh* m : {&a, &b}) {
      if (scheme == loop)
        S::loop(*m, np);
      else if (scheme == catmull_clark)
        S::catmull_clark(*m, np);
      else if (scheme == doo_sabin)
        S::doo_sabin(*m, np);
      else
        S::sqrt3(*m, np);
    }
    // Orientation changes the numbering of the children of edges and corners
    // from the second level on, so compare the point sets.
    ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
    const std::vector<Point> pa(a.points().data().begin(), a.points().data().end()),
      pb(b.points().data().begin(), b.points().data().end());
    EXPECT_EQ(test::unmatched_points(pa, pb, 1e-12), 0u);
  }
}

// ----------------------------------------------------------------- exact kernels

const std::vector<std::array<int, 3>> cube_points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<std::array<std::size_t, 4>> cube_quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
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

TEST(SubdivisionExact, CubeOneLevelByHand)
{
  using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Q = CGAL::Gmpq;
  auto m = unit_cube<K>();
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
  // Edge (v0, v1) and face z = 0, found before subdividing.
  const auto e01 = [&] {
    for (auto e : m.edges())
      if ((m.vertex(e, 0).idx() == 0 && m.vertex(e, 1).idx() == 1) ||
          (m.vertex(e, 0).idx() == 1 && m.vertex(e, 1).idx() == 0))
        return e.idx();
    return 0u;
  }();
  S::catmull_clark(m);
  // Corner of valence 3: V/3 + (sum of 3 neighbours)/9 + (sum of 3 face centres)/9.
  // At (0,0,0): neighbours sum to (1,1,1), face centres to (1,1,1): 2/9 each.
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), K::Point_3(Q(2, 9), Q(2, 9), Q(2, 9)));
  // At (1,1,1): 1/3 + (2,2,2)/9 + (2,2,2)/9 = 7/9.
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(6)), K::Point_3(Q(7, 9), Q(7, 9), Q(7, 9)));
  // Edge (0,0,0)-(1,0,0): (v0+v1)/4 + (faces z=0 and y=0 centres)/4 = (1/2, 1/8, 1/8).
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(nv + e01)), K::Point_3(Q(1, 2), Q(1, 8), Q(1, 8)));
  // Face z = 0 (face 0): its centroid.
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(nv + ne + 0)), K::Point_3(Q(1, 2), Q(1, 2), Q(0)));
  // Face x = 1 (face 3).
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(nv + ne + 3)), K::Point_3(Q(1), Q(1, 2), Q(1, 2)));
}

// EPECK's exact numbers (Boost's gmp_rational or gmpxx's mpq_class, as CGAL
// was configured) and CGAL::Gmpq are all GMP rationals.
template <class ET>
auto mpq_of(const ET& a, int) -> decltype(a.backend().data())
{
  return a.backend().data();
}
template <class ET>
auto mpq_of(const ET& a, long) -> decltype(a.get_mpq_t())
{
  return a.get_mpq_t();
}
template <class ET>
bool same(const ET& a, const CGAL::Gmpq& b)
{
  return mpq_equal(mpq_of(a, 0), b.mpq()) != 0;
}

TEST(SubdivisionExact, EpeckThreeLevelsEqualsGmpqAndDouble)
{
  using Kq = CGAL::Simple_cartesian<CGAL::Gmpq>;
  auto e = unit_cube<test::Epeck>();
  auto q = unit_cube<Kq>();
  auto d = unit_cube<test::Kd>();
  // A semi-sharp edge and a corner exercise the blends in exact arithmetic.
  CGAL_ext::edge_sharpness_map(e)[CGAL_ext::Edge_index(0)] = 1.5f;
  CGAL_ext::edge_sharpness_map(q)[CGAL_ext::Edge_index(0)] = 1.5f;
  CGAL_ext::edge_sharpness_map(d)[CGAL_ext::Edge_index(0)] = 1.5f;
  CGAL_ext::vertex_sharpness_map(e)[CGAL_ext::Vertex_index(6)] = 0.5f;
  CGAL_ext::vertex_sharpness_map(q)[CGAL_ext::Vertex_index(6)] = 0.5f;
  CGAL_ext::vertex_sharpness_map(d)[CGAL_ext::Vertex_index(6)] = 0.5f;
  const auto np = CGAL_ext::parameters::number_of_iterations(3);
  S::catmull_clark(e, np);
  S::catmull_clark(q, np);
  S::catmull_clark(d, np);
  ASSERT_EQ(e.number_of_vertices(), 386u); // 8 -> 26 -> 98 -> 386
  for (auto v : e.vertices()) {
    const auto& pe = e.point(v);
    const auto& pq = q.point(v);
    EXPECT_TRUE(same(pe.x().exact(), pq.x()) && same(pe.y().exact(), pq.y()) && same(pe.z().exact(), pq.z()));
    EXPECT_NEAR(CGAL::to_double(pq.x()), d.point(v).x(), 1e-14);
    EXPECT_NEAR(CGAL::to_double(pq.y()), d.point(v).y(), 1e-14);
    EXPECT_NEAR(CGAL::to_double(pq.z()), d.point(v).z(), 1e-14);
  }
}

// ----------------------------------------------------------------- API

// A read-only sharpness map over a vector, as a user might pass.
struct Vector_edge_map
{
  const std::vector<float>* values;
  friend float get(const Vector_edge_map& m, CGAL_ext::Edge_index e) { return (*m.values)[e.idx()]; }
};

TEST(SubdivisionApi, SharpnessMapsFromMeshAndParameters)
{
  // The same creases given as the mesh's "e:sharpness" map and as a parameter.
  Mesh a = load("opensubdiv/catmark_cube_creases1.obj");
  Mesh b = a;
  const Shape s = read_shape(test::data("opensubdiv/catmark_cube_creases1.obj"));
  auto es = CGAL_ext::edge_sharpness_map(a);
  std::vector<float> values(b.number_of_edges(), 0.0f);
  for (std::size_t i = 0; i < s.crease_pairs.size(); ++i) {
    const auto e = find_edge(a, s.crease_pairs[i][0], s.crease_pairs[i][1]);
    es[e] = s.crease_values[i];
    values[e.idx()] = s.crease_values[i];
  }
  Mesh c = b; // no sharpness at all
  S::catmull_clark(a, CGAL_ext::parameters::number_of_iterations(2));
  S::catmull_clark(b, CGAL_ext::parameters::number_of_iterations(2).edge_sharpness_map(Vector_edge_map{&values}));
  S::catmull_clark(c, CGAL_ext::parameters::number_of_iterations(2));
  double ab = 0, ac = 0;
  for (auto v : a.vertices()) {
    ab = std::max(ab, CGAL::squared_distance(a.point(v), b.point(v)));
    ac = std::max(ac, CGAL::squared_distance(a.point(v), c.point(v)));
  }
  EXPECT_EQ(ab, 0.0);
  EXPECT_GT(ac, 1e-6);
  // The result carries the decayed sharpness: 5 -> 3 after two steps.
  auto out = a.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name);
  ASSERT_TRUE(out.has_value());
  int threes = 0, fives = 0;
  for (auto e : a.edges())
    threes += (*out)[e] == 3.0f ? 1 : 0;
  for (float x : s.crease_values)
    fives += x == 5.0f ? 1 : 0;
  EXPECT_EQ(fives, 11);
  EXPECT_EQ(threes, 4 * fives); // each edge of sharpness 5 in four pieces of sharpness 3
}

// The option enums live in one place, namespace CGAL_ext; the subdivision
// namespace names the same types (checked when this file compiles).
TEST(SubdivisionApi, OptionEnumsAreOneTypeEach)
{
  static_assert(std::is_same_v<S::Vertex_rule, CGAL_ext::Vertex_rule>);
  static_assert(std::is_same_v<S::Boundary_interpolation, CGAL_ext::Boundary_interpolation>);
  static_assert(std::is_same_v<S::Crease_method, CGAL_ext::Crease_method>);
  static_assert(std::is_same_v<S::Triangle_subdivision, CGAL_ext::Triangle_subdivision>);
}

TEST(SubdivisionApi, BadInputLeavesMeshUnchanged)
{
  Mesh m = load("opensubdiv/catmark_cube.obj");
  const Mesh before = m;
  EXPECT_THROW(S::loop(m), CGAL_ext::Parameter_error); // quads
  auto es = CGAL_ext::edge_sharpness_map(m);
  es[CGAL_ext::Edge_index(2)] = std::nanf("");
  EXPECT_THROW(S::catmull_clark(m), CGAL_ext::Parameter_error);
  EXPECT_EQ(m.number_of_vertices(), before.number_of_vertices());
  EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
  for (auto v : m.vertices())
    EXPECT_EQ(m.point(v), before.point(v));
}

// A negative sharpness means nothing (OpenSubdiv's sharpness is a number of
// levels): refused as NaN is, naming the edge or vertex, not taken as smooth.
TEST(SubdivisionApi, NegativeSharpnessIsRefused)
{
  for (bool on_edge : {true, false}) {
    SCOPED_TRACE(on_edge ? "edge" : "vertex");
    Mesh m = load("opensubdiv/catmark_cube.obj");
    if (on_edge)
      CGAL_ext::edge_sharpness_map(m)[CGAL_ext::Edge_index(2)] = -1.0f;
    else
      CGAL_ext::vertex_sharpness_map(m)[CGAL_ext::Vertex_index(3)] = -0.5f;
    const Mesh before = m;
    for (int scheme = 0; scheme < 2; ++scheme) {
      try {
        scheme == 0 ? S::catmull_clark(m) : S::doo_sabin(m);
        ADD_FAILURE() << "a negative sharpness was accepted";
      } catch (const CGAL_ext::Parameter_error& e) {
        EXPECT_NE(std::string(e.what()).find(on_edge ? "edge e2 " : "vertex v3 "), std::string::npos) << e.what();
      }
      EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
    }
  }
}

// In double the rules add a ring's points up before they weight the sum:
// points beyond +-1e300, or not finite, are refused naming the vertex, with
// the mesh unchanged; up to there the result is the scaled result.
TEST(SubdivisionApi, PointsWhoseSumsWouldOverflowAreRefused)
{
  const Mesh unit = load("opensubdiv/catmark_cube.obj"); // coordinates up to sqrt(2)
  double largest = 0;
  for (auto v : unit.vertices())
    for (int i = 0; i < 3; ++i)
      largest = (std::max)(largest, std::abs(unit.point(v)[i]));
  const double scale = 0.999e300 / largest;
  Mesh large = unit;
  for (auto v : large.vertices())
    large.point(v) = CGAL::ORIGIN + scale * (large.point(v) - CGAL::ORIGIN);
  Mesh unit_refined = unit;
  S::catmull_clark(unit_refined, CGAL_ext::parameters::number_of_iterations(3));
  S::catmull_clark(large, CGAL_ext::parameters::number_of_iterations(3));
  ASSERT_EQ(large.number_of_vertices(), unit_refined.number_of_vertices());
  for (auto v : large.vertices())
    for (int i = 0; i < 3; ++i) {
      ASSERT_TRUE(std::isfinite(large.point(v)[i]));
      EXPECT_NEAR(large.point(v)[i] / scale, unit_refined.point(v)[i], 1e-14);
    }
  for (const double bad : {1e301, -1e305, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    Mesh m = unit;
    m.point(CGAL_ext::Vertex_index(5)) = Point(0.5, bad, 0.5);
    const Mesh before = m;
    for (int scheme = 0; scheme < 3; ++scheme) {
      try {
        scheme == 0 ? S::catmull_clark(m) : scheme == 1 ? S::doo_sabin(m) : S::linear(m);
        ADD_FAILURE() << "a point at " << bad << " was subdivided";
      } catch (const CGAL_ext::Parameter_error& e) {
        EXPECT_NE(std::string(e.what()).find("vertex v5 "), std::string::npos) << e.what();
      }
      ASSERT_EQ(m.number_of_vertices(), before.number_of_vertices());
      ASSERT_EQ(m.number_of_faces(), before.number_of_faces());
      for (auto v : m.vertices())
        for (int i = 0; i < 3; ++i) { // bit for bit: NaN is not equal to itself
          const double now = m.point(v)[i], was = before.point(v)[i];
          EXPECT_EQ(std::memcmp(&now, &was, sizeof(double)), 0);
        }
    }
  }
}

TEST(SubdivisionApi, EdgePointsVertexRule)
{
  // On the cube, the variant rule at a corner of valence 3:
  // V/3 + (sum of new edge points)/9 + (sum of face points)/9, with the edge
  // points (1/2,1/8,1/8) and permutations: sum (3/4,3/4,3/4); face centres
  // sum (1,1,1): (3/4 + 1)/9 = 7/36.
  using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
  auto m = unit_cube<K>();
  S::catmull_clark(m, CGAL_ext::parameters::vertex_rule(S::Vertex_rule::edge_points));
  const CGAL::Gmpq c(7, 36);
  EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), K::Point_3(c, c, c));
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

TEST(SubdivisionApi, VertexRuleOfUnequalWeightsByHand)
{
  // Cube corners of valence 3. At (0,0,0) the neighbours and the face centres
  // each sum to (1,1,1), the new edge points to (3/4,3/4,3/4) (as in
  // EdgePointsVertexRule); at (1,1,1), to (2,2,2), (2,2,2) and (9/4,9/4,9/4).
  // Three weights 1/12, 1/16, 1/48: 1/12 + 1/16 + 3/4 · 1/48 = 31/192, and
  // 1/2 + 2/12 + 2/16 + 9/4 · 1/48 = 161/192. Two weights 1/12, 1/24, 1/24:
  // 1/12 + 1/24 + 3/4 · 1/24 = 5/32 and 1/2 + 2/12 + 2/24 + 9/4 · 1/24 = 27/32.
  using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
  using Q = CGAL::Gmpq;
  auto check = [](auto mask, const Q& low, const Q& high) {
    auto m = unit_cube<K>();
    S::subdivide(m, mask);
    EXPECT_EQ(m.point(CGAL_ext::Vertex_index(0)), K::Point_3(low, low, low));
    EXPECT_EQ(m.point(CGAL_ext::Vertex_index(6)), K::Point_3(high, high, high));
  };
  check(Unequal_weights_mask<3>(), Q(31, 192), Q(161, 192));
  check(Unequal_weights_mask<2>(), Q(5, 32), Q(27, 32));
}

// The one-pass path (used by the free functions) against refine(),
// interpolate_level() and build_mesh(): the same mesh, bit for bit the same
// points, the same sharpness and hole maps.
template <class Mask, class ConcurrencyTag = CGAL::Sequential_tag>
void check_one_pass(const std::string& file, unsigned n, const Boundary_interpolation* boundary = nullptr)
{
  SCOPED_TRACE(file);
  const Shape s = read_shape(test::data(file));
  const Built b = build(s);
  S::Refinement_options options;
  options.boundary_interpolation = boundary ? *boundary : s.boundary;
  options.crease_method = s.crease_method;
  options.parallel_min_vertices = 0; // the parallel pass on every level, however small
  S::Refiner<Mask> r(Mask(), options);
  const std::vector<std::vector<V3>> levels = our_levels(r, b, n);
  Mesh expected;
  r.build_mesh(expected, true);

  S::Refiner<Mask> one(Mask(), options);
  std::vector<V3> values = levels[0];
  Mesh out;
  one.template refine_and_interpolate<ConcurrencyTag>(b.mesh, n, values, out, b.edge_sharpness,
                                                      b.vertex_sharpness, true);
  EXPECT_EQ(one.number_of_levels(), 0u);
  ASSERT_TRUE(out.is_valid(true));
  ASSERT_EQ(out.number_of_vertices(), expected.number_of_vertices());
  ASSERT_EQ(out.number_of_edges(), expected.number_of_edges());
  ASSERT_EQ(out.number_of_faces(), expected.number_of_faces());
  for (auto h : out.halfedges()) {
    const CGAL_ext::Dart d(h, false);
    ASSERT_EQ(out.target(d), expected.target(d));
    ASSERT_EQ(out.next(d), expected.next(d));
    ASSERT_EQ(out.face(h), expected.face(h));
  }
  for (auto e : out.edges())
    ASSERT_EQ(out.is_mobius(e), expected.is_mobius(e));
  for (auto v : out.vertices())
    ASSERT_EQ(out.halfedge(v), expected.halfedge(v));
  ASSERT_EQ(values.size(), levels[n].size());
  EXPECT_EQ(std::memcmp(values.data(), levels[n].data(), values.size() * sizeof(V3)), 0);
  auto es = out.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name);
  auto es_expected = expected.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name);
  auto vs = out.property_map<CGAL_ext::Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  auto vs_expected = expected.property_map<CGAL_ext::Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(es && es_expected && vs && vs_expected);
  EXPECT_EQ(es->data(), es_expected->data());
  EXPECT_EQ(vs->data(), vs_expected->data());
  auto holes = out.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  auto holes_expected = expected.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  ASSERT_EQ(holes.has_value(), holes_expected.has_value());
  if (holes) {
    EXPECT_EQ(holes->data(), holes_expected->data());
  }
}

TEST(SubdivisionApi, OnePassEqualsLevelByLevel)
{
  const Boundary_interpolation none = Boundary_interpolation::none;
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_cube_creases1.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_chaikin1.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_edgecorner.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_edgecorner.obj", 2, &none);
  check_one_pass<S::Catmull_clark_mask>("nonorientable/mobius_20x4_quads.obj", 3);
  check_one_pass<S::Catmull_clark_mask>("nonorientable/torus_24x12_quads.obj", 2);
  check_one_pass<S::Loop_mask>("opensubdiv/loop_icos_semisharp.obj", 3);
  check_one_pass<S::Loop_mask>("opensubdiv/loop_triangle_edgeonly.obj", 3);
  check_one_pass<S::Loop_mask>("opensubdiv/loop_triangle_edgeonly.obj", 2, &none);
  check_one_pass<S::Loop_mask>("nonorientable/mobius_20x4_tris.obj", 3, &none);
  check_one_pass<S::Bilinear_mask>("opensubdiv/catmark_cube_creases1.obj", 2);
  check_one_pass<S::Linear_mask>("nonorientable/mobius_20x4_tris.obj", 2);
  check_one_pass<S::Catmull_clark_mask>("opensubdiv/catmark_cube_creases1.obj", 0);
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  check_one_pass<S::Catmull_clark_mask, CGAL::Parallel_tag>("opensubdiv/catmark_chaikin1.obj", 3);
  check_one_pass<S::Loop_mask, CGAL::Parallel_tag>("opensubdiv/loop_icos_semisharp.obj", 3);
#endif
}

// The one-pass path that writes the last level straight into the result's
// points (the free functions' path for points of doubles) against the one
// that returns the values: the same mesh and maps, and the points are the
// values, bit for bit, in every scheme.
template <class Mask, class ConcurrencyTag = CGAL::Sequential_tag>
void check_points_pass(const std::string& file, unsigned n, const Boundary_interpolation* boundary = nullptr)
{
  SCOPED_TRACE(file + ", " + std::to_string(n) + " levels");
  const Shape s = read_shape(test::data(file));
  const Built b = build(s);
  S::Refinement_options options;
  options.boundary_interpolation = boundary ? *boundary : s.boundary;
  options.crease_method = s.crease_method;
  options.parallel_min_vertices = 0; // the parallel pass on every level, however small
  std::vector<V3> values;
  for (const Point& p : b.mesh.points().data())
    values.push_back({p.x(), p.y(), p.z()});
  std::vector<V3> into_points = values;

  Mesh expected;
  S::Refiner<Mask>(Mask(), options)
    .template refine_and_interpolate<ConcurrencyTag>(b.mesh, n, values, expected, b.edge_sharpness,
                                                     b.vertex_sharpness, true);
  Mesh out;
  S::Refiner<Mask> r(Mask(), options);
  r.template refine_and_interpolate_points<S::internal::Point_values<Point>, ConcurrencyTag>(
    b.mesh, n, into_points, out, b.edge_sharpness, b.vertex_sharpness, true);
  EXPECT_TRUE(into_points.empty());
  EXPECT_EQ(r.number_of_levels(), 0u);
  ASSERT_TRUE(out.is_valid(true));
  ASSERT_EQ(out.number_of_vertices(), values.size());
  ASSERT_EQ(out.number_of_halfedges(), expected.number_of_halfedges());
  ASSERT_EQ(out.number_of_faces(), expected.number_of_faces());
  std::vector<V3> points;
  for (const Point& p : out.points().data())
    points.push_back({p.x(), p.y(), p.z()});
  EXPECT_EQ(std::memcmp(points.data(), values.data(), values.size() * sizeof(V3)), 0);
  for (auto h : out.halfedges()) {
    const CGAL_ext::Dart d(h, false);
    ASSERT_EQ(out.target(d), expected.target(d));
    ASSERT_EQ(out.next(d), expected.next(d));
    ASSERT_EQ(out.face(h), expected.face(h));
  }
  for (auto e : out.edges())
    ASSERT_EQ(out.is_mobius(e), expected.is_mobius(e));
  for (auto v : out.vertices())
    ASSERT_EQ(out.halfedge(v), expected.halfedge(v));
  auto holes = out.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  auto holes_expected = expected.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
  ASSERT_EQ(holes.has_value(), holes_expected.has_value());
  if (holes) {
    EXPECT_EQ(holes->data(), holes_expected->data());
  }
  auto sharpness = [](const Mesh& m, auto key) {
    using Key = decltype(key);
    auto map = m.property_map<Key, float>(std::is_same_v<Key, CGAL_ext::Edge_index> ? CGAL_ext::edge_sharpness_name
                                                                                     : CGAL_ext::vertex_sharpness_name);
    return map ? map->data() : std::vector<float>{-1.0f}; // a missing map differs from every map
  };
  EXPECT_EQ(sharpness(out, CGAL_ext::Edge_index()), sharpness(expected, CGAL_ext::Edge_index()));
  EXPECT_EQ(sharpness(out, CGAL_ext::Vertex_index()), sharpness(expected, CGAL_ext::Vertex_index()));
}

TEST(SubdivisionApi, PointsWrittenInPlaceAreTheOnePassValues)
{
  auto each_tag = [](auto check) {
    check(CGAL::Sequential_tag());
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
    check(CGAL::Parallel_tag());
#endif
  };
  const Boundary_interpolation none = Boundary_interpolation::none;
  each_tag([&](auto tag) {
    using Tag = decltype(tag);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_edgecorner.obj", 2, &none); // holes
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_chaikin1.obj", 3);
    check_points_pass<S::Loop_mask, Tag>("opensubdiv/loop_triangle_edgeonly.obj", 2, &none);
    check_points_pass<Unequal_weights_mask<2>, Tag>("opensubdiv/catmark_cube_creases1.obj", 2); // two sums
    check_points_pass<Unequal_weights_mask<3>, Tag>("nonorientable/mobius_20x4_quads.obj", 2);  // three
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 3);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_edgecorner.obj", 3);
    check_points_pass<S::Catmull_clark_mask, Tag>("nonorientable/mobius_20x4_quads.obj", 3);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 1);
    check_points_pass<S::Catmull_clark_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 0);
    check_points_pass<S::Loop_mask, Tag>("opensubdiv/loop_icos_semisharp.obj", 3);
    check_points_pass<S::Loop_mask, Tag>("nonorientable/mobius_20x4_tris.obj", 2);
    check_points_pass<S::Bilinear_mask, Tag>("opensubdiv/catmark_cube_creases1.obj", 2);
    check_points_pass<S::Linear_mask, Tag>("nonorientable/mobius_20x4_tris.obj", 2);
    check_points_pass<S::Doo_sabin_mask, Tag>("nonorientable/mobius_20x4_quads.obj", 2);
    check_points_pass<S::Sqrt3_mask, Tag>("opensubdiv/loop_icos_semisharp.obj", 3);
  });
}

#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
// ----------------------------------------------------------------- parallel stages

// A mesh's connectivity, array by array, read through its public accessors.
struct Connectivity
{
  std::vector<std::uint32_t> target, next, prev, face, vertex_dart, face_dart;
  std::vector<std::uint8_t> mobius;
};

Connectivity connectivity_of(const Mesh& m)
{
  Connectivity c;
  for (auto h : m.halfedges()) {
    const CGAL_ext::Dart d(h, false);
    c.target.push_back(m.target(d).idx());
    c.next.push_back(m.next(d).bits());
    c.prev.push_back(m.prev(d).bits());
    c.face.push_back(m.face(h).is_valid() ? m.face(h).idx() : ~0u);
  }
  for (auto e : m.edges())
    c.mobius.push_back(m.is_mobius(e) ? 1 : 0);
  for (auto v : m.vertices())
    c.vertex_dart.push_back(m.halfedge(v).bits());
  for (auto f : m.faces())
    c.face_dart.push_back(m.halfedge(f).bits());
  return c;
}

template <class T, class A, class B>
bool same_bytes(const std::vector<T, A>& a, const std::vector<T, B>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Whether two meshes have the same connectivity arrays, byte for byte.
bool same_connectivity(const Mesh& a, const Mesh& b)
{
  const Connectivity ca = connectivity_of(a), cb = connectivity_of(b);
  return same_bytes(ca.target, cb.target) && same_bytes(ca.next, cb.next) && same_bytes(ca.prev, cb.prev) &&
         same_bytes(ca.face, cb.face) && same_bytes(ca.mobius, cb.mobius) &&
         same_bytes(ca.vertex_dart, cb.vertex_dart) && same_bytes(ca.face_dart, cb.face_dart);
}

struct Refined
{
  Mesh mesh;
  std::vector<V3> points;
};

// `n` steps of `Mask` on `b` under `ConcurrencyTag`, by the two paths of the
// free functions: one pass, or refine(), interpolate() and build_mesh().
template <class Mask, class ConcurrencyTag>
Refined refine_with(const Built& b, const S::Refinement_options& options, unsigned n, bool one_pass)
{
  Refined r;
  std::vector<V3> base;
  for (const Point& p : b.mesh.points().data())
    base.push_back({p.x(), p.y(), p.z()});
  S::Refiner<Mask> refiner(Mask(), options);
  if (one_pass) {
    r.points = base;
    refiner.template refine_and_interpolate<ConcurrencyTag>(b.mesh, n, r.points, r.mesh, b.edge_sharpness,
                                                            b.vertex_sharpness, true);
  } else {
    refiner.template refine<ConcurrencyTag>(b.mesh, n, b.edge_sharpness, b.vertex_sharpness);
    refiner.template interpolate<ConcurrencyTag>(base, r.points);
    refiner.template build_mesh<ConcurrencyTag>(r.mesh, true);
  }
  return r;
}

// Serial and parallel refinement of `b` (the parallel path forced on every
// level) give the same mesh, array for array, the same points, sharpness
// and holes, bit for bit.
//
// Then again with threads from the last step only (the threshold at its
// parent's vertex count): the serial steps before it make the incidence
// tables that the parallel one reads.
template <class Mask>
void check_parallel_stages(const std::string& what, const Built& b, S::Refinement_options options, unsigned n)
{
  const std::uint32_t last_parent =
    std::uint32_t(S::refined_size(Mask::split, S::internal::size_of(b.mesh), n - 1).vertices);
  for (std::uint32_t threshold : {std::uint32_t(0), last_parent}) {
    for (bool one_pass : {true, false}) {
      options.parallel_min_vertices = threshold;
      SCOPED_TRACE(what + (one_pass ? ", one pass" : ", level by level") + ", threads from " +
                   std::to_string(threshold) + " vertices");
      const Refined s = refine_with<Mask, CGAL::Sequential_tag>(b, options, n, one_pass);
      const Refined p = refine_with<Mask, CGAL::Parallel_tag>(b, options, n, one_pass);
      ASSERT_TRUE(p.mesh.is_valid(true));
      ASSERT_EQ(p.mesh.number_of_faces(), s.mesh.number_of_faces());
      const Connectivity cs = connectivity_of(s.mesh), cp = connectivity_of(p.mesh);
      EXPECT_TRUE(same_bytes(cs.target, cp.target));
      EXPECT_TRUE(same_bytes(cs.next, cp.next));
      EXPECT_TRUE(same_bytes(cs.prev, cp.prev));
      EXPECT_TRUE(same_bytes(cs.face, cp.face));
      EXPECT_TRUE(same_bytes(cs.mobius, cp.mobius));
      EXPECT_TRUE(same_bytes(cs.vertex_dart, cp.vertex_dart));
      EXPECT_TRUE(same_bytes(cs.face_dart, cp.face_dart));
      EXPECT_TRUE(same_bytes(s.points, p.points));
      for (const char* name : {CGAL_ext::edge_sharpness_name, CGAL_ext::vertex_sharpness_name}) {
        const bool on_edges = name == std::string(CGAL_ext::edge_sharpness_name);
        std::vector<float> ss, sp;
        if (on_edges) {
          ss = s.mesh.property_map<CGAL_ext::Edge_index, float>(name)->data();
          sp = p.mesh.property_map<CGAL_ext::Edge_index, float>(name)->data();
        } else {
          ss = s.mesh.property_map<CGAL_ext::Vertex_index, float>(name)->data();
          sp = p.mesh.property_map<CGAL_ext::Vertex_index, float>(name)->data();
        }
        EXPECT_TRUE(same_bytes(ss, sp)) << name;
      }
      auto hs = s.mesh.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
      auto hp = p.mesh.property_map<CGAL_ext::Face_index, std::uint8_t>("f:hole");
      ASSERT_EQ(hs.has_value(), hp.has_value());
      if (hs) {
        EXPECT_TRUE(same_bytes(hs->data(), hp->data()));
      }
    }
  }
}

// A generated mesh with, if `sharp`, a fixed mix of smooth, semi-sharp and
// infinitely sharp edges and a few corners.
Built generated(Mesh m, bool sharp)
{
  Built b;
  b.mesh = std::move(m);
  b.edge_sharpness.assign(b.mesh.number_of_edges(), 0.0f);
  b.vertex_sharpness.assign(b.mesh.number_of_vertices(), 0.0f);
  if (sharp) {
    for (std::size_t e = 0; e < b.edge_sharpness.size(); ++e)
      b.edge_sharpness[e] = e % 7 == 0 ? 10.0f : (e % 5 == 0 ? 0.25f + float(e % 11) / 4.0f : 0.0f);
    for (std::size_t v = 0; v < b.vertex_sharpness.size(); v += 19)
      b.vertex_sharpness[v] = 2.5f;
  }
  return b;
}

// A scheme with every crease method and, on a surface with a border, every
// boundary rule (`all_rules`; else the defaults), on a one-sided surface
// large enough that the loops of the last step are split among threads (a
// TBB task takes 4096 elements at least), with and without sharpness.
template <class Mask>
void check_schemes_on(const std::string& name, const Mesh& m, unsigned n, bool all_rules)
{
  using B = Boundary_interpolation;
  const std::vector<Crease_method> methods =
    all_rules ? std::vector<Crease_method>{Crease_method::uniform, Crease_method::chaikin}
              : std::vector<Crease_method>{Crease_method::uniform};
  const auto edges = m.edges();
  const bool border = std::any_of(edges.begin(), edges.end(), [&](CGAL_ext::Edge_index e) { return m.is_border(e); });
  const std::vector<B> rules = all_rules && border
                                 ? std::vector<B>{B::edge_only, B::edge_and_corner, B::none}
                                 : std::vector<B>{B::edge_only};
  for (bool sharp : {false, true}) {
    const Built b = generated(m, sharp);
    for (Crease_method c : methods)
      for (Boundary_interpolation bi : rules) {
        S::Refinement_options options;
        options.crease_method = c;
        options.boundary_interpolation = bi;
        check_parallel_stages<Mask>(name + (sharp ? ", sharp" : ", smooth") + ", crease method " +
                                      std::to_string(int(c)) + ", boundary " + std::to_string(int(bi)),
                                    b, options, n);
      }
  }
}

// A double cone over a regular n-gon: two apexes of valence n, whose
// incidence lists (n > 32) the parallel pass sorts with std::sort rather
// than its insertion sort for short lists.
Mesh bipyramid(std::size_t n)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * CGAL_PI * double(i) / double(n);
    points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  points.emplace_back(0.0, 0.0, 1.0);
  points.emplace_back(0.0, 0.0, -1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    faces.push_back({i, j, n});
    faces.push_back({j, i, n + 1});
  }
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, m);
  return m;
}

// A non-finite point spoils only the child points made from it, in both
// passes. Catmull–Clark of an 8 × 8 torus of quads (every vertex of valence
// 4) with vertex 0 at NaN: its own vertex point, those of the 8 vertices that
// share a face with it, the 12 edge points and the 4 face points of its 4
// faces read it, 25 points of 256; every other stays finite.
TEST(SubdivisionParallel, NonFinitePointSpoilsOnlyThePointsMadeFromIt)
{
  Mesh torus;
  CGAL_ext::make_torus(torus, 8, 8);
  torus.point(CGAL_ext::Vertex_index(0)) = Point(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  const Built b = generated(torus, false);
  S::Refinement_options options;
  options.parallel_min_vertices = 0; // the gather on the level, however small
  auto count_non_finite = [](const std::vector<V3>& points) {
    return std::count_if(points.begin(), points.end(), [](const V3& p) {
      return !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    });
  };
  const Refined s = refine_with<S::Catmull_clark_mask, CGAL::Sequential_tag>(b, options, 1, true);
  const Refined p = refine_with<S::Catmull_clark_mask, CGAL::Parallel_tag>(b, options, 1, true);
  ASSERT_EQ(s.points.size(), 256u);
  EXPECT_EQ(count_non_finite(s.points), 25);
  EXPECT_EQ(count_non_finite(p.points), 25);
}

TEST(SubdivisionParallel, EveryStageBitIdenticalToSerial)
{
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  tbb::task_arena arena(4);
  arena.execute([] {
    Mesh strip, strip_tris, klein;
    CGAL_ext::make_mobius_strip(strip, 64, 16);
    CGAL_ext::make_mobius_strip(strip_tris, 64, 16, 1, 1.0, 0.5, false);
    CGAL_ext::make_klein_bottle(klein, 40, 40);
    // Doo–Sabin and √3 have border rules of their own and no creases.
    check_schemes_on<S::Catmull_clark_mask>("Catmull-Clark, Moebius strip", strip, 2, true);
    check_schemes_on<S::Catmull_clark_mask>("Catmull-Clark, Klein bottle", klein, 2, true);
    check_schemes_on<S::Bilinear_mask>("bilinear, Moebius strip", strip, 2, true);
    check_schemes_on<S::Doo_sabin_mask>("Doo-Sabin, Moebius strip", strip, 2, false);
    check_schemes_on<S::Doo_sabin_mask>("Doo-Sabin, Klein bottle", klein, 2, false);
    check_schemes_on<Unequal_weights_mask<3>>("three vertex sums, Moebius strip", strip, 2, true);
    check_schemes_on<Unequal_weights_mask<2>>("two vertex sums, Klein bottle", klein, 2, false);
    check_schemes_on<S::Loop_mask>("Loop, Moebius strip", strip_tris, 2, true);
    check_schemes_on<S::Linear_mask>("linear, Moebius strip", strip_tris, 2, true);
    check_schemes_on<S::Sqrt3_mask>("sqrt(3), Moebius strip", strip_tris, 3, false);
    const Mesh cone = bipyramid(48);
    check_schemes_on<S::Catmull_clark_mask>("Catmull-Clark, vertices of valence 48", cone, 3, false);
    check_schemes_on<S::Loop_mask>("Loop, vertices of valence 48", cone, 3, false);
  });
}

// The faces of the corners of level `L`, from its corner table.
std::vector<std::uint32_t> faces_of_corners(const Level& L)
{
  std::vector<std::uint32_t> faces(L.nc);
  for (std::uint32_t f = 0; f < L.nf; ++f)
    for (std::uint32_t k = L.f_offset[f]; k < L.f_offset[f + 1]; ++k)
      faces[k] = f;
  return faces;
}

// The tables `t` of level `L` are `reference`'s (a counting sort over `L`),
// and give each corner its face.
void expect_incidence(const Level& L, const S::internal::Incidence& t, const S::internal::Incidence& reference)
{
  EXPECT_TRUE(same_bytes(t.edge_offset, reference.edge_offset));
  EXPECT_TRUE(same_bytes(t.edge_ends, reference.edge_ends));
  EXPECT_TRUE(same_bytes(t.corner_offset, reference.corner_offset));
  EXPECT_TRUE(same_bytes(t.corners, reference.corners));
  if (t.corners.empty())
    return;
  const std::vector<std::uint32_t> faces = faces_of_corners(L);
  std::size_t wrong = 0;
  for (std::uint32_t k = 0; k < L.nc; ++k)
    wrong += t.face_of_corner(k) == faces[k] ? 0 : 1;
  EXPECT_EQ(wrong, 0u);
}

// Each level's incidence tables, walked around its vertices in parallel and
// derived by the split from its parent's, are those of a counting sort over
// the level itself: every list in order, every corner's face. (How the
// refiner hands them from level to level is covered by the bit-identical
// results of the parallel pass above.)
template <class Mask>
void check_incidence_tables(const std::string& what, const Mesh& m, unsigned n)
{
  SCOPED_TRACE(what);
  constexpr bool corners = Mask::split == S::Split::quad;
  S::Refiner<Mask> r{Mask()};
  r.refine(m, n);
  ASSERT_EQ(r.number_of_levels(), n);
  for (unsigned k = 0; k <= n; ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    const Level& L = r.level(k);
    S::internal::Incidence reference, walked;
    S::internal::build_incidence_serially(L, corners, reference);
    ASSERT_EQ(reference.edge_ends.size(), 2 * std::size_t(L.ne));
    ASSERT_EQ(reference.corners.size(), corners ? std::size_t(L.nc) : 0u);
    S::internal::build_incidence<CGAL::Parallel_tag>(L, corners, walked);
    expect_incidence(L, walked, reference);
    if (k == 0)
      continue;
    S::internal::Incidence parent, derived;
    S::internal::build_incidence_serially(r.level(k - 1), corners, parent);
    S::internal::derive_incidence<CGAL::Parallel_tag, Mask::split>(r.level(k - 1), parent, derived);
    expect_incidence(L, derived, reference);
  }
}

TEST(SubdivisionParallel, IncidenceTablesOfEveryLevelAsACountingSort)
{
  Mesh strip, strip_tris, klein;
  CGAL_ext::make_mobius_strip(strip, 12, 3);
  CGAL_ext::make_mobius_strip(strip_tris, 12, 3, 1, 1.0, 0.5, false);
  CGAL_ext::make_klein_bottle(klein, 6, 6);
  // Vertices on no edge keep empty lists.
  klein.add_vertex(Point(9, 9, 9));
  strip_tris.add_vertex(Point(9, 9, 9));
  check_incidence_tables<S::Catmull_clark_mask>("Catmull-Clark, Moebius strip", strip, 3);
  check_incidence_tables<S::Catmull_clark_mask>("Catmull-Clark, Klein bottle", klein, 3);
  check_incidence_tables<S::Loop_mask>("Loop, Moebius strip", strip_tris, 3);
  check_incidence_tables<S::Catmull_clark_mask>("Catmull-Clark, vertices of valence 48", bipyramid(48), 2);
  check_incidence_tables<S::Loop_mask>("Loop, vertices of valence 48", bipyramid(48), 2);
  for (const char* file : {"catmark_nonquads.obj", "catmark_pole64.obj", "catmark_edgecorner.obj", "catmark_smoothtris1.obj"})
    check_incidence_tables<S::Catmull_clark_mask>(file, build(read_shape(test::data(std::string("opensubdiv/") + file))).mesh, 2);
  for (const char* file : {"loop_tetrahedron.obj", "loop_triangle_edgeonly.obj"})
    check_incidence_tables<S::Loop_mask>(file, build(read_shape(test::data(std::string("opensubdiv/") + file))).mesh, 2);
}

TEST(SubdivisionParallel, OpenSubdivShapesBitIdenticalToSerial)
{
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  tbb::task_arena arena(4);
  arena.execute([] {
    auto check = [](auto mask, const std::string& file, unsigned n) {
      using Mask = decltype(mask);
      const Shape s = read_shape(test::data("opensubdiv/" + file));
      S::Refinement_options options;
      options.crease_method = s.crease_method;
      options.boundary_interpolation = s.boundary;
      check_parallel_stages<Mask>(file, build(s), options, n);
    };
    check(S::Catmull_clark_mask(), "catmark_cube_creases1.obj", 5);
    check(S::Catmull_clark_mask(), "catmark_chaikin1.obj", 4);
    check(S::Catmull_clark_mask(), "catmark_edgecorner.obj", 5);
    check(S::Catmull_clark_mask(), "catmark_torus_creases1.obj", 4);
    check(S::Bilinear_mask(), "catmark_cube_creases1.obj", 5);
    check(S::Doo_sabin_mask(), "catmark_cube_creases1.obj", 5);
    check(S::Loop_mask(), "loop_icos_semisharp.obj", 5);
    check(S::Loop_mask(), "loop_triangle_edgeonly.obj", 6);
    check(S::Linear_mask(), "loop_icos_semisharp.obj", 5);
    check(S::Sqrt3_mask(), "loop_icos_semisharp.obj", 6);
  });
}

// The automatic threshold is the documented rule: more than one thread, and
// at least parallel_vertices_per_thread vertices per thread; any other value
// of the option is a plain minimum.
TEST(SubdivisionParallel, ThresholdFollowsThreadsAndSize)
{
  const std::uint32_t g = S::parallel_vertices_per_thread, automatic = S::Refinement_options::automatic;
  EXPECT_EQ(S::Refinement_options().parallel_min_vertices, automatic);
  {
    tbb::task_arena one(1);
    one.execute([&] { EXPECT_FALSE(S::runs_in_parallel(1u << 30, automatic)); });
    one.execute([&] { EXPECT_TRUE(S::runs_in_parallel(5, 0)); }); // an explicit minimum is obeyed
  }
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 4);
  for (int t : {2, 4}) {
    tbb::task_arena arena(t);
    arena.execute([&] {
      EXPECT_FALSE(S::runs_in_parallel(std::uint32_t(t) * g - 1, automatic)) << t;
      EXPECT_TRUE(S::runs_in_parallel(std::uint32_t(t) * g, automatic)) << t;
    });
  }
  EXPECT_TRUE(S::runs_in_parallel(0, 0));
  EXPECT_FALSE(S::runs_in_parallel(99, 100));
  EXPECT_TRUE(S::runs_in_parallel(100, 100));
}

// The tuner's rule on given timings: the smallest class without a verdict
// runs with threads three times, then serially three times, and the faster
// (per parent vertex, best of) is its verdict; a win of the threads carries
// to larger classes, a loss to smaller ones; each number of threads learns
// on its own.
TEST(SubdivisionParallel, TunerTriesTheSmallestOpenClassBothWays)
{
  using Plan = S::internal::Parallel_plan;
  using Modes = std::array<bool, 3>;
  S::internal::Parallel_step_tuner tuner;
  ASSERT_EQ(S::internal::Parallel_step_tuner::samples_per_verdict, 3u);
  const auto prior = [](std::uint32_t n) { return n >= 16384; };
  // Parents of 4 096 (class 12, below the prior), 20 000 (class 14), 80 000
  // (class 16) and 320 000 (class 18) vertices.
  const std::vector<std::uint32_t> parents = {4096, 20000, 80000, 320000};
  auto modes = [&](unsigned threads) {
    const Plan p = tuner.plan(threads, parents, prior);
    return Modes{p.parallel_class(14), p.parallel_class(16), p.parallel_class(18)};
  };
  auto record = [&](std::uint32_t parent, bool parallel, std::initializer_list<double> seconds) {
    for (double t : seconds)
      tuner.record(2, parent, parallel, t);
  };
  EXPECT_EQ(modes(2), (Modes{true, true, true}));
  EXPECT_EQ(tuner.plan(2, parents, prior).tried, 14);
  EXPECT_EQ(tuner.plan(2, parents, prior, false).tried, -1); // refine(): follows verdicts, tries nothing
  // Class 14: threads at 2, 1.8 and 1.9 ms a step, serially 1, 1.2 and 1.1 ms.
  record(20000, true, {2e-3, 1.8e-3});
  EXPECT_EQ(modes(2), (Modes{true, true, true}));
  record(20000, true, {1.9e-3});
  EXPECT_EQ(modes(2), (Modes{false, true, true})); // now the serial tries
  record(20000, false, {1e-3, 1.2e-3});
  EXPECT_EQ(tuner.verdict(2, 14), -1);
  EXPECT_EQ(modes(2), (Modes{false, true, true}));
  record(20000, false, {1.1e-3});
  EXPECT_EQ(tuner.verdict(2, 14), Plan::serial);
  // Class 16 is next; class 14 stays serial, as do the classes below it.
  EXPECT_EQ(modes(2), (Modes{false, true, true}));
  EXPECT_EQ(tuner.plan(2, parents, prior).tried, 16);
  EXPECT_FALSE(tuner.plan(2, parents, prior).parallel_class(13));
  record(80000, true, {2e-3, 2.5e-3, 2.2e-3});
  EXPECT_EQ(modes(2), (Modes{false, false, true}));
  record(80000, false, {4e-3, 3.5e-3, 3.9e-3});
  EXPECT_EQ(tuner.verdict(2, 16), Plan::parallel);
  // Class 18 follows the win at 16 without a try; class 15, between a loss
  // and a win, has no verdict yet.
  EXPECT_EQ(modes(2), (Modes{false, true, true}));
  EXPECT_EQ(tuner.plan(2, parents, prior).tried, -1);
  EXPECT_EQ(tuner.verdict(2, 18), -1);
  EXPECT_EQ(tuner.verdict(2, 15), -1);
  // Class 15, between a loss below and a win above, is implied nothing: it
  // uses threads, as a class with no verdict does, and is tried.
  EXPECT_TRUE(tuner.plan(2, {32768}, prior).parallel_class(15));
  EXPECT_EQ(tuner.plan(2, {32768}, prior).tried, 15);
  // The time per vertex decides, not the time: serial steps from 65 536
  // vertices (class 16 too) at 2.6 ms are faster per vertex than steps with
  // threads from 80 000 at 3.5 ms.
  S::internal::Parallel_step_tuner per_vertex;
  for (int i = 0; i < 3; ++i) {
    per_vertex.record(2, 80000, true, 3.5e-3);
    per_vertex.record(2, 65536, false, 2.6e-3);
  }
  EXPECT_EQ(per_vertex.verdict(2, 16), Plan::serial);
  // Four threads have learnt nothing.
  EXPECT_EQ(modes(4), (Modes{true, true, true}));
  EXPECT_EQ(tuner.verdict(4, 14), -1);
}

// A mask type of its own, so that its refiners' tuner starts empty here
// whatever other tests ran before in this process.
struct Tuned_catmull_clark_mask : S::Catmull_clark_mask
{};

// Refinements under CGAL::Parallel_tag with the automatic choice time their
// steps: after three runs each way a class has its verdict, and every run,
// whichever way each step went, gives the serial result bit for bit. An
// explicit threshold times nothing.
TEST(SubdivisionParallel, RepeatedRefinementsLearnAndStayBitIdentical)
{
  using R = S::Refiner<Tuned_catmull_clark_mask>;
  R::tuner().clear(); // as new, also when the test repeats
  Mesh torus;
  CGAL_ext::make_torus(torus, 128, 128); // 16 384 vertices: the prior's least on two threads
  const Built b = generated(torus, true);
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 2);
  tbb::task_arena arena(2);
  arena.execute([&] {
    const unsigned c = S::internal::size_class(16384);
    S::Refinement_options fixed;
    fixed.parallel_min_vertices = 16384;
    refine_with<Tuned_catmull_clark_mask, CGAL::Parallel_tag>(b, fixed, 1, true);
    EXPECT_EQ(R::tuner().verdict(2, c), -1);
    const Refined s = refine_with<Tuned_catmull_clark_mask, CGAL::Sequential_tag>(b, S::Refinement_options(), 1, true);
    for (int run = 0; run < 6; ++run) {
      EXPECT_EQ(R::tuner().verdict(2, c), -1) << run;
      const Refined p = refine_with<Tuned_catmull_clark_mask, CGAL::Parallel_tag>(b, S::Refinement_options(), 1, true);
      EXPECT_TRUE(same_bytes(s.points, p.points)) << run;
      EXPECT_TRUE(same_connectivity(s.mesh, p.mesh)) << run;
    }
    EXPECT_NE(R::tuner().verdict(2, c), -1);
  });
}

// Threads in one step and none in the next, which no minimum size gives but
// verdicts may (a win at 16 384 vertices, a loss at 65 536): the serial step
// after a parallel one, in one pass and level by level, gives the serial
// result bit for bit, whether the base uses threads or not.
struct Mixed_catmull_clark_mask : S::Catmull_clark_mask
{};

TEST(SubdivisionParallel, ThreadsThenNoneStayBitIdentical)
{
  using R = S::Refiner<Mixed_catmull_clark_mask>;
  using Plan = S::internal::Parallel_plan;
  R::tuner().clear();
  for (int i = 0; i < 3; ++i) {
    R::tuner().record(2, 16384, true, 1e-3);
    R::tuner().record(2, 16384, false, 2e-3);
    R::tuner().record(2, 65536, true, 2e-3);
    R::tuner().record(2, 65536, false, 1e-3);
  }
  ASSERT_EQ(R::tuner().verdict(2, 14), Plan::parallel);
  ASSERT_EQ(R::tuner().verdict(2, 16), Plan::serial);
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 2);
  tbb::task_arena arena(2);
  arena.execute([&] {
    const Plan plan =
      R::tuner().plan(2, {16384, 65536}, [](std::uint32_t n) { return S::runs_in_parallel(n, S::Refinement_options::automatic); });
    ASSERT_TRUE(plan.parallel_class(14));
    ASSERT_FALSE(plan.parallel_class(16));
    EXPECT_TRUE(plan.parallel_class(15)); // a win below and a loss above as near: the win
    EXPECT_EQ(plan.tried, -1);
    // From 16 384 vertices: threads, then none. From 4 096 (below the
    // floor): none, threads, none, the serial base making the tables of the
    // step with threads.
    for (auto [n, levels] : {std::pair<std::size_t, unsigned>{128, 2}, std::pair<std::size_t, unsigned>{64, 3}}) {
      Mesh torus;
      CGAL_ext::make_torus(torus, n, n);
      const Built b = generated(torus, true);
      for (bool one_pass : {true, false}) {
        SCOPED_TRACE(std::to_string(n) + (one_pass ? ", one pass" : ", level by level"));
        const Refined s =
          refine_with<Mixed_catmull_clark_mask, CGAL::Sequential_tag>(b, S::Refinement_options(), levels, one_pass);
        const Refined p =
          refine_with<Mixed_catmull_clark_mask, CGAL::Parallel_tag>(b, S::Refinement_options(), levels, one_pass);
        EXPECT_TRUE(same_bytes(s.points, p.points));
        EXPECT_TRUE(same_connectivity(s.mesh, p.mesh));
        EXPECT_TRUE(same_bytes(s.mesh.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name)->data(),
                               p.mesh.property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name)->data()));
      }
    }
  });
}

// A mesh with maps of its own refines level by level; then each vertex map
// is interpolated and each child face takes its base face's value. Under
// CGAL::Parallel_tag, with threads in the last step (mask types of their own,
// so that their refiners have no verdicts) and in the maps' loops, the
// points and every map are the serial run's, bit for bit.
struct Carried_catmull_clark_mask : S::Catmull_clark_mask
{};
struct Carried_loop_mask : S::Loop_mask
{};

template <class Mask>
void expect_carried_maps_bit_identical(const std::string& what, const Mesh& base)
{
  SCOPED_TRACE(what);
  using CGAL_ext::Face_index;
  using CGAL_ext::Vertex_index;
  S::Refiner<Mask>::tuner().clear();
  Mesh m = base;
  auto scalar = m.add_property_map<Vertex_index, double>("v:scalar").first;
  auto colour = m.add_property_map<Vertex_index, std::array<float, 3>>("v:colour").first;
  auto label = m.add_property_map<Face_index, int>("f:label").first;
  auto name = m.add_property_map<Face_index, std::string>("f:name").first;
  for (auto v : m.vertices()) {
    const double t = double(v.idx());
    scalar[v] = std::sin(0.37 * t) + 1e-3 * t;
    colour[v] = {float(std::cos(t)), float(0.5 + 0.25 * std::sin(2 * t)), float(t / 7)};
  }
  for (auto f : m.faces()) {
    label[f] = int(7 * f.idx() + 1);
    name[f] = "face " + std::to_string(f.idx());
  }
  Mesh serial = m, parallel = m;
  const auto two = CGAL_ext::parameters::number_of_iterations(2);
  S::subdivide(serial, Mask(), two);
  {
    tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 2);
    tbb::task_arena arena(2);
    arena.execute([&] { S::subdivide<CGAL::Parallel_tag>(parallel, Mask(), two); });
  }
  ASSERT_EQ(serial.number_of_faces(), 16 * base.number_of_faces());
  // The result is large enough for threads in its maps' loops.
  ASSERT_GE(serial.number_of_vertices(), 2 * S::parallel_vertices_per_thread);
  EXPECT_TRUE(same_bytes(serial.points().data(), parallel.points().data()));
  EXPECT_TRUE(same_connectivity(serial, parallel));
  auto data = [](const Mesh& mesh, auto key, auto value, const char* map) {
    return mesh.property_map<decltype(key), decltype(value)>(map).value().data();
  };
  EXPECT_TRUE(same_bytes(data(serial, Vertex_index(), 0.0, "v:scalar"), data(parallel, Vertex_index(), 0.0, "v:scalar")));
  const std::array<float, 3> c{};
  EXPECT_TRUE(same_bytes(data(serial, Vertex_index(), c, "v:colour"), data(parallel, Vertex_index(), c, "v:colour")));
  EXPECT_EQ(data(serial, Face_index(), 0, "f:label"), data(parallel, Face_index(), 0, "f:label"));
  EXPECT_EQ(data(serial, Face_index(), std::string(), "f:name"), data(parallel, Face_index(), std::string(), "f:name"));
}

TEST(SubdivisionParallel, CarriedMapsBitIdenticalToSerial)
{
  Mesh torus, strip;
  CGAL_ext::make_torus(torus, 64, 64); // level 1: 16 384 vertices, threads from there on two
  expect_carried_maps_bit_identical<Carried_catmull_clark_mask>("Catmull-Clark, torus", torus);
  CGAL_ext::make_mobius_strip(strip, 128, 32, 1, 1.0, 0.5, false); // triangles, a border
  expect_carried_maps_bit_identical<Carried_loop_mask>("Loop, Moebius strip", strip);
}
#endif

TEST(SubdivisionApi, RefinerReinterpolatesOtherData)
{
  // Interpolating the points moved by a translation gives the translated
  // result: subdivision is affine invariant (weights sum to 1).
  Mesh m = load("nonorientable/mobius_20x4_quads.obj");
  S::Refiner<S::Catmull_clark_mask> r;
  r.refine(m, 3);
  std::vector<V3> base, moved, out1, out2, scratch;
  for (auto v : m.vertices()) {
    const Point& p = m.point(v);
    base.push_back({p.x(), p.y(), p.z()});
    moved.push_back({p.x() + 1.0, p.y() - 2.0, p.z() + 0.5});
  }
  r.interpolate(base, out1, scratch);
  r.interpolate(moved, out2, scratch);
  ASSERT_EQ(out1.size(), out2.size());
  double worst = 0;
  for (std::size_t i = 0; i < out1.size(); ++i)
    worst = std::max({worst, std::abs(out2[i].x - out1[i].x - 1.0), std::abs(out2[i].y - out1[i].y + 2.0),
                      std::abs(out2[i].z - out1[i].z - 0.5)});
  EXPECT_LE(worst, 1e-12);
  // A scalar field: constants stay constant.
  std::vector<double> ones(m.number_of_vertices(), 1.0), res, tmp;
  r.interpolate(ones, res, tmp);
  for (double x : res)
    EXPECT_NEAR(x, 1.0, 1e-14);
}

// interpolate() is const and writes nothing into the refiner: threads that
// share one refiner get the same bits as one thread alone.
TEST(SubdivisionApi, RefinerInterpolatesFromSeveralThreads)
{
  const Shape s = read_shape(test::data("opensubdiv/catmark_chaikin1.obj"));
  const Built b = build(s);
  S::Refinement_options options;
  options.crease_method = s.crease_method;
  options.parallel_min_vertices = 0; // incidence tables on every level
  S::Refiner<S::Catmull_clark_mask> r(S::Catmull_clark_mask(), options);
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
  r.refine<CGAL::Parallel_tag>(b.mesh, 3, b.edge_sharpness, b.vertex_sharpness);
#else
  r.refine(b.mesh, 3, b.edge_sharpness, b.vertex_sharpness);
#endif
  std::vector<V3> base;
  for (auto v : b.mesh.vertices()) {
    const Point& p = b.mesh.point(v);
    base.push_back({p.x(), p.y(), p.z()});
  }
  std::vector<V3> expected;
  r.interpolate(base, expected);
  std::vector<std::vector<V3>> results(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < results.size(); ++i)
    threads.emplace_back([&, i]() {
#if defined(CGAL_EXT_SUBDIVISION_PARALLEL)
      if (i % 2 == 1) {
        r.interpolate<CGAL::Parallel_tag>(base, results[i]);
        return;
      }
#endif
      r.interpolate(base, results[i]);
    });
  for (std::thread& t : threads)
    t.join();
  for (const std::vector<V3>& result : results) {
    ASSERT_EQ(result.size(), expected.size());
    EXPECT_EQ(std::memcmp(result.data(), expected.data(), expected.size() * sizeof(V3)), 0);
  }
}

// Doo–Sabin's vertex faces are oriented against most of the edge quads
// around them, so the Möbius edges do not multiply from level to level. A
// strip needs at least one Möbius edge per row of faces across it (a seam
// from border to border), and a step makes 2r − 1 rows of r (the faces and
// the quads of the edges between them): on a 12×3 Möbius strip the counts
// are 3, 5, 9, 17, that minimum, where orienting the vertex faces like most
// of their faces gave 3, 9, 13, 37. The surface stays a one-sided strip.
TEST(SubdivisionMobius, DooSabinKeepsFewMobiusEdges)
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3);
  const std::size_t base = CGAL_ext::number_of_mobius_edges(m);
  ASSERT_EQ(base, 3u);
  ASSERT_EQ(CGAL_ext::euler_characteristic(m), 0);
  std::vector<std::size_t> counts{base};
  for (int level = 1; level <= 3; ++level) {
    S::doo_sabin(m);
    ASSERT_TRUE(m.is_valid(true));
    counts.push_back(CGAL_ext::number_of_mobius_edges(m));
    EXPECT_EQ(CGAL_ext::euler_characteristic(m), 0);
    EXPECT_FALSE(CGAL_ext::is_orientable(m));
    EXPECT_EQ(CGAL_ext::number_of_border_cycles(m), 1u);
  }
  for (std::size_t k = 1; k < counts.size(); ++k)
    EXPECT_LE(counts[k], 2 * counts[k - 1] - 1) << ::testing::PrintToString(counts);
  // An orientable mesh stays without Möbius edges.
  Mesh torus;
  CGAL_ext::make_torus(torus, 8, 6);
  S::doo_sabin(torus, CGAL_ext::parameters::number_of_iterations(2));
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(torus), 0u);
  EXPECT_TRUE(CGAL_ext::is_orientable(torus));
}

} // namespace

// ----------------------------------------------------------------- sizes

namespace {

CGAL_ext::Mesh_size counts(const Mesh& m)
{
  CGAL_ext::Mesh_size s{m.number_of_vertices(), m.number_of_edges(), m.number_of_faces(), 0};
  for (auto e : m.edges())
    s.border_edges += m.is_border(e) ? 1 : 0;
  return s;
}

} // namespace

// The limit, from the dart encoding by hand: the flipped dart of the last
// halfedge of edge e is 4e + 3, which must stay below the null dart 2^32 - 1.
TEST(MeshSize, EdgeLimitIsTheLastEdgeWithDarts)
{
  namespace X = CGAL_ext;
  const unsigned long long last = X::internal::max_edges - 1; // the last edge index
  EXPECT_EQ(X::internal::max_edges, (1ull << 30) - 1);
  EXPECT_LT(4 * last + 3, 0xFFFFFFFFull);
  EXPECT_EQ(4 * (last + 1) + 3, 0xFFFFFFFFull); // one edge more: its dart is the null dart
  EXPECT_NE(X::Dart(X::Halfedge_index(std::uint32_t(2 * last + 1)), true), X::Dart());
  X::Mesh_size most, one_more, vertices;
  most.edges = X::internal::max_edges;
  one_more.edges = X::internal::max_edges + 1;
  vertices.vertices = 1ull << 32;
  EXPECT_NO_THROW(X::internal::check_mesh_size("test", most));
  EXPECT_THROW(X::internal::check_mesh_size("test", one_more), X::Size_error);
  EXPECT_THROW(X::internal::check_mesh_size("test", vertices), X::Size_error);
}

// Twelve levels of a strip of 80 quads need about 2.7e9 edges, past the
// 2^30 - 1 that darts index: refused, from counts computed by closed forms,
// before anything is allocated (under ASan, allocating them would abort).
TEST(MeshSize, SubdivisionPastTheLimitIsRefusedBeforeAllocating)
{
  Mesh quads;
  CGAL_ext::make_mobius_strip(quads, 40, 2);
  const CGAL_ext::Mesh_size q0 = counts(quads);
  ASSERT_EQ(q0.faces, 80u);
  const unsigned long long c0 = 4 * q0.faces; // corners
  const long long chi = CGAL_ext::euler_characteristic(quads);
  // Catmull–Clark: all faces quads after one step, F_k = c0 4^(k-1),
  // E_k = 2^k E0 + c0 (4^k - 2^k) / 2, the border doubles, chi is kept.
  for (unsigned k : {1u, 2u, 7u, 11u, 12u}) {
    const auto s = S::refined_size(S::Split::quad, q0, k);
    const unsigned long long p2 = 1ull << k, p4 = 1ull << (2 * k);
    EXPECT_EQ(s.faces, c0 * p4 / 4) << k;
    EXPECT_EQ(s.edges, p2 * q0.edges + c0 * (p4 - p2) / 2) << k;
    EXPECT_EQ(s.border_edges, p2 * q0.border_edges) << k;
    EXPECT_EQ((long long)(s.vertices + s.faces) - (long long)s.edges, chi) << k;
  }
  const unsigned long long e12 = 4096 * q0.edges + c0 * ((1ull << 24) - 4096) / 2;
  EXPECT_GT(e12, 2'600'000'000ull);
  // One level in the real refinement against the closed form.
  Mesh once = quads;
  S::catmull_clark(once);
  EXPECT_EQ(once.number_of_edges(), 2 * q0.edges + c0);
  EXPECT_EQ(once.number_of_vertices(), S::refined_size(S::Split::quad, q0, 1).vertices);

  S::Refiner<S::Catmull_clark_mask> refiner;
  try {
    refiner.refine(quads, 12);
    ADD_FAILURE() << "no Size_error";
  } catch (const CGAL_ext::Size_error& e) {
    EXPECT_EQ(e.element(), "edges");
    EXPECT_EQ(e.count(), e12);
    EXPECT_EQ(e.limit(), (1ull << 30) - 1);
    EXPECT_NE(std::string(e.what()).find(std::to_string(e12)), std::string::npos) << e.what();
  }
  const Mesh before = quads;
  EXPECT_THROW(S::catmull_clark(quads, CGAL_ext::parameters::number_of_iterations(12)), CGAL_ext::Size_error);
  EXPECT_EQ(quads.number_of_edges(), before.number_of_edges());
  // A thousand levels: the estimate stops at the first level past the limit, nothing wraps.
  EXPECT_THROW(S::catmull_clark(quads, CGAL_ext::parameters::number_of_iterations(1000)), CGAL_ext::Size_error);

  // Loop on 160 triangles: F_k = 4^k F0, E_k = 2^k E0 + 3 F0 (4^k - 2^k) / 2.
  Mesh triangles;
  CGAL_ext::make_mobius_strip(triangles, 40, 2, 1, 1.0, 0.5, false);
  const CGAL_ext::Mesh_size t0 = counts(triangles);
  ASSERT_EQ(t0.faces, 160u);
  const auto t12 = S::refined_size(S::Split::triangle, t0, 12);
  EXPECT_EQ(t12.faces, (1ull << 24) * t0.faces);
  EXPECT_EQ(t12.edges, 4096 * t0.edges + 3 * t0.faces * ((1ull << 24) - 4096) / 2);
  EXPECT_THROW(S::loop(triangles, CGAL_ext::parameters::number_of_iterations(12)), CGAL_ext::Size_error);
  // Doo–Sabin and √3: upper bounds, refused alike.
  EXPECT_THROW(S::doo_sabin(quads, CGAL_ext::parameters::number_of_iterations(40)), CGAL_ext::Size_error);
  EXPECT_THROW(S::sqrt3(triangles, CGAL_ext::parameters::number_of_iterations(40)), CGAL_ext::Size_error);
}

// Memory: the estimate is refused up front, naming the gigabytes, and the
// mesh is unchanged. Twelve Catmull–Clark levels of a cube make 6 * 4^12 =
// 100 663 296 quads, which index (201 M edges) but take about 10 GB.
bool same_points(const Mesh& a, const Mesh& b)
{
  if (a.number_of_vertices() != b.number_of_vertices())
    return false;
  for (CGAL_ext::Vertex_index v : a.vertices())
    if (a.point(v) != b.point(v))
      return false;
  return true;
}

TEST(MeshSize, SubdivisionPastTheMemoryLimitIsRefusedBeforeAllocating)
{
  Mesh cube;
  CGAL_ext::polygon_soup_to_mobius_mesh(
    std::vector<Point>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
    std::vector<std::vector<std::size_t>>{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                          {3, 0, 4, 7}},
    cube);
  const Mesh before = cube;
  const auto started = std::chrono::steady_clock::now();
  try {
    S::catmull_clark(cube, CGAL_ext::parameters::number_of_iterations(12).maximum_memory(1e9));
    ADD_FAILURE() << "no Size_error";
  } catch (const CGAL_ext::Size_error& e) {
    EXPECT_EQ(e.element(), "bytes");
    EXPECT_EQ(e.limit(), 1'000'000'000ull);
    // At least the result's points and two halfedges of four indices per edge.
    const unsigned long long quads = 6ull << 24, edges = 2 * quads, vertices = quads + 2;
    EXPECT_GE(e.count(), vertices * sizeof(Point) + edges * 2 * 16) << e.what();
    EXPECT_NE(std::string(e.what()).find("GB of memory"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1.0);
  EXPECT_TRUE(same_points(cube, before));
  EXPECT_EQ(cube.number_of_faces(), 6u);

  // Every scheme reads the limit; a limit that is not positive is refused.
  Mesh triangles;
  CGAL_ext::make_mobius_strip(triangles, 40, 2, 1, 1.0, 0.5, false);
  const auto tight = CGAL_ext::parameters::number_of_iterations(6).maximum_memory(1e6);
  EXPECT_THROW(S::loop(triangles, tight), CGAL_ext::Size_error);
  EXPECT_THROW(S::sqrt3(triangles, tight), CGAL_ext::Size_error);
  EXPECT_THROW(S::doo_sabin(cube, tight), CGAL_ext::Size_error);
  EXPECT_THROW(S::bilinear(cube, tight), CGAL_ext::Size_error);
  for (const double bad : {0.0, -1.0, std::nan("")}) {
    try {
      S::catmull_clark(cube, CGAL_ext::parameters::maximum_memory(bad));
      ADD_FAILURE() << "no error for maximum_memory " << bad;
    } catch (const CGAL_ext::Size_error& e) {
      ADD_FAILURE() << "maximum_memory " << bad << " taken as a limit: " << e.what();
    } catch (const CGAL_ext::Parameter_error& e) {
      EXPECT_NE(std::string(e.what()).find("maximum_memory"), std::string::npos) << e.what();
    }
  }
  // Within the limit, the same result as without one.
  Mesh limited = cube, unlimited = cube;
  S::catmull_clark(limited, CGAL_ext::parameters::number_of_iterations(2).maximum_memory(1e6));
  S::catmull_clark(unlimited, CGAL_ext::parameters::number_of_iterations(2));
  EXPECT_TRUE(same_points(limited, unlimited));

  // By default the limit is the machine's memory: 13 levels of a cube
  // (403 M quads, 805 M edges: indexable) need about 40 GB.
  const double physical = CGAL_ext::internal::physical_memory();
  if (physical > 45e9)
    GTEST_SKIP() << "this machine has " << physical / 1e9 << " GB: 13 levels of a cube may fit";
  EXPECT_THROW(S::catmull_clark(cube, CGAL_ext::parameters::number_of_iterations(13)), CGAL_ext::Size_error);
}

// A Refiner used directly reads the same limit from its options, in both of
// its ways of refining, and keeps nothing of a refused refinement.
TEST(MeshSize, RefinerPastItsMemoryLimitIsRefusedBeforeAllocating)
{
  Mesh strip;
  CGAL_ext::make_mobius_strip(strip, 40, 2, 1, 1.0, 0.5, false);
  S::Refinement_options options;
  options.maximum_memory = 1e6;
  S::Refiner<S::Catmull_clark_mask> refiner(S::Catmull_clark_mask(), options);
  refiner.refine(strip, 1); // 320 quads: well under a megabyte
  ASSERT_EQ(refiner.number_of_levels(), 1u);
  // 7 levels: 80 * 4^7 = 1.3 M quads, at least 1.3 M points of 24 bytes.
  const unsigned long long points = 80ull << 14;
  try {
    refiner.refine(strip, 7);
    ADD_FAILURE() << "no Size_error from refine()";
  } catch (const CGAL_ext::Size_error& e) {
    EXPECT_EQ(e.element(), "bytes");
    EXPECT_EQ(e.limit(), 1'000'000ull);
    EXPECT_GE(e.count(), points * sizeof(Point)) << e.what();
  }
  EXPECT_EQ(refiner.number_of_levels(), 1u) << "the refused call kept nothing of its own";
  std::vector<V3> values(strip.number_of_vertices(), V3{0, 0, 0});
  const std::vector<V3> before = values;
  Mesh out;
  EXPECT_THROW(refiner.refine_and_interpolate(strip, 7, values, out), CGAL_ext::Size_error);
  EXPECT_EQ(values.size(), before.size());
  EXPECT_EQ(out.number_of_vertices(), 0u);
  options.maximum_memory = 0;
  EXPECT_THROW(S::Refiner<S::Catmull_clark_mask>(S::Catmull_clark_mask(), options).refine(strip, 1),
               CGAL_ext::Parameter_error);
}

// ----------------------------------------------------------------- property maps

// Every rule's weights sum to one, and the maps take the points' weights: a
// map that is an affine function of the points is, after subdivision, that
// function of the new points (at borders and creases too). Checked against
// the function evaluated on the result's points.
TEST(SubdivisionMaps, VertexMapsFollowTheirAffineFunctionOfThePoints)
{
  auto scalar = [](const Point& p) { return 2 * p.x() - 3 * p.y() + 0.5 * p.z() + 1; };
  auto colour = [](const Point& p) {
    return std::array<double, 3>{0.5 + 0.1 * p.x(), 0.5 + 0.1 * (p.y() + p.z()), 1 - 0.2 * p.z()};
  };
  auto with_maps = [&](Mesh m) {
    auto s = m.add_property_map<CGAL_ext::Vertex_index, double>("v:scalar").first;
    auto c = m.add_property_map<CGAL_ext::Vertex_index, std::array<double, 3>>("v:colour").first;
    auto rest = m.add_property_map<CGAL_ext::Vertex_index, Point>("v:rest", CGAL::ORIGIN).first;
    auto id = m.add_property_map<CGAL_ext::Vertex_index, int>("v:id").first;
    for (auto v : m.vertices()) {
      s[v] = scalar(m.point(v));
      c[v] = colour(m.point(v));
      rest[v] = m.point(v);
      id[v] = int(v.idx());
    }
    return m;
  };
  auto check = [&](const Mesh& m, const std::string& what) {
    const auto s = m.property_map<CGAL_ext::Vertex_index, double>("v:scalar");
    const auto c = m.property_map<CGAL_ext::Vertex_index, std::array<double, 3>>("v:colour");
    const auto rest = m.property_map<CGAL_ext::Vertex_index, Point>("v:rest");
    ASSERT_TRUE(s && c && rest) << what;
    double worst = 0;
    for (auto v : m.vertices()) {
      const Point& p = m.point(v);
      worst = std::max(worst, std::abs((*s)[v] - scalar(p)));
      for (int i = 0; i < 3; ++i)
        worst = std::max(worst, std::abs((*c)[v][i] - colour(p)[i]));
      worst = std::max(worst, std::sqrt(CGAL::squared_distance((*rest)[v], p)));
    }
    EXPECT_LE(worst, 1e-12) << what;
    // Integers have no linear combination: the map is dropped.
    EXPECT_FALSE((m.property_map<CGAL_ext::Vertex_index, int>("v:id"))) << what;
  };
  Mesh klein;
  CGAL_ext::make_klein_bottle(klein, 8, 6);
  Mesh cc = with_maps(klein);
  S::catmull_clark(cc, CGAL_ext::parameters::number_of_iterations(2));
  ASSERT_EQ(cc.number_of_faces(), 16 * klein.number_of_faces());
  check(cc, "Catmull-Clark, Klein bottle");

  Mesh strip; // triangles, with a border and a crease
  CGAL_ext::make_mobius_strip(strip, 12, 3, 1, 1.0, 0.5, false);
  Mesh lp = with_maps(strip);
  auto sharp = lp.add_property_map<CGAL_ext::Edge_index, float>("e:sharpness", 0.0f).first;
  sharp[CGAL_ext::Edge_index(std::uint32_t(5))] = 2.0f;
  S::loop(lp, CGAL_ext::parameters::number_of_iterations(2));
  ASSERT_EQ(lp.number_of_faces(), 16 * strip.number_of_faces());
  check(lp, "Loop, Möbius strip with a crease");
}

// Each child face takes the value of the face it lies in. The parent is
// read off the result's vertices by the documented layout: Catmull–Clark
// gives face f the vertex nv + ne + f, one per child face; a Loop child face
// has two edge points (nv + e) of two edges of its parent.
TEST(SubdivisionMaps, FaceMapsGoToTheChildFaces)
{
  auto label = [](std::size_t f) { return int(7 * f + 1); };
  auto with_maps = [&](Mesh m) {
    auto l = m.add_property_map<CGAL_ext::Face_index, int>("f:label").first;
    auto n = m.add_property_map<CGAL_ext::Face_index, std::string>("f:name").first;
    for (auto f : m.faces()) {
      l[f] = label(f.idx());
      n[f] = "face " + std::to_string(f.idx());
    }
    return m;
  };
  {
    Mesh torus;
    CGAL_ext::make_torus(torus, 5, 4);
    const std::size_t nv = torus.number_of_vertices(), ne = torus.number_of_edges();
    Mesh m = with_maps(torus);
    S::catmull_clark(m);
    const auto l = m.property_map<CGAL_ext::Face_index, int>("f:label");
    const auto n = m.property_map<CGAL_ext::Face_index, std::string>("f:name");
    ASSERT_TRUE(l && n);
    for (auto g : m.faces()) {
      std::vector<std::size_t> face_points;
      for (auto v : CGAL_ext::vertices_around_face(m.halfedge(g), m))
        if (v.idx() >= nv + ne)
          face_points.push_back(v.idx() - nv - ne);
      ASSERT_EQ(face_points.size(), 1u);
      EXPECT_EQ((*l)[g], label(face_points[0]));
      EXPECT_EQ((*n)[g], "face " + std::to_string(face_points[0]));
    }
  }
  {
    Mesh strip;
    CGAL_ext::make_mobius_strip(strip, 6, 2, 1, 1.0, 0.5, false);
    const std::size_t nv = strip.number_of_vertices();
    auto faces_of_edge = [&](std::size_t e) {
      std::set<std::size_t> faces;
      for (int i : {0, 1}) {
        const auto f = strip.face(Mesh::halfedge(CGAL_ext::Edge_index(std::uint32_t(e)), i));
        if (f.is_valid())
          faces.insert(f.idx());
      }
      return faces;
    };
    Mesh m = with_maps(strip);
    S::loop(m);
    const auto l = m.property_map<CGAL_ext::Face_index, int>("f:label");
    ASSERT_TRUE(l);
    for (auto g : m.faces()) {
      std::vector<std::size_t> edges;
      for (auto v : CGAL_ext::vertices_around_face(m.halfedge(g), m))
        if (v.idx() >= nv)
          edges.push_back(v.idx() - nv);
      ASSERT_GE(edges.size(), 2u);
      const auto a = faces_of_edge(edges[0]), b = faces_of_edge(edges[1]);
      std::vector<std::size_t> common;
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
      ASSERT_EQ(common.size(), 1u);
      EXPECT_EQ((*l)[g], label(common[0]));
    }
  }
}

// Closed forms in exact arithmetic: the Catmull–Clark limit of a cube's
// corner is (3/8) V + (1/6) Σ neighbours + (1/24) Σ opposite corners, which
// is (1/4, 1/4, 1/4) at the origin of the unit cube; the Loop limit of a
// vertex of valence 4 is (1 − 4χ) V + χ Σ neighbours with χ = 31/220
// (Loop's β = 31/256), so (24/55, 0, 0) at (1, 0, 0) of the octahedron.
TEST(SubdivisionLimit, ExactClosedForms)
{
  using K = test::Epeck;
  using FT = K::FT;
  const auto cube = unit_cube<K>();
  EXPECT_EQ(S::limit_point<S::Catmull_clark_mask>(CGAL_ext::Vertex_index(0), cube),
            K::Point_3(FT(1) / 4, FT(1) / 4, FT(1) / 4));
  EXPECT_EQ(S::limit_point<S::Catmull_clark_mask>(CGAL_ext::Vertex_index(6), cube),
            K::Point_3(FT(3) / 4, FT(3) / 4, FT(3) / 4));
  std::vector<K::Point_3> points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<std::size_t, 3>> faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  CGAL_ext::Mobius_mesh<K::Point_3> octahedron;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, faces, octahedron);
  EXPECT_EQ(S::limit_point<S::Loop_mask>(CGAL_ext::Vertex_index(0), octahedron),
            K::Point_3(FT(24) / 55, 0, 0));
  // By symmetry the limit normal at a vertex of the octahedron is radial.
  const auto n = S::limit_normal<S::Loop_mask>(CGAL_ext::internal::vertex_side_dart(CGAL_ext::Vertex_index(0),
                                                                                    octahedron),
                                               octahedron);
  EXPECT_GT(CGAL::to_double(n.x()), 0.0);
  EXPECT_LE(std::abs(CGAL::to_double(n.y())) + std::abs(CGAL::to_double(n.z())), 1e-12 * CGAL::to_double(n.x()));
}

} // namespace subdivision_tests
