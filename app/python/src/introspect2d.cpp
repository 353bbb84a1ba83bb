// convexloc Python module — a 2D locator's trace, statistics and cells as plain Python values.
//
// Keys are core's field names in snake_case; every trace and every cell has every key, so a
// notebook can read any of them without asking which method made it. Points are tuples,
// lists of them numpy arrays, and index lists int64 arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"

namespace convexloc::python {

py::tuple toPython(Vec2 v) {
  return py::make_tuple(v.x, v.y);
}

namespace {

// [(index, sign), ...] of the edge or ray tests
template <class Test, class Index>
py::list tests(const std::vector<Test>& list, Index Test::*index) {
  py::list out;
  for (const Test& t : list) out.append(py::make_tuple(t.*index, t.sign));
  return out;
}

}  // namespace

py::dict traceToPython(const Trace2D& t) {
  py::dict d;
  d["method"] = std::string(toString(t.method));
  d["result"] = static_cast<int>(t.result);
  d["location"] = std::string(toString(t.result));
  d["outside_box"] = t.outsideBox;
  d["cell"] = t.cell;
  d["octant"] = t.octant;
  d["crowded"] = t.crowded;
  d["at_centre"] = t.atCentre;
  d["by_radius"] = t.byRadius;
  d["distance"] = t.distance;
  d["inner_radius"] = t.innerRadius;
  d["outer_radius"] = t.outerRadius;
  d["apex"] = toPython(t.apex);
  d["rays"] = tests(t.rays, &RayTest::vertex);
  d["edges"] = tests(t.edges, &EdgeTest::edge);
  return d;
}

py::dict statsToPython(const Stats2D& s) {
  py::dict d;
  d["edges"] = s.edges;
  d["cells"] = s.cells;
  d["entries"] = s.entries;
  d["max_per_cell"] = s.maxPerCell;
  d["mean_per_cell"] = s.meanPerCell;
  d["crowded_cells"] = s.crowdedCells;
  d["bytes"] = s.bytes;
  d["bytes_per_edge"] = s.bytesPerEdge;
  d["build_seconds"] = s.buildSeconds;
  d["histogram"] = py::cast(s.histogram);
  return d;
}

py::list cellsToPython(const std::vector<Cell2D>& cells) {
  py::list out;
  for (const Cell2D& c : cells) {
    py::dict d;
    d["index"] = c.index;
    d["octant"] = c.octant;
    d["outline"] = coordinateArray<Vec2>(c.outline);
    d["dir_lo"] = toPython(c.dirLo);
    d["dir_hi"] = toPython(c.dirHi);
    d["hit_lo"] = toPython(c.hitLo);
    d["hit_hi"] = toPython(c.hitHi);
    d["y0"] = c.y0;
    d["y1"] = c.y1;
    d["edges"] = indexArray(c.edges);
    out.append(std::move(d));
  }
  return out;
}

}  // namespace convexloc::python
