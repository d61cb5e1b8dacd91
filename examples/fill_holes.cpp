// fill_holes IN OUT [--fill triangulate|refine|fair] [--triangulate]
//
// One of the geometry tools; its code is in geometry_tools.cpp, which the
// four of them share (see geometry_tools.h).

#include "geometry_tools.h"

int main(int argc, char* argv[]) { return examples::fill_holes_tool(argc, argv); }
