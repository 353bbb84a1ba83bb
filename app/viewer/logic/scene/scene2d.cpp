// convexloc-viewer — the 2D scene's own state transitions: its shape, hover and drag.
#include "logic/scene/scene2d.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "convexloc/text_reader.hpp"
#include "logic/base/format.hpp"
#include "logic/view/picking.hpp"

namespace convexloc::viewer {
namespace {

constexpr std::size_t kDefaultVertices = 16;
constexpr std::uint64_t kDefaultSeed = 7;
constexpr std::size_t kDefaultSpray = 3000;
constexpr std::uint32_t kDefaultPolarSlabs = 8;

// Core counts input vertices from 1 (as lines of a file); the viewer labels them from 0.
// A drag's message names every "vertex K" as the label on the drawing, K - 1.
std::string countedFromZero(std::string message) {
  const std::string word = "vertex ";
  for (std::size_t at = message.find(word); at != std::string::npos;
       at = message.find(word, at + 1)) {
    const std::size_t digits = at + word.size();
    std::size_t end = digits;
    while (end < message.size() && message[end] >= '0' && message[end] <= '9') ++end;
    if (end == digits || end - digits > 18) continue;
    const unsigned long long k = std::stoull(message.substr(digits, end - digits));
    if (k > 0) message.replace(digits, end - digits, std::to_string(k - 1));
  }
  return message;
}

}  // namespace

std::vector<Vec2> Traits2D::sprayPoints(const ConvexPolygon& p, std::size_t n, std::uint64_t seed,
                                        bool nearBoundary) {
  return generatePoints(p, n, seed, nearBoundary);
}

ConvexPolygon Traits2D::readShape(const std::string& path) {
  const PointList list = readPoints2D(path);
  return ConvexPolygon(list.points, list.lines);
}

std::size_t baseEdgesPerCell(Method2D m) {
  return (m == Method2D::Slab || m == Method2D::Uniform) ? 2 : 1;
}

Scene2D::Scene2D() {
  generate(PolygonKind::Random, kDefaultVertices, kDefaultSeed);
  // eight polar slabs per octant: most cells then list one edge, and the cells where a
  // vertex falls stand out, as in the paper's figure
  resolution_[Traits2D::slot(Method2D::Polar)] = kDefaultPolarSlabs;
  rebuildLocator();
  spray({kDefaultSpray, 1, false});
}

// === Shape

bool Scene2D::adopt(ConvexPolygon polygon, std::string label, bool fresh) {
  if (!swapShape(std::move(polygon), std::move(label), fresh)) return false;
  dropped_.clear();
  // a new shape gets a new spray (same count, seed and kind, in its box); an edited one
  // keeps its points, which rebuildLocator has classified again
  if (fresh && !points_.empty()) spray(spray_);
  retrace();
  return true;
}

bool Scene2D::adoptShape(ConvexPolygon polygon, std::string label) {
  return adopt(std::move(polygon), std::move(label), true);
}

bool Scene2D::setShape(std::span<const Vec2> points, std::string label,
                       std::span<const std::size_t> lines, const std::string& source) {
  if (!guarded(source, [&] { return adoptShape(ConvexPolygon(points, lines), std::move(label)); }))
    return false;
  // the input points that are no vertex now, to be drawn as dropped
  std::vector<bool> kept(points.size(), false);
  for (const std::uint32_t i : shape_->sourceIndex())
    if (i < kept.size()) kept[i] = true;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!kept[i]) dropped_.push_back(points[i]);
  return true;
}

bool Scene2D::generate(PolygonKind kind, std::size_t n, std::uint64_t seed) {
  return guarded("", [&] {
    std::vector<Vec2> v = generatePolygon(kind, n, seed);
    std::string label = std::string(toString(kind)) + ", " + std::to_string(n) + " vertices";
    if (kind == PolygonKind::Random || kind == PolygonKind::Triangle || kind == PolygonKind::Offset)
      label += ", seed " + std::to_string(seed);
    return setShape(v, std::move(label));
  });
}

// === Method

void Scene2D::cellsChanged() {
  hovered_ = -1;
  if (hoverPoint_) hover(hoverPoint_);
}

std::uint32_t Scene2D::effectiveResolution() const {
  if (const auto* u = locator_->get<UniformLocator>()) return u->slabCount();
  if (const auto* p = locator_->get<PolarLocator>()) return p->slabsPerOctant();
  return 0;
}

std::optional<Vec2> Scene2D::centre() const {
  const auto* p = locator_->get<PolarLocator>();
  if (!p) return std::nullopt;
  return p->centre();
}

// === Hover

void Scene2D::hover(std::optional<Vec2> p) {
  hoverPoint_ = p;
  std::ptrdiff_t cell = -1;
  if (p) {
    // the common case first: the cursor is still in the same cell
    if (hovered_ >= 0 && hovered_ < static_cast<std::ptrdiff_t>(cells_.size()) &&
        outlineContains(cells_[static_cast<std::size_t>(hovered_)].outline, *p))
      cell = hovered_;
    else
      cell = pickCell(cells_, *p);
  }
  if (cell != hovered_) {
    hovered_ = cell;
    ++versions_.overlay;
  }
}

// === Snap indicator

void Scene2D::setSnapMark(std::optional<Snap> s) {
  if (s && s->kind == SnapKind::None) s.reset();
  const bool same = s.has_value() == snapMark_.has_value() &&
                    (!s || (s->kind == snapMark_->kind && s->point == snapMark_->point));
  if (same) return;
  snapMark_ = s;
  ++versions_.overlay;
}

// === Drag

void Scene2D::beginDrag(std::size_t i) {
  if (i >= shape_->size()) return;
  drag_ = Drag{i, shape_->vertex(i), false, {}};
  ++versions_.overlay;
}

bool Scene2D::dragTo(Vec2 p) {
  if (!drag_) return false;
  const std::size_t i = drag_->vertex;
  drag_->cursor = p;
  ++versions_.overlay;
  std::vector<Vec2> moved(shape_->vertices().begin(), shape_->vertices().end());
  moved[i] = p;
  try {
    ConvexPolygon candidate(moved);
    if (candidate.size() != moved.size()) {
      drag_->rejected = true;
      drag_->message = "vertex " + std::to_string(i) +
                       " would lie on the segment of its neighbours or on another vertex";
      return false;
    }
    // normalisation may start the ring elsewhere or reverse it: follow the dragged vertex
    const auto source = candidate.sourceIndex();
    const auto it = std::find(source.begin(), source.end(), static_cast<std::uint32_t>(i));
    const std::size_t now = static_cast<std::size_t>(it - source.begin());
    const std::string label = label_.ends_with(" (edited)") ? label_ : label_ + " (edited)";
    if (!adopt(std::move(candidate), label, false)) {
      drag_->rejected = true;
      drag_->message = error_;
      return false;
    }
    drag_->vertex = now;
    drag_->rejected = false;
    drag_->message.clear();
    return true;
  } catch (const Error& e) {
    drag_->rejected = true;
    drag_->message = shortestCoordinates(countedFromZero(e.what()));
  }
  return false;
}

void Scene2D::endDrag() {
  if (!drag_) return;
  if (drag_->rejected)
    setError("vertex drag: " + drag_->message + "; the last valid shape is kept");
  drag_.reset();
  ++versions_.overlay;
}

}  // namespace convexloc::viewer
