// geodesics IN OUT.ply --source V[,W...] [--method heat|exact] [--triangulate]
//
// One of the geometry tools; its code is in geometry_tools.cpp, which the
// four of them share (see geometry_tools.h).

#include "geometry_tools.h"

int main(int argc, char* argv[]) { return examples::geodesics_tool(argc, argv); }
