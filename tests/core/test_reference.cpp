// The reference itself: its filtered signs equal plain rational signs at every scale, and its
// classification and hull are right on cases checked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "reference2d.hpp"

using convexloc::Location;
using convexloc::Rng;
using convexloc::Vec2;

namespace {

// a double with a random exponent in [lo, hi] and a random sign
double anyScale(Rng& r, int lo, int hi) {
  const double m = 1 + r.uniform();
  const int e = lo + static_cast<int>(r.below(static_cast<std::uint64_t>(hi - lo + 1)));
  return (r.below(2) ? -1 : 1) * std::ldexp(m, e);
}

TEST(Reference, FilteredCrossEqualsRationalCross) {
  Rng r(31);
  const int ranges[][2] = {{-1074, -1000}, {-600, -400}, {-60, 60},
                           {400, 600},     {1000, 1023}, {-1074, 1023}};
  for (auto [lo, hi] : ranges)
    for (int i = 0; i < 30000; ++i) {
      Vec2 o{anyScale(r, lo, hi), anyScale(r, lo, hi)}, a{anyScale(r, lo, hi), anyScale(r, lo, hi)};
      Vec2 b{anyScale(r, lo, hi), anyScale(r, lo, hi)};
      switch (r.below(4)) {
        case 0: b = {o.x + (a.x - o.x) * 0.5, o.y + (a.y - o.y) * 0.5}; break;  // near a line
        case 1: b = {std::nextafter(a.x, 0.0), a.y}; break;                     // next to a
        case 2: b = {a.x, o.y}; break;                                          // axis-aligned
        default: break;
      }
      if (!std::isfinite(b.x) || !std::isfinite(b.y)) continue;  // the midpoint overflowed
      ASSERT_EQ(ref::cross(o, a, b), ref::crossRational(o, a, b)) << lo << ' ' << hi << ' ' << i;
    }
}

TEST(Reference, NearlyCollinearAtEveryScale) {
  // points on and one ulp off y = x, scaled by powers of two: each filter stage must give way
  Rng r(32);
  for (int i = 0; i < 100000; ++i) {
    const double s = std::ldexp(1.0, static_cast<int>(r.below(2000)) - 1000);
    const double t0 = s * r.uniform(), t1 = s * r.uniform(), t2 = s * r.uniform();
    Vec2 a{t0, t0}, b{t1, t1}, c{t2, t2};
    const int nudge = static_cast<int>(r.below(3));
    if (nudge == 1) c.y = std::nextafter(c.y, 1e308);
    if (nudge == 2) c.y = std::nextafter(c.y, -1e308);
    ASSERT_EQ(ref::cross(a, b, c), ref::crossRational(a, b, c)) << i;
  }
}

TEST(Reference, KnownSigns) {
  EXPECT_EQ(ref::cross({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(ref::cross({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(ref::cross({0, 0}, {1, 1}, {3, 3}), 0);
  const double big = std::numeric_limits<double>::max();
  EXPECT_EQ(ref::cross({-big, -big}, {big, big}, {0, 0}), 0);
  EXPECT_EQ(ref::cross({-big, -big}, {big, -big}, {0, big}), 1);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(ref::cross({0, 0}, {tiny, 0}, {0, tiny}), 1);
  EXPECT_EQ(ref::cross({0, 0}, {tiny, tiny}, {3 * tiny, 3 * tiny}), 0);
  // 0.1 + 0.2 is not 0.3 in doubles; (0.1, 0.2), (0.2, 0.4), (0.3, 0.6) are not collinear
  const int s = ref::cross({0.1, 0.2}, {0.2, 0.4}, {0.3, 0.6});
  EXPECT_EQ(s, ref::crossRational({0.1, 0.2}, {0.2, 0.4}, {0.3, 0.6}));
  EXPECT_EQ(ref::crossDirection({0, 0}, {1, 0}, {5, 1}), 1);
  EXPECT_EQ(ref::crossDirection({1, 1}, {1, 1}, {3, 3}), 0);
  EXPECT_EQ(ref::crossDirection({0, 0}, {0, 1}, {1, 5}), -1);
}

TEST(Reference, LocateOnASquare) {
  const std::vector<Vec2> sq = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_EQ(ref::locate(sq, {1, 1}), Location::Inside);
  EXPECT_EQ(ref::locate(sq, {0, 0}), Location::Boundary);
  EXPECT_EQ(ref::locate(sq, {1, 2}), Location::Boundary);
  EXPECT_EQ(ref::locate(sq, {2, 0.5}), Location::Boundary);
  EXPECT_EQ(ref::locate(sq, {3, 2}), Location::Outside);  // on an edge's line, off the edge
  EXPECT_EQ(ref::locate(sq, {-1e-300, 1}), Location::Outside);
  EXPECT_EQ(ref::locate(sq, {std::nextafter(2.0, 3.0), 1}), Location::Outside);
  EXPECT_EQ(ref::locate(sq, {std::nextafter(2.0, 1.0), 1}), Location::Inside);
  EXPECT_EQ(ref::locate(sq, {-0.0, 1}), Location::Boundary);
}

TEST(Reference, HullDropsRepeatsAndCollinearPoints) {
  const std::vector<Vec2> pts = {{1, 1}, {0, 0}, {2, 0}, {1, 0}, {2, 2},
                                 {0, 2}, {0, 0}, {2, 1}, {1, 1}};
  const std::vector<Vec2> h = ref::hull(pts);
  EXPECT_EQ(h, (std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  EXPECT_TRUE(ref::strictlyConvexTurns(h));
  EXPECT_EQ(ref::hull(std::vector<Vec2>{{0, 0}, {1, 1}, {2, 2}}).size(), 2u);
  EXPECT_EQ(ref::hull(std::vector<Vec2>{{5, 5}, {5, 5}}).size(), 1u);
  EXPECT_TRUE(ref::sameCycle(std::vector<Vec2>{{1, 0}, {2, 0}, {0, 1}},
                             std::vector<Vec2>{{0, 1}, {1, 0}, {2, 0}}));
  EXPECT_FALSE(ref::sameCycle(std::vector<Vec2>{{1, 0}, {2, 0}, {0, 1}},
                              std::vector<Vec2>{{0, 1}, {2, 0}, {1, 0}}));
  EXPECT_FALSE(ref::strictlyConvexTurns(std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}, {1, 1}}));
}

}  // namespace
