// Tests of CGAL_ext/IO/polygon_mesh_io.h: reading OBJ/OFF/PLY, OpenSubdiv's
// OBJ tags, round trips, and the errors for malformed files.
//
// Expected values come from the files themselves: the header line of each
// test/data/nonorientable file, the tag lines of the OpenSubdiv shapes (read
// here by hand), and the first-line comment of each test/data/bad file,
// which names the line at fault.

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Sharp_features.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using CGAL_ext::Edge_index;
using CGAL_ext::IO_error;
using CGAL_ext::Soup_error;
using CGAL_ext::Vertex_index;
using CGAL_ext::IO::read_polygon_mesh;
using CGAL_ext::IO::write_polygon_mesh;

using Mesh_d = CGAL_ext::Mobius_mesh<test::Kd::Point_3>;
using Mesh_e = CGAL_ext::Mobius_mesh<test::Epeck::Point_3>;

struct Stated_topology
{
  std::size_t vertices = 0, edges = 0, faces = 0, border_loops = 0;
  long long chi = 0;
  bool orientable = false;
};

// The value of "key=value" in a header line.
std::string header_field(const std::string& header, const std::string& key)
{
  const std::size_t at = header.find(" " + key + "=");
  if (at == std::string::npos) {
    ADD_FAILURE() << "no " << key << "= in: " << header;
    return "0";
  }
  const std::size_t begin = at + key.size() + 2;
  return header.substr(begin, header.find(' ', begin) - begin);
}

// "# name  V=100 E=180 F=80 chi=0 orientable=False boundary_loops=1"
Stated_topology stated_topology(const fs::path& file)
{
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  Stated_topology t;
  t.vertices = std::stoul(header_field(header, "V"));
  t.edges = std::stoul(header_field(header, "E"));
  t.faces = std::stoul(header_field(header, "F"));
  t.chi = std::stoll(header_field(header, "chi"));
  const std::string orientable = header_field(header, "orientable");
  EXPECT_TRUE(orientable == "True" || orientable == "False") << header;
  t.orientable = orientable == "True";
  t.border_loops = std::stoul(header_field(header, "boundary_loops"));
  return t;
}

std::vector<fs::path> files_in(const std::string& directory)
{
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(test::data(directory)))
    if (entry.is_regular_file())
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The `v` lines of an OBJ file, as doubles.
std::vector<std::array<double, 3>> obj_vertex_lines(const fs::path& file)
{
  std::vector<std::array<double, 3>> points;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string keyword;
    std::array<double, 3> p;
    if (s >> keyword && keyword == "v" && s >> p[0] >> p[1] >> p[2])
      points.push_back(p);
  }
  return points;
}

template <class Mesh>
Edge_index find_edge(const Mesh& mesh, std::size_t a, std::size_t b)
{
  const Vertex_index va(a), vb(b);
  if (mesh.is_isolated(vb))
    return Edge_index();
  for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(vb, mesh))
    if (mesh.source(d) == va)
      return mesh.edge(d);
  return Edge_index();
}

// The sharpness of edge (a, b); NaN if there is no such edge.
template <class Mesh>
float crease(const Mesh& mesh, std::size_t a, std::size_t b)
{
  const auto map = mesh.template property_map<Edge_index, float>(CGAL_ext::edge_sharpness_name);
  const Edge_index e = find_edge(mesh, a, b);
  if (!map || !e.is_valid())
    return std::nanf("");
  return (*map)[e];
}

template <class Mesh>
bool has_edge_sharpness(const Mesh& mesh)
{
  return mesh.template property_map<Edge_index, float>(CGAL_ext::edge_sharpness_name).has_value();
}

template <class Mesh>
bool has_vertex_sharpness(const Mesh& mesh)
{
  return mesh.template property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name).has_value();
}

template <class Mesh>
std::size_t number_of_sharp_edges(const Mesh& mesh)
{
  const auto map = mesh.template property_map<Edge_index, float>(CGAL_ext::edge_sharpness_name);
  std::size_t n = 0;
  for (Edge_index e : mesh.edges())
    n += (map && (*map)[e] != 0) ? 1 : 0;
  return n;
}

// A fresh directory for the files a test writes (tests may run in parallel).
fs::path scratch_directory()
{
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / ("cgal_ext_test_io_" + std::to_string(::getpid()) + "_" +
                                                    info->test_suite_name() + "_" + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& file, const std::string& text)
{
  std::ofstream out(file, std::ios::binary);
  out << text;
}

template <class Mesh>
void expect_stated_topology(const fs::path& file)
{
  SCOPED_TRACE(file.string());
  const Stated_topology t = stated_topology(file);
  Mesh mesh;
  const CGAL_ext::Sharp_feature_options options = read_polygon_mesh(file.string(), mesh);
  EXPECT_TRUE(mesh.is_valid(true));
  EXPECT_EQ(mesh.number_of_vertices(), t.vertices);
  EXPECT_EQ(mesh.number_of_edges(), t.edges);
  EXPECT_EQ(mesh.number_of_faces(), t.faces);
  EXPECT_EQ(CGAL_ext::euler_characteristic(mesh), t.chi);
  EXPECT_EQ(CGAL_ext::is_orientable(mesh), t.orientable);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(mesh), t.border_loops);
  EXPECT_EQ(CGAL_ext::is_closed(mesh), t.border_loops == 0);
  // These files carry no tags.
  EXPECT_FALSE(options.boundary_interpolation || options.crease_method || options.triangle_subdivision);
  EXPECT_FALSE(has_edge_sharpness(mesh));
}

} // namespace

// ---------------------------------------------------------------- reading

TEST(IO_read, nonorientable_files_match_their_header)
{
  const std::vector<fs::path> files = files_in("nonorientable");
  ASSERT_GE(files.size(), 7u);
  for (const fs::path& file : files)
    expect_stated_topology<Mesh_d>(file);
}

TEST(IO_read, nonorientable_files_match_their_header_epeck)
{
  for (const fs::path& file : files_in("nonorientable"))
    expect_stated_topology<Mesh_e>(file);
}

TEST(IO_read, positions_are_those_of_the_file)
{
  // The Möbius strip's first vertex is "v 0.600000000 0.000000000 -0.000000000".
  const std::string file = test::data("nonorientable/mobius_20x4_quads.obj");
  Mesh_d d;
  read_polygon_mesh(file, d);
  const std::vector<std::array<double, 3>> lines = obj_vertex_lines(file);
  ASSERT_EQ(lines.size(), d.number_of_vertices());
  for (Vertex_index v : d.vertices()) {
    EXPECT_EQ(d.point(v).x(), lines[v.idx()][0]);
    EXPECT_EQ(d.point(v).y(), lines[v.idx()][1]);
    EXPECT_EQ(d.point(v).z(), lines[v.idx()][2]);
  }
  EXPECT_EQ(d.point(Vertex_index(0u)).x(), 0.6);

  // An exact kernel reads the decimal text exactly: 0.6 is 3/5, not the double 0.6.
  Mesh_e e;
  read_polygon_mesh(file, e);
  using FT = test::Epeck::FT;
  EXPECT_TRUE(e.point(Vertex_index(0u)).x() == FT(3) / FT(5));
  EXPECT_FALSE(e.point(Vertex_index(0u)).x() == FT(0.6));
  EXPECT_TRUE(e.point(Vertex_index(0u)).y() == FT(0));
}

TEST(IO_read, extension_is_case_insensitive_and_obj_syntax_variants_are_read)
{
  const fs::path dir = scratch_directory();
  // CRLF line ends, tabs, v/vt/vn corners, a relative index (-1: the last
  // vertex so far), a face before its last vertex, comments and groups.
  write_text(dir / "quad.OBJ", "# a unit square\r\n"
                               "o square\r\n"
                               "v 0 0 0\r\n"
                               "v 1 0 0\r\n"
                               "vt 0 0\r\n"
                               "vn 0 0 1\r\n"
                               "v 1 1 0   # third\r\n"
                               "f\t1/1/1\t2//1 -1/1\t4\r\n"
                               "v 0 1 0\r\n");
  Mesh_d mesh;
  read_polygon_mesh((dir / "quad.OBJ").string(), mesh);
  ASSERT_EQ(mesh.number_of_vertices(), 4u);
  ASSERT_EQ(mesh.number_of_faces(), 1u);
  std::vector<std::size_t> cycle;
  for (Vertex_index v : CGAL_ext::vertices_around_face(CGAL_ext::Face_index(0u), mesh))
    cycle.push_back(v.idx());
  std::rotate(cycle.begin(), std::find(cycle.begin(), cycle.end(), 0u), cycle.end());
  EXPECT_EQ(cycle, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.point(Vertex_index(3u)), test::Kd::Point_3(0, 1, 0));

  // OFF with comments, blank lines and counts on the header line.
  write_text(dir / "quad.Off", "OFF 4 1 4 # counts\n\n# vertices\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4  0 1 2 3\n");
  Mesh_d off;
  read_polygon_mesh((dir / "quad.Off").string(), off);
  EXPECT_EQ(off.number_of_vertices(), 4u);
  EXPECT_EQ(off.number_of_edges(), 4u);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(off), 1u);
  fs::remove_all(dir);
}

TEST(IO_read, named_parameters_reach_the_soup_import)
{
  // Two triangles that repeat the points of their common edge: two
  // components as they are, one square once duplicates are merged.
  const fs::path dir = scratch_directory();
  const std::string file = (dir / "two_triangles.obj").string();
  write_text(file, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 4 5 6\n");
  Mesh_d mesh;
  read_polygon_mesh(file, mesh);
  EXPECT_EQ(mesh.number_of_vertices(), 6u);
  EXPECT_EQ(CGAL_ext::connected_components(mesh).count, 2u);
  read_polygon_mesh(file, mesh, CGAL_ext::parameters::tolerance(0.0));
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(mesh.number_of_edges(), 5u);
  EXPECT_EQ(CGAL_ext::connected_components(mesh).count, 1u);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(mesh), 1u);
  // A negative tolerance is a parameter error, not a file error.
  EXPECT_THROW(read_polygon_mesh(file, mesh, CGAL_ext::parameters::tolerance(-1.0)), CGAL_ext::Parameter_error);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- OpenSubdiv tags

TEST(IO_tags, cube_creases1)
{
  // t crease 2/1/0 a b 5.0 for the 11 pairs below, (3, 5) with 0.1; interpolateboundary 2.
  const std::string file = test::data("opensubdiv/catmark_cube_creases1.obj");
  Mesh_d mesh;
  const CGAL_ext::Sharp_feature_options options = read_polygon_mesh(file, mesh);
  ASSERT_EQ(mesh.number_of_vertices(), 8u);
  // Tags count vertices from 0 in the order of the `v` lines.
  const std::vector<std::array<double, 3>> lines = obj_vertex_lines(file);
  for (Vertex_index v : mesh.vertices())
    EXPECT_EQ(mesh.point(v), test::Kd::Point_3(lines[v.idx()][0], lines[v.idx()][1], lines[v.idx()][2]));
  const std::size_t five[][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                 {7, 6}, {6, 4}, {0, 6}, {1, 7}, {2, 4}};
  for (const auto& e : five)
    EXPECT_EQ(crease(mesh, e[0], e[1]), 5.0f) << e[0] << "-" << e[1];
  EXPECT_EQ(crease(mesh, 3, 5), 0.1f);
  EXPECT_EQ(crease(mesh, 5, 3), 0.1f);
  EXPECT_EQ(number_of_sharp_edges(mesh), 12u);
  EXPECT_EQ(options.boundary_interpolation, CGAL_ext::Boundary_interpolation::edge_only);
  EXPECT_FALSE(options.crease_method);
  EXPECT_FALSE(options.triangle_subdivision);
  EXPECT_FALSE(has_vertex_sharpness(mesh));
}

TEST(IO_tags, cube_corner4)
{
  // t corner 1/1/0 0 10.0, nothing else.
  Mesh_d mesh;
  const CGAL_ext::Sharp_feature_options options =
    read_polygon_mesh(test::data("opensubdiv/catmark_cube_corner4.obj"), mesh);
  const auto corners = mesh.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(corners);
  for (Vertex_index v : mesh.vertices())
    EXPECT_EQ((*corners)[v], v.idx() == 0 ? 10.0f : 0.0f);
  EXPECT_FALSE(has_edge_sharpness(mesh));
  EXPECT_FALSE(options.boundary_interpolation || options.crease_method || options.triangle_subdivision);
}

TEST(IO_tags, chaikin1)
{
  Mesh_d mesh;
  const CGAL_ext::Sharp_feature_options options = read_polygon_mesh(test::data("opensubdiv/catmark_chaikin1.obj"), mesh);
  // From the file: 0 1 5, 0 2 1, 1 3 1, 2 4 2, 4 6 3, 6 8 4, 14 16 4, 20 22 1, 23 1 5, 12 13 5.
  EXPECT_EQ(crease(mesh, 0, 1), 5.0f);
  EXPECT_EQ(crease(mesh, 0, 2), 1.0f);
  EXPECT_EQ(crease(mesh, 1, 3), 1.0f);
  EXPECT_EQ(crease(mesh, 2, 4), 2.0f);
  EXPECT_EQ(crease(mesh, 4, 6), 3.0f);
  EXPECT_EQ(crease(mesh, 6, 8), 4.0f);
  EXPECT_EQ(crease(mesh, 14, 16), 4.0f);
  EXPECT_EQ(crease(mesh, 20, 22), 1.0f);
  EXPECT_EQ(crease(mesh, 23, 1), 5.0f);
  EXPECT_EQ(crease(mesh, 12, 13), 5.0f);
  EXPECT_EQ(number_of_sharp_edges(mesh), 28u); // 28 crease lines, each a different edge
  EXPECT_EQ(options.crease_method, CGAL_ext::Crease_method::chaikin);
  EXPECT_FALSE(options.boundary_interpolation);
}

TEST(IO_tags, loop_triangle_edgeonly)
{
  // interpolateboundary 2; corners 15 and 19 at 10, 33 and 34 at 2, 35 at 10.
  Mesh_d mesh;
  const CGAL_ext::Sharp_feature_options options =
    read_polygon_mesh(test::data("opensubdiv/loop_triangle_edgeonly.obj"), mesh);
  EXPECT_EQ(options.boundary_interpolation, CGAL_ext::Boundary_interpolation::edge_only);
  const auto corners = mesh.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(corners);
  std::size_t sharp = 0;
  for (Vertex_index v : mesh.vertices())
    sharp += (*corners)[v] != 0 ? 1 : 0;
  EXPECT_EQ(sharp, 5u);
  EXPECT_EQ((*corners)[Vertex_index(15u)], 10.0f);
  EXPECT_EQ((*corners)[Vertex_index(19u)], 10.0f);
  EXPECT_EQ((*corners)[Vertex_index(33u)], 2.0f);
  EXPECT_EQ((*corners)[Vertex_index(34u)], 2.0f);
  EXPECT_EQ((*corners)[Vertex_index(35u)], 10.0f);
  EXPECT_FALSE(has_edge_sharpness(mesh));
}

TEST(IO_tags, smoothtriangles_and_edge_and_corner)
{
  Mesh_d mesh;
  EXPECT_EQ(read_polygon_mesh(test::data("opensubdiv/catmark_smoothtris1.obj"), mesh).triangle_subdivision,
            CGAL_ext::Triangle_subdivision::smooth);
  EXPECT_EQ(read_polygon_mesh(test::data("opensubdiv/catmark_edgecorner.obj"), mesh).boundary_interpolation,
            CGAL_ext::Boundary_interpolation::edge_and_corner);
}

TEST(IO_tags, pairs_lists_and_unknown_tags)
{
  const fs::path dir = scratch_directory();
  const std::string file = (dir / "square.obj").string();
  write_text(file, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"
                   "t crease 4/2/0 0 1 1 2 1.5 2.5\n" // pairs (0 1) and (1 2), one sharpness each
                   "t crease 4/1/0 2 3 3 0 0.25\n"    // pairs (2 3) and (3 0), one sharpness for both
                   "t corner 2/1/0 1 3 4\n"
                   "t hole 1/0/0 0\n"                 // not a mesh matter: ignored
                   "t creasemethod 0/0/1 normal\n");  // OpenSubdiv's name for uniform
  Mesh_d mesh;
  const CGAL_ext::Sharp_feature_options options = read_polygon_mesh(file, mesh);
  EXPECT_EQ(crease(mesh, 0, 1), 1.5f);
  EXPECT_EQ(crease(mesh, 1, 2), 2.5f);
  EXPECT_EQ(crease(mesh, 2, 3), 0.25f);
  EXPECT_EQ(crease(mesh, 3, 0), 0.25f);
  const auto corners = mesh.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(corners);
  EXPECT_EQ((*corners)[Vertex_index(0u)], 0.0f);
  EXPECT_EQ((*corners)[Vertex_index(1u)], 4.0f);
  EXPECT_EQ((*corners)[Vertex_index(3u)], 4.0f);
  EXPECT_EQ(options.crease_method, CGAL_ext::Crease_method::uniform);
  fs::remove_all(dir);
}

TEST(IO_tags, follow_merged_points)
{
  const fs::path dir = scratch_directory();
  // Two triangles that repeat the points of their common edge (0 = 3, 2 = 4).
  const std::string file = (dir / "two_triangles.obj").string();
  write_text(file, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\n"
                   "f 1 2 3\nf 4 5 6\n"
                   "t crease 2/1/0 3 4 3.5\n" // the common edge, named by the second triangle's points
                   "t corner 1/1/0 3 7.0\n");
  Mesh_d mesh;
  // As they are, points 3 and 4 are joined by an edge of the second triangle.
  read_polygon_mesh(file, mesh);
  EXPECT_EQ(mesh.number_of_vertices(), 6u);
  EXPECT_EQ(crease(mesh, 3, 4), 3.5f);
  EXPECT_EQ(number_of_sharp_edges(mesh), 1u);
  // Merged (tolerance 0: exact duplicates), the common edge joins vertices 0 and 2.
  read_polygon_mesh(file, mesh, CGAL_ext::parameters::tolerance(0.0));
  ASSERT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(mesh.point(Vertex_index(2u)), test::Kd::Point_3(1, 1, 0));
  EXPECT_EQ(crease(mesh, 0, 2), 3.5f);
  EXPECT_EQ(number_of_sharp_edges(mesh), 1u);
  const auto corners = mesh.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(corners);
  EXPECT_EQ((*corners)[Vertex_index(0u)], 7.0f); // point 3 merged into point 0
  fs::remove_all(dir);
}

TEST(IO_tags, follow_split_points)
{
  const fs::path dir = scratch_directory();
  // A bowtie split at its shared point 0: a corner there marks both copies.
  const std::string bowtie = (dir / "bowtie.obj").string();
  write_text(bowtie, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n"
                     "t corner 1/1/0 0 2.0\nt crease 2/1/0 0 3 1.0\n");
  Mesh_d mesh;
  EXPECT_THROW(read_polygon_mesh(bowtie, mesh), IO_error);
  read_polygon_mesh(bowtie, mesh, CGAL_ext::parameters::split_non_manifold_vertices(true));
  ASSERT_EQ(mesh.number_of_vertices(), 6u);
  EXPECT_EQ(CGAL_ext::connected_components(mesh).count, 2u);
  const auto corners = mesh.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(corners);
  std::size_t sharp = 0;
  for (Vertex_index v : mesh.vertices()) {
    if ((*corners)[v] != 0) {
      EXPECT_EQ((*corners)[v], 2.0f);
      EXPECT_EQ(mesh.point(v), test::Kd::Point_3(0, 0, 0));
      ++sharp;
    }
  }
  EXPECT_EQ(sharp, 2u);
  // The crease (0, 3) lies in the second triangle, whichever copy of point 0 it has.
  const auto edge_map = mesh.property_map<Edge_index, float>(CGAL_ext::edge_sharpness_name);
  ASSERT_TRUE(edge_map);
  std::size_t creases = 0;
  for (Edge_index e : mesh.edges()) {
    if ((*edge_map)[e] == 0)
      continue;
    ++creases;
    EXPECT_EQ((*edge_map)[e], 1.0f);
    EXPECT_TRUE(mesh.point(mesh.vertex(e, 0)) == test::Kd::Point_3(-1, 0, 0) ||
                mesh.point(mesh.vertex(e, 1)) == test::Kd::Point_3(-1, 0, 0));
  }
  EXPECT_EQ(creases, 1u);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- round trips

namespace {

// Exercises 17 significant digits: none of these has a short decimal form.
template <class Mesh>
void set_awkward_points(Mesh& mesh)
{
  using Point = typename Mesh::Point;
  mesh.point(Vertex_index(0u)) = Point(1.0 / 3.0, 0.1 + 0.2, std::nextafter(1.0, 2.0));
  mesh.point(Vertex_index(1u)) = Point(-2.0 / 7.0, 3.141592653589793e10, 1e-7 / 3.0);
  mesh.point(Vertex_index(2u)) = Point(-0.0, 5e-324, -1.7976931348623157e308);
}

void expect_same_mesh(const Mesh_d& a, const Mesh_d& b)
{
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  ASSERT_EQ(a.number_of_edges(), b.number_of_edges());
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  EXPECT_TRUE(b.is_valid(true));
  EXPECT_EQ(CGAL_ext::is_orientable(a), CGAL_ext::is_orientable(b));
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(a), CGAL_ext::number_of_border_cycles(b));
  for (Vertex_index v : a.vertices()) {
    // Bit-exact, including the sign of zero.
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(a.point(v)[i], b.point(v)[i]) << v << " coordinate " << i;
      EXPECT_EQ(std::signbit(a.point(v)[i]), std::signbit(b.point(v)[i])) << v << " coordinate " << i;
    }
  }
  // Faces keep their orientation, so the same edges are Möbius edges.
  for (Edge_index e : a.edges()) {
    const Edge_index f = find_edge(b, a.vertex(e, 0).idx(), a.vertex(e, 1).idx());
    ASSERT_TRUE(f.is_valid()) << e;
    EXPECT_EQ(a.is_mobius(e), b.is_mobius(f)) << e;
  }
}

} // namespace

TEST(IO_round_trip, obj_off_ply_keep_counts_mobius_edges_and_exact_positions)
{
  const fs::path dir = scratch_directory();
  Mesh_d mesh;
  read_polygon_mesh(test::data("nonorientable/mobius_20x4_tris.obj"), mesh);
  const std::size_t mobius_left = CGAL_ext::orient(mesh);
  ASSERT_GT(mobius_left, 0u);
  set_awkward_points(mesh);
  for (const char* name : {"strip.obj", "strip.off", "strip.ply", "strip.PLY"}) {
    SCOPED_TRACE(name);
    const std::string file = (dir / name).string();
    write_polygon_mesh(file, mesh);
    Mesh_d back;
    const CGAL_ext::Sharp_feature_options options = read_polygon_mesh(file, back);
    expect_same_mesh(mesh, back);
    EXPECT_EQ(CGAL_ext::number_of_mobius_edges(back), mobius_left);
    EXPECT_FALSE(options.boundary_interpolation || options.crease_method || options.triangle_subdivision);
  }
  // Text PLY and text OFF carry all 17 digits too.
  const std::string ascii = (dir / "ascii.ply").string();
  write_polygon_mesh(ascii, mesh, CGAL_ext::parameters::use_binary_mode(false));
  {
    std::ifstream in(ascii);
    std::string line;
    std::getline(in, line);
    std::getline(in, line);
    EXPECT_EQ(line, "format ascii 1.0");
  }
  Mesh_d back;
  read_polygon_mesh(ascii, back);
  expect_same_mesh(mesh, back);
  fs::remove_all(dir);
}

TEST(IO_round_trip, obj_keeps_tags_and_options)
{
  const fs::path dir = scratch_directory();
  Mesh_d mesh;
  read_polygon_mesh(test::data("nonorientable/mobius_20x4_quads.obj"), mesh);
  auto edges = CGAL_ext::edge_sharpness_map(mesh);
  auto vertices = CGAL_ext::vertex_sharpness_map(mesh);
  edges[Edge_index(0u)] = 2.5f;
  edges[Edge_index(7u)] = 0.1f;
  edges[Edge_index(100u)] = CGAL_ext::infinitely_sharp;
  vertices[Vertex_index(3u)] = 10.0f;
  vertices[Vertex_index(50u)] = 1.0f / 3.0f;
  CGAL_ext::Sharp_feature_options options;
  options.boundary_interpolation = CGAL_ext::Boundary_interpolation::edge_and_corner;
  options.crease_method = CGAL_ext::Crease_method::chaikin;
  options.triangle_subdivision = CGAL_ext::Triangle_subdivision::smooth;

  const std::string file = (dir / "strip.obj").string();
  write_polygon_mesh(file, mesh, CGAL_ext::parameters::default_values(), options);
  Mesh_d back;
  const CGAL_ext::Sharp_feature_options read_options = read_polygon_mesh(file, back);
  expect_same_mesh(mesh, back);
  EXPECT_EQ(read_options.boundary_interpolation, options.boundary_interpolation);
  EXPECT_EQ(read_options.crease_method, options.crease_method);
  EXPECT_EQ(read_options.triangle_subdivision, options.triangle_subdivision);
  for (Edge_index e : mesh.edges())
    EXPECT_EQ(crease(back, mesh.vertex(e, 0).idx(), mesh.vertex(e, 1).idx()), edges[e]) << e;
  const auto back_vertices = back.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(back_vertices);
  for (Vertex_index v : mesh.vertices())
    EXPECT_EQ((*back_vertices)[v], vertices[v]) << v;

  // Maps given as parameters take the place of the mesh's own.
  Mesh_d plain;
  read_polygon_mesh(test::data("nonorientable/mobius_20x4_quads.obj"), plain);
  auto mine = plain.add_property_map<Edge_index, float>("e:mine", 0.0f).first;
  mine[Edge_index(5u)] = 4.0f;
  const std::string other = (dir / "other.obj").string();
  write_polygon_mesh(other, plain, CGAL_ext::parameters::edge_sharpness_map(mine));
  read_polygon_mesh(other, back);
  EXPECT_EQ(number_of_sharp_edges(back), 1u);
  EXPECT_EQ(crease(back, plain.vertex(Edge_index(5u), 0).idx(), plain.vertex(Edge_index(5u), 1).idx()), 4.0f);
  EXPECT_FALSE(has_vertex_sharpness(back));
  fs::remove_all(dir);
}

TEST(IO_round_trip, exact_kernel_writes_doubles)
{
  const fs::path dir = scratch_directory();
  Mesh_e exact;
  read_polygon_mesh(test::data("nonorientable/rp2_hemi_icosahedron.obj"), exact);
  using FT = test::Epeck::FT;
  // 1/3 has no double; the file gets the nearest one.
  exact.point(Vertex_index(0u)) = test::Epeck::Point_3(FT(1) / FT(3), FT(2) / FT(3), FT(-1) / FT(7));
  for (const char* name : {"rp2.obj", "rp2.off", "rp2.ply"}) {
    SCOPED_TRACE(name);
    const std::string file = (dir / name).string();
    write_polygon_mesh(file, exact);
    Mesh_d back;
    read_polygon_mesh(file, back);
    ASSERT_EQ(back.number_of_vertices(), exact.number_of_vertices());
    EXPECT_EQ(back.number_of_faces(), exact.number_of_faces());
    EXPECT_FALSE(CGAL_ext::is_orientable(back));
    EXPECT_EQ(CGAL_ext::euler_characteristic(back), 1);
    for (Vertex_index v : exact.vertices())
      for (int i = 0; i < 3; ++i)
        EXPECT_EQ(back.point(v)[i], CGAL::to_double(exact.point(v)[i]));
    const double third = 1.0 / 3.0, ulp = std::nextafter(third, 1.0) - third;
    EXPECT_LE(std::abs(back.point(Vertex_index(0u)).x() - third), ulp);
    // Read exactly, the 17 digits (OBJ) or the double (OFF, PLY) lie within
    // half a unit in the last place of the double written.
    Mesh_e exact_back;
    read_polygon_mesh(file, exact_back);
    for (Vertex_index v : exact.vertices())
      for (int i = 0; i < 3; ++i) {
        const double written = back.point(v)[i];
        const double half_ulp = (std::nextafter(std::abs(written), HUGE_VAL) - std::abs(written)) / 2;
        EXPECT_TRUE(CGAL::abs(exact_back.point(v)[i] - FT(written)) <= FT(half_ulp)) << v << " " << i;
      }
  }
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- errors

namespace {

struct Expected_error
{
  std::set<std::size_t> lines; // {0}: no line
};

// "... (error at line 7 or 8)" or "... (error with no line)"
Expected_error expected_error(const fs::path& file)
{
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  Expected_error expected;
  const std::string at = "error at line ";
  const std::size_t begin = header.find(at);
  if (begin != std::string::npos) {
    // "7", "7 or 8", ...
    std::istringstream lines(header.substr(begin + at.size(), header.find(')', begin) - begin - at.size()));
    std::string word;
    while (lines >> word)
      if (word != "or")
        expected.lines.insert(std::stoul(word));
  } else if (header.find("error with no line") != std::string::npos) {
    expected.lines.insert(0);
  }
  if (expected.lines.empty())
    ADD_FAILURE() << file << ": the first line does not say where the error is";
  return expected;
}

std::optional<Soup_error::Kind> expected_soup_kind(const std::string& name)
{
  if (name.find("nonmanifold_edge") != std::string::npos)
    return Soup_error::Kind::non_manifold_edge;
  if (name.find("nonmanifold_vertex") != std::string::npos)
    return Soup_error::Kind::non_manifold_vertex;
  if (name.find("repeated_vertex") != std::string::npos)
    return Soup_error::Kind::repeated_vertex;
  return std::nullopt;
}

// A mesh with content and an extra property map, to see that failed reads leave it alone.
Mesh_d prefilled_mesh()
{
  Mesh_d mesh;
  read_polygon_mesh(test::data("nonorientable/mobius_min_5tris.obj"), mesh);
  CGAL_ext::edge_sharpness_map(mesh)[Edge_index(2u)] = 3.0f;
  return mesh;
}

void expect_untouched(const Mesh_d& mesh)
{
  const Mesh_d reference = prefilled_mesh();
  ASSERT_EQ(mesh.number_of_vertices(), reference.number_of_vertices());
  EXPECT_EQ(mesh.number_of_edges(), reference.number_of_edges());
  EXPECT_EQ(mesh.number_of_faces(), reference.number_of_faces());
  EXPECT_TRUE(mesh.is_valid());
  for (Vertex_index v : mesh.vertices())
    EXPECT_EQ(mesh.point(v), reference.point(v));
  EXPECT_EQ(mesh.properties<Edge_index>(), reference.properties<Edge_index>());
  EXPECT_EQ(mesh.properties<Vertex_index>(), reference.properties<Vertex_index>());
  EXPECT_EQ(crease(mesh, mesh.vertex(Edge_index(2u), 0).idx(), mesh.vertex(Edge_index(2u), 1).idx()), 3.0f);
}

} // namespace

TEST(IO_errors, every_bad_file_names_its_line_and_leaves_the_mesh_alone)
{
  const std::vector<fs::path> files = files_in("bad");
  ASSERT_GE(files.size(), 20u);
  for (const fs::path& file : files) {
    const std::string name = file.filename().string();
    SCOPED_TRACE(name);
    const Expected_error expected = expected_error(file);
    Mesh_d mesh = prefilled_mesh();
    try {
      read_polygon_mesh(file.string(), mesh);
      ADD_FAILURE() << "no error";
    } catch (const IO_error& e) {
      EXPECT_EQ(expected.lines.count(e.line()), 1u) << "line " << e.line() << ": " << e.what();
      EXPECT_EQ(e.file(), file.string());
      const std::string prefix = file.string() + (e.line() ? ":" + std::to_string(e.line()) : std::string()) + ": ";
      EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
      EXPECT_EQ(e.soup_kind(), expected_soup_kind(name)) << e.what();
    }
    expect_untouched(mesh);
    // The same with an exact kernel.
    Mesh_e exact;
    try {
      read_polygon_mesh(file.string(), exact);
      ADD_FAILURE() << "no error (EPECK)";
    } catch (const IO_error& e) {
      EXPECT_EQ(expected.lines.count(e.line()), 1u) << "line " << e.line() << ": " << e.what();
    }
    EXPECT_EQ(exact.number_of_vertices(), 0u);
  }
}

TEST(IO_errors, non_manifold_opensubdiv_shape)
{
  // catmark_fan: edge (8, 9) (1-based) lies in the faces on lines 58, 61 and
  // 65, edge (9, 10) in those on lines 57, 62 and 66.
  Mesh_d mesh = prefilled_mesh();
  try {
    read_polygon_mesh(test::data("opensubdiv/catmark_fan.obj"), mesh);
    ADD_FAILURE() << "no error";
  } catch (const IO_error& e) {
    EXPECT_EQ(e.soup_kind(), Soup_error::Kind::non_manifold_edge);
    const std::set<std::size_t> lines = {57, 58, 61, 62, 65, 66};
    EXPECT_EQ(lines.count(e.line()), 1u) << e.what();
  }
  expect_untouched(mesh);
}

TEST(IO_errors, missing_file_unknown_extension_and_unwritable_file)
{
  Mesh_d mesh = prefilled_mesh();
  const std::string missing = test::data("no_such_file.obj");
  try {
    read_polygon_mesh(missing, mesh);
    ADD_FAILURE() << "no error";
  } catch (const IO_error& e) {
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(e.file(), missing);
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_polygon_mesh(test::data("no_such_file.ply"), mesh), IO_error);
  EXPECT_THROW(read_polygon_mesh(test::data("nonorientable"), mesh), IO_error);
  try {
    read_polygon_mesh(test::data("README.md"), mesh);
    ADD_FAILURE() << "no error";
  } catch (const IO_error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown file extension '.md'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_polygon_mesh(test::data("nonorientable/no_extension"), mesh), IO_error);
  expect_untouched(mesh);

  EXPECT_THROW(write_polygon_mesh("/no_such_directory/x.obj", mesh), IO_error);
  const fs::path dir = scratch_directory();
  EXPECT_THROW(write_polygon_mesh((dir / "x.stl").string(), mesh), IO_error);
  EXPECT_FALSE(fs::exists(dir / "x.stl"));
  fs::remove_all(dir);
}

TEST(IO_errors, bad_ply_is_an_error_not_a_crash)
{
  const fs::path dir = scratch_directory();
  write_text(dir / "garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 1\n"
                                  "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n");
  write_text(dir / "not_ply.ply", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  // A PLY whose face names a vertex that does not exist: a soup error, no line.
  write_text(dir / "out_of_range.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                       "property double y\nproperty double z\nelement face 1\n"
                                       "property list uchar int vertex_indices\nend_header\n"
                                       "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  Mesh_d mesh = prefilled_mesh();
  EXPECT_THROW(read_polygon_mesh((dir / "garbage.ply").string(), mesh), IO_error);
  EXPECT_THROW(read_polygon_mesh((dir / "not_ply.ply").string(), mesh), IO_error);
  try {
    read_polygon_mesh((dir / "out_of_range.ply").string(), mesh);
    ADD_FAILURE() << "no error";
  } catch (const IO_error& e) {
    EXPECT_EQ(e.soup_kind(), Soup_error::Kind::index_out_of_range) << e.what();
  }
  expect_untouched(mesh);
  fs::remove_all(dir);
}
