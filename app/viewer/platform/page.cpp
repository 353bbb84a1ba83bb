// convexloc-viewer — the web page's downloads, opened files, message box and view state
// (the command line's behaviour on the desktop).
#include "platform/page.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "logic/app/model.hpp"
#include "platform/input.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <system_error>

// a file of the in-memory files saved by the browser under `name`, then removed
// clang-format off
EM_JS(void, convexlocDownload, (const char* path, const char* name, const char* type), {
  const file = UTF8ToString(path);
  const data = FS.readFile(file);
  const link = document.createElement('a');
  link.href = URL.createObjectURL(new Blob([data], {type: UTF8ToString(type)}));
  link.download = UTF8ToString(name);
  document.body.appendChild(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(link.href), 10000);
  FS.unlink(file);
  if (Module.onDownload) Module.onDownload(UTF8ToString(name), data.length);
});
EM_JS(void, convexlocPageProblem, (const char* text), {
  if (Module.onProblem) Module.onProblem(UTF8ToString(text));
});
EM_JS(void, convexlocFrameDrawn, (bool overUi, int dim, double scale2d, double centreX,
                                  double centreY, double distance, double yaw, double pitch,
                                  double targetX, double targetY, double targetZ,
                                  double panelScroll, double panelScrollMax, int slide,
                                  int slides, bool drawerOpen), {
  Module.pointerOverUi = overUi;
  Module.view = {dim: dim, scale2d: scale2d, centre2d: [centreX, centreY], distance: distance,
                 yaw: yaw, pitch: pitch, target: [targetX, targetY, targetZ],
                 panelScroll: panelScroll,
                 panelScrollMax: panelScrollMax, slide: slide, slides: slides,
                 drawerOpen: drawerOpen};
  if (Module.onFrame) Module.onFrame();
});
// clang-format on
#endif

namespace convexloc::viewer {
namespace {

#ifdef __EMSCRIPTEN__
// the page's folder for the files the viewer writes
constexpr const char* kDownloadDir = "/downloads";

// the options as the page's URL wrote them: "--figure 99" is "figure=99"
std::string asInUrl(std::span<const std::string_view> group) {
  std::string text(group.front().substr(2));
  for (std::size_t i = 1; i < group.size(); ++i)
    text += (i == 1 ? "=" : ",") + std::string(group[i]);
  return text;
}

// a message of the command line's parser in the page's words: no leading dashes
std::string inPageWords(std::string text) {
  if (const std::size_t at = text.find(" (see --help)"); at != std::string::npos) text.erase(at);
  for (std::size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at))
    text.erase(at, 2);
  return text;
}

// the end of the option that starts at `i` (its name and its values)
std::size_t groupEnd(std::span<const std::string_view> args, std::size_t i) {
  std::size_t j = i + 1;
  while (j < args.size() && !args[j].starts_with("--")) ++j;
  return j;
}

// the options one by one, each kept when the viewer takes it with those kept before it;
// each one left out is said in the page's message box
ParsedOptions keepWhatParses(std::span<const std::string_view> args) {
  std::vector<std::string_view> kept;
  for (std::size_t i = 0; i < args.size();) {
    const std::size_t j = groupEnd(args, i);
    std::vector<std::string_view> tried = kept;
    tried.insert(tried.end(), args.begin() + static_cast<std::ptrdiff_t>(i),
                 args.begin() + static_cast<std::ptrdiff_t>(j));
    const ParsedOptions p = parseOptions(tried);
    if (p.error.empty())
      kept = std::move(tried);
    else
      showPageProblem("The link's \"" + asInUrl(args.subspan(i, j - i)) +
                      "\" was left out: " + inPageWords(p.error));
    i = j;
  }
  return parseOptions(kept);
}
#endif

}  // namespace

ParsedOptions parsePageOptions(std::span<const std::string_view> args) {
  ParsedOptions all = parseOptions(args);
#ifdef __EMSCRIPTEN__
  if (!all.error.empty()) return keepWhatParses(args);
#endif
  return all;
}

#ifdef __EMSCRIPTEN__

void preparePage() {
  std::error_code ec;
  std::filesystem::create_directories(kDownloadDir, ec);
  std::filesystem::current_path(kDownloadDir, ec);
}

void showPageProblem(const std::string& text) {
  std::cerr << "convexloc-viewer: " << text << "\n";
  convexlocPageProblem(text.c_str());
}

void frameDrawn(const Model& model, std::ptrdiff_t slide, std::size_t slides) {
  const ImGuiWindow* panel = ImGui::FindWindowByName("convexloc");
  const Camera2D& c2 = model.camera2d;
  const Camera3D& c3 = model.camera3d;
  convexlocFrameDrawn(ImGui::GetIO().WantCaptureMouse, model.dim == Dim::Two ? 2 : 3, c2.scale(),
                      c2.centre().x, c2.centre().y, c3.distance(), c3.yaw(), c3.pitch(),
                      c3.target().x, c3.target().y, c3.target().z, panel ? panel->Scroll.y : -1.0,
                      panel ? panel->ScrollMax.y : -1.0, static_cast<int>(slide),
                      static_cast<int>(slides), model.settings.drawerOpen);
}

void offerDownloads() {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> written;
  for (const fs::directory_entry& e : fs::directory_iterator(kDownloadDir, ec))
    if (e.is_regular_file(ec)) written.push_back(e.path());
  for (const fs::path& p : written) {
    const std::string ext = p.extension().string();
    const char* type = ext == ".png"   ? "image/png"
                       : ext == ".svg" ? "image/svg+xml"
                                       : "application/octet-stream";
    convexlocDownload(p.c_str(), p.filename().c_str(), type);
  }
}

#else

void preparePage() {}
void showPageProblem(const std::string& text) {
  std::cerr << "convexloc-viewer: " << text << "\n";
}
void frameDrawn(const Model&, std::ptrdiff_t, std::size_t) {}
void offerDownloads() {}

#endif

}  // namespace convexloc::viewer

extern "C" void convexloc_open_file(const char* path) {
  convexloc::viewer::openLater(path);
}
