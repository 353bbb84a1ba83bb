// convexloc-viewer — what the 2D scene draws, built from what core reports: the polygon,
// each method's cells (their outlines, the polar rays' box exits, the edges they list),
// the centre, the box, the placed point's trace, the hovered cell, a dragged vertex.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/draw/clip2d.hpp"
#include "logic/scene/scene2d.hpp"

namespace convexloc::viewer {

// what the structure layer shows
struct View2DOptions {
  bool showStructure = true;  // the method's cells (rays, slabs, fan, edge lines)
  bool showTints = true;      // cells listing extra edges tinted apart
  bool showBox = true;        // the bounding box
  bool showOctants = true;    // polar: the eight octant lines through the centre
  bool showLabels = true;     // vertex, octant and edge numbers where they fit
  bool showHandles = true;    // vertex handles (drag to edit)
  bool showCentre = true;     // the method's centre x_T (off in the Lines mode)
  bool showGap = false;       // the smallest y-gap marked, with the paper's slab count
  // tiny edges' zoom inset beside the polygon in world units (a slide draws it in the
  // corner its layout keeps for it instead)
  bool zoomInset = true;
};

// limits above which the drawing thins out (the scene stays exact, only less is drawn)
inline constexpr std::size_t kMaxLabelledVertices = 40;
inline constexpr std::size_t kMaxHandles = 400;
inline constexpr std::size_t kMaxCellLines = 40000;
inline constexpr std::size_t kMaxFilledVertices = 1 << 16;

// the static layer: rebuilt when the shape, the method or the palette changes
void buildStructure2D(const Scene2D& scene, const Palette& palette, const View2DOptions& options,
                      DrawList& out);

// the overlay: hover, the placed point's trace, a drag; rebuilt when those change
void buildOverlay2D(const Scene2D& scene, const Palette& palette, const View2DOptions& options,
                    DrawList& out);

// the position in scene.cells() of the cell whose index is `index`, or -1

std::ptrdiff_t cellPosition(const Scene2D& scene, std::int64_t index);

}  // namespace convexloc::viewer
