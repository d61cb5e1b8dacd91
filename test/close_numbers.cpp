// close_numbers A B TOLERANCE
//
// Whether two numbers agree within a relative tolerance: |A - B| <= TOLERANCE
// times the larger of |A| and |B|. The tool tests compare a figure a tool
// prints with a closed form or with the same figure computed another way;
// CMake's scripts cannot compute with real numbers.
// Prints "A B: relative difference D" and exits 0 if they agree, 1 if not, 2
// if an argument is not a number.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

bool number(const char* text, double& x)
{
  char* end = nullptr;
  x = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(x);
}

} // namespace

int main(int argc, char* argv[])
{
  double a = 0, b = 0, tolerance = 0;
  if (argc != 4 || !number(argv[1], a) || !number(argv[2], b) || !number(argv[3], tolerance)) {
    std::cerr << "usage: close_numbers A B TOLERANCE (three finite numbers)\n";
    return 2;
  }
  const double scale = std::max(std::abs(a), std::abs(b));
  const double difference = scale > 0 ? std::abs(a - b) / scale : 0.0;
  std::cout << argv[1] << " " << argv[2] << ": relative difference " << difference << "\n";
  return difference <= tolerance ? 0 : 1;
}
