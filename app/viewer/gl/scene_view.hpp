// convexloc-viewer — keeps the GPU copy of the model's scene (2D or 3D) up to date and draws
// it: rebuilds a draw list only when the part of the scene behind it changed, and moves the
// local origin near the camera when zooming deep, so floats never blur the picture.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gl/renderer.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/app/model.hpp"

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
  // the split view's right half: its structure and overlay (for their labels)
  const DrawList& splitStructure() const { return splitStructure_; }
  const DrawList& splitOverlay() const { return splitOverlay_; }
  // the point size the last frame used (window pixels)
  float pointSize() const { return pointSize_; }

 private:
  // what the cached base was drawn from
  struct BaseKey {
    glm::mat4 clip{0.0f};
    glm::mat4 splitClip{0.0f};  // the split view's right half, or zero
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

  // === The split view and the build animation
  // whether the right half shows (2D, split on, no Lines mode)
  static bool splitShown(const Model& model);
  glm::mat4 splitClip(const Model& model) const;
  template <class Draw>
  void drawHalves(const Model& model, Renderer& renderer, const FrameParams& f, Layer left,
                  Layer right, Draw draw) const;
  // the right half's lists, after a change of its scene, a restyle or a move of the origin
  void syncSplit(const Model& model, Renderer& renderer, const View2DOptions& opt, bool force);
  // the structure with the build animation's step over it (tints left to the animation)
  void buildStructure(const Model& model, const View2DOptions& opt);
  DrawList splitStructure_, splitOverlay_;
  Versions splitSeen_{~0ull, ~0ull, ~0ull, ~0ull, ~0ull};
  bool splitDrawn_ = false;
  std::uint64_t buildSeen_ = ~0ull;  // the build animation's version drawn (~0: off)

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
  bool linesShown_ = false;           // the 2D Lines mode was on
  std::uint64_t linesSeen_ = ~0ull;   // the Lines mode's version drawn
  bool planesShown_ = false;          // the 3D Planes mode was on
  std::uint64_t planesSeen_ = ~0ull;  // the Planes mode's version drawn
  DrawList planesOverlay_;            // its marks over everything
  std::uint64_t uploads_ = 0;         // grows with every upload the base depends on
  BaseKey lastKey_;
  bool cached_ = false;          // the cache holds lastKey_'s picture
  bool partial_ = false;         // ... drawn with a subsample of the points
  std::size_t budget_ = 250000;  // points a moving frame may draw
  std::size_t pointsDrawn_ = 0;
  bool first_ = true;
  float pointSize_ = 4.0f;
};

}  // namespace convexloc::viewer
