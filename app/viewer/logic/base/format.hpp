// convexloc-viewer — numbers as the viewer writes them: for statistics, counts, timings,
// captions. The exact decimals and the byte sizes are core's (convexloc/format.hpp), the
// same as the command line's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "convexloc/format.hpp"
#include "convexloc/geometry.hpp"

namespace convexloc::viewer {

// `v` with `digits` significant digits, for statistics
std::string approx(double v, int digits = 4);
// `prefix` followed by `n` ("e7", "octant 3")
std::string numbered(std::string_view prefix, std::uint64_t n);
// "y(3)": the slab method's 4th smallest distinct vertex y (from y(0)), named so that it does
// not read as vertex 3's
std::string sortedY(std::size_t rank);
// a time in nanoseconds, to 3 digits without an exponent ("6810", "154", "12.3", "4.07")
std::string nsText(double ns);
// " +", " 0" or " -" (the sign of a predicate, for labels)
std::string signText(int sign);
// "1 234 567": thousands apart, for counts
std::string grouped(std::size_t n);
// Numbers for captions, which must never break across lines: `v` to 6 significant digits
// without spaces ("0.43", "-1.5e+07"), 0 for |v| < 1e-12 * scale (display only: the centre
// (8.28e-21, 0, 0) of a cube of size 2 reads (0, 0, 0)) and for -0.
std::string compact(double v, double scale = 0.0);
// A message with its coordinates in the shortest digits that read back as the same doubles:
// core names a vertex "(0.30000000000000004, 0.59999999999999998)", which reads here
// "(0.30000000000000004, 0.6)". Only parenthesised lists of two or three numbers change.
std::string shortestCoordinates(std::string_view message);
// A typed number: the whole of `text` (spaces around allowed) read as the nearest double
// ("0.1", "-2.5e-3", "1e9"); none for anything else, an overflow or a non-finite value.
std::optional<double> parseNumber(std::string_view text);
// "(x,y)" and "(x,y,z)" with compact(), no spaces
std::string compact(Vec2 p, double scale = 0.0);
std::string compact(Vec3 p, double scale = 0.0);

}  // namespace convexloc::viewer
