// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reads a PLY file (ASCII, binary little or big endian) in one pass into a
// polygon soup: the x, y, z of the `vertex` element (and its texture
// coordinates and normals, for corner channels) and the index list
// `vertex_indices` (or `vertex_index`) of the `face` element (and its
// per-corner `texcoord` list), with any of PLY's integer types for the lists,
// and the other scalar properties of the `vertex` element as columns of
// values; other elements and properties are read over. Element counts are
// believed only as far as the bytes after the header can hold them.

#ifndef CGAL_EXT_IO_INTERNAL_PLY_READER_H
#define CGAL_EXT_IO_INTERNAL_PLY_READER_H

#include <CGAL_ext/IO/internal/Corner_data.h>
#include <CGAL_ext/IO/internal/Text_scanning.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace IO {
namespace internal {

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline bool parse_ply_type(Token name, Ply_type& type)
{
  static const struct
  {
    const char* name;
    Ply_type type;
  } types[] = {{"char", Ply_type::int8},     {"int8", Ply_type::int8},       {"uchar", Ply_type::uint8},
               {"uint8", Ply_type::uint8},   {"short", Ply_type::int16},     {"int16", Ply_type::int16},
               {"ushort", Ply_type::uint16}, {"uint16", Ply_type::uint16},   {"int", Ply_type::int32},
               {"int32", Ply_type::int32},   {"uint", Ply_type::uint32},     {"uint32", Ply_type::uint32},
               {"float", Ply_type::float32}, {"float32", Ply_type::float32}, {"double", Ply_type::float64},
               {"float64", Ply_type::float64}};
  for (const auto& t : types)
    if (name == t.name) {
      type = t.type;
      return true;
    }
  return false;
}

inline std::size_t ply_size(Ply_type t)
{
  static const std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[int(t)];
}

inline bool ply_is_integral(Ply_type t) { return t != Ply_type::float32 && t != Ply_type::float64; }

struct Ply_property
{
  std::string name;
  bool is_list = false;
  Ply_type count_type = Ply_type::uint8; // lists only
  Ply_type type = Ply_type::float32;     // the value, or a list's items
};

// The values of one scalar property of the `vertex` element other than x,
// y and z, in the order of the vertices, with the PLY type the file gives it
// (every PLY type's values are doubles exactly).
struct Ply_vertex_column
{
  std::string name;
  Ply_type type = Ply_type::float32;
  std::vector<double> values;
};

struct Ply_element
{
  std::string name;
  unsigned long long count = 0;
  std::size_t line = 0; // of its header line
  std::vector<Ply_property> properties;
};

enum class Ply_format { ascii, binary_little_endian, binary_big_endian };

struct Ply_header
{
  Ply_format format = Ply_format::ascii;
  std::vector<Ply_element> elements;
  std::size_t data_begin = 0; // offset of the data in the file
  std::size_t lines = 0;      // lines of the header
};

// One property line: `property type name` or `property list count_type item_type name`.
inline Ply_property parse_ply_property(const std::string& filename, std::size_t line, const std::vector<Token>& tok)
{
  auto fail = [&](const std::string& what) { throw IO_error(filename, line, what); };
  Ply_property property;
  property.is_list = tok.size() > 1 && tok[1] == "list";
  const std::size_t name_at = property.is_list ? 4 : 2;
  if (tok.size() != name_at + 1)
    fail("expected 'property type name' or 'property list count_type item_type name'");
  if (property.is_list && !parse_ply_type(tok[2], property.count_type))
    fail("unknown PLY type '" + printable(tok[2]) + "'");
  if (property.is_list && !ply_is_integral(property.count_type))
    fail("a list's count needs an integer type, not '" + printable(tok[2]) + "'");
  if (!parse_ply_type(tok[name_at - 1], property.type))
    fail("unknown PLY type '" + printable(tok[name_at - 1]) + "'");
  property.name = tok[name_at].str();
  return property;
}

inline Ply_header read_ply_header(const std::string& filename, const std::string& text)
{
  Ply_header header;
  const char* const text_end = text.data() + text.size();
  const char* begin = text.data();
  std::vector<Token> tok;
  bool has_format = false;
  for (std::size_t line = 1;; ++line) {
    auto fail = [&](const std::string& what) { throw IO_error(filename, line, what); };
    const char* end = static_cast<const char*>(std::memchr(begin, '\n', std::size_t(text_end - begin)));
    if (end == nullptr)
    {
      if (line == 1)
        fail("not a PLY file: it does not start with a line 'ply'");
      throw IO_error(filename, 0, "the header has no 'end_header' line");
    }
    split_tokens(begin, end, tok);
    begin = end + 1;
    if (line == 1) {
      if (tok.size() != 1 || !(tok[0] == "ply"))
        fail("not a PLY file: it does not start with a line 'ply'");
    } else if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") {
    } else if (tok[0] == "format") {
      if (tok.size() != 3 || !(tok[2] == "1.0"))
        fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (tok[1] == "ascii")
        header.format = Ply_format::ascii;
      else if (tok[1] == "binary_little_endian")
        header.format = Ply_format::binary_little_endian;
      else if (tok[1] == "binary_big_endian")
        header.format = Ply_format::binary_big_endian;
      else
        fail("unknown PLY format '" + printable(tok[1]) + "'");
      has_format = true;
    } else if (tok[0] == "element") {
      long long count = 0;
      if (tok.size() != 3 || !parse_integer(tok[2], count) || count < 0)
        fail("expected 'element name count'");
      header.elements.push_back(Ply_element{tok[1].str(), (unsigned long long)count, line, {}});
    } else if (tok[0] == "property") {
      if (header.elements.empty())
        fail("a property before any element");
      header.elements.back().properties.push_back(parse_ply_property(filename, line, tok));
    } else if (tok[0] == "end_header" && tok.size() == 1) {
      if (!has_format)
        fail("the header has no 'format' line");
      header.data_begin = std::size_t(begin - text.data());
      header.lines = line;
      return header;
    } else {
      fail("unknown PLY header line '" + printable(tok[0]) + "'");
    }
  }
}

// The values of a PLY body one by one, as doubles (every PLY type fits).
class Ply_values
{
public:
  Ply_values(Ply_format format, const char* begin, const char* end, std::size_t line)
    : ascii_(format == Ply_format::ascii), bytes_(begin, end, format == Ply_format::binary_big_endian),
      p_(begin), end_(end), line_(line)
  {}
  bool is_ascii() const { return ascii_; }
  std::size_t remaining() const { return ascii_ ? std::size_t(end_ - p_) : bytes_.remaining(); }
  // The line of the next value (ASCII only; 0 in binary files).
  std::size_t line()
  {
    if (!ascii_)
      return 0;
    skip_space();
    return line_;
  }

  // Reads one value of `type`; false at the end of the data or, in ASCII, on
  // a token that is not a number of that type.
  bool read(Ply_type type, double& value)
  {
    if (ascii_)
      return read_text(type, value);
    if (!bytes_.has(ply_size(type)))
      return false;
    switch (type) {
      case Ply_type::int8: value = bytes_.read<std::int8_t>(); break;
      case Ply_type::uint8: value = bytes_.read<std::uint8_t>(); break;
      case Ply_type::int16: value = bytes_.read<std::int16_t>(); break;
      case Ply_type::uint16: value = bytes_.read<std::uint16_t>(); break;
      case Ply_type::int32: value = bytes_.read<std::int32_t>(); break;
      case Ply_type::uint32: value = bytes_.read<std::uint32_t>(); break;
      case Ply_type::float32: value = bytes_.read<float>(); break;
      case Ply_type::float64: value = bytes_.read<double>(); break;
    }
    return true;
  }
  // The last token read (ASCII), for error messages.
  std::string last_token() const { return printable(token_); }
  // How many bytes follow what was read, blanks and line ends at the very
  // end left out: a file may end in a line end, but not in more data than
  // its header declares.
  std::size_t bytes_after_data() const
  {
    const char* last = end_;
    const char* const at = end_ - remaining();
    while (last != at && (is_blank(last[-1]) || last[-1] == '\n' || last[-1] == '\r'))
      --last;
    return std::size_t(last - at);
  }

private:
  void skip_space()
  {
    for (; p_ != end_ && (is_blank(*p_) || *p_ == '\n'); ++p_)
      line_ += *p_ == '\n' ? 1 : 0;
  }
  bool read_text(Ply_type type, double& value)
  {
    skip_space();
    const char* stop = p_;
    while (stop != end_ && !is_blank(*stop) && *stop != '\n')
      ++stop;
    token_ = Token{p_, stop};
    p_ = stop;
    if (token_.empty())
      return false;
    if (ply_is_integral(type)) {
      static const double limits[][2] = {{-128, 127},   {0, 255}, {-32768, 32767}, {0, 65535}, {-2147483648.0, 2147483647.0},
                                         {0, 4294967295.0}};
      long long n = 0;
      if (!parse_integer(token_, n) || double(n) < limits[int(type)][0] || double(n) > limits[int(type)][1])
        return false;
      value = double(n);
      return true;
    }
    // Any double, "nan" and "inf" included: only x, y and z must be finite.
    const char* first = token_.begin + (*token_.begin == '+' ? 1 : 0);
    const auto [at, error] = std::from_chars(first, stop, value);
    return error == std::errc() && at == stop;
  }

  bool ascii_;
  Byte_reader bytes_;
  const char* p_;
  const char* end_;
  std::size_t line_;
  Token token_{nullptr, nullptr};
};

// The fewest bytes one item of `element` takes (each ASCII value needs a
// digit and a separator).
inline std::size_t ply_min_bytes(const Ply_element& element, bool ascii)
{
  std::size_t bytes = 0;
  for (const Ply_property& p : element.properties)
    bytes += ascii ? 2 : ply_size(p.is_list ? p.count_type : p.type);
  return bytes;
}

// Reads one item of `element`; `values` receives its scalar values (by
// property), `list` the items of the list property numbered `list_at` and
// `second` those of the one numbered `second_at` (none: std::size_t(-1)).
inline void read_ply_item(const std::string& filename, const Ply_element& element, unsigned long long item,
                          Ply_values& in, std::vector<double>& values, std::size_t list_at,
                          std::vector<double>& list, std::size_t second_at, std::vector<double>& second)
{
  const std::string where = "'" + printable(element.name) + "' " + std::to_string(item);
  auto fail = [&](const std::string& what) { throw IO_error(filename, in.line(), what); };
  for (std::size_t k = 0; k < element.properties.size(); ++k) {
    const Ply_property& p = element.properties[k];
    const std::size_t line = in.line();
    double value = 0;
    if (!in.read(p.is_list ? p.count_type : p.type, value))
      throw IO_error(filename, line,
                     !in.is_ascii() || in.last_token().empty()
                       ? "the file ends in " + where
                       : "property '" + printable(p.name) + "' of " + where + ": '" + in.last_token() +
                           "' is not a value of its type");
    values[k] = value;
    if (!p.is_list)
      continue;
    if (value < 0)
      fail("the list '" + printable(p.name) + "' of " + where + " has a negative length");
    check_count_fits(filename, line, "items in the list '" + printable(p.name) + "' of " + where,
                     (unsigned long long)value, in.is_ascii() ? 2 : ply_size(p.type), in.remaining());
    std::vector<double>* kept = k == list_at ? &list : k == second_at ? &second : nullptr;
    if (kept)
      kept->resize(std::size_t(value));
    for (std::size_t i = 0; i < std::size_t(value); ++i) {
      double x = 0;
      if (!in.read(p.type, x))
        throw IO_error(filename, in.line(), "item " + std::to_string(i) + " of the list '" + printable(p.name) +
                                              "' of " + where + " is not a value of its type");
      if (kept)
        (*kept)[i] = x;
    }
  }
}

inline std::size_t ply_property_at(const Ply_element& element, const char* name, bool is_list)
{
  for (std::size_t k = 0; k < element.properties.size(); ++k)
    if (element.properties[k].name == name && element.properties[k].is_list == is_list)
      return k;
  return std::size_t(-1);
}

// The properties of the `vertex` element beside x, y, z that become corner
// channels: texture coordinates (the first pair found of s t, u v,
// texture_u texture_v) and normals (nx ny nz); `none` where absent.
struct Ply_vertex_values
{
  static constexpr std::size_t none = std::size_t(-1);
  std::size_t uv[2] = {none, none};
  std::size_t normal[3] = {none, none, none};

  explicit Ply_vertex_values(const Ply_element& vertex)
  {
    static const char* const pairs[][2] = {{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}};
    for (const auto& pair : pairs) {
      const std::size_t a = ply_property_at(vertex, pair[0], false), b = ply_property_at(vertex, pair[1], false);
      if (a != none && b != none) {
        uv[0] = a, uv[1] = b;
        break;
      }
    }
    const std::size_t n[3] = {ply_property_at(vertex, "nx", false), ply_property_at(vertex, "ny", false),
                              ply_property_at(vertex, "nz", false)};
    if (n[0] != none && n[1] != none && n[2] != none)
      std::copy(n, n + 3, normal);
  }

  // Whether property k becomes a corner channel.
  bool uses(std::size_t k) const
  {
    return k != none && (k == uv[0] || k == uv[1] || k == normal[0] || k == normal[1] || k == normal[2]);
  }

  // Appends the values of one vertex item; false if one is not finite.
  bool add(const std::vector<double>& values, Read_corner_data& data) const
  {
    if (uv[0] != none && data.uv.corner_index.empty()) // not where faces gave theirs already
      data.uv.values.push_back({values[uv[0]], values[uv[1]]});
    if (normal[0] != none)
      data.normal.values.push_back({values[normal[0]], values[normal[1]], values[normal[2]]});
    for (std::size_t k : {uv[0], uv[1], normal[0], normal[1], normal[2]})
      if (k != none && !std::isfinite(values[k]))
        return false;
    return true;
  }
};

// The scalar properties of the `vertex` element other than x, y and z and
// those that become corner channels (any property of their names), as empty
// columns (the first of two properties of one name only).
inline std::vector<Ply_vertex_column> ply_vertex_columns(const Ply_element& element, const Ply_vertex_values& corners,
                                                         std::vector<std::size_t>& at)
{
  std::vector<Ply_vertex_column> columns;
  for (std::size_t k = 0; k < element.properties.size(); ++k) {
    const Ply_property& p = element.properties[k];
    const bool taken = std::any_of(columns.begin(), columns.end(),
                                   [&](const Ply_vertex_column& c) { return c.name == p.name; });
    const bool corner = std::any_of(element.properties.begin(), element.properties.end(), [&](const Ply_property& q) {
      return corners.uses(std::size_t(&q - element.properties.data())) && q.name == p.name;
    });
    if (p.is_list || p.name == "x" || p.name == "y" || p.name == "z" || taken || corner)
      continue;
    columns.push_back({p.name, p.type, {}});
    at.push_back(k);
  }
  return columns;
}

// Appends a face's `texcoord` list (u v for each of its `n` corners; an
// empty list: corners without a value) to the texture coordinates, a value
// per corner; the first face drops the per-vertex values read before (a
// face's own are the finer).
inline void add_face_texcoords(const std::string& filename, std::size_t line, unsigned long long item,
                               const std::vector<double>& texcoord, std::size_t n, Read_channel<2>& uv)
{
  if (!texcoord.empty() && texcoord.size() != 2 * n)
    throw IO_error(filename, line, "face " + std::to_string(item) + " has " + std::to_string(n) + " corners but " +
                                     std::to_string(texcoord.size()) + " texcoord values (u v per corner)");
  if (uv.corner_index.empty())
    uv.values.clear();
  if (texcoord.empty())
    uv.corner_index.resize(uv.corner_index.size() + n, no_corner_value);
  for (std::size_t c = 0; c < n && !texcoord.empty(); ++c) {
    if (!std::isfinite(texcoord[2 * c]) || !std::isfinite(texcoord[2 * c + 1]))
      throw IO_error(filename, line, "face " + std::to_string(item) + " has a texcoord that is not a finite number");
    if (uv.values.size() >= no_corner_value)
      throw IO_error(filename, line, "more texture coordinates than the mesh's 32-bit indices hold");
    uv.corner_index.push_back(std::uint32_t(uv.values.size()));
    uv.values.push_back({texcoord[2 * c], texcoord[2 * c + 1]});
  }
}

// Reads a PLY file (its whole content) into a polygon soup, and the
// vertices' texture coordinates and normals into `corners` (a value per
// point); returns the line of each point and polygon in ASCII files (none in
// binary ones). With `columns`, the other scalar properties of the vertices
// go there (not those that became corner channels).
template <class P>
Soup_lines read_ply(const std::string& filename, const std::string& text, std::vector<P>& points,
                    std::vector<std::vector<std::size_t>>& polygons, Read_corner_data& corners,
                    std::vector<Ply_vertex_column>* columns = nullptr)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  const Ply_header header = read_ply_header(filename, text);
  Ply_values in(header.format, text.data() + header.data_begin, text.data() + text.size(), header.lines + 1);
  Soup_lines lines;
  bool has_vertices = false;
  for (const Ply_element& element : header.elements) {
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    const std::size_t xyz[3] = {ply_property_at(element, "x", false), ply_property_at(element, "y", false),
                                ply_property_at(element, "z", false)};
    std::size_t list_at = ply_property_at(element, "vertex_indices", true);
    if (list_at == std::size_t(-1))
      list_at = ply_property_at(element, "vertex_index", true);
    if (is_vertex && (xyz[0] == std::size_t(-1) || xyz[1] == std::size_t(-1) || xyz[2] == std::size_t(-1)))
      throw IO_error(filename, element.line, "the 'vertex' element lacks an x, y or z property");
    if (is_face && (list_at == std::size_t(-1) || !ply_is_integral(element.properties[list_at].type)))
      throw IO_error(filename, element.line, "the 'face' element lacks an integer list 'vertex_indices'");
    has_vertices = has_vertices || is_vertex;
    if (element.properties.empty())
      continue; // nothing to read, however many
    check_count_fits(filename, element.line, "'" + printable(element.name) + "' elements", element.count,
                     ply_min_bytes(element, in.is_ascii()), in.remaining());
    const Ply_vertex_values vertex_values(element);
    std::vector<double> values(element.properties.size()), list, texcoord;
    std::vector<std::size_t> column_at;
    if (is_vertex && columns != nullptr)
      *columns = ply_vertex_columns(element, vertex_values, column_at);
    // Per-face texture coordinates (`texcoord`, u v per corner), a convention of several writers.
    const std::size_t texcoord_at = is_face ? ply_property_at(element, "texcoord", true) : std::size_t(-1);
    for (unsigned long long item = 0; item < element.count; ++item) {
      const std::size_t line = in.line();
      read_ply_item(filename, element, item, in, values, is_face ? list_at : std::size_t(-1), list, texcoord_at,
                    texcoord);
      if (is_vertex) {
        if (!std::isfinite(values[xyz[0]]) || !std::isfinite(values[xyz[1]]) || !std::isfinite(values[xyz[2]]))
          throw IO_error(filename, line, "vertex " + std::to_string(item) + " has a coordinate that is not a finite number");
        if (!vertex_values.add(values, corners))
          throw IO_error(filename, line, "vertex " + std::to_string(item) +
                                           " has a texture coordinate or normal that is not a finite number");
        points.emplace_back(FT(values[xyz[0]]), FT(values[xyz[1]]), FT(values[xyz[2]]));
        for (std::size_t c = 0; c < column_at.size(); ++c)
          (*columns)[c].values.push_back(values[column_at[c]]);
        if (line != 0)
          lines.point_lines.push_back(line);
      } else if (is_face) {
        std::vector<std::size_t> polygon(list.size());
        for (std::size_t c = 0; c < list.size(); ++c) {
          if (list[c] < 0)
            throw IO_error(filename, line, "face " + std::to_string(item) + " names vertex " +
                                             std::to_string((long long)list[c]) + "; indices start at 0");
          polygon[c] = std::size_t(list[c]);
        }
        if (texcoord_at != std::size_t(-1))
          add_face_texcoords(filename, line, item, texcoord, polygon.size(), corners.uv);
        polygons.push_back(std::move(polygon));
        if (line != 0)
          lines.polygon_lines.push_back(line);
      }
    }
  }
  if (!has_vertices)
    throw IO_error(filename, 0, "the header declares no 'vertex' element");
  if (const std::size_t extra = in.bytes_after_data())
    throw IO_error(filename, in.line(),
                   std::to_string(extra) + " bytes of data after the last element: the header's counts do not "
                                           "cover the file");
  corners.normal.per_vertex = true;
  // Texture coordinates per face corner where the faces have them, else per vertex.
  corners.uv.per_vertex = corners.uv.corner_index.empty();
  return lines;
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_PLY_READER_H
