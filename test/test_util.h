// Shared helpers of the test suites.
#ifndef CGAL_EXT_TEST_UTIL_H
#define CGAL_EXT_TEST_UTIL_H

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test {

using Kd = CGAL::Simple_cartesian<double>;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

// The data folder's path is compiled into one small file (test_data_dir.cpp)
// only, so that the other files do not depend on where the tree is checked out
// and compiler caches can share them between checkouts.
const char* data_directory();
inline std::string data(const std::string& relative) { return std::string(data_directory()) + "/" + relative; }

// The tests' own OBJ reader, independent of the library's: `on_vertex(x, y, z)`
// for each `v` line, `on_face(indices)` (0-based; `a/t/n` corners allowed) for
// each `f` line, `on_other(tag, line, rest)` for every other line, `rest` being
// the stream after the tag. Returns false if the file cannot be opened.
template <class OnVertex, class OnFace, class OnOther>
bool read_obj_lines(const std::string& path, OnVertex on_vertex, OnFace on_face, OnOther on_other)
{
  std::ifstream in(path);
  if (!in)
    return false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      double x, y, z;
      ls >> x >> y >> z;
      on_vertex(x, y, z);
    } else if (tag == "f") {
      std::vector<std::size_t> face;
      std::string corner;
      while (ls >> corner)
        face.push_back(std::stoul(corner.substr(0, corner.find('/'))) - 1);
      on_face(face);
    } else {
      on_other(tag, line, ls);
    }
  }
  return true;
}

// How many points of `a` have no point of `b` within `tolerance`: the two
// point sets agree, whatever the vertex numbering, when both directions give 0.
template <class Point>
std::size_t unmatched_points(const std::vector<Point>& a, std::vector<Point> b, double tolerance)
{
  std::sort(b.begin(), b.end(), [](const Point& p, const Point& q) { return p.x() < q.x(); });
  std::size_t unmatched = 0;
  for (const Point& p : a) {
    auto it = std::lower_bound(b.begin(), b.end(), CGAL::to_double(p.x()) - tolerance,
                               [](const Point& q, double x) { return CGAL::to_double(q.x()) < x; });
    bool found = false;
    for (; it != b.end() && CGAL::to_double(it->x()) <= CGAL::to_double(p.x()) + tolerance && !found; ++it)
      found = CGAL::to_double(CGAL::squared_distance(p, *it)) <= tolerance * tolerance;
    unmatched += found ? 0 : 1;
  }
  return unmatched;
}

} // namespace test

#endif
