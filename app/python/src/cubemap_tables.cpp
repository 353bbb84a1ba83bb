// convexloc Python module — a pickled CubemapLocator carries its tables as numpy arrays
// (uint32 indices, float32 radii, float64 points) and loads from them without building.
//
// The state: (2, polyhedron, resolution asked for, tables), the tables a dict holding
// "version" (CubemapTables::kVersion), "resolution", "centre", "build_seconds" and one array
// per table. Tables of another version are not read: the locator is rebuilt from the
// polyhedron and the resolution. The older state (1, polyhedron, resolution) is rebuilt too.
// Tables that are read are checked by core (CubemapLocator's load constructor): a damaged
// one raises convexloc.ParseError naming the table.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "locator_class.hpp"

namespace convexloc::python {
namespace {

constexpr int kTablesState = 2;  // the state carrying the tables
constexpr int kShapeState = 1;   // the older one: polyhedron and resolution only

// `values` as a read-only numpy array of rows of `width` (one dimension when width is 1)
template <class T>
py::array_t<T> tableArray(const std::vector<T>& values, py::ssize_t width) {
  const auto n = static_cast<py::ssize_t>(values.size());
  py::array_t<T> out = width == 1 ? py::array_t<T>(n) : py::array_t<T>({n / width, width});
  std::copy(values.begin(), values.end(), out.mutable_data());
  out.attr("flags").attr("writeable") = false;
  return out;
}

py::dict tablesToPython(const CubemapTables& t) {
  py::dict d;
  d["version"] = t.version;
  d["resolution"] = t.resolution;
  d["centre"] = py::make_tuple(t.centre.x, t.centre.y, t.centre.z);
  d["build_seconds"] = t.buildSeconds;
  d["nodes"] = tableArray(t.nodes, 2);
  d["radii"] = tableArray(t.radii, 2);
  d["entries"] = tableArray(t.entries, 1);
  d["zones"] = tableArray(t.zones, 3);
  d["zone_edges"] = tableArray(t.zoneEdges, 2);
  d["zone_faces"] = tableArray(t.zoneFaces, 1);
  d["zone_ranges"] = tableArray(t.zoneRanges, 3);
  d["sector_points"] = tableArray(t.sectorPoints, 6);
  d["sectors"] = tableArray(t.sectors, 4);
  d["sector_faces"] = tableArray(t.sectorFaces, 1);
  d["sector_keys"] = tableArray(t.sectorKeys, 1);
  d["sector_ranges"] = tableArray(t.sectorRanges, 3);
  d["slabs"] = tableArray(t.slabs, 5);
  return d;
}

[[noreturn]] void badState(const std::string& problem) {
  throw py::value_error("cannot unpickle this CubemapLocator: " + problem);
}

// the entry `key` of the pickled tables
py::object entry(const py::dict& d, const char* key) {
  if (!d.contains(key)) badState(std::string("its tables lack '") + key + "'");
  return d[key];
}

// the table `key`: a numpy array of T (its rows flattened); the sizes are core's to check
template <class T>
std::vector<T> tableFrom(const py::dict& d, const char* key) {
  const py::object a = entry(d, key);
  if (!py::isinstance<py::array_t<T>>(a))  // an ndarray of that dtype
    badState(std::string("its table '") + key + "' is not a numpy array of " +
             std::string(py::str(py::dtype::of<T>())));
  const auto flat = py::array_t<T, py::array::c_style>::ensure(a);
  if (!flat) badState(std::string("its table '") + key + "' cannot be read");
  return std::vector<T>(flat.data(), flat.data() + flat.size());
}

// the tables of a pickled state, or none where they are of another version
std::optional<CubemapTables> tablesFrom(const py::object& state) {
  if (!py::isinstance<py::dict>(state)) badState("its tables are not a dict");
  const auto d = state.cast<py::dict>();
  CubemapTables t;
  if (entry(d, "version").cast<std::uint32_t>() != CubemapTables::kVersion) return std::nullopt;
  t.resolution = entry(d, "resolution").cast<std::uint32_t>();
  const auto c = entry(d, "centre").cast<std::array<double, 3>>();
  t.centre = {c[0], c[1], c[2]};
  t.buildSeconds = entry(d, "build_seconds").cast<double>();
  t.nodes = tableFrom<std::uint32_t>(d, "nodes");
  t.radii = tableFrom<float>(d, "radii");
  t.entries = tableFrom<std::uint32_t>(d, "entries");
  t.zones = tableFrom<std::uint32_t>(d, "zones");
  t.zoneEdges = tableFrom<std::uint32_t>(d, "zone_edges");
  t.zoneFaces = tableFrom<std::uint32_t>(d, "zone_faces");
  t.zoneRanges = tableFrom<std::uint32_t>(d, "zone_ranges");
  t.sectorPoints = tableFrom<double>(d, "sector_points");
  t.sectors = tableFrom<std::uint32_t>(d, "sectors");
  t.sectorFaces = tableFrom<std::uint32_t>(d, "sector_faces");
  t.sectorKeys = tableFrom<std::uint32_t>(d, "sector_keys");
  t.sectorRanges = tableFrom<std::uint32_t>(d, "sector_ranges");
  if (d.contains("slabs")) t.slabs = tableFrom<float>(d, "slabs");  // none: no slab decides
  return t;
}

using CubemapBound = Bound<CubemapLocator>;

// the locator a state describes: loaded from its tables, else rebuilt
CubemapBound fromState(const py::tuple& state) {
  const int kind = state.size() > 0 ? state[0].cast<int>() : 0;
  if (kind == kShapeState && state.size() == 3)
    return buildBound<CubemapLocator, Method3D>(state[1], state[2].cast<std::uint32_t>());
  if (kind != kTablesState || state.size() != 4)
    badState("it was pickled by another version of convexloc");
  const std::uint32_t resolution = state[2].cast<std::uint32_t>();
  std::optional<CubemapTables> tables = tablesFrom(state[3]);
  if (!tables) return buildBound<CubemapLocator, Method3D>(state[1], resolution);
  const py::object shape = shapeArgument<Method3D>(state[1]);
  const auto& polyhedron = shape.cast<const ConvexPolyhedron&>();
  std::optional<CubemapLocator> loaded;
  {
    py::gil_scoped_release released;  // the checks; `shape` stays referenced
    loaded.emplace(polyhedron, *tables);
  }
  return CubemapBound{std::move(*loaded), shape, resolution};
}

}  // namespace

void defineCubemapPickle(py::class_<Bound<CubemapLocator>>& c) {
  c.def(py::pickle(
      [](const CubemapBound& b) {
        return py::make_tuple(kTablesState, b.shape, b.resolution,
                              tablesToPython(b.locator.tables()));
      },
      [](const py::tuple& state) { return fromState(state); }));
}

}  // namespace convexloc::python
