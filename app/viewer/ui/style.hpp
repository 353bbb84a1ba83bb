// convexloc-viewer — how the panels look: the ImGui theme and the font.
#pragma once

#include "logic/base/colour.hpp"
#include "logic/app/model.hpp"

namespace convexloc::viewer {

// ImGui's colours and sizes for a theme at a scale (1 = normal)
void applyStyle(Theme theme, float scale);

// (Re)builds the font atlas at `pixels` pixel height: DejaVu Sans when installed, ImGui's
// own font otherwise. Call outside a frame; with `recreateTexture` (after the first frame)
// the GL backend's font texture is made again.
void loadFont(float pixels, bool recreateTexture);

// Keeps ImGui's font and style in step with the settings' theme and text scale on screen
// (Settings::uiScale: the text size, the zoom and a slide's page scale), on a screen of
// `dpi` framebuffer pixels per window pixel. Changes are applied outside a frame.
class StyleKeeper {
 public:
  // loads the font and applies the style of `settings`
  StyleKeeper(const Settings& settings, float dpi);
  // Takes a font scale the View panel asked for (> 0), and restyles after any change.
  // Returns true when the text's size on screen changed.
  bool update(Settings& settings, float& pendingFontScale);

 private:
  float dpi_;
  Theme theme_;
  float scale_;
};

}  // namespace convexloc::viewer
