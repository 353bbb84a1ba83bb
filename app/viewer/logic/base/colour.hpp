// convexloc-viewer — colours: the palette of each theme, the colour of a class, the tint
// of a cell. GL-free; the renderer only uploads what these functions return.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "convexloc/geometry.hpp"

namespace convexloc::viewer {

// a colour with straight (not premultiplied) alpha, each channel in [0, 1]
struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

// the same colour with alpha `a`
constexpr Rgba withAlpha(Rgba c, float a) {
  return {c.r, c.g, c.b, a};
}
// a colour from 0xRRGGBB and an alpha
constexpr Rgba hex(std::uint32_t rgb, float a = 1.0f) {
  return {static_cast<float>((rgb >> 16) & 0xff) / 255.0f,
          static_cast<float>((rgb >> 8) & 0xff) / 255.0f, static_cast<float>(rgb & 0xff) / 255.0f,
          a};
}
// linear interpolation between two colours, t in [0, 1]
Rgba mix(Rgba a, Rgba b, float t);

enum class Theme : std::uint8_t { Dark, Light };
// "dark" or "light"
std::string_view toString(Theme t);

// Every colour the scene uses. The class colours follow Okabe and Ito's palette, which
// stays distinguishable for the common forms of colour blindness: inside blue, outside
// orange (vermillion on dark), boundary bright yellow (drawn larger and with a dark rim).
struct Palette {
  Rgba background;
  Rgba text, textMuted;
  Rgba polygonEdge, polygonFill;
  Rgba box, octant, structure, structureStrong;
  Rgba centre;
  Rgba inside, boundary, outside, rim;
  Rgba extraEdges;  // cells listing more edges than the method's minimum
  Rgba crowded;     // cells searched by bisection
  Rgba hoverFill, hoverOutline, hoverEdge;
  Rgba positive, zero, negative;  // signs of the predicates in a trace
  Rgba handle, handleError;       // vertex handles; the handle of a rejected drag
  Rgba meshFill, meshEdge;        // 3D: the polyhedron
  Rgba cube, slicePlane;          // 3D: the cube around the centre, the slicing plane
};

// the palette of a theme
const Palette& paletteFor(Theme t);

// the colour of a class
Rgba colourOf(const Palette& p, Location l);
// the colour of a class for text: the boundary's yellow darkened on a light background
Rgba textColourOf(const Palette& p, Location l);

// the WCAG contrast ratio of two opaque colours, 1 (same luminance) .. 21 (black on white)
float contrastRatio(Rgba a, Rgba b);
// `c` for text on `background`: mixed toward `toward` (the theme's text colour) just enough
// that its contrast ratio reaches `ratio`, so that the light theme's yellow labels turn a
// readable dark gold while its markers keep the legend's yellow; `c` itself where it already
// reads
Rgba readableOn(Rgba c, Rgba background, Rgba toward, float ratio = 4.0f);

// How a cell listing `edges` edges is tinted, where `base` is the fewest edges a cell of
// the method lists (1 for polar and wedge cells, 2 for slabs): transparent at or below the
// base, then the extra-edges colour growing stronger with each extra edge, and the crowded
// colour for cells searched by bisection.
Rgba cellTint(const Palette& p, std::size_t edges, std::size_t base, bool crowded);

// 0xAABBGGRR, the byte order ImGui's draw lists take
std::uint32_t packAbgr(Rgba c);

}  // namespace convexloc::viewer
