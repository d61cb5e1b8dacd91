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
#include <CGAL_ext/subdivision.h>

#include "test_util.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace io_tests {

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

// The names of the entries of `dir`, sorted (hidden ones included).
std::vector<std::string> files_in_directory(const fs::path& dir)
{
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
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

// The bytes of a file, to compare a file before and after a failed write.
std::string file_bytes(const fs::path& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(IO_errors, failed_write_keeps_the_old_file)
{
  const fs::path dir = scratch_directory();
  const fs::path out = dir / "out.obj";
  Mesh_d small, large;
  read_polygon_mesh(test::data("nonorientable/mobius_min_5tris.obj"), small);
  read_polygon_mesh(test::data("nonorientable/torus_24x12_quads.obj"), large);
  write_polygon_mesh(out.string(), small);
  const std::string before = file_bytes(out);
  ASSERT_FALSE(before.empty());
  // A file-size limit below the large mesh's size: the write fails part way
  // (EFBIG), as on a full disk. The old file stays, and no temporary file.
  struct rlimit old_limit;
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  void (*old_handler)(int) = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit limit = old_limit;
  limit.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
  bool threw = false;
  try {
    write_polygon_mesh(out.string(), large);
  } catch (const IO_error& e) {
    threw = true;
    EXPECT_NE(std::string(e.what()).find("the old file is unchanged"), std::string::npos) << e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_TRUE(threw);
  EXPECT_EQ(file_bytes(out), before);
  EXPECT_EQ(files_in_directory(dir), std::vector<std::string>{"out.obj"});
  // A coordinate that cannot be written: refused before the file is touched.
  Mesh_d bad = small;
  bad.point(*bad.vertices().begin()) = test::Kd::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_THROW(write_polygon_mesh(out.string(), bad), IO_error);
  EXPECT_EQ(file_bytes(out), before);
  // Writing over the file that was read: the output replaces the input whole.
  Mesh_d same;
  read_polygon_mesh(out.string(), same);
  write_polygon_mesh(out.string(), same);
  Mesh_d again;
  read_polygon_mesh(out.string(), again);
  EXPECT_EQ(again.number_of_faces(), small.number_of_faces());
  EXPECT_EQ(files_in_directory(dir), std::vector<std::string>{"out.obj"});
  // A directory as the output, and a missing directory: refused up front.
  EXPECT_THROW(write_polygon_mesh(dir.string(), small), IO_error);
  EXPECT_THROW(write_polygon_mesh((dir / "missing" / "x.obj").string(), small), IO_error);
  fs::remove_all(dir);
}

// A pipe has no size to check up front: it is read in blocks up to the
// reader's limit, and one that runs past it is refused, not read until the
// machine runs out of memory. A short one reads as a file does.
TEST(IO_errors, a_fifo_is_read_up_to_the_limit)
{
  const fs::path dir = scratch_directory();
  const fs::path fifo = dir / "mesh.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const auto write_into_fifo = [&](std::size_t copies) {
    return std::thread([&, copies] {
      std::ofstream out(fifo, std::ios::binary);
      for (std::size_t i = 0; i < copies && out; ++i)
        out << triangle;
    });
  };
  std::thread writer = write_into_fifo(1);
  EXPECT_EQ(CGAL_ext::IO::internal::read_whole_file(fifo.string(), 1 << 16), triangle);
  writer.join();
  // 1 MB into a reader that takes 64 kB: refused, naming the file. The
  // writer stops on the broken pipe (SIGPIPE ignored meanwhile).
  void (*old_handler)(int) = std::signal(SIGPIPE, SIG_IGN);
  writer = write_into_fifo((1 << 20) / triangle.size());
  try {
    CGAL_ext::IO::internal::read_whole_file(fifo.string(), 1 << 16);
    ADD_FAILURE() << "a FIFO longer than the limit was read";
  } catch (const IO_error& e) {
    EXPECT_NE(std::string(e.what()).find("mesh.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is longer than 65536 bytes"), std::string::npos) << e.what();
  }
  writer.join();
  std::signal(SIGPIPE, old_handler);
  // A regular file past the limit is refused before it is read.
  std::ofstream(dir / "big.obj") << triangle;
  EXPECT_THROW(CGAL_ext::IO::internal::read_whole_file((dir / "big.obj").string(), 10), IO_error);
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

// ---------------------------------------------------------------- hostile input
//
// Hand-made files of every hostile kind: each gives the right mesh or one
// IO_error naming the file (and the line where there is one), never a crash,
// a silent misread or an allocation beyond what the file can hold.

namespace {

// The vertices of face `f`, in order.
std::vector<std::size_t> face_vertices(const Mesh_d& mesh, CGAL_ext::Face_index f)
{
  std::vector<std::size_t> vertices;
  for (Vertex_index v : CGAL_ext::vertices_around_face(mesh.halfedge(f), mesh))
    vertices.push_back(v.idx());
  return vertices;
}

// Reads `file`, which must hold the triangle (0,0,0) (1,0,0) (0,1,0).
void expect_unit_triangle(const fs::path& file)
{
  SCOPED_TRACE(file.filename().string());
  Mesh_d mesh;
  try {
    read_polygon_mesh(file.string(), mesh);
  } catch (const IO_error& e) {
    ADD_FAILURE() << e.what();
    return;
  }
  ASSERT_EQ(mesh.number_of_vertices(), 3u);
  ASSERT_EQ(mesh.number_of_faces(), 1u);
  EXPECT_EQ(mesh.point(Vertex_index(0u)), test::Kd::Point_3(0, 0, 0));
  EXPECT_EQ(mesh.point(Vertex_index(1u)), test::Kd::Point_3(1, 0, 0));
  EXPECT_EQ(mesh.point(Vertex_index(2u)), test::Kd::Point_3(0, 1, 0));
  EXPECT_EQ(face_vertices(mesh, CGAL_ext::Face_index(0u)).size(), 3u);
}

// Reading `file` must fail with an IO_error at `line` (0: none) whose
// message contains `words`, is one printable line, and leaves the mesh alone.
void expect_read_error(const fs::path& file, std::size_t line, const std::string& words)
{
  SCOPED_TRACE(file.filename().string());
  Mesh_d mesh = prefilled_mesh();
  try {
    read_polygon_mesh(file.string(), mesh);
    ADD_FAILURE() << "no error";
  } catch (const IO_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), file.string());
    EXPECT_EQ(e.line(), line) << what;
    EXPECT_NE(what.find(words), std::string::npos) << what;
    EXPECT_TRUE(std::all_of(what.begin(), what.end(), [](char c) { return c >= 0x20 && c < 0x7f; })) << what;
    EXPECT_LT(what.size(), 400u);
  }
  expect_untouched(mesh);
}

const std::string unit_triangle_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const std::string unit_triangle_off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

std::string replace_all(std::string s, const std::string& from, const std::string& to)
{
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

// Binary values in a given byte order, appended to a string.
struct Bytes
{
  bool big_endian;
  std::string data;
  template <class T>
  Bytes& put(T value)
  {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    const std::uint16_t probe = 1;
    if ((*reinterpret_cast<const char*>(&probe) == 0) != big_endian)
      std::reverse(b, b + sizeof(T));
    data.append(b, sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& s)
  {
    data += s;
    return *this;
  }
};

// The unit triangle as binary OFF (Geomview: big-endian int32 and float32).
std::string binary_off_triangle(const std::string& keyword, int floats_per_vertex, int face_colours)
{
  Bytes b{true, {}};
  b.text(keyword + " BINARY\n").put<std::int32_t>(3).put<std::int32_t>(1).put<std::int32_t>(3);
  const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (const auto& p : xyz) {
    for (float c : p)
      b.put<float>(c);
    for (int extra = 3; extra < floats_per_vertex; ++extra)
      b.put<float>(0.5f);
  }
  b.put<std::int32_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  b.put<std::int32_t>(face_colours);
  for (int c = 0; c < face_colours; ++c)
    b.put<float>(0.25f);
  return b.data;
}

std::string ply_header(const std::string& format, const std::string& vertex_count, const std::string& face_count,
                       const std::string& list_types)
{
  return "ply\nformat " + format + " 1.0\ncomment hand-made\nelement vertex " + vertex_count +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nelement face " + face_count +
         "\nproperty list " + list_types + " vertex_indices\nproperty uchar flags\nelement edge 1\n"
         "property int vertex1\nproperty int vertex2\nend_header\n";
}

// The unit triangle as binary PLY with the index list types `Count` and `Index`.
template <class Count, class Index>
std::string binary_ply_triangle(bool big_endian, const std::string& list_types)
{
  Bytes b{big_endian, {}};
  b.text(ply_header(big_endian ? "binary_big_endian" : "binary_little_endian", "3", "1", list_types));
  const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (const auto& p : xyz)
    b.put<float>(p[0]).put<float>(p[1]).put<float>(p[2]).put<float>(-1.0f);
  b.put<Count>(3);
  for (Index i : {0, 1, 2})
    b.put<Index>(i);
  b.put<std::uint8_t>(7);
  b.put<std::int32_t>(0).put<std::int32_t>(1);
  return b.data;
}

} // namespace

TEST(IO_hostile, obj_corner_with_a_long_texture_index_is_read_as_its_triangle)
{
  // A reader that skips only 256 characters of a corner read this as the quad 1 4 2 3.
  const fs::path dir = scratch_directory();
  // (The texture coordinate 4 exists: a corner naming one that does not is refused.)
  write_text(dir / "zeros.obj",
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 0 0\nvt 0 0\nvt 0 0\nf 1/" + std::string(260, '0') +
               "4 2 3\n");
  Mesh_d mesh;
  read_polygon_mesh((dir / "zeros.obj").string(), mesh);
  ASSERT_EQ(mesh.number_of_faces(), 1u);
  std::vector<std::size_t> corners = face_vertices(mesh, CGAL_ext::Face_index(0u));
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(corners, (std::vector<std::size_t>{0, 1, 2}));
  fs::remove_all(dir);
}

TEST(IO_hostile, line_ends_byte_order_mark_and_comments)
{
  const fs::path dir = scratch_directory();
  const std::string bom = "\xEF\xBB\xBF";
  const std::string obj = "# a triangle\nv 0 0 0\nv 1 0 0 # after a vertex\nv 0 1 0\nf 1 2 3 # after a face\n";
  const std::string off = "OFF # keyword\n3 1 0 # counts\n0 0 0\n1 0 0 # a vertex\n\n0 1 0\n3 0 1 2 # a face\n";
  for (const auto& [name, text] : {std::pair{std::string("a.obj"), obj}, std::pair{std::string("a.off"), off}}) {
    write_text(dir / ("lf_" + name), text);
    write_text(dir / ("crlf_" + name), replace_all(text, "\n", "\r\n"));
    write_text(dir / ("cr_" + name), replace_all(text, "\n", "\r"));
    write_text(dir / ("bom_" + name), bom + text);
    write_text(dir / ("bom_cr_" + name), bom + replace_all(text, "\n", "\r"));
    write_text(dir / ("no_last_end_" + name), text.substr(0, text.size() - 1));
    for (const char* prefix : {"lf_", "crlf_", "cr_", "bom_", "bom_cr_", "no_last_end_"})
      expect_unit_triangle(dir / (prefix + name));
  }
  // Lines are counted the same whatever ends them.
  write_text(dir / "cr_bad.obj", "v 0 0 0\rv 1 0 0\rv 0 x 0\rf 1 2 3\r");
  expect_read_error(dir / "cr_bad.obj", 3, "'x'");
  write_text(dir / "crlf_bad.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 x 0\r\nf 1 2 3\r\n");
  expect_read_error(dir / "crlf_bad.obj", 3, "'x'");
  fs::remove_all(dir);
}

TEST(IO_hostile, numbers_after_the_coordinates_and_words_after_them)
{
  const fs::path dir = scratch_directory();
  // A weight or a colour after x y z is read over; a word is refused.
  write_text(dir / "colour.obj", "v 0 0 0 1 0.5 0\nv 1 0 0 1\nv 0 1 0 0 0 1\nf 1 2 3\n");
  expect_unit_triangle(dir / "colour.obj");
  write_text(dir / "word.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0 red\nf 1 2 3\n");
  expect_read_error(dir / "word.obj", 3, "unexpected 'red' after the vertex coordinates");
  write_text(dir / "word_face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 red\n");
  expect_read_error(dir / "word_face.obj", 4, "'red'");
  fs::remove_all(dir);
}

TEST(IO_hostile, numbers_with_leading_zeros_or_a_hundred_thousand_digits)
{
  const fs::path dir = scratch_directory();
  const std::string zeros(100000, '0');
  write_text(dir / "zeros.obj", "v 0000.0 00 -0\nv " + zeros + "1 0 0\nv 0 0" + zeros + "1.0 " + zeros +
                                  "e5\nf 0001 " + zeros + "2 -" + zeros + "1\n");
  expect_unit_triangle(dir / "zeros.obj");
  write_text(dir / "zeros.off", "OFF\n0003 " + zeros + "1 0\n0 0 0\n1 0 0\n0 1 0\n3 " + zeros + " 01 002\n");
  expect_unit_triangle(dir / "zeros.off");
  // 10^100000 is no finite double; the message shows the start of the number only.
  write_text(dir / "huge.obj", "v 0 0 0\nv 1" + zeros + " 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(dir / "huge.obj", 2, "is not a finite number");
  write_text(dir / "huge_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1" + zeros + "\n");
  expect_read_error(dir / "huge_index.obj", 4, "is not a vertex index");
  fs::remove_all(dir);
}

TEST(IO_hostile, extreme_indices_are_named_by_their_text)
{
  const fs::path dir = scratch_directory();
  const std::string points = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  write_text(dir / "min.obj", points + "f 1 -9223372036854775808 3\n");
  expect_read_error(dir / "min.obj", 4, "'-9223372036854775808' counts back past the first vertex");
  write_text(dir / "below_min.obj", points + "f 1 2 -9223372036854775809\n");
  expect_read_error(dir / "below_min.obj", 4, "'-9223372036854775809' is not a vertex index");
  write_text(dir / "max.obj", points + "f 1 2 9223372036854775807\n");
  expect_read_error(dir / "max.obj", 4, "face names vertex 9223372036854775807, but the file has only 3 vertices");
  write_text(dir / "max.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9223372036854775807\n");
  expect_read_error(dir / "max.off", 6, "face names vertex 9223372036854775807");
  write_text(dir / "negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n");
  expect_read_error(dir / "negative.off", 6, "face names vertex -1");
  fs::remove_all(dir);
}

TEST(IO_hostile, coordinates_must_be_finite_denormals_are_kept)
{
  const fs::path dir = scratch_directory();
  for (const char* bad : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e309", "-1e400", "0x1p3", "1.0.0"}) {
    SCOPED_TRACE(bad);
    write_text(dir / "bad.obj", "v 0 0 0\nv 1 " + std::string(bad) + " 0\nv 0 1 0\nf 1 2 3\n");
    expect_read_error(dir / "bad.obj", 2, "is not a finite number");
    write_text(dir / "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 " + std::string(bad) + "\n0 1 0\n3 0 1 2\n");
    expect_read_error(dir / "bad.off", 4, "is not a finite number");
  }
  write_text(dir / "denormal.obj", "v 4.9406564584124654e-324 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  Mesh_d mesh;
  read_polygon_mesh((dir / "denormal.obj").string(), mesh);
  EXPECT_EQ(mesh.point(Vertex_index(0u)).x(), std::numeric_limits<double>::denorm_min());
  // A homogeneous OFF vertex with w = 0 lies at infinity.
  write_text(dir / "w0.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n3 0 1 2\n");
  expect_read_error(dir / "w0.off", 4, "has no finite position");
  fs::remove_all(dir);
}

TEST(IO_hostile, unprintable_bytes_are_escaped_in_messages)
{
  const fs::path dir = scratch_directory();
  write_text(dir / "nul.obj", std::string("v 0 0 0\nv 1 0\0 0\nv 0 1 0\nf 1 2 3\n", 34));
  expect_read_error(dir / "nul.obj", 2, "'0\\x00' is not a finite number");
  write_text(dir / "control.obj", std::string("v 0 0 0\n\x01\x00\xFF\x1B[2J 1\n", 18));
  expect_read_error(dir / "control.obj", 2, "unknown OBJ statement '\\x01\\x00\\xFF\\x1B[2J'");
  write_text(dir / "control.off", std::string("\x7F" "OFF\n3 1 0\n", 11));
  expect_read_error(dir / "control.off", 1, "the file starts with '\\x7FOFF'");
  fs::remove_all(dir);
}

TEST(IO_hostile, off_variants_are_read)
{
  const fs::path dir = scratch_directory();
  const std::pair<std::string, std::string> variants[] = {
    {"OFF\n3 1 0\n", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
    {"OFF 3 1 0\n", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
    {"OFF\n3 1\n", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
    {"COFF\n3 1 0\n", "0 0 0 255 0 0 255\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2 0.5 0.5 0.5 1\n"},
    {"NOFF\n3 1 0\n", "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"},
    {"STOFF\n3 1 0\n", "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n"},
    {"STCNOFF\n3 1 0\n", "0 0 0 0 0 1 1 1 1 0 0 1\n1 0 0 0 0 1 1 1 1 1 0 1\n0 1 0 0 0 1 1 1 1 0 1\n3 0 1 2 7\n"},
    {"4OFF\n3 1 0\n", "0 0 0 2\n2 0 0 2\n0 -2 0 -2\n3 0 1 2\n"},
    {"nOFF\n3\n3 1 0\n", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
  };
  int k = 0;
  for (const auto& [header, rest] : variants) {
    const fs::path file = dir / ("variant" + std::to_string(k++) + ".off");
    write_text(file, header + rest);
    expect_unit_triangle(file);
  }
  fs::remove_all(dir);
}

TEST(IO_hostile, binary_off_is_read_and_every_truncation_refused)
{
  const fs::path dir = scratch_directory();
  const std::string plain = binary_off_triangle("OFF", 3, 0);
  const std::string coloured = binary_off_triangle("COFF", 7, 4);
  write_text(dir / "plain.off", plain);
  write_text(dir / "coloured.off", coloured);
  write_text(dir / "normals_texture.off", binary_off_triangle("STNOFF", 8, 3));
  expect_unit_triangle(dir / "plain.off");
  expect_unit_triangle(dir / "coloured.off");
  expect_unit_triangle(dir / "normals_texture.off");
  const std::size_t header = std::string("OFF BINARY\n").size();
  for (std::size_t size = header; size < plain.size(); ++size) {
    write_text(dir / "cut.off", plain.substr(0, size));
    SCOPED_TRACE(size);
    Mesh_d mesh;
    EXPECT_THROW(read_polygon_mesh((dir / "cut.off").string(), mesh), IO_error);
  }
  fs::remove_all(dir);
}

TEST(IO_hostile, binary_off_counts_are_believed_only_as_far_as_the_file_holds)
{
  const fs::path dir = scratch_directory();
  auto off = [](std::int32_t vertices, std::int32_t faces) {
    return Bytes{true, {}}.text("OFF BINARY\n").put(vertices).put(faces).put<std::int32_t>(0);
  };
  // 23 bytes that claim 200 million faces (and then 2^31 - 1 vertices).
  write_text(dir / "faces.off", off(0, 200000000).data);
  expect_read_error(dir / "faces.off", 0, "announces 200000000 faces");
  write_text(dir / "vertices.off", off(2147483647, 0).data);
  expect_read_error(dir / "vertices.off", 0, "announces 2147483647 vertices");
  write_text(dir / "negative.off", off(-1, 1).data);
  expect_read_error(dir / "negative.off", 0, "negative");
  // A face of 2^31 - 1 corners in a file of a few dozen bytes.
  Bytes corners = off(3, 1);
  for (int i = 0; i < 9; ++i)
    corners.put<float>(0);
  corners.put<std::int32_t>(2147483647).put<std::int32_t>(0).put<std::int32_t>(1);
  write_text(dir / "corners.off", corners.data);
  expect_read_error(dir / "corners.off", 0, "announces 2147483647 corners in face 0");
  // The same in text OFF.
  write_text(dir / "faces_text.off", "OFF\n3 200000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_read_error(dir / "faces_text.off", 2, "announces 200000000 faces");
  write_text(dir / "more_vertices.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_read_error(dir / "more_vertices.off", 6, "the file ends after 0 of 1 faces");
  fs::remove_all(dir);
}

TEST(IO_hostile, ply_index_lists_of_any_integer_type_and_byte_order)
{
  const fs::path dir = scratch_directory();
  write_text(dir / "ascii_uint8.ply",
             ply_header("ascii", "3", "1", "uchar uchar") + "0 0 0 -1\n1 0 0 -1\n0 1 0 -1\n3 0 1 2 7\n0 1\n");
  write_text(dir / "ascii_int.ply",
             ply_header("ascii", "3", "1", "uint8 int32") + "0 0 0 nan\n1 0 0 inf\n0 1 0 1e3\n3 0 1 2 0\n0 1\n");
  write_text(dir / "le_uint8.ply", binary_ply_triangle<std::uint8_t, std::uint8_t>(false, "uchar uchar"));
  write_text(dir / "le_ushort.ply", binary_ply_triangle<std::uint16_t, std::uint16_t>(false, "ushort ushort"));
  write_text(dir / "be_int.ply", binary_ply_triangle<std::uint8_t, std::int32_t>(true, "uchar int"));
  write_text(dir / "be_uint.ply", binary_ply_triangle<std::int32_t, std::uint32_t>(true, "int uint"));
  for (const char* name : {"ascii_uint8.ply", "ascii_int.ply", "le_uint8.ply", "le_ushort.ply", "be_int.ply",
                           "be_uint.ply"})
    expect_unit_triangle(dir / name);
  fs::remove_all(dir);
}

TEST(IO_hostile, ply_truncated_oversized_or_not_ply_is_refused)
{
  const fs::path dir = scratch_directory();
  const std::string whole = binary_ply_triangle<std::uint8_t, std::int32_t>(false, "uchar int");
  const std::size_t header = whole.find("end_header\n") + 11;
  for (std::size_t size = header; size < whole.size(); ++size) {
    write_text(dir / "cut.ply", whole.substr(0, size));
    SCOPED_TRACE(size);
    Mesh_d mesh;
    EXPECT_THROW(read_polygon_mesh((dir / "cut.ply").string(), mesh), IO_error);
  }
  // A header of a few hundred bytes that claims 300 million vertices.
  write_text(dir / "vertices.ply", ply_header("binary_little_endian", "300000000", "200000000", "uchar int"));
  expect_read_error(dir / "vertices.ply", 4, "announces 300000000 'vertex' elements");
  write_text(dir / "faces.ply", ply_header("ascii", "3", "200000000", "uchar int") + "0 0 0 0\n1 0 0 0\n0 1 0 0\n");
  expect_read_error(dir / "faces.ply", 9, "announces 200000000 'face' elements");
  // A list of 2^32 - 1 items.
  Bytes list{false, ply_header("binary_little_endian", "0", "1", "uint int")};
  list.put<std::uint32_t>(4294967295u);
  for (int i = 0; i < 4; ++i)
    list.put<std::int32_t>(0); // enough bytes for the face, not for its list
  write_text(dir / "list.ply", list.data);
  expect_read_error(dir / "list.ply", 0, "announces 4294967295 items in the list 'vertex_indices' of 'face' 0");
  // A megabyte of zeros, a header that never ends, a NaN coordinate, a negative index.
  write_text(dir / "zeros.ply", std::string(1 << 20, '\0'));
  expect_read_error(dir / "zeros.ply", 1, "not a PLY file");
  write_text(dir / "endless.ply", "ply\nformat ascii 1.0\n" + std::string(1 << 16, '\n'));
  expect_read_error(dir / "endless.ply", 0, "no 'end_header'");
  write_text(dir / "nan.ply", ply_header("ascii", "3", "1", "uchar int") + "0 0 0 0\n1 nan 0 0\n0 1 0 0\n3 0 1 2 0\n0 1\n");
  expect_read_error(dir / "nan.ply", 17, "vertex 1 has a coordinate that is not a finite number");
  write_text(dir / "negative.ply",
             ply_header("ascii", "3", "1", "uchar int") + "0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 -1 2 0\n0 1\n");
  expect_read_error(dir / "negative.ply", 19, "face 0 names vertex -1");
  write_text(dir / "too_big_for_uchar.ply",
             ply_header("ascii", "3", "1", "uchar uchar") + "0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 256 0\n0 1\n");
  expect_read_error(dir / "too_big_for_uchar.ply", 19, "is not a value of its type");
  fs::remove_all(dir);
}

// A header whose counts do not cover the file lies: data after the last
// element is refused (line ends and blanks at the very end are not data).
TEST(IO_hostile, ply_with_more_data_than_its_header_declares_is_refused)
{
  const fs::path dir = scratch_directory();
  const std::string body = "0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 2 0\n0 1\n";
  write_text(dir / "ascii_more.ply", ply_header("ascii", "3", "1", "uchar int") + body + "5 5 5 0\n");
  expect_read_error(dir / "ascii_more.ply", 21, "bytes of data after the last element");
  write_text(dir / "ascii_trailing_lines.ply", ply_header("ascii", "3", "1", "uchar int") + body + "\n \r\n\n");
  expect_unit_triangle(dir / "ascii_trailing_lines.ply");
  const std::string binary = binary_ply_triangle<std::uint8_t, std::int32_t>(false, "uchar int");
  write_text(dir / "binary_more.ply", binary + std::string("\x01\x02\x03\x04", 4));
  expect_read_error(dir / "binary_more.ply", 0, "4 bytes of data after the last element");
  write_text(dir / "binary_newline.ply", binary + "\n");
  expect_unit_triangle(dir / "binary_newline.ply");
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- readable by others

TEST(IO_round_trip, output_without_sharpness_is_read_by_cgal)
{
  // Catmull-Clark twice on the cube: 8 + 12 + 6 = 26 vertices and 24 quads,
  // then 26 + 48 + 24 = 98 vertices and 96 quads. An all-zero sharpness map
  // and no options carry nothing, so no tag line is written, and CGAL's
  // polygon soup readers (which refuse tag lines) read every format back.
  // (The cube's texture coordinates and normals, which OFF and PLY cannot
  // hold at its seams, are tested in test_corner_io.cpp.)
  const fs::path dir = scratch_directory();
  Mesh_d mesh;
  read_polygon_mesh(test::data("opensubdiv/catmark_cube.obj"), mesh);
  EXPECT_TRUE(mesh.remove_corner_channel(CGAL_ext::corner_uv_name));
  EXPECT_TRUE(mesh.remove_corner_channel(CGAL_ext::corner_normal_name));
  CGAL_ext::Subdivision::catmull_clark(mesh, CGAL_ext::parameters::number_of_iterations(2));
  CGAL_ext::edge_sharpness_map(mesh);
  CGAL_ext::vertex_sharpness_map(mesh);
  for (const char* name : {"cube.obj", "cube.off", "cube.ply"}) {
    SCOPED_TRACE(name);
    const std::string file = (dir / name).string();
    write_polygon_mesh(file, mesh);
    std::ifstream in(file, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("\nt "), std::string::npos);
    std::vector<test::Kd::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(file, points, polygons, CGAL::parameters::verbose(false)));
    CGAL::Surface_mesh<test::Kd::Point_3> cgal_mesh;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, cgal_mesh);
    EXPECT_EQ(cgal_mesh.number_of_vertices(), 98u);
    EXPECT_EQ(cgal_mesh.number_of_faces(), 96u);
    EXPECT_TRUE(CGAL::is_closed(cgal_mesh));
  }
  fs::remove_all(dir);
}

TEST(IO_round_trip, write_subdivision_tags_false_writes_what_cgal_reads)
{
  // OpenSubdiv's cube with 12 creased edges, its uv and normals (kept, so
  // that the corners are written as f v/vt/vn, which CGAL's reader takes too).
  const fs::path dir = scratch_directory();
  Mesh_d mesh;
  const CGAL_ext::Sharp_feature_options options =
    read_polygon_mesh(test::data("opensubdiv/catmark_cube_creases1.obj"), mesh);
  ASSERT_TRUE(options.boundary_interpolation);
  const auto slurp = [](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const auto cgal_reads = [](const std::string& file) {
    std::vector<test::Kd::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    const bool read = CGAL::IO::read_polygon_soup(file, points, polygons, CGAL::parameters::verbose(false));
    return read && points.size() == 8 && polygons.size() == 6;
  };
  // By default the sharpness goes into tag lines, which CGAL's reader refuses.
  const std::string tagged = (dir / "tagged.obj").string();
  write_polygon_mesh(tagged, mesh, CGAL_ext::parameters::default_values(), options);
  const std::string tagged_text = slurp(tagged);
  EXPECT_NE(tagged_text.find("\nt crease 2/1/0 "), std::string::npos);
  EXPECT_NE(tagged_text.find("\nt interpolateboundary "), std::string::npos);
  EXPECT_FALSE(cgal_reads(tagged));
  // Without them: no 't' line, and CGAL's polygon soup reader takes the file.
  const std::string plain = (dir / "plain.obj").string();
  write_polygon_mesh(plain, mesh, CGAL_ext::parameters::write_subdivision_tags(false), options);
  const std::string plain_text = slurp(plain);
  EXPECT_EQ(plain_text.find("\nt "), std::string::npos);
  EXPECT_NE(plain_text.find("\nvt "), std::string::npos);
  EXPECT_TRUE(cgal_reads(plain));
  std::vector<test::Kd::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::ifstream in(plain);
  EXPECT_TRUE(CGAL::IO::read_OBJ(in, points, polygons, CGAL::parameters::verbose(false)));
  // What the tags said is lost; the rest reads back as it was.
  Mesh_d back;
  const CGAL_ext::Sharp_feature_options back_options = read_polygon_mesh(plain, back);
  EXPECT_FALSE(back_options.boundary_interpolation);
  EXPECT_FALSE((back.property_map<Edge_index, float>(CGAL_ext::edge_sharpness_name).has_value()));
  EXPECT_EQ(back.number_of_faces(), 6u);
  EXPECT_EQ(back.corner_channels().size(), 2u);
  // write_subdivision_tags(true) is the default.
  const std::string explicit_true = (dir / "true.obj").string();
  write_polygon_mesh(explicit_true, mesh, CGAL_ext::parameters::write_subdivision_tags(true), options);
  EXPECT_EQ(slurp(explicit_true), tagged_text);
  fs::remove_all(dir);
}

TEST(IO_errors, non_finite_coordinates_are_not_written)
{
  const fs::path dir = scratch_directory();
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Mesh_d mesh = prefilled_mesh();
    mesh.point(Vertex_index(3u)) = test::Kd::Point_3(0, bad, 0);
    for (const char* name : {"x.obj", "x.off", "x.ply"}) {
      const fs::path file = dir / name;
      try {
        write_polygon_mesh(file.string(), mesh);
        ADD_FAILURE() << "no error";
      } catch (const IO_error& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 3 has a coordinate that is not a finite double"),
                  std::string::npos)
          << e.what();
      }
      EXPECT_FALSE(fs::exists(file));
    }
  }
  fs::remove_all(dir);
}


// ------------------------------------------------------ PLY vertex properties

namespace {

using Surface_mesh_d = CGAL::Surface_mesh<test::Kd::Point_3>;

// A value for vertex i and map k that differs from vertex to vertex and map
// to map, and fits every type below (0 .. 120).
double ply_test_value(std::size_t i, int k) { return double((i * 7 + std::size_t(k) * 13) % 121); }

// The mesh of `file` with one vertex map of each type CGAL's Surface_mesh
// writer writes, and maps it does not write (no "v:" prefix, a vector, a
// bool, a name that is not a word, a coordinate's name).
Mesh_d mesh_with_vertex_maps(const std::string& file)
{
  Mesh_d mesh;
  read_polygon_mesh(test::data(file), mesh);
  auto fill = [&](auto map, int k) {
    for (Vertex_index v : mesh.vertices())
      map[v] = static_cast<typename decltype(map)::value_type>(ply_test_value(v.idx(), k));
  };
  fill(mesh.add_property_map<Vertex_index, double>("v:distance").first, 0);
  fill(mesh.add_property_map<Vertex_index, float>("v:curvature").first, 1);
  fill(mesh.add_property_map<Vertex_index, std::int8_t>("v:i8").first, 2);
  fill(mesh.add_property_map<Vertex_index, std::uint8_t>("v:u8").first, 3);
  fill(mesh.add_property_map<Vertex_index, std::int16_t>("v:i16").first, 4);
  fill(mesh.add_property_map<Vertex_index, std::uint16_t>("v:u16").first, 5);
  fill(mesh.add_property_map<Vertex_index, std::int32_t>("v:i32").first, 6);
  fill(mesh.add_property_map<Vertex_index, std::uint32_t>("v:u32").first, 7);
  fill(mesh.add_property_map<Vertex_index, std::int64_t>("v:i64").first, 8);
  // The distance is not a small integer everywhere: 17 digits must come back.
  mesh.property_map<Vertex_index, double>("v:distance")->operator[](Vertex_index(3u)) = 0.1 + 1e-17 * 3;
  mesh.property_map<Vertex_index, float>("v:curvature")->operator[](Vertex_index(4u)) = 1.0f / 3.0f;
  mesh.add_property_map<Vertex_index, double>("distance", 1.0);
  mesh.add_property_map<Vertex_index, std::array<double, 3>>("v:vector");
  mesh.add_property_map<Vertex_index, bool>("v:selected", true);
  mesh.add_property_map<Vertex_index, double>("v:two words", 1.0);
  mesh.add_property_map<Vertex_index, double>("v:x", 1.0);
  return mesh;
}

const std::vector<std::string> written_vertex_maps = {"distance", "curvature", "i8",  "u8", "i16",
                                                      "u16",      "i32",       "u32", "i64"};

// The header's vertex property lines of a PLY file.
std::vector<std::string> ply_vertex_properties(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::vector<std::string> properties;
  bool in_vertex = false;
  for (std::string line; std::getline(in, line) && line != "end_header";) {
    if (line.rfind("element ", 0) == 0)
      in_vertex = line.rfind("element vertex ", 0) == 0;
    else if (in_vertex && line.rfind("property ", 0) == 0)
      properties.push_back(line.substr(9));
  }
  return properties;
}

template <class T, class Mesh, class Key>
void expect_map_values(const Mesh& mesh, const std::string& name, int k, Key)
{
  SCOPED_TRACE(name);
  const auto map = mesh.template property_map<Key, T>(name);
  ASSERT_TRUE(map);
  for (auto v : mesh.vertices()) {
    const double expected = v.idx() == 3 && name == "v:distance"   ? 0.1 + 1e-17 * 3
                            : v.idx() == 4 && name == "v:curvature" ? double(1.0f / 3.0f)
                                                                    : ply_test_value(v.idx(), k);
    EXPECT_EQ(double(get(*map, v)), expected) << v;
  }
}

// CGAL's Surface_mesh property maps are optionals of another shape.
template <class T>
struct Surface_mesh_map
{
  Surface_mesh_d::Property_map<Surface_mesh_d::Vertex_index, T> map;
  bool found;
  explicit operator bool() const { return found; }
  const Surface_mesh_d::Property_map<Surface_mesh_d::Vertex_index, T>& operator*() const { return map; }
};

struct Surface_mesh_view
{
  const Surface_mesh_d& mesh;
  template <class Key, class T>
  Surface_mesh_map<T> property_map(const std::string& name) const
  {
    const auto [map, found] = mesh.property_map<Surface_mesh_d::Vertex_index, T>(name);
    return {map, found};
  }
  auto vertices() const { return mesh.vertices(); }
};

template <class MeshView, class Key>
void expect_written_maps(const MeshView& mesh, Key key)
{
  expect_map_values<double>(mesh, "v:distance", 0, key);
  expect_map_values<float>(mesh, "v:curvature", 1, key);
  expect_map_values<std::int8_t>(mesh, "v:i8", 2, key);
  expect_map_values<std::uint8_t>(mesh, "v:u8", 3, key);
  expect_map_values<std::int16_t>(mesh, "v:i16", 4, key);
  expect_map_values<std::uint16_t>(mesh, "v:u16", 5, key);
  expect_map_values<std::int32_t>(mesh, "v:i32", 6, key);
  expect_map_values<std::uint32_t>(mesh, "v:u32", 7, key);
  expect_map_values<std::int32_t>(mesh, "v:i64", 8, key); // written as a 32-bit integer, as CGAL does
}

} // namespace

TEST(IO_ply_vertex_properties, written_as_cgal_writes_them_read_back_by_cgal_and_by_the_library)
{
  // CGAL's Surface_mesh reads orientable surfaces only: the torus for both
  // readers, the Möbius strip for the library's.
  const fs::path dir = scratch_directory();
  for (const auto& [input, binary] : {std::pair("nonorientable/torus_24x12_quads.obj", true),
                                      std::pair("nonorientable/torus_24x12_quads.obj", false),
                                      std::pair("nonorientable/mobius_20x4_tris.obj", true)}) {
    SCOPED_TRACE(std::string(input) + (binary ? " binary" : " ascii"));
    const Mesh_d mesh = mesh_with_vertex_maps(input);
    const bool orientable = CGAL_ext::is_orientable(mesh);
    const std::string file = (dir / (binary ? "binary.ply" : "ascii.ply")).string();
    write_polygon_mesh(file, mesh, CGAL_ext::parameters::use_binary_mode(binary));
    EXPECT_EQ(ply_vertex_properties(file),
              (std::vector<std::string>{"double x", "double y", "double z", "double distance", "float curvature",
                                        "char i8", "uchar u8", "short i16", "ushort u16", "int i32", "uint u32",
                                        "int i64"}));
    // CGAL's Surface_mesh reader: maps of the same names, types and values.
    if (orientable) {
      Surface_mesh_d cgal_mesh;
      std::ifstream in(file, std::ios::binary);
      ASSERT_TRUE(CGAL::IO::read_PLY(in, cgal_mesh));
      ASSERT_EQ(cgal_mesh.number_of_vertices(), mesh.number_of_vertices());
      expect_written_maps(Surface_mesh_view{cgal_mesh}, Surface_mesh_d::Vertex_index());
    }
    // The library's reader: the same.
    Mesh_d back;
    read_polygon_mesh(file, back);
    expect_same_mesh(mesh, back);
    expect_written_maps(back, Vertex_index());
    for (const char* absent : {"v:vector", "v:selected", "v:two words", "v:x", "v:i64"})
      EXPECT_FALSE((back.property_map<Vertex_index, std::int64_t>(absent))) << absent;
  }
  fs::remove_all(dir);
}

TEST(IO_ply_vertex_properties, cgal_surface_mesh_files_are_read_with_their_vertex_maps)
{
  const fs::path dir = scratch_directory();
  Surface_mesh_d cgal_mesh;
  std::vector<test::Kd::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  ASSERT_TRUE(CGAL::IO::read_polygon_soup(test::data("nonorientable/torus_24x12_quads.obj"), points, polygons));
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, cgal_mesh);
  auto heat = cgal_mesh.add_property_map<Surface_mesh_d::Vertex_index, float>("v:heat").first;
  auto label = cgal_mesh.add_property_map<Surface_mesh_d::Vertex_index, std::uint16_t>("v:label").first;
  for (auto v : cgal_mesh.vertices()) {
    heat[v] = float(v.idx()) / 7.0f;
    label[v] = std::uint16_t(v.idx() * 3);
  }
  for (const bool binary : {true, false}) {
    const std::string file = (dir / (binary ? "cgal_binary.ply" : "cgal_ascii.ply")).string();
    {
      std::ofstream out(file, std::ios::binary);
      out.precision(17);
      CGAL::IO::set_mode(out, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
      ASSERT_TRUE(CGAL::IO::write_PLY(out, cgal_mesh));
    }
    Mesh_d mesh;
    read_polygon_mesh(file, mesh);
    ASSERT_EQ(mesh.number_of_vertices(), cgal_mesh.number_of_vertices());
    const auto read_heat = mesh.property_map<Vertex_index, float>("v:heat");
    const auto read_label = mesh.property_map<Vertex_index, std::uint16_t>("v:label");
    ASSERT_TRUE(read_heat && read_label);
    for (Vertex_index v : mesh.vertices()) {
      EXPECT_EQ((*read_heat)[v], float(v.idx()) / 7.0f);
      EXPECT_EQ((*read_label)[v], std::uint16_t(v.idx() * 3));
    }
  }
  fs::remove_all(dir);
}

TEST(IO_ply_vertex_properties, without_maps_the_file_is_cgals_soup_file_byte_for_byte)
{
  const fs::path dir = scratch_directory();
  Mesh_d mesh;
  read_polygon_mesh(test::data("nonorientable/klein_fig8_24x12_quads.obj"), mesh);
  std::vector<test::Kd::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  for (Vertex_index v : mesh.vertices())
    points.push_back(mesh.point(v));
  for (CGAL_ext::Face_index f : mesh.faces()) {
    polygons.emplace_back();
    for (Vertex_index v : CGAL_ext::vertices_around_face(mesh.halfedge(f), mesh))
      polygons.back().push_back(v.idx());
  }
  for (const bool binary : {true, false}) {
    const std::string file = (dir / "mine.ply").string();
    write_polygon_mesh(file, mesh, CGAL_ext::parameters::use_binary_mode(binary));
    std::ostringstream cgal(std::ios::binary);
    CGAL::IO::set_mode(cgal, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
    ASSERT_TRUE(CGAL::IO::write_PLY(cgal, points, polygons, CGAL::parameters::stream_precision(17)));
    std::ifstream in(file, std::ios::binary);
    const std::string mine((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(mine == cgal.str()) << (binary ? "binary" : "ascii");
  }
  fs::remove_all(dir);
}

TEST(IO_ply_vertex_properties, sharpness_travels_and_merged_points_carry_none)
{
  const fs::path dir = scratch_directory();
  // The vertex sharpness map is "v:sharpness": PLY carries corners too.
  Mesh_d mesh;
  read_polygon_mesh(test::data("opensubdiv/catmark_cube_corner4.obj"), mesh);
  ASSERT_TRUE(has_vertex_sharpness(mesh));
  // (Its texture coordinates have seams, which PLY cannot hold.)
  mesh.remove_corner_channel(CGAL_ext::corner_uv_name);
  mesh.remove_corner_channel(CGAL_ext::corner_normal_name);
  const std::string file = (dir / "corners.ply").string();
  write_polygon_mesh(file, mesh);
  Mesh_d back;
  read_polygon_mesh(file, back);
  const auto sharpness = mesh.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  const auto back_sharpness = back.property_map<Vertex_index, float>(CGAL_ext::vertex_sharpness_name);
  ASSERT_TRUE(sharpness && back_sharpness);
  for (Vertex_index v : mesh.vertices())
    EXPECT_EQ((*back_sharpness)[v], (*sharpness)[v]);
  // Points merged on reading: vertex i is no longer point i, no map is made.
  // A property named like the point map is not taken for it.
  write_text(dir / "merged.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                 "property float z\nproperty float point\nelement face 2\n"
                                 "property list uchar int vertex_indices\nend_header\n"
                                 "0 0 0 5\n1 0 0 6\n0 1 0 7\n1 0 0 8\n3 0 1 2\n3 0 2 3\n");
  Mesh_d merged;
  read_polygon_mesh((dir / "merged.ply").string(), merged, CGAL_ext::parameters::tolerance(0.0));
  EXPECT_EQ(merged.number_of_vertices(), 3u);
  EXPECT_EQ(merged.properties<Vertex_index>(), (std::vector<std::string>{"v:point"}));
  Mesh_d unmerged;
  read_polygon_mesh((dir / "merged.ply").string(), unmerged);
  EXPECT_EQ(unmerged.number_of_vertices(), 4u);
  EXPECT_FALSE((unmerged.property_map<Vertex_index, float>("v:point")));
  fs::remove_all(dir);
}

} // namespace io_tests
