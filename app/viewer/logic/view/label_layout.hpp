// convexloc-viewer — where the scene's labels go: each label takes the first of a few
// candidate positions around its anchor that overlaps no label placed before it and no
// marker, so that numbers never run into each other ("9 10") or sit on the mark they name.
// GL-free: the window's text measure comes in as a callback, so the renderer's labels and
// the SVG's are placed by the same rule.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "logic/base/text_layout.hpp"

namespace convexloc::viewer {

// a label to place: its anchor (window pixels), the offset its builder asked for (pixels,
// before scaling) and whether it must be shown even where every candidate is taken
struct LabelRequest {
  glm::dvec2 anchor{0.0};
  glm::dvec2 offset{0.0};
  std::string_view text;
  bool essential = false;
};

// a disc of window pixels no label may cover (a marker)
struct PixelDisc {
  glm::dvec2 centre{0.0};
  double radius = 0.0;
};

// where a label went: the middle of its text box; `shown` false when it was dropped;
// `leader` when an essential label was pushed away and needs a line to its anchor
struct LabelPlacement {
  bool shown = false;
  glm::dvec2 centre{0.0};
  glm::dvec2 size{0.0};
  bool leader = false;
};

// a rectangle of window pixels the labels must stay in; empty: no bounds
struct PixelBox {
  glm::dvec2 lo{0.0};
  glm::dvec2 hi{0.0};
  bool empty() const { return hi.x <= lo.x || hi.y <= lo.y; }
};

// Which cells of a coarse pixel grid over an area the drawn segments cross, so that a label
// can be kept off the lines where a free spot exists; cheap to build and to ask.
class SegmentGrid {
 public:
  // an empty grid over `area` with square cells `cell` pixels wide
  explicit SegmentGrid(PixelBox area = {}, double cell = 4.0);
  // marks the cells the segment from `a` to `b` (window pixels) crosses, inside the area;
  // past a fixed budget of cells walked (a dense wireframe) further segments are left out,
  // so that a frame's labels stay cheap
  void add(glm::dvec2 a, glm::dvec2 b);
  // marks a window over the scene (the legend, the Steps window): a label covering any of
  // it counts far more cells than any line, so it goes there only where nothing else is free
  void block(const PixelBox& box);
  // how many line cells the placed box covers (its outer cells half-covered count too), a
  // window's cells counted many times over
  int covered(const LabelPlacement& box) const;
  bool empty() const { return marked_ == 0; }

 private:
  // the cells a pixel rectangle touches, clamped to the grid
  struct Span {
    int x0, y0, x1, y1;
  };
  Span span(glm::dvec2 lo, glm::dvec2 hi) const;
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(cols_) +
           static_cast<std::size_t>(x);
  }

  PixelBox area_;
  double cell_;
  int cols_ = 0, rows_ = 0;
  std::size_t marked_ = 0;
  std::size_t walked_ = 0;
  std::vector<unsigned char> cells_;
};

// Places the labels in order (earlier ones win a contested spot): the asked offset times
// `scale` first, then 8 directions around the anchor at growing distances. A label whose
// every candidate overlaps a placed label or a marker is dropped, unless essential: then
// it goes to the least crowded candidate farther out with a leader line. A candidate
// reaching out of `area` (when not empty) is not taken. Among the free candidates, the
// first covering the fewest cells of `lines` (when given) wins, so that a label sits off
// the drawn segments wherever a free spot allows. Returns one placement per request, in
// order.
std::vector<LabelPlacement> placeLabels(std::span<const LabelRequest> labels,
                                        std::span<const PixelDisc> markers,
                                        const MeasureText& measure, double scale = 1.0,
                                        PixelBox area = {}, const SegmentGrid* lines = nullptr);

// true when the two placed boxes overlap (the gap between them below `pad` pixels)
bool boxesOverlap(const LabelPlacement& a, const LabelPlacement& b, double pad = 0.0);
// true when the placed box covers part of the disc
bool boxCoversDisc(const LabelPlacement& box, const PixelDisc& disc);

}  // namespace convexloc::viewer
