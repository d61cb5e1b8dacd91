// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The exceptions CGAL_ext throws for bad input. Bad input is not a
// programming error, so it is reported by exceptions that say what is wrong
// and where, never by assertions.

#ifndef CGAL_EXT_EXCEPTIONS_H
#define CGAL_EXT_EXCEPTIONS_H

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {

namespace internal {

// Ids in an error message: the first few, then how many in all.
inline std::string join_ids(const std::vector<std::size_t>& ids, const char* prefix = "", std::size_t max_shown = 8)
{
  std::string s;
  for (std::size_t i = 0; i < ids.size() && i < max_shown; ++i)
    s += (i ? ", " : "") + std::string(prefix) + std::to_string(ids[i]);
  if (ids.size() > max_shown)
    s += ", ... (" + std::to_string(ids.size()) + " in all)";
  return s;
}

} // namespace internal

/// Base class of every exception CGAL_ext throws.
class Error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// A parameter value is out of its domain (e.g. a negative or NaN tolerance).
class Parameter_error : public Error
{
public:
  using Error::Error;
};

/// A mesh, or a result, with more elements than the 32-bit indices of
/// `Mobius_mesh` hold (see `internal::check_mesh_size()` for the limits), or
/// a search structure with more sample triangles than it numbers
/// (`Limit_surface::closest_point()`). Thrown before the elements are
/// allocated; `element()` says of what (below), `count()` how many there
/// would be (computed in 64 bits), `limit()` the most there may be.
class Size_error : public Parameter_error
{
public:
  /// An error with the text `message`, about `count` elements of kind
  /// `element` where at most `limit` fit.
  Size_error(const std::string& message, std::string element, unsigned long long count, unsigned long long limit)
    : Parameter_error(message), element_(std::move(element)), count_(count), limit_(limit)
  {}
  /// The kind of element that does not fit: `"vertices"`, `"edges"`,
  /// `"faces"`, `"triangles"` (a closest-point search structure's) or
  /// `"corner normal values"` (`offset_mesh()`'s); `"bytes"` where the
  /// memory an operation would need is more than it may take (`maximum_memory`).
  const std::string& element() const { return element_; }
  /// How many elements there would be.
  unsigned long long count() const { return count_; }
  /// The most elements of that kind there may be.
  unsigned long long limit() const { return limit_; }

private:
  std::string element_;
  unsigned long long count_;
  unsigned long long limit_;
};

/// A polygon soup that does not describe a 2-manifold polygon mesh.
class Soup_error : public Error
{
public:
  /// What is wrong with the soup.
  enum class Kind {
    index_out_of_range,  ///< a polygon names a point that does not exist
    degenerate_polygon,  ///< a polygon has fewer than three vertices
    repeated_vertex,     ///< a polygon visits a vertex twice
    non_manifold_edge,   ///< an edge is shared by three or more polygons
    non_manifold_vertex, ///< the polygons around a vertex form several fans
    non_finite_point     ///< a coordinate is infinite or NaN
  };

  /// An error of kind `kind` with the text `message`, naming the offending
  /// polygons and points by their indices in the soup.
  Soup_error(Kind kind, std::string message, std::vector<std::size_t> polygons,
             std::vector<std::size_t> vertices)
    : Error(std::move(message)), kind_(kind), polygons_(std::move(polygons)), vertices_(std::move(vertices))
  {}

  /// What is wrong with the soup.
  Kind kind() const { return kind_; }
  /// Indices of the offending polygons, in the order of the soup.
  const std::vector<std::size_t>& polygons() const { return polygons_; }
  /// Indices of the offending points.
  const std::vector<std::size_t>& vertices() const { return vertices_; }

private:
  Kind kind_;
  std::vector<std::size_t> polygons_;
  std::vector<std::size_t> vertices_;
};

/// A file that cannot be read or written, or whose content is malformed.
/// `line()` is 0 where no line can be named. Where the file was read but its
/// polygons do not form a 2-manifold, `soup_kind()` tells which `Soup_error` it was.
class IO_error : public Error
{
public:
  /// An error in `file` at `line` (0: no line); its text is
  /// `file:line: what` (`file: what` without a line).
  IO_error(const std::string& file, std::size_t line, const std::string& what,
           std::optional<Soup_error::Kind> soup_kind = std::nullopt)
    : Error(file + (line ? ":" + std::to_string(line) : std::string()) + ": " + what), file_(file), line_(line),
      soup_kind_(soup_kind)
  {}
  /// The name of the file, as given to the reader or writer.
  const std::string& file() const { return file_; }
  /// The line (1-based) of the file where the error is, 0 where none can be named.
  std::size_t line() const { return line_; }
  /// The kind of `Soup_error` the file's polygons gave, if that was the error.
  std::optional<Soup_error::Kind> soup_kind() const { return soup_kind_; }

private:
  std::string file_;
  std::size_t line_;
  std::optional<Soup_error::Kind> soup_kind_;
};

/// A merge of mesh borders that cannot be done; `vertices()` names the
/// offending vertices of the input (two-mesh merges number the second mesh's
/// vertices after the first's).
class Merge_error : public Error
{
public:
  /// Why the merge cannot be done.
  enum class Kind {
    non_manifold_edge,   ///< three or more border edges would be glued into one edge
    non_manifold_vertex, ///< the glue would give a vertex several fans
    collapsed_face,      ///< the glue would identify two vertices of one face
    mismatched_chains,   ///< the two chosen borders do not correspond (length, vertex pairs)
    not_a_border         ///< a dart given as a border is not one
  };
  /// An error of kind `kind` with the text `message`, naming the offending vertices.
  Merge_error(Kind kind, std::string message, std::vector<std::size_t> vertices)
    : Error(std::move(message)), kind_(kind), vertices_(std::move(vertices))
  {}
  /// Why the merge cannot be done.
  Kind kind() const { return kind_; }
  /// Indices of the offending vertices of the input.
  const std::vector<std::size_t>& vertices() const { return vertices_; }

private:
  Kind kind_;
  std::vector<std::size_t> vertices_;
};

/// A seam map (which border halfedges of a cut mesh are glued, and how) that
/// is inconsistent or whose gluing is not a 2-manifold.
class Seam_error : public Error
{
public:
  using Error::Error;
};

/// An Euler operation refused because it would not leave a valid 2-manifold
/// mesh (the matching `can_*()` function or the link condition said no); the
/// mesh is unchanged.
class Euler_error : public Error
{
public:
  using Error::Error;
};

} // namespace CGAL_ext

#endif // CGAL_EXT_EXCEPTIONS_H
