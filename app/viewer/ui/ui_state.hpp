// convexloc-viewer — what the panels keep between frames, and what they ask the frame
// loop to do (it owns the window and the GL context).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "logic/app/lecture.hpp"
#include "logic/scene/scene2d.hpp"
#include "logic/scene/scene3d.hpp"
#include "logic/teach/slide_layout.hpp"

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
  // presentation and vector figures
  bool svgRequested = false;
  std::string exportDir;          // where F12 and V write; empty: the working directory
  char exportDirEdit[1024] = "";  // the View panel's box for it
  bool legendMoved = false;       // the user dragged the legend: it stays where put
  bool legendDragging = false;    // a drag that began on the legend goes on
  bool exporting = false;         // files are being written: no tooltips, no hover
  bool webPage = false;           // the viewer runs in a web page: files are downloads
  float legendPos[2] = {0.0f, 0.0f};
  float legendSize[2] = {0.0f, 0.0f};  // the floating legend's size in the last frame
  float captionHeight = 0.0f;          // the caption box's height in the last frame
  std::size_t compareSeen = 0;         // the comparison rows the Shape panel was last folded for
  double refitUntil = 0.0;  // until then a change of the layout's scene room refits the scene
  ScreenRect fittedScene;   // the room the camera was last fitted into
  // the camera as the last fit left it (2D: centre, scale; 3D: target, distance, yaw,
  // pitch): while it stays so, a new room (a Steps window, a taller legend) refits it
  double fittedView[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  // the slide's layout this frame (ui/slide_frame): what the window's boxes and the SVG draw
  SlideLayout layout;
  TextBox splitHeadings[2];  // the split view's headings this frame (none: no lines)
  // the Why O(1) window this frame and the page of plots in it (empty: not shown), for the SVG
  struct WhyPlots {
    ScreenRect rect;
    double fontPx = 0.0;
    bool solid = false;
  } whyPlots;
  ScreenRect whyWindow;
  // the Steps window
  int stepsCode = -1;  // its pseudo-code: 1 whole, 0 the current line, -1 whole where wide
  // the floating legend's and the Steps window's rectangles this frame (x0, y0, x1, y1; all
  // zero where not shown), which the scene's labels keep off
  float legendRect[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  float stepsRect[4] = {0.0f, 0.0f, 0.0f, 0.0f};

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

  // the lecture (or the paper's figure) shown, and the spray settings the Points panel last
  // took from the scene
  SlideShow show;
  bool showNotes = false;       // the speaker notes' window (N)
  bool notesOwnWindow = false;  // they have a window of their own (else one inside this)
  // a slide moved to by a key, and the viewer just started, show no hovered cell until the
  // pointer moves
  bool pointerStill = true;
  SpraySettings sprayFollowed{~std::size_t{0}, 0, false};
};

// The Points panel's spray settings follow the scene's whenever the scene's change (a
// --spray, a slide, a new scene), so that the panel, Spray and Space go on from the spray
// shown; edits in the panel stay until the scene's settings change again.
inline void followSpray(UiState& ui, const SpraySettings& s) {
  const SpraySettings& f = ui.sprayFollowed;
  if (s.count == f.count && s.seed == f.seed && s.nearBoundary == f.nearBoundary) return;
  ui.sprayFollowed = s;
  ui.sprayCount = static_cast<int>(std::min<std::size_t>(s.count, 10000000));
  ui.spraySeed = s.seed;
  ui.sprayNear = s.nearBoundary;
}

class Model;

// The panels of one scene, as the layout shows them: the left window's Shape, Method, an
// optional panel of its own and Points; the View panel's options; the right window's
// legend and inspector.
struct ScenePanels {
  void (*shape)(Model&, UiState&);
  void (*method)(Model&, UiState&);
  const char* ownTitle;  // the scene's own panel ("Slicing plane"), or nullptr
  void (*own)(Model&);
  void (*points)(Model&, UiState&);
  bool pointsOpen;  // the Points panel starts open
  void (*viewOptions)(Model&);
  void (*legend)(Model&);
  void (*inspector)(Model&, bool hints);
  // a hovered or pinned cell, or a placed point, for the floating inspector
  bool (*inspectable)(Model&);
  const char* const* hints;  // the mouse and key hints under the panels, nullptr-terminated
};

}  // namespace convexloc::viewer
