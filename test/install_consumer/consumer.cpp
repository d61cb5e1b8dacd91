// A user program against the installed package: a mesh, and a parallel
// Catmull-Clark step that must match the serial one. Exit status 2: the
// package was built with TBB but parallel subdivision did not reach this
// program (CGAL::Parallel_tag would run serially).
#include <CGAL/Simple_cartesian.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/subdivision.h>

#include <iostream>

int main()
{
#if defined(EXPECT_PARALLEL) && !(defined(CGAL_EXT_SUBDIVISION_PARALLEL) && defined(CGAL_LINKED_WITH_TBB))
  std::cerr << "consumer: the package was built with TBB, but CGAL_EXT_SUBDIVISION_PARALLEL is not defined\n";
  return 2;
#else
  using Mesh = CGAL_ext::Mobius_mesh<CGAL::Simple_cartesian<double>::Point_3>;
  Mesh serial;
  CGAL_ext::make_mobius_strip(serial, 8, 2);
  if (!serial.is_valid())
    return 1;
  Mesh parallel = serial;
  CGAL_ext::Subdivision::catmull_clark(serial, CGAL_ext::parameters::number_of_iterations(2));
#ifdef CGAL_EXT_SUBDIVISION_PARALLEL
  CGAL_ext::Subdivision::catmull_clark<CGAL::Parallel_tag>(parallel, CGAL_ext::parameters::number_of_iterations(2));
#else
  CGAL_ext::Subdivision::catmull_clark(parallel, CGAL_ext::parameters::number_of_iterations(2));
#endif
  if (parallel.number_of_vertices() != serial.number_of_vertices())
    return 1;
  for (auto v : serial.vertices())
    if (serial.point(v) != parallel.point(v))
      return 1;
  return 0;
#endif
}
