// The command line of the example tools, in one place: `--help` and `-h`
// print the usage on stdout and exit 0; a bad argument prints one line on
// stderr, "TOOL: <what>; usage: <synopsis>", and exits 2; a failure of the
// work itself prints "TOOL: <what>" and exits 2.
#ifndef CGAL_EXT_EXAMPLES_ARGUMENTS_H
#define CGAL_EXT_EXAMPLES_ARGUMENTS_H

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace examples {

/// A bad command line: the message is followed by the tool's synopsis.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// What `--help` prints: the one-line synopsis (also the end of every
/// usage error) and the description under it.
struct Tool_usage
{
  const char* name;
  const char* synopsis;
  const char* description;
};

/// One line on stderr, whatever the message holds; returns the exit status 2.
inline int fail(const std::string& tool, std::string what)
{
  std::replace(what.begin(), what.end(), '\n', ' ');
  std::cerr << tool << ": " << what << std::endl;
  return 2;
}

/// The arguments in order (file names, numbers) and the options given.
struct Arguments
{
  std::vector<std::string> positional;
  std::map<std::string, std::string> options; ///< value "" for a flag
  bool has(const std::string& option) const { return options.count(option) != 0; }
  std::string value(const std::string& option, const std::string& fallback) const
  {
    const auto it = options.find(option);
    return it == options.end() ? fallback : it->second;
  }
};

/// Splits the command line: options named in `with_value` take the next
/// argument as their value, `flags` take none; any other argument that
/// starts with "--" is an unknown option.
inline Arguments parse_arguments(int argc, char** argv, std::initializer_list<std::string> with_value,
                                 std::initializer_list<std::string> flags = {})
{
  Arguments args;
  const auto among = [](const std::string& a, std::initializer_list<std::string> names) {
    return std::find(names.begin(), names.end(), a) != names.end();
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--", 0) != 0) {
      args.positional.push_back(a);
      continue;
    }
    const bool flag = among(a, flags);
    if (!flag && !among(a, with_value))
      throw Usage_error("unknown option " + a);
    if (!flag && i + 1 >= argc)
      throw Usage_error("option " + a + " needs a value");
    if (!args.options.emplace(a, flag ? "" : argv[++i]).second)
      throw Usage_error("option " + a + " is given twice");
  }
  return args;
}

/// `text` as a whole integer in [low, high], or a Usage_error naming `what`.
inline long integer_argument(const std::string& what, const std::string& text, long low, long high)
{
  char* end = nullptr;
  errno = 0;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || n < low || n > high)
    throw Usage_error(what + " '" + text + "' is not an integer from " + std::to_string(low) + " to " +
                      std::to_string(high));
  return n;
}

/// `text` as a whole finite number, or a Usage_error naming `what`.
inline double real_argument(const std::string& what, const std::string& text)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(x))
    throw Usage_error(what + " '" + text + "' is not a finite number");
  return x;
}

/// One accepted value of an enumerated option: its name on the command line
/// and what it stands for.
template <class T>
struct Choice
{
  const char* name;
  T value;
};

/// The accepted values of an enumerated option, in the order the error
/// message lists them.
template <class T>
using Choices = std::vector<Choice<T>>;

/// The value named `text` among `choices`, or a Usage_error
/// "OPTION 'TEXT' is not A, B or C" listing the accepted names.
template <class T>
T choice_argument(const std::string& option, const std::string& text, const Choices<T>& choices)
{
  for (const Choice<T>& c : choices)
    if (text == c.name)
      return c.value;
  std::string names;
  for (std::size_t i = 0; i < choices.size(); ++i)
    names += std::string(i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i].name;
  throw Usage_error(option + " '" + text + "' is not " + names);
}

/// The value of the enumerated `option` if it is given (see choice_argument()).
template <class T>
std::optional<T> choice_option(const Arguments& args, const std::string& option, const Choices<T>& choices)
{
  if (!args.has(option))
    return std::nullopt;
  return choice_argument(option, args.value(option, ""), choices);
}

/// The name of `value` among `choices` (the first that stands for it).
template <class T>
const char* choice_name(const Choices<T>& choices, T value)
{
  for (const Choice<T>& c : choices)
    if (c.value == value)
      return c.name;
  throw std::logic_error("a value without a name among the choices");
}

/// Runs a tool: `--help` or `-h` anywhere prints the usage on stdout (exit
/// 0); otherwise `body()` runs and its result is the exit status, and what
/// it throws becomes one line on stderr with exit status 2 (with the
/// synopsis after a Usage_error).
template <class Body>
int run_tool(const Tool_usage& usage, int argc, char** argv, Body&& body)
{
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::cout << "usage: " << usage.synopsis << "\n\n" << usage.description;
      return 0;
    }
#ifdef SIGXFSZ
  // Past a file-size limit a write fails (and the library says so, leaving
  // the old file) instead of the signal killing the tool without a word.
  std::signal(SIGXFSZ, SIG_IGN);
#endif
  try {
    return body();
  } catch (const Usage_error& e) {
    return fail(usage.name, std::string(e.what()) + "; usage: " + usage.synopsis);
  } catch (const std::exception& e) {
    return fail(usage.name, e.what());
  }
}

} // namespace examples

#endif
