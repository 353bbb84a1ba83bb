// The exact stage of the predicates (detail::crossExact, detail::orient3dExact), called
// directly so that the filter decides nothing, against GMP rationals (exact_cases.hpp):
// random, collinear and coplanar by construction (with exact and with inexact differences),
// one ulp off, huge, subnormal, mixed and 2^+-700 inputs, and the rims of each stage's range.
// Each group also checks which stage decided it: narrow integers, expansions, multiprecision.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "exact_cases.hpp"

using namespace exact_cases;

TEST(ExactStage, CrossNarrowIntegersDecideCoordinatesCloseInScale) {
  Rng r(107);
  const auto lattice =
      make(kCases, [&] { return latticeLine(r, static_cast<int>(r.below(121)) - 60); });
  const auto box =
      make(kCases, [&] { return r.below(2) ? boxLine(r, -1, 1) : boxLine(r, 1000, 1001); });
  const auto diagonal = make(kCases, [&] { return diagonalLine(r, 0, 0); });
  const auto offLattice = make(kCases, [&] {
    Cross c = latticeLine(r, static_cast<int>(r.below(41)) - 20);
    c.q1.y = ulpOff(r, c.q1.y);
    return c;
  });
  const auto rim =
      make(kCases, [&] { return scaled(rimLine(r, false), static_cast<int>(r.below(61)) - 30); });
  const auto zeros = make(kCases, [&] {
    Cross c = latticeLine(r, static_cast<int>(r.below(121)) - 60);
    c.p0.x = 0;
    c.q1.y = r.below(2) ? 0.0 : c.q1.y;
    return c;
  });
  for (const auto* cases : {&lattice, &box, &diagonal, &rim, &zeros})
    EXPECT_EQ(expectAllMatch(*cases, crossStage, crossRef).narrowIntegers, cases->size());
  // one ulp off a small coordinate widens the span past the stage now and then
  EXPECT_GT(expectAllMatch(offLattice, crossStage, crossRef).narrowIntegers,
            offLattice.size() * 9 / 10);
}

TEST(ExactStage, CrossExpansionsDecideWideSpansInOrdinaryRange) {
  Rng r(101);
  const auto random = make(kCases, [&] {
    return Cross{{wild(r, -40, 40), wild(r, -40, 40)},
                 {wild(r, -40, 40), wild(r, -40, 40)},
                 {wild(r, -40, 40), wild(r, -40, 40)},
                 {wild(r, -40, 40), wild(r, -40, 40)}};
  });
  const auto diagonal = make(kCases, [&] { return diagonalLine(r, -60, 60); });
  const auto offDiagonal = make(kCases, [&] {
    Cross c = diagonalLine(r, -30, 30);
    c.q1.x = ulpOff(r, c.q1.x);
    return c;
  });
  const auto mixed = make(kCases, [&] {
    return Cross{{wild(r, -480, 499), wild(r, -480, 499)},
                 {wild(r, -480, 499), 0},
                 {0, wild(r, -480, 499)},
                 {wild(r, -480, 499), wild(r, -480, 499)}};
  });
  const auto rim =
      make(kCases, [&] { return scaled(rimLine(r, true), static_cast<int>(r.below(61)) - 30); });
  for (const auto* cases : {&random, &diagonal, &offDiagonal, &mixed, &rim}) {
    const ExactStageCounts counts = expectAllMatch(*cases, crossStage, crossRef);
    EXPECT_EQ(counts.multiprecision, 0u);
    EXPECT_GT(counts.expansions, cases->size() / 2);
  }
}

TEST(ExactStage, Orient3dNarrowIntegersDecideCoordinatesCloseInScale) {
  Rng r(108);
  const auto lattice =
      make(kCases, [&] { return latticePlane(r, static_cast<int>(r.below(121)) - 60); });
  const auto box =
      make(kCases, [&] { return r.below(2) ? boxPlane(r, -1, 1) : boxPlane(r, 1000, 1001); });
  const auto column = make(kCases, [&] { return columnPlane(r, 0, 0); });
  const auto offLattice = make(kCases, [&] {
    Orient o = latticePlane(r, static_cast<int>(r.below(41)) - 20);
    o.d.z = ulpOff(r, o.d.z);
    return o;
  });
  const auto rim =
      make(kCases, [&] { return scaled(rimPlane(r, false), static_cast<int>(r.below(61)) - 30); });
  const auto zeros = make(kCases, [&] {
    Orient o = latticePlane(r, static_cast<int>(r.below(121)) - 60);
    o.a.x = 0;
    o.d.z = r.below(2) ? 0.0 : o.d.z;
    return o;
  });
  for (const auto* cases : {&lattice, &box, &column, &rim, &zeros})
    EXPECT_EQ(expectAllMatch(*cases, orientStage, orientRef).narrowIntegers, cases->size());
  // one ulp off a small coordinate widens the span past the stage now and then
  EXPECT_GT(expectAllMatch(offLattice, orientStage, orientRef).narrowIntegers,
            offLattice.size() * 9 / 10);
}

TEST(ExactStage, Orient3dExpansionsDecideWideSpansInOrdinaryRange) {
  Rng r(103);
  auto point = [&](int lo, int hi) {
    return Vec3{wild(r, lo, hi), wild(r, lo, hi), wild(r, lo, hi)};
  };
  const auto random = make(kCases, [&] {
    return Orient{point(-40, 40), point(-40, 40), point(-40, 40), point(-40, 40)};
  });
  const auto column = make(kCases, [&] { return columnPlane(r, -60, 60); });
  const auto offColumn = make(kCases, [&] {
    Orient o = columnPlane(r, -30, 30);
    o.d.x = ulpOff(r, o.d.x);
    return o;
  });
  const auto mixed = make(kCases, [&] {
    return Orient{point(-300, 329), point(-300, 329), point(-300, 329), point(-300, 329)};
  });
  const auto edge = make(kCases, [&] {
    // the edges of the expansions' range, 2^-300 <= |v| < 2^330, and values inside it
    const double top = std::nextafter(0x1p330, 0);
    const double at[] = {top, -top, 0x1p329, 0x1p-300, -0x1p-300, 0};
    auto pick = [&] { return at[r.below(6)]; };
    return Orient{{top, pick(), pick()},
                  {0x1p-300, pick(), pick()},
                  {pick(), pick(), pick()},
                  {pick(), pick(), pick()}};
  });
  const auto rim =
      make(kCases, [&] { return scaled(rimPlane(r, true), static_cast<int>(r.below(61)) - 30); });
  for (const auto* cases : {&random, &column, &offColumn, &mixed, &edge, &rim}) {
    const ExactStageCounts counts = expectAllMatch(*cases, orientStage, orientRef);
    EXPECT_EQ(counts.multiprecision, 0u);
    EXPECT_GT(counts.expansions, cases->size() / 2);
  }
}

TEST(ExactStage, CrossAtExtremeExponentsUsesMultiprecision) {
  Rng r(102);
  const double big = std::numeric_limits<double>::max(),
               tiny = std::numeric_limits<double>::denorm_min();
  const auto huge = make(kCases, [&] {
    return Cross{{wild(r, 990, 1023), wild(r, 990, 1023)},
                 {big, -big},
                 {-big, wild(r, 990, 1023)},
                 {wild(r, 990, 1023), big}};
  });
  const auto subnormal = make(kCases, [&] {
    return Cross{{wild(r, -1074, -1023), tiny},
                 {wild(r, -1074, -1023), wild(r, -1074, -1023)},
                 {wild(r, -1074, -1023), wild(r, -1074, -1023)},
                 {-tiny, wild(r, -1074, -1023)}};
  });
  const auto mixed = make(kCases, [&] {
    return Cross{{wild(r, -1074, 1023), wild(r, -1074, 1023)},
                 {wild(r, -1074, 1023), tiny},
                 {big, wild(r, -1074, 1023)},
                 {wild(r, -1074, 1023), wild(r, -1074, 1023)}};
  });
  const auto far = make(kCases, [&] {
    const int s = r.below(2) ? 700 : -700;
    Cross c = r.below(2) ? scaled(latticeLine(r, 0), s) : scaled(diagonalLine(r, -20, 20), s);
    if (r.below(2)) c.q1.y = ulpOff(r, c.q1.y);
    return c;
  });
  for (const auto* cases : {&huge, &subnormal, &mixed, &far}) {
    // a lattice at 2^+-700 is still narrow integers; nothing here is for the expansions
    const ExactStageCounts counts = expectAllMatch(*cases, crossStage, crossRef);
    EXPECT_EQ(counts.expansions, 0u);
    EXPECT_GT(counts.multiprecision, cases->size() / 4);
  }
}

TEST(ExactStage, Orient3dAtExtremeExponentsUsesMultiprecision) {
  Rng r(104);
  const double big = std::numeric_limits<double>::max(),
               tiny = std::numeric_limits<double>::denorm_min();
  auto point = [&](int lo, int hi) {
    return Vec3{wild(r, lo, hi), wild(r, lo, hi), wild(r, lo, hi)};
  };
  const auto huge = make(kCases, [&] {
    return Orient{
        point(990, 1023), {big, -big, big}, point(995, 1023), scaled(latticePlane(r, 0), 960).d};
  });
  const auto subnormal = make(kCases, [&] {
    Orient o =
        r.below(2)
            ? latticePlane(r, -1074)
            : Orient{
                  point(-1074, -1023), point(-1074, -1023), {tiny, 0, -tiny}, point(-1074, -1023)};
    if (r.below(2)) o.d.y = ulpOff(r, o.d.y);
    return o;
  });
  const auto mixed = make(kCases, [&] {
    return Orient{point(-1074, 1023), point(-1074, 1023), {big, tiny, 0}, point(-1074, 1023)};
  });
  const auto far = make(kCases, [&] {
    const int s = r.below(2) ? 700 : -700;
    Orient o = r.below(2) ? scaled(latticePlane(r, 0), s) : scaled(columnPlane(r, -20, 20), s);
    if (r.below(2)) o.d.x = ulpOff(r, o.d.x);
    return o;
  });
  const auto outside = make(kCases, [&] {
    // just beyond the range: 2^330, and 2^-300 less one ulp
    const double edge[] = {0x1p330, std::nextafter(0x1p-300, 0), 1, -1};
    auto pick = [&] { return edge[r.below(4)]; };
    return Orient{{edge[r.below(2)], pick(), pick()},
                  {pick(), pick(), pick()},
                  {pick(), pick(), pick()},
                  {pick(), pick(), pick()}};
  });
  for (const auto* cases : {&huge, &subnormal, &mixed, &far, &outside}) {
    const ExactStageCounts counts = expectAllMatch(*cases, orientStage, orientRef);
    EXPECT_EQ(counts.expansions, 0u);
    EXPECT_GT(counts.multiprecision, cases->size() / 4);
  }
}
