// What the example tools print on success: one line of JSON, an object
// whose fields come in the order they are added.
#ifndef CGAL_EXT_EXAMPLES_JSON_LINE_H
#define CGAL_EXT_EXAMPLES_JSON_LINE_H

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iostream>
#include <locale>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>

namespace examples {

class Json_object;
class Json_array;

/// `text` as a JSON string: quoted, with quotes, backslashes and control
/// characters escaped (other bytes, UTF-8 included, as they are).
inline std::string json_text(const std::string& text)
{
  std::string quoted = "\"";
  for (const char c : text) {
    switch (c) {
    case '"': quoted += "\\\""; break;
    case '\\': quoted += "\\\\"; break;
    case '\b': quoted += "\\b"; break;
    case '\f': quoted += "\\f"; break;
    case '\n': quoted += "\\n"; break;
    case '\r': quoted += "\\r"; break;
    case '\t': quoted += "\\t"; break;
    default:
      if (static_cast<unsigned char>(c) < 0x20) {
        char escape[8];
        std::snprintf(escape, sizeof escape, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
        quoted += escape;
      } else {
        quoted += c;
      }
    }
  }
  return quoted + "\"";
}

inline std::string json_text(const char* text) { return json_text(std::string(text)); }

inline std::string json_text(bool value) { return value ? "true" : "false"; }

/// An integer in full.
template <class Integer, std::enable_if_t<std::is_integral_v<Integer> && !std::is_same_v<Integer, bool>, int> = 0>
std::string json_text(Integer value)
{
  return std::to_string(value);
}

/// A number as a stream prints it by default (six significant digits);
/// null where it is not finite, which JSON cannot write.
inline std::string json_text(double value)
{
  if (!std::isfinite(value))
    return "null";
  std::ostringstream text;
  text.imbue(std::locale::classic());
  text << value;
  return text.str();
}

inline std::string json_text(std::nullptr_t) { return "null"; }

/// The value, or null where there is none.
template <class T>
std::string json_text(const std::optional<T>& value)
{
  return value ? json_text(*value) : "null";
}

std::string json_text(const Json_object& object);
std::string json_text(const Json_array& array);

/// A JSON object built field by field: `add(key, value)` appends a field
/// (strings, booleans, integers, doubles, null, optional values, nested
/// objects and arrays), `append(other)` the fields of another object.
class Json_object
{
public:
  template <class T>
  Json_object& add(const std::string& key, const T& value)
  {
    return field(json_text(key) + ":" + json_text(value));
  }

  Json_object& append(const Json_object& other)
  {
    return other.fields_.empty() ? *this : field(other.fields_);
  }

  std::string str() const { return "{" + fields_ + "}"; }

private:
  Json_object& field(const std::string& text)
  {
    fields_ += (fields_.empty() ? "" : ",") + text;
    return *this;
  }

  std::string fields_;
};

/// A JSON array built element by element.
class Json_array
{
public:
  template <class T>
  Json_array& add(const T& value)
  {
    elements_ += (elements_.empty() ? "" : ",") + json_text(value);
    return *this;
  }

  std::string str() const { return "[" + elements_ + "]"; }

private:
  std::string elements_;
};

inline std::string json_text(const Json_object& object) { return object.str(); }
inline std::string json_text(const Json_array& array) { return array.str(); }

/// Prints `line` as one line and flushes it.
inline void print_json_line(const Json_object& line, std::ostream& out = std::cout)
{
  out << line.str() << std::endl;
}

} // namespace examples

#endif
