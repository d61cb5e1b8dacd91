// A libFuzzer target for one reader of CGAL_ext/IO/polygon_mesh_io.h. This
// file is compiled once; each executable links it with fuzz_format.cpp, which
// names its format ("obj", "off" or "ply").
//
// Each input is written to a file and read with read_polygon_mesh(), the
// whole path a user's file takes. Bad input must give a CGAL_ext::Error; any
// other exception, a crash or a sanitizer report is a finding. A mesh that
// was read must be valid, survive one Catmull-Clark step (or refuse it with
// an Error) still valid, and convert to a Surface_mesh with as many faces.

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/Surface_mesh_conversion.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

// The file extension, and so the reader, of this executable (fuzz_format.cpp).
const char* cgal_ext_fuzz_format();

namespace {

using Point = CGAL::Simple_cartesian<double>::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;

// Bounds the work of one input: a step of subdivision on a large mesh says
// nothing the small ones do not, and slows the search down.
constexpr std::size_t max_faces_to_subdivide = 4096;

const std::string& scratch_file()
{
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir != nullptr ? dir : "/tmp") + "/cgal_ext_fuzz_" + std::to_string(::getpid()) + "." +
           cgal_ext_fuzz_format();
  }();
  return path;
}

void check(bool condition, const char* what)
{
  if (!condition) {
    std::fprintf(stderr, "fuzz finding: %s\n", what);
    std::abort();
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  {
    std::ofstream out(scratch_file(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  Mesh mesh;
  try {
    CGAL_ext::IO::read_polygon_mesh(scratch_file(), mesh);
  } catch (const CGAL_ext::Error&) {
    check(mesh.number_of_vertices() == 0 && mesh.number_of_faces() == 0, "a failed read changed the mesh");
    return 0;
  }
  check(mesh.is_valid(), "the mesh read is not valid");
  check(mesh.number_of_faces() > 0, "a mesh without faces was read");

  CGAL::Surface_mesh<Point> sm;
  CGAL_ext::to_surface_mesh(mesh, sm);
  check(sm.number_of_faces() == mesh.number_of_faces(), "the Surface_mesh lost faces");
  check(sm.is_valid(false), "the Surface_mesh is not valid");

  if (mesh.number_of_faces() <= max_faces_to_subdivide) {
    try {
      CGAL_ext::Subdivision::catmull_clark(mesh);
      check(mesh.is_valid(), "Catmull-Clark made an invalid mesh");
    } catch (const CGAL_ext::Error&) {
    }
  }
  return 0;
}
