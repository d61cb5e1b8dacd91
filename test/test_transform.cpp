// Copying a Mobius_mesh (also across kernels and into a mesh that is not
// empty), disjoint unions, and affine transformations
// (Mobius_mesh/transform.h). References: the counts and topology stated in
// the test meshes' first line, property maps of the library's and of user
// value types, and exact rationals on EPECK.

#include "test_util.h"

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/corner_data.h>
#include <CGAL_ext/Mobius_mesh/topology.h>
#include <CGAL_ext/Mobius_mesh/transform.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Cartesian_converter.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace transform_tests {

namespace {

using Kd = test::Kd;
using Epeck = test::Epeck;

struct Soup
{
  std::vector<Kd::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  // From the first line of the test files: expected V, E, F, chi, orientability, border loops.
  std::size_t v = 0, e = 0, f = 0, loops = 0;
  long chi = 0;
  bool orientable = false;
};

// A minimal OBJ reader for the test meshes: `v x y z` and `f a b c ...` (1-based, `a/t/n` allowed).
Soup read_obj(const std::string& relative)
{
  Soup soup;
  const bool opened = test::read_obj_lines(
    test::data(relative), [&](double x, double y, double z) { soup.points.emplace_back(x, y, z); },
    [&](const std::vector<std::size_t>& polygon) { soup.polygons.push_back(polygon); },
    [&](const std::string& tag, const std::string& line, std::istream&) {
      if (tag != "#" || line.find("V=") == std::string::npos)
        return;
      auto value = [&](const std::string& key) {
        const std::size_t at = line.find(key);
        return line.substr(at + key.size(), line.find(' ', at) - at - key.size());
      };
      soup.v = std::stoul(value("V="));
      soup.e = std::stoul(value("E="));
      soup.f = std::stoul(value("F="));
      soup.chi = std::stol(value("chi="));
      soup.orientable = value("orientable=") == "True";
      soup.loops = std::stoul(value("boundary_loops="));
    });
  EXPECT_TRUE(opened) << relative;
  return soup;
}

template <class P>
CGAL_ext::Mobius_mesh<P> mesh_of(const Soup& soup)
{
  std::vector<P> points;
  CGAL::Cartesian_converter<Kd, typename CGAL::Kernel_traits<P>::Kernel> convert;
  for (const auto& p : soup.points)
    points.push_back(convert(p));
  CGAL_ext::Mobius_mesh<P> mesh;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, soup.polygons, mesh);
  return mesh;
}

// Face cycles as vertex-index lists, starting at the source of halfedge(f).
template <class P>
std::vector<std::vector<std::size_t>> face_cycles(const CGAL_ext::Mobius_mesh<P>& m)
{
  std::vector<std::vector<std::size_t>> cycles;
  for (auto f : m.faces()) {
    std::vector<std::size_t> c;
    for (auto d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      c.push_back(m.source(d).idx());
    cycles.push_back(c);
  }
  return cycles;
}

TEST(Copy, AcrossKernelsWithIndexMaps)
{
  const Soup soup = read_obj("nonorientable/klein_fig8_24x12_quads.obj");
  auto mesh = mesh_of<Kd::Point_3>(soup);
  auto es = CGAL_ext::edge_sharpness_map(mesh);
  es[CGAL_ext::Edge_index(5u)] = 2.5f;
  CGAL_ext::Mobius_mesh<Epeck::Point_3> copy;
  copy.add_vertex(Epeck::Point_3(9, 9, 9)); // not empty: the copy is appended
  std::vector<std::pair<CGAL_ext::Vertex_index, CGAL_ext::Vertex_index>> vpairs;
  std::vector<std::pair<CGAL_ext::Face_index, CGAL_ext::Face_index>> fpairs;
  const auto off = CGAL_ext::copy_mesh(mesh, copy,
                                       CGAL_ext::parameters::vertex_to_vertex_output_iterator(std::back_inserter(vpairs))
                                         .face_to_face_output_iterator(std::back_inserter(fpairs)));
  EXPECT_EQ(off.vertices, 1u);
  ASSERT_TRUE(copy.is_valid(true));
  EXPECT_EQ(copy.number_of_vertices(), soup.v + 1);
  EXPECT_EQ(copy.number_of_faces(), soup.f);
  EXPECT_EQ(CGAL_ext::is_orientable(copy), false);
  EXPECT_EQ(CGAL_ext::number_of_mobius_edges(copy), CGAL_ext::number_of_mobius_edges(mesh));
  ASSERT_EQ(vpairs.size(), mesh.number_of_vertices());
  for (const auto& [v, c] : vpairs) {
    EXPECT_EQ(c.idx(), v.idx() + 1);
    EXPECT_EQ(copy.point(c), Epeck::Point_3(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()));
  }
  EXPECT_EQ(fpairs.size(), mesh.number_of_faces());
  auto ces = copy.property_map<CGAL_ext::Edge_index, float>("e:sharpness");
  ASSERT_TRUE(ces);
  EXPECT_EQ((*ces)[CGAL_ext::Edge_index(5u + off.edges)], 2.5f);
}

TEST(Copy, DisjointUnionCountsAdd)
{
  const auto a = mesh_of<Kd::Point_3>(read_obj("nonorientable/mobius_20x4_quads.obj"));
  const auto b = mesh_of<Kd::Point_3>(read_obj("nonorientable/rp2_hemi_icosahedron.obj"));
  auto u = a;
  CGAL_ext::disjoint_union(b, u);
  ASSERT_TRUE(u.is_valid(true));
  EXPECT_EQ(u.number_of_vertices(), 106u);
  EXPECT_EQ(CGAL_ext::euler_characteristic(u), 0 + 1);
  EXPECT_EQ(CGAL_ext::connected_components(u).count, 2u);
  EXPECT_EQ(CGAL_ext::number_of_border_cycles(u), 1u);
}

// A value type the library has never heard of.
struct Rgb
{
  int r = -1, g = -1, b = -1;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};
Rgb rgb_of(std::size_t i) { return Rgb{int(i), int(i % 3), -int(i)}; }

TEST(Copy, UserValueTypesCrossKernelsAndUnions)
{
  const auto src = [] {
    auto m = mesh_of<Kd::Point_3>(read_obj("nonorientable/mobius_20x4_quads.obj"));
    auto colour = m.add_property_map<CGAL_ext::Face_index, Rgb>("f:colour").first;
    for (auto f : m.faces())
      colour[f] = rgb_of(f.idx());
    auto mark = m.add_property_map<CGAL_ext::Vertex_index, bool>("v:mark", false).first;
    for (auto v : m.vertices())
      mark[v] = v.idx() % 4 == 1;
    return m;
  }();
  auto check = [&](const auto& dst, std::size_t face_offset, std::size_t vertex_offset) {
    const auto colour = dst.template property_map<CGAL_ext::Face_index, Rgb>("f:colour");
    const auto mark = dst.template property_map<CGAL_ext::Vertex_index, bool>("v:mark");
    ASSERT_TRUE(colour && mark);
    for (std::size_t f = 0; f < face_offset; ++f) // faces that were there before: the default
      EXPECT_EQ((*colour)[CGAL_ext::Face_index(f)], Rgb());
    for (std::size_t f = 0; f < 80; ++f)
      EXPECT_EQ((*colour)[CGAL_ext::Face_index(f + face_offset)], rgb_of(f));
    std::size_t marked = 0;
    for (auto v : dst.vertices())
      marked += (*mark)[v] ? 1 : 0;
    EXPECT_EQ(marked, 25u); // 1, 5, ..., 97
    EXPECT_TRUE((*mark)[CGAL_ext::Vertex_index(vertex_offset + 97)]);
  };

  // Across kernels, appended to a mesh that is not empty.
  CGAL_ext::Mobius_mesh<Epeck::Point_3> exact;
  exact.add_vertex(Epeck::Point_3(9, 9, 9));
  const auto off = CGAL_ext::copy_mesh(src, exact);
  EXPECT_EQ(off.vertices, 1u);
  check(exact, 0, 1);

  // Source first: `dst` grows by `src`, which is left alone.
  auto dst = mesh_of<Kd::Point_3>(read_obj("nonorientable/rp2_hemi_icosahedron.obj"));
  const std::size_t nf = dst.number_of_faces(), nv = dst.number_of_vertices();
  const auto union_off = CGAL_ext::disjoint_union(src, dst);
  EXPECT_EQ(union_off.faces, nf);
  EXPECT_EQ(dst.number_of_faces(), nf + 80);
  EXPECT_EQ(src.number_of_faces(), 80u);
  check(dst, nf, nv);
}

TEST(Transform, ExactOnEpeck)
{
  auto mesh = mesh_of<Epeck::Point_3>(read_obj("nonorientable/mobius_min_5tris.obj"));
  const auto original = mesh;
  // A rotation by a quarter turn about z, a scaling by 1/3 and a translation: exact rationals.
  const CGAL::Aff_transformation_3<Epeck> t(0, -1, 0, Epeck::FT(1) / 2, 1, 0, 0, 0, 0, 0, 1, 5, 3);
  CGAL_ext::transform(mesh, t);
  for (auto v : mesh.vertices()) {
    const auto& p = original.point(v);
    EXPECT_EQ(mesh.point(v), Epeck::Point_3((-p.y() + Epeck::FT(1) / 2) / 3, p.x() / 3, (p.z() + 5) / 3));
  }
  CGAL_ext::transform(mesh, t.inverse());
  for (auto v : mesh.vertices())
    EXPECT_EQ(mesh.point(v), original.point(v));
  EXPECT_EQ(face_cycles(mesh), face_cycles(original));
  EXPECT_TRUE(mesh.is_valid());
}

// A square in the plane z = 0, walked counterclockwise seen from +z, with the
// corner normals `normals` (a value per corner, in the order of its vertices).
template <class P>
CGAL_ext::Mobius_mesh<P> square_with_normals(const std::vector<CGAL_ext::Corner_normal<P>>& normals)
{
  const std::vector<P> points = {P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0)};
  CGAL_ext::Mobius_mesh<P> mesh;
  CGAL_ext::polygon_soup_to_mobius_mesh(points, std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}}, mesh,
                                        CGAL_ext::parameters::keep_orientation(true));
  auto channel = mesh.template add_corner_channel<CGAL_ext::Corner_normal<P>>(CGAL_ext::corner_normal_name).first;
  for (const auto& n : normals)
    channel.add_value(n);
  for (auto d : CGAL_ext::halfedges_around_face(mesh.halfedge(*mesh.faces().begin()), mesh))
    channel.set_index(mesh.corner(d), std::uint32_t(mesh.target(d).idx()));
  return mesh;
}

template <class P>
std::vector<CGAL_ext::Corner_normal<P>> normals_at_vertices(const CGAL_ext::Mobius_mesh<P>& mesh)
{
  const auto channel = mesh.template corner_channel<CGAL_ext::Corner_normal<P>>(CGAL_ext::corner_normal_name);
  std::vector<CGAL_ext::Corner_normal<P>> result(4);
  for (auto d : CGAL_ext::halfedges_around_face(mesh.halfedge(*mesh.faces().begin()), mesh))
    result[mesh.target(d).idx()] = (*channel)[mesh.corner(d)];
  return result;
}

TEST(Transform, CornerNormalsFollowAScaleAndStayUnit)
{
  using V = Kd::Vector_3;
  const double r2 = std::sqrt(2.0), r5 = std::sqrt(5.0);
  auto mesh = square_with_normals<Kd::Point_3>({V(1 / r2, 1 / r2, 0), V(0, 0, 1), V(1, 0, 0), V(0, 0, 2)});
  // Scaling x by 2: a plane x + y = c becomes x/2 + y = c, normal (1, 2, 0)/sqrt(5).
  CGAL_ext::transform(mesh, CGAL::Aff_transformation_3<Kd>(2, 0, 0, 0, 1, 0, 0, 0, 1));
  const auto n = normals_at_vertices(mesh);
  EXPECT_NEAR(n[0].x(), 1 / r5, 1e-15);
  EXPECT_NEAR(n[0].y(), 2 / r5, 1e-15);
  EXPECT_EQ(n[0].z(), 0.0);
  EXPECT_EQ(n[1], V(0, 0, 1)); // normal to the plane of the scaling: unchanged
  EXPECT_EQ(n[2], V(1, 0, 0)); // (1/2, 0, 0), given back its length
  EXPECT_EQ(n[3], V(0, 0, 2)); // a length of 2 stays 2
  EXPECT_EQ(mesh.point(CGAL_ext::Vertex_index(2u)), Kd::Point_3(2, 1, 0));
  // Texture coordinates are not touched.
  EXPECT_EQ(mesh.corner_channels(), std::vector<std::string>{CGAL_ext::corner_normal_name});
}

TEST(Transform, CornerNormalsOfAMirrorAgreeWithTheKeptFaceCycle)
{
  using V = Kd::Vector_3;
  auto mesh = square_with_normals<Kd::Point_3>({V(0, 0, 1), V(0, 0, 1), V(0, 0, 1), V(1, 0, 1)});
  // x -> -x: the face keeps its cycle 0 1 2 3, now clockwise seen from +z,
  // so its normal, the cross product of its edges, is -z.
  CGAL_ext::transform(mesh, CGAL::Aff_transformation_3<Kd>(-1, 0, 0, 0, 1, 0, 0, 0, 1));
  const auto p = [&](unsigned i) { return mesh.point(CGAL_ext::Vertex_index(i)); };
  const V face_normal = CGAL::cross_product(p(1) - p(0), p(2) - p(1));
  EXPECT_EQ(face_normal, V(0, 0, -1));
  const auto n = normals_at_vertices(mesh);
  EXPECT_EQ(n[0], face_normal);
  EXPECT_EQ(n[3], V(1, 0, -1)); // -A^-T (1, 0, 1) = -(-1, 0, 1)
}

TEST(Transform, CornerNormalsAreExactOnEpeck)
{
  using FT = Epeck::FT;
  using V = Epeck::Vector_3;
  auto mesh = square_with_normals<Epeck::Point_3>({V(1, 1, 0), V(1, 2, 3), V(0, 0, 1), V(FT(1) / 3, 0, 1)});
  // A shear and a scale with rationals: A = [[2, 1, 0], [0, 3, 0], [0, 0, 1/5]]
  // (det 6/5), whose inverse transpose, by hand, is
  // [[1/2, 0, 0], [-1/6, 1/3, 0], [0, 0, 5]].
  const CGAL::Aff_transformation_3<Epeck> t(2, 1, 0, 0, 3, 0, 0, 0, FT(1) / 5);
  CGAL_ext::transform(mesh, t);
  const auto n = normals_at_vertices(mesh);
  const auto expected = [](const V& m) {
    return V(m.x() / 2, -m.x() / 6 + m.y() / 3, 5 * m.z());
  };
  EXPECT_EQ(n[0], expected(V(1, 1, 0))); // (1/2, 1/6, 0): not rescaled (a square root would be inexact)
  EXPECT_EQ(n[0], V(FT(1) / 2, FT(1) / 6, 0));
  EXPECT_EQ(n[1], expected(V(1, 2, 3)));
  EXPECT_EQ(n[2], V(0, 0, 5));
  EXPECT_EQ(n[3], expected(V(FT(1) / 3, 0, 1)));
  // Normals stay normal: orthogonal to the transformed tangent (1, 1, 0) -> A (1, -1, 0).
  EXPECT_EQ(n[0] * t.transform(V(1, -1, 0)), 0);
  // A rotation keeps lengths: exact and unit where they were.
  auto rotated = square_with_normals<Epeck::Point_3>({V(0, 0, 1), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)});
  CGAL_ext::transform(rotated, CGAL::Aff_transformation_3<Epeck>(0, -1, 0, 1, 0, 0, 0, 0, 1));
  EXPECT_EQ(normals_at_vertices(rotated)[1], V(0, 1, 0));
  EXPECT_EQ(normals_at_vertices(rotated)[2], V(-1, 0, 0));
}

TEST(Transform, CornerNormalsRefusedWhereTheyCannotFollow)
{
  using V = Kd::Vector_3;
  auto mesh = square_with_normals<Kd::Point_3>({V(0, 0, 1), V(0, 0, 1), V(0, 0, 1), V(0, 0, 1)});
  const auto before = mesh.point(CGAL_ext::Vertex_index(1u));
  // A singular map has no inverse transpose: refused, the mesh untouched.
  EXPECT_THROW(CGAL_ext::transform(mesh, CGAL::Aff_transformation_3<Kd>(1, 0, 0, 0, 1, 0, 0, 0, 0)),
               CGAL_ext::Parameter_error);
  EXPECT_EQ(mesh.point(CGAL_ext::Vertex_index(1u)), before);
  // A transformation without a matrix cannot carry normals.
  struct Shift
  {
    Kd::Point_3 transform(const Kd::Point_3& p) const { return p + Kd::Vector_3(1, 0, 0); }
  };
  EXPECT_THROW(CGAL_ext::transform(mesh, Shift()), CGAL_ext::Parameter_error);
  EXPECT_EQ(mesh.point(CGAL_ext::Vertex_index(1u)), before);
  // Without normals it moves the points as before.
  EXPECT_TRUE(mesh.remove_corner_channel(CGAL_ext::corner_normal_name));
  CGAL_ext::transform(mesh, Shift());
  EXPECT_EQ(mesh.point(CGAL_ext::Vertex_index(1u)), Kd::Point_3(2, 0, 0));
  // Normals of a type the readers do not make are refused, not left behind.
  mesh.add_corner_channel<std::array<double, 3>>(CGAL_ext::corner_normal_name);
  EXPECT_THROW(CGAL_ext::transform(mesh, CGAL::Aff_transformation_3<Kd>(CGAL::SCALING, 2)), CGAL_ext::Parameter_error);
}

} // namespace

} // namespace transform_tests
