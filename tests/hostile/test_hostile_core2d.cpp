// Hostile inputs to the core library, where the CLI tests cannot look closely: the exact
// doubles the reader makes of extreme numbers, the line limit at its exact edge, every
// locator on extreme polygons against the exact reference over many points, and a polygon
// of 10^7 vertices built and queried with every method (CONVEXLOC_HOSTILE_SCALE shrinks it).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/text_reader.hpp"
#include "fuzz_support.hpp"
#include "tool.hpp"

namespace {

using convexloc::ConvexPolygon;
using convexloc::kMaxLineBytes;
using convexloc::Location;
using convexloc::Locator2D;
using convexloc::ParseError;
using convexloc::Vec2;

constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

// the one number parseRow reads from `text`
double parseOne(const std::string& text) {
  double v[1];
  EXPECT_TRUE(convexloc::parseRow(text, 1, 1, v)) << text;
  return v[0];
}

// true when a and b are the same double, sign of zero included
bool same(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// === Numbers

TEST(HostileCore, ExtremeNumbersReadAsTheNearestDouble) {
  EXPECT_TRUE(same(parseOne("1e308"), 1e308));
  EXPECT_TRUE(same(parseOne("1.7976931348623157e308"), kMax));
  EXPECT_TRUE(same(parseOne("1.7976931348623158e308"), kMax));  // rounds down to the max
  EXPECT_TRUE(same(parseOne("-1.7976931348623157e308"), -kMax));
  EXPECT_TRUE(same(parseOne("5e-324"), kTiny));
  EXPECT_TRUE(same(parseOne("4.9406564584124654e-324"), kTiny));
  EXPECT_TRUE(same(parseOne("3e-324"), kTiny));                   // rounds up to the smallest
  EXPECT_TRUE(same(parseOne("2.4703282292062328e-324"), kTiny));  // just above half of it
  EXPECT_TRUE(same(parseOne("2.4703282292062327e-324"), 0.0));    // just below: zero
  EXPECT_TRUE(same(parseOne("-2e-324"), -0.0));
  EXPECT_TRUE(same(parseOne("1e-99999"), 0.0));
  EXPECT_TRUE(same(parseOne("-0.0"), -0.0));
  EXPECT_TRUE(same(parseOne("-0"), -0.0));
  EXPECT_TRUE(same(parseOne("+0"), 0.0));
  EXPECT_TRUE(same(parseOne("2.2250738585072011e-308"), std::nextafter(0x1p-1022, 0.0)));
  EXPECT_TRUE(same(parseOne("2.2250738585072014e-308"), 0x1p-1022));
  for (const char* bad : {"1.7976931348623159e308", "1e309", "-1e309", "1e400000000000"}) {
    double v[1];
    try {
      convexloc::parseRow(bad, 7, 1, v);
      ADD_FAILURE() << bad << " was read as " << v[0];
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), 7u);
      EXPECT_NE(std::string(e.what()).find("out of the range of double"), std::string::npos)
          << e.what();
    }
  }
}

// === The line limit, exactly at its edge

// RowReader over `text`, collecting rows of 2 numbers until the end or an error
struct ReadResult {
  std::size_t rows = 0;
  std::size_t errorLine = 0;
  std::string error;
};
ReadResult readAll(const std::string& text) {
  std::FILE* f = fmemopen(const_cast<char*>(text.data()), text.size(), "rb");
  ReadResult out;
  try {
    convexloc::RowReader reader(f, 2);
    double row[2];
    while (reader.next(row)) ++out.rows;
  } catch (const ParseError& e) {
    out.errorLine = e.line();
    out.error = e.what();
  }
  std::fclose(f);
  return out;
}

// a valid row padded with blanks to exactly `length` bytes
std::string row(std::size_t length) {
  std::string s = "1";
  s.append(length - 2, ' ');
  return s + "2";
}

TEST(HostileCore, TheLineLimitIsExact) {
  for (const char* end : {"\n", "\r\n", ""}) {
    SCOPED_TRACE(end[0] == '\r' ? "CRLF" : end[0] ? "LF" : "no final newline");
    ReadResult at = readAll("1 2\n" + row(kMaxLineBytes) + end);
    EXPECT_EQ(at.rows, 2u) << at.error;
    ReadResult past = readAll("1 2\n" + row(kMaxLineBytes + 1) + end);
    EXPECT_EQ(past.rows, 1u);
    EXPECT_EQ(past.errorLine, 2u);
    EXPECT_NE(past.error.find("line longer than 1048576 bytes"), std::string::npos) << past.error;
  }
  // many lines at the limit in a row keep working (the buffer is reused, not grown)
  std::string many;
  for (int i = 0; i < 5; ++i) many += row(kMaxLineBytes) + "\r\n";
  EXPECT_EQ(readAll(many).rows, 5u);
}

// Regression: a last line without a newline that exactly fills the reader's buffer (64 KiB,
// then doubling) made it read freed memory (a crash on binary garbage of 128 KiB). The
// input of tests/data/fuzz/points_reader/last-line-fills-the-buffer replays it under ASan.
TEST(HostileCore, ALastLineFillingTheBufferIsRead) {
  for (std::size_t size = std::size_t{1} << 15; size <= (std::size_t{1} << 20); size *= 2)
    for (std::size_t delta : {0, 1, 2}) {
      SCOPED_TRACE(std::to_string(size - delta) + " bytes");
      ReadResult r = readAll("3 4\n" + row(size - delta));
      EXPECT_EQ(r.rows, 2u) << r.error;
      r = readAll(row(size - delta));
      EXPECT_EQ(r.rows, 1u) << r.error;
    }
}

// === Extreme polygons, every method against the exact reference

// random doubles spread over every exponent between 2^lo and 2^hi, either sign
double spread(convexloc::Rng& rng, int lo, int hi) {
  double m = 1 + rng.uniform();
  int e = lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - lo + 1)));
  double v = std::ldexp(m, e);
  return rng.below(2) ? -v : v;
}

// Checks every method, and two grid resolutions, at `count` points made by `point` plus the
// vertices, their one-ulp neighbours and the edge midpoints.
template <class PointFn>
void checkEveryMethod(const std::vector<Vec2>& input, std::size_t count, PointFn point) {
  ConvexPolygon poly(input);
  auto v = poly.vertices();
  std::vector<Vec2> queries;
  for (std::size_t i = 0; i < count; ++i) queries.push_back(point(i));
  for (std::size_t i = 0; i < v.size(); ++i) {
    queries.push_back(v[i]);
    fuzz::addNeighbours(queries, v[i]);
    Vec2 b = v[(i + 1) % v.size()];
    queries.push_back({v[i].x / 2 + b.x / 2, v[i].y / 2 + b.y / 2});
  }
  std::vector<Location> want;
  for (Vec2 q : queries) want.push_back(fuzz::exactLocate(v, q));
  for (convexloc::Method2D m : convexloc::kAllMethods2D)
    for (std::uint32_t resolution : {0u, 1u, 1000u}) {
      Locator2D loc(poly, m, resolution);
      for (std::size_t k = 0; k < queries.size(); ++k)
        ASSERT_EQ(loc.locate(queries[k]), want[k])
            << convexloc::toString(m) << " resolution " << resolution << " at "
            << fuzz::show(queries[k]);
    }
}

TEST(HostileCore, ExtremePolygonsAreExactWithEveryMethod) {
  const std::size_t n = hostile::scaled(5000, 1000);
  convexloc::Rng rng(300);
  // near the largest double: differences overflow
  checkEveryMethod({{-kMax, -kMax}, {kMax, -kMax}, {kMax, kMax}, {-kMax, kMax}}, n,
                   [&](std::size_t) {
                     return Vec2{spread(rng, 1000, 1023), spread(rng, 1000, 1023)};
                   });
  checkEveryMethod({{-kMax, -kMax}, {kMax, 0}, {0, kMax}}, n, [&](std::size_t) {
    return Vec2{spread(rng, -1074, 1023), spread(rng, -1074, 1023)};
  });
  // subnormal: a hexagon on the lattice of the smallest double
  std::vector<Vec2> sub;
  for (auto [x, y] : {std::pair{4, 0}, {2, 3}, {-2, 3}, {-4, 0}, {-2, -3}, {2, -3}})
    sub.push_back({x * kTiny, y * kTiny});
  checkEveryMethod(sub, n, [&](std::size_t) {
    return Vec2{static_cast<double>(static_cast<int>(rng.below(11)) - 5) * kTiny,
                static_cast<double>(static_cast<int>(rng.below(9)) - 4) * kTiny};
  });
  // scales 10^300 apart in one polygon
  checkEveryMethod({{-1e150, -1e-150}, {1e-150, -1e150}, {1e150, 1e-150}, {-1e-150, 1e150}}, n,
                   [&](std::size_t) {
                     return Vec2{spread(rng, -500, 500), spread(rng, -500, 500)};
                   });
  checkEveryMethod({{0, 0}, {1e150, 1e-150}, {1e150, 2e-150}, {0, 1e-150}}, n, [&](std::size_t) {
    return Vec2{rng.uniform(0, 1e150), rng.uniform(-1e-150, 3e-150)};
  });
  // a 200-gon of radius 1e290 around (1e300, -1e300): a few hundred thousand ulps wide,
  // so rounding leaves a lattice polygon that the hull makes strictly convex
  std::vector<Vec2> far;
  for (Vec2 p : convexloc::generatePolygon(convexloc::PolygonKind::Regular, 200, 1))
    far.push_back({1e300 + p.x * 1e290, -1e300 + p.y * 1e290});
  checkEveryMethod(convexloc::convexHull(far), n, [&](std::size_t) {
    return Vec2{1e300 + rng.uniform(-2e290, 2e290), -1e300 + rng.uniform(-2e290, 2e290)};
  });
}

// Regression (found by the differential fuzz target): a needle whose far vertices are
// 10^180 times farther than its near ones. Seen from polar's centre, far out in the needle,
// the near vertices all fall into one cell together with the two long edges, so that cell
// lists every edge; its run was searched from edge 0 instead of from the far vertex, and a
// point just outside the near end was called inside.
TEST(HostileCore, ANeedleWhoseOneCellHoldsEveryEdge) {
  std::vector<Vec2> needle = {{-3.9925662228460821, 0.24375183320042917},
                              {-3.5904823607587741, -1.7630758398549111},
                              {-2.2483588858566113, -3.3083050524988802},
                              {-0.31758291132683836, -3.9873727057340864},
                              {1.6963408096626067, -3.6224891797593006},
                              {2.9671816882932579e+183, 3.0414991604661539e+183},
                              {6.8656096013085994e+173, 7.1231403742292267e+173},
                              {1.5884778712944536e+164, 1.6681102126379433e+164},
                              {-3.3493391686951761, 2.1867617915640256}};
  ConvexPolygon poly(needle);
  const Vec2 justOutside{0x1.a210d17f2cc2fp+1, -0x1.279369d0c48d9p+1};
  ASSERT_EQ(fuzz::exactLocate(poly.vertices(), justOutside), Location::Outside);
  for (std::uint32_t slabs : {0u, 1u, 2u, 3u, 8u})
    EXPECT_EQ(convexloc::PolarLocator(poly, slabs).locate(justOutside), Location::Outside)
        << slabs << " slabs per octant";
  convexloc::Rng rng(180);
  checkEveryMethod(needle, 2000, [&](std::size_t) {
    return Vec2{rng.uniform(-5, 5), rng.uniform(-5, 5)};
  });
}

// === 10^7 vertices

TEST(HostileCore, TenMillionVerticesWithEveryMethod) {
  using Clock = std::chrono::steady_clock;
  const std::size_t n = hostile::scaled(10'000'000, 100'000);
  auto t0 = Clock::now();
  std::vector<Vec2> input = convexloc::generatePolygon(convexloc::PolygonKind::Regular, n, 1);
  ConvexPolygon poly(input);
  double validate = std::chrono::duration<double>(Clock::now() - t0).count();
  ASSERT_EQ(poly.size(), n) << "a regular polygon keeps every vertex";
  input.clear();
  input.shrink_to_fit();
  // points whose answers are known: vertices (boundary), one ulp outside the rightmost
  // vertex (1, 0), the centre, well inside the inscribed circle, outside the unit circle
  std::vector<Vec2> queries;
  std::vector<Location> want;
  auto v = poly.vertices();
  for (std::size_t i = 0; i < n; i += n / 97) {
    queries.push_back(v[i]);
    want.push_back(Location::Boundary);
    queries.push_back({v[i].x * 0.999999, v[i].y * 0.999999});
    want.push_back(Location::Inside);
    queries.push_back({v[i].x * 1.000001, v[i].y * 1.000001});
    want.push_back(Location::Outside);
  }
  queries.push_back({std::nextafter(1.0, 2.0), 0.0});
  want.push_back(Location::Outside);
  queries.push_back({0, 0});
  want.push_back(Location::Inside);
  for (convexloc::Method2D m : convexloc::kAllMethods2D) {
    auto t1 = Clock::now();
    Locator2D loc(poly, m);
    double build = std::chrono::duration<double>(Clock::now() - t1).count();
    for (std::size_t k = 0; k < queries.size(); ++k)
      ASSERT_EQ(loc.locate(queries[k]), want[k])
          << convexloc::toString(m) << " at " << fuzz::show(queries[k]);
    convexloc::Stats2D st = loc.stats();
    std::printf("[ figures  ] %zu-gon %-9s build %.2f s, %.1f bytes per edge, max %zu per cell\n",
                n, std::string(convexloc::toString(m)).c_str(), build, st.bytesPerEdge,
                st.maxPerCell);
    // the documented bound: 64 bytes per edge, the locator's copy of the vertices included
    EXPECT_LE(st.bytesPerEdge, 64.0) << convexloc::toString(m);
  }
  std::printf("[ figures  ] %zu-gon generated and validated in %.2f s\n", n, validate);
}

}  // namespace
