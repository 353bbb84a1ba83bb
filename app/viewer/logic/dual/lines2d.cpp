// convexloc-viewer — the Lines mode's state and its inspector text.
#include "logic/dual/lines2d.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace convexloc::viewer {
namespace {

// the gap between the primal frame and the inset, as a fraction of the inset's side
constexpr double kInsetGap = 0.08;
// the primal frame: the polygon's box grown by this fraction on each side
constexpr double kPrimalMargin = 0.06;
// the dual square's half-side beyond the unit square b lies on
constexpr double kDualMargin = 1.12;

// the point where the line meets the boundary at `h`: a vertex, or the rounded crossing
Vec2 hitPoint(const LineIntersector& li, Vec2 p1, Vec2 p2, const BoundaryHit& h) {
  const auto v = li.vertices();
  if (h.atVertex) return v[h.index];
  return roundedIntersection(p1, p2, v[h.index], v[(h.index + 1) % v.size()]);
}

// "vertex 7" or "edge 7 (7-8)"
std::string hitText(const BoundaryHit& h, std::size_t n) {
  if (h.atVertex) return "vertex " + std::to_string(h.index);
  return "edge " + std::to_string(h.index) + " (" + std::to_string(h.index) + "-" +
         std::to_string((h.index + 1) % n) + ")";
}

TraceLine::Kind signKind(int sign) {
  return sign > 0 ? TraceLine::Positive : (sign < 0 ? TraceLine::Negative : TraceLine::Zero);
}

// the dual cell's part of the story: the cell, the dual edges it lists, its proposals
void describeCell(const LineProbe2D& line, const PolarLocator* dual, std::vector<TraceLine>& out) {
  const LineTrace& t = line.trace;
  if (t.method != LineMethod::Dual) return;
  if (t.cell < 0 || !dual) {
    out.push_back({TraceLine::Step, "no dual cell: the extremes were found by bisection"});
    return;
  }
  std::string edges;
  const auto listed = dual->cellEdges(t.cell);
  for (std::size_t i = 0; i < listed.size() && i < 12; ++i)
    edges += (i ? ", " : "") + std::to_string(listed[i]);
  if (listed.size() > 12) edges += ", ...";
  out.push_back({TraceLine::Heading, "dual cell " + std::to_string(t.cell) + " (the point b)"});
  out.push_back(
      {TraceLine::Step, "lists dual edge" + std::string(listed.size() == 1 ? " " : "s ") + edges});
  out.push_back(
      {TraceLine::Step, "its direction cell proposes vertex " + std::to_string(t.startMax) +
                            " (largest f); that of -b (cell " + std::to_string(t.opposite) +
                            ") vertex " + std::to_string(t.startMin) + " (smallest f)"});
  std::string climb = std::to_string(t.climbSteps) + " climb move" +
                      (t.climbSteps == 1 ? "" : "s") + " to the extremes";
  if (t.bisected) climb += ", then bisection";
  out.push_back({TraceLine::Step, climb});
}

}  // namespace

// === The inset

glm::dvec2 DualInset::toWorld(Vec2 d) const {
  const glm::dvec2 mid{0.5 * frame.lo.x + 0.5 * frame.hi.x, 0.5 * frame.lo.y + 0.5 * frame.hi.y};
  return mid + scale * glm::dvec2(d.x - dualMiddle.x, d.y - dualMiddle.y);
}

Vec2 DualInset::toDual(glm::dvec2 w) const {
  const glm::dvec2 mid{0.5 * frame.lo.x + 0.5 * frame.hi.x, 0.5 * frame.lo.y + 0.5 * frame.hi.y};
  return {dualMiddle.x + (w.x - mid.x) / scale, dualMiddle.y + (w.y - mid.y) / scale};
}

Box2 DualInset::both() const {
  return {{std::min(primal.lo.x, frame.lo.x), std::min(primal.lo.y, frame.lo.y)},
          {std::max(primal.hi.x, frame.hi.x), std::max(primal.hi.y, frame.hi.y)}};
}

DualInset makeDualInset(const Box2& bounds, Vec2 dualMiddle, double dualHalf) {
  DualInset in;
  const double w = bounds.hi.x - bounds.lo.x, h = bounds.hi.y - bounds.lo.y;
  const double pad = kPrimalMargin * std::max(w, h);
  in.primal = {{bounds.lo.x - pad, bounds.lo.y - pad}, {bounds.hi.x + pad, bounds.hi.y + pad}};
  double side = std::max(in.primal.hi.x - in.primal.lo.x, in.primal.hi.y - in.primal.lo.y);
  if (!(side > 0.0)) side = 1.0;
  const double midY = 0.5 * in.primal.lo.y + 0.5 * in.primal.hi.y;
  const double x0 = in.primal.hi.x + kInsetGap * side;
  in.frame = {{x0, midY - 0.5 * side}, {x0 + side, midY + 0.5 * side}};
  in.dualMiddle = dualMiddle;
  in.scale = 0.5 * side / (dualHalf > 0.0 ? dualHalf : 1.0);
  return in;
}

// === The mode

void Lines2D::setEnabled(bool on) {
  if (on == enabled_) return;
  enabled_ = on;
  if (!on) framed_.reset();
  intersector_.reset();  // built afresh by the next sync
  ++version_;
}

void Lines2D::sync(const Scene2D& scene) {
  if (!enabled_) return;
  if (intersector_ && sceneSeen_ == &scene && shapeSeen_ == scene.versions().shape) return;
  rebuild(scene.polygon());
  sceneSeen_ = &scene;
  shapeSeen_ = scene.versions().shape;
}

void Lines2D::rebuild(const ConvexPolygon& polygon) {
  intersector_ = std::make_unique<LineIntersector>(polygon, LineMethod::Dual);
  dualCells_.clear();
  Vec2 middle{0.0, 0.0};
  double half = kDualMargin;
  if (const PolarLocator* dual = intersector_->dualLocator()) {
    dualCells_ = dual->cells();
    if (const auto c = dual->centre()) middle = *c;
    // b lies on the square of half-side 1 around c*, P* within the dual's box
    const Box2 b = dual->box();
    const double reach =
        std::max({1.0, b.hi.x - middle.x, middle.x - b.lo.x, b.hi.y - middle.y, middle.y - b.lo.y});
    half = kDualMargin * reach;
  }
  Box2 frame = polygon.bounds();
  if (framed_)
    frame = {{std::min(frame.lo.x, framed_->lo.x), std::min(frame.lo.y, framed_->lo.y)},
             {std::max(frame.hi.x, framed_->hi.x), std::max(frame.hi.y, framed_->hi.y)}};
  inset_ = makeDualInset(frame, middle, half);
  answer();
}

bool Lines2D::setLine(Vec2 p1, Vec2 p2) {
  if (p1 == p2) return false;
  asked_ = {p1, p2};
  answer();
  return true;
}

void Lines2D::clearLine() {
  asked_.reset();
  answer();
}

void Lines2D::frameLine() {
  if (!asked_) return;
  const auto [p1, p2] = *asked_;
  framed_ = Box2{{std::min(p1.x, p2.x), std::min(p1.y, p2.y)},
                 {std::max(p1.x, p2.x), std::max(p1.y, p2.y)}};
  intersector_.reset();  // the inset moves: built afresh by the next sync
}

void Lines2D::answer() {
  ++version_;
  line_.reset();
  if (!asked_ || !intersector_) return;
  const auto [p1, p2] = *asked_;
  LineProbe2D l;
  l.p1 = p1;
  l.p2 = p2;
  l.vertices = intersector_->vertices().size();
  l.trace = intersector_->trace(p1, p2);
  l.hit = intersector_->intersect(p1, p2);
  if (l.hit.crossing != Crossing::Misses) {
    l.entry = hitPoint(*intersector_, p1, p2, l.hit.entry);
    l.exit = hitPoint(*intersector_, p1, p2, l.hit.exit);
  }
  l.clipped = intersector_->clip(p1, p2);
  line_ = std::move(l);
}

std::span<const Vec2> Lines2D::dualVertices() const {
  if (!intersector_) return {};
  return intersector_->dualVertices();
}

std::optional<Vec2> Lines2D::dualCentre() const {
  const PolarLocator* dual = intersector_ ? intersector_->dualLocator() : nullptr;
  if (!dual) return std::nullopt;
  return dual->centre();
}

std::optional<Vec2> Lines2D::dualPoint() const {
  const std::optional<Vec2> c = dualCentre();
  if (!line_ || !c) return std::nullopt;
  const double dx = line_->p2.x - line_->p1.x, dy = line_->p2.y - line_->p1.y;
  const double m = std::max(std::fabs(dx), std::fabs(dy));
  if (!(m > 0.0) || !std::isfinite(m)) return std::nullopt;
  return Vec2{c->x - dy / m, c->y + dx / m};
}

// === The inspector's text

void describeExtremes(const ExtremeVertices& x, const char* side, std::uint32_t comparisons,
                      std::vector<TraceLine>& out) {
  out.push_back({TraceLine::Heading, "extreme vertices"});
  out.push_back({signKind(x.largestSign), "largest " + std::string(side) + " at vertex " +
                                              std::to_string(x.largest) + ": sign" +
                                              signText(x.largestSign)});
  out.push_back({signKind(x.smallestSign), "smallest " + std::string(side) + " at vertex " +
                                               std::to_string(x.smallest) + ": sign" +
                                               signText(x.smallestSign)});
  out.push_back({TraceLine::Step, std::to_string(comparisons) + " exact comparisons"});
}

std::vector<TraceLine> describeLine(const LineProbe2D& line, std::span<const Vec2> dualVertices,
                                    const PolarLocator* dual) {
  std::vector<TraceLine> out;
  const LineTrace& t = line.trace;
  out.push_back(
      {TraceLine::Step, "line through " + exactText(line.p1) + " and " + exactText(line.p2)});
  out.push_back({TraceLine::Step, "f(v) = orient2d(p1, p2, v), exact"});
  if (!dualVertices.empty())
    out.push_back({TraceLine::Step, "dual P*: " + std::to_string(dualVertices.size()) +
                                        " vertices (unit edge normals and their antipodes)"});
  describeCell(line, dual, out);
  describeExtremes(t.extremes, "f", t.comparisons, out);
  out.push_back({TraceLine::Result, "the line " + std::string(toString(line.hit.crossing))});
  if (line.hit.crossing != Crossing::Misses && line.entry && line.exit) {
    out.push_back({TraceLine::Step, "entry at " + hitText(line.hit.entry, line.vertices) + ": " +
                                        exactText(*line.entry)});
    out.push_back({TraceLine::Step, "exit at " + hitText(line.hit.exit, line.vertices) + ": " +
                                        exactText(*line.exit)});
  }
  if (line.clipped)
    out.push_back({TraceLine::Step, "segment p1-p2 clipped: " + exactText(line.clipped->a) +
                                        " to " + exactText(line.clipped->b)});
  else
    out.push_back({TraceLine::Step, "segment p1-p2 clipped: outside"});
  return out;
}

}  // namespace convexloc::viewer
