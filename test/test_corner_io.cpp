// Texture coordinates and normals in files: OBJ's `vt`/`vn` and `f v/vt/vn`
// corners read into the corner channels "c:uv" and "c:normal" (checked
// against the tests' own parse of the file, corner by corner, also where the
// import reverses faces), PLY's and OFF's per-vertex values, the errors, and
// the writers: OBJ round trips exact to the bit, OFF and PLY written per
// vertex where a channel has no seam and refused where it has one.

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/subdivision.h>

#include "test_util.h"

#include <CGAL/IO/polygon_soup_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace corner_io_tests {

namespace {

namespace fs = std::filesystem;
using CGAL_ext::Dart;
using CGAL_ext::Face_index;
using CGAL_ext::IO_error;
using CGAL_ext::Vertex_index;
using CGAL_ext::IO::read_polygon_mesh;
using CGAL_ext::IO::write_polygon_mesh;

using Point = test::Kd::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using UV = CGAL_ext::Corner_uv<Point>;         // Kd::Point_2
using Normal = CGAL_ext::Corner_normal<Point>; // Kd::Vector_3
using Values = std::vector<double>;
// (face, vertex) -> the value of that corner, as doubles.
using Corner_values = std::map<std::pair<std::size_t, std::size_t>, Values>;

fs::path scratch_directory()
{
  const fs::path dir = fs::temp_directory_path() / ("cgal_ext_corner_io_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& file, const std::string& text)
{
  std::ofstream out(file, std::ios::binary);
  out << text;
}

// The tests' own reading of an OBJ file's corners: for each face (in file
// order) and vertex, the `vt` and `vn` values its corner names (none where
// the face has none).
struct Obj_corners
{
  Corner_values uv, normal;
};

Obj_corners parse_obj_corners(const std::string& file)
{
  std::ifstream in(file);
  EXPECT_TRUE(bool(in)) << file;
  std::vector<Values> vt, vn;
  Obj_corners result;
  std::size_t face = 0;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    Values v;
    double x;
    if (tag == "vt" || tag == "vn") {
      while (ls >> x)
        v.push_back(x);
      v.resize(tag == "vt" ? 2 : 3, 0.0);
      (tag == "vt" ? vt : vn).push_back(v);
    } else if (tag == "f") {
      std::string c;
      while (ls >> c) {
        const std::size_t s1 = c.find('/'), s2 = s1 == std::string::npos ? s1 : c.find('/', s1 + 1);
        const std::size_t vertex = std::stoul(c.substr(0, s1)) - 1;
        const std::string t = s1 == std::string::npos ? "" : c.substr(s1 + 1, s2 - s1 - 1);
        const std::string n = s2 == std::string::npos ? "" : c.substr(s2 + 1);
        if (!t.empty())
          result.uv[{face, vertex}] = vt[std::stoul(t) - 1];
        if (!n.empty())
          result.normal[{face, vertex}] = vn[std::stoul(n) - 1];
      }
      ++face;
    }
  }
  return result;
}

template <class T>
Values as_values(const T& t, int n)
{
  Values v;
  for (int i = 0; i < n; ++i)
    v.push_back(CGAL::to_double(t[i]));
  return v;
}

// The corners of a mesh's channel, as the file parse gives them (faces keep
// the file's order; vertices are the file's points when nothing is merged).
template <class T, class M>
Corner_values mesh_corners(const M& m, const char* name, int n)
{
  Corner_values result;
  const auto channel = m.template corner_channel<T>(name);
  if (!channel)
    return result;
  for (Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      if (channel->has_value(m.corner(d)))
        result[{f.idx(), m.target(d).idx()}] = as_values((*channel)[m.corner(d)], n);
  return result;
}

void expect_read_error(const fs::path& file, std::size_t line, const std::string& part)
{
  Mesh mesh;
  CGAL_ext::make_mobius_strip(mesh, 5, 1);
  const std::size_t before = mesh.number_of_faces();
  try {
    read_polygon_mesh(file.string(), mesh);
    ADD_FAILURE() << file << ": no error";
  } catch (const IO_error& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file.filename().string() + ":"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mesh.number_of_faces(), before); // untouched
  EXPECT_TRUE(mesh.corner_channels().empty());
}

void expect_write_error(const Mesh& mesh, const fs::path& file, const std::string& part)
{
  try {
    write_polygon_mesh(file.string(), mesh);
    ADD_FAILURE() << file << ": no error";
  } catch (const IO_error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(file));
}

// ---------------------------------------------------------------- reading OBJ

TEST(CornerIO, OpenSubdivShapesAreReadCornerByCorner)
{
  for (const char* name : {"catmark_cube.obj", "catmark_chaikin1.obj", "catmark_edgecorner.obj",
                           "catmark_nonquads.obj", "loop_icos_semisharp.obj", "catmark_smoothtris1.obj"}) {
    SCOPED_TRACE(name);
    const std::string file = test::data(std::string("opensubdiv/") + name);
    Mesh m;
    read_polygon_mesh(file, m);
    const Obj_corners expected = parse_obj_corners(file);
    ASSERT_FALSE(expected.uv.empty());
    EXPECT_EQ(mesh_corners<UV>(m, CGAL_ext::corner_uv_name, 2), expected.uv);
    EXPECT_EQ(mesh_corners<Normal>(m, CGAL_ext::corner_normal_name, 3), expected.normal);
    // Every corner has its value (the shapes texture every face).
    for (const auto& s : CGAL_ext::corner_channel_summaries(m))
      EXPECT_EQ(s.corners_without_value, 0u) << s.name;
  }
}

// A cube whose odd faces are listed the other way round: the import
// reverses them to orient the surface, and each corner's values must stay
// at its vertex. Every corner has values of its own (24 vt, 24 vn).
std::string cube_with_reversed_faces()
{
  const int quads[6][4] = {{0, 1, 3, 2}, {2, 3, 5, 4}, {4, 5, 7, 6}, {6, 7, 1, 0}, {1, 7, 5, 3}, {6, 0, 2, 4}};
  std::ostringstream s;
  for (int v = 0; v < 8; ++v)
    s << "v " << (v & 1) << ' ' << ((v >> 1) & 1) << ' ' << (v >> 2) << '\n';
  for (int c = 0; c < 24; ++c)
    s << "vt " << 0.03125 * c << ' ' << 1 - 0.0625 * c << '\n' << "vn " << c << " 0.5 " << -c << '\n';
  for (int f = 0; f < 6; ++f) {
    s << 'f';
    for (int k = 0; k < 4; ++k) {
      const int i = f % 2 == 1 ? 3 - k : k; // odd faces reversed
      s << ' ' << quads[f][i] + 1 << '/' << 4 * f + i + 1 << '/' << 4 * f + i + 1;
    }
    s << '\n';
  }
  return s.str();
}

TEST(CornerIO, CornersFollowTheirVertexWhereTheImportReversesFaces)
{
  const fs::path dir = scratch_directory();
  const fs::path file = dir / "cube.obj";
  write_text(file, cube_with_reversed_faces());
  const Obj_corners expected = parse_obj_corners(file.string());
  for (bool keep : {false, true}) {
    SCOPED_TRACE(keep ? "keep_orientation" : "oriented");
    Mesh m;
    read_polygon_mesh(file.string(), m, CGAL_ext::parameters::keep_orientation(keep));
    if (keep)
      EXPECT_GT(CGAL_ext::number_of_mobius_edges(m), 0u);
    else
      EXPECT_EQ(CGAL_ext::number_of_mobius_edges(m), 0u);
    // Face 1, written 5 6 4 3, walks from its corner 1 as written, or
    // against the file's order once oriented.
    std::vector<std::size_t> walk;
    for (Vertex_index v : CGAL_ext::vertices_around_face(Face_index(1u), m))
      walk.push_back(v.idx());
    EXPECT_EQ(walk, keep ? (std::vector<std::size_t>{5, 3, 2, 4}) : (std::vector<std::size_t>{4, 2, 3, 5}));
    EXPECT_EQ(mesh_corners<UV>(m, CGAL_ext::corner_uv_name, 2), expected.uv);
    EXPECT_EQ(mesh_corners<Normal>(m, CGAL_ext::corner_normal_name, 3), expected.normal);
  }
  fs::remove_all(dir);
}

// Merged points, a reversed face and tags: the tags name the points of the
// file, and their sharpness lands on the vertices those points became.
TEST(CornerIO, TagsAndCornersOnMergedPointsOfReversedFaces)
{
  const fs::path dir = scratch_directory();
  const fs::path file = dir / "square.obj";
  // Triangle (0 1 2), and (0 2 3) written reversed over copies 4 (of 0) and 5 (of 2).
  write_text(file, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 0\nv 1 1 0\n"
                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                   "f 1/1 2/2 3/3\nf 5/5 4/4 6/3\nt corner 1/1/0 3 7\n");
  Mesh m;
  read_polygon_mesh(file.string(), m, CGAL_ext::parameters::tolerance(0.0));
  ASSERT_EQ(m.number_of_vertices(), 4u);
  const auto sharpness = m.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(sharpness);
  const auto uv = *m.corner_channel<UV>(CGAL_ext::corner_uv_name);
  for (Vertex_index v : m.vertices())
    EXPECT_EQ((*sharpness)[v], m.point(v) == Point(0, 1, 0) ? 7.0f : 0.0f) << m.point(v);
  for (Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const Point& p = m.point(m.target(d));
      // The copy of point 0 in the second face carries the seam value (0.5, 0.5).
      const UV expected = f.idx() == 1 && p == Point(0, 0, 0) ? UV(0.5, 0.5) : UV(p.x(), p.y());
      EXPECT_EQ(uv[m.corner(d)], expected) << "face " << f << " at " << p;
    }
  EXPECT_EQ(CGAL_ext::corner_channel_summaries(m).front().seam_edges, 1u); // the diagonal, cut at (0, 0)
  fs::remove_all(dir);
}

// A face without `vt` (or a corner without, as CGAL's reader takes it) has
// corners without a value: neither refused nor filled in.
TEST(CornerIO, FacesWithoutValuesHaveCornersWithoutValue)
{
  const fs::path dir = scratch_directory();
  const fs::path file = dir / "part.obj";
  write_text(file, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                   "f 4 1 3\nf 1/1 2/2 3/3\nf 2//1 5//1 3//1\nf 5/3 6 3/2/1\n");
  Mesh m;
  read_polygon_mesh(file.string(), m);
  const auto summaries = CGAL_ext::corner_channel_summaries(m);
  ASSERT_EQ(summaries.size(), 2u);
  EXPECT_EQ(summaries[0].name, CGAL_ext::corner_uv_name);
  EXPECT_EQ(summaries[0].corners_without_value, 7u);
  EXPECT_EQ(summaries[1].name, CGAL_ext::corner_normal_name);
  EXPECT_EQ(summaries[1].corners_without_value, 8u);
  EXPECT_EQ(mesh_corners<UV>(m, CGAL_ext::corner_uv_name, 2), parse_obj_corners(file.string()).uv);
  // Subdivision refuses a corner without a value, naming it.
  EXPECT_THROW(CGAL_ext::Subdivision::catmull_clark(m), CGAL_ext::Parameter_error);
  // Written back, each face keeps its form (walked from its corner 1; the
  // values numbered in order of first use).
  const fs::path again = dir / "again.obj";
  write_polygon_mesh(again.string(), m);
  std::ifstream in(again);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\nf 1 3 4\nf 2/1 3/2 1/3\nf 5//1 3//1 2//1\nf 6 3/1/1 5/2\n"), std::string::npos) << text;
  Mesh back;
  read_polygon_mesh(again.string(), back);
  EXPECT_EQ(mesh_corners<UV>(back, CGAL_ext::corner_uv_name, 2), mesh_corners<UV>(m, CGAL_ext::corner_uv_name, 2));
  EXPECT_EQ(CGAL_ext::corner_channel_summaries(back)[1].corners_without_value, 8u);
  fs::remove_all(dir);
}

// A Möbius strip of three quads: columns t_k b_k (vertices k and k + 3) at 0,
// 120 and 240 degrees, each a half turn further; quad 2 joins column 2 to
// column 0 turned over, so the faces' own orientations (kept: the surface is
// one-sided) run the same way along t0 b0, its one Möbius edge.
Mesh three_quad_mobius_strip()
{
  const std::vector<Point> points = {{2.5, 0, 0},    {-1.125, 1.9485, 0.433},  {-0.875, -1.5155, 0.433},
                                     {1.5, 0, 0},    {-0.875, 1.5155, -0.433}, {-1.125, -1.9485, -0.433}};
  const std::vector<std::vector<std::size_t>> quads = {{0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 0, 3}};
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, quads, m, CGAL_ext::parameters::keep_orientation(true));
  return m;
}

TEST(CornerIO, SummariesTellMobiusEdgesWithAndWithoutSeam)
{
  Mesh m = three_quad_mobius_strip();
  ASSERT_EQ(m.number_of_faces(), 3u);
  ASSERT_EQ(m.number_of_vertices(), 6u);
  std::size_t mobius = 0;
  for (CGAL_ext::Edge_index e : m.edges()) {
    const std::size_t a = m.vertex(e, 0).idx(), b = m.vertex(e, 1).idx();
    const bool t0_b0 = std::min(a, b) == 0 && std::max(a, b) == 3;
    EXPECT_EQ(m.is_mobius(e), t0_b0) << a << ' ' << b;
    mobius += m.is_mobius(e) ? 1 : 0;
  }
  ASSERT_EQ(mobius, 1u);
  // Value indices: vertex v's own (v) on every corner but those of `cut`,
  // (face, vertex) pairs that get a value of their own.
  const auto summary = [&](const std::vector<std::pair<std::size_t, std::size_t>>& cut) {
    Mesh copy = m;
    auto uv = copy.add_corner_channel<UV>(CGAL_ext::corner_uv_name).first;
    for (std::size_t v = 0; v < 6; ++v)
      uv.add_value(UV(double(v), 0));
    for (Face_index f : copy.faces())
      for (Dart d : CGAL_ext::halfedges_around_face(copy.halfedge(f), copy)) {
        const std::size_t v = copy.target(d).idx();
        const bool own = std::find(cut.begin(), cut.end(), std::make_pair(std::size_t(f.idx()), v)) != cut.end();
        uv.set_index(copy.corner(d), own ? uv.add_value(UV(double(v), 1)) : std::uint32_t(v));
      }
    return CGAL_ext::corner_channel_summaries(copy).front();
  };
  const auto expect = [&](const std::vector<std::pair<std::size_t, std::size_t>>& cut, std::size_t seams,
                          std::size_t continuous, std::size_t seamed) {
    const CGAL_ext::Corner_channel_summary s = summary(cut);
    EXPECT_EQ(s.seam_edges, seams);
    EXPECT_EQ(s.mobius_edges_continuous, continuous);
    EXPECT_EQ(s.mobius_edges_seamed, seamed);
    EXPECT_EQ(s.corners_without_value, 0u);
  };
  expect({}, 0, 1, 0);               // a value per vertex: continuous across the Möbius edge
  expect({{2, 0}, {2, 3}}, 1, 0, 1); // quad 2 cut off along t0 b0 (from quad 0): the Möbius edge a seam
  expect({{2, 0}}, 1, 0, 1);         // ... at one end of it only
  expect({{1, 1}, {1, 4}}, 1, 1, 0); // quad 1 cut off along t1 b1 (from quad 0): a seam elsewhere
  expect({{0, 0}, {0, 3}, {0, 1}, {0, 4}, {1, 2}, {1, 5}}, 3, 0, 1); // every inner edge
}

TEST(CornerIO, BadValuesAndIndicesNameTheLine)
{
  const fs::path dir = scratch_directory();
  const std::string points = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::pair<std::string, std::pair<std::size_t, std::string>> cases[] = {
    {points + "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/5\n", {7, "names texture coordinate 5, but the file has only 3"}},
    {points + "vn 0 0 1\nf 1//1 2//1 3//2\n", {5, "names normal 2, but the file has only 1"}},
    {points + "vt 0 0\nf 1/0 2/1 3/1\n", {5, "texture coordinate indices start at 1"}},
    {points + "vt 0 0\nf 1/-2 2/1 3/1\n", {5, "counts back past the first texture coordinate"}},
    {points + "vt 0 0 0.5\nf 1/1 2/1 3/1\n", {4, "3D texture coordinates are not read"}},
    {points + "vt\nf 1 2 3\n", {4, "a texture coordinate is 'vt u [v [w]]'"}},
    {points + "vn 0 1\nf 1 2 3\n", {4, "a normal has three coordinates"}},
    {points + "vn 0 1 nan\nf 1 2 3\n", {4, "normal coordinate 'nan' is not a finite number"}},
    {points + "vt 0 1e999\nf 1 2 3\n", {4, "texture coordinate '1e999' is not a finite number"}},
    {points + "vt 0 0\nf 1/ 2/1 3/1\n", {5, "is not a vertex index"}},
    {points + "vt 0 0\nf 1/99999999999 2/1 3/1\n", {5, "more than the mesh's 32-bit indices hold"}},
  };
  int k = 0;
  for (const auto& [text, expected] : cases) {
    SCOPED_TRACE(text);
    const fs::path file = dir / ("bad" + std::to_string(k++) + ".obj");
    write_text(file, text);
    expect_read_error(file, expected.first, expected.second);
  }
  // Values may be defined after the faces that name them (as vertices may).
  write_text(dir / "later.obj", "f 1/1 2/2 3/3\n" + points + "vt 0 0\nvt 1 0\nvt 0 1\n");
  Mesh m;
  read_polygon_mesh((dir / "later.obj").string(), m);
  EXPECT_EQ(m.corner_channel<UV>(CGAL_ext::corner_uv_name)->number_of_values(), 3u);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- writing OBJ

// A Möbius strip with texture coordinates that wrap around once (a seam) and
// random normals, values of any 53 bits.
Mesh textured_mobius_strip()
{
  Mesh m;
  CGAL_ext::make_mobius_strip(m, 12, 3, 1, 1.0, 0.4, true);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> any(-3, 3);
  auto uv = m.add_corner_channel<UV>(CGAL_ext::corner_uv_name).first;
  auto normal = m.add_corner_channel<Normal>(CGAL_ext::corner_normal_name).first;
  std::map<std::pair<std::size_t, bool>, std::uint32_t> value_of; // (vertex, wrapped)
  for (Face_index f : m.faces()) {
    bool straddles = false;
    for (Vertex_index v : CGAL_ext::vertices_around_face(f, m))
      straddles = straddles || (m.point(v).y() < 0 && m.point(v).x() < -0.5);
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const Vertex_index v = m.target(d);
      const bool wrapped = straddles && m.point(v).y() >= 0;
      auto [it, fresh] = value_of.emplace(std::make_pair(v.idx(), wrapped), 0);
      if (fresh)
        it->second = uv.add_value(UV(any(random), any(random)));
      uv.set_index(m.corner(d), it->second);
      normal.set_index(m.corner(d), normal.add_value(Normal(any(random), any(random), any(random))));
    }
  }
  return m;
}

TEST(CornerIO, ObjRoundTripsAreExact)
{
  const fs::path dir = scratch_directory();
  const Mesh strip = textured_mobius_strip();
  Mesh cube;
  read_polygon_mesh(test::data("opensubdiv/catmark_chaikin1.obj"), cube);
  for (const Mesh* m : {&strip, static_cast<const Mesh*>(&cube)}) {
    const fs::path file = dir / "round.obj";
    write_polygon_mesh(file.string(), *m);
    Mesh back;
    read_polygon_mesh(file.string(), back);
    EXPECT_EQ(mesh_corners<UV>(back, CGAL_ext::corner_uv_name, 2), mesh_corners<UV>(*m, CGAL_ext::corner_uv_name, 2));
    EXPECT_EQ(mesh_corners<Normal>(back, CGAL_ext::corner_normal_name, 3),
              mesh_corners<Normal>(*m, CGAL_ext::corner_normal_name, 3));
    const auto a = CGAL_ext::corner_channel_summaries(*m), b = CGAL_ext::corner_channel_summaries(back);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].name, b[i].name);
      EXPECT_EQ(a[i].seam_edges, b[i].seam_edges);
    }
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(back), CGAL_ext::number_of_mobius_edges(*m));
  }
  EXPECT_GT(CGAL_ext::corner_channel_summaries(strip).front().seam_edges, 0u);
  fs::remove_all(dir);
}

// The exact kernel reads the values as the doubles of the file, exactly.
TEST(CornerIO, ExactKernelReadsAndWritesTheSameValues)
{
  using Exact_mesh = CGAL_ext::Mobius_mesh<test::Epeck::Point_3>;
  const std::string file = test::data("opensubdiv/catmark_cube.obj");
  Exact_mesh m;
  read_polygon_mesh(file, m);
  EXPECT_EQ((mesh_corners<CGAL_ext::Corner_uv<test::Epeck::Point_3>>(m, CGAL_ext::corner_uv_name, 2)),
            parse_obj_corners(file).uv);
  const fs::path dir = scratch_directory();
  write_polygon_mesh((dir / "exact.obj").string(), m);
  EXPECT_EQ(parse_obj_corners((dir / "exact.obj").string()).uv, parse_obj_corners(file).uv);
  fs::remove_all(dir);
}

// CGAL's own OBJ reader takes the files with vt and vn (it reads over them).
TEST(CornerIO, ObjWithCornersIsReadByCgal)
{
  const fs::path dir = scratch_directory();
  const Mesh strip = textured_mobius_strip();
  write_polygon_mesh((dir / "strip.obj").string(), strip);
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  ASSERT_TRUE(CGAL::IO::read_polygon_soup((dir / "strip.obj").string(), points, polygons));
  EXPECT_EQ(points.size(), strip.number_of_vertices());
  ASSERT_EQ(polygons.size(), strip.number_of_faces());
  for (Face_index f : strip.faces()) {
    std::vector<std::size_t> vs;
    for (Vertex_index v : CGAL_ext::vertices_around_face(f, strip))
      vs.push_back(v.idx());
    EXPECT_EQ(polygons[f.idx()], vs);
  }
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- OFF and PLY

// A torus whose texture coordinates are the points' x and y: no seam.
Mesh seamless_torus()
{
  Mesh m;
  CGAL_ext::make_torus(m, 8, 5, 2.0, 0.5);
  auto uv = m.add_corner_channel<UV>(CGAL_ext::corner_uv_name).first;
  auto normal = m.add_corner_channel<Normal>(CGAL_ext::corner_normal_name).first;
  for (Vertex_index v : m.vertices()) {
    uv.add_value(UV(m.point(v).x(), m.point(v).y() / 3));
    normal.add_value(Normal(m.point(v).z(), 1.0 / 3, m.point(v).x()));
  }
  for (Face_index f : m.faces())
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      uv.set_index(m.corner(d), m.target(d).idx());
      normal.set_index(m.corner(d), m.target(d).idx());
    }
  return m;
}

TEST(CornerIO, OffAndPlyHoldValuesPerVertex)
{
  const fs::path dir = scratch_directory();
  const Mesh torus = seamless_torus();
  // OFF files are written with normals only (NOFF): CGAL's OFF reader
  // misreads STOFF.
  Mesh torus_without_uv = torus;
  torus_without_uv.remove_corner_channel(CGAL_ext::corner_uv_name);
  expect_write_error(torus, dir / "uv.off", "which OFF files are not written with");
  for (const char* name : {"t.ply", "t_ascii.ply", "t.off"}) {
    SCOPED_TRACE(name);
    const fs::path file = dir / name;
    const bool off = std::string(name) == "t.off";
    write_polygon_mesh(file.string(), off ? torus_without_uv : torus,
                       CGAL_ext::parameters::use_binary_mode(std::string(name) != "t_ascii.ply"));
    Mesh back;
    read_polygon_mesh(file.string(), back);
    EXPECT_EQ(mesh_corners<UV>(back, CGAL_ext::corner_uv_name, 2),
              off ? Corner_values() : mesh_corners<UV>(torus, CGAL_ext::corner_uv_name, 2));
    EXPECT_EQ(mesh_corners<Normal>(back, CGAL_ext::corner_normal_name, 3),
              mesh_corners<Normal>(torus, CGAL_ext::corner_normal_name, 3));
    EXPECT_EQ(CGAL_ext::corner_channel_summaries(back).front().seam_edges, 0u);
    // Other readers read the points and faces.
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    EXPECT_TRUE(CGAL::IO::read_polygon_soup(file.string(), points, polygons));
    EXPECT_EQ(polygons.size(), torus.number_of_faces());
  }
  fs::remove_all(dir);
}

TEST(CornerIO, SeamsAndUnknownChannelsAreNotDroppedSilently)
{
  const fs::path dir = scratch_directory();
  const Mesh strip = textured_mobius_strip();
  // A seam: OFF and PLY hold one value per vertex.
  expect_write_error(strip, dir / "s.ply", "has a seam at vertex");
  Mesh strip_normals = strip;
  strip_normals.remove_corner_channel(CGAL_ext::corner_uv_name);
  expect_write_error(strip_normals, dir / "s.off", "write OBJ, which holds a value per face corner");
  Mesh cube;
  read_polygon_mesh(test::data("opensubdiv/catmark_cube.obj"), cube);
  expect_write_error(cube, dir / "c.ply", "PLY files hold one value per vertex");
  // A corner without a value beside corners with values.
  Mesh torus = seamless_torus();
  torus.corner_channel<Normal>(CGAL_ext::corner_normal_name)
    ->set_index(torus.corner(torus.halfedge(Face_index(3u))), CGAL_ext::IO::internal::no_corner_value);
  expect_write_error(torus, dir / "t.ply", "has corners with a value and corners without one");
  // OBJ holds it, corner by corner.
  write_polygon_mesh((dir / "t.obj").string(), torus);
  Mesh back;
  read_polygon_mesh((dir / "t.obj").string(), back);
  EXPECT_EQ(mesh_corners<Normal>(back, CGAL_ext::corner_normal_name, 3),
            mesh_corners<Normal>(torus, CGAL_ext::corner_normal_name, 3));
  EXPECT_EQ(CGAL_ext::corner_channel_summaries(back)[1].corners_without_value, 1u);
  // Channels no format holds, or of a type the writers do not know.
  for (const char* name : {"x.obj", "x.off", "x.ply"}) {
    Mesh m = seamless_torus();
    m.add_corner_channel<double>("c:weight");
    expect_write_error(m, dir / name, "corner channel \"c:weight\", which");
    EXPECT_TRUE(m.remove_corner_channel("c:weight"));
    m.remove_corner_channel(CGAL_ext::corner_uv_name);
    m.add_corner_channel<int>(CGAL_ext::corner_uv_name);
    expect_write_error(m, dir / name, "has values of a type the writers do not know");
  }
  fs::remove_all(dir);
}

TEST(CornerIO, PlyAndOffVertexValuesAreRead)
{
  const fs::path dir = scratch_directory();
  const std::string faces = "3 0 1 2\n3 0 2 3\n";
  write_text(dir / "st.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                             "property float texture_u\nproperty float texture_v\nelement face 2\n"
                             "property list uchar int vertex_indices\nend_header\n"
                             "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 0.5 0\n1 1 0 0 0 1 0.5 0.5\n0 1 0 0 0 -1 0 0.5\n" +
                               faces);
  write_text(dir / "st.off", "STNOFF\n4 2 0\n0 0 0 0 0 1 0 0\n1 0 0 0 0 1 0.5 0\n1 1 0 0 0 1 0.5 0.5\n"
                             "0 1 0 0 0 -1 0 0.5\n" + faces);
  for (const char* name : {"st.ply", "st.off"}) {
    SCOPED_TRACE(name);
    Mesh m;
    read_polygon_mesh((dir / name).string(), m);
    const auto uv = m.corner_channel<UV>(CGAL_ext::corner_uv_name);
    const auto normal = m.corner_channel<Normal>(CGAL_ext::corner_normal_name);
    ASSERT_TRUE(uv && normal);
    for (Face_index f : m.faces())
      for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
        const Point& p = m.point(m.target(d));
        EXPECT_EQ((*uv)[m.corner(d)], UV(p.x() / 2, p.y() / 2));
        EXPECT_EQ((*normal)[m.corner(d)], Normal(0, 0, p == Point(0, 1, 0) ? -1 : 1));
      }
  }
  // Per-face texcoord lists (u v per corner): a value per corner, seams included.
  write_text(dir / "texcoord.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                   "property float z\nproperty float s\nproperty float t\nelement face 2\n"
                                   "property list uchar int vertex_indices\nproperty list uchar float texcoord\n"
                                   "end_header\n0 0 0 9 9\n1 0 0 9 9\n1 1 0 9 9\n0 1 0 9 9\n"
                                   "3 0 1 2 6 0 0 0.5 0 0.5 0.5\n3 0 2 3 6 0.25 0.25 0.5 0.5 0 0.5\n");
  Mesh m;
  read_polygon_mesh((dir / "texcoord.ply").string(), m);
  const Corner_values texcoords = {{{0, 0}, {0, 0}},   {{0, 1}, {0.5, 0}},  {{0, 2}, {0.5, 0.5}},
                                   {{1, 0}, {0.25, 0.25}}, {{1, 2}, {0.5, 0.5}}, {{1, 3}, {0, 0.5}}};
  EXPECT_EQ(mesh_corners<UV>(m, CGAL_ext::corner_uv_name, 2), texcoords);
  EXPECT_EQ(CGAL_ext::corner_channel_summaries(m).front().seam_edges, 1u); // at vertex 0 across the diagonal
  write_text(dir / "texcoord_short.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                         "property float y\nproperty float z\nelement face 1\n"
                                         "property list uchar int vertex_indices\nproperty list uchar float texcoord\n"
                                         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 4 0 0 1 0\n");
  expect_read_error(dir / "texcoord_short.ply", 14, "face 0 has 3 corners but 4 texcoord values");
  // A texture coordinate that is not finite, in a binary file.
  std::string nan_ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                        "property float y\nproperty float z\nproperty float s\nproperty float t\n"
                        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float vertices[3][5] = {{0, 0, 0, 0, 0}, {1, 0, 0, std::nanf(""), 0}, {0, 1, 0, 0, 1}};
  nan_ply.append(reinterpret_cast<const char*>(vertices), sizeof vertices); // little-endian machines
  const std::int32_t face[3] = {0, 1, 2};
  nan_ply += char(3);
  nan_ply.append(reinterpret_cast<const char*>(face), sizeof face);
  write_text(dir / "nan.ply", nan_ply);
  expect_read_error(dir / "nan.ply", 0, "vertex 1 has a texture coordinate or normal that is not a finite number");
  write_text(dir / "short.off", "STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1\n0 1 0 0 1\n3 0 1 2\n");
  expect_read_error(dir / "short.off", 4, "the vertex lacks its texture coordinates");
  fs::remove_all(dir);
}

// PLY files with both: the properties that become corner channels make no
// vertex map, the others do; written back, x y z come first, then the
// channels' nx ny nz and s t, then the maps.
TEST(CornerIO, PlyCornerChannelsBesideVertexMaps)
{
  const fs::path dir = scratch_directory();
  write_text(dir / "both.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                               "property float z\nproperty float quality\nproperty float nx\nproperty float ny\n"
                               "property float nz\nproperty float s\nproperty float t\nproperty uchar label\n"
                               "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0 1.5 0 0 1 0 0 7\n1 0 0 2.5 0 0 1 0.5 0 8\n1 1 0 3.5 0 0 1 0.5 0.5 9\n"
                               "0 1 0 4.5 0 0 1 0 0.5 10\n3 0 1 2\n3 0 2 3\n");
  Mesh m;
  read_polygon_mesh((dir / "both.ply").string(), m);
  ASSERT_TRUE(m.corner_channel<UV>(CGAL_ext::corner_uv_name));
  ASSERT_TRUE(m.corner_channel<Normal>(CGAL_ext::corner_normal_name));
  EXPECT_EQ(m.properties<Vertex_index>(), (std::vector<std::string>{"v:point", "v:quality", "v:label"}));
  const auto quality = m.property_map<Vertex_index, float>("v:quality");
  const auto label = m.property_map<Vertex_index, std::uint8_t>("v:label");
  ASSERT_TRUE(quality && label);
  EXPECT_EQ((*quality)[Vertex_index(2)], 3.5f);
  EXPECT_EQ((*label)[Vertex_index(3)], 10);

  for (bool binary : {false, true}) {
    SCOPED_TRACE(binary);
    const fs::path out = dir / "both_out.ply";
    write_polygon_mesh(out.string(), m, CGAL_ext::parameters::use_binary_mode(binary));
    std::ifstream in(out, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("property double x\nproperty double y\nproperty double z\nproperty double nx\n"
                        "property double ny\nproperty double nz\nproperty double s\nproperty double t\n"
                        "property float quality\nproperty uchar label\nelement face"),
              std::string::npos)
      << text.substr(0, 400);
    Mesh back;
    read_polygon_mesh(out.string(), back);
    const auto uv = back.corner_channel<UV>(CGAL_ext::corner_uv_name);
    const auto normal = back.corner_channel<Normal>(CGAL_ext::corner_normal_name);
    ASSERT_TRUE(uv && normal);
    for (Face_index f : back.faces())
      for (Dart d : CGAL_ext::halfedges_around_face(back.halfedge(f), back)) {
        const Point& p = back.point(back.target(d));
        EXPECT_EQ((*uv)[back.corner(d)], UV(p.x() / 2, p.y() / 2));
        EXPECT_EQ((*normal)[back.corner(d)], Normal(0, 0, 1));
      }
    const auto q = back.property_map<Vertex_index, float>("v:quality");
    const auto l = back.property_map<Vertex_index, std::uint8_t>("v:label");
    ASSERT_TRUE(q && l);
    for (Vertex_index v : back.vertices()) {
      EXPECT_EQ((*q)[v], (*quality)[v]);
      EXPECT_EQ((*l)[v], (*label)[v]);
    }
    EXPECT_EQ(back.properties<Vertex_index>(), (std::vector<std::string>{"v:point", "v:quality", "v:label"}));
  }

  // A map under the name of a written channel property is refused.
  m.add_property_map<Vertex_index, double>("v:nx", 0.0);
  expect_write_error(m, dir / "clash.ply", "the vertex map \"v:nx\"");
  EXPECT_THROW(CGAL_ext::IO::check_output_file((dir / "clash.ply").string(), m), IO_error);
  fs::remove_all(dir);
}

} // namespace

} // namespace corner_io_tests
