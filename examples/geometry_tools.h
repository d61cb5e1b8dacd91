// The geometry tools: geodesics, fill_holes, smooth and curvature. Their code
// is one translation unit (geometry_tools.cpp), compiled once into a static
// library: CGAL's heat method, shortest paths, hole filling and fairing take
// minutes to compile, and the four tools share most of them. Each tool's own
// source file is its main() only.
#ifndef CGAL_EXT_EXAMPLES_GEOMETRY_TOOLS_H
#define CGAL_EXT_EXAMPLES_GEOMETRY_TOOLS_H

namespace examples {

/// geodesics IN OUT.ply --source V[,W...] [--method heat|exact] [--triangulate]
int geodesics_tool(int argc, char** argv);
/// fill_holes IN OUT [--fill triangulate|refine|fair] [--triangulate]
int fill_holes_tool(int argc, char** argv);
/// smooth IN OUT [--iterations K] [--time T] [--triangulate]
int smooth_tool(int argc, char** argv);
/// curvature IN OUT.ply [--triangulate]
int curvature_tool(int argc, char** argv);

} // namespace examples

#endif
