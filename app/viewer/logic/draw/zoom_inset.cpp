// convexloc-viewer — the zoom inset.
#include "logic/draw/zoom_inset.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "convexloc/format.hpp"
#include "logic/draw/cube_inset.hpp"

namespace convexloc::viewer {
namespace {

// an edge shorter than this fraction of the box's diagonal is too short to see
constexpr double kTinyEdge = 1e-4;
// the frame's side as a fraction of the polygon box's height, and its gap to the box
constexpr double kFrameShare = 0.5;
constexpr double kFrameGap = 0.08;

double lengthOf(Vec2 a, Vec2 b) {
  return std::hypot(b.x - a.x, b.y - a.y);
}

// the part of the segment a-b inside `box` (Liang and Barsky over t in [0, 1])
bool clipSegment(Vec2 a, Vec2 b, const Box2& box, Vec2& p, Vec2& q) {
  double t0 = 0.0, t1 = 1.0;
  const double d[2] = {b.x - a.x, b.y - a.y};
  const double lo[2] = {box.lo.x - a.x, box.lo.y - a.y}, hi[2] = {box.hi.x - a.x, box.hi.y - a.y};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (lo[k] > 0.0 || hi[k] < 0.0) return false;
      continue;
    }
    double ta = lo[k] / d[k], tb = hi[k] / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return false;
  p = {a.x + t0 * d[0], a.y + t0 * d[1]};
  q = {a.x + t1 * d[0], a.y + t1 * d[1]};
  return true;
}

bool inBox(const Box2& b, Vec2 p) {
  return b.lo.x <= p.x && p.x <= b.hi.x && b.lo.y <= p.y && p.y <= b.hi.y;
}

}  // namespace

std::optional<ZoomInset> tinyEdgesInset(const ConvexPolygon& polygon) {
  const Box2 box = polygon.bounds();
  const double diagonal = lengthOf(box.lo, box.hi), height = box.hi.y - box.lo.y;
  if (!(diagonal > 0.0) || !(height > 0.0)) return std::nullopt;
  // the box of every tiny edge's ends
  Box2 tiny{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
  for (std::size_t e = 0; e < polygon.size(); ++e) {
    const Vec2 a = polygon.edgeStart(e), b = polygon.edgeEnd(e);
    if (lengthOf(a, b) >= kTinyEdge * diagonal) continue;
    for (const Vec2 p : {a, b}) {
      tiny.lo = {std::min(tiny.lo.x, p.x), std::min(tiny.lo.y, p.y)};
      tiny.hi = {std::max(tiny.hi.x, p.x), std::max(tiny.hi.y, p.y)};
    }
  }
  if (!(tiny.lo.x <= tiny.hi.x)) return std::nullopt;
  // a square around them, a fifth wider, magnified by a power of ten to about the share
  const double side = 1.2 * std::max(tiny.hi.x - tiny.lo.x, tiny.hi.y - tiny.lo.y);
  if (!(side > 0.0)) return std::nullopt;
  ZoomInset inset;
  // 1, 2 or 5 times a power of ten: the frame between 40% and 100% of the share
  const double wanted = kFrameShare * height / side;
  inset.exponent = static_cast<int>(std::floor(std::log10(wanted)));
  const double decade = std::pow(10.0, inset.exponent);
  inset.mantissa = wanted >= 5.0 * decade ? 5 : wanted >= 2.0 * decade ? 2 : 1;
  inset.magnification = inset.mantissa * decade;
  const Vec2 mid{0.5 * (tiny.lo.x + tiny.hi.x), 0.5 * (tiny.lo.y + tiny.hi.y)};
  inset.source = {{mid.x - 0.5 * side, mid.y - 0.5 * side},
                  {mid.x + 0.5 * side, mid.y + 0.5 * side}};
  // at the box's corner next to the tiny edges, outside the box on their side
  const double frame = side * inset.magnification, gap = kFrameGap * height;
  const double x = mid.x > 0.5 * (box.lo.x + box.hi.x) ? box.hi.x + gap : box.lo.x - gap - frame;
  const double y = mid.y > 0.5 * (box.lo.y + box.hi.y) ? box.hi.y - frame : box.lo.y;
  inset.frame = {{x, y}, {x + frame, y + frame}};
  return inset;
}

glm::dvec3 zoomLeaderEnd(const ZoomInset& inset) {
  const Box2& f = inset.frame;
  const double cx = 0.5 * (inset.source.lo.x + inset.source.hi.x);
  return {cx < f.lo.x ? f.lo.x : f.hi.x, 0.5 * (f.lo.y + f.hi.y), 0.0};
}

std::string magnificationText(const ZoomInset& inset) {
  std::string text = "\u00D7";
  if (inset.mantissa != 1) text += std::to_string(inset.mantissa) + "\u00B7";
  return text + "10^" + std::to_string(inset.exponent);
}

Vec2 insetPoint(const ZoomInset& inset, Vec2 p) {
  const double m = inset.magnification;
  return {inset.frame.lo.x + (p.x - inset.source.lo.x) * m,
          inset.frame.lo.y + (p.y - inset.source.lo.y) * m};
}

void drawZoomInset(const ConvexPolygon& polygon, const ZoomInset& inset, const Palette& pal,
                   DrawList& out) {
  const Box2& f = inset.frame;
  const glm::dvec3 c00{f.lo.x, f.lo.y, 0.0}, c10{f.hi.x, f.lo.y, 0.0}, c11{f.hi.x, f.hi.y, 0.0},
      c01{f.lo.x, f.hi.y, 0.0};
  out.triangle(c00, c10, c11, pal.background);
  out.triangle(c00, c11, c01, pal.background);
  for (const auto& [a, b] : {std::pair{c00, c10}, {c10, c11}, {c11, c01}, {c01, c00}})
    out.segment(a, b, pal.textMuted, 1.25f);
  for (std::size_t e = 0; e < polygon.size(); ++e) {
    Vec2 p, q;
    if (!clipSegment(polygon.edgeStart(e), polygon.edgeEnd(e), inset.source, p, q)) continue;
    const Vec2 a = insetPoint(inset, p), b = insetPoint(inset, q);
    out.segment({a.x, a.y, 0.0}, {b.x, b.y, 0.0}, pal.polygonEdge, 2.25f);
  }
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (inBox(inset.source, polygon.vertex(i))) {
      const Vec2 v = insetPoint(inset, polygon.vertex(i));
      out.marker({v.x, v.y, 0.0}, pal.polygonEdge, 6.0f, MarkerShape::Disc);
    }
  // where the inset looks (a few pixels wide at the polygon's scale), and a leader from it to
  // the middle of the frame's side that faces it (off the polygon's edges)
  const Vec2 s{0.5 * (inset.source.lo.x + inset.source.hi.x),
               0.5 * (inset.source.lo.y + inset.source.hi.y)};
  out.marker({s.x, s.y, 0.0}, pal.textMuted, 18.0f, MarkerShape::Ring);
  out.segment({s.x, s.y, 0.0}, zoomLeaderEnd(inset), withAlpha(pal.textMuted, 0.7f), 1.25f, 6.0f);
  out.label({0.5 * (f.lo.x + f.hi.x), f.hi.y, 0.0}, "zoom " + magnificationText(inset), pal.text,
            {0.0f, -14.0f});
}

void drawZoomInsetOnScreen(const ConvexPolygon& polygon, const ZoomInset& inset, const Palette& pal,
                           PixelBox frame, double textRoom,
                           const std::function<std::optional<glm::dvec2>(Vec2)>& project,
                           DrawList& out) {
  const Box2& src = inset.source;
  const double k = (frame.hi.x - frame.lo.x) / (src.hi.x - src.lo.x);
  // a world point of the source in the frame, y downward
  const auto at = [&](Vec2 p) {
    return glm::dvec3(frame.lo.x + (p.x - src.lo.x) * k, frame.hi.y - (p.y - src.lo.y) * k, 0.0);
  };
  const glm::dvec3 c00{frame.lo, 0.0}, c10{frame.hi.x, frame.lo.y, 0.0}, c11{frame.hi, 0.0},
      c01{frame.lo.x, frame.hi.y, 0.0};
  out.triangle(c00, c10, c11, pal.background);
  out.triangle(c00, c11, c01, pal.background);
  for (std::size_t e = 0; e < polygon.size(); ++e) {
    Vec2 p, q;
    if (clipSegment(polygon.edgeStart(e), polygon.edgeEnd(e), src, p, q))
      out.segment(at(p), at(q), pal.polygonEdge, 2.25f);
  }
  // the vertices as small discs (markers are world-drawn: these are short crosses of fills)
  const double r = std::max(2.0, std::min(0.18 * textRoom, 0.02 * (frame.hi.x - frame.lo.x)));
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (inBox(src, polygon.vertex(i))) {
      const glm::dvec3 v = at(polygon.vertex(i));
      for (int a = 0; a < 8; ++a) {
        const double u = a * 0.7853981633974483, w = (a + 1) * 0.7853981633974483;
        out.triangle(v, v + r * glm::dvec3(std::cos(u), std::sin(u), 0.0),
                     v + r * glm::dvec3(std::cos(w), std::sin(w), 0.0), pal.polygonEdge);
      }
    }
  for (const auto& [a, b] : {std::pair{c00, c10}, {c10, c11}, {c11, c01}, {c01, c00}})
    out.segment(a, b, pal.textMuted, 1.5f);
  out.label({0.5 * (frame.lo.x + frame.hi.x), frame.lo.y - 0.5 * textRoom, 0.0},
            "zoom " + magnificationText(inset), pal.text);
  const std::optional<glm::dvec2> s =
      project({0.5 * (src.lo.x + src.hi.x), 0.5 * (src.lo.y + src.hi.y)});
  if (!s) return;
  // the leader: from the middle of the frame's side facing the source to a ring around it
  // (across the page, never along one of the polygon's edges through the source)
  const double ring = 0.6 * textRoom;
  const glm::dvec2 from = insetLeaderStart(frame, *s), d = *s - from;
  const double length = glm::length(d);
  const glm::dvec3 a(*s, 0.0);
  if (length > ring)
    out.segment(glm::dvec3(from, 0.0), a - ring * glm::dvec3(d / length, 0.0),
                withAlpha(pal.text, 0.8f), 1.5f, 6.0f);
  for (int e = 0; e < 12; ++e) {
    const double u = e * 0.5235987755982988, v = (e + 1) * 0.5235987755982988;
    out.segment(a + ring * glm::dvec3(std::cos(u), std::sin(u), 0.0),
                a + ring * glm::dvec3(std::cos(v), std::sin(v), 0.0), pal.text, 1.5f);
  }
}

std::optional<std::string> offsetNote(const ConvexPolygon& polygon) {
  const Box2 box = polygon.bounds();
  const double size = lengthOf(box.lo, box.hi);
  const double far =
      std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.hi.x), std::abs(box.hi.y)});
  if (!(size > 0.0) || !(far > 1e6 * size) || polygon.size() == 0) return std::nullopt;
  const int power = static_cast<int>(std::lround(std::log10(far)));
  return "at 10^" + std::to_string(power) + " from the origin: vertex 0 is " +
         exactText(polygon.vertex(0)) + ", exactly";
}

void drawOffsetNote(const ConvexPolygon& polygon, const std::string& note, const Palette& pal,
                    DrawList& out) {
  const Box2 box = polygon.bounds();
  const Vec2 v = polygon.vertex(0);
  out.marker({v.x, v.y, 0.0}, pal.text, 14.0f, MarkerShape::Ring);
  if (note.empty()) return;
  out.label({0.5 * (box.lo.x + box.hi.x), box.hi.y, 0.0}, note, pal.text, {0.0f, -30.0f});
  out.labels.back().essential = true;  // the shape's point: never left out for a vertex number
}

void drawDegenerateInsets(const ConvexPolygon& polygon, const Palette& pal, DrawList& out,
                          bool zoom) {
  if (const auto inset = tinyEdgesInset(polygon); inset && zoom)
    drawZoomInset(polygon, *inset, pal, out);
  if (const auto note = offsetNote(polygon)) drawOffsetNote(polygon, zoom ? *note : "", pal, out);
}

}  // namespace convexloc::viewer
