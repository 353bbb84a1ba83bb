// convexloc-viewer — keeps the GPU copy of the model's scene (2D or 3D) up to date and draws
// it: rebuilds a draw list only when the part of the scene behind it changed, and moves the
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
  void sync(Model& model, Renderer& renderer);
  // draws the scene into the framebuffer (fbSize pixels, pixelRatio per window pixel)
  void draw(Model& model, Renderer& renderer, glm::vec2 fbSize, float pixelRatio);

  // the draw lists with labels, for the text ImGui writes over the scene
  const DrawList& structure() const { return structure_; }
  const DrawList& overlay() const { return overlay_; }
  // the point size the last frame used (window pixels)
  float pointSize() const { return pointSize_; }

private:
  void sync2d(const Model& model, Renderer& renderer, bool restyle);
  void sync3d(Model& model, Renderer& renderer, bool restyle);

  glm::dvec3 origin_{0.0};
  DrawList structure_, overlay_, mesh_, section_;
  // what the uploaded data was built from
  Dim dim_ = Dim::Two;
  Versions seen_{~0ull, ~0ull, ~0ull, ~0ull, ~0ull};
  const void* scene_ = nullptr;
  Theme theme_ = Theme::Dark;
  View2DOptions options2_{};
  View3DOptions options3_{};
  unsigned farFaces_ = 0;
  bool first_ = true;
  float pointSize_ = 4.0f;
};

}  // namespace convexloc::viewer
