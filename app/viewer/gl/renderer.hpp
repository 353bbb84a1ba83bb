// convexloc-viewer — the thin GL backend: it uploads draw lists and points (as floats
// relative to an origin, so that shapes far from zero stay sharp) and draws them. It knows
// nothing of polygons or locators; what to draw comes from logic/.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include <glm/glm.hpp>

#include "convexloc/geometry.hpp"
#include "gl/gl.hpp"
#include "gl/no_copy.hpp"
#include "gl/shader.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {

// the draw lists the renderer keeps
enum class Layer : int {
  Structure = 0,
  Overlay = 1,
  Mesh = 2,
  Section = 3,
  SplitStructure = 4,
  SplitOverlay = 5
};
inline constexpr int kLayerCount = 6;

// which triangles a fill draw skips
enum class Cull { None, Front, Back };

// which points a point draw covers: boundary points are kept at the end of the buffer so
// that they can be drawn last, over the polygon's edges
enum class PointRange { All, AllButBoundary, Boundary };

// what a frame's draw calls share
struct FrameParams {
  glm::mat4 clipFromLocal{1.0f};
  glm::vec3 eyeLocal{0.0f};     // 3D: the eye, for the headlight
  glm::vec2 framebuffer{1.0f};  // pixels
  float pixelRatio = 1.0f;      // framebuffer pixels per window pixel
  float pointSize = 4.0f;       // window pixels
  float lineScale = 1.0f;       // segment widths and marker sizes are multiplied by it
  unsigned visibleMask = 7u;    // classes of points drawn
  Rgba classColours[3];
  Rgba rim;
  bool depth = false;                       // 3D: depth-test
  bool depthWrite = false;                  // 3D: and write depth
  bool offset = false;                      // push fills back a little (so edges drawn on them win)
  std::size_t maxPoints = ~std::size_t{0};  // draw at most this many points (a uniform subsample:
                                            // the sprays come in random order)
};

class Renderer : NoCopy {
 public:
  // deletes the GL objects (the context must still be current)
  ~Renderer();

  // Creates the buffers and compiles the shaders in `dir`. False when a shader failed:
  // shaderLog() then holds the compiler's words, and the layers it draws are skipped.
  bool init(const std::string& dir);
  // compiles the shaders again (after editing them); false and shaderLog() on failure
  bool reload();
  const std::string& shaderLog() const { return log_; }
  const std::string& shaderDir() const { return dir_; }

  // replaces a layer's geometry
  void upload(Layer layer, const DrawList& list, glm::dvec3 origin);
  // replaces the points and their classes
  void uploadPoints(std::span<const Vec2> points, std::span<const Location> classes,
                    glm::dvec3 origin);
  void uploadPoints(std::span<const Vec3> points, std::span<const Location> classes,
                    glm::dvec3 origin);
  std::size_t pointCount() const { return pointCount_; }

  void drawFills(Layer layer, const FrameParams& f, Cull cull = Cull::None);
  void drawSegments(Layer layer, const FrameParams& f);
  void drawMarkers(Layer layer, const FrameParams& f);
  void drawPoints(const FrameParams& f, PointRange range = PointRange::All);
  // draws only inside `rect` (window pixels) until clearClip(); the split view's halves
  void clipTo(ScreenRect rect, const FrameParams& f);
  void clearClip();

  // === The scene cache: the scene is drawn into an offscreen target (multisampled when
  // asked) only when it changes; every frame composites it, then the overlay and ImGui.
  // Makes (or remakes, on a new size) the target; false when the GL cannot.
  bool ensureTarget(int width, int height, int samples);
  // draws into the target from now on
  void bindTarget();
  // resolves the target and draws into the window again
  void finishTarget();
  // draws the target's picture over the whole window
  void compositeTarget();
  bool hasTarget() const { return resolveFbo_ != 0; }

 private:
  struct GpuLayer {
    GLuint fillVao = 0, fillVbo = 0;
    GLuint segVao = 0, segVbo = 0;
    GLuint markVao = 0, markVbo = 0;
    GLsizei fills = 0, segments = 0, markers = 0;
  };
  bool compileAll();

  std::string dir_, log_;
  ShaderProgram fill_, segments_, markers_, points_, blit_;
  GpuLayer layers_[kLayerCount];
  GLuint pointVao_ = 0, pointVbo_ = 0, classVbo_ = 0;
  std::size_t pointCount_ = 0;
  std::size_t boundaryStart_ = 0;  // points [boundaryStart_, pointCount_) are boundary points
  bool created_ = false;
  template <class P, class Put>
  void uploadOrdered(std::span<const P> points, std::span<const Location> classes, Put put);
  void destroyTarget();
  GLuint msFbo_ = 0, msColour_ = 0, msDepth_ = 0;    // multisampled, when samples > 0
  GLuint resolveFbo_ = 0, texture_ = 0, depth_ = 0;  // single-sampled, sampled by the blit
  GLuint blitVao_ = 0;
  int targetW_ = 0, targetH_ = 0, targetSamples_ = 0;
};

}  // namespace convexloc::viewer
