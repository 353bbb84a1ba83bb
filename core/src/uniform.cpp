// convexloc — the uniform locator, O(1): equal horizontal slabs over the bounding box (eq. 4),
// each listing every edge whose y range meets it, built with slabOf(), the query's own index
// function, so that every slab lists every edge a point mapped to it can exit through.
//
// A slab lists its rising edges by ascending y, then its falling edges by descending y, then
// its horizontal ones. A crowded slab is searched by bisection: the last rising edge starting
// at or below p.y and the last falling edge starting at or above it are the two edges
// spanning p.y, and they (with any horizontal edges) decide.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

#include "convexloc/error.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/timing.hpp"
#include "detail/sink_queries.hpp"
#include "detail/sinks2d.hpp"
#include "detail/stats2d.hpp"

namespace convexloc {
namespace {

// how an edge runs in y; the index of its group within a slab
enum EdgeKind : std::uint32_t { Rising, Falling, Flat };

// the kind of edge e of the ring v
EdgeKind kindOf(const std::vector<Vec2>& v, std::uint32_t e) {
  const std::size_t n = v.size();
  double a = v[e].y, b = v[e + 1 == n ? 0 : e + 1].y;
  return a < b ? Rising : (a > b ? Falling : Flat);
}

}  // namespace

// === Build steps

UniformLocator::UniformLocator(const ConvexPolygon& polygon, std::uint32_t slabs) {
  const auto t0 = Clock::now();
  vertices_ = detail::copyVertices(polygon);
  box_ = polygon.bounds();
  chooseSlabs(slabs);
  std::vector<std::uint64_t> cursor = layOutSlabs(countEntries());
  fillSlabs(cursor);
  buildSeconds_ = secondsSince(t0);
}

// the slab count and the index scale; a box too tall or too flat for the index arithmetic
// gets one slab, searched by bisection
void UniformLocator::chooseSlabs(std::uint32_t slabs) {
  if (slabs > (1u << 26)) throw UsageError("uniform: at most 2^26 slabs");
  slabCount_ = slabs ? slabs : static_cast<std::uint32_t>(vertices_.size());
  double extent = box_.hi.y - box_.lo.y;
  slabScale_ = static_cast<double>(slabCount_) / extent;
  if (!std::isfinite(extent) || !std::isfinite(slabScale_)) {
    slabCount_ = 1;
    slabScale_ = 0.0;
  }
}

// the first and last slab edge e meets
std::pair<std::uint32_t, std::uint32_t> UniformLocator::slabRange(std::uint32_t e) const {
  const std::size_t n = vertices_.size();
  double a = vertices_[e].y, b = vertices_[e + 1 == n ? 0 : e + 1].y;
  return {slabOf(std::min(a, b)), slabOf(std::max(a, b))};
}

// per slab s and edge kind k, at 3 s + k: how many edges the slab lists
std::vector<std::uint32_t> UniformLocator::countEntries() const {
  const std::uint32_t n = static_cast<std::uint32_t>(vertices_.size());
  std::vector<std::uint32_t> count(3 * std::size_t{slabCount_}, 0);
  for (std::uint32_t e = 0; e < n; ++e) {
    auto [s0, s1] = slabRange(e);
    EdgeKind k = kindOf(vertices_, e);
    for (std::uint32_t s = s0; s <= s1; ++s) ++count[3 * std::size_t{s} + k];
  }
  return count;
}

// the offsets, and per slab its rising and falling counts; returns where each slab's group
// of each kind starts (at 3 s + k); throws where the table would exceed 2^32 entries
std::vector<std::uint64_t> UniformLocator::layOutSlabs(const std::vector<std::uint32_t>& count) {
  offsets_.assign(slabCount_ + 1, 0);
  rising_.resize(slabCount_);
  falling_.resize(slabCount_);
  std::vector<std::uint64_t> cursor(3 * std::size_t{slabCount_});
  std::uint64_t total = 0;
  for (std::uint32_t s = 0; s < slabCount_; ++s) {
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
  offsets_[slabCount_] = static_cast<std::uint32_t>(total);
  return cursor;
}

// every edge into its slabs, counter-clockwise from the bottom vertex: the rising edges come
// in ascending y, then the falling ones in descending y
void UniformLocator::fillSlabs(std::vector<std::uint64_t>& cursor) {
  const std::uint32_t n = static_cast<std::uint32_t>(vertices_.size());
  std::uint32_t bottom = 0;
  for (std::uint32_t i = 1; i < n; ++i)
    if (vertices_[i].y < vertices_[bottom].y) bottom = i;
  entries_.resize(offsets_[slabCount_]);
  for (std::uint32_t k = 0; k < n; ++k) {
    std::uint32_t e = (bottom + k) % n;
    auto [s0, s1] = slabRange(e);
    EdgeKind kind = kindOf(vertices_, e);
    for (std::uint32_t s = s0; s <= s1; ++s) entries_[cursor[3 * std::size_t{s} + kind]++] = e;
  }
}

// === Query

std::uint32_t UniformLocator::slabOf(double y) const noexcept {
  // y >= lo.y; NaN only when slabScale_ is 0 and y - lo is inf
  double t = (y - box_.lo.y) * slabScale_;
  return t < static_cast<double>(slabCount_) ? static_cast<std::uint32_t>(t) : slabCount_ - 1;
}

template <class Sink>
Location UniformLocator::run(Vec2 p, Sink& sink) const noexcept {
  if (detail::outsideBox(box_, p)) {
    sink.outsideBox();
    return Location::Outside;
  }
  const std::uint32_t s = slabOf(p.y);
  sink.uniformIndex(p.y, box_.lo.y, slabScale_, slabCount_);
  sink.cell(s, -1);
  const std::uint32_t* first = entries_.data() + offsets_[s];
  const std::uint32_t* last = entries_.data() + offsets_[s + 1];
  if (static_cast<std::size_t>(last - first) <= kCrowdedCell)
    return detail::testEdges(vertices_, first, last, p, sink);
  // crowded: the rising edge and the falling edge spanning p.y, and any horizontal edges
  sink.crowded();
  auto startY = [&](std::uint32_t e) { return vertices_[e].y; };
  const std::uint32_t r = rising_[s], f = falling_[s];
  // last rising edge starting at or below p.y
  const std::uint32_t* rise = std::upper_bound(
      first, first + r, p.y, [&](double y, std::uint32_t e) { return y < startY(e); });
  // last falling edge starting at or above p.y
  const std::uint32_t* fall = std::upper_bound(
      first + r, first + r + f, p.y, [&](double y, std::uint32_t e) { return y > startY(e); });
  std::uint32_t pick[4];
  std::uint32_t k = 0;
  pick[k++] = *(rise - 1);
  pick[k++] = *(fall - 1);
  for (const std::uint32_t* it = first + r + f; it != last && k < 4; ++it) pick[k++] = *it;
  return detail::testEdges(vertices_, pick, pick + k, p, sink);
}

template class detail::SinkQueries<UniformLocator, Vec2, Trace2D>;

// === What the build made

Stats2D UniformLocator::stats() const {
  return detail::csrStats(vertices_.size(), offsets_,
                          sizeof(*this) + detail::bytesOf(vertices_) + detail::bytesOf(offsets_) +
                              detail::bytesOf(entries_) + detail::bytesOf(rising_) +
                              detail::bytesOf(falling_),
                          buildSeconds_);
}

std::vector<Cell2D> UniformLocator::cells() const {
  std::vector<Cell2D> out;
  const double h = (box_.hi.y - box_.lo.y) / slabCount_;
  for (std::uint32_t s = 0; s < slabCount_; ++s) {
    Cell2D c;
    c.index = s;
    c.y0 = box_.lo.y + h * s;
    c.y1 = s + 1 == slabCount_ ? box_.hi.y : box_.lo.y + h * (s + 1);
    c.outline = {{box_.lo.x, c.y0}, {box_.hi.x, c.y0}, {box_.hi.x, c.y1}, {box_.lo.x, c.y1}};
    c.edges.assign(entries_.begin() + offsets_[s], entries_.begin() + offsets_[s + 1]);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace convexloc
