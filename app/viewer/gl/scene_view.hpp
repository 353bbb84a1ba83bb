// convexloc-viewer — keeps the GPU copy of the model's scene up to date and draws it:
// rebuilds a draw list only when the part of the scene behind it changed, and moves the
// local origin near the camera when zooming deep, so floats never blur the picture.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gl/renderer.hpp"
#include "logic/draw_list.hpp"
#include "logic/model.hpp"

namespace convexloc::viewer {

class SceneView {
public:
  // brings the renderer's layers and points up to date with the model
  void sync(const Model& model, Renderer& renderer);
  // draws the scene into the framebuffer (fbSize pixels, pixelRatio per window pixel)
  void draw(const Model& model, Renderer& renderer, glm::vec2 fbSize, float pixelRatio);

  // the draw lists, for the labels ImGui writes over the scene
  const DrawList& structure() const { return structure_; }
  const DrawList& overlay() const { return overlay_; }
  // the point size the last frame used (window pixels)
  float pointSize() const { return pointSize_; }

private:
  glm::dvec3 origin_{0.0};
  DrawList structure_, overlay_;
  // what the uploaded data was built from
  std::uint64_t shape_ = ~0ull, structureV_ = ~0ull, points_ = ~0ull, overlayV_ = ~0ull;
  Theme theme_ = Theme::Dark;
  View2DOptions options_{};
  bool first_ = true;
  float pointSize_ = 4.0f;
};

}  // namespace convexloc::viewer
