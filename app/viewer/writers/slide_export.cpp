// convexloc-viewer — writing every slide.
#include "writers/slide_export.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "ui/panels/lecture_panel.hpp"
#include "writers/screenshot.hpp"
#include "writers/svg_export.hpp"

namespace convexloc::viewer {

bool SlideExporter::afterFrame(Model& model, const SceneView& view, UiState& ui, int width,
                               int height) {
  if (!active() || finished_) return true;
  // a slide measuring Why O(1) is written with its plots finished
  if (model.whyOpen && model.scaling->running()) return true;
  if (++frames_ < kFramesPerSlide) return true;
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  char name[32];
  std::snprintf(name, sizeof name, "slide-%02zu", ui.show.current + 1);
  const std::string path = (std::filesystem::path(dir_) / name).string();
  std::string problem = saveScreenshot(path + ".png", width, height);
  if (problem.empty()) writeSceneSvg(model, view, ui, path + ".svg", problem);
  if (!problem.empty()) {
    std::cerr << "convexloc-viewer: " << problem << "\n";
    return false;
  }
  ++written_;
  frames_ = 0;
  // the next slide that can be shown as written (the others were reported at the start)
  const std::size_t next = ui.show.goodFrom(ui.show.current + 1);
  if (next >= ui.show.lecture.slides.size()) {
    finished_ = true;
    return true;
  }
  problem = showSlideNow(model, ui, static_cast<std::ptrdiff_t>(next));
  if (!problem.empty()) {
    std::cerr << "convexloc-viewer: slide " << next + 1 << ": " << problem << "\n";
    return false;
  }
  return true;
}

}  // namespace convexloc::viewer
