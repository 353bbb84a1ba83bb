// convexloc-viewer — the degenerate gallery: shapes that break naive implementations,
// one click each. Their vertices come from core's generators where core has the kind.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate2d.hpp"

namespace convexloc::viewer {

struct Preset {
  std::string_view name;           // for --preset
  std::string_view title;          // for the button
  std::string_view about;          // one sentence: what it shows
  bool solid = false;              // a polyhedron (3D) rather than a polygon
  std::optional<Method2D> method;  // the method that shows it best, if it matters
};

// every preset, 2D first
std::span<const Preset> presets();
// the preset with that name
const Preset* findPreset(std::string_view name);
// the input vertices of a 2D preset (before core's normalisation); empty for a 3D one
std::vector<Vec2> presetPolygon(std::string_view name);

}  // namespace convexloc::viewer
