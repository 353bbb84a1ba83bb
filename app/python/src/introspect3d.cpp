// convexloc Python module — a 3D locator's trace, statistics and cells as plain Python values.
//
// The same conventions as introspect2d.cpp: core's field names in snake_case, every key
// always present, points as tuples, lists of points and of indices as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"

namespace convexloc::python {

py::tuple toPython(Vec3 v) {
  return py::make_tuple(v.x, v.y, v.z);
}

namespace {

// [(face, edge, sign), ...] of a walk's edge tests
py::list walkSteps(const std::vector<WalkTest>& steps) {
  py::list out;
  for (const WalkTest& w : steps) out.append(py::make_tuple(w.face, int{w.edge}, w.sign));
  return out;
}

// [(face, sign), ...] of the plane tests
py::list faceTests(const std::vector<FaceTest>& tests) {
  py::list out;
  for (const FaceTest& f : tests) out.append(py::make_tuple(f.face, f.sign));
  return out;
}

}  // namespace

py::dict traceToPython(const Trace3D& t) {
  py::dict d;
  d["method"] = std::string(toString(t.method));
  d["result"] = static_cast<int>(t.result);
  d["location"] = std::string(toString(t.result));
  d["non_finite"] = t.nonFinite;
  d["at_centre"] = t.atCentre;
  d["fallback"] = t.fallback;
  d["crowded"] = t.crowded;
  d["by_radius"] = t.byRadius;
  d["distance"] = t.distance;
  d["inner_radius"] = t.innerRadius;
  d["outer_radius"] = t.outerRadius;
  d["centre"] = t.centre ? py::object(toPython(*t.centre)) : py::object(py::none());
  d["cube_face"] = t.cubeFace;
  d["level"] = t.level;
  d["cell_i"] = t.cellI;
  d["cell_j"] = t.cellJ;
  d["s"] = t.s;
  d["t"] = t.t;
  d["path"] = indexArray(t.path);
  d["steps"] = walkSteps(t.steps);
  d["faces"] = faceTests(t.faces);
  return d;
}

py::dict statsToPython(const Stats3D& s) {
  py::dict d;
  d["faces"] = s.faces;
  d["vertices"] = s.vertices;
  d["cells"] = s.cells;
  d["nodes"] = s.nodes;
  d["entries"] = s.entries;
  d["max_per_cell"] = s.maxPerCell;
  d["mean_per_cell"] = s.meanPerCell;
  d["crowded_cells"] = s.crowdedCells;
  d["resolution"] = s.resolution;
  d["max_level"] = s.maxLevel;
  d["centred"] = s.centred;
  d["bytes"] = s.bytes;
  d["bytes_per_face"] = s.bytesPerFace;
  d["build_seconds"] = s.buildSeconds;
  d["histogram"] = py::cast(s.histogram);
  return d;
}

py::list cellsToPython(const std::vector<Cell3D>& cells) {
  py::list out;
  for (const Cell3D& c : cells) {
    py::dict d;
    d["index"] = c.index;
    d["cube_face"] = c.cubeFace;
    d["level"] = c.level;
    d["i"] = c.i;
    d["j"] = c.j;
    d["s0"] = c.s0;
    d["s1"] = c.s1;
    d["t0"] = c.t0;
    d["t1"] = c.t1;
    d["apex"] = toPython(c.apex);
    d["corners"] = coordinateArray<Vec3>(c.corners);
    d["faces"] = indexArray(c.faces);
    out.append(std::move(d));
  }
  return out;
}

}  // namespace convexloc::python
