// convexloc-viewer — the draw lists' labels placed on the screen.
#include "logic/view/scene_labels.hpp"

#include <algorithm>

namespace convexloc::viewer {

std::vector<PlacedSceneLabel> layoutSceneLabels(std::span<const DrawList* const> lists,
                                                std::size_t essentialFrom,
                                                const ScreenProjection& project,
                                                const PixelBox& area, const MeasureText& measure,
                                                double scale, std::size_t budget,
                                                std::span<const PixelBox> windows) {
  std::vector<PlacedSceneLabel> shown;
  std::vector<LabelRequest> requests;
  std::vector<PixelDisc> markers;
  // essential labels first, so that they win their spots
  for (std::size_t pass = 0; pass < 2; ++pass)
    for (std::size_t k = 0; k < lists.size(); ++k)
      for (const Label& l : lists[k]->labels) {
        const bool essential = k >= essentialFrom || l.essential;
        if (essential != (pass == 0)) continue;
        if (shown.size() >= budget) break;
        const std::optional<glm::dvec3> s = project(l.p);
        if (!s) continue;
        const glm::dvec2 at(*s);
        if (!area.empty() && (at.x < area.lo.x - 200.0 || at.y < area.lo.y - 50.0 ||
                              at.x > area.hi.x + 200.0 || at.y > area.hi.y + 50.0))
          continue;
        shown.push_back({&l, at, {}});
        requests.push_back({at, glm::dvec2(l.offset), l.text, pass == 0});
      }
  for (const DrawList* list : lists)
    for (const Marker& m : list->markers)
      if (const std::optional<glm::dvec3> s = project(m.p))
        markers.push_back({glm::dvec2(*s), 0.5 * m.size * scale});
  // the drawn segments, so that labels keep off the lines where they can
  SegmentGrid lines(area, 4.0 * std::max(scale, 1.0));
  for (const DrawList* list : lists)
    for (const Segment& g : list->segments) {
      const std::optional<glm::dvec3> a = project(g.a), b = project(g.b);
      if (a && b) lines.add(glm::dvec2(*a), glm::dvec2(*b));
    }
  for (const PixelBox& w : windows) lines.block(w);
  const std::vector<LabelPlacement> placed =
      placeLabels(requests, markers, measure, scale, area, &lines);
  std::vector<PlacedSceneLabel> out;
  for (std::size_t i = 0; i < shown.size(); ++i)
    if (placed[i].shown) out.push_back({shown[i].label, shown[i].anchor, placed[i]});
  return out;
}

}  // namespace convexloc::viewer
