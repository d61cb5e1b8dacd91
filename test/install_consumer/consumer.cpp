#include <CGAL/Simple_cartesian.h>
#include <CGAL_ext/Mobius_mesh.h>

int main()
{
  CGAL_ext::Mobius_mesh<CGAL::Simple_cartesian<double>::Point_3> m;
  return m.is_valid() ? 0 : 1;
}
