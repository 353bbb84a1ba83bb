// convexloc fuzzing — what the targets share: bytes as a FILE, bytes as numbers, an exact
// reference for 2D location, and a loud failure.
//
// A target returns normally on any input core handles: a result, or a convexloc::Error. It
// aborts (which libFuzzer and the replay driver report with the input) on anything else: a
// wrong answer, an exception that is not a convexloc::Error, a broken invariant.
#pragma once

#include <gmpxx.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "convexloc/geometry.hpp"

namespace fuzz {

using convexloc::Location;
using convexloc::Vec2;
using convexloc::Vec3;

// === Failing loudly

// prints what went wrong and aborts: the fuzzer saves the input
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "convexloc fuzz: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

// a double with every digit, for messages
inline std::string show(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g (%a)", v, v);
  return buf;
}

inline std::string show(Vec2 p) {
  std::string out = "(";  // appended, not "(" + ...: g++ 12 warns falsely on that (-Wrestrict)
  out += show(p.x);
  out += ", ";
  out += show(p.y);
  out += ")";
  return out;
}

inline std::string show(Vec3 p) {
  std::string out = "(";
  out += show(p.x);
  out += ", ";
  out += show(p.y);
  out += ", ";
  out += show(p.z);
  out += ")";
  return out;
}

// === Bytes as a FILE

// The fuzzer's bytes as a read-only FILE (fmemopen on a copy; an empty input is a tmpfile).
class MemFile {
 public:
  MemFile(const std::uint8_t* data, std::size_t size) : copy_(data, data + size) {
    f_ = size ? fmemopen(copy_.data(), size, "rb") : std::tmpfile();
    if (!f_) fail("cannot open the input as a FILE");
  }
  ~MemFile() { std::fclose(f_); }
  MemFile(const MemFile&) = delete;
  MemFile& operator=(const MemFile&) = delete;
  std::FILE* get() const noexcept { return f_; }

 private:
  std::vector<std::uint8_t> copy_;
  std::FILE* f_ = nullptr;
};

// === Bytes as numbers

// Reads the fuzzer's bytes front to back; past the end every read is zero.
class ByteSource {
 public:
  ByteSource(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const noexcept { return pos_ >= size_; }
  std::size_t left() const noexcept { return pos_ < size_ ? size_ - pos_ : 0; }
  std::uint8_t byte() noexcept { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint16_t u16() noexcept {
    std::uint16_t hi = byte();
    return static_cast<std::uint16_t>(hi << 8 | byte());
  }
  std::uint64_t u64() noexcept {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | byte();
    return v;
  }
  // a small signed integer in [-8, 7]: duplicates and collinear triples are common
  int smallInt() noexcept { return static_cast<int>(byte() & 15) - 8; }
  // any finite double from 8 raw bytes (a NaN or infinity becomes a signed zero)
  double rawDouble() noexcept {
    double v = std::bit_cast<double>(u64());
    return std::isfinite(v) ? v : std::copysign(0.0, v);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// How the bytes of a coordinate are read, so that one input file exercises one family of
// hard cases: exact lattices, huge offsets, wild scales, raw bit patterns.
enum class Encoding : std::uint8_t {
  SmallInt,    // integers in [-8, 7]
  ScaledInt,   // integers in [-8, 7] times one power of two (2^-1074 .. 2^1019) per input
  OffsetInt,   // a large common offset plus integers in [-8, 7] times a small step
  MixedScale,  // integers in [-8, 7] each times its own power of two: scales 10^600 apart
  Raw,         // any finite double
  Circle,      // points on a circle of radius 2^k, angle from 16 bits
};
inline constexpr int kEncodings = 6;

// reads coordinates in one Encoding; the parameters of the encoding come from the bytes
class CoordinateReader {
 public:
  CoordinateReader(ByteSource& src, Encoding e) : src_(src), e_(e) {
    // one read per statement: the order of reads must not depend on the compiler
    scale_ = std::ldexp(1.0, static_cast<int>(src_.u16() % 2094) - 1074);
    offset_ = std::ldexp(1.0, 20 + src_.u16() % 1000);
    if (src_.byte() & 1) offset_ = -offset_;
    step_ = std::ldexp(1.0, std::ilogb(offset_) - 52 + src_.byte() % 8);
  }
  Vec2 point() noexcept {
    switch (e_) {
      case Encoding::SmallInt: return {double(src_.smallInt()), double(src_.smallInt())};
      case Encoding::ScaledInt: return {src_.smallInt() * scale_, src_.smallInt() * scale_};
      case Encoding::OffsetInt:
        return {offset_ + src_.smallInt() * step_, offset_ + src_.smallInt() * step_};
      case Encoding::MixedScale: return {mixed(), mixed()};
      case Encoding::Raw: return {src_.rawDouble(), src_.rawDouble()};
      case Encoding::Circle: {
        double r = std::ldexp(1.0, static_cast<int>(src_.byte() % 64) * 32 - 1022);
        double t = src_.u16() * (2 * std::numbers::pi / 65536.0);
        return {r * std::cos(t), r * std::sin(t)};
      }
    }
    return {};
  }

  Vec3 point3() noexcept {
    if (e_ == Encoding::Circle) {  // on a sphere: two angles
      double r = std::ldexp(1.0, static_cast<int>(src_.byte() % 64) * 32 - 1022);
      double t = src_.u16() * (2 * std::numbers::pi / 65536.0);
      double u = src_.u16() * (std::numbers::pi / 65535.0);
      return {r * std::cos(t) * std::sin(u), r * std::sin(t) * std::sin(u), r * std::cos(u)};
    }
    Vec2 xy = point();
    Vec2 z = point();
    return {xy.x, xy.y, z.x};
  }

 private:
  double mixed() noexcept {
    int k = src_.smallInt();
    int e = static_cast<int>(src_.u16() % 2094) - 1074;
    return std::ldexp(static_cast<double>(k), e);
  }
  ByteSource& src_;
  Encoding e_;
  double scale_ = 1, offset_ = 0, step_ = 1;
};

// === An exact reference, independent of core's predicates

// Exact sign of (b - a) x (c - a): a filter in x87 extended precision, where no product of
// doubles can overflow or underflow (15-bit exponent), so that Shewchuk's bound with the
// unit roundoff 2^-64 holds everywhere; rationals when the filter cannot decide. (Core
// filters in double with underflow guards and falls back to integers: a different path.)
inline int exactOrient(Vec2 a, Vec2 b, Vec2 c) {
  static_assert(std::numeric_limits<long double>::digits == 64, "x87 extended precision");
  {
    long double dx1 = static_cast<long double>(b.x) - a.x,
                dy1 = static_cast<long double>(b.y) - a.y;
    long double dx2 = static_cast<long double>(c.x) - a.x,
                dy2 = static_cast<long double>(c.y) - a.y;
    long double left = dx1 * dy2, right = dy1 * dx2;
    long double det = left - right;
    constexpr long double kEpsL = 0x1p-64L;
    long double bound = (3 * kEpsL + 16 * kEpsL * kEpsL) * (std::fabs(left) + std::fabs(right));
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  for (Vec2 p : {a, b, c})
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      fail("exactOrient needs finite points, got " + show(p));
  // kept between calls: GMP reuses their storage instead of allocating each time
  thread_local mpq_class ax, ay, dx1, dy1, dx2, dy2;
  ax = a.x;
  ay = a.y;
  dx1 = b.x;
  dx1 -= ax;
  dy1 = b.y;
  dy1 -= ay;
  dx2 = c.x;
  dx2 -= ax;
  dy2 = c.y;
  dy2 -= ay;
  dx1 *= dy2;
  dy1 *= dx2;
  return cmp(dx1, dy1);
}

// where p lies with respect to the strictly convex counter-clockwise polygon v
inline Location exactLocate(std::span<const Vec2> v, Vec2 p) {
  bool on = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    int s = exactOrient(v[i], v[(i + 1) % v.size()], p);
    if (s < 0) return Location::Outside;
    if (s == 0) on = true;
  }
  return on ? Location::Boundary : Location::Inside;
}

// Exact sign of det[a - d; b - d; c - d] (core's orient3d convention: > 0 when d is on the
// inner side of a triangle a, b, c that is counter-clockwise seen from outside). The same
// two stages as exactOrient: an x87 filter with Shewchuk's bound for 3x3 determinants, then
// rationals.
inline int exactOrient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  {
    using L = long double;
    L adx = L(a.x) - d.x, ady = L(a.y) - d.y, adz = L(a.z) - d.z;
    L bdx = L(b.x) - d.x, bdy = L(b.y) - d.y, bdz = L(b.z) - d.z;
    L cdx = L(c.x) - d.x, cdy = L(c.y) - d.y, cdz = L(c.z) - d.z;
    L bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    L cdxady = cdx * ady, adxcdy = adx * cdy;
    L adxbdy = adx * bdy, bdxady = bdx * ady;
    L det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    L permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                  (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                  (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
    constexpr L kEpsL = 0x1p-64L;
    L bound = (7 * kEpsL + 56 * kEpsL * kEpsL) * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  for (Vec3 p : {a, b, c, d})
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail("exactOrient3d needs finite points, got " + show(p));
  thread_local mpq_class q[9], t1, t2, det;
  const double in[9] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
  const double sub[3] = {d.x, d.y, d.z};
  for (int i = 0; i < 9; ++i) {
    q[i] = in[i];
    q[i] -= mpq_class(sub[i % 3]);
  }
  // rows a - d, b - d, c - d; expand along the z column
  t1 = q[3] * q[7];
  t2 = q[6] * q[4];
  det = q[2] * (t1 - t2);
  t1 = q[6] * q[1];
  t2 = q[0] * q[7];
  det += q[5] * (t1 - t2);
  t1 = q[0] * q[4];
  t2 = q[3] * q[1];
  det += q[8] * (t1 - t2);
  return sgn(det);
}

// where p lies with respect to a closed convex surface of triangles, each counter-clockwise
// seen from outside
template <class Triangles>
Location exactLocate3d(std::span<const Vec3> v, const Triangles& triangles, Vec3 p) {
  bool on = false;
  for (const auto& t : triangles) {
    int s = exactOrient3d(v[t[0]], v[t[1]], v[t[2]], p);
    if (s < 0) return Location::Outside;
    if (s == 0) on = true;
  }
  return on ? Location::Boundary : Location::Inside;
}

// the points one ulp away from p along each axis, both ways, and along the two diagonals
inline void addNeighbours3d(std::vector<Vec3>& out, Vec3 p) {
  const double inf = HUGE_VAL;
  auto push = [&](Vec3 q) {
    if (std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z)) out.push_back(q);
  };
  for (double to : {-inf, inf}) {
    push({std::nextafter(p.x, to), p.y, p.z});
    push({p.x, std::nextafter(p.y, to), p.z});
    push({p.x, p.y, std::nextafter(p.z, to)});
    push({std::nextafter(p.x, to), std::nextafter(p.y, to), std::nextafter(p.z, to)});
  }
}

// the points one ulp away from p in each of the eight directions
inline void addNeighbours(std::vector<Vec2>& out, Vec2 p) {
  const double inf = HUGE_VAL;
  for (double dx : {-inf, 0.0, inf})
    for (double dy : {-inf, 0.0, inf}) {
      if (dx == 0.0 && dy == 0.0) continue;
      Vec2 q{dx == 0.0 ? p.x : std::nextafter(p.x, dx), dy == 0.0 ? p.y : std::nextafter(p.y, dy)};
      if (std::isfinite(q.x) && std::isfinite(q.y)) out.push_back(q);
    }
}

}  // namespace fuzz
