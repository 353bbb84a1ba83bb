// convexloc — LineIntersector: one method chosen at build time, the answers it shares.
//
// Every method reaches a vertex where f is largest and one where it is smallest (the
// vertices method by its scan), and the crossing is read from their exact signs
// (crossingOf). Only how the two vertices are found differs: bisection (O(log N)), or the
// dual table's proposals and a short climb (O(1), see dual_polar.cpp).
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include "convexloc/intersect2d.hpp"
#include "convexloc/predicates.hpp"
#include "convexloc/table.hpp"
#include "convexloc/timing.hpp"
#include "intersect/blocks.hpp"
#include "intersect/dual_polar.hpp"
#include "intersect/hits2d.hpp"
#include "intersect/ring2d.hpp"
#include "intersect/scan.hpp"

namespace convexloc {

namespace {

// moves a climb from the dual's proposal may take before bisection takes over
constexpr std::uint32_t kClimbMoves = 8;

// one method: its enum value, what --method takes, the cost of one query
struct LineMethodInfo {
  LineMethod method;
  std::string_view name, cost;
};
constexpr std::array<LineMethodInfo, 3> kLineMethods = {
    {{LineMethod::Vertices, "vertices", "O(N)"},
     {LineMethod::Bisection, "bisection", "O(log N)"},
     {LineMethod::Dual, "dual", "O(1)"}}};

}  // namespace

std::string_view toString(LineMethod m) noexcept {
  return kLineMethods[static_cast<std::size_t>(m)].name;
}

std::string_view costOf(LineMethod m) noexcept {
  return kLineMethods[static_cast<std::size_t>(m)].cost;
}

std::optional<LineMethod> parseLineMethod(std::string_view name) noexcept {
  for (const LineMethodInfo& m : kLineMethods)
    if (m.name == name) return m.method;
  return std::nullopt;
}

LineIntersector::LineIntersector(const ConvexPolygon& polygon, LineMethod method)
    : method_(method), ring_(polygon.vertices().begin(), polygon.vertices().end()) {
  const auto t0 = Clock::now();
  if (method_ == LineMethod::Dual) dual_ = std::make_unique<detail::DualPolar2D>(ring_);
  buildSeconds_ = secondsSince(t0);
}

LineIntersector::~LineIntersector() = default;
LineIntersector::LineIntersector(LineIntersector&&) noexcept = default;
LineIntersector& LineIntersector::operator=(LineIntersector&&) noexcept = default;

std::uint32_t LineIntersector::largestFrom(std::int64_t c, detail::LineProbe& probe, Vec2& at,
                                           std::uint32_t& steps, bool& bisected) const noexcept {
  const detail::RingWindow& w = dual_->window(c);
  const std::uint32_t s = dual_->proposal(c);
  if (const int k = detail::largestInWindow(w.v, probe); k != 0) {
    at = w.v[k];
    if (k == 1) return s;
    ++steps;
    return detail::nextOf(s, ring_.size());
  }
  std::uint32_t i = s;
  if (!detail::climbToLargest(ring_, probe, i, steps + kClimbMoves, steps)) {
    i = detail::bisectLargest(ring_, probe);
    bisected = true;
  }
  at = ring_[i];
  return i;
}

ExtremeVertices LineIntersector::extremes(Vec2 p1, Vec2 p2, LineTrace* trace) const noexcept {
  detail::LineProbe up{p1, p2}, down = up.reversed();
  ExtremeVertices e;
  std::int64_t cell = -1, opposite = -1;
  std::uint32_t steps = 0, startMax = 0, startMin = 0;
  bool bisected = false;
  if (method_ == LineMethod::Vertices) {
    e.largest = detail::scanLargest<Vec2>(ring_, up);
    e.smallest = detail::scanLargest<Vec2>(ring_, down);
  } else if (std::int64_t high = -1, low = -1;
             method_ == LineMethod::Dual && dual_->cells(p1, p2, high, low)) {
    if (trace) dual_->polarCells(p1, p2, cell, opposite);
    startMax = dual_->proposal(high);
    startMin = dual_->proposal(low);
    Vec2 at;
    e.largest = largestFrom(high, up, at, steps, bisected);
    e.smallest = largestFrom(low, down, at, steps, bisected);
  } else {
    cell = opposite = -1;
    e.largest = detail::bisectLargest(ring_, up);
    e.smallest = detail::bisectLargest(ring_, down);
    bisected = method_ == LineMethod::Dual;
  }
  e.largestSign = orient2d(p1, p2, ring_[e.largest]);
  e.smallestSign = orient2d(p1, p2, ring_[e.smallest]);
  if (trace) {
    trace->extremes = e;
    trace->cell = cell;
    trace->opposite = opposite;
    trace->startMax = startMax;
    trace->startMin = startMin;
    trace->climbSteps = steps;
    trace->bisected = bisected;
    trace->comparisons = up.comparisons + down.comparisons;
  }
  return e;
}

// Both windows confirmed (nearly every line): each extreme's sign read with no branch on the
// line's data; a window that confirms neither vertex goes the general way (largestFrom).
Crossing LineIntersector::classifyInCells(Vec2 p1, Vec2 p2, std::int64_t up,
                                          std::int64_t down) const noexcept {
  const detail::RingWindow& high = dual_->window(up);
  const detail::RingWindow& low = dual_->window(down);
  const int kHigh = detail::largestInWindowFlat(high.v, p1, p2);
  const int kLow = detail::largestInWindowFlat(low.v, p2, p1);
  if ((kHigh == 0) | (kLow == 0)) [[unlikely]] {
    detail::LineProbe probeHigh{p1, p2}, probeLow = probeHigh.reversed();
    Vec2 largest, smallest;
    std::uint32_t steps = 0;
    bool bisected = false;
    largestFrom(up, probeHigh, largest, steps, bisected);
    largestFrom(down, probeLow, smallest, steps, bisected);
    return crossingOf(orient2d(p1, p2, largest), orient2d(p1, p2, smallest));
  }
  const Vec2 largest = high.v[kHigh], smallest = low.v[kLow];
  // orient2d(p1, p2, v) is the cross product (p1 - v) x (p2 - v)
  return crossingOf(detail::crossSign(largest, p1, largest, p2),
                    detail::crossSign(smallest, p1, smallest, p2));
}

Crossing LineIntersector::classify(Vec2 p1, Vec2 p2) const noexcept {
  if (method_ == LineMethod::Vertices) return detail::crossingBySides(ring_, p1, p2);
  std::int64_t up = -1, down = -1;
  if (method_ == LineMethod::Dual && dual_->cells(p1, p2, up, down)) {
    dual_->prefetch(up);  // both windows requested at once
    dual_->prefetch(down);
    return classifyInCells(p1, p2, up, down);
  }
  const ExtremeVertices e = extremes(p1, p2, nullptr);
  return crossingOf(e.largestSign, e.smallestSign);
}

// The dual batch through detail::inBlocks (blocks.hpp): the cells of the next block are found
// and their windows prefetched while this block is confirmed. Every line gets what
// classify(p1, p2) gives it.
void LineIntersector::classify(std::span<const Vec2> lines,
                               std::span<Crossing> out) const noexcept {
  const std::size_t n = std::min(lines.size() / 2, out.size());
  if (method_ != LineMethod::Dual) {
    for (std::size_t i = 0; i < n; ++i) out[i] = classify(lines[2 * i], lines[2 * i + 1]);
    return;
  }
  detail::inBlocks(
      n,
      [&](std::size_t i, std::int64_t& up, std::int64_t& down) {
        if (!dual_->cells(lines[2 * i], lines[2 * i + 1], up, down)) return false;
        dual_->prefetch(up);
        dual_->prefetch(down);
        return true;
      },
      [&](std::size_t i, std::int64_t up, std::int64_t down) {
        const Vec2 p1 = lines[2 * i], p2 = lines[2 * i + 1];
        out[i] = up < 0 ? classify(p1, p2) : classifyInCells(p1, p2, up, down);
      });
}

LineHit LineIntersector::intersect(Vec2 p1, Vec2 p2) const noexcept {
  if (method_ == LineMethod::Vertices) return detail::hitsBySides(ring_, p1, p2);
  const ExtremeVertices e = extremes(p1, p2, nullptr);
  return detail::hitsFromExtremes(ring_, p1, p2, e.largest, e.smallest, e.largestSign,
                                  e.smallestSign);
}

LineTrace LineIntersector::trace(Vec2 p1, Vec2 p2) const {
  LineTrace t;
  t.method = method_;
  const ExtremeVertices e = extremes(p1, p2, &t);
  t.crossing = crossingOf(e.largestSign, e.smallestSign);
  return t;
}

LineStats LineIntersector::stats() const {
  LineStats s;
  s.vertices = ring_.size();
  s.bytes = detail::bytesOf(ring_);
  s.buildSeconds = buildSeconds_;
  if (dual_) {
    s.dualVertices = dual_->dualVertices();
    s.cells = dual_->locator() ? dual_->locator()->cellCount() : 0;
    s.maxPerCell = dual_->maxPerCell();
    s.bytes += dual_->bytes();
  }
  return s;
}

const PolarLocator* LineIntersector::dualLocator() const noexcept {
  return dual_ ? dual_->locator() : nullptr;
}

std::span<const Vec2> LineIntersector::dualVertices() const noexcept {
  if (!dual_) return {};
  return dual_->vertices();
}

}  // namespace convexloc
