// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Uniform subdivision, side by side: CGAL_ext::Subdivision::catmull_clark /
// loop on a Mobius_mesh against CGAL's Subdivision_method_3 on a Surface_mesh,
// OpenSubdiv's Far refiner and OpenMesh's uniform subdividers, on the same
// points and faces:
//   catmull_clark/octahedron   6 vertices, 8 triangles, levels 1-8
//   catmull_clark/torus100x100 CGAL_ext::make_torus(mesh, 100, 100), 10 000 quads, levels 1-5
//   loop/icosahedron           12 vertices, 20 triangles, levels 1-8
//   bilinear/torus100x100      the same torus, levels 1-5 (CGAL: PQQ with Linear_mask_3;
//                              OpenSubdiv: its bilinear scheme)
//   doo_sabin/torus100x100     the same torus, levels 1-4 (CGAL only: OpenSubdiv has none)
//   sqrt3/icosahedron          levels 1-10 (CGAL and OpenMesh)
// and, ours alone (the peers take no one-sided surface), Catmull–Clark of
//   catmull_clark/mobius_strip625x25   make_mobius_strip(mesh, 625, 25), 15 625 quads, level 3: 1 M quads
//   catmull_clark/mobius_strip625x64   make_mobius_strip(mesh, 625, 64), 40 000 quads, level 4: 10.24 M quads
//   catmull_clark/klein_bottle125x125  make_klein_bottle(mesh, 125, 125), 15 625 quads, level 3: 1 M quads
//   catmull_clark/klein_bottle200x200  make_klein_bottle(mesh, 200, 200), 40 000 quads, level 4: 10.24 M quads
//
// Timed (manual time): the subdivision call alone, from a ready input mesh to
// a ready output mesh with its points. Every iteration starts from a fresh
// copy of the input, made (and the previous output destroyed) outside the
// timing, and outside the CPU time too (PauseTiming). For OpenSubdiv: from
// building the TopologyRefiner out of the base topology to having the points
// of every level. Outputs of 1 M faces and more run once per repetition.
//
// Implementations: CGAL_ext_Mobius_mesh (serial, the reference), and
// CGAL_ext_Mobius_mesh_parallel/threads:N (CGAL::Parallel_tag) for N = 1, 2,
// 4, … up to std::thread::hardware_concurrency() when the library has the
// parallel path; CGAL_Surface_mesh; OpenSubdiv_Far (the default
// UniformOptions: the last level keeps only its face-vertices) and
// OpenSubdiv_Far_full_topology (fullTopologyInLastLevel, a complete mesh as
// the others build); OpenMesh_PolyMesh / OpenMesh_TriMesh (double points);
// and bandwidth_floor/threads:N, in every case (see class Floor): allocating
// the result Mobius_mesh's arrays and writing each of their bytes once with
// memset, by N threads on disjoint slices, the least any implementation has
// to do. Each threads:N benchmark runs under its own tbb::global_control
// (max_allowed_parallelism = N), made and destroyed with the benchmark, so
// no cap exists for the whole program: TBB applies the smallest of the caps
// alive, not the innermost (a benchmark whose cap TBB does not apply as asked
// stops with an error). The CPU time is the main thread's: for the
// threaded variants, read the real (manual) time.
//
// Counters (memory measured once per benchmark, outside the timed loop):
//   faces          faces of the result
//   peak_bytes     highest heap while subdividing, the input copy included
//   result_bytes   heap held once the call returns (OpenSubdiv: the refiner,
//                  which keeps every level, and the points of every level)
//   faults_per_run minor page faults per timed call (first touches of fresh
//                  pages: what the cold runs pay for)
//
// Heap modes as in bench_soup_import: `warm` (no mmap, no trimming, pages
// reused from the run before) for every case, `cold` (blocks of 128 KiB and
// more are fresh mmaps, so every run touches new pages) for outputs of 80 k to
// 1.5 M faces. All cold benchmarks run before the warm ones.
//
// At start the program checks that every implementation gives the same
// vertex and face counts and the same points (as sets, to 1e-9) at level 2 on
// every input the peers take, and, on the one-sided inputs, that ours (serial
// and parallel) gives the closed-form counts at level 1; each benchmark
// checks its face and vertex counts against the closed form: a comparison of
// different outputs would be worthless.
//
// And subdivision/parallel_threshold/...: one step of tori of 1 k to 262 k
// vertices, serial against parallel, the measurement behind the automatic
// parallel threshold (see register_threshold()).
//
// Names follow `group/case.../implementation`; scripts/bench.sh takes the
// first implementation whose name starts with `CGAL_ext` as the reference.

#include "bench_subdivision.h"
// The counting operator new / delete: in this translation unit only.
#include "heap_accounting.h"
#include "heap_modes.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#if CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#endif

#if CGAL_EXT_HAVE_OPENMESH
// OpenMesh's VectorT leaves its coordinates uninitialised, which its property
// arrays then copy (PropertyT::push_back).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>
#pragma GCC diagnostic pop
#endif

#include <benchmark/benchmark.h>

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <tuple>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace subdivision_bench;
using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------------------
// Inputs

// The faces of a convex polyhedron centred at the origin: the triples of
// vertices pairwise at the shortest distance, oriented outward.
Soup convex_triangles(std::vector<std::array<double, 3>> v)
{
  auto d2 = [&](std::size_t a, std::size_t b) {
    double s = 0;
    for (int k = 0; k < 3; ++k)
      s += (v[a][k] - v[b][k]) * (v[a][k] - v[b][k]);
    return s;
  };
  double edge = std::numeric_limits<double>::max();
  for (std::size_t a = 0; a < v.size(); ++a)
    for (std::size_t b = a + 1; b < v.size(); ++b)
      edge = (std::min)(edge, d2(a, b));
  auto adjacent = [&](std::size_t a, std::size_t b) { return d2(a, b) < edge * 1.01; };
  Soup s;
  for (const auto& p : v)
    s.points.emplace_back(p[0], p[1], p[2]);
  for (std::size_t a = 0; a < v.size(); ++a)
    for (std::size_t b = a + 1; b < v.size(); ++b)
      for (std::size_t c = b + 1; c < v.size(); ++c)
        if (adjacent(a, b) && adjacent(b, c) && adjacent(a, c)) {
          const auto n = CGAL::cross_product(s.points[b] - s.points[a], s.points[c] - s.points[a]);
          const bool outward = n * (s.points[a] - CGAL::ORIGIN) > 0;
          s.polygons.push_back(outward ? Polygon{a, b, c} : Polygon{a, c, b});
        }
  return s;
}

Soup octahedron()
{
  return convex_triangles({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
}

Soup icosahedron()
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  return convex_triangles({{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}});
}

enum class Input {
  octahedron,
  torus,
  icosahedron,
  mobius_strip_625x25,
  mobius_strip_625x64,
  klein_bottle_125x125,
  klein_bottle_200x200,
  torus_bilinear,
  torus_doo_sabin,
  icosahedron_sqrt3
};

struct Input_data
{
  Soup soup;
  Scheme scheme;
  long long euler_characteristic;
  std::size_t border_edges;
  // Whether the peers subdivide it too: they do not take one-sided surfaces.
  bool has_peers;
};

Input_data make_input(Input which)
{
  // The counts are the generators' closed forms: a Möbius strip of n x m
  // quads has χ = 0 and one border of 2n edges; a Klein bottle has χ = 0
  // and no border.
  switch (which) {
  case Input::octahedron: return {octahedron(), Scheme::catmull_clark, 2, 0, true};
  case Input::torus: return {torus_soup(100, 100), Scheme::catmull_clark, 0, 0, true};
  case Input::icosahedron: return {icosahedron(), Scheme::loop, 2, 0, true};
  case Input::mobius_strip_625x25: return {mobius_strip_soup(625, 25), Scheme::catmull_clark, 0, 2 * 625, false};
  case Input::mobius_strip_625x64: return {mobius_strip_soup(625, 64), Scheme::catmull_clark, 0, 2 * 625, false};
  case Input::klein_bottle_125x125: return {klein_bottle_soup(125, 125), Scheme::catmull_clark, 0, 0, false};
  case Input::klein_bottle_200x200: return {klein_bottle_soup(200, 200), Scheme::catmull_clark, 0, 0, false};
  case Input::torus_bilinear: return {torus_soup(100, 100), Scheme::bilinear, 0, 0, true};
  case Input::torus_doo_sabin: return {torus_soup(100, 100), Scheme::doo_sabin, 0, 0, true};
  case Input::icosahedron_sqrt3: return {icosahedron(), Scheme::sqrt3, 2, 0, true};
  }
  std::abort();
}

const Input_data& input(Input which)
{
  static std::map<Input, Input_data> cache;
  auto it = cache.find(which);
  if (it == cache.end())
    it = cache.emplace(which, make_input(which)).first;
  return it->second;
}

struct Size
{
  std::size_t vertices, edges, faces;
};

// Counts of the result after `levels` >= 1 steps: a step of Catmull–Clark
// (or bilinear) turns a face of n sides into n quads, of Loop a triangle
// into 4, and halves every border edge. Every halfedge with a face is one
// corner, so 4F = 2E - B (quads) or 3F = 2E - B (triangles); then
// V = χ + E - F. On closed meshes: a Doo–Sabin step makes a vertex per
// corner (V' = 2E, each of valence 4: E' = 4E) and a face per face, edge and
// vertex (F' = F + E + V); a √3 step a vertex per triangle (V' = V + F), three
// triangles per triangle (F' = 3F) and three edges per triangle (E' = E + 3F).
Size expected_size(const Input_data& in, unsigned levels)
{
  if (in.scheme == Scheme::doo_sabin || in.scheme == Scheme::sqrt3) {
    std::size_t f = in.soup.polygons.size(), e = 0, v = in.soup.points.size();
    for (const Polygon& p : in.soup.polygons)
      e += p.size();
    e /= 2; // closed: every edge has two corners
    for (unsigned l = 0; l < levels; ++l) {
      if (in.scheme == Scheme::doo_sabin)
        std::tie(v, e, f) = std::make_tuple(2 * e, 4 * e, f + e + v);
      else
        std::tie(v, e, f) = std::make_tuple(v + f, e + 3 * f, 3 * f);
    }
    return {v, e, f};
  }
  std::size_t f = 0;
  if (in.scheme == Scheme::catmull_clark || in.scheme == Scheme::bilinear) {
    for (const Polygon& p : in.soup.polygons)
      f += p.size();
    f <<= 2 * (levels - 1);
  } else {
    f = in.soup.polygons.size() << (2 * levels);
  }
  const std::size_t b = in.border_edges << levels;
  const std::size_t e = ((in.scheme == Scheme::loop ? 3 : 4) * f + b) / 2;
  return {std::size_t(in.euler_characteristic + (long long)e - (long long)f), e, f};
}

// ---------------------------------------------------------------------------
// Implementations. A runner holds a working copy of one input: `reset` makes
// a fresh one (untimed), `subdivide` is the timed call, `release` frees the
// working mesh and the result.

struct Result
{
  std::size_t vertices = 0, faces = 0;
};

class Runner
{
public:
  virtual ~Runner() = default;
  virtual void reset() = 0;
  virtual void subdivide() = 0;
  virtual void release() = 0;
  virtual Result result() const = 0;
  virtual std::vector<Point> points() const = 0;
  // Whether `subdivide` builds a mesh, whose result() and points() mean something.
  virtual bool builds_mesh() const { return true; }
};

// `threads`: the TBB cap the runner is timed under (0 for none), which the
// bandwidth floor also takes as its number of writers.
using Make_runner = std::function<std::unique_ptr<Runner>(const Input_data&, unsigned levels, unsigned threads)>;

class Ours final : public Runner
{
public:
  Ours(const Input_data& in, unsigned levels, bool parallel) : scheme_(in.scheme), levels_(levels), parallel_(parallel)
  {
    input_.assign(in.soup);
  }
  void reset() override
  {
    work_.reset();
    work_ = std::make_unique<Our_mesh>();
    work_->assign(input_);
  }
  void subdivide() override { work_->subdivide(scheme_, levels_, parallel_); }
  void release() override { work_.reset(); }
  Result result() const override { return {work_->number_of_vertices(), work_->number_of_faces()}; }
  std::vector<Point> points() const override { return work_->points(); }

private:
  Our_mesh input_;
  std::unique_ptr<Our_mesh> work_;
  Scheme scheme_;
  unsigned levels_;
  bool parallel_;
};

class Cgal final : public Runner
{
  using Mesh = CGAL::Surface_mesh<Point>;

public:
  Cgal(const Input_data& in, unsigned levels) : scheme_(in.scheme), levels_(levels)
  {
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(in.soup.points, in.soup.polygons, input_);
  }
  void reset() override
  {
    work_.reset();
    work_.emplace(input_);
  }
  void subdivide() override
  {
    namespace SM = CGAL::Subdivision_method_3;
    const auto np = CGAL::parameters::number_of_iterations(levels_);
    switch (scheme_) {
    case Scheme::catmull_clark: SM::CatmullClark_subdivision(*work_, np); return;
    case Scheme::loop: SM::Loop_subdivision(*work_, np); return;
    case Scheme::bilinear: // CGAL's bilinear: the quad split with its linear mask
      SM::PQQ(*work_, CGAL::Linear_mask_3<Mesh>(&*work_, get(CGAL::vertex_point, *work_)), np);
      return;
    case Scheme::doo_sabin: SM::DooSabin_subdivision(*work_, np); return;
    case Scheme::sqrt3: SM::Sqrt3_subdivision(*work_, np); return;
    }
  }
  void release() override { work_.reset(); }
  Result result() const override { return {work_->number_of_vertices(), work_->number_of_faces()}; }
  std::vector<Point> points() const override
  {
    std::vector<Point> p;
    for (auto v : work_->vertices())
      p.push_back(work_->point(v));
    return p;
  }

private:
  Mesh input_;
  std::optional<Mesh> work_;
  Scheme scheme_;
  unsigned levels_;
};

#if CGAL_EXT_HAVE_OPENSUBDIV
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

struct Osd_vertex
{
  double x, y, z;
  void Clear(void* = nullptr) { x = y = z = 0; }
  void AddWithWeight(const Osd_vertex& s, double w)
  {
    x += w * s.x;
    y += w * s.y;
    z += w * s.z;
  }
};

class Osd final : public Runner
{
public:
  // `full_topology`: the last level also gets its edges and vertex rings, as
  // the other levels (UniformOptions::fullTopologyInLastLevel), which a
  // complete mesh has; by default it gets only its face-vertices.
  Osd(const Input_data& in, unsigned levels, bool full_topology)
    : levels_(int(levels)), full_topology_(full_topology)
  {
    for (const Polygon& p : in.soup.polygons) {
      sizes_.push_back(int(p.size()));
      for (std::size_t v : p)
        indices_.push_back(int(v));
    }
    for (const Point& p : in.soup.points)
      base_.push_back({p.x(), p.y(), p.z()});
    type_ = in.scheme == Scheme::catmull_clark ? Sdc::SCHEME_CATMARK
            : in.scheme == Scheme::loop        ? Sdc::SCHEME_LOOP
                                               : Sdc::SCHEME_BILINEAR;
    options_.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY); // ours' default
  }
  void reset() override
  {
    release();
    positions_ = base_;
  }
  void subdivide() override
  {
    Far::TopologyDescriptor desc;
    desc.numVertices = int(base_.size());
    desc.numFaces = int(sizes_.size());
    desc.numVertsPerFace = sizes_.data();
    desc.vertIndicesPerFace = indices_.data();
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    refiner_.reset(Factory::Create(desc, Factory::Options(type_, options_)));
    Far::TopologyRefiner::UniformOptions uniform(levels_);
    uniform.fullTopologyInLastLevel = full_topology_;
    refiner_->RefineUniform(uniform);
    positions_.resize(std::size_t(refiner_->GetNumVerticesTotal()));
    Far::PrimvarRefinerReal<double> primvar(*refiner_);
    Osd_vertex* src = positions_.data();
    for (int level = 1; level <= levels_; ++level) {
      Osd_vertex* dst = src + refiner_->GetLevel(level - 1).GetNumVertices();
      primvar.Interpolate(level, src, dst);
      src = dst;
    }
  }
  void release() override
  {
    refiner_.reset();
    std::vector<Osd_vertex>().swap(positions_);
  }
  Result result() const override
  {
    const auto& last = refiner_->GetLevel(levels_);
    return {std::size_t(last.GetNumVertices()), std::size_t(last.GetNumFaces())};
  }
  std::vector<Point> points() const override
  {
    const std::size_t n = std::size_t(refiner_->GetLevel(levels_).GetNumVertices());
    std::vector<Point> p;
    for (std::size_t i = positions_.size() - n; i < positions_.size(); ++i)
      p.emplace_back(positions_[i].x, positions_[i].y, positions_[i].z);
    return p;
  }

private:
  std::vector<int> sizes_, indices_;
  std::vector<Osd_vertex> base_, positions_;
  Sdc::SchemeType type_;
  Sdc::Options options_;
  std::unique_ptr<Far::TopologyRefiner> refiner_;
  int levels_;
  bool full_topology_;
};
#endif

#if CGAL_EXT_HAVE_OPENMESH
// Double coordinates, as the others (OpenMesh's default is float).
struct Om_traits : OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Om_poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<Om_traits>;
using Om_tri_mesh = OpenMesh::TriMesh_ArrayKernelT<Om_traits>;

// Catmull–Clark needs a PolyMesh, Loop and √3 a TriMesh.
template <class Mesh, template <class, class> class Subdivider>
class Om final : public Runner
{
public:
  Om(const Input_data& in, unsigned levels) : levels_(levels)
  {
    std::vector<typename Mesh::VertexHandle> v;
    for (const Point& p : in.soup.points)
      v.push_back(input_.add_vertex(typename Mesh::Point(p.x(), p.y(), p.z())));
    std::vector<typename Mesh::VertexHandle> face;
    for (const Polygon& polygon : in.soup.polygons) {
      face.clear();
      for (std::size_t i : polygon)
        face.push_back(v[i]);
      input_.add_face(face);
    }
  }
  void reset() override
  {
    work_.reset();
    work_.emplace(input_);
  }
  void subdivide() override
  {
    Subdivider<Mesh, double> subdivider;
    subdivider.attach(*work_);
    subdivider(levels_);
    subdivider.detach();
  }
  void release() override { work_.reset(); }
  Result result() const override { return {work_->n_vertices(), work_->n_faces()}; }
  std::vector<Point> points() const override
  {
    std::vector<Point> p;
    for (auto v : work_->vertices()) {
      const auto& q = work_->point(v);
      p.emplace_back(q[0], q[1], q[2]);
    }
    return p;
  }

private:
  Mesh input_;
  std::optional<Mesh> work_;
  unsigned levels_;
};
#endif

// The bandwidth floor: what it costs only to put the result in memory. The
// timed call allocates one block per array of the result Mobius_mesh, as
// large as that array (mesh_array_bytes() of the expected counts: 98 bytes a
// quad at large levels), and writes every byte of them once with memset,
// split among `parts` writers on disjoint, page-aligned slices. Freeing the
// blocks is outside the timing, as freeing a result is. Every implementation
// has to produce at least these bytes, in memory it allocates, so none can
// be faster on this machine: memset is the C library's tuned write (glibc:
// `rep stosb` on large blocks), reads nothing, computes nothing, and on a
// cold heap faults in the same fresh pages as the result's arrays.
class Floor final : public Runner
{
public:
  Floor(const Input_data& in, unsigned levels, unsigned parts) : parts_((std::max)(parts, 1u))
  {
    const Size n = expected_size(in, levels);
    sizes_ = mesh_array_bytes(n.vertices, n.edges, n.faces);
    blocks_.reserve(sizes_.size()); // nothing grows inside the timing
    buffers_.reserve(sizes_.size());
  }
  void reset() override { release(); }
  void subdivide() override
  {
    for (std::size_t size : sizes_) {
      buffers_.emplace_back(new unsigned char[size]); // not value-initialised: no zeroing
      blocks_.push_back({buffers_.back().get(), size});
    }
    write_blocks(blocks_, parts_);
    benchmark::ClobberMemory();
  }
  void release() override
  {
    blocks_.clear();
    buffers_.clear();
  }
  Result result() const override { return {}; }
  std::vector<Point> points() const override { return {}; }
  bool builds_mesh() const override { return false; }

private:
  unsigned parts_;
  std::vector<std::size_t> sizes_;
  std::vector<Block> blocks_;
  std::vector<std::unique_ptr<unsigned char[]>> buffers_;
};

struct Implementation
{
  std::string name;
  Make_runner make;
  // Whether it runs once per thread count, as `.../name/threads:N`.
  bool threaded = false;
};

void add_peers(Scheme scheme, std::vector<Implementation>& all)
{
  all.push_back(
    {"CGAL_Surface_mesh", [](const Input_data& d, unsigned n, unsigned) { return std::make_unique<Cgal>(d, n); }});
  // OpenSubdiv has no Doo–Sabin or √3; OpenMesh has Catmull–Clark, Loop and
  // √3 among its uniform subdividers.
  const bool opensubdiv = scheme != Scheme::doo_sabin && scheme != Scheme::sqrt3;
#if CGAL_EXT_HAVE_OPENSUBDIV
  if (opensubdiv) {
  all.push_back({"OpenSubdiv_Far",
                 [](const Input_data& d, unsigned n, unsigned) { return std::make_unique<Osd>(d, n, false); }});
  all.push_back({"OpenSubdiv_Far_full_topology",
                 [](const Input_data& d, unsigned n, unsigned) { return std::make_unique<Osd>(d, n, true); }});
  }
#else
  (void)opensubdiv;
#endif
#if CGAL_EXT_HAVE_OPENMESH
  using namespace OpenMesh::Subdivider::Uniform;
  if (scheme == Scheme::catmull_clark)
    all.push_back({"OpenMesh_PolyMesh", [](const Input_data& d, unsigned n, unsigned) {
                     return std::make_unique<Om<Om_poly_mesh, CatmullClarkT>>(d, n);
                   }});
  else if (scheme == Scheme::loop)
    all.push_back({"OpenMesh_TriMesh", [](const Input_data& d, unsigned n, unsigned) {
                     return std::make_unique<Om<Om_tri_mesh, LoopT>>(d, n);
                   }});
  else if (scheme == Scheme::sqrt3)
    all.push_back({"OpenMesh_TriMesh", [](const Input_data& d, unsigned n, unsigned) {
                     return std::make_unique<Om<Om_tri_mesh, Sqrt3T>>(d, n);
                   }});
#else
  (void)scheme;
#endif
}

// The serial ours first: scripts/bench.sh takes the first `CGAL_ext*` as the
// reference. The peers only on inputs they take.
std::vector<Implementation> implementations(const Input_data& in)
{
  std::vector<Implementation> all;
  all.push_back({"CGAL_ext_Mobius_mesh",
                 [](const Input_data& d, unsigned n, unsigned) { return std::make_unique<Ours>(d, n, false); }});
  if (parallel_available())
    all.push_back({"CGAL_ext_Mobius_mesh_parallel",
                   [](const Input_data& d, unsigned n, unsigned) { return std::make_unique<Ours>(d, n, true); }, true});
  if (in.has_peers)
    add_peers(in.scheme, all);
  all.push_back({"bandwidth_floor",
                 [](const Input_data& d, unsigned n, unsigned t) { return std::make_unique<Floor>(d, n, t); }, true});
  return all;
}

// 1, 2, 4, … up to the hardware threads, and their number itself; 1 alone
// without the parallel path.
std::vector<unsigned> thread_counts()
{
  const unsigned hardware = (std::max)(std::thread::hardware_concurrency(), 1u);
  std::vector<unsigned> counts{1};
  if (!parallel_available())
    return counts;
  while (counts.back() * 2 <= hardware)
    counts.push_back(counts.back() * 2);
  if (counts.back() != hardware)
    counts.push_back(hardware);
  return counts;
}

// ---------------------------------------------------------------------------
// Checks

// Whether `a` and `b` are the same points, as sets, to `tol` per coordinate.
bool same_point_sets(std::vector<Point> a, std::vector<Point> b, double tol, std::string& why)
{
  if (a.size() != b.size()) {
    why = std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " points";
    return false;
  }
  auto by_x = [](const Point& p, const Point& q) { return p.x() < q.x(); };
  std::sort(b.begin(), b.end(), by_x);
  std::vector<bool> used(b.size(), false);
  for (const Point& p : a) {
    auto it = std::lower_bound(b.begin(), b.end(), Point(p.x() - tol, 0, 0), by_x);
    bool found = false;
    for (; it != b.end() && it->x() <= p.x() + tol; ++it) {
      const std::size_t i = std::size_t(it - b.begin());
      if (!used[i] && std::abs(it->y() - p.y()) <= tol && std::abs(it->z() - p.z()) <= tol) {
        used[i] = found = true;
        break;
      }
    }
    if (!found) {
      why = "no match for (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) + ")";
      return false;
    }
  }
  return true;
}

struct Case
{
  Input which;
  std::string name;
  unsigned min_level, max_level;
};

// The one-sided cases come at about 1 M and 10 M output faces.
const std::vector<Case>& cases()
{
  static const std::vector<Case> all = {{Input::octahedron, "catmull_clark/octahedron", 1, 8},
                                        {Input::torus, "catmull_clark/torus100x100", 1, 5},
                                        {Input::icosahedron, "loop/icosahedron", 1, 8},
                                        {Input::mobius_strip_625x25, "catmull_clark/mobius_strip625x25", 3, 3},
                                        {Input::mobius_strip_625x64, "catmull_clark/mobius_strip625x64", 4, 4},
                                        {Input::klein_bottle_125x125, "catmull_clark/klein_bottle125x125", 3, 3},
                                        {Input::klein_bottle_200x200, "catmull_clark/klein_bottle200x200", 4, 4},
                                        {Input::torus_bilinear, "bilinear/torus100x100", 1, 5},
                                        {Input::torus_doo_sabin, "doo_sabin/torus100x100", 1, 4},
                                        {Input::icosahedron_sqrt3, "sqrt3/icosahedron", 1, 10}};
  return all;
}

// Every input, at level 2 where the peers take it: every implementation's
// counts against the closed form and its points against ours. The one-sided
// inputs have no peer: their counts at level 1 (serial and parallel) against
// the closed form are the check.
bool check_implementations_agree()
{
  bool ok = true;
  for (const Case& c : cases()) {
    const Input_data& in = input(c.which);
    const unsigned levels = in.has_peers ? 2 : 1;
    const Size expected = expected_size(in, levels);
    std::vector<Point> reference;
    for (const Implementation& impl : implementations(in)) {
      auto runner = impl.make(in, levels, 0);
      if (!runner->builds_mesh())
        continue;
      runner->reset();
      runner->subdivide();
      const Result r = runner->result();
      std::string why;
      if (r.faces != expected.faces || r.vertices != expected.vertices) {
        why = std::to_string(r.vertices) + " vertices and " + std::to_string(r.faces) + " faces instead of " +
              std::to_string(expected.vertices) + " and " + std::to_string(expected.faces);
      } else if (reference.empty()) {
        reference = runner->points();
      } else if (in.has_peers) {
        same_point_sets(reference, runner->points(), 1e-9, why);
      }
      if (!why.empty()) {
        std::fprintf(stderr, "bench_subdivision: %s, level %u: %s disagrees: %s\n", c.name.c_str(), levels,
                     impl.name.c_str(), why.c_str());
        ok = false;
      }
    }
  }
  return ok;
}

// ---------------------------------------------------------------------------
// Running

long minor_faults()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

struct Memory
{
  double peak = 0, result = 0;
};

// Heap of one run, counted from an empty working mesh: the input copy, then
// the subdivision. Nothing allocated before is freed while counting, and the
// result is freed uncounted afterwards.
Memory measure(Runner& runner)
{
  runner.release();
  heap::live = heap::peak = 0;
  heap::counting = true;
  runner.reset();
  runner.subdivide();
  const Memory m{double(heap::peak), double(heap::live)};
  heap::counting = false;
  return m;
}

// `memory` is shared by the repetitions of one benchmark: it is measured once.
// `threads` (0: none) caps TBB for this benchmark alone, its measuring run
// included.
void run(benchmark::State& state, Input which, unsigned levels, Heap_mode heap_mode, const Make_runner& make,
         unsigned threads, std::optional<Memory>& memory)
{
  std::optional<Thread_limit> limit;
  if (threads > 0) {
    limit.emplace(int(threads));
    if (Thread_limit::allowed() != threads && parallel_available()) {
      state.SkipWithError(("TBB allows " + std::to_string(Thread_limit::allowed()) + " threads, not " +
                           std::to_string(threads) + ": another tbb::global_control caps it")
                            .c_str());
      return;
    }
  }
  const Input_data& in = input(which);
  set_heap_mode(heap_mode);
  const auto runner = make(in, levels, threads);
  // The measuring run, in the first repetition, also warms the heap for the
  // timed runs; later repetitions follow the one before, whose pages the
  // warm heap keeps (Google Benchmark runs the repetitions of a benchmark
  // back to back, unless told to interleave them).
  if (!memory)
    memory = measure(*runner);

  long faults = 0;
  for (auto _ : state) {
    state.PauseTiming(); // keeps the copy out of the CPU time too
    runner->reset();
    state.ResumeTiming();
    const long faults_before = minor_faults();
    const auto start = Clock::now();
    runner->subdivide();
    const auto stop = Clock::now();
    faults += minor_faults() - faults_before;
    state.SetIterationTime(std::chrono::duration<double>(stop - start).count());
  }

  const Result r = runner->result();
  const Size expected = expected_size(in, levels);
  const bool checked = runner->builds_mesh();
  runner->release();
  if (checked && (r.faces != expected.faces || r.vertices != expected.vertices)) {
    state.SkipWithError(("got " + std::to_string(r.vertices) + " vertices and " + std::to_string(r.faces) +
                         " faces instead of " + std::to_string(expected.vertices) + " and " +
                         std::to_string(expected.faces))
                          .c_str());
    return;
  }
  state.counters["faces"] = double(expected.faces);
  state.counters["peak_bytes"] = memory->peak;
  state.counters["result_bytes"] = memory->result;
  state.counters["faults_per_run"] = double(faults) / double(state.iterations());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(expected.faces));
}

// One benchmark of `impl` on `c` at `level`; a threaded implementation gets
// the argument `threads` (its name ends with `/threads:N`).
void register_one(const Case& c, unsigned level, Heap_mode mode, const Implementation& impl)
{
  const std::size_t faces = expected_size(input(c.which), level).faces;
  const std::string name = "subdivision/" + c.name + "/level_" + std::to_string(level) +
                           (mode == Heap_mode::cold ? "/cold/" : "/warm/") + impl.name;
  const Input which = c.which;
  const Make_runner make = impl.make;
  const bool threaded = impl.threaded;
  // Memory per thread count: each is a benchmark of its own.
  const auto memory = std::make_shared<std::map<unsigned, std::optional<Memory>>>();
  auto* b = benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& st) {
    const unsigned threads = threaded ? unsigned(st.range(0)) : 0;
    run(st, which, level, mode, make, threads, (*memory)[threads]);
  });
  if (threaded) {
    b->ArgName("threads");
    for (unsigned t : thread_counts())
      b->Arg(t);
  }
  b->UseManualTime()->Unit(benchmark::kMillisecond);
  // Large outputs take a second or more per run: one run per repetition.
  if (faces >= 1000000)
    b->Iterations(1);
  else
    b->MinTime(0.05);
}

// The measurement behind Subdivision::parallel_vertices_per_thread: one
// Catmull–Clark step of an n x n torus (n² vertices), serially, in parallel
// however small the level (`parallel_min_vertices` = 0) and with the
// automatic choice, under a cap of N threads. Where `parallel_always` beats
// `serial` at N = 2 is the crossover; `parallel_auto` should follow the
// faster of the two once it has timed both (its first six iterations, where
// the level may use threads at all).
void register_threshold()
{
  for (std::size_t n : {32, 45, 64, 91, 128, 181, 256, 362, 512}) {
    const std::string base = "subdivision/parallel_threshold/torus" + std::to_string(n) + "x" + std::to_string(n) +
                             "/level_1/warm/";
    auto bench = [n](benchmark::State& st, bool parallel, std::uint32_t min_vertices) {
      std::optional<Thread_limit> limit;
      if (parallel)
        limit.emplace(int(st.range(0)));
      set_heap_mode(Heap_mode::warm);
      Our_mesh input, work;
      input.assign(torus_soup(n, n));
      for (auto _ : st) {
        st.PauseTiming();
        work.assign(input);
        st.ResumeTiming();
        const auto start = Clock::now();
        work.refine_once(parallel, min_vertices);
        st.SetIterationTime(std::chrono::duration<double>(Clock::now() - start).count());
      }
      st.counters["vertices"] = double(n * n);
    };
    benchmark::RegisterBenchmark((base + "serial").c_str(),
                                 [=](benchmark::State& st) { bench(st, false, 0); })
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond)
      ->MinTime(0.2);
    if (!parallel_available())
      continue;
    using Variant = std::pair<const char*, std::uint32_t>;
    for (const Variant& variant :
         {Variant{"parallel_always", 0u}, Variant{"parallel_auto", Our_mesh::automatic_threshold()}}) {
      const std::string name = variant.first;
      const std::uint32_t min_vertices = variant.second;
      auto* b = benchmark::RegisterBenchmark((base + name).c_str(),
                                             [=](benchmark::State& st) { bench(st, true, min_vertices); });
      b->ArgName("threads");
      for (unsigned t : thread_counts())
        if (t > 1)
          b->Arg(t);
      b->UseManualTime()->Unit(benchmark::kMicrosecond)->MinTime(0.2);
    }
  }
}

// How the machine hands data from core to core, beside the threshold: two
// loops over arrays of 256 KiB to 64 MiB, the second reading what its own
// writer (`own`) or another one (`other`) wrote in the first, on N threads;
// `serial` is both loops on one thread. Where `other` is much slower than
// `own`, a parallel pass whose loops hand data across cores gains little
// until its levels outgrow the caches (doc/benchmarks/subdivision_parallel.md).
void register_cross_core()
{
  for (std::size_t kib : {256, 1024, 4096, 16384, 65536}) {
    const std::string base = "subdivision/cross_core_reads/" + std::to_string(kib) + "KiB/";
    auto bench = [kib](benchmark::State& st, unsigned threads, bool other) {
      std::optional<Thread_limit> limit;
      if (threads > 1)
        limit.emplace(int(threads));
      std::vector<double> data(kib * 1024 / sizeof(double) / 2, 1.0), sums(data.size(), 0.0);
      for (auto _ : st)
        benchmark::DoNotOptimize(write_then_read(data, sums, threads, other));
      st.counters["bytes"] = double(kib * 1024);
    };
    benchmark::RegisterBenchmark((base + "serial").c_str(), [=](benchmark::State& st) { bench(st, 1, false); })
      ->Unit(benchmark::kMicrosecond);
    if (!parallel_available())
      continue;
    for (bool other : {false, true}) {
      auto* b = benchmark::RegisterBenchmark((base + (other ? "other" : "own")).c_str(),
                                             [=](benchmark::State& st) { bench(st, unsigned(st.range(0)), other); });
      b->ArgName("threads");
      for (unsigned t : thread_counts())
        if (t > 1)
          b->Arg(t);
      b->Unit(benchmark::kMicrosecond);
    }
  }
}

void register_all()
{
  // All cold benchmarks first: a warm run leaves its pages in the heap's free
  // lists, and glibc serves a large block from there before it considers
  // mmap, so a cold run after warm ones would find its pages already there.
  for (Heap_mode mode : {Heap_mode::cold, Heap_mode::warm})
    for (const Case& c : cases()) {
      const Input_data& in = input(c.which);
      for (unsigned level = c.min_level; level <= c.max_level; ++level) {
        const std::size_t faces = expected_size(in, level).faces;
        // Cold only for the larger outputs (some 10 MB of mesh and more), where
        // first touches of fresh pages weigh, and up to 1.5 M faces, which keeps
        // the program within minutes: beyond, a cold run faults in GBs at ~10 µs
        // a page, seconds per implementation and repetition.
        if (mode == Heap_mode::cold && !(faces >= 80000 && faces <= 1500000))
          continue;
        for (const Implementation& impl : implementations(in))
          register_one(c, level, mode, impl);
      }
    }
  register_threshold();
  register_cross_core();
}

} // namespace

int main(int argc, char** argv)
{
  // No cap for the whole program: TBB would apply it under every
  // benchmark's own (the smallest cap wins).
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  set_heap_mode(Heap_mode::cold); // the check leaves no large free blocks behind
  if (!check_implementations_agree()) {
    std::fprintf(stderr, "bench_subdivision: the implementations disagree; not benchmarking\n");
    return 1;
  }
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
