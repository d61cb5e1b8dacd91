// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// How many elements a Mobius_mesh can index, and the one check of it that
// every operation growing a mesh makes before it allocates.

#ifndef CGAL_EXT_MOBIUS_MESH_INTERNAL_SIZE_LIMITS_H
#define CGAL_EXT_MOBIUS_MESH_INTERNAL_SIZE_LIMITS_H

#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <type_traits>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace CGAL_ext {

/// \ingroup PkgMobiusMesh
/// Element counts of a mesh, in 64 bits so that counts past what the mesh
/// can index can be computed (and refused) before anything is allocated.
struct Mesh_size
{
  unsigned long long vertices = 0;
  unsigned long long edges = 0;
  unsigned long long faces = 0;
  unsigned long long border_edges = 0; ///< edges with a face on one side only
};

namespace internal {

// A dart packs 4 e + 2 i + flipped into 32 bits (Dart_encoding.h) and must
// stay below the null value 2^32 - 1: the last edge index is 2^30 - 2.
// Vertex and face indices run up to the null value, excluded.
constexpr unsigned long long max_edges = (1ull << 30) - 1;
constexpr unsigned long long max_vertices = dart_encoding::null;
constexpr unsigned long long max_faces = dart_encoding::null;

/// Throws `Size_error` if a mesh of `size` cannot be indexed; `what` says
/// which operation would make it ("subdividing 12 levels", "the polygon soup").
inline void check_mesh_size(const std::string& what, const Mesh_size& size)
{
  auto check = [&](const char* element, unsigned long long count, unsigned long long limit) {
    if (count > limit)
      throw Size_error(what + " would make " + std::to_string(count) + " " + element + ", more than the " +
                         std::to_string(limit) + " that the mesh's 32-bit indices hold",
                       element, count, limit);
  };
  check("edges", size.edges, max_edges);
  check("vertices", size.vertices, max_vertices);
  check("faces", size.faces, max_faces);
}

/// The machine's physical memory in bytes; infinity where it cannot be asked.
inline double physical_memory()
{
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGE_SIZE)
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page > 0)
    return double(pages) * double(page);
#endif
  return HUGE_VAL;
}

/// The memory the machine can give a process now, in bytes: Linux's
/// `MemAvailable` (free memory plus the caches it can drop), else the free
/// pages, else the physical memory. The default limit of every operation that
/// estimates its memory: the physical memory would let a second large mesh,
/// or other processes, push a call that fits alone into an out-of-memory kill.
inline double available_memory()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0;
  while (meminfo >> key >> kilobytes) {
    if (key == "MemAvailable:" && kilobytes > 0)
      return kilobytes * 1024;
    meminfo.ignore(256, '\n');
  }
#if defined(_SC_AVPHYS_PAGES) && defined(_SC_PAGE_SIZE)
  const long pages = ::sysconf(_SC_AVPHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page > 0)
    return double(pages) * double(page);
#endif
  return physical_memory();
}

/// The bytes the arrays of a `Mobius_mesh` of point type `Point` and counts
/// `size` take: per vertex its point and a dart, per edge two halfedges of
/// four indices each and the Möbius flag, per face a halfedge. A point that
/// is a handle (the lazy exact kernels) adds an estimate of what it points to.
template <class Point>
double mesh_bytes(const Mesh_size& size)
{
  constexpr double handle_target = std::is_trivially_copyable_v<Point> ? 0 : 160;
  return double(size.vertices) * (double(sizeof(Point)) + handle_target + 4) + double(size.edges) * (2 * 16 + 1) +
         double(size.faces) * 4;
}

/// Throws `Size_error` (element `"bytes"`) if an operation needs an
/// estimated `bytes` of memory and more than `limit` is asked.
inline void check_memory(const std::string& what, double bytes, double limit)
{
  if (!(bytes > limit))
    return;
  const auto gigabytes = [](double b) {
    std::ostringstream text;
    text << std::setprecision(3) << b / 1e9;
    return text.str();
  };
  throw Size_error(what + " would need about " + gigabytes(bytes) + " GB of memory, more than the limit of " +
                     gigabytes(limit) + " GB (named parameter maximum_memory; by default the memory available)",
                   "bytes", static_cast<unsigned long long>(std::min(bytes, 1.8e19)),
                   static_cast<unsigned long long>(std::min(limit, 1.8e19)));
}

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_MOBIUS_MESH_INTERNAL_SIZE_LIMITS_H
