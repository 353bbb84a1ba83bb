// convexloc-viewer — the cube map's zoom inset.
#include "logic/draw/cube_inset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "logic/scene/scene3d.hpp"

namespace convexloc::viewer {
namespace {

// a leaf at most this fraction of a base cell wide is too small to see: the inset shows it
constexpr double kRefinedShare = 1.0 / 16.0;
// the patch is this many smallest leaves wide at the least
constexpr double kLeavesAcross = 16.0;

double sideOf(const Cell3D& c) {
  return c.s1 - c.s0;
}

bool overlaps(const PixelBox& a, const PixelBox& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

// Whether the box keeps `gap` off the convex hull of `points`: some axis (x, y, or normal to
// the line through two of the points, which includes the hull's edges) parts them by it.
bool keepsOff(const PixelBox& box, std::span<const glm::dvec2> points, double gap) {
  if (points.empty()) return true;
  const glm::dvec2 corners[4] = {box.lo, {box.hi.x, box.lo.y}, box.hi, {box.lo.x, box.hi.y}};
  const auto parted = [&](glm::dvec2 axis) {
    const double length = glm::length(axis);
    if (!(length > 0.0)) return false;
    axis /= length;
    double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
    for (const glm::dvec2& c : corners)
      a0 = std::min(a0, glm::dot(c, axis)), a1 = std::max(a1, glm::dot(c, axis));
    for (const glm::dvec2& p : points)
      b0 = std::min(b0, glm::dot(p, axis)), b1 = std::max(b1, glm::dot(p, axis));
    return a1 + gap <= b0 || b1 + gap <= a0;
  };
  if (parted({1.0, 0.0}) || parted({0.0, 1.0})) return true;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const glm::dvec2 d = points[j] - points[i];
      if (parted({-d.y, d.x})) return true;
    }
  return false;
}

// "1", "-0.5", "0.9999": a coordinate in few digits
std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v == 0.0 ? 0.0 : v);
  return text;
}

}  // namespace

double CubeInset::magnification() const {
  return mantissa * std::pow(10.0, exponent);
}

std::optional<CubeInset> cubeMapInset(std::span<const Cell3D> cells) {
  if (cells.empty()) return std::nullopt;
  CubeInset inset;
  inset.baseSide = sideOf(cells.front()) * std::ldexp(1.0, cells.front().level);
  const auto smallest =
      std::min_element(cells.begin(), cells.end(),
                       [](const Cell3D& a, const Cell3D& b) { return sideOf(a) < sideOf(b); });
  inset.smallestSide = sideOf(*smallest);
  if (!(inset.smallestSide > 0.0) || inset.smallestSide > kRefinedShare * inset.baseSide)
    return std::nullopt;
  inset.cubeFace = smallest->cubeFace;
  // the box of the smallest leaves on that face
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  for (const Cell3D& c : cells) {
    if (c.cubeFace != inset.cubeFace || sideOf(c) != inset.smallestSide) continue;
    lo = glm::min(lo, glm::dvec2(c.s0, c.t0));
    hi = glm::max(hi, glm::dvec2(c.s1, c.t1));
  }
  // a cube face's side (2) over 1, 2 or 5 times a power of ten: the patch at least as wide
  // as the leaves' box and kLeavesAcross leaves
  const double wanted = std::max({kLeavesAcross * inset.smallestSide, hi.x - lo.x, hi.y - lo.y});
  const double ratio = std::max(2.0 / wanted, 1.0);
  inset.exponent = static_cast<int>(std::floor(std::log10(ratio)));
  const double decade = std::pow(10.0, inset.exponent);
  inset.mantissa = ratio >= 5.0 * decade ? 5 : ratio >= 2.0 * decade ? 2 : 1;
  inset.side = 2.0 / inset.magnification();
  const glm::dvec2 middle = 0.5 * (lo + hi);
  inset.lo = glm::clamp(middle - 0.5 * inset.side, glm::dvec2(-1.0), glm::dvec2(1.0 - inset.side));
  const glm::dvec2 top = inset.lo + inset.side;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const Cell3D& c = cells[k];
    if (c.cubeFace == inset.cubeFace && c.s0 < top.x && c.s1 > inset.lo.x && c.t0 < top.y &&
        c.t1 > inset.lo.y)
      inset.cells.push_back(k);
  }
  return inset;
}

std::string cubeInsetTitle(const CubeInset& inset) {
  const glm::dvec2 m = inset.lo + 0.5 * inset.side;
  return "cube face " + std::string(kCubeFaceNames[static_cast<std::size_t>(inset.cubeFace)]) +
         " near (s,t) = (" + shortNumber(m.x) + ", " + shortNumber(m.y) + ")";
}

std::vector<std::string> cubeInsetTitleLines(const CubeInset& inset) {
  const std::string title = cubeInsetTitle(inset);
  const std::size_t near = title.find(" near ");
  return {title.substr(0, near), title.substr(near + 1)};
}

std::string cubeInsetZoomText(const CubeInset& inset) {
  std::string text = "zoom \u00D7";
  if (inset.mantissa != 1) text += std::to_string(inset.mantissa) + "\u00B7";
  return text + "10^" + std::to_string(inset.exponent);
}

glm::dvec3 cubeInsetAnchor(const CubeInset& inset, std::span<const Cell3D> cells) {
  // the widest cell on the face: (s, t) maps affinely onto its square's plane
  const Cell3D* wide = nullptr;
  for (const Cell3D& c : cells)
    if (c.cubeFace == inset.cubeFace && (!wide || sideOf(c) > sideOf(*wide))) wide = &c;
  if (!wide) return glm::dvec3(0.0);
  const glm::dvec3 c0 = toGlm(wide->corners[0]), c1 = toGlm(wide->corners[1]),
                   c3 = toGlm(wide->corners[3]);
  const glm::dvec2 m = inset.lo + 0.5 * inset.side;
  return c0 + (m.x - wide->s0) / (wide->s1 - wide->s0) * (c1 - c0) +
         (m.y - wide->t0) / (wide->t1 - wide->t0) * (c3 - c0);
}

std::optional<PixelBox> placeCubeInset(PixelBox area, std::span<const glm::dvec2> avoid,
                                       std::span<const PixelBox> keepOff, glm::dvec2 text) {
  constexpr double kMargin = 12.0, kMin = 120.0;
  const double height = area.hi.y - area.lo.y;
  for (double side = 0.4 * height; side >= kMin; side *= 0.95)
    for (int corner = 0; corner < 4; ++corner) {
      // upper right, upper left, lower right, lower left: the frame with its text's room
      const bool right = corner % 2 == 0, upper = corner < 2;
      const glm::dvec2 size(std::max(side, text.x), side + 2.0 * text.y);
      PixelBox outer;
      outer.lo.x = right ? area.hi.x - kMargin - size.x : area.lo.x + kMargin;
      outer.lo.y = upper ? area.lo.y + kMargin : area.hi.y - kMargin - size.y;
      outer.hi = outer.lo + size;
      if (outer.lo.x < area.lo.x || outer.lo.y < area.lo.y || !keepsOff(outer, avoid, kMargin))
        continue;
      if (std::any_of(keepOff.begin(), keepOff.end(),
                      [&](const PixelBox& k) { return !k.empty() && overlaps(outer, k); }))
        continue;
      const double left = 0.5 * (outer.lo.x + outer.hi.x - side);
      return PixelBox{{left, outer.lo.y + text.y}, {left + side, outer.hi.y - text.y}};
    }
  return std::nullopt;
}

glm::dvec2 insetLeaderStart(const PixelBox& frame, glm::dvec2 target) {
  const glm::dvec2 mid = 0.5 * (frame.lo + frame.hi), half = 0.5 * (frame.hi - frame.lo),
                   away = target - mid;
  if (std::abs(away.x) * half.y >= std::abs(away.y) * half.x)
    return {away.x < 0.0 ? frame.lo.x : frame.hi.x, mid.y};
  return {mid.x, away.y < 0.0 ? frame.lo.y : frame.hi.y};
}

void drawCubeInset(const CubeInset& inset, std::span<const Cell3D> cells, const Palette& pal,
                   PixelBox frame, double textRoom, std::optional<glm::dvec2> anchor, DrawList& out,
                   bool twoLines) {
  const double k = (frame.hi.x - frame.lo.x) / inset.side;
  // (s, t) to window pixels, t upward, clamped to the patch
  const auto at = [&](double s, double t) {
    s = std::clamp(s, inset.lo.x, inset.lo.x + inset.side);
    t = std::clamp(t, inset.lo.y, inset.lo.y + inset.side);
    return glm::dvec3(frame.lo.x + (s - inset.lo.x) * k, frame.hi.y - (t - inset.lo.y) * k, 0.0);
  };
  const glm::dvec3 f00 = at(-2.0, -2.0), f10 = at(2.0, -2.0), f11 = at(2.0, 2.0),
                   f01 = at(-2.0, 2.0);
  out.triangle(f00, f10, f11, pal.background);
  out.triangle(f00, f11, f01, pal.background);
  for (std::size_t i : inset.cells) {
    const Cell3D& c = cells[i];
    const glm::dvec3 q[4] = {at(c.s0, c.t0), at(c.s1, c.t0), at(c.s1, c.t1), at(c.s0, c.t1)};
    const bool crowded = c.faces.size() > kCrowdedCell3D;
    if (c.faces.size() > kBaseFacesPerCell || crowded) {
      const Rgba tint = cellTint(pal, c.faces.size(), kBaseFacesPerCell, crowded);
      out.triangle(q[0], q[1], q[2], tint);
      out.triangle(q[0], q[2], q[3], tint);
    }
    for (int e = 0; e < 4; ++e) out.segment(q[e], q[(e + 1) % 4], pal.cube, 1.0f);
  }
  const glm::dvec3 border[4] = {f00, f10, f11, f01};
  for (int e = 0; e < 4; ++e) out.segment(border[e], border[(e + 1) % 4], pal.textMuted, 1.5f);
  const double mid = 0.5 * (frame.lo.x + frame.hi.x);
  const std::vector<std::string> title =
      twoLines ? cubeInsetTitleLines(inset) : std::vector<std::string>{cubeInsetTitle(inset)};
  for (std::size_t i = 0; i < title.size(); ++i)
    out.label({mid, frame.lo.y - (static_cast<double>(title.size() - i) - 0.5) * textRoom, 0.0},
              title[i], pal.text);
  out.label({mid, frame.hi.y + 0.5 * textRoom, 0.0}, cubeInsetZoomText(inset), pal.text);
  if (!anchor) return;
  // the leader: from the middle of the frame's side facing the patch on screen, a ring of 8
  // pixels there
  const glm::dvec2 from = insetLeaderStart(frame, *anchor);
  const glm::dvec3 a(*anchor, 0.0);
  out.segment(glm::dvec3(from, 0.0), a, withAlpha(pal.textMuted, 0.85f), 1.25f, 6.0f);
  for (int e = 0; e < 8; ++e) {
    const double u = e * 0.7853981633974483, v = (e + 1) * 0.7853981633974483;
    out.segment(a + 8.0 * glm::dvec3(std::cos(u), std::sin(u), 0.0),
                a + 8.0 * glm::dvec3(std::cos(v), std::sin(v), 0.0), pal.text, 1.5f);
  }
  // the face the inset shows named at the ring, beyond it from the frame: the scene's face
  // names are drawn through the see-through cube, a far face's over the near one's corner
  const glm::dvec2 away = *anchor - from;
  const double length = glm::length(away);
  const glm::dvec2 dir = length > 0.0 ? away / length : glm::dvec2(0.0, -1.0);
  out.label(glm::dvec3(*anchor + 0.75 * textRoom * dir, 0.0),
            std::string(kCubeFaceNames[static_cast<std::size_t>(inset.cubeFace)]), pal.text);
}

}  // namespace convexloc::viewer
