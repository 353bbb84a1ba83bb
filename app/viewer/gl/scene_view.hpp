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
  // Draws the scene's base (everything but the overlay) into the renderer's cache when it
  // changed, then the cache into the window; without a cache, straight into the window.
  // While the camera moves over a heavy spray, a subsample of the points is drawn, sized
  // so that a frame takes about `frameBudgetMs`; all of them once it stops.
  void drawBase(Model& model, Renderer& renderer, glm::vec2 fbSize, float pixelRatio,
                double frameBudgetMs = 40.0);
  // draws the overlay (hover, probe, drag) over it
  void drawOverlay(Model& model, Renderer& renderer, glm::vec2 fbSize, float pixelRatio);
  // how many points the last base drew, of how many
  std::size_t pointsDrawn() const { return pointsDrawn_; }

  // the draw lists with labels, for the text ImGui writes over the scene
  const DrawList& structure() const { return structure_; }
  const DrawList& overlay() const { return overlay_; }
  // 3D: the polyhedron's faces and the slicing plane's section
  const DrawList& mesh() const { return mesh_; }
  const DrawList& section() const { return section_; }
  // the point size the last frame used (window pixels)
  float pointSize() const { return pointSize_; }

 private:
  // what the cached base was drawn from
  struct BaseKey {
    glm::mat4 clip{0.0f};
    glm::vec2 fb{0.0f};
    std::uint64_t uploads = 0;
    unsigned mask = 0;
    float pointSize = 0.0f;
    float lineScale = 0.0f;
    bool operator==(const BaseKey&) const = default;
  };
  FrameParams frameParams(Model& model, glm::vec2 fbSize, float pixelRatio);
  void drawBaseLayers(Model& model, Renderer& renderer, const FrameParams& f);
  void sync2d(const Model& model, Renderer& renderer, bool restyle);
  void sync3d(Model& model, Renderer& renderer, bool restyle);
  // the overlay (rebuilt by `buildOverlay`) and the points, after a move of the origin, a
  // restyle or a change of theirs; then remembers what they were built from
  template <class Scene, class BuildOverlay>
  void syncOverlayAndPoints(const Scene& scene, Renderer& renderer, bool moved, bool restyle,
                            bool overlayStale, BuildOverlay buildOverlay);

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
  bool linesShown_ = false;          // the 2D Lines mode was on
  std::uint64_t linesSeen_ = ~0ull;  // the Lines mode's version drawn
  std::uint64_t uploads_ = 0;        // grows with every upload the base depends on
  BaseKey lastKey_;
  bool cached_ = false;          // the cache holds lastKey_'s picture
  bool partial_ = false;         // ... drawn with a subsample of the points
  std::size_t budget_ = 250000;  // points a moving frame may draw
  std::size_t pointsDrawn_ = 0;
  bool first_ = true;
  float pointSize_ = 4.0f;
};

}  // namespace convexloc::viewer
