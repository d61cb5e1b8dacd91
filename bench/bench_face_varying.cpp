// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Catmull–Clark subdivision with one channel of texture coordinates, side by
// side with OpenSubdiv's Far, and what the channel costs over the positions:
//   face_varying/cube_uv/level:6-8   OpenSubdiv's catmark_cube (6 quads, its
//                                    uv net of 14 values): 24 576 to 393 216 quads
//   face_varying/torus100x100_uv/level:5  a torus of 100 x 100 quads whose uv
//                                    grid is cut open along two circles: 10 240 000 quads
// Implementations, serial, each from a ready input to every level's values:
//   CGAL_ext_positions    catmull_clark() of the points alone
//   CGAL_ext_vertex_map   the points and a vertex map of std::array<double, 2>
//                         (the cost of two more doubles per vertex)
//   CGAL_ext_vertex_map_4d  the points and a vertex map of std::array<double, 4>:
//                         as many bytes as the channel holds (its two doubles
//                         per value and its four 4-byte indices per quad)
//   CGAL_ext_vertex_map_and_indices  the points and the vertex map of
//                         std::array<double, 2>, then an index per face
//                         corner of the result (its target vertex) written
//                         in a pass of its own into an array such as a
//                         channel's: what any channel that holds an index
//                         per corner costs at the least
//   CGAL_ext_uv_channel   the points and the corner channel "c:uv" of
//                         std::array<double, 2> (the default rule, corners_plus1)
//   OpenSubdiv_Far_positions   TopologyRefiner from the descriptor, RefineUniform
//                         (its default: the last level without edges),
//                         PrimvarRefiner::Interpolate level by level
//   OpenSubdiv_Far_uv_channel  the same with one face-varying channel in the
//                         descriptor and InterpolateFaceVarying (FVAR_LINEAR_CORNERS_PLUS1)
// Ours builds a complete mesh (every level's halfedges, faces and the
// channel's indices); Far keeps its levels' tables. Every iteration starts from
// a fresh copy of the input, made outside the timing.
//
// At start the program checks, on every input at level 2, that ours and Far
// give the same channel values (as sets, to 1e-9): a comparison of different
// outputs would be worthless.

#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/polygon_soup_to_mobius_mesh.h>
#include <CGAL_ext/subdivision.h>
#include <CGAL_ext/internal/Uninitialized_array.h> // the array a channel keeps its indices in

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <benchmark/benchmark.h>

#if CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL_ext::Mobius_mesh<Point>;
using Uv = std::array<double, 2>;

// Points, faces, and each face corner's index into the uv values.
struct Input
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  std::vector<Uv> uvs;
  std::vector<std::vector<std::uint32_t>> uv_of; // by face, by corner
};

Input cube()
{
  const double r = 1.414214;
  Input in;
  in.points = {{0, -r, 1}, {r, 0, 1}, {-r, 0, 1}, {0, r, 1}, {-r, 0, -1}, {0, r, -1}, {0, -r, -1}, {r, 0, -1}};
  in.faces = {{0, 1, 3, 2}, {2, 3, 5, 4}, {4, 5, 7, 6}, {6, 7, 1, 0}, {1, 7, 5, 3}, {6, 0, 2, 4}};
  in.uvs = {{0.375, 0},    {0.625, 0},    {0.375, 0.25}, {0.625, 0.25}, {0.375, 0.5},
            {0.625, 0.5},  {0.375, 0.75}, {0.625, 0.75}, {0.375, 1},    {0.625, 1},
            {0.875, 0},    {0.875, 0.25}, {0.125, 0},    {0.125, 0.25}};
  in.uv_of = {{0, 1, 3, 2}, {2, 3, 5, 4}, {4, 5, 7, 6}, {6, 7, 9, 8}, {1, 10, 11, 3}, {12, 0, 2, 13}};
  return in;
}

// An n x n torus of radii 2 and 1; the uv of grid node (i, j) is (i/n, j/n),
// so the channel is cut along the circles i = 0 and j = 0.
Input torus(int n)
{
  Input in;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * CGAL_PI * i / n, v = 2 * CGAL_PI * j / n;
      in.points.emplace_back((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      in.uvs.push_back({double(i) / n, double(j) / n});
  const auto vertex = [n](int i, int j) { return std::size_t((i % n) * n + (j % n)); };
  const auto node = [n](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      in.faces.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
      in.uv_of.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  return in;
}

const Input& input(const std::string& name)
{
  static std::map<std::string, Input> inputs;
  auto it = inputs.find(name);
  if (it == inputs.end())
    it = inputs.emplace(name, name == "cube_uv" ? cube() : torus(100)).first;
  return it->second;
}

enum class Data { positions, vertex_map, vertex_map_4d, vertex_map_and_indices, uv_channel };

// The input as our mesh, with the data asked for. Face p is polygon p, and a
// corner is found by its vertex (the import may reverse a face).
Mesh our_mesh(const Input& in, Data data)
{
  Mesh m;
  CGAL_ext::polygon_soup_to_mobius_mesh(in.points, in.faces, m);
  if (data == Data::vertex_map || data == Data::vertex_map_and_indices) {
    auto map = m.add_property_map<CGAL_ext::Vertex_index, Uv>("v:uv").first;
    for (CGAL_ext::Vertex_index v : m.vertices())
      map[v] = {m.point(v).x(), m.point(v).y()};
  } else if (data == Data::vertex_map_4d) {
    auto map = m.add_property_map<CGAL_ext::Vertex_index, std::array<double, 4>>("v:uvst").first;
    for (CGAL_ext::Vertex_index v : m.vertices())
      map[v] = {m.point(v).x(), m.point(v).y(), m.point(v).z(), 1.0};
  } else if (data == Data::uv_channel) {
    auto uv = m.add_corner_channel<Uv>("c:uv").first;
    uv.values() = in.uvs;
    for (std::size_t p = 0; p < in.faces.size(); ++p)
      for (CGAL_ext::Dart d : CGAL_ext::halfedges_around_face(m.halfedge(CGAL_ext::Face_index(p)), m)) {
        const auto k = std::find(in.faces[p].begin(), in.faces[p].end(), m.target(d).idx()) - in.faces[p].begin();
        uv.set_index(m.corner(d), in.uv_of[p][std::size_t(k)]);
      }
  }
  return m;
}

std::vector<Uv> our_uvs(const Input& in, int levels)
{
  Mesh m = our_mesh(in, Data::uv_channel);
  CGAL_ext::Subdivision::catmull_clark(m, CGAL_ext::parameters::number_of_iterations(levels));
  return m.corner_channel<Uv>("c:uv")->values();
}

// An index per face corner of `m` (null on the border), as a channel holds
// them, kept from the optimiser.
void write_corner_indices(const Mesh& m)
{
  CGAL_ext::internal::Uninitialized_array<std::uint32_t> index(m.number_of_halfedges());
  for (CGAL_ext::Halfedge_index h : m.halfedges())
    index[h.idx()] = m.is_border(h) ? std::uint32_t(-1) : std::uint32_t(m.target(h).idx());
  benchmark::DoNotOptimize(index.data());
  benchmark::ClobberMemory();
}

void ours(benchmark::State& state, const std::string& name, Data data)
{
  const Mesh base = our_mesh(input(name), data);
  const int levels = int(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    auto m = std::make_unique<Mesh>(base);
    state.ResumeTiming();
    CGAL_ext::Subdivision::catmull_clark(*m, CGAL_ext::parameters::number_of_iterations(levels));
    if (data == Data::vertex_map_and_indices)
      write_corner_indices(*m);
    state.PauseTiming();
    state.counters["faces"] = double(m->number_of_faces());
    m.reset();
    state.ResumeTiming();
  }
}

#if CGAL_EXT_HAVE_OPENSUBDIV
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

template <int N>
struct Far_value
{
  std::array<double, N> x;
  void Clear() { x.fill(0); }
  void AddWithWeight(const Far_value& s, double w)
  {
    for (int k = 0; k < N; ++k)
      x[std::size_t(k)] += w * s.x[std::size_t(k)];
  }
};

// Far's refinement of `in` to `levels`, with the uv channel if `uv`; its
// points and channel values, every level's, one after the other.
struct Far_run
{
  std::unique_ptr<Far::TopologyRefiner> refiner;
  std::vector<Far_value<3>> points;
  std::vector<Far_value<2>> uvs;

  Far_run(const Input& in, int levels, bool uv)
  {
    std::vector<int> sizes, vertices, uv_indices;
    for (std::size_t p = 0; p < in.faces.size(); ++p)
      for (std::size_t k = 0; k < in.faces[p].size(); ++k) {
        vertices.push_back(int(in.faces[p][k]));
        uv_indices.push_back(int(in.uv_of[p][k]));
      }
    for (const auto& f : in.faces)
      sizes.push_back(int(f.size()));
    Far::TopologyDescriptor desc;
    desc.numVertices = int(in.points.size());
    desc.numFaces = int(in.faces.size());
    desc.numVertsPerFace = sizes.data();
    desc.vertIndicesPerFace = vertices.data();
    Far::TopologyDescriptor::FVarChannel channel;
    channel.numValues = int(in.uvs.size());
    channel.valueIndices = uv_indices.data();
    if (uv) {
      desc.numFVarChannels = 1;
      desc.fvarChannels = &channel;
    }
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY); // ours' default
    options.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    refiner.reset(Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, options)));
    refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
    points.resize(std::size_t(refiner->GetNumVerticesTotal()));
    for (std::size_t v = 0; v < in.points.size(); ++v)
      points[v].x = {in.points[v].x(), in.points[v].y(), in.points[v].z()};
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    Far_value<3>* src = points.data();
    for (int level = 1; level <= levels; ++level) {
      Far_value<3>* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
      primvar.Interpolate(level, src, dst);
      src = dst;
    }
    if (!uv)
      return;
    uvs.resize(std::size_t(refiner->GetNumFVarValuesTotal(0)));
    for (std::size_t i = 0; i < in.uvs.size(); ++i)
      uvs[i].x = in.uvs[i];
    Far_value<2>* from = uvs.data();
    for (int level = 1; level <= levels; ++level) {
      Far_value<2>* to = from + refiner->GetLevel(level - 1).GetNumFVarValues(0);
      primvar.InterpolateFaceVarying(level, from, to, 0);
      from = to;
    }
  }

  std::vector<Uv> last_uvs() const
  {
    const std::size_t n = std::size_t(refiner->GetLevel(refiner->GetMaxLevel()).GetNumFVarValues(0));
    std::vector<Uv> result;
    for (std::size_t i = uvs.size() - n; i < uvs.size(); ++i)
      result.push_back(uvs[i].x);
    return result;
  }
};

void far(benchmark::State& state, const std::string& name, bool uv)
{
  const Input& in = input(name);
  const int levels = int(state.range(0));
  for (auto _ : state) {
    auto run = std::make_unique<Far_run>(in, levels, uv);
    state.PauseTiming();
    state.counters["faces"] = double(run->refiner->GetLevel(levels).GetNumFaces());
    run.reset();
    state.ResumeTiming();
  }
}

// Ours and Far give the same values at level 2, as sorted lists of values
// rounded to 1e-9 (unrounded, values equal up to rounding could sort in
// another order), each within one unit of the other's.
bool same_channel_values(const std::string& name)
{
  const auto rounded = [](const std::vector<Uv>& values) {
    std::vector<std::array<long long, 2>> r;
    for (const Uv& v : values)
      r.push_back({std::llround(v[0] * 1e9), std::llround(v[1] * 1e9)});
    std::sort(r.begin(), r.end());
    return r;
  };
  const auto a = rounded(our_uvs(input(name), 2)), b = rounded(Far_run(input(name), 2, true).last_uvs());
  bool same = a.size() == b.size();
  for (std::size_t i = 0; same && i < a.size(); ++i)
    same = std::abs(a[i][0] - b[i][0]) <= 1 && std::abs(a[i][1] - b[i][1]) <= 1;
  if (!same)
    std::cerr << name << ": ours and Far's uv values differ at level 2 (" << a.size() << " and " << b.size()
              << " values)\n";
  return same;
}
#endif

void register_case(const std::string& name, int first_level, int last_level)
{
  const auto add = [&](const std::string& implementation, auto function, auto data) {
    benchmark::RegisterBenchmark(("face_varying/" + name + "/" + implementation).c_str(), function, name, data)
      ->DenseRange(first_level, last_level)
      ->ArgName("level")
      ->Unit(benchmark::kMillisecond);
  };
  add("CGAL_ext_positions", ours, Data::positions);
  add("CGAL_ext_vertex_map", ours, Data::vertex_map);
  add("CGAL_ext_vertex_map_4d", ours, Data::vertex_map_4d);
  add("CGAL_ext_vertex_map_and_indices", ours, Data::vertex_map_and_indices);
  add("CGAL_ext_uv_channel", ours, Data::uv_channel);
#if CGAL_EXT_HAVE_OPENSUBDIV
  add("OpenSubdiv_Far_positions", far, false);
  add("OpenSubdiv_Far_uv_channel", far, true);
#endif
}

} // namespace

int main(int argc, char** argv)
{
#if CGAL_EXT_HAVE_OPENSUBDIV
  if (!same_channel_values("cube_uv") || !same_channel_values("torus100x100_uv"))
    return 1;
#endif
  register_case("cube_uv", 6, 8);
  register_case("torus100x100_uv", 5, 5);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
