// convexloc — the polar locator's build: a centre strictly inside, then for every edge the
// cells its span of pseudo-angles meets, widened by the index's margin (polar/index.hpp
// argues why that makes every cell conservative), stored flat (CSR) with each cell's edges
// in counter-clockwise order, then the cells' radii (polar/radii.cpp).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/timing.hpp"
#include "detail/sinks2d.hpp"
#include "detail/stats2d.hpp"
#include "polar/index.hpp"

namespace convexloc {
namespace {

// === The centre

// all edges strictly on the inner side of c
bool strictlyInside(const std::vector<Vec2>& v, Vec2 c) {
  for (std::uint32_t e = 0; e < v.size(); ++e)
    if (detail::edgeSign(v, e, c) <= 0) return false;
  return true;
}

// the centroid of the polygon's area, from the fan of vertex 0 in long double; nothing for a
// fan without positive area
std::optional<Vec2> areaCentroid(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  long double ax = 0, ay = 0, area = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // relative to vertex 0
    long double x1 = static_cast<long double>(v[i].x) - v[0].x;
    long double y1 = static_cast<long double>(v[i].y) - v[0].y;
    long double x2 = static_cast<long double>(v[i + 1].x) - v[0].x;
    long double y2 = static_cast<long double>(v[i + 1].y) - v[0].y;
    long double a = x1 * y2 - x2 * y1;
    area += a;
    ax += a * (x1 + x2) / 3;
    ay += a * (y1 + y2) / 3;
  }
  if (!(area > 0)) return std::nullopt;
  return Vec2{static_cast<double>(v[0].x + ax / area), static_cast<double>(v[0].y + ay / area)};
}

// a double point strictly inside, if one of a few natural candidates is: the area centroid,
// the vertex mean, the centroids of a few triangles of vertices
std::optional<Vec2> findCentre(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  std::vector<Vec2> candidates;
  if (auto c = areaCentroid(v)) candidates.push_back(*c);
  long double sx = 0, sy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sx += static_cast<long double>(v[i].x) / n;
    sy += static_cast<long double>(v[i].y) / n;
  }
  candidates.push_back({static_cast<double>(sx), static_cast<double>(sy)});
  auto third = [&](std::size_t a, std::size_t b, std::size_t c) {
    long double x = (static_cast<long double>(v[a].x) + v[b].x + v[c].x) / 3;
    long double y = (static_cast<long double>(v[a].y) + v[b].y + v[c].y) / 3;
    return Vec2{static_cast<double>(x), static_cast<double>(y)};
  };
  candidates.push_back(third(0, n / 3, 2 * n / 3));
  // triangles of consecutive vertices, spread around the ring
  for (std::size_t i = 0; i + 2 < n && candidates.size() < 8; i += std::max<std::size_t>(1, n / 4))
    candidates.push_back(third(i, (i + 1) % n, (i + 2) % n));
  for (Vec2 c : candidates)
    if (std::isfinite(c.x) && std::isfinite(c.y) && strictlyInside(v, c)) return c;
  return std::nullopt;
}

// Every vertex's direction from c has a pseudo-angle: none overflows (it would in a polygon
// wider than the double range, from near -DBL_MAX to near DBL_MAX).
bool directionsFinite(const std::vector<Vec2>& v, Vec2 c) {
  for (Vec2 p : v)
    if (!(std::fabs(p.x - c.x) + std::fabs(p.y - c.y) < std::numeric_limits<double>::infinity()))
      return false;
  return true;
}

// the cell of a cyclic cell number (any integer) among `cells`
inline std::uint32_t wrapCell(std::int64_t c, std::uint32_t cells) {
  return static_cast<std::uint32_t>(((c % cells) + cells) % cells);
}

}  // namespace

// each edge's cells, as a cyclic range of cell numbers, and how many edges each cell lists
struct PolarLocator::EdgeSpans {
  std::vector<std::int64_t> first, last;  // per edge; last >= first, may pass cellCount()
  std::vector<std::uint32_t> count;       // per cell
  std::uint64_t total = 0;                // entries over all cells
};

// === Build steps

PolarLocator::PolarLocator(const ConvexPolygon& polygon, std::uint32_t slabsPerOctant) {
  const auto t0 = Clock::now();
  vertices_ = detail::copyVertices(polygon);
  box_ = polygon.bounds();
  vertexCount_ = static_cast<std::uint32_t>(vertices_.size());
  layOutOctants(slabsPerOctant);
  const std::optional<Vec2> centre = findCentre(vertices_);
  if (!centre || !directionsFinite(vertices_, *centre)) {
    buildWithoutCentre();
  } else {
    index_.centre = *centre;
    {
      const EdgeSpans spans = spanEdges();
      fillCells(spans);
      orderCells(spans);
    }  // the per-edge arrays go before the radii are built: the build's peak is the table's
    buildRadii();
  }
  padRing();
  buildSeconds_ = secondsSince(t0);
}

// The slabs per octant (by default about one cell per 2 edges, at least 64 cells: small
// polygons get cells narrow enough for their radii to decide most points, large ones a
// table that stays in cache while its radii still decide nearly every point), and each
// octant index's first cell and direction.
void PolarLocator::layOutOctants(std::uint32_t slabsPerOctant) {
  if (slabsPerOctant > (1u << 23)) throw UsageError("polar: at most 2^23 slabs per octant");
  const std::uint32_t q =
      slabsPerOctant ? slabsPerOctant : std::max<std::uint32_t>(8, (vertexCount_ + 15) / 16);
  index_.slabsPerOctant = q;
  index_.slabScale = static_cast<double>(q);
  for (std::size_t i = 0; i < 8; ++i) {
    const polar::OctantLayout o = polar::kOctantLayout[i];
    index_.cellBase[i] = static_cast<std::int64_t>(o.octant) * q + (o.falling ? q - 1 : 0);
    index_.cellStep[i] = o.falling ? -1 : 1;
  }
}

// No double point lies strictly inside (a sliver thinner than the double grid), or the
// directions overflow: an empty table whose radii decide nothing, so every query bisects the
// fan from vertex 0 (the index still runs, from vertex 0, and finds empty cells).
void PolarLocator::buildWithoutCentre() {
  index_.centre = vertices_[0];
  offsets_.assign(cellCount() + 1, 0);
  radii_.assign(cellCount(), {0.0f, std::numeric_limits<float>::infinity()});
}

// each edge's cells: its pseudo-angle span, widened by the margin, as a cyclic range
PolarLocator::EdgeSpans PolarLocator::spanEdges() const {
  const std::uint32_t n = vertexCount_, cells = cellCount();
  const Vec2 c = index_.centre;
  EdgeSpans spans{std::vector<std::int64_t>(n), std::vector<std::int64_t>(n),
                  std::vector<std::uint32_t>(cells, 0), 0};
  std::vector<double> angle(n);
  for (std::uint32_t i = 0; i < n; ++i)
    angle[i] = polar::pseudoAngle(vertices_[i].x - c.x, vertices_[i].y - c.y);
  for (std::uint32_t e = 0; e < n; ++e) {
    double a0 = angle[e], a1 = angle[e + 1 == n ? 0 : e + 1];
    if (a1 < a0) a1 += 8;  // the span wraps past direction +x
    const std::int64_t first =
        static_cast<std::int64_t>(std::floor((a0 - polar::kPolarMargin) * index_.slabScale));
    const std::int64_t last =
        static_cast<std::int64_t>(std::floor((a1 + polar::kPolarMargin) * index_.slabScale));
    for (std::int64_t k = first; k <= last; ++k) ++spans.count[wrapCell(k, cells)];
    spans.first[e] = first;
    spans.last[e] = last;
    spans.total += static_cast<std::uint64_t>(last - first + 1);
  }
  if (spans.total > std::numeric_limits<std::uint32_t>::max())
    throw UsageError("polar: the table would exceed 2^32 entries; use fewer slabs");
  return spans;
}

// the CSR table: each cell's offsets, then every edge in the cells of its span
void PolarLocator::fillCells(const EdgeSpans& spans) {
  const std::uint32_t n = vertexCount_, cells = cellCount();
  offsets_.assign(cells + 1, 0);
  for (std::uint32_t c = 0; c < cells; ++c) offsets_[c + 1] = offsets_[c] + spans.count[c];
  entries_.resize(spans.total);
  std::vector<std::uint32_t> cursor(offsets_.begin(), offsets_.end() - 1);
  for (std::uint32_t e = 0; e < n; ++e)
    for (std::int64_t k = spans.first[e]; k <= spans.last[e]; ++k)
      entries_[cursor[wrapCell(k, cells)]++] = e;
}

namespace {

// A run of every edge has no index gap (a needle far longer than wide: seen from the
// centre, the far vertices bunch into one cell and two edges span half a turn each). It
// starts at the edge whose range began furthest before cell c, the first of them if several
// began there, so that its inner vertices lie in the cell.
std::uint32_t fullRunStart(std::uint32_t c, const std::vector<std::int64_t>& first,
                           std::uint32_t cells) {
  const std::uint32_t n = static_cast<std::uint32_t>(first.size());
  auto back = [&](std::uint32_t e) { return wrapCell(c - first[e], cells); };
  std::uint32_t start = 0;
  for (std::uint32_t e = 1; e < n; ++e)
    if (back(e) > back(start)) start = e;
  for (std::uint32_t k = 0; k < n && back(start == 0 ? n - 1 : start - 1) == back(start); ++k)
    start = start == 0 ? n - 1 : start - 1;
  return start;
}

}  // namespace

// each cell's edges are a cyclic run; rotate those that wrap past edge 0 into order
void PolarLocator::orderCells(const EdgeSpans& spans) {
  for (std::uint32_t c = 0; c < cellCount(); ++c) {
    auto b = entries_.begin() + offsets_[c], end = entries_.begin() + offsets_[c + 1];
    if (static_cast<std::uint32_t>(end - b) == vertexCount_) {
      std::rotate(b, b + fullRunStart(c, spans.first, cellCount()), end);
      continue;
    }
    for (auto it = b + 1; it < end; ++it)
      if (*it != *(it - 1) + 1) {
        std::rotate(b, it, end);
        break;
      }
  }
}

// the ring closes on itself: edges e and e + 1 read vertices_[e .. e + 2] without wrapping
void PolarLocator::padRing() {
  vertices_.push_back(vertices_[0]);
  vertices_.push_back(vertices_[1]);
  vertices_.shrink_to_fit();
}

// === What the build made

Stats2D PolarLocator::stats() const {
  return detail::csrStats(vertexCount_, offsets_,
                          sizeof(*this) + detail::bytesOf(vertices_) + detail::bytesOf(offsets_) +
                              detail::bytesOf(entries_) + detail::bytesOf(radii_),
                          buildSeconds_);
}

namespace {

// where the ray from c along d leaves the box b (c inside b)
Vec2 rayExit(const Box2& b, Vec2 c, Vec2 d) {
  double t = std::numeric_limits<double>::infinity();
  if (d.x > 0) t = std::min(t, (b.hi.x - c.x) / d.x);
  if (d.x < 0) t = std::min(t, (b.lo.x - c.x) / d.x);
  if (d.y > 0) t = std::min(t, (b.hi.y - c.y) / d.y);
  if (d.y < 0) t = std::min(t, (b.lo.y - c.y) / d.y);
  return {c.x + t * d.x, c.y + t * d.y};
}

}  // namespace

std::vector<Cell2D> PolarLocator::cells() const {
  std::vector<Cell2D> out;
  if (entries_.empty()) return out;
  const Vec2 centre = index_.centre;
  const double q = index_.slabScale;
  const Vec2 corners[4] = {box_.hi, {box_.lo.x, box_.hi.y}, box_.lo, {box_.hi.x, box_.lo.y}};
  for (std::uint32_t i = 0; i < cellCount(); ++i) {
    Cell2D c;
    c.index = i;
    c.octant = static_cast<int>(i / index_.slabsPerOctant);
    double a0 = static_cast<double>(i) / q, a1 = static_cast<double>(i + 1) / q;
    c.dirLo = polar::directionOf(a0);
    c.dirHi = polar::directionOf(a1 >= 8 ? 8 - 1e-12 : a1);
    c.hitLo = rayExit(box_, centre, c.dirLo);
    c.hitHi = rayExit(box_, centre, c.dirHi);
    c.outline = {centre, c.hitLo};
    for (Vec2 k : corners) {
      double a = polar::pseudoAngle(k.x - centre.x, k.y - centre.y);
      if (a > a0 && a < a1) c.outline.push_back(k);
    }
    c.outline.push_back(c.hitHi);
    c.edges.assign(entries_.begin() + offsets_[i], entries_.begin() + offsets_[i + 1]);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace convexloc
