// convexloc-viewer — the fit's room beside the corner windows.
#include "logic/view/fit_room.hpp"

#include <algorithm>

namespace convexloc::viewer {
namespace {

// the drawn height of a scene `aspect` times as wide as high fitted into `r`
double drawn(const ScreenRect& r, double aspect) {
  const glm::dvec2 s = r.size();
  return s.x <= 0.0 || s.y <= 0.0 ? 0.0 : std::min(s.x / aspect, s.y);
}

}  // namespace

ScreenRect roomBesideCorners(ScreenRect fitted, ScreenRect full, const CornerBoxes& boxes,
                             double aspect) {
  if (boxes.steps.x <= 0.0 || boxes.steps.y <= 0.0 || aspect <= 0.0) return fitted;
  const double top = full.hi.y - 2.0 * boxes.margin - boxes.steps.y;
  const double right = full.lo.x + 2.0 * boxes.margin + boxes.steps.x;
  if (top >= fitted.hi.y || right <= fitted.lo.x) return fitted;
  const bool legend = boxes.legend.x > 0.0 && boxes.legend.y > 0.0;
  ScreenRect best = fitted;
  double most = 0.4 * drawn(fitted, aspect);
  for (int legendRight = 0; legendRight < (legend ? 2 : 1); ++legendRight)
    for (int stepsLeft = 0; stepsLeft < 2; ++stepsLeft) {
      ScreenRect r = full;
      if (legend && legendRight) r.hi.x -= boxes.legend.x;
      if (legend && !legendRight) r.hi.y -= boxes.legend.y;
      if (stepsLeft)
        r.lo.x = std::max(r.lo.x, right);
      else
        r.hi.y = std::min(r.hi.y, top);
      if (drawn(r, aspect) > most) {
        best = r;
        most = drawn(r, aspect);
      }
    }
  return best;
}

}  // namespace convexloc::viewer
