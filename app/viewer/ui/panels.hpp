// convexloc-viewer — the Dear ImGui panels: shape, method, points, view; the inspector;
// the legend; error toasts; labels written over the scene.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/renderer.hpp"
#include "gl/scene_view.hpp"
#include "logic/model.hpp"

namespace convexloc::viewer {

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
  int generatorKind = 1;  // index into kAllPolygonKinds
  int generatorN = 16;
  std::uint64_t generatorSeed = 7;
  int generator3Kind = 4;  // index into kAllPolyhedronKinds (icosahedron)
  int generator3N = 320;
  std::uint64_t generator3Seed = 1;
  std::vector<CompareRow3D> compare3;
  int sprayCount = 3000;
  bool sprayNear = false;
  std::uint64_t spraySeed = 1;
  float fontScaleEdit = 1.0f;
  std::vector<CompareRow> compare;
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

// the panel widths in window pixels, at the current font scale
float leftPanelWidth(const Model& model, glm::dvec2 window);
float rightPanelWidth(const Model& model, glm::dvec2 window);
// the part of the window the scene has to itself (right of the panel when it shows)
ScreenRect sceneArea(const Model& model, glm::dvec2 window);

// finds the shape files in ui.assetDir
void scanAssets(UiState& ui);

// keyboard shortcuts (F fit, H panels, 1..5 method, Space spray, Esc clear, T theme, F12)
void handleKeys(Model& model, UiState& ui);

// every window of the frame; `now` in seconds
void drawUi(Model& model, Renderer& renderer, const SceneView& view, UiState& ui, double now);

// the draw lists' labels, written on ImGui's background draw list over the scene
void drawLabels(Model& model, const SceneView& view);

}  // namespace convexloc::viewer
