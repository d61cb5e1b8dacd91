// Names the format of one fuzz executable (CGAL_EXT_FUZZ_FORMAT: "obj", "off"
// or "ply"), so that fuzz_reader.cpp, the slow part, is compiled only once.
#ifndef CGAL_EXT_FUZZ_FORMAT
#error "define CGAL_EXT_FUZZ_FORMAT as \"obj\", \"off\" or \"ply\""
#endif

const char* cgal_ext_fuzz_format() { return CGAL_EXT_FUZZ_FORMAT; }
