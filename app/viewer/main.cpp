// convexloc-viewer — the interactive teaching app for the paper's polar slabs.
//
// Viewer::frame() is one turn of Dear ImGui's GLFW + OpenGL 3 example loop: take
// events, start the ImGui frame, build the UI (the camera moves only when ImGui does not
// want the mouse), render ImGui's lists, clear, draw the scene, draw ImGui over it, swap.
// The window and input live in platform/, everything shown in logic/ (GL-free), every GL
// call in gl/, the panels in ui/.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "gl/context.hpp"
#include "gl/renderer.hpp"
#include "gl/scene_view.hpp"
#include "logic/app/interaction.hpp"
#include "logic/app/lecture.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "platform/frame_loop.hpp"
#include "platform/frame_stats.hpp"
#include "platform/input.hpp"
#include "platform/notes_window.hpp"
#include "platform/page.hpp"
#include "platform/window.hpp"
#include "ui/frame.hpp"
#include "ui/key_actions.hpp"
#include "ui/label_overlay.hpp"
#include "ui/panels/lecture_panel.hpp"
#include "ui/panels/scaling_panel.hpp"
#include "ui/scene_area.hpp"
#include "ui/slide_frame.hpp"
#include "ui/style.hpp"
#include "writers/screenshot.hpp"
#include "writers/slide_export.hpp"

#ifndef CONVEXLOC_SHADER_DIR
#define CONVEXLOC_SHADER_DIR "shaders"
#endif
#ifndef CONVEXLOC_ASSET_DIR
#define CONVEXLOC_ASSET_DIR "assets"
#endif
#ifndef CONVEXLOC_VERSION
#define CONVEXLOC_VERSION "unknown"
#endif

namespace cv = convexloc::viewer;

namespace {

// The answer to a command line that opens no window (an error, --help, --version), or -1.
int answerWithoutWindow(const cv::ParsedOptions& parsed) {
  if (!parsed.error.empty()) {
    std::cerr << "convexloc-viewer: " << parsed.error << "\n";
    return 2;
  }
  const cv::Options& o = parsed.options;
  if (!o.whySvg.empty() || !o.whyRecord.empty()) return cv::measureToSvg(o);
  if (!o.checkFile.empty() || !o.notesFile.empty()) {
    std::string out, err;
    const int code = cv::lectureReport(o, out, err);
    std::cout << out;
    std::cerr << err;
    return code;
  }
  if (parsed.options.help) std::cout << cv::usageText();
  if (parsed.options.version) std::cout << "convexloc-viewer " CONVEXLOC_VERSION "\n";
  return parsed.options.help || parsed.options.version ? 0 : -1;
}

// the shaders: --shaders, else the source tree's, else an installed copy beside the binary
std::string shaderDirFor(const cv::Options& options, const char* argv0) {
  if (!options.shaderDir.empty()) return options.shaderDir;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path installed =
      fs::path(cv::selfPath(argv0)).parent_path() / ".." / "share" / "convexloc" / "shaders";
  if (!fs::exists(fs::path(CONVEXLOC_SHADER_DIR) / "points.vert", ec) &&
      fs::exists(installed / "points.vert", ec))
    return installed.lexically_normal().string();
  return CONVEXLOC_SHADER_DIR;
}

// Multisampling costs a software renderer (Mesa's llvmpipe) about three times the frame
// time, and the shaders anti-alias lines and points themselves: none there by default.
int samplesFor(const cv::Options& options, const cv::GlInfo& gl) {
  return std::min(options.samples >= 0 ? options.samples : (gl.software ? 0 : 4), gl.maxSamples);
}

// the panels' first state: the assets, a comparison asked by --compare, the GL's name
cv::UiState startUi(cv::Model& model, const cv::Options& options, const cv::GlInfo& gl,
                    int samples) {
  cv::UiState ui;
  ui.assetDir = CONVEXLOC_ASSET_DIR;
  ui.assets = cv::shapeFilesIn(ui.assetDir);
  ui.fontScaleEdit = model.settings.fontScale;
  if (options.compare && model.dim == cv::Dim::Two) ui.compare2d = model.scene2d.compare();
  if (options.compare && model.dim == cv::Dim::Three) ui.compare3d = model.scene3d().compare();
  ui.glInfo = gl.renderer + ", GL " + gl.version +
              (samples > 0 ? ", MSAA " + std::to_string(samples) + "x" : ", no MSAA");
  return ui;
}

// A lecture dropped on the window or picked in the web page, at its first slide: the text
// size the window had becomes the lecture's zoom, as --font-scale is at start.
void openLecture(cv::Model& model, cv::UiState& ui, const std::string& path) {
  if (ui.show.lecture.slides.empty()) {
    model.settings.textZoom = model.settings.fontScale / model.settings.uiScaleFactor;
    model.settings.fontScale = 1.0f;
  }
  cv::Options options;
  options.lecture = path;
  cv::startLecture(model, ui, options, false);
}

// the files dropped on the window become the scene, or the lecture among them (the others
// are its shapes); true when there were any
bool openDropped(cv::Model& model, cv::UiState& ui) {
  const std::vector<std::string> files = cv::takeDroppedFiles();
  const auto lecture = std::find_if(files.begin(), files.end(), [](const std::string& f) {
    return std::filesystem::path(f).extension() == ".lecture";
  });
  if (lecture != files.end()) {
    openLecture(model, ui, *lecture);
    return true;
  }
  for (const std::string& path : files)
    if (model.open(path)) std::snprintf(ui.path, sizeof ui.path, "%s", path.c_str());
  return !files.empty();
}

// --animate: the camera moves a little every frame, as under a hand (for timing)
void nudgeCamera(cv::Model& model) {
  if (model.dim == cv::Dim::Two)
    model.camera2d.pan({1.0, 0.5});
  else
    model.camera3d.orbit({2.0, 0.0});
}

// Clears the window and draws the scene: its cached base, then the overlay. A target with
// `samples` the GL refuses falls back to none.
void drawScene(cv::Model& model, cv::Renderer& renderer, cv::SceneView& view,
               const cv::FrameSize& size, int& samples, cv::UiState& ui) {
  const int fbW = size.framebufferWidth, fbH = size.framebufferHeight;
  cv::clearWindow(fbW, fbH, cv::paletteFor(model.settings.theme).background);
  if (!renderer.ensureTarget(fbW, fbH, samples) && samples > 0 &&
      renderer.ensureTarget(fbW, fbH, samples = 0))
    ui.glInfo += " (multisampled target refused: none)";
  const glm::vec2 fb{static_cast<float>(fbW), static_cast<float>(fbH)};
  if (cv::plotsSlide(model, ui)) return;  // Why O(1)'s plots are that slide's figure
  view.drawBase(model, renderer, fb, size.pixelRatio);
  view.drawOverlay(model, renderer, fb, size.pixelRatio);
}

// the pointer's gestures on the scene (a window with hands only)
void takePointer(const cv::Window& window, cv::Interaction& interaction, cv::Model& model,
                 cv::UiState& ui) {
  cv::PointerInput pointer = cv::pointerInput(window.hovered());
  // after a clicker's slide change the resting pointer hovers nothing until it moves
  if (pointer.delta != glm::dvec2(0.0)) ui.pointerStill = false;
  if (ui.pointerStill) pointer.hovering = false;
  interaction.update(model.split.toLeft(pointer), model);
}

// The frame's files: the next slide of --export, the screenshot and SVG asked for (by a key,
// or --screenshot / --svg on the last frame). True when the run ends after this frame;
// `exitCode` becomes 1 when a file could not be written.
bool writeFrameFiles(const cv::Options& options, bool headless, const cv::FrameStats& stats,
                     const cv::FrameSize& size, cv::Model& model, const cv::SceneView& view,
                     cv::UiState& ui, cv::SlideExporter& exporter, int& exitCode) {
  bool lastFrame = headless && stats.frames() >= options.frames;
  if (exporter.active()) {  // --export: every slide written, then the run ends
    if (!exporter.afterFrame(model, view, ui, size.framebufferWidth, size.framebufferHeight))
      exitCode = 1;
    lastFrame = exporter.finished() || exitCode != 0;
  }
  const std::string finalShot = lastFrame ? options.screenshot : "";
  if (!cv::screenshotIfAsked(model, ui, finalShot, size.framebufferWidth, size.framebufferHeight,
                             stats.seconds()))
    exitCode = 1;
  if (!cv::svgIfAsked(model, view, ui, lastFrame ? options.svg : "", stats.seconds())) exitCode = 1;
  return lastFrame;
}

// The speaker notes in their own window while N asks for them during a lecture; where no
// second window opens they are drawn inside the main one (the next frame's panels).
void showNotes(cv::NotesWindow& notes, const cv::Window& window, cv::UiState& ui) {
  bool wanted = ui.showNotes && ui.show.active();
  ui.notesOwnWindow = notes.update(
      wanted, window.handle(), [](float pixels) { cv::loadFont(pixels, false); },
      [&ui] { cv::notesContents(ui.show); });
  if (ui.show.active()) ui.showNotes = wanted;
}

// The viewer from its first frame to its last: the window, the model, the panels' state,
// the GL objects; frame() is one turn of Dear ImGui's GLFW + OpenGL 3 example loop.
class Viewer final : public cv::FrameSource {
 public:
  Viewer(const cv::Options& options, bool headless) : options_(options), headless_(headless) {}
  // opens the window and readies the scene: an exit code when the run ends here, else -1
  int start(const char* argv0);
  bool frame() override;
  int exitCode() const override { return exitCode_; }

 private:
  // --frames and the other headless runs: what the frames cost, on stdout
  void printSummary() const;

  cv::Options options_;
  bool headless_;
  cv::Window window_;  // first: the GL objects below go before their context
  int samples_ = 0;
  cv::Model model_;
  cv::UiState ui_;
  std::unique_ptr<cv::SlideExporter> exporter_;
  std::unique_ptr<cv::StyleKeeper> style_;
  cv::Renderer renderer_;
  cv::SceneView view_;
  cv::NotesWindow notes_;
  cv::Interaction interaction_;
  cv::FrameStats stats_;
  cv::IdleCounter idle_;
  int exitCode_ = 0;
};

int Viewer::start(const char* argv0) {
  if (!window_.open(options_, headless_)) return 1;
  cv::watchDrops(window_.handle());
  cv::watchKeys(window_.handle());
  const cv::GlInfo gl = cv::queryGl();
  samples_ = samplesFor(options_, gl);
  cv::enableMultisample();
  if (const std::string problem = model_.apply(options_); !problem.empty() && headless_) {
    std::cerr << "convexloc-viewer: " << problem << "\n";
    return 1;
  }
  ui_ = startUi(model_, options_, gl, samples_);
  ui_.exporting = headless_;  // no tooltips in written files
#ifdef __EMSCRIPTEN__
  ui_.webPage = true;
#endif
  model_.settings.uiScaleFactor = options_.uiScale;
  if (!options_.lecture.empty()) {
    // a lecture's slides give their own text size: --font-scale zooms it
    model_.settings.textZoom = options_.fontScale;
    model_.settings.fontScale = 1.0f;
  } else if (!options_.figure) {
    model_.settings.fontScale *= options_.uiScale;  // the panels, not a figure's slide
  }
  if (!cv::startLecture(model_, ui_, options_, headless_)) return 1;
  // the web page: what the link asked for and could not be shown, in the page's message box
  if (ui_.webPage && !model_.error().empty()) cv::showPageProblem(model_.error());
  exporter_ = std::make_unique<cv::SlideExporter>(options_.exportDir, options_.exportFirst);
  style_ = std::make_unique<cv::StyleKeeper>(model_.settings, window_.contentScale());
  const std::string shaderDir = shaderDirFor(options_, argv0);
  if (!renderer_.init(shaderDir)) {
    std::cerr << "convexloc-viewer: shader problems in " << shaderDir << ":\n"
              << renderer_.shaderLog();
    model_.fail("shaders failed to compile (see View > shaders): " + shaderDir);
    if (headless_) return 1;
  }
  return -1;
}

bool Viewer::frame() {
  if (window_.shouldClose()) return false;
  stats_.begin();
  // the web page, idle: nothing new to draw, the picture on the page stays
  if (!window_.takeEvents(!headless_ && idle_.idle())) return true;
  model_.settings.drawer = window_.narrow();
  // the keys' actions (a window with hands), or --export's next slide, before the frame's
  // text size, fit and layout: a slide shown now is final on its first frame
  if (!headless_)
    for (const cv::Action& a : cv::keyActions()) cv::perform(a, model_, ui_);
  if (!exporter_->turnPage(model_, ui_)) exitCode_ = 1;
  // a slide's page scales with the window; outside the ImGui frame, a new text size on
  // screen (a new page scale, zoom or text size) makes the font again and refits the scene
  model_.settings.pageScale =
      static_cast<float>(cv::pageOf(model_, ui_, window_.frameSize().window).scale);
  if (style_->update(model_.settings, ui_.pendingFontScale)) model_.requestFit();
  window_.newFrame();

  const cv::FrameSize size = window_.frameSize();
  model_.camera2d.setViewport(size.window);
  model_.camera3d.setViewport(size.window);
  const bool dropped = openDropped(model_, ui_);
  if (model_.takeFitRequest()) cv::fitScene(model_, ui_, size.window, stats_.seconds());
  if (!headless_) takePointer(window_, interaction_, model_, ui_);
  if (options_.animate && stats_.frames() > 0) nudgeCamera(model_);
  model_.lines2d.sync(model_.scene2d);
  model_.collectErrors();
  idle_.note(cv::hadInput(dropped || ui_.pendingFontScale > 0.0f) || model_.busy() ||
             options_.animate);  // a camera moving by itself is never idle

  cv::drawUi(model_, renderer_, ui_, stats_.seconds());
  view_.sync(model_, renderer_);
  cv::drawLabels(model_, ui_, view_);
  cv::blankIfAsked(ui_.show);
  ImGui::Render();

  drawScene(model_, renderer_, view_, size, samples_, ui_);
  window_.renderImGui();

  stats_.count();
  const bool lastFrame =
      writeFrameFiles(options_, headless_, stats_, size, model_, view_, ui_, *exporter_, exitCode_);
  cv::offerDownloads();
  if (headless_) cv::finishGl();  // time what the GL really did
  window_.swapBuffers();
  if (!headless_) showNotes(notes_, window_, ui_);
  if (ui_.reloadShaders && !renderer_.reload()) model_.fail("shaders failed to compile: see View");
  ui_.reloadShaders = false;
  stats_.end();
  ui_.frameMs = stats_.smoothedMs();
  const std::size_t slides = ui_.show.lecture.slides.size();
  cv::frameDrawn(model_, slides == 0 ? -1 : static_cast<std::ptrdiff_t>(ui_.show.current), slides);
  // --export: a lecture with problems wrote its good slides, and says so by its exit code
  if (lastFrame && exporter_->active() && !ui_.show.lecture.allProblems().empty()) exitCode_ = 1;
  if (lastFrame && headless_) printSummary();
  return !lastFrame;
}

void Viewer::printSummary() const {
  std::printf(
      "convexloc-viewer: %d frames at %dx%d, %zu points (%zu drawn in the last), %s, mean %.2f "
      "ms/frame after the first (%s)\n",
      stats_.frames(), options_.width, options_.height, renderer_.pointCount(), view_.pointsDrawn(),
      options_.animate ? "camera moving" : "camera still", stats_.meanMs(), ui_.glInfo.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  const cv::ParsedOptions parsed = cv::parsePageOptions(args);
  if (const int code = answerWithoutWindow(parsed); code >= 0) return code;
  const cv::Options& options = parsed.options;
  if (!cv::displayAvailable()) {
    if (!options.noXvfb) return cv::rerunUnderXvfb(argc, argv, options);
    std::cerr << "convexloc-viewer: no display (DISPLAY is not set)\n";
    return 1;
  }
  const bool headless = !options.screenshot.empty() || !options.svg.empty() ||
                        options.framesGiven || !options.exportDir.empty();
  cv::preparePage();
  auto viewer = std::make_unique<Viewer>(options, headless);
  if (const int code = viewer->start(argv[0]); code >= 0) return code;
  return cv::runFrames(std::move(viewer));
}
