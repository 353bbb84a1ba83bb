// convexloc-viewer — what `--export` writes beside the slides' pictures: layout.json, the
// numbers each slide was drawn from, in page pixels ([x, y, width, height] from the page's
// top left), so that a test (or a reader) checks the layout's rules without the viewer.
// GL-free.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "logic/base/screen_rect.hpp"

namespace convexloc::viewer {

// what a slide is: a title alone, a 2D or 3D figure, or plots (Why O(1))
enum class SlideKind { Title, Figure2D, Figure3D, Plots };

// a 3D query on the page: the centre x_T, the point x, the middle of the face the ray hits
struct Query3DOnPage {
  glm::dvec2 centre{0.0};
  glm::dvec2 point{0.0};
  glm::dvec2 hitFace{0.0};
};

// one slide's record; boxes in page pixels, in the order written
struct SlideRecord {
  std::size_t slide = 1;  // the slide's number, from 1
  SlideKind kind = SlideKind::Figure2D;
  glm::dvec2 page{0.0};  // the page's size in pixels
  std::vector<std::pair<std::string, ScreenRect>> boxes;
  double minTextPx = 0.0;  // the smallest text drawn on the slide, pixels high
  std::optional<Query3DOnPage> query3d;
  // adds `box` (window pixels, the page's top left at `pageLo`) under `name`; an empty box
  // is left out
  void add(const std::string& name, ScreenRect box, glm::dvec2 pageLo);
};

// "title", "figure2d", "figure3d", "plots"
const char* kindName(SlideKind kind);

// the records as layout.json: {"slides": [{"slide": 1, "kind": ..., "page": [W, H],
// "boxes": {...}, "min_text_px": ..., "query3d": {...}}]}, numbers to a hundredth
std::string layoutJson(std::span<const SlideRecord> slides);

}  // namespace convexloc::viewer
