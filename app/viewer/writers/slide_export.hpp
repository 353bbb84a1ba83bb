// convexloc-viewer — --export DIR: every good slide of the lecture (or the figure) rendered
// and written as DIR/slide-01.png and slide-01.svg, slide-02..., driven by the frame loop; a
// slide with problems keeps its number and is left out (its problems were reported).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "gl/scene_view.hpp"
#include "logic/app/model.hpp"
#include "logic/teach/slide_record.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// frames rendered for each slide before it is written: the camera fits at the first, the
// panels and the legend take their size over the next ones
inline constexpr int kFramesPerSlide = 5;

// the slide shown, as drawn this frame in a `window` of pixels: its kind, its boxes on the
// page, its smallest text and its 3D query
SlideRecord recordSlide(const Model& model, const UiState& ui, glm::dvec2 window);

class SlideExporter {
 public:
  // exports to `dir` (made when missing) when it is not empty; inactive otherwise; `first`:
  // each slide's first frame is written too, as slide-NN-first.png
  explicit SlideExporter(std::string dir, bool first = false)
      : dir_(std::move(dir)), first_(first) {}
  bool active() const { return !dir_.empty(); }
  // Called after each frame is drawn (before the swap): writes the slide once its frames
  // are done (and its first frame where asked). False on a problem, printed on stderr.
  bool afterFrame(Model& model, const SceneView& view, UiState& ui, int width, int height);
  // Called where a window takes its keys, before the frame's fit and layout: the next slide
  // is shown there, as PageDown shows it. False on a problem, printed on stderr.
  bool turnPage(Model& model, UiState& ui);
  // every slide written
  bool finished() const { return finished_; }
  std::size_t written() const { return written_; }

 private:
  std::string dir_;
  bool first_ = false;
  int frames_ = 0;
  std::optional<std::size_t> next_;  // the slide to show at the next frame's start
  std::size_t written_ = 0;
  std::vector<SlideRecord> records_;
  bool finished_ = false;
};

}  // namespace convexloc::viewer
