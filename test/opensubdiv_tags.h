// OpenSubdiv's tags as its regression shapes' OBJ files carry them
// (`t NAME ni/nf/ns ints floats strings`): creases, corners and the options,
// read by the one small parser of the tests, put into a mesh's sharpness
// maps, and (with OpenSubdiv) turned into its topology descriptor's arrays and
// options. The library's own reader is under test elsewhere; these tests
// compare its results with OpenSubdiv's on the same shapes.
#ifndef CGAL_EXT_TEST_OPENSUBDIV_TAGS_H
#define CGAL_EXT_TEST_OPENSUBDIV_TAGS_H

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Sharp_feature_options.h>

#include <array>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/sdc/options.h>
#endif

namespace test {

struct Osd_tags
{
  std::vector<std::array<int, 2>> crease_pairs; // the two vertices of each crease edge
  std::vector<float> crease_values;
  std::vector<int> corners;
  std::vector<float> corner_values;
  CGAL_ext::Boundary_interpolation boundary = CGAL_ext::Boundary_interpolation::edge_only;
  CGAL_ext::Crease_method crease_method = CGAL_ext::Crease_method::uniform;
  CGAL_ext::Triangle_subdivision triangles = CGAL_ext::Triangle_subdivision::catmark;

  // Reads the rest of a line that starts with `t`.
  void read(std::istream& line)
  {
    std::string name, counts;
    line >> name >> counts;
    int ni = 0, nf = 0, ns = 0;
    char separator;
    std::istringstream(counts) >> ni >> separator >> nf >> separator >> ns;
    std::vector<int> ints(std::size_t(ni > 0 ? ni : 0));
    std::vector<float> floats(std::size_t(nf > 0 ? nf : 0));
    std::vector<std::string> strings(std::size_t(ns > 0 ? ns : 0));
    for (int& i : ints)
      line >> i;
    for (float& f : floats)
      line >> f;
    for (std::string& s : strings)
      line >> s;
    add(name, ints, floats, strings);
  }

  // The crease pairs as one list of vertex indices, as OpenSubdiv takes them.
  std::vector<int> crease_indices() const
  {
    std::vector<int> indices;
    for (const auto& p : crease_pairs)
      indices.insert(indices.end(), p.begin(), p.end());
    return indices;
  }

  // The sharpness of the tags in the maps "e:sharpness" and "v:sharpness" of
  // `m`, built from the shape's faces (vertices numbered as in the file).
  template <class P>
  void add_sharpness_maps(CGAL_ext::Mobius_mesh<P>& m) const
  {
    auto es = m.template add_property_map<CGAL_ext::Edge_index, float>(CGAL_ext::edge_sharpness_name, 0.0f).first;
    auto vs = m.template add_property_map<CGAL_ext::Vertex_index, float>(CGAL_ext::vertex_sharpness_name, 0.0f).first;
    for (std::size_t i = 0; i < crease_pairs.size(); ++i)
      for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_target(CGAL_ext::Vertex_index(crease_pairs[i][1]), m))
        if (m.source(d) == CGAL_ext::Vertex_index(crease_pairs[i][0]))
          es[m.edge(d)] = crease_values[i];
    for (std::size_t i = 0; i < corners.size(); ++i)
      vs[CGAL_ext::Vertex_index(corners[i])] = corner_values[i];
  }

private:
  void add(const std::string& name, const std::vector<int>& ints, const std::vector<float>& floats,
           const std::vector<std::string>& strings)
  {
    // One value for all, or one each.
    const auto value = [&](std::size_t i) { return floats.size() == 1 ? floats[0] : floats.at(i); };
    if (name == "crease") {
      for (std::size_t i = 0; i + 1 < ints.size(); i += 2) {
        crease_pairs.push_back({ints[i], ints[i + 1]});
        crease_values.push_back(value(i / 2));
      }
    } else if (name == "corner") {
      for (std::size_t i = 0; i < ints.size(); ++i) {
        corners.push_back(ints[i]);
        corner_values.push_back(value(i));
      }
    } else if (name == "interpolateboundary" && !ints.empty()) {
      boundary = ints[0] == 0   ? CGAL_ext::Boundary_interpolation::none
                 : ints[0] == 1 ? CGAL_ext::Boundary_interpolation::edge_and_corner
                                : CGAL_ext::Boundary_interpolation::edge_only;
    } else if (name == "creasemethod" && !strings.empty()) {
      crease_method = strings[0] == "chaikin" ? CGAL_ext::Crease_method::chaikin : CGAL_ext::Crease_method::uniform;
    } else if (name == "smoothtriangles" && !strings.empty()) {
      triangles =
        strings[0] == "smooth" ? CGAL_ext::Triangle_subdivision::smooth : CGAL_ext::Triangle_subdivision::catmark;
    }
  }
};

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
// OpenSubdiv's options for `boundary`, `method` and `triangles`.
inline OpenSubdiv::Sdc::Options opensubdiv_options(CGAL_ext::Boundary_interpolation boundary,
                                                   CGAL_ext::Crease_method method,
                                                   CGAL_ext::Triangle_subdivision triangles =
                                                     CGAL_ext::Triangle_subdivision::catmark)
{
  using Sdc = OpenSubdiv::Sdc::Options;
  using B = CGAL_ext::Boundary_interpolation;
  Sdc options;
  options.SetVtxBoundaryInterpolation(boundary == B::none        ? Sdc::VTX_BOUNDARY_NONE
                                      : boundary == B::edge_only ? Sdc::VTX_BOUNDARY_EDGE_ONLY
                                                                 : Sdc::VTX_BOUNDARY_EDGE_AND_CORNER);
  options.SetCreasingMethod(method == CGAL_ext::Crease_method::chaikin ? Sdc::CREASE_CHAIKIN : Sdc::CREASE_UNIFORM);
  options.SetTriangleSubdivision(triangles == CGAL_ext::Triangle_subdivision::smooth ? Sdc::TRI_SUB_SMOOTH
                                                                                     : Sdc::TRI_SUB_CATMARK);
  return options;
}

// The options of `tags`.
inline OpenSubdiv::Sdc::Options opensubdiv_options(const Osd_tags& tags)
{
  return opensubdiv_options(tags.boundary, tags.crease_method, tags.triangles);
}
#endif

} // namespace test

#endif // CGAL_EXT_TEST_OPENSUBDIV_TAGS_H
