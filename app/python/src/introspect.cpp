// convexloc Python module — a locator's trace, statistics and cells as plain Python values.
//
// Keys are core's field names in snake_case; every trace and every cell of a dimension has
// every key, so a notebook can read any of them without asking which method made it. Points
// are tuples, lists of points and of indices numpy arrays. What Trace2D and Trace3D (Stats2D
// and Stats3D) share is written once.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"

namespace convexloc::python {

py::tuple toPython(Vec2 v) {
  return py::make_tuple(v.x, v.y);
}

py::tuple toPython(Vec3 v) {
  return py::make_tuple(v.x, v.y, v.z);
}

namespace {

// [(index, sign), ...] of edge, ray or plane tests
template <class Test, class Index>
py::list signs(const std::vector<Test>& tests, Index Test::*index) {
  py::list out;
  for (const Test& t : tests) out.append(py::make_tuple(t.*index, t.sign));
  return out;
}

// the keys every trace has: the method, the result, and the cell's shortcuts
template <class Trace>
py::dict traceCommon(const Trace& t) {
  py::dict d;
  d["method"] = std::string(toString(t.method));
  d["result"] = static_cast<int>(t.result);
  // the same convexloc.Location value locate's code names, and its name in words
  d["location"] = py::module_::import("convexloc").attr("Location")(static_cast<int>(t.result));
  d["location_name"] = std::string(toString(t.result));
  d["crowded"] = t.crowded;
  d["at_centre"] = t.atCentre;
  d["by_radius"] = t.byRadius;
  d["distance"] = t.distance;
  d["inner_radius"] = t.innerRadius;
  d["outer_radius"] = t.outerRadius;
  return d;
}

// the keys every statistics dict has
template <class Stats>
py::dict statsCommon(const Stats& s) {
  py::dict d;
  d["cells"] = s.cells, d["entries"] = s.entries, d["crowded_cells"] = s.crowdedCells;
  d["max_per_cell"] = s.maxPerCell, d["mean_per_cell"] = s.meanPerCell;
  d["bytes"] = s.bytes, d["build_seconds"] = s.buildSeconds;
  d["histogram"] = py::cast(s.histogram);
  return d;
}

// one dict per cell, `fill` adding the keys of its dimension after the index
template <class Cell, class Fill>
py::list cellList(const std::vector<Cell>& cells, Fill fill) {
  py::list out;
  for (const Cell& c : cells) {
    py::dict d;
    d["index"] = c.index;
    fill(d, c);
    out.append(std::move(d));
  }
  return out;
}

}  // namespace

// === 2D

py::dict traceToPython(const Trace2D& t) {
  py::dict d = traceCommon(t);
  d["outside_box"] = t.outsideBox;
  d["cell"] = t.cell;
  d["octant"] = t.octant;
  d["apex"] = toPython(t.apex);
  d["rays"] = signs(t.rays, &RayTest::vertex);
  d["edges"] = signs(t.edges, &EdgeTest::edge);
  d["radius_filter"] = t.radiusFilter;
  py::list probes;
  for (const SlabProbe& s : t.probes) probes.append(py::make_tuple(s.rank, s.y, s.above));
  d["probes"] = probes;
  py::dict uniform;
  uniform["y_min"] = t.uniform.yMin, uniform["height"] = t.uniform.height;
  uniform["value"] = t.uniform.value, uniform["slabs"] = t.uniform.slabs;
  d["uniform"] = uniform;
  py::dict polar;
  polar["direction"] = toPython(t.polar.direction), polar["ratio"] = t.polar.ratio;
  polar["steep"] = t.polar.steep, polar["slab"] = t.polar.slab, polar["slabs"] = t.polar.slabs;
  polar["base"] = t.polar.base, polar["step"] = t.polar.step;
  d["polar"] = polar;
  return d;
}

py::dict statsToPython(const Stats2D& s) {
  py::dict d = statsCommon(s);
  d["edges"] = s.edges;
  d["bytes_per_edge"] = s.bytesPerEdge;
  return d;
}

py::list cellsToPython(const std::vector<Cell2D>& cells) {
  return cellList(cells, [](py::dict& d, const Cell2D& c) {
    d["octant"] = c.octant;
    d["outline"] = coordinateArray<Vec2>(c.outline);
    d["dir_lo"] = toPython(c.dirLo), d["dir_hi"] = toPython(c.dirHi);
    d["hit_lo"] = toPython(c.hitLo), d["hit_hi"] = toPython(c.hitHi);
    d["y0"] = c.y0, d["y1"] = c.y1;
    d["edges"] = indexArray(c.edges);
  });
}

// === 3D

py::dict traceToPython(const Trace3D& t) {
  py::dict d = traceCommon(t);
  d["non_finite"] = t.nonFinite;
  d["fallback"] = t.fallback;
  d["centre"] = t.centre ? py::object(toPython(*t.centre)) : py::object(py::none());
  d["cube_face"] = t.cubeFace;
  d["level"] = t.level;
  d["cell_i"] = t.cellI, d["cell_j"] = t.cellJ;
  d["s"] = t.s, d["t"] = t.t;
  d["path"] = indexArray(t.path);
  py::list steps;
  for (const WalkTest& w : t.steps) steps.append(py::make_tuple(w.face, int{w.edge}, w.sign));
  d["steps"] = steps;
  d["faces"] = signs(t.faces, &FaceTest::face);
  py::list zone;
  for (const ZoneTest& z : t.zoneSteps) zone.append(py::make_tuple(z.edge, z.a, z.b, z.sign));
  d["zone_steps"] = zone;
  py::list fan;
  for (const SectorTest& z : t.sectorSteps) fan.append(py::make_tuple(z.index, z.vertex, z.sign));
  d["sector_steps"] = fan;
  d["radius_filter"] = t.radiusFilter;
  d["direction"] = toPython(t.direction);
  d["cells_per_side"] = t.cellsPerSide;
  return d;
}

py::dict statsToPython(const Stats3D& s) {
  py::dict d = statsCommon(s);
  d["faces"] = s.faces, d["triangles"] = s.triangles, d["vertices"] = s.vertices;
  d["nodes"] = s.nodes, d["zone_cells"] = s.zoneCells;
  d["sector_cells"] = s.sectorCells;
  d["resolution"] = s.resolution, d["max_level"] = s.maxLevel, d["centred"] = s.centred;
  d["bytes_per_face"] = s.bytesPerFace;
  return d;
}

py::list cellsToPython(const std::vector<Cell3D>& cells) {
  return cellList(cells, [](py::dict& d, const Cell3D& c) {
    d["cube_face"] = c.cubeFace, d["level"] = c.level;
    d["i"] = c.i, d["j"] = c.j;
    d["s0"] = c.s0, d["s1"] = c.s1, d["t0"] = c.t0, d["t1"] = c.t1;
    d["apex"] = toPython(c.apex);
    d["corners"] = coordinateArray<Vec3>(c.corners);
    d["faces"] = indexArray(c.faces);
  });
}

}  // namespace convexloc::python
