// subdivide IN OUT [--scheme catmull-clark|loop|linear|doo-sabin|sqrt3] [--levels N]
//   [--vertex-rule standard|edge-points] [--boundary none|edge-only|edge-and-corner]
//   [--crease-method uniform|chaikin] [--kernel double|epick|epeck]
//
// Reads a mesh (OBJ with OpenSubdiv's tags, OFF, PLY), subdivides it and
// writes the result (format by extension). The OBJ tags give the defaults of
// --boundary and --crease-method; flags override them. Prints one JSON line
// with the result's counts and the subdivision time (without I/O). Bad input
// or options: one line on stderr, exit status 2.

#include "mesh_summary.h"

#include <CGAL_ext/IO/polygon_mesh_io.h>
#include <CGAL_ext/subdivision.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

namespace {

namespace S = CGAL_ext::Subdivision;

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Settings
{
  std::string in, out, scheme = "catmull-clark", kernel = "double";
  unsigned levels = 1;
  S::Vertex_rule vertex_rule = S::Vertex_rule::standard;
  std::optional<CGAL_ext::Boundary_interpolation> boundary;
  std::optional<CGAL_ext::Crease_method> crease_method;
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
    else if (a == "--kernel")
      s.kernel = pick<std::string>({{"double", "double"}, {"epick", "epick"}, {"epeck", "epeck"}}, a, v);
    else
      throw Usage_error("unknown option " + a);
  }
  if (positional != 2)
    throw Usage_error("usage: subdivide IN OUT [--scheme catmull-clark|loop|linear|doo-sabin|sqrt3] [--levels N] "
                      "[--vertex-rule standard|edge-points] [--boundary none|edge-only|edge-and-corner] "
                      "[--crease-method uniform|chaikin] [--kernel double|epick|epeck]");
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

  CGAL_ext::Sharp_feature_options out_tags = tags;
  out_tags.boundary_interpolation = boundary;
  out_tags.crease_method = crease;
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
