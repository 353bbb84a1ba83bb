// convexloc-viewer — what the panels keep between frames, and what they ask the frame
// loop to do (it owns the window and the GL context).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "logic/scene2d.hpp"
#include "logic/scene3d.hpp"

namespace convexloc::viewer {

// a generator's settings in the Shape panel
struct GeneratorChoice {
  int kind = 0;  // index into kAllPolygonKinds or kAllPolyhedronKinds
  int n = 16;    // vertices (2D) or faces, about (3D)
  std::uint64_t seed = 1;
};

// what the panels keep between frames, and what they ask main to do
struct UiState {
  // requests for main, which owns the window and the GL context
  bool screenshotRequested = false;
  std::string screenshotPath;
  bool reloadShaders = false;
  float pendingFontScale = 0.0f;  // > 0: rebuild the font at this scale
  bool quit = false;

  // widget state
  char path[1024] = "";
  GeneratorChoice generator2d{1, 16, 7};   // random, 16 vertices, seed 7
  GeneratorChoice generator3d{4, 320, 1};  // icosahedron
  int sprayCount = 3000;
  bool sprayNear = false;
  std::uint64_t spraySeed = 1;
  float fontScaleEdit = 1.0f;
  std::vector<CompareRow> compare2d;  // the last Compare all methods, per scene
  std::vector<CompareRow3D> compare3d;
  std::string assetDir;
  std::vector<std::string> assets;  // shape files found in assetDir

  // the toast: the last error, shown for a while
  std::string toast;
  double toastUntil = 0.0;
  std::uint64_t toastSerial = 0;
  std::string notice;  // a short confirmation (screenshot written, ...)
  double noticeUntil = 0.0;

  // timing, for the View panel
  double frameMs = 0.0;
  std::string glInfo;
};

}  // namespace convexloc::viewer
