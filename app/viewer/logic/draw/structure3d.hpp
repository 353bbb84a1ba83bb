// convexloc-viewer — what the 3D scene draws, from what core reports: the polyhedron's
// triangles and edges, the cube map's cells on the six faces of the drawing cube (tinted by
// the faces they list), the slicing plane with the section core classifies on it, and the
// overlay: cell pyramids, the faces a cell lists, the placed point's trace.
#pragma once

#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/scene/scene3d.hpp"

namespace convexloc::viewer {

struct View3DOptions {
  bool showMesh = true;
  bool transparent = true;  // the polyhedron's faces see-through
  bool wireframe = true;    // its triangle edges
  bool showCube = true;     // the cube map's grid on the cube's six faces
  bool showTints = true;    // cells listing extra faces tinted apart
  bool showSlice = true;    // the slicing plane and its section
  bool showLabels = true;
  unsigned faceNames = 0x3fu;  // the cube faces named (bit f: face f; a slide names few)
};

// above this many faces the wireframe and the cube grid thin out (drawing only)
inline constexpr std::size_t kMaxWireframeFaces = 200000;
inline constexpr std::size_t kMaxGridCells = 60000;

// the polyhedron's faces (lit), in the mesh layer
void buildMesh3D(const Scene3D& scene, const Palette& palette, const View3DOptions& options,
                 DrawList& out);
// Edges, the cube and its cells, the centre, the slicing plane and its section. Cells are
// drawn on the cube faces in `farFaces` (bit f for cube face f): those the eye sees from
// inside, behind the polyhedron; the other faces show their grid only faintly, untinted.
void buildStructure3D(const Scene3D& scene, const Palette& palette, const View3DOptions& options,
                      unsigned farFaces, DrawList& out);

// the 12 edges of the cube of half-side `half` around `centre` (the cube a cube map's cells
// are drawn on)
void cubeEdges(glm::dvec3 centre, double half, Rgba colour, float width, DrawList& out);
// the section of `polyhedron` on the section's plane as one straight-sided polygon in the
// inside colour, and the samples core found exactly on the boundary as squares (the slicing
// plane's, and the Planes mode's)
void buildSection(const ConvexPolyhedron& polyhedron, const Section& section,
                  const Palette& palette, DrawList& out);

// the cube faces (bit f for +x, -x, +y, -y, +z, -z) whose plane has `eye` on its inner side
unsigned farCubeFaces(const Scene3D& scene, glm::dvec3 eye);
// hovered and pinned cells, the probe and its trace
void buildOverlay3D(const Scene3D& scene, const Palette& palette, const View3DOptions& options,
                    DrawList& out);

}  // namespace convexloc::viewer
