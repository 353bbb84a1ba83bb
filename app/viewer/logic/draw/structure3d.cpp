// convexloc-viewer — the 3D draw lists.
#include "logic/draw/structure3d.hpp"

#include <algorithm>
#include <string>

#include "logic/base/format.hpp"
#include "logic/draw/cube_cells.hpp"
#include "logic/draw/section_polygon.hpp"
#include "logic/narration/steps.hpp"

namespace convexloc::viewer {
namespace {

using Tri = ConvexPolyhedron::Triangle;

glm::dvec3 vertexOf(const ConvexPolyhedron& p, std::uint32_t i) {
  return toGlm(p.vertices()[i]);
}

// the unit normal of a triangle, for shading (drawing only)
glm::vec3 normalOf(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  return len > 0.0 ? glm::vec3(n / len) : glm::vec3(0.0f, 0.0f, 1.0f);
}

// plane face f (all its triangles) filled in colour c, lit or flat
void fillFace(const ConvexPolyhedron& p, std::uint32_t f, Rgba c, bool lit, DrawList& out) {
  for (std::uint32_t tri : p.planeTriangles(f)) {
    const Tri& t = p.triangles()[tri];
    const glm::dvec3 a = vertexOf(p, t[0]), b = vertexOf(p, t[1]), d = vertexOf(p, t[2]);
    const glm::vec3 n = lit ? normalOf(a, b, d) : glm::vec3(0.0f);
    out.fills.push_back({a, c, n});
    out.fills.push_back({b, c, n});
    out.fills.push_back({d, c, n});
  }
}

// plane face f's outline
void strokeFace(const ConvexPolyhedron& p, std::uint32_t f, Rgba c, float width, DrawList& out) {
  const auto loop = p.planeLoop(f);
  for (std::size_t k = 0; k < loop.size(); ++k)
    out.segment(vertexOf(p, loop[k]), vertexOf(p, loop[(k + 1) % loop.size()]), c, width);
}

// the middle of plane face f: the mean of its corners
glm::dvec3 faceMiddle(const ConvexPolyhedron& p, std::uint32_t f) {
  const auto loop = p.planeLoop(f);
  glm::dvec3 sum(0.0);
  for (std::uint32_t w : loop) sum += vertexOf(p, w);
  return sum / static_cast<double>(loop.size());
}

// a cell's square on the drawing cube, filled
void fillCell(const Cell3D& c, Rgba colour, DrawList& out) {
  fillCubeCell(placeOf(c), colour, out);
}

// a cell's pyramid from the centre: its square and the four edges to the apex
void pyramid(const Cell3D& c, Rgba colour, float width, DrawList& out) {
  cubeCellPyramid(placeOf(c), colour, width + 0.75f, width, out);
}

Rgba signColour(const Palette& p, int sign) {
  return sign > 0 ? p.positive : (sign < 0 ? p.negative : p.zero);
}

// === The query step by step: each step up to the current one drawn, the current one bold

// the square of cube face f on the drawing cube around the centre, outlined
void cubeFaceSquare(const Scene3D& scene, int f, Rgba colour, float width, DrawList& out) {
  const auto c = scene.centre();
  if (!c || f < 0 || f > 5) return;
  const int axis = f / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double h = scene.cubeHalfSize();
  glm::dvec3 n(0.0), du(0.0), dv(0.0);
  n[axis] = f % 2 ? -h : h;
  du[u] = h;
  dv[v] = h;
  const glm::dvec3 m = toGlm(*c) + n;
  const glm::dvec3 q[4] = {m - du - dv, m + du - dv, m + du + dv, m - du + dv};
  for (int k = 0; k < 4; ++k) out.segment(q[k], q[(k + 1) % 4], colour, width);
}

// the radii along the ray from the centre: inside up to r_in, undecided up to r_out
void radiiOnRay(const Trace3D& t, const Palette& pal, bool current, DrawList& out) {
  if (!t.centre || t.distance <= 0.0) return;
  const glm::dvec3 c = toGlm(*t.centre), dir = toGlm(t.direction) / t.distance;
  const float w = current ? 4.0f : 2.0f;
  out.segment(c, c + t.innerRadius * dir, withAlpha(pal.positive, current ? 1.0f : 0.5f), w);
  out.segment(c + t.innerRadius * dir, c + t.outerRadius * dir,
              withAlpha(pal.zero, current ? 1.0f : 0.5f), w);
  out.marker(c + t.innerRadius * dir, pal.positive, 9.0f, MarkerShape::Ring);
  out.marker(c + t.outerRadius * dir, pal.negative, 9.0f, MarkerShape::Ring);
}

// a face tested (a plane test or a walk's edge test), by its sign
void stepFace(const ConvexPolyhedron& p, const Step& s, const Palette& pal, bool current,
              bool labels, DrawList& out) {
  // a walk step names a triangle, a plane test a plane face
  const bool walk = s.focus == StepFocus::Walk;
  if (s.item < 0 || static_cast<std::size_t>(s.item) >= (walk ? p.faceCount() : p.planeCount()))
    return;
  const auto f =
      walk ? p.planeOf()[static_cast<std::size_t>(s.item)] : static_cast<std::uint32_t>(s.item);
  const Rgba c =
      s.focus == StepFocus::Walk && s.sign <= 0 ? pal.structureStrong : signColour(pal, s.sign);
  fillFace(p, f, withAlpha(c, current ? 0.6f : 0.25f), false, out);
  if (current) strokeFace(p, f, c, 2.5f, out);
  if (current && labels) out.label(faceMiddle(p, f), numbered("f", f) + signText(s.sign), c);
}

// one step's drawing
void drawStep3D(const Scene3D& scene, const Trace3D& t, const Step& s, const Palette& pal,
                bool current, bool labels, DrawList& out) {
  const Rgba hi = withAlpha(pal.hoverEdge, current ? 1.0f : 0.45f);
  switch (s.focus) {
    case StepFocus::Octant: cubeFaceSquare(scene, static_cast<int>(s.item), hi, 2.5f, out); break;
    case StepFocus::Cell:
      if (const std::ptrdiff_t k = scene.probeCell(); k >= 0)
        pyramid(scene.cells()[static_cast<std::size_t>(k)], hi, current ? 2.0f : 1.0f, out);
      break;
    case StepFocus::Radii: radiiOnRay(t, pal, current, out); break;
    case StepFocus::Walk:
    case StepFocus::Face: stepFace(scene.polyhedron(), s, pal, current, labels, out); break;
    default: break;
  }
}

// the placed point's steps up to `step`, the point and the ray from the centre
void probeSteps3D(const Scene3D& scene, const Probe3D& probe, const Palette& pal,
                  const View3DOptions& opt, DrawList& out) {
  const Trace3D& t = probe.trace;
  const Bounds3 b = scene.bounds();
  const StepModel m = buildSteps3D(t, probe.point, glm::length(b.hi - b.lo));
  const int k = clampStep(scene.step(), m.steps.size());
  const glm::dvec3 x = toGlm(probe.point);
  if (t.centre) out.segment(toGlm(*t.centre), x, pal.text, 1.25f, 5.0f);
  for (int j = 0; j <= k; ++j)
    drawStep3D(scene, t, m.steps[static_cast<std::size_t>(j)], pal, j == k, opt.showLabels, out);
  const bool done = m.steps[static_cast<std::size_t>(k)].focus == StepFocus::Result;
  out.marker(x, pal.rim, 17.0f, MarkerShape::Disc);
  out.marker(x, done ? colourOf(pal, t.result) : pal.text, 13.0f, MarkerShape::Disc);
  if (opt.showLabels)
    out.label(x, done ? std::string(toString(t.result)) : "x",
              done ? textColourOf(pal, t.result) : pal.text, {12.0f, 12.0f});
}

}  // namespace

void buildMesh3D(const Scene3D& scene, const Palette& pal, const View3DOptions& opt,
                 DrawList& out) {
  out.clear();
  if (!opt.showMesh) return;
  const ConvexPolyhedron& p = scene.polyhedron();
  const Rgba c = withAlpha(pal.meshFill, opt.transparent ? pal.meshFill.a : 1.0f);
  out.fills.reserve(3 * p.faceCount());
  for (std::uint32_t f = 0; f < p.planeCount(); ++f) fillFace(p, f, c, true, out);
}

unsigned farCubeFaces(const Scene3D& scene, glm::dvec3 eye) {
  const auto c = scene.centre();
  const double h = scene.cubeHalfSize();
  if (!c || !(h > 0.0)) return 0;
  const glm::dvec3 d = eye - toGlm(*c);
  unsigned mask = 0;
  for (int a = 0; a < 3; ++a) {
    if (d[a] < h) mask |= 1u << (2 * a);       // inside the + face's plane
    if (d[a] > -h) mask |= 1u << (2 * a + 1);  // inside the - face's plane
  }
  return mask;
}

void buildStructure3D(const Scene3D& scene, const Palette& pal, const View3DOptions& opt,
                      unsigned farFaces, DrawList& out) {
  out.clear();
  const ConvexPolyhedron& p = scene.polyhedron();
  const auto& cells = scene.cells();

  // the plane faces' edges, each once (the neighbour across it has the higher index); the
  // diagonals inside a plane face are left out
  if (opt.wireframe && p.faceCount() <= kMaxWireframeFaces) {
    const auto tris = p.triangles();
    const auto nbs = p.neighbours();
    const auto plane = p.planeOf();
    for (std::uint32_t f = 0; f < tris.size(); ++f)
      for (int k = 0; k < 3; ++k)
        if (nbs[f][k] > f && plane[nbs[f][k]] != plane[f])
          out.segment(vertexOf(p, tris[f][k]), vertexOf(p, tris[f][(k + 1) % 3]), pal.meshEdge,
                      1.0f);
  }

  // the cube map: tinted cells and the grid on the far faces, the cube's outline
  if (opt.showCube && !cells.empty()) {
    if (opt.showTints)
      for (const Cell3D& c : cells) {
        if (!(farFaces >> c.cubeFace & 1u)) continue;
        const bool crowded = c.faces.size() > kCrowdedCell3D;
        if (c.faces.size() > kBaseFacesPerCell || crowded)
          fillCell(c, cellTint(pal, c.faces.size(), kBaseFacesPerCell, crowded), out);
      }
    // the near faces' grid only faintly, so that it does not veil the polyhedron
    const Rgba faint = withAlpha(pal.cube, 0.16f);
    if (cells.size() <= kMaxGridCells)
      for (const Cell3D& c : cells) {
        const Rgba colour = (farFaces >> c.cubeFace & 1u) ? pal.cube : faint;
        outlineCubeCell(placeOf(c), colour, 1.0f, out);
      }
    const glm::dvec3 ctr = toGlm(*scene.centre());
    const double h = scene.cubeHalfSize();
    cubeEdges(ctr, h, pal.cube, 1.25f, out);
    // the cube faces' names
    if (opt.showLabels) {
      for (int f = 0; f < 6; ++f) {
        if (!(opt.faceNames >> f & 1u)) continue;
        glm::dvec3 q = ctr;
        q[f / 2] += (f % 2 ? -1.0 : 1.0) * h * 1.12;
        out.label(q, std::string(kCubeFaceNames[f]), pal.textMuted);
      }
    }
  }

  // the centre
  if (auto c = scene.centre(); c && scene.method() != Method3D::Halfspace) {
    out.marker(toGlm(*c), pal.centre, 11.0f, MarkerShape::Cross);
    if (opt.showLabels) out.label(toGlm(*c), "x_T", pal.text, {16.0f, -14.0f});
  }

  // the slicing plane and the section core classifies on it
  if (opt.showSlice) {
    const auto r = scene.sliceRectangle();
    for (int k = 0; k < 4; ++k) out.segment(r[k], r[(k + 1) % 4], pal.box, 1.25f, 6.0f);
    out.triangle(r[0], r[1], r[2], pal.slicePlane);
    out.triangle(r[0], r[2], r[3], pal.slicePlane);
    buildSection(scene.polyhedron(), scene.section(), pal, out);
  }
}

void cubeEdges(glm::dvec3 ctr, double h, Rgba colour, float width, DrawList& out) {
  for (int e = 0; e < 12; ++e) {
    // the 12 edges: along axis e / 4, at the other two axes' signs from e % 4
    const int a = e / 4, u = (a + 1) % 3, v = (a + 2) % 3;
    glm::dvec3 from = ctr, to = ctr;
    from[a] -= h;
    to[a] += h;
    from[u] = to[u] = ctr[u] + (e & 1 ? h : -h);
    from[v] = to[v] = ctr[v] + (e & 2 ? h : -h);
    out.segment(from, to, colour, width);
  }
}

void buildSection(const ConvexPolyhedron& p, const Section& s, const Palette& pal, DrawList& out) {
  // the inside as one polygon with straight sides, outlined
  const std::vector<glm::dvec3> section = sectionPolygon(p, s.corner, s.du, s.dv);
  const Rgba inside = withAlpha(colourOf(pal, Location::Inside), 0.6f);
  for (std::size_t i = 1; i + 1 < section.size(); ++i)
    out.triangle(section[0], section[i], section[i + 1], inside);
  for (std::size_t i = 0; i < section.size(); ++i)
    out.segment(section[i], section[(i + 1) % section.size()], colourOf(pal, Location::Inside),
                2.0f);
  // the samples core put exactly on the boundary, as squares in its colour
  const Rgba boundary = withAlpha(colourOf(pal, Location::Boundary), 0.95f);
  for (std::uint32_t j = 0; j < s.n; ++j)
    for (std::uint32_t i = 0; i < s.n; ++i) {
      if (s.classes[static_cast<std::size_t>(j) * s.n + i] != Location::Boundary) continue;
      const glm::dvec3 a = s.corner + static_cast<double>(i) * s.du + static_cast<double>(j) * s.dv;
      out.triangle(a, a + s.du, a + s.du + s.dv, boundary);
      out.triangle(a, a + s.du + s.dv, a + s.dv, boundary);
    }
}

void buildOverlay3D(const Scene3D& scene, const Palette& pal, const View3DOptions& opt,
                    DrawList& out) {
  out.clear();
  const ConvexPolyhedron& p = scene.polyhedron();
  const auto& cells = scene.cells();

  // the pinned and the hovered cell: the pyramid and the faces the cell lists
  auto showCell = [&](std::ptrdiff_t k, Rgba colour) {
    if (k < 0 || k >= static_cast<std::ptrdiff_t>(cells.size())) return;
    const Cell3D& c = cells[static_cast<std::size_t>(k)];
    fillCell(c, withAlpha(colour, 0.25f), out);
    pyramid(c, colour, 1.5f, out);
    for (std::uint32_t f : c.faces) {
      fillFace(p, f, withAlpha(colour, 0.55f), false, out);
      strokeFace(p, f, colour, 2.0f, out);
    }
    if (opt.showLabels && c.faces.size() <= 12)
      for (std::uint32_t f : c.faces) out.label(faceMiddle(p, f), numbered("f", f), colour);
  };
  showCell(scene.pinnedCell(), pal.crowded);
  if (scene.secondPinnedCell() != scene.pinnedCell())
    showCell(scene.secondPinnedCell(), pal.inside);
  if (scene.hoveredCell() != scene.pinnedCell() && scene.hoveredCell() != scene.secondPinnedCell())
    showCell(scene.hoveredCell(), pal.hoverEdge);

  if (const auto& probe = scene.probe(); probe && scene.step() >= 0) {
    probeSteps3D(scene, *probe, pal, opt, out);  // the query step by step
  } else if (probe) {
    const Trace3D& t = probe->trace;
    const glm::dvec3 x = toGlm(probe->point);
    const Rgba rc = colourOf(pal, t.result);
    // the cube map's cell: its pyramid, and the ray from the centre through the point
    const std::ptrdiff_t k = scene.probeCell();
    if (k >= 0) pyramid(cells[static_cast<std::size_t>(k)], rc, 1.75f, out);
    if (t.byRadius) radiiOnRay(t, pal, true, out);  // the radii, where they decided
    if (t.centre) out.segment(toGlm(*t.centre), x, pal.text, 1.25f, 5.0f);
    // the walk's path, face after face
    for (std::size_t i = 0; i < t.path.size(); ++i) {
      fillFace(p, t.path[i], withAlpha(pal.structureStrong, 0.35f), false, out);
      if (opt.showLabels && t.path.size() <= 40)
        out.label(faceMiddle(p, t.path[i]), std::to_string(i + 1), pal.text);
    }
    // the planes tested, coloured by the sign
    const bool few = t.faces.size() <= 64;
    for (const FaceTest& f : t.faces) {
      if (f.face >= p.planeCount()) continue;
      if (few || f.sign <= 0) {
        fillFace(p, f.face, withAlpha(signColour(pal, f.sign), 0.35f), false, out);
        strokeFace(p, f.face, signColour(pal, f.sign), 2.0f, out);
      }
    }
    out.marker(x, pal.rim, 17.0f, MarkerShape::Disc);
    out.marker(x, rc, 13.0f, MarkerShape::Disc);
    if (opt.showLabels)
      out.label(x, std::string(toString(t.result)), textColourOf(pal, t.result), {12.0f, 12.0f});
  }
}

}  // namespace convexloc::viewer
