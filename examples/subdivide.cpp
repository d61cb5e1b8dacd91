// subdivide IN OUT [--scheme catmull-clark|loop|linear|doo-sabin|sqrt3] [--levels N]
//   [--vertex-rule standard|edge-points] [--boundary none|edge-only|edge-and-corner]
//   [--crease-method uniform|chaikin] [--kernel double|epick|epeck] [--max-memory BYTES]
//
// Reads a mesh (OBJ with OpenSubdiv's tags, OFF, PLY), subdivides it and
// writes the result (format by extension). The OBJ tags give the defaults of
// --boundary and --crease-method; flags override them. Prints one JSON line
// with the result's counts and the subdivision time (without I/O). Before it
// starts, it estimates the memory the result needs and refuses (naming the
// bytes) beyond --max-memory, by default the machine's physical memory. Bad
// input or options: one line on stderr, exit status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace {

namespace S = CGAL_ext::Subdivision;

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

double physical_memory()
{
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : HUGE_VAL;
}

struct Settings
{
  std::string in, out, scheme = "catmull-clark", kernel = "double";
  unsigned levels = 1;
  S::Vertex_rule vertex_rule = S::Vertex_rule::standard;
  std::optional<CGAL_ext::Boundary_interpolation> boundary;
  std::optional<CGAL_ext::Crease_method> crease_method;
  double max_memory = physical_memory();
};

template <class T>
T pick(const std::map<std::string, T>& choices, const std::string& option, const std::string& value)
{
  const auto it = choices.find(value);
  if (it == choices.end())
    throw Usage_error("bad value '" + value + "' for " + option);
  return it->second;
}

Settings parse(int argc, char** argv)
{
  Settings s;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--", 0) != 0) {
      (positional++ == 0 ? s.in : s.out) = a;
      if (positional > 2)
        throw Usage_error("too many file names");
      continue;
    }
    if (i + 1 >= argc)
      throw Usage_error("missing value for " + a);
    const std::string v = argv[++i];
    if (a == "--scheme")
      s.scheme = pick<std::string>({{"catmull-clark", "catmull-clark"}, {"loop", "loop"}, {"linear", "linear"},
                                    {"doo-sabin", "doo-sabin"}, {"sqrt3", "sqrt3"}},
                                   a, v);
    else if (a == "--levels") {
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || v.empty() || n < 0 || n > 15)
        throw Usage_error("bad value '" + v + "' for --levels (0 to 15)");
      s.levels = unsigned(n);
    } else if (a == "--vertex-rule")
      s.vertex_rule = pick<S::Vertex_rule>(
        {{"standard", S::Vertex_rule::standard}, {"edge-points", S::Vertex_rule::edge_points}}, a, v);
    else if (a == "--boundary")
      s.boundary = pick<CGAL_ext::Boundary_interpolation>(
        {{"none", CGAL_ext::Boundary_interpolation::none},
         {"edge-only", CGAL_ext::Boundary_interpolation::edge_only},
         {"edge-and-corner", CGAL_ext::Boundary_interpolation::edge_and_corner}},
        a, v);
    else if (a == "--crease-method")
      s.crease_method = pick<CGAL_ext::Crease_method>(
        {{"uniform", CGAL_ext::Crease_method::uniform}, {"chaikin", CGAL_ext::Crease_method::chaikin}}, a, v);
    else if (a == "--max-memory") {
      char* end = nullptr;
      s.max_memory = std::strtod(v.c_str(), &end);
      if (*end != '\0' || v.empty() || !(s.max_memory > 0) || !std::isfinite(s.max_memory))
        throw Usage_error("bad value '" + v + "' for --max-memory (a number of bytes)");
    } else if (a == "--kernel")
      s.kernel = pick<std::string>({{"double", "double"}, {"epick", "epick"}, {"epeck", "epeck"}}, a, v);
    else
      throw Usage_error("unknown option " + a);
  }
  if (positional != 2)
    throw Usage_error("usage: subdivide IN OUT [--scheme catmull-clark|loop|linear|doo-sabin|sqrt3] [--levels N] "
                      "[--vertex-rule standard|edge-points] [--boundary none|edge-only|edge-and-corner] "
                      "[--crease-method uniform|chaikin] [--kernel double|epick|epeck] [--max-memory BYTES]");
  return s;
}

template <class Mesh>
bool is_triangle_mesh(const Mesh& mesh)
{
  for (auto f : mesh.faces())
    if (mesh.degree(f) != 3)
      return false;
  return true;
}

// The faces after `levels` steps of `scheme`: exact for the schemes that split
// every face alike, a lower bound for Doo-Sabin (each step at least triples).
template <class Mesh>
double output_faces(const Mesh& mesh, const std::string& scheme, unsigned levels)
{
  if (levels == 0)
    return double(mesh.number_of_faces());
  const double f = double(mesh.number_of_faces());
  double corners = 0;
  for (auto face : mesh.faces())
    corners += double(mesh.degree(face));
  const bool triangles = is_triangle_mesh(mesh);
  if (scheme == "sqrt3")
    return f * std::pow(3.0, levels);
  if (scheme == "doo-sabin")
    return f * std::pow(3.0, levels);
  if (scheme == "loop" || (scheme == "linear" && triangles))
    return f * std::pow(4.0, levels);
  return corners * std::pow(4.0, levels - 1); // an n-gon into n quads, then quads into four
}

// Bytes per output face: the subdivision's peak of about 123 bytes per quad
// (doc/benchmarks.md) and the soup that writing copies the result into (a
// vector of indices per face and a point per vertex, about 70 bytes per quad).
constexpr double bytes_per_output_face = 190;

template <class Mesh>
void check_memory(const Mesh& mesh, const Settings& s)
{
  const double faces = output_faces(mesh, s.scheme, s.levels);
  const double bytes = faces * bytes_per_output_face;
  if (bytes > s.max_memory) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%u levels of %s make %.0f faces, which need about %.3g bytes; the limit is %.3g (--max-memory)",
                  s.levels, s.scheme.c_str(), faces, bytes, s.max_memory);
    throw Usage_error(text);
  }
}

template <class K>
void run(const Settings& s)
{
  CGAL_ext::Mobius_mesh<typename K::Point_3> mesh;
  CGAL_ext::Sharp_feature_options tags = CGAL_ext::IO::read_polygon_mesh(s.in, mesh);
  const auto boundary =
    s.boundary ? *s.boundary : tags.boundary_interpolation.value_or(CGAL_ext::Boundary_interpolation::edge_only);
  const auto crease = s.crease_method ? *s.crease_method : tags.crease_method.value_or(CGAL_ext::Crease_method::uniform);
  const auto triangles = tags.triangle_subdivision.value_or(CGAL_ext::Triangle_subdivision::catmark);
  const auto np = CGAL_ext::parameters::number_of_iterations(s.levels)
                    .boundary_interpolation(boundary)
                    .crease_method(crease)
                    .vertex_rule(s.vertex_rule)
                    .triangle_subdivision(triangles);

  check_memory(mesh, s);
  const auto start = std::chrono::steady_clock::now();
  if (s.scheme == "loop")
    S::loop(mesh, np);
  else if (s.scheme == "linear" && is_triangle_mesh(mesh))
    S::linear(mesh, np); // midpoints, each triangle into four
  else if (s.scheme == "linear")
    S::bilinear(mesh, np); // midpoints and centroids, each n-gon into n quads
  else if (s.scheme == "doo-sabin")
    S::doo_sabin(mesh, np);
  else if (s.scheme == "sqrt3")
    S::sqrt3(mesh, np);
  else
    S::catmull_clark(mesh, np);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The output carries the options the input or the flags set, and no
  // others: a tag line makes the file unreadable to CGAL's OBJ reader, so one
  // is written only where it tells something.
  CGAL_ext::Sharp_feature_options out_tags = tags;
  if (s.boundary)
    out_tags.boundary_interpolation = s.boundary;
  if (s.crease_method)
    out_tags.crease_method = s.crease_method;
  CGAL_ext::IO::write_polygon_mesh(s.out, mesh, CGAL_ext::parameters::default_values(), out_tags);
  std::cout << "{\"scheme\":\"" << s.scheme << "\",\"kernel\":\"" << s.kernel << "\",\"levels\":" << s.levels
            << ",\"vertices\":" << mesh.number_of_vertices() << ",\"edges\":" << mesh.number_of_edges()
            << ",\"faces\":" << mesh.number_of_faces() << ",\"seconds\":" << seconds << "}" << std::endl;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const Settings s = parse(argc, argv);
    if (s.kernel == "epick")
      run<CGAL::Exact_predicates_inexact_constructions_kernel>(s);
    else if (s.kernel == "epeck")
      run<CGAL::Exact_predicates_exact_constructions_kernel>(s);
    else
      run<CGAL::Simple_cartesian<double>>(s);
  } catch (const std::exception& e) {
    return examples::fail("subdivide", e.what());
  }
  return 0;
}
