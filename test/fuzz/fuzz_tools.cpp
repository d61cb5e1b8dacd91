// A libFuzzer target for the paths of the tools: a mesh read from a file,
// then one algorithm family with options taken from the input's first bytes.
// This file is compiled once; each executable links it with fuzz_family.cpp,
// which names its family ("subdivide", "decimate", "remesh", "merge" or
// "offset").
//
// An input is four option bytes, then a mesh file (OBJ). A bad file or bad
// options must give a CGAL_ext::Error, and a call that throws must leave its
// mesh as it was; any other exception, a crash, a sanitizer report or an
// invalid result is a finding. The work of one input is bounded (faces,
// levels, memory) so that the search stays fast, as a tool bounds it with its
// options.

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Mobius_mesh/non_manifold_joins.h>
#include <CGAL_ext/decimation.h>
#include <CGAL_ext/isotropic_remeshing.h>
#include <CGAL_ext/merge_borders.h>
#include <CGAL_ext/offset_mesh.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

// The algorithm family of this executable (fuzz_family.cpp).
const char* cgal_ext_fuzz_family();

namespace {

using Point = CGAL::Simple_cartesian<double>::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
namespace S = CGAL_ext::Subdivision;

constexpr std::size_t max_input_faces = 512;
constexpr double memory_limit = 2e8; // bytes, as a tool's --max-memory

void check(bool condition, const char* what)
{
  if (!condition) {
    std::fprintf(stderr, "fuzz finding (%s): %s\n", cgal_ext_fuzz_family(), what);
    std::abort();
  }
}

const std::string& scratch_file()
{
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir != nullptr ? dir : "/tmp") + "/cgal_ext_fuzz_tools_" + std::to_string(::getpid()) + ".obj";
  }();
  return path;
}

// What a failed call must leave as it was: the points and the faces' vertices.
struct Snapshot
{
  std::vector<Point> points;
  std::vector<std::vector<std::uint32_t>> faces;

  explicit Snapshot(const Mesh& m)
  {
    for (CGAL_ext::Vertex_index v : m.vertices())
      points.push_back(m.point(v));
    for (CGAL_ext::Face_index f : m.faces()) {
      faces.emplace_back();
      for (CGAL_ext::Vertex_index v : CGAL_ext::vertices_around_face(f, m))
        faces.back().push_back(v.idx());
    }
  }
  bool operator==(const Snapshot& o) const { return points == o.points && faces == o.faces; }
};

// The length of the bounding box's diagonal, the unit of the options' lengths.
double diagonal(const Mesh& m)
{
  CGAL::Bbox_3 box;
  for (CGAL_ext::Vertex_index v : m.vertices())
    box += m.point(v).bbox();
  return std::sqrt(CGAL::square(box.x_span()) + CGAL::square(box.y_span()) + CGAL::square(box.z_span()));
}

// A byte as a fraction in [0, 1].
double fraction(std::uint8_t b) { return double(b) / 255.0; }

void subdivide(Mesh& m, const std::array<std::uint8_t, 4>& o)
{
  const unsigned levels = o[1] % 3;
  const auto boundary = CGAL_ext::Boundary_interpolation(o[2] % 3);
  const auto crease = o[3] & 1 ? CGAL_ext::Crease_method::chaikin : CGAL_ext::Crease_method::uniform;
  const auto np = CGAL_ext::parameters::number_of_iterations(levels)
                    .boundary_interpolation(boundary)
                    .crease_method(crease)
                    .maximum_memory(memory_limit);
  switch (o[0] % 6) {
  case 0: S::catmull_clark(m, np); break;
  case 1: S::loop(m, np); break;
  case 2: S::bilinear(m, np); break;
  case 3: S::linear(m, np); break;
  case 4: S::doo_sabin(m, np); break;
  default: S::sqrt3(m, np); break;
  }
}

// Every corner of `out` that names a value of the channel (as the readers
// type it) names one it has.
template <class T>
void check_channel(const Mesh& out, const char* name)
{
  if (const auto channel = out.corner_channel<T>(name))
    for (CGAL_ext::Halfedge_index h : out.halfedges())
      check(!channel->has_value(h) || channel->index(h) < channel->number_of_values(),
            "a corner names a value its channel does not have");
}

void decimate(Mesh& m, const std::array<std::uint8_t, 4>& o)
{
  const auto np = CGAL_ext::parameters::face_ratio(fraction(o[0]))
                    .protect_borders((o[1] & 1) != 0)
                    .relocate_vertices((o[1] & 2) != 0)
                    .maximum_normal_deviation(180.0 * fraction(o[2]));
  CGAL_ext::decimate(m, np);
}

void remesh(Mesh& m, const std::array<std::uint8_t, 4>& o)
{
  // From a 50th of the diagonal to the diagonal; an edge length of 0 or of
  // an empty mesh's diagonal is a bad option, refused.
  const double length = diagonal(m) * (0.02 + fraction(o[0]));
  const auto np = CGAL_ext::parameters::number_of_iterations(1 + o[1] % 3)
                    .protect_borders((o[2] & 1) != 0)
                    .relax_constraints((o[2] & 2) != 0)
                    .maximum_memory(memory_limit);
  const std::vector<std::string> channels = m.corner_channels();
  CGAL_ext::isotropic_remeshing(m, length, np);
  check(m.corner_channels() == channels, "the remeshing lost or made a corner channel");
  check_channel<CGAL_ext::Corner_uv<Point>>(m, CGAL_ext::corner_uv_name);
  check_channel<CGAL_ext::Corner_normal<Point>>(m, CGAL_ext::corner_normal_name);
}

void merge(Mesh& m, const std::array<std::uint8_t, 4>& o)
{
  const double tolerance = diagonal(m) * fraction(o[0]) / 16;
  if (o[1] & 1) {
    CGAL_ext::merge_borders(m, CGAL_ext::parameters::tolerance(tolerance));
    return;
  }
  // The manual strategies, between the mesh and a copy moved along x.
  Mesh other = m;
  const double shift = diagonal(m) * (0.5 + fraction(o[2]));
  for (CGAL_ext::Vertex_index v : other.vertices())
    other.point(v) = other.point(v) + CGAL::Simple_cartesian<double>::Vector_3(shift, 0, 0);
  const auto strategy = CGAL_ext::Merge_strategy(o[3] % 4);
  CGAL_ext::merge_borders(m, other, CGAL_ext::facing_borders(m, other), strategy);
}

void offset(Mesh& m, const std::array<std::uint8_t, 4>& o)
{
  Mesh out;
  const double distance = diagonal(m) * fraction(o[0]) / 4;
  const CGAL_ext::Offset_result r = CGAL_ext::offset_mesh(m, distance, out);
  check(out.is_valid(), "the offset is not valid");
  check(out.corner_channels() == m.corner_channels(), "the offset lost or made a corner channel");
  check(r.corners_without_values == (m.corner_channels().empty() ? 0 : 4 * r.rim_faces),
        "the offset's corners without values are not the rims'");
  check_channel<CGAL_ext::Corner_uv<Point>>(out, CGAL_ext::corner_uv_name);
  check_channel<CGAL_ext::Corner_normal<Point>>(out, CGAL_ext::corner_normal_name);
}

void run(Mesh& m, const std::array<std::uint8_t, 4>& options)
{
  const std::string family = cgal_ext_fuzz_family();
  if (family == "subdivide")
    subdivide(m, options);
  else if (family == "decimate")
    decimate(m, options);
  else if (family == "remesh")
    remesh(m, options);
  else if (family == "merge")
    merge(m, options);
  else
    offset(m, options);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::array<std::uint8_t, 4> options{};
  if (size < options.size())
    return 0;
  std::memcpy(options.data(), data, options.size());
  {
    std::ofstream out(scratch_file(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + options.size()), std::streamsize(size - options.size()));
  }
  Mesh mesh;
  // As the tools read: subdivide takes non-manifold input as sheets.
  const bool sheets = cgal_ext_fuzz_family() == std::string("subdivide");
  try {
    CGAL_ext::IO::read_polygon_mesh(
      scratch_file(), mesh,
      CGAL_ext::parameters::non_manifold_policy(sheets ? CGAL_ext::Non_manifold_policy::split
                                                       : CGAL_ext::Non_manifold_policy::refuse));
  } catch (const CGAL_ext::Error&) {
    return 0;
  }
  if (mesh.number_of_faces() > max_input_faces)
    return 0;
  const Snapshot before(mesh);
  try {
    run(mesh, options);
  } catch (const CGAL_ext::Error&) {
    check(Snapshot(mesh) == before, "a call that failed changed the mesh");
    return 0;
  }
  check(mesh.is_valid(), "the result is not valid");
  if (CGAL_ext::non_manifold_join_map(mesh)) { // the joins follow the levels
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    CGAL_ext::joined_polygon_soup(mesh, points, polygons);
    check(polygons.size() == mesh.number_of_faces(), "the joined soup lost faces");
  }
  return 0;
}
