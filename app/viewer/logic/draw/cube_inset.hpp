// convexloc-viewer — the cube map's zoom inset: where the quadtree refines cube-map cells far
// below a base cell's size (the tiny-faces shape's rounded corner), a flat square beside the
// cube shows that patch of the cube face in its (s, t) coordinates, the leaves outlined and
// tinted as the main view tints them, titled with the face and the place, the magnification
// written under it, a leader to the place on the cube. Screen-space drawing only: the inset
// copies core's cells through a scale, nothing in it is decided. GL-free.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "convexloc/locate3d.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/view/label_layout.hpp"

namespace convexloc::viewer {

// the patch of one cube face the inset shows, in (s, t), and the leaves in it
struct CubeInset {
  int cubeFace = 0;
  glm::dvec2 lo{0.0};  // the patch: a square of side `side` from lo, inside [-1, 1]^2
  double side = 2.0;
  double baseSide = 2.0;           // a base cell's side (2 / G)
  double smallestSide = 2.0;       // the smallest leaf's side
  std::vector<std::size_t> cells;  // positions in cells() of the cells meeting the patch
  int mantissa = 1;                // the magnification, a cube face's side over the patch's:
  int exponent = 0;                // mantissa * 10^exponent, mantissa 1, 2 or 5
  double magnification() const;
};

// The inset where some leaf is at most 1/16 of a base cell wide: the patch around the
// smallest leaves (on the cube face of the first of them) at least 16 of them wide, its side a
// cube face's side over 1, 2 or 5 times a power of ten; none for cells not refined that far.
std::optional<CubeInset> cubeMapInset(std::span<const Cell3D> cells);

// "cube face +x near (s,t) = (1, 1)": the face and the patch's middle
std::string cubeInsetTitle(const CubeInset& inset);
// the title in two lines, "cube face +x" and "near (s,t) = (1, 1)" (a slide's narrow corner)
std::vector<std::string> cubeInsetTitleLines(const CubeInset& inset);
// "zoom ×5·10^4"
std::string cubeInsetZoomText(const CubeInset& inset);

// the patch's middle on the drawing cube (where core's cells are drawn), in world units
glm::dvec3 cubeInsetAnchor(const CubeInset& inset, std::span<const Cell3D> cells);

// A square frame for the inset in window pixels, `text.y` free above and below it for the
// title and the zoom, their width `text.x` centred over it: the largest (up to 40% of the
// area's height, at least 120 pixels) in a corner of `area` that keeps 12 pixels off the
// convex hull of `avoid` (the cube's corners on screen) and meets none of `keepOff` (the
// legend, the slide's boxes), the upper right corner first at each size. None where none
// fits.
std::optional<PixelBox> placeCubeInset(PixelBox area, std::span<const glm::dvec2> avoid,
                                       std::span<const PixelBox> keepOff, glm::dvec2 text);

// where an inset's leader to `target` leaves its frame: the middle of the frame's side that
// faces the target (the leader then crosses the page, not the inset's own text)
glm::dvec2 insetLeaderStart(const PixelBox& frame, glm::dvec2 target);

// The inset in window pixels (points (x, y, 0), t upward): the frame's background and
// border, the cells meeting the patch tinted by the faces they list and outlined, the title
// centred `textRoom` / 2 over the frame (`twoLines`: its two lines, the last there), the
// zoom as far under it (labels at their text's middle), and a dashed leader from the frame to
// `anchor` (the patch on screen) when given, ringed there and the face named beyond the ring
// (the last label).
void drawCubeInset(const CubeInset& inset, std::span<const Cell3D> cells, const Palette& palette,
                   PixelBox frame, double textRoom, std::optional<glm::dvec2> anchor, DrawList& out,
                   bool twoLines = false);

}  // namespace convexloc::viewer
