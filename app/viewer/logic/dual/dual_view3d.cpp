// convexloc-viewer — the Planes mode's draw lists.
#include "logic/dual/dual_view3d.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "logic/draw/cube_cells.hpp"
#include "logic/draw/structure3d.hpp"

namespace convexloc::viewer {
namespace {

// above this many dual faces their edges would whiten the small dual view: faces only
constexpr std::size_t kMaxDualEdgeFaces = 4000;

// the colour of an exact sign
Rgba signOf(const Palette& p, int sign) {
  return sign > 0 ? p.positive : (sign < 0 ? p.negative : p.zero);
}

// dual face f of the cube map's surface, mapped into the dual view, lit
void dualFace(const CubemapLocator& cube, const DualPlace3D& at, std::uint32_t f, Rgba c,
              DrawList& out) {
  const auto v = cube.vertices();
  const auto& t = cube.faces()[f];
  const glm::dvec3 a = at.toWorld(v[t[0]]), b = at.toWorld(v[t[1]]), d = at.toWorld(v[t[2]]);
  const glm::dvec3 n = glm::cross(b - a, d - a);
  const double len = glm::length(n);
  const glm::vec3 normal = len > 0.0 ? glm::vec3(n / len) : glm::vec3(0.0f, 0.0f, 1.0f);
  out.fills.push_back({a, c, normal});
  out.fills.push_back({b, c, normal});
  out.fills.push_back({d, c, normal});
}

// the dual polyhedron: faces see-through, edges once each, the cube its cells lie on
void dualSolid(const CubemapLocator& cube, const DualPlace3D& at, const Palette& pal,
               DrawList& out) {
  const auto v = cube.vertices();
  const auto faces = cube.faces();
  for (std::uint32_t f = 0; f < faces.size(); ++f) dualFace(cube, at, f, pal.meshFill, out);
  if (faces.size() <= kMaxDualEdgeFaces)
    for (const auto& t : faces)
      for (int k = 0; k < 3; ++k)
        if (t[k] < t[(k + 1) % 3])  // each edge once: it runs up in one of its two faces
          out.segment(at.toWorld(v[t[k]]), at.toWorld(v[t[(k + 1) % 3]]), pal.meshEdge, 1.0f);
  const auto c = cube.centre();
  if (!c) return;
  cubeEdges(at.toWorld(*c), at.scale * cube.cubeHalfSize(), withAlpha(pal.cube, 0.5f), 1.0f, out);
}

// a cell of the dual's cube map: its square, its pyramid from c*, the dual faces it lists
void dualCell(const CubemapLocator& cube, const DualPlace3D& at, const Cell3D& cell,
              const std::vector<std::uint32_t>& listed, Rgba colour, DrawList& out) {
  CubeCellPlace place;
  for (std::size_t i = 0; i < 4; ++i) place.corners[i] = at.toWorld(cell.corners[i]);
  place.apex = at.toWorld(cell.apex);
  fillCubeCell(place, withAlpha(colour, 0.35f), out);
  cubeCellPyramid(place, colour, 2.0f, 1.25f, out);
  const auto v = cube.vertices();
  for (const std::uint32_t f : listed) {
    if (f >= cube.faces().size()) continue;
    dualFace(cube, at, f, withAlpha(colour, 0.7f), out);
    const auto& t = cube.faces()[f];
    for (int i = 0; i < 3; ++i)
      out.segment(at.toWorld(v[t[i]]), at.toWorld(v[t[(i + 1) % 3]]), colour, 3.0f);
  }
}

// the plane's patch and, where it meets the polyhedron, the section core classifies on it
void planePatch(const Planes3D& planes, const PlaneProbe3D& p, const Palette& pal, DrawList& out) {
  const auto& patch = p.patch;
  for (std::size_t i = 0; i < patch.size(); ++i)
    out.segment(patch[i], patch[(i + 1) % patch.size()], pal.box, 1.25f, 6.0f);
  for (std::size_t i = 1; i + 1 < patch.size(); ++i)
    out.triangle(patch[0], patch[i], patch[i + 1], pal.slicePlane);
  if (p.dual.crossing != Crossing::Misses && planes.polyhedron())
    buildSection(*planes.polyhedron(), p.section, pal, out);
}

// the direction y and -y in the dual view, the ray from c* through y
void dualPoints(const Planes3D& planes, const Palette& pal, bool labels, DrawList& out) {
  const PlaneProbe3D& p = *planes.plane();
  const CubemapLocator* cube = planes.dualIntersector()->dualLocator();
  if (!cube || !p.dual.proposed) return;
  const DualPlace3D& at = planes.place();
  const Vec3 y = p.dual.direction, down{-y.x, -y.y, -y.z};
  if (const auto c = cube->centre()) {
    out.segment(at.toWorld(*c), at.toWorld(y), pal.text, 1.25f, 5.0f);
    out.marker(at.toWorld(*c), pal.centre, 9.0f, MarkerShape::Cross);
  }
  out.marker(at.toWorld(y), pal.rim, 14.0f);
  out.marker(at.toWorld(y), pal.text, 10.0f);
  out.marker(at.toWorld(down), pal.text, 10.0f, MarkerShape::Ring);
  if (!labels) return;
  out.label(at.toWorld(y), "b = y", pal.text, {-30.0f, 12.0f});
  out.label(at.toWorld(down), "-y", pal.text, {16.0f, 10.0f});
}

// the three points, the extremes (by sign), the vertices the dual cells proposed
void primalMarks(const Planes3D& planes, const ConvexPolyhedron& poly, const Palette& pal,
                 bool labels, DrawList& out) {
  const PlaneProbe3D& p = *planes.plane();
  const auto v = poly.vertices();
  const PlaneTrace& t = p.chosen(planes.method());
  // the vertices the listed dual faces stand for, the proposals ringed larger
  const auto lab = planes.dualIntersector()->dualLabels();
  for (const auto* listed : {&p.listedUp, &p.listedDown})
    for (const std::uint32_t f : *listed)
      if (f < lab.size() && lab[f] < v.size())
        out.marker(toGlm(v[lab[f]]), pal.hoverEdge, 9.0f, MarkerShape::Ring);
  if (p.dual.proposed && p.dual.startMax < v.size() && p.dual.startMin < v.size()) {
    out.marker(toGlm(v[p.dual.startMax]), pal.hoverEdge, 24.0f, MarkerShape::Ring);
    out.marker(toGlm(v[p.dual.startMin]), pal.hoverEdge, 24.0f, MarkerShape::Ring);
  }
  const ExtremeVertices& x = t.extremes;
  if (x.largest < v.size() && x.smallest < v.size()) {
    out.marker(toGlm(v[x.largest]), signOf(pal, x.largestSign), 13.0f);
    out.marker(toGlm(v[x.smallest]), signOf(pal, x.smallestSign), 13.0f);
    if (labels) {
      out.label(toGlm(v[x.largest]), "max G" + signText(x.largestSign), signOf(pal, x.largestSign),
                {0.0f, -26.0f});
      out.label(toGlm(v[x.smallest]), "min G" + signText(x.smallestSign),
                signOf(pal, x.smallestSign), {0.0f, 26.0f});
    }
  }
  const char* names[3] = {"q1", "q2", "q3"};
  for (int i = 0; i < 3; ++i) {
    out.marker(toGlm(p.q[static_cast<std::size_t>(i)]), pal.text, 9.0f, MarkerShape::Ring);
    if (labels)
      out.label(toGlm(p.q[static_cast<std::size_t>(i)]), names[i], pal.textMuted, {-14.0f, -12.0f});
  }
}

// the two views' names, and the answer as a caption above the polyhedron
void captions(const Planes3D& planes, const Palette& pal, DrawList& out) {
  glm::dvec3 primalTop = planes.centre();
  primalTop.z = planes.box().hi.z;
  out.label(planes.dualCorner(), "dual P*", pal.text, {36.0f, -12.0f});
  const auto& p = planes.plane();
  if (!p) return out.label(primalTop, "primal P", pal.text, {0.0f, -40.0f});
  const Crossing c = p->chosen(planes.method()).crossing;
  out.label(primalTop, "primal P: the plane " + std::string(toString(c)), crossingColour(pal, c),
            {0.0f, -40.0f});
}

}  // namespace

Rgba crossingColour(const Palette& pal, Crossing c) {
  return c == Crossing::Crosses ? pal.inside
                                : (c == Crossing::Touches ? pal.boundary : pal.outside);
}

void buildPlanes3D(const Planes3D& planes, const Palette& pal, bool labels, DrawList& solid,
                   DrawList& overlay) {
  const PlaneIntersector* dual = planes.dualIntersector();
  if (!planes.enabled() || !dual) return;
  const CubemapLocator* cube = dual->dualLocator();
  const DualPlace3D& at = planes.place();
  if (cube) dualSolid(*cube, at, pal, solid);
  if (labels) captions(planes, pal, overlay);
  const auto& p = planes.plane();
  if (!p) return;
  planePatch(planes, *p, pal, solid);
  const auto& cells = planes.dualCells();
  if (cube && p->cellDown >= 0 && static_cast<std::size_t>(p->cellDown) < cells.size())
    dualCell(*cube, at, cells[static_cast<std::size_t>(p->cellDown)], p->listedDown,
             withAlpha(pal.hoverEdge, 0.6f), solid);
  if (cube && p->cellUp >= 0 && static_cast<std::size_t>(p->cellUp) < cells.size())
    dualCell(*cube, at, cells[static_cast<std::size_t>(p->cellUp)], p->listedUp, pal.hoverEdge,
             solid);
  dualPoints(planes, pal, labels, overlay);
  primalMarks(planes, *planes.polyhedron(), pal, labels, overlay);
}

}  // namespace convexloc::viewer
