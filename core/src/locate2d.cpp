// convexloc — the five 2D locators.
#include "convexloc/locate2d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <numeric>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "convexloc/batch.hpp"
#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "convexloc/timing.hpp"
#include "detail/batch_loop.hpp"
#include "detail/radii.hpp"

namespace convexloc {
namespace {

// === Trace sinks: the query code is written once and either records or not

// records nothing; compiles away in locate()
struct NoSink {
  void ray(std::uint32_t, int) {}
  void edge(std::uint32_t, int) {}
  void cell(std::int64_t, int) {}
  void crowded() {}
  void outsideBox() {}
  void atCentre() {}
  void apex(Vec2) {}
  void radius(double, float, float, bool) {}
};

// records every step into a Trace2D
struct TraceSink {
  Trace2D& t;
  void ray(std::uint32_t v, int s) { t.rays.push_back({v, s}); }
  void edge(std::uint32_t e, int s) { t.edges.push_back({e, s}); }
  void cell(std::int64_t c, int octant) {
    t.cell = c;
    t.octant = octant;
  }
  void crowded() { t.crowded = true; }
  void outsideBox() { t.outsideBox = true; }
  void atCentre() { t.atCentre = true; }
  void apex(Vec2 a) { t.apex = a; }
  void radius(double d2, float in2, float out2, bool decided) {
    t.distance = std::sqrt(d2);
    t.innerRadius = std::sqrt(static_cast<double>(in2));
    t.outerRadius = std::sqrt(static_cast<double>(out2));
    t.byRadius = decided;
  }
};

// orient2d of p against edge e of the ring v
inline int edgeSign(std::span<const Vec2> v, std::uint32_t e, Vec2 p) {
  std::uint32_t next = e + 1 == v.size() ? 0 : e + 1;
  return orient2d(v[e], v[next], p);
}

// the class from the edge tests of a cell whose edges include every edge p can exit through
struct Verdict {
  bool zero = false;
  bool negative = false;
  Location result() const {
    return negative ? Location::Outside : (zero ? Location::Boundary : Location::Inside);
  }
};

// tests p against the listed edges, stopping at the first outer side
template <class Sink>
inline Location testEdges(std::span<const Vec2> v, const std::uint32_t* first,
                          const std::uint32_t* last, Vec2 p, Sink& sink) {
  bool zero = false;
  for (const std::uint32_t* it = first; it != last; ++it) {
    int s = edgeSign(v, *it, p);
    sink.edge(*it, s);
    if (s < 0) return Location::Outside;
    zero |= s == 0;
  }
  return zero ? Location::Boundary : Location::Inside;
}

// p has an infinite or NaN coordinate: no polygon contains it, and no predicate may see it
// (the exact fallback cannot represent it)
inline bool nonFinite(Vec2 p) { return !(std::isfinite(p.x) && std::isfinite(p.y)); }

// p outside the closed box
inline bool outsideBox(const Box2& b, Vec2 p) {
  return !(p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y);
}

// Bisection over the fan from vertex 0 (the wedge method), shared by `wedge` and by the
// polar locator's fallback. v is counter-clockwise and strictly convex.
template <class Sink>
Location fanLocate(std::span<const Vec2> v, Vec2 p, Sink& sink) {
  if (nonFinite(p)) return Location::Outside;
  const std::uint32_t n = static_cast<std::uint32_t>(v.size());
  const Vec2 o = v[0];
  sink.apex(o);  // the rays below start here, also when polar falls back to the fan
  int first = orient2d(o, v[1], p);
  sink.ray(1, first);
  if (first < 0) return Location::Outside;  // clockwise of the first edge's line
  int last = orient2d(o, v[n - 1], p);
  sink.ray(n - 1, last);
  if (last > 0) return Location::Outside;  // counter-clockwise of the last edge's line
  if (first == 0 && last == 0) return Location::Boundary;  // p is vertex 0
  std::uint32_t lo = 1, hi = n - 1;  // orient(o, v[lo], p) >= 0 >= orient(o, v[hi], p)
  while (hi - lo > 1) {
    std::uint32_t mid = lo + (hi - lo) / 2;
    int s = orient2d(o, v[mid], p);
    sink.ray(mid, s);
    if (s >= 0) lo = mid;
    else hi = mid;
  }
  int s = orient2d(v[lo], v[hi], p);
  sink.edge(lo, s);
  if (s < 0) return Location::Outside;
  if (s == 0) return Location::Boundary;
  // strictly inside triangle edge lo; on the fan's outer rays means on edge 0 or n-1
  if ((lo == 1 && first == 0) || (hi == n - 1 && last == 0)) return Location::Boundary;
  return Location::Inside;
}

using detail::bytesOf;

// statistics of a CSR table
Stats2D csrStats(std::size_t edges, std::span<const std::uint32_t> offsets, std::size_t bytes,
                 double buildSeconds) {
  Stats2D s;
  s.edges = edges;
  s.cells = offsets.empty() ? 0 : offsets.size() - 1;
  s.bytes = bytes;
  s.bytesPerEdge = edges ? static_cast<double>(bytes) / static_cast<double>(edges) : 0.0;
  s.buildSeconds = buildSeconds;
  s.histogram.assign(kCrowdedCell + 2, 0);
  for (std::size_t c = 0; c < s.cells; ++c) {
    std::size_t k = offsets[c + 1] - offsets[c];
    s.entries += k;
    s.maxPerCell = std::max(s.maxPerCell, k);
    if (k > kCrowdedCell) ++s.crowdedCells;
    ++s.histogram[std::min(k, s.histogram.size() - 1)];
  }
  s.meanPerCell = s.cells ? static_cast<double>(s.entries) / static_cast<double>(s.cells) : 0.0;
  return s;
}

Stats2D plainStats(std::size_t edges, std::size_t bytes, double buildSeconds) {
  Stats2D s;
  s.edges = edges;
  s.bytes = bytes;
  s.bytesPerEdge = edges ? static_cast<double>(bytes) / static_cast<double>(edges) : 0.0;
  s.buildSeconds = buildSeconds;
  return s;
}

std::vector<Vec2> copyVertices(const ConvexPolygon& polygon) {
  return {polygon.vertices().begin(), polygon.vertices().end()};
}

}  // namespace

// === halfplane

HalfplaneLocator::HalfplaneLocator(const ConvexPolygon& polygon) {
  auto t0 = Clock::now();
  v_ = copyVertices(polygon);
  buildSeconds_ = secondsSince(t0);
}

Location HalfplaneLocator::locate(Vec2 p) const noexcept {
  if (nonFinite(p)) return Location::Outside;
  bool zero = false;
  const std::size_t n = v_.size();
  for (std::size_t i = 0; i < n; ++i) {
    int s = orient2d(v_[i], v_[i + 1 == n ? 0 : i + 1], p);
    if (s < 0) return Location::Outside;
    zero |= s == 0;
  }
  return zero ? Location::Boundary : Location::Inside;
}

void HalfplaneLocator::locate(std::span<const Vec2> points, std::span<Location> out) const noexcept {
  detail::locateEach(*this, points, out);
}

Trace2D HalfplaneLocator::trace(Vec2 p) const {
  Trace2D t;
  t.method = Method2D::Halfplane;
  if (nonFinite(p)) return t;  // Outside, before any predicate
  bool zero = false;
  t.result = Location::Inside;
  for (std::uint32_t i = 0; i < v_.size(); ++i) {
    int s = edgeSign(v_, i, p);
    t.edges.push_back({i, s});
    if (s < 0) {
      t.result = Location::Outside;
      return t;
    }
    zero |= s == 0;
  }
  if (zero) t.result = Location::Boundary;
  return t;
}

Stats2D HalfplaneLocator::stats() const {
  return plainStats(v_.size(), sizeof(*this) + bytesOf(v_), buildSeconds_);
}

// === wedge

WedgeLocator::WedgeLocator(const ConvexPolygon& polygon) {
  auto t0 = Clock::now();
  v_ = copyVertices(polygon);
  buildSeconds_ = secondsSince(t0);
}

Location WedgeLocator::locate(Vec2 p) const noexcept {
  NoSink sink;
  return fanLocate(v_, p, sink);
}

void WedgeLocator::locate(std::span<const Vec2> points, std::span<Location> out) const noexcept {
  detail::locateEach(*this, points, out);
}

Trace2D WedgeLocator::trace(Vec2 p) const {
  Trace2D t;
  t.method = Method2D::Wedge;
  t.apex = v_[0];
  TraceSink sink{t};
  t.result = fanLocate(v_, p, sink);
  if (!t.edges.empty()) t.cell = t.edges.back().edge;
  return t;
}

Stats2D WedgeLocator::stats() const {
  // the fan triangles of cells(): one per inner diagonal pair, holding 1 to 3 edges
  Stats2D s = plainStats(v_.size(), sizeof(*this) + bytesOf(v_), buildSeconds_);
  const std::size_t n = v_.size();
  s.cells = n - 2;
  s.entries = n;
  s.maxPerCell = n == 3 ? 3 : 2;
  s.meanPerCell = static_cast<double>(n) / static_cast<double>(n - 2);
  s.histogram.assign(kCrowdedCell + 2, 0);
  if (n == 3) {
    s.histogram[3] = 1;
  } else {
    s.histogram[2] = 2;
    s.histogram[1] = n - 4;
  }
  return s;
}

std::vector<Cell2D> WedgeLocator::cells() const {
  std::vector<Cell2D> out;
  const std::uint32_t n = static_cast<std::uint32_t>(v_.size());
  for (std::uint32_t i = 1; i + 1 < n; ++i) {
    Cell2D c;
    c.index = i;
    c.outline = {v_[0], v_[i], v_[i + 1]};
    c.edges = {i};
    if (i == 1) c.edges.insert(c.edges.begin(), 0);
    if (i + 2 == n) c.edges.push_back(n - 1);
    out.push_back(std::move(c));
  }
  return out;
}

// === slab

SlabLocator::SlabLocator(const ConvexPolygon& polygon) {
  auto t0 = Clock::now();
  v_ = copyVertices(polygon);
  box_ = polygon.bounds();
  const std::uint32_t n = static_cast<std::uint32_t>(v_.size());
  ys_.reserve(n);
  for (Vec2 p : v_) ys_.push_back(p.y);
  std::sort(ys_.begin(), ys_.end());
  ys_.erase(std::unique(ys_.begin(), ys_.end()), ys_.end());
  const std::size_t slabs = ys_.size() - 1;  // >= 1: a polygon with area spans some height
  active_.assign(2 * slabs, 0);
  auto rank = [&](double y) {
    return static_cast<std::size_t>(std::lower_bound(ys_.begin(), ys_.end(), y) - ys_.begin());
  };
  for (std::uint32_t e = 0; e < n; ++e) {
    Vec2 a = v_[e], b = v_[e + 1 == n ? 0 : e + 1];
    if (a.y == b.y) continue;
    bool rising = a.y < b.y;
    std::size_t r0 = rank(std::min(a.y, b.y)), r1 = rank(std::max(a.y, b.y));
    for (std::size_t s = r0; s < r1; ++s) active_[2 * s + (rising ? 0 : 1)] = e;
  }
  buildSeconds_ = secondsSince(t0);
}

template <class Sink>
Location SlabLocator::run(Vec2 p, Sink& sink) const noexcept {
  if (outsideBox(box_, p)) {
    sink.outsideBox();
    return Location::Outside;
  }
  const std::size_t slabs = ys_.size() - 1;
  std::size_t s = static_cast<std::size_t>(std::upper_bound(ys_.begin(), ys_.end(), p.y) - ys_.begin());
  s = std::min(s == 0 ? 0 : s - 1, slabs - 1);
  sink.cell(static_cast<std::int64_t>(s), -1);
  const std::uint32_t* pair = active_.data() + 2 * s;
  Location r = testEdges(v_, pair, pair + 2, p, sink);
  // on the bottom or top line, the only points between the chains are boundary points
  if (r == Location::Inside && (p.y == box_.lo.y || p.y == box_.hi.y)) return Location::Boundary;
  return r;
}

Location SlabLocator::locate(Vec2 p) const noexcept {
  NoSink sink;
  return run(p, sink);
}

void SlabLocator::locate(std::span<const Vec2> points, std::span<Location> out) const noexcept {
  detail::locateEach(*this, points, out);
}

Trace2D SlabLocator::trace(Vec2 p) const {
  Trace2D t;
  t.method = Method2D::Slab;
  TraceSink sink{t};
  t.result = run(p, sink);
  return t;
}

Stats2D SlabLocator::stats() const {
  Stats2D s = plainStats(v_.size(),
                         sizeof(*this) + bytesOf(v_) + bytesOf(ys_) + bytesOf(active_),
                         buildSeconds_);
  s.cells = ys_.size() - 1;
  s.entries = active_.size();
  s.maxPerCell = 2;
  s.meanPerCell = 2.0;
  s.histogram.assign(kCrowdedCell + 2, 0);
  s.histogram[2] = s.cells;
  return s;
}

std::vector<Cell2D> SlabLocator::cells() const {
  std::vector<Cell2D> out;
  for (std::size_t s = 0; s + 1 < ys_.size(); ++s) {
    Cell2D c;
    c.index = static_cast<std::uint32_t>(s);
    c.y0 = ys_[s];
    c.y1 = ys_[s + 1];
    c.outline = {{box_.lo.x, c.y0}, {box_.hi.x, c.y0}, {box_.hi.x, c.y1}, {box_.lo.x, c.y1}};
    c.edges = {active_[2 * s], active_[2 * s + 1]};
    out.push_back(std::move(c));
  }
  return out;
}

// === uniform

UniformLocator::UniformLocator(const ConvexPolygon& polygon, std::uint32_t slabs) {
  auto t0 = Clock::now();
  v_ = copyVertices(polygon);
  box_ = polygon.bounds();
  const std::uint32_t n = static_cast<std::uint32_t>(v_.size());
  if (slabs > (1u << 26)) throw UsageError("uniform: at most 2^26 slabs");
  slabs_ = slabs ? slabs : n;
  double extent = box_.hi.y - box_.lo.y;
  scale_ = static_cast<double>(slabs_) / extent;
  if (!std::isfinite(extent) || !std::isfinite(scale_)) {
    // too tall or too flat for the index arithmetic: one slab, searched by bisection
    slabs_ = 1;
    scale_ = 0.0;
  }
  // the bottom vertex: rising edges follow it in ascending y, then falling ones descend
  std::uint32_t bottom = 0;
  for (std::uint32_t i = 1; i < n; ++i)
    if (v_[i].y < v_[bottom].y) bottom = i;
  enum Kind { Rising, Falling, Flat };
  auto kindOf = [&](std::uint32_t e) {
    double a = v_[e].y, b = v_[e + 1 == n ? 0 : e + 1].y;
    return a < b ? Rising : (a > b ? Falling : Flat);
  };
  auto range = [&](std::uint32_t e) {
    double a = v_[e].y, b = v_[e + 1 == n ? 0 : e + 1].y;
    return std::pair{slabOf(std::min(a, b)), slabOf(std::max(a, b))};
  };
  std::vector<std::uint32_t> count(3 * std::size_t{slabs_}, 0);
  for (std::uint32_t e = 0; e < n; ++e) {
    auto [s0, s1] = range(e);
    Kind k = kindOf(e);
    for (std::uint32_t s = s0; s <= s1; ++s) ++count[3 * std::size_t{s} + k];
  }
  offsets_.assign(slabs_ + 1, 0);
  rising_.resize(slabs_);
  falling_.resize(slabs_);
  std::vector<std::uint64_t> cursor(3 * std::size_t{slabs_});
  std::uint64_t total = 0;
  for (std::uint32_t s = 0; s < slabs_; ++s) {
    offsets_[s] = static_cast<std::uint32_t>(total);
    rising_[s] = count[3 * s + Rising];
    falling_[s] = count[3 * s + Falling];
    cursor[3 * s + Rising] = total;
    cursor[3 * s + Falling] = total + rising_[s];
    cursor[3 * s + Flat] = total + rising_[s] + falling_[s];
    total += count[3 * s] + count[3 * s + 1] + count[3 * s + 2];
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw UsageError("uniform: the table would exceed 2^32 entries; use fewer slabs");
  }
  offsets_[slabs_] = static_cast<std::uint32_t>(total);
  entries_.resize(total);
  for (std::uint32_t k = 0; k < n; ++k) {
    std::uint32_t e = (bottom + k) % n;
    auto [s0, s1] = range(e);
    Kind kind = kindOf(e);
    for (std::uint32_t s = s0; s <= s1; ++s) entries_[cursor[3 * std::size_t{s} + kind]++] = e;
  }
  buildSeconds_ = secondsSince(t0);
}

std::uint32_t UniformLocator::slabOf(double y) const noexcept {
  double t = (y - box_.lo.y) * scale_;  // y >= lo.y; NaN only when scale_ is 0 and y - lo is inf
  return t < static_cast<double>(slabs_) ? static_cast<std::uint32_t>(t) : slabs_ - 1;
}

template <class Sink>
Location UniformLocator::run(Vec2 p, Sink& sink) const noexcept {
  if (outsideBox(box_, p)) {
    sink.outsideBox();
    return Location::Outside;
  }
  const std::uint32_t s = slabOf(p.y);
  sink.cell(s, -1);
  const std::uint32_t* first = entries_.data() + offsets_[s];
  const std::uint32_t* last = entries_.data() + offsets_[s + 1];
  if (static_cast<std::size_t>(last - first) <= kCrowdedCell) return testEdges(v_, first, last, p, sink);
  // crowded: the rising edge and the falling edge spanning p.y, and any horizontal edges
  sink.crowded();
  auto startY = [&](std::uint32_t e) { return v_[e].y; };
  const std::uint32_t r = rising_[s], f = falling_[s];
  // last rising edge starting at or below p.y
  const std::uint32_t* rise = std::upper_bound(first, first + r, p.y,
                                               [&](double y, std::uint32_t e) { return y < startY(e); });
  // last falling edge starting at or above p.y
  const std::uint32_t* fall = std::upper_bound(first + r, first + r + f, p.y,
                                               [&](double y, std::uint32_t e) { return y > startY(e); });
  std::uint32_t pick[4];
  std::uint32_t k = 0;
  pick[k++] = *(rise - 1);
  pick[k++] = *(fall - 1);
  for (const std::uint32_t* it = first + r + f; it != last && k < 4; ++it) pick[k++] = *it;
  return testEdges(v_, pick, pick + k, p, sink);
}

Location UniformLocator::locate(Vec2 p) const noexcept {
  NoSink sink;
  return run(p, sink);
}

void UniformLocator::locate(std::span<const Vec2> points, std::span<Location> out) const noexcept {
  detail::locateEach(*this, points, out);
}

Trace2D UniformLocator::trace(Vec2 p) const {
  Trace2D t;
  t.method = Method2D::Uniform;
  TraceSink sink{t};
  t.result = run(p, sink);
  return t;
}

Stats2D UniformLocator::stats() const {
  return csrStats(v_.size(), offsets_,
                  sizeof(*this) + bytesOf(v_) + bytesOf(offsets_) + bytesOf(entries_) +
                      bytesOf(rising_) + bytesOf(falling_),
                  buildSeconds_);
}

std::vector<Cell2D> UniformLocator::cells() const {
  std::vector<Cell2D> out;
  const double h = (box_.hi.y - box_.lo.y) / slabs_;
  for (std::uint32_t s = 0; s < slabs_; ++s) {
    Cell2D c;
    c.index = s;
    c.y0 = box_.lo.y + h * s;
    c.y1 = s + 1 == slabs_ ? box_.hi.y : box_.lo.y + h * (s + 1);
    c.outline = {{box_.lo.x, c.y0}, {box_.hi.x, c.y0}, {box_.hi.x, c.y1}, {box_.lo.x, c.y1}};
    c.edges.assign(entries_.begin() + offsets_[s], entries_.begin() + offsets_[s + 1]);
    out.push_back(std::move(c));
  }
  return out;
}

// === polar

namespace {

// The index function (cellOf) is, in exact arithmetic, floor(q * P) for the pseudo-angle P
// in [0, 8) of the direction from the centre: octant from signs and |dx| vs |dy|, then the
// ratio min/max of |dx|, |dy| inside it. In doubles the ratio carries a relative error of at
// most 2 ulps (one rounding in each subtraction, one in the division), so the cell a query
// computes lies within 2^-50 of its exact P, and on an octant border it may land on either
// side. The build evaluates the same quantities for each vertex and registers every edge on
// the cells of its span widened by this margin, far above those errors and far below a
// cell: every point maps to a cell listing the edge its ray from the centre exits through.
constexpr double kPolarMargin = 0x1p-40;

// per octant index (sign bit of dx, sign bit of dy, |dy| > |dx|): the octant counter-clockwise
// from +x, and whether the ratio min/max falls as the angle grows in it
struct OctantLayout {
  std::uint32_t octant;
  bool falling;
};
constexpr OctantLayout kOctantLayout[8] = {{0, false}, {1, true}, {7, true}, {6, false},
                                           {3, true},  {2, false}, {4, false}, {5, true}};

// Quadrant and canonical coordinates (u > 0, v >= 0) of a direction; false for (0, 0).
// Each quadrant is the direction rotated by a multiple of 90 degrees, which is exact.
inline bool canonical(double dx, double dy, int& quad, double& u, double& v) {
  if (dy >= 0 && dx > 0) { quad = 0; u = dx; v = dy; }
  else if (dx <= 0 && dy > 0) { quad = 1; u = dy; v = -dx; }
  else if (dx < 0 && dy <= 0) { quad = 2; u = -dx; v = -dy; }
  else if (dx >= 0 && dy < 0) { quad = 3; u = -dy; v = dx; }
  else return false;
  return true;
}

// the pseudo-angle in [0, 8] of a direction, computed with the query's own operations
double pseudoAngle(double dx, double dy) {
  int quad = 0;
  double u = 0, v = 0;
  canonical(dx, dy, quad, u, v);
  return v <= u ? 2 * quad + v / u : 2 * quad + 1 + (1 - u / v);
}

// direction for a pseudo-angle (drawing only)
Vec2 directionOf(double angle) {
  int oct = std::clamp(static_cast<int>(std::floor(angle)), 0, 7);
  double f = angle - oct;
  double u = 1, v = f;
  if (oct % 2) { u = 1 - f; v = 1; }
  switch (oct / 2) {
    case 0: return {u, v};
    case 1: return {-v, u};
    case 2: return {-u, -v};
    default: return {v, -u};
  }
}

// where the ray from c along d leaves the box b (c inside b)
Vec2 rayExit(const Box2& b, Vec2 c, Vec2 d) {
  double t = std::numeric_limits<double>::infinity();
  if (d.x > 0) t = std::min(t, (b.hi.x - c.x) / d.x);
  if (d.x < 0) t = std::min(t, (b.lo.x - c.x) / d.x);
  if (d.y > 0) t = std::min(t, (b.hi.y - c.y) / d.y);
  if (d.y < 0) t = std::min(t, (b.lo.y - c.y) / d.y);
  return {c.x + t * d.x, c.y + t * d.y};
}

// all edges strictly on the inner side of c
bool strictlyInside(const std::vector<Vec2>& v, Vec2 c) {
  for (std::uint32_t e = 0; e < v.size(); ++e)
    if (edgeSign(v, e, c) <= 0) return false;
  return true;
}

// a double point strictly inside, if one of a few natural candidates is
std::optional<Vec2> findCentre(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  std::vector<Vec2> candidates;
  long double sx = 0, sy = 0, ax = 0, ay = 0, area = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sx += static_cast<long double>(v[i].x) / n;
    sy += static_cast<long double>(v[i].y) / n;
    // area centroid of the fan from vertex 0, relative to vertex 0
    if (i >= 1 && i + 1 < n) {
      long double x1 = static_cast<long double>(v[i].x) - v[0].x;
      long double y1 = static_cast<long double>(v[i].y) - v[0].y;
      long double x2 = static_cast<long double>(v[i + 1].x) - v[0].x;
      long double y2 = static_cast<long double>(v[i + 1].y) - v[0].y;
      long double a = x1 * y2 - x2 * y1;
      area += a;
      ax += a * (x1 + x2) / 3;
      ay += a * (y1 + y2) / 3;
    }
  }
  if (area > 0)
    candidates.push_back({static_cast<double>(v[0].x + ax / area), static_cast<double>(v[0].y + ay / area)});
  candidates.push_back({static_cast<double>(sx), static_cast<double>(sy)});
  auto third = [&](std::size_t a, std::size_t b, std::size_t c) {
    long double x = (static_cast<long double>(v[a].x) + v[b].x + v[c].x) / 3;
    long double y = (static_cast<long double>(v[a].y) + v[b].y + v[c].y) / 3;
    return Vec2{static_cast<double>(x), static_cast<double>(y)};
  };
  candidates.push_back(third(0, n / 3, 2 * n / 3));
  // the triangle of the three vertices farthest apart along the box diagonal directions
  for (std::size_t i = 0; i + 2 < n && candidates.size() < 8; i += std::max<std::size_t>(1, n / 4))
    candidates.push_back(third(i, (i + 1) % n, (i + 2) % n));
  for (Vec2 c : candidates)
    if (std::isfinite(c.x) && std::isfinite(c.y) && strictlyInside(v, c)) return c;
  return std::nullopt;
}

}  // namespace

PolarLocator::PolarLocator(const ConvexPolygon& polygon, std::uint32_t slabsPerOctant) {
  auto t0 = Clock::now();
  v_ = copyVertices(polygon);
  box_ = polygon.bounds();
  const std::uint32_t n = static_cast<std::uint32_t>(v_.size());
  if (slabsPerOctant > (1u << 23)) throw UsageError("polar: at most 2^23 slabs per octant");
  // by default about one cell per 2 edges, and at least 64 cells: small polygons get cells
  // narrow enough for their radii to decide most points, large ones a table a quarter the
  // size of one with 2 cells per edge, which stays in cache far longer (a regular 2^20-gon,
  // one point per call: 14 ns against 47) while its radii still decide nearly every point
  q_ = slabsPerOctant ? slabsPerOctant : std::max<std::uint32_t>(8, (n + 15) / 16);
  qd_ = static_cast<double>(q_);
  n_ = n;
  const std::uint32_t cells = 8 * q_;
  for (std::size_t i = 0; i < 8; ++i) {
    const OctantLayout o = kOctantLayout[i];
    cellBase_[i] = static_cast<std::int64_t>(o.octant) * q_ + (o.falling ? q_ - 1 : 0);
    cellStep_[i] = o.falling ? -1 : 1;
  }
  auto centre = findCentre(v_);
  // the ring closes on itself: edges e and e + 1 read v_[e .. e + 2] without wrapping
  auto pad = [&] {
    v_.push_back(v_[0]);
    v_.push_back(v_[1]);
    v_.shrink_to_fit();
  };
  // A vertex whose direction from the centre overflows (a polygon wider than the double
  // range, from near -DBL_MAX to near DBL_MAX) has no pseudo-angle; found by the
  // differential fuzz target, where the build converted a NaN to an index.
  auto directionsFinite = [&] {
    for (std::uint32_t i = 0; i < n; ++i)
      if (!(std::fabs(v_[i].x - centre->x) + std::fabs(v_[i].y - centre->y) <
            std::numeric_limits<double>::infinity()))
        return false;
    return true;
  };
  if (!centre || !directionsFinite()) {
    // no double point lies strictly inside (a sliver thinner than the double grid), or the
    // directions overflow: keep an empty table and answer by bisection over the fan from
    // vertex 0
    c_ = v_[0];
    offsets_.assign(cells + 1, 0);
    radii_.assign(cells, {0.0f, std::numeric_limits<float>::infinity()});  // decide nothing
    pad();
    buildSeconds_ = secondsSince(t0);
    return;
  }
  c_ = *centre;

  // each edge's cells: its pseudo-angle span, widened by the margin, as a cyclic range
  std::vector<std::int64_t> first(n), last(n);
  std::vector<double> angle(n);
  for (std::uint32_t i = 0; i < n; ++i) angle[i] = pseudoAngle(v_[i].x - c_.x, v_[i].y - c_.y);
  std::vector<std::uint32_t> count(cells, 0);
  std::uint64_t total = 0;
  for (std::uint32_t e = 0; e < n; ++e) {
    double a0 = angle[e], a1 = angle[e + 1 == n ? 0 : e + 1];
    if (a1 < a0) a1 += 8;  // the span wraps past direction +x
    first[e] = static_cast<std::int64_t>(std::floor((a0 - kPolarMargin) * qd_));
    last[e] = static_cast<std::int64_t>(std::floor((a1 + kPolarMargin) * qd_));
    for (std::int64_t c = first[e]; c <= last[e]; ++c) ++count[((c % cells) + cells) % cells];
    total += static_cast<std::uint64_t>(last[e] - first[e] + 1);
  }
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw UsageError("polar: the table would exceed 2^32 entries; use fewer slabs");
  offsets_.assign(cells + 1, 0);
  for (std::uint32_t c = 0; c < cells; ++c) offsets_[c + 1] = offsets_[c] + count[c];
  entries_.resize(total);
  std::vector<std::uint32_t> cursor(offsets_.begin(), offsets_.end() - 1);
  for (std::uint32_t e = 0; e < n; ++e)
    for (std::int64_t c = first[e]; c <= last[e]; ++c) entries_[cursor[((c % cells) + cells) % cells]++] = e;
  // each cell's edges are a cyclic run; rotate those that wrap past edge 0 into order
  for (std::uint32_t c = 0; c < cells; ++c) {
    auto b = entries_.begin() + offsets_[c], end = entries_.begin() + offsets_[c + 1];
    if (static_cast<std::uint32_t>(end - b) == n) {
      // A run of every edge has no index gap (a needle 10^180 times longer than wide: seen
      // from the centre, the far vertices bunch into this cell and two edges span half a
      // turn each). It starts at the edge whose range began furthest before this cell, the
      // first of them if several began there, so that its inner vertices lie in the cell.
      auto back = [&](std::uint32_t e) { return ((c - first[e]) % cells + cells) % cells; };
      std::uint32_t start = 0;
      for (std::uint32_t e = 1; e < n; ++e)
        if (back(e) > back(start)) start = e;
      for (std::uint32_t k = 0; k < n && back(start == 0 ? n - 1 : start - 1) == back(start); ++k)
        start = start == 0 ? n - 1 : start - 1;
      std::rotate(b, b + start, end);
      continue;
    }
    for (auto it = b + 1; it < end; ++it)
      if (*it != *(it - 1) + 1) {
        std::rotate(b, it, end);
        break;
      }
  }
  // the per-edge arrays go before the radii are built: the build's peak is the table's
  first = {};
  last = {};
  angle = {};
  count = {};
  buildRadii();
  pad();
  buildSeconds_ = secondsSince(t0);
}

namespace {

// A lower bound on the squared distance from c to the line through a and b, for c strictly
// on its inner side (0 when the doubles cannot bound it: underflow, overflow). The cross
// product's filter bound makes the numerator a lower bound; the rest is a few roundings,
// which the radius slack covers. The distance is formed before it is squared: the cross
// product squared overflows long before the distance does (a triangle 10^150 long and
// 10^12 wide, found by the polygon reader's fuzz target, where the squared numerator
// became infinity and the cell claimed every point inside).
double lineDistance2Below(Vec2 a, Vec2 b, Vec2 c) {
  using detail::kCcwBound;
  const double ux = b.x - a.x, uy = b.y - a.y, wx = c.x - a.x, wy = c.y - a.y;
  const double l = ux * wy, m = uy * wx;
  const double permanent = std::fabs(l) + std::fabs(m);
  const double num = (l - m) - (kCcwBound * permanent + detail::kUnderflowSlack);
  const double len2 = ux * ux + uy * uy;
  if (!(permanent >= detail::kTinyPermanent) || !(num > 0) || !(len2 >= 0x1p-900) ||
      !(len2 <= std::numeric_limits<double>::max()))
    return 0.0;
  const double d = num / std::sqrt(len2);  // at most |c - a|, which is finite
  return d * d;  // infinity only where the true square exceeds the double range
}

// the squared distance of p from c, as the query computes it
inline double distance2(Vec2 p, Vec2 c) {
  const double dx = p.x - c.x, dy = p.y - c.y;
  return dx * dx + dy * dy;
}

}  // namespace

namespace {

// Tighter bounds for one cell and one of its edges: the points of edge (a, b) that rays from
// c with pseudo-angles in [angleLo, angleHi] (a cell's range, widened) can meet form a piece
// of it, from where the lower ray meets the edge's line to where the upper one does (the
// edge runs counter-clockwise around c). Its ends are computed in long double, moved out by
// 2^-20 of the edge, and fall back to the edge's ends where a ray misses the line or runs
// nearly along it. Over that piece the squared distance from c lies in [in2, out2]; each
// is also bounded by the whole edge's (edgeIn2, edgeOut2), and the tighter one is kept.
//
// Returns a bound on the squared distance from c to the edge's line along every ray of the
// range, where both boundary rays meet that line ahead (infinity otherwise): a ray leaves a
// convex polygon at the nearest edge line it meets ahead, so that bound alone bounds the
// exit point of every point of the cell.
double pieceBounds(Vec2 a, Vec2 b, Vec2 c, double angleLo, double angleHi, double& in2,
                   double& out2) {
  using L = long double;
  const L ux = L(b.x) - a.x, uy = L(b.y) - a.y, wx = L(a.x) - c.x, wy = L(a.y) - c.y;
  const L size = std::fabs(ux) + std::fabs(uy);
  constexpr L kMiss = std::numeric_limits<L>::infinity();
  auto along = [&](double angle) {
    const Vec2 d = directionOf(angle < 0 ? angle + 8 : (angle >= 8 ? angle - 8 : angle));
    const L den = L(d.x) * uy - L(d.y) * ux;  // > 0: the ray meets the line ahead of c
    if (!(den > 0x1p-30L * (std::fabs(L(d.x)) + std::fabs(L(d.y))) * size)) return kMiss;
    return -(L(d.x) * wy - L(d.y) * wx) / den;
  };
  auto dist = [&](L t) {
    const L x = wx + t * ux, y = wy + t * uy;
    return std::sqrt(x * x + y * y);
  };
  // rounding in the ends and distances stays far below this
  const L slack = 0x1p-50L * (std::fabs(wx) + std::fabs(wy) + size);
  const L lineLo = along(angleLo), lineHi = along(angleHi);
  double line2 = HUGE_VAL;
  if (lineLo != kMiss && lineHi != kMiss) {
    // where the boundary rays meet the line (far outside the edge, possibly), each moved by
    // far more than its rounding: the guard on den keeps t's error below 2^-30 of
    // |w| / size + |t|
    auto reach = [&](L t) {
      return dist(t) + 0x1p-30L * (std::fabs(t) * size + std::fabs(wx) + std::fabs(wy) + size) +
             slack;
    };
    const L far = std::max(reach(lineLo), reach(lineHi));
    line2 = static_cast<double>(far * far);
  }
  constexpr L kWiden = 0x1p-20L;
  const L t0 = std::clamp((lineLo != kMiss ? lineLo : 0) - kWiden, L(0), L(1));
  const L t1 = std::clamp((lineHi != kMiss ? lineHi : 1) + kWiden, L(0), L(1));
  if (!(t0 <= t1)) return line2;  // keep the whole edge's bounds
  const L d0 = dist(t0), d1 = dist(t1);
  const L far = std::max(d0, d1) + slack;
  out2 = std::min(out2, static_cast<double>(far * far));
  // the nearest point: the foot of the perpendicular if the piece holds it (then the line's
  // bound stands), else the nearer end
  const L foot = -(wx * ux + wy * uy) / (ux * ux + uy * uy);
  if (!(foot >= t0 - kWiden && foot <= t1 + kWiden)) {
    const L near = std::min(d0, d1) - slack;
    if (near > 0) in2 = std::max(in2, static_cast<double>(near * near));
  }
  return line2;
}

}  // namespace

void PolarLocator::buildRadii() {
  const std::uint32_t cells = 8 * q_;
  // a cell's range in pseudo-angle, widened far beyond the query's index error (2^-50) and
  // the rounding of the directions drawn from it
  constexpr double kWidenAngle = 0x1p-30;
  radii_.resize(cells);
  for (std::uint32_t c = 0; c < cells; ++c) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0, anyLine = HUGE_VAL;
    const double angleLo = c / qd_ - kWidenAngle, angleHi = (c + 1) / qd_ + kWidenAngle;
    for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
      // the whole edge's bounds, then its piece's (computed per entry: no array per edge,
      // so the build's peak memory stays that of the table)
      const std::uint32_t e = entries_[k];
      const Vec2 a = v_[e], b = v_[e + 1 == n_ ? 0 : e + 1];
      double edgeIn2 = lineDistance2Below(a, b, c_);
      double edgeOut2 = std::max(distance2(a, c_), distance2(b, c_));
      anyLine = std::min(anyLine, pieceBounds(a, b, c_, angleLo, angleHi, edgeIn2, edgeOut2));
      lo = std::min(lo, edgeIn2);
      hi = std::max(hi, edgeOut2);
    }
    hi = std::min(hi, anyLine);
    if (offsets_[c] == offsets_[c + 1]) lo = 0.0, hi = std::numeric_limits<double>::infinity();
    radii_[c] = {detail::innerBound(lo), detail::outerBound(hi)};
  }
}

std::int64_t PolarLocator::cellOf(Vec2 p) const noexcept { return cellIndex(p); }

inline std::int64_t PolarLocator::cellIndex(Vec2 p) const noexcept {
  const double dx = p.x - c_.x, dy = p.y - c_.y;
  const double ax = std::fabs(dx), ay = std::fabs(dy);
  const double hi = std::max(ax, ay), lo = std::min(ax, ay);  // maxsd / minsd, no branch
  // the centre itself, a non-finite point, or one too far for the arithmetic
  if (!(ax + ay < std::numeric_limits<double>::infinity()) || hi == 0) return -1;
  const std::uint32_t k = std::min(static_cast<std::uint32_t>(lo / hi * qd_), q_ - 1);
  const unsigned octant = (std::signbit(dx) ? 4u : 0u) | (std::signbit(dy) ? 2u : 0u) | (ay > ax ? 1u : 0u);
  return cellBase_[octant] + cellStep_[octant] * static_cast<std::int64_t>(k);
}

template <class Sink>
Location PolarLocator::searchRange(Vec2 p, std::uint32_t first, std::uint32_t count,
                                   Sink& sink) const noexcept {
  // The run's inner vertices and p's direction lie within the cell's widened angular range
  // (under 90 degrees), so the side of each ray from the centre is monotone along the run.
  const std::uint32_t* e = entries_.data() + first;
  std::uint32_t lo = 0, hi = count;
  while (hi - lo > 1) {
    std::uint32_t mid = lo + (hi - lo) / 2;
    int s = orient2d(c_, v_[e[mid]], p);
    sink.ray(e[mid], s);
    if (s >= 0) lo = mid;
    else hi = mid;
  }
  // the ray from the centre through p leaves through edge e[lo]: one test decides
  int s = edgeSign(ring(), e[lo], p);
  sink.edge(e[lo], s);
  return s > 0 ? Location::Inside : (s == 0 ? Location::Boundary : Location::Outside);
}

template <class Sink>
Location PolarLocator::run(Vec2 p, Sink& sink) const noexcept {
  if (entries_.empty()) return fanLocate(ring(), p, sink);  // no centre strictly inside
  std::int64_t c = cellOf(p);
  if (c < 0) {
    if (p == c_) {
      sink.atCentre();
      return Location::Inside;
    }
    return fanLocate(ring(), p, sink);  // offsets too large for the index arithmetic
  }
  const std::uint32_t cell = static_cast<std::uint32_t>(c);
  sink.cell(c, static_cast<int>(cell / q_));
  const Radii r = radii_[cell];
  const double d2 = distance2(p, c_);
  const bool decided = detail::radiiDecide(d2, r.in2, r.out2);
  sink.radius(d2, r.in2, r.out2, decided);
  if (decided) return detail::insideOrOutside(d2 > static_cast<double>(r.out2));
  const std::uint32_t b = offsets_[cell], k = offsets_[cell + 1] - b;
  if (k <= kCrowdedCell) return testEdges(ring(), entries_.data() + b, entries_.data() + b + k, p, sink);
  sink.crowded();
  return searchRange(p, b, k, sink);
}

namespace {

// Inside / Outside from the filtered signs of p against edges (r0, r1) and (r1, r2), without a
// branch on the answer; false when the filter cannot decide one of them (then the caller
// takes the exact path). Testing a second edge that the cell does not list is harmless:
// p is inside the polygon only if it is on the inner side of every edge.
inline bool twoEdges(const Vec2* r, Vec2 p, Location& out) noexcept {
  using detail::kCcwBound;
  using detail::kTinyPermanent;
  using detail::kUnderflowSlack;
  const double l0 = (r[0].x - p.x) * (r[1].y - p.y), m0 = (r[0].y - p.y) * (r[1].x - p.x);
  const double l1 = (r[1].x - p.x) * (r[2].y - p.y), m1 = (r[1].y - p.y) * (r[2].x - p.x);
  const double d0 = l0 - m0, d1 = l1 - m1;
  const double s0 = std::fabs(l0) + std::fabs(m0), s1 = std::fabs(l1) + std::fabs(m1);
  const bool sure = std::fabs(d0) > kCcwBound * s0 + kUnderflowSlack && s0 >= kTinyPermanent &&
                    std::fabs(d1) > kCcwBound * s1 + kUnderflowSlack && s1 >= kTinyPermanent;
  out = ((d0 < 0) | (d1 < 0)) ? Location::Outside : Location::Inside;
  return sure;
}

}  // namespace

Location PolarLocator::locate(Vec2 p) const noexcept {
  const std::int64_t c = cellIndex(p);
  if (c >= 0) {
    const Radii r = radii_[static_cast<std::size_t>(c)];
    const double d2 = distance2(p, c_);
    // one branch, taken by most points, then the answer without one
    if (detail::radiiDecide(d2, r.in2, r.out2)) return detail::insideOrOutside(d2 > static_cast<double>(r.out2));
    const std::uint32_t b = offsets_[static_cast<std::size_t>(c)];
    const std::uint32_t k = offsets_[static_cast<std::size_t>(c) + 1] - b;
    Location out;
    if (k - 1 < 2 && twoEdges(v_.data() + entries_[b], p, out)) return out;
  }
  NoSink sink;
  return run(p, sink);
}

namespace {

// what the vector cell index needs of the locator
struct PolarParams {
  Vec2 c;
  double qd, lastSlab;
  std::int32_t base[8], step[8];
};

#if defined(__x86_64__)
// PolarLocator::cellIndex and the squared distance for 4 points at a time, in AVX2 (no FMA:
// every operation rounds as the scalar code does, so the cells are the scalar ones; lanes
// the scalar code gives -1 get -1). Returns how many points it did (a multiple of 4).
__attribute__((target("avx2"))) std::size_t polarAimAvx2(const Vec2* p, std::size_t m,
                                                         const PolarParams& a, std::int64_t* cell,
                                                         double* d2) noexcept {
  const __m256d cx = _mm256_set1_pd(a.c.x), cy = _mm256_set1_pd(a.c.y);
  const __m256d sign = _mm256_set1_pd(-0.0), inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  const __m256d qd = _mm256_set1_pd(a.qd), last = _mm256_set1_pd(a.lastSlab);
  const __m256i base = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a.base));
  const __m256i step = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a.step));
  const __m256i low32 = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);  // int64 lanes to int32
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    // 4 points as 2 loads (x0 y0 x1 y1 | x2 y2 x3 y3), regrouped by coordinate
    const double* q = &p[j].x;
    static_assert(sizeof(Vec2) == 2 * sizeof(double));
    const __m256d v0 = _mm256_loadu_pd(q), v1 = _mm256_loadu_pd(q + 4);
    const __m256d xs = _mm256_permute4x64_pd(_mm256_unpacklo_pd(v0, v1), _MM_SHUFFLE(3, 1, 2, 0));
    const __m256d ys = _mm256_permute4x64_pd(_mm256_unpackhi_pd(v0, v1), _MM_SHUFFLE(3, 1, 2, 0));
    const __m256d dx = _mm256_sub_pd(xs, cx), dy = _mm256_sub_pd(ys, cy);
    const __m256d ax = _mm256_andnot_pd(sign, dx), ay = _mm256_andnot_pd(sign, dy);
    const __m256d hi = _mm256_max_pd(ax, ay), lo = _mm256_min_pd(ax, ay);
    const __m256d good = _mm256_and_pd(_mm256_cmp_pd(_mm256_add_pd(ax, ay), inf, _CMP_LT_OQ),
                                       _mm256_cmp_pd(hi, zero, _CMP_NEQ_OQ));
    // lanes that are not good may divide 0 by 0: masked to 0 before converting
    const __m256d k = _mm256_and_pd(good, _mm256_min_pd(_mm256_mul_pd(_mm256_div_pd(lo, hi), qd), last));
    const __m128i slab = _mm256_cvttpd_epi32(k);
    // sign bits of dx and dy as 0 / 1 in 32-bit lanes (a lambda would lose the target)
    const __m128i sx = _mm256_castsi256_si128(
        _mm256_permutevar8x32_epi32(_mm256_srli_epi64(_mm256_castpd_si256(dx), 63), low32));
    const __m128i sy = _mm256_castsi256_si128(
        _mm256_permutevar8x32_epi32(_mm256_srli_epi64(_mm256_castpd_si256(dy), 63), low32));
    const __m128i steep = _mm256_cvttpd_epi32(_mm256_and_pd(_mm256_cmp_pd(ay, ax, _CMP_GT_OQ), one));
    const __m128i octant =
        _mm_or_si128(_mm_or_si128(_mm_slli_epi32(sx, 2), _mm_slli_epi32(sy, 1)), steep);
    const __m256i index = _mm256_castsi128_si256(octant);
    const __m128i b = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(base, index));
    const __m128i st = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(step, index));
    __m128i c = _mm_add_epi32(b, _mm_mullo_epi32(st, slab));
    const __m128i bad = _mm256_cvtpd_epi32(_mm256_andnot_pd(good, one));  // 1 where not good
    c = _mm_or_si128(c, _mm_sub_epi32(_mm_setzero_si128(), bad));        // -1 there
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(cell + j), _mm256_cvtepi32_epi64(c));
    _mm256_storeu_pd(d2 + j, _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)));
  }
  return j;
}

// for each 4-bit mask of open lanes, those lanes in order (then zeros)
struct LaneLists {
  alignas(16) std::uint32_t lanes[16][4] = {};
  constexpr LaneLists() {
    for (std::uint32_t mask = 0; mask < 16; ++mask) {
      std::uint32_t k = 0;
      for (std::uint32_t lane = 0; lane < 4; ++lane)
        if (mask >> lane & 1) lanes[mask][k++] = lane;
    }
  }
};
inline constexpr LaneLists kOpenLanes;

// cell `c`'s radii as one 64-bit word (in2 in the low half), copied rather than read through
// a pointer of another type
inline long long radiiWord(const void* radii, std::int64_t c) noexcept {
  long long w;
  std::memcpy(&w, static_cast<const char*>(radii) + 8 * c, sizeof w);
  return w;
}

// The radii stage of PolarLocator's batch for 4 points at a time, in AVX2. Each lane loads
// its cell's radii as one 64-bit word (in2 low, out2 high; 4 plain loads, which beat
// vpgatherqq on the AMD cores measured), widens both to double (exact, as the scalar casts)
// and forms radiiDecide's product and the verdict's comparison with the same roundings (no
// FMA), so every lane gets the scalar answer. Lanes with no cell read cell 0 and are open.
// Writes the 4 verdicts, appends the open lanes to `pending` at `left` and prefetches their
// offsets, as the scalar loop does; returns how many points it did (a multiple of 4).
__attribute__((target("avx2"))) std::size_t polarDecideAvx2(const std::int64_t* cell, const double* d2,
                                                            std::size_t m, const void* radii,
                                                            const std::uint32_t* offsets, Location* o,
                                                            std::uint32_t* pending,
                                                            std::size_t& left) noexcept {
  // a local count: `left` itself might alias the stores through `pending` and `o`, which
  // would keep it in memory and chain every group to the previous one's store
  std::size_t open = left;
  const __m256i halves = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);  // in2 x4 | out2 x4
  const __m256d zero = _mm256_setzero_pd();
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    std::int64_t c[4];
    for (int k = 0; k < 4; ++k) c[k] = std::max<std::int64_t>(cell[j + k], 0);
    const __m256i r = _mm256_permutevar8x32_epi32(
        _mm256_setr_epi64x(radiiWord(radii, c[0]), radiiWord(radii, c[1]), radiiWord(radii, c[2]),
                           radiiWord(radii, c[3])), halves);
    const __m256d in2 = _mm256_cvtps_pd(_mm_castsi128_ps(_mm256_castsi256_si128(r)));
    const __m256d out2 = _mm256_cvtps_pd(_mm_castsi128_ps(_mm256_extracti128_si256(r, 1)));
    const __m256d d = _mm256_loadu_pd(d2 + j);
    // the verdicts' 4 bits spread to the low bit of 4 bytes, times 2: Inside 0, Outside 2
    const auto farther =
        static_cast<std::uint32_t>(_mm256_movemask_pd(_mm256_cmp_pd(d, out2, _CMP_GT_OQ)));
    const std::uint32_t verdicts = (farther * 0x204081u & 0x01010101u) * 2;
    static_assert(sizeof(Location) == 1);
    std::memcpy(o + j, &verdicts, 4);
    // open: no cell, or not decided (a NaN product compares false, as in the scalar code)
    const __m256d decided =
        _mm256_cmp_pd(_mm256_mul_pd(_mm256_sub_pd(d, in2), _mm256_sub_pd(d, out2)), zero, _CMP_GT_OQ);
    const __m256i ci = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cell + j));
    const __m256i none = _mm256_cmpgt_epi64(_mm256_setzero_si256(), ci);
    const auto lanes = static_cast<std::uint32_t>((_mm256_movemask_pd(decided) ^ 15) |
                                                  _mm256_movemask_pd(_mm256_castsi256_pd(none)));
    // a 16-byte store of the open lanes' indices: open never passes j, so it stays in the block
    const __m128i list = _mm_load_si128(reinterpret_cast<const __m128i*>(kOpenLanes.lanes[lanes]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(pending + open),
                     _mm_add_epi32(list, _mm_set1_epi32(static_cast<int>(j))));
    open += static_cast<std::size_t>(__builtin_popcount(lanes));
    for (int k = 0; k < 4; ++k) __builtin_prefetch(offsets + (lanes >> k & 1 ? c[k] : 0));
  }
  left = open;
  return j;
}
#else
std::size_t polarAimAvx2(const Vec2*, std::size_t, const PolarParams&, std::int64_t*, double*) noexcept {
  return 0;
}
std::size_t polarDecideAvx2(const std::int64_t*, const double*, std::size_t, const void*,
                            const std::uint32_t*, Location*, std::uint32_t*, std::size_t&) noexcept {
  return 0;
}
#endif

}  // namespace

void PolarLocator::locate(std::span<const Vec2> points, std::span<Location> out) const noexcept {
  // Blocks of points go through the table in stages (cell radii, then for the points they do
  // not decide the cell's run, then its edges), prefetching each stage's memory for the
  // whole block before the next stage reads it, so that the cache misses of a large table
  // overlap instead of following one another.
  constexpr std::size_t kBlock = 32;
  const std::size_t n = std::min(points.size(), out.size());
  std::int64_t cell[kBlock];
  double dist2[kBlock];
  std::uint32_t first[kBlock], count[kBlock], pending[kBlock];
  const bool vector = vectorBatches();
  // The radii pass pays only where the table outgrows the L2 (1 MiB on the machines
  // measured): below that the vector stage's loads hit it anyway and the pass costs more than
  // it hides. The scalar stage keeps it always, as before.
  const bool prefetchRadii = !vector || radii_.size() * sizeof(Radii) > (std::size_t{1} << 20);
  PolarParams params{c_, qd_, static_cast<double>(q_ - 1), {}, {}};
  for (int i = 0; i < 8; ++i) {
    params.base[i] = static_cast<std::int32_t>(cellBase_[i]);
    params.step[i] = static_cast<std::int32_t>(cellStep_[i]);
  }
  for (std::size_t i0 = 0; i0 < n; i0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - i0);
    const Vec2* p = points.data() + i0;
    Location* o = out.data() + i0;
    for (std::size_t j = vector ? polarAimAvx2(p, m, params, cell, dist2) : 0; j < m; ++j) {
      cell[j] = cellIndex(p[j]);
      dist2[j] = distance2(p[j], c_);
    }
    if (prefetchRadii)
      for (std::size_t j = 0; j < m; ++j)
        if (cell[j] >= 0) __builtin_prefetch(radii_.data() + cell[j]);
    // Without a branch on the answer (inside or outside come at random): every point writes
    // its radius verdict and its index, and only the open ones (between the radii, or with
    // no cell) advance the list of those left for the next stages.
    std::size_t left = 0, decided = 0;
    if (vector) {
      static_assert(sizeof(Radii) == 8 && offsetof(Radii, in2) == 0 && offsetof(Radii, out2) == 4);
      decided = polarDecideAvx2(cell, dist2, m, radii_.data(), offsets_.data(), o, pending, left);
    }
    for (std::size_t j = decided; j < m; ++j) {
      const std::size_t c = cell[j] >= 0 ? static_cast<std::size_t>(cell[j]) : 0;
      const Radii r = radii_[c];
      const double d2 = dist2[j];
      o[j] = detail::insideOrOutside(d2 > static_cast<double>(r.out2));
      const bool open = (cell[j] < 0) | !detail::radiiDecide(d2, r.in2, r.out2);
      pending[left] = static_cast<std::uint32_t>(j);
      left += open;
      __builtin_prefetch(offsets_.data() + (open ? c : 0));
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      first[j] = 0;
      count[j] = 0;
      if (cell[j] < 0) continue;
      first[j] = offsets_[static_cast<std::size_t>(cell[j])];
      count[j] = offsets_[static_cast<std::size_t>(cell[j]) + 1] - first[j];
      __builtin_prefetch(entries_.data() + first[j]);
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      if (count[j] - 1 >= 2) continue;
      first[j] = entries_[first[j]];  // now the first edge
      __builtin_prefetch(v_.data() + first[j]);
      __builtin_prefetch(v_.data() + first[j] + 2);
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      Location r;
      if (count[j] - 1 < 2 && twoEdges(v_.data() + first[j], p[j], r)) {
        o[j] = r;
      } else {
        NoSink sink;
        o[j] = run(p[j], sink);
      }
    }
  }
}

Trace2D PolarLocator::trace(Vec2 p) const {
  Trace2D t;
  t.method = Method2D::Polar;
  t.apex = entries_.empty() ? v_[0] : c_;
  TraceSink sink{t};
  t.result = run(p, sink);
  return t;
}

Stats2D PolarLocator::stats() const {
  return csrStats(n_, offsets_,
                  sizeof(*this) + bytesOf(v_) + bytesOf(offsets_) + bytesOf(entries_) +
                      bytesOf(radii_),
                  buildSeconds_);
}

std::vector<Cell2D> PolarLocator::cells() const {
  std::vector<Cell2D> out;
  if (entries_.empty()) return out;
  const std::uint32_t cells = 8 * q_;
  Vec2 corners[4] = {box_.hi, {box_.lo.x, box_.hi.y}, box_.lo, {box_.hi.x, box_.lo.y}};
  for (std::uint32_t i = 0; i < cells; ++i) {
    Cell2D c;
    c.index = i;
    c.octant = static_cast<int>(i / q_);
    double a0 = static_cast<double>(i) / qd_, a1 = static_cast<double>(i + 1) / qd_;
    c.dirLo = directionOf(a0);
    c.dirHi = directionOf(a1 >= 8 ? 8 - 1e-12 : a1);
    c.hitLo = rayExit(box_, c_, c.dirLo);
    c.hitHi = rayExit(box_, c_, c.dirHi);
    c.outline = {c_, c.hitLo};
    for (Vec2 k : corners) {
      double a = pseudoAngle(k.x - c_.x, k.y - c_.y);
      if (a > a0 && a < a1) c.outline.push_back(k);
    }
    c.outline.push_back(c.hitHi);
    c.edges.assign(entries_.begin() + offsets_[i], entries_.begin() + offsets_[i + 1]);
    out.push_back(std::move(c));
  }
  return out;
}

// === Locator2D

namespace {
std::variant<HalfplaneLocator, WedgeLocator, SlabLocator, UniformLocator, PolarLocator> build(
    const ConvexPolygon& polygon, Method2D method, std::uint32_t resolution) {
  switch (method) {
    case Method2D::Halfplane: return HalfplaneLocator(polygon);
    case Method2D::Wedge: return WedgeLocator(polygon);
    case Method2D::Slab: return SlabLocator(polygon);
    case Method2D::Uniform: return UniformLocator(polygon, resolution);
    case Method2D::Polar: break;
  }
  return PolarLocator(polygon, resolution);
}
}  // namespace

Locator2D::Locator2D(const ConvexPolygon& polygon, Method2D method, std::uint32_t resolution)
    : impl_(build(polygon, method, resolution)) {}

Location Locator2D::locate(Vec2 p) const noexcept {
  return std::visit([&](const auto& l) { return l.locate(p); }, impl_);
}
void Locator2D::locate(std::span<const Vec2> points, std::span<Location> out) const noexcept {
  std::visit([&](const auto& l) { l.locate(points, out); }, impl_);
}
Trace2D Locator2D::trace(Vec2 p) const {
  return std::visit([&](const auto& l) { return l.trace(p); }, impl_);
}
Stats2D Locator2D::stats() const {
  return std::visit([&](const auto& l) { return l.stats(); }, impl_);
}
std::vector<Cell2D> Locator2D::cells() const {
  return std::visit([&](const auto& l) { return l.cells(); }, impl_);
}

}  // namespace convexloc
