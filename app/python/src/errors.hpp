// convexloc Python module — core's errors as Python exceptions.
//
// convexloc.Error is a ValueError; ParseError, GeometryError and UsageError mirror core's
// kinds, and FileError (also an OSError) is a file that cannot be opened or read. Each
// instance carries `path` (None for a shape built in memory), `line` (1-based, 0 when none)
// and `problem`; its text is the command-line tool's message, "FILE:LINE: problem".
#pragma once

#include <pybind11/pybind11.h>

#include <cstddef>
#include <exception>
#include <string>
#include <utility>

#include "convexloc/error.hpp"

namespace convexloc::python {

namespace py = pybind11;

// which Python exception a failure raises
enum class ErrorKind { Error, Parse, Geometry, Usage, File };

// A failure to report about a file, turned into a Python exception by the translator.
class FileFailure : public std::exception {
 public:
  FileFailure(ErrorKind kind, std::string path, std::size_t line, std::string problem);
  const char* what() const noexcept override { return message_.c_str(); }
  ErrorKind kind() const noexcept { return kind_; }
  const std::string& path() const noexcept { return path_; }
  std::size_t line() const noexcept { return line_; }
  const std::string& problem() const noexcept { return problem_; }

 private:
  ErrorKind kind_;
  std::string path_;
  std::size_t line_;
  std::string problem_;
  std::string message_;
};

// creates the exception classes in `m` and translates FileFailure and convexloc::Error
void registerErrors(py::module_& m);

// the kind of a core error that comes from reading or validating a file
ErrorKind kindOf(const convexloc::Error& e) noexcept;

// Runs fn(); a core error it throws becomes a FileFailure about `path`, with the message the
// command-line tool prints. A UsageError from a reader names no file, as the tool does.
template <class Fn>
void aboutFile(const std::string& path, Fn&& fn) {
  try {
    std::forward<Fn>(fn)();
  } catch (const convexloc::UsageError& e) {
    throw FileFailure(ErrorKind::Usage, "", 0, e.what());
  } catch (const convexloc::Error& e) {
    throw FileFailure(kindOf(e), path, e.line(), e.what());
  }
}

}  // namespace convexloc::python
