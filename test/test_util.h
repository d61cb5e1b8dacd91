// Shared helpers of the test suites.
#ifndef CGAL_EXT_TEST_UTIL_H
#define CGAL_EXT_TEST_UTIL_H

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <string>

namespace test {

using Kd = CGAL::Simple_cartesian<double>;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

inline std::string data(const std::string& relative) { return std::string(CGAL_EXT_TEST_DATA_DIR) + "/" + relative; }

} // namespace test

#endif
