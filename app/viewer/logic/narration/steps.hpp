// convexloc-viewer — a query told step by step, the viewer's one narration of a trace: the placed
// point's trace (core's, never the viewer's own judgement) as a list of steps, each with a short
// caption, the line of the method's pseudo-code it belongs to and what the drawing highlights; and
// the cursor that plays them (next, previous, play at a speed). GL-free and ImGui-free.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polygon.hpp"
#include "logic/base/format.hpp"

namespace convexloc::viewer {

// one line of a narration, coloured by its kind
struct TraceLine {
  enum Kind { Heading, Step, Positive, Zero, Negative, Result } kind = Step;
  std::string text;
};

// what the drawing highlights for one step
enum class StepFocus : std::uint8_t {
  None,
  Box,     // the bounding box (outside it: no cell is needed)
  Search,  // slab: the probe line y = y[item] of the binary search
  Index,   // uniform: eq. (4)'s slab; polar: the octant and the ratio's slab
  Octant,  // polar: the octant holding the direction from the centre
  Cell,    // the cell the index chose (slab, uniform slab, polar cell, cube-map cell)
  Radii,   // polar, cube map: the cell's two radii around the centre
  Ray,     // a ray from the apex through vertex `item`, tested with `sign`
  Edge,    // edge `item`, tested with `sign`
  Walk,    // walk: edge `sub` of face `item`, tested with `sign`
  Face,    // face `item`'s plane, tested with `sign`
  Result   // the answer
};

// one step of a query
struct Step {
  std::string caption;  // "edge 5: orient2d = +1 (inner side)"
  int line = 0;         // the pseudo-code line it belongs to
  StepFocus focus = StepFocus::None;
  std::int64_t item = -1;  // the edge, vertex, face, cell or probe it is about
  int sub = 0;             // walk: the face's edge
  int sign = 0;            // the predicate's sign, where the step tests one
  TraceLine::Kind kind = TraceLine::Step;
};

// the steps of one query and the method's pseudo-code
struct StepModel {
  std::string title;              // "polar: point (0.25, 0.5)"
  std::string note;               // what mode the trace ran in, or empty
  std::vector<std::string> code;  // the method's pseudo-code, a few lines
  std::vector<Step> steps;        // in order; the last is the result
};

// The steps of a 2D query: `point` was traced into `trace` by a locator of `polygon`.
StepModel buildSteps(const Trace2D& trace, Vec2 point, const ConvexPolygon& polygon);

// The steps of a 3D query; `scale` (the shape's size) snaps tiny coordinates to 0 for
// display.
StepModel buildSteps3D(const Trace3D& trace, Vec3 point, double scale);

// The trace of one query as the inspector lists it: the steps' title, every step's caption
// (the same sentences as the Steps window's) and the result with how many predicates were
// evaluated.
std::vector<TraceLine> describeTrace(const Trace2D& trace, Vec2 point,
                                     const ConvexPolygon& polygon);
// The same for a 3D query; `scale` (the shape's size) snaps tiny coordinates to 0.
std::vector<TraceLine> describeTrace3D(const Trace3D& trace, Vec3 point, double scale);

// the step shown for an asked step `k` among `count`: -1 (all shown) stays -1, a step
// beyond the end is the last one, none below -1
int clampStep(int k, std::size_t count);

// the step after (`forward`) or before `k` among `count`; stepping from -1 (all shown)
// starts at the first step (or the last one, backwards)
int nextStep(int k, std::size_t count, bool forward);

// Play: the step to show at `now` (seconds), advancing one step per 1 / speed seconds and
// stopping at the last.
struct StepPlayer {
  bool playing = false;
  float speed = 1.0f;  // steps per second
  double last = 0.0;   // when the shown step was reached
  // starts playing at `now`, from the first step when at the end or showing all
  void start(int& step, std::size_t count, double now);
  // the step to show now; stops playing at the last step
  int tick(int step, std::size_t count, double now);
};

}  // namespace convexloc::viewer
