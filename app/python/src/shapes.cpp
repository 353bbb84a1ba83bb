// convexloc Python module — Polygon, Polyhedron and the file readers.
//
// A shape is validated once, by core, with the GIL released; what it exposes is copied out
// as numpy arrays (coordinates float64, indices int64) and tuples. The readers report a bad
// file as the command-line tool does: "FILE:LINE: problem" (errors.hpp).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/text_reader.hpp"
#include "errors.hpp"
#include "shape_protocols.hpp"

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

// === Arrays in

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
    for (std::size_t k = 0; k < width; ++k)
      face[k] = faceVertex(py::int_(ints.data()[f * width + k]), mesh.vertices.size(), f);
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
      face.push_back(faceVertex(index, mesh.vertices.size(), f));
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

// a path argument (str or os.PathLike) as text, refused as the tool refuses a directory
std::string filePath(const py::object& pathArg) {
  const std::string path = py::str(py::module_::import("os").attr("fspath")(pathArg));
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec))
    throw FileFailure(ErrorKind::File, path, 0, "cannot open: it is a directory");
  return path;
}

// === Readers

// the polygon in a file of "x y" lines, reported as the command-line tool reports it
ConvexPolygon readPolygon(const py::object& pathArg) {
  const std::string path = filePath(pathArg);
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

// the polyhedron in an OFF, OBJ, STL or PLY file, or (`hull`) the convex hull of its vertices;
// every complaint about the mesh is about the file
ConvexPolyhedron readPolyhedron(const py::object& pathArg, bool hull) {
  const std::string path = filePath(pathArg);
  py::gil_scoped_release released;
  MeshData mesh;
  aboutFile(path, [&] { mesh = readMesh(path); });
  try {
    return hull ? ConvexPolyhedron::hullOf(mesh.vertices) : polyhedronOf(mesh);
  } catch (const convexloc::Error& e) {
    throw FileFailure(kindOf(e), path, e.line(), e.what());
  }
}

// === Classes

// a span a shape holds, as a read-only numpy array: a view of the coordinates (kept alive by
// the shape `owner`), a copy of the indices (as int64)
template <class Item>
py::array arrayOf(std::span<const Item> items, py::handle owner) {
  if constexpr (std::is_same_v<Item, Vec2> || std::is_same_v<Item, Vec3>) {
    return coordinateView(&items.data()->x, items.size(), kDims<Item>, owner);
  } else {
    py::array copy;
    if constexpr (std::is_same_v<Item, std::uint32_t>)
      copy = indexArray(items);
    else
      copy = triangleArray(items);
    copy.attr("setflags")(py::arg("write") = false);
    return copy;
  }
}

// the read-only property `name`: what `get` returns, as an array
template <class Shape, class Item>
void arrayProperty(py::class_<Shape>& c, const char* name,
                   std::span<const Item> (Shape::*get)() const noexcept, const char* doc) {
  c.def_property_readonly(
      name,
      [get](const py::object& self) { return arrayOf((self.cast<const Shape&>().*get)(), self); },
      doc);
}

// the history property `name` (slot `slot` of the pickled history): an index array
template <class Shape>
void indexHistory(py::class_<Shape>& c, const char* name, std::size_t slot,
                  std::span<const std::uint32_t> (Shape::*get)() const noexcept, const char* doc) {
  historyProperty(
      c, name, slot, [get](const Shape& s) { return arrayOf((s.*get)(), {}); }, doc);
}

// the classes' docstrings
constexpr const char* kPolygonDoc =
    "A strictly convex polygon, validated once: counter-clockwise, repeated and "
    "collinear vertices dropped. Immutable: its arrays are read-only. Two polygons "
    "are equal when they have the same vertices in the same counter-clockwise "
    "order, from any start; pickle, copy and deepcopy keep the exact doubles.";
constexpr const char* kPolyhedronDoc =
    "A closed convex polyhedron, validated once, as triangles counter-clockwise "
    "seen from outside. Immutable: its arrays are read-only. Two polyhedra are "
    "equal when they have the same vertices and the same triangles, in any order; "
    "pickle, copy and deepcopy keep the exact doubles.";

// the read-only property `bounds`: the exact box as Shapely orders it, (lo..., hi...)
template <class Shape>
void boundsProperty(py::class_<Shape>& c, const char* doc) {
  c.def_property_readonly(
      "bounds",
      [](const Shape& s) {
        const py::tuple lo = toPython(s.bounds().lo);
        const py::tuple hi = toPython(s.bounds().hi);
        return py::tuple(lo + hi);
      },
      doc);
}

// a closed GeoJSON ring of `points`: (x, y[, z]) tuples, the first repeated at the end
template <class Point>
py::tuple closedRing(std::span<const Point> points) {
  py::tuple ring(points.size() + 1);
  for (std::size_t k = 0; k <= points.size(); ++k) ring[k] = toPython(points[k % points.size()]);
  return ring;
}

// __geo_interface__: the polygon as a GeoJSON Polygon (its ring counter-clockwise, as RFC
// 7946 wants an exterior ring), the polyhedron as a MultiPolygon of its triangles with z
void geoInterface(py::class_<ConvexPolygon>& c) {
  c.def_property_readonly(
      "__geo_interface__",
      [](const ConvexPolygon& p) {
        py::dict geo;
        geo["type"] = "Polygon";
        geo["coordinates"] = py::make_tuple(closedRing(p.vertices()));
        return geo;
      },
      "a GeoJSON Polygon mapping (shapely.geometry.shape and GeoPandas read it)");
}

void geoInterface(py::class_<ConvexPolyhedron>& c) {
  c.def_property_readonly(
      "__geo_interface__",
      [](const ConvexPolyhedron& p) {
        const std::span<const Vec3> v = p.vertices();
        py::tuple parts(p.faceCount());
        std::size_t k = 0;
        for (const auto& t : p.triangles()) {
          const std::array<Vec3, 3> corners{v[t[0]], v[t[1]], v[t[2]]};
          parts[k++] = py::make_tuple(closedRing(std::span<const Vec3>(corners)));
        }
        py::dict geo;
        geo["type"] = "MultiPolygon";
        geo["coordinates"] = parts;
        return geo;
      },
      "a GeoJSON MultiPolygon mapping of the triangles, with z (counter-clockwise from outside)");
}

void bindPolygon(py::module_& m) {
  using P = ConvexPolygon;
  py::class_<P> c(m, "Polygon", kPolygonDoc, py::dynamic_attr());
  c.def(py::init([](const py::object& vertices) { return polygonFrom(vertices); }),
        py::arg("vertices"),
        signedDoc("__init__", "(self, vertices)",
                  "Validates the (N, 2) vertices (either orientation), or the exterior ring of "
                  "a geometry: an object with a Polygon __geo_interface__ (a Shapely polygon) "
                  "or a GeoJSON mapping (a Polygon, a Feature, a one-part MultiPolygon), any z "
                  "dropped; holes and several parts are a GeometryError. Raises GeometryError "
                  "naming the witness: not convex, fewer than 3 distinct vertices, a "
                  "non-finite coordinate."));
  c.def_static("hull", &polygonHull, py::arg("points"),
               signedDoc("hull", "(points)",
                         "The exact convex hull of (M, 2) points as a Polygon: every point "
                         "inside or on it, every vertex one of the points (exact predicates). "
                         "GeometryError when the points are fewer than 3, not finite or all on "
                         "one line."));
  arrayProperty(c, "vertices", &P::vertices,
                "(N, 2) float64, read-only: the vertices, counter-clockwise");
  indexHistory(c, "source_index", 0, &P::sourceIndex, "int64: each vertex's index in the input");
  boundsProperty(c, "(minx, miny, maxx, maxy), exact: Shapely's order");
  geoInterface(c);
  c.def("__len__", &P::size,
        signedDoc("__len__", "(self, /)", "the number of vertices (and of edges)"));
  c.def_property_readonly("area", &P::area, "the area (for display, not for decisions)");
  historyProperty(c, "dropped_count", 1, std::mem_fn(&P::droppedCount),
                  "input vertices dropped as repeated or collinear");
  historyProperty(c, "was_clockwise", 2, std::mem_fn(&P::wasClockwise),
                  "whether the input was clockwise and got reversed");
  defineShapeProtocols(c);
  c.def(
      "__repr__",
      [](const P& p) {
        return "<convexloc.Polygon with " + std::to_string(p.size()) + " vertices>";
      },
      signedDoc("__repr__", "(self, /)", "Return repr(self)."));
}

// the constructor from a mesh, and the hull of a cloud
void definePolyhedronMakers(py::class_<ConvexPolyhedron>& c) {
  c.def(py::init([](const py::object& vertices, const py::object& faces) {
          const MeshData mesh = meshFrom(vertices, faces);
          py::gil_scoped_release released;
          return ConvexPolyhedron(mesh);
        }),
        py::arg("vertices"), py::arg("faces"),
        signedDoc("__init__", "(self, vertices, faces)",
                  "Validates the mesh of (V, 3) vertices and faces (an (F, k) integer array or "
                  "sequences of 0-based vertex indices; faces of more than 3 vertices are "
                  "triangulated). Raises GeometryError naming the witness."));
  c.def_static(
      "hull",
      [](const py::object& points) {
        const py::array cloud = pointArray(points, 3, "points");
        const std::span<const Vec3> read = pointsOf<Vec3>(cloud);
        requireHullPoints(read.size());
        py::gil_scoped_release released;
        return ConvexPolyhedron::hullOf(read);
      },
      py::arg("points"),
      signedDoc("hull", "(points)",
                "The exact convex hull of (M, 3) points: every point inside or on it. Raises "
                "GeometryError when the points are fewer than 4, not finite or coplanar."));
}

void bindPolyhedron(py::module_& m) {
  using P = ConvexPolyhedron;
  py::class_<P> c(m, "Polyhedron", kPolyhedronDoc, py::dynamic_attr());
  definePolyhedronMakers(c);
  arrayProperty(c, "vertices", &P::vertices,
                "(V, 3) float64, read-only: the vertices the triangles use");
  arrayProperty(c, "triangles", &P::triangles, "(F, 3) int64: counter-clockwise from outside");
  arrayProperty(c, "neighbours", &P::neighbours, "(F, 3) int64: [t, k] is across edge k of t");
  indexHistory(c, "source_face", 0, &P::sourceFace, "int64: each triangle's input face");
  indexHistory(c, "source_vertex", 1, &P::sourceVertex, "int64: each vertex's index in the input");
  boundsProperty(c, "(minx, miny, minz, maxx, maxy, maxz), exact: Shapely's order, with z");
  geoInterface(c);
  c.def_property_readonly(
      "centre", [](const P& p) { return centreToPython(p.centre()); },
      "(x, y, z) strictly inside, or None for a sliver thinner than doubles");
  c.def_property_readonly("face_count", &P::faceCount, "the number of triangles");
  c.def_property_readonly("vertex_count", &P::vertexCount, "the number of vertices");
  c.def_property_readonly("volume", &P::volume, "the volume (for display)");
  c.def_property_readonly("area", &P::area, "the surface area (for display)");
  historyProperty(c, "was_inverted", 2, std::mem_fn(&P::wasInverted),
                  "whether the input was clockwise from outside and got reversed");
  defineShapeProtocols(c);
  c.def(
      "__repr__",
      [](const P& p) {
        return "<convexloc.Polyhedron with " + std::to_string(p.faceCount()) + " triangles, " +
               std::to_string(p.vertexCount()) + " vertices>";
      },
      signedDoc("__repr__", "(self, /)", "Return repr(self)."));
}

}  // namespace

void bindShapes(py::module_& m) {
  bindPolygon(m);
  bindPolyhedron(m);
  m.def("read_polygon", &readPolygon, py::arg("path"),
        signedDoc(
            "read_polygon", "(path)",
            "Reads a polygon file (one vertex 'x y' per line). Raises ParseError, GeometryError or "
            "FileError with the command-line tool's message, 'FILE:LINE: problem'."));
  m.def("read_polyhedron", &readPolyhedron, py::arg("path"), py::kw_only(), py::arg("hull") = false,
        signedDoc(
            "read_polyhedron", "(path, *, hull=False)",
            "Reads an .off, .obj, .stl or .ply polyhedron; with hull=True, the convex hull of the "
            "file's vertices (its faces ignored: a point cloud without faces works). Raises "
            "ParseError, GeometryError or FileError with the command-line tool's message, "
            "'FILE:LINE: problem' ('FILE: byte N: problem' in binary data); UsageError for another "
            "extension."));
}

}  // namespace convexloc::python
