// convexloc-viewer — the two themes' palettes.
#include "logic/base/colour.hpp"

#include <algorithm>
#include <cmath>

namespace convexloc::viewer {
namespace {

// Okabe and Ito's colour-blind-safe palette
constexpr Rgba kSkyBlue = hex(0x56B4E9);
constexpr Rgba kBlue = hex(0x0072B2);
constexpr Rgba kOrange = hex(0xE69F00);
constexpr Rgba kYellow = hex(0xF0E442);
constexpr Rgba kGreen = hex(0x009E73);
constexpr Rgba kVermillion = hex(0xD55E00);
constexpr Rgba kPurple = hex(0xCC79A7);

// each colour of the palette, in the dark and in the light theme; the class colours are
// sky blue and vermillion on dark, blue and orange on light: apart in hue and in lightness
// on each background
struct ThemedColour {
  Rgba Palette::*member;
  Rgba dark, light;
};
constexpr ThemedColour kColours[] = {
    {&Palette::background, hex(0x15171c), hex(0xfbfbfa)},
    {&Palette::text, hex(0xe8eaed), hex(0x1f2328)},
    {&Palette::textMuted, hex(0x9aa0a6), hex(0x5f6770)},
    {&Palette::polygonEdge, hex(0xf4f5f7), hex(0x1f2328)},
    {&Palette::polygonFill, hex(0xffffff, 0.05f), hex(0x000000, 0.035f)},
    {&Palette::box, hex(0x8b929c, 0.9f), hex(0x6b7280, 0.9f)},
    {&Palette::octant, hex(0xd4d8de, 0.85f), hex(0x3c4249, 0.8f)},
    {&Palette::structure, hex(0x7d8590, 0.55f), hex(0x8a929c, 0.55f)},
    {&Palette::structureStrong, hex(0xaab1bb, 0.9f), hex(0x4b525a, 0.9f)},
    {&Palette::centre, hex(0xffffff), hex(0x111111)},
    {&Palette::inside, kSkyBlue, kBlue},
    {&Palette::boundary, kYellow, kYellow},
    {&Palette::outside, kVermillion, kOrange},
    {&Palette::rim, hex(0x111111, 0.9f), hex(0x111111, 0.9f)},
    {&Palette::extraEdges, hex(0x2fbf8f), kGreen},
    {&Palette::crowded, kPurple, kPurple},
    {&Palette::hoverFill, hex(0xffffff, 0.10f), hex(0x000000, 0.07f)},
    {&Palette::hoverOutline, hex(0xffffff, 0.95f), hex(0x111111, 0.9f)},
    {&Palette::hoverEdge, kPurple, hex(0xb8498a)},
    {&Palette::positive, hex(0x35c08f), kGreen},
    {&Palette::zero, kYellow, hex(0xb59f00)},
    {&Palette::negative, hex(0xff7a3d), kVermillion},
    {&Palette::handle, hex(0xf4f5f7), hex(0x1f2328)},
    {&Palette::handleError, kVermillion, kVermillion},
    {&Palette::meshFill, hex(0x8fb8de, 0.22f), hex(0x5b8fc0, 0.20f)},
    {&Palette::meshEdge, hex(0xe8eaed, 0.8f), hex(0x1f2328, 0.75f)},
    {&Palette::cube, hex(0x9aa0a6, 0.7f), hex(0x5f6770, 0.7f)},
    {&Palette::slicePlane, hex(0xcfd8e3, 0.12f), hex(0x40607f, 0.10f)},
};

Palette makePalette(Theme theme) {
  Palette p;
  for (const ThemedColour& c : kColours) p.*c.member = theme == Theme::Dark ? c.dark : c.light;
  return p;
}

}  // namespace

Rgba mix(Rgba a, Rgba b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
          a.a + (b.a - a.a) * t};
}

std::string_view toString(Theme t) {
  return t == Theme::Dark ? "dark" : "light";
}

const Palette& paletteFor(Theme t) {
  static const Palette dark = makePalette(Theme::Dark);
  static const Palette light = makePalette(Theme::Light);
  return t == Theme::Dark ? dark : light;
}

Rgba colourOf(const Palette& p, Location l) {
  switch (l) {
    case Location::Inside: return p.inside;
    case Location::Boundary: return p.boundary;
    case Location::Outside: return p.outside;
  }
  return p.outside;
}

Rgba textColourOf(const Palette& p, Location l) {
  return readableOn(l == Location::Boundary ? p.zero : colourOf(p, l), p.background, p.text);
}

float contrastRatio(Rgba a, Rgba b) {
  // relative luminance of sRGB
  auto luminance = [](Rgba c) {
    auto lin = [](float v) {
      return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    };
    return 0.2126f * lin(c.r) + 0.7152f * lin(c.g) + 0.0722f * lin(c.b);
  };
  const float la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05f) / (std::min(la, lb) + 0.05f);
}

Rgba readableOn(Rgba c, Rgba background, Rgba toward, float ratio) {
  Rgba out = c;
  for (int step = 1; step <= 10 && contrastRatio(out, background) < ratio; ++step)
    out = mix(c, toward, 0.1f * static_cast<float>(step));
  out.a = c.a;
  return out;
}

Rgba cellTint(const Palette& p, std::size_t edges, std::size_t base, bool crowded) {
  if (crowded) return withAlpha(p.crowded, 0.40f);
  if (edges <= base) return withAlpha(p.extraEdges, 0.0f);
  // one extra edge: clearly visible; each further one a little stronger, up to a cap
  const float extra = static_cast<float>(std::min<std::size_t>(edges - base, 4));
  return withAlpha(p.extraEdges, 0.16f + 0.08f * (extra - 1.0f));
}

std::uint32_t packAbgr(Rgba c) {
  auto byte = [](float v) {
    return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return byte(c.r) | (byte(c.g) << 8) | (byte(c.b) << 16) | (byte(c.a) << 24);
}

}  // namespace convexloc::viewer
