// convexloc Python module — convexloc._core: the codes, the errors, then every binding file.
#include "bindings.hpp"
#include "convexloc/batch.hpp"
#include "errors.hpp"

#include <list>
#include <string>

const char* convexloc::python::signedDoc(const char* name, const char* params,
                                         const std::string& doc) {
  static std::list<std::string> kept;  // pybind11 keeps docstrings by pointer
  return kept.emplace_back(std::string(name) + params + "\n--\n\n" + doc).c_str();
}

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  namespace cl = convexloc;
  m.doc() = "convexloc's core: exact O(1) point location in convex polygons and polyhedra.";
  m.attr("__version__") = CONVEXLOC_VERSION;
  m.attr("INSIDE") = static_cast<int>(cl::Location::Inside);
  m.attr("BOUNDARY") = static_cast<int>(cl::Location::Boundary);
  m.attr("OUTSIDE") = static_cast<int>(cl::Location::Outside);
  using convexloc::python::signedDoc;
  py::options options;  // every docstring leads with its text signature (signedDoc)
  options.disable_function_signatures();
  convexloc::python::registerErrors(m);
  convexloc::python::bindShapes(m);
  convexloc::python::bindLocators2D(m);
  convexloc::python::bindLocators3D(m);
  convexloc::python::bindConveniences(m);
  m.def("set_vector_batches", &cl::setVectorBatches, py::arg("enabled"),
        signedDoc("set_vector_batches", "(enabled)",
                  "Whether batches may use the AVX2 code where the CPU has it (answers are the "
                  "same)."));
  m.def("vector_batches", &cl::vectorBatches,
        signedDoc("vector_batches", "()", "Whether batches use the AVX2 code."));
}
