// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The patches of one base face, found as OpenSubdiv's Bfr finds them: a
// regular face is one bicubic B-spline patch (boundary patches extrapolate
// phantom points); any other face is refined, its neighbourhood copied into
// a small mesh and subdivided by the library's own rules, the children
// treated in turn, down to the approximation levels, where an irregular face
// becomes a Gregory patch built as OpenSubdiv's GregoryConverter builds it.
// Everything is walked by darts, so a neighbourhood across a Möbius edge is
// that of the orientation double cover.

#ifndef CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCH_BUILDER_H
#define CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCH_BUILDER_H

#include <CGAL_ext/Limit_surface/internal/Patches.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Sharp_features.h>
#include <CGAL_ext/Subdivision/Crease.h>
#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/subdivision.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// What the patch builder reads from the named parameters.
struct Limit_options
{
  Boundary_interpolation boundary = Boundary_interpolation::edge_only;
  Crease_method crease = Crease_method::uniform;
  Triangle_subdivision triangles = Triangle_subdivision::catmark; // Catmull–Clark only
  unsigned level_smooth = 2; // Bfr's approxLevelSmooth
  unsigned level_sharp = 6;  // Bfr's approxLevelSharp
};

// A mesh of one level with its sharpness maps (absent: all 0).
template <class P>
struct Level_mesh
{
  Mobius_mesh<P> mesh;
  std::optional<typename Mobius_mesh<P>::template Property_map<Edge_index, float>> es;
  std::optional<typename Mobius_mesh<P>::template Property_map<Vertex_index, float>> vs;

  // The number of sides every face has, 0 if they differ: where it is the
  // scheme's regular size, no corner needs to walk its faces to know.
  unsigned face_size = 0;
  // Whether an edge is semi-sharp: Chaikin's rule then needs deeper copies.
  bool semi_sharp_edges = false;

  void bind()
  {
    es = mesh.template property_map<Edge_index, float>(edge_sharpness_name);
    vs = mesh.template property_map<Vertex_index, float>(vertex_sharpness_name);
    semi_sharp_edges = false;
    if (es)
      for (Edge_index e : mesh.edges())
        semi_sharp_edges = semi_sharp_edges || Crease::is_semi_sharp((*es)[e]);
    face_size = 0;
    for (Face_index f : mesh.faces()) {
      const unsigned n = unsigned(mesh.degree(f));
      if (face_size != 0 && n != face_size) {
        face_size = 0;
        break;
      }
      face_size = n;
    }
  }
  // A border edge is infinitely sharp, as OpenSubdiv makes it.
  float edge_sharpness(Dart o) const
  {
    if (mesh.is_border(mesh.edge(o)))
      return infinitely_sharp;
    return es ? (*es)[mesh.edge(o)] : 0.0f;
  }
  float vertex_sharpness(Vertex_index v) const { return vs ? (*vs)[v] : 0.0f; }
};

// The dart of face f running from a to b, flipped if the face runs the other way.
template <class P>
Dart dart_between(const Mobius_mesh<P>& m, Face_index f, Vertex_index a, Vertex_index b)
{
  for (Dart d : halfedges_around_face(m.halfedge(f), m)) {
    if (m.source(d) == a && m.target(d) == b)
      return d;
    if (m.source(d) == b && m.target(d) == a)
      return d.flipped();
  }
  throw Parameter_error("Limit_surface: internal error, no dart between two corners of a face");
}

// The named parameters of one refinement of a copied neighbourhood. Under
// Boundary_interpolation::none the faces kept have edge_only's surface (and
// a copy's own border is not the mesh's: no face of it is a hole).
inline auto refinement_parameters(const Limit_options& opt)
{
  const Boundary_interpolation b =
    opt.boundary == Boundary_interpolation::none ? Boundary_interpolation::edge_only : opt.boundary;
  return parameters::boundary_interpolation(b).crease_method(opt.crease);
}

// The faces without a limit surface, by face index: under
// Boundary_interpolation::none every face with a vertex on a border, as
// OpenSubdiv makes them holes (and subdivision marks them, Refiner's
// mark_border()); none under the other rules, where the surface reaches the
// border. The other faces' surface is that of edge_only.
template <class P>
std::vector<bool> hole_faces(const Mobius_mesh<P>& m, Boundary_interpolation boundary)
{
  std::vector<bool> hole;
  if (boundary != Boundary_interpolation::none)
    return hole;
  hole.assign(m.number_of_faces(), false);
  for (Vertex_index v : m.vertices())
    if (!m.is_isolated(v) && m.is_border(v))
      for (Face_index f : faces_around_target(m.halfedge(v), m))
        if (f != Face_index())
          hole[f.idx()] = true;
  return hole;
}

// A corner of a face as OpenSubdiv's patch builder sees it: the span of
// faces around the vertex that contains the face (all of them, or those
// between two infinitely sharp edges or borders), its ring of points in
// counter-clockwise order (the order of the darts) from the leading edge of
// the span, the face's place in it, and the flags of its rules. The ring
// holds for each face of the span its edge end and, in a quad, its opposite
// corner; a bounded span ends with its trailing edge's end.
struct Corner
{
  // 24 points inline (an inner vertex of valence 12 among quads, 24 among
  // triangles; one less along a crease or border): analysing a face's
  // corners allocates nothing on most meshes.
  using Ring = boost::container::small_vector<Vertex_index, 24>;
  Ring ring; // edge end, opposite corner, edge end, ... (quads); edge ends (triangles)
  unsigned faces = 0;             // faces in the span
  unsigned face_in_ring = 0;
  unsigned all_faces = 0;
  unsigned infinite_edges = 0;
  bool boundary = false; // the span is bounded
  bool sharp = false;    // a corner rule from infinite sharpness
  bool semi_sharp = false;
  bool irregular_faces = false; // a face of another size than the scheme's regular one
};

// The corner at source(o), o a dart of the face, in a scheme whose regular
// faces have `face_size` sides (4: Catmull–Clark, 3: Loop).
template <class P>
Corner analyse_corner(const Level_mesh<P>& L, Dart o, const Limit_options& opt, unsigned face_size = 4)
{
  const Mobius_mesh<P>& m = L.mesh;
  Corner c;
  const Vertex_index v = m.source(o);
  // One turn round the vertex from o (forward: o -> opposite(prev(o)))
  // counts faces and sharp edges; a border stops it, and the walk back
  // from o covers the rest.
  bool border = false;
  const bool all_regular = L.face_size == face_size;
  auto count_edge = [&](Dart e) {
    const float s = L.edge_sharpness(e);
    c.infinite_edges += Crease::is_infinite(s) ? 1 : 0;
    c.semi_sharp |= Crease::is_semi_sharp(s);
  };
  {
    Dart e = o;
    do {
      count_edge(e);
      ++c.all_faces;
      c.irregular_faces |= !all_regular && m.degree(m.face(e)) != face_size;
      const Dart n = m.opposite(m.prev(e));
      if (m.is_border(n)) {
        count_edge(n);
        border = true;
        break;
      }
      e = n;
    } while (e != o);
    if (border) {
      Dart b = o;
      while (!m.is_border(m.opposite(b))) {
        b = m.next(m.opposite(b));
        ++c.all_faces;
        c.irregular_faces |= !all_regular && m.degree(m.face(b)) != face_size;
        count_edge(b);
      }
    }
  }
  const float vs = L.vertex_sharpness(v);
  c.semi_sharp |= Crease::is_semi_sharp(vs);
  const bool vertex_infinite = Crease::is_infinite(vs) ||
                               (border && c.all_faces == 1 && opt.boundary == Boundary_interpolation::edge_and_corner);
  const bool spans = c.infinite_edges >= 2; // a dart keeps its whole ring
  auto breaks = [&](Dart e) { return spans && Crease::is_infinite(L.edge_sharpness(e)); };
  Dart start = o;
  if (spans)
    while (!breaks(start)) {
      start = m.next(m.opposite(start));
      ++c.face_in_ring;
    }
  Dart e = start;
  do {
    c.ring.push_back(m.target(e));
    if (face_size == 4)
      c.ring.push_back(m.target(m.next(e)));
    ++c.faces;
    e = m.opposite(m.prev(e));
    if (breaks(e)) {
      c.ring.push_back(m.target(e));
      break;
    }
  } while (e != start);
  c.boundary = spans;
  if (spans)
    c.sharp = vertex_infinite || c.infinite_edges > 2;
  else
    c.sharp = vertex_infinite;
  return c;
}

// OpenSubdiv's regular corner (semi-sharpness aside: a leaf at the last
// level is regular whatever sharpness is left): 4 quads or 6 triangles
// inside, 2 quads or 3 triangles along a border or an infinitely sharp
// crease, one face at a sharp corner.
inline bool regular_corner(const Corner& c, unsigned face_size = 4)
{
  if (c.irregular_faces)
    return false;
  if (c.infinite_edges == 0)
    return !c.sharp && c.faces == (face_size == 4 ? 4u : 6u);
  if (c.infinite_edges == 1)
    return false;
  return c.sharp ? c.faces == 1 : c.faces == (face_size == 4 ? 2u : 3u);
}

// What Far's feature-adaptive selection reads of a face's corners, for
// quads and Loop triangles alike.
struct Face_features
{
  bool regular = true, semi_sharp = false, sharp_irregular = false;

  void add(const Corner& c, unsigned face_size)
  {
    const bool r = regular_corner(c, face_size);
    regular &= r;
    semi_sharp |= c.semi_sharp;
    sharp_irregular |= c.sharp && !r;
  }

  // Every feature refines up to the smooth level, semi-sharp ones and
  // irregular sharp corners up to the sharp level.
  bool refines(const Limit_options& opt, unsigned level) const
  {
    return (level < opt.level_smooth && (!regular || semi_sharp)) ||
           (level < std::max(opt.level_sharp, opt.level_smooth) && (semi_sharp || sharp_irregular));
  }
};

// The four corners of the quad of frame d (d runs from corner 0 to corner 1).
template <class P>
std::array<Dart, 4> quad_darts(const Mobius_mesh<P>& m, Dart d)
{
  return {d, m.next(d), m.next(m.next(d)), m.prev(d)};
}

template <class FT, class P>
Coordinates<FT> coordinates(const Mobius_mesh<P>& m, Vertex_index v)
{
  const P& p = m.point(v);
  return {FT(p.x()), FT(p.y()), FT(p.z())};
}

// The 16 points of the B-spline patch of a regular quad, point (i, j) at
// 4 j + i, the face's corners at (1, 1), (2, 1), (2, 2), (1, 2); beyond an
// infinitely sharp edge or a border the row is extrapolated (2 P - Q), as
// OpenSubdiv's boundary weights do.
template <class FT, class P>
void bspline_points(const Level_mesh<P>& L, Dart d, std::array<Coordinates<FT>, 20>& out)
{
  const Mobius_mesh<P>& m = L.mesh;
  const auto dk = quad_darts(m, d);
  bool known[16] = {};
  auto set = [&](int i, int j, Vertex_index v) {
    out[4 * j + i] = coordinates<FT>(m, v);
    known[4 * j + i] = true;
  };
  static const int corner_ij[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  // Per corner k: the point beyond it along edge k, the diagonal one, and
  // the one beyond it along edge k - 1.
  static const int along[4][2] = {{1, 0}, {3, 1}, {2, 3}, {0, 2}};
  static const int diagonal[4][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  static const int behind[4][2] = {{0, 1}, {2, 0}, {3, 2}, {1, 3}};
  bool boundary[4];
  for (int k = 0; k < 4; ++k)
    boundary[k] = Crease::is_infinite(L.edge_sharpness(dk[k]));
  for (int k = 0; k < 4; ++k) {
    set(corner_ij[k][0], corner_ij[k][1], m.source(dk[k]));
    const int prev = (k + 3) % 4;
    if (!boundary[k]) { // the face across edge k: c_k -> a_k -> b_k -> c_k+1
      const Dart a = m.next(m.opposite(dk[k]));
      set(along[k][0], along[k][1], m.target(a));
      set(behind[(k + 1) % 4][0], behind[(k + 1) % 4][1], m.target(m.next(a)));
    }
    if (!boundary[k] && !boundary[prev]) {
      const Dart g = m.opposite(m.prev(m.opposite(dk[prev]))); // c_k -> b_prev in the diagonal face
      set(diagonal[k][0], diagonal[k][1], m.target(m.next(g)));
    }
  }
  auto at = [&](int i, int j) -> Coordinates<FT>& { return out[4 * j + i]; };
  auto extrapolate = [&](int i, int j, int i1, int j1, int i2, int j2) {
    for (int c = 0; c < 3; ++c)
      at(i, j)[c] = FT(2) * at(i1, j1)[c] - at(i2, j2)[c];
    known[4 * j + i] = true;
  };
  for (int x = 1; x <= 2; ++x) { // edges first, then the corners of the grid
    if (boundary[0]) extrapolate(x, 0, x, 1, x, 2);
    if (boundary[2]) extrapolate(x, 3, x, 2, x, 1);
    if (boundary[3]) extrapolate(0, x, 1, x, 2, x);
    if (boundary[1]) extrapolate(3, x, 2, x, 1, x);
  }
  for (int k = 0; k < 4; ++k) {
    const int i = diagonal[k][0], j = diagonal[k][1];
    if (known[4 * j + i])
      continue;
    // OpenSubdiv folds the rows beyond edges 0 and 2 first: a corner of the
    // grid beyond one of them comes from its column.
    const int si = i == 0 ? 1 : -1, sj = j == 0 ? 1 : -1;
    if (boundary[j == 0 ? 0 : 2])
      extrapolate(i, j, i, j + sj, i, j + 2 * sj);
    else
      extrapolate(i, j, i + si, j, i + 2 * si, j);
  }
}


// A point of a patch as weights on vertices of its level.
using Row = std::vector<std::pair<Vertex_index, double>>;

inline void add_row(Row& r, const Row& x, double w)
{
  for (const auto& [v, xw] : x)
    r.push_back({v, w * xw});
}

// Catmull–Clark's scale of the limit tangents at an interior vertex of
// valence n (OpenSubdiv's table up to 29, its formula beyond).
inline double tangent_scale(unsigned n)
{
  static const double table[30] = {
    0.0, 0.0, 0.0, 8.1281572906372312e-01, 0.5, 3.6364406329142801e-01, 2.8751379706077085e-01,
    2.3868786685851678e-01, 2.0454364190756097e-01, 1.7922903958061159e-01, 1.5965737079986253e-01,
    1.4404233443011302e-01, 1.3127568415883017e-01, 1.2063172212675841e-01, 1.1161437506676930e-01,
    1.0387245516114274e-01, 9.7150019090724835e-02, 9.1255917505950648e-02, 8.6044378511602668e-02,
    8.1402211336798411e-02, 7.7240129516184072e-02, 7.3486719751997026e-02, 7.0084157479797987e-02,
    6.6985104030725440e-02, 6.4150420569810074e-02, 6.1547457638637268e-02, 5.9148757447233989e-02,
    5.6931056818776957e-02, 5.4874512279256417e-02, 5.2962091433796134e-02};
  if (n < 30)
    return table[n];
  const double c = std::cos(2.0 * M_PI / double(n));
  return 16.0 / double(n) / ((c + 5.0) + std::sqrt((c + 9.0) * (c + 1.0)));
}

// Limit point and the two edge points of an interior irregular corner
// (weights on the corner, then its ring), from the eigen-analysis that
// OpenSubdiv's Gregory patches use.
inline void interior_corner_weights(unsigned n, unsigned face_in_ring, std::vector<double>& p, std::vector<double>& ep,
                                    std::vector<double>& em)
{
  const unsigned width = 1 + 2 * n;
  p.assign(width, 0.0);
  std::vector<double> tangent(width, 0.0);
  const double coefficient = 1.0 / (double(n) * (double(n) + 5.0));
  const double tangent_coefficient = tangent_scale(n) * 0.5 / (double(n) + 5.0);
  p[0] = double(n) / (double(n) + 5.0);
  for (unsigned i = 0; i < n; ++i) {
    p[1 + 2 * i] = coefficient * 4.0;
    p[2 + 2 * i] = coefficient;
    const unsigned before = (i + n - 1) % n, after = (i + 1) % n;
    const double c = tangent_coefficient * std::cos(2.0 * M_PI / double(n) * double(i));
    tangent[1 + 2 * before] += c * 2.0;
    tangent[2 + 2 * before] += c;
    tangent[1 + 2 * i] += c * 4.0;
    tangent[2 + 2 * i] += c;
    tangent[1 + 2 * after] += c * 2.0;
  }
  // The tangent along ring edge j is the one along edge 0 turned by j.
  const unsigned ep_offset = 2 * ((n - face_in_ring) % n), em_offset = 2 * ((2 * n - face_in_ring - 1) % n);
  ep.assign(width, p[0]);
  em.assign(width, p[0]);
  for (unsigned i = 1; i < width; ++i) {
    unsigned a = i + ep_offset, b = i + em_offset;
    if (a >= width)
      a -= width - 1;
    if (b >= width)
      b -= width - 1;
    ep[i] = p[i] + tangent[a];
    em[i] = p[i] + tangent[b];
  }
}

// The same at a border (or infinitely sharp crease) vertex of `faces` > 1
// faces in its span: the crease limit point, and edge points from the
// border tangent and the interior tangent of Biermann et al.
inline void boundary_corner_weights(unsigned faces, unsigned face_in_ring, std::vector<double>& p,
                                    std::vector<double>& ep, std::vector<double>& em)
{
  const unsigned width = 2 * faces + 2, last = width - 1;
  const double angle = M_PI / double(faces);
  p.assign(width, 0.0);
  p[0] = 4.0 / 6.0;
  p[1] = p[last] = 1.0 / 6.0;
  std::vector<double> tangent(width, 0.0);
  {
    const double k = double(faces), c = std::cos(angle), s = std::sin(angle), third = 1.0 / 3.0;
    const double d = 1.0 / (3.0 * k + c);
    const double alpha0 = -((1.0 + 2.0 * c) * std::sqrt(1.0 + c)) * d / std::sqrt(1.0 - c);
    tangent[0] = -4.0 * s * d * third;
    tangent[1] = tangent[last] = alpha0 * third;
    tangent[2] = s * d * third;
    for (unsigned i = 1; i < faces; ++i) {
      const double si = std::sin(angle * double(i)), si1 = std::sin(angle * double(i + 1));
      tangent[1 + 2 * i] = 4.0 * si * d * third;
      tangent[2 + 2 * i] = (si + si1) * d * third;
    }
  }
  auto edge_point = [&](std::vector<double>& e, unsigned ring_edge) {
    const double a = angle * double(ring_edge), c = std::cos(a), s = std::sin(a);
    e.assign(width, 0.0);
    for (unsigned i = 0; i < width; ++i)
      e[i] = tangent[i] * s;
    e[0] += p[0];
    e[1] += p[1] + 1.0 / 6.0 * c;
    e[last] += p[last] - 1.0 / 6.0 * c;
  };
  if (face_in_ring == 0) {
    ep.assign(width, 0.0);
    ep[0] = 2.0 / 3.0;
    ep[1] = 1.0 / 3.0;
  } else {
    edge_point(ep, face_in_ring);
  }
  if (face_in_ring == faces - 1) {
    em.assign(width, 0.0);
    em[0] = 2.0 / 3.0;
    em[last] = 1.0 / 3.0;
  } else {
    edge_point(em, (face_in_ring + 1) % (faces + 1));
  }
}

// What a corner's face points depend on.
struct Gregory_corner
{
  bool regular = false, ep_on_boundary = false, em_on_boundary = false, fp_regular = false, fm_regular = false,
       fp_copied = false, fm_copied = false;
  unsigned valence = 0;
  double cosine = 0;
};

// The face points: regular ones from the face's corners; the others from
// the corner's limit point and edge points, the far corner's edge point and
// the points of the two faces beside the edge, weighted by the cosines of
// the two corners' face angles.
inline void gregory_face_rows(const Vertex_index cv[4], const std::array<Corner, 4>& corners,
                              const Gregory_corner info[4], std::array<Row, 20>& rows)
{
  for (int k = 0; k < 4; ++k) {
    const Gregory_corner& i = info[k];
    const int next = (k + 1) % 4, opposite = (k + 2) % 4, prev = (k + 3) % 4;
    const Row regular = {{cv[k], 4.0 / 9.0}, {cv[prev], 2.0 / 9.0}, {cv[next], 2.0 / 9.0}, {cv[opposite], 1.0 / 9.0}};
    auto irregular = [&](unsigned ring_edge, int far, const Row& e_near, const Row& e_far, double sign) {
      const double c_near = i.cosine, c_far = info[far].cosine;
      Row f;
      add_row(f, rows[5 * k], c_far / 3.0);
      add_row(f, e_near, (3.0 - 2.0 * c_near - c_far) / 3.0);
      add_row(f, e_far, 2.0 * c_near / 3.0);
      const Corner::Ring& r = corners[k].ring;
      const unsigned n = i.valence, before = (ring_edge + n - 1) % n, after = (ring_edge + 1) % n;
      f.push_back({r[2 * before], -sign / 9.0});
      f.push_back({r[2 * before + 1], -sign / 18.0});
      f.push_back({r[2 * ring_edge + 1], sign / 18.0});
      f.push_back({r[2 * after], sign / 9.0});
      return f;
    };
    Row &fp = rows[5 * k + 3], &fm = rows[5 * k + 4];
    if (i.fp_regular)
      fp = regular;
    if (i.fm_regular)
      fm = regular;
    if (!i.fp_regular && !i.fp_copied)
      fp = irregular(corners[k].face_in_ring, next, rows[5 * k + 1], rows[5 * next + 2], 1.0);
    if (!i.fm_regular && !i.fm_copied)
      fm = irregular((corners[k].face_in_ring + 1) % i.valence, prev, rows[5 * k + 2], rows[5 * prev + 1], -1.0);
    if (i.fp_copied)
      fp = fm;
    if (i.fm_copied)
      fm = fp;
  }
}

// The 20 points of the Gregory patch of the quad of frame d, as rows of
// weights, following OpenSubdiv's GregoryConverter (the labelling of Loop,
// Schaefer, Ni and Castaño): per corner the limit point P, edge points Ep
// (along edge k) and Em (along edge k - 1), face points Fp and Fm.
template <class P>
std::array<Row, 20> gregory_rows(const Mobius_mesh<P>& m, Dart d, const std::array<Corner, 4>& corners)
{
  const auto dk = quad_darts(m, d);
  Vertex_index cv[4];
  for (int k = 0; k < 4; ++k)
    cv[k] = m.source(dk[k]);
  Gregory_corner info[4];
  for (int k = 0; k < 4; ++k) {
    const Corner& c = corners[k];
    Gregory_corner& i = info[k];
    i.regular = (c.faces << (c.boundary ? 1 : 0)) == 4 && !c.sharp;
    i.valence = c.faces + (c.boundary ? 1 : 0);
    i.cosine = i.regular ? 0.0 : std::cos((c.boundary ? M_PI : 2.0 * M_PI) / double(c.faces));
  }
  for (int k = 0; k < 4; ++k) {
    const Corner& c = corners[k];
    Gregory_corner& i = info[k];
    i.fp_regular = i.regular && info[(k + 1) % 4].regular;
    i.fm_regular = i.regular && info[(k + 3) % 4].regular;
    if (!c.boundary)
      continue;
    i.ep_on_boundary = c.face_in_ring == 0;
    i.em_on_boundary = c.face_in_ring == c.faces - 1;
    if (c.faces > 1) { // a face point beside a border edge is its partner
      if (i.ep_on_boundary) {
        i.fp_regular = i.fm_regular;
        i.fp_copied = !i.fp_regular;
      }
      if (i.em_on_boundary) {
        i.fm_regular = i.fp_regular;
        i.fm_copied = !i.fm_regular;
      }
    } else {
      i.fp_regular = i.fm_regular = true;
    }
  }
  std::array<Row, 20> rows;
  for (int k = 0; k < 4; ++k) {
    const Corner& c = corners[k];
    const Gregory_corner& i = info[k];
    const Corner::Ring& r = c.ring;
    Row &p = rows[5 * k], &ep = rows[5 * k + 1], &em = rows[5 * k + 2];
    const Vertex_index v = cv[k], next = cv[(k + 1) % 4], prev = cv[(k + 3) % 4];
    if (i.regular && !c.boundary) {
      p = {{v, 4.0 / 9.0}, {r[0], 1.0 / 9.0}, {r[2], 1.0 / 9.0}, {r[4], 1.0 / 9.0}, {r[6], 1.0 / 9.0},
           {r[1], 1.0 / 36.0}, {r[3], 1.0 / 36.0}, {r[5], 1.0 / 36.0}, {r[7], 1.0 / 36.0}};
      const unsigned e_p = 2 * c.face_in_ring, e_m = 2 * ((c.face_in_ring + 1) & 3),
                     o_p = 2 * ((c.face_in_ring + 2) & 3), o_m = 2 * ((c.face_in_ring + 3) & 3);
      ep = {{v, 4.0 / 9.0}, {r[e_p], 2.0 / 9.0}, {r[e_m], 1.0 / 9.0}, {r[o_m], 1.0 / 9.0}, {r[e_p + 1], 1.0 / 18.0},
            {r[o_m + 1], 1.0 / 18.0}};
      em = {{v, 4.0 / 9.0}, {r[e_m], 2.0 / 9.0}, {r[e_p], 1.0 / 9.0}, {r[o_p], 1.0 / 9.0}, {r[e_p + 1], 1.0 / 18.0},
            {r[e_m + 1], 1.0 / 18.0}};
    } else if (i.regular) { // a regular border corner: two faces
      p = {{v, 2.0 / 3.0}, {r[0], 1.0 / 6.0}, {r[4], 1.0 / 6.0}};
      Row& on_border = i.ep_on_boundary ? ep : em;
      Row& inside = i.ep_on_boundary ? em : ep;
      on_border = {{v, 2.0 / 3.0}, {r[i.ep_on_boundary ? 0 : 4], 1.0 / 3.0}};
      inside = {{v, 4.0 / 9.0}, {r[2], 2.0 / 9.0}, {r[0], 1.0 / 9.0}, {r[4], 1.0 / 9.0}, {r[1], 1.0 / 18.0},
                {r[3], 1.0 / 18.0}};
    } else if (c.sharp) {
      p = {{v, 1.0}};
      ep = {{v, 2.0 / 3.0}, {next, 1.0 / 3.0}};
      em = {{v, 2.0 / 3.0}, {prev, 1.0 / 3.0}};
    } else if (!c.boundary || c.faces > 1) {
      std::vector<double> wp, wep, wem;
      if (c.boundary)
        boundary_corner_weights(c.faces, c.face_in_ring, wp, wep, wem);
      else
        interior_corner_weights(c.faces, c.face_in_ring, wp, wep, wem);
      p = {{v, wp[0]}};
      ep = {{v, wep[0]}};
      em = {{v, wem[0]}};
      for (std::size_t j = 1; j < wp.size(); ++j) {
        p.push_back({r[j - 1], wp[j]});
        ep.push_back({r[j - 1], wep[j]});
        em.push_back({r[j - 1], wem[j]});
      }
    } else { // a smooth corner of one face
      p = {{v, 4.0 / 6.0}, {next, 1.0 / 6.0}, {prev, 1.0 / 6.0}};
      ep = {{v, 2.0 / 3.0}, {next, 1.0 / 3.0}};
      em = {{v, 2.0 / 3.0}, {prev, 1.0 / 3.0}};
    }
  }
  gregory_face_rows(cv, corners, info, rows);
  return rows;
}


// Whether a copy of a face's neighbourhood must reach two rings deep.
// Under Chaikin's rule the sharpness of a child edge at a vertex averages
// the vertex's semi-sharp edges, and the point of an edge at a corner takes
// its rule from both of its children: the one at the far end needs the
// whole ring of the corner's neighbour. Uniform decay needs no ring.
template <class P>
bool needs_two_rings(const Level_mesh<P>& L, const Limit_options& opt)
{
  return opt.crease == Crease_method::chaikin && L.semi_sharp_edges;
}

// Copies the faces around the corners of face(d) (with their sharpness)
// into `out` and returns the dart of `out` that stands for d; with
// `two_rings`, the faces around the vertices of those faces too. Faces keep
// their own orientation, so Möbius edges stay Möbius. A vertex that two
// separate fans of the copy share (a small or wrapped mesh) is split for
// the face that cannot join it: only the corners' rings are kept whole
// (with two rings, Chaikin's rule at a split neighbour of a corner then sees
// part of its ring, as with one ring everywhere).
template <class P>
Dart copy_neighbourhood(const Level_mesh<P>& L, Dart d, Level_mesh<P>& out, bool two_rings = false)
{
  const Mobius_mesh<P>& m = L.mesh;
  std::vector<Face_index> faces;
  auto add = [&](Face_index g) {
    if (std::find(faces.begin(), faces.end(), g) == faces.end())
      faces.push_back(g);
  };
  auto add_around = [&](Dart c) { // the faces around target(c)
    for (Dart a : halfedges_around_target(c, m))
      if (!m.is_border(a))
        add(m.face(a));
  };
  std::vector<Vertex_index> corners;
  for (Dart c : halfedges_around_face(d, m)) {
    corners.push_back(m.target(c));
    add_around(c);
  }
  if (two_rings)
    for (std::size_t i = 0, n = faces.size(); i < n; ++i)
      for (Dart c : halfedges_around_face(m.halfedge(faces[i]), m))
        add_around(c);
  out.mesh.clear();
  std::vector<std::pair<Vertex_index, Vertex_index>> map; // (level vertex, copy)
  auto copy_of = [&](Vertex_index v, bool fresh) {
    if (!fresh)
      for (const auto& [a, b] : map)
        if (a == v)
          return b;
    const Vertex_index c = out.mesh.add_vertex(m.point(v));
    map.push_back({v, c});
    return c;
  };
  // A plain map and a flag, not an optional: GCC 12 warns (falsely) that the
  // optional's map may be read uninitialised.
  const bool sharp = bool(L.es);
  typename Mobius_mesh<P>::template Property_map<Edge_index, float> es_map;
  if (sharp)
    es_map = out.mesh.template add_property_map<Edge_index, float>(edge_sharpness_name, 0.0f).first;
  auto* es = sharp ? &es_map : nullptr;
  Face_index copy_of_face;
  std::vector<Vertex_index> source, copy;
  for (Face_index g : faces) {
    source.clear();
    for (Vertex_index v : vertices_around_face(m.halfedge(g), m))
      source.push_back(v);
    Face_index h;
    for (bool fresh : {false, true}) {
      copy.clear();
      for (Vertex_index v : source)
        copy.push_back(copy_of(v, fresh && std::find(corners.begin(), corners.end(), v) == corners.end()));
      h = out.mesh.add_face(copy);
      if (h != out.mesh.null_face())
        break;
    }
    if (h == out.mesh.null_face())
      throw Parameter_error("Limit_surface: the faces around face f" + std::to_string(m.face(d).idx()) +
                            " do not form a manifold neighbourhood");
    if (g == m.face(d))
      copy_of_face = h;
    if (es) {
      std::size_t i = 0;
      for (Dart s : halfedges_around_face(m.halfedge(g), m)) { // s ends at source[i]
        const Dart c = dart_between(out.mesh, h, copy[(i + source.size() - 1) % source.size()], copy[i]);
        (*es)[out.mesh.edge(c)] = (*L.es)[m.edge(s)];
        ++i;
      }
    }
  }
  // An edge the copy cuts is a border of the copy: infinitely sharp, as in
  // the local mesh of Bfr, where it counts for no semi-sharp average.
  if (es)
    for (Edge_index e : out.mesh.edges())
      if (out.mesh.is_border(e))
        (*es)[e] = infinitely_sharp;
  if (L.vs) {
    auto vs = out.mesh.template add_property_map<Vertex_index, float>(vertex_sharpness_name, 0.0f).first;
    for (const auto& [a, b] : map)
      vs[b] = (*L.vs)[a];
  }
  out.bind();
  Vertex_index a, b;
  for (const auto& [x, y] : map) {
    if (x == m.source(d) && a == Vertex_index())
      a = y;
    if (x == m.target(d) && b == Vertex_index())
      b = y;
  }
  return dart_between(out.mesh, copy_of_face, a, b);
}

// The dart from a to b in the child faces of a parent face (those around
// its point `face_point`), walked the way the parent's frame is walked
// (`flipped`): children keep their parent's orientation, and the edges
// between two children are walked one way in each.
template <class P>
Dart child_frame(const Mobius_mesh<P>& m, Vertex_index face_point, Vertex_index a, Vertex_index b, bool flipped)
{
  for (Dart x : halfedges_around_target(face_point, m)) {
    if (m.is_border(x))
      continue;
    for (Dart y : halfedges_around_face(m.halfedge(m.face(x)), m)) {
      const Dart z = flipped ? y.flipped() : y;
      if (m.source(z) == a && m.target(z) == b)
        return z;
    }
  }
  throw Parameter_error("Limit_surface: internal error, a child face was not found");
}

// Builds the patches of the face of frame d of level mesh L, which covers
// [u0, u0 + size]² of its (sub-)face's parameters.
template <class FT, class P>
class Patch_tree_builder
{
public:
  // A face's patch lists, one per sub-face (one for a quad).
  using Sub_face_lists = boost::container::small_vector<Patch_list<FT>, 1>;

  Patch_tree_builder(const Limit_options& options, Patch_list<FT>& out) : opt_(options), out_(out) {}

  void build(const Level_mesh<P>& L, Dart d, unsigned level, double u0, double v0, double size)
  {
    const auto dk = quad_darts(L.mesh, d);
    std::array<Corner, 4> corners;
    Face_features features;
    for (int k = 0; k < 4; ++k) {
      corners[k] = analyse_corner(L, dk[k], opt_);
      features.add(corners[k], 4);
    }
    const bool regular = features.regular;
    if (!features.refines(opt_, level)) {
      Patch<FT> patch;
      patch.u0 = u0;
      patch.v0 = v0;
      patch.size = size;
      patch.type = regular ? Patch_type::bspline : Patch_type::gregory;
      if (regular) {
        bspline_points<FT>(L, d, patch.points);
      } else {
        const std::array<Row, 20> rows = gregory_rows(L.mesh, d, corners);
        for (int k = 0; k < 20; ++k) {
          patch.points[k] = {FT(0), FT(0), FT(0)};
          for (const auto& [v, w] : rows[k])
            add_scaled(patch.points[k], FT(w), coordinates<FT>(L.mesh, v));
        }
      }
      out_.push_back(patch);
      return;
    }
    Level_mesh<P> child;
    std::vector<Vertex_index> vp, ep;
    Vertex_index fp;
    const bool flip = refine_around(L, d, child, vp, ep, fp);
    const double h = size / 2;
    build(child, child_frame(child.mesh, fp, vp[0], ep[0], flip), level + 1, u0, v0, h);
    build(child, child_frame(child.mesh, fp, ep[0], vp[1], flip), level + 1, u0 + h, v0, h);
    build(child, child_frame(child.mesh, fp, fp, ep[1], flip), level + 1, u0 + h, v0 + h, h);
    build(child, child_frame(child.mesh, fp, ep[3], fp, flip), level + 1, u0, v0 + h, h);
  }

  // Copies the neighbourhood of face(d) and subdivides it once; gives the
  // child vertices of the face's corners and edges (from d on) and of the
  // face, and whether the copy of d runs against its face.
  bool refine_around(const Level_mesh<P>& L, Dart d, Level_mesh<P>& child, std::vector<Vertex_index>& vp,
                     std::vector<Vertex_index>& ep, Vertex_index& fp) const
  {
    const Dart c = copy_neighbourhood(L, d, child, needs_two_rings(L, opt_));
    const auto nv = child.mesh.number_of_vertices(), ne = child.mesh.number_of_edges();
    vp.clear();
    ep.clear();
    for (Dart x : halfedges_around_face(child.mesh.prev(c), child.mesh)) { // x ends at corner k
      vp.push_back(child.mesh.target(x));
      ep.push_back(Vertex_index(nv + child.mesh.edge(child.mesh.next(x)).idx()));
    }
    fp = Vertex_index(nv + ne + child.mesh.face(c).idx());
    catmull_clark(child.mesh, refinement_parameters(opt_).triangle_subdivision(opt_.triangles));
    child.bind();
    return c.is_flipped();
  }

  // A face that is not a quad: its n quads, each a sub-face of Bfr's
  // parameterisation, built into `lists[k]`.
  void build_sub_faces(const Level_mesh<P>& L, Dart d, Sub_face_lists& lists)
  {
    Level_mesh<P> child;
    std::vector<Vertex_index> vp, ep;
    Vertex_index fp;
    const bool flip = refine_around(L, d, child, vp, ep, fp);
    lists.assign(vp.size(), {});
    for (std::size_t k = 0; k < vp.size(); ++k) {
      Patch_tree_builder sub(opt_, lists[k]);
      sub.build(child, child_frame(child.mesh, fp, vp[k], ep[k], flip), 1, 0.0, 0.0, 1.0);
    }
  }

private:
  const Limit_options& opt_;
  Patch_list<FT>& out_;
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_LIMIT_SURFACE_INTERNAL_PATCH_BUILDER_H
