// convexloc-viewer — the snap indicator.
#include "logic/draw/snap_indicator.hpp"

#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {

std::string snapText(const Snap& s, std::size_t n) {
  const auto edgeName = [n](std::size_t from) {
    std::string e = "edge ";
    e.append(std::to_string(from));
    e.append("-");
    e.append(std::to_string(n > 0 ? (from + 1) % n : 0));
    return e;
  };
  std::string text = toString(s.kind);
  if (s.kind == SnapKind::Vertex) {
    text.append(" ");
    text.append(std::to_string(s.index));
    // the edge aimed at has no double near: say so, or the jump to its end surprises
    if (s.fromEdge) {
      text.append(" (");
      text.append(edgeName(*s.fromEdge));
      text.append(" holds no double here)");
    }
  } else if (s.kind == SnapKind::Edge) {
    text = edgeName(s.index);
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
