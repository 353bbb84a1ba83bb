// convexloc Python module — the exception classes and the translation of errors.hpp.
#include "errors.hpp"

#include <array>

namespace convexloc::python {

namespace {

// the exception classes, indexed by ErrorKind; kept for the life of the interpreter
std::array<PyObject*, 5> gTypes{};

// "FILE:LINE: problem", as the command-line tool prints it ("-" is standard input)
std::string fileMessage(const std::string& path, std::size_t line, const std::string& problem) {
  return convexloc::located(path, line, problem);
}

// a new exception class convexloc.<name> deriving from `bases` (a class or a tuple)
PyObject* newType(py::module_& m, const char* name, const char* doc, py::handle bases) {
  const std::string qualified = std::string("convexloc.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::handle(type));  // the module holds a reference, gTypes another
  return type;
}

// raises the Python exception for a failure, with its path, line and problem attached
void raise(ErrorKind kind, const std::string& path, std::size_t line, const std::string& problem,
           const std::string& message) {
  py::handle type(gTypes[static_cast<std::size_t>(kind)]);
  py::object error = type(message);
  error.attr("path") = path.empty() ? py::object(py::none()) : py::object(py::str(path));
  error.attr("line") = line;
  error.attr("problem") = problem;
  PyErr_SetObject(type.ptr(), error.ptr());
}

}  // namespace

FileFailure::FileFailure(ErrorKind kind, std::string path, std::size_t line, std::string problem)
    : kind_(kind),
      path_(std::move(path)),
      line_(line),
      problem_(std::move(problem)),
      message_(fileMessage(path_, line_, problem_)) {}

ErrorKind kindOf(const convexloc::Error& e) noexcept {
  if (dynamic_cast<const ParseError*>(&e)) return ErrorKind::Parse;
  if (dynamic_cast<const GeometryError*>(&e)) return ErrorKind::Geometry;
  if (dynamic_cast<const UsageError*>(&e)) return ErrorKind::Usage;
  return ErrorKind::File;  // core's plain Error: a file that cannot be opened, read or written
}

void registerErrors(py::module_& m) {
  auto& t = gTypes;
  const py::handle valueError(PyExc_ValueError);
  t[0] = newType(m, "Error",
                 "Base of every convexloc error (a ValueError). Attributes: path (the file, or "
                 "None), line (1-based, 0 when none), problem (the message without its place).",
                 valueError);
  const py::handle base(t[0]);
  t[1] = newType(m, "ParseError", "A file's text is malformed: a bad number, a wrong field count.",
                 base);
  t[2] =
      newType(m, "GeometryError",
              "The numbers do not make a valid shape: not convex, degenerate, not finite.", base);
  t[3] = newType(m, "UsageError", "An argument outside what the API accepts.", base);
  t[4] = newType(m, "FileError", "A file that cannot be opened or read (also an OSError).",
                 py::make_tuple(base, py::handle(PyExc_OSError)));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileFailure& f) {
      raise(f.kind(), f.path(), f.line(), f.problem(), f.what());
    } catch (const convexloc::Error& e) {
      // a shape built in memory: no file to name
      const ErrorKind kind = kindOf(e) == ErrorKind::File ? ErrorKind::Error : kindOf(e);
      raise(kind, "", e.line(), e.what(), e.what());
    }
  });
}

}  // namespace convexloc::python
