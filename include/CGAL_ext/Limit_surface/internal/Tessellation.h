// A tessellation of a limit surface, watertight by construction: every
// sample the faces share (the limit point of a base vertex, the samples
// inside a base edge) is evaluated once and its index reused, so
// neighbouring faces cannot disagree even by rounding. The samples of each
// face are those of OpenSubdiv's Bfr::Tessellation at the same rates; a face
// whose rates are all one is laid out as Bfr lays it out (quads preserved
// under Catmull–Clark, a triangle's domain under Loop), and a face whose
// rates differ has Bfr's interior grid at its inner rates joined to the
// samples of its edges by a strip of triangles. The layout runs in face
// order; the evaluations it asks for run in batches, on threads under
// `CGAL::Parallel_tag`, and give the serial result bit for bit.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_TESSELLATION_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_TESSELLATION_H

#include <CGAL_ext/Limit_surface/internal/Parameterization.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_builder.h>
#include <CGAL_ext/Subdivision/Refiner.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/internal/Parallel_loops.h>
#include <CGAL_ext/internal/Uninitialized_array.h>

#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// The rates of a tessellation, as Bfr::Tessellation takes them: for each
// base edge the number of segments along it, for each face its inner rates
// (along u and v for a quad; other faces use the first).
struct Tessellation_rates
{
  std::vector<int> edge;                 // by edge index
  std::vector<std::array<int, 2>> inner; // by face index

  static Tessellation_rates uniform(std::size_t edges, std::size_t faces, int rate)
  {
    return {std::vector<int>(edges, rate), std::vector<std::array<int, 2>>(faces, {rate, rate})};
  }
};

// Builds the tessellation of `mesh` (the surface's own copy of the base
// mesh) at `rates`. `Surface` is Limit_surface; `corner_point(v, f,
// evaluated)` gives the point of base vertex v, first met at a corner of f
// where the surface evaluates to `evaluated`. With `triangle_domain` (Loop)
// a triangle is parameterised over the triangle (0, 0), (1, 0), (0, 1), not
// split into sub-faces.
template <class Surface, class P, class CornerPoint>
class Limit_tessellator
{
  using FT = typename Surface::FT;
  using Vector = typename Surface::Kernel::Vector_3;
  using Evaluation = typename Surface::Evaluation;
  static constexpr std::size_t none = std::size_t(-1);

public:
  Limit_tessellator(const Surface& surface, const Mobius_mesh<P>& mesh, const Tessellation_rates& rates,
                    const CornerPoint& corner_point, bool triangle_domain = false)
      : s_(surface), m_(mesh), rates_(rates), corner_point_(corner_point), triangle_domain_(triangle_domain)
  {}

  // The result, with "v:normal" and, where the base has Möbius edges,
  // "h:normal": sample() then build().
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  Mobius_mesh<P> run()
  {
    sample<ConcurrencyTag>();
    return build<ConcurrencyTag>();
  }

  // Lays out the samples and facets of every face, in face order, and
  // evaluates the samples in batches as they are laid out: in parallel for
  // `CGAL::Parallel_tag`, each sample one evaluation of its own, so that the
  // points and normals are the serial ones bit for bit.
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  void sample()
  {
    bool mobius = false;
    for (Edge_index e : m_.edges())
      mobius = mobius || m_.is_mobius(e);
    corner_normals_ = mobius;
    points_.reserve(expected_samples());
    normals_.reserve(points_.capacity());
    points_.assign(m_.number_of_vertices(), P(CGAL::ORIGIN));
    normals_.assign(m_.number_of_vertices(), Vector(CGAL::NULL_VECTOR));
    n_samples_ = m_.number_of_vertices();
    vertex_done_.assign(m_.number_of_vertices(), false);
    edge_owner_.assign(m_.number_of_edges(), Dart());
    edge_first_.assign(m_.number_of_edges(), none);
    for (Vertex_index v : m_.vertices())
      points_[v.idx()] = m_.point(v); // an isolated vertex stays where it is
    for (Face_index f : m_.faces()) {
      if (!s_.is_hole(f)) // a hole's edges are sampled by its neighbours
        add_face(f);
      if (pending_.size() >= batch_size)
        evaluate_pending<ConcurrencyTag>();
    }
    evaluate_pending<ConcurrencyTag>();
  }

  // After sample(): the mesh of the facets, built at once from their lists
  // (facet f is face f, its corners in the facet's order), as the soup
  // import builds (in parallel for `CGAL::Parallel_tag`, the same mesh).
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  Mobius_mesh<P> build()
  {
    Mobius_mesh<P> out;
    try {
      // The parallel builder does more work in all: with one thread, or few
      // samples a thread, the serial one is faster (the same mesh).
      CGAL_ext::internal::with_concurrency<ConcurrencyTag>(
        runs_in_parallel(std::uint32_t(points_.size()), Refinement_options::automatic), [&](auto tag) {
          copies_ = CGAL_ext::internal::build_mesh_from_faces<decltype(tag)>(
            facets_.view(std::uint32_t(points_.size())), [&](std::uint32_t v) { return points_[v]; }, true, out);
        });
    } catch (const Soup_error& e) {
      throw Parameter_error(std::string("Limit_surface::tessellate: internal error, a facet was refused: ") + e.what());
    }
    auto vn = out.template add_property_map<Vertex_index, Vector>("v:normal", Vector(CGAL::NULL_VECTOR)).first;
    CGAL_ext::internal::for_each_index<ConcurrencyTag>(std::uint32_t(out.number_of_vertices()), [&](std::uint32_t v) {
      vn[Vertex_index(v)] = normals_[sample_of(Vertex_index(v))];
    });
    if (corner_normals_)
      add_corner_normals<ConcurrencyTag>(out);
    return out;
  }

  // After sample(): the corners of each facet of the result (facet f is face
  // f of the result), as sample ids in the order the facet was made; the
  // same layout at the same rates on another mesh of the same faces (a
  // channel's cage).
  const CGAL_ext::internal::Face_list& facets() const { return facets_; }
  // After sample(): the point of each sample id.
  const CGAL_ext::internal::Uninitialized_array<P>& points() const { return points_; }
  // After build(): the sample id of vertex v of the result. Holes can leave
  // faces with a surface meeting at one vertex only (their other neighbours
  // holes): the result has a copy of that vertex per further fan, at the end.
  std::uint32_t sample_of(Vertex_index v) const
  {
    return v.idx() < points_.size() ? std::uint32_t(v.idx()) : copies_[v.idx() - points_.size()].original;
  }

private:
  // The samples laid out and not yet evaluated, at most about this many at
  // once: enough work for the threads of a batch, and a bounded list.
  static constexpr std::size_t batch_size = std::size_t(1) << 16;

  // An evaluation to make: at parameter uv of face f, into sample `target`
  // (its point and normal), or with `normal_only` into the normal that a
  // face sees at a base vertex that another face evaluated first.
  struct Pending
  {
    Face_index f;
    std::array<FT, 2> uv;
    std::size_t target;
    bool normal_only;
  };

  // Where a facet corner takes its normal from (corner normals only): a
  // sample's normal, or its negation (across a Möbius edge), or a normal of
  // its face's own evaluation (`seen`).
  struct Normal_source
  {
    enum Kind : std::uint8_t { sample, negated_sample, seen };
    std::size_t index;
    Kind kind;
  };

  // One face: its corners' darts and samples, and where the normals of its
  // boundary samples seen from it come from.
  struct Face_state
  {
    Face_index f;
    std::vector<Dart> darts;          // darts[k] runs from corner k to corner k + 1
    std::vector<std::size_t> corners; // the sample of each corner
    std::unordered_map<std::size_t, Normal_source> boundary_normals; // in f's orientation
  };

  // A sample of the ring that a strip joins to an edge, at fraction
  // num / den along the edge.
  struct Ring_sample
  {
    std::size_t id;
    std::int64_t num, den;
  };

  int sides(const Face_state& st) const { return int(st.darts.size()); }
  int edge_rate(const Face_state& st, int k) const { return rates_.edge[m_.edge(st.darts[std::size_t(k)]).idx()]; }

  // A new sample at parameter uv of face f, evaluated with its batch.
  std::size_t add_sample(Face_index f, const std::array<FT, 2>& uv)
  {
    pending_.push_back({f, uv, n_samples_, false});
    return n_samples_++;
  }

  // The sample of corner k of the face: the base vertex, its point given
  // once, by the first face to reach it.
  std::size_t corner(Face_state& st, int k)
  {
    const Vertex_index v = m_.source(st.darts[std::size_t(k)]);
    const std::array<FT, 2> uv = corner_parameter<FT>(sides(st), triangle_domain_, k);
    const bool first = !vertex_done_[v.idx()];
    if (first) {
      vertex_done_[v.idx()] = true;
      pending_.push_back({st.f, uv, v.idx(), false});
    }
    if (corner_normals_) {
      if (first) {
        st.boundary_normals[v.idx()] = {v.idx(), Normal_source::sample};
      } else {
        st.boundary_normals[v.idx()] = {seen_normals_.size(), Normal_source::seen};
        pending_.push_back({st.f, uv, seen_normals_.size(), true});
        seen_normals_.push_back(Vector(CGAL::NULL_VECTOR));
      }
    }
    return v.idx();
  }

  // The sample at fraction i / N (0 < i < N, N the edge's rate) along edge k
  // from corner k. The first face to reach an edge makes its samples, in
  // the order from its dart's source; another dart reads them backwards if
  // it runs the other way, as a neighbour of the same orientation does, and
  // forwards if it runs the same way: across a Möbius edge, whose far face
  // sees the surface from the other side, so its normal is the negation.
  std::size_t edge_sample(Face_state& st, int k, int i)
  {
    const Dart d = st.darts[std::size_t(k)];
    const Edge_index e = m_.edge(d);
    const int N = rates_.edge[e.idx()];
    if (edge_first_[e.idx()] == none) {
      edge_owner_[e.idx()] = d;
      edge_first_[e.idx()] = n_samples_;
      for (int j = 1; j < N; ++j)
        add_sample(st.f, edge_parameter<FT>(sides(st), triangle_domain_, k, j, N));
    }
    const Dart owner = edge_owner_[e.idx()];
    const bool same_way = m_.source(owner) == m_.source(d); // an edge's ends differ
    const std::size_t id = edge_first_[e.idx()] + std::size_t(same_way ? i - 1 : N - i - 1);
    if (corner_normals_)
      st.boundary_normals[id] = {id, same_way && !(owner == d) ? Normal_source::negated_sample : Normal_source::sample};
    return id;
  }

  // A face whose outer and inner rates are all one rate is laid out as Bfr
  // lays it out at that uniform rate; another has Bfr's interior samples at
  // its inner rates, raised where Bfr puts only the face's centre (an inner
  // rate of 1, or 2 on a Loop triangle) to the rate that gives just that.
  void add_face(Face_index f)
  {
    Face_state st;
    st.f = f;
    for (Dart d : CGAL_ext::halfedges_around_face(m_.halfedge(f), m_))
      st.darts.push_back(m_.next(d));
    const int n = sides(st);
    for (int k = 0; k < n; ++k)
      st.corners.push_back(corner(st, k));
    const std::array<int, 2> inner = rates_.inner[f.idx()];
    bool uniform = n != 4 || inner[1] == inner[0];
    for (int k = 0; k < n; ++k)
      uniform = uniform && edge_rate(st, k) == inner[0];
    if (is_triangle_domain(n, triangle_domain_))
      add_triangle(st, uniform ? inner[0] : std::max(inner[0], 3), !uniform);
    else if (n == 4 && (uniform || (inner[0] >= 2 && inner[1] >= 2)))
      add_quad(st, inner[0], inner[1], !uniform);
    else if (n == 4)
      add_quad(st, 2, 2, true);
    else
      add_polygon(st, uniform ? inner[0] : std::max(inner[0], 2), !uniform);
  }

  // The strip between edge k of the face (its corners and samples) and the
  // part `ring` of the interior's outermost ring that faces it, from the
  // ring's sample nearest corner k to that nearest corner k + 1: triangles
  // made by walking both in order of their fraction along the edge (so the
  // strips of neighbouring edges meet along the segment from a corner to
  // the ring's sample nearest it).
  void zip(Face_state& st, int k, const std::vector<Ring_sample>& ring)
  {
    const int N = edge_rate(st, k);
    std::vector<Ring_sample> edge{{st.corners[std::size_t(k)], 0, 1}};
    for (int i = 1; i < N; ++i)
      edge.push_back({edge_sample(st, k, i), i, N});
    edge.push_back({st.corners[std::size_t((k + 1) % sides(st))], 1, 1});
    std::size_t x = 0, y = 0;
    while (x + 1 < edge.size() || y + 1 < ring.size()) {
      const Ring_sample &a = edge[std::min(x + 1, edge.size() - 1)], &b = ring[std::min(y + 1, ring.size() - 1)];
      if (y + 1 == ring.size() || (x + 1 < edge.size() && a.num * b.den <= b.num * a.den)) {
        emit(st, {edge[x].id, edge[x + 1].id, ring[y].id});
        ++x;
      } else {
        emit(st, {edge[x].id, ring[y + 1].id, ring[y].id});
        ++y;
      }
    }
  }

  // A triangle over its own domain at rate N: N² triangles, (i, j) at
  // parameter (i / N, j / N), i + j <= N, the lattice's lines parallel to
  // the sides. With `strips`, the samples of the edges are their own and
  // the lattice's outermost row of triangles (N >= 3) is replaced by strips.
  void add_triangle(Face_state& st, int N, bool strips)
  {
    std::vector<std::size_t> g(std::size_t(N + 1) * std::size_t(N + 1), none);
    auto at = [&](int i, int j) -> std::size_t& { return g[std::size_t(j) * std::size_t(N + 1) + std::size_t(i)]; };
    if (!strips) {
      at(0, 0) = st.corners[0];
      at(N, 0) = st.corners[1];
      at(0, N) = st.corners[2];
      for (int i = 1; i < N; ++i) {
        at(i, 0) = edge_sample(st, 0, i);
        at(N - i, i) = edge_sample(st, 1, i);
        at(0, N - i) = edge_sample(st, 2, i);
      }
    }
    for (int j = 1; j < N; ++j)
      for (int i = 1; i + j < N; ++i)
        at(i, j) = add_sample(st.f, {FT(i) / FT(N), FT(j) / FT(N)});
    const int lo = strips ? 1 : 0, hi = strips ? N - 1 : N;
    for (int j = lo; j < hi; ++j)
      for (int i = lo; i + j < hi; ++i) {
        emit(st, {at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < hi)
          emit(st, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    if (!strips)
      return;
    // The ring's samples, by their fraction along each side (that of their
    // projection onto it, in units of 1 / 2N).
    std::array<std::vector<Ring_sample>, 3> ring;
    for (int i = 1; i <= N - 2; ++i)
      ring[0].push_back({at(i, 1), 2 * i, 2 * N});
    for (int j = 1; j <= N - 2; ++j)
      ring[1].push_back({at(N - 1 - j, j), 2 * j + 1, 2 * N});
    for (int j = N - 2; j >= 1; --j)
      ring[2].push_back({at(1, j), 2 * (N - j), 2 * N});
    for (int k = 0; k < 3; ++k)
      zip(st, k, ring[std::size_t(k)]);
  }

  // A quad: a U × V grid of quads, (i, j) at parameter (i / U, j / V). With
  // `strips` (U, V >= 2), the samples of the edges are their own and the
  // grid's outermost ring of quads is replaced by strips.
  void add_quad(Face_state& st, int U, int V, bool strips)
  {
    std::vector<std::size_t> g(std::size_t(U + 1) * std::size_t(V + 1), none);
    auto at = [&](int i, int j) -> std::size_t& { return g[std::size_t(j) * std::size_t(U + 1) + std::size_t(i)]; };
    if (!strips) { // U = V
      at(0, 0) = st.corners[0];
      at(U, 0) = st.corners[1];
      at(U, U) = st.corners[2];
      at(0, U) = st.corners[3];
      for (int i = 1; i < U; ++i) {
        at(i, 0) = edge_sample(st, 0, i);
        at(U, i) = edge_sample(st, 1, i);
        at(U - i, U) = edge_sample(st, 2, i);
        at(0, U - i) = edge_sample(st, 3, i);
      }
    }
    for (int j = 1; j < V; ++j) // rows, as Bfr orders its interior points
      for (int i = 1; i < U; ++i)
        at(i, j) = add_sample(st.f, {FT(i) / FT(U), FT(j) / FT(V)});
    const int lo = strips ? 1 : 0;
    for (int j = lo; j < V - lo; ++j)
      for (int i = lo; i < U - lo; ++i)
        emit(st, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    if (!strips)
      return;
    std::array<std::vector<Ring_sample>, 4> ring;
    for (int i = 1; i < U; ++i) {
      ring[0].push_back({at(i, 1), i, U});
      ring[2].push_back({at(U - i, V - 1), i, U});
    }
    for (int j = 1; j < V; ++j) {
      ring[1].push_back({at(U - 1, j), j, V});
      ring[3].push_back({at(1, V - j), j, V});
    }
    for (int k = 0; k < 4; ++k)
      zip(st, k, ring[std::size_t(k)]);
  }

  // An n-gon at rate N, as Bfr lays it out: sub-face k holds the grid
  // G_k(i, j), 0 <= i, j <= M = N div 2, at local parameter (2i / N, 2j / N),
  // G_k(i, 0) on edge k and G_k(0, j) on edge k - 1. At an even rate the
  // grids meet along the spokes (G_k(M, j) = G_{k+1}(j, M)) and at the
  // centre; at an odd rate a strip of quads joins neighbouring grids and
  // their inner corners make a triangle (n = 3) or a fan of triangles round
  // the centre. With `strips` (N >= 2), the samples of the edges are their
  // own and the grids' outermost rows are replaced by strips.
  void add_polygon(Face_state& st, int N, bool strips)
  {
    const int n = sides(st), M = N / 2;
    const bool even = N % 2 == 0;
    std::vector<std::vector<std::size_t>> g(std::size_t(n), std::vector<std::size_t>(std::size_t((M + 1) * (M + 1)), none));
    auto at = [&](int k, int i, int j) -> std::size_t& { return g[std::size_t((k + n) % n)][std::size_t(j * (M + 1) + i)]; };
    if (!strips)
      for (int k = 0; k < n; ++k) {
        at(k, 0, 0) = st.corners[std::size_t(k)];
        for (int i = 1; i <= M; ++i)
          at(k, i, 0) = edge_sample(st, k, i);
        for (int j = 1; j <= M; ++j)
          at(k, 0, j) = edge_sample(st, (k + n - 1) % n, N - j);
      }
    std::size_t centre = none;
    if (even || n > 3)
      centre = add_sample(st.f, sub_face_parameter(n, 0, FT(1), FT(1)));
    for (int k = 0; k < n; ++k) {
      for (int j = 1; j <= M; ++j)
        for (int i = 1; i <= M; ++i) {
          if (even && i == M && j == M)
            at(k, i, j) = centre;
          else if (!(even && i == M)) // G_k(M, j) is the next sub-face's row M
            at(k, i, j) = add_sample(st.f, sub_face_parameter(n, k, FT(2 * i) / FT(N), FT(2 * j) / FT(N)));
        }
    }
    if (even)
      for (int k = 0; k < n; ++k)
        for (int j = 1; j < M; ++j)
          at(k, M, j) = at(k + 1, j, M);
    const int lo = strips ? 1 : 0;
    for (int k = 0; k < n; ++k)
      for (int j = lo; j < M; ++j)
        for (int i = lo; i < M; ++i)
          emit(st, {at(k, i, j), at(k, i + 1, j), at(k, i + 1, j + 1), at(k, i, j + 1)});
    if (!even) {
      for (int k = 0; k < n; ++k)
        for (int j = lo; j < M; ++j)
          emit(st, {at(k, M, j), at(k + 1, j, M), at(k + 1, j + 1, M), at(k, M, j + 1)});
      if (n == 3)
        emit(st, {at(0, M, M), at(1, M, M), at(2, M, M)});
      else
        for (int k = 0; k < n; ++k)
          emit(st, {at(k, M, M), at(k + 1, M, M), centre});
    }
    if (!strips)
      return;
    // Along edge k the ring runs over row 1 of sub-face k, then down
    // column 1 of sub-face k + 1 (G_{k+1}(1, j) faces the edge's sample N − j).
    for (int k = 0; k < n; ++k) {
      std::vector<Ring_sample> ring;
      for (int i = 1; i <= M; ++i)
        ring.push_back({at(k, i, 1), i, N});
      for (int j = even ? M - 1 : M; j >= 1; --j)
        ring.push_back({at(k + 1, 1, j), N - j, N});
      zip(st, k, ring);
    }
  }

  void emit(const Face_state& st, std::initializer_list<std::size_t> facet)
  {
    if (corner_normals_)
      for (std::size_t id : facet) {
        const auto it = st.boundary_normals.find(id);
        const bool own = it != st.boundary_normals.end();
        facet_normals_.push_back(own ? it->second : Normal_source{id, Normal_source::sample});
      }
    // The facet lists index samples and corners in 32 bits.
    if (n_samples_ > std::size_t(std::uint32_t(-1)) ||
        facets_.vertex.size() + facet.size() > std::size_t(std::uint32_t(-1)))
      throw Parameter_error("Limit_surface::tessellate: the tessellation would have 2^32 samples or facet corners");
    std::uint32_t ids[4]; // a facet is a triangle or a quad
    std::size_t n = 0;
    for (std::size_t id : facet)
      ids[n++] = std::uint32_t(id);
    facets_.add(ids, ids + n);
  }

  // Evaluates the samples laid out since the last batch (their points and
  // normals first written here, by the threads that evaluate them). A base
  // vertex's point is the corner point that the first face to reach it gives.
  template <class ConcurrencyTag>
  void evaluate_pending()
  {
    points_.resize(n_samples_);
    normals_.resize(n_samples_);
    CGAL_ext::internal::for_each_index<ConcurrencyTag>(std::uint32_t(pending_.size()), [&](std::uint32_t i) {
      const Pending& p = pending_[i];
      const Evaluation e = s_.evaluate(p.f, p.uv[0], p.uv[1]);
      if (p.normal_only) {
        seen_normals_[p.target] = e.normal;
        return;
      }
      points_[p.target] =
        p.target < m_.number_of_vertices() ? corner_point_(Vertex_index(p.target), p.f, e.point) : e.point;
      normals_[p.target] = e.normal;
    });
    pending_.clear();
  }

  // About as many samples as the rates give (exactly at a uniform rate):
  // the vectors' first capacity. None past the 2^32 samples that the facet
  // lists can index, which the layout refuses with its own error. Counted
  // in double, as the rates of many faces can overflow an integer.
  std::size_t expected_samples() const
  {
    double n = double(m_.number_of_vertices());
    for (Edge_index e : m_.edges())
      n += double(rates_.edge[e.idx()] - 1);
    for (Face_index f : m_.faces()) {
      const double u = rates_.inner[f.idx()][0], v = rates_.inner[f.idx()][1], sides = double(m_.degree(f));
      const double half = std::floor(u / 2);
      if (is_triangle_domain(int(sides), triangle_domain_))
        n += (u - 1) * (u - 2) / 2;
      else
        n += sides == 4 ? (u - 1) * (v - 1) : sides * half * half + 1;
    }
    return n < double(std::uint32_t(-1)) ? std::size_t(n) : 0;
  }

  // "h:normal": for each halfedge of a facet, the normal at its target
  // seen from the facet, as the facet's corner recorded it.
  template <class ConcurrencyTag>
  void add_corner_normals(Mobius_mesh<P>& out) const
  {
    auto hn = out.template add_property_map<Halfedge_index, Vector>("h:normal", Vector(CGAL::NULL_VECTOR)).first;
    const auto normal = [&](const Normal_source& s) {
      switch (s.kind) {
      case Normal_source::negated_sample:
        return Vector(-normals_[s.index]);
      case Normal_source::seen:
        return seen_normals_[s.index];
      default:
        return normals_[s.index];
      }
    };
    CGAL_ext::internal::for_each_index<ConcurrencyTag>(std::uint32_t(out.number_of_faces()), [&](std::uint32_t i) {
      const Face_index f(i);
      const std::uint32_t first = facets_.offset[i], end = facets_.offset[i + 1];
      for (Dart d : CGAL_ext::halfedges_around_face(out.halfedge(f), out))
        for (std::uint32_t c = first; c < end; ++c)
          if (facets_.vertex[c] == sample_of(out.target(d)))
            hn[d.halfedge()] = normal(facet_normals_[c]);
    });
  }

  const Surface& s_;
  const Mobius_mesh<P>& m_;
  const Tessellation_rates& rates_;
  const CornerPoint& corner_point_;
  bool triangle_domain_ = false;
  bool corner_normals_ = false;
  std::size_t n_samples_ = 0;
  CGAL_ext::internal::Uninitialized_array<P> points_;
  CGAL_ext::internal::Uninitialized_array<Vector> normals_;
  std::vector<bool> vertex_done_;
  std::vector<Dart> edge_owner_; // the dart whose face evaluated the edge's samples
  std::vector<std::size_t> edge_first_;
  CGAL_ext::internal::Face_list facets_;
  std::vector<Pending> pending_;  // laid out, not yet evaluated
  std::vector<Vector> seen_normals_; // with corner normals: Normal_source::seen
  std::vector<CGAL_ext::internal::Split_vertex> copies_; // the result's vertices past the samples
  std::vector<Normal_source> facet_normals_; // with corner normals: one per facet corner, as facets_.vertex
};

// The smallest rate in [1, max_rate] at which `within(rate)` holds (else
// max_rate): searched by doubling, then by bisection, as a deviation falls
// with the rate (but for rounding).
template <class Within>
int smallest_rate(const Within& within, int max_rate)
{
  int lo = 1, hi = 1; // within(hi), and not within(lo - 1)
  while (!within(hi)) {
    if (hi >= max_rate)
      return max_rate;
    lo = hi + 1;
    hi = std::min(2 * hi, max_rate);
  }
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (within(mid))
      hi = mid;
    else
      lo = mid + 1;
  }
  return hi;
}

// One face of a limit surface, as the choice of rates sees it: its
// evaluation, and the distance from a point to it near a parameter.
template <class Surface>
struct Face_surface
{
  using FT = typename Surface::FT;
  using Evaluation = typename Surface::Evaluation;

  const Surface& surface;
  Face_index f;
  int sides;
  bool triangle_domain;

  Evaluation at(const std::array<FT, 2>& uv) const { return surface.evaluate(f, uv[0], uv[1]); }

  // The distance from q to the surface by two Newton steps on |S(u, v) − q|²
  // from `start`, kept in the domain of its sub-face (of the face, for a quad
  // or a Loop triangle): where the foot lies beyond, an overestimate. The
  // steps are taken in double, so that an exact kernel's numbers do not grow.
  template <class Point>
  double distance_near(const Point& q, const std::array<FT, 2>& start) const
  {
    const bool whole = has_own_domain(sides, triangle_domain);
    double u = CGAL::to_double(start[0]), v = CGAL::to_double(start[1]);
    const double u0 = whole ? 0.0 : std::floor(u), v0 = whole ? 0.0 : std::floor(v), side = whole ? 1.0 : 0.5;
    Evaluation e = at(start);
    for (int step = 0; step < 2; ++step) {
      const auto r = q - e.point;
      const double a = CGAL::to_double(e.du * e.du), b = CGAL::to_double(e.du * e.dv), c = CGAL::to_double(e.dv * e.dv);
      const double x = CGAL::to_double(e.du * r), y = CGAL::to_double(e.dv * r), det = a * c - b * b;
      if (!(det > 1e-24 * a * c))
        break; // at a degenerate corner: the distance from there
      u = std::clamp(u + (c * x - b * y) / det, u0, u0 + side);
      v = std::clamp(v + (a * y - b * x) / det, v0, v0 + side);
      if (is_triangle_domain(sides, triangle_domain) && u + v > 1) { // back onto the hypotenuse
        u = std::clamp((1 + u - v) / 2, 0.0, 1.0);
        v = 1 - u;
      }
      e = at({FT(u), FT(v)});
    }
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(q, e.point)));
  }
};

// Whether the `rate` segments of a curve on face `face` (its parameter at
// fraction i / n along it: `param(i, n)`) lie within `tolerance` of the
// surface at their midpoints (Face_surface::distance_near() from the curve's
// midpoint); of a border curve, whether the curve's midpoint lies within
// `tolerance` of its segment (a chord of a border leaves the surface where
// the border bends inwards).
template <class Surface, class Param>
bool segments_within(const Face_surface<Surface>& face, const Param& param, int rate, double tolerance,
                     bool border = false)
{
  auto a = face.at(param(0, rate));
  for (int i = 0; i < rate; ++i) {
    const auto b = face.at(param(i + 1, rate));
    const std::array<typename Surface::FT, 2> middle = param(2 * i + 1, 2 * rate);
    const double off =
      border ? std::sqrt(CGAL::to_double(CGAL::squared_distance(face.at(middle).point, typename Surface::Kernel::Segment_3(a.point, b.point))))
             : face.distance_near(CGAL::midpoint(a.point, b.point), middle);
    if (off > tolerance)
      return false;
    a = b;
  }
  return true;
}

// The smallest rate (at most max_rate) at which the segments of edge k of
// `face` lie within `tolerance` of the surface (a border's: of the border).
template <class Surface>
int edge_rate_within(const Face_surface<Surface>& face, int k, bool border, double tolerance, int max_rate)
{
  using FT = typename Surface::FT;
  const auto param = [&](int i, int n) { return edge_parameter<FT>(face.sides, face.triangle_domain, k, i, n); };
  return smallest_rate([&](int rate) { return segments_within(face, param, rate, tolerance, border); }, max_rate);
}

// The smallest rate (at most max_rate) at which the segments along the
// lines `lines` of `face` lie within `tolerance` of the surface, a line
// being its ends' parameters and the rate the number of segments along a
// unit of parameter (so a line of parameter length 1/2 is cut in rate / 2).
template <class Surface>
int lines_rate_within(const Face_surface<Surface>& face, const std::vector<std::array<typename Surface::FT, 4>>& lines,
                      int per_unit, double tolerance, int max_rate)
{
  using FT = typename Surface::FT;
  const auto within = [&](int rate) {
    for (const auto& l : lines) {
      const auto param = [&](int i, int n) {
        const FT t = FT(i) / FT(n);
        return std::array<FT, 2>{l[0] + t * (l[2] - l[0]), l[1] + t * (l[3] - l[1])};
      };
      if (!segments_within(face, param, rate, tolerance))
        return false;
    }
    return true;
  };
  return std::min(max_rate, per_unit * smallest_rate(within, (max_rate + per_unit - 1) / per_unit));
}

// The interior lines of face f along which its inner rates are measured,
// for each inner rate: for a quad the lines v = 1/4, 1/2, 3/4 (its rate
// along u) and u = 1/4, 1/2, 3/4 (along v); for a Loop triangle its three
// mid-lines, parallel to its sides; for another face the lines at 1/4, 1/2
// and 3/4 of each sub-face both ways. Mid-lines and sub-face lines are half
// a unit of parameter long.
template <class FT>
std::vector<std::vector<std::array<FT, 4>>> inner_lines(int sides, bool triangle_domain)
{
  const FT q[3] = {FT(1) / FT(4), FT(1) / FT(2), FT(3) / FT(4)}, h = FT(1) / FT(2);
  if (sides == 4) {
    std::vector<std::array<FT, 4>> along_u, along_v;
    for (const FT& c : q) {
      along_u.push_back({FT(0), c, FT(1), c});
      along_v.push_back({c, FT(0), c, FT(1)});
    }
    return {along_u, along_v};
  }
  if (is_triangle_domain(sides, triangle_domain))
    return {{{FT(0), h, h, h}, {h, FT(0), h, h}, {h, FT(0), FT(0), h}}};
  std::vector<std::array<FT, 4>> lines;
  for (int k = 0; k < sides; ++k)
    for (const FT& c : q) {
      const std::array<FT, 2> a = sub_face_parameter(sides, k, FT(0), c), b = sub_face_parameter(sides, k, FT(1), c);
      const std::array<FT, 2> d = sub_face_parameter(sides, k, c, FT(0)), e = sub_face_parameter(sides, k, c, FT(1));
      lines.push_back({a[0], a[1], b[0], b[1]});
      lines.push_back({d[0], d[1], e[0], e[1]});
    }
  return {lines};
}

// Rates whose samples lie within about `tolerance` of the surface: each edge
// the smallest rate whose segments do (edge_rate_within(), from the first
// face in face order that has the edge); each face the larger of the inner
// rates that Bfr infers from its edges' (the mean of opposite edges' for a
// quad, of all edges' for another face) and those at which the segments
// along its inner lines do (inner_lines()). A quad with an inner rate of 1
// one way and more the other takes 2: Bfr puts only its centre inside at 1,
// which would drop the other way's samples. Edges, then faces, are measured
// in parallel for `CGAL::Parallel_tag`, each on its own: the same rates.
template <class ConcurrencyTag = CGAL::Sequential_tag, class Surface, class P>
Tessellation_rates tolerance_rates(const Surface& surface, const Mobius_mesh<P>& m, double tolerance, int max_rate,
                                   bool triangle_domain)
{
  using FT = typename Surface::FT;
  Tessellation_rates rates = Tessellation_rates::uniform(m.number_of_edges(), m.number_of_faces(), 1);
  std::vector<Face_index> faces;
  std::vector<std::pair<Face_index, int>> edge_side(m.number_of_edges()); // the face that measures it, and its side
  for (Face_index f : m.faces()) {
    if (surface.is_hole(f))
      continue;
    faces.push_back(f);
    int k = 0;
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m)) {
      const Edge_index e = m.edge(m.next(d)); // edge k runs from corner k
      if (edge_side[e.idx()].first == Face_index())
        edge_side[e.idx()] = {f, k};
      ++k;
    }
  }
  CGAL_ext::internal::for_each_index<ConcurrencyTag>(std::uint32_t(edge_side.size()), [&](std::uint32_t e) {
    const auto [f, k] = edge_side[e];
    if (f == Face_index())
      return;
    const Face_surface<Surface> face{surface, f, int(m.degree(f)), triangle_domain};
    rates.edge[e] = edge_rate_within(face, k, m.is_border(Edge_index(e)), tolerance, max_rate);
  });
  CGAL_ext::internal::for_each_index<ConcurrencyTag>(std::uint32_t(faces.size()), [&](std::uint32_t i) {
    const Face_index f = faces[i];
    std::vector<int> outer;
    for (Dart d : CGAL_ext::halfedges_around_face(m.halfedge(f), m))
      outer.push_back(rates.edge[m.edge(m.next(d)).idx()]);
    const int n = int(outer.size());
    const Face_surface<Surface> face{surface, f, n, triangle_domain};
    const auto lines = inner_lines<FT>(n, triangle_domain);
    const int per_unit = n == 4 ? 1 : 2;
    if (n == 4) {
      const int u = std::max((outer[0] + outer[2]) / 2, lines_rate_within(face, lines[0], 1, tolerance, max_rate));
      const int v = std::max((outer[1] + outer[3]) / 2, lines_rate_within(face, lines[1], 1, tolerance, max_rate));
      rates.inner[f.idx()] = u == 1 && v == 1 ? std::array<int, 2>{1, 1} : std::array<int, 2>{std::max(u, 2), std::max(v, 2)};
    } else {
      int sum = 0;
      for (int r : outer)
        sum += r;
      rates.inner[f.idx()].fill(std::max(sum / n, lines_rate_within(face, lines[0], per_unit, tolerance, max_rate)));
    }
  });
  return rates;
}

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_TESSELLATION_H
