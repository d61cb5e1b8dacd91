// Compile-only check: every call shape of CGAL 5.5's CGAL::draw() for a
// Surface_mesh, made on a Mobius_mesh, resolves to CGAL_ext::draw(). Built
// with CGAL's viewer where CGAL's Qt5 component is installed (the viewer's
// code is then compiled too); not run, as it opens windows.

#include <CGAL/Simple_cartesian.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/generators.h>
#include <CGAL_ext/draw_mobius_mesh.h>

int main()
{
  using Mesh = CGAL_ext::Mobius_mesh<CGAL::Simple_cartesian<double>::Point_3>;
  Mesh mesh;
  CGAL_ext::make_mobius_strip(mesh, 20, 4);
  const char* title = "a title";
  CGAL_ext::draw(mesh);                      // CGAL::draw(sm)
  CGAL_ext::draw(mesh, "Mobius strip");      // CGAL::draw(sm, title)
  CGAL_ext::draw(mesh, title);               // a title held in a pointer
  CGAL_ext::draw(mesh, title, true);         // CGAL::draw(sm, title, nofill)
  draw(mesh, "found by argument-dependent lookup");
  CGAL_ext::draw(mesh, CGAL_ext::parameters::default_values(), "with named parameters");
  return 0;
}
