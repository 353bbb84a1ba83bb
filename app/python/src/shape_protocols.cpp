// convexloc Python module — pickling, equality, hashing and views of the shapes.
#include "shape_protocols.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"

namespace convexloc::python {

namespace {

// the version of the pickled state, first in the tuple (1: index histories as int64; 2: as
// uint32, which holds every index a shape has; both load)
constexpr int kStateVersion = 2;

// === Canonical forms: equal shapes have equal canonical forms

// the coordinate with -0 made +0, so that equal doubles have equal bytes
double plain(double v) {
  return v + 0.0;
}
Vec2 plain(Vec2 p) {
  return {plain(p.x), plain(p.y)};
}
Vec3 plain(Vec3 p) {
  return {plain(p.x), plain(p.y), plain(p.z)};
}

// lexicographic order of points
bool before(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}
bool before(Vec3 a, Vec3 b) {
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

// a polygon's vertices, counter-clockwise from its lexicographically smallest one
std::vector<Vec2> canonical(const ConvexPolygon& p) {
  const std::span<const Vec2> v = p.vertices();
  const auto first =
      std::min_element(v.begin(), v.end(), [](Vec2 a, Vec2 b) { return before(a, b); });
  std::vector<Vec2> out;
  out.reserve(v.size());
  for (auto it = first; it != v.end(); ++it) out.push_back(plain(*it));
  for (auto it = v.begin(); it != first; ++it) out.push_back(plain(*it));
  return out;
}

// a polyhedron as sorted vertices and sorted triangles over them, each triangle starting
// at its smallest index (its orientation kept)
struct CanonicalMesh {
  std::vector<Vec3> vertices;
  std::vector<ConvexPolyhedron::Triangle> triangles;
  friend bool operator==(const CanonicalMesh&, const CanonicalMesh&) = default;
};

CanonicalMesh canonical(const ConvexPolyhedron& p) {
  const std::span<const Vec3> v = p.vertices();
  std::vector<std::uint32_t> order(v.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return before(v[a], v[b]); });
  CanonicalMesh out;
  std::vector<std::uint32_t> rank(v.size());
  for (std::uint32_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = r;
    out.vertices.push_back(plain(v[order[r]]));
  }
  for (const auto& t : p.triangles()) {
    std::array<std::uint32_t, 3> u{rank[t[0]], rank[t[1]], rank[t[2]]};
    std::rotate(u.begin(), std::min_element(u.begin(), u.end()), u.end());
    out.triangles.push_back(u);
  }
  std::sort(out.triangles.begin(), out.triangles.end());
  return out;
}

// a hash of the bytes of `items`
template <class T>
std::size_t bytesHash(const std::vector<T>& items) {
  const std::string_view bytes(reinterpret_cast<const char*>(items.data()),
                               items.size() * sizeof(T));
  return std::hash<std::string_view>{}(bytes);
}

std::size_t shapeHash(const ConvexPolygon& p) {
  return bytesHash(canonical(p));
}
std::size_t shapeHash(const ConvexPolyhedron& p) {
  const CanonicalMesh m = canonical(p);
  return bytesHash(m.vertices) * 31 + bytesHash(m.triangles);
}

// === Equality and hashing, the same for both shapes

template <class Shape>
void defineEquality(py::class_<Shape>& c) {
  c.def(
      "__eq__",
      [](const Shape& a, const py::object& other) -> py::object {
        if (!py::isinstance<Shape>(other))
          return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        return py::bool_(canonical(a) == canonical(other.cast<const Shape&>()));
      },
      py::is_operator(),
      signedDoc("__eq__", "(self, other, /)",
                "Whether the shapes are the same (see the class's docstring)."));
  c.def(
      "__hash__",
      [](const py::object& self) {
        py::dict state = self.attr("__dict__");
        if (!state.contains("_hash")) {
          // Python's hash is a Py_ssize_t, and -1 is reserved for errors
          auto h = static_cast<py::ssize_t>(shapeHash(self.cast<const Shape&>()));
          state["_hash"] = py::int_(h == -1 ? -2 : h);
        }
        return state["_hash"];
      },
      signedDoc("__hash__", "(self, /)", "A hash consistent with ==, computed once."));
}

// === Pickling

// an (N, dims) float64 array holding `points` in a pickled state, checked
template <class Point>
std::vector<Point> pointsFromState(const py::handle& item) {
  const py::array rows =
      pointArray(py::reinterpret_borrow<py::object>(item), kDims<Point>, "pickled vertices");
  const std::span<const Point> read = pointsOf<Point>(rows);
  return {read.begin(), read.end()};
}

// the tuple's items after checking its length and version
py::tuple stateItems(const py::tuple& state, std::size_t size, const char* cls) {
  const int version = state.size() == size ? state[0].cast<int>() : -1;
  if (version != 1 && version != kStateVersion)
    throw py::value_error(std::string("cannot unpickle this ") + cls +
                          ": it was pickled by another version of convexloc");
  return state;
}

// an index array of a history as it travels: uint32 (half of int64's bytes)
py::object compactIndices(const py::object& indices) {
  return indices.attr("astype")("uint32");
}

// the restored history goes into the new instance's __dict__, its index arrays (`slots`) as
// the read-only int64 arrays the properties give
py::dict historyDict(const py::handle& saved, std::initializer_list<std::size_t> slots) {
  py::list history = py::reinterpret_borrow<py::object>(saved);
  for (const std::size_t slot : slots) {
    py::object indices = history[slot].attr("astype")("int64");
    indices.attr("setflags")(py::arg("write") = false);
    history[slot] = indices;
  }
  py::dict d;
  d["_history"] = py::tuple(history);
  return d;
}

}  // namespace

py::array coordinateView(const double* data, std::size_t count, int dims, py::handle owner) {
  const auto rows = static_cast<py::ssize_t>(count);
  const auto width = static_cast<py::ssize_t>(dims);
  py::array view(py::dtype::of<double>(), {rows, width},
                 {width * py::ssize_t{sizeof(double)}, py::ssize_t{sizeof(double)}}, data, owner);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

py::object restoredHistory(py::handle self, std::size_t slot) {
  const py::object state = py::getattr(self, "__dict__", py::none());
  if (state.is_none() || !py::dict(state).contains("_history")) return py::none();
  return py::tuple(py::dict(state)["_history"])[slot];
}

// equality, hashing and pickling: `state(self, shape)` gives the pickled tuple, and
// `restore(items)` the shape and its history from the tuple's `count` checked items
template <class Shape, class State, class Restore>
void defineProtocols(py::class_<Shape>& c, const char* name, std::size_t count, State state,
                     Restore restore) {
  defineEquality(c);
  pickleAnyProtocol(c);
  c.def(
      py::pickle([state](const py::object& self) { return state(self, self.cast<const Shape&>()); },
                 [restore, count, name](const py::tuple& saved) {
                   return restore(stateItems(saved, count, name));
                 }));
}

void defineShapeProtocols(py::class_<ConvexPolygon>& c) {
  defineProtocols(
      c, "Polygon", 3,
      [](const py::object& self, const ConvexPolygon& p) {
        const py::tuple history =
            py::make_tuple(compactIndices(self.attr("source_index")), self.attr("dropped_count"),
                           self.attr("was_clockwise"));
        return py::make_tuple(kStateVersion, coordinateArray<Vec2>(p.vertices()), history);
      },
      [](const py::tuple& items) {
        const std::vector<Vec2> vertices = pointsFromState<Vec2>(items[1]);
        return std::make_pair(ConvexPolygon(vertices), historyDict(items[2], {0}));
      });
}

void defineShapeProtocols(py::class_<ConvexPolyhedron>& c) {
  defineProtocols(
      c, "Polyhedron", 4,
      [](const py::object& self, const ConvexPolyhedron& p) {
        py::array_t<std::uint32_t> triangles(
            {static_cast<py::ssize_t>(p.faceCount()), py::ssize_t{3}});
        std::copy_n(p.triangles().data()->data(), 3 * p.faceCount(), triangles.mutable_data());
        const py::tuple history =
            py::make_tuple(compactIndices(self.attr("source_face")),
                           compactIndices(self.attr("source_vertex")), self.attr("was_inverted"));
        return py::make_tuple(kStateVersion, coordinateArray<Vec3>(p.vertices()), triangles,
                              history);
      },
      [](const py::tuple& items) {
        MeshData mesh;
        mesh.vertices = pointsFromState<Vec3>(items[1]);
        const auto triangles = items[2].cast<py::array_t<std::uint32_t, py::array::c_style>>();
        const std::uint32_t* t = triangles.data();
        for (py::ssize_t f = 0; f < triangles.shape(0); ++f)
          mesh.addFace({t[3 * f], t[3 * f + 1], t[3 * f + 2]});
        std::optional<ConvexPolyhedron> made;
        {
          py::gil_scoped_release released;
          made.emplace(mesh);
        }
        return std::make_pair(std::move(*made), historyDict(items[3], {0, 1}));
      });
}

}  // namespace convexloc::python
