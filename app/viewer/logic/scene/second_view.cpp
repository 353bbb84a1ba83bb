// convexloc-viewer — the split view's second scene and halves.
#include "logic/scene/second_view.hpp"

#include <vector>

namespace convexloc::viewer {

void SecondView::sync(const Scene2D& main) {
  const Versions& v = main.versions();
  if (v.shape != shapeSeen_) {
    const std::span<const Vec2> vs = main.polygon().vertices();
    scene_.setShape(std::vector<Vec2>(vs.begin(), vs.end()), main.label());
    scene_.clearSpray();  // the points are the main scene's
    shapeSeen_ = v.shape;
    overlaySeen_ = ~0ull;
  }
  if (v.overlay != overlaySeen_) {
    if (main.probe()) {
      if (!scene_.probe() || scene_.probe()->point != main.probe()->point)
        scene_.place(main.probe()->point);
    } else if (scene_.probe()) {
      scene_.clearProbe();
    }
    overlaySeen_ = v.overlay;
  }
  // the cell under the cursor, in this half's own cells
  if (main.hoverPoint() != scene_.hoverPoint()) scene_.hover(main.hoverPoint());
}

ScreenRect SecondView::left() const {
  if (stacked()) return {area_.lo, {area_.hi.x, area_.middle().y}};
  return {area_.lo, {area_.middle().x, area_.hi.y}};
}

ScreenRect SecondView::right() const {
  if (stacked()) return {{area_.lo.x, area_.middle().y}, area_.hi};
  return {{area_.middle().x, area_.lo.y}, area_.hi};
}

std::array<glm::dvec2, 2> SecondView::divider() const {
  const ScreenRect r = right();
  return {r.lo, stacked() ? glm::dvec2(r.hi.x, r.lo.y) : glm::dvec2(r.lo.x, r.hi.y)};
}

Camera2D SecondView::rightCamera(const Camera2D& main) const {
  Camera2D c = main;
  c.pan(right().lo - left().lo);
  return c;
}

glm::dvec2 SecondView::toLeft(glm::dvec2 pos) const {
  if (enabled_ && right().contains(pos)) pos -= right().lo - left().lo;
  return pos;
}

std::string SecondView::traceCaption(const Scene2D& scene) {
  const std::string name(toString(scene.method()));
  if (!scene.probe()) return name;
  const Trace2D& t = scene.probe()->trace;
  const std::size_t k = t.edges.size() + t.rays.size();
  return name + ": " + std::to_string(k) + (k == 1 ? " predicate, " : " predicates, ") +
         std::string(toString(t.result));
}

}  // namespace convexloc::viewer
