// Byte-for-byte comparisons of meshes and arrays, for the tests that a
// parallel path gives the serial result exactly.
#ifndef CGAL_EXT_TEST_SAME_MESH_H
#define CGAL_EXT_TEST_SAME_MESH_H

#include <CGAL_ext/Mobius_mesh.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace test {

template <class T, class A, class B>
bool same_bytes(const std::vector<T, A>& a, const std::vector<T, B>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// A mesh's connectivity, array by array, read through its public accessors.
struct Connectivity
{
  std::vector<std::uint32_t> target, next, prev, face, vertex_dart, face_dart;
  std::vector<std::uint8_t> mobius;
};

template <class P>
Connectivity connectivity_of(const CGAL_ext::Mobius_mesh<P>& m)
{
  Connectivity c;
  for (auto h : m.halfedges()) {
    const CGAL_ext::Dart d(h, false);
    c.target.push_back(m.target(d).idx());
    c.next.push_back(m.next(d).bits());
    c.prev.push_back(m.prev(d).bits());
    c.face.push_back(m.face(h).is_valid() ? m.face(h).idx() : ~0u);
  }
  for (auto e : m.edges())
    c.mobius.push_back(m.is_mobius(e) ? 1 : 0);
  for (auto v : m.vertices())
    c.vertex_dart.push_back(m.halfedge(v).bits());
  for (auto f : m.faces())
    c.face_dart.push_back(m.halfedge(f).bits());
  return c;
}

// Whether two meshes have the same connectivity arrays, byte for byte.
template <class P>
bool same_connectivity(const CGAL_ext::Mobius_mesh<P>& a, const CGAL_ext::Mobius_mesh<P>& b)
{
  const Connectivity ca = connectivity_of(a), cb = connectivity_of(b);
  return same_bytes(ca.target, cb.target) && same_bytes(ca.next, cb.next) && same_bytes(ca.prev, cb.prev) &&
         same_bytes(ca.face, cb.face) && same_bytes(ca.mobius, cb.mobius) &&
         same_bytes(ca.vertex_dart, cb.vertex_dart) && same_bytes(ca.face_dart, cb.face_dart);
}

} // namespace test

#endif // CGAL_EXT_TEST_SAME_MESH_H
