// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the OBJ, OFF and PLY readers share: the whole file in memory, its
// lines and tokens, numbers parsed without locale or exceptions, binary
// values of either byte order, error text that is safe to print, and the
// check that a count in a header fits in the bytes that follow it.

#ifndef CGAL_EXT_IO_INTERNAL_TEXT_SCANNING_H
#define CGAL_EXT_IO_INTERNAL_TEXT_SCANNING_H

#include <CGAL_ext/Mobius_mesh/internal/Size_limits.h>
#include <CGAL_ext/exceptions.h>

#include <CGAL/IO/io.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace IO {
namespace internal {

inline std::string system_reason()
{
  return errno != 0 ? std::string(": ") + std::strerror(errno) : std::string();
}

// The longest file a reader takes: its text, its points and faces and the
// mesh built from them take several times its size, so a quarter of the
// memory available. Past it a file, or a pipe that never ends, is refused
// before the machine runs out of memory.
inline double longest_readable_file() { return CGAL_ext::internal::available_memory() / 4; }

inline IO_error file_too_long(const std::string& filename, double limit)
{
  return IO_error(filename, 0,
                  "is longer than " + std::to_string(static_cast<unsigned long long>(limit)) +
                    " bytes, the most a reader takes (a quarter of the memory available)");
}

// A stream that cannot tell its size (a pipe, a FIFO), copied through in
// blocks up to `limit` bytes.
inline std::string read_unsized_stream(std::ifstream& in, const std::string& filename, double limit)
{
  in.clear();
  std::string text;
  std::vector<char> block(1 << 16);
  while (in.read(block.data(), std::streamsize(block.size())) || in.gcount() > 0) {
    text.append(block.data(), std::size_t(in.gcount()));
    if (double(text.size()) > limit)
      throw file_too_long(filename, limit);
    if (in.eof())
      break;
  }
  return text;
}

// The whole file, up to `limit` bytes (else IO_error).
inline std::string read_whole_file(const std::string& filename, double limit = longest_readable_file())
{
  std::error_code ec;
  if (std::filesystem::is_directory(filename, ec))
    throw IO_error(filename, 0, "is a directory, not a file");
  errno = 0;
  std::ifstream in(filename, std::ios::binary);
  if (!in)
    throw IO_error(filename, 0, "cannot open the file for reading" + system_reason());
  // One bulk read of the whole file, far faster than stream iteration.
  std::string text;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (double(size) > limit)
    throw file_too_long(filename, limit);
  if (size > 0) {
    text.resize(std::size_t(size));
    in.read(&text[0], size);
  } else if (size < 0) { // not seekable (a pipe): copy it through
    text = read_unsized_stream(in, filename, limit);
  }
  if (in.bad())
    throw IO_error(filename, 0, "cannot read the file" + system_reason());
  return text;
}

// A decimal number as `operator>>(double&)` reads it (the way CGAL's readers
// read coordinates): no "nan", "inf" or hexadecimal forms, and finite.
inline bool parse_real(const std::string& token, double& value)
{
  if (token.empty())
    return false;
  for (char c : token)
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'))
      return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && std::isfinite(value);
}

// A float rounded from its decimal text, as OpenSubdiv's `sscanf("%f")` does.
inline bool parse_float(const std::string& token, float& value)
{
  double check = 0;
  if (!parse_real(token, check))
    return false;
  char* end = nullptr;
  value = std::strtof(token.c_str(), &end);
  return std::isfinite(value);
}

inline bool parse_integer(const std::string& token, long long& value)
{
  if (token.empty())
    return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return end == token.c_str() + token.size() && errno == 0 && !std::isspace(static_cast<unsigned char>(token[0]));
}

// Where each soup point and polygon came from in the file (1-based lines);
// empty where the format has no lines (binary OFF and PLY).
struct Soup_lines
{
  std::vector<std::size_t> point_lines;
  std::vector<std::size_t> polygon_lines;
};

// A token of a line: [begin, end) in the file's text.
struct Token
{
  const char* begin;
  const char* end;
  bool empty() const { return begin == end; }
  std::string str() const { return std::string(begin, end); }
  bool operator==(const char* s) const
  {
    const std::size_t n = std::strlen(s);
    return std::size_t(end - begin) == n && std::memcmp(begin, s, n) == 0;
  }
};

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The whitespace-separated tokens of [begin, end), into `tokens`.
inline void split_tokens(const char* begin, const char* end, std::vector<Token>& tokens)
{
  tokens.clear();
  while (true) {
    while (begin != end && is_blank(*begin))
      ++begin;
    if (begin == end)
      return;
    const char* stop = begin;
    while (stop != end && !is_blank(*stop))
      ++stop;
    tokens.push_back(Token{begin, stop});
    begin = stop;
  }
}

// `parse_integer()` on a token, without making a string of it.
inline bool parse_integer(Token t, long long& value)
{
  const char* p = t.begin;
  const bool negative = p != t.end && *p == '-';
  if (p != t.end && (*p == '-' || *p == '+'))
    ++p;
  if (p == t.end)
    return false;
  unsigned long long magnitude = 0;
  const unsigned long long limit = negative ? 9223372036854775808ull : 9223372036854775807ull;
  for (; p != t.end; ++p) {
    if (*p < '0' || *p > '9')
      return false;
    const unsigned digit = unsigned(*p - '0');
    if (magnitude > (limit - digit) / 10)
      return false; // out of range, as strtoll's ERANGE
    magnitude = magnitude * 10 + digit;
  }
  value = negative ? (magnitude == limit ? (std::numeric_limits<long long>::min)() : -(long long)magnitude)
                   : (long long)magnitude;
  return true;
}

// `parse_real()` on a token: from_chars where it can, strtod (which takes a
// leading '+' and reads underflows as 0 or denormals) otherwise.
inline bool parse_real(Token t, double& value)
{
  if (t.empty())
    return false;
  for (const char* p = t.begin; p != t.end; ++p)
    if (!(std::isdigit(static_cast<unsigned char>(*p)) || *p == '+' || *p == '-' || *p == '.' || *p == 'e' ||
          *p == 'E'))
      return false;
  if (*t.begin != '+') {
    const auto [stop, error] = std::from_chars(t.begin, t.end, value);
    if (error == std::errc() && stop == t.end)
      return std::isfinite(value);
    if (error != std::errc::result_out_of_range)
      return false;
  }
  return parse_real(t.str(), value);
}

// A point from three coordinate tokens read as CGAL's reader reads them:
// a `double` FT takes the correctly rounded value (as `operator>>(double&)`
// gives); other number types read the text through their own `operator>>`
// (exact kernels read decimals exactly; a `float` is rounded once).
template <class P>
P point_from_tokens(const Token* coordinates, const double* values)
{
  using FT = typename CGAL::Kernel_traits<P>::Kernel::FT;
  if constexpr (std::is_same_v<FT, double>) {
    (void)coordinates;
    return P(FT(values[0]), FT(values[1]), FT(values[2]));
  } else {
    (void)values;
    std::istringstream in(std::string(coordinates[0].begin, coordinates[2].end));
    CGAL::IO::set_ascii_mode(in);
    P p;
    in >> p;
    return p;
  }
}


// File content quoted in an error message: bytes that are not printable
// ASCII (a NUL, a control or a UTF-8 byte) as \xNN, so that the message is
// one clean line; a long token is cut short.
inline std::string printable(const char* begin, const char* end, std::size_t max_shown = 40)
{
  std::string s;
  for (const char* p = begin; p != end; ++p) {
    if (s.size() >= max_shown) {
      s += "... (" + std::to_string(end - begin) + " bytes)";
      break;
    }
    const unsigned char c = static_cast<unsigned char>(*p);
    if (c >= 0x20 && c < 0x7f) {
      s += char(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", unsigned(c));
      s += hex;
    }
  }
  return s;
}
inline std::string printable(const std::string& s) { return printable(s.data(), s.data() + s.size()); }
inline std::string printable(Token t) { return printable(t.begin, t.end); }

// The lines of a text, each ended by "\n", "\r\n" or a lone "\r" (old Mac
// files), without its end and cut at the first '#' (a comment runs to the
// end of its line in OBJ and OFF). A UTF-8 byte order mark is skipped.
class Text_lines
{
public:
  Text_lines(const char* begin, const char* end) : next_(begin), end_(end)
  {
    if (end - begin >= 3 && std::memcmp(begin, "\xEF\xBB\xBF", 3) == 0)
      next_ += 3;
  }

  // Moves to the next line; false at the end of the text.
  bool next()
  {
    if (next_ == end_)
      return false;
    const char* stop = next_;
    while (stop != end_ && *stop != '\n' && *stop != '\r')
      ++stop;
    const char* hash = static_cast<const char*>(std::memchr(next_, '#', std::size_t(stop - next_)));
    line_ = Token{next_, hash != nullptr ? hash : stop};
    next_ = stop;
    if (next_ != end_ && *next_++ == '\r' && next_ != end_ && *next_ == '\n')
      ++next_;
    ++number_;
    return true;
  }
  // The line without its end and comment.
  Token line() const { return line_; }
  // Its number, from 1.
  std::size_t number() const { return number_; }
  // Where the next line starts (binary OFF data starts after its header line).
  const char* rest() const { return next_; }

private:
  const char* next_;
  const char* end_;
  Token line_{nullptr, nullptr};
  std::size_t number_ = 0;
};

// Binary values of either byte order from [begin, end); reading past the end
// is an error of the caller's file, so `has()` is asked first.
class Byte_reader
{
public:
  Byte_reader(const char* begin, const char* end, bool big_endian)
    : p_(begin), end_(end), big_endian_(big_endian)
  {}
  std::size_t remaining() const { return std::size_t(end_ - p_); }
  bool has(std::size_t bytes) const { return bytes <= remaining(); }

  template <class T>
  T read()
  {
    static_assert(std::is_arithmetic_v<T>);
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, p_, sizeof(T));
    p_ += sizeof(T);
    const std::uint16_t probe = 1;
    const bool host_big = *reinterpret_cast<const unsigned char*>(&probe) == 0;
    if (host_big != big_endian_)
      std::reverse(bytes, bytes + sizeof(T));
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

private:
  const char* p_;
  const char* end_;
  bool big_endian_;
};

// Believes a count from a header only as far as the bytes left in the file
// can hold that many items of at least `min_bytes` each, so that no reader
// reserves (or loops) for more than its file justifies.
inline void check_count_fits(const std::string& filename, std::size_t line, const std::string& what,
                             unsigned long long count, std::size_t min_bytes, std::size_t remaining)
{
  if (min_bytes != 0 && count > remaining / min_bytes)
    throw IO_error(filename, line,
                   "the file announces " + std::to_string(count) + " " + what + ", but the " +
                     std::to_string(remaining) + " bytes that follow can hold at most " +
                     std::to_string(remaining / min_bytes));
}

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_TEXT_SCANNING_H
