// convexloc-viewer — the web page's downloads and opened files (nothing on the desktop).
#include "platform/page.hpp"

#include <string>

#include "platform/input.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>

#include <filesystem>
#include <system_error>
#include <vector>

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
EM_JS(void, convexlocFrameDrawn, (), {
  if (Module.onFrame) Module.onFrame();
});
// clang-format on
#endif

namespace convexloc::viewer {

#ifdef __EMSCRIPTEN__

namespace {
// the page's folder for the files the viewer writes
constexpr const char* kDownloadDir = "/downloads";
}  // namespace

void preparePage() {
  std::error_code ec;
  std::filesystem::create_directories(kDownloadDir, ec);
  std::filesystem::current_path(kDownloadDir, ec);
}

void frameDrawn() {
  convexlocFrameDrawn();
}

void offerDownloads() {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> written;
  for (const fs::directory_entry& e : fs::directory_iterator(kDownloadDir, ec))
    if (e.is_regular_file(ec)) written.push_back(e.path());
  for (const fs::path& p : written) {
    const std::string ext = p.extension().string();
    const char* type = ext == ".png" ? "image/png"
                       : ext == ".svg" ? "image/svg+xml"
                                       : "application/octet-stream";
    convexlocDownload(p.c_str(), p.filename().c_str(), type);
  }
}

#else

void preparePage() {}
void frameDrawn() {}
void offerDownloads() {}

#endif

}  // namespace convexloc::viewer

extern "C" void convexloc_open_file(const char* path) {
  convexloc::viewer::openLater(path);
}
