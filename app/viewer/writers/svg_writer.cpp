// convexloc-viewer — the SVG writer.
#include "writers/svg_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "logic/base/format.hpp"
#include "writers/svg_slide.hpp"

namespace convexloc::viewer {
namespace {

using svg::num;
using svg::paint;

// one element of the picture and the depth it is sorted by (3D)
struct Item {
  double depth = 0.0;
  std::string svg;
};

// the parts of the picture, in the renderer's order
struct Parts {
  std::vector<Item> fills, lowPoints, segments, highPoints, markers;
};

// the screen points of a triangle or polygon, or nothing when a corner is behind the eye
bool projectAll(const ScreenProjection& project, std::span<const glm::dvec3> world,
                std::vector<glm::dvec3>& out) {
  out.clear();
  for (const glm::dvec3& w : world) {
    const std::optional<glm::dvec3> s = project(w);
    if (!s) return false;
    out.push_back(*s);
  }
  return true;
}

// true when the screen points' box misses the viewport grown by `margin`
bool offScreen(std::span<const glm::dvec3> pts, glm::dvec2 size, double margin) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : pts) {
    lo = glm::min(lo, glm::dvec2(p));
    hi = glm::max(hi, glm::dvec2(p));
  }
  return hi.x < -margin || hi.y < -margin || lo.x > size.x + margin || lo.y > size.y + margin;
}

// the mean depth of screen points
double meanDepth(std::span<const glm::dvec3> pts) {
  double d = 0.0;
  for (const glm::dvec3& p : pts) d += p.z;
  return pts.empty() ? 0.0 : d / static_cast<double>(pts.size());
}

// "x,y x,y ..." for a polygon's points attribute
std::string pointList(std::span<const glm::dvec3> pts) {
  std::string s;
  for (const glm::dvec3& p : pts) {
    if (!s.empty()) s += ' ';
    s += num(p.x);
    s += ',';
    s += num(p.y);
  }
  return s;
}

// a fill's colour, lit by the headlight like the fill shader does
Rgba litColour(const FillVertex& v, const std::optional<glm::dvec3>& eye, glm::dvec3 middle) {
  Rgba c = v.colour;
  if (!eye || glm::dot(v.normal, v.normal) <= 0.0f) return c;
  const glm::dvec3 toEye = *eye - middle;
  const double len = glm::length(toEye);
  const double facing =
      len > 0.0 ? std::abs(glm::dot(glm::normalize(glm::dvec3(v.normal)), toEye / len)) : 1.0;
  const auto k = static_cast<float>(0.45 + 0.55 * facing);
  return {c.r * k, c.g * k, c.b * k, c.a};
}

// Triangle fans of one colour (the draw lists' convex outlines) joined back into one
// polygon each: triangle t continues the fan when it shares the first corner and the
// previous triangle's last edge.
void addFills(const SvgScene& s, const DrawList& list, std::vector<Item>& out) {
  const auto& f = list.fills;
  std::vector<glm::dvec3> world, screen;
  for (std::size_t t = 0; t + 2 < f.size();) {
    world = {f[t].p, f[t + 1].p, f[t + 2].p};
    std::size_t next = t + 3;
    while (next + 2 < f.size() && f[next].p == f[t].p && f[next + 1].p == world.back() &&
           f[next].colour == f[t].colour && f[next].normal == f[t].normal) {
      world.push_back(f[next + 2].p);
      next += 3;
    }
    glm::dvec3 middle(0.0);
    for (const glm::dvec3& w : world) middle += w / static_cast<double>(world.size());
    if (projectAll(s.project, world, screen) && !offScreen(screen, s.size, 2.0))
      out.push_back({meanDepth(screen), "<polygon points=\"" + pointList(screen) + "\"" +
                                            paint("fill", litColour(f[t], s.eye, middle)) + "/>"});
    t = next;
  }
}

// Cuts the screen segment to the viewport grown by `m` (Liang-Barsky); false when it misses.
bool clipToView(glm::dvec2& a, glm::dvec2& b, glm::dvec2 size, double m) {
  double t0 = 0.0, t1 = 1.0;
  if (!clipSegment(a, b, glm::dvec2(-m), size + m, t0, t1)) return false;
  const glm::dvec2 d = b - a;
  const glm::dvec2 a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

void addSegments(const SvgScene& s, const DrawList& list, std::vector<Item>& out) {
  for (const Segment& g : list.segments) {
    const std::optional<glm::dvec3> a = s.project(g.a), b = s.project(g.b);
    if (!a || !b) continue;
    glm::dvec2 p(*a), q(*b);
    if (!clipToView(p, q, s.size, 10.0)) continue;
    std::string e = "<line x1=\"" + num(p.x) + "\" y1=\"" + num(p.y) + "\" x2=\"" + num(q.x) +
                    "\" y2=\"" + num(q.y) + "\"" + paint("stroke", g.colour) + " stroke-width=\"" +
                    num(g.width * s.scale) + "\"";
    if (g.dash > 0.0f) e += " stroke-dasharray=\"" + num(g.dash * s.scale) + "\"";
    out.push_back({0.5 * (a->z + b->z), e + "/>"});
  }
}

// a marker of each shape, as the marker shader draws it: a disc of the marker's diameter,
// a ring inside its rim, the ring crossed, a square
std::string markerSvg(glm::dvec2 c, double size, const Marker& m) {
  const double r = std::max(0.5 * size, 0.5);
  const std::string at = " cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\"";
  const std::string ring = "<circle" + at + " r=\"" + num(std::max(r - 1.0, 0.5)) + "\"";
  switch (m.shape) {
    case MarkerShape::Disc:
      return "<circle" + at + " r=\"" + num(r) + "\"" + paint("fill", m.colour) + "/>";
    case MarkerShape::Ring:
      return ring + " fill=\"none\"" + paint("stroke", m.colour) + " stroke-width=\"2\"/>";
    case MarkerShape::Cross: {
      const double b = std::max(r - 2.0, 0.5);
      return "<g" + paint("stroke", m.colour) + " fill=\"none\" stroke-width=\"2\">" + ring +
             "/><path d=\"M" + num(c.x - b) + " " + num(c.y) + "H" + num(c.x + b) + "M" + num(c.x) +
             " " + num(c.y - b) + "V" + num(c.y + b) + "\"/></g>";
    }
    case MarkerShape::Square: break;
  }
  return "<rect x=\"" + num(c.x - r) + "\" y=\"" + num(c.y - r) + "\" width=\"" + num(2 * r) +
         "\" height=\"" + num(2 * r) + "\"" + paint("fill", m.colour) + "/>";
}

void addMarkers(const SvgScene& s, const DrawList& list, std::vector<Item>& out) {
  for (const Marker& m : list.markers) {
    const std::optional<glm::dvec3> p = s.project(m.p);
    if (!p || offScreen(std::span(&*p, 1), s.size, m.size * s.scale)) continue;
    out.push_back({p->z, markerSvg(glm::dvec2(*p), m.size * s.scale, m)});
  }
}

// every k-th visible point, so that at most maxPoints are written; the stride k
std::size_t addPoints(const SvgScene& s, Parts& parts, std::size_t& visible) {
  const SvgPoints& sp = s.points;
  const std::size_t n = std::min(sp.points.size(), sp.classes.size());
  visible = 0;
  for (std::size_t i = 0; i < n; ++i)
    visible += (sp.visibleMask >> static_cast<unsigned>(sp.classes[i])) & 1u;
  const std::size_t stride =
      std::max<std::size_t>(1, (visible + s.maxPoints - 1) / std::max<std::size_t>(s.maxPoints, 1));
  // fewer points are drawn larger (up to the size of a light spray's), so that the thinned
  // spray still reads as the classes' areas
  const double size =
      std::min(sp.size * std::sqrt(static_cast<double>(stride)), std::max<double>(sp.size, 3.5));
  std::size_t seen = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned>(sp.classes[i]);
    if (!((sp.visibleMask >> c) & 1u) || seen++ % stride != 0) continue;
    const std::optional<glm::dvec3> p = s.project(sp.points[i]);
    if (!p || offScreen(std::span(&*p, 1), s.size, 4.0)) continue;
    const bool boundary = sp.classes[i] == Location::Boundary;
    const double r = 0.5 * size * (boundary ? 1.7 : 1.0);
    std::string e = "<circle cx=\"" + num(p->x) + "\" cy=\"" + num(p->y) + "\" r=\"" + num(r) +
                    "\"" + paint("fill", sp.colours[c]);
    if (boundary) e += paint("stroke", sp.rim) + " stroke-width=\"1\"";
    (boundary || sp.overLines ? parts.highPoints : parts.lowPoints).push_back({p->z, e + "/>"});
  }
  return stride;
}

// the items in the order written: 2D in the renderer's layer order; 3D back to front
void writeItems(std::string& out, std::vector<Item> items, bool sorted) {
  if (sorted)
    std::stable_sort(items.begin(), items.end(),
                     [](const Item& a, const Item& b) { return a.depth > b.depth; });
  for (const Item& i : items) out += "  " + i.svg + "\n";
}

// the base layers (fills, points, segments, markers) and the overlay over them
void writeScene(const SvgScene& s, std::string& out, std::size_t& visible, std::size_t& stride) {
  Parts base;
  for (const DrawList* l : s.base) {
    addFills(s, *l, base.fills);
    addSegments(s, *l, base.segments);
    addMarkers(s, *l, base.markers);
  }
  stride = addPoints(s, base, visible);
  out += "<g id=\"scene\" stroke-linecap=\"butt\">\n";
  if (s.depthSorted) {
    std::vector<Item> all = std::move(base.fills);
    for (auto* part : {&base.lowPoints, &base.segments, &base.highPoints})
      all.insert(all.end(), part->begin(), part->end());
    writeItems(out, std::move(all), true);
  } else {
    for (auto* part : {&base.fills, &base.lowPoints, &base.segments, &base.highPoints})
      writeItems(out, std::move(*part), false);
  }
  writeItems(out, std::move(base.markers), false);
  Parts over;
  for (const DrawList* l : s.overlay) {
    addFills(s, *l, over.fills);
    addSegments(s, *l, over.segments);
    addMarkers(s, *l, over.markers);
  }
  for (auto* part : {&over.fills, &over.segments, &over.markers})
    writeItems(out, std::move(*part), false);
  out += "</g>\n";
}

// core's cells and the shape's edges, unpainted, for selecting in an editor
void writeOutlines(const SvgScene& s, std::string& out) {
  std::vector<glm::dvec3> screen;
  out += "<g id=\"cells\" fill=\"none\" stroke=\"none\">\n";
  for (std::size_t k = 0; k < s.cells.size(); ++k)
    if (projectAll(s.project, s.cells[k], screen))
      out += "  <polygon class=\"cell\" data-cell=\"" + std::to_string(k) + "\" points=\"" +
             pointList(screen) + "\"/>\n";
  out += "</g>\n<g id=\"edges\" fill=\"none\" stroke=\"none\">\n";
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    const auto a = s.project(s.edges[e].first), b = s.project(s.edges[e].second);
    if (!a || !b) continue;
    out += "  <line class=\"edge\" data-edge=\"" + std::to_string(e) + "\" x1=\"" + num(a->x) +
           "\" y1=\"" + num(a->y) + "\" x2=\"" + num(b->x) + "\" y2=\"" + num(b->y) + "\"/>\n";
  }
  out += "</g>\n";
}

// `text` centred at `c` as the window centres it (its box's top left rounded), with a halo of
// the background behind it
std::string textSvg(const SvgScene& s, glm::dvec2 c, std::string_view text, Rgba colour,
                    const char* cls = "label") {
  const glm::dvec2 at = imguiBaseline(glm::round(c - 0.5 * s.measure(text)), s.fontPixels);
  return "<text class=\"" + std::string(cls) + "\" x=\"" + num(at.x) + "\" y=\"" + num(at.y) +
         "\"" + paint("fill", colour) + ">" + wordsSvg(at.x, 1.0, std::string(text), s) + "</text>";
}

void writeLabels(const SvgScene& s, std::string& out) {
  std::vector<const DrawList*> lists = s.base;
  lists.insert(lists.end(), s.overlay.begin(), s.overlay.end());
  const auto placed =
      layoutSceneLabels(lists, s.base.size(), s.project,
                        s.labelArea.empty() ? PixelBox{{0.0, 0.0}, s.size} : s.labelArea, s.measure,
                        s.scale, 400, s.keepOff);
  out += "<g id=\"labels\" font-family=\"DejaVu Sans, Verdana, sans-serif\" font-size=\"" +
         num(s.fontPixels) + "\"" + paint("stroke", withAlpha(s.background, 0.85f)) +
         " stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\">\n";
  for (const PlacedSceneLabel& p : placed) {
    if (p.place.leader)
      out += "  <line x1=\"" + num(p.anchor.x) + "\" y1=\"" + num(p.anchor.y) + "\" x2=\"" +
             num(p.place.centre.x) + "\" y2=\"" + num(p.place.centre.y) + "\"" +
             paint("stroke", withAlpha(p.label->colour, 0.6f)) + " stroke-width=\"1\"/>\n";
    out += "  " +
           textSvg(s, p.place.centre, p.label->text,
                   readableOn(p.label->colour, s.background, s.text)) +
           "\n";
  }
  out += "</g>\n";
}

// the thinning note along the bottom
void writeNote(const SvgScene& s, std::string& out, std::size_t visible, std::size_t stride) {
  if (stride <= 1) return;
  const std::string note = "spray thinned for the SVG: 1 point in " + std::to_string(stride) +
                           " of " + grouped(visible) + " drawn";
  out += "<!-- " + note + " -->\n<text class=\"note\" x=\"10\" y=\"" + num(s.size.y - 10.0) +
         "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"" + num(0.8 * s.fontPixels) +
         "\"" + paint("fill", withAlpha(s.text, 0.75f)) + ">" + xmlEscape(note) + "</text>\n";
}

// a rectangle as a clip path `id`
std::string clipSvg(const char* id, const ScreenRect& r) {
  return "<clipPath id=\"" + std::string(id) + "\"><rect x=\"" + num(r.lo.x) + "\" y=\"" +
         num(r.lo.y) + "\" width=\"" + num(r.size().x) + "\" height=\"" + num(r.size().y) +
         "\"/></clipPath>\n";
}

// the split view: each half clipped to its rectangle (the right one through its own
// projection and lists), the divider, the headings over the labels
void writeSplit(const SvgScene& s, std::string& out, std::size_t& visible, std::size_t& stride) {
  const SvgSplit& split = *s.split;
  out += "<defs>\n" + clipSvg("left-half", split.left) + clipSvg("right-half", split.right) +
         "</defs>\n<g id=\"left-half\" clip-path=\"url(#left-half)\">\n";
  SvgScene left = s;
  left.labelArea = {split.left.lo, split.left.hi};
  writeScene(left, out, visible, stride);
  writeLabels(left, out);
  out += "</g>\n<g id=\"right-half\" clip-path=\"url(#right-half)\">\n";
  SvgScene right = s;
  right.project = split.project;
  right.base = split.base;
  right.overlay = split.overlay;
  right.labelArea = {split.right.lo, split.right.hi};
  writeScene(right, out, visible, stride);
  writeLabels(right, out);
  // the right half's left edge, or (halves one over the other) the lower half's top
  const bool stacked = split.right.lo.x == split.left.lo.x;
  const glm::dvec2 to = stacked ? glm::dvec2(split.right.hi.x, split.right.lo.y)
                                : glm::dvec2(split.right.lo.x, split.right.hi.y);
  out += "</g>\n<line id=\"divider\" x1=\"" + num(split.right.lo.x) + "\" y1=\"" +
         num(split.right.lo.y) + "\" x2=\"" + num(to.x) + "\" y2=\"" + num(to.y) + "\"" +
         paint("stroke", s.textMuted) + " stroke-width=\"2\"/>\n";
  for (const TextBox& t : split.headings) {
    if (t.lines.empty()) continue;
    const double em = s.fontPixels * t.scale;
    const double pad = 0.6 * 1.164 * em;
    out += "<g class=\"heading\"><rect x=\"" + num(t.box.lo.x) + "\" y=\"" + num(t.box.lo.y) +
           "\" width=\"" + num(t.box.size().x) + "\" height=\"" + num(t.box.size().y) +
           "\" rx=\"4\"" + paint("fill", withAlpha(s.background, 0.9f)) + "/><text x=\"" +
           num(t.box.lo.x + pad) + "\" y=\"" + num(t.box.lo.y + 0.5 * pad + 0.928 * em) +
           "\" font-family=\"DejaVu Sans, Verdana, sans-serif\" font-size=\"" + num(em) + "\"" +
           paint("fill", s.text) + ">" + xmlEscape(t.lines[0]) + "</text></g>\n";
  }
}

}  // namespace

std::string sceneSvg(const SvgScene& s) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(s.size.x) + "\" height=\"" +
         num(s.size.y) + "\" viewBox=\"0 0 " + num(s.size.x) + " " + num(s.size.y) + "\">\n";
  out += "<!-- convexloc-viewer: the scene as drawn, in window pixels -->\n";
  out += "<rect id=\"background\" width=\"100%\" height=\"100%\"" + paint("fill", s.background) +
         "/>\n";
  if (!s.plotsSvg.empty()) return out + plotsSlideSvg(s);
  writeOutlines(s, out);
  std::size_t visible = 0, stride = 1;
  if (s.split) {
    writeSplit(s, out, visible, stride);
  } else {
    writeScene(s, out, visible, stride);
    writeLabels(s, out);
  }
  writeNote(s, out, visible, stride);
  writeLetterbox(s, out);
  // over the bars: the cube map's inset may sit beside the figure's room
  for (const DrawList* l : s.screen) writeScreenList(s, *l, out);
  writeSlideBoxes(s, out);
  if (s.legend) writeLegend(s, out);
  out += "</svg>\n";
  return out;
}

bool writeTextFile(const std::string& path, const std::string& text, std::string& error) {
  std::ofstream f(path, std::ios::binary);
  if (f) f << text;
  if (!f || !f.flush()) {
    error = path + ": cannot be written (" + std::strerror(errno) + ")";
    return false;
  }
  return true;
}

}  // namespace convexloc::viewer
