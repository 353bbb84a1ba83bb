// convexloc-viewer — the build, animated: a method's cells receiving their edges one edge
// at a time, in edge order. Every count comes from the edge lists core's cells() reports;
// at step k the edges 0 .. k-1 are in, edge k-1 (the one just added) flashes in the cells
// that list it, each cell's tint grows with the edges it holds, and a cell holding more
// than kCrowdedCell edges is marked crowded as it fills. In 3D the same with the faces the
// cube-map cells list. GL-free.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"

namespace convexloc::viewer {

class Scene2D;
class Scene3D;

// the cells each edge (face) is listed in, read once from core's cells
class BuildOrder {
 public:
  // `edgeCount` edges; every cell's edges must be below it
  BuildOrder(std::span<const Cell2D> cells, std::size_t edgeCount)
      : BuildOrder(cells, edgeCount, &Cell2D::edges) {}
  // `faceCount` faces of the cube map's cells
  BuildOrder(std::span<const Cell3D> cells, std::size_t faceCount)
      : BuildOrder(cells, faceCount, &Cell3D::faces) {}
  // the number of steps: one per edge
  std::size_t steps() const { return cellsOfEdge_.size(); }
  // the positions (in the cells given) of the cells listing edge e
  const std::vector<std::size_t>& cellsOf(std::size_t e) const { return cellsOfEdge_[e]; }
  // per cell, how many of its edges have an index below k (k <= steps())
  std::vector<std::size_t> countsAt(std::size_t k) const;

 private:
  template <class Cell>
  BuildOrder(std::span<const Cell> cells, std::size_t count, std::vector<std::uint32_t> Cell::*list)
      : cellsOfEdge_(count), cellCount_(cells.size()) {
    for (std::size_t c = 0; c < cells.size(); ++c)
      for (const std::uint32_t e : cells[c].*list)
        if (e < count) cellsOfEdge_[e].push_back(c);
  }
  std::vector<std::vector<std::size_t>> cellsOfEdge_;
  std::size_t cellCount_ = 0;
};

// the animation's state: on or off, the step shown, playing or paused
struct BuildPlayback {
  bool active = false;
  bool playing = false;
  std::size_t step = 0;         // edges added so far
  double edgesPerSecond = 3.0;  // playing speed
  double carry = 0.0;           // the part of a step the clock has run
  std::uint64_t version = 0;    // grows with every change drawn

  // shows step k (clamped to `steps`) and pauses
  void show(std::size_t k, std::size_t steps);
  // moves on by `seconds` of play; stops at the last step
  void advance(double seconds, std::size_t steps);
};

// Draws step `step` of the scene's build: tints, the flashing cells and edge, crowded marks
// and the label "edge k of N". Nothing for a method without cells.
void buildAnimation2D(const Scene2D& scene, std::size_t step, const Palette& palette,
                      DrawList& out);
// Draws step `step` of the cube map's build: tints on the far cube faces (`farFaces`, a bit
// per cube face), the cells listing the face just added outlined, that face filled, crowded
// cells crossed, the label "fK added: k of F faces". Nothing without cells.
void buildAnimation3D(const Scene3D& scene, std::size_t step, unsigned farFaces,
                      const Palette& palette, DrawList& out);
// Adds a build step's drawing to the structure's: its fills, lines and marks drawn over the
// structure, its labels placed first ("e8 added" wins its spot before the vertex numbers,
// which are placed in order and would crowd it out).
void appendBuildStep(DrawList& structure, const DrawList& step);
// the build animation's steps for a scene: its edges or faces, or 0 when its method has no cells
std::size_t buildStepCount(const Scene2D& scene);
std::size_t buildStepCount(const Scene3D& scene);

}  // namespace convexloc::viewer
