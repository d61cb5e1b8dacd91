// A mesh's whole state as a string, for the tests that an operation which
// fails leaves the caller's mesh as it was.
#ifndef CGAL_EXT_TEST_MESH_SNAPSHOT_H
#define CGAL_EXT_TEST_MESH_SNAPSHOT_H

#include <CGAL_ext/Mobius_mesh.h>

#include <sstream>
#include <string>
#include <vector>

namespace test {

// Every link, flag, point and property map name of `m`, and the values of
// its int maps: equal strings for meshes equal byte for byte.
template <class P>
std::string snapshot(const CGAL_ext::Mobius_mesh<P>& m)
{
  std::ostringstream s;
  s << m.num_vertices() << ' ' << m.num_edges() << ' ' << m.num_faces() << '\n';
  for (auto v : m.vertices())
    s << m.halfedge(v).bits() << ' ' << m.point(v) << ';';
  for (auto h : m.halfedges())
    s << m.target(h) << ' ' << m.next(CGAL_ext::Dart(h)).bits() << ' ' << m.prev(CGAL_ext::Dart(h)).bits() << ' '
      << m.face(h) << ';';
  for (auto e : m.edges())
    s << m.is_mobius(e);
  for (auto f : m.faces())
    s << m.halfedge(f).bits() << ';';
  auto dump = [&](auto key, const std::vector<std::string>& names, const auto& range) {
    using I = decltype(key);
    for (const std::string& name : names) {
      s << '\n' << name << ':';
      if (auto map = m.template property_map<I, int>(name))
        for (auto x : range)
          s << (*map)[x] << ',';
    }
  };
  dump(CGAL_ext::Vertex_index(), m.template properties<CGAL_ext::Vertex_index>(), m.vertices());
  dump(CGAL_ext::Halfedge_index(), m.template properties<CGAL_ext::Halfedge_index>(), m.halfedges());
  dump(CGAL_ext::Edge_index(), m.template properties<CGAL_ext::Edge_index>(), m.edges());
  dump(CGAL_ext::Face_index(), m.template properties<CGAL_ext::Face_index>(), m.faces());
  return s.str();
}

} // namespace test

#endif // CGAL_EXT_TEST_MESH_SNAPSHOT_H
