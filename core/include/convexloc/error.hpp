// convexloc — errors a user can act on.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace convexloc {

// Base of every error core throws. `line()` is the 1-based source line the problem
// comes from, 0 when it has none (a shape built in memory, a generator argument).
class Error : public std::runtime_error {
public:
  explicit Error(const std::string& what, std::size_t line = 0)
      : std::runtime_error(what), line_(line) {}
  std::size_t line() const noexcept { return line_; }

private:
  std::size_t line_;
};

// "FILE:LINE: problem", as every front end reports a problem (the CLI, the Python module,
// the viewer): the file ("-" reads "<stdin>"), ":LINE" where line > 0, then the problem;
// the problem alone when there is no file.
inline std::string located(const std::string& file, std::size_t line, const std::string& problem) {
  if (file.empty()) return problem;
  std::string where = file == "-" ? "<stdin>" : file;
  if (line > 0) where += ':' + std::to_string(line);
  return where + ": " + problem;
}

// The text of a file is malformed: a bad number, a wrong field count, garbage.
class ParseError : public Error {
public:
  using Error::Error;
};

// The numbers parse but do not make a valid shape: not convex, degenerate, non-finite.
class GeometryError : public Error {
public:
  using Error::Error;
};

// An argument outside what an API accepts (a resolution of zero, an unknown kind).
class UsageError : public Error {
public:
  using Error::Error;
};

}  // namespace convexloc
