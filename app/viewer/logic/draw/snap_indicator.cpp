// convexloc-viewer — the snap indicator.
#include "logic/draw/snap_indicator.hpp"

#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {

std::string snapText(const Snap& s, std::size_t n) {
  std::string text = toString(s.kind);
  if (s.kind == SnapKind::Vertex) {
    text.append(" ");
    text.append(std::to_string(s.index));
  } else if (s.kind == SnapKind::Edge && n > 0) {
    text.append(" ");
    text.append(std::to_string(s.index));
    text.append("-");
    text.append(std::to_string((s.index + 1) % n));
  }
  return text;
}

void snapIndicator(const Scene2D& scene, const Palette& pal, DrawList& out) {
  const auto& s = scene.snapMark();
  if (!s) return;
  const glm::dvec3 at = at2(toGlm(s->point));
  out.marker(at, pal.hoverEdge, 17.0f, MarkerShape::Square);
  out.label(at, snapText(*s, scene.polygon().size()), pal.hoverEdge, {12.0f, -18.0f});
}

}  // namespace convexloc::viewer
