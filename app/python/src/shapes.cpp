// convexloc Python module — Polygon, Polyhedron and the file readers.
//
// A shape is validated once, by core, with the GIL released; what it exposes is copied out
// as numpy arrays (coordinates float64, indices int64) and tuples. The readers report a bad
// file as the command-line tool does: "FILE:LINE: problem" (errors.hpp).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/text_reader.hpp"
#include "errors.hpp"

namespace convexloc::python {

namespace {

// === Arrays out

// the triangles as an (F, 3) int64 array
py::array_t<std::int64_t> triangleArray(std::span<const ConvexPolyhedron::Triangle> triangles) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(triangles.size()), py::ssize_t{3}});
  std::int64_t* to = out.mutable_data();
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) to[3 * i + k] = triangles[i][k];
  return out;
}

// ((xlo, ylo), (xhi, yhi)) and its 3D twin
template <class Box>
py::tuple boundsToPython(const Box& box) {
  return py::make_tuple(toPython(box.lo), toPython(box.hi));
}

// === Arrays in

// a vertex index of face `f`, checked to fit the 32-bit indices of a mesh
std::uint32_t vertexIndex(long long value, std::size_t f) {
  if (value < 0 || value > std::numeric_limits<std::uint32_t>::max())
    throw py::value_error("faces: face " + std::to_string(f) + " has vertex index " +
                          std::to_string(value) + ", which no vertex has");
  return static_cast<std::uint32_t>(value);
}

// faces given as an (F, k) integer array: every face has k vertices
bool addFaceRows(MeshData& mesh, const py::object& faces) {
  py::array rows;
  try {
    rows = py::module_::import("numpy").attr("asarray")(faces);
  } catch (const py::error_already_set&) {
    return false;  // ragged: numpy will not make one array of it
  }
  const char kind = rows.dtype().kind();
  if (rows.ndim() != 2 || (kind != 'i' && kind != 'u')) return false;
  const py::array_t<long long, py::array::c_style | py::array::forcecast> ints(rows);
  const auto count = static_cast<std::size_t>(ints.shape(0));
  const auto width = static_cast<std::size_t>(ints.shape(1));
  std::vector<std::uint32_t> face(width);
  for (std::size_t f = 0; f < count; ++f) {
    for (std::size_t k = 0; k < width; ++k) face[k] = vertexIndex(ints.data()[f * width + k], f);
    mesh.addFace(face);
  }
  return true;
}

// faces given as any sequence of sequences of integers
void addFaceLists(MeshData& mesh, const py::object& faces) {
  std::vector<std::uint32_t> face;
  std::size_t f = 0;
  for (const py::handle polygon : py::iter(faces)) {
    face.clear();
    for (const py::handle index : py::iter(polygon)) {
      if (!PyIndex_Check(index.ptr()))
        throw py::type_error("faces: face " + std::to_string(f) + " holds " +
                             std::string(py::repr(index)) + ", not a vertex index");
      const auto number = py::reinterpret_steal<py::object>(PyNumber_Index(index.ptr()));
      if (!number) throw py::error_already_set();
      int overflow = 0;
      const long long value = PyLong_AsLongLongAndOverflow(number.ptr(), &overflow);
      face.push_back(vertexIndex(overflow ? -1 : value, f));
    }
    mesh.addFace(face);
    ++f;
  }
}

// the mesh of `vertices` ((V, 3) array-like) and `faces` (sequences of vertex indices)
MeshData meshFrom(const py::object& vertices, const py::object& faces) {
  MeshData mesh;
  const py::array points = pointArray(vertices, 3, "vertices");
  const std::span<const Vec3> read = pointsOf<Vec3>(points);
  mesh.vertices.assign(read.begin(), read.end());
  if (!addFaceRows(mesh, faces)) addFaceLists(mesh, faces);
  return mesh;
}

// a path argument (str or os.PathLike) as text
std::string pathText(const py::object& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

// === Readers

// the polygon in a file of "x y" lines, reported as the command-line tool reports it
ConvexPolygon readPolygon(const py::object& pathArg) {
  const std::string path = pathText(pathArg);
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec))
    throw FileFailure(ErrorKind::File, path, 0, "cannot open: it is a directory");
  py::gil_scoped_release released;
  PointList list;
  aboutFile(path, [&] { list = readPoints2D(path); });
  if (list.points.empty())
    throw FileFailure(ErrorKind::Parse, path, 0,
                      "no vertices: a polygon file lists one vertex 'x y' per line");
  std::optional<ConvexPolygon> polygon;
  aboutFile(path, [&] { polygon.emplace(list.points, list.lines); });
  return std::move(*polygon);
}

// the polyhedron in an OFF or OBJ file; every complaint about the mesh is about the file
ConvexPolyhedron readPolyhedron(const py::object& pathArg) {
  const std::string path = pathText(pathArg);
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec))
    throw FileFailure(ErrorKind::File, path, 0, "cannot open: it is a directory");
  py::gil_scoped_release released;
  MeshData mesh;
  aboutFile(path, [&] { mesh = readMesh(path); });
  try {
    return ConvexPolyhedron(mesh);
  } catch (const convexloc::Error& e) {
    throw FileFailure(kindOf(e), path, e.line(), e.what());
  }
}

// === Classes

void bindPolygon(py::module_& m) {
  py::class_<ConvexPolygon>(
      m, "Polygon",
      "A strictly convex polygon, validated once: counter-clockwise, repeated "
      "and collinear vertices dropped.")
      .def(py::init([](const py::object& vertices) {
             const py::array points = pointArray(vertices, 2, "vertices");
             const std::span<const Vec2> read = pointsOf<Vec2>(points);
             py::gil_scoped_release released;
             return ConvexPolygon(read);
           }),
           py::arg("vertices"),
           "Validates the (N, 2) vertices (either orientation). Raises GeometryError naming "
           "the witness: not convex, fewer than 3 distinct vertices, a non-finite coordinate.")
      .def_property_readonly(
          "vertices", [](const ConvexPolygon& p) { return coordinateArray(p.vertices()); },
          "(N, 2) float64: the vertices, counter-clockwise")
      .def("__len__", &ConvexPolygon::size, "the number of vertices (and of edges)")
      .def_property_readonly(
          "bounds", [](const ConvexPolygon& p) { return boundsToPython(p.bounds()); },
          "((xmin, ymin), (xmax, ymax)), exact")
      .def_property_readonly("area", &ConvexPolygon::area,
                             "the area (for display, not for decisions)")
      .def_property_readonly(
          "source_index", [](const ConvexPolygon& p) { return indexArray(p.sourceIndex()); },
          "int64: each kept vertex's index in the input")
      .def_property_readonly("dropped_count", &ConvexPolygon::droppedCount,
                             "input vertices dropped as repeated or collinear")
      .def_property_readonly("was_clockwise", &ConvexPolygon::wasClockwise,
                             "whether the input was clockwise and got reversed")
      .def("__repr__", [](const ConvexPolygon& p) {
        return "<convexloc.Polygon with " + std::to_string(p.size()) + " vertices>";
      });
}

void bindPolyhedron(py::module_& m) {
  using P = ConvexPolyhedron;
  py::class_<P>(m, "Polyhedron",
                "A closed convex polyhedron, validated once, as triangles counter-clockwise seen "
                "from outside.")
      .def(py::init([](const py::object& vertices, const py::object& faces) {
             const MeshData mesh = meshFrom(vertices, faces);
             py::gil_scoped_release released;
             return P(mesh);
           }),
           py::arg("vertices"), py::arg("faces"),
           "Validates the mesh of (V, 3) vertices and faces (an (F, k) integer array or "
           "sequences of 0-based vertex indices; faces of more than 3 vertices are "
           "triangulated). Raises GeometryError naming the witness.")
      .def_static(
          "hull",
          [](const py::object& points) {
            const py::array cloud = pointArray(points, 3, "points");
            const std::span<const Vec3> read = pointsOf<Vec3>(cloud);
            py::gil_scoped_release released;
            return P::hullOf(read);
          },
          py::arg("points"),
          "The convex hull of (M, 3) points (Qhull), validated exactly. Raises GeometryError "
          "when the points are fewer than 4, not finite or coplanar.")
      .def_property_readonly(
          "vertices", [](const P& p) { return coordinateArray(p.vertices()); },
          "(V, 3) float64: the vertices the triangles use")
      .def_property_readonly(
          "triangles", [](const P& p) { return triangleArray(p.triangles()); },
          "(F, 3) int64: the triangles, counter-clockwise from outside")
      .def_property_readonly(
          "neighbours", [](const P& p) { return triangleArray(p.neighbours()); },
          "(F, 3) int64: [t, k] is the triangle across edge k of t")
      .def_property_readonly("face_count", &P::faceCount, "the number of triangles")
      .def_property_readonly("vertex_count", &P::vertexCount, "the number of vertices")
      .def_property_readonly(
          "centre",
          [](const P& p) -> py::object {
            if (auto c = p.centre()) return toPython(*c);
            return py::none();
          },
          "(x, y, z) strictly inside, or None for a sliver thinner than doubles")
      .def_property_readonly(
          "bounds", [](const P& p) { return boundsToPython(p.bounds()); },
          "((xmin, ymin, zmin), (xmax, ymax, zmax)), exact")
      .def_property_readonly("volume", &P::volume, "the volume (for display)")
      .def_property_readonly("area", &P::area, "the surface area (for display)")
      .def_property_readonly(
          "source_face", [](const P& p) { return indexArray(p.sourceFace()); },
          "int64: each triangle's input face")
      .def_property_readonly(
          "source_vertex", [](const P& p) { return indexArray(p.sourceVertex()); },
          "int64: each vertex's index in the input")
      .def_property_readonly("was_inverted", &P::wasInverted,
                             "whether the input was clockwise from outside and got reversed")
      .def("__repr__", [](const P& p) {
        return "<convexloc.Polyhedron with " + std::to_string(p.faceCount()) + " triangles, " +
               std::to_string(p.vertexCount()) + " vertices>";
      });
}

}  // namespace

void bindShapes(py::module_& m) {
  bindPolygon(m);
  bindPolyhedron(m);
  m.def("read_polygon", &readPolygon, py::arg("path"),
        "Reads a polygon file (one vertex 'x y' per line). Raises ParseError, GeometryError or "
        "FileError with the command-line tool's message, 'FILE:LINE: problem'.");
  m.def("read_polyhedron", &readPolyhedron, py::arg("path"),
        "Reads an .off or .obj polyhedron. Raises ParseError, GeometryError or FileError with "
        "the command-line tool's message, 'FILE:LINE: problem'; UsageError for another extension.");
}

}  // namespace convexloc::python
