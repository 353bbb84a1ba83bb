// convexloc-viewer — words for the inspector: numbers that read back to the same double,
// and a trace told step by step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polygon.hpp"

namespace convexloc::viewer {

// the shortest decimal that reads back to exactly `v`
std::string exact(double v);
// "(x, y)" with exact()
std::string exact(Vec2 p);
// `v` with `digits` significant digits, for statistics
std::string approx(double v, int digits = 4);
// `prefix` followed by `n` ("e7", "octant 3")
std::string numbered(std::string_view prefix, std::uint64_t n);
// a time in nanoseconds, to 3 digits without an exponent ("6810", "154", "12.3", "4.07")
std::string nsText(double ns);
// " +", " 0" or " -" (the sign of a predicate, for labels)
std::string signText(int sign);
// "1 234 567": thousands apart, for counts
std::string grouped(std::size_t n);
// "12.3 kB", "4.0 MB"
std::string bytesText(std::size_t bytes);

// Numbers for captions, which must never break across lines: `v` to 6 significant digits
// without spaces ("0.43", "-1.5e+07"), 0 for |v| < 1e-12 * scale (display only: the centre
// (8.28e-21, 0, 0) of a cube of size 2 reads (0, 0, 0)) and for -0.
std::string compact(double v, double scale = 0.0);
// "(x,y)" and "(x,y,z)" with compact(), no spaces
std::string compact(Vec2 p, double scale = 0.0);
std::string compact(Vec3 p, double scale = 0.0);

// one line of the inspector
struct TraceLine {
  enum Kind { Heading, Step, Positive, Zero, Negative, Result } kind = Step;
  std::string text;
};

// The trace of one query, told for a student: where the point went (box, octant, cell,
// wedge), each predicate evaluated with its sign, and the result. `q` is the polar slabs
// per octant (0 for other methods).
std::vector<TraceLine> describeTrace(const Trace2D& trace, Vec2 point, const ConvexPolygon& polygon,
                                     std::uint32_t q);

// "(x, y, z)" with exact()
std::string exact(Vec3 p);

// The trace of one 3D query, told for a student: the cube face and cell of the direction
// from the centre (cube map), the faces walked across and each edge test of the walk, each
// plane tested with its sign, the result. `scale` (the shape's size) snaps the centre's tiny
// coordinates to 0.
std::vector<TraceLine> describeTrace3D(const Trace3D& trace, Vec3 point, double scale = 0.0);

}  // namespace convexloc::viewer
