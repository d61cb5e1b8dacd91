// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The attribute quadrics of decimation: Garland and Heckbert's quadrics
// ("Simplifying surfaces with color and texture using quadric error
// metrics", 1998) for the values of the corner channels, in Hoppe's form
// ("New quadric metric for simplifying meshes with appearance attributes",
// 1999), where the error of a value is its distance to the value that each
// face of the input would give at the point, not a distance in a space of
// points and values together.

#ifndef CGAL_EXT_DECIMATION_INTERNAL_ATTRIBUTE_QUADRICS_H
#define CGAL_EXT_DECIMATION_INTERNAL_ATTRIBUTE_QUADRICS_H

#include <CGAL_ext/Decimation/internal/Quadric.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/internal/Collapse_checks.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_edits.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL_ext {
namespace internal {

// Each triangle of the input whose corners have values of a channel gives
// them as an affine field over its plane, s(x) = G x + d (G's rows in the
// plane). A vertex sums, over the triangles merged into it, their area a
// times the squared distance of a value s to their fields at x:
//   sum_f a_f |s - G_f x - d_f|^2
//     = A s.s - 2 s.(Gs x + ds) + x^T H x + 2 h.x + k,
// with A = sum a_f, Gs = sum a_f G_f, ds = sum a_f d_f, H = sum a_f G_f^T G_f,
// h = sum a_f G_f^T d_f, k = sum a_f |d_f|^2: terms that add up when
// vertices merge. At a point x the best value is (Gs x + ds) / A, the mean
// of the fields there, and what is left is a quadric in x alone (H - Gs^T Gs
// / A, ...): the spread of the fields at x, zero where they agree (a channel
// affine over the region). Added to the plane quadrics, it steers both the
// order of the collapses and their points away from where the values bend.
//
// Each channel is weighed so that a value off by a share of the channel's
// range costs as a point off by the same share of the mesh's bounding box,
// times the caller's weight (0: none of this, the values follow the points).
// The seam vertices are left out: their faces hold several values, and they
// never move nor take a new one (Corner_channel_edits.h).
template <class P>
class Attribute_quadrics
{
public:
  // `weight` scales every channel's (decimate()'s corner_value_weight).
  Attribute_quadrics(const Mobius_mesh<P>& mesh, const Corner_channel_edits<P>& corners, double weight)
    : m_(mesh), c_(corners)
  {
    lay_out(weight);
    if (stride_ == 0)
      return;
    terms_.assign(mesh.num_vertices() * stride_, 0.0);
    Face_values scratch; // reused from face to face: no allocation per face
    for (Face_index f : mesh.faces())
      add_face(f, scratch);
  }

  bool empty() const { return stride_ == 0; }

  // The quadric in the point that the values' error adds to a collapse
  // merging the ends given (those off the seams: none, one or both). `a`
  // and `b` are the darts (of a face along the collapsed edge) whose
  // corners' values the merged corners take or make: a channel is taken at
  // a value the collapse keeps (the same at both, or the one of the two that
  // has one; pass one dart twice for an end whose values are kept), else at
  // its best value (none given: at its best everywhere).
  Quadric residual(std::initializer_list<Vertex_index> ends, Dart a = Dart(), Dart b = Dart()) const
  {
    Quadric q;
    if (empty())
      return q;
    sum_terms(ends);
    for (const Channel& c : channels_) {
      const double* kept = a.is_valid() ? kept_value(c, a, b) : nullptr;
      q += kept ? residual_at(c, &sum_[c.offset], kept) : residual_of(c, &sum_[c.offset]);
    }
    return q;
  }

  // By channel, the value (as doubles) that the merged vertex of `ends`
  // takes at `x`: empty for a channel the ends' faces give no value.
  std::vector<std::vector<double>> fitted(std::initializer_list<Vertex_index> ends, const Point_d& x) const
  {
    std::vector<std::vector<double>> values(c_.number_of_channels());
    if (empty())
      return values;
    sum_terms(ends);
    for (const Channel& c : channels_) {
      const double* t = &sum_[c.offset];
      if (!(t[0] > 0))
        continue;
      std::vector<double>& s = values[c.index];
      s.resize(c.m);
      // Kept within the channel's bounding box: the fields meet at the
      // point only approximately, and extrapolated they could run far.
      for (std::size_t j = 0; j < c.m; ++j) {
        const double* g = t + 11 + 3 * j;
        s[j] = std::clamp((g[0] * x[0] + g[1] * x[1] + g[2] * x[2] + t[11 + 3 * c.m + j]) / t[0], c.lo[j], c.hi[j]);
      }
    }
    return values;
  }

  // The kept vertex of a collapse takes the removed one's terms too.
  void merge(Vertex_index removed, Vertex_index kept)
  {
    if (empty())
      return;
    double* to = &terms_[kept.idx() * stride_];
    const double* from = &terms_[removed.idx() * stride_];
    for (std::size_t i = 0; i < stride_; ++i)
      to[i] += from[i];
  }

private:
  // A channel read as m doubles, its terms at `offset` of a vertex's
  // (A, H's upper triangle xx xy xz yy yz zz, h, k, Gs by rows, ds: 11 + 4 m).
  struct Channel
  {
    std::size_t index, m, offset;
    double weight;
    std::vector<double> lo, hi; // the bounding box of its values
  };

  void lay_out(double weight)
  {
    if (c_.number_of_channels() == 0 || !(weight > 0))
      return; // weighed 0: no quadric, and the values are interpolated along the edges
    Bbox_d box;
    for (Vertex_index v : m_.vertices())
      box.add(to_point_d(m_.point(v)).data(), 3);
    const double size = box.diagonal();
    for (std::size_t k = 0; k < c_.number_of_channels(); ++k) {
      const std::size_t m = c_.value_size(k);
      if (m == 0)
        continue;
      Bbox_d values;
      std::vector<double> x(m);
      for (Face_index f : m_.faces())
        for (Dart h : CGAL_ext::halfedges_around_face(m_.halfedge(f), m_))
          if (c_.read_corner(k, h, x.data()) && all_finite(x))
            values.add(x.data(), m);
      const double range = values.diagonal();
      if (!(range > 0) || !(size > 0) || !std::isfinite(range))
        continue; // one value (or none, or values beyond double's range): nothing to weigh
      const double w = weight * (size / range) * (size / range);
      if (!std::isfinite(w))
        continue;
      channels_.push_back({k, m, stride_, w, values.lo, values.hi});
      stride_ += 11 + 4 * m;
      value_.resize((std::max)(value_.size(), m));
      other_.resize(value_.size());
    }
    sum_.resize(stride_);
  }

  // A face's three corner values in one channel, and its terms.
  struct Face_values
  {
    std::vector<double> s0, s1, s2, terms;
  };

  // The field of triangle f in each channel whose three corners have values,
  // weighted by its area, added to its corners' vertices.
  void add_face(Face_index f, Face_values& scratch)
  {
    const Dart d0 = m_.halfedge(f), d1 = m_.next(d0), d2 = m_.next(d1);
    const Point_d p0 = to_point_d(m_.point(m_.target(d0)));
    const Point_d e1 = minus_d(to_point_d(m_.point(m_.target(d1))), p0);
    const Point_d e2 = minus_d(to_point_d(m_.point(m_.target(d2))), p0);
    const double a11 = dot_d(e1, e1), a12 = dot_d(e1, e2), a22 = dot_d(e2, e2);
    const double det = a11 * a22 - a12 * a12; // twice the area, squared
    const double longest = (std::max)({a11, a22, a11 + a22 - 2 * a12}); // squared
    if (!(det > 1e-8 * longest * longest))
      return; // a sliver (height under 1e-4 of its longest side): its field's gradient would be a rounding error
    const double area = 0.5 * std::sqrt(det);
    auto& [s0, s1, s2, terms] = scratch;
    for (const Channel& c : channels_) {
      s0.resize(c.m);
      s1.resize(c.m);
      s2.resize(c.m);
      if (!c_.read_corner(c.index, d0, s0.data()) || !c_.read_corner(c.index, d1, s1.data()) ||
          !c_.read_corner(c.index, d2, s2.data()) || !all_finite(s0) || !all_finite(s1) || !all_finite(s2))
        continue; // no field (a NaN would poison every cost it reached)
      terms.assign(11 + 4 * c.m, 0.0);
      terms[0] = area;
      for (std::size_t j = 0; j < c.m; ++j) {
        // The gradient g in the plane with g.e1 = s1 - s0 and g.e2 = s2 - s0.
        const double u1 = s1[j] - s0[j], u2 = s2[j] - s0[j];
        const double alpha = (a22 * u1 - a12 * u2) / det, beta = (a11 * u2 - a12 * u1) / det;
        const Point_d g{alpha * e1[0] + beta * e2[0], alpha * e1[1] + beta * e2[1], alpha * e1[2] + beta * e2[2]};
        const double dj = s0[j] - dot_d(g, p0);
        add_outer(&terms[1], g, area);
        for (int i = 0; i < 3; ++i) {
          terms[7 + i] += area * g[i] * dj;
          terms[11 + 3 * j + i] = area * g[i];
        }
        terms[10] += area * dj * dj;
        terms[11 + 3 * c.m + j] = area * dj;
      }
      for (Dart h : {d0, d1, d2}) {
        double* to = &terms_[m_.target(h).idx() * stride_ + c.offset];
        for (std::size_t i = 0; i < terms.size(); ++i)
          to[i] += terms[i];
      }
    }
  }

  static bool all_finite(const std::vector<double>& x)
  {
    return std::all_of(x.begin(), x.end(), [](double y) { return std::isfinite(y); });
  }

  // The value of channel c that a collapse keeps, given the corners of its
  // two ends along the edge (merged() in Corner_channel_edits.h): theirs if
  // they agree, the one there is if one has none; null if it makes one.
  const double* kept_value(const Channel& c, Dart a, Dart b) const
  {
    const bool at_a = c_.read_corner(c.index, a, value_.data()), at_b = c_.read_corner(c.index, b, other_.data());
    if (at_a && at_b)
      return std::equal(value_.begin(), value_.begin() + std::ptrdiff_t(c.m), other_.begin()) ? value_.data() : nullptr;
    return at_a ? value_.data() : at_b ? other_.data() : nullptr;
  }

  // The channel's terms t at the given value s0 (m doubles): the quadric
  // x^T H x + 2 (h - Gs^T s0).x + k - 2 s0.ds + A |s0|^2, weighted.
  static Quadric residual_at(const Channel& c, const double* t, const double* s0)
  {
    Quadric q;
    if (!(t[0] > 0))
      return q;
    for (int i = 0; i < 6; ++i)
      q.a[std::size_t(i)] = c.weight * t[1 + i];
    double b[3] = {t[7], t[8], t[9]}, k = t[10];
    for (std::size_t j = 0; j < c.m; ++j) {
      for (int i = 0; i < 3; ++i)
        b[i] -= t[11 + 3 * j + std::size_t(i)] * s0[j];
      k += t[0] * s0[j] * s0[j] - 2 * s0[j] * t[11 + 3 * c.m + j];
    }
    for (int i = 0; i < 3; ++i)
      q.b[std::size_t(i)] = c.weight * b[i];
    q.c = c.weight * k;
    return q;
  }

  // Adds w g g^T to the upper triangle `a` (xx xy xz yy yz zz).
  static void add_outer(double* a, const Point_d& g, double w)
  {
    a[0] += w * g[0] * g[0];
    a[1] += w * g[0] * g[1];
    a[2] += w * g[0] * g[2];
    a[3] += w * g[1] * g[1];
    a[4] += w * g[1] * g[2];
    a[5] += w * g[2] * g[2];
  }

  // The terms of `ends` summed into sum_.
  void sum_terms(std::initializer_list<Vertex_index> ends) const
  {
    std::fill(sum_.begin(), sum_.end(), 0.0);
    for (Vertex_index v : ends) {
      const double* from = &terms_[v.idx() * stride_];
      for (std::size_t i = 0; i < stride_; ++i)
        sum_[i] += from[i];
    }
  }

  // What is left of a channel's terms t at the best value: the quadric
  // x^T (H - Gs^T Gs / A) x + 2 (h - Gs^T ds / A).x + k - |ds|^2 / A, weighted.
  static Quadric residual_of(const Channel& c, const double* t)
  {
    Quadric q;
    if (!(t[0] > 0))
      return q;
    const double A = t[0];
    for (int i = 0; i < 6; ++i)
      q.a[std::size_t(i)] = t[1 + i];
    for (int i = 0; i < 3; ++i)
      q.b[std::size_t(i)] = t[7 + i];
    q.c = t[10];
    for (std::size_t j = 0; j < c.m; ++j) {
      const Point_d g{t[11 + 3 * j], t[12 + 3 * j], t[13 + 3 * j]};
      const double dj = t[11 + 3 * c.m + j];
      add_outer(q.a.data(), g, -1 / A);
      for (int i = 0; i < 3; ++i)
        q.b[std::size_t(i)] -= g[std::size_t(i)] * dj / A;
      q.c -= dj * dj / A;
    }
    for (double& x : q.a)
      x *= c.weight;
    for (double& x : q.b)
      x *= c.weight;
    q.c *= c.weight;
    return q;
  }

  // A bounding box in any dimension, for the weights.
  struct Bbox_d
  {
    std::vector<double> lo, hi;
    void add(const double* x, std::size_t n)
    {
      if (lo.empty()) {
        lo.assign(x, x + n);
        hi.assign(x, x + n);
      }
      for (std::size_t i = 0; i < n; ++i) {
        lo[i] = (std::min)(lo[i], x[i]);
        hi[i] = (std::max)(hi[i], x[i]);
      }
    }
    double diagonal() const
    {
      double s = 0;
      for (std::size_t i = 0; i < lo.size(); ++i)
        s += (hi[i] - lo[i]) * (hi[i] - lo[i]);
      return std::sqrt(s);
    }
  };

  const Mobius_mesh<P>& m_;
  const Corner_channel_edits<P>& c_;
  std::vector<Channel> channels_;
  std::size_t stride_ = 0;
  std::vector<double> terms_;       // by vertex, stride_ each
  mutable std::vector<double> sum_;   // the terms of a collapse's ends
  mutable std::vector<double> value_, other_; // the values of a collapse's two ends, read
};

} // namespace internal
} // namespace CGAL_ext

#endif // CGAL_EXT_DECIMATION_INTERNAL_ATTRIBUTE_QUADRICS_H
