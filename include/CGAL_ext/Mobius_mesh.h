// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mobius_mesh: a halfedge mesh that holds orientable and non-orientable
// 2-manifolds (with or without border) and walks both the same way.

#ifndef CGAL_EXT_MOBIUS_MESH_H
#define CGAL_EXT_MOBIUS_MESH_H

#include <CGAL_ext/exceptions.h>
#include <CGAL_ext/Mobius_mesh/internal/Connectivity_access.h>
#include <CGAL_ext/Mobius_mesh/internal/Corner_channel_array.h>
#include <CGAL_ext/Mobius_mesh/internal/Dart_encoding.h>
#include <CGAL_ext/Mobius_mesh/internal/Property_container.h>
#include <CGAL_ext/Mobius_mesh/internal/Size_limits.h>
#include <CGAL_ext/internal/Uninitialized_array.h>

#include <CGAL/Origin.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

namespace internal {
class Plain_reader;
} // namespace internal

/// \ingroup PkgMobiusMesh
/// A typed index into one of the element arrays of a `Mobius_mesh`.
template <class Tag>
class Index
{
public:
  /// The unsigned 32-bit integer that holds the index.
  using size_type = std::uint32_t;
  /// The value of a null (invalid) index: the largest `size_type`.
  static constexpr size_type null_value = (std::numeric_limits<size_type>::max)();

  /// A null index.
  constexpr Index() = default;
  ///@{
  /// The index `i`; `i` must fit in `size_type`.
  constexpr explicit Index(size_type i) : idx_(i) {}
  constexpr explicit Index(std::size_t i) : idx_(static_cast<size_type>(i)) {}
  constexpr explicit Index(int i) : idx_(static_cast<size_type>(i)) {}
  ///@}

  /// The index as an integer (`null_value` for a null index).
  constexpr size_type idx() const { return idx_; }
  /// The index as an integer, as `idx()`.
  constexpr explicit operator size_type() const { return idx_; }
  /// True unless the index is null.
  constexpr bool is_valid() const { return idx_ != null_value; }
  /// Makes the index null.
  void reset() { idx_ = null_value; }

  ///@{
  /// Compares the integer values of two indices (a null index is the largest).
  constexpr bool operator==(Index o) const { return idx_ == o.idx_; }
  constexpr bool operator!=(Index o) const { return idx_ != o.idx_; }
  constexpr bool operator<(Index o) const { return idx_ < o.idx_; }
  constexpr bool operator>(Index o) const { return idx_ > o.idx_; }
  ///@}

  /// Writes the index as the tag's prefix and its value (`v12`, `f3`), or the
  /// prefix and `null`.
  friend std::ostream& operator<<(std::ostream& os, Index i)
  {
    os << Tag::prefix;
    return i.is_valid() ? (os << i.idx_) : (os << "null");
  }
  /// A hash of the index, for `boost::hash` and `std::hash`.
  friend std::size_t hash_value(Index i) { return std::hash<size_type>()(i.idx_); }

private:
  size_type idx_ = null_value;
};

/// \ingroup PkgMobiusMesh
/// The tag of `Vertex_index`.
struct Vertex_tag { static constexpr const char* prefix = "v"; };
/// \ingroup PkgMobiusMesh
/// The tag of `Halfedge_index`.
struct Halfedge_tag { static constexpr const char* prefix = "h"; };
/// \ingroup PkgMobiusMesh
/// The tag of `Edge_index`.
struct Edge_tag { static constexpr const char* prefix = "e"; };
/// \ingroup PkgMobiusMesh
/// The tag of `Face_index`.
struct Face_tag { static constexpr const char* prefix = "f"; };

/// \var Vertex_tag::prefix
/// The prefix with which vertex indices are printed.

/// \var Halfedge_tag::prefix
/// The prefix with which halfedge indices are printed.

/// \var Edge_tag::prefix
/// The prefix with which edge indices are printed.

/// \var Face_tag::prefix
/// The prefix with which face indices are printed.

/// \ingroup PkgMobiusMesh
/// The index of a vertex of a `Mobius_mesh`.
using Vertex_index = Index<Vertex_tag>;
/// \ingroup PkgMobiusMesh
/// The index of a halfedge of a `Mobius_mesh`: the halfedges of edge `e` are `2e` and `2e+1`.
using Halfedge_index = Index<Halfedge_tag>;
/// \ingroup PkgMobiusMesh
/// The index of an edge of a `Mobius_mesh`.
using Edge_index = Index<Edge_tag>;
/// \ingroup PkgMobiusMesh
/// The index of a face of a `Mobius_mesh`.
using Face_index = Index<Face_tag>;

/// \ingroup PkgMobiusMesh
/// A dart is a halfedge together with an orientation bit. The unflipped dart
/// walks the halfedge along the orientation of its face; the flipped dart is
/// the same halfedge walked against it (source and target, next and prev swap).
/// Links between darts make all orientable halfedge identities hold on
/// non-orientable meshes too.
class Dart
{
public:
  /// The unsigned 32-bit integer that holds the halfedge index and the orientation bit.
  using size_type = std::uint32_t;
  /// The bits of a null dart.
  static constexpr size_type null_value = (std::numeric_limits<size_type>::max)();

  /// A null dart.
  constexpr Dart() = default;
  /// The dart of `h`, flipped if `flipped`; null if `h` is null.
  constexpr Dart(Halfedge_index h, bool flipped)
    : bits_(h.is_valid() ? internal::dart_encoding::dart(h.idx(), flipped) : null_value)
  {}
  /// The unflipped dart of `h`.
  constexpr explicit Dart(Halfedge_index h) : Dart(h, false) {}

  /// The dart whose encoding is `b`, as returned by `bits()`.
  static constexpr Dart from_bits(size_type b)
  {
    Dart d;
    d.bits_ = b;
    return d;
  }
  /// The encoding of the dart (halfedge and orientation bit) as one integer,
  /// for use as an array index or a hash key.
  constexpr size_type bits() const { return bits_; }
  /// The halfedge of the dart; null for a null dart.
  constexpr Halfedge_index halfedge() const
  {
    return is_valid() ? Halfedge_index(internal::dart_encoding::halfedge_of_dart(bits_)) : Halfedge_index();
  }
  /// True if the dart walks its halfedge against the orientation of its face.
  constexpr bool is_flipped() const { return internal::dart_encoding::is_flipped(bits_); }
  /// The same halfedge with the other orientation bit.
  constexpr Dart flipped() const { return from_bits(internal::dart_encoding::flip(bits_)); }
  /// True unless the dart is null.
  constexpr bool is_valid() const { return bits_ != null_value; }

  ///@{
  /// Compares the encodings of two darts, as returned by `bits()`.
  constexpr bool operator==(Dart o) const { return bits_ == o.bits_; }
  constexpr bool operator!=(Dart o) const { return bits_ != o.bits_; }
  constexpr bool operator<(Dart o) const { return bits_ < o.bits_; }
  ///@}

  /// Writes the dart as its halfedge, followed by `~` if flipped (`h7~`), or `d:null`.
  friend std::ostream& operator<<(std::ostream& os, Dart d)
  {
    if (!d.is_valid())
      return os << "d:null";
    return os << d.halfedge() << (d.is_flipped() ? "~" : "");
  }
  /// A hash of the dart, for `boost::hash` and `std::hash`.
  friend std::size_t hash_value(Dart d) { return std::hash<size_type>()(d.bits_); }

private:
  size_type bits_ = null_value;
};

namespace internal {

// Iterator over the indices [0, n) of one element kind that skips removed
// elements. `removed` flags them (null while nothing is removed), one flag per
// `2^shift` indices: halfedges are removed with their edge.
template <class I>
class Index_iterator
{
public:
  using iterator_category = std::bidirectional_iterator_tag;
  using value_type = I;
  using difference_type = std::ptrdiff_t;
  using pointer = const I*;
  using reference = I;
  using size_type = typename I::size_type;

  Index_iterator() = default;
  Index_iterator(size_type i, size_type end, const Property_array<bool>* removed = nullptr, unsigned shift = 0)
    : i_(i), end_(end), removed_(removed), shift_(shift)
  {
    skip_forward();
  }

  I operator*() const { return I(i_); }
  Index_iterator& operator++()
  {
    ++i_;
    skip_forward();
    return *this;
  }
  Index_iterator operator++(int) { Index_iterator t = *this; ++*this; return t; }
  Index_iterator& operator--()
  {
    do
      --i_;
    while (is_removed(i_));
    return *this;
  }
  Index_iterator operator--(int) { Index_iterator t = *this; --*this; return t; }
  bool operator==(const Index_iterator& o) const { return i_ == o.i_; }
  bool operator!=(const Index_iterator& o) const { return i_ != o.i_; }

private:
  bool is_removed(size_type i) const { return removed_ != nullptr && removed_->data()[i >> shift_].value; }
  void skip_forward()
  {
    while (i_ < end_ && is_removed(i_))
      ++i_;
  }

  size_type i_ = 0, end_ = 0;
  const Property_array<bool>* removed_ = nullptr;
  unsigned shift_ = 0;
};

template <class It>
class Iterator_range
{
public:
  Iterator_range(It b, It e, std::size_t n) : b_(b), e_(e), n_(n) {}
  It begin() const { return b_; }
  It end() const { return e_; }
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }

private:
  It b_, e_;
  std::size_t n_;
};

} // namespace internal

/// \ingroup PkgMobiusMesh
///
/// A halfedge data structure for polygon meshes that are 2-manifolds, with or
/// without border, orientable or not.
///
/// Storage follows `CGAL::Surface_mesh`: index handles, struct-of-arrays
/// connectivity, and named dynamic property maps for user data. Halfedges
/// come in pairs per edge (`2e`, `2e+1`). Each face has its own orientation,
/// and each edge has a *Möbius bit*, set when the two faces of the edge run
/// along it in the same direction (a Möbius connection). Border halfedges
/// have a null face; border edges are never Möbius.
///
/// All navigation goes through `Dart`s, for which the orientable identities
/// hold on every mesh:
/// `opposite(opposite(d)) == d`, `next(prev(d)) == d`,
/// `target(opposite(d)) == source(d)`, `source(next(d)) == target(d)`.
/// Circulating around a vertex with `opposite(next(d))` crosses Möbius edges
/// and borders without special cases.
///
/// \tparam P the point type, for example `Kernel::Point_3` of any CGAL kernel.
template <class P>
class Mobius_mesh
{
public:
  /// The point type.
  using Point = P;
  /// The type of element counts and indices (32 bits).
  using size_type = std::uint32_t;
  ///@{
  /// The element indices and darts, as in the enclosing namespace.
  using Vertex_index = CGAL_ext::Vertex_index;
  using Halfedge_index = CGAL_ext::Halfedge_index;
  using Edge_index = CGAL_ext::Edge_index;
  using Face_index = CGAL_ext::Face_index;
  using Dart = CGAL_ext::Dart;
  ///@}

  /// A property map with key `I` (an index type) and value `T`, a model of
  /// `LvaluePropertyMap`; it converts to `false` when null.
  template <class I, class T>
  using Property_map = internal::Property_map<I, T>;

  /// A corner channel with values of type `T`: per-corner data (texture
  /// coordinates, corner normals) as OBJ and OpenSubdiv model it, an index
  /// per face corner into the channel's own values (see `add_corner_channel()`).
  template <class T>
  using Corner_channel = internal::Corner_channel<Halfedge_index, T>;

  ///@{
  /// Ranges of the indices of one kind of element, in index order, removed
  /// elements skipped; they have `begin()`, `end()`, `size()` and `empty()`.
  using Vertex_range = internal::Iterator_range<internal::Index_iterator<Vertex_index>>;
  using Halfedge_range = internal::Iterator_range<internal::Index_iterator<Halfedge_index>>;
  using Edge_range = internal::Iterator_range<internal::Index_iterator<Edge_index>>;
  using Face_range = internal::Iterator_range<internal::Index_iterator<Face_index>>;
  ///@}

  // ---------------------------------------------------------------- lifecycle

  /// An empty mesh, with its point map.
  Mobius_mesh() { init_points(); }
  /// A copy of `o`: connectivity, removed elements and every property map.
  Mobius_mesh(const Mobius_mesh& o) { *this = o; }
  /// Takes the elements and property maps of `o`, which is left empty.
  Mobius_mesh(Mobius_mesh&& o) noexcept { *this = std::move(o); }
  /// Makes this mesh a copy of `o`: connectivity, removed elements and every property map.
  Mobius_mesh& operator=(const Mobius_mesh& o)
  {
    if (this != &o) {
      copy_connectivity(o);
      vprops_ = o.vprops_;
      hprops_ = o.hprops_;
      eprops_ = o.eprops_;
      fprops_ = o.fprops_;
      points_ = Property_map<Vertex_index, Point>(vprops_.template get<Point>("v:point"));
      find_removal_marks(o.removed_vertices_.count, o.removed_edges_.count, o.removed_faces_.count);
      removed_vertices_.free = o.removed_vertices_.free;
      removed_edges_.free = o.removed_edges_.free;
      removed_faces_.free = o.removed_faces_.free;
      recycle_ = o.recycle_;
    }
    return *this;
  }
  /// Takes the elements and property maps of `o`, which is left empty.
  Mobius_mesh& operator=(Mobius_mesh&& o) noexcept
  {
    if (this != &o) {
      v_halfedge_ = std::move(o.v_halfedge_);
      h_target_ = std::move(o.h_target_);
      h_next_ = std::move(o.h_next_);
      h_prev_ = std::move(o.h_prev_);
      h_face_ = std::move(o.h_face_);
      e_mobius_ = std::move(o.e_mobius_);
      f_halfedge_ = std::move(o.f_halfedge_);
      vprops_ = std::move(o.vprops_);
      hprops_ = std::move(o.hprops_);
      eprops_ = std::move(o.eprops_);
      fprops_ = std::move(o.fprops_);
      points_ = o.points_;
      removed_vertices_ = std::move(o.removed_vertices_);
      removed_edges_ = std::move(o.removed_edges_);
      removed_faces_ = std::move(o.removed_faces_);
      mobius_edges_ = o.mobius_edges_;
      recycle_ = o.recycle_;
      o.clear();
    }
    return *this;
  }

  /// Removes all elements and all property maps but the point map.
  void clear()
  {
    v_halfedge_.clear();
    h_target_.clear();
    h_next_.clear();
    h_prev_.clear();
    h_face_.clear();
    e_mobius_.clear();
    f_halfedge_.clear();
    vprops_.clear();
    hprops_.clear();
    eprops_.clear();
    fprops_.clear();
    removed_vertices_ = removed_edges_ = removed_faces_ = Removal_marks();
    mobius_edges_ = 0;
    init_points();
  }

  /// Reserves storage for the given numbers of elements.
  void reserve(size_type nv, size_type ne, size_type nf)
  {
    v_halfedge_.reserve(nv);
    vprops_.reserve(nv);
    h_target_.reserve(2 * std::size_t(ne));
    h_next_.reserve(2 * std::size_t(ne));
    h_prev_.reserve(2 * std::size_t(ne));
    h_face_.reserve(2 * std::size_t(ne));
    hprops_.reserve(2 * std::size_t(ne));
    e_mobius_.reserve(ne);
    eprops_.reserve(ne);
    f_halfedge_.reserve(nf);
    fprops_.reserve(nf);
  }

  /// Releases unused capacity.
  void shrink_to_fit()
  {
    v_halfedge_.shrink_to_fit();
    h_target_.shrink_to_fit();
    h_next_.shrink_to_fit();
    h_prev_.shrink_to_fit();
    h_face_.shrink_to_fit();
    e_mobius_.shrink_to_fit();
    f_halfedge_.shrink_to_fit();
    vprops_.shrink_to_fit();
    hprops_.shrink_to_fit();
    eprops_.shrink_to_fit();
    fprops_.shrink_to_fit();
  }

  // ---------------------------------------------------------------- counts and ranges

  ///@{
  /// The numbers of elements, removed ones not counted (as in `Surface_mesh`).
  size_type number_of_vertices() const { return num_vertices() - removed_vertices_.count; }
  size_type number_of_halfedges() const { return num_halfedges() - 2 * removed_edges_.count; }
  size_type number_of_edges() const { return num_edges() - removed_edges_.count; }
  size_type number_of_faces() const { return num_faces() - removed_faces_.count; }
  ///@}
  /// True if the mesh has no vertex (removed ones not counted).
  bool is_empty() const { return number_of_vertices() == 0; }

  ///@{
  /// The numbers of element slots, removed elements included: every index of
  /// the mesh is below them. Equal to the `number_of_*()` functions unless
  /// `has_garbage()`.
  size_type num_vertices() const { return size_type(v_halfedge_.size()); }
  size_type num_halfedges() const { return size_type(h_target_.size()); }
  size_type num_edges() const { return size_type(e_mobius_.size()); }
  size_type num_faces() const { return size_type(f_halfedge_.size()); }
  ///@}

  ///@{
  /// The elements, in index order, removed ones skipped.
  Vertex_range vertices() const { return range<Vertex_index>(num_vertices(), removed_vertices_, 0); }
  Halfedge_range halfedges() const { return range<Halfedge_index>(num_halfedges(), removed_edges_, 1); }
  Edge_range edges() const { return range<Edge_index>(num_edges(), removed_edges_, 0); }
  Face_range faces() const { return range<Face_index>(num_faces(), removed_faces_, 0); }
  ///@}

  ///@{
  /// The null index (or dart) of each kind, as returned where there is no element.
  static constexpr Vertex_index null_vertex() { return Vertex_index(); }
  static constexpr Halfedge_index null_halfedge() { return Halfedge_index(); }
  static constexpr Edge_index null_edge() { return Edge_index(); }
  static constexpr Face_index null_face() { return Face_index(); }
  static constexpr Dart null_dart() { return Dart(); }
  ///@}

  ///@{
  /// True if the index (or the dart's halfedge) names a slot of the mesh
  /// (removed or not); null indices are not valid.
  bool is_valid(Vertex_index v) const { return v.idx() < num_vertices(); }
  bool is_valid(Halfedge_index h) const { return h.idx() < num_halfedges(); }
  bool is_valid(Edge_index e) const { return e.idx() < num_edges(); }
  bool is_valid(Face_index f) const { return f.idx() < num_faces(); }
  bool is_valid(Dart d) const { return d.is_valid() && is_valid(d.halfedge()); }
  ///@}

  // ---------------------------------------------------------------- darts

  /// The dart of `h`; unflipped runs along the orientation of `h`'s face.
  static constexpr Dart dart(Halfedge_index h, bool flipped = false) { return Dart(h, flipped); }
  /// The same halfedge as `d` with the other orientation bit: `d.flipped()`.
  static constexpr Dart flip(Dart d) { return d.flipped(); }

  /// The vertex `d` points to.
  Vertex_index target(Dart d) const
  {
    return d.is_flipped() ? source_of(d.halfedge()) : h_target_[d.halfedge().idx()];
  }
  /// The vertex `d` starts from: `target(opposite(d))`.
  Vertex_index source(Dart d) const
  {
    return d.is_flipped() ? h_target_[d.halfedge().idx()] : source_of(d.halfedge());
  }
  /// The dart after `d` around its face (or border cycle), walked in `d`'s
  /// direction: `source(next(d)) == target(d)`.
  Dart next(Dart d) const
  {
    const size_type h = d.halfedge().idx();
    return d.is_flipped() ? h_prev_[h].flipped() : h_next_[h];
  }
  /// The dart before `d` around its face (or border cycle): `next(prev(d)) == d`.
  Dart prev(Dart d) const
  {
    const size_type h = d.halfedge().idx();
    return d.is_flipped() ? h_next_[h].flipped() : h_prev_[h];
  }
  /// The dart of the other halfedge of the edge that runs against `d`.
  Dart opposite(Dart d) const
  {
    const size_type b = d.bits();
    return Dart::from_bits(internal::dart_encoding::opposite_dart(b, e_mobius_[internal::dart_encoding::edge_of_dart(b)] != 0));
  }
  /// The face of `d`'s halfedge; null on the border.
  Face_index face(Dart d) const { return h_face_[d.halfedge().idx()]; }
  /// The edge of `d`'s halfedge.
  Edge_index edge(Dart d) const { return Edge_index(internal::dart_encoding::edge_of_dart(d.bits())); }
  /// The halfedge of `d`: `d.halfedge()`.
  static Halfedge_index halfedge(Dart d) { return d.halfedge(); }

  /// An incoming dart of `v` (target `v`); a border dart if `v` is on the border.
  Dart halfedge(Vertex_index v) const { return v_halfedge_[v.idx()]; }
  /// The unflipped dart of the stored halfedge of `f`.
  Dart halfedge(Face_index f) const { return Dart(f_halfedge_[f.idx()], false); }
  /// The unflipped dart of the first halfedge of `e`.
  static Dart halfedge(Edge_index e) { return Dart(halfedge(e, 0), false); }
  /// Halfedge `i` (0 or 1) of `e`: `2e + i`.
  static Halfedge_index halfedge(Edge_index e, unsigned i)
  {
    return Halfedge_index(internal::dart_encoding::halfedge_of_edge(e.idx(), i));
  }
  /// The edge of `h`: `h / 2`.
  static Edge_index edge(Halfedge_index h) { return Edge_index(internal::dart_encoding::edge_of_halfedge(h.idx())); }
  /// The other halfedge of `h`'s edge, as an index (`h ^ 1`); to walk the
  /// mesh, use `opposite(Dart)`, which also sets the orientation bit.
  static Halfedge_index opposite_halfedge(Halfedge_index h)
  {
    return Halfedge_index(internal::dart_encoding::opposite_halfedge(h.idx()));
  }

  /// The target of the unflipped dart of `h`.
  Vertex_index target(Halfedge_index h) const { return target(dart(h)); }
  /// The source of the unflipped dart of `h`.
  Vertex_index source(Halfedge_index h) const { return source(dart(h)); }
  /// The face of `h`; null on the border.
  Face_index face(Halfedge_index h) const { return h_face_[h.idx()]; }
  /// End `i` of `e`: its source (`i == 0`) or target (`i == 1`) as seen from `halfedge(e)`.
  Vertex_index vertex(Edge_index e, unsigned i) const
  {
    return i == 0 ? source(halfedge(e)) : target(halfedge(e));
  }

  // ---------------------------------------------------------------- queries

  ///@{
  /// True if the halfedge has no face.
  bool is_border(Dart d) const { return !h_face_[d.halfedge().idx()].is_valid(); }
  bool is_border(Halfedge_index h) const { return !h_face_[h.idx()].is_valid(); }
  ///@}
  /// True if one of the two halfedges of `e` has no face.
  bool is_border(Edge_index e) const
  {
    return is_border(halfedge(e, 0)) || is_border(halfedge(e, 1));
  }
  /// True if `v` is on the border or isolated. As in `Surface_mesh`, the
  /// stored dart is a border dart on the border after the mesh's own
  /// operations, but CGAL's generic `Euler::remove_face()` leaves it as it
  /// was when it opens a closed fan: unless `check_all_incident_halfedges`
  /// is false, every dart around `v` is looked at.
  bool is_border(Vertex_index v, bool check_all_incident_halfedges = true) const
  {
    const Dart d = v_halfedge_[v.idx()];
    if (!d.is_valid() || is_border(d))
      return true;
    return check_all_incident_halfedges && border_dart_into(v).is_valid();
  }
  /// A border dart ending at `v`, or a null dart if `v` is interior or isolated.
  Dart border_dart_into(Vertex_index v) const;
  /// True if `v` has no incident edge.
  bool is_isolated(Vertex_index v) const { return !v_halfedge_[v.idx()].is_valid(); }
  /// True if the two faces of `e` run along it in the same direction.
  bool is_mobius(Edge_index e) const { return e_mobius_[e.idx()] != 0; }
  /// True if `v` is an end of a Möbius edge.
  bool is_on_mobius_connection(Vertex_index v) const;

  /// Number of incident edges.
  size_type degree(Vertex_index v) const;
  /// Number of sides.
  size_type degree(Face_index f) const;

  // ---------------------------------------------------------------- points and properties

  ///@{
  /// The point of `v`.
  const Point& point(Vertex_index v) const { return points_[v]; }
  Point& point(Vertex_index v) { return points_[v]; }
  ///@}
  /// The point map (the vertex property named `"v:point"`).
  Property_map<Vertex_index, Point> points() const { return points_; }

  /// Adds a property map named `name` with value type `T`, or returns the
  /// existing one; `second` tells whether it was created. If a map of that
  /// name exists with another value type, returns a null map and `false`.
  template <class I, class T>
  std::pair<Property_map<I, T>, bool> add_property_map(const std::string& name, const T& t = T())
  {
    auto [array, created] = container<I>().template add<T>(name, t);
    return {Property_map<I, T>(array), created};
  }
  /// The property map named `name` of value type `T`, if any.
  template <class I, class T>
  std::optional<Property_map<I, T>> property_map(const std::string& name) const
  {
    if (auto* array = container<I>().template get<T>(name))
      return Property_map<I, T>(array);
    return std::nullopt;
  }
  /// Removes a property map; the point map cannot be removed.
  template <class I, class T>
  bool remove_property_map(Property_map<I, T>& map)
  {
    if (!map || static_cast<const void*>(map.array()) == static_cast<const void*>(points_.array()) ||
        is_removal_mark(map.array()))
      return false;
    const bool removed = container<I>().remove(map.array());
    map = Property_map<I, T>();
    return removed;
  }
  /// The names of the property maps with key type `I`, the point map
  /// included (for `Halfedge_index`, the corner channels too).
  template <class I>
  std::vector<std::string> properties() const { return container<I>().names(); }

  /// \name Corner channels
  /// Per-corner data, one more kind of property: each face corner holds an
  /// index into the channel's own array of values, so that corners at one
  /// vertex share a value where the data is continuous and hold different
  /// ones along a *seam* (OBJ's `f v/vt/vn`, OpenSubdiv's face-varying
  /// channels). The indices are a halfedge property (the names share the
  /// halfedge maps' namespace, `"c:uv"` by convention), so every operation
  /// that keeps halfedge maps keeps channels: copies, `join()` (the joined
  /// mesh's values follow this mesh's), `collect_garbage()`; and
  /// `reverse_face_orientation()` (and so `orient()`) keeps each corner's
  /// index at its vertex. A corner is the corner of `face(d)` at `target(d)`
  /// for a face dart `d`; its value does not depend on the way the face is
  /// walked, so Möbius edges need nothing special.
  /// @{

  /// Adds a corner channel named `name` with values of type `T`, or returns
  /// the existing one; `second` tells whether it was created. If a halfedge
  /// map or channel of that name exists with another type, returns a null
  /// channel and `false`. A new channel has no values and no corner has an index.
  template <class T>
  std::pair<Corner_channel<T>, bool> add_corner_channel(const std::string& name)
  {
    auto [array, created] = hprops_.template add_array<internal::Corner_channel_array<T>>(name);
    return {Corner_channel<T>(array), created};
  }
  /// The corner channel named `name` with values of type `T`, if any.
  template <class T>
  std::optional<Corner_channel<T>> corner_channel(const std::string& name) const
  {
    if (auto* array = hprops_.template find_array<internal::Corner_channel_array<T>>(name))
      return Corner_channel<T>(array);
    return std::nullopt;
  }
  /// Removes a corner channel (and nulls the handle); false if it was not one of this mesh.
  template <class T>
  bool remove_corner_channel(Corner_channel<T>& channel)
  {
    const bool removed = channel && hprops_.remove(channel.array());
    channel = Corner_channel<T>();
    return removed;
  }
  /// Removes the corner channel named `name`, whatever its value type; false
  /// if there is none (a halfedge map of that name is left alone).
  bool remove_corner_channel(const std::string& name)
  {
    return hprops_.remove(hprops_.template find_array<internal::Base_corner_channel>(name));
  }
  /// The names of the corner channels, in order of creation.
  std::vector<std::string> corner_channels() const
  {
    std::vector<std::string> names;
    hprops_.template for_each_array<internal::Base_corner_channel>(
      [&](const internal::Base_corner_channel& c) { names.push_back(c.name()); });
    return names;
  }
  /// The slot of the corner of `face(d)` at `target(d)`: the halfedge of that
  /// face that ends there along the face's orientation (`d`'s own halfedge
  /// unless `d` is flipped). `d` must not be a border dart.
  Halfedge_index corner(Dart d) const { return d.is_flipped() ? next(d).halfedge() : d.halfedge(); }
  /// Gives the corner in slot `to` the value index of the corner in slot
  /// `from`, in every channel: for edits that make a corner at a vertex that
  /// the same face already had a corner at (`Euler::split_face()` does).
  void copy_corner(Halfedge_index from, Halfedge_index to)
  {
    if (hprops_.arrays().empty())
      return;
    hprops_.template for_each_array<internal::Base_corner_channel>(
      [&](internal::Base_corner_channel& c) { c.indices()[to.idx()] = c.indices()[from.idx()]; });
  }
  /// Leaves the corner in slot `h` without a value in every channel: for
  /// edits after which the value there is not known (`Euler::split_edge()`
  /// moves a halfedge's end to a new vertex), or that leave no corner there
  /// (a face removed: its halfedges become border halfedges).
  void clear_corner(Halfedge_index h)
  {
    if (hprops_.arrays().empty())
      return;
    hprops_.template for_each_array<internal::Base_corner_channel>(
      [&](internal::Base_corner_channel& c) { c.indices()[h.idx()] = internal::Base_corner_channel::no_value; });
  }
  /// @}

  // ---------------------------------------------------------------- construction

  ///@{
  /// Adds an isolated vertex. (`p` is taken by value: it may be a point of
  /// this mesh, which the insertion can move.)
  Vertex_index add_vertex() { return add_vertex_record(); } // the point map's default is the point
  Vertex_index add_vertex(Point p)
  {
    const Vertex_index v = add_vertex_record();
    points_[v] = std::move(p);
    return v;
  }
  ///@}

  /// Adds a face given its vertices in order; an edge it shares with an
  /// existing face becomes a Möbius edge if both faces run along it the same
  /// way. A face is refused (the mesh is left unchanged and `null_face()`
  /// returned, with the reason in `*why`) if it has fewer than three
  /// vertices, a repeated or invalid vertex, an edge that already has two
  /// faces, or if it would make a vertex non-manifold for good: touch a
  /// vertex whose fan is closed, or close one fan of a vertex that has
  /// others. As in `Surface_mesh`, faces may come in any order, so a vertex
  /// may hold several fans until the faces between them are added
  /// (`is_valid()` reports such vertices); `polygon_soup_to_mobius_mesh()`
  /// builds a whole mesh at once.
  template <class VertexRange>
  Face_index add_face(const VertexRange& vertices, std::string* why = nullptr);
  /// `add_face()` for a braced list of vertices: `m.add_face({u, v, w})`.
  Face_index add_face(std::initializer_list<Vertex_index> vertices, std::string* why = nullptr)
  {
    return add_face<std::initializer_list<Vertex_index>>(vertices, why);
  }

  /// The offsets returned by `join()`: element `x` of the joined mesh is
  /// element `x + offset` of this one.
  struct Join_offsets { size_type vertices, edges, faces; };

  /// \var Join_offsets::vertices
  /// The offset of the joined mesh's vertex indices.

  /// \var Join_offsets::edges
  /// The offset of the joined mesh's edge indices (its halfedges move by twice as much).

  /// \var Join_offsets::faces
  /// The offset of the joined mesh's face indices.

  /// Appends a disjoint copy of `other` to this mesh and returns where its
  /// elements went: the offsets of its vertex, edge and face indices (its
  /// halfedges move by twice the edge offset). Property maps of the same
  /// name and type are copied.
  Join_offsets join(const Mobius_mesh& other);

  /// Reverses the orientation of face `f`: its halfedges change direction,
  /// Möbius bits of its interior edges toggle, border links stay consistent.
  void reverse_face_orientation(Face_index f);

  // ---- low-level construction, as in Surface_mesh; the mesh may be invalid
  //      until the caller has set every link.

  /// Adds a vertex with no halfedge and a default point.
  Vertex_index add_vertex_record()
  {
    if (recycle_ && !removed_vertices_.free.empty()) {
      const size_type v = reuse_slot(vprops_, removed_vertices_);
      v_halfedge_[v] = Dart();
      return Vertex_index(v);
    }
    if (v_halfedge_.size() >= internal::max_vertices)
      refuse_growth("add_vertex()", 1, 0, 0);
    v_halfedge_.push_back(Dart());
    grow_properties(vprops_, removed_vertices_.flags, points_.array());
    return Vertex_index(size_type(v_halfedge_.size() - 1));
  }
  /// Adds an edge with two unlinked halfedges `2e` (target `t0`) and `2e+1` (target `t1`).
  Edge_index add_edge(Vertex_index t0, Vertex_index t1, bool mobius = false)
  {
    if (recycle_ && !removed_edges_.free.empty())
      return reuse_edge(t0, t1, mobius);
    if (e_mobius_.size() >= internal::max_edges)
      refuse_growth("add_edge()", 0, 1, 0);
    // Euler operations add edges one at a time: one test for room in all the
    // arrays, then stores without reallocation paths (growing is out of line).
    if (!has_room(h_target_, 2) || !has_room(h_next_, 2) || !has_room(h_prev_, 2) || !has_room(h_face_, 2) ||
        !has_room(e_mobius_, 1))
      grow_edge_arrays();
    using internal::push_within_capacity;
    push_within_capacity(h_target_, t0);
    push_within_capacity(h_target_, t1);
    for (int i = 0; i < 2; ++i) {
      push_within_capacity(h_next_, Dart());
      push_within_capacity(h_prev_, Dart());
      push_within_capacity(h_face_, Face_index());
    }
    hprops_.resize(h_target_.size());
    push_within_capacity(e_mobius_, std::uint8_t(mobius ? 1 : 0));
    if (mobius)
      count_mobius_change(false, true);
    grow_properties(eprops_, removed_edges_.flags);
    return Edge_index(size_type(e_mobius_.size() - 1));
  }
  /// Adds a face whose stored halfedge is `h`; no halfedge is linked to it.
  Face_index add_face_record(Halfedge_index h = Halfedge_index())
  {
    if (recycle_ && !removed_faces_.free.empty()) {
      const size_type f = reuse_slot(fprops_, removed_faces_);
      f_halfedge_[f] = h;
      return Face_index(f);
    }
    if (f_halfedge_.size() >= internal::max_faces)
      refuse_growth("add_face()", 0, 0, 1);
    f_halfedge_.push_back(h);
    grow_properties(fprops_, removed_faces_.flags);
    return Face_index(size_type(f_halfedge_.size() - 1));
  }
  /// Resizes all element arrays at once (new elements are unlinked).
  void resize(size_type nv, size_type ne, size_type nf)
  {
    internal::check_mesh_size("resize()", Mesh_size{nv, ne, nf, 0});
    v_halfedge_.resize(nv, Dart());
    vprops_.resize(nv);
    h_target_.resize(2 * std::size_t(ne), Vertex_index());
    h_next_.resize(2 * std::size_t(ne), Dart());
    h_prev_.resize(2 * std::size_t(ne), Dart());
    h_face_.resize(2 * std::size_t(ne), Face_index());
    hprops_.resize(2 * std::size_t(ne));
    e_mobius_.resize(ne, 0);
    recount_mobius_edges();
    eprops_.resize(ne);
    f_halfedge_.resize(nf, Halfedge_index());
    fprops_.resize(nf);
  }
  /// The counts of this mesh with `nv`, `ne`, `nf` more elements.
  Mesh_size grown_size(std::size_t nv, std::size_t ne, std::size_t nf) const
  {
    return Mesh_size{v_halfedge_.size() + nv, e_mobius_.size() + ne, f_halfedge_.size() + nf, 0};
  }
  /// Links `a` to `b`: afterwards `next(a) == b` and `prev(b) == a`.
  void set_next(Dart a, Dart b)
  {
    if (a.is_flipped())
      h_prev_[a.halfedge().idx()] = b.flipped();
    else
      h_next_[a.halfedge().idx()] = b;
    if (b.is_flipped())
      h_next_[b.halfedge().idx()] = a.flipped();
    else
      h_prev_[b.halfedge().idx()] = a;
  }
  /// Sets the target of (the unflipped dart of) `h` to `v`.
  void set_target(Halfedge_index h, Vertex_index v) { h_target_[h.idx()] = v; }
  /// Sets the face of `h` to `f` (null makes `h` a border halfedge).
  void set_face(Halfedge_index h, Face_index f) { h_face_[h.idx()] = f; }
  /// Sets the stored dart of `v`, which must end at `v` (a border dart if `v` is on the border).
  void set_halfedge(Vertex_index v, Dart d) { v_halfedge_[v.idx()] = d; }
  /// Sets the stored halfedge of `f`, which must be one of `f`'s halfedges.
  void set_halfedge(Face_index f, Halfedge_index h) { f_halfedge_[f.idx()] = h; }
  /// Sets the Möbius bit of `e`: whether its two faces run along it in the same direction.
  void set_mobius(Edge_index e, bool m)
  {
    count_mobius_change(e_mobius_[e.idx()] != 0, m);
    e_mobius_[e.idx()] = m ? 1 : 0;
  }

  // ---------------------------------------------------------------- validity

  /// Checks every link identity; returns an empty string if the mesh is
  /// valid, otherwise an explanation of the first failure found.
  std::string validity_report() const;
  /// `validity_report().empty()`, printing the report to `std::cerr` if `verbose`.
  bool is_valid(bool verbose = false) const
  {
    const std::string report = validity_report();
    if (verbose && !report.empty())
      std::cerr << "Mobius_mesh is invalid: " << report << std::endl;
    return report.empty();
  }

  // ---------------------------------------------------------------- removal and garbage collection

  /// \name Removal and garbage collection
  /// As in `Surface_mesh`, the low-level `remove_*()` functions only mark an
  /// element removed: they change no link, so the caller (an Euler operation,
  /// usually) keeps the rest of the mesh consistent. Removed elements are
  /// skipped by the ranges and not counted by `number_of_*()`, but keep their
  /// indices until `collect_garbage()` compacts every array and every property
  /// map.
  ///
  /// Elements added after a removal are appended by default, so indices
  /// handed out stay unique until the garbage is collected: an algorithm may
  /// keep the indices of removed elements (in a priority queue, say) and
  /// find them still removed. `set_recycle_garbage(true)` makes the adders
  /// take the most recently removed slot of their kind instead, as
  /// `Surface_mesh` does by default (a mesh that appends does not list its
  /// removed slots: turning recycling on lists them, highest index taken
  /// first): a mesh edited for a long time then
  /// stays as large as its live elements, with no collection, and the slots
  /// in use stay in the cache. A recycled slot is unlinked and its property
  /// values are the defaults again.
  /// @{

  /// Whether the adders reuse the slots of removed elements (default: false).
  /// Turning it on lists the slots already removed (highest index taken
  /// first); later removals are taken back last removed first.
  void set_recycle_garbage(bool recycle)
  {
    if (recycle && !recycle_)
      list_free_slots();
    recycle_ = recycle;
  }
  /// True if the adders reuse the slots of removed elements.
  bool does_recycle_garbage() const { return recycle_; }

  /// Marks `v` removed.
  void remove_vertex(Vertex_index v) { mark(vprops_, "v:removed", removed_vertices_, v.idx(), recycle_); }
  /// Marks `e` and its two halfedges removed. Their corners lose their value
  /// indices in every channel: a removed corner keeps no value alive (and a
  /// recycled slot starts without one).
  void remove_edge(Edge_index e)
  {
    clear_corner(halfedge(e, 0));
    clear_corner(halfedge(e, 1));
    mark(eprops_, "e:removed", removed_edges_, e.idx(), recycle_);
  }
  /// Marks `f` removed.
  void remove_face(Face_index f) { mark(fprops_, "f:removed", removed_faces_, f.idx(), recycle_); }

  /// True if `v` is marked removed.
  bool is_removed(Vertex_index v) const { return removed_vertices_.is_marked(v.idx()); }
  /// True if `h`'s edge is marked removed.
  bool is_removed(Halfedge_index h) const { return removed_edges_.is_marked(h.idx() / 2); }
  /// True if `e` is marked removed.
  bool is_removed(Edge_index e) const { return removed_edges_.is_marked(e.idx()); }
  /// True if `f` is marked removed.
  bool is_removed(Face_index f) const { return removed_faces_.is_marked(f.idx()); }

  /// The number of vertices marked removed.
  size_type number_of_removed_vertices() const { return removed_vertices_.count; }
  /// The number of halfedges marked removed: twice the number of removed edges.
  size_type number_of_removed_halfedges() const { return 2 * removed_edges_.count; }
  /// The number of edges marked removed.
  size_type number_of_removed_edges() const { return removed_edges_.count; }
  /// The number of faces marked removed.
  size_type number_of_removed_faces() const { return removed_faces_.count; }
  /// True if some element is marked removed and `collect_garbage()` has not run since.
  bool has_garbage() const
  {
    return removed_vertices_.count != 0 || removed_edges_.count != 0 || removed_faces_.count != 0;
  }

  /// Where `collect_garbage()` moved each element: `maps(x)` is the new index
  /// of the old index (or dart) `x`, null for a removed element.
  struct Garbage_collection_maps
  {
    /// The new index of each old vertex index (null if removed).
    std::vector<Vertex_index> vertices;
    /// The new index of each old edge index (null if removed).
    std::vector<Edge_index> edges;
    /// The new index of each old face index (null if removed).
    std::vector<Face_index> faces;

    /// The new index of `v`; null if `v` was removed or is null.
    Vertex_index operator()(Vertex_index v) const { return v.is_valid() ? vertices[v.idx()] : v; }
    /// The new index of `e`; null if `e` was removed or is null.
    Edge_index operator()(Edge_index e) const { return e.is_valid() ? edges[e.idx()] : e; }
    /// The new index of `f`; null if `f` was removed or is null.
    Face_index operator()(Face_index f) const { return f.is_valid() ? faces[f.idx()] : f; }
    /// The new index of `h` (halfedges move with their edge); null if removed or null.
    Halfedge_index operator()(Halfedge_index h) const
    {
      if (!h.is_valid())
        return h;
      const Edge_index e = (*this)(Edge_index(internal::dart_encoding::edge_of_halfedge(h.idx())));
      return e.is_valid() ? Halfedge_index(internal::dart_encoding::halfedge_of_edge(e.idx(), h.idx() & 1u))
                          : Halfedge_index();
    }
    /// The new dart of `d`, with the same orientation bit; null if removed or null.
    Dart operator()(Dart d) const
    {
      return d.is_valid() ? Dart((*this)(d.halfedge()), d.is_flipped()) : d;
    }
  };

  /// Removes the removed elements for good: every connectivity array and
  /// every property map is compacted, keeping the order of the elements that
  /// stay; their indices change (the optional `maps` say how).
  void collect_garbage()
  {
    Garbage_collection_maps maps;
    collect_garbage(maps);
  }
  /// As `collect_garbage()`, and fills `maps` with where each element went.
  void collect_garbage(Garbage_collection_maps& maps);
  /// @}

private:
  // A loop (both ends one vertex) is a degenerate edge of non-manifold input
  // (see `polygon_soup_to_mobius_mesh()`): a border whose border halfedge is
  // a border loop of its own; any other loop is invalid.
  bool is_lone_border_loop(Edge_index e) const
  {
    const Dart b(halfedge(e, is_border(halfedge(e, 0)) ? 0 : 1), false);
    return is_border(b) && next(b) == b;
  }

  // Subdivision writes whole arrays, copies carry property arrays of any type.
  friend struct internal::Connectivity_access;
  // Euler operations walk and edit orientable patches by halfedge index.
  friend class internal::Plain_reader;

  // The removed elements of one kind: their flags, a property array created
  // at the first removal (so a mesh that never removes pays nothing), their
  // number, and, while the mesh recycles, their indices in the order of
  // removal (the slots recycling takes back, last first). Removal changes no
  // link, so the free slots are listed here rather than threaded through the
  // links as Surface_mesh does; a mesh that appends lists none, so that a
  // long decimation does not hold a list of everything it removed.
  struct Removal_marks
  {
    internal::Property_array<bool>* flags = nullptr;
    size_type count = 0;
    std::vector<size_type> free;
    bool is_marked(size_type i) const { return flags != nullptr && flags->data()[i].value; }
  };

  // The property arrays of one kind of element grow by one element. Most
  // meshes have only the mesh's own arrays (the points, the removal flags):
  // those grow inline, the others through the type-erased container.
  static void grow_properties(internal::Property_container& props, internal::Property_array<bool>* flags,
                              internal::Property_array<Point>* points = nullptr)
  {
    const std::size_t own = (flags != nullptr ? 1 : 0) + (points != nullptr ? 1 : 0);
    if (props.arrays().size() != own) {
      props.resize(props.size() + 1);
      return;
    }
    if (flags != nullptr)
      flags->push_default();
    if (points != nullptr)
      points->push_default();
    props.grown_by_one();
  }

  // Keeping `mobius_edges_` (below) up to date.
  void count_mobius_change(bool was, bool is)
  {
    if (mobius_edges_ != unknown_count)
      mobius_edges_ += size_type(is) - size_type(was);
  }
  void recount_mobius_edges()
  {
    // A sum rather than count_if: the compiler vectorises the sum, not
    // count_if's branch (3x faster on the millions of edges of a subdivision).
    size_type n = 0;
    for (std::uint8_t b : e_mobius_)
      n += size_type(b != 0);
    mobius_edges_ = n;
  }

  template <class Array>
  static bool has_room(const Array& a, std::size_t k)
  {
    return a.capacity() - a.size() >= k;
  }
  // Room for the next edges in every array of halfedges and edges, as
  // push_back would make it (doubling).
  [[gnu::noinline]] void grow_edge_arrays()
  {
    const std::size_t nh = h_target_.size() + 2, ne = e_mobius_.size() + 1;
    h_target_.reserve((std::max)(nh, 2 * h_target_.capacity()));
    h_next_.reserve((std::max)(nh, 2 * h_next_.capacity()));
    h_prev_.reserve((std::max)(nh, 2 * h_prev_.capacity()));
    h_face_.reserve((std::max)(nh, 2 * h_face_.capacity()));
    e_mobius_.reserve((std::max)(ne, 2 * e_mobius_.capacity()));
  }

  // Throws the size error of an element added past the limits, out of line:
  // the functions that add elements stay small enough to inline.
  [[gnu::cold, gnu::noinline]] void refuse_growth(const char* function, std::size_t nv, std::size_t ne,
                                                  std::size_t nf) const
  {
    internal::check_mesh_size(function, grown_size(nv, ne, nf));
  }

  // Euler operations mark elements at every step: the flags are created
  // once, out of line, and the marking itself stays small enough to inline.
  static void mark(internal::Property_container& props, const char* name, Removal_marks& marks, size_type i,
                   bool list_free)
  {
    if (marks.flags == nullptr)
      create_marks(props, name, marks);
    bool& flag = marks.flags->data()[i].value;
    if (!flag) {
      ++marks.count;
      if (list_free)
        marks.free.push_back(i);
    }
    flag = true;
  }
  // Lists every removed slot as free, in index order (recycling turned on,
  // or a join while recycling).
  void list_free_slots()
  {
    for (Removal_marks* marks : {&removed_vertices_, &removed_edges_, &removed_faces_}) {
      marks->free.clear();
      if (marks->flags == nullptr)
        continue;
      const auto& flags = marks->flags->data();
      for (size_type i = 0; i < size_type(flags.size()); ++i)
        if (flags[i].value)
          marks->free.push_back(i);
    }
  }
  // Takes back the most recently removed slot of one kind: its property
  // values (the removal flag among them) go back to their defaults.
  static size_type reuse_slot(internal::Property_container& props, Removal_marks& marks)
  {
    const size_type i = marks.free.back();
    marks.free.pop_back();
    --marks.count;
    props.reset(i);
    return i;
  }
  // add_edge() on a recycled slot: two unlinked halfedges, as a new edge has.
  Edge_index reuse_edge(Vertex_index t0, Vertex_index t1, bool mobius)
  {
    const Edge_index e(reuse_slot(eprops_, removed_edges_));
    for (unsigned k = 0; k < 2; ++k) {
      const size_type h = internal::dart_encoding::halfedge_of_edge(e.idx(), k);
      h_target_[h] = k == 0 ? t0 : t1;
      h_next_[h] = h_prev_[h] = Dart();
      h_face_[h] = Face_index();
      hprops_.reset(h);
    }
    set_mobius(e, mobius);
    return e;
  }
  [[gnu::noinline]] static void create_marks(internal::Property_container& props, const char* name,
                                             Removal_marks& marks)
  {
    marks.flags = props.template add<bool>(name, false).first;
  }
  bool is_removal_mark(const void* array) const
  {
    for (const Removal_marks* m : {&removed_vertices_, &removed_edges_, &removed_faces_})
      if (m->flags != nullptr && static_cast<const void*>(m->flags) == array)
        return true;
    return false;
  }
  // After the property containers were copied or appended: the flag arrays
  // are found again by name, with the numbers of removed elements given.
  void find_removal_marks(size_type nv, size_type ne, size_type nf)
  {
    removed_vertices_.flags = vprops_.template get<bool>("v:removed");
    removed_edges_.flags = eprops_.template get<bool>("e:removed");
    removed_faces_.flags = fprops_.template get<bool>("f:removed");
    removed_vertices_.count = nv;
    removed_edges_.count = ne;
    removed_faces_.count = nf;
  }
  // Forgets every removal (the arrays are replaced or compacted).
  void drop_removal_marks()
  {
    vprops_.remove(removed_vertices_.flags);
    eprops_.remove(removed_edges_.flags);
    fprops_.remove(removed_faces_.flags);
    removed_vertices_ = removed_edges_ = removed_faces_ = Removal_marks();
  }

  template <class I>
  static internal::Iterator_range<internal::Index_iterator<I>> range(size_type n, const Removal_marks& marks,
                                                                     unsigned shift)
  {
    using It = internal::Index_iterator<I>;
    return {It(0, n, marks.flags, shift), It(n, n), std::size_t(n - (marks.count << shift))};
  }

  // Border edges are never Möbius, so the source of a halfedge is the target
  // of its partner, except across a Möbius edge, where it is the target of
  // the previous halfedge in its face (face cycles are never flipped).
  Vertex_index source_of(Halfedge_index h) const
  {
    const size_type i = h.idx();
    if (e_mobius_[internal::dart_encoding::edge_of_halfedge(i)] == 0)
      return h_target_[internal::dart_encoding::opposite_halfedge(i)];
    return h_target_[h_prev_[i].halfedge().idx()];
  }

  // CGAL's points are not zero-initialized: default to the origin where the
  // point type has one, so no array is filled with indeterminate values.
  static Point default_point()
  {
    if constexpr (std::is_constructible_v<Point, CGAL::Origin>)
      return Point(CGAL::ORIGIN);
    else
      return Point();
  }

  void init_points()
  {
    points_ = Property_map<Vertex_index, Point>(vprops_.template add<Point>("v:point", default_point()).first);
  }

  void copy_connectivity(const Mobius_mesh& o)
  {
    mobius_edges_ = o.mobius_edges_;
    v_halfedge_ = o.v_halfedge_;
    h_target_ = o.h_target_;
    h_next_ = o.h_next_;
    h_prev_ = o.h_prev_;
    h_face_ = o.h_face_;
    e_mobius_ = o.e_mobius_;
    f_halfedge_ = o.f_halfedge_;
  }

  void reverse_border_halfedge(Halfedge_index g);

  // validity_report() in parts.
  std::string check_sizes() const;
  std::string check_halfedge_links() const;
  std::string check_face_cycles() const;
  std::string check_vertex_fans() const;

  // add_face() in three steps: what the face meets at its vertices (or why it
  // is refused), its halfedges, and the border links around its vertices.
  struct Border_fan { Dart first_out, last_in; }; // border darts, in cyclic order
  struct Face_site
  {
    std::vector<std::vector<Border_fan>> fans; // the fans at each vertex
    std::vector<Dart> existing;                // the border dart from vs[i] to vs[i+1], if any
  };
  std::string check_face_site(const std::vector<Vertex_index>& vs, Face_site& site) const;
  std::vector<Halfedge_index> add_face_halfedges(Face_index f, const std::vector<Vertex_index>& vs,
                                                 const std::vector<Dart>& existing, std::vector<Dart>& new_border_out,
                                                 std::vector<Dart>& new_border_in);
  std::size_t fan_containing(const std::vector<Border_fan>& fans, Edge_index e) const
  {
    for (std::size_t k = 0; k < fans.size(); ++k)
      if (edge(fans[k].first_out) == e || edge(fans[k].last_in) == e)
        return k;
    return fans.size();
  }

  template <class I>
  internal::Property_container& container()
  {
    return const_cast<internal::Property_container&>(std::as_const(*this).template container<I>());
  }
  template <class I>
  const internal::Property_container& container() const
  {
    if constexpr (std::is_same_v<I, Vertex_index>)
      return vprops_;
    else if constexpr (std::is_same_v<I, Halfedge_index>)
      return hprops_;
    else if constexpr (std::is_same_v<I, Edge_index>)
      return eprops_;
    else {
      static_assert(std::is_same_v<I, Face_index>, "property maps are keyed by element indices");
      return fprops_;
    }
  }

  // Connectivity, one array per attribute.
  // (Not zeroed when resized without a value: see internal::Connectivity_access::overwrite();
  // large ones on huge pages: see internal/Huge_page_allocator.h.)
  internal::Uninitialized_array<Dart> v_halfedge_;
  internal::Uninitialized_array<Vertex_index> h_target_;
  internal::Uninitialized_array<Dart> h_next_;
  internal::Uninitialized_array<Dart> h_prev_;
  internal::Uninitialized_array<Face_index> h_face_;
  internal::Uninitialized_array<std::uint8_t> e_mobius_;
  internal::Uninitialized_array<Halfedge_index> f_halfedge_;

  internal::Property_container vprops_, hprops_, eprops_, fprops_;
  Property_map<Vertex_index, Point> points_;
  Removal_marks removed_vertices_, removed_edges_, removed_faces_;
  // Whether the adders take removed slots back (set_recycle_garbage()).
  bool recycle_ = false;
  // How many edge slots (removed ones included) are Möbius, or
  // `unknown_count` while arrays written from outside are not counted yet
  // (`Connectivity_access::overwrite()` until `reset_property_maps()`).
  // Zero means that no link of the mesh is flipped and opposite(h) is h ^ 1
  // everywhere: Euler operations then skip their local checks for it.
  static constexpr size_type unknown_count = (std::numeric_limits<size_type>::max)();
  size_type mobius_edges_ = 0;
};

// ============================================================================
// Circulators: ranges over darts that follow one step function until they
// come back to the start. They work on borders and across Möbius edges.
// ============================================================================

namespace internal {

template <class Mesh, class Step, class Value>
class Dart_cycle_range
{
public:
  class iterator
  {
  public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = decltype(Value()(std::declval<const Mesh&>(), Dart()));
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = value_type;

    iterator() = default;
    iterator(const Mesh* m, Dart start, Dart cur, bool done)
      : m_(m), start_(start), cur_(cur), done_(done)
    {}

    reference operator*() const { return Value()(*m_, cur_); }
    iterator& operator++()
    {
      cur_ = Step()(*m_, cur_);
      if (cur_ == start_)
        done_ = true;
      return *this;
    }
    iterator operator++(int)
    {
      iterator t = *this;
      ++*this;
      return t;
    }
    bool operator==(const iterator& o) const { return done_ == o.done_ && cur_ == o.cur_; }
    bool operator!=(const iterator& o) const { return !(*this == o); }
    Dart dart() const { return cur_; }

  private:
    const Mesh* m_ = nullptr;
    Dart start_, cur_;
    bool done_ = true;
  };

  Dart_cycle_range(const Mesh& m, Dart start) : m_(&m), start_(start) {}
  iterator begin() const { return iterator(m_, start_, start_, !start_.is_valid()); }
  iterator end() const { return iterator(m_, start_, start_, true); }
  std::size_t size() const { return std::size_t(std::distance(begin(), end())); }
  bool empty() const { return !start_.is_valid(); }

private:
  const Mesh* m_;
  Dart start_;
};

struct Next_step { template <class M> Dart operator()(const M& m, Dart d) const { return m.next(d); } };
struct Prev_step { template <class M> Dart operator()(const M& m, Dart d) const { return m.prev(d); } };
// Incoming darts of a vertex, in the rotational direction of the start dart's face.
struct Around_target_step
{
  template <class M> Dart operator()(const M& m, Dart d) const { return m.opposite(m.next(d)); }
};
struct Around_target_reverse_step
{
  template <class M> Dart operator()(const M& m, Dart d) const { return m.prev(m.opposite(d)); }
};

struct Dart_value { template <class M> Dart operator()(const M&, Dart d) const { return d; } };
struct Opposite_value { template <class M> Dart operator()(const M& m, Dart d) const { return m.opposite(d); } };
struct Target_value
{
  template <class M> Vertex_index operator()(const M& m, Dart d) const { return m.target(d); }
};
struct Source_value { template <class M> Vertex_index operator()(const M& m, Dart d) const { return m.source(d); } };
struct Face_value { template <class M> Face_index operator()(const M& m, Dart d) const { return m.face(d); } };
struct Opposite_face_value
{
  template <class M> Face_index operator()(const M& m, Dart d) const { return m.face(m.opposite(d)); }
};
struct Edge_value { template <class M> Edge_index operator()(const M& m, Dart d) const { return m.edge(d); } };

} // namespace internal

namespace internal {

// Where a circulator starts: a dart or a vertex, taken through this
// conversion on purpose. CGAL's BGL defines templates of the same names
// (`CGAL::halfedges_around_face()`, ...) that CGAL's algorithms call
// unqualified and whose result types they rely on; with the graph traits of
// `CGAL_ext/boost/graph/graph_traits_Mobius_mesh.h` both are viable for a
// `Mobius_mesh`, and the conversion makes CGAL's the better match in an
// unqualified call. The library calls its own ones qualified.
template <class H>
struct Circulator_start
{
  Circulator_start(H h) : value(h) {}
  operator H() const { return value; }
  H value;
};

} // namespace internal

/// \name Circulators
/// Ranges usable in a range-`for`, as `CGAL::halfedges_around_target()` and
/// friends are for `Surface_mesh`. Functions taking a vertex start at
/// `halfedge(v)` (a border dart if `v` is on the border); those taking a
/// dart start there. `reverse = true` walks the other way round.
/// @{

/// Darts of the face (or border loop) of `d`, starting at `d`.
template <class P>
auto halfedges_around_face(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Next_step, internal::Dart_value>(m, d);
}
template <class P>
auto halfedges_around_face_reverse(Dart d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Prev_step, internal::Dart_value>(m, d);
}
template <class P>
auto vertices_around_face(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Next_step, internal::Target_value>(m, d);
}
/// Faces across the edges of the face of `d` (null faces across border edges).
template <class P>
auto faces_around_face(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Next_step, internal::Opposite_face_value>(m, d);
}
template <class P>
auto edges_around_face(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Next_step, internal::Edge_value>(m, d);
}
template <class P>
auto halfedges_around_face(Face_index f, const Mobius_mesh<P>& m) { return CGAL_ext::halfedges_around_face(m.halfedge(f), m); }
template <class P>
auto vertices_around_face(Face_index f, const Mobius_mesh<P>& m) { return CGAL_ext::vertices_around_face(m.halfedge(f), m); }
template <class P>
auto faces_around_face(Face_index f, const Mobius_mesh<P>& m) { return CGAL_ext::faces_around_face(m.halfedge(f), m); }
template <class P>
auto edges_around_face(Face_index f, const Mobius_mesh<P>& m) { return CGAL_ext::edges_around_face(m.halfedge(f), m); }

/// Incoming darts of `target(d)`, starting at `d`.
template <class P>
auto halfedges_around_target(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Around_target_step, internal::Dart_value>(m, d);
}
template <class P>
auto halfedges_around_target_reverse(Dart d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Around_target_reverse_step, internal::Dart_value>(m, d);
}
/// Outgoing darts of `target(d)`: the opposites of the incoming ones.
template <class P>
auto halfedges_around_source(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Around_target_step, internal::Opposite_value>(m, d);
}
/// Faces around `target(d)`; a null face stands for the border gap.
template <class P>
auto faces_around_target(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Around_target_step, internal::Face_value>(m, d);
}
/// Vertices adjacent to `target(d)`.
template <class P>
auto vertices_around_target(internal::Circulator_start<Dart> d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Around_target_step, internal::Source_value>(m, d);
}
template <class P>
auto edges_around_target(Dart d, const Mobius_mesh<P>& m)
{
  return internal::Dart_cycle_range<Mobius_mesh<P>, internal::Around_target_step, internal::Edge_value>(m, d);
}

template <class P>
auto halfedges_around_target(internal::Circulator_start<Vertex_index> v, const Mobius_mesh<P>& m) { return CGAL_ext::halfedges_around_target(m.halfedge(v), m); }
template <class P>
auto halfedges_around_target_reverse(Vertex_index v, const Mobius_mesh<P>& m)
{
  return CGAL_ext::halfedges_around_target_reverse(m.halfedge(v), m);
}
template <class P>
auto halfedges_around_source(internal::Circulator_start<Vertex_index> v, const Mobius_mesh<P>& m) { return CGAL_ext::halfedges_around_source(m.halfedge(v), m); }
template <class P>
auto faces_around_target(internal::Circulator_start<Vertex_index> v, const Mobius_mesh<P>& m) { return CGAL_ext::faces_around_target(m.halfedge(v), m); }
template <class P>
auto vertices_around_target(internal::Circulator_start<Vertex_index> v, const Mobius_mesh<P>& m) { return CGAL_ext::vertices_around_target(m.halfedge(v), m); }
template <class P>
auto edges_around_target(Vertex_index v, const Mobius_mesh<P>& m) { return CGAL_ext::edges_around_target(m.halfedge(v), m); }

/// @}

namespace internal {

// Algorithms that lay out arrays by element index (subdivision, conversion,
// writing, merging) need indices without gaps: they refuse a mesh with
// removed elements rather than carry its garbage.
template <class P>
void require_no_garbage(const Mobius_mesh<P>& m, const char* function)
{
  if (m.has_garbage())
    throw Parameter_error(std::string(function) + ": the mesh has removed elements; call collect_garbage() first");
}

} // namespace internal

// ============================================================================
// Out-of-line members
// ============================================================================

template <class P>
bool Mobius_mesh<P>::is_on_mobius_connection(Vertex_index v) const
{
  for (Edge_index e : CGAL_ext::edges_around_target(v, *this))
    if (is_mobius(e))
      return true;
  return false;
}

template <class P>
Dart Mobius_mesh<P>::border_dart_into(Vertex_index v) const
{
  const Dart stored = v_halfedge_[v.idx()];
  if (!stored.is_valid() || is_border(stored))
    return stored;
  for (Dart d : CGAL_ext::halfedges_around_target(stored, *this))
    if (is_border(d))
      return d;
  return Dart();
}

template <class P>
typename Mobius_mesh<P>::size_type Mobius_mesh<P>::degree(Vertex_index v) const
{
  return size_type(CGAL_ext::halfedges_around_target(halfedge(v), *this).size());
}

template <class P>
typename Mobius_mesh<P>::size_type Mobius_mesh<P>::degree(Face_index f) const
{
  return size_type(CGAL_ext::halfedges_around_face(halfedge(f), *this).size());
}

template <class P>
std::string Mobius_mesh<P>::check_face_site(const std::vector<Vertex_index>& vs, Face_site& site) const
{
  const std::size_t n = vs.size();
  auto name = [](Vertex_index v) { return "v" + std::to_string(v.idx()); };
  if (n < 3)
    return "a face needs at least three vertices";
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_valid(vs[i]))
      return "vertex index " + std::to_string(vs[i].idx()) + " is not in the mesh";
    for (std::size_t j = 0; j < i; ++j)
      if (vs[i] == vs[j])
        return "vertex " + name(vs[i]) + " is repeated in the face";
  }
  // The fans around each vertex. A vertex may hold several fans while a mesh
  // is built face by face, as in Surface_mesh.
  site.fans.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex_index v = vs[i];
    if (is_isolated(v))
      continue;
    if (!is_border(v))
      return "vertex " + name(v) + " is interior; another face would make it non-manifold";
    std::vector<Dart> border_in;
    for (Dart d : CGAL_ext::halfedges_around_target(halfedge(v), *this))
      if (is_border(d))
        border_in.push_back(d);
    for (std::size_t k = 0; k < border_in.size(); ++k)
      site.fans[i].push_back(Border_fan{next(border_in[k]), border_in[(k + 1) % border_in.size()]});
  }
  // Existing edges of the face.
  site.existing.assign(n, Dart());
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex_index a = vs[i], b = vs[(i + 1) % n];
    if (is_isolated(b))
      continue;
    for (Dart d : CGAL_ext::halfedges_around_target(halfedge(b), *this)) {
      if (source(d) != a)
        continue;
      if (!is_border(edge(d)))
        return "edge (" + name(a) + ", " + name(b) + ") already has two faces";
      site.existing[i] = is_border(d) ? d : opposite(d);
      break;
    }
  }
  // The new corner at vs[i] lies between the edges in = (vs[i-1], vs[i]) and
  // out = (vs[i], vs[i+1]). Each existing one is a border edge of some fan.
  for (std::size_t i = 0; i < n; ++i) {
    const Dart in = site.existing[(i + n - 1) % n], out = site.existing[i];
    if (in.is_valid() && out.is_valid() && site.fans[i].size() > 1 &&
        fan_containing(site.fans[i], edge(in)) == fan_containing(site.fans[i], edge(out)))
      return "the face would close one fan of vertex " + name(vs[i]) + " while others remain (non-manifold vertex)";
  }
  return {};
}

// The face's halfedges, taking over existing border halfedges; the new
// border darts at each vertex into `new_border_out` and `new_border_in`.
template <class P>
std::vector<Halfedge_index> Mobius_mesh<P>::add_face_halfedges(Face_index f, const std::vector<Vertex_index>& vs,
                                                               const std::vector<Dart>& existing,
                                                               std::vector<Dart>& new_border_out,
                                                               std::vector<Dart>& new_border_in)
{
  const std::size_t n = vs.size();
  std::vector<Halfedge_index> face_halfedges(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex_index a = vs[i], b = vs[(i + 1) % n];
    if (!existing[i].is_valid()) {
      const Edge_index e = add_edge(b, a);
      face_halfedges[i] = halfedge(e, 0);
      // The border halfedge 2e+1 runs b -> a: outgoing at b, incoming at a.
      new_border_out[(i + 1) % n] = dart(halfedge(e, 1));
      new_border_in[i] = dart(halfedge(e, 1));
      continue;
    }
    const Halfedge_index g = existing[i].halfedge();
    // The old face runs along the edge a -> b as well: a Möbius connection.
    const bool mobius = h_target_[opposite_halfedge(g).idx()] == b;
    h_target_[g.idx()] = b;
    set_mobius(edge(g), mobius);
    face_halfedges[i] = g;
  }
  for (std::size_t i = 0; i < n; ++i) {
    h_face_[face_halfedges[i].idx()] = f;
    set_next(dart(face_halfedges[i]), dart(face_halfedges[(i + 1) % n]));
  }
  f_halfedge_[f.idx()] = face_halfedges[0];
  return face_halfedges;
}

template <class P>
template <class VertexRange>
typename Mobius_mesh<P>::Face_index
Mobius_mesh<P>::add_face(const VertexRange& vertex_range, std::string* why)
{
  const std::vector<Vertex_index> vs(std::begin(vertex_range), std::end(vertex_range));
  const std::size_t n = vs.size();
  Face_site site;
  if (std::string reason = check_face_site(vs, site); !reason.empty()) {
    if (why)
      *why = reason;
    return null_face();
  }
  const std::vector<Dart>& existing = site.existing;
  const Face_index f = add_face_record();
  std::vector<Dart> new_border_out(n), new_border_in(n); // new border darts at vs[i]
  const std::vector<Halfedge_index> face_halfedges =
    add_face_halfedges(f, vs, existing, new_border_out, new_border_in);

  // Relink the border at each vertex: merge the new corner with the fans it
  // touches, walking each fan in the direction that agrees with the new
  // face, then link the fans in a cycle.
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Border_fan>& list = site.fans[i];
    const std::size_t ip = (i + n - 1) % n;
    // Going backward from the new corner crosses `in`, forward crosses `out`.
    const Edge_index e_in = edge(dart(face_halfedges[ip])), e_out = edge(dart(face_halfedges[i]));
    Border_fan merged{new_border_out[i], new_border_in[i]};
    auto take = [&](Edge_index e, bool before) {
      const std::size_t k = fan_containing(list, e);
      Border_fan x = list[k];
      list.erase(list.begin() + std::ptrdiff_t(k));
      // A fan before the corner must end at e; one after it must start at e.
      if (before != (edge(x.last_in) == e))
        x = Border_fan{x.last_in.flipped(), x.first_out.flipped()};
      return x;
    };
    if (existing[ip].is_valid() && existing[i].is_valid() && fan_containing(list, e_in) == fan_containing(list, e_out)) {
      list.erase(list.begin() + std::ptrdiff_t(fan_containing(list, e_in))); // the fan closes
      merged = Border_fan{};
    } else {
      if (existing[ip].is_valid())
        merged.first_out = take(e_in, true).first_out;
      if (existing[i].is_valid())
        merged.last_in = take(e_out, false).last_in;
    }
    if (merged.first_out.is_valid())
      list.push_back(merged);
    for (std::size_t k = 0; k < list.size(); ++k)
      set_next(list[k].last_in, list[(k + 1) % list.size()].first_out);
    v_halfedge_[vs[i].idx()] = list.empty() ? dart(face_halfedges[ip]) : list.front().last_in;
  }
  return f;
}

template <class P>
typename Mobius_mesh<P>::Join_offsets Mobius_mesh<P>::join(const Mobius_mesh& o)
{
  internal::check_mesh_size("joining two meshes",
                            grown_size(o.num_vertices(), o.num_edges(), o.num_faces()));
  const Join_offsets off{num_vertices(), num_edges(), num_faces()};
  const size_type hoff = 2 * off.edges;
  auto shift_dart = [hoff](Dart d) {
    return d.is_valid() ? Dart::from_bits(d.bits() + 2 * hoff) : d;
  };
  // Each array grows once (resize leaves the new slots unwritten) and is
  // written in one pass: push_back would copy it again at every doubling.
  auto append = [](auto& to, const auto& from, auto shift) {
    const std::size_t n = to.size();
    to.resize(n + from.size());
    std::transform(from.begin(), from.end(), to.begin() + std::ptrdiff_t(n), shift);
  };
  append(v_halfedge_, o.v_halfedge_, shift_dart);
  append(h_target_, o.h_target_, [&off](Vertex_index v) { return Vertex_index(size_type(v.idx() + off.vertices)); });
  append(h_next_, o.h_next_, shift_dart);
  append(h_prev_, o.h_prev_, shift_dart);
  append(h_face_, o.h_face_,
         [&off](Face_index f) { return f.is_valid() ? Face_index(size_type(f.idx() + off.faces)) : f; });
  e_mobius_.insert(e_mobius_.end(), o.e_mobius_.begin(), o.e_mobius_.end());
  mobius_edges_ = (mobius_edges_ == unknown_count || o.mobius_edges_ == unknown_count) ? unknown_count
                                                                                       : mobius_edges_ + o.mobius_edges_;
  append(f_halfedge_, o.f_halfedge_, [hoff](Halfedge_index h) { return Halfedge_index(size_type(h.idx() + hoff)); });
  vprops_.append(o.vprops_);
  hprops_.append(o.hprops_);
  eprops_.append(o.eprops_);
  fprops_.append(o.fprops_);
  points_ = Property_map<Vertex_index, Point>(vprops_.template get<Point>("v:point"));
  find_removal_marks(removed_vertices_.count + o.removed_vertices_.count,
                     removed_edges_.count + o.removed_edges_.count, removed_faces_.count + o.removed_faces_.count);
  if (recycle_)
    list_free_slots(); // the other mesh's removed slots too, whether it recycled or not
  return off;
}

template <class P>
void Mobius_mesh<P>::reverse_border_halfedge(Halfedge_index g)
{
  // What was the dart (g, unflipped) is now (g, flipped), also where g is
  // its own neighbour (the border of a loop).
  const Dart d = dart(g), turned = d.flipped();
  auto renamed = [&](Dart x) { return x.halfedge() != g ? x : (x == d ? turned : d); };
  const Dart old_next = renamed(next(d)), old_prev = renamed(prev(d));
  h_target_[g.idx()] = source(d);
  set_next(turned, old_next);
  set_next(old_prev, turned);
}

template <class P>
void Mobius_mesh<P>::reverse_face_orientation(Face_index f)
{
  std::vector<Halfedge_index> hs;
  std::vector<Vertex_index> sources;
  for (Dart d : CGAL_ext::halfedges_around_face(halfedge(f), *this)) {
    hs.push_back(d.halfedge());
    sources.push_back(source(d));
  }
  // Border edges stay non-Möbius: their border halfedges turn round too.
  std::vector<Halfedge_index> reversed = hs;
  for (Halfedge_index h : hs) {
    const Halfedge_index g = opposite_halfedge(h);
    if (is_border(g)) {
      reverse_border_halfedge(g);
      reversed.push_back(g);
    }
  }
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const size_type h = hs[i].idx();
    h_target_[h] = sources[i];
    std::swap(h_next_[h], h_prev_[h]);
  }
  // Corner values stay at their vertices (the corner slots move).
  if (!hprops_.arrays().empty()) {
    std::vector<std::uint32_t> cycle(hs.size());
    std::transform(hs.begin(), hs.end(), cycle.begin(), [](Halfedge_index h) { return h.idx(); });
    for (const auto& array : hprops_.arrays())
      array->reverse_face(cycle.data(), cycle.size());
  }
  for (Halfedge_index h : hs) {
    const Face_index other = face(opposite_halfedge(h));
    if (other.is_valid() && other != f)
      set_mobius(edge(h), !is_mobius(edge(h)));
  }
  // A vertex dart on a turned halfedge names the same walk with the other
  // bit (once per vertex: a face may visit one twice).
  std::sort(sources.begin(), sources.end());
  sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
  for (std::size_t i = 0; i < sources.size(); ++i) {
    Dart& vd = v_halfedge_[sources[i].idx()];
    if (std::find(reversed.begin(), reversed.end(), vd.halfedge()) != reversed.end())
      vd = vd.flipped();
  }
}

template <class P>
void Mobius_mesh<P>::collect_garbage(Garbage_collection_maps& maps)
{
  // New indices in order of the old: kept[i] is the old index of element i.
  auto renumber = [](size_type n, const Removal_marks& marks, auto& new_of_old) {
    using I = typename std::decay_t<decltype(new_of_old)>::value_type;
    std::vector<std::uint32_t> kept;
    kept.reserve(n - marks.count);
    new_of_old.assign(n, I());
    for (size_type i = 0; i < n; ++i)
      if (!marks.is_marked(i)) {
        new_of_old[i] = I(size_type(kept.size()));
        kept.push_back(i);
      }
    return kept;
  };
  const std::vector<std::uint32_t> kept_v = renumber(num_vertices(), removed_vertices_, maps.vertices);
  const std::vector<std::uint32_t> kept_e = renumber(num_edges(), removed_edges_, maps.edges);
  const std::vector<std::uint32_t> kept_f = renumber(num_faces(), removed_faces_, maps.faces);
  drop_removal_marks();

  // Every element moves to a lower or equal index, so the arrays compact in place.
  std::vector<std::uint32_t> kept_h(2 * kept_e.size());
  for (std::size_t e = 0; e < kept_e.size(); ++e)
    for (unsigned k = 0; k < 2; ++k) {
      const size_type from = internal::dart_encoding::halfedge_of_edge(kept_e[e], k);
      const size_type to = internal::dart_encoding::halfedge_of_edge(size_type(e), k);
      kept_h[to] = from;
      h_target_[to] = maps(h_target_[from]);
      h_next_[to] = maps(h_next_[from]);
      h_prev_[to] = maps(h_prev_[from]);
      h_face_[to] = maps(h_face_[from]);
    }
  for (std::size_t e = 0; e < kept_e.size(); ++e)
    e_mobius_[e] = e_mobius_[kept_e[e]];
  for (std::size_t v = 0; v < kept_v.size(); ++v)
    v_halfedge_[v] = maps(v_halfedge_[kept_v[v]]);
  for (std::size_t f = 0; f < kept_f.size(); ++f)
    f_halfedge_[f] = maps(f_halfedge_[kept_f[f]]);

  v_halfedge_.resize(kept_v.size());
  h_target_.resize(kept_h.size());
  h_next_.resize(kept_h.size());
  h_prev_.resize(kept_h.size());
  h_face_.resize(kept_h.size());
  e_mobius_.resize(kept_e.size());
  recount_mobius_edges();
  f_halfedge_.resize(kept_f.size());
  vprops_.compact(kept_v);
  hprops_.compact(kept_h);
  eprops_.compact(kept_e);
  fprops_.compact(kept_f);
}

template <class P>
std::string Mobius_mesh<P>::validity_report() const
{
  std::string report = check_sizes();
  if (report.empty())
    report = check_halfedge_links();
  if (report.empty())
    report = check_face_cycles();
  if (report.empty())
    report = check_vertex_fans();
  return report;
}

template <class P>
std::string Mobius_mesh<P>::check_sizes() const
{
  const size_type nh = num_halfedges();
  if (h_next_.size() != nh || h_prev_.size() != nh || h_face_.size() != nh || nh != 2 * e_mobius_.size())
    return "connectivity arrays have inconsistent sizes";
  if (vprops_.size() != num_vertices() || hprops_.size() != nh || eprops_.size() != num_edges() ||
      fprops_.size() != num_faces())
    return "property arrays have inconsistent sizes";
  return std::string();
}

// Every link of a live halfedge names a live element, and the dart identities hold.
template <class P>
std::string Mobius_mesh<P>::check_halfedge_links() const
{
  std::ostringstream out;
  auto live = [&](auto x) { return is_valid(x) && !is_removed(x); };
  for (Halfedge_index h : halfedges()) {
    const size_type i = h.idx();
    if (!live(h_target_[i]))
      return (out << h << " has an invalid or removed target", out.str());
    if (!live(h_next_[i].halfedge()) || !live(h_prev_[i].halfedge()))
      return (out << h << " has an invalid or removed next or prev link", out.str());
    if (h_face_[i].is_valid() && !live(h_face_[i]))
      return (out << h << " has an invalid or removed face", out.str());
  }
  for (Edge_index e : edges()) {
    const Halfedge_index h0 = halfedge(e, 0), h1 = halfedge(e, 1);
    if (is_border(h0) && is_border(h1))
      return (out << e << " has no face", out.str());
    if (is_mobius(e) && (is_border(h0) || is_border(h1)))
      return (out << "border " << e << " is marked Möbius", out.str());
  }
  for (Halfedge_index h : halfedges()) {
    for (bool flipped : {false, true}) {
      const Dart d(h, flipped);
      if (next(prev(d)) != d)
        return (out << "next(prev(" << d << ")) != " << d, out.str());
      if (prev(next(d)) != d)
        return (out << "prev(next(" << d << ")) != " << d, out.str());
      if (opposite(opposite(d)) != d)
        return (out << "opposite(opposite(" << d << ")) != " << d, out.str());
      if (source(d) == target(d) && !is_lone_border_loop(edge(d)))
        return (out << d << " is a loop at " << target(d) << " that is not a border loop of its own", out.str());
      if (target(opposite(d)) != source(d))
        return (out << "target(opposite(" << d << ")) != source(" << d << ")", out.str());
      if (source(next(d)) != target(d))
        return (out << "source(next(" << d << ")) != target(" << d << ")", out.str());
      if (face(next(d)) != face(d))
        return (out << "next(" << d << ") lies in another face", out.str());
      if (!is_border(d) && next(d).is_flipped() != d.is_flipped())
        return (out << "the cycle of face " << face(d) << " mixes orientations at " << d, out.str());
    }
  }
  return std::string();
}

// Each face's cycle holds exactly the halfedges that name it.
template <class P>
std::string Mobius_mesh<P>::check_face_cycles() const
{
  std::ostringstream out;
  std::vector<size_type> face_size(num_faces(), 0);
  for (Halfedge_index h : halfedges())
    if (h_face_[h.idx()].is_valid())
      ++face_size[h_face_[h.idx()].idx()];
  for (Face_index f : faces()) {
    const Halfedge_index h = f_halfedge_[f.idx()];
    if (!is_valid(h) || is_removed(h) || face(h) != f)
      return (out << f << " has a halfedge of another face", out.str());
    size_type k = 0;
    for (Dart d : CGAL_ext::halfedges_around_face(dart(h), *this)) {
      (void)d;
      if (++k > face_size[f.idx()])
        break;
    }
    if (k != face_size[f.idx()])
      return (out << "the cycle of " << f << " has " << k << " halfedges, but " << face_size[f.idx()]
                  << " halfedges name it",
              out.str());
    if (k < 3)
      return (out << f << " has fewer than three sides", out.str());
  }
  return std::string();
}

// One fan per vertex, seen from its stored dart (a border vertex's stored dart
// need not be a border dart: CGAL's Euler::remove_face() leaves it as it was).
template <class P>
std::string Mobius_mesh<P>::check_vertex_fans() const
{
  std::ostringstream out;
  std::vector<size_type> incident(num_vertices(), 0);
  for (Edge_index e : edges()) {
    ++incident[vertex(e, 0).idx()];
    ++incident[vertex(e, 1).idx()];
  }
  for (Vertex_index v : vertices()) {
    const size_type i = v.idx();
    const Dart d = v_halfedge_[i];
    if (!d.is_valid()) {
      if (incident[i] != 0)
        return (out << v << " has edges but no halfedge", out.str());
      continue;
    }
    if (!is_valid(d) || is_removed(d.halfedge()) || target(d) != v)
      return (out << "halfedge(" << v << ") does not end at it", out.str());
    size_type k = 0, border = 0;
    for (Dart c : CGAL_ext::halfedges_around_target(d, *this)) {
      if (is_border(c))
        ++border;
      if (++k > incident[i])
        break;
    }
    if (k != incident[i])
      return (out << v << " has " << incident[i] << " edges but its fan reaches " << k
                  << " (non-manifold vertex)",
              out.str());
    if (border > 1)
      return (out << v << " has " << border << " border gaps (non-manifold vertex)", out.str());
  }
  return std::string();
}

} // namespace CGAL_ext

namespace std {
/// Hashes mesh indices, so that they key `std::unordered_map` and `std::unordered_set`.
template <class Tag>
struct hash<CGAL_ext::Index<Tag>>
{
  /// `hash_value(i)`.
  std::size_t operator()(CGAL_ext::Index<Tag> i) const { return hash_value(i); }
};
/// Hashes darts, so that they key `std::unordered_map` and `std::unordered_set`.
template <>
struct hash<CGAL_ext::Dart>
{
  /// `hash_value(d)`.
  std::size_t operator()(CGAL_ext::Dart d) const { return hash_value(d); }
};
} // namespace std

#endif // CGAL_EXT_MOBIUS_MESH_H
