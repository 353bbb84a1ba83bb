// convexloc-viewer — the degenerate gallery.
#include "logic/scene/presets.hpp"

#include "convexloc/generate2d.hpp"

namespace convexloc::viewer {
namespace {

constexpr Preset kPresets[] = {
    {"sliver", "Sliver",
     "A needle 10^9 times longer than wide: the centre must still lie strictly inside.", false,
     std::nullopt},
    {"tiny-edges", "Tiny edges",
     "Three long edges and a corner of edges 10^10 times shorter: one polar cell lists them all.",
     false, std::nullopt},
    {"large-offset", "Large offset",
     "A unit polygon at (10^9, -10^9): doubles have only ~10^-7 of room there, predicates stay "
     "exact.",
     false, std::nullopt},
    {"collinear-duplicate", "Collinear & duplicate",
     "A square given with repeated corners and extra points on its sides: normalisation drops "
     "them.",
     false, std::nullopt},
    {"thin-slab", "Thin slab",
     "Two vertices 10^-12 apart in y: a slab that thin, and uniform slabs listing extra edges.",
     false, Method2D::Uniform},
    {"small-gap", "Small y-gap",
     "Two vertices 0.05 apart in y: the paper's uniform slabs must be that thin (Fig. 5).",
     false, Method2D::Uniform},
    {"tiny-faces", "Tiny faces",
     "A cube with one corner rounded by a cap of tiny triangles (areas 10^10 apart): the "
     "cube map refines its cells there as a quadtree.",
     true, std::nullopt},
    {"coplanar-faces", "Coplanar faces",
     "A cube whose sides are split into grids of coplanar squares: valid, and every cell "
     "lists the pieces it meets.",
     true, std::nullopt},
};

}  // namespace

std::span<const Preset> presets() {
  return kPresets;
}

const Preset* findPreset(std::string_view name) {
  for (const Preset& p : kPresets)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<Vec2> presetPolygon(std::string_view name) {
  if (name == "sliver") return generatePolygon(PolygonKind::Sliver, 48, 1);
  if (name == "tiny-edges") return generatePolygon(PolygonKind::TinyEdges, 24, 1);
  if (name == "large-offset") return generatePolygon(PolygonKind::Offset, 12, 3);
  if (name == "collinear-duplicate") return generatePolygon(PolygonKind::Degenerate, 16, 1);
  if (name == "thin-slab")
    return {{0.0, -1.0}, {1.8, -0.4},         {2.2, 0.5},  {1.2, 1.4},
            {-1.0, 1.3}, {-2.0, 0.5 + 1e-12}, {-1.5, -0.5}};
  if (name == "small-gap")
    return {{0.0, -1.0}, {1.8, -0.4},         {2.2, 0.5},  {1.2, 1.4},
            {-1.0, 1.3}, {-2.0, 0.5 + 0.05}, {-1.5, -0.5}};
  return {};
}

}  // namespace convexloc::viewer
