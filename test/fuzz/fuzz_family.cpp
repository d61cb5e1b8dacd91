// Names the algorithm family of one fuzz executable (CGAL_EXT_FUZZ_FAMILY:
// "subdivide", "decimate", "remesh", "merge" or "offset"), so that
// fuzz_tools.cpp, the slow part, is compiled only once.
#ifndef CGAL_EXT_FUZZ_FAMILY
#error "define CGAL_EXT_FUZZ_FAMILY as the name of an algorithm family"
#endif

const char* cgal_ext_fuzz_family() { return CGAL_EXT_FUZZ_FAMILY; }
