// convexloc CLI (internal) — `info --intersect`: the line and plane methods in numbers,
// the section info.cpp adds after the locators' table.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "commands.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"

namespace convexloc::cli {

// one intersection method in numbers; `built` false for a dual left unbuilt
struct DualRow {
  std::string name, cost;
  bool built = true;
  std::size_t dualSize = 0, cells = 0, entries = 0, maxPerCell = 0, bytes = 0;
  double bytesPer = 0.0, buildSeconds = 0.0;
  std::string measured;  // the dual's work per query on random queries, a sentence
};

// the words of one dimension's intersection section
struct DualWords {
  const char* title;    // "Line methods": what the section lists
  const char* element;  // "edge": what the memory is counted per
  const char* note;     // what 'dual size' and 'max' count
};

// the words of the 2D (lines) and 3D (planes) sections
extern const DualWords kLineWords;
extern const DualWords kPlaneWords;

// the line methods built on the polygon, measured
std::vector<DualRow> lineRows(const ConvexPolygon& polygon);
// the plane methods built on the polyhedron (the dual one only when `buildDual`), measured
std::vector<DualRow> planeRows(const ConvexPolyhedron& polyhedron, bool buildDual);
// the section: its title, a row per method, the note on what the columns count
void reportDualTable(Output& out, const std::vector<DualRow>& rows, const DualWords& words);

}  // namespace convexloc::cli
