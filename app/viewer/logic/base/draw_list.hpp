// convexloc-viewer — what a layer of the scene draws, in world coordinates (double), GL-free.
// The structure builders fill these from core's introspection; the renderer uploads them
// as floats relative to an origin and draws them. Nothing here decides a classification.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "logic/base/colour.hpp"

namespace convexloc::viewer {

// a line segment of constant width in pixels; dashed when `dash` > 0 (dash length, pixels)
struct Segment {
  glm::dvec3 a{0.0};
  glm::dvec3 b{0.0};
  Rgba colour;
  float width = 1.0f;
  float dash = 0.0f;
};

// a triangle corner; three consecutive corners make a triangle
struct FillVertex {
  glm::dvec3 p{0.0};
  Rgba colour;
  glm::vec3 normal{0.0f};  // zero: unlit (2D fills); else lit (3D faces)
};

enum class MarkerShape : std::uint8_t { Disc, Ring, Cross, Square };

// a screen-sized marker at a world point (centres, handles, placed points)
struct Marker {
  glm::dvec3 p{0.0};
  Rgba colour;
  float size = 8.0f;  // diameter in pixels
  MarkerShape shape = MarkerShape::Disc;
};

// a text label at a world point, shifted by `offset` pixels
struct Label {
  glm::dvec3 p{0.0};
  std::string text;
  Rgba colour;
  glm::vec2 offset{0.0f};
  bool essential = false;  // shown even where it must move off its spot (a leader to it)
};

struct DrawList {
  std::vector<FillVertex> fills;
  std::vector<Segment> segments;
  std::vector<Marker> markers;
  std::vector<Label> labels;

  void clear() {
    fills.clear();
    segments.clear();
    markers.clear();
    labels.clear();
  }
  bool empty() const {
    return fills.empty() && segments.empty() && markers.empty() && labels.empty();
  }
  void segment(glm::dvec3 a, glm::dvec3 b, Rgba c, float width, float dash = 0.0f) {
    segments.push_back({a, b, c, width, dash});
  }
  void triangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, Rgba colour) {
    fills.push_back({a, colour, {}});
    fills.push_back({b, colour, {}});
    fills.push_back({c, colour, {}});
  }
  void marker(glm::dvec3 p, Rgba c, float size, MarkerShape s = MarkerShape::Disc) {
    markers.push_back({p, c, size, s});
  }
  void label(glm::dvec3 p, std::string text, Rgba c, glm::vec2 offset = {0.0f, 0.0f}) {
    labels.push_back({p, std::move(text), c, offset});
  }
};

// 2D helpers: points of the plane z = 0
inline glm::dvec3 at2(glm::dvec2 p) {
  return {p.x, p.y, 0.0};
}

}  // namespace convexloc::viewer
