// The portable double <-> text conversions (convexloc/detail/chars.hpp: what the web build's
// libc++ 14 uses in place of floating-point std::to_chars / std::from_chars) held against
// libstdc++'s own, on hard cases and on random bit patterns.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "convexloc/detail/chars.hpp"

namespace {

using convexloc::detail::portableDoubleFromChars;
using convexloc::detail::portableDoubleToChars;

std::string portableText(double v) {
  char buf[40];
  const auto r = portableDoubleToChars(buf, buf + sizeof buf, v);
  EXPECT_EQ(r.ec, std::errc());
  return std::string(buf, r.ptr);
}

// the significant digits of a decimal text ("-1.25e+07" -> 3, "0.0012" -> 2, "1200" -> 2)
int significantDigits(const std::string& text) {
  std::string digits;
  for (const char c : text) {
    if (c == 'e' || c == 'E') break;
    if (c >= '0' && c <= '9') digits += c;
  }
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  const auto last = digits.find_last_not_of('0');
  return static_cast<int>(last - first + 1);
}

// v's text reads back as v itself (the sign of zero too), with the shortest digits
void expectShortestRoundTrip(double v) {
  const std::string mine = portableText(v);
  const double back = std::strtod(mine.c_str(), nullptr);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(v)) << mine;
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  EXPECT_EQ(significantDigits(mine), significantDigits(std::string(buf, r.ptr)))
      << mine << " against " << std::string(buf, r.ptr);
}

// the portable reader does what std::from_chars (general) does with `text`
void expectSameRead(const std::string& text) {
  const char* b = text.data();
  const char* e = b + text.size();
  double mine = -7.0, theirs = -7.0;
  const auto m = portableDoubleFromChars(b, e, mine);
  const auto t = std::from_chars(b, e, theirs, std::chars_format::general);
  EXPECT_EQ(m.ec, t.ec) << "'" << text << "'";
  EXPECT_EQ(m.ptr - b, t.ptr - b) << "'" << text << "'";
  if (std::isnan(theirs))
    EXPECT_TRUE(std::isnan(mine)) << "'" << text << "'";
  else
    EXPECT_EQ(std::bit_cast<std::uint64_t>(mine), std::bit_cast<std::uint64_t>(theirs))
        << "'" << text << "'";
}

TEST(PortableChars, HardDoublesComeBackExactlyInTheShortestDigits) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const double v :
       {0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3.0, 2.0 / 3.0, 123000.0, 1e15, 1e16, 1e21, 1e22, 1e23,
        5e-324, -5e-324, 2.2250738585072009e-308, 2.2250738585072014e-308, 1e-300,
        std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
        9007199254740993.0, 0.30000000000000004, 1.7976931348623157e308, 4.35, 0.001,
        1234567890123456789.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0)})
    expectShortestRoundTrip(v);
  EXPECT_EQ(portableText(inf), "inf");
  EXPECT_EQ(portableText(-inf), "-inf");
}

TEST(PortableChars, RandomBitPatternsComeBackExactly) {
  std::mt19937_64 rng(20261126);
  for (int i = 0; i < 5000; ++i) {
    const double v = std::bit_cast<double>(rng());
    if (std::isfinite(v)) expectShortestRoundTrip(v);
  }
}

TEST(PortableChars, ReadsWhatFromCharsReads) {
  for (const char* text :
       {"1", "-1", "+1", " 1", "1 ", "0", "-0", "00012", "1e", "1e+", "1e-", "1e5x", "1E5",
        ".5", "5.", ".", "-", "", "e5", "-.5e-3", "0x10", "0X1p3", "inf", "-INF", "Infinity",
        "infinit", "infx", "nan", "NaN", "-nan", "na", "1e400", "-1e400", "1e-400", "-1e-400",
        "4.9e-324", "2.4e-324", "2.5e-324", "1e-310", "2.2250738585072011e-308",
        "1.7976931348623157e308", "1.7976931348623159e308", "123456789012345678901234567890",
        "0.30000000000000004441", "1..2", "1.2.3", "--1", "1e+0005", "3,5", "7#"})
    expectSameRead(text);
}

TEST(PortableChars, RandomNumbersReadAsFromCharsReadsThem) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 5000; ++i) {
    const double v = std::bit_cast<double>(rng());
    if (!std::isfinite(v)) continue;
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    expectSameRead(std::string(buf, r.ptr));
  }
}

TEST(PortableChars, ATooSmallBufferIsRefused) {
  char buf[4];
  const auto r = portableDoubleToChars(buf, buf + sizeof buf, 0.1234567);
  EXPECT_EQ(r.ec, std::errc::value_too_large);
}

}  // namespace
