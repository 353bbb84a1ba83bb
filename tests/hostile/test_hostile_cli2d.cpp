// Hostile and huge inputs to the real `convexloc` binary: each gets the exact answer or a
// clear error (exit 1, "FILE:LINE: problem" on stderr, nothing on stdout), never a crash, a
// hang, a blow-up of memory or a silent wrong answer. Big inputs are generated here, in a
// temporary directory; CONVEXLOC_HOSTILE_SCALE shrinks them (the sanitized run uses 0.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/text_reader.hpp"
#include "fuzz_support.hpp"
#include "tool.hpp"

namespace {

using namespace std::string_literals;
using convexloc::kMaxLineBytes;
using convexloc::Vec2;
using fuzz::exactLocate;
using hostile::runTool;
using hostile::TempDir;
using hostile::ToolRun;
using hostile::writeFile;

const char* const kMethods[] = {"halfplane", "wedge", "slab", "uniform", "polar"};
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

// the shortest text that reads back as the same double
std::string text(double v) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

std::string lines(const std::vector<Vec2>& points) {
  std::string out;
  for (Vec2 p : points) out += text(p.x) + " " + text(p.y) + "\n";
  return out;
}

// the answer lines for a list of locations
std::string answers(const std::vector<convexloc::Location>& where) {
  std::string out;
  for (auto l : where) out += std::string(convexloc::toString(l)) + "\n";
  return out;
}

// a clean rejection: exit 1, nothing on stdout, one short printable line on stderr that
// starts with "FILE:LINE: " (or "FILE: " for line 0) and contains `message`
void expectRejected(const ToolRun& r, const std::string& file, std::size_t line,
                    const std::string& message) {
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.outBytes, 0u) << "stdout must stay empty on bad input";
  std::string where = file;  // appended: g++ 12 warns falsely on "x" + string (-Wrestrict)
  if (line) where.append(":").append(std::to_string(line));
  where.append(": ");
  EXPECT_EQ(r.err.rfind(where, 0), 0u) << "stderr: " << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "stderr: " << r.err;
  EXPECT_LT(r.err.size(), 400u) << "the message must stay short";
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (char c : r.err)
    EXPECT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7f)) << "unprintable byte in: " << r.err;
}

// Classifies `points` against `polygon` with every method through files, and checks every
// answer against the exact rational reference.
void expectExactEveryMethod(const std::vector<Vec2>& polygon, const std::vector<Vec2>& points) {
  TempDir dir;
  writeFile(dir.file("shape.txt"), lines(polygon));
  writeFile(dir.file("points.txt"), lines(points));
  convexloc::ConvexPolygon poly(polygon);
  std::vector<convexloc::Location> where;
  for (Vec2 p : points) where.push_back(exactLocate(poly.vertices(), p));
  const std::string want = answers(where);
  for (const char* m : kMethods) {
    ToolRun r = runTool({"classify", dir.file("shape.txt"), dir.file("points.txt"), "--method", m});
    EXPECT_EQ(r.status, 0) << m << ": " << r.err;
    EXPECT_EQ(r.out, want) << "method " << m;
  }
}

// a polygon's vertices, each with its one-ulp neighbours, the edge midpoints, and `extra`
std::vector<Vec2> hardPoints(const std::vector<Vec2>& polygon, std::vector<Vec2> extra) {
  std::vector<Vec2> out = std::move(extra);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    out.push_back(a);
    fuzz::addNeighbours(out, a);
    out.push_back({a.x / 2 + b.x / 2, a.y / 2 + b.y / 2});
  }
  return out;
}

const std::vector<Vec2> kUnitSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

// === Long lines (the reader's limit is kMaxLineBytes = 1 MiB)

// "0.25" then blanks then "0.75": a valid point on a line of exactly `length` bytes
std::string paddedPoint(std::size_t length) {
  std::string s = "0.25";
  s.append(length - 8, ' ');
  return s + "0.75";
}

TEST(HostileCli, LinesUpToTheLimitAreRead) {
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  // LF, CRLF and no final newline, each exactly at the limit (the '\r' is not counted)
  writeFile(dir.file("points.txt"), "0.5 0.5\n" + paddedPoint(kMaxLineBytes) + "\n" +
                                        paddedPoint(kMaxLineBytes) + "\r\n" +
                                        paddedPoint(kMaxLineBytes));
  ToolRun r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt")});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "inside\ninside\ninside\ninside\n");
}

TEST(HostileCli, LinesPastTheLimitAreRejectedWithTheirNumber) {
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  const std::string tooLong = paddedPoint(kMaxLineBytes + 1);
  const std::string limit = "line longer than " + std::to_string(kMaxLineBytes) + " bytes";
  for (const std::string tail : {"\n", "\r\n", ""}) {
    // LF, CRLF, and the last line without a newline
    writeFile(dir.file("points.txt"),
              "0.5 0.5\n# two\n" + tooLong + tail + (tail.empty() ? "" : "0.5 0.5\n"));
    ToolRun r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt")});
    expectRejected(r, dir.file("points.txt"), 3, limit);
  }
  // the same limit for a shape
  writeFile(dir.file("shape.txt"), "0 0\n" + tooLong + "\n1 1\n");
  ToolRun r = runTool({"classify", dir.file("shape.txt"), dir.file("square.txt")});
  expectRejected(r, dir.file("shape.txt"), 2, limit);
}

TEST(HostileCli, AnEndlessLineIsRejectedInBoundedMemory) {
  // 64 MiB of digits and no newline: one "number" far past the limit
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  std::size_t left = std::size_t{64} << 20;
  hostile::writeBig(dir.file("digits.txt"), [&](std::string& buf) {
    std::size_t n = std::min<std::size_t>(left, 1 << 16);
    buf.append(n, '7');
    left -= n;
    return left > 0;
  });
  ToolRun r = runTool({"classify", dir.file("square.txt"), dir.file("digits.txt")});
  expectRejected(r, dir.file("digits.txt"), 1, "line longer than");
  EXPECT_LT(r.maxRssKiB, 48 * 1024) << "the reader must not hold the line";
}

TEST(HostileCli, MillionDigitNumbersRoundToTheNearestDouble) {
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  // 1 followed by 999,000 zeros, times 10^-999000: exactly 1 (the right edge)
  std::string one = "1";
  one.append(999000, '0').append("e-999000");
  // 0.000...0005 with a million zeros: far below the smallest double, so 0 (the left edge)
  std::string zero = "0.";
  zero.append(1000000, '0').append("5");
  // 0.4999...9 with 500,000 nines: rounds up to exactly 0.5
  std::string half = "0.4";
  half.append(500000, '9');
  std::string points = one;
  points.append(" 0.5\n").append(zero).append(" 0.5\n").append(half).append(" ").append(half);
  points.append("\n-").append(one).append(" 0.5\n");
  writeFile(dir.file("points.txt"), points);
  ToolRun r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt")});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "boundary\nboundary\ninside\noutside\n");
}

TEST(HostileCli, AMillionCharactersOfGarbageGetAShortMessage) {
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  std::string garbage(1000000, 'x');
  for (std::size_t i = 0; i < garbage.size(); i += 7) garbage[i] = static_cast<char>(i % 251);
  for (char& c : garbage)
    if (c == '\n' || c == '#') c = '?';
  garbage[0] = 'q';
  writeFile(dir.file("points.txt"), "0.5 0.5\n" + garbage + "\n");
  ToolRun r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt")});
  expectRejected(r, dir.file("points.txt"), 2, "not a number: 'q");
}

// === Extreme numbers

TEST(HostileCli, ExtremeNumbersParseExactly) {
  // 1e308 squares: differences of coordinates overflow a double
  std::vector<Vec2> big = {{-1e308, -1e308}, {1e308, -1e308}, {1e308, 1e308}, {-1e308, 1e308}};
  expectExactEveryMethod(big, hardPoints(big, {{0, 0},
                                               {kMax, 0},
                                               {-kMax, kMax},
                                               {1e308, 0},
                                               {std::nextafter(1e308, 0.0), -0.0},
                                               {kTiny, kTiny}}));
  // the smallest subnormals: a square 4 ulps of zero wide
  std::vector<Vec2> tiny = {{0, 0}, {4 * kTiny, 0}, {4 * kTiny, 4 * kTiny}, {0, 4 * kTiny}};
  expectExactEveryMethod(tiny, hardPoints(tiny, {{2 * kTiny, 2 * kTiny},
                                                 {-0.0, 2 * kTiny},
                                                 {2 * kTiny, -0.0},
                                                 {-0.0, -0.0},
                                                 {5 * kTiny, 0},
                                                 {-kTiny, 0},
                                                 {1, 1},
                                                 {0, 0}}));
  // -0.0 everywhere it can be
  std::vector<Vec2> negZero = {{-0.0, -0.0}, {1, -0.0}, {-0.0, 1}};
  expectExactEveryMethod(
      negZero, hardPoints(negZero, {{-0.0, 0.5}, {0.5, -0.0}, {0, 0}, {0.5, 0.5}, {-kTiny, -0.0}}));
}

TEST(HostileCli, CoordinatesNearTheLargestDouble) {
  // a triangle spanning the whole double range: every difference overflows
  std::vector<Vec2> huge = {{-kMax, -kMax}, {kMax, -kMax}, {0, kMax}};
  expectExactEveryMethod(
      huge,
      hardPoints(
          huge,
          {{0, 0}, {kMax / 2, 0}, {kMax / 2, 1e300}, {-kMax / 2, 0}, {-kMax, kMax}, {kMax, kMax}}));
  // a thin needle near the top of the range
  std::vector<Vec2> needle = {
      {kMax, kMax}, {std::nextafter(kMax, 0.0), kMax}, {kMax, std::nextafter(kMax, 0.0)}};
  expectExactEveryMethod(needle, hardPoints(needle, {{kMax, kMax}, {0, 0}}));
}

TEST(HostileCli, ScalesTenToThe300Apart) {
  // vertices at 1e-150 and 1e150 magnitudes in one polygon
  std::vector<Vec2> mixed = {
      {-1e150, -1e-150}, {1e-150, -1e150}, {1e150, 1e-150}, {-1e-150, 1e150}};
  expectExactEveryMethod(
      mixed,
      hardPoints(
          mixed,
          {{0, 0}, {1e-150, 1e-150}, {1e149, 1e149}, {5e149, 5e149}, {1e150, 0}, {-1e150, 0}}));
  // a sliver 10^300 times longer than wide
  std::vector<Vec2> sliver = {{0, 0}, {1e150, 1e-150}, {1e150, 2e-150}, {0, 1e-150}};
  expectExactEveryMethod(
      sliver,
      hardPoints(sliver,
                 {{5e149, 1e-150}, {5e149, 1.5e-150}, {1e-300, 1e-300}, {1e150, 1.5e-150}}));
  // subnormal and huge vertices together
  std::vector<Vec2> span = {{kTiny, 0}, {1e300, kTiny}, {0, 1e300}};
  expectExactEveryMethod(span, hardPoints(span, {{1, 1}, {kTiny, kTiny}, {1e299, 1e299}}));
}

TEST(HostileCli, NumbersOutOfRangeAreRejected) {
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  struct Case {
    std::string line;
    std::string message;
  };
  const Case cases[] = {{"1e309 0", "out of the range of double"},
                        {"0 -1.7976931348623159e308", "out of the range of double"},
                        {"1e99999999999999999999 0", "out of the range of double"},
                        {"inf 0", "not a number"},
                        {"nan 0", "not a number"},
                        {"0x1p3 0", "not a number"},
                        {"0 1e", "not a number"},
                        {"--1 0", "not a number"}};
  for (const Case& c : cases) {
    writeFile(dir.file("points.txt"), "0.5 0.5\n" + c.line + "\n");
    ToolRun r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt")});
    SCOPED_TRACE(c.line);
    expectRejected(r, dir.file("points.txt"), 2, c.message);
  }
  // underflow is not an error: it rounds to (signed) zero, as strtod does
  writeFile(dir.file("points.txt"),
            "1e-99999999999999999999 0.5\n-2e-324 0.5\n3e-324 0.5\n"
            "1.7976931348623158e308 0.5\n");
  ToolRun r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt")});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "boundary\nboundary\ninside\noutside\n");
}

// === Line ends and file ends

TEST(HostileCli, LineEndsAndFileEnds) {
  TempDir dir;
  struct Case {
    std::string shape;
    bool ok;
    std::size_t line;  // of the error
    std::string message;
  };
  const Case cases[] = {
      {"0 0\n1 0\n1 1\n0 1", true, 0, ""},                             // no final newline
      {"0 0\r\n1 0\r\n1 1\r\n0 1\r\n", true, 0, ""},                   // CRLF
      {"0 0\r\n1 0\n1 1\r\n0 1", true, 0, ""},                         // mixed, no final newline
      {"\r\n0 0\r\n\r\n1 0\n1 1\n0 1\n\r\n", true, 0, ""},             // blank CRLF lines
      {"0 0\n1 0\n1 1\n0 1\n# the end", true, 0, ""},                  // a final comment
      {"0 0\n1 0\n1 1\n0 ", false, 4, "expected 2 numbers, found 1"},  // ends mid-line
      {"0 0\n1 0\n1 1\n0 1e", false, 4, "not a number"},               // ends mid-number
      {"0 0\n1 0\n1 1\n0 1,", false, 4, "unexpected text"},            // ends after a separator
      {"0 0\r1 0\r1 1\r0 1\r", false, 1, "not a number"},  // old Mac line ends: one line
      {"0 0\n1 0\n\0\x01\n0 1\n"s, false, 3, "not a number: '\\x00\\x01'"},  // a NUL
      {"0 0\n1\t0\v\n1 1\f\n0 1 \t\n", true, 0, ""},  // every blank character
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.shape);
    writeFile(dir.file("shape.txt"), c.shape);
    writeFile(dir.file("points.txt"), "0.5 0.5\n2 2\n1 1\n");
    ToolRun r = runTool({"classify", dir.file("shape.txt"), dir.file("points.txt")});
    if (c.ok) {
      EXPECT_EQ(r.status, 0) << r.err;
      EXPECT_EQ(r.out, "inside\noutside\nboundary\n");
    } else {
      expectRejected(r, dir.file("shape.txt"), c.line, c.message);
    }
  }
}

// === Binary garbage

TEST(HostileCli, BinaryGarbageIsRejectedCleanly) {
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  convexloc::Rng rng(6);
  for (int round = 0; round < 8; ++round) {
    // random bytes; some rounds without newlines, some without NULs, one mostly digits
    std::string bytes(std::size_t{1} << (12 + round), '\0');
    for (char& c : bytes) {
      auto b = static_cast<unsigned char>(rng.next());
      if (round % 2 == 1 && b == '\n') b = ' ';
      if (round == 4) b = "0123456789 .e-\n"[b % 15];
      c = static_cast<char>(b);
    }
    writeFile(dir.file("garbage.bin"), bytes);
    SCOPED_TRACE("round " + std::to_string(round));
    for (bool asShape : {true, false}) {
      ToolRun r = asShape ? runTool({"classify", dir.file("garbage.bin"), dir.file("square.txt")})
                          : runTool({"classify", dir.file("square.txt"), dir.file("garbage.bin")});
      EXPECT_EQ(r.status, 1) << r.err;
      EXPECT_EQ(r.outBytes, 0u);
      EXPECT_EQ(r.err.rfind(dir.file("garbage.bin") + ":", 0), 0u) << r.err;
      EXPECT_LT(r.err.size(), 400u) << r.err;
      for (char c : r.err) EXPECT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7f)) << r.err;
    }
  }
  // the tool's own executable, as a shape and as points
  ToolRun r = runTool({"classify", hostile::kBin, dir.file("square.txt")});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.outBytes, 0u);
  r = runTool({"info", hostile::kBin});
  EXPECT_EQ(r.status, 1) << r.err;
  r = runTool({"classify", dir.file("square.txt"), hostile::kBin});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.outBytes, 0u);
}

// === Huge inputs

// Writes `count` query points against the unit square that cycle through inside, boundary
// and outside, so that the answers can be counted.
std::function<bool(std::string&)> cyclingPoints(std::size_t count) {
  return [count, i = std::size_t{0}](std::string& buf) mutable {
    static const char* const kCycle[] = {"0.5 0.25\n", "1 0.75\n", "2.5,-1\n"};
    for (int k = 0; k < 4096 && i < count; ++k, ++i) buf += kCycle[i % 3];
    return i < count;
  };
}

TEST(HostileCli, TenMillionPointsStreamInConstantMemory) {
  const std::size_t n = hostile::scaled(10'000'000, 100'000);
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  writeFile(dir.file("few.txt"), "0.5 0.25\n1 0.75\n2.5,-1\n");
  hostile::writeBig(dir.file("many.txt"), cyclingPoints(n));
  hostile::Options keep;
  ToolRun few = runTool({"classify", dir.file("square.txt"), dir.file("few.txt")}, keep);
  ASSERT_EQ(few.status, 0) << few.err;
  hostile::Options count;
  count.keepOut = false;
  ToolRun many = runTool({"classify", dir.file("square.txt"), dir.file("many.txt")}, count);
  ASSERT_EQ(many.status, 0) << many.err;
  EXPECT_EQ(many.outLines, n);
  EXPECT_EQ(many.answers[0], (n + 2) / 3);
  EXPECT_EQ(many.answers[1], (n + 1) / 3);
  EXPECT_EQ(many.answers[2], n / 3);
  // from standard input too (spooled to a temporary file, not to memory)
  count.stdinFill = cyclingPoints(n);
  ToolRun piped = runTool({"classify", dir.file("square.txt"), "-"}, count);
  ASSERT_EQ(piped.status, 0) << piped.err;
  EXPECT_EQ(piped.answers, many.answers);
  std::printf(
      "[ figures  ] %zu points: %.2f s from a file, %.2f s from a pipe; peak memory "
      "%ld KiB for 3 points, %ld KiB (file) and %ld KiB (pipe) for %zu\n",
      n, many.seconds, piped.seconds, few.maxRssKiB, many.maxRssKiB, piped.maxRssKiB, n);
  EXPECT_LT(many.maxRssKiB, few.maxRssKiB + hostile::constantMemorySlackKiB())
      << "memory grew with the points";
  EXPECT_LT(piped.maxRssKiB, few.maxRssKiB + hostile::constantMemorySlackKiB())
      << "memory grew with the points";
}

TEST(HostileCli, TenMillionVertices) {
  // a regular 10^7-gon from the tool's own generator, classified with every method
  const std::size_t n = hostile::scaled(10'000'000, 100'000);
  TempDir dir;
  hostile::Options toFile;
  toFile.stdoutPath = dir.file("polygon.txt");
  ToolRun gen =
      runTool({"generate", "polygon", "--kind", "regular", "--n", std::to_string(n), "--seed", "1"},
              toFile);
  ASSERT_EQ(gen.status, 0) << gen.err;
  // vertex 0 is (1, 0): on it, one ulp out, one ulp in; the centre; far out; inside the
  // inscribed circle (radius cos(pi/n) > 1 - 5e-10 for n >= 10^5); outside the unit circle
  const std::string points =
      "1 0\n1.0000000000000002 0\n0.9999999999999999 0\n0 0\n"
      "3 -4\n0 0.999999999\n-0.707 -0.707\n0 1.000000001\n";
  const std::string want = "boundary\noutside\ninside\ninside\noutside\ninside\ninside\noutside\n";
  writeFile(dir.file("points.txt"), points);
  for (const char* m : kMethods) {
    ToolRun r =
        runTool({"classify", dir.file("polygon.txt"), dir.file("points.txt"), "--method", m});
    EXPECT_EQ(r.status, 0) << m << ": " << r.err;
    EXPECT_EQ(r.out, want) << m;
    std::printf(
        "[ figures  ] %zu-gon, %-9s classify: %.2f s, peak memory %ld MiB (%.0f bytes "
        "per vertex)\n",
        n, m, r.seconds, r.maxRssKiB / 1024, r.maxRssKiB * 1024.0 / static_cast<double>(n));
    // reading (24 bytes a vertex, doubling), the polygon (20), the locator (<= 64 + 16)
    EXPECT_LT(static_cast<double>(r.maxRssKiB) * 1024, 200.0 * static_cast<double>(n) + 64e6) << m;
  }
  ToolRun info = runTool({"info", dir.file("polygon.txt"), "--method", "polar"});
  EXPECT_EQ(info.status, 0) << info.err;
  std::printf("[ figures  ] %zu-gon generated in %.2f s; info --method polar:\n%s\n", n,
              gen.seconds, info.out.c_str());
}

TEST(HostileCli, HugeDegeneratePolygonsAreRejectedQuickly) {
  const std::size_t n = hostile::scaled(1'000'000, 100'000);
  TempDir dir;
  struct Case {
    const char* name;
    std::function<Vec2(std::size_t)> vertex;
    std::string message;
  };
  const Case cases[] = {
      {"one point repeated",
       [](std::size_t) {
         return Vec2{3, 4};
       },
       "fewer than 3 distinct"},
      {"collinear",
       [](std::size_t i) {
         return Vec2{double(i), 2.0 * double(i)};
       },
       "collinear"},
      {"a zigzag",
       [](std::size_t i) {
         return Vec2{double(i), double(i % 2)};
       },
       "not convex"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::size_t i = 0;
    hostile::writeBig(dir.file("shape.txt"), [&](std::string& buf) {
      for (int k = 0; k < 4096 && i < n; ++k, ++i) {
        Vec2 v = c.vertex(i);
        buf += text(v.x) + " " + text(v.y) + "\n";
      }
      return i < n;
    });
    ToolRun r = runTool({"classify", dir.file("shape.txt"), "-"});
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(r.outBytes, 0u);
    EXPECT_LT(r.seconds, 60.0);
  }
}

// === Past the tools' limits

TEST(HostileCli, LimitsOfTheTools) {
  TempDir dir;
  writeFile(dir.file("square.txt"), lines(kUnitSquare));
  writeFile(dir.file("points.txt"), "0.5 0.5\n");
  // generating past 2^26 vertices, and grids past their limits, are usage errors
  ToolRun r = runTool({"generate", "polygon", "--kind", "regular", "--n", "67108865"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("2^26"), std::string::npos) << r.err;
  r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt"), "--method", "polar",
               "--resolution", "8388609"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("2^23"), std::string::npos) << r.err;
  r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt"), "--method", "uniform",
               "--resolution", "67108865"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("2^26"), std::string::npos) << r.err;
  r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt"), "--resolution",
               "99999999999999999999999"});
  EXPECT_EQ(r.status, 2) << r.err;
  // the largest grids still accepted work on a small polygon, and answer exactly
  r = runTool({"classify", dir.file("square.txt"), dir.file("points.txt"), "--method", "polar",
               "--resolution", "8388608"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "inside\n");
}

}  // namespace
