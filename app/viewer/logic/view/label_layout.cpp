// convexloc-viewer — label placement.
#include "logic/view/label_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "logic/base/screen_rect.hpp"

namespace convexloc::viewer {
namespace {

// the 8 directions tried around an anchor: right first, then counter-clockwise on screen
constexpr glm::dvec2 kDirections[8] = {{1, 0},  {1, -1}, {0, -1}, {-1, -1},
                                       {-1, 0}, {-1, 1}, {0, 1},  {1, 1}};
// rings of candidates, and the extra rings an essential label may use
constexpr int kRings = 3;
constexpr int kEssentialRings = 3;
// the gap between an anchor and its label's box on the first ring (pixels, at scale 1)
constexpr double kGap = 5.0;
constexpr double kRingStep = 9.0;
// labels keep this many pixels apart
constexpr double kPad = 3.0;
// what a candidate one ring farther out costs, in line cells covered: a label leaves its
// anchor only for much freer room (a number two rings out reads as another vertex's)
constexpr int kRingCost = 10;
// what a candidate nearer to another marker than to its own anchor costs: it would read as
// that marker's label
constexpr int kStrayCost = 60;
// what a cell under a window counts: more than a label's worth of line cells
constexpr unsigned char kBlocked = 200;
// the cells a SegmentGrid walks at most (well under a millisecond)
constexpr std::size_t kWalkBudget = 300000;

// the box of `size` put in direction `d` from the anchor, `gap` pixels clear of it
LabelPlacement around(glm::dvec2 anchor, glm::dvec2 size, glm::dvec2 d, double gap) {
  LabelPlacement p;
  p.size = size;
  p.centre = anchor + glm::dvec2(d.x * (0.5 * size.x + gap), d.y * (0.5 * size.y + gap));
  return p;
}

// true when the box reaches out of the area (never for an empty area)
bool outside(const LabelPlacement& c, const PixelBox& area) {
  if (area.empty()) return false;
  const glm::dvec2 lo = c.centre - 0.5 * c.size, hi = c.centre + 0.5 * c.size;
  return lo.x < area.lo.x || lo.y < area.lo.y || hi.x > area.hi.x || hi.y > area.hi.y;
}

// how many placed labels and markers the candidate runs into (reaching out of the area
// counts as one)
int conflicts(const LabelPlacement& c, const std::vector<LabelPlacement>& placed,
              std::span<const PixelDisc> markers, const PixelBox& area, bool stopAtFirst) {
  int n = outside(c, area) ? 1 : 0;
  if (n && stopAtFirst) return n;
  for (const LabelPlacement& p : placed)
    if (p.shown && boxesOverlap(c, p, kPad) && (++n, stopAtFirst)) return n;
  for (const PixelDisc& m : markers)
    if (boxCoversDisc(c, m) && (++n, stopAtFirst)) return n;
  return n;
}

// the gap between a placed box and a point
double gapTo(const LabelPlacement& c, glm::dvec2 p) {
  const glm::dvec2 lo = c.centre - 0.5 * c.size, hi = c.centre + 0.5 * c.size;
  return glm::length(glm::clamp(p, lo, hi) - p);
}

// true when the candidate lies nearer to some marker than to its own anchor
bool strays(const LabelPlacement& c, glm::dvec2 anchor, std::span<const PixelDisc> markers) {
  const double own = gapTo(c, anchor);
  for (const PixelDisc& m : markers)
    if (gapTo(c, m.centre) + 0.5 < own) return true;
  return false;
}

}  // namespace

bool boxesOverlap(const LabelPlacement& a, const LabelPlacement& b, double pad) {
  const glm::dvec2 reach = 0.5 * (a.size + b.size) + pad;
  return std::abs(a.centre.x - b.centre.x) < reach.x && std::abs(a.centre.y - b.centre.y) < reach.y;
}

bool boxCoversDisc(const LabelPlacement& box, const PixelDisc& disc) {
  const glm::dvec2 lo = box.centre - 0.5 * box.size, hi = box.centre + 0.5 * box.size;
  const glm::dvec2 nearest = glm::clamp(disc.centre, lo, hi);
  const glm::dvec2 d = disc.centre - nearest;
  return glm::dot(d, d) < disc.radius * disc.radius;
}

SegmentGrid::SegmentGrid(PixelBox area, double cell) : area_(area), cell_(std::max(cell, 1.0)) {
  if (area.empty()) return;
  cols_ = static_cast<int>(std::ceil((area.hi.x - area.lo.x) / cell_));
  rows_ = static_cast<int>(std::ceil((area.hi.y - area.lo.y) / cell_));
  cells_.assign(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_), 0);
}

void SegmentGrid::add(glm::dvec2 a, glm::dvec2 b) {
  if (cells_.empty() || walked_ > kWalkBudget) return;
  // clipped to the area (Liang-Barsky), then walked in steps of half a cell
  double t0 = 0.0, t1 = 1.0;
  if (!clipSegment(a, b, area_.lo, area_.hi, t0, t1)) return;
  const glm::dvec2 d = b - a;
  const glm::dvec2 from = a + d * t0, to = a + d * t1;
  const int steps = 1 + static_cast<int>(glm::length(to - from) / (0.5 * cell_));
  walked_ += static_cast<std::size_t>(steps);
  for (int s = 0; s <= steps; ++s) {
    const glm::dvec2 at = from + (to - from) * (static_cast<double>(s) / steps) - area_.lo;
    const int cx = std::clamp(static_cast<int>(at.x / cell_), 0, cols_ - 1);
    const int cy = std::clamp(static_cast<int>(at.y / cell_), 0, rows_ - 1);
    unsigned char& c = cells_[index(cx, cy)];
    if (c == 0) {
      ++marked_;
      c = 1;
    }
  }
}

SegmentGrid::Span SegmentGrid::span(glm::dvec2 lo, glm::dvec2 hi) const {
  const glm::dvec2 a = (lo - area_.lo) / cell_, b = (hi - area_.lo) / cell_;
  return {std::max(0, static_cast<int>(std::floor(a.x))),
          std::max(0, static_cast<int>(std::floor(a.y))),
          std::min(cols_ - 1, static_cast<int>(std::ceil(b.x)) - 1),
          std::min(rows_ - 1, static_cast<int>(std::ceil(b.y)) - 1)};
}

void SegmentGrid::block(const PixelBox& box) {
  if (cells_.empty() || box.empty()) return;
  const Span r = span(box.lo, box.hi);
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      unsigned char& c = cells_[index(x, y)];
      marked_ += c == 0;
      c = kBlocked;
    }
}

int SegmentGrid::covered(const LabelPlacement& box) const {
  if (marked_ == 0) return 0;
  const Span r = span(box.centre - 0.5 * box.size, box.centre + 0.5 * box.size);
  int n = 0;
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) n += cells_[index(x, y)];
  return n;
}

std::vector<LabelPlacement> placeLabels(std::span<const LabelRequest> labels,
                                        std::span<const PixelDisc> markers,
                                        const MeasureText& measure, double scale, PixelBox area,
                                        const SegmentGrid* lines) {
  std::vector<LabelPlacement> placed(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const LabelRequest& l = labels[i];
    const glm::dvec2 size = measure(l.text);
    LabelPlacement asked;
    asked.size = size;
    asked.centre = l.anchor + l.offset * scale;
    std::vector<LabelPlacement> candidates{asked};
    std::vector<int> rings{0};
    for (int ring = 0; ring < kRings; ++ring)
      for (glm::dvec2 d : kDirections) {
        candidates.push_back(around(l.anchor, size, d, (kGap + kRingStep * ring) * scale));
        rings.push_back(ring);
      }
    // the free candidate over the fewest line cells, a farther ring costing a few cells so
    // that a label leaves its anchor only for clearly freer room; the first free one
    // without lines
    int fewest = std::numeric_limits<int>::max();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const LabelPlacement& c = candidates[k];
      if (conflicts(c, placed, markers, area, true) != 0) continue;
      const int over = (lines ? lines->covered(c) + kRingCost * rings[k] : 0) +
                       (strays(c, l.anchor, markers) ? kStrayCost : 0);
      if (over < fewest) {
        fewest = over;
        placed[i] = c;
        placed[i].shown = true;
      }
      if (fewest == 0) break;
    }
    if (placed[i].shown || !l.essential) continue;
    // essential: the farther candidate with the fewest conflicts, joined by a leader line
    int best = std::numeric_limits<int>::max();
    for (int ring = kRings; ring < kRings + kEssentialRings; ++ring)
      for (glm::dvec2 d : kDirections) {
        const LabelPlacement c = around(l.anchor, size, d, (kGap + kRingStep * 2 * ring) * scale);
        const int n = conflicts(c, placed, markers, area, false);
        if (n < best) {
          best = n;
          placed[i] = c;
        }
      }
    placed[i].shown = true;
    placed[i].leader = true;
  }
  return placed;
}

}  // namespace convexloc::viewer
