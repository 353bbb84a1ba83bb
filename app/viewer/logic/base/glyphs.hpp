// convexloc-viewer — the characters the viewer's font is loaded with: the ranges handed to
// Dear ImGui's font atlas, and a check that a text uses none outside them (a glyph outside
// is drawn as "?"). GL-free.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace convexloc::viewer {

// inclusive code point ranges, in ImGui's order (pairs, first to last)
struct GlyphRange {
  char32_t first, last;
};

// Latin-1, Greek (φ, θ in a lecturer's captions), general punctuation with super- and subscripts,
// arrows, mathematical operators, miscellaneous technical (the floor and ceiling brackets),
// geometric shapes
std::span<const GlyphRange> fontGlyphRanges();

// the first code point of the UTF-8 `text` outside fontGlyphRanges() (newlines and tabs
// aside), or none; a malformed byte counts as outside (U+FFFD)
std::optional<char32_t> firstMissingGlyph(std::string_view text);

}  // namespace convexloc::viewer
